"""Work budgets: what decides *certified* or *inconclusive* is counted work, never the wall clock.

A :class:`Work` holds a number of work units and counts what is spent from it. The searches charge
it for what they do (see :func:`analysis.jsr.jsr_bounds` for what one unit is in each phase) and
stop when it is exhausted, so the same input gives the same sequence of decisions on every machine,
idle or loaded. A phase that today gets a fraction of "what is left" gets a :meth:`Work.share`: a
child budget whose spending is charged to its parent as well; :meth:`Work.split` cuts what is left
into parts that sum to it exactly.

>>> w = Work(1000)
>>> s = w.share(0.25)            # a quarter of what is left, charged to w as it is spent
>>> s.total, w.left
(250, 1000)
>>> s.charge(300)                # a phase may overrun its share by its last step
>>> s.exhausted, w.spent, w.left
(True, 300, 700)
>>> [p.total for p in w.split([1, 1, 2])]
[175, 175, 350]
"""

from __future__ import annotations

import math
from typing import Sequence

__all__ = ["Work", "as_work"]


class Work:
    """A budget of ``total`` work units (a non-negative integer) and the units ``spent`` from it.

    ``charge(u)`` spends ``u`` units here and in every parent budget; ``exhausted`` is true once
    ``spent >= total`` (a budget of 0 is exhausted at once). Shares are children: spending in a
    share counts against its parent, so the parent's ``left`` shrinks as the phase works.
    """

    __slots__ = ("total", "spent", "_parent", "_listener")

    def __init__(self, total: float, parent: "Work | None" = None, listener=None):
        if not (isinstance(total, (int, float)) and math.isfinite(total) and total >= 0):
            raise ValueError(f"a work budget must be a finite number >= 0, not {total!r}")
        self.total = int(total)
        self.spent = 0
        self._parent = parent
        self._listener = listener          # called with the units charged (progress display; decides nothing)

    def charge(self, units: int = 1) -> None:
        """Spend ``units`` (a non-negative integer) here and in every parent (and tell the listener of
        the outermost budget, if it has one)."""
        units = int(units)
        w: Work = self
        while True:
            w.spent += units
            if w._parent is None:
                break
            w = w._parent
        if w._listener is not None:
            w._listener(units)

    @property
    def left(self) -> int:
        """Units not spent yet (never negative)."""
        return max(self.total - self.spent, 0)

    @property
    def exhausted(self) -> bool:
        return self.spent >= self.total

    def sub(self, units: float) -> "Work":
        """A child budget of ``units`` (rounded down, at most what is left, at least 0)."""
        return Work(min(max(int(units), 0), self.left), parent=self)

    def share(self, fraction: float) -> "Work":
        """A child budget of ``floor(fraction * left)`` units."""
        return self.sub(math.floor(fraction * self.left))

    def split(self, weights: Sequence[float]) -> list["Work"]:
        """Children for what is left, in proportion to ``weights`` (largest remainders get the
        leftover units, earliest first on ties): their totals sum to ``left`` exactly."""
        left = self.left
        tot = float(sum(weights))
        if not weights:
            return []
        if not tot > 0:
            weights, tot = [1.0] * len(weights), float(len(weights))
        exact = [left * float(wt) / tot for wt in weights]
        parts = [math.floor(x) for x in exact]
        order = sorted(range(len(parts)), key=lambda i: (-(exact[i] - parts[i]), i))
        for i in order[: left - sum(parts)]:
            parts[i] += 1
        return [Work(p, parent=self) for p in parts]

    def __repr__(self) -> str:
        return f"Work(total={self.total}, spent={self.spent})"


def as_work(budget: "Work | float | None", default: float) -> Work:
    """``budget`` as a :class:`Work` (a number of units, ``None`` for ``default``); a ``Work`` is
    used as it is (a caller's share)."""
    if isinstance(budget, Work):
        return budget
    return Work(default if budget is None else budget)
