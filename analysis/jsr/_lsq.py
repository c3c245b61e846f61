"""Least-squares solutions of small real systems: ``numpy.linalg.lstsq`` without its per-call checks.

The polytope polishes every LP solution and the parametric strip certificate re-solves every image on the
support of the previous sub-interval by least squares (thousands of 4 x 3 to 16 x 40 systems per run), where
``numpy.linalg.lstsq`` spends more time on its argument checks and result copies than LAPACK spends
solving. :func:`lstsq_solution` calls the same LAPACK driver (``dgelsd``) through the same ufunc with the
same ``rcond`` and error handling, so the solution is the same, bit for bit (a test compares them).

Examples
--------
>>> import numpy as np
>>> A = np.array([[1.0, 0.0], [0.0, 2.0], [1.0, 1.0]])
>>> b = np.array([1.0, 2.0, 2.0])
>>> lstsq_solution(A, b).tolist() == np.linalg.lstsq(A, b, rcond=None)[0].tolist()
True
"""

from __future__ import annotations

import numpy as np

__all__ = ["lstsq_solution"]

try:   # the ufunc numpy.linalg.lstsq calls, and the handler it installs for a failed SVD
    from numpy.linalg import _umath_linalg
    from numpy.linalg._linalg import _raise_linalgerror_lstsq
except ImportError:  # pragma: no cover - another numpy layout
    _umath_linalg = None

_EPS = float(np.finfo(np.float64).eps)


def lstsq_solution(A: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``numpy.linalg.lstsq(A, b, rcond=None)[0]`` for a float64 matrix ``A`` (``m x n``, ``m, n >= 1``) and
    a float64 vector ``b``: the minimum-norm least-squares solution, the same numbers."""
    if _umath_linalg is None or A.dtype != np.float64 or b.dtype != np.float64 or A.ndim != 2 \
            or b.ndim != 1 or 0 in A.shape:
        return np.linalg.lstsq(A, b, rcond=None)[0]
    m, n = A.shape
    with np.errstate(call=_raise_linalgerror_lstsq, invalid="call", over="ignore", divide="ignore",
                     under="ignore"):
        x = _umath_linalg.lstsq(A, b[:, None], _EPS * max(m, n), signature="ddd->ddid")[0]
    return x[:, 0].copy()
