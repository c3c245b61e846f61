"""Speed of the exact norms (issue 2 targets; numbers go to the README).

    python benchmarks/bench_norms.py

* exact ||(1/2 S_a)^12||_inf of a 10-coefficient rational mask        (target < 1 s)
* the one-parameter norm-set solve for seed 003's scheme (1), m=3, L=2 (target < 5 s)
* the same solve for L = 3 and 4, and seed 004's (3.7) for m = 1..3, L = 1..3 (for reference)
"""

from __future__ import annotations

import random
import statistics
import time

import sympy as sp

import schemes
from analysis.stationary.difference import scheme_norm
from analysis.stationary.normset import norm_solution_set
from analysis.algebra.symbol import LaurentSymbol


def timed(fn, repeat: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def main() -> None:
    rng = random.Random(2026)
    mask = [sp.Rational(rng.randint(-60, 60), rng.choice([64, 96, 128, 243])) for _ in range(10)]
    a = LaurentSymbol.from_mask(mask, start=-4)
    t, r = timed(lambda: scheme_norm(a, 12, scale=sp.Rational(1, 2)), 5)
    print(f"exact ||(1/2 S_a)^12||_inf, 10-coefficient rational mask: {t:.3f} s (median of 5); "
          f"value ~ {float(r.value):.6g}")

    dfh = schemes.get("dfh-chaikin-perturbation").symbol
    for L, rep in ((2, 5), (3, 3), (4, 1)):
        t, r = timed(lambda: norm_solution_set(dfh, 3, L, within=(0, sp.oo)), rep)
        print(f"seed 003 (1): exact set of omega > 0 with ||(1/2 S_a3)^{L}|| < 1: {t:.3f} s "
              f"(median of {rep}) -> {r.value}")

    t_nu = schemes.get("seed004-t-nu").symbol
    t0 = time.perf_counter()
    for m in (1, 2, 3):
        for L in (1, 2, 3):
            norm_solution_set(t_nu, m, L)
    print(f"seed 004 (3.7): all nine sets m = 1..3, L = 1..3: {time.perf_counter() - t0:.3f} s")


if __name__ == "__main__":
    main()
