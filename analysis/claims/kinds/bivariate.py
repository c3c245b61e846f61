"""The claim kinds ``sum rules``, ``reproduction``, ``smoothness``, ``holder`` and ``ck range`` for a bivariate
scheme (``[schemes.NAME] bivariate = { dilation = "...", symbol = "..." }``): the same kinds and fields as for
curves, evaluated by :mod:`analysis.bivariate`.

* ``sum rules``: ``factors = k`` is the order of the sum rules (for curves the number of factors ``(1+z)/2``, the
  same number); ``exceptional = [{ at = {...}, factors = k }]`` the parameter values where it is higher.
* ``reproduction``: ``generation`` (``k - 1``) and ``reproduction`` degree (:func:`analysis.bivariate.algebra.reproduction`).
* ``smoothness``: ``C = l``, ``holds``: the certified verdict from the Hölder exponent (isotropic ``M``).
* ``holder``: ``value``/``tolerance``/``lower``/``upper`` against the certified enclosure of alpha.
* ``ck range``: ``j``, ``interval``: C^j on the whole interval (rational ends), proven by
  :func:`analysis.bivariate.ranges.ck_set`, or refuted by a certified counterexample inside it.
"""

from __future__ import annotations

import sympy as sp

from ...result import CERTIFIED, AnalysisError, Result
from ..model import Number, Verdict
from .base import evidence, interval_text

#: grid cells and work budget of a bivariate ``ck range`` claim
CK_GRID = 2
CK_BUDGET = 400_000
#: the tensor-product route's grid and per-verdict budget (the defaults of subdiv surface --C --within)
TENSOR_GRID = 8
TENSOR_BUDGET = 20_000


def _label(kind) -> str:
    return kind.where_text() or kind.scheme.name


def sum_rules_verdict(kind) -> Verdict:
    from ...bivariate.algebra import sum_rules

    a = kind.bivariate_mask()
    r = sum_rules(a)
    k = r.value
    found = r.witness.get("exceptional", [])
    exc_text = "; ".join(f"{sp.sstr(e['value'])}: order {e['order']}" for e in found) or "none"
    ev = [evidence("equal coset moments of order < k (exact)", r, text=f"order {k}; exceptional: {exc_text}")]
    wrong = []
    if (k < kind.get("factors")) if kind.get("at_least") else (k != kind.get("factors")):
        wrong.append(f"sum rules of order {k}, not {'at least ' if kind.get('at_least') else ''}{kind.get('factors')}")
    for e in kind.get("exceptional", []):
        vals = kind.scheme.values(e["at"], kind.where)
        kk = sum_rules(a.at(vals)).value
        if kk != e["factors"]:
            wrong.append(f"at {', '.join(f'{x} = {sp.sstr(v)}' for x, v in vals.items())}: order {kk}, not {e['factors']}")
    nums = [Number("sum rule order", k), Number("exceptional values", len(found))]
    corrected = f"sum rules of order {k} (generation degree {k - 1}); exceptional: {exc_text}"
    if wrong:
        return kind.refuted("; ".join(wrong), corrected=corrected, evidence=ev, numbers=nums)
    return kind.certified(f"{_label(kind)} satisfies sum rules of order {k}" + (f"; exceptional: {exc_text}" if found else ""),
                          evidence=ev, numbers=nums)


def reproduction_verdict(kind) -> Verdict:
    from ...bivariate.algebra import reproduction, sum_rules

    a = kind.bivariate_mask()
    g = sum_rules(a)
    r = reproduction(a)
    gen = g.value - 1
    tau = r.witness["tau"]
    ev = [evidence("sum rules (generation)", g, text=f"degree {gen}"),
          evidence("S_a p = p(M^-1 . + tau) (reproduction)", r,
                   text=f"degree {r.value}" + (f", tau = ({', '.join(map(sp.sstr, tau))})" if tau else ""))]
    wrong = [f"{what} degree is {v}, not {kind.get(what)}" for what, v in (("generation", gen), ("reproduction", r.value))
             if what in kind.fields and kind.get(what) != v]
    nums = [Number("generation degree", gen), Number("reproduction degree", r.value)]
    fact = f"generates degree {gen}, reproduces degree {r.value}"
    if wrong:
        return kind.refuted("; ".join(wrong), corrected=f"{_label(kind)} {fact}", evidence=ev, numbers=nums)
    return kind.certified(f"{_label(kind)} {fact}", evidence=ev, numbers=nums)


def holder_result(kind, a) -> Result:
    from ...bivariate.holder import holder_exponent

    budget = int(kind.number("budget") or 20_000)
    return holder_exponent(a, budget=budget)


