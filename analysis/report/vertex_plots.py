"""Figures of ``subdiv vertex`` (matplotlib, Agg backend): rendering only, no analysis here.

:func:`plot_vertex_spectrum` draws the subdominant eigenvalue lambda, the subsubdominant mu and lambda^2
against the valence n, from the documents of :func:`analysis.vertex.valence.valence_entry` (the floats
are the midpoints of certified balls whose radii are far below the drawing's resolution).

Examples
--------
>>> import tempfile, os
>>> e = [{"n": n, "lambda": {"witness": {"float": 0.5}}, "mu": {"witness": {"float": 0.25}},
...       "curvature": {"value": "bounded"}, "c1": {"status": "certified"}} for n in (3, 4)]
>>> path = os.path.join(tempfile.mkdtemp(), "v.png")
>>> plot_vertex_spectrum(e, path, "demo") == path and os.path.getsize(path) > 0
True
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def plot_vertex_spectrum(entries: list[dict], path: str, name: str) -> str:
    """lambda(n), mu(n) and lambda(n)^2; valences where C^1 is certified are marked."""
    rows = [e for e in entries if "lambda" in e]
    ns = [e["n"] for e in rows]
    lam = [e["lambda"]["witness"]["float"] for e in rows]
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(ns, lam, "o-", ms=3, lw=1, label="lambda (subdominant)")
    ax.plot(ns, [x * x for x in lam], "--", lw=1, color="gray", label="lambda^2")
    mu = [(e["n"], e["mu"]["witness"]["float"]) for e in rows if "mu" in e]
    if mu:
        ax.plot(*zip(*mu), "s-", ms=3, lw=1, label="mu (subsubdominant modulus)")
    c1 = [(e["n"], e["lambda"]["witness"]["float"]) for e in rows if e.get("c1", {}).get("status") == "certified"]
    if c1:
        ax.plot(*zip(*c1), "o", mfc="none", ms=8, color="tab:green", label="C^1 certified")
    ax.set_xlabel("valence n")
    ax.set_ylabel("eigenvalue")
    ax.set_title(f"{name}: leading eigenvalues at an extraordinary vertex")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path
