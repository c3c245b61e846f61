"""The butterfly family and Kobbelt's sqrt(3) at an extraordinary vertex: rules, certified eigen-structure,
honest C^1 verdicts.

The rules are checked against an independent construction (the schemes applied by mesh adjacency on a
triangulated disk round the vertex, floats) before the certified spectrum is compared with the literature.
Literature statements used as checks, each with its source:

* Modified butterfly: subdominant eigenvalue 1/2 at every valence, the weights designed for that (Zorin,
  Schröder, Sweldens, SIGGRAPH 1996); n = 3, 4 weights as in OpenMesh's ``ModifiedButterFlyT.hh``.
* Original butterfly: not C^1 at valence 3 and at valences > 7 (Zorin–Schröder–Sweldens 1996 and Zorin's
  thesis 1998, as we recall them; the text was not available to check): the computation finds Reif's
  eigen-conditions certified at n = 4..7 and certified to fail at n = 3 (lambda = 1/4 also an eigenvalue of
  block 0) and n >= 8 (block 2 exceeds block 1).
* sqrt(3), two steps: lambda = (2 + 2 cos(2 pi/n))/9 = (2 cos(pi/n)/3)^2 and 2/3 - alpha_n = (2 + 2c)/9, so
  block 0's second eigenvalue (2/3 - alpha_n)^2 is lambda^2 (computed here; alpha_n from Kobbelt, SIGGRAPH 2000).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import sympy as sp

from analysis.result import AnalysisError
from analysis.vertex.blocks import c, local_matrix
from analysis.vertex.rules import butterfly_stencil, scheme_rules, sqrt3_rules
from analysis.vertex.spectrum import analyse
from analysis.vertex.valence import closed_form_lambda, valence_entry


# --------------------------------------------------------------------------------------------------
# an independent construction: the schemes on a triangulated disk, by mesh adjacency

def _canon(j, x, y, n):
    """The vertex (x, y) of sector j's chart (x, y >= 0), with (0, y) of sector j = (y, 0) of sector j + 1."""
    if x == 0 and y == 0:
        return ("centre",)
    if x == 0:
        j, x, y = j + 1, y, 0
    return (j % n, x, y)


