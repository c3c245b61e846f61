"""The HTML report: MathML typesetting of untrusted paper text (sanitised), the index page and the
links between reports, and the certified smoothness profile shown beside the claims it speaks to
(on a small family, so that the test stays cheap)."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.claims.model import Claim, Evidence, Paper, certified, evaluate_paper, exact_result
from analysis.report.mathml import latex_mathml, pretty_text, quote_html, sanitise, sympy_mathml
from analysis.report.render import html, markdown

HOSTILE = (r"C^2 for 0 < \omega < \frac{1}{2} <script>alert(1)</script> \text{<img src=x onerror=alert(1)>} "
           r"\href{javascript:alert(1)}{x} & \mathbb{R}")


def _ok():
    return certified("x**2 = 4 at x = 2", evidence=[Evidence("exact", latex=r"\frac{\sqrt{6}-1}{80}",
                                                             result=exact_result(0, "exact"))])


def _paper(statement: str, title: str = "Toy") -> Paper:
    return Paper(id="997", title=title, citation="-", claims=[
        Claim(id="997:(1)", kind="identity", statement=statement, title=title, evaluate=_ok)])


def test_hostile_paper_text_is_never_markup():
    for text in (HOSTILE, r"\frac{1}{2} </math><script>x</script>", "a < b & c > d"):
        p = _paper(text, title="<b onclick=x>")
        page = html(p, evaluate_paper(p), figures={})
        assert "<script>alert" not in page and "onerror=" not in page.replace("onerror=alert(1)&gt;", "")
        assert "javascript:" not in page.split("<pre", 1)[0] and "<b onclick" not in page
        assert "<img src=x" not in page


def test_latex_is_typeset_and_sanitised():
    assert latex_mathml(r"\href{javascript:alert(1)}{x}") is None              # an href attribute: refused
    assert latex_mathml(r"\text{<b>}") is None
    assert sanitise('<math><mi onclick="x">a</mi></math>') is None
    assert sanitise("<math><mi>a</mi><foreignObject/></math>") is None
    m = quote_html(r"and C^2 - continuous limit curves for 0 < omega < \frac{\sqrt{6}-1}{80}.")
    assert m.startswith("and <math") and "continuous limit curves for" in m and "<mfrac>" in m and "ω" in m
    assert quote_html("no latex here") is None


def test_exact_values_and_prose_formulas():
    w = sp.Symbol("w")
    m = sympy_mathml(sp.CRootOf(32 * w**3 + 4 * w - 1, 0))
    assert "<msub><mi>root</mi><mn>1</mn></msub>" in m and "<msup><mi>w</mi><mn>3</mn></msup>" in m
    assert pretty_text("sqrt(2)**3 < 2*w") == "√(2)<sup>3</sup> &lt; 2·w"


def test_report_page_has_mathml_source_and_phone_layout():
    p = _paper(r"0 < x \leq \frac{1}{2}")
    results = evaluate_paper(p)
    page = html(p, results, figures={}, siblings={"996": ["996:(1)"], "997": ["997:(1)"]})
    assert "<mfrac>" in page and "the paper's LaTeX" in page and r"\frac{1}{2}" in page
    assert 'name="viewport"' in page and "@media (max-width:600px)" in page
    assert '<a href="996.html">996</a>' in page and '<a href="index.html">' in page
    assert "x<sup>2</sup> = 4" in page
    assert "![formula]" not in markdown(p, results, figures={})          # no SVG rendered: none referenced


def test_profile_beside_the_claims_on_a_small_family():
    """A one-parameter family (w in (0, 1/4), a 4-point grid): the C^j sets, the largest alpha and the
    sentences for two other claims; the report shows them in the profiles section and beside the claims."""
    from analysis.algebra.symbol import LaurentSymbol
    from analysis.claims.kinds.base import SchemeSpec
    from analysis.claims.kinds.profile import SmoothnessProfile

    w = sp.Symbol("w")
    a = LaurentSymbol.from_mask([w, sp.Rational(1, 2) - w, sp.Rational(1, 2) - w, w], start=-2) * 2
    kind = SmoothnessProfile({"within": "(0, 1/4)", "grid": 4, "samples": 4, "beside": [
        {"claim": "C0", "j": 0, "interval": "(0, 1/16)"}, {"claim": "C1", "j": 1, "interval": "(0, 1/4)"},
        {"claim": "C0w", "j": 0, "interval": "(0, 1/4)"}]}, {"s": SchemeSpec("s", a)}, "x")
    v = kind.evaluate()
    nums = {n.name: n.value for n in v.numbers}
    assert nums["beside C0"] == "inside the C^0 set (understated)"
    assert nums["beside C1"] == "not inside the C^1 set"
    assert nums["beside C0w"] == "is the C^0 set (search window)"
    assert nums["alpha max at"] == sp.Rational(1, 8) and nums["alpha max lower"] == 2
    assert v.profile["compact"][0][:2] == ("C^0", "(0, 1/4)") and v.profile["exceptional"] == [("1/8", 3)]

    claims = [Claim(id="995:C0", kind="smoothness", statement="C^0 on (0, 1/16)", evaluate=_ok),
              Claim(id="995:profile", kind="smoothness profile", statement="profile", title="Profile in w",
                    objects=("toy",), evaluate=lambda: v)]
    p = Paper(id="995", title="Toy", citation="-", claims=claims)
    results = evaluate_paper(p)
    page, md = html(p, results, figures={}), markdown(p, results, figures={})
    assert 'id="profiles"' in page and "Certified profile beside the claim" in page
    assert page.index("Certified profile beside the claim") < page.index('id="claim-995-profile"')
    assert "the paper understates" in page and "profile: certified C<sup>0</sup> set (0, 1/4): inside" in page
    assert "## Certified smoothness profiles" in md and "- beside 995:C1: claim: C^1 for w in (0, 1/4)" in md


def test_beside_names_a_claim_of_the_file(tmp_path):
    from analysis.claims.paperfile import load_paper
    from analysis.result import AnalysisError

    text = ('[paper]\nid = "994"\ntitle = "t"\n[schemes.s]\nmask = ["2*w", "1 - 2*w", "1 - 2*w", "2*w"]\nstart = -2\n'
            '[[claims]]\nid = "P"\nstatement = "p"\nkind = "smoothness profile"\nwithin = "(0, 1/4)"\n'
            'beside = [{ claim = "%s", j = 0, interval = "(0, 1/8)" }]\n'
            '[[claims]]\nid = "C0"\nstatement = "c"\nkind = "smoothness"\nC = 0\nat = { w = "1/8" }\n')
    good = tmp_path / "good.toml"
    good.write_text(text % "C0")
    assert [c.id for c in load_paper(good).claims] == ["994:P", "994:C0"]
    bad = tmp_path / "bad.toml"
    bad.write_text(text % "C9")
    with pytest.raises(AnalysisError, match="beside names the claim 'C9'"):
        load_paper(bad)
