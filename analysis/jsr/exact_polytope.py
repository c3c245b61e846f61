"""The invariant polytope with **exact** vertices: ``||A_i / r||_P <= 1`` proven in rational arithmetic, so that
``JSR <= r`` holds exactly (not ``r (1 + 1e-13)``) when the roots are exact eigenvectors.

The float phase (:func:`analysis.jsr._polytope.build_polytope`) gives the vertex words: vertex ``j`` is
``v_j = B_{w_L} ... B_{w_1} u_{root(j)}`` with ``B_i = A_i / r`` and ``u`` the roots. Here every vertex is
recomputed exactly from its word (rational matrices, rational roots), and for every vertex ``j`` and matrix
``i`` the image ``x = B_i v_j`` is bounded in the Minkowski norm of ``P = absconv{v_j}``:

* ``x = +-v_k`` exactly (the cycle of a root, or an image that is a vertex): ``||x||_P <= 1``;
* else the support ``S`` of the float linear program ``min ||c||_1, V c = x`` is taken and ``V_S c = x``
  solved exactly: when it is consistent, ``||x||_P <= ||c||_1`` (exact);
* otherwise ``c`` is the float solution rounded to a rational and ``||x||_P <= ||c||_1 + ||G^{-1}(x - V_S
  c)||_1`` with ``G`` a basis of vertices (exact inverse).

The largest bound ``c*`` gives ``||B_i||_P <= c*`` for every ``i``, hence ``JSR(A) <= r c*`` (exact). An image
on the boundary of ``P`` other than a cycle (a second spectrum-maximising product) gives ``c* = 1`` exactly
only when its exact solve is consistent; images with slack give ``c* < 1`` for them.

Examples
--------
Two matrices with the common leading eigenvalue 1 (eigenvectors ``(1, 0)`` and ``(0, 1)``):

>>> from flint import fmpq, fmpq_mat
>>> from analysis.jsr._polytope import build_polytope
>>> from analysis.jsr._work import Work
>>> A = [fmpq_mat([[1, fmpq(1, 4)], [0, fmpq(1, 2)]]), fmpq_mat([[fmpq(1, 2), 0], [fmpq(1, 4), 1]])]
>>> roots = [[fmpq(1), fmpq(0)], [fmpq(0), fmpq(1)]]
>>> st = build_polytope(floats(A), 1.0, [[float(x) for x in u] for u in roots], work=Work(1000))
>>> st.closed
True
>>> b = exact_polytope_bound(A, fmpq(1), roots, st)
>>> str(b["bound"]), b["exact_solves"] + b["vertex_images"] + b["residual_bounds"] == 2 * len(st.V)
('1', True)

References
----------
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear operators*, Found.
Comput. Math. 13 (2013) 37-97.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Sequence

import numpy as np
from flint import fmpq, fmpq_mat

from ._pivots import qr_pivots

__all__ = ["exact_polytope_bound", "floats", "MAX_SUBSETS", "MAX_NEW_VERTICES"]

#: the most independent subsets of a support tried by the exact solve of a dependent support
MAX_SUBSETS = 50
#: the most images added as vertices by the exact closure
MAX_NEW_VERTICES = 400
#: an image whose bound exceeds 1 by at most this becomes a vertex (the float tolerance of the polytope is
#: 1e-11; a larger excess is a genuine one and is reported)
CLOSURE_EXCESS = Fraction(1, 10 ** 9)


def floats(mats: Sequence[fmpq_mat]) -> list[np.ndarray]:
    """The float matrices of exact ``fmpq_mat``."""
    return [np.array([[float(M[a, b]) for b in range(M.ncols())] for a in range(M.nrows())]) for M in mats]


def _fr(x: fmpq) -> Fraction:
    return Fraction(int(x.p), int(x.q))


def _col(v: list[fmpq]) -> fmpq_mat:
    return fmpq_mat(len(v), 1, v)


def _solve_cols(cols: list[fmpq_mat], x: fmpq_mat):
    """``(rank of cols, c)`` with ``sum c_k cols_k = x`` exactly when the columns are independent; ``c`` None when
    inconsistent or dependent."""
    n, s = x.nrows(), len(cols)
    M = fmpq_mat(n, s + 1, [cols[k][a, 0] if k < s else x[a, 0] for a in range(n) for k in range(s + 1)])
    R, rank = M.rref()
    piv = [next(j for j in range(s + 1) if R[i, j] != 0) for i in range(rank)]
    if s in piv:
        return rank, None, False
    return rank, ([R[i, s] for i in range(s)] if len(piv) == s else None), True


def _exact_solve(cols: list[fmpq_mat], x: fmpq_mat, lam=None, max_subsets: int = MAX_SUBSETS):
    """An exact solution of ``sum c_k cols_k = x`` supported on independent columns, as ``(positions, c)``: the
    unique one when the columns are independent; else the columns taken greedily by decreasing float coefficient
    ``|lam_k|`` while they stay independent (one exact solve), and when that is inconsistent the least ``||c||_1``
    over at most ``max_subsets`` independent subsets (the basic solutions of the restricted linear program
    contain an optimum). None when ``x`` is not in their span."""
    from itertools import combinations

    rank, c, consistent = _solve_cols(cols, x)
    if not consistent:
        return None
    if c is not None:
        return list(range(len(cols))), c
    if lam is not None:
        n = x.nrows()
        F = np.array([[float(col[a, 0]) for a in range(n)] for col in cols]).T
        chosen: list[int] = []
        for k in np.argsort(-np.abs(np.asarray(lam, dtype=float)), kind="stable"):
            if np.linalg.matrix_rank(F[:, chosen + [int(k)]]) > len(chosen):
                chosen.append(int(k))
            if len(chosen) == rank:
                break
        _, c2, _ = _solve_cols([cols[j] for j in chosen], x)
        if c2 is not None:
            return chosen, c2
    best = None
    for k, sub in enumerate(combinations(range(len(cols)), rank)):
        if k >= max_subsets:
            break
        _, c2, _ = _solve_cols([cols[j] for j in sub], x)
        if c2 is None:
            continue
        norm = sum((abs(_fr(y)) for y in c2), Fraction(0))
        if best is None or norm < best[2]:
            best = (list(sub), c2, norm)
    return None if best is None else best[:2]


def exact_polytope_bound(mats: Sequence[fmpq_mat], r: fmpq, roots: Sequence[Sequence[fmpq]], st,
                         coef_bits: int = 60, max_new: int = MAX_NEW_VERTICES) -> dict:
    """``{"bound": c*, ...}`` with ``||A_i / r||_P <= c*`` for every ``i`` (exact ``Fraction``; see the module
    docstring), ``P`` the absolutely convex hull of the exact vertices of the float polytope ``st`` and of at most
    ``max_new`` further images (an image whose bound exceeds 1 by at most ``CLOSURE_EXCESS`` becomes a vertex, exactly, and its images are
    bounded in turn: the float polytope accepts images up to ``1 + 1e-11``); ``None`` as bound when the vertices
    do not span. Counts: ``vertex_images``, ``exact_solves``, ``residual_bounds``, ``added_vertices``;
    ``worst``: ``(i, j)`` of the largest bound. The closure is limited by size (``max_new`` vertices, each with
    one small LP and at most ``MAX_SUBSETS`` exact solves per image), not by the caller's work budget."""
    from .parametric import _l1_coefficients

    n = mats[0].nrows()
    B = [M * (1 / r) for M in mats]
    base = [_col(list(u)) for u in roots]
    V: list[fmpq_mat] = []
    by_path: dict = {}
    for ro, path in zip(st.root_of, st.path):
        if ro >= len(base):
            return {"bound": None, "reason": "the float polytope added complement roots (a further invariant subspace)"}
        x = base[ro]
        for k, i in enumerate(path):
            key = (ro, path[: k + 1])
            if key in by_path:
                x = by_path[key]
                continue
            x = B[i] * x
            by_path[key] = x
        V.append(x)
    Vf = np.array([[float(v[a, 0]) for a in range(n)] for v in V]).T
    if np.linalg.matrix_rank(Vf) < n:
        return {"bound": None, "reason": "the vertices do not span the space"}
    piv = [int(p) for p in qr_pivots(Vf)[:n]]
    G = fmpq_mat(n, n, [V[j][a, 0] for a in range(n) for j in piv])
    try:
        Gi = G.inv()
    except ZeroDivisionError:
        return {"bound": None, "reason": "the basis of vertices is singular"}
    index = {}

    def register(k, v):
        index[tuple(v[a, 0] for a in range(n))] = k
        index[tuple(-v[a, 0] for a in range(n))] = k

    for k, v in enumerate(V):
        register(k, v)
    counts = {"vertex_images": 0, "exact_solves": 0, "residual_bounds": 0, "added_vertices": 0}
    scale = 2 ** coef_bits

    def bound(x, rep):
        if tuple(x[a, 0] for a in range(n)) in index:
            counts["vertex_images"] += 1
            return Fraction(1)
        if rep is None:
            lp = _l1_coefficients(Vf, np.array([float(x[a, 0]) for a in range(n)]))
            if lp is None:
                return None
            rep = lp
        supp, lam = [int(s) for s in rep[0]], rep[1]
        sol = _exact_solve([V[s] for s in supp], x, lam) if supp else None
        if sol is not None:
            counts["exact_solves"] += 1
            return sum((abs(_fr(y)) for y in sol[1]), Fraction(0))
        cq = [fmpq(int(round(float(y) * scale)), scale) for y in lam]
        res = x
        for s_, y in zip(supp, cq):
            res = res - V[s_] * y
        g = Gi * res
        counts["residual_bounds"] += 1
        return sum((abs(_fr(y)) for y in cq), Fraction(0)) + sum((abs(_fr(g[a, 0])) for a in range(n)), Fraction(0))

    bounds: dict = {}
    todo = [(i, j) for j in range(len(V)) for i in range(len(B))]
    while todo:
        outside = []
        for i, j in todo:
            x = B[i] * V[j]
            b = bound(x, st.reps.get((i, j)) if j < len(st.V) else None)
            bounds[(i, j)] = b
            if b is not None and 1 < b <= 1 + CLOSURE_EXCESS:
                outside.append((i, j, x))
        todo = []
        for i, j, x in outside:
            if tuple(x[a, 0] for a in range(n)) in index:       # added meanwhile
                bounds[(i, j)] = Fraction(1)
                continue
            if counts["added_vertices"] >= max_new:
                break
            counts["added_vertices"] += 1
            V.append(x)
            register(len(V) - 1, x)
            bounds[(i, j)] = Fraction(1)
            todo += [(i2, len(V) - 1) for i2 in range(len(B))]
        if outside:
            Vf = np.array([[float(v[a, 0]) for a in range(n)] for v in V]).T
    if any(b is None for b in bounds.values()):
        return {"bound": None, "reason": "a linear program of the exact closure failed", **counts}
    worst = max(bounds, key=lambda key: bounds[key])
    return {"bound": bounds[worst], "worst": worst, "vertices": len(V), **counts}
