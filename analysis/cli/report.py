"""``subdiv report`` and ``subdiv check``: proof-check reports of papers and their regression.

* ``subdiv report 004`` (or ``all``) evaluates every claim of the paper(s), writes
  ``<output>/<paper>.md``, ``<output>/<paper>.html``, ``<output>/figures/`` and
  ``<output>/verdicts.json`` (statuses and key numbers of every claim; ``<output>`` is
  ``--output DIR`` or ``reports/`` of the current directory), prints progress on stderr and the
  verdict table on stdout. ``--claim ID`` (repeatable; shell patterns allowed) evaluates and
  prints only those claims (no files are written unless ``--write``). ``--update-golden`` also
  writes each paper's golden verdicts, ``papers/<paper>/verdicts.json`` (in a source checkout).
* ``subdiv check`` re-evaluates every claim of the bundled papers and compares with their golden
  verdicts (shipped inside ``papers/``, so an installed wheel can check itself; ``--verdicts
  FILE`` compares with another file): exit code 0 when everything agrees, 1 with a readable diff
  when a status changed or a number moved beyond its tolerance.

* ``subdiv report FILE.toml`` and ``subdiv check FILE.toml`` do the same for a paper file
  (:mod:`analysis.claims.paperfile`, issue 11); its golden verdicts are ``FILE.verdicts.json``
  beside it (``--update-golden`` writes them). A paper file without golden verdicts yet is checked
  all the same: ``check`` prints its verdicts, says that there is nothing to compare with and how to
  create the golden file, and exits 0 (``--json``: one document with ``"missing_golden"``).

A paper file is data: its ``python`` claims run only with ``--allow-python`` (or for a file of the
bundled ``papers`` package); without it they are inconclusive ("not run") and the rest of the report
is computed as usual. When Python code from a paper file ran, the verdict table, the Markdown and
HTML reports and the JSON verdicts say so.

``--output DIR`` is created when missing (parents too). Every file is written inside it (names are
slugs; symbolic links leading out of it are refused), atomically (temporary file, then rename), and
rewritten on every run; afterwards the figures of ``DIR/figures`` that an earlier run wrote (listed,
with a hash of their bytes, in ``DIR/figures/.subdiv-written.json``) and that no report in ``DIR`` refers
to any more are removed (:func:`analysis.report.files.remove_orphans`); no other file is ever removed. The golden files are what the code
computed, reviewed in the diff of a commit — never typed by hand.

Examples
--------
::

    subdiv report all
    subdiv report 004 --claim '004:Theorem5.2(m=1)'
    subdiv check
    subdiv report examples/four-point.toml --output /tmp/r
    subdiv check examples/four-point.toml
    subdiv report my-paper.toml --allow-python --output /tmp/r     # runs the file's python claims
"""

from __future__ import annotations

import fnmatch
import json
import os
import sys
import time
from pathlib import Path

from ..result import AnalysisError
from .common import _print

#: Default output folder: ``reports/`` of the current directory.
REPORTS = Path("reports")


def _select(paper, patterns):
    if not patterns:
        return None
    ids = [c.id for c in paper.claims if any(fnmatch.fnmatchcase(c.id, p) or c.id == p for p in patterns)]
    return ids


def _progress(quiet: bool):
    from .. import progress

    def show(k, n, ev):
        if not quiet:
            progress.clear()
            print(f"  [{k:>2}/{n}] {ev.claim.id:<34} {ev.verdict.label:<15} {ev.seconds:6.2f} s",
                  file=sys.stderr, flush=True)
    return show


def _table(results) -> str:
    rows = [(ev.claim.id, ev.verdict.label, ev.verdict.summary) for ev in results]
    w0 = max([len(r[0]) for r in rows] + [5])
    w1 = max([len(r[1]) for r in rows] + [7])
    out = [f"{'claim':<{w0}}  {'verdict':<{w1}}  summary", "-" * (w0 + w1 + 60)]
    for cid, lab, summ in rows:
        s = summ if len(summ) <= 110 else summ[:107] + "..."
        out.append(f"{cid:<{w0}}  {lab:<{w1}}  {s}")
    return "\n".join(out)


