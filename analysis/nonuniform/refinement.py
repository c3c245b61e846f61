"""The NVPS refinement (seeds 000/001): the scheme, one step, many steps, parameters and angles.

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
:func:`.definitions.compare_definitions` for how the two relate (same data rule up to the shift
``tau_d``; the same parameter inheritance for odd ``d``; mirror images of each other for even ``d``).

Open polygons (``closed=False``): ``n`` points and ``n - 1`` edge parameters give
``2(n-1) - (d-2)`` points and one parameter per new edge; every step re-indexes from 0 (the rules
are translation covariant, so this is harmless). Closed polygons: ``n`` points, ``n`` parameters
(edge ``n-1`` joins ``P_{n-1}`` to ``P_0``), ``2n`` new points.

Parameters are held as ``v = 1 - u``, updated by the cancellation-free form of the rule,
``v_new = (v/2) / (1 + sqrt(1 - v/2))``, so that ``1 - u^k ~ 4^{-k}`` and the mask differences
``h - 1/4 = v/(4(2 - v))`` keep full relative precision at every level (see "Precision").
``u = cos(theta)`` (``0 <= theta < pi``) gives ``u^k = cos(theta/2^k)``; ``u = cosh(theta)`` gives
``u^k = cosh(theta/2^k)``; :func:`parameter_from_angle` builds ``v`` accurately from ``theta``.

The masks of a step are in :mod:`.masks`; the arithmetics (``arithmetic=``: ``"float"``,
``"mp"``, ``"iv"``, ``"exact"``) in :mod:`.arithmetic`.

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

import mpmath
import numpy as np
import sympy as sp

from ..result import AnalysisError
from .arithmetic import _SYMPY_SQRT, _Arith

RULES = ("seed001", "seed000")


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


def limit_mask(degree: int):
    """The limit mask ``a(z) = z^{-d}(1+z)^{d+1}/2^d`` (uniform B-spline of degree d).

    >>> limit_mask(2)
    LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
    """
    from ..algebra.symbol import LaurentSymbol

    d = _check_degree(degree)
    return LaurentSymbol.from_mask([sp.Rational(math.comb(d + 1, t), 2 ** d) for t in range(d + 2)], start=-d)


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
