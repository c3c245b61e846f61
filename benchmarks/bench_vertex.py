"""Extraordinary vertices: CPU seconds per valence of the certified analysis (spectrum, Reif's conditions,
curvature, characteristic map; for the butterfly family where an eigen-condition fails, the not-C^1 theorem of
analysis.vertex.necessary, whose first use includes the regular part's derivative bound, about 5 s) for Loop, Catmull–Clark, the butterfly family and sqrt(3) at valences 3..50.

Run: ``python benchmarks/bench_vertex.py [N [SCHEME ...]]`` (valences 3..N, default 50; all schemes by default). Process time, not wall-clock:
the shared machine's load does not enter. The first valence of each scheme includes one-time work (the
generic block polynomial; for Loop the Bézier form of the box-spline patch).
"""

from __future__ import annotations

import sys
import time

from analysis.vertex.rules import scheme_rules
from analysis.vertex.valence import closed_form_lambda, valence_entry


#: scheme and the rings it is analysed on (the command's defaults)
SCHEMES = (("loop", 2), ("catmull-clark", 2), ("butterfly", 3), ("modified-butterfly", 3), ("sqrt3", 2))


def main(top: int = 50, names: tuple[str, ...] = ()) -> None:
    for name, ring in SCHEMES:
        if names and name not in names:
            continue
        closed = closed_form_lambda(scheme_rules(name, ring))
        times, certified, refuted, reif, fails = [], 0, [], 0, 0
        for n in range(3, top + 1):
            t = time.process_time()
            e = valence_entry(scheme_rules(name, ring, n), n, closed)
            times.append(time.process_time() - t)
            certified += e["c1"]["status"] == "certified"
            if e["c1"]["status"] == "refuted":
                refuted.append(n)
            reif += e["reif"]["value"] is True and e["reif"]["status"] == "certified"
            fails += e["reif"]["value"] is False and e["reif"]["status"] == "certified"
        print(f"{name:<18} valences 3..{top}: total {sum(times):6.1f} s CPU, mean {sum(times) / len(times):.2f} s, "
              f"max {max(times):.2f} s (n = {3 + times.index(max(times))}); eigen-conditions certified to hold at "
              f"{reif} and to fail at {fails}, C^1 certified at {certified} of {len(times)}"
              + (f", not C^1 certified at {len(refuted)} (n = {', '.join(map(str, refuted))})" if refuted else ""))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 50, tuple(sys.argv[2:]))
