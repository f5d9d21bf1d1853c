#!/usr/bin/env python3
"""The polynomial ζ(−β, x) ≈ P(2x − 3) on x ∈ [1, 2] for β = 1/4 (Hertz) and β = 1/2 (p = 2) of
src/contact/step_exact.rs (`HURWITZ_Q`, `HURWITZ_H`) and include/demcontact_inline.h: Chebyshev
interpolation of degree 13 at 40 digits (mpmath's zeta), converted to monomials in t = 2x − 3 and
rounded to doubles. Prints the coefficients and the largest absolute error of the rounded
polynomial, evaluated by Horner in doubles as the kernel does, on 4001 points of [1, 2].
Run: python3 scripts/hurwitz_fit.py (needs mpmath)."""
import mpmath as mp

mp.mp.dps = 40
DEGREE = 13


def cheb_mono(f, n):
    """Monomial coefficients (in t) of the degree-n Chebyshev interpolant of f on [-1, 1]."""
    m = n + 1
    nodes = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / m) for k in range(m)]
    vals = [f(t) for t in nodes]
    cheb = []
    for j in range(m):
        s = sum(vals[k] * mp.cos(j * mp.pi * (k + mp.mpf(1) / 2) / m) for k in range(m))
        cheb.append(2 * s / m if j else s / m)
    mono = [mp.mpf(0)] * m
    prev, cur = [mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]
    for j in range(m):
        if j == 0:
            t_j = prev
        elif j == 1:
            t_j = cur
        else:
            t_j = [mp.mpf(0)] * (j + 1)
            for i, a in enumerate(cur):
                t_j[i + 1] += 2 * a
            for i, a in enumerate(prev):
                t_j[i] -= a
            prev, cur = cur, t_j
        for i, a in enumerate(t_j):
            mono[i] += cheb[j] * a
    return [float(c) for c in mono]


def horner(c, t):
    r = c[-1]
    for a in reversed(c[:-1]):
        r = a + t * r
    return r


def main():
    status = 0
    for beta, name in ((0.25, "HURWITZ_Q"), (0.5, "HURWITZ_H")):
        c = cheb_mono(lambda t: mp.zeta(-beta, mp.mpf(3) / 2 + t / 2), DEGREE)
        worst = 0.0
        for i in range(4001):
            x = 1.0 + i / 4000
            worst = max(worst, abs(float(horner(c, 2.0 * x - 3.0) - mp.zeta(-beta, x))))
        print(f"{name} (beta = {beta}): largest error {worst:.2e} on [1, 2]")
        print("    " + ",\n    ".join(repr(v) for v in c) + ",")
        if not worst < 1e-12:
            status = 1
    return status


if __name__ == "__main__":
    raise SystemExit(main())
