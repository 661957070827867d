#!/usr/bin/python3
"""Does `sinu diagnose` name an effect in data our simulator did not make?
An evaluation, not a unit test.

The real logs (../shared/data/real/*) are the base: their trajectories,
vibration, receivers and sensor errors are nobody's model. Each log is first
diagnosed as it is (`--apply`: what the unit itself has, e.g. the
quadcopter's soft iron), again from that model file until nothing more is
named; then one known effect, drawn as `sinu simulate` draws it (its
"large enough to matter" ranges), is put into a copy of the log
(tools/inject_effect.py) and the copy is diagnosed without truth, carrying
the untouched log's effects as states (`--effects`, from the vocabulary's
prior: the model files' sigmas come from this same data, once per pass).
Right: the injected effect is named first (for effects the model carries
from zero, `mag_hard_iron` and the log's own: nothing named, and the
estimate moves by the injected value; for those it carries from a configured
value, `gps_latency` and a lever arm the log has, whose configuration for the
copies is the untouched log's estimate: named as a configured value off). Effects the log cannot
test are skipped, as diagnose itself says ("not tested": no magnetometer,
the irons; temperature within 2 degC, the temperature coefficients). The error against the log's own reference
(the autopilot's EKF, or the car's RTK) is given for a replay with the log's
effects and from the model file diagnose wrote.

  /usr/bin/python3 tools/diagnose_real_eval.py --sinu build/release/firmware/sinu \
      --per-effect 10 --out docs/diagnose.md
(about 3 minutes on 2 cores; the table goes between the markers in docs/diagnose.md)
"""
import argparse
import collections
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys

from diagnose_eval import CARRIED, EFFECTS, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
# Effects whose injected value is the state's, times this (ppm for the scales), component for component.
SIMPLE_UNITS = {"gps_latency": 1.0, "lever_arm": 1.0, "mag_hard_iron": 1.0, "accel_scale": 1e-6, "gyro_scale": 1e-6,
                "gps_velocity_latency": 1.0, "mag_motor_interference": 1.0, "mag_latency": 1.0}


