"""Sizes bounded before the work: ``subs`` and ``--where`` results, nested ``diff``, ``CRootOf`` degrees,
decimal literals with exponents, atlas axes and workers, JSON files, and names that are constants.
Each hostile input ends in one line ``subdiv: error: ...`` (and one JSON document with ``--json``)."""

from __future__ import annotations

import json

import pytest

from analysis.algebra.reader import InputError, read_expression
from analysis.cli.main import main


def _error(capsys, *argv) -> str:
    code = main(list(argv))
    out, err = capsys.readouterr()
    assert code == 2, (argv, code, out[-300:], err[-300:])
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("subdiv: error: "), err
    return lines[0]


def _json_error(capsys, *argv) -> dict:
    code = main(list(argv))
    out, err = capsys.readouterr()
    assert code == 2, (argv, code, err[-300:])
    doc = json.loads(out)
    assert set(doc) == {"error"}
    return doc["error"]


@pytest.mark.parametrize("text,limit", [
    ("subs(z**2000, z, z**2000)", "degree"),
    ("subs(w**40, w, w**60)", "degree"),
    ("0.1e10000", "bits"),
    ("0.1e4000", "bits"),
    ("CRootOf(x**40 + x + 1, 3)", "crootof"),
    ("diff(diff(diff(diff(diff(diff(diff(exp(exp(z)), z), z), z), z), z), z), z)", "diffs"),
])
def test_sizes_are_refused_before_the_work(text, limit):
    with pytest.raises(InputError, match=f"limit '{limit}'"):
        read_expression(text)


def test_sizes_within_the_limits_are_read():
    assert str(read_expression("subs(z**2, z, z**3)")) == "z**6"
    assert read_expression("0.1e3900").p == 10 ** 3899
    assert str(read_expression("diff(diff(z**3, z), z)")) == "6*z"
    read_expression("CRootOf(x**24 + x + 1, 3)")


def test_subs_in_the_command_line_and_json(capsys):
    line = _error(capsys, "symbol", "--symbol", "subs(z**2000, z, z**2000)")
    assert "limit 'degree'" in line
    err = _json_error(capsys, "symbol", "--json", "--symbol", "0.1e10000")
    assert err["kind"] == "limit" and "bits" in err["message"]


def test_a_chain_of_where_definitions_is_bounded(capsys):
    where = [a for i in range(40) for a in ("--where", f"b{i}=b{i + 1}**2")]
    line = _error(capsys, "symbol", "--mask", "b0", *where, "--where", "b40=1+z")
    assert "degree up to" in line and "limit 'degree'" in line
    line = _error(capsys, "symbol", "--mask", "b0**3", "--where", "b0=z**1000")
    assert "degree up to 3000" in line


def test_a_matrix_file_is_read_within_its_byte_limit(capsys, tmp_path, monkeypatch):
    import analysis.cli.jsr as jsr_cli

    monkeypatch.setattr(jsr_cli, "MAX_FILE_BYTES", 100)
    line = _error(capsys, "jsr", "/dev/zero")                   # size 0 by stat, endless when read
    assert "larger than the limit of 100 bytes" in line
    big = tmp_path / "big.json"
    big.write_text("[[[" + "9" * 5000 + "]]]", encoding="utf-8")
    monkeypatch.setattr(jsr_cli, "MAX_FILE_BYTES", 10_000)
    err = _json_error(capsys, "jsr", "--json", str(big))
    assert err["kind"] == "limit" and "5000 digits" in err["message"]


def test_a_golden_file_over_its_limit_is_refused(tmp_path, monkeypatch):
    import analysis.cli.report as report_cli
    import analysis.algebra.json_input as json_input

    g = tmp_path / "golden.json"
    g.write_text('{"papers": {}, "pad": "' + "x" * 200 + '"}', encoding="utf-8")
    monkeypatch.setattr(json_input, "MAX_VERDICTS_BYTES", 100)
    with pytest.raises(Exception, match="larger than the limit of 100 bytes"):
        report_cli._read_golden(g)


_PAPER = '[paper]\nid = "991"\ntitle = "t"\ncitation = "c"\n'


@pytest.mark.parametrize("body,message", [
    ('[[claims]]\nid = "c1"\nstatement = "s"\nkind = "vertex"\nlattice = "triangle"\ncentre = ' + "9" * 5000
     + '\nedge = "3/8; 1/n"\nvalence = "4"\nproperty = "eigen-conditions"\n', "5000 digits"),
    ('[schemes.s]\nmask = ["1/2", "1", "1/2"]\nstart = -1\n[[claims]]\nid = "c1"\nstatement = "s"\n'
     'kind = "sum rules"\nscheme = ["s"]\nfactors = 1\n', "in quotes"),
    ('[schemes.s]\nmask = ["z", "1-z"]\nstart = 0\nparameters = { z = "(-1/4, 1/4)" }\n[[claims]]\nid = "c1"\n'
     'statement = "s"\nkind = "sum rules"\nfactors = 1\n', "'z' is the variable of the symbol: rename it"),
    ('[schemes.s]\nmask = ["pi", "1-pi"]\nstart = 0\nparameters = { pi = "(-1/4, 1/4)" }\n[[claims]]\nid = "c1"\n'
     'statement = "s"\nkind = "sum rules"\nfactors = 1\n', "'pi' is a constant"),
    ('[schemes.s]\nmask = ["subs(w**2000, w, w**2000)", "1"]\nstart = 0\n[[claims]]\nid = "c1"\n'
     'statement = "s"\nkind = "sum rules"\nfactors = 1\n', "limit 'degree'"),
], ids=["long-integer", "scheme-list", "parameter-z", "parameter-pi", "subs-coefficient"])
def test_paper_fields_of_the_wrong_size_or_type_say_what_to_write(capsys, tmp_path, body, message):
    f = tmp_path / "p.toml"
    f.write_text(_PAPER + body, encoding="utf-8")
    line = _error(capsys, "report", str(f), "--output", str(tmp_path / "out"))
    assert message in line and "internal error" not in line


@pytest.mark.parametrize("x,y,extra,message", [
    ("w=0:1/8:100000", "v=0:1/8:3", [], "100000 points for w exceed the limit 257 per axis"),
    ("w=0:1/8:200", "v=0:1/8:200", [], "200 x 200 = 40000 points exceeds the limit 10000"),
    ("w=0:1/8:3", "v=0:1/8:3", ["--workers", "1000"], "--workers must be between 1 and 64"),
], ids=["axis", "grid", "workers"])
def test_atlas_sizes_are_refused_before_the_work(capsys, x, y, extra, message):
    line = _error(capsys, "atlas", "--mask", "-w,0,1/2+v,1,1/2+v,0,-w", "--start", "-3", "--x", x, "--y", y,
                  "--no-progress", *extra)
    assert message in line


def test_the_atlas_library_refuses_too_many_workers():
    from analysis.regularity.atlas import _check_executor

    with pytest.raises(Exception, match="1000 workers exceed the limit 64"):
        _check_executor("local", 1000)
