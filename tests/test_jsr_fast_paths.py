"""Fast paths of the JSR engine give what the reference paths give: the membership LPs (analysis.jsr._lp), the
polytope's cached data and the strongly connected components of the block-triangular reduction.

For the LPs the reference is ``scipy.optimize.linprog(method="highs")``: :func:`small_lp` must return the very
same numbers (it passes the same model to the same HiGHS), so that polytopes and certificates do
not move; the warm-started model (another HiGHS build) must reach the same optimal value.
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.jsr._lp import WarmLP, _linprog_lp, small_lp
from analysis.jsr._polytope import PolytopeState, _Member


def _problems():
    rng = np.random.default_rng(7)
    out = []
    for t in range(24):
        n, m = (3, 7) if t % 2 else (6, 20)
        V = rng.integers(-3, 4, size=(n, m)).astype(float) / 4     # ties and zeros: degenerate LPs
        x = V @ rng.standard_normal(m) * (0.2 + t % 3)
        if t % 6 == 0:
            V[0, :] = 0.0                                           # x outside the span: infeasible
        out.append((V, x))
    return out


@pytest.mark.parametrize("case", range(24))
def test_small_lp_is_linprog_bit_for_bit(case):
    V, x = _problems()[case]
    ours, ref = small_lp(V, x), _linprog_lp(V, x)
    assert (ours is None) == (ref is None)
    if ref is not None:
        assert ours[0] == ref[0]
        assert np.array_equal(ours[1], ref[1]) and np.array_equal(ours[2], ref[2])


def test_small_lp_reuses_its_highs_object_without_carrying_state():
    """:func:`small_lp` solves every problem on one HiGHS object per thread: a sequence of problems of
    different sizes, infeasible ones among them, solved twice in different orders, gives each time exactly
    what a fresh object (``linprog``) gives."""
    probs = _problems()
    refs = [_linprog_lp(V, x) for V, x in probs]
    for order in (range(len(probs)), reversed(range(len(probs)))):
        for i in order:
            got, ref = small_lp(*probs[i]), refs[i]
            assert (got is None) == (ref is None)
            if ref is not None:
                assert got[0] == ref[0] and np.array_equal(got[1], ref[1]) and np.array_equal(got[2], ref[2])


def test_lstsq_solution_is_numpy_lstsq_bit_for_bit():
    """The polish and strip least-squares solves call numpy's lstsq ufunc directly: the same solutions, for
    full-rank, rank-deficient, nearly rank-deficient (decided by rcond), square, wide and tall systems."""
    from analysis.jsr._lsq import lstsq_solution

    rng = np.random.default_rng(5)
    for t in range(60):
        m, n = int(rng.integers(1, 9)), int(rng.integers(1, 12))
        A = rng.standard_normal((m, n)) * 10.0 ** int(rng.integers(-6, 7))
        if t % 4 == 0 and n > 1:
            A[:, -1] = A[:, 0] * 3.0                                 # rank deficient
        if t % 4 == 1 and n > 1:                                     # nearly: decided by rcond
            A[:, -1] = A[:, 0] * 3.0 + 1e-11 * np.abs(A).max() * rng.standard_normal(m)
        b = rng.standard_normal(m)
        assert np.array_equal(lstsq_solution(A, b), np.linalg.lstsq(A, b, rcond=None)[0])


def test_small_lp_values():
    """The optimum is the Minkowski norm: a vertex has norm 1, the origin 0, twice a vertex 2."""
    V = np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 1.0]])
    assert small_lp(V, np.array([1.0, 1.0]))[0] == 1.0
    assert small_lp(V, np.zeros(2))[0] == 0.0
    assert small_lp(V, np.array([0.0, -2.0]))[0] == 2.0
    assert small_lp(V[:1, :1], np.array([0.0]))[0] == 0.0
    assert small_lp(np.array([[1.0], [0.0]]), np.array([0.0, 1.0])) is None   # not in the span


def test_warm_lp_reaches_the_linprog_optimum_while_vertices_are_added():
    rng = np.random.default_rng(3)
    n = 5
    V = rng.standard_normal((n, 40))
    w = WarmLP.create(n)
    for m in (5, 12, 25, 40):
        w.sync(list(V[:, :m].T))
        for _ in range(4):
            x = rng.standard_normal(n)
            got, ref = w.solve(x), _linprog_lp(V[:, :m], x)
            assert (got is None) == (ref is None)
            if ref is not None:
                assert got[0] == pytest.approx(ref[0], rel=1e-8)
                assert np.allclose(V[:, :m] @ got[1], x, atol=1e-8)


def test_member_matrix_is_the_vertex_matrix_with_its_layout():
    """The growing buffer gives st.matrix() exactly: values, shape and strides (so that every
    numpy/BLAS operation on it rounds as before)."""
    rng = np.random.default_rng(1)
    st = PolytopeState(4, 2)
    mem = _Member(st)
    for m in range(1, 40):
        st.V.append(rng.standard_normal(4))
        if m % 3 == 0 or m < 5:
            a, b = mem.matrix(), st.matrix()
            assert a.shape == b.shape and a.strides == b.strides and np.array_equal(a, b)


def test_member_basis_as_recomputed_from_scratch():
    """After each added vertex the basis (pivoted-QR pick, inverse) and the largest length equal
    those of a fresh oracle built on the same vertices."""
    rng = np.random.default_rng(2)
    st = PolytopeState(3, 2)
    mem = _Member(st)
    for _ in range(12):
        st.V.append(rng.standard_normal(3))
        mem.refresh()
        fresh = _Member(st)
        fresh.refresh()
        assert mem._r2 == fresh._r2
        assert (mem._basis is None) == (fresh._basis is None)
        if fresh._basis is not None:
            assert np.array_equal(mem._basis[0], fresh._basis[0])
            assert np.array_equal(mem._basis[1], fresh._basis[1])


def test_strong_components_in_the_order_of_scipy():
    """The block-triangular reduction lists its blocks in the order of SciPy's labels (the budget
    is split in that order), now without importing scipy.sparse."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    from analysis.jsr._subspace import strong_components

    rng = np.random.default_rng(0)
    for t in range(300):
        n = int(rng.integers(1, 16))
        adj = rng.random((n, n)) < (0.04, 0.1, 0.2, 0.4)[t % 4]
        np.fill_diagonal(adj, False)
        nc, labels = connected_components(csr_matrix(adj.astype(int)), directed=True, connection="strong")
        ref = [sorted(np.nonzero(labels == c)[0].tolist()) for c in range(nc)]
        assert strong_components([[b for b in reversed(range(n)) if adj[a, b]] for a in range(n)]) == ref
