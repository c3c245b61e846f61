"""Hölder exponents, C^k verdicts, Sobolev exponents and C^k parameter ranges (issue 3)."""

import pytest
import sympy as sp

import schemes
from analysis.algebra.algebraic import RealAlgebraic
from analysis.regularity import ck_parameter_set, holder_exponent, smoothness, sobolev_exponent
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol

Q = sp.Rational


@pytest.mark.parametrize("d", range(1, 8), ids=[f"bspline-{d}" for d in range(1, 8)])
def test_bspline_alpha_is_degree_attained(d):
    h = holder_exponent(schemes.get(f"bspline-{d}").symbol)
    assert (h.value, h.status) == (d, "certified")
    assert smoothness(schemes.get(f"bspline-{d}").symbol, d - 1).value is True
    assert smoothness(schemes.get(f"bspline-{d}").symbol, d).value is False


def test_four_point_alpha_two_exactly():
    h = holder_exponent(schemes.get("four-point").symbol_at(w=Q(1, 16)))
    assert h.value == 2 and h.status == "certified"


@pytest.mark.parametrize("shift,reverse", [(0, True), (3, False), (-2, True)], ids=["reversed", "shift3", "both"])
def test_alpha_invariant_under_shift_and_reversal(shift, reverse):
    a = schemes.get("dfh-chaikin-perturbation").symbol_at(omega=Q(1, 50))
    b = a.shift(shift)
    if reverse:
        b = b.reversed()
    ha, hb = holder_exponent(a), holder_exponent(b)
    assert ha.status == hb.status == "certified"
    assert ha.lower <= ha.upper and hb.lower <= hb.upper
    assert ha.lower <= hb.upper and hb.lower <= ha.upper      # the enclosures overlap
    assert float(ha.upper - ha.lower) < 1e-8


def test_borderline_decided_exactly():
    """Chaikin: rho = 1 exactly, so alpha = 2 and the scheme is not C^2 (decided without floats)."""
    r = smoothness(schemes.get("chaikin").symbol, 2)
    assert r.value is False and r.status == "certified"


@pytest.mark.parametrize("d", [1, 2, 3, 4], ids=lambda d: f"bspline-{d}")
def test_sobolev_bspline(d):
    r = sobolev_exponent(schemes.get(f"bspline-{d}").symbol)
    assert r.lower <= d + Q(1, 2) <= r.upper and r.upper - r.lower < Q(1, 10**20)


def test_sobolev_exceeds_holder_for_four_point():
    """s_2 >= alpha always (Sobolev embedding in 1-D: alpha >= s_2 - 1/2)."""
    a = schemes.get("four-point").symbol_at(w=Q(1, 16))
    s2 = sobolev_exponent(a)
    assert Q(2) <= s2.lower and s2.upper <= Q(5, 2)


def test_seed003_true_c2_range():
    """The paper's (0, (sqrt6-1)/80) is only sufficient: the true C^2 set is (0, omega*), omega* ~ 0.021464."""
    a = schemes.get("dfh-chaikin-perturbation").symbol
    r = ck_parameter_set(a, 2, within=(Q(-1, 20), Q(1, 20)), grid=10)
    # boundaries certified on both sides; the interior near omega* is beyond the norm tests but
    # closed by the parametric invariant polytope (issue 14, analysis.regularity.strips)
    assert r.witness["boundaries_certified"] and r.status == "certified"
    assert r.value[0]["interior"]["proven"] is True
    assert "invariant polytope" in r.value[0]["interior"]["route"]
    (run,) = r.value
    left, right = run["left"], run["right"]
    assert left["exact"] == 0
    star = RealAlgebraic.from_expr(right["exact"])
    x = sp.Symbol("x")
    assert star.sign_of(sp.Poly(327680 * x**4 + 25600 * x**3 + 352 * x**2 + 24 * x - 1, x)) == 0
    assert star.compare(RealAlgebraic.from_expr((sp.sqrt(6) - 1) / 80)) > 0
    # certified points within 1e-8 on both sides of each boundary
    for b in (left, right):
        c, n = b["certified_C^j_at"], b["certified_not_C^j_at"]
        assert abs(float(c) - float(n)) < 1e-8
        assert smoothness(a.subs({"omega": c}), 2).value is True


def test_range_needs_one_parameter():
    with pytest.raises(AnalysisError, match="several free parameters"):
        ck_parameter_set(schemes.get("seed004-design-control").symbol, 1)


def test_non_convergent_mask_rejected():
    with pytest.raises(AnalysisError, match="sum rules"):
        holder_exponent(LaurentSymbol.from_mask([1, 2, 3]))


def test_four_point_c1_range():
    """C^1 exactly for 0 < w < w*, w* the real root of 32 w^3 + 4 w - 1 (~0.19273; Hechler-Mößner-Reif 2009)."""
    r = ck_parameter_set(schemes.get("four-point").symbol, 1, within=(Q(-1, 8), Q(1, 4)), grid=12)
    assert r.witness["boundaries_certified"]
    assert all(b["status"] == "certified" for b in r.witness["boundaries"])
    (run,) = r.value
    assert run["left"]["exact"] == 0
    x = sp.Symbol("x")
    star = RealAlgebraic.from_expr(run["right"]["exact"])
    assert star.sign_of(sp.Poly(32 * x**3 + 4 * x - 1, x)) == 0
    assert abs(float(star) - 0.19272924926) < 1e-10


def test_not_ck_between_counterexamples_is_proven_and_never_over_a_ck_point():
    """The complement of the C^1 set of the 4-point scheme in [0, 1/4] is proven not C^1 on the whole
    stretch [w*, 1/4] (an exact sign of a determinant), and the same proof refuses a stretch that contains
    C^1 points (1/8 is C^1: it lies in (0, w*))."""
    from analysis.regularity.crossings import _prove_not_cj

    a = schemes.get("four-point").symbol
    r = ck_parameter_set(a, 1, within=(0, Q(1, 4)), grid=8)
    assert r.status == "certified"
    stretch = [s for s in r.witness["not_Cj"] if s["from"] != s["to"]]
    assert len(stretch) == 1 and stretch[0]["proven"] and stretch[0]["to"] == Q(1, 4)
    assert abs(float(stretch[0]["from"]) - 0.1927292493) < 1e-9
    w = r.witness["parameter"]
    assert _prove_not_cj(a, sp.Symbol(w), 1, Q(1, 8), Q(1, 4), []) is None
    assert _prove_not_cj(a, sp.Symbol(w), 1, Q(1, 5), Q(1, 4), []) is not None


def test_a_stretch_through_a_point_where_the_support_shrinks_needs_the_point_verdict():
    """At w = 0 the four-point scheme's c has a smaller support (its end coefficients are -2w): a generic
    eigenvalue proves nothing there, so [-1/8, 0] is proven not C^1 only with the scheme's verdict at 0."""
    from analysis.regularity.crossings import _prove_not_cj, _support_shrinks

    a = schemes.get("four-point").symbol
    w = a.params[0]
    assert [P.as_expr() for P in _support_shrinks(a, w)] == [-2 * w, -2 * w]
    assert _prove_not_cj(a, w, 1, Q(-1, 8), 0, []) is None
    assert _prove_not_cj(a, w, 1, Q(-1, 8), 0, [], point_verdict=lambda q: smoothness(a.subs({w: q}), 1).value) \
        is not None
