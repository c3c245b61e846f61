"""Issue 13: `subdiv holder` on level-dependent schemes typed inline (exponential B-splines), and
seed 003's weighted series over the whole (alpha, omega) rectangle.

Run: ``python benchmarks/bench_levels.py`` (targets on 2 cores: holder under 10 s, rectangle under 60 s).
Each line runs the command in a fresh process, as a researcher would type it.
"""

from __future__ import annotations

import subprocess
import sys
import time

CASES = [
    ("degree-2 trig, issue example", ["--symbol", "(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2",
                                      "--where", "c=cos(theta/2**(n+1))", "--param", "theta=pi/2"]),
    ("degree-3 hyp (cubic), acosh", ["--symbol", "(1+z)**2*(1+2*v*z+z**2)/(4*(1+v))/z**2",
                                     "--where", "v=cosh(acosh(w)/2**(n+1))", "--param", "w=3"]),
    ("degree-5 trig (catalogue)", ["--scheme", "exp-quintic-trig", "--param", "t=1"]),
]


SERIES = [
    ("seed 003 (2), e^n, m = 1, full rectangle", ["series", "--scheme", "seed003-trigonometric", "--difference", "1",
                                                  "--box", "alpha=0,pi/3", "--box", "omega=1/10000,(sqrt(6)-1)/80",
                                                  "--m", "1", "--depth", "2"]),
]


def main() -> None:
    for label, argv in [(lab, ["holder", *a]) for lab, a in CASES] + SERIES:
        cmd = [sys.executable, "-m", "analysis", *argv]
        t = time.perf_counter()
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        dt = time.perf_counter() - t
        last = out.strip().splitlines()[-1].strip()
        print(f"{label:<42} {dt:6.2f} s   {last}")


if __name__ == "__main__":
    main()
