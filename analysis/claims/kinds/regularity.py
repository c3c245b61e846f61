"""Claim kinds about smoothness: the norm test for given L, a C^k range, a Hölder value or
bounds, a Sobolev exponent.

A value claim compares the claimed value (``value``, optionally ``tolerance``) or bounds
(``lower``: ``alpha >= lower``; ``upper``: ``alpha <= upper``) with the certified enclosure
``[lo, hi]``: proven when the enclosure lies inside the claimed set, refuted when it lies outside,
inconclusive otherwise (an enclosure that merely contains an exact claimed value proves nothing).

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> w = sp.Symbol("w")
>>> four = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
>>> S = {"4pt": SchemeSpec("4pt", four)}
>>> Holder({"at": {"w": "1/16"}, "value": 2}, S, "x").evaluate().label      # Dubuc (1986)
'CERTIFIED TRUE'
>>> NormTest({"j": 1, "L": 2, "interval": "(0, 1/8)"}, S, "x").evaluate().label
'CERTIFIED TRUE'

Algorithm
---------
:func:`analysis.regularity.holder.holder_exponent` (JSR bounds of the difference scheme),
:func:`analysis.regularity.sobolev.sobolev_exponent`, the exact norm set
:func:`analysis.stationary.normset.norm_solution_set` and
:func:`analysis.regularity.ranges.verify_smoothness_interval`.

References
----------
N. Dyn, D. Levin, Acta Numer. 11 (2002), Thm 3.3; O. Rioul, SIAM J. Math. Anal. 23 (1992);
S. Dubuc, *Interpolation through an iterative scheme*, J. Math. Anal. Appl. 114 (1986).
"""

from __future__ import annotations

import sympy as sp

from ...regularity.holder import holder_exponent
from ...regularity.ranges import ck_range, verify_smoothness_interval
from ...regularity.sobolev import sobolev_exponent
from ...jsonable import fmt_bound
from ...result import CERTIFIED, REFUTED, AnalysisError, Result
from ...stationary.normset import norm_solution_set
from ..model import Number, Verdict, contains_interval
from .base import Kind, _compare, evidence, interval_text, point_in, set_text
from ...algebra.reader import as_expr

__all__ = ["NormTest", "CkRange", "Holder", "Sobolev", "enclosure_text", "compare_enclosure"]


def enclosure_text(r: Result) -> str:
    """``alpha = 2`` (exact) or ``alpha in [lo, hi]`` (decimals, outward) with the status."""
    if r.value is not None:
        return f"{sp.sstr(r.value)} (exact, {r.status})"
    if r.lower is None or r.upper is None:
        return f"not enclosed ({r.status})"
    return f"[{fmt_bound(r.lower, 'lower')}, {fmt_bound(r.upper, 'upper')}] ({r.status})"


def _sign(x, y) -> int | None:
    """The certified sign of ``x - y`` (:func:`.base._compare`), None when it cannot be decided."""
    try:
        return _compare(x, y)
    except AnalysisError:
        return None


def _claimed_bounds(value=None, tol=None, lower=None, upper=None) -> tuple[list, list]:
    """The claimed set as lists of lower and upper bounds (``value ± tol``, ``lower``, ``upper``)."""
    lows, highs = [], []
    if value is not None:
        t = tol or 0
        lows.append(value - t)
        highs.append(value + t)
    if lower is not None:
        lows.append(lower)
    if upper is not None:
        highs.append(upper)
    return lows, highs


