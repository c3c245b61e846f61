"""Paper files are data, and reports stay inside --output: hostile paper files (a `python` claim naming
`os:system`, evaluator strings that are paths, ids that are paths, deep nesting, symbolic links leading
out of the output folder), the output folder created when missing, figure paths of every command
checked before any computation, formula images rewritten on every run and orphaned figures removed.

Everything runs in-process (``analysis.cli.main.main``) and fast: no claim here computes anything.
"""

from __future__ import annotations

import json
import os
import sys
import uuid

import pytest

from analysis.cli import main
from tests.cli_run import assert_one_line_error, run_main

HEAD = '''
[paper]
id = "{pid}"
title = "A hostile paper"
citation = "nobody"

[schemes.chaikin]
mask = ["1/4", "3/4", "3/4", "1/4"]
start = -2

[[claims]]
id = "Factors"
statement = "three smoothing factors"
kind = "sum rules"
factors = 3
'''

PYTHON_CLAIM = '''
[[claims]]
id = "Code"
statement = "runs code"
kind = "python"
evaluator = "{evaluator}"
args = {args}
'''


def _paper(tmp_path, pid="666", evaluator=None, args=(), name="p.toml"):
    text = HEAD.format(pid=pid)
    if evaluator is not None:
        text += PYTHON_CLAIM.format(evaluator=evaluator, args=json.dumps(list(args)))
    f = tmp_path / name
    f.write_text(text, encoding="utf-8")
    return f


_run, _one_line_error = run_main, assert_one_line_error


