"""The catalogue of bivariate schemes on regular grids (the regular parts of surface schemes), with sources.

Convention (:mod:`analysis.bivariate`): ``(S_a f)(alpha) = sum_beta a(alpha - M beta) f(beta)``; the
three-direction grid in the lattice coordinates with edge directions ``e1, e2, e1 + e2``. Every entry is built
from its definition, nothing typed in as a table: box splines from their direction multisets (symbol
``|det M| prod_xi (1 + z^xi)/2``), tensor products from the univariate catalogue, and the schemes defined by
stencils (butterfly, sqrt 3) from the stencils as printed, by :func:`from_stencils`.

``claims`` are the properties the sources state (sum-rule order, reproduction degree, ``C^l``, exact Hölder
exponent); ``tests/test_surfaces.py`` checks each against the computation (the transcription first: sum
rules, symmetry and reproduction; then the smoothness).

Examples
--------
>>> e = get("loop")
>>> e.title, e.mask().dilation
("Loop's scheme, regular part (three-direction box spline B_222)", Dilation(dyadic))
>>> sorted(names())[:3]
['bicubic', 'biquadratic', 'box-111']
>>> get("butterfly").mask(w="1/16")[(1, 2)]
1/8
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from analysis.result import AnalysisError

__all__ = ["SurfaceEntry", "get", "names", "entries", "box_spline_mask", "from_stencils", "tensor_mask"]


@dataclass(frozen=True)
class SurfaceEntry:
    """A named bivariate scheme: a builder of its :class:`~analysis.bivariate.mask.BivariateMask`, its
    source, defaults for its parameters and the properties its source states (``claims``)."""

    slug: str
    title: str
    build: Callable[[], Any]
    source: str
    notes: str = ""
    defaults: Mapping[str, str] = field(default_factory=dict)
    claims: Mapping[str, Any] = field(default_factory=dict)
    aliases: tuple[str, ...] = ()
    dilation_name: str = "dyadic"
    #: the grid whose lattice coordinates the mask uses (``quad`` or ``triangular``, for drawing)
    grid: str = "quad"

    def mask(self, values: Mapping[str, Any] | None = None, **kw: Any):
        """The mask, with the parameters given (or the defaults) substituted; ``general=True`` keeps them."""
        general = kw.pop("general", False)
        a = self.build()
        if general:
            return a
        vals = {**self.defaults, **dict(values or {}), **kw}
        return a.at(vals) if vals else a


# --------------------------------------------------------------------------------------------
# builders
# --------------------------------------------------------------------------------------------

def box_spline_mask(directions, dilation="dyadic", name=""):
    """The mask ``|det M| prod_xi (1 + z^xi)/2`` of the box spline with the direction multiset ``directions``
    (refinable with ``M = 2I``; with another ``M`` it is the product's mask, not a box spline).

    >>> a = box_spline_mask([(1, 0), (0, 1), (1, 1)])
    >>> a.total, a.support_box
    (4, ((-1, -1), (1, 1)))
    """
    import sympy as sp

    from analysis.bivariate.mask import Z1, Z2, BivariateMask

    expr = sp.Integer(1)
    for (p, q) in directions:
        expr = expr * (1 + Z1 ** p * Z2 ** q) / 2
    # centred: shifted by floor(sum(xi)/2), the centre of the support (primal when sum(xi) is even)
    cx, cy = sum(p for p, _ in directions) // 2, sum(q for _, q in directions) // 2
    expr = expr / (Z1 ** cx * Z2 ** cy)
    a = BivariateMask.from_symbol(expr, dilation)
    return BivariateMask.from_symbol(a.dilation.m * expr, dilation, name=name)


def tensor_mask(u, v, name=""):
    """The tensor product ``a(z1, z2) = u(z1) v(z2)`` of two binary univariate symbols
    (:class:`~analysis.algebra.symbol.LaurentSymbol`), dilation ``2I``."""
    from analysis.bivariate.mask import BivariateMask

    coeffs = {}
    for i, x in enumerate(u.mask):
        for j, y in enumerate(v.mask):
            coeffs[(u.start + i, v.start + j)] = x * y
    return BivariateMask(coeffs, name=name)


def from_stencils(rules: Mapping[tuple[int, int], Mapping[tuple[int, int], Any]], dilation="dyadic", name=""):
    """The mask of a scheme given by its stencils: ``rules[alpha] = {beta: weight}`` says
    ``(S f)(alpha) = sum_beta weight f(beta)``, i.e. ``a(alpha - M beta) = weight``. Every coset of
    ``Z^2 / M Z^2`` must be given, and two stencils of one coset must agree.

    >>> from_stencils({(0, 0): {(0, 0): 1}, (1, 0): {(0, 0): "1/2", (1, 0): "1/2"}},
    ...               dilation="quincunx").symbol
    z1/2 + 1 + 1/(2*z2)
    """
    import sympy as sp

    from analysis.algebra.reader import as_expr
    from analysis.bivariate.mask import BivariateMask, _dilation

    D = _dilation(dilation)
    coeffs: dict[tuple[int, int], Any] = {}
    seen = set()
    for alpha, st in rules.items():
        seen.add(D.coset(alpha))
        for beta, w in st.items():
            Mb = D.apply(beta)
            g = (alpha[0] - Mb[0], alpha[1] - Mb[1])
            w = as_expr(w)
            if g in coeffs and sp.expand(coeffs[g] - w) != 0:
                raise AnalysisError(f"the stencils disagree on a{g}: {coeffs[g]} and {w}")
            coeffs[g] = w
    if len(seen) != D.m:
        raise AnalysisError(f"the stencils cover {len(seen)} of the {D.m} cosets of Z^2 / M Z^2")
    return BivariateMask(coeffs, D, name=name)


#: the rotation by 60 degrees of the three-direction grid (e1 -> e1 + e2 -> e2 -> -e1)
_R60 = ((1, -1), (1, 0))


def _rot(v, k):
    for _ in range(k):
        v = (_R60[0][0] * v[0] + _R60[0][1] * v[1], _R60[1][0] * v[0] + _R60[1][1] * v[1])
    return v


def _hexagonal_rules(vertex: Mapping, edge: Mapping | None = None, *, alpha0=(1, 0), rotations=(0, 1, 2)):
    rules = {(0, 0): dict(vertex)}
    if edge is not None:
        for k in rotations:
            rules[_rot(alpha0, k)] = {_rot(b, k): w for b, w in edge.items()}
    return rules


def _butterfly():
    import sympy as sp

    w = sp.Symbol("w")
    # the edge (0,0)-(1,0) of the coarse grid, new point at its midpoint (fine index (1, 0)): 1/2 at the two ends,
    # 2w at the opposite vertices (1,1), (0,-1) of the two triangles, -w at the four wing vertices
    edge = {(0, 0): sp.Rational(1, 2), (1, 0): sp.Rational(1, 2), (1, 1): 2 * w, (0, -1): 2 * w,
            (0, 1): -w, (2, 1): -w, (-1, -1): -w, (1, -1): -w}
    return from_stencils(_hexagonal_rules({(0, 0): 1}, edge), name="butterfly")


def _sqrt3():
    import sympy as sp

    # old vertex: (1 - alpha_6) p + alpha_6/6 * (its 6 neighbours), alpha_6 = (4 - 2 cos(2 pi/6))/9 = 1/3;
    # new vertex at the centroid of a triangle: 1/3 of each corner. Fine indices: M beta for the old
    # vertex beta, M (2/3, 1/3) = (1, 1) and M (1/3, 2/3) = (0, 1) for the two triangles at the origin.
    third, a6 = sp.Rational(1, 3), sp.Rational(1, 3)
    nbrs = [(1, 0), (1, 1), (0, 1), (-1, 0), (-1, -1), (0, -1)]
    vertex = {(0, 0): 1 - a6, **{n: a6 / 6 for n in nbrs}}
    rules = {(0, 0): vertex,
             (1, 1): {(0, 0): third, (1, 0): third, (1, 1): third},
             (0, 1): {(0, 0): third, (1, 1): third, (0, 1): third}}
    return from_stencils(rules, dilation="sqrt3", name="sqrt3")


def _uni(slug):
    import schemes

    return schemes.get(slug)


def _tensor(slug, w=None):
    def build():
        e = _uni(slug)
        s = e.symbol
        return tensor_mask(s, s, name=slug)
    return build


_E1, _E2, _E3, _E4 = (1, 0), (0, 1), (1, 1), (1, -1)

_ENTRIES = (
    SurfaceEntry("box-111", "Courant element (three-direction box spline B_111, piecewise linear)",
                 lambda: box_spline_mask([_E1, _E2, _E3], name="box-111"),
                 "C. de Boor, K. Höllig, S. Riemenschneider, Box splines, Springer (1993), Ch. I",
                 claims={"sum_rules": 2, "reproduction": 1, "alpha": 1, "C": 0}, aliases=("courant",),
                 grid="triangular"),
    SurfaceEntry("loop", "Loop's scheme, regular part (three-direction box spline B_222)",
                 lambda: box_spline_mask([_E1, _E2, _E3] * 2, name="loop"),
                 "C. Loop, Smooth subdivision surfaces based on triangles, MS thesis, Univ. of Utah (1987); "
                 "de Boor-Höllig-Riemenschneider (1993)",
                 claims={"sum_rules": 4, "reproduction": 1, "alpha": 3, "C": 2}, aliases=("box-222",),
                 grid="triangular"),
    SurfaceEntry("box-333", "Three-direction box spline B_333",
                 lambda: box_spline_mask([_E1, _E2, _E3] * 3, name="box-333"),
                 "de Boor-Höllig-Riemenschneider (1993): C^{m(Xi)-2}, m(Xi) = 6",
                 claims={"sum_rules": 6, "alpha": 5, "C": 4}, grid="triangular"),
    SurfaceEntry("zwart-powell", "Zwart-Powell element (four-direction box spline B_1111)",
                 lambda: box_spline_mask([_E1, _E2, _E3, _E4], name="zwart-powell"),
                 "P. B. Zwart, Multivariate splines with nondegenerate partitions, SIAM J. Numer. Anal. 10 (1973); "
                 "de Boor-Höllig-Riemenschneider (1993)",
                 notes="m(Xi) = 3 but the shifts are linearly dependent: the mask has sum rules of order 2 only",
                 claims={"sum_rules": 2, "alpha": 2, "C": 1}),
    SurfaceEntry("biquadratic", "Biquadratic tensor B-spline (Doo-Sabin regular part)", _tensor("bspline-2"),
                 "D. Doo, M. Sabin, Behaviour of recursive division surfaces near extraordinary points, "
                 "Computer-Aided Design 10 (1978) 356-360",
                 claims={"sum_rules": 3, "reproduction": 1, "alpha": 2, "C": 1}, aliases=("doo-sabin",)),
    SurfaceEntry("bicubic", "Bicubic tensor B-spline (Catmull-Clark regular part)", _tensor("bspline-3"),
                 "E. Catmull, J. Clark, Recursively generated B-spline surfaces on arbitrary topological meshes, "
                 "Computer-Aided Design 10 (1978) 350-355",
                 claims={"sum_rules": 4, "reproduction": 1, "alpha": 3, "C": 2}, aliases=("catmull-clark",)),
    SurfaceEntry("butterfly", "Butterfly scheme (interpolatory, three-direction grid)", _butterfly,
                 "N. Dyn, J. A. Gregory, D. Levin, A butterfly subdivision scheme for surface interpolatory with "
                 "tension control, ACM Trans. Graph. 9 (1990) 160-169; alpha(1/16) = 2: N. Guglielmi, V. Protasov, "
                 "Invariant polytopes of linear operators with applications to regularity of wavelets and of "
                 "subdivisions, SIAM J. Matrix Anal. Appl. 37 (2016) 18-52",
                 defaults={"w": "1/16"}, claims={"sum_rules": 4, "reproduction": 3, "alpha": 2, "C": 1},
                 grid="triangular"),
    SurfaceEntry("kobbelt-quad", "Kobbelt's interpolatory quad scheme, regular part (tensor 4-point)",
                 _tensor("four-point"),
                 "L. Kobbelt, Interpolatory subdivision on open quadrilateral nets with arbitrary topology, "
                 "Comput. Graph. Forum 15 (1996) 409-420 (Eurographics '96)",
                 defaults={"w": "1/16"}, claims={"sum_rules": 4, "reproduction": 3, "alpha": 2, "C": 1}),
    SurfaceEntry("sqrt3", "Kobbelt's sqrt 3 scheme, regular part", _sqrt3,
                 "L. Kobbelt, sqrt(3)-subdivision, Proc. SIGGRAPH 2000, 103-112",
                 notes="dilation sqrt3 = [[2,-1],[1,1]] in the three-direction coordinates; alpha_6 = 1/3",
                 claims={"sum_rules": 3, "C": 2}, dilation_name="sqrt3", grid="triangular"),
    SurfaceEntry("quincunx-zp", "Quincunx scheme (1+z1)(1+z2)/2 (two steps: the Zwart-Powell element)",
                 lambda: box_spline_mask([_E1, _E2], dilation="quincunx", name="quincunx-zp"),
                 "two quincunx steps give the symbol a(z) a(z^M) of the Zwart-Powell mask with M = 2I (checked "
                 "exactly in the tests); L. Velho, D. Zorin, 4-8 subdivision, CAGD 18 (2001) 397-427 (quincunx "
                 "refinement of box splines)",
                 claims={"sum_rules": 2, "alpha": 2, "C": 1}, dilation_name="quincunx"),
)

_BY_NAME = {e.slug: e for e in _ENTRIES}
_ALIASES = {al: e.slug for e in _ENTRIES for al in e.aliases}


def names() -> list[str]:
    return [e.slug for e in _ENTRIES]


def entries() -> tuple[SurfaceEntry, ...]:
    return _ENTRIES


def get(name: str) -> SurfaceEntry:
    """The entry named ``name`` (slug or alias); an error with suggestions otherwise."""
    slug = _ALIASES.get(name, name)
    if slug in _BY_NAME:
        return _BY_NAME[slug]
    close = difflib.get_close_matches(name, list(_BY_NAME) + list(_ALIASES), n=3)
    hint = f"; did you mean: {', '.join(close)}?" if close else f"; known: {', '.join(names())}"
    raise AnalysisError(f"unknown surface scheme {name!r}{hint}")
