"""C^k verdicts of a level-dependent scheme at every point of a parameter box (adaptive cover).

:func:`level_smoothness_box` is :func:`analysis.levels.ck.level_smoothness` on one or two closed
parameter boxes. The theorems are pointwise in the parameters, so "C^k at every point of the box"
follows from a finite cover of the box by sub-boxes, each certified by *some* route:

1. **Dyn–Levin direct** and 2. **Dyn–Levin on the j-th divided difference scheme**
   ``e^n = (2/(1+z))^j a^n`` (``(1+z)^j | a^n`` exactly, identically in n and in the parameters):
   on a closed sub-box ``B``, same support at every level (:func:`analysis.levels.series.same_support`,
   Arb enclosures over ``B``), ``sum_n 2^{(k-j)n} ||S_{e^n} - S_e||_inf < oo`` bounded on ``B``
   (:func:`analysis.levels.series.weighted_series`: Arb partial sums + Taylor-model tail over ``B``),
   and the stationary limit ``S_e`` C^{k-j} on ``B``: exact (Dyn–Levin norm test; when the limit
   depends on a parameter, exact norm sets over the parameter with real algebraic end points,
   :func:`analysis.stationary.normset.norm_solution_set`, computed once and tested for containment
   of each sub-interval; with ``open_param`` the limit's hypothesis is certified once on the *open*
   interval, :func:`analysis.levels.region.limit_smoothness_open`, as ``subdiv series --C K --open``
   does, and the region is the box with that parameter's interval open);
2′. **generalized divided differences** (:mod:`.gendiff`): (H1) ``p_n | a^n`` proved *exactly,
   identically in n and in the parameters* (the factorization over ``Q(params)[z, h, exp(g h)]``;
   the frequencies are searched with the parameters declared positive, so ``+-i theta`` pair up,
   and each candidate ``p_n`` is then proved to divide ``a^n`` on the scheme itself, for every real
   parameter value, 0 included), (H2) convergence (the C^0 cover of the whole box, else Dyn–Levin
   direct on the sub-box), (H3) Dyn–Levin on ``c^n = 2^j a^n/p_n`` on the sub-box as in 1.

Asymptotic similarity (route 3 of :mod:`.ck`) is not tried on boxes: its JSR condition
``alpha(S_a) > k`` is a point computation.

"Not C^d on the whole box" (route 4): the exponential B-spline form is recognised *identically in
the parameters* (:func:`analysis.levels.expbspline.recognise` on the parametric scheme: an exact
rational identity in ``z``, the generators ``exp(g h)`` and the parameters) and the normalisers
``1 + exp(lambda_i(p) 2^-(n+1))`` are certified non-zero for every level and every ``p`` in the box
(:mod:`.expbspline_box`, the box version of ``expbspline._normalisers_nonzero``).

**Arity m** (``arity=m``, ``h = m^-n``; issue 12/13 item 6): the same cover with dilation m, as
``level_smoothness(..., arity=m)``: series and supports with ``arity``, the divided difference schemes
``(m/q_m)^j a^n`` (``q_m = 1 + z + ... + z^(m-1)``; these also need the convergence of ``{S_(a^n)}`` on the
sub-box, the case ``Lambda = (0, ..., 0)`` of :mod:`.gendiff`), the factors ``q_m(e^{lambda m^-(n+1)} z)``,
the limit's C^k by the m-ary norm test, and the normalisers ``q_m(e^{lambda m^-(n+1)})`` (zero iff
``v^m = 1 != v``). ``--open`` is binary only.

A sub-box where no route succeeds is bisected (every boxed parameter) at most ``depth`` times;
the sub-boxes left are reported with exact rational ends and, per route, the hypothesis that
failed. C^k is certified only when the cover is complete.

Examples
--------
>>> import sympy as sp
>>> from schemes.level_dependent import get
>>> r = level_smoothness_box(get("exp-chaikin-trig"), {"t": (sp.Rational(1, 2), 2)})
>>> r.value, r.status, r.witness["exact"], r.witness["region"]
(1, 'certified', True, 't in [1/2, 2]')
>>> [(v["k"], v["verdict"], v["status"]) for v in r.witness["verdicts"]]
[(0, 'C^0', 'certified'), (1, 'C^1', 'certified'), (2, 'not C^2', 'certified')]

Algorithm
---------
For ``k = 0, 1, ...`` up to the limit's smoothness (parameter-free limit: the Hölder/JSR verdict of
:func:`analysis.regularity.smoothness`, as in :mod:`.ck`; parametric limit: while ``(1+z)^{k+1}``
divides it generically): :func:`analysis.levels.series.adaptive_boxes` over ``pieces`` sub-boxes per
parameter, each sub-box tried by the routes in the order of :mod:`.ck` (``j = k`` first when
``(1+z)^k`` divides ``a^n``, then direct, then smaller ``j``, then 2′). A k left undecided is
certified when a higher k' is certified on the whole box (C^k' implies C^k). Series, supports and limit
tests are cached per (scheme, sub-box). Route 4 bisects the box (``depth + 4`` times at most) until
``1 + exp(lambda 2^-(n+1))`` excludes 0 in complex ball arithmetic at the finitely many levels
with ``sup |lambda| 2^-(n+1) >= pi`` (for the others ``1 + e^mu = 0`` needs ``|mu| >= pi``).

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*,
J. Math. Anal. Appl. 193 (1995) 594-621.
N. Dyn, D. Levin, A. Luzzatto, *Exponentials reproducing subdivision schemes*, Found. Comput.
Math. 3 (2003) 187-206 (generalized differences).
M. Unser, T. Blu, *Cardinal exponential splines: part I*, IEEE Trans. Signal Process. 53 (2005)
1425-1438 (exponential B-splines: the "not C^d" of route 4).
"""

