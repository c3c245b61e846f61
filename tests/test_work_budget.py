"""Work budgets decide, the wall clock only reports (DESIGN.md, "Determinism").

* the budget helper (:mod:`analysis.jsr._work`): shares sum to the whole, exhaustion is a count;
* no module of the engine decides on ``time.perf_counter()`` / ``time.time()``: a source scan lists
  every use of a clock and allows it only where it fills a timing field;
* the same ``holder`` command run twice in subprocesses, once on an idle machine and once with both
  cores busy, prints the same JSON document except its top-level ``"timing"`` key.
"""

from __future__ import annotations

import ast
import functools
import json
import os
import re
import subprocess
import sys
import time
import unicodedata
from pathlib import Path

import pytest

from analysis.jsr import Work, jsr_bounds
from analysis.jsonable import hoist_timing

ROOT = Path(__file__).resolve().parent.parent


# --------------------------------------------------------------------------------------------
# the helper
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("total, weights", [(1000, [1, 1, 2]), (7, [1, 1, 1]), (10_001, [9, 16, 1, 4]),
                                            (3, [5, 0, 5]), (0, [1, 2]), (5, [0, 0])])
def test_split_shares_sum_to_the_whole(total, weights):
    w = Work(total)
    w.charge(total // 3)
    parts = w.split(weights)
    assert sum(p.total for p in parts) == w.left
    assert all(p.total >= 0 for p in parts)
    if sum(weights) > 0:              # in proportion, to one unit
        for p, wt in zip(parts, weights):
            assert abs(p.total - w.left * wt / sum(weights)) < 1


def test_shares_charge_their_parent_and_exhaust_by_count():
    w = Work(100)
    s = w.share(0.25)
    assert (s.total, s.exhausted, w.left) == (25, False, 100)
    for _ in range(24):
        s.charge()
    assert not s.exhausted and w.spent == 24
    s.charge()
    assert s.exhausted and w.left == 75 and not w.exhausted
    grand = s.sub(10)                 # nothing left in s: an empty child, exhausted at once
    assert grand.total == 0 and grand.exhausted
    t = w.sub(10 ** 9)                # never more than what is left
    assert t.total == 75
    t.charge(80)                      # the last step may overrun
    assert t.exhausted and w.exhausted and w.left == 0


def test_exhaustion_is_deterministic():
    def run():
        w, trace = Work(1000), []
        phases = [w.share(f) for f in (0.25, 0.5)]
        for i, p in enumerate(phases):
            while not p.exhausted:
                p.charge(7 + i)
                trace.append((i, p.spent, w.left))
        return trace
    assert run() == run()


@pytest.mark.parametrize("bad", [-1, float("inf"), float("nan"), "10"])
def test_bad_budgets_are_refused(bad):
    with pytest.raises(ValueError):
        Work(bad)


def test_jsr_bounds_reports_its_work_and_timing():
    r = jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], budget=5000)
    prov = r.provenance
    assert prov["budget"] == 5000 and 0 < prov["work"] <= 5000
    assert set(prov["timing"]) == {"seconds"} and "seconds" not in prov
    assert "seconds" not in r.witness["search"] and "work" in r.witness["search"]
    again = jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], budget=5000)
    assert (again.lower, again.upper, again.provenance["work"]) == (r.lower, r.upper, prov["work"])


def test_a_small_budget_is_inconclusive_the_same_way_every_time():
    fam = [[[1, 1], [0, 1]], [[1, 0], [0, "1/2"]]]          # the polytope cannot close
    runs = [jsr_bounds(fam, method="polytope", budget=300, max_length=4) for _ in range(2)]
    assert all(r.status == "inconclusive" for r in runs)
    a, b = (dict(r.to_json()) for r in runs)
    for d in (a, b):
        d["provenance"] = {k: v for k, v in d["provenance"].items() if k != "timing"}
    assert a == b
    assert "work budget exhausted" in json.dumps(a)


