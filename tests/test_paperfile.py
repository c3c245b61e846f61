"""Issue 11, items 1, 3 and 6: paper files, `subdiv report/check FILE.toml`, `subdiv new-paper`,
and bad paper files (one-line errors; a failing claim is inconclusive, the others still run)."""

from __future__ import annotations

import json

import pytest

from analysis.claims.kinds import KIND_CLASSES
from analysis.claims.model import evaluate_paper, verdicts_json
from analysis.claims.paperfile import golden_file, load_paper, parse_paper
from analysis.claims.template import template
from analysis.cli import main
from analysis.result import AnalysisError

EXTRA = ["analysis.cli.report", "analysis.cli.paperfile"]

SMALL = '''
[paper]
id = "901"
title = "Chaikin and the 4-point scheme"
authors = ["G. Chaikin"]
citation = "Comput. Graph. Image Process. 3 (1974)"

[schemes.chaikin]
symbol = "(1+z)**3/(4*z**2)"

[schemes.four]
catalogue = "four-point"
parameters = { w = "(-1/4, 1/4)" }

[[claims]]
id = "Prop1"
statement = "Chaikin's algorithm has three smoothing factors."
kind = "sum rules"
scheme = "chaikin"
factors = 3

[[claims]]
id = "Prop2"
statement = "The 4-point scheme with w = 1/16 has Hoelder exponent 2."
kind = "holder"
scheme = "four"
at = { w = "1/16" }
value = 2
'''


def _write(tmp_path, text, name="p.toml"):
    f = tmp_path / name
    f.write_text(text, encoding="utf-8")
    return f


def _err(tmp_path, capsys, text):
    f = _write(tmp_path, text)
    assert main(["report", str(f), "--output", str(tmp_path)], extra_modules=EXTRA) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and err.startswith("subdiv: error: ")
    return err


def test_syntax_error_names_file_and_line(tmp_path, capsys):
    err = _err(tmp_path, capsys, SMALL.replace('factors = 3', 'factors = = 3'))
    line = SMALL.splitlines().index("factors = 3") + 1
    assert f"p.toml:{line}: TOML syntax error" in err


def test_unknown_kind_lists_the_kinds(tmp_path, capsys):
    err = _err(tmp_path, capsys, SMALL.replace('kind = "holder"', 'kind = "hölder"'))
    assert "unknown kind 'hölder'" in err and all(k in err for k in KIND_CLASSES)


@pytest.mark.parametrize("old,new,named", [
    ('scheme = "four"', 'scheme = "five"', "unknown scheme 'five'"),
    ('at = { w = "1/16" }', 'at = { omega = "1/16" }', "unknown parameter 'omega'"),
    ('value = 2', 'valeur = 2', "unknown field 'valeur'"),
    ('catalogue = "four-point"', 'catalogue = "four-piont"', "unknown scheme 'four-piont'"),
    ('parameters = { w = "(-1/4, 1/4)" }', 'parameters = { v = "real" }', "unknown parameter 'v'"),
    ('at = { w = "1/16" }', 'at = { w = "1/2" }', "outside its domain"),
    ('title = "Chaikin and the 4-point scheme"\n', '', "missing 'title'"),
])
def test_unknown_names_are_named(tmp_path, capsys, old, new, named):
    assert old in SMALL
    assert named in _err(tmp_path, capsys, SMALL.replace(old, new))


def test_a_raising_claim_is_inconclusive_and_the_others_still_run(tmp_path):
    import schemes

    p = parse_paper(SMALL.replace('at = { w = "1/16" }\n', ''), "p.toml", catalogue=schemes.get)   # w left free
    evs = evaluate_paper(p)
    assert [e.verdict.status for e in evs] == ["certified", "inconclusive"]
    assert "fix every parameter" in evs[1].error


