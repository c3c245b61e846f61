"""Claim kinds that need no scheme: a claim that is cited and not checkable here, and a bespoke
Python evaluator referenced by dotted name (run only for the bundled papers or when the user passes
``--allow-python``: a paper file is data, never code). The lemma inequality over (n, parameter box) lives in
:mod:`.lemma` with the other lemma kinds and is re-exported here (its first-edition form below).

Examples
--------
>>> Inequality({"lhs": "sin(2**(-n))", "rhs": "2**(-n)", "n0": 1}, {}, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = Cited({"source": "[7, Thm 2]", "settle": "the proof in [7]"}, {}, "x").evaluate()
>>> v.label, v.settle
('INCONCLUSIVE', 'the proof in [7]')
>>> Python({"evaluator": "no.such.module:f"}, {}, "x", python="allowed")
Traceback (most recent call last):
...
analysis.result.AnalysisError: x: cannot import the evaluator module 'no.such.module'
>>> v = Python({"evaluator": "os:system", "args": ["touch /tmp/marker"]}, {}, "x").evaluate()   # not trusted
>>> v.label, v.summary.startswith("not run")
('INCONCLUSIVE', True)
>>> Python({"evaluator": "../../etc:passwd"}, {}, "x")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
analysis.result.AnalysisError: x: evaluator must be "package.module:function" (Python names separated by dots, ...

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
import re

from ...result import AnalysisError
from ..model import Verdict
from .base import Kind
from .lemma import Inequality  # the lemma inequality kind lives with the other lemma kinds (issue 11)

__all__ = ["Inequality", "Cited", "Python", "EVALUATOR", "PYTHON_MODES", "NOT_RUN_SETTLE"]


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


#: ``package.module:function``: dotted Python identifiers only (no ``..``, ``/`` or leading dots)
EVALUATOR = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*:[A-Za-z_][A-Za-z0-9_]*")

#: what a ``python`` claim that was not run says would settle it
NOT_RUN_SETTLE = ("if you trust the paper file, run the command again with --allow-python "
                  "(subdiv report FILE.toml --allow-python)")

#: how a paper file's ``python`` claims are treated (:func:`analysis.claims.paperfile.parse_paper`):
#: ``"skip"`` not run (a paper file is data: the claim is inconclusive and says how to run it),
#: ``"allowed"`` run because the user passed ``--allow-python`` (the report says that it ran code),
#: ``"bundled"`` run: a paper shipped with the tool (its evaluators are the tool's own code)
PYTHON_MODES = ("skip", "allowed", "bundled")


class Python(Kind):
    """A bespoke evaluator ``"package.module:function"`` returning a :class:`~analysis.claims.model.Verdict`.

    The evaluator is imported and run only when the paper is trusted (``python = "allowed"`` or
    ``"bundled"``); otherwise nothing is imported and the claim is inconclusive, saying that it was not
    run. The evaluator string is checked against :data:`EVALUATOR` before anything else.
    """

    name = "python"
    summary = ("a bespoke Python evaluator \"package.module:function\" returning a Verdict (runs only for the "
               "bundled papers or with --allow-python)")
    uses_scheme = False
    required = {"evaluator": "\"package.module:function\""}
    optional = {"reports_as": "the kind shown in reports (e.g. \"mask identity\"; default \"python\")",
                "args": "positional arguments of the evaluator (a list of TOML values; default none)"}
    example = 'evaluator = "papers.seed000.claims:_v_s_d"'

    def __init__(self, fields, schemes, where: str, *, python: str = "skip"):
        if python not in PYTHON_MODES:
            raise ValueError(f"python must be one of {PYTHON_MODES}, not {python!r}")
        self.python = python
        super().__init__(fields, schemes, where)

    @property
    def runs(self) -> bool:
        """Whether the evaluator is imported and run (a bundled paper, or ``--allow-python``)."""
        return self.python != "skip"

    def check(self) -> None:
        ev = self.get("evaluator")
        if not isinstance(ev, str) or EVALUATOR.fullmatch(ev) is None:
            shown = repr(ev) if not isinstance(ev, str) or len(ev) <= 80 else repr(ev[:77] + "...")
            raise AnalysisError(f"{self.where}: evaluator must be \"package.module:function\" (Python names "
                                f"separated by dots, e.g. \"mypaper.claims:theorem_2\"), not {shown}")
        if not isinstance(self.get("args", []), list):
            raise AnalysisError(f"{self.where}: args must be a list, e.g. args = [1, \"P0\"]")
        if self.runs:                # a trusted paper: a missing module or function fails at load time
            self.function()

    def shown_kind(self) -> str:
        return str(self.get("reports_as", self.name))

    def function(self):
        if not self.runs:            # never reached through the kind's own methods: a second lock
            raise AnalysisError(f"{self.where}: Python code from a paper file runs only with --allow-python")
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
        if not self.runs:
            return self.inconclusive(
                f"not run: Python code named by the paper file (evaluator {self.get('evaluator')}) runs only "
                "with --allow-python",
                settle=NOT_RUN_SETTLE)
        v = self.function()(*self.get("args", []))
        if not isinstance(v, Verdict):
            raise TypeError(f"{self.get('evaluator')} returned {type(v).__name__}, not a Verdict")
        return v
