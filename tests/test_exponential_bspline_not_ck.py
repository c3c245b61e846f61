"""Issue 13 (not C^k): exponential B-spline schemes are recognised exactly and certified not C^d.

Reference facts (independent of the code under test):
* the exponential B-spline of order d + 1 (degree d) with integer knots is C^(d-1) and not C^d
  (M. Unser, T. Blu, *Cardinal exponential splines: part I*, IEEE Trans. Signal Process. 53 (2005)
  1425-1438): its pieces lie in ker prod(D - lambda_i), an order d + 1 ODE;
* the catalogue's degree-d schemes ``exp-*-trig``/``exp-*-hyp`` have the frequencies 0 (d - 1 times)
  and +-i t resp. +-t (their construction: factors (1+z)^(d-1) (1 + 2 v_n z + z^2),
  v_n = cos(t 2^-(n+1)) resp. cosh(t 2^-(n+1)); L. Romani, J. Comput. Appl. Math. 224 (2009) 383-396);
* symbols that are not of the exponential B-spline form must not be recognised: the "not C^k"
  of such a level-dependent scheme stays inconclusive.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import sympy as sp

from analysis.cli import main
from analysis.levels.ck import level_smoothness
from analysis.levels.expbspline import not_ck, recognise
from analysis.levels.level_dependent import LevelDependentScheme
from schemes.level_dependent import get

DEGREES = {"exp-chaikin": 2, "exp-cubic": 3, "exp-quartic": 4, "exp-quintic": 5}
CASES = [(f"{name}-{kind}", d, kind) for name, d in DEGREES.items() for kind in ("trig", "hyp")]


@pytest.mark.parametrize("slug, d, kind", CASES, ids=[c[0] for c in CASES])
@pytest.mark.parametrize("t", [1, sp.Rational(5, 2)], ids=["t=1", "t=5/2"])
def test_catalogue_exponential_bsplines_are_recognised_with_their_frequencies(slug, d, kind, t):
    s = get(slug).subs({"t": t})
    r = recognise(s)
    lam = sp.I * t if kind == "trig" else sp.sympify(t)
    assert r.status == "certified" and r.witness["order"] == d + 1
    assert sorted(r.value, key=sp.default_sort_key) == sorted([0] * (d - 1) + [lam, -lam], key=sp.default_sort_key)
    c = not_ck(s)
    assert c.status == "certified" and c.value is False and c.witness["k"] == d


@pytest.mark.parametrize("slug, d", [("exp-chaikin-hyp", 2), ("exp-cubic-trig", 3)])
def test_level_smoothness_is_exact(slug, d):
    r = level_smoothness(get(slug).subs({"t": 1}))
    ks = {v["k"]: v for v in r.witness["verdicts"]}
    assert r.value == d - 1 and r.witness["exact"] is True and r.witness["not_C^k"] == d
    assert ks[d]["holds"] is False and ks[d]["status"] == "certified"
    assert ks[d]["hypotheses"]["normalisers_nonzero"].value is True


INLINE = "(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2"


def test_inline_symbol_with_where_is_recognised():
    s = LevelDependentScheme.from_symbol(INLINE, where=["c=cos(theta/2**(n+1))"]).subs({"theta": sp.pi / 2})
    r = recognise(s)
    assert r.witness["order"] == 3 and set(r.value) == {0, sp.I * sp.pi / 2, -sp.I * sp.pi / 2}
    # acosh-parametrised hyperbolic cubic: frequencies +-acosh(2)
    s = LevelDependentScheme.from_symbol("(1+z)**2*(1+2*c*z+z**2)/(4*(1+c))/z**2",
                                         where=["c=cosh(acosh(w)/2**(n+1))"]).subs({"w": 2})
    assert set(recognise(s).value) == {0, sp.acosh(2), -sp.acosh(2)}


def test_complex_and_distinct_real_frequencies():
    # lambda = 1 +- i: 1 + 2 e^(h/2) cos(h/2) z + e^h z^2 = (1 + e^((1+i)h/2) z)(1 + e^((1-i)h/2) z)
    q = "(1+2*exp(h/2)*cos(h/2)*z + exp(h)*z**2)".replace("h", "2**(-n)")
    qn = q.replace("*z**2", "").replace("*z", "")
    s = LevelDependentScheme.from_symbol(f"(1+z)*{q}/{qn}/z**2")
    assert recognise(LevelDependentScheme.from_symbol(f"(1+z)*{q}/(2*{qn})/z**2")).value is None   # a(1) = 1
    assert set(recognise(s).value) == {0, 1 + sp.I, 1 - sp.I}
    e = "(1+exp(2**(-n-1))*z)*(1+exp(-3*2**(-n-1))*z)*(1+z)/((1+exp(2**(-n-1)))*(1+exp(-3*2**(-n-1))))/z"
    assert recognise(LevelDependentScheme.from_symbol(e)).value == (-3, 0, 1)


PERTURBED = "(1+z)**4/(8*z**2) + 2**(-n)*(1+z)**3*(1-z)/(16*z**2) + 2**(-3*n)/16"


@pytest.mark.parametrize("expr, where", [
    (PERTURBED, None),                                                            # powers of 2^-n
    ("(1+z)**2*(1+2*c*z+z**2)/(4*(2+c)/3)/z**2", ["c=cos(1/2**(n+1))"]),          # wrong normalisation
    ("(1+z)**2*(1+2*c*z+z**2)/(4*(1+c))/z**2", ["c=cos(1/2**(n+1))**2"]),         # roots not -exp(lambda h/2)
    ("(1+z)**2*(1+2*c*z+z**2)/(4*(1+c))/z**2", ["c=sqrt((1+cos(1/2**n))/2)"]),    # not recognisable form
], ids=["perturbed", "normalisation", "roots", "half-angle"])
def test_non_exponential_symbols_are_not_recognised(expr, where):
    s = LevelDependentScheme.from_symbol(expr, where=where)
    r = not_ck(s)
    assert r.status == "inconclusive" and r.value is None and "not recognised" in r.witness["reason"]


def test_non_exponential_scheme_keeps_the_generic_inconclusive():
    r = level_smoothness(LevelDependentScheme.from_symbol(PERTURBED))
    ks = {v["k"]: v for v in r.witness["verdicts"]}
    assert r.value == 2 and r.witness["exact"] is False and r.witness["not_C^k"] is None
    assert ks[3]["status"] == "inconclusive" and "no implemented theorem" in ks[3]["reason"]


def test_seed003_schemes_are_not_exponential_bsplines():
    s = get("seed003-trigonometric").subs({"alpha": sp.pi / 4, "omega": sp.Rational(1, 100)})
    assert recognise(s).value is None


def test_vanishing_normaliser_is_not_certified():
    # theta = 2 pi: 1 + cos(theta/2) = 0 at level 0, the mask is undefined there
    s = LevelDependentScheme.from_symbol(INLINE, where=["c=cos(theta/2**(n+1))"])
    assert not_ck(s.subs({"theta": 2 * sp.pi})).status == "inconclusive"
    assert not_ck(s.subs({"theta": 3 * sp.pi})).status == "certified"     # 1 + e^(3 pi i/2) = 1 - i
    assert not_ck(s).status == "inconclusive"                             # free theta: not checked


@pytest.mark.parametrize("slug, d", [("exp-chaikin-trig", 2), ("exp-cubic-hyp", 3)])
def test_numerical_jump_of_the_dth_derivative(slug, d):
    """Independent (float) evidence: the d-th divided differences 2^(nd) Delta^d f^n of the cascade
    from the delta sequence jump from 0 to a non-zero value at the left end of the support (a
    jump of the d-th derivative), while the (d-1)-th ones start at O(2^-n) (continuous)."""
    s = get(slug).subs({"t": 1})
    f = np.array([1.0])
    for n in range(12):
        a = np.array([float(c) for c in s.mask_at(n)])
        up = np.zeros(2 * len(f) - 1)
        up[::2] = f
        f = np.convolve(up, a)
    jd = 2.0 ** (12 * d) * np.diff(np.concatenate([np.zeros(d), f]), d)[0]
    jd1 = 2.0 ** (12 * (d - 1)) * np.diff(np.concatenate([np.zeros(d - 1), f]), d - 1)[0]
    assert abs(jd) > 0.1 and abs(jd1) < 1e-2


def test_cli_prints_exact_smoothness(capsys):
    assert main(["holder", "--scheme", "exp-chaikin-trig", "--param", "t=1"]) == 0
    out = capsys.readouterr().out
    assert "C^2: no [certified] — exponential B-spline of order 3" in out
    assert "=> C^1 exactly (certified: C^1 and not C^2)" in out
    assert main(["holder", "--symbol", INLINE, "--where", "c=cos(theta/2**(n+1))", "--param", "theta=pi/2",
                 "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["smoothness"]["witness"]["exact"] is True and data["smoothness"]["value"] == 1
