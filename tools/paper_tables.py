#!/usr/bin/python3
"""Paper tables from sinu replay outputs (run by tools/paper_experiments.sh).

  paper_tables.py places TRUTH_CSV            -> 8 outage start times (stdout)
  paper_tables.py table5 DIR                  -> Table 5 (markdown)
  paper_tables.py table6 DIR                  -> Table 6 (markdown)

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


def table5(d):
    rows = ["| GPS period [s] | GM: RMSE vs 0.2 s solution [m] | AR: RMSE vs 0.2 s solution [m] | GM: RMSE vs truth [m] | AR: RMSE vs truth [m] |",
            "|---|---|---|---|---|"]
    ref = {m: load(f"{d}/{m}_p0.2/nav.csv") for m in ("gm", "ar")}
    for p in ("0.2", "10", "15", "20", "25", "30"):
        cells = []
        for m in ("gm", "ar"):
            e = horiz_err(load(f"{d}/{m}_p{p}/nav.csv"), ref[m])
            cells.append(f"{np.sqrt(np.mean(e ** 2)):.2f}")
        for m in ("gm", "ar"):
            s = json.load(open(f"{d}/{m}_p{p}/summary.json"))
            cells.append(f"{s['rmse']['pos_h_m']:.2f}")
        rows.append(f"| {p} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def table6(d):
    kinds = [line.split(",")[1].strip() for line in open(f"{d}/places.txt")]
    out = []
    for dur in ("20", "25", "30"):
        s = {m: json.load(open(f"{d}/{m}_o{dur}/summary.json")) for m in ("gm", "ar")}
        out.append(f"\n{dur} s outages: maximum horizontal drift against truth [m]\n")
        out.append("| place | start t [s] | dynamics | GM | AR |")
        out.append("|---|---|---|---|---|")
        gm_all, ar_all = [], []
        for i, (og, oa) in enumerate(zip(s["gm"]["outages"], s["ar"]["outages"])):
            gm_all.append(og["max_drift_h_m"])
            ar_all.append(oa["max_drift_h_m"])
            out.append(f"| {i + 1} | {og['start']:.1f} | {kinds[i]} | {og['max_drift_h_m']:.1f} | {oa['max_drift_h_m']:.1f} |")
        out.append(f"| RMS | | | {np.sqrt(np.mean(np.square(gm_all))):.1f} | {np.sqrt(np.mean(np.square(ar_all))):.1f} |")
    return "\n".join(out)


if __name__ == "__main__":
    if sys.argv[1] == "places":
        for t, k in places(sys.argv[2]):
            print(f"{t:.3f},{k}")
    elif sys.argv[1] == "table5":
        print(table5(sys.argv[2]))
    elif sys.argv[1] == "table6":
        print(table6(sys.argv[2]))
