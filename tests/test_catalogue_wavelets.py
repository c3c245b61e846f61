"""Tests of the Daubechies (schemes.wavelets) and interpolation-based (schemes.interpolatory)
catalogue entries: certified enclosures, exact masks, published tables, registry wiring."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import flint
import mpmath
import pytest
import sympy as sp

import schemes
from analysis.algebra.factorization import smoothing_factor
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol
from schemes import seed004
from schemes.catalogue import NumericSchemeEntry
from schemes.interpolatory import (dual_lagrange_rules, dual_lagrange_symbol,
                                   dubuc_deslauriers_symbol, lagrange_weights)
from schemes.wavelets import (DAUBECHIES_ORDERS, daubechies_enclosure, daubechies_exact_symbol,
                              daubechies_mask_float, daubechies_polynomial)

DATA = Path(__file__).parent / "data"
ORDERS = list(DAUBECHIES_ORDERS)
IDS = [f"D{2 * N}" for N in ORDERS]
PREC = 128                      # bits of the enclosures tested
REF_PREC = 4 * PREC             # references (exact values) are evaluated far more precisely


def encloses(ball: flint.arb, ref: flint.arb, *, max_rad: flint.arb | None = None) -> bool:
    """``ref`` lies in ``ball`` and (optionally) ``ball`` is narrow enough."""
    narrow = max_rad is None or ball.rad() < max_rad
    return bool(ball.contains(ref)) and bool(narrow)


def _balls(N: int, prec: int = PREC) -> list[flint.arb]:
    return schemes.get(f"daubechies-{2 * N}").enclosure(prec)


# --------------------------------------------------------------------------------------------
# registry
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("N", ORDERS, ids=IDS)
def test_daubechies_slugs_and_aliases(N):
    e = schemes.get(f"daubechies-{2 * N}")
    assert isinstance(e, NumericSchemeEntry)
    assert schemes.get(f"d{2 * N}") is e and schemes.get(f"db{N}") is e
    assert e.support == (0, 2 * N - 1) and e.sum_rules == N and e.params == ()
    assert e.slug in schemes.names(numeric=True) and e.slug not in schemes.names()
    assert e in schemes.entries(numeric=True) and e not in schemes.entries()


def test_only_d4_has_an_exact_symbol():
    assert [e.slug for e in schemes.entries(numeric=True)
            if isinstance(e, NumericSchemeEntry) and e.has_exact_symbol] == ["daubechies-4"]
    with pytest.raises(AnalysisError, match="no exact symbol; use .enclosure"):
        schemes.get("db3").symbol
    with pytest.raises(AnalysisError, match="no parameter"):
        schemes.get("db2").symbol_at(w=1)


def test_aliases_of_numeric_entries_only_listed_with_numeric():
    assert "db2" not in schemes.names(aliases=True)
    assert "db2" in schemes.names(aliases=True, numeric=True)
    assert "dual-four-point" in schemes.names(aliases=True)


def test_close_match_hint_includes_numeric_slugs():
    with pytest.raises(AnalysisError, match="daubechies-4"):
        schemes.get("daubechies-5")


# --------------------------------------------------------------------------------------------
# Daubechies: certified enclosures
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("N", ORDERS, ids=IDS)
def test_enclosure_radius_below_requested_precision(N):
    balls = _balls(N)
    assert len(balls) == 2 * N
    assert all(b.rad() < flint.arb(2) ** -PREC for b in balls)


@pytest.mark.parametrize("N", ORDERS, ids=IDS)
def test_orthogonality_of_translates(N):
    """sum_k a_k a_{k+2m} = 2 delta_m (a = sqrt(2) h), certified: 2 delta_m lies in the ball."""
    a = _balls(N)
    with flint.ctx.workprec(REF_PREC):
        for m in range(N):
            s = sum((a[k] * a[k + 2 * m] for k in range(2 * N - 2 * m)), flint.arb(0))
            expected = flint.arb(2 if m == 0 else 0)
            assert encloses(s, expected, max_rad=flint.arb(2) ** (10 - PREC)), m


@pytest.mark.parametrize("N", ORDERS, ids=IDS)
def test_sum_rules_of_order_exactly_n(N):
    """a(1) = 2 and the moments sum_k (-1)^k k^j a_k vanish for j < N (a(-1) = 0 to order N),
    certified; the N-th moment is certified nonzero."""
    a = _balls(N)
    with flint.ctx.workprec(REF_PREC):
        assert encloses(sum(a, flint.arb(0)), flint.arb(2))
        for j in range(N + 1):
            moment = sum((a[k] * (-1) ** k * k**j for k in range(2 * N)), flint.arb(0))
            assert moment.contains(0) is (j < N), j


@pytest.mark.parametrize("N", ORDERS, ids=IDS)
def test_extremal_phase_roots_outside_unit_circle(N):
    """The N-1 roots of q(z) = a(z) / ((1+z)/2)^N are outside the unit circle (Daubechies'
    choice): R_N has 2N-2 simple roots, half of them outside."""
    R = flint.fmpz_poly(daubechies_polynomial(N))
    roots = R.complex_roots()
    assert all(m == 1 for _, m in roots) and len(roots) == 2 * N - 2
    assert sum(1 for r, _ in roots if abs(r) > 1) == N - 1
    # |q(e^{it})|^2 = 4 P_N(sin^2(t/2)) at a sample point, t = 1
    a = _balls(N)
    with flint.ctx.workprec(REF_PREC):
        z = flint.acb(1j).exp()
        av = sum((a[k] * z**k for k in range(2 * N)), flint.acb(0))
        qv = av / ((1 + z) / 2) ** N
        y = flint.arb(0.5).sin() ** 2
        P = sum((math.comb(N - 1 + k, k) * y**k for k in range(N)), flint.arb(0))
        assert (abs(qv) ** 2).overlaps(4 * P)


@pytest.mark.parametrize("N", [2, 3, 5, 10, 20], ids=["D4", "D6", "D10", "D20", "D40"])
def test_enclosure_agrees_with_independent_mpmath_factorisation(N):
    """mpmath.polyroots on R_N, same root choice, 60 digits: inside the 128-bit balls' reach."""
    with mpmath.workdps(60):
        coeffs = list(reversed(daubechies_polynomial(N)))          # highest degree first
        roots = mpmath.polyroots(coeffs, maxsteps=500, extraprec=400)
        out = [r for r in roots if abs(r) > 1]
        q = [mpmath.mpf(1)]
        for r in out:                                              # q *= (z - r)
            q = [(q[k - 1] if k > 0 else 0) - r * (q[k] if k < len(q) else 0)
                 for k in range(len(q) + 1)]
        scale = 2 / sum(q)
        a = [c * scale for c in q]
        for _ in range(N):                                         # *= (1+z)/2
            a = [((a[k] if k < len(a) else 0) + (a[k - 1] if k > 0 else 0)) / 2
                 for k in range(len(a) + 1)]
        balls = _balls(N)
        for x, b in zip(a, balls, strict=True):
            assert abs(mpmath.im(x)) < mpmath.mpf(10) ** -45
            mid = mpmath.mpf(b.mid().str(50, radius=False))
            assert abs(mpmath.re(x) - mid) < mpmath.mpf(10) ** -35


