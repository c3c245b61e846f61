"""Constructions of new schemes from old ones; each returns a :class:`LaurentSymbol`.

* :func:`displacement_symbol` — seed 004's "translate Q by displacement vectors Q - R"
  construction (:func:`analysis.algebra.linear_forms.displacement_construction`), as a symbol;
* :func:`convex_combination` — ``(1 - w) a + w b``;
* :func:`averaging` — ``s`` Lane–Riesenfeld averaging steps ``a(z) ((1+z)/2)^s``, re-centred;
* :func:`dual` — one averaging step (primal <-> dual symmetric);
* :func:`pseudo_spline` — the binary pseudo-spline of type ``(m, l)`` (Dong–Shen).

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> hat = LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)
>>> averaging(hat, 1)                          # Chaikin
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
>>> pseudo_spline(2, 1).mask                   # Dubuc–Deslauriers 4-point
(-1/16, 0, 9/16, 1, 9/16, 0, -1/16)

Algorithm
---------
Exact Laurent-polynomial arithmetic. Averaging multiplies by ``(1+z)/2`` per step and shifts by
``z^(-ceil(c + s/2))`` (``c`` the centre of the support) so that the centre stays at ``0`` (primal)
or ``-1/2`` (dual), the workbench's convention. The pseudo-spline symbol is Dong–Shen's
``2 cos^{2m}(x/2) sum_{j=0}^{l} binom(m+l, j) sin^{2j}(x/2) cos^{2(l-j)}(x/2)`` with
``cos^2(x/2) = (2 + z + 1/z)/4`` and ``sin^2(x/2) = (2 - z - 1/z)/4``.

References
----------
J. M. Lane, R. F. Riesenfeld, *A theoretical development for the computer generation and display
of piecewise polynomial surfaces*, IEEE TPAMI 2 (1980) 35-46.
B. Dong, Z. Shen, *Pseudo-splines, wavelets and framelets*, Appl. Comput. Harmon. Anal. 22 (2007)
78-104.
Seed paper 004 (2023), Sect. 3 (the displacement construction).
"""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from ..result import AnalysisError
from .linear_forms import LinearForm, displacement_construction
from .symbol import Z, LaurentSymbol, parse_coefficient

__all__ = ["displacement_symbol", "convex_combination", "averaging", "dual", "pseudo_spline"]


def _rule_stencil(form: LinearForm) -> tuple[list, int]:
    offs = form.offsets()
    if not offs:
        return [0], 0
    return list(form.coefficients()), offs[0]


def displacement_symbol(Q_even: LinearForm, Q_odd: LinearForm, R_even: LinearForm, R_odd: LinearForm,
                        weights_even: Mapping[int, object], weights_odd: Mapping[int, object]) -> LaurentSymbol:
    """The symbol of ``P_{2i} = Q_{2i} - sum_s w_s D_{2i+2s}``, ``P_{2i+1} = Q_{2i+1} - sum_s w'_s D_{2i+1+2s}``.

    Seed 004's construction (Steps 1-4) as one call; the rules are read as ``f[2i] = sum_p c_p f[i+p]``.

    >>> h = sp.Rational(1, 2)
    >>> displacement_symbol(LinearForm({0: 1}), LinearForm({0: h, 1: h}),
    ...                     LinearForm({0: h, 1: h}), LinearForm({0: 1}), {0: 1}, {0: 0})
    LaurentSymbol([1/2, 1/2, 1/2, 1/2], start=-2, domain=QQ)
    """
    out = displacement_construction(Q_even, Q_odd, R_even, R_odd, weights_even, weights_odd)
    even, ef = _rule_stencil(out["P_{2i}"])
    odd, of = _rule_stencil(out["P_{2i+1}"])
    return LaurentSymbol.from_rules(even, odd, even_first=ef, odd_first=of)


def convex_combination(a: LaurentSymbol, b: LaurentSymbol, w) -> LaurentSymbol:
    """``(1 - w) a + w b`` (``w`` a number or a parameter expression).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> a = LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)
    >>> b = LaurentSymbol.from_mask(["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"], start=-3)
    >>> convex_combination(a, b, sp.Symbol("w")).mask[0]
    -w/16
    """
    w = parse_coefficient(w)
    expr = sp.expand((1 - w) * a.expr() + w * b.expr())
    return LaurentSymbol.from_expr(expr)


def averaging(a: LaurentSymbol, steps: int = 1) -> LaurentSymbol:
    """``s`` Lane–Riesenfeld averaging steps: ``a(z) ((1+z)/2)^s``, centred at 0 or -1/2."""
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
        raise AnalysisError(f"the number of averaging steps must be a non-negative integer, not {steps!r}")
    out = a
    half = LaurentSymbol.from_mask([sp.Rational(1, 2), sp.Rational(1, 2)])
    for _ in range(steps):
        out = out * half
    centre = sp.Rational(out.start + out.end, 2)
    return out.shift(-int(sp.ceiling(centre)))


def dual(a: LaurentSymbol) -> LaurentSymbol:
    """The scheme after one averaging step: a primal symmetric mask becomes a dual one and vice versa.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> dual(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)).mask    # cubic B-spline
    (1/8, 1/2, 3/4, 1/2, 1/8)
    """
    return averaging(a, 1)


def pseudo_spline(m: int, l: int) -> LaurentSymbol:
    """The binary (primal) pseudo-spline of type ``(m, l)``, ``0 <= l <= m - 1`` (Dong–Shen 2007).

    ``(m, 0)`` is the B-spline of order ``2m``; ``(m, m-1)`` the Dubuc–Deslauriers ``2m``-point scheme.

    >>> pseudo_spline(2, 0).mask
    (1/8, 1/2, 3/4, 1/2, 1/8)
    """
    for name, v in (("m", m), ("l", l)):
        if isinstance(v, bool) or not isinstance(v, int):
            raise AnalysisError(f"the pseudo-spline type needs integers, {name} = {v!r}")
    if m < 1 or not 0 <= l <= m - 1:
        raise AnalysisError(f"a pseudo-spline of type (m, l) needs m >= 1 and 0 <= l <= m - 1, not ({m}, {l})")
    cos2 = (2 + Z + 1 / Z) / 4
    sin2 = (2 - Z - 1 / Z) / 4
    expr = 2 * cos2 ** m * sum(sp.binomial(m + l, j) * sin2 ** j * cos2 ** (l - j) for j in range(l + 1))
    return LaurentSymbol.from_expr(sp.expand(expr))
