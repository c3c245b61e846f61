"""The smoothness profile of a one-parameter family (issue 11, item 5): what a referee wants
from every family, every time.

For ``j = 0, 1, ...`` up to the largest ``j`` with a non-empty set, the C^j set of the parameter
in ``within`` (:func:`analysis.regularity.ranges.ck_parameter_set`: every boundary bracketed by
certified verdicts on both sides, exact where an eigenvalue of a spectrum-maximizing product
crosses ``2^(k-j)``); the largest Hölder exponent over the sample points and where it is
attained, with its certified enclosure at that point; an exceptional parameter value (more
smoothing factors, e.g. a B-spline member) outside every run of a C^j set is certified at the point
and listed as an isolated point of that set (its alpha joins the samples); beside the claimed range (proven or
refuted by :func:`analysis.regularity.ranges.verify_smoothness_interval`) and which C^j set the
printed interval actually is.

What is certified: each C^j verdict at the grid points and on both sides of each boundary, the
boundaries themselves (exact or to ``tol``), the interior of each run up to explicit strips next
to ends of eigenvalue type (exact parametric norm tests, :mod:`analysis.regularity.interior`),
the enclosure of alpha at each sample point, the verdict on the claimed range. What is *not
proven*: those strips (the ``C^j`` line lists them), and the maximum of alpha (the largest
certified value at the sample points, not a certified maximum over the interval).

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> w = sp.Symbol("w")
>>> a = LaurentSymbol.from_mask([w, sp.Rational(1, 2) - w, sp.Rational(1, 2) - w, w], start=-2) * 2
>>> v = SmoothnessProfile({"within": "(0, 1/4)", "grid": 4, "samples": 4}, {"s": SchemeSpec("s", a)}, "x").evaluate()
>>> v.label, v.numbers[0].name, v.numbers[0].value
('INCONCLUSIVE', 'largest j', 1)
>>> [(n.name, n.value) for n in v.numbers if "isolated" in n.name]   # w = 1/8: 3 smoothing factors
[('C^1 isolated point', 1/8)]

Algorithm
---------
``ck_parameter_set`` for each ``j`` (grid, certified bisection / exact s.m.p. crossings, norm
tests on the interior); ``alpha_curve`` at ``samples + 1`` rational points; the claimed range by
``verify_smoothness_interval``. A printed interval "is" the C^j set when each of its ends is an
end of one run of that set (equal to an exact boundary, inside a certified bracket, or the end of
``within``).

References
----------
N. Dyn, D. Levin, Acta Numer. 11 (2002); O. Rioul, SIAM J. Math. Anal. 23 (1992).
"""

from __future__ import annotations

import sympy as sp

from ...algebra.algebraic import RealAlgebraic
from ...algebra.factorization import smoothing_factor
from ...regularity.holder import holder_exponent, smoothness
from ...regularity.ranges import alpha_curve, ck_parameter_set, ck_range, verify_smoothness_interval
from ...result import CERTIFIED, REFUTED, AnalysisError
from ..model import Number, Verdict
from .base import Kind, evidence, interval_text, parse_interval, point_in, set_text, alpha_maximum
from .regularity import SET_LS
from ...algebra.reader import as_expr

__all__ = ["SmoothnessProfile", "beside_text", "boundary_text", "compact_set", "run_matches", "which_set"]


def _ra(x) -> RealAlgebraic:
    return RealAlgebraic.from_expr(as_expr(x))


def boundary_text(b: dict) -> str:
    """One end of a run: exact, bracketed, or an end of the searched interval."""
    if "open_end" in b:
        return f"{sp.sstr(b['open_end'])} (end of the searched interval)"
    if "exact" in b:
        return f"{sp.sstr(b['exact'])} ≈ {float(b['exact_float']):.10g} (exact; {b['how']})"
    lo, hi = b["bracket"]
    return f"in [{float(lo):.10g}, {float(hi):.10g}] ({b.get('how', b['status'])})"


def _end_matches(b: dict, x) -> bool:
    X = _ra(x)
    if "open_end" in b:
        return X.compare(_ra(b["open_end"])) == 0
    if "exact" in b:
        return X.compare(_ra(b["exact"])) == 0
    lo, hi = b["bracket"]
    return _ra(lo).compare(X) <= 0 <= _ra(hi).compare(X)


