"""Verification of claimed C^k parameter intervals (analysis.regularity.ranges)."""

import pytest
import sympy as sp

import schemes
from analysis.regularity.ranges import verify_smoothness_interval
from analysis.regularity import smoothness
from analysis.result import AnalysisError

Q = sp.Rational


@pytest.fixture(scope="module")
def dfh():
    return schemes.get("dfh-chaikin-perturbation").symbol


def test_papers_interval_proven_by_the_exact_norm_set(dfh):
    r = verify_smoothness_interval(dfh, 2, (0, (sp.sqrt(6) - 1) / 80))
    assert (r.value, r.status, r.witness["route"]) == (True, "certified", "exact norm inequality, L = 2")


def test_wider_interval_proven_by_norm_sets_and_arb_boxes(dfh):
    r = verify_smoothness_interval(dfh, 2, (0, Q(1, 50)))
    assert r.value is True and r.status == "certified"
    assert r.witness["route"] == "exact norm sets and interval arithmetic over a subdivision"


def test_too_wide_interval_refuted_at_a_certified_point(dfh):
    r = verify_smoothness_interval(dfh, 2, (0, Q(1, 40)))
    assert r.value is False and r.status == "refuted"
    q = r.witness["counterexample"]
    assert 0 < q < Q(1, 40)
    assert smoothness(dfh.subs({"omega": q}), 2).value is False     # independent re-check


def test_interval_reaching_the_true_boundary_is_proven_and_not_overclaimed(dfh):
    """Up to 0.0214 (omega* ~ 0.021464) the exact norm sets and the Arb boxes cannot cover
    everything; the parametric norms with the invariant polytope on the strip next to omega* do.
    Past omega* the claim is refuted at a certified point beyond it."""
    r = verify_smoothness_interval(dfh, 2, (Q(1, 100), Q(214, 10000)), max_boxes=60, samples=2)
    assert r.value is True and r.status == "certified", r.witness
    assert r.witness["route"] == "parametric norm tests and invariant polytopes on sub-intervals"
    r = verify_smoothness_interval(dfh, 2, (Q(1, 100), Q(216, 10000)), max_boxes=60, samples=2)
    assert r.value is False and r.status == "refuted"
    w, q = sp.Symbol("w"), r.witness["counterexample"]
    assert (327680 * w**4 + 25600 * w**3 + 352 * w**2 + 24 * w - 1).subs(w, q) > 0     # beyond omega*


def test_bad_input(dfh):
    with pytest.raises(AnalysisError, match="empty"):
        verify_smoothness_interval(dfh, 2, (Q(1, 50), Q(1, 100)))
    with pytest.raises(AnalysisError, match="exactly one free parameter"):
        verify_smoothness_interval(schemes.get("seed004-design-control").symbol, 2, (0, 1))
