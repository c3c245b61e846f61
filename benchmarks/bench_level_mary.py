"""Issue 12 (catalogue): the level-dependent m-ary exponential B-splines of :mod:`schemes.level_mary`.

Run: ``python benchmarks/bench_level_mary.py``. Prints, per entry, the time of the exact generation check
(:func:`analysis.levels.reproduction_mary.generation_mary` of its frequencies) and of the C^k verdicts
(:func:`analysis.levels.mary.level_smoothness_mary` at ``t = 1``), each in a fresh cache state of the entry
(the first call includes the exact series expansion), with the verdicts.
"""

from __future__ import annotations

import time

import sympy as sp


def main() -> None:
    from analysis.levels.mary import level_smoothness_mary
    from analysis.levels.reproduction_mary import generation_mary
    from schemes.level_mary import MARY_ENTRIES, T

    for slug, s in MARY_ENTRIES.items():
        d = int(slug.split("-")[3])
        lam = ([0] if d > 1 else []) + ([sp.I * T, -sp.I * T] if slug.endswith("trig") else [T, -T])
        t0 = time.perf_counter()
        g = generation_mary(s, lam)
        t1 = time.perf_counter()
        r = level_smoothness_mary(s, {"t": 1})
        t2 = time.perf_counter()
        undecided = [(v["k"], v["failed"]) for v in r.witness["verdicts"] if v["status"] != "certified"]
        print(f"{slug:30s} generation of {', '.join(map(str, lam))}: {g.status} {t1 - t0:5.1f} s; "
              f"C^{r.value} {r.status} {t2 - t1:4.1f} s; undecided {undecided}", flush=True)


if __name__ == "__main__":
    main()
