"""Local rules of the interpolating butterfly family and of Kobbelt's sqrt(3) scheme at a vertex of valence n.

* **Butterfly** (Dyn, Gregory, Levin 1990), tension ``w`` (default 1/16): old vertices stay; the new point
  on an edge ``pq`` is ``(p + q)/2 + 2w (o1 + o2) - w (four wings)``, o1, o2 the opposite vertices of the two
  triangles on the edge, the wings the opposite vertices of the four triangles across their other edges.
  At an extraordinary vertex the stencil is applied as it stands (its points are found by walking the
  triangles round the vertex; at n = 3 a wing of the edge at the centre *is* the opposite vertex o2, so the
  weights add).
* **Modified butterfly** (Zorin, Schröder, Sweldens 1996): the same regular rule; the new point on an edge
  from the extraordinary vertex to e_0 is ``3/4 centre + sum_j s_j e_j`` with
  ``s_j = (1/4 + cos(2 pi j/n) + cos(4 pi j/n)/2)/n`` for n >= 5, ``(5/12, -1/12, -1/12)`` for n = 3 and
  ``(3/8, 0, -1/8, 0)`` for n = 4.
* **sqrt(3)** (Kobbelt 2000): one step inserts the centroid ``f_j = (p + e_j + e_(j+1))/3`` of every
  triangle, relaxes every old vertex to ``(1 - alpha_n) p + alpha_n/n sum e_j``,
  ``alpha_n = (4 - 2 cos(2 pi/n))/9``, and flips the old edges: the new 1-ring of p is the n centroids,
  turned by pi/n against the old one. One step is therefore no map of a ring onto itself *in the same
  position*: its Fourier block k is ``(1 + w^k)/3``, complex, with the phase ``pi k/n`` of the turn.
  We take **two steps**: the second step's new neighbours of p are the
  centroids of ``(p', f_(j-1), f_j)``, aligned with the old e_j, so two steps map the 1-ring onto itself
  without a turn (a triadic refinement: lambda = 1/3 at n = 6). The rules below are those of the two-step
  map on the 1-ring, composed exactly (see :func:`sqrt3_rules`).

The butterfly rules are built on the triangular lattice's sectors with the regular stencil
(:func:`butterfly_stencil`) as Loop's are, on ``ring`` rings: the 2-ring is the smallest set closed under
the rules (the scheme is interpolating: the new points within distance 2 depend on old points within
distance 2); the 3-ring adds the outer points whose wings reach the 3-ring (their block is triangular, with
eigenvalues 0 and -w), and beyond the 3-ring every new point of ring r >= 4 depends on old points of rings
<= r - 1 only, so larger rings add only the eigenvalue 0.

Examples
--------
>>> r = butterfly_rules(ring=2)
>>> r.points, [str(t.weight) for t in r.rules[1]]
(('p10', 'p20', 'p11'), ['1/2', '1/2', '1/8', '1/8', '-1/16', '-1/16', '-1/16', '-1/16'])
>>> [str(t.weight) for t in modified_butterfly_rules(ring=2, n=3).rules[1][:2]]
['3/4', 'W/6 + 1/12 + 1/(6*W)']

References
----------
N. Dyn, J. A. Gregory, D. Levin, A butterfly subdivision scheme for surface interpolation with tension
control, ACM TOG 9 (1990); D. Zorin, P. Schröder, W. Sweldens, Interpolating subdivision for meshes with
arbitrary topology, SIGGRAPH 1996; D. Zorin, A method for analysis of C^1-continuity of subdivision
surfaces, SIAM J. Numer. Anal. 37 (2000); L. Kobbelt, sqrt(3)-subdivision, SIGGRAPH 2000 (the stencils and
the choice of alpha_n); OpenMesh's ``ModifiedButterFlyT.hh`` (cross-check of the n = 3, 4 weights).
"""

from __future__ import annotations

import sympy as sp

from ..result import AnalysisError
from .rules import ALL, C1, CENTRE, LocalRules, Term, W, _stencil_terms, _tri_home, _TRI_DIRS, n_sym

