"""Issue 13, items 2 and 3: C^k verdicts of level-dependent schemes with their theorems, and the
exponential frequencies they generate and reproduce.

Reference values: the exponential B-spline of degree d (order d + 1) is C^(d-1) and not C^d,
like the polynomial B-spline it tends to (M. Unser, T. Blu, *Cardinal exponential splines:
part I*, IEEE Trans. Signal Process. 53 (2005) 1425-1438); its symbol has the roots -1 (d - 1
times) and -exp(-+ lambda h/2), lambda = +-t (hyperbolic) or +-i t (trigonometric), by
construction (Dyn–Levin 1995; Romani 2009)."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.levels.ck import approximate_sum_rules, level_smoothness
from analysis.levels.level_dependent import LevelDependentScheme
from analysis.levels.reproduction import exponential_frequencies
from schemes.level_dependent import get

DEGREES = {"exp-chaikin": 2, "exp-cubic": 3, "exp-quartic": 4, "exp-quintic": 5}
CASES = [(f"{name}-{kind}", d) for name, d in DEGREES.items() for kind in ("trig", "hyp")]


@pytest.mark.parametrize("slug, d", CASES, ids=[c[0] for c in CASES])
def test_exponential_bsplines_reach_their_true_smoothness(slug, d):
    s = get(slug)
    z = sp.Symbol("z")
    bspline = sp.Poly(sp.expand((1 + z) ** (d + 1)), z).all_coeffs()     # (1+z)^(d+1) / 2^d, independently
    assert [sp.Rational(c, 2 ** d) for c in bspline] == list(s.limit().mask)
    r = level_smoothness(s.subs({"t": 1}))
    assert r.status == "certified" and r.value == d - 1
    ks = {v["k"]: v for v in r.witness["verdicts"]}
    assert all(ks[k]["status"] == "certified" for k in range(d))
    # issue 13 (not C^k): recognised as an exponential B-spline scheme of order d + 1, certified not C^d
    assert ks[d]["status"] == "certified" and ks[d]["verdict"] == "not C^%d" % d and ks[d]["holds"] is False
    assert r.witness["exact"] is True
    # the direct Dyn-Levin series with weight 4^n diverges (a^n - a ~ 4^-n): the divided differences decide
    assert ks[d - 1]["route"] == "Dyn-Levin on the %s divided difference scheme" % {1: "1st", 2: "2nd", 3: "3rd", 4: "4th"}[d - 1]


# a^n = cubic B-spline + 2^-n (1+z)^3 (1-z)/(16 z^2) + 2^-3n/16: ||a^n - a|| ~ 2^-n (the Dyn-Levin
# series diverges for k >= 1, and (1+z) does not divide a^n), but a^n(1) - 2 = a^n(-1) = 2^-3n/16
# and D a^n(-1) = D^2 a^n(-1) = 0: approximate sum rules of order 3 with sum 4^n mu_n < oo.
PERTURBED = "(1+z)**4/(8*z**2) + 2**(-n)*(1+z)**3*(1-z)/(16*z**2) + 2**(-3*n)/16"


def test_asymptotic_similarity_route_is_used_where_dyn_levin_fails():
    s = LevelDependentScheme.from_symbol(PERTURBED)
    r = level_smoothness(s)
    ks = {v["k"]: v for v in r.witness["verdicts"]}
    assert r.value == 2 and ks[0]["route"] == "Dyn-Levin direct"
    for k in (1, 2):
        assert ks[k]["route"].startswith("Charina-Conti-Guglielmi-Protasov 2017")
        assert ks[k]["hypotheses"]["same_support"].value is True
    asr = approximate_sum_rules(s, 2)
    assert asr.witness["checks"]["a(1) - 2"] == {"order_in_h": 3, "leading": sp.Rational(1, 16)}
    assert asr.witness["checks"]["D^0 a(-1)"] == {"order_in_h": 3, "leading": sp.Rational(1, 16)}


def test_inconclusive_names_the_failed_hypotheses():
    # 2^-n moves mass between even and odd coefficients: a^n(-1) = 2^(1-n)... no sum rule, no C^1 theorem applies
    s = LevelDependentScheme.from_mask(["1/4", "3/4 - 2**(-n)/8", "3/4 + 2**(-n)/8", "1/4"], -2)
    r = level_smoothness(s)
    ks = {v["k"]: v for v in r.witness["verdicts"]}
    assert r.value == 0 and ks[1]["status"] == "inconclusive"
    failed = {t["route"]: t["failed"] for t in ks[1]["tried"]}
    assert failed["Dyn-Levin direct"] == ["series_m=1"]
    assert any("approximate_sum_rules_order_2" in f for f in failed.values())


@pytest.mark.parametrize("slug, generated", [
    ("exp-cubic-trig", {0: 2, "I*t": 1, "-I*t": 1}),
    ("exp-chaikin-hyp", {0: 1, "t": 1, "-t": 1}),
], ids=["cubic-trig", "chaikin-hyp"])
def test_exponential_frequencies(slug, generated):
    s = get(slug)
    t = s.params[0]
    r = exponential_frequencies(s)
    want = {sp.sympify(k, locals={"t": t}): m for k, m in generated.items()}
    assert r.status == "certified" and r.value["generated"] == want
    assert r.value["reproduced"] == [0]            # a^n(1) = 2 exactly; e^(+-t x) only generated


def test_frequencies_from_inline_symbol_with_parameter_value():
    s = LevelDependentScheme.from_symbol("(1+z)**2*(1+2*v*z+z**2)/(4*(1+v)*z**2)",
                                         where={"v": "cosh(acosh(w)/2**(n+1))"}).subs({"w": 3})
    r = exponential_frequencies(s)
    assert r.status == "certified"
    assert set(r.value["generated"]) == {0, sp.acosh(3), -sp.acosh(3)}


def test_holder_takes_a_level_dependent_catalogue_name(capsys):
    """`subdiv holder --scheme exp-chaikin-trig` (a name of the level-dependent catalogue): the arity
    lookup of the m-ary input (issue 12) must not reject it as an unknown stationary scheme."""
    import json

    from analysis.cli import main

    assert main(["holder", "--scheme", "exp-chaikin-trig", "--param", "t=1", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    # the exponential Chaikin scheme (degree 2) is C^1: certified through the catalogue name as inline
    assert data["level_dependent"] is True
    assert data["smoothness"]["value"] == 1 and data["smoothness"]["status"] == "certified"
    assert main(["holder", "--scheme", "exp-chaikin-trig", "--arity", "3", "--param", "t=1"]) == 2
    assert "arity 2" in capsys.readouterr().err
