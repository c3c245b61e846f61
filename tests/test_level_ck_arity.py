"""Issue 12 (+ issue 13 item 6): C^k verdicts of level-dependent m-ary schemes reach the truth.

:func:`analysis.levels.ck.level_smoothness` on a scheme of arity m (carried by the scheme) is the binary chain with
``arity = m``: Dyn–Levin direct, on the m-ary divided difference schemes ``(m/q_m)^j a^n``, on the generalized
ones ``m^j a^n/p_n`` (exponential factors ``q_m(e^{lambda m^-(n+1)} z)``), and "not C^d" for m-ary exponential
B-spline schemes.

Independent references: the smoothness of the exponential B-spline of degree d is C^(d-1) and not C^d
(Unser–Blu 2005, *Cardinal exponential splines: part I*, IEEE TSP 53), for every dilation; d is computed here
from the entry's support (an m-ary symbol of degree d spans ``(d+1)(m-1)+1`` coefficients), not typed. The
refinement identity behind the m-ary "not C^d" (module docstring of :mod:`analysis.levels.expbspline`) is checked
in mpmath from the closed form of the order-2 exponential B-spline, and tied to the catalogue's level-0 mask.
"""

from __future__ import annotations

import json

import mpmath
import pytest
import sympy as sp

from analysis.levels.ck import check_real
from analysis.levels.expbspline import recognise
from analysis.levels.ck import level_smoothness
from analysis.levels.level_dependent import H, LevelDependentScheme
from analysis.result import CERTIFIED, AnalysisError
from schemes.level_dependent import T, get
from tests.test_levels_one_implementation import _run


def _degree_from_support(s) -> int:
    """d with ``len(mask) = (d+1)(m-1) + 1`` (the support of an m-ary symbol of degree d)."""
    n, m = len(s.mask), s.arity
    assert (n - 1) % (m - 1) == 0
    return (n - 1) // (m - 1) - 1


# ternary degree 1-3 trig: tests/test_catalogue_level_arity.py; all 12: benchmarks/bench_level_arity.py
@pytest.mark.parametrize("slug", ["quaternary-exp-bspline-2-hyp", "quaternary-exp-bspline-1-trig"])
def test_true_smoothness_certified_both_ways(slug):
    s = get(slug)
    d = _degree_from_support(s)
    r = level_smoothness(s, {"t": 1})
    assert r.status == CERTIFIED and r.value == d - 1
    assert r.witness["exact"] is True and r.witness["not_C^k"] == d
    ks = [v["k"] for v in r.witness["verdicts"]]
    assert ks == list(range(d + 1))
    assert all(v["status"] == CERTIFIED for v in r.witness["verdicts"])
    last = r.witness["verdicts"][-1]
    assert last["holds"] is False and last["verdict"] == f"not C^{d}"
    if d >= 2:
        # C^(d-1) through the (d-1)-th m-ary divided difference scheme, with the convergence hypothesis (H2)
        v = r.witness["verdicts"][d - 1]
        assert v["route"].startswith(f"Dyn-Levin on the {d - 1}")
        assert v["hypotheses"]["convergence"].is_certified


def test_generalized_differences_ternary():
    """No factor 1+z+z^2 (frequencies 1, +-i theta): C^1 only through the generalized divided difference
    scheme 3 a^n/q(e^{3^-(n+1)} z); C^2 is refuted by the exponential B-spline theorem (order 3)."""
    s = LevelDependentScheme.from_symbol("3*(1+v*z+v**2*z**2)*(1+2*c1*z+(1+2*c2)*z**2+2*c1*z**3+z**4)"
                          "/((1+v+v**2)*(3+4*c1+2*c2))/z**3", where=["v=exp(1/3**(n+1))", "c1=cos(theta/3**(n+1))", "c2=cos(2*theta/3**(n+1))"], arity=3)
    r = level_smoothness(s, {"theta": 1})
    assert r.value == 1 and r.witness["exact"] is True
    v1 = r.witness["verdicts"][1]
    assert "generalized divided difference" in v1["route"] and v1["j"] == 1 and v1["r"] == 0
    assert v1["Lambda"] == ["1", "-I", "I"] or sorted(v1["Lambda"]) == sorted(["1", "-I", "I"])


def _order2_bspline(l1, l2, w, x):
    """``(beta_{l1,w} * beta_{l2,w})(x)``, ``beta_{l,w} = e^{l t}`` on ``[0, w)``: closed form (l1 != l2)."""
    lo, hi = max(0, x - w), min(w, x)
    if hi <= lo:
        return mpmath.mpf(0)
    d = l1 - l2
    return mpmath.exp(l2 * x) * (mpmath.exp(d * hi) - mpmath.exp(d * lo)) / d