#: the butterfly's default tension (Dyn–Gregory–Levin 1990)
DEFAULT_TENSION = sp.Rational(1, 16)
#: rings of the butterfly's local matrix: 2 is the smallest closed set, 3 adds the outer block
BUTTERFLY_RINGS = (2, 3)


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
    half, w = sp.Rational(1, 2), sp.sympify(tension)
    return ([(half, p), (half, q), (2 * w, add(p, d(i + 1))), (2 * w, add(p, d(i - 1)))]
            + [(-w, add(p, d(i + 2))), (-w, add(q, d(i + 1))), (-w, add(p, d(i - 2))), (-w, add(q, d(i - 1)))])


def _lattice_rules(name: str, ring: int, centre_rule, overrides: dict, tension, source: str,
                   generic_from: int = 1) -> LocalRules:
    if ring not in BUTTERFLY_RINGS:
        raise AnalysisError(f"the butterfly schemes take --ring 2 or 3, not {ring}")
    sector = triangle_sector(ring)
    coords = {p: i for i, p in enumerate(sector)}
    rules = [centre_rule]
    for X, Y in sector:
        if (X, Y) in overrides:
            rules.append(overrides[(X, Y)])
        else:
            rules.append(_stencil_terms(butterfly_stencil(X, Y, tension), coords, _tri_home, centre_rule))
    return LocalRules(name, True, tuple(f"p{x}{y}" for x, y in sector), tuple(rules), "triangle, interpolating",
                      ring, source, coords=tuple(sector), generic_from=generic_from)


def butterfly_rules(ring: int = 3, tension: sp.Expr = DEFAULT_TENSION) -> LocalRules:
    """The original butterfly scheme at a vertex of valence n, on ``ring`` (2 or 3) rings."""
    w = sp.sympify(tension)
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
    w = sp.sympify(tension)
    edge = (Term(sp.Rational(3, 4), (CENTRE,)), Term(modified_butterfly_weights(n), (0, ALL)))
    src = ("Zorin, Schroeder, Sweldens 1996: 3/4 and s_j = (1/4 + cos(2 pi j/n) + cos(4 pi j/n)/2)/n (n >= 5; "
           f"n = 3: 5/12, -1/12, -1/12; n = 4: 3/8, 0, -1/8, 0); butterfly tension w = {w} elsewhere")
    return _lattice_rules("modified-butterfly", ring, (Term(sp.S.One, (CENTRE,)),), {(1, 0): edge}, w, src,
                          generic_from=5 if n is None else 1)


#: Kobbelt's alpha_n = (4 - 2 cos(2 pi/n))/9
SQRT3_ALPHA = (4 - 2 * C1) / 9


def sqrt3_rules(alpha: sp.Expr = SQRT3_ALPHA) -> LocalRules:
    """Two steps of Kobbelt's sqrt(3) scheme on the 1-ring (centre p, neighbours e_j), composed exactly:

    ``p'' = ((1 - a)^2 + a/3) p + (a/n)(5/3 - a) sum e_j`` and
    ``e_j'' = ((1 - a)/3 + 2/9) p + a/(3n) sum e_l + (e_(j-1) + 2 e_j + e_(j+1))/9`` (a = alpha_n),
    from ``p' = (1 - a) p + (a/n) sum e_j``, ``f_j = (p + e_j + e_(j+1))/3`` and ``e_j'' = (p' + f_(j-1) + f_j)/3``.

    >>> [str(t.weight) for t in sqrt3_rules(sp.Rational(1, 3)).rules[1]]
    ['4/9', '1/(9*n)', '1/9', '2/9', '1/9']
    """
    a = sp.sympify(alpha)
    third, ninth = sp.Rational(1, 3), sp.Rational(1, 9)
    centre = (Term(sp.expand((1 - a) ** 2 + a / 3), (CENTRE,)), Term(sp.expand(a / n_sym * (1 - a + 2 * third)), (0, ALL)))
    ring = (Term(sp.expand((1 - a) / 3 + 2 * ninth), (CENTRE,)), Term(sp.expand(a / (3 * n_sym)), (0, ALL)),
            Term(ninth, (0, -1)), Term(2 * ninth, (0, 0)), Term(ninth, (0, 1)))
    src = ("Kobbelt 2000: sqrt(3), alpha_n = (4 - 2 cos(2 pi/n))/9; two steps (the refinement turns the ring by "
           "pi/n per step), 1-ring")
    return LocalRules("sqrt3", True, ("e",), (centre, ring), "sqrt3", 1, src)
