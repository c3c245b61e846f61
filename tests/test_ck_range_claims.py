"""The paper-file kind ``ck range`` certifies every closed sub-interval of the C^1 set of the
Dyn–Levin–Gregory four-point scheme up to its true end, and refutes a claim that crosses it.

The four-point scheme is C^1 exactly for ``0 < w < w*``, ``w*`` the real root of
``32 w^3 + 4 w - 1`` (~0.19273; Hechler, Mößner, Reif, CAGD 26 (2009)); the norm tests of
Dyn–Levin–Gregory (1987) prove it only up to ``(sqrt(5) - 1)/8`` (~0.1545), so the claims below
need the parametric norms and the invariant polytope on the strip next to ``w*``.
"""

from __future__ import annotations

import sympy as sp

from analysis.algebra.symbol import LaurentSymbol
from analysis.claims.kinds import Domain, SchemeSpec, kind_class

W = sp.Symbol("w")
FOUR = LaurentSymbol.from_mask([-W, 0, sp.Rational(1, 2) + W, 1, sp.Rational(1, 2) + W, 0, -W], start=-3)
SCHEMES = {"4pt": SchemeSpec("4pt", FOUR, {"w": Domain.parse("(-1/4, 1/4)")})}


def run(interval: str):
    return kind_class("ck range")({"j": 1, "interval": interval}, SCHEMES, "t").evaluate()


def test_a_closed_sub_interval_next_to_the_true_end_is_certified_with_its_ends():
    v = run("[1/1000, 1927/10000]")           # 1927/10000 is 3e-5 below w*
    assert v.status == "certified", v.summary
    assert "parametric norm tests and invariant polytopes" in v.summary
    assert "not checked" not in v.summary      # the closed ends are part of the proof


def test_a_claim_across_the_true_end_is_refuted_by_a_certified_point_beyond_it():
    v = run("(0, 1/5)")                       # w* ~ 0.19273 < 1/5: every sample point of the old
    assert v.status == "refuted", v.summary   # routes lies below w*; the counterexample comes from the strip
    q = sp.Rational(v.numbers[0].value)
    assert 32 * q**3 + 4 * q - 1 > 0 and q < sp.Rational(1, 5)


def test_the_float_screen_of_a_box_skips_only_boxes_the_arb_norm_test_fails(monkeypatch):
    """Route 3's boxes: the float screen at the midpoint (``_fails_at_a_point``) answers "not below 1" only
    where the Arb products give that answer too, so every box is decided as by the Arb test alone."""
    from analysis.stationary import ballnorm
    from analysis.stationary.difference import difference_symbol

    d = difference_symbol(FOUR, 2)
    terms = ballnorm.mask_terms(d, W)
    boxes = [(sp.Rational(i, 80), sp.Rational(i + 1, 80)) for i in range(20)]      # [0, 1/4]: C^1 ends at 0.19273
    screened = [ballnorm._fails_at_a_point(terms, box, 8) for box in boxes]
    monkeypatch.setattr(ballnorm, "_fails_at_a_point", lambda *args: False)
    arb = [ballnorm.norm_below_one_on_box(terms, d.start, box, 8) for box in boxes]
    assert any(screened) and any(arb)               # both answers occur
    assert not any(s and a for s, a in zip(screened, arb))