from __future__ import annotations

from typing import Any, Mapping

import sympy as sp

from .ck import _Differences, check_real, limit_smoothness
from .divided import q_label
from .expbspline_box import conjugation_closed_box, exact_box, normalisers_nonzero_box, not_ck_box
from .gendiff import _subsets, exponential_factors, generalized_difference
from .hseries import prefill_taylor
from .level_dependent import H, LevelDependentScheme
from .region import _describe, limit_smoothness_open
from .series import _bisect, _parse_values, _split, same_support, stationary_smoothness, weighted_series
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..algebra.reader import as_expr

__all__ = ["conjugation_closed_box", "level_smoothness_box", "normalisers_nonzero_box", "not_ck_box"]


def _ordinal(j: int) -> str:
    return f"{j}{ {1: 'st', 2: 'nd', 3: 'rd'}.get(j if j < 20 else j % 10, 'th')}"


def _ok(r: Result) -> bool:
    return r.is_certified and (r.value is True or r.witness.get("verdict") == "convergent")


def _key(box: Mapping) -> tuple:
    return tuple(sorted((k, v if not isinstance(v, tuple) else (sp.sstr(v[0]), sp.sstr(v[1])))
                        for k, v in box.items()))


def _with_box_signs(s: LevelDependentScheme, env: Mapping) -> LevelDependentScheme:
    """The scheme with a boxed parameter re-declared positive (negative) when its box lies in (0, oo)
    ((-oo, 0)): valid on the box, and lets the exact factorizations pair ``+-i theta`` as conjugates."""
    rep, params = {}, []
    for p in s.params:
        v = env.get(p.name)
        new = p
        if isinstance(v, tuple) and not p.is_positive and not p.is_negative:
            if bool(as_expr(v[0]) > 0):
                new = sp.Symbol(p.name, positive=True)
            elif bool(as_expr(v[1]) < 0):
                new = sp.Symbol(p.name, negative=True)
        if new is not p:
            rep[p] = new
        params.append(new)
    if not rep:
        return s
    return LevelDependentScheme(tuple(c.subs(rep) for c in s.mask), s.start, tuple(params), slug=s.slug,
                                title=s.title, source=s.source, notes=s.notes)


def _smoothing_order(a, arity: int) -> int:
    """The largest k with ``(1+z)^k`` (arity m: ``q_m^k``) dividing the limit generically (exact)."""
    from ..algebra.factorization import smoothing_factor

    return smoothing_factor(a, exceptional=False, arity=arity).value


