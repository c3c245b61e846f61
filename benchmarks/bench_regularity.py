"""Benchmark: certified Hölder exponents (numbers for the README), against the textbook methods.

1. Every catalogue scheme with at most 12 mask coefficients (parameters at their default or a
   representative value, listed in the table): certified alpha with gap <= 1e-6
   (:func:`analysis.regularity.holder.holder_exponent`: invariant polytope JSR, exact/Arb certificate).
2. Daubechies D4 ... D54 from certified ball masks
   (:func:`analysis.regularity.holder_exponent`).
3. Seed 003's C^2 boundary located to 1e-8 (:func:`analysis.regularity.ck_parameter_set`).
4. In the same run, the textbook approach on the same schemes: the exact Dyn–Levin norm
   ``||(1/2 S_{a_N})^L||_inf^(1/L)`` (an upper bound of the JSR; catalogue schemes) or the float
   max norm over all ``2^L`` products (Daubechies), with the float brute-force spectral radius
   over all products of length <= L (a lower bound), for L = 1, 2, ... until the alpha gap is
   <= 1e-6 or the time cap; the speed-up is textbook time / certified time (a lower bound ">"
   when the textbook method did not reach the gap).

Run:  python benchmarks/bench_regularity.py [--daub-budget UNITS] [--cap S] [--max-daub N] [--quick]
      python benchmarks/bench_regularity.py --only-daub --min-daub 10 --max-daub 20 --daub-budget 150000
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

import numpy as np
import sympy as sp

import schemes
from analysis.stationary.difference import difference_norm
from analysis.jsr import brute_force_bounds
from analysis.regularity import ck_parameter_set, difference_mask, holder_exponent
from analysis.regularity.balls import ball_divide_by_one_plus_z, ball_transition_matrices
from analysis.stationary.transition import transition_matrices

R = sp.Rational
#: representative parameter values where the catalogue has no default (or a special one)
REPRESENTATIVE = {
    "four-point": [{"w": R(1, 16)}, {"w": R(1, 32)}],
    "dfh-chaikin-perturbation": [{"omega": R(1, 128)}, {"omega": R(1, 100)}],
    "seed004-design-control": [{"mu": R(1, 50), "nu": R(1, 2), "omega": R(1, 50)}],
    "seed004-t-nu": [{"nu": R(1, 2)}],
    "seed004-l-mu": [{"mu": R(1, 20)}],
}
GAP = 1e-6


def catalogue_cases() -> list[tuple[str, object]]:
    out = []
    for name in schemes.names():
        e = schemes.get(name)
        a = e.symbol
        if len(a.mask) > 12:
            continue
        if a.params:
            for vals in REPRESENTATIVE.get(name, [dict(e.defaults)]):
                sub = {p: vals[p.name] for p in a.params}
                label = name + " (" + ", ".join(f"{k}={v}" for k, v in vals.items()) + ")"
                out.append((label, a.subs(sub)))
        else:
            out.append((name, a))
    return out


def textbook_alpha_gap(k: int, norm_upper, floats: list[np.ndarray], cap: float,
                       max_L: int = 24) -> dict:
    """Textbook bounds for L = 1, 2, ...: alpha in [k - log2 U_L, k - log2 l_L] with
    ``U_L = min_{l<=L} norm_upper(l)`` and ``l_L`` the brute-force spectral radius over all
    products of length <= L. Stops at gap <= GAP, at the time cap, or at max_L."""
    t0 = time.perf_counter()
    best_u, L, gap = math.inf, 0, math.inf
    n = floats[0].shape[0]
    lower = 0.0
    while L < max_L:
        L += 1
        if 2 ** L * n * n * 8 > 3e8:
            L -= 1
            break
        t_l = time.perf_counter()
        best_u = min(best_u, norm_upper(L))
        bf = brute_force_bounds(floats, L)
        lower = max(lower, bf["lower"])
        gap = math.log2(best_u) - math.log2(lower) if lower > 0 else math.inf
        el = time.perf_counter() - t0
        if gap <= GAP or el + 2.5 * (time.perf_counter() - t_l) > cap:
            break
    return {"L": L, "gap": gap, "seconds": time.perf_counter() - t0, "reached": gap <= GAP}


def catalogue_row(label, a, cap):
    t = time.perf_counter()
    h = holder_exponent(a, budget=60_000, rel_gap=5e-7, max_length=16)
    dt = time.perf_counter() - t
    k, c = difference_mask(a)
    T = transition_matrices(c, numeric=True)
    N = k + 1

    def upper(L):
        return float(difference_norm(a, N, L).value) ** (1.0 / L)

    tb = textbook_alpha_gap(k, upper, list(T), cap)
    return h, dt, tb


def daubechies_row(N, budget, cap):
    e = schemes.get(f"daubechies-{2 * N}")
    t = time.perf_counter()
    h = holder_exponent(e, budget=budget, rel_gap=5e-7)
    dt = time.perf_counter() - t
    import flint
    with flint.ctx.workprec(256):
        c = [float(x.mid()) * 2 ** (N - 1) for x in ball_divide_by_one_plus_z(e.enclosure(200), N)]
    T = [np.array(M, dtype=float) for M in ball_transition_matrices(c)]

    def upper(L):       # max over all products of the max row sum (= brute force upper)
        return brute_force_bounds(T, L)["per_length"][-1][2]

    tb = textbook_alpha_gap(N - 1, upper, T, cap)
    return h, dt, tb


def fmt_tb(tb, dt):
    if tb["reached"] and tb["L"] <= 2:
        sp_ = "— (textbook exact at small L)"
    else:
        ratio = tb["seconds"] / max(dt, 1e-3)
        sp_ = f"{ratio:.1f}x" if tb["reached"] else f"> {ratio:.1f}x (gap not reached)"
    g = "inf" if not math.isfinite(tb["gap"]) else f"{tb['gap']:.1e}"
    return f"L={tb['L']}, gap {g}, {tb['seconds']:.2f} s | {sp_}"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--daub-budget", type=int, default=120_000, help="work units of holder_exponent")
    ap.add_argument("--cap", type=float, default=20.0, help="time cap of the textbook method")
    ap.add_argument("--max-daub", type=int, default=20, help="largest N (D2N)")
    ap.add_argument("--min-daub", type=int, default=2, help="smallest N (D2N)")
    ap.add_argument("--only-daub", action="store_true",
                    help="only section 2 (Daubechies), e.g. to measure the JSR engine")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    if args.quick:
        args.max_daub, args.cap = min(args.max_daub, 9), 5.0
    if not args.only_daub:
        catalogue_section(args)
    daubechies_section(args)
    if not args.only_daub:
        seed003_section()


def catalogue_section(args) -> None:
    print("## 1. Catalogue schemes with <= 12 coefficients (alpha gap target 1e-6)\n")
    print("| scheme | coeffs | certified alpha | gap | status | s.m.p. | time | "
          "textbook (norms + brute force) | speed-up |")
    print("|---|---|---|---|---|---|---|---|---|")
    times = []
    for label, a in catalogue_cases():
        h, dt, tb = catalogue_row(label, a, args.cap)
        times.append(dt)
        g = float(h.upper - h.lower)
        word = "".join(map(str, h.witness.get("product") or ()))
        print(f"| {label} | {len(a.mask)} | [{float(h.lower):.9f}, {float(h.upper):.9f}] | "
              f"{g:.1e} | {h.status} | {word} | {dt:.2f} s | {fmt_tb(tb, dt)} |", flush=True)
    print(f"\nmedian certified time: {statistics.median(times):.2f} s "
          f"(max {max(times):.2f} s, {len(times)} schemes)\n")


def daubechies_section(args) -> None:
    print("## 2. Daubechies D%d ... D%d (ball masks)\n" % (2 * args.min_daub, 2 * args.max_daub))
    print("| scheme | matrix size | certified alpha | gap | status | s.m.p. | vertices | time | "
          "textbook (brute force, floats) | speed-up |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for N in range(args.min_daub, args.max_daub + 1):
        h, dt, tb = daubechies_row(N, args.daub_budget, args.cap)
        j = h.witness["jsr"]
        g = float(h.upper - h.lower)
        word = "".join(map(str, h.witness.get("product") or ()))
        print(f"| D{2 * N} | {h.witness['matrix_size']} | [{float(h.lower):.10f}, "
              f"{float(h.upper):.10f}] | {g:.1e} | {h.status} | {word} | "
              f"{j.witness['polytope_vertices']} | {dt:.1f} s | {fmt_tb(tb, dt)} |", flush=True)


def seed003_section() -> None:
    print("\n## 3. Seed 003: C^2 boundary of the DFH perturbation of Chaikin\n")
    t = time.perf_counter()
    r = ck_parameter_set(schemes.get("dfh-chaikin-perturbation").symbol, 2,
                         within=(-R(1, 20), R(1, 20)), grid=10)
    dt = time.perf_counter() - t
    print(f"status {r.status}, {dt:.1f} s")
    for b in r.witness["boundaries"]:
        br = b.get("bracket")
        width = float(abs(sp.N(br[1] - br[0], 30))) if br else float("nan")
        print(f"- boundary {b.get('exact', '')} ~ {b.get('exact_float', '')}: bracket "
              f"{tuple(sp.sstr(x) for x in br)}, width {width:.2e}, {b.get('how')}, {b['status']}")


if __name__ == "__main__":
    main()
