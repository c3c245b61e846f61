"""Issue 12 / issue 13 item 6: level-dependent m-ary schemes, their weighted series and C^k.

Independent checks: the ternary exponential B-spline is checked against its defining property (it generates
1, cos(theta x), sin(theta x): a^n(eps e^(-+ i theta 3^-(n+1))) = 0 at the nontrivial cube roots eps, evaluated
with mpmath at 60 digits) and its limit against the catalogue's ternary quadratic B-spline; distances and
series are re-computed here in mpmath from the coefficients (no code under test); for m = 2 the m-ary code is
compared with the binary code (analysis.levels.series) on the binary exponential B-spline.
"""

from __future__ import annotations

import contextlib
import io
import json

import mpmath
import pytest
import sympy as sp

import schemes
from analysis.levels.level_dependent import H, LevelDependentScheme, distance
from analysis.levels.ck import level_smoothness
from analysis.levels.expbspline import ternary_exponential_bspline_2
from analysis.levels.leading_term import series_by_leading_term
from analysis.levels.series import weighted_series
from analysis.result import CERTIFIED, AnalysisError

Z = sp.Symbol("z")
SYM3 = "(1+z+z**2)*(1+2*c*z+(1+2*d)*z**2+2*c*z**3+z**4)/((3+4*c+2*d)*z**3)"
WHERE3 = ["c=cos(theta/3**(n+1))", "d=cos(2*theta/3**(n+1))"]


@pytest.fixture(scope="module")
def exp3():
    return ternary_exponential_bspline_2()


def _mp_mask(s, n, theta):
    th = s.params[0]
    return [mpmath.mpf(sp.N(c.subs({H: sp.Rational(1, s.arity ** n), th: theta}), 60)) for c in s.mask]


def test_transcription_generates_exponentials_and_limit_is_the_bspline(exp3):
    assert exp3.limit() == schemes.get("ternary-bspline-2").symbol
    with mpmath.workdps(60):
        for n in (0, 1, 3):
            coeffs = _mp_mask(exp3, n, sp.Rational(7, 5))
            tau = mpmath.mpf(3) ** (-(n + 1))
            for sign in (1, -1):
                for j in (1, 2):
                    z0 = mpmath.exp(2j * mpmath.pi * j / 3) * mpmath.exp(-sign * 1j * mpmath.mpf(7) / 5 * tau)
                    val = sum(c * z0 ** (exp3.start + k) for k, c in enumerate(coeffs))
                    assert abs(val) < mpmath.mpf(10) ** -50
            assert abs(sum(coeffs) - 3) < mpmath.mpf(10) ** -50                # a^n(1) = 3
    # the inline symbol with --where spells the same scheme
    inline = LevelDependentScheme.from_symbol(SYM3, where=WHERE3, arity=3)
    for n in (0, 2):
        a = [sp.N(c.subs(H, sp.Rational(1, 3 ** n)).subs(inline.params[0], 1), 30) for c in inline.mask]
        b = [sp.N(c.subs(H, sp.Rational(1, 3 ** n)).subs(exp3.params[0], 1), 30) for c in exp3.mask]
        assert inline.start == exp3.start and max(abs(x - y) for x, y in zip(a, b)) < 1e-25


def _mp_distance(s, n, theta):
    lim = [mpmath.mpf(sp.N(c, 60)) for c in s.limit().mask]
    cur = _mp_mask(s, n, theta)
    groups = [[k for k in range(len(s.mask)) if (s.start + k) % s.arity == r] for r in range(s.arity)]
    return max(sum(abs(cur[k] - lim[k]) for k in ks) for ks in groups)


