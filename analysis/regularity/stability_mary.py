"""Stability of the integer shifts of an m-ary refinable function, for the m-ary Sobolev exponent (issue 12).

For a mask with ``a(1) = m`` the refinable distribution ``phi = sum_k a_k phi(m . - k)``
(``phi^(0) = 1``) has ``phi^(xi) = prod_{j>=1} A(xi/m^j)``, ``A(xi) = a(e^{-i xi})/m``. Its shifts are
stable iff the *bad set* ``B = {xi : phi^(xi + 2 pi k) = 0 for all k}`` is empty.

Criterion (m >= 3): symmetric zeros, blocking cycles, and why they are all
-----------------------------------------------------------------------------
Splitting ``k`` by its residue mod ``m``: ``xi`` is bad iff each of its ``m`` *children*
``(xi + 2 pi l)/m`` (``l = 0..m-1``, mod ``2 pi``) is a zero of ``A`` or bad.

* **Symmetric zeros** (reduction). ``a(eps z0) = 0`` for every m-th root of unity ``eps`` iff ``z0^m``
  is a common zero of the polyphase components ``a_r`` (``a(z) = sum_r z^r a_r(z^m)``: a Vandermonde
  system), i.e. of ``H = gcd(a_0, ..., a_{m-1})``. When ``H`` has a zero on the unit circle the shifts are
  unstable (every child of ``xi = -arg z0^m`` is a zero of ``A``), and ``b = a H(z)/H(z^m)`` satisfies
  ``b(1) = m`` and, telescoping the product, ``phi_a^(xi) = phi_b^(xi) H(e^{-i xi})/H(1)``
  (``H(1) != 0`` since ``a(1) = m``): ``phi_a = H(tau) phi_b / H(1)``. Repeated on ``b``.
* **Stable** (sufficient). If every zero of ``a`` on the unit circle is an m-th root of unity
  (``!= 1``), the zeros of ``A`` mod ``2 pi`` lie in ``{2 pi l/m : l = 1..m-1}``. A bad ``xi == 0 (mod
  2 pi)`` is impossible (its child 0 has ``A(0) = 1`` and ``phi^(0) = 1``); for a bad ``xi != 0`` no
  child lies in ``(2 pi/m) Z``, so all ``m`` children are bad, and by induction all ``m^j`` points
  ``(xi + 2 pi l)/m^j``. They are ``2 pi/m^j`` apart, so some bad point lies within ``2 pi/m^j`` of 0,
  where ``phi^`` (continuous, ``phi^(0) = 1``) does not vanish: ``B`` is empty.
* **Blocking cycles** (instability, issue 12 second round; the m-ary form of Cohen's cycles). Let
  ``{xi_1, ..., xi_p}`` be a cycle of ``xi -> m xi (mod 2 pi)`` not containing 0, such that every child of
  ``xi_{j+1}`` other than ``xi_j`` is a zero of ``A``. Then every ``xi_j`` is bad: for ``x = xi_j + 2 pi k``,
  ``phi^(x) = prod_{i>=1} A(x/m^i)`` and the points ``y_i = x/m^i (mod 2 pi)`` are successive children; if no
  ``A(y_i)`` vanished they would all stay on the (finite, 0-free) cycle, but ``x/m^i -> 0``. For a rational mask
  the cycle points are roots of unity ``z = e^{-i xi}`` of an order ``n > 1`` prime to ``m``, the siblings are
  ``z eps^l`` (``l = 1..m-1``), of the orders ``n d`` with ``d | m``, ``d > 1``, and by Galois invariance the
  condition is ``Phi_{nd}(z) | a(z)`` for every divisor ``d > 1`` of ``m`` (then every cycle among the
  primitive n-th roots blocks; for ``m = 2``: ``Phi_{2n} | a``, the binary condition). Reduction:
  ``Phi_n(z^m) = prod_{d | m} Phi_{nd}(z)``, so ``b = a / prod_{d>1} Phi_{nd}`` satisfies
  ``a(z) Phi_n(z) = b(z) Phi_n(z^m)``, ``b(1) = m`` and ``phi_a = Phi_n(tau) phi_b / Phi_n(1)``.
* **Completeness** (derived here; for ``m = 2`` it is the Jia–Wang / Cohen criterion). The shifts are unstable
  iff there are symmetric zeros on the circle or a blocking cycle. Proof of "only if": ``B`` is finite
  (``phi^`` is entire and ``phi^(0) = 1``, and ``B`` lies in its zero set on ``[0, 2 pi]``). Assume no point has
  all its children in ``Z_A`` (no symmetric zeros). Every ``xi in B`` then has a child in ``B`` outside ``Z_A``; following
  such children inside the finite ``B`` runs into a cycle ``x_i = m x_{i+1}``, whose points are roots of unity
  of an order prime to ``m``. A sibling ``y`` of a cycle point that is not a zero of ``A`` lies in ``B`` and has
  an order divisible by a prime ``p | m``; the children of such a point have a strictly larger ``p``-adic order
  (``v_p(ord w) = v_p(ord y) + v_p(m)``), so the chain of ``B``-children from ``y`` would be infinite in the finite
  ``B`` unless it reaches a point with all children in ``Z_A`` — excluded. Hence every sibling is a zero: a
  blocking cycle. For a rational mask both conditions are decided exactly (polyphase gcd; cyclotomic
  divisibility), so the test is **necessary and sufficient**; after removing both mechanisms
  (``b``, repeatedly) the reduced mask is stable even when it keeps zeros on the circle.
* Algebraic (non-rational) masks: the cycle condition is not Galois-invariant and is not searched; a zero on the
  circle that is not an m-th root of unity (and not symmetric) gives *inconclusive*.

For ``m = 2`` the complete binary criterion (:func:`analysis.regularity.stability.stable_shifts`:
symmetric zeros and blocking cycles) is used unchanged.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> stable_shifts_mary(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 3).value   # ternary linear B-spline
True
>>> r = stable_shifts_mary(LaurentSymbol.from_expr("(1+z**3+z**6)*(1+z+z**2)**2/9"), 3)
>>> r.value, r.witness["q"], r.witness["reduced_mask"].expr().factor()    # phi_a = (1+tau+tau^2) phi_b/3
(False, LaurentSymbol([1, 1, 1], start=0, domain=QQ), (z**2 + z + 1)**3/9)
>>> r = stable_shifts_mary(LaurentSymbol.from_expr("1 + z**2 + z**4"), 3)   # box on [0, 2]: blocking cycle {pi}
>>> r.value, r.witness["blocking_cycles"], r.witness["reduced_mask"].expr()
(False, [2], z**2 + z + 1)

Algorithm
---------
Exact gcds of polyphase components over the coefficient field (QQ or a real algebraic field); zeros on the
unit circle decided by :func:`analysis.regularity.stability.unit_circle_zero` (Cayley transform, Sturm
count) after dividing out every factor of ``z^m - 1``.

References
----------
R.-Q. Jia, J. Wang, *Stability and linear independence associated with wavelet decompositions*,
Proc. Amer. Math. Soc. 117 (1993) 1115-1124 (the general dilation).
A. Cohen, I. Daubechies, *A new technique to estimate the regularity of refinable functions*,
Rev. Mat. Iberoam. 12 (1996) 527-591 (cycles).
"""

