#!/usr/bin/python3
"""Markdown tables of the paper's Section 3 from a multi-session
`sinu calibrate --report DIR` folder (run with /usr/bin/python3):
Tables 1-3 (AR(4) ax, AR(5) az, AR(6) gy coefficients, three methods, all
sessions, with the spread across sessions), Table 4 (GM1 versus AR(3)).

  calibration_tables.py DIR
"""
import csv
import statistics
import sys

METHODS = ["yule_walker", "covariance", "burg"]


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def coefficient_table(coef, axis, order):
    sessions = sorted({r["session"] for r in coef})
    lines = [f"| method | session | " + " | ".join(f"a{i}" for i in range(1, order + 1)) + " |",
             "|---|---|" + "---|" * order]
    spreads = {}
    for m in METHODS:
        per_index = {i: [] for i in range(1, order + 1)}
        for s in sessions:
            vals = {int(r["index"]): float(r["value"]) for r in coef
                    if r["axis"] == axis and r["method"] == m and r["session"] == s and int(r["order"]) == order}
            for i, v in vals.items():
                per_index[i].append(v)
            lines.append(f"| {m} | {s} | " + " | ".join(f"{vals[i]:.5f}" for i in range(1, order + 1)) + " |")
        spread = [max(v) - min(v) for v in per_index.values()]
        spreads[m] = max(spread)
        lines.append(f"| {m} | spread | " + " | ".join(f"{x:.5f}" for x in spread) + " |")
    return "\n".join(lines), spreads


def main(argv):
    d = argv[1]
    coef = read(f"{d}/ar_coefficients.csv")
    for title, axis, order in [("Table 1", "ax", 4), ("Table 2", "az", 5), ("Table 3", "gy", 6)]:
        table, spreads = coefficient_table(coef, axis, order)
        print(f"### {title}: AR({order}) coefficients of {axis}\n")
        print(table)
        print("\nLargest spread across sessions: " +
              ", ".join(f"{m} {spreads[m]:.4f}" for m in METHODS) + "\n")
    gm = read(f"{d}/gm_vs_ar.csv")
    print("### Table 4: GM1 versus AR(3) variance\n")
    print("| session | axis | GM1 tau_s | GM1 sigma^2 | GM1 driving var | GM1 1-step pred. var (data) | "
          "YW AR(3) | Cov AR(3) | Burg AR(3) | GM1 pred / Burg AR(3) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in gm:
        ratio = float(r["gm_prediction_variance"]) / float(r["burg_ar3"])
        print(f"| {r['session']} | {r['axis']} | {float(r['gm_tau_s']):.3g} | {float(r['gm_variance']):.3e} | "
              f"{float(r['gm_driving_variance']):.3e} | {float(r['gm_prediction_variance']):.3e} | "
              f"{float(r['yule_walker_ar3']):.3e} | {float(r['covariance_ar3']):.3e} | {float(r['burg_ar3']):.3e} | "
              f"{ratio:.0f} |")
    var = read(f"{d}/ar_variance.csv")
    print("\n### Figure 7 data: ay driving-noise variance by order (session 1)\n")
    print("| order | " + " | ".join(METHODS) + " |\n|---|---|---|---|")
    for p in range(1, 11):
        row = [next(float(r["variance"]) for r in var if r["session"] == "1" and r["axis"] == "ay"
                    and r["method"] == m and int(r["order"]) == p) for m in METHODS]
        print(f"| {p} | " + " | ".join(f"{v:.4e}" for v in row) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
