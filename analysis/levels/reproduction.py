"""Exponential generation/reproduction of level-dependent schemes, and how far limit curves stay
from circles, ellipses and the cardioid, astroid and lemniscate of seed 003 (Figs 1-5).

Examples
--------
>>> import sympy as sp
>>> from schemes.level_dependent import get
>>> t = sp.Symbol("t", positive=True)
>>> generation(get("exp-chaikin-trig"), [sp.I * t, -sp.I * t]).status     # {cos tx, sin tx}
'certified'
>>> generation(get("exp-chaikin-trig"), [t]).status                      # not e^{tx}
'refuted'
>>> r = curve_deviation(get("exp-chaikin-trig"), "circle", {"t": 2 * sp.pi / 8}, points=8, steps=6)
>>> r.status, r.value < 1e-12
('numerical', True)

Algorithm
---------
Generation of ``e^{lambda x}`` at every level (Dyn–Levin; Conti–Romani): with ``h = 2^-n`` and
``w = e^{-lambda h/2}``, ``S_{a^n}`` maps samples ``e^{lambda j h}`` to multiples of
``e^{lambda i h/2}`` iff ``a^n(-w) = 0``; reproduction (with parametrisation shift ``tau``, the
same for all ``lambda``) iff moreover ``a^n(w) = 2 w^tau``. Both are tested as exact identities
in ``h`` and the parameters (sympy), refuted by a certified nonzero value (ball arithmetic).
Curves: closed control polygons sampled from the curve, refined in float64 (numerical), compared
with the exact curve (radial deviation, discrete Hausdorff distance, discrete curvature from the
circumcircle of consecutive points).

References
----------
C. Conti, L. Romani, *Algebraic conditions on non-stationary subdivision symbols for exponential
polynomial reproduction*, J. Comput. Appl. Math. 236 (2011) 543-556.

Arity m (``LevelDependentScheme(..., arity=m)``, ``h = m^-n``; :func:`generation`, :func:`reproduction`)
--------------------------------------------------------------------------------------------------------
The scheme *generates* ``e^{lambda x}`` at every level when ``S_{a^n}`` maps the samples ``e^{lambda j h}`` to
multiples of ``e^{lambda i h/m}``, and *reproduces* it (parametrisation ``t^n_i = (i + tau/(m-1)) m^-n``,
``tau = a'(1)/m`` of the limit symbol, Conti–Hormann 2011) when the multiple is exactly the sample at level
``n+1``. Write ``i = m k + r`` and ``w = e^{-lambda h/m}``. Then ``(S_{a^n} e^{lambda . h})_i = e^{lambda k h}
sum_l a^n_{r+ml} e^{-lambda l h}``, which is ``c e^{lambda i h/m}`` for all ``i`` iff the m sub-symbols
``A_r(w) = sum_l a^n_{r+ml} w^{r+ml}`` are equal (to ``c``), i.e. iff ``a^n(eps^j w) = 0`` for the m-th roots of
unity ``eps^j != 1`` (for ``m = 2``: ``a^n(-e^{-lambda h/2}) = 0``, the binary condition of
:func:`analysis.levels.reproduction.generation`). With the data ``e^{lambda (j+sigma) h}`` the same computation
gives reproduction iff moreover ``A_r(w) = w^{sigma (m-1)}`` for every r, i.e. ``a^n(w) = m w^tau`` with
``tau = sigma (m-1)``; letting ``lambda -> 0`` gives ``tau = a'(1)/m`` (the polynomial-reproduction shift).
The conditions ``A_r(w) - A_0(w) = 0`` (and ``A_0(w) - w^tau = 0``) are proven as exact identities in ``h``
and the parameters (sympy simplification; no roots of unity are needed in this form) or refuted by a
certified nonzero ball value (Arb, ``h = m^-n`` at levels ``n = 0..3``, parameters at the given values
or at points of the given box). The exact/box reading of the values and the search for a certified nonzero
value are shared by every arity.

The binary statements (``a^n(-e^{-lambda h/2}) = 0``) are kept for ``m = 2`` because the binary reports and
goldens record them; for ``m > 2`` the m sub-symbols are compared (the same condition, written for any m).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Mapping, Sequence

import numpy as np
import sympy as sp

from .bounds import _exact_zero
from .level_dependent import H, LevelDependentScheme, _ball, _env_values, _to_ball, workprec
from ..result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, AnalysisError, Result
from ..algebra.reader import as_expr

_Z = sp.Symbol("z")


def _symbol(s: LevelDependentScheme, z) -> sp.Expr:
    return sum(c * z ** (s.start + k) for k, c in enumerate(s.mask))


def _exact_and_boxes(values) -> tuple[dict, dict]:
    """Split parameter values into exact ones and closed boxes ``(lo, hi)`` (issue 13)."""
    exact, boxes = {}, {}
    for k, v in dict(values or {}).items():
        if isinstance(v, (tuple, list)):
            if len(v) != 2:
                raise AnalysisError(f"a box for {k} needs exactly two ends (LOW, HIGH)")
            lo, hi = (as_expr(x, what=f"end of the box of {k}") for x in v)
            if lo.free_symbols or hi.free_symbols or not bool(lo < hi):
                raise AnalysisError(f"the box for {k} must be [LOW, HIGH] with numbers LOW < HIGH")
            boxes[str(k)] = (lo, hi)
        else:
            exact[str(k)] = v
    return exact, boxes


def _box_points(boxes: dict, depth: int) -> list[dict]:
    """Midpoints of the box and of its sub-boxes after 1..depth bisections of every side (adaptive
    search for a counterexample inside the box)."""
    pts, cells = [], [dict(boxes)]
    for _ in range(depth + 1):
        pts.extend({k: (lo + hi) / 2 for k, (lo, hi) in c.items()} for c in cells)
        nxt = []
        for c in cells:
            parts = [{}]
            for k, (lo, hi) in c.items():
                mid = (lo + hi) / 2
                parts = [{**q, k: half} for q in parts for half in ((lo, mid), (mid, hi))]
            nxt.extend(parts)
        cells = nxt
    return pts


def _prepare(s: LevelDependentScheme, values) -> tuple[LevelDependentScheme, dict, dict]:
    """``(s at the exact values, {parameter symbol: exact value}, boxes)``; every name must be a parameter of ``s``."""
    exact, boxes = _exact_and_boxes(values)
    rep = {}
    if exact:
        rep = {s._param(str(k)): as_expr(v) for k, v in exact.items()}
        s = s.subs(exact)
    for k in boxes:
        s._param(k)
    return s, rep, boxes


def _certify_nonzero_in(expr: sp.Expr, s: LevelDependentScheme, boxes: dict, depth: int = 2, *,
                        arity: int = 2) -> dict | None:
    """A level ``n`` (``h = m^-n``, m = ``arity``) and a point of the box (``boxes``; none: the default point)
    where ``expr != 0`` is proven."""
    if not boxes:
        return _certify_nonzero(expr, s, None, arity=arity)
    for pt in _box_points(boxes, depth):
        w = _certify_nonzero(expr, s, pt, arity=arity)
        if w:
            return w
    return None


def _certify_nonzero(expr: sp.Expr, s: LevelDependentScheme, values, *, arity: int = 2) -> dict | None:
    """A level (``h = m^-n``, ``n = 0..3``) and parameter point where ball arithmetic proves ``expr != 0``."""
    pts = dict(values or {})
    for name in s.param_names:
        pts.setdefault(name, sp.Rational(7, 10))
    for extra in {str(x) for x in expr.free_symbols} - set(pts) - {"h"}:
        pts[extra] = sp.Rational(7, 10)
    for n in (0, 1, 2, 3):
        try:
            with workprec(128):
                env = {k: _to_ball(v, True) for k, v in pts.items()}
                env["h"] = _to_ball(sp.Rational(1, arity ** n), True)
                b = _ball(as_expr(expr), env, True)
        except (AnalysisError, ZeroDivisionError):
            continue
        if b.is_finite() and not b.contains(0):
            return {"n": n, "point": pts, "value": str(b)}
    return None


def sub_symbols(s: LevelDependentScheme, w: sp.Expr) -> list[sp.Expr]:
    """``A_r(w) = sum_l a^n_{r+ml} w^{r+ml}`` for ``r = 0..m-1`` (expressions in ``h`` and the parameters).

    >>> s = LevelDependentScheme.from_symbol("(1+z+z**2)**2/(3*z**2)", arity=3)
    >>> [sp.factor(x) for x in sub_symbols(s, sp.Integer(1))]
    [1, 1, 1]
    """
    m = s.arity
    out = [sp.Integer(0)] * m
    for k, c in enumerate(s.mask):
        e = s.start + k
        out[e % m] += c * w ** e
    return out


def generation(s: LevelDependentScheme, lambdas: Sequence, values: Mapping[str, Any] | None = None, *,
               depth: int = 2) -> Result:
    """Certify that every level ``S_{a^n}`` generates ``e^{lambda x}`` for each lambda.

    ``lambdas`` are sympy expressions (``t``, ``-t``, ``I*t``, ``0``...). Certified when
    ``a^n(-e^{-lambda h/2})`` simplifies to 0 identically in ``h`` and the parameters; refuted
    with a certified nonzero value. ``values`` may give closed boxes ``(lo, hi)`` (several
    parameters): certified then holds on the whole box (the identity is exact in the boxed
    parameters), and a counterexample is searched at the midpoints of the box and of its
    sub-boxes, bisected up to ``depth`` times, so it lies in the box.

    >>> import sympy as sp
    >>> from schemes.seed003 import TRIGONOMETRIC
    >>> a, w = sp.Symbol("alpha", positive=True), sp.Symbol("omega")
    >>> r = generation(TRIGONOMETRIC, [sp.I * a, -sp.I * a], {"alpha": (0, 1), "omega": (0, sp.Rational(1, 50))})
    >>> r.status, r.witness["counterexample"]["point"]
    ('refuted', {'alpha': 1/2, 'omega': 1/100})

    Arity ``m > 2`` (the scheme's; module docstring): the m sub-symbols ``A_r(w)``, ``w = e^{-lambda h/m}``,
    are equal identically.

    >>> from analysis.levels.expbspline import ternary_exponential_bspline_2
    >>> t3 = ternary_exponential_bspline_2()
    >>> generation(t3, [0, sp.I * t3.params[0], -sp.I * t3.params[0]]).status          # 1, cos(theta x), sin(theta x)
    'certified'
    >>> r = generation(t3, [t3.params[0]], {"theta": 1})                                # not e^(theta x)
    >>> r.status, r.witness["counterexample"]["n"]
    ('refuted', 0)
    """
    s, rep, boxes = _prepare(s, values)
    if s.arity != 2:
        m = s.arity
        out = {}
        for lam in lambdas:
            lam = as_expr(lam).subs(rep)
            A = sub_symbols(s, sp.exp(-lam * H / m))
            for r in range(1, m):
                e = A[r] - A[0]
                if _exact_zero(e):
                    continue
                stmt = f"A_{r}(w) != A_0(w) at w = exp(-({lam}) h/{m}), i.e. a^n(eps^j w) != 0 for some j"
                w = _certify_nonzero_in(e, s, boxes, depth, arity=m)
                if w:
                    return Result(value=False, status=REFUTED, witness={"lambda": lam, "statement": stmt,
                                                                        "residue": r, "counterexample": w},
                                  provenance={"method": "acb ball evaluation", "arity": m})
                return Result(value=None, status=INCONCLUSIVE, witness={"lambda": lam, "statement": stmt, "residue": r},
                              provenance={"method": "no exact zero proof, no certified nonzero value", "arity": m})
            out[sp.sstr(lam)] = f"A_0 = ... = A_{m - 1} at w = exp(-lambda h/{m}) identically"
        wit: dict[str, Any] = {"generated": [sp.sstr(as_expr(x)) for x in lambdas], "conditions": out, "arity": m}
        if boxes:
            wit["box"] = {k: tuple(v) for k, v in boxes.items()}
        return Result(value=True, status=CERTIFIED, witness=wit,
                      provenance={"method": f"exact: a^n(eps^j exp(-lambda h/{m})) == 0, j = 1..{m - 1}, for all h = "
                                            f"{m}^-n and all parameters (sympy)", "arity": m})
    out = {}
    for lam in lambdas:
        lam = as_expr(lam).subs(rep)
        e = _symbol(s, -sp.exp(-lam * H / 2))
        if _exact_zero(e):
            out[sp.sstr(lam)] = "identically 0"
            continue
        w = _certify_nonzero_in(e, s, boxes, depth)
        stmt = f"a^n(-exp(-({lam}) h/2)) != 0"
        if w:
            return Result(value=False, status=REFUTED,
                          witness={"lambda": lam, "statement": stmt, "counterexample": w},
                          provenance={"method": "acb ball evaluation"})
        return Result(value=None, status=INCONCLUSIVE, witness={"lambda": lam, "statement": stmt},
                      provenance={"method": "no exact zero proof, no certified nonzero value"})
    wit = {"generated": [sp.sstr(as_expr(x)) for x in lambdas], "conditions": out}
    if boxes:
        wit["box"] = {k: tuple(v) for k, v in boxes.items()}
    return Result(value=True, status=CERTIFIED, witness=wit,
                  provenance={"method": "exact: a^n(-exp(-lambda h/2)) == 0 for all h and all parameters (sympy)"})


def reproduction(s: LevelDependentScheme, lambdas: Sequence, values: Mapping[str, Any] | None = None, *,
                 depth: int = 2) -> Result:
    """Certify reproduction: generation and ``a^n(e^{-lambda h/2}) = 2 e^{-lambda tau h/2}``.

    ``tau = a'(1)/2`` of the limit symbol (the parametrisation of polynomial reproduction).
    Boxes in ``values`` as in :func:`generation`. Arity ``m > 2``: ``a^n(w) = m w^tau``, ``w = e^{-lambda h/m}``,
    ``tau = a'(1)/m`` (module docstring).

    >>> from analysis.levels.expbspline import ternary_exponential_bspline_2
    >>> r = reproduction(ternary_exponential_bspline_2(), [0])          # reproduces constants
    >>> r.status, r.witness["tau"]
    ('certified', 0)
    """
    g = generation(s, lambdas, values, depth=depth)
    if g.status != CERTIFIED:
        return g
    s, rep, boxes = _prepare(s, values)
    if s.arity != 2:
        m = s.arity
        a = s.limit()
        tau = sp.simplify(sum(c * (a.start + k) for k, c in enumerate(a.mask)) / m)
        for lam in lambdas:
            lam = as_expr(lam).subs(rep)
            w = sp.exp(-lam * H / m)
            e = sub_symbols(s, w)[0] - w ** tau
            if not _exact_zero(e):
                cx = _certify_nonzero_in(e, s, boxes, depth, arity=m)
                return Result(value=False if cx else None, status=REFUTED if cx else INCONCLUSIVE,
                              witness={"generation": True, "lambda": lam, "tau": tau,
                                       "statement": f"a^n(exp(-({lam}) h/{m})) != {m} exp(-({lam}) tau h/{m})",
                                       "counterexample": cx},
                              provenance={"method": "exact identity test + acb ball evaluation", "arity": m})
        wit: dict[str, Any] = {"tau": tau, "lambdas": list(lambdas), "arity": m,
                               "parametrisation": f"t_i^n = (i + tau/{m - 1}) {m}^-n"}
        if boxes:
            wit["box"] = {k: tuple(v) for k, v in boxes.items()}
        return Result(value=True, status=CERTIFIED, witness=wit,
                      provenance={"method": "exact generalized m-ary sum rules at every level and parameter (sympy)",
                                  "arity": m})
    a = s.limit()
    tau = sp.simplify(sum(c * (a.start + k) for k, c in enumerate(a.mask)) / 2)
    for lam in lambdas:
        lam = as_expr(lam).subs(rep)
        e = _symbol(s, sp.exp(-lam * H / 2)) - 2 * sp.exp(-lam * tau * H / 2)
        if not _exact_zero(e):
            w = _certify_nonzero_in(e, s, boxes, depth)
            st = REFUTED if w else INCONCLUSIVE
            return Result(value=False if w else None, status=st,
                          witness={"generation": True, "lambda": lam, "tau": tau,
                                   "statement": f"a^n(exp(-({lam}) h/2)) != 2 exp(-({lam}) tau h/2)",
                                   "counterexample": w},
                          provenance={"method": "exact identity test + acb ball evaluation"})
    wit = {"tau": tau, "lambdas": list(lambdas)}
    if boxes:
        wit["box"] = {k: tuple(v) for k, v in boxes.items()}
    return Result(value=True, status=CERTIFIED, witness=wit,
                  provenance={"method": "exact generalized sum rules at every level and every parameter (sympy)"})


@lru_cache(maxsize=256)
def _root_frequency(r: sp.Expr) -> sp.Expr | None:
    """``lim_{h->0} -2 log(-r(h))/h`` simplified, or ``None`` when sympy cannot take the limit (a pure function
    of the root ``r(h)``, remembered: the same factors recur across schemes, and each limit costs up to a second)."""
    try:
        return sp.simplify(sp.limit(-2 * sp.log(-r) / H, H, 0))
    except (NotImplementedError, ValueError):
        return None


def exponential_frequencies(s: LevelDependentScheme, values: Mapping[str, Any] | None = None) -> Result:
    """The frequencies ``lambda`` (with multiplicity) whose exponential polynomials ``x^j e^{lambda x}``
    every level generates, and those whose ``e^{lambda x}`` it reproduces — exactly.

    Returns certified ``value = {"generated": {lambda: m}, "reproduced": [lambda, ...]}``:
    ``a^n(z)`` vanishes to order ``m`` at ``z = -e^{-lambda h/2}`` identically in ``h`` (so the
    space spanned by ``x^j e^{lambda x}``, ``j < m``, is generated; Conti–Romani 2011), and
    ``a^n(e^{-lambda h/2}) = 2 e^{-lambda tau h/2}`` for the reproduced ones (:func:`reproduction`).

    >>> from schemes.level_dependent import get
    >>> r = exponential_frequencies(get("exp-cubic-trig"))
    >>> r.status, r.value["generated"], r.value["reproduced"]
    ('certified', {0: 2, -I*t: 1, I*t: 1}, [0])

    Algorithm: the numerator of ``a^n(z)`` is factored in ``z`` over the expressions in ``h`` (sympy);
    each root ``r(h)`` of a factor gives the candidate ``lambda = lim_{h->0} -2 log(-r(h))/h``; a
    candidate is kept only when the exact identities ``D^j a^n(-e^{-lambda h/2}) = 0``, ``j < m``,
    hold (zero test in sympy). Factors sympy cannot solve are listed in ``witness["unsolved"]``
    and candidates neither proved nor refuted in ``witness["unverified_candidates"]`` (then the list
    may be incomplete and the status is inconclusive).
    """
    if values:
        s = s.subs(values)
    z = _Z
    num, _ = sp.fraction(sp.together(sp.expand(sum(c * z ** k for k, c in enumerate(s.mask)))))
    gen: dict = {}
    unsolved = []
    for f, mult in sp.factor_list(num, z)[1]:
        if not f.has(z):
            continue
        try:
            roots = sp.roots(sp.Poly(f, z))
        except (sp.PolynomialError, NotImplementedError):
            roots = {}
        if sum(roots.values()) != sp.degree(f, z):
            unsolved.append(sp.sstr(f))
            continue
        for r, m in roots.items():
            lam = _root_frequency(r)
            if lam is None:
                unsolved.append(sp.sstr(f))
                continue
            if lam.has(sp.Limit) or H in lam.free_symbols:
                unsolved.append(sp.sstr(f))
                continue
            if lam.has(sp.oo, -sp.oo, sp.zoo, sp.nan):      # r(h) does not tend to -1: no frequency
                continue
            gen[lam] = gen.get(lam, 0) + m * mult
    verified, unverified = {}, []
    sym = sum(c * z ** (s.start + k) for k, c in enumerate(s.mask))
    for lam, m in gen.items():
        at = -sp.exp(-lam * H / 2)
        j = 0
        while j < m and _exact_zero(sp.diff(sym, z, j).subs(z, at)):
            j += 1
        if j:
            verified[lam] = j
        if j < m and _certify_nonzero(sp.diff(sym, z, j).subs(z, at), s, None) is None:
            unverified.append(sp.sstr(lam))       # neither proved nor refuted: the list may be incomplete
    a = s.limit()
    tau = sp.simplify(sum(c * (a.start + k) for k, c in enumerate(a.mask)) / 2)
    reproduced = []
    for lam in verified:
        e = _symbol(s, sp.exp(-lam * H / 2)) - 2 * sp.exp(-lam * tau * H / 2)
        if _certify_nonzero(e, s, None) is not None:      # refuted by a certified nonzero value (fast)
            continue
        if _exact_zero(e):
            reproduced.append(lam)
        else:
            unverified.append(f"reproduction of {sp.sstr(lam)}")
    value = {"generated": verified, "reproduced": reproduced}
    st = CERTIFIED if not (unsolved or unverified) else INCONCLUSIVE
    return Result(value=value, status=st,
                  witness={"unsolved_factors": unsolved, "unverified_candidates": unverified,
                           "statement": "x^j e^(lambda x), j < m, generated at every level; e^(lambda x) reproduced"},
                  provenance={"method": "exact factorization in z, limits of roots, exact identities (sympy)"})


# --------------------------------------------------------------------------------------------
# refinement and curves (float64: numerical)
# --------------------------------------------------------------------------------------------

_MASK_FLOATS: dict = {}


def mask_floats(s: LevelDependentScheme, n: int, values) -> np.ndarray:
    """The level-n mask in float64 (evaluated at 60 digits, then rounded; remembered per scheme, level
    and values, since refining several curves with one scheme asks for the same levels)."""
    try:
        key = (id(s), int(n), tuple(sorted((str(k), sp.srepr(v) if isinstance(v, sp.Basic) else repr(v))
                                          for k, v in (values or {}).items())))
    except TypeError:
        key = None
    hit = _MASK_FLOATS.get(key) if key is not None else None
    if hit is not None and hit[0] is s:
        return hit[1].copy()
    out = np.array([float(sp.N(c, 60)) for c in s.mask_at(n, values)])
    if key is not None:
        if len(_MASK_FLOATS) > 512:
            _MASK_FLOATS.clear()
        _MASK_FLOATS[key] = (s, out.copy())     # the scheme is kept: its id cannot be reused meanwhile
    return out


def refine_closed(s: LevelDependentScheme, points, steps: int, values=None) -> np.ndarray:
    """Apply ``S_{a^0}, ..., S_{a^{steps-1}}`` to a closed polygon (float64)."""
    P = np.asarray(points, dtype=float)
    env = _env_values(s, values)
    for n in range(steps):
        a = mask_floats(s, n, env)
        m = len(P)
        out = np.zeros((2 * m,) + P.shape[1:])
        j = np.arange(m)
        for k, c in enumerate(a):
            i = (2 * j + s.start + k) % (2 * m)
            np.add.at(out, i, c * P)
        P = out
    return P


def _curve(name: str):
    if name == "circle":
        return lambda t: np.stack([np.cos(t), np.sin(t)], -1)
    if name == "ellipse":
        return lambda t: np.stack([2 * np.cos(t), np.sin(t)], -1)
    if name == "cardioid":  # a = 1/2, as in seed 003 Fig. 3
        return lambda t: 0.5 * np.stack([1 + 2 * np.cos(t) + np.cos(2 * t), 2 * np.sin(t) + np.sin(2 * t)], -1)
    if name == "astroid":  # b = 2, Fig. 4
        return lambda t: 2 * np.stack([np.cos(t) ** 3, np.sin(t) ** 3], -1)
    if name == "lemniscate":  # a = 2, Fig. 5
        return lambda t: 2 * np.stack([np.cos(t), np.sin(t) * np.cos(t)], -1) / (1 + np.sin(t) ** 2)[:, None]
    raise AnalysisError(f"unknown curve {name!r}; use circle, ellipse, cardioid, astroid, lemniscate")


CURVES = ("circle", "ellipse", "cardioid", "astroid", "lemniscate")
#: refinement steps allowed for curves (points * 2^steps float64 points are kept)
MAX_STEPS = 12


def check_curve_options(points, steps, plot=None) -> None:
    """Reject bad ``points``/``steps``/``plot`` before any computation (one-line AnalysisError)."""
    import os

    if isinstance(points, bool) or not isinstance(points, int) or points < 3:
        raise AnalysisError(f"points must be an integer >= 3 (a closed control polygon), not {points!r}")
    if isinstance(steps, bool) or not isinstance(steps, int) or not 0 <= steps <= MAX_STEPS:
        raise AnalysisError(f"steps must be an integer in 0..{MAX_STEPS}, not {steps!r}")
    if plot:
        d = os.path.dirname(os.path.abspath(str(plot)))
        if not os.path.isdir(d):
            raise AnalysisError(f"cannot write the plot {plot}: directory {d} does not exist")


def _curvature(P: np.ndarray) -> np.ndarray:
    A, B, C = np.roll(P, 1, 0), P, np.roll(P, -1, 0)
    ab, bc, ca = (np.linalg.norm(x, axis=1) for x in (B - A, C - B, A - C))
    cross = (B - A)[:, 0] * (C - A)[:, 1] - (B - A)[:, 1] * (C - A)[:, 0]
    return 2 * cross / (ab * bc * ca)


def curve_deviation(s: LevelDependentScheme, curve: str, values=None, *, points: int = 10,
                    steps: int = 6, plot: str | None = None) -> Result:
    """Refine control points sampled from ``curve`` and measure the distance of the result to it.

    Control points: ``curve(2 pi j / points)``. Reports (NUMERICAL, float64):

    * circle/ellipse: the maximal relative radial deviation (in the coordinates where the
      ellipse is the unit circle) — the value; 0 up to rounding for exact circle generation;
    * all curves: the discrete Hausdorff distance to the exact curve, and the relative
      curvature deviation (circle/ellipse: ``(max k - min k)/mean k``).

    ``plot``: a file name; the curvature plot (and the curves) are written there (matplotlib,
    Agg backend).
    """
    check_curve_options(points, steps, plot)
    f = _curve(curve)
    t0 = 2 * np.pi * np.arange(points) / points
    P = refine_closed(s, f(t0), steps, values)
    witness: dict[str, Any] = {"curve": curve, "points": points, "steps": steps, "refined": len(P)}
    kappa = _curvature(P)
    if curve in ("circle", "ellipse"):
        sc = np.array([1.0, 1.0]) if curve == "circle" else np.array([2.0, 1.0])
        Q = P / sc
        r = np.linalg.norm(Q, axis=1)
        value = float(np.max(np.abs(r - r.mean())) / r.mean())
        witness["mean_radius"] = float(r.mean())
        if curve == "circle":
            witness["curvature_deviation"] = float((kappa.max() - kappa.min()) / abs(kappa.mean()))
    dense = f(np.linspace(0, 2 * np.pi, 20000, endpoint=False))
    # one matrix of squared distances serves both directions (sqrt commutes with min: the same numbers)
    D = dense[::5]
    dx = P[:, 0, None] - D[None, :, 0]
    dy = P[:, 1, None] - D[None, :, 1]
    S2 = dx * dx + dy * dy
    d1, d2 = np.sqrt(S2.min(1)), np.sqrt(S2.min(0))
    haus = float(max(d1.max(), d2.max()))
    witness["hausdorff"] = haus
    witness["curvature_range"] = (float(kappa.min()), float(kappa.max()))
    if curve not in ("circle", "ellipse"):
        value = haus
    if plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(1, 2, figsize=(9, 4))
        ax[0].plot(*np.vstack([dense, dense[:1]]).T, "g:", lw=1, label=curve)
        ax[0].plot(*np.vstack([P, P[:1]]).T, "b-", lw=1, label=s.slug)
        ax[0].set_aspect("equal")
        ax[0].legend(fontsize=7)
        ax[1].plot(kappa, "b-", lw=1)
        ax[1].set_title("discrete curvature")
        fig.tight_layout()
        try:
            fig.savefig(plot)
        except OSError as exc:
            raise AnalysisError(f"cannot write the plot {plot}: {exc.strerror or exc}") from None
        finally:
            plt.close(fig)
        witness["plot"] = plot
    return Result(value=value, status=NUMERICAL, witness=witness,
                  provenance={"method": "float64 refinement", "scheme": s.slug,
                              "parameters": {k: str(v) for k, v in dict(values or {}).items()}})
