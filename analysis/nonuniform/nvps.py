"""Non-uniform variable-parameter subdivision (NVPS, seeds 000/001): refinement and analysis.

The NVPS of degree ``d >= 2`` (Fang, Jeong, Yoon) refines a polygon whose *edges* carry tension
parameters ``u``. One step (seed 001, rules (2)-(6); seed 000 writes ``lambda`` and
``eta(x) = 1/(2(1+x))``):

1. degree 2 (a Chaikin step with a weight per edge ``e`` between ``P_e`` and ``P_{e+1}``)::

       Q_{2e}   = (1 - h_e) P_e + h_e P_{e+1},      h_e = 1/(2(1+u_e)),
       Q_{2e+1} = h_e P_e + (1 - h_e) P_{e+1};

2. degree d: ``d - 2`` averagings, ``(S_d P)_i = ((S_{d-1} P)_i + (S_{d-1} P)_{i+1})/2`` (seed 001,
   (6)), i.e. ``(S_d P)_i = 2^{2-d} sum_l binom(d-2, l) Q_{i+l}``; seed 000 writes the same sum with
   the index shifted by ``tau_d = ceil((d-2)/2)``, ``(S_d P)_i = 2^{2-d} sum_l binom(d-2,l) Q_{i+l-tau_d}``;

3. the parameters of the new edges: ``u_new = sqrt((1+u_old)/2)`` taken from one old edge.
   Seed 001 (Algorithm 1, step 3, both cases in one formula): new edge ``j`` takes old edge
   ``ceil((j + floor((d-2)/2))/2)``; for ``d = 2`` this is rule (2): ``u_{2i} <- u_i``,
   ``u_{2i+1} <- u_{i+1}``. Seed 000: ``lambda_{2i} = lambda_{2i+1} <- lambda_i`` in its own
   (shifted) indexing.

``rule="seed001"`` (default) or ``rule="seed000"`` selects the indexing and the inheritance; see
:func:`compare_definitions` for how the two relate (same data rule up to the shift ``tau_d``; the
same parameter inheritance for odd ``d``; mirror images of each other for even ``d``).

Open polygons (``closed=False``): ``n`` points and ``n - 1`` edge parameters give
``2(n-1) - (d-2)`` points and one parameter per new edge; every step re-indexes from 0 (the rules
are translation covariant, so this is harmless). Closed polygons: ``n`` points, ``n`` parameters
(edge ``n-1`` joins ``P_{n-1}`` to ``P_0``), ``2n`` new points.

Parameters are held as ``v = 1 - u``, updated by the cancellation-free form of the rule,
``v_new = (v/2) / (1 + sqrt(1 - v/2))``, so that ``1 - u^k ~ 4^{-k}`` and the mask differences
``h - 1/4 = v/(4(2 - v))`` keep full relative precision at every level (see "Precision").
``u = cos(theta)`` (``0 <= theta < pi``) gives ``u^k = cos(theta/2^k)``; ``u = cosh(theta)`` gives
``u^k = cosh(theta/2^k)``; :func:`parameter_from_angle` builds ``v`` accurately from ``theta``.

Masks
-----
Convention of the workbench: ``(S_a f)_i = sum_j a_{i-2j} f_j``. The new point ``i`` of level
``k+1`` is ``P^{k+1}_i = sum_p a^{k,i}_{i-2p} P^k_p`` (seed 001, (1)); only the coefficients of
parity ``i`` act. We complete the mask to both parities in the natural way: every degree-2 point
``Q_q`` of edge ``e = floor(q/2)`` has the full Chaikin-type mask
``A_2(h; z) = h z^-2 + (1-h) z^-1 + (1-h) + h z`` (rule (3); seed 001's (11) is ``z A_2``), and
``a^{k,i}(z) = 2^{2-d} sum_l binom(d-2, l) z^{-l} A_2(h_{floor((i+l)/2)}; z)``.
When all ``h = 1/4`` (``u = 1``) this is ``a(z) = z^{-d} (1+z)^{d+1} / 2^d``, the uniform B-spline
of degree ``d`` (catalogue ``bspline-d`` shifted).

Arithmetic
----------
One algorithm, four arithmetics (``arithmetic=``): ``"float"`` (numpy float64, vectorised),
``"mp"`` (mpmath ``mpf`` at ``prec`` bits, numpy object arrays), ``"iv"`` (``mpmath.iv``
intervals: rigorous enclosures of every refined point) and ``"exact"`` (sympy numbers, e.g.
rational data and parameters whose square-root updates stay rational).

Examples
--------
>>> import numpy as np
>>> P = np.array([[0., 0.], [1., 0.], [1., 1.], [0., 1.]])
>>> r = refine(P, [1, 1, 1, 1], degree=2, steps=1, closed=True)     # u = 1: Chaikin
>>> r.points[:2].tolist()
[[0.25, 0.0], [0.75, 0.0]]
>>> r.level, len(r.points), r.u.tolist()
(1, 8, [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0])

Algorithm
---------
Vectorised slices: one fused Chaikin step on all edges, ``d - 2`` pairwise averages (``np.roll``
for closed polygons), one gather for the new parameters. ``O(n d)`` per step.

Precision and conditioning
--------------------------
The data rule is a convex combination (well conditioned). The only cancellation in the naive
formulas is ``1 - u^k`` (and ``h - 1/4``), both avoided by carrying ``v = 1 - u``.

References
----------
Seed 000: M. Fang, B. Jeong, J. Yoon, *Non-uniform subdivision schemes reproducing locally
different curves* (conference abstract).
Seed 001: M. Fang, B. Jeong, J. Yoon, *A non-uniform subdivision scheme with variable parameters
for curve design* (preprint, 17 pp.).
M. Fang, W. Ma, G. Wang, *A generalized curve subdivision scheme of arbitrary order with a tension
parameter*, CAGD 27 (2010) 720-733.
N. Dyn, D. Levin, J. Yoon, *A new method for the analysis of univariate nonuniform subdivision
schemes*, Constr. Approx. 40 (2014) 173-188.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Sequence

import mpmath
import numpy as np
import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, AnalysisError, Result

__all__ = [
    "NVPS", "Refinement", "refine", "step", "parameter_from_angle", "angle_from_parameter",
    "location_masks", "limit_mask", "mask_distance", "mask_decay", "u_convergence_bound",
    "lemma_2_1", "compare_definitions", "symbol_identities", "property_a", "property_a_structure",
    "property_a_table", "blended_example",
    "junction_smoothness", "circle_polygon", "hyperbola_polygon", "parabola_polygon",
    "reproduce", "chamfer_polygon", "chamfer_example", "plot_blended", "plot_chamfer",
    "ARITHMETICS", "RULES",
]

ARITHMETICS = ("float", "mp", "iv", "exact")
RULES = ("seed001", "seed000")


# --------------------------------------------------------------------------------------------
# arithmetics
# --------------------------------------------------------------------------------------------

class _ivprec:
    def __init__(self, prec: int):
        self.prec = prec

    def __enter__(self):
        self.saved = mpmath.iv.prec
        mpmath.iv.prec = self.prec

    def __exit__(self, *exc):
        mpmath.iv.prec = self.saved
        return False


_SYMPY_SQRT = np.frompyfunc(sp.sqrt, 1, 1)


class _Arith:
    """A number context: conversion of inputs, a vectorised square root, a precision scope."""

    def __init__(self, name: str, prec: int = 113):
        if name not in ARITHMETICS:
            raise AnalysisError(f"unknown arithmetic {name!r}; use one of {', '.join(ARITHMETICS)}")
        if not isinstance(prec, int) or prec < 24:
            raise AnalysisError("prec must be an integer number of bits >= 24")
        self.name, self.prec = name, prec
        if name == "float":
            self.sqrt = np.sqrt
        elif name == "mp":
            self.sqrt = np.frompyfunc(mpmath.mp.sqrt, 1, 1)
        elif name == "iv":
            self.sqrt = np.frompyfunc(mpmath.iv.sqrt, 1, 1)
        else:
            self.sqrt = _SYMPY_SQRT

    def scope(self):
        if self.name == "mp":
            return mpmath.workprec(self.prec)
        if self.name == "iv":
            return _ivprec(self.prec)
        import contextlib

        return contextlib.nullcontext()

    def scalar(self, x):
        if isinstance(x, (bool, np.bool_)):
            raise AnalysisError(f"value {x!r} is not a number")
        if self.name == "float":
            try:
                f = float(x)
            except (TypeError, ValueError):
                raise AnalysisError(f"value {x!r} is not a real number") from None
            if not math.isfinite(f):
                raise AnalysisError("the data or parameters contain NaN or infinite values")
            return f
        if isinstance(x, str):
            x = sp.sympify(x, rational=True)
        if self.name == "exact":
            if isinstance(x, float):
                if not math.isfinite(x):
                    raise AnalysisError("the data or parameters contain NaN or infinite values")
                return sp.Rational(x)
            if isinstance(x, Fraction):
                return sp.Rational(x.numerator, x.denominator)
            if isinstance(x, np.generic):
                x = x.item()
            e = sp.sympify(x)
            if not e.is_real or e.free_symbols:
                raise AnalysisError(f"exact arithmetic needs real numbers, not {x!r}")
            return e
        ctx = mpmath.mp if self.name == "mp" else mpmath.iv
        if isinstance(x, Fraction):
            return ctx.mpf(x.numerator) / x.denominator
        if isinstance(x, sp.Basic):
            if x.is_Rational:
                return ctx.mpf(int(x.p)) / int(x.q)
            if self.name == "iv":
                from ..algebra.algebraic import enclose

                return enclose(x, self.prec)
            return ctx.mpf(sp.N(x, int(self.prec * 0.31) + 5))
        if isinstance(x, np.generic):
            x = x.item()
        if isinstance(x, float) and not math.isfinite(x):
            raise AnalysisError("the data or parameters contain NaN or infinite values")
        return ctx.mpf(x)

    def array(self, xs) -> np.ndarray:
        arr = np.asarray(xs, dtype=object)
        flat = [self.scalar(x) for x in arr.ravel()]
        if self.name == "float":
            return np.array(flat, dtype=float).reshape(arr.shape)
        out = np.empty(len(flat), dtype=object)
        out[:] = flat
        return out.reshape(arr.shape)


def _check_degree(degree) -> int:
    if isinstance(degree, bool) or not isinstance(degree, (int, np.integer)) or degree < 2:
        raise AnalysisError(f"the NVPS degree must be an integer >= 2 (the papers define d >= 2), not {degree!r}")
    if degree > 64:
        raise AnalysisError("the NVPS degree must be at most 64")
    return int(degree)


def _check_rule(rule: str) -> str:
    if rule not in RULES:
        raise AnalysisError(f"unknown NVPS rule {rule!r}; use 'seed001' (rules (2)-(6), Algorithm 1) or 'seed000'")
    return rule


def _tau(d: int) -> int:
    """Seed 000's shift tau_d = ceil((d-2)/2)."""
    return (d - 1) // 2


