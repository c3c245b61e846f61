"""Issue 11: seed 001 is a paper file (papers/seed001/paper.toml). Its claims are the golden file's,
the kinds are data where they fit (the local rule (3) as a mask identity, cited results as `cited`),
every bespoke evaluator is named by the file (or by seed 000), and `subdiv nonuniform claims --seed
001` lists the verdicts of the file. The mask (4) is recomputed here from rule (3) by applying the
rule to a delta (sympy, generic u), independently of the kind's code.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import sympy as sp

from analysis.claims.paperfile import parse_paper
from analysis.cli import main
from papers import seed001

ROOT = Path(__file__).resolve().parents[1]
FOLDER = ROOT / "papers" / "seed001"
TEXT = (FOLDER / "paper.toml").read_text(encoding="utf-8")


def test_paper_file_claims_and_kinds():
    kinds = [t.split('"')[1] for t in TEXT.split("\nkind = ")[1:]]
    assert (kinds.count("python"), kinds.count("cited"), kinds.count("mask identity")) == (21, 6, 1)
    golden = json.loads((FOLDER / "verdicts.json").read_text(encoding="utf-8"))["papers"]["001"]["claims"]
    assert [c.id for c in seed001.PAPER.claims] == [c["id"] for c in seed001.CLAIMS]
    assert sorted(c.id for c in seed001.PAPER.claims) == sorted(golden)
    assert all(c.command.startswith("subdiv ") and "paper.toml" not in c.command for c in seed001.PAPER.claims)


def test_every_evaluator_is_named():
    """No evaluator left behind: each _v_* of the folder is named by paper.toml (or used by seed 000)."""
    named = set(re.findall(r'evaluator = "papers\.seed001\.\w+:(\w+)"', TEXT))
    seed000 = (ROOT / "papers" / "seed000" / "claims.py").read_text(encoding="utf-8")
    for mod in ("claims_sec1_3.py", "examples.py"):
        defined = re.findall(r"^def (_v_\w+)", (FOLDER / mod).read_text(encoding="utf-8"), re.M)
        assert defined and all(f in named or f in seed000 for f in defined), (mod, set(defined) - named)


def _rule3_mask():
    """(S f)_i = sum_j a_(i-2j) f_j: apply rule (3) to delta_0 and read a_(-2..1) (generic u)."""
    u = sp.Symbol("u")
    even = [(1 + 2 * u) / (2 * (1 + u)), 1 / (2 * (1 + u))]     # P_2i = even[0] P_i + even[1] P_i+1
    odd = [1 / (2 * (1 + u)), (1 + 2 * u) / (2 * (1 + u))]      # P_2i+1 = odd[0] P_i + odd[1] P_i+1
    out = {}
    for i in (-1, 0):                  # the new points P_2i, P_2i+1 that see f_0 (through P_(i+p), i + p = 0)
        p = -i
        out[2 * i], out[2 * i + 1] = even[p], odd[p]
    return [sp.simplify(out[k]) for k in range(-2, 2)]


def test_mask_4_is_rule_3_independently():
    u = sp.Symbol("u")
    h = 1 / (2 * (1 + u))
    assert all(sp.simplify(x - y) == 0 for x, y in zip(_rule3_mask(), [h, 1 - h, 1 - h, h]))
    (claim,) = [c for c in seed001.PAPER.claims if c.id == "001:(4)"]
    assert claim.evaluate().status == "certified"
    # the file can fail: a printed mask with a wrong second entry is refuted
    bad = parse_paper(TEXT.replace('mask = ["1/(2*(1 + u))", "(1 + 2*u)/(2*(1 + u))"',
                                   'mask = ["1/(2*(1 + u))", "(1 + u)/(2*(1 + u))"'), "bad.toml")
    (claim,) = [c for c in bad.claims if c.id == "001:(4)"]
    assert claim.evaluate().status == "refuted"


def test_nonuniform_claims_lists_the_paper_file(capsys):
    assert main(["nonuniform", "claims", "--seed", "001", "--id", "001:(4)", "--json"]) == 0
    (row,) = json.loads(capsys.readouterr().out)
    assert row["status"] == "certified" and row["result"]["label"] == "CERTIFIED TRUE"
    assert seed001.check("001:Lemma3.2").status == "inconclusive"