def _evaluate(paper, args, only):
    """Evaluate the claims (``only``: ids, or None for all) with the per-claim lines on stderr (unless
    ``--quiet``) and, on a terminal, the claim and stage running now (not with ``--quiet`` or ``--json``)."""
    from .. import progress

    with progress.on_terminal(args.func.__name__.removeprefix("cmd_"), enabled=not (args.quiet or args.json)):
        return evaluate_paper(paper, progress=_progress(args.quiet), only=only)


#: the columns of the verdict table written by ``--table``
TABLE_COLUMNS = ("claim", "paper's statement", "verdict", "computed", "witness")
#: its LaTeX column specification (the text columns wrap)
TABLE_SPEC = r"lp{0.3\linewidth}lp{0.3\linewidth}p{0.15\linewidth}"


def verdict_rows(results) -> list[list]:
    """One row per evaluated claim: id, the paper's statement, the verdict, what was computed (the
    verdict's summary, and the corrected statement of a refuted claim) and the witness (each piece of
    evidence that is a computed result, with its status; ``none`` when no result backs the verdict)."""
    from .tables import Name, Quote

    rows = []
    for ev in results:
        v = ev.verdict
        computed = v.summary + (f"; corrected: {v.corrected}" if v.corrected else "")
        witness = "; ".join(f"{e.title} [{e.result.status}]" for e in v.evidence if e.result is not None)
        rows.append([Name(ev.claim.id), Quote(ev.claim.statement), v.label, computed, witness or "none"])
    return rows


def _write_table(path: str, all_results: dict, titles: dict) -> None:
    """``--table``: the verdicts of every evaluated claim as CSV or a LaTeX tabular."""
    from .tables import write_table

    rows = [row for pid in all_results for row in verdict_rows(all_results[pid])]
    caption = ("subdiv: verdicts of " + "; ".join(f"paper {pid} ({titles.get(pid, '')})" for pid in all_results)
               + "\nneeds \\usepackage{booktabs,amsmath,amssymb}")
    write_table(path, TABLE_COLUMNS, rows, caption, spec=TABLE_SPEC)


def evaluate_paper(paper, **kwargs):
    """:func:`analysis.claims.model.evaluate_paper`, imported when a report is computed (the claims
    layer is not imported to build the parser); a module attribute, so that tests can replace it."""
    from ..claims.model import evaluate_paper as evaluate

    return evaluate(paper, **kwargs)


def _papers_arg(arg: str):
    from ..claims.model import get_paper, papers

    if arg == "all":
        return list(papers().values())
    return [get_paper(arg)]


def _dump(data: dict) -> str:
    return json.dumps(data, indent=1, ensure_ascii=False, sort_keys=True) + "\n"


def is_paper_file(arg: str) -> bool:
    """A paper file (``*.toml``) rather than a bundled paper id."""
    return str(arg).endswith(".toml")


def bundled_id(arg: str) -> str:
    """The paper id when ``arg`` is the ``paper.toml`` of a bundled paper (``papers/seed003/paper.toml``
    is paper ``003``, with its golden verdicts and trusted evaluators), else ``arg`` unchanged."""
    if not is_paper_file(arg):
        return arg
    import papers

    path = Path(arg).expanduser()
    try:
        if not (path.name == "paper.toml" and path.is_file()
                and path.resolve().parent.parent == Path(papers.__file__).resolve().parent):
            return arg
        import tomllib

        with open(path, "rb") as f:
            pid = tomllib.load(f).get("paper", {}).get("id")
    except (OSError, ValueError):
        return arg                                # read (and reported) as a paper file
    return pid if isinstance(pid, str) and pid else arg


def _catalogue(name: str):
    from papers import catalogue

    return catalogue(name)


def is_bundled_file(path) -> bool:
    """Whether ``path`` (symbolic links resolved) lies inside the installed ``papers`` package: a paper
    shipped with the tool, whose evaluators are the tool's own code."""
    import papers as bundled

    root = Path(bundled.__file__).resolve().parent
    return root in Path(path).resolve().parents


def load_file(path, allow_python: bool = False):
    """The paper file at ``path`` (catalogue names resolved by :mod:`schemes`). Its ``python`` claims
    run for a bundled paper file or with ``allow_python`` (``--allow-python``); otherwise they are not run."""
    from ..claims.paperfile import load_paper

    mode = "bundled" if is_bundled_file(path) else "allowed" if allow_python else "skip"
    return load_paper(path, catalogue=_catalogue, python=mode)


