"""The claims framework (a fake paper with a true, a false and an inconclusive claim) and the seed
004 claims, each checked against an independent recomputation (never against typed-in verdicts)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from analysis import claims as C
from analysis.result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, Result


# ------------------------------------------------------------------------------ the framework
def _true():
    return C.certified("1 + 1 = 2", evidence=[C.Evidence("sum", result=C.exact_result(2, "exact"))],
                       numbers=[C.Number("sum", sp.Integer(2))])


def _false():
    return C.refuted("1 + 1 = 2, not 3", "1 + 1 = 2", numbers=[C.Number("sum", 2)],
                     evidence=[C.Evidence("sum", result=C.exact_result(2, "exact"))])


def _open():
    return C.inconclusive("needs a bigger computer", settle="run it on a bigger computer")


def _boom():
    raise RuntimeError("deliberate")


FAKE = C.Paper(id="990", title="Fake", citation="nobody", claims=[
    C.Claim(id="990:T1", kind="identity", statement="1 + 1 = 2", evaluate=_true),
    C.Claim(id="990:T2", kind="identity", statement="1 + 1 = 3", evaluate=_false),
    C.Claim(id="990:T3", kind="smoothness", statement="the scheme is C^9", evaluate=_open),
    C.Claim(id="990:T4", kind="identity", statement="broken", evaluate=_boom)])


def test_fake_paper_verdicts():
    evs = C.evaluate_paper(FAKE)
    assert [e.verdict.status for e in evs] == [CERTIFIED, REFUTED, INCONCLUSIVE, INCONCLUSIVE]
    assert evs[1].verdict.corrected == "1 + 1 = 2"
    assert "deliberate" in evs[3].verdict.summary and evs[3].error


def test_verdict_never_says_more_than_its_evidence():
    num = C.Evidence("float", result=Result(0.1, status=NUMERICAL))
    with pytest.raises(ValueError, match="numerical evidence"):
        C.Verdict(CERTIFIED, "x", evidence=[num])
    with pytest.raises(ValueError, match="corrected"):
        C.Verdict(REFUTED, "x")
    with pytest.raises(ValueError, match="settle"):
        C.Verdict(INCONCLUSIVE, "x")
    assert C.Verdict(NUMERICAL, "x", evidence=[num]).label == "NUMERICAL"


def test_claim_ids_are_checked():
    with pytest.raises(ValueError):
        C.Claim(id="no-colon", kind="identity", statement="", evaluate=_true)
    with pytest.raises(ValueError, match="start with"):
        C.Paper(id="991", title="", citation="", claims=[FAKE.claims[0]])


def test_compare_verdicts_reports_status_and_number_moves():
    evs = C.evaluate_paper(FAKE)
    golden = {"papers": {"990": {"claims": {e.claim.id: {"status": e.verdict.status, "numbers": {
        n.name: n.to_json() for n in e.verdict.numbers}} for e in evs}}}}
    assert C.compare_verdicts(golden, golden) == []
    changed = {"papers": {"990": {"claims": dict(golden["papers"]["990"]["claims"])}}}
    changed["papers"]["990"]["claims"]["990:T1"] = {"status": "refuted", "numbers": {
        "sum": {"exact": "3", "float": 3.0, "tol": 0}}}
    diffs = C.compare_verdicts(golden, changed)
    assert "990:T1: status changed: certified -> refuted" in diffs
    assert any("number 'sum' changed: 2 -> 3" in d for d in diffs)


def test_registry_finds_seed004():
    ps = C.papers()
    assert "004" in ps and C.get_paper("4") is ps["004"] and C.get_paper("seed004") is ps["004"]
    ids = [c.id for c in ps["004"].claims]
    assert len(ids) == len(set(ids)) >= 40


def test_exact_set_handles_points_and_gaps():
    x = sp.Symbol("x")
    s = C.exact_set(lambda v: v * v != 1, [sp.Poly(x * x - 1, x)])       # all but +-1
    assert str(s) == "(-oo, -1) U (-1, 1) U (1, oo)"
    s = C.exact_set(lambda v: v * v <= 2, [sp.Poly(x * x - 2, x)])
    assert str(s) == "[-sqrt(2), sqrt(2)]"


# ------------------------------------------------------------------------------ seed 004
from analysis.algebra.linear_forms import read_garbled_linear  # noqa: E402
import schemes  # noqa: E402
from analysis.algebra.symbol import LaurentSymbol  # noqa: E402
from analysis.algebra.linear_forms import end_rules  # noqa: E402
from analysis.claims.kinds.open_curves import _nonneg_set, zeta_conditions  # noqa: E402
from papers.seed004 import special as K4  # noqa: E402
from schemes import seed004  # noqa: E402

MU, NU, OMEGA = seed004.MU, seed004.NU, seed004.OMEGA
_GREEK = {"μ": MU, "ν": NU, "ω": OMEGA}


def _printed_end_rules():
    """The printed end rules, as the paper file holds them: {point: [(garbled, index), ...]}."""
    from pathlib import Path

    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib

    data = tomllib.loads((Path(K4.__file__).with_name("paper.toml")).read_text(encoding="utf-8"))
    return {c["point"]: [tuple(x) for x in c["printed"]] for c in data["claims"] if c["kind"] == "end rules"}


PRINTED_END_RULES = _printed_end_rules()


def _construction():
    """Steps 1-4 as the paper file's 'construction' claims build them."""
    from analysis.claims.kinds.construction import Construction
    from analysis.claims.kinds.base import SchemeSpec

    specs = {n: SchemeSpec(n, schemes.get(s).symbol) for n, s in (("dc", "seed004-design-control"),)}
    q, r = (LaurentSymbol.from_rules(x.even, x.odd, even_first=x.even_first, odd_first=x.odd_first)
            for x in (seed004.RULE_3_1, seed004.RULE_3_2))
    specs.update({"q": SchemeSpec("q", q), "r": SchemeSpec("r", r)})
    return Construction({"scheme": "dc", "from": {"Q": "q", "R": "r"}, "weights": {
        "even": {"-1": "mu", "0": "nu", "1": "omega"}, "odd": {"-1": "omega", "0": "nu", "1": "mu"}}}, specs, "x").build()


