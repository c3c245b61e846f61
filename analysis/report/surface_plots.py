"""Figures of bivariate refinement (matplotlib, Agg backend): rendering only, no analysis here."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

__all__ = ["plot_basic_limit"]


def plot_basic_limit(points: np.ndarray, values: np.ndarray, path: str, title: str = "") -> None:
    """A heat map of the samples ``values`` at ``points`` (a triangulated colour plot) written to ``path``."""
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    try:
        tpc = ax.tripcolor(points[:, 0], points[:, 1], values, shading="gouraud", cmap="viridis")
    except (ValueError, RuntimeError):                    # too few points to triangulate
        tpc = ax.scatter(points[:, 0], points[:, 1], c=values, cmap="viridis", s=12)
    fig.colorbar(tpc, ax=ax)
    ax.set_aspect("equal")
    ax.set_title(title or "basic limit function (samples of S^n delta)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
