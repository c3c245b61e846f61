"""Daubechies' orthogonal scaling functions D4, D6, ..., D54 as subdivision schemes.

``D2N`` (PyWavelets ``dbN``) has ``N`` vanishing moments and ``2N`` mask coefficients. In the
catalogue's convention (``(S_a f)_i = sum_j a_{i-2j} f_j``, ``a(1) = 2``) the mask is
``a = sqrt(2) h``, ``h`` the orthonormal scaling filter with ``sum h = sqrt(2)``:

    a(z) = ((1+z)/2)^N q(z),     |q(e^{it})|^2 = 4 P_N(sin^2(t/2)),
    P_N(y) = sum_{k<N} binom(N-1+k, k) y^k.

(The factor 4 is the ``a(1) = 2`` normalisation: ``q(1) = 2`` and ``P_N(0) = 1``.) Orthonormality
of the integer translates of the scaling function reads ``sum_k a_k a_{k+2m} = 2 delta_m``.

The masks are **computed**, never typed in: the roots of the spectral polynomial are isolated
by Arb (python-flint) with certified error balls, the roots outside the unit circle are kept
(Daubechies' extremal-phase choice, ``a_0`` the first coefficient, exactly as in her tables),
and the coefficients come out as real :class:`flint.arb` balls that are guaranteed to contain
the true coefficients. Only D4 has an exact :class:`~analysis.algebra.symbol.LaurentSymbol` here (over
``QQ(sqrt 3)``); the others are catalogued as :class:`~schemes.catalogue.NumericSchemeEntry`.

Examples
--------
>>> from schemes import get
>>> e = get("daubechies-4")
>>> e.symbol
LaurentSymbol([1/4 + sqrt(3)/4, sqrt(3)/4 + 3/4, 3/4 - sqrt(3)/4, 1/4 - sqrt(3)/4], start=0, domain=QQ<sqrt(3)>)
>>> [round(x, 12) for x in get("db3").mask_float()]
[0.470467207784, 1.141116915831, 0.650365000526, -0.190934415568, -0.12083220831, 0.049817499737]
>>> balls = get("d40").enclosure(200)           # 40 Arb balls, each of radius < 2^-200
>>> len(balls), all(b.rad() < flint.arb(2)**-200 for b in balls)
(40, True)
>>> sum(balls).contains(2)
True

Algorithm
---------
1. ``R_N(z) = 4^(N-1) z^(N-1) P_N((2 - z - 1/z)/4)`` is an integer polynomial of degree
   ``2N-2`` (``y = sin^2(t/2) = (2 - z - 1/z)/4`` on ``|z| = 1``); its roots come in pairs
   ``r, 1/r`` and in conjugate pairs, none on the unit circle (``P_N > 0`` on ``[0, 1]``).
2. ``flint.fmpz_poly(R_N).complex_roots()`` isolates them in complex balls; each ball is
   certified to lie outside or inside the unit circle (``|r| > 1`` decided in ball arithmetic;
   if undecided the working precision is doubled).
3. ``q(z) = 2 prod_{|r|>1} (z - r) / (1 - r)`` and ``a(z) = ((1+z)/2)^N q(z)`` in ``acb_poly``
   arithmetic; the true coefficients are real, so the real parts of the complex balls enclose
   them.
4. The working precision is raised until every ball has radius ``< 2^-prec`` (the requested
   absolute accuracy).

Precision and conditioning
--------------------------
The root isolation is well conditioned (simple roots, at distance ``>= |r| - 1`` from the unit
circle); the product of ``N-1`` root factors loses a few bits that the guard bits absorb. D40
at ``prec = 53`` takes a few milliseconds. Float values are the rounded midpoints of balls of
radius ``< 2^-60``, so they are correctly rounded up to one ulp.

References
----------
I. Daubechies, *Orthonormal bases of compactly supported wavelets*, Comm. Pure Appl. Math. 41
(1988) 909-996 (Table 1: the coefficients for N = 2..10).
I. Daubechies, *Ten Lectures on Wavelets*, SIAM 1992, Section 6.1 (the polynomial P_N, the
spectral factorisation) and Table 6.1.
F. Johansson, *Arb: efficient arbitrary-precision midpoint-radius interval arithmetic*, IEEE
Trans. Computers 66 (2017) 1281-1292.
"""

from __future__ import annotations

import functools
from math import comb

import flint

from analysis.result import AnalysisError

from .catalogue import LazyEntries, NumericSchemeEntry

