"""Issue 13, item 5: `subdiv holder --box` — C^k of a level-dependent scheme at every point of a
parameter box (analysis.levels.ck_box).

Reference values: the exponential B-spline of degree d (order d + 1) is C^(d-1) and not C^d for
every value of its frequency parameter (M. Unser, T. Blu, *Cardinal exponential splines: part I*,
IEEE Trans. Signal Process. 53 (2005) 1425-1438); the trigonometric masks are undefined where
1 + cos(t 2^-(n+1)) = 0, e.g. at t = 2 pi for n = 0. Seed 003 (form (2), Theorem 3.1 corrected
route): the pointwise region theorem of analysis.levels.region is the independent reference; its
limit at omega = 0 is Chaikin's scheme, which is C^1 and not C^2 (Chaikin 1974; certified below by
the stationary JSR code, not by the code under test)."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.cli import main
from analysis.levels.ck import level_smoothness
from analysis.levels.ck_box import _with_box_signs, level_smoothness_box, normalisers_nonzero_box
from analysis.levels.level_dependent import LevelDependentScheme
from schemes import seed003 as S
from schemes.level_dependent import get

ISSUE_SYMBOL = "(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2"
OMEGA_MAX = (sp.sqrt(6) - 1) / 80


def _verdicts(r):
    return {v["k"]: (v["verdict"], v["status"]) for v in r.witness["verdicts"]}


def _contains(box, name, x):
    lo, hi = (sp.sympify(e) for e in box[name])
    return bool(lo <= x) and bool(x <= hi)


def test_exp_cubic_trig_is_c2_exactly_on_the_whole_box():
    # acceptance: `subdiv holder --scheme exp-cubic-trig --box t=1/10,3`; degree 3 => C^2, not C^3
    r = level_smoothness_box(get("exp-cubic-trig"), {"t": (sp.Rational(1, 10), 3)})
    assert (r.value, r.status, r.witness["exact"]) == (2, "certified", True)
    assert _verdicts(r)[3] == ("not C^3", "certified")
    assert all(not v.get("undecided") for v in r.witness["verdicts"])


def test_issue_example_theta_box_c1_exactly_and_pairs_frequencies():
    s = LevelDependentScheme.from_symbol(ISSUE_SYMBOL, where=["c=cos(theta/2**(n+1))"])
    r = level_smoothness_box(s, {"theta": (sp.Rational(1, 10), sp.pi / 2)})
    # degree 2 exponential B-spline: C^1 and not C^2 at every theta of the box
    assert (r.value, r.status, r.witness["exact"]) == (1, "certified", True)
    freqs = next(v["frequencies"] for v in r.witness["verdicts"] if v["verdict"] == "not C^2")
    theta = sp.Symbol("theta", positive=True)
    assert set(freqs) == {0, sp.I * theta, -sp.I * theta}
    # the point verdict (independent: analysis.levels.ck at one theta of the box) agrees
    p = level_smoothness(s, {"theta": 1})
    assert p.value == r.value and p.witness["exact"]


def test_route_2prime_on_a_box_through_zero():
    """Degree-3 exponential B-spline from +-i theta, +-2i theta (no frequency 0: (1+z) does not divide
    a^n, only generalized differences reach C^2): C^2 and not C^3 for every theta in [-1, 1]."""
    s = LevelDependentScheme.from_symbol("2*(1+2*c1*z+z**2)*(1+2*c2*z+z**2)/((2+2*c1)*(2+2*c2))/z**2",
                                         where=["c1=cos(theta/2**(n+1))", "c2=cos(2*theta/2**(n+1))"])
    r = level_smoothness_box(s, {"theta": (-1, 1)})
    assert (r.value, r.status, r.witness["exact"]) == (2, "certified", True)
    c2 = r.witness["verdicts"][2]
    assert any("generalized" in c["route"] for c in c2["cover"])
    assert any(_contains(c["box"], "theta", 0) for c in c2["cover"])


def test_box_signs_only_when_the_box_excludes_zero():
    s = LevelDependentScheme.from_symbol(ISSUE_SYMBOL, where=["c=cos(theta/2**(n+1))"])
    assert _with_box_signs(s, {"theta": (sp.Rational(1, 10), 1)}).params[0].is_positive
    assert _with_box_signs(s, {"theta": (-2, -1)}).params[0].is_negative
    assert _with_box_signs(s, {"theta": (-1, 1)}).params[0].is_positive is None


def test_seed003_open_region_matches_the_region_theorem():
    """holder --box alpha=0,pi/3 --box omega=0,(sqrt(6)-1)/80 --open omega: the same Dyn-Levin
    theorem as `series --C 2 --open omega` (analysis.levels.region), the same answer."""
    from analysis.levels.region import smoothness_on_region

    rect = {"alpha": (0, sp.pi / 3), "omega": (0, OMEGA_MAX)}
    r = level_smoothness_box(S.TRIGONOMETRIC, rect, open_param="omega", k_max=2)
    ref = smoothness_on_region(S.TRIGONOMETRIC, rect, 2, difference=1, open_param="omega")
    assert ref.status == "certified"
    assert (r.value, r.status) == (2, "certified")
    assert r.witness["region"] == ref.witness["region"]


def test_seed003_closed_box_leaves_exactly_the_strip_at_omega_0():
    """Closed omega box: the limit at omega = 0 is Chaikin's (not C^2), so C^2 cannot be certified
    on a sub-box containing omega = 0; every other sub-box is, and the undecided one is reported."""
    from analysis.algebra.symbol import LaurentSymbol
    from analysis.regularity import smoothness

    chaikin = LaurentSymbol.from_mask([sp.Rational(1, 4), sp.Rational(3, 4), sp.Rational(3, 4), sp.Rational(1, 4)], -2)
    assert smoothness(chaikin, 2).value is False                 # independent: S_a(omega = 0) is not C^2
    rect = {"alpha": (0, sp.pi / 3), "omega": (0, sp.Rational(1, 100))}     # closed, inside [0, OMEGA_MAX)
    r = level_smoothness_box(S.TRIGONOMETRIC, rect, depth=1, k_max=2, L_max=2)
    assert (r.value, r.status) == (1, "certified")
    v2 = r.witness["verdicts"][2]
    assert v2["status"] == "inconclusive"
    assert len(v2["undecided"]) == 1
    u = v2["undecided"][0]
    assert _contains(u["box"], "omega", 0) and u["box"]["alpha"] == ["0", "pi/3"]    # bisected in omega only
    assert any("limit_C" in f for t in u["tried"] for f in t["failed"])
    assert all(not _contains(c["box"], "omega", 0) for c in v2["cover"])


def test_undefined_mask_in_the_box_is_never_certified():
    # exp-chaikin-trig at t = 2 pi, n = 0: 1 + cos(t/2) = 0, the mask is undefined
    r = level_smoothness_box(get("exp-chaikin-trig"), {"t": (sp.Rational(31, 5), sp.Rational(32, 5))}, depth=0)
    assert (r.value, r.status) == (-1, "inconclusive")
    assert r.witness["not_C^k"] is None
    assert _contains(r.witness["verdicts"][0]["undecided"][0]["box"], "t", 2 * sp.pi)


@pytest.mark.parametrize("lams, box, status", [
    ([sp.I * sp.Symbol("t", positive=True)], {"t": (sp.Rational(1, 10), 3)}, "certified"),
    ([sp.I * sp.Symbol("t", positive=True)], {"t": (6, 7)}, "inconclusive"),          # 2 pi inside
    ([sp.I * sp.Symbol("t", positive=True)], {"t": (sp.Rational(13, 2), 12)}, "certified"),   # 4 pi: n = 1 is fine
    ([sp.Symbol("t", positive=True)], {"t": (1, 100)}, "certified"),                  # real: w > 0
], ids=["trig-small", "trig-2pi", "trig-no-odd-pi", "hyp"])
def test_normalisers_on_a_box(lams, box, status):
    # 1 + exp(i t 2^-(n+1)) = 0 iff t 2^-(n+1) = pi mod 2 pi: t = 2 pi (n = 0), 4 pi (n = 1), ...;
    # in [13/2, 12] only 4 pi = 12.57.. at n = 1 would matter and it lies outside
    assert normalisers_nonzero_box(lams, box).status == status


def test_cli_text_and_json(capsys):
    assert main(["holder", "--scheme", "exp-chaikin-hyp", "--box", "t=1/2,2"]) == 0
    out = capsys.readouterr().out
    assert "=> C^1 exactly at every point of t in [1/2, 2]" in out
    assert main(["holder", "--scheme", "exp-chaikin-hyp", "--box", "t=1/2,2", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)                   # exactly one JSON document
    assert data["box"] == {"t": ["1/2", "2"]}
    assert data["smoothness"]["value"] == 1 and data["smoothness"]["status"] == "certified"


@pytest.mark.parametrize("argv, message", [
    (["--box", "t=1/10,3", "--param", "t=1"], "given both by --param and by --box"),
    (["--box", "t=3,1"], "empty parameter box"),
    (["--box", "u=1,2"], "has no parameter u"),
    (["--box", "t=1,2", "--open", "u"], "--open u needs a --box for u"),
    (["--param", "t=1", "--depth", "1"], "--depth needs --box"),
    (["--box", "t=1,2", "--pieces", "0"], "--pieces must be between 1 and 16"),
    (["--box", "t=-1,2"], "outside the declared domain"),
    (["--box", "t=1,2", "--arity", "3"], "has arity 2; drop --arity"),   # m-ary boxes: issue 12/13 item 6
    (["--box", "t=1,2", "--open", "t"], "the limit does not depend on t"),
], ids=["box-and-param", "empty", "unknown", "open-unboxed", "depth-without-box", "pieces", "domain", "arity",
        "open-not-in-limit"])
def test_cli_bad_input_one_line(capsys, argv, message):
    assert main(["holder", "--scheme", "exp-cubic-trig", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1 and err.startswith("subdiv: error:")


def test_cli_box_on_a_stationary_scheme_is_refused(capsys):
    assert main(["holder", "--mask", "1/4,3/4,3/4,1/4", "--start", "-2", "--box", "t=1,2"]) == 2
    assert "subdiv range" in capsys.readouterr().err


def test_a_higher_ck_on_the_whole_box_implies_the_lower_ones(monkeypatch):
    """Bookkeeping: C^1 certified on the whole box gives C^0 there even when no route certified C^0
    directly (here C^0 is forced undecided); the undecided sub-boxes stay in the witness."""
    import analysis.levels.ck_box as ck_box

    decide = ck_box._decide

    def forced(ctx, box, k, max_tries=6):
        if k == 0:
            return {"status": "inconclusive", "tried": [{"route": "test", "failed": ["H1: forced"], "why": "forced"}]}
        return decide(ctx, box, k, max_tries)

    monkeypatch.setattr(ck_box, "_decide", forced)
    r = level_smoothness_box(get("exp-chaikin-hyp"), {"t": (sp.Rational(1, 2), 2)})
    v0 = r.witness["verdicts"][0]
    assert (v0["status"], v0["implied_by"]) == ("certified", "C^1")
    assert v0["undecided_directly"] and not v0["undecided"]
    assert (r.value, r.witness["exact"]) == (1, True)


def test_no_bisection_where_the_series_is_certified_divergent():
    """a^n = B-spline + w 2^-n (1+z)^3 (1-z)/16 + 2^-3n/16: for w > 0 the direct m = 1 series diverges
    (terms ~ w/8; checked pointwise with weighted_series), no divided difference applies ((1+z) does
    not divide a^n), so C^1 stays undecided; the divergent sub-boxes are not bisected further."""
    from analysis.levels.series import weighted_series

    s = LevelDependentScheme.from_symbol("(1+z)**4/(8*z**2) + w*2**(-n)*(1+z)**3*(1-z)/(16*z**2) + 2**(-3*n)/16")
    assert weighted_series(s, {"w": 1}, 1).witness["verdict"] == "divergent"
    r = level_smoothness_box(s, {"w": (0, 1)}, k_max=1)
    assert (r.value, r.status) == (0, "certified")
    und = r.witness["verdicts"][1]["undecided"]
    assert [u["box"]["w"] for u in und] == [["0", "1/4"], ["1/4", "1/2"], ["1/2", "1"]]
    assert [any("(divergent)" in f for t in u["tried"] for f in t["failed"]) for u in und] == [False, True, True]


def test_not_ck_needs_real_masks_on_the_whole_box():
    """Review finding: with frequencies {0, sqrt(t)} the mask is complex for t < 0; 'not C^1 at every point' must
    not be certified on a box through 0 (it is on a box inside t > 0)."""
    from analysis.levels.ck_box import level_smoothness_box
    from analysis.levels.level_dependent import LevelDependentScheme

    s = LevelDependentScheme.from_symbol("(1+e*z)*(1+z)/(1+e)/z", where={"e": "exp(sqrt(t)/2**(n+1))"})
    r = level_smoothness_box(s, {"t": (sp.Integer(-1), sp.Integer(3))})
    assert not any(v.get("holds") is False and v["status"] == "certified" for v in r.witness["verdicts"])
    r = level_smoothness_box(s, {"t": (sp.Rational(1, 2), sp.Integer(3))})
    assert any(v.get("holds") is False and v["status"] == "certified" and v["k"] == 1 for v in r.witness["verdicts"])
