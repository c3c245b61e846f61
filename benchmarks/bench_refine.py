"""Speed of :func:`analysis.stationary.refinement.refine` (float path); not a timed test.

Run: ``python benchmarks/bench_refine.py [--repeat 7]``. Prints one line per case, ready to paste
into a README, e.g. ``refine closed 4-point 1e6 points: 0.031 s (median of 7)``.

Cases
-----
* one step of the 4-point scheme (w = 1/16) on a closed polygon of 10^6 points in R^2
  (target: under 0.5 s);
* the same on an open polygon of 10^4 points, 7 steps (10^4 -> ~1.3*10^6 points), with the
  "interior" and "extrapolate" end rules;
* the cubic B-spline, one closed step on 10^6 points in R^3;
* the exact path (Fraction data via FLINT rationals), one closed 4-point step on 10^4 points.
"""

from __future__ import annotations

import argparse
import statistics
import time
from fractions import Fraction

import numpy as np

from analysis.stationary.refinement import refine
from analysis.algebra.symbol import LaurentSymbol


def median_time(fn, repeat: int) -> tuple[float, object]:
    out = fn()  # warm-up (and the result, for the size report)
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    r = args.repeat

    four = LaurentSymbol.from_mask(["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"], start=-3)
    cubic = LaurentSymbol.from_mask([1, 4, 6, 4, 1], start=-2) / 8
    rng = np.random.default_rng(0)

    closed = rng.standard_normal((10**6, 2))
    t, out = median_time(lambda: refine(four, closed), r)
    print(f"refine closed 4-point 1e6 points in R^2 -> {len(out)} points: {t:.3f} s (median of {r})")

    open_ = rng.standard_normal((10**4, 2))
    for rule in ("interior", "extrapolate"):
        t, out = median_time(lambda: refine(four, open_, 7, closed=False, end_rule=rule), r)
        print(f"refine open 4-point 1e4 points, 7 steps ({rule}) -> {len(out)} points: "
              f"{t:.3f} s (median of {r})")

    closed3 = rng.standard_normal((10**6, 3))
    t, out = median_time(lambda: refine(cubic, closed3), r)
    print(f"refine closed cubic B-spline 1e6 points in R^3: {t:.3f} s (median of {r})")

    exact = np.array([[Fraction(int(v), 7) for v in row]
                      for row in rng.integers(-100, 100, size=(10**4, 2))], dtype=object)
    t, out = median_time(lambda: refine(four, exact), max(3, r // 2))
    print(f"refine closed 4-point 1e4 points in R^2, exact (Fraction): {t:.3f} s "
          f"(median of {max(3, r // 2)})")


if __name__ == "__main__":
    main()
