"""Whether the Jacobian of the characteristic map's segment patches is *proven* to change sign.

:func:`.charmap.characteristic_map` reports a map that it could not certify regular as inconclusive,
whether the Bernstein bounds merely ran out of subdivision depth or a corner value of the other sign
was found. Corner values are values of the Jacobian itself (the corner Bernstein coefficients of a
tensor-product patch, the vertex ordinates of a triangular one), so two corners of opposite certified
sign prove that the Jacobian changes sign on the segment: the map is not regular there, and more
precision cannot change that. This module reads those corners from the same patches.

Algorithm
---------
Rebuild the segment patches of :mod:`.charmap` (bicubic on the quad lattice, quartic box-spline on the
triangle lattice, rules on the 2-ring) at ``prec`` bits and collect the certified signs of the
Jacobian's corner values.

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> from analysis.vertex.spectrum import analyse
>>> r = scheme_rules("loop", ring=2)
>>> a = analyse(r, 5, curvature=False)
>>> jacobian_sign_change(r, 5, a.lam.ball.real)
False
"""

from __future__ import annotations

from .rules import LocalRules


def jacobian_sign_change(rules: LocalRules, n: int, lam_ball, prec: int = 128) -> bool:
    """True when corner values of the Jacobian of the segment patches of the characteristic map (for the
    eigenvalue in ``lam_ball``) have opposite certified signs; False when not proven (including rules
    whose patches are not built here: Doo–Sabin, the 1-ring)."""
    from flint import ctx

    from . import charmap as cm

    if rules.lattice not in ("quad", "triangle") or rules.ring != 2:
        return False
    old = ctx.prec
    ctx.prec = prec
    try:
        v = cm.eigenvector(rules, n, lam_ball)
        if rules.lattice == "quad":
            net = cm._Net(rules, n, v, lam_ball)
            jac = [cm._jacobian_bernstein(net.bezier(a, b)) for a, b in cm.SEGMENT]
            return _opposite(jac, _quad_corners, lambda J, d: cm._split(J, d % 2), cm.MAX_DEPTH)
        from .boxspline import SUBTRIANGLES, bezier_index, restriction_matrices

        net = cm._TriNet(rules, n, v, lam_ball)            # the segment: level-1 triangles 1..3
        jac = [cm._tri_jacobian(net.bezier_tri(*st)) for st in SUBTRIANGLES[1:]]
        i6 = bezier_index(6)
        at = [i6.index(x) for x in ((6, 0, 0), (0, 6, 0), (0, 0, 6))]
        mats = restriction_matrices(6)

        def split(J, _d):
            out = []
            for R in mats:
                sub = []
                for i in range(R.rows):
                    acc = 0 * J[0]
                    for j in range(R.cols):
                        if R[i, j] != 0:
                            acc += J[j] * int(R[i, j].p) / int(R[i, j].q)
                    sub.append(acc)
                out.append(sub)
            return out

        return _opposite(jac, lambda J: [J[i] for i in at], split, TRI_DEPTH)
    finally:
        ctx.prec = old


#: the subdivision depth of the corner search on triangles (as :mod:`.charmap`'s sign test)
TRI_DEPTH = 4


def _quad_corners(J: list[list]) -> list:
    return [J[0][0], J[0][-1], J[-1][0], J[-1][-1]]


def _opposite(jac: list, corners, split, depth: int) -> bool:
    """Corner values of opposite certified sign among the patches ``jac`` and their pieces (subdivided
    ``depth`` times where a piece's coefficients are not of one sign)."""
    signs = set()
    todo = [(J, 0) for J in jac]
    while todo:
        J, d = todo.pop()
        signs |= {1 for x in corners(J) if x > 0} | {-1 for x in corners(J) if x < 0}
        if signs == {1, -1}:
            return True
        flat = [x for row in J for x in row] if isinstance(J[0], list) else J
        if d < depth and not (all(x > 0 for x in flat) or all(x < 0 for x in flat)):
            todo += [(h, d + 1) for h in split(J, d)]
    return False
    return any(x > 0 for x in corners) and any(x < 0 for x in corners)
