"""Issue 12: the strip-closing parametric invariant polytope for arity m (ternary and quaternary families).

Run: ``python benchmarks/bench_arity_strips.py`` (2 cores; target: each strip under 1 s, the whole ternary
C^1 range under 15 s).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import sympy as sp

import schemes
from analysis.regularity.ranges import ck_range
from analysis.regularity.strips import close_strip
from analysis.stationary.difference import difference_symbol

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from test_strips_arity import _quaternary  # noqa: E402  (the quaternary test family)

R = sp.Rational
MU = sp.Symbol("mu")


def _t(label, fn, show):
    t0 = time.perf_counter()
    r = fn()
    dt = time.perf_counter() - t0
    print(f"{label:<62} {dt:7.2f} s   {show(r)}")
    return dt


def main() -> None:
    t4 = schemes.get("ternary-four-point").symbol
    strip = lambda r: f"closed={r['closed']} word={r['word']} pieces={len(r['pieces'])} {r['reason']}"
    rng = lambda r: f"{r.status}: {r.value} (undecided {r.witness['undecided']})"
    _t("ternary 4-point, C^1 strip (-1/5, -11455/65536]",
       lambda: close_strip(difference_symbol(t4, 2, arity=3), MU, R(-1, 5), R(-11455, 65536), lo_open=True,
                           arity=3), strip)
    _t("ternary 4-point, C^0 strip [14931/16384, 1)",
       lambda: close_strip(difference_symbol(t4, 1, arity=3), MU, R(14931, 16384), 1, hi_open=True, arity=3), strip)
    q = difference_symbol(_quaternary(), 2, arity=4)
    _t("quaternary test family, C^1 strip (-5/128, -18307/524288]",
       lambda: close_strip(q, MU, R(-5, 128), R(-18307, 524288), lo_open=True, arity=4), strip)
    _t("quaternary test family, C^1 strip [43069/524288, 11/128)",
       lambda: close_strip(q, MU, R(43069, 524288), R(11, 128), hi_open=True, arity=4), strip)
    _t("ternary 4-point, ck_range C^1 within (-1/4, 1/2)",
       lambda: ck_range(t4, 1, "mu", Ls=(1, 2), within=(R(-1, 4), R(1, 2)), arity=3), rng)
    _t("ternary 4-point, ck_range C^0 within (-2, 2)",
       lambda: ck_range(t4, 0, "mu", Ls=(1, 2), within=(-2, 2), arity=3), rng)


if __name__ == "__main__":
    main()
