"""The smoothest member of a one-parameter family: the maximiser of the Hölder exponent, with a certified gap.

For a family ``a(t)``, ``t`` in a box ``[lo, hi]``, :func:`maximize_holder` returns a rational
``t*``, the certified enclosure of ``alpha(t*)`` (:func:`analysis.regularity.holder_exponent`)
and a certified **upper** bound of ``alpha`` over the whole box; the difference is the certified
gap: no member of the family is smoother than ``alpha(t*)`` by more than the gap.

Examples
--------
The 4-point family ``(-w, 0, 1/2+w, 1, 1/2+w, 0, -w)`` on ``[0, 1/8]`` is smoothest at the
Dubuc–Deslauriers scheme ``w = 1/16`` (``alpha = 2``, exact; Daubechies–Lagarias 1992):

>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> w = sp.Symbol("w")
>>> a = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
>>> r = maximize_holder(a, within=(0, sp.Rational(1, 8)), gap=sp.Rational(1, 100))
>>> r.value, r.witness["alpha_at"].value, r.status, r.witness["gap"] <= sp.Rational(1, 100)
(1/16, 2, 'certified', True)

Algorithm
---------
With ``N`` the generic number of factors ``(1+z)``, ``k = N - 1`` and ``c(t) = 2^k a(t)/(1+z)^N``
(coefficients polynomials in ``t``), ``alpha(t) = k - log2 JSR(T_0(t), T_1(t))`` (DESIGN.md).

1. *Search* (floats): on a grid and then by golden-section refinement, ``alpha`` is estimated by
   ``k - max_{|w| <= L} log2 rho(T_w)/|w|``; the maximiser is rounded to a nearby rational ``t*``.
2. *At t\\**: :func:`~analysis.regularity.holder.holder_exponent` gives a certified enclosure.
3. *Upper bound on the box* (branch and bound): on a sub-interval ``I`` the transition
   matrices are enclosed by Arb ball matrices (the coefficients of ``c`` evaluated on the ball
   ``I``); for each candidate word ``w`` (the float search's spectrum-maximising products) the
   eigenvalues of the ball product ``T_w(I)`` are enclosed (``acb_mat.eig``, valid for every
   matrix in the balls), or, for a real dominant eigenvalue, an exact sign change of the
   characteristic polynomial ``det(x I - T_w(t))`` (polynomial in ``t``, Taylor-bounded on
   ``I``) between ``x = +-r`` and infinity, so ``min_{t in I} rho(T_w(t)) >= r_w`` and, since
   ``rho(T_w)^(1/|w|) <= JSR``, ``alpha(t) <= k - log2(r_w)/|w|`` on ``I``. Intervals whose bound
   exceeds ``alpha_lower(t*) + gap`` are bisected (down to ``min_width``). At the exceptional
   parameters in the box (more factors ``(1+z)``, where the generic formula may underestimate
   ``alpha``) ``holder_exponent`` is called exactly and its upper bound joins the maximum.

The result is certified when every step is; a sub-interval that could not be bounded (ball
eigenvalues failed at ``min_width``) makes it inconclusive with the reason. More than one free
parameter is *inconclusive* ("family too large": the box search is one-dimensional).

References
----------
O. Rioul, *Simple regularity criteria for subdivision schemes*, SIAM J. Math. Anal. 23 (1992).
I. Daubechies, J. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23 (1992).
F. Johansson, *Arb: efficient arbitrary-precision midpoint-radius interval arithmetic*, IEEE
Trans. Comput. 66 (2017) (ball eigenvalue enclosures, ``acb_mat_eig_multiple``).
"""

from __future__ import annotations

import math
import time
from fractions import Fraction

import numpy as np
import sympy as sp

from ..algebra.factorization import factor_out, smoothing_factor
from ..algebra.symbol import LaurentSymbol
from .. import progress
from ..jsr._work import Work
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..algebra.reader import as_expr
from .balls import ball_transition_matrices
from .holder import holder_exponent

__all__ = ["maximize_holder"]

