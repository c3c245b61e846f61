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

import sys
from fractions import Fraction
from typing import Any

# No sympy at import: a document of plain values (``subdiv list --json``) is written without it.
# An object can only be a sympy object once sympy is imported, so :func:`jsonable` looks for sympy
# in ``sys.modules``; the functions that build sympy values import it.


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
    sp = sys.modules.get("sympy")                  # None: obj is no sympy object
    if sp is not None and isinstance(obj, sp.Integer):
        return int(obj)
    if sp is not None and isinstance(obj, sp.Basic):
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


def _own_value(x: Any):
    """A sympy object for one of our own values (a sympy object, int, Fraction, float, or a
    rational's text such as ``"1/3"``); text is never parsed as a formula here (user text goes
    through :mod:`analysis.algebra.reader`)."""
    import sympy as sp

    if isinstance(x, sp.Basic):
        return x
    if isinstance(x, str):
        try:
            f = Fraction(x.strip())
        except ValueError:
            raise ValueError(f"not a number: {x[:40]!r}") from None
        return sp.Rational(f.numerator, f.denominator)
    if isinstance(x, (list, tuple, dict, set)):
        raise ValueError(f"not a number: a {type(x).__name__}")
    return sp.sympify(x, strict=True)


def hoist_timing(doc: Any, seconds: float | None = None) -> Any:
    """A JSON-ready document with every ``"timing"`` entry (wall-clock times, which differ from run
    to run) moved to one top-level ``"timing"`` key, keyed by where it was (a dotted path, ``[i]``
    for list items), so that two runs of a command can be compared by dropping that one key.
    ``seconds`` (the whole command's) is added as ``timing["seconds"]``. A document without any
    timing and without ``seconds`` is returned unchanged.

    >>> hoist_timing({"alpha": {"provenance": {"method": "m", "timing": {"seconds": 0.5}}}})
    {'alpha': {'provenance': {'method': 'm'}}, 'timing': {'alpha.provenance': {'seconds': 0.5}}}
    """
    found: dict = {}

    def walk(x: Any, path: str) -> Any:
        if isinstance(x, dict):
            out = {}
            for k, v in x.items():
                if k == "timing":
                    found[path or "."] = v
                else:
                    out[k] = walk(v, f"{path}.{k}" if path else str(k))
            return out
        if isinstance(x, list):
            return [walk(v, f"{path}[{i}]") for i, v in enumerate(x)]
        return x

    body = walk(doc, "")
    if not isinstance(body, dict) or (not found and seconds is None):
        return doc
    timing: dict = {} if seconds is None else {"seconds": round(seconds, 3)}
    timing.update(found)
    body["timing"] = timing
    return body


def exact_and_float(x: Any) -> dict:
    """``{"exact": "...", "float": 0.123}`` for a real exact number ``x``."""
    import sympy as sp

    x = _own_value(x)
    out: dict = {"exact": sp.sstr(x)}
    if x.is_real and x.is_number:
        out["float"] = float(sp.N(x, 20))
    return out


# --------------------------------------------------------------------------------------------
# printing enclosures: outward (directed) decimal rounding
# --------------------------------------------------------------------------------------------

def _as_fraction(x: Any, side: str) -> Fraction:
    """``x`` as an exact Fraction, or (for an irrational number) a rational bound on the ``side``
    of it ("lower": <= x, "upper": >= x)."""
    if isinstance(x, Fraction):
        return x
    if isinstance(x, bool):
        return Fraction(int(x))
    if isinstance(x, int):
        return Fraction(x)
    if isinstance(x, str):                           # "1/3", "0.0133087386193", "1e-12": exact
        try:
            return Fraction(x.strip())
        except ValueError:
            pass
    if isinstance(x, float):
        if x != x or x in (float("inf"), float("-inf")):
            raise ValueError(f"cannot print {x} as a bound")
        return Fraction(x)                            # exact: a float is a dyadic rational
    try:
        import numpy as np

        if isinstance(x, np.generic):
            return _as_fraction(x.item(), side)
    except ImportError:  # pragma: no cover
        pass
    import sympy as sp

    e = _own_value(x)
    if e.is_Rational:
        return Fraction(int(e.p), int(e.q))
    if isinstance(e, sp.Float):
        r = sp.Rational(e)                           # exact: the Float's binary value
        return Fraction(int(r.p), int(r.q))
    if not (e.is_number and e.is_real):
        raise ValueError(f"cannot print {x!r} as a real bound")
    # an irrational real number: 60 correct digits, then one unit of the 55th digit outward
    approx = sp.Rational(sp.N(e, 60))
    q = Fraction(int(approx.p), int(approx.q))
    scale = max(abs(q), Fraction(1, 10 ** 40))
    eps = scale / 10 ** 55
    return q - eps if side == "lower" else q + eps


def _directed(q: Fraction, side: str) -> int:
    """floor(q) for the lower side, ceil(q) for the upper side."""
    n = q.numerator // q.denominator
    return n if side == "lower" or n == q else n + 1