def compare_enclosure(r: Result, value=None, tol=None, lower=None, upper=None) -> tuple[bool | None, str]:
    """Decide a value/bounds claim from an enclosure: True (proven), False (refuted), None.

    Every comparison is certified (:func:`.base._compare`: exact for algebraic numbers, Arb balls
    otherwise), so a claimed value such as ``2 - log2(1 + sqrt(3))`` is compared rigorously with the
    rational end points."""
    lo = r.value if r.value is not None else r.lower
    hi = r.value if r.value is not None else r.upper
    if lo is None or hi is None or r.status not in (CERTIFIED, REFUTED):
        return None, "no certified enclosure"
    if isinstance(lo, float) or isinstance(hi, float) or isinstance(lo, sp.Float) or isinstance(hi, sp.Float):
        return None, "the enclosure is given in floats (not exact end points): not decided"
    lo, hi = as_expr(lo), as_expr(hi)              # exact: Fractions, Rationals, algebraic numbers
    lows, highs = _claimed_bounds(value, tol, lower, upper)
    inside = all(_sign(lo, b) in (0, 1) for b in lows) and all(_sign(hi, b) in (-1, 0) for b in highs)
    outside = any(_sign(hi, b) == -1 for b in lows) or any(_sign(lo, b) == 1 for b in highs)
    if inside:
        return True, "the certified enclosure lies inside the claimed set"
    if outside:
        return False, "the certified enclosure lies outside the claimed set"
    return None, "the certified enclosure straddles the claimed set"


def compare_exact(h: Result, arity: int, value=None, tol=None, lower=None, upper=None) -> tuple[bool | None, str]:
    """Decide a Hölder value/bounds claim by the exact closed form of alpha
    (:func:`analysis.regularity.exact_alpha.compare_alpha`): True, False or None (not decided)."""
    from ...regularity.exact_alpha import alpha_closed_form, compare_alpha

    form = alpha_closed_form(h, arity)
    if form is None:
        return None, "no exact closed form of alpha"
    conds = ([("eq", value)] if value is not None and not tol else []) + \
        [("ge", b) for b in _claimed_bounds(value if tol else None, tol, lower, None)[0]] + \
        [("le", b) for b in _claimed_bounds(value if tol else None, tol, None, upper)[1]]
    results, whys = [], []
    for op, b in conds:
        s, why = compare_alpha(h, b, arity, form=form)
        whys.append(why)
        results.append(None if s is None else (s == 0) if op == "eq" else (s >= 0) if op == "ge" else (s <= 0))
    why = whys[0] if len(set(whys)) == 1 else "; ".join(dict.fromkeys(whys))
    if any(x is False for x in results):
        return False, why
    if results and all(x is True for x in results):
        return True, why
    return None, why


#: the L of the exact norm sets of :func:`ck_range_by_sets` (as `subdiv range --arity`)
SET_LS = (1, 2)


