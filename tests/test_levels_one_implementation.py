"""Issue 12 (level-dependent m-ary schemes) / issue 13 item 6: one implementation of the level-dependent code
for every arity — a level-dependent scheme carries its arity and the functions of :mod:`analysis.levels`
(series, reproduction) and :mod:`analysis.cli.levels` run one code with ``arity = m``, so its checks serve every arity.

Independent checks: the supports below are read off the exact masks by hand (stated in each test); the mpmath
distance is a separate evaluation (sympy lambdify in mpmath at 60 digits) of the same exact coefficients.
"""

from __future__ import annotations

import contextlib
import io

import flint
import pytest
import sympy as sp

from analysis.levels import series
from analysis.levels.expbspline import ternary_exponential_bspline_2
from analysis.levels.level_dependent import LevelDependentScheme, distance
from analysis.levels.leading_term import series_by_leading_term
from analysis.levels.series import same_support
from analysis.result import CERTIFIED

SYM3 = "(1+z+z**2)*(1+2*c*z+(1+2*d)*z**2+2*c*z**3+z**4)/((3+4*c+2*d)*z**3)"
WHERE3 = ["--where", "c=cos(theta/3**(n+1))", "--where", "d=cos(2*theta/3**(n+1))"]


def _run(*argv):
    from analysis.cli.main import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(argv))
    return rc, out.getvalue(), err.getvalue()


def test_disjoint_enclosures_are_a_certification_bug_for_every_arity(monkeypatch):
    """The binary check (direct and Taylor-model enclosures must overlap) now guards the m-ary series too
    (before the merge the m-ary copy silently kept the Taylor-model enclosure)."""
    real = series.coefficient_differences
    monkeypatch.setattr(series, "coefficient_differences",
                        lambda s, n, env, **kw: [d + flint.arb(10) for d in real(s, n, env, **kw)])
    with pytest.raises(RuntimeError, match="certification bug"):
        series_by_leading_term(ternary_exponential_bspline_2(), {"theta": 1}, 1)


def test_same_support_treats_a_vanishing_limit_coefficient_exactly():
    # a^n = 1 + 0 z + (1 + 3^-n) z^2 + z^3: a^n_1 = a_1 = 0 at every level, the other coefficients are >= 1,
    # so a^n and a = 1 + z^2 + z^3 have the same support at every level (by inspection)
    s = LevelDependentScheme.from_mask(["1", "0", "1 + 3**(-n)", "1"], 0, arity=3)
    r = same_support(s, {})
    assert r.status == CERTIFIED and r.value is True
    assert r.witness["vanishing_limit_coefficients"] == ["a_1: a^n_k = a_k for every n (exact)"]
    assert r.provenance["method"].startswith("arb enclosures")
    # a^n_1 = 3^-n != 0 while a_1 = 0: the supports differ at every level, so this must not be certified
    bad = same_support(LevelDependentScheme.from_mask(["1", "3**(-n)", "1", "1"], 0, arity=3), {})
    assert not bad.is_certified and bad.value is None


@pytest.mark.parametrize("n", [12])
def test_ternary_distance_in_mpmath_lies_in_the_certified_enclosure(n):
    s = ternary_exponential_bspline_2()
    box = distance(s, n, {"theta": 1})
    mp = distance(s, n, {"theta": 1}, arithmetic="mp", prec=200, arity=3)
    assert box.status == CERTIFIED and mp.status == "numerical"
    assert box.lower <= sp.Rational(str(mp.value)) * (1 + sp.Rational(1, 10 ** 40)) and \
        sp.Rational(str(mp.value)) <= box.upper * (1 + sp.Rational(1, 10 ** 40))
    assert box.upper - box.lower < box.upper * sp.Rational(1, 10 ** 12)


def test_cli_one_reading_of_param_and_box():
    base = ["series", "--arity", "3", "--symbol", SYM3, *WHERE3, "--m", "1"]
    rc, _, err = _run(*base, "--box", "theta=1/2,1", "--param", "theta=1")
    assert rc == 2 and err.strip() == ("subdiv: error: theta is given both by --param and by --box: "
                                       "give one of them")
    rc, _, err = _run(*base, "--box", "theta=1")
    assert rc == 2 and err.strip() == ("subdiv: error: malformed --box 'theta=1': use NAME=LOW,HIGH, "
                                       "e.g. theta=1/2,2")
    rc, _, err = _run("holder", "--arity", "3", "--symbol", SYM3, *WHERE3, "--param", "theta=1", "--C", "x")
    assert rc == 2 and err.strip() == "subdiv: error: --C must be an integer, not 'x'"
