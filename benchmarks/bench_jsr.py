"""Benchmark: time to a certified JSR interval (relative gap <= 1e-6) with the invariant polytope
algorithm, against the textbook brute force (max norm / max spectral radius over *all* products
up to length L, in floats).

Families (sizes 2..12): the golden-ratio pair, the Daubechies D4 difference pair (entries in
Q(sqrt 3), Arb certificate), transition matrices of difference masks of the Dubuc–Deslauriers
4-, 6- and 8-point schemes (k chosen to give several sizes), and random integer families.

Run:  python benchmarks/bench_jsr.py [--budget UNITS] [--quick]   (work units of jsr_bounds)
Prints a Markdown table for the README.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import sympy as sp

from analysis.jsr import brute_force_bounds, jsr_bounds, parse_family

z = sp.Symbol("z")


def difference_pair(mask: list, start: int, k: int) -> list[sp.Matrix]:
    """T_0, T_1 of c(z) = 2^k a(z) / (1+z)^(k+1), T_e[i, j] = c_{2i-j+e} (N x N, N = len(c)-1)."""
    a = sum(sp.nsimplify(m) * z ** i for i, m in enumerate(mask))   # z^start: a shift only
    q, r = sp.div(sp.Poly(2 ** k * a, z), sp.Poly((1 + z) ** (k + 1), z))
    assert r.is_zero, "mask lacks the factor (1+z)^(k+1)"
    c = q.all_coeffs()[::-1]
    N = len(c) - 1

    def T(e: int) -> sp.Matrix:
        return sp.Matrix(N, N, lambda i, j: c[2 * i - j + e] if 0 <= 2 * i - j + e < len(c) else 0)

    return [T(0), T(1)]


def families(quick: bool) -> list[tuple[str, list, str]]:
    s3 = sp.sqrt(3)
    d4 = [(1 + s3) / 4, (3 + s3) / 4, (3 - s3) / 4, (1 - s3) / 4]
    dd4 = [sp.Rational(x, 16) for x in (-1, 0, 9, 16, 9, 0, -1)]
    dd6 = [sp.Rational(x, 256) for x in (3, 0, -25, 0, 150, 256, 150, 0, -25, 0, 3)]
    dd8 = [sp.Rational(x, 2048) for x in (-5, 0, 49, 0, -245, 0, 1225, 2048, 1225, 0, -245, 0,
                                          49, 0, -5)]
    fams = [
        ("golden pair", [[[1, 1], [0, 1]], [[1, 0], [1, 1]]], "rational"),
        ("D4, k=0 (Q(sqrt3))", difference_pair(d4, 0, 0), "real"),
        ("DD 4-point, k=2", difference_pair(dd4, -3, 2), "rational"),
        ("DD 4-point, k=1 (defective)", difference_pair(dd4, -3, 1), "rational"),
        ("DD 6-point, k=3", difference_pair(dd6, -5, 3), "rational"),
        ("DD 6-point, k=1 (defective)", difference_pair(dd6, -5, 1), "rational"),
        ("DD 8-point, k=5", difference_pair(dd8, -7, 5), "rational"),
        ("DD 8-point, k=3", difference_pair(dd8, -7, 3), "rational"),
    ]
    rng = np.random.default_rng(2024)
    for n in ([4, 8] if quick else [4, 6, 8, 10, 12]):
        for attempt in range(50):     # random integer pairs whose candidate has a real leading
            M = [rng.integers(-5, 6, (n, n)) for _ in range(2)]   # eigenvalue (see README)
            ev = [np.linalg.eigvals(A.astype(float)) for A in M]
            if all(abs(e[np.argmax(abs(e))].imag) < 1e-9 for e in ev):
                break
        fams.append((f"random integer pair n={n}", [m.tolist() for m in M], "rational"))
    return fams


def brute_force(floats: list[np.ndarray], budget: float, max_len: int = 22) -> dict:
    """Textbook bounds for L = 1, 2, ... until the time budget: best gap and its time."""
    best = None
    t0 = time.perf_counter()
    k = len(floats)
    L = 0
    while L < max_len:
        L += 1
        if k ** L * floats[0].shape[0] ** 2 * 8 > 4e8:    # memory for the level's products
            L -= 1
            break
        t = time.perf_counter()
        b = brute_force_bounds(floats, L)
        dt = time.perf_counter() - t0
        best = {"L": L, "lower": b["lower"], "upper": b["upper"],
                "gap": b["upper"] / b["lower"] - 1 if b["lower"] > 0 else float("inf"),
                "seconds": dt}
        if dt + (time.perf_counter() - t) * k * 1.2 > budget:
            break
    return best


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--budget", type=int, default=60_000, help="work units of jsr_bounds")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    rows = []
    print("| family | n | certified interval (float) | rel. gap | status | s.m.p. | L | "
          "vertices | time | brute force: L, gap, time |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, mats, _kind in families(args.quick):
        F = parse_family(mats)
        t = time.perf_counter()
        r = jsr_bounds(mats, budget=args.budget, rel_gap=1e-6, max_length=16)
        dt = time.perf_counter() - t
        bf = brute_force(F.floats, min(args.budget / 1000, max(5.0, 3 * dt)))   # seconds (the textbook method)
        g = float(r.upper / r.lower - 1) if r.lower and r.lower > 0 else 0.0
        word = "".join(map(str, r.witness["product"]))
        row = (f"| {name} | {F.n} | [{float(r.lower):.10f}, {float(r.upper):.10f}] | {g:.1e} | "
               f"{r.status} | {word} | {r.witness['length']} | {r.witness['polytope_vertices']} | "
               f"{dt:.2f} s | L={bf['L']}, {bf['gap']:.1e}, {bf['seconds']:.2f} s |")
        print(row, flush=True)
        rows.append(row)


if __name__ == "__main__":
    main()
