"""Divided difference schemes of level-dependent schemes of any arity: ``(m/q_m)^j a^n``, ``q_m = 1+z+...+z^(m-1)``.

One implementation for every arity ``m``: the binary case is
:meth:`analysis.levels.level_dependent.LevelDependentScheme.difference` (``(2/(1+z))^j a^n``, unchanged);
``m >= 3`` divides by ``q_m`` with the synthetic division of :func:`divide_by_q` (used by
:meth:`analysis.levels.level_dependent.LevelDependentScheme.difference` and by the C^k routes of :mod:`.ck`).

Why ``m/q_m``. With ``f^{n+1}(z) = a^n(z) f^n(z^m)`` and ``(1-z) a^n(z) = (1-z^m) a^n(z)/q_m(z)``,
``m^{n+1} (1-z) f^{n+1}(z) = (m a^n/q_m)(z) * m^n (1-z^m) f^n(z^m)``: the scaled differences ``m^n Delta f^n`` are
refined by ``e^n = m a^n/q_m``. The stationary difference schemes of :mod:`analysis.stationary.difference`,
``a_k = (m z^{m-1}/q_m)^k a``, are the same up to the shift ``z^{(m-1)k}``, which norms and smoothness do not see
(here the lowest exponent is kept, as the binary "divided" spelling does).

Examples
--------
>>> import sympy as sp
>>> from analysis.levels.level_dependent import H
>>> divide_by_q([sp.Integer(1), 1 + H, 1 + H, H], 3, 1)          # (1+z+z^2)(1 + h z)
[3, 3*h]
>>> divide_by_q([sp.Integer(1), 1 + H, sp.Integer(1)], 3, 1)
Traceback (most recent call last):
...
analysis.result.AnalysisError: 1+z+z^2 does not divide a^n(z) identically in n (remainder coefficient h)

References
----------
N. Dyn, *Subdivision schemes in CAGD*, in: Advances in Numerical Analysis II, Oxford (1992) 36-104 (divided
difference schemes, binary); C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of
any arity*, J. Approx. Theory 163 (2011) 413-437 (m-ary symbols).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .level_dependent import H, LevelDependentScheme
from ..result import AnalysisError
from ..algebra.reader import as_expr

__all__ = ["q_label", "divide_by_q", "divided_difference"]


def _exact_zero(expr: sp.Expr) -> bool:
    """``expr == 0`` proved by sympy simplification (exp-rewritten, plain, trig-expanded); False: no proof.

    The answer is "some simplification gives 0", so the order only decides the time: the exp-rewritten form
    goes first because it proves the identities of exponential generation and reproduction (trigonometric and
    hyperbolic coefficients times ``exp(lambda h)``), where plain ``simplify`` spends about a second and fails.
    """
    e = as_expr(expr)
    if e == 0:
        return True
    if e not in _ZERO_PROOFS:
        if len(_ZERO_PROOFS) >= 256:
            _ZERO_PROOFS.clear()
        _ZERO_PROOFS[e] = _prove_zero(e)
    return _ZERO_PROOFS[e]


#: the answers of :func:`_exact_zero` by expression (bounded): generation, reproduction and the claims
#: beside them ask about the same sub-symbol identities, and each simplification costs up to seconds
_ZERO_PROOFS: dict = {}


def _prove_zero(e: sp.Expr) -> bool:
    if _nonzero_somewhere(e):
        return False        # no simplification can prove it zero: skip them (seconds each)
    for f in (lambda x: sp.cancel(sp.together(x.rewrite(sp.exp))), lambda x: sp.simplify(x.rewrite(sp.exp)),
              lambda x: sp.simplify(x),
              lambda x: sp.simplify(sp.expand_trig(x))):
        try:
            if f(e) == 0:
                return True
        except Exception:  # noqa: BLE001 - a failed simplification is not a proof either way
            continue
    return False


def _nonzero_somewhere(e: sp.Expr) -> bool:
    """True when ``e`` is certainly not identically zero: its value at a rational point (respecting the
    symbols' sign and integer assumptions) is finite and, at 50 significant digits, of modulus > 1e-20
    (``evalf`` guarantees the digits it returns). False means nothing (a singular point, a tiny value)."""
    symbols = sorted(e.free_symbols, key=lambda x: x.name)
    for shift in (0, 1):
        values = {}
        for i, x in enumerate(symbols):
            if x.is_integer:
                v = sp.Integer(3 + i + 2 * shift)
            else:
                v = sp.Rational(3 + 2 * i + shift, 7 + 3 * i)
            if x.is_negative or x.is_nonpositive:
                v = -v
            if x.is_zero or (x.is_integer is False and v.is_integer) or (x.is_rational is False):
                return False        # assumptions a rational point cannot satisfy
            values[x] = v
        try:
            z = e.subs(values).evalf(50)
        except Exception:  # noqa: BLE001 - a point where the expression is undefined proves nothing
            continue
        if not z.is_number or z.free_symbols or z.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            continue
        try:
            if abs(complex(z)) > 1e-20:
                return True
        except (TypeError, ValueError, OverflowError):
            continue
    return False


def q_label(m: int) -> str:
    """``1+z+...+z^(m-1)`` as printed in messages."""
    return "1+" + "+".join(f"z^{i}" if i > 1 else "z" for i in range(1, m))


def _divide_once(coeffs, m: int) -> tuple[list, list]:
    """One synthetic division by ``q_m`` from the top power: ``(quotient, remainder)`` (``len(coeffs) >= m``)."""
    r = list(coeffs)
    quot = [sp.Integer(0)] * (len(r) - m + 1)
    for k in range(len(r) - 1, m - 2, -1):
        c = r[k]
        quot[k - m + 1] = c
        for i in range(m):
            r[k - m + 1 + i] = r[k - m + 1 + i] - c
    return quot, r[: m - 1]


def certainly_not_divisible(coeffs, m: int) -> bool:
    """True when ``q_m`` certainly does not divide ``sum_k coeffs[k] z^k`` identically: a remainder coefficient is
    non-zero at a rational point (:func:`_nonzero_somewhere`), so no simplification can prove it zero and
    :func:`divide_by_q` (``m = 2``: :meth:`~analysis.levels.level_dependent.LevelDependentScheme.difference`, whose
    remainder ``a^n(-1)`` is the same up to sign) raises. False means nothing. A cheap test before the exact one."""
    if len(coeffs) < m:
        return False
    return any(_nonzero_somewhere(sp.expand(x)) for x in _divide_once(coeffs, m)[1])


def divide_by_q(coeffs, m: int, j: int) -> list:
    """The coefficients of ``(m/q_m)^j a^n`` (ascending, same lowest exponent) of ``a^n`` (``coeffs`` ascending).

    Each remainder must simplify to 0 identically in ``h`` and the parameters, else an :class:`AnalysisError`.
    """
    return list(_divide_by_q(tuple(coeffs), m, j))


def _divide_by_q(coeffs: tuple, m: int, j: int) -> tuple:
    """:func:`divide_by_q` as ``j`` single divisions (:func:`_divide_step`, remembered: the C^k routes ask for the
    same divisions for every k and every j; a failed division raises each time)."""
    for _ in range(j):
        out = _divide_step(coeffs, m)
        if isinstance(out, str):
            raise AnalysisError(out)
        coeffs = out
    return coeffs


@lru_cache(maxsize=256)
def _divide_step(coeffs: tuple, m: int) -> tuple | str:
    """The coefficients of ``(m/q_m) a^n`` (``coeffs`` those of ``a^n``), or the message of the
    :class:`AnalysisError` when ``q_m`` does not divide ``a^n`` identically (a pure function of its arguments)."""
    q = q_label(m)
    if len(coeffs) < m:
        return f"{q} does not divide a^n(z): the mask is too short"
    quot, rem = _divide_once(coeffs, m)
    for x in rem:
        if not _exact_zero(sp.expand(x)):
            return (f"{q} does not divide a^n(z) identically in n (remainder coefficient "
                    f"{sp.sstr(sp.simplify(x))})")
    return tuple(sp.cancel(m * c) if as_expr(c).is_rational_function(H) else sp.simplify(m * c) for c in quot)


def divided_difference(s: LevelDependentScheme, j: int, arity: int | None = None) -> LevelDependentScheme:
    """``(m/q_m)^j a^n`` as a :class:`LevelDependentScheme` (``m`` the scheme's arity unless given; ``m = 2``:
    ``s.difference(j)``). The lowest exponent is kept: the shift ``z^(m-1)`` of
    ``m^{n+1} Delta f^{n+1} = S_{z^(m-1) b^n} (m^n Delta f^n)`` is dropped (norms and smoothness do not see it).

    >>> from .expbspline import ternary_exponential_bspline_2
    >>> divided_difference(ternary_exponential_bspline_2(), 1).limit().expr().factor()   # ternary linear B-spline
    (z**2 + z + 1)**2/(3*z**3)
    """
    arity = s.arity if arity is None else arity
    if isinstance(j, bool) or not isinstance(j, int) or j < 0:
        raise AnalysisError(f"difference must be a non-negative integer, not {j!r}")
    if arity == 2:
        return s.difference(j)
    coeffs = divide_by_q(s.mask, arity, j)
    return LevelDependentScheme(tuple(coeffs), s.start, s.params, slug=f"{s.slug}-diff{j}",
                                title=f"{j}-th divided difference of {s.title or s.slug}", source=s.source,
                                arity=arity)
