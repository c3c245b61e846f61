"""Seed 003's proof-check claims: verdicts computed by the engine agree with independent
recomputations of the key facts, and with the reviewed golden file (reports/verdicts.json)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from analysis.claims import compare_verdicts, evaluate_claim, verdicts_json
from schemes import seed003 as S

PAPER = S.PAPER
REPORTS = Path(__file__).resolve().parents[1] / "reports"
Z, W = sp.Symbol("z"), S.OMEGA


@pytest.fixture(scope="module")
def evaluated():
    """Every claim of paper 003, evaluated once (about 55 s)."""
    return {c.id: evaluate_claim(c) for c in PAPER.claims}


def test_every_claim_evaluates_without_error(evaluated):
    errors = {cid: ev.error for cid, ev in evaluated.items() if ev.error}
    assert not errors
    assert all(ev.verdict.status != "inconclusive" for ev in evaluated.values())


def test_matches_golden_file(evaluated):
    """`subdiv check 003` on fresh verdicts: statuses and key numbers as reviewed."""
    golden = json.loads((REPORTS / "verdicts.json").read_text(encoding="utf-8"))
    fresh = verdicts_json({"003": list(evaluated.values())})
    assert compare_verdicts(golden, fresh, papers_=["003"]) == []


def test_l2_norm_set_is_exactly_the_printed_interval(evaluated):
    """Independent: ||(1/2 S_(a_3))^2|| at the printed endpoint is exactly 1, and < 1 just inside."""
    from analysis.difference import difference_norm

    a = S._stationary()
    end = (sp.sqrt(6) - 1) / 80
    assert sp.simplify(difference_norm(a.subs({W: end}), 3, 2).value - 1) == 0
    assert difference_norm(a.subs({W: sp.Rational(18, 1000)}), 3, 2).value < 1
    v = evaluated["003:Sec2(C2)"].verdict
    nums = {n.name: n for n in v.numbers}
    assert v.status == "certified" and sp.simplify(nums["L2_right_end"].value - end) == 0
    assert abs(nums["true_right_end"].float - 0.0214640075) < 1e-9


def test_true_c2_end_is_root_of_quartic(evaluated):
    x = sp.Symbol("x")
    star = {n.name: n for n in evaluated["003:Sec2(C2)"].verdict.numbers}["true_right_end"].float
    assert abs(327680 * star**4 + 25600 * star**3 + 352 * star**2 + 24 * star - 1) < 1e-12
    assert star > float((sp.sqrt(6) - 1) / 80)
    assert sp.Poly(327680 * x**4 + 25600 * x**3 + 352 * x**2 + 24 * x - 1, x).count_roots(0, sp.Rational(1, 40)) == 1


def test_lemma_3_4_d_of_one_is_minus_two(evaluated):
    """Independent: the printed d(1) = -2, while e = 2a/(1+z) has e(1) = a(1) = 2; d = -e exactly."""
    assert S.LEMMA_3_4_D.subs(Z, 1) == -2
    a = S._stationary().expr()
    e = sp.cancel(2 * a / (1 + Z))
    assert sp.simplify(e.subs(Z, 1)) == 2
    assert sp.simplify(S.LEMMA_3_4_D + e) == 0
    assert evaluated["003:Lemma3.4(d)"].verdict.status == "refuted"
    assert evaluated["003:Lemma3.4"].verdict.status == "refuted"


def test_chaikin_at_omega_zero(evaluated):
    import schemes

    assert S._stationary().subs({W: 0}) == schemes.get("chaikin").symbol
    assert evaluated["003:Sec2(omega=0)"].verdict.status == "certified"


@pytest.mark.parametrize("item, status", [("ii", "certified"), ("iii", "refuted"), ("vi", "certified"),
                                          ("vii", "refuted")])
def test_lemma_3_1_swapped_cos_cosh(evaluated, item, status):
    """Independent point check: beta_2 >= 1/4 + 3w > 1/(4 cosh x) + 3w, so (iii) as printed fails."""
    x = sp.pi / 12
    b2 = sp.sin(x / 4) / sp.sin(x)
    assert float(b2) > 0.25 > float(1 / (4 * sp.cosh(x)))
    assert evaluated[f"003:Lemma3.1({item})"].verdict.status == status


def test_theorem_3_1_direct_route_diverges_with_3_alpha2_over_32(evaluated):
    v = evaluated["003:Theorem3.1(proof)"].verdict
    nums = {n.name: n for n in v.numbers}
    assert v.status == "refuted"
    assert sp.simplify(nums["direct_m2_leading_constant"].value - 3 * (sp.pi / 5) ** 2 / 32) == 0
    assert nums["printed_beta2_term_limit"].value == sp.Rational(-1, 4)
    assert evaluated["003:Theorem3.1"].verdict.status == "certified"
    assert evaluated["003:Corollary3.2"].verdict.status == "certified"


def test_theorem_5_1_centre_is_minus_half(evaluated):
    """Independent: the level-0 mask of (2) is a palindrome on [-4, 3], centre -1/2, not 0."""
    m = S.TRIGONOMETRIC.mask_at(0, {"alpha": sp.pi / 5, "omega": sp.Rational(1, 100)})
    assert all(sp.simplify(m[i] - m[-1 - i]) == 0 for i in range(len(m)))
    assert (S.TRIGONOMETRIC.start + S.TRIGONOMETRIC.end) / 2 == -0.5
    assert evaluated["003:Theorem5.1"].verdict.status == "refuted"
    assert evaluated["003:(7)"].verdict.status == "refuted"


def test_comparisons_are_numerical_only(evaluated):
    for cid in ("003:Sec6-7(circles,ellipses)", "003:Sec6-7(cardioid,astroid,lemniscate)"):
        assert evaluated[cid].verdict.status == "numerical"


def test_jena_scheme_reconstruction_reproduces_circles():
    from analysis.reproduction import generation

    assert generation(S.JENA_11, [sp.I * S.ALPHA, -sp.I * S.ALPHA]).status == "certified"
    import schemes

    assert S.JENA_11.limit() == schemes.get("dd-4").symbol        # w_n -> 1/16: the DD 4-point scheme
