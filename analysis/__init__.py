"""Subdivision workbench engine: exact Laurent symbols, difference schemes, norms, matrices,
refinement; every analysis returns a :class:`~analysis.result.Result` with a status.

Conventions: ``(S_a f)_i = sum_j a_{i-2j} f_j`` and ``a(z) = sum_i a_i z^i`` (see README).
"""

from .result import Result, AnalysisError, CERTIFIED, NUMERICAL, REFUTED, INCONCLUSIVE
from .algebra.symbol import LaurentSymbol, Rules, Z, parse_coefficient

__all__ = ["Result", "AnalysisError", "CERTIFIED", "NUMERICAL", "REFUTED", "INCONCLUSIVE",
           "LaurentSymbol", "Rules", "Z", "parse_coefficient"]
__version__ = "0.1.0"