#: work units of the maximisation (about a millisecond each on the reference machine): a float
#: alpha estimate at a point (all products up to ``max_length``), and one certified bound on a
#: sub-interval per candidate word (Arb eigenvalue enclosure); the certified alpha at ``t*`` and
#: at the exceptional parameters are charged what :func:`holder_exponent` spent
FLOAT_ALPHA_UNITS = 6
BOUND_UNITS_PER_WORD = 2


class _Family:
    """``c(t)``'s coefficients as polynomials in ``t``, evaluated in floats or on Arb balls."""

    def __init__(self, a: LaurentSymbol, p: sp.Symbol):
        f = smoothing_factor(a)
        self.N = f.value
        if self.N < 1:
            raise AnalysisError("the family does not satisfy a(-1) = 0 identically: not convergent generically")
        self.k = self.N - 1
        c = factor_out(a, self.N) / 2
        self.polys = [sp.Poly(sp.expand(x), p) for x in c.mask]
        self.float_coeffs = [[float(v) for v in q.all_coeffs()] for q in self.polys]
        # the exact coefficients (highest first) as (numerator, denominator), converted once for the balls
        self._qcoeffs = [[(int(sp.Rational(v).p), int(sp.Rational(v).q)) for v in q.all_coeffs()] for q in self.polys]
        self.exceptional = f.witness["exceptional"]
        self.p = p
        self._K = sp.QQ[p]
        self._charpolys: dict = {}

    def charpoly(self, word):
        """``det(x I - T_w(t))`` exactly: a list of coefficients (highest first), each a Poly in ``t``."""
        if word not in self._charpolys:
            from sympy.polys.matrices import DomainMatrix

            K = self._K
            c = [K.from_sympy(q.as_expr()) for q in self.polys]
            n = max(len(c) - 1, 1)

            def T(eps):
                return DomainMatrix([[c[2 * i - j + eps] if 0 <= 2 * i - j + eps < len(c) else K.zero
                                      for j in range(n)] for i in range(n)], (n, n), K)

            M = (T(0), T(1))
            P = M[word[0]]
            for e in word[1:]:
                P = M[e] * P
            self._charpolys[word] = [_fmpq_poly(sp.Poly(K.to_sympy(x), self.p)) for x in P.charpoly()]
        return self._charpolys[word]

    def floats(self, t: float):
        c = [np.polyval(q, t) for q in self.float_coeffs]
        T0, T1 = ball_transition_matrices(c)
        return np.array(T0, dtype=float), np.array(T1, dtype=float)

    def balls(self, lo: sp.Rational, hi: sp.Rational, prec: int = 128):
        import flint

        old = flint.ctx.prec
        flint.ctx.prec = prec
        try:
            x = flint.arb(flint.fmpq(int(lo.p), int(lo.q))).union(flint.arb(flint.fmpq(int(hi.p), int(hi.q))))
            c = []
            for q in self._qcoeffs:
                acc = flint.arb(0)
                for num, den in q:   # Horner
                    acc = acc * x + flint.arb(flint.fmpq(num, den))
                c.append(acc)
            return ball_transition_matrices(c)
        finally:
            flint.ctx.prec = old


def word_radii(T, L: int):
    """``(w, rho(T_w))`` in floats for every word ``w`` over ``range(len(T))`` of length 1..L, in
    ``itertools.product`` order, ``T_w = T[w[-1]] ... T[w[0]]``. The products of one length are
    stacked and their eigenvalues computed in one LAPACK call each: the same products and
    eigenvalues, matrix by matrix, as one call per word."""
    m = len(T)
    level = np.eye(T[0].shape[0])[None]          # the products of the words of the previous length
    words = [()]
    for n in range(1, L + 1):
        nxt = np.empty((len(level) * m,) + level.shape[1:])
        for e in range(m):
            nxt[e::m] = T[e] @ level
        words = [w + (e,) for w in words for e in range(m)]
        radii = np.abs(np.linalg.eigvals(nxt))
        for w, row in zip(words, radii):
            yield w, max(row)
        level = nxt


def _float_alpha(F: _Family, t: float, L: int) -> tuple[float, tuple]:
    T = F.floats(t)
    best, word = -math.inf, ()
    for w, r in word_radii(T, L):
        if r > 0:
            v = math.log2(r) / len(w)
            if v > best + 1e-12:
                best, word = v, w
    return F.k - best, word


