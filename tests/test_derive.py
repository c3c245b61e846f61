"""Issue 14: masks derived from requirements, constructions, and the smoothest member.

Every expected mask is computed independently of :mod:`analysis.algebra.derive` (Lagrange
interpolation in sympy, the pseudo-spline formula, binomials) or quoted from the literature.
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.algebra.constructions import averaging, convex_combination, displacement_symbol, dual, pseudo_spline
from analysis.algebra.derive import InconsistentRequirements, derive_mask, max_sum_rules
from analysis.algebra.linear_forms import LinearForm
from analysis.algebra.symbol import LaurentSymbol
from analysis.result import AnalysisError
from tests.cli_run import run_cli

R = sp.Rational


def lagrange_weights(nodes, x):
    """Lagrange basis values at ``x`` for ``nodes`` (independent of the derivation)."""
    X = sp.Symbol("X")
    return [sp.interpolating_poly(len(nodes), X, nodes, [1 if j == i else 0 for j in range(len(nodes))]).subs(X, x)
            for i in range(len(nodes))]


def dd_mask(n):
    """Dubuc–Deslauriers 2n-point: a_{1-2p} = L_p(1/2) on nodes p = -n+1..n (Deslauriers–Dubuc 1989)."""
    nodes = list(range(-n + 1, n + 1))
    w = lagrange_weights(nodes, R(1, 2))
    a = {0: 1}
    for p, v in zip(nodes, w):
        a[1 - 2 * p] = v
    lo, hi = min(a), max(a)
    return tuple(sp.sympify(a.get(i, 0)) for i in range(lo, hi + 1)), lo


@pytest.mark.parametrize("n", [2, 3, 4], ids=["4pt", "6pt", "8pt"])
def test_dubuc_deslauriers(n):
    r = derive_mask(support=4 * n - 1, interpolatory=True, symmetric="primal", reproduction=2 * n - 1)
    mask, lo = dd_mask(n)
    assert r.witness["dimension"] == 0 and r.status == "certified"
    assert r.value.mask == mask and r.value.start == lo


def test_dd_published_values():
    # Deslauriers–Dubuc 1989: 4-point (-1, 0, 9, 16, 9, 0, -1)/16; 6-point (3, 0, -25, 0, 150, 256, ...)/256
    assert derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=5).value.mask == tuple(
        R(x, 256) for x in (3, 0, -25, 0, 150, 256, 150, 0, -25, 0, 3))


def test_four_point_tension_family():
    r = derive_mask(support=7, interpolatory=True, symmetric="primal", reproduction=1, names=["m"])
    w = sp.Symbol("w")
    expected = [-w, 0, R(1, 2) + w, 1, R(1, 2) + w, 0, -w]   # Dyn–Levin–Gregory 1987
    got = r.value.subs({"m": -w})
    assert r.witness["dimension"] == 1 and got.mask == tuple(sp.expand(e) for e in expected)


@pytest.mark.parametrize("n", [1, 2, 3], ids=["2pt", "4pt", "6pt"])
def test_dual_2n_point(n):
    # dual 2n-point (Dyn–Floater–Hormann 2005): even/odd rules are Lagrange values at 1/4 and 3/4
    r = derive_mask(support=4 * n, symmetric="dual", reproduction=2 * n - 1)
    nodes = list(range(-n + 1, n + 1))
    w1, w3 = lagrange_weights(nodes, R(1, 4)), lagrange_weights(nodes, R(3, 4))
    a = {}
    for p, u, v in zip(nodes, w1, w3):   # tau = -1/2: f[2i] at u = 1/4, f[2i+1] at u = 3/4 (node p at u = p)
        a[-2 * p] = u
        a[1 - 2 * p] = v
    lo = min(a)
    expected = tuple(sp.sympify(a.get(i, 0)) for i in range(lo, max(a) + 1))
    assert r.witness["dimension"] == 0
    assert r.value.mask == expected


@pytest.mark.parametrize("n", [3, 4, 5, 8], ids=lambda n: f"n{n}")
def test_bspline_most_sum_rules(n):
    r = max_sum_rules(support=n)
    assert r.witness["order"] == n - 1 and r.witness["dimension"] == 0
    assert r.value.mask == tuple(R(sp.binomial(n - 1, i), 2 ** (n - 2)) for i in range(n))


@pytest.mark.parametrize("m,l", [(2, 1), (3, 2), (4, 3), (2, 0), (3, 1)])
def test_pseudo_splines(m, l):
    a = pseudo_spline(m, l)
    z = sp.Symbol("z")
    # the constructive formula's defining properties: a(1) = 2, 2m sum rules, support 2(m+l)+1
    assert a(1) == 2 and len(a.mask) == 2 * (m + l) + 1
    q, rem = sp.div(sp.expand(a.expr() * z ** (m + l)), (1 + z) ** (2 * m), z)
    assert rem == 0
    if l == m - 1:       # (m, m-1) is Dubuc–Deslauriers 2m-point (Dong–Shen 2007)
        assert a.mask == dd_mask(m)[0]
    if l == 0:           # (m, 0) is the B-spline of order 2m
        assert a.mask == tuple(R(sp.binomial(2 * m, i), 2 ** (2 * m - 1)) for i in range(2 * m + 1))
    else:                # the derived family with 2m sum rules on the same support contains it
        fam = derive_mask(support=2 * (m + l) + 1, symmetric="primal", sum_rules=2 * m)
        sol = sp.solve([sp.expand(x - y) for x, y in zip(fam.value.mask, a.mask)], list(fam.value.params), dict=True)
        assert sol


def test_ternary_four_point_family():
    r = derive_mask(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=2)
    assert r.witness["dimension"] == 1
    r3 = derive_mask(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=3)
    w13, w23 = lagrange_weights([-1, 0, 1, 2], R(1, 3)), lagrange_weights([-1, 0, 1, 2], R(2, 3))
    # f[3i+1] = sum_p w13_p f[i+p] -> a_{1-3p}; f[3i+2] -> a_{2-3p}
    a = {0: 1, 3: 0, -3: 0}
    for p, u, v in zip([-1, 0, 1, 2], w13, w23):
        a[1 - 3 * p], a[2 - 3 * p] = u, v
    assert r3.value.mask == tuple(sp.sympify(a.get(i, 0)) for i in range(-5, 6))
    # the cubic member lies in the quadratic family
    t = r.value.params[0]
    assert r.value.subs({t: r3.value.mask[0]}).mask == r3.value.mask


def test_exponential_reproduction_four_point():
    # independent: the 4-point midpoint rule applied to cos(theta x) on the integers, theta = pi/2
    r = derive_mask(support=7, interpolatory=True, symmetric="primal", reproduction=0, exponentials=["I*pi/2", "-I*pi/2"])
    th = sp.pi / 2
    w = (1 - sp.cos(th / 2)) / (2 * sp.cos(th / 2) - 2 * sp.cos(3 * th / 2))
    assert sp.simplify(r.value.mask[0] + w) == 0
    re = derive_mask(support=7, interpolatory=True, symmetric="primal", reproduction=0, exponentials=["1", "-1"])
    wc = (1 - sp.cosh(R(1, 2))) / (2 * sp.cosh(R(1, 2)) - 2 * sp.cosh(R(3, 2)))
    assert re.value is None and abs(sp.N(re.witness["coefficients"][0] + wc, 30)) < 1e-25


def test_conflict_is_irreducible():
    with pytest.raises(InconsistentRequirements) as e:
        derive_mask(support=7, interpolatory=True, symmetric="primal", reproduction=3, fixed={"a-3": "1/10"})
    conflict = e.value.conflict
    assert conflict == ("reproduction of degree 3 (tau = 0)", "fixed a-3 = 1/10")
    # irreducible: each member alone is satisfiable; together they are not (a-3 = -1/16 is forced:
    # cubic reproduction on 7 coefficients is the Dubuc–Deslauriers scheme)
    assert derive_mask(support=7, reproduction=3).value.mask[0] == R(-1, 16)
    assert derive_mask(support=7, fixed={"a-3": "1/10"}).witness["dimension"] == 6


def test_bad_input():
    with pytest.raises(AnalysisError):
        derive_mask(support=4, symmetric="primal")
    with pytest.raises(AnalysisError):
        derive_mask(support=7, fixed={"a9": 1})
    with pytest.raises(AnalysisError):
        derive_mask(support=7, interpolatory=True, names=["x", "y"])
    with pytest.raises(AnalysisError):
        derive_mask(arity=1, support=3)
    with pytest.raises(AnalysisError):
        derive_mask(support=1000)


def test_constructions():
    hat = LaurentSymbol.from_mask([R(1, 2), 1, R(1, 2)], start=-1)
    assert averaging(hat, 2).mask == tuple(R(sp.binomial(4, i), 8) for i in range(5))   # cubic B-spline
    assert dual(dual(hat)) == averaging(hat, 2)
    dd4 = LaurentSymbol.from_mask(dd_mask(2)[0], start=-3)
    assert convex_combination(hat, dd4, R(1, 2)).mask == tuple(R(x, 32) for x in (-1, 0, 17, 32, 17, 0, -1))
    # seed 004's construction with mu = nu = omega = 0 is Q itself
    Q0 = LinearForm({-1: R(-7, 128), 0: R(105, 128), 1: R(35, 128), 2: R(-5, 128)})
    Q1 = LinearForm({-1: R(-5, 128), 0: R(35, 128), 1: R(105, 128), 2: R(-7, 128)})
    Rr = LinearForm({0: 1})
    assert displacement_symbol(Q0, Q1, Rr, Rr, {0: 0}, {0: 0}) == LaurentSymbol.from_rules(
        [R(-7, 128), R(105, 128), R(35, 128), R(-5, 128)], [R(-5, 128), R(35, 128), R(105, 128), R(-7, 128)], first=-1)


def test_cli_derive_json_and_error(capfd):
    out = run_cli(capfd, "derive", "--support", "7", "--interpolatory", "--symmetric", "primal", "--reproduce", "1",
                  "--json")
    d = json.loads(out.stdout)
    assert d["dimension"] == 1 and d["mask"] == "t1,0,1/2 - t1,1,1/2 - t1,0,t1"
    bad = run_cli(capfd, "derive", "--support", "5", "--interpolatory", "--sum-rules", "3")
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "interpolatory; sum rules of order 3" in bad.stderr
