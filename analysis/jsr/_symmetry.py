"""Exact cyclic conjugation symmetries of a rational family, and the reduced family they give.

If an invertible ``G`` permutes the family cyclically by conjugation,

    G A_{c_j} G^{-1} = A_{c_{j+1}}    (j mod k; c_0, ..., c_{k-1} an ordering of the k matrices),

and ``G^k = I`` (after scaling ``G`` by a rational ``k``-th root of the scalar ``G^k``), write
``T_j = A_{c_j} = G^j T_0 G^{-j}``. Then every product of the ``A``'s is

    T_{e_1} T_{e_2} ... T_{e_L} = G^{e_1} B_{d_1} B_{d_2} ... B_{d_{L-1}} T_0 G^{-e_L},
    B_d = T_0 G^d  (d = 0, ..., k - 1),  d_t = e_{t+1} - e_t mod k,

and conversely ``B_{d_1} ... B_{d_L} = T_{s_0} T_{s_1} ... T_{s_{L-1}} G^{s_L}`` with the partial sums
``s_t = d_1 + ... + d_t`` (``s_0 = 0``). Since the powers of ``G`` are bounded, both families have the
same joint spectral radius: ``JSR(A) = JSR(B)``, exactly. The reduced family can be much easier: a
spectrum-maximising product ``T_0 T_1 ... T_{k-1}`` of the ``A``'s is ``B_1^k``, a product of length
one, and the ``B``'s may share invariant subspaces that the ``A``'s do not have (the regular part of
Kobbelt's sqrt 3 scheme: the rotation by 120 degrees maps each digit's transition operator to the
next; on ``V_3`` the ``A``'s have no rational invariant subspace of dimension below 19, the ``B``'s
split into blocks of sizes 1, 13 and 5, and the invariant polytope of the 13-dimensional block
closes).

A ``B`` word ``w = (d_1, ..., d_L)`` is the ``A`` word of its ``m``-th power (``m`` the least with
``m (d_1 + ... + d_L) = 0 mod k``): ``rho(B_w)^m = rho(T_{s_0} ... T_{s_{mL-1}})`` (:func:`a_word`).

Examples
--------
Conjugation by the coordinate permutation ``(x, y) -> (y, x)`` swaps ``A_0`` and ``A_1``:

>>> from flint import fmpq_mat
>>> A = [fmpq_mat([[2, 1], [0, 1]]), fmpq_mat([[1, 0], [1, 2]])]
>>> cycle, G = cyclic_symmetry(A, min_n=2)      # (the engine searches from MIN_N = 8 on)
>>> cycle, str(G)
([0, 1], '[0, 1]\\n[1, 0]')
>>> B = reduced_family(A, cycle, G)
>>> [str(M) for M in B]
['[2, 1]\\n[0, 1]', '[1, 2]\\n[1, 0]']
>>> a_word((1,), cycle)
(0, 1)

References
----------
N. Guglielmi, V. Yu. Protasov, *Invariant polytopes of linear operators with applications to
regularity of wavelets and of subdivisions*, SIAM J. Matrix Anal. Appl. 37 (2016) 18-52 (symmetries
of the transition operators).
R. Jungers, *The joint spectral radius: theory and applications*, LNCIS 385, Springer 2009, Sect. 1.2.
"""

from __future__ import annotations

import itertools
from typing import Any, Callable, Sequence

import numpy as np
from flint import fmpq, fmpq_mat

from ._bounds import _Bounds, _lower_from_word
from ._exact import Family
from ._norms import arithmetic_of
from ._subspace import _kernel, invariant_subspace

#: families of more matrices than this are not searched (the cycles tried grow as (k - 1)!)
MAX_K = 4
#: nor matrices larger than this (the linear system for G has n^2 unknowns)
MAX_N = 24
#: nor smaller ones: their polytopes close at once, and the results established without the
#: reduction are kept (the quincunx scheme's blocks of sizes 2 and 3 have such symmetries)
MIN_N = 8


def _float(M: fmpq_mat) -> np.ndarray:
    return np.array([[float(M[a, b]) for b in range(M.ncols())] for a in range(M.nrows())])


def _nullity(mats: Sequence[np.ndarray], cycle: Sequence[int]) -> int:
    """Float dimension of ``{X : X A_{c_j} = A_{c_{j+1}} X for all j}`` (a pre-test only)."""
    n, k = mats[0].shape[0], len(cycle)
    eye = np.eye(n)
    K = np.vstack([np.kron(eye, mats[cycle[j]].T) - np.kron(mats[cycle[(j + 1) % k]], eye)
                   for j in range(k)])
    s = np.linalg.svd(K, compute_uv=False)
    return int(np.sum(s <= 1e-9 * s[0])) + max(K.shape[1] - len(s), 0)


def _solve_exact(mats: Sequence[fmpq_mat], cycle: Sequence[int]) -> fmpq_mat | None:
    """The exact solution ``X`` of ``X A_{c_j} = A_{c_{j+1}} X`` when the solution space is a line."""
    n, k = mats[0].nrows(), len(cycle)
    rows = []
    for j in range(k):
        A, C = mats[cycle[j]], mats[cycle[(j + 1) % k]]
        for a in range(n):
            for c in range(n):
                row = [fmpq(0)] * (n * n)
                for b in range(n):
                    row[a * n + b] += A[b, c]           # (X A)[a, c]
                    row[b * n + c] -= C[a, b]           # (C X)[a, c]
                rows.append(row)
    ker = _kernel(fmpq_mat(len(rows), n * n, [x for r in rows for x in r]))
    if len(ker) != 1:
        return None
    return fmpq_mat(n, n, ker[0])


