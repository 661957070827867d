#!/usr/bin/python3
"""Paper tables from sinu replay outputs (run by tools/paper_experiments.sh).

  paper_tables.py places TRUTH_CSV            -> 8 outage start times (stdout)
  paper_tables.py table5 DIR                  -> Table 5 (markdown)
  paper_tables.py table6 DIR                  -> Table 6 (markdown)
  paper_tables.py summary OUT SEED...         -> both across seeds: mean and spread

The models (tools/paper_experiments.sh): gm (GM1), ar40 (Burg AR(3) at the IMU
rate), arrate (Burg AR(3) at the model rate sinu calibrate chose).

Table 5: horizontal position RMSE of the solution with GPS every P seconds
against the solution with every 0.2 s epoch (same model), as in the paper;
the RMSE against truth is given too.
Table 6: per outage place, maximum horizontal drift against truth.
"""
import json
import sys

import numpy as np

R_EARTH = 6371000.0


def load(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def horiz_err(a, b):
    """a, b structured arrays with lat/lon [deg]; rows matched on t."""
    t = np.intersect1d(np.round(a["t"], 3), np.round(b["t"], 3))
    ia = np.isin(np.round(a["t"], 3), t)
    ib = np.isin(np.round(b["t"], 3), t)
    dn = np.radians(a["lat"][ia] - b["lat"][ib]) * R_EARTH
    de = np.radians(a["lon"][ia] - b["lon"][ib]) * R_EARTH * np.cos(np.radians(b["lat"][ib]))
    return np.hypot(dn, de)


def places(truth_csv):
    tr = load(truth_csv)
    t = tr["t"]
    dt = np.median(np.diff(t))
    yaw = np.unwrap(np.radians(tr["yaw"]))
    rate = np.abs(np.gradient(yaw, dt))
    climb = np.abs(tr["vd"])
    speed = np.hypot(tr["vn"], tr["ve"])
    accel = np.abs(np.gradient(speed, dt))
    win = int(30 / dt)

    def mean_over(x):
        return np.convolve(x, np.ones(win) / win, mode="valid")

    start_ok = (t[: len(t) - win + 1] > t[0] + 300) & (t[: len(t) - win + 1] < t[-1] - 120)
    airborne = mean_over(speed) > 20.0
    chosen = []
    scores = {
        "straight": -(mean_over(rate) + mean_over(climb) / 5 + mean_over(accel)),
        "turning": mean_over(rate),
        "climbing": mean_over(climb),
        "speed change": mean_over(accel),
    }
    for kind, score in scores.items():
        for _ in range(2):
            s = np.where(start_ok & airborne, score, -np.inf)
            for c, _k in chosen:
                s[np.abs(t[: len(s)] - c) < 150] = -np.inf
            i = int(np.argmax(s))
            chosen.append((t[i], kind))
    chosen.sort()
    return chosen


MODELS = ("gm", "ar40", "arrate")
NAMES = {"gm": "GM1", "ar40": "AR(3) 40 Hz", "arrate": "AR(3) model rate"}
PERIODS = ("0.2", "10", "15", "20", "25", "30")
DURATIONS = ("20", "25", "30")


def rmse_vs_dense(d, m, p):
    """Horizontal RMSE of the solution with GPS every p s against the same model's 0.2 s solution."""
    e = horiz_err(load(f"{d}/{m}_p{p}/nav.csv"), load(f"{d}/{m}_p0.2/nav.csv"))
    return float(np.sqrt(np.mean(e ** 2)))


def summary_json(d, name):
    return json.load(open(f"{d}/{name}/summary.json"))


def drift_rms(d, m, dur):
    s = summary_json(d, f"{m}_o{dur}")
    return float(np.sqrt(np.mean(np.square([o["max_drift_h_m"] for o in s["outages"]]))))


def table5(d):
    head = " | ".join(f"{NAMES[m]}: vs 0.2 s [m]" for m in MODELS) + " | " + " | ".join(f"{NAMES[m]}: vs truth [m]" for m in MODELS)
    rows = [f"| GPS period [s] | {head} |", "|---" * (1 + 2 * len(MODELS)) + "|"]
    for p in PERIODS:
        cells = [f"{rmse_vs_dense(d, m, p):.2f}" for m in MODELS]
        cells += [f"{summary_json(d, f'{m}_p{p}')['rmse']['pos_h_m']:.2f}" for m in MODELS]
        rows.append(f"| {p} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def table6(d):
    kinds = [line.split(",")[1].strip() for line in open(f"{d}/places.txt")]
    out = []
    for dur in DURATIONS:
        s = {m: summary_json(d, f"{m}_o{dur}") for m in MODELS}
        out.append(f"\n{dur} s outages: maximum horizontal drift against truth [m]\n")
        out.append("| place | start t [s] | dynamics | " + " | ".join(NAMES[m] for m in MODELS) + " |")
        out.append("|---" * (3 + len(MODELS)) + "|")
        for i in range(len(s["gm"]["outages"])):
            o = [s[m]["outages"][i] for m in MODELS]
            out.append(f"| {i + 1} | {o[0]['start']:.1f} | {kinds[i]} | " +
                       " | ".join(f"{x['max_drift_h_m']:.1f}" for x in o) + " |")
        out.append("| RMS | | | " + " | ".join(f"{drift_rms(d, m, dur):.1f}" for m in MODELS) + " |")
    return "\n".join(out)


def mean_spread(values):
    v = np.array(values, dtype=float)
    return f"{v.mean():.2f} ({v.min():.2f}-{v.max():.2f})"


def summary(out, seeds):
    dirs = [f"{out}/seed{s}" for s in seeds]
    lines = [f"Mean over {len(seeds)} seeds ({', '.join(seeds)}), in brackets the smallest and largest.", "",
             "Table 5: horizontal RMSE against the same model's 0.2 s solution [m]", "",
             "| GPS period [s] | " + " | ".join(NAMES[m] for m in MODELS) + " |", "|---" * (1 + len(MODELS)) + "|"]
    for p in PERIODS[1:]:
        lines.append(f"| {p} | " + " | ".join(mean_spread([rmse_vs_dense(d, m, p) for d in dirs]) for m in MODELS) + " |")
    lines += ["", "Table 6: RMS over the eight places of the maximum horizontal drift [m]", "",
              "| outage [s] | " + " | ".join(NAMES[m] for m in MODELS) + " | AR model rate vs GM1 |",
              "|---" * (2 + len(MODELS)) + "|"]
    for dur in DURATIONS:
        per = {m: [drift_rms(d, m, dur) for d in dirs] for m in MODELS}
        gain = [1.0 - a / g for a, g in zip(per["arrate"], per["gm"])]
        lines.append(f"| {dur} | " + " | ".join(mean_spread(per[m]) for m in MODELS) +
                     f" | {100 * np.mean(gain):.0f} % less ({100 * min(gain):.0f}..{100 * max(gain):.0f} %) |")
    lines += ["", "Consistency with GPS every 0.2 s: NEES inside its 95 % bounds (9 dof)", "",
              "| | " + " | ".join(NAMES[m] for m in MODELS) + " |", "|---" * (1 + len(MODELS)) + "|",
              "| NEES inside 95 % | " + " | ".join(mean_spread([summary_json(d, f"{m}_p0.2")["nees"]["inside_95"] for d in dirs]) for m in MODELS) + " |",
              "| NEES mean | " + " | ".join(mean_spread([summary_json(d, f"{m}_p0.2")["nees"]["mean"] for d in dirs]) for m in MODELS) + " |",
              "| model rate [Hz] | | | " + mean_spread([summary_json(d, "arrate_p0.2")["ar"]["rate_hz"] for d in dirs]) + " |"]
    return "\n".join(lines)


if __name__ == "__main__":
    if sys.argv[1] == "places":
        for t, k in places(sys.argv[2]):
            print(f"{t:.3f},{k}")
    elif sys.argv[1] == "table5":
        print(table5(sys.argv[2]))
    elif sys.argv[1] == "table6":
        print(table6(sys.argv[2]))
    elif sys.argv[1] == "summary":
        print(summary(sys.argv[2], sys.argv[3:]))
