"""Issue 14: the certified interior of one-parameter C^j sets (exact parametric norm tests).

Reference values are computed independently (exact numeric norms at rational points with
``difference_norm`` / ``difference_norm``, certified Hölder verdicts with ``smoothness``) or
published: the 4-point scheme with tension w is C^1 for 0 < w < (sqrt(5) - 1)/8 (Dyn, Gregory,
Levin 1987, a sufficient condition) and its exact C^1 range is (0, w*), w* ~ 0.19273 (Hechler,
Mößner, Reif, *C1-continuity of the generalized four-point scheme*, Linear Algebra Appl. 430 (2009)).
"""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy as sp

from analysis.algebra.algebraic import RealAlgebraic
from analysis.algebra.derive import derive_mask
from analysis.algebra.symbol import LaurentSymbol
from analysis.regularity.holder import smoothness
from analysis.regularity.interior import ck_interior
from analysis.stationary.difference import difference_norm, difference_symbol
from analysis.stationary.normbox import ParametricNorm

W = sp.Symbol("w")
FOUR_POINT = LaurentSymbol.from_mask([-W, 0, W + sp.Rational(1, 2), 1, W + sp.Rational(1, 2), 0, -W], start=-3)


@pytest.fixture(scope="module")
def six_point():
    return derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=3).value


@pytest.mark.parametrize("L", [1, 3, 5], ids=lambda L: f"L{L}")
@pytest.mark.parametrize("q", ["1/16", "-1/40", "3/25"], ids=lambda q: f"w={q}")
def test_point_box_is_the_exact_norm(L, q):
    """On a one-point box the Bernstein bound is the norm itself (vs the numeric exact norm)."""
    q = sp.Rational(q)
    N = ParametricNorm(difference_symbol(FOUR_POINT, 2), W, L)
    ref = difference_norm(FOUR_POINT.subs({W: q}), 2, L).value
    b = N.box_bound(q, q)
    assert sp.Rational(b.numerator, b.denominator) == ref


def test_ternary_point_box_is_the_exact_norm():
    """m-ary: the ternary interpolatory 4-point family, first differences, L = 2."""
    a = derive_mask(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=2).value
    t = a.params[0]
    q = sp.Rational(-1, 30)
    N = ParametricNorm(difference_symbol(a, 2, arity=3), t, 2, arity=3)
    ref = difference_norm(a.subs({t: q}), 2, 2, arity=3).value
    b = N.box_bound(q, q)
    assert sp.Rational(b.numerator, b.denominator) == ref


@pytest.mark.parametrize("box", [("0", "1/10"), ("1/20", "1/8"), ("-1/16", "1/32")], ids=str)
def test_box_bound_dominates_the_norm_inside(box):
    u, v = (sp.Rational(x) for x in box)
    N = ParametricNorm(difference_symbol(FOUR_POINT, 2), W, 4)
    b = N.box_bound(u, v)
    for k in range(9):
        q = u + (v - u) * sp.Rational(k, 8)
        assert difference_norm(FOUR_POINT.subs({W: q}), 2, 4).value <= sp.Rational(b.numerator, b.denominator)


def test_four_point_C1_up_to_the_open_end_zero():
    """(0, 1/8]: the end w = 0 (the linear scheme, not C^1) is reached by the exact end test."""
    r = ck_interior(FOUR_POINT, 1, 0, sp.Rational(1, 8), hi_open=False, L_max=6)
    assert r.status == "certified"
    assert str(r.value["certified"]) == "(0, 1/8]"
    ends = [pc for pc in r.witness["pieces"] if pc["kind"] == "left-end"]
    assert len(ends) == 1


