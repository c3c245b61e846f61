"""Exact common invariant subspaces of a rational family, and the block-triangular reduction.

If the matrices ``A_1, ..., A_k`` have a common invariant subspace ``W`` (``0 < dim W < n``), then
in a basis ``Q = [W | E]`` they are all block upper triangular,

    Q^{-1} A_i Q = [[A_i|W, *], [0, A_i on R^n / W]],

and ``JSR = max(JSR(A|W), JSR(A on the quotient))`` (Berger–Wang; Jungers 2009, Prop. 1.5).
The invariant polytope algorithm needs an *irreducible* family: for a reducible one an extremal
norm may not exist and the polytope need not close, so splitting is both a speed-up (smaller
matrices) and a necessity (Mejstrik 2020 does the same, numerically; here it is exact).

Coordinate subspaces are found from the sparsity pattern (``analysis.jsr._solve_blocks``: the
strongly connected components of the union of the patterns, :func:`strong_components`). This
module finds the others, exactly over ``Q``: for start vectors ``v`` (the unit vectors, and
kernel vectors of ``f(X)`` for the irreducible factors ``f`` of the characteristic polynomial of
pseudo-random elements ``X`` of the matrix algebra, as in the meataxe) the smallest common
invariant subspace containing ``v`` (the Krylov space ``span{A_w v}``, built by exact row
reduction), and the same for the transposed family (a common invariant subspace ``U`` of the
``A_i^T`` gives the invariant subspace ``U^perp`` of the ``A_i``). The first proper one found is
returned; the reduction is applied recursively by the caller.

Examples
--------
``A_0 = [[1, 1], [0, 2]]`` and ``A_1 = [[2, 0], [1, 1]]`` have no common zero pattern, but
both map ``(1, 1)`` to ``(2, 2)``: the line it spans is invariant (eigenvalue 2 on it, 1 on the
quotient), so ``JSR = 2``:

>>> from flint import fmpq_mat
>>> A = [fmpq_mat([[1, 1], [0, 2]]), fmpq_mat([[2, 0], [1, 1]])]
>>> W = invariant_subspace(A)
>>> W.nrows(), W.ncols()
(2, 1)
>>> top, bottom = split_family(A, W)
>>> [str(M) for M in top], [str(M) for M in bottom]
(['[2]', '[2]'], ['[1]', '[1]'])

References
----------
R. Jungers, *The joint spectral radius: theory and applications*, LNCIS 385, Springer 2009,
Section 1.2 (reducible families).
T. Mejstrik, *Algorithm 1011: Improved invariant polytope algorithm and applications*, ACM Trans.
Math. Softw. 46(3) (2020) 29 (invariant subspaces).
"""

from __future__ import annotations

from typing import Sequence

from flint import fmpq, fmpq_mat, nmod_mat

#: the prime of the modular pre-check of a Krylov spin (:func:`_full_mod_p`)
_PRIME = (1 << 61) - 1


def _rref_rows(rows: list[list[fmpq]], n: int) -> list[list[fmpq]]:
    """Row-reduced basis of ``span(rows)`` (fmpq lists); the zero rows dropped."""
    if not rows:
        return []
    M = fmpq_mat(len(rows), n, [x for r in rows for x in r])
    R, rank = M.rref()
    return [[R[i, j] for j in range(n)] for i in range(rank)]


class _Echelon:
    """An echelon basis grown one vector at a time: each row has a pivot (its first nonzero entry,
    scaled to 1) where the later rows vanish; :meth:`add` reduces a vector against the rows in
    order (O(rank n) operations instead of a new row reduction of everything)."""

    def __init__(self, n: int):
        self.n = n
        self.rows: list[tuple[int, list[fmpq]]] = []

    def add(self, v: list[fmpq]) -> bool:
        """Add ``v``; True when it was independent of the rows (the rank grew)."""
        w = list(v)
        for p, r in self.rows:
            c = w[p]
            if c != 0:
                for j in range(p, self.n):
                    if r[j] != 0:
                        w[j] -= c * r[j]
        for p in range(self.n):
            if w[p] != 0:
                inv = 1 / w[p]
                self.rows.append((p, [x * inv for x in w]))
                return True
        return False

    def __len__(self) -> int:
        return len(self.rows)


