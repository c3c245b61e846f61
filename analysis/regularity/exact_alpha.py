"""Exact Hölder exponents and certified comparisons of alpha with a claimed exact value.

A certified enclosure ``[lower, upper]`` of alpha (:func:`analysis.regularity.holder.holder_exponent`)
decides a claimed value only when the value lies outside it. Papers print exponents in closed form
(Daubechies' D4: ``alpha = 2 - log2(1 + sqrt(3))``), and a closed form inside a tiny enclosure is
neither proven nor refuted by it. This module decides such claims exactly where the mathematics allows:

* :func:`exact_spectral_radius` — the spectral radius of a small matrix with rational or algebraic
  entries as an exact real algebraic number, chosen with a certified enclosure: the roots of the
  rational polynomial ``Q`` (the norm of the characteristic polynomial over its number field)
  whose modulus can lie in the enclosure must all be real with one and the same absolute value;
* :func:`alpha_closed_form` — ``alpha = k - log_m(rho)/L`` exactly, when the joint spectral radius
  is *proven equal* to ``rho(Pi)^(1/L)`` of a product ``Pi`` of length ``L``: a single matrix, a
  commuting family (``JSR = max_i rho(A_i)``: every 1 x 1 family, e.g. D4), a block-triangular
  family whose best block is one of those and dominates the others, or equal JSR bounds
  (B-splines). An invariant polytope certified in floating point or balls proves
  ``rho(Pi)^(1/L) <= JSR <= rho(Pi)^(1/L) (1 + eps)`` only, so there ``alpha <= k - log_m(rho)/L``
  is exact but equality is not proven (``exact`` is False, ``bound = "upper"``);
* :func:`compare_alpha` — the sign of ``alpha - v`` for an exact claimed ``v``:
  ``alpha - v`` has the sign of ``m^(L (k - v)) - rho``, and ``m^(L (k - v))`` is an algebraic
  number when ``v`` is a rational (small denominator) plus rational multiples of ``log_m`` of
  positive algebraic numbers (``log2(1 + sqrt(3))``); the two algebraic numbers are compared exactly
  (:class:`analysis.algebra.algebraic.RealAlgebraic`).

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.regularity.holder import holder_exponent
>>> s3 = sp.sqrt(3)
>>> d4 = LaurentSymbol.from_mask([(1 + s3)/4, (3 + s3)/4, (3 - s3)/4, (1 - s3)/4])   # Daubechies D4
>>> h = holder_exponent(d4)
>>> f = alpha_closed_form(h)
>>> f["exact"], f["alpha"]
(True, -log(1/2 + sqrt(3)/2)/log(2) + 1)
>>> compare_alpha(h, 2 - sp.log(1 + s3, 2))[0], compare_alpha(h, sp.Rational(11, 20))[0]
(0, 1)

Algorithm
---------
``Q = Norm_{K/QQ}(det(x I - Pi))`` (sympy's ``Poly.norm`` over the primitive element field ``K``);
real roots by exact isolation, non-real ones by FLINT's certified complex root balls at up to 1024
bits. ``m^(L (k - v))`` is built from ``sympy.expand(L (k - v) log m)``: each term must be
``c log(y)`` with ``c`` rational (denominator at most :data:`MAX_DENOMINATOR`) and ``y`` a
positive algebraic number; otherwise the claim is left to the enclosure.

References
----------
N. Guglielmi, V. Protasov, Found. Comput. Math. 13 (2013) (s.m.p. and the JSR);
I. Daubechies, *Ten Lectures on Wavelets*, SIAM (1992), Sect. 7.2 (alpha of D4 = 2 - log2(1 + sqrt 3)).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import sympy as sp

from ..algebra.algebraic import RealAlgebraic
from ..algebra.reader import as_expr
from ..result import CERTIFIED, Result

__all__ = ["exact_spectral_radius", "alpha_closed_form", "compare_alpha", "power_of_claim", "MAX_DENOMINATOR",
           "EXACT_METHODS"]

#: the largest denominator of a rational exponent in ``m^(L (k - v))`` (its algebraic degree)
MAX_DENOMINATOR = 240
#: the largest matrix whose spectral radius is identified exactly
MAX_SIZE = 8
#: JSR methods that prove ``JSR = max rho(A_i)`` or ``rho(A)`` exactly
EXACT_METHODS = ("spectral radius (single matrix)", "commuting family: JSR = max_i rho(A_i)")


def _q(x) -> sp.Rational:
    if isinstance(x, Fraction):
        return sp.Rational(x.numerator, x.denominator)
    return sp.Rational(x)


def _rational_multiple(P: sp.Matrix) -> sp.Poly:
    """A nonzero polynomial over QQ vanishing at every eigenvalue of ``P`` (rational or algebraic entries)."""
    x = sp.Symbol("x")
    cp = sp.Poly(P.charpoly(x).as_expr(), x, extension=True)
    if cp.domain.is_QQ or cp.domain.is_ZZ:
        return cp.set_domain(sp.QQ)
    return sp.Poly(cp.norm().as_expr(), x, domain=sp.QQ)


def exact_spectral_radius(mats, lo, hi) -> sp.Expr | None:
    """The exact value of a number ``rho`` known to lie in ``[lo, hi]`` and to be the modulus of an
    eigenvalue of one of the matrices ``mats`` (sympy matrices, rational or algebraic entries), as a
    closed form (rational, radicals, or ``CRootOf``); None when it cannot be identified.

    Every root of ``Q`` (a rational multiple of the characteristic polynomials) whose modulus may lie in
    ``[lo, hi]`` must be real, and their absolute values must be one number: then it is ``rho``.

    >>> exact_spectral_radius([sp.Matrix([[1, 1], [1, 0]])], sp.Rational(161, 100), sp.Rational(162, 100))
    1/2 + sqrt(5)/2
    >>> exact_spectral_radius([sp.Matrix([[0, 2], [1, 0]])], 1, 2)          # eigenvalues +- sqrt(2)
    sqrt(2)
    """
    import flint

    lo, hi = _q(lo), _q(hi)
    if lo <= 0 or hi < lo:
        return None
    mats = list(mats)
    if not mats or any(M.shape[0] > MAX_SIZE for M in mats):
        return None
    x = sp.Symbol("x")
    factors = set()
    for M in mats:
        f = _rational_multiple(M)
        for g, _mult in sp.Poly(f.as_expr().subs(f.gen, x), x, domain=sp.QQ).factor_list()[1]:
            factors.add(g.monic())
    cands: list[RealAlgebraic] = []
    for f in sorted(factors, key=lambda g: (g.degree(), str(g))):
        fneg = sp.Poly(f.as_expr().subs(x, -x), x, domain=sp.QQ)
        for r in RealAlgebraic.roots_of(f):
            a = r if r.sign() >= 0 else RealAlgebraic(fneg, -r.b, -r.a)     # |r|, a root of f(-x)
            if a.compare(lo) >= 0 and a.compare(hi) <= 0:
                cands.append(a)
        if f.count_roots() == f.degree():
            continue
        coeffs = [sp.Rational(c) for c in reversed(f.all_coeffs())]
        den = sp.ilcm(*[c.q for c in coeffs])
        fp = flint.fmpq_poly([int(c * den) for c in coeffs])
        decided = False
        old = flint.ctx.prec
        try:
            for prec in (64, 256, 1024):
                flint.ctx.prec = prec
                lo_b = flint.arb(int(lo.p)) / int(lo.q)
                hi_b = flint.arb(int(hi.p)) / int(hi.q)
                nonreal = [z for z, _ in fp.complex_roots() if not z.imag.is_zero()]
                if all(abs(z) < lo_b or abs(z) > hi_b for z in nonreal):
                    decided = True
                    break
        finally:
            flint.ctx.prec = old
        if not decided:
            return None
    if not cands or any(c.compare(cands[0]) != 0 for c in cands[1:]):
        return None
    return cands[0].expr


def _dominant_block(jsr: Result):
    """The best block of a block-triangular JSR result when it dominates every other block (its lower
    bound above their upper bounds), else None."""
    parts = jsr.witness.get("blocks")
    if parts is None:
        sub = jsr.witness.get("invariant_subspace")
        parts = sub.get("blocks") if isinstance(sub, dict) else None
    if not parts:
        return None
    best = max(parts, key=lambda b: _q(b["lower"]))
    if all(b is best or (b.get("upper") is not None and _q(b["upper"]) < _q(best["lower"])) for b in parts):
        return best
    return None


def alpha_closed_form(h: Result, arity: int = 2) -> dict[str, Any] | None:
    """``alpha = k - log_m(rho)/L`` from a Hölder result of the exact route (binary or m-ary):
    ``{"alpha", "rho", "L", "k", "m", "word", "exact", "how"}``. ``exact`` is True when the JSR is
    proven equal to ``rho^(1/L)`` (``alpha`` is then the exponent); otherwise ``alpha`` is an exact
    upper bound (the JSR is at least ``rho(Pi)^(1/L)``). None for the ball routes, uncertified results
    or matrices whose spectral radius cannot be identified exactly."""
    from ..stationary.transition import transition_matrices
    from .holder import word_product

    if h is None:
        return None
    jsr, c, k = h.witness.get("jsr"), h.witness.get("c"), h.witness.get("k")
    if jsr is None or c is None or k is None or jsr.status != CERTIFIED or not hasattr(c, "mask"):
        return None
    if jsr.provenance.get("input_kind") == "float":
        return None
    m = arity
    word = tuple(jsr.witness.get("product") or ())
    method = jsr.provenance.get("method", "")
    block = _dominant_block(jsr)
    T = None

    def mats():
        return list(transition_matrices(c, arity=m))

    if jsr.value is not None:                                     # JSR known exactly (rational)
        rho, L, exact, how = _q(jsr.value), 1, True, "JSR bounds equal"
    elif block is not None and _q(block["lower"]) == _q(block["upper"]):
        rho, L, exact, how = _q(block["lower"]), 1, True, "dominant diagonal block with equal JSR bounds"
    elif method in EXACT_METHODS or (block is not None and block.get("method") in EXACT_METHODS):
        # JSR = max_i rho(A_i) (of the family or of its dominant block): an eigenvalue modulus of one A_i
        rho = exact_spectral_radius(mats(), jsr.lower, jsr.upper)
        L, exact, how = 1, True, "JSR = max_i rho(T_i) (" + (method if block is None else block["method"]) + ")"
    else:
        if not word:
            return None
        T = mats()
        rp = jsr.witness.get("rho_product") or {}
        if rp.get("lower") is None or rp.get("upper") is None:
            return None
        rho = exact_spectral_radius([word_product(T, word)], rp["lower"], rp["upper"])
        L, exact, how = len(word), False, "JSR >= rho(T_w)^(1/L); the invariant polytope is certified up to rounding"
    if rho is None:
        return None
    alpha = sp.Integer(k) - sp.log(rho, m) / L
    return {"alpha": alpha, "rho": rho, "L": L, "k": k, "m": m, "word": word, "exact": exact, "how": how}


def power_of_claim(v, k: int, L: int, m: int) -> sp.Expr | None:
    """``m^(L (k - v))`` as an exact algebraic expression, or None when ``v`` is not a rational (small
    denominator) plus rational multiples of logarithms of positive algebraic numbers.

    >>> power_of_claim(2 - sp.log(1 + sp.sqrt(3), 2), 1, 1, 2)
    1/2 + sqrt(3)/2
    >>> power_of_claim(sp.Rational(11, 20), 1, 1, 2)
    2**(9/20)
    >>> power_of_claim(sp.pi, 1, 1, 2) is None
    True
    """
    v = as_expr(v)
    E = sp.expand(sp.Integer(L) * (sp.Integer(k) - v) * sp.log(m))
    out = sp.Integer(1)
    for term in sp.Add.make_args(E):
        c, rest = term.as_coeff_Mul()
        if not c.is_Rational or c.q > MAX_DENOMINATOR:
            return None
        if rest == 1:
            return None                         # a rational not multiplied by a logarithm: e^c
        if not isinstance(rest, sp.log) or len(rest.args) != 1:
            return None
        y = rest.args[0]
        if y.free_symbols or not y.is_algebraic:
            return None
        try:
            if RealAlgebraic.from_expr(y).sign() <= 0:
                return None
        except Exception:            # not a real algebraic number sympy can handle
            return None
        out = out * y ** c
    return out


def compare_alpha(h: Result, v, arity: int = 2, *, form: dict | None = None) -> tuple[int | None, str]:
    """``(sign(alpha - v), why)`` decided exactly (see the module docstring), or ``(None, why)``.

    With an exact closed form the sign is -1, 0 or 1; with an upper bound only (a polytope certificate)
    only ``alpha < v`` (-1) is decided here (``alpha <= bound < v``). ``form``: the result of
    :func:`alpha_closed_form` when it is already known.
    """
    f = form if form is not None else alpha_closed_form(h, arity)
    if f is None:
        return None, "no exact closed form of alpha"
    t = power_of_claim(v, f["k"], f["L"], f["m"])
    if t is None:
        return None, (f"alpha {'=' if f['exact'] else '<='} {sp.sstr(f['alpha'])}, but the claimed value is not a "
                      f"rational plus rational multiples of log{f['m']}(algebraic number): no exact comparison")
    try:
        s = RealAlgebraic.from_expr(t).compare(RealAlgebraic.from_expr(f["rho"]))
    except Exception as exc:                 # pragma: no cover - sympy could not handle the numbers
        return None, f"exact comparison failed ({type(exc).__name__})"
    form = sp.sstr(f["alpha"])
    if f["exact"]:
        rel = "equal to" if s == 0 else "greater than" if s > 0 else "less than"
        return s, f"alpha = {form} exactly ({f['how']}), {rel} the claimed value (exact algebraic comparison)"
    w = "".join(map(str, f["word"]))
    if s < 0:
        return -1, (f"alpha <= {form} (JSR >= rho(T_{w})^(1/{f['L']}), exact) < the claimed value (exact algebraic "
                    "comparison)")
    return None, (f"alpha <= {form} exactly; equality JSR = rho(T_{w})^(1/{f['L']}) is certified only up to the "
                  "invariant polytope's rounding")