def _derived_end_rules():
    b = _construction()
    return end_rules(b["P_{2i}"], b["P_{2i+1}"])


def _verdict(cid):
    return C.evaluate_claim(C.get_paper("004").claim(cid)).verdict


def test_construction_equals_catalogue_entry():
    b = _construction()
    # independent: Q_{2i} - DE by hand with the printed (3.1), (3.2)
    Q = [sp.Rational(c, 128) for c in (-7, 105, 35, -5)]
    R = [sp.Rational(c, 64) for c in (7, 35, 21, 1)]
    D = [q - r for q, r in zip(Q, R)]
    even = {p: 0 for p in range(-2, 4)}
    for s, w in ((-1, MU), (0, NU), (1, OMEGA)):
        for k, d in enumerate(D):
            even[k - 1 + s] -= w * d
    for k, q in enumerate(Q):
        even[k - 1] += q
    assert all(sp.expand(b["P_{2i}"][p] - even[p]) == 0 for p in even)
    assert _verdict("004:(3.6)").status == CERTIFIED


def _reflect_and_apply(lab, vals):
    """Independent end-rule computation: numeric ghost points and the (3.6) mask directly."""
    a = schemes.get("seed004-design-control").symbol.subs(vals)
    n = 9
    rng = np.random.default_rng(1)
    P = {j: sp.Rational(int(v), 7) for j, v in enumerate(rng.integers(-20, 20, n + 1))}
    for m in (1, 2):
        P[-m] = 2 * P[0] - P[m]
    for m in (1, 2, 3):
        P[n + m] = 2 * P[n] - P[n - m]
    k = {"P0": 0, "P1": 1, "P2": 2, "P3": 3}.get(lab)
    if k is None:
        k = 2 * n + int(lab[3:] or 0)
    val = sum(a.coeff(k - 2 * j) * P[j] for j in range(-2, n + 4) if j in P)
    form = _derived_end_rules()[lab].subs(vals)
    base = 0 if lab in ("P0", "P1", "P2", "P3") else n
    return val, sum(c * P[base + q] for q, c in form.items())


@pytest.mark.parametrize("lab", list(PRINTED_END_RULES))
def test_end_rules_match_direct_ghost_refinement(lab):
    vals = {MU: sp.Rational(3, 17), NU: sp.Rational(-5, 11), OMEGA: sp.Rational(2, 13)}
    direct, derived = _reflect_and_apply(lab, vals)
    assert direct == derived


