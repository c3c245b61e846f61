"""Issue 11, two more claim kinds: "support after steps" and "limit symmetry" (binary and m-ary).

Expected values are computed here independently of the code under test: the support after L steps
by running the subdivision operator ``(S f)_i = sum_j a_(i-mj) f_j`` on a delta (plain Python,
exact fractions) and reading off the non-zero indices; the symmetry of the basic limit function from
the same direct subdivision: ``S^L delta`` is symmetric and its centre (in level-0 units) tends to
the centre of ``phi``. The support
``[s, e]/(m-1)`` of the basic limit function is Cavaretta–Dahmen–Micchelli (Mem. AMS 93, 1991),
the quadratic B-spline (Chaikin) is symmetric about the middle of its support (G. Chaikin 1974).
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest
import sympy as sp

from analysis.algebra.symbol import LaurentSymbol
from analysis.claims.kinds import KIND_CLASSES
from analysis.claims.kinds.base import SchemeSpec
from analysis.claims.kinds.limit_symmetry import LimitSymmetry
from analysis.claims.kinds.support_steps import SupportAfterSteps
from analysis.claims.paperfile import parse_paper
from analysis.claims.template import template
from analysis.result import AnalysisError

ROOT = Path(__file__).resolve().parents[1]
R = Fraction
CHAIKIN = ([R(1, 4), R(3, 4), R(3, 4), R(1, 4)], -2)
#: the ternary 4-point scheme of Hassan-Ivrissimitzis-Dodgson-Sabin (2002) at mu = 1/10
MU = R(1, 10)
TERNARY = ([MU / 6 - R(1, 18), -MU / 6 - R(1, 18), 0, R(7, 18) - MU / 2, R(13, 18) + MU / 2, 1,
            R(13, 18) + MU / 2, R(7, 18) - MU / 2, 0, -MU / 6 - R(1, 18), MU / 6 - R(1, 18)], -5)
#: a non-symmetric mask with a(1) = 2, a(-1) = 0
SKEW = ([R(1, 4), R(1, 2), R(3, 4), R(1, 2)], -1)


def _spec(mask, start, m=2):
    return {"s": SchemeSpec("s", LaurentSymbol.from_mask([sp.Rational(x.numerator, x.denominator) if isinstance(x, R)
                                                           else x for x in mask], start=start), arity=m)}


def _subdivide(mask, start, m, steps):
    """S^steps applied to delta_0: {index: value} (exact fractions)."""
    f = {0: R(1)}
    for _ in range(steps):
        g = {}
        for j, fj in f.items():
            for k, a in enumerate(mask):
                if a:
                    g[m * j + start + k] = g.get(m * j + start + k, 0) + a * fj
        f = {i: v for i, v in g.items() if v != 0}
    return f


def _support(mask, start, m, steps):
    f = _subdivide(mask, start, m, steps)
    return min(f), max(f)


@pytest.mark.parametrize("name, m, L", [("chaikin", 2, 3), ("ternary", 3, 2), ("skew", 2, 4)])
def test_support_after_steps_matches_direct_subdivision(name, m, L):
    mask, start = {"chaikin": CHAIKIN, "ternary": TERNARY, "skew": SKEW}[name]
    lo, hi = _support(mask, start, m, L)
    S = _spec(mask, start, m)
    v = SupportAfterSteps({"steps": L, "support": [lo, hi]}, S, "x").evaluate()
    assert v.status == "certified"
    nums = {n.name: n.value for n in v.numbers}
    assert (nums[f"support after {L} steps start"], nums[f"support after {L} steps end"]) == (lo, hi)
    # the basic limit function: [s, e]/(m-1) (Cavaretta-Dahmen-Micchelli)
    e = start + len(mask) - 1
    assert (nums["limit function start"], nums["limit function end"]) == (sp.Rational(start, m - 1), sp.Rational(e, m - 1))
    # a wrong printed interval is refuted, the true one in the corrected statement
    w = SupportAfterSteps({"steps": L, "support": [lo + 1, hi]}, S, "x").evaluate()
    assert w.status == "refuted" and f"[{lo}, {hi}]" in w.corrected
    # scaled to level-0 units: divide by m^L (the limit function's support is approached from inside)
    sc = SupportAfterSteps({"steps": L, "support": [str(R(lo, m ** L)), str(R(hi, m ** L))], "of": "scaled"}, S, "x")
    assert sc.evaluate().status == "certified"


def test_support_after_steps_parameters_and_errors():
    w = sp.Symbol("w")
    four = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
    S = {"4pt": SchemeSpec("4pt", four)}
    v = SupportAfterSteps({"steps": 2, "support": [-9, 9]}, S, "x").evaluate()
    assert v.status == "certified" and "w = 0: [-1, 1]" in v.sharpness      # w = 0: the linear B-spline
    at0 = [R(0), 0, R(1, 2), 1, R(1, 2), 0, R(0)]
    assert _support(at0, -3, 2, 2) == (-3, 3)
    assert SupportAfterSteps({"steps": 2, "support": [-3, 3], "at": {"w": "0"}}, S, "x").evaluate().status == "certified"
    for fields, msg in (({"steps": 0, "support": [0, 1]}, "steps"), ({"steps": 1, "support": [0]}, "support"),
                        ({"steps": 1, "support": [0, 1], "of": "limit"}, "'of'")):
        with pytest.raises(AnalysisError, match=msg):
            SupportAfterSteps(fields, S, "x")


def _finite_centre(mask, start, m, levels):
    """The symmetry centre of S^levels delta in level-0 units (None if it is not symmetric)."""
    f = _subdivide(mask, start, m, levels)
    c2 = min(f) + max(f)                       # twice the midpoint index
    return R(c2, 2 * m ** levels) if all(f.get(c2 - i, 0) == v for i, v in f.items()) else None


@pytest.mark.parametrize("name, m, centre", [("chaikin", 2, R(-1, 2)), ("ternary", 3, R(0)), ("ternary-shifted", 3, R(1, 2))])
def test_limit_symmetry_matches_direct_subdivision(name, m, centre):
    """S^L delta is symmetric at every level; its centre tends to phi's centre (within m^-L here)."""
    mask, start = {"chaikin": CHAIKIN, "ternary": TERNARY, "ternary-shifted": (TERNARY[0], TERNARY[1] + 1)}[name]
    L = 6 if m == 2 else 4
    cL = _finite_centre(mask, start, m, L)
    assert cL is not None and abs(cL - centre) <= R(1, m ** L) < abs(cL - centre - R(1, 2))
    S = _spec(mask, start, m)
    typ = "primal" if centre.denominator == 1 else "dual"
    v = LimitSymmetry({"centre": str(centre), "type": typ}, S, "x").evaluate()
    assert v.status == "certified" and {n.name: n.value for n in v.numbers}["centre"] == centre
    wrong = LimitSymmetry({"centre": str(centre + R(1, 2))}, S, "x").evaluate()
    assert wrong.status == "refuted" and f"symmetric about {sp.Rational(centre.numerator, centre.denominator)}" in wrong.corrected
    other = "dual" if typ == "primal" else "primal"
    assert LimitSymmetry({"type": other}, S, "x").evaluate().status == "refuted"


