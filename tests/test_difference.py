"""Difference schemes and exact L-step norms."""

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

from analysis.stationary.difference import difference_norm, difference_symbol, iterated_symbol, scheme_norm
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol

Q = sp.Rational
w = sp.Symbol("omega")
rationals = st.fractions(min_value=-3, max_value=3, max_denominator=32)
masks = st.lists(rationals, min_size=1, max_size=8).filter(lambda m: m[0] != 0 and m[-1] != 0)


def dfh():
    return LaurentSymbol.from_mask([-5 * w, -7 * w, Q(1, 4) + 3 * w, Q(3, 4) + 9 * w, Q(3, 4) + 9 * w,
                                    Q(1, 4) + 3 * w, -7 * w, -5 * w], start=-4)


def brute_norm(a: LaurentSymbol, L: int, scale=1) -> sp.Expr:
    """Independent reference: the L-step symbol in sympy and residue sums by hand."""
    prod = iterated_symbol(a, L)
    sums = {}
    for i, c in prod.items():
        sums[i % 2 ** L] = sums.get(i % 2 ** L, 0) + abs(c)
    return max(sums.values()) * sp.Rational(scale) ** L


@given(masks, st.integers(-5, 5), st.integers(1, 4))
@settings(max_examples=40, deadline=None)
def test_flint_norm_equals_reference(mask, start, L):
    a = LaurentSymbol.from_mask(mask, start=start)
    assert scheme_norm(a, L).value == brute_norm(a, L)


@given(masks, st.integers(-5, 5), st.integers(1, 5))
@settings(max_examples=40, deadline=None)
def test_norm_submultiplicative(mask, start, L):
    """||S^{L+1}|| <= ||S^L|| * ||S||, exactly."""
    a = LaurentSymbol.from_mask(mask, start=start)
    assert scheme_norm(a, L + 1).value <= scheme_norm(a, L).value * scheme_norm(a, 1).value


@given(masks, st.integers(-5, 5), st.integers(1, 3))
@settings(max_examples=30, deadline=None)
def test_norm_shift_and_reversal_invariant(mask, start, L):
    a = LaurentSymbol.from_mask(mask, start=start)
    n = scheme_norm(a, L).value
    assert scheme_norm(a.shift(3), L).value == n
    assert scheme_norm(a.reversed(), L).value == n


def test_spellings_differ_by_a_shift_only():
    a = dfh().subs({"omega": Q(1, 100)})
    for m in (1, 2, 3):
        assert difference_symbol(a, m, spelling="paper") == difference_symbol(a, m, spelling="divided").shift(m)
        assert difference_norm(a, m, 2, spelling="paper").value == difference_norm(a, m, 2, spelling="divided").value


@pytest.mark.parametrize("omega,L,expected", [
    (Q(1, 100), 1, Q(29, 25)), (Q(1, 100), 2, Q(551, 625)), (Q(1, 50), 2, Q(731, 625)),
], ids=["1/100-L1", "1/100-L2", "1/50-L2"])
def test_seed003_norms_rational(omega, L, expected):
    """Values recomputed independently by brute_norm (no typed-in verdict)."""
    a = dfh().subs({"omega": omega})
    r = difference_norm(a, 3, L)
    assert r.value == expected == brute_norm(difference_symbol(a, 3), L, Q(1, 2))
    assert r.witness["contractive"] == (expected < 1)


def test_seed003_norm_at_algebraic_endpoint_is_exactly_one():
    a = dfh().subs({"omega": "(sqrt(6)-1)/80"})
    r = difference_norm(a, 3, 2)
    assert sp.simplify(r.value - 1) == 0
    assert r.witness["contractive"] is False
    r3 = difference_norm(a, 3, 3)
    assert sp.simplify(r3.value - (Q(-639, 500) + 227 * sp.sqrt(6) / 250)) == 0
    assert r3.witness["contractive"] is True


def test_bspline_norms():
    cubic = LaurentSymbol.from_mask([Q(1, 8), Q(1, 2), Q(3, 4), Q(1, 2), Q(1, 8)], start=-2)
    assert scheme_norm(cubic).value == 1
    # the 4th difference scheme of the cubic B-spline is 2 * identity-like: 1/2 S has norm 1
    assert difference_norm(cubic, 3, 1).value == Q(1, 2)


@pytest.mark.parametrize("call,message", [
    (lambda: difference_symbol(dfh(), 4), "only 3 factor"),
    (lambda: difference_norm(dfh(), 3, 2), "needs values for the parameter"),
    (lambda: scheme_norm(LaurentSymbol.from_mask([1, 1]), 0), "positive integer"),
    (lambda: difference_symbol(dfh(), 1, spelling="x"), "unknown spelling"),
], ids=["missing-factor", "free-parameter", "L-zero", "spelling"])
def test_bad_input(call, message):
    with pytest.raises(AnalysisError, match=message):
        call()
