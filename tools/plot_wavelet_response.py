#!/usr/bin/python3
"""Plot the denoiser's measured magnitude response (CSV of the C++ host tool
build/release/host_tests/wavelet_response) as docs/img/wavelet_response.png.

Run: build/release/host_tests/wavelet_response /tmp/wavelet_response.csv
     /usr/bin/python3 tools/plot_wavelet_response.py /tmp/wavelet_response.csv
"""
import csv
import pathlib
import sys
from collections import defaultdict

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

OUT = pathlib.Path(__file__).resolve().parent.parent / 'docs' / 'img' / 'wavelet_response.png'


def main():
    data = defaultdict(lambda: ([], []))
    with open(sys.argv[1]) as f:
        for row in csv.DictReader(f):
            fr, g = data[(row['wavelet'], int(row['levels']))]
            fr.append(float(row['freq_hz']))
            g.append(float(row['gain']))
    fig, axes = plt.subplots(2, 2, figsize=(10, 6.5), sharex=True, sharey=True)
    for level, ax in zip(range(1, 5), axes.flat):
        for name in ['haar', 'db2', 'db4', 'cdf53', 'cdf97']:
            fr, g = data[(name, level)]
            ax.plot(fr, g, label=name, lw=1.2, ls='--' if name.startswith('cdf') else '-')
        ax.axvspan(12, 16, color='orange', alpha=0.15, label='engine band 12-16 Hz')
        ax.axvline(40 / 2 ** (level + 1), color='red', lw=0.8, label='40 / 2^(L+1) Hz')
        ax.axhline(2 ** -0.5, color='gray', lw=0.6, ls=':')
        ax.set_title(f'level {level}')
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel('frequency [Hz] (40 Hz sampling)')
    for ax in axes[:, 0]:
        ax.set_ylabel('gain (measured, C++)')
    axes[0, 0].legend(fontsize=8)
    fig.suptitle('Streaming wavelet denoiser: magnitude response (approximation only)')
    fig.tight_layout()
    fig.savefig(OUT, dpi=80)
    print(OUT)


if __name__ == '__main__':
    main()
