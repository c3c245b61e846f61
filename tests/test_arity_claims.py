"""Issue 12 (second half): m-ary schemes in paper files and claim kinds, the m-ary smoothness profile,
``subdiv range --figure`` for m-ary families, and the one-line error of ``subdiv atlas`` for them.

Expected values are computed here independently of the engine (exact polynomial division by
1+z+z^2, Lagrange interpolation, the support formula) or taken from the literature: the ternary
cubic B-spline is a cubic spline, C^2 and not C^3, so alpha = 3 (de Boor, *A Practical Guide to
Splines*); the m-ary basic limit function of a mask on [s, e] is supported on [s, e]/(m-1)
(Daubechies-Lagarias, SIAM J. Math. Anal. 23 (1992)); the local subdivision matrix of the m-ary
B-spline of degree d has the dominant eigenvalues 1, 1/m, 1/m^2, ... (Dyn-Levin, Acta Numer. 11 (2002)).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from analysis.claims.model import compare_verdicts, evaluate_paper
from analysis.claims.paperfile import parse_paper
from analysis.cli import main
from analysis.cli.report import load_file
from analysis.regularity.holder import smoothness
from analysis.result import AnalysisError

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "ternary-four-point.toml"
EXTRA = ["analysis.cli.report", "analysis.cli.paperfile"]
MU = sp.Symbol("mu")
Z = sp.Symbol("z")


def _mask(mu):
    r = sp.Rational
    a0, a1, a2, a3 = -r(1, 18) - mu / 6, r(13, 18) + mu / 2, r(7, 18) - mu / 2, -r(1, 18) + mu / 6
    return [a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3]          # from index -5 (file and catalogue)


def _factors(coeffs) -> int:
    """Number of factors 1+z+z^2 of sum_i c_i z^i, by sympy's exact polynomial division."""
    P, k = sp.Poly(list(reversed(coeffs)), Z), 0
    while not P.is_zero:
        q, rem = sp.div(P, sp.Poly(1 + Z + Z ** 2, Z))
        if not rem.is_zero:
            break
        P, k = q, k + 1
    return k


def _ternary_lagrange_mask():
    """Cubic Lagrange interpolation at i + r/3 from f_{i-1..i+2} (ternary Dubuc-Deslauriers)."""
    t = sp.Symbol("t")
    nodes = (-1, 0, 1, 2)
    a = {}
    for r in (1, 2):
        for p in nodes:
            w = sp.prod([(t - q) / (p - q) for q in nodes if q != p]).subs(t, sp.Rational(r, 3))
            a[r - 3 * p] = w
    a[0] = 1
    return [a.get(i, 0) for i in range(-5, 6)]


def test_file_mask_is_the_catalogue_mask_and_dd_at_1_27():
    text = EXAMPLE.read_text()
    assert 'arity = 3' in text
    assert _mask(sp.Rational(1, 27)) == _ternary_lagrange_mask()


@pytest.fixture(scope="module")
def example():
    paper = load_file(EXAMPLE)
    return paper, {e.claim.id: e for e in evaluate_paper(paper)}


def test_example_paper_file(example):
    paper, ev = example
    status = {k: e.verdict.status for k, e in ev.items()}
    # independent expectations: 3 factors generically and 4 at mu = 1/27 (exact division below), C^2 on
    # (1/15, 1/9) (checked point-wise below), the 1/27 member is the Lagrange scheme, reproduction of
    # degree 2 only (the Lagrange member reproduces cubics, others not: checked below), support [-5,5]/2
    assert status == {"t4pt:SumRules": "certified", "t4pt:Title": "certified", "t4pt:DD": "certified",
                      "t4pt:R1": "refuted", "t4pt:Support": "certified", "t4pt:BSpline": "certified",
                      "t4pt:BSplineEig": "certified"}
    assert _factors(_mask(sp.Rational(1, 10))) == 3 and _factors(_mask(sp.Rational(1, 27))) == 4
    n = {k: {x.name: x for x in e.verdict.numbers} for k, e in ev.items()}
    assert n["t4pt:SumRules"]["factors"].value == 3
    assert n["t4pt:R1"]["reproduction degree"].value == 2
    assert n["t4pt:BSpline"]["alpha"].value == 3                       # de Boor: cubic spline, C^2 not C^3
    assert n["t4pt:Title"]["C^2 set"].value == "(1/15, 1/9)"
    assert n["t4pt:Support"]["support end"].value == sp.Rational(5, 2)  # [s, e]/(m - 1) = [-5, 5]/2
    # the catalogue entry's arity is used for a scheme given by catalogue name
    spec = next(c for c in paper.claims if c.id == "t4pt:BSpline")
    assert "arity 3" in paper.notes and spec.objects == ("ternary-cubic-bspline",)


