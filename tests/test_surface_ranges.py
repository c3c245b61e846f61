"""Certified C^l sets of one-parameter bivariate families (analysis.bivariate.ranges) and the mask file form
(analysis.bivariate.mask_file, ``subdiv surface --file``)."""

from __future__ import annotations

import json

import pytest
import sympy as sp
from flint import fmpq

from analysis.bivariate.mask import BivariateMask
from analysis.bivariate.mask_file import mask_from_data, read_mask_file
from analysis.bivariate.ranges import ck_set, parametric_family
from analysis.bivariate.transition import restricted_transition
from analysis.cli.main import main
from analysis.result import CERTIFIED, INCONCLUSIVE, AnalysisError

#: a perturbed tensor hat function: T_0(t) has the eigenvalue 1 at t = 3/4 exactly
HAT = "(1+z1)**2*(1+z2)**2/(4*z1*z2) + t*(1-z1**2)*(1-z2**2)/(z1*z2)"


@pytest.fixture(scope="module")
def hat():
    return BivariateMask.from_symbol(HAT)


@pytest.mark.parametrize("t", ["1/3", "-2/7", "5"])
def test_parametric_family_is_the_restriction_at_every_value(hat, t):
    F = parametric_family(hat, 1)
    want = restricted_transition(hat.at(t=t), 1, F.omega).matrices
    assert F.at(sp.Rational(t)) == list(want)


def test_bernstein_ends_are_the_matrices_at_the_ends_and_the_hull_holds_the_middle(hat):
    B = parametric_family(BivariateMask.from_symbol("(1+z1)*(1+z2)*(1+z1*z2)/(2*z1*z2) + t**2*(1-z1**2)*(1-z2**2)"
                                                    "/(z1*z2)"), 1)
    assert B.degree == 2
    u, v = sp.Rational(1, 4), sp.Rational(1, 2)
    C = B.bernstein(u, v)                  # 3 control matrices per digit, digit-major
    assert C[0] == B.at(u)[0] and C[2] == B.at(v)[0]
    # t = (u+v)/2: the Bernstein weights (1/4, 1/2, 1/4)
    mid = C[0] * fmpq(1, 4) + C[1] * fmpq(1, 2) + C[2] * fmpq(1, 4)
    assert mid == B.at((u + v) / 2)[0]


def test_hat_family_c0_set_reaches_its_exact_end(hat):
    r = ck_set(hat, 0, within=(0, 1), grid=2, budget=200_000, point_budget=5000, box_budget=5000, approach=3)
    (b,) = r.witness["boundaries"]
    assert b["exact"] == sp.Rational(3, 4) and "T_0" in b["how"]
    # the strip next to the end: a leading subspace of dimension 7 where the JSR is t + 1/4 (exact polytope
    # of the hull in 1/lambda, bound exactly 1), the quotient's JSR at most 1/2 < 1
    es = b["end_strip"]
    t = sp.Symbol("t")
    assert es["closed"] and es["lambda"] == t + sp.Rational(1, 4) and es["leading_dimension"] == 7
    assert es["polytope_bound"] == 1 and es["quotient_upper"] < 1 and es["letters"] == [0, 1, 2, 3]
    assert r.value["gaps"] == []
    assert sp.Rational(3, 4) in r.value["not_Cl"] and 1 in r.value["not_Cl"]
    # between the exact end 3/4 and the counterexample 1 every letter has the eigenvalue t + 1/4 twice: the sign of
    # det(T_w(t) - I) does not see it; the square-free part of the characteristic polynomial does
    (st,) = r.witness["not_Cl_proven"]
    assert (st["from"], st["to"]) == (sp.Rational(3, 4), 1) and "square-free" in st["how"]
    assert r.witness["between_counterexamples"] == [] and r.status == CERTIFIED
    (I,) = r.value["certified"]
    assert (I.start, I.end, I.left_open, I.right_open) == (0, sp.Rational(3, 4), False, True)
    assert all(x["certified_Cl"] for x in r.witness["boxes"] if x["to"] <= sp.Rational(5, 8))


def test_c_set_refuses_what_it_cannot_certify(hat):
    with pytest.raises(AnalysisError, match="exactly one free parameter"):
        ck_set(hat.at(t=0), 0, within=(0, 1))
    with pytest.raises(AnalysisError, match="C\\^2 needs order 3"):
        ck_set(hat, 2, within=(0, 1))
    q = BivariateMask.from_symbol("(1+z1)*(1+z2)/2 + t*(1-z1**2)", "quincunx")
    with pytest.raises(AnalysisError, match="irrational"):
        ck_set(q, 1, within=(0, 1))


def test_cli_c_set_needs_both_options(capsys):
    assert main(["surface", "--scheme", "butterfly", "--C", "1"]) == 2
    err = capsys.readouterr().err
    assert "--within" in err and "--param w=1/16 --C 1" in err


