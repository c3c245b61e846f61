"""Conversion of exact objects (sympy numbers, rationals, intervals) to JSON-ready values.

Exact numbers are written as strings in sympy syntax (``"-1/80 + sqrt(6)/80"``) so that nothing is
rounded; where a number is real and explicit, a float approximation is added beside it by callers
that want one (:func:`exact_and_float`).

Examples
--------
>>> import sympy as sp
>>> jsonable(sp.Rational(1, 3))
'1/3'
>>> jsonable({"a": [sp.Integer(2), 0.5]})
{'a': [2, 0.5]}
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import sympy as sp


def jsonable(obj: Any) -> Any:
    """Recursively turn ``obj`` into JSON-serialisable data without rounding exact numbers."""
    if obj is None or isinstance(obj, (bool, str)):
        return obj
    if isinstance(obj, int):
        return obj
    if isinstance(obj, float):
        return obj
    if isinstance(obj, Fraction):
        return str(obj)
    if isinstance(obj, sp.Integer):
        return int(obj)
    if isinstance(obj, sp.Basic):
        return sp.sstr(obj)
    if isinstance(obj, dict):
        return {str(k): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if hasattr(obj, "to_json"):
        return obj.to_json()
    try:  # numpy scalars and arrays
        import numpy as np

        if isinstance(obj, np.ndarray):
            return jsonable(obj.tolist())
        if isinstance(obj, np.generic):
            return obj.item()
    except ImportError:  # pragma: no cover
        pass
    return str(obj)


def exact_and_float(x: Any) -> dict:
    """``{"exact": "...", "float": 0.123}`` for a real exact number ``x``."""
    x = sp.sympify(x)
    out: dict = {"exact": sp.sstr(x)}
    if x.is_real and x.is_number:
        out["float"] = float(sp.N(x, 20))
    return out