def _rational_root(c: fmpq, k: int) -> fmpq | None:
    """The rational ``k``-th root of ``c`` (real; negative only for odd ``k``), or None (exact)."""
    if c == 0 or (c < 0 and k % 2 == 0):
        return None
    sgn = -1 if c < 0 else 1
    p, q = abs(c.p), c.q
    x, y = p.root(k), q.root(k)                 # floor roots (FLINT fmpz)
    if x ** k != p or y ** k != q:
        return None
    return fmpq(sgn * x, y)


def cyclic_symmetry(mats: Sequence[fmpq_mat],
                    min_n: int = MIN_N) -> tuple[list[int], fmpq_mat] | None:
    """``(cycle, G)``: an ordering ``cycle = [0, c_1, ..., c_{k-1}]`` of the family and an exact rational
    ``G`` with ``G A_{c_j} = A_{c_{j+1}} G`` (indices mod ``k``) and ``G^k = I``, every identity checked
    exactly; ``None`` when there is none (only the ``k``-cycles for ``2 <= k <= MAX_K`` and
    ``min_n <= n <= MAX_N`` are tried; the solution space must be one-dimensional, and the scalar
    ``G^k`` must have a rational ``k``-th root)."""
    k = len(mats)
    if not 2 <= k <= MAX_K:
        return None
    n = mats[0].nrows()
    if not min_n <= n <= MAX_N:
        return None
    cp = [A.charpoly() for A in mats]
    if any(c != cp[0] for c in cp):       # conjugate matrices have one characteristic polynomial
        return None
    if all(A == mats[0] for A in mats):
        return None
    fl = [_float(A) for A in mats]
    for rest in itertools.permutations(range(1, k)):
        cycle = [0, *rest]
        if _nullity(fl, cycle) != 1:
            continue
        G = _solve_exact(mats, cycle)
        if G is None:
            continue
        if any(G * mats[cycle[j]] != mats[cycle[(j + 1) % k]] * G for j in range(k)):
            continue                                                  # pragma: no cover
        P = fmpq_mat(n, n)
        for a in range(n):
            P[a, a] = 1
        for _ in range(k):
            P = P * G
        c = P[0, 0]
        if c == 0 or any(P[a, b] != (c if a == b else 0) for a in range(n) for b in range(n)):
            continue
        root = _rational_root(c, k)
        if root is None:
            continue
        return cycle, G * (1 / root)
    return None


def reduced_family(mats: Sequence[fmpq_mat], cycle: Sequence[int], G: fmpq_mat) -> list[fmpq_mat]:
    """``B_d = A_{c_0} G^d`` for ``d = 0, ..., k - 1`` (module docstring)."""
    out = [mats[cycle[0]]]
    for _ in range(1, len(cycle)):
        out.append(out[-1] * G)
    return out


def a_word(word: Sequence[int], cycle: Sequence[int]) -> tuple[int, ...]:
    """The word of the ``A``'s whose product is ``B_w^m`` (module docstring; ``m`` the least power with
    ``m sum(w) = 0 mod k``), as indices of the input family."""
    k = len(cycle)
    m = 1
    while (m * sum(word)) % k:
        m += 1
    out, s = [], 0
    for d in list(word) * m:
        out.append(cycle[s % k])
        s += d
    return tuple(out)


def reduction_that_splits(F: Family, blocks: Callable, rational_family: Callable):
    """``(cycle, G, B)`` for a rational family with a cyclic symmetry whose reduced family ``B`` splits
    (``blocks(B)`` finds coordinate blocks, or an exact invariant subspace exists), else None: the
    reduction is used only when it gives smaller diagonal blocks."""
    sym = cyclic_symmetry(F.exact_q)
    if sym is None:
        return None
    B = rational_family(reduced_family(F.exact_q, *sym))
    if len(blocks(B)) > 1 or invariant_subspace(B.exact_q) is not None:
        return (*sym, B)
    return None


def solve_reduced(F: Family, cycle: list[int], G: fmpq_mat, B: Family, solve: Callable,
                  **kw: Any) -> _Bounds:
    """``JSR(A) = JSR(B)`` (module docstring): the bounds ``solve(B, **kw)`` found for the reduced family,
    with the witness word translated back (the ``A`` word of a power of the ``B`` word, the same spectral
    radius) and ``witness["cyclic_symmetry"]`` (the ordering, ``G`` and the reduced product)."""
    import sympy as sp

    b = solve(B, **kw)
    word = a_word(b.word, cycle)
    lower, rp = _lower_from_word(F, word)
    wit = dict(b.witness)
    if "candidates" in wit:
        wit["candidates"] = [a_word(w, cycle) for w in wit["candidates"]]
    n = G.nrows()
    wit["cyclic_symmetry"] = {"cycle": list(cycle), "reduced_product": tuple(b.word),
                              "G": [[sp.Rational(int(G[a, c].p), int(G[a, c].q)) for c in range(n)]
                                    for a in range(n)]}
    if "vertices" in wit or "blocks" in wit:
        wit["polytope_coordinates"] = ("the polytope, its vertices and blocks are those of the "
                                       "reduced family B_d = A_c0 G^d")
    method = (f"cyclic conjugation symmetry G A_c(j) G^-1 = A_c(j+1) of order {len(cycle)} "
              "(JSR(A) = JSR(A_c0 G^d)); reduced family: " + b.method)
    return _Bounds(max(lower, b.lower), b.upper, word, rp, method, arithmetic_of(F), wit, b.notes)
