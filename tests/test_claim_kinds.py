"""Issue 11, item 2: the library of claim kinds. Every expected value is from the literature
(cited) or computed independently here; each kind is tested with a true and a false claim."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.algebra.symbol import LaurentSymbol
from analysis.claims.kinds import KIND_CLASSES, Domain, SchemeSpec, kind_class
from analysis.claims.model import evaluate_claim, Claim
from analysis.result import AnalysisError

W = sp.Symbol("w")
# Dyn, Levin, Gregory, CAGD 4 (1987): f[2i] = f[i], f[2i+1] = -w f[i-1] + (1/2+w)(f[i]+f[i+1]) - w f[i+2]
FOUR = LaurentSymbol.from_mask([-W, 0, sp.Rational(1, 2) + W, 1, sp.Rational(1, 2) + W, 0, -W], start=-3)
CHAIKIN = LaurentSymbol.from_expr("(1+z)**3/(4*z**2)")          # Chaikin (1974): ((1+z)/2)^3 * 2 / z^2
S = {"4pt": SchemeSpec("4pt", FOUR, {"w": Domain.parse("(-1/4, 1/4)")}), "chaikin": SchemeSpec("chaikin", CHAIKIN)}


def run(kind, **fields):
    return kind_class(kind)(fields, S, "t").evaluate()


def test_mask_identity_printed_rules_and_a_typo():
    # the DLG rules at w = 1/16 are the Deslauriers-Dubuc mask (-1, 0, 9, 16, 9, 0, -1)/16
    assert run("mask identity", scheme="4pt", at={"w": "1/16"}, mask=["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"],
               start=-3).status == "certified"
    v = run("mask identity", scheme="4pt", at={"w": "1/16"}, mask=["-1/16", 0, "9/16", 1, "8/16", 0, "-1/16"], start=-3)
    assert v.status == "refuted" and "a_1" in v.summary and "9/16" in v.corrected
    assert run("mask identity", scheme="4pt", rules={"even": [1], "even_first": 0, "odd": ["-w", "1/2+w", "1/2+w", "-w"],
                                                     "odd_first": -1}).status == "certified"


def test_sum_rules_generic_and_exceptional():
    # (1+z)^2 | a for every w and (1+z)^4 | a at w = 1/16 (Deslauriers-Dubuc cubic reproduction)
    assert run("sum rules", scheme="4pt", factors=2, exceptional=[{"at": {"w": "1/16"}, "factors": 4}]).status == "certified"
    v = run("sum rules", scheme="chaikin", factors=4)
    assert v.status == "refuted" and "((1+z)/2)^3" in v.corrected
    v = run("sum rules", scheme="4pt", factors=2, exceptional=[{"at": {"w": "1/8"}, "factors": 4}])
    assert v.status == "refuted" and "w = 1/8: k = 2" in v.summary


def test_symmetry_support_and_eigenvalues():
    assert run("symmetry", scheme="chaikin", centre="-1/2").status == "certified"      # dual: centre -1/2
    assert run("symmetry", scheme="chaikin", centre="0").status == "refuted"
    # the basic limit function of Chaikin (quadratic B-spline) has support of width 3: [-2, 1] here
    assert run("support", scheme="chaikin", of="limit function", support=[-2, 1]).status == "certified"
    assert run("support", scheme="4pt", of="limit function, centred", support=[-3, 3]).status == "certified"
    assert run("support", scheme="4pt", support=[-2, 2]).status == "refuted"
    # Deslauriers-Dubuc 4-point: local subdivision matrix spectrum 1, 1/2, 1/4, 1/4, 1/8 (Dyn-Levin 2002, Sect. 4)
    assert run("eigenvalues", scheme="4pt", at={"w": "1/16"}, eigenvalues=[1, "1/2", "1/4", "1/4", "1/8"],
               complete=True).status == "certified"
    v = run("eigenvalues", scheme="4pt", at={"w": "1/16"}, eigenvalues=[1, "1/2", "1/3"])
    assert v.status == "refuted" and "1/3" in v.summary


def test_reproduction_degrees():
    # DLG reproduces linear polynomials for every w, cubics at w = 1/16 (Deslauriers-Dubuc 1989)
    assert run("reproduction", scheme="4pt", at={"w": "1/16"}, generation=3, reproduction=3).status == "certified"
    v = run("reproduction", scheme="4pt", reproduction=3)
    assert v.status == "refuted" and "degree is 1" in v.summary


def test_norm_test_and_ck_range():
    # DLG (1987), Thm 3: the norm test proves C^1 exactly for 0 < w < (sqrt(5)-1)/8
    v = run("norm test", scheme="4pt", j=1, L=2, interval="(0, (sqrt(5)-1)/8)")
    assert v.status == "certified" and v.numbers[0].value == "(0, -1/8 + sqrt(5)/8)"
    assert run("norm test", scheme="4pt", j=1, L=2, interval="(0, 1/6)").status == "refuted"   # 1/6 > 0.1545
    assert run("ck range", scheme="4pt", j=1, interval="(0, 1/8)").status == "certified"
    # not C^1 beyond w* = 0.19273 (root of 32 w^3 + 4 w - 1; Hechler, Moessner, Reif, LAA 430 (2009))
    v = run("ck range", scheme="4pt", j=1, interval="(0, 1/4)")
    assert v.status == "refuted" and sp.Rational(v.numbers[0].value) > sp.Rational(19273, 100000)


def test_holder_and_sobolev_enclosures():
    # Deslauriers-Dubuc 4-point: alpha = 2 (Dubuc 1986; Daubechies-Lagarias 1992), s_2 = 2.44076 (Eirola 1992)
    assert run("holder", scheme="4pt", at={"w": "1/16"}, value=2).status == "certified"
    assert run("holder", scheme="4pt", at={"w": "1/16"}, lower="2.5").status == "refuted"
    v = run("sobolev", scheme="4pt", at={"w": "1/16"}, value="2.44077", tolerance="0.0001")
    assert v.status == "certified" and abs(v.numbers[0].float - 2.44077) < 1e-4
    assert run("sobolev", scheme="4pt", at={"w": "1/16"}, upper="2.4").status == "refuted"
    # an enclosure that merely straddles the claim proves nothing
    assert run("holder", scheme="4pt", at={"w": "1/32"}, value="1.2284", tolerance="0.00001").status == "refuted"


def test_inequality_cited_python():
    assert run("inequality", lhs="sin(2**(-n))", rhs="2**(-n)").status == "certified"            # sin x <= x
    assert run("inequality", lhs="2**(-n)", rhs="sin(2**(-n))", n0=1, strict=True).status == "refuted"
    v = run("cited", source="[3]", settle="the proof in [3]")
    assert v.status == "inconclusive" and v.settle == "the proof in [3]"
    fields = dict(evaluator="analysis.claims.model:inconclusive", args=["a bespoke evaluator", "its own test"])
    v = kind_class("python")(fields, S, "t", python="allowed").evaluate()
    assert (v.status, v.summary, v.settle) == ("inconclusive", "a bespoke evaluator", "its own test")
    v = run("python", **fields)                  # a paper file's code runs only when allowed
    assert v.status == "inconclusive" and v.summary.startswith("not run") and "--allow-python" in v.settle


def test_level_dependent_kinds():
    import schemes.level_dependent as ld

    s = ld.get("exp-chaikin-hyp")
    T = {"e": SchemeSpec("e", None, {"t": Domain.parse("(0, oo)")}, level=s)}
    k = lambda kind, **f: kind_class(kind)(f, T, "t").evaluate()                                       # noqa: E731
    # exponential B-splines generate {1, e^(tx), e^(-tx)} (Dyn-Levin 1995; Romani 2009), not e^(2tx)
    assert k("exponential reproduction", lambdas=["0", "t", "-t"], at={"t": 1}).status == "certified"
    assert k("exponential reproduction", lambdas=["2*t"], at={"t": 1}).status == "refuted"
    # ||a^n - a|| = O(4^-n): the m = 0 series converges (asymptotic equivalence), m = 2 diverges
    assert k("asymptotic equivalence", converges=True, at={"t": 1}).status == "certified"
    assert k("weighted series", converges=True, m=2, at={"t": 1}).status == "refuted"


def test_a_failing_evaluation_is_inconclusive_and_named():
    kind = kind_class("holder")({"scheme": "4pt", "lower": 1}, S, "t")       # w left free
    ev = evaluate_claim(Claim(id="9:x", kind="holder", statement="s", evaluate=kind.evaluate))
    assert ev.verdict.status == "inconclusive" and "fix every parameter" in ev.error


@pytest.mark.parametrize("name", sorted(KIND_CLASSES))
def test_every_kind_documents_its_fields(name):
    cls = KIND_CLASSES[name]
    assert cls.summary and cls.example and cls.__doc__
    with pytest.raises(AnalysisError, match="unknown field 'nonsense'"):
        cls({"nonsense": 1, **({"scheme": "4pt"} if cls.uses_scheme else {})}, S, "t")


def test_which_set_a_printed_interval_is():
    from analysis.claims.kinds.profile import which_set
    from analysis.result import Result

    w1 = sp.sqrt(5) / 8 - sp.Rational(1, 8)
    c1 = Result(value=[{"left": {"exact": 0}, "right": {"bracket": (sp.Rational(1, 5), sp.Rational(21, 100)),
                                                         "certified_C^j_at": sp.Rational(1, 5)}}], status="certified")
    c0 = Result(value=[{"left": {"open_end": -1}, "right": {"open_end": 1}}], status="certified")
    sets = {0: c0, 1: c1}
    assert which_set(sets, 0, sp.Rational(41, 200))[1] == "the C^1 set"             # inside the bracket
    assert which_set(sets, 0, w1)[1] == "inside the C^1 set"                         # 0.1545 < 1/5: not sharp
    assert which_set(sets, -1, 1)[1] == "the C^j set for j in [0] (search window)"
    assert which_set(sets, 0, 2)[1] == "none"
