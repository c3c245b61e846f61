"""Column pivots of a QR factorisation with column pivoting, in numpy (no scipy at import).

The invariant polytope picks a basis of vertices by the pivots of a pivoted QR of the vertex matrix
(``scipy.linalg.qr(V, pivoting=True)``, LAPACK ``dgeqp3``). Importing ``scipy.linalg`` costs about
0.3 s of a command that computes for 0.02 s (``subdiv holder --scheme daubechies-8``), so the pivots
are computed here by the same algorithm: LAPACK's unblocked ``dlaqp2``, which ``dgeqp3`` runs when
``min(rows, columns)`` is at most its block size 32, for polytopes with up to six vertices per
dimension (a small polytope, such as the six vertices of D8's, imports no scipy). Larger and
wider matrices go to LAPACK, which is faster per call once imported.

Examples
--------
>>> import numpy as np
>>> V = np.array([[1.0, 0.5, 0.0, 2.0], [0.0, 0.5, 1.0, 0.1], [0.0, 0.0, 0.5, 0.3]])
>>> qr_pivots(V).tolist()
[3, 2, 1, 0]
>>> import scipy.linalg
>>> scipy.linalg.qr(V, pivoting=True, mode="economic")[2].tolist()
[3, 2, 1, 0]

Algorithm
---------
Businger–Golub pivoting as LAPACK 3.x ``dlaqp2`` does it, step for step: the column of largest
(downdated) norm is swapped to the front (the first one on ties, as ``idamax``), a Householder
reflector (``dlarfg``: ``beta = -sign(alpha) hypot(alpha, ||x||)`` as ``dlapy2`` computes it, ``x``
scaled by ``1/(alpha - beta)``) is applied to the remaining columns (``dlarf``: ``w = C^T v``,
``C -= tau v w^T``), and the partial column norms are downdated by
``vn1 * sqrt(1 - (|r_ij|/vn1)^2)``, recomputed when the downdate would lose more than half of the
digits (Drmač–Bujanović's test with ``tol3z = sqrt(eps)``, ``eps = 2^-53`` as ``dlamch``).

Precision and conditioning
--------------------------
The pivots are a choice among columns of nearly equal norm; they agree with LAPACK's unless two
downdated norms differ in the last bits only, where the summation order of the BLAS kernels (which
differ from machine to machine) decides anyway. The choice of basis never decides a certificate:
the polytope's norm bound is evaluated exactly or in Arb balls for whatever basis is chosen.

References
----------
P. Businger, G. H. Golub, *Linear least squares solutions by Householder transformations*,
Numer. Math. 7 (1965) 269-276. Z. Drmač, Z. Bujanović, *On the failure of rank-revealing QR
factorization software -- a case study*, ACM TOMS 35 (2008) 12. LAPACK 3.x, ``dgeqp3``,
``dlaqp2``, ``dlarfg``, ``dlarf``, ``dlapy2``.
"""

from __future__ import annotations

import math

import numpy as np

#: ``min(rows, columns)`` up to which ``dgeqp3`` runs the unblocked ``dlaqp2`` (its block size ``nb``)
UNBLOCKED = 32
#: at most this many columns per row are pivoted here. A polytope with more vertices than six times
#: its dimension solves small LPs through SciPy's HiGHS (:func:`analysis.jsr._lp.small_lp`), so SciPy
#: is imported by then, and LAPACK's pivots cost a fifth of these per call
WIDTH = 6

#: LAPACK's ``dlamch('Epsilon')`` (relative machine precision, rounding: 2^-53)
_EPS = 2.0 ** -53
_TOL3Z = math.sqrt(_EPS)
#: ``dlamch('S') / dlamch('E')``: below it ``dlarfg`` rescales (then scipy is asked)
_SAFMIN = np.finfo(float).tiny / _EPS


class _Rescale(Exception):
    """A reflector whose norm is below ``_SAFMIN``: LAPACK rescales; this code hands over to scipy."""


def _nrm2(x: np.ndarray) -> np.ndarray:
    """``||x||_2`` of each column of ``x`` (2-d) or of ``x`` (1-d), the squares summed in extended
    precision (as the x87 ``dnrm2`` kernel of OpenBLAS) and rounded once."""
    xl = x.astype(np.longdouble)
    return np.sqrt(np.sum(xl * xl, axis=0)).astype(np.float64)


def _lapy2(x: float, y: float) -> float:
    """``sqrt(x^2 + y^2)`` as LAPACK's ``dlapy2``."""
    xa, ya = abs(x), abs(y)
    w, z = max(xa, ya), min(xa, ya)
    if z == 0.0:
        return w
    zw = z / w
    return w * math.sqrt(1.0 + zw * zw)