def word_product(M, w):
    """The ball (``acb_mat``) product ``M[w[-1]] ... M[w[0]]`` of a word of transition matrices."""
    P = M[w[0]]
    for e in w[1:]:
        P = M[e] * P
    return P


def rho_lower(P, r0=0):
    """A certified lower bound of the spectral radius of every matrix in the ball matrix ``P``: the
    largest of ``r0``, the trace bound and the lower moduli of Arb's eigenvalue enclosures (Rump's
    algorithm, else the multiple-eigenvalue one). Shared by the one-parameter and the box maximisation."""
    import flint

    r_lo = max(flint.arb(r0).lower(), _trace_bound(P))
    for kw in ({"algorithm": "rump"}, {"multiple": True}):
        try:
            return max([r_lo] + [abs(z).lower() for z in P.eig(**kw)])
        except (ValueError, ZeroDivisionError):
            continue
    return r_lo


def _ball_bound(F: _Family, lo, hi, words, prec=128):
    """A certified upper bound of ``alpha`` on ``[lo, hi]`` (or None) and the word giving it."""
    import flint

    T0, T1 = F.balls(lo, hi, prec)
    Tf = F.floats(float((lo + hi) / 2))
    M = (flint.acb_mat(T0), flint.acb_mat(T1))
    best = None
    old = flint.ctx.prec
    flint.ctx.prec = prec
    try:
        for w in words:
            P = word_product(M, w)
            if best is not None and _no_better(P, F.k, len(w), best[0]):
                continue            # its bound could not be below the best one: skip the costly enclosures
            Pm = np.eye(len(Tf[0]))
            for e in w:
                Pm = Tf[e] @ Pm
            rr = _real_root_bound(F, w, lo, hi, Pm)
            r_lo = rho_lower(P, flint.arb(flint.fmpq(int(rr.p), int(rr.q))).lower())
            if not r_lo > 0:
                continue
            ub = F.k - flint.arb(r_lo).log() / (flint.arb(2).log() * len(w))
            ub = _upper_fraction(ub)
            if best is None or ub < best[0]:
                best = (ub, w)
    finally:
        flint.ctx.prec = old
    return best


def _no_better(P, k: int, length: int, best: Fraction, squarings: int = 5) -> bool:
    """Certainly ``k - log2(r)/length >= best`` for every lower bound ``r`` that the word's ball product ``P``
    can give (:func:`rho_lower`, with the real-root bound): the word cannot lower the best bound, and skipping
    it changes nothing (only the smallest bound is used).

    Each of those lower bounds is at most ``rho(Q)`` for every ``Q`` in the balls (the trace bound and the
    eigenvalue enclosures hold for every matrix in them, the real-root bound for every ``T_w(t)``, ``t`` in
    the interval, and those are in the balls), and ``rho(Q) <= ||Q^(2^s)||_inf^(2^-s)``, bounded above by
    the norm of the ball power ``P^(2^s)``. Runs at the caller's ``flint.ctx.prec``."""
    import flint

    n = P.nrows()
    Q = P
    for _ in range(squarings):
        Q = Q * Q
    U = None
    for i in range(n):
        row = sum((abs(Q[i, j]) for j in range(n)), flint.arb(0)).upper()
        U = row if U is None or row > U else U
    if U is None or not U > 0:
        return False
    lb = k - flint.arb(U).log() / ((2 ** squarings) * length * flint.arb(2).log())
    return bool(lb.lower() >= flint.arb(_fmpq_of(best)))


def _fmpq_of(x: Fraction):
    import flint

    return flint.fmpq(x.numerator, x.denominator)


def _fmpq_poly(q: sp.Poly):
    import flint

    return flint.fmpq_poly([flint.fmpq(int(sp.Rational(v).p), int(sp.Rational(v).q)) for v in q.all_coeffs()[::-1]])


def _fmpq(x: sp.Rational):
    import flint

    return flint.fmpq(int(x.p), int(x.q))


