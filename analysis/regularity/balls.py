"""Masks known by certified enclosures (Arb balls): division by ``(1+z)^N`` and transition
matrices in ball arithmetic, and the ball route of the Hölder exponent.

Used for the catalogue's Daubechies masks (certified spectral factorisation), masks typed in
closed form (:class:`~analysis.algebra.closed_form.ClosedFormMask`), decimal tables under the
approximate reading (:class:`~analysis.algebra.approx.ApproximateMask`) and, on request, exact
symbols enclosed in balls. A result is valid for **every** mask in the balls with the factor
``(1+z)^N``; the user-facing entry point is :func:`analysis.regularity.holder_exponent`.
"""

from __future__ import annotations

import sys
from fractions import Fraction
from typing import Any, Sequence

from ..result import CERTIFIED, AnalysisError, Result
from .convergence import log_bounds

# No sympy at import, nor on the route of a catalogue entry or a list of balls: their exact
# numbers (the bounds, the radius of c) are ints and Fractions, printed and written to JSON as
# sympy's Rationals are. An exact symbol (sympy) is read only when one is given.


def _exact(x: Fraction):
    """``x`` as an int when it is one, else the Fraction (as a sympy Integer/Rational reads in JSON)."""
    return x.numerator if x.denominator == 1 else x


def _is_symbol(x: Any) -> bool:
    """Is ``x`` a LaurentSymbol? (Its module is imported once one exists.)"""
    mod = sys.modules.get("analysis.algebra.symbol")
    return mod is not None and isinstance(x, mod.LaurentSymbol)


def ball_divide_by_one_plus_z(coeffs: Sequence[Any], times: int = 1) -> list:
    """Exact division of a ball polynomial by ``(1+z)^times`` (constant term first).

    The balls are assumed to contain a polynomial divisible by ``(1+z)^times`` (known by
    construction, e.g. the sum rules of a Daubechies mask). Each quotient coefficient is
    computed twice, by the forward recurrence ``q_i = a_i - q_{i-1}`` and by the backward one
    ``q_{i-1} = a_i - q_i``; both enclose the true quotient, so their intersection does too (and
    is much narrower in the middle). The two remainders must contain 0, otherwise no polynomial
    in the balls is divisible and :class:`AnalysisError` is raised.

    >>> import flint
    >>> ball_divide_by_one_plus_z([flint.arb(1), flint.arb(2), flint.arb(1)], 2)   # (1+z)^2
    [1.00000000000000]
    """
    import flint

    q = [flint.arb(x) if not isinstance(x, flint.arb) else x for x in coeffs]
    for _ in range(times):
        m = len(q)
        if m < 2:
            raise AnalysisError("cannot divide a constant by (1+z)")
        fwd, prev = [], flint.arb(0)
        for x in q[:-1]:
            prev = x - prev
            fwd.append(prev)
        bwd = [flint.arb(0)] * (m - 1)
        nxt = q[-1]
        bwd[m - 2] = nxt
        for i in range(m - 2, 0, -1):
            nxt = q[i] - nxt
            bwd[i - 1] = nxt
        if not (q[-1] - fwd[-1]).contains(0) or not (q[0] - bwd[0]).contains(0):
            raise AnalysisError("the balls contain no polynomial divisible by (1+z): "
                                "the sum rule order is wrong")
        q = [f.intersection(b) for f, b in zip(fwd, bwd)]
    return q


def ball_transition_matrices(c: Sequence[Any]) -> tuple[list[list[Any]], list[list[Any]]]:
    """``(T_0, T_1)`` with ``(T_eps)_{ij} = c_{2i-j+eps}`` (as
    :func:`analysis.stationary.transition.transition_matrices`, size ``max(len(c) - 1, 1)``) for a mask
    given by its coefficients ``c_0, ..., c_N`` (any numbers, e.g. Arb balls), as nested lists."""
    n_coeff = len(c)
    size = max(n_coeff - 1, 1)

    def entry(k: int):
        return c[k] if 0 <= k < n_coeff else 0

    return tuple([[entry(2 * i - j + eps) for j in range(size)] for i in range(size)]
                 for eps in (0, 1))