def qr_pivots(A: np.ndarray) -> np.ndarray:
    """The column permutation ``piv`` of ``scipy.linalg.qr(A, pivoting=True)`` (0-based), computed
    in numpy for a real float64 ``A`` (``m x n``) with ``min(m, n) <= UNBLOCKED`` and ``n <= WIDTH m``,
    by scipy otherwise (complex vertex matrices, large or wide ones; see the module docstring)."""
    A = np.asarray(A)
    m, n = A.shape
    if A.dtype != np.float64 or min(m, n) > UNBLOCKED or n > WIDTH * m or not np.all(np.isfinite(A)):
        return _scipy_pivots(A)
    try:
        return _dlaqp2(np.array(A, dtype=float, order="F"))
    except _Rescale:
        return _scipy_pivots(A)


def _scipy_pivots(A: np.ndarray) -> np.ndarray:
    """The pivots of ``scipy.linalg.qr(A, pivoting=True)``: the same ``dgeqp3`` call in every mode; ``mode="r"``
    skips forming ``Q`` (``dorgqr``), a third of the time on a wide vertex matrix."""
    import scipy.linalg

    return scipy.linalg.qr(A, pivoting=True, mode="r")[1]


def _dlaqp2(A: np.ndarray) -> np.ndarray:
    """LAPACK ``dgeqp3`` with every column free and ``dlaqp2`` for all of them; ``A`` is overwritten.
    The norm updates of one step are done for all columns at once (the same operations, elementwise)."""
    m, n = A.shape
    jpvt = list(range(n))
    vn1 = _nrm2(A)
    vn2 = vn1.copy()
    with np.errstate(divide="ignore", invalid="ignore"):       # 0/0 on the columns whose norm is 0
        for i in range(min(m, n)):
            pvt = i + int(vn1[i:].argmax())                    # idamax: the first largest
            if pvt != i:
                col = A[:, i].copy()
                A[:, i] = A[:, pvt]
                A[:, pvt] = col
                jpvt[i], jpvt[pvt] = jpvt[pvt], jpvt[i]
                vn1[pvt] = vn1[i]
                vn2[pvt] = vn2[i]
            tau = _dlarfg(A, i) if i < m - 1 else 0.0
            if i == n - 1:
                break
            if tau != 0.0:
                aii = A[i, i]
                A[i, i] = 1.0
                _dlarf_left(A, i, tau)
                A[i, i] = aii
            v1, v2 = vn1[i + 1:], vn2[i + 1:]
            ratio = np.abs(A[i, i + 1:]) / v1
            temp = np.maximum(1.0 - ratio * ratio, 0.0)
            q = v1 / v2
            again = temp * (q * q) <= _TOL3Z
            again &= v1 != 0.0
            np.copyto(v1, v1 * np.sqrt(temp), where=(v1 != 0.0) & ~again)
            if again.any():
                redo = np.flatnonzero(again)
                v1[redo] = _nrm2(A[i + 1:, i + 1 + redo]) if i < m - 1 else 0.0
                v2[redo] = v1[redo]
    return np.array(jpvt)


def _dlarfg(A: np.ndarray, i: int) -> float:
    """``dlarfg`` on ``alpha = A[i, i]``, ``x = A[i+1:, i]`` (overwritten by ``v[1:]``); returns ``tau``."""
    alpha = float(A[i, i])
    x = A[i + 1:, i]
    xl = x.astype(np.longdouble)
    xnorm = float(np.sqrt(np.dot(xl, xl)))
    if xnorm == 0.0:
        return 0.0
    beta = -math.copysign(_lapy2(alpha, xnorm), alpha)
    if abs(beta) < _SAFMIN:
        raise _Rescale
    tau = (beta - alpha) / beta
    x *= 1.0 / (alpha - beta)
    A[i, i] = beta
    return tau


def _dlarf_left(A: np.ndarray, i: int, tau: float) -> None:
    """``dlarf('Left')``: ``C = (I - tau v v^T) C`` on ``C = A[i:, i+1:]``, ``v = A[i:, i]``, over the
    rows up to the last nonzero of ``v``. (LAPACK also skips the trailing zero columns of ``C``: on
    them the update changes at most the sign of a zero.)"""
    v = A[i:, i]
    lastv = len(v)
    while lastv > 0 and v[lastv - 1] == 0.0:
        lastv -= 1
    if lastv == 0:
        return
    vv = v[:lastv]
    C = A[i:i + lastv, i + 1:]
    w = vv @ C
    C -= vv[:, None] * (tau * w)
