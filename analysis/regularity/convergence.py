"""Convergence (the sum rules), the difference mask of the Hölder formula, and exact helpers
shared by the regularity routines, for any arity ``m`` (the keyword ``arity``, default 2).

A scheme can converge only if ``a(1) = m`` and ``a(eps) = 0`` at the m-th roots of unity
``eps != 1`` (``a(1) = 2``, ``a(-1) = 0`` for ``m = 2``); a failure is a **certified** verdict
(:class:`NotConvergent`), not bad input. With ``N`` factors ``q_m = 1 + ... + z^{m-1}``, ``k = N - 1``
and ``c = m^k a/q_m^(k+1)`` (:func:`difference_mask`), ``alpha = k - log_m rho(c)``.
"""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING

import mpmath

from ..result import CERTIFIED, AnalysisError, Result

if TYPE_CHECKING:  # pragma: no cover
    import sympy as sp

    from ..algebra.symbol import LaurentSymbol

# No sympy at import: the ball route (catalogue entries known by Arb balls) needs only
# NotConvergent and log_bounds from here. The functions on exact symbols import it.

iv = mpmath.iv


class NotConvergent(AnalysisError):
    """The scheme fails a sum rule, so it does not converge — a **certified** verdict, not bad
    input. ``reason`` is the exact failure (``"a(-1) = 1/2 != 0"``, ``"a(1) = 5/2 != 2"``);
    :meth:`result` is the verdict as a certified :class:`Result` (``value`` False).

    A subclass of :class:`AnalysisError`, so callers that only ask for an exponent keep working;
    callers that report regularity (``subdiv holder``, :func:`smoothness`) turn it into a result.
    """

    def __init__(self, reason: str, *, hint: str | None = None, arity: int = 2):
        self.reason, self.hint, self.arity = reason, hint, arity
        m = arity
        rules = "sum rules a(1) = 2, a(-1) = 0" if m == 2 else \
            f"{m}-ary sum rules a(1) = {m}, a(eps) = 0 for eps^{m} = 1, eps != 1"
        super().__init__(f"the scheme does not satisfy the {rules} ({reason}): "
                         "it does not converge" + (f"; {hint}" if hint else ""))

    def result(self) -> Result:
        from ..algebra.factorization import arity_key

        m = self.arity
        method = ("exact sum rules a(1) = 2, a(-1) = 0 (necessary for convergence)" if m == 2 else
                  f"exact {m}-ary sum rules (necessary for convergence)")
        return Result(value=False, status=CERTIFIED,
                      witness={"convergent": False, "reason": f"not convergent: {self.reason}",
                               **({"hint": self.hint} if self.hint else {})},
                      provenance={"method": method, **arity_key(m)})


def convergence_failure(a: LaurentSymbol, *, arity: int = 2) -> str | None:
    """``None`` when the sum rules hold exactly (``a(1) = 2`` and ``a(-1) = 0`` for ``m = 2``; ``a(1) = m``
    and ``a(eps) = 0`` at the m-th roots of unity ``eps != 1``), else the reason, e.g.
    ``"a(-1) = 1/2 != 0"`` or one naming the root of unity (the sum rules are necessary for convergence).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> convergence_failure(LaurentSymbol.from_mask(["1/4", "1/2", "1", "1/4"]))
    'a(-1) = 1/2 != 0'
    >>> convergence_failure(LaurentSymbol.from_mask(["1/2", 1, 1, 1, "1/2"]), arity=4) is None
    True
    >>> convergence_failure(LaurentSymbol.from_mask(["1/2", 1, 1, 1, "1/2"]), arity=3)
    'a(1) = 4 != 3; a(exp(2*pi*i/3)) = 1/4 + sqrt(3)*I/4 != 0; a(exp(4*pi*i/3)) = 1/4 - sqrt(3)*I/4 != 0'
    """
    import sympy as sp

    from ..algebra.factorization import sum_rules

    a.require_numeric("the sum rules")
    if arity != 2:
        r = sum_rules(a, arity=arity)
        return None if r.value else "; ".join(r.witness["failures"])
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
    import sympy as sp

    qs = [c.q for c in a.mask if isinstance(c, sp.Rational)]
    return any(q >= 2 ** 40 and q & (q - 1) == 0 for q in qs)


def difference_mask(a: LaurentSymbol, *, arity: int = 2) -> tuple[int, LaurentSymbol]:
    """``(k, c)`` with ``k = N - 1`` (``N`` factors ``q_m``) and ``c = m^k a / q_m^(k+1)``
    (``2^k a/(1+z)^(k+1)`` for ``m = 2``).

    Raises :class:`NotConvergent` (a certified verdict) when a sum rule fails.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> difference_mask(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), arity=3)
    (1, LaurentSymbol([1], start=-2, domain=QQ))
    """
    from ..algebra.factorization import check_arity, factor_out, smoothing_factor

    m = check_arity(arity)
    a.require_numeric("a Hölder exponent")
    why = convergence_failure(a, arity=m)
    if why is not None:
        raise NotConvergent(why, arity=m)
    N = smoothing_factor(a, arity=m, exceptional=False).value
    return N - 1, factor_out(a, N, arity=m) / m


def log_bounds(lo, hi, base: int = 2, prec: int = 90) -> tuple[Fraction, Fraction]:
    """Rational outward bounds ``(l, h)`` with ``l <= log_base lo`` and ``log_base hi <= h``, as
    Fractions (``lo``, ``hi``: positive rationals — int, Fraction or sympy Rational), from mpmath's
    interval arithmetic at ``prec`` bits; no sympy.

    >>> l, h = log_bounds(Fraction(3, 2), Fraction(3, 2))
    >>> l < h and float(h - l) < 1e-25 and abs(float(l) - 0.5849625007211562) < 1e-15
    True
    """
    old = iv.prec
    iv.prec = prec
    try:
        L1 = iv.log(iv.mpf(int(lo.numerator)) / int(lo.denominator)) / iv.log(iv.mpf(base))
        L2 = iv.log(iv.mpf(int(hi.numerator)) / int(hi.denominator)) / iv.log(iv.mpf(base))
        ends = []
        for x in (L1.a, L2.b):
            p, q = mpmath.libmp.to_rational(x._mpi_[0])     # a degenerate interval: its exact end
            ends.append(Fraction(int(p), int(q)))
        return ends[0], ends[1]
    finally:
        iv.prec = old


def log_interval(lo: sp.Rational, hi: sp.Rational, base: int = 2, prec: int = 90):
    """Rational outward bounds of ``[log_base lo, log_base hi]`` (:func:`log_bounds` as sympy Rationals)."""
    import sympy as sp

    l, h = log_bounds(lo, hi, base, prec)
    return sp.Rational(l.numerator, l.denominator), sp.Rational(h.numerator, h.denominator)


def power_exponent(x, m: int = 2) -> int | None:
    """``e`` if ``x == m^e`` exactly (``e`` an integer), else None.

    >>> import sympy as sp
    >>> power_exponent(sp.Rational(1, 9), 3), power_exponent(2, 3), power_exponent(sp.Rational(1, 4))
    (-2, None, -2)
    """
    import sympy as sp

    x = sp.Rational(x)
    if x <= 0:
        return None
    p, q = int(x.p), int(x.q)
    if q == 1:
        e = 0
        while p % m == 0:
            p, e = p // m, e + 1
        return e if p == 1 else None
    if p == 1:
        e = 0
        while q % m == 0:
            q, e = q // m, e + 1
        return -e if q == 1 else None
    return None