from __future__ import annotations

import sympy as sp

from ..algebra.mary import check_arity
from ..algebra.symbol import LaurentSymbol, Z
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .stability import _field_poly, stable_shifts, unit_circle_zero

__all__ = ["polyphase_gcd", "stable_shifts_mary"]


def polyphase_gcd(p: sp.Poly, m: int) -> sp.Poly:
    """Monic ``H`` with ``H(z^m) = gcd_eps p(eps z)``: the gcd of the polyphase components of ``p``.

    >>> polyphase_gcd(sp.Poly((1 + Z**3) * (1 + Z + Z**2), Z, domain=sp.QQ), 3).as_expr()
    w + 1
    """
    w = sp.Symbol("w")
    comps: dict[int, dict] = {}
    for (e,), c in p.terms():
        comps.setdefault(e % m, {})[(e // m,)] = c
    g = None
    for r in range(m):
        pr = sp.Poly.from_dict(comps.get(r, {(0,): p.domain.zero}) or {(0,): p.domain.zero}, w, domain=p.domain)
        g = pr if g is None else g.gcd(pr)
    if g.is_zero or g.degree() <= 0:
        return sp.Poly(1, w, domain=p.domain)
    return g.monic()


def _upsample(H: sp.Poly, m: int) -> sp.Poly:
    return sp.Poly.from_dict({(e * m,): c for (e,), c in H.terms()}, Z, domain=H.domain)


def _strip_roots_of_unity(p: sp.Poly, m: int) -> sp.Poly:
    """``p`` with every factor it shares with ``z^m - 1`` divided out (repeatedly)."""
    zm = sp.Poly(Z ** m - 1, Z, domain=p.domain)
    while True:
        g = p.gcd(zm)
        if g.degree() <= 0:
            return p
        p = sp.div(p, g)[0]


def _blocking_orders(p: sp.Poly, m: int):
    """``(n, [d ...])`` for the orders ``n > 1`` prime to ``m`` with ``Phi_{nd} | p`` for every divisor ``d > 1`` of
    ``m`` (rational ``p``; with multiplicity: an order is yielded once per complete set of factors).

    >>> list(_blocking_orders(sp.Poly(1 + Z**2 + Z**4, Z, domain=sp.QQ), 3))
    [(2, [3])]
    """
    from math import gcd

    from sympy import totient

    divs = [d for d in range(2, m + 1) if m % d == 0]
    deg = p.degree()
    cur = p
    for n in range(2, 2 * deg * deg + 2):          # phi(k) >= sqrt(k/2): n d <= 2 deg^2
        if gcd(n, m) != 1 or sum(int(totient(n * d)) for d in divs) > cur.degree():
            continue
        while True:
            polys = [sp.Poly(sp.cyclotomic_poly(n * d, Z), Z, domain=p.domain) for d in divs]
            if not all(sp.rem(cur, f).is_zero for f in polys) or sum(f.degree() for f in polys) > cur.degree():
                break
            cur = sp.div(cur, sp.prod(polys))[0]
            yield n, divs


def stable_shifts_mary(a: LaurentSymbol, m: int) -> Result:
    """Are the integer shifts of the m-ary refinable function ``phi_a`` stable?

    Returns a :class:`Result`: ``value`` True / False (certified) or None (inconclusive, with
    ``witness["reason"]``); the witness carries ``reduced_mask`` ``b`` (stable) and ``q`` with
    ``phi_a = q(tau) phi_b / q(1)``, ``a(z) q(z) = b(z) q(z^m)``. See the module docstring.
    """
    m = check_arity(m)
    if m == 2:
        return stable_shifts(a)
    p = _field_poly(a)
    if sp.simplify(p.eval(1) - m) != 0:
        raise AnalysisError(f"stability of the {m}-ary refinable function needs a(1) = {m} "
                            f"(here a(1) = {sp.sstr(a(1))})")
    dom = p.domain
    q = sp.Poly(1, Z, domain=dom)
    cur, symmetric, steps = p, [], []
    method = (f"polyphase gcd H (H(z^{m}) | a) with Cayley/Sturm zeros on |z| = 1; every other zero on the "
              f"circle an m-th root of unity (m = {m}) => stable")
    rational = dom.is_QQ or dom.is_ZZ
    cycles: list[int] = []
    for _ in range(p.degree() + 1):            # each round removes a factor of positive degree
        H = polyphase_gcd(cur, m)
        on = False
        if H.degree() > 0:
            Hz = sp.Poly(H.as_expr().subs(H.gen, Z), Z, domain=dom)
            on, how = unit_circle_zero(Hz)
            if on is None:
                return Result(value=None, status=INCONCLUSIVE,
                              witness={"reason": f"cannot decide whether H = {sp.sstr(Hz.as_expr())} has a zero on "
                                                 f"the unit circle ({how})", "symmetric_zeros_on_circle": symmetric},
                              provenance={"method": method, "arity": m})
        if on:
            b, r = sp.div(cur * Hz, _upsample(Hz, m))
            if not r.is_zero:  # pragma: no cover - H(z^m) | a
                raise ArithmeticError("H(z^m) does not divide a(z) H(z)")
            symmetric.append(Hz.as_expr())
            steps.append(f"symmetric zeros on the unit circle: H = {sp.sstr(Hz.as_expr())} (H(z^{m}) | a; {how}); "
                         f"b = a H(z)/H(z^{m})")
            q, cur = q * Hz, b
            continue
        found = next(iter(_blocking_orders(cur, m)), None) if rational else None
        if found is None:
            break
        n, factors = found
        names = [f"Phi_{n * d}" for d in factors]
        cur = sp.div(cur, sp.prod([sp.Poly(sp.cyclotomic_poly(n * d, Z), Z, domain=dom) for d in factors]))[0]
        q = q * sp.Poly(sp.cyclotomic_poly(n, Z), Z, domain=dom)
        cycles.append(n)
        steps.append(f"blocking cycles among the primitive {n}-th roots of unity (xi -> {m} xi): "
                     f"{', '.join(names)} | a; b = a/({'*'.join(names)})")
    rest = _strip_roots_of_unity(cur, m)
    on, how = unit_circle_zero(rest)
    witness = {"symmetric_zeros_on_circle": symmetric, "blocking_cycles": cycles, "steps": steps}
    prov = {"method": method, "arity": m, "arithmetic": f"exact over {dom}"}
    if on is None or (on and not rational):
        witness["reason"] = ((f"a (after the reductions) has a zero on the unit circle that is not an m-th root "
                              f"of unity (m = {m}; {how}); blocking cycles are decided for rational masks only")
                             if on else f"cannot decide the zeros of a on the unit circle ({how})")
        if cycles or symmetric:      # unstable anyway (certified mechanism), the reduction is just incomplete
            witness["reason"] = "unstable (" + "; ".join(steps) + "); the reduced mask is undecided: " + witness["reason"]
            return Result(value=False, status=CERTIFIED, witness=witness, provenance=prov)
        return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=prov)
    stable = not symmetric and not cycles
    if on:          # rational mask, zeros on the circle that no mechanism explains: stable by the criterion
        prov["method"] += "; complete criterion for rational masks (module docstring): no symmetric zeros, no cycles"
        why = (f"the zeros on the unit circle that are not m-th roots of unity (m = {m}) ({how}) lie on no blocking cycle and "
               f"have no symmetric partners: the bad set is empty (module docstring)")
    else:
        why = f"every zero of a on the unit circle is an m-th root of unity (m = {m})"
    witness.update({"reduced_mask": LaurentSymbol(cur, a.start, a.params), "q": LaurentSymbol(q, 0, a.params),
                    "reason": (f"{why}: stable" if stable else
                               "unstable: " + "; ".join(steps) + f"; the reduced mask is stable ({why})")})
    return Result(value=stable, status=CERTIFIED, witness=witness, provenance=prov)
