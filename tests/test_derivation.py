"""analysis.algebra.linear_forms: linear forms, ghost points, garbled readings (exact identities)."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, strategies as st

from analysis.algebra.linear_forms import (LinearForm, N_SYM, displacement_construction, end_rules,
                                 ghost_substitute, read_garbled_linear)

mu, nu = sp.symbols("mu nu")
G = {"μ": mu, "ν": nu}


@pytest.mark.parametrize("text, plus, minus", [
    ("7ω", None, None),
    ("42+42μ14ν", 42 + 42 * mu - 14 * nu, -42 + 42 * mu - 14 * nu),
    ("7μ+21ν7", 7 * mu + 21 * nu - 7, -7 * mu + 21 * nu - 7),
], ids=["unknown-symbol", "lost-minus", "leading-sign"])
def test_read_garbled_linear(text, plus, minus):
    if plus is None:
        with pytest.raises(ValueError):
            read_garbled_linear(text, G)
        return
    assert read_garbled_linear(text, G) == (sp.expand(plus), sp.expand(minus))


@given(st.lists(st.fractions(), min_size=1, max_size=6), st.integers(-3, 3))
def test_shift_and_rebase_round_trip(coeffs, s):
    f = LinearForm({k: sp.Rational(c.numerator, c.denominator) for k, c in enumerate(coeffs)})
    assert f.shift(s).shift(-s) == f
    assert f.total() == f.shift(s).total()


def test_reflection_reproduces_linear_data():
    """Ghost points by point reflection keep the end rules affine: coefficients sum to 1, and
    linear data P_j = j is mapped to the refined linear data for a scheme that reproduces lines."""
    h = sp.Rational(1, 2)
    even = LinearForm({-1: sp.Rational(1, 8), 0: sp.Rational(3, 4), 1: sp.Rational(1, 8)})   # cubic B-spline
    odd = LinearForm({0: h, 1: h})
    rules = end_rules(even, odd, left_ghosts=(1,), right_ghosts=(1,), left_i=(0,), right_i=(0,))
    for lab, f in rules.items():
        assert f.total() == 1, lab
    assert rules["P0"].items() == [(0, 1)]              # the end point is interpolated
    assert rules["P2n"].base == N_SYM


def test_ghost_substitute_keeps_other_points():
    f = LinearForm({-1: 1, 0: 1, 2: 5}, base=0)
    g = ghost_substitute(f, {-1: LinearForm({0: 2, 1: -1}, base=0)})
    assert g.items() == [(0, 3), (1, -1), (2, 5)]


def test_displacement_construction_with_zero_weights_is_q():
    Q = LinearForm({0: sp.Rational(3, 4), 1: sp.Rational(1, 4)})
    R = LinearForm({0: 1})
    out = displacement_construction(Q, Q, R, R, {0: 0}, {0: 0})
    assert out["P_{2i}"] == Q and out["DE"].items() == []
