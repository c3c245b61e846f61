"""Figures (matplotlib, Agg backend): rendering only, no analysis here.

:func:`plot_alpha_curve` draws a certified Hölder-exponent curve; :func:`plot_blended` and
:func:`plot_chamfer` draw the NVPS examples of seed 001 (computed by :mod:`analysis.nonuniform`).

Examples
--------
>>> import tempfile, os, sympy as sp
>>> from analysis.result import Result
>>> curve = Result(value=[{"p": sp.Rational(i, 10), "lower": sp.Rational(i), "upper": sp.Rational(i) + 1,
...                        "status": "certified"} for i in range(3)], status="certified", witness={"parameter": "w"})
>>> path = os.path.join(tempfile.mkdtemp(), "a.png")
>>> plot_alpha_curve(curve, path, j=1) == path and os.path.getsize(path) > 0
True
"""

from __future__ import annotations

from typing import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

from ..nonuniform import (CHAMFER_QUADRANGLE, CHAMFER_RADII, blended_example,  # noqa: E402
                          chamfer_polygon, refine)


def plot_alpha_curve(curve, path: str, *, j: int | None = None, boundaries=(), label: str = "",
                     claimed=None) -> str:
    """alpha(p) as certified error bars; the level alpha = j, located boundaries and a claimed range."""
    rows = [r for r in curve.value if r.get("lower") is not None]
    p = [float(r["p"]) for r in rows]
    lo = [float(r["lower"]) for r in rows]
    hi = [float(r["upper"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7, 4))
    mid = [(a + b) / 2 for a, b in zip(lo, hi)]
    err = [(b - a) / 2 for a, b in zip(lo, hi)]
    ax.errorbar(p, mid, yerr=err, fmt="o-", ms=3, lw=1, capsize=2, label="alpha (certified enclosure)")
    bad = [(float(r["p"]), (float(r["lower"]) + float(r["upper"])) / 2) for r in rows if r["status"] != "certified"]
    if bad:
        ax.plot(*zip(*bad), "x", color="tab:red", label="not certified")
    if j is not None:
        ax.axhline(j, color="gray", ls="--", lw=1, label=f"alpha = {j}")
    for b in boundaries:
        x = b.get("exact_float")
        if x is None and b.get("bracket"):
            x = float(b["bracket"][0])
        if x is not None:
            ax.axvline(x, color="tab:green", lw=1)
    if claimed is not None:
        ax.axvspan(float(claimed[0]), float(claimed[1]), color="tab:orange", alpha=0.2, label="claimed range")
    ax.set_xlabel(curve.witness.get("parameter", "p"))
    ax.set_ylabel("Hölder exponent alpha")
    ax.set_title(label)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_blended(path: str, *, degrees: Sequence[int] = (2, 3, 4), levels: int = 6) -> str:
    """Figure: blended curves (circle arc, line, hyperbola) by the NVPS of several degrees."""
    fig, ax = plt.subplots(figsize=(7, 5))
    P0, u0, _ = blended_example(2)
    ax.plot(P0[:, 0], P0[:, 1], "o--", color="tab:blue", lw=0.8, ms=3, label="control polygon")
    for d, col in zip(degrees, ("black", "tab:red", "tab:green", "tab:purple")):
        P, u, _ = blended_example(d)
        r = refine(P, u, degree=d, steps=levels)
        ax.plot(r.points[:, 0], r.points[:, 1], "-", color=col, lw=1.2, label=f"NVPS degree {d}")
    ax.set_aspect("equal")
    ax.legend(fontsize=8)
    ax.set_title("NVPS: circle (u = cos), line (u = 1), hyperbola (u = cosh) pieces")
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_chamfer(path: str, *, levels: int = 7) -> str:
    """Figure: seed 001's chamfering example (Fig. 3(c)-(d)), degree 2."""
    P, u, arcs = chamfer_polygon(CHAMFER_QUADRANGLE, CHAMFER_RADII)
    r = refine(P, u, degree=2, steps=levels, closed=True)
    fig, ax = plt.subplots(figsize=(6, 5))
    Q = np.vstack([CHAMFER_QUADRANGLE, CHAMFER_QUADRANGLE[:1]])
    ax.plot(Q[:, 0], Q[:, 1], "--", color="gray", lw=0.8, label="quadrangle ABCD")
    C = np.vstack([P, P[:1]])
    ax.plot(C[:, 0], C[:, 1], "o:", color="tab:blue", ms=3, lw=0.8, label="control polygon (P1 A P2 per corner)")
    R = np.vstack([r.points, r.points[:1]])
    ax.plot(R[:, 0], R[:, 1], "-", color="black", lw=1.3, label=f"NVPS degree 2, {levels} steps")
    for a in arcs:
        ax.add_patch(Circle(a["center"], a["radius"], fill=False, ls=":", color="tab:red", lw=0.7))
    ax.set_aspect("equal")
    ax.legend(fontsize=7, loc="lower left")
    ax.set_title("Chamfering (seed 001, Fig. 3): r_A, r_B, r_C, r_D = 3.650669, 2, 1, 1.691966")
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path
