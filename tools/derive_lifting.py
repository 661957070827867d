#!/usr/bin/python3
"""Derive lifting factorisations of pywt's filter banks by the Euclidean
algorithm on Laurent polynomials (Daubechies & Sweldens 1998, section 7),
verify them numerically against pywt, and print them as C++ step tables.

Run: /usr/bin/python3 tools/derive_lifting.py [--check-only]

Conventions (they are the ones of estimator/wavelet/):
  * The signal is split into pairs  e[m] = x[2m], o[m] = x[2m+1].
  * z^p applied to a pair sequence means "index m + p": z^-1 is one pair late.
  * pywt's analysis is a[k] = sum_j h[j] x[2k+1-j] (downsampling_convolution,
    odd output phase), so its polyphase row is
        he(z) = sum_i h[2i+1] z^-i   (weights of e),
        ho(z) = sum_i h[2i]   z^-i   (weights of o).
  * A predict step is  o[m] += sum_p c_p e[m+p];  an update step is
    e[m] += sum_p c_p o[m+p].  After the steps, s[m] = K e[m] and
    d[m] = o[m] / K' (d is never used: details are dropped).
  * The analysis output s[m] equals pywt's a[m + shift]; `shift` is printed.
"""
import sys

import numpy as np
import pywt

TOL = 1e-11


class Laurent:
    """sum_i c[i] z^(low + i)"""

    def __init__(self, coeffs, low):
        c = np.array(coeffs, dtype=float)
        scale = max(1.0, np.max(np.abs(c))) if c.size else 1.0
        nz = np.nonzero(np.abs(c) > TOL * scale)[0]
        if nz.size == 0:
            self.c, self.low = np.zeros(0), 0
        else:
            self.c, self.low = c[nz[0]:nz[-1] + 1], low + int(nz[0])

    @property
    def zero(self):
        return self.c.size == 0

    @property
    def high(self):
        return self.low + self.c.size - 1

    def __len__(self):
        return self.c.size

    def __add__(self, o):
        if self.zero:
            return o
        if o.zero:
            return self
        lo = min(self.low, o.low)
        hi = max(self.high, o.high)
        c = np.zeros(hi - lo + 1)
        c[self.low - lo:self.low - lo + len(self)] += self.c
        c[o.low - lo:o.low - lo + len(o)] += o.c
        return Laurent(c, lo)

    def __neg__(self):
        return Laurent(-self.c, self.low)

    def __sub__(self, o):
        return self + (-o)

    def __mul__(self, o):
        if self.zero or o.zero:
            return Laurent([], 0)
        return Laurent(np.convolve(self.c, o.c), self.low + o.low)

    def terms(self):
        return [(self.low + i, float(v)) for i, v in enumerate(self.c)]


def quotient(a, b):
    """A quotient q with a - q b shorter than a: kills a's end terms."""
    if len(b) == 1:  # exact division by a monomial
        return Laurent(a.c / b.c[0], a.low - b.low)
    if len(a) == len(b):  # one term kills the highest coefficient
        return Laurent([a.c[-1] / b.c[-1]], a.high - b.high)
    # two terms kill the lowest and the highest coefficient
    lo_exp, hi_exp = a.low - b.low, a.high - b.high
    c = np.zeros(hi_exp - lo_exp + 1)
    c[0] = a.c[0] / b.c[0]
    c[-1] = a.c[-1] / b.c[-1]
    return Laurent(c, lo_exp)


