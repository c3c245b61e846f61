"""Claim kinds that need no scheme: a claim that is cited and not checkable here, and a bespoke
Python evaluator referenced by dotted name. The lemma inequality over (n, parameter box) lives in
:mod:`.lemma` with the other lemma kinds and is re-exported here (its first-edition form below).

Examples
--------
>>> Inequality({"lhs": "sin(2**(-n))", "rhs": "2**(-n)", "n0": 1}, {}, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = Cited({"source": "[7, Thm 2]", "settle": "the proof in [7]"}, {}, "x").evaluate()
>>> v.label, v.settle
('INCONCLUSIVE', 'the proof in [7]')
>>> Python({"evaluator": "no.such.module:f"}, {}, "x")
Traceback (most recent call last):
...
analysis.result.AnalysisError: x: cannot import the evaluator module 'no.such.module'

Algorithm
---------
The inequality is proven by Arb branch and bound for the first levels and a Taylor model in
``h = 2^-n`` for the tail (:func:`analysis.levels.bounds.check_inequality`; see :mod:`.lemma`).

References
----------
F. Johansson, *Arb*, IEEE Trans. Comput. 66 (2017).
"""

from __future__ import annotations

import importlib

from ...result import AnalysisError
from ..model import Verdict
from .base import Kind
from .lemma import Inequality  # the lemma inequality kind lives with the other lemma kinds (issue 11)

__all__ = ["Inequality", "Cited", "Python"]


class Cited(Kind):
    """A statement cited from elsewhere, or not checkable with this engine: says what would settle it."""

    name = "cited"
    summary = "cited / not checkable here: inconclusive, with what would settle it"
    uses_scheme = False
    required = {"settle": "what would settle the claim"}
    optional = {"source": "where the result is proven", "why": "why it is not checked here"}
    example = 'source = "Dyn, Levin, Acta Numer. 11 (2002), Thm 4.7"\nsettle = "the proof of the cited theorem"'

    def evaluate(self) -> Verdict:
        src = self.get("source")
        why = self.get("why", "a cited result, not re-derived here" if src else "not checkable with this engine")
        return self.inconclusive(f"{why}" + (f" (cited from {src})" if src else ""), settle=self.get("settle"))


class Python(Kind):
    """A bespoke evaluator ``"package.module:function"`` returning a :class:`~analysis.claims.model.Verdict`."""

    name = "python"
    summary = "a bespoke Python evaluator \"package.module:function\" returning a Verdict"
    uses_scheme = False
    required = {"evaluator": "\"package.module:function\""}
    optional = {"reports_as": "the kind shown in reports (e.g. \"mask identity\"; default \"python\")",
                "args": "positional arguments of the evaluator (a list of TOML values; default none)"}
    example = 'evaluator = "papers.seed000.claims:_v_s_d"'

    def check(self) -> None:
        ev = self.get("evaluator")
        if not isinstance(ev, str) or ev.count(":") != 1:
            raise AnalysisError(f"{self.where}: evaluator must be \"package.module:function\", not {ev!r}")
        if not isinstance(self.get("args", []), list):
            raise AnalysisError(f"{self.where}: args must be a list, e.g. args = [1, \"P0\"]")
        self.function()

    def shown_kind(self) -> str:
        return str(self.get("reports_as", self.name))

    def function(self):
        mod, _, fn = self.get("evaluator").partition(":")
        try:
            m = importlib.import_module(mod)
        except ImportError:
            raise AnalysisError(f"{self.where}: cannot import the evaluator module {mod!r}") from None
        f = getattr(m, fn, None)
        if not callable(f):
            raise AnalysisError(f"{self.where}: module {mod!r} has no function {fn!r}")
        return f

    def evaluate(self) -> Verdict:
        v = self.function()(*self.get("args", []))
        if not isinstance(v, Verdict):
            raise TypeError(f"{self.get('evaluator')} returned {type(v).__name__}, not a Verdict")
        return v