def test_four_point_beyond_the_published_C1_range_is_not_certified():
    """Past w* ~ 0.19273 the scheme is not C^1: the cover must stop before it, and it does go
    past the classical sufficient bound (sqrt(5) - 1)/8 ~ 0.1545."""
    r = ck_interior(FOUR_POINT, 1, sp.Rational(1, 10), sp.Rational(1, 4), lo_open=False, hi_open=False,
                    L_max=8, budget=20000)
    assert r.status == "inconclusive"
    (lo, hi, _, _), = r.value["certified"].parts
    assert lo.compare(RealAlgebraic.rational(sp.Rational(1, 10))) == 0
    assert hi.compare(RealAlgebraic.rational(sp.Rational(19273, 100000))) < 0
    assert hi.compare(RealAlgebraic.from_expr((sp.sqrt(5) - 1) / 8)) > 0
    assert smoothness(FOUR_POINT.subs({W: sp.Rational(1, 5)}), 1).value is False


def test_end_piece_refuses_the_wrong_side(six_point):
    """At t1 = 0 the C^2 norm touches 1; to the left of 0 the family is not C^2: no certificate."""
    t = six_point.params[0]
    N = ParametricNorm(difference_symbol(six_point, 3), t, 3)
    zero = RealAlgebraic.rational(0)
    assert N.end_piece(zero, sp.Rational(1, 128), +1) is not None
    assert N.end_piece(zero, sp.Rational(-1, 128), -1) is None
    assert smoothness(six_point.subs({t: sp.Rational(-1, 256)}), 2).value is False


@pytest.mark.slow
def test_six_point_C2_interior(six_point):
    """Acceptance family, C^2 = (0, t*): the open end 0 is reached, a thin strip remains at t*."""
    t = six_point.params[0]
    star = sp.CRootOf(524288 * t**5 - 65536 * t**4 + 12800 * t**3 - 352 * t**2 + 61 * t - 3, 0)
    r = ck_interior(six_point, 2, 0, star, L_max=12, close_strips=False)   # the norm tests alone
    parts = r.value["certified"].parts
    assert len(parts) == 1 and parts[0][0].compare(RealAlgebraic.rational(0)) == 0 and not parts[0][2]
    (x, y), = r.value["strips"]
    assert y == star and 0 < float(y - x) < 3e-3
    # the strip's inner end is certified C^2 by an independent route (Hölder exponent)
    assert smoothness(six_point.subs({t: x}), 2).value is True


def test_bad_input():
    from analysis.result import AnalysisError

    with pytest.raises(AnalysisError):
        ck_interior(FOUR_POINT, 1, sp.Rational(1, 8), 0)
    two = LaurentSymbol.from_mask([W, sp.Symbol("v"), 1], start=0)
    with pytest.raises(AnalysisError):
        ck_interior(two, 0, 0, 1)
    assert Fraction(0) == ParametricNorm(difference_symbol(FOUR_POINT, 2), W, 2).box_bound(0, 0) * 0


# ------------------------------------------------------------------ m-ary ranges, family files, CLI
@pytest.mark.slow
def test_ternary_c1_range_grows_beyond_the_norm_sets():
    """The ternary 4-point family: the parametric tests certify C^1 beyond the L <= 2 norm sets
    (down to < -0.17), the undecided part stays inside (-1/5, -4/45) (not C^1 from the eigenvalue
    side at -1/5), and a point they certify is C^1 by the independent JSR verdict."""
    import schemes
    from analysis.regularity.ranges import ck_range
    from analysis.regularity.holder import smoothness

    a = schemes.get("ternary-four-point").symbol
    r = ck_range(a, 1, "mu", Ls=(1, 2), arity=3)
    assert r.witness["interior_tests"]
    assert r.value.inf < sp.Rational(-17, 100)
    U = r.witness["undecided"]
    assert U.is_subset(sp.Interval(sp.Rational(-1, 5), sp.Rational(-4, 45)))
    q = sp.Rational(-17, 100)
    assert r.value.contains(q) is sp.true
    assert smoothness(a.subs({sp.Symbol("mu"): q}), 1, arity=3).value is True


