"""CPU time of certified JSR computations (``jsr_bounds``), this checkout against another one.

Cases: the Daubechies transition pairs ``T_0, T_1`` (D4 to D40, Arb ball entries: the Hölder
exponents of ``subdiv holder --scheme daubechies-2N``), the random nonnegative pairs (4x4, 8x8,
16x16), the classical families of ``bench_jsr.py`` and the three hard random signed pairs of
``bench_jsr.py`` (there the polytope does not close and the whole budget is spent: what is
compared is the CPU time of the same counted work, and the certified bounds must be equal).

Each case runs in a fresh interpreter per checkout (``python bench_jsr_speed.py --root DIR --case
NAME``), the two checkouts alternately case by case so that both see the same load; inside, one
warm-up call pays the imports, then the case runs ``--runs`` times (a fast case more often, until
its runs add up to a CPU second, a slow one, over 5 s, once) and the minimum CPU time (``time.process_time``) is kept. The bounds of both checkouts are printed as fractions' hashes
so that a change of result shows. Not a test: timings are never asserted.

Run::

    python benchmarks/bench_jsr_speed.py                        # this checkout
    python benchmarks/bench_jsr_speed.py --before /path/to/old  # old vs this, side by side
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BUDGET = 20_000
#: a fast case is repeated until its runs add up to this many CPU seconds (at most MAX_RUNS runs)
MIN_CPU = 1.0
MAX_RUNS = 50
#: a case that took this many CPU seconds is not repeated
SLOW_CPU = 5.0


def _cases() -> dict:
    """name -> (function building the family, budget)."""
    import bench_jsr as B

    out = {}
    for N in (2, 4, 6, 8, 10, 12, 15, 20):
        out[f"Daubechies D{2 * N}"] = (lambda N=N: B.daubechies_pair(N), BUDGET)
    for n in (4, 8, 16):
        out[f"nonneg {n}x{n} seed 1"] = (lambda n=n: B.random_pair(1, n, 0), BUDGET)
    for name, mats in B.cases(quick=True):
        if not name.startswith(("Daubechies", "nonneg", "signed")):
            out[name] = (lambda mats=mats: mats, BUDGET)
    for n, seed in ((8, 1), (16, 1), (16, 2)):
        out[f"signed {n}x{n} seed {seed}"] = (lambda n=n, seed=seed: B.random_pair(seed, n, -9), BUDGET)
    return out


def run_case(name: str, runs: int) -> dict:
    """In this interpreter: the minimum CPU seconds of ``runs`` runs of the case."""
    from analysis.jsr import jsr_bounds

    build, budget = _cases()[name]
    mats = build()
    jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], method="polytope")     # warm-up: imports
    best, r, done, spent = None, None, 0, 0.0
    while (done < runs and spent < SLOW_CPU) or (spent < MIN_CPU and done < MAX_RUNS):
        t = time.process_time()
        r = jsr_bounds(mats, budget=budget, rel_gap=1e-9)
        cpu = time.process_time() - t
        best = cpu if best is None else min(best, cpu)
        done, spent = done + 1, spent + cpu
    digest = hashlib.sha1(f"{r.lower}|{r.upper}|{r.status}".encode()).hexdigest()[:10]
    return {"cpu": best, "status": r.status, "gap": float(r.upper / r.lower - 1) if r.lower > 0 else None,
            "work": r.provenance.get("work"), "result": digest}


def measure(root: Path, name: str, runs: int) -> dict:
    """The case in a fresh interpreter running ``root``'s code."""
    p = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--root", str(root), "--case", name,
                        "--runs", str(runs)], capture_output=True, text=True, cwd=root)
    if p.returncode != 0:
        raise SystemExit(f"case {name!r} failed in {root}: {p.stderr[-600:]}")
    return json.loads(p.stdout.strip().splitlines()[-1])


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=2, help="runs per case (the minimum is shown; default 2)")
    ap.add_argument("--before", metavar="DIR", help="another checkout to compare with")
    ap.add_argument("--only", help="the cases whose name contains this text")
    ap.add_argument("--root", help=argparse.SUPPRESS)
    ap.add_argument("--case", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.case:                       # child: one case of one checkout
        sys.path.insert(0, args.root)
        print(json.dumps(run_case(args.case, args.runs)))
        return
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at the start; min of {args.runs} "
          f"runs; CPU seconds (time.process_time) of jsr_bounds(budget={BUDGET}, rel_gap=1e-9)")
    roots = [("before", Path(args.before).resolve())] if args.before else []
    roots.append(("after" if args.before else "this", ROOT))
    cols = " | ".join(f"{name} CPU s" for name, _ in roots)
    print(f"| case | status | gap | units | {cols} |" + (" ratio | same bounds |" if args.before else ""))
    print("|---|---|---|---|" + "---|" * len(roots) + ("---|---|" if args.before else ""))
    for name in _cases():
        if args.only and args.only not in name:
            continue
        res = [measure(root, name, args.runs) for _, root in roots]
        last = res[-1]
        gap = f"{last['gap']:.1e}" if last["gap"] is not None else "-"
        row = f"| {name} | {last['status']} | {gap} | {last['work']} | " + " | ".join(f"{r['cpu']:.3f}" for r in res) + " |"
        if args.before:
            row += f" {res[0]['cpu'] / max(res[1]['cpu'], 1e-9):.2f}x | {'yes' if res[0]['result'] == res[1]['result'] else 'NO'} |"
        print(row, flush=True)
    print(f"load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    main()
