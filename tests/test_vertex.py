"""Extraordinary vertices: local matrices, Fourier blocks, certified eigen-structure, curvature behaviour,
the ``subdiv vertex`` command.

Literature values (each with its source) are checks of the computation, never inputs to it:

* Loop: subdominant eigenvalue 3/8 + cos(2 pi/n)/4 (Loop 1987; Peters–Reif, Subdivision Surfaces, 2008,
  ch. 6); Catmull–Clark: (c + 5 + sqrt((c + 9)(c + 1)))/16, c = cos(2 pi/n) (Stam 1998; Peters–Reif 2008);
  Doo–Sabin: 1/2 and 1/4 on the n-gon (Doo–Sabin 1978).
* Curvature — UNVERIFIED literature checks, written from memory of Karčiauskas–Peters–Reif, Shape
  characterization of subdivision surfaces — case studies, CAGD 21 (2004) and Peters–Reif 2008, ch. 7;
  a search of the available references did not confirm them; re-check against the papers' tables: Catmull–Clark has mu > lambda^2 (unbounded curvature) for
  n >= 5 and a flat spot (mu < lambda^2) at n = 3; Loop has mu > lambda^2 for n >= 7 (the block-2
  eigenvalue 3/8 + cos(4 pi/n)/4) and at n = 3 (the 2-ring eigenvalue 1/8 > 1/16 = lambda^2), while Loop's
  beta_n makes the block-0 eigenvalue equal lambda^2 (bounded curvature at n = 4..6; 6 is regular).
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.algebra.reader import InputError
from analysis.result import AnalysisError
from analysis.vertex.blocks import block_charpoly, c, fourier_block, lam, local_matrix
from analysis.vertex.rules import scheme_rules, user_rules
from analysis.vertex.spectrum import analyse
from analysis.vertex.valence import closed_form_lambda, parse_valences, valence_entry


def _block_product(rules, n):
    out = sp.S.One
    for k in range(n):
        P = block_charpoly(fourier_block(rules, k, n))
        out *= P.subs(c, sp.cos(2 * sp.pi * k / n))
    return sp.expand(out)


@pytest.mark.parametrize("name, ring, n", [("catmull-clark", 1, 4), ("catmull-clark", 1, 6),
                                           ("loop-warren", 2, 4), ("doo-sabin", 1, 6)],
                         ids=["cc-1ring-4", "cc-1ring-6", "loop-warren-2ring-4", "doo-sabin-6"])
def test_fourier_blocks_factor_the_full_local_matrix(name, ring, n):
    """det(lam I - S) of the full matrix = product of the blocks' polynomials (exact, rational cosines)."""
    rules = scheme_rules(name, ring, n)
    S = local_matrix(rules, n)
    assert S.shape[0] == len(rules.points) * n + (1 if rules.centre else 0)
    assert all(sum(S.row(i)) == 1 for i in range(S.rows))           # affine invariance of every rule
    assert sp.expand(S.charpoly(lam).as_expr()) == _block_product(rules, n)


def test_subdominant_closed_forms_match_the_literature():
    loop = closed_form_lambda(scheme_rules("loop", ring=1))["expr"]
    assert sp.expand(loop - (sp.Rational(3, 8) + c / 4)) == 0                       # Loop 1987
    cc = closed_form_lambda(scheme_rules("catmull-clark", ring=1))["expr"]
    stam = (c + 5 + sp.sqrt((c + 9) * (c + 1))) / 16                                # Stam 1998
    assert sp.simplify(cc - stam) == 0
    assert closed_form_lambda(scheme_rules("doo-sabin"))["expr"] == sp.Rational(1, 2)


@pytest.mark.parametrize("n", [3, 4, 5, 7, 8, 12])
def test_loop_eigen_conditions_certified(n):
    a = analyse(scheme_rules("loop", ring=2, n=n), n)
    assert a.reif_ok and a.reif_status == "certified"
    assert a.separation > 0
    assert sp.simplify(a.lam_exact - (sp.Rational(3, 8) + sp.cos(2 * sp.pi / n) / 4)) == 0


