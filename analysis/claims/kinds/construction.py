"""Claim kind "construction": a scheme built from two schemes of the file by displacement vectors
(seed 004, Sect. 3: "translate the points of Q by a combination of the vectors D = Q - R"), checked
against the printed intermediate rules, the printed result and the printed special cases.

The construction (:func:`analysis.algebra.linear_forms.displacement_construction`, the symbol by
:func:`analysis.algebra.constructions.displacement_symbol`): ``D_{2i} = Q_{2i} - R_{2i}``,
``D_{2i+1} = Q_{2i+1} - R_{2i+1}`` and their shifts ``D_{2i+2s}``; ``DE = sum_s w_s D_{2i+2s}``,
``DO = sum_s w'_s D_{2i+1+2s}``; ``P_{2i} = Q_{2i} - DE``, ``P_{2i+1} = Q_{2i+1} - DO``. Fields:
``forms`` (printed intermediate rules: ``{ first = p, coefficients = [...] }`` on ``P_{i+p}``, or an
expression in the names of the other forms, e.g. ``"nu*D_{2i}"``), ``substitute`` (compare the forms in
a sub-family), ``cases`` (the construction at given parameters is another scheme of the file), and the
claim's ``scheme`` (the printed result: its symbol must be the constructed one; ``result = false`` skips).

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> w = sp.Symbol("w")
>>> q = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)          # Chaikin
>>> r = LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)                     # linear B-spline
>>> c = LaurentSymbol.from_expr(sp.expand((1 - w) * q.expr() + w * r.expr()))  # Q - w (Q - R)
>>> S = {"q": SchemeSpec("q", q), "r": SchemeSpec("r", r), "c": SchemeSpec("c", c)}
>>> f = {"scheme": "c", "from": {"Q": "q", "R": "r"}, "weights": {"even": {"0": "w"}, "odd": {"0": "w"}},
...      "forms": {"D_{2i}": {"first": 0, "coefficients": ["-1/4", "1/4"]}, "DE": "w*D_{2i}"},
...      "cases": [{"at": {"w": 1}, "same_as": "r"}, {"at": {"w": 0}, "same_as": "q"}]}
>>> v = Construction(f, S, "x").evaluate()
>>> v.label, v.summary
('CERTIFIED TRUE', "The construction from 'q' and 'r' gives the printed D_{2i}, DE; the symbol of 'c'; 'r' at w = 1 and 'q' at w = 0 (exact)")
>>> Construction({**f, "forms": {"D_{2i}": {"first": 0, "coefficients": ["1/4", "1/4"]}}}, S, "x").evaluate().label
'REFUTED'

Algorithm
---------
Exact linear forms in sympy; forms compare coefficient by coefficient after the substitution; symbols
compare exactly.

References
----------
Seed 004 (2023), Sect. 3.1-3.6.
"""

from __future__ import annotations

import sympy as sp

from ...algebra.constructions import displacement_symbol
from ...algebra.linear_forms import LinearForm, displacement_construction
from ...algebra.symbol import parse_coefficient
from ...result import AnalysisError
from ..model import Evidence, Number, Verdict, exact_result
from .base import Kind, evidence
from ...algebra.reader import read_in_context

__all__ = ["Construction"]