def _run(capfd, *argv):
    from tests.cli_run import run_cli

    return run_cli(capfd, *argv)


def test_family_file_round_trip(tmp_path, capfd):
    from analysis.cli.family import read_family

    f = tmp_path / "fam.json"
    out = _run(capfd, "derive", "--support", "7", "--interpolatory", "--symmetric", "primal", "--reproduce", "1",
               "--output", str(f))
    assert out.returncode == 0 and "family written to" in out.stdout
    doc = read_family(str(f))
    assert doc["arity"] == 2 and doc["start"] == -3 and doc["parameters"] == ["t1"]
    mask = LaurentSymbol.from_mask(doc["mask"], start=doc["start"])
    t = mask.params[0]
    assert mask == FOUR_POINT.subs({W: -t})            # t1 = -w (the tension family)
    r = _run(capfd, "range", "--family", str(f), "--C", "1", "--within=-1/8,0", "--grid", "4", "--json")
    assert r.returncode == 0, r.stderr
    import json

    d = json.loads(r.stdout)
    assert d["result"]["status"] == "certified"


@pytest.mark.parametrize("content,msg", [
    (None, "cannot read the family file"),
    ("{", "invalid JSON"),
    ('{"format": "other"}', "is not a family file"),
    ('{"format": "subdiv-family", "arity": 2, "start": 0, "mask": []}', "non-empty list"),
    ('{"format": "subdiv-family", "arity": 2, "start": "0", "mask": ["1"]}', "'start' missing"),
], ids=["missing", "json", "format", "empty-mask", "start"])
def test_bad_family_file_is_one_line_error(tmp_path, content, msg, capfd):
    f = tmp_path / "bad.json"
    if content is not None:
        f.write_text(content)
    r = _run(capfd, "range", "--family", str(f), "--C", "1", "--within=0,1")
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.startswith("subdiv: error:") and msg in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_family_excludes_other_inputs(tmp_path, capfd):
    f = tmp_path / "fam.json"
    _run(capfd, "derive", "--support", "3", "--symmetric", "primal", "--sum-rules", "1", "--output", str(f))
    r = _run(capfd, "atlas", "--family", str(f), "--mask", "1,1", "--x", "t1=0:1:2", "--y", "t1=0:1:2")
    assert r.returncode == 2 and "--family replaces the scheme input" in r.stderr


# ------------------------------------------------------------------ --maximize beyond one binary parameter
def test_maximize_ternary_family():
    """Ternary interpolatory 4-point family on [-1/16, 0]: certified gap <= 1e-3, and every sampled
    member's certified alpha (holder_exponent, an independent route) lies below the box bound."""
    from analysis.regularity.holder import holder_exponent
    from analysis.regularity.maximize_box import maximize_holder_box

    a = derive_mask(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=2).value
    t = a.params[0]
    r = maximize_holder_box(a, {"t1": (sp.Rational(-1, 16), 0)}, arity=3, gap=sp.Rational(1, 1000),
                            budget=60000)
    assert r.status == "certified" and r.witness["gap"] <= sp.Rational(1, 1000)
    for q in (sp.Rational(-1, 16), sp.Rational(-1, 20), r.value["t1"] + sp.Rational(1, 500), sp.Rational(-1, 100)):
        h = holder_exponent(a.subs({t: q}), arity=3)
        assert h.lower <= r.upper
    h = holder_exponent(a.subs({t: r.value["t1"]}), arity=3)
    assert h.upper >= r.lower