# (scheme, n): mu against lambda^2, as we recall the literature (module docstring: unverified)
CURVATURE = {("loop", 3): ">", ("loop", 4): "=", ("loop", 5): "=", ("loop", 6): "=", ("loop", 7): ">",
             ("loop", 10): ">", ("catmull-clark", 3): "<", ("catmull-clark", 4): "=",
             ("catmull-clark", 5): ">", ("catmull-clark", 6): ">", ("catmull-clark", 7): ">"}


@pytest.mark.parametrize("key", sorted(CURVATURE), ids=[f"{s}-{n}" for s, n in sorted(CURVATURE)])
def test_curvature_behaviour_matches_the_literature(key):
    name, n = key
    a = analyse(scheme_rules(name, ring=2, n=n), n)
    assert a.reif_ok
    verdict = {"<": "zero", "=": "bounded", ">": "unbounded"}[CURVATURE[key]]
    assert (a.mu_vs_lam2, a.curvature, a.curvature_status) == (CURVATURE[key], verdict, "certified")


def test_doo_sabin_curvature_is_not_claimed():
    """mu = lambda^2 = 1/4 at every valence, but the biquadratic regular part is only C^1."""
    e = valence_entry(scheme_rules("doo-sabin"), 5)
    assert e["curvature"]["value"] == "not applicable" and e["curvature"]["status"] == "inconclusive"
    assert e["curvature"]["witness"]["mu_vs_lambda2"] == "="


def test_catmull_clark_subsubdominant_is_block_2_from_valence_5():
    a = analyse(scheme_rules("catmull-clark", ring=2), 8)
    assert a.mu.k == 2 and a.mu.ball.real.contains(0.5)        # mu(8) = lambda(4) = 1/2 (block 2: cos(4 pi/8) = 0)


def test_characteristic_map_is_the_identity_at_the_regular_valence():
    """n = 4: the eigenvector is the lattice itself, the Jacobian of every segment patch is 1/4."""
    from flint import acb, arb

    from analysis.vertex.charmap import SEGMENT, _jacobian_bernstein, _Net, eigenvector

    rules = scheme_rules("catmull-clark", ring=2)
    v = eigenvector(rules, 4, arb(1) / 2)
    assert all(x.overlaps(acb(z.real, z.imag)) and x.rad() < 1e-12
               for x, z in zip(v, [1, 1 + 1j, 2, 2 + 1j, 2 + 2j, 1 + 2j]))
    net = _Net(rules, 4, v, arb(1) / 2)
    for a, b in SEGMENT:
        assert all(x.contains(arb(1) / 4) and x.rad() < 1e-12 for row in _jacobian_bernstein(net.bezier(a, b))
                   for x in row)


@pytest.mark.parametrize("n", [3, 5, 9])
def test_catmull_clark_characteristic_map_certified(n):
    from analysis.vertex.charmap import characteristic_map

    cc = scheme_rules("catmull-clark", ring=2)
    r = characteristic_map(cc, n, analyse(cc, n).lam.ball.real)
    assert (r["status"], r["regular"], r["jacobian_sign"], r["winding_number"]) == ("certified", True, 1, 1)


def test_the_other_eigenvector_of_block_1_is_refuted():
    """The second root of block 1's quadratic gives a regular map whose boundary winds 1 - n times."""
    from analysis.vertex.charmap import characteristic_map

    rules = scheme_rules("catmull-clark", ring=2)
    a = analyse(rules, 5)
    other = next(e for e in a.eigenvalues if e.k == 1 and e.factor == a.lam.factor and e is not a.lam)
    r = characteristic_map(rules, 5, other.ball.real)
    assert (r["status"], r["regular"], r["winding_number"]) == ("refuted", True, -4)


