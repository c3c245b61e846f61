"""Figures (matplotlib, Agg backend): rendering only, no analysis here.

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

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


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
