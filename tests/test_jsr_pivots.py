"""The polytope's pivoted QR in numpy (analysis/jsr/_pivots.py) picks LAPACK's pivots.

``qr_pivots`` must return the column order of ``scipy.linalg.qr(A, pivoting=True)`` (LAPACK ``dgeqp3``):
the invariant polytope's basis of vertices, and so its vertices, certificate and printed bounds, were
computed with those. Compared on generic matrices, small-integer matrices with many exactly tied
column norms, unit columns next to generic ones (the polytope's interior fillers), and a vertex matrix
of a Daubechies polytope; large, wide and complex matrices take SciPy's route.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from analysis.jsr._pivots import UNBLOCKED, WIDTH, _dlaqp2, qr_pivots


def lapack(A):
    return scipy.linalg.qr(A, pivoting=True, mode="economic")[2]


def numpy_pivots(A):
    """The numpy algorithm itself, whatever the shape (qr_pivots hands wide matrices to LAPACK)."""
    return _dlaqp2(np.array(A, dtype=float, order="F"))


def _cases():
    rng = np.random.default_rng(20261127)
    out = []
    for t in range(40):
        n, m = int(rng.integers(1, 20)), int(rng.integers(1, 60))
        out.append((f"gaussian-{n}x{m}", rng.standard_normal((n, m))))
    for t in range(40):
        n, m = int(rng.integers(1, 20)), int(rng.integers(1, 60))
        out.append((f"integers-{n}x{m}", rng.integers(-3, 4, size=(n, m)).astype(float)))
    for t in range(20):
        n, m = int(rng.integers(2, 17)), int(rng.integers(2, 40))
        out.append((f"fillers-{n}x{m}", np.concatenate([0.5 * np.eye(n), rng.standard_normal((n, m))], axis=1)))
    out.append(("full-width", rng.standard_normal((UNBLOCKED, 3 * UNBLOCKED))))
    return out


@pytest.mark.parametrize("A", [c[1] for c in _cases()], ids=[c[0] for c in _cases()])
def test_pivots_are_lapacks(A):
    assert numpy_pivots(A).tolist() == lapack(A).tolist()
    assert qr_pivots(A).tolist() == lapack(A).tolist()


def test_pivots_of_a_daubechies_polytope():
    """The vertex matrices of the D12 polytope, as the JSR engine builds them (every refresh)."""
    import analysis.jsr._polytope as P
    import schemes
    from analysis.regularity import holder_exponent

    seen = []
    real = P.qr_pivots

    def spy(A):
        seen.append((np.array(A), real(A)))
        return seen[-1][1]

    P.qr_pivots = spy
    try:
        holder_exponent(schemes.get("daubechies-12"))
    finally:
        P.qr_pivots = real
    assert len(seen) > 5 and any(A.shape[1] <= WIDTH * A.shape[0] for A, _ in seen)
    for A, piv in seen:
        assert piv.tolist() == lapack(A).tolist()
        assert numpy_pivots(A).tolist() == lapack(A).tolist()


def test_large_wide_and_complex_matrices_go_to_scipy():
    rng = np.random.default_rng(1)
    A = rng.standard_normal((UNBLOCKED + 1, UNBLOCKED + 5))
    assert qr_pivots(A).tolist() == lapack(A).tolist()
    W = rng.standard_normal((3, 3 * WIDTH + 1))
    assert qr_pivots(W).tolist() == lapack(W).tolist()
    Z = rng.standard_normal((4, 9)) + 1j * rng.standard_normal((4, 9))
    assert qr_pivots(Z).tolist() == lapack(Z).tolist()