def test_warren_beta_changes_block_0_not_lambda():
    a = analyse(scheme_rules("loop-warren", ring=2, n=5), 5)
    b = analyse(scheme_rules("loop", ring=2, n=5), 5)
    assert a.lam_exact == b.lam_exact
    assert (a.mu_vs_lam2, b.mu_vs_lam2) == (">", "=")       # Warren's 1/4 exceeds lambda(5)^2 = 0.2045...


def test_a_bad_centre_weight_fails_reif_certified():
    """beta = 1/n leaves the centre nothing: block 0 has -3/8, larger in modulus than lambda(3) = 1/4."""
    rules = user_rules("triangle", "1/n", ring=1)
    a = analyse(rules, 3)
    assert a.reif_ok is False and a.reif_status == "certified"
    assert "block 0" in a.reif_reason


def test_user_rules_reproduce_loop_with_warren_weights():
    mine = analyse(user_rules("triangle", "3/(8*n)", ring=2), 7)
    ref = analyse(scheme_rules("loop-warren", ring=2, n=7), 7)
    assert mine.lam.factor == ref.lam.factor and mine.mu_vs_lam2 == ref.mu_vs_lam2


def test_user_edge_rule_enters_the_blocks_by_frequency():
    """W(j) = (a + b cos(2 pi j/n))/n contributes a to block 0 and b/2 to blocks 1 and n-1."""
    rules = user_rules("triangle", "3/(8*n)", "1/4; (3/4 + 1/2*cos(2*pi*j/n))/n", ring=1)
    assert fourier_block(rules, 0, 7)[1, 1] == sp.Rational(3, 4)
    assert fourier_block(rules, 1, 7)[0, 0] == sp.Rational(1, 4)
    assert fourier_block(rules, 3, 7)[0, 0] == 0


@pytest.mark.parametrize("text, needle", [("__import__('os')", "not allowed"), ("(1/4 + sin(2*pi*j/n))/n", "j may"),
                                          ("cos(pi*j/n)/n", "integer l"), ("k/n", "unknown name")],
                         ids=["code", "sin", "half-frequency", "unknown-name"])
def test_user_weights_are_read_as_data(text, needle):
    with pytest.raises((InputError, AnalysisError), match=needle):
        user_rules("triangle", "3/(8*n)", f"3/8; {text}")


def test_valence_ranges_parse_and_refuse():
    assert parse_valences("3..5") == [3, 4, 5]
    for bad, needle in (("2..5", "must lie in 3..200"), ("3..1000", "must lie in 3..200"), ("3,1000", "3..200"),
                        ("x", "takes N, LO..HI"), ("5..3", "is empty")):
        with pytest.raises(AnalysisError, match=needle):
            parse_valences(bad)


def test_c1_is_certified_only_with_the_characteristic_map():
    e = valence_entry(scheme_rules("catmull-clark", ring=2), 5, closed_form_lambda(scheme_rules("catmull-clark")))
    assert e["reif"]["status"] == "certified" and e["lambda"]["witness"]["closed_form_checked"]
    assert sp.Rational(e["lambda"]["lower"]) < sp.Rational(e["lambda"]["upper"])
    assert e["c1"]["status"] == "certified" and e["characteristic_map"]["value"] is True
    for rules in (scheme_rules("loop", ring=1, n=5), scheme_rules("catmull-clark", ring=1)):
        e = valence_entry(rules, 5)
        assert e["reif"]["status"] == "certified" and "characteristic_map" not in e
        assert e["c1"]["status"] == "inconclusive" and e["c1"]["value"] is None
        assert "characteristic map not checked" in e["c1"]["witness"]["verdict"]


