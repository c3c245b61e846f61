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

__all__ = ["basic_limit_samples", "support_boxes", "check_steps", "EMBEDDINGS", "MAX_POINTS", "MAX_STEPS"]

#: the most samples one refinement may produce (the points of the bounding box of the support after each step)
MAX_POINTS = 400_000
#: the most steps of one refinement
MAX_STEPS = 12
EMBEDDINGS = {"quad": np.eye(2), "triangular": np.array([[1.0, -0.5], [0.0, np.sqrt(3) / 2]])}


def support_boxes(a: BivariateMask, steps: int) -> list[tuple[int, int, int, int]]:
    """The bounding boxes ``(x0, y0, x1, y1)`` of ``supp S_a^n delta`` for ``n = 1 .. steps``, exactly, before
    any refinement.

    Algorithm: ``supp S_a^n delta`` lies in ``A + M A + ... + M^(n-1) A`` (``A = supp a``), and the bounding box
    of a Minkowski sum is the sum of the bounding boxes, each ``M^k A`` taken point by point (integers).

    >>> from analysis.bivariate.mask import BivariateMask
    >>> support_boxes(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)"), 3)
    [(-1, -1, 1, 1), (-3, -3, 3, 3), (-7, -7, 7, 7)]
    """
    (m00, m01), (m10, m11) = a.dilation.matrix
    pts = list(a.coeffs)
    box = (0, 0, 0, 0)
    out = []
    for _ in range(steps):
        xs, ys = [x for x, _ in pts], [y for _, y in pts]
        box = (box[0] + min(xs), box[1] + min(ys), box[2] + max(xs), box[3] + max(ys))
        out.append(box)
        pts = [(m00 * x + m01 * y, m10 * x + m11 * y) for x, y in pts]
    return out


def box_points(box: tuple[int, int, int, int]) -> int:
    """The number of integer points of a box ``(x0, y0, x1, y1)``."""
    return (box[2] - box[0] + 1) * (box[3] - box[1] + 1)


def check_steps(a: BivariateMask, steps: int) -> list[tuple[int, int, int, int]]:
    """:func:`support_boxes`, or an :class:`AnalysisError` saying how many steps fit in :data:`MAX_POINTS`."""
    if not 0 <= steps <= MAX_STEPS:
        raise AnalysisError(f"--refine takes 0 to {MAX_STEPS} steps, not {steps}")
    boxes = support_boxes(a, steps)
    sizes = [box_points(b) for b in boxes]
    if sizes and sizes[-1] > MAX_POINTS:
        fit = sum(1 for n in sizes if n <= MAX_POINTS)
        raise AnalysisError(f"--refine {steps} would give up to {sizes[-1]} samples (the bounding box of the "
                            f"support; limit {MAX_POINTS}): take --refine {fit} or fewer")
    return boxes


def basic_limit_samples(a: BivariateMask, steps: int, grid: str = "quad") -> tuple[np.ndarray, np.ndarray]:
    """``(points, values)``: ``S_a^steps delta`` at the points ``E M^{-steps} alpha`` (module docstring).

    Algorithm: the mask is converted to floats once; the values live on the bounding box of the support after
    each step (:func:`support_boxes`, checked against :data:`MAX_POINTS` before any step). A step adds, for each
    mask coefficient ``a(gamma)``, ``a(gamma) f(beta)`` at ``M beta + gamma`` for all nonzero ``f(beta)`` at once
    (one numpy scatter per coefficient: the points ``M beta + gamma`` of one ``gamma`` are distinct). The
    samples are the points reached from nonzero values.
    """
    if a.params:
        raise AnalysisError("give values to the parameters before refining")
    if grid not in EMBEDDINGS:
        raise AnalysisError(f"grid must be one of {', '.join(EMBEDDINGS)}, not {grid!r}")
    boxes = check_steps(a, steps)
    M = np.array(a.dilation.matrix, dtype=np.int64)
    offsets = np.array(list(a.coeffs), dtype=np.int64).reshape(-1, 2)
    weights = np.array([float(v) for v in a.coeffs.values()])
    alphas = np.zeros((1, 2), dtype=np.int64)                    # the delta sequence
    vals = np.ones(1)
    for x0, y0, x1, y1 in boxes:
        live = vals != 0.0
        beta, fv = alphas[live], vals[live]
        height = y1 - y0 + 1
        Mb = beta @ M.T
        base = (Mb[:, 0] - x0) * height + (Mb[:, 1] - y0)
        g = np.zeros((x1 - x0 + 1) * height)
        reached = np.zeros(g.size, dtype=bool)
        for (i, j), w in zip(offsets.tolist(), weights.tolist()):
            at = base + (i * height + j)
            g[at] += w * fv
            reached[at] = True
        idx = np.flatnonzero(reached)                              # increasing: alpha in lexicographic order
        alphas = np.stack([idx // height + x0, idx % height + y0], axis=1)
        vals = g[idx]
    Minv_n = np.linalg.matrix_power(np.linalg.inv(M.astype(float)), steps)
    pts = alphas.astype(float) @ Minv_n.T @ EMBEDDINGS[grid].T
    return pts, vals