def _restrict(box: Mapping, t: LevelDependentScheme) -> dict:
    names = set(t.param_names)
    return {k: v for k, v in box.items() if k in names}


class _BoxGeneralizedDifferences:
    """Route 2′'s generalized difference schemes on a box.

    The *search* for the frequencies (:func:`analysis.levels.gendiff.exponential_factors`) and for
    their conjugation-closed subsets runs on a copy whose real parameters without a sign are
    declared positive (so ``+-i theta`` pair up even when the box contains 0); each candidate is
    then *proved* on the scheme itself: :func:`analysis.levels.gendiff.generalized_difference`
    re-checks ``a^n = p_n b^n`` exactly, as a rational identity in ``h``, ``exp(g h)`` and the
    parameters, so H1 holds for every real parameter value (0 included) where the mask is defined.
    """

    def __init__(self, s: LevelDependentScheme, arity: int = 2):
        self.s, self.arity = s, arity
        loose = {p.name: (1, 2) for p in s.params if p.is_real and not (p.is_positive or p.is_negative)}
        self.probe = _with_box_signs(s, loose) if loose else s
        self.back = {q: p for p, q in zip(s.params, self.probe.params) if p is not q}
        self._schemes: dict = {}

    def factors(self) -> Result:
        fac = exponential_factors(self.probe, self.arity)
        if fac.value is None or not self.back:
            return fac
        return Result(value=tuple(x.xreplace(self.back) for x in fac.value), status=fac.status,
                      witness={**fac.witness, "search": "frequencies found with the parameters declared positive; "
                               "p_n | a^n is proved for each subset on the scheme itself (generalized_difference)"},
                      provenance=fac.provenance)

    def subsets(self, j: int) -> list[tuple]:
        fac = exponential_factors(self.probe, self.arity)
        return [tuple(x.xreplace(self.back) for x in sub) for sub in _subsets(fac.value, j)]

    def get(self, subset) -> tuple[LevelDependentScheme | None, Result]:
        if subset not in self._schemes:
            try:
                self._schemes[subset] = generalized_difference(self.s, subset, self.arity)
            except (AnalysisError, ValueError, TypeError) as e:      # no proof of H1: inconclusive
                self._schemes[subset] = (None, Result(value=None, status=INCONCLUSIVE, witness={"reason": str(e)}))
        return self._schemes[subset]


