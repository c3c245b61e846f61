"""Tests of analysis.levels.bounds on seed 003's lemmas and identities (verdicts computed, not typed in)."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.levels.bounds import check_identity, check_inequality
from analysis.levels.level_dependent import N
from analysis.claims.kinds import KIND_CLASSES, SchemeSpec
from schemes import seed003 as S
from schemes.seed003 import OMEGA as W

T = S      # the lemma tables of Sect. 3.3 (schemes.seed003, read by `subdiv bound --claim`)
_z = sp.Symbol("z")


def lemma_3_3_e(coeffs):
    """Lemma 3.3's e^n(z) as printed (transcribed here independently of paper.toml)."""
    b0, b1, b2, b3 = coeffs
    z = _z
    return 2 * (b3 * z ** -4 + (b0 - b3) * z ** -3 - (b0 - b2 - b3) * z ** -2
                + (b0 - b2 + b1 - b3) * z ** -1 + (-b0 + b3 + b2) + (b0 - b3) * z + b3 * z ** 2)


#: Lemma 3.4's d(z) as printed
LEMMA_3_4_D = 2 * (5 * W * _z ** -4 + 2 * W * _z ** -3 - (1 + 20 * W) / 4 * _z ** -2
                   + (-1 - 8 * W) / 2 * _z ** -1 + (-1 - 20 * W) / 4 + 2 * W * _z + 5 * W * _z ** 2)

BOX = {"alpha": ("1/100", "pi/3"), "omega": "1/100"}


def _box_for(lhs, rhs):
    names = {s.name for s in (sp.sympify(lhs).free_symbols | sp.sympify(rhs).free_symbols)}
    return {k: v for k, v in BOX.items() if k in names}


@pytest.mark.parametrize("cid", list(T.LEMMA_3_1), ids=list(T.LEMMA_3_1))
def test_lemma_3_1_items(cid):
    lhs, rhs, strict = T.LEMMA_3_1[cid]
    r = check_inequality(lhs, rhs, 1, _box_for(lhs, rhs), strict=strict, claim=cid)
    # (iii) upper and (vii) lower use c and c' the wrong way round: false for every alpha > 0
    expected = "refuted" if cid in ("003:Lemma3.1(iii)-upper", "003:Lemma3.1(vii)-lower") else "certified"
    assert r.status == expected, r.witness
    if expected == "refuted":
        assert r.witness["counterexample"]["n"] >= 1


@pytest.mark.parametrize("cid", list(T.LEMMA_3_1_CORRECTED), ids=list(T.LEMMA_3_1_CORRECTED))
def test_lemma_3_1_corrected(cid):
    lhs, rhs, strict = T.LEMMA_3_1_CORRECTED[cid]
    assert check_inequality(lhs, rhs, 1, _box_for(lhs, rhs), strict=strict).status == "certified"


@pytest.mark.parametrize("cid", ["003:Lemma3.2(ii)", "003:Lemma3.2(vi)"], ids=["ii", "vi"])
def test_lemma_3_2(cid):
    lhs, rhs, strict = T.LEMMA_3_2[cid]
    assert check_inequality(lhs, rhs, 0, _box_for(lhs, rhs), strict=strict).status == "certified"


def test_too_small_constant_is_refuted():
    """C = 7 alpha^2/128 * 0.9 is below the sharp asymptotic constant: refuted at some level."""
    lhs = sp.Abs(S.BETA[1] - sp.Rational(3, 4) - 9 * S.OMEGA)
    rhs = sp.Rational(9, 10) * sp.Rational(7, 128) * S.ALPHA ** 2 / 4 ** N
    r = check_inequality(lhs, rhs, 0, {"alpha": 1, "omega": "1/100"})
    assert r.status == "refuted"


@pytest.mark.parametrize("form, total", [(S.TRIGONOMETRIC, S.BETA_SUM), (S.HYPERBOLIC, S.GAMMA_SUM)],
                         ids=["beta-sum", "gamma-sum"])
def test_normalization_sums_are_proven(form, total):
    assert check_identity(form.stencil_sum(), total).status == "certified"


@pytest.mark.parametrize("coeffs, form", [(S.BETA, S.TRIGONOMETRIC), (S.GAMMA, S.HYPERBOLIC)],
                         ids=["lemma-3.3", "corollary-3.1"])
def test_lemma_3_3_factorization_proven(coeffs, form):
    z = sp.Symbol("z")
    e = lemma_3_3_e(coeffs)
    assert check_identity(form.symbol_expr(), (1 + z) / 2 * e).status == "certified"


def test_lemma_3_4_d_is_refuted_and_minus_d_is_the_limit():
    z = sp.Symbol("z")
    e = S.TRIGONOMETRIC.difference(1).limit().expr()
    assert check_identity(LEMMA_3_4_D, e).status == "refuted"
    assert check_identity(LEMMA_3_4_D, -e).status == "certified"
    assert LEMMA_3_4_D.subs(z, 1) == -2


def test_negative_first_level_rejected():
    from analysis.result import AnalysisError

    with pytest.raises(AnalysisError, match="n0 must be a non-negative"):
        check_inequality(sp.Rational(3, 4), S.BETA[1], -1, {"alpha": 1, "omega": "1/100"})


def test_identity_items_refute_only_with_a_certified_value():
    """Lemma 3.1/3.2 definition items (kind identity): a wrong identity is refuted with a ball-certified
    nonzero value."""
    form2 = {"form2": SchemeSpec("form2", None, level=S.TRIGONOMETRIC)}
    run = lambda rhs: KIND_CLASSES["identity"]({"scheme": "form2", "where": {"beta_0": "a(2)"},  # noqa: E731
                                                "lhs": "beta_0", "rhs": rhs}, form2, "t").evaluate()
    assert run("-7*omega").status == "certified"
    bad = run("-5*omega")
    assert bad.status == "refuted"
    r = bad.evidence[0].result
    assert r.status == "refuted" and r.provenance["method"] == "acb ball evaluation at a rational point"
    # independent: the difference -2 omega at the reported point is nonzero
    w = r.witness["point"]["omega"]
    assert -2 * w != 0