def test_loop_patch_bezier_form_has_linear_precision():
    """Control points sampled from x and y (lattice coordinates) give Bézier ordinates j/4 and k/4: the box
    spline reproduces linear functions, an identity the subdivision equations did not impose."""
    from analysis.vertex.boxspline import BEZIER_INDEX, NET, loop_bezier_matrix

    G = loop_bezier_matrix()
    xs = G * sp.Matrix([p[0] for p in NET])
    ys = G * sp.Matrix([p[1] for p in NET])
    assert list(xs) == [sp.Rational(j, 4) for _, j, _ in BEZIER_INDEX]
    assert list(ys) == [sp.Rational(k, 4) for _, _, k in BEZIER_INDEX]


def test_doo_sabin_characteristic_map_is_affine_at_the_regular_valence_and_certified_at_3():
    from flint import arb

    from analysis.vertex.charmap import SEGMENT, _DualNet, _jacobian_bernstein, characteristic_map, eigenvector

    rules = scheme_rules("doo-sabin")
    net = _DualNet(rules, 4, eigenvector(rules, 4, arb(1) / 2), arb(1) / 2)
    for a, b in SEGMENT:
        assert all(x.overlaps(arb(1) / 2) and x.rad() < 1e-12 for row in _jacobian_bernstein(net.bezier_dual(a, b))
                   for x in row)
    r = characteristic_map(rules, 3, analyse(rules, 3).lam.ball.real)
    assert (r["status"], r["regular"], r["winding_number"]) == ("certified", True, 1)


@pytest.mark.parametrize("n", [3, 7])
def test_loop_characteristic_map_certified(n):
    from analysis.vertex.charmap import characteristic_map

    loop = scheme_rules("loop", ring=2, n=n)
    r = characteristic_map(loop, n, analyse(loop, n).lam.ball.real)
    assert (r["status"], r["regular"], r["winding_number"]) == ("certified", True, 1)


def test_loop_characteristic_map_is_affine_at_the_regular_valence():
    from flint import arb

    from analysis.vertex.boxspline import SUBTRIANGLES
    from analysis.vertex.charmap import _tri_jacobian, _TriNet, eigenvector

    rules = scheme_rules("loop", ring=2, n=6)
    net = _TriNet(rules, 6, eigenvector(rules, 6, arb(1) / 2), arb(1) / 2)
    area = arb(3).sqrt() / 8                      # |det| of the level-1 edge vectors (1/2, 0), (1/4, sqrt(3)/4)
    for st in SUBTRIANGLES[1:]:
        assert all(x.overlaps(area) and x.rad() < 1e-12 for x in _tri_jacobian(net.bezier_tri(*st)))