@pytest.mark.parametrize("lab", list(PRINTED_END_RULES))
def test_end_rule_verdict_follows_printed_coefficients(lab):
    derived = _derived_end_rules()[lab]
    agree = all(any(sp.expand(r - derived[q] * 128) == 0
                    for r in read_garbled_linear(g, _GREEK))
                for g, idx in PRINTED_END_RULES[lab]
                for q in [int(idx[1:] or 0) if idx.startswith("n") else int(idx)])
    agree &= len(PRINTED_END_RULES[lab]) == len(derived.items())
    assert _verdict(f"004:(3.9)-(3.10)/{lab}").status == (CERTIFIED if agree else REFUTED)


def test_theorem_5_1_necessary_set_is_minus_one_to_25_over_7():
    # independent: sample |9/64 - 7nu/64| < 1/4 on a grid of rationals
    from analysis.claims.kinds.base import SchemeSpec
    from analysis.claims.kinds.spectral import EigenvalueInequality
    t = SchemeSpec("t-nu", schemes.get("seed004-t-nu").symbol)
    s = EigenvalueInequality({"j": 2, "interval": "(5/7, 13/7)"}, {"t-nu": t}, "x").exact()[0]
    for q in [sp.Rational(k, 20) for k in range(-40, 90)]:
        assert s.contains(q) == (abs(sp.Rational(9, 64) - 7 * q / 64) < sp.Rational(1, 4))
    v = _verdict("004:Theorem5.1")
    assert v.status == CERTIFIED and "(-1, 25/7)" in v.sharpness


def test_inequality_5_7_against_float_eigenvalues():
    from analysis.claims.kinds.spectral import moduli_chain_set
    D = 833 * MU ** 2 + 70 * MU + 1
    s = moduli_chain_set([-7 * MU / 32, (7 * MU + 1 + sp.sqrt(D)) / 128], MU)
    for mu in (-2.0, -0.5, -0.06, -0.04, -0.03, 0.0, 0.3):
        c, D = 7 * mu + 1, 833 * mu ** 2 + 70 * mu + 1
        l8 = (c + np.sqrt(complex(D))) / 128
        assert s.contains(sp.Rational(str(mu))) == (abs(7 * mu / 32) > abs(l8))


def test_c6_claim_is_refuted_by_a_c7_member():
    from analysis.stationary.difference import difference_norm
    a = schemes.get("seed004-design-control").symbol_at(mu="-1/56", nu="29/28", omega="-1/56")
    assert difference_norm(a, 8, 1).value < 1            # C^7 by Dyn-Levin
    v = _verdict("004:Sec7(C6)")                          # alpha <= 7 is refuted: alpha > 7 there
    assert v.status == REFUTED and v.numbers[0].lower > 7


def test_theorem_5_3_eigenvalue_list_is_refuted_for_the_double_one_over_64():
    from analysis.stationary.transition import local_eigenvalues
    r = local_eigenvalues(schemes.get("seed004-l-mu").symbol)
    assert r.value[sp.Rational(1, 64)] == 1 and sum(r.value.values()) == 10
    assert _verdict("004:Theorem5.3(eigenvalues)").status == REFUTED


def test_gibbs_level_one_conditions():
    t = schemes.get("seed004-t-nu").symbol
    z = zeta_conditions(t, 1)
    # the paper's own partial sums: zeta_0(-2) = t_-4, zeta_1(-1) = t_-1 + t_-3
    assert sp.expand(z[(0, -2)] - t.coeff(-4)) == 0
    assert sp.expand(z[(1, -1)] - t.coeff(-1) - t.coeff(-3)) == 0
    s = _nonneg_set(z.values(), NU)
    assert str(s) == "[5/7, 7]"


def test_certified_verdict_without_a_certified_result_is_rejected():
    import pytest as _pytest

    from analysis import claims as C

    with _pytest.raises(ValueError, match="needs at least one certified"):
        C.certified("looks fine", evidence=[C.Evidence("prose only", text="trust me")])
    with _pytest.raises(ValueError, match="needs at least one certified"):
        C.refuted("wrong", corrected="right")
