"""Proof-check claims of seeds 000/001 (NVPS): every claim gives a Verdict, key verdicts agree with
independent recomputations (not typed-in verdicts), and ``subdiv report`` writes the report files."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from analysis import claims as C
from analysis.claims.model import compare_verdicts
from papers import seed000, seed001


@pytest.fixture(scope="module")
def evaluated_001():
    """Every claim of paper 001, evaluated once per test process (here and for its report below)."""
    return C.evaluate_paper(seed001.PAPER)


@pytest.fixture(scope="module")
def evaluated(evaluated_001):
    out = {ev.claim.id: ev for ev in C.evaluate_paper(seed000.PAPER)}
    out.update((ev.claim.id, ev) for ev in evaluated_001)
    return out


def test_every_claim_evaluates_to_a_verdict(evaluated):
    assert len(evaluated) == len(seed000.PAPER.claims) + len(seed001.PAPER.claims)
    for cid, ev in evaluated.items():
        assert isinstance(ev.verdict, C.Verdict), cid
        assert ev.error is None, (cid, ev.error)
        assert ev.claim.statement and ev.claim.command.startswith("subdiv "), cid


def test_matches_golden_files(evaluated):
    """`subdiv check 000 001` on fresh verdicts: statuses and key numbers as reviewed (papers 000 and
    001's part of the CI regression, ``tests/test_report.py::test_committed_verdicts_are_reproduced``;
    the claims are evaluated once, here)."""
    import json

    from analysis.claims import golden_path

    C.papers()                           # discovery names each bundled paper's folder (its golden file)
    for paper in (seed000.PAPER, seed001.PAPER):
        golden = json.loads(golden_path(paper).read_text(encoding="utf-8"))
        fresh = C.verdicts_json({paper.id: [evaluated[c.id] for c in paper.claims]})
        assert compare_verdicts(golden, fresh, papers_=[paper.id]) == []


def test_papers_are_discovered():
    allp = C.papers()
    assert allp["000"] is seed000.PAPER and allp["001"] is seed001.PAPER
    # the older dict-based CLAIMS (used by `subdiv nonuniform claims`) are kept
    assert seed001.check("001:(17)").status == "refuted"


def _exact_symbol_values():
    u, z = sp.symbols("u z")
    a = (1 + (1 + 2 * u) * z + (1 + 2 * u) * z ** 2 + z ** 3) / (2 * (1 + u) * z)
    return [sp.simplify(sp.diff(a, z, n).subs(z, 1)) for n in range(3)]


def test_17_refuted_by_independent_values(evaluated):
    a0, a1, a2 = _exact_symbol_values()
    u = sp.Symbol("u")
    assert a0 == 2 and a1 == 1 and sp.simplify(a2 - 2 / (1 + u)) == 0   # printed (17): 1, 2, 1
    v = evaluated["001:(17)"].verdict
    nums = {n.name: n for n in v.numbers}
    assert nums["a(1)"].value == a0 and nums["a'(1)"].value == a1
    assert sp.simplify(sp.sympify(nums["a''(1)"].value, locals={"u": u}) - a2) == 0
    # the corrected statement carries the computed values
    assert v.corrected and "(1) = 2" in v.corrected and "(1) = 1" in v.corrected and "2/(u^k_j + 1)" in v.corrected


def _lane_riesenfeld_mask(d):
    m = np.array([1.0, 3.0, 3.0, 1.0]) / 4
    for _ in range(d - 2):
        m = np.convolve(m, [0.5, 0.5])
    return m


def test_bspline_special_case_independent(evaluated):
    from analysis import nonuniform as nu
    ok = True
    for d in range(2, 8):
        expect = np.array([math.comb(d + 1, t) for t in range(d + 2)]) / 2 ** d
        ok &= np.allclose(_lane_riesenfeld_mask(d), expect)
        # refine delta data with u = 1 and read the mask off the result
        e = np.zeros(15)
        e[7] = 1.0
        r = nu.refine(e, [1.0] * 14, degree=d, steps=1).points
        ok &= np.allclose(sorted(r[r > 1e-14]), sorted(expect))
    assert ok
    assert evaluated["001:Abstract(special cases)"].verdict.status == "certified"
    assert evaluated["001:(3)Chaikin"].verdict.status == "certified"


def test_16_fails_at_a_junction_independently(evaluated):
    # degree 4: average three consecutive degree-2 points, two of them on edges with different h
    z = sp.Symbol("z")
    h1, h2 = sp.Rational(1, 3), sp.Rational(1, 8)       # u = 1/2 and u = 3

    def A2(h):
        return h / z ** 2 + (1 - h) / z + (1 - h) + h * z

    # S_2 point q on edge floor(q/2); a_4 at new point i = (Q_i + 2 Q_{i+1} + Q_{i+2})/4
    # with Q_i, Q_{i+1} on the left edge and Q_{i+2} on the right one (shifted masks z^-l)
    a4 = sp.expand(z ** 4 * (A2(h1) + 2 * A2(h1) / z + A2(h2) / z ** 2) / 4)
    p = sp.Poly(a4, z)
    k = 0
    while p.eval(-1) == 0:
        p = sp.Poly(sp.quo(p, sp.Poly(1 + z, z)), z)
        k += 1
    assert k < 3                         # (16) would give (1+z)^3
    assert evaluated["001:(16)"].verdict.status == "refuted"


def test_corollary_3_4_rate_independently(evaluated):
    mpmath.mp.prec = 200
    u = mpmath.mpf("0.1")
    dev = []
    for k in range(15):
        dev.append(abs(1 / (2 * (1 + u)) - mpmath.mpf(1) / 4))
        u = mpmath.sqrt((1 + u) / 2)
    ratio = float(dev[-1] / dev[-2])
    mpmath.mp.prec = 53
    assert abs(ratio - 0.25) < 1e-6
    v = evaluated["001:Corollary3.4"].verdict
    nums = {n.name: n for n in v.numbers}
    assert abs(nums["ratio_last"].float - ratio) < 1e-4
    # the certified constants c1, c2 of c1 4^-k <= sup_j ||S^k - S_a|| <= c2 4^-k are exact and enclose an
    # independent high-precision replay (u0 = 1/10 edge: ||S^k - S_a|| = 2 |delta_k| on its windows)
    lo, hi = nums["lower_constant"].value, nums["upper_constant"].value
    assert isinstance(lo, sp.Rational) and isinstance(hi, sp.Rational) and 0 < lo < hi
    for k, dk in enumerate(dev):
        assert float(lo) <= float(2 * dk * 4 ** k) <= float(hi)
    assert v.status == "certified" and "4^-k" in v.summary


def test_000_update_differs_for_even_d_independently(evaluated):
    # d = 2: seed 000 gives new edge 1 the parameter of old edge 0, seed 001's (2) that of old edge 1
    u = [0.2, 5.0]
    phi = lambda x: math.sqrt((1 + x) / 2)  # noqa: E731
    s000 = [phi(u[0]), phi(u[0]), phi(u[1]), phi(u[1])][:3]
    s001 = [phi(u[0]), phi(u[1]), phi(u[1])]
    assert s000 != s001
    assert evaluated["000:update"].verdict.status == "refuted"


def test_tau_gloss_independently(evaluated):
    bad = [d for d in range(3, 11) if math.ceil((d - 2) / 2) != math.floor((d - 2) / 2) + 1]
    assert bad == [4, 6, 8, 10]
    v = evaluated["000:tau_d"].verdict
    assert v.status == "refuted" and v.corrected


def test_support_count_independently(evaluated):
    # B-spline of degree d has d + 2 mask coefficients; Z ∩ [0, d] has d + 1 points
    assert all(len(_lane_riesenfeld_mask(d)) == d + 2 for d in range(2, 8))
    assert evaluated["001:Sect3.3(support)"].verdict.status == "refuted"


def test_circle_reproduction_identity_independently(evaluated):
    # rule (3) on a regular polygon of angle step 2phi with u = cos(phi): new points on a regular polygon of step phi
    phi = 0.37
    h = 1 / (2 * (1 + math.cos(phi)))
    f = np.exp(2j * phi * np.arange(6))
    new = np.empty(10, dtype=complex)
    new[0::2] = (1 - h) * f[:-1] + h * f[1:]
    new[1::2] = h * f[:-1] + (1 - h) * f[1:]
    ratios = new[1:] / new[:-1]
    assert np.allclose(ratios, np.exp(1j * phi), atol=1e-14)
    assert evaluated["001:Remark1(reproduction)"].verdict.status == "certified"
    assert evaluated["000:reproduction"].verdict.status == "certified"


def test_theorem_3_6_is_numerical_with_c3_failure(evaluated):
    v = evaluated["001:Theorem3.6"].verdict
    nums = {n.name: n.float for n in v.numbers}
    assert v.status == "numerical"
    assert nums["omega_d4"] > 0.5 and nums["omega_d4_order2"] < 1e-3 and nums["omega_d2"] < 1e-3
    assert evaluated["001:(19)"].verdict.status == "refuted"


def test_chamfer_radii_half_of_rmax(evaluated):
    from analysis import nonuniform as nu

    v = evaluated["001:Algorithm2"].verdict
    nums = {n.name: n for n in v.numbers}
    # computed content: the midpoints (limit points for d = 2) lie on the exact shape ...
    assert nums["midpoint_deviation_below_1e-12"].value is True
    assert "midpoint_deviation" not in nums      # its float64 value (~4e-15) differs between machines
    # ... and r_A, r_D are half of r_max (arc through B1 A C1 with |AB1| = |AC1| = min(|AB|, |AC|)), recomputed here
    V = np.array(nu.CHAMFER_QUADRANGLE, dtype=float)
    for i, name in ((0, "rA_over_rmax"), (3, "rD_over_rmax")):
        A, B, Cq = V[i], V[i - 1], V[(i + 1) % 4]
        lb, lc = np.linalg.norm(B - A), np.linalg.norm(Cq - A)
        th = math.acos(float((B - A) @ (Cq - A)) / (lb * lc))
        rmax = min(lb, lc) * math.tan(th / 2) / 2
        assert abs(nu.CHAMFER_RADII[i] / rmax - 0.5) < 1e-6
        assert abs(nums[name].float - nu.CHAMFER_RADII[i] / rmax) < 1e-12
    assert v.figures and v.figures[0].name == "001-chamfer"


def test_locality_count_independently(evaluated):
    from fractions import Fraction

    from analysis import nonuniform as nu

    # d = 4, k = 3: changing one edge parameter changes (2^3 - 1) * 4 = 28 points (exact arithmetic)
    data = [Fraction(i * i % 7, 3) for i in range(14)]
    w = Fraction(11, 10)
    for _ in range(3):
        w = 2 * w * w - 1
    u1 = [1] * 13
    u1[6] = w
    a = nu.refine(data, [1] * 13, degree=4, steps=3, arithmetic="exact").points
    b = nu.refine(data, u1, degree=4, steps=3, arithmetic="exact").points
    changed = sum(1 for x, y in zip(a, b) if x != y)
    v = evaluated["001:Remark2(locality)"].verdict
    nums = {n.name: n.value for n in v.numbers}
    assert changed == nums["changed_points_d4_k3"] == 28
    assert nums["count_rule_holds"] is True


def test_report_files_written(tmp_path, evaluated_001, monkeypatch):
    """``subdiv report 001`` renders and writes every claim's verdict. Its evaluation is
    ``analysis.claims.model.evaluate_paper`` on paper 001, which the fixture ran already (and the tests
    above check claim by claim): the command gets those verdicts instead of computing them again."""
    from analysis.cli import main
    from analysis.cli import report as cli_report

    def evaluate_paper(paper, progress=None, only=None):
        assert paper is seed001.PAPER and only is None
        for k, ev in enumerate(evaluated_001, start=1):
            if progress is not None:
                progress(k, len(evaluated_001), ev)
        return list(evaluated_001)

    monkeypatch.setattr(cli_report, "evaluate_paper", evaluate_paper)
    assert main(["report", "001", "--output", str(tmp_path), "--quiet"]) in (0, None)
    assert (tmp_path / "001.md").stat().st_size > 5000 and (tmp_path / "001.html").exists()
    assert (tmp_path / "figures" / "001-chamfer.png").exists()
    md = (tmp_path / "001.md").read_text(encoding="utf-8")
    assert "001:Theorem3.6" in md and "REFUTED" in md
