"""Daubechies D4-D12 typed in closed form: certified alpha through `subdiv holder --mask`.

Closed forms as a user would paste them: D4 (sqrt 3) and D6 (sqrt 10, sqrt(5 + 2 sqrt 10)) as real
radicals; D8/D10 sympy's radical roots of the spectral factorisation (with I that cancels; D8
Cardano, D10 Ferrari with a cube root of a complex number and square roots on the branch cut);
D12 (a quintic) with CRootOf. Each is compared with the catalogue's ball version
(`--scheme d2N`); the last column says how N, a(1) = 2 and the reality of the coefficients were
proven (see the "Zero test" section of `analysis/closed_form.py`).

    python benchmarks/bench_closed_form.py          # target: certified, < 5 s each
    python benchmarks/bench_closed_form.py 4 6      # some orders only
"""

from __future__ import annotations

import contextlib
import io
import json
import sys
import time
from math import comb

import sympy as sp

from analysis.cli import main
from analysis.jsonable import fmt_bound
from analysis.algebra.zero_test import enclose


def daubechies_closed_form(N: int) -> list[str]:
    """Coefficient strings of the D2N mask a = sqrt(2) h (a(1) = 2), extremal phase."""
    if N == 2:
        return ["(1+sqrt(3))/4", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3))/4"]
    if N == 3:
        s = "sqrt(5+2*sqrt(10))"
        return [f"(1+sqrt(10)+{s})/16", f"(5+sqrt(10)+3*{s})/16", f"(10-2*sqrt(10)+2*{s})/16",
                f"(10-2*sqrt(10)-2*{s})/16", f"(5+sqrt(10)-3*{s})/16", f"(1+sqrt(10)-{s})/16"]
    y = sp.Symbol("y")
    P = sp.Poly(sum(comb(N - 1 + k, k) * y**k for k in range(N)), y)
    ys = list(sp.roots(P, y, multiple=True)) if N <= 5 else P.all_roots()
    zs = []
    for yk in ys:
        w = 2 - 4 * yk
        zs.append(next(zc for zc in ((w + sg * sp.sqrt(w**2 - 4)) / 2 for sg in (1, -1))
                       if abs(enclose(zc, 64)) > 1))     # certified |z| > 1 (sympy's evalf is slow here)
    c = [sp.Integer(1)]
    for zc in zs:   # prod (z - z_k), constant term first, radicals not expanded
        c = [(c[i - 1] if i else 0) - (zc * c[i] if i < len(c) else 0) for i in range(len(c) + 1)]
    den = sp.Mul(*[1 - zc for zc in zs])
    return [sp.sstr(2 * sum(comb(N, i - j) * c[j] for j in range(len(c)) if 0 <= i - j <= N) / (2**N * den),
                    order="none")   # sympy's term ordering evaluates CRootOfs: slow
            for i in range(N + len(c))]


def _run(argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()) as err:
        rc = main(argv + ["--json"])
    return rc, (json.loads(out.getvalue()) if rc == 0 else err.getvalue().strip())


def _route(alpha: dict) -> str:
    """How N, a(1) = 2 and reality were decided: the ball route's zero test, or the exact route."""
    msg = alpha.get("provenance", {}).get("message", "")
    if "decided exactly by the zero test (" in msg:
        return "ball: " + msg.split("decided exactly by the zero test (", 1)[1].rstrip(")")
    return "exact number-field arithmetic"


def main_bench(orders=(2, 3, 4, 5, 6)) -> None:
    _run(["holder", "--scheme", "d4"])      # warm-up: imports are not part of the timings
    print(f"{'D2N':5} {'seconds':>8}  {'status':12} {'alpha (closed form)':33} overlap  zero test")
    for N in orders:
        mask = daubechies_closed_form(N)
        t = time.perf_counter()
        rc, data = _run(["holder", "--mask", ",".join(mask), "--start", "0", "--budget", "20000"])
        dt = time.perf_counter() - t
        _, ref = _run(["holder", "--scheme", f"d{2 * N}"])
        if rc != 0:
            print(f"D{2 * N:<4} {dt:8.2f}  error: {data[:150]}")
            continue
        a = data["alpha"]
        if a.get("lower") is None:
            print(f"D{2 * N:<4} {dt:8.2f}  {a.get('status'):12} {a.get('reason', '')[:150]}")
            continue
        lo, hi = sp.Rational(a["lower"]), sp.Rational(a["upper"])
        rlo, rhi = sp.Rational(ref["alpha"]["lower"]), sp.Rational(ref["alpha"]["upper"])
        print(f"D{2 * N:<4} {dt:8.2f}  {a['status']:12} [{fmt_bound(lo, 'lower', 12)}, {fmt_bound(hi, 'upper', 12)}]  "
              f"{'yes' if lo <= rhi and rlo <= hi else 'NO':7}  {_route(a)}")


if __name__ == "__main__":
    main_bench(tuple(int(x) for x in sys.argv[1:]) or (2, 3, 4, 5, 6))
