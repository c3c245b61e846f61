"""Exact algebra of a bivariate mask: sum rules, generation and reproduction degree, symmetry group,
box-spline factors.

Sum rules of order ``k`` (Jia 1998; Cabrelli–Heil–Molter 2004): for every polynomial ``p`` of total degree
``< k`` the coset sums ``sum_beta a(eps + M beta) p(eps + M beta)`` are the same for every digit ``eps`` of
``Z^2 / M Z^2`` (and each coset sums to 1). Equivalently the symbol and its partial derivatives of order
``< k`` vanish at the nontrivial dual points ``z = exp(2 pi i omega)``, ``omega in M^{-T} Z^2 / Z^2``
(:attr:`analysis.bivariate.dilation.Dilation.dual_points`); the coset form is rational arithmetic, so this
module uses it. Sum rules of order ``k`` are polynomial *generation* of degree ``k - 1``.

Reproduction of degree ``d``: ``S_a p = p(M^{-1} . + tau)`` for every ``p`` of degree ``<= d``, the shift
``tau`` being fixed by the linear polynomials (``tau = 0``: primal parametrisation).

Examples
--------
>>> from analysis.bivariate.mask import BivariateMask
>>> loop = BivariateMask.from_symbol("((1+z1)*(1+z2)*(1+z1*z2))**2/(16*z1**2*z2**2)")
>>> sum_rules(loop).value, reproduction(loop).value
(4, 1)
>>> box_factors(loop).value
{(1, 0): 2, (0, 1): 2, (1, 1): 2}
>>> symmetry_group(loop).value                     # the 12 symmetries of the hexagonal lattice
12

References
----------
R.-Q. Jia, *Approximation properties of multivariate wavelets*, Math. Comp. 67 (1998) 647-665.
C. Cabrelli, C. Heil, U. Molter, *Self-similarity and multiwavelets in higher dimensions*, Mem. AMS 807 (2004).
C. de Boor, K. Höllig, S. Riemenschneider, *Box splines*, Springer (1993).
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*, J. Approx.
Theory 163 (2011) (the shift tau; here the bivariate analogue).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..result import CERTIFIED, AnalysisError, Result
from .mask import Z1, Z2, BivariateMask

__all__ = ["sum_rules", "coset_moments", "reproduction", "symmetry_group", "box_factors", "DIRECTIONS",
           "MAX_ORDER"]

#: sum rules are counted up to this order
MAX_ORDER = 12
#: the candidate directions of box-spline factors (one of each pair +-xi)
DIRECTIONS = ((1, 0), (0, 1), (1, 1), (1, -1), (1, 2), (2, 1), (1, -2), (2, -1))


def _monomials(d: int):
    return [(p, d - p) for p in range(d, -1, -1)]


def _cosets(a: BivariateMask) -> dict[tuple, list]:
    D = a.dilation
    rep = {D.coset(e): e for e in D.digits}
    out: dict[tuple, list] = {e: [] for e in D.digits}
    for ij, v in a:
        out[rep[D.coset(ij)]].append((ij, v))
    return out


def _zero(x: sp.Expr) -> bool:
    """Exactly zero: ``cancel`` brings a rational function of the parameters to its normal form (``expand`` alone
    does not see ``2w/(1+2w) + 1/(1+2w) - 1 = 0``)."""
    return sp.cancel(x) == 0


def coset_moments(a: BivariateMask, mu: tuple[int, int]) -> dict[tuple[int, int], sp.Expr]:
    """``{eps: sum_{alpha = eps mod M} a(alpha) alpha^mu}`` for every digit ``eps``."""
    return {e: sp.expand(sum((v * i ** mu[0] * j ** mu[1] for (i, j), v in lst), sp.Integer(0)))
            for e, lst in _cosets(a).items()}


def sum_rules(a: BivariateMask, max_order: int = MAX_ORDER) -> Result:
    """The order ``k`` of the sum rules (generic in the parameters), with the first failing moment as witness.

    ``witness["generation_degree"] = k - 1``; for a one-parameter mask, ``witness["exceptional"]`` lists the
    rational parameter values where the order is higher, with that order (irrational ones are not searched).

    >>> from analysis.bivariate.mask import BivariateMask
    >>> sum_rules(BivariateMask.from_list("0,0:1; 1,0:1; 0,1:1; 1,1:1")).value        # Haar on 2I
    1
    >>> r = sum_rules(BivariateMask.from_list("0,0:1; 1,0:1; 0,1:1; 1,1:1/2"))
    >>> r.value, r.witness["failing"]["moment"]
    (0, (0, 0))
    """
    k, fail = _order(a, max_order)
    wit: dict[str, Any] = {"generation_degree": k - 1, "failing": fail, "dual_points": a.dilation.dual_points}
    ps = a.params
    if len(ps) == 1 and fail is not None and k < max_order:
        wit["exceptional"] = _exceptional(a, ps[0], fail, max_order, k)
    return Result(value=k, status=CERTIFIED, witness=wit,
                  provenance={"method": "equal coset moments of order < k (exact)", "max_order": max_order})


def _order(a: BivariateMask, max_order: int) -> tuple[int, dict | None]:
    k = 0
    for d in range(max_order):
        for mu in _monomials(d):
            mom = coset_moments(a, mu)
            vals = list(mom.values())
            target = vals[0] if d > 0 else sp.Integer(1)
            if not all(_zero(v - target) for v in vals):
                return k, {"moment": mu, "coset_moments": mom}
        k = d + 1
    return k, None


def _exceptional(a: BivariateMask, p: sp.Symbol, fail: dict, max_order: int, generic: int) -> list[dict]:
    vals = list(fail["coset_moments"].values())
    target = vals[0] if fail["moment"] != (0, 0) else sp.Integer(1)
    # numerators: the coefficients may be rational functions of the parameter (w/(1+2w))
    eqs = [sp.fraction(sp.cancel(v - target))[0] for v in vals]
    eqs = [sp.expand(e) for e in eqs if sp.expand(e) != 0]
    g = eqs[0]
    for e in eqs[1:]:
        g = sp.gcd(g, e)
    out = []
    if g.free_symbols == {p}:
        # a value where the order is higher equalises this moment: a rational root of g (its linear factors
        # over Q, any degree); kept only where the order there is really higher (other moments of the same
        # degree may still differ)
        roots = sorted({-f.all_coeffs()[1] / f.all_coeffs()[0] for f, _ in sp.Poly(g, p).factor_list()[1]
                        if f.degree() == 1})
        for r in roots:
            try:
                at = a.at({p.name: r})
            except (AnalysisError, ZeroDivisionError):          # a pole of a coefficient: no mask there
                continue
            k, _ = _order(at, max_order)
            if k > generic:
                out.append({"value": r, "order": k})
    return out


def reproduction(a: BivariateMask, max_degree: int = MAX_ORDER - 1) -> Result:
    """The largest ``d`` with ``S_a p = p(M^{-1} . + tau)`` for all ``p`` of degree ``<= d`` (``-1``: not even
    constants), ``witness["tau"]`` the shift (``(0, 0)``: primal).

    >>> from analysis.bivariate.mask import BivariateMask
    >>> r = reproduction(BivariateMask.from_symbol("(1+z1)**3*(1+z2)**3/(16*z1*z2)"))     # biquadratic (dual)
    >>> r.value, r.witness["tau"]
    (1, (-1/4, -1/4))
    """
    k, _ = _order(a, max_degree + 1)
    if k == 0:
        return Result(value=-1, status=CERTIFIED, witness={"tau": None, "generation_degree": -1},
                      provenance={"method": "S_a p versus p(M^-1 . + tau), exact"})
    D = a.dilation
    x1, x2 = sp.symbols("x1 x2")
    cos = _cosets(a)
    pts = {ij: tuple(sp.Rational(q.numerator, q.denominator) for q in D.solve(ij)) for ij, _ in a}
    e0 = D.digits[0]
    tau = tuple(sp.expand(-sum((v * pts[ij][c] for ij, v in cos[e0]), sp.Integer(0))) for c in (0, 1))
    d = -1
    for deg in range(0, k):
        ok = True
        for mu in _monomials(deg):
            want = sp.expand((x1 + tau[0]) ** mu[0] * (x2 + tau[1]) ** mu[1])
            for e, lst in cos.items():
                got = sp.expand(sum((v * (x1 - pts[ij][0]) ** mu[0] * (x2 - pts[ij][1]) ** mu[1]
                                     for ij, v in lst), sp.Integer(0)))
                if not _zero(got - want):
                    ok = False
                    break
            if not ok:
                break
        if not ok:
            break
        d = deg
    return Result(value=d, status=CERTIFIED, witness={"tau": tau, "generation_degree": k - 1},
                  provenance={"method": "S_a p versus p(M^-1 . + tau), exact"})


def _hull(points: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """The vertices of the convex hull in counter-clockwise order (Andrew's monotone chain, exact integers)."""
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts

    def cross(o, p, q):
        return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])

    lower: list = []
    upper: list = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def symmetry_group(a: BivariateMask) -> Result:
    """The lattice symmetries of the mask: the integer matrices ``R`` (``det R = +-1``, ``R M = M R``) with
    ``a(R alpha + t) = a(alpha)`` for all ``alpha`` and an integer shift ``t``. ``value`` is the order of the
    group, ``witness["matrices"]`` its elements; ``value`` is ``None`` when the support of the mask lies on a
    line (or is one point): such a mask is fixed by infinitely many integer matrices (shears along the line).

    8 is the symmetry group of the square (quad grids), 12 that of the hexagonal lattice in the
    three-direction coordinates (:mod:`analysis.bivariate`).

    Algorithm: each such map ``alpha -> R alpha + t`` permutes the support, hence the vertices of its convex hull,
    keeping their cyclic order or reversing it; it is fixed by the images of three consecutive vertices. So the
    ``2h`` maps sending ``(v_0, v_1, v_2)`` to ``(v_k, v_{k+-1}, v_{k+-2})`` (``h`` hull vertices) are the only
    candidates, each checked exactly (an integer ``R`` with ``det R = +-1`` commuting with ``M``, and the mask
    fixed coefficient by coefficient): the group found is complete, with no bound on the entries of ``R``.

    >>> from analysis.bivariate.mask import BivariateMask
    >>> symmetry_group(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)")).value
    8
    >>> r = symmetry_group(BivariateMask.from_symbol("(1+z1)**2/2"))        # a univariate mask: a line
    >>> r.value, r.witness["degenerate"]
    (None, 'the support of the mask lies on a line: infinitely many integer matrices fix it')
    """
    M = a.dilation.matrix
    supp = [ij for ij, v in a]
    hull = _hull(supp)
    if len(hull) < 3:
        return Result(value=None, status=CERTIFIED,
                      witness={"matrices": (), "degenerate": "the support of the mask lies on a line: infinitely "
                                                            "many integer matrices fix it"},
                      provenance={"method": "convex hull of the support (exact integers)"})
    h = len(hull)
    v0, v1, v2 = hull[0], hull[1], hull[2]
    V = ((v1[0] - v0[0], v2[0] - v0[0]), (v1[1] - v0[1], v2[1] - v0[1]))        # columns v1 - v0, v2 - v0
    detV = V[0][0] * V[1][1] - V[0][1] * V[1][0]                                   # != 0: a strict hull
    group = []
    for k in range(h):
        for sgn in (1, -1):
            w0, w1, w2 = hull[k], hull[(k + sgn) % h], hull[(k + 2 * sgn) % h]
            W = ((w1[0] - w0[0], w2[0] - w0[0]), (w1[1] - w0[1], w2[1] - w0[1]))
            # R = W V^-1, exact; integer entries needed
            num = ((W[0][0] * V[1][1] - W[0][1] * V[1][0], -W[0][0] * V[0][1] + W[0][1] * V[0][0]),
                   (W[1][0] * V[1][1] - W[1][1] * V[1][0], -W[1][0] * V[0][1] + W[1][1] * V[0][0]))
            if any(x % detV for r in num for x in r):
                continue
            (p, q), (r, s_) = R = tuple(tuple(x // detV for x in row) for row in num)
            if abs(p * s_ - q * r) != 1:
                continue
            RM = ((p * M[0][0] + q * M[1][0], p * M[0][1] + q * M[1][1]),
                  (r * M[0][0] + s_ * M[1][0], r * M[0][1] + s_ * M[1][1]))
            MR = ((M[0][0] * p + M[0][1] * r, M[0][0] * q + M[0][1] * s_),
                  (M[1][0] * p + M[1][1] * r, M[1][0] * q + M[1][1] * s_))
            if RM != MR:
                continue
            t = (w0[0] - (p * v0[0] + q * v0[1]), w0[1] - (r * v0[0] + s_ * v0[1]))
            if all(_zero(a[(p * i + q * j + t[0], r * i + s_ * j + t[1])] - v) for (i, j), v in a):
                group.append(R)
    return Result(value=len(group), status=CERTIFIED, witness={"matrices": tuple(group)},
                  provenance={"method": "exact comparison of a(R alpha + t) with a(alpha)"})


def box_factors(a: BivariateMask, directions=DIRECTIONS) -> Result:
    """``{xi: n}``: the multiplicity ``n >= 1`` of the factor ``(1 + z^xi)`` of the symbol, for the candidate
    directions ``xi``; ``witness["quotient"]`` the symbol divided by ``prod ((1 + z^xi)/2)^n``.

    >>> from analysis.bivariate.mask import BivariateMask
    >>> box_factors(BivariateMask.from_symbol("(1+z1)*(1+z2)*(1+z1/z2)/(2*z1)")).value
    {(1, 0): 1, (0, 1): 1, (1, -1): 1}
    """
    num = sp.expand(a.symbol * Z1 ** max(0, -a.support_box[0][0]) * Z2 ** max(0, -a.support_box[0][1]))
    out = {}
    quotient = num
    gens = (Z1, Z2)
    for xi in directions:
        f = Z1 ** max(xi[0], 0) * Z2 ** max(xi[1], 0) + Z1 ** max(-xi[0], 0) * Z2 ** max(-xi[1], 0)
        n = 0
        while n < 2 * 40:
            q, r = sp.div(quotient, f, *gens)
            if not _zero(r):
                break
            quotient = sp.expand(q)
            n += 1
        if n:
            out[xi] = n
    scale = sp.Integer(2) ** sum(out.values())
    shift = Z1 ** max(0, -a.support_box[0][0]) * Z2 ** max(0, -a.support_box[0][1])
    return Result(value=out, status=CERTIFIED,
                  witness={"quotient": sp.expand(quotient * scale / shift)},
                  provenance={"method": "exact polynomial division by 1 + z^xi", "directions": tuple(directions)})