@pytest.mark.parametrize("m,kind", [(3, "hyp"), (4, "trig")])
def test_refinement_identity_dilation_m(m, kind):
    """B_(Lambda,1) = sum_j p_j B_(Lambda,1/m)(. - j/m), p(z) = prod q(e^(lambda_i/m) z); and the catalogue's
    level-0 mask is m p / p(1) (the docstring's m-ary refinement equation, order 2)."""
    mpmath.mp.dps = 40
    t = mpmath.mpf(7) / 10
    lams = (t, -t) if kind == "hyp" else (mpmath.mpc(0, t), mpmath.mpc(0, -t))
    v = [mpmath.exp(lam / m) for lam in lams]
    p = [mpmath.mpf(0)] * (2 * m - 1)
    for i in range(m):
        for j in range(m):
            p[i + j] += v[0] ** i * v[1] ** j
    for x in (mpmath.mpf(1) / 7, mpmath.mpf(2) / 3, 1, mpmath.mpf(13) / 10, mpmath.mpf(19) / 10):
        lhs = _order2_bspline(*lams, 1, x)
        rhs = sum(p[j] * _order2_bspline(*lams, mpmath.mpf(1) / m, x - mpmath.mpf(j) / m) for j in range(2 * m - 1))
        assert abs(lhs - rhs) < mpmath.mpf(10) ** -35
    s = get(f"{ {3: 'ternary', 4: 'quaternary'}[m]}-exp-bspline-1-{kind}")
    P1 = sum(p)
    for k, c in enumerate(s.mask):
        val = complex(sp.N(c.subs({H: 1, T: sp.Rational(7, 10)}), 30))
        assert abs(val - complex(m * p[k] / P1)) < 1e-25


def test_recognition_is_exact_and_arity_specific():
    s = get("ternary-exp-bspline-2-trig").subs({"t": 1})
    assert recognise(s, 3).value == (0, -sp.I, sp.I)
    assert recognise(s, 4).value is None and recognise(s).value is None      # read with another dilation
    perturbed = LevelDependentScheme.from_symbol("(1+z+z**2)**3/(9*z**3) + 3**(-2*n)*(1+z+z**2)**2*(1-z)**2/z**3", arity=3)
    rec = recognise(perturbed, 3)
    assert rec.value is None and "not recognised" in rec.witness["reason"]
    r = level_smoothness(perturbed, k_max=1)
    assert r.witness["not_C^k"] is None and r.witness["exact"] is False


def test_cli_holder_text_and_json():
    rc, out, _ = _run("holder", "--scheme", "ternary-exp-bspline-1-hyp", "--param", "t=1")
    assert rc == 0 and "  C^1: no [certified] — exponential B-spline of order 2" in out
    assert out.rstrip().endswith("=> C^0 exactly (certified: C^0 and not C^1)")
    rc, out, _ = _run("holder", "--scheme", "ternary-exp-bspline-1-hyp", "--param", "t=1", "--json")
    doc = json.loads(out)
    assert rc == 0 and doc["arity"] == 3 and doc["smoothness"]["value"] == 0
    assert doc["smoothness"]["witness"]["not_C^k"] == 1


def test_bad_input_one_line():
    with pytest.raises(AnalysisError, match="the C\\^k verdicts need exact values: give --param t=VALUE"):
        level_smoothness(get("ternary-exp-bspline-1-hyp"), {"t": (1, 2)})
    s = LevelDependentScheme.from_symbol("(1+z+z**2)/z * (1 + 1/(1 - 3*3**(-n)))", arity=3)
    with pytest.raises(AnalysisError, match="undefined at level n = 1"):
        check_real(s, arity=3)


@pytest.mark.parametrize("slug,j", [("ternary-exp-bspline-2-hyp", 1), ("quaternary-exp-bspline-2-trig", 1)])
def test_divided_difference_normalisation_matches_stationary(slug, j):
    """lim (m/q_m)^j a^n = (m/q_m)^j a: the stationary m-ary difference symbol of the limit
    (:func:`analysis.stationary.difference.difference_symbol`, ``(m z^(m-1)/q_m)^j a`` up to the shift), exactly."""
    from analysis.levels.divided import divided_difference
    from analysis.stationary.difference import difference_symbol

    s = get(slug)
    e = divided_difference(s, j, s.arity)
    assert e.limit() == difference_symbol(s.limit(), j, spelling="divided", arity=s.arity)
    assert e.limit().shift(j * (s.arity - 1)) == difference_symbol(s.limit(), j, arity=s.arity)
