"""The guide's worked paper file (examples/four-point.toml, docs/paper-files.md "A worked example") is a test:
the file shown is the file in examples/, the report it prints is the one shown, and its verdicts agree with
the literature and with its golden file (examples/four-point.verdicts.json)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
import sympy as sp

from analysis.claims.model import compare_verdicts
from analysis.cli import main

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "four-point.toml"
GUIDE = ROOT / "docs" / "paper-files.md"
EXTRA = ["analysis.cli.report", "analysis.cli.paperfile"]


def _section() -> str:
    text = GUIDE.read_text(encoding="utf-8")
    start = text.index("## A worked example")
    return text[start: text.index("\n## ", start + 10)]


def test_the_guide_shows_the_example_file():
    assert len(EXAMPLE.read_text().splitlines()) <= 40
    block = re.search(r"```toml\n(.*?)```", _section(), re.S).group(1)
    assert block == EXAMPLE.read_text()


@pytest.mark.slow
def test_the_example_report(tmp_path, capsys):
    out = tmp_path / "r"
    out.mkdir()
    assert main(["report", str(EXAMPLE), "--output", str(out), "--quiet"], extra_modules=EXTRA) == 0
    printed = capsys.readouterr().out
    # the verdict table in the guide is the one printed
    shown = re.search(r"```text\n\$ subdiv report examples/four-point.toml[^\n]*\n(.*?)```", _section(), re.S).group(1)
    table = [ln.rstrip() for ln in printed.strip().splitlines() if ln.startswith(("claim", "4pt:", "---"))]
    assert table == [ln.rstrip() for ln in shown.strip().splitlines() if ln.startswith(("claim", "4pt:", "---"))]
    fresh = json.loads((out / "verdicts.json").read_text())
    golden = json.loads((ROOT / "examples" / "four-point.verdicts.json").read_text())
    assert compare_verdicts(golden, fresh) == []
    c = fresh["papers"]["4pt"]["claims"]
    # literature: (1+z)^2 | a, (1+z)^4 at w = 1/16; C^1 for 0 < w < (sqrt 5 - 1)/8 (DLG 1987), the exact
    # C^1 set reaching w* = 0.19273, the root of 32 w^3 + 4 w - 1 (Hechler, Moessner, Reif, LAA 430 (2009));
    # alpha(1/16) = 2 (Dubuc 1986); cubic reproduction only at w = 1/16 (Deslauriers-Dubuc 1989)
    assert [c[k]["status"] for k in ("4pt:(2.3)", "4pt:Theorem3", "4pt:Remark4", "4pt:Remark5")] == \
        ["certified", "certified", "certified", "refuted"]
    w = sp.Symbol("w")
    right = c["4pt:Theorem3"]["numbers"]["C^1 run 1 right"]
    assert sp.simplify(sp.sympify(right["exact"]) - sp.CRootOf(32 * w**3 + 4 * w - 1, 0)) == 0
    assert abs(right["float"] - 0.19273) < 1e-5
    assert c["4pt:Theorem3"]["numbers"]["printed interval is"]["exact"] == "inside the C^1 set"
    assert c["4pt:Remark4"]["numbers"]["alpha"]["exact"] == "2"
    assert c["4pt:Remark5"]["numbers"]["reproduction degree"]["exact"] == "1"