@pytest.fixture
def evaluator_module(tmp_path, monkeypatch):
    """A module on sys.path whose import leaves a marker file, with an evaluator that leaves another one
    and returns a verdict with a formula and a figure."""
    name = f"subdiv_test_ev_{uuid.uuid4().hex[:8]}"
    imported, ran = tmp_path / "IMPORTED", tmp_path / "RAN"
    (tmp_path / f"{name}.py").write_text(f'''
from pathlib import Path
from analysis.claims.model import Evidence, Figure, Number, Series, Verdict
Path({str(imported)!r}).write_text("imported")

def check(marker):
    Path(marker).write_text("ran")
    return Verdict("numerical", "the evaluator ran", evidence=[Evidence("a sum", latex=r"a_0 + a_1 = 1")],
                   numbers=[Number("n", 1)],
                   figures=[Figure("curve-1", "a line", (Series("s", (0.0, 1.0), (0.0, 1.0)),))])
''', encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    yield name, imported, ran
    sys.modules.pop(name, None)


# --------------------------------------------------------------------------------------------
# python claims: nothing runs without --allow-python
# --------------------------------------------------------------------------------------------

def test_os_system_is_not_run_without_the_flag(tmp_path, capsys):
    marker = tmp_path / "MARKER"
    f = _paper(tmp_path, evaluator="os:system", args=[f"touch {marker}"])
    out = tmp_path / "out"
    code, stdout, err = _run(capsys, "report", f, "--output", out, "--quiet")
    assert code == 0, err
    assert not marker.exists()
    assert "666:Code" in stdout and "not run" in stdout and "--allow-python" in err
    md = (out / "666.md").read_text(encoding="utf-8")
    assert "| 666:Code | python | INCONCLUSIVE | not run" in md and "--allow-python" in md
    assert "| 666:Factors | sum rules | CERTIFIED TRUE |" in md          # the rest of the report is there
    data = json.loads((out / "verdicts.json").read_text())
    assert data["papers"]["666"]["claims"]["666:Code"]["status"] == "inconclusive"
    assert "ran_python" not in data["papers"]["666"]


def test_nothing_is_imported_without_the_flag_and_the_report_says_when_code_ran(tmp_path, capsys, evaluator_module):
    name, imported, ran = evaluator_module
    f = _paper(tmp_path, evaluator=f"{name}:check", args=[str(ran)])
    out = tmp_path / "out"
    assert _run(capsys, "report", f, "--output", out, "--quiet")[0] == 0
    assert not imported.exists() and not ran.exists()
    assert "Warning" not in (out / "666.md").read_text(encoding="utf-8")
    # with --allow-python the evaluator is imported and run, and every form of the report says so
    code, stdout, err = _run(capsys, "report", f, "--output", out, "--quiet", "--allow-python")
    assert code == 0, err
    assert imported.exists() and ran.exists()
    notice = f"this report ran Python code from the paper file: evaluator {name}:check (claim 666:Code)"
    assert f"WARNING: {notice}" in stdout
    md = (out / "666.md").read_text(encoding="utf-8")
    assert notice[1:] in md and f"evaluator `{name}:check`" in md
    assert notice[1:] in (out / "666.html").read_text(encoding="utf-8")
    data = json.loads((out / "verdicts.json").read_text())["papers"]["666"]
    assert data["ran_python"] == notice and data["claims"]["666:Code"]["ran_python"] == f"{name}:check"
    code, stdout, err = _run(capsys, "report", f, "--claim", "666:Code", "--json", "--quiet", "--allow-python")
    assert json.loads(stdout)["papers"]["666"]["ran_python"] == notice            # --json: one document
    # `subdiv check` runs nothing without the flag either: the verdict differs from the golden one
    assert _run(capsys, "report", f, "--output", out, "--quiet", "--allow-python", "--update-golden")[0] == 0
    ran.unlink()
    with pytest.raises(SystemExit) as exc:
        main(["check", str(f), "--quiet"])
    assert exc.value.code == 1 and not ran.exists()
    stdout, err = capsys.readouterr()
    assert "666:Code: status changed: numerical -> inconclusive" in stdout and "--allow-python" in err
    assert _run(capsys, "check", f, "--quiet", "--allow-python")[0] == 0 and ran.exists()


@pytest.mark.parametrize("evaluator", ["../../etc:passwd", "/etc/passwd:x", ".relative:f", "os.system", "a..b:f",
                                       "os:system:x", "os: system", "os:", ":f"])
@pytest.mark.parametrize("flag", [[], ["--allow-python"]])
def test_evaluator_must_be_dotted_names(tmp_path, capsys, evaluator, flag):
    f = _paper(tmp_path, evaluator=evaluator)
    code, _, err = _run(capsys, "report", f, "--output", tmp_path / "out", *flag)
    _one_line_error(code, err, "evaluator must be \"package.module:function\"")
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------------------------
# names that become file names; writes stay inside --output
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("pid", ["{tmp}/evil", "../evil", "a/b", "..", ".hidden", "x" * 65, "ok..no", "tab\tx"])
def test_paper_ids_that_are_paths_are_refused(tmp_path, capsys, pid):
    f = _paper(tmp_path, pid=pid.replace("{tmp}", str(tmp_path)).replace("\t", "\\t"))
    code, _, err = _run(capsys, "report", f, "--output", tmp_path / "out")
    _one_line_error(code, err, "[paper] id", "cannot be a file name", 'e.g. "900"')
    assert not list(tmp_path.rglob("*.md")) and not list(tmp_path.rglob("*.html"))


def test_scheme_and_figure_names_are_slugs(tmp_path, capsys):
    f = tmp_path / "p.toml"
    f.write_text(HEAD.format(pid="1").replace("[schemes.chaikin]", '[schemes."../../x"]'), encoding="utf-8")
    code, _, err = _run(capsys, "report", f, "--output", tmp_path / "out")
    _one_line_error(code, err, "scheme name '../../x' cannot be a file name")
    from analysis.claims.model import Figure
    from analysis.report.render import render_figure
    from analysis.result import AnalysisError

    with pytest.raises(AnalysisError, match="figure name '../x' cannot be a file name"):
        render_figure(Figure("../x", "t", ()), tmp_path)


def test_symbolic_links_leading_out_of_the_output_folder_are_refused(tmp_path, capsys):
    f = _paper(tmp_path)
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    out.mkdir()
    elsewhere.mkdir()
    (out / "figures").symlink_to(elsewhere)
    code, _, err = _run(capsys, "report", f, "--output", out, "--quiet")
    _one_line_error(code, err, "outside the output folder", "symbolic link")
    (out / "figures").unlink()
    victim = elsewhere / "victim.txt"
    victim.write_text("keep me")
    (out / "666.md").symlink_to(victim)
    code, _, err = _run(capsys, "report", f, "--output", out, "--quiet")
    _one_line_error(code, err, "outside the output folder")
    assert victim.read_text() == "keep me" and not list(elsewhere.glob("*.md"))


def test_missing_output_folder_is_created_with_its_parents(tmp_path, capsys):
    out = tmp_path / "a" / "b" / "c"
    code, _, err = _run(capsys, "report", _paper(tmp_path), "--output", out, "--quiet")
    assert code == 0, err
    assert (out / "666.md").is_file() and (out / "666.html").is_file() and (out / "verdicts.json").is_file()


@pytest.mark.parametrize("where, message", [("file", "is a file, not a folder"),
                                            ("/dev/null/x", "cannot create the output folder")])
def test_output_folder_that_cannot_be_made(tmp_path, capsys, where, message):
    target = tmp_path / "file" if where == "file" else where
    (tmp_path / "file").write_text("")
    code, _, err = _run(capsys, "report", _paper(tmp_path), "--output", target)
    _one_line_error(code, err, message)


@pytest.mark.parametrize("text", ["a = " + "[" * 100000, "a = " + "[" * 20 + "]" * 20,
                                  "a = " + "{ b = " * 30 + "1" + " }" * 30])
def test_deeply_nested_toml_is_a_one_line_error(tmp_path, capsys, text):
    f = tmp_path / "deep.toml"
    f.write_text(text, encoding="utf-8")
    code, _, err = _run(capsys, "report", f, "--output", tmp_path / "out")
    _one_line_error(code, err, "nested too deeply")


@pytest.mark.parametrize("argv, message", [(["check", "003", "--claim", "none", "--verdicts"], "nested too deeply"),
                                           (["range", "--C", "1", "--within=0,1", "--family"], "nested too deeply")])
def test_deeply_nested_json_inputs_are_one_line_errors(tmp_path, capsys, argv, message):
    f = tmp_path / "deep.json"
    f.write_text("[" * 100000, encoding="utf-8")
    _one_line_error(*_run(capsys, *argv, f)[::2], message)


def test_large_and_special_paper_files_are_refused(tmp_path, capsys):
    big = tmp_path / "big.toml"
    big.write_text("# " + "x" * (1 << 20) + "\n", encoding="utf-8")
    _one_line_error(*_run(capsys, "report", big, "--output", tmp_path / "o")[::2], "larger than", "split it")
    folder = tmp_path / "dir.toml"
    folder.mkdir()
    _one_line_error(*_run(capsys, "report", folder, "--output", tmp_path / "o")[::2], "not a regular file")


# --------------------------------------------------------------------------------------------
# figure and output options of every command: checked before any computation
# --------------------------------------------------------------------------------------------

def _forbid(monkeypatch, module, name):
    import importlib

    def computed(*a, **k):
        raise AssertionError(f"{module}.{name} ran before the figure path was checked")
    monkeypatch.setattr(importlib.import_module(module), name, computed)


COMMANDS = [
    (["atlas", "--scheme", "seed004-design-control", "--param", "omega=0", "--x", "mu=0:1/5:3", "--y", "nu=0:2:3",
      "--figure"], "analysis.regularity.atlas", "holder_atlas"),
    (["range", "--scheme", "four-point", "--C", "1", "--within=-1/8,1/4", "--figure"],
     "analysis.regularity.ranges", "ck_parameter_set"),
    (["range", "--scheme", "ternary-four-point", "--C", "1", "--within=0,1/8", "--figure"],
     "analysis.regularity.ranges", "ck_range"),
    (["nonuniform", "reproduce", "--figure"], "analysis.nonuniform", "reproduce"),
    (["nonuniform", "chamfer", "--figure"], "analysis.nonuniform", "chamfer_example"),
    (["reproduce", "--scheme", "exp-chaikin-trig", "--lambdas", "I*t,-I*t", "--param", "t=1", "--plot"],
     "analysis.levels.reproduction", "generation"),
]


@pytest.mark.parametrize("path, message", [("/proc/x.png", "does not accept new files"),
                                           ("x.bogusext", "'.bogusext' is not an image format"),
                                           ("noext", "no extension"),
                                           ("/dev/null/x.svg", "does not exist")])
@pytest.mark.parametrize("argv, module, name", COMMANDS, ids=["atlas", "range", "range-mary", "nonuniform-reproduce",
                                                              "nonuniform-chamfer", "reproduce"])
def test_figure_paths_are_checked_first(tmp_path, capsys, monkeypatch, argv, module, name, path, message):
    if path == "/proc/x.png" and not os.path.isdir("/proc"):
        pytest.skip("no /proc")
    monkeypatch.chdir(tmp_path)
    _forbid(monkeypatch, module, name)
    code, _, err = _run(capsys, *argv, path)
    _one_line_error(code, err, message)
    if "extension" in message or "image format" in message:
        assert ".png, .svg or .pdf" in err


@pytest.mark.parametrize("argv, module, name", [
    (["refine", "--scheme", "chaikin", "--points", "0,0;1,0;1,1", "--output"], "analysis.stationary.refinement",
     "refine"),
    (["nonuniform", "refine", "--points", "0,0;1,0;1,1", "--u", "1", "--output"], "analysis.nonuniform", "refine"),
], ids=["refine", "nonuniform-refine"])
def test_data_outputs_in_unwritable_places_are_checked_first(capsys, monkeypatch, argv, module, name):
    _forbid(monkeypatch, module, name)
    _one_line_error(*_run(capsys, *argv, "/proc/x.csv")[::2], "does not accept new files")


# --------------------------------------------------------------------------------------------
# reports: every file rewritten, orphans removed
# --------------------------------------------------------------------------------------------

def test_formula_images_are_rewritten_and_orphans_removed(tmp_path, capsys, evaluator_module):
    from analysis.report.files import record_written

    name, _, ran = evaluator_module
    f = _paper(tmp_path, evaluator=f"{name}:check", args=[str(ran)])
    out = tmp_path / "out"
    assert _run(capsys, "report", f, "--output", out, "--quiet", "--allow-python")[0] == 0
    svgs = list((out / "figures" / "formulas").glob("f-*.svg"))
    assert len(svgs) == 1 and (out / "figures" / "curve-1.png").is_file()
    good = svgs[0].read_bytes()
    svgs[0].write_text("damaged")                                            # a damaged formula image
    orphans = [out / "figures" / "formulas" / "f-000000000000.svg", out / "figures" / "old-figure.png"]
    kept = [out / "figures" / "notes.txt", out / "figures" / "formulas" / "f-111111111111.svg", out / "other.json",
            out / "stale.md"]
    mine = [out / "figures" / "holiday.png", out / "figures" / "formulas" / "f-222222222222.svg"]
    for p in orphans + kept + mine:
        p.write_text("x")
    record_written(out, orphans + kept[1:2] + mine[1:])                       # as if an earlier run wrote them
    mine[1].write_text("changed since")                                      # no longer the tool's bytes
    (out / "other.md").write_text("![formula](figures/formulas/f-111111111111.svg)")   # another report's image
    for p in orphans + kept + svgs + mine:
        os.utime(p, (1e9, 1e9))                                              # written before this run
    code, _, err = _run(capsys, "report", f, "--output", out, "--quiet", "--allow-python")
    assert code == 0, err
    assert svgs[0].read_bytes() == good                                      # rewritten, identical to a fresh one
    assert not any(p.exists() for p in orphans)
    assert all(p.exists() for p in kept)                                     # not generated / still referenced
    assert all(f"removed {p}" in err for p in orphans)
    assert all(p.exists() for p in mine), "a file the tool cannot prove it wrote was removed"


def test_the_users_own_images_in_the_figures_folder_are_kept(tmp_path, capsys):
    """A picture of the user's in ``OUTPUT/figures/`` (older than the run, referenced by no report, named
    like a generated figure or not) is not the tool's to remove."""
    f = _paper(tmp_path)
    out = tmp_path / "out"
    own = [out / "figures" / "holiday.png", out / "figures" / "formulas" / "f-0123456789ab.svg"]
    for p in own:
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(b"my picture")
        os.utime(p, (1e9, 1e9))
    code, _, err = _run(capsys, "report", f, "--output", out, "--quiet")
    assert code == 0, err
    assert all(p.read_bytes() == b"my picture" for p in own) and "removed" not in err


def test_a_bundled_papers_own_file_is_the_bundled_paper(tmp_path):
    """``subdiv check papers/seed000/paper.toml`` is ``subdiv check 000`` (its golden verdicts, its
    trusted evaluators); the same text copied elsewhere is a stranger's paper file."""
    import shutil
    from pathlib import Path

    import papers
    from analysis.cli.report import bundled_id

    own = Path(papers.__file__).parent / "seed000" / "paper.toml"
    assert bundled_id(str(own)) == "000"
    copy = tmp_path / "seed000" / "paper.toml"
    copy.parent.mkdir()
    shutil.copy(own, copy)
    assert bundled_id(str(copy)) == str(copy)
    assert bundled_id("000") == "000"
