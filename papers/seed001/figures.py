"""Seed 001, figure data of the report: the blended curve of Sect. 4 (also used by seed 000 with
its own rules) and the chamfered quadrangle of Fig. 3. They return :class:`analysis.claims.Figure`
data; the engine renders them (:mod:`analysis.report.plots`).
"""

from __future__ import annotations

import math

import numpy as np

from analysis import claims as C
from analysis import nonuniform as nu


def blended_figure(name: str, rule: str, degrees=(2, 3, 4), levels: int = 6) -> C.Figure:
    P0, _, _ = nu.blended_example(2, rule)
    series = [C.Series("control polygon (d = 2)", tuple(map(float, P0[:, 0])), tuple(map(float, P0[:, 1])), "o--")]
    for d in degrees:
        P, u, _ = nu.blended_example(d, rule)
        r = nu.refine(P, u, degree=d, steps=levels, rule=rule)
        series.append(C.Series(f"NVPS degree {d}", tuple(map(float, r.points[:, 0])), tuple(map(float, r.points[:, 1]))))
    return C.Figure(name, f"Blended curve ({rule} rules): circle arc (u = cos), line (u = 1), hyperbola (u = cosh)",
                    tuple(series), xlabel="x", ylabel="y", equal_aspect=True)


def chamfer_figure(levels: int = 7) -> C.Figure:
    P, u, arcs = nu.chamfer_polygon(nu.CHAMFER_QUADRANGLE, nu.CHAMFER_RADII)
    r = nu.refine(P, u, degree=2, steps=levels, closed=True)
    Q = np.vstack([nu.CHAMFER_QUADRANGLE, nu.CHAMFER_QUADRANGLE[:1]])
    Cc = np.vstack([P, P[:1]])
    R = np.vstack([r.points, r.points[:1]])
    series = [C.Series("quadrangle ABCD", tuple(Q[:, 0]), tuple(Q[:, 1]), "k:"),
              C.Series("control polygon (P1 A P2 per corner)", tuple(Cc[:, 0]), tuple(Cc[:, 1]), "o--"),
              C.Series(f"NVPS degree 2, {levels} steps", tuple(map(float, R[:, 0])), tuple(map(float, R[:, 1])), "-")]
    t = np.linspace(0, 2 * math.pi, 200)
    for a in arcs:
        c, rad = a["center"], a["radius"]
        series.append(C.Series(f"circle r = {rad:g}", tuple(c[0] + rad * np.cos(t)), tuple(c[1] + rad * np.sin(t)), ":"))
    return C.Figure("001-chamfer", "Chamfering (Fig. 3(c)-(d)): r_A, r_B, r_C, r_D = 3.650669, 2, 1, 1.691966",
                    tuple(series), xlabel="x", ylabel="y", equal_aspect=True)
