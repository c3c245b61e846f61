"""Zorin's test of the characteristic map of the modified butterfly at valence n, in Arb: every cell of a
fundamental annulus, and the winding number of a ring. The computation certifies each of its steps; the
argument that joins them (below) has not yet been independently reviewed, so the result is *inconclusive*
and no C^1 verdict is drawn from it.

Algorithm
---------
Chart: sector 0 in lattice coordinates ``(x, y)`` (``e_0`` at 0 degrees, ``e_1`` at 60; ring = x + y), mask
coordinates ``(p, q) = (x, -y)`` (the butterfly mask's third direction ``(1, 1)``; this flips orientation).

1. ``v``: an Arb enclosure of block 1's eigenvector for lambda = 1/2 on the ``ring``-ring
   (:func:`analysis.vertex.charmap.eigenvector`); every ring is closed under the rules and the scheme is
   interpolating, so ``Phi(x, y) = w^d v(home)`` at the lattice points (``w = exp(2 pi i/n)``).
2. Cover: the mask cells with chart corner ``(x, y + 1)``, ``x, y >= 0``, ``lo <= x + y < hi`` are the
   triangles of sector 0 between rings ``lo`` and ``hi``. Each cell's neighbourhood ``i0 - Omega`` must satisfy
   ``x + y >= 1`` at every point: its convex hull then lies in the half-plane ``x + y > 0`` (chart sectors -1, 0,
   1, where the chart is a faithful development of the mesh) at distance > 1/2 from the centre, so no point
   of any refinement of it is a new point on an edge at the centre, all rules used there are the regular
   stencil, and ``Phi`` on the cell is the regular butterfly limit of its local net.
3. Regularity: :func:`analysis.vertex.derived.jacobian_sign_on_cell` on every cell with one common sign;
   ``Phi(x/2) = Phi(x)/2`` and ``Phi(R x) = w Phi(x)`` carry the sign to the punctured plane.
4. Winding: the ring-``hi`` arc of sector 0 runs from ``(hi, 0)`` to ``(0, hi)``, with images ``P0`` and
   ``w P0``. On its edges (the cells' diagonals) ``|Phi(a + t e) - Phi(a) - t d| <= K ||W c(u)||``; the tubes
   are refined along the diagonals until each is proven to miss the ray from 0 at the angle
   ``arg P0 + pi + pi/n``. Then the arc's argument increases by exactly ``2 pi/n`` and the ring winds once.
   With a positive Jacobian in the chart's orientation (negative in the mask's) the map is injective
   (Reif 1995; Peters–Reif 2008, ch. 5).

References
----------
D. Zorin, A method for analysis of C^1-continuity of subdivision surfaces, SIAM J. Numer. Anal. 37 (2000).
U. Reif, A unified approach to subdivision algorithms near extraordinary vertices, CAGD 12 (1995).
J. Peters, U. Reif, Subdivision Surfaces, Springer 2008.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..result import INCONCLUSIVE, AnalysisError, Result

__all__ = ["modified_butterfly_zorin", "nested_neighbourhoods"]


def _hull(points):
    """The convex hull of integer points, counter-clockwise (Andrew's monotone chain, exact)."""
    pts = sorted(set(points))

    def half(seq):
        out: list = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(reversed(pts))
    return lower[:-1] + upper[:-1]


def nested_neighbourhoods(omega, digits) -> bool:
    """``(Omega - eps)/2`` lies in ``conv(Omega)`` for every digit (exact): the neighbourhoods of all
    refinements of a cell stay in the convex hull of its own (step 2 of the module docstring).

    >>> nested_neighbourhoods([(0, 0), (-1, 0), (0, -1), (-1, -1)], [(0, 0), (1, 0), (0, 1), (1, 1)])
    True
    >>> nested_neighbourhoods([(0, 0), (1, 0), (0, 1), (1, 1)], [(0, 0), (1, 0), (0, 1), (1, 1)])
    False
    """
    V = _hull(omega)
    for e in digits:
        for x, y in omega:
            q = (Fraction(x - e[0], 2), Fraction(y - e[1], 2))
            for k in range(len(V)):
                a, b = V[k], V[(k + 1) % len(V)]
                if (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) < 0:
                    return False
    return True


def _tube_misses_ray(p, q, rad, rho) -> bool:
    """The set ``[p, q] + disk(rad)`` misses the ray ``{t rho : t >= 0}`` (``|rho| = 1``), proven in Arb."""
    a, b = p * rho.conjugate(), q * rho.conjugate()           # the ray is now the positive real axis
    ya, yb = a.imag, b.imag
    if (ya > rad and yb > rad) or (ya < -rad and yb < -rad):
        return True                                           # the tube stays on one side of the line
    # otherwise the whole tube must lie left of the imaginary axis, beyond the disk around 0
    return bool(a.real < -rad and b.real < -rad)


def modified_butterfly_zorin(n: int, *, ring: int = 24, lo: int = 8, hi: int = 16, r=Fraction(2, 5),
                             max_depth: int = 8, tension=Fraction(1, 16), prec: int = 128) -> Result:
    """Steps 1-4 of the module docstring for the modified butterfly at valence ``n``; *inconclusive* always
    (see the module docstring), with ``witness``: ``cells`` (proven of total), ``jacobian_sign_mask``,
    ``winding`` (True when step 4 succeeded), ``K``, ``subcells`` (cells examined after refinement).
    """
    from flint import acb, ctx, fmpq

    from schemes.surfaces import get

    from ..bivariate.holder import holder_exponent
    from .charmap import eigenvector
    from .derived import defect_functionals, derivative_error_bound, jacobian_sign_on_cell
    from .rules import _tri_home, modified_butterfly_rules

    a = get("butterfly").mask(w=str(tension))
    bound = derivative_error_bound(a, r, holder=holder_exponent(a, budget=50))
    if not bound.is_certified:
        raise AnalysisError("the derivative error bound of the regular part is not certified")
    K, W = bound.value, bound.witness["W"]
    d = defect_functionals(a, (1, 1))
    fam, B = d["family"], d["basis"]
    omega = fam.omega
    idx = {p: s for s, p in enumerate(omega)}
    if not nested_neighbourhoods(omega, a.dilation.digits):
        raise AnalysisError("the refinements' neighbourhoods are not inside the cell's: the cover argument fails")
    rules = modified_butterfly_rules(ring, n, Fraction(tension))
    old = ctx.prec
    ctx.prec = prec
    try:
        v = eigenvector(rules, n, acb(fmpq(1, 2)))
        index = {p: i for i, p in enumerate(rules.coords)}
        rot = [acb(fmpq(2 * k, n)).exp_pi_i() for k in range(n)]

        def phi(x, y):
            if (x, y) == (0, 0):
                return acb(0)
            k, hx, hy = _tri_home(x, y)
            if (hx, hy) not in index:
                raise AnalysisError(f"the point ({x}, {y}) is outside the {ring}-ring")
            return rot[k % n] * v[index[(hx, hy)]]

        def net(x, y):
            cx, cy = x, y + 1
            if min(cx - jx + cy + jy for jx, jy in omega) < 1:
                raise AnalysisError(f"the neighbourhood of the cell ({x}, {y}) comes too close to the centre")
            return [phi(cx - jx, cy + jy) for jx, jy in omega]

        proven = total = sub = 0
        signs = set()
        for x in range(hi):
            for y in range(hi - x):
                if x + y < lo:
                    continue
                total += 1
                res = jacobian_sign_on_cell(a, net(x, y), bound, max_depth=max_depth, prec=prec)
                sub += res.witness["cells"]
                if res.is_certified:
                    proven += 1
                    signs.add(res.value)
        regular = proven == total and len(signs) == 1
        winding = _winding_once(n, hi, net, phi, fam, B, W, K, idx, max_depth)
    finally:
        ctx.prec = old
    wit: dict[str, Any] = {"cells": f"{proven} of {total}", "jacobian_sign_mask": signs.pop() if regular else None,
                           "regular": regular, "winding": winding, "K": K, "subcells": sub,
                           "ring": ring, "annulus": (lo, hi)}
    done = regular and winding
    msg = ("every cell and the winding number proven in Arb (regular and injective by the argument of the "
           "module docstring); that argument awaits an independent review, so no C^1 verdict is drawn"
           if done else "not every step was proven")
    return Result(status=INCONCLUSIVE, witness=wit,
                  provenance={"method": "Zorin 2000: cell cover of a fundamental annulus, derivative error bounds "
                                        "of the regular butterfly, winding of a ring", "message": msg})


def _winding_once(n, hi, net, phi, fam, B, W, K, idx, max_depth) -> bool:
    """Step 4 of the module docstring: the image of the sector-0 arc of ring ``hi`` misses the ray from 0 at
    the angle ``arg P0 + pi + pi/n``, proven with tubes refined along the cells' diagonals."""
    from flint import acb, acb_mat, arb, fmpq

    P0 = phi(hi, 0)
    rho = -P0 * acb(fmpq(1, n)).exp_pi_i()
    rho = rho / abs(rho)
    Tt = [acb_mat(T.transpose()) for T in fam.full]
    WBt = acb_mat(W * B.transpose())
    Ka = arb(K.numerator) / K.denominator
    i0, i3 = idx[(0, 0)], idx[(-1, -1)]
    # the arc's edges: from chart (hi - i, i) to (hi - 1 - i, i + 1) is the diagonal of the cell (hi - 1 - i, i)
    for i in range(hi):
        stack = [(0, acb_mat([[z] for z in net(hi - 1 - i, i)]))]
        while stack:
            m, u = stack.pop()
            z = WBt * u
            rad = arb(0)
            for t in range(z.nrows()):
                rad = rad.max(abs(z[t, 0])) if t else abs(z[t, 0])
            rad = Ka * rad
            if _tube_misses_ray(u[i0, 0], u[i3, 0], rad, rho):
                continue
            if m >= max_depth:
                return False
            stack.append((m + 1, Tt[0] * u))                  # digit (0, 0): the diagonal's first half
            stack.append((m + 1, Tt[3] * u))                  # digit (1, 1): its second half
    return True
