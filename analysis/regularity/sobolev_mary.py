"""The L2-Sobolev exponent of an m-ary refinable function, certified (issue 12).

``s_2(phi) = sup { s : int |phi^(xi)|^2 (1 + |xi|^2)^s d xi < oo }`` for ``phi = phi_a``,
``phi = sum_k a_k phi(m . - k)``, ``a(1) = m``, ``phi^(xi) = prod_{j>=1} A(xi/m^j)``,
``A(xi) = a(e^{-i xi})/m``.

Normalisation (derivation)
--------------------------
Let ``P(z) = a(z) a(1/z)/m`` (so ``P(e^{-i xi}) = m |A(xi)|^2``) and the m-ary transfer operator
``(T h)_i = sum_j P_{m i - j} h_j`` on Laurent polynomials; in Fourier terms
``(T h)(xi) = sum_{l=0}^{m-1} |A((xi + 2 pi l)/m)|^2 h((xi + 2 pi l)/m)``. Periodising over
``[-m^n pi, m^n pi]`` gives, for every 2pi-periodic ``g >= 0``,

    int_{|xi| <= m^n pi} |prod_{j=1}^n A(xi/m^j)|^2 g(m^-n xi) d xi = 2 pi (T^n g)_0 .

No stability of the shifts is needed. Let ``w_a(xi) = sum_k |phi^(xi + 2 pi k)|^2`` be the autocorrelation
symbol (a Laurent polynomial when ``phi in L2``; ``T w_a = w_a``), ``h = (2 - z - 1/z)^r w_a``,
``s_n = (T^n h)_0`` and ``lambda = limsup s_n^(1/n)``. Periodising the whole line,

    s_n = (1/2 pi) int_R |phi^(xi)|^2 |2 sin(m^-n xi/2)|^(2r) d xi .

* On the band ``m^(n-1) pi <= |xi| <= m^n pi`` the sine factor is ``>= 2 sin(pi/(2m)) > 0``, so the band
  energy is ``O(s_n)``: ``phi in H^s`` whenever ``m^(2s) lambda < 1``.
* ``|2 sin(x/2)|^(2r) <= C |x|^(2s)`` for ``0 <= s <= r``, so ``s_n <= C m^(-2sn) int |phi^|^2 |xi|^(2s)``
  for ``s < min(s_2, r)``: ``lambda <= m^(-2 min(s_2, r))``.

Hence

    s_2 = -(1/2) log_m lambda          when  m^(-2r) < lambda < 1

(``r`` starts at ``N + 1``, ``N`` the number of factors ``q_m = 1 + ... + z^(m-1)``, and grows if needed;
for ``m = 2`` this is today's ``-(1/2) log_2 lambda``). ``lambda = m^-k`` is recognised exactly, giving
``s_2 = k/2``: the m-ary B-spline of degree ``d`` (mask ``q_m^(d+1)/m^d``, the B-spline of order ``d+1`` on
integer knots, ``phi^ = ((1 - e^{-i xi})/(i xi))^(d+1)``) has ``lambda = m^-(2d+1)``, ``s_2 = d + 1/2``.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> r = sobolev_exponent_mary(LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)"), 3)   # ternary cubic B-spline
>>> r.value, r.status, r.witness["minimal_polynomial_root"]
(7/2, 'certified', 1/2187)
>>> sobolev_exponent_mary(LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1), 2).value   # hat function
3/2

Algorithm
---------
1. ``phi in L2``: with ``h = (2 - z - 1/z)^(N+1)`` alone the band energies are still ``O(s_n)`` (the truncated
   product identity ``int_{|xi| <= m^n pi} |prod_{j<=n} A(xi/m^j)|^2 g(m^-n xi) = 2 pi (T^n g)_0`` and
   ``|phi^| <= C`` on ``[-pi, pi]``), so ``lambda < 1`` there certifies ``phi in L2``; else *inconclusive*.
2. ``w_a`` is then the eigenvector of ``T`` for the eigenvalue 1 on Laurent polynomials supported in
   ``[-L, L]`` (``L`` the mask length), normalised by ``w(1) = 1`` — used when that eigenspace is
   one-dimensional (exact nullspace over the mask's field). Otherwise the stability reduction
   ``phi_a = q(tau) phi_b/q(1)`` (:func:`analysis.regularity.stability_mary.stable_shifts_mary`) gives the weight
   ``q(z) q(1/z)`` as in the binary code (``w_a = |q|^2 w_b/q(1)^2`` with ``w_b`` bounded below), or
   *inconclusive*.
3. ``s_n`` satisfies a linear recurrence of order at most ``D = 2 max(M, L) + 1`` (``h`` on ``[-M, M]``, ``P`` on
   ``[-L, L]``; ``T`` maps Laurent polynomials supported in ``[-K, K]``, ``K = max(M, L)``, into themselves since
   ``(K + L)/m <= K``). Berlekamp–Massey on ``2D + 2`` exact terms (QQ or the real algebraic field of the mask)
   gives the minimal polynomial ``mu``; ``lambda = max |roots of mu|`` by Arb root isolation (a minimal
   recurrence has every root of ``mu`` in its closed form); ``lambda = m^-k`` is recognised exactly; ``log_m`` is
   enclosed with outward rounding. Masks with parameters must be substituted first.

For ``m = 2`` this is an independent route to the binary :func:`analysis.regularity.sobolev.sobolev_exponent`
(which always uses the stability reduction); ``tests/test_sobolev_mary.py`` checks they agree on random masks.

References
----------
L. Villemoes, *Wavelet analysis of refinement equations*, SIAM J. Math. Anal. 25 (1994) 1433-1460.
R.-Q. Jia, *Characterization of smoothness of multivariate refinable functions in Sobolev spaces*,
Trans. Amer. Math. Soc. 351 (1999) 4089-4112 (general dilation matrices).
T. Eirola, *Sobolev characterization of solutions of dilation equations*, SIAM J. Math. Anal. 23 (1992).
"""

