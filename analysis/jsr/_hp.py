"""High-precision re-certification of a closed float invariant polytope.

The float polytope of :mod:`analysis.jsr._polytope` stores its vertices as 52-bit dyadics: the
root ``v`` (a leading eigenvector of the s.m.p. ``P_w``) is then not an exact eigenvector, and
``B_w v = v + e`` with ``||e|| ~ 1e-16``. Writing ``e`` in a vertex basis costs ``cond(basis) ||e||``
(``1e-10`` and worse for ill-conditioned families such as Daubechies D14+), which is what limits
the gap of the standard certificate.

Here the same combinatorial polytope (same roots, same vertex paths, same LP supports) is rebuilt
with ``HP_BITS``-bit vertices: leading eigenpairs refined by Newton's method in mpmath (the phase
fixed by the float eigenvector's largest component), descendants ``v_{p i} = B_i v_p`` computed
in mpmath and rounded to exact dyadics. Every membership ``A_i v_j / r in absconv(V)`` is then
re-solved in Arb ball arithmetic in a *local* vertex basis (the LP support completed to ``n``
independent vertices): ``A_i v_j / r = M lambda`` exactly for some ``lambda`` in the enclosure,
hence ``||A_i v_j / r||_P <= ||lambda||_1``, and ``JSR <= r max_{i,j} ||lambda||_1``. With exact
roots the boundary memberships are exact up to ``2^-HP_BITS``, so the certificate is as tight as
the float LP (``1 + tol``).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Sequence

import mpmath
import numpy as np
from flint import arb, arb_mat

from ._exact import Family, arb_precision, arb_to_fraction_bounds, fraction_to_arb
from ._balance import eigen_groups
from ._pivots import qr_pivots
from ._polytope import Certificate, PolytopeState

#: bits of the exact dyadic vertex coordinates
HP_BITS = 200
#: Arb working precision of the local solves
HP_ARB_PREC = 320


def _mid_matrices(F: Family, prec: int) -> list:
    """Midpoint matrices of ``F`` as mpmath matrices (exact for rational and dyadic entries)."""
    out = []
    with mpmath.workprec(prec):
        for i in range(F.k):
            M = F.arb(i)
            A = mpmath.matrix(F.n, F.n)
            for a in range(F.n):
                for b in range(F.n):
                    m, e = M[a, b].mid().man_exp()
                    A[a, b] = mpmath.ldexp(mpmath.mpf(int(m)), int(e))
            out.append(A)
    return out


def _refine_eigenpair(P, lam: complex, u: np.ndarray, prec: int, iters: int = 12):
    """Newton's method for ``P u = lam u`` with ``u[q]`` fixed (``q = argmax |u|``)."""
    n = P.rows
    q = int(np.argmax(np.abs(u)))
    with mpmath.workprec(prec):
        L = mpmath.mpc(lam.real, lam.imag)
        U = mpmath.matrix([mpmath.mpc(complex(x).real, complex(x).imag) for x in u])
        for _ in range(iters):
            R = P * U - L * U
            J = mpmath.matrix(n + 1, n + 1)
            for a in range(n):
                for b in range(n):
                    J[a, b] = P[a, b] - (L if a == b else 0)
                J[a, n] = -U[a]
            J[n, q] = 1
            rhs = mpmath.matrix(n + 1, 1)
            for a in range(n):
                rhs[a] = -R[a]
            d = mpmath.lu_solve(J, rhs)
            for a in range(n):
                U[a] += d[a]
            L += d[n]
            if mpmath.mnorm(d, 1) < mpmath.ldexp(1, -prec + 8):
                break
    return L, U


def hp_roots(Pm: Sequence, mats: Sequence[np.ndarray], words: Sequence, r: float,
             prec: int) -> list:
    """The unscaled roots of :func:`analysis.jsr._balance.balanced_roots`, in the same order,
    as ``prec``-bit mpmath vectors: each leading eigenpair Newton-refined for the exact
    (midpoint) product, with the same normalization ``u[q] = 1``."""
    n = mats[0].shape[0]
    B = [np.asarray(A, dtype=float) / r for A in mats]
    out = []
    with mpmath.workprec(prec):
        rr = mpmath.mpf(r)
        for word in words:
            Pmp = mpmath.eye(n)
            for i in word:
                Pmp = Pmp * (Pm[i] / rr)
            for lam, u, _ in eigen_groups(B, word):
                _, V = _refine_eigenpair(Pmp, lam, u, prec)
                if lam.imag == 0:
                    out.append([mpmath.re(x) for x in V])
                else:
                    out.append([mpmath.re(x) for x in V])
                    out.append([mpmath.im(x) for x in V])
    return out


