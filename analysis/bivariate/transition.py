"""Transition operators of a bivariate mask on its invariant support, and their restriction to the
difference subspaces ``V_k``.

With the refinable function ``phi(x) = sum_alpha a(alpha) phi(M x - alpha)`` and ``v(x) = (phi(x + j))_j``,
``v(M^{-1}(x + eps)) = T_eps v(x)`` where, for the digits ``eps`` of ``Z^2 / M Z^2``,

    (T_eps)_{j, i} = a(eps + M j - i),        i, j in Omega.

``Omega = H cap Z^2``, ``H`` the attractor of the maps ``x -> M^{-1}(x + d)``, ``d in supp(a) - digits``
(``H = K - G``: the support of ``phi`` minus the digit tile; Cabrelli–Heil–Molter 2004, Charina–Protasov 2019).
``Omega`` is the largest set of integer points in a box containing ``H`` in which every point ``j`` has a
predecessor ``M j - d`` (a backward orbit stays in ``H``): a decreasing iteration, exact. Then the column of
``T_eps`` for ``i in Omega`` is supported in ``Omega``, so the principal submatrices multiply like the operators.

``V_k = {u in R^Omega : sum_j u_j p(j) = 0 for every polynomial p of degree < k}`` (vectors orthogonal to the
polynomial sequences of degree ``< k``: the span of the differences of order ``k``) is a common invariant
subspace of the ``T_eps`` exactly when ``a`` satisfies sum rules of order ``k``; its basis is computed exactly
(reduced echelon form of the moment matrix) and the restrictions ``T_eps|V_k`` are exact rational matrices.

Examples
--------
>>> from analysis.bivariate.mask import BivariateMask
>>> hat = BivariateMask.from_symbol("(1+z1)*(1+z2)*(1+z1*z2)/(2*z1*z2)")      # the Courant element B_111
>>> om = invariant_support(hat)
>>> len(om), om[:3]
(14, ((-2, -2), (-2, -1), (-2, 0)))
>>> R = restricted_transition(hat, 2)
>>> len(R.matrices), R.matrices[0].nrows(), R.dimension
(4, 11, 11)

References
----------
C. Cabrelli, C. Heil, U. Molter, *Self-similarity and multiwavelets in higher dimensions*, Mem. AMS 170 (2004).
M. Charina, V. Yu. Protasov, *Regularity of anisotropic refinable functions*, Appl. Comput. Harmon. Anal. 47
(2019) 795-821.
H. M. Möller, T. Sauer, *Multivariate refinable functions of high approximation order via quotient ideals of
Laurent polynomials*, Adv. Comput. Math. 20 (2004) 205-228 (the difference subspaces).
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import sympy as sp
from flint import fmpq, fmpq_mat

from ..result import AnalysisError
from .mask import BivariateMask

__all__ = ["invariant_support", "fixed_points", "check_invariant_support_size", "transition_matrices",
           "difference_subspace", "restricted_transition",
           "RestrictedFamily", "MAX_OMEGA"]

#: the largest invariant support (the transition matrices are |Omega| x |Omega|)
MAX_OMEGA = 400


def _inverse_power_bound(D, p: int) -> tuple[Fraction, list]:
    (a, b), (c, d) = D.matrix
    det = Fraction(D.det)
    Minv = [[d / det, -b / det], [-c / det, a / det]]
    P = [[Fraction(1), Fraction(0)], [Fraction(0), Fraction(1)]]
    norms = []
    for _ in range(p):
        P = [[sum(P[r][t] * Minv[t][s] for t in range(2)) for s in range(2)] for r in range(2)]
        norms.append(max(abs(P[r][0]) + abs(P[r][1]) for r in range(2)))
    return norms[-1], norms


def _predecessor_offsets(a: BivariateMask) -> list[tuple[int, int]]:
    """``supp(a) - digits``: ``j`` in ``Omega`` has a predecessor ``M j - d`` in ``Omega`` for one of these ``d``."""
    digits = a.dilation.digits                                  # computed on each access
    return sorted({(i - e[0], j - e[1]) for (i, j) in a.coeffs for e in digits})


def fixed_points(a: BivariateMask) -> set[tuple[int, int]]:
    """The integer fixed points ``j = (M - I)^-1 d`` of the maps ``x -> M^-1 (x + d)``, ``d in supp(a) - digits``:
    points of ``H`` and of ``Omega`` (``M j - d = j`` is its own predecessor), known from the support of the mask
    and ``M`` alone, so ``|Omega|`` is at least their number (all of ``supp(a) - digits`` when ``M = 2I``).

    >>> from analysis.bivariate.mask import BivariateMask
    >>> len(fixed_points(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)")))
    16
    """
    (m00, m01), (m10, m11) = a.dilation.matrix
    p, q, r, t = m00 - 1, m01, m10, m11 - 1                  # M - I (invertible: M has no eigenvalue 1)
    det = p * t - q * r
    out = set()
    for dx, dy in _predecessor_offsets(a):
        x, y = t * dx - q * dy, -r * dx + p * dy             # adj(M - I) d
        if x % det == 0 and y % det == 0:
            out.add((x // det, y // det))
    return out


def check_invariant_support_size(a: BivariateMask) -> None:
    """Refuse, before any computation, a mask whose invariant support is sure to exceed :data:`MAX_OMEGA` points
    (:func:`fixed_points` are in it)."""
    n = len(fixed_points(a))
    if n > MAX_OMEGA:
        raise AnalysisError(f"the invariant support has at least {n} points (limit {MAX_OMEGA}; the transition "
                            f"matrices would be {n} x {n} or larger): give a mask with a smaller support")


def invariant_support(a: BivariateMask) -> tuple[tuple[int, int], ...]:
    """``Omega = H cap Z^2`` (module docstring), sorted lexicographically.

    Algorithm: :func:`check_invariant_support_size` first; then the decreasing iteration on a boolean array over
    a box containing ``H`` (numpy, integers only: exact), each step keeping the points ``j`` with ``M j - d`` in
    the set for some ``d``.
    """
    import numpy as np

    check_invariant_support_size(a)
    D = a.dilation
    ds = _predecessor_offsets(a)
    dmax = max(max(abs(x), abs(y)) for x, y in ds)
    for p in range(1, 40):
        q, norms = _inverse_power_bound(D, p)
        if q < 1:
            break
    else:                                                 # pragma: no cover - expanding M always contracts
        raise AnalysisError("M^-p does not contract in the max norm for p < 40")
    # h = M^-p h' + sum_{i=1..p} M^-i d_i  =>  |h| <= q |h| + sum |M^-i| dmax
    R = (sum(norms) * dmax) / (1 - q)
    r = int(R) + 1
    side = 2 * r + 1
    if side ** 2 > 200_000:
        raise AnalysisError("the invariant support is too large for this mask and dilation: give a mask with a "
                            "smaller support")
    inside = np.ones((side, side), dtype=bool)              # inside[x + r, y + r]: (x, y) still in the set
    M = np.array(D.matrix, dtype=np.int64)
    while True:
        pts = np.argwhere(inside) - r
        Mj = pts @ M.T
        keep = np.zeros(len(pts), dtype=bool)
        for dx, dy in ds:
            x, y = Mj[:, 0] - dx + r, Mj[:, 1] - dy + r
            ok = (~keep) & (x >= 0) & (x < side) & (y >= 0) & (y < side)
            keep[ok] = inside[x[ok], y[ok]]
        if keep.all():
            break
        inside[tuple((pts[~keep] + r).T)] = False
    omega = [(int(x), int(y)) for x, y in np.argwhere(inside) - r]
    if not omega:                                          # pragma: no cover - H always has integer points?
        raise AnalysisError("the invariant support has no integer points")
    if len(omega) > MAX_OMEGA:
        raise AnalysisError(f"the invariant support has {len(omega)} points (limit {MAX_OMEGA}): give a mask with "
                            "a smaller support")
    return tuple(sorted(omega))


def _fmpq(x) -> fmpq:
    x = sp.Rational(x)
    return fmpq(int(x.p), int(x.q))


def _rational_mask(a: BivariateMask) -> dict:
    if a.params:
        raise AnalysisError(f"give values to the parameters {', '.join(p.name for p in a.params)} "
                            "(e.g. --param w=1/16) before computing transition operators")
    out = {}
    for ij, v in a:
        if not v.is_Rational:
            raise AnalysisError(f"the coefficient {ij[0]},{ij[1]} = {sp.sstr(v)} is not rational; "
                                "the bivariate route is exact over the rationals")
        out[ij] = _fmpq(v)
    return out


def transition_matrices(a: BivariateMask, omega=None) -> tuple[list[fmpq_mat], tuple]:
    """``[T_eps for eps in digits]`` on ``Omega`` (exact ``fmpq_mat``) and ``Omega``."""
    omega = invariant_support(a) if omega is None else omega
    c = _rational_mask(a)
    D = a.dilation
    n = len(omega)
    mats = []
    zero = fmpq(0)
    for e in D.digits:
        T = fmpq_mat(n, n)
        for r, j in enumerate(omega):
            Mj = D.apply(j)
            for s, i in enumerate(omega):
                v = c.get((e[0] + Mj[0] - i[0], e[1] + Mj[1] - i[1]), zero)
                if v != 0:
                    T[r, s] = v
        mats.append(T)
    return mats, omega


def difference_subspace(omega, k: int) -> tuple[fmpq_mat, list[int]]:
    """A basis ``B`` (columns) of ``V_k`` on ``Omega`` with ``B[free, :] = I``, and the rows ``free``."""
    n = len(omega)
    mons = [(p, d - p) for d in range(k) for p in range(d, -1, -1)]
    if not mons:
        B = fmpq_mat(n, n)
        for t in range(n):
            B[t, t] = 1
        return B, list(range(n))
    P = fmpq_mat(len(mons), n)
    for r, (p, q) in enumerate(mons):
        for s, (x, y) in enumerate(omega):
            P[r, s] = fmpq(x ** p * y ** q)
    R, rank = P.rref()
    pivots = []
    row = 0
    for col in range(n):
        if row < rank and R[row, col] != 0:
            pivots.append(col)
            row += 1
    free = [c for c in range(n) if c not in pivots]
    B = fmpq_mat(n, len(free))
    for t, f in enumerate(free):
        B[f, t] = 1
        for r, pc in enumerate(pivots):
            B[pc, t] = -R[r, f]
    return B, free


@dataclass(frozen=True)
class RestrictedFamily:
    """``T_eps|V_k`` (exact), with ``Omega``, ``k``, the basis and the full operators."""

    matrices: tuple
    omega: tuple
    k: int
    basis: fmpq_mat
    full: tuple

    @property
    def dimension(self) -> int:
        return self.basis.ncols()


def restricted_transition(a: BivariateMask, k: int, omega=None) -> RestrictedFamily:
    """The restrictions ``T_eps|V_k``; an :class:`AnalysisError` when ``V_k`` is not invariant (the mask
    does not satisfy sum rules of order ``k``) or is ``{0}``. ``omega``: the invariant support to use (default
    that of ``a``; a one-parameter family uses its generic support at every value, see
    :mod:`analysis.bivariate.ranges`)."""
    mats, omega = transition_matrices(a, omega)
    B, free = difference_subspace(omega, k)
    if B.ncols() == 0:
        raise AnalysisError(f"the difference subspace V_{k} on the invariant support is {{0}}")
    out = []
    for T in mats:
        TB = T * B
        X = fmpq_mat(B.ncols(), B.ncols())
        for r, f in enumerate(free):
            for s in range(B.ncols()):
                X[r, s] = TB[f, s]
        if B * X != TB:
            raise AnalysisError(f"V_{k} is not invariant under the transition operators: "
                                f"the mask does not satisfy sum rules of order {k}")
        out.append(X)
    return RestrictedFamily(tuple(out), omega, k, B, tuple(mats))
