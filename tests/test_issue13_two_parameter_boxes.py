"""Issue 13, item 5 (part): weighted series over two-parameter boxes, with adaptive subdivision.

Property checked: the certified enclosure over the (alpha, omega) rectangle of seed 003 contains the
certified enclosures at points of the rectangle (computed without boxes), and the box split is
the product of the one-parameter splits."""

from __future__ import annotations

import sympy as sp

from analysis.levels.series import _split, weighted_series
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