def run_matches(run: dict, lo, hi) -> str | None:
    """Is the printed interval (lo, hi) this run of a C^j set?  ``"exact"`` (both ends are
    certified boundaries), ``"window"`` (an end is only the end of the searched interval), None."""
    if not (_end_matches(run["left"], lo) and _end_matches(run["right"], hi)):
        return None
    return "window" if "open_end" in run["left"] or "open_end" in run["right"] else "exact"


def which_set(sets: dict, lo, hi) -> tuple[str, str]:
    """Which C^j set the printed interval (lo, hi) actually is (``sets``: j -> ck_parameter_set):
    a sentence and a short key (``"C^1 set"``, ``"inside the C^1 set"``, ...)."""
    found = {j: m for j, r in sets.items() for m in [next((x for x in map(lambda u: run_matches(u, lo, hi), r.value) if x), None)] if m}
    txt = interval_text(lo, hi)
    exact = [j for j, m in found.items() if m == "exact"]
    window = [j for j, m in found.items() if m == "window"]
    if exact:
        return (f"the printed interval {txt} is the C^{exact[0]} set" + (f" (and the C^j set for j in {exact})" if len(exact) > 1
                                                                           else ""), f"the C^{exact[0]} set")
    if window:
        return (f"the printed interval {txt} is the C^j set for j in {window} within the searched interval only "
                "(an end of it is an end of the search, not a certified boundary)", f"the C^j set for j in {window} (search window)")
    inside = [j for j, r in sets.items() if any(_run_contains(x, lo, hi) for x in r.value)]
    if inside:
        J = max(inside)
        run = next(x for x in sets[J].value if _run_contains(x, lo, hi))
        return (f"the printed interval {txt} is none of the C^j sets: it lies inside the C^{J} set, whose run is "
                f"({_short(run['left'])}, {_short(run['right'])}) (not sharp)", f"inside the C^{J} set")
    return f"the printed interval {txt} is none of the C^j sets found and lies in none of them", "none"


def _value(b: dict):
    """A boundary as a number: exact, the end of the search, or the certified C^j side of its bracket."""
    if "open_end" in b:
        return b["open_end"]
    if "exact" in b:
        return b["exact"]
    return b["certified_C^j_at"]


def _run_contains(run: dict, lo, hi) -> bool:
    return _ra(_value(run["left"])).compare(_ra(lo)) <= 0 and _ra(hi).compare(_ra(_value(run["right"]))) <= 0


def _exceptional(a, p, lo, hi) -> dict:
    """Rational parameter values in (lo, hi) where the symbol has more smoothing factors: value -> factors."""
    w = smoothing_factor(a, exceptional=True).witness.get("exceptional", [])
    out = {}
    for e in w:
        cond = e.get("condition", {})
        q = cond.get(p) if len(cond) == 1 else None
        if q is not None and as_expr(q).is_Rational and lo < q < hi:
            out[sp.Rational(q)] = e["k"]
    return out



def _interior_status(r) -> str:
    """The status cell of a C^j set that is not certified as a whole: what the norm tests left."""
    if not r.witness.get("boundaries_certified"):
        return r.status
    its = [x.get("interior") or {} for x in r.value]
    if its and all("certified" in it for it in its):
        strips = [s for it in its for s in it["strips"]]
        return ("boundaries certified; interior certified (exact parametric norm tests) except "
                + ", ".join(f"({_num(x)}, {_num(y)})" for x, y in strips))
    return "boundaries certified, interior sampled"


def _num(x) -> str:
    x = as_expr(x)
    return sp.sstr(x) if x.is_Rational else f"{sp.sstr(x)} ≈ {float(sp.N(x, 20)):.10g}"


def _short(b: dict) -> str:
    v = _value(b)
    return sp.sstr(v) if as_expr(v).is_Rational else f"{sp.sstr(v)} ≈ {float(sp.N(v, 20)):.10g}"


def compact_set(r, isolated=()) -> str:
    """A C^j set in short: its runs with exact or bracketed ends (and isolated points), or "empty"."""
    parts = [f"({_short(x['left'])}, {_short(x['right'])})" for x in r.value] + [f"{{{sp.sstr(q)}}}" for q in isolated]
    return " ∪ ".join(parts) or "empty"


