"""C^m of a level-dependent scheme at every point of an (open) parameter region.

The hypotheses of Dyn–Levin (1995) are *pointwise* in the parameters: at each parameter point
``p`` one needs (A) the stationary limit ``S_a`` (at ``p``) to be C^m, (B) the weighted series
``sum_n 2^{mn} ||S_{a^n} - S_a||_inf`` to converge at ``p`` and (C) ``a^n`` and ``a`` to have the
same support at ``p``. No uniformity in ``p`` is needed, so the region may be open where a margin
vanishes at its boundary. :func:`smoothness_on_region` certifies

* (B) and (C) on the *closed* box (the closure of the region), with the interval enclosures and
  adaptive bisection of :func:`analysis.levels.series.weighted_series` and
  :func:`analysis.levels.series.same_support`;
* (A) on the *open* interval of the limit's one parameter, exactly: the sublevel set
  ``{p : ||(1/2 S_{a_{m+1}})^L||_inf < 1}`` is computed with real algebraic end points
  (:func:`analysis.stationary.normset.norm_solution_set`) and must contain the whole open
  interval. This reaches an open end where the norm tends to 1 (seed 003: ``omega -> 0``, where
  the limit becomes Chaikin's scheme), which no finite cover by closed boxes with a fixed-L
  enclosure of the norm can do.

Examples
--------
>>> import sympy as sp
>>> from schemes.seed003 import HYPERBOLIC
>>> r = smoothness_on_region(HYPERBOLIC, {"alpha": (0, sp.pi / 3), "omega": (0, (sp.sqrt(6) - 1) / 80)},
...                          2, difference=1, open_param="omega")
>>> r.status, r.value, r.witness["region"]
('certified', True, 'alpha in [0, pi/3], omega in (0, -1/80 + sqrt(6)/80)')
>>> r.witness["hypotheses"]["limit_C^1"].witness["set"]
'(0, -1/80 + sqrt(6)/80)'

Algorithm
---------
(A) for ``L = 1, ..., L_max``: the exact norm set over ``(lo - 1, hi + 1)``; certified when one of
its intervals contains ``(lo, hi)`` (exact comparison of real algebraic end points); else the
piecewise exact parametric norms of :func:`analysis.regularity.interior.ck_interior`.
(B), (C): as in :func:`analysis.levels.series.smoothness`, over the closed box, bisected at most
``depth`` times. With ``difference = k`` the theorem is applied to ``e^n = (2/(1+z))^k a^n`` with
``m - k`` (C^m of ``a^n`` from C^{m-k} of ``e^n``, the difference-scheme argument).

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*,
J. Math. Anal. Appl. 193 (1995) 594-621 (Theorem 1.1 of seed 003).
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numerica 11 (2002) 73-144
(the norm test and difference schemes).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Mapping

import sympy as sp

from ..algebra.algebraic import RealAlgebraic
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .level_dependent import LevelDependentScheme
from .series import _dyn_levin_hypotheses, _dyn_levin_target, same_support, weighted_series
from ..algebra.reader import as_expr


def _covers(part, lo, hi) -> bool:
    """Does the interval ``part`` of an IntervalSet contain the open interval ``(lo, hi)``?"""
    plo, phi, _, _ = part
    left = plo is None or plo.compare(RealAlgebraic.from_expr(lo)) <= 0
    right = phi is None or phi.compare(RealAlgebraic.from_expr(hi)) >= 0
    return left and right


def limit_smoothness_open(a: LaurentSymbol, m: int, name: str, lo, hi, *, L_max: int = 4,
                          budget: int = 30_000) -> Result:
    """Certify that ``S_a`` is C^m for every value of its one parameter ``name`` in the open ``(lo, hi)``.

    Exact: the Dyn–Levin norm test ``||(1/2 S_{a_{m+1}})^L||_inf < 1`` holds on an exact sublevel
    set containing ``(lo, hi)`` for some ``L <= L_max``; failing that, on pieces with their own L
    (:func:`analysis.regularity.interior.ck_interior`, L <= 12, with ``budget`` work units: counted,
    never timed); otherwise inconclusive with the exact strips that remain.

    >>> w = sp.Symbol("omega")
    >>> a = LaurentSymbol.from_mask([-5*w, -7*w, sp.Rational(1,4)+3*w, sp.Rational(3,4)+9*w,
    ...                              sp.Rational(3,4)+9*w, sp.Rational(1,4)+3*w, -7*w, -5*w], start=-4)
    >>> limit_smoothness_open(a, 2, "omega", 0, (sp.sqrt(6) - 1) / 80).status
    'certified'
    >>> r = limit_smoothness_open(a, 2, "omega", 0, sp.Rational(1, 40), L_max=2, budget=5000)
    >>> r.status, r.witness["strips"][0][1]
    ('inconclusive', 1/40)
    """
    lo, hi = as_expr(lo), as_expr(hi)
    if not bool(lo < hi):
        raise AnalysisError(f"empty open interval {name} in ({lo}, {hi})")
    return _limit_smoothness_open(a, m, name, lo, hi, L_max, budget)


@lru_cache(maxsize=64)
def _limit_smoothness_open(a: LaurentSymbol, m: int, name: str, lo, hi, L_max: int, budget: int) -> Result:
    """:func:`limit_smoothness_open` (a pure function of its arguments, remembered: the region theorem, the box
    cover and the claims ask again for the same limit on the same interval)."""
    from ..algebra.factorization import smoothing_factor
    from ..stationary.normset import norm_solution_set

    k = smoothing_factor(a, exceptional=False).value
    if k < m + 1:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"smooth": None, "reason": f"(1+z)^{m + 1} does not divide a generically"},
                      provenance={"method": "exact division by (1+z)"})
    tried = []
    for L in range(1, L_max + 1):
        r = norm_solution_set(a, m + 1, L, name, within=(lo - 1, hi + 1))
        tried.append(f"L = {L}: {r.value}")
        if any(_covers(part, lo, hi) for part in r.value.parts):
            return Result(value=True, status=CERTIFIED,
                          witness={"smooth": True, "test": "Dyn-Levin norm test on an exact set",
                                   "set": str(r.value), "L": L, "m": m + 1,
                                   "interval": f"({sp.sstr(lo)}, {sp.sstr(hi)})"},
                          provenance={"method": "exact norm set (analysis.stationary.normset), real algebraic "
                                                "end points compared exactly"})
    # several L on several pieces: exact parametric norms on boxes and open end pieces (issue 14)
    from ..regularity.interior import ck_interior

    r = ck_interior(a, m, lo, hi, name, L_max=max(L_max, 12), budget=budget)
    if r.is_certified:
        return Result(value=True, status=CERTIFIED,
                      witness={"smooth": True, "test": "Dyn-Levin norm tests on pieces (exact parametric norms)",
                               "set": str(r.value["certified"]), "pieces": len(r.witness.get("pieces", ())),
                               "m": m + 1, "interval": f"({sp.sstr(lo)}, {sp.sstr(hi)})"},
                      provenance={"method": "analysis.regularity.interior.ck_interior (exact Bernstein bounds on "
                                            "rational boxes, exact end pieces)"})
    strips = ", ".join(f"({sp.sstr(u)}, {sp.sstr(v)})" for u, v in r.value["strips"])
    return Result(value=None, status=INCONCLUSIVE,
                  witness={"smooth": None, "sets": tried, "certified_part": str(r.value["certified"]),
                           "strips": r.value["strips"],
                           "reason": f"no exact norm set with L <= {L_max} contains ({sp.sstr(lo)}, {sp.sstr(hi)}); "
                                     f"norm tests on pieces (L <= {max(L_max, 12)}) certify {r.value['certified']} "
                                     f"and leave {strips}"},
                  provenance={"method": "exact norm sets + analysis.regularity.interior.ck_interior"})


def _describe(env: Mapping[str, Any], open_param: str | None) -> str:
    out = []
    for k, v in env.items():
        if isinstance(v, tuple):
            br = "()" if k == open_param else "[]"
            out.append(f"{k} in {br[0]}{sp.sstr(v[0])}, {sp.sstr(v[1])}{br[1]}")
        else:
            out.append(f"{k} = {sp.sstr(v)}")
    return ", ".join(out)


def smoothness_on_region(s: LevelDependentScheme, values: Mapping[str, Any], m: int, *, difference: int = 0,
                         open_param: str | None = None, L_max: int = 4, N: int = 40, depth: int = 2) -> Result:
    """C^m of ``{S_{a^n}}`` at every point of a parameter region (Dyn–Levin, hypotheses pointwise).

    ``values`` maps each parameter to an exact value or a closed box ``(lo, hi)``. The limit may
    depend on one boxed parameter, ``open_param``: its box is read as the *open* interval for
    hypothesis (A) (the other hypotheses are certified on the closed box, which contains it).
    Certified ``value = True`` means: C^m at every point of the region in ``witness["region"]``.
    """
    target, mm, env, a_sub = _dyn_levin_target(s, values, m, difference)
    free = [p.name for p in a_sub.params]
    if len(free) > 1:
        raise AnalysisError(f"the limit depends on several boxed parameters ({', '.join(free)}): fix all but one")
    if free and free[0] != open_param:
        raise AnalysisError(f"the limit depends on {free[0]}: give open_param={free[0]!r} (a box of {free[0]})")
    if free:
        lo, hi = env[free[0]]
        lim = limit_smoothness_open(a_sub, mm, free[0], lo, hi, L_max=L_max)
    else:
        from .series import stationary_smoothness

        lim = stationary_smoothness(a_sub, mm, L_max=L_max)
    ser = weighted_series(target, env, mm, N=N, depth=depth)
    sup = same_support(target, env, N=N, depth=depth)
    hyps, ok, failed = _dyn_levin_hypotheses(sup, lim, ser, mm)
    route = ("direct" if not difference else
             f"divided differences of order {difference}: e^n = (2/(1+z))^{difference} a^n")
    return Result(value=True if ok else None, status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"claim": f"C^{m}", "route": route, "region": _describe(env, open_param if free else None),
                           "hypotheses": hyps, "failed": failed,
                           "theorem": "Dyn-Levin 1995 (seed 003 Theorem 1.1), at every point of the region: same "
                                      "support and the series on the closed box, S_a C^m on the open interval "
                                      "(exact norm set)"},
                  provenance={"scheme": s.slug, "parameters": env, "method": "analysis.levels.region"})
