"""Issue 13 (not C^k): exact recognition of exponential B-spline schemes, and `subdiv holder` on them.

Run: ``python benchmarks/bench_not_ck.py`` (target on 2 cores: `subdiv holder` under 10 s per scheme).
Prints, per catalogue scheme, the time of :func:`analysis.levels.expbspline.not_ck` (in process) and
of the full `subdiv holder --scheme NAME --param t=1` (a fresh process, as a researcher types it).
"""

from __future__ import annotations

import subprocess
import sys
import time


def main() -> None:
    from analysis.levels.expbspline import not_ck
    from schemes.level_dependent import get

    for kind in ("chaikin", "cubic", "quartic", "quintic"):
        for fam in ("trig", "hyp"):
            slug = f"exp-{kind}-{fam}"
            t0 = time.perf_counter()
            r = not_ck(get(slug).subs({"t": 1}))
            t1 = time.perf_counter()
            out = subprocess.run([sys.executable, "-m", "analysis", "holder", "--scheme", slug, "--param", "t=1"],
                                 capture_output=True, text=True, check=True).stdout
            t2 = time.perf_counter()
            last = out.strip().splitlines()[-1].strip()
            print(f"{slug:18s} not C^{r.witness['k']} [{r.status}] recognition {t1 - t0:5.2f} s; "
                  f"holder {t2 - t1:5.2f} s: {last}")


if __name__ == "__main__":
    main()