def beside_text(sets: dict, points: dict, j: int, lo, hi, p) -> tuple[str, str]:
    """What the certified C^j set says beside a claim "C^j on (lo, hi)": a sentence and a short key
    (``"is the C^j set"``, ``"inside the C^j set (understated)"``, ``"not inside the C^j set"``)."""
    txt = interval_text(lo, hi)
    if j not in sets:
        return (f"claim: C^{j} on {txt}; the profile has no C^{j} set (it stops at the first empty set: "
                f"nowhere C^{j} in the searched interval)", f"no C^{j} set")
    r = sets[j]
    true = compact_set(r, points.get(j, ()))
    status = "certified" if r.status == CERTIFIED else _interior_status(r)
    head = f"claim: C^{j} for {p.name} in {txt}; certified C^{j} set: {true} [{status}]"
    matches = {run_matches(x, lo, hi) for x in r.value}
    if "exact" in matches:
        return head + f" — the claimed interval is exactly the C^{j} set", f"is the C^{j} set"
    if "window" in matches:
        return (head + f" — the claimed interval is the C^{j} set within the searched interval (an end of it is an "
                "end of the search)", f"is the C^{j} set (search window)")
    if any(_run_contains(x, lo, hi) for x in r.value):
        if r.status == CERTIFIED:
            return (head + f" — the claimed interval lies strictly inside the C^{j} set: the paper understates "
                    f"(C^{j} holds on the larger set, certified)", f"inside the C^{j} set (understated)")
        return (head + f" — the claimed interval lies strictly inside the C^{j} set found (its boundaries are "
                "certified; the part of its interior named in the status is not proven)",
                f"inside the C^{j} set found (interior not all proven)")
    return (head + f" — the claimed interval is not inside the C^{j} set (C^{j} fails somewhere on it)",
            f"not inside the C^{j} set")