def ball_route(scheme: Any, *, sum_rules: int | None = None, prec: int | None = None,
               budget: int = 60_000, max_length: int = 16,
               rel_gap: float = 1e-8, max_vertices: int = 4000) -> Result:
    """Certified Hölder exponent of a scheme whose mask is known by **certified enclosures** (the ball route).

    ``scheme`` is a catalogue entry with ``enclosure(prec)`` and ``sum_rules`` (a
    :class:`~schemes.catalogue.NumericSchemeEntry`, e.g. ``schemes.get("daubechies-12")``), a
    list of ``flint.arb`` balls ``[a_0, ..., a_m]`` (then ``sum_rules`` is required: the number
    ``N`` of factors ``(1+z)`` of the true mask, known by construction), or an exact
    :class:`~analysis.algebra.symbol.LaurentSymbol` (its coefficients are enclosed in balls; this is the
    interval back end for a mask that :func:`~analysis.regularity.holder.holder_exponent` handles
    exactly). Reached through :func:`~analysis.regularity.holder.holder_exponent`, the one public
    entry point, for every mask that is not an exact symbol (or with ``arithmetic="ball"``).

    The result is valid for **every** mask in the balls that has the factor ``(1+z)^N``; since
    the true mask is in the balls by construction, it is a certified enclosure of its exponent.

    Parameters
    ----------
    sum_rules
        ``N``; defaults to ``scheme.sum_rules`` (for a symbol: its smoothing factor).
    prec
        Radius bound ``2^-prec`` of the mask balls (default ``128 + 4 N``; the division by
        ``(1+z)^N`` widens the balls by at most ``binom(2N, N)``).
    budget, max_length, rel_gap, max_vertices
        Passed to :func:`analysis.jsr.jsr_bounds` (``budget`` in its work units, counted, never
        timed; ``rel_gap`` is on the JSR; the gap in alpha is about ``rel_gap / ln 2``).

    Returns
    -------
    Result
        ``lower``/``upper``: rational enclosure of alpha (outward rounded); status of the JSR
        bounds (*certified* when tight to ``rel_gap``); ``witness``: ``N``, ``k``, the JSR
        :class:`Result` (``jsr``), the s.m.p. ``product``, ``alpha_exact`` (the closed form
        ``k - log2(rho(T_w))/L`` when the invariant polytope is certified), ``c_radius``.

    Examples
    --------
    >>> import schemes
    >>> r = ball_route(schemes.get("daubechies-4"), budget=10_000)
    >>> r.status, round(float(r.lower), 12), float(r.upper - r.lower) < 1e-20
    ('certified', 0.550015686524, True)
    >>> import math; round(2 - math.log2(1 + math.sqrt(3)), 12)        # Daubechies-Lagarias
    0.550015686524
    >>> r = ball_route(schemes.get("daubechies-6"), budget=10_000)
    >>> r.status, round(float(r.lower), 6), r.witness["product"]
    ('certified', 1.087834, (0,))

    Algorithm
    ---------
    1. Mask balls ``a`` at ``prec`` bits (certified spectral factorisation for Daubechies).
    2. ``c = 2^k a / (1+z)^N``, ``k = N - 1``, by exact division in ball arithmetic
       (:func:`ball_divide_by_one_plus_z`: forward and backward recurrences, intersected).
    3. Transition matrices ``T_0, T_1`` of ``c`` with ball entries, and
       :func:`analysis.jsr.jsr_bounds` on them: the lower bound is the lower end of the ball
       enclosure of ``rho(T_w)^(1/L)`` for the s.m.p. ``w``, the upper bound an invariant polytope
       (or norm) certificate re-checked in ball arithmetic over all matrices in the balls.
    4. ``alpha = k - log2 JSR`` with outward rounding.

    References
    ----------
    I. Daubechies, J. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23
    (1992) 1031-1079. O. Rioul, *Simple regularity criteria for subdivision schemes*, SIAM J.
    Math. Anal. 23 (1992) 1544-1576. N. Guglielmi, V. Protasov, *Invariant polytopes of sets of
    matrices with application to regularity of wavelets and subdivisions*, SIAM J. Matrix Anal.
    Appl. 37 (2016) 18-52. T. Mejstrik, *Algorithm 1011*, ACM TOMS 46 (2020) 29.
    """
    import time as _time

    import flint

    from ..jsr import jsr_bounds
    from ..jsr._exact import arb_to_fraction_bounds, sympy_to_arb

    t0 = _time.perf_counter()
    source = "balls"
    if _is_symbol(scheme):
        from ..algebra.factorization import smoothing_factor
        from ..algebra.reader import as_expr

        scheme.require_numeric("a Hölder exponent")
        N = sum_rules if sum_rules is not None else smoothing_factor(scheme, exceptional=False).value
        prec = prec if prec is not None else 128 + 4 * N
        with flint.ctx.workprec(prec + 64):
            balls = [sympy_to_arb(as_expr(x)) for x in scheme.mask]
        source = "exact symbol enclosed in balls"
    elif hasattr(scheme, "enclosure") and callable(scheme.enclosure):
        N = sum_rules if sum_rules is not None else getattr(scheme, "sum_rules", None)
        if N is None:
            raise AnalysisError(f"{getattr(scheme, 'slug', scheme)!r}: the sum rule order is not "
                                "known; pass sum_rules=N")
        prec = prec if prec is not None else 128 + 4 * N
        balls = list(scheme.enclosure(prec))
        source = f"catalogue entry {getattr(scheme, 'slug', '?')!r}, enclosure({prec})"
    else:
        balls = list(scheme)
        if sum_rules is None:
            raise AnalysisError("a ball mask needs sum_rules=N (the number of factors (1+z) of the "
                                "true mask, known by construction)")
        N = sum_rules
        if not all(isinstance(b, flint.arb) for b in balls):
            raise AnalysisError("expected a list of flint.arb balls")
        prec = prec if prec is not None else 128 + 4 * N
    if not (isinstance(N, int) and N >= 1):
        raise AnalysisError(f"sum_rules = {N!r}: the Hölder formula needs N >= 1 factors (1+z)")
    k = N - 1
    with flint.ctx.workprec(max(prec + 64, 192)):
        s = sum(balls, flint.arb(0))
        if not s.contains(2):
            raise AnalysisError("the balls contain no mask with a(1) = 2")
        c = [x * 2 ** k for x in ball_divide_by_one_plus_z(balls, N)]
        # trailing/leading coefficients that are exactly zero would change the matrix size
        while len(c) > 1 and c[-1].is_zero():
            c.pop()
        while len(c) > 1 and c[0].is_zero():
            c.pop(0)
        T0, T1 = ball_transition_matrices(c)
    c_rad = max(arb_to_fraction_bounds(flint.arb(x.rad()))[1] for x in c)
    r = jsr_bounds([T0, T1], budget=budget, max_length=max_length,
                   rel_gap=rel_gap, max_vertices=max_vertices)
    lo, hi = r.lower, r.upper
    if lo is None or lo <= 0:
        raise AnalysisError("the joint spectral radius lower bound is 0; the Hölder formula does not apply")
    if hi is not None:
        l2lo, l2hi = log_bounds(Fraction(lo), Fraction(hi))
        a_lo, a_hi = _exact(k - l2hi), _exact(k - l2lo)
    else:
        a_lo, a_hi = None, _exact(k - log_bounds(Fraction(lo), Fraction(lo))[0])
    word = r.witness.get("product") or ()
    witness = {"N": N, "k": k, "jsr": r, "product": word, "rho_product": r.witness.get("rho_product"),
               "c_radius": _exact(c_rad),
               "matrix_size": len(T0)}
    if r.status == CERTIFIED and r.witness.get("closed") and word:
        witness["alpha_exact"] = f"{k} - log2(rho(T_{''.join(map(str, word))}))/{len(word)}"
    gap = None if a_lo is None else float(a_hi - a_lo)
    return Result(value=None, lower=a_lo, upper=a_hi, status=r.status, witness=witness,
                  provenance={"method": "alpha = k - log2 JSR(T0, T1) of c = 2^k a/(1+z)^(k+1), "
                                        "ball arithmetic over certified mask enclosures",
                              "source": source, "prec": prec, "alpha_gap": gap,
                              "jsr_method": r.provenance.get("method"),
                              "valid_for": "every mask in the balls with the factor (1+z)^N",
                              "work": r.provenance.get("work"),
                              "timing": {"seconds": round(_time.perf_counter() - t0, 4)}})