def ck_range_by_sets(kind: Kind) -> Verdict:
    """The ``ck range`` kind from the exact C^j and not-C^j sets of
    :func:`analysis.regularity.ranges.ck_range` (used for arity ``m > 2``; the binary kind proves a claimed
    interval directly, :func:`analysis.regularity.ranges.verify_smoothness_interval`). A claimed open interval
    is proven when it lies in the C^j set, refuted at a rational point of the not-C^j set inside it; what
    neither covers is undecided (inconclusive, never certified).

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> from analysis.claims.kinds.base import SchemeSpec
    >>> mu = sp.Symbol("mu")
    >>> r = sp.Rational
    >>> a0, a1, a2, a3 = -r(1, 18) - mu/6, r(13, 18) + mu/2, r(7, 18) - mu/2, -r(1, 18) + mu/6
    >>> a = LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)
    >>> S = {"t4": SchemeSpec("t4", a, arity=3)}
    >>> CkRange({"j": 2, "interval": "(1/15, 1/9)"}, S, "x").evaluate().label
    'CERTIFIED TRUE'
    >>> v = CkRange({"j": 2, "interval": "(0, 1/9)"}, S, "x").evaluate()
    >>> v.label, v.numbers[0].value
    ('REFUTED', 1/30)
    """
    a, m = kind.symbol(), kind.arity
    p = kind.single_parameter()
    j = kind.get("j")
    lo, hi, lc, hc = kind.interval("interval")
    claim = interval_text(lo, hi, lc, hc)
    r = ck_range(a, j, p, Ls=SET_LS, within=(lo, hi), arity=m)
    S, V, U = r.value, r.witness["not_Cj"], r.witness["undecided"]
    text = (f"C^{j} (m-ary norm sets, L in {list(SET_LS)}): {set_text(S)}; not C^{j} (transition-matrix eigenvalue "
            f"of modulus >= {m}^{r.witness['k'] - j}): {set_text(V)}; undecided: {set_text(U)}")
    ev = [evidence(f"C^{j} of the {m}-ary scheme on {claim}", r, text=text)]
    note = " (the closed ends are not checked: the interval is treated as open)" if lc or hc else ""
    if r.witness["exact"] and (V == sp.EmptySet or V.is_empty is True):
        return kind.certified(f"C^{j} for every {p.name} in {claim} ({m}-ary Dyn-Levin norm sets){note}", evidence=ev,
                              numbers=[Number("proven", True)])
    q = point_in(V)
    if q is not None:
        return kind.refuted(f"not C^{j} at {p.name} = {sp.sstr(q)} in {claim} (certified: a transition matrix has an "
                            f"eigenvalue of modulus >= {m}^{r.witness['k'] - j})",
                            corrected=f"on {claim} the scheme is C^{j} exactly on {set_text(S)}"
                                      + (f" and undecided on {set_text(U)}" if not r.witness["exact"] else ""),
                            evidence=ev, numbers=[Number("counterexample", q)])
    return kind.inconclusive(f"C^{j} on {claim} neither proven nor refuted: undecided on {set_text(U)}",
                             settle=f"decide points of {set_text(U)} with `subdiv holder --arity {m} --C {j}` "
                                    "or longer norm tests", evidence=ev)


class _ValueClaim(Kind):
    #: decide a claimed closed form inside the enclosure by the exact alpha (:func:`compare_exact`)
    exact_comparison = False
    optional = {"value": "claimed value", "tolerance": "|true - value| <= tolerance", "lower": "claim >= lower",
                "upper": "claim <= upper", "at": "parameter values", "budget": "work units for the JSR search (default 20000)"}
    quantity = ""

    def check(self) -> None:
        self.values()
        if not {"value", "lower", "upper"} & set(self.fields):
            raise AnalysisError(f"{self.where}: kind {self.name!r} needs 'value', 'lower' or 'upper'")
        [self.number(k) for k in ("value", "tolerance", "lower", "upper", "budget")]

    def compute(self, a) -> Result:  # pragma: no cover
        raise NotImplementedError

    def evaluate(self) -> Verdict:
        a = self.bivariate_mask() if self.scheme.bivariate is not None else self.symbol()
        if a.params:
            raise AnalysisError(f"{self.where}: fix every parameter with at = {{...}} "
                                f"(free: {', '.join(p.name for p in a.params)})")
        r = self.compute(a)
        claimed = (self.number("value"), self.number("tolerance"), self.number("lower"), self.number("upper"))
        ok, why = compare_enclosure(r, *claimed)
        exact_why = settle = None
        if ok is None and self.exact_comparison and self.scheme.bivariate is None:        # a closed form inside the enclosure: decide it exactly
            ok2, why2 = compare_exact(r, self.arity, *claimed)
            ok, why = (ok2, why2) if ok2 is not None else (None, f"{why}; {why2}")
            exact_why = why2
            if ok2 is None and "rounding" in why2:
                settle = ("an exact proof that the JSR equals rho(T_w)^(1/L) (the invariant polytope checked in exact "
                          "algebraic arithmetic)")
        claim = " and ".join(x for x in (
            f"= {sp.sstr(self.number('value'))}" + (f" ± {sp.sstr(self.number('tolerance'))}" if self.get("tolerance") else "")
            if self.get("value") is not None else "",
            f">= {sp.sstr(self.number('lower'))}" if self.get("lower") is not None else "",
            f"<= {sp.sstr(self.number('upper'))}" if self.get("upper") is not None else "") if x)
        enc = enclosure_text(r)
        lo = r.value if r.value is not None else r.lower
        hi = r.value if r.value is not None else r.upper
        mid = r.value if r.value is not None else (None if lo is None or hi is None else (sp.Rational(lo) + sp.Rational(hi)) / 2)
        width = 0 if r.value is not None or mid is None else float(sp.Rational(hi) - sp.Rational(lo))
        nums = [Number(self.quantity, mid if r.value is not None else (float(mid) if mid is not None else "no enclosure"),
                       tol=0 if r.value is not None else max(1e-6, 2 * width), lower=lo, upper=hi)]
        if lo is None and hi is None and r.provenance.get("message"):         # e.g. an anisotropic dilation
            enc = f"{enc} ({r.provenance['message']})"
        text = f"{self.quantity} of {self.where_text()}: {enc}"
        if ok is True:
            return self.certified(f"{text}; claimed {claim}: {why}", evidence=[evidence(self.quantity, r, text=enc)], numbers=nums)
        if ok is False:
            return self.refuted(f"{text}; claimed {claim}: {why}",
                                corrected=f"{self.quantity} = {enc}" + (f"; {exact_why}" if exact_why else ""),
                                evidence=[evidence(self.quantity, r, text=enc)], numbers=nums)
        return self.inconclusive(f"{text}; claimed {claim}: {why}", evidence=[evidence(self.quantity, text=enc)],
                                 settle=settle or "a tighter enclosure (longer JSR budget) or an exact closed form of "
                                                  "the exponent", numbers=nums)