def test_example_matches_its_golden_file(example, tmp_path):
    from analysis.claims.model import verdicts_json

    paper, ev = example
    fresh = verdicts_json({paper.id: list(ev.values())}, titles={paper.id: paper.title})
    golden = json.loads(EXAMPLE.with_name("ternary-four-point.verdicts.json").read_text())
    assert compare_verdicts(golden, fresh) == []


def test_c2_range_boundaries_pointwise():
    """Both ends of the C^2 set (1/15, 1/9) by the point-wise m-ary verdict (another route than the sets)."""
    def c2(mu):
        from analysis.algebra.symbol import LaurentSymbol

        return smoothness(LaurentSymbol.from_mask(_mask(mu), start=-5), 2, arity=3).value
    e = sp.Rational(1, 1000)
    assert [c2(sp.Rational(1, 15) - e), c2(sp.Rational(1, 15) + e), c2(sp.Rational(1, 9) - e),
            c2(sp.Rational(1, 9) + e)] == [False, True, True, False]


TEMPLATE = '''
[paper]
id = "902"
title = "m-ary"
[schemes.t]
mask = {mask}
start = -5
arity = {arity}
parameters = {{ mu = "(-1/5, 1/3)" }}
[[claims]]
id = "C1"
statement = "s"
kind = "{kind}"
{fields}
'''


def _paper(kind, fields, arity=3, mask=None):
    mask = mask or json.dumps([str(c) for c in _mask(MU)])
    return parse_paper(TEMPLATE.format(mask=mask, arity=arity, kind=kind, fields=fields), "m.toml")


def test_binary_kinds_refuse_mary_schemes_at_load_time():
    # every stationary kind is m-ary since the m-ary Sobolev exponent (tests/test_sobolev_arity.py): the
    # sobolev claim is now evaluated (s_2 = 2.2105... at mu = 1/27, between alpha = 1.817... and alpha + 1/2)
    v = evaluate_paper(_paper("sobolev", 'at = { mu = "1/27" }\nlower = 2\nupper = 3'))[0].verdict
    assert v.status == "certified"
    v = evaluate_paper(_paper("sobolev", 'at = { mu = "1/27" }\nlower = "9/4"'))[0].verdict
    assert v.status == "refuted"
    with pytest.raises(AnalysisError, match="arity must be an integer >= 2"):
        _paper("sum rules", "factors = 3", arity=1)
    # even/odd rules are binary; a ternary scheme's printed rules are three stencils
    with pytest.raises(AnalysisError, match="printed rules have 2 stencils, but scheme .* has arity 3"):
        _paper("mask identity", 'rules = { even = [1], odd = ["1/2", "1/2"] }')


def test_catalogue_arity_conflict_and_rules_with_arity(tmp_path, capsys):
    text = ('[paper]\nid = "903"\ntitle = "t"\n[schemes.b]\ncatalogue = "ternary-bspline-2"\narity = 2\n'
            '[[claims]]\nid = "C"\nstatement = "s"\nkind = "sum rules"\nfactors = 3\n')
    f = tmp_path / "p.toml"
    f.write_text(text)
    assert main(["report", str(f), "--output", str(tmp_path)], extra_modules=EXTRA) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "has arity 3, not 2" in err
    with pytest.raises(AnalysisError, match="arity 3 needs 3 stencils"):
        parse_paper('[paper]\nid = "9"\ntitle = "t"\n[schemes.r]\nrules = { even = [1], odd = ["1/2", "1/2"] }\n'
                    'arity = 3\n', "r.toml")


def test_arity_2_is_the_binary_default():
    """An explicit arity = 2 changes nothing (same verdict and summary as without it)."""
    four = '["-w", 0, "1/2+w", 1, "1/2+w", 0, "-w"]'
    base = ('[paper]\nid = "904"\ntitle = "t"\n[schemes.f]\nmask = ' + four + '\nstart = -3\nAR'
            'parameters = { w = "(0, 1/4)" }\n[[claims]]\nid = "C"\nstatement = "s"\nkind = "norm test"\n'
            'j = 1\nL = 2\ninterval = "(0, 1/8)"\n')
    v = [evaluate_paper(parse_paper(base.replace("AR", x), "b.toml"))[0].verdict for x in ("", "arity = 2\n")]
    assert v[0].status == v[1].status == "certified" and v[0].summary == v[1].summary
    assert "1/2 S_(a_2)" in v[1].evidence[0].title