def _python_lines(results, path=None, json_output: bool = False) -> None:
    """Say on stdout that Python code from the paper file ran (with ``--json`` the verdicts carry it as
    ``ran_python``), and on stderr how many ``python`` claims were not run and how to run them."""
    from ..claims.kinds.other import NOT_RUN_SETTLE
    from ..claims.model import python_notice

    notice = python_notice(results)
    if notice and not json_output:
        _print(f"\nWARNING: {notice}")
    skipped = [ev.claim.id for ev in results if ev.verdict.settle == NOT_RUN_SETTLE]
    if skipped:
        print(f"{len(skipped)} python claim(s) not run ({', '.join(skipped[:3])}{', ...' if len(skipped) > 3 else ''}): "
              f"a paper file is data; if you trust {path or 'it'}, run again with --allow-python", file=sys.stderr)


def _print_details(results) -> None:
    for ev in results:
        v = ev.verdict
        _print(f"\n{ev.claim.id}: {v.label}\n  {v.summary}")
        for t, x in (("corrected", v.corrected), ("sharpness", v.sharpness), ("settle", v.settle)):
            if x:
                _print(f"  {t}: {x}")
        for e in v.evidence:
            _print(f"  - {e.title}: {e.text}" if e.text else f"  - {e.title}")
        for n in v.numbers:
            _print(f"  {n.name} = {n.exact_text()}" + (f" ≈ {n.float!r}" if n.float is not None else ""))


def _write_combined(outdir: Path, data: dict, merge: bool) -> None:
    from ..report.files import atomic_write_text, inside

    combined = inside(outdir, "verdicts.json")
    if combined.exists() and merge:       # keep the other papers' entries
        try:
            from ..algebra.json_input import MAX_VERDICTS_BYTES, load_json

            old = load_json(combined, limit=MAX_VERDICTS_BYTES, what="the combined verdicts file")
        except (OSError, UnicodeDecodeError, json.JSONDecodeError, RecursionError):   # replaced by a fresh one
            old = {}
        if not isinstance(old, dict) or not isinstance(old.get("papers"), dict):
            old = {"papers": {}}
        old["papers"].update(data["papers"])
        data = {**data, "papers": dict(sorted(old["papers"].items()))}
    atomic_write_text(combined, _dump(data))
    print(f"wrote {combined}", file=sys.stderr)


def _targets(outdir: Path, pids) -> None:
    """Check, before any computation, that every file a report writes stays inside ``outdir``."""
    from ..report.files import inside

    for parts in (("verdicts.json",), ("index.html",), ("figures",), ("figures", "formulas"),
                  *((f"{pid}.{ext}",) for pid in pids for ext in ("md", "html"))):
        inside(outdir, *parts)


def _table_target(args, outdir) -> str | None:
    """The file of ``--table NAME`` (a name inside the output folder, which exists), checked before any
    computation; None without ``--table``."""
    if not args.table:
        return None
    from .tables import check_table

    return check_table(args.table, folder=outdir)


def _prune(outdir: Path, started: float) -> None:
    from ..report.files import remove_orphans

    for p in remove_orphans(outdir, older_than=started):
        print(f"removed {p} (no report refers to it)", file=sys.stderr)


def _report_file(args, outdir: Path, write: bool) -> None:
    """``subdiv report FILE.toml``: one paper file."""
    from ..claims.model import verdicts_json
    from ..claims.paperfile import golden_file
    from ..report.files import atomic_write_text, output_folder

    started = time.time()
    path = Path(args.paper)
    paper = load_file(path, args.allow_python)
    golden = golden_file(path)
    if args.update_golden and not os.access(golden.parent, os.W_OK):
        raise AnalysisError(f"cannot write the golden verdicts {golden}: {golden.parent} is not writable")
    only = _select(paper, args.claim)
    if only is not None and not only:
        raise AnalysisError(f"no claim of paper {paper.id} matches {args.claim}")
    if write or args.table:
        outdir = output_folder(outdir)
        _targets(outdir, [paper.id] if write else [])
    table = _table_target(args, outdir)
    t0 = time.perf_counter()
    print(f"paper {paper.id} ({path}): {paper.title} ({len(only) if only is not None else len(paper.claims)} claims)",
          file=sys.stderr, flush=True)
    results = _evaluate(paper, args, only)
    data = verdicts_json({paper.id: results}, titles={paper.id: paper.title})
    if args.json:
        _print(json.dumps(data, indent=1, ensure_ascii=False))
    else:
        _print(f"\n== {paper.id}: {paper.title}")
        _print(_table(results))
        if only is not None:
            _print_details(results)
    _python_lines(results, path, args.json)
    if table:
        _write_table(table, {paper.id: results}, {paper.id: paper.title})
        print(f"wrote {table}", file=sys.stderr)
    if write:
        from ..report.index import render_index, siblings
        from ..report.render import render_paper

        others = siblings(outdir, {paper.id: [ev.claim.id for ev in results]})
        for p in render_paper(paper, results, outdir, with_figures=not args.no_figures, siblings=others):
            print(f"wrote {p}", file=sys.stderr)
        _write_combined(outdir, data, merge=True)
        print(f"wrote {render_index(outdir)}", file=sys.stderr)
        _prune(outdir, started)
    if args.update_golden:
        atomic_write_text(golden, _dump(data))
        print(f"wrote {golden} (golden verdicts: review the diff)", file=sys.stderr)
    print(f"\n{len(results)} claims in {time.perf_counter() - t0:.1f} s", file=sys.stderr)


