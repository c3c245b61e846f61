"""Benchmark: certified JSR enclosures (``jsr_bounds``) side by side with the textbook brute force,
in one process, on the classical JSR benchmark families and the hard random signed pairs.

For every case ``jsr_bounds`` runs with a work budget and its CPU time is measured
(``time.process_time``); then the brute force (the float bounds ``max rho(P)^(1/L) <= JSR <=
max ||P||^(1/L)`` over *all* ``k^L`` products of length ``L``, :func:`analysis.jsr.brute_force_bounds`)
runs for ``L = 1, 2, ...``, once in the infinity norm (plain) and once in the sum-of-squares
balanced norm, until its CPU time exceeds 10x ours (or memory). Printed per case: our certified gap
``upper/lower - 1``, the work units and CPU seconds (and units per CPU second), the gap each brute
force reaches within *our* CPU time, and the CPU time it needs to reach *our* gap (">" when it does
not within 10x). The brute-force numbers are floats, not certificates.

Families:
* random signed pairs ``A = numpy.random.default_rng(seed).integers(-9, 10, size=(2, n, n))``
  (8x8 seed 1, 16x16 seeds 1 and 2: no short s.m.p., the invariant polytope does not close);
* random nonnegative pairs (``integers(0, 10, ...)``, n = 4, 8, 16, seed 1);
* the golden-ratio pair ``[[1,1],[0,1]], [[1,0],[1,1]]`` (JSR = golden ratio, s.m.p. A0 A1);
* Gripenberg (1996), Sec. 4: ``[[3,0],[1,3]]/5, [[3,-3],[0,-1]]/5`` (JSR ~ 0.6597);
* the 4x4 integer pair of the README of the D-Tarnu ``jsr`` prototype (a Python implementation of
  the Guglielmi–Protasov / Guglielmi–Zennaro polytope algorithms) and Jungers–Cicone–Guglielmi
  (2014) Ex. 6.1 (JSR ~ 1.7779);
* the finiteness counterexample family ``[[1,1],[0,1]], t [[1,0],[1,1]]`` (Blondel–Theys–Vladimirov
  2003; no s.m.p. at the critical ``t* = 0.7493265463...``, Hare–Morris–Sidorov–Theys 2011) at
  rationals near ``t*``;
* Daubechies transition matrices ``T_0, T_1`` of ``c = 2^(N-1) a / (1+z)^N`` (D8, D12, D20; Arb
  ball entries).

Run:  python benchmarks/bench_jsr.py [--budget UNITS] [--quick] [--only NAME] [--factor F]
Prints a Markdown table (docs/jsr.md has one with the machine and the command).
"""

from __future__ import annotations

import argparse
import gc
import os
import time

import numpy as np

from analysis.jsr import brute_force_bounds, jsr_bounds, parse_family

#: memory limit of one brute-force level (bytes of the products of length L)
BRUTE_BYTES = 6e8
#: brute force stops once it has used this many times our CPU time
BRUTE_FACTOR = 10.0


def random_pair(seed: int, n: int, lo: int) -> list:
    A = np.random.default_rng(seed).integers(lo, 10, size=(2, n, n))
    return [A[0].tolist(), A[1].tolist()]


def daubechies_pair(N: int) -> list:
    import flint

    import schemes
    from analysis.regularity.balls import ball_divide_by_one_plus_z, ball_transition_matrices

    e = schemes.get(f"daubechies-{2 * N}")
    with flint.ctx.workprec(300):
        c = [x * 2 ** (N - 1) for x in ball_divide_by_one_plus_z(e.enclosure(250), N)]
        T0, T1 = ball_transition_matrices(c)
    return [T0, T1]


