"""Stability of the integer shifts of the basic limit function, decided exactly (issue 9.3).

For a binary mask with ``a(1) = 2`` the refinable distribution ``phi`` (``phi = sum_k a_k
phi(2 . - k)``, ``phi^(0) = 1``) has ``phi^(xi) = prod_{j>=1} A(xi/2^j)``, ``A(xi) = a(e^{-i xi})/2``.
Its integer shifts are *stable* (a Riesz basis of their span) iff for every ``xi`` some
``phi^(xi + 2 pi k)`` is nonzero.

Criterion (Jia–Wang 1993; Cohen's cycles)
-----------------------------------------
The shifts are **unstable** iff

(i)  ``a`` has a pair of symmetric zeros ``z0, -z0`` **on the unit circle**, or
(ii) there is a nontrivial cycle ``{z_1, ..., z_p}`` of the squaring map on the unit circle
     (``z_j^2 = z_{j+1}`` cyclically: roots of unity of odd order ``n > 1``) with
     ``a(-z_j) = 0`` for every ``j`` (a *blocking cycle*). For a rational mask this is
     ``Phi_{2n}(z) | a(z)`` for some odd ``n > 1`` (then every cycle among the primitive
     ``n``-th roots blocks).

Why: ``phi^(xi + 2 pi k) = 0`` for all ``k`` means, splitting ``k`` by parity, that each of the
two "children" ``xi/2`` and ``xi/2 + pi`` is either a zero of ``A`` or again such a point; the
set of such points is finite (it lies in ``{2^j eta : A(eta) = 0}``), so following children one
either meets a point where both children are zeros of ``A`` (symmetric zeros ``z0, -z0`` of
``a``, on the circle since ``|e^{-i xi}| = 1``) or runs into a cycle of the doubling map
``xi -> 2 xi`` whose points all have ``A(xi + pi) = 0`` (a blocking cycle).

*Correction of the issue's wording.* Issue 9 says "no pair of symmetric zeros ``z0, -z0``
(Jia–Micchelli)". That is not the stability criterion: the box function on ``[0, 3]``
(``a = 1 + z^3``, zeros ``-1, e^{+-i pi/3}``) has no symmetric zeros, yet its shifts are unstable
(blocking cycle ``{e^{2 pi i/3}, e^{4 pi i/3}}``, ``Phi_6 | a``); and symmetric zeros *off* the
unit circle do not destroy stability (they matter for linear independence, not stability).

Arity m >= 3 (``stable_shifts(a, arity=m)``): symmetric zeros, blocking cycles, and why they are all
------------------------------------------------------------------------------------------------------
For arity ``m`` ``phi = sum_k a_k phi(m . - k)``, ``phi^(xi) = prod_{j>=1} A(xi/m^j)``, ``A(xi) = a(e^{-i xi})/m``.
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

Algorithm (exact)
-----------------
* ``g = gcd(a(z), a(-z))`` is even, ``g(z) = H(z^2)``; (i) iff ``H`` has a zero on the unit
  circle, decided by the Cayley transform ``w = (1+it)/(1-it)``: ``(1-it)^m H(w) = R(t) + i I(t)``
  and ``H`` has a zero on the circle iff ``H(-1) = 0`` or ``gcd(R, I)`` has a real zero (Sturm
  count over QQ; over a real algebraic field: certified isolation of the roots of the squarefree
  gcd, a root being real when its ball is the only one meeting its mirror image).
* (ii) iff ``Phi_{2n} | a`` for an odd ``n > 1`` with ``phi(2n) <= deg a`` (rational masks;
  over an algebraic field a proper partial factor ``gcd(a, Phi_{2n})`` gives *inconclusive*).
* Ball masks (Daubechies D6 ...): divide out ``(1+z)^N`` (:func:`~analysis.regularity.balls.ball_divide_by_one_plus_z`)
  and isolate the roots of the quotient in Arb; if every root ball is certified off the unit
  circle the only zeros on the circle are at ``-1``, so neither (i) nor (ii) can hold.

Reduction
---------
When unstable, ``a`` is factored so that ``phi_a = q(tau) phi_b / q(1)`` with ``phi_b`` stable
(``tau`` the shift, ``q(tau) f = sum_k q_k f(. - k)``): for (i) ``b = a H(z)/H(z^2)`` (so
``a(z) H(z) = b(z) H(z^2)``, ``q = H``); for (ii) ``b = a / Phi_{2n}`` (``Phi_n(z^2) = Phi_n(z)
Phi_{2n}(z)`` for odd ``n``, so ``a Phi_n(z) = b Phi_n(z^2)``, ``q = Phi_n``). In both cases
``b(1) = 2`` and, telescoping the infinite product, ``phi_a^(xi) = phi_b^(xi) q(e^{-i xi})/q(1)``.
Repeated until stable.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> r = stable_shifts(LaurentSymbol.from_mask([1, 0, 0, 1]))      # the box on [0, 3]
>>> r.value, r.status, r.witness["blocking_cycles"]
(False, 'certified', [3])
>>> r.witness["reduced_mask"], r.witness["q"]
(LaurentSymbol([1, 1], start=0, domain=QQ), LaurentSymbol([1, 1, 1], start=0, domain=QQ))
>>> stable_shifts(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)).value
True

References
----------
R.-Q. Jia, J. Wang, *Stability and linear independence associated with wavelet
decompositions*, Proc. Amer. Math. Soc. 117 (1993) 1115-1124.
A. Cohen, *Ondelettes, analyses multirésolutions et filtres miroirs en quadrature*, Ann. IHP
Anal. Non Linéaire 7 (1990) 439-459 (the cycle condition).
R.-Q. Jia, C. A. Micchelli, *On linear independence for integer translates of a finite number
of functions*, Proc. Edinburgh Math. Soc. 36 (1993) 69-85 (symmetric zeros: linear independence).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result

if TYPE_CHECKING:  # pragma: no cover
    import sympy as sp

    from ..algebra.symbol import LaurentSymbol

# No sympy at import: a mask known by balls (stable_shifts of a catalogue entry such as
# daubechies-8) is decided by Arb root isolation without it; the exact criterion imports it.

# --------------------------------------------------------------------------------------------
# exact helpers
# --------------------------------------------------------------------------------------------

def _field_poly(a: LaurentSymbol) -> sp.Poly:
    """``z^(-start) a(z)`` over a field (QQ or a real algebraic field), or AnalysisError."""
    import sympy as sp

    a.require_numeric("the stability of the shifts")
    p = a.poly
    dom = p.domain
    if dom.is_ZZ:
        p = p.set_domain(sp.QQ)
    elif not (dom.is_QQ or dom.is_AlgebraicField):
        raise AnalysisError(f"stability is decided for rational or algebraic masks, not over {dom}")
    if dom.is_AlgebraicField and not all(sp.im(c) == 0 for c in a.mask):
        raise AnalysisError("stability is decided for masks with real coefficients")
    return p


def _reflect(p: sp.Poly) -> sp.Poly:
    """``p(-z)``."""
    import sympy as sp

    coeffs = p.rep.to_list()                     # highest first
    d = len(coeffs) - 1
    return sp.Poly.from_list([c if (d - i) % 2 == 0 else -c for i, c in enumerate(coeffs)],
                             p.gen, domain=p.domain)


def _even_part(g: sp.Poly) -> sp.Poly:
    """``H`` with ``g(z) = H(z^2)`` (``g`` even)."""
    import sympy as sp

    terms = {(m[0] // 2,): c for m, c in g.rep.to_dict().items()}
    if any(m[0] % 2 for m in g.monoms()):  # pragma: no cover - gcd(a(z), a(-z)) is even
        raise ArithmeticError("gcd(a(z), a(-z)) is not even")
    return sp.Poly.from_dict(terms, g.gen, domain=g.domain)


def _upsample(H: sp.Poly, m: int = 2) -> sp.Poly:
    """``H(z^m)``."""
    import sympy as sp

    return sp.Poly.from_dict({(e[0] * m,): c for e, c in H.rep.to_dict().items()}, H.gen, domain=H.domain)


def _real_roots_exist(D: sp.Poly) -> tuple[bool | None, str]:
    """Does the real-coefficient polynomial ``D`` (over QQ or a real algebraic field) have a real
    root?  Exact over QQ (Sturm); over an algebraic field by certified root isolation."""
    import sympy as sp

    from ..algebra.reader import as_expr

    if D.degree() <= 0:
        return False, "constant"
    if D.domain.is_QQ or D.domain.is_ZZ:
        return bool(D.count_roots() > 0), "Sturm count over QQ"
    # squarefree part, then certified isolation with the mirror-image argument
    sq = sp.Poly(sp.quo(D, sp.gcd(D, D.diff(D.gen))), D.gen, domain=D.domain)
    import flint

    from ..jsr._exact import NoEnclosure, sympy_to_arb

    for prec in (128, 256, 512, 1024):
        try:
            with flint.ctx.workprec(prec):
                coeffs = [flint.acb(sympy_to_arb(as_expr(sq.domain.to_sympy(c))))
                          for c in reversed(sq.rep.to_list())]
                roots = flint.acb_poly(coeffs).roots()
        except (ValueError, NoEnclosure):
            continue
        undecided = False
        for r in roots:
            if not r.imag.contains(0):
                continue
            mirror = r.conjugate()
            meets = [s for s in roots if s.overlaps(mirror)]
            if len(meets) == 1:
                return True, f"certified root isolation at {prec} bits"
            undecided = True
        if not undecided:
            return False, f"certified root isolation at {prec} bits (no real root)"
    return None, "root isolation over the algebraic field did not separate the roots"


def unit_circle_zero(H: sp.Poly) -> tuple[bool | None, str]:
    """Exactly: has the real-coefficient polynomial ``H`` a zero on the unit circle?

    Cayley transform ``w = (1+it)/(1-it)``: ``(1-it)^m H(w) = R(t) + i I(t)``; a zero on the
    circle other than ``-1`` is a common real zero of ``R`` and ``I``.

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import Z
    >>> unit_circle_zero(sp.Poly(Z**2 + 1, Z))[0], unit_circle_zero(sp.Poly(Z**2 - 3*Z + 1, Z))[0]
    (True, False)
    """
    import sympy as sp

    from ..algebra.reader import as_expr

    if H.degree() <= 0:
        return False, "constant"
    if H.eval(-1) == 0:
        return True, "H(-1) = 0"
    m = H.degree()
    t = sp.Symbol("t", real=True)
    expr = sp.Integer(0)
    for (k,), c in H.terms():
        expr += as_expr(c) * (1 + sp.I * t) ** k * (1 - sp.I * t) ** (m - k)
    expr = sp.expand(expr)
    R = expr.subs(sp.I, 0)
    I = sp.expand((expr - R) / sp.I)
    dom = H.domain
    Rp = sp.Poly(R, t, domain=dom)
    Ip = sp.Poly(I, t, domain=dom)
    D = Rp.gcd(Ip)
    if D.degree() <= 0:
        return False, "gcd of the Cayley real and imaginary parts is constant"
    has, how = _real_roots_exist(D)
    return has, f"common real zeros of the Cayley parts: {how}"


def _cyclotomic(n: int, dom) -> sp.Poly:
    import sympy as sp

    from ..algebra.symbol import Z

    return sp.Poly(sp.cyclotomic_poly(n, Z), Z, domain=dom)


# --------------------------------------------------------------------------------------------
# the decision and the reduction
# --------------------------------------------------------------------------------------------

def _one_step(p: sp.Poly):
    """One exact analysis of the polynomial ``p``.

    Returns ``(kind, data, factor_q, new_p, note)``: kind "stable", "symmetric" (data = H),
    "cycle" (data = n) or "inconclusive" (data = reason).
    """
    import sympy as sp

    dom = p.domain
    g = p.gcd(_reflect(p))
    notes = []
    if g.degree() > 0:
        H = _even_part(g.monic())
        on, how = unit_circle_zero(H)
        if on is None:
            return "inconclusive", f"cannot decide whether H = {sp.sstr(H.as_expr())} has a zero on the unit circle ({how})", None, None, None
        if on:
            # a(z) H(z) = b(z) H(z^2)
            b, r = sp.div(p * H, _upsample(H))
            if not r.is_zero:  # pragma: no cover - H(z^2) | a
                raise ArithmeticError("H(z^2) does not divide a(z) H(z)")
            return "symmetric", H, H, b, how
        notes.append(f"symmetric zeros gcd(a(z), a(-z)) = {sp.sstr(g.as_expr())}: none on the unit circle ({how})")
    deg = p.degree()
    n = 3
    while sp.totient(n) <= deg:
        Phi2n = _cyclotomic(2 * n, dom)
        G = p.gcd(Phi2n)
        if G.degree() == Phi2n.degree():
            b, r = sp.div(p, Phi2n)
            assert r.is_zero
            return "cycle", n, _cyclotomic(n, dom), b, None
        if G.degree() > 0:
            return ("inconclusive", f"gcd(a, Phi_{2 * n}) = {sp.sstr(G.as_expr())} is a proper factor over {dom}: "
                    "whether a cycle of primitive " f"{n}-th roots blocks is not decided", None, None, None)
        n += 2
    return "stable", notes, None, None, None


def stable_shifts(a: Any, *, arity: int = 2, sum_rules: int | None = None, prec: int | None = None) -> Result:
    """Are the integer shifts of the basic limit function ``phi_a`` stable?  Decided exactly.

    ``arity`` ``m >= 3``: an exact symbol with ``a(1) = m``, the m-ary criterion of the module docstring
    (:func:`_stable_shifts_dilated`: polyphase gcds and the m-ary cycles; its witness names the m-ary
    mechanisms, so the binary route below, with its own witness, is kept for ``m = 2``).

    ``a`` is a :class:`~analysis.algebra.symbol.LaurentSymbol` (rational or real algebraic
    coefficients), a catalogue entry known by Arb balls (``enclosure(prec)``, ``sum_rules``), or
    a list of ``flint.arb`` balls (then ``sum_rules`` is required).

    Returns a :class:`Result` with ``value`` True (stable) / False (unstable) / None and the
    witness: ``symmetric_zeros_on_circle`` (the polynomials ``H`` with ``H(z^2) | a`` and a zero
    of ``H`` on the unit circle), ``blocking_cycles`` (the odd orders ``n`` with ``Phi_{2n} | a``),
    ``reduced_mask`` ``b`` (stable) and ``q`` with ``phi_a = q(tau) phi_b / q(1)``,
    ``a(z) q(z) = b(z) q(z^2)``; ``reason`` in words. See the module docstring for the
    criterion (and why the issue's wording was corrected) and the algorithm.
    """
    from .balls import _is_symbol

    if arity != 2:
        from ..algebra.factorization import check_arity

        return _stable_shifts_dilated(a, check_arity(arity))
    if not _is_symbol(a):
        return _stable_shifts_balls(a, sum_rules=sum_rules, prec=prec)
    import sympy as sp

    from ..algebra.symbol import LaurentSymbol, Z

    p = _field_poly(a)
    if p.eval(1) != 2:
        raise AnalysisError(f"stability of the refinable function needs a(1) = 2 (here a(1) = {sp.sstr(a(1))})")
    dom = p.domain
    q = sp.Poly(1, Z, domain=dom)
    cur = p
    symmetric, cycles, steps, notes = [], [], [], []
    for _ in range(p.degree() + 1):
        kind, data, fq, newp, note = _one_step(cur)
        if kind == "inconclusive":
            return Result(value=None, status=INCONCLUSIVE,
                          witness={"reason": data, "symmetric_zeros_on_circle": symmetric,
                                   "blocking_cycles": cycles},
                          provenance={"method": "Jia-Wang criterion, exact gcds over " + str(dom)})
        if kind == "stable":
            notes.extend(data)
            break
        if kind == "symmetric":
            symmetric.append(data.as_expr())
            steps.append(f"symmetric zeros on the unit circle: H = {sp.sstr(data.as_expr())} "
                         f"(H(z^2) | a; {note}); b = a H(z)/H(z^2)")
        else:
            cycles.append(data)
            steps.append(f"blocking cycle of primitive {data}-th roots: Phi_{2 * data} | a; b = a/Phi_{2 * data}")
        q = q * fq
        cur = newp
    stable = not symmetric and not cycles
    b = LaurentSymbol(cur, a.start, a.params)
    qs = LaurentSymbol(q, 0, a.params)
    if stable:
        reason = "no symmetric zeros on the unit circle, no blocking cycle"
    else:
        parts = []
        if symmetric:
            parts.append("symmetric zeros on the unit circle (" + ", ".join(f"H = {sp.sstr(h)}" for h in symmetric) + ")")
        if cycles:
            parts.append("the blocking cycle(s) of primitive " + ", ".join(f"{n}-th" for n in cycles)
                         + " roots of unity (" + ", ".join(f"Phi_{2 * n} | a" for n in cycles) + ")")
        reason = "a(z) has " + " and ".join(parts)
    return Result(value=stable, status=CERTIFIED,
                  witness={"reason": reason, "symmetric_zeros_on_circle": symmetric, "blocking_cycles": cycles,
                           "reduced_mask": b, "q": qs, "steps": steps, "notes": notes},
                  provenance={"method": "Jia-Wang criterion: gcd(a(z), a(-z)) = H(z^2), Cayley transform "
                                        "+ Sturm for zeros of H on |z| = 1; Phi_{2n} | a for blocking cycles",
                              "arithmetic": f"exact over {dom}"})


def _stable_shifts_balls(scheme: Any, *, sum_rules: int | None = None, prec: int | None = None) -> Result:
    """Ball masks: certified stable when every root of ``a/(1+z)^N`` is certified off the circle."""
    import flint

    from .balls import ball_divide_by_one_plus_z

    balls, N, prec, source = ball_mask(scheme, sum_rules=sum_rules, prec=prec)
    for wp in (prec + 64, 2 * prec + 64, 4 * prec + 64):
        with flint.ctx.workprec(wp):
            if not sum(balls, flint.arb(0)).contains(2):
                raise AnalysisError("the balls contain no mask with a(1) = 2")
            c = ball_divide_by_one_plus_z(balls, N) if N > 0 else list(balls)
            while len(c) > 1 and c[-1].is_zero():
                c.pop()
            while len(c) > 1 and c[0].is_zero():
                c.pop(0)
            if len(c) == 1:
                roots = []
            else:
                if c[-1].contains(0) or c[0].contains(0):
                    continue
                try:
                    roots = flint.acb_poly([flint.acb(x) for x in c]).roots()
                except ValueError:
                    continue
            off = all((abs(r) > 1) or (abs(r) < 1) for r in roots)
            if off:
                return Result(value=True, status=CERTIFIED,
                              witness={"reason": f"every zero of a/(1+z)^{N} is certified off the unit circle "
                                                 f"({len(roots)} isolated root balls): the only zeros on the circle "
                                                 "are at -1, so no symmetric zeros on the circle and no blocking cycle",
                                       "symmetric_zeros_on_circle": [], "blocking_cycles": [],
                                       "reduced_mask": None, "q": None,
                                       "min_distance_to_circle": min((float(abs(abs(r) - 1).lower()) for r in roots),
                                                                     default=None)},
                              provenance={"method": "Arb root isolation of the mask quotient", "source": source,
                                          "prec": wp})
    return Result(value=None, status=INCONCLUSIVE,
                  witness={"reason": f"the zeros of a/(1+z)^{N} could not all be certified off the unit circle "
                                     "(ball masks cannot decide exact zeros on the circle)"},
                  provenance={"method": "Arb root isolation of the mask quotient", "source": source})


def ball_mask(scheme: Any, *, sum_rules: int | None = None, prec: int | None = None):
    """``(balls, N, prec, source)`` for a catalogue entry with ``enclosure`` or a list of arb balls."""
    import flint

    if hasattr(scheme, "enclosure") and callable(scheme.enclosure):
        N = sum_rules if sum_rules is not None else getattr(scheme, "sum_rules", None)
        if N is None:
            raise AnalysisError(f"{getattr(scheme, 'slug', scheme)!r}: the sum rule order is not known; pass sum_rules=N")
        prec = prec if prec is not None else 128 + 4 * N
        return list(scheme.enclosure(prec)), N, prec, f"catalogue entry {getattr(scheme, 'slug', '?')!r}, enclosure({prec})"
    if isinstance(scheme, (list, tuple)):
        if sum_rules is None:
            raise AnalysisError("a ball mask needs sum_rules=N (the number of factors (1+z) of the true mask)")
        if not all(isinstance(b, flint.arb) for b in scheme):
            raise AnalysisError("expected a list of flint.arb balls")
        prec = prec if prec is not None else 128 + 4 * sum_rules
        return list(scheme), sum_rules, prec, "balls"
    raise AnalysisError(f"expected a LaurentSymbol, a catalogue entry with enclosure(prec) or a list of arb balls, "
                        f"not {type(scheme).__name__}")


# --------------------------------------------------------------------------------------------
# arity m >= 3
# --------------------------------------------------------------------------------------------

def polyphase_gcd(p: sp.Poly, m: int) -> sp.Poly:
    """Monic ``H`` with ``H(z^m) = gcd_eps p(eps z)``: the gcd of the polyphase components of ``p``.

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import Z
    >>> polyphase_gcd(sp.Poly((1 + Z**3) * (1 + Z + Z**2), Z, domain=sp.QQ), 3).as_expr()
    w + 1
    """
    import sympy as sp

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


def _strip_roots_of_unity(p: sp.Poly, m: int) -> sp.Poly:
    """``p`` with every factor it shares with ``z^m - 1`` divided out (repeatedly)."""
    import sympy as sp

    from ..algebra.symbol import Z

    zm = sp.Poly(Z ** m - 1, Z, domain=p.domain)
    while True:
        g = p.gcd(zm)
        if g.degree() <= 0:
            return p
        p = sp.div(p, g)[0]


def _blocking_orders(p: sp.Poly, m: int):
    """``(n, [d ...])`` for the orders ``n > 1`` prime to ``m`` with ``Phi_{nd} | p`` for every divisor ``d > 1`` of
    ``m`` (rational ``p``; with multiplicity: an order is yielded once per complete set of factors).

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import Z
    >>> list(_blocking_orders(sp.Poly(1 + Z**2 + Z**4, Z, domain=sp.QQ), 3))
    [(2, [3])]
    """
    import sympy as sp

    from ..algebra.symbol import Z

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


def _stable_shifts_dilated(a: LaurentSymbol, m: int) -> Result:
    """:func:`stable_shifts` for arity ``m >= 3`` (module docstring, "Arity m >= 3"): ``value`` True / False
    (certified) or None (inconclusive, with ``witness["reason"]``); the witness carries ``reduced_mask`` ``b``
    (stable) and ``q`` with ``phi_a = q(tau) phi_b / q(1)``, ``a(z) q(z) = b(z) q(z^m)``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> _stable_shifts_dilated(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 3).value   # ternary linear B-spline
    True
    >>> r = _stable_shifts_dilated(LaurentSymbol.from_expr("(1+z**3+z**6)*(1+z+z**2)**2/9"), 3)
    >>> r.value, r.witness["q"], r.witness["reduced_mask"].expr().factor()    # phi_a = (1+tau+tau^2) phi_b/3
    (False, LaurentSymbol([1, 1, 1], start=0, domain=QQ), (z**2 + z + 1)**3/9)
    >>> r = _stable_shifts_dilated(LaurentSymbol.from_expr("1 + z**2 + z**4"), 3)   # box on [0, 2]: blocking cycle {pi}
    >>> r.value, r.witness["blocking_cycles"], r.witness["reduced_mask"].expr()
    (False, [2], z**2 + z + 1)
    """
    import sympy as sp

    from ..algebra.symbol import LaurentSymbol, Z

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
