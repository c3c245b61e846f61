"""Local subdivision rules at a vertex of valence n, as data: a centre, n congruent sectors, and the
rule of every new point in sector 0 as weights on old points.

A rotationally symmetric rule set is given by

* ``centre``: whether there is a centre point (the extraordinary vertex itself; Doo–Sabin has none:
  its extraordinary element is an n-gon whose corners are sector points);
* ``points``: the names of the points of one sector (sector j holds the j-th copy of each);
* one rule per new point: a tuple of :class:`Term` — a weight on the centre, on point ``p`` of the
  sector ``d`` steps further round (``d`` an integer, taken mod n), or on point ``p`` of *every*
  sector j with a weight that depends on j through ``W = exp(2 pi i j / n)`` (a Laurent polynomial
  in ``W``: ``cos(2 pi l j / n)`` is ``(W^l + W^-l)/2``).

Weights are sympy expressions in the valence ``n`` and ``C1 = cos(2 pi / n)`` (Loop's beta_n).
The catalogue rules are built from the regular stencils on the sector's lattice coordinates
(:func:`triangle_rules`, :func:`quad_rules`), so that only the rule of the centre is typed in;
:func:`user_rules` reads a user's centre and edge weights with :mod:`analysis.algebra.reader`. The
interpolating butterfly family (:func:`butterfly_rules`, :func:`modified_butterfly_rules`, with the regular
:func:`butterfly_stencil` on 2 or 3 rings) and Kobbelt's sqrt(3) (:func:`sqrt3_rules`, two steps composed)
have a section of their own below.

Examples
--------
>>> r = scheme_rules("loop", ring=1)
>>> r.points, [str(t.weight) for t in r.rules[1]]
(('e',), ['3/8', '3/8', '1/8', '1/8'])
>>> len(scheme_rules("catmull-clark").points), len(scheme_rules("doo-sabin").points)
(6, 4)
>>> r = butterfly_rules(ring=2)
>>> r.points, [str(t.weight) for t in r.rules[1]]
(('p10', 'p20', 'p11'), ['1/2', '1/2', '1/8', '1/8', '-1/16', '-1/16', '-1/16', '-1/16'])
>>> [str(t.weight) for t in modified_butterfly_rules(ring=2, n=3).rules[1][:2]]
['3/4', 'W/6 + 1/12 + 1/(6*W)']

References
----------
C. Loop, Smooth subdivision surfaces based on triangles, MS thesis, Utah, 1987 (rules, beta_n);
J. Warren, H. Weimer, Subdivision Methods for Geometric Design, 2002 (beta = 3/(8n));
E. Catmull, J. Clark, Recursively generated B-spline surfaces on arbitrary topological meshes, CAD 10
(1978); D. Doo, M. Sabin, Behaviour of recursive division surfaces near extraordinary points, CAD 10
(1978); J. Peters, U. Reif, Subdivision Surfaces, Springer 2008, ch. 4–6 (sectors, rings, Fourier
blocks).
N. Dyn, J. A. Gregory, D. Levin, A butterfly subdivision scheme for surface interpolation with tension
control, ACM TOG 9 (1990); D. Zorin, P. Schröder, W. Sweldens, Interpolating subdivision for meshes with
arbitrary topology, SIGGRAPH 1996; D. Zorin, A method for analysis of C^1-continuity of subdivision
surfaces, SIAM J. Numer. Anal. 37 (2000); L. Kobbelt, sqrt(3)-subdivision, SIGGRAPH 2000 (the stencils and
the choice of alpha_n); OpenMesh's ``ModifiedButterFlyT.hh`` (cross-check of the n = 3, 4 weights).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

from ..result import AnalysisError

#: the valence and cos(2 pi / n), the symbols weights may use
n_sym = sp.Symbol("n", positive=True, integer=True)
C1 = sp.Symbol("C1")
#: exp(2 pi i j / n) in a weight on every sector j
W = sp.Symbol("W")
CENTRE = "centre"
ALL = "all"


@dataclass(frozen=True)
class Term:
    """``weight`` times an old point: ``(CENTRE,)``, ``(p, d)`` (point p of sector i + d for the new point
    of sector i) or ``(p, ALL)`` (every sector j, weight a Laurent polynomial in W = exp(2 pi i j/n))."""

    weight: sp.Expr
    source: tuple


@dataclass(frozen=True)
class LocalRules:
    """The rules of one scheme near a vertex: ``rules[0]`` is the centre's (if ``centre``), then one
    rule per sector point, in the order of ``points``."""

    name: str
    centre: bool
    points: tuple[str, ...]
    rules: tuple[tuple[Term, ...], ...]
    lattice: str
    ring: int
    source: str
    min_valence: int = 3
    #: lattice coordinates (x, y) of the sector points in sector 0 (x >= 1, y >= 0), when on a lattice
    coords: tuple = ()
    #: the smallest valence at which the rules with n symbolic (``n=None``) are the rules at n
    generic_from: int = 1
    #: the butterfly family's tension w (None for other rules)
    tension: object = None

    @property
    def size(self) -> str:
        """The size of the local matrix as a formula in n."""
        m = len(self.points)
        return f"{m}n + 1" if self.centre else f"{m}n"

    def sector_rules(self) -> tuple[tuple[Term, ...], ...]:
        return self.rules[1:] if self.centre else self.rules

    def check_valence(self, n: int) -> None:
        if n < self.min_valence:
            raise AnalysisError(f"valence {n} is below {self.min_valence}: give --valence 3..N")


# --------------------------------------------------------------------------------------------------
# lattices: sector coordinates, neighbours, the regular stencils

def _tri_home(x: int, y: int) -> tuple[int, int, int]:
    """Sector offset and coordinates of the triangular-lattice point ``x u + y v`` of sector 0
    (u = e_0, v = e_1) in the sector that holds it (x >= 1, y >= 0)."""
    d = 0
    while (x, y) != (0, 0) and not (x >= 1 and y >= 0):
        if y < 0:
            x, y, d = -y, x + y, d - 1
        else:
            x, y, d = x + y, -x, d + 1
    return d, x, y


def _quad_home(x: int, y: int) -> tuple[int, int, int]:
    d = 0
    while (x, y) != (0, 0) and not (x >= 1 and y >= 0):
        if y < 0:
            x, y, d = -y, x, d - 1
        else:
            x, y, d = y, -x, d + 1
    return d, x, y


#: the six neighbour directions of the triangular lattice, in cyclic order
_TRI_DIRS = ((1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1))
_QUAD_EDGE = ((1, 0), (0, 1), (-1, 0), (0, -1))
_QUAD_DIAG = ((1, 1), (-1, 1), (-1, -1), (1, -1))


def _stencil_terms(stencil, coords: Mapping[tuple[int, int], int], home, centre_rule) -> tuple[Term, ...]:
    """Terms of a lattice stencil ``[(weight, (x2, y2)), ...]`` (doubled coordinates of level m)."""
    out: dict[tuple, sp.Expr] = {}
    for wgt, (x, y) in stencil:
        d, hx, hy = home(x, y)
        if (hx, hy) == (0, 0):
            src = (CENTRE,)
        elif (hx, hy) in coords:
            src = (coords[(hx, hy)], d)
        else:
            raise AnalysisError(f"the rings are not closed under subdivision: point {(hx, hy)} is needed")
        out[src] = out.get(src, sp.S.Zero) + wgt
    return tuple(Term(w, s) for s, w in out.items())


def triangle_rules(name: str, ring: int, centre_rule: tuple[Term, ...], source: str) -> LocalRules:
    """Loop-type rules on the triangular lattice: the centre's rule given, every other new point by
    Loop's regular stencils (edge 3/8, 3/8, 1/8, 1/8; vertex 5/8 and 1/16 on six neighbours)."""
    sector = {1: [(1, 0)], 2: [(1, 0), (1, 1), (2, 0)]}[ring]
    names = {(1, 0): "e", (1, 1): "a", (2, 0): "b"}
    coords = {p: i for i, p in enumerate(sector)}
    rules = [centre_rule]
    for X, Y in sector:                       # new point at level m+1 = (X/2, Y/2) at level m
        if X % 2 == 0 and Y % 2 == 0:
            x, y = X // 2, Y // 2
            st = [(sp.Rational(5, 8), (x, y))] + [(sp.Rational(1, 16), (x + dx, y + dy)) for dx, dy in _TRI_DIRS]
        else:
            i = next(i for i, (dx, dy) in enumerate(_TRI_DIRS) if (X - dx) % 2 == 0 and (Y - dy) % 2 == 0)
            dx, dy = _TRI_DIRS[i]
            p = ((X - dx) // 2, (Y - dy) // 2)
            q = (p[0] + dx, p[1] + dy)
            o1 = tuple(a + b for a, b in zip(p, _TRI_DIRS[(i - 1) % 6]))
            o2 = tuple(a + b for a, b in zip(p, _TRI_DIRS[(i + 1) % 6]))
            st = [(sp.Rational(3, 8), p), (sp.Rational(3, 8), q), (sp.Rational(1, 8), o1), (sp.Rational(1, 8), o2)]
        rules.append(_stencil_terms(st, coords, _tri_home, centre_rule))
    return LocalRules(name, True, tuple(names[p] for p in sector), tuple(rules), "triangle", ring, source,
                      coords=tuple(sector))


def quad_rules(name: str, ring: int, centre_rule: tuple[Term, ...], source: str) -> LocalRules:
    """Catmull–Clark-type rules on the square lattice: the centre's rule given, every other new point
    by the bicubic B-spline stencils (face 1/4; edge 3/8, 3/8 and 1/16 on four; vertex 9/16, 3/32, 1/64)."""
    sector = {1: [(1, 0), (1, 1)], 2: [(1, 0), (1, 1), (2, 0), (2, 1), (2, 2), (1, 2)]}[ring]
    names = {(1, 0): "e", (1, 1): "f", (2, 0): "g", (2, 1): "h", (2, 2): "i", (1, 2): "l"}
    coords = {p: i for i, p in enumerate(sector)}
    rules = [centre_rule]
    h = sp.Rational
    for X, Y in sector:
        if X % 2 == 0 and Y % 2 == 0:
            x, y = X // 2, Y // 2
            st = ([(h(9, 16), (x, y))] + [(h(3, 32), (x + a, y + b)) for a, b in _QUAD_EDGE]
                  + [(h(1, 64), (x + a, y + b)) for a, b in _QUAD_DIAG])
        elif X % 2 == 1 and Y % 2 == 1:
            x, y = (X - 1) // 2, (Y - 1) // 2
            st = [(h(1, 4), (x + a, y + b)) for a, b in ((0, 0), (1, 0), (0, 1), (1, 1))]
        elif X % 2 == 1:                      # edge along x between (x, y) and (x+1, y)
            x, y = (X - 1) // 2, Y // 2
            st = ([(h(3, 8), (x, y)), (h(3, 8), (x + 1, y))]
                  + [(h(1, 16), (x + a, y + b)) for a in (0, 1) for b in (-1, 1)])
        else:
            x, y = X // 2, (Y - 1) // 2
            st = ([(h(3, 8), (x, y)), (h(3, 8), (x, y + 1))]
                  + [(h(1, 16), (x + a, y + b)) for a in (-1, 1) for b in (0, 1)])
        rules.append(_stencil_terms(st, coords, _quad_home, centre_rule))
    return LocalRules(name, True, tuple(names[p] for p in sector), tuple(rules), "quad", ring, source,
                      coords=tuple(sector))


def doo_sabin_rules() -> LocalRules:
    """Doo–Sabin at an n-gon: sector j holds the n-gon's corner p_j, the outer corners a_j, b_j of the
    quad on edge p_j p_(j+1) (a_j next to p_j) and the corner c_j of the quad at p_j opposite p_j."""
    h = sp.Rational
    alpha = (3 + W + 1 / W) / (4 * n_sym)          # (3 + 2 cos(2 pi j / n)) / (4n) on every corner j
    ngon = (Term(h(1, 4), (0, 0)), Term(alpha, (0, ALL)))
    a = (Term(h(9, 16), (0, 0)), Term(h(3, 16), (0, 1)), Term(h(3, 16), (1, 0)), Term(h(1, 16), (2, 0)))
    b = (Term(h(9, 16), (0, 1)), Term(h(3, 16), (0, 0)), Term(h(3, 16), (2, 0)), Term(h(1, 16), (1, 0)))
    c = (Term(h(9, 16), (0, 0)), Term(h(3, 16), (1, 0)), Term(h(3, 16), (2, -1)), Term(h(1, 16), (3, 0)))
    return LocalRules("doo-sabin", False, ("p", "a", "b", "c"), (ngon, a, b, c), "dual quad", 1,
                      "Doo, Sabin, CAD 10 (1978): alpha_0 = 1/4 + 5/(4n), alpha_j = (3 + 2 cos(2 pi j/n))/(4n)")


def _loop_centre(beta: sp.Expr) -> tuple[Term, ...]:
    return (Term(1 - n_sym * beta, (CENTRE,)), Term(beta, (0, ALL)))


#: Loop's beta_n (Loop 1987): (5/8 - (3/8 + cos(2 pi/n)/4)^2) / n
LOOP_BETA = (sp.Rational(5, 8) - (sp.Rational(3, 8) + C1 / 4) ** 2) / n_sym


def _warren_beta(n: int | None) -> sp.Expr:
    if n is None:
        return 3 / (8 * n_sym)
    return sp.Rational(3, 16) if n == 3 else sp.Rational(3, 8 * n)


def _cc_centre() -> tuple[Term, ...]:
    # v' = (1 - 7/(4n)) v + 3/(2n^2) sum e_j + 1/(4n^2) sum f_j  (Catmull–Clark 1978, with the
    # face and edge points substituted into (Q + 2R + (n-3) S)/n)
    return (Term(1 - sp.Rational(7, 4) / n_sym, (CENTRE,)), Term(sp.Rational(3, 2) / n_sym ** 2, (0, ALL)),
            Term(sp.Rational(1, 4) / n_sym ** 2, (1, ALL)))


SCHEMES: dict[str, tuple[str, str]] = {
    "loop": ("triangle", "Loop 1987: beta_n = (5/8 - (3/8 + cos(2 pi/n)/4)^2)/n"),
    "loop-warren": ("triangle", "Warren, Weimer 2002: beta = 3/(8n) (n > 3), 3/16 (n = 3)"),
    "catmull-clark": ("quad", "Catmull, Clark, CAD 10 (1978): alpha = 1 - 7/(4n), beta = 3/(2n^2), gamma = 1/(4n^2)"),
    "doo-sabin": ("dual quad", "Doo, Sabin, CAD 10 (1978)"),
    "butterfly": ("triangle, interpolating", "Dyn, Gregory, Levin 1990"),
    "modified-butterfly": ("triangle, interpolating", "Zorin, Schroeder, Sweldens 1996"),
    "sqrt3": ("sqrt3", "Kobbelt 2000"),
}


def scheme_rules(name: str, ring: int = 2, n: int | None = None, tension: sp.Expr | None = None) -> LocalRules:
    """The local rules of a catalogue scheme on ``ring`` rings (1: the 1-ring, enough for the leading
    eigenvalues of Loop and Catmull–Clark; 2: the 2-ring, the support of the patches of the first
    ring, which the characteristic map needs; the butterfly schemes take 2 or 3, sqrt(3) (two steps) 1 or 2).
    ``n`` matters only for rules piecewise in n (Warren's beta at n = 3, the modified butterfly at
    n = 3, 4); ``tension`` is the butterfly's w (default 1/16)."""
    if name not in SCHEMES:
        raise AnalysisError(f"unknown scheme {name!r} for `subdiv vertex`: use one of {', '.join(SCHEMES)}")
    if name in ("butterfly", "modified-butterfly", "sqrt3"):
        w = DEFAULT_TENSION if tension is None else tension
        if name != "sqrt3" and ring not in BUTTERFLY_RINGS:
            raise AnalysisError(f"the butterfly schemes take --ring 2 or 3, not {ring}")
        if name == "butterfly":
            return butterfly_rules(ring, w)
        if name == "modified-butterfly":
            return modified_butterfly_rules(ring, n, w)
        if ring not in (1, 2):
            raise AnalysisError(f"sqrt3 is analysed on its 1-ring or 2-ring (two steps): give --ring 1 or 2, not {ring}")
        return sqrt3_rules(ring=ring)
    if tension is not None:
        raise AnalysisError("--tension applies to the butterfly schemes only")
    if ring not in (1, 2):
        raise AnalysisError(f"--ring must be 1 or 2, not {ring}")
    lattice, src = SCHEMES[name]
    if name == "loop":
        return triangle_rules(name, ring, _loop_centre(LOOP_BETA), src)
    if name == "loop-warren":
        return triangle_rules(name, ring, _loop_centre(_warren_beta(n)), src)
    if name == "catmull-clark":
        return quad_rules(name, ring, _cc_centre(), src)
    return doo_sabin_rules()


# --------------------------------------------------------------------------------------------------
# the interpolating butterfly family and Kobbelt's sqrt(3)
#
# Local rules of the interpolating butterfly family and of Kobbelt's sqrt(3) scheme at a vertex of valence n.
#
# * **Butterfly** (Dyn, Gregory, Levin 1990), tension ``w`` (default 1/16): old vertices stay; the new point
#   on an edge ``pq`` is ``(p + q)/2 + 2w (o1 + o2) - w (four wings)``, o1, o2 the opposite vertices of the two
#   triangles on the edge, the wings the opposite vertices of the four triangles across their other edges.
#   At an extraordinary vertex the stencil is applied as it stands (its points are found by walking the
#   triangles round the vertex; at n = 3 a wing of the edge at the centre *is* the opposite vertex o2, so the
#   weights add).
# * **Modified butterfly** (Zorin, Schröder, Sweldens 1996): the same regular rule; the new point on an edge
#   from the extraordinary vertex to e_0 is ``3/4 centre + sum_j s_j e_j`` with
#   ``s_j = (1/4 + cos(2 pi j/n) + cos(4 pi j/n)/2)/n`` for n >= 5, ``(5/12, -1/12, -1/12)`` for n = 3 and
#   ``(3/8, 0, -1/8, 0)`` for n = 4.
# * **sqrt(3)** (Kobbelt 2000): one step inserts the centroid ``f_j = (p + e_j + e_(j+1))/3`` of every
#   triangle, relaxes every old vertex to ``(1 - alpha_n) p + alpha_n/n sum e_j``,
#   ``alpha_n = (4 - 2 cos(2 pi/n))/9``, and flips the old edges: the new 1-ring of p is the n centroids,
#   turned by pi/n against the old one. One step is therefore no map of a ring onto itself *in the same
#   position*: its Fourier block k is ``(1 + w^k)/3``, complex, with the phase ``pi k/n`` of the turn.
#   We take **two steps**: the second step's new neighbours of p are the
#   centroids of ``(p', f_(j-1), f_j)``, aligned with the old e_j, so two steps map the 1-ring onto itself
#   without a turn (a triadic refinement: lambda = 1/3 at n = 6). The rules below are those of the two-step
#   map on the 1-ring, composed exactly (see :func:`sqrt3_rules`).
#
# The butterfly rules are built on the triangular lattice's sectors with the regular stencil
# (:func:`butterfly_stencil`) as Loop's are, on ``ring`` rings: the 2-ring is the smallest set closed under
# the rules (the scheme is interpolating: the new points within distance 2 depend on old points within
# distance 2); the 3-ring adds the outer points whose wings reach the 3-ring (their block is triangular, with
# eigenvalues 0 and -w), and beyond the 3-ring every new point of ring r >= 4 depends on old points of rings
# <= r - 1 only, so larger rings add only the eigenvalue 0.
#: the butterfly's default tension (Dyn–Gregory–Levin 1990)
DEFAULT_TENSION = sp.Rational(1, 16)
#: rings of the butterfly's local matrix: 2 is the smallest closed set, 3 adds the outer block
BUTTERFLY_RINGS = (2, 3)
#: larger rings (every ring is closed under the rules) serve the numerical characteristic map only
MAX_BUTTERFLY_RING = 32


def _number(x) -> sp.Expr:
    """A weight given as a sympy expression or a Python int or Fraction (never text)."""
    if isinstance(x, sp.Basic):
        return x
    if isinstance(x, int):
        return sp.Integer(x)
    from fractions import Fraction

    if isinstance(x, Fraction):
        return sp.Rational(x.numerator, x.denominator)
    raise AnalysisError(f"a weight must be a number or an expression, not {type(x).__name__}")


def triangle_sector(ring: int) -> list[tuple[int, int]]:
    """The lattice points of sector 0 (x >= 1, y >= 0) within ``ring`` rings, ring by ring.

    >>> triangle_sector(3)
    [(1, 0), (2, 0), (1, 1), (3, 0), (2, 1), (1, 2)]
    """
    return [(x, r - x) for r in range(1, ring + 1) for x in range(r, 0, -1)]


def butterfly_stencil(X: int, Y: int, tension: sp.Expr = DEFAULT_TENSION) -> list[tuple[sp.Expr, tuple[int, int]]]:
    """The regular rule of the new point at level-1 lattice coordinates (X, Y) as weights on level-0 points.

    >>> [(str(a), p) for a, p in butterfly_stencil(2, 0)]
    [('1', (1, 0))]
    >>> sorted(p for a, p in butterfly_stencil(1, 0) if a == -sp.Rational(1, 16))
    [(-1, 1), (0, -1), (1, 1), (2, -1)]
    """
    if X % 2 == 0 and Y % 2 == 0:
        return [(sp.S.One, (X // 2, Y // 2))]
    i = next(i for i, (dx, dy) in enumerate(_TRI_DIRS) if (X - dx) % 2 == 0 and (Y - dy) % 2 == 0)

    def d(j):
        return _TRI_DIRS[j % 6]

    def add(a, b):
        return (a[0] + b[0], a[1] + b[1])

    p = ((X - d(i)[0]) // 2, (Y - d(i)[1]) // 2)
    q = add(p, d(i))
    half, w = sp.Rational(1, 2), _number(tension)
    return ([(half, p), (half, q), (2 * w, add(p, d(i + 1))), (2 * w, add(p, d(i - 1)))]
            + [(-w, add(p, d(i + 2))), (-w, add(q, d(i + 1))), (-w, add(p, d(i - 2))), (-w, add(q, d(i - 1)))])


def _lattice_rules(name: str, ring: int, centre_rule, overrides: dict, tension, source: str,
                   generic_from: int = 1) -> LocalRules:
    if not 2 <= ring <= MAX_BUTTERFLY_RING:
        raise AnalysisError(f"the butterfly schemes take --ring 2 or 3, not {ring}")
    sector = triangle_sector(ring)
    coords = {p: i for i, p in enumerate(sector)}
    rules = [centre_rule]
    for X, Y in sector:
        if (X, Y) in overrides:
            rules.append(overrides[(X, Y)])
        else:
            rules.append(_stencil_terms(butterfly_stencil(X, Y, tension), coords, _tri_home, centre_rule))
    return LocalRules(name, True, tuple(f"p{x}_{y}" if ring > 9 else f"p{x}{y}" for x, y in sector), tuple(rules),
                      "triangle, interpolating", ring, source, coords=tuple(sector), generic_from=generic_from,
                      tension=tension)


def butterfly_rules(ring: int = 3, tension: sp.Expr = DEFAULT_TENSION) -> LocalRules:
    """The original butterfly scheme at a vertex of valence n, on ``ring`` (2 or 3) rings."""
    w = _number(tension)
    src = f"Dyn, Gregory, Levin 1990: butterfly, tension w = {w}, the regular stencil at every edge"
    return _lattice_rules("butterfly", ring, (Term(sp.S.One, (CENTRE,)),), {}, w, src)


def modified_butterfly_weights(n: int | None) -> sp.Expr:
    """``s_j`` of the modified butterfly as a Laurent polynomial in ``W = exp(2 pi i j/n)`` (n = None: the
    formula for n >= 5).

    >>> modified_butterfly_weights(4)
    W**2/32 + W/8 + 1/16 + 1/(8*W) + 1/(32*W**2)
    """
    if n == 3:                       # s = (5/12, -1/12, -1/12) = 1/12 + (2/6) cos(2 pi j/3)
        return sp.Rational(1, 12) + (W + 1 / W) / 6
    if n == 4:                       # s = (3/8, 0, -1/8, 0) = 1/16 + cos(pi j/2)/4 + cos(pi j)/16
        return sp.Rational(1, 16) + (W + 1 / W) / 8 + (W ** 2 + W ** -2) / 32
    return sp.expand((sp.Rational(1, 4) + (W + 1 / W) / 2 + (W ** 2 + W ** -2) / 4) / n_sym)


def modified_butterfly_rules(ring: int = 3, n: int | None = None, tension: sp.Expr = DEFAULT_TENSION) -> LocalRules:
    """The modified butterfly (Zorin–Schröder–Sweldens 1996) at a vertex of valence n: the regular
    butterfly everywhere except the new points on the edges at the vertex (``3/4`` on the vertex, ``s_j``
    on its neighbours e_j). ``n`` selects the special weights of n = 3, 4 (None: the formula, n >= 5)."""
    w = _number(tension)
    edge = (Term(sp.Rational(3, 4), (CENTRE,)), Term(modified_butterfly_weights(n), (0, ALL)))
    src = ("Zorin, Schroeder, Sweldens 1996: 3/4 and s_j = (1/4 + cos(2 pi j/n) + cos(4 pi j/n)/2)/n (n >= 5; "
           f"n = 3: 5/12, -1/12, -1/12; n = 4: 3/8, 0, -1/8, 0); butterfly tension w = {w} elsewhere")
    return _lattice_rules("modified-butterfly", ring, (Term(sp.S.One, (CENTRE,)),), {(1, 0): edge}, w, src,
                          generic_from=5 if n is None else 1)


#: Kobbelt's alpha_n = (4 - 2 cos(2 pi/n))/9
SQRT3_ALPHA = (4 - 2 * C1) / 9


#: the six directions of the level-1 (turned) lattice in thirds of level-0 lattice coordinates, in cyclic order
_SQRT3_DIRS = ((1, 1), (-1, 2), (-2, 1), (-1, -1), (1, -2), (2, -1))


def sqrt3_rules(alpha: sp.Expr = SQRT3_ALPHA, ring: int = 1) -> LocalRules:
    """Two steps of Kobbelt's sqrt(3) scheme on ``ring`` rings (1: :func:`sqrt3_rules_1ring`, closed form; 2:
    composed on the lattice by :func:`_sqrt3_lattice_rules`)."""
    if ring == 1:
        return sqrt3_rules_1ring(alpha)
    if ring != 2:
        raise AnalysisError(f"sqrt3 takes --ring 1 or 2, not {ring}")
    return _sqrt3_lattice_rules(_number(alpha), ring)


def _sqrt3_lattice_rules(a: sp.Expr, ring: int) -> LocalRules:
    """Two sqrt(3) steps on the lattice, points in thirds of level-0 coordinates (``X = 3x``): the level-1
    points are the old vertices (X, Y = 0 mod 3) and the face centroids (X = Y mod 3), the level-2 points all
    integer (X, Y). Old vertices other than the centre have valence 6 (alpha_6 = 1/3: 2/3 and 1/18 on the
    six neighbours); the centre is relaxed with alpha_n in both steps; a level-1 point is relaxed over its six
    level-1 neighbours ``P + d`` (:data:`_SQRT3_DIRS`); a new level-2 point is the centroid of its level-1
    triangle."""
    sector = triangle_sector(ring)
    coords = {p: i for i, p in enumerate(sector)}
    third = sp.Rational(1, 3)

    def add(acc: dict, terms: dict, wgt) -> None:
        for k, v in terms.items():
            acc[k] = acc.get(k, sp.S.Zero) + wgt * v

    def level0(x: int, y: int) -> dict:
        d, hx, hy = _tri_home(x, y)
        if (hx, hy) == (0, 0):
            return {(CENTRE,): sp.S.One}
        if (hx, hy) not in coords:
            raise AnalysisError(f"the rings are not closed under two sqrt(3) steps: point {(hx, hy)} is needed")
        return {(coords[(hx, hy)], d): sp.S.One}

    centre1 = {(CENTRE,): 1 - a, (coords[(1, 0)], ALL): a / n_sym}     # p' = (1 - a) p + (a/n) sum e_j

    def level1(X: int, Y: int) -> dict:
        if (X, Y) == (0, 0):
            return dict(centre1)
        if X % 3 == 0 and Y % 3 == 0:                                  # an old vertex of valence 6
            x, y = X // 3, Y // 3
            out = {}
            add(out, level0(x, y), sp.Rational(2, 3))
            for dx, dy in _TRI_DIRS:
                add(out, level0(x + dx, y + dy), sp.Rational(1, 18))
            return out
        x, y = (X - 1) // 3, (Y - 1) // 3
        tri = ((x, y), (x + 1, y), (x, y + 1)) if (X - 1) % 3 == 0 else ((x + 1, y), (x + 1, y + 1), (x, y + 1))
        out = {}
        for px, py in tri:
            add(out, level0(px, py), third)
        return out

    def level2(X: int, Y: int) -> dict:
        out = {}
        if (X - Y) % 3 == 0:                                           # a level-1 point, relaxed
            if (X, Y) == (0, 0):
                raise AnalysisError("the centre's two-step rule is the closed form of sqrt3_rules_1ring")
            add(out, level1(X, Y), sp.Rational(2, 3))
            for dx, dy in _SQRT3_DIRS:
                add(out, level1(X + dx, Y + dy), sp.Rational(1, 18))
            return out
        offsets = ((0, -1), (1, 0), (-1, 1)) if (X - Y + 1) % 3 == 0 else ((1, -1), (0, 1), (-1, 0))
        for dx, dy in offsets:
            add(out, level1(X + dx, Y + dy), third)
        return out

    one = sqrt3_rules_1ring(a)
    rules = [one.rules[0]]
    for X, Y in sector:
        terms = level2(X, Y)
        rules.append(tuple(Term(sp.expand(v), k) for k, v in terms.items() if sp.expand(v) != 0))
    src = ("Kobbelt 2000: sqrt(3), alpha_n = (4 - 2 cos(2 pi/n))/9; two steps (the refinement turns the ring by "
           f"pi/n per step), {ring}-ring")
    return LocalRules("sqrt3", True, tuple(f"q{x}{y}" for x, y in sector), tuple(rules), "sqrt3", ring, src,
                      coords=tuple(sector))


def sqrt3_rules_1ring(alpha: sp.Expr = SQRT3_ALPHA) -> LocalRules:
    """Two steps of Kobbelt's sqrt(3) scheme on the 1-ring (centre p, neighbours e_j), composed exactly:

    ``p'' = ((1 - a)^2 + a/3) p + (a/n)(5/3 - a) sum e_j`` and
    ``e_j'' = ((1 - a)/3 + 2/9) p + a/(3n) sum e_l + (e_(j-1) + 2 e_j + e_(j+1))/9`` (a = alpha_n),
    from ``p' = (1 - a) p + (a/n) sum e_j``, ``f_j = (p + e_j + e_(j+1))/3`` and ``e_j'' = (p' + f_(j-1) + f_j)/3``.

    >>> [str(t.weight) for t in sqrt3_rules_1ring(sp.Rational(1, 3)).rules[1]]
    ['4/9', '1/(9*n)', '1/9', '2/9', '1/9']
    """
    a = _number(alpha)
    third, ninth = sp.Rational(1, 3), sp.Rational(1, 9)
    centre = (Term(sp.expand((1 - a) ** 2 + a / 3), (CENTRE,)), Term(sp.expand(a / n_sym * (1 - a + 2 * third)), (0, ALL)))
    ring = (Term(sp.expand((1 - a) / 3 + 2 * ninth), (CENTRE,)), Term(sp.expand(a / (3 * n_sym)), (0, ALL)),
            Term(ninth, (0, -1)), Term(2 * ninth, (0, 0)), Term(ninth, (0, 1)))
    src = ("Kobbelt 2000: sqrt(3), alpha_n = (4 - 2 cos(2 pi/n))/9; two steps (the refinement turns the ring by "
           "pi/n per step), 1-ring")
    return LocalRules("sqrt3", True, ("e",), (centre, ring), "sqrt3", 1, src)

# --------------------------------------------------------------------------------------------------
# user rules

def _cos_to_W(expr: sp.Expr, j: sp.Symbol, what: str) -> sp.Expr:
    """``cos(2 pi l j / n)`` -> ``(W^l + W^-l)/2``; anything else that depends on j is refused."""

    def repl(arg):
        ratio = sp.simplify(arg / (2 * sp.pi * j / n_sym))
        if not (ratio.is_Integer):
            raise AnalysisError(f"{what}: cos({arg}) is not cos(2*pi*l*j/n) with an integer l; "
                                "write the j-dependence as cos(2*pi*j/n), cos(4*pi*j/n), ...")
        return (W ** int(ratio) + W ** (-int(ratio))) / 2

    out = expr.replace(lambda e: isinstance(e, sp.cos) and e.has(j), lambda e: repl(e.args[0]))
    if out.has(j):
        raise AnalysisError(f"{what}: j may appear only inside cos(2*pi*l*j/n)")
    return sp.expand(out)


def read_weight(text: str, what: str, *, with_j: bool = False, free: str | None = None) -> sp.Expr:
    """A weight read by :func:`analysis.algebra.reader.read_expression`: names ``n``, ``c``
    (= cos(2 pi/n)) and, for weights on every sector, ``j``.

    >>> read_weight("3/(8*n)", "centre weight")
    3/(8*n)
    >>> read_weight("(1/4 + cos(2*pi*j/n))/n", "edge weight", with_j=True)
    W/(2*n) + 1/(4*n) + 1/(2*W*n)
    """
    from ..algebra.reader import read_expression

    j = sp.Symbol("j", integer=True)
    names = {"n": n_sym, "c": C1}
    if with_j:
        names["j"] = j
    if free:
        names[free] = free_weight(free)
    e = read_expression(text, names=names, free=False, what=what,
                        hint="the weights may use n, c = cos(2*pi/n)" + (" and j" if with_j else "")
                        + (f" and the free weight {free}" if free else ""))
    return _cos_to_W(e, j, what) if with_j else e


def free_weight(name: str) -> sp.Symbol:
    """The symbol of a free weight named by the user (``--tune NAME``)."""
    return sp.Symbol(f"free_{name}", real=True)


def regular_next_to_centre(rules: LocalRules) -> bool:
    """Whether every new point except the centre is made by the regular stencils (the rules are those of
    :func:`~analysis.vertex.rules.triangle_rules` / :func:`~analysis.vertex.rules.quad_rules` with the same centre
    rule). The characteristic map's segment is read as box-spline (bicubic) patches of the level-1 net, which is
    its limit only when every later refinement there is regular; a special rule for the edge points next to the
    centre (``--edge``) also makes the points on the centre's edges at every finer level, inside those patches.

    >>> from analysis.vertex.rules import scheme_rules, user_rules
    >>> regular_next_to_centre(scheme_rules("loop", ring=2))
    True
    >>> regular_next_to_centre(user_rules("triangle", "3/(8*n)", "3/8; (5/8 + cos(2*pi*j/n))/n"))
    False
    """
    if rules.lattice not in ("quad", "triangle"):
        return True
    build = triangle_rules if rules.lattice == "triangle" else quad_rules
    reference = build(rules.name, rules.ring, rules.rules[0], rules.source)
    return reference.points == rules.points and reference.rules[1:] == rules.rules[1:]


def user_rules(lattice: str, centre: str, edge: str | None = None, *, ring: int = 2,
               free: str | None = None) -> LocalRules:
    """Rules typed by a user: the regular stencils of ``lattice`` ('triangle': Loop's; 'quad':
    Catmull–Clark's), the centre's rule ``centre`` = "WEIGHT_ON_EACH_EDGE_NEIGHBOUR" (triangle; the centre
    keeps 1 - n*w) or "W_EDGE, W_FACE" (quad; the centre keeps 1 - n*(w_e + w_f)), and optionally the rule of
    the new edge points next to the centre, ``edge`` = "W_CENTRE; W(j)" (weight W(j) on the edge neighbour
    e_j of the new point on edge e_0, an expression in n and cos(2*pi*l*j/n); on quads "W_CENTRE; W(j); F(j)",
    F(j) on the face neighbour f_j).

    >>> r = user_rules("triangle", "3/(8*n)")
    >>> [str(t.weight) for t in r.rules[0]]
    ['5/8', '3/(8*n)']
    """
    if lattice not in ("triangle", "quad"):
        raise AnalysisError(f"--lattice must be triangle or quad, not {lattice!r}")
    if ring not in (1, 2):
        raise AnalysisError(f"--ring must be 1 or 2 for user rules, not {ring}")
    parts = [p for p in centre.split(",")]
    want = 1 if lattice == "triangle" else 2
    if len(parts) != want:
        raise AnalysisError(f"--centre takes {want} weight{'s' if want > 1 else ''} on a {lattice} lattice "
                            f"({'the weight of each edge neighbour' if want == 1 else 'W_EDGE, W_FACE'})")
    ws = [read_weight(p.strip(), "centre weight", free=free) for p in parts]
    terms = [Term(sp.expand(1 - n_sym * sum(ws)), (CENTRE,))]
    terms += [Term(w, (i, ALL)) for i, w in enumerate(ws)]
    build = triangle_rules if lattice == "triangle" else quad_rules
    rules = build("user", ring, tuple(terms), f"user rules on the {lattice} lattice")
    if edge is not None:
        e = edge.split(";")
        if len(e) != want + 1:
            raise AnalysisError(f'--edge takes {"W_CENTRE; W(j)" if want == 1 else "W_CENTRE; W(j); F(j)"}: the '
                                'weight of the centre and of each edge neighbour e_j (and face neighbour f_j) '
                                'in the new point on the edge to e_0, e.g. "3/8; (1/4+cos(2*pi*j/n))/n"')
        wc = read_weight(e[0].strip(), "edge weight of the centre")
        ws_j = [read_weight(t.strip(), "edge weight W(j)", with_j=True) for t in e[1:]]
        new = list(rules.rules)
        new[1] = (Term(wc, (CENTRE,)), *(Term(w, (i, ALL)) for i, w in enumerate(ws_j)))
        rules = LocalRules(rules.name, True, rules.points, tuple(new), lattice, ring,
                           rules.source + ", edge rule at the centre given", coords=rules.coords)
    return rules

