"""Issue 11: parameter values of a claim are checked against the scheme's domains exactly, also when
they are not algebraic (``pi/5``: found while converting seed 003 — it raised NotAlgebraic)."""

import pytest

from analysis.claims.paperfile import parse_paper
from analysis.result import AnalysisError

PAPER = """
[paper]
id = "dom"
title = "domains"

[schemes.chaikin-like]
mask = ["1/4 + t", "3/4 - t", "3/4 - t", "1/4 + t"]
start = -2
parameters = { t = "(-1/8, pi/20)" }

[[claims]]
id = "C1"
statement = "sum rules at t = AT"
kind = "sum rules"
factors = 2
exceptional = [{ at = { t = "AT" }, factors = 2 }]
"""


@pytest.mark.parametrize("at", ["pi/40", "1/10", "sqrt(2)/20"])
def test_transcendental_and_algebraic_values_inside_the_domain_load(at):
    parse_paper(PAPER.replace("AT", at), "dom.toml")


@pytest.mark.parametrize("at", ["pi/20", "pi/10", "-1/8", "exp(1)"])
def test_values_outside_the_domain_are_one_line_errors(at):
    with pytest.raises(AnalysisError, match="outside|not in|domain"):
        parse_paper(PAPER.replace("AT", at), "dom.toml")