def _images(frontier, mats, n: int) -> list:
    """``A v`` for every vector ``v`` of ``frontier`` and every matrix ``A`` (exact, in that order)."""
    out = []
    for v in frontier:
        col = fmpq_mat(n, 1, v)
        for A in mats:
            w = A * col
            out.append([w[a, 0] for a in range(n)])
    return out


def _krylov(mats: Sequence[fmpq_mat], start: list[fmpq], n: int, limit: int) -> list[list[fmpq]]:
    """Basis (rows, reduced echelon form) of the smallest common invariant subspace containing
    ``start``; stops early (returning what it has, of dimension ``>= limit``) once the dimension
    reaches ``limit``."""
    ech = _Echelon(n)
    if not ech.add(start):
        return []
    vecs = [start]
    frontier = [start]
    while frontier and len(ech) < limit:
        new_vecs = _images(frontier, mats, n)
        # the new directions: candidates that increased the rank, in order
        frontier = []
        for v in new_vecs:
            if ech.add(v):
                frontier.append(v)
                vecs.append(v)
            if len(ech) >= limit:
                break
    return _rref_rows(vecs, n)


def _to_mod_p(A: fmpq_mat) -> nmod_mat | None:
    """``A`` reduced modulo :data:`_PRIME` (``A = N / d`` with ``d`` invertible mod p), or None."""
    N, d = A.numer_denom()
    if int(d) % _PRIME == 0:
        return None
    inv = pow(int(d), -1, _PRIME)
    return nmod_mat(A.nrows(), A.ncols(), [int(x) % _PRIME * inv % _PRIME for x in N.entries()], _PRIME)


def _dim_mod_p(mats_p: Sequence[nmod_mat], start: list[fmpq], n: int, stop: int) -> int:
    """The dimension of the spin of ``start`` reduced mod p, computed until it reaches ``stop`` (then
    ``stop`` or more is returned); 0 when ``start`` does not reduce. It is a lower bound of the dimension
    of the rational spin (the rank of the reductions of the vectors ``A_w v`` is at most their rank over
    ``Q``): when it reaches ``n`` the rational spin spans ``Q^n``, and when it reaches the dimension of a
    subspace already found the rational spin cannot be smaller; either way the exact spin is skipped. Pure
    speed-up: a smaller value decides nothing."""
    col = _to_mod_p(fmpq_mat(n, 1, start))
    if col is None:
        return 0
    S = col.transpose()                                  # rows span the current space
    dim = S.rank()
    while dim < stop:
        rows = [S] + [(A * S.transpose()).transpose() for A in mats_p]
        stacked = nmod_mat(sum(r.nrows() for r in rows), n,
                           [int(x) for r in rows for x in r.entries()], _PRIME)
        R, rank = stacked.rref()
        if rank == dim:
            return dim
        dim = rank
        S = nmod_mat(rank, n, [int(R[i, j]) for i in range(rank) for j in range(n)], _PRIME)
    return dim


def _krylov_guided(mats: Sequence[fmpq_mat], mats_p: Sequence[nmod_mat], start: list[fmpq],
                   n: int) -> list[list[fmpq]] | None:
    """:func:`_krylov` with the independent vectors chosen modulo p (one C row reduction per level: the
    pivot columns of ``[basis | candidates]``), the products computed exactly, and the span verified exactly:
    it contains ``start`` and is invariant, and it is spanned by vectors ``A_w start``, so it *is* the
    Krylov space, returned in the same reduced echelon form. None when the verification fails (a vector
    dependent mod p only); the caller then runs the exact spin."""
    def mod_col(v):
        return _to_mod_p(fmpq_mat(n, 1, v))

    first = mod_col(start)
    if first is None:
        return None
    vecs = [start]
    cols_p = [first]
    frontier = [start]
    while frontier:
        cands = _images(frontier, mats, n)
        cand_p = [mod_col(v) for v in cands]
        if any(c is None for c in cand_p):
            return None
        allc = cols_p + cand_p
        M = nmod_mat(n, len(allc), [int(c[a, 0]) for a in range(n) for c in allc], _PRIME)
        R, rank = M.rref()
        pivots = []
        for i in range(rank):
            for j in range(len(allc)):
                if int(R[i, j]) != 0:
                    pivots.append(j)
                    break
        frontier = [cands[j - len(cols_p)] for j in pivots if j >= len(cols_p)]
        cols_p = [allc[j] for j in pivots]
        vecs += frontier
    W = _rref_rows(vecs, n)
    d = len(W)
    Wm = fmpq_mat(d, n, [x for r in W for x in r])
    for A in mats:
        img = (A * Wm.transpose()).transpose()
        stacked = fmpq_mat(2 * d, n, [x for r in W for x in r] + [img[i, j] for i in range(d) for j in range(n)])
        if stacked.rank() != d:
            return None
    return W


