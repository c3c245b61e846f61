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
>>> r                                   # one line: the value (or enclosure) and the status
Result(1, certified)
>>> Result(lower=Fraction(1, 3), upper=Fraction(1, 2), status=CERTIFIED)
Result([1/3, 1/2], certified)
>>> Result(lower=Fraction(2, 3), upper=Fraction(2, 3) + Fraction(1, 10**20), status=CERTIFIED)
Result(0.6666666667... (width 1.0e-20), certified)

In IPython/Jupyter a result shows as a small table (``_repr_html_``: value, status, method, the
witness keys), as LaTeX (``_repr_latex_``) or as pretty text (``_repr_pretty_``); ``str(r)`` is
``repr(r)``; the full content is ``r.witness``, ``r.provenance`` and :meth:`Result.to_json`.
"""

from __future__ import annotations

import html as _html
from dataclasses import dataclass, field
from fractions import Fraction
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


def _short(x: Any, digits: int = 10) -> str:
    """A number in a few characters: exact integers and short rationals as they are, others as
    decimals (outward rounding is not needed here: this is display, the exact ends stay in the result)."""
    if isinstance(x, bool) or x is None:
        return str(x)
    text = str(x)
    if len(text) <= 24 and "." not in text and "e" not in text.lower():
        return text
    try:
        return format(float(x), f".{digits}g")
    except (TypeError, ValueError, OverflowError):
        return text if len(text) <= 60 else text[:57] + "..."


def _value_text(r: "Result") -> str:
    if r.value is not None and not isinstance(r.value, (list, tuple, dict)):
        return _short(r.value)
    if r.lower is not None or r.upper is not None:
        lo = "-oo" if r.lower is None else _short(r.lower)
        hi = "oo" if r.upper is None else _short(r.upper)
        if r.lower is not None and r.upper is not None and ("." in lo) != ("." in hi):
            lo, hi = _short(float(r.lower)), _short(float(r.upper))     # both ends as decimals
        if lo != hi:
            return f"[{lo}, {hi}]"
        width = float(r.upper - r.lower)     # the ends agree to 10 digits: those digits, and the width
        return f"{lo}... (width {width:.1e})"
    if r.value is None:
        return "None"
    return f"<{type(r.value).__name__} of {len(r.value)}>"


def _latex_of(x: Any) -> str:
    if isinstance(x, bool) or x is None:
        return r"\text{%s}" % x
    if len(str(x)) > 24:                              # a long exact number: its decimal digits
        return _short(x)
    if isinstance(x, (int, Fraction)) or type(x).__module__.startswith("sympy"):
        import sympy as sp

        if isinstance(x, Fraction):
            x = sp.Rational(x.numerator, x.denominator)
        elif isinstance(x, int):
            x = sp.Integer(x)
        if isinstance(x, sp.Basic):
            return sp.latex(x)
    return r"\text{%s}" % _short(x).replace("\\", "")


@dataclass(frozen=True, repr=False)
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

    def __repr__(self) -> str:
        return f"Result({_value_text(self)}, {self.status})"

    def _repr_pretty_(self, p, cycle) -> None:  # IPython
        p.text(repr(self))
        method = self.provenance.get("method")
        if method and not cycle:
            p.break_()
            p.text(f"  method: {method}")
        message = self.provenance.get("message")
        if message and not cycle:
            p.break_()
            p.text(f"  note: {message}")

    def _repr_latex_(self) -> str:  # Jupyter
        if self.value is not None and not isinstance(self.value, (list, tuple, dict)):
            body = _latex_of(self.value)
        elif self.lower is not None or self.upper is not None:
            lo = r"-\infty" if self.lower is None else _latex_of(self.lower)
            hi = r"\infty" if self.upper is None else _latex_of(self.upper)
            body = rf"\left[{lo},\ {hi}\right]"
        else:
            body = r"\text{%s}" % _value_text(self)
        return rf"${body}\quad\text{{({self.status})}}$"

    def _repr_html_(self) -> str:  # Jupyter
        e = _html.escape
        rows = [("value", _value_text(self)), ("status", self.status)]
        for key in ("method", "message"):
            if self.provenance.get(key):
                rows.append((key, str(self.provenance[key])))
        if self.witness:
            rows.append(("witness", ", ".join(map(str, self.witness))))
        return ('<table class="subdiv-result">' + "".join(
            f"<tr><th style='text-align:left'>{e(k)}</th><td style='text-align:left'>{e(v)}</td></tr>"
            for k, v in rows) + "</table>")

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