@pytest.mark.parametrize("N", [2, 3, 20], ids=["D4", "D6", "D40"])
def test_float_and_mpmath_values_are_ball_midpoints(N):
    e = schemes.get(f"db{N}")
    assert e.mask_float() == daubechies_mask_float(N)
    balls = e.enclosure(200)
    with mpmath.workdps(50):
        for x, b in zip(e.mask_mpmath(50), balls, strict=True):
            assert abs(x - mpmath.mpf(b.mid().str(60, radius=False))) < mpmath.mpf(10) ** -48


def test_haar_is_n_equals_one():
    assert [float(b) for b in daubechies_enclosure(1)] == [1.0, 1.0]
    assert daubechies_exact_symbol(1) == LaurentSymbol.from_mask([1, 1])


@pytest.mark.parametrize("bad", [0, -1, 2.0], ids=["zero", "negative", "float"])
def test_bad_order_is_an_analysis_error(bad):
    with pytest.raises(AnalysisError):
        daubechies_enclosure(bad)


# --------------------------------------------------------------------------------------------
# Daubechies: exact D4, published D4 / D6 / D8 tables
# --------------------------------------------------------------------------------------------

S3 = sp.sqrt(3)
PUBLISHED_D4 = [(1 + S3) / 4, (3 + S3) / 4, (3 - S3) / 4, (1 - S3) / 4]      # a = sqrt(2) h