class _Context:
    """One scheme on one box: the difference schemes, the caches of series, supports and limit tests."""

    def __init__(self, s: LevelDependentScheme, env: dict, open_param: str | None, N: int, L_max: int,
                 arity: int = 2):
        self.s, self.env, self.open_param, self.N, self.L_max = s, env, open_param, N, L_max
        self.arity = arity
        self.diffs = _Differences(s, arity)    # the divided difference schemes, shared with ck.py's chain
        self.gd = _BoxGeneralizedDifferences(s, arity)
        self.cache: dict = {}
        self.converges: Result | None = None

    def difference(self, j: int) -> LevelDependentScheme | None:
        return self.diffs.get(j)

    def divisibility(self, k: int) -> int:
        return self.diffs.divisibility(k)

    # ---------------------------------------------------------------- the limit's C^m on a sub-box
    def limit_ck(self, a, m: int, box: Mapping) -> Result:
        free = [p.name for p in a.params]
        if not free:
            key = ("lim", str(a), m)
            if key not in self.cache:
                self.cache[key] = stationary_smoothness(a, m, L_max=self.L_max, arity=self.arity)
            return self.cache[key]
        if len(free) > 1:
            return Result(value=None, status=INCONCLUSIVE,
                          witness={"smooth": None, "reason": f"the limit depends on several parameters "
                                   f"({', '.join(free)}): its C^{m} on a two-parameter box is not implemented"})
        name = free[0]
        if name == self.open_param:
            lo, hi = self.env[name]
            key = ("open", str(a), m)
            if key not in self.cache:
                self.cache[key] = limit_smoothness_open(a, m, name, lo, hi, L_max=self.L_max)
            return self.cache[key]
        return self._limit_closed(a, m, name, box[name])

    def _limit_closed(self, a, m: int, name: str, sub) -> Result:
        """C^m of ``S_a`` on the closed sub-interval ``sub`` of ``name``: exact norm sets over the whole box."""
        from ..algebra.algebraic import IntervalSet
        from ..stationary.normset import norm_solution_set

        key = ("sf", str(a))
        if key not in self.cache:
            self.cache[key] = _smoothing_order(a, self.arity)
        if self.cache[key] < m + 1:
            q = "(1+z)" if self.arity == 2 else f"({q_label(self.arity)})"
            return Result(value=None, status=INCONCLUSIVE,
                          witness={"smooth": None, "reason": f"{q}^{m + 1} does not divide the limit generically"})
        lo, hi = self.env[name]
        for L in range(1, self.L_max + 1):
            key = ("set", str(a), m, L)
            if key not in self.cache:
                self.cache[key] = norm_solution_set(a, m + 1, L, name, within=(lo - 1, hi + 1),
                                                     arity=self.arity).value
            for part in self.cache[key].parts:
                one = IntervalSet([part])
                if one.contains(sub[0]) and one.contains(sub[1]):
                    return Result(value=True, status=CERTIFIED,
                                  witness={"smooth": True, "test": "Dyn-Levin norm test on an exact set",
                                           "set": str(self.cache[key]), "L": L, "m": m + 1,
                                           "interval": f"[{sp.sstr(sub[0])}, {sp.sstr(sub[1])}]"},
                                  provenance={"method": "exact norm set (analysis.stationary.normset)"})
        if self.open_param is None:
            advice = (f"; if the norm tends to 1 at an end of the box of {name}, read that interval as open "
                      f"(--open {name}, as subdiv series --C K --open)")
        else:
            advice = ""
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"smooth": None, "reason": f"no exact norm set with L <= {self.L_max} contains "
                               f"{name} in [{sp.sstr(sub[0])}, {sp.sstr(sub[1])}]{advice}"})

    def _is_difference_limit(self, t: LevelDependentScheme, j: int) -> bool:
        """``(1+z)^j lim t^n = 2^j lim a^n`` exactly (checked once per scheme); arity m: not used (False)."""
        if self.arity != 2:
            return False
        key = ("dlim", id(t), j)
        if key not in self.cache:
            z = sp.Symbol("z")
            self.cache[key] = sp.simplify((1 + z) ** j * t.limit().expr() - 2 ** j * self.s.limit().expr()) == 0
        return self.cache[key]

    # ---------------------------------------------------------------- Dyn-Levin on a sub-box
    def dyn_levin(self, t: LevelDependentScheme, box: Mapping, m: int, k: int | None = None) -> Result:
        """Dyn–Levin 1995 for ``{S_{t^n}}`` C^m on the closed sub-box (limit, series, support; first failure).

        ``k``: ``t`` is a (generalized) divided difference scheme of order ``k - m`` of the scheme, whose
        limit is ``2^j a/(1+z)^j``; its C^m norm test is then the C^k norm test of ``a`` itself
        (``(2z/(1+z))^(m+1) 2^j a/(1+z)^j = z^-j (2z/(1+z))^(k+1) a``, a shift: the same norms), so the
        limit's test is computed once per k for every route.
        """
        b = _restrict(box, t)
        hyps: dict[str, Result] = {}
        if k is None or k == m or not self._is_difference_limit(t, k - m):
            lim = self.limit_ck(t.limit(), m, b)
        else:
            lim = self.limit_ck(self.s.limit(), k, _restrict(box, self.s))
        hyps[f"limit_C^{m}"] = lim
        if _ok(lim) and any(H in c.free_symbols for c in t.mask):
            key = ("series", t.slug, id(t), m, _key(b))
            if key not in self.cache:
                try:
                    self.cache[key] = weighted_series(t, b, m, N=self.N, arity=self.arity)
                except AnalysisError as e:
                    self.cache[key] = Result(status=INCONCLUSIVE, witness={"verdict": "unknown", "error": str(e)})
            hyps[f"series_m={m}"] = ser = self.cache[key]
            if _ok(ser):
                key = ("support", t.slug, id(t), _key(b))
                if key not in self.cache:
                    try:
                        self.cache[key] = same_support(t, b, N=self.N, arity=self.arity)
                    except AnalysisError as e:
                        self.cache[key] = Result(status=INCONCLUSIVE, witness={"failed": str(e)})
                hyps["same_support"] = self.cache[key]
        failed = [name for name, r in hyps.items() if not _ok(r)]
        ok = not failed and len(hyps) == (3 if any(H in c.free_symbols for c in t.mask) else 1)
        why = "; ".join(_why(name, hyps[name]) for name in failed)
        # a series certified divergent on the sub-box diverges on every smaller box: no use bisecting
        failed = [f"{name} (divergent)" if name.startswith("series") and hyps[name].is_certified
                  and hyps[name].witness.get("verdict") == "divergent" else name for name in failed]
        return Result(value=True if ok else None, status=CERTIFIED if ok else INCONCLUSIVE,
                      witness={"claim": f"C^{m}", "hypotheses": hyps, "failed": failed, "why": why},
                      provenance={"scheme": t.slug, "box": exact_box(b)})