def _scaled_root(p: list, v: np.ndarray):
    """``s p`` with the float factor ``s`` that matches the (balanced, rounded) float root ``v``;
    ``None`` if ``v`` is not a multiple of ``p`` (the root order does not match the float run).
    Any multiple of an exact eigenvector is one, so the factor need not be exact."""
    pf = np.array([float(x) for x in p])
    s = float(pf @ v) / float(pf @ pf)
    if not np.isfinite(s) or float(np.max(np.abs(s * pf - v))) > 1e-6 * max(float(np.max(np.abs(v))), 1e-300):
        return None
    return [mpmath.mpf(s) * x for x in p]


def certify_polytope_hp(F: Family, r: Fraction, st: PolytopeState, candidate_words: Sequence,
                        rho_float: float) -> Certificate | None:
    """Rigorous ``JSR <= r * c`` from a closed float polytope rebuilt at high precision (see the
    module docstring); ``None`` if a vertex cannot be rebuilt or a local basis is singular."""
    n, k, m = st.n, st.k, len(st.V)
    if m < n or any((i, j) not in st.reps for j in range(m) for i in range(k)):
        return None
    prec = HP_BITS + 64
    Pm = _mid_matrices(F, prec)
    roots = hp_roots(Pm, F.floats, candidate_words, rho_float, prec)
    index = {(st.root_of[j], st.path[j]): j for j in range(m)}
    S = HP_BITS
    Vint: list[list[int] | None] = [None] * m
    with mpmath.workprec(prec):
        rr = mpmath.mpf(r.numerator) / r.denominator
        B = [A / rr for A in Pm]
        Vmp: list = [None] * m
        for j in sorted(range(m), key=lambda t: len(st.path[t])):
            p, ro = st.path[j], st.root_of[j]
            if not p:
                if ro < len(roots):
                    sr = _scaled_root(roots[ro], st.V[j])
                    if sr is None:
                        return None           # the root order does not match the float run
                    v = mpmath.matrix(sr)
                else:
                    v = mpmath.matrix([mpmath.mpf(float(x)) for x in st.V[j]])
            else:
                parent = index.get((ro, p[:-1]))
                if parent is None or Vmp[parent] is None:
                    return None
                v = B[p[-1]] * Vmp[parent]
            Vmp[j] = v
            Vint[j] = [int(mpmath.nint(mpmath.ldexp(x, S))) for x in v]
    Vm = st.matrix()
    piv = qr_pivots(Vm)
    order = [int(p) for p in piv]
    groups: dict[tuple[int, ...], list[tuple[int, int]]] = {}
    for j in range(m):
        for i in range(k):
            supp, lam_f = st.reps[(i, j)]
            cols: list[int] = []
            # the support's largest coefficients first, then the pivoted-QR order
            pref = [int(supp[t]) for t in np.argsort(-np.abs(np.asarray(lam_f, dtype=float)),
                                                    kind="stable")]
            for t in pref + order:
                if len(cols) == n:
                    break
                if t not in cols and np.linalg.matrix_rank(Vm[:, cols + [t]]) == len(cols) + 1:
                    cols = cols + [t]
            if len(cols) < n:
                return None
            groups.setdefault(tuple(sorted(cols)), []).append((i, j))
    best, worst = Fraction(-1), (0, 0)
    with arb_precision(HP_ARB_PREC):
        two_S = arb(2) ** S
        rinv = 1 / fraction_to_arb(r)
        Ab = [arb_mat(F.arb(i)) for i in range(k)]
        for cols, keys in groups.items():
            M = arb_mat(n, n, [arb(Vint[t][a]) / two_S for a in range(n) for t in cols])
            for i in sorted({i for i, _ in keys}):
                js = [j for (ii, j) in keys if ii == i]
                X = arb_mat(n, len(js), [arb(Vint[j][a]) / two_S for a in range(n) for j in js])
                W = (Ab[i] * X) * rinv
                try:
                    lam = M.solve(W)
                except ZeroDivisionError:
                    return None
                for col, j in enumerate(js):
                    tot = arb(0)
                    for a in range(n):
                        tot += abs(lam[a, col])
                    if not tot.is_finite():
                        return None
                    hi = arb_to_fraction_bounds(tot)[1]
                    if hi > best:
                        best, worst = hi, (i, j)
    return Certificate(best, r * best, Fraction(0),
                       f"high-precision polytope ({HP_BITS}-bit vertices, Newton-refined roots), "
                       "every membership re-solved in a local vertex basis in Arb ball arithmetic",
                       worst)