def _sign_on_interval(poly, tm, h) -> int:
    """The sign of the ``fmpq_poly`` ``poly(t)`` for every ``t`` in ``[tm - h, tm + h]`` (0 when not certain).

    Exact: Taylor coefficients at ``tm``; ``|poly(t) - poly(tm)| <= sum_{j>=1} |c_j| h^j``."""
    import flint

    coeffs = poly(flint.fmpq_poly([tm, 1])).coeffs()      # Taylor coefficients at tm, constant first
    if not coeffs:
        return 0
    c0 = coeffs[0]
    rest, hj = flint.fmpq(0), flint.fmpq(1)
    for cj in coeffs[1:]:
        hj *= h
        rest += abs(cj) * hj
    if abs(c0) > rest:
        return 1 if c0 > 0 else -1
    return 0


def _real_root_bound(F: "_Family", word, lo, hi, P_mid) -> sp.Rational:
    """A rational ``r`` with ``rho(T_w(t)) >= r`` for every ``t`` in ``[lo, hi]`` (0 if none found).

    When the float spectrum at the midpoint is dominated by a real eigenvalue of sign ``s``, the
    exact characteristic polynomial ``chi(x) = det(x I - T_w(t))`` (monic, sign ``s^n`` as
    ``x -> s oo``) is evaluated at ``x = s r``: a certified sign ``-s^n`` on the whole interval
    means a real eigenvalue beyond ``s r``, so ``rho >= r`` (intermediate value theorem)."""
    ev = np.linalg.eigvals(P_mid)
    lam = ev[int(np.argmax(abs(ev)))]
    if lam == 0 or abs(lam.imag) > 1e-12 * abs(lam):
        return sp.Integer(0)
    import flint

    sgn = 1 if lam.real > 0 else -1
    chi = F.charpoly(word)
    n = len(chi) - 1
    tm, h = _fmpq((lo + hi) / 2), _fmpq((hi - lo) / 2)
    base = _fmpq_of(Fraction(abs(float(lam.real))).limit_denominator(10 ** 12))
    for d in (10 ** 9, 10 ** 7, 10 ** 5, 10 ** 4, 10 ** 3, 100):      # r = base (1 - 1/d), exactly
        r = base * (1 - flint.fmpq(1, d))
        x = r if sgn > 0 else -r
        val = chi[0] * 0
        for c in chi:                                   # Horner in x
            val = val * x + c
        if _sign_on_interval(val, tm, h) == -(sgn ** n):
            return sp.Rational(int(r.p), int(r.q))
    return sp.Integer(0)


def _trace_bound(P, squarings: int = 5):
    """``rho(P) >= (|tr P^j| / n)^(1/j)``, ``j = 1, 2, 4, ..`` (``|sum lambda^j| <= n rho^j``): crude, never fails."""
    import flint

    n = P.nrows()
    best = flint.arb(0)
    Q, j = P, 1
    for _ in range(squarings + 1):
        tr = sum((Q[i, i] for i in range(n)), flint.acb(0))
        v = (abs(tr) / n).lower()
        if v > 0:
            best = max(best, (flint.arb(v).log() / j).exp().lower())
        Q, j = Q * Q, 2 * j
    return best


def _upper_fraction(x) -> Fraction:
    """A rational ``>=`` every point of the arb ball ``x``."""
    m, e = x.upper().mid().man_exp()
    f = Fraction(int(m)) * (Fraction(2) ** int(e))
    return f


def _rational_near(t: float, lo: sp.Rational, hi: sp.Rational, den: int = 10 ** 6) -> sp.Rational:
    q = sp.Rational(Fraction(t).limit_denominator(den))
    return min(max(q, lo), hi)


