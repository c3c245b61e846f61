"""Refinement on regular grids: ``S_a^n`` applied to the delta sequence (the basic limit function's samples).

``(S_a f)(alpha) = sum_beta a(alpha - M beta) f(beta)``; after ``n`` steps the value at ``alpha`` sits at the point
``M^{-n} alpha`` of the coarse lattice, drawn in the plane by the grid's embedding (``quad``: the identity;
``triangular``: ``e1 -> (1, 0)``, ``e2 -> (-1/2, sqrt(3)/2)``, so that ``e1 + e2`` is the unit vector at 60
degrees). This is an illustration in floating point (numpy), not a certified computation.

Examples
--------
>>> from analysis.bivariate.mask import BivariateMask
>>> pts, vals = basic_limit_samples(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)"), 2)
>>> len(vals), float(vals.max()), float(vals.sum())
(49, 1.0, 16.0)
"""

from __future__ import annotations

import numpy as np

from ..result import AnalysisError
from .mask import BivariateMask

__all__ = ["basic_limit_samples", "EMBEDDINGS", "MAX_POINTS"]

#: the most samples one refinement may produce
MAX_POINTS = 400_000
EMBEDDINGS = {"quad": np.eye(2), "triangular": np.array([[1.0, -0.5], [0.0, np.sqrt(3) / 2]])}


def basic_limit_samples(a: BivariateMask, steps: int, grid: str = "quad") -> tuple[np.ndarray, np.ndarray]:
    """``(points, values)``: ``S_a^steps delta`` at the points ``E M^{-steps} alpha`` (module docstring)."""
    if a.params:
        raise AnalysisError("give values to the parameters before refining")
    if grid not in EMBEDDINGS:
        raise AnalysisError(f"grid must be one of {', '.join(EMBEDDINGS)}, not {grid!r}")
    if not 0 <= steps <= 12:
        raise AnalysisError("--refine takes 0 to 12 steps")
    D = a.dilation
    M = np.array(D.matrix, dtype=np.int64)
    (i0, j0), (i1, j1) = a.support_box
    mask = np.zeros((i1 - i0 + 1, j1 - j0 + 1))
    for (i, j), v in a:
        mask[i - i0, j - j0] = float(v)
    f = {(0, 0): 1.0}
    for _ in range(steps):
        g: dict[tuple[int, int], float] = {}
        for (bx, by), fv in f.items():
            if fv == 0.0:
                continue
            mx, my = M[0, 0] * bx + M[0, 1] * by, M[1, 0] * bx + M[1, 1] * by
            for (i, j), v in a.coeffs.items():
                key = (mx + i, my + j)
                g[key] = g.get(key, 0.0) + float(v) * fv
        if len(g) > MAX_POINTS:
            raise AnalysisError(f"{steps} steps give more than {MAX_POINTS} samples: take fewer steps")
        f = g
    alphas = np.array(sorted(f), dtype=float)
    vals = np.array([f[k] for k in sorted(f)])
    Minv_n = np.linalg.matrix_power(np.linalg.inv(M.astype(float)), steps)
    pts = alphas @ Minv_n.T @ EMBEDDINGS[grid].T
    return pts, vals
