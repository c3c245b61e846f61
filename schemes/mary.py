"""m-ary catalogue entries (issue 12): m-ary B-splines, ternary and quaternary interpolatory schemes.

Every entry carries its ``arity`` (``SchemeEntry.arity``); they are found by :func:`schemes.get` and
listed by ``schemes.names(mary=True)`` / ``schemes.entries(mary=True)`` (not by the default binary
listings, which reports and benchmarks iterate over). Convention: ``(S_a f)_i = sum_j a_{i-mj} f_j``.

Examples
--------
>>> import schemes
>>> e = schemes.get("ternary-bspline-2")
>>> e.arity, e.symbol
(3, LaurentSymbol([1/9, 1/3, 2/3, 7/9, 2/3, 1/3, 1/9], start=-3, domain=QQ))
>>> schemes.get("ternary-four-point").params
(mu,)

References
----------
M. F. Hassan, I. P. Ivrissimitzis, N. A. Dodgson, M. A. Sabin, *An interpolating 4-point C^2 ternary
stationary subdivision scheme*, Comput. Aided Geom. Design 19 (2002) 1-18.
G. Deslauriers, S. Dubuc, *Symmetric iterative interpolation processes*, Constr. Approx. 5 (1989) 49-68
(interpolation with any dilation factor).
J.-A. Lian, *On a-ary subdivision for curve design I. 4-point and 6-point interpolatory schemes*,
Appl. Appl. Math. 3 (2008) 18-29.
"""

from __future__ import annotations

import functools

import sympy as sp

from analysis.algebra.symbol import LaurentSymbol, Z

from .catalogue import LazyEntries, SchemeEntry

_ARITY_NAME = {3: "ternary", 4: "quaternary"}
_ORDINAL = {1: "linear", 2: "quadratic", 3: "cubic", 4: "quartic", 5: "quintic"}
MU = sp.Symbol("mu")


