#!/usr/bin/python3
"""Does `sinu diagnose` name the right effect? An evaluation, not a unit test.

Simulates flights with one hidden effect each (every effect of the simulator's
vocabulary, random magnitudes, seeds and trajectories), clean flights, and
flights with two effects; each with a one-hour bench session of the same unit
(same seed) for `sinu calibrate`. Runs `sinu diagnose --apply` WITHOUT
truth.csv, then scores:
  - top-1: the first effect named is the hidden one (one the model carries,
    the latency or the hard iron, is named as carried and far from the
    assumed value; clean flights: right when nothing is named);
  - after --apply: the outage drift of a replay that starts from the model
    file, against a replay given the true effect's states (truth only here);
  - two effects: both named in two rounds; again where both matter (the true
    model drifts MATTERS less than the filter given only the other's states);
  - where it matters: top-1 again over the flights whose true model lowers the
    outage drift by MATTERS (5 %) or more (the issue asks for effects "at
    magnitudes that matter"; a carried effect always counts);
  - --airframe multirotor: the same on a slow multirotor's flights (sinu
    simulate flight --airframe; docs/simulation.md);
  - --sweep EFFECT:S1,S2,..: the first --sweep-flights one-effect flights of
    EFFECT again with its hidden value times each scale (where it starts to
    matter, and whether it is named then).
Writes a markdown report (tables) to --out.

  /usr/bin/python3 tools/diagnose_eval.py --sinu build/release/firmware/sinu \
      --work /tmp/diagnose_eval --per-effect 10 --clean 20 --pairs 20 --out docs/diagnose.md
(about 10 minutes on 2 cores; the tables go between the markers in docs/diagnose.md)
"""
import argparse
import collections
import concurrent.futures
import json
import os
import shutil
import statistics
import subprocess
import sys

EFFECTS = ["accel_scale", "gyro_scale", "accel_misalign", "gyro_misalign", "lever_arm", "gps_latency",
           "accel_temp_bias", "gyro_temp_bias", "mag_hard_iron", "mag_soft_iron", "gyro_g_sensitivity",
           "mag_misalign", "gps_velocity_latency", "mag_motor_interference", "mag_latency"]
