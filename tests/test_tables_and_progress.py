"""``--table FILE.csv|FILE.tex`` of ``holder``, ``report`` and ``check`` (the cells are what the command
computed; the LaTeX compiles: balanced braces and ``$``, special characters escaped, a paper's formulas
typeset only when they are standard LaTeX), and the progress line of the long commands: shown on a
terminal only, never with ``--json``, never changing standard output.

``range`` and ``atlas`` tables and the ``range`` progress line are tested in ``tests/test_cli_options.py``;
the refusal of table paths that leave the output folder in ``tests/test_hostile_inputs.py``.
"""

from __future__ import annotations

import csv
import io
import json
import re

import pytest

from analysis.cli.main import main

#: a small paper file: two cheap claims; statements with LaTeX, special characters and a hostile command
PAPER = r'''
[paper]
id = "tbl"
title = "Tables & 100% of the verdicts"
citation = "test"

[schemes.chaikin]
mask = ["1/4", "3/4", "3/4", "1/4"]
start = -2

[[claims]]
id = "Chaikin_C1"
statement = 'The limit is C^1 for 0 < \frac{1}{2} \leq omega_1.'
kind = "smoothness"
scheme = "chaikin"
C = 1

[[claims]]
id = "Chaikin.C2#alpha"
statement = 'C^2 \input{/etc/passwd} & 50% $x$ ~ {'
kind = "smoothness"
scheme = "chaikin"
C = 2
'''


def _tex_cells(text: str, columns: int) -> list[list[str]]:
    """Check that a ``--table`` LaTeX file compiles structurally; its rows as lists of cells."""
    lines = text.splitlines()
    body = [x for x in lines if not x.startswith("%")]
    assert body[0].startswith(r"\begin{tabular}{") and body[-1] == r"\end{tabular}"
    assert body[1] == r"\toprule" and body[3] == r"\midrule" and body[-2] == r"\bottomrule"
    plain = re.sub(r"\\[\\{}&%$#_]", "", "\n".join(body))       # escaped characters and row ends removed
    depth = 0
    for ch in plain:
        depth += (ch == "{") - (ch == "}")
        assert depth >= 0
    assert depth == 0
    rows = []
    for row in [body[2]] + body[4:-2]:
        assert row.endswith(r" \\")
        cells = re.split(r"(?<!\\)&", row[:-3])
        assert len(cells) == columns, row
        for cell in cells:
            bare = re.sub(r"\\[\\{}&%$#_]", "", cell)
            assert bare.count("$") % 2 == 0, cell                   # math opened is closed in the cell
            assert not re.search(r"[%#]", bare), cell                # a comment would swallow the row end
            for m in re.finditer(r"\$([^$]*)\$", bare):              # no text-mode character leaks into math
                assert "\\input" not in m.group(1)
            assert "_" not in re.sub(r"\$[^$]*\$", "", bare), cell   # an underscore outside math is escaped
        rows.append([c.strip() for c in cells])
    return rows


