"""Tests of analysis.levels.level_dependent: limits, exact asymptotics, cancellation-safe norms, Taylor models."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from analysis.levels.level_dependent import H, LevelDependentScheme, distance, leading_asymptotics, to_h, workprec
from analysis.levels.taylor_model import taylor_models
from analysis.result import AnalysisError
from schemes import seed003
from schemes.level_dependent import get

TRIG, HYP = seed003.TRIGONOMETRIC, seed003.HYPERBOLIC
VALS = {"alpha": 1, "omega": sp.Rational(1, 100)}


@pytest.mark.parametrize("scheme", [TRIG, HYP, seed003.TRIGONOMETRIC_NORMALIZED],
                         ids=["trig-2", "hyp-3", "trig-normalized-4"])
def test_limit_of_seed003_forms_is_rule_1(scheme):
    from schemes import get as get_stationary

    assert scheme.limit() == get_stationary("dfh-chaikin-perturbation").symbol


@pytest.mark.parametrize("slug, limit", [("exp-chaikin-trig", "chaikin"), ("exp-cubic-hyp", "bspline-3")],
                         ids=["chaikin", "cubic"])
def test_exponential_bspline_limits(slug, limit):
    import schemes

    a = get(slug).limit()
    b = schemes.get(limit).symbol
    assert a.mask == b.mask


@pytest.mark.parametrize("scheme", [TRIG, HYP], ids=["trig", "hyp"])
def test_leading_asymptotics_seed003(scheme):
    r = leading_asymptotics(scheme)
    assert r.witness["order"] == 2
    assert sp.simplify(r.value - 3 * seed003.ALPHA ** 2 / 32) == 0
    coeffs = r.witness["leading_coefficients"]
    sign = 1 if scheme is TRIG else -1
    assert sp.simplify(coeffs[0] - sign * sp.Rational(7, 128) * seed003.ALPHA ** 2) == 0   # beta_1
    assert sp.simplify(coeffs[-2] - sign * sp.Rational(5, 128) * seed003.ALPHA ** 2) == 0  # beta_2


@pytest.mark.parametrize("n", [30, 100, 200], ids=["n30", "n100", "n200"])
def test_arb_enclosure_matches_asymptotics_at_large_n(n):
    """Regression for catastrophic cancellation: 4^n ||S_{a^n} - S_a|| -> 3/32 (alpha = 1)."""
    r = distance(TRIG, n, VALS)
    lo, hi = float(r.lower * 4 ** n), float(r.upper * 4 ** n)
    assert r.status == "certified"
    assert lo <= hi and abs(lo - 3 / 32) < 4.0 ** (-n) * 0.1 + 1e-15
    assert (r.upper - r.lower) / r.lower < sp.Rational(1, 10 ** 15)


def test_float64_is_wrong_and_ours_is_not():
    n = 40
    exact = distance(TRIG, n, VALS)
    f = distance(TRIG, n, VALS, arithmetic="float").value
    mp = distance(TRIG, n, VALS, arithmetic="mp").value
    assert exact.lower <= sp.Float(mp, 30) <= exact.upper
    # float64: sin(3x/4)/sin(x) - 3/4 at x = 2^-40 is lost entirely, the true value is ~7.8e-26
    assert not (float(exact.lower) <= f <= float(exact.upper))
    assert abs(f - float(exact.lower)) > 0.5 * float(exact.lower)   # float64 returns 0.0 here


def test_difference_scheme_matches_hand_division():
    e = TRIG.difference(1)
    w = seed003.OMEGA
    lim = e.limit()
    assert lim.start == -4
    assert lim.mask == tuple(sp.expand(2 * c) for c in (-5 * w, -2 * w, sp.Rational(1, 4) + 5 * w,
                                                          sp.Rational(1, 2) + 4 * w, sp.Rational(1, 4) + 5 * w,
                                                          -2 * w, -5 * w))


def test_taylor_model_encloses_values():
    models = taylor_models(TRIG, {"alpha": (sp.Rational(1, 2), 1), "omega": sp.Rational(1, 100)})
    import flint

    for n in (3, 10):
        for alpha in (sp.Rational(1, 2), sp.Rational(3, 4), 1):
            d = distance(TRIG, n, {"alpha": alpha, "omega": sp.Rational(1, 100)})
            with workprec(128):
                h = flint.arb(2) ** (-n)
                enc = [m.enclose(h) for m in models]
            # even residues: beta_1 and beta_2 differences
            tot = sum(abs(float(enc[k].mid())) + float(enc[k].rad()) for k in range(0, 8, 2))
            assert float(d.lower) <= tot + 1e-30


def test_to_h_rejects_other_level_dependence():
    with pytest.raises(AnalysisError, match="2\\^n"):
        to_h(sp.Symbol("n") ** 2)


def test_stationary_scheme_has_no_order():
    s = LevelDependentScheme((sp.Rational(1, 2), 1, sp.Rational(1, 2)), -1)
    with pytest.raises(AnalysisError, match="stationary"):
        s.order()


def test_bad_arithmetic_is_one_line_error():
    with pytest.raises(AnalysisError, match="unknown arithmetic"):
        distance(TRIG, 1, VALS, arithmetic="double")