from __future__ import annotations

import math
import time as _time
from fractions import Fraction
from typing import Any

import sympy as sp

from ..algebra.mary import check_arity, smoothing_factor_mary
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .mary import _logm_interval
from .sobolev import _arb_roots_exact_poly, _coeffs, berlekamp_massey
from .stability_mary import stable_shifts_mary

__all__ = ["transfer_sequence_mary", "sobolev_exponent_mary"]


def transfer_sequence_mary(P: dict, h: dict, K, terms: int, m: int) -> list:
    """``[(T^n h)_0 for n < terms]`` exactly, ``(T h)_i = sum_j P_{m i - j} h_j``; dicts index -> ``K``.

    >>> transfer_sequence_mary({-1: sp.QQ(1, 2), 0: sp.QQ(1), 1: sp.QQ(1, 2)}, {0: sp.QQ(1)}, sp.QQ, 3, 3)
    [1, 1, 1]
    """
    out = []
    cur = dict(h)
    for _ in range(terms):
        out.append(cur.get(0, K.zero))
        new: dict[int, Any] = {}
        for j, hj in cur.items():
            for k, pk in P.items():          # i with m i - j = k
                if (k + j) % m == 0:
                    i = (k + j) // m
                    new[i] = new.get(i, K.zero) + pk * hj
        cur = {i: v for i, v in new.items() if v != K.zero}
    return out


def _max_modulus_mary(mu: sp.Poly, m: int):
    """``(lo, hi, k)``: rational bounds of the largest root modulus of ``mu``; ``k`` when it is exactly ``m^-k``
    (a root ``+-m^-k`` of ``mu`` whose ball is the only one not certified below ``m^-k``), else None."""
    import flint

    from ..jsr._exact import arb_to_fraction_bounds

    roots, how = _arb_roots_exact_poly(mu)
    with flint.ctx.workprec(256):
        bounds = [arb_to_fraction_bounds(abs(r)) for r in roots]
    lo = max(b[0] for b in bounds)
    hi = max(b[1] for b in bounds)
    if lo <= 0:
        return lo, hi, None, how
    k = -round(math.log(float((lo + hi) / 2), m))
    cand = sp.Rational(1, m ** k) if k >= 0 else sp.Integer(m) ** (-k)
    hits = [s for s in (1, -1) if mu.eval(s * cand) == 0]
    if not hits:
        return lo, hi, None, how
    with flint.ctx.workprec(256):
        cb = flint.arb(flint.fmpq(int(cand.p), int(cand.q)))
        for r in roots:
            if any(r.contains(flint.acb(s * cb)) for s in hits):
                continue                     # the exact root +-m^-k itself
            if not (abs(r) < cb):
                return lo, hi, None, how
    c = Fraction(int(cand.p), int(cand.q))
    return c, c, k, how