def test_holder_table_csv_and_latex(tmp_path, capsys):
    four = ["holder", "--mask", "-1/16,0,9/16,1,9/16,0,-1/16", "--start", "-3", "--C", "1"]
    assert main([*four, "--table", str(tmp_path / "h.csv")]) == 0
    out = capsys.readouterr().out
    rows = list(csv.reader((tmp_path / "h.csv").open(newline="")))
    assert rows[0] == ["", "value", "status", "witness"]
    table = {r[0]: r[1:] for r in rows[1:]}
    assert table["alpha"][:2] == ["2", "certified"] and "alpha = 2 exactly   [certified]" in out
    assert table["C^1"][:2] == ["yes", "certified"] and "C^1: yes   [certified]" in out
    assert table["shifts of phi"][:2] == ["stable", "certified"]
    assert f"table written to {tmp_path / 'h.csv'}" in out
    assert main([*four, "--table", str(tmp_path / "h.tex"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["table"] == str(tmp_path / "h.tex")
    rows = _tex_cells((tmp_path / "h.tex").read_text(), 4)
    assert rows[1][:3] == [r"$\alpha$", "$2$", "certified"] and rows[3][:2] == ["$C^{1}$", "yes"]


@pytest.mark.parametrize("scheme", [["four-point", "--param", "w=1/10"],
                                    ["ternary-four-point", "--param", "mu=1/18"]], ids=["binary", "ternary"])
def test_holder_table_enclosure_is_the_printed_one(tmp_path, capsys, scheme):
    assert main(["holder", "--scheme", *scheme, "--table", str(tmp_path / "h.csv")]) == 0
    out = capsys.readouterr().out
    alpha = next(r for r in csv.reader((tmp_path / "h.csv").open(newline="")) if r[0] == "alpha")
    assert alpha[2] == "certified" and f"alpha in {alpha[1]}   [certified]" in out


def test_holder_table_of_a_level_dependent_scheme(tmp_path, capsys):
    argv = ["holder", "--symbol", "(1+z)**2*(1+2*c*z+z**2)/(4*(1+c))/z**2", "--where", "c=cos(t/2**(n+1))",
            "--param", "t=1"]
    assert main([*argv, "--table", str(tmp_path / "e.csv")]) == 0
    out = capsys.readouterr().out
    rows = list(csv.reader((tmp_path / "e.csv").open(newline="")))
    assert rows[0] == ["", "verdict", "status", "theorem"]
    for name, verdict, status, theorem in rows[1:]:          # the verdict lines the command printed
        assert f"  {name}: {verdict} [{status}] — {theorem}" in out
    assert [r[:2] for r in rows[1:]] == [["convergence (C^0)", "yes"], ["C^1", "yes"], ["C^2", "yes"], ["C^3", "no"]]
    assert main(["holder", "--scheme", "exp-bspline-3-trig", "--box", "theta=1/10,1", "--table",
                 str(tmp_path / "b.csv")]) == 2                # a box of sub-box verdicts: no table yet
    assert "--table is not available for a level-dependent scheme on a --box" in capsys.readouterr().err
    assert not (tmp_path / "b.csv").exists()


def test_report_and_check_verdict_tables(tmp_path, capsys):
    paper = tmp_path / "tbl.toml"
    paper.write_text(PAPER)
    out_dir = tmp_path / "out"
    assert main(["report", str(paper), "--output", str(out_dir), "--no-figures", "--table", "v.tex", "--quiet"]) == 0
    capsys.readouterr()
    golden = json.loads((out_dir / "verdicts.json").read_text())["papers"]["tbl"]["claims"]
    text = (out_dir / "v.tex").read_text()
    rows = _tex_cells(text, 5)
    assert rows[0] == ["claim", "paper's statement", "verdict", "computed", "witness"]
    assert [r[0] for r in rows[1:]] == [r"tbl:Chaikin\_C1", r"tbl:Chaikin.C2\#alpha"]     # names, never math
    assert [r[2] for r in rows[1:]] == [golden[c]["label"] for c in ("tbl:Chaikin_C1", "tbl:Chaikin.C2#alpha")]
    # standard LaTeX is typeset; a statement with any other command is text, escaped
    assert rows[1][1] == r"The limit is $C^1$ for $0 < \frac{1}{2} \leq \omega_1.$"
    assert r"\textbackslash{}input\{/etc/passwd\} \& 50\% \$x\$ \textasciitilde{} \{" in rows[2][1]
    assert "[certified]" in rows[1][4] and text.startswith("% subdiv: verdicts of paper tbl (Tables & 100% of")
    assert main(["check", str(paper), "--table", str(tmp_path / "v.csv"), "--quiet"]) == 0
    assert f"table written to {tmp_path / 'v.csv'}" in capsys.readouterr().out
    rows = list(csv.reader((tmp_path / "v.csv").open(newline="")))
    assert [r[0] for r in rows[1:]] == ["tbl:Chaikin_C1", "tbl:Chaikin.C2#alpha"]      # the paper's order
    for r in rows[1:]:
        g = golden[r[0]]
        assert r[2] == g["label"]
        assert r[3] == g["summary"] if g["status"] != "refuted" else r[3].startswith(g["summary"] + "; corrected: ")
    assert rows[2][1] == r"C^2 \input{/etc/passwd} & 50% $x$ ~ {"          # CSV: the statement as printed


class _Terminal(io.StringIO):
    def isatty(self):
        return True


@pytest.mark.parametrize("argv, shown", [
    (["vertex", "--scheme", "loop", "--valence", "3", "--ring", "1"], "subdiv vertex: valence 3 (1/1)"),
    (["jsr", "examples/jsr-golden-pair.json"], "subdiv jsr: work units"),
    (["derive", "--support", "7", "--interpolatory", "--symmetric", "primal", "--reproduce", "1", "--maximize",
      "holder", "--within=-1/8,0", "--gap", "1/10"], "subdiv derive: float search 103/103"),
    (["atlas", "--symbol", "(1+z)**2/(2*z)*(1 + s*(z-2+1/z) + t*(z**2-2+z**-2))", "--x", "s=0:1/8:2", "--y",
      "t=0:0:1", "--j", "1", "--refine", "0", "--executor", "serial"], "subdiv atlas: atlas grid: points 2/2"),
    (["bound", "--lhs", "1/2**n", "--rhs", "1"], "subdiv bound: levels 0..3: level 4/4"),
    (["nonuniform", "claims", "--seed", "000", "--id", "000:eta"], "subdiv nonuniform claims: claim 1/1 000:eta"),
], ids=["vertex", "jsr", "derive-maximize", "atlas", "bound", "nonuniform-claims"])
def test_progress_on_a_terminal_only(capsys, monkeypatch, argv, shown):
    assert main(argv) == 0
    plain = capsys.readouterr()
    assert plain.err == ""                                     # not a terminal: nothing on stderr
    term = _Terminal()
    monkeypatch.setattr("sys.stderr", term)
    assert main(argv) == 0
    seconds = re.compile(r"\d+\.\d+ s\b")                       # wall-clock times printed by derive
    assert seconds.sub("", capsys.readouterr().out) == seconds.sub("", plain.out)   # the result does not depend on it
    assert shown in term.getvalue() and term.getvalue().endswith("\r")
    if argv[0] == "derive":                                    # the slowest: its --json is the same switch
        return
    term.seek(0)
    term.truncate()
    assert main([*argv, "--json"]) == 0
    assert term.getvalue() == ""                               # never with --json


def test_check_progress_names_the_claim_running(tmp_path, capsys, monkeypatch):
    paper = tmp_path / "tbl.toml"
    paper.write_text(PAPER)
    assert main(["check", str(paper)]) == 0
    assert "\r" not in capsys.readouterr().err                # per-claim lines only, no progress line
    term = _Terminal()
    monkeypatch.setattr("sys.stderr", term)
    assert main(["check", str(paper)]) == 0
    shown = term.getvalue()
    assert "\rsubdiv check: claim 2/2 tbl:Chaikin.C2#alpha" in shown
    # the line is erased before each per-claim line, which therefore starts a line of its own
    assert re.search(r"\r +\r  \[ 1/2\] tbl:Chaikin_C1", shown)
    term.seek(0)
    term.truncate()
    assert main(["check", str(paper), "--quiet"]) == 0
    assert "subdiv check:" not in term.getvalue()              # --quiet: silent


def test_series_announces_each_weight():
    from types import SimpleNamespace

    from analysis import progress
    from analysis.cli.levels import _weights

    seen: list = []
    with progress.listening(seen.append):
        assert list(_weights(SimpleNamespace(m="0,2", json=False))) == [0, 2]
    assert seen == ["weight m = 0 (1/2)", "weight m = 2 (2/2)"]
