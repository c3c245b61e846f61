"""The Dyn–Levin norm test ``||(1/2 S_a)^L||_inf < 1`` of a one-parameter difference symbol, proven for every
parameter value of a closed rational box at once, in Arb ball arithmetic: the box as one ball, the product
symbol ``a(z) a(z^2) ... a(z^(2^(L-1)))`` of ball polynomials, and the largest residue sum of absolute values.
A cheaper and coarser companion of the Bernstein bounds of :mod:`analysis.stationary.normbox`, used to cover a
claimed interval by boxes (:func:`analysis.regularity.ranges.verify_smoothness_interval`).

Algorithm
---------
The coefficients of ``a`` are read once (:func:`mask_terms`); on a box the ball ``P`` containing it is
substituted into each, and the product for ``L`` extends the one for ``L - 1`` by the factor ``a(z^(2^(L-1)))``
(the same balls a separate computation for that ``L`` would give). ``N_L < 1`` is an Arb comparison: True only
when proven for the whole ball. Before the Arb products, a float screen at the box's midpoint ``t``: when
``N_L(t) >= 1`` is certain for every ``L`` (float residue sums lowered by an a-priori rounding bound), no ball
bound can be below 1 and the answer is False without them (most boxes near a true C^j boundary are of this kind).

Examples
--------
The four-point scheme's second differences: ``N_L < 1`` (so C^1) proven on a whole box of the tension ``w``,
and not provable on a box reaching beyond the C^1 range:

>>> from sympy import Rational as Q
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.stationary.difference import difference_symbol
>>> d = difference_symbol(LaurentSymbol.from_mask(["-w", 0, "w + 1/2", 1, "w + 1/2", 0, "-w"], start=-3), 2)
>>> terms = mask_terms(d, d.params[0])
>>> [norm_below_one_on_box(terms, d.start, box, 4) for box in ((Q(1, 32), Q(1, 16)), (Q(1, 4), Q(1, 2)))]
[True, False]

The second box fails at its midpoint already (``N_L(3/8) >= 1`` for every ``L <= 4``, certain in floats), so no
Arb product is computed for it; the first is decided in Arb:

>>> [_fails_at_a_point(terms, box, 4) for box in ((Q(1, 32), Q(1, 16)), (Q(1, 4), Q(1, 2)))]
[False, True]

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numerica 11 (2002) 73-144 (the norm test).
F. Johansson, *Arb: efficient arbitrary-precision midpoint-radius interval arithmetic*, IEEE Trans. Comput.
66 (2017) 1281-1292.
"""

from __future__ import annotations

import sympy as sp

from ..algebra.symbol import LaurentSymbol

__all__ = ["mask_terms", "norm_below_one_on_box"]


def mask_terms(am: LaurentSymbol, p: sp.Symbol) -> list:
    """Each coefficient of ``am`` as a rational ``(p, q)`` (no ``p``) or its terms ``[(e, p, q), ...]``
    in ``p`` (sympy's order), for :func:`norm_below_one_on_box`: read once per claimed interval."""
    out = []
    for c in am.mask:
        if c.free_symbols:
            out.append([(int(e), int(sp.Rational(co).p), int(sp.Rational(co).q))
                        for (e,), co in sp.Poly(c, p).terms()])
        else:
            q = sp.Rational(c)
            out.append((int(q.p), int(q.q)))
    return out


#: the a-priori bound of the relative rounding error of :func:`_fails_at_a_point`: each float coefficient of
#: the product symbol at ``t`` is off by at most ``gamma_n`` (``n`` the roundings along the chain of ``L``
#: convolutions with ``len(terms)`` nonzero factor coefficients, plus the evaluation at ``t``: n < 10^4, so
#: gamma_n < 2e-12) times the same product of absolute values, and each residue sum by ``gamma_n`` times
#: itself; this factor exceeds both more than 500-fold
_SCREEN_ERROR = 1e-9


