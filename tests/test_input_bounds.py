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
