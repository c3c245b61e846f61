"""The results contract: every analysis returns a small immutable :class:`Result`.

A result carries

* ``value`` — the exact value when known (a sympy number or expression), else ``None``;
* ``lower``/``upper`` — an enclosure (exact numbers or rationals) when the value is not exact;
* ``status`` — one of :data:`CERTIFIED`, :data:`NUMERICAL`, :data:`REFUTED`, :data:`INCONCLUSIVE`;
* ``witness`` — what proves it (a factorization, a symbol and its L, a product of matrices…);
* ``provenance`` — method, arithmetic, parameters.

Statuses are used the same way everywhere (see ``DESIGN.md``): *certified* means exact arithmetic
or a rigorous enclosure proves it; a float comparison is never certified.

Examples
--------
>>> r = Result(value=1, status=CERTIFIED, provenance={"method": "exact"})
>>> r.status
'certified'
>>> r.is_certified
True
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

CERTIFIED = "certified"
NUMERICAL = "numerical"
REFUTED = "refuted"
INCONCLUSIVE = "inconclusive"
STATUSES = (CERTIFIED, NUMERICAL, REFUTED, INCONCLUSIVE)


class AnalysisError(ValueError):
    """Bad input to an analysis: the message is one line, fit for a user to read.

    The CLI prints ``subdiv: error: <message>`` and exits with code 2.
    """


@dataclass(frozen=True)
class Result:
    """An analysis outcome with its status, witness and provenance (immutable)."""

    value: Any = None
    status: str = NUMERICAL
    lower: Any = None
    upper: Any = None
    witness: Mapping[str, Any] = field(default_factory=dict)
    provenance: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"unknown status {self.status!r}; expected one of {STATUSES}")

    @property
    def is_certified(self) -> bool:
        return self.status == CERTIFIED

    def to_json(self) -> dict:
        """A JSON-ready dict; exact numbers become strings (and a float approximation)."""
        from .jsonable import jsonable

        return {
            "value": jsonable(self.value),
            "lower": jsonable(self.lower),
            "upper": jsonable(self.upper),
            "status": self.status,
            "witness": jsonable(dict(self.witness)),
            "provenance": jsonable(dict(self.provenance)),
        }
