"""Issue 9.1 and 9.8: option values beginning with '-', repeated --param, unwritable output paths
checked before computing, outward-rounded enclosures, `subdiv --version`, machine-independent
reports."""

from __future__ import annotations

import json
import random
import re
from fractions import Fraction

import pytest
import sympy as sp

from analysis.cli import main
from analysis.jsonable import fmt_bound, fmt_lower, fmt_upper, roundoff_text

FOUR_POINT = "-1/16,0,9/16,1,9/16,0,-1/16"


def call(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, err, message):
    assert code == 2, err
    assert err.startswith("subdiv: error: ") and err.count("\n") == 1 and message in err, err


# --------------------------------------------------------------------------------------------
# 9.1 option values that begin with '-'
# --------------------------------------------------------------------------------------------

def test_mask_starting_with_minus_is_accepted(capsys):
    code, out, err = call(capsys, "holder", "--mask", FOUR_POINT, "--start", "-3", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["alpha"]["value"] == 2 and data["alpha"]["witness"]["c"]["start"] == -3


@pytest.mark.parametrize("argv, check", [
    (["norm", "--mask", FOUR_POINT, "--start", "-3", "--m", "2", "--L", "2"],
     lambda d: d["results"][0]["contractive"] is True),
    (["symbol", "--even", "0,1,0,0", "--odd", "-1/16,9/16,9/16,-1/16", "--first", "-1"],   # the 4-point rules
     lambda d: [str(c) for c in d["mask"]] == FOUR_POINT.split(",") and d["start"] == -3),
    (["symbol", "--even", "-1/8,0", "--odd", "1,0", "--even-first", "-1", "--odd-first", "0"],
     lambda d: d["rules"]["even_first"] == -1),
    (["range", "--scheme", "four-point", "--C", "0", "--within", "-1/16,1/8", "--grid", "2"],
     lambda d: d["within"] == ["-1/16", "1/8"]),
    (["refine", "--scheme", "chaikin", "--points", "-1,0;1,0;1,1;0,1", "--exact"],
     lambda d: d["points"][0] == ["-1/2", "0"]),
    (["bound", "--lhs", "-1", "--rhs", "sin(alpha/2**n)", "--n0", "0", "--box", "alpha=1/100,1"],
     lambda d: d["status"] == "certified"),
    (["nonuniform", "decay", "--u0", "-0.5,2", "--degree", "2", "--levels", "2"],
     lambda d: d["status"] == "certified"),
    (["nonuniform", "refine", "--points", "-1,0;1,0;1,1;0,1", "--u", "-0.5", "--closed"],
     lambda d: d["points"][0][0] != 0),
    (["holder", "--mas", FOUR_POINT, "--sta", "-3"],                     # abbreviations, as argparse allows
     lambda d: d["alpha"]["value"] == 2),
], ids=["norm-mask", "symbol-even-odd", "symbol-first", "range-within", "refine-points", "bound-lhs",
        "nonuniform-decay", "nonuniform-refine", "abbreviated"])
def test_option_values_starting_with_minus_are_accepted(capsys, argv, check):
    code, out, err = call(capsys, *argv, "--json")
    assert code == 0, err
    assert check(json.loads(out))


@pytest.mark.parametrize("argv, message", [
    (["atlas", "--scheme", "seed004-design-control", "--param", "omega=0", "--x", "-mu=0:1:2", "--y", "nu=0:1:2"],
     "malformed"),                                           # our message, not argparse's "expected one argument"
    (["bound", "--lhs", "1", "--rhs", "2", "--n0", "-1"], "--n0 must be a non-negative level"),
    (["norm", "--scheme", "four-point", "--param", "-w=1"], "malformed parameter name '-w'"),
    (["symbol", "--mask", "--json"], "argument --mask: expected one argument"),   # a missing value stays an error
    (["nonuniform", "lemma", "--u0-range", "-2,100"], "u0"),
])
def test_option_values_starting_with_minus_reach_the_command(capsys, argv, message):
    code, out, err = call(capsys, *argv)
    one_line_error(code, err, message)


# --------------------------------------------------------------------------------------------
# 9.8 repeated --param
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("argv, message", [
    (["norm", "--scheme", "four-point", "--param", "w=1/16", "--param", "w=1/32"], "--param w is given twice"),
    (["holder", "--scheme", "four-point", "--param", "w=1/16", "--param", "w = 1/16"], "--param w is given twice"),
    (["series", "--scheme", "seed003-trigonometric", "--param", "omega=1/100", "--param", "omega=1/50"],
     "--param omega is given twice"),
    (["series", "--scheme", "seed003-trigonometric", "--box", "alpha=0,1", "--box", "alpha=1,2"],
     "--box alpha is given twice"),
    (["bound", "--lhs", "alpha", "--rhs", "1", "--param", "alpha=1", "--box", "alpha=0,1"],
     "alpha is given both by --param and by --box"),
    (["reproduce", "--scheme", "exp-chaikin-trig", "--lambdas", "I*t,-I*t", "--param", "t=1", "--param", "t=2"],
     "--param t is given twice"),
])
def test_repeated_param_is_an_error(capsys, argv, message):
    code, out, err = call(capsys, *argv)
    one_line_error(code, err, message)


# --------------------------------------------------------------------------------------------
# 9.8 unwritable --figure / --output / --plot: found before any computation
# --------------------------------------------------------------------------------------------

def _forbid(monkeypatch, module, name):
    import importlib

    def computed(*a, **k):
        raise AssertionError(f"{module}.{name} ran before the output path was checked")
    monkeypatch.setattr(importlib.import_module(module), name, computed)


BAD = "/nonexistent/dir/x.png"


@pytest.mark.parametrize("argv, module, name", [
    (["range", "--scheme", "four-point", "--C", "1", "--within=-1/8,1/4", "--figure", BAD],
     "analysis.regularity.ranges", "ck_parameter_set"),
    (["atlas", "--scheme", "seed004-design-control", "--param", "omega=0", "--x", "mu=0:1/5:3", "--y", "nu=0:2:3",
      "--figure", BAD], "analysis.regularity.atlas", "holder_atlas"),
    (["refine", "--scheme", "chaikin", "--points", "0,0;1,0;1,1", "--output", "/nonexistent/x.csv"],
     "analysis.stationary.refinement", "refine"),
    (["nonuniform", "refine", "--points", "0,0;1,0;1,1", "--u", "1", "--output", "/nonexistent/x.csv"],
     "analysis.nonuniform", "refine"),
    (["nonuniform", "reproduce", "--figure", BAD], "analysis.nonuniform", "reproduce"),
    (["nonuniform", "chamfer", "--figure", BAD], "analysis.nonuniform", "chamfer_example"),
    (["reproduce", "--scheme", "exp-chaikin-trig", "--lambdas", "I*t,-I*t", "--param", "t=1", "--plot", BAD],
     "analysis.levels.reproduction", "generation"),
    (["report", "000", "--output", "/dev/null/dir"], "analysis.cli.report", "evaluate_paper"),   # cannot be created
], ids=["range", "atlas", "refine", "nonuniform-refine", "nonuniform-reproduce", "nonuniform-chamfer",
        "reproduce", "report"])
def test_unwritable_output_fails_before_computing(capsys, monkeypatch, argv, module, name):
    _forbid(monkeypatch, module, name)
    code, out, err = call(capsys, *argv)
    assert code == 2, err
    assert err.count("\n") == 1 and ("cannot write" in err or "does not exist" in err or "cannot create" in err), err


def test_output_path_that_is_a_directory_is_refused(capsys, monkeypatch, tmp_path):
    _forbid(monkeypatch, "analysis.regularity.ranges", "ck_parameter_set")
    code, out, err = call(capsys, "range", "--scheme", "four-point", "--C", "1", "--within=0,1/4",
                          "--figure", str(tmp_path))
    one_line_error(code, err, "it is a directory")


# --------------------------------------------------------------------------------------------
# 9.8 enclosures printed outward, never a negative zero
# --------------------------------------------------------------------------------------------

def test_fmt_bound_rounds_outward_exactly():
    rng = random.Random(9)
    values = [Fraction(rng.randint(-10**30, 10**30), 10**rng.randint(0, 40)) for _ in range(300)]
    values += [Fraction(-1, 10**27), Fraction(0), Fraction(99999999995, 10**11), Fraction(-99999999995, 10**11)]
    for q in values:
        for style, digits in (("f", 10), ("f", 0), ("e", 6), ("g", 1), ("g", 12)):
            lo, hi = fmt_lower(q, digits, style), fmt_upper(q, digits, style)
            assert Fraction(lo) <= q <= Fraction(hi), (q, style, digits, lo, hi)
            for s in (lo, hi):
                assert not (s.startswith("-") and Fraction(s) == 0), s          # no negative zero
            if style == "f":
                assert Fraction(hi) - Fraction(lo) <= Fraction(1, 10**digits)   # and as tight as printed
    x = sp.sqrt(2)                                   # irrational: rigorous via high-precision evaluation
    assert (fmt_lower(x, 12), fmt_upper(x, 12)) == ("1.414213562373", "1.414213562374")
    assert fmt_upper(0.1 + 0.2, 1) == "0.4" and fmt_lower(0.1 + 0.2, 1) == "0.3"
    assert fmt_bound(Fraction(-1, 10**27), "upper") == "0.0000000000"
    with pytest.raises(ValueError):
        fmt_bound(1, "nearest")


def test_zero_enclosure_never_prints_negative_zero(capsys):
    """phi = delta (a = 2): s_2 is enclosed in [-1/2, 0]; the upper end 0 prints as 0.0000000000."""
    code, out, err = call(capsys, "holder", "--mask", "2", "--start", "0", "--sobolev")
    assert code == 0, err
    assert "s_2 in [-0.5000000000, 0.0000000000]" in out and not re.search(r"-0\.0+\b(?![0-9]*[1-9])", out), out


def _printed_pairs(text):
    return re.findall(r"\[(-?[0-9.e+-]+), (-?[0-9.e+-]+)\]", text)


def test_series_and_decay_enclosures_contain_the_exact_ones(capsys):
    argv = ["nonuniform", "decay", "--u0", "0.5,2", "--degree", "2", "--levels", "3"]
    code, text, _ = call(capsys, *argv)
    code2, js, _ = call(capsys, *argv, "--json")
    assert code == code2 == 0
    rows = json.loads(js)["witness"]["levels"]
    pairs = _printed_pairs(text)
    assert len(pairs) == len(rows)
    for (lo, hi), row in zip(pairs, rows):
        assert Fraction(lo) <= Fraction(row["lower"]) and Fraction(row["upper"]) <= Fraction(hi)
    argv = ["series", "--scheme", "seed003-trigonometric", "--param", "alpha=1", "--param", "omega=1/100", "--m", "1"]
    code, text, _ = call(capsys, *argv)
    code2, js, _ = call(capsys, *argv, "--json")
    (lo, hi), = _printed_pairs(text)
    s = json.loads(js)["series"][0]
    assert Fraction(lo) <= Fraction(sp.Rational(s["lower"]).p, sp.Rational(s["lower"]).q)
    assert Fraction(sp.Rational(s["upper"]).p, sp.Rational(s["upper"]).q) <= Fraction(hi)


def test_holder_text_enclosures_contain_the_json_ones(capsys):
    argv = ["holder", "--mask", "2", "--start", "0", "--sobolev"]
    code, text, _ = call(capsys, *argv)
    code2, js, _ = call(capsys, *argv, "--json")
    s2 = json.loads(js)["sobolev"]
    (lo, hi), = _printed_pairs(text.split("s_2 in", 1)[1])
    assert Fraction(lo) <= Fraction(s2["lower"]) and Fraction(s2["upper"]) <= Fraction(hi)


# --------------------------------------------------------------------------------------------
# 9.8 subdiv --version
# --------------------------------------------------------------------------------------------

def test_version(capsys):
    from importlib.metadata import version

    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out == f"subdiv {version('subdiv-workbench')}\n"


# --------------------------------------------------------------------------------------------
# 9.8 reports independent of float64 round-off
# --------------------------------------------------------------------------------------------

def test_roundoff_text():
    assert roundoff_text(8.9e-16) == roundoff_text(2.2e-15) == roundoff_text(-3e-13) == "< 1e-12"
    assert roundoff_text(2.01e-9) == "<= 3e-09" and roundoff_text(Fraction(3, 10**9)) == "<= 3e-09"


def _verdict_text(v):
    return (v.summary, [e.text for e in v.evidence], [(n.name, n.to_json()) for n in v.numbers])


def _claim(paper, cid):
    (c,) = [c for c in paper.claims if c.id == cid]
    return c


@pytest.mark.parametrize("which", ["000-reproduction", "001-reproduction", "001-algorithm2"])
def test_report_text_is_independent_of_float_roundoff(monkeypatch, which):
    """The same claim evaluated with two different float64 round-off figures (as on two machines:
    8.9e-16 here, 2.2e-15 there) gives the same verdict text and key numbers."""
    from analysis import nonuniform as nu
    from papers.seed000 import claims as seed000
    from papers.seed001 import PAPER as PAPER_001
    from papers.seed001 import examples as seed001_sect4  # Sect. 4 evaluators: they call claim_* from here

    texts = []
    for noise in (8.9e-16, 2.2e-15):
        if which == "000-reproduction":
            real = nu.reproduce

            def patched(*a, _real=real, _noise=noise, **k):
                r = _real(*a, **k)
                r.witness["form_error"][-1] = _noise
                return r
            monkeypatch.setattr(seed000.nu, "reproduce", patched)
            # seed 000 is a paper file: its claim calls the `python` evaluator _v_reproduction by name
            (claim,) = [c for c in seed000.PAPER.claims if c.id.endswith(":reproduction")]
        elif which == "001-reproduction":
            real = seed001_sect4.claim_reproduction

            def patched(_real=real, _noise=noise):
                return {k: _noise if v < 1e-12 else v for k, v in _real().items()}
            monkeypatch.setattr(seed001_sect4, "claim_reproduction", patched)
            # seed 001 is a paper file: its claim calls the `python` evaluator _v_reproduction by name
            claim = _claim(PAPER_001, "001:Remark1(reproduction)")
        else:
            real = seed001_sect4.claim_chamfer

            def patched(_real=real, _noise=noise):
                r = _real()
                r.witness["midpoint_deviation"][-1] = _noise
                return r
            monkeypatch.setattr(seed001_sect4, "claim_chamfer", patched)
            claim = _claim(PAPER_001, "001:Algorithm2")
        texts.append(_verdict_text(claim.evaluate()))
        monkeypatch.undo()
    assert texts[0] == texts[1]
    assert "< 1e-12" in json.dumps(texts[0])


def test_norm_solve_without_m_is_the_convergence_test(capsys):
    from analysis.cli.main import main

    assert main(["norm", "--scheme", "four-point", "--solve", "w"]) == 0
    out = capsys.readouterr().out
    # ||(1/2 S_{a_1})|| = 1/2 + 2|w| for the four-point scheme: < 1 exactly on (-1/4, 1/4)
    assert "L = 1: (-1/4, 1/4)" in out and "C^0 (Dyn-Levin)" in out and "C^-1" not in out
    assert main(["norm", "--scheme", "four-point", "--solve", "w", "--m", "0"]) == 2
    err = capsys.readouterr().err
    assert "tests no smoothness" in err and err.count("\n") == 1


def test_range_shows_progress_on_a_terminal_only(capsys, monkeypatch):
    import io

    from analysis.cli.main import main

    argv = ["range", "--mask", "-w,0,w+1/2,1,w+1/2,0,-w", "--start", "-3", "--C", "0", "--within=0,1/8",
            "--grid", "2"]
    assert main(argv) == 0
    quiet = capsys.readouterr()
    assert quiet.err == ""                                    # not a terminal: nothing on stderr

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    term = Terminal()
    monkeypatch.setattr("sys.stderr", term)
    assert main(argv) == 0
    assert capsys.readouterr().out == quiet.out               # the result does not depend on it
    shown = term.getvalue()
    assert "subdiv range: C^0 verdicts at the grid points 3/3" in shown and shown.endswith("\r")


def test_range_and_atlas_tables_for_papers_and_spreadsheets(tmp_path, capsys):
    import csv

    from analysis.cli.main import main

    tex, table = tmp_path / "c1.tex", tmp_path / "atlas.csv"
    four = ["--mask", "-w,0,w+1/2,1,w+1/2,0,-w", "--start", "-3"]
    assert main(["range", *four, "--C", "1", "--within=0,1/4", "--grid", "4", "--table", str(tex)]) == 0
    text = tex.read_text()
    # the C^1 set (0, w*) with w* the real root of 32 w^3 + 4 w - 1, as a paper writes it
    assert r"$C^{1}$ & $0$ & root $\approx 0.1927292493$ of $32 w^{3} + 4 w - 1$ \\" in text
    assert text.startswith("% subdiv range:") and r"\bottomrule" in text
    family = "(1+z)**2/(2*z)*(1 + s*(z-2+1/z) + t*(z**2-2+z**-2))"       # tests/test_atlas.py
    assert main(["atlas", "--symbol", family, "--x", "s=0:1/8:2", "--y", "t=0:0:1", "--j", "1", "--refine", "0",
                 "--executor", "serial", "--table", str(table)]) == 0
    out = capsys.readouterr().out
    rows = list(csv.reader(table.open()))
    assert rows[0] == ["s", "t", "alpha lower", "alpha upper", "status", "C^1"]
    assert [r[:2] for r in rows[1:]] == [["0", "0"], ["1/8", "0"]]
    for r in rows[1:]:                 # the enclosures the command printed, outward-rounded
        assert f"{r[0]:>10} {r[1]:>10}  {r[2]:>12} {r[3]:>12}  {r[4]:<12}" in out
    assert main(["range", *four, "--C", "1", "--within=0,1/4", "--table", str(tmp_path / "c1.txt")]) == 2
    assert "end the name in .csv" in capsys.readouterr().err