def _published_d6() -> list[sp.Expr]:
    r10, s = sp.sqrt(10), sp.sqrt(5 + 2 * sp.sqrt(10))
    return [(1 + r10 + s) / 16, (5 + r10 + 3 * s) / 16, (10 - 2 * r10 + 2 * s) / 16,
            (10 - 2 * r10 - 2 * s) / 16, (5 + r10 - 3 * s) / 16, (1 + r10 - s) / 16]


def _arb(expr: sp.Expr) -> flint.arb:
    """A tight ball around a real sympy constant (evaluated with 40 guard digits)."""
    digits = int(REF_PREC / 3.32) + 40
    text = sp.N(expr, digits)
    return flint.arb(str(text)) + flint.arb(0, flint.arb(10) ** (-(digits - 5)))


def test_d4_exact_symbol_is_the_published_mask():
    e = schemes.get("daubechies-4")
    assert e.symbol == LaurentSymbol.from_mask(PUBLISHED_D4, start=0)
    assert e.symbol(1) == 2 and e.symbol(-1) == 0
    assert smoothing_factor(e.symbol).value == 2


def test_d4_exact_orthogonality():
    m = schemes.get("d4").symbol.mask
    assert sp.expand(sum(c * c for c in m)) == 2
    assert sp.expand(m[0] * m[2] + m[1] * m[3]) == 0


@pytest.mark.parametrize("N, published", [(2, PUBLISHED_D4), (3, _published_d6())],
                         ids=["D4", "D6"])
def test_published_closed_forms_lie_in_the_balls(N, published):
    balls = _balls(N)
    with flint.ctx.workprec(REF_PREC):
        for b, p in zip(balls, published, strict=True):
            assert encloses(b, _arb(p)), (b, p)


def test_exact_d4_lies_in_its_balls():
    e = schemes.get("d4")
    with flint.ctx.workprec(REF_PREC):
        assert all(encloses(b, _arb(c)) for b, c in zip(_balls(2), e.symbol.mask, strict=True))


def test_d8_agrees_with_published_table():
    """Daubechies' Table 6.1 (N = 4), 12 decimals: see tests/data/README.md."""
    with open(DATA / "daubechies_masks_published.csv", newline="") as fh:
        rows = [r for r in csv.DictReader(fh) if r["N"] == "4"]
    h = [b / flint.arb(2).sqrt() for b in _balls(4)]
    assert len(rows) == len(h) == 8
    for r in rows:
        tol = 0.5 * 10.0 ** -int(r["decimals"])
        assert abs(float(h[int(r["k"])].mid()) - float(r["h_k"])) <= tol, r


# --------------------------------------------------------------------------------------------
# published Hölder exponents (tests/data): transcription checks only (issue 3 compares)
# --------------------------------------------------------------------------------------------