def _lambda(Pd: dict, h: LaurentSymbol, K, L: int, m: int):
    """``(lo, hi, k_exact, mu, D, terms, how)`` for ``lambda = limsup ((T^n h)_0)^(1/n)``, exactly."""
    hd = _coeffs(h, K)
    D = 2 * max(max(abs(i) for i in hd), L) + 1
    seq = transfer_sequence_mary(Pd, hd, K, 2 * D + 2, m)
    C = berlekamp_massey(seq, K)
    mu = sp.Poly.from_list([K.to_sympy(c) for c in C], sp.Symbol("x"), domain=K)
    if mu.degree() <= 0:
        return Fraction(0), Fraction(0), None, mu, D, len(seq), "the sequence vanishes"
    lo, hi, k_exact, how = _max_modulus_mary(mu, m)
    return lo, hi, k_exact, mu, D, len(seq), how


def autocorrelation_symbol(a: LaurentSymbol, m: int):
    """``(w, dim)``: the eigenvector ``w`` of the m-ary transfer operator ``T`` (``P = a a*/m``) for the eigenvalue 1
    on Laurent polynomials supported in ``[-L, L]`` (``L`` the length of the mask), normalised to ``w(1) = 1``, when
    that eigenspace has dimension ``dim = 1``; else ``(None, dim)``.

    If ``phi_a`` is in ``L2`` and ``a`` satisfies the m-ary sum rules, ``w`` is its autocorrelation symbol
    ``w_a(xi) = sum_k |phi^(xi + 2 pi k)|^2 = sum_k (int phi phi(. - k)) e^{-i k xi}`` (``T w_a = w_a``, support
    inside ``[-L/(m-1), L/(m-1)]``, ``w_a(1) = 1``).

    >>> w, dim = autocorrelation_symbol(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 3)   # hat function
    >>> w.mask, dim
    ((1/6, 2/3, 1/6), 1)
    """
    from sympy.polys.matrices import DomainMatrix

    dom = a.domain if not a.domain.is_ZZ else sp.QQ
    P = a * a.reversed() / m
    L = P.end
    idx = range(-L, L + 1)
    rows = [[dom.from_sympy(P.coeff(m * i - j)) - (dom.one if i == j else dom.zero) for j in idx] for i in idx]
    ns = DomainMatrix(rows, (len(idx), len(idx)), dom).nullspace()
    dim = ns.shape[0]
    if dim != 1:
        return None, dim
    v = ns.to_list()[0]
    total = sum(v, dom.zero)
    if total == dom.zero:
        return None, dim
    return LaurentSymbol.from_mask([dom.to_sympy(dom.quo(x, total)) for x in v], start=-L), dim