def test_distance_and_series_against_mpmath(exp3):
    with mpmath.workdps(60):
        for n in (0, 5, 25):
            d = distance(exp3, n, {"theta": 1})
            ref = _mp_distance(exp3, n, 1)
            assert d.status == CERTIFIED and float(d.lower) <= float(ref) * (1 + 1e-12) and float(ref) <= float(d.upper) * (1 + 1e-12)
        r = series_by_leading_term(exp3, {"theta": 1}, 1)
        ref = sum(mpmath.mpf(3) ** n * _mp_distance(exp3, n, 1) for n in range(60))   # terms ~ 3^-n: tail < 1e-28
        assert r.witness["verdict"] == "convergent" and float(r.lower) <= float(ref) <= float(r.upper)
        # the leading constant: 9^n ||S_(a^n) - S_a|| -> C
        C = r.witness["leading_constant"]
        assert abs(float(mpmath.mpf(9) ** 40 * _mp_distance(exp3, 40, 1)) - float(C)) < 1e-12
    d = series_by_leading_term(exp3, {"theta": 1}, 2)
    assert (d.status, d.witness["verdict"]) == (CERTIFIED, "divergent")


def test_series_over_a_box(exp3):
    r = series_by_leading_term(exp3, {"theta": (sp.Rational(1, 2), 2)}, 1)
    assert r.status == CERTIFIED and r.witness["verdict"] == "convergent"
    inside = series_by_leading_term(exp3, {"theta": 1}, 1)
    assert r.lower <= inside.lower and inside.upper <= r.upper


def test_arity_two_equals_binary_code():
    sym, where = "(1+z)**2*(1+2*v*z+z**2)/(4*(1+v)*z**2)", ["v=cos(t/2**(n+1))"]
    mine = LevelDependentScheme.from_symbol(sym, where=where, arity=2)
    binary = LevelDependentScheme.from_symbol(sym, where=where)
    assert mine.mask == binary.mask and mine.start == binary.start
    for n in (0, 7):
        a, b = distance(mine, n, {"t": 1}), distance(binary, n, {"t": 1})
        assert a.lower <= b.upper and b.lower <= a.upper
    for k in (0, 1, 2):
        a, b = series_by_leading_term(mine, {"t": 1}, k), weighted_series(binary, {"t": 1}, k)
        assert a.witness["verdict"] == b.witness["verdict"]
        if a.witness["verdict"] == "convergent":
            assert a.lower <= b.upper and b.lower <= a.upper


def test_smoothness_c1_and_not_c2(exp3):
    # C^2 was undecided before the m-ary C^k chain; the limit is not C^2 and the scheme is a ternary exponential
    # B-spline scheme of order 3, so "not C^2" is now certified (tests/test_level_ck_arity.py)
    r = level_smoothness(exp3, {"theta": sp.pi / 2})
    assert r.value == 1 and r.status == CERTIFIED
    last = r.witness["verdicts"][-1]
    assert last["k"] == 2 and last["verdict"] == "not C^2" and last["status"] == CERTIFIED


def _run(*argv):
    from analysis.cli.main import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(argv))
    return rc, out.getvalue(), err.getvalue()


def test_cli_series_and_holder():
    base = ["--arity", "3", "--symbol", SYM3, "--where", WHERE3[0], "--where", WHERE3[1], "--param", "theta=1"]
    rc, out, _ = _run("series", *base, "--m", "1,2", "--json")
    rows = json.loads(out)["series"]
    assert rc == 0 and [r["witness"]["verdict"] for r in rows] == ["convergent", "divergent"]
    rc, out, _ = _run("holder", *base)
    assert rc == 0 and "C^1: yes [certified]" in out and "=> C^1 exactly" in out


def test_bad_input():
    with pytest.raises(AnalysisError, match="only through 3\\^n"):
        LevelDependentScheme.from_symbol(SYM3, where=["c=cos(theta/2**(n+1))", "d=1"], arity=3)
    rc, out, err = _run("series", "--arity", "3", "--symbol", SYM3, "--where", WHERE3[0], "--where", WHERE3[1])
    assert rc != 0 and err.startswith("subdiv: error: undefined name(s) theta")
    rc, out, err = _run("series", "--arity", "3", "--symbol", SYM3, "--where", WHERE3[0], "--where", WHERE3[1],
                        "--param", "theta=1", "--C", "1")      # --difference works since round 2 (test_level_arity_claims)
    assert rc != 0 and "not available for m-ary" in err
    rc, out, err = _run("series", "--arity", "1", "--symbol", SYM3)
    assert rc != 0 and "--arity must be an integer >= 2" in err
