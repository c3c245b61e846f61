"""Claims about bivariate schemes in a paper file (``bivariate = {...}`` schemes with the claim kinds ``sum
rules``, ``reproduction``, ``smoothness``, ``holder``, ``ck range``), each verdict asserted."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis.claims.model import evaluate_paper
from analysis.claims.paperfile import load_paper, parse_paper
from analysis.result import AnalysisError

DATA = Path(__file__).parent / "data" / "bivariate-claims.toml"
T, F = "CERTIFIED TRUE", "REFUTED"
EXPECTED = {"Courant.sumrules": T, "Courant.sumrules3": F, "Courant.reproduction": T, "Courant.C0": T,
            "Courant.C1": F, "Courant.alpha": T, "Bilinear.alpha": F, "Family.sumrules": T,
            "Family.C0.inner": T, "Family.C0.wide": F}


@pytest.fixture(scope="module")
def verdicts():
    return {e.claim.id.split(":", 1)[1]: e for e in evaluate_paper(load_paper(DATA))}


def test_every_bivariate_claim_is_judged_right(verdicts):
    assert {k: v.verdict.label for k, v in verdicts.items()} == EXPECTED


def test_the_wide_range_is_refuted_at_the_exact_end(verdicts):
    v = verdicts["Family.C0.wide"].verdict
    assert "t = 3/4" in v.summary


HEAD = '[paper]\nid = "t"\ntitle = "t"\n[schemes.s]\nbivariate = { symbol = "(1+z1)*(1+z2)/2", dilation = "quincunx" }\n'


@pytest.mark.parametrize("claims,match", [
    ('[[claims]]\nid = "c"\nstatement = "s"\nkind = "symmetry"\n', "not available for the bivariate scheme"),
    ('[[claims]]\nid = "c"\nstatement = "s"\nkind = "sobolev"\nvalue = 1\n', "not available for the bivariate"),
])
def test_kinds_without_a_bivariate_reading_are_refused(claims, match):
    with pytest.raises(AnalysisError, match=match):
        parse_paper(HEAD + claims, "t.toml")


@pytest.mark.parametrize("scheme,match", [
    ('bivariate = { symbol = "1+z1", mask = "0,0:1" }', "exactly one"),
    ('bivariate = { symbol = "1+z1", run = "x" }', "unknown key"),
    ('bivariate = { symbol = "1+w*z1" }\nparameters = { v = "(0, 1)" }', "unknown parameter 'v'"),
    ('bivariate = { symbol = "1+z1" }\nstart = 0', "not 'start'"),
])
def test_bad_bivariate_schemes(scheme, match):
    text = f'[paper]\nid = "t"\ntitle = "t"\n[schemes.s]\n{scheme}\n'
    with pytest.raises(AnalysisError, match=match):
        parse_paper(text, "t.toml")
