"""Tests of analysis.stationary.transition: transition matrices, local subdivision matrices and their
eigenvalues, and the support of the basic limit function.

Everything algebraic is compared exactly (``==`` on sympy objects after ``expand``); the only
float comparisons are the numpy spectral radii, which are checked against exact norm bounds.
"""

from __future__ import annotations

import itertools
import random

import numpy as np
import pytest
import sympy as sp

from analysis.result import CERTIFIED, AnalysisError, Result
from analysis.algebra.symbol import Z, LaurentSymbol
from analysis.stationary.transition import (LAMBDA, basic_limit_support, invariant_window, is_invariant_window,
                                 local_eigenvalues, local_subdivision_matrix, transition_matrices)

R = sp.Rational
nu, mu, w, t = sp.symbols("nu mu omega t")


# --------------------------------------------------------------------------------------------
# masks
# --------------------------------------------------------------------------------------------

def bspline(d: int) -> LaurentSymbol:
    """Degree-d B-spline, (1+z)^(d+1)/2^d, centred (start -floor((d+1)/2))."""
    coeffs = [R(sp.binomial(d + 1, i), 2**d) for i in range(d + 2)]
    return LaurentSymbol.from_mask(coeffs, start=-((d + 1) // 2))


FOUR_POINT = LaurentSymbol.from_mask([-w, 0, w + R(1, 2), 1, w + R(1, 2), 0, -w], start=-3)
FOUR_POINT_16 = FOUR_POINT.subs({w: R(1, 16)})
SIX_POINT = LaurentSymbol.from_mask([R(c, 256) for c in (3, 0, -25, 0, 150, 256, 150, 0, -25, 0, 3)],
                                    start=-5)
CHAIKIN = LaurentSymbol.from_mask([R(1, 4), R(3, 4), R(3, 4), R(1, 4)], start=-2)
_s6 = (sp.sqrt(6) - 1) / 80
ALGEBRAIC = (LaurentSymbol.from_mask([R(1, 2), R(1, 2)]) ** 2
             * LaurentSymbol.from_mask([_s6, 2 - 2 * _s6, _s6], start=-2))           # QQ<sqrt(6)>
RATIONAL_PARAM = LaurentSymbol.from_mask([1 / (4 * (1 + w)), R(1, 2), 1 - 1 / (2 * (1 + w)), R(1, 2),
                                          1 / (4 * (1 + w))], start=-2)            # QQ(omega)

# seed 004, sub-schemes (3.7) and (3.8), in our convention (see the module report)
S37 = LaurentSymbol.from_mask([(-5 + 7 * nu) / 128, (-7 + 21 * nu) / 128, (35 + 7 * nu) / 128,
                               (105 - 35 * nu) / 128, (105 - 35 * nu) / 128, (35 + 7 * nu) / 128,
                               (-7 + 21 * nu) / 128, (-5 + 7 * nu) / 128], start=-4)
S38 = LaurentSymbol.from_mask([7 * mu / 128, 21 * mu / 128, R(1, 64) - 7 * mu / 128,
                               R(7, 64) - 77 * mu / 128, R(21, 64) - 21 * mu / 64,
                               R(35, 64) + 49 * mu / 64, R(35, 64) + 49 * mu / 64,
                               R(21, 64) - 21 * mu / 64, R(7, 64) - 77 * mu / 128,
                               R(1, 64) - 7 * mu / 128, 21 * mu / 128, 7 * mu / 128], start=-6)

# (mask, smoothing order k = multiplicity of (1+z)) for the spectrum test
SCHEMES = {
    "linear": (bspline(1), 2),
    "chaikin": (CHAIKIN, 3),
    "cubic-bspline": (bspline(3), 4),
    "quintic-bspline": (bspline(5), 6),
    "4point-1/16": (FOUR_POINT_16, 4),
    "4point-omega": (FOUR_POINT, 2),
    "6point-DD": (SIX_POINT, 6),
    "sqrt6": (ALGEBRAIC, 2),
    "rational-param": (RATIONAL_PARAM, 2),
    "seed004-3.7": (S37, 2),
    "seed004-3.8": (S38, 2),
}


def difference_mask(a: LaurentSymbol, k: int) -> LaurentSymbol:
    """c(z) = 2^k a(z) / (1+z)^(k+1), by exact polynomial division (independent of the module)."""
    q, r = sp.div(sp.Poly(a.poly.as_expr() * 2**k, Z), sp.Poly((1 + Z) ** (k + 1), Z))
    assert r.is_zero
    return LaurentSymbol.from_mask(list(reversed(q.all_coeffs())), start=a.start)


def power_symbol(c: LaurentSymbol, L: int) -> LaurentSymbol:
    """c(z) c(z^2) ... c(z^(2^(L-1)))."""
    out = LaurentSymbol.from_mask([1])
    for m in range(L):
        out = out * c.upsample(2**m)
    return out


def norm_L(c: LaurentSymbol, L: int) -> sp.Expr:
    """||S_c^L||_inf = max over residues r mod 2^L of sum |coeff| (exact, numeric masks)."""
    sums = [sp.Integer(0)] * 2**L
    for i, x in power_symbol(c, L).items():
        sums[i % 2**L] += abs(x)
    return max(sums, key=lambda v: sp.N(v, 30))


def refine(a: LaurentSymbol, f: dict[int, sp.Expr]) -> dict[int, sp.Expr]:
    """One step (S_a f)_i = sum_j a_{i-2j} f_j on finitely supported data (plain loops)."""
    out: dict[int, sp.Expr] = {}
    for j, fj in f.items():
        for k, ak in a.items():
            out[k + 2 * j] = out.get(k + 2 * j, 0) + ak * fj
    return out


# --------------------------------------------------------------------------------------------
# 1. transition matrices
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("start", [0, -3, 5], ids=["c=1", "c=z^-3", "c=z^5"])
def test_bspline_difference_mask_has_jsr_one(start):
    T0, T1 = transition_matrices(LaurentSymbol.from_mask([1], start=start))
    assert T0 == sp.Matrix([[1]]) and T1 == sp.Matrix([[0]])
    # 1x1 matrices commute: the JSR is the largest modulus, exactly 1
    assert max(abs(T0[0, 0]), abs(T1[0, 0])) == 1


@pytest.mark.parametrize("d", [1, 2, 3, 5], ids=lambda d: f"bspline-deg{d}")
def test_bspline_c_is_one(d):
    """For a B-spline of degree d, c = 2^d a/(1+z)^(d+1) = z^s, so JSR = 1 and alpha = d."""
    c = difference_mask(bspline(d), d)
    assert c.mask == (1,)
    T0, T1 = transition_matrices(c)
    assert (T0, T1) == (sp.Matrix([[1]]), sp.Matrix([[0]]))


def test_four_point_transition_matrices():
    c = difference_mask(FOUR_POINT_16, 3)
    assert c == LaurentSymbol.from_mask([R(-1, 2), 2, R(-1, 2)], start=-3)
    T0, T1 = transition_matrices(c)
    assert T0 == sp.Matrix([[R(-1, 2), 0], [R(-1, 2), 2]])
    assert T1 == sp.Matrix([[2, R(-1, 2)], [0, R(-1, 2)]])
    # rho(T_0) = 2 exactly, and ||S_c^L|| >= 2^L: alpha = 3 - log2(JSR) <= 2
    assert T0.eigenvals() == {R(-1, 2): 1, 2: 1}
    assert all(norm_L(c, L) >= 2**L for L in range(1, 6))


TRANSITION_MASKS = {
    "4point": difference_mask(FOUR_POINT_16, 3),
    "6point": difference_mask(SIX_POINT, 5),
    "quintic-k3": difference_mask(bspline(5), 3),
    "random": LaurentSymbol.from_mask([R(3, 7), R(-1, 5), R(2, 3), R(1, 9), R(-4, 11)], start=-2),
    "sqrt6": difference_mask(ALGEBRAIC, 1),
    "single-coeff-3": LaurentSymbol.from_mask([3], start=2),
    "two-coeffs": LaurentSymbol.from_mask([R(1, 3), R(2, 3)], start=0),
}


@pytest.mark.parametrize("c", list(TRANSITION_MASKS.values()), ids=list(TRANSITION_MASKS))
def test_transition_entries_follow_the_convention(c):
    T = transition_matrices(c)
    N = c.end - c.start
    for eps in (0, 1):
        assert T[eps].shape == (max(N, 1), max(N, 1))
        for i, j in itertools.product(range(max(N, 1)), repeat=2):
            assert T[eps][i, j] == c.coeff(c.start + 2 * i - j + eps)


@pytest.mark.parametrize("c", list(TRANSITION_MASKS.values()), ids=list(TRANSITION_MASKS))
def test_products_are_L_step_coefficients(c):
    """(T_e1 ... T_eL)_{ij} = c^[L]_{2^L i - j + sum e_m 2^(L-m)} with c shifted to [0, N]."""
    c0 = c.shift(-c.start)
    T = transition_matrices(c)
    n = T[0].shape[0]
    for L in (1, 2, 3):
        cL = power_symbol(c0, L)
        for word in itertools.product((0, 1), repeat=L):
            P = sp.eye(n)
            for e in word:
                P = P * T[e]
            d = sum(e * 2 ** (L - 1 - m) for m, e in enumerate(word))
            for i, j in itertools.product(range(n), repeat=2):
                assert sp.expand(P[i, j] - cL.coeff(2**L * i - j + d)) == 0


@pytest.mark.parametrize("c", [TRANSITION_MASKS[k] for k in ("4point", "6point", "quintic-k3", "random",
                                                              "sqrt6")],
                         ids=["4point", "6point", "quintic-k3", "random", "sqrt6"])
def test_spectral_radius_below_norm_bound(c):
    """rho(T_eps) <= ||T_eps^L||_1^(1/L) <= ||S_c^L||_inf^(1/L), the last step exactly."""
    T = transition_matrices(c)
    Tf = transition_matrices(c, numeric=True)
    for eps in (0, 1):
        rho = max(abs(np.linalg.eigvals(Tf[eps])))
        for L in range(1, 5):
            TL = T[eps] ** L
            col_norm = max(sum(abs(x) for x in TL.col(j)) for j in range(TL.shape[1]))
            nL = norm_L(c, L)
            assert sp.simplify(nL - col_norm) >= 0          # exact
            assert rho <= float(nL) ** (1 / L) * (1 + 1e-12)


@pytest.mark.parametrize("c", [TRANSITION_MASKS[k] for k in ("4point", "6point", "random", "sqrt6",
                                                              "two-coeffs")],
                         ids=["4point", "6point", "random", "sqrt6", "two-coeffs"])
def test_norm_equals_max_column_norm_of_products(c):
    """||S_c^L||_inf = max over words of length L of ||T_w||_1 (so JSR = lim ||S_c^L||^(1/L)):
    column 0 of T_w, w the binary digits of r, is the whole residue class r mod 2^L."""
    T = transition_matrices(c)
    n = T[0].shape[0]
    for L in (1, 2, 3, 4):
        best = []
        for word in itertools.product((0, 1), repeat=L):
            P = sp.eye(n)
            for e in word:
                P = P * T[e]
            best.append(max(sum(abs(x) for x in P.col(j)) for j in range(n)))
        best_value = max(best, key=lambda v: sp.N(v, 30))
        assert sp.simplify(best_value - norm_L(c, L)) == 0


def test_numeric_flag():
    c = TRANSITION_MASKS["sqrt6"]
    T = transition_matrices(c)
    Tf = transition_matrices(c, numeric=True)
    for eps in (0, 1):
        assert isinstance(Tf[eps], np.ndarray) and Tf[eps].dtype == float
        assert np.allclose(Tf[eps], np.array(T[eps].evalf(), dtype=float), rtol=0, atol=1e-15)


def test_parametric_transition_matrices():
    c = LaurentSymbol.from_mask([-w, 2 * w, R(1, 2)], start=-1)
    T0, T1 = transition_matrices(c)
    assert T0 == sp.Matrix([[-w, 0], [R(1, 2), 2 * w]])
    assert T1 == sp.Matrix([[2 * w, -w], [0, R(1, 2)]])
    with pytest.raises(AnalysisError, match="omega"):
        transition_matrices(c, numeric=True)


@pytest.mark.parametrize("bad", [[1, 2, 3], "1+z", LaurentSymbol.from_mask([0])],
                         ids=["list", "string", "zero"])
def test_transition_bad_input(bad):
    with pytest.raises(AnalysisError):
        transition_matrices(bad)


# --------------------------------------------------------------------------------------------
# 2. local subdivision matrix
# --------------------------------------------------------------------------------------------

WINDOW_MASKS = {k: v[0] for k, v in SCHEMES.items()}
WINDOW_MASKS["shifted-cubic"] = bspline(3).shift(3)
WINDOW_MASKS["asymmetric"] = LaurentSymbol.from_mask([R(1, 3), R(1, 2), R(2, 3), R(1, 2)], start=-1)


def _depends_only_on_window(a: LaurentSymbol, lo: int, hi: int) -> bool:
    """Simulation: changing data outside [lo, hi] leaves new values in [lo, hi] unchanged."""
    s, e = a.start, a.end
    reach = range(min(lo, (lo - e) // 2) - 2, max(hi, (hi - s) // 2) + 3)
    rng = random.Random(lo * 1000 + hi)
    base = {j: R(rng.randint(-9, 9), rng.randint(1, 9)) for j in reach}
    new = refine(a, base)
    for j in reach:
        if lo <= j <= hi:
            continue
        bumped = dict(base)
        bumped[j] = base[j] + 1
        new2 = refine(a, bumped)
        if any(sp.expand(new2.get(i, 0) - new.get(i, 0)) != 0 for i in range(lo, hi + 1)):
            return False
    return True


@pytest.mark.parametrize("a", list(WINDOW_MASKS.values()), ids=list(WINDOW_MASKS))
def test_window_is_invariant_and_minimal(a):
    l, r = invariant_window(a)
    assert (l, r) == (1 - a.end, -a.start - 1)
    assert r - l + 1 == len(a) - 2
    assert _depends_only_on_window(a, l, r)
    if r > l:                                   # minimal: dropping either end breaks invariance
        assert not _depends_only_on_window(a, l + 1, r)
        assert not _depends_only_on_window(a, l, r - 1)
    # windows containing [l, r] are invariant; without zero coefficients they are the only ones
    no_zeros = all(c != 0 for c in a.mask)
    for lo in range(l - 2, r + 2):
        for hi in range(lo, r + 3):
            contains = lo <= l and hi >= r
            if contains or no_zeros:
                assert is_invariant_window(a, (lo, hi)) == contains, (lo, hi)
    # [l, r] are exactly the j whose phi(x - j) (support [s, e]) is nonzero near x = 0
    assert list(range(l, r + 1)) == [j for j in range(-a.end - 3, -a.start + 3) if a.start < -j < a.end]


def test_interpolatory_schemes_have_smaller_invariant_windows():
    """Interior zeros (a_{2j} = 0 for j != 0) make {0} invariant; it does not determine the limit
    near 0, so the local matrix stays on the structural window (1 - e, -s - 1)."""
    for a in (FOUR_POINT_16, SIX_POINT):
        assert is_invariant_window(a, (0, 0))
        assert invariant_window(a) == (1 - a.end, -a.start - 1)
        assert local_subdivision_matrix(a, window=(0, 0))[0] == sp.Matrix([[1]])


@pytest.mark.parametrize("a", list(WINDOW_MASKS.values()), ids=list(WINDOW_MASKS))
def test_local_matrix_is_one_refinement_step(a):
    M, (l, r) = local_subdivision_matrix(a)
    assert M.shape == (r - l + 1, r - l + 1)
    rng = random.Random(7)
    f = {j: R(rng.randint(-9, 9), rng.randint(1, 5)) for j in range(l - len(a), r + len(a))}
    new = refine(a, f)
    lhs = M * sp.Matrix([f[j] for j in range(l, r + 1)])
    assert all(sp.expand(lhs[i - l] - new.get(i, 0)) == 0 for i in range(l, r + 1))


@pytest.mark.parametrize("mask,start,window", [([1, 1], 0, (0, 0)), ([1, 1], 3, (-3, -3)),
                                               ([2], 1, (-1, -1))],
                         ids=["haar", "haar-shifted", "monomial"])
def test_short_masks(mask, start, window):
    a = LaurentSymbol.from_mask(mask, start=start)
    assert invariant_window(a) == window
    assert is_invariant_window(a, window)
    M, win = local_subdivision_matrix(a)
    assert win == window and M == sp.Matrix([[a.coeff(window[0] - 2 * window[0])]])


def test_explicit_window():
    M, win = local_subdivision_matrix(bspline(3), window=(-2, 2))
    assert win == (-2, 2) and M.shape == (5, 5)
    assert M[0, :] == sp.Matrix([[R(1, 8), R(3, 4), R(1, 8), 0, 0]])
    with pytest.raises(AnalysisError, match="not invariant"):
        local_subdivision_matrix(bspline(3), window=(0, 1))
    with pytest.raises(AnalysisError, match="empty"):
        local_subdivision_matrix(bspline(3), window=(1, 0))


# --------------------------------------------------------------------------------------------
# 3. eigenvalues
# --------------------------------------------------------------------------------------------

def test_cubic_bspline_eigenvalues():
    r = local_eigenvalues(bspline(3))
    assert isinstance(r, Result) and r.status == CERTIFIED
    assert r.witness["window"] == (-1, 1)
    assert r.value == {1: 1, R(1, 2): 1, R(1, 4): 1}
    # the 5-point window (-2, 2) adds the double eigenvalue 1/8
    r5 = local_eigenvalues(bspline(3), window=(-2, 2))
    assert r5.value == {1: 1, R(1, 2): 1, R(1, 4): 1, R(1, 8): 2}


@pytest.mark.parametrize("a,k", list(SCHEMES.values()), ids=list(SCHEMES))
def test_spectrum_contains_powers_of_one_half(a, k):
    """(1+z)^k | a: polynomials of degree < k are invariant, giving 2^-d, d < min(k, size)."""
    r = local_eigenvalues(a)
    l, rr = r.witness["window"]
    for d in range(min(k, rr - l + 1)):
        assert r.value.get(R(1, 2**d), 0) >= 1, d


@pytest.mark.parametrize("a", [v[0] for v in SCHEMES.values()], ids=list(SCHEMES))
def test_eigenvalues_match_independent_charpoly(a):
    r = local_eigenvalues(a)
    M, win = local_subdivision_matrix(a)
    assert r.witness["window"] == win and r.witness["matrix"] == M
    independent = M.charpoly(LAMBDA).as_expr()            # Matrix.charpoly: another algorithm
    assert sp.simplify(sp.expand(r.witness["charpoly"] - independent)) == 0
    assert r.provenance["complete"]
    assert sum(r.value.values()) == M.shape[0]
    product = sp.Mul(*[(LAMBDA - lam) ** m for lam, m in r.value.items()])
    assert sp.simplify(sp.expand(product - independent)) == 0


def test_numeric_irreducible_cubic_gives_exact_roots():
    a = LaurentSymbol.from_mask([R(1, 3), R(1, 5), R(1, 2), R(2, 7), R(1, 9)], start=-2)  # 3x3
    r = local_eigenvalues(a)
    M, _ = local_subdivision_matrix(a)
    cp = M.charpoly(LAMBDA)
    assert len(r.witness["factors"]) == 1 and sp.degree(r.witness["factors"][0][0], LAMBDA) == 3
    assert sum(r.value.values()) == 3
    expected = set(sp.Poly(cp.as_expr(), LAMBDA).all_roots())     # CRootOf is canonical
    assert set(r.value) == expected and all(isinstance(x, sp.CRootOf) for x in r.value)


def test_seed004_37_eigenvalues():
    """Sub-scheme (3.7): our minimal window is (-2, 3), the same 6x6 matrix as the paper's T."""
    r = local_eigenvalues(S37)
    assert r.witness["window"] == (-2, 3)
    M = r.witness["matrix"]
    independent = sp.roots(M.charpoly(LAMBDA).as_expr(), LAMBDA)
    assert r.value == independent
    assert r.value == {1: 1, R(1, 2): 1, R(1, 4): 1, R(1, 8): 1, R(1, 16): 1, R(9, 64) - 7 * nu / 64: 1}


def test_seed004_38_eigenvalues():
    """Sub-scheme (3.8): minimal window (-4, 5), the 10x10 matrix printed in the paper."""
    r = local_eigenvalues(S38)
    assert r.witness["window"] == (-4, 5)
    M = r.witness["matrix"]
    independent = sp.roots(M.charpoly(LAMBDA).as_expr(), LAMBDA)
    assert {sp.expand(k): v for k, v in r.value.items()} == {sp.expand(k): v for k, v in independent.items()}
    root = sp.sqrt(833 * mu**2 + 70 * mu + 1) / 128
    assert r.value == {1: 1, R(1, 2): 1, R(1, 4): 1, R(1, 8): 1, R(1, 16): 1, R(1, 32): 1, R(1, 64): 1,
                       -7 * mu / 32: 1, 7 * mu / 128 + R(1, 128) + root: 1, 7 * mu / 128 + R(1, 128) - root: 1}


def _paper_layout_matrix(a: LaurentSymbol, rows_i: range, cols: range) -> sp.Matrix:
    """Rows P_{2i}, P_{2i+1} for i in rows_i from the paper-style stencils (a.rules())."""
    rules = a.rules()
    rows = []
    for i in rows_i:
        for stencil, first in ((rules.even, rules.even_first), (rules.odd, rules.odd_first)):
            row = {i + first + k: c for k, c in enumerate(stencil)}
            rows.append([row.get(j, 0) for j in cols])
    return sp.Matrix(rows)


@pytest.mark.parametrize("a,rows_i,cols", [(S37, range(-1, 2), range(-2, 4)),
                                           (S38, range(-2, 3), range(-4, 6))],
                         ids=["3.7-6x6", "3.8-10x10"])
def test_paper_matrix_layout_is_ours(a, rows_i, cols):
    """The paper's matrices (rows from i = -1..1 resp. -2..2) are our local matrices."""
    M, (l, r) = local_subdivision_matrix(a)
    assert (l, r) == (cols[0], cols[-1])
    assert _paper_layout_matrix(a, rows_i, cols) == M


def test_seed004_38_at_mu_zero_has_double_1_64():
    """At mu = 0 ((3.8) becomes a degree-6 B-spline) 1/64 becomes double and 0 appears."""
    r = local_eigenvalues(S38.subs({mu: 0}), window=(-4, 5))
    assert r.value == {1: 1, R(1, 2): 1, R(1, 4): 1, R(1, 8): 1, R(1, 16): 1, R(1, 32): 1, R(1, 64): 2,
                       0: 2}


def test_two_parameter_mask():
    a = LaurentSymbol.from_mask([-w, t, R(1, 2) + w, 1 - 2 * t, R(1, 2) + w, t, -w], start=-3)
    r = local_eigenvalues(a)
    M, _ = local_subdivision_matrix(a)
    assert sp.expand(r.witness["charpoly"] - M.charpoly(LAMBDA).as_expr()) == 0
    assert sum(r.value.values()) + sum(m * sp.degree(f, LAMBDA)
                                       for f, m in r.witness.get("implicit", ())) == 5


# --------------------------------------------------------------------------------------------
# 4. support of the basic limit function
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("a", [bspline(1), bspline(3), CHAIKIN, FOUR_POINT_16, SIX_POINT, ALGEBRAIC],
                         ids=["linear", "cubic", "chaikin", "4point", "6point", "sqrt6"])
def test_support_matches_iterated_refinement(a):
    r = basic_limit_support(a)
    s, e = r.value
    assert r.status == CERTIFIED and r.witness["width"] == e - s == len(a) - 1
    f = {0: sp.Integer(1)}
    for n in range(1, 5):
        f = refine(a, f)
        nz = [i for i, v in f.items() if sp.expand(v) != 0]
        assert (min(nz), max(nz)) == ((2**n - 1) * s, (2**n - 1) * e)


@pytest.mark.parametrize("a,support,centred,exceptional", [
    (S37, (-4, 3), (R(-7, 2), R(7, 2)), {R(5, 7): (-3, 2)}),
    (S38, (-6, 5), (R(-11, 2), R(11, 2)), {0: (-4, 3)}),
    (FOUR_POINT, (-3, 3), (-3, 3), {0: (-1, 1)}),
], ids=["seed004-3.7", "seed004-3.8", "4point"])
def test_parametric_support(a, support, centred, exceptional):
    r = basic_limit_support(a)
    assert r.value == support
    assert r.witness["centred"] == centred
    assert r.witness["width"] == support[1] - support[0]
    assert r.witness["exceptional"] == exceptional


def test_support_irrational_exceptional_values():
    a = LaurentSymbol.from_mask([t**2 - 2, 1, 1, 1 - t], start=-1)
    r = basic_limit_support(a)
    assert r.value == (-1, 2)
    assert r.witness["exceptional"] == {-sp.sqrt(2): (0, 2), 1: (-1, 1), sp.sqrt(2): (0, 2)}


def test_support_several_parameters_gives_conditions():
    a = LaurentSymbol.from_mask([w - t, 1, 1, w + t], start=-2)
    r = basic_limit_support(a)
    assert r.value == (-2, 1)
    assert r.witness["conditions"] == {"left": sp.Eq(w - t, 0), "right": sp.Eq(w + t, 0)}
    assert "exceptional" not in r.witness


@pytest.mark.parametrize("fn", [local_eigenvalues, basic_limit_support], ids=["eigen", "support"])
def test_results_serialise(fn):
    import json

    out = json.loads(json.dumps(fn(S38).to_json()))
    assert out["status"] == "certified"

