"""Exact real algebraic numbers, signs and enclosures."""

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

from analysis.algebra.algebraic import IntervalSet, RealAlgebraic, enclose, sign, _q

x = sp.Symbol("x")


@pytest.mark.parametrize("expr,expected", [
    ((sp.sqrt(6) - 1) / 80 - sp.Rational(1, 50), -1),
    (sp.sqrt(2) * sp.sqrt(3) - sp.sqrt(6), 0),
    (sp.sqrt(2) + sp.sqrt(3) - sp.sqrt(5 + 2 * sp.sqrt(6)), 0),
    (sp.Rational(10**20 + 1, 10**20) - 1, 1),
    (sp.CRootOf(x**3 - 2, 0) - sp.Rational(126, 100), -1),
], ids=["dfh-vs-1/50", "sqrt-identity", "denesting", "tiny-rational", "crootof"])
def test_sign(expr, expected):
    assert sign(expr) == expected


@given(st.fractions(min_value=-10, max_value=10, max_denominator=1000))
@settings(max_examples=50, deadline=None)
def test_enclosure_contains_rational(f):
    q = sp.Rational(f.numerator, f.denominator)
    I = enclose(q * sp.sqrt(2), 60)
    lo, hi = _q(I.a), _q(I.b)
    assert lo ** 2 * (1 if lo >= 0 else -1) <= 2 * q**2 * (1 if q >= 0 else -1) <= hi ** 2 * (1 if hi >= 0 else -1)


def test_roots_are_sorted_and_compare_exactly():
    r = RealAlgebraic.roots_of(sp.Poly((x**2 - 2) * (x - 1) * (3 * x + 5), x))
    assert [e.expr for e in r] == [sp.Rational(-5, 3), -sp.sqrt(2), 1, sp.sqrt(2)]
    assert r[1].compare(RealAlgebraic.from_expr(-sp.sqrt(2))) == 0
    assert r[3].sign_of(sp.Poly(x**2 - 2, x)) == 0
    assert r[3].sign_of(sp.Poly(x - sp.Rational(141, 100), x)) == 1


def test_interval_set():
    s = IntervalSet([(None, RealAlgebraic.rational(0), False, True),
                     (RealAlgebraic.from_expr(sp.sqrt(2)), None, False, False)])
    assert str(s) == "(-oo, 0] U (sqrt(2), oo)"
    assert s.contains(0) and not s.contains(1) and s.contains(2) and not s.contains(sp.sqrt(2))
