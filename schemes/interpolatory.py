"""Schemes from local polynomial interpolation: Dubuc–Deslauriers (primal) and dual 2n-point.

* **Dubuc–Deslauriers 2n-point** (``dd-4``, ``dd-6``, ``dd-8``): interpolatory,
  ``f[2i] = f[i]``, and ``f[2i+1] = p(i + 1/2)`` for the polynomial ``p`` of degree ``2n-1``
  through ``f[i-n+1], ..., f[i+n]``. The 4-point one is the Dyn–Levin–Gregory scheme
  (``four-point``) at ``w = 1/16``.
* **Dual 2n-point** (:func:`dual_lagrange_symbol`): ``f[2i] = p(i + 1/4)``,
  ``f[2i+1] = p(i + 3/4)`` with the same ``p``. For 2n = 4 this is the cubic-reproducing dual
  4-point scheme of Dyn–Floater–Hormann, rules ``[-7, 105, 35, -5]/128`` and its mirror.

* **Arity m** (``ternary-dd-4``, ``quaternary-dd-4``; :func:`dubuc_deslauriers_symbol` with ``arity``):
  ``f[mi] = f[i]`` and ``f[mi+r]`` the value at ``i + r/m`` of the polynomial interpolating
  ``f[i-n/2+1..i+n/2]``; reproduces degree ``n - 1`` (Deslauriers–Dubuc 1989, any dilation).
* **Ternary 4-point** (``ternary-four-point``, tension ``mu``; :func:`ternary_four_point_symbol`,
  Hassan–Ivrissimitzis–Dodgson–Sabin 2002): equal to ``ternary-dd-4`` at ``mu = 1/27``.

The dual 4-point family of Dyn, Floater and Hormann (2005) is the catalogue's
``dfh-chaikin-perturbation`` (seed 003, rule (1)): Chaikin's rules plus ``omega`` times the
linear-annihilating perturbation ``-(7 Δ²f[i-1] + 5 Δ²f[i])``,
``Δ²f[j] = f[j] - 2f[j+1] + f[j+2]`` (and its mirror for the odd rule); ``omega = 1/128`` is
the cubic-reproducing dual 4-point scheme computed here. This module registers the alias
``dual-four-point`` for that entry rather than a duplicate (the same way ``four-point`` names
the DLG family whose default ``w = 1/16`` is
``dd-4``). The parametrisation by ``omega`` is seed 003's; we have not re-read the 2005 paper's
own letter for the parameter (see the test ``test_dual_four_point_family_is_chaikin_perturbation``).

Examples
--------
>>> from schemes import get
>>> get("dd-4").symbol
LaurentSymbol([-1/16, 0, 9/16, 1, 9/16, 0, -1/16], start=-3, domain=QQ)
>>> print(get("dd-6").stencils)
f[2i]   = 1 f[i]
f[2i+1] = 3/256 f[i-2] - 25/256 f[i-1] + 75/128 f[i] + 75/128 f[i+1] - 25/256 f[i+2] + 3/256 f[i+3]
>>> get("ternary-four-point").params
(mu,)
>>> get("dual-four-point").slug
'dfh-chaikin-perturbation'
>>> dual_lagrange_symbol(4) == get("dual-four-point").default_symbol()
True

Algorithm
---------
Lagrange weights ``w_p = prod_{q != p} (t - q)/(p - q)`` for the nodes ``p = -n+1, ..., n``,
evaluated at ``t = 1/2`` (primal) or ``t = 1/4, 3/4`` (dual) in exact rational arithmetic, then
:meth:`~analysis.algebra.symbol.LaurentSymbol.from_rules`. Nothing is typed in.

References
----------
S. Dubuc, *Interpolation through an iterative scheme*, J. Math. Anal. Appl. 114 (1986) 185-204.
G. Deslauriers, S. Dubuc, *Symmetric iterative interpolation processes*, Constr. Approx. 5 (1989)
49-68.
N. Dyn, M. S. Floater, K. Hormann, *A C^2 four-point subdivision scheme with fourth order
accuracy and its extensions*, in: Mathematical Methods for Curves and Surfaces: Tromsø 2004,
Nashboro Press (2005) 145-156.
N. Dyn, K. Hormann, M. A. Sabin, Z. Shen, *Polynomial reproduction by symmetric subdivision
schemes*, J. Approx. Theory 155 (2008) 28-42.
"""