def _decimal10(m: int, decimals: int) -> str:
    """The integer ``m`` times ``10^-decimals`` as a decimal string (never a negative zero)."""
    sign = "-" if m < 0 else ""
    digits = str(abs(m)).rjust(decimals + 1, "0")
    if decimals == 0:
        return sign + digits
    return f"{sign}{digits[:-decimals]}.{digits[-decimals:]}"


def _exponent10(q: Fraction) -> int:
    """``E`` with ``10^E <= |q| < 10^(E+1)`` (``q != 0``), exactly."""
    a = abs(q)
    E = len(str(a.numerator)) - len(str(a.denominator))
    while Fraction(10) ** E > a:
        E -= 1
    while Fraction(10) ** (E + 1) <= a:
        E += 1
    return E


def fmt_bound(x: Any, side: str, digits: int = 10, style: str = "f") -> str:
    """``x`` printed with ``digits`` digits as Python's ``format(x, f".{digits}{style}")`` would,
    but rounded **towards** ``-oo`` (``side="lower"``) or ``+oo`` (``side="upper"``) exactly, so a
    printed enclosure ``[fmt_bound(lo, "lower"), fmt_bound(hi, "upper")]`` contains ``[lo, hi]``;
    never a negative zero. ``style``: ``"f"`` (fixed decimals), ``"e"`` (scientific) or ``"g"``
    (significant digits, trailing zeros removed).

    >>> import sympy as sp
    >>> import sympy as sp
    >>> fmt_bound(sp.Rational(-1, 10**30), "lower"), fmt_bound(sp.Rational(-1, 10**30), "upper")
    ('-0.0000000001', '0.0000000000')
    >>> fmt_bound(sp.sqrt(2), "lower", 4), fmt_bound(sp.sqrt(2), "upper", 4)
    ('1.4142', '1.4143')
    >>> fmt_bound(8.9e-16, "upper", 1, "g"), fmt_bound(2, "upper", 3, "g"), fmt_bound(0.0, "lower", 3, "e")
    ('9e-16', '2', '0.000e+00')
    """
    if side not in ("lower", "upper"):
        raise ValueError(f"side must be 'lower' or 'upper', not {side!r}")
    q = _as_fraction(x, side)
    if style == "f":
        return _decimal10(_directed(q * 10 ** digits, side), digits)
    if style not in ("e", "g"):
        raise ValueError(f"style must be 'f', 'e' or 'g', not {style!r}")
    p = max(digits, 1) if style == "g" else digits + 1          # significant digits
    if q == 0:
        m, E = 0, 0
    else:
        E = _exponent10(q)
        m = _directed(q / Fraction(10) ** (E - p + 1), side)    # p significant digits (maybe p + 1)
        if abs(m) >= 10 ** p:                                     # 9.99.. rounded up to 10.0..
            E += 1
            m = _directed(Fraction(m, 10), side)                   # exact: m is a power of ten then
    if style == "e":
        mant = _decimal10(m, p - 1)
        return f"{mant}e{'-' if E < 0 else '+'}{abs(E):02d}"
    if -4 <= E < p:                                               # %g: fixed notation
        s = _decimal10(m, p - 1 - E)                               # m * 10^(E - p + 1), E < p
        return s.rstrip("0").rstrip(".") if "." in s else s
    mant = _decimal10(m, p - 1)
    mant = mant.rstrip("0").rstrip(".") if "." in mant else mant
    return f"{mant}e{'-' if E < 0 else '+'}{abs(E):02d}"


def fmt_lower(x: Any, digits: int = 10, style: str = "f") -> str:
    """A lower bound ``x`` printed rounded down (see :func:`fmt_bound`)."""
    return fmt_bound(x, "lower", digits, style)


def fmt_upper(x: Any, digits: int = 10, style: str = "f") -> str:
    """An upper bound ``x`` printed rounded up (see :func:`fmt_bound`)."""
    return fmt_bound(x, "upper", digits, style)


def roundoff_text(x: Any, threshold: Any = Fraction(1, 10 ** 12)) -> str:
    """A float64 round-off figure as a statement that does not depend on the machine: ``"< 1e-12"``
    when ``|x|`` is below ``threshold``, else ``|x|`` rounded **up** to one significant digit
    (``"<= 3e-09"``). Printing the raw float (``8.9e-16`` here, ``2.2e-15`` there) would make a
    generated report differ between machines.

    >>> roundoff_text(8.9e-16), roundoff_text(2.2e-15), roundoff_text(2.1e-9)
    ('< 1e-12', '< 1e-12', '<= 3e-09')
    """
    q = abs(_as_fraction(x, "upper"))
    t = _as_fraction(threshold, "upper")
    if q < t:
        return f"< {fmt_upper(t, 1, 'g')}"
    return f"<= {fmt_upper(q, 1, 'g')}"


def stable_float(x: Any, digits: int = 10) -> float:
    """A float64 result rounded to ``digits`` significant digits (round half even of the decimal
    string), so that a key number in a generated report or golden file does not carry the
    machine-dependent last bits of a float64 computation.

    >>> stable_float(0.5000000454133834), stable_float(3.1908685783616296e-05, 6)
    (0.5000000454, 3.19087e-05)
    """
    return float(f"{float(x):.{digits - 1}e}")
