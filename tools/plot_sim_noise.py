#!/usr/bin/python3
"""Autocorrelation of a simulated static session's IMU error after the
paper's wavelet denoising (db4, level-3 approximation at 40 Hz, ~2.5 Hz),
against the first-order Gauss-Markov autocorrelation with the same lag-1
value. Shows the periodic-random component a GM model cannot follow.

usage: tools/plot_sim_noise.py DATASET HIDDEN.json OUT.png
(run with /usr/bin/python3: numpy, matplotlib, pywt from Debian)
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pywt


def denoise(x):
    coeffs = pywt.wavedec(x, "db4", level=3)
    coeffs = [coeffs[0]] + [np.zeros_like(c) for c in coeffs[1:]]
    return pywt.waverec(coeffs, "db4")[: len(x)]


def autocorr(x, max_lag):
    x = x - x.mean()
    n = len(x)
    f = np.fft.rfft(x, 2 * n)
    r = np.fft.irfft(f * np.conj(f))[:max_lag]
    return r / r[0]


def main():
    dataset, hidden_path, out = sys.argv[1:4]
    hidden = json.load(open(hidden_path))
    rate = hidden["imu_rate_hz"]
    data = np.loadtxt(f"{dataset}/imu.csv", delimiter=",", skiprows=1, usecols=range(1, 7), max_rows=int(rate * 7200))
    true = np.array(hidden["true_specific_force_b_m_s2"] + hidden["true_angular_rate_b_rad_s"])
    err = data - true
    max_lag = int(120 * rate)
    lags = np.arange(max_lag) / rate
    fig, axes = plt.subplots(2, 3, figsize=(11, 5.5), sharex=True)
    names = ["accel x", "accel y", "accel z", "gyro x", "gyro y", "gyro z"]
    for i, ax in enumerate(axes.flat):
        triad = hidden["imu_error_model"]["accel" if i < 3 else "gyro"]
        period = triad["periodic_period_s"][i % 3]
        r = autocorr(denoise(err[:, i]), max_lag)
        gm = r[1] ** (lags * rate)  # first-order GM with the same lag-1 correlation
        ax.plot(lags, r, lw=1, label="denoised error")
        ax.plot(lags, gm, lw=1, ls="--", label="1st-order GM")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_title(f"{names[i]} (periodic {period:.1f} s)", fontsize=9)
        ax.set_ylim(-1, 1)
    for ax in axes[1]:
        ax.set_xlabel("lag [s]")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("sinu simulate static: autocorrelation of the wavelet-denoised IMU error (first 2 h)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=70)


if __name__ == "__main__":
    main()
