#!/usr/bin/env python3
"""Coefficients of core/fast_math.h's asin polynomial, and their error.

asin(s) = s + s z P(z), z = s^2, and acos_fast needs s in [0, 1/2], so z in
[0, 1/4]. P is known exactly as a series, P(z) = sum_k c_(k+1) z^k with
c_0 = 1, c_(k+1) = c_k (2k+1)^2 / ((2k+2)(2k+3)); this prints the
interpolant of P at Chebyshev points of [0, 1/4] as a polynomial in z (the
conversion done in exact fractions), which needs half the terms of the
truncated series for the same error: 12 for double, 6 for float.

    python3 scripts/fit_asin.py
"""
import math
from fractions import Fraction

SERIES = []
c = Fraction(1)
for k in range(80):
    c = c * Fraction((2 * k + 1) ** 2, (2 * k + 2) * (2 * k + 3))
    SERIES.append(float(c))


def p_exact(z):  # all terms positive: no cancellation, ~1 ulp
    s = 0.0
    for coef in reversed(SERIES):
        s = s * z + coef
    return s


def fit(degree, hi=0.25):
    n = degree + 1
    nodes = [math.cos(math.pi * (k + 0.5) / n) for k in range(n)]
    values = [p_exact(hi / 2 * (1 + u)) for u in nodes]
    cheb = [Fraction(2, n) * Fraction(sum(values[k] * math.cos(j * math.pi * (k + 0.5) / n)
                                          for k in range(n))) for j in range(n)]
    cheb[0] /= 2
    t = [[Fraction(1)], [Fraction(0), Fraction(1)]]  # Chebyshev polynomials in u
    for j in range(2, n):
        a = [Fraction(0)] + [2 * x for x in t[j - 1]]
        b = t[j - 2] + [Fraction(0)] * (len(a) - len(t[j - 2]))
        t.append([x - y for x, y in zip(a, b)])
    in_u = [Fraction(0)] * n
    for j in range(n):
        for i, x in enumerate(t[j]):
            in_u[i] += cheb[j] * x
    scale = Fraction(2) / Fraction(hi)  # u = scale z - 1
    in_z = [Fraction(0)] * n
    for i, a in enumerate(in_u):
        for k in range(i + 1):
            in_z[k] += a * math.comb(i, k) * scale ** k * (-1) ** (i - k)
    return [float(x) for x in in_z]


def worst_relative_error(coefs):
    worst = 0.0
    for k in range(1, 20001):
        s = 0.5 * k / 20000
        z = s * s
        p = 0.0
        for coef in reversed(coefs):
            p = p * z + coef
        exact = s + s * z * p_exact(z)
        worst = max(worst, abs(s + s * z * p - exact) / exact)
    return worst


for name, degree in (("double", 11), ("float", 5)):
    coefs = fit(degree)
    print(f"{name}: {len(coefs)} coefficients, worst relative error {worst_relative_error(coefs):.2e}")
    print("   ", ", ".join(repr(x) for x in coefs))
