"""Claim kind "curve comparison": which of several level-dependent schemes constructs given
closed curves best ("the trigonometric form is more suitable for circles and ellipses"), measured
on control points sampled from the exact curve (issue 11).

Fields: ``compare`` (the schemes and their labels), ``curves`` (circle, ellipse, cardioid,
astroid, lemniscate), ``best`` (the claimed winner's label), ``at`` (parameter values, per curve in
``curve_at``), ``vary`` (one parameter swept over a list: the ranking may depend on it), ``points``
and ``steps``; ``generation`` certifies exact generation of exponentials (e.g. ``e^(+-i alpha x)``
for circles) for some of the schemes; ``figure`` / ``draw`` name the comparison plot and the
curve drawn with every scheme.

Examples
--------
>>> from analysis.levels.level_dependent import H, LevelDependentScheme
>>> from analysis.claims.kinds.base import SchemeSpec
>>> t = sp.Symbol("t", positive=True)
>>> v = sp.cos(t * H / 2)                      # the trigonometric Chaikin scheme: circles exactly
>>> trig = LevelDependentScheme((1 / (2 * (1 + v)), (2 * v + 1) / (2 * (1 + v)),
...                              (2 * v + 1) / (2 * (1 + v)), 1 / (2 * (1 + v))), -2, (t,))
>>> q = sp.Rational(1, 4)
>>> chaikin = LevelDependentScheme((q, 3 * q, 3 * q, q), -2)
>>> S = {"trig": SchemeSpec("trig", None, level=trig), "chaikin": SchemeSpec("chaikin", None, level=chaikin)}
>>> v = CurveComparison({"compare": [{"scheme": "trig", "label": "trigonometric"},
...                                  {"scheme": "chaikin", "label": "Chaikin"}],
...                      "curves": ["circle"], "best": "trigonometric", "at": {"t": "pi/5"}, "steps": 4},
...                     S, "x").evaluate()
>>> v.status, v.summary.split(":")[0], [n.name for n in v.numbers]
('numerical', 'True numerically for every case', ['circle.trigonometric.None=None', 'circle.Chaikin.None=None'])

Algorithm
---------
:func:`analysis.levels.reproduction.curve_deviation` (float64 refinement of ``points`` control
points ``curve(2 pi j/points)``, ``steps`` times): the maximal relative radial deviation for
circle and ellipse, the discrete Hausdorff distance to the exact curve otherwise. Differences at
rounding level (1e-12) are ties. Always ``numerical``; the generation checks are exact
(:func:`analysis.levels.reproduction.generation`).

References
----------
W. us Salam, S. S. Siddiqi, K. Rehan, Alexandria Eng. J. (2016), Sect. 6 (seed 003).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from ...levels.reproduction import CURVES, _curve, curve_deviation, generation, refine_closed
from ...result import AnalysisError
from ..model import Figure, Number, Series, Verdict
from ...algebra.reader import read_in_context
from ..names import check_slug
from .base import Kind, evidence, parse_number

__all__ = ["CurveComparison"]

_TIE = 1e-12


def _s(x) -> str:
    return "None" if x is None else sp.sstr(x)


class CurveComparison(Kind):
    """Which scheme constructs the given curves best (numerical, float64 refinement)."""

    name = "curve comparison"
    summary = "which level-dependent scheme constructs given closed curves best (float64; numerical)"
    uses_scheme = False
    required = {"compare": "[{ scheme, label }] the level-dependent schemes compared", "curves": "curve names",
                "best": "the label of the scheme claimed best"}
    optional = {"at": "parameter values", "curve_at": "{ curve = { name = value } } per-curve values",
                "vary": "{ name = [values] }: one parameter swept", "points": "control points (default 10)",
                "steps": "refinement steps (default 6)", "generation": "{ lambdas, schemes, vary }: exact checks",
                "figure": "{ name, title }: the deviation plot", "draw": "{ curve, name, at }: the refined curves"}
    example = ('compare = [{ scheme = "exp-chaikin", label = "exponential Chaikin" }]\ncurves = ["circle"]\n'
               'best = "exponential Chaikin"\nat = { t = "pi/5" }')

    def check(self) -> None:
        comp = self.get("compare")
        if not isinstance(comp, list) or not comp or not all(isinstance(c, dict) and {"scheme", "label"} <= set(c)
                                                               for c in comp):
            raise AnalysisError(f"{self.where}: 'compare' is a list [{{ scheme = ..., label = ... }}]")
        for c in comp:
            s = self.schemes.get(c["scheme"])
            if s is None or s.level is None:
                raise AnalysisError(f"{self.where}: {c['scheme']!r} is not a level-dependent scheme of the file")
        self.labels = [c["label"] for c in comp]
        if self.get("best") not in self.labels:
            raise AnalysisError(f"{self.where}: 'best' must be one of the labels {', '.join(self.labels)}")
        bad = [c for c in self.get("curves") if c not in CURVES]
        if bad:
            raise AnalysisError(f"{self.where}: unknown curve {bad[0]!r}; the curves are {', '.join(CURVES)}")
        vary = self.get("vary", {})
        if not isinstance(vary, dict) or len(vary) > 1:
            raise AnalysisError(f"{self.where}: 'vary' is {{ name = [values] }} (one parameter)")
        for key in ("figure", "draw"):          # the names become figure files, figures/<name>.png
            t = self.get(key)
            if t is None:
                continue
            if not isinstance(t, dict) or "name" not in t:
                raise AnalysisError(f"{self.where}: '{key}' is a table {{ name = \"...\", ... }}")
            check_slug(t["name"], f"{self.where}: {key} name", '"conics-003"')
        self.vary_name, vals = next(iter(vary.items()), (None, [None]))
        self.vary_values = [None if v is None else parse_number(v, f"{self.where}: vary") for v in vals]
        for c in comp:                               # bad values fail when the file is loaded
            for curve in self.get("curves"):
                self._values(c, curve, None)

    def _values(self, c: dict, curve: str, v) -> dict:
        lv = self.schemes[c["scheme"]].level
        names = {p.name for p in lv.params}
        raw = {**(self.get("at") or {}), **((self.get("curve_at") or {}).get(curve, {}))}
        out = {k: parse_number(x, f"{self.where}: at {k}") for k, x in raw.items() if k in names}
        if v is not None and self.vary_name in names:
            out[self.vary_name] = v
        return out

    def _varies(self, c: dict) -> bool:
        return self.vary_name in {p.name for p in self.schemes[c["scheme"]].level.params}

    def table(self) -> dict:
        """(curve, label, vary value or None) -> curve_deviation Result."""
        if getattr(self, "_table", None) is None:
            pts, steps = self.get("points", 10), self.get("steps", 6)
            self._table = {(curve, c["label"], v if self._varies(c) else None):
                           curve_deviation(self.schemes[c["scheme"]].level, curve, self._values(c, curve, v),
                                           points=pts, steps=steps)
                           for curve in self.get("curves") for c in self.get("compare")
                           for v in (self.vary_values if self._varies(c) else [None])}
        return self._table

    def _row(self, curve, v) -> dict:
        t = self.table()
        return {c["label"]: t[(curve, c["label"], v if self._varies(c) else None)].value for c in self.get("compare")}

    def _best(self, curve, v) -> str:
        row = self._row(curve, v)
        lo = min(row.values())
        tied = [n for n, x in row.items() if x <= lo + _TIE]
        return tied[0] if len(tied) == 1 else "tie: " + " = ".join(tied)

    def evaluate(self) -> Verdict:
        curves, vs = self.get("curves"), self.vary_values
        wins = {(c, _s(v)): self._best(c, v) for c in curves for v in vs}
        best = self.get("best")
        won = [k for k, w in wins.items() if w == best]
        by: dict = {}
        for (c, o), w in wins.items():
            by.setdefault(w, []).append(f"{c}@{o}")
        winners = "; ".join(f"{w}: {', '.join(x)}" for w, x in by.items())
        rows = [("curve", self.vary_name or "") + tuple(self.labels) + ("best",)]
        for c in curves:
            for v in vs:
                row = self._row(c, v)
                rows.append((c, _s(v)) + tuple(f"{row[n]:.3e}" for n in self.labels) + (wins[(c, _s(v))],))
        pts, steps = self.get("points", 10), self.get("steps", 6)
        first = self.table()[(curves[0], best, vs[0] if self._varies(self.get("compare")[self.labels.index(best)]) else None)]
        ev = [evidence(f"deviation after {steps} steps from {pts} control points on the curve", first,
                       text="value: maximal relative radial deviation for circle/ellipse (0 = exact shape, whatever "
                            "its size), discrete Hausdorff distance to the exact curve otherwise", table=tuple(rows))]
        gen_text = self._generation(ev)
        nums = [Number(f"{c}.{lab}.{self.vary_name}={_s(v)}", r.value, tol=1e-6)
                for (c, lab, v), r in self.table().items()]
        what = (f"{best} is strictly closest in {len(won)} of {len(wins)} (curve, {self.vary_name or 'case'}) cases "
                f"({', '.join(f'{c} at {self.vary_name} = {o}' for c, o in won) or 'none'}); winners: {winners}."
                + (f" Exact generation: {gen_text}." if gen_text else ""))
        lead = "True numerically for every case: " if len(won) == len(wins) else "Not as a general statement: "
        return Verdict("numerical", lead + what, evidence=ev, numbers=nums, figures=self._figures(),
                       sharpness="float64 refinement from one sampling of the curve; the ranking may depend on "
                                 "the parameters")

    def _generation(self, ev) -> str:
        g = self.get("generation")
        if not g:
            return ""
        out = []
        for c in (x for x in self.get("compare") if x["scheme"] in g.get("schemes", [])):
            lv = self.schemes[c["scheme"]].level
            loc = {p.name: p for p in lv.params}
            try:
                lams = [read_in_context(x, loc, what="lambda", free=True) for x in g["lambdas"]]
            except AnalysisError as exc:
                raise AnalysisError(f"{self.where}: {exc}") from None
            for v in (g.get("vary", [None]) if self._varies(c) else [None]):
                vals = {self.vary_name: parse_number(v)} if v is not None else None
                r = generation(lv, lams, vals)
                label = f"{c['label']}" + (f" {self.vary_name} = {v}" if v is not None else "")
                ev.append(evidence(f"exact generation of e^(lambda x), lambda in {g['lambdas']}: {label}", r,
                                   text=f"{r.status}: {'generates' if r.value else 'does not generate'}"))
                out.append(f"{label}: {'yes' if r.value else 'no'} ({r.status})")
        return "; ".join(out)

    def _figures(self) -> list:
        figs = []
        f = self.get("figure")
        if f:
            xs = tuple(float(v) if v is not None else 0.0 for v in self.vary_values)
            styles = ("o-", "s--", "^:", "d-.")
            series = [Series(f"{curve}: {lab}", xs, tuple(self._row(curve, v)[lab] for v in self.vary_values),
                             styles[i % 4]) for curve in self.get("curves") for i, lab in enumerate(self.labels)]
            figs.append(Figure(f["name"], f.get("title", ""), tuple(series), xlabel=self.vary_name or "",
                               ylabel="deviation (radial for conics, Hausdorff otherwise)"))
        d = self.get("draw")
        if d:
            fc = _curve(d["curve"])
            dense = fc(np.linspace(0, 2 * np.pi, 400))
            series = [Series(f"exact {d['curve']}", tuple(dense[:, 0]), tuple(dense[:, 1]), "g:")]
            t0 = 2 * np.pi * np.arange(self.get("points", 10)) / self.get("points", 10)
            for c in self.get("compare"):
                vals = self._values(c, d["curve"], None)
                extra = {k: parse_number(x) for k, x in (d.get("at") or {}).items() if k in
                         {p.name for p in self.schemes[c["scheme"]].level.params}}
                P = refine_closed(self.schemes[c["scheme"]].level, fc(t0), self.get("steps", 6), {**vals, **extra})
                P = np.vstack([P, P[:1]])
                series.append(Series(c["label"] + "".join(f", {k} = {_s(x)}" for k, x in extra.items()),
                                     tuple(P[:, 0]), tuple(P[:, 1]), "-"))
            figs.append(Figure(d["name"], f"{d['curve']}: {self.get('points', 10)} control points, "
                                          f"{self.get('steps', 6)} steps", tuple(series), equal_aspect=True))
        return figs
