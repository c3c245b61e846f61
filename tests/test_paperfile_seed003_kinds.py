"""Issue 11, seeds 003 and 000 as data: the lemma kinds (inequality with parts, dilation cover,
cancellation, corrections and asymptotics; identity, with integer ranges; factorization), the
"all of" and "curve comparison" kinds, and paper files naming level-dependent catalogue entries.
Every expected value is recomputed independently here (series, float refinement, integer
arithmetic), and each test can fail."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from analysis.algebra.symbol import LaurentSymbol
from analysis.claims.kinds import KIND_CLASSES, SchemeSpec
from analysis.claims.model import evaluate_claim
from analysis.claims.paperfile import parse_paper
from analysis.levels.level_dependent import H, LevelDependentScheme
from analysis.result import AnalysisError

W = sp.Symbol("w")
FOUR = LaurentSymbol.from_mask([-W, 0, sp.Rational(1, 2) + W, 1, sp.Rational(1, 2) + W, 0, -W], start=-3)
T = sp.Symbol("t", positive=True)
_V = sp.cos(T * H / 2)
TRIG_CHAIKIN = LevelDependentScheme((1 / (2 * (1 + _V)), (2 * _V + 1) / (2 * (1 + _V)), (2 * _V + 1) / (2 * (1 + _V)),
                                     1 / (2 * (1 + _V))), -2, (T,))
Q = sp.Rational(1, 4)
CHAIKIN = LevelDependentScheme((Q, 3 * Q, 3 * Q, Q), -2)
S = {"4pt": SchemeSpec("4pt", FOUR), "trig": SchemeSpec("trig", None, level=TRIG_CHAIKIN),
     "chaikin": SchemeSpec("chaikin", None, level=CHAIKIN)}


def run(kind, **fields):
    return KIND_CLASSES[kind](fields, S, "t").evaluate()


# ------------------------------------------------------------------------------------ inequality
def test_dilation_cover_reaches_small_parameters():
    """sin(x) <= x holds for x > 0; x^2 <= x only for x <= 1: with x = alpha/2^n, alpha in (0, 2),
    the cover alpha in [1, 2] x n >= 0 must find the counterexample (alpha > 1 at n = 0)."""
    where, box = {"x": "alpha/2**n"}, {"alpha": "(0, 2)"}
    ok = run("inequality", where=where, box=box, dilation="alpha", parts=[{"lhs": "sin(x)", "rhs": "x"}])
    assert ok.status == "certified"
    bad = run("inequality", where=where, box=box, dilation="alpha", parts=[{"label": "square", "lhs": "x**2", "rhs": "x"}])
    assert bad.status == "refuted"
    n = {x.name: x.value for x in bad.numbers}["square.counterexample_n"]
    pt = bad.evidence[0].result.witness["counterexample"]["point"]["alpha"]
    x = float(sp.sympify(pt)) / 2 ** n          # independent: the counterexample violates x^2 <= x
    assert x ** 2 > x


def test_dilation_needs_invariance():
    """(alpha/2^n)^2 is a function of alpha/2^n; alpha^2/2^n is not: refused."""
    with pytest.raises(AnalysisError, match="through alpha/2\\^n only"):
        run("inequality", box={"alpha": "(0, 1)"}, dilation="alpha", parts=[{"lhs": "alpha**2/2**n", "rhs": "1"}])
    assert run("inequality", box={"alpha": "(0, 1)"}, dilation="alpha",
               parts=[{"lhs": "(alpha/2**n)**2", "rhs": "1"}]).status == "certified"


def test_cancelled_parameter_and_correction():
    """9 w cancels from both sides; the printed bound (cosh) is false, the corrected one (cos) is true."""
    v = run("inequality", where={"x": "alpha/2**n", "b": "sin(x/4)/sin(x) + 3*w"}, n0=1,
            box={"alpha": "(0, pi/3)", "w": "(0, 1/50)"}, dilation="alpha",
            parts=[{"label": "upper", "lhs": "b", "rhs": "1/(4*cosh(x)) + 3*w"}],
            corrected={"statement": "with cos", "lhs": "b", "rhs": "1/(4*cos(x)) + 3*w"})
    assert v.status == "refuted" and v.corrected == "with cos (certified)"
    assert "w cancels exactly" in v.evidence[0].text
    x = 0.3                                   # independent point check of both readings
    b = math.sin(x / 4) / math.sin(x)
    assert b > 1 / (4 * math.cosh(x)) and b <= 1 / (4 * math.cos(x))


def test_asymptotic_constant_is_the_series_coefficient():
    v = run("inequality", where={"x": "alpha/2**n"}, box={"alpha": "(0, pi/3)"}, dilation="alpha",
            parts=[{"lhs": "Abs(sin(3*x/4)/sin(x) - 3/4)", "rhs": "3*x**2/(8*cos(x))"}],
            asymptotics={"of": "sin(3*x/4)/sin(x) - 3/4", "order": 2, "over": "alpha**2", "name": "c"})
    y = sp.Symbol("y")
    c = sp.series(sp.sin(3 * y / 4) / sp.sin(y), y, 0, 4).removeO().coeff(y, 2)
    assert v.status == "certified" and {n.name: n.value for n in v.numbers}["c"] == c == sp.Rational(7, 128)


def test_plain_inequality_unchanged():
    v = run("inequality", lhs="sin(2**(-n))", rhs="2**(-n)")
    assert v.status == "certified" and [n.name for n in v.numbers] == ["proven"]


# ------------------------------------------------------------------------------------ identity
def test_identity_over_integers_matches_math_ceil():
    v = run("identity", lhs="ceiling((d - 2)/2)", rhs="floor((d - 2)/2) + 1", integers={"d": "[3, 10]"})
    first = next(d for d in range(3, 11) if math.ceil((d - 2) / 2) != math.floor((d - 2) / 2) + 1)
    assert v.status == "refuted" and {n.name: n.value for n in v.numbers}["first counterexample d"] == first
    ok = run("identity", lhs="ceiling((d - 2)/2)", rhs="floor((d - 1)/2)", integers={"d": "[3, 10]"})
    assert ok.status == "certified"


def test_identity_with_scheme_coefficients():
    assert run("identity", scheme="4pt", lhs="a(-3) + a(-1) + a(1) + a(3)", rhs="1").status == "certified"
    v = run("identity", scheme="4pt", lhs="a(3)", rhs="w")
    assert v.status == "refuted" and v.evidence[0].result.provenance["method"] == "acb ball evaluation at a rational point"


def test_identity_at_parameter_values_in_their_domain():
    from analysis.claims.kinds import Domain

    dom = {"4pt": SchemeSpec("4pt", FOUR, {"w": Domain.parse("(-1/4, pi/12)")})}
    run_ = lambda **f: KIND_CLASSES["identity"]({"scheme": "4pt", **f}, dom, "t").evaluate()  # noqa: E731
    assert run_(lhs="a(3)", rhs="-1/16", at={"w": "1/16"}).status == "certified"
    v = run_(lhs="a(3)", rhs="-1/16", at={"w": "pi/16"})          # pi/16 < pi/12: inside; -pi/16 != -1/16
    assert v.status == "refuted" and "w = pi/16" in v.summary
    with pytest.raises(AnalysisError, match="outside its domain"):
        run_(lhs="a(3)", rhs="-1/16", at={"w": "pi/12"})


def test_factorization_against_polynomial_division():
    z = sp.Symbol("z")
    q, r = sp.div(sp.expand(FOUR.expr() * z ** 3), ((1 + z) / 2) ** 2, z)
    assert r == 0
    cof = sp.sstr(sp.expand(q / z ** 3))
    assert run("factorization", scheme="4pt", factor="((1+z)/2)**2", cofactor=cof).status == "certified"
    assert run("factorization", scheme="4pt", factor="((1+z)/2)**2", cofactor=cof + " + w").status == "refuted"


# ------------------------------------------------------------------------------------ all of, curves
def test_all_of_combines_statuses():
    sr = {"kind": "sum rules", "scheme": "4pt", "factors": 2}
    sym = {"kind": "symmetry", "scheme": "4pt", "label": "sym"}
    assert run("all of", parts=[sr, sym]).status == "certified"
    v = run("all of", parts=[sr, {**sym, "symmetric": False}])
    assert v.status == "refuted" and v.corrected.startswith("sym: ")
    with pytest.raises(AnalysisError, match="unknown kind"):
        run("all of", parts=[{"kind": "sum rule", "scheme": "4pt"}])


def test_curve_comparison_against_independent_refinement():
    v = run("curve comparison", compare=[{"scheme": "trig", "label": "trig"}, {"scheme": "chaikin", "label": "C"}],
            curves=["circle"], best="C", at={"t": "2*pi/8"}, points=8, steps=5)
    assert v.status == "numerical" and v.summary.startswith("Not as a general statement")
    nums = {n.name: n.value for n in v.numbers}
    P = np.stack([np.cos(2 * np.pi * np.arange(8) / 8), np.sin(2 * np.pi * np.arange(8) / 8)], -1)
    for _ in range(5):                        # Chaikin's corner cutting on a closed polygon
        Pn = np.roll(P, -1, axis=0)
        P = np.stack([0.75 * P + 0.25 * Pn, 0.25 * P + 0.75 * Pn], 1).reshape(-1, 2)
    r = np.linalg.norm(P, axis=1)
    assert abs(nums["circle.C.None=None"] - float(np.max(np.abs(r - r.mean())) / r.mean())) < 1e-12
    assert nums["circle.trig.None=None"] < 1e-12      # the trigonometric form generates circles


# ------------------------------------------------------------------------------------ paper files
def test_paper_file_with_level_dependent_catalogue_entry():
    from papers import catalogue

    text = ('[paper]\nid = "t"\ntitle = "t"\n[schemes.f2]\ncatalogue = "seed003-trigonometric"\n'
            '[[claims]]\nid = "L"\nstatement = "s"\nkind = "identity"\nscheme = "f2"\nlhs = "a(2)"\nrhs = "-7*omega"\n')
    p = parse_paper(text, "t.toml", catalogue=catalogue)
    assert evaluate_claim(p.claims[0]).verdict.status == "certified"
    with pytest.raises(AnalysisError, match="unknown name 'omgea'"):
        parse_paper(text.replace('rhs = "-7*omega"', 'rhs = "-7*omgea"'), "t.toml", catalogue=catalogue)
    with pytest.raises(AnalysisError, match="unknown scheme 'seed003-trig'"):
        parse_paper(text.replace('"seed003-trigonometric"', '"seed003-trig"'), "t.toml", catalogue=catalogue)


def test_seed_003_and_000_python_is_mostly_gone():
    from pathlib import Path

    root = Path(__file__).resolve().parents[1] / "papers"
    lines = {s: sum(len(f.read_text(encoding="utf-8").splitlines()) for f in (root / s).glob("*.py"))
             for s in ("seed003", "seed000")}
    assert lines["seed003"] <= 600 and lines["seed000"] <= 210       # 1,098 and 247 lines before issue 11's 2nd half
