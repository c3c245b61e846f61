"""The claim kind ``smoothness``: "S is C^k" or "S is not C^k", for one scheme (or one parameter point),
decided both ways by the engine.

A stationary scheme of any arity m is C^k exactly when ``alpha > k`` (for ``k`` below its number of
smoothing factors): :func:`analysis.regularity.holder.smoothness` (binary) and
:func:`analysis.regularity.holder.smoothness` (m-ary) decide it — the Dyn–Levin norm test for "C^k",
an exact spectral radius ``rho(Pi) >= m^((N-1-k) L)`` of a product of transition matrices for "not C^k"
(this decides the borderline ``alpha = k`` exactly: Chaikin is not C^2, the four-point scheme at
``w = 1/16`` is not C^2 and at ``w = 0`` not C^1), then the joint spectral radius bounds. A level-dependent
scheme (binary or m-ary) is decided by :func:`analysis.levels.ck.level_smoothness` (Dyn–Levin on the divided
difference schemes, generalized differences, asymptotic similarity; "not C^k" for exponential B-spline
schemes). Beside the verdict the kind states the certified truth around ``k`` ("C^1 but not C^2"),
searching the neighbouring orders until both sides are certified.

Fields: ``C = k`` (required), ``holds = true`` (default; ``false`` for "not C^k"), ``at = { w = "1/16" }``
(every parameter must be fixed: a parameter range is the kind ``ck range`` or ``smoothness profile``),
``budget`` (work units of the joint spectral radius search).

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> chaikin = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
>>> S = {"chaikin": SchemeSpec("chaikin", chaikin)}
>>> Smoothness({"C": 1}, S, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = Smoothness({"C": 2}, S, "x").evaluate()
>>> v.label, v.corrected
('REFUTED', 'chaikin is C^1 but not C^2 (certified)')
>>> Smoothness({"C": 2, "holds": False}, S, "x").evaluate().label
'CERTIFIED TRUE'

Algorithm
---------
One engine call per order k (exact norm tests and exact spectral radii of short products first, the JSR
within ``budget`` work units only when those do not decide); the neighbouring orders are decided the same
way until the smoothness is bracketed (at most the number of smoothing factors upwards, ``k`` downwards).

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002) 73-144, Thm 3.3 and
Sect. 3.5; O. Rioul, SIAM J. Math. Anal. 23 (1992); N. Dyn, D. Levin, J. Math. Anal. Appl. 193 (1995);
S. Dubuc, J. Math. Anal. Appl. 114 (1986) (the four-point scheme at w = 1/16: alpha = 2, not C^2).
"""

from __future__ import annotations

from ...result import CERTIFIED, AnalysisError, Result
from ..model import Number, Verdict
from .base import Kind, evidence

__all__ = ["Smoothness"]

#: the largest k of a ``smoothness`` claim (C^k needs k + 1 smoothing factors; masks have at most 1000)
MAX_K = 64


def _certified(r: Result | None) -> bool | None:
    """True / False when ``r`` certifies C^k / not C^k, None otherwise."""
    if r is None or r.status != CERTIFIED or r.value not in (True, False):
        return None
    return bool(r.value)


