"""The `subdiv` CLI: end to end in a subprocess, and every bad input with its one-line message."""

import json
import subprocess
import sys

import pytest
import sympy

from analysis.cli import main


def run(*args):
    """Run `python -m analysis ARGS` in a subprocess (what a user types, minus the console script)."""
    p = subprocess.run([sys.executable, "-m", "analysis", *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def test_e2e_norm_set_seed003_acceptance():
    code, out, err = run("norm", "--scheme", "dfh-chaikin-perturbation", "--m", "3", "--L", "1,2",
                         "--solve", "omega", "--within", "0,oo", "--json")
    assert code == 0, err
    data = json.loads(out)
    by_L = {r["L"]: r["set"] for r in data["results"]}
    assert by_L[1] == []
    (part,) = by_L[2]
    assert (part["lower"], part["upper"]) == ("0", "-1/80 + sqrt(6)/80")
    assert not part["lower_closed"] and not part["upper_closed"]


def test_e2e_symbol_factor_refine_text():
    code, out, _ = run("factor", "--mask", "1/4,3/4,3/4,1/4", "--start", "-2")
    assert code == 0 and "a(z) = ((1+z)/2)^3 b(z)" in out
    code, out, _ = run("symbol", "--even", "3/4,1/4", "--odd", "1/4,3/4", "--first", "0", "--json")
    assert code == 0
    data = json.loads(out)
    assert data["mask"] == ["1/4", "3/4", "3/4", "1/4"] and data["start"] == -2
    code, out, _ = run("refine", "--scheme", "chaikin", "--points", "0,0;1,0;1,1;0,1", "--exact", "--json")
    assert code == 0
    pts = json.loads(out)["points"]
    assert len(pts) == 8 and pts[0] == ["1/4", "0"]


def test_e2e_console_script_is_installed():
    import shutil

    exe = shutil.which("subdiv")
    if exe is None:
        pytest.skip("console script not on PATH (package not installed with pip)")
    p = subprocess.run([exe, "list"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0 and "dfh-chaikin-perturbation" in p.stdout


def test_numeric_norm_json(capsys):
    assert main(["norm", "--scheme", "dfh-chaikin-perturbation", "--param", "omega=1/100", "--m", "3",
                 "--L", "1,2", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["results"]
    assert [r["norm"]["exact"] for r in rows] == ["29/25", "551/625"]
    assert [r["contractive"] for r in rows] == [False, True]


@pytest.mark.parametrize("argv,message", [
    (["norm", "--mask", "1/4,,3/4"], "malformed mask"),
    (["norm", "--mask", "1/4,abc("], "cannot read coefficient"),
    (["symbol", "--mask", "sin(1),1"], "not an exact algebraic number"),
    (["norm", "--mask", "1,1", "--start", "x"], "--start must be an integer"),
    (["norm", "--scheme", "dfh-chaikin-perturbation", "--param", "nu=1"], "unknown parameter 'nu'"),
    (["norm", "--scheme", "dfh-chaikin-perturbation", "--m", "3"], "free parameter(s) omega"),
    (["refine", "--scheme", "four-point", "--points", "0;1;2;3"], "needs values for the parameter(s) w"),
    (["norm", "--scheme", "dfh-chaikin-perturbation", "--param", "omega=abc("], "cannot read"),
    (["norm", "--scheme", "dfh-chaikin-perturbation", "--param", "omega"], "use NAME=VALUE"),
    (["norm", "--scheme", "chaikin", "--m", "4"], "only 3 factor(s) (1+z)"),
    (["norm", "--mask", "1,2,3", "--m", "1"], "only 0 factor(s) (1+z)"),
    (["norm", "--scheme", "no-such-scheme"], "unknown scheme"),
    (["norm"], "give exactly one of"),
    (["norm", "--scheme", "chaikin", "--L", "0"], "between 1 and 24"),
    (["norm", "--scheme", "dfh-chaikin-perturbation", "--m", "3", "--solve", "mu"], "unknown parameter 'mu'"),
    (["norm", "--scheme", "dfh-chaikin-perturbation", "--m", "3", "--solve", "omega", "--within", "1"], "malformed --within"),
    (["norm", "--scheme", "seed004-design-control", "--m", "1", "--solve", "nu"], "fix the other parameter"),
    (["symbol", "--symbol", "1/(1+z)"], "Laurent polynomial"),
    (["symbol", "--even", "1"], "--even needs --odd"),
    (["refine", "--scheme", "chaikin", "--points", "0,0;1"], "same number of coordinates"),
    (["refine", "--scheme", "chaikin"], "exactly one of --points"),
    (["frobnicate"], "unknown command 'frobnicate'"),
    (["surface", "--scheme", "bicubic", "--refine", "2", "--grid", "hex"],
     "--grid takes quad or triangular, not 'hex'"),
    (["derive", "--symmetric", "x"], "--symmetric takes one of primal, dual, any, not 'x'"),
    (["nonuniform", "refin"], "unknown nonuniform command 'refin': did you mean `subdiv nonuniform refine`?"),
    (["symbol", "--mask", "inf,1"], "not a finite number"),
    (["refine", "--scheme", "chaikin", "--points", "0,0;1,0;1,1", "--output", "/nonexistent/x.csv"], "cannot write"),
    (["range", "--scheme", "four-point", "--C", "1", "--within=0,1/4", "--tol", "0"], "--tol must be between"),
    (["check", "--verdicts", "/etc/hostname"], "cannot read the golden file"),
    (["check", "003", "--claim", "nosuch"], "no claim of paper 003 matches"),
    (["report", "003", "--claim", "003:(7)", "--write"], "would replace the paper's report"),
    (["report", "003", "--output", "/dev/null/dir"], "cannot create the output folder"),   # under a device: no folder
], ids=lambda v: v if isinstance(v, str) else None)
def test_bad_input_one_line_exit_2(argv, message, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("subdiv: error: ") and message in err
    assert err.count("\n") == 1 and "Traceback" not in err


def test_bad_input_in_subprocess_has_no_traceback():
    code, out, err = run("norm", "--mask", "1/4,,3/4")
    assert code == 2 and out == "" and err.count("\n") == 1 and "malformed mask" in err


def test_holder_of_a_scheme_known_by_enclosures(capsys):
    assert main(["holder", "--scheme", "d6", "--json"]) == 0
    alpha = json.loads(capsys.readouterr().out)["alpha"]
    assert alpha["status"] == "certified"
    lo, hi = float(sympy.Rational(alpha["lower"])), float(sympy.Rational(alpha["upper"]))
    assert abs((lo + hi) / 2 - 1.0878339263) < 1e-10 and hi - lo < 1e-8   # Daubechies-Lagarias: 1.0878


def test_holder_json_for_exact_scheme(capsys):
    assert main(["holder", "--scheme", "four-point", "--param", "w=1/16", "--C", "1", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["alpha"]["value"] == 2 and data["smoothness"]["value"] is True
