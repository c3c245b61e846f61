"""Issue 12 (acceptance): the strip-closing parametric invariant polytope for arity m >= 2
(analysis.regularity.strips.close_strip with ``arity``), used by the m-ary C^j ranges.

The family: the ternary interpolatory 4-point scheme with tension ``mu`` (catalogue entry
``ternary-four-point``; its mask is NOT checked against Hassan–Ivrissimitzis–Dodgson–Sabin 2002, see the
entry's notes, so the ranges below are computed facts about the catalogue mask, not the paper's claims).
Before the generalisation the m-ary range left the strip ``(-1/5, -11455/65536)`` of the C^1 set
undecided. The ends are recomputed here independently of the package: the transition matrices of
``c = (1/3) a_2`` are built by hand from the mask (polynomial division by ``(1+z+z^2)^2``).
"""

import numpy as np
import pytest
import sympy as sp

import schemes
from analysis.algebra.symbol import LaurentSymbol
from analysis.regularity.ranges import ck_range
from analysis.regularity.holder import smoothness
from analysis.regularity.strips import close_strip
from analysis.stationary.difference import difference_symbol
from analysis.stationary.transition import transition_matrices

R = sp.Rational
MU, Z = sp.Symbol("mu"), sp.Symbol("z")


def _t4():
    return schemes.get("ternary-four-point").symbol


