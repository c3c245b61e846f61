"""Tests of analysis.levels.reproduction and the `subdiv series/bound/reproduce` commands."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.cli import main
from analysis.levels.reproduction import curve_deviation, generation, reproduction
from schemes import seed003 as S
from schemes.level_dependent import T, get

A = S.ALPHA
EXTRA = ["analysis.cli.levels"]


@pytest.mark.parametrize("slug, lambdas", [("exp-chaikin-hyp", [0, T, -T]), ("exp-chaikin-trig", [0, sp.I * T, -sp.I * T]),
                                           ("exp-cubic-hyp", [0, T, -T])], ids=["chaikin-hyp", "chaikin-trig", "cubic-hyp"])
def test_exponential_bsplines_generate_their_exponentials(slug, lambdas):
    assert generation(get(slug), lambdas).status == "certified"


def test_exponential_chaikin_generates_but_does_not_reproduce():
    r = reproduction(get("exp-chaikin-hyp"), [T, -T])
    assert r.status == "refuted" and r.witness["generation"] is True


@pytest.mark.parametrize("omega, status", [(0, "certified"), (sp.Rational(1, 100), "refuted")], ids=["omega0", "omega1/100"])
def test_normalized_trig_form_generates_circles_only_without_perturbation(omega, status):
    assert generation(S.TRIGONOMETRIC_NORMALIZED, [sp.I * A, -sp.I * A], {"omega": omega}).status == status


def test_circle_exact_for_generating_scheme_and_not_for_perturbed(tmp_path):
    plot = tmp_path / "k.png"
    ok = curve_deviation(S.TRIGONOMETRIC_NORMALIZED, "circle", {"alpha": sp.pi / 4, "omega": 0}, points=8,
                         steps=5, plot=str(plot))
    bad = curve_deviation(S.TRIGONOMETRIC_NORMALIZED, "circle", {"alpha": sp.pi / 4, "omega": sp.Rational(1, 100)},
                          points=8, steps=5)
    assert ok.status == "numerical" and ok.value < 1e-12 and plot.stat().st_size > 1000
    assert bad.value > 1e-4


def test_cli_series_json_reports_divergence(capsys):
    assert main(["series", "--scheme", "seed003-trigonometric", "--param", "alpha=1", "--param", "omega=1/100",
                 "--m", "1,2", "--json"], extra_modules=EXTRA) == 0
    out = json.loads(capsys.readouterr().out)
    verdicts = [row["witness"]["verdict"] for row in out["series"]]
    assert verdicts == ["convergent", "divergent"]


def test_cli_bound_claim_refuted(capsys):
    assert main(["bound", "--claim", "003:Lemma3.1(vii)-lower", "--box", "alpha=1/100,pi/3"], extra_modules=EXTRA) == 0
    assert "refuted" in capsys.readouterr().out


def test_cli_reproduce_text(capsys):
    assert main(["reproduce", "--scheme", "exp-chaikin-trig", "--lambdas", "I*t,-I*t", "--param", "t=pi/4",
                 "--curve", "circle", "--points", "8", "--steps", "4"], extra_modules=EXTRA) == 0
    out = capsys.readouterr().out
    assert "generation of exp(lambda x), lambda in I*t,-I*t: certified" in out


_TRIG = ["--scheme", "seed003-trigonometric"]
_OM = ["--param", "omega=1/100"]
_REP = ["reproduce", "--scheme", "exp-chaikin-trig", "--param", "t=pi/4", "--curve", "circle"]


@pytest.mark.parametrize("argv, message", [
    (["series", "--scheme", "seed003-trig"], "unknown level-dependent scheme"),
    (["bound", "--lhs", "1"], "give --claim"),
    (["series", "--scheme", "seed003-trigonometric", "--box", "alpha=1"], "malformed --box"),
    (["series", *_TRIG, "--box", "alpha=1,0", *_OM, "--m", "1"], "empty parameter box"),
    (["series", *_TRIG, "--param", "alpha=1", *_OM, "--m", "1", "--pieces", "0"], "--pieces must be >= 1"),
    (["series", *_TRIG, "--param", "alpha=1", *_OM, "--m", "1", "--difference", "-1"], "--difference must be >= 0"),
    (["series", *_TRIG, "--param", "alpha=-1", *_OM, "--m", "1"], "outside the declared domain of alpha"),
    (["bound", "--lhs", "3/4", "--rhs", "sin(3*alpha/2**(n+2))/sin(alpha/2**n)", "--n0", "-1", "--box",
      "alpha=1/100,1"], "--n0 must be a non-negative level"),
    ([*_REP, "--plot", "/nonexistent/dir/x.png"], "cannot write the plot"),
    ([*_REP, "--points", "0"], "points must be an integer >= 3"),
    ([*_REP, "--points", "-4"], "points must be an integer >= 3"),
    ([*_REP, "--steps", "-1"], "steps must be an integer in 0..12"),
    ([*_REP, "--steps", "13"], "steps must be an integer in 0..12"),
], ids=["unknown-scheme", "missing-rhs", "bad-box", "reversed-box", "pieces-0", "difference-neg", "alpha-neg",
        "n0-neg", "plot-dir", "points-0", "points-neg", "steps-neg", "steps-too-many"])
def test_cli_errors_are_one_line(argv, message, capsys):
    assert main(argv, extra_modules=EXTRA) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


def test_plot_write_failure_is_an_analysis_error(tmp_path):
    """An unwritable plot target (here: a directory) is a one-line AnalysisError, not an OSError."""
    from analysis.result import AnalysisError

    target = tmp_path / "d.png"
    target.mkdir()
    with pytest.raises(AnalysisError, match="cannot write the plot"):
        curve_deviation(get("exp-chaikin-trig"), "circle", {"t": sp.pi / 4}, points=8, steps=2, plot=str(target))