def _mesh_matrix(n, R, special=None, w=1 / 16):
    """The butterfly's local matrix on the R-ring, built from the faces of a disk (no lattice charts):
    opposite vertices and wings are the third vertices of the faces on the edges."""
    third = {}
    for j in range(n):
        for x in range(R + 4):
            for y in range(R + 4 - x):
                tris = []
                if x + y + 1 <= R + 3:
                    tris.append(((x, y), (x + 1, y), (x, y + 1)))
                if x + y + 2 <= R + 3:
                    tris.append(((x + 1, y), (x + 1, y + 1), (x, y + 1)))
                for t in tris:
                    f = [_canon(j, a, b, n) for a, b in t]
                    for i in range(3):
                        third.setdefault(frozenset((f[i], f[(i + 1) % 3])), []).append(f[(i + 2) % 3])

    def across(a, b, not_c):
        return next(v for v in third[frozenset((a, b))] if v != not_c)

    old = sorted({_canon(j, x, y, n) for j in range(n) for x in range(R + 1) for y in range(R + 1 - x)}, key=str)
    idx = {v: i for i, v in enumerate(old)}
    rows = {}
    for j in range(n):
        for X in range(R + 1):
            for Y in range(R + 1 - X):
                key = _canon(j, X, Y, n)
                row = np.zeros(len(old))
                if X % 2 == 0 and Y % 2 == 0:
                    row[idx[_canon(j, X // 2, Y // 2, n)]] = 1
                else:
                    dx, dy = next(d for d in ((1, 0), (0, 1), (-1, 1)) if (X - d[0]) % 2 == 0 and (Y - d[1]) % 2 == 0)
                    a = _canon(j, (X - dx) // 2, (Y - dy) // 2, n)
                    b = _canon(j, (X + dx) // 2, (Y + dy) // 2, n)
                    c1, c2 = third[frozenset((a, b))]
                    stencil = special(a, b) if special and ("centre",) in (a, b) else None
                    if stencil is None:
                        stencil = ([(0.5, a), (0.5, b), (2 * w, c1), (2 * w, c2)]
                                   + [(-w, across(p, q, r)) for p, q, r in ((a, c1, b), (b, c1, a), (a, c2, b), (b, c2, a))])
                    for wt, v in stencil:
                        row[idx[v]] += wt
                rows[key] = row
    return np.array([rows[v] for v in old]), old


def _modified_special(n):
    s = [float(sp.N(sp.Rational(1, 4) + sp.cos(2 * sp.pi * j / n) + sp.cos(4 * sp.pi * j / n) / 2)) / n
         for j in range(n)]
    s = {3: [5 / 12, -1 / 12, -1 / 12], 4: [3 / 8, 0, -1 / 8, 0]}.get(n, s)

    def special(a, b):
        e = b if a == ("centre",) else a
        return [(0.75, ("centre",))] + [(s[(l_ - e[0]) % n], (l_, 1, 0)) for l_ in range(n)]
    return special


def _sorted_moduli(values):
    return sorted((abs(complex(v)) for v in values), reverse=True)


@pytest.mark.parametrize("name, n", [("butterfly", 3), ("butterfly", 5), ("butterfly", 8),
                                     ("modified-butterfly", 3), ("modified-butterfly", 4), ("modified-butterfly", 7)],
                         ids=["bf-3", "bf-5", "bf-8", "mbf-3", "mbf-4", "mbf-7"])
def test_rules_match_the_scheme_applied_on_a_mesh(name, n):
    """The lattice-built local matrix (3-ring) equals the one built from mesh adjacency, entry by entry up to
    the order of the points; and the certified spectrum encloses the float eigenvalues of the mesh matrix."""
    rules = scheme_rules(name, 3, n)
    S = np.array(local_matrix(rules, n).evalf(), dtype=float)
    M, order = _mesh_matrix(n, 3, _modified_special(n) if name == "modified-butterfly" else None)
    pos = {("centre",): 0}
    for j in range(n):
        for p, (x, y) in enumerate(rules.coords):
            pos[(j, x, y)] = 1 + j * len(rules.coords) + p
    perm = [pos[v] for v in order]
    assert np.allclose(S[np.ix_(perm, perm)], M, atol=1e-14)
    a = analyse(rules, n)
    certified = []
    for e in a.eigenvalues:
        copies = 1 if (e.k == 0 or 2 * e.k == n) else 2
        certified += [abs(complex(e.ball.mid()))] * (e.mult * copies)
    assert len(certified) == M.shape[0]
    # a multiple eigenvalue with a Jordan block splits by ~ eps^(1/size) in floats
    assert np.allclose(sorted(certified, reverse=True), _sorted_moduli(np.linalg.eigvals(M)), atol=1e-4)


def test_butterfly_stencil_is_the_regular_rule():
    """Weights 1/2, 1/2, 2w, 2w, -w x 4 summing to 1, mirror-symmetric about the edge."""
    st = butterfly_stencil(1, 2, sp.Rational(1, 16))
    assert sum(w for w, _ in st) == 1 and len(st) == 8
    assert sorted(w for w, _ in st) == [-sp.Rational(1, 16)] * 4 + [sp.Rational(1, 8)] * 2 + [sp.Rational(1, 2)] * 2


# --------------------------------------------------------------------------------------------------
# certified verdicts against the literature

@pytest.mark.parametrize("n, holds", [(3, False), (4, True), (5, True), (6, True), (7, True), (8, False), (11, False)])
def test_original_butterfly_eigen_conditions(n, holds):
    a = analyse(scheme_rules("butterfly", 3, n), n)
    assert a.reif_status == "certified" and a.reif_ok is holds
    if n == 3:
        assert a.lam_exact == sp.Rational(1, 4) and "block 0 equals lambda exactly" in a.reif_reason
    if n >= 8:
        assert "an eigenvalue of block 2" in a.reif_reason and "exceeds block 1" in a.reif_reason


@pytest.mark.parametrize("n", [3, 4, 5, 9, 16])
def test_modified_butterfly_lambda_is_one_half(n):
    a = analyse(scheme_rules("modified-butterfly", 3, n), n)
    assert a.reif_ok and a.reif_status == "certified"
    assert a.lam_exact == sp.Rational(1, 2) and a.separation > 0


def test_modified_butterfly_closed_form_starts_where_the_formula_does():
    closed = closed_form_lambda(scheme_rules("modified-butterfly", 3))
    assert closed["expr"] == sp.Rational(1, 2) and closed["valid_from"] == 5


def test_c1_without_the_cell_test_is_inconclusive_and_the_butterfly_at_9_is_refuted():
    e = valence_entry(scheme_rules("modified-butterfly", 3, 5), 5)
    assert e["c1"]["status"] == "inconclusive" and e["c1"]["value"] is None
    assert "not piecewise polynomial" in e["c1"]["witness"]["verdict"]
    assert "characteristic_map" not in e
    assert e["curvature"]["value"] == "not applicable"
    bad = valence_entry(scheme_rules("butterfly", 3, 9), 9)
    assert bad["reif"]["status"] == "certified" and bad["reif"]["value"] is False
    # an eigen-condition fails, and "not C^1" is certified by a theorem whose hypotheses are all checked
    assert bad["c1"]["status"] == "refuted" and bad["c1"]["value"] is False
    assert "winds 2 times" in bad["c1"]["witness"]["verdict"] and bad["not_c1"]["witness"]["block"] == 2


def test_sampled_characteristic_net_is_numerical_evidence_only():
    """The net sampled on 16 rings: the regular lattice at n = 6 (all discrete Jacobians equal), regular and
    winding once for the modified butterfly at n = 3; the block-1 eigenvector of another eigenvalue (1/8) is
    not regular. The result is 'numerical' and C^1 stays inconclusive."""
    from analysis.vertex.netmap import numerical_characteristic_map

    six = numerical_characteristic_map(scheme_rules("modified-butterfly", 3, 6), 6, 0.5)
    assert six["injective"] and abs(six["min_jacobian_ratio"] - 1) < 1e-9
    three = numerical_characteristic_map(scheme_rules("modified-butterfly", 3, 3), 3, 0.5)
    assert three["status"] == "numerical" and three["regular"] and three["winding_number"] == 1
    other = numerical_characteristic_map(scheme_rules("modified-butterfly", 3, 5), 5, 0.125)
    assert abs(other["eigenvalue_used"] - 0.125) < 1e-9 and not other["regular"] and not other["injective"]
    e = valence_entry(scheme_rules("modified-butterfly", 3, 7), 7)
    assert e["characteristic_map_numerical"]["status"] == "numerical" and e["characteristic_map_numerical"]["value"]
    assert e["c1"]["status"] == "inconclusive" and "not a proof" in e["c1"]["witness"]["numerical_evidence"]


def test_two_rings_and_three_rings_agree_on_the_leading_eigenvalues():
    """The 3-ring adds the outer block (eigenvalues 0 and -w) and nothing above it."""
    for n in (4, 8):
        a2, a3 = analyse(scheme_rules("butterfly", 2, n), n), analyse(scheme_rules("butterfly", 3, n), n)
        assert a2.lam.ball.overlaps(a3.lam.ball) and a2.reif_ok == a3.reif_ok
        extra = [e for e in a3.eigenvalues if not any(e.ball.overlaps(f.ball) for f in a2.eigenvalues)]
        assert all(abs(complex(e.ball.mid()) + 1 / 16) < 1e-12 for e in extra)


# --------------------------------------------------------------------------------------------------
# sqrt(3)

def test_sqrt3_two_steps_compose_the_one_step_rules():
    """Two one-step maps (relax + centroids; then the centroids of (p', f_(j-1), f_j)) give the rules."""
    for n in (3, 5, 8):
        cn = np.cos(2 * np.pi / n)
        a = (4 - 2 * cn) / 9
        M1 = np.zeros((n + 1, n + 1))
        M1[0, 0], M1[0, 1:] = 1 - a, a / n
        for j in range(n):                                   # f_j = (p + e_j + e_(j+1))/3
            M1[1 + j, 0] = 1 / 3
            M1[1 + j, 1 + j] += 1 / 3
            M1[1 + j, 1 + (j + 1) % n] += 1 / 3
        M2 = np.zeros((n + 1, n + 1))
        M2[0, 0], M2[0, 1:] = 1 - a, a / n
        for j in range(n):                                   # g_j = (p' + f_(j-1) + f_j)/3
            M2[1 + j, 0] = 1 / 3
            M2[1 + j, 1 + (j - 1) % n] += 1 / 3
            M2[1 + j, 1 + j] += 1 / 3
        S = np.array(local_matrix(sqrt3_rules(), n).evalf(), dtype=float)
        assert np.allclose(M2 @ M1, S, atol=1e-14)


@pytest.mark.parametrize("n", [3, 5, 7, 12])
def test_sqrt3_lambda_and_kobbelts_alpha(n):
    a = analyse(scheme_rules("sqrt3", 1, n), n, curvature=False)
    assert a.reif_ok and a.reif_status == "certified"
    lam = (2 + 2 * sp.cos(2 * sp.pi / n)) / 9
    assert abs(float(a.lam_exact) - float(lam)) < 1e-15
    block0 = [e for e in a.eigenvalues if e.k == 0 and not e.ball.real.contains(1)][0]
    assert block0.ball.overlaps(a.lam.ball ** 2)                           # (2/3 - alpha_n)^2 = lambda^2


def test_sqrt3_two_ring_composition():
    """The 2-ring rules of two steps: the 1-ring rows are the closed forms; at the regular valence they map the
    lattice positions to the positions of the level-2 lattice (linear precision, scale 1/3, no turn); the
    2-ring adds eigenvalues below lambda (at n = 3 one of 0.041 > 3 lambda^2 = 3/81)."""
    r1, r2 = scheme_rules("sqrt3", 1), scheme_rules("sqrt3", 2)
    for i in (0, 1):
        assert {t.source: t.weight for t in r2.rules[i]} == {t.source: t.weight for t in r1.rules[i]}
    S = np.array(local_matrix(r2, 6).evalf(), dtype=float)
    w6 = np.exp(1j * np.pi / 3)
    pos = np.array([0j] + [w6 ** j * (x + y * w6) for j in range(6) for x, y in r2.coords])
    assert np.allclose(S @ pos, pos / 3, atol=1e-14)
    a = analyse(r2, 3, curvature=False)
    assert a.reif_ok and a.lam_exact == sp.Rational(1, 9)
    others = [e for e in a.eigenvalues if e is not a.lam and not (e.k == 0 and e.ball.real.contains(1))]
    assert any(e.modulus > 3 / 81 for e in others)


def test_sqrt3_closed_form():
    assert sp.expand(closed_form_lambda(scheme_rules("sqrt3", 1))["expr"] - (2 + 2 * c) / 9) == 0


# --------------------------------------------------------------------------------------------------
# command line

def test_cli_butterfly_json_tension_and_errors(capsys):
    from analysis.cli.main import main

    assert main(["vertex", "--scheme", "butterfly", "--valence", "7..8", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["ring"] == 3 and [e["reif"]["value"] for e in doc["valences"]] == [True, False]
    assert main(["vertex", "--scheme", "butterfly", "--tension", "1/32", "--valence", "6", "--ring", "2",
                 "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert "w = 1/32" in doc["rules"] and doc["valences"][0]["lambda"]["value"] == "1/2"
    for argv, needle in ((["--scheme", "loop", "--tension", "1/16"], "butterfly schemes only"),
                         (["--scheme", "butterfly", "--tension", "sqrt(2)"], "rational number"),
                         (["--scheme", "sqrt3", "--ring", "3"], "give --ring 1 or 2"),
                         (["--lattice", "triangle", "--centre", "3/(8*n)", "--ring", "3"], "--ring must be 1 or 2")):
        assert main(["vertex", *argv, "--valence", "5"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and needle in err


def test_unknown_ring_for_butterfly_is_refused():
    with pytest.raises(AnalysisError, match="--ring 2 or 3"):
        scheme_rules("butterfly", 1)


# --------------------------------------------------------------------------------------------------
# tuning a free weight of the centre's rule

def test_tuning_loops_beta_gives_the_exact_interval():
    """Loop's block 0 has the eigenvalue 5/8 - n beta besides 1: the conditions hold iff |5/8 - n beta| < lambda
    = 3/8 + cos(2 pi/n)/4, i.e. beta in ((1 - c)/(4n), (1 + c/4)/n) (derived by hand from the 1-ring block)."""
    from analysis.vertex.tuning import tune_centre

    n = 5
    r = tune_centre("triangle", "b", "b", n, ring=1)
    held = [i for i in r["intervals"] if i["holds"]]
    assert r["status"] == "certified" and len(held) == 1
    cn = sp.cos(2 * sp.pi / n)
    assert sp.simplify(held[0]["lower"] - (1 - cn) / (4 * n)) == 0
    assert sp.simplify(held[0]["upper"] - (1 + cn / 4) / n) == 0
    beta = (sp.Rational(5, 8) - (sp.Rational(3, 8) + cn / 4) ** 2) / n              # Loop's beta_n inside
    assert held[0]["lower"] < beta < held[0]["upper"] and held[0]["lower"] < sp.Rational(3, 8 * n) < held[0]["upper"]


def test_tuning_decides_rational_endpoints_warren_at_three():
    """On the 2-ring at n = 3 the set is (1/8, 7/24), both ends failing exactly: Warren's 3/(8n) = 1/8 is the
    left end (an eigenvalue of block 0 equals lambda = 1/4), and 3/16 is inside."""
    from analysis.vertex.tuning import tune_centre

    r = tune_centre("triangle", "b", "b", 3, ring=2)
    held = [i for i in r["intervals"] if i["holds"]]
    assert [(i["lower"], i["upper"]) for i in held] == [(sp.Rational(1, 8), sp.Rational(7, 24))]
    assert [(p["value"], p["holds"]) for p in r["critical"]] == [(sp.Rational(1, 8), False), (sp.Rational(7, 24), False)]


def test_cli_tune(capsys):
    from analysis.cli.main import main

    assert main(["vertex", "--lattice", "quad", "--centre", "3/(2*n**2), f", "--tune", "f", "--valence", "3",
                 "--ring", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    v = doc["valences"][0]
    assert v["factors"] == ["12*f + 4*lam - 1"]
    assert [(i["lower"], i["upper"]) for i in v["intervals"] if i["holds"]] == [("-sqrt(17)/96 - 1/96",
                                                                                  "sqrt(17)/96 + 17/96")]
    for argv, needle in ((["--scheme", "loop", "--tune", "b"], "works on user rules"),
                         (["--lattice", "triangle", "--centre", "3/(8*n)", "--tune", "b"], "does not appear"),
                         (["--lattice", "triangle", "--centre", "n", "--tune", "n"], "takes a name")):
        assert main(["vertex", *argv, "--valence", "4"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and needle in err
