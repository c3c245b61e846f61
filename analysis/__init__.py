"""Subdivision workbench engine: exact Laurent symbols, difference schemes, norms, matrices,
refinement; every analysis returns a :class:`~analysis.result.Result` with a status.

Conventions: ``(S_a f)_i = sum_j a_{i-2j} f_j`` and ``a(z) = sum_i a_i z^i`` (see README).

For notebooks: ``from analysis import Scheme`` (:mod:`analysis.api`), e.g.
``Scheme(["1/4", "3/4", "3/4", "1/4"], start=-2).holder()``; see ``docs/python.md``.

Importing ``analysis`` is cheap: the results contract is imported at once, the symbol algebra
(sympy) only when one of its names is first used (PEP 562 ``__getattr__``), so that the command
line starts without sympy when a command does not need it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .result import Result, AnalysisError, CERTIFIED, NUMERICAL, REFUTED, INCONCLUSIVE

if TYPE_CHECKING:  # pragma: no cover - for type checkers and readers; resolved lazily below
    from .algebra.symbol import LaurentSymbol, Rules, Z, parse_coefficient
    from .api import Scheme

__all__ = ["Result", "AnalysisError", "CERTIFIED", "NUMERICAL", "REFUTED", "INCONCLUSIVE",
           "LaurentSymbol", "Rules", "Z", "parse_coefficient", "Scheme"]
__version__ = "0.1.0"

#: re-exports imported on first use: name -> module (relative to this package)
_LAZY = {"LaurentSymbol": ".algebra.symbol", "Rules": ".algebra.symbol", "Z": ".algebra.symbol",
         "parse_coefficient": ".algebra.symbol", "Scheme": ".api"}


from ._lazy import lazy_exports  # noqa: E402

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
