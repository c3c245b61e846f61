"""The claim model: claims, verdicts, evidence, papers, evaluation and golden-verdict comparison.

Use it as ``from analysis import claims as C`` (``C.Claim``, ``C.certified(...)``,
``C.Evidence``, ...). Layering: may import every engine layer below (algebra, stationary, jsr,
regularity, levels, nonuniform), never :mod:`analysis.report` or :mod:`analysis.cli`.
"""

from .model import (KINDS, LABELS, Claim, Evaluated, Evidence, Figure, Number, Paper, Series, Verdict,
                    certified, compare_verdicts, contains_interval, evaluate_claim, evaluate_paper,
                    exact_result, exact_set, get_paper, golden_path, inconclusive, papers, refuted, verdicts_json)

__all__ = ["KINDS", "LABELS", "Claim", "Evaluated", "Evidence", "Figure", "Number", "Paper", "Series",
           "Verdict", "certified", "compare_verdicts", "contains_interval", "evaluate_claim", "evaluate_paper",
           "exact_result", "exact_set", "get_paper", "golden_path", "inconclusive", "papers", "refuted", "verdicts_json"]
