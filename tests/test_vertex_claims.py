"""Paper-file claims about extraordinary vertices (kind ``vertex``): the example paper file
``tests/data/vertex-claims.toml`` (true and deliberately false claims) is evaluated once and every
verdict is asserted, with the first failing valence of each refutation; bad fields fail at load time."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis.claims.model import evaluate_paper
from analysis.claims.paperfile import load_paper, parse_paper
from analysis.result import AnalysisError

DATA = Path(__file__).parent / "data" / "vertex-claims.toml"

T, F, I = "CERTIFIED TRUE", "REFUTED", "INCONCLUSIVE"
EXPECTED = {"Loop.lambda": T, "Loop.lambda.wrong": F, "CatmullClark.lambda": T, "Loop.C1": T, "Loop.eigen": T,
            "Butterfly.C1": F, "Butterfly.C1.4": I, "Butterfly.eigen": F, "Warren.eigen": T,
            "Butterfly.notC1.3": T, "Butterfly.notC1.4": I, "Warren.C1.3": I}


@pytest.fixture(scope="module")
def verdicts():
    paper = load_paper(DATA)
    return {e.claim.id.split(":", 1)[1]: e.verdict for e in evaluate_paper(paper)}


def test_every_vertex_claim_is_judged_right(verdicts):
    assert {k: v.label for k, v in verdicts.items()} == EXPECTED


def _first_failure(v) -> int:
    return int(next(x.value for x in v.numbers if x.name == "first failing valence"))


def test_refutations_name_the_first_failing_valence_and_the_reason(verdicts):
    v = verdicts["Butterfly.eigen"]
    assert _first_failure(v) == 8 and "block 2" in v.summary
    v = verdicts["Loop.lambda.wrong"]
    assert _first_failure(v) == 3 and "lambda = 1/4" in v.summary and "1/4" in v.corrected


def test_failed_eigen_conditions_leave_c1_undecided_and_say_what_failed(verdicts):
    """Reif's conditions are sufficient; their certified failure is not by itself a certified "not C^1"
    (Warren's weight at n = 3: no not-C^1 theorem with checked hypotheses applies to Loop-type rules), so
    the C^1 claim stays open, naming the failure."""
    v = verdicts["Warren.C1.3"]
    assert "n = 3" in v.summary and "fail, certified" in v.summary and "no not-C^1 theorem" in v.summary
    assert "not C^1" in v.settle


def test_butterfly_c1_is_refuted_by_a_checked_theorem(verdicts):
    """The butterfly at n = 3: lambda = 1/4 has a Jordan chain of length 3 in block 0 whose eigenfunction has
    one sign around the vertex (analysis.vertex.necessary): "C^1 at 3..8" is refuted at n = 3, "not C^1 at 3"
    is certified, "not C^1 at 4" stays open (Reif's conditions hold there)."""
    v = verdicts["Butterfly.C1"]
    assert _first_failure(v) == 3 and "Jordan chain of length 3" in v.summary and "not C^1" in v.corrected
    assert "n = 3" in verdicts["Butterfly.notC1.3"].summary
    assert "n = 4" in verdicts["Butterfly.notC1.4"].summary


def test_undecided_c1_says_why(verdicts):
    v = verdicts["Butterfly.C1.4"]
    assert "n = 4" in v.summary and "characteristic map not certified" in v.summary
    assert "characteristic map" in v.settle


def _claim(body: str):
    return parse_paper('[paper]\nid = "t"\ntitle = "t"\n[[claims]]\nid = "c"\nstatement = "s"\nkind = "vertex"\n'
                       + body, "t.toml")


@pytest.mark.parametrize("body, message", [
    ('surface = "loop"\nvalence = "3..51"\nproperty = "C1"', "3 <= A <= B <= 50"),
    ('surface = "loop"\nvalence = "8..3"\nproperty = "C1"', "3 <= A <= B <= 50"),
    ('surface = "loop"\nvalence = 2\nproperty = "C1"', "3 <= A <= B <= 50"),
    ('surface = "lop"\nvalence = "3..5"\nproperty = "C1"', "field 'surface' must be one of"),
    ('surface = "loop"\nvalence = "3..5"\nproperty = "C2"', "field 'property' must be one of"),
    ('surface = "loop"\nvalence = "3..5"\nproperty = "subdominant eigenvalue"', "field 'value' goes with"),
    ('surface = "loop"\nvalence = "3..5"\nproperty = "subdominant eigenvalue"\nvalue = "x/8"', "x"),
    ('surface = "loop"\nlattice = "triangle"\ncentre = "1/n"\nvalence = "3"\nproperty = "C1"', "not both"),
])
def test_bad_fields_fail_at_load_with_one_line(body, message):
    with pytest.raises(AnalysisError) as e:
        _claim(body)
    assert message in str(e.value) and "\n" not in str(e.value)


def test_a_single_valence_and_user_rules_load():
    p = _claim('lattice = "quad"\ncentre = "3/(2*n**2), 1/(4*n**2)"\nvalence = 5\nproperty = "eigen-conditions"\n')
    assert p.claims[0].kind == "vertex"


def _verdict(value: str, valence: str = "5..6"):
    fields = {"surface": "loop", "valence": valence, "property": "subdominant eigenvalue", "value": value, "ring": 1}
    from analysis.claims.kinds.vertex import Vertex

    return Vertex(fields, {}, "t").evaluate()


def test_a_formula_undefined_at_a_valence_is_refuted_there():
    v = _verdict("1/(n - 5)")
    assert v.label == F and "undefined at n = 5" in v.summary and _first_failure(v) == 5


def test_an_equal_formula_written_otherwise_is_certified_and_one_outside_arb_is_inconclusive():
    """Exact equality through the minimal polynomial; a formula the ball evaluator cannot enclose is undecided."""
    assert _verdict("3/8 + (2*cos(pi/n)**2 - 1)/4", "5..7").label == T       # exact: cos(2x) = 2 cos(x)^2 - 1
    v = _verdict("3/8 + cos(2*pi/n)**(3/2)/4")                      # a rational power of a positive ball: enclosed
    assert v.label == F and _first_failure(v) == 5
    v = _verdict("3/8 + cos(2*pi/n)**(3/2)/4", "3..4")              # cos(2 pi/3) < 0: not a real number
    assert v.label == I and "Arb evaluator" in v.summary
