"""Refinement of data by a stationary binary subdivision scheme; basic limit functions.

Convention (the one of :mod:`analysis.algebra.symbol`, stated once for the whole workbench)::

    (S_a f)_k = sum_j a_{k-2j} f_j,        a(z) = sum_i a_i z^i.

Writing ``k = 2i + eps`` (``eps`` in {0, 1}) the same rule reads, with the paper-style stencils
of :meth:`~analysis.algebra.symbol.LaurentSymbol.rules`::

    new[2i + eps] = sum_p a_{eps-2p} f[i+p].

Data are points in ``R^d``: an array of shape ``(n,)`` (scalars) or ``(n, d)``. The result has
the same rank.

Which new points are returned
-----------------------------
**Closed polygons** (``closed=True``, the default): the data are periodic, ``f[j + n] = f[j]``;
one step maps ``n`` points to ``2n`` points, the new points ``k = 0, 1, ..., 2n-1`` in that order
(``new[2i]`` and ``new[2i+1]`` for ``i = 0..n-1``). So output row ``k`` is ``(S_a f)_k`` exactly as
in the convention above, with no shift.

**Open polygons** (``closed=False``): the data are ``f[0..n-1]`` and nothing else. Three end rules:

* ``end_rule="interior"`` (default): keep only new points whose whole stencil lies inside the
  data, i.e. the contiguous run ``k = k_lo..k_hi`` of new points ``(S_a f)_k`` that use
  ``f[0..n-1]`` only. (When the even and odd stencils have different extents, as for the 4-point
  scheme, a point at either end whose stencil is inside may be dropped so that the output is
  one contiguous polygon.) The polygon shrinks at both ends and converges to the part of the
  limit curve that the data determine. Cubic B-spline: ``n -> 2n-3`` points, ``k = 1..2n-3``;
  Chaikin: ``n -> 2n-2``, ``k = 0..2n-3``; 4-point: ``n -> 2n-5``, ``k = 2..2n-4``.
* ``end_rule="extrapolate"``: the data are extended by *ghost points* obtained by point
  reflection through the end points, ``P_{-m} = 2 P_0 - P_m`` and ``P_{n-1+m} = 2 P_{n-1} -
  P_{n-1-m}`` (seed paper 004, Sect. 3.7, rules (3.9)-(3.10), with their last point ``P_n`` being
  our ``P_{n-1}``), as many as the stencils need. The new points kept are those whose stencil
  *centre* lies in the data's index range: new point ``k`` is centred at old index
  ``(k - c)/2`` with ``c = (start + end)/2`` the centre of the mask, so ``k = ceil(c) ..
  2n - 2 + floor(c)``. Primal schemes (``c = 0``: B-splines of odd degree, 4-point, 6-point):
  ``n -> 2n-1`` points, ``k = 0..2n-2``; a symmetric primal scheme with ``sum_j a_{2j} = 1``
  keeps the end points fixed (reflected data are odd-symmetric about them). Dual schemes (``c = -1/2``,
  Chaikin): ``k = 0..2n-3``. Reflection reproduces linear data, so linear data stay linear.
* ``end_rule=callable(points, side, count)``: ghost points supplied by the caller, used exactly
  like the reflected ones (same kept range as ``"extrapolate"``). ``points`` is the current data
  (same rank as the input; ``fractions.Fraction`` entries on the exact path); ``side`` is
  ``"left"`` or ``"right"``; ``count >= 1`` is the number of ghosts needed. Return an array of
  shape ``(count, d)`` (or ``(count,)`` for scalar data) **in index order**: for ``"left"`` the
  rows are ``P_{-count}, ..., P_{-1}``; for ``"right"`` they are ``P_n, ..., P_{n+count-1}``.
  :func:`point_reflection` is the rule of ``"extrapolate"`` in this form.

:func:`refined_indices` returns the range of ``k`` that one step keeps. ``steps=k`` applies the
step ``k`` times; each step re-indexes its output from 0.

Arithmetic
----------
*Float* (default): numpy float64, vectorised — for each residue ``eps`` a sum over ``p`` of
coefficient times a shifted slice of the (extended) data; no Python loop over points. Mask
coefficients are rounded to float; algebraic ones such as ``sqrt(6)`` are evaluated to double
precision first (the result is then a float approximation, never a certified value).

*Exact* (``exact=True``, or automatically when the data hold ``Fraction``, sympy numbers or
other non-float Python numbers in an object array): the same algorithm on numpy object arrays of
``flint.fmpq`` (about 15x faster than ``fractions.Fraction``), returned as ``Fraction``. The mask
coefficients must be rational; float data are read as the binary rationals they are.

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numerica 11 (2002) 73-144.
N. Dyn, J. A. Gregory, D. Levin, *A 4-point interpolatory subdivision scheme for curve design*,
CAGD 4 (1987) 257-268.
G. Chaikin, *An algorithm for high speed curve generation*, CGIP 3 (1974) 346-349.
Seed paper 004, *Modeling of curves by a design-control approximating refinement scheme* (2023),
Sect. 3.7, rules (3.9)-(3.10) (end rules for open polygons).
"""