def _half_update(v, sqrt, exact: bool = False):
    """``1 - sqrt((1+u)/2)`` from ``v = 1 - u``, without cancellation (exact arithmetic: the
    direct form, which sympy simplifies better)."""
    if exact:
        return 1 - sqrt(1 - v / 2)
    return (v / 2) / (1 + sqrt(1 - v / 2))


# --------------------------------------------------------------------------------------------
# the scheme and one step
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class NVPS:
    """The non-uniform variable-parameter scheme of degree ``d`` (a scheme *family*: its masks
    depend on the parameter sequence, hence on level and location).

    >>> NVPS(3)
    NVPS(degree=3, rule='seed001')
    >>> NVPS(4).limit_symbol().mask
    (1/16, 5/16, 5/8, 5/8, 5/16, 1/16)
    """

    degree: int
    rule: str = "seed001"

    def __post_init__(self):
        _check_degree(self.degree)
        _check_rule(self.rule)

    def refine(self, points, u=None, *, steps: int = 1, closed: bool = False, **kw) -> "Refinement":
        """:func:`refine` with this degree and rule."""
        return refine(points, u, degree=self.degree, steps=steps, closed=closed, rule=self.rule, **kw)

    def limit_symbol(self):
        """The limit (u = 1) mask ``z^{-d}(1+z)^{d+1}/2^d`` as a :class:`LaurentSymbol`."""
        return limit_mask(self.degree)


@dataclass(frozen=True)
class Refinement:
    """Refined points and the parameters of their edges (``v = 1 - u``), after ``level`` steps."""

    points: np.ndarray
    one_minus_u: np.ndarray
    level: int
    degree: int
    closed: bool
    rule: str
    arithmetic: str = "float"
    prec: int = 53
    provenance: dict = field(default_factory=dict)

    @property
    def u(self) -> np.ndarray:
        return 1 - self.one_minus_u


def step(points: np.ndarray, one_minus_u: np.ndarray, degree: int, *, closed: bool = False,
         rule: str = "seed001", sqrt=np.sqrt) -> tuple[np.ndarray, np.ndarray]:
    """One NVPS step on arrays already in one arithmetic (float64 or object); returns the new
    points and the ``v = 1 - u`` of the new edges.

    >>> P = np.array([0., 1., 3.])
    >>> Q, v = step(P, np.array([0., 0.]), 2)          # u = 1: Chaikin on 3 points
    >>> Q.tolist(), v.tolist()
    ([0.25, 0.75, 1.5, 2.5], [0.0, 0.0, 0.0])
    """
    d = degree
    n = points.shape[0]
    edges = n if closed else n - 1
    h = 1 / (2 * (2 - one_minus_u))
    if points.ndim == 2:
        h = h[:, None]
    A = points[:edges]
    B = np.roll(points, -1, axis=0) if closed else points[1:]
    Q = np.empty((2 * edges,) + points.shape[1:], dtype=points.dtype)
    Q[0::2] = A + h * (B - A)
    Q[1::2] = B + h * (A - B)
    for _ in range(d - 2):
        Q = (Q + np.roll(Q, -1, axis=0)) / 2 if closed else (Q[:-1] + Q[1:]) / 2
    if rule == "seed000" and closed:
        Q = np.roll(Q, _tau(d), axis=0)
    v_new = _half_update(one_minus_u, sqrt, exact=points.dtype == object and sqrt is _SYMPY_SQRT)
    new_edges = Q.shape[0] if closed else Q.shape[0] - 1
    j = np.arange(new_edges)
    src = _sources(j, d, closed, rule, edges)
    return Q, v_new[src]