def _holder_rows() -> list[dict]:
    with open(DATA / "daubechies_holder.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def test_holder_table_rows_are_catalogue_entries():
    rows = _holder_rows()
    assert rows
    for r in rows:
        e = schemes.get(r["slug"])
        assert e.sum_rules == int(r["N"])
        assert r["confidence"] in {"high", "medium"} and r["source"]
        assert len(r["alpha"].split(".")[1]) == int(r["decimals"])


def test_holder_d4_printed_value_is_the_closed_form_rounded():
    row = next(r for r in _holder_rows() if r["slug"] == "daubechies-4")
    exact = 2 - math.log2(1 + math.sqrt(3))
    assert round(exact, int(row["decimals"])) == float(row["alpha"])


# --------------------------------------------------------------------------------------------
# Dubuc–Deslauriers and the dual 4-point scheme
# --------------------------------------------------------------------------------------------

DD_ODD = {4: ((-1, 9, 9, -1), 16),
          6: ((3, -25, 150, 150, -25, 3), 256),
          8: ((-5, 49, -245, 1225, 1225, -245, 49, -5), 2048)}


def test_dd4_is_the_classic_mask_and_the_four_point_default():
    a = schemes.get("dd-4").symbol
    assert a == LaurentSymbol.from_mask([sp.Rational(n, 16) for n in (-1, 0, 9, 16, 9, 0, -1)],
                                        start=-3)
    assert a == schemes.get("four-point").default_symbol()


@pytest.mark.parametrize("n", sorted(DD_ODD), ids=[f"dd-{n}" for n in sorted(DD_ODD)])
def test_dd_odd_rule_is_the_known_table(n):
    nums, den = DD_ODD[n]
    e = schemes.get(f"dd-{n}")
    assert e.stencils.odd == tuple(sp.Rational(x, den) for x in nums)
    assert e.stencils.odd_first == -n // 2 + 1
    assert schemes.get(f"deslauriers-dubuc-{n}") is e


@pytest.mark.parametrize("n", sorted(DD_ODD), ids=[f"dd-{n}" for n in sorted(DD_ODD)])
def test_dd_is_interpolatory_and_reproduces_degree_n_minus_1(n):
    a = schemes.get(f"dd-{n}").symbol
    for i, c in a.items():
        if i % 2 == 0:
            assert c == (1 if i == 0 else 0)
    assert smoothing_factor(a).value == n
    # (S_a f)_i = sum_j a_{i-2j} f_j with f_j = j^d gives (i/2)^d for d < n
    for d in range(n):
        for i in (-1, 0, 1, 2, 3):
            lo, hi = a.support
            val = sum(a.coeff(i - 2 * j) * sp.Integer(j)**d
                      for j in range((i - hi) // 2 - 1, (i - lo) // 2 + 2))
            assert val == sp.Rational(i, 2)**d, (d, i)


@pytest.mark.parametrize("n_points", [3, 0, "4"], ids=["odd", "zero", "string"])
def test_lagrange_weights_reject_bad_point_counts(n_points):
    with pytest.raises(AnalysisError):
        lagrange_weights(n_points, sp.Rational(1, 2))


def test_dual_two_point_is_chaikin():
    assert dual_lagrange_symbol(2) == schemes.get("chaikin").symbol
    assert dubuc_deslauriers_symbol(2) == schemes.get("bspline-1").symbol


def test_dual_four_point_is_the_dfh_default_and_seed004_rule_3_1():
    d4 = dual_lagrange_symbol(4)
    assert dual_lagrange_rules(4).even == tuple(sp.Rational(n, 128) for n in (-7, 105, 35, -5))
    assert schemes.get("dual-four-point") is schemes.get("dfh-chaikin-perturbation")
    assert d4 == schemes.get("dual-four-point").default_symbol()
    r = seed004.RULE_3_1
    assert d4 == LaurentSymbol.from_rules(r.even, r.odd, even_first=r.even_first,
                                          odd_first=r.odd_first)


def test_dual_four_point_family_is_chaikin_perturbation():
    """The DFH one-parameter family is the line through Chaikin (omega = 0) and the cubic dual
    4-point scheme (omega = 1/128): a(omega) = chaikin + 128 omega (dual4 - chaikin)."""
    omega = sp.Symbol("omega")
    chaikin, dual4 = schemes.get("chaikin").symbol, dual_lagrange_symbol(4)
    line = chaikin + (dual4 - chaikin) * (128 * omega)
    assert line == schemes.get("dual-four-point").symbol