def _kernel(M: fmpq_mat) -> list[list[fmpq]]:
    """A basis (rows) of the right kernel ``{x : M x = 0}``, from the exact RREF."""
    n = M.ncols()
    R, rank = M.rref()
    pivots = []
    for i in range(rank):
        for j in range(n):
            if R[i, j] != 0:
                pivots.append(j)
                break
    out = []
    for f in (j for j in range(n) if j not in pivots):
        x = [fmpq(0)] * n
        x[f] = fmpq(1)
        for i, pj in enumerate(pivots):
            x[pj] = -R[i, f]
        out.append(x)
    return out


def _orth_complement(rows: list[list[fmpq]], n: int) -> list[list[fmpq]]:
    """A basis (rows) of ``{x : <r, x> = 0 for all rows r}``."""
    return _kernel(fmpq_mat(len(rows), n, [x for r in rows for x in r]))


def _poly_at(f, X: fmpq_mat) -> fmpq_mat:
    """``f(X)`` by Horner's rule (exact)."""
    n = X.nrows()
    coeffs = [fmpq(c) for c in f.coeffs()]
    R = fmpq_mat(n, n)
    for c in reversed(coeffs):
        R = R * X
        for a in range(n):
            R[a, a] += c
    return R


def _spin_candidates(mats: Sequence[fmpq_mat], trials: int = 3):
    """Start vectors for the Krylov spins: the unit vectors, then (meataxe-style, Holt–Rees) a
    kernel vector of ``f(X)`` for each irreducible factor ``f`` of the characteristic polynomial
    of a few pseudo-random elements ``X`` of the algebra generated by the family (fixed seeds,
    so the result is reproducible). A common invariant subspace on which ``X`` acts with factor
    ``f`` contains such a vector."""
    n = mats[0].nrows()
    for j in range(n):
        yield [fmpq(1) if a == j else fmpq(0) for a in range(n)]
    k = len(mats)
    prods = list(mats) + [mats[i] * mats[j] for i in range(k) for j in range(k)]
    for t in range(trials):
        X = fmpq_mat(n, n)
        for s, P in enumerate(prods):
            X += P * (1 + (7 * s + 3 * t * t + 5 * t) % 11)
        _, factors = X.charpoly().factor()
        for f, _e in sorted(factors, key=lambda fe: fe[0].degree()):
            for v in _kernel(_poly_at(f, X))[:1]:
                yield v


def _spin(mats, mats_p, v, n, below: int | None = None) -> list[list[fmpq]] | None:
    """The exact Krylov space of ``v``, or None when it is known (mod p) to be the whole space or, with
    ``below``, to have dimension ``>= below`` (it cannot improve on a subspace of that dimension)."""
    if mats_p is None:
        return _krylov(mats, v, n, n)
    stop = n if below is None else min(n, below)
    if _dim_mod_p(mats_p, v, n, stop) >= stop:
        return None
    W = _krylov_guided(mats, mats_p, v, n)
    if W is None:
        W = _krylov(mats, v, n, n)
    return W


