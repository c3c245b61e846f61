"""The smoothest member of a family with several parameters or of arity m, with a certified gap.

:func:`maximize_holder_box` generalises :func:`analysis.regularity.maximize.maximize_holder`
(one parameter, binary) to a box of ``d`` parameters and to arity ``m``: it returns a rational
point ``t*``, the certified ``alpha(t*)`` and a certified upper bound of ``alpha`` over the whole
box. A binary one-parameter family is handed to ``maximize_holder`` unchanged.

Examples
--------
The ternary interpolatory 4-point family (``subdiv derive --arity 3 --support 11 --interpolatory
--symmetric primal --reproduce 2``) on ``[-1/16, 0]``:

>>> import sympy as sp
>>> from analysis.algebra.derive import derive_mask
>>> a = derive_mask(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=2).value
>>> r = maximize_holder_box(a, {"t1": (sp.Rational(-1, 16), 0)}, arity=3, gap=sp.Rational(1, 20),
...                         budget=60_000)
>>> r.status, r.witness["gap"] <= sp.Rational(1, 20)
('certified', True)

Algorithm
---------
With ``N`` the generic number of factors ``q_m = 1 + z + ... + z^(m-1)``, ``k = N - 1`` and
``c = m^k a / q_m^N`` (coefficients polynomials in the parameters),
``alpha = k - log_m JSR(T_0, ..., T_{m-1})``.

1. *Search* (floats): a grid over the box, then Nelder–Mead from the best grid point, of
   ``k - max_{|w| <= L} log_m rho(T_w)/|w|``; the maximiser is rounded to a rational ``t*``.
2. *At t\\**: ``holder_exponent`` with the arity (certified enclosure).
3. *Upper bound* (branch and bound over sub-boxes, the box with the largest bound split along its
   widest side): the transition matrices on a sub-box are Arb ball matrices (each coefficient a
   polynomial in the parameters evaluated on the ball box); for each candidate word the ball
   eigenvalues of ``T_w`` (``acb_mat.eig``, valid for every matrix in the balls) or a trace bound
   give ``min rho(T_w) >= r_w`` on the sub-box, so ``alpha <= k - log_m(r_w)/|w|`` there.
4. *Exceptional parameters* (more factors ``q_m``: the generic formula does not bound ``alpha``
   there): a condition ``p_i = f(other parameters)`` with ``f`` affine defines a sub-family of one
   parameter fewer, maximised recursively over the part of the box it crosses; a point condition
   gets the certified exponent at the point. Other conditions make the result inconclusive.

References
----------
O. Rioul, SIAM J. Math. Anal. 23 (1992); I. Daubechies, J. Lagarias, SIAM J. Math. Anal. 23 (1992);
F. Johansson, Arb, IEEE Trans. Comput. 66 (2017).
"""

from __future__ import annotations

import heapq
import itertools
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
from ..stationary.transition import transition_matrices
from ..algebra.reader import as_expr

__all__ = ["maximize_holder_box"]


class _BoxFamily:
    """The transition matrices of ``c`` as polynomial entries in the parameters (floats and balls)."""

    def __init__(self, a: LaurentSymbol, params: tuple, m: int):
        f = smoothing_factor(a, arity=m)
        self.N, self.m, self.params = f.value, m, params
        if self.N < 1:
            raise AnalysisError("the family does not satisfy the sum rules identically: not convergent generically")
        self.k = self.N - 1
        self.exceptional = f.witness.get("exceptional", [])
        c = factor_out(a, self.N, arity=m) / m
        mats = transition_matrices(c, arity=m)
        self.n = mats[0].shape[0]
        self.entries = [[[sp.Poly(sp.expand(M[i, j]), *params) for j in range(self.n)] for i in range(self.n)]
                        for M in mats]
        # each entry's terms as (numerator, denominator, exponents), converted once for the ball evaluations
        self._terms = [[[[(int(sp.Rational(co).p), int(sp.Rational(co).q), [int(e) for e in mon])
                          for mon, co in q.terms()] for q in row] for row in E] for E in self.entries]
        self._f = [sp.lambdify(params, M, "numpy") for M in mats]

    def floats(self, t):
        return [np.array(f(*t), dtype=float).reshape(self.n, self.n) for f in self._f]

    def balls(self, box, prec=128):
        import flint

        old = flint.ctx.prec
        flint.ctx.prec = prec
        try:
            xs = [flint.arb(flint.fmpq(int(lo.p), int(lo.q))).union(flint.arb(flint.fmpq(int(hi.p), int(hi.q))))
                  for lo, hi in box]
            out = []
            for E in self._terms:
                rows = []
                for row in E:
                    vals = []
                    for terms in row:
                        acc = flint.arb(0)
                        for num, den, mon in terms:
                            term = flint.arb(flint.fmpq(num, den))
                            for x, e in zip(xs, mon):
                                if e:
                                    term *= x ** e
                            acc += term
                        vals.append(acc)
                    rows.append(vals)
                out.append(flint.acb_mat(rows))
            return out
        finally:
            flint.ctx.prec = old


