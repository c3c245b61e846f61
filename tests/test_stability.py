"""Stability of the integer shifts of phi (issue 9.3): the exact Jia–Wang criterion and the reduction."""

import pytest
import sympy as sp

import schemes
from analysis.result import AnalysisError
from analysis.regularity.stability import stable_shifts, unit_circle_zero
from analysis.algebra.symbol import LaurentSymbol, Z

Q = sp.Rational
D4 = ["(1+sqrt(3))/4", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3))/4"]


def sym(expr):
    return LaurentSymbol.from_expr(expr)


def check_reduction(a, r):
    """a(z) q(z) = b(z) q(z^2) exactly, b(1) = 2, b stable."""
    b, q = r.witness["reduced_mask"], r.witness["q"]
    assert b(1) == 2
    assert a * q == b * q.upsample(2)
    assert stable_shifts(b).value is True


@pytest.mark.parametrize("d", range(1, 6))
def test_bsplines_are_stable(d):
    r = stable_shifts(schemes.get(f"bspline-{d}").symbol)
    assert (r.value, r.status) == (True, "certified")
    assert r.witness["q"] == LaurentSymbol.from_mask([1])


def test_four_point_is_stable():
    assert stable_shifts(schemes.get("four-point").symbol_at(w=Q(1, 16))).value is True


def test_algebraic_daubechies_d4_is_stable():
    r = stable_shifts(LaurentSymbol.from_mask(D4))
    assert (r.value, r.status) == (True, "certified")


@pytest.mark.parametrize("name", ["d6", "d8", "d20"])
def test_daubechies_ball_masks_are_stable(name):
    r = stable_shifts(schemes.get(name))
    assert (r.value, r.status) == (True, "certified")
    assert r.witness["min_distance_to_circle"] > 0


def test_box_on_0_3_is_unstable_though_it_has_no_symmetric_zeros():
    """The issue's 'no symmetric zeros' wording would call 1 + z^3 stable: it is not (blocking cycle)."""
    a = LaurentSymbol.from_mask([1, 0, 0, 1])
    r = stable_shifts(a)
    assert (r.value, r.status) == (False, "certified")
    assert r.witness["symmetric_zeros_on_circle"] == [] and r.witness["blocking_cycles"] == [3]
    assert r.witness["reduced_mask"] == LaurentSymbol.from_mask([1, 1])
    assert r.witness["q"] == LaurentSymbol.from_mask([1, 1, 1])
    check_reduction(a, r)


def test_symmetric_pair_on_the_circle_is_unstable():
    a = sym("(1+z)*(1+z**2)/2")                      # zeros +-i
    r = stable_shifts(a)
    assert r.value is False and r.witness["blocking_cycles"] == []
    assert r.witness["symmetric_zeros_on_circle"] == [Z + 1]
    check_reduction(a, r)


def test_symmetric_pair_off_the_circle_is_stable():
    a = sym("(1+z)*(z**2-4)/(-3)")                   # zeros +-2: linear dependence, not instability
    r = stable_shifts(a)
    assert (r.value, r.status) == (True, "certified")
    assert "z**2 - 4" in r.witness["notes"][0]


def test_factor_one_minus_z_plus_z2_blocks():
    a = sym("(1+z)**2*(1-z+z**2)/2")
    r = stable_shifts(a)
    assert r.value is False and r.witness["blocking_cycles"] == [3]
    check_reduction(a, r)


def test_both_mechanisms_and_higher_cycles_reduce_to_a_stable_mask():
    a = sym("(1+z)*(1+z**2)*(1+z**5)*(1+z**6)/8")
    r = stable_shifts(a)
    assert r.value is False and r.status == "certified"
    assert r.witness["symmetric_zeros_on_circle"] and 5 in r.witness["blocking_cycles"]
    check_reduction(a, r)


def test_unit_circle_zero_exact():
    z = Z
    assert unit_circle_zero(sp.Poly(z**2 - z + 1, z))[0] is True        # e^{+-i pi/3}
    assert unit_circle_zero(sp.Poly(z**2 - 3 * z + 1, z))[0] is False   # 2 +- sqrt 3, reciprocal pair
    assert unit_circle_zero(sp.Poly(z + 1, z))[0] is True
    K = sp.QQ.algebraic_field(sp.sqrt(3))
    assert unit_circle_zero(sp.Poly(z**2 + sp.sqrt(3) * z + 1, z, domain=K))[0] is True   # e^{+-5 i pi/6}
    assert unit_circle_zero(sp.Poly(z**2 + 3 * sp.sqrt(3) * z + 1, z, domain=K))[0] is False


def test_shift_does_not_matter_and_bad_normalisation_is_an_error():
    a = LaurentSymbol.from_mask([1, 0, 0, 1], start=-2)
    assert stable_shifts(a).value is False
    with pytest.raises(AnalysisError, match="a\\(1\\) = 2"):
        stable_shifts(LaurentSymbol.from_mask([1, 1, 1]))
