"""Issue 13 item 2: `subdiv holder` on exponential B-splines without the frequency 0 (generalized differences).

Run: ``python benchmarks/bench_gendiff.py`` (target on 2 cores: `subdiv holder` under 10 s per scheme).
Each line is one fresh process ``python -m analysis holder --symbol ... --where ...`` as a researcher
types it: the trigonometric / hyperbolic exponential B-splines of degrees 2..5 built from the frequencies
``+-i, +-2i, +-3i`` resp. ``+-1, +-2, +-3`` (odd orders with one real frequency), and the issue's
acceptance command (frequencies ``+-i theta, +-2i theta``, ``theta = 1``).
"""

from __future__ import annotations

import subprocess
import sys
import time

DEFS = {"c1": "cos(1/2**(n+1))", "c2": "cos(2/2**(n+1))", "c3": "cos(3/2**(n+1))",
        "k1": "cosh(1/2**(n+1))", "k2": "cosh(2/2**(n+1))", "k3": "cosh(3/2**(n+1))",
        "e1": "exp(1/2**(n+1))", "e3": "exp(3/2**(n+1))"}
PAIR, REAL = "(1+2*{v}*z+z**2)/(2+2*{v})", "(1+{v}*z)/(1+{v})"
FAMILIES = {
    "trig deg 2": [(PAIR, "c1"), (REAL, "e1")], "hyp deg 2": [(PAIR, "k1"), (REAL, "e3")],
    "trig deg 3": [(PAIR, "c1"), (PAIR, "c2")], "hyp deg 3": [(PAIR, "k1"), (PAIR, "k2")],
    "trig deg 4": [(PAIR, "c1"), (PAIR, "c2"), (REAL, "e1")], "hyp deg 4": [(PAIR, "k1"), (PAIR, "k2"), (REAL, "e3")],
    "trig deg 5": [(PAIR, "c1"), (PAIR, "c2"), (PAIR, "c3")], "hyp deg 5": [(PAIR, "k1"), (PAIR, "k2"), (PAIR, "k3")],
}


def _args(factors) -> list[str]:
    nf = sum(2 if f is PAIR else 1 for f, _ in factors)
    sym = "2*" + "*".join(f.format(v=v) for f, v in factors) + f"/z**{nf // 2}"
    out = ["--symbol", sym]
    for _, v in factors:
        out += ["--where", f"{v}={DEFS[v]}"]
    return out


def main() -> None:
    cases = {"acceptance": ["--symbol", "2*(1+2*c1*z+z**2)*(1+2*c2*z+z**2)/((2+2*c1)*(2+2*c2))/z**2",
                            "--where", "c1=cos(theta/2**(n+1))", "--where", "c2=cos(2*theta/2**(n+1))",
                            "--param", "theta=1"]}
    cases.update({name: _args(f) for name, f in FAMILIES.items()})
    for name, args in cases.items():
        t0 = time.perf_counter()
        out = subprocess.run([sys.executable, "-m", "analysis", "holder", *args],
                             capture_output=True, text=True, check=True).stdout
        t1 = time.perf_counter()
        print(f"{name:12s} holder {t1 - t0:5.2f} s: {out.strip().splitlines()[-1].strip()}", flush=True)


if __name__ == "__main__":
    main()
