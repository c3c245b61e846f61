"""Tuning a free weight of the centre's rule: the exact set of values for which Reif's eigen-conditions hold
at valence n.

A weight of the centre's rule (Loop's beta, Catmull–Clark's edge and face weights) enters only Fourier
block 0 (the centre meets no other block), so lambda (block 1) and every eigenvalue of the blocks k != 0 are
fixed; only the roots of block 0's polynomial ``P_0(lam, t)`` move with the free weight t. The truth of the
conditions can change only where a root of a t-dependent factor G of ``P_0`` reaches the circle
``|z| = lambda``; a real factor has a root there only if it has two roots with product lambda^2 (the root and
its conjugate), so every such t is a root of

    ``R_G(t) = Res_z(G(z, t), z^d G(lambda^2/z, t))``     (d = deg_z G),

a polynomial in t whose coefficients are polynomials in lambda and cos(2 pi/n), evaluated in Arb. Its real
roots (isolated by ``acb_poly.roots``, a root being real when its ball meets its conjugate ball and no other)
cut the line into open intervals on which the conditions cannot change; each is decided by the certified
analysis (:func:`.spectrum.analyse`) at one rational point inside. The result is the union of the intervals
where they hold, with exact endpoints where a root of ``R_G`` is a closed form (degree <= 2 in t with lambda
exact), else as Arb balls. At an endpoint itself the conditions are decided only when it is rational (there
an eigenvalue of modulus lambda makes them fail, unless the critical value came from two roots with product
lambda^2 that are not on the circle).

Examples
--------
>>> r = tune_centre("triangle", "b", "b", 5, ring=1)
>>> [(str(i["lower"]), str(i["upper"])) for i in r["intervals"] if i["holds"]]
[('1/16 - sqrt(5)/80', 'sqrt(5)/80 + 3/16')]

Algorithm
---------
1. ``P_0`` exactly (sympy, with t and ``C1 = cos(2 pi/n)`` symbols), factored over Q; the factors free of t
   are left to the sample analyses.
2. ``R_G`` for each factor G that has t and lambda (resultant in z, sympy), coefficients in t evaluated at
   lambda's isolating ball and cos(2 pi/n) in Arb; real roots isolated.
3. One rational sample per interval, the certified eigen-conditions there.

References
----------
U. Reif, A unified approach to subdivision algorithms near extraordinary vertices, CAGD 12 (1995); C. Loop
1987 and J. Warren, H. Weimer 2002 (beta_n and its admissible range).
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from ..result import AnalysisError
from .blocks import block_charpoly, c, fourier_block, lam
from .rules import C1, LocalRules, Term, free_weight, user_rules
from .spectrum import analyse, arb_value, exact_rational

#: at most this many critical values per valence
MAX_CRITICAL = 40


def substitute(rules: LocalRules, t: sp.Symbol, value: sp.Rational) -> LocalRules:
    """The rules with the free weight t set to ``value``."""
    new = tuple(tuple(Term(sp.expand(term.weight.subs(t, value)), term.source) for term in rule) for rule in rules.rules)
    return replace(rules, rules=new, source=rules.source + f", {t.name[5:]} = {value}")


def _arb_poly_in_t(expr: sp.Expr, t: sp.Symbol, x: sp.Symbol, lam_ball, n: int, prec: int):
    """The polynomial ``expr(x = lambda, t)`` in t with Arb coefficients (lambda and cos(2 pi/n) as balls)."""
    from flint import acb, acb_poly, arb, ctx, fmpq

    old = ctx.prec
    ctx.prec = prec
    try:
        c1 = arb.cos_pi_fmpq(fmpq(2, n))
        P = sp.Poly(expr, t)
        coeffs = []
        for (i,), co in sorted(P.terms()):
            val = arb(0)
            for (a, b), q in sp.Poly(co, x, C1).terms():
                q = sp.Rational(q)
                val += arb(int(q.p)) / int(q.q) * lam_ball ** a * c1 ** b
            coeffs.append((i, val))
        out = [arb(0)] * (P.degree() + 1)
        for i, v in coeffs:
            out[i] = v
        return acb_poly([acb(v) for v in out])
    finally:
        ctx.prec = old


def _real_roots(poly, prec: int):
    """Isolating balls of the real roots of an Arb polynomial (None if isolation fails)."""
    from flint import ctx

    old = ctx.prec
    ctx.prec = prec
    try:
        if poly.degree() < 1:
            return []
        roots = poly.roots(maxprec=4 * prec)
    except ValueError:
        return None
    finally:
        ctx.prec = old
    out = []
    for i, r in enumerate(roots):
        meets = [j for j, s in enumerate(roots) if r.conjugate().overlaps(s)]
        if meets == [i]:
            out.append(r.real)
    return out


def _closed_forms(expr: sp.Expr, t: sp.Symbol, x: sp.Symbol, lam_exact, n: int) -> list:
    """Roots in t of ``expr(x = lambda)`` as closed forms, when lambda is exact: of the whole polynomial when its
    degree in t is <= 2, of its factors of degree <= 2 over Q when its coefficients are rational."""
    if lam_exact is None:
        return []
    e = sp.expand(expr.subs({x: lam_exact, C1: sp.cos(2 * sp.pi / n)}))
    P = sp.Poly(e, t)
    if P.degree() < 1:
        return []
    if all(co.is_Rational for co in P.all_coeffs()):           # factors of degree <= 2 over Q, any degree
        factors = [f for f, _ in sp.factor_list(P)[1] if f.degree() <= 2]
    elif P.degree() <= 2:
        factors = [P]
    else:
        return []
    return [r if r.is_Rational else sp.sqrtdenest(sp.simplify(r)) for f in factors for r in sp.roots(f, multiple=True)]


def _sample_between(lo, hi) -> sp.Rational:
    """A simple rational strictly between two reals given as exact rationals (lo < hi)."""
    mid = (lo + hi) / 2
    for den in (1, 2, 4, 8, 10, 16, 32, 64, 100, 128, 1000, 1024, 10 ** 4, 2 ** 16):
        q = sp.Rational(round(mid * den), den)
        if lo < q < hi:
            return q
    return mid


def tune_centre(lattice: str, centre: str, name: str, n: int, *, ring: int = 2, prec: int = 128) -> dict:
    """The values of the free weight ``name`` in the centre's rule ``centre`` (as for :func:`user_rules`) for
    which Reif's eigen-conditions hold at valence n: a dict with the critical values and the intervals
    (``lower``, ``upper``: exact or float, ``holds``: bool or None, ``sample``, ``status``)."""
    rules = user_rules(lattice, centre, ring=ring, free=name)
    t = free_weight(name)
    if not any(term.weight.has(t) for term in rules.rules[0]):
        raise AnalysisError(f"the free weight {name} does not appear in --centre {centre!r}")
    rules.check_valence(n)
    x = sp.Symbol("x")
    P0 = sp.expand(block_charpoly(fourier_block(rules, 0, n)).subs(c, 1))
    if sp.expand(P0.subs(lam, 1)) != 0:
        raise AnalysisError("1 is not an eigenvalue of block 0 for every value: the rules are not affine invariant")
    base = analyse(substitute(rules, t, sp.Integer(0)), n, curvature=False)
    if base.lam is None or not base.lam.real:
        return {"n": n, "status": "inconclusive", "reason": "lambda (block 1) is not certified real", "intervals": []}
    lam_ball = base.lam.ball.real
    gens = [lam, t] + ([C1] if P0.has(C1) else [])
    critical, closed, reasons = [], [], []
    for G, _ in sp.factor_list(sp.Poly(P0, *gens, domain="QQ"))[1]:
        G = G.as_expr()
        if not (G.has(t) and G.has(lam)):
            continue
        z = sp.Symbol("z")
        Gz = sp.Poly(G.subs(lam, z), z)
        d = Gz.degree()
        mirror = sp.expand(z ** d * G.subs(lam, x ** 2 / z))
        R = sp.resultant(Gz.as_expr(), mirror, z) if d > 1 else sp.expand(mirror.subs(z, sp.solve(Gz.as_expr(), z)[0]))
        num, _ = sp.fraction(sp.together(sp.expand(R)))
        num = sp.expand(num)
        if num == 0:
            return {"n": n, "status": "inconclusive", "intervals": [],
                    "reason": f"factor {sp.sstr(G)} has two roots with product lambda^2 for every value"}
        sq = sp.Poly(num, t).sqf_part().as_expr() if num.has(t) else num
        poly = _arb_poly_in_t(sq, t, x, lam_ball, n, prec)
        roots = _real_roots(poly, prec)
        if roots is None:
            return {"n": n, "status": "inconclusive", "intervals": [],
                    "reason": f"the critical values of factor {sp.sstr(G)} could not be isolated at {prec} bits"}
        critical += roots
        closed += _closed_forms(sq, t, x, base.lam_exact, n)
        reasons.append(sp.sstr(G))
    if len(critical) > MAX_CRITICAL:
        raise AnalysisError(f"more than {MAX_CRITICAL} critical values at valence {n}")
    critical.sort(key=lambda b: float(b.mid()))
    for a, b in zip(critical, critical[1:]):
        if a.overlaps(b):
            return {"n": n, "status": "inconclusive", "intervals": [],
                    "reason": "two critical values are not separated at this precision"}
    ends = [(exact_rational(b.lower()), exact_rational(b.upper())) for b in critical]
    cuts = [None] + ends + [None]
    intervals = []
    for i in range(len(cuts) - 1):
        lo, hi = cuts[i], cuts[i + 1]
        if lo is None and hi is None:
            q = sp.Integer(0)
        elif lo is None:
            q = sp.floor(hi[0]) - 1
        elif hi is None:
            q = sp.ceiling(lo[1]) + 1
        else:
            q = _sample_between(lo[1], hi[0])
        a = analyse(substitute(rules, t, q), n, curvature=False)
        intervals.append({"lower": _endpoint(critical[i - 1], critical, closed, n) if lo is not None else "-oo",
                          "upper": _endpoint(critical[i], critical, closed, n) if hi is not None else "oo",
                          "sample": q, "holds": a.reif_ok if a.reif_status == "certified" else None,
                          "status": a.reif_status, "reason": a.reif_reason})
    points = []
    for b in critical:
        e = _endpoint(b, critical, closed, n)
        at = None
        if isinstance(e, sp.Basic) and e.is_Rational:
            a = analyse(substitute(rules, t, e), n, curvature=False)
            at = a.reif_ok if a.reif_status == "certified" else None
        points.append({"value": e, "holds": at})
    return {"n": n, "status": "certified" if all(i["holds"] is not None for i in intervals) else "inconclusive",
            "parameter": name, "lambda_ball": str(lam_ball), "factors": reasons,
            "critical": points, "intervals": intervals}


def _endpoint(ball, critical: list, closed: list, n: int):
    """The closed form among ``closed`` (roots of the same polynomial) that lies in ``ball`` and in no other
    critical ball (a rational: exactly; otherwise its Arb value), or the ball itself."""
    for r in closed:
        if r.is_Rational:
            if exact_rational(ball.lower()) <= r <= exact_rational(ball.upper()):
                return r
            continue
        v = arb_value(r, n, 256)
        if v is not None and v.overlaps(ball) and not any(v.overlaps(b) for b in critical if b is not ball):
            return r
    return ball