def _float_alpha(F: _BoxFamily, t, L: int):
    from .maximize import word_radii

    T = F.floats(t)
    best, word = -math.inf, ()
    for w, r in word_radii(T, L):
        if r > 0:
            v = math.log(r, F.m) / len(w)
            if v > best + 1e-12:
                best, word = v, w
    return F.k - best, word


def _upper_fraction(x) -> Fraction:
    m, e = x.upper().mid().man_exp()
    return Fraction(int(m)) * (Fraction(2) ** int(e))


def _ball_bound(F: _BoxFamily, box, words, prec=128):
    """A certified upper bound of alpha on the closed box (a Fraction) or None."""
    import flint

    from .maximize import rho_lower, word_product

    M = F.balls(box, prec)
    best = None
    old = flint.ctx.prec
    flint.ctx.prec = prec
    try:
        for w in words:
            r_lo = rho_lower(word_product(M, w))
            if not r_lo > 0:
                continue
            ub = _upper_fraction(F.k - flint.arb(r_lo).log() / (flint.arb(F.m).log() * len(w)))
            if best is None or ub < best:
                best = ub
    finally:
        flint.ctx.prec = old
    return best


def _certified_alpha(a: LaurentSymbol, m: int, budget: int, work: Work | None = None):
    from .holder import holder_exponent

    r = holder_exponent(a, budget=budget, arity=m)
    if work is not None:
        work.charge(r.provenance.get("work") or 0)
    return r


def _parse_box(a: LaurentSymbol, box) -> tuple[tuple, list]:
    names = {p.name: p for p in a.params}
    if not a.params:
        raise AnalysisError("nothing to maximise: the family has no free parameter (dimension 0)")
    if set(map(str, box)) != set(names):
        raise AnalysisError(f"give a range for every free parameter ({', '.join(names)}), e.g. "
                            + " ".join(f"--box {n}=LO,HI" for n in names))
    params = tuple(names[str(k)] for k in box)
    out = []
    for k in box:
        lo, hi = (sp.Rational(sp.nsimplify(as_expr(x))) for x in box[k])
        if not lo < hi:
            raise AnalysisError(f"the range of {k} needs low < high")
        out.append((lo, hi))
    return params, out


