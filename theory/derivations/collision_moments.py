#!/usr/bin/env python3
"""Exact (symbolic) values of every collision integral the C++ quadrature of molchaos::theory
evaluates numerically: the moments mu_p (p = 2, 4, 6) term by term in a2, a3 and b, the contact
averages over colliding pairs, and the coefficients built from them. Run at build time: it prints
the results and writes the C++ header that the tests and `molchaos theory` read.

Definition (paper Eq. (20), generalised to d dimensions and moment p):
  mu_p = -1/2 int dc1 dc2 de Theta(-c12.e) |c12.e| f1 f2 [1 + b (k (c1.e)(c2.e) - c1.c2)]
         Delta(c1^p + c2^p)
with f = phi(c)(1 + a2 S2(c^2) + a3 S3(c^2)), phi = pi^{-d/2} exp(-c^2), S2, S3 the
d-dimensional Sonine polynomials, k the dyad factor (3 as printed; d for a traceless dyad).

Reduction used here (exact, different from the C++ one): e = x by rotational invariance (factor
|S^{d-1}|). The Maxwellians factorise per particle and per component; only the normal components
are coupled, through the collision cut. With C = (c1x + c2x)/2 and u = c2x - c1x > 0 (the approach
speed), e^{-c1x^2 - c2x^2} = e^{-2C^2 - u^2/2}. The transverse parts y1, y2 (dimension m = d - 1)
enter only through P = |y1|^2, Q = |y2|^2, R = y1.y2, whose Gaussian averages are
  <P^a Q^b R^c> = <|y|^{2a+c}> <|y|^{2b+c}> <cos^c theta>_m   (c even; zero for c odd),
  <|y|^{2k}> = Gamma(k + m/2)/Gamma(m/2), <cos^c> = 1 (m = 1), (c-1)!!/c!! (m = 2).
The collision sends c1x -> C + eps u/2, c2x -> C - eps u/2. What remains are the moments
int dC C^{2a} e^{-2C^2} = sqrt(pi/2) (2a-1)!!/4^a and int_0^inf du u^{2j+1} e^{-u^2/2} = 2^j j!,
so every integral is sqrt(2 pi) times a polynomial in eps with rational coefficients.

Usage: collision_moments.py [--header PATH]
"""
import argparse
import os
import sys
from functools import lru_cache

import sympy as sp
from sympy.polys.domains import QQ
from sympy.polys.rings import ring

R_, Cx, U, P, Q, Rt, EPS = ring("C,u,P,Q,R,eps", QQ)
EPS_SYMBOL = sp.Symbol("epsilon")
TERMS = [("1", 0, 0, 0), ("a2", 1, 0, 0), ("a2^2", 2, 0, 0), ("b", 0, 0, 1), ("a2*b", 1, 0, 1),
         ("a2^2*b", 2, 0, 1), ("a3", 0, 1, 0), ("a2*a3", 1, 1, 0), ("a3^2", 0, 2, 0),
         ("a3*b", 0, 1, 1), ("a2*a3*b", 1, 1, 1), ("a3^2*b", 0, 2, 1)]


def double_factorial(n):
    return sp.factorial2(n) if n > 0 else 1


@lru_cache(maxsize=None)
def radial_moment(m, k):
    """<|y|^{2k}> for an m-dimensional Gaussian with weight pi^{-m/2} e^{-y^2}."""
    return sp.gamma(sp.Rational(2 * k + m, 2)) / sp.gamma(sp.Rational(m, 2))


@lru_cache(maxsize=None)
def transverse_moment(m, a, b, c):
    if c % 2:
        return sp.Integer(0)
    # <|y1|^{2a+c}> <|y2|^{2b+c}> <cos^c>: the direction of y2 is independent of both lengths.
    angle = 1 if m == 1 else sp.Rational(double_factorial(c - 1), double_factorial(c))
    return sp.nsimplify(radial_moment(m, a + sp.Rational(c, 2)) *
                        radial_moment(m, b + sp.Rational(c, 2)) * angle)


