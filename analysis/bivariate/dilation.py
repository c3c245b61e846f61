"""Dilation matrices of bivariate schemes: digits, dual points, isotropy.

A dilation is a 2 x 2 integer matrix ``M`` with ``|det M| >= 2`` whose eigenvalues lie outside the unit disc.
Its *digits* are representatives ``eps`` of the cosets ``Z^2 / M Z^2`` (``|det M|`` of them, ``0`` first); the
*dual points* are the representatives ``omega`` of ``M^{-T} Z^2 / Z^2``; the nontrivial ones carry the sum rules
(the symbol vanishes at ``z = exp(2 pi i omega)``, ``omega != 0``).

``M`` is *isotropic* when it is similar to a multiple of an orthogonal matrix (all eigenvalues of modulus
``rho(M) = sqrt(|det M|)`` and ``M`` diagonalisable); only then is the Hölder exponent
``-log_{rho(M)} rho(T|V_k)`` (Charina–Protasov 2019, Sect. 2).

Named dilations (lattice coordinates of the grid):

* ``dyadic``: ``2I`` — quad grids and the three-direction grid (midpoint refinement);
* ``quincunx``: ``[[1, 1], [1, -1]]`` — ``sqrt 2`` times a reflection composed with a rotation by 45 degrees;
* ``sqrt3``: ``[[2, -1], [1, 1]]`` — the three-direction grid with directions ``e1, e2, e1 + e2``
  (drawn as the unit vectors at 0, 120 and 60 degrees); ``M = I + R`` with ``R`` the rotation by 60 degrees,
  i.e. ``sqrt 3`` times a rotation by 30 degrees; the new points ``M^{-1} Z^2`` are the old points and the
  centroids ``(1/3, 2/3)``, ``(2/3, 1/3)`` of the triangles (Kobbelt's sqrt 3 refinement);
* ``triadic``: ``3I``.

Examples
--------
>>> d = Dilation.named("quincunx")
>>> d.det, d.digits, d.dual_points, d.isotropic
(-2, ((0, 0), (1, 0)), ((0, 0), (1/2, 1/2)), True)
>>> Dilation.named("sqrt3").dual_points
((0, 0), (1/3, 1/3), (2/3, 2/3))
>>> Dilation([[2, 0], [0, 3]]).isotropic
False
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from numbers import Integral
from typing import Sequence

from ..result import AnalysisError

__all__ = ["Dilation", "NAMED_DILATIONS", "parse_dilation"]

NAMED_DILATIONS = {
    "dyadic": ((2, 0), (0, 2)),
    "quincunx": ((1, 1), (1, -1)),
    "sqrt3": ((2, -1), (1, 1)),
    "triadic": ((3, 0), (0, 3)),
}
#: the largest |det M| accepted (the transition operators are |det M| matrices on the invariant support)
MAX_DET = 16
#: the largest |entry| of M
MAX_ENTRY = 16


class _Q(Fraction):
    def __repr__(self) -> str:                      # 1/2 rather than Fraction(1, 2) in tuples
        return str(self)


@dataclass(frozen=True)
class Dilation:
    """A 2 x 2 integer dilation matrix (rows), with its digits and dual points."""

    matrix: tuple[tuple[int, int], tuple[int, int]]

    def __init__(self, matrix: Sequence[Sequence[int]]):
        # integers only: int(2.5) would silently be 2 (a float, a Fraction or a string is refused, never rounded)
        try:
            ok = all(type(x) is int or (isinstance(x, Integral) and not isinstance(x, bool))
                     for r in matrix for x in r)
            rows = tuple(tuple(int(x) for x in r) for r in matrix) if ok else None
        except TypeError:
            rows = None
        if rows is None or len(rows) != 2 or any(len(r) != 2 for r in rows):
            given = repr(matrix)
            raise AnalysisError("a dilation matrix is 2 x 2 integers, e.g. [[1,1],[1,-1]]"
                                + (f", not {given}" if len(given) <= 60 else ""))
        if any(abs(x) > MAX_ENTRY for r in rows for x in r):
            raise AnalysisError(f"dilation entries are limited to |m_ij| <= {MAX_ENTRY}")
        object.__setattr__(self, "matrix", rows)
        (a, b), (c, d) = rows
        det = a * d - b * c
        if abs(det) < 2:
            raise AnalysisError(f"a dilation needs |det M| >= 2, not {det}")
        if abs(det) > MAX_DET:
            raise AnalysisError(f"|det M| is limited to {MAX_DET}, not {abs(det)}")
        tr = a + d
        # expanding: both eigenvalues of modulus > 1 (2x2: |det| > 1 and |tr| < 1 + det ... check via char poly)
        if not _expanding(tr, det):
            raise AnalysisError(f"the matrix {list(map(list, rows))} is not expanding (an eigenvalue has modulus <= 1)")

    @classmethod
    def named(cls, name: str) -> "Dilation":
        if name not in NAMED_DILATIONS:
            raise AnalysisError(f"unknown dilation {name!r}; known: {', '.join(NAMED_DILATIONS)} or a matrix a,b;c,d")
        return cls(NAMED_DILATIONS[name])

    # -- basic data ------------------------------------------------------------------------------
    @property
    def det(self) -> int:
        (a, b), (c, d) = self.matrix
        return a * d - b * c

    @property
    def m(self) -> int:
        """``|det M|``, the number of digits."""
        return abs(self.det)

    def apply(self, v: Sequence[int]) -> tuple[int, int]:
        (a, b), (c, d) = self.matrix
        return (a * v[0] + b * v[1], c * v[0] + d * v[1])

    def solve(self, v: Sequence) -> tuple[Fraction, Fraction]:
        """``M^{-1} v`` exactly."""
        (a, b), (c, d) = self.matrix
        D = Fraction(self.det)
        return ((d * v[0] - b * v[1]) / D, (-c * v[0] + a * v[1]) / D)

    def coset(self, v: Sequence[int]) -> tuple[Fraction, Fraction]:
        """The class of ``v`` in ``Z^2 / M Z^2`` as ``M^{-1} v mod 1``."""
        x, y = self.solve(v)
        return (x - (x.numerator // x.denominator), y - (y.numerator // y.denominator))

    @property
    def digits(self) -> tuple[tuple[int, int], ...]:
        """Coset representatives of ``Z^2 / M Z^2``: the first integer points met in the order
        ``max(|x|, |y|)``, then nonnegative before negative, then lexicographic (``0`` first)."""
        r = self.m
        pts = [(x, y) for x in range(-r, r + 1) for y in range(-r, r + 1)]
        pts.sort(key=lambda p: (max(abs(p[0]), abs(p[1])), p[0] < 0 or p[1] < 0, p[1], p[0]))
        seen, out = set(), []
        for p in pts:
            c = self.coset(p)
            if c not in seen:
                seen.add(c)
                out.append(p)
        assert len(out) == r
        return tuple(out)

    @property
    def dual_points(self) -> tuple[tuple[_Q, _Q], ...]:
        """Representatives in ``[0, 1)^2`` of ``M^{-T} Z^2 / Z^2`` (``(0, 0)`` first)."""
        (a, b), (c, d) = self.matrix
        MT = Dilation(((a, c), (b, d)))
        out = sorted({MT.coset(p) for p in MT.digits}, key=lambda w: (w != (0, 0), w[0] + w[1], w))
        return tuple((_Q(w[0]), _Q(w[1])) for w in out)

    # -- isotropy --------------------------------------------------------------------------------
    @property
    def isotropic(self) -> bool:
        """Similar to a multiple of an orthogonal matrix: complex eigenvalues (a scaled rotation),
        ``M = lambda I``, or real eigenvalues ``+-lambda`` (trace 0)."""
        (a, b), (c, d) = self.matrix
        tr, det = a + d, self.det
        disc = tr * tr - 4 * det
        if disc < 0:
            return True
        if disc == 0:
            return b == 0 and c == 0 and a == d
        return tr == 0

    def __repr__(self) -> str:
        for name, mat in NAMED_DILATIONS.items():
            if mat == self.matrix:
                return f"Dilation({name})"
        return f"Dilation({[list(r) for r in self.matrix]})"


def _expanding(tr: int, det: int) -> bool:
    # eigenvalues of x^2 - tr x + det; both of modulus > 1
    disc = tr * tr - 4 * det
    if disc < 0:
        return det > 1                      # |lambda|^2 = det
    import math

    s = math.isqrt(disc) if disc >= 0 else 0
    if s * s == disc:
        l1, l2 = Fraction(tr + s, 2), Fraction(tr - s, 2)
        return abs(l1) > 1 and abs(l2) > 1
    # irrational real roots: |roots| > 1 iff p(1) and p(-1) have the sign that puts no root in [-1, 1]
    p1, pm1 = 1 - tr + det, 1 + tr + det
    # the roots lie outside [-1, 1] iff neither (-1, 1) contains a root: p(1), p(-1) > 0 and the
    # vertex outside, or p(1) < 0 and p(-1) < 0 (roots on both sides) -- enumerate the cases
    if p1 < 0 and pm1 < 0:
        return True
    if p1 > 0 and pm1 > 0:
        return abs(Fraction(tr, 2)) > 1
    return False


def parse_dilation(text: str | None) -> Dilation:
    """A dilation from a name (``dyadic``, ``quincunx``, ``sqrt3``, ``triadic``) or ``a,b;c,d`` (rows).

    >>> parse_dilation("1,1;1,-1") == Dilation.named("quincunx")
    True
    >>> parse_dilation(None)
    Dilation(dyadic)
    """
    if text is None or text == "":
        return Dilation.named("dyadic")
    t = text.strip()
    if t in NAMED_DILATIONS:
        return Dilation.named(t)
    if len(t) > 80:
        raise AnalysisError("a dilation is a name or 'a,b;c,d' (rows)")
    rows = [r for r in t.replace("[[", "").replace("]]", "").replace("],[", ";").split(";")]
    try:
        vals = [[int(x) for x in r.split(",")] for r in rows]
    except ValueError:
        raise AnalysisError(f"cannot read the dilation {text!r}: type a name ({', '.join(NAMED_DILATIONS)}) "
                            "or the rows 'a,b;c,d', e.g. 1,1;1,-1") from None
    return Dilation(vals)
