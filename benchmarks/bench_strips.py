"""Issue 14: closing the strips next to eigenvalue-type ends with the parametric invariant polytope.

Run: ``python benchmarks/bench_strips.py`` (target: under 15 s in total on 2 cores).
"""

from __future__ import annotations

import time

import sympy as sp

import schemes
from analysis.algebra.symbol import LaurentSymbol
from analysis.regularity.strips import close_strip
from analysis.stationary.difference import difference_symbol

t = sp.Symbol("t1")
SIX = LaurentSymbol.from_mask(sp.sympify("t1,0,-3*t1-1/16,0,2*t1+9/16,1,2*t1+9/16,0,-3*t1-1/16,0,t1".split(",")),
                              start=-5)
T_STAR = sp.CRootOf(524288 * t**5 - 65536 * t**4 + 12800 * t**3 - 352 * t**2 + 61 * t - 3, 0)
w = sp.Symbol("omega")
OMEGA_STAR = sp.CRootOf(327680 * w**4 + 25600 * w**3 + 352 * w**2 + 24 * w - 1, 1)


def _t(label, fn):
    t0 = time.perf_counter()
    r = fn()
    dt = time.perf_counter() - t0
    print(f"{label:<58} {dt:7.2f} s   closed={r['closed']} pieces={len(r['pieces'])} {r['reason']}")
    return dt


def main() -> None:
    total = _t("6-point family, C^2 strip [22607/524288, t*)",
               lambda: close_strip(difference_symbol(SIX, 3), t, sp.Rational(22607, 524288), T_STAR, hi_open=True))
    rule1 = schemes.get("dfh-chaikin-perturbation").symbol
    total += _t("seed 003 rule (1), C^2 strip [21877/1048576, omega*)",
                lambda: close_strip(difference_symbol(rule1, 3), w, sp.Rational(21877, 1048576), OMEGA_STAR,
                                    hi_open=True))
    print(f"{'total':<58} {total:7.2f} s")


if __name__ == "__main__":
    main()