def smoothness_verdict(kind) -> Verdict:
    from ...bivariate.holder import holder_exponent, smoothness_verdicts

    a = kind.bivariate_mask()
    if a.params:
        raise AnalysisError(f"{kind.where}: fix every parameter with at = {{...}}")
    k = kind.get("C")
    claim_holds = kind.boolean("holds", True)
    h = holder_exponent(a, budget=int(kind.number("budget") or 20_000))
    ck = smoothness_verdicts(h, max_l=max(k, h.witness["k"]))
    t = ck.get(k)
    yes = max((l for l, v in ck.items() if v is True), default=-1 if ck.get(0) is False else None)
    no = min((l for l, v in ck.items() if v is False), default=None)
    truth = (f"{_label(kind)} is C^{yes} but not C^{no} (certified)" if yes is not None and no == yes + 1 and yes >= 0
             else f"{_label(kind)} is not C^0 (certified)" if yes == -1 else
             f"{_label(kind)}: C^j certified up to j = {yes}, not C^j from j = {no}")
    lo = "?" if h.lower is None else sp.sstr(h.lower) if h.value is not None else f"{float(h.lower):.10g}"
    hi = "?" if h.upper is None else sp.sstr(h.upper) if h.value is not None else f"{float(h.upper):.10g}"
    reason = f"alpha = {sp.sstr(h.value)}" if h.value is not None else f"alpha in [{lo}, {hi}] ({h.status})"
    if not h.witness["isotropic"]:                 # no alpha: C^0 from the JSR on V_k, C^l (l >= k) from the sum rules
        r = h.witness["jsr"]
        reason = (f"{h.provenance['message']}; JSR(T|V_{h.witness['k']}) in [{float(r.lower):.10g}, "
                  f"{'?' if r.upper is None else f'{float(r.upper):.10g}'}] ({r.status}); "
                  f"sum rules of order {h.witness['k']}")
    nums = [Number(f"C^{k}", "undecided" if t is None else t),
            Number("C^j certified up to j", -1 if yes is None else yes),
            Number("not C^j from j", "none certified" if no is None else no)]
    if t is None:
        return kind.inconclusive(f"{_label(kind)}: C^{k} undecided ({reason})",
                                 settle="a larger budget (field 'budget')", evidence=[evidence(f"C^{k}", text=reason)],
                                 numbers=nums)
    fact = Result(value=t, status=CERTIFIED, witness={"reason": reason, "k": k},
                  provenance={"method": h.provenance.get("method", "")})
    ev = [evidence(f"C^{k} of {_label(kind)}: {'yes' if t else 'no'}", fact, text=reason)]
    said = f"{_label(kind)} is {'' if t else 'not '}C^{k} (certified: {reason})"
    if t == claim_holds:
        return kind.certified(f"{said}; {truth}", evidence=ev, numbers=nums, sharpness=truth)
    return kind.refuted(f"{said}, so the claim '{'' if claim_holds else 'not '}C^{k}' is false", corrected=truth,
                        evidence=ev, numbers=nums)


