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
    assert r.value is None
    assert "not identically zero (rank 2)" in r.witness["reason"] or "not m I" in r.witness["reason"]


def test_the_butterfly_has_a_nonzero_minor():
    r = tensor_factors(get("butterfly").mask(general=True))
    assert r.value is None and "2x2 minor" in r.witness["reason"] and "w**2" in r.witness["reason"]


@pytest.mark.parametrize("dilation", ["quincunx", "2,1;0,2", "2,0;0,3"], ids=["quincunx", "jordan", "diag-2-3"])
def test_a_rank_one_grid_with_a_dilation_other_than_mI_is_not_reduced(dilation):
    assert tensor_factors(BivariateMask.from_symbol(BILINEAR)).value is not None      # the same grid, M = 2I
    r = tensor_factors(BivariateMask.from_symbol(BILINEAR, dilation))
    assert r.value is None and "is not m I" in r.witness["reason"]


def test_a_total_that_depends_on_the_parameter_is_not_reduced():
    r = tensor_factors(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2*(1+t)/(4*z1*z2)"))
    assert r.value is None and "not a nonzero constant" in r.witness["reason"]


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