# Carried by the model (the latency from the configured value, the hard iron from
# zero with a magnetometer): nothing is missing, the baseline follows them, and
# diagnose names them as carried and far from the assumed value (diagnosis.json
# carried_findings); that counts as naming them. They always "matter".
CARRIED = {"mag_hard_iron", "gps_latency"}
DURATION_S = 1200
AIRFRAME = "fixed-wing"  # --airframe
# Eight 30-s outages spread over the flight (after the first 3 minutes), from its start.
OUTAGE_STARTS = list(range(180, DURATION_S - 60, (DURATION_S - 240) // 8))[:8]
# An effect matters in a flight when the filter given its states drifts this much less.
MATTERS = 0.05


def outages(t0_s):
    return ",".join(f"{t0_s + t:.3f}:30" for t in OUTAGE_STARTS)


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)


def simulate(sinu, work, seed, k):
    """A flight with k random effects: (folder, hidden effect names, its start time)."""
    d = os.path.join(work, f"s{seed}_k{k}")
    hidden = d + "_hidden.json"
    shutil.rmtree(d, ignore_errors=True)
    run([sinu, "simulate", "flight", "--seed", str(seed), "--duration", str(DURATION_S), "--airframe", AIRFRAME,
         "--effects-random", str(k),
         "--hidden-out", hidden, "--out", d])
    h = json.load(open(hidden))
    return d, sorted(h.get("effects", {}).keys()), h["t0_s"]


def true_model_args(flight, without=None):
    """replay options giving the filter the hidden effects' states (all but `without`);
    the latency as the configured value it is (the receiver's own delay plus the hidden one)."""
    h = json.load(open(flight + "_hidden.json"))
    effects = {n: v for n, v in h.get("effects", {}).items() if n != without}
    states = [n for n in sorted(effects) if n not in CARRIED]
    args = ["--effects", ",".join(states)] if states else []
    if "gps_latency" in effects:
        args += ["--gps-latency", f"{effects['gps_latency'] + h['gps_error_model']['base_latency_s']:.4f}"]
    return args


def scaled(effects, scale):
    """The simulator's effects JSON with every value times scale (a soft iron's deviation from I)."""
    def times(v):
        return [times(x) for x in v] if isinstance(v, list) else v * scale
    out = {}
    for name, v in effects.items():
        if name == "mag_soft_iron":
            out[name] = [[(1.0 if i == j else 0.0) + scale * (x - (1.0 if i == j else 0.0)) for j, x in enumerate(r)]
                         for i, r in enumerate(v)]
        else:
            out[name] = times(v)
    return out


def simulate_scaled(sinu, work, seed, scale):
    """Flight `seed` (one random effect) again with that effect's value times scale."""
    hidden = os.path.join(work, f"s{seed}_k1_hidden.json")
    effects = scaled(json.load(open(hidden))["effects"], scale)
    d = os.path.join(work, f"s{seed}_x{scale:g}")
    spec = d + "_effects.json"
    json.dump(effects, open(spec, "w"))
    shutil.rmtree(d, ignore_errors=True)
    run([sinu, "simulate", "flight", "--seed", str(seed), "--duration", str(DURATION_S), "--airframe", AIRFRAME,
         "--effects", spec,
         "--hidden-out", d + "_hidden.json", "--out", d])
    h = json.load(open(d + "_hidden.json"))
    return d, sorted(h.get("effects", {}).keys()), h["t0_s"]


def matters(row):
    """The effect changes navigation here: carried, or its true model drifts MATTERS less."""
    if all(n in CARRIED for n in row["hidden"]):
        return True
    b, t = row.get("drift_baseline"), row.get("drift_true_model")
    return b is not None and t is not None and t <= (1.0 - MATTERS) * b


def matters_in_pair(row, effect):
    """One of two hidden effects matters: carried, or the true model drifts MATTERS less
    than the filter given only the other effect's states."""
    if effect in CARRIED:
        return True
    w, t = row.get("drift_without", {}).get(effect), row.get("drift_true_model")
    return w is not None and t is not None and t <= (1.0 - MATTERS) * w


def outage_drift(sinu, data, truth, t0_s, out, extra):
    run([sinu, "replay", "--in", data, "--truth", truth, "--calib", extra["calib"], "--outage", outages(t0_s), "--quiet",
         "--out", out] + extra.get("args", []))
    return json.load(open(os.path.join(out, "summary.json"))).get("outage_max_drift_h_rms_m")


def evaluate(sinu, work, seed, k, names, t0_s, flight):
    truth = flight + "_truth.csv"
    if os.path.exists(os.path.join(flight, "truth.csv")):
        os.replace(os.path.join(flight, "truth.csv"), truth)
    bench = os.path.join(work, f"bench{seed}")
    calib = bench + "_calib.json"
    if not os.path.exists(calib):
        run([sinu, "simulate", "static", "--seed", str(seed), "--hours", "1", "--out", bench])
        run([sinu, "calibrate", "--in", bench, "--out", calib])
        shutil.rmtree(bench, ignore_errors=True)
    diag = flight + "_diag"
    run([sinu, "diagnose", "--in", flight, "--calib", calib, "--rounds", str(max(1, k)), "--threads", "1", "--quiet",
         "--apply", "--out", diag])
    dj = json.load(open(os.path.join(diag, "diagnosis.json")))
    named = dj.get("missing_effects", [])
    named += [f["effect"] for f in dj.get("carried_findings", []) if f["effect"] not in named]
    row = {"seed": seed, "k": k, "hidden": names, "named": named,
           "bias_moved": bool(dj.get("bias_walk", {}).get("named", False))}
    if k >= 1:
        base = {"calib": calib}
        row["drift_baseline"] = outage_drift(sinu, flight, truth, t0_s, diag + "_r0", base)
        row["drift_applied"] = outage_drift(sinu, flight, truth, t0_s, diag + "_r1",
                                            {"calib": calib, "args": ["--model-file", os.path.join(diag, "model.json")]})
        row["drift_true_model"] = outage_drift(sinu, flight, truth, t0_s, diag + "_r2",
                                               {"calib": calib, "args": true_model_args(flight)})
    if k >= 2:  # what each effect is worth: the true model without it
        row["drift_without"] = {}
        for e in names:
            if e not in CARRIED:
                row["drift_without"][e] = outage_drift(sinu, flight, truth, t0_s, diag + "_r3",
                                                       {"calib": calib, "args": true_model_args(flight, e)})
        shutil.rmtree(diag + "_r3", ignore_errors=True)
    shutil.rmtree(diag + "_r0", ignore_errors=True)
    shutil.rmtree(diag + "_r1", ignore_errors=True)
    shutil.rmtree(diag + "_r2", ignore_errors=True)
    return row


def correct(row):
    hidden = row["hidden"]
    if not hidden:
        return not row["named"]
    if row["k"] == 1:
        return bool(row["named"]) and row["named"][0] == hidden[0]
    return set(hidden) <= set(row["named"])


def main():
    global AIRFRAME
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sinu", default="build/release/firmware/sinu")
    ap.add_argument("--work", default="/tmp/diagnose_eval")
    ap.add_argument("--per-effect", type=int, default=10)
    ap.add_argument("--clean", type=int, default=20)
    ap.add_argument("--pairs", type=int, default=20)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--first-seed", type=int, default=1000)
    ap.add_argument("--airframe", default=AIRFRAME, choices=["fixed-wing", "multirotor"])
    ap.add_argument("--sweep", default="", help="EFFECT:S1,S2,... (e.g. gyro_g_sensitivity:1,2,3)")
    ap.add_argument("--sweep-flights", type=int, default=5)
    ap.add_argument("--out", default="-")
    a = ap.parse_args()
    AIRFRAME = a.airframe
    os.makedirs(a.work, exist_ok=True)

    # Pick flights: seeds in order, kept while their drawn effect still needs flights.
    need = collections.Counter({e: a.per_effect for e in EFFECTS})
    jobs, seed = [], a.first_seed
    while sum(need.values()) > 0 and seed < a.first_seed + 100 * len(EFFECTS) * a.per_effect:
        d, names, t0 = simulate(a.sinu, a.work, seed, 1)
        if names and need[names[0]] > 0:
            need[names[0]] -= 1
            jobs.append((seed, 1, names, t0, d, None))
        else:
            shutil.rmtree(d, ignore_errors=True)
        seed += 1
    for i in range(a.clean):
        d, names, t0 = simulate(a.sinu, a.work, seed + i, 0)
        jobs.append((seed + i, 0, names, t0, d, None))
    seed += a.clean
    for i in range(a.pairs):
        d, names, t0 = simulate(a.sinu, a.work, seed + i, 2)
        jobs.append((seed + i, 2, names, t0, d, None))
    sweep_effect, sweep_scales = (a.sweep.split(":") + [""])[:2] if a.sweep else ("", "")
    swept = [j for j in jobs if j[1] == 1 and j[2] == [sweep_effect]][:a.sweep_flights]
    for s, *_ in swept:
        for x in (float(v) for v in sweep_scales.split(",") if v):
            d, names, t0 = simulate_scaled(a.sinu, a.work, s, x)
            jobs.append((s, 1, names, t0, d, x))

    rows = []
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futures = {pool.submit(evaluate, a.sinu, a.work, s, k, n, t0, d): x for s, k, n, t0, d, x in jobs}
        for i, f in enumerate(concurrent.futures.as_completed(futures)):
            row = f.result()
            if futures[f] is not None:  # a sweep flight
                row["scale"], row["sweep"] = futures[f], True
            rows.append(row)
            print(f"diagnose_eval: {i + 1}/{len(jobs)} flights", file=sys.stderr)
    json.dump(rows, open(os.path.join(a.work, "rows.json"), "w"), indent=1)
    write_section(a.out, "diagnose_eval", report(rows, a.first_seed))


def report(rows, first_seed):
    """The markdown tables of the evaluated rows."""
    airframe = "" if AIRFRAME == "fixed-wing" else f" --airframe {AIRFRAME}"
    out = [f"Flights of {DURATION_S // 60} min (`sinu simulate flight{airframe} --effects-random K`, seeds {first_seed}..), "
           "each with a 1-h bench session of the same unit for `sinu calibrate`; `sinu diagnose --calib --apply` "
           f"without truth.csv; outage drift: RMS of the largest horizontal drift in eight 30-s outages (at "
           f"{', '.join(str(t) for t in OUTAGE_STARTS)} s into the flight).", "",
           "| hidden effect | flights | named first (right) | top-1 | named instead | outage drift RMS: baseline / after --apply / true model [m] |",
           "|---|---|---|---|---|---|"]
    one = [r for r in rows if r["k"] == 1 and not r.get("sweep")]
    total_right = 0
    for e in EFFECTS:
        rs = [r for r in one if r["hidden"] == [e]]
        if not rs:
            continue
        right = sum(correct(r) for r in rs)
        total_right += right
        instead = collections.Counter(r["named"][0] if r["named"] else "nothing" for r in rs if not correct(r))
        med = lambda key: statistics.median(r[key] for r in rs if r.get(key) is not None) if any(r.get(key) is not None for r in rs) else float("nan")
        out.append(f"| `{e}` | {len(rs)} | {right} | {100 * right / len(rs):.0f} % | "
                   f"{', '.join(f'{n} x{c}' for n, c in instead.most_common()) or '-'} | "
                   f"{med('drift_baseline'):.2f} / {med('drift_applied'):.2f} / {med('drift_true_model'):.2f} |")
    if one:
        out.append(f"| **all** | {len(one)} | {total_right} | **{100 * total_right / len(one):.0f} %** | | |")
        mat = [r for r in one if matters(r)]
        per = collections.Counter(r["hidden"][0] for r in one if not matters(r))
        ok = sum(correct(r) for r in mat)
        out += ["", f"Where the effect matters (the filter given its true states drifts {100 * MATTERS:.0f} % less "
                    f"than the baseline in the outages, or the model carries it): named first in {ok} of {len(mat)} "
                    f"({100 * ok / max(1, len(mat)):.0f} %); it did not matter in "
                    + (", ".join(f"{c} `{n}`" for n, c in per.most_common()) or "none") + " of the flights."]
    clean = [r for r in rows if r["k"] == 0]
    if clean:
        ok = sum(correct(r) for r in clean)
        falsely = collections.Counter(r["named"][0] for r in clean if r["named"])
        out += ["", f"Clean flights: adequate (nothing named) in {ok} of {len(clean)} ({100 * ok / len(clean):.0f} %)"
                + (f"; named instead: {', '.join(f'{n} x{c}' for n, c in falsely.most_common())}" if falsely else "") + "."]
    moved = collections.Counter("clean" if r["k"] == 0 else "+".join(r["hidden"]) for r in rows if r.get("bias_moved"))
    out += ["", "A moved bias (none was simulated) named in "
            + (", ".join(f"{c} `{n}`" for n, c in moved.most_common()) + " flight(s)." if moved else "no flight.")]
    applied = [r for r in one if r.get("drift_applied") and r.get("drift_true_model")]
    if applied:
        within = sum(r["drift_applied"] <= 1.15 * r["drift_true_model"] for r in applied)
        out += ["", f"After --apply the outage drift is within 15 % of the true model's in {within} of {len(applied)} "
                    f"one-effect flights ({100 * within / len(applied):.0f} %)."]
    pairs = [r for r in rows if r["k"] == 2]
    if pairs:
        ok = sum(correct(r) for r in pairs)
        out += ["", "| two hidden effects | named (rounds of 2) | both found | matters (5 %) | "
                    "outage drift RMS: baseline / after --apply / true model [m] |", "|---|---|---|---|---|"]
        fmt = lambda v: f"{v:.2f}" if v is not None else "n/a"
        for r in sorted(pairs, key=lambda r: r["seed"]):
            mat = [e for e in r["hidden"] if matters_in_pair(r, e)]
            out.append(f"| {', '.join(r['hidden'])} | {', '.join(r['named']) or 'nothing'} | "
                       f"{'yes' if correct(r) else 'no'} | {', '.join(mat) or 'neither'} | "
                       f"{fmt(r.get('drift_baseline'))} / {fmt(r.get('drift_applied'))} / {fmt(r.get('drift_true_model'))} |")
        out.append(f"| **both found** | | **{ok} of {len(pairs)} ({100 * ok / len(pairs):.0f} %)** | | |")
        both = [r for r in pairs if all(matters_in_pair(r, e) for e in r["hidden"])]
        found_mat = sum(all(e in r["named"] for e in r["hidden"] if matters_in_pair(r, e)) for r in pairs)
        within = sum(r["drift_applied"] <= 1.15 * r["drift_true_model"] for r in pairs
                     if r.get("drift_applied") and r.get("drift_true_model"))
        out += ["", f"Where both matter (each, added to the other's states, lowers the outage drift by "
                    f"{100 * MATTERS:.0f} %, or the model carries it): both named in {sum(correct(r) for r in both)} of "
                    f"{len(both)}. Every effect that matters named in {found_mat} of {len(pairs)} pairs. After --apply "
                    f"the outage drift is within 15 % of the true model's in {within} of {len(pairs)}."]
    sweep = sorted((r for r in rows if r.get("sweep")), key=lambda r: (r["scale"], r["seed"]))
    if sweep:
        sweep_effect = sweep[0]["hidden"][0]
        out += ["", f"`{sweep_effect}` at its drawn value times a scale (--sweep, the same flights and units):", "",
                "| scale | flights | named first (right) | named instead | matters (true model 5 % better) | "
                "outage drift RMS: baseline / after --apply / true model [m] |", "|---|---|---|---|---|---|"]
        for x in sorted({r["scale"] for r in sweep}):
            rs = [r for r in sweep if r["scale"] == x]
            instead = collections.Counter(r["named"][0] if r["named"] else "nothing" for r in rs if not correct(r))
            med = lambda key: statistics.median(r[key] for r in rs if r.get(key) is not None)
            out.append(f"| {x:g} | {len(rs)} | {sum(correct(r) for r in rs)} | "
                       f"{', '.join(f'{n} x{c}' for n, c in instead.most_common()) or '-'} | "
                       f"{sum(matters(r) for r in rs)} | "
                       f"{med('drift_baseline'):.2f} / {med('drift_applied'):.2f} / {med('drift_true_model'):.2f} |")
    return "\n".join(out) + "\n"


def write_section(path, marker, text):
    """The text to stdout (path "-"), or into the file between `<!-- marker: begin -->` and
    `<!-- marker: end -->` when it has them (docs/diagnose.md), else as the whole file."""
    if path == "-":
        sys.stdout.write(text)
        return
    begin, end = f"<!-- {marker}: begin -->\n", f"<!-- {marker}: end -->"
    old = open(path).read() if os.path.exists(path) else ""
    if begin in old and end in old:
        text = old[:old.index(begin) + len(begin)] + text + old[old.index(end):]
    open(path, "w").write(text)


if __name__ == "__main__":
    main()
