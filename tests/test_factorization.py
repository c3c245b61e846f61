"""Smoothing factors, exceptional parameter values, sum rules, reproduction, symmetry."""

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

from analysis.algebra.factorization import (factor_out, polynomial_generation, polynomial_reproduction,
                                    smoothing_factor, sum_rules, symmetry)
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol, Z

w = sp.Symbol("omega")
Q = sp.Rational
rationals = st.fractions(min_value=-5, max_value=5, max_denominator=32)


def dfh():
    return LaurentSymbol.from_mask([-5 * w, -7 * w, Q(1, 4) + 3 * w, Q(3, 4) + 9 * w, Q(3, 4) + 9 * w,
                                    Q(1, 4) + 3 * w, -7 * w, -5 * w], start=-4)


def bspline(d):
    return LaurentSymbol.from_expr(sp.expand((1 + Z) ** (d + 1) / 2 ** d))


@given(st.lists(rationals, min_size=1, max_size=6).filter(lambda m: m[0] != 0 and m[-1] != 0),
       st.integers(0, 5), st.integers(-4, 4))
@settings(max_examples=60, deadline=None)
def test_factorization_identity(core, j, start):
    """a = ((1+z)/2)^k b exactly, with k >= the number of factors put in and b(-1) != 0."""
    a = LaurentSymbol.from_mask(core, start=start) * LaurentSymbol.from_mask([1, 1]) ** j
    f = smoothing_factor(a)
    k, b = f.value, f.witness["b"]
    assert k >= j
    assert LaurentSymbol.from_mask([Q(1, 2), Q(1, 2)]) ** k * b == a
    assert b(-1) != 0


@pytest.mark.parametrize("d", range(1, 8), ids=[f"bspline-{d}" for d in range(1, 8)])
def test_bspline_smoothing_factor(d):
    f = smoothing_factor(bspline(d))
    assert f.value == d + 1 and f.witness["b"] == LaurentSymbol.from_mask([2])
    assert polynomial_generation(bspline(d)).value == d


def test_seed003_generic_and_exceptional():
    f = smoothing_factor(dfh())
    assert f.value == 3
    cases = f.witness["exceptional"]
    assert [c["condition"] for c in cases] == [{w: Q(1, 128)}]
    assert cases[0]["k"] == 5
    # and the generic factorization really holds identically in omega
    assert LaurentSymbol.from_mask([Q(1, 2), Q(1, 2)]) ** 3 * f.witness["b"] == dfh()


def test_exceptional_values_at_algebraic_points():
    # (1+z)(z - (3 - 2 sqrt 2)... ) style: b(-1) = omega^2 - 2 vanishes at +-sqrt(2)
    a = LaurentSymbol.from_mask([1, 1]) * LaurentSymbol.from_mask([w ** 2 - 1, 1])
    f = smoothing_factor(a)
    assert f.value == 1
    assert sorted((c["condition"][w] for c in f.witness["exceptional"]), key=float) == [-sp.sqrt(2), sp.sqrt(2)]
    assert all(c["k"] == 2 for c in f.witness["exceptional"])


def test_factor_out_refuses_missing_factor():
    with pytest.raises(AnalysisError, match="only 3 factor"):
        factor_out(dfh(), 4)


def test_sum_rules_conditions():
    a = LaurentSymbol.from_mask([w, 1, Q(1, 2)])
    r = sum_rules(a)
    assert r.value is False
    assert r.witness["solutions"] == [{w: Q(1, 2)}]
    assert sum_rules(dfh()).value is True


@pytest.mark.parametrize("mask,start,degree,tau", [
    ([Q(1, 2), 1, Q(1, 2)], -1, 1, 0),
    ([Q(1, 4), Q(3, 4), Q(3, 4), Q(1, 4)], -2, 1, Q(-1, 2)),
    ([Q(1, 8), Q(1, 2), Q(3, 4), Q(1, 2), Q(1, 8)], -2, 1, 0),
    ([-Q(1, 16), 0, Q(9, 16), 1, Q(9, 16), 0, -Q(1, 16)], -3, 3, 0),
], ids=["linear", "chaikin", "cubic-bspline", "four-point-1/16"])
def test_reproduction(mask, start, degree, tau):
    r = polynomial_reproduction(LaurentSymbol.from_mask(mask, start=start))
    assert (r.value, r.witness["tau"]) == (degree, tau)


def test_reproduction_exceptional_seed003():
    r = polynomial_reproduction(dfh())
    assert r.value == 1
    assert r.witness["higher"] == [{"condition": {w: Q(1, 128)}, "degree": 3}]


def test_symmetry():
    assert symmetry(dfh()).value is True
    assert symmetry(dfh()).witness == {"centre": Q(-1, 2), "kind": "dual"}
    a = LaurentSymbol.from_mask([w, 1, Q(1, 3)])
    r = symmetry(a)
    assert r.value is False and r.witness["solutions"] == [{w: Q(1, 3)}]
