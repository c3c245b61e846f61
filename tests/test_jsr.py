"""Tests of the joint spectral radius engine (analysis.jsr).

Every certified interval is checked against an independent truth: a closed form (spectral
radius, commuting or triangular families, the golden ratio, the D4 Hölder exponent) or the float
brute force over all products (``brute_force_bounds``), which must be consistent with it.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from analysis import AnalysisError
from analysis.jsr import Work, brute_force_bounds, canonical_word, jsr_bounds, parse_family
from analysis.jsr._balance import balanced_roots
from analysis.jsr._polytope import build_polytope, certify_polytope, complete_reps

PHI = (1 + sp.sqrt(5)) / 2


def contains(r, x) -> bool:
    """Exact test lower <= x <= upper (x a sympy real number)."""
    return bool(sp.Le(r.lower, x)) and bool(sp.Le(x, r.upper))


def gap(r) -> float:
    return float(r.upper / r.lower - 1)


def transition_matrices(c: list, n: int | None = None) -> tuple[sp.Matrix, sp.Matrix]:
    """T_eps[i, j] = c_{2i - j + eps} for a mask c_0..c_N (N x N); any consistent convention
    gives a family similar or transposed to this one, with the same JSR."""
    N = len(c) - 1 if n is None else n

    def T(e):
        return sp.Matrix(N, N, lambda i, j: c[2 * i - j + e] if 0 <= 2 * i - j + e < len(c) else 0)

    return T(0), T(1)


# --------------------------------------------------------------------------------------------
# closed forms
# --------------------------------------------------------------------------------------------

def test_single_matrix_is_its_spectral_radius():
    r = jsr_bounds([[[2, 1], [1, 2]]])
    assert r.status == "certified" and r.value == 3
    r = jsr_bounds([[[1, 1], [1, 0]]])               # rho = golden ratio, irrational
    assert r.status == "certified" and contains(r, PHI) and gap(r) < 1e-20
    r = jsr_bounds([[[1, 1], [0, 1]]])               # a Jordan block: JSR = rho = 1 exactly
    assert r.value == 1


def test_commuting_family_is_max_spectral_radius():
    fam = [[[2, 0], [0, 1]], [[1, 0], [0, 3]], [["1/2", 0], [0, "5/2"]]]
    r = jsr_bounds(fam)
    assert r.status == "certified" and r.value == 3
    # the general machinery (no structural shortcut) must agree
    rp = jsr_bounds(fam, method="polytope", budget=5000)
    assert rp.status == "certified" and contains(rp, 3) and gap(rp) < 1e-10
    assert rp.witness["closed"] and rp.witness["product"] == (1,)


def test_triangular_families():
    A = [[[2, 5], [0, 1]], [[1, -3], [0, "3/2"]]]    # JSR = max |diagonal| = 2
    r = jsr_bounds(A)
    assert r.value == 2 and "block" in r.provenance["method"]
    rp = jsr_bounds(A, method="polytope", budget=5000)
    assert rp.status == "certified" and contains(rp, 2)
    # lower-triangular, 3x3, with a product that has larger diagonal than either factor? no:
    # diagonals multiply, so JSR = max |d|; check against brute force as well
    B = [[[1, 0, 0], [4, -2, 0], [1, 1, "1/2"]], [["3/2", 0, 0], [1, 1, 0], [7, 0, -1]]]
    r = jsr_bounds(B)
    assert r.value == 2
    bf = brute_force_bounds(np.array(parse_family(B).floats), 8)
    assert bf["lower"] == pytest.approx(2.0)


def test_golden_ratio_pair():
    r = jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], budget=5000)
    assert r.status == "certified"
    assert contains(r, PHI) and gap(r) < 1e-12
    assert r.witness["product"] == (0, 1) and r.witness["length"] == 2
    assert r.witness["closed"] is True and r.witness["polytope_vertices"] >= 2
    exact = r.witness["rho_product_root_exact"]
    assert sp.simplify(exact - PHI) == 0
    json.dumps(r.to_json())                           # the contract: JSON-ready


def test_identity_like_families():
    I = [[1, 0], [0, 1]]
    for other in ([[0, 1], [1, 0]], [[0, -1], [1, 0]], [["1/2", 0], [0, "1/2"]], I):
        for method in ("auto", "polytope"):
            r = jsr_bounds([I, other], method=method, budget=5000)
            assert r.status == "certified" and contains(r, 1) and gap(r) < 1e-10, (other, method)
    r = jsr_bounds([I, I, I])
    assert r.value == 1 and r.provenance["duplicates_removed"] == 2


def test_jointly_nilpotent_family():
    r = jsr_bounds([[[0, 1, 2], [0, 0, 3], [0, 0, 0]], [[0, 5, 0], [0, 0, 1], [0, 0, 0]]])
    assert r.value == 0 and r.status == "certified"


# --------------------------------------------------------------------------------------------
# subdivision examples
# --------------------------------------------------------------------------------------------

def test_daubechies_d4_holder_exponent():
    """D4: a(z) = ((1+z)/2)^2 ((1+sqrt3) + (1-sqrt3) z); with k = 0, c = a/(1+z) =
    ((1+sqrt3)/4, 1/2, (1-sqrt3)/4) and alpha = -log2 JSR(T0, T1) = 2 - log2(1 + sqrt 3)."""
    s3 = sp.sqrt(3)
    a = sp.expand(((1 + sp.Symbol("z")) / 2) ** 2 * ((1 + s3) + (1 - s3) * sp.Symbol("z")))
    z = sp.Symbol("z")
    assert sp.simplify(a.subs(z, 1) - 2) == 0 and sp.simplify(a.subs(z, -1)) == 0
    c = sp.Poly(sp.cancel(a / (1 + z)), z).all_coeffs()[::-1]
    assert [sp.simplify(x) for x in c] == [sp.simplify((1 + s3) / 4), sp.Rational(1, 2),
                                           sp.simplify((1 - s3) / 4)]
    T0, T1 = transition_matrices(c)
    r = jsr_bounds([T0, T1], budget=10000)
    assert r.status == "certified"
    assert "Arb" in r.provenance["arithmetic"]       # irrational entries: ball arithmetic
    assert contains(r, (1 + s3) / 4) and gap(r) < 1e-9
    alpha_lo = -math.log2(float(r.upper))
    alpha_hi = -math.log2(float(r.lower))
    alpha = 2 - math.log2(1 + math.sqrt(3))
    assert alpha_lo <= alpha + 1e-12 and alpha <= alpha_hi + 1e-12
    assert abs(alpha - 0.5500) < 1e-4 and alpha_hi - alpha_lo < 1e-8
    # brute force agrees: products up to length 10 bracket the certified interval
    bf = brute_force_bounds([np.array(T0, dtype=float), np.array(T1, dtype=float)], 10)
    assert bf["lower"] <= float(r.upper) * (1 + 1e-12)
    assert float(r.lower) <= bf["upper"] * (1 + 1e-12)
    assert bf["upper"] > float(r.upper) + 1e-3      # ... but brute force is far from tight


def test_four_point_scheme_holder_exponent_two():
    """4-point scheme: a(z) = -(1/16) z^-3 (1+z)^4 (z^2 - 4z + 1). For k = 2 and k = 3 the two
    difference masks must give the same alpha = 2 (JSR 1 and 2)."""
    c2 = [sp.Rational(-1, 4), sp.Rational(3, 4), sp.Rational(3, 4), sp.Rational(-1, 4)]
    r2 = jsr_bounds(list(transition_matrices(c2)), budget=5000)
    c3 = [sp.Rational(-1, 2), 2, sp.Rational(-1, 2)]
    r3 = jsr_bounds(list(transition_matrices(c3)), method="polytope", budget=5000)
    assert r2.status == r3.status == "certified"
    assert contains(r2, 1) and gap(r2) < 1e-12
    assert contains(r3, 2) and gap(r3) < 1e-12
    # two s.m.p.s (T0 and T1 both have rho = 2): both leading eigenvectors are roots
    assert set(r3.witness["candidates"]) == {(0,), (1,)}


# --------------------------------------------------------------------------------------------
# random families, effort, brute force
# --------------------------------------------------------------------------------------------

def _random_rational_family(seed: int, n: int = 3, k: int = 2) -> list[list[list[Fraction]]]:
    rng = np.random.default_rng(seed)
    return [[[Fraction(int(x), 4) for x in row] for row in rng.integers(-8, 9, (n, n))]
            for _ in range(k)]


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4, 5])
def test_random_3x3_certified_and_consistent_with_brute_force(seed):
    fam = _random_rational_family(seed)
    r = jsr_bounds(fam, budget=5000)
    assert r.lower <= r.upper
    assert r.status in ("certified", "inconclusive")
    floats = parse_family(fam).floats
    bf = brute_force_bounds(floats, 10)
    # rigorous bounds vs float brute force (float slack 1e-12)
    assert bf["lower"] <= float(r.upper) * (1 + 1e-12)
    assert float(r.lower) <= bf["upper"] * (1 + 1e-12)
    if r.status == "certified":
        assert gap(r) <= 1e-6
        # the witness product really has the reported spectral radius
        P = np.eye(3)
        for i in r.witness["product"]:
            P = P @ floats[i]
        rho = max(abs(np.linalg.eigvals(P))) ** (1 / r.witness["length"])
        assert rho == pytest.approx(float(r.lower), rel=1e-12)


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_longer_products_never_worsen_the_interval(seed):
    fam = _random_rational_family(seed)
    for method in ("norms", "auto"):
        prev = None
        for L in (1, 2, 4, 8):
            r = jsr_bounds(fam, method=method, max_length=L, budget=5000)
            assert r.lower <= r.upper
            if prev is not None:
                assert r.lower >= prev.lower, (method, L)
                assert r.upper <= prev.upper, (method, L)
            prev = r
    # and the polytope is far sharper than the textbook bound at the same length
    rn = jsr_bounds(fam, method="norms", max_length=8)
    ra = jsr_bounds(fam, max_length=8, budget=5000)
    assert gap(ra) < gap(rn)


def test_complex_leading_eigenvalue_complex_polytope():
    """The s.m.p. (0,) of this family has a complex leading eigenvalue pair (an irrational
    rotation): the real polytope cannot close exactly; the complex polytope (started from u and
    conj(u)) closes and is certified in Arb complex balls, to the precision of the arithmetic."""
    fam = _random_rational_family(10)
    r = jsr_bounds(fam, budget=20000, rel_gap=1e-8)
    assert r.status == "certified" and gap(r) <= 1e-12
    assert r.witness["leading_eigenvalue_real"] is False
    assert "complex invariant polytope" in r.provenance["method"]
    assert r.witness["complex_polytope"]["closed"]
    bf = brute_force_bounds(parse_family(fam).floats, 10)
    assert bf["lower"] <= float(r.upper) and float(r.lower) <= bf["upper"]


def test_complex_certificate_is_rigorous_for_a_rotation():
    """Scaled rotation by an irrational angle (cos = 3/5) and a contraction: JSR = 2 exactly.
    The certified upper bound must be >= 2 (rigour) and within 1e-12 of it (closure)."""
    from analysis.jsr._complex import build_complex_polytope, certify_complex_polytope
    R = sp.Rational
    fam = [[[R(6, 5), R(-8, 5)], [R(8, 5), R(6, 5)]], [[R(1, 2), 0], [0, R(1, 4)]]]
    F = parse_family(fam)
    u = np.array([1.0, -1.0j])
    st = build_complex_polytope(F.floats, 2.0, [u, u.conj()], work=Work(10_000))
    assert st.closed
    c = certify_complex_polytope(F, Fraction(2), st)
    assert 2 <= c.upper <= 2 * (1 + Fraction(1, 10 ** 12))
    # a scale below the JSR cannot be certified: the bound exceeds it by the true ratio
    c2 = certify_complex_polytope(F, Fraction(19, 10), st)
    assert c2 is None or c2.upper >= 2


def test_brute_force_bounds_bracket_known_value():
    A = [np.array([[1., 1], [0, 1]]), np.array([[1., 0], [1, 1]])]
    for L in (2, 5, 9):
        b = brute_force_bounds(A, L)
        assert b["lower"] <= 1.6180339887498951 <= b["upper"] + 1e-15
    assert brute_force_bounds(A, 9)["upper"] < brute_force_bounds(A, 3)["upper"]


# --------------------------------------------------------------------------------------------
# honesty of the certificate
# --------------------------------------------------------------------------------------------

def test_certificate_is_not_fooled_by_wrong_coefficients():
    """Corrupt every float coefficient: the exact re-check must still return a valid upper
    bound (>= the true JSR = golden ratio), i.e. it may not trust the float LP."""
    F = parse_family([[[1, 1], [0, 1]], [[1, 0], [1, 1]]])
    rho = float(PHI)
    st = build_polytope(F.floats, rho, balanced_roots(F.floats, rho, [(0, 1)])[0],
                        work=Work(5_000))
    assert st.closed
    good = certify_polytope(F, Fraction(rho), st)
    assert good.upper >= Fraction(str(sp.N(PHI, 30))) * (1 - Fraction(1, 10 ** 25))
    for key, (supp, lam) in list(st.reps.items()):
        st.reps[key] = (supp, lam * 0.5)
    bad = certify_polytope(F, Fraction(rho), st)
    assert bad.upper > good.upper
    assert bad.upper >= Fraction(rho)


def test_certificate_of_a_too_small_scale_is_still_an_upper_bound():
    """Scaling by r < JSR cannot close; the completed (non-closing) polytope still certifies a
    valid bound, necessarily >= JSR."""
    F = parse_family([[[1, 1], [0, 1]], [[1, 0], [1, 1]]])
    r = 1.5
    st = build_polytope(F.floats, r, balanced_roots(F.floats, r, [(0, 1)])[0],
                        work=Work(1_000), max_vertices=20, check_better=False)
    assert not st.closed
    assert complete_reps(F.floats, r, st, work=Work(5_000))
    cert = certify_polytope(F, Fraction(r), st)
    assert float(cert.upper) >= float(PHI)


def test_float_input_is_numerical_unless_declared_exact():
    A = [np.array([[1., 1], [0, 1]]), np.array([[1., 0], [1, 1]])]
    r = jsr_bounds(A, budget=5000)
    assert r.status == "numerical" and contains(r, PHI)
    r2 = jsr_bounds(A, budget=5000, floats_exact=True)
    assert r2.status == "certified" and "binary rationals" in r2.provenance["arithmetic"]
    # exact inputs in several spellings give the same rigorous bounds
    r3 = jsr_bounds([sp.Matrix([[1, 1], [0, 1]]), [["1", "0"], ["1.0", 1]]], budget=5000)
    assert (r3.lower, r3.upper) == (r2.lower, r2.upper)


def test_inconclusive_outcome_keeps_rigorous_bounds():
    # a Jordan block with a contraction: JSR = 1 is not attained by any extremal norm, so the
    # polytope cannot close (the structural shortcut would settle it; method="polytope" skips it)
    r = jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [0, "1/2"]]], method="polytope",
                   budget=1000, max_length=4)
    assert r.status == "inconclusive"
    assert contains(r, 1) and r.upper > 1
    assert "settle" in r.provenance["message"]


def test_canonical_word():
    assert canonical_word((1, 0, 1, 0)) == (0, 1)
    assert canonical_word((2, 0, 1)) == (0, 1, 2)
    assert canonical_word((1, 1)) == (1,)


@pytest.mark.parametrize("bad", [
    [],
    [[[1, 2, 3], [4, 5, 6]]],
    [[[1, 0], [0, 1]], [[1]]],
    [[["x", 0], [0, 1]]],
    [[[float("nan"), 0], [0, 1]]],
])
def test_bad_input(bad):
    with pytest.raises(AnalysisError):
        jsr_bounds(bad)


def test_bad_method():
    with pytest.raises(AnalysisError):
        jsr_bounds([[[1]]], method="magic")


# --------------------------------------------------------------------------------------------
# ball-valued (uncertain) families
# --------------------------------------------------------------------------------------------

def test_ball_family_certified_and_contains_every_member():
    from flint import arb

    eps = arb(2) ** -60
    one = arb(1, eps)
    r = jsr_bounds([[[one, 1], [0, 1]], [[1, 0], [1, one]]], budget=5000)
    assert r.status == "certified" and r.provenance["input_kind"] == "ball"
    assert contains(r, PHI) and gap(r) < 1e-15
    # exactly known balls (radius 0) are read exactly: same result as the rational family
    re_ = jsr_bounds([[[arb(1), 1], [0, 1]], [[1, 0], [1, arb(1)]]], budget=5000)
    assert re_.provenance["input_kind"] == "rational" and contains(re_, PHI)


def test_ball_entries_containing_zero_are_not_structural_zeros():
    """A ball around 0 may be nonzero: the block-triangular shortcut must not use it."""
    from flint import arb

    tiny = arb(0, arb(2) ** -40)
    r = jsr_bounds([[[2, 0], [tiny, 1]], [[1, 1], [0, 3]]], budget=5000)
    assert "block" not in r.provenance["method"]
    assert r.lower <= 3 <= r.upper and gap(r) < 1e-6       # the member tiny = 0 has JSR 3
    rb = jsr_bounds([[[2, 0], [0, 1]], [[1, 1], [0, 3]]])   # exactly 0: block triangular
    assert rb.value == 3 and "block" in rb.provenance["method"]


def test_ball_and_exact_d4_agree():
    """D4 difference pair (1x1): exact Q(sqrt 3) entries vs Arb balls around them."""
    import flint

    s3 = sp.sqrt(3)
    exact = jsr_bounds([[[(1 + s3) / 2]], [[(1 - s3) / 2]]])
    with flint.ctx.workprec(200):
        b = (1 + flint.arb(3).sqrt()) / 2
        c = (1 - flint.arb(3).sqrt()) / 2
    ball = jsr_bounds([[[b]], [[c]]])
    assert exact.status == ball.status == "certified"
    assert contains(exact, (1 + s3) / 2) and contains(ball, (1 + s3) / 2)
    assert ball.lower <= exact.upper and exact.lower <= ball.upper


def test_similarity_preconditioning_preserves_the_jsr():
    """``S^-1 A_i S`` for a dyadic ``S`` (exact rational and ball back ends) has the same JSR:
    the golden-ratio pair stays certified around phi after the transform."""
    from flint import arb
    from analysis.jsr._precondition import rounding_transform, transform_family

    F = parse_family([[[1, 1], [0, 1]], [[1, 0], [1, 1]]])
    S = rounding_transform(np.array([[1.0, 0.3, -0.2], [1e-6, 2e-6, 5e-7]]))
    assert S is not None
    G = transform_family(F, S)
    assert G.kind == "rational"
    r = jsr_bounds(G.exact_q, budget=5000)
    assert r.status == "certified" and contains(r, PHI)
    one = arb(1, arb(2) ** -100)
    Fb = parse_family([[[one, 1], [0, 1]], [[1, 0], [1, one]]])
    Gb = transform_family(Fb, S)
    assert Gb.kind == "ball"
    rb = jsr_bounds([[[M[a, b] for b in range(2)] for a in range(2)] for M in Gb.balls],
                    budget=5000)
    assert rb.lower <= PHI <= rb.upper and float(rb.upper / rb.lower - 1) < 1e-9


def test_exact_invariant_subspace_not_a_coordinate_one():
    """A common invariant line spanned by (1, 1) (no common zero pattern): found exactly, the
    family split into 1 x 1 blocks, JSR = 2 exactly; and a similar conjugate of a
    block-triangular 3 x 3 family reduces the same way."""
    r = jsr_bounds([[[1, 1], [0, 2]], [[2, 0], [1, 1]]])
    assert r.status == "certified" and r.lower == r.upper == 2
    assert r.witness["invariant_subspace"]["dimension"] == 1
    from flint import fmpq_mat
    from analysis.jsr._subspace import invariant_subspace, split_family
    Q = fmpq_mat([[1, 2, 0], [0, 1, 3], [1, 0, 1]])
    blocks = [fmpq_mat([[2, 1, 5], [1, 1, 7], [0, 0, 3]]), fmpq_mat([[0, 1, 1], [3, 1, 2], [0, 0, -1]])]
    fam = [Q * B * Q.inv() for B in blocks]
    W = invariant_subspace(fam)
    assert W is not None and W.ncols() == 2
    top, bottom = split_family(fam, W)
    # the spectra of the blocks are those of the original diagonal blocks
    assert sorted(str(M) for M in bottom) == ["[-1]", "[3]"]
    rr = jsr_bounds([[[sp.Rational(int(M[a, b].p), int(M[a, b].q)) for b in range(3)]
                      for a in range(3)] for M in fam])
    assert rr.witness["invariant_subspace"]["dimension"] in (1, 2)
    ref = jsr_bounds([[[2, 1], [1, 1]], [[0, 1], [3, 1]]])
    assert rr.lower <= max(ref.upper, 3) and max(ref.lower, 3) <= rr.upper


def test_irreducible_family_has_no_invariant_subspace_found():
    from flint import fmpq_mat
    from analysis.jsr._subspace import invariant_subspace
    assert invariant_subspace([fmpq_mat([[1, 1], [0, 1]]), fmpq_mat([[1, 0], [1, 1]])]) is None