def cmd_report(args) -> None:
    from ..claims.model import get_paper, golden_path, verdicts_json
    from ..report.files import atomic_write_text, output_folder

    if args.output is not None and not args.output.strip():
        raise AnalysisError("--output needs a folder name, e.g. --output reports (leave --output out to write to "
                            f"{REPORTS}/ of the current folder)")
    outdir = Path(args.output) if args.output else REPORTS
    if args.claim and args.write and not args.output:
        raise AnalysisError("--write with --claim would replace the paper's report and golden verdicts in "
                            f"{REPORTS} by a partial one; write elsewhere with --output DIR")
    if args.claim and args.update_golden:
        raise AnalysisError("--update-golden needs every claim of the paper: drop --claim")
    write = args.claim is None or args.write
    args.paper = bundled_id(args.paper)
    if is_paper_file(args.paper):
        return _report_file(args, outdir, write)
    started = time.time()
    selected = _papers_arg(args.paper)
    if write or args.table:
        outdir = output_folder(outdir)
        _targets(outdir, [p.id for p in selected] if write else [])
    table = _table_target(args, outdir)
    if args.update_golden:
        for paper in selected:
            g = golden_path(paper)
            if g is None or not os.access(g.parent, os.W_OK):
                raise AnalysisError(f"cannot update the golden verdicts of paper {paper.id}: "
                                    + ("it has no folder of its own" if g is None else f"{g.parent} is not writable"))
    t0 = time.perf_counter()
    all_results = {}
    for paper in selected:
        only = _select(paper, args.claim)
        if only is not None and not only:
            raise AnalysisError(f"no claim of paper {paper.id} matches {args.claim}")
        print(f"paper {paper.id}: {paper.title} ({len(only) if only is not None else len(paper.claims)} claims)",
              file=sys.stderr, flush=True)
        results = _evaluate(paper, args, only)
        all_results[paper.id] = results
        if args.json:
            continue
        _print(f"\n== {paper.id}: {paper.title}")
        _print(_table(results))
        if only is not None:
            _print_details(results)
    if table:
        _write_table(table, all_results, {pid: get_paper(pid).title for pid in all_results})
        print(f"wrote {table}", file=sys.stderr)
    if write:
        from ..report.index import render_index, siblings
        from ..report.render import render_paper

        others = siblings(outdir, {pid: [ev.claim.id for ev in res] for pid, res in all_results.items()})
        for pid, results in all_results.items():
            for p in render_paper(get_paper(pid), results, outdir, with_figures=not args.no_figures, siblings=others):
                print(f"wrote {p}", file=sys.stderr)
        _write_combined(outdir, verdicts_json(all_results), merge=args.paper != "all")
        print(f"wrote {render_index(outdir)}", file=sys.stderr)
        _prune(outdir, started)
    if args.update_golden:
        for pid, results in all_results.items():
            g = golden_path(get_paper(pid))
            atomic_write_text(g, _dump(verdicts_json({pid: results})))
            print(f"wrote {g} (golden verdicts: review the diff)", file=sys.stderr)
    if args.json:
        _print(json.dumps(verdicts_json(all_results), indent=1, ensure_ascii=False))
    print(f"\n{sum(len(r) for r in all_results.values())} claims in {time.perf_counter() - t0:.1f} s",
          file=sys.stderr)