def test_report_update_golden_and_check(tmp_path, capsys):
    f = _write(tmp_path, SMALL)
    out = tmp_path / "out"
    out.mkdir()
    assert main(["report", str(f), "--output", str(out), "--update-golden", "--quiet", "--no-figures"],
                extra_modules=EXTRA) == 0
    golden = golden_file(f)
    assert golden.name == "p.verdicts.json" and (out / "901.md").is_file()
    data = json.loads(golden.read_text())
    assert data["papers"]["901"]["title"] == "Chaikin and the 4-point scheme"
    assert {c: v["status"] for c, v in data["papers"]["901"]["claims"].items()} == {"901:Prop1": "certified",
                                                                                    "901:Prop2": "certified"}
    assert not [p for p in tmp_path.rglob("*.tmp")]                # atomic writes leave no temporary file
    capsys.readouterr()
    assert main(["check", str(f), "--quiet"], extra_modules=EXTRA) == 0
    assert "2 claims agree" in capsys.readouterr().out
    # a changed claim (a wrong count) makes `check` fail with a readable diff
    _write(tmp_path, SMALL.replace("factors = 3", "factors = 2"))
    with pytest.raises(SystemExit) as e:
        main(["check", str(f), "--quiet"], extra_modules=EXTRA)
    assert e.value.code == 1
    assert "901:Prop1: status changed: certified -> refuted" in capsys.readouterr().out


def test_json_output_is_one_document(tmp_path, capsys):
    f = _write(tmp_path, SMALL)
    assert main(["report", str(f), "--claim", "901:Prop1", "--json", "--quiet"], extra_modules=EXTRA) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["papers"]["901"]["claims"]["901:Prop1"]["numbers"]["factors"]["exact"] == "3"


def test_new_paper_template_loads_and_evaluates(tmp_path, capsys):
    f = tmp_path / "new.toml"
    assert main(["new-paper", str(f)], extra_modules=EXTRA) == 0
    assert f.read_text() == template()
    assert main(["new-paper", str(f)], extra_modules=EXTRA) == 2              # no silent overwrite
    assert "exists" in capsys.readouterr().err
    paper = load_paper(f)
    assert sorted(c.kind for c in paper.claims) == sorted(KIND_CLASSES)
    evs = evaluate_paper(paper)
    bad = [(e.claim.id, e.error) for e in evs if e.error]
    assert not bad, bad
    json.dumps(verdicts_json({paper.id: evs}, titles={paper.id: paper.title}))    # every key number serialises
    # every example is true, except "cited" (inconclusive by design), "python" (a paper file runs no code
    # without --allow-python: not run); a curve comparison is float64 (numerical)
    assert {e.claim.kind: e.verdict.status for e in evs if e.verdict.status != "certified"} == {
        "cited": "inconclusive", "python": "inconclusive", "curve comparison": "numerical"}
    assert next(e for e in evs if e.claim.kind == "python").verdict.summary.startswith("not run")
    # allowed, the template's python example runs (the bundled evaluator it names) and is true
    trusted = load_paper(f, python="allowed")
    claim = next(c for c in trusted.claims if c.kind == "python")
    assert claim.runs_python and evaluate_paper(trusted, only=[claim.id])[0].verdict.status == "certified"


def test_paper_file_without_catalogue_is_an_error():
    with pytest.raises(AnalysisError, match="catalogue names need the catalogue"):
        parse_paper(SMALL, "p.toml")


def test_a_kind_on_the_wrong_sort_of_scheme_fails_at_load():
    level = '[paper]\nid = "902"\ntitle = "t"\n[schemes.e]\nlevel_mask = ["1/4", "3/4", "3/4", "1/4"]\nstart = -2\n'
    with pytest.raises(AnalysisError, match="kind 'holder' needs a stationary scheme"):
        parse_paper(level + '[[claims]]\nid = "a"\nstatement = "s"\nkind = "holder"\nvalue = 1\n', "p.toml")
    with pytest.raises(AnalysisError, match="needs a level-dependent scheme"):
        parse_paper(SMALL + '[[claims]]\nid = "a"\nstatement = "s"\nkind = "asymptotic equivalence"\n'
                    'scheme = "chaikin"\nconverges = true\n', "p.toml", catalogue=lambda n: __import__("schemes").get(n))


# ------------------------------------------------------------------ parameter values vs the scheme's domains
#: parameter values of a claim are checked against the scheme's domains exactly, also when they are not
#: algebraic (``pi/5``: found while converting seed 003 - it raised NotAlgebraic)
DOMAINS = """
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
    parse_paper(DOMAINS.replace("AT", at), "dom.toml")


@pytest.mark.parametrize("at", ["pi/20", "pi/10", "-1/8", "exp(1)"])
def test_values_outside_the_domain_are_one_line_errors(at):
    with pytest.raises(AnalysisError, match="outside|not in|domain"):
        parse_paper(DOMAINS.replace("AT", at), "dom.toml")
