#!/usr/bin/env python3
"""Exact (symbolic) values of the collision moments mu_p, p = 2, 4, that the C++ quadrature in
theory/src/collision_moments.cpp evaluates numerically. An independent route to the same numbers:
sympy integrates the Gaussian moments exactly. Used to derive the closed forms asserted in
tests/theory/test_collision_moments.cpp; not part of the build.

Definition (paper eq. defmu2, generalised to d dimensions and moment p):
  mu_p = -1/2 \int dc1 dc2 de Theta(-c12.e) |c12.e| f1 f2 [1 + b (k (c1.e)(c2.e) - c1.c2)] Delta(c1^p + c2^p)
with f = phi(c)(1 + a2 S2(c^2)), phi = pi^{-d/2} exp(-c^2), S2 the d-dimensional second Sonine
polynomial, k the dyad factor (3 as printed; d for a traceless dyad in d dimensions).
e is fixed along x by rotational invariance (factor |S^{d-1}|); c1 = C + g/2, c2 = C - g/2.
Usage: python3 collision_moments.py
"""
import sympy as sp


def moments(d, p, dyad):
    eps, a2, b = sp.symbols("epsilon a2 b")
    u = sp.symbols("u", positive=True)  # approach speed -g.e
    C = sp.symbols(f"C1:{d + 1}", real=True)
    gperp = sp.symbols(f"h1:{d}", real=True)
    g = [-u] + list(gperp)
    c1 = [C[i] + g[i] / 2 for i in range(d)]
    c2 = [C[i] - g[i] / 2 for i in range(d)]
    sq = lambda v: sum(x * x for x in v)
    S2 = lambda x: x**2 / 2 - sp.Rational(d + 2, 2) * x + sp.Rational(d * (d + 2), 8)
    gn = g[0]
    c1p = [c1[0] - (1 + eps) / 2 * gn] + c1[1:]
    c2p = [c2[0] + (1 + eps) / 2 * gn] + c2[1:]
    P = lambda v: sq(v) ** sp.Rational(p, 2)
    delta = sp.expand(P(c1p) + P(c2p) - P(c1) - P(c2))
    dyadD = dyad * c1[0] * c2[0] - sum(c1[i] * c2[i] for i in range(d))
    s1, s2 = S2(sq(c1)), S2(sq(c2))
    terms = {"1": 1, "a2": s1 + s2, "a2^2": s1 * s2, "b": dyadD, "a2*b": (s1 + s2) * dyadD,
             "a2^2*b": s1 * s2 * dyadD}
    sphere = {2: 2 * sp.pi, 3: 4 * sp.pi}[d]
    weight = sp.exp(-2 * sq(C) - sq(g) / 2) / sp.pi**d
    out = {}
    for name, t in terms.items():
        integrand = sp.expand(u * t * delta)
        val = 0
        for mono in sp.Add.make_args(integrand):
            m = mono * weight
            for v in list(C) + list(gperp):
                m = sp.integrate(m, (v, -sp.oo, sp.oo))
            m = sp.integrate(m, (u, 0, sp.oo))
            val += m
        out[name] = sp.simplify(-sp.Rational(1, 2) * sphere * val)
    return out


if __name__ == "__main__":
    for d in (2, 3):
        for p in (2, 4):
            for dyad in sorted({3, d}):
                res = moments(d, p, dyad)
                base = res["1"]
                print(f"d={d} p={p} dyad={dyad}: mu_p(0,0) = {sp.factor(base)}")
                for k, v in res.items():
                    if k != "1":
                        print(f"    {k:7s} {sp.factor(sp.simplify(v / base))}")
