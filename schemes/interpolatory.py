"""Schemes from local polynomial interpolation: Dubuc–Deslauriers (primal) and dual 2n-point.

* **Dubuc–Deslauriers 2n-point** (``dd-4``, ``dd-6``, ``dd-8``): interpolatory,
  ``f[2i] = f[i]``, and ``f[2i+1] = p(i + 1/2)`` for the polynomial ``p`` of degree ``2n-1``
  through ``f[i-n+1], ..., f[i+n]``. The 4-point one is the Dyn–Levin–Gregory scheme
  (``four-point``) at ``w = 1/16``.
* **Dual 2n-point** (:func:`dual_lagrange_symbol`): ``f[2i] = p(i + 1/4)``,
  ``f[2i+1] = p(i + 3/4)`` with the same ``p``. For 2n = 4 this is the cubic-reproducing dual
  4-point scheme of Dyn–Floater–Hormann, rules ``[-7, 105, 35, -5]/128`` and its mirror.

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

import sympy as sp

from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol, Rules

from .catalogue import SchemeEntry

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


def dubuc_deslauriers_symbol(n_points: int) -> LaurentSymbol:
    """The symbol of the Dubuc–Deslauriers ``n_points``-point scheme (symmetric about 0).

    >>> dubuc_deslauriers_symbol(2)          # 2 points: the linear B-spline
    LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
    """
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


#: The Dubuc–Deslauriers entries dd-4, dd-6, dd-8.
ENTRIES: tuple[SchemeEntry, ...] = tuple(_dd_entry(n) for n in DD_POINTS)

#: Extra names for entries defined elsewhere (registered by schemes.catalogue).
ALIASES = {"dual-four-point": "dfh-chaikin-perturbation"}
