"""Seed 004's figures: basic limit functions (Sect. 4), the norms of the difference schemes
against the parameter (Sect. 5) and the Gibbs experiment (Sect. 6)."""

from __future__ import annotations

import sympy as sp

from analysis import claims as C
from schemes.seed004 import MU, NU

from .derivations import _sym


def _blf_figure(name, title, symbols_labels, level=7):
    from analysis.stationary.refinement import basic_limit_function
    series = []
    for lab, sym in symbols_labels:
        x, v = basic_limit_function(sym, level, centre=True)
        series.append(C.Series(lab, tuple(float(t) for t in x), tuple(float(t) for t in v)))
    return C.Figure(name, title, tuple(series), xlabel="x (centred)", ylabel="phi(x)")


def _norm_figure(name, title, slug, ms, L, param, xr, claimed, extra_bands=()):
    import numpy as np
    from analysis.stationary.normset import norm_function
    p = {"nu": NU, "mu": MU}[param]
    xs = np.linspace(xr[0], xr[1], 801)
    series = []
    for m in ms:
        pieces = norm_function(_sym(slug), m=m, L=L).value
        ys = []
        for x in xs:
            xq = sp.Rational(str(round(float(x), 6)))
            piece = next((pc for pc in pieces if (pc.lo is None or float(pc.lo) <= x)
                          and (pc.hi is None or x <= float(pc.hi))), pieces[-1])
            ys.append(max(float(q.eval(xq)) for q in piece.polys))
        series.append(C.Series(f"m = {m}, L = {L}", tuple(float(x) for x in xs), tuple(ys)))
    bands = [(float(claimed[0]), float(claimed[1]), "claimed range", "tab:orange")] + list(extra_bands)
    return C.Figure(name, title, tuple(series), xlabel=param, ylabel="||(1/2 S_{a_m})^L||",
                    bands=tuple(bands), hlines=((1.0, "1 (contraction threshold)"),), ylim=(0, 2.5))


def _gibbs_figure():
    import numpy as np
    from analysis.stationary.refinement import refine
    xs = np.linspace(0, 1, 11)
    ys = np.where(xs <= 0.5, np.sin(np.pi * xs), -np.sin(np.pi * xs))
    pts = np.stack([xs, ys], axis=1)
    series = [C.Series("data (6.21)", tuple(xs), tuple(ys), "k--o")]
    for nu in ("0", "1", "3/2"):
        out = refine(_sym("seed004-t-nu").subs({NU: nu}), pts, 4, closed=False, end_rule="extrapolate")
        series.append(C.Series(f"nu = {nu}, 4 steps", tuple(out[:, 0]), tuple(out[:, 1])))
    return C.Figure("gibbs-t-nu", "Experiment 6.1 data refined by S_t,nu (nu = 0 lies outside [5/7, 7])",
                    tuple(series), xlabel="x", ylabel="y")