def cases(quick: bool) -> list[tuple[str, list]]:
    out = [
        ("signed 8x8 seed 1", random_pair(1, 8, -9)),
        ("signed 16x16 seed 1", random_pair(1, 16, -9)),
        ("signed 16x16 seed 2", random_pair(2, 16, -9)),
        ("nonneg 4x4 seed 1", random_pair(1, 4, 0)),
        ("nonneg 8x8 seed 1", random_pair(1, 8, 0)),
        ("nonneg 16x16 seed 1", random_pair(1, 16, 0)),
        ("golden pair", [[[1, 1], [0, 1]], [[1, 0], [1, 1]]]),
        ("Gripenberg 1996 Sec. 4", [[["3/5", 0], ["1/5", "3/5"]], [["3/5", "-3/5"], [0, "-1/5"]]]),
        ("4x4 pair of the D-Tarnu jsr README", [[[-3, -2, 1, 2], [-2, 0, -2, 1], [1, 3, -1, -5], [-3, -3, -2, -1]],
                                   [[1, 0, -3, -1], [-4, -2, -1, -4], [-1, 0, -1, 2], [-1, -2, -1, 2]]]),
        ("Jungers-Cicone-Guglielmi Ex 6.1", [[[0, -1, 1, 1], [1, 0, 0, 0], [0, -1, 0, 0], [1, -1, -1, 0]],
                                             [[0, -1, 1, 0], [-1, -1, 1, 1], [-1, 0, 0, 0], [-1, -1, 0, -1]]]),
        ("finiteness family t=3/4", [[[1, 1], [0, 1]], [["3/4", 0], ["3/4", "3/4"]]]),
        ("finiteness family t=7493/10000", [[[1, 1], [0, 1]], [["7493/10000", 0], ["7493/10000", "7493/10000"]]]),
    ]
    for N in ((4,) if quick else (4, 6, 10)):
        out.append((f"Daubechies D{2 * N} T0,T1", daubechies_pair(N)))
    if quick:
        out = [c for c in out if not c[0].startswith(("signed 16", "nonneg 16"))]
    return out


def brute(floats: list[np.ndarray], norm: str, cpu_ours: float, gap_ours: float,
          factor: float = BRUTE_FACTOR) -> dict:
    """Brute force for L = 1, 2, ...: the gap reached within ``cpu_ours`` and the CPU needed to
    reach ``gap_ours`` (None if not within ``factor`` times ``cpu_ours``)."""
    k, n = len(floats), floats[0].shape[0]
    spent = 0.0
    at_same = None
    reach = None
    L = 0
    while True:
        L += 1
        if k ** L * n * n * 8 * 3 > BRUTE_BYTES:
            break
        t = time.process_time()
        b = brute_force_bounds(floats, L, norm=norm)
        spent += time.process_time() - t          # the textbook method redoes every length
        gap = b["upper"] / b["lower"] - 1 if b["lower"] > 0 else float("inf")
        if spent <= cpu_ours:
            at_same = (L, gap)
        if reach is None and gap <= gap_ours:
            reach = spent
        if reach is not None and spent > cpu_ours:
            break
        if spent > factor * max(cpu_ours, 0.01):
            break
    return {"at_same": at_same, "reach": reach, "spent": spent, "L": L}


def fmt_bf(b: dict) -> str:
    same = f"L={b['at_same'][0]}: {b['at_same'][1]:.2e}" if b["at_same"] else "-"
    reach = f"{b['reach']:.2f} s" if b["reach"] is not None else f"> {b['spent']:.1f} s"
    return f"{same} | {reach}"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--budget", type=int, default=20_000, help="work units of jsr_bounds")
    ap.add_argument("--quick", action="store_true", help="skip the 16x16 cases and large Daubechies")
    ap.add_argument("--only", help="run the cases whose name contains this text")
    ap.add_argument("--factor", type=float, default=BRUTE_FACTOR,
                    help=f"brute force stops after this many times our CPU time (default {BRUTE_FACTOR:g})")
    args = ap.parse_args()
    print(f"budget {args.budget} work units; CPU seconds (time.process_time); brute-force gaps are floats; "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    print()
    print("| case | n | status | certified [lower, upper] | gap | units | CPU s | units/CPU s | "
          "inf-norm brute force: gap in our CPU | its CPU to our gap | balanced brute force: "
          "gap in our CPU | its CPU to our gap |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], method="polytope")   # warm-up: imports
    for name, mats in cases(args.quick):
        if args.only and args.only not in name:
            continue
        F = parse_family(mats)
        gc.collect()
        t = time.process_time()
        r = jsr_bounds(mats, budget=args.budget, rel_gap=1e-9)
        cpu = time.process_time() - t
        gap = float(r.upper / r.lower - 1) if r.lower > 0 else float("inf")
        units = r.provenance["work"]
        bi = brute(F.floats, "inf", cpu, gap, args.factor)
        bb = brute(F.floats, "balanced", cpu, gap, args.factor)
        print(f"| {name} | {F.n} | {r.status} | [{float(r.lower):.12g}, {float(r.upper):.12g}] | "
              f"{gap:.2e} | {units} | {cpu:.2f} | {units / max(cpu, 1e-3):.0f} | {fmt_bf(bi)} | "
              f"{fmt_bf(bb)} |", flush=True)


if __name__ == "__main__":
    main()