def test_limit_symmetry_of_a_skew_mask_and_unnormalised_masks():
    assert _finite_centre(*SKEW, 2, 3) is None
    S = _spec(*SKEW)
    assert LimitSymmetry({}, S, "x").evaluate().status == "refuted"
    assert LimitSymmetry({"symmetric": False}, S, "x").evaluate().status == "certified"
    half = _spec([R(1, 4), R(1, 2), R(1, 4)], -1)                # a(1) = 1: no normalised refinable function
    assert LimitSymmetry({}, half, "x").evaluate().status == "inconclusive"
    with pytest.raises(AnalysisError, match="'type'"):
        LimitSymmetry({"type": "odd"}, S, "x")


def test_kinds_registered_in_the_template():
    assert {"support after steps", "limit symmetry"} <= set(KIND_CLASSES)
    p = parse_paper(template(), "new.toml")
    byid = {c.id: c for c in p.claims}
    for cid in ("900:Example.support-after-steps", "900:Example.limit-symmetry"):
        assert byid[cid].evaluate().status == "certified"


def test_example_file_and_golden():
    """examples/support-symmetry.toml: the golden file is what the code computes; T1 (a false reading) is refuted."""
    import schemes
    from analysis.claims.model import evaluate_paper

    path = ROOT / "examples" / "support-symmetry.toml"
    p = parse_paper(path.read_text(encoding="utf-8"), str(path), catalogue=schemes.get)
    got = {e.claim.id: e.verdict.status for e in evaluate_paper(p)}
    golden = json.loads((ROOT / "examples" / "support-symmetry.verdicts.json").read_text(encoding="utf-8"))
    assert got == {k: v["status"] for k, v in golden["papers"]["supp"]["claims"].items()}
    assert got["supp:T1"] == "refuted" and sum(s == "certified" for s in got.values()) == 5
    # C1 and T2 independently: Chaikin 2 steps, ternary 4-point (any mu) 2 steps
    assert _support(*CHAIKIN, 2, 2) == (-6, 3) and _support(*TERNARY, 3, 2) == (-20, 20)


def test_the_guide_shows_the_example_report(tmp_path, capsys):
    """The verdict table of examples/support-symmetry.toml in docs/paper-files.md is the one `subdiv report`
    prints (tests/test_docs_examples.py runs the page's examples too; this keeps the table from leaving it)."""
    import re

    from analysis.cli import main

    assert main(["report", str(ROOT / "examples" / "support-symmetry.toml"), "--output", str(tmp_path), "--quiet"],
                extra_modules=["analysis.cli.report", "analysis.cli.paperfile"]) == 0
    printed = capsys.readouterr().out
    guide = (ROOT / "docs" / "paper-files.md").read_text(encoding="utf-8")
    shown = re.search(r"```console\n\$ subdiv report examples/support-symmetry.toml[^\n]*\n(.*?)```", guide, re.S).group(1)
    keep = ("claim", "supp:", "---")
    assert [x.rstrip() for x in printed.splitlines() if x.startswith(keep)] == \
        [x.rstrip() for x in shown.splitlines() if x.startswith(keep)]
