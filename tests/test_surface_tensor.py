"""Tensor-product masks: the exact rank-1 reduction and the C^l set as the intersection of univariate ones."""

from __future__ import annotations

import json

import pytest
import sympy as sp

import schemes
from analysis.algebra.symbol import LaurentSymbol
from analysis.bivariate.mask import BivariateMask
from analysis.bivariate.tensor import tensor_ck_set, tensor_factors
from analysis.cli.main import main
from analysis.regularity.ranges import ck_parameter_set
from analysis.result import AnalysisError
from schemes.surfaces import get

BILINEAR = "(1+z1)**2*(1+z2)**2/(4*z1*z2)"


def _tensor(u: LaurentSymbol, v: LaurentSymbol, dilation="dyadic") -> BivariateMask:
    return BivariateMask({(u.start + i, v.start + j): x * y for i, x in enumerate(u.mask) for j, y in enumerate(v.mask)},
                         dilation)


def test_kobbelt_quad_is_the_tensor_square_of_the_four_point_scheme():
    r = tensor_factors(get("kobbelt-quad").mask(general=True))
    four = schemes.get("four-point").symbol
    assert r.status == "certified" and r.value is not None
    assert r.value.m == 2 and r.value.same and r.value.b == four and r.value.c == four
    assert r.value.grid == (7, 7)
    assert sum(r.value.b.mask) == 2            # for every w: the sum is the constant 2


@pytest.mark.parametrize("name", ["butterfly", "loop", "sqrt3"])
def test_masks_of_rank_two_are_not_reduced(name):
    r = tensor_factors(get(name).mask(general=True))
    assert r.value is None and r.witness["reason"].startswith("not reduced: ")
    assert any(x in r.witness["reason"] for x in ("rank >= 2 over Q(w)", "rank >= 2 (not a tensor product)",
                                                    "not m I"))


def test_the_butterfly_has_a_nonzero_minor():
    r = tensor_factors(get("butterfly").mask(general=True))
    assert r.value is None and "2x2 minor" in r.witness["reason"] and "w**2" in r.witness["reason"]


@pytest.mark.parametrize("dilation", ["quincunx", "2,1;0,2", "2,0;0,3"], ids=["quincunx", "jordan", "diag-2-3"])
def test_a_rank_one_grid_with_a_dilation_other_than_mI_is_not_reduced(dilation):
    assert tensor_factors(BivariateMask.from_symbol(BILINEAR)).value is not None      # the same grid, M = 2I
    r = tensor_factors(BivariateMask.from_symbol(BILINEAR, dilation))
    assert r.value is None and "is not m I" in r.witness["reason"]


def test_a_total_that_depends_on_the_parameter_is_not_reduced():
    a = BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2*(1+t)/(4*z1*z2)")
    r = tensor_factors(a)
    assert r.value is None and "not a nonzero constant" in r.witness["reason"]
    # certified is "not reduced", not "not a tensor product": the grid has rank 1 for every t (at t = 0 it is reduced)
    assert r.witness["reason"].startswith("not reduced: ") and "rank of the grid is not examined" in r.witness["reason"]
    assert tensor_factors(a.at({"t": 0})).value is not None


def test_a_minor_nonzero_only_generically_does_not_say_not_a_tensor_product():
    """The minors of bilinear + t (1 - z1^2)(1 - z2^2)/(z1 z2) are multiples of t: rank 1 at t = 0."""
    a = BivariateMask.from_symbol(BILINEAR + " + t*(1-z1**2)*(1-z2**2)/(z1*z2)")
    r = tensor_factors(a)
    assert r.value is None and r.witness["reason"].startswith("not reduced: ")
    assert "not identically zero: rank >= 2 over Q(t)" in r.witness["reason"]
    assert "rank 1 is still possible where every minor vanishes" in r.witness["reason"]
    assert tensor_factors(a.at({"t": 0})).value is not None
    fixed = tensor_factors(a.at({"t": 1}))                  # a nonzero constant minor: rank >= 2, said so
    assert fixed.value is None and fixed.witness["reason"].endswith("not zero: rank >= 2 (not a tensor product)")


def test_a_negative_multiple_of_the_identity_is_not_reduced():
    """With M = -2I the scheme is S_{b (x) b} after a reflection, not the binary S_b (x) S_b: the family
    b_t = (1-t) b + t (1+z)^2/(2z), b = (1+z)^2 (-29/10 + 28/10 z + 21/10 z^2)/4, was reduced with "M = 2I" and given
    a certified C^0 set containing t = 0."""
    b = "(1+{z})**2*(-29/10+28/10*{z}+21/10*{z}**2)/4"
    bt = "((1-t)*" + b + "+t*(1+{z})**2/(2*{z}))"
    symbol = bt.format(z="z1") + "*" + bt.format(z="z2")
    assert tensor_factors(BivariateMask.from_symbol(symbol)).value is not None      # M = 2I: reduced
    for dilation in ("-2,0;0,-2", "-3,0;0,-3"):
        a = BivariateMask.from_symbol(symbol, dilation)
        r = tensor_factors(a)
        assert r.value is None and "is not m I with m >= 2" in r.witness["reason"]
        with pytest.raises(AnalysisError, match="tensor-product route does not apply"):
            tensor_ck_set(a, 0, within=(0, sp.Rational(1, 16)))


