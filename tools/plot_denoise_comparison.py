#!/usr/bin/python3
"""Per-axis standard deviation before/after `sinu denoise` and a plot like the
paper's Figure 3 (60 s of the y accelerometer, raw and denoised).

Run (see docs/wavelet.md for the whole recipe):
  /usr/bin/python3 tools/plot_denoise_comparison.py STATIC STATIC_DN FLIGHT FLIGHT_DN [FLIGHT_T0]
FLIGHT_T0: start of the plotted flight minute, seconds after the first row (default 240).
Prints a Markdown table; writes docs/img/wavelet_fig3.png.
"""
import pathlib
import sys

import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

OUT = pathlib.Path(__file__).resolve().parent.parent / 'docs' / 'img' / 'wavelet_fig3.png'
AXES = ['ax', 'ay', 'az', 'gx', 'gy', 'gz']
EDGE = 80  # rows dropped at each end: the filter's ends use the held sample


def load(folder):
    with open(pathlib.Path(folder) / 'imu.csv') as f:
        names = f.readline().strip().split(',')
    data = np.genfromtxt(pathlib.Path(folder) / 'imu.csv', delimiter=',', skip_header=1)
    return {n: data[:, i] for i, n in enumerate(names)}


def main():
    static, static_dn, flight, flight_dn = (load(p) for p in sys.argv[1:5])
    flight_t0 = float(sys.argv[5]) if len(sys.argv) > 5 else 240.0
    print('| session | axis | unit | std raw | std denoised | ratio | std removed (raw - denoised) |')
    print('|---|---|---|---|---|---|---|')
    for label, raw, dn in [('static', static, static_dn), ('flight', flight, flight_dn)]:
        assert np.array_equal(raw['t'], dn['t'])
        for a in AXES:
            r, d = raw[a][EDGE:-EDGE], dn[a][EDGE:-EDGE]
            unit = 'm/s^2' if a[0] == 'a' else 'rad/s'
            print(f'| {label} | {a} | {unit} | {np.std(r):.4g} | {np.std(d):.4g} | {np.std(d) / np.std(r):.3f} '
                  f'| {np.std(r - d):.4g} |')
    fig, axes = plt.subplots(2, 1, figsize=(9, 6))
    for ax, (label, raw, dn, t0) in zip(axes, [('(a) static bench', static, static_dn, 60.0),
                                               ('(b) UAV flight', flight, flight_dn, flight_t0)]):
        t = raw['t'] - raw['t'][0]
        sel = (t >= t0) & (t < t0 + 60)
        ax.plot(t[sel], raw['ay'][sel], lw=0.6, color='tab:blue',
                label=f'raw (std in this minute {np.std(raw["ay"][sel]):.4f})')
        ax.plot(t[sel], dn['ay'][sel], lw=1.2, color='tab:red',
                label=f'db4 level 3 (std {np.std(dn["ay"][sel]):.4f})')
        ax.set_title(f'{label}: y accelerometer, 60 s (simulated)')
        ax.set_ylabel('ay [m/s^2]')
        ax.legend(fontsize=8, loc='upper right')
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel('time since start [s]')
    fig.tight_layout()
    fig.savefig(OUT, dpi=64)
    print(OUT, file=sys.stderr)


if __name__ == '__main__':
    main()