def _sources(j: np.ndarray, d: int, closed: bool, rule: str, old_edges: int) -> np.ndarray:
    """Old edge from which new edge ``j`` inherits its parameter."""
    if rule == "seed001":
        src = (j + (d - 2) // 2 + 1) // 2
    elif closed:
        src = j // 2
    else:
        src = (j + _tau(d)) // 2
    return src % old_edges if closed else src


def parameter_from_angle(theta, kind: str = "trigonometric", arithmetic: str = "float", prec: int = 113):
    """``v = 1 - u`` for ``u = cos(theta)`` (``kind="trigonometric"``) or ``u = cosh(theta)``
    (``"hyperbolic"``), computed as ``2 sin^2(theta/2)`` / ``-2 sinh^2(theta/2)`` (no cancellation).

    >>> f"{parameter_from_angle(1e-8):.6e}"         # 1 - cos(1e-8) = 5e-17, not 0
    '5.000000e-17'
    >>> round(float(parameter_from_angle(1, "hyperbolic", "mp")), 14)
    -0.54308063481524
    """
    ctx = _Arith(arithmetic, prec)
    if kind not in ("trigonometric", "hyperbolic"):
        raise AnalysisError("kind must be 'trigonometric' or 'hyperbolic'")
    with ctx.scope():
        t = ctx.scalar(theta)
        if arithmetic == "float":
            s = math.sin(t / 2) if kind == "trigonometric" else math.sinh(t / 2)
            return (2 if kind == "trigonometric" else -2) * s * s
        if arithmetic == "exact":
            s = sp.sin(t / 2) if kind == "trigonometric" else sp.sinh(t / 2)
            return (2 if kind == "trigonometric" else -2) * s ** 2
        c = mpmath.mp if arithmetic == "mp" else mpmath.iv
        s = c.sin(t / 2) if kind == "trigonometric" else c.sinh(t / 2)
        return (2 if kind == "trigonometric" else -2) * s * s


def angle_from_parameter(u) -> tuple[str, float]:
    """``("trigonometric", theta)`` with ``u = cos theta`` for ``-1 < u <= 1``, else
    ``("hyperbolic", theta)`` with ``u = cosh theta``.

    >>> angle_from_parameter(0.5)
    ('trigonometric', 1.0471975511965979)
    """
    u = float(u)
    if not u > -1:
        raise AnalysisError(f"tension parameter u = {u} must be > -1 (the papers take u > 0)")
    return ("trigonometric", math.acos(u)) if u <= 1 else ("hyperbolic", math.acosh(u))


def _prepare(points, u, one_minus_u, closed: bool, ctx: _Arith, degree: int):
    P = ctx.array(points)
    if P.ndim not in (1, 2) or P.shape[0] == 0:
        raise AnalysisError("points must be an array of shape (n,) or (n, dim) with n >= 1")
    n = P.shape[0]
    edges = n if closed else n - 1
    if (u is None) == (one_minus_u is None):
        raise AnalysisError("give the edge parameters as exactly one of u=... or one_minus_u=...")
    if one_minus_u is not None:
        v = ctx.array(np.atleast_1d(np.asarray(one_minus_u, dtype=object)))
    else:
        uu = np.atleast_1d(np.asarray(u, dtype=object))
        if uu.ndim == 1 and len(uu) == 1 and edges != 1:
            uu = np.repeat(uu, max(edges, 1))
        v = 1 - ctx.array(uu)
    if v.ndim != 1 or len(v) != edges:
        raise AnalysisError(f"{'a closed' if closed else 'an open'} polygon of {n} points has {edges} edges: "
                            f"give {edges} edge parameters, not {v.size}")
    for x in v:
        lo = x.a if ctx.name == "iv" else x
        if not (2 - lo > 0):
            raise AnalysisError(f"every tension parameter must satisfy u > -1 (the papers take u > 0); got u = {1 - x}")
    if not closed and 2 * edges - (degree - 2) < 1:
        raise AnalysisError(f"an open polygon needs at least {degree // 2 + 2 - (1 if degree % 2 else 0)} points "
                            f"for one step of degree {degree}")
    if closed and n < 2:
        raise AnalysisError("a closed polygon needs at least 2 points")
    return P, v


def refine(points, u=None, *, degree: int = 2, steps: int = 1, closed: bool = False, rule: str = "seed001",
           arithmetic: str = "float", prec: int = 113, one_minus_u=None) -> Refinement:
    """Apply ``steps`` NVPS steps of degree ``degree`` to a polygon with one parameter per edge.

    ``u`` is a sequence (one per edge; a single value is repeated) or give ``one_minus_u`` for
    full accuracy near ``u = 1``. ``points`` has shape ``(n,)`` or ``(n, dim)``.

    >>> r = refine([0, 1, 2, 3], [1, 1, 1], degree=3, steps=2)     # u = 1: cubic B-spline
    >>> r.points.tolist()                  # linear data stay linear
    [0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25]
    >>> from fractions import Fraction
    >>> r = refine([0, 1, 0], [Fraction(1, 2), 7], degree=2, arithmetic="exact")
    >>> r.points.tolist(), r.u.tolist()
    ([1/3, 2/3, 15/16, 1/16], [sqrt(3)/2, 2, 2])

    Raises :class:`AnalysisError` for a degree < 2, u <= -1, a wrong number of parameters, or an
    open polygon too short for one step.
    """
    d = _check_degree(degree)
    _check_rule(rule)
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 0 or steps > 40:
        raise AnalysisError("steps must be an integer between 0 and 40")
    ctx = _Arith(arithmetic, prec)
    with ctx.scope():
        P, v = _prepare(points, u, one_minus_u, closed, ctx, d)
        for k in range(steps):
            if not closed and 2 * (P.shape[0] - 1) - (d - 2) < 2:
                raise AnalysisError(f"the open polygon became too short after {k} steps (degree {d})")
            P, v = step(P, v, d, closed=closed, rule=rule, sqrt=ctx.sqrt)
    return Refinement(points=P, one_minus_u=v, level=int(steps), degree=d, closed=closed, rule=rule,
                      arithmetic=arithmetic, prec=53 if arithmetic == "float" else prec,
                      provenance={"method": "NVPS refinement, vectorised", "rule": rule})


# --------------------------------------------------------------------------------------------
# masks a^{k,j}, the limit mask, distances
# --------------------------------------------------------------------------------------------

def limit_mask(degree: int):
    """The limit mask ``a(z) = z^{-d}(1+z)^{d+1}/2^d`` (uniform B-spline of degree d).

    >>> limit_mask(2)
    LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
    """
    from ..algebra.symbol import LaurentSymbol

    d = _check_degree(degree)
    return LaurentSymbol.from_mask([sp.Rational(math.comb(d + 1, t), 2 ** d) for t in range(d + 2)], start=-d)


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


# --------------------------------------------------------------------------------------------
# convergence of u^k (Lemma 2.1) and decay of the masks
# --------------------------------------------------------------------------------------------

def _arb_to_iv(x):
    """A python-flint ``arb`` ball as an ``mpmath.iv`` interval (outward)."""
    iv = mpmath.iv
    m, e = x.mid().man_exp()
    r, re_ = x.rad().man_exp()
    two = iv.mpf(2)
    mid = iv.mpf(int(m)) * two ** int(e)
    rad = iv.mpf(int(r)) * two ** int(re_)
    lo, hi = mid - rad, mid + rad
    return iv.mpf([lo.a, hi.b])


def _arb_point(t):
    """An exact arb for a mpf endpoint."""
    import flint

    x = mpmath.mpf(t)
    man, exp = x.man_exp
    sign = -1 if x < 0 else 1
    return sign * flint.arb(int(man)) * flint.arb(2) ** int(exp)


def _iv_monotone(x, name: str, increasing: bool):
    """Rigorous enclosure of the monotone Arb function ``name`` over the interval ``x``."""
    import flint

    old = flint.ctx.prec
    flint.ctx.prec = max(old, mpmath.iv.prec + 10)
    try:
        ends = (x.a, x.b) if increasing else (x.b, x.a)
        lo = _arb_to_iv(getattr(_arb_point(ends[0]), name)())
        hi = _arb_to_iv(getattr(_arb_point(ends[1]), name)())
    finally:
        flint.ctx.prec = old
    return mpmath.iv.mpf([lo.a, hi.b])


def _iv_acos(x):
    """Rigorous enclosure of arccos over the interval ``x`` (decreasing), via Arb."""
    return _iv_monotone(x, "acos", increasing=False)


def _iv_acosh(x):
    """Rigorous enclosure of arccosh over ``x >= 1`` (increasing), via Arb."""
    return _iv_monotone(x, "acosh", increasing=True)


def _limit_constant_iv(u0, prec: int):
    """Enclosure of ``lim 4^k (1 - u^k)``: ``arccos(u0)^2/2`` (u0 <= 1) or ``-arccosh(u0)^2/2``."""
    with _ivprec(prec):
        x = _Arith("iv", prec).scalar(u0)
        if x.b <= 1:
            return _iv_acos(x) ** 2 / 2
        if x.a >= 1:
            return -(_iv_acosh(x) ** 2) / 2
        raise AnalysisError("u0 enclosure straddles 1; give an exact value")


def _endpoint_rational(x, side: str, digits: int | None = 30) -> sp.Rational:
    """An interval end point as an exact Rational, rounded *outward*: ``side="lower"`` rounds
    down, ``side="upper"`` rounds up (to ``digits`` significant decimals; ``None``: the exact
    binary value). Never round-to-nearest.

    >>> import mpmath
    >>> iv = mpmath.iv.mpf([1, 1]) / 3
    >>> lo, hi = _endpoint_rational(iv, "lower", 5), _endpoint_rational(iv, "upper", 5)
    >>> lo, hi, lo <= sp.Rational(1, 3) <= hi
    (33333/100000, 16667/50000, True)
    """
    if side not in ("lower", "upper"):
        raise ValueError("side must be 'lower' or 'upper'")
    if hasattr(x, "_mpi_"):                       # an mpmath.iv interval: take its end point
        raw = x._mpi_[0 if side == "lower" else 1]
    elif hasattr(x, "_mpf_"):
        raw = x._mpf_
    else:
        raw = mpmath.mpf(x)._mpf_
    if raw in (mpmath.libmp.finf, mpmath.libmp.fninf, mpmath.libmp.fnan):
        raise AnalysisError("an interval end point is not finite; raise the precision")
    p_, q_ = mpmath.libmp.to_rational(raw)
    exact = sp.Rational(int(p_), int(q_))
    if digits is None or exact == 0:
        return exact
    e = int(sp.floor(sp.log(abs(exact), 10))) if abs(exact) >= 1 else -len(str(int(1 / abs(exact))))
    scale = sp.Integer(10) ** (digits - 1 - e)
    n = exact * scale
    n = sp.floor(n) if side == "lower" else sp.ceiling(n)
    return sp.Rational(int(n)) / scale


def _decimal_text(r: sp.Rational) -> str:
    """The exact decimal expansion of a rational whose denominator divides a power of 10."""
    r = sp.Rational(r)
    q = int(r.q)
    s = 0
    while (10 ** s) % q:
        s += 1
        if s > 400:
            return sp.sstr(r)
    n = int(r * 10 ** s)
    sign, n = ("-" if n < 0 else ""), abs(n)
    if s == 0:
        return f"{sign}{n}"
    txt = str(n).rjust(s + 1, "0")
    return f"{sign}{txt[:-s]}.{txt[-s:]}".rstrip("0").rstrip(".")


def u_convergence_bound(u0_low, u0_high, *, levels: int = 60, prec: int = 128) -> Result:
    """Certified: for every ``u^0`` in ``[u0_low, u0_high]`` (``> -1``) and every ``k >= 0``,
    ``|1 - u^k| <= C 4^{-k}``, and ``4^k (1 - u^k)`` converges to ``arccos(u0)^2/2`` (u0 <= 1) or
    ``-arccosh(u0)^2/2`` (u0 >= 1) — the true rate is ``4^{-k}``, not the ``2^{-k}`` used in
    seed 001's proof of Theorem 3.6.

    >>> r = u_convergence_bound(0.5, 2, levels=20)
    >>> r.status, round(float(r.value), 6)          # C = max(acos(1/2)^2/2, 2 - 1)
    ('certified', 1.0)

    Algorithm
    ---------
    Analytic, for all k: ``u0 = cos(theta)``, ``0 <= theta < pi``: ``u^k = cos(theta/2^k)`` and
    ``1 - u^k = 2 sin^2(theta/2^{k+1}) <= theta^2 4^{-k}/2``. ``u0 = cosh(theta)``:
    ``u^k - 1 = 2 sinh^2(theta/2^{k+1}) <= 2 sinh^2(theta/2) 4^{-k} = (u0 - 1) 4^{-k}`` since
    ``sinh(x/2^k) <= sinh(x)/2^k`` (convexity). Both bounds are monotone in ``u0``, so the range's
    constant is attained at an end point; it is enclosed with ``mpmath.iv``. The recursion is
    also run in interval arithmetic for ``k <= levels`` as a consistency check (an enclosure of
    ``4^k |1-u^k|`` at both ends must stay below the constant).
    """
    lo_in, hi_in = float(u0_low), float(u0_high)
    if not (lo_in > -1) or not (hi_in >= lo_in) or not math.isfinite(hi_in):
        raise AnalysisError("need -1 < u0_low <= u0_high < oo")
    ctx = _Arith("iv", prec)
    iv = mpmath.iv
    with ctx.scope():
        a, b = ctx.scalar(u0_low), ctx.scalar(u0_high)
        parts = []
        if a.a < 1:
            parts.append(_iv_acos(iv.mpf([a.a, min(a.b, 1)])) ** 2 / 2)
        if b.b > 1:
            parts.append(b - 1)
        C = parts[0] if len(parts) == 1 else iv.mpf([max(p.a for p in parts), max(p.b for p in parts)])
        if not parts:
            C = iv.mpf(0)
        table = []
        ok = True
        for u0 in (a, b):
            v = 1 - u0
            for k in range(levels + 1):
                scaled = abs(v) * iv.mpf(4) ** k
                if scaled.a > C.b:  # a certain violation (the bound is approached in the limit)
                    ok = False
                if k in (0, 1, 2, 5, 10, 20, levels):
                    table.append({"u0": str(u0), "k": k, "4^k|1-u^k|": str(scaled)})
                v = _half_update(v, iv.sqrt)
    lim_lo = _limit_constant_iv(u0_low, prec) if lo_in != 1 else iv.mpf(0)
    lim_hi = _limit_constant_iv(u0_high, prec) if hi_in != 1 else iv.mpf(0)
    C_up = _endpoint_rational(C, "upper")      # exact Rational, rounded up (never to nearest)
    return Result(value=C_up, lower=None, upper=C_up,
                  status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"bound": "sup_k 4^k |1 - u^k| <= C", "C_enclosure": str(C),
                           "limit_at_low": str(lim_lo), "limit_at_high": str(lim_hi),
                           "interval_recursion_check": table, "recursion_consistent": ok},
                  provenance={"method": "analytic bound (cos/cosh half-angle) + mpmath.iv enclosure; the "
                                        "reported C is the enclosure's upper end point rounded up to a Rational",
                              "prec_bits": prec, "u0_range": [str(u0_low), str(u0_high)]})


