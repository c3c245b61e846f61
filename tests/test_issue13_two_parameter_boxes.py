"""Issue 13, item 5 (part): weighted series and same support over two-parameter boxes, with
adaptive subdivision.

Property checked: the certified enclosure over the (alpha, omega) rectangle of seed 003 contains the
certified enclosures at points of the rectangle (computed without boxes), and the box split is
the product of the one-parameter splits."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.levels.series import _split, same_support, smoothness, weighted_series
from schemes import seed003 as S

OMEGA_MAX = (sp.sqrt(6) - 1) / 80
RECT = {"alpha": (sp.Integer(0), sp.pi / 3), "omega": (sp.Rational(1, 10 ** 4), OMEGA_MAX)}


def test_product_split():
    boxes = _split(RECT, 3)
    assert len(boxes) == 9
    assert {b["alpha"] for b in boxes} == {b["alpha"] for b in _split({"alpha": RECT["alpha"]}, 3)}


def test_series_on_the_whole_rectangle_encloses_point_values():
    s = S.TRIGONOMETRIC.difference(1)
    r = weighted_series(s, RECT, 1, depth=1)
    assert r.status == "certified" and r.witness["verdict"] == "convergent"
    for point in ({"alpha": 1, "omega": sp.Rational(1, 100)}, {"alpha": sp.pi / 3, "omega": OMEGA_MAX}):
        p = weighted_series(s, point, 1)
        assert r.lower <= p.lower and p.upper <= r.upper


@pytest.mark.parametrize("scheme", [S.TRIGONOMETRIC, S.HYPERBOLIC], ids=["form-2", "form-3"])
def test_seed003_c2_on_the_rectangle_away_from_omega_0(scheme):
    # Dyn-Levin on e^n = 2 a^n/(1+z) (Theorem 3.1 / Corollary 3.2 of seed 003, corrected route) with
    # every hypothesis certified on alpha in [0, pi/3], omega in [1e-4, (sqrt(6)-1)/80]; the open end
    # omega -> 0 is covered by analysis.levels.region (tests/test_issue13_region.py).
    r = smoothness(scheme, RECT, 2, difference=1, depth=3)
    assert r.status == "certified", r.witness["failed"]
    # the level coefficients are enclosed directly as well as a^n_k = a_k + (a^n_k - a_k): no bisection needed
    assert same_support(scheme.difference(1), RECT).is_certified