class Holder(_ValueClaim):
    """The Hölder exponent at fixed parameters: certified enclosure vs the claimed value/bounds."""

    name = "holder"
    summary = ("Hölder exponent at fixed parameters: value (± tolerance) or bounds, certified enclosure; a closed form "
               "(value = \"2 - log2(1 + sqrt(3))\") inside it is compared exactly where the JSR is known exactly")
    quantity = "alpha"
    example = 'at = { w = "1/16" }\nvalue = 2'
    any_arity = True
    exact_comparison = True
    bivariate = True

    def compute(self, a) -> Result:
        if self.scheme.bivariate is not None:
            from .bivariate import holder_result

            return holder_result(self, a)
        return holder_exponent(a, budget=self._budget(), arity=self.arity)

    def _budget(self) -> int:
        return int(self.number("budget") or 20_000)


class Sobolev(_ValueClaim):
    """The L2-Sobolev exponent at fixed parameters."""

    name = "sobolev"
    summary = "L2-Sobolev exponent s_2 at fixed parameters: value or bounds, certified"
    quantity = "s_2"
    example = 'at = { w = "1/16" }\nlower = 2'
    any_arity = True

    def compute(self, a) -> Result:
        return sobolev_exponent(a, arity=self.arity)      # s_2 = -(1/2) log_m lambda


