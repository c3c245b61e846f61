"""Issue 11, seed 004 as data: CPU time of each claim of ``subdiv report 004`` grouped by kind (the new
kinds "eigenvalue inequality", "end rules", "gibbs" beside the others), evaluated in this process.

Run: ``python benchmarks/bench_seed004.py`` (prints one line per kind: claims, total and largest CPU seconds).
"""

from __future__ import annotations

import time
from collections import defaultdict


def main() -> None:
    from analysis.claims import evaluate_claim, get_paper

    paper = get_paper("004")
    by_kind: dict = defaultdict(list)
    t_all = time.process_time()
    for claim in paper.claims:
        t = time.process_time()
        ev = evaluate_claim(claim)
        by_kind[claim.kind].append((time.process_time() - t, claim.id, ev.verdict.label))
    total = time.process_time() - t_all
    print(f"{'kind':<24} {'claims':>6} {'CPU s':>8} {'largest':>8}  slowest claim")
    for kind, rows in sorted(by_kind.items(), key=lambda kv: -sum(r[0] for r in kv[1])):
        worst = max(rows)
        print(f"{kind:<24} {len(rows):>6} {sum(r[0] for r in rows):>8.2f} {worst[0]:>8.2f}  {worst[1]}")
    print(f"{'all':<24} {len(paper.claims):>6} {total:>8.2f}")


if __name__ == "__main__":
    main()