def maximize_holder(a: LaurentSymbol, param=None, *, within=(-1, 1), gap=sp.Rational(1, 1000),
                    grid: int = 40, max_length: int = 6, min_width=sp.Rational(1, 10 ** 7),
                    max_intervals: int = 4000, budget: int = 60_000) -> Result:
    """The maximiser ``t*`` of the Hölder exponent of ``a(t)`` over ``within``, with a certified gap.

    ``value`` is ``t*`` (rational); ``lower`` is the certified lower bound of ``alpha(t*)``,
    ``upper`` a certified upper bound of ``alpha`` over the whole box; ``witness["gap"] =
    upper - lower``, ``witness["alpha_at"]`` the :func:`holder_exponent` result at ``t*``,
    ``witness["intervals"]`` the number of sub-intervals, ``witness["words"]`` the candidate
    products. Status certified when the box is covered, inconclusive otherwise (with
    ``provenance["message"]``). ``gap`` is the target: intervals are refined until their bound is
    within it (or ``min_width``/``max_intervals``/``budget`` is reached).

    ``budget`` is in work units, counted, never timed (``FLOAT_ALPHA_UNITS`` per float estimate,
    ``BOUND_UNITS_PER_WORD`` per word of a certified sub-interval bound, and the work of the
    :func:`holder_exponent` calls, which get at most half of it and 20 000 each):
    ``provenance["work"]`` says what was spent, ``provenance["timing"]`` the seconds (reported only).
    """
    t0 = time.perf_counter()          # timing only
    work = Work(budget)
    params = a.params
    if not params:
        raise AnalysisError("nothing to maximise: the family has no free parameter (dimension 0)")
    if param is None:
        if len(params) != 1:
            names = ", ".join(p.name for p in params) or "none"
            return Result(value=None, status=INCONCLUSIVE,
                          witness={"parameters": names},
                          provenance={"method": "one-parameter box search",
                                      "message": f"family too large to maximise: {len(params)} free parameters "
                                                 f"({names}); the box search takes exactly one (fix the others)"})
        p = params[0]
    else:
        p = next((q for q in params if q.name == str(param)), None)
        if p is None:
            raise AnalysisError(f"unknown parameter {param!r} (the family's parameters: "
                                f"{', '.join(q.name for q in params) or 'none'})")
        if len(params) != 1:
            return Result(value=None, status=INCONCLUSIVE, provenance={
                "method": "one-parameter box search",
                "message": f"family too large to maximise: {len(params)} free parameters; fix all but {p.name}"})
    lo, hi = (sp.Rational(sp.nsimplify(as_expr(x))) for x in within)
    if not lo < hi:
        raise AnalysisError("the box needs low < high")
    gap = sp.Rational(sp.nsimplify(as_expr(gap)))
    F = _Family(a, p)

    def float_alpha(x):
        work.charge(FLOAT_ALPHA_UNITS)
        progress.step()
        return _float_alpha(F, x, max_length)

    def certified_alpha(sym, units):
        r = holder_exponent(sym, budget=units)
        work.charge(r.provenance.get("work") or 0)
        return r

    # 1. float search
    progress.stage("float search", grid + 1 + 62)
    xs = np.linspace(float(lo), float(hi), grid + 1)
    vals = [float_alpha(float(x)) for x in xs]
    words = {w for _v, w in vals}
    i = int(np.argmax([v for v, _w in vals]))
    l, r = xs[max(i - 1, 0)], xs[min(i + 1, grid)]
    g = (math.sqrt(5) - 1) / 2
    x1, x2 = r - g * (r - l), l + g * (r - l)
    f1, f2 = float_alpha(x1), float_alpha(x2)
    for _ in range(60):
        words.update((f1[1], f2[1]))
        if f1[0] >= f2[0]:
            r, x2, f2 = x2, x1, f1
            x1 = r - g * (r - l)
            f1 = float_alpha(x1)
        else:
            l, x1, f1 = x1, x2, f2
            x2 = l + g * (r - l)
            f2 = float_alpha(x2)
    words.update((f1[1], f2[1]))
    tstar_f = (l + r) / 2
    best_grid = max(vals, key=lambda v: v[0])[0]
    if best_grid > max(f1[0], f2[0]):
        tstar_f = float(xs[i])
    tstar = _rational_near(tstar_f, lo, hi)
    # 2. certified alpha at t*
    progress.stage(f"certified alpha at {p} = {tstar}")
    h = certified_alpha(a.subs({p: tstar}), min(20_000, budget // 2))
    # exceptional parameters (more factors (1+z)): exact Hölder exponent there; the maximum is often
    # attained at one of them (a kink of alpha), so they are candidates for t* as well
    exc, exc_unbounded = [], []
    for e in F.exceptional:
        v = e["condition"].get(p)
        if v is None or not v.is_real or not (lo <= v <= hi) or not v.is_Rational:
            if v is not None and v.is_real and lo <= v <= hi:
                exc_unbounded.append((v, v))
            continue
        he = certified_alpha(a.subs({p: v}), 20_000)
        exc.append({"t": v, "alpha": (he.lower, he.upper), "status": he.status})
        if he.status == CERTIFIED and he.lower is not None and (
                h.status != CERTIFIED or sp.Rational(he.lower) > sp.Rational(h.lower)):
            tstar, h = v, he
    alpha_lo = sp.Rational(h.lower)
    target = alpha_lo + gap
    words = sorted(words | {(0,), (1,), (0, 1)}, key=lambda w: (len(w), w))
    # 3. branch and bound over the box, best first (the interval with the largest bound is refined)
    import heapq

    progress.stage("upper bound on the box: sub-intervals")

    def bound(I0, I1):
        work.charge(BOUND_UNITS_PER_WORD * len(words))
        progress.step()
        b = _ball_bound(F, I0, I1, words)
        return sp.Rational(b[0].numerator, b[0].denominator) if b else None

    heap, count, stopped, final = [], 0, None, []
    for j in range(16):
        I0, I1 = lo + (hi - lo) * sp.Rational(j, 16), lo + (hi - lo) * sp.Rational(j + 1, 16)
        ub = bound(I0, I1)
        count += 1
        heapq.heappush(heap, (-(ub if ub is not None else sp.oo), count, I0, I1, ub))
    while heap:
        negub, _n, I0, I1, ub = heap[0]
        if ub is not None and ub <= target:
            break
        if count > max_intervals or work.exhausted:
            stopped = "interval or work budget exhausted"
            break
        heapq.heappop(heap)
        if I1 - I0 <= min_width:
            final.append((I0, I1, ub))
            continue
        mid = (I0 + I1) / 2
        for J0, J1 in ((I0, mid), (mid, I1)):
            v = bound(J0, J1)
            count += 1
            heapq.heappush(heap, (-(v if v is not None else sp.oo), count, J0, J1, v))
    leaves = [(I0, I1, ub) for _u, _n, I0, I1, ub in heap] + final
    unbounded = [(I0, I1) for I0, I1, ub in leaves if ub is None]
    ubs = [ub for _I0, _I1, ub in leaves if ub is not None]
    upper = max(ubs) if ubs else None
    for e in exc:
        if e["status"] != CERTIFIED:
            unbounded.append((e["t"], e["t"]))
        else:
            upper = max(upper, sp.Rational(e["alpha"][1])) if upper is not None else sp.Rational(e["alpha"][1])
    unbounded += exc_unbounded
    certified = h.status == CERTIFIED and not unbounded and upper is not None
    witness = {"parameter": p.name, "alpha_at": h, "gap": (upper - alpha_lo) if upper is not None else None,
               "intervals": count, "words": words, "k": F.k, "exceptional": exc,
               "float_maximiser": tstar_f, "box": (lo, hi)}
    prov = {"method": "float search; certified alpha at t* (holder_exponent); Arb ball eigenvalue enclosures "
                      "of products T_w on sub-intervals (rho(T_w)^(1/|w|) <= JSR) give alpha <= k - log2 rho/|w|",
            "target_gap": gap, "budget": budget, "work": work.spent,
            "timing": {"seconds": round(time.perf_counter() - t0, 2)}}
    if not certified:
        why = []
        if unbounded:
            why.append(f"{len(unbounded)} sub-interval(s) without a certified bound (e.g. {unbounded[0]})")
        if h.status != CERTIFIED:
            why.append(f"alpha at t* is {h.status}")
        prov["message"] = "; ".join(why) or "no bound"
    elif stopped:
        prov["message"] = f"{stopped}: the gap is larger than the target"
    return Result(value=tstar, lower=alpha_lo, upper=upper, status=CERTIFIED if certified else INCONCLUSIVE,
                  witness=witness, provenance=prov)
