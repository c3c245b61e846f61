"""Benchmark: the certified C^1 set of the butterfly family on [0, 1/8] (``subdiv surface --scheme butterfly --C 1
--within=0,1/8 --grid-cells 4``), with the strip next to the exact end w = 1/8 closed exactly (the leading
subspace of dimension 14 where the JSR is 4w, the convex hull in 1/(4w), the quotient's JSR below 1/2).

Prints the CLI text, then the CPU seconds (``time.process_time``: this process only) of the whole C^1 set and
the work units it counted.

Run:  python benchmarks/bench_butterfly_c1_set.py
"""

from __future__ import annotations

import time

from analysis.cli.main import main


def run() -> float:
    t0 = time.process_time()
    main(["surface", "--scheme", "butterfly", "--C", "1", "--within=0,1/8", "--grid-cells", "4"])
    return time.process_time() - t0


if __name__ == "__main__":
    cpu = run()
    print(f"CPU {cpu:.1f} s")