def sobolev_exponent_mary(a: LaurentSymbol, m: int, *, max_extra_r: int = 4) -> Result:
    """The L2-Sobolev exponent ``s_2`` of the m-ary refinable function ``phi_a``, certified or inconclusive.

    ``a``: a numeric :class:`~analysis.algebra.symbol.LaurentSymbol` (rational or real algebraic) with
    ``a(1) = m`` (else :class:`AnalysisError`). Returns a :class:`Result`: ``value`` (exact ``k/2`` when
    ``lambda = m^-k``), ``lower``/``upper`` (rational, outward rounded), the witness (``weight`` ``w``,
    ``r``, the minimal polynomial, ``lambda`` bounds) and provenance. See the module docstring.
    """
    m = check_arity(m)
    if not isinstance(a, LaurentSymbol):
        raise AnalysisError(f"the {m}-ary Sobolev exponent needs an exact symbol, not {type(a).__name__}")
    a.require_numeric("a Sobolev exponent")
    dom = a.domain
    if not (dom.is_QQ or dom.is_ZZ or dom.is_AlgebraicField):
        raise AnalysisError(f"the Sobolev exponent needs rational or algebraic coefficients, not {dom}")
    if sp.simplify(a(1) - m) != 0:
        raise AnalysisError(f"the {m}-ary Sobolev exponent needs the normalisation a(1) = {m} "
                            f"(here a(1) = {sp.sstr(a(1))})")
    t0 = _time.perf_counter()
    N = smoothing_factor_mary(a, m).value
    method = (f"exact {m}-ary transfer-operator sequence s_n = (T^n h)_0, (T h)_i = sum_j P_(m i - j) h_j, "
              f"P = a a*/{m}, h = (2-z-1/z)^r w; Berlekamp-Massey; s_2 = -(1/2) log_{m} lambda")
    witness: dict[str, Any] = {"N": N, "arity": m, "method": method}
    prov = {"method": method, "arity": m}

    def inconclusive(reason, **extra):
        witness.update(extra, reason=reason)
        prov["timing"] = {"seconds": round(_time.perf_counter() - t0, 4)}
        return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=prov)

    K = dom if not dom.is_ZZ else sp.QQ
    Pd = _coeffs(a * a.reversed() / m, K)
    L = max(abs(i) for i in Pd)
    diff = LaurentSymbol.from_mask([-1, 2, -1], start=-1)
    # route 1: phi in L2 (h = (2-z-1/z)^r alone bounds the band energies, no stability needed), then the
    # autocorrelation symbol w_a (T w_a = w_a) as the weight
    lo1, hi1, _k1, _mu1, _, _, _ = _lambda(Pd, diff ** (N + 1), K, L, m)
    witness["lambda_L2_upper"] = hi1
    w = None
    if not hi1 < 1:
        why = (f"phi is not certified to be in L2 (lambda for h = (2-z-1/z)^{N + 1} is only bounded by "
               f"{float(hi1):.6g}, not < 1)")
    else:
        w, dim = autocorrelation_symbol(a, m)
        why = f"the eigenvalue 1 of T has multiplicity {dim} (the autocorrelation symbol is not determined)"
    if w is not None:
        witness["weight"] = "autocorrelation symbol w_a (eigenvalue 1 of T simple)"
    else:
        # route 2: the stability reduction phi_a = q(tau) phi_b/q(1), weight q q*
        stab = stable_shifts_mary(a, m)
        witness["stable_shifts"] = stab
        if stab.value is None or stab.witness.get("q") is None:
            return inconclusive(f"{why}, and the stability reduction is incomplete: {stab.witness['reason']}")
        q = stab.witness["q"]
        w = q * q.reversed()
        witness["weight"] = "q q* with phi_a = q(tau) phi_b/q(1), phi_b stable"
    witness["w"] = w
    r = N + 1
    while True:
        lo, hi, k_exact, mu, D, terms, how = _lambda(Pd, diff ** r * w, K, L, m)
        threshold = Fraction(1, m ** (2 * r))
        if lo > threshold or r >= N + 1 + max_extra_r:
            break
        r += 1
    witness.update({"r": r, "recurrence_order": mu.degree(), "krylov_bound": D, "terms": terms,
                    "minimal_polynomial": mu.as_expr(), "lambda_lower": lo, "lambda_upper": hi, "roots": how,
                    "minimal_polynomial_root": sp.Rational(lo.numerator, lo.denominator) if k_exact is not None
                    else None})
    if not lo > threshold:
        return inconclusive(f"lambda is not certified above {m}^(-2r) for r <= {r}: increase r")
    if not hi < 1:
        return inconclusive(f"lambda >= 1 is possible (lambda <= {float(hi):.6g}): phi may not be in L2")
    if k_exact is not None:
        value = lower = upper = sp.Rational(k_exact, 2)
    else:
        value = None
        llo, lhi = _logm_interval(sp.Rational(lo.numerator, lo.denominator),
                                  sp.Rational(hi.numerator, hi.denominator), m)
        lower, upper = -lhi / 2, -llo / 2
    prov.update({"arithmetic": f"exact over {K}, Arb root isolation",
                 "timing": {"seconds": round(_time.perf_counter() - t0, 4)}})
    return Result(value=value, lower=lower, upper=upper, status=CERTIFIED, witness=witness, provenance=prov)
