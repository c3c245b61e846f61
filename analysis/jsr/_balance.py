"""Balancing of the starting vertices when there are several leading products.

When two or more products ``P_1, ..., P_m`` (candidates for spectrum maximizing products, or
the two eigenvectors of one product with ``lambda`` and ``-lambda``) all reach the scale ``r``,
the invariant polytope must start from *all* their leading eigenvectors ``v_1, ..., v_m``
(Guglielmi–Protasov 2016). With unit scalings the orbit of one root can reach another root's
direction with a coefficient above 1; that root is then interior, the orbit keeps approaching it
from outside and the polytope never closes. The cure is to start from ``alpha_1 v_1, ...,
alpha_m v_m`` with *balancing* factors: with ``l_j`` the left eigenvector of ``P_j``
(``<l_j, v_j> = 1``; along ``P_j``-powers every point ``x`` tends to ``<l_j, x> v_j``) and

    q_ij = sup { |<l_j, B_w v_i>| : w a word },      B_s = A_s / r,

the polytope can close only if ``alpha_i q_ij < alpha_j`` for all ``i != j``. In logarithms this
is a system of difference constraints; :func:`balanced_roots` takes the factors that maximize the
smallest margin ``mu = min_{i != j} (log alpha_j - log alpha_i - log q_ij)`` (a small linear
program). The ``q_ij`` are estimated from a depth-limited orbit tree (a beam of the largest
points), so the factors are heuristics: they only decide whether and how fast the float phase
closes. The certificate (:func:`analysis.jsr._polytope.certify_polytope`) is indifferent to how
the starting vertices were scaled.

Examples
--------
Two diagonal matrices with equal spectral radius: each root is fixed by its own matrix and
killed by the other, so any factors balance (the margin is large):

>>> import numpy as np
>>> A = [np.diag([1.0, 0.5]), np.diag([0.5, 1.0])]
>>> roots, info = balanced_roots(A, 1.0, [(0,), (1,)])
>>> len(roots), info["margin"] > 1
(2, True)

References
----------
N. Guglielmi, V. Yu. Protasov, *Invariant polytopes of sets of matrices with application to
regularity of wavelets and subdivisions*, SIAM J. Matrix Anal. Appl. 37 (2016) 18-52 (balancing).
T. Mejstrik, *Algorithm 1011: Improved invariant polytope algorithm and applications*, ACM Trans.
Math. Softw. 46(3) (2020) 29.
"""

from __future__ import annotations

import itertools
import warnings
from typing import Any, Sequence

import numpy as np

#: bound on |log alpha| (the factors stay within e^-8 .. e^8)
LOG_ALPHA_MAX = 8.0


def eigen_groups(B: Sequence[np.ndarray], word: Sequence[int], rel: float = 1e-8):
    """``[(lam, u, left)]`` for the eigenvalues of maximal modulus of ``B_{w_1} ... B_{w_L}``
    (of a conjugate pair only the member with ``Im lam > 0``), ``u`` normalized by its largest
    entry (``u[q] = 1`` exactly, ``q = argmax |u|``), ``left`` with ``<left, u> = 1``. A real
    eigenvalue gives one real root ``u``, a complex one the two roots ``Re u, Im u``
    (:func:`group_roots`); the high-precision certificate refines the same pairs."""
    n = B[0].shape[0]
    P = np.eye(n)
    for i in word:
        P = P @ B[i]
    w, U = np.linalg.eig(P)
    wl, Ul = np.linalg.eig(P.T)
    top = float(np.max(np.abs(w)))
    out = []
    for lam, u in zip(w, U.T):
        if abs(lam) < top * (1 - rel) or lam.imag < -1e-12 * top:
            continue
        real = abs(lam.imag) <= 1e-12 * top
        j = int(np.argmin(np.abs(wl - lam)))
        l = Ul[:, j]
        u = u / u[int(np.argmax(np.abs(u)))]
        if real:
            lam, u, l = complex(lam.real, 0.0), u.real.astype(complex), l.real.astype(complex)
        d = np.sum(l * u)                              # <l, u> = l^T u
        if abs(d) < 1e-300:
            continue
        out.append((complex(lam), u, l / d))
    return out


def group_roots(lam: complex, u: np.ndarray) -> list[np.ndarray]:
    """The real root vectors of one eigen group: ``[u]`` (real) or ``[Re u, Im u]``."""
    return [u.real.copy()] if lam.imag == 0 else [u.real.copy(), u.imag.copy()]


