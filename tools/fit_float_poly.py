#!/usr/bin/env python3
"""Minimax (Remez exchange) fits of the float polynomials in
lib/strider/math/float_atan.h. Standard library only:

    python3 tools/fit_float_poly.py

The forms follow Cephes' atanf/asinf/acosf (S. L. Moshier, Cephes Math
Library, 1989-1992): reduce the argument so that a short odd polynomial
suffices, and go through sqrt(1 - |x|) near +-1. Strider refits the
coefficients for absolute error (what an IK angle needs) with one degree
fewer than Cephes where 2e-6 rad allows it:

  atan t  = t P(t^2),         |t| <= tan(pi/8)      (degree 3 in t^2)
  asin x  = x P(x^2),         |x| <= 1/2            (degree 4 in x^2)
  acos a  = sqrt(w) Q(w),     w = 1 - a in [0, 1/2] (degree 4 in w)

For each fit the script prints the coefficients rounded to float (9
significant digits reproduce the float exactly), the minimax error of the
exact polynomial, and the error of the float coefficients evaluated with
float rounding after every operation (Horner), on a dense grid.
"""

import math
import struct


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def solve(a, b):
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(n):
            if r != c:
                f = m[r][c] / m[c][c]
                for k in range(c, n + 1):
                    m[r][k] -= f * m[c][k]
    return [m[i][n] / m[i][i] for i in range(n)]


def remez(g, w, a, b, deg, iters=40, grid_n=20000):
    """Coefficients c minimising max |w(x) (g(x) - sum c_k x^k)| on [a, b]."""
    n = deg + 2
    xs = [(a + b) / 2 - (b - a) / 2 * math.cos(math.pi * i / (n - 1)) for i in range(n)]
    grid = [a + (b - a) * i / grid_n for i in range(grid_n + 1)]
    coef = None
    for _ in range(iters):
        rows = [[x ** k for k in range(deg + 1)] + [(-1) ** i / w(x)] for i, x in enumerate(xs)]
        coef = solve(rows, [g(x) for x in xs])[:-1]
        ev = [w(x) * (g(x) - sum(c * x ** k for k, c in enumerate(coef))) for x in grid]
        segs, cur = [], [0]
        for j in range(1, len(grid)):
            if (ev[j] >= 0) == (ev[cur[0]] >= 0):
                cur.append(j)
            else:
                segs.append(cur)
                cur = [j]
        segs.append(cur)
        pts = [max(s, key=lambda j: abs(ev[j])) for s in segs]
        while len(pts) > n:
            pts.pop(0 if abs(ev[pts[0]]) < abs(ev[pts[-1]]) else -1)
        if len(pts) < n:
            break
        xs = [grid[j] for j in pts]
    return coef


def horner_f32(coef, z):
    acc = f32(coef[-1])
    for c in reversed(coef[:-1]):
        acc = f32(f32(acc * z) + f32(c))
    return acc


def report(name, coef, exact, approx_f32, lo, hi, n=200000):
    worst = 0.0
    for i in range(n + 1):
        x = f32(lo + (hi - lo) * i / n)
        worst = max(worst, abs(approx_f32(x) - exact(x)))
    print("%s:" % name)
    for k, c in enumerate(coef):
        print("  c%d = %.9ef" % (k, f32(c)))
    print("  max abs error with float arithmetic: %.3g rad" % worst)


def main():
    tan_pi8 = math.tan(math.pi / 8)

    def atan_g(z):
        t = math.sqrt(z)
        return 1.0 if z < 1e-14 else math.atan(t) / t

    c = [f32(v) for v in remez(atan_g, lambda z: math.sqrt(z) if z > 0 else 1e-300, 0.0, tan_pi8 ** 2, 3)]
    report("atan t = t P(t^2), |t| <= tan(pi/8)", c, math.atan,
           lambda t: f32(t * horner_f32(c, f32(t * t))), 0.0, tan_pi8)

    def asin_g(z):
        s = math.sqrt(z)
        return 1.0 if z < 1e-14 else math.asin(s) / s

    c = [f32(v) for v in remez(asin_g, lambda z: math.sqrt(z) if z > 0 else 1e-300, 0.0, 0.25, 4)]
    report("asin x = x P(x^2), |x| <= 1/2", c, math.asin,
           lambda x: f32(x * horner_f32(c, f32(x * x))), 0.0, 0.5)

    def acos_g(w):
        return math.sqrt(2.0) if w < 1e-14 else math.acos(1.0 - w) / math.sqrt(w)

    c = [f32(v) for v in remez(acos_g, lambda w: math.sqrt(w) if w > 0 else 1e-300, 0.0, 0.5, 4)]
    report("acos a = sqrt(1 - a) Q(1 - a), a in [1/2, 1]", c, math.acos,
           lambda a: f32(f32(math.sqrt(f32(1.0 - a))) * horner_f32(c, f32(1.0 - a))), 0.5, 1.0)


if __name__ == "__main__":
    main()
