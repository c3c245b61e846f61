"""Bivariate schemes with a dilation matrix: readers, exact algebra, certified Hölder exponents, catalogue
claims (transcription first: sum rules, reproduction, symmetry; then smoothness), and ``subdiv surface``.

The slower catalogue entries (Kobbelt's quad scheme ~30 s, sqrt 3 ~20 s of CPU) are checked here only by their
algebra; their certified exponents are measured in ``docs/surfaces.md``. The butterfly scheme at w = 1/16 (C^1, not
C^2, alpha <= 2 exactly) is checked through the documentation's ``--sweep`` example.
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.bivariate.algebra import box_factors, reproduction, sum_rules, symmetry_group
from analysis.bivariate.dilation import Dilation, parse_dilation
from analysis.bivariate.holder import holder_exponent, smoothness_verdicts
from analysis.bivariate.mask import Z1, Z2, BivariateMask
from analysis.bivariate.transition import invariant_support, restricted_transition, transition_matrices
from analysis.cli.main import main
from analysis.result import CERTIFIED, INCONCLUSIVE, AnalysisError
from schemes.surfaces import box_spline_mask, entries, from_stencils, get

# ----------------------------------------------------------------------------------------------
# dilations
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name,det,iso,n_dual", [("dyadic", 4, True, 4), ("quincunx", -2, True, 2),
                                                 ("sqrt3", 3, True, 3), ("triadic", 9, True, 9)])
def test_named_dilations(name, det, iso, n_dual):
    D = Dilation.named(name)
    assert D.det == det and D.isotropic is iso and len(D.dual_points) == n_dual == len(D.digits)
    assert len({D.coset(e) for e in D.digits}) == D.m and D.digits[0] == (0, 0)


def test_sqrt3_dilation_is_sqrt3_times_a_rotation_of_the_three_direction_grid():
    # M^T G M = 3 G for the Gram matrix G of e1, e2 drawn at 0 and 120 degrees
    M = sp.Matrix(Dilation.named("sqrt3").matrix)
    G = sp.Matrix([[1, sp.Rational(-1, 2)], [sp.Rational(-1, 2), 1]])
    assert M.T * G * M == 3 * G


@pytest.mark.parametrize("rows,iso", [([[2, 0], [0, 3]], False), ([[2, 1], [0, 2]], False), ([[1, -1], [1, 1]], True),
                                      ([[0, 2], [1, 0]], True)])
def test_isotropy(rows, iso):
    assert Dilation(rows).isotropic is iso


@pytest.mark.parametrize("rows", [[[1, 0], [0, 1]], [[2, 0], [0, 1]], [[1, 1], [0, 3]], [[2]], [[1, 2], [3]]])
def test_bad_dilations(rows):
    with pytest.raises(AnalysisError):
        Dilation(rows)


def test_parse_dilation():
    assert parse_dilation("1,1;1,-1") == Dilation.named("quincunx")
    with pytest.raises(AnalysisError, match="a,b;c,d"):
        parse_dilation("two")


# ----------------------------------------------------------------------------------------------
# masks
# ----------------------------------------------------------------------------------------------


def test_symbol_and_list_give_the_same_mask():
    a = BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)")
    b = BivariateMask.from_list("0,0:1; 1,0:1/2; -1,0:1/2; 0,1:1/2; 0,-1:1/2; 1,1:1/4; -1,-1:1/4; 1,-1:1/4; -1,1:1/4")
    assert a.coeffs == b.coeffs and a.total == 4


@pytest.mark.parametrize("text,match", [("(1+z1)/(1+z2)", "monomial"), ("__import__('os')", "symbol"),
                                        ("z1**2+", "symbol")])
def test_bad_symbols(text, match):
    with pytest.raises(AnalysisError, match=match):
        BivariateMask.from_symbol(text)


@pytest.mark.parametrize("text,match", [("0,0:1; 0,0:2", "twice"), ("0,0 1", "i,j:coef"), ("a,b:1", "two integers"),
                                        ("0,0:0", "zero"), ("99,0:1", "limited")])
def test_bad_lists(text, match):
    with pytest.raises(AnalysisError, match=match):
        BivariateMask.from_list(text)


def test_parameters_are_substituted_exactly():
    a = get("butterfly").mask(general=True)
    assert [p.name for p in a.params] == ["w"]
    assert a.at(w="1/16")[(1, 2)] == sp.Rational(1, 8) and a.at(w="1/16").params == ()
    with pytest.raises(AnalysisError, match="no parameter"):
        a.at(v=1)


# ----------------------------------------------------------------------------------------------
# algebra
# ----------------------------------------------------------------------------------------------


def test_sum_rules_are_the_dual_point_conditions():
    # the coset-moment test agrees with the vanishing of the symbol's derivatives at z = exp(2 pi i omega)
    for slug in ("loop", "biquadratic", "zwart-powell", "quincunx-zp", "sqrt3"):
        a = get(slug).mask()
        k = sum_rules(a).value
        sym = a.symbol
        for w in a.dilation.dual_points[1:]:
            pt = {Z1: sp.exp(2 * sp.pi * sp.I * sp.Rational(w[0].numerator, w[0].denominator)),
                  Z2: sp.exp(2 * sp.pi * sp.I * sp.Rational(w[1].numerator, w[1].denominator))}
            for d in range(k + 1):
                vals = [sp.nsimplify(sp.expand(sp.diff(sym, Z1, p, Z2, d - p).subs(pt)))
                        for p in range(d + 1)]
                if d < k:
                    assert all(v == 0 for v in vals), (slug, w, d)
        # and order k + 1 fails at some dual point (the witness is a real difference of moments)
        assert sum_rules(a).witness["failing"] is not None


def test_butterfly_sum_rules_generic_and_exceptional():
    r = sum_rules(get("butterfly").mask(general=True))
    assert r.value == 2
    assert r.witness["exceptional"] == [{"value": sp.Rational(1, 16), "order": 4}]


@pytest.mark.parametrize("directions", [[(1, 0), (0, 1), (1, 1)], [(1, 0)] * 2 + [(0, 1)] * 2 + [(1, 1)] * 2,
                                        [(1, 0), (0, 1), (1, 1), (1, -1)], [(1, 0)] * 3 + [(0, 1)] * 3])
def test_box_factors_recover_the_directions(directions):
    want = {}
    for xi in directions:
        want[xi] = want.get(xi, 0) + 1
    r = box_factors(box_spline_mask(directions))
    q = r.witness["quotient"]                      # 4 times a monomial (the centring shift)
    assert r.value == want and len(sp.Add.make_args(q)) == 1 and q.subs({Z1: 1, Z2: 1}) == 4


def test_quincunx_entry_squares_to_the_zwart_powell_mask():
    q = get("quincunx-zp").mask()
    # two steps: a(z) a(z^M), (z^M)_j = prod_i z_i^{M_ij}
    M = q.dilation.matrix
    zM = {Z1: Z1 ** M[0][0] * Z2 ** M[1][0], Z2: Z1 ** M[0][1] * Z2 ** M[1][1]}
    two = sp.expand(q.symbol * q.symbol.subs(zM, simultaneous=True))
    zp = get("zwart-powell").mask().symbol
    ratio = sp.cancel(two / zp)                       # a monomial: the same mask up to a shift
    assert len(sp.Add.make_args(sp.expand(ratio))) == 1 and ratio.subs({Z1: 1, Z2: 1}) == 1


def test_reproduction_shift_of_dual_and_primal_schemes():
    assert reproduction(get("biquadratic").mask()).witness["tau"] == (sp.Rational(-1, 4), sp.Rational(-1, 4))
    assert reproduction(get("loop").mask()).witness["tau"] == (0, 0)


def test_from_stencils_checks_coverage_and_consistency():
    with pytest.raises(AnalysisError, match="cover 1 of the 4"):
        from_stencils({(0, 0): {(0, 0): 1}})
    with pytest.raises(AnalysisError, match="disagree"):
        from_stencils({(0, 0): {(0, 0): 1}, (1, 0): {(0, 0): "1/2"}, (2, 1): {(1, 0): 1}}, dilation="quincunx")


# ----------------------------------------------------------------------------------------------
# the catalogue: transcription first (algebra), every entry
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("entry", entries(), ids=lambda e: e.slug)
def test_catalogue_transcription(entry):
    a = entry.mask()
    assert a.total == a.dilation.m                      # sum rules of order 1 need each coset to sum to 1
    assert entry.source
    c = entry.claims
    if "sum_rules" in c:
        assert sum_rules(a).value == c["sum_rules"]
    if "reproduction" in c:
        assert reproduction(a).value == c["reproduction"]
    grid = a.dilation.matrix == ((2, 0), (0, 2))
    hexagonal = entry.slug in ("box-111", "loop", "box-333", "butterfly")
    want = 12 if hexagonal else 8 if grid and entry.slug not in ("zwart-powell",) else None
    if want is not None:
        assert symmetry_group(a).value == want


# ----------------------------------------------------------------------------------------------
# transition operators and the Hölder exponent
# ----------------------------------------------------------------------------------------------


def test_invariant_support_is_closed():
    a = get("loop").mask()
    omega = set(invariant_support(a))
    D = a.dilation
    for i in omega:
        for e in D.digits:
            for (x, y) in a.coeffs:
                # column i of T_eps has its support in Omega: j = M^-1(i + alpha - eps) integer => j in Omega
                j = D.solve((i[0] + x - e[0], i[1] + y - e[1]))
                if j[0].denominator == 1 and j[1].denominator == 1:
                    assert (int(j[0]), int(j[1])) in omega


def test_transition_operators_sum_to_the_column_stochastic_operator():
    # sum_eps of each column of T_eps is sum_alpha a(alpha) = |det M| ... per coset: each column sums to 1
    mats, omega = transition_matrices(get("box-111").mask())
    for T in mats:
        for s, i in enumerate(omega):
            col = sum(T[r, s] for r in range(len(omega)))
            assert col in (0, 1)


def test_difference_subspace_needs_the_sum_rules():
    with pytest.raises(AnalysisError, match="sum rules of order 3"):
        restricted_transition(get("box-111").mask(), 3)


@pytest.mark.parametrize("slug", ["box-111", "loop", "zwart-powell", "biquadratic"])
def test_catalogue_alpha_exact(slug):
    e = get(slug)
    h = holder_exponent(e.mask())
    assert h.status == CERTIFIED and h.value == e.claims["alpha"] and h.witness["jsr_value"] is not None
    ck = smoothness_verdicts(h)
    assert ck[e.claims["C"]] is True and ck[e.claims["C"] + 1] is False


def test_quincunx_alpha_enclosed_with_exact_upper_end():
    # JSR >= 1/2 = rho(M)^-2 exactly (a product's spectral radius); the polytope closes up to rounding only
    e = get("quincunx-zp")
    h = holder_exponent(e.mask())
    assert h.status == CERTIFIED and h.value is None and h.witness["alpha_upper_exact"]
    assert h.upper == e.claims["alpha"] and 0 < h.upper - h.lower < sp.Rational(1, 10 ** 12)
    ck = smoothness_verdicts(h)
    assert ck[1] is True and ck[2] is False


def test_sqrt3_alpha_is_two_plus_log3_of_2():
    """T_012 has the leading eigenvalues +-i/sqrt(5832) (JSR >= 5832^(-1/6), alpha <= 2 + log_3 2); the upper
    bound comes from the reduced family B_d = T_0 G^d of the exact cyclic symmetry G T_j G^-1 = T_(j+1)."""
    h = holder_exponent(get("sqrt3").mask())
    assert h.status == CERTIFIED and h.value is None
    exact = 2 + sp.log(2) / sp.log(3)
    assert h.lower <= exact <= h.upper and h.upper - h.lower < sp.Rational(1, 10 ** 12)
    r = h.witness["jsr"]
    assert r.witness["product"] == (0, 1, 2) and r.witness["cyclic_symmetry"]["reduced_product"] == (1,)
    assert r.witness["rho_product"]["lower"] ** 2 <= sp.Rational(1, 5832) <= r.witness["rho_product"]["upper"] ** 2
    ck = smoothness_verdicts(h)
    assert ck[2] is True and ck[3] is False


def test_box_spline_alpha_is_m_xi_minus_one_on_a_scaled_courant_family():
    # three-direction box spline B_211: m(Xi) = 2 -> alpha = 1 (C^0, not C^1)
    h = holder_exponent(box_spline_mask([(1, 0), (1, 0), (0, 1), (1, 1)]))
    assert h.value == 1 and smoothness_verdicts(h)[1] is False


def test_anisotropic_dilation_is_inconclusive_but_decides_c0():
    # the tensor product of the linear B-spline (M = 2) and the ternary linear B-spline (M = 3)
    a = BivariateMask.from_symbol("(1+z1)**2/(2*z1)*(1+z2+z2**2)**2/(3*z2**2)", [[2, 0], [0, 3]])
    h = holder_exponent(a)
    assert h.status == INCONCLUSIVE and h.value is None and not h.witness["isotropic"]
    ck = smoothness_verdicts(h)
    assert ck[0] is True and ck[2] is False


def test_not_convergent_mask_is_refused():
    with pytest.raises(AnalysisError, match="sum rules of order 1"):
        holder_exponent(BivariateMask.from_list("0,0:1; 1,0:1; 0,1:1; 1,1:1/2"))


# ----------------------------------------------------------------------------------------------
# the command
# ----------------------------------------------------------------------------------------------


def test_cli_surface_text(capsys):
    assert main(["surface", "--scheme", "box-111"]) == 0
    out = capsys.readouterr().out
    assert "sum rules: order 2" in out and "alpha = 1 exactly (certified)" in out and "C^0: yes; C^1: no" in out


def test_cli_surface_json(capsys):
    assert main(["surface", "--symbol", "(1+z1)*(1+z2)/2", "--dilation", "quincunx", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["sum_rules"] == 2 and doc["holder"]["upper"] == "2" and doc["smoothness"] == {
        "C0": True, "C1": True, "C2": False}
    assert doc["dual_points"] == [["0", "0"], ["1/2", "1/2"]]


@pytest.mark.parametrize("argv,match", [
    (["surface"], "exactly one of"),
    (["surface", "--scheme", "lopo"], "did you mean"),
    (["surface", "--symbol", "1+z1", "--dilation", "1,0;0,1"], "det"),
    (["surface", "--scheme", "loop", "--dilation", "quincunx"], "own dilation"),
    (["surface", "--symbol", "(1+z1)*(1+w*z2)"], "give values"),
    (["surface", "--scheme", "butterfly", "--sweep", "w0"], "NAME=v1"),
])
def test_cli_surface_errors_are_one_line(argv, match, capsys):
    assert main(argv + ["--json"]) == 2
    cap = capsys.readouterr()
    assert cap.err.count("\n") == 1 and cap.err.startswith("subdiv: error:") and match in cap.err
    assert "error" in json.loads(cap.out)


def test_refine_delta_keeps_the_mass_and_draws_a_figure(tmp_path, capsys):
    from analysis.bivariate.refine import basic_limit_samples

    pts, vals = basic_limit_samples(get("loop").mask(), 3, "triangular")
    assert abs(vals.sum() - 4 ** 3) < 1e-9 and abs(pts[:, 0]).max() <= 2        # hexagonal support of radius 2
    fig = tmp_path / "phi.png"
    assert main(["surface", "--scheme", "box-111", "--refine", "2", "--figure", str(fig)]) == 0
    assert fig.stat().st_size > 1000 and "triangular grid" in capsys.readouterr().out
    assert main(["surface", "--scheme", "box-111", "--figure", str(fig)]) == 2


def test_sum_rule_order_beyond_the_limit_is_refused(monkeypatch):
    # with the limit lowered to 2, the bilinear mask (sum rules of order exactly 2) reaches it
    import analysis.bivariate.holder as H

    monkeypatch.setattr(H, "sum_rules", lambda a: sum_rules(a, max_order=2))
    with pytest.raises(AnalysisError, match="every order up to 2"):
        H.holder_exponent(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)"))


def test_an_inconclusive_alpha_says_which_budget_it_had(capsys):
    """The JSR of the quincunx scheme does not close in 3 work units: the text says so and names the budget;
    with the default budget the same line is certified and carries no such note."""
    main(["surface", "--scheme", "quincunx-zp", "--budget", "3"])
    line = next(t for t in capsys.readouterr().out.splitlines() if t.startswith("alpha"))
    assert "(inconclusive;" in line and "a larger --budget may settle it (now 3)" in line
    main(["surface", "--scheme", "quincunx-zp"])
    line = next(t for t in capsys.readouterr().out.splitlines() if t.startswith("alpha"))
    assert "certified" in line and "--budget" not in line
