"""The certified spectrum of the local subdivision matrix at valence n, Reif's eigen-conditions, and the
curvature behaviour read from the subsubdominant eigenvalue.

For each Fourier block k (:mod:`.blocks`) the characteristic polynomial ``P_k(lam)`` has coefficients in
``Q(cos(2 pi / n))``. Its exact factors (sympy, over Q with ``c`` and ``C1 = cos(2 pi/n)`` as
variables) are evaluated at ``c = cos(2 pi k / n)``:

* where both cosines are rational (n = 1, 2, 3, 4, 6 and their blocks) the factor is an integer
  polynomial and FLINT's ``complex_roots`` gives every root with its exact multiplicity (real roots with
  an exactly zero imaginary part);
* otherwise the coefficients are Arb balls and ``acb_poly.roots`` isolates the roots; success *proves*
  that the factor has ``deg`` simple roots, one in each ball; a factor that is squareful at this
  valence is retried at higher precision and then reported inconclusive.

The checks (Reif 1995; Peters–Reif 2008, ch. 5) are ball comparisons, never float comparisons:
1 is an eigenvalue of block 0 (exactly: ``P_0(1) = 0`` in ``Q(C1)``), simple; the subdominant
``lambda`` is the eigenvalue of block 1 of largest modulus, real (its isolating ball meets its
conjugate ball and no other), positive, simple in block 1 (hence double: blocks 1 and n - 1, and
semisimple: two Jordan blocks of size 1); every other eigenvalue has a modulus certified below lambda.
The subsubdominant ``mu`` (largest modulus after lambda) is compared with lambda^2 by balls, and an
equality is decided exactly when lambda is rational-linear in ``C1`` (Loop) or both are rational. The
exact value of lambda is a closed form accepted only when its Arb value meets lambda's isolating ball
and no other (a rational one: when the ball contains it). Unbounded and bounded curvature also need the
deciding eigenvalue's eigenfunction certified nonzero on the ring (Bézier ordinates of its segment
patches, rules on the 2-ring), and mu = lambda^2 semisimple (exact rank); otherwise the curvature is
inconclusive with the reason.

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> a = analyse(scheme_rules("loop", ring=2, n=5), 5)
>>> a.lam_exact, a.reif_ok, a.curvature, a.curvature_status
(sqrt(5)/16 + 5/16, True, 'bounded', 'certified')
>>> b = analyse(scheme_rules("loop", ring=1), 5)
>>> b.mu_vs_lam2, b.curvature, b.curvature_reason[:45]
('=', 'inconclusive', 'mu = lambda^2, but eigenfunctions on the ring')

References
----------
U. Reif, A unified approach to subdivision algorithms near extraordinary vertices, CAGD 12 (1995);
J. Peters, U. Reif, Subdivision Surfaces, Springer 2008, ch. 5 (spectral properties), ch. 7 (curvature);
F. Johansson, Arb: efficient arbitrary-precision midpoint-radius interval arithmetic, IEEE TC 2017.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import lru_cache

import sympy as sp

from .blocks import block_charpoly, c, cos_minimal_polynomial, fourier_block, lam, special_frequencies
from .exact_blocks import _exact_eigenspace
from .rules import C1, LocalRules, n_sym, regular_next_to_centre

PRECISIONS = (64, 128, 256, 512)


@dataclass
class Eigenvalue:
    """One eigenvalue: its ball, multiplicity (within its block), block k, and the exact factor of
    ``P_k`` it is a root of (a polynomial in lam, with c and C1 to be set to the cosines)."""

    ball: object          # flint.acb
    mult: int
    k: int
    factor: sp.Poly
    real: bool

    @property
    def modulus(self):
        return abs(self.ball)


@dataclass
class VertexAnalysis:
    n: int
    scheme: str
    eigenvalues: list[Eigenvalue]
    lam: Eigenvalue | None
    lam_exact: sp.Expr | None
    mu: Eigenvalue | None
    checks: dict = field(default_factory=dict)
    reif_ok: bool | None = None
    reif_status: str = "inconclusive"
    reif_reason: str = ""
    separation: object = None          # arb: lambda - max |other|
    curvature: str = "inconclusive"
    curvature_status: str = "inconclusive"
    mu_vs_lam2: str = "?"
    curvature_reason: str = ""
    curvature_final: bool = False      # inconclusive for a reason that more precision does not remove
    prec: int = 0
    notes: list = field(default_factory=list)
    #: eigenvalues of other blocks certified larger in modulus than block 1's leading one (then that one is
    #: not the subdominant eigenvalue), largest first
    above_lambda: list = field(default_factory=list)


# --------------------------------------------------------------------------------------------------

def _is_rational_cos(d: int) -> bool:
    return d in (1, 2, 3, 4, 6)


def _cos_value(k: int, n: int) -> sp.Rational | None:
    from math import gcd

    g = gcd(k, n)
    d = n // g
    if not _is_rational_cos(d):
        return None
    return {1: sp.Integer(1), 2: sp.Integer(-1), 3: sp.Rational(-1, 2), 4: sp.Integer(0), 6: sp.Rational(1, 2)}[d]


@lru_cache(maxsize=64)
def _generic_charpoly(rules: LocalRules) -> sp.Expr:
    k = max(special_frequencies(rules) | {0}) + 1
    return block_charpoly(fourier_block(rules, k, None))


def block_polynomials(rules: LocalRules, n: int) -> list[tuple[int, int, sp.Expr]]:
    """``(k, copies, P_k(lam, c, C1))`` for k = 0..floor(n/2): copies = 2 for blocks k and n-k."""
    rules.check_valence(n)
    special = {0} | {s % n for s in special_frequencies(rules)} | {(-s) % n for s in special_frequencies(rules)}
    gen = None
    out = []
    for k in range(n // 2 + 1):
        copies = 1 if (k == 0 or 2 * k == n) else 2
        if k in special or (n - k) % n in special:
            P = block_charpoly(fourier_block(rules, k, n))
        else:
            if gen is None:
                gen = sp.expand(_generic_charpoly(rules).subs(n_sym, n))
            P = gen
        if k == 0:
            P = sp.expand(P.subs(c, 1))
        out.append((k, copies, P))
    return out


@lru_cache(maxsize=4096)
def _factors(P: sp.Expr) -> tuple[tuple[sp.Poly, int], ...]:
    gens = [g for g in (lam, c, C1) if P.has(g)]
    if lam not in gens:
        gens.insert(0, lam)
    _, fl = sp.factor_list(sp.Poly(P, *gens, domain="QQ"))
    return tuple((f, e) for f, e in fl if f.degree(lam) > 0)


def _arb_value(expr: sp.Expr, ck, c1):
    """An Arb ball for a polynomial expression in c, C1 with rational coefficients."""
    from flint import arb

    poly = sp.Poly(expr, c, C1)
    total = arb(0)
    for (i, j), co in poly.terms():
        q = sp.Rational(co)
        total += arb(int(q.p)) / int(q.q) * ck ** i * c1 ** j
    return total


def _roots(F: sp.Poly, k: int, n: int, prec: int):
    """Isolated roots of the factor F(lam, c_k, C1) as (acb ball, multiplicity, real?) or None."""
    from flint import acb, acb_poly, arb, ctx, fmpq, fmpq_poly

    ck_q, c1_q = _cos_value(k, n), _cos_value(1, n)
    deg = F.degree(lam)
    coeffs = [sp.expand(F.as_expr()).coeff(lam, i) for i in range(deg + 1)]
    old = ctx.prec
    ctx.prec = prec
    try:
        free = F.free_symbols
        if (c not in free or ck_q is not None) and (C1 not in free or c1_q is not None):
            qs = [sp.Rational(co.subs({c: ck_q if ck_q is not None else 0, C1: c1_q if c1_q is not None else 0}))
                  for co in coeffs]
            fp = fmpq_poly([fmpq(int(q.p), int(q.q)) for q in qs])
            num = fp.numer()
            return [(r, m, r.imag.is_zero()) for r, m in num.complex_roots()]
        ck = arb.cos_pi_fmpq(fmpq(2 * k, n))
        c1 = arb.cos_pi_fmpq(fmpq(2, n))
        poly = acb_poly([acb(_arb_value(co, ck, c1)) for co in coeffs])
        try:
            roots = poly.roots(maxprec=prec * 2)
        except ValueError:
            return None
        out = []
        for i, r in enumerate(roots):
            cj = r.conjugate()
            meets = [j for j, s in enumerate(roots) if cj.overlaps(s)]
            out.append((r, 1, meets == [i]))
        return out
    finally:
        ctx.prec = old


def spectrum(rules: LocalRules, n: int, prec: int = 64) -> list[Eigenvalue] | None:
    """Every eigenvalue of the local matrix at valence n (blocks k <= n/2; block k != 0, n/2 stands for
    itself and its mirror n - k), or None if some factor could not be isolated at ``prec``."""
    out = []
    for k, copies, P in block_polynomials(rules, n):
        for F, e in _factors(P):
            rs = _roots(F, k, n, prec)
            if rs is None:
                return None
            for r, m, real in rs:
                out.append(Eigenvalue(r, m * e, k, F, real))
    return out


# --------------------------------------------------------------------------------------------------

def exact_rational(x) -> sp.Rational:
    """The exact rational value of an exact Arb number (an endpoint or midpoint: a binary float)."""
    man, exp = x.mid().man_exp()
    return sp.Integer(int(man)) * sp.Integer(2) ** int(exp)


def _ball_has_rational(ball, q: sp.Rational) -> bool:
    """Does the complex ball contain the rational q? (exact comparison with the ball's endpoints)"""
    return bool(ball.imag.contains(0) and exact_rational(ball.real.lower()) <= q <= exact_rational(ball.real.upper()))


def _exact_root(F: sp.Poly, ball, n: int, k: int, siblings: list, prec: int = 128):
    """The root of F(lam, cos(2 pi k/n)) in ``ball`` as a radical expression when deg F <= 2 (or when the
    cosines are rational and the root is one of a factor of degree <= 2 over Q), or None.

    ``siblings`` are the isolating balls of all roots of F in block k (one root in each). A rational
    root is accepted only if ``ball`` contains it exactly. Any other root expression is evaluated in Arb
    (:func:`arb_value`, refined up to 4 ``prec``) and accepted only if its enclosure meets
    ``ball`` and no other isolating ball: the root it denotes is then the one in ``ball``.
    """
    from flint import acb


    ck = sp.cos(2 * sp.pi * k / n)
    P = sp.Poly(F.as_expr().subs({c: ck, C1: sp.cos(2 * sp.pi / n)}), lam)
    if F.degree(lam) <= 2:
        candidates = sp.roots(P, multiple=True)
    elif all(co.is_Rational for co in P.all_coeffs()):       # rational cosines: factors of degree <= 2 over Q
        candidates = [r for f, _ in sp.factor_list(P)[1] if f.degree() <= 2 for r in sp.roots(f, multiple=True)]
    else:
        return None
    for r in candidates:
        if r.is_Rational:
            if _ball_has_rational(ball, r):
                return r
            continue
        value = sp.simplify(r)
        for bits in (prec, 2 * prec, 4 * prec):
            enc = arb_value(value, n, bits)
            if enc is None:
                break
            meets = [s for s in siblings if s.overlaps(acb(enc))]
            if not any(s is ball for s in meets):
                break
            if len(meets) == 1:
                return value
    return None


def _lambda_in_c1(lam_e: Eigenvalue, lam_exact: sp.Expr | None) -> sp.Expr | None:
    """lambda as a polynomial in C1 = cos(2 pi/n), when it is one: rational, or the root of a factor of
    block 1 that is linear in lam (c = C1 in block 1)."""
    if lam_exact is not None and lam_exact.is_Rational:
        return lam_exact
    lin = sp.Poly(lam_e.factor.as_expr().subs(c, C1), lam)
    if lin.degree() != 1:
        return None
    a1, a0 = lin.all_coeffs()
    return sp.expand(-a0 / a1)


def _equal_exact(mu: Eigenvalue, lam_e: Eigenvalue, lam_exact: sp.Expr | None, n: int, sign: int,
                 eigenvalues: list[Eigenvalue], power: int = 2) -> bool | None:
    """Is ``mu = sign * lambda^power``? Decided exactly when lambda is a polynomial in C1 (or rational):
    ``F_mu(sign lambda^power)`` reduced modulo the minimal polynomial of cos(2 pi/n) is zero (so it is a
    root of mu's factor at c = cos(2 pi k/n)), and its ball meets mu's isolating ball and no other
    isolating ball of that factor's roots. False: certainly not equal. None: not decided."""
    lam_c1 = _lambda_in_c1(lam_e, lam_exact)
    if lam_c1 is None:
        return None
    target = sp.expand(sign * lam_c1 ** power)
    val = sp.expand(mu.factor.as_expr().subs(c, sp.chebyshevt(mu.k, C1)).subs(lam, target))
    num, _ = sp.fraction(sp.together(val))
    if not sp.Poly(num, C1, domain="QQ").rem(cos_minimal_polynomial(n)).is_zero:
        return False
    ball = lam_e.ball ** power * sign
    siblings = [e for e in eigenvalues if e.k == mu.k and e.factor == mu.factor]
    meets = [e for e in siblings if e.ball.overlaps(ball)]
    return True if meets == [mu] else None


def analyse(rules: LocalRules, n: int, *, max_prec: int = 512, curvature: bool = True) -> VertexAnalysis:
    """The certified eigen-structure at valence n (see the module docstring), at the first precision of
    :data:`PRECISIONS` (up to ``max_prec`` bits) where everything is decided (``curvature=False``: the
    eigen-conditions only, the curvature left undecided).

    Computed once per process for the same rules, valence, options and working precision (the claims, the
    command line and the C^1 tests ask for the same valences again); each caller gets its own copy of the
    lists and dicts of the result."""
    from flint import ctx

    try:
        hash(rules)
    except TypeError:                            # rules holding a mutable part: computed, not remembered
        return _analyse.__wrapped__(rules, n, max_prec, curvature, ctx.prec)
    a = _analyse(rules, n, max_prec, curvature, ctx.prec)
    return replace(a, eigenvalues=list(a.eigenvalues), checks=dict(a.checks), notes=list(a.notes),
                   above_lambda=list(a.above_lambda))


@lru_cache(maxsize=128, typed=True)
def _analyse(rules: LocalRules, n: int, max_prec: int, curvature: bool, working_prec: int) -> VertexAnalysis:
    """:func:`analyse`, computed (``working_prec``: Arb's working precision of the caller, which the few
    comparisons made outside the precision loop use)."""
    eig, res = None, None
    for prec in PRECISIONS:
        if prec > max_prec:
            break
        eig = spectrum(rules, n, prec)
        if eig is None:
            continue
        res = _check(rules, n, eig, prec, curvature)
        if res.reif_status != "inconclusive" and (not curvature or res.curvature_status != "inconclusive"
                                                  or res.curvature_final):
            return res
    if res is None:
        a = VertexAnalysis(n, rules.name, [], None, None, None, prec=max_prec)
        a.reif_reason = f"a block's characteristic polynomial could not be isolated at {max_prec} bits"
        return a
    return res


def _check(rules: LocalRules, n: int, eig: list[Eigenvalue], prec: int, curvature: bool = True) -> VertexAnalysis:
    from flint import arb

    a = VertexAnalysis(n, rules.name, eig, None, None, None, prec=prec)
    one = [e for e in eig if e.k == 0 and e.real and e.ball.real.contains(1)]
    P0 = dict((k, P) for k, _, P in block_polynomials(rules, n))[0]
    p0_at_1 = sp.expand(P0.subs(lam, 1))
    if p0_at_1.has(C1):
        num, _ = sp.fraction(sp.together(p0_at_1))
        one_exact = sp.Poly(num, C1, domain="QQ").rem(cos_minimal_polynomial(n)).is_zero
    else:
        one_exact = p0_at_1 == 0
    a.checks["1 eigenvalue of block 0 (exact)"] = bool(one_exact)
    a.checks["1 simple"] = one_exact and len(one) == 1 and one[0].mult == 1
    b1 = [e for e in eig if e.k == 1]
    if not b1:
        a.reif_reason = "no block 1"
        return a
    top = max(b1, key=lambda e: e.modulus.upper())
    a.lam = top
    others = [e for e in eig if e is not top and not (one and e is one[0])]
    a.separation = top.modulus - max(((e.modulus for e in others)), key=lambda m: m.upper(), default=arb(0))
    real = top.real
    positive = real and top.ball.real > 0
    simple = top.mult == 1
    dominated = all(e.modulus < top.modulus for e in others)
    below_one = top.modulus < 1
    a.above_lambda = sorted((e for e in others if e.modulus > top.modulus), key=lambda e: -float(e.modulus.lower()))
    a.checks.update({"lambda real": bool(real), "lambda > 0": bool(positive), "lambda < 1": bool(below_one),
                     "lambda simple in block 1 (double: blocks 1, n-1; semisimple)": bool(simple),
                     "others < lambda in modulus": bool(dominated)})
    if all(a.checks.values()):
        a.reif_ok, a.reif_status = True, "certified"
    else:
        failed = [k for k, v in a.checks.items() if not v]
        # a failure is certified when the ball comparison that failed is decided the other way
        bigger, tie = [e for e in others if e.modulus > top.modulus], None
        if bigger:
            e = bigger[0]
            a.reif_ok, a.reif_status = False, "certified"
            a.reif_reason = (f"an eigenvalue of block {e.k} ({_fmt(e.ball)}) exceeds block 1's leading "
                             f"eigenvalue ({_fmt(top.ball)}) in modulus")
        elif (tie := _tie_with_lambda(a, top, others, n)) is not None:
            a.reif_ok, a.reif_status = False, "certified"
            a.reif_reason = tie
        elif top.mult > 1:
            a.reif_ok, a.reif_status = False, "certified"
            a.reif_reason = (f"lambda is a root of multiplicity {top.mult} of block 1 (exact), so its multiplicity "
                             f"is {2 * top.mult} (blocks 1 and n - 1), not 2")
        elif top.real is True and top.ball.real < 0:
            a.reif_ok, a.reif_status = False, "certified"
            a.reif_reason = "the subdominant eigenvalue is negative"
        elif _certainly_nonreal(top.ball):
            a.reif_ok, a.reif_status = False, "certified"
            a.reif_reason = "the subdominant eigenvalue is not real"
        else:
            a.reif_reason = "not decided at " + str(prec) + " bits: " + ", ".join(failed)
        if not dominated and not bigger and tie is None:    # not proven either way: no false that was not proven
            a.checks["others < lambda in modulus"] = None
    a.lam_exact = _exact_root(top.factor, top.ball, n, 1, _siblings(eig, top))
    if curvature:
        _curvature(rules, a, others, n)
    return a


def subdominant(a: VertexAnalysis) -> tuple[Eigenvalue | None, str]:
    """The subdominant eigenvalue over *all* blocks when another block's eigenvalue is certified larger in
    modulus than block 1's leading one (``a.above_lambda``): the one of largest modulus, returned when its
    modulus is certified below 1 and above every other eigenvalue's (but block 0's eigenvalue 1);
    otherwise None and why. (When no block dominates block 1, ``a.lam`` is the subdominant eigenvalue.)

    Examples
    --------
    >>> from analysis.vertex.rules import user_rules
    >>> a = analyse(user_rules("triangle", "0", None, ring=2), 3, curvature=False)
    >>> e, _ = subdominant(a)
    >>> e.k, float(e.ball.real.mid())
    (0, 0.625)
    """
    if not a.above_lambda:
        return None, "no block's eigenvalue exceeds block 1's leading eigenvalue"
    top = max(a.above_lambda, key=lambda e: float(e.modulus.lower()))
    one = [e for e in a.eigenvalues if e.k == 0 and e.real and e.ball.real.contains(1)]
    rest = [e for e in a.eigenvalues if e is not top and not (one and e is one[0])]
    if not top.modulus < 1:
        return None, (f"block {top.k}'s eigenvalue {_fmt(top.ball)} exceeds block 1's leading eigenvalue and is "
                      "not certified below 1 in modulus")
    if not all(e.modulus < top.modulus for e in rest):
        return None, (f"block {top.k}'s eigenvalue {_fmt(top.ball)} exceeds block 1's leading eigenvalue, but "
                      "another eigenvalue is not certified below it in modulus")
    return top, f"block {top.k}'s eigenvalue {_fmt(top.ball)} (certified: every other eigenvalue but 1 is smaller)"


def _tie_with_lambda(a: VertexAnalysis, top: Eigenvalue, others: list[Eigenvalue], n: int) -> str | None:
    """An eigenvalue other than lambda (and its mirror) proven equal to +-lambda: lambda is then not a
    double, strictly dominant eigenvalue. (Exact test as for mu = lambda^2.)"""
    if not (top.real and top.ball.real > 0):
        return None
    lam_exact = _exact_root(top.factor, top.ball, n, 1, _siblings(a.eigenvalues, top))
    for e in others:
        if e.modulus < top.modulus or not e.real:
            continue
        sign = 1 if e.ball.real > 0 else (-1 if e.ball.real < 0 else 0)
        if sign and (_equal_exact(e, top, lam_exact, n, sign, a.eigenvalues, power=1)
                     or _common_root(e, top, n, sign, a.eigenvalues, a.prec)):
            return (f"an eigenvalue of block {e.k} equals {'-' if sign < 0 else ''}lambda exactly "
                    f"({'lambda is not double' if sign > 0 else 'not strictly below lambda in modulus'})")
    return None


def _common_root(e: Eigenvalue, top: Eigenvalue, n: int, sign: int, eigenvalues: list[Eigenvalue],
                 prec: int) -> bool:
    """Is ``e = sign * top``, proven through a common factor? (Any algebraic lambda, e.g. sqrt(2)/8 + 1/4,
    shared by three blocks of the butterfly with tension 1/32 at n = 3.)

    Algorithm: G = gcd(F_top(lam), F_e(sign lam)) over Q(cos(2 pi/n)) (sympy; each factor at its block's
    cosine); G's roots isolated and refined in Arb (G divides a squarefree factor). Each root r of F_top
    lies in one of the isolating balls of F_top's roots, so a root ball of G meeting top's ball and no
    other of them holds top; if it also meets ``sign * e``'s ball and no other ``sign *`` ball of F_e's
    roots, that root is also sign * e. False when not proven.

    >>> from analysis.vertex.rules import scheme_rules
    >>> a = analyse(scheme_rules("butterfly", 3, 3, sp.Rational(1, 32)), 3, curvature=False)
    >>> a.reif_ok, a.reif_status, a.reif_reason
    (False, 'certified', 'an eigenvalue of block 0 equals lambda exactly (lambda is not double)')
    """
    from flint import acb, acb_poly, arb, ctx

    cos1 = sp.cos(2 * sp.pi / n)

    def at_valence(f: Eigenvalue, s: int) -> sp.Expr:
        return sp.expand(f.factor.as_expr().subs(c, sp.chebyshevt(f.k, C1)).subs(C1, cos1).subs(lam, s * lam))

    ft, fe = at_valence(top, 1), at_valence(e, sign)
    rational = _cos_value(1, n) is not None
    try:
        dom = sp.QQ if rational else sp.QQ.algebraic_field(cos1)
        G = sp.Poly(ft, lam, domain=dom).gcd(sp.Poly(fe, lam, domain=dom))
    except (sp.PolificationFailed, sp.CoercionFailed, sp.GeneratorsNeeded, NotImplementedError):
        return False
    if G.degree() < 1:
        return False
    old = ctx.prec
    ctx.prec = max(prec, 128)
    try:
        coeffs = []
        for q in reversed(G.all_coeffs()):
            v = arb_value(q, n, ctx.prec)            # all_coeffs: sympy numbers in cos(2 pi/n)
            if v is None:
                return False
            coeffs.append(acb(v))
        try:
            roots = acb_poly(coeffs).roots(tol=arb(2) ** (-ctx.prec // 2), maxprec=4 * ctx.prec)
        except ValueError:
            return False
        tops, es = _siblings(eigenvalues, top), [b * sign for b in _siblings(eigenvalues, e)]

        def only(r, ball, balls) -> bool:
            return r.overlaps(ball) and sum(1 for b in balls if r.overlaps(b)) == 1

        return any(only(r, top.ball, tops) and only(r, e.ball * sign, es) for r in roots)
    finally:
        ctx.prec = old


def _siblings(eig: list[Eigenvalue], e: Eigenvalue) -> list:
    """The isolating balls of the roots of e's factor in e's block."""
    return [x.ball for x in eig if x.k == e.k and x.factor == e.factor]


def _certainly_nonreal(ball) -> bool:
    return not ball.imag.contains(0)


def _fmt(ball) -> str:
    x = complex(ball.mid())
    return f"{x.real:.6g}" if ball.imag.contains(0) else f"{x.real:.6g}{x.imag:+.6g}i"


def _curvature(rules: LocalRules, a: VertexAnalysis, others: list[Eigenvalue], n: int) -> None:
    """mu (the largest modulus after lambda) against lambda^2.

    Zero curvature (every other eigenvalue below lambda^2) needs nothing more. Unbounded and bounded
    curvature rest on the eigenvalue that decides them (Peters–Reif 2008, ch. 7): its eigenfunction must
    be nonzero on the ring (some Bézier ordinate of the segment patches excludes 0, :func:`_nonzero_on_ring`),
    and for mu = lambda^2 the eigenvalue must be semisimple (a Jordan block makes the curvature grow like
    m on the m-th ring): rank(B_k - lambda^2 I) = size - multiplicity, exactly over Q(exp(2 pi i/n))."""
    top = a.lam
    rest = [e for e in others if not (e.k == 1 and e.factor == top.factor and e.ball.overlaps(top.ball))]
    if not rest or not a.reif_ok:
        return
    mu = max(rest, key=lambda e: e.modulus.upper())
    a.mu = mu
    lam2 = top.ball.real * top.ball.real
    if all(e.modulus < lam2 for e in rest):
        a.mu_vs_lam2 = "<"
        if rules.ring < 2 and rules.lattice in ("quad", "triangle"):
            _inconclusive(a, ONE_RING_ZERO, final=True)
            return
        a.curvature, a.curvature_status = "zero", "certified"
        return
    big = [e for e in rest if e.modulus > lam2]
    if big:
        a.mu = max(big, key=lambda e: e.modulus.lower())
        a.mu_vs_lam2 = ">"
        if not _ring_evaluated(rules):
            _inconclusive(a, f"mu > lambda^2, but {_ring_not_evaluated(rules)}", final=True)
            return
        for e in sorted(big, key=lambda e: -float(e.modulus.lower())):
            vecs = _arb_eigenvectors(rules, n, e)
            ok, why = _nonzero_on_ring(rules, n, e, vecs, a.prec)
            if ok:
                a.mu, a.curvature, a.curvature_status = e, "unbounded", "certified"
                a.notes.append(why)
                return
        _inconclusive(a, f"mu > lambda^2, but {why}", final=True)
        return
    tied = [e for e in rest if not (e.modulus < lam2)]
    verdicts, signs = [], []
    for e in tied:
        sign = (1 if e.ball.real > 0 else (-1 if e.ball.real < 0 else 0)) if e.real else 0
        signs.append(sign)
        verdicts.append(_equal_exact(e, top, a.lam_exact, n, sign, a.eigenvalues) if sign else None)
    if any(v is False for v in verdicts):
        _inconclusive(a, "mu != lambda^2 (exact) but not yet separated by the balls")
        return
    if not all(v is True for v in verdicts):
        _inconclusive(a, "mu and lambda^2 not separated by the balls and not decided exactly "
                         "(exact equality is decided when lambda is a polynomial in cos(2 pi/n))")
        return
    a.mu, a.mu_vs_lam2 = tied[0], "="
    if not _ring_evaluated(rules):
        _inconclusive(a, f"mu = lambda^2, but {_ring_not_evaluated(rules)}", final=True)
        return
    lam_c1 = _lambda_in_c1(top, a.lam_exact)
    groups: dict = {}
    for e, sign in zip(tied, signs):
        groups.setdefault((e.k, sign), []).append(e)
    nonzero = None
    for (k, sign), es in sorted(groups.items()):
        mult = sum(e.mult for e in es)
        got = _exact_eigenspace(rules, n, k, sp.expand(sign * lam_c1 ** 2))
        if got is None:
            _inconclusive(a, f"mu = lambda^2 in block {k}, but its semisimplicity could not be decided exactly",
                          final=True)
            return
        size, basis = got
        if size - len(basis) != size - mult:
            _inconclusive(a, f"mu = lambda^2 is not semisimple in block {k} (eigenspace of dimension {len(basis)}, "
                             f"multiplicity {mult}): a Jordan block, curvature not bounded by this criterion",
                          final=True)
            return
        a.notes.append(f"mu = lambda^2 semisimple in block {k}: rank(B_{k} - mu I) = {size - mult} "
                       f"= size {size} - multiplicity {mult} (exact)")
        if nonzero is None:
            ok, why = _nonzero_on_ring(rules, n, es[0], basis, a.prec)
            if ok:
                nonzero = why
    if nonzero is None:
        _inconclusive(a, f"mu = lambda^2, but {why}", final=True)
        return
    a.notes.append(nonzero)
    a.curvature, a.curvature_status = "bounded", "certified"


#: why "zero" curvature is not certified from the 1-ring's matrix
ONE_RING_ZERO = ("mu < lambda^2 on the 1-ring, but the 1-ring's matrix lacks eigenvalues of the 2-ring that can "
                 "exceed lambda^2: run with the default 2-ring (omit --ring 1)")


RING_NOT_EVALUATED = ("eigenfunctions on the ring are evaluated only for Loop- and Catmull-Clark-type rules "
                      "(box-spline patches) on the 2-ring (--ring 2)")


def _ring_not_evaluated(rules: LocalRules) -> str:
    """Why eigenfunctions on the ring are not evaluated for these rules."""
    if rules.lattice == "sqrt3":
        return "eigenfunctions on the ring are not evaluated for sqrt(3) (no patch form)"
    if rules.ring == 2 and rules.lattice in ("quad", "triangle"):
        return ("eigenfunctions on the ring are not evaluated: the new points next to the centre are not made by "
                "the regular stencils (e.g. a given --edge rule), so the segment is not a box-spline patch")
    return RING_NOT_EVALUATED


def _ring_evaluated(rules: LocalRules) -> bool:
    """Whether eigenfunctions on the ring are evaluated for these rules (segment patches as in :mod:`.charmap`:
    the 2-ring, regular stencils everywhere but at the centre)."""
    return rules.ring == 2 and rules.lattice in ("quad", "triangle") and regular_next_to_centre(rules)


def _inconclusive(a: VertexAnalysis, reason: str, final: bool = False) -> None:
    a.curvature, a.curvature_status, a.curvature_reason = "inconclusive", "inconclusive", reason
    a.curvature_final = final
    a.notes.append(reason)


def _arb_eigenvectors(rules: LocalRules, n: int, e: Eigenvalue) -> list:
    """An Arb eigenvector of block e.k for e (geometrically simple), or none."""
    from flint import ctx

    from ..result import AnalysisError
    from .charmap import eigenvector

    old = ctx.prec
    ctx.prec = max(old, 128)
    try:
        return [eigenvector(rules, n, e.ball, e.k)]
    except AnalysisError:
        return []
    finally:
        ctx.prec = old


def _nonzero_on_ring(rules: LocalRules, n: int, e: Eigenvalue, vectors: list, prec: int) -> tuple[bool, str]:
    """Is some eigenfunction (one of ``vectors``, eigenvectors of block e.k for e) nonzero on the ring?
    Certified when a Bézier ordinate of its segment patches (:func:`.charmap.segment_ordinates`) excludes 0.
    Returns (certified?, what was shown or why not)."""
    from flint import ctx

    from .charmap import segment_ordinates

    if not _ring_evaluated(rules):
        return False, _ring_not_evaluated(rules)
    if not vectors:
        return False, f"no eigenvector of block {e.k} could be enclosed"
    old = ctx.prec
    ctx.prec = max(prec, 128)
    try:
        for v in vectors:
            ords = segment_ordinates(rules, n, v, e.ball, e.k)
            good = [x for x in ords if not (x.real.contains(0) and x.imag.contains(0))]
            if good:
                big = max(good, key=lambda x: float(abs(x).lower()))
                return True, (f"eigenfunction of block {e.k} nonzero on the ring: a Bézier ordinate of its segment "
                              f"patches has modulus >= {float(abs(big).lower()):.3g} (eigenvector normalised to 1)")
        return False, f"no Bézier ordinate of the eigenfunctions of block {e.k} on the ring is certified nonzero"
    finally:
        ctx.prec = old


def arb_value(expr: sp.Expr, n: int, prec: int = 128):
    """An Arb ball for an expression in c = cos(2 pi/n) and n (and what
    :func:`analysis.jsr._exact.sympy_to_arb` encloses: rationals, + * /, powers, pi, elementary functions);
    None if it has anything else (or a root of a ball that may be negative)."""
    from flint import arb, ctx, fmpq

    from ..jsr._exact import NoEnclosure, sympy_to_arb

    old = ctx.prec
    ctx.prec = prec
    try:
        cval = arb.cos_pi_fmpq(fmpq(2, n))
        return sympy_to_arb(expr, {c: cval, C1: cval, n_sym: arb(n)})
    except (NoEnclosure, ValueError, ZeroDivisionError):
        return None
    finally:
        ctx.prec = old
