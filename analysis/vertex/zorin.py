"""Zorin's test of the characteristic map of the modified butterfly at valence n, in Arb: every cell of a
fundamental annulus, and the winding number of a ring. When every step below is proven the result is
*certified*: the characteristic map is regular and injective, so with Reif's eigen-conditions (step 0) the
scheme is C^1 at valence n for generic initial data (Reif's criterion). n = 6 is the regular case.

Algorithm
---------
Chart: sector 0 in lattice coordinates ``(x, y)`` (``e_0`` at 0 degrees, ``e_1`` at 60; ring = x + y), mask
coordinates ``(p, q) = (x, -y)`` (the butterfly mask's third direction ``(1, 1)``; this flips orientation).

0. Eigen-structure: :func:`analysis.vertex.spectrum.analyse` on the 3-ring certifies Reif's conditions with
   lambda = 1/2 exact and simple in block 1; :func:`outer_rings_nilpotent` checks exactly that the
   ``ring``-ring rules agree with the 3-ring rules on the 3-ring and that every rule of a point of ring
   ``r >= 4`` uses only sources of rings ``< r``. Block 1 of the ``ring``-ring matrix is then
   ``[[B3, 0], [X, Y]]`` with ``Y`` strictly lower triangular (by ring), so its characteristic polynomial is
   ``B3``'s times a power of lambda: 1/2 is an algebraically simple eigenvalue, ``B - I/2`` has rank ``m - 1``,
   and the solution of step 1 (``m - 1`` equations with a nonsingular minor, one entry fixed to 1) is the
   eigenvector, whose first six entries are the 3-ring's.
1. ``v``: an Arb enclosure of block 1's eigenvector for lambda = 1/2 on the ``ring``-ring
   (:func:`analysis.vertex.charmap.eigenvector`); every ring is closed under the rules and the scheme is
   interpolating, so ``Phi(x, y) = w^d v(home)`` at the lattice points (``w = exp(2 pi i/n)``).
2. Cover: cell ``(x, y)`` is the chart parallelogram with corners ``(x, y)`` and ``(x + 1, y + 1)`` (mask
   corner ``(x, y + 1)``), split by its diagonal from ``(x + 1, y)`` to ``(x, y + 1)`` into a triangle between
   rings ``x + y`` and ``x + y + 1`` and one between rings ``x + y + 1`` and ``x + y + 2``. Lemma
   (:func:`annulus_cells`, :func:`covers_annulus`): with the cells ``x, y >= 0``,
   ``lo - 1 <= x + y <= hi - 1``, every lattice triangle of sector 0 between rings ``lo`` and ``hi`` is half
   of some cell; with ``hi = 2 lo``, ``Phi(x/2) = Phi(x)/2`` and the n rotations give the whole punctured
   plane. Each cell's neighbourhood ``i0 - Omega`` must satisfy ``x + y >= 1`` at every point: its convex hull
   then lies in the half-plane ``x + y > 0`` (chart sectors -1, 0, 1, where the chart is a faithful
   development of the mesh) at distance > 1/2 from the centre, so no point of any refinement of it is a new
   point on an edge at the centre, all rules used there are the regular stencil, and ``Phi`` on the cell is
   the regular butterfly limit of its local net.
3. Regularity: :func:`analysis.vertex.derived.jacobian_sign_on_cell` on every cell with one common sign, with
   the regular part's derivative error bound :func:`analysis.vertex.defectsum.defect_sum_bound`
   (``|D_e Phi - d_e| <= 2^k K_e ||W c(u_k)||_2`` on a cell of level k, one constant per direction);
   ``Phi(x/2) = Phi(x)/2`` and ``Phi(R x) = w Phi(x)`` carry the sign to the punctured plane.
4. Winding: the ring-``hi`` arc of sector 0 runs from ``(hi, 0)`` to ``(0, hi)``, with images ``P0`` and
   ``w P0``. On its edges (the cells' diagonals, direction ``e = (1, 1)``)
   ``|Phi(a + t e) - Phi(a) - t d| <= K_e ||W c(u)||_2`` (the integral of the derivative error); the tubes
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
from functools import lru_cache
from typing import Any

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result

__all__ = ["annulus_cells", "covers_annulus", "modified_butterfly_zorin", "regular_butterfly_mask",
           "nested_neighbourhoods", "outer_rings_nilpotent", "eigenfunction_nets", "winding_of_arc", "regular_bound",
           "regular_defect_bound", "regular_holder"]


def annulus_cells(lo: int, hi: int) -> list[tuple[int, int]]:
    """The cells ``(x, y)``, ``x, y >= 0``, ``lo - 1 <= x + y <= hi - 1`` of step 2 of the module docstring.

    >>> annulus_cells(2, 4)
    [(0, 1), (0, 2), (0, 3), (1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (3, 0)]
    """
    return [(x, y) for x in range(hi) for y in range(hi - x) if x + y >= lo - 1]


def _halves(x: int, y: int):
    """The two lattice triangles of cell ``(x, y)`` (chart coordinates), as frozensets of corners."""
    return (frozenset({(x, y), (x + 1, y), (x, y + 1)}), frozenset({(x + 1, y), (x, y + 1), (x + 1, y + 1)}))


def covers_annulus(cells, lo: int, hi: int) -> bool:
    """Every lattice triangle of sector 0 (corners ``x, y >= 0``) with all corners on rings ``lo..hi`` is half
    of one of ``cells`` (exact enumeration; the triangles are ``{(x, y), (x+1, y), (x, y+1)}`` and
    ``{(x+1, y), (x, y+1), (x+1, y+1)}``, edges along e_0, e_1 and e_1 - e_0).

    >>> covers_annulus(annulus_cells(8, 16), 8, 16)
    True
    >>> covers_annulus([(x, y) for x, y in annulus_cells(8, 16) if x + y >= 8], 8, 16)   # ring band 8-9
    False
    """
    have = {t for c in cells for t in _halves(*c)}
    for x in range(hi + 1):
        for y in range(hi + 1 - x):
            for t in _halves(x, y):
                if all(lo <= a + b <= hi for a, b in t) and t not in have:
                    return False
    return True


def outer_rings_nilpotent(rules, inner) -> bool:
    """Step 0 of the module docstring, exact: ``rules`` (on more rings) agree with ``inner`` (the 3-ring rules)
    on ``inner``'s points, and every rule of a point of ring ``r`` beyond ``inner.ring`` uses only the centre and
    points of rings ``< r``.

    >>> from analysis.vertex.rules import modified_butterfly_rules
    >>> outer_rings_nilpotent(modified_butterfly_rules(6, 5), modified_butterfly_rules(3, 5))
    True
    """
    coords, k = rules.coords, len(inner.coords)
    if tuple(coords[:k]) != tuple(inner.coords) or rules.centre != inner.centre:
        return False
    sect, sect3 = rules.sector_rules(), inner.sector_rules()
    if tuple(sect[:k]) != tuple(sect3) or (rules.centre and rules.rules[0] != inner.rules[0]):
        return False
    for i in range(k, len(coords)):
        r = sum(coords[i])
        if r <= inner.ring:
            return False
        for t in sect[i]:
            if len(t.source) == 2 and sum(coords[t.source[0]]) >= r:
                return False
    return True


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


def regular_butterfly_mask(tension=Fraction(1, 16)):
    """The regular (valence-6) part of the butterfly family as a bivariate mask with dilation 2I, built from
    :func:`analysis.vertex.rules.butterfly_stencil` (``a(alpha - 2 beta)`` = the weight of ``beta`` in the rule
    of ``alpha``, one rule per coset), in the mask coordinates ``(x, -y)`` of the lattice chart — the same mask
    as the catalogue's ``butterfly`` (a test compares them).

    >>> a = regular_butterfly_mask()
    >>> a.coeffs[(0, 0)], a.coeffs[(1, 0)], len(a.coeffs)
    (1, 1/2, 25)
    """
    import sympy as sp

    from ..bivariate.mask import BivariateMask
    from .rules import butterfly_stencil

    coeffs: dict = {}
    for alpha in ((0, 0), (1, 0), (0, 1), (1, 1)):
        for weight, beta in butterfly_stencil(*alpha, tension=sp.Rational(str(tension))):
            k = (alpha[0] - 2 * beta[0], -(alpha[1] - 2 * beta[1]))
            coeffs[k] = coeffs.get(k, 0) + weight
    return BivariateMask(coeffs, name="butterfly")


@lru_cache(maxsize=8)
def regular_bound(tension=Fraction(1, 16), r=Fraction(2, 5), budget: int = 50):
    """``(mask, bound)``: the regular butterfly mask of ``tension`` and its certified (or not)
    :func:`analysis.vertex.derived.derivative_error_bound` for the contraction factor ``r``, the Hölder exponent
    computed with ``budget`` (cached: one computation per process and arguments)."""
    from .derived import derivative_error_bound

    a = regular_butterfly_mask(tension)
    return a, derivative_error_bound(a, Fraction(r), holder=regular_holder(tension, budget))


@lru_cache(maxsize=8)
def regular_holder(tension=Fraction(1, 16), budget: int = 20):
    """The certified Hölder exponent of the regular butterfly of ``tension`` (its C^1 makes the divided
    differences tend to the derivatives), computed with ``budget`` once per process and arguments."""
    from ..bivariate.holder import holder_exponent

    return holder_exponent(regular_butterfly_mask(tension), budget=budget)


@lru_cache(maxsize=8)
def regular_defect_bound(tension=Fraction(1, 16), budget: int = 20):
    """``(mask, bound)``: the regular butterfly mask of ``tension`` and its certified (or not)
    :func:`analysis.vertex.defectsum.defect_sum_bound` (Euclidean norm, one constant per direction), the Hölder
    exponent computed with ``budget`` (cached: one computation per process and arguments)."""
    from .defectsum import defect_sum_bound

    a = regular_butterfly_mask(tension)
    return a, defect_sum_bound(a, holder=regular_holder(tension, budget))


def modified_butterfly_zorin(n: int, *, ring: int | None = None, lo: int = 8, hi: int = 16, max_depth: int = 8,
                             tension=Fraction(1, 16), prec: int = 128) -> Result:
    """Steps 0-4 of the module docstring for the modified butterfly at valence ``n``: *certified* (value True,
    "C^1 for generic initial data (Reif's criterion)") when every step is proven, else *inconclusive*; the
    ``witness`` has ``eigen`` (Reif's conditions, lambda exact, the outer-ring check), ``cells`` (proven of
    total), ``cover`` (the lemma of step 2), ``jacobian_sign_mask`` (-1: positive in the chart), ``winding``
    (True when step 4 succeeded), ``K`` (the largest of ``K_by_direction``, :func:`regular_defect_bound`),
    ``subcells`` (cells examined after refinement), ``depth`` (the deepest refinement level reached). ``ring`` defaults to the smallest ring holding every cell's
    neighbourhood (``hi + 4`` for the butterfly's invariant support: the 20-ring for rings 8..16).
    """
    import sympy as sp
    from flint import acb, ctx, fmpq

    from .charmap import eigenvector
    from .derived import cell_frame, jacobian_sign_on_cell
    from .rules import modified_butterfly_rules
    from .spectrum import analyse

    if hi != 2 * lo or lo < 2:
        raise AnalysisError(f"the annulus must be rings lo..2 lo (Phi(x/2) = Phi(x)/2), not {lo}..{hi}")
    a, bound = regular_defect_bound(tension)
    K, W, fam, B, omega, idx = cell_frame(a, bound, (1, 1))
    K_diag, norm = bound.witness["K_by_direction"][(1, 1)], bound.witness["norm"]
    frame = cell_frame(a, bound, (1, 0))
    if ring is None:                       # net() reads the chart points (x + 1 - jx, y + 1 + jy), x + y <= hi - 1
        ring = hi - min(jx - jy for jx, jy in omega)
    rules = modified_butterfly_rules(ring, n, Fraction(tension))
    inner = modified_butterfly_rules(3, n, Fraction(tension))
    va = analyse(inner, n, curvature=False)
    eigen = {"reif_status": va.reif_status, "reif_ok": va.reif_ok, "checks": dict(va.checks),
             "lambda_exact": str(va.lam_exact), "outer_rings_nilpotent": outer_rings_nilpotent(rules, inner)}
    eigen_ok = (va.reif_ok is True and va.reif_status == "certified" and va.lam_exact is not None
                and sp.Rational(va.lam_exact) == sp.Rational(1, 2) and eigen["outer_rings_nilpotent"])
    cells = annulus_cells(lo, hi)
    cover = covers_annulus(cells, lo, hi)
    if not nested_neighbourhoods(omega, a.dilation.digits):
        raise AnalysisError("the refinements' neighbourhoods are not inside the cell's: the cover argument fails")
    old = ctx.prec
    ctx.prec = prec
    try:
        v = eigenvector(rules, n, acb(fmpq(1, 2)))
        phi, net = eigenfunction_nets(rules, n, v, omega)

        proven = total = sub = depth = 0
        signs = set()
        for x, y in cells:
            total += 1
            res = jacobian_sign_on_cell(a, net(x, y), bound, max_depth=max_depth, prec=prec, frame=frame)
            sub += res.witness["cells"]
            depth = max(depth, res.witness["depth"])
            if res.is_certified:
                proven += 1
                signs.add(res.value)
        regular = proven == total and len(signs) == 1
        winding = winding_of_arc(n, hi, net, phi, fam, B, W, K_diag, idx, max_depth, norm=norm)
    finally:
        ctx.prec = old
    sign = next(iter(signs)) if regular else None
    wit: dict[str, Any] = {"eigen": eigen, "cells": f"{proven} of {total}", "cover": cover,
                           "jacobian_sign_mask": sign, "regular": regular, "winding": winding, "K": K,
                           "K_by_direction": dict(bound.witness["K_by_direction"]), "norm": norm,
                           "subcells": sub, "depth": depth, "ring": ring, "annulus": (lo, hi), "regular_valence": n == 6}
    return _verdict(n, wit, eigen_ok)


def _verdict(n: int, wit: dict, eigen_ok: bool) -> Result:
    """The result of :func:`modified_butterfly_zorin` from its steps: *certified* only when all are proven and
    the Jacobian's sign agrees with the winding (a mismatch is a contradiction: *inconclusive*).

    >>> w = {"cover": True, "regular": True, "winding": True, "jacobian_sign_mask": -1}
    >>> _verdict(5, w, True).status, _verdict(5, dict(w, jacobian_sign_mask=1), True).status
    ('certified', 'inconclusive')
    >>> _verdict(5, w, False).provenance["message"]
    "not every step was proven: Reif's eigen-conditions with lambda = 1/2 exact"
    """
    cover, regular, winding, sign = wit["cover"], wit["regular"], wit["winding"], wit["jacobian_sign_mask"]
    # the winding of step 4 is counter-clockwise in the chart: it agrees with a positive chart Jacobian only,
    # which is sign -1 in the mask's (flipped) coordinates
    done = eigen_ok and cover and regular and winding and sign == -1
    prov: dict[str, Any] = {"method": "Zorin 2000: cell cover of a fundamental annulus, derivative error bounds "
                                      "of the regular butterfly, winding of a ring; Reif's eigen-conditions "
                                      "(Reif 1995)"}
    if done:
        prov["message"] = ("C^1 for generic initial data (Reif's criterion), certified: Reif's eigen-conditions "
                           "(lambda = 1/2 exact), a regular characteristic map (every cell of the annulus, "
                           "Jacobian positive in the chart) winding once, all proven"
                           + (" (n = 6 is the regular case)" if n == 6 else ""))
        return Result(status=CERTIFIED, value=True, witness=wit, provenance=prov)
    failed = [name for name, ok in (("Reif's eigen-conditions with lambda = 1/2 exact", eigen_ok),
                                    ("the cover of the annulus", cover), ("the sign on every cell", regular),
                                    ("the winding number", winding),
                                    ("the Jacobian's sign agreeing with the winding", regular and sign == -1))
              if not ok]
    prov["message"] = "not every step was proven: " + ", ".join(failed)
    return Result(status=INCONCLUSIVE, witness=wit, provenance=prov)


def eigenfunction_nets(rules, n: int, v: list, omega, k: int = 1):
    """``(phi, net)`` for the eigenfunction of Fourier block ``k`` with eigenvector ``v`` (Arb entries in the order
    of ``rules.coords``; no centre entry): ``phi(x, y) = w^(k d) v(home)`` at the chart point ``(x, y)`` of sector
    ``d`` (``w = exp(2 pi i/n)``; the scheme is interpolating, so this is the eigenfunction's value there) and
    ``net(x, y)``, the local net of cell ``(x, y)`` (step 2 of the module docstring), which must stay at
    ``x + y >= 1``."""
    from flint import acb, fmpq

    from .rules import _tri_home

    index = {p: i for i, p in enumerate(rules.coords)}
    rot = [acb(fmpq(2 * k * d, n)).exp_pi_i() for d in range(n)]

    def phi(x, y):
        if (x, y) == (0, 0):
            return acb(0)
        d, hx, hy = _tri_home(x, y)
        if (hx, hy) not in index:
            raise AnalysisError(f"the point ({x}, {y}) is outside the {rules.ring}-ring")
        return rot[d % n] * v[index[(hx, hy)]]

    def net(x, y):
        cx, cy = x, y + 1
        if min(cx - jx + cy + jy for jx, jy in omega) < 1:
            raise AnalysisError(f"the neighbourhood of the cell ({x}, {y}) comes too close to the centre")
        return [phi(cx - jx, cy + jy) for jx, jy in omega]

    return phi, net


def winding_of_arc(n, hi, net, phi, fam, B, W, K, idx, max_depth, k: int = 1, norm: str = "inf") -> bool:
    """Step 4 of the module docstring for the eigenfunction of Fourier block ``k`` (``Phi(R x) = w^k Phi(x)``):
    the image of the sector-0 arc of ring ``hi`` (from ``P0 = Phi(hi, 0)`` to ``w^k P0``) misses the ray from 0
    at the angle ``arg P0 + pi + k pi/n``, proven with tubes refined along the cells' diagonals. Then the arc's
    argument increases by exactly ``2 pi k/n`` (the only value of ``2 pi k/n + 2 pi j`` within pi of
    ``k pi/n``), and the closed ring (the n rotations of the arc) winds exactly k times around 0. ``K`` bounds
    the derivative error along the diagonal direction (1, 1) in the ``norm`` of ``W c`` (:func:`.derived.net_size`)."""
    from flint import acb, acb_mat, arb, fmpq

    from .derived import net_size

    P0 = phi(hi, 0)
    rho = -P0 * acb(fmpq(k, n)).exp_pi_i()
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
            rad = Ka * net_size(WBt * u, norm)
            if _tube_misses_ray(u[i0, 0], u[i3, 0], rad, rho):
                continue
            if m >= max_depth:
                return False
            stack.append((m + 1, Tt[0] * u))                  # digit (0, 0): the diagonal's first half
            stack.append((m + 1, Tt[3] * u))                  # digit (1, 1): its second half
    return True
