"""Extraordinary vertices: CPU seconds per valence of the certified analysis (spectrum, Reif's conditions,
curvature, characteristic map) for Loop and Catmull–Clark at valences 3..50.

Run: ``python benchmarks/bench_vertex.py [N]`` (valences 3..N, default 50). Process time, not wall-clock:
the shared machine's load does not enter. The first valence of each scheme includes one-time work (the
generic block polynomial; for Loop the Bézier form of the box-spline patch).
"""

from __future__ import annotations

import sys
import time

from analysis.vertex.rules import scheme_rules
from analysis.vertex.valence import closed_form_lambda, valence_entry


def main(top: int = 50) -> None:
    for name in ("loop", "catmull-clark"):
        closed = closed_form_lambda(scheme_rules(name))
        times, certified = [], 0
        for n in range(3, top + 1):
            t = time.process_time()
            e = valence_entry(scheme_rules(name, 2, n), n, closed)
            times.append(time.process_time() - t)
            certified += e["c1"]["status"] == "certified"
        print(f"{name:<14} valences 3..{top}: total {sum(times):6.1f} s CPU, mean {sum(times) / len(times):.2f} s, "
              f"max {max(times):.2f} s (n = {3 + times.index(max(times))}); C^1 certified at {certified} of "
              f"{len(times)}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 50)
