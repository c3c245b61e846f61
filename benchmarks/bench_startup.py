"""Start-up cost of the ``subdiv`` command line: CPU and wall time of a few short commands.

Each command runs as ``python -m analysis ARGS`` in a fresh interpreter (what ``subdiv ARGS`` runs,
without the shell shim of a virtual environment), ``--runs`` times (default 5); the table shows
the minimum of the runs, CPU (user + system of the child, from ``getrusage``) and wall. CPU is the
number to compare on a shared machine: wall time grows with the load, CPU time much less.

Run::

    python benchmarks/bench_startup.py                       # this checkout
    python benchmarks/bench_startup.py --before /path/to/old  # old checkout vs this one, side by side

``--before`` names another checkout (its ``python -m analysis`` runs from there); the table then
shows before, after and the ratio. Not a test: timings are never asserted (see
``tests/test_startup.py`` for the structural check of what the start-up imports).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

COMMANDS = (
    ("--help",),
    ("list",),
    ("holder", "--help"),
    ("holder", "--mask", "1/4,3/4,3/4,1/4"),
    ("holder", "--mask", "-1/16,0,9/16,1,9/16,0,-1/16", "--start", "-3"),
    ("holder", "--scheme", "chaikin"),
    ("holder", "--scheme", "daubechies-8"),
    ("holder", "--scheme", "daubechies-8", "--json"),
)


def run_once(root: Path, args: tuple[str, ...]) -> tuple[float, float]:
    """(CPU seconds, wall seconds) of one ``python -m analysis ARGS`` run from ``root``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "analysis", *args], cwd=root, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise SystemExit(f"`subdiv {' '.join(args)}` failed in {root}: {p.stderr.decode()[-400:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def measure(root: Path, args: tuple[str, ...], runs: int) -> tuple[float, float]:
    """Minimum CPU and minimum wall over ``runs`` runs (after one warm-up run for the byte-code cache)."""
    run_once(root, args)
    samples = [run_once(root, args) for _ in range(runs)]
    return min(c for c, _ in samples), min(w for _, w in samples)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5, help="runs per command (the minimum is shown; default 5)")
    ap.add_argument("--before", metavar="DIR", help="another checkout to compare with (run from there)")
    args = ap.parse_args(argv)
    load = os.getloadavg()[0]
    print(f"{os.cpu_count()} cores, load average {load:.2f} at the start; min of {args.runs} runs; "
          f"{Path(sys.executable).name} {sys.version.split()[0]}")
    roots = [("before", Path(args.before).resolve())] if args.before else []
    roots.append(("after" if args.before else "this", ROOT))
    head = f"{'command':66s}" + "".join(f" {name + ' CPU':>11s} {name + ' wall':>12s}" for name, _ in roots)
    if args.before:
        head += f" {'CPU ratio':>10s}"
    print(head)
    for cmd in COMMANDS:
        row = f"{'subdiv ' + ' '.join(cmd):66s}"
        cpus = []
        for _, root in roots:
            cpu, wall = measure(root, cmd, args.runs)
            cpus.append(cpu)
            row += f" {cpu:10.2f}s {wall:11.2f}s"
        if args.before:
            row += f" {cpus[0] / max(cpus[1], 1e-9):9.1f}x"
        print(row, flush=True)
    print(f"load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