def run(cmd):
    return subprocess.run(cmd, check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def draws(sinu, work, per_effect, first_seed):
    """{effect: [(seed, value), ...]}: the simulator's own random draws, per_effect of each."""
    got = collections.defaultdict(list)
    seed = first_seed
    while any(len(got[e]) < per_effect for e in EFFECTS) and seed < first_seed + 100 * per_effect * len(EFFECTS):
        d, hidden = os.path.join(work, "draw"), os.path.join(work, "draw.json")
        run([sinu, "simulate", "flight", "--seed", str(seed), "--duration", "300", "--effects-random", "1",
             "--hidden-out", hidden, "--out", d])
        shutil.rmtree(d, ignore_errors=True)
        for name, value in json.load(open(hidden)).get("effects", {}).items():
            if len(got[name]) < per_effect:
                got[name].append((seed, value))
        seed += 1
    return got


def untestable(diagnosis_dir):
    """{effect: why} the log cannot test, as diagnose itself said ("not tested"; the
    hard iron, always carried with a magnetometer, goes with the soft iron)."""
    skipped = {s["effect"]: s["reason"]
               for s in json.load(open(os.path.join(diagnosis_dir, "diagnosis.json"))).get("skipped", [])}
    if "mag_soft_iron" in skipped:
        skipped["mag_hard_iron"] = skipped["mag_soft_iron"]
    return skipped


def replay(sinu, data, truth, model_args, out):
    """A replay with the model arguments: (horizontal [m], attitude [deg] RMSE against the
    log's reference, {effect: (estimate, sigma)} at the end)."""
    cmd = [sinu, "replay", "--in", data, "--quiet", "--out", out] + (["--truth", truth] if os.path.exists(truth) else [])
    run(cmd + model_args)
    s = json.load(open(os.path.join(out, "summary.json")))
    shutil.rmtree(out, ignore_errors=True)
    r = s.get("rmse") or {}
    return r.get("pos_h_m"), r.get("att_deg"), {e["name"]: (e["estimate"], e["sigma"]) for e in s.get("effects", [])}


def moved_by(value, effect, base, copy):
    """How far the copy's estimate of a carried effect moved from the untouched log's,
    against the injected value: the largest |moved - injected| / sigma, or None."""
    if effect not in SIMPLE_UNITS or effect not in base or effect not in copy:
        return None
    injected = value if isinstance(value, list) else [value]
    return max(abs(c - b - SIMPLE_UNITS[effect] * v) / s
               for v, b, c, s in zip(injected, base[effect][0], copy[effect][0], copy[effect][1]))


def without_truth(log, dst):
    os.makedirs(dst, exist_ok=True)
    for f in ("imu.csv", "gps.nmea"):
        if os.path.exists(os.path.join(log, f)) and not os.path.exists(os.path.join(dst, f)):
            os.symlink(os.path.abspath(os.path.join(log, f)), os.path.join(dst, f))


def evaluate(sinu, work, log, base_args, base_estimates, base_carried, nav, effect, seed, value):
    name = os.path.basename(log.rstrip("/"))
    case = os.path.join(work, f"{name}_{effect}_{seed}")
    fx = case + "_effects.json"
    json.dump({effect: value}, open(fx, "w"))
    run(["/usr/bin/python3", os.path.join(HERE, "inject_effect.py"), "--in", log, "--effects", fx, "--nav", nav,
         "--out", case])
    diag = case + "_diag"
    run([sinu, "diagnose", "--in", case, "--rounds", "1", "--threads", "1", "--quiet", "--apply", "--out", diag]
        + base_args)
    dj = json.load(open(os.path.join(diag, "diagnosis.json")))
    named = dj.get("missing_effects", [])
    # Carried and far from the assumed value: what the untouched log had too (its hard iron) is the unit's.
    named += [f["effect"] for f in dj.get("carried_findings", [])
              if f["effect"] not in named and f["effect"] not in base_carried]
    truth = os.path.join(log, "truth.csv")
    row = {"log": name, "effect": effect, "seed": seed, "named": named}
    before = replay(sinu, case, truth, base_args, diag + "_r0")
    after = replay(sinu, case, truth, ["--model-file", os.path.join(diag, "model.json")], diag + "_r1")
    row["before"], row["after"] = before[:2], after[:2]
    row["moved_z"] = moved_by(value, effect, base_estimates, before[2])
    shutil.rmtree(case, ignore_errors=True)
    shutil.rmtree(diag, ignore_errors=True)
    return row


# Carried from a configured value (the copies' is the untouched log's estimate): a copy
# that moves it is right when diagnose names it as a configured value off.
CONFIGURED = {"gps_latency", "lever_arm"}


def right(row, carried):
    if row["effect"] in carried and row["effect"] not in CONFIGURED:
        return not row["named"]
    return bool(row["named"]) and row["named"][0] == row["effect"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sinu", default="build/release/firmware/sinu")
    ap.add_argument("--logs", nargs="*",
                    default=[os.path.join(HERE, "..", "..", "shared", "data", "real", n)
                             for n in ("uav_log171", "drive_0708")])
    ap.add_argument("--work", default="/tmp/diagnose_real_eval")
    ap.add_argument("--per-effect", type=int, default=10)
    ap.add_argument("--first-seed", type=int, default=1000)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--out", default="-")
    a = ap.parse_args()
    logs = [l for l in a.logs if os.path.exists(os.path.join(l, "imu.csv"))]
    if not logs:
        sys.exit("diagnose_real_eval: no real log found (../shared/data/real/*); give --logs")
    os.makedirs(a.work, exist_ok=True)
    drawn = draws(a.sinu, a.work, a.per_effect, a.first_seed)

    jobs, bases = [], {}
    for log in logs:
        name = os.path.basename(log.rstrip("/"))
        plain = os.path.join(a.work, name)
        without_truth(log, plain)
        # The unit's own effects, until a diagnosis from the last model file names nothing more
        # (a flight that starts from a model sees more than one that starts from nothing):
        # the copies then differ from the base by the injected effect alone. The copies carry
        # them as states from the vocabulary's prior (--effects), not from the model file: its
        # sigmas come from this same data, once per pass.
        named, base, model = [], None, []
        for i in range(4):
            base = f"{plain}_diag{i}"
            run([a.sinu, "diagnose", "--in", plain, "--rounds", "5", "--apply", "--quiet", "--out", base] + model)
            new = json.load(open(os.path.join(base, "diagnosis.json"))).get("missing_effects", [])
            named += new
            model = ["--model-file", os.path.join(base, "model.json")]
            if not new:
                break
        skipped = untestable(f"{plain}_diag0")
        # Carried properties the untouched log already has that no option configures (its hard iron).
        base_carried = {f["effect"] for f in json.load(open(f"{plain}_diag0/diagnosis.json")).get("carried_findings", [])
                        } - CONFIGURED
        bases[name] = (named, skipped)
        base_args = ["--effects", ",".join(named)] if named else []
        base_estimates = replay(a.sinu, plain, os.path.join(log, "truth.csv"), base_args, base + "_replay")[2]
        # The unit's own latency (and lever arm, when it has one) are the copies' configuration:
        # as diagnose's baseline learns them with its tuned noise (the real quadcopter's latency:
        # 0.250 s in a replay with its effects, 0.223 s in diagnose's baseline), so that a copy's
        # diagnosis differs from the untouched log's by the injected effect alone.
        configured = {}
        for name in ("gps_latency", "lever_arm"):
            if name in base_estimates:
                configured[name] = base_estimates[name][0]
        def configured_args():
            out = []
            if "gps_latency" in configured:
                out += ["--gps-latency", f"{configured['gps_latency'][0]:.4f}"]
            if "lever_arm" in configured:
                out += ["--lever-arm", ",".join(f"{v:.4f}" for v in configured["lever_arm"])]
            return out
        check = f"{plain}_configured"
        run([a.sinu, "diagnose", "--in", plain, "--rounds", "1", "--quiet", "--out", check] + base_args
            + configured_args())
        tuned = json.load(open(os.path.join(check, "baseline", "summary.json")))
        for e in tuned.get("effects", []):
            if e["name"] in configured:
                configured[e["name"]] = e["estimate"]
        base_args += configured_args()
        base_estimates = replay(a.sinu, plain, os.path.join(log, "truth.csv"), base_args, base + "_replay")[2]
        for effect in EFFECTS:
            if effect in skipped:
                continue
            for seed, value in drawn[effect]:
                jobs.append((log, base_args, base_estimates, base_carried,
                             os.path.join(base, "baseline", "nav.csv"), effect,
                             seed, value))
    rows = []
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(evaluate, a.sinu, a.work, *j) for j in jobs]
        for i, f in enumerate(concurrent.futures.as_completed(futures)):
            rows.append(f.result())
            print(f"diagnose_real_eval: {i + 1}/{len(jobs)}", file=sys.stderr)
    json.dump(rows, open(os.path.join(a.work, "rows.json"), "w"), indent=1)

    def med(values):
        v = sorted(x for x in values if x is not None)
        return v[len(v) // 2] if v else float("nan")

    def num(x, f):
        return "-" if x != x else f"{x:{f}}"

    out = [f"Each real log diagnosed as it is (`--rounds 5 --apply`, again from the model file until nothing more is named), then {a.per_effect} copies per effect with one effect "
           "put in (tools/inject_effect.py; magnitudes drawn by `sinu simulate`, seeds "
           f"{a.first_seed}..), each diagnosed without truth with the effects the untouched log has (`--effects`). "
           "RMSE against the log's reference (the autopilot's EKF; the car's RTK, which is also its GNSS input) "
           "for a replay with those effects and from the model file diagnose wrote (medians).", ""]
    for log in logs:
        name = os.path.basename(log.rstrip("/"))
        named, skipped = bases[name]
        rs = [r for r in rows if r["log"] == name]
        why = collections.defaultdict(list)
        for effect, reason in skipped.items():
            why[reason].append(effect)
        out += [f"`{name}` as it is: {', '.join(named) or 'nothing'} named"
                + "".join(f"; not tested ({reason}): {', '.join(sorted(es))}" for reason, es in why.items())
                + ".", "",
                "| effect put in | right means | copies | right | named instead | carried: estimate moved by the injected value (largest error/sigma, median) | horizontal RMSE [m] before / after | attitude RMSE [deg] before / after |",
                "|---|---|---|---|---|---|---|---|"]
        total = 0
        for e in EFFECTS:
            es = [r for r in rs if r["effect"] == e]
            if not es:
                continue
            carried = CARRIED | set(named)
            ok = sum(right(r, carried) for r in es)
            total += ok
            instead = collections.Counter(r["named"][0] if r["named"] else "nothing" for r in es if not right(r, carried))
            b = [r.get("before") or (None, None) for r in es]
            f = [r.get("after") or (None, None) for r in es]
            z = med(r.get("moved_z") for r in es)
            out.append(f"| `{e}` | {('named as carried' if e in CONFIGURED else 'nothing named (carried)') if e in carried else 'named first'} | {len(es)} | {ok} | "
                       f"{', '.join(f'{n} x{c}' for n, c in instead.most_common()) or '-'} | "
                       f"{num(z, '.1f')} | {num(med(x[0] for x in b), '.3f')} / {num(med(x[0] for x in f), '.3f')} | "
                       f"{num(med(x[1] for x in b), '.2f')} / {num(med(x[1] for x in f), '.2f')} |")
        if rs:
            out.append(f"| **all** | | {len(rs)} | **{total} ({100 * total / len(rs):.0f} %)** | | | | |")
        out.append("")
    write_section(a.out, "diagnose_real_eval", "\n".join(out))


if __name__ == "__main__":
    main()