#: The catalogued numbers of vanishing moments: D4 (N = 2) ... D54 (N = 27). (D56 and beyond:
#: the Arb eigenvalue isolation of the s.m.p. needs wider precision than the JSR code uses.)
DAUBECHIES_ORDERS = range(2, 28)

_GUARD_BITS = 32


def daubechies_polynomial(N: int) -> list[int]:
    """Integer coefficients (constant term first) of ``R_N(z) = 4^(N-1) z^(N-1) P_N((2-z-1/z)/4)``.

    With ``y = (2 - z - 1/z)/4 = -(z-1)^2/(4z)``,
    ``R_N(z) = sum_{k<N} binom(N-1+k, k) (-1)^k 4^(N-1-k) (z-1)^(2k) z^(N-1-k)``.

    >>> daubechies_polynomial(2)            # -2 (z^2 - 4 z + 1): roots 2 +- sqrt(3)
    [-2, 8, -2]
    >>> daubechies_polynomial(3)
    [6, -36, 76, -36, 6]
    """
    if N < 1:
        raise AnalysisError("a Daubechies scaling function has N >= 1 vanishing moments")
    z = flint.fmpz_poly([0, 1])
    zm1 = flint.fmpz_poly([-1, 1])
    total = flint.fmpz_poly([0])
    for k in range(N):
        total += comb(N - 1 + k, k) * (-1)**k * 4**(N - 1 - k) * zm1**(2 * k) * z**(N - 1 - k)
    return [int(c) for c in total.coeffs()]


def _enclosure_at(N: int, wp: int) -> list[flint.arb] | None:
    """The ball mask computed at working precision ``wp``, or None if a root is undecided."""
    with flint.ctx.workprec(wp):
        R = flint.fmpz_poly(daubechies_polynomial(N))
        outside = []
        for r, mult in R.complex_roots():
            if mult != 1:  # pragma: no cover - P_N has simple roots
                raise AnalysisError(f"D{2 * N}: multiple root of the spectral polynomial")
            if abs(r) > 1:
                outside.append(r)
            elif not abs(r) < 1:
                return None
        if 2 * len(outside) != R.degree():
            return None
        q = flint.acb_poly([1])
        for r in outside:
            q *= flint.acb_poly([-r, 1]) * (1 / (1 - r))
        q *= 2
        a = q * flint.acb_poly([flint.acb(1) / 2, flint.acb(1) / 2]) ** N
        coeffs = a.coeffs()
        if len(coeffs) != 2 * N or not all(c.imag.contains(0) for c in coeffs):
            return None  # pragma: no cover - would contradict real coefficients
        return [c.real for c in coeffs]


@functools.lru_cache(maxsize=None)
def _enclosure_cached(N: int, prec: int) -> tuple:
    bound = flint.arb(2) ** (-prec)
    wp = prec + _GUARD_BITS + 4 * N
    for _ in range(8):
        balls = _enclosure_at(N, wp)
        if balls is not None and all(b.rad() < bound for b in balls):
            return tuple(balls)
        wp *= 2
    raise AnalysisError(f"D{2 * N}: could not reach {prec} bits (last working precision {wp}); "
                        "the root isolation did not converge")  # pragma: no cover


def daubechies_enclosure(N: int, prec: int = 53) -> list[flint.arb]:
    """Certified Arb balls ``[a_0, ..., a_{2N-1}]`` of the D2N mask (``a(1) = 2``), each of
    radius ``< 2^-prec``.

    The balls are exact-midpoint Arb numbers valid at any context precision; arithmetic on them
    follows ``flint.ctx.prec`` (raise it to keep the accuracy).

    >>> b = daubechies_enclosure(2, prec=100)
    >>> with flint.ctx.workprec(200):                     # a_0 = (1+sqrt 3)/4
    ...     b[0].contains((1 + flint.arb(3).sqrt()) / 4)
    True
    >>> daubechies_enclosure(1)                            # N = 1: the Haar mask 1 + z
    [1.00000000000000, 1.00000000000000]

    Algorithm: see the module docstring (certified root isolation, extremal phase).
    """
    if not isinstance(N, int) or N < 1:
        raise AnalysisError(f"N = {N!r}: a Daubechies scaling function has N >= 1 "
                            "vanishing moments")
    if N == 1:
        return [flint.arb(1), flint.arb(1)]
    if not isinstance(prec, int) or prec < 2:
        raise AnalysisError(f"precision {prec!r} must be an integer number of bits >= 2")
    return list(_enclosure_cached(N, prec))


