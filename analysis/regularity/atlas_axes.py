"""The axes of a Hölder atlas (:mod:`analysis.regularity.atlas`): ``NAME=LO:HI:N`` read exactly, and the limits on
the number of grid points (each point is a certified Hölder analysis).

Examples
--------
>>> parse_axis("w=0:1/8:5")
('w', 0, 1/8, 5)
"""

from __future__ import annotations

import sympy as sp

from ..algebra.symbol import parse_coefficient
from ..result import AnalysisError

#: Grid points of one axis, and of the whole grid (before refinement): each point is a Hölder analysis.
MAX_AXIS_POINTS = 257
MAX_GRID_POINTS = 10_000


def _rational(value, what: str) -> sp.Rational:
    v = parse_coefficient(value)
    if v.free_symbols or not v.is_Rational:
        raise AnalysisError(f"{what} must be an exact rational number, not {sp.sstr(v)!r}")
    return sp.Rational(v)


def _parse_range(range_, name: str) -> tuple[sp.Rational, sp.Rational]:
    if isinstance(range_, str):
        parts = range_.split(":")
    else:
        try:
            parts = list(range_)
        except TypeError:
            raise AnalysisError(f"the range of {name} must be a pair (low, high)") from None
    if len(parts) != 2:
        raise AnalysisError(f"the range of {name} must be a pair (low, high)")
    lo, hi = (_rational(v, f"the range end of {name}") for v in parts)
    if lo > hi:
        raise AnalysisError(f"the range of {name} needs low <= high, got [{lo}, {hi}]")
    return lo, hi


def parse_axis(text: str) -> tuple[str, sp.Rational, sp.Rational, int]:
    """Read ``NAME=LO:HI:N`` (``N`` grid points, ends included) into ``(name, lo, hi, n)``.

    >>> parse_axis("mu=-0.2:1/5:9")
    ('mu', -1/5, 1/5, 9)
    >>> parse_axis("nu=0:2")
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: malformed axis 'nu=0:2': use NAME=LO:HI:N, e.g. mu=-1/5:1/5:9
    """
    bad = AnalysisError(f"malformed axis {text!r}: use NAME=LO:HI:N, e.g. mu=-1/5:1/5:9")
    if "=" not in text:
        raise bad
    name, spec = (s.strip() for s in text.split("=", 1))
    parts = [p.strip() for p in spec.split(":")]
    if not name.isidentifier() or len(parts) != 3 or not all(parts):
        raise bad
    lo, hi = _parse_range(parts[:2], name)
    try:
        n = int(parts[2]) if len(parts[2]) <= 12 else MAX_AXIS_POINTS + 1
    except ValueError:
        raise AnalysisError(f"the number of points of {name} must be an integer, not {parts[2]!r}") from None
    _check_points(name, n)
    return name, lo, hi, n


def _check_points(name: str, n) -> None:
    """At most :data:`MAX_AXIS_POINTS` points on one axis.

    >>> _check_points("w", 100000)
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: 100000 points for w exceed the limit 257 per axis: use fewer, e.g. w=LO:HI:33, and --refine to add points where the verdicts change
    """
    if isinstance(n, int) and not isinstance(n, bool) and n > MAX_AXIS_POINTS:
        raise AnalysisError(f"{n} points for {name} exceed the limit {MAX_AXIS_POINTS} per axis: use fewer, e.g. "
                            f"{name}=LO:HI:33, and --refine to add points where the verdicts change")
