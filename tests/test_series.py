"""Tests of analysis.levels.series: verdicts, enclosures, divergence witnesses, smoothness routes."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.levels.level_dependent import distance
from analysis.result import AnalysisError
from analysis.levels.series import smoothness, stationary_smoothness, weighted_series
from schemes import seed003
from schemes.level_dependent import get

TRIG, HYP = seed003.TRIGONOMETRIC, seed003.HYPERBOLIC
VALS = {"alpha": 1, "omega": sp.Rational(1, 100)}


@pytest.mark.parametrize("m", [0, 1], ids=["m0", "m1"])
def test_convergent_series_encloses_brute_force_partial_sum(m):
    r = weighted_series(TRIG, VALS, m, N=30)
    assert r.status == "certified" and r.witness["verdict"] == "convergent"
    brute = sum(2 ** (m * n) * distance(TRIG, n, VALS).lower for n in range(60))
    assert r.lower <= brute <= r.upper
    assert r.upper - r.lower < sp.Rational(1, 10 ** 8)


@pytest.mark.parametrize("scheme", [TRIG, HYP], ids=["trig", "hyp"])
def test_m2_series_is_divergent_with_certified_constant(scheme):
    r = weighted_series(scheme, VALS, 2)
    assert r.status == "certified" and r.witness["verdict"] == "divergent" and r.value == sp.oo
    assert r.witness["leading_constant"] == sp.Rational(3, 32)
    assert 0 < r.witness["term_lower_bound"] <= sp.Rational(3, 32)


def test_difference_scheme_series_has_constant_5_32():
    r = weighted_series(TRIG, VALS, 1, difference=1)
    assert r.witness["verdict"] == "convergent"
    assert r.witness["leading_constant"] == sp.Rational(5, 32)
    d = weighted_series(TRIG, VALS, 2, difference=1)
    assert d.witness["verdict"] == "divergent"


def test_box_statement_contains_point_values():
    box = weighted_series(TRIG, {"alpha": (sp.Rational(1, 2), 1), "omega": sp.Rational(1, 100)}, 1, pieces=4)
    assert box.witness["verdict"] == "convergent"
    for a in (sp.Rational(1, 2), sp.Rational(3, 4), 1):
        p = weighted_series(TRIG, {"alpha": a, "omega": sp.Rational(1, 100)}, 1, N=20)
        assert box.lower <= p.lower and p.upper <= box.upper


def test_theorem_1_1_direct_route_fails_for_C2_and_difference_route_works():
    direct = smoothness(TRIG, VALS, 2)
    assert direct.status == "inconclusive" and direct.witness["failed"] == ["series_m=2"]
    via = smoothness(TRIG, VALS, 2, difference=1)
    assert via.status == "certified" and via.value is True
    hyp = via.witness["hypotheses"]
    assert hyp["limit_C^1"].witness["L"] == 2 and hyp["same_support"].value is True


def test_limit_not_C2_certified_by_missing_factor():
    e = TRIG.difference(1).limit().subs({"omega": sp.Rational(1, 100)})
    r = stationary_smoothness(e, 2)
    assert r.status == "certified" and r.value is False and r.witness["smoothing_factor"] == 2


def test_exponential_chaikin_is_C1_by_theorem():
    r = smoothness(get("exp-chaikin-hyp"), {"t": 1}, 1)
    assert r.status == "certified"


def test_two_boxes_accepted():
    # issue 13 item 5: two boxed parameters are split on the product grid (formerly an error)
    r = weighted_series(TRIG, {"alpha": (1, 2), "omega": (0, 1)}, 0, pieces=2)
    assert r.status == "certified" and r.witness["sub_boxes"] == 4


@pytest.mark.parametrize("values, kw, message", [
    ({"alpha": (1, 0), "omega": sp.Rational(1, 100)}, {}, "empty parameter box"),
    ({"alpha": (1, 1), "omega": sp.Rational(1, 100)}, {}, "empty parameter box"),
    ({"alpha": -1, "omega": sp.Rational(1, 100)}, {}, "outside the declared domain"),
    ({"alpha": (-1, 1), "omega": sp.Rational(1, 100)}, {}, "outside the declared domain"),
    ({"alpha": 1, "omega": sp.Rational(1, 100)}, {"pieces": 0}, "pieces must be an integer >= 1"),
    ({"alpha": 1, "omega": sp.Rational(1, 100)}, {"difference": -1}, "difference must be a non-negative"),
], ids=["reversed-box", "degenerate-box", "negative-positive-symbol", "box-below-0", "pieces-0", "difference-neg"])
def test_bad_values_rejected(values, kw, message):
    with pytest.raises(AnalysisError, match=message):
        weighted_series(TRIG, values, 1, **kw)


def test_smoothness_rejects_negative_difference():
    with pytest.raises(AnalysisError, match="difference must be"):
        smoothness(TRIG, VALS, 2, difference=-1)


def test_box_touching_the_closure_of_a_positive_domain_is_accepted_and_sum_is_nonnegative():
    r = weighted_series(TRIG, {"alpha": (0, sp.Rational(1, 10)), "omega": sp.Rational(1, 100)}, 1)
    assert r.status == "certified" and r.witness["verdict"] == "convergent"
    # the sum of norms is >= 0: the lower bound is clipped at 0, and the terms vanish at alpha = 0
    assert r.lower == 0 and 0 < r.upper < 1


def test_disjoint_enclosures_are_a_certification_bug(monkeypatch):
    """Direct and Taylor-model enclosures that do not overlap must not be silently ignored."""
    import flint

    from analysis.levels import series

    real = series.coefficient_differences
    monkeypatch.setattr(series, "coefficient_differences",
                        lambda s, n, env, **kw: [d + flint.arb(10) for d in real(s, n, env, **kw)])
    with pytest.raises(RuntimeError, match="certification bug"):
        weighted_series(TRIG, VALS, 1, N=30)
