"""Issue 11, second half: the bundled papers 003 and 004 are paper files; `python` claims take
`args`; the smoothness profile lists isolated C^j points at exceptional parameter values; exact
boundaries come from a determinant over Q[p].

Expected values are independent of the code under test: Chaikin's scheme (w = 1/8 below) is the
quadratic B-spline scheme, C^1 with Hölder exponent 2 (G. Chaikin, Comput. Graph. Image Process. 3
(1974); Dyn-Levin, Acta Numer. 11 (2002), Sect. 2); the old symbolic Berkowitz determinant is
recomputed here and compared with the new one.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from analysis.algebra.factorization import factor_out, smoothing_factor
from analysis.algebra.symbol import LaurentSymbol
from analysis.claims.kinds.base import SchemeSpec
from analysis.claims.kinds.profile import SmoothnessProfile
from analysis.claims.paperfile import parse_paper
from analysis.regularity.holder import word_product
from analysis.regularity.crossings import _exact_boundaries
from analysis.result import AnalysisError
from analysis.stationary.transition import transition_matrices

ROOT = Path(__file__).resolve().parents[1]
W = sp.Symbol("w")
#: 2 (w, 1/2 - w, 1/2 - w, w): w = 1/8 gives Chaikin's mask (1, 3, 3, 1)/4
FAMILY = LaurentSymbol.from_mask([W, sp.Rational(1, 2) - W, sp.Rational(1, 2) - W, W], start=-2) * 2


@pytest.mark.parametrize("pid, n_python, n_profile", [("003", 9, 1), ("004", 4, 2)])
def test_bundled_papers_are_paper_files(pid, n_python, n_profile):
    """Every claim of the golden file is in paper.toml; the python claims are the special ones (004: 4 of 49)."""
    import importlib

    paper = importlib.import_module(f"papers.seed{pid}").PAPER
    text = (ROOT / "papers" / f"seed{pid}" / "paper.toml").read_text(encoding="utf-8")
    kinds = [t.split('"')[1] for t in text.split("\nkind = ")[1:]]
    assert kinds.count("python") == n_python and kinds.count("smoothness profile") == n_profile
    golden = json.loads((ROOT / "papers" / f"seed{pid}" / "verdicts.json").read_text(encoding="utf-8"))
    assert sorted(c.id for c in paper.claims) == sorted(golden["papers"][pid]["claims"])


def test_python_claim_args():
    """`args` are passed to the evaluator; a non-list is a one-line error."""
    base = ('[paper]\nid = "t"\ntitle = "t"\n[[claims]]\nid = "A"\nstatement = "s"\nkind = "python"\n'
            'evaluator = "analysis.claims.model:inconclusive"\n')
    p = parse_paper(base + 'args = ["the arguments reach the evaluator", "both of them"]\n', "t.toml", python="allowed")
    v = p.claims[0].evaluate()
    assert v.status == "inconclusive" and (v.summary, v.settle) == ("the arguments reach the evaluator", "both of them")
    with pytest.raises(AnalysisError, match="args must be a list"):
        parse_paper(base + 'args = "3.1"\n', "t.toml")


def test_profile_isolated_point_at_exceptional_value():
    """w = 1/8 (Chaikin) is an isolated C^1 point of the family, with alpha = 2 there."""
    exc = smoothing_factor(FAMILY, exceptional=True).witness["exceptional"]
    assert [e["condition"][W] for e in exc] == [sp.Rational(1, 8)]
    v = SmoothnessProfile({"within": "(0, 1/4)", "grid": 4, "samples": 4},
                          {"s": SchemeSpec("s", FAMILY)}, "x").evaluate()
    nums = {n.name: n for n in v.numbers}
    assert sp.sympify(nums["C^1 isolated point"].value) == sp.Rational(1, 8)
    assert "C^2 isolated point" not in nums
    # the certified maximum of alpha over (0, 1/4): Chaikin's alpha = 2 at the exceptional value (every
    # other w has two sum rules only, so alpha <= 2 there; the branch and bound proves alpha < 2 off 1/8)
    assert sp.sympify(nums["alpha max at"].value) == sp.Rational(1, 8)
    assert nums["alpha max lower"].lower == 2 and nums["alpha max upper"].upper == 2
    assert v.status != "certified"   # C^1 elsewhere between the grid points is sampled, not proven


def _berkowitz_numerator(a, p, j, word):
    """The first half's determinant (symbolic Berkowitz), for comparison."""
    N = smoothing_factor(a, exceptional=False).value
    P = word_product(transition_matrices(factor_out(a, N) / 2), word)
    theta = sp.Integer(2) ** ((N - 1 - j) * len(word))
    out = []
    for sgn in (1, -1):
        D = sp.together((P - sgn * theta * sp.eye(P.shape[0])).det(method="berkowitz"))
        out.append(sp.Poly(sp.fraction(sp.together(D))[0], p, domain=sp.QQ))
    return out


@pytest.mark.parametrize("j, word", [(0, (0,)), (1, (0, 1))])
def test_exact_boundaries_same_roots_as_berkowitz(j, word):
    """The Q[p] determinant has the roots of the symbolic Berkowitz determinant (up to a constant)."""
    lo, hi = sp.Rational(-1), sp.Rational(1)
    new = _exact_boundaries(FAMILY, W, j, word, lo, hi)
    assert new
    old_polys = [q for q in _berkowitz_numerator(FAMILY, W, j, word) if not q.is_zero and q.degree() >= 1]
    old_roots = sorted(float(r) for q in old_polys for r in sp.Poly(q, W).real_roots() if lo <= r <= hi)
    assert sorted(float(r) for r, _, _ in new) == pytest.approx(old_roots, abs=1e-12)
    for r, _, poly in new:
        assert any(sp.Poly(poly, W).rem(sp.Poly(q, W)).is_zero or sp.Poly(q, W).rem(sp.Poly(poly, W)).is_zero
                   for q in old_polys)