def _read_golden(path: Path) -> dict:
    if not path.is_file():
        raise AnalysisError(f"no golden file {path}: run `subdiv report ... --update-golden` and review it")
    try:
        from ..algebra.json_input import MAX_VERDICTS_BYTES, load_json

        golden = load_json(path, limit=MAX_VERDICTS_BYTES, what="the golden file")
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise AnalysisError(f"cannot read the golden file {path}: {str(exc).splitlines()[0]}") from None
    except RecursionError:
        raise AnalysisError(f"cannot read the golden file {path}: arrays or objects nested too deeply "
                            "(regenerate it with `subdiv report ... --update-golden`)") from None
    if not isinstance(golden, dict) or not isinstance(golden.get("papers"), dict):
        raise AnalysisError(f"{path} is not a verdicts file (expected {{\"papers\": {{...}}}})")
    return golden


def bundled_golden(pids=None) -> tuple[dict, str]:
    """The golden verdicts shipped in the paper folders (all papers, or ``pids``), merged."""
    from ..claims.model import get_paper, golden_path, papers

    chosen = [get_paper(p) for p in pids] if pids else list(papers().values())
    merged: dict = {"papers": {}}
    where = []
    for paper in chosen:
        g = golden_path(paper)
        if g is None:
            raise AnalysisError(f"paper {paper.id} has no golden verdicts of its own: give --verdicts FILE")
        merged["papers"].update(_read_golden(g)["papers"])
        where.append(str(g))
    return merged, ", ".join(where) if len(where) <= 1 else f"the golden verdicts of {len(where)} papers"


def cmd_check(args) -> None:
    from ..claims.model import compare_verdicts, get_paper, verdicts_json
    from ..claims.paperfile import golden_file

    args.paper = [bundled_id(p) for p in (args.paper or [])] or args.paper
    if args.table:                              # before any computation
        from .tables import check_table

        check_table(args.table)

    files = [p for p in (args.paper or []) if is_paper_file(p)]
    if files and len(files) != len(args.paper):
        raise AnalysisError("check paper files and bundled papers separately")
    loaded, sources = {}, {}
    new = []             # paper ids of files without golden verdicts yet: evaluated, shown, not compared
    if files:
        for f in files:
            paper = load_file(f, args.allow_python)
            if paper.id in loaded:
                raise AnalysisError(f"two paper files define paper {paper.id}")
            loaded[paper.id], sources[paper.id] = paper, f
        if args.verdicts:
            golden, where = _read_golden(Path(args.verdicts)), args.verdicts
        else:
            golden, found = {"papers": {}}, []
            for pid, f in sources.items():
                g = golden_file(f)
                if not g.exists():
                    new.append(pid)
                    continue
                golden["papers"].update(_read_golden(g)["papers"])
                found.append(str(g))
            where = ", ".join(found)
    elif args.verdicts:
        golden_path_ = Path(args.verdicts)
        golden, where = _read_golden(golden_path_), str(golden_path_)
    else:
        golden, where = bundled_golden(args.paper)
    t0 = time.perf_counter()
    fresh_results = {}
    pids = list(loaded) or args.paper or sorted(golden.get("papers", {}))
    for pid in pids:
        paper = loaded[pid] if loaded else get_paper(pid)
        only = _select(paper, args.claim)
        if only is not None and not only:
            raise AnalysisError(f"no claim of paper {paper.id} matches {args.claim}")
        print(f"checking paper {paper.id} ...", file=sys.stderr, flush=True)
        fresh_results[paper.id] = _evaluate(paper, args, only)
    fresh = verdicts_json(fresh_results, titles={k: p.title for k, p in loaded.items()} if loaded else None)
    compared = [pid for pid in fresh_results if pid not in new]
    if args.claim:   # compare only the selected claims
        sel = {ev.claim.id for evs in fresh_results.values() for ev in evs}
        golden = {"papers": {pid: {"claims": {k: v for k, v in golden["papers"].get(pid, {}).get("claims", {}).items()
                                              if k in sel}} for pid in compared}}
    diffs = compare_verdicts(golden, fresh, papers_=compared) if compared else []
    n = sum(len(v) for v in fresh_results.values())
    for pid, evs in fresh_results.items():
        _python_lines(evs, sources.get(pid), args.json)
    if args.table:
        _write_table(args.table, fresh_results, {pid: (loaded[pid] if loaded else get_paper(pid)).title
                                                  for pid in fresh_results})
    missing = [str(golden_file(sources[pid])) for pid in new]
    note = (f"no golden file {', '.join(missing)} yet: nothing to compare with; after reviewing the verdicts, create it "
            f"with `subdiv report {' '.join(sources[pid] for pid in new)} --update-golden` (then `subdiv check` "
            "compares with it)") if new else None
    if args.json:
        _print(json.dumps({"golden": where or None, "claims": n, "agree": (not diffs) if compared else None,
                           "differences": [str(d) for d in diffs], "verdicts": fresh,
                           **({"missing_golden": missing, "note": note} if new else {}),
                           **({"table": args.table} if args.table else {})}, indent=1, ensure_ascii=False))
        if diffs:
            raise SystemExit(1)
        return
    if args.table:
        _print(f"table written to {args.table}")
    for pid in new:
        _print(f"\n== {pid}: {loaded[pid].title}")
        _print(_table(fresh_results[pid]))
    if new:
        _print(f"\nsubdiv check: {note}")
    if diffs:
        _print(f"subdiv check: {len(diffs)} difference(s) from {where}:")
        for d in diffs:
            _print(f"  {d}")
        again = " ".join(sources[p] for p in compared) if files else "all"
        _print(f"If the change is intended, regenerate with `subdiv report {again} --update-golden` and review the diff.")
        raise SystemExit(1)
    if compared:
        k = sum(len(fresh_results[p]) for p in compared)
        _print(f"subdiv check: {k} claims agree with {where} ({time.perf_counter() - t0:.1f} s)")