def mary_bspline_symbol(d: int, m: int) -> LaurentSymbol:
    """``q_m(z)^(d+1) / (m^d z^floor((d+1)(m-1)/2))``: the m-ary B-spline of degree ``d`` (the
    (d+1)-fold convolution of the box function, whose m-ary mask is ``q_m``), centred.

    >>> mary_bspline_symbol(1, 3)
    LaurentSymbol([1/3, 2/3, 1, 2/3, 1/3], start=-2, domain=QQ)
    """
    q = sum(Z ** i for i in range(m))
    return LaurentSymbol.from_expr(q ** (d + 1) / (m ** d * Z ** (((d + 1) * (m - 1)) // 2)))


def lagrange_mary_symbol(n_points: int, m: int) -> LaurentSymbol:
    """The m-ary Dubuc–Deslauriers scheme: ``f_{mi} = f_i`` and ``f_{mi+r}`` the value at ``i + r/m`` of
    the polynomial interpolating ``f_{i-n/2+1..i+n/2}`` (``n`` even); reproduces degree ``n - 1``.

    >>> lagrange_mary_symbol(4, 3).mask[:4]
    (-4/81, -5/81, 0, 10/27)
    """
    half = n_points // 2
    nodes = list(range(-half + 1, half + 1))
    entries = {0: sp.Integer(1)}
    for r in range(1, m):
        t = sp.Rational(r, m)
        for p in nodes:
            w = sp.prod([(t - q) / sp.Integer(p - q) for q in nodes if q != p])
            entries[r - m * p] = w          # f_{mi+r} = sum_p w_p f_{i+p}: coefficient a_{r - m p}
    lo, hi = min(entries), max(entries)
    return LaurentSymbol.from_mask([entries.get(i, 0) for i in range(lo, hi + 1)], start=lo)


def ternary_four_point_symbol() -> LaurentSymbol:
    """Hassan–Ivrissimitzis–Dodgson–Sabin (2002): ``f_{3i} = f_i``,
    ``f_{3i+1} = a0 f_{i-1} + a1 f_i + a2 f_{i+1} + a3 f_{i+2}``, ``f_{3i+2}`` the mirror, with
    ``a0 = -1/18 - mu/6``, ``a1 = 13/18 + mu/2``, ``a2 = 7/18 - mu/2``, ``a3 = -1/18 + mu/6``.

    The coefficients were typed from memory; they could not be checked against the paper (only its
    first page and those of papers quoting it are in the stored corpora): see the catalogue entry's notes.

    >>> ternary_four_point_symbol().subs({MU: sp.Rational(1, 27)}) == lagrange_mary_symbol(4, 3)
    True
    """
    r = sp.Rational
    a0, a1, a2, a3 = -r(1, 18) - MU / 6, r(13, 18) + MU / 2, r(7, 18) - MU / 2, -r(1, 18) + MU / 6
    return LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)


def _bspline_entry(d: int, m: int) -> SchemeEntry:
    name = _ARITY_NAME[m]
    return SchemeEntry(
        slug=f"{name}-bspline-{d}", title=f"{name.capitalize()} {_ORDINAL[d]} B-spline (degree {d})",
        symbol=mary_bspline_symbol(d, m), params=(), arity=m,
        source="de Boor, A Practical Guide to Splines (B-splines as convolutions of boxes); "
               "Hassan & Dodgson 2003 / Lian 2008 (m-ary B-spline refinement)",
        notes=f"a(z) = (1+...+z^{m - 1})^{d + 1} / ({m}^{d} z^{((d + 1) * (m - 1)) // 2}), computed, not typed.")


#: The m-ary entries by slug, each built on first use.
ENTRIES = LazyEntries({
    **{f"{_ARITY_NAME[m]}-bspline-{d}": functools.partial(_bspline_entry, d, m) for m in (3, 4) for d in range(1, 6)},
    "ternary-four-point": lambda: SchemeEntry(
        slug="ternary-four-point", title="Ternary interpolatory 4-point scheme with tension mu",
        symbol=ternary_four_point_symbol(), params=(MU,), arity=3,
        defaults={"mu": sp.Rational(1, 27)},
        source="Hassan, Ivrissimitzis, Dodgson, Sabin, Comput. Aided Geom. Design 19 (2002) 1-18 "
               "(mask NOT checked against the paper, see notes)",
        notes="a0..a3 as in ternary_four_point_symbol, typed from memory by the implementer. Transcription "
              "check attempted 2026-11-24 with the search corpora (pages/code/docs): the stored copies of the "
              "paper and of the papers quoting it (Beccari-Casciola-Romani, "
              "https://123dok.org/document/zlgj223o-an-interpolating-point-c.html; Mustafa-Khan 2009, "
              "https://studylib.net/doc/10817457/) hold only their first page, without the mask or the "
              "parameter ranges, so the coefficients are UNVERIFIED. The only published claims retrieved are "
              "the paper's title ('An interpolating 4-point C2 ternary stationary subdivision scheme') and "
              "Beccari et al.'s summary ('Hassan et al. (2002) showed that we can achieve higher smoothness and "
              "smaller support for the so-called interpolating 4-point stationary scheme, by going from binary "
              "(Dyn et al., 1987) to ternary'); both are checked in tests/test_mary.py. Internal "
              "checks: interpolatory, symmetric, sum rules for every mu, and at mu = 1/27 it equals the "
              "ternary Lagrange (Dubuc-Deslauriers) scheme. Default mu = 1/27 (cubic reproduction, computed)."),
    "ternary-dd-4": lambda: SchemeEntry(
        slug="ternary-dd-4", title="Ternary Dubuc-Deslauriers 4-point (reproduces cubics)",
        symbol=lagrange_mary_symbol(4, 3), params=(), arity=3,
        source="Deslauriers & Dubuc, Constr. Approx. 5 (1989) 49-68; Lian, Appl. Appl. Math. 3 (2008) 18-29",
        notes="cubic Lagrange interpolation at i + 1/3, i + 2/3 from f_{i-1..i+2}; computed, not typed."),
    "quaternary-dd-4": lambda: SchemeEntry(
        slug="quaternary-dd-4", title="Quaternary Dubuc-Deslauriers 4-point (reproduces cubics)",
        symbol=lagrange_mary_symbol(4, 4), params=(), arity=4,
        source="Deslauriers & Dubuc, Constr. Approx. 5 (1989) 49-68; Lian, Appl. Appl. Math. 3 (2008) 18-29",
        notes="cubic Lagrange interpolation at i + r/4 from f_{i-1..i+2}; computed, not typed."),
})