def factor(name):
    w = pywt.Wavelet(name)
    h, g = np.array(w.dec_lo), np.array(w.dec_hi)
    # z^-i for index i: reverse order, exponents 0, -1, -2, ...
    he = Laurent(h[1::2][::-1], -(len(h[1::2]) - 1))
    ho = Laurent(h[0::2][::-1], -(len(h[0::2]) - 1))
    ge = Laurent(g[1::2][::-1], -(len(g[1::2]) - 1))
    go = Laurent(g[0::2][::-1], -(len(g[0::2]) - 1))
    steps = []  # ('predict'|'update', Laurent)

    def right_mul(kind, q):
        nonlocal he, ho, ge, go
        # predict o += q e  <=>  row (re, ro) -> (re - q ro, ro)
        # update  e += q o  <=>  row (re, ro) -> (re, ro - q re)
        if kind == 'predict':
            he, ge = he - q * ho, ge - q * go
        else:
            ho, go = ho - q * he, go - q * ge
        steps.append((kind, q))

    while not he.zero and not ho.zero:
        if len(he) >= len(ho) and not (len(he) == len(ho) == 1):
            right_mul('predict', quotient(he, ho))
        elif len(ho) > len(he):
            right_mul('update', quotient(ho, he))
        else:  # both monomials: remove the odd one
            right_mul('update', quotient(ho, he))
    if he.zero:  # (0, c z^k): move it to the even channel
        right_mul('predict', Laurent([-1.0], 0))  # (c, c)  -> he = 0 - (-1) ho
        right_mul('update', quotient(ho, he))
    assert len(he) == 1 and ho.zero
    K, k_shift = float(he.c[0]), he.low
    # high row is now (ge, go) with go a monomial (the determinant is one);
    # a last predict o += (ge / go) e makes it (0, go)
    assert len(go) == 1
    t = Laurent(ge.c / go.c[0], ge.low - go.low)
    if not t.zero:
        right_mul('predict', t)
    assert ge.zero and len(go) == 1
    return dict(name=name, steps=steps, K=K, k_shift=k_shift, d_scale=float(go.c[0]), h=h)


def lifting_forward(x, f):
    e, o = x[0::2].astype(float).copy(), x[1::2].astype(float).copy()
    n = len(e)

    def apply(target, src, q, sign):
        out = target.copy()
        for p, c in q.terms():
            for m in range(n):
                if 0 <= m + p < n:
                    out[m] += sign * c * src[m + p]
        return out

    for kind, q in f['steps']:
        if kind == 'predict':
            o = apply(o, e, q, +1)
        else:
            e = apply(e, o, q, +1)
    return f['K'] * e, o


def lifting_inverse_lowpass(s, f):
    e = s / f['K']
    o = np.zeros_like(e)
    n = len(e)

    def apply(target, src, q):
        out = target.copy()
        for p, c in q.terms():
            for m in range(n):
                if 0 <= m + p < n:
                    out[m] -= c * src[m + p]
        return out

    for kind, q in reversed(f['steps']):
        if kind == 'predict':
            o = apply(o, e, q)
        else:
            e = apply(e, o, q)
    x = np.zeros(2 * n)
    x[0::2], x[1::2] = e, o
    return x


def verify(f, rng):
    """s[m] = pywt a[m + shift] and the approximation-only reconstruction of
    one level equals pywt's idwt(a, None) away from the ends."""
    x = rng.standard_normal(400)
    a = pywt.dwt(x, f['name'], mode='symmetric')[0]
    s, _ = lifting_forward(x, f)
    margin = 12
    best = None
    for shift in range(-8, 9):
        m = np.arange(margin, len(s) - margin)
        if np.all((m + shift >= 0) & (m + shift < len(a))):
            err = np.max(np.abs(s[m] - a[m + shift]))
            if best is None or err < best[1]:
                best = (shift, err)
    shift, err_a = best
    # approximation-only: feed pywt's a (shifted to lifting indexing)
    s_from_a = np.array([a[m + shift] if 0 <= m + shift < len(a) else 0.0 for m in range(len(s))])
    y = lifting_inverse_lowpass(s_from_a, f)
    y_ref = pywt.idwt(a, None, f['name'], mode='symmetric')[:len(x)]
    n = np.arange(4 * margin, len(x) - 4 * margin)
    err_y = np.max(np.abs(y[n] - y_ref[n]))
    return shift, err_a, err_y


def main():
    rng = np.random.default_rng(4)
    ok = True
    for name in ['haar', 'db2', 'db4', 'bior2.2', 'bior4.4']:
        f = factor(name)
        shift, err_a, err_y = verify(f, rng)
        # 1e-10: pywt tabulates bior4.4 to ~12 digits, so its synthesis filter is
        # the exact inverse of its analysis filter only to ~6e-12
        ok &= err_a < 1e-12 and err_y < 1e-10
        print(f"// {name}: {len(f['steps'])} steps, K = {f['K']!r}, pywt shift = {shift}, "
              f"max |s - a| = {err_a:.2e}, max |y - idwt| = {err_y:.2e}")
        if '--check-only' in sys.argv:
            continue
        for kind, q in f['steps']:
            terms = ', '.join(f"{{{p}, {c!r}}}" for p, c in q.terms())
            print(f"//   {kind:7s} {terms}")
    if not ok:
        print("FACTORISATION CHECK FAILED", file=sys.stderr)
        sys.exit(1)


if __name__ == '__main__':
    main()