def _fails_at_a_point(terms: list, box: tuple, max_L: int) -> bool:
    """True when ``N_L(t) >= 1`` is certain for every ``L <= max_L`` at a point ``t`` of the box: then no ball
    bound on the box can be below 1 (each Arb residue sum contains the exact one at ``t``), and
    :func:`norm_below_one_on_box` is False without its Arb products. False when the floats do not settle it
    (the Arb test then decides as before). Floats only: ``N_L(t)`` from the float product symbol at ``t``,
    lowered by ``_SCREEN_ERROR`` times the float product of the absolute values of the coefficients."""
    import numpy as np
    from fractions import Fraction

    lo, hi = (Fraction(int(x.p), int(x.q)) for x in box)
    t = float((lo + hi) / 2)
    if not lo <= Fraction(t) <= hi:
        return False
    vals, absv = [], []
    for c in terms:
        if isinstance(c, tuple):
            v = c[0] / c[1]
            vals.append(v)
            absv.append(abs(v))
        else:
            vals.append(sum((num / den) * t ** e for e, num, den in c))
            absv.append(sum(abs(num / den) * abs(t) ** e for e, num, den in c))
    a, A = np.array(vals), np.array(absv)
    if not (np.isfinite(a).all() and np.isfinite(A).all()):
        return False
    if len(a) * max_L > 2000 or len(a) * 2 ** max_L > 10 ** 6:      # beyond the sizes the error bound covers
        return False
    prod, aprod = a, A
    for L in range(1, max_L + 1):
        if L > 1:
            step = 2 ** (L - 1)
            spaced, aspaced = np.zeros((len(a) - 1) * step + 1), np.zeros((len(a) - 1) * step + 1)
            spaced[::step], aspaced[::step] = a, A
            prod, aprod = np.convolve(prod, spaced), np.convolve(aprod, aspaced)
        mod = 2 ** L
        lower = np.abs(prod) - _SCREEN_ERROR * aprod - 1e-300
        pad = -len(lower) % mod
        sums = np.concatenate([lower, np.zeros(pad)]).reshape(-1, mod).sum(axis=0)
        if not (np.isfinite(sums).all() and float(sums.max()) >= mod * (1 + _SCREEN_ERROR)):
            return False
    return True


def norm_below_one_on_box(terms: list, start: int, box: tuple, max_L: int, prec: int = 128) -> bool:
    """True when ||(1/2 S_{am})^L||_inf < 1 is proven for every p in the closed box (Arb) for one
    ``L = 1, ..., max_L`` (the first that proves it; ``terms`` from :func:`mask_terms`, ``start``
    the first exponent of ``am``). The product for ``L`` extends the one for ``L - 1`` by one factor:
    every ``L`` computes exactly the balls a separate computation for that ``L`` would.

    A box where a float screen shows ``N_L >= 1`` at a point for every ``L`` (:func:`_fails_at_a_point`)
    is False at once: no ball bound there could be below 1, so the answer is the one the Arb products
    would give."""
    from flint import arb, arb_poly, ctx

    if _fails_at_a_point(terms, box, max_L):
        return False
    old = ctx.prec
    ctx.prec = prec
    try:
        lo, hi = box
        mid = (arb(int(lo.p)) / int(lo.q) + arb(int(hi.p)) / int(hi.q)) / 2
        rad = (arb(int(hi.p)) / int(hi.q) - arb(int(lo.p)) / int(lo.q)) / 2
        P = mid + arb(0, rad.upper())  # the box as a ball
        coeffs = []
        for c in terms:
            if isinstance(c, tuple):
                coeffs.append(arb(c[0]) / c[1])
            else:
                v = arb(0)
                for e, num, den in c:
                    v += (arb(num) / den) * P ** e
                coeffs.append(v)
        prod = arb_poly(coeffs)
        for L in range(1, max_L + 1):
            if L > 1:
                step = 2 ** (L - 1)
                spaced = [arb(0)] * ((len(coeffs) - 1) * step + 1)
                spaced[::step] = coeffs
                prod = prod * arb_poly(spaced)
            mod = 2 ** L
            first = start * (2 ** L - 1)
            cs = prod.coeffs()
            best = arb(0)
            for r in range(mod):
                s = arb(0)
                for idx in range((r - first) % mod, len(cs), mod):
                    s += abs(cs[idx])
                best = s if s.upper() > best.upper() else best
            if best / 2 ** L < 1:  # Arb comparison: True only when proven for the whole ball
                return True
        return False
    finally:
        ctx.prec = old
