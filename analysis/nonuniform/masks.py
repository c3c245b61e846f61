"""Masks of the NVPS: the location masks ``a^{k,i}`` of one step, the limit mask, distances.

Convention of the workbench: ``(S_a f)_i = sum_j a_{i-2j} f_j``. The new point ``i`` of level
``k+1`` is ``P^{k+1}_i = sum_p a^{k,i}_{i-2p} P^k_p`` (seed 001, (1)); only the coefficients of
parity ``i`` act. We complete the mask to both parities in the natural way: every degree-2 point
``Q_q`` of edge ``e = floor(q/2)`` has the full Chaikin-type mask
``A_2(h; z) = h z^-2 + (1-h) z^-1 + (1-h) + h z`` (rule (3); seed 001's (11) is ``z A_2``), and
``a^{k,i}(z) = 2^{2-d} sum_l binom(d-2, l) z^{-l} A_2(h_{floor((i+l)/2)}; z)``.
When all ``h = 1/4`` (``u = 1``) this is ``a(z) = z^{-d} (1+z)^{d+1} / 2^d``, the uniform B-spline
of degree ``d`` (catalogue ``bspline-d`` shifted).

Differences from the limit mask are computed from ``h - 1/4 = v/(4(2 - v))`` (``v = 1 - u``), so
they keep full relative precision near ``u = 1``.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from ..result import AnalysisError
from .arithmetic import _Arith
from .refinement import _check_degree, _check_rule, _tau, limit_mask  # noqa: F401 (limit_mask: re-exported)


def _binomial_weights(d: int):
    return [Fraction(math.comb(d - 2, l), 2 ** (d - 2)) for l in range(d - 1)]


def _mask_array(delta, d: int, closed: bool, base=None):
    """Full masks of all new points (seed 001 layout), rows i, columns exponents -d..1.

    With ``base=None`` the result is the difference ``a^{k,i} - a`` as a linear function of
    ``delta_e = h_e - 1/4``; with ``base = h`` it is the mask itself.
    """
    edges = len(delta)
    nq = 2 * edges
    count = nq if closed else nq - (d - 2)
    dtype = float if isinstance(delta, np.ndarray) and delta.dtype == float else object
    M = np.zeros((count, d + 2), dtype=dtype)
    if dtype is object:
        M[:] = 0
    idx = np.arange(count)
    for l, w in enumerate(_binomial_weights(d)):
        q = (idx + l) % nq if closed else idx + l
        e = q // 2
        if base is None:
            x = delta[e]
            coeffs = (x, -x, -x, x)
        else:
            x = base[e]
            coeffs = (x, 1 - x, 1 - x, x)
        wl = float(w) if dtype is float else sp.Rational(w.numerator, w.denominator)
        for s, c in enumerate(coeffs):
            t = (s - 2) - l + d
            M[:, t] = M[:, t] + wl * c
    return M


def location_masks(u=None, degree: int = 2, *, closed: bool = False, rule: str = "seed001",
                   arithmetic: str = "float", prec: int = 113, one_minus_u=None) -> tuple[np.ndarray, int]:
    """The full masks ``a^{k,i}`` of all new points of one step (rows), and the exponent of the
    first column, for the edge parameters ``u`` of level ``k``.

    >>> M, start = location_masks([1, 0], degree=2)
    >>> start, M.tolist()
    (-2, [[0.25, 0.75, 0.75, 0.25], [0.25, 0.75, 0.75, 0.25], [0.5, 0.5, 0.5, 0.5], [0.5, 0.5, 0.5, 0.5]])
    """
    d = _check_degree(degree)
    _check_rule(rule)
    ctx = _Arith(arithmetic, prec)
    with ctx.scope():
        if one_minus_u is None:
            if u is None:
                raise AnalysisError("give u=... or one_minus_u=...")
            v = 1 - ctx.array(np.atleast_1d(np.asarray(u, dtype=object)))
        else:
            v = ctx.array(np.atleast_1d(np.asarray(one_minus_u, dtype=object)))
        h = 1 / (2 * (2 - v))
        M = _mask_array(h, d, closed, base=h)
    start = -d
    if rule == "seed000":
        if closed:
            M = np.roll(M, _tau(d), axis=0)
        start += _tau(d)
    return M, start


def _parity_norms(D: np.ndarray, start: int, absf) -> np.ndarray:
    """Per new point i: sum over exponents s = i (mod 2) of |D[i, s]| (operator-row l1 norm)."""
    count, width = D.shape
    out = []
    A = absf(D)
    exps = np.arange(width) + start
    for par in (0, 1):
        cols = np.nonzero((exps - par) % 2 == 0)[0]
        out.append(A[:, cols].sum(axis=1))
    rows = np.arange(count) % 2
    return np.where(rows == 0, out[0], out[1])


def mask_distance(u=None, degree: int = 2, *, closed: bool = False, one_minus_u=None,
                  arithmetic: str = "float", prec: int = 113) -> dict:
    """Distances of the level's masks from the limit B-spline mask.

    Returns ``{"operator": max_i sum_p |a^{k,i}_{i-2p} - a_{i-2p}|`` (the row l1 norm of
    ``S^k - S_a``, the norm of DESIGN.md), ``"coefficient": max_{i,s} |a^{k,i}_s - a_s|``
    (seed 001's (12))``}``, computed from ``h - 1/4 = v/(4(2-v))`` without cancellation.

    >>> out = mask_distance([0.0], degree=2)      # u = 0: h = 1/2
    >>> out["operator"], out["coefficient"]
    (0.5, 0.25)
    """
    d = _check_degree(degree)
    ctx = _Arith(arithmetic, prec)
    with ctx.scope():
        if one_minus_u is None:
            v = 1 - ctx.array(np.atleast_1d(np.asarray(u, dtype=object)))
        else:
            v = ctx.array(np.atleast_1d(np.asarray(one_minus_u, dtype=object)))
        delta = v / (4 * (2 - v))
        D = _mask_array(delta, d, closed)
        absf = np.abs if D.dtype == float else np.frompyfunc(abs, 1, 1)
        op = _parity_norms(D, -d, absf)
        co = absf(D)
        op_max = float(op.max()) if D.dtype == float else _obj_max(list(op))
        co_max = float(co.max()) if D.dtype == float else _obj_max(list(co.ravel()))
    return {"operator": op_max, "coefficient": co_max}


def _obj_max(xs):
    """Max of mpf/sympy numbers; for intervals, the interval [max of lower ends, max of upper ends]."""
    if isinstance(xs[0], mpmath.iv.mpf):
        return mpmath.iv.mpf([max(x.a for x in xs), max(x.b for x in xs)])
    return max(xs)


def _pure_constant(d: int, parity: int | None = None) -> Fraction:
    """Row l1 norm of ``z^{-d}(1-z)^2 (1+z)^{d-1} / 2^{d-2}`` over the exponents of parity
    ``parity`` (the operator distance ``||S^k - S_a||`` at a new point of that parity whose whole
    window has one parameter, divided by ``|h - 1/4|``); the max over both parities if ``None``."""
    z = sp.Symbol("z")
    p = sp.Poly(sp.expand((1 - z) ** 2 * (1 + z) ** (d - 1)), z)
    coeffs = p.all_coeffs()[::-1]          # exponent t - d for index t
    sums = {par: sum(abs(c) for t, c in enumerate(coeffs) if (t - d - par) % 2 == 0) for par in (0, 1)}
    if parity is None:
        return Fraction(int(max(sums.values())), 2 ** (d - 2))
    return Fraction(int(sums[parity]), 2 ** (d - 2))