@pytest.mark.slow
def test_maximize_two_parameters_finds_the_exceptional_line():
    """The two-parameter family (support 11, reproducing linears) on t1 in [0, 1/32], t2 in [-1/8, 0]:
    generic members have 2 factors (alpha < 2), the maximum lies on the exceptional line
    t1 = -t2/3 - 1/48 (4 factors: the one-parameter family reproducing cubics), whose maximiser the
    one-parameter routine finds independently (README: t1* ~ 0.0138241, alpha 3.206710)."""
    from analysis.regularity.maximize import maximize_holder
    from analysis.regularity.maximize_box import maximize_holder_box

    a = derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=1).value
    r = maximize_holder_box(a, {"t1": (0, sp.Rational(1, 32)), "t2": (sp.Rational(-1, 8), 0)},
                            gap=sp.Rational(1, 100), budget=120000)
    assert r.status == "certified" and r.witness["gap"] <= sp.Rational(1, 100)
    t1, t2 = r.value["t1"], r.value["t2"]
    assert t1 == -t2 / 3 - sp.Rational(1, 48)
    one = derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=3).value
    # only the maximiser and the certified alpha there are compared (both found before the bound over the
    # box, whatever its gap): the branch and bound stops after the first sub-intervals
    ref = maximize_holder(one, within=(0, sp.Rational(1, 32)), gap=sp.Rational(1, 100), max_intervals=16)
    assert abs(float(ref.value) - float(t1)) < 1e-3
    assert abs(float(ref.lower) - float(r.lower)) < 1e-2 and ref.lower <= r.upper
    h = smoothness(a.subs({"t1": sp.Rational(1, 64), "t2": sp.Rational(-1, 16)}), 2)   # a generic member
    assert h.value is False


def test_cli_maximize_box_errors(capfd):
    r = _run(capfd, "derive", "--support", "11", "--interpolatory", "--symmetric", "primal", "--reproduce", "1",
             "--maximize", "holder", "--box", "t1=0,1/32")
    assert r.returncode == 2 and "give a range for every free parameter (t1, t2)" in r.stderr
    r = _run(capfd, "derive", "--support", "11", "--interpolatory", "--symmetric", "primal", "--reproduce", "1",
             "--maximize", "holder", "--box", "t1:0,1")
    assert r.returncode == 2 and "malformed --box" in r.stderr


def test_profile_lists_the_strips():
    """The smoothness-profile kind: the C^1 row of the 4-point family reaches w* (the root of
    32 w^3 + 4 w - 1, Hechler–Mößner–Reif 2009): the norm tests leave a strip next to it, which the
    parametric invariant polytope (issue 14, analysis.regularity.strips) closes — certified."""
    from analysis.claims.kinds.base import SchemeSpec
    from analysis.claims.kinds.profile import SmoothnessProfile

    v = SmoothnessProfile({"within": "(0, 1/4)", "max_j": 1, "grid": 4, "samples": 2},
                          {"s": SchemeSpec("s", FOUR_POINT)}, "x").evaluate()
    assert v.label == "CERTIFIED TRUE"
    table = next(e.table for e in v.evidence if e.table)
    row = next(r for r in table if r[0] == "C^1")
    assert row[2] == "certified"
    assert "CRootOf(32*w**3 + 4*w - 1, 0)" in row[1]


def test_range_with_algebraic_coefficients_is_not_a_traceback():
    """Regression: a family over QQ(sqrt 2)[t1] crashed in the exact boundary determinant
    (CoercionFailed); now the boundary is bisected and the interior says why no norm test ran."""
    from analysis.regularity.ranges import ck_parameter_set

    t = sp.Symbol("t1")
    s2 = sp.sqrt(2)
    a = LaurentSymbol.from_mask([s2 * t, 0, sp.Rational(1, 2) - s2 * t, 1, sp.Rational(1, 2) - s2 * t, 0, s2 * t],
                                start=-3)
    r = ck_parameter_set(a, 1, within=(sp.Rational(-1, 16), 0), grid=2, tol=0.05)
    (run,) = r.value
    assert r.status == "inconclusive" and run["interior"]["proven"] is False
    assert "polynomials in t1 over the rationals" in run["interior"]["route"]
    with pytest.raises(Exception) as exc:
        ParametricNorm(difference_symbol(a, 2), t, 2)
    assert type(exc.value).__name__ == "AnalysisError"
