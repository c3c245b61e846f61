"""Figures of ``subdiv vertex`` (matplotlib, Agg backend): rendering only, no analysis here.

:func:`plot_vertex_spectrum` draws the subdominant eigenvalue lambda, the subsubdominant mu and lambda^2
against the valence n, from the documents of :func:`analysis.vertex.valence.valence_entry` (the floats
are the midpoints of certified balls whose radii are far below the drawing's resolution).
:func:`plot_characteristic_map` draws the characteristic map at one valence: the segment's parameter lines
(:func:`analysis.vertex.charpicture.characteristic_map_lines`) rotated into every sector and scaled by
lambda^m on the inner rings.

Examples
--------
>>> import tempfile, os
>>> e = [{"n": n, "lambda": {"witness": {"float": 0.5}}, "mu": {"witness": {"float": 0.25}},
...       "curvature": {"value": "bounded"}, "c1": {"status": "certified"}} for n in (3, 4)]
>>> path = os.path.join(tempfile.mkdtemp(), "v.png")
>>> plot_vertex_spectrum(e, path, "demo") == path and os.path.getsize(path) > 0
True
>>> seg = {"lines": [[1 + 0j, 2 + 0j, 2 + 1j]], "lambda": 0.5, "source": "demo"}
>>> plot_characteristic_map(seg, 5, path, "demo", "C^1 certified") == path
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


def plot_characteristic_map(segment: dict, n: int, path: str, name: str, status: str, rings: int = 4) -> str:
    """The segment's lines under the characteristic map, in all n sectors and ``rings`` scaled copies."""
    import cmath

    from matplotlib.collections import LineCollection

    lam = segment["lambda"]
    fig, ax = plt.subplots(figsize=(6, 6))
    colours = plt.get_cmap("viridis")
    for m in range(rings):
        scale = lam ** m
        turns = [cmath.exp(2j * cmath.pi * j / n) * scale for j in range(n)]
        segs = [[((t * z).real, (t * z).imag) for z in line] for t in turns for line in segment["lines"]]
        ax.add_collection(LineCollection(segs, linewidths=0.5, colors=[colours(m / max(rings, 2))],
                                         label=f"ring {m} (x lambda^{m})"))
    ax.autoscale()
    ax.set_aspect("equal")
    ax.plot([0], [0], "k+", ms=8)
    import textwrap

    ax.set_title(f"{name}, n = {n}: characteristic map ({segment['source']})\n" + textwrap.fill(status, 90),
                 fontsize=8)
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path