def _hand_transition(j: int):
    """The 3 transition matrices ``(T_eps)_{ik} = c_{3i - k + eps}`` of ``c = (1/3) a_{j+1}``, with
    ``a_{j+1} = (3 z^2/(1+z+z^2))^{j+1} a`` computed by sympy polynomial division from the mask typed
    here (``a0..a3`` as in the catalogue's docstring), not by the package."""
    a0, a1, a2, a3 = -R(1, 18) - MU / 6, R(13, 18) + MU / 2, R(7, 18) - MU / 2, -R(1, 18) + MU / 6
    mask = [a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3]                    # z^-5 .. z^5
    num = sp.Poly(sum(c * Z**i for i, c in enumerate(mask)), Z)         # z^5 a(z)
    q, r = sp.div(num * 3 ** (j + 1), sp.Poly((1 + Z + Z**2) ** (j + 1), Z))
    assert r.is_zero
    c = [sp.expand(x / 3) for x in reversed(q.all_coeffs())]            # the shift does not matter
    N = len(c) - 1
    n = -(-N // 2)
    return [sp.Matrix(n, n, lambda i, k, e=e: c[3 * i - k + e] if 0 <= 3 * i - k + e <= N else 0) for e in range(3)]


def _rho(M, x: float) -> float:
    return float(max(abs(np.linalg.eigvals(np.array(M.subs(MU, x).evalf(), dtype=float)))))


@pytest.fixture(scope="module")
def c1_range():
    return ck_range(_t4(), 1, "mu", Ls=(1, 2), within=(R(-1, 4), R(1, 2)), arity=3)


def test_ternary_c1_set_is_exactly_the_open_interval(c1_range):
    r = c1_range
    assert r.status == "certified" and r.witness["exact"], r.witness["undecided"]
    assert r.value == sp.Interval.open(R(-1, 5), R(1, 3))
    assert r.witness["undecided"] == sp.EmptySet
    # the strip next to -1/5 is certified by the polytope (the norm tests alone stop at -11455/65536)
    poly = [x for t in r.witness["interior_tests"] for x in t.get("polytope", [])]
    assert any(x["from"] == "-1/5" and x["kind"] == "strip-left-end" for x in poly)
    assert all(x["max image norm <="] < 1 for x in poly)
    # a point inside the strip by the other route (certified JSR bounds at that point)
    s = smoothness(_t4().subs({MU: R(-1999, 10000)}), 1, max_L=0, max_word=0, arity=3)
    assert (s.value, s.status) == (True, "certified")


def test_left_end_is_minus_one_fifth_by_the_eigenvalue_condition(c1_range):
    T = _hand_transition(1)
    lam = sp.Symbol("lam")
    # the mu in (-1/4, 0) where a transition matrix of c has an eigenvalue +-1 (rho(c) >= 1: not C^1)
    ends = set()
    for M in T:
        cp = (M - lam * sp.eye(M.rows)).det()
        for s in (1, -1):
            ends |= {x for x in sp.Poly(cp.subs(lam, s), MU).real_roots() if R(-1, 4) < x < 0}
    end = max(ends)
    assert end == sp.Rational(-1, 5)
    assert c1_range.value.inf == end and c1_range.witness["not_Cj"].contains(end) is sp.true
    # JSR >= rho(T_1) > 1 just below the end; rho(T_eps) < 1 just above it (float, independent)
    assert _rho(T[1], -0.2 - 1e-4) > 1 and max(_rho(M, -0.2 + 1e-4) for M in T) < 1


def test_c0_set_is_minus_one_to_one_on_the_command_line(capsys):
    """C^0 through `subdiv range --json` (one JSON document): the strip next to 1 left by the norm tests
    is closed; the end 1 is where T_0 of (1/3) a_1 has the eigenvalue 1 (hand-built matrices,
    independent of the package)."""
    import json

    from analysis.cli.main import main

    assert main(["range", "--scheme", "ternary-four-point", "--C", "0", "--within=-2,2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert (out["Cj"], out["status"], out["undecided"]) == ("(-1, 1)", "certified", "empty")
    assert out["not_Cj"] == "(-2, -1] U [1, 2)"
    # (how many strips the norm tests leave depends on their time budget; the one at the end 1 is always there)
    strip = next(x for x in out["strips_closed"] if x["to"] == "1")
    assert strip["kind"] == "strip-right-end" and strip["product"] == "0"
    T = _hand_transition(0)
    assert T[0].subs(MU, 1).eigenvals().get(1, 0) >= 1
    assert _rho(T[0], 1 + 1e-4) > 1 and max(_rho(M, 1 - 1e-4) for M in T) < 1


def test_beyond_the_end_there_is_no_certificate():
    am = difference_symbol(_t4(), 2, arity=3)
    across = close_strip(am, MU, R(-21, 100), R(-11455, 65536), arity=3, max_depth=8)   # contains -1/5
    assert not across["closed"] and "no certificate" in across["reason"]
    below = close_strip(am, MU, R(-21, 100), R(-1, 5), hi_open=True, arity=3, max_depth=8)  # JSR > 1 there
    assert not below["closed"]


def _quaternary():
    """A quaternary interpolatory 4-point family with tension (built here, not a catalogue entry): the
    quaternary Dubuc–Deslauriers rules (cubic Lagrange) plus ``mu`` times the third difference
    ``(-1, 3, -3, 1)`` on the rule ``f_{4i+1}`` and its mirror on ``f_{4i+3}``."""
    from schemes.interpolatory import dubuc_deslauriers_symbol

    L4 = dubuc_deslauriers_symbol(4, 4)
    coef = {i: L4.coeff(i) for i in range(L4.start, L4.end + 1)}
    for r, sign in ((1, 1), (3, -1)):
        for p, w in zip((-1, 0, 1, 2), (-1, 3, -3, 1)):
            coef[r - 4 * p] = coef.get(r - 4 * p, 0) + sign * w * MU
    lo, hi = min(coef), max(coef)
    return LaurentSymbol.from_mask([coef.get(i, 0) for i in range(lo, hi + 1)], start=lo)


def _hand_transition_q(a: LaurentSymbol, j: int):
    """The 4 transition matrices of ``c = (1/4) a_{j+1}``, ``a_{j+1} = (4 z^3/(1+z+z^2+z^3))^{j+1} a``,
    by polynomial division (not by the package)."""
    num = sp.Poly(sum(a.coeff(i) * Z**(i - a.start) for i in range(a.start, a.end + 1)), Z)
    q, r = sp.div(num * 4 ** (j + 1), sp.Poly((1 + Z + Z**2 + Z**3) ** (j + 1), Z))
    assert r.is_zero
    c = [sp.expand(x / 4) for x in reversed(q.all_coeffs())]
    N = len(c) - 1
    n = -(-N // 3)
    return [sp.Matrix(n, n, lambda i, k, e=e: c[4 * i - k + e] if 0 <= 4 * i - k + e <= N else 0) for e in range(4)]


def test_quaternary_strips_close_at_both_c1_ends():
    """m = 4: the C^1 strips next to both ends close. The left end -5/128: T_1 of (1/4) a_2 has the
    eigenvalue 1 (s.m.p. T_1); the right end 11/128: T_1 has the eigenvalue -1 (s.m.p. T_1^2, the
    half cycle T_1 maps the eigenvector to minus itself). The strip starts are where the exact norm tests
    (L <= 8) stop (``ck_range(a, 1, within=(-1, 1), arity=4)``, 64 s, not re-run here)."""
    a = _quaternary()
    am = difference_symbol(a, 2, arity=4)
    left = close_strip(am, MU, R(-5, 128), R(-18307, 524288), lo_open=True, arity=4)
    right = close_strip(am, MU, R(43069, 524288), R(11, 128), hi_open=True, arity=4)
    assert left["closed"] and right["closed"], (left["reason"], right["reason"])
    assert left["word"] == (1,) and right["word"] == (1, 1)
    assert left["pieces"][0]["from"] == "-5/128" and right["pieces"][-1]["to"] == "11/128"
    # the ends, independently: det(T_1 -+ I) = 0 there, rho(T_1) > 1 beyond them
    T1 = _hand_transition_q(a, 1)[1]
    assert (T1 - sp.eye(T1.rows)).det().subs(MU, R(-5, 128)) == 0
    assert (T1 + sp.eye(T1.rows)).det().subs(MU, R(11, 128)) == 0
    assert _rho(T1, -5 / 128 - 1e-4) > 1 and _rho(T1, 11 / 128 + 1e-4) > 1
    beyond = close_strip(am, MU, R(43069, 524288), R(3, 32), arity=4, max_depth=8)
    assert not beyond["closed"]


def test_binary_through_the_mary_path_is_the_binary_result():
    """m = 2 through the generalised code (m-ary difference symbol, arity=2) equals the binary call on
    the 4-point family's C^1 strip up to w* (Hechler–Mößner–Reif 2009: the real root of 32 w^3 + 4 w - 1)."""
    w = sp.Symbol("w")
    a = LaurentSymbol.from_mask([-w, 0, w + R(1, 2), 1, w + R(1, 2), 0, -w], start=-3)
    w_star = sp.CRootOf(32 * w**3 + 4 * w - 1, 0)
    c = difference_symbol(a, 2)
    assert difference_symbol(a, 2, arity=2) == c
    assert all(sp.expand(x - y) == sp.zeros(*x.shape)
               for x, y in zip(transition_matrices(c), transition_matrices(c, arity=2)))
    old = close_strip(c, w, R(6049, 32768), w_star, hi_open=True)
    new = close_strip(difference_symbol(a, 2, arity=2), w, R(6049, 32768), w_star, hi_open=True, arity=2)
    assert old["closed"] and new["closed"]
    assert (new["word"], new["mu"], new["pieces"]) == (old["word"], old["mu"], old["pieces"])
    assert new["pieces"][0]["from"] == "6049/32768" and new["pieces"][-1]["to"] == sp.sstr(w_star)


@pytest.mark.parametrize("bad", ["1", "x"])
def test_bad_arity_is_one_line(bad):
    from analysis.result import AnalysisError

    with pytest.raises(AnalysisError):
        close_strip(difference_symbol(_t4(), 2, arity=3), MU, R(-1, 5), R(-11455, 65536), arity=bad)


@pytest.mark.parametrize("value, message", [("abc", "--strip-budget must be a number of work units"),
                                            ("-1", "--strip-budget must be between 0 and 1000000000 work units")])
def test_mary_strip_budget_bad_input_is_one_line(value, message, capsys):
    from analysis.cli.main import main

    assert main(["range", "--scheme", "ternary-four-point", "--C", "1", "--within=-1/4,1/2",
                 "--strip-budget", value]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1
