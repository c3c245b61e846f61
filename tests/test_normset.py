"""The exact one-parameter norm sets (acceptance figures of issue 2)."""

import functools

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

from analysis.stationary.difference import difference_norm
from analysis.stationary.normset import norm_function, norm_solution_set
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol

Q = sp.Rational
w, nu = sp.symbols("omega nu")


def dfh():
    return LaurentSymbol.from_mask([-5 * w, -7 * w, Q(1, 4) + 3 * w, Q(3, 4) + 9 * w, Q(3, 4) + 9 * w,
                                    Q(1, 4) + 3 * w, -7 * w, -5 * w], start=-4)


def t_nu():
    c = [(-5 + 7 * nu) / 128, (-7 + 21 * nu) / 128, (35 + 7 * nu) / 128, (105 - 35 * nu) / 128]
    return LaurentSymbol.from_mask(c + c[::-1], start=-4)


def test_seed003_acceptance_L2_is_exactly_the_papers_interval():
    r = norm_solution_set(dfh(), m=3, L=2, within=(0, sp.oo))
    assert r.status == "certified"
    (lo, hi, lc, hc), = r.value.parts
    assert lo.expr == 0 and not lc and not hc
    assert sp.simplify(hi.expr - (sp.sqrt(6) - 1) / 80) == 0


def test_seed003_L1_gives_nothing_and_L3_more():
    assert norm_solution_set(dfh(), m=3, L=1, within=(0, sp.oo)).value.is_empty
    r3 = norm_solution_set(dfh(), m=3, L=3, within=(0, sp.oo)).value
    (lo, hi, _, _), = r3.parts
    assert lo.expr == 0 and hi.compare(RealAlgebraicOf((sp.sqrt(6) - 1) / 80)) > 0


def RealAlgebraicOf(x):
    from analysis.algebra.algebraic import RealAlgebraic
    return RealAlgebraic.from_expr(x)


@pytest.mark.parametrize("m,lo,hi", [(1, -1, Q(25, 7)), (2, -1, Q(25, 7)), (3, Q(1, 7), Q(17, 7))],
                         ids=["m1", "m2", "m3"])
def test_seed004_t_nu_L1_sets(m, lo, hi):
    """The exact sets, cross-checked below point by point against the direct exact norm."""
    (a, b, _, _), = norm_solution_set(t_nu(), m=m, L=1).value.parts
    assert (a.expr, b.expr) == (lo, hi)


@functools.lru_cache(maxsize=None)
def _dfh_set_m3_L2():
    """The exact set, computed once for all examples below (each example checks one point of it)."""
    return norm_solution_set(dfh(), m=3, L=2).value


@functools.lru_cache(maxsize=None)
def _t_nu_pieces(m: int, L: int):
    """The exact piecewise norm, computed once per (m, L) for all examples below."""
    return norm_function(t_nu(), m, L).value


@given(st.fractions(min_value=-1, max_value=Q(1, 20), max_denominator=2000))
@settings(max_examples=40, deadline=None)
def test_set_membership_agrees_with_direct_norm_seed003(omega):
    s = _dfh_set_m3_L2()
    direct = difference_norm(dfh().subs({"omega": omega}), 3, 2).value
    assert s.contains(Q(omega.numerator, omega.denominator)) == (direct < 1)


@given(st.fractions(min_value=-3, max_value=6, max_denominator=500), st.integers(1, 3), st.integers(1, 2))
@settings(max_examples=40, deadline=None)
def test_piecewise_norm_agrees_with_direct_norm(v, m, L):
    q = Q(v.numerator, v.denominator)
    pieces = _t_nu_pieces(m, L)
    direct = difference_norm(t_nu().subs({"nu": q}), m, L).value
    from analysis.algebra.algebraic import RealAlgebraic
    x = RealAlgebraic.rational(q)
    for p in pieces:
        inside = (p.lo is None or p.lo.compare(x) <= 0) and (p.hi is None or p.hi.compare(x) >= 0)
        if inside:
            assert max(poly.eval(q) for poly in p.polys) == direct


def test_errors():
    mixed = LaurentSymbol.from_mask([w, nu, 1 - w - nu])
    with pytest.raises(AnalysisError, match="several free parameters"):
        norm_solution_set(mixed, 0, 1)
    with pytest.raises(AnalysisError, match="unknown parameter"):
        norm_solution_set(dfh(), 3, 1, "mu")
    with pytest.raises(AnalysisError, match="no free parameter"):
        norm_solution_set(dfh().subs({"omega": 0}), 3, 1)
