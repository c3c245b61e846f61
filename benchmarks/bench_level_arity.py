"""Issue 12 (catalogue): the level-dependent m-ary exponential B-splines of :mod:`schemes.level_dependent`.

Run: ``python benchmarks/bench_level_arity.py``. Prints, per entry, the time of the exact generation check
(:func:`analysis.levels.reproduction.generation` of its frequencies) and of the C^k verdicts
(:func:`analysis.levels.mary.level_smoothness` at ``t = 1``), each in a fresh cache state of the entry
(the first call includes the exact series expansion), with the verdicts: the certified C^k, whether "not C^(k+1)"
is certified too (the smoothness is then exact), and whether that is the true C^(d-1) of the exponential B-spline
of degree d (d from the support: ``len(mask) = (d+1)(m-1) + 1``; Unser-Blu 2005). Then the wall time of
``subdiv holder --scheme ternary-exp-bspline-3-trig --param t=1`` (a fresh process, as a user runs it).
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time

import sympy as sp


def main() -> None:
    from analysis.levels.ck import level_smoothness
    from analysis.levels.reproduction import generation
    from schemes.level_dependent import ARITY_ENTRIES, T

    gen_times, ck_times, all_true = [], [], True
    for slug, s in ARITY_ENTRIES.items():
        d = (len(s.mask) - 1) // (s.arity - 1) - 1
        lam = ([0] if d > 1 else []) + ([sp.I * T, -sp.I * T] if slug.endswith("trig") else [T, -T])
        t0 = time.perf_counter()
        g = generation(s, lam)
        t1 = time.perf_counter()
        r = level_smoothness(s, {"t": 1})
        t2 = time.perf_counter()
        gen_times.append(t1 - t0)
        ck_times.append(t2 - t1)
        true = r.value == d - 1 and r.witness["exact"]
        all_true &= bool(true)
        routes = "; ".join(f"{v['verdict']}: {v['route']}" for v in r.witness["verdicts"] if v["status"] == "certified")
        print(f"{slug:30s} generation of {', '.join(map(str, lam))}: {g.status} {t1 - t0:5.1f} s; "
              f"C^{r.value} {r.status}, exact {r.witness['exact']} (true C^{d - 1}: {true}) {t2 - t1:4.1f} s "
              f"[{routes}]", flush=True)
    print(f"generation: median {statistics.median(gen_times):.1f} s, max {max(gen_times):.1f} s; C^k verdicts: "
          f"median {statistics.median(ck_times):.1f} s, max {max(ck_times):.1f} s; every entry at its true "
          f"smoothness, certified both ways: {all_true}")
    cmd = [sys.executable, "-m", "analysis", "holder", "--scheme", "ternary-exp-bspline-3-trig", "--param", "t=1"]
    t0 = time.perf_counter()
    out = subprocess.run(cmd, capture_output=True, text=True, env=os.environ, check=False).stdout
    print(f"subdiv holder --scheme ternary-exp-bspline-3-trig --param t=1: {time.perf_counter() - t0:.1f} s "
          f"(wall, fresh process): {out.strip().splitlines()[-1] if out.strip() else '?'}")


if __name__ == "__main__":
    main()
