#!/usr/bin/python3
"""Reference outputs of batch wavelet denoising (pywt) for the C++ tests.

Run: /usr/bin/python3 tools/gen_wavelet_fixtures.py
Writes host_tests/fixtures/wavelet/:
  signal.txt                  the test signal, one value per line
  <wavelet>_L<levels>.txt     header "first N", then N reference values
The reference is pywt.waverec(details zeroed, pywt.wavedec(x, w, 'symmetric',
level)), Debian's python3-pywt. Only the interior is stored: samples whose value
does not depend on anything outside the signal (checked by padding the signal
with two different random prefixes/suffixes whose lengths are multiples of
2^levels, which keeps the decimation phase), so the C++ streaming filter, which
sees a different start-up, must match every stored value.
"""
import pathlib

import numpy as np
import pywt

OUT = pathlib.Path(__file__).resolve().parent.parent / 'host_tests' / 'fixtures' / 'wavelet'
WAVELETS = {'haar': 'haar', 'db2': 'db2', 'db4': 'db4', 'cdf53': 'bior2.2', 'cdf97': 'bior4.4'}
N = 384
RATE_HZ = 40.0


def denoise(x, w, levels):
    coeffs = pywt.wavedec(x, w, mode='symmetric', level=levels)
    coeffs = [coeffs[0]] + [np.zeros_like(c) for c in coeffs[1:]]
    return pywt.waverec(coeffs, w, mode='symmetric')[:len(x)]


def interior(x, w, levels, rng):
    pad = 64 * 2 ** levels
    ys = []
    for _ in range(2):
        xp = np.concatenate([rng.standard_normal(pad), x, rng.standard_normal(pad)])
        ys.append(denoise(xp, w, levels)[pad:pad + len(x)])
    ys.append(denoise(x, w, levels))
    same = (np.abs(ys[0] - ys[1]) < 1e-12) & (np.abs(ys[0] - ys[2]) < 1e-12)
    idx = np.nonzero(same)[0]
    first, last = int(idx[0]), int(idx[-1])
    assert np.all(same[first:last + 1]), 'interior is not contiguous'
    return first, last + 1


def main():
    rng = np.random.default_rng(20261122)
    t = np.arange(N) / RATE_HZ
    # an accelerometer-like test signal: offset, slow motion, 14 Hz vibration, noise
    x = (0.8 + 0.5 * np.sin(2 * np.pi * 0.7 * t) + 0.3 * np.sin(2 * np.pi * 14.0 * t + 0.4)
         + 0.2 * rng.standard_normal(N))
    OUT.mkdir(parents=True, exist_ok=True)
    np.savetxt(OUT / 'signal.txt', x, fmt='%.17g')
    for name, w in WAVELETS.items():
        for levels in range(1, 5):
            first, end = interior(x, w, levels, rng)
            y = denoise(x, w, levels)
            with open(OUT / f'{name}_L{levels}.txt', 'w') as f:
                f.write(f'{first} {end - first}\n')
                for v in y[first:end]:
                    f.write(f'{v:.16g}\n')
            print(f'{name} (pywt {w}) level {levels}: interior [{first}, {end})')


if __name__ == '__main__':
    main()
