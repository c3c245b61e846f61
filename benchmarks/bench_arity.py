"""Benchmark (issue 12): certified Hölder exponent of every m-ary catalogue scheme with at most 12
mask coefficients (parameters at their default; the ternary 4-point family also at mu = 1/10, -1/10).

Prints one row per scheme (arity, length, alpha or its enclosure, status, seconds) and the median and
maximum time. Target (issue 12): median under 2 s, none over 30 s.

Then the same for the certified m-ary L2-Sobolev exponent (``sobolev_exponent``), and the weighted
series ``sum 3^(kn)||S_(a^n) - S_a||`` (k = 0, 1, 2) and the C^k verdicts of the ternary exponential
B-spline (level-dependent, theta = 1).

Run:  python benchmarks/bench_arity.py
"""

from __future__ import annotations

import statistics
import time

import sympy as sp

import schemes
from analysis.regularity.holder import holder_exponent
from analysis.regularity.sobolev import sobolev_exponent

EXTRA = {"ternary-four-point": [{"mu": sp.Rational(1, 10)}, {"mu": sp.Rational(-1, 10)}]}


def _cases():
    """``(label, entry, mask)`` for every m-ary catalogue scheme (m >= 3) with at most 12 coefficients, at its
    defaults and the EXTRA parameter values."""
    for e in schemes.entries(mary=True):
        if e.arity == 2:
            continue
        for values in [dict(e.defaults)] + EXTRA.get(e.slug, []):
            a = e.symbol_at(**values)
            if len(a) <= 12:
                yield e.slug + ("" if not values else " " + ",".join(f"{k}={v}" for k, v in values.items())), e, a


def main() -> None:
    rows, times = [], []
    for label, e, a in _cases():
        t0 = time.perf_counter()
        h = holder_exponent(a, arity=e.arity)
        dt = time.perf_counter() - t0
        times.append(dt)
        alpha = sp.sstr(h.value) if h.value is not None else f"[{float(h.lower):.10f}, {float(h.upper):.10f}]"
        rows.append((label, e.arity, len(a), alpha, h.status, dt))
    w = max(len(r[0]) for r in rows)
    print(f"{'scheme':<{w}}  m  len  alpha                          status     seconds")
    for label, m, n, alpha, status, dt in rows:
        print(f"{label:<{w}}  {m}  {n:>3}  {alpha:<30} {status:<10} {dt:7.3f}")
    print(f"{len(times)} schemes: median {statistics.median(times):.3f} s, max {max(times):.3f} s")
    sobolev()
    levels()


def sobolev() -> None:
    times = []
    print("\nm-ary L2-Sobolev exponent s_2 (certified)")
    for label, e, a in _cases():
        t0 = time.perf_counter()
        r = sobolev_exponent(a, arity=e.arity)
        dt = time.perf_counter() - t0
        times.append(dt)
        s2 = sp.sstr(r.value) if r.value is not None else (
            f"[{float(r.lower):.10f}, {float(r.upper):.10f}]" if r.lower is not None else "-")
        print(f"  {label:<32} s_2 = {s2:<30} {r.status:<12} {dt:7.3f} s")
    print(f"{len(times)} schemes: median {statistics.median(times):.3f} s, max {max(times):.3f} s")


def levels() -> None:
    from analysis.levels.ck import level_smoothness
    from analysis.levels.expbspline import ternary_exponential_bspline_2
    from analysis.levels.leading_term import series_by_leading_term

    s = ternary_exponential_bspline_2()
    print("\nternary exponential B-spline of degree 2, theta = 1 (level-dependent)")
    for k in (0, 1, 2):
        t0 = time.perf_counter()
        r = series_by_leading_term(s, {"theta": 1}, k)
        print(f"  sum 3^({k}n)||S_(a^n) - S_a||: {r.witness['verdict']:<10} {r.status:<10} "
              f"{time.perf_counter() - t0:7.3f} s")
    t0 = time.perf_counter()
    r = level_smoothness(s, {"theta": 1})
    print(f"  C^k verdicts (holder): C^{r.value} {r.status}, exact {r.witness['exact']} (not C^{r.witness['not_C^k']})   "
          f"{time.perf_counter() - t0:7.3f} s")


if __name__ == "__main__":
    main()