class Smoothness(Kind):
    """``S`` is C^k (``holds = true``) or is not C^k (``holds = false``), certified both ways."""

    name = "smoothness"
    summary = ("the scheme is C^k (holds = true) or is not C^k (holds = false): one scheme or one parameter point, "
               "stationary (any arity) or level-dependent; certified both ways, with the certified truth")
    required = {"C": "k of the claim C^k (0: convergence)"}
    optional = {"holds": "true (default): the scheme is C^k; false: it is not C^k",
                "at": "parameter values (every parameter fixed)",
                "budget": "work units for the JSR search when the exact tests do not decide (default 20000)"}
    example = 'at = { w = "1/16" }\nC = 2\nholds = false'
    any_arity = True
    level_scheme = None          # stationary or level-dependent
    bivariate = True

    def check(self) -> None:
        k = self.integer("C")
        if k > MAX_K:
            raise AnalysisError(f"{self.where}: field 'C' is at most {MAX_K}, not {k}")
        self.boolean("holds", True)
        vals = self.values()
        free = sorted(p.name for p in self.scheme.params if p.name not in vals)
        if free:
            raise AnalysisError(f"{self.where}: kind 'smoothness' speaks of one scheme: fix every parameter with "
                                f"at = {{ {free[0]} = \"...\" }} (free: {', '.join(free)}); for a parameter interval use "
                                + ("kind 'ck range'" if self.scheme.bivariate is not None
                                   else "kind 'ck range' or 'smoothness profile'"))
        b = self.number("budget")
        if b is not None and not (b.is_Integer and 0 < b <= 10 ** 7):
            raise AnalysisError(f"{self.where}: field 'budget' must be an integer number of work units in [1, 10^7]")

    # ------------------------------------------------------------------ stationary schemes
    def _stationary(self, j: int) -> Result:
        from ...regularity.holder import EXACT_BUDGET, smoothness

        budget = int(self.number("budget") or EXACT_BUDGET)
        a = self.symbol()
        return smoothness(a, j, budget=budget, arity=self.arity)

    def _truth_stationary(self, k: int, first: Result) -> tuple[int | None, int | None, dict]:
        """``(yes, no)``: the largest j certified C^j and the smallest certified not C^j found around ``k``."""
        results = {k: first}
        t = _certified(first)
        yes = k if t is True else None
        no = k if t is False else None
        if t is True:
            j = k + 1
            while j <= MAX_K:
                r = results[j] = self._stationary(j)
                tj = _certified(r)
                if tj is True:
                    yes, j = j, j + 1
                    continue
                no = j if tj is False else None
                break
        elif t is False:
            j = k - 1
            while j >= 0:
                r = results[j] = self._stationary(j)
                tj = _certified(r)
                if tj is False:
                    no, j = j, j - 1
                    continue
                yes = j if tj is True else None
                break
            else:
                yes = -1              # not even C^0
        return yes, no, results

    # ------------------------------------------------------------------ level-dependent schemes
    def _level(self, k: int) -> tuple[bool | None, int, int | None, Result, str]:
        """``(holds, yes, no, result, reason)`` for a level-dependent scheme."""
        s, vals = self.scheme.level, self.values()
        from ...levels.ck import level_smoothness

        r = level_smoothness(s, vals, k_max=k + 1)
        verdicts = r.witness["verdicts"]
        yes = r.value                               # C^j certified for every j <= yes
        no = r.witness.get("not_C^k")               # certified not C^no (exponential B-spline schemes)
        entry = next((v for v in verdicts if v["k"] == k), None)
        if no is not None and no <= k:
            e = next(v for v in verdicts if v["k"] == no and v.get("holds") is False)
            return False, yes, no, r, f"not C^{no}: {e['route']}; {e['theorem']}"
        if entry is not None and entry["status"] == CERTIFIED and entry["verdict"] == f"C^{k}" and yes >= k:
            return True, yes, no, r, f"{entry['route']}: {entry['theorem']}"
        if entry is None:
            lim = r.witness["limit"]
            why = (f"the limit scheme is C^k certified only up to k = {lim['C^k_certified_up_to']}"
                   + (f" and certified not C^{lim['not_C^k']}" if lim.get("not_C^k") is not None else ""))
        elif entry.get("reason"):
            why = entry["reason"]
        else:
            why = "; ".join(f"{t['route']}: failed {', '.join(map(str, t['failed']))}" for t in entry.get("tried", []))
        return None, yes, no, r, why or "no route decided it"

    # ------------------------------------------------------------------ the verdict
    def evaluate(self) -> Verdict:
        if self.scheme.bivariate is not None:
            from .bivariate import smoothness_verdict

            return smoothness_verdict(self)
        k = self.get("C")
        claim_holds = self.boolean("holds", True)
        where = self.where_text()
        if self.scheme.level is not None:
            t, yes, no, r, reason = self._level(k)
            level = True
        else:
            first = self._stationary(k)
            t = _certified(first)
            reason = str(first.witness.get("reason", first.provenance.get("message", "")))
            yes, no, results = self._truth_stationary(k, first)
            r, level = first, False
        truth = self._truth_text(yes, no, level)
        nums = [Number(f"C^{k}", "undecided" if t is None else t),
                Number("C^j certified up to j", -1 if yes is None else yes),
                Number("not C^j from j", "none certified" if no is None else no)]
        claim = f"{'' if claim_holds else 'not '}C^{k}"
        if t is None:
            return self.inconclusive(f"{where}: C^{k} undecided ({reason}); {truth}",
                                     settle=("a larger budget (field 'budget'), or an exact analysis of the borderline "
                                             "alpha = k" if not level else
                                             "a theorem whose hypotheses the scheme meets (see the reason)"),
                                     evidence=[evidence(f"C^{k} of {where}", text=reason)], numbers=nums)
        fact = Result(value=t, status=CERTIFIED, witness={"reason": reason, "k": k},
                      provenance={"method": r.provenance.get("method", "") if isinstance(r.provenance, dict) else "",
                                  **({"level_dependent": True} if level else {})})
        ev = [evidence(f"C^{k} of {where}: {'yes' if t else 'no'}", fact, text=reason)]
        said = f"{where} is {'' if t else 'not '}C^{k} (certified: {reason})"
        if t == claim_holds:
            return self.certified(f"{said}; {truth}", evidence=ev, numbers=nums, sharpness=truth)
        return self.refuted(f"{said}, so the claim '{claim}' is false", corrected=truth, evidence=ev, numbers=nums)

    def _truth_text(self, yes: int | None, no: int | None, level: bool) -> str:
        where = self.where_text()
        if yes is not None and no is not None and no == yes + 1:
            return f"{where} is not C^0 (certified)" if yes < 0 else f"{where} is C^{yes} but not C^{no} (certified)"
        parts = []
        if yes is not None and yes >= 0:
            parts.append(f"C^{yes} certified")
        if no is not None:
            parts.append(f"not C^{no} certified")
        rest = "; the orders in between undecided" if yes is not None and no is not None else \
            "; higher orders undecided" if no is None else "; lower orders undecided"
        return f"{where}: " + (" and ".join(parts) + rest if parts else "no order certified either way")
