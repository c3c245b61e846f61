"""Issue 13, item 5: seed 003's weighted series over the FULL closed (alpha, omega) rectangle
[0, pi/3] x [0, (sqrt6-1)/80] and C^2 of the forms (2)-(5) on the whole open claimed region.

Run: ``python benchmarks/bench_levels_region.py`` (target on 2 cores: the series over the full
rectangle under 60 s). Each line runs the command in a fresh process, as a researcher would type it;
wall time and the process CPU time (user + sys of the child) are printed.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time

BOX = ["--box", "alpha=0,pi/3", "--box", "omega=0,(sqrt(6)-1)/80"]
FORMS = ["seed003-trigonometric", "seed003-hyperbolic", "seed003-trigonometric-normalized",
         "seed003-hyperbolic-normalized"]

CASES = ([(f"series m = 1 of e^n, {f}", ["series", "--scheme", f, "--difference", "1", *BOX, "--m", "1"])
          for f in FORMS]
         + [(f"C^2 on the open region, {f}", ["series", "--scheme", f, "--difference", "1", *BOX, "--C", "2",
                                              "--open", "omega"]) for f in FORMS])


def main() -> None:
    for label, argv in CASES:
        cmd = [sys.executable, "-m", "analysis", *argv]
        before = os.times()
        t = time.perf_counter()
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        dt = time.perf_counter() - t
        after = os.times()
        cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
        first = out.strip().splitlines()[0 if "--C" in argv else -1].strip()
        print(f"{label:<58} {dt:6.2f} s wall {cpu:6.2f} s cpu   {first[:110]}")


if __name__ == "__main__":
    main()
