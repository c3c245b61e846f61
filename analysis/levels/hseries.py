"""Exact truncated power series in ``h`` of mask coefficients, without ``sympy.series``.

``sympy.series`` on a rational function of several ``cos(b h)``, ``cosh(b h)``, ``exp(b h)`` (the
masks of exponential B-spline schemes and of their generalized difference schemes,
:mod:`.gendiff`) takes seconds per coefficient; the same exact coefficients come from truncated
power-series arithmetic in a fraction of that. :func:`taylor_rows` computes
``g_{k,j}``, ``j < J``, of ``g_k(h) = a^n_k - a_k`` exactly — what
:meth:`~analysis.levels.level_dependent.LevelDependentScheme.taylor` returns — and
:func:`prefill_taylor` stores them in the scheme's Taylor cache, so that every later request
``taylor(J') , J' <= J`` (weighted series, Taylor models, approximate sum rules) is served from it.
Expressions outside the supported class return ``None`` and the cache is left alone (then
``sympy.series`` is used as before).

Examples
--------
>>> import sympy as sp
>>> from analysis.levels.level_dependent import H
>>> _series(sp.cos(H / 2) / (1 + sp.exp(H)), 4)
[1/2, -1/4, -1/16, 5/96]
>>> sp.series(sp.cos(H / 2) / (1 + sp.exp(H)), H, 0, 4)
1/2 - h/4 - h**2/16 + 5*h**3/96 + O(h**4)

Algorithm
---------
Recursive evaluation on the expression tree with series truncated at ``h^J``: sums and products
(Cauchy product), integer powers (a negative power needs a non-zero constant term: series
inversion ``v_k = -(1/u_0) sum_{i>=1} u_i v_{k-i}``), and ``exp``, ``cos``, ``sin``, ``cosh``,
``sinh`` of a series ``u = u_0 + w`` by the addition theorems and the recurrences
``E' = w' E``, ``C' = -w' S``, ``S' = w' C`` (exact rational coefficients ``1/k``). Any other
node (``sqrt``, ``acos``...) is *unsupported*; a removable singularity ``sin(x h)/sin(y h)`` is supported by
:func:`taylor_polynomial` only (the divisor's vanishing leading terms cancelled exactly against the numerator's).
Coefficients are exact sympy numbers or expressions, normalised as in ``taylor``
(``factor(simplify(.))``).

References
----------
D. E. Knuth, *The Art of Computer Programming*, Vol. 2, 3rd ed., Sec. 4.7 (manipulation of power
series: reciprocals and exponentials by recurrences).
R. P. Brent, H. T. Kung, *Fast algorithms for manipulating formal power series*, J. ACM 25 (1978)
581-595.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
from flint import fmpq

from ..algebra.reader import as_expr

#: the level variable ``h = 2^-n``: the symbol ``analysis.levels.level_dependent.H`` (a sympy symbol is the same by
#: name and assumptions; not imported from there, which uses this module)
H = sp.Symbol("h", positive=True)

__all__ = ["taylor_rows", "prefill_taylor"]


class _Unsupported(Exception):
    pass


def _rational(*series) -> bool:
    """Every coefficient a sympy Rational: the recurrences then run in exact FLINT rationals (``fmpq``: the same
    numbers as sympy's, much faster)."""
    return all(x.is_Rational for s in series for x in s)


def _fractions(s) -> list:
    return [fmpq(int(x.p), int(x.q)) for x in s]


def _rationals(s) -> list:
    return [sp.Rational(int(x.p), int(x.q)) for x in s]


def _mul(a, b, J):
    if _rational(a[:J], b[:J]):
        fa, fb = _fractions(a[:J]), _fractions(b[:J])
        return _rationals(sum((fa[i] * fb[k - i] for i in range(k + 1)), fmpq(0)) for k in range(J))
    return [sp.expand(sum((a[i] * b[k - i] for i in range(k + 1)), sp.Integer(0))) for k in range(J)]


def _inv(a, J):
    a0 = a[0]
    if a0 == 0 or sp.simplify(a0) == 0:
        raise _Unsupported("division by a series without constant term")
    if _rational(a[:J]):
        fa = _fractions(a[:J])
        v = [1 / fa[0]]
        for k in range(1, J):
            v.append(-sum((fa[i] * v[k - i] for i in range(1, k + 1)), fmpq(0)) / fa[0])
        return _rationals(v)
    v = [1 / a0]
    for k in range(1, J):
        v.append(sp.expand(-sum((a[i] * v[k - i] for i in range(1, k + 1)), sp.Integer(0)) / a0))
    return v


def _exp0(w, J):
    """``exp(w)`` for ``w(0) = 0``."""
    if _rational(w[:J]):
        fw = _fractions(w[:J])
        v = [fmpq(1)]
        for k in range(1, J):
            v.append(sum((i * fw[i] * v[k - i] for i in range(1, k + 1)), fmpq(0)) / k)
        return _rationals(v)
    v = [sp.Integer(1)]
    for k in range(1, J):
        v.append(sp.expand(sum((i * w[i] * v[k - i] for i in range(1, k + 1)), sp.Integer(0)) / k))
    return v


def _cos_sin0(w, J, sign):
    """``(cos w, sin w)`` (``sign = -1``) or ``(cosh w, sinh w)`` (``sign = +1``) for ``w(0) = 0``."""
    if _rational(w[:J]):
        fw = _fractions(w[:J])
        c, s = [fmpq(1)], [fmpq(0)]
        for k in range(1, J):
            c.append(sign * sum((i * fw[i] * s[k - i] for i in range(1, k + 1)), fmpq(0)) / k)
            s.append(sum((i * fw[i] * c[k - i] for i in range(1, k + 1)), fmpq(0)) / k)
        return _rationals(c), _rationals(s)
    c, s = [sp.Integer(1)], [sp.Integer(0)]
    for k in range(1, J):
        ck = sign * sum((i * w[i] * s[k - i] for i in range(1, k + 1)), sp.Integer(0)) / k
        sk = sum((i * w[i] * c[k - i] for i in range(1, k + 1)), sp.Integer(0)) / k
        c.append(sp.expand(ck))
        s.append(sp.expand(sk))
    return c, s


def _series(e: sp.Expr, J: int) -> list:
    """The first ``J`` Taylor coefficients of ``e`` in ``h`` at 0 (exact), or :class:`_Unsupported`."""
    if H not in e.free_symbols:
        return [e] + [sp.Integer(0)] * (J - 1)
    if e == H:
        return [sp.Integer(0), sp.Integer(1)] + [sp.Integer(0)] * (J - 2)
    if e.is_Add:
        out = [sp.Integer(0)] * J
        for a in e.args:
            s = _series(a, J)
            out = [x + y for x, y in zip(out, s)]
        return [sp.expand(x) for x in out]
    if e.is_Mul:
        out = None
        for a in e.args:
            s = _series(a, J)
            out = s if out is None else _mul(out, s, J)
        return out
    if e.is_Pow:
        base, ex = e.args
        if H in ex.free_symbols or not ex.is_Integer:
            raise _Unsupported(f"power {e}")
        b = _series(base, J)
        if ex < 0:
            b, ex = _inv(b, J), -ex
        out = [sp.Integer(1)] + [sp.Integer(0)] * (J - 1)
        for _ in range(int(ex)):
            out = _mul(out, b, J)
        return out
    if isinstance(e, (sp.exp, sp.cos, sp.sin, sp.cosh, sp.sinh)):
        u = _series(e.args[0], J)
        u0, w = u[0], [sp.Integer(0)] + u[1:]
        if isinstance(e, sp.exp):
            return [sp.expand(sp.exp(u0) * x) for x in _exp0(w, J)]
        trig = isinstance(e, (sp.cos, sp.sin))
        c, s = _cos_sin0(w, J, -1 if trig else 1)
        C0, S0 = (sp.cos(u0), sp.sin(u0)) if trig else (sp.cosh(u0), sp.sinh(u0))
        if isinstance(e, (sp.cos, sp.cosh)):       # cos(u0 + w) = cos u0 cos w - sin u0 sin w (cosh: +)
            return [sp.expand(C0 * x + (-1 if trig else 1) * S0 * y) for x, y in zip(c, s)]
        return [sp.expand(S0 * x + C0 * y) for x, y in zip(c, s)]
    raise _Unsupported(f"{type(e).__name__}")


def _rational_poly(x: sp.Expr):
    """``x`` as a polynomial over QQ in its free symbols (``Poly``), else :class:`_Unsupported`: the zero tests
    below are exact only there (an expanded polynomial over QQ is 0 exactly when it is the number 0)."""
    syms = sorted(x.free_symbols, key=lambda t: t.name)
    try:
        return sp.Poly(x, *syms, domain=sp.QQ) if syms else sp.Poly(x, H, domain=sp.QQ)
    except (sp.PolynomialError, sp.polys.polyerrors.CoercionFailed) as exc:
        raise _Unsupported(f"coefficient {x}") from exc


def _quotient(a: list, va: int, b: list, vb: int, N: int) -> tuple[list, int]:
    """``a / b`` for series without negative powers whose quotient has none either (``b`` may vanish at 0:
    ``sin(x h)/sin(y h)``); ``va``, ``vb``: how many leading coefficients are known. Returns the quotient
    and how many of its coefficients are known."""
    v = next((i for i in range(vb) if not _rational_poly(b[i]).is_zero), None)
    if v is None or v >= va or any(not _rational_poly(a[i]).is_zero for i in range(v)):
        raise _Unsupported("a pole at h = 0, or too few known terms")
    pad = [sp.Integer(0)] * v
    return _mul(a[v:] + pad, _inv(b[v:] + pad, N), N), min(va, vb) - v


def _series_known(e: sp.Expr, N: int) -> tuple[list, int]:
    """``N`` Taylor coefficients of ``e`` in ``h`` and how many of them are known (a quotient by a series
    vanishing at 0 loses terms at the end), or :class:`_Unsupported`. As :func:`_series`, plus removable
    singularities such as ``sin(h/4)/sin(h)``."""
    if H not in e.free_symbols or e == H:
        return _series(e, N), N
    if e.is_Add:
        out, known = [sp.Integer(0)] * N, N
        for a in e.args:
            s, k = _series_known(a, N)
            out, known = [x + y for x, y in zip(out, s)], min(known, k)
        return [sp.expand(x) for x in out], known
    if e.is_Mul:
        out, known, den = [sp.Integer(1)] + [sp.Integer(0)] * (N - 1), N, []
        for a in e.args:
            if a.is_Pow and a.args[1].is_Integer and a.args[1] < 0:
                b, kb = _series_known(a.args[0], N)
                if _rational_poly(b[0]).is_zero:        # divided by below, once every numerator factor is in
                    den += [(b, kb)] * int(-a.args[1])
                    continue
                s, k = _inv(b, N), kb
                for _ in range(int(-a.args[1]) - 1):
                    s = _mul(s, _inv(b, N), N)
            else:
                s, k = _series_known(a, N)
            out, known = _mul(out, s, N), min(known, k)
        for b, kb in den:
            out, known = _quotient(out, known, b, kb, N)
        return out, known
    if e.is_Pow and e.args[1].is_Integer and e.args[1] > 0:
        b, kb = _series_known(e.args[0], N)
        out = [sp.Integer(1)] + [sp.Integer(0)] * (N - 1)
        for _ in range(int(e.args[1])):
            out = _mul(out, b, N)
        return out, kb
    if isinstance(e, (sp.exp, sp.cos, sp.sin, sp.cosh, sp.sinh)):
        if not _series_known(e.args[0], N)[1] == N:
            raise _Unsupported(f"{e}")
    return _series(e, N), N


def taylor_polynomial(g: sp.Expr, J: int) -> sp.Expr | None:
    """``expand(series(g, h, 0, J).removeO())`` by series arithmetic — the same expression when every
    coefficient is a polynomial over QQ in the parameters (its expanded form is then unique) — or ``None``
    (unsupported: then ``sympy.series``).

    >>> a = sp.Symbol("alpha")
    >>> taylor_polynomial(sp.sin(a * H / 4) / sp.sin(a * H), 4)
    5*alpha**2*h**2/128 + 1/4
    >>> taylor_polynomial(1 / sp.sin(H), 3) is None          # a pole at h = 0
    True
    """
    try:
        for extra in (4, 8):
            s, known = _series_known(g, J + extra)
            if known >= J:
                break
        else:
            return None
        for x in s[:J]:
            _rational_poly(x)
    except (_Unsupported, ZeroDivisionError, TypeError, ValueError):
        return None
    return sp.expand(sum((x * H ** j for j, x in enumerate(s[:J])), sp.Integer(0)))


def taylor_rows(s, J: int) -> tuple | None:
    """``taylor(J)`` of the scheme ``s`` (a :class:`~analysis.levels.level_dependent.LevelDependentScheme`) computed by truncated series arithmetic, or ``None`` (unsupported)."""
    return _taylor_rows(s.mask, s._limits, J)


@lru_cache(maxsize=512)
def _taylor_rows(mask: tuple, limits: tuple, J: int) -> tuple | None:
    """:func:`taylor_rows` of a mask and its limits (a pure function of them, remembered)."""
    rows, done = [], {}                     # a symmetric mask repeats its coefficients: one expansion each
    try:
        for c, c0 in zip(mask, limits):
            if H not in c.free_symbols:
                rows.append(tuple(sp.Integer(0) for _ in range(J)))
                continue
            if (c, c0) not in done:
                ser = _series(as_expr(c), J)
                if sp.simplify(ser[0] - c0) != 0:
                    return None
                done[c, c0] = (sp.Integer(0),) + tuple(sp.factor(sp.simplify(x)) for x in ser[1:])
            rows.append(done[c, c0])
    except (_Unsupported, ZeroDivisionError, TypeError, ValueError):
        return None
    return tuple(rows)


def prefill_taylor(s, J: int = 12) -> bool:
    """Store ``taylor(J)`` in the scheme's cache (see the module); False when unsupported."""
    cache = s.__dict__.setdefault("_taylor_cache", {})
    if any(Jc >= J for Jc in cache):
        return True
    rows = taylor_rows(s, J)
    if rows is None:
        return False
    cache[J] = rows
    return True