def lemma_2_1(u0_low, u0_high, *, levels: int = 60, prec: int = 128) -> Result:
    """Seed 001, Lemma 2.1 on the range ``u^0 in [u0_low, u0_high]``: ``u^k -> 1`` uniformly and
    ``||U^k||_inf <= C max(1, ||U^0||_inf)`` (certified with ``C = 1``), with the rate.

    >>> r = lemma_2_1(0.1, 10)
    >>> r.status, r.value
    ('certified', 1)

    Algorithm
    ---------
    ``phi(u) = sqrt((1+u)/2)`` is increasing with fixed point 1, ``phi(u) < u`` for ``u > 1`` and
    ``u < phi(u) <= 1`` for ``-1 <= u < 1``; so ``max_n u^k_n = phi^k(max u^0)`` and
    ``||U^k|| <= max(1, ||U^0||)`` for every k (the lemma with C = 1, exact), and
    ``sup_n |1 - u^k_n| <= C' 4^{-k}`` (:func:`u_convergence_bound`). The monotonicity is checked in
    interval arithmetic at both ends for ``k <= levels``.
    """
    bound = u_convergence_bound(u0_low, u0_high, levels=levels, prec=prec)
    iv = mpmath.iv
    ok = bound.status == CERTIFIED
    with _ivprec(prec):
        a, b = _Arith("iv", prec).scalar(u0_low), _Arith("iv", prec).scalar(u0_high)
        norm0 = iv.mpf([max(abs(a).b, abs(b).b), max(abs(a).b, abs(b).b)])
        hi = b
        for k in range(levels + 1):
            if hi.b > max(1, norm0.b) and not (hi.a <= 1 <= hi.b):
                ok = False
            hi = iv.sqrt((1 + hi) / 2)
    return Result(value=1, status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"C": 1, "rate": "sup_n |1-u^k_n| <= C' 4^-k", "C'": bound.witness["C_enclosure"],
                           "limits": [bound.witness["limit_at_low"], bound.witness["limit_at_high"]],
                           "note": "needs u0 > -1 for the real square root; the papers assume u0 > 0"},
                  provenance={"method": "monotonicity of phi + interval check", "prec_bits": prec})


