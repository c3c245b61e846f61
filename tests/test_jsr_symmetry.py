"""Exact cyclic conjugation symmetries of a family (``G A_c(j) G^-1 = A_c(j+1)``) and the reduced family
``B_d = A_c0 G^d`` with the same joint spectral radius."""

from __future__ import annotations

import numpy as np
from flint import fmpq, fmpq_mat

from analysis.jsr import jsr_bounds
from analysis.jsr._polytope import rotation_order
from analysis.jsr._symmetry import MIN_N, a_word, cyclic_symmetry, reduced_family


def _identity(n: int) -> fmpq_mat:
    eye = fmpq_mat(n, n)
    for a in range(n):
        eye[a, a] = 1
    return eye


def _rotating_family():
    """``A_j = G^j A_0 G^-j`` with ``G`` a non-orthogonal similar copy of the shift by 3 (order 3) and
    ``A_0 G = R`` a rotation by 90 degrees on a plane plus a contraction: the best products are
    ``A_0 A_1 A_2 = R^3 G^-3`` and its shifts (length 3, leading eigenvalues ``+-i``)."""
    n = 9
    P, D, R = fmpq_mat(n, n), fmpq_mat(n, n), fmpq_mat(n, n)
    for a in range(n):
        P[(a + 3) % n, a] = 1
        D[a, a] = 2 ** (a % 4)
    R[0, 1], R[1, 0] = -1, 1
    for a in range(2, n - 1):
        R[a, a + 1], R[a, 0] = fmpq(1, 4), fmpq(1, 8)
    G = D * P * D.inv()
    Gi = G.inv()
    A0 = R * Gi
    return [A0, G * A0 * Gi, G * G * A0 * Gi * Gi]


def test_the_symmetry_is_found_and_checked_exactly():
    A = _rotating_family()
    cycle, G = cyclic_symmetry(A)
    assert cycle == [0, 1, 2]
    for j in range(3):
        assert G * A[cycle[j]] == A[cycle[(j + 1) % 3]] * G
    assert G * G * G == _identity(9)
    B = reduced_family(A, cycle, G)
    assert B[0] == A[0] and B[2] == A[0] * G * G
    # the A word of B_1 is that of B_1^3 = T_0 T_1 T_2; B_1 B_2 = T_0 T_1 G^3
    assert a_word((1,), cycle) == (0, 1, 2) and a_word((1, 2), cycle) == (0, 1)
    # the engine searches only from MIN_N dimensions on
    small = [fmpq_mat([[2, 1], [0, 1]]), fmpq_mat([[1, 0], [1, 2]])]   # swapped by (x, y) -> (y, x)
    assert MIN_N > 2 and cyclic_symmetry(small) is None
    assert cyclic_symmetry(small, min_n=2) is not None


def test_the_reduced_family_gives_the_jsr():
    r = jsr_bounds(_rotating_family(), budget=5000)
    assert r.status == "certified" and r.lower == 1 and r.upper - 1 < 1e-12
    assert r.provenance["method"].startswith("cyclic conjugation symmetry")
    sym = r.witness["cyclic_symmetry"]
    assert sym["cycle"] == [0, 1, 2] and sym["reduced_product"] == (1,)
    assert r.witness["product"] == (0, 1, 2)
    assert "reduced family" in r.witness["polytope_coordinates"]
    # the witness word is a product of the input matrices with the certified spectral radius
    P = np.eye(9)
    for i in r.witness["product"]:
        P = P @ np.array(_rotating_family()[i].tolist(), dtype=float)
    assert abs(max(abs(np.linalg.eigvals(P))) - 1) < 1e-12
    # without the structural reductions: the polytope of the A's
    r2 = jsr_bounds(_rotating_family(), budget=5000, method="polytope")
    assert "cyclic" not in r2.provenance["method"]


def test_no_symmetry_when_the_spectra_differ_or_the_reduced_family_does_not_split():
    A = [fmpq_mat([[1, 1], [0, 1]]), fmpq_mat([[1, 0], [1, 2]])]
    assert cyclic_symmetry(A, min_n=2) is None              # different characteristic polynomials
    # T_1 = J T_0 J (a symmetric mask): a symmetry, but {T_0, T_0 J} does not split: not used
    n = 8
    T0, J = fmpq_mat(n, n), fmpq_mat(n, n)
    for a in range(n):
        J[a, n - 1 - a] = 1
        T0[a, a] = fmpq(1, 2)
        if a + 1 < n:
            T0[a, a + 1], T0[a + 1, a] = fmpq(1, 4), fmpq(1, 8 + a)
    fam = [T0, J * T0 * J]
    assert cyclic_symmetry(fam) is not None
    r = jsr_bounds(fam, budget=300)
    assert "cyclic" not in r.provenance["method"]


def test_rotation_order():
    rot = np.array([[0.0, -1.0], [1.0, 0.0]])
    assert rotation_order([rot], (0,)) == 4
    assert rotation_order([np.diag([2.0, -1.0])], (0,)) == 1
    c, s = 3 / 5, 4 / 5                                     # an irrational angle
    assert rotation_order([np.array([[c, -s], [s, c]])], (0,)) is None