def invariant_subspace(mats: Sequence[fmpq_mat]) -> fmpq_mat | None:
    """An exact proper common invariant subspace (columns of the returned ``n x d`` matrix), or
    ``None`` when none is found among the spins of the start vectors of
    :func:`_spin_candidates` for the family and for its transpose (module docstring). ``None``
    does not prove irreducibility; the caller then works with the full family."""
    n = mats[0].nrows()
    if n < 2:
        return None
    best: list[list[fmpq]] | None = None
    mats_p = [_to_mod_p(A) for A in mats]
    if any(A is None for A in mats_p):
        mats_p = None
    for v in _spin_candidates(mats):
        if best is not None and len(best) == 1:
            break                                        # a line: nothing smaller is proper
        W = _spin(mats, mats_p, v, n, None if best is None else len(best))
        if W is None:
            continue
        if 0 < len(W) < n and (best is None or len(W) < len(best)):
            best = W
    trans = [A.transpose() for A in mats]
    trans_p = None if mats_p is None else [A.transpose() for A in mats_p]
    # (after a line nothing is smaller: the transposed spins are not needed)
    for v in _spin_candidates(trans) if best is None or len(best) > 1 else ():
        U = _spin(trans, trans_p, v, n)
        if U is None:
            continue
        if 0 < len(U) < n:
            W = _orth_complement(U, n)
            if 0 < len(W) < n and (best is None or len(W) < len(best)):
                best = W
    if best is None:
        return None
    d = len(best)
    return fmpq_mat(n, d, [best[c][a] for a in range(n) for c in range(d)])


def split_family(mats: Sequence[fmpq_mat], W: fmpq_mat) -> tuple[list[fmpq_mat], list[fmpq_mat]]:
    """The diagonal blocks ``(A|W, A on R^n / W)`` of ``Q^{-1} A_i Q`` with ``Q = [W | E]``
    (``E`` unit vectors completing a basis), exactly; raises ``ArithmeticError`` if ``W`` is
    not invariant."""
    n, d = W.nrows(), W.ncols()
    cols = [[W[a, c] for a in range(n)] for c in range(d)]
    cur = _rref_rows(cols, n)
    for j in range(n):
        if len(cur) == n:
            break
        e = [fmpq(1) if a == j else fmpq(0) for a in range(n)]
        t = _rref_rows(cur + [e], n)
        if len(t) > len(cur):
            cols.append(e)
            cur = t
    Q = fmpq_mat(n, n, [cols[c][a] for a in range(n) for c in range(n)])
    Qi = Q.inv()
    top, bottom = [], []
    for A in mats:
        T = Qi * A * Q
        if any(T[a, c] != 0 for a in range(d, n) for c in range(d)):
            raise ArithmeticError("the subspace is not invariant")
        top.append(fmpq_mat(d, d, [T[a, c] for a in range(d) for c in range(d)]))
        bottom.append(fmpq_mat(n - d, n - d, [T[a, c] for a in range(d, n) for c in range(d, n)]))
    return top, bottom


def strong_components(succ: Sequence[Sequence[int]]) -> list[list[int]]:
    """The strongly connected components of the digraph ``a -> b`` for ``b`` in ``succ[a]``,
    each sorted, in the order in which they complete in a depth-first search from the vertices
    ``0, 1, ...`` that tries the successors in the order given (Tarjan 1972, iteratively). With
    the successors in decreasing order this is the order of the labels of
    ``scipy.sparse.csgraph.connected_components(..., connection="strong")`` (a test compares
    them), without importing SciPy's sparse package (half a second of a command's start).

    >>> strong_components([[2, 1], [], [], [2]])
    [[2], [1], [0], [3]]
    >>> strong_components([[1], [2, 0], [], [2]])
    [[2], [0, 1], [3]]
    """
    n = len(succ)
    index, low = [-1] * n, [0] * n
    on_stack = [False] * n
    stack: list[int] = []
    comps: list[list[int]] = []
    counter = 0
    for root in range(n):
        if index[root] >= 0:
            continue
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack[root] = True
        path = [[root, 0]]                      # the DFS path: vertex, next successor to try
        while path:
            v, i = path[-1]
            if i < len(succ[v]):
                path[-1][1] += 1
                w = succ[v][i]
                if index[w] < 0:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack[w] = True
                    path.append([w, 0])
                elif on_stack[w]:
                    low[v] = min(low[v], index[w])
                continue
            path.pop()
            if path:
                u = path[-1][0]
                low[u] = min(low[u], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack[w] = False
                    comp.append(w)
                    if w == v:
                        break
                comps.append(sorted(comp))
    return comps