def test_kobbelt_c1_set_is_the_four_point_c1_set(capsys):
    """Both ways: the surface command (tensor route) and the univariate machinery on the four-point scheme."""
    assert main(["surface", "--scheme", "kobbelt-quad", "--C", "1", "--within=0,1/4", "--grid-cells", "4",
                 "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    u = ck_parameter_set(schemes.get("four-point").symbol, 1, within=(0, sp.Rational(1, 4)), grid=4,
                         interior_L_max=12)
    assert u.status == "certified" and len(u.value) == 1
    run = u.value[0]
    assert run["interior"]["proven"] and "exact" in run["left"] and "exact" in run["right"]
    want = {"from": sp.sstr(run["left"]["exact"]), "to": sp.sstr(run["right"]["exact"]), "from_open": True,
            "to_open": True}
    assert d["route"] == "tensor product" and d["status"] == "certified"
    assert d["certified"] == [want]
    # the complement in [0, 1/4]: 0, and the whole closed stretch [w*, 1/4] proven not C^1 (not sampled)
    (stretch,) = [s for s in u.witness["not_Cj"] if s["from"] != s["to"]]
    assert stretch["proven"]
    assert d["not_Cl"] == [want["from"], {"from": want["to"], "to": "1/4", "from_open": False, "to_open": False}]
    assert d["gaps"] == [] and d["between_counterexamples"] == []
    assert d["tensor"]["same_factor"] and d["tensor"]["b"] == str(schemes.get("four-point").symbol)


def test_two_different_factors_intersect():
    """b = four-point(w), c = four-point(1/8 - w): C^1 for 0 < w < w* and for 1/8 - w* < w < 1/8."""
    four = schemes.get("four-point").symbol
    w = four.params[0]
    c = four.subs({w: sp.Rational(1, 8) - w})
    a = _tensor(four, c)
    t = tensor_factors(a).value
    assert t is not None and not t.same and t.b == four and t.c == c
    r = tensor_ck_set(a, 1, within=(0, sp.Rational(1, 4)), grid=4)
    assert r.status == "certified"
    assert str(r.value["Cl"]) == "(0, 1/8)"                      # 0 from b, 1/8 from c
    assert str(r.witness["b"].sets["Cl"]).startswith("(0, CRootOf(32*w**3 + 4*w - 1, 0)")
    assert str(r.witness["c"].sets["Cl"]) == "[0, 1/8)"
    assert r.value["not_Cl"].contains(0) and r.value["not_Cl"].contains(sp.Rational(1, 8))


def test_a_triadic_tensor_family_uses_the_m_ary_route():
    """The ternary 4-point scheme's C^2 range is exactly (1/15, 1/9) (docs/m-ary.md); its tensor square has it."""
    u = schemes.get("ternary-four-point").symbol
    r = tensor_ck_set(_tensor(u, u, "triadic"), 2, within=(sp.Rational(-1, 4), sp.Rational(1, 2)))
    assert r.status == "certified" and r.witness["m"] == 3 and r.witness["b"].route == "ck_range"
    assert str(r.value["Cl"]) == "(1/15, 1/9)"
    assert str(r.value["not_Cl"]) == "[-1/4, 1/15] U [1/9, 1/2]"


def test_a_factor_without_the_parameter_is_one_verdict_on_the_whole_interval():
    """four-point(w) (x) cubic B-spline: the B-spline is C^1 for every w, so the set is the four-point scheme's."""
    four, cubic = schemes.get("four-point").symbol, schemes.get("bspline-3").symbol
    r = tensor_ck_set(_tensor(four, cubic), 1, within=(0, sp.Rational(1, 4)), grid=4)
    assert r.witness["c"].route.startswith("the point verdict") and str(r.witness["c"].sets["Cl"]) == "[0, 1/4]"
    assert r.status == "certified" and r.value["Cl"].parts == r.witness["b"].sets["Cl"].parts
    rough = tensor_ck_set(_tensor(four, schemes.get("bspline-1").symbol), 1, within=(0, sp.Rational(1, 4)), grid=4)
    assert rough.value["Cl"].is_empty and str(rough.value["not_Cl"]) == "[0, 1/4]"    # the hat function: not C^1


def test_too_few_factors_for_m_above_two_is_not_cl_on_the_whole_interval(capsys):
    """Ternary quartic B-spline (1-t) + t quadratic: three factors q_3 identically, five at t = 0. C^3 needs four:
    certified not C^3 on the interval except at t = 0, where the point verdict (the quartic B-spline) says C^3."""
    u = LaurentSymbol.from_expr("(1-t)*(1+z+z**2)**5/(81*z**5) + t*(1+z+z**2)**3/(9*z**3)")
    r = tensor_ck_set(_tensor(u, u, "triadic"), 3, within=(-1, 1))
    assert r.status == "certified" and r.witness["b"].route == "factor count"
    assert str(r.value["Cl"]) == "{0}" and str(r.value["not_Cl"]) == "[-1, 0) U (0, 1]"
    reason = r.witness["b"].result.witness["reason"]
    assert "only 3 factors q_3" in reason and "C^3 needs 4" in reason and "except at t = 0" in reason
    away = tensor_ck_set(_tensor(u, u, "triadic"), 3, within=(sp.Rational(1, 4), sp.Rational(1, 2)))
    assert away.status == "certified" and away.value["Cl"].is_empty and str(away.value["not_Cl"]) == "[1/4, 1/2]"
    one = "(1-t)*(1+z1+z1**2)**5/(81*z1**5) + t*(1+z1+z1**2)**3/(9*z1**3)"
    assert main(["surface", "--symbol", f"({one})*({one.replace('z1', 'z2')})", "--dilation", "triadic", "--C", "3",
                 "--within=-1,1"]) == 0
    out = capsys.readouterr().out
    assert "C^3 needs 4 (q_3^4 | b): not C^3 on the whole interval except at t = 0" in out
    assert "not C^3 (certified: counterexamples and proven stretches): t = [-1, 0), (0, 1]" in out