from __future__ import annotations

import functools

import sympy as sp

from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol, Rules

from .catalogue import LazyEntries, SchemeEntry

#: Numbers of points of the catalogued Dubuc–Deslauriers schemes.
DD_POINTS = (4, 6, 8)


def lagrange_weights(n_points: int, t) -> tuple[sp.Rational, ...]:
    """Weights of ``f[i+p]``, ``p = -n+1..n`` (``n = n_points/2``), in ``p(i+t)`` for the
    interpolating polynomial of degree ``n_points - 1``.

    >>> lagrange_weights(4, sp.Rational(1, 2))
    (-1/16, 9/16, 9/16, -1/16)
    >>> lagrange_weights(4, sp.Rational(1, 4))
    (-7/128, 105/128, 35/128, -5/128)
    """
    if not isinstance(n_points, int) or n_points < 2 or n_points % 2:
        raise AnalysisError(f"{n_points!r} points: an even number >= 2 is needed")
    n = n_points // 2
    t = sp.Rational(t)
    nodes = range(-n + 1, n + 1)
    out = []
    for p in nodes:
        w = sp.Integer(1)
        for q in nodes:
            if q != p:
                w *= (t - q) / sp.Integer(p - q)
        out.append(w)
    return tuple(out)


def dubuc_deslauriers_rules(n_points: int) -> Rules:
    """The rules of the interpolatory Dubuc–Deslauriers ``n_points``-point scheme.

    >>> print(dubuc_deslauriers_rules(4))
    f[2i]   = 1 f[i]
    f[2i+1] = -1/16 f[i-1] + 9/16 f[i] + 9/16 f[i+1] - 1/16 f[i+2]
    """
    w = lagrange_weights(n_points, sp.Rational(1, 2))
    return Rules(even=(sp.Integer(1),), even_first=0, odd=w, odd_first=-(n_points // 2) + 1)


def dubuc_deslauriers_symbol(n_points: int, arity: int = 2) -> LaurentSymbol:
    """The symbol of the Dubuc–Deslauriers ``n_points``-point scheme of arity ``m`` (symmetric about 0):
    ``f_{mi} = f_i`` and ``f_{mi+r}`` the value at ``i + r/m`` of the polynomial interpolating
    ``f_{i-n/2+1..i+n/2}`` (``n`` even); reproduces degree ``n - 1``. For ``m = 2`` it is built from the
    printed rules (:func:`dubuc_deslauriers_rules`).

    >>> dubuc_deslauriers_symbol(2)          # 2 points: the linear B-spline
    LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
    >>> dubuc_deslauriers_symbol(4, 3).mask[:4]
    (-4/81, -5/81, 0, 10/27)
    """
    if arity != 2:
        m, half = arity, n_points // 2
        nodes = list(range(-half + 1, half + 1))
        entries = {0: sp.Integer(1)}
        for r in range(1, m):
            t = sp.Rational(r, m)
            for p in nodes:
                entries[r - m * p] = sp.prod([(t - q) / sp.Integer(p - q) for q in nodes if q != p])
        lo, hi = min(entries), max(entries)
        return LaurentSymbol.from_mask([entries.get(i, 0) for i in range(lo, hi + 1)], start=lo)
    r = dubuc_deslauriers_rules(n_points)
    return LaurentSymbol.from_rules(r.even, r.odd, even_first=r.even_first, odd_first=r.odd_first)


def dual_lagrange_rules(n_points: int) -> Rules:
    """The rules of the dual ``n_points``-point scheme: ``p(i+1/4)``, ``p(i+3/4)``.

    >>> print(dual_lagrange_rules(2))       # 2 points: Chaikin
    f[2i]   = 3/4 f[i] + 1/4 f[i+1]
    f[2i+1] = 1/4 f[i] + 3/4 f[i+1]
    """
    first = -(n_points // 2) + 1
    return Rules(even=lagrange_weights(n_points, sp.Rational(1, 4)), even_first=first,
                 odd=lagrange_weights(n_points, sp.Rational(3, 4)), odd_first=first)


def dual_lagrange_symbol(n_points: int) -> LaurentSymbol:
    """The symbol of the dual ``n_points``-point scheme (reproduces degree ``n_points - 1``).

    >>> dual_lagrange_symbol(4).mask
    (-5/128, -7/128, 35/128, 105/128, 105/128, 35/128, -7/128, -5/128)
    """
    r = dual_lagrange_rules(n_points)
    return LaurentSymbol.from_rules(r.even, r.odd, even_first=r.even_first, odd_first=r.odd_first)


def _dd_entry(n_points: int) -> SchemeEntry:
    aliases = (f"deslauriers-dubuc-{n_points}", f"dubuc-deslauriers-{n_points}")
    return SchemeEntry(
        slug=f"dd-{n_points}",
        title=f"Dubuc-Deslauriers interpolatory {n_points}-point scheme",
        symbol=dubuc_deslauriers_symbol(n_points),
        params=(),
        source=("S. Dubuc, J. Math. Anal. Appl. 114 (1986) 185-204; G. Deslauriers, S. Dubuc, "
                "Constr. Approx. 5 (1989) 49-68"),
        notes=(f"Odd rule = value at i+1/2 of the degree-{n_points - 1} polynomial through "
               f"f[i-{n_points // 2 - 1}..i+{n_points // 2}], computed by exact Lagrange "
               "interpolation; even rule f[2i] = f[i]. Reproduces polynomials of degree "
               f"{n_points - 1}."
               + (" Equal to 'four-point' at w = 1/16." if n_points == 4 else "")),
        stencils=dubuc_deslauriers_rules(n_points),
        aliases=aliases,
    )


MU = sp.Symbol("mu")


def ternary_four_point_symbol() -> LaurentSymbol:
    """Hassan–Ivrissimitzis–Dodgson–Sabin (2002): ``f_{3i} = f_i``,
    ``f_{3i+1} = a0 f_{i-1} + a1 f_i + a2 f_{i+1} + a3 f_{i+2}``, ``f_{3i+2}`` the mirror, with
    ``a0 = -1/18 - mu/6``, ``a1 = 13/18 + mu/2``, ``a2 = 7/18 - mu/2``, ``a3 = -1/18 + mu/6``.

    The coefficients were typed from memory; they could not be checked against the paper (only its
    first page and those of papers quoting it are in the stored corpora): see the catalogue entry's notes.

    >>> ternary_four_point_symbol().subs({MU: sp.Rational(1, 27)}) == dubuc_deslauriers_symbol(4, 3)
    True
    """
    r = sp.Rational
    a0, a1, a2, a3 = -r(1, 18) - MU / 6, r(13, 18) + MU / 2, r(7, 18) - MU / 2, -r(1, 18) + MU / 6
    return LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)


#: The Dubuc–Deslauriers entries dd-4, dd-6, dd-8, then those of arity 3 and 4, each built on first use.
ENTRIES = LazyEntries({
    **{f"dd-{n}": functools.partial(_dd_entry, n) for n in DD_POINTS},
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
              "(Dyn et al., 1987) to ternary'); both are checked in the tests. Internal "
              "checks: interpolatory, symmetric, sum rules for every mu, and at mu = 1/27 it equals the "
              "ternary Lagrange (Dubuc-Deslauriers) scheme. Default mu = 1/27 (cubic reproduction, computed)."),
    "ternary-dd-4": lambda: SchemeEntry(
        slug="ternary-dd-4", title="Ternary Dubuc-Deslauriers 4-point (reproduces cubics)",
        symbol=dubuc_deslauriers_symbol(4, 3), params=(), arity=3,
        source="Deslauriers & Dubuc, Constr. Approx. 5 (1989) 49-68; Lian, Appl. Appl. Math. 3 (2008) 18-29",
        notes="cubic Lagrange interpolation at i + 1/3, i + 2/3 from f_{i-1..i+2}; computed, not typed."),
    "quaternary-dd-4": lambda: SchemeEntry(
        slug="quaternary-dd-4", title="Quaternary Dubuc-Deslauriers 4-point (reproduces cubics)",
        symbol=dubuc_deslauriers_symbol(4, 4), params=(), arity=4,
        source="Deslauriers & Dubuc, Constr. Approx. 5 (1989) 49-68; Lian, Appl. Appl. Math. 3 (2008) 18-29",
        notes="cubic Lagrange interpolation at i + r/4 from f_{i-1..i+2}; computed, not typed."),
})

#: Extra names for entries defined elsewhere (registered by schemes.catalogue).
ALIASES = {"dual-four-point": "dfh-chaikin-perturbation"}
