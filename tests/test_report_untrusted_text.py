"""A paper file is written by a stranger: its text cannot become markup in the Markdown report, its claim
ids are checked when it is read, and the output folder given is checked (empty, too long)."""

from __future__ import annotations

import json
import re

import pytest

from tests.cli_run import assert_one_line_error, run_main

PAPER = '''
[paper]
id = "667"
title = {title}
citation = "nobody [c](javascript:alert(5))"
notes = "<script>alert(6)</script>\\n[x]: javascript:alert(7)"

[schemes.chaikin]
mask = ["1/4", "3/4", "3/4", "1/4"]
start = -2

[[claims]]
id = {cid}
title = "a | b <i>c</i>"
statement = "<img src=x onerror=alert(2)> [l](javascript:alert(4)) <javascript:alert(8)>"
reading = "<b>read</b>"
location = "p. 1 | 2"
command = "subdiv x` <img src=y onerror=alert(9)> `"
kind = "sum rules"
factors = 3
'''


def _paper(tmp_path, title='"<script>alert(1)</script> | x"', cid='"Factors(u>0)"'):
    f = tmp_path / "p.toml"
    f.write_text(PAPER.format(title=title, cid=cid), encoding="utf-8")
    return f


_run, _one_line_error = run_main, assert_one_line_error


def test_paper_text_cannot_become_markup_in_the_markdown_report(tmp_path, capsys):
    out = tmp_path / "out"
    code, _, err = _run(capsys, "report", _paper(tmp_path), "--output", out, "--quiet", "--no-figures")
    assert code == 0, err
    md = (out / "667.md").read_text(encoding="utf-8")
    span = "`` subdiv x` <img src=y onerror=alert(9)> ` ``"
    assert span in md                                   # a code span: shown as written, not closed early
    md = md.replace(span, "")
    for raw in ("<script", "<img", "<i>", "<b>", "<javascript:"):
        assert raw not in md, raw
    assert not re.search(r"(?<!\\)[\[\]]", md.split("## 667:")[0]), "a bracket not escaped"
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in md and "\\[l\\](javascript:alert(4))" in md
    assert "Factors(u&gt;0)" in md
    verdict_rows = [ln for ln in md.splitlines() if ln.startswith("| 667:")]
    assert len(verdict_rows) == 1 and verdict_rows[0].replace("\\|", "").count("|") == 5   # 4 cells, not split


@pytest.mark.parametrize("cid", ['"../../x/y"', '"<b>y</b>"', '"a|b"', '"a`b"', '" Lemma1"'])
def test_claim_ids_outside_the_safe_characters_are_refused(tmp_path, capsys, cid):
    code, _, err = _run(capsys, "check", _paper(tmp_path, cid=cid))
    _one_line_error(code, err, "is not a claim id", "letters, digits, spaces and . , : ; _ - + = ^ / ( ) > ' * #")


def test_every_bundled_claim_id_is_accepted():
    import glob
    import re
    import tomllib

    from analysis.claims.names import check_claim_id

    seen = 0
    for f in sorted(glob.glob("papers/*/paper.toml") + glob.glob("examples/*.toml")):
        for c in tomllib.loads(open(f, encoding="utf-8").read()).get("claims", []):
            check_claim_id(c["id"], f)
            seen += 1
    for f in sorted(glob.glob("docs/*.md")):
        for cid in re.findall(r'^id = "(.*)"$', open(f, encoding="utf-8").read(), re.M):
            check_claim_id(cid, f)
            seen += 1
    assert seen > 100


def test_an_empty_output_folder_is_an_error(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, err = _run(capsys, "report", _paper(tmp_path), "--output", "", "--quiet")
    _one_line_error(code, err, "--output needs a folder name")
    assert not (tmp_path / "reports").exists()


@pytest.mark.parametrize("argv", [["new-paper", "{long}.toml", "--json"],
                                  ["report", "{paper}", "--output", "{long}", "--quiet", "--json"]],
                         ids=["new-paper", "report-output"])
def test_a_file_name_too_long_is_an_input_error(tmp_path, capsys, argv):
    long = str(tmp_path / ("d" * 300))
    argv = [a.format(long=long, paper=_paper(tmp_path)) for a in argv]
    code, out, err = _run(capsys, *argv)
    _one_line_error(code, err, "too long", "give a shorter path")
    assert json.loads(out[out.index('{\n  "error"'):])["error"]["kind"] == "input"
