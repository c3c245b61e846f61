"""Extraordinary vertices: what is proven about the subdominant eigenvalue and what is not.

The subdominant eigenvalue is the largest modulus below 1 over all Fourier blocks, not block 1's leading
eigenvalue when another block dominates; exact ties with an algebraic lambda; "zero" curvature is not
read from the 1-ring; a complex lambda is printed as complex; a proven sign change of the Jacobian is said
as such; options that do not apply are refused.
"""

from __future__ import annotations

import json

import sympy as sp

from analysis.claims.kinds.vertex import Vertex
from analysis.vertex.rules import scheme_rules, user_rules
from analysis.vertex.spectrum import analyse

#: Loop's rules with the centre keeping weight 0 on its edge neighbours: at n = 3 block 0's eigenvalue 5/8
#: exceeds block 1's leading eigenvalue 3/8 + cos(2 pi/3)/4 = 1/4
CENTRE0 = {"lattice": "triangle", "centre": "0", "valence": "3", "property": "subdominant eigenvalue"}


def test_claim_compares_with_the_dominant_block_not_block_1():
    wrong = Vertex(dict(CENTRE0, value="3/8 + cos(2*pi/n)/4"), {}, "x").evaluate()
    assert wrong.label == "REFUTED" and "block 0" in wrong.summary
    right = Vertex(dict(CENTRE0, value="5/8"), {}, "x").evaluate()
    assert right.label == "CERTIFIED TRUE"


def test_json_says_which_eigenvalue_is_subdominant(capsys):
    from analysis.cli.main import main

    assert main(["vertex", "--lattice", "triangle", "--centre", "0", "--valence", "3", "--json"]) == 0
    e = json.loads(capsys.readouterr().out)["valences"][0]
    assert e["lambda"]["status"] == "inconclusive" and e["lambda"]["witness"]["subdominant"] is False
    assert e["subdominant"]["status"] == "certified" and e["subdominant"]["witness"]["block"] == 0
    assert e["subdominant"]["witness"]["float"] == 0.625


def test_zero_curvature_is_not_certified_from_the_1_ring():
    one = analyse(user_rules("triangle", "5/(8*n)", None, ring=1), 3)
    assert one.mu_vs_lam2 == "<" and one.curvature_status == "inconclusive" and "2-ring" in one.curvature_reason


def test_algebraic_lambda_tied_with_another_block_is_found_exactly():
    a = analyse(scheme_rules("butterfly", 3, 3, sp.Rational(1, 32)), 3, curvature=False)
    assert (a.reif_ok, a.reif_status) == (False, "certified") and "equals lambda exactly" in a.reif_reason
    assert a.checks["others < lambda in modulus"] is False


def test_common_root_over_the_cosine_field():
    from analysis.vertex.spectrum import _common_root

    a = analyse(scheme_rules("butterfly", 3, 5, sp.Rational(1, 32)), 5, curvature=False)
    other = next(e for e in a.eigenvalues if e.k == 0 and abs(float(e.ball.real.mid()) - 0.4268) < 1e-3)
    assert _common_root(a.lam, a.lam, 5, 1, a.eigenvalues, a.prec)
    assert not _common_root(other, a.lam, 5, 1, a.eigenvalues, a.prec)


def test_complex_lambda_is_printed_as_complex():
    from analysis.cli.vertex import _line

    entry = {"n": 3, "lambda": {"value": None, "witness": {"polynomial": "p", "float": 0.25, "float_imag": 0.25}},
             "curvature": {"value": "not applicable", "status": "inconclusive", "witness": {}},
             "reif": {"value": False, "status": "certified", "witness": {"reason": "r"}},
             "c1": {"status": "inconclusive", "witness": {"verdict": "v"}}}
    assert "~ 0.2500000000+0.2500000000i (complex)" in _line(entry)


def test_a_proven_sign_change_of_the_jacobian_is_said_as_such():
    from analysis.vertex.spectrum import VertexAnalysis
    from analysis.vertex.valence import c1_verdict

    a = VertexAnalysis(5, "user", [], None, None, None, reif_ok=True, reif_status="certified")
    cm = {"status": "inconclusive", "regular": False, "injective": None, "precision_bits": 256,
          "winding_number": None, "jacobian_sign_change": True}
    status, verdict = c1_verdict(a, cm, "triangle")
    assert status == "inconclusive" and "changes sign" in verdict and "bits" not in verdict


def test_doo_sabin_refuses_ring(capsys):
    from analysis.cli.main import main

    assert main(["vertex", "--scheme", "doo-sabin", "--ring", "1", "--valence", "3"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--ring does not apply to doo-sabin" in err
