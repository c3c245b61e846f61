"""Reproduction of circles (``u = cos``), hyperbolas (``u = cosh``) and parabolas (``u = 1``);
seed 001's chamfering (Algorithm 2, Fig. 3) and the blended example (Fig. 2).

The figures of these examples are drawn by :func:`analysis.report.plots.plot_blended` and
:func:`analysis.report.plots.plot_chamfer` (rendering lives in the report layer).
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from ..result import NUMERICAL, AnalysisError, Result
from .refinement import _check_degree, step


def _scale_factor(kind: str, alpha: float, d: int) -> float:
    """Limit radius / control radius for a regular (exponential) polygon of half-step ``alpha``:
    ``cos(a) (sin(a)/a)^{d-2}`` (trigonometric) or ``cosh(a)(sinh(a)/a)^{d-2}`` (hyperbolic)."""
    if alpha == 0:
        return 1.0
    if kind == "trigonometric":
        return math.cos(alpha) * (math.sin(alpha) / alpha) ** (d - 2)
    return math.cosh(alpha) * (math.sinh(alpha) / alpha) ** (d - 2)


def circle_polygon(radius: float, angles: Sequence[float] | None = None, *, center=(0.0, 0.0), start: float = 0.0,
                   step_angle: float = math.pi / 6, count: int = 8, degree: int = 2):
    """Control points and edge parameters whose NVPS limit is exactly an arc of the circle
    ``|x - center| = radius``: ``P_j = center + rho (cos(start + j step), sin(...))``,
    ``u = cos(step/2)``, ``rho = radius / (cos(a) (sin(a)/a)^{d-2})``, ``a = step/2``.

    >>> P, u = circle_polygon(1.0, step_angle=math.pi / 2, count=4, degree=2)
    >>> round(float(np.hypot(*P[0])), 12), round(u[0], 12)      # rho = 1/cos(pi/4), u = cos(pi/4)
    (1.414213562373, 0.707106781187)
    """
    d = _check_degree(degree)
    a = step_angle / 2
    if not 0 < a < math.pi / 2:
        raise AnalysisError("step_angle must be in (0, pi)")
    rho = radius / _scale_factor("trigonometric", a, d)
    t = start + step_angle * np.arange(count)
    P = np.column_stack([center[0] + rho * np.cos(t), center[1] + rho * np.sin(t)])
    return P, [math.cos(a)] * (count - 1)


def hyperbola_polygon(a_axis: float = 1.0, b_axis: float = 1.0, *, center=(0.0, 0.0), start: float = 0.0,
                      step_param: float = 0.5, count: int = 8, degree: int = 2):
    """Control points and parameters whose limit is the hyperbola branch
    ``(a cosh t, b sinh t) + center``: spacing ``step_param`` in t, ``u = cosh(step/2)``.

    >>> P, u = hyperbola_polygon(step_param=1.0, count=3, degree=2)
    >>> round(u[0], 12)
    1.127625965206
    """
    d = _check_degree(degree)
    al = step_param / 2
    if not al > 0:
        raise AnalysisError("step_param must be > 0")
    rho = 1 / _scale_factor("hyperbolic", al, d)
    t = start + step_param * np.arange(count)
    P = np.column_stack([center[0] + rho * a_axis * np.cosh(t), center[1] + rho * b_axis * np.sinh(t)])
    return P, [math.cosh(al)] * (count - 1)


def parabola_polygon(c2: float = 0.5, *, start: float = -1.0, step_param: float = 0.5, count: int = 8,
                     degree: int = 2):
    """Control points (u = 1) whose limit is the parabola ``(t, c2 t^2)``: the B-spline
    quasi-interpolant ``P_j = (t_j, c2 t_j^2 - c2 h^2 (d+1)/12)`` (the degree-d B-spline has
    variance ``(d+1)/12``).

    >>> P, u = parabola_polygon(1.0, start=0.0, step_param=1.0, count=3, degree=2)
    >>> P.tolist(), u
    ([[0.0, -0.25], [1.0, 0.75], [2.0, 3.75]], [1.0, 1.0])
    """
    d = _check_degree(degree)
    t = start + step_param * np.arange(count)
    P = np.column_stack([t, c2 * t ** 2 - c2 * step_param ** 2 * (d + 1) / 12])
    return P, [1.0] * (count - 1)


def reproduce(kind: str = "circle", *, degree: int = 2, levels: int = 8, count: int = 10, spacing: float | None = None,
              arithmetic: str = "float", prec: int = 113) -> Result:
    """Reproduction test: refine the control polygon of an exact curve (``"circle"`` radius 1,
    ``"hyperbola"`` (cosh t, sinh t), ``"parabola"`` (t, t^2/2)) and measure

    * ``deviation_k``: max distance of the level-k points from the curve (-> 0 like 4^{-k});
    * ``form_error_k``: for circle/hyperbola, how far the level-k points are from the *exact*
      level-k polygon predicted by the theory (a scaled regular polygon): rounding level if the
      reproduction is exact.

    >>> r = reproduce("circle", degree=3, levels=6)
    >>> r.witness["form_error"][-1] < 1e-13, r.witness["rate"][-1] > 3.9
    (True, True)
    """
    d = _check_degree(degree)
    if kind == "circle":
        s = spacing or math.pi / 6
        P, u = circle_polygon(1.0, step_angle=s, count=count, degree=d)
        dist = lambda X: np.abs(np.hypot(X[:, 0], X[:, 1]) - 1.0)  # noqa: E731
    elif kind == "hyperbola":
        s = spacing or 0.4
        P, u = hyperbola_polygon(1.0, 1.0, start=-s * (count - 1) / 2, step_param=s, count=count, degree=d)

        def dist(X):
            # distance to x^2 - y^2 = 1 (x > 0): Newton on the foot point parameter
            t = np.arcsinh(X[:, 1])
            for _ in range(30):
                cx, sy = np.cosh(t), np.sinh(t)
                g = (cx - X[:, 0]) * sy + (sy - X[:, 1]) * cx
                dg = sy * sy + (cx - X[:, 0]) * cx + cx * cx + (sy - X[:, 1]) * sy
                t = t - g / dg
            return np.hypot(np.cosh(t) - X[:, 0], np.sinh(t) - X[:, 1])
    elif kind == "parabola":
        s = spacing or 0.5
        P, u = parabola_polygon(0.5, start=-s * (count - 1) / 2, step_param=s, count=count, degree=d)

        def dist(X):
            t = X[:, 0].copy()
            for _ in range(40):
                g = (t - X[:, 0]) + (t * t / 2 - X[:, 1]) * t
                dg = 1 + t * t + (t * t / 2 - X[:, 1])
                t = t - g / dg
            return np.hypot(t - X[:, 0], t * t / 2 - X[:, 1])
    else:
        raise AnalysisError("kind must be 'circle', 'hyperbola' or 'parabola'")
    devs, forms = [], []
    Pk, vk = np.asarray(P, dtype=float), 1 - np.asarray(u, dtype=float)
    for k in range(levels + 1):
        devs.append(float(dist(Pk).max()))
        if kind == "circle":
            rad = np.hypot(Pk[:, 0], Pk[:, 1])
            ang = np.unwrap(np.arctan2(Pk[:, 1], Pk[:, 0]))
            forms.append(float(max(np.ptp(rad), np.ptp(np.diff(ang)) if len(ang) > 2 else 0.0)))
        elif kind == "hyperbola":
            # points must be rho_k (cosh, sinh)(t0 + j s_k) for one rho_k: x^2 - y^2 constant, equal spacing
            q = Pk[:, 0] ** 2 - Pk[:, 1] ** 2
            tt = np.arctanh(Pk[:, 1] / Pk[:, 0])
            forms.append(float(max(np.ptp(q) / q.mean(), np.ptp(np.diff(tt)))))
        else:
            forms.append(float("nan"))
        if k < levels:
            Pk, vk = step(Pk, vk, d)
    rate = [devs[k] / devs[k + 1] for k in range(levels) if devs[k + 1] > 0]
    return Result(value=devs[-1], status=NUMERICAL,
                  witness={"deviation": devs, "form_error": forms, "rate": rate, "kind": kind, "degree": d,
                           "note": "deviation = max distance of level-k points from the exact limit curve "
                                   "(float64, ~1e-16 relative); form_error ~ 1e-15 means the level-k polygon is "
                                   "exactly the predicted scaled regular polygon, so the limit is the curve"},
                  provenance={"method": "float64 refinement; closed-form limit radius "
                                        "cos(a)(sin a/a)^(d-2) / cosh(a)(sinh a/a)^(d-2)", "levels": levels})


def chamfer_polygon(vertices, radii, *, closed: bool = True):
    """Seed 001's Algorithm 2 (degree 2): replace each corner ``A`` (neighbours ``B``, ``C``,
    angle ``theta``) with a radius ``r_A > 0`` by ``P1, A, P2`` on the two edges at distance
    ``2 r cot(theta/2)`` from ``A`` and give the edges ``P1 A``, ``A P2`` the parameter
    ``u_A = sin(theta/2)`` (= cos of half the arc angle); all other edges get ``u = 1``. The degree-2
    limit is then exactly: straight segments joined by circular arcs of radius ``r_A`` tangent to
    both edges (at the midpoints of ``P1 A`` and ``A P2``).

    >>> P, u, arcs = chamfer_polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [1, 1, 1, 1])
    >>> len(P), [round(x, 6) for x in u[:3]]
    (12, [0.707107, 0.707107, 1.0])
    """
    V = np.asarray(vertices, dtype=float)
    n = len(V)
    if len(radii) != n:
        raise AnalysisError("give one radius per vertex (0 = keep the corner)")
    pts, params, arcs = [], [], []
    for i in range(n):
        A = V[i]
        r = float(radii[i])
        if not closed and i in (0, n - 1):
            pts.append(A)
            params.append(1.0)
            continue
        B, C = V[i - 1], V[(i + 1) % n]
        eb, ec = (B - A) / np.linalg.norm(B - A), (C - A) / np.linalg.norm(C - A)
        theta = math.acos(max(-1.0, min(1.0, float(eb @ ec))))
        if r <= 0:
            pts += [A, A, A]
            params += [1.0, 1.0, 1.0]
            continue
        t = r / math.tan(theta / 2)
        if 2 * t > min(np.linalg.norm(B - A), np.linalg.norm(C - A)) + 1e-12:
            raise AnalysisError(f"radius {r} too large at vertex {i}: needs 2 r cot(theta/2) <= shortest edge")
        P1, P2 = A + 2 * t * eb, A + 2 * t * ec
        bis = (eb + ec) / np.linalg.norm(eb + ec)
        O = A + bis * r / math.sin(theta / 2)
        arcs.append({"vertex": i, "center": O.tolist(), "radius": r, "E": (A + t * eb).tolist(), "F": (A + t * ec).tolist()})
        u = math.sin(theta / 2)
        pts += [P1, A, P2]
        params += [u, u, 1.0]
    P = np.array(pts)
    u = params if closed else params[:-1]
    return P, u, arcs


#: Seed 001, Fig. 3(c): the quadrangle ABCD and the radii r_A, r_B, r_C, r_D.
CHAMFER_QUADRANGLE = ((-6.3825, 1.6082), (3.2028, 4.2398), (10.0, -6.7544), (-8.4101, -6.7544))
CHAMFER_RADII = (3.650669, 2.0, 1.0, 1.691966)


def _distance_to_chamfer(X, vertices, arcs):
    """Distance of points X to the chamfered shape (segments between tangent points + arcs)."""
    V = np.asarray(vertices, dtype=float)
    n = len(V)
    by_vertex = {a["vertex"]: a for a in arcs}
    best = np.full(len(X), np.inf)
    for i in range(n):
        j = (i + 1) % n
        S = np.array(by_vertex[i]["F"]) if i in by_vertex else V[i]
        T = np.array(by_vertex[j]["E"]) if j in by_vertex else V[j]
        ST = T - S
        tt = np.clip(((X - S) @ ST) / (ST @ ST), 0, 1)
        best = np.minimum(best, np.linalg.norm(X - (S + tt[:, None] * ST), axis=1))
    for a in arcs:
        O, r = np.array(a["center"]), a["radius"]
        E, F = np.array(a["E"]) - O, np.array(a["F"]) - O
        Y = X - O
        ang = np.arctan2(Y[:, 1], Y[:, 0])
        ae, af = math.atan2(E[1], E[0]), math.atan2(F[1], F[0])
        span = (af - ae) % (2 * math.pi)
        if span > math.pi:
            ae, af, span = af, ae, 2 * math.pi - span
        inside = ((ang - ae) % (2 * math.pi)) <= span
        d_arc = np.where(inside, np.abs(np.linalg.norm(Y, axis=1) - r), np.inf)
        best = np.minimum(best, d_arc)
    return best


def chamfer_example(*, levels: int = 8, degree: int = 2) -> Result:
    """Seed 001's chamfering example (Fig. 3(c)-(d)): max distance of the refined points, and of
    the edge midpoints (which are limit points for d = 2), from the exact chamfered shape.

    >>> r = chamfer_example(levels=6)
    >>> r.witness["midpoint_deviation"][-1] < 1e-12, r.witness["rate"][-1] > 3.5
    (True, True)
    """
    d = _check_degree(degree)
    P, u, arcs = chamfer_polygon(CHAMFER_QUADRANGLE, CHAMFER_RADII)
    Pk, vk = P.copy(), 1 - np.asarray(u)
    devs, mids = [], []
    for k in range(levels + 1):
        devs.append(float(_distance_to_chamfer(Pk, CHAMFER_QUADRANGLE, arcs).max()))
        M = (Pk + np.roll(Pk, -1, axis=0)) / 2
        mids.append(float(_distance_to_chamfer(M, CHAMFER_QUADRANGLE, arcs).max()))
        if k < levels:
            Pk, vk = step(Pk, vk, d, closed=True)
    rate = [devs[k] / devs[k + 1] for k in range(levels)]
    return Result(value=devs[-1], status=NUMERICAL,
                  witness={"deviation": devs, "midpoint_deviation": mids, "rate": rate, "arcs": arcs,
                           "u": [float(x) for x in u], "degree": d,
                           "note": "for d = 2 the edge midpoints are limit points; their distance from the exact "
                                   "shape is rounding error, so the chamfer is reproduced exactly. For d > 2 the "
                                   "three control points per corner do not reproduce the arc."},
                  provenance={"method": "float64, exact geometry of segments and arcs", "levels": levels})


def blended_example(degree: int = 2, rule: str = "seed001"):
    """A control polygon with a circular piece (u = cos), a straight/parabolic piece (u = 1) and a
    hyperbolic piece (u = cosh): returns (points, u, pieces) with the index ranges of each piece."""
    d = _check_degree(degree)
    Pc, uc = circle_polygon(1.0, start=math.pi / 2, step_angle=math.pi / 6, count=7, degree=d)
    # straight piece continuing from the last circle point downwards-right
    last = Pc[-1]
    Pl = last + np.outer(np.arange(1, 5), [0.6, -0.3])
    Ph, uh = hyperbola_polygon(0.5, 0.5, center=(Pl[-1][0] + 0.3, Pl[-1][1] - 1.2), start=-0.9, step_param=0.45,
                               count=7, degree=d)
    P = np.vstack([Pc, Pl, Ph])
    u = list(uc) + [1.0] * (len(Pl) + 1) + list(uh)
    return P, u, {"circle": (0, len(Pc)), "line": (len(Pc), len(Pc) + len(Pl)), "hyperbola": (len(Pc) + len(Pl), len(P))}
