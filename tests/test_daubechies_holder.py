"""Certified Hölder exponents of Daubechies' scaling functions from ball-valued masks.

The masks D6 ... D54 are known only by certified Arb enclosures (``schemes.wavelets``); the
exponents come from :func:`analysis.regularity.holder_exponent` (ball route) (JSR bounds valid for
every mask in the balls). They are compared with the published values in
``tests/data/daubechies_holder.csv`` to the published digits, and for D4 with the closed form
``2 - log2(1 + sqrt 3)`` (Daubechies–Lagarias 1992).
"""

from __future__ import annotations

import csv
import math
import time
from pathlib import Path

import flint
import pytest
import sympy as sp

import schemes
from analysis.jsr import jsr_bounds
from analysis.regularity import holder_exponent
from analysis.regularity.balls import ball_divide_by_one_plus_z, ball_transition_matrices

DATA = Path(__file__).parent / "data" / "daubechies_holder.csv"
PUBLISHED = {row["slug"]: row for row in csv.DictReader(DATA.open())}


def _certified(slug: str, budget: int = 30_000):
    t = time.perf_counter()
    r = holder_exponent(schemes.get(slug), budget=budget, rel_gap=1e-8)
    return r, time.perf_counter() - t


def _agrees_to_digits(r, alpha: float, decimals: int) -> bool:
    """The certified enclosure meets the interval of numbers that round to ``alpha``."""
    half = 0.5 * 10.0 ** (-decimals)
    return float(r.lower) <= alpha + half and float(r.upper) >= alpha - half


@pytest.mark.parametrize("slug", ["daubechies-4", "daubechies-6", "daubechies-8",
                                  "daubechies-10", "daubechies-12"])
def test_published_values(slug):
    r, dt = _certified(slug)
    assert r.status == "certified"
    assert r.lower <= r.upper and float(r.upper - r.lower) < 1e-8
    row = PUBLISHED[slug]
    assert _agrees_to_digits(r, float(row["alpha"]), int(row["decimals"])), (
        slug, float(r.lower), float(r.upper), row["alpha"])
    assert r.witness["alpha_exact"].startswith(f"{r.witness['k']} - log2(rho(T_")
    assert dt < 20


def test_d4_closed_form_and_backends_agree():
    """D4: exact symbol over Q(sqrt 3) (exact back end) vs its ball enclosure (interval back
    end); both contain 2 - log2(1 + sqrt 3)."""
    exact_alpha = 2 - sp.log(1 + sp.sqrt(3), 2)
    e = schemes.get("daubechies-4")
    rb = holder_exponent(e)
    rx = holder_exponent(e.symbol)
    rs = holder_exponent(e.symbol, arithmetic="ball")          # exact symbol, enclosed in balls
    for r in (rb, rx, rs):
        assert r.status == "certified"
        assert bool(sp.Le(r.lower, exact_alpha)) and bool(sp.Le(exact_alpha, r.upper))
        assert float(r.upper - r.lower) < 1e-15
    # 0.5500 published; the closed form is 0.550015686...
    assert round(float(rb.lower), 4) == 0.5500
    assert abs(float(rb.lower) - 0.5500156865235) < 1e-12


def test_intervals_agree_across_precisions_and_tighten():
    """Bounds valid at any precision; wider balls give wider (but overlapping) intervals, and
    more effort (tighter target) never loosens them."""
    e = schemes.get("daubechies-8")
    coarse = holder_exponent(e, prec=40)
    fine = holder_exponent(e, prec=200)
    assert coarse.lower <= fine.upper and fine.lower <= coarse.upper
    assert float(coarse.upper - coarse.lower) >= float(fine.upper - fine.lower)
    loose = holder_exponent(e, rel_gap=1e-2, budget=5000)
    tight = holder_exponent(e, rel_gap=1e-10, budget=30000)
    assert loose.lower <= tight.lower <= tight.upper <= loose.upper or (
        float(tight.upper - tight.lower) <= float(loose.upper - loose.lower))


def test_ball_family_bounds_cover_every_member():
    """A ball family: the certified interval contains the JSR of the midpoint family and of
    perturbed members inside the balls."""
    e = schemes.get("daubechies-6")
    with flint.ctx.workprec(200):
        c = [x * 4 for x in ball_divide_by_one_plus_z(e.enclosure(60), 3)]
        T0, T1 = ball_transition_matrices([flint.arb(x.mid(), flint.arb(2) ** -30) for x in c])
    r = jsr_bounds([T0, T1], budget=10000)
    assert r.provenance["input_kind"] == "ball" and r.lower <= r.upper
    import numpy as np
    for shift in (-1, 0, 1):
        M = [np.array([[float(x.mid()) + shift * 2.0 ** -31 if not isinstance(x, int) else 0.0
                        for x in row] for row in T], dtype=float) for T in (T0, T1)]
        rho = max(max(abs(np.linalg.eigvals(A))) for A in M)   # <= JSR of that member
        assert float(r.lower) <= rho * (1 + 1e-12) and rho <= float(r.upper) * (1 + 1e-12)
    # uncertainty of 2^-30 costs at most ~2^-28 relative
    assert float(r.upper / r.lower - 1) < 1e-7