def _orbit_sup(B: Sequence[np.ndarray], roots: list[np.ndarray], funcs: list[np.ndarray],
               depth: int, beam: int) -> np.ndarray:
    """``max |<l_j, B_w x>|`` over the roots ``x`` and words of length ``<= depth`` kept in a
    beam of the points largest in norm or in some functional."""
    F = np.array(funcs)                                # (m, n), maybe complex
    best = np.max(np.abs(np.array(roots) @ F.T), axis=0)
    front = list(roots)
    for _ in range(depth):
        new = np.array([Bs @ x for x in front for Bs in B])
        vals = np.abs(new @ F.T)                       # (points, m)
        best = np.maximum(best, vals.max(axis=0))
        keep = set(np.argsort(-np.linalg.norm(new, axis=1))[:beam].tolist())
        per = max(beam // (2 * len(funcs)), 1)
        for j in range(len(funcs)):
            keep.update(np.argsort(-vals[:, j])[:per].tolist())
        front = [new[t] for t in sorted(keep)]
    return best


def _factors(B: Sequence[np.ndarray], groups: list, depth: int, beam: int
             ) -> tuple[np.ndarray, float | None]:
    """Balancing factors of the groups ``[(real roots, left functional)]`` and the margin."""
    m = len(groups)
    if m <= 1:
        return np.ones(m), None
    from scipy.optimize import linprog          # imported only when an LP is solved (about 1 s)

    funcs = [g[1] for g in groups]
    q = np.array([_orbit_sup(B, g[0], funcs, depth, beam) for g in groups])
    q = np.maximum(q, 1e-300)
    # variables t_0..t_{m-1}, mu; maximize mu s.t. t_i - t_j + mu <= -log q_ij, t_0 = 0
    rows, rhs = [], []
    for i, j in itertools.permutations(range(m), 2):
        row = np.zeros(m + 1)
        row[i], row[j], row[m] = 1.0, -1.0, 1.0
        rows.append(row)
        rhs.append(-np.log(q[i, j]))
    bounds = [(0.0, 0.0)] + [(-LOG_ALPHA_MAX, LOG_ALPHA_MAX)] * (m - 1) + [(None, None)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = linprog(np.r_[np.zeros(m), -1.0], A_ub=np.array(rows), b_ub=np.array(rhs),
                      bounds=bounds, method="highs")
    if res.status != 0 or res.x is None:
        return np.ones(m), None
    return np.exp(res.x[:m]), float(res.x[m])


def interior_fillers(mats: Sequence[np.ndarray], r: float, words: Sequence[Sequence[int]],
                     roots_info: dict[str, Any], *, theta: float = 0.5, depth: int = 8,
                     beam: int = 200, rel: float = 1e-8) -> list[np.ndarray]:
    """Extra starting vertices ``theta e_i / q_i`` (``e_i`` the unit vectors) that make the
    polytope full-dimensional from the start, each scaled so that its orbit stays well inside:
    ``q_i = max |<l, B_w e_i>|`` over a beam of the orbit, ``l`` the left leading eigenvectors of
    the candidates normalized against their balanced roots (``<l, alpha u> = 1``).

    Why: the orbit of the leading eigenvectors alone spans ``R^n`` only numerically (Daubechies
    D20+: condition numbers 1e3 to 1e12); a polytope that is flat in some directions gets
    vertices there only late and at the wrong scale, and the images of those converge to the
    s.m.p. eigenvector from outside at the rate of its second eigenvalue (thousands of barely
    outside vertices). Small fillers in every direction remove that phase: Daubechies D30 and
    D32 close with about 150 vertices instead of not at all. They are vertices like any other,
    so the certificate is unchanged.

    >>> import numpy as np
    >>> A = [np.array([[1.0, 1.0], [0.0, 1.0]]), np.array([[1.0, 0.0], [1.0, 1.0]])]
    >>> roots, info = balanced_roots(A, 1.618033988749895, [(0, 1)])
    >>> f = interior_fillers(A, 1.618033988749895, [(0, 1)], info)
    >>> len(f), all(float(np.max(np.abs(x))) < 1 for x in f)
    (2, True)
    """
    B = [np.asarray(A, dtype=float) / r for A in mats]
    n = B[0].shape[0]
    eig = [(lam, u, l) for w in words for lam, u, l in eigen_groups(B, w, rel)]
    if not eig:
        return []
    alpha = roots_info.get("factors") or [1.0] * len(eig)
    Ls = np.array([l / a for (_, _, l), a in zip(eig, alpha)])
    out = []
    for i in range(n):
        e = np.zeros(n)
        e[i] = 1.0
        front = [e]
        best = float(np.max(np.abs(Ls @ e)))
        for _ in range(depth):
            new = np.array([Bs @ y for y in front for Bs in B])
            vals = np.max(np.abs(new @ Ls.T), axis=1)
            order = np.argsort(-vals)[:beam]
            front = [new[t] for t in order]
            best = max(best, float(vals[order[0]]))
        if best > 0 and np.isfinite(best):
            out.append(theta * e / best)
    return out


def balanced_roots(mats: Sequence[np.ndarray], r: float, words: Sequence[Sequence[int]], *,
                   depth: int = 8, beam: int = 200, rel: float = 1e-8, complex_roots: bool = False
                   ) -> tuple[list[np.ndarray], dict[str, Any]]:
    """Starting vertices for the invariant polytope of ``{A_i / r}``: the leading eigenvectors
    of the candidate products ``words``, scaled by balancing factors (module docstring).

    ``complex_roots=True``: roots for the complex polytope (:mod:`analysis.jsr._complex`), i.e.
    ``alpha u`` for a real eigenvalue and ``alpha u, alpha conj(u)`` for a complex one, instead
    of the real roots ``alpha u`` resp. ``alpha Re u, alpha Im u``.

    Returns ``(roots, info)`` with ``info = {"factors": [...], "margin": mu, "groups": m}``
    (``margin`` ``None`` for a single group; a negative margin means the estimated ``q_ij``
    admit no balancing: the factors are then the least bad ones).
    """
    B = [np.asarray(A, dtype=float) / r for A in mats]
    eig = [(lam, u, l) for w in words for lam, u, l in eigen_groups(B, w, rel)]
    groups = [(group_roots(lam, u), l) for lam, u, l in eig]
    alpha, mu = _factors(B, groups, depth, beam)
    if complex_roots:
        roots = []
        for a, (lam, u, _) in zip(alpha, eig):
            roots.extend([a * u] if lam.imag == 0 else [a * u, a * u.conj()])
    else:
        roots = [a * x for a, g in zip(alpha, groups) for x in g[0]]
    return roots, {"factors": [float(a) for a in alpha], "margin": mu, "groups": len(groups)}
