"""Claim kind "all of": a printed sentence that states several checkable facts at once ("omega = 0
is Chaikin's scheme, and it is C^1"; "(4) and (5) reproduce constants, (2) does not"), each fact a
claim of another kind (issue 11).

Fields: ``parts``, a list of tables, each with a ``kind``, an optional ``label`` and that kind's
fields (``scheme`` included); ``reports_as``: the kind shown in reports (default "all of").

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> S = {"chaikin": SchemeSpec("chaikin", LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2))}
>>> v = AllOf({"parts": [{"kind": "sum rules", "label": "three factors", "factors": 3},
...                      {"kind": "symmetry", "label": "symmetric", "symmetric": True}]}, S, "x").evaluate()
>>> v.label, [n.name for n in v.numbers][:2]
('CERTIFIED TRUE', ['three factors: factors', 'three factors: exceptional values'])
>>> AllOf({"parts": [{"kind": "sum rules", "factors": 4}]}, S, "x").evaluate().label
'REFUTED'

Algorithm
---------
Every part is loaded (validated) with the file and evaluated by its own kind. The verdict is
refuted if a part is refuted (with that part's correction), certified if every part is
certified, numerical if the weakest part is numerical, inconclusive otherwise. Evidence and key
numbers are the parts', prefixed by their labels.

References
----------
Issue 11 ("claims, each with ... a kind and that kind's fields").
"""

from __future__ import annotations

import dataclasses

from ...result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, AnalysisError
from ..model import Evidence, Verdict
from .base import Kind

__all__ = ["AllOf"]


class AllOf(Kind):
    """Every part (a claim of another kind) holds."""

    name = "all of"
    summary = "several facts in one printed sentence: every part, a claim of another kind, must hold"
    uses_scheme = False
    required = {"parts": "[{ kind = \"...\", label = \"...\", <that kind's fields> }]"}
    optional = {"reports_as": "the kind shown in reports (default \"all of\")"}
    example = ('parts = [{ kind = "sum rules", label = "two factors", scheme = "four-point", factors = 2 },\n'
               '         { kind = "symmetry", label = "symmetric", scheme = "four-point", symmetric = true }]')

    def check(self) -> None:
        from . import kind_class

        ps = self.get("parts")
        if not isinstance(ps, list) or not ps or not all(isinstance(p, dict) and "kind" in p for p in ps):
            raise AnalysisError(f"{self.where}: 'parts' is a list of tables, each with a 'kind'")
        self.items = []
        for i, p in enumerate(ps, start=1):
            label = str(p.get("label", f"part {i}"))
            if p["kind"] in (self.name, "python"):
                raise AnalysisError(f"{self.where}: a part of kind {p['kind']!r} is not allowed")
            try:
                cls = kind_class(p["kind"])
            except AnalysisError as exc:
                raise AnalysisError(f"{self.where}: {label}: {exc}") from None
            fields = {k: v for k, v in p.items() if k not in ("kind", "label")}
            self.items.append((label, cls(fields, self.schemes, f"{self.where}: {label}")))

    def shown_kind(self) -> str:
        return str(self.get("reports_as", self.name))

    def evaluate(self) -> Verdict:
        done = [(label, k.evaluate()) for label, k in self.items]
        ev, nums, figs = [], [], []
        for label, v in done:
            ev.append(Evidence(f"{label}: {v.label}", text=v.summary))
            ev.extend(Evidence(f"{label}: {e.title}", text=e.text, latex=e.latex, result=e.result, table=e.table)
                      for e in v.evidence)
            nums.extend(dataclasses.replace(n, name=f"{label}: {n.name}") for n in v.numbers)
            figs.extend(v.figures)
        text = "; ".join(f"{label}: {v.summary}" for label, v in done)
        kw = dict(evidence=ev, numbers=nums, figures=figs)
        statuses = [v.status for _, v in done]
        if REFUTED in statuses:
            bad = [(label, v) for label, v in done if v.status == REFUTED]
            return self.refuted(f"false: {', '.join(label for label, _ in bad)}. {text}",
                                corrected="; ".join(f"{label}: {v.corrected}" for label, v in bad), **kw)
        if all(s == CERTIFIED for s in statuses):
            sharp = "; ".join(f"{label}: {v.sharpness}" for label, v in done if v.sharpness) or None
            return self.certified(f"True, every part certified. {text}", sharpness=sharp, **kw)
        if INCONCLUSIVE in statuses:
            return self.inconclusive(f"not settled: {text}", settle="; ".join(
                f"{label}: {v.settle}" for label, v in done if v.status == INCONCLUSIVE), **kw)
        return Verdict(NUMERICAL, f"numerical evidence only: {text}", **kw)
