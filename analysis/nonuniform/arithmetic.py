"""Number contexts of the NVPS engine: one algorithm, four arithmetics.

One algorithm, four arithmetics (``arithmetic=``): ``"float"`` (numpy float64, vectorised),
``"mp"`` (mpmath ``mpf`` at ``prec`` bits, numpy object arrays), ``"iv"`` (``mpmath.iv``
intervals: rigorous enclosures of every refined point) and ``"exact"`` (sympy numbers, e.g.
rational data and parameters whose square-root updates stay rational).

:class:`_Arith` converts inputs to one of them, gives a vectorised square root and a precision
scope; :class:`_ivprec` is the precision scope of ``mpmath.iv``.

>>> _Arith("exact").array([0.5, "1/3", Fraction(2, 7)]).tolist()
[1/2, 1/3, 2/7]
>>> ctx = _Arith("iv", 64)
>>> with ctx.scope():
...     x = ctx.scalar("1/3")                       # an enclosure of 1/3 at 64 bits
>>> x.a < x.b, float(x.delta) < 2 ** -60
(True, True)
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from ..result import AnalysisError
from ..algebra.reader import as_expr

ARITHMETICS = ("float", "mp", "iv", "exact")


class _ivprec:
    def __init__(self, prec: int):
        self.prec = prec

    def __enter__(self):
        self.saved = mpmath.iv.prec
        mpmath.iv.prec = self.prec

    def __exit__(self, *exc):
        mpmath.iv.prec = self.saved
        return False


_SYMPY_SQRT = np.frompyfunc(sp.sqrt, 1, 1)


class _Arith:
    """A number context: conversion of inputs, a vectorised square root, a precision scope."""

    def __init__(self, name: str, prec: int = 113):
        if name not in ARITHMETICS:
            raise AnalysisError(f"unknown arithmetic {name!r}; use one of {', '.join(ARITHMETICS)}")
        if not isinstance(prec, int) or prec < 24:
            raise AnalysisError("prec must be an integer number of bits >= 24")
        self.name, self.prec = name, prec
        if name == "float":
            self.sqrt = np.sqrt
        elif name == "mp":
            self.sqrt = np.frompyfunc(mpmath.mp.sqrt, 1, 1)
        elif name == "iv":
            self.sqrt = np.frompyfunc(mpmath.iv.sqrt, 1, 1)
        else:
            self.sqrt = _SYMPY_SQRT

    def scope(self):
        if self.name == "mp":
            return mpmath.workprec(self.prec)
        if self.name == "iv":
            return _ivprec(self.prec)
        import contextlib

        return contextlib.nullcontext()

    def scalar(self, x):
        if isinstance(x, (bool, np.bool_)):
            raise AnalysisError(f"value {x!r} is not a number")
        if self.name == "float":
            try:
                f = float(x)
            except (TypeError, ValueError):
                raise AnalysisError(f"value {x!r} is not a real number") from None
            if not math.isfinite(f):
                raise AnalysisError("the data or parameters contain NaN or infinite values")
            return f
        if isinstance(x, str):
            x = as_expr(x, what="value")
        if self.name == "exact":
            if isinstance(x, float):
                if not math.isfinite(x):
                    raise AnalysisError("the data or parameters contain NaN or infinite values")
                return sp.Rational(x)
            if isinstance(x, Fraction):
                return sp.Rational(x.numerator, x.denominator)
            if isinstance(x, np.generic):
                x = x.item()
            e = as_expr(x)
            if not e.is_real or e.free_symbols:
                raise AnalysisError(f"exact arithmetic needs real numbers, not {x!r}")
            return e
        ctx = mpmath.mp if self.name == "mp" else mpmath.iv
        if isinstance(x, Fraction):
            return ctx.mpf(x.numerator) / x.denominator
        if isinstance(x, sp.Basic):
            if x.is_Rational:
                return ctx.mpf(int(x.p)) / int(x.q)
            if self.name == "iv":
                from ..algebra.algebraic import enclose

                return enclose(x, self.prec)
            return ctx.mpf(sp.N(x, int(self.prec * 0.31) + 5))
        if isinstance(x, np.generic):
            x = x.item()
        if isinstance(x, float) and not math.isfinite(x):
            raise AnalysisError("the data or parameters contain NaN or infinite values")
        return ctx.mpf(x)

    def array(self, xs) -> np.ndarray:
        arr = np.asarray(xs, dtype=object)
        flat = [self.scalar(x) for x in arr.ravel()]
        if self.name == "float":
            return np.array(flat, dtype=float).reshape(arr.shape)
        out = np.empty(len(flat), dtype=object)
        out[:] = flat
        return out.reshape(arr.shape)
