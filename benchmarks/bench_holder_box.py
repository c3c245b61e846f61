"""Issue 13 item 5: `subdiv holder --box` (C^k of a level-dependent scheme on a whole parameter box; m-ary: item 6).

Run: ``python benchmarks/bench_holder_box.py`` (2 cores shared). Each command runs in a fresh process,
as a researcher types it; prints wall and child CPU time and the conclusion line.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time

COMMANDS = [
    ["holder", "--scheme", "exp-cubic-trig", "--box", "t=1/10,3"],
    ["holder", "--symbol", "(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2", "--where", "c=cos(theta/2**(n+1))",
     "--box", "theta=1/10,pi/2"],
    ["holder", "--scheme", "seed003-trigonometric", "--box", "alpha=0,pi/3", "--box", "omega=0,(sqrt(6)-1)/80",
     "--open", "omega"],
    ["holder", "--scheme", "seed003-trigonometric", "--box", "alpha=0,pi/3", "--box", "omega=0,(sqrt(6)-1)/80"],
    ["holder", "--scheme", "exp-cubic-hyp", "--box", "t=1/10,3"],
    ["holder", "--scheme", "exp-quintic-trig", "--box", "t=1/10,3"],
    # issue 12/13 item 6: m-ary level-dependent schemes on a box
    ["holder", "--scheme", "ternary-exp-bspline-3-trig", "--box", "t=1/10,2"],
    ["holder", "--scheme", "quaternary-exp-bspline-3-hyp", "--box", "t=1/10,2"],
    ["holder", "--arity", "3", "--symbol", "(1+z+z**2)*(1+2*c*z+(1+2*d)*z**2+2*c*z**3+z**4)/((3+4*c+2*d)*z**3)",
     "--where", "c=cos(theta/3**(n+1))", "--where", "d=cos(2*theta/3**(n+1))", "--box", "theta=1/2,2"],
]


def main() -> None:
    for argv in COMMANDS:
        c0 = os.times()
        t0 = time.perf_counter()
        out = subprocess.run([sys.executable, "-m", "analysis", *argv], capture_output=True, text=True,
                             check=True).stdout
        wall = time.perf_counter() - t0
        c1 = os.times()
        cpu = (c1.children_user - c0.children_user) + (c1.children_system - c0.children_system)
        last = out.strip().splitlines()[-1].strip()
        print(f"{wall:6.1f} s wall / {cpu:5.1f} s CPU  subdiv {' '.join(argv)}\n        {last}")


if __name__ == "__main__":
    main()