def daubechies_mask_mpmath(N: int, dps: int = 50) -> list:
    """The D2N mask as mpmath ``mpf`` numbers, accurate to about ``dps`` digits.

    Midpoints of :func:`daubechies_enclosure` balls of radius ``< 10^-(dps+5)``, converted
    exactly (the midpoint of an Arb ball is a binary floating point number).

    >>> import mpmath
    >>> with mpmath.workdps(30):
    ...     print(daubechies_mask_mpmath(2, 30)[3])
    -0.183012701892219323381861585376
    """
    import mpmath

    prec = int(dps * 3.33) + 20
    out = []
    with mpmath.workprec(prec + 64):
        for b in daubechies_enclosure(N, prec):
            man, exp = b.mid().man_exp()
            out.append(mpmath.ldexp(mpmath.mpf(int(man)), int(exp)))
    return out


def daubechies_mask_float(N: int) -> list[float]:
    """The D2N mask in float64 (each value within one ulp of the true coefficient).

    >>> [round(x, 15) for x in daubechies_mask_float(2)]
    [0.683012701892219, 1.183012701892219, 0.316987298107781, -0.183012701892219]
    """
    return [float(b.mid()) for b in daubechies_enclosure(N, 60)]


def daubechies_exact_symbol(N: int):
    """The exact D2N symbol, for N = 1 (Haar, over QQ) and N = 2 (D4, over QQ(sqrt 3)).

    Computed with the same extremal-phase root choice as the enclosures (the roots of
    ``R_N`` are real and exact radicals for N <= 2). For N >= 3 the coefficients lie in a
    degree >= 4 number field with nested radicals; use :func:`daubechies_enclosure`.

    >>> daubechies_exact_symbol(2).mask
    (1/4 + sqrt(3)/4, sqrt(3)/4 + 3/4, 3/4 - sqrt(3)/4, 1/4 - sqrt(3)/4)
    """
    import sympy as sp

    from analysis.algebra.symbol import LaurentSymbol, Z

    if N == 1:
        return LaurentSymbol.from_mask([1, 1], start=0)
    if N != 2:
        raise AnalysisError(f"no exact symbol is catalogued for D{2 * N}; "
                            "use the certified enclosure (entry.enclosure(prec))")
    R = sp.Poly(list(reversed(daubechies_polynomial(N))), Z)
    roots = [r for r in sp.roots(R, Z) if abs(sp.N(r, 30)) > 1]  # decided exactly below
    assert len(roots) == 1 and sp.simplify(roots[0] - (2 + sp.sqrt(3))) == 0
    r = roots[0]
    q = 2 * (Z - r) / (1 - r)
    a = sp.expand(q * (1 + Z)**N / 2**N)
    coeffs = [sp.radsimp(a.coeff(Z, k)) for k in range(2 * N)]
    return LaurentSymbol.from_mask(coeffs, start=0)


def _entry(N: int) -> NumericSchemeEntry:
    exact = daubechies_exact_symbol(N) if N == 2 else None
    return NumericSchemeEntry(
        slug=f"daubechies-{2 * N}",
        title=f"Daubechies orthogonal scaling function D{2 * N} ({N} vanishing moments)",
        source=("I. Daubechies, Orthonormal bases of compactly supported wavelets, Comm. Pure "
                "Appl. Math. 41 (1988) 909-996; Ten Lectures on Wavelets (SIAM 1992) Sec. 6.1"),
        notes=(f"a = sqrt(2) h (a(1) = 2), {2 * N} coefficients a_0..a_{2 * N - 1}, start 0; "
               "computed by certified spectral factorisation of P_N (roots of q outside the unit "
               "circle: Daubechies' extremal-phase choice, the order of her Table 6.1 and of "
               "PyWavelets' rec_lo). Not symmetric."
               + (" Exact symbol over QQ(sqrt 3)." if exact is not None else
                  " No exact symbol: use enclosure(prec), mask_float(), mask_mpmath(dps).")),
        aliases=(f"d{2 * N}", f"db{N}"),
        start=0,
        length=2 * N,
        enclosure=functools.partial(daubechies_enclosure, N),
        exact_symbol=exact,
        sum_rules=N,
    )


#: Entries with an exact, symmetric symbol (none here: see NUMERIC_ENTRIES).
ENTRIES: tuple = ()

#: The Daubechies entries D4 ... D54 (registered by schemes.catalogue, listed with numeric=True),
#: each built on first use (D4's exact symbol takes sympy's radical simplification).
NUMERIC_ENTRIES: LazyEntries = LazyEntries({f"daubechies-{2 * N}": functools.partial(_entry, N)
                                            for N in DAUBECHIES_ORDERS})