@lru_cache(maxsize=None)
def normal_moment(a, j):
    """C^a u^j with weight e^{-2C^2} u e^{-u^2/2}, divided by sqrt(pi/2); zero unless both even."""
    if a % 2 or j % 2:
        return None if (a % 2 == 0 and j % 2) else sp.Integer(0)
    return sp.Rational(double_factorial(a - 1), 4 ** (a // 2)) * 2 ** (j // 2) * sp.factorial(j // 2)


def integrate(poly, d):
    """The integral of poly (in C, u, P, Q, R, eps) over all colliding pairs, divided by
    sqrt(2 pi): a polynomial in eps (dict power -> rational). Includes |S^{d-1}| / pi."""
    m = d - 1
    out = {}
    odd_u = {}
    for (a, j, pa, qb, rc, k), coef in poly.items():
        if a % 2:
            continue
        t = transverse_moment(m, pa, qb, rc)
        if t == 0:
            continue
        c = sp.Rational(int(coef.numerator), int(coef.denominator)) * t
        w = normal_moment(a, j)
        if w is None:  # an odd power of u: these must cancel (the integrand is even in u)
            key = (j, k)
            odd_u[key] = odd_u.get(key, 0) + c * normal_moment(a, 0)
            continue
        out[k] = out.get(k, 0) + c * w
    assert all(v == 0 for v in odd_u.values()), "odd powers of the approach speed did not cancel"
    # |S^{d-1}| pi^{-1} sqrt(pi/2) / sqrt(2 pi) = 1 (d = 2), 2 (d = 3).
    sphere = {2: 1, 3: 2}[d]
    return {k: sphere * v for k, v in out.items() if v != 0}


def to_expr(poly_eps):
    return sum((v * EPS_SYMBOL ** k for k, v in poly_eps.items()), sp.Integer(0))


def sonine(d, x):
    s2 = x ** 2 / 2 - QQ(d + 2, 2) * x + QQ(d * (d + 2), 8)
    s3 = (-x ** 3 / 6 + QQ(d + 4, 4) * x ** 2 - QQ((d + 2) * (d + 4), 8) * x +
          QQ(d * (d + 2) * (d + 4), 48))
    return s2, s3


def pieces(d):
    c1sq = (Cx - U / 2) ** 2 + P
    c2sq = (Cx + U / 2) ** 2 + Q
    normal = Cx ** 2 - U ** 2 / 4          # (c1.e)(c2.e)
    dot = normal + Rt                      # c1.c2
    s21, s31 = sonine(d, c1sq)
    s22, s32 = sonine(d, c2sq)
    weights = {"1": R_(1), "a2": s21 + s22, "a2^2": s21 * s22, "a3": s31 + s32,
               "a2*a3": s21 * s32 + s31 * s22, "a3^2": s31 * s32}
    c1sq_after = (Cx + EPS * U / 2) ** 2 + P
    c2sq_after = (Cx - EPS * U / 2) ** 2 + Q
    delta = {p: c1sq_after ** (p // 2) + c2sq_after ** (p // 2) - c1sq ** (p // 2) - c2sq ** (p // 2)
             for p in (2, 4, 6)}
    return weights, normal, dot, delta


def term_integrals(d, observable, dyad):
    """{term name: eps-polynomial} of int W_T X over colliding pairs (X includes -1/2 for mu_p)."""
    weights, normal, dot, _ = pieces(d)
    out = {}
    d_b = dyad * normal - dot
    for name, i2, i3, ib in TERMS:
        base = weights[{(0, 0): "1", (1, 0): "a2", (2, 0): "a2^2", (0, 1): "a3", (1, 1): "a2*a3",
                        (0, 2): "a3^2"}[(i2, i3)]]
        w = base * d_b if ib else base
        out[name] = integrate(w * observable, d)
    return out


def rational_function(num, den):
    return sp.factor(sp.cancel(to_expr(num) / to_expr(den)))


def cxx_number(x):
    x = sp.Rational(x)
    return f"{x.p}.0 / {x.q}.0" if x.q != 1 else f"{x.p}.0"


def text(expr):
    return str(expr).replace("epsilon", "ε").replace("**", "^").replace("*", "·")


def moment_tables():
    rows = []
    for d in (2, 3):
        _, _, _, delta = pieces(d)
        for p in (2, 4, 6):
            for dyad in sorted({3, d}):
                ints = term_integrals(d, delta[p] * QQ(-1, 2), dyad)
                base = ints["1"]
                for name, i2, i3, ib in TERMS:
                    value = ints[name]
                    coefficient = rational_function(value, base) if name != "1" else sp.Integer(1)
                    rows.append(dict(d=d, p=p, dyad=dyad, term=name, poly=value,
                                     integral=sp.factor(to_expr(value)), coefficient=coefficient))
    return rows


def expansion_first_order(ints):
    """<X> = N/D to first order in a2 and b (with the a2*b cross term): value, d/da2, d/db,
    d2/da2db, from the term integrals N (observable X) and D (observable 1)."""
    N, D = ints
    n = {k: sp.Rational(to_expr(v)) if v else sp.Integer(0) for k, v in N.items()}
    dd = {k: sp.Rational(to_expr(v)) if v else sp.Integer(0) for k, v in D.items()}
    x0 = n["1"] / dd["1"]
    xa = (n["a2"] - x0 * dd["a2"]) / dd["1"]
    xb = (n["b"] - x0 * dd["b"]) / dd["1"]
    xab = (n["a2*b"] - x0 * dd["a2*b"] - xa * dd["b"] - xb * dd["a2"]) / dd["1"]
    return [x0, xa, xb, xab]


def contact_tables():
    """Contact averages over colliding pairs with f2 = f f [1 + b D]: for each dyad the expansion
    of <(c1.e)(c2.e)>, <c1.c2>, <D>, omega/omega_Enskog and <(g.e)^2>/<(g.e)^2>_chaos."""
    rows = []
    for d in (2, 3):
        _, normal, dot, _ = pieces(d)
        for dyad in sorted({3, d}):
            one = term_integrals(d, R_(1), dyad)
            nrm = term_integrals(d, normal, dyad)
            dt = term_integrals(d, dot, dyad)
            dy = term_integrals(d, dyad * normal - dot, dyad)
            gn2 = term_integrals(d, U ** 2, dyad)
            j1 = sp.Rational(to_expr(one["1"]))
            g0 = expansion_first_order((gn2, one))[0]
            omega = [sp.Rational(to_expr(one[k])) / j1 if one[k] else 0
                     for k in ("1", "a2", "b", "a2*b")]
            diss = [x / g0 for x in expansion_first_order((gn2, one))]
            rows.append(dict(d=d, dyad=dyad, name="normal_product",
                             c=expansion_first_order((nrm, one))))
            rows.append(dict(d=d, dyad=dyad, name="velocity_product",
                             c=expansion_first_order((dt, one))))
            rows.append(dict(d=d, dyad=dyad, name="dyad", c=expansion_first_order((dy, one))))
            rows.append(dict(d=d, dyad=dyad, name="collision_frequency_ratio", c=omega))
            rows.append(dict(d=d, dyad=dyad, name="dissipation_ratio", c=diss))
            rows.append(dict(d=d, dyad=dyad, name="collision_integral_J1",
                             c=[j1, 0, 0, 0]))
    return rows


def check_closed_forms(moments, contacts):
    """Facts derived by hand in doc/theory.md; a failure stops the build."""
    get = {(r["d"], r["p"], r["dyad"], r["term"]): r for r in moments}
    e = EPS_SYMBOL
    assert sp.simplify(get[(2, 2, 3, "1")]["integral"] - (1 - e ** 2) / 2) == 0
    assert sp.simplify(get[(3, 2, 3, "1")]["integral"] - (1 - e ** 2)) == 0
    for d in (2, 3):
        assert get[(d, 2, 3, "a2")]["coefficient"] == sp.Rational(3, 16)
        assert get[(d, 2, 3, "b")]["coefficient"] == sp.Rational(-3, 2)
    for r in contacts:
        if r["name"] in ("normal_product", "velocity_product"):
            assert r["c"][0] == sp.Rational(-1, 4), r
        if r["name"] == "dyad" and r["dyad"] == 3:
            assert r["c"][0] == sp.Rational(-1, 2), r
    # <c^6> over phi (1 + a2 S2 + a3 S3) = d(d+2)(d+4)/8 (1 + 3 a2 - a3): the HCS moment relation.
    x = sp.Symbol("x", positive=True)
    for d in (2, 3):
        s2 = x ** 2 / 2 - sp.Rational(d + 2, 2) * x + sp.Rational(d * (d + 2), 8)
        s3 = (-x ** 3 / 6 + sp.Rational(d + 4, 4) * x ** 2 - sp.Rational((d + 2) * (d + 4), 8) * x
              + sp.Rational(d * (d + 2) * (d + 4), 48))
        avg = lambda g: sp.integrate(x ** sp.Rational(d - 2, 2) * sp.exp(-x) * g, (x, 0, sp.oo)) \
            / sp.gamma(sp.Rational(d, 2))
        c6 = sp.Rational(d * (d + 2) * (d + 4), 8)
        assert sp.simplify(avg(x ** 3 * s2) - 3 * c6) == 0
        assert sp.simplify(avg(x ** 3 * s3) + c6) == 0
        assert sp.simplify(avg(x ** 2 * s2) - sp.Rational(d * (d + 2), 4)) == 0
        assert sp.simplify(avg(x ** 2 * s3)) == 0


def header(moments, contacts):
    out = ["// Generated by theory/derivations/collision_moments.py at build time: the exact values",
           "// of the collision integrals, derived symbolically (sympy) by a route independent of",
           "// the quadrature. Do not edit.",
           "#pragma once", "", "#include <array>", "", "namespace molchaos::theory::exact {", "",
           "/// One term a2^i a3^j b^k of μ_p: integral = √(2π) Σ_k eps_polynomial[k] ε^k; the",
           "/// coefficient is integral / integral of term \"1\" (a rational function of ε).",
           "struct MomentTerm {", "  int dimension;", "  int moment;", "  int dyad_factor;",
           "  const char* term;", "  std::array<double, 7> eps_polynomial;",
           "  const char* integral_text;", "  const char* coefficient_text;", "};", "",
           "inline constexpr MomentTerm k_moment_terms[] = {"]
    for r in moments:
        coeffs = [cxx_number(r["poly"].get(k, 0)) for k in range(7)]
        out.append(f'    {{{r["d"]}, {r["p"]}, {r["dyad"]}, "{r["term"]}", {{{", ".join(coeffs)}}},'
                   f' "√(2π)·({text(r["integral"])})", "{text(r["coefficient"])}"}},')
    out += ["};", "",
            "/// A contact average over colliding pairs with f2 = f f [1 + b D], to first order in",
            "/// a2 and b: value + d_a2·a2 + d_b·b + d_a2b·a2·b (c = v/√(2T)).",
            "struct ContactTerm {", "  int dimension;", "  int dyad_factor;", "  const char* quantity;",
            "  std::array<double, 4> coefficients;  // value, d_a2, d_b, d_a2b",
            "  std::array<const char*, 4> texts;", "};", "",
            "inline constexpr ContactTerm k_contact_terms[] = {"]
    for r in contacts:
        nums = ", ".join(cxx_number(x) for x in r["c"])
        texts = ", ".join(f'"{text(sp.nsimplify(x))}"' for x in r["c"])
        out.append(f'    {{{r["d"]}, {r["dyad"]}, "{r["name"]}", {{{nums}}}, {{{texts}}}}},')
    out += ["};", "", "}  // namespace molchaos::theory::exact", ""]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--header", help="write the C++ header here")
    parser.add_argument("--listing", help="write the printed results here instead of stdout")
    args = parser.parse_args()
    lines = []
    print_line = lines.append
    moments = moment_tables()
    contacts = contact_tables()
    check_closed_forms(moments, contacts)
    for r in moments:
        if r["term"] == "1":
            print_line(f'd={r["d"]} p={r["p"]} dyad={r["dyad"]}: '
                       f'mu_p(0,0) = sqrt(2 pi) ({r["integral"]})')
        else:
            print_line(f'    {r["term"]:9s} {r["coefficient"]}')
    for r in contacts:
        print_line(f'contact d={r["d"]} dyad={r["dyad"]} {r["name"]}: value {r["c"][0]}, '
              f'a2 {r["c"][1]}, b {r["c"][2]}, a2*b {r["c"][3]}')
    if args.listing:
        write_atomically(args.listing, "\n".join(lines) + "\n")
    else:
        print("\n".join(lines))
    if args.header:
        write_atomically(args.header, header(moments, contacts))
    return 0


def write_atomically(path, content):
    """Nothing half-written: write beside the target, then rename over it."""
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(content)
    os.replace(path + ".tmp", path)


if __name__ == "__main__":
    sys.exit(main())
