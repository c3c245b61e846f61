"""Rigorous ball evaluation of sympy expressions (python-flint ``arb``/``acb``).

:func:`ball` encloses an expression built from rationals, ``pi``, ``E``, parameters (balls or
exact numbers or ``(lo, hi)`` boxes) and the elementary functions Arb can enclose: ``sin cos tan
sec csc cot``, their hyperbolic versions, ``exp log sqrt sinc``, real and complex powers, and the
inverse functions ``asin acos atan asinh acosh atanh``. Used by every module of
:mod:`analysis.levels`.

Examples
--------
>>> import sympy as sp
>>> with workprec(80):
...     b = ball(sp.acos(sp.Rational(1, 2)) - sp.pi / 3)
...     c = ball(sp.acosh(sp.Integer(2)))
>>> b.contains(0), c.contains(sp.log(2 + sp.sqrt(3)).evalf(30))
(True, True)

Algorithm
---------
A recursive walk of the expression tree; every node is one Arb operation, so the result is a
ball guaranteed to contain the exact value (Arb's containment property). A function argument
outside the real domain (``acos`` of a ball reaching beyond ``[-1, 1]``) gives a non-finite real
ball; callers treat non-finite as "not certified".

References
----------
F. Johansson, *Arb: efficient arbitrary-precision midpoint-radius interval arithmetic*,
IEEE Trans. Comput. 66 (2017) 1281-1292.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any, Mapping

import flint
import mpmath
import sympy as sp

from ..result import AnalysisError
from ..algebra.reader import as_expr

# --------------------------------------------------------------------------------------------
# ball evaluation (python-flint arb/acb): rigorous
# --------------------------------------------------------------------------------------------

class workprec:
    """Context manager: python-flint working precision in bits (like ``mpmath.workprec``)."""

    def __init__(self, bits: int):
        self.bits = int(bits)

    def __enter__(self):
        self._old = flint.ctx.prec
        flint.ctx.prec = self.bits
        return self

    def __exit__(self, *exc):
        flint.ctx.prec = self._old


_FUNCS = {"sin": "sin", "cos": "cos", "sinh": "sinh", "cosh": "cosh", "tan": "tan", "tanh": "tanh",
          "exp": "exp", "log": "log", "sinc": "sinc", "sqrt": "sqrt", "sec": "sec", "csc": "csc",
          "cot": "cot", "coth": "coth", "sech": "sech", "csch": "csch",
          "asin": "asin", "acos": "acos", "atan": "atan", "asinh": "asinh", "acosh": "acosh", "atanh": "atanh"}


def ball(expr, env: Mapping[str, Any] | None = None, *, complex_: bool = False):
    """A rigorous ``arb`` (or ``acb``) enclosure of a sympy expression.

    ``env`` maps parameter names to arb/acb balls or exact sympy numbers (or ``(lo, hi)``
    pairs: the ball covering that interval). Use inside :class:`workprec`.

    >>> with workprec(80):
    ...     b = ball(sp.sin(sp.pi / 6) - sp.Rational(1, 2))
    >>> b.contains(0)
    True
    """
    env = dict(env or {})
    cenv = {k: _to_ball(v, complex_) for k, v in env.items()}
    return _ball(as_expr(expr), cenv, complex_)


def _to_ball(v, complex_: bool):
    if isinstance(v, (flint.arb, flint.acb)):
        return flint.acb(v) if complex_ and isinstance(v, flint.arb) else v
    if isinstance(v, tuple) and len(v) == 2:
        lo, hi = (_ball(as_expr(x), {}, False) for x in v)
        b = lo.union(hi)
        return flint.acb(b) if complex_ else b
    return _ball(as_expr(v), {}, complex_)


def _ball(e: sp.Expr, env, cx: bool):
    """The enclosure of ``e`` with the names of ``env`` (see :func:`ball`): :func:`_compiled` evaluated."""
    return _compiled(e, cx)(env)


#: compiled evaluators of the expressions seen last (a pure function of the expression: bounded, no effect on
#: results; an expression with a Float is compiled every time)
_COMPILED: dict = {}
_COMPILED_MAX = 4096


def _compiled(e: sp.Expr, cx: bool):
    """``env -> ball``: the expression tree of ``e`` turned once into nested closures that perform exactly the
    Arb operations of a recursive walk, in the same order and at the working precision of the call (constants
    such as ``1/3`` and ``pi`` are rounded at call time); errors (a missing name, an unsupported function, ``I``
    in real arithmetic) are raised when called, as by the walk."""
    key = (e, cx)
    f = _COMPILED.get(key)
    if f is None:
        floats = []
        f = _compile(e, cx, floats)
        if not floats:
            if len(_COMPILED) >= _COMPILED_MAX:
                _COMPILED.pop(next(iter(_COMPILED)))
            _COMPILED[key] = f
    return f


def _raiser(msg: str):
    def f(env):
        raise AnalysisError(msg)
    return f


def _compile(e: sp.Expr, cx: bool, floats: list):
    T = flint.acb if cx else flint.arb
    if e.is_Integer:
        k = int(e)
        return lambda env: T(k)
    if e.is_Rational:
        p, q = int(e.p), int(e.q)
        return lambda env: T(p) / q
    if e is sp.pi:
        return lambda env: T(flint.arb.pi())
    if e is sp.E:
        return lambda env: T(flint.arb(1).exp())
    if e is sp.I:
        if not cx:
            return _raiser("the expression is complex: evaluate with complex_=True")
        return lambda env: flint.acb(0, 1)
    if isinstance(e, sp.Float):
        floats.append(e)
        return lambda env: T(flint.arb(mpmath.mpf(e)))
    if e.is_Symbol:
        name = e.name

        def sym(env):
            try:
                return env[name]
            except KeyError:
                raise AnalysisError(f"no value for the parameter {name}") from None
        return sym
    if e.is_Add or e.is_Mul:
        parts = [_compile(t, cx, floats) for t in e.args]
        if e.is_Add:
            def add(env):
                out = T(0)
                for g in parts:
                    out = out + g(env)
                return out
            return add

        def mul(env):
            out = T(1)
            for g in parts:
                out = out * g(env)
            return out
        return mul
    if e.is_Pow:
        b, x = e.args
        gb = _compile(b, cx, floats)
        if x.is_Integer:
            k = int(x)
            if k >= 0:
                return lambda env: gb(env) ** k
            return lambda env: 1 / gb(env) ** (-k)
        if x == sp.Rational(1, 2):
            return lambda env: gb(env).sqrt()
        gx = _compile(x, cx, floats)
        return lambda env: (gx(env) * gb(env).log()).exp()
    if isinstance(e, sp.Abs):
        ga = _compile(e.args[0], cx, floats)
        return lambda env: abs(ga(env))
    name = type(e).__name__
    if name == "sinc" and not cx and e.args[0].has(sp.I):
        # real sinc(i v) = sinh(v)/v, even and increasing in |v|: enclose by its values at the ends
        gv = _compile(sp.expand(e.args[0] / sp.I), False, floats)

        def sinc_i(env):
            v = gv(env)
            lo, hi = flint.arb(v.abs_lower()), flint.arb(v.abs_upper())
            f = [flint.arb(1) if x == 0 else x.sinh() / x for x in (lo, hi)]
            return f[0].union(f[1])
        return sinc_i
    if name in _FUNCS and len(e.args) == 1:
        ga, meth = _compile(e.args[0], cx, floats), _FUNCS[name]
        return lambda env: getattr(ga(env), meth)()
    return _raiser(f"cannot evaluate {name} in ball arithmetic")


def arb_abs(x):
    """``|x|`` for an arb ball, with lower end clipped at 0 (arb's ``abs`` may dip below 0)."""
    if x.contains(0):
        return flint.arb(0).union(flint.arb(x.abs_upper()))
    return abs(x)


def ball_to_interval(b) -> tuple[sp.Rational, sp.Rational]:
    """The exact rational endpoints ``(mid - rad, mid + rad)`` of an arb ball."""
    if not b.is_finite():
        raise AnalysisError("the enclosure is not finite (a pole or a too wide parameter box)")
    m, e = b.mid().man_exp()
    r, f = b.rad().man_exp()
    mid = sp.Rational(int(m)) * sp.Rational(2) ** int(e)
    rad = sp.Rational(int(r)) * sp.Rational(2) ** int(f)
    return mid - rad, mid + rad


def _fraction(x: sp.Rational) -> Fraction:
    return Fraction(int(x.p), int(x.q))