ALLOW_PYTHON_HELP = ("run the `python` claims of a paper file (they import and run the Python code the file names: "
                     "only for files you trust; the report then says so). Without it they are not run")


def register(subparsers) -> None:
    """Add ``report`` and ``check`` to the ``subdiv`` command."""
    s = subparsers.add_parser("report", help="proof-check report of a paper (or all): verdicts, Markdown, HTML")
    s.add_argument("paper", help="paper id (e.g. 004), 'all', or a paper file FILE.toml")
    s.add_argument("--claim", action="append", metavar="ID", help="only these claims (shell patterns); print details")
    s.add_argument("--write", action="store_true", help="with --claim and --output: write a partial report there")
    s.add_argument("--output", metavar="DIR", help="output folder (default: reports/ of the current directory)")
    s.add_argument("--update-golden", action="store_true",
                   help="also write each paper's golden verdicts (papers/<paper>/verdicts.json, or FILE.verdicts.json "
                        "beside a paper file) for review")
    s.add_argument("--no-figures", action="store_true", help="skip figures and formula images")
    s.add_argument("--allow-python", action="store_true", help=ALLOW_PYTHON_HELP)
    s.add_argument("--table", metavar="NAME", help="also write the verdict table (claim, paper's statement, verdict, "
                   "computed, witness) as NAME.csv or NAME.tex (a LaTeX booktabs tabular) in the output folder")
    s.add_argument("--quiet", action="store_true", help="no per-claim progress")
    s.add_argument("--json", action="store_true", help="print the verdicts as JSON")
    s.set_defaults(func=cmd_report)
    c = subparsers.add_parser("check", help="recompute every claim and compare with the golden verdicts")
    c.add_argument("paper", nargs="*", help="paper ids or paper files FILE.toml (golden: FILE.verdicts.json) "
                   "(default: every bundled paper, or all in --verdicts)")
    c.add_argument("--verdicts", metavar="FILE",
                   help="golden file to compare with (default: each paper's papers/<paper>/verdicts.json)")
    c.add_argument("--claim", action="append", metavar="ID", help="only these claims (shell patterns)")
    c.add_argument("--allow-python", action="store_true", help=ALLOW_PYTHON_HELP)
    c.add_argument("--table", metavar="FILE", help="also write the verdict table (claim, paper's statement, verdict, "
                   "computed, witness) as FILE.csv or FILE.tex (a LaTeX booktabs tabular)")
    c.add_argument("--quiet", action="store_true", help="no per-claim progress")
    c.add_argument("--json", action="store_true", help="print the comparison (and the fresh verdicts) as JSON")
    c.set_defaults(func=cmd_check)