def maximize_holder_box(a: LaurentSymbol, box: dict, *, arity: int = 2, gap=sp.Rational(1, 1000),
                        grid: int | None = None, max_length: int | None = None, max_boxes: int = 3000,
                        min_width=sp.Rational(1, 10 ** 6), budget: int = 120_000) -> Result:
    """Maximise alpha over ``box`` (``{name: (lo, hi)}``, one entry per free parameter), arity ``arity``.

    ``value``: the rational point ``t*`` (a dict name -> value); ``lower``: certified lower bound of
    ``alpha(t*)``; ``upper``: certified upper bound of alpha over the box; ``witness["gap"]``.
    Certified when the whole box (and every exceptional sub-family in it) is bounded.

    ``budget`` is in work units, counted, never timed (as in
    :func:`analysis.regularity.maximize.maximize_holder`: ``FLOAT_ALPHA_UNITS`` per float estimate,
    ``BOUND_UNITS_PER_WORD`` per word of a certified sub-box bound, the work of the certified alpha
    computations; each exceptional sub-family gets a third); ``provenance["work"]`` says what was
    spent, ``provenance["timing"]`` the seconds (reported only).
    """
    from .maximize import BOUND_UNITS_PER_WORD, FLOAT_ALPHA_UNITS

    t0 = time.perf_counter()          # timing only
    work = Work(budget)
    params, B = _parse_box(a, box)
    if arity == 2 and len(params) == 1:
        from .maximize import maximize_holder

        r = maximize_holder(a, params[0], within=B[0], gap=gap, budget=budget)
        value = None if r.value is None else {params[0].name: r.value}
        return Result(value=value, lower=r.lower, upper=r.upper, status=r.status,
                      witness={**r.witness, "box": {params[0].name: B[0]}}, provenance=r.provenance)
    gap = sp.Rational(sp.nsimplify(as_expr(gap)))
    F = _BoxFamily(a, params, arity)
    d = len(params)
    L = max_length or (6 if arity == 2 else 4 if arity == 3 else 3)
    G = grid or (40 if d == 1 else 12 if d == 2 else 4)
    # 1. float search
    axes = [np.linspace(float(lo), float(hi), G + 1) for lo, hi in B]
    best, words = (-math.inf, None), set()
    progress.stage("float search: grid points", (G + 1) ** d)
    for t in itertools.product(*axes):
        work.charge(FLOAT_ALPHA_UNITS)
        progress.step()
        v, w = _float_alpha(F, t, L)
        words.add(w)
        if v > best[0]:
            best = (v, t)
    from scipy.optimize import minimize

    lo_f, hi_f = np.array([float(x) for x, _ in B]), np.array([float(y) for _, y in B])

    progress.stage("float search: Nelder-Mead", 150 * d)

    def neg(t):
        t = np.clip(t, lo_f, hi_f)
        work.charge(FLOAT_ALPHA_UNITS)
        progress.step()
        v, w = _float_alpha(F, t, L)
        words.add(w)
        return -v

    res = minimize(neg, np.array(best[1]), method="Nelder-Mead",
                   options={"xatol": 1e-7, "fatol": 1e-9, "maxfev": 150 * d})
    t_f = np.clip(res.x, lo_f, hi_f) if -res.fun >= best[0] else np.array(best[1])
    tstar = [min(max(sp.Rational(Fraction(float(x)).limit_denominator(10 ** 6)), lo), hi)
             for x, (lo, hi) in zip(t_f, B)]
    v_float = max(best[0], -res.fun)
    words = sorted(words | {(e,) for e in range(arity)}, key=lambda w: (len(w), w))
    # 2. exceptional sub-families
    exc, problems, sub_best = [], [], None
    for e in F.exceptional:
        sub = _exceptional_part(a, e, params, B, arity, gap, budget // 3, work)
        if sub is None:
            continue
        exc.append(sub["record"])
        if sub["result"] is None or sub["result"].upper is None or sub["result"].status != CERTIFIED:
            problems.append(f"exceptional {sub['record']['condition']}: not bounded")
        r = sub["result"]
        if r is not None and r.lower is not None and (sub_best is None or r.lower > sub_best[0]):
            sub_best = (sp.Rational(r.lower), sub["point"])
    if sub_best is not None and sub_best[0] > v_float + 1e-6:
        # an exceptional member beats every generic one the float search saw: no need to certify t*
        alpha_lo, tstar, h = sub_best[0], [sub_best[1][p.name] for p in params], None
    else:
        progress.stage("certified alpha at t*")
        h = _certified_alpha(a.subs(dict(zip(params, tstar))), arity, min(20_000, budget // 4), work)
        alpha_lo = sp.Rational(h.lower) if h.lower is not None else None
        if sub_best is not None and (alpha_lo is None or sub_best[0] > alpha_lo):
            alpha_lo, tstar, h = sub_best[0], [sub_best[1][p.name] for p in params], None
    target = (alpha_lo if alpha_lo is not None else sp.Integer(F.k)) + gap
    # 3. branch and bound on the generic formula
    progress.stage("upper bound on the box: sub-boxes")

    def bound(bx):
        work.charge(BOUND_UNITS_PER_WORD * len(words))
        progress.step()
        b = _ball_bound(F, bx, words)
        return sp.Rational(b.numerator, b.denominator) if b is not None else None

    heap, count, stopped, final = [], 0, None, []
    b0 = bound(B)
    heapq.heappush(heap, (-(b0 if b0 is not None else sp.oo), 0, B, b0))
    while heap:
        _neg, _c, bx, ub = heap[0]
        if ub is not None and ub <= target:
            break
        if count > max_boxes or work.exhausted:
            stopped = "box or work budget exhausted"
            break
        heapq.heappop(heap)
        widths = [hi - lo for lo, hi in bx]
        i = max(range(d), key=lambda k: widths[k] / (B[k][1] - B[k][0]))
        if widths[i] <= min_width:
            final.append((bx, ub))
            continue
        mid = (bx[i][0] + bx[i][1]) / 2
        for part in ((bx[i][0], mid), (mid, bx[i][1])):
            nb = list(bx)
            nb[i] = part
            v = bound(nb)
            count += 1
            heapq.heappush(heap, (-(v if v is not None else sp.oo), count, nb, v))
    leaves = [(bx, ub) for _n, _c, bx, ub in heap] + final
    unbounded = [bx for bx, ub in leaves if ub is None]
    ubs = [ub for _bx, ub in leaves if ub is not None]
    upper = max(ubs) if ubs else None
    for x in exc:
        if x.get("upper") is not None and upper is not None:
            upper = max(upper, x["upper"])
    certified = (not unbounded and not problems and upper is not None and alpha_lo is not None
                 and (h is None or h.status == CERTIFIED))
    point = {p.name: v for p, v in zip(params, tstar)}
    prov = {"method": "float search (grid, Nelder-Mead); certified alpha at t*; Arb ball eigenvalue enclosures "
                      "of products T_w on sub-boxes (rho(T_w)^(1/|w|) <= JSR): alpha <= k - log_m rho/|w|; "
                      "exceptional sub-families recursively",
            "target_gap": gap, "arity": arity, "budget": budget, "work": work.spent,
            "timing": {"seconds": round(time.perf_counter() - t0, 2)}}
    if not certified:
        why = list(problems)
        if unbounded:
            why.append(f"{len(unbounded)} sub-box(es) without a certified bound")
        if h is not None and h.status != CERTIFIED:
            why.append(f"alpha at t* is {h.status}")
        prov["message"] = "; ".join(why) or "no bound"
    elif stopped:
        prov["message"] = f"{stopped}: the gap is larger than the target"
    return Result(value=point, lower=alpha_lo, upper=upper, status=CERTIFIED if certified else INCONCLUSIVE,
                  witness={"parameters": [p.name for p in params], "box": {p.name: b for p, b in zip(params, B)},
                           "alpha_at": h, "gap": (upper - alpha_lo) if upper is not None and alpha_lo is not None
                           else None, "boxes": count, "words": words, "k": F.k, "exceptional": exc},
                  provenance=prov)


def _exceptional_part(a, e, params, B, arity, gap, budget, work):
    """Maximise over the exceptional set ``e["condition"]`` inside the box (None: it misses the box)."""
    cond = e.get("condition", {})
    if len(cond) != 1:
        return {"record": {"condition": str(cond), "upper": None}, "result": None, "point": None}
    (p, f), = cond.items()
    others = [q for q in params if q != p]
    i = params.index(p)
    f = as_expr(f)
    if not others:                                   # a point
        if not f.is_Rational or not (B[i][0] <= f <= B[i][1]):
            return None if f.is_real and not (B[i][0] <= f <= B[i][1]) else \
                {"record": {"condition": str(cond), "upper": None}, "result": None, "point": None}
        h = _certified_alpha(a.subs({p: f}), arity, 20_000, work)
        rec = {"condition": str(cond), "alpha": (h.lower, h.upper), "status": h.status,
               "upper": sp.Rational(h.upper) if h.upper is not None else None}
        return {"record": rec, "result": Result(value=None, lower=h.lower, upper=h.upper, status=h.status),
                "point": {p.name: f}}
    poly = sp.Poly(f, *others)
    if poly.total_degree() > 1 or len(others) != 1:
        return {"record": {"condition": str(cond), "upper": None}, "result": None, "point": None}
    q = others[0]
    j = params.index(q)
    s, c0 = poly.coeff_monomial(q), poly.coeff_monomial(1)
    lo_q, hi_q = B[j]
    if s != 0:                                       # p = s q + c0 within [B_i]: q in an interval
        e1, e2 = sorted(((B[i][0] - c0) / s, (B[i][1] - c0) / s))
        lo_q, hi_q = max(lo_q, e1), min(hi_q, e2)
    elif not (B[i][0] <= c0 <= B[i][1]):
        return None
    if not lo_q < hi_q:
        return None
    sub = a.subs({p: f})
    r = maximize_holder_box(sub, {q.name: (lo_q, hi_q)}, arity=arity, gap=gap, budget=budget)
    work.charge(r.provenance.get("work") or 0)
    pt = None
    if r.value is not None:
        tq = r.value[q.name]
        pt = {q.name: tq, p.name: f.subs(q, tq)}
    rec = {"condition": f"{p.name} = {sp.sstr(f)}", "range": (lo_q, hi_q), "factors": e.get("k"),
           "upper": r.upper, "lower": r.lower, "status": r.status, "maximiser": pt}
    return {"record": rec, "result": r, "point": pt}
