"""Convergence (the sum rules), the difference mask of the Hölder formula, and exact helpers
shared by the regularity routines.

A binary scheme can converge only if ``a(1) = 2`` and ``a(-1) = 0``; a failure is a
**certified** verdict (:class:`NotConvergent`), not bad input. With ``N`` factors ``(1+z)``,
``k = N - 1`` and ``c = 2^k a/(1+z)^(k+1)`` (:func:`difference_mask`), ``alpha = k - log2 rho(c)``.
"""

from __future__ import annotations

import mpmath
import sympy as sp

from ..algebra.factorization import factor_out, smoothing_factor
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, AnalysisError, Result

iv = mpmath.iv


class NotConvergent(AnalysisError):
    """The scheme fails a sum rule, so it does not converge — a **certified** verdict, not bad
    input. ``reason`` is the exact failure (``"a(-1) = 1/2 != 0"``, ``"a(1) = 5/2 != 2"``);
    :meth:`result` is the verdict as a certified :class:`Result` (``value`` False).

    A subclass of :class:`AnalysisError`, so callers that only ask for an exponent keep working;
    callers that report regularity (``subdiv holder``, :func:`smoothness`) turn it into a result.
    """

    def __init__(self, reason: str, *, hint: str | None = None):
        self.reason = reason
        self.hint = hint
        super().__init__(f"the scheme does not satisfy the sum rules a(1) = 2, a(-1) = 0 ({reason}): "
                         "it does not converge" + (f"; {hint}" if hint else ""))

    def result(self) -> Result:
        return Result(value=False, status=CERTIFIED,
                      witness={"convergent": False, "reason": f"not convergent: {self.reason}",
                               **({"hint": self.hint} if self.hint else {})},
                      provenance={"method": "exact sum rules a(1) = 2, a(-1) = 0 (necessary for convergence)"})


def convergence_failure(a: LaurentSymbol) -> str | None:
    """``None`` when ``a(1) = 2`` and ``a(-1) = 0`` exactly, else the reason, e.g.
    ``"a(-1) = 1/2 != 0"`` (both sum rules are necessary for convergence).

    >>> convergence_failure(LaurentSymbol.from_mask(["1/4", "1/2", "1", "1/4"]))
    'a(-1) = 1/2 != 0'
    """
    a.require_numeric("the sum rules")
    s1, sm1 = sp.expand(a(1)), sp.expand(a(-1))
    bad = []
    if s1 - 2 != 0:
        t = sp.sstr(s1)
        bad.append(f"a(1) = {t} != 2" if len(t) <= 24 else f"a(1) - 2 = {sp.sstr(sp.N(s1 - 2, 3))} != 0")
    if sm1 != 0:
        t = sp.sstr(sm1)
        bad.append(f"a(-1) = {t} != 0" if len(t) <= 24 else f"a(-1) = {sp.sstr(sp.N(sm1, 3))} != 0")
    if bad and _from_doubles(a) and abs(s1 - 2) + abs(sm1) < sp.Rational(1, 10 ** 12):
        bad.append("the coefficients are doubles taken at their exact binary values, which miss the sum rules by "
                   "rounding: give decimals as text ('0.1' is 1/10) or read the doubles as balls "
                   "(analysis.Scheme(mask), subdiv holder --approx)")
    return "; ".join(bad) or None


def _from_doubles(a: LaurentSymbol) -> bool:
    """Do some coefficients look like doubles read exactly (denominators powers of two of 2^40 or more)?"""
    qs = [c.q for c in a.mask if isinstance(c, sp.Rational)]
    return any(q >= 2 ** 40 and q & (q - 1) == 0 for q in qs)


def difference_mask(a: LaurentSymbol) -> tuple[int, LaurentSymbol]:
    """``(k, c)`` with ``k = N - 1`` (``N`` factors ``(1+z)``) and ``c = 2^k a / (1+z)^(k+1)``.

    Raises :class:`NotConvergent` (a certified verdict) when a sum rule fails."""
    a.require_numeric("a Hölder exponent")
    why = convergence_failure(a)
    if why is not None:
        raise NotConvergent(why)
    N = smoothing_factor(a, exceptional=False).value
    return N - 1, factor_out(a, N) / 2


def log2_interval(lo: sp.Rational, hi: sp.Rational, prec: int = 90):
    """Rational outward bounds of ``[log2 lo, log2 hi]``."""
    from ..algebra.algebraic import _q

    old = iv.prec
    iv.prec = prec
    try:
        L1 = iv.log(iv.mpf(int(lo.p)) / int(lo.q)) / iv.log(2)
        L2 = iv.log(iv.mpf(int(hi.p)) / int(hi.q)) / iv.log(2)
        return _q(L1.a), _q(L2.b)
    finally:
        iv.prec = old


def power_of_two_exponent(x: sp.Rational) -> int | None:
    """``e`` if ``x == 2^e`` exactly, else None."""
    x = sp.Rational(x)
    if x <= 0:
        return None
    p, q = int(x.p), int(x.q)
    if p & (p - 1) == 0 and q & (q - 1) == 0:
        return p.bit_length() - q.bit_length()
    return None