def test_division_rejects_wrong_sum_rule_order():
    from analysis import AnalysisError

    with pytest.raises(AnalysisError):
        holder_exponent(schemes.get("daubechies-6").enclosure(100), sum_rules=4)
    with pytest.raises(AnalysisError):
        holder_exponent(schemes.get("daubechies-6").enclosure(100))   # N missing


@pytest.mark.parametrize("N", [7, 8, 9])
def test_larger_daubechies_certified(N):
    """D14, D16, D18: certified (invariant polytope, high-precision certificate), consistent with
    the float values of Guglielmi–Protasov (2016)."""
    expected = {7: 2.4604, 8: 2.7608, 9: 3.0736}[N]
    r, dt = _certified(f"daubechies-{2 * N}", budget=60_000)
    assert r.status == "certified" and float(r.upper - r.lower) < 1e-8
    assert abs(float(r.lower) - expected) < 1e-4


def test_d22_thin_polytope_certified_after_preconditioning():
    """D22: the invariant polytope is thin (vertex matrix condition ~1e13); it is certified only
    after the exact similarity that rounds it (``analysis.jsr._precondition``)."""
    r, dt = _certified("daubechies-22", budget=60_000)
    assert r.status == "certified" and float(r.upper - r.lower) < 1e-8
    assert abs(float(r.lower) - 3.6035) < 1e-4
    assert "preconditioning" in r.witness["jsr"].witness


def test_d40_two_smps_balanced_and_certified():
    """D40: T0 and T1 have the same spectral radius (two s.m.p.s); the polytope closes only from
    balanced roots (Guglielmi–Protasov 2016) in the ellipsoid-rounded coordinates. Cross-checks:
    the lower end is k - log2 rho(T_w) of a single matrix, and the interval lies between the
    float brute-force bounds of all products of length <= 8 (spectral radii below, norms above)."""
    import numpy as np
    from analysis.jsr import brute_force_bounds

    r, dt = _certified("daubechies-40", budget=150_000)
    assert r.status == "certified" and float(r.upper - r.lower) < 1e-9
    jw = r.witness["jsr"].witness
    assert jw["closed"] and jw["balancing"]["groups"] >= 2 and len(r.witness["product"]) == 1
    assert jw["preconditioning"][0]["kind"] == "sum-of-squares ellipsoid"
    e = schemes.get("daubechies-40")
    with flint.ctx.workprec(400):
        c = [x * 2 ** 19 for x in ball_divide_by_one_plus_z(e.enclosure(300), 20)]
        T0, T1 = ball_transition_matrices(c)
    M = [np.array([[float(x.mid()) if not isinstance(x, int) else 0.0 for x in row]
                   for row in T]) for T in (T0, T1)]
    bf = brute_force_bounds(M, 8)
    a_lo, a_hi = 19 - math.log2(bf["upper"]), 19 - math.log2(bf["lower"])
    assert a_lo - 1e-9 <= float(r.lower) <= float(r.upper) <= a_hi + 1e-9
    assert abs(float(r.lower) - a_hi) < 1e-8          # rho(T_1) attains the JSR


@pytest.mark.parametrize("slug,word", [("daubechies-30", (0, 0, 0, 0, 1, 1)),
                                       ("daubechies-32", (0, 0, 1, 1)),
                                       ("daubechies-44", (0, 0, 1, 1, 1, 1))])
def test_high_orders_certified(slug, word):
    """D30, D32: one s.m.p. with many near ties (T0 alone is within 0.2 %); the polytope closes
    only with the interior fillers (``analysis.jsr._balance.interior_fillers``). D44: the near
    tie (0,0,1,1) (relative 5e-6 below the s.m.p.) must be a balanced root as well. Each is
    certified to the precision of the arithmetic (the s.m.p. search was exhaustive to length
    >= 8; the closed polytope proves that no longer product does better)."""
    r, dt = _certified(slug, budget=120_000)
    assert r.status == "certified" and float(r.upper - r.lower) < 1e-10
    assert r.witness["product"] == word
    assert r.witness["jsr"].witness["search"]["exhaustive_to_length"] >= 8