class SmoothnessProfile(Kind):
    """The C^j set for every j, the largest Hölder exponent and where, beside the claimed range."""

    name = "smoothness profile"
    summary = "C^j set for every j (certified boundaries), max of alpha (sampled, certified enclosure), vs the claim"
    optional = {"within": "parameter interval searched (default: the parameter's domain)",
                "claimed": "{ j = ..., interval = \"(a, b)\" }: the printed C^j range",
                "max_j": "largest j to examine (default: generic smoothing factors - 1)",
                "grid": "grid intervals per C^j search (default 8)", "samples": "alpha sample intervals (default 8)",
                "tol": "boundary bracket width (default 1e-8)", "at": "values of the other parameters",
                "beside": "[{ claim = \"ID\", j = ..., interval = \"(a, b)\" }, ...]: other claims of the paper about "
                          "this family's C^j range, each shown beside the certified C^j set"}
    example = 'within = "(1/32, 1/8)"\nclaimed = { j = 1, interval = "(1/16, 1/8)" }\nmax_j = 1\ngrid = 4\nsamples = 4'
    any_arity = True

    def check(self) -> None:
        self.values()
        for k in ("max_j", "grid", "samples"):
            self.integer(k, 1 if k != "max_j" else 0)
        self.number("tol")
        c = self.get("claimed")
        if c is not None:
            if not isinstance(c, dict) or set(c) != {"j", "interval"}:
                raise AnalysisError(f"{self.where}: claimed = {{ j = ..., interval = \"(a, b)\" }}")
            parse_interval(c["interval"], f"{self.where}: claimed interval")
        for b in self.get("beside") or ():
            if not isinstance(b, dict) or set(b) != {"claim", "j", "interval"} or not isinstance(b["claim"], str):
                raise AnalysisError(f"{self.where}: beside = [{{ claim = \"ID\", j = ..., interval = \"(a, b)\" }}, ...]")
            parse_interval(b["interval"], f"{self.where}: beside {b['claim']}")
        self._within()

    def _within(self):
        if self.get("within") is not None:
            return self.interval("within")[:2]
        p = self.scheme.symbol.params
        dom = self.scheme.domains.get(p[0].name) if len(p) == 1 else None
        if dom is None or dom.lo == -sp.oo or dom.hi == sp.oo:
            raise AnalysisError(f"{self.where}: give 'within' (a bounded parameter interval)")
        return dom.lo, dom.hi

    def evaluate(self) -> Verdict:
        """The profile verdict; its ``profile`` (the C^j sets in short, the largest alpha, the exceptional
        values, and the sentences for the claims of ``beside``) is what reports show beside the claims."""
        import dataclasses

        self.profile = None
        v = self._evaluate()
        return dataclasses.replace(v, profile=self.profile) if self.profile is not None else v

    def _evaluate(self) -> Verdict:
        if self.arity != 2:                       # ck_range for each j
            return profile_by_sets(self)
        a = self.symbol()
        p = self.single_parameter()
        lo, hi = self._within()
        grid, tol = self.get("grid", 8), float(self.number("tol") or 1e-8)
        k = smoothing_factor(a, exceptional=False).value
        exc = _exceptional(a, p, lo, hi)
        max_j = self.get("max_j", max(max([k, *exc.values()]) - 1, 0))
        rows, ev, nums, all_cert, sets, points = [], [], [], True, {}, {}
        for j in range(0, max_j + 1):
            r = ck_parameter_set(a, j, p, within=(lo, hi), grid=grid, tol=tol, interior_L_max=10)
            # a grid point at an exceptional value (more smoothing factors) gives a run that bisection
            # shrinks onto it: that run is the isolated point
            degenerate = [q for q in exc for x in r.value if "bracket" in x["left"] and "bracket" in x["right"]
                          and _end_matches(x["left"], q) and _end_matches(x["right"], q)]
            if degenerate:
                r.value[:] = [x for x in r.value if not any(_end_matches(x["left"], q) and _end_matches(x["right"], q)
                                                            for q in degenerate)]
            sets[j] = r
            # exceptional values outside every run: isolated C^j points (certified at the point)
            iso = [q for q in exc if q in degenerate or (not any(_run_contains(x, q, q) for x in r.value)
                                                          and smoothness(a.subs({p: q}), j).value is True)]
            points[j] = iso
            runs = " ∪ ".join([f"({boundary_text(x['left'])}, {boundary_text(x['right'])})" for x in r.value]
                              + [f"{{{sp.sstr(q)}}} (isolated: exceptional value with {exc[q]} smoothing factors, "
                                 "certified)" for q in iso]) or "empty"
            proven = r.status == CERTIFIED
            all_cert &= proven
            rows.append((f"C^{j}", runs, "certified" if proven else _interior_status(r)))
            for i, x in enumerate(r.value):
                for side in ("left", "right"):
                    b = x[side]
                    v = b.get("exact", b.get("open_end"))
                    nums.append(Number(f"C^{j} run {i + 1} {side}", sp.sstr(v) if v is not None else
                                       float((b["bracket"][0] + b["bracket"][1]) / 2),
                                       tol=0 if v is not None else 10 * tol))
            nums += [Number(f"C^{j} isolated point", q) for q in iso]
            if not r.value and not iso:
                break
        largest = max([j for j, r in sets.items() if r.value or points[j]], default=-1)
        ev.append(evidence(f"C^j sets of {p.name} in {interval_text(lo, hi)}", table=(("j", "set", "status"), *rows),
                           result=sets[0] if all_cert else None,
                           text=f"{k} generic smoothing factors" + (
                               "; exceptional values: " + ", ".join(f"{p.name} = {sp.sstr(q)} ({m} factors)"
                                                                   for q, m in exc.items()) if exc else "")
                           + f"; largest j with a non-empty set: {largest}"))
        curve = alpha_curve(a, p, within=(lo, hi), samples=self.get("samples", 8))
        if any(points.values()):  # an isolated point of a C^j set: its alpha belongs beside the samples
            for q in sorted({q for v in points.values() for q in v} - {x["p"] for x in curve.value}):
                h = holder_exponent(a.subs({p: q}))
                curve.value.append({"p": q, "lower": h.lower, "upper": h.upper, "status": h.status})
        alpha_line, alpha_nums, alpha_ev = alpha_maximum(
            a, p, lo, hi, curve.value, note=" (with the isolated C^j points)" if any(points.values()) else "")
        nums += alpha_nums
        ev.append(alpha_ev)
        nums.insert(0, Number("largest j", largest))
        profile = "; ".join(f"{r[0]}: {r[1]}" for r in rows) + f"; {alpha_line}"
        beside = []
        for b in self.get("beside") or ():
            blo, bhi, _, _ = parse_interval(b["interval"])
            j = int(b["j"])
            text, key = beside_text(sets, points, j, blo, bhi, p)
            short = f"certified C^{j} set {compact_set(sets[j], points.get(j, ()))}: {key}" if j in sets else key
            beside.append((b["claim"], text, short))
            nums.append(Number(f"beside {b['claim']}", key))
        self.profile = {"parameter": p.name, "within": interval_text(lo, hi), "largest": largest,
                        "rows": rows, "compact": [(f"C^{j}", compact_set(sets[j], points[j]), row[2]) for j, row in zip(sets, rows)],
                        "alpha": alpha_line, "exceptional": [(sp.sstr(q), m) for q, m in exc.items()],
                        "beside": beside}
        claim = self.get("claimed")
        if claim is None:
            if all_cert:
                return self.certified(f"smoothness profile of {self.where_text()}", evidence=ev, numbers=nums,
                                      sharpness=profile)
            return self.inconclusive(f"smoothness profile of {self.where_text()} (boundaries certified, some interiors "
                                     "not covered by the norm tests)",
                                     settle="the strips next to ends of eigenvalue type: an extremal (invariant "
                                            "polytope) norm on parameter boxes, or the norm tests with a larger L",
                                     evidence=ev, numbers=nums, sharpness=profile)
        cj = claim["j"]
        clo, chi, _, _ = parse_interval(claim["interval"])
        which, key = which_set(sets, clo, chi)
        v = verify_smoothness_interval(a, cj, (clo, chi), p)
        ev.insert(0, evidence(f"claimed: C^{cj} on {interval_text(clo, chi)}", v if v.status in (CERTIFIED, REFUTED) else None,
                              text=f"route: {v.witness.get('route')}; {which}"))
        nums.append(Number("printed interval is", key))
        sharp = f"{which}. {profile}"
        if v.value is True:
            return self.certified(f"true, {key}: C^{cj} on {interval_text(clo, chi)} proven ({v.witness.get('route')})",
                                  evidence=ev, numbers=nums, sharpness=sharp)
        if v.value is False:
            true = next((r[1] for r in rows if r[0] == f"C^{cj}"), "see the profile")
            return self.refuted(f"false: not C^{cj} at {p.name} = {sp.sstr(v.witness['counterexample'])} (certified); {which}",
                                corrected=f"C^{cj} exactly on {true}", evidence=ev, numbers=nums, sharpness=sharp)
        ev[0] = evidence(ev[0].title, text=ev[0].text)
        return self.inconclusive(f"C^{cj} on {interval_text(clo, chi)} neither proven nor refuted; {which}",
                                 settle=v.provenance.get("message", "finer norm tests"), evidence=ev, numbers=nums,
                                 sharpness=sharp)