def _rule_forms(a):
    """The even and odd rules of a binary symbol as linear forms on ``P_{i+p}``."""
    even = LinearForm({p: a.coeff(-2 * p) for p in range(-a.end // 2 - 1, -a.start // 2 + 2)})
    odd = LinearForm({p: a.coeff(1 - 2 * p) for p in range((1 - a.end) // 2 - 1, (1 - a.start) // 2 + 2)})
    return even, odd


class Construction(Kind):
    """A displacement construction vs its printed intermediate rules, result and special cases."""

    name = "construction"
    summary = "a displacement construction P = Q - sum w D (D = Q - R) vs the printed rules, result and special cases"
    required = {"from": "{ Q = \"scheme\", R = \"scheme\" }", "weights": "{ even = { \"s\" = w_s }, odd = { \"s\" = w'_s } }"}
    optional = {"forms": "{ name = { first = p, coefficients = [...] } or \"expression in other forms\" }",
                "substitute": "{ parameter = \"expression\" }: compare the forms in a sub-family",
                "cases": "[{ at = {...}, same_as = \"scheme\" }]: special cases", "result": "false: do not compare "
                "the claim's scheme with the constructed one"}
    example = ('from = { Q = "four-point", R = "four-point" }\nweights = { even = { "0" = "w" }, odd = { "0" = "w" } }\n'
               'forms = { "D_{2i}" = { first = 0, coefficients = [] } }')

    def check(self) -> None:
        fr, wt = self.get("from"), self.get("weights")
        if not isinstance(fr, dict) or set(fr) != {"Q", "R"} or not all(v in self.schemes for v in fr.values()):
            raise AnalysisError(f"{self.where}: field 'from' is {{ Q = \"scheme\", R = \"scheme\" }} with schemes of the file")
        if not isinstance(wt, dict) or set(wt) != {"even", "odd"}:
            raise AnalysisError(f"{self.where}: field 'weights' is {{ even = {{...}}, odd = {{...}} }}")
        names = {p.name: p for p in self.scheme.params}
        try:
            self.w = [{int(s): parse_coefficient(v, locals_=names) for s, v in wt[k].items()} for k in ("even", "odd")]
        except (ValueError, TypeError, AttributeError, AnalysisError) as exc:
            raise AnalysisError(f"{self.where}: cannot read 'weights': {exc}") from None
        try:
            self.sub = {names[k]: read_in_context(v, names, what=f"substitute {k}", free=True)
                        for k, v in (self.get("substitute") or {}).items() if k in names}
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None
        if set(self.get("substitute") or {}) - set(names):
            raise AnalysisError(f"{self.where}: 'substitute' names a parameter the scheme does not have")
        for c in self.get("cases", []):
            if not isinstance(c, dict) or set(c) != {"at", "same_as"} or c["same_as"] not in self.schemes:
                raise AnalysisError(f"{self.where}: each case is {{ at = {{...}}, same_as = \"scheme of the file\" }}")
            self.scheme.values(c["at"], self.where)

    def build(self) -> dict:
        (qe, qo), (re_, ro) = (_rule_forms(self.schemes[self.get("from")[k]].symbol) for k in ("Q", "R"))
        return displacement_construction(qe, qo, re_, ro, *self.w)

    def printed_form(self, name, spec, built):
        if isinstance(spec, dict) and set(spec) == {"first", "coefficients"}:
            locs = {p.name: p for p in self.scheme.params}
            return LinearForm({spec["first"] + k: parse_coefficient(c, locals_=locs) for k, c in enumerate(spec["coefficients"])})
        if not isinstance(spec, str):
            raise AnalysisError(f"{self.where}: form {name!r} is {{ first = p, coefficients = [...] }} or an expression")
        text, slots = spec, {}
        for k, n in enumerate(sorted(built, key=len, reverse=True)):
            if n in text:
                text = text.replace(n, f"F{k}_")
                slots[sp.Symbol(f"F{k}_")] = built[n]
        try:
            expr = sp.expand(read_in_context(text, {**{p.name: p for p in self.scheme.params},
                                                    **{str(s): s for s in slots}}, what=f"form {name}", free=True))
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None
        out = LinearForm({})
        for s, form in slots.items():
            out = out + form * expr.coeff(s)
        if sp.expand(expr.subs({s: 0 for s in slots})) != 0:
            raise AnalysisError(f"{self.where}: form {name!r}: {spec!r} is not linear in the forms {', '.join(built)}")
        return out

    def evaluate(self) -> Verdict:
        built = self.build()
        sub = self.sub
        rows, ev, bad = [], [], []
        for name, spec in (self.get("forms") or {}).items():
            if name not in built:
                raise AnalysisError(f"{self.where}: unknown form {name!r} (the construction has {', '.join(built)})")
            printed = self.printed_form(name, spec, built).subs(sub)
            derived = built[name].subs(sub)
            ok = printed == derived
            rows.append((name, sp.sstr(printed.to_expr()), sp.sstr(derived.to_expr()), "yes" if ok else "NO"))
            if not ok:
                bad.append(f"{name}: printed {sp.sstr(printed.to_expr())}, derived {sp.sstr(derived.to_expr())}")
        if rows:
            at = (" with " + ", ".join(f"{k} = {sp.sstr(v)}" for k, v in sub.items())) if sub else ""
            ev.append(evidence(f"printed forms vs the construction{at}", exact_result(not bad, "exact linear forms"),
                               table=(("form", "printed (as read)", "derived", "agree"), *rows)))
        sym = displacement_symbol(*_rule_forms(self.schemes[self.get("from")["Q"]].symbol),
                                  *_rule_forms(self.schemes[self.get("from")["R"]].symbol), *self.w)
        if self.get("result", True):
            ok = sym == self.scheme.symbol
            ev.append(Evidence(f"the constructed symbol vs scheme {self.scheme.name!r}", result=exact_result(ok, "exact symbols"),
                               text=f"a(z) = {sp.sstr(sym.expr())}", latex="a(z) = " + sym.latex()))
            ev.append(Evidence("Step 4: P_{2i} = Q_{2i} - DE", latex=r"P_{2i}^{k+1} = " + built["P_{2i}"].latex()))
            if not ok:
                bad.append(f"the constructed symbol is not that of {self.scheme.name!r}")
        for c in self.get("cases", []):
            vals = {sp.Symbol(k): v for k, v in self.scheme.values(c["at"], self.where).items()}
            ok = sym.subs(vals) == self.schemes[c["same_as"]].symbol
            txt = ", ".join(f"{k} = {sp.sstr(v)}" for k, v in vals.items())
            ev.append(evidence(f"at {txt}", exact_result(ok, "substitution"), text=f"scheme {c['same_as']!r}: "
                                                                               + ("yes" if ok else "NO")))
            if not ok:
                bad.append(f"at {txt} the construction is not {c['same_as']!r}")
        nums = [Number("mask_length", len(sym))]
        if not bad:
            at = (" with " + ", ".join(f"{k} = {sp.sstr(v)}" for k, v in sub.items())) if sub else ""
            cases = " and ".join(f"{c['same_as']!r} at " + ", ".join(f"{k} = {v}" for k, v in c["at"].items())
                                 for c in self.get("cases", []))
            parts = ([f"the printed {', '.join(r[0] for r in rows)}{at}"] if rows else []) + \
                    ([f"the symbol of {self.scheme.name!r}"] if self.get("result", True) else []) + ([cases] if cases else [])
            Q, R = self.get("from")["Q"], self.get("from")["R"]
            return self.certified(f"The construction from {Q!r} and {R!r} gives " + "; ".join(parts) + " (exact)",
                                  evidence=ev, numbers=nums)
        return self.refuted("; ".join(bad), corrected="the derived forms in the evidence", evidence=ev, numbers=nums)