def ck_range_verdict(kind) -> Verdict:
    from ...bivariate.ranges import ck_set

    a = kind.bivariate_mask()
    if len(a.params) != 1:
        raise AnalysisError(f"{kind.where}: kind 'ck range' needs exactly one free parameter (fix the others with at)")
    p = a.params[0]
    j = kind.get("j")
    lo, hi, lc, hc = kind.interval("interval")
    if not (getattr(lo, "is_Rational", False) and getattr(hi, "is_Rational", False)):
        raise AnalysisError(f"{kind.where}: a bivariate 'ck range' needs rational ends of the interval")
    claim = interval_text(lo, hi, lc, hc)
    from ...bivariate.tensor import tensor_factors

    tf = tensor_factors(a)
    if tf.value is not None:                  # b(z1) c(z2), M = m I: the univariate route, as subdiv surface --C
        return _tensor_ck_range_verdict(kind, a, tf.value, j, (lo, hi, lc, hc), claim)
    r = ck_set(a, j, within=(lo, hi), grid=CK_GRID, budget=CK_BUDGET)
    inside = [x for x in r.value["not_Cl"] if (lo < x < hi) or (lc and x == lo) or (hc and x == hi)]
    cert = r.value["certified"]
    text = ("C^%d certified on %s; not C^%d at %s; undecided %s" % (
        j, " u ".join(f"[{sp.sstr(I.start)}, {sp.sstr(I.end)}]" for I in cert) or "nothing", j,
        ", ".join(map(sp.sstr, r.value["not_Cl"])) or "no point",
        ", ".join(f"({sp.sstr(u)}, {sp.sstr(v)})" for u, v in r.value["gaps"]) or "nothing"))
    ev = [evidence(f"C^{j} of {kind.scheme.name} on {claim}", r if r.status == CERTIFIED else None, text=text)]
    prov = {"method": r.provenance["method"], "work": r.provenance["work"]}
    if inside:
        q = inside[0]
        b = next((b for b in r.witness["boundaries"] if b.get("exact") == q), None)
        how = b["how"] if b else "certified Hölder verdict at the grid point"
        ev.insert(0, evidence(f"not C^{j} at {p.name} = {sp.sstr(q)}", Result(
            value=False, status=CERTIFIED, witness={"counterexample": q, "how": how}, provenance=prov), text=how))
        return kind.refuted(f"not C^{j} at {p.name} = {sp.sstr(q)} in {claim} (certified: {how})", corrected=text,
                            evidence=ev, numbers=[Number("counterexample", q)])
    covered = any(I.start <= lo and I.end >= hi for I in cert)
    if covered:
        ev.insert(0, evidence(f"C^{j} on {claim}", Result(value=True, status=CERTIFIED, witness={"boxes": len(
            [x for x in r.witness["boxes"] if x["certified_Cl"]])}, provenance=prov), text=text))
        return kind.certified(f"C^{j} for every {p.name} in {claim} (certified point verdicts and the JSR of the "
                              f"Bernstein coefficient matrices on boxes)", evidence=ev, numbers=[Number("proven", True)])
    return kind.inconclusive(f"C^{j} on {claim} neither proven nor refuted: {text}",
                             settle="more grid cells or a larger budget (`subdiv surface --C --within`); next to an end "
                                    "of eigenvalue type the boxes never reach the end", evidence=ev)


def _tensor_ck_range_verdict(kind, a, tf, j: int, interval, claim: str) -> Verdict:
    """``ck range`` of a tensor-product family (:func:`analysis.bivariate.tensor.tensor_ck_set`: the intersection of
    the factors' univariate ``C^j`` sets, the route of ``subdiv surface --C --within``)."""
    from ...algebra.algebraic import RealAlgebraic, rational_between
    from ...bivariate.tensor import tensor_ck_set

    lo, hi, lc, hc = interval
    p = a.params[0]
    r = tensor_ck_set(a, j, p.name, within=(lo, hi), grid=TENSOR_GRID, budget=TENSOR_BUDGET, factors=tf)
    v = r.value
    want = sp.Interval(lo, hi, not lc, not hc)
    text = (f"the mask is a tensor product b(z1) {'b' if tf.same else 'c'}(z2) with M = {tf.m}I (exact), so C^{j} "
            f"exactly where the univariate factor{'' if tf.same else 's'} {'is' if tf.same else 'are'}: C^{j} on "
            f"{v['Cl']}; not C^{j} on {v['not_Cl']}"
            + (f"; undecided {v['undecided']}" if not v["undecided"].is_empty else "")
            + (f"; between counterexamples (sampled) {v['sampled']}" if not v["sampled"].is_empty else ""))
    prov = {"method": "tensor product: the intersection of the univariate C^l sets", "status": r.status}
    ev = [evidence(f"C^{j} of {kind.scheme.name} on {claim}", r if r.status == CERTIFIED else None, text=text)]
    bad = want.intersect(v["not_Cl"].to_sympy())
    if bad.is_empty is False:
        q = bad.inf if bad.inf in bad else rational_between(RealAlgebraic.from_expr(bad.inf),
                                                               RealAlgebraic.from_expr(bad.sup))
        at = sp.sstr(q) + ("" if q.is_Rational else f" ~ {float(q):.10g}")
        ev.insert(0, evidence(f"not C^{j} at {p.name} = {at}", Result(
            value=False, status=CERTIFIED, witness={"counterexample": q}, provenance=prov), text=text))
        return kind.refuted(f"not C^{j} at {p.name} = {at} in {claim} (certified: {text})", corrected=text,
                            evidence=ev, numbers=[Number("counterexample", q)])
    if want.is_subset(v["Cl"].to_sympy()) is True:
        ev.insert(0, evidence(f"C^{j} on {claim}", Result(value=True, status=CERTIFIED, witness={"route": "tensor"},
                                                          provenance=prov), text=text))
        return kind.certified(f"C^{j} for every {p.name} in {claim} (certified: {text})", evidence=ev,
                              numbers=[Number("proven", True)])
    return kind.inconclusive(f"C^{j} on {claim} neither proven nor refuted: {text}",
                             settle="a larger budget (`subdiv surface --C --within`)", evidence=ev)