def test_mary_ck_range_and_norm_test_refuted_with_counterexample():
    v = evaluate_paper(_paper("ck range", 'j = 2\ninterval = "(0, 1/9)"'))[0].verdict
    assert v.status == "refuted"
    q = next(x.value for x in v.numbers if x.name == "counterexample")
    assert 0 < q <= sp.Rational(1, 15)
    from analysis.algebra.symbol import LaurentSymbol

    assert smoothness(LaurentSymbol.from_mask(_mask(q), start=-5), 2, arity=3).value is False
    w = evaluate_paper(_paper("norm test", 'j = 2\nL = 1\ninterval = "(1/15, 1/9)"'))[0].verdict
    assert w.status == "certified" and "1/3 S_(a_3)" in w.evidence[0].title


def test_mary_smoothness_profile_refutes_a_wrong_range():
    v = evaluate_paper(_paper("smoothness profile", 'within = "(0, 1/5)"\nclaimed = { j = 2, interval = "(1/15, 1/5)" }\n'
                                                    'samples = 1\nmax_j = 2'))[0].verdict
    assert v.status == "refuted"
    assert "C^2 exactly on (1/15, 1/9)" in v.corrected


def test_range_figure_mary(tmp_path, capsys):
    fig = tmp_path / "a.png"
    assert main(["range", "--scheme", "ternary-four-point", "--C", "2", "--within=0,1/5", "--grid", "2",
                 "--figure", str(fig)]) == 0
    out = capsys.readouterr().out
    assert fig.stat().st_size > 1000 and "alpha at 9 points" in out


FAMILY = "(1+z+z**2)**2/(3*z**2)*(1 + s*(z-2+1/z) + t*(z**2-2+z**-2))"


def test_atlas_mary(tmp_path, capsys):
    """A two-parameter ternary family through the ternary linear B-spline (s = t = 0: the hat function,
    alpha = 1 exactly) and the ternary cubic B-spline (s = 2/9, t = 1/9: (1+z+z^2)^4/(27 z^4), a cubic
    spline, alpha = 3: de Boor); more factors 1+z+z^2 exactly on s + t = 1/3 (checked by division)."""
    s_, t_ = sp.symbols("s t")
    expr = sp.expand((1 + Z + Z**2) ** 2 * (Z**2 + s_ * (Z**3 - 2 * Z**2 + Z) + t_ * (Z**4 - 2 * Z**2 + 1)))
    rem = sp.rem(sp.Poly(expr, Z), sp.Poly((1 + Z + Z**2) ** 3, Z))
    assert all(sp.simplify(c.subs(s_, sp.Rational(1, 3) - t_)) == 0 for c in rem.all_coeffs())
    assert sp.expand(expr.subs({s_: sp.Rational(2, 9), t_: sp.Rational(1, 9)}) * 9 - (1 + Z + Z**2) ** 4) == 0
    fig = tmp_path / "atlas.png"
    assert main(["atlas", "--symbol", FAMILY, "--arity", "3", "--x", "s=0:1/3:4", "--y", "t=0:1/9:3", "--j", "1,2",
                 "--executor", "serial", "--no-progress", "--json", "--figure", str(fig)]) == 0
    d = json.loads(capsys.readouterr().out)
    pts = {(sp.Rational(x["p1"]["exact"] if isinstance(x["p1"], dict) else x["p1"]),
            sp.Rational(x["p2"]["exact"] if isinstance(x["p2"], dict) else x["p2"])): x for x in d["value"]}
    lin, cub = pts[(0, 0)], pts[(sp.Rational(2, 9), sp.Rational(1, 9))]
    assert (lin["C^1"], lin["C^2"], cub["C^1"], cub["C^2"]) == (False, False, True, True)
    assert (sp.Rational(str(lin["alpha"])), sp.Rational(str(cub["alpha"]))) == (1, 3)
    assert cub["exceptional"] and fig.stat().st_size > 1000
    assert main(["atlas", "--scheme", "ternary-four-point", "--x", "mu=0:1/9:2", "--y", "mu=0:1/9:2"]) == 2
    assert "different parameters" in capsys.readouterr().err


def test_mary_kinds_list_matches_the_classes():
    from analysis.claims.kinds import KIND_CLASSES
    from analysis.claims.kinds.base import ANY_ARITY_KINDS as MARY_KINDS
    from analysis.claims.template import template

    assert sorted(n for n, c in KIND_CLASSES.items() if c.any_arity) == sorted(MARY_KINDS)
    assert all(k in " ".join(template().split()) for k in MARY_KINDS)