def test_hoist_timing_moves_every_timing_to_the_top():
    doc = {"a": {"provenance": {"timing": {"seconds": 1.5}, "x": 1}},
           "rows": [{"timing": {"seconds": 2}}, {"y": [{"timing": 3}]}]}
    out = hoist_timing(doc)
    assert out["timing"] == {"a.provenance": {"seconds": 1.5}, "rows[0]": {"seconds": 2}, "rows[1].y[0]": 3}
    assert "timing" not in json.dumps({k: v for k, v in out.items() if k != "timing"})
    assert hoist_timing({"x": 1}) == {"x": 1}


# --------------------------------------------------------------------------------------------
# no decision on the wall clock
# --------------------------------------------------------------------------------------------

#: every function of the engine that reads a clock; each may only fill a timing field (a
#: ``"timing"`` entry, a ``seconds`` record of the claim evaluation, or text printed to stderr)
ALLOWED_CLOCKS = {
    ("analysis/cli/vertex.py", "cmd_vertex"),
    ("analysis/jsr/__init__.py", "jsr_bounds"),
    ("analysis/jsr/_search.py", "smp_search"),
    ("analysis/regularity/atlas.py", "evaluate_point"),
    ("analysis/regularity/atlas.py", "holder_atlas"),
    ("analysis/regularity/balls.py", "ball_route"),
    ("analysis/regularity/interior.py", "ck_interior"),
    ("analysis/regularity/maximize.py", "maximize_holder"),
    ("analysis/regularity/maximize_box.py", "maximize_holder_box"),
    ("analysis/regularity/sobolev.py", "_exact_route"),
    ("analysis/regularity/sobolev.py", "_ball_route"),
    ("analysis/regularity/sobolev.py", "_autocorrelation_route"),
    ("analysis/jsr/parametric.py", "close_family"),
    ("analysis/claims/model.py", "evaluate_claim"),
    ("analysis/cli/report.py", "_report_file"),
    ("analysis/cli/report.py", "cmd_report"),
    ("analysis/cli/report.py", "cmd_check"),
    ("analysis/progress.py", "on_terminal"),          # how often the progress line is redrawn (stderr)
}
CLOCKS = {"perf_counter", "time", "monotonic", "process_time", "perf_counter_ns", "time_ns", "monotonic_ns"}


def _clock_reads(tree: ast.AST):
    """``(function, line, variable or None)`` of every clock read: ``time.X()`` / ``_time.X()``."""
    out = []

    def visit(node, func):
        for child in ast.iter_child_nodes(node):
            f = child.name if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)) and func is None else func
            if isinstance(child, ast.Call) and isinstance(child.func, ast.Attribute) \
                    and child.func.attr in CLOCKS and isinstance(child.func.value, ast.Name) \
                    and child.func.value.id in ("time", "_time"):
                out.append((func, child.lineno))
            visit(child, f)
    visit(tree, None)
    return out


def _sources():
    for f in sorted((ROOT / "analysis").rglob("*.py")):
        yield f.relative_to(ROOT).as_posix(), f.read_text(encoding="utf-8")


#: a clock read ``time.X()`` / ``_time.X()`` needs the name ``time`` or ``_time`` in the source; an identifier
#: is compared after NFKC normalisation (PEP 3131), so the search runs on the normalised text
_CLOCK_NAME = re.compile(r"\b_?time\b")


@functools.cache
def _tree(rel: str) -> ast.AST:
    """The syntax tree of ``analysis/...`` (parsed once for both scans: parsing the engine is most of their cost)."""
    return ast.parse((ROOT / rel).read_text(encoding="utf-8"))


def _may_read_a_clock(text: str) -> bool:
    return _CLOCK_NAME.search(unicodedata.normalize("NFKC", text)) is not None