def test_cli_one_verdict_when_no_parameter_is_free(capsys):
    """``--C L`` on a scheme without a free parameter is the C^L verdict of the scheme, not a C^l set."""
    assert main(["surface", "--symbol", HAT, "--C", "0", "--json"]) == 2            # t is free: a set is asked
    capsys.readouterr()
    bilinear = "(1+z1)**2*(1+z2)**2/(4*z1*z2)"
    assert main(["surface", "--symbol", bilinear, "--C", "0", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["C"] == {"l": 0, "value": True, "status": "certified"}
    assert main(["surface", "--symbol", bilinear, "--C", "1"]) == 0                 # alpha = 1: not C^1
    assert capsys.readouterr().out.splitlines()[-1] == "C^1: no   [certified]"
    assert main(["surface", "--symbol", bilinear, "--C", "31"]) == 2
    assert "between 0 and 30" in capsys.readouterr().err
    assert main(["surface", "--symbol", bilinear, "--C", "1", "--within=0,1"]) == 2
    assert "no free parameter: drop --within (--C 1 alone gives its C^1 verdict)" in capsys.readouterr().err


# --------------------------------------------------------------------------- mask files

def test_toml_and_json_files_give_the_mask_of_the_options(tmp_path):
    t = tmp_path / "q.toml"
    t.write_text('name = "zp"\ndilation = "quincunx"\nsymbol = "(1+z1)*(1+z2)/2"\n', encoding="utf-8")
    j = tmp_path / "q.json"
    j.write_text(json.dumps({"dilation": [[1, 1], [1, -1]],
                             "mask": [[0, 0, "1/2"], [1, 0, "1/2"], [0, 1, "1/2"], [1, 1, "1/2"]]}), encoding="utf-8")
    a, b = read_mask_file(str(t)), read_mask_file(str(j))
    want = BivariateMask.from_list("0,0:1/2; 1,0:1/2; 0,1:1/2; 1,1:1/2", "quincunx")
    assert a.coeffs == b.coeffs == want.coeffs and a.dilation == b.dilation == want.dilation and a.name == "zp"


def test_mask_file_list_text_and_parameters():
    a = mask_from_data({"mask": "0,0: 1; 1,0: w", "dilation": "quincunx"})
    assert [p.name for p in a.params] == ["w"]


@pytest.mark.parametrize("data,match", [
    ({"symbol": "1+z1", "mask": "0,0:1"}, "exactly one"),
    ({"symbol": "1+z1", "extra": 1}, "unknown key"),
    ({"mask": [[0, 0, "1"], [0, 0, "2"]]}, "twice"),
    ({"mask": [[0, 0, 0.5]]}, "integer"),
    ([1, 2], "table"),
])
def test_mask_file_errors(data, match):
    with pytest.raises(AnalysisError, match=match):
        mask_from_data(data)


def test_cli_file(tmp_path, capsys):
    f = tmp_path / "hat.toml"
    f.write_text('mask = "0,0:1; 1,0:1/2; -1,0:1/2; 0,1:1/2; 0,-1:1/2; 1,1:1/4; -1,-1:1/4; 1,-1:1/4; -1,1:1/4"\n',
                 encoding="utf-8")
    assert main(["surface", "--file", str(f), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["sum_rules"] == 2 and doc["holder"]["value"] == "1"
    assert main(["surface", "--file", str(f), "--dilation", "quincunx"]) == 2


def test_cli_c_set_of_a_closed_run(capsys):
    """Both grid points C^0 and one box between them: the C^0 set [0, 1/2] is certified, nothing undecided."""
    assert main(["surface", "--symbol", HAT, "--C", "0", "--within=0,1/2", "--grid-cells", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["status"] == "certified" and doc["gaps"] == [] and doc["not_Cl"] == []
    assert doc["certified"] == [{"from": "0", "to": "1/2", "from_open": False, "to_open": False}]
    assert [s["Cl"] for s in doc["samples"]] == [True, True]


def test_the_stretch_between_an_exact_end_and_a_counterexample_is_proven_not_c0():
    """A perturbed tensor hat family whose eigenvalue t + 1/4 of T_0 is simple: [3/4, 1] is proven not C^0 (the
    sign of det(T_0(t) - I) between its real roots) and the C^0 set is certified on both sides; the same proof
    refuses an interval that contains C^0 points."""
    from analysis.bivariate.ranges import _prove_not_cl, parametric_family
    from analysis.jsr._work import Work

    g = BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2) + t*(1-z1**2)*(1-z2**2)/z1")
    r = ck_set(g, 0, within=(0, 1), grid=2, budget=200_000, point_budget=5000, box_budget=5000, approach=1,
               strip_budget=0, end_budget=0)
    (st,) = r.witness["not_Cl_proven"]
    assert (st["from"], st["to"]) == (sp.Rational(3, 4), 1) and "T_0" in st["how"]
    assert r.witness["between_counterexamples"] == []
    # (the strip next to 3/4 on the C^0 side is left open here: no end-strip budget)
    assert r.status == INCONCLUSIVE and r.value["gaps"]
    F = parametric_family(g, 1)
    t = g.params[0]
    assert _prove_not_cl(F, g, t, 0, 1, sp.Rational(1, 2), 1, [(0,)], 5000, Work(100_000)) is None
    assert _prove_not_cl(F, g, t, 0, 1, sp.Rational(7, 8), 1, [(0,)], 5000, Work(100_000)) is not None
