"""The Bézier form of Loop's regular patch (the quartic three-direction box spline B_222) and triangular
Bernstein tools, derived exactly from the subdivision rules themselves.

A regular Loop patch over a triangle T is a quartic polynomial whose 15 Bézier ordinates are linear in
the 12 control points of T's 1-rings: ``B = G P``. Subdivision splits T into four triangles whose
12-point nets are ``A_s P`` (Loop's regular stencils), and the patch restricted to each sub-triangle is
the patch of its net, so ``R_s G = G A_s`` (``R_s``: the Bézier ordinates of the restriction, by
blossoming). With the affine invariance ``G 1 = 1`` these linear equations have one solution, which is
computed over Q (no table is typed in).

Examples
--------
>>> G = loop_bezier_matrix()
>>> G.shape, all(sum(G.row(i)) == 1 for i in range(15))
((15, 12), True)
>>> G[BEZIER_INDEX.index((4, 0, 0)), NET.index((0, 0))]       # limit position weight of the corner
1/2

References
----------
C. de Boor, K. Höllig, S. Riemenschneider, Box Splines, Springer 1993; J. Stam, Evaluation of Loop
subdivision surfaces, SIGGRAPH 1998 course notes (the patch as a quartic in Bézier form); G. Farin, Curves
and Surfaces for CAGD (triangular Bézier patches, blossoms).
"""

from __future__ import annotations

from functools import lru_cache
import sympy as sp

from ..result import AnalysisError

#: the 12 control points of the triangle (0,0), (1,0), (0,1) (lattice with edges (1,0), (0,1), (1,-1))
NET = ((0, 0), (1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1), (2, -1), (2, 0), (1, 1), (0, 2), (-1, 2))
TRI_DIRS = ((1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1))
#: the four sub-triangles at level 1 (doubled coordinates): corner q0 and edge vectors a, b
SUBTRIANGLES = (((0, 0), (1, 0), (0, 1)), ((1, 0), (1, 0), (0, 1)), ((0, 1), (1, 0), (0, 1)),
                ((1, 1), (-1, 0), (0, -1)))


def bezier_index(d: int) -> tuple[tuple[int, int, int], ...]:
    """Multi-indices (i, j, k), i + j + k = d, of the vertices (0,0), (1,0), (0,1) in a fixed order."""
    return tuple((d - j - k, j, k) for j in range(d + 1) for k in range(d + 1 - j))


BEZIER_INDEX = bezier_index(4)


def loop_stencil(X: int, Y: int) -> list[tuple[sp.Rational, tuple[int, int]]]:
    """Loop's regular rule for the level-1 point at (X, Y) (doubled coordinates) on level-0 points."""
    h = sp.Rational
    if X % 2 == 0 and Y % 2 == 0:
        x, y = X // 2, Y // 2
        return [(h(5, 8), (x, y))] + [(h(1, 16), (x + a, y + b)) for a, b in TRI_DIRS]
    i = next(i for i, (dx, dy) in enumerate(TRI_DIRS) if (X - dx) % 2 == 0 and (Y - dy) % 2 == 0)
    dx, dy = TRI_DIRS[i]
    p = ((X - dx) // 2, (Y - dy) // 2)
    q = (p[0] + dx, p[1] + dy)
    o1 = (p[0] + TRI_DIRS[(i - 1) % 6][0], p[1] + TRI_DIRS[(i - 1) % 6][1])
    o2 = (p[0] + TRI_DIRS[(i + 1) % 6][0], p[1] + TRI_DIRS[(i + 1) % 6][1])
    return [(h(3, 8), p), (h(3, 8), q), (h(1, 8), o1), (h(1, 8), o2)]


def _blossom_matrix(d: int, points: list[tuple]) -> list:
    """Rows: for each target multi-index, the coefficients (on the source Bézier ordinates of degree d) of
    the blossom at ``points`` (barycentric, with respect to the source triangle) — i.e. the Bézier
    ordinates of the restriction to the triangle with those vertices."""
    src = bezier_index(d)
    rows = []
    for (i, j, k) in bezier_index(d):
        args = [points[0]] * i + [points[1]] * j + [points[2]] * k
        # coefficient of source ordinate b_(a,b,c) in the blossom: sum over assignments (multinomial)
        coeffs = {idx: sp.S.Zero for idx in src}
        states = {(0, 0, 0): sp.S.One}
        for bary in args:
            new = {}
            for (a, b, c), w in states.items():
                for t, inc in enumerate(((1, 0, 0), (0, 1, 0), (0, 0, 1))):
                    if bary[t] == 0:
                        continue
                    key = (a + inc[0], b + inc[1], c + inc[2])
                    new[key] = new.get(key, 0) + w * bary[t]
            states = new
        for (a, b, c), w in states.items():           # de Casteljau with the arguments in turn
            coeffs[(a, b, c)] += w
        rows.append([coeffs[idx] for idx in src])
    return rows


@lru_cache(maxsize=8)
def restriction_matrices(d: int) -> tuple[sp.Matrix, ...]:
    """The Bézier ordinates (degree d) of a polynomial on T restricted to each sub-triangle of the
    midpoint split, as 4 matrices on T's ordinates (order of :data:`SUBTRIANGLES`)."""
    out = []
    for q0, a, b in SUBTRIANGLES:
        verts = [q0, (q0[0] + a[0], q0[1] + a[1]), (q0[0] + b[0], q0[1] + b[1])]
        bary = [(1 - sp.Rational(x + y, 2), sp.Rational(x, 2), sp.Rational(y, 2)) for x, y in verts]
        out.append(sp.Matrix(_blossom_matrix(d, bary)))
    return tuple(out)


def _net_subdivision(q0, a, b) -> sp.Matrix:
    """A_s: the 12-point net of a sub-triangle (level 1) from T's net (level 0)."""
    A = sp.zeros(12, 12)
    for r, (x, y) in enumerate(NET):
        X, Y = q0[0] + x * a[0] + y * b[0], q0[1] + x * a[1] + y * b[1]
        for wgt, p in loop_stencil(X, Y):
            if p not in NET:
                raise AnalysisError(f"Loop's regular net is not closed: {p} needed")
            A[r, NET.index(p)] += wgt
    return A


@lru_cache(maxsize=1)
def loop_bezier_matrix() -> sp.Matrix:
    """G (15 x 12): the Bézier ordinates of the regular Loop patch over (0,0), (1,0), (0,1) from its 12
    control points (:data:`NET`), the unique solution of ``R_s G = G A_s`` (s = 1..4), ``G 1 = 1``."""
    syms = sp.symbols(f"g0:{15 * 12}")
    G = sp.Matrix(15, 12, syms)
    eqs = []
    for R, (q0, a, b) in zip(restriction_matrices(4), SUBTRIANGLES):
        eqs += list(R * G - G * _net_subdivision(q0, a, b))
    eqs += [sum(G.row(i)) - 1 for i in range(15)]
    sol = sp.linsolve(eqs, syms)
    (vals,) = list(sol)
    if any(v.free_symbols for v in vals):
        raise AnalysisError("the Bézier form of Loop's patch is not determined by the subdivision equations")
    return sp.Matrix(15, 12, list(vals))