def _why(name: str, r: Result) -> str:
    w = r.witness
    if name.startswith("series"):
        v = w.get("verdict")
        return f"{name}: " + (w.get("error") or ("divergent (certified)" if v == "divergent" else
                                                  "not decided on this box"))
    if name == "same_support":
        return f"{name}: failed at {w.get('failed')}"
    return f"{name}: {w.get('reason') or w.get('test') or 'not certified'}"


# -------------------------------------------------------------------- one k on one sub-box
def _decide(ctx: _Context, box: dict, k: int, max_tries: int = 6) -> dict:
    tried = []
    jmax = ctx.divisibility(k)
    order = ([jmax] if jmax == k and k > 0 else []) + [0] + [j for j in range(jmax, 0, -1) if j != k]
    for j in order:
        r = ctx.dyn_levin(ctx.difference(j), box, k - j, k)
        route = "Dyn-Levin direct" if j == 0 else f"Dyn-Levin on the {_ordinal(j)} divided difference scheme"
        if _ok(r) and j > 0 and ctx.arity != 2:
            # arity m: the divided-difference argument is the generalized one with Lambda = (0, ..., 0)
            # (analysis.levels.gendiff), which also needs the convergence of {S_(a^n)} (H2), as in ck.py
            conv = _converges(ctx, box)
            if not _ok(conv):
                tried.append({"route": route, "failed": ["H2: convergence of {S_(a^n)} on the sub-box"],
                              "why": conv.witness.get("why", "")})
                continue
            return {"status": CERTIFIED, "route": route, "j": j,
                    "hypotheses": {**r.witness["hypotheses"], "convergence": conv}}
        if _ok(r):
            return {"status": CERTIFIED, "route": route, "j": j, "hypotheses": r.witness["hypotheses"]}
        tried.append({"route": route, "failed": r.witness["failed"], "why": r.witness["why"]})
    if k > 0:
        tried.append(_gendiff(ctx, box, k, max_tries))
        if tried[-1].get("status") == CERTIFIED:
            return tried[-1]
    return {"status": INCONCLUSIVE, "tried": tried}


def _converges(ctx: _Context, box: dict) -> Result:
    """H2: ``{S_(a^n)}`` converges on the sub-box (the C^0 cover of the whole box, else Dyn–Levin direct there)."""
    conv = ctx.converges
    if conv is not None and conv.is_certified:
        return conv
    d = ctx.dyn_levin(ctx.s, box, 0)
    if not _ok(d):
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"why": f"C^0 is not certified on the sub-box ({d.witness['why']})"})
    return Result(value=True, status=CERTIFIED, witness={"statement": "{S_(a^n)} converges on the sub-box",
                                                         "route": "Dyn-Levin direct", **d.witness},
                  provenance=d.provenance)


