"""Laurent symbols: construction, round trips, algebra, printing, bad input."""

from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol, Z, parse_coefficient

w, mu = sp.symbols("omega mu")
Q = sp.Rational

rationals = st.fractions(min_value=-5, max_value=5, max_denominator=64)
masks = st.lists(rationals, min_size=1, max_size=9).filter(lambda m: m[0] != 0 and m[-1] != 0)
starts = st.integers(min_value=-6, max_value=6)

DFH_EVEN = [-7 * w, Q(3, 4) + 9 * w, Q(1, 4) + 3 * w, -5 * w]
DFH_ODD = [-5 * w, Q(1, 4) + 3 * w, Q(3, 4) + 9 * w, -7 * w]


def test_seed003_rules_give_the_mask_in_our_convention():
    a = LaurentSymbol.from_rules(DFH_EVEN, DFH_ODD, first=-1)
    assert a.start == -4 and a.end == 3
    assert a.mask == (-5 * w, -7 * w, Q(1, 4) + 3 * w, Q(3, 4) + 9 * w, Q(3, 4) + 9 * w,
                      Q(1, 4) + 3 * w, -7 * w, -5 * w)
    assert str(a.domain) == "QQ[omega]"
    r = a.rules()
    assert (list(r.even), r.even_first, list(r.odd), r.odd_first) == (DFH_EVEN, -1, DFH_ODD, -1)


@pytest.mark.parametrize("text,expected", [
    ("1/4", Q(1, 4)), ("0.25", Q(1, 4)), ("3/4+9*omega", Q(3, 4) + 9 * w),
    ("(sqrt(6)-1)/80", (sp.sqrt(6) - 1) / 80), (Fraction(1, 3), Q(1, 3)), (0.5, Q(1, 2)), (3, 3),
], ids=["fraction", "decimal-exact", "parameter", "algebraic", "Fraction", "float-exact", "int"])
def test_parse_coefficient(text, expected):
    assert parse_coefficient(text) == expected


@pytest.mark.parametrize("coeffs,domain", [
    (["1/4", "3/4", "3/4", "1/4"], "QQ"),
    (["(sqrt(6)-1)/80", "1"], "QQ<sqrt(6)>"),
    (["omega", "1-omega"], "QQ[omega]"),
    (["mu*sqrt(6)", "1"], "QQ<sqrt(6)>[mu]"),
    (["1/(1+omega)", "1"], "QQ(omega)"),
], ids=["rational", "algebraic", "parametric", "algebraic-parametric", "rational-function"])
def test_domain_is_shown_in_repr(coeffs, domain):
    a = LaurentSymbol.from_mask(coeffs)
    assert str(a.domain) == domain
    assert f"domain={domain}" in repr(a)


@pytest.mark.parametrize("mask,message", [
    ([], "empty"),
    (["1/4", "abc("], "cannot read"),
    (["sin(1)", "1"], "not an exact algebraic number"),
    (["1/4", "nan"], "not a finite number"),
    (["1/0", "1"], "not a finite number"),
    (["sin(omega)", "1"], "not a rational function"),
    ([None, 1], "not a number"),
], ids=["empty", "syntax", "transcendental", "nan", "division-by-zero", "function-of-parameter", "none"])
def test_bad_masks(mask, message):
    with pytest.raises(AnalysisError, match=message):
        LaurentSymbol.from_mask(mask)


def test_unknown_parameter_in_subs():
    a = LaurentSymbol.from_mask(["omega", "1-omega"])
    with pytest.raises(AnalysisError, match="unknown parameter 'nu'"):
        a.subs({"nu": 1})


@given(masks, starts)
@settings(max_examples=60, deadline=None)
def test_round_trips(mask, start):
    a = LaurentSymbol.from_mask(mask, start=start)
    assert a.mask == tuple(Q(f.numerator, f.denominator) for f in mask)
    assert LaurentSymbol.from_mask(a.mask, start=a.start) == a
    assert LaurentSymbol.from_expr(a.expr()) == a
    r = a.rules()
    assert LaurentSymbol.from_rules(r.even, r.odd, even_first=r.even_first, odd_first=r.odd_first) == a
    e, o = a.subsymbols()
    assert e.upsample(2) + o.upsample(2).shift(1) == a
    assert a.reversed().reversed() == a


@given(masks, starts, masks, starts)
@settings(max_examples=40, deadline=None)
def test_product_is_polynomial_product(m1, s1, m2, s2):
    a, b = LaurentSymbol.from_mask(m1, start=s1), LaurentSymbol.from_mask(m2, start=s2)
    assert sp.expand((a * b).expr() - a.expr() * b.expr()) == 0
    assert (a * b).start == a.start + b.start
    assert (a + b).expr() - (a.expr() + b.expr()) == 0


def test_shift_reverse_upsample():
    a = LaurentSymbol.from_mask([1, 2, 3], start=-1)
    assert a.shift(2).start == 1
    assert a.reversed() == LaurentSymbol.from_mask([3, 2, 1], start=-1)
    assert a.upsample(2) == LaurentSymbol.from_mask([1, 0, 2, 0, 3], start=-2)
    assert a.reversed().expr() == sp.expand(a.expr().subs(Z, 1 / Z))


def test_evaluation_and_subs_with_algebraic_value():
    a = LaurentSymbol.from_rules(DFH_EVEN, DFH_ODD, first=-1)
    assert (a(1), a(-1)) == (2, 0)
    b = a.subs({"omega": "(sqrt(6)-1)/80"})
    assert str(b.domain) == "QQ<sqrt(6)>"
    assert b(1) == 2 and b(-1) == 0


def test_printing():
    a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
    assert a.pretty() == "1/4*z^(-2) + 3/4*z^(-1) + 3/4 + 1/4*z"
    assert a.latex() == r"\frac{1}{4} z^{-2} + \frac{3}{4} z^{-1} + \frac{3}{4} + \frac{1}{4} z"
    assert str(a.rules()) == "f[2i]   = 3/4 f[i] + 1/4 f[i+1]\nf[2i+1] = 1/4 f[i] + 3/4 f[i+1]"


def test_from_expr_rejects_non_laurent():
    with pytest.raises(AnalysisError, match="Laurent polynomial"):
        LaurentSymbol.from_expr("1/(1+z)")
