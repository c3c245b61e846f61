"""Benchmark: a 20 x 20 Hölder atlas of seed 004's scheme (3.6) in (mu, nu) at omega = 0.

    python benchmarks/bench_atlas.py                      # 20 x 20, 2 local processes
    python benchmarks/bench_atlas.py --n 10 --workers 1   # smaller / serial-equivalent
    python benchmarks/bench_atlas.py --figure atlas.png --json atlas.json
    python benchmarks/bench_atlas.py --without-exact-rho  # what-if: skip the optional closed form

Prints the wall time, the summed per-point time, points per second, the status counts, and the
distribution of per-point times. ``--without-exact-rho`` replaces
``analysis.jsr._exact.exact_rho_expression`` (an optional closed form of rho(Pi)^(1/L) put in the
JSR witness; it refines sympy ``CRootOf`` roots and dominates the cost of a point) by a stub, in
this process and the forked workers only, to measure what the atlas would cost without it.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=20, help="grid points per axis (default 20)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--refine", type=int, default=0, help="refinement levels (default 0: plain grid)")
    ap.add_argument("--budget", type=int, default=2000, help="JSR work budget per point, work units")
    ap.add_argument("--executor", default="local")
    ap.add_argument("--figure")
    ap.add_argument("--json")
    ap.add_argument("--without-exact-rho", action="store_true")
    args = ap.parse_args()

    import schemes
    from analysis.regularity.atlas import holder_atlas, plot_atlas

    if args.without_exact_rho:
        import analysis.jsr as jsr

        jsr.exact_rho_expression = lambda F, word: None  # what-if measurement only

    a = schemes.get("seed004-design-control").symbol.subs({"omega": 0})
    t0 = time.perf_counter()
    r = holder_atlas(a, "mu", ("-1/5", "1/5"), "nu", (0, 2), n1=args.n, n2=args.n, j_levels=(1, 2, 3),
                     refine_levels=args.refine, executor=args.executor, workers=args.workers,
                     budget=args.budget, progress=True)
    wall = time.perf_counter() - t0
    c = r.witness["counts"]
    timing = r.provenance["timing"]
    secs = sorted(timing["samples"])
    print(f"seed004-design-control, omega = 0, mu in [-1/5, 1/5] x nu in [0, 2], {args.n} x {args.n}, "
          f"refine {args.refine}, budget {args.budget} work units, {r.witness['executor']}"
          + ("  [exact_rho_expression stubbed]" if args.without_exact_rho else ""))
    print(f"  wall {wall:.1f} s   summed per-point {timing['task_seconds']:.1f} s   "
          f"{c['samples'] / wall:.2f} points/s   samples {c['samples']} (per level {c['per_level']})")
    print(f"  certified {c['certified']}   inconclusive {c['inconclusive']}   "
          f"exceptional samples {r.witness['exceptional_samples']}")
    print(f"  per-point seconds: median {statistics.median(secs):.2f}   p90 {secs[int(0.9 * (len(secs) - 1))]:.2f}"
          f"   max {secs[-1]:.2f}")
    for key, v in c["verdicts"].items():
        print(f"  {key}: yes {v['yes']}, no {v['no']}, undecided {v['undecided']}")
    gen = [s for s in r.value if not s["exceptional"] and s["alpha_lower"] is not None]
    best = max(gen, key=lambda s: s["alpha_lower"])
    print(f"  generic max alpha >= {float(best['alpha_lower']):.4f} at mu = {best['p1']}, nu = {best['p2']}")
    if args.figure:
        print("  figure:", plot_atlas(r, args.figure))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(r.to_json(), fh, indent=1)
        print("  json:", args.json)


if __name__ == "__main__":
    main()