def test_no_module_decides_on_the_wall_clock():
    found = set()
    for rel, text in _sources():
        # a module without the name time/_time has no clock read: not parsed (the text checks below still run)
        for func, line in (_clock_reads(_tree(rel)) if _may_read_a_clock(text) else ()):
            assert (rel, func) in ALLOWED_CLOCKS, f"{rel}:{line}: a clock read in {func!r} (not a timing field)"
            found.add((rel, func))
        # the old wall-clock interfaces are gone
        assert "deadline" not in text.replace("deadline=None", ""), f"{rel}: a deadline"
        assert "budget_seconds" not in text and "strip_seconds" not in text, f"{rel}: a seconds budget"
    assert found == ALLOWED_CLOCKS, f"stale entries: {ALLOWED_CLOCKS - found}"


def test_clock_reads_only_fill_timing_fields():
    """In each allowed function, every name assigned from a clock is used only to compute a time
    difference that ends up in a ``timing``/``seconds`` field or in printed text, never in a
    comparison (``if``/``while`` test)."""
    for rel in sorted({rel for rel, _ in ALLOWED_CLOCKS}):     # only these modules hold allowed functions
        for node in ast.walk(_tree(rel)):
            if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) or (rel, node.name) not in ALLOWED_CLOCKS:
                continue
            clock_vars = set()
            for sub in ast.walk(node):
                if isinstance(sub, ast.Assign) and isinstance(sub.value, ast.Call) \
                        and isinstance(sub.value.func, ast.Attribute) and sub.value.func.attr in CLOCKS:
                    clock_vars |= {t.id for t in sub.targets if isinstance(t, ast.Name)}
            for sub in ast.walk(node):
                tests = []
                if isinstance(sub, (ast.If, ast.While, ast.IfExp, ast.Assert)):
                    tests.append(sub.test)
                elif isinstance(sub, ast.comprehension):
                    tests.extend(sub.ifs)
                for t in tests:
                    names = {n.id for n in ast.walk(t) if isinstance(n, ast.Name)}
                    calls = {n.func.attr for n in ast.walk(t) if isinstance(n, ast.Call)
                             and isinstance(n.func, ast.Attribute)}
                    assert not (names & clock_vars) and not (calls & CLOCKS), \
                        f"{rel}:{sub.lineno}: {node.name} decides on a clock"


# --------------------------------------------------------------------------------------------
# the same verdict on a loaded machine
# --------------------------------------------------------------------------------------------

#: Daubechies D8 typed as a 12-digit decimal table (README), with a budget small enough that the
#: s.m.p. search is cut by it (8 of its 16 levels): with a wall-clock budget it would stop at
#: different levels on an idle and on a loaded machine
D8 = ("0.325803428051,1.010945715092,0.892200138246,-0.039575026236,-0.264507167369,0.043616300475,"
      "0.046503601071,-0.014986989330")
HOLDER = ["holder", "--mask", D8, "--approx", "--budget", "30", "--json"]


def _holder_json(capfd) -> dict:
    """``subdiv holder ... --json`` in this process (``tests/cli_run.py``): the clock it could read is
    the same wall clock as a fresh process's, without a fresh interpreter's imports for each run."""
    from tests.cli_run import run_cli

    r = run_cli(capfd, *HOLDER)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_same_json_on_an_idle_and_on_a_loaded_machine(capfd):
    idle = _holder_json(capfd)
    burners = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(2)]
    try:
        time.sleep(0.2)
        loaded = _holder_json(capfd)
    finally:
        for b in burners:
            b.kill()
        for b in burners:
            b.wait()
    assert "timing" in idle and "timing" in loaded
    idle.pop("timing")
    loaded.pop("timing")
    assert idle == loaded
    # the budget decided where the search stopped (it did not run to max_length)
    jsr = idle["alpha"]["witness"]["jsr"]
    assert jsr["witness"]["search"]["levels"] < jsr["provenance"]["max_length"], jsr["witness"]["search"]
    assert jsr["provenance"]["work"] <= jsr["provenance"]["budget"]
