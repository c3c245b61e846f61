"""User rules with a given edge rule next to the centre (``--edge``): the characteristic map's segment is not a
box-spline patch of the level-1 net there (the edge rule also makes the points on the centre's edges at every finer
level), so C^1 is not certified from those patches, and eigenfunctions are not evaluated on them."""

from __future__ import annotations

from analysis.result import CERTIFIED, INCONCLUSIVE
from analysis.vertex.rules import user_rules
from analysis.vertex.valence import vertex_results

CENTRE = "(5/8-(3/8+c/4)**2)/n"          # Loop's centre weight


def test_a_given_edge_rule_is_not_certified_c1_from_box_spline_patches():
    edge = user_rules("triangle", CENTRE, "3/8; 5/(8*n) + 2*(17/20)*cos(2*pi*j/n)/n")
    r = vertex_results(edge, 3)
    assert r["c1"].status == INCONCLUSIVE and "not made by the regular stencils" in r["c1"].witness["verdict"]
    assert "characteristic_map" not in r


def test_without_a_given_edge_rule_the_certificate_stands():
    """Loop's centre rule alone: every other new point by the regular stencils, the patches are the limit."""
    typed = user_rules("triangle", CENTRE)
    r = vertex_results(typed, 3)
    assert r["c1"].status == CERTIFIED