class NormTest(Kind):
    """The Dyn–Levin norm test ``||(1/2 S_{a_{j+1}})^L||_inf < 1`` holds on the claimed interval."""

    name = "norm test"
    summary = "the L-step norm test proves C^j on the claimed interval (exact norm set)"
    required = {"j": "smoothness C^j", "L": "number of steps", "interval": "claimed parameter interval"}
    optional = {"at": "values of the other parameters", "plot": "\"(a, b)\": the report draws the norm over this range"}
    example = 'j = 1\nL = 2\ninterval = "(0, 1/8)"'
    any_arity = True

    def check(self) -> None:
        self.integer("j"), self.integer("L", 1), self.interval("interval"), self.interval("plot")
        self.values()

    def evaluate(self) -> Verdict:
        a = self.symbol()
        p = self.single_parameter()
        j, L = self.get("j"), self.get("L")
        lo, hi, lc, hc = self.interval("interval")
        dom = self.scheme.domains.get(p.name)
        within = (dom.lo, dom.hi) if dom is not None else (-sp.oo, sp.oo)
        m = self.arity
        r = norm_solution_set(a, j + 1, L, p, within=within, arity=m)
        S = r.value
        ok = contains_interval(S, lo, hi, closed=lc or hc)
        claim = interval_text(lo, hi, lc, hc)
        ev = [evidence(f"exact set where ||(1/{m} S_(a_{j + 1}))^{L}||_inf < 1", r, text=f"{p.name} in {S}")]
        nums = [Number("norm set", str(S))]
        figs = []
        if self.get("plot") and m == 2:           # the norm curve (issue 11, seed 004)
            from .plots import norm_figure

            figs = [norm_figure(f"norm-{self.scheme.name}-j{j}-L{L}", f"{L}-step norm of the difference scheme for C^{j}",
                                a, p, j, L, self.interval("plot")[:2], (lo, hi), S)]
        if ok:
            return self.certified(f"the {L}-step norm test proves C^{j} for {p.name} in {claim}: it holds exactly on {S}",
                                  evidence=ev, numbers=nums, sharpness=f"the norm-test set is {S}", figures=figs)
        return self.refuted(f"the {L}-step norm test for C^{j} holds exactly on {S}, which does not contain {claim}",
                            corrected=f"the {L}-step norm test proves C^{j} for {p.name} in {S}", evidence=ev, numbers=nums,
                            figures=figs)


class CkRange(Kind):
    """``S_a(p)`` is C^j for every parameter value in the claimed open interval."""

    name = "ck range"
    summary = "C^j for every parameter value in the claimed interval (norm sets, Arb boxes, or a certified counterexample)"
    required = {"j": "smoothness C^j", "interval": "claimed open parameter interval"}
    optional = {"at": "values of the other parameters"}
    example = 'j = 1\ninterval = "(0, 1/8)"'
    any_arity = True
    bivariate = True

    def check(self) -> None:
        self.integer("j")
        lo, hi, _, _ = self.interval("interval")
        self.values()
        if self.scheme.bivariate is not None and not (getattr(lo, "is_Rational", False)
                                                      and getattr(hi, "is_Rational", False)):
            raise AnalysisError(f"{self.where}: a bivariate 'ck range' needs rational ends of the interval, e.g. "
                                f"interval = \"(0, 1/8)\"")

    def evaluate(self) -> Verdict:
        if self.scheme.bivariate is not None:
            from .bivariate import ck_range_verdict

            return ck_range_verdict(self)
        if self.arity != 2:                       # issue 12
            return ck_range_by_sets(self)
        a = self.symbol()
        p = self.single_parameter()
        j = self.get("j")
        lo, hi, lc, hc = self.interval("interval")
        claim = interval_text(lo, hi, lc, hc)
        r = verify_smoothness_interval(a, j, (lo, hi), p, closed=(lc, hc))
        route = r.witness.get("route")
        ev = [evidence(f"C^{j} on {claim}", r if r.status in (CERTIFIED, REFUTED) else None, text=f"route: {route}")]
        if r.value is True:
            note = (" (the closed ends are not checked: the interval is treated as open)"
                    if (lc or hc) and not r.witness.get("ends checked") else "")
            return self.certified(f"C^{j} for every {p.name} in {claim}, proven by {route}{note}", evidence=ev,
                                  numbers=[Number("proven", True)])
        if r.value is False:
            q = r.witness["counterexample"]
            return self.refuted(f"not C^{j} at {p.name} = {sp.sstr(q)} in {claim} (certified)",
                                corrected=f"the scheme is not C^{j} at {p.name} = {sp.sstr(q)}; see the smoothness profile "
                                          "for the true C^j set", evidence=ev, numbers=[Number("counterexample", q)])
        return self.inconclusive(f"C^{j} on {claim} neither proven nor refuted", settle=r.provenance.get("message", ""),
                                 evidence=[evidence(ev[0].title, text=str(r.witness.get("uncovered")))])
