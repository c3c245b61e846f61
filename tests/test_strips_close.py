"""Issue 14: the strips next to eigenvalue-type ends of C^j sets, closed by a parametric invariant
polytope (analysis.regularity.strips).

The family: symmetric 6-point interpolatory binary schemes reproducing cubics (README, issue 14),
mask ``(t, 0, -3t - 1/16, 0, 2t + 9/16, 1, 2t + 9/16, 0, -3t - 1/16, 0, t)``. Its C^2 set ends at
``t*``, the smallest real root of ``524288 t^5 - 65536 t^4 + 12800 t^3 - 352 t^2 + 61 t - 3`` (where
``rho(T_1 T_0) = 1`` for ``c = a_3 / 2``; checked below in floating point, independently of the
package). The norm tests alone leave ``(22607/524288, t*)`` open.
"""

import numpy as np
import pytest
import sympy as sp

from analysis.algebra.algebraic import RealAlgebraic
from analysis.algebra.symbol import LaurentSymbol
from analysis.regularity.interior import ck_interior
from analysis.regularity.strips import close_strip
from analysis.stationary.difference import difference_symbol

t = sp.Symbol("t1")
MASK = "t1,0,-3*t1-1/16,0,2*t1+9/16,1,2*t1+9/16,0,-3*t1-1/16,0,t1"
T_STAR = sp.CRootOf(524288 * t**5 - 65536 * t**4 + 12800 * t**3 - 352 * t**2 + 61 * t - 3, 0)


def _scheme():
    return LaurentSymbol.from_mask(sp.sympify(MASK.split(",")), start=-5)


def _rho_T1T0(tv: float) -> float:
    """rho(T_1 T_0) of c = a_3/2 (a_3 = 8t, -24t, 24t - 1/2, 3/2 - 8t, ... written out by hand)."""
    c = np.array([8 * tv, -24 * tv, 24 * tv - .5, 1.5 - 8 * tv, 1.5 - 8 * tv, 24 * tv - .5, -24 * tv, 8 * tv]) / 2
    N = len(c) - 1
    T = [np.array([[c[2 * i - j + e] if 0 <= 2 * i - j + e <= N else 0 for j in range(N)] for i in range(N)])
         for e in (0, 1)]
    return float(max(abs(np.linalg.eigvals(T[1] @ T[0]))))


def test_end_is_eigenvalue_type():
    # independent float check of the end: rho(T_1 T_0) = 1 at t*, > 1 just above it
    assert abs(_rho_T1T0(float(T_STAR)) - 1) < 1e-9
    assert _rho_T1T0(float(T_STAR) + 1e-4) > 1


@pytest.mark.slow
def test_c2_range_is_the_open_interval_to_t_star():
    r = ck_interior(_scheme(), 2, 0, T_STAR, lo_open=True, hi_open=True)
    assert r.status == "certified", r.provenance
    assert r.value["strips"] == []
    (lo, hi, lc, hc), = r.value["certified"].parts
    assert lo.compare(RealAlgebraic.rational(0)) == 0
    assert hi.compare(RealAlgebraic.from_expr(T_STAR)) == 0
    assert not lc and not hc          # open at both ends: not C^2 at 0 nor at t*
    poly = [x["polytope"] for x in r.witness["pieces"] if "polytope" in x]
    assert len(poly) == 1 and poly[0]["product"] == "10" and poly[0]["max image norm <="] < 1


def test_close_strip_certifies_up_to_t_star():
    r = close_strip(difference_symbol(_scheme(), 3), t, sp.Rational(22607, 524288), T_STAR, hi_open=True)
    assert r["closed"], r["reason"]
    assert r["word"] == (0, 1) and r["mu"] == "1/2"
    assert r["pieces"][0]["from"] == "22607/524288" and r["pieces"][-1]["to"] == sp.sstr(T_STAR)
    # the pieces tile the strip
    for x, y in zip(r["pieces"], r["pieces"][1:]):
        assert x["to"] == y["from"]


def test_refuses_beyond_the_end():
    # [0.04471586, 1/20] contains t*, where rho(T_1 T_0) = 1, and points above it (JSR > 1): no
    # certificate may exist
    r = close_strip(difference_symbol(_scheme(), 3), t, sp.Rational(2235793, 50000000), sp.Rational(1, 20),
                    max_depth=12)
    assert not r["closed"]
    assert "no certificate" in r["reason"]


def test_four_point_c1_set_is_the_published_open_interval():
    # Hechler, Mößner, Reif, CAGD 26 (2009): the 4-point scheme is C^1 exactly for 0 < w < w*,
    # w* the real root of 32 w^3 + 4 w - 1 (~0.19273)
    w = sp.Symbol("w")
    a = LaurentSymbol.from_mask([-w, 0, w + sp.Rational(1, 2), 1, w + sp.Rational(1, 2), 0, -w], start=-3)
    w_star = sp.CRootOf(32 * w**3 + 4 * w - 1, 0)
    r = ck_interior(a, 1, 0, w_star)
    assert r.status == "certified", r.provenance
    (lo, hi, lc, hc), = r.value["certified"].parts
    assert lo.compare(RealAlgebraic.rational(0)) == 0 and hi.compare(RealAlgebraic.from_expr(w_star)) == 0
    assert not lc and not hc


@pytest.mark.parametrize("value, message", [("abc", "--strip-budget must be a number of work units"),
                                            ("-1", "--strip-budget must be between 0 and 1000000000 work units")])
def test_strip_budget_bad_input_is_one_line(value, message, capsys):
    from analysis.cli.main import main

    argv = ["range", "--mask", "-w,0,w+1/2,1,w+1/2,0,-w", "--start", "-3", "--C", "1", "--within=0,1/4",
            "--strip-budget", value]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1
