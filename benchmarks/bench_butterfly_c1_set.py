"""Benchmark: the butterfly family's C^1 set next to its exact end w = 1/8, closed exactly.

``close_end_strip`` on the restricted transition operators ``T_eps(w)|V_2`` (dimension 43, affine in w) between
the C^1 grid point ``w = START`` (default 1/16) and the end ``w = 1/8``, where each of the four digits has the
eigenvalue ``4w = 1/2``: the leading subspace (dimension 14, where the JSR is ``4w``: an exact invariant polytope
of the convex hull of ``T(START)/(4 START)`` and ``T(1/8)/(1/2)``), and the quotient (dimension 29, the JSR of its
hull below 1/2 by the engine). This is the step ``subdiv surface --scheme butterfly --C 1 --within=0,1/8`` runs
for the right end after its grid verdicts and boxes (``--grid-cells 2`` starts it at 1/16, ``4`` at 3/32).

Prints the result and the CPU seconds (``time.process_time``: this process only).

Run:  python benchmarks/bench_butterfly_c1_set.py [START]
"""

from __future__ import annotations

import sys
import time

from flint import fmpq

from analysis.bivariate.end_strip import close_end_strip
from analysis.bivariate.ranges import ParametricFamily
from schemes.surfaces import get


def run(start: fmpq) -> dict:
    F = ParametricFamily(get("butterfly").mask(general=True), 2)
    return close_end_strip(F.C, fmpq(1, 2), fmpq(1, 8), start)


if __name__ == "__main__":
    start = fmpq(*map(int, (sys.argv[1] if len(sys.argv) > 1 else "1/16").split("/")))
    t0 = time.process_time()
    r = run(start)
    cpu = time.process_time() - t0
    for k, v in r.items():
        print(f"{k}: {v}")
    print(f"CPU {cpu:.1f} s")
