#!/usr/bin/python3
"""Plots of a `sinu calibrate --report DIR` folder (run with /usr/bin/python3).

  plot_calibration.py DIR            per session and axis: acf_s<k>_<axis>.png
                                     (measured vs GM1 vs AR(p)), allan_s<k>_<axis>.png
                                     (measured ADEV with interval vs the noise model)
  plot_calibration.py DIR --paper OUT  the paper's figures across sessions into OUT:
                                     figure7_<axis>.png (variance vs order per method),
                                     consistency_<method>.png (coefficient spread)
"""
import csv
import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["yule_walker", "covariance", "burg"]


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def col(rows, key):
    return [float(r[key]) if r[key] != "" else float("nan") for r in rows]


def plot_acf(path, out):
    rows = read(path)
    lag = col(rows, "lag_s")
    r0 = float(rows[0]["measured"])
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=90)
    ax.plot(lag, [v / r0 for v in col(rows, "measured")], "k", lw=1.2, label="measured (denoised)")
    ax.plot(lag, [v / r0 for v in col(rows, "gm1")], "r--", lw=1, label="GM1")
    if "ar_model_rate" in rows[0]:  # the AR at the model rate (block means: right beyond one block)
        ax.plot(lag, [v / r0 for v in col(rows, "ar_model_rate")], "b-.", lw=1, label="AR at the model rate")
    for key in rows[0].keys():
        if key.endswith(tuple(f"_ar{p}" for p in range(1, 11))):
            vals = col(rows, key)
            if vals[0] == vals[0]:
                ax.plot(lag, [v / vals[0] for v in vals], lw=0.8, label=key.replace("_", " "))
    ax.set_xscale("symlog", linthresh=1.0)
    ax.set_xlabel("lag [s]")
    ax.set_ylabel("normalised autocorrelation")
    ax.axhline(0, color="0.7", lw=0.5)
    ax.legend(fontsize=7)
    ax.set_title(os.path.basename(path)[:-4], fontsize=9)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)


def plot_allan(path, out):
    rows = read(path)
    tau = col(rows, "tau_s")
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=90)
    ax.fill_between(tau, col(rows, "adev_low"), col(rows, "adev_high"), color="0.85", label="68% interval")
    ax.loglog(tau, col(rows, "adev"), "k.-", lw=1, ms=3, label="measured (raw)")
    ax.loglog(tau, col(rows, "model_adev"), "r--", lw=1, label="fitted Q/N/B/K/R model")
    models = path.replace(os.sep + "allan_s", os.sep + "allan_models_s")
    if os.path.exists(models):  # what each EKF model predicts over 1-100 s (white noise N added)
        m = read(models)
        mt = col(m, "tau_s")
        for key, style, label in (("gm1", "m:", "GM1"), ("ar_imu_rate", "g-.", "AR at the IMU rate"),
                                  ("ar_model_rate", "b-", "AR at the model rate")):
            ax.loglog(mt, col(m, key), style, lw=1.2, label=label)
    ax.set_xlabel("tau [s]")
    ax.set_ylabel("Allan deviation")
    ax.grid(True, which="both", color="0.9")
    ax.legend(fontsize=7)
    ax.set_title(os.path.basename(path)[:-4], fontsize=9)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)


def paper_figures(report, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    var = read(os.path.join(report, "ar_variance.csv"))
    sessions = sorted({r["session"] for r in var})
    for axis in sorted({r["axis"] for r in var}):
        fig, ax = plt.subplots(figsize=(5.6, 3.4), dpi=90)
        for m, style in zip(METHODS, ["o-", "s--", "^:"]):
            for s in sessions:
                pts = [r for r in var if r["axis"] == axis and r["method"] == m and r["session"] == s]
                ax.semilogy([int(r["order"]) for r in pts], [float(r["variance"]) for r in pts], style, ms=3,
                            lw=0.8, label=f"{m} s{s}" if len(sessions) > 1 else m)
        ax.set_xlabel("AR order p")
        ax.set_ylabel("driving-noise variance")
        ax.set_title(f"Figure 7 analogue: {axis}", fontsize=9)
        ax.legend(fontsize=6, ncol=3)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, f"figure7_{axis}.png"))
        plt.close(fig)
    coef = read(os.path.join(report, "ar_coefficients.csv"))
    axes = sorted({r["axis"] for r in coef})
    for m in METHODS:
        fig, axs = plt.subplots(1, 3, figsize=(9.6, 3.0), dpi=90, sharey=False)
        for ax, p in zip(axs, [4, 5, 6]):
            for k, axis in enumerate(axes):
                for s in sessions:
                    pts = [r for r in coef if r["axis"] == axis and r["method"] == m and r["session"] == s
                           and int(r["order"]) == p]
                    ax.plot([int(r["index"]) + 0.1 * (k - 2.5) for r in pts], [float(r["value"]) for r in pts], "o",
                            ms=2.5, color=f"C{k}", label=axis if s == sessions[0] else None)
            ax.set_title(f"{m} AR({p})", fontsize=9)
            ax.set_xlabel("coefficient index i")
        axs[0].set_ylabel("a_i (all sessions)")
        axs[0].legend(fontsize=6)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, f"consistency_{m}.png"))
        plt.close(fig)


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    report = argv[1]
    if len(argv) >= 4 and argv[2] == "--paper":
        paper_figures(report, argv[3])
        return 0
    for path in sorted(glob.glob(os.path.join(report, "acf_s*_*.csv"))):
        plot_acf(path, path[:-4] + ".png")
    for path in sorted(glob.glob(os.path.join(report, "allan_s*_*.csv"))):
        plot_allan(path, path[:-4] + ".png")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
