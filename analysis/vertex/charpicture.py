"""Points of the characteristic map for a picture (floats): the image of the segment's parameter lines, for
``subdiv vertex --valence N --figure FILE``. Drawing only: the certificates are in :mod:`.charmap` and
:mod:`.netmap`.

The segment (sector 0, between the level-0 and level-1 1-rings) is mapped by the same Bézier patches as
:mod:`.charmap` (bicubic: Catmull–Clark-type rules; quartic box-spline: Loop-type rules, both on the 2-ring;
biquadratic: Doo–Sabin), evaluated at the midpoints of their Arb coefficients on ``resolution`` parameter
lines per direction; for the butterfly schemes the lattice triangles of :mod:`.netmap`'s sampled net (the
net points are points of the limit: the schemes interpolate). The whole map is the segment rotated by
``w^j`` (``j < n``) and scaled by ``lambda^m`` (``Phi(x/2) = lambda Phi(x)``).

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> from analysis.vertex.spectrum import analyse
>>> r = scheme_rules("catmull-clark", ring=2)
>>> s = characteristic_map_lines(r, 5, analyse(r, 5).lam.ball.real, resolution=4)
>>> s["source"], len(s["lines"]) > 0, isinstance(s["lines"][0][0], complex)
('bicubic Bézier patches', True, True)
"""

from __future__ import annotations

from math import comb

from ..result import AnalysisError


def _c(z) -> complex:
    return complex(float(z.real.mid()), float(z.imag.mid()))


def _tensor_lines(P: list[list], res: int) -> list[list[complex]]:
    """Iso-parameter lines of a tensor Bézier patch (control points P[i][j], i along u)."""
    d = len(P) - 1

    def at(u, v):
        return sum(comb(d, i) * u ** i * (1 - u) ** (d - i) * comb(d, j) * v ** j * (1 - v) ** (d - j) * P[i][j]
                   for i in range(d + 1) for j in range(d + 1))

    ts = [k / res for k in range(res + 1)]
    fine = [k / (4 * res) for k in range(4 * res + 1)]
    return [[at(t, s) for s in fine] for t in ts] + [[at(s, t) for s in fine] for t in ts]


def _triangle_lines(b: dict, res: int) -> list[list[complex]]:
    """Iso-parameter lines of a triangular Bézier patch (ordinates b[(i, j, k)], degree i + j + k)."""
    d = sum(next(iter(b)))

    def at(u, v):
        w = 1 - u - v
        return sum(comb(d, i) * comb(d - i, j) * u ** i * v ** j * w ** k * p for (i, j, k), p in b.items())

    out = []
    for t in (k / res for k in range(res + 1)):
        fine = [s * (1 - t) / (4 * res) for s in range(4 * res + 1)]
        out.append([at(t, s) for s in fine])                       # u = t
        out.append([at(s, t) for s in fine])                       # v = t
        out.append([at(s, 1 - t - s) for s in fine])               # w = t
    return out


def characteristic_map_lines(rules, n: int, lam_ball, resolution: int = 8) -> dict:
    """``{"lines": [[complex, ...], ...], "source": ..., "lambda": float}``: the segment's parameter lines
    under the characteristic map (block 1's eigenvector for ``lam_ball``), sector 0."""
    from flint import ctx

    from .charmap import SEGMENT, _DualNet, _Net, _TriNet, eigenvector

    lam = float(lam_ball.mid())
    if rules.lattice == "triangle, interpolating":
        from .netmap import net_triangles

        tris = net_triangles(rules, n, lam)
        return {"lines": [[a, b, c, a] for a, b, c in tris], "source": "sampled net (floats)", "lambda": lam}
    if not (rules.lattice == "dual quad" or (rules.lattice in ("quad", "triangle") and rules.ring == 2)):
        raise AnalysisError("the characteristic map is drawn for Loop- and Catmull-Clark-type rules on the 2-ring, "
                            "Doo-Sabin and the butterfly schemes")
    old = ctx.prec
    ctx.prec = 64
    try:
        v = eigenvector(rules, n, lam_ball)
        if rules.lattice == "triangle":
            from .boxspline import BEZIER_INDEX, SUBTRIANGLES

            net = _TriNet(rules, n, v, lam_ball)
            lines = []
            for st in SUBTRIANGLES[1:]:
                ords = net.bezier_tri(*st)
                lines += _triangle_lines({idx: _c(z) for idx, z in zip(BEZIER_INDEX, ords)}, resolution)
            return {"lines": lines, "source": "quartic box-spline Bézier patches", "lambda": lam}
        if rules.lattice == "dual quad":
            net = _DualNet(rules, n, v, lam_ball)
            patches, what = [net.bezier_dual(a, b) for a, b in SEGMENT], "biquadratic Bézier patches"
        else:
            net = _Net(rules, n, v, lam_ball)
            patches, what = [net.bezier(a, b) for a, b in SEGMENT], "bicubic Bézier patches"
        lines = [ln for P in patches for ln in _tensor_lines([[_c(z) for z in row] for row in P], resolution)]
        return {"lines": lines, "source": what, "lambda": lam}
    finally:
        ctx.prec = old
