"""Figure data for claim kinds (issue 11): the report draws them, nothing is decided from them.

* :func:`limit_function_figure` — basic limit functions of a family at a few parameter values
  (kind ``support`` with ``plot``);
* :func:`norm_figure` — ``||(1/2 S_(a_(j+1)))^L||_inf`` against the parameter with the claimed interval
  and the exact norm set shaded (kind ``norm test`` with ``plot``);
* :func:`step_figure` — step data refined by the scheme (kind ``gibbs``).

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
>>> f = step_figure("gibbs-chaikin", "Chaikin", [("Chaikin", a)])
>>> f.name, len(f.series), max(f.series[1].y) <= 1
('gibbs-chaikin', 2, True)

Algorithm
---------
Float refinement (:func:`analysis.stationary.refinement.basic_limit_function`, ``refine``) and the
exact piecewise-polynomial norm (:func:`analysis.stationary.normset.norm_function`) sampled at 801
points: pictures, never evidence.

References
----------
Seed 004 (2023), Figs. of Sect. 4-6 (the pictures these replace).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from ..model import Figure, Series

__all__ = ["limit_function_figure", "norm_figure", "step_figure"]


def limit_function_figure(name: str, title: str, members, level: int = 7) -> Figure:
    """``members``: ``[(label, LaurentSymbol without parameters), ...]``."""
    from ...stationary.refinement import basic_limit_function

    series = []
    for label, sym in members:
        x, v = basic_limit_function(sym, level, centre=True)
        series.append(Series(label, tuple(float(t) for t in x), tuple(float(t) for t in v)))
    return Figure(name, title, tuple(series), xlabel="x (centred)", ylabel="phi(x)")


def norm_figure(name: str, title: str, a, p, j: int, L: int, xr, claimed, exact_set) -> Figure:
    """The L-step norm of the (j+1)-st difference scheme against ``p`` on ``xr`` (floats)."""
    from ...stationary.normset import norm_function

    pieces = norm_function(a, m=j + 1, L=L, param=p).value
    xs = np.linspace(float(xr[0]), float(xr[1]), 801)
    ys = []
    for x in xs:
        q = sp.Rational(str(round(float(x), 6)))
        piece = next((pc for pc in pieces if (pc.lo is None or float(pc.lo) <= x) and (pc.hi is None or x <= float(pc.hi))),
                     pieces[-1])
        ys.append(max(float(poly.eval(q)) for poly in piece.polys))
    bands = [(float(claimed[0]), float(claimed[1]), "claimed range", "tab:orange")]
    bands += [(float(lo if lo is not None else xr[0]), float(hi if hi is not None else xr[1]), f"exact norm set, L = {L}",
               "tab:green") for lo, hi, _, _ in exact_set.parts]
    return Figure(name, title, (Series(f"j = {j}, L = {L}", tuple(map(float, xs)), tuple(ys)),), xlabel=p.name,
                  ylabel=f"||(1/2 S_(a_{j + 1}))^{L}||", bands=tuple(bands), hlines=((1.0, "1 (contraction threshold)"),),
                  ylim=(0, 2.5))


def step_figure(name: str, title: str, members, steps: int = 4) -> Figure:
    """Step data (0 left of 1/2, 1 right of it, 11 points) refined ``steps`` times by each member."""
    from ...stationary.refinement import refine

    xs = np.linspace(0, 1, 11)
    pts = np.stack([xs, np.where(xs <= 0.5, 0.0, 1.0)], axis=1)
    series = [Series("step data", tuple(map(float, xs)), tuple(map(float, pts[:, 1])), "k--o")]
    for label, sym in members:
        out = refine(sym, pts, steps, closed=False, end_rule="extrapolate")
        series.append(Series(f"{label}, {steps} steps", tuple(map(float, out[:, 0])), tuple(map(float, out[:, 1]))))
    return Figure(name, title, tuple(series), xlabel="x", ylabel="y")
