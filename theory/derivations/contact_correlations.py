#!/usr/bin/env python3
"""Exact (symbolic) collision averages at contact with the two-particle distribution
  f2(c1, c2; e) = f(c1) f(c2) g2 [1 + b_par (c1.e)(c2.e) + b_perp (c1.c2 - (c1.e)(c2.e))]
and f = phi(c)(1 + a2 S2(c^2)): the molecular-chaos values (b_par = b_perp = 0) to first order in
a2, and the derivatives with respect to the two amplitudes at a2 = 0. The paper's ansatz
b (k (c1.e)(c2.e) - c1.c2) is b_par = (k - 1) b, b_perp = -b (k = 3 printed, k = d traceless).
These are the closed forms of validation/src/contact_ansatz.cpp; not part of the build.
molecular_chaos_sonine(d) gives the molecular-chaos values in full, for the product
f(c1) f(c2) with f = phi(c)(1 + a2 S2(c^2) + a3 S3(c^2)): rational in (a2, a3), the same for
d = 2 and 3 (validation's molecular_chaos_contact_sonine).

Averages are over colliding pairs (weight Theta(-c12.e)|c12.e|), c = v/sqrt(2T), e along x,
c1 = C + g/2, c2 = C - g/2, u = -g.e > 0. Quantities:
  P = (c1.e)(c2.e),  Q = c1.c2,  W = omega/omega_Enskog (the normalisation itself),
  Y = (g.e)^2/2 = (v12.e)^2/(4T)  (energy loss per collision over its molecular-chaos value).
Under Gaussian weights every monomial's average is a product of one-dimensional moments:
C_i ~ exp(-2 C_i^2), g_perp ~ exp(-g^2/2), u ~ u exp(-u^2/2) on u > 0.
Usage: python3 contact_correlations.py
"""
import sympy as sp


def gaussian_moment(n, variance):
    return 0 if n % 2 else sp.factorial2(n - 1) * variance ** sp.Rational(n, 2)


def flux_moment(n):  # E[u^n] for the density u exp(-u^2/2), u > 0
    return 2 ** sp.Rational(n, 2) * sp.gamma(sp.Rational(n, 2) + 1)


def expectation(expr, C, h, u):
    poly = sp.Poly(sp.expand(expr), *C, *h, u)
    total = 0
    for powers, coeff in poly.terms():
        term = coeff
        for k in powers[: len(C)]:
            term *= gaussian_moment(k, sp.Rational(1, 4))
        for k in powers[len(C): len(C) + len(h)]:
            term *= gaussian_moment(k, 1)
        term *= flux_moment(powers[-1])
        total += term
    return sp.nsimplify(total)


def square(v):
    return sum(x * x for x in v)


def sonine_s2(d, x):
    return x**2 / 2 - sp.Rational(d + 2, 2) * x + sp.Rational(d * (d + 2), 8)


def sonine_s3(d, x):
    return (-x**3 / 6 + sp.Rational(d + 4, 4) * x**2 - sp.Rational((d + 2) * (d + 4), 8) * x
            + sp.Rational(d * (d + 2) * (d + 4), 48))


class ContactPair:
    """A colliding pair in d dimensions: C (centre of mass), h (g transverse to e), u = -g.e > 0,
    c1 = C + g/2, c2 = C - g/2 with e along x, and the quantities P, Q, Y averaged at contact."""

    def __init__(self, d):
        self.u = sp.symbols("u", positive=True)
        self.C = sp.symbols(f"C1:{d + 1}", real=True)
        self.h = sp.symbols(f"h1:{d}", real=True)
        g = [-self.u] + list(self.h)
        self.c1 = [self.C[i] + g[i] / 2 for i in range(d)]
        self.c2 = [self.C[i] - g[i] / 2 for i in range(d)]
        self.P = self.c1[0] * self.c2[0]
        self.Q = sum(self.c1[i] * self.c2[i] for i in range(d))
        self.Y = self.u * self.u / 2

    def expectation(self, expr):
        return expectation(expr, self.C, self.h, self.u)


def contact_table(d):
    a2, bp, bt = sp.symbols("a2 b_par b_perp")
    pair = ContactPair(d)
    P, Q = pair.P, pair.Q
    weight = ((1 + a2 * (sonine_s2(d, square(pair.c1)) + sonine_s2(d, square(pair.c2))))
              * (1 + bp * P + bt * (Q - P)))
    norm = pair.expectation(weight)
    rows = {name: pair.expectation(X * weight) / norm
            for name, X in (("P", P), ("Q", Q), ("Y", pair.Y))}
    rows["W"] = norm

    def first_order(f):
        f0 = f.subs({a2: 0, bp: 0, bt: 0})
        return (sp.nsimplify(f0),
                sp.nsimplify(sp.diff(f, a2).subs({a2: 0, bp: 0, bt: 0})),
                sp.nsimplify(sp.diff(f, bp).subs({a2: 0, bp: 0, bt: 0})),
                sp.nsimplify(sp.diff(f, bt).subs({a2: 0, bp: 0, bt: 0})))

    return {k: first_order(v) for k, v in rows.items()}


def molecular_chaos_sonine(d):
    """P, Q, W, Y under molecular chaos with f = phi (1 + a2 S2 + a3 S3), all orders."""
    a2, a3 = sp.symbols("a2 a3")
    pair = ContactPair(d)
    f = lambda c: 1 + a2 * sonine_s2(d, square(c)) + a3 * sonine_s3(d, square(c))
    weight = f(pair.c1) * f(pair.c2)
    norm = pair.expectation(weight)
    rows = {"W": sp.factor(norm)}
    for name, X in (("P", pair.P), ("Q", pair.Q), ("Y", pair.Y)):
        rows[name] = sp.factor(pair.expectation(X * weight) / norm)
    return rows


if __name__ == "__main__":
    for d in (2, 3):
        print(f"d = {d}: quantity: value at a2 = b = 0, d/da2, d/db_par, d/db_perp")
        t = contact_table(d)
        for name, (v, da2, dpar, dperp) in t.items():
            print(f"  {name}: {v}, {da2}, {dpar}, {dperp}")
        for k in (3, d):
            # paper's dyad: b_par = (k - 1) b, b_perp = -b
            slopes = {n: sp.nsimplify((k - 1) * r[2] - r[3]) for n, r in t.items()}
            print(f"  dyad factor {k}: d/db of P, Q, W, Y =", slopes["P"], slopes["Q"],
                  slopes["W"], slopes["Y"], " d ln(W Y)/db =", slopes["W"] + slopes["Y"])
    for d in (2, 3):
        print(f"d = {d}: molecular chaos with a2, a3 in full, and to second order")
        for name, v in molecular_chaos_sonine(d).items():
            a2, a3 = sp.symbols("a2 a3")
            series = sp.series(sp.series(v, a2, 0, 3).removeO(), a3, 0, 2).removeO()
            print(f"  {name} = {v}\n      = {sp.expand(series)} + ...")