def test_cli_vertex_json_and_errors(capsys):
    from analysis.cli.main import main

    assert main(["vertex", "--scheme", "loop", "--valence", "5..6", "--ring", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert [e["n"] for e in doc["valences"]] == [5, 6]
    assert doc["closed_form"]["lambda"] == "c/4 + 3/8"
    assert main(["vertex", "--scheme", "lop", "--valence", "5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("subdiv: error: unknown scheme 'lop'")
    assert main(["vertex", "--scheme", "loop", "--valence", "2", "--json"]) == 2
    assert json.loads(capsys.readouterr().out)["error"]["message"].startswith("valences must lie")


def _doc_examples():
    import re
    import shlex
    from pathlib import Path

    text = (Path(__file__).resolve().parent.parent / "docs" / "vertices.md").read_text(encoding="utf-8")
    out = []
    for block in re.findall(r"```console\n(.*?)```", text, flags=re.S):
        cmd, lines = None, []
        for line in block.splitlines():
            if line.startswith("$ subdiv "):
                if cmd:
                    out.append((cmd, "\n".join(lines)))
                cmd, lines = shlex.split(line[2:])[1:], []
            else:
                lines.append(line)
        out.append((cmd, "\n".join(lines)))
    # examples whose output the page elides with "..." (or that write a file) are run by
    # tests/test_docs_examples.py, in a temporary folder, with its "..." matching
    return [(a, e) for a, e in out if "..." not in e.splitlines()]


DOC_EXAMPLES = _doc_examples()


@pytest.mark.parametrize("argv, expected", DOC_EXAMPLES, ids=[" ".join(a)[:40] for a, _ in DOC_EXAMPLES])
def test_docs_examples_print_what_the_docs_show(argv, expected, capsys):
    from analysis.cli.main import main

    code = main(argv)
    cap = capsys.readouterr()
    assert (cap.out + cap.err).rstrip("\n") == expected
    assert code == (2 if expected.startswith("subdiv: error") else 0)


def test_block_0_is_evaluated_at_w_1_for_any_centre_weights():
    """Regression: block 0 was a polynomial in w before w = 1 was set, and a centre rule that made it
    asymmetric in w was refused as 'not mirror-symmetric'."""
    rules = user_rules("quad", "1/n**2, 1/n**2", ring=1)
    assert not fourier_block(rules, 0, 3).has(sp.Symbol("w"))
    S = local_matrix(rules, 4)
    assert sp.expand(S.charpoly(lam).as_expr()) == _block_product(rules, 4)
    assert analyse(rules, 3).reif_ok


def test_cli_vertex_figure(tmp_path, capsys):
    from analysis.cli.main import main

    path = tmp_path / "spectrum.png"
    assert main(["vertex", "--scheme", "loop", "--valence", "4..5", "--ring", "1", "--figure", str(path)]) == 0
    assert path.stat().st_size > 0 and capsys.readouterr().out.rstrip().endswith(f"figure: {path}")
    assert main(["vertex", "--scheme", "loop", "--valence", "4", "--figure", str(tmp_path / "x.txt")]) == 2
    assert "not an image format" in capsys.readouterr().err


def test_exact_lambda_needs_its_ball_not_a_float_match():
    """A root is the exact value only if the ball contains it (rational) or its Arb value meets this
    isolating ball and no other; a float within 1e-12 of the ball's midpoint is not enough."""
    from flint import acb, arb

    from analysis.vertex.spectrum import _exact_root

    quarter = sp.Poly(lam - sp.Rational(1, 4), lam)
    near = acb(arb(0.25 + 2.0 ** -50, 2.0 ** -60))                 # misses 1/4 by ~1e-15
    assert _exact_root(quarter, near, 4, 1, [near]) is None
    exact = acb(arb(0.25, 2.0 ** -60))
    assert _exact_root(quarter, exact, 4, 1, [exact]) == sp.Rational(1, 4)
    root2 = sp.Poly(lam ** 2 - 2, lam)
    miss, other = acb(arb(2).sqrt() + 2.0 ** -50), acb(-arb(2).sqrt())
    assert _exact_root(root2, miss, 4, 1, [miss, other]) is None
    hit = acb(arb(2).sqrt())
    assert _exact_root(root2, hit, 4, 1, [hit, other]) == sp.sqrt(2)


@pytest.mark.parametrize("n, value", [(3, (9 + sp.sqrt(17)) / 32), (6, (11 + sp.sqrt(57)) / 32)])
def test_catmull_clark_exact_lambda_is_certified_where_the_double_misses_the_ball(n, value):
    a = analyse(scheme_rules("catmull-clark", ring=2), n)
    assert sp.simplify(a.lam_exact - value) == 0


@pytest.fixture
def uncached_analyse():
    """``analyse`` recomputed while a test replaces its internals (its per-process cache emptied before, and
    after, so that no later test sees a result of the replaced code)."""
    from analysis.vertex.spectrum import _analyse

    _analyse.cache_clear()
    yield
    _analyse.cache_clear()


def test_a_jordan_block_at_lambda_squared_is_not_bounded_curvature(monkeypatch, uncached_analyse):
    """Catmull–Clark n = 4: lambda^2 = 1/4 is double in block 2 and semisimple (bounded curvature). Block 2
    replaced by its companion matrix (same characteristic polynomial, so the same spectrum, but one Jordan
    block per eigenvalue) must not be called bounded."""
    import analysis.vertex.spectrum as spec

    rules = scheme_rules("catmull-clark", ring=2)
    a = analyse(rules, 4)
    assert (a.curvature, a.curvature_status) == ("bounded", "certified")
    assert any("semisimple in block 2" in x for x in a.notes)
    orig = spec.fourier_block

    def companion(r, k, n):
        B = orig(r, k, n)
        if (k, n) != (2, 4):
            return B
        co = sp.Poly(B.charpoly(lam).as_expr(), lam).all_coeffs()[::-1]       # monic, constant first
        m = B.rows
        C = sp.zeros(m, m)
        for i in range(1, m):
            C[i, i - 1] = 1
        for i in range(m):
            C[i, m - 1] = -co[i]
        return C

    import analysis.vertex.exact_blocks as exact_blocks

    monkeypatch.setattr(spec, "fourier_block", companion)
    monkeypatch.setattr(exact_blocks, "fourier_block", companion)          # the exact eigenspaces use it too
    spec._analyse.cache_clear()
    b = analyse(rules, 4)
    assert b.mu_vs_lam2 == "=" and (b.curvature, b.curvature_status) == ("inconclusive", "inconclusive")
    assert "not semisimple in block 2" in b.curvature_reason


def test_curvature_needs_an_eigenfunction_nonzero_on_the_ring(monkeypatch, uncached_analyse):
    """Loop n = 3: mu = 1/8 > lambda^2 = 1/16 (a 2-ring eigenvalue); its eigenfunctions in blocks 0 and 1
    are certified nonzero on the ring. If they vanished there, mu would not decide the curvature."""
    from flint import acb

    import analysis.vertex.spectrum as spec
    from analysis.vertex.charmap import eigenvector, segment_ordinates

    rules = scheme_rules("loop", ring=2, n=3)
    a = analyse(rules, 3)
    assert (a.curvature, a.curvature_status) == ("unbounded", "certified")
    assert a.mu.ball.overlaps(acb(1) / 8)
    eighth = [e for e in a.eigenvalues if e.ball.overlaps(acb(1) / 8)]
    assert sorted(e.k for e in eighth) == [0, 1]
    for e in eighth:
        ords = segment_ordinates(rules, 3, eigenvector(rules, 3, e.ball, e.k), e.ball, e.k)
        assert any(not x.contains(0) for x in ords)
    zero = [acb(0)] * len(eigenvector(rules, 3, a.mu.ball, a.mu.k))
    assert all(x.contains(0) for x in segment_ordinates(rules, 3, zero, a.mu.ball, a.mu.k))
    monkeypatch.setattr(spec, "_arb_eigenvectors", lambda r, n, e: [[acb(0)] * len(zero)])
    spec._analyse.cache_clear()
    b = analyse(rules, 3)
    assert b.mu_vs_lam2 == ">" and b.curvature == "inconclusive"
    assert "certified nonzero" in b.curvature_reason


def test_one_ring_rules_do_not_decide_bounded_or_unbounded_curvature():
    """Loop's 1-ring misses the 2-ring eigenvalue 1/8 at n = 3 (mu = 1/16 = lambda^2 there): without the
    eigenfunctions on the ring no bounded/unbounded verdict is given."""
    a = analyse(scheme_rules("loop", ring=1), 3)
    assert a.mu_vs_lam2 == "=" and (a.curvature, a.curvature_status) == ("inconclusive", "inconclusive")
    assert "2-ring" in a.curvature_reason


def test_c1_wording_generic_data_and_no_refutation_from_a_non_injective_map():
    from analysis.vertex.valence import c1_verdict

    a = analyse(scheme_rules("catmull-clark", ring=2), 5)
    status, text = c1_verdict(a, {"status": "certified", "winding_number": 1, "precision_bits": 128})
    assert status == "certified" and "generic initial data" in text and "Reif 1995" in text
    status, text = c1_verdict(a, {"status": "refuted", "winding_number": -4, "precision_bits": 128})
    assert status == "inconclusive" and "not injective" in text and "sufficient condition fails" in text
