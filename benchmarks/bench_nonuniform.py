"""Speed of :func:`analysis.nonuniform.refine` (float path); not a timed test.

Run: ``python benchmarks/bench_nonuniform.py [--repeat 5]``. Target: non-uniform refinement of a
10^4-point polygon to ~10^6 points (7 steps) in under 2 s. Prints one line per case.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from analysis.nonuniform import refine


def median_time(fn, repeat: int):
    out = fn()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    rng = np.random.default_rng(0)
    n = 10_000
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    P = np.column_stack([np.cos(t), np.sin(3 * t)]) + 0.01 * rng.standard_normal((n, 2))
    u_closed = rng.choice([0.5, 1.0, 2.0], size=n) * rng.uniform(0.9, 1.1, size=n)
    for d in (2, 3, 4, 6):
        for closed in (True, False):
            u = u_closed if closed else u_closed[:-1]
            sec, r = median_time(lambda: refine(P, u, degree=d, steps=7, closed=closed), args.repeat)
            print(f"NVPS degree {d}, {'closed' if closed else 'open  '} 10^4 -> {len(r.points):,} points "
                  f"(7 steps, R^2): {sec:.3f} s (median of {args.repeat}){'  TARGET MISSED (2 s)' if sec > 2 else ''}")
    sec, r = median_time(lambda: refine(P[:200], u_closed[:199], degree=3, steps=5, arithmetic="mp", prec=128), 1)
    print(f"NVPS degree 3, open 200 -> {len(r.points):,} points (5 steps, mpmath 128 bits): {sec:.3f} s")
    sec, r = median_time(lambda: refine(P[:200], u_closed[:199], degree=3, steps=5, arithmetic="iv", prec=128), 1)
    print(f"NVPS degree 3, open 200 -> {len(r.points):,} points (5 steps, mpmath.iv 128 bits): {sec:.3f} s")


if __name__ == "__main__":
    main()