from __future__ import annotations

import math
from fractions import Fraction
from numbers import Integral
from typing import Any, Callable, Mapping, Union

import numpy as np
import sympy as sp

from ..result import AnalysisError
from ..algebra.symbol import LaurentSymbol
from ..algebra.reader import as_expr

try:  # python-flint: fast exact rationals (a declared dependency); Fraction works without it
    from flint import fmpq as _Q, fmpq_poly as _QPoly
except ImportError:  # pragma: no cover
    _Q = Fraction
    _QPoly = None

__all__ = ["refine", "refined_indices", "point_reflection", "basic_limit_function", "EndRule"]

#: An end rule for open polygons: ``"interior"``, ``"extrapolate"`` or a ghost-point callable.
EndRule = Union[str, Callable[[np.ndarray, str, int], Any]]

_END_RULES = ("interior", "extrapolate")


# --------------------------------------------------------------------------------------------
# the mask as two stencils
# --------------------------------------------------------------------------------------------

class _Stencils:
    """``terms[eps]`` = [(p, coefficient)] with ``new[2i+eps] = sum_p c f[i+p]`` (nonzero only)."""

    __slots__ = ("terms", "pmin", "pmax", "start", "end")

    def __init__(self, a: LaurentSymbol, convert: Callable[[sp.Expr], Any]):
        self.start, self.end = a.start, a.end
        self.terms: list[list[tuple[int, Any]]] = [[], []]
        for i, c in a.items():
            if c == 0:
                continue
            eps = i % 2
            self.terms[eps].append(((eps - i) // 2, convert(c)))
        for t in self.terms:
            t.sort(key=lambda pc: pc[0])
        # an empty residue (degenerate mask) has no stencil: treat it as p = 0 so ranges stay sane
        self.pmin = [t[0][0] if t else 0 for t in self.terms]
        self.pmax = [t[-1][0] if t else 0 for t in self.terms]


def _check_symbol(a, params: Mapping | None, what: str) -> LaurentSymbol:
    if not isinstance(a, LaurentSymbol):
        raise AnalysisError(f"{what} needs a LaurentSymbol (build one with LaurentSymbol.from_mask), "
                            f"not {type(a).__name__}")
    if params:
        a = a.subs(params)
    a.require_numeric(what)
    if a.is_zero:
        raise AnalysisError(f"{what} needs a nonzero mask")
    return a


def _exact_coefficient(c: sp.Expr):
    if not c.is_Rational:
        raise AnalysisError(f"exact refinement needs rational mask coefficients; {sp.sstr(c)} is not "
                            "rational (use exact=False for a float approximation)")
    return _Q(int(c.p), int(c.q))


def _float_coefficient(c: sp.Expr) -> float:
    if c.is_Rational:
        return float(Fraction(int(c.p), int(c.q)))  # correctly rounded
    value = float(sp.N(c, 30))
    if not math.isfinite(value):
        raise AnalysisError(f"mask coefficient {sp.sstr(c)} is not a finite number")
    return value


def _stencils(a: LaurentSymbol, exact: bool) -> _Stencils:
    return _Stencils(a, _exact_coefficient if exact else _float_coefficient)


# --------------------------------------------------------------------------------------------
# data
# --------------------------------------------------------------------------------------------

def _to_q(x):
    """One exact rational (fmpq) from a Python/numpy/sympy number."""
    if isinstance(x, _Q):
        return x
    if isinstance(x, (bool, np.bool_)):
        raise AnalysisError(f"data value {x!r} is not a number")
    if isinstance(x, Fraction):
        return _Q(x.numerator, x.denominator)
    if isinstance(x, Integral):
        return _Q(int(x))
    if isinstance(x, sp.Basic):
        if x.is_Rational:
            return _Q(int(x.p), int(x.q))
        raise AnalysisError(f"exact refinement needs rational data; {sp.sstr(x)} is not rational")
    if isinstance(x, (float, np.floating)):
        if not math.isfinite(x):
            raise AnalysisError("the data contain NaN or infinite values")
        f = Fraction(float(x))
        return _Q(f.numerator, f.denominator)
    if isinstance(x, str):
        try:
            f = Fraction(x.strip())
        except (ValueError, ZeroDivisionError):
            raise AnalysisError(f"cannot read data value {x!r} as a rational number") from None
        return _Q(f.numerator, f.denominator)
    num, den = getattr(x, "numerator", None), getattr(x, "denominator", None)
    if num is not None and den is not None:  # gmpy2.mpq and friends
        try:
            return _Q(int(num), int(den))
        except (TypeError, ValueError):
            pass
    raise AnalysisError(f"data value {x!r} of type {type(x).__name__} is not a rational number")


_to_q_array = np.frompyfunc(_to_q, 1, 1)
_to_fraction_array = np.frompyfunc(
    lambda q: Fraction(int(q.p), int(q.q)) if _Q is not Fraction else q, 1, 1)


def _is_float_like(x) -> bool:
    return isinstance(x, (float, np.floating)) and not isinstance(x, bool)


def _prepare(points, exact: bool) -> tuple[np.ndarray, bool, bool]:
    """``(data of shape (n, d), exact, was_1d)``; float64 or an object array of fmpq."""
    try:
        arr = points if isinstance(points, np.ndarray) else np.asarray(points)
    except (ValueError, TypeError):
        raise AnalysisError("points must be an array of shape (n,) or (n, d) "
                            "(rows of equal length)") from None
    if arr.ndim not in (1, 2):
        raise AnalysisError(f"points must have shape (n,) or (n, d); got shape {arr.shape}")
    if arr.shape[0] == 0 or (arr.ndim == 2 and arr.shape[1] == 0):
        raise AnalysisError("no data points to refine")
    was_1d = arr.ndim == 1
    data = arr.reshape(arr.shape[0], 1) if was_1d else arr
    if data.dtype == object:
        if not exact and not all(_is_float_like(x) for x in data.flat):
            exact = True
    elif data.dtype.kind not in "iuf":
        raise AnalysisError(f"data must be real numbers; got dtype {data.dtype}")
    if exact:
        return _to_q_array(data).astype(object), True, was_1d
    try:
        out = np.asarray(data, dtype=np.float64)
    except (TypeError, ValueError):
        raise AnalysisError("data must be real numbers") from None
    if not np.isfinite(out).all():
        raise AnalysisError("the data contain NaN or infinite values")
    return out, False, was_1d


def _finish(data: np.ndarray, exact: bool, was_1d: bool) -> np.ndarray:
    out = _to_fraction_array(data).astype(object) if exact else data
    return out.reshape(-1) if was_1d else out


# --------------------------------------------------------------------------------------------
# planning one step: which new points, how many ghost points
# --------------------------------------------------------------------------------------------

def _residue_span(k0: int, k1: int, eps: int) -> tuple[int, int, int]:
    """``(first k of parity eps in [k0, k1], its i, count)``."""
    ke = k0 + ((eps - k0) % 2)
    if ke > k1:
        return ke, (ke - eps) // 2, 0
    return ke, (ke - eps) // 2, (k1 - ke) // 2 + 1


def _needed(st: _Stencils, k0: int, k1: int) -> tuple[int, int]:
    """The smallest and largest old index the new points ``k0..k1`` read."""
    lo, hi = None, None
    for eps in (0, 1):
        _, i0, cnt = _residue_span(k0, k1, eps)
        if cnt == 0:
            continue
        a, b = i0 + st.pmin[eps], i0 + cnt - 1 + st.pmax[eps]
        lo = a if lo is None else min(lo, a)
        hi = b if hi is None else max(hi, b)
    return (0, 0) if lo is None else (lo, hi)


def _plan(st: _Stencils, n: int, closed: bool, end_rule: EndRule) -> tuple[int, int, int, int]:
    """``(k0, k1, left ghosts, right ghosts)`` of one step on ``n`` points."""
    if closed:
        k0, k1 = 0, 2 * n - 1
    elif isinstance(end_rule, str) and end_rule == "interior":
        first = [2 * (-st.pmin[e]) + e for e in (0, 1)]
        last = [2 * (n - 1 - st.pmax[e]) + e for e in (0, 1)]
        k0, k1 = max(first) - 1, min(last) + 1
        if k1 < k0:
            width = max(st.pmax) - min(st.pmin) + 1
            raise AnalysisError(f"an open polygon of {n} point(s) is too short for the interior end "
                                f"rule of this mask (stencils span {width} points); use more points, "
                                "fewer steps or end_rule='extrapolate'")
        return k0, k1, 0, 0
    else:
        k0 = -((-(st.start + st.end)) // 2)          # ceil(c), c = (start+end)/2
        k1 = 2 * n - 2 + (st.start + st.end) // 2      # 2n-2 + floor(c)
        if k1 < k0:
            raise AnalysisError(f"an open polygon of {n} point(s) keeps no new point under this "
                                "end rule; give at least 2 points")
    lo, hi = _needed(st, k0, k1)
    return k0, k1, max(0, -lo), max(0, hi - (n - 1))


def _check_end_rule(end_rule) -> None:
    if isinstance(end_rule, str):
        if end_rule not in _END_RULES:
            raise AnalysisError(f"unknown end_rule {end_rule!r}; use 'interior', 'extrapolate' "
                                "or a callable(points, side, count)")
    elif not callable(end_rule):
        raise AnalysisError(f"end_rule must be 'interior', 'extrapolate' or a callable, "
                            f"not {type(end_rule).__name__}")


def refined_indices(a: LaurentSymbol, n: int, *, closed: bool = True,
                    end_rule: EndRule = "interior", params: Mapping | None = None) -> range:
    """The indices ``k`` of the new points ``(S_a f)_k`` that one step of :func:`refine` returns.

    Output row ``r`` of one step is the new point ``k = range[r]``. See the module docstring for
    the rules.

    Examples
    --------
    >>> cubic = LaurentSymbol.from_mask([1, 4, 6, 4, 1], start=-2) / 8
    >>> refined_indices(cubic, 10)
    range(0, 20)
    >>> refined_indices(cubic, 10, closed=False)
    range(1, 18)
    >>> refined_indices(cubic, 10, closed=False, end_rule="extrapolate")
    range(0, 19)
    >>> chaikin = LaurentSymbol.from_expr("(1+z)**3/(4*z**2)")
    >>> refined_indices(chaikin, 10, closed=False, end_rule="extrapolate")
    range(0, 18)
    """
    a = _check_symbol(a, params, "refinement")
    _check_end_rule(end_rule)
    if isinstance(n, bool) or not isinstance(n, Integral) or n < 1:
        raise AnalysisError(f"the number of points must be a positive integer, not {n!r}")
    k0, k1, _, _ = _plan(_stencils(a, False), int(n), closed, end_rule)
    return range(k0, k1 + 1)


# --------------------------------------------------------------------------------------------
# ghost points
# --------------------------------------------------------------------------------------------

def point_reflection(points: np.ndarray, side: str, count: int) -> np.ndarray:
    """Ghost points by point reflection through an end point (the ``"extrapolate"`` end rule).

    ``P_{-m} = 2 P_0 - P_m`` on the left and ``P_{n-1+m} = 2 P_{n-1} - P_{n-1-m}`` on the right,
    ``m = 1..count``, returned in index order (``P_{-count}, ..., P_{-1}`` on the left,
    ``P_n, ..., P_{n+count-1}`` on the right). These are rules (3.9)-(3.10) of seed paper 004
    (whose last point ``P_n`` is our ``P_{n-1}``); the extraction of that paper lost the minus
    signs. Works on float arrays and on object arrays of exact rationals.

    Examples
    --------
    >>> point_reflection(np.array([0.0, 1.0, 4.0]), "left", 2)
    array([-4., -1.])
    >>> point_reflection(np.array([0.0, 1.0, 4.0]), "right", 1)
    array([7.])
    """
    pts = np.asarray(points)
    n = pts.shape[0]
    if count > n - 1:
        raise AnalysisError(f"point reflection needs at least {count + 1} points to make {count} "
                            f"ghost point(s) at the {side} end; the polygon has {n}")
    if side == "left":
        return 2 * pts[0] - pts[np.arange(count, 0, -1)]
    if side == "right":
        return 2 * pts[n - 1] - pts[np.arange(n - 2, n - 2 - count, -1)]
    raise AnalysisError(f"side must be 'left' or 'right', not {side!r}")


def _ghosts(data: np.ndarray, side: str, count: int, end_rule: EndRule, exact: bool,
            was_1d: bool) -> np.ndarray:
    d = data.shape[1]
    if isinstance(end_rule, str):  # "extrapolate": reflect in the working arithmetic
        return point_reflection(data, side, count)
    view = _finish(data, exact, was_1d).view()
    view.flags.writeable = False  # the callable must not change the data it is shown
    try:
        got = end_rule(view, side, count)
    except AnalysisError:
        raise
    except Exception as exc:  # the user's callable failed: report it on one line
        raise AnalysisError(f"the end_rule callable failed on the {side} side: "
                            f"{type(exc).__name__}: {exc}") from exc
    try:
        arr = np.asarray(got, dtype=object if exact else None)
        arr = arr.reshape(count, d)
    except (ValueError, TypeError):
        shape = getattr(np.asarray(got, dtype=object), "shape", "?")
        raise AnalysisError(f"the end_rule callable must return {count} ghost point(s) of dimension "
                            f"{d} for the {side} side; got shape {shape}") from None
    if exact:
        return _to_q_array(arr).astype(object)
    try:
        arr = np.asarray(arr, dtype=np.float64)
    except (TypeError, ValueError):
        raise AnalysisError("the end_rule callable returned non-numeric ghost points") from None
    if not np.isfinite(arr).all():
        raise AnalysisError(f"the end_rule callable returned NaN or infinite ghost points ({side})")
    return arr


# --------------------------------------------------------------------------------------------
# one step
# --------------------------------------------------------------------------------------------

def _apply(g: np.ndarray, offset: int, st: _Stencils, k0: int, k1: int, exact: bool) -> np.ndarray:
    """New points ``k0..k1`` from extended data ``g`` (old index ``j`` is row ``offset + j``)."""
    d = g.shape[1]
    out = np.empty((k1 - k0 + 1, d), dtype=object if exact else np.float64)
    tmp = None  # scratch for coefficient * slice, sized for the larger residue
    for eps in (0, 1):
        ke, i0, cnt = _residue_span(k0, k1, eps)
        if cnt == 0:
            continue
        view = out[ke - k0::2]
        terms = st.terms[eps]
        if not terms:
            view[...] = _Q(0) if exact else 0.0
            continue
        for t, (p, c) in enumerate(terms):
            s = offset + i0 + p
            src = g[s:s + cnt]
            if t == 0:
                if c == 1:
                    view[...] = src
                else:
                    np.multiply(src, c, out=view)
            else:
                if tmp is None:
                    tmp = np.empty(((k1 - k0) // 2 + 1, d), dtype=out.dtype)
                buf = tmp[:cnt]
                if c == 1:
                    np.add(view, src, out=view)
                else:
                    np.multiply(src, c, out=buf)
                    np.add(view, buf, out=view)
    return out


def _step(data: np.ndarray, st: _Stencils, closed: bool, end_rule: EndRule, exact: bool,
          was_1d: bool) -> np.ndarray:
    n = data.shape[0]
    k0, k1, left, right = _plan(st, n, closed, end_rule)
    if left == 0 and right == 0:
        return _apply(data, 0, st, k0, k1, exact)
    parts = []
    if left:
        parts.append(data[np.arange(-left, 0) % n] if closed
                     else _ghosts(data, "left", left, end_rule, exact, was_1d))
    parts.append(data)
    if right:
        parts.append(data[np.arange(n, n + right) % n] if closed
                     else _ghosts(data, "right", right, end_rule, exact, was_1d))
    g = np.concatenate(parts, axis=0)
    return _apply(g, left, st, k0, k1, exact)


def refine(a: LaurentSymbol, points, steps: int = 1, *, closed: bool = True,
           end_rule: EndRule = "interior", exact: bool = False,
           params: Mapping | None = None, arity: int = 2) -> np.ndarray:
    """Apply ``steps`` steps of the scheme ``S_a`` of arity ``m`` (default 2) to a polygon in ``R^d``.

    Parameters
    ----------
    a : LaurentSymbol
        The mask, ``a(z) = sum_i a_i z^i``; numeric, or made numeric by ``params``.
    points : array_like, shape ``(n,)`` or ``(n, d)``
        The data, one point per row. An object array of ``Fraction``/sympy/int values selects
        exact arithmetic.
    steps : int
        Number of refinement steps (``0`` returns a copy).
    closed : bool
        Closed polygon (periodic data, ``n -> 2n`` points) or open polygon.
    end_rule : ``"interior"`` | ``"extrapolate"`` | callable
        Open polygons only (ignored when ``closed``); see the module docstring.
    exact : bool
        Exact rational arithmetic (rational mask required); the result holds ``Fraction``.
    params : mapping, optional
        Values for the mask's free parameters, e.g. ``{"omega": "1/16"}`` (arity 2).
    arity : int
        The dilation ``m``: ``f_i <- sum_j a_{i-mj} f_j``. For ``m > 2`` see :func:`_refine_dilated`
        (a direct loop; the points are returned as rows of an array, exact values as sympy rationals).

    Returns
    -------
    numpy.ndarray
        The refined points, same rank as ``points``: float64, or object dtype of ``Fraction``.

    Algorithm
    ---------
    One step: extend the data (periodically for a closed polygon, by ghost points for the
    ``"extrapolate"`` / callable end rules), then for each residue ``eps`` accumulate
    ``new[2i+eps] = sum_p a_{eps-2p} f[i+p]`` as ``coefficient * shifted slice`` over all ``i``
    at once. Cost per step: (number of nonzero mask coefficients) x (points) x d operations.

    Examples
    --------
    >>> lin = LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)     # linear B-spline
    >>> refine(lin, [0.0, 2.0, 6.0], closed=False)
    array([0., 1., 2., 4., 6.])
    >>> chaikin = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
    >>> refine(chaikin, [[0, 0], [1, 0], [1, 1], [0, 1]])               # closed square
    array([[0.25, 0.  ],
           [0.75, 0.  ],
           [1.  , 0.25],
           [1.  , 0.75],
           [0.75, 1.  ],
           [0.25, 1.  ],
           [0.  , 0.75],
           [0.  , 0.25]])
    >>> from fractions import Fraction
    >>> out = refine(lin, [Fraction(0), Fraction(1)], steps=2, closed=False)   # exact
    >>> out.dtype, [str(q) for q in out]
    (dtype('O'), ['0', '1/4', '1/2', '3/4', '1'])
    >>> four = LaurentSymbol.from_mask(["-w", 0, "1/2+w", 1, "1/2+w", 0, "-w"], start=-3)
    >>> cubes = [0, 1, 8, 27, 64]                                      # x^3 at x = 0..4
    >>> refine(four, cubes, closed=False, params={"w": "1/16"})        # interior: k = 2..6
    array([ 1.   ,  3.375,  8.   , 15.625, 27.   ])
    >>> refine(four, cubes, closed=False, end_rule="extrapolate", params={"w": "1/16"})
    array([ 0.   ,  0.125,  1.   ,  3.375,  8.   , 15.625, 27.   , 44.375,
           64.   ])

    The end points are kept; the ghost ``2*64 - 27 = 101`` (not ``5^3 = 125``) moves the last
    inserted point off the cubic (``44.375``, not ``3.5^3 = 42.875``).

    References
    ----------
    N. Dyn, D. Levin, Acta Numerica 11 (2002) 73-144, Sect. 2; seed paper 004, Sect. 3.7.
    """
    if arity != 2:
        return _refine_dilated(a, points, arity, steps, closed=closed, exact=exact, end_rule=end_rule)
    a = _check_symbol(a, params, "refinement")
    _check_end_rule(end_rule)
    if isinstance(steps, bool) or not isinstance(steps, Integral) or steps < 0:
        raise AnalysisError(f"steps must be a non-negative integer, not {steps!r}")
    data, exact, was_1d = _prepare(points, bool(exact))
    st = _stencils(a, exact)
    for _ in range(int(steps)):
        data = _step(data, st, bool(closed), end_rule, exact, was_1d)
    if steps == 0:
        data = data.copy()
    return _finish(data, exact, was_1d)


def _refine_dilated(a: LaurentSymbol, points, m: int, steps: int = 1, *, closed: bool = True,
                    exact: bool = False, end_rule: str = "interior") -> np.ndarray:
    """``steps`` rounds of ``f_i <- sum_j a_{i-mj} f_j`` for arity ``m > 2`` (rows = points, any dimension).

    Kept beside the vectorised binary step (:func:`refine`) because its results differ in form (a 2-D
    array always, exact values as sympy rationals), which the m-ary command and reports print.

    Closed polygons are periodic (``n`` points -> ``m n`` points per round, new point ``i`` attached to
    index ``i`` of the refined periodic sequence). Open polygons, both end rules of :func:`refine` with
    dilation ``m``:

    * ``end_rule="interior"`` keeps only the new points that depend on old points alone:
      ``f^{n+1}_i`` for ``e - m + 1 <= i <= m n + s - 1`` (``[s, e]`` the support of the mask);
    * ``end_rule="extrapolate"`` extends the data by ghost points reflected through the end points,
      ``P_{-k} = 2 P_0 - P_k`` and ``P_{n-1+k} = 2 P_{n-1} - P_{n-1-k}`` (:func:`point_reflection`), and
      keeps the new points whose stencil centre lies in the data's index range: with ``c = (s + e)/2``,
      new point ``i`` is centred at old index ``(i - c)/m`` (data at ``x_j = (j + p) h``, new points at
      ``(i + p) h/m``, ``p = c/(m-1)``: the parametrisation in which the symmetric mask is centred), so
      ``i = ceil(c) .. m (n-1) + floor(c)``. For ``m = 2`` these are the binary ranges; primal schemes
      (``c = 0``) map ``n`` points to ``m (n-1) + 1`` and keep the end points when ``sum_j a_{mj} = 1`` and
      the mask is symmetric (reflected data are odd-symmetric about them), so linear data stay linear.

    >>> tri = LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)")          # ternary linear B-spline
    >>> refine(tri, [[0.0], [3.0]], closed=False, arity=3).ravel().tolist()
    [0.0, 1.0, 2.0, 3.0]
    >>> q = LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)")            # ternary quadratic B-spline
    >>> refine(q, [[0], [9], [18]], closed=False, exact=True, end_rule="extrapolate", arity=3).ravel().tolist()
    [0, 3, 6, 9, 12, 15, 18]
    """
    from ..algebra.factorization import check_arity

    m = check_arity(m)
    a.require_numeric("refinement")
    if not isinstance(steps, int) or steps < 0:
        raise AnalysisError(f"steps must be a non-negative integer, not {steps!r}")
    if end_rule not in ("interior", "extrapolate"):
        raise AnalysisError(f"unknown end_rule {end_rule!r}; use 'interior' or 'extrapolate'")
    data = np.array(points, dtype=object if exact else float)
    if data.ndim == 1:
        data = data[:, None]
    if exact:
        data = np.vectorize(lambda x: sp.Rational(x))(data).astype(object)
    coeffs = {i: (sp.Rational(c) if exact else float(c)) for i, c in a.items()}
    s, e = a.start, a.end
    for _ in range(steps):
        n = data.shape[0]
        if n == 0:
            raise AnalysisError("the polygon has no points")
        if closed:
            lo, hi, src, off = 0, m * n - 1, None, 0
        elif end_rule == "interior":
            lo, hi, src, off = e - m + 1, m * n + s - 1, data, 0
            if hi < lo:
                raise AnalysisError(f"an open polygon of {n} points is too short for a mask of support "
                                    f"[{s}, {e}] (no new point depends on old points only); use more points, "
                                    "fewer steps or --end-rule extrapolate")
        else:
            src, off, lo, hi = _extrapolated(data, s, e, m, n)
        out = np.zeros((hi - lo + 1, data.shape[1]), dtype=data.dtype)
        if exact:
            out[:] = sp.Integer(0)
        for i in range(lo, hi + 1):
            for j in range(-((e - i) // m), (i - s) // m + 1):
                x = data[j % n] if src is None else src[j + off]
                out[i - lo] = out[i - lo] + coeffs.get(i - m * j, 0) * x
        data = out
    return data


def _extrapolated(data: np.ndarray, s: int, e: int, m: int, n: int):
    """``(extended data, index offset, first kept i, last kept i)`` of the ``"extrapolate"`` end rule."""
    lo = -((-(s + e)) // 2)                      # ceil(c), c = (s + e)/2
    hi = m * (n - 1) + (s + e) // 2              # m(n-1) + floor(c)
    if hi < lo:
        raise AnalysisError(f"an open polygon of {n} point(s) keeps no new point; give at least 2 points")
    jmin, jmax = -((e - lo) // m), (hi - s) // m
    left, right = max(0, -jmin), max(0, jmax - (n - 1))
    parts = []
    if left:
        parts.append(point_reflection(data, "left", left))
    parts.append(data)
    if right:
        parts.append(point_reflection(data, "right", right))
    return np.concatenate(parts, axis=0), left, lo, hi


# --------------------------------------------------------------------------------------------
# basic limit function
# --------------------------------------------------------------------------------------------

def basic_limit_function(a: LaurentSymbol, level: int, *, exact: bool = False, centre: bool = False,
                         params: Mapping | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Samples of the basic limit function: ``S_a^level`` applied to the delta sequence.

    Returns ``(x, values)`` with ``x_j = j / 2^level`` and ``values_j = (S_a^level delta)_j`` for
    ``j = start (2^level - 1) .. end (2^level - 1)`` (the support of the iterated symbol
    ``a(z) a(z^2) ... a(z^{2^(level-1)})``). With our convention the basic limit function
    ``phi`` satisfies ``phi(x) = sum_i a_i phi(2x - i)``, is supported on ``[start, end]`` of
    the mask, and ``phi(j/2^level) ~ values_j`` for a convergent scheme (exactly for an
    interpolatory one). So a primal symmetric scheme (``start = -end``) gives ``phi`` centred
    at 0 — the cubic B-spline mask ``[1,4,6,4,1]/8``, start -2, gives ``B_3`` on ``[-2, 2]`` — and
    a dual scheme such as Chaikin's (start -2, end 1) gives a ``phi`` on ``[-2, 1]`` centred at
    ``-1/2``.

    ``centre=True`` samples at ``x_j = (j + m) / 2^level`` instead, with ``m = sum_i i a_i /
    sum_i a_i`` the mask's centre of mass (``(start + end)/2`` for a symmetric mask). The values
    are the same; only the abscissae move. ``values_j`` is the coefficient of the level-``level``
    copy of ``phi`` centred at ``(j + m)/2^level``, so for a symmetric scheme these samples are
    second-order accurate, ``O(4^-level)``, while ``j/2^level`` is only first order when
    ``m != 0`` (dual schemes: Chaikin's samples are shifted by ``2^-(level+1)``). For ``m = 0``
    (primal symmetric, interpolatory) both are the same.

    ``exact=True`` returns ``x`` and ``values`` as object arrays of ``Fraction`` (rational mask
    required); otherwise float64 arrays.

    Algorithm
    ---------
    ``v <- a(z) v(z^2)`` ``level`` times (upsample by 2 and convolve with the mask), which is
    refinement of the delta sequence with no truncation; exact products by FLINT.

    Examples
    --------
    >>> cubic = LaurentSymbol.from_mask([1, 4, 6, 4, 1], start=-2) / 8
    >>> x, v = basic_limit_function(cubic, 1, exact=True)
    >>> [str(t) for t in x]                     # level 1: the mask itself at j/2
    ['-1', '-1/2', '0', '1/2', '1']
    >>> [str(t) for t in v]
    ['1/8', '1/2', '3/4', '1/2', '1/8']
    >>> x, v = basic_limit_function(cubic, 8)
    >>> round(float(v[x == 0][0]), 4), round(float(v[x == 1][0]), 4)    # B3(0) = 2/3, B3(1) = 1/6
    (0.6667, 0.1667)

    References
    ----------
    N. Dyn, D. Levin, Acta Numerica 11 (2002) 73-144, Sect. 2.3 (basic limit function).
    """
    a = _check_symbol(a, params, "the basic limit function")
    if isinstance(level, bool) or not isinstance(level, Integral) or level < 0:
        raise AnalysisError(f"level must be a non-negative integer, not {level!r}")
    level = int(level)
    scale = 2 ** level
    lo = a.start * (scale - 1)
    size = (a.end - a.start) * (scale - 1) + 1
    if size > 50_000_000:
        raise AnalysisError(f"level {level} gives {size} samples; choose a smaller level")
    shift: Any = 0
    if centre:
        total = sum(a.mask)
        if total == 0:
            raise AnalysisError("centre=True needs a mask with a(1) != 0")
        shift = as_expr(sum(i * c for i, c in a.items()) / total)
    if exact:
        coeffs = [_exact_coefficient(c) for c in a.mask]
        if _QPoly is not None:
            mask_poly = _QPoly(coeffs)
            v = _QPoly([1])
            for _ in range(level):
                up = [_Q(0)] * (2 * max(v.degree(), 0) + 1)
                up[::2] = v.coeffs()
                v = mask_poly * _QPoly(up)
            vals = list(v.coeffs())
        else:  # pragma: no cover - plain Fractions
            vals = [Fraction(1)]
            for _ in range(level):
                up = [Fraction(0)] * (2 * len(vals) - 1)
                up[::2] = vals
                new = [Fraction(0)] * (len(up) + len(coeffs) - 1)
                for i, u in enumerate(up):
                    if u:
                        for k, c in enumerate(coeffs):
                            new[i + k] += c * u
                vals = new
        vals = vals + [_Q(0)] * (size - len(vals))
        values = _to_fraction_array(np.array(vals, dtype=object)).astype(object)
        m = Fraction(int(shift.p), int(shift.q)) if centre else 0
        x = np.array([(lo + j + m) / Fraction(scale) for j in range(size)], dtype=object)
        return x, values
    mask = np.array([_float_coefficient(c) for c in a.mask], dtype=np.float64)
    v = np.ones(1)
    for _ in range(level):
        up = np.zeros(2 * len(v) - 1)
        up[::2] = v
        v = np.convolve(up, mask)
    x = (np.arange(lo, lo + size, dtype=np.float64) + _float_coefficient(as_expr(shift))) / scale
    return x, v