def mask_decay(u0, degree: int = 2, *, levels: int = 12, closed: bool = False, rule: str = "seed001",
               prec: int = 128) -> Result:
    """``sup_j ||S^{k} - S_a||_inf`` (operator rows) for ``k = 0..levels`` starting from the edge
    parameters ``u0``; certified enclosure ``[c_d max_pure |delta|, 2 max_e |delta^k_e|]`` and the
    ratio of consecutive levels (-> 1/4) and ``4^k sup_j`` (-> ``max_e |arccos or arccosh(u0_e)|^2/8``
    times ``c_d``).

    >>> r = mask_decay([0.5, 0.5], degree=2, levels=6)
    >>> r.status, [round(x, 4) for x in r.witness["ratios"][-2:]]
    ('certified', [0.2499, 0.25])
    >>> r.lower <= r.upper, type(r.upper).__name__      # exact end points, rounded outward
    (True, 'Rational')

    Algorithm
    ---------
    Descendants of an edge share its parameter, so level k has finitely many distinct values
    ``delta^k_e = v/(4(2-v))`` (enclosed by iterating the cancellation-free update in
    ``mpmath.iv``). ``a^{k,i} - a = sum_l w_l z^{-l} delta_{e(i+l)} z^{-2}(1-z)^2(1+z)`` gives the
    upper bound (``||z^{-2}(1-z)^2(1+z)||`` per parity is 2); a location whose window has one
    parameter attains ``c_d |delta|`` exactly (:func:`_pure_constant`). Which windows are pure
    is decided with the integer ancestry of the edges (exact). The exact sup over all locations
    is also evaluated in floats (``witness["float_sup"]``).
    """
    d = _check_degree(degree)
    _check_rule(rule)
    u0 = list(np.atleast_1d(np.asarray(u0, dtype=object)))
    if levels < 0 or levels > 30:
        raise AnalysisError("levels must be between 0 and 30")
    ctx = _Arith("iv", prec)
    c_d = _pure_constant(d)
    iv = mpmath.iv
    rows, ratios, scaled, bounds = [], [], [], []
    consistent = True
    with ctx.scope():
        v = [1 - ctx.scalar(x) for x in u0]
        for x in v:
            if not (2 - x).a > 0:
                raise AnalysisError("every u0 must be > -1")
        anc = np.arange(len(u0))
        prev_hi = None
        for k in range(levels + 1):
            delta = [x / (4 * (2 - x)) for x in v]
            absd = [abs(x) for x in delta]
            # pure windows: S_2 points i..i+d-2 from one ancestor
            edges = len(anc)
            nq = 2 * edges
            count = nq if closed else nq - (d - 2)
            idx = np.arange(count)
            first = anc[((idx) % nq if closed else idx) // 2]
            pure = np.ones(count, dtype=bool)
            for l in range(1, d - 1):
                q = (idx + l) % nq if closed else idx + l
                pure &= anc[q // 2] == first
            pure_anc = {par: sorted(set(first[pure & (idx % 2 == par)].tolist())) for par in (0, 1)}
            up = 2 * max(x.b for x in absd)
            lo_iv = iv.mpf(0)
            for par in (0, 1):
                cp = _pure_constant(d, par)
                for a_ in pure_anc[par]:
                    cand = iv.mpf(cp.numerator) / cp.denominator * absd[a_]
                    if cand.a > lo_iv.a:
                        lo_iv = cand
            # float sup over all locations (descendant values)
            if edges <= 2 ** 18:
                vk = np.array([float(mpmath.mpf(x.mid)) for x in v])[anc]
                fs = mask_distance(one_minus_u=vk, degree=d, closed=closed)["operator"]
            else:
                fs = None
            lo_q = _endpoint_rational(lo_iv, "lower")            # outward: lower end rounded down
            up_q = _endpoint_rational(iv.mpf(up), "upper")       # upper end rounded up
            consistent &= bool(0 <= lo_q <= up_q)
            bounds.append((lo_q, up_q))
            rows.append({"k": k, "lower": _decimal_text(lo_q), "upper": _decimal_text(up_q),
                         "float_sup": fs,
                         "pure_windows": bool(pure_anc[0] or pure_anc[1])})
            scaled.append(float(mpmath.mpf(up)) * 4 ** k)
            if prev_hi is not None:
                ratios.append(float(mpmath.mpf(up)) / prev_hi)
            prev_hi = float(mpmath.mpf(up))
            # next level
            v = [_half_update(x, iv.sqrt) for x in v]
            j = np.arange(count if closed else count - 1)
            anc = anc[_sources(j, d, closed, rule, edges)]
    s_lim = max(abs(float(mpmath.mpf(_limit_constant_iv(x, 64).mid))) if float(x) != 1 else 0.0 for x in u0)
    pos = [(k, lo * 4 ** k) for k, (lo, _) in enumerate(bounds) if lo > 0]
    scaled_lo = min(x for _, x in pos) if pos else sp.Integer(0)
    scaled_hi = max(up * 4 ** k for k, (_, up) in enumerate(bounds))
    return Result(value=None, lower=bounds[-1][0], upper=bounds[-1][1],
                  status=CERTIFIED if consistent else INCONCLUSIVE,
                  witness={"levels": rows, "ratios": ratios, "scaled_4k_upper": scaled,
                           "c_d": str(c_d), "predicted_limit_4k_upper": s_lim / 4,
                           "certified_4k_bounds": {"min_k 4^k lower_k": scaled_lo, "max_k 4^k upper_k": scaled_hi,
                                                   "levels_with_positive_lower": [k for k, _ in pos],
                                                   "k_range": [0, levels]},
                           "rate": ("c 4^-k <= sup_j ||S^k - S_a|| <= C 4^-k on k = 0..levels (certified "
                                    "end points)" if pos and len(pos) == len(bounds) else
                                    "upper bound C 4^-k on k = 0..levels (certified end points)"),
                           "ratios_note": "float quotients of consecutive upper bounds (an observation)"},
                  provenance={"method": "interval enclosures of delta^k_e + exact ancestry", "prec_bits": prec,
                              "degree": d, "rule": rule, "closed": closed})


# --------------------------------------------------------------------------------------------
# seed 000 vs seed 001
# --------------------------------------------------------------------------------------------

def _chebyshev_rational_params(rng, count: int, levels: int, hyperbolic_share: float = 0.5):
    """Rational u^0 whose square-root updates stay rational for ``levels`` steps:
    ``u^0 = T_{2^levels}(r)`` with rational ``r`` (then ``u^k = T_{2^{levels-k}}(r)``)."""
    out = []
    for _ in range(count):
        if rng.random() < hyperbolic_share:
            r = Fraction(int(rng.integers(101, 130)), 100)
        else:
            r = Fraction(int(rng.integers(990, 1000)), 1000)
        u = r
        for _ in range(levels):
            u = 2 * u * u - 1
        out.append(u)
    return out


class _SymbolicRuns:
    """Both rules on *symbolic* data ``Q_i`` and symbolic edge parameters ``v_e = 1 - u_e``
    (the engine's :func:`step` on sympy object arrays, exact square-root update), computed on
    demand: ``run(rule, steps)``, and seed 001 on the reversed polygon, reversed back."""

    def __init__(self, d: int, n: int, closed: bool):
        self.d, self.closed = d, closed
        edges = n if closed else n - 1
        self.Q = np.empty(n, dtype=object)
        self.Q[:] = sp.symbols(f"Q0:{n}")
        self.V = np.empty(edges, dtype=object)
        self.V[:] = sp.symbols(f"v0:{edges}", positive=True)

    def run(self, rule: str, steps: int, reverse: bool = False):
        P, v = (self.Q[::-1].copy(), self.V[::-1].copy()) if reverse else (self.Q, self.V)
        for _ in range(steps):
            P, v = step(P, v, self.d, closed=self.closed, rule=rule, sqrt=_SYMPY_SQRT)
        return list(P[::-1]) if reverse else list(P)


def _same_symbolic(xs, ys) -> bool:
    """Exact: the two lists of expressions are identical (equal trees, or the difference expands
    to 0). ``False`` may be a failure to simplify, never a proof of difference."""
    if len(xs) != len(ys):
        return False
    return all(a == b or sp.expand(a - b) == 0 for a, b in zip(xs, ys))


def compare_definitions(degree: int, *, levels: int = 3, points: int = 7, seed: int = 1,
                        closed: bool = False) -> Result:
    """Are seed 000's and seed 001's S_d the same scheme? Certified "same" parts come from a
    symbolic run (symbolic data ``Q_i`` and edge parameters ``v_e``, the engine's step on sympy
    objects, exact square roots: the differences expand to 0), "different" parts from an exact
    counterexample; if a "same" part is seen only on the rational example the status is
    ``numerical``.

    Checks, for random rational data and rational Chebyshev parameters (square-root updates stay
    rational), with exact sympy arithmetic, and again symbolically:

    * ``data``: one step with the same edge parameters — seed 000's points equal seed 001's
      shifted by ``tau_d = ceil((d-2)/2)`` (identical arrays for open polygons, a cyclic shift by
      ``tau_d`` for closed ones); symbolically the binomial sum is the unrolled recursion (6);
    * ``levels``: ``levels`` steps with each paper's parameter inheritance; equal for odd d,
      different for even d (then seed 000 equals seed 001 applied to the *reversed* polygon,
      reversed back — a mirror image).

    >>> compare_definitions(3, levels=2).value
    'same scheme up to the index shift tau_d = 1'
    >>> compare_definitions(2, levels=2).value
    'same data rule (shift tau_d = 0), different parameter inheritance: mirror images'
    """
    d = _check_degree(degree)
    rng = np.random.default_rng(seed)
    n = points
    edges = n if closed else n - 1
    data = [Fraction(int(x), int(y)) for x, y in zip(rng.integers(-50, 50, n), rng.integers(1, 9, n))]
    u0 = _chebyshev_rational_params(rng, edges, levels)
    tau = _tau(d)
    # symbolic identity of the data rule: recursion (6) unrolled == binomial sum (seed 000) shifted
    Qs = sp.symbols(f"Q0:{d + 4}")
    rec = list(Qs)
    for _ in range(d - 2):
        rec = [(rec[i] + rec[i + 1]) / 2 for i in range(len(rec) - 1)]
    binom = [sum(sp.Rational(math.comb(d - 2, l), 2 ** (d - 2)) * Qs[i + l] for l in range(d - 1))
             for i in range(len(rec))]
    symbolic_ok = all(sp.expand(a - b) == 0 for a, b in zip(rec, binom))
    one = {r: refine(data, u0, degree=d, steps=1, closed=closed, rule=r, arithmetic="exact") for r in RULES}
    p1, p0 = one["seed001"].points, one["seed000"].points
    same_one_step = list(p0) == (list(np.roll(p1, tau)) if closed else list(p1))
    many = {r: refine(data, u0, degree=d, steps=levels, closed=closed, rule=r, arithmetic="exact") for r in RULES}
    m1, m0 = many["seed001"].points, many["seed000"].points
    shift_total = tau * (2 ** levels - 1)
    if closed:
        same_levels = list(m0) == list(np.roll(m1, shift_total % len(m1)))
    else:
        same_levels = list(m0) == list(m1)
    # mirror: seed 000 on P == reverse(seed 001 on reverse(P)) (open polygons)
    mirror = None
    if not closed:
        mr = refine(data[::-1], u0[::-1], degree=d, steps=levels, rule="seed001", arithmetic="exact")
        mirror = list(m0) == list(mr.points[::-1])
    first_diff = None
    if not same_levels:
        m1 = np.roll(m1, shift_total % len(m1)) if closed else m1
        for i, (a, b) in enumerate(zip(m0, m1)):
            if a != b:
                first_diff = {"index": i, "seed000": str(a), "seed001": str(b), "difference": str(sp.Rational(a) - sp.Rational(b)) if a.is_Rational and b.is_Rational else str(a - b)}
                break
    # the symbolic proof: symbolic data Q_i and parameters v_e, the engine's step on both rules
    # (only the parts the rational example leaves standing: a proof of "same" is attempted where it
    # could hold; "different" is settled by the exact counterexample)
    S = _SymbolicRuns(d, n, closed)

    def rolled(xs, t):
        return list(np.roll(np.array(xs, dtype=object), t % len(xs))) if closed else xs

    sym_one = _same_symbolic(S.run("seed000", 1), rolled(S.run("seed001", 1), tau)) if same_one_step else None
    sym_levels = (_same_symbolic(S.run("seed000", levels), rolled(S.run("seed001", levels), shift_total))
                  if same_levels else None)
    sym_mirror = (None if closed or not mirror else
                  _same_symbolic(S.run("seed000", levels), S.run("seed001", levels, reverse=True)))
    # each part of the verdict: "same" needs the symbolic proof, "different" the exact counterexample
    data_rule_proved = bool(symbolic_ok and sym_one)
    if same_one_step and same_levels:
        verdict = f"same scheme up to the index shift tau_d = {tau}"
        certified = data_rule_proved and sym_levels
    elif same_one_step and mirror:
        verdict = f"same data rule (shift tau_d = {tau}), different parameter inheritance: mirror images"
        certified = data_rule_proved and bool(sym_mirror)
    elif same_one_step:
        verdict = f"same data rule (shift tau_d = {tau}), different parameter inheritance"
        certified = data_rule_proved
    else:
        verdict = "different data rules"
        certified = True                         # the exact rational counterexample (first_difference)
    if not same_one_step:
        first_diff = first_diff or {"note": "one-step points differ (exact rational data)"}
    return Result(value=verdict, status=CERTIFIED if certified else NUMERICAL,
                  witness={"symbolic_recursion_equals_binomial": symbolic_ok,
                           "symbolic_one_step_equal": sym_one, "symbolic_multi_level_equal": sym_levels,
                           "symbolic_mirror": sym_mirror,
                           "symbolic_scope": f"symbolic data Q_0..Q_{n - 1} and parameters v_e = 1 - u_e, "
                                             f"{'closed' if closed else 'open'} polygon of {n} points, "
                                             f"1 and {levels} steps",
                           "one_step_equal_up_to_shift": same_one_step,
                           "multi_level_equal": same_levels, "seed000_is_mirror_of_seed001": mirror,
                           "first_difference": first_diff, "tau_d": tau, "levels": levels,
                           "data": [str(x) for x in data], "u0": [str(x) for x in u0],
                           "inheritance": {"seed001": "new edge j <- old edge ceil((j + floor((d-2)/2))/2)",
                                           "seed000": "new edge j <- old edge floor(j/2) (own indexing)"}},
                  provenance={"method": "'same': symbolic data and parameters through the engine's step (sympy, "
                                        "differences expand to 0); 'different': an exact rational counterexample "
                                        "(Chebyshev-rational parameters)",
                              "degree": d, "closed": closed, "seed": seed})


# --------------------------------------------------------------------------------------------
# symbol identities (17), Lemma 3.3 algebra, b(z)
# --------------------------------------------------------------------------------------------

def symbol_identities() -> Result:
    """Seed 001's degree-2 symbol (11), ``a(z) = (1 + (1+2u)z + (1+2u)z^2 + z^3)/(2(1+u)z)``: its
    values at ``z = 1`` (the printed (17) says ``a(1) = 1, a'(1) = 2, a''(1) = 1``), at ``z = -1``,
    ``b(z) = 2a(z)/(1+z)``, and the ratio identity in the proof of Lemma 3.3.

    >>> r = symbol_identities()
    >>> r.witness["differs_from_printed"]
    {'a(1)': True, "a'(1)": True, "a''(1)": True}
    >>> r.status
    'refuted'
    >>> print(r.value)
    a(1) = 2, a'(1) = 1, a''(1) = 2/(u + 1)

    Algorithm
    ---------
    sympy on the generic parameter ``u``; all identities are polynomial/rational identities, so
    ``simplify(lhs - rhs) == 0`` proves them; a printed value that differs is refuted by the exact
    value (for every u for a(1), a'(1); for every u != 1 for a''(1)).
    """
    u, z = sp.symbols("u z")
    a = (1 + (1 + 2 * u) * z + (1 + 2 * u) * z ** 2 + z ** 3) / (2 * (1 + u) * z)
    a1 = sp.simplify(a.subs(z, 1))
    da1 = sp.simplify(sp.diff(a, z).subs(z, 1))
    dda1 = sp.simplify(sp.diff(a, z, 2).subs(z, 1))
    am1 = sp.simplify(a.subs(z, -1))
    dam1 = sp.simplify(sp.diff(a, z).subs(z, -1))
    b = sp.simplify(2 * a / (1 + z))
    b_printed = (1 + 2 * u * z + z ** 2) / (z * (1 + u))
    # rule (3) symbol: h z^-2 + (1-h) z^-1 + (1-h) + h z, h = 1/(2(1+u))
    h = 1 / (2 * (1 + u))
    a_rule3 = h / z ** 2 + (1 - h) / z + (1 - h) + h * z
    shift_ok = sp.simplify(a - z * a_rule3) == 0
    # Lemma 3.3 proof: E^k / E^{k-1} with u_{k-1} = 2u^2 - 1 equals 2 (u/(1+u))^2
    uk = sp.Symbol("u_k", positive=True)
    E = lambda x, k: 2 ** k * (1 - x) / (4 * (1 + x))  # noqa: E731  (sign-free for u < 1)
    ratio = sp.simplify(E(uk, 1) / E(2 * uk ** 2 - 1, 0))
    ratio_ok = sp.simplify(ratio - 2 * (uk / (1 + uk)) ** 2) == 0
    # (12): 2^k max(|1/(2(1+u)) - 1/4|, |(1+2u)/(2(1+u)) - 3/4|) = 2^{k-2}|1-u|/(1+u)
    e12 = [sp.simplify(1 / (2 * (1 + u)) - sp.Rational(1, 4) - (1 - u) / (4 * (1 + u))),
           sp.simplify((1 + 2 * u) / (2 * (1 + u)) - sp.Rational(3, 4) + (1 - u) / (4 * (1 + u)))]
    printed = {"a(1)": 1, "a'(1)": 2, "a''(1)": 1}
    found = {"a(1)": a1, "a'(1)": da1, "a''(1)": dda1}
    # exact comparison, generic u: a printed value that differs from the exact rational function
    mismatch = {k: sp.simplify(found[k] - printed[k]) != 0 for k in printed}
    refuted = any(mismatch.values())
    if refuted:
        note = ("(17) as printed is refuted (exact, generic u): "
                + "; ".join(f"{k} = {sp.sstr(found[k])}, printed {printed[k]}" for k in printed if mismatch[k])
                + ". The values depend on the index normalisation: for rule (3)'s symbol (= (11)/z) "
                  "a'(1) = -1, a''(1) = 2 + 4h.")
    else:
        note = "(17) as printed holds (exact, generic u)."
    return Result(value=f"a(1) = {a1}, a'(1) = {da1}, a''(1) = {sp.sstr(dda1)}",
                  status=REFUTED if refuted else CERTIFIED,
                  witness={"printed_(17)": printed, "exact": {k: sp.sstr(v) for k, v in found.items()},
                           "differs_from_printed": mismatch,
                           "a(-1)": sp.sstr(am1), "a'(-1)": sp.sstr(dam1),
                           "b(z)_equals_printed": sp.simplify(b - b_printed) == 0,
                           "b(-1)": sp.sstr(sp.simplify(b_printed.subs(z, -1))),
                           "(11)_is_z_times_rule_(3)": shift_ok,
                           "(12)_identities_hold": all(x == 0 for x in e12),
                           "Lemma3.3_ratio_2(u/(1+u))^2_holds": ratio_ok,
                           "note": note},
                  provenance={"method": "sympy, generic parameter u", "arithmetic": "exact"})


# --------------------------------------------------------------------------------------------
# Property A (Dyn-Levin-Yoon 2014) quantities (13)-(14)
# --------------------------------------------------------------------------------------------

def _falling(x: int, r: int) -> int:
    out = 1
    for t in range(r):
        out *= x - t
    return out


def _property_a_values(D: np.ndarray, start: int, m: int, r: int, z0: int, closed: bool):
    """``d^{(r)}_m(z0)`` at every location ``j`` (``j >= m`` for open polygons) from the mask
    differences ``D`` (the limit mask contributes 0 for r < m at z = 1 and r <= d at z = -1)."""
    count, width = D.shape
    exps = np.arange(width) + start
    total = None
    js = np.arange(count) if closed else np.arange(m, count)
    for i in range(m + 1):
        g = np.array([_falling(int(e + i), r) * (z0 ** int(e + i - r)) if _falling(int(e + i), r) else 0
                      for e in exps], dtype=object)
        rows = (js - i) % count if closed else js - i
        if D.dtype == float:
            part = D[rows].dot(g.astype(float))
        else:
            part = D[rows].dot(g)
        term = (-1) ** i * math.comb(m, i) * part
        total = term if total is None else total + term
    return js, total


def property_a_structure(degree: int, m: int, r: int, z0: int, *, part: str = "full") -> Result:
    """Exact structure of seed 001's (13)-(14) quantity ``d^{(r)}_m(z0)`` for the NVPS of degree d:
    a linear form in ``delta_e = h_e - 1/4`` of the edges around the location. Certified:

    * whether it vanishes identically (then Property A holds trivially for this (m, r, z0));
    * whether it vanishes on constant parameter sequences (``sum of coefficients = 0``): then on
      blended data it equals ``kappa (delta_B - delta_A)`` at a junction, ``= Theta(4^{-k})``, and
      Property A of order m (``o(2^{-k(m-r)})``) fails there as soon as ``m - r >= 2``.

    ``part="full"`` uses the full masks (both parities; the unused parity completed as described
    in the module docstring), ``part="used"`` only the coefficients that act (parity of the new
    point), evaluated at ``z = 1`` (``z0`` is then ignored): a completion-independent variant.

    >>> property_a_structure(4, 3, 1, -1).value
    'nonzero at junctions'
    >>> property_a_structure(3, 2, 1, -1).witness["property_A_fails_on_blended_data"]
    False
    >>> property_a_structure(4, 2, 0, 1).value
    'identically zero'
    """
    d = _check_degree(degree)
    if not (0 <= r < m):
        raise AnalysisError("Property A uses 0 <= r < m")
    if z0 not in (1, -1):
        raise AnalysisError("z0 must be 1 or -1")
    if m > d + 1:
        raise AnalysisError("m must be <= d + 1")
    if part not in ("full", "used"):
        raise AnalysisError("part must be 'full' or 'used'")
    edges = 2 * ((m + d) // 2 + 4)
    scale = 2 ** (d - 2)

    def values(delta):
        # integer masks: weights binom(d-2, l) (the factor 2^{2-d} is put back at the end)
        count = 2 * edges - (d - 2)
        D = np.zeros((count, d + 2), dtype=object)
        D[:] = 0
        idx = np.arange(count)
        for l in range(d - 1):
            x = delta[(idx + l) // 2]
            for s_, sg in enumerate((1, -1, -1, 1)):
                D[:, (s_ - 2) - l + d] += math.comb(d - 2, l) * sg * x
        if part == "used":
            exps = np.arange(d + 2) - d
            par = (exps[None, :] - idx[:, None]) % 2 == 0
            D = np.where(par, D, 0)
            return _property_a_values(D, -d, m, r, 1, False)[1]
        return _property_a_values(D, -d, m, r, z0, False)[1]

    kappas = []
    for junction in range(1, edges):
        delta = np.array([0] * junction + [1] * (edges - junction), dtype=object)
        kappas.extend(Fraction(int(x), scale) for x in values(delta))
    cvals = values(np.array([1] * edges, dtype=object))
    const_zero = all(x == 0 for x in cvals)
    nonzero = any(x != 0 for x in kappas)
    kmax = max(abs(x) for x in kappas) if kappas else 0
    if not nonzero and const_zero:
        verdict = "identically zero"
    elif const_zero:
        verdict = "nonzero at junctions"
    else:
        verdict = "nonzero on constant sequences"
    fails = bool(nonzero or not const_zero) and (m - r) >= 2
    return Result(value=verdict, status=CERTIFIED,
                  witness={"max_|kappa|": str(kmax), "required": f"o(2^(-k({m}-{r})))",
                           "junction_order": "Theta(4^-k) (delta_B - delta_A) when nonzero",
                           "property_A_fails_on_blended_data": fails, "m": m, "r": r,
                           "z0": z0 if part == "full" else 1, "degree": d, "part": part},
                  provenance={"method": "exact integer linear forms on unit step sequences", "arithmetic": "exact"})


def property_a_table(degree: int, *, part: str = "full") -> list[dict]:
    """All (m, r, z0) with ``1 <= m <= d-1`` (the orders Theorem 3.6 needs) whose quantity does not
    vanish identically, with whether Property A then fails on blended parameters.

    >>> [(x["m"], x["r"], x["z0"]) for x in property_a_table(3)]
    [(2, 1, -1)]
    """
    d = _check_degree(degree)
    out = []
    for m in range(1, d):
        for r in range(m):
            for z0 in ((1, -1) if part == "full" else (1,)):
                res = property_a_structure(d, m, r, z0, part=part)
                if res.value != "identically zero":
                    out.append({"m": m, "r": r, "z0": z0, "verdict": res.value,
                                "max_kappa": res.witness["max_|kappa|"],
                                "fails_on_blended": res.witness["property_A_fails_on_blended_data"]})
    return out


def property_a(u0, degree: int, m: int, r: int, z0: int, *, levels: int = 12, closed: bool = False,
               rule: str = "seed001") -> Result:
    """``max_j |d^{(r)}_m(z0)|`` at levels ``k = 0..levels`` for the initial edge parameters
    ``u0`` (floats, cancellation-free), its scaled value ``2^{k(m-r)} max_j |.|`` (Property A of
    order m asks that this -> 0) and ``4^k max_j |.|``. NUMERICAL (double precision on exact
    linear forms of accurately computed ``delta``).

    >>> r = property_a([0.5] * 4 + [3.0] * 4, 4, 3, 1, -1, levels=10)
    >>> r.value                                     # does 2^{k(m-r)} max_j|.| -> 0 ?
    'does not tend to 0'
    """
    d = _check_degree(degree)
    if not (0 <= r < m <= d + 1) or z0 not in (1, -1):
        raise AnalysisError("need 0 <= r < m <= d + 1 and z0 in {1, -1}")
    res = refine(np.zeros(len(u0) + (0 if closed else 1)), u0, degree=d, steps=0, closed=closed, rule=rule)
    v = res.one_minus_u
    rows = []
    for k in range(levels + 1):
        delta = v / (4 * (2 - v))
        D = _mask_array(delta, d, closed)
        if D.shape[0] > m:
            _, vals = _property_a_values(D, -d, m, r, z0, closed)
            mx = float(np.max(np.abs(vals.astype(float)))) if len(vals) else 0.0
        else:
            mx = float("nan")
        rows.append({"k": k, "max": mx, "scaled_2^{k(m-r)}": mx * 2.0 ** (k * (m - r)), "scaled_4^k": mx * 4.0 ** k})
        if k < levels:
            _, v = step(np.zeros(len(v) + (0 if closed else 1)), v, d, closed=closed, rule=rule)
    tail = [x["scaled_2^{k(m-r)}"] for x in rows[-3:]]
    if all(x == 0 for x in tail):
        verdict = "identically 0"
    elif tail[-1] < 0.3 * tail[0]:
        verdict = "tends to 0"
    else:
        verdict = "does not tend to 0"
    return Result(value=verdict, status=NUMERICAL, witness={"levels": rows, "m": m, "r": r, "z0": z0},
                  provenance={"method": "float64 on exact linear forms; delta = v/(4(2-v)) without cancellation",
                              "degree": d, "rule": rule, "closed": closed})


# --------------------------------------------------------------------------------------------
# smoothness at junctions (numerical)
# --------------------------------------------------------------------------------------------

def junction_smoothness(degree: int, u_left, u_right, *, levels: int = 16, rule: str = "seed001",
                        order: int | None = None, seed: int = 0, half_width: int = 12) -> Result:
    """Numerical evidence on the C^{d-1} claim at a junction between two parameter values.

    Scalar data (random, fixed seed) on an open polygon whose left edges carry ``u_left`` and
    right edges ``u_right``; a window of ``2 half_width`` points around the junction is refined
    ``levels`` times in ``mpmath`` (precision grown with the level so that divided differences
    keep ~60 correct bits). Reports ``omega_k = max |Delta D^k|`` where
    ``D^k = 2^{k q} Delta^q f^k`` are the q-th divided differences (``q = order``, default d-1).
    If the limit is C^q near the junction, ``omega_k -> 0``; a jump of the q-th derivative shows
    as ``omega_k`` bounded away from 0. Also reported for a uniform window as a control.

    >>> r = junction_smoothness(2, 0.3, 4.0, levels=10)
    >>> r.value
    'omega_k -> 0'
    """
    d = _check_degree(degree)
    q = d - 1 if order is None else int(order)
    rng = np.random.default_rng(seed)
    n0 = 2 * half_width
    data = [float(x) for x in rng.standard_normal(n0)]

    def run(ul, ur):
        prec = 64 + levels * (q + 1) + 8 * d
        ctx = _Arith("mp", prec)
        out = []
        with ctx.scope():
            P = ctx.array(data)
            v = ctx.array([1 - ul] * (half_width - 1) + [1 - ur] * (half_width))
            anc = np.array([0] * (half_width - 1) + [1] * half_width)
            for k in range(levels + 1):
                # q-th divided differences and their first differences near the junction
                diffs = P.copy()
                for _ in range(q):
                    diffs = diffs[1:] - diffs[:-1]
                Dk = diffs * mpmath.mpf(2) ** (k * q)
                jumps = [abs(Dk[i + 1] - Dk[i]) for i in range(len(Dk) - 1)]
                out.append(float(max(jumps)))
                if k == levels:
                    break
                P, v_new = step(P, v, d, rule=rule, sqrt=ctx.sqrt)
                j = np.arange(len(P) - 1)
                anc = anc[_sources(j, d, False, rule, len(v))]
                v = v_new
                # crop to a window around the junction (first edge inheriting from the right side)
                jn = int(np.argmax(anc == 1)) if (anc == 1).any() else len(anc) // 2
                a = max(0, jn - half_width)
                b = min(len(P), jn + half_width)
                P, v, anc = P[a:b], v[a:b - 1], anc[a:b - 1]
        return out

    junction = run(float(u_left), float(u_right))
    uniform = run(float(u_left), float(u_left))
    mid = junction[len(junction) // 2]
    verdict = "omega_k -> 0" if junction[-1] < 0.25 * mid else "omega_k bounded away from 0"
    rates = [math.log2(junction[k] / junction[k + 1]) if junction[k + 1] > 0 else float("inf")
             for k in range(len(junction) - 1)]
    return Result(value=verdict, status=NUMERICAL,
                  witness={"omega_junction": junction, "omega_uniform": uniform, "log2_ratios": rates,
                           "order": q, "levels": levels},
                  provenance={"method": "windowed refinement in mpmath, divided differences", "degree": d,
                              "rule": rule, "seed": seed})


# --------------------------------------------------------------------------------------------
# reproduction of circles, hyperbolas, parabolas; chamfering
# --------------------------------------------------------------------------------------------

def _scale_factor(kind: str, alpha: float, d: int) -> float:
    """Limit radius / control radius for a regular (exponential) polygon of half-step ``alpha``:
    ``cos(a) (sin(a)/a)^{d-2}`` (trigonometric) or ``cosh(a)(sinh(a)/a)^{d-2}`` (hyperbolic)."""
    if alpha == 0:
        return 1.0
    if kind == "trigonometric":
        return math.cos(alpha) * (math.sin(alpha) / alpha) ** (d - 2)
    return math.cosh(alpha) * (math.sinh(alpha) / alpha) ** (d - 2)


def circle_polygon(radius: float, angles: Sequence[float] | None = None, *, center=(0.0, 0.0), start: float = 0.0,
                   step_angle: float = math.pi / 6, count: int = 8, degree: int = 2):
    """Control points and edge parameters whose NVPS limit is exactly an arc of the circle
    ``|x - center| = radius``: ``P_j = center + rho (cos(start + j step), sin(...))``,
    ``u = cos(step/2)``, ``rho = radius / (cos(a) (sin(a)/a)^{d-2})``, ``a = step/2``.

    >>> P, u = circle_polygon(1.0, step_angle=math.pi / 2, count=4, degree=2)
    >>> round(float(np.hypot(*P[0])), 12), round(u[0], 12)      # rho = 1/cos(pi/4), u = cos(pi/4)
    (1.414213562373, 0.707106781187)
    """
    d = _check_degree(degree)
    a = step_angle / 2
    if not 0 < a < math.pi / 2:
        raise AnalysisError("step_angle must be in (0, pi)")
    rho = radius / _scale_factor("trigonometric", a, d)
    t = start + step_angle * np.arange(count)
    P = np.column_stack([center[0] + rho * np.cos(t), center[1] + rho * np.sin(t)])
    return P, [math.cos(a)] * (count - 1)


def hyperbola_polygon(a_axis: float = 1.0, b_axis: float = 1.0, *, center=(0.0, 0.0), start: float = 0.0,
                      step_param: float = 0.5, count: int = 8, degree: int = 2):
    """Control points and parameters whose limit is the hyperbola branch
    ``(a cosh t, b sinh t) + center``: spacing ``step_param`` in t, ``u = cosh(step/2)``.

    >>> P, u = hyperbola_polygon(step_param=1.0, count=3, degree=2)
    >>> round(u[0], 12)
    1.127625965206
    """
    d = _check_degree(degree)
    al = step_param / 2
    if not al > 0:
        raise AnalysisError("step_param must be > 0")
    rho = 1 / _scale_factor("hyperbolic", al, d)
    t = start + step_param * np.arange(count)
    P = np.column_stack([center[0] + rho * a_axis * np.cosh(t), center[1] + rho * b_axis * np.sinh(t)])
    return P, [math.cosh(al)] * (count - 1)


def parabola_polygon(c2: float = 0.5, *, start: float = -1.0, step_param: float = 0.5, count: int = 8,
                     degree: int = 2):
    """Control points (u = 1) whose limit is the parabola ``(t, c2 t^2)``: the B-spline
    quasi-interpolant ``P_j = (t_j, c2 t_j^2 - c2 h^2 (d+1)/12)`` (the degree-d B-spline has
    variance ``(d+1)/12``).

    >>> P, u = parabola_polygon(1.0, start=0.0, step_param=1.0, count=3, degree=2)
    >>> P.tolist(), u
    ([[0.0, -0.25], [1.0, 0.75], [2.0, 3.75]], [1.0, 1.0])
    """
    d = _check_degree(degree)
    t = start + step_param * np.arange(count)
    P = np.column_stack([t, c2 * t ** 2 - c2 * step_param ** 2 * (d + 1) / 12])
    return P, [1.0] * (count - 1)


def reproduce(kind: str = "circle", *, degree: int = 2, levels: int = 8, count: int = 10, spacing: float | None = None,
              arithmetic: str = "float", prec: int = 113) -> Result:
    """Reproduction test: refine the control polygon of an exact curve (``"circle"`` radius 1,
    ``"hyperbola"`` (cosh t, sinh t), ``"parabola"`` (t, t^2/2)) and measure

    * ``deviation_k``: max distance of the level-k points from the curve (-> 0 like 4^{-k});
    * ``form_error_k``: for circle/hyperbola, how far the level-k points are from the *exact*
      level-k polygon predicted by the theory (a scaled regular polygon): rounding level if the
      reproduction is exact.

    >>> r = reproduce("circle", degree=3, levels=6)
    >>> r.witness["form_error"][-1] < 1e-13, r.witness["rate"][-1] > 3.9
    (True, True)
    """
    d = _check_degree(degree)
    if kind == "circle":
        s = spacing or math.pi / 6
        P, u = circle_polygon(1.0, step_angle=s, count=count, degree=d)
        dist = lambda X: np.abs(np.hypot(X[:, 0], X[:, 1]) - 1.0)  # noqa: E731
    elif kind == "hyperbola":
        s = spacing or 0.4
        P, u = hyperbola_polygon(1.0, 1.0, start=-s * (count - 1) / 2, step_param=s, count=count, degree=d)

        def dist(X):
            # distance to x^2 - y^2 = 1 (x > 0): Newton on the foot point parameter
            t = np.arcsinh(X[:, 1])
            for _ in range(30):
                cx, sy = np.cosh(t), np.sinh(t)
                g = (cx - X[:, 0]) * sy + (sy - X[:, 1]) * cx
                dg = sy * sy + (cx - X[:, 0]) * cx + cx * cx + (sy - X[:, 1]) * sy
                t = t - g / dg
            return np.hypot(np.cosh(t) - X[:, 0], np.sinh(t) - X[:, 1])
    elif kind == "parabola":
        s = spacing or 0.5
        P, u = parabola_polygon(0.5, start=-s * (count - 1) / 2, step_param=s, count=count, degree=d)

        def dist(X):
            t = X[:, 0].copy()
            for _ in range(40):
                g = (t - X[:, 0]) + (t * t / 2 - X[:, 1]) * t
                dg = 1 + t * t + (t * t / 2 - X[:, 1])
                t = t - g / dg
            return np.hypot(t - X[:, 0], t * t / 2 - X[:, 1])
    else:
        raise AnalysisError("kind must be 'circle', 'hyperbola' or 'parabola'")
    devs, forms = [], []
    Pk, vk = np.asarray(P, dtype=float), 1 - np.asarray(u, dtype=float)
    for k in range(levels + 1):
        devs.append(float(dist(Pk).max()))
        if kind == "circle":
            rad = np.hypot(Pk[:, 0], Pk[:, 1])
            ang = np.unwrap(np.arctan2(Pk[:, 1], Pk[:, 0]))
            forms.append(float(max(np.ptp(rad), np.ptp(np.diff(ang)) if len(ang) > 2 else 0.0)))
        elif kind == "hyperbola":
            # points must be rho_k (cosh, sinh)(t0 + j s_k) for one rho_k: x^2 - y^2 constant, equal spacing
            q = Pk[:, 0] ** 2 - Pk[:, 1] ** 2
            tt = np.arctanh(Pk[:, 1] / Pk[:, 0])
            forms.append(float(max(np.ptp(q) / q.mean(), np.ptp(np.diff(tt)))))
        else:
            forms.append(float("nan"))
        if k < levels:
            Pk, vk = step(Pk, vk, d)
    rate = [devs[k] / devs[k + 1] for k in range(levels) if devs[k + 1] > 0]
    return Result(value=devs[-1], status=NUMERICAL,
                  witness={"deviation": devs, "form_error": forms, "rate": rate, "kind": kind, "degree": d,
                           "note": "deviation = max distance of level-k points from the exact limit curve "
                                   "(float64, ~1e-16 relative); form_error ~ 1e-15 means the level-k polygon is "
                                   "exactly the predicted scaled regular polygon, so the limit is the curve"},
                  provenance={"method": "float64 refinement; closed-form limit radius "
                                        "cos(a)(sin a/a)^(d-2) / cosh(a)(sinh a/a)^(d-2)", "levels": levels})


def chamfer_polygon(vertices, radii, *, closed: bool = True):
    """Seed 001's Algorithm 2 (degree 2): replace each corner ``A`` (neighbours ``B``, ``C``,
    angle ``theta``) with a radius ``r_A > 0`` by ``P1, A, P2`` on the two edges at distance
    ``2 r cot(theta/2)`` from ``A`` and give the edges ``P1 A``, ``A P2`` the parameter
    ``u_A = sin(theta/2)`` (= cos of half the arc angle); all other edges get ``u = 1``. The degree-2
    limit is then exactly: straight segments joined by circular arcs of radius ``r_A`` tangent to
    both edges (at the midpoints of ``P1 A`` and ``A P2``).

    >>> P, u, arcs = chamfer_polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [1, 1, 1, 1])
    >>> len(P), [round(x, 6) for x in u[:3]]
    (12, [0.707107, 0.707107, 1.0])
    """
    V = np.asarray(vertices, dtype=float)
    n = len(V)
    if len(radii) != n:
        raise AnalysisError("give one radius per vertex (0 = keep the corner)")
    pts, params, arcs = [], [], []
    for i in range(n):
        A = V[i]
        r = float(radii[i])
        if not closed and i in (0, n - 1):
            pts.append(A)
            params.append(1.0)
            continue
        B, C = V[i - 1], V[(i + 1) % n]
        eb, ec = (B - A) / np.linalg.norm(B - A), (C - A) / np.linalg.norm(C - A)
        theta = math.acos(max(-1.0, min(1.0, float(eb @ ec))))
        if r <= 0:
            pts += [A, A, A]
            params += [1.0, 1.0, 1.0]
            continue
        t = r / math.tan(theta / 2)
        if 2 * t > min(np.linalg.norm(B - A), np.linalg.norm(C - A)) + 1e-12:
            raise AnalysisError(f"radius {r} too large at vertex {i}: needs 2 r cot(theta/2) <= shortest edge")
        P1, P2 = A + 2 * t * eb, A + 2 * t * ec
        bis = (eb + ec) / np.linalg.norm(eb + ec)
        O = A + bis * r / math.sin(theta / 2)
        arcs.append({"vertex": i, "center": O.tolist(), "radius": r, "E": (A + t * eb).tolist(), "F": (A + t * ec).tolist()})
        u = math.sin(theta / 2)
        pts += [P1, A, P2]
        params += [u, u, 1.0]
    P = np.array(pts)
    u = params if closed else params[:-1]
    return P, u, arcs


#: Seed 001, Fig. 3(c): the quadrangle ABCD and the radii r_A, r_B, r_C, r_D.
CHAMFER_QUADRANGLE = ((-6.3825, 1.6082), (3.2028, 4.2398), (10.0, -6.7544), (-8.4101, -6.7544))
CHAMFER_RADII = (3.650669, 2.0, 1.0, 1.691966)


def _distance_to_chamfer(X, vertices, arcs):
    """Distance of points X to the chamfered shape (segments between tangent points + arcs)."""
    V = np.asarray(vertices, dtype=float)
    n = len(V)
    by_vertex = {a["vertex"]: a for a in arcs}
    best = np.full(len(X), np.inf)
    for i in range(n):
        j = (i + 1) % n
        S = np.array(by_vertex[i]["F"]) if i in by_vertex else V[i]
        T = np.array(by_vertex[j]["E"]) if j in by_vertex else V[j]
        ST = T - S
        tt = np.clip(((X - S) @ ST) / (ST @ ST), 0, 1)
        best = np.minimum(best, np.linalg.norm(X - (S + tt[:, None] * ST), axis=1))
    for a in arcs:
        O, r = np.array(a["center"]), a["radius"]
        E, F = np.array(a["E"]) - O, np.array(a["F"]) - O
        Y = X - O
        ang = np.arctan2(Y[:, 1], Y[:, 0])
        ae, af = math.atan2(E[1], E[0]), math.atan2(F[1], F[0])
        span = (af - ae) % (2 * math.pi)
        if span > math.pi:
            ae, af, span = af, ae, 2 * math.pi - span
        inside = ((ang - ae) % (2 * math.pi)) <= span
        d_arc = np.where(inside, np.abs(np.linalg.norm(Y, axis=1) - r), np.inf)
        best = np.minimum(best, d_arc)
    return best


def chamfer_example(*, levels: int = 8, degree: int = 2) -> Result:
    """Seed 001's chamfering example (Fig. 3(c)-(d)): max distance of the refined points, and of
    the edge midpoints (which are limit points for d = 2), from the exact chamfered shape.

    >>> r = chamfer_example(levels=6)
    >>> r.witness["midpoint_deviation"][-1] < 1e-12, r.witness["rate"][-1] > 3.5
    (True, True)
    """
    d = _check_degree(degree)
    P, u, arcs = chamfer_polygon(CHAMFER_QUADRANGLE, CHAMFER_RADII)
    Pk, vk = P.copy(), 1 - np.asarray(u)
    devs, mids = [], []
    for k in range(levels + 1):
        devs.append(float(_distance_to_chamfer(Pk, CHAMFER_QUADRANGLE, arcs).max()))
        M = (Pk + np.roll(Pk, -1, axis=0)) / 2
        mids.append(float(_distance_to_chamfer(M, CHAMFER_QUADRANGLE, arcs).max()))
        if k < levels:
            Pk, vk = step(Pk, vk, d, closed=True)
    rate = [devs[k] / devs[k + 1] for k in range(levels)]
    return Result(value=devs[-1], status=NUMERICAL,
                  witness={"deviation": devs, "midpoint_deviation": mids, "rate": rate, "arcs": arcs,
                           "u": [float(x) for x in u], "degree": d,
                           "note": "for d = 2 the edge midpoints are limit points; their distance from the exact "
                                   "shape is rounding error, so the chamfer is reproduced exactly. For d > 2 the "
                                   "three control points per corner do not reproduce the arc."},
                  provenance={"method": "float64, exact geometry of segments and arcs", "levels": levels})


def blended_example(degree: int = 2, rule: str = "seed001"):
    """A control polygon with a circular piece (u = cos), a straight/parabolic piece (u = 1) and a
    hyperbolic piece (u = cosh): returns (points, u, pieces) with the index ranges of each piece."""
    d = _check_degree(degree)
    Pc, uc = circle_polygon(1.0, start=math.pi / 2, step_angle=math.pi / 6, count=7, degree=d)
    # straight piece continuing from the last circle point downwards-right
    last = Pc[-1]
    Pl = last + np.outer(np.arange(1, 5), [0.6, -0.3])
    Ph, uh = hyperbola_polygon(0.5, 0.5, center=(Pl[-1][0] + 0.3, Pl[-1][1] - 1.2), start=-0.9, step_param=0.45,
                               count=7, degree=d)
    P = np.vstack([Pc, Pl, Ph])
    u = list(uc) + [1.0] * (len(Pl) + 1) + list(uh)
    return P, u, {"circle": (0, len(Pc)), "line": (len(Pc), len(Pc) + len(Pl)), "hyperbola": (len(Pc) + len(Pl), len(P))}


def plot_blended(path: str, *, degrees: Sequence[int] = (2, 3, 4), levels: int = 6) -> str:
    """Figure: blended curves (circle arc, line, hyperbola) by the NVPS of several degrees."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 5))
    P0, u0, _ = blended_example(2)
    ax.plot(P0[:, 0], P0[:, 1], "o--", color="tab:blue", lw=0.8, ms=3, label="control polygon")
    for d, col in zip(degrees, ("black", "tab:red", "tab:green", "tab:purple")):
        P, u, _ = blended_example(d)
        r = refine(P, u, degree=d, steps=levels)
        ax.plot(r.points[:, 0], r.points[:, 1], "-", color=col, lw=1.2, label=f"NVPS degree {d}")
    ax.set_aspect("equal")
    ax.legend(fontsize=8)
    ax.set_title("NVPS: circle (u = cos), line (u = 1), hyperbola (u = cosh) pieces")
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_chamfer(path: str, *, levels: int = 7) -> str:
    """Figure: seed 001's chamfering example (Fig. 3(c)-(d)), degree 2."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    P, u, arcs = chamfer_polygon(CHAMFER_QUADRANGLE, CHAMFER_RADII)
    r = refine(P, u, degree=2, steps=levels, closed=True)
    fig, ax = plt.subplots(figsize=(6, 5))
    Q = np.vstack([CHAMFER_QUADRANGLE, CHAMFER_QUADRANGLE[:1]])
    ax.plot(Q[:, 0], Q[:, 1], "--", color="gray", lw=0.8, label="quadrangle ABCD")
    C = np.vstack([P, P[:1]])
    ax.plot(C[:, 0], C[:, 1], "o:", color="tab:blue", ms=3, lw=0.8, label="control polygon (P1 A P2 per corner)")
    R = np.vstack([r.points, r.points[:1]])
    ax.plot(R[:, 0], R[:, 1], "-", color="black", lw=1.3, label=f"NVPS degree 2, {levels} steps")
    for a in arcs:
        ax.add_patch(matplotlib.patches.Circle(a["center"], a["radius"], fill=False, ls=":", color="tab:red", lw=0.7))
    ax.set_aspect("equal")
    ax.legend(fontsize=7, loc="lower left")
    ax.set_title("Chamfering (seed 001, Fig. 3): r_A, r_B, r_C, r_D = 3.650669, 2, 1, 1.691966")
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path
