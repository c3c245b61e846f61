"""The L2-Sobolev exponent of the basic limit function, with or without stable shifts (issue 9.4).

``s_2(phi) = sup { s : int |phi^(xi)|^2 (1 + |xi|^2)^s d xi < oo }`` for the refinable
distribution ``phi = phi_a`` of a binary mask with ``a(1) = 2`` (``phi^(xi) = prod_j A(xi/2^j)``,
``A(xi) = a(e^{-i xi})/2``). Convergence of the scheme (``a(-1) = 0``) is not needed.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> r = sobolev_exponent(LaurentSymbol.from_mask([1, 0, 0, 1]))       # the box on [0, 3]
>>> r.value, r.status, r.witness["stable_shifts"].value
(1/2, 'certified', False)
>>> sobolev_exponent(LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)).value   # hat function
3/2
>>> r = sobolev_exponent(LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)"), arity=3)   # ternary cubic B-spline
>>> r.value, r.status, r.witness["minimal_polynomial_root"]
(7/2, 'certified', 1/2187)

Algorithm
---------
*Exact masks (rational, or over a real algebraic field such as QQ(sqrt 3)).* With
``P(z) = a(z) a(1/z)/2`` and the transfer operator ``(T h)_i = sum_j P_{2i-j} h_j`` on Laurent
polynomials, periodising ``|phi^|^2`` gives, for every 2pi-periodic trigonometric polynomial
``g >= 0``,

    int_R |phi^(xi)|^2 g(2^-n xi) d xi = 2 pi (T^n (g w_a))_0,
    int_{|xi| <= 2^n pi} |prod_{j=1}^n A(xi/2^j)|^2 g(2^-n xi) d xi = 2 pi (T^n g)_0,

``w_a(xi) = sum_k |phi^(xi + 2 pi k)|^2`` the autocorrelation symbol. By
:func:`analysis.regularity.stability.stable_shifts`, ``phi_a = q(tau) phi_b / q(1)`` with ``phi_b`` stable,
so ``w_a = |q|^2 w_b / q(1)^2`` with ``0 < c <= w_b <= C``. Take ``h = (2 - z - 1/z)^r q(z) q(1/z)``
(``= |2 sin(xi/2)|^{2r} |q|^2 >= 0``) and ``s_n = (T^n h)_0``. Then

* ``E_n := int_{2^{n-1} pi <= |xi| <= 2^n pi} |phi^|^2 <= C' s_n`` (``|phi_b^|`` is bounded on
  ``[-pi, pi]``): ``phi in H^s`` for every ``s < -(1/2) log2 lambda``;
* ``s_n <= C'' int |phi^|^2 |2 sin(2^{-n-1} xi)|^{2r}`` (``w_b >= c``), which is
  ``O(4^{-s n})`` for ``0 < s < min(s_2, r)``: ``s_2 <= -(1/2) log2 lambda`` when
  ``lambda > 4^-r`` and ``s_2 > 0``;

with ``lambda = limsup s_n^{1/n}``. Hence ``s_2 = -(1/2) log2 lambda`` when ``4^-r < lambda < 1``
(``r`` starts at ``N + 1``, ``N`` the number of factors ``(1+z)``, and grows if needed); when
``lambda >= 1`` only ``s_2 in [-(1/2) log2 lambda, 0]`` is proven (inconclusive). The sequence
``s_n`` is computed **exactly**: it satisfies a linear recurrence whose order is at most the
dimension ``D = 2 max(M, L) + 1`` of the space of Laurent polynomials supported in
``[-max(M, L), max(M, L)]`` (``h`` on ``[-M, M]``, ``P`` on ``[-L, L]``; ``T`` maps it into
itself), so Berlekamp–Massey on ``2D`` terms gives its minimal polynomial ``mu`` exactly, and
``lambda = max |roots of mu|`` (a minimal recurrence sequence has every root of ``mu`` in its
closed form, so ``limsup |s_n|^{1/n}`` is the largest modulus). The roots are isolated in Arb
(``fmpq_poly.complex_roots``, or ``acb_poly.roots`` of the squarefree part over the algebraic
field); ``lambda = 2^-k`` is recognised exactly (``mu(+-2^-k) = 0`` and every other root ball
below it), giving ``s_2 = k/2`` exactly. The logarithm is enclosed with outward rounding.

*Arity m > 2* (``sobolev_exponent(a, arity=m)``; :func:`_autocorrelation_route`). With ``P = a a*/m`` and
``(T h)_i = sum_j P_{m i - j} h_j`` the same periodisation holds with ``m^-n``. No stability is needed:
with ``h = (2 - z - 1/z)^(N+1)`` alone ``lambda < 1`` certifies ``phi in L2``; the weight is then the
autocorrelation symbol ``w_a`` (:func:`autocorrelation_symbol`, the eigenvector of ``T`` for the eigenvalue 1
when that eigenspace is one-dimensional), else ``q q*`` from the stability reduction
(:func:`analysis.regularity.stability.stable_shifts`). With ``h = (2 - z - 1/z)^r w`` and ``lambda`` as above,
``s_2 = -(1/2) log_m lambda`` when ``m^(-2r) < lambda < 1``; ``lambda = m^-k`` gives ``s_2 = k/2`` (the m-ary
B-spline of degree ``d`` has ``s_2 = d + 1/2``). At ``m = 2`` this route is independent of the binary one
(which always uses the stability reduction, and whose witness the binary reports record); the tests check
that they agree on random masks.

*Ball masks (Daubechies D6 ... known by Arb enclosures).* The exact sequence is not available.
Stability is certified by root isolation (:func:`analysis.regularity.stability.stable_shifts`) and then the
stable-case formula ``s_2 = N - (1/2) log2 rho(T_Q)`` is used (Villemoes, Eirola):
``Q = c(z) c(1/z)/2``, ``c = 2^N a/(1+z)^N``, ``T_Q = (Q_{2i-j})`` on the indices of ``Q``'s
support, ``rho`` enclosed by certified Arb eigenvalue balls (``acb_mat.eig(multiple=True)``).
Without certified stability the result is inconclusive. The property test
``tests/test_sobolev.py::test_stable_formula_agrees_with_sequence_method`` checks on random
stable rational masks that the two methods agree.

References
----------
L. Villemoes, *Wavelet analysis of refinement equations*, SIAM J. Math. Anal. 25 (1994) 1433-1460.
T. Eirola, *Sobolev characterization of solutions of dilation equations*, SIAM J. Math. Anal.
23 (1992) 1015-1030.
R.-Q. Jia, *Characterization of smoothness of multivariate refinable functions in Sobolev
spaces*, Trans. Amer. Math. Soc. 351 (1999) 4089-4112.
A. Ron, Z. Shen, *The Sobolev regularity of refinable functions*, J. Approx. Theory 106 (2000)
185-225 (without stability the stable-shifts formula can be far off).
"""