#: work units of JSR search per alpha sample point of :func:`profile_by_sets` (analysis.jsr.jsr_bounds)
SET_ALPHA_BUDGET = 2_000


def profile_by_sets(kind) -> Verdict:
    """The ``smoothness profile`` kind from the exact C^j sets (used for arity ``m > 2``): for each ``j`` the
    C^j set of :func:`analysis.regularity.ranges.ck_range` — the union of the exact sets where the Dyn–Levin test
    ``||(1/m S_{a_{j+1}})^L||_inf < 1`` holds (C^j proven) and the exact set where one transition matrix of
    ``c = m^k a/q_m^(k+1)`` has a real eigenvalue of modulus ``>= m^(k-j)`` (not C^j proven); what neither covers
    is *undecided* (inconclusive, never certified). The Hölder exponent is enclosed at ``samples + 1`` rational
    points only (:func:`analysis.regularity.ranges.alpha_curve`): its maximum is sampled, not certified."""
    a, m = kind.symbol(), kind.arity
    p = kind.single_parameter()
    lo, hi = kind._within()
    N = smoothing_factor(a, exceptional=False, arity=m).value
    max_j = kind.get("max_j", max(N - 1, 0))
    sets, rows, nums, all_cert = {}, [], [], True
    for j in range(0, min(max_j, N - 1) + 1):
        r = ck_range(a, j, p, Ls=SET_LS, within=(lo, hi), arity=m)
        sets[j] = r
        all_cert &= bool(r.witness["exact"])
        rows.append((f"C^{j}", set_text(r.value), "certified" if r.witness["exact"] else
                     f"undecided on {set_text(r.witness['undecided'])}"))
        nums.append(Number(f"C^{j} set", set_text(r.value)))
        if not r.witness["exact"]:
            nums.append(Number(f"C^{j} undecided", set_text(r.witness["undecided"])))
        if r.value == sp.EmptySet and r.witness["exact"]:
            break
    largest = max([j for j, r in sets.items() if r.value != sp.EmptySet], default=-1)
    ev = [evidence(f"C^j sets of {p.name} in {interval_text(lo, hi)} ({m}-ary)", table=(("j", "set", "status"), *rows),
                   text=f"{N} generic factors (1+...+z^{m - 1})/{m}; largest j with a non-empty C^j set: {largest}")]
    curve = alpha_curve(a, p, within=(lo, hi), samples=kind.get("samples", 8), budget=SET_ALPHA_BUDGET, arity=m).value
    alpha_line, alpha_nums, alpha_ev = alpha_maximum(a, p, lo, hi, curve, arity=m)
    nums += alpha_nums
    ev.append(alpha_ev)
    nums.insert(0, Number("largest j", largest))
    profile = "; ".join(f"{r[0]}: {r[1]}" + ("" if r[2] == "certified" else f" ({r[2]})") for r in rows) + f"; {alpha_line}"
    claim = kind.get("claimed")
    where = kind.where_text()
    if claim is None:
        if all_cert:
            return kind.certified(f"smoothness profile of {where} ({m}-ary)", evidence=ev, numbers=nums,
                                  sharpness=profile)
        return kind.inconclusive(f"smoothness profile of {where} ({m}-ary; some C^j sets have undecided strips)",
                                 settle="longer norm tests or point-wise JSR verdicts on the undecided strips",
                                 evidence=ev, numbers=nums, sharpness=profile)
    cj = claim["j"]
    clo, chi, _, _ = parse_interval(claim["interval"])
    if cj > N - 1:
        return kind.refuted(f"false: C^{cj} needs {cj + 1} factors 1+...+z^{m - 1}; the family has {N}",
                            corrected=f"at most C^{N - 1}", evidence=ev, numbers=nums, sharpness=profile)
    r = sets.get(cj)
    if r is None or not (bool(clo >= lo) and bool(chi <= hi)):
        r = ck_range(a, cj, p, Ls=SET_LS, within=(clo, chi), arity=m)
    V = r.witness["not_Cj"].intersect(sp.Interval.open(clo, chi))
    inside = sp.Interval.open(clo, chi).is_subset(r.value)
    exact_set = r.witness["exact"] and r.value == sp.Interval.open(clo, chi)
    which = (f"the printed interval {interval_text(clo, chi)} is the C^{cj} set" if exact_set else
             f"the C^{cj} set (within {interval_text(lo, hi)}) is {set_text(r.value)}"
             + ("" if r.witness["exact"] else f", undecided on {set_text(r.witness['undecided'])}"))
    ev.insert(0, evidence(f"claimed: C^{cj} on {interval_text(clo, chi)}", r, text=which))
    sharp = f"{which}. {profile}"
    if inside:
        return kind.certified(f"true: C^{cj} on {interval_text(clo, chi)} proven ({m}-ary Dyn-Levin norm sets)",
                              evidence=ev, numbers=nums, sharpness=sharp)
    q = point_in(V)
    if q is not None:
        return kind.refuted(f"false: not C^{cj} at {p.name} = {sp.sstr(q)} (certified: a transition matrix has an "
                            f"eigenvalue of modulus >= {m}^{N - 1 - cj}); {which}",
                            corrected=f"C^{cj} exactly on {set_text(r.value)}" if r.witness["exact"] else which,
                            evidence=ev, numbers=nums, sharpness=sharp)
    return kind.inconclusive(f"C^{cj} on {interval_text(clo, chi)} neither proven nor refuted; {which}",
                             settle="longer norm tests or point-wise JSR verdicts", evidence=ev, numbers=nums,
                             sharpness=sharp)