def _gendiff(ctx: _Context, box: dict, k: int, max_tries: int) -> dict:
    route = "Dyn-Levin on a generalized divided difference scheme (exponential factors)"
    fac = ctx.gd.factors()
    if fac.value is None or not fac.witness["nonzero"]:
        why = fac.witness.get("reason") or ("no exponential factor with lambda != 0 divides a^n identically in n "
                                            "and in the parameters")
        return {"route": route, "failed": ["H1: exponential factor p_n | a^n for every n"], "why": why}
    conv = _converges(ctx, box)
    if not _ok(conv):
        return {"route": route, "failed": ["H2: convergence of {S_(a^n)} on the sub-box"], "why": conv.witness["why"]}
    fails = []
    for j in range(min(k, len(fac.value)), 0, -1):
        for subset in ctx.gd.subsets(j)[:max_tries]:
            c, h1 = ctx.gd.get(subset)
            if c is None:
                fails.append(f"H1: {h1.witness['reason']}")
                continue
            h3 = ctx.dyn_levin(c, box, k - j, k)
            names = ", ".join(sp.sstr(x) for x in subset)
            if _ok(h3):
                return {"status": CERTIFIED, "j": j, "r": k - j,
                        "route": (f"Dyn-Levin on the {_ordinal(j)} generalized divided difference scheme "
                                  f"(exponential factors {names})"),
                        "hypotheses": {"H1": h1, "H2": conv, "H3": h3},
                        "Lambda": [sp.sstr(x) for x in fac.value]}
            fails.append(f"H3 ({names}): {h3.witness['why']}")
    return {"route": route, "failed": ["H3: Dyn-Levin on c^n = 2^j a^n/p_n"], "why": "; ".join(fails[:3])}


def _split_names(ctx: _Context, outcome: dict, box: dict) -> list[str]:
    """The boxed parameters worth bisecting after ``outcome``: a failed series, support or H3 may
    improve on smaller boxes in every parameter, a failed limit test only in the limit's parameter;
    H1 (exact, identically in the parameters), a parameter-free limit and a series certified
    divergent on the sub-box do not improve on smaller boxes."""
    boxed = [k for k, v in box.items() if isinstance(v, tuple)]
    lim = {p.name for p in ctx.s.limit().params}
    names: set[str] = set()
    for t in outcome.get("tried", []):
        for f in t["failed"]:
            if f.startswith("limit_C"):
                names |= lim
            elif not (f.startswith("H1") or f.endswith("(divergent)")):
                names |= set(boxed)
    return [k for k in boxed if k in names]


def _bisect_in(box: dict, names: list[str]) -> list[dict]:
    """Halve the boxed parameters ``names`` of ``box``."""
    return [{**box, **half} for half in _bisect({k: box[k] for k in names})]


def _cover(ctx: _Context, k: int, pieces: int, depth: int) -> dict:
    """Adaptive cover of the box for C^k: the certified sub-boxes (with routes) and the undecided ones."""
    done, todo = [], [(b, 0) for b in _split(ctx.env, pieces)]
    while todo:
        b, d = todo.pop(0)
        try:
            o = _decide(ctx, b, k)
        except AnalysisError as e:                 # e.g. a level not finite on a wide box: bisect
            o = {"status": INCONCLUSIVE, "tried": [{"route": "all", "failed": ["error"], "why": str(e)}]}
        names = _split_names(ctx, o, b) if o["status"] != CERTIFIED and d < depth else []
        if names:
            todo.extend((c, d + 1) for c in _bisect_in(b, names))
        else:
            done.append((b, o))
    done.sort(key=lambda bo: tuple(float(sp.N(v[0])) for v in bo[0].values() if isinstance(v, tuple)))
    cover = [{"box": exact_box(b), **o} for b, o in done if o["status"] == CERTIFIED]
    undecided = [{"box": exact_box(b), "tried": o["tried"]} for b, o in done if o["status"] != CERTIFIED]
    routes: dict[str, int] = {}
    for c in cover:
        routes[c["route"]] = routes.get(c["route"], 0) + 1
    ok = not undecided
    out = {"k": k, "verdict": f"C^{k}" if ok else "undecided", "status": CERTIFIED if ok else INCONCLUSIVE,
           "routes": routes, "sub_boxes": len(done), "cover": cover, "undecided": undecided}
    if ok and len(routes) == 1:
        out["route"] = next(iter(routes))
    return out