from __future__ import annotations

import math
import time as _time
from fractions import Fraction
from typing import Any

import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .stability import ball_mask, stable_shifts
from ..algebra.symbol import LaurentSymbol, Z
from ..algebra.reader import as_expr


# --------------------------------------------------------------------------------------------
# exact linear-recurrence machinery
# --------------------------------------------------------------------------------------------

def _coeffs(s: LaurentSymbol, K) -> dict[int, Any]:
    return {i: K.from_sympy(c) for i, c in s.items() if c != 0}


def transfer_sequence(P: dict, h: dict, K, terms: int, m: int = 2) -> list:
    """``[(T^n h)_0 for n < terms]`` exactly over the domain ``K``, ``(T h)_i = sum_j P_{m i - j} h_j``;
    ``P``, ``h`` dicts index -> K.

    >>> transfer_sequence({-1: sp.QQ(1, 2), 0: sp.QQ(1), 1: sp.QQ(1, 2)}, {0: sp.QQ(1)}, sp.QQ, 3, 3)
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


def berlekamp_massey(s: list, K) -> list:
    """The minimal connection polynomial ``[1, c_1, ..., c_L]`` of ``s`` over the field ``K``:
    ``s_n + c_1 s_{n-1} + ... + c_L s_{n-L} = 0`` for ``L <= n < len(s)``.

    >>> berlekamp_massey([sp.QQ(1), sp.QQ(2), sp.QQ(4), sp.QQ(8)], sp.QQ)
    [1, -2]
    """
    C, B = [K.one], [K.one]
    L, m, b = 0, 1, K.one
    for n in range(len(s)):
        d = s[n]
        for i in range(1, L + 1):
            d = d + C[i] * s[n - i]
        if d == K.zero:
            m += 1
            continue
        coef = d / b if not hasattr(K, "quo") else K.quo(d, b)
        T = list(C)
        need = len(B) + m
        if len(C) < need:
            C = C + [K.zero] * (need - len(C))
        for i, x in enumerate(B):
            C[i + m] = C[i + m] - coef * x
        if 2 * L <= n:
            L, B, b, m = n + 1 - L, T, d, 1
        else:
            m += 1
    C = C[:L + 1] + [K.zero] * max(0, L + 1 - len(C))
    return C


def _arb_roots_exact_poly(mu: sp.Poly):
    """Certified root balls (one per distinct root) of the exact polynomial ``mu``."""
    import flint

    from ..jsr._exact import sympy_to_arb

    dom = mu.domain
    if dom.is_QQ or dom.is_ZZ:
        coeffs = [sp.Rational(dom.to_sympy(c)) for c in reversed(mu.rep.to_list())]
        den = sp.ilcm(*[c.q for c in coeffs]) if coeffs else 1
        fp = flint.fmpq_poly([int(c * den) for c in coeffs])
        return [r for r, _m in fp.complex_roots()], "fmpq_poly.complex_roots"
    sq = sp.Poly(sp.quo(mu, sp.gcd(mu, mu.diff(mu.gen))), mu.gen, domain=dom)
    for prec in (128, 256, 512, 1024, 2048):
        try:
            with flint.ctx.workprec(prec):
                coeffs = [flint.acb(sympy_to_arb(as_expr(dom.to_sympy(c)))) for c in reversed(sq.rep.to_list())]
                roots = flint.acb_poly(coeffs).roots(tol=flint.arb(2) ** (40 - prec))
                return roots, f"acb_poly.roots of the squarefree part at {prec} bits"
        except ValueError:
            continue
    raise ArithmeticError("could not isolate the roots of the minimal polynomial")


def _fr(x) -> Fraction:
    return x if isinstance(x, Fraction) else Fraction(int(x.p), int(x.q))


def _max_modulus(mu: sp.Poly, m: int = 2):
    """``(lo, hi, exact, how)``: rational bounds of the largest root modulus of ``mu``; ``exact`` is
    the exponent ``k`` when the largest modulus is exactly ``m^-k`` (else None)."""
    import flint

    from ..jsr._exact import arb_to_fraction_bounds

    roots, how = _arb_roots_exact_poly(mu)
    with flint.ctx.workprec(256):
        bounds = [arb_to_fraction_bounds(abs(r)) for r in roots]
    lo = max(b[0] for b in bounds)
    hi = max(b[1] for b in bounds)
    exact = None
    if lo > 0:
        import math

        mid = (lo + hi) / 2
        k = -round(math.log2(float(mid)) if m == 2 else math.log(float(mid), m))
        cand = sp.Rational(1, m ** k) if k >= 0 else sp.Integer(m) ** (-k)
        with flint.ctx.workprec(256):
            cb = flint.arb(flint.fmpq(int(cand.p), int(cand.q)))
            ok = True
            accounted = 0
            for sign in (1, -1):
                if mu.eval(sign * cand) == 0:
                    hits = [r for r in roots if r.contains(flint.acb(sign * cb))]
                    accounted += len(hits)
            if accounted == 0:
                ok = False
            for r in roots:
                if r.contains(flint.acb(cb)) or r.contains(flint.acb(-cb)):
                    if (mu.eval(cand) == 0 and r.contains(flint.acb(cb))) or (mu.eval(-cand) == 0 and r.contains(flint.acb(-cb))):
                        continue
                if not (abs(r) < cb):
                    ok = False
            if ok:
                exact = k
                lo = hi = Fraction(int(cand.p), int(cand.q))
    return lo, hi, exact, how


def _log2_bounds(lo: Fraction, hi: Fraction):
    from .convergence import log_interval

    return log_interval(sp.Rational(lo.numerator, lo.denominator), sp.Rational(hi.numerator, hi.denominator))


# --------------------------------------------------------------------------------------------
# the exact route
# --------------------------------------------------------------------------------------------

def _exact_route(a: LaurentSymbol, *, max_extra_r: int = 4) -> Result:
    from ..algebra.factorization import smoothing_factor

    t0 = _time.perf_counter()
    stab = stable_shifts(a)
    N = smoothing_factor(a, exceptional=False).value
    witness = {"stable_shifts": stab, "reduced_mask": stab.witness.get("reduced_mask"),
               "q": stab.witness.get("q"), "N": N}
    method = "exact transfer-operator sequence s_n = (T^n h)_0, h = (2-z-1/z)^r q(z)q(1/z); Berlekamp-Massey"
    if stab.value is None:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={**witness, "reason": "stability of the shifts undecided: " + stab.witness["reason"],
                               "method": method},
                      provenance={"method": method})
    q = stab.witness["q"]
    K = a.poly.domain if not a.poly.domain.is_ZZ else sp.QQ
    P = a * a.reversed() / 2
    Pd = _coeffs(P, K)
    qq = q * q.reversed()
    L = max(abs(i) for i in Pd)
    diff = LaurentSymbol.from_mask([-1, 2, -1], start=-1)
    r = N + 1
    while True:
        h = diff ** r * qq
        hd = _coeffs(h, K)
        M = max(abs(i) for i in hd)
        D = 2 * max(M, L) + 1
        seq = transfer_sequence(Pd, hd, K, 2 * D + 2)
        C = berlekamp_massey(seq, K)
        order = len(C) - 1
        mu = sp.Poly.from_list([K.to_sympy(c) for c in C], sp.Symbol("x"), domain=K)   # x^L + c1 x^{L-1} + ...
        lo, hi, k_exact, how = _max_modulus(mu)
        threshold = Fraction(1, 4 ** r)
        if lo > threshold or r >= N + 1 + max_extra_r:
            break
        r += 1
    witness.update({"r": r, "recurrence_order": order, "krylov_bound": D, "terms": len(seq),
                    "minimal_polynomial": mu.as_expr(), "lambda_lower": lo, "lambda_upper": hi,
                    "roots": how, "method": method})
    prov = {"method": method, "arithmetic": f"exact over {K}, Arb root isolation",
            "timing": {"seconds": round(_time.perf_counter() - t0, 4)}}
    if not lo > threshold:
        witness["reason"] = f"lambda is not certified above 4^-r for r <= {r}: increase r"
        return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=prov)
    return _finish(lo, hi, k_exact, witness, prov, offset=0)


def _finish(lo: Fraction, hi: Fraction, k_exact, witness, prov, *, offset: int) -> Result:
    """``s_2 = offset - (1/2) log2 lambda`` from ``lambda in [lo, hi]``."""
    if lo <= 0:
        witness["reason"] = "the largest root modulus is not separated from 0"
        return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=prov)
    if k_exact is not None:
        value = sp.Integer(offset) + sp.Rational(k_exact, 2)
        lower = upper = value
    else:
        value = None
        l2lo, l2hi = _log2_bounds(lo, hi)
        lower, upper = offset - l2hi / 2, offset - l2lo / 2
    if offset == 0 and not hi < 1:
        witness["reason"] = ("lambda >= 1 is possible: only s_2 in [-(1/2) log2 lambda, 0] is proven "
                             "(phi may not be in L2)")
        return Result(value=None, lower=lower, upper=0, status=INCONCLUSIVE, witness=witness, provenance=prov)
    return Result(value=value, lower=lower, upper=upper, status=CERTIFIED, witness=witness, provenance=prov)


# --------------------------------------------------------------------------------------------
# any arity: the autocorrelation-weighted route
# --------------------------------------------------------------------------------------------

def _lambda(Pd: dict, h: LaurentSymbol, K, L: int, m: int):
    """``(lo, hi, k_exact, mu, D, terms, how)`` for ``lambda = limsup ((T^n h)_0)^(1/n)``, exactly."""
    hd = _coeffs(h, K)
    D = 2 * max(max(abs(i) for i in hd), L) + 1
    seq = transfer_sequence(Pd, hd, K, 2 * D + 2, m)
    C = berlekamp_massey(seq, K)
    mu = sp.Poly.from_list([K.to_sympy(c) for c in C], sp.Symbol("x"), domain=K)
    if mu.degree() <= 0:
        return Fraction(0), Fraction(0), None, mu, D, len(seq), "the sequence vanishes"
    lo, hi, k_exact, how = _max_modulus(mu, m)
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


def _autocorrelation_route(a: LaurentSymbol, m: int, *, max_extra_r: int = 4) -> Result:
    """The L2-Sobolev exponent ``s_2`` of the refinable function ``phi_a`` of arity ``m``, certified or
    inconclusive, weighted by the autocorrelation symbol (module docstring, "Arity m > 2").

    ``a``: a numeric :class:`~analysis.algebra.symbol.LaurentSymbol` (rational or real algebraic) with
    ``a(1) = m`` (else :class:`AnalysisError`). Returns a :class:`Result`: ``value`` (exact ``k/2`` when
    ``lambda = m^-k``), ``lower``/``upper`` (rational, outward rounded), the witness (``weight`` ``w``,
    ``r``, the minimal polynomial, ``lambda`` bounds) and provenance.

    >>> _autocorrelation_route(LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1), 2).value   # hat function
    3/2
    """
    from ..algebra.factorization import check_arity, smoothing_factor
    from .convergence import log_interval

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
    N = smoothing_factor(a, arity=m).value
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
        stab = stable_shifts(a, arity=m)
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
        llo, lhi = log_interval(sp.Rational(lo.numerator, lo.denominator),
                                  sp.Rational(hi.numerator, hi.denominator), m)
        lower, upper = -lhi / 2, -llo / 2
    prov.update({"arithmetic": f"exact over {K}, Arb root isolation",
                 "timing": {"seconds": round(_time.perf_counter() - t0, 4)}})
    return Result(value=value, lower=lower, upper=upper, status=CERTIFIED, witness=witness, provenance=prov)


# --------------------------------------------------------------------------------------------
# the ball route (stable case formula)
# --------------------------------------------------------------------------------------------

def sobolev_stable_formula(balls, N: int, *, prec: int = 192):
    """``(lo, hi)``: rational enclosure of ``rho(T_Q)`` for the ball mask ``balls`` with ``N``
    factors ``(1+z)``: ``Q = c(z) c(1/z)/2``, ``c = 2^N a/(1+z)^N``, ``(T_Q)_{ij} = Q_{2i-j}``,
    ``i, j`` over the support of ``Q``. Valid for every mask in the balls with ``(1+z)^N | a``.
    The stable-case Sobolev exponent is ``N - (1/2) log2 rho(T_Q)``. None when Arb cannot
    enclose the eigenvalues (e.g. defective multiple eigenvalues)."""
    import flint

    from ..jsr._exact import arb_to_fraction_bounds
    from .balls import ball_divide_by_one_plus_z

    for wp in (prec, 2 * prec, 4 * prec):
        with flint.ctx.workprec(wp):
            c = [x * 2 ** N for x in ball_divide_by_one_plus_z(balls, N)] if N > 0 else list(balls)
            m = len(c) - 1
            Q = {}
            for i in range(len(c)):
                for j in range(len(c)):
                    Q[i - j] = Q.get(i - j, flint.arb(0)) + c[i] * c[j] / 2
            idx = list(range(-m, m + 1))
            T = flint.acb_mat([[Q.get(2 * i - j, flint.arb(0)) for j in idx] for i in idx])
            try:
                eigs = T.eig(multiple=True)
            except ValueError:
                continue
            if not all(e.is_finite() for e in eigs):
                continue
            bounds = [arb_to_fraction_bounds(abs(e)) for e in eigs]
            return max(b[0] for b in bounds), max(b[1] for b in bounds), wp
    return None


def _ball_route(scheme: Any, *, sum_rules: int | None = None, prec: int | None = None) -> Result:
    t0 = _time.perf_counter()
    stab = stable_shifts(scheme, sum_rules=sum_rules, prec=prec)
    balls, N, prec, source = ball_mask(scheme, sum_rules=sum_rules, prec=prec)
    method = "stable-case formula s_2 = N - (1/2) log2 rho(T_Q), Arb eigenvalue enclosures (ball mask)"
    witness = {"stable_shifts": stab, "reduced_mask": None, "q": None, "N": N, "method": method}
    prov = {"method": method, "source": source, "prec": prec}
    if stab.value is not True:
        witness["reason"] = ("stability of the shifts is not certified, so the stable-case formula does not apply: "
                             + stab.witness.get("reason", ""))
        return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=prov)
    enc = sobolev_stable_formula(balls, N, prec=max(prec + 64, 192))
    if enc is None:
        witness["reason"] = "Arb could not enclose the eigenvalues of T_Q (multiple or defective eigenvalues)"
        return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=prov)
    lo, hi, wp = enc
    witness.update({"rho_lower": lo, "rho_upper": hi, "matrix_size": 2 * (len(balls) - 1 - N) + 1})
    prov["timing"] = {"seconds": round(_time.perf_counter() - t0, 4)}
    return _finish(lo, hi, None, witness, prov, offset=N)


# --------------------------------------------------------------------------------------------
# public entry point
# --------------------------------------------------------------------------------------------

def sobolev_exponent(a: Any, *, arity: int = 2, sum_rules: int | None = None, prec: int | None = None) -> Result:
    """The L2-Sobolev exponent ``s_2`` of the basic limit function ``phi_a``, certified.

    ``arity`` ``m > 2``: an exact symbol with ``a(1) = m``, :func:`_autocorrelation_route`.

    ``a``: a :class:`~analysis.algebra.symbol.LaurentSymbol` (rational or real algebraic coefficients;
    exact route), a catalogue entry known by Arb balls (``enclosure(prec)``, ``sum_rules``), or a
    list of ``flint.arb`` balls with ``sum_rules=N`` (ball route). Correct whether or not the
    shifts of ``phi_a`` are stable (exact route), or inconclusive with the reason.

    Returns a :class:`Result`: ``value`` (exact ``k/2`` when ``lambda = 2^-k``), ``lower``/``upper``
    (rational, outward rounded), status, witness ``{"stable_shifts": Result, "reduced_mask": b,
    "q": q, "method": ..., ...}``. :class:`AnalysisError` when ``a(1) != 2``.
    See the module docstring for the algorithm and references.
    """
    if arity != 2:
        return _autocorrelation_route(a, arity)
    if isinstance(a, LaurentSymbol):
        a.require_numeric("a Sobolev exponent")
        dom = a.domain
        if not (dom.is_QQ or dom.is_ZZ or dom.is_AlgebraicField):
            raise AnalysisError(f"the Sobolev exponent needs rational or algebraic coefficients, not {dom}")
        a1 = a(1)
        if sp.simplify(a1 - 2) != 0:
            raise AnalysisError(f"the Sobolev exponent needs the normalisation a(1) = 2 (here a(1) = {sp.sstr(a1)})")
        return _exact_route(a)
    import flint

    if not (hasattr(a, "enclosure") or isinstance(a, (list, tuple))):
        raise AnalysisError(f"expected a LaurentSymbol, a catalogue entry or a list of arb balls, not {type(a).__name__}")
    balls, N, p, _ = ball_mask(a, sum_rules=sum_rules, prec=prec)
    with flint.ctx.workprec(p + 64):
        if not sum(balls, flint.arb(0)).contains(2):
            raise AnalysisError("the Sobolev exponent needs the normalisation a(1) = 2 (the balls exclude it)")
    return _ball_route(a, sum_rules=sum_rules, prec=prec)


def sobolev_stable_formula_exact(a: LaurentSymbol):
    """The stable-case formula evaluated exactly for a symbol: ``(N, lo, hi, k_exact)`` with
    ``rho(T_Q) in [lo, hi]`` from the exact characteristic polynomial of ``T_Q`` (``Q = c c*/2``,
    ``c = 2^N a/(1+z)^N``). Used to check the formula against the sequence method (tests)."""
    from ..algebra.factorization import factor_out, smoothing_factor

    N = smoothing_factor(a, exceptional=False).value
    c = factor_out(a, N) if N > 0 else a
    Qs = c * c.reversed() / 2
    m = Qs.end
    idx = list(range(-m, m + 1))
    T = sp.Matrix(len(idx), len(idx), lambda i, j: Qs.coeff(2 * idx[i] - idx[j]))
    x = sp.Symbol("x")
    K = a.poly.domain if not a.poly.domain.is_ZZ else sp.QQ
    cp = sp.Poly(T.charpoly(x).as_expr(), x, domain=K)
    lo, hi, k, _ = _max_modulus(cp)
    return N, lo, hi, k
