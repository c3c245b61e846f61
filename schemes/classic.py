"""Classic schemes: B-splines of degree 1..7 (binary) and 1..5 (ternary, quaternary), Chaikin, the
Dyn–Levin–Gregory 4-point scheme.

Examples
--------
>>> from schemes import get
>>> get("bspline-2").symbol                 # centred: z^(-1) (1+z)^3 / 4
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-1, domain=QQ)
>>> get("chaikin").symbol                   # the classical rules' indexing: one step to the left
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
>>> e = get("ternary-bspline-2")                 # the m-ary B-spline: (1+z+...+z^(m-1))^(d+1) / m^d, centred
>>> e.arity, e.symbol
(3, LaurentSymbol([1/9, 1/3, 2/3, 7/9, 2/3, 1/3, 1/9], start=-3, domain=QQ))
>>> print(get("four-point").stencils)
f[2i]   = 1 f[i]
f[2i+1] = -w f[i-1] + (w + 1/2) f[i] + (w + 1/2) f[i+1] - w f[i+2]

References
----------
C. de Boor, *A Practical Guide to Splines*, Springer 1978 (rev. 2001).
J. M. Lane, R. F. Riesenfeld, *A theoretical development for the computer generation and display
of piecewise polynomial surfaces*, IEEE TPAMI 2 (1980) 35-46.
G. M. Chaikin, *An algorithm for high-speed curve generation*, Computer Graphics and Image
Processing 3 (1974) 346-349.
N. Dyn, D. Levin, J. A. Gregory, *A 4-point interpolatory subdivision scheme for curve design*,
Computer Aided Geometric Design 4 (1987) 257-268.
"""

from __future__ import annotations

import functools

import sympy as sp

from analysis.algebra.symbol import LaurentSymbol, Rules, Z

from .catalogue import LazyEntries, SchemeEntry

#: Degrees of the catalogued B-spline schemes.
BSPLINE_DEGREES = range(1, 8)

_ORDINAL = {1: "linear", 2: "quadratic", 3: "cubic", 4: "quartic", 5: "quintic", 6: "sextic",
            7: "septic"}


def bspline_symbol(d: int, arity: int = 2) -> LaurentSymbol:
    """The centred degree-``d`` B-spline symbol of arity ``m``: ``q_m(z)^(d+1) / (m^d z^floor((d+1)(m-1)/2))``,
    ``q_m = 1 + z + ... + z^(m-1)`` (the (d+1)-fold convolution of the box function, whose m-ary mask is
    ``q_m``); ``(1+z)^(d+1) / (2^d z^floor((d+1)/2))`` for ``m = 2``.

    >>> bspline_symbol(1)
    LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
    >>> bspline_symbol(1, 3)
    LaurentSymbol([1/3, 2/3, 1, 2/3, 1/3], start=-2, domain=QQ)
    """
    if d < 0:
        raise ValueError("the degree of a B-spline is non-negative")
    m = arity
    q = sum(Z ** i for i in range(m))
    return LaurentSymbol.from_expr(q ** (d + 1) / (m ** d * Z ** (((d + 1) * (m - 1)) // 2)))


def _bspline_entry(d: int) -> SchemeEntry:
    aliases = {1: ("linear-bspline",), 3: ("cubic-bspline",)}.get(d, ())
    return SchemeEntry(
        slug=f"bspline-{d}",
        title=f"{_ORDINAL[d].capitalize()} B-spline (degree {d})",
        symbol=bspline_symbol(d),
        params=(),
        source=("Lane & Riesenfeld, IEEE TPAMI 2 (1980) 35-46; "
                "de Boor, A Practical Guide to Splines"),
        notes=(f"a(z) = (1+z)^{d + 1} / (2^{d} z^{(d + 1) // 2}), computed, not typed. "
               + ("Even degree: the mask has odd length and the centring puts the symmetry centre "
                  "at c = start+end = 1; schemes indexed like the paper rules "
                  "f[2i] = ... f[i] + ... "
                  "f[i+1] (e.g. 'chaikin') are this symbol times z^-1."
                  if d % 2 == 0 else "Odd degree: symmetric about 0 (a_i = a_-i).")),
        aliases=aliases,
    )


_ARITY_NAME = {3: "ternary", 4: "quaternary"}


def _bspline_entry_of_arity(d: int, m: int) -> SchemeEntry:
    name = _ARITY_NAME[m]
    return SchemeEntry(
        slug=f"{name}-bspline-{d}", title=f"{name.capitalize()} {_ORDINAL[d]} B-spline (degree {d})",
        symbol=bspline_symbol(d, m), params=(), arity=m,
        source="de Boor, A Practical Guide to Splines (B-splines as convolutions of boxes); "
               "Hassan & Dodgson 2003 / Lian 2008 (m-ary B-spline refinement)",
        notes=f"a(z) = (1+...+z^{m - 1})^{d + 1} / ({m}^{d} z^{((d + 1) * (m - 1)) // 2}), computed, not typed.")


_W = sp.Symbol("w")
_HALF = sp.Rational(1, 2)
_FOUR_POINT_RULES = Rules(even=(sp.Integer(1),), even_first=0,
                          odd=(-_W, _HALF + _W, _HALF + _W, -_W), odd_first=-1)

#: The classic entries by slug, in catalogue order, each built on first use.
ENTRIES = LazyEntries({
    **{f"bspline-{d}": functools.partial(_bspline_entry, d) for d in BSPLINE_DEGREES},
    "chaikin": lambda: SchemeEntry(
        slug="chaikin",
        title="Chaikin's corner cutting",
        symbol=LaurentSymbol.from_mask([sp.Rational(1, 4), sp.Rational(3, 4), sp.Rational(3, 4),
                                        sp.Rational(1, 4)], start=-2),
        params=(),
        source="G. M. Chaikin, Computer Graphics and Image Processing 3 (1974) 346-349",
        notes=("Rules f[2i] = 3/4 f[i] + 1/4 f[i+1], f[2i+1] = 1/4 f[i] + 3/4 f[i+1] (start -2). "
               "The same scheme as 'bspline-2' up to the index shift z^-1 "
               "(the B-spline entries are "
               "centred with z^floor((d+1)/2)); this indexing is the one of seed 003 rule (1) "
               "at omega = 0."),
        stencils=Rules(even=(sp.Rational(3, 4), sp.Rational(1, 4)), even_first=0,
                       odd=(sp.Rational(1, 4), sp.Rational(3, 4)), odd_first=0),
    ),
    "four-point": lambda: SchemeEntry(
        slug="four-point",
        title="Dyn-Levin-Gregory interpolatory 4-point scheme",
        symbol=LaurentSymbol.from_rules(_FOUR_POINT_RULES.even, _FOUR_POINT_RULES.odd,
                                        even_first=0, odd_first=-1),
        params=(_W,),
        source=("N. Dyn, D. Levin, J. A. Gregory, A 4-point interpolatory subdivision scheme for "
                "curve design, Computer Aided Geometric Design 4 (1987) 257-268"),
        notes=("Tension w; w = 1/16 reproduces cubics (the Deslauriers-Dubuc scheme); "
               "w = 0 is the linear B-spline."),
        defaults={"w": sp.Rational(1, 16)},
        stencils=_FOUR_POINT_RULES,
    ),
    **{f"{_ARITY_NAME[m]}-bspline-{d}": functools.partial(_bspline_entry_of_arity, d, m)
       for m in (3, 4) for d in range(1, 6)},
})