# -------------------------------------------------------------------- the entry point
def _limit_top(ctx: _Context, a, k_max: int | None) -> tuple[int, int | None, dict, int]:
    """``(k_lim, not_k, a_smooth, top)``: the limit's certified smoothness and the last k to decide."""
    cap = 12 if k_max is None else k_max
    if not a.params:
        from ..regularity import smoothness as regularity_smoothness

        def dilated_smoothness(a, k):
            return stationary_smoothness(a, k, L_max=ctx.L_max, arity=ctx.arity)

        k_lim, not_k, a_smooth = limit_smoothness(a, cap, regularity_smoothness if ctx.arity == 2 else dilated_smoothness)
        return k_lim, not_k, a_smooth, k_lim
    top = min(cap, _smoothing_order(a, ctx.arity) - 1)
    return -1, None, {}, top


def level_smoothness_box(s: LevelDependentScheme, values: Mapping[str, Any], *, pieces: int = 1, depth: int = 2,
                         k_max: int | None = None, open_param: str | None = None, N: int = 40,
                         L_max: int = 4, arity: int | None = None) -> Result:
    """C^k of ``{S_{a^n}}`` at every point of a parameter box, for each k (see the module).

    ``values``: every parameter an exact value or a closed box ``(lo, hi)`` (one or two boxes).
    ``open_param``: a boxed parameter of the limit whose interval is read as open for the limit's
    hypothesis (the region is then the box with that interval open). ``value``: the largest k
    with C^k certified on the whole region for every ``k' <= k`` (``-1``: none);
    ``witness["verdicts"]``: per k the cover (sub-boxes with their routes) and the undecided
    sub-boxes (exact ends, per route the failed hypothesis); ``witness["not_C^k"]``, ``"exact"``
    as in :func:`analysis.levels.ck.level_smoothness`.

    ``arity`` m (default: the scheme's): ``s`` is read with ``h = m^-n``: the routes with dilation m, as
    ``level_smoothness(..., arity=m)`` (divided differences ``(m/q_m)^j a^n`` need the convergence of
    ``{S_(a^n)}`` on the sub-box, the normalisers are ``q_m(exp(lambda m^-(n+1)))``); ``open_param`` is binary only.

    >>> from schemes.level_dependent import get
    >>> r = level_smoothness_box(get("ternary-exp-bspline-1-hyp"), {"t": (sp.Rational(1, 2), 2)})
    >>> r.value, r.witness["exact"], [(v["verdict"], v["status"]) for v in r.witness["verdicts"]]
    (0, True, [('C^0', 'certified'), ('not C^1', 'certified')])
    """
    if s.arity != 2 and arity not in (None, 2, s.arity):
        raise AnalysisError(f"scheme {s.slug!r} has arity {s.arity}, not {arity}")
    arity = s.arity if arity is None or s.arity != 2 else arity
    if isinstance(arity, bool) or not isinstance(arity, int) or arity < 2:
        raise AnalysisError(f"arity must be an integer >= 2, not {arity!r}")
    if open_param is not None and arity != 2:
        raise AnalysisError("open_param (--open) is available for binary schemes only (the open-interval limit test "
                            "is binary)")
    if isinstance(pieces, bool) or not isinstance(pieces, int) or pieces < 1:
        raise AnalysisError(f"pieces must be an integer >= 1, not {pieces!r}")
    if isinstance(depth, bool) or not isinstance(depth, int) or not 0 <= depth <= 8:
        raise AnalysisError(f"depth must be between 0 and 8, not {depth!r}")
    values = dict(values or {})
    point = {k: v for k, v in values.items() if not isinstance(v, (tuple, list))}
    if point:
        for k in point:
            s._param(str(k))
        s = s.subs(point)
    boxes = {k: v for k, v in values.items() if isinstance(v, (tuple, list))}
    if not boxes:
        raise AnalysisError("give a box (NAME=LOW,HIGH) for at least one parameter; for values only use "
                            "analysis.levels.ck.level_smoothness")
    if len(boxes) > 2:
        raise AnalysisError(f"at most two parameter boxes, not {len(boxes)} ({', '.join(boxes)})")
    for k in boxes:
        s._param(str(k))                            # an unknown name: one-line error
    missing = sorted(set(s.param_names) - set(boxes))
    if missing:
        raise AnalysisError(f"give a value or a box for {', '.join(missing)} (--param NAME=VALUE or --box NAME=LOW,HIGH)")
    env = _parse_values(s, boxes)
    if open_param is not None and not isinstance(env.get(open_param), tuple):
        raise AnalysisError(f"open_param {open_param} needs a box for {open_param}")
    s = _with_box_signs(s, env)
    mid = {k: sp.nsimplify(sp.Rational(str(sp.N((v[0] + v[1]) / 2, 15)))) for k, v in env.items()}
    check_real(s.subs(mid), arity=arity)                       # one-line error on a mask that is not real (box midpoint)
    if all(H not in c.free_symbols for c in s.mask):
        raise AnalysisError("the scheme does not depend on the level: use the stationary analysis")
    prefill_taylor(s)
    a = s.limit()
    if open_param is not None and open_param not in {p.name for p in a.params}:
        raise AnalysisError(f"the limit does not depend on {open_param}: --open names the limit's parameter "
                            f"(its parameters: {', '.join(p.name for p in a.params) or 'none'})")
    ctx = _Context(s, env, open_param, N, L_max, arity)
    k_lim, not_k, a_smooth, top = _limit_top(ctx, a, k_max)
    verdicts, best = [], -1
    for k in range(top + 1):
        v = _cover(ctx, k, pieces, depth)
        if k == 0:
            ctx.converges = Result(value=True if v["status"] == CERTIFIED else None, status=v["status"],
                                   witness={"statement": "{S_(a^n)} converges (C^0) at every point of the box",
                                            "routes": v["routes"]},
                                   provenance={"method": "the C^0 cover above"})
        verdicts.append(v)
    for v in verdicts:                 # C^k' on the whole box implies C^k for k < k'
        higher = [w["k"] for w in verdicts if w["k"] > v["k"] and w["status"] == CERTIFIED]
        if v["status"] != CERTIFIED and higher:
            v.update({"verdict": f"C^{v['k']}", "status": CERTIFIED, "implied_by": f"C^{higher[0]}",
                      "routes": {f"implied by C^{higher[0]} on the whole box": 1},
                      "undecided_directly": v["undecided"], "undecided": []})
    for v in verdicts:
        if v["status"] == CERTIFIED and best == v["k"] - 1:
            best = v["k"]
    cert = not_ck_box(s, env, depth=depth + 4, arity=arity)
    d = cert.witness.get("k")
    if cert.is_certified and cert.value is False and d is not None and d > max(best, k_lim) and \
            (k_max is None or d <= k_max):
        verdicts.append({"k": d, "verdict": f"not C^{d}", "holds": False, "status": CERTIFIED,
                         "route": f"exponential B-spline of order {d + 1} (recognised identically in the parameters)",
                         "theorem": cert.witness["theorem"], "hypotheses": cert.witness["hypotheses"],
                         "frequencies": cert.witness["frequencies"]})
    else:
        if not_k is not None and (k_max is None or not_k <= k_max):
            verdicts.append({"k": not_k, "verdict": "undecided", "status": INCONCLUSIVE, "route": None,
                             "reason": (f"the limit S_a is certified not C^{not_k}, but no implemented theorem "
                                        "transfers 'not C^k' to the level-dependent scheme on the box "
                                        f"(exponential B-spline route: {cert.witness.get('reason')})")})
        cert = None
    region = _describe({**point, **env}, open_param)
    exact = cert is not None and best == cert.witness["k"] - 1
    lim_info = {"symbol": a, "C^k_certified_up_to": k_lim if not a.params else None, "not_C^k": not_k,
                "parametric": [p.name for p in a.params]}
    return Result(value=best, status=CERTIFIED if best >= 0 else INCONCLUSIVE,
                  witness={"region": region, "box": exact_box(env), "verdicts": verdicts, "max_certified_k": best,
                           "limit": lim_info, "not_C^k": None if cert is None else cert.witness["k"], "exact": exact,
                           "open": open_param},
                  provenance={"scheme": s.slug, "N": N, "pieces": pieces, "depth": depth,
                              **({} if arity == 2 else {"arity": arity}),
                              "method": ("adaptive cover of the box; per sub-box Dyn-Levin 1995 (direct, divided "
                                         "differences, generalized divided differences); exponential B-spline "
                                         "recognition for 'not C^d'")})
