"""Convergence of the parameters ``u^k -> 1`` (seed 001, Lemma 2.1) and decay of the masks
``sup_j ||S^k - S_a||`` to the limit B-spline mask, with certified enclosures.

Interval arithmetic is ``mpmath.iv``; arccos / arccosh of an interval are enclosed through Arb
(python-flint), ``_iv_acos`` / ``_iv_acosh``. Reported end points are exact Rationals rounded
outward (:func:`_endpoint_rational`), never to nearest.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .arithmetic import _Arith, _ivprec
from .masks import _pure_constant, mask_distance
from .refinement import _check_degree, _check_rule, _half_update, _sources


def _arb_to_iv(x):
    """A python-flint ``arb`` ball as an ``mpmath.iv`` interval (outward)."""
    iv = mpmath.iv
    m, e = x.mid().man_exp()
    r, re_ = x.rad().man_exp()
    two = iv.mpf(2)
    mid = iv.mpf(int(m)) * two ** int(e)
    rad = iv.mpf(int(r)) * two ** int(re_)
    lo, hi = mid - rad, mid + rad
    return iv.mpf([lo.a, hi.b])


def _arb_point(t):
    """An exact arb for a mpf endpoint."""
    import flint

    x = mpmath.mpf(t)
    man, exp = x.man_exp
    sign = -1 if x < 0 else 1
    return sign * flint.arb(int(man)) * flint.arb(2) ** int(exp)


def _iv_monotone(x, name: str, increasing: bool):
    """Rigorous enclosure of the monotone Arb function ``name`` over the interval ``x``."""
    import flint

    old = flint.ctx.prec
    flint.ctx.prec = max(old, mpmath.iv.prec + 10)
    try:
        ends = (x.a, x.b) if increasing else (x.b, x.a)
        lo = _arb_to_iv(getattr(_arb_point(ends[0]), name)())
        hi = _arb_to_iv(getattr(_arb_point(ends[1]), name)())
    finally:
        flint.ctx.prec = old
    return mpmath.iv.mpf([lo.a, hi.b])


def _iv_acos(x):
    """Rigorous enclosure of arccos over the interval ``x`` (decreasing), via Arb."""
    return _iv_monotone(x, "acos", increasing=False)


def _iv_acosh(x):
    """Rigorous enclosure of arccosh over ``x >= 1`` (increasing), via Arb."""
    return _iv_monotone(x, "acosh", increasing=True)


def _limit_constant_iv(u0, prec: int):
    """Enclosure of ``lim 4^k (1 - u^k)``: ``arccos(u0)^2/2`` (u0 <= 1) or ``-arccosh(u0)^2/2``."""
    with _ivprec(prec):
        x = _Arith("iv", prec).scalar(u0)
        if x.b <= 1:
            return _iv_acos(x) ** 2 / 2
        if x.a >= 1:
            return -(_iv_acosh(x) ** 2) / 2
        raise AnalysisError("u0 enclosure straddles 1; give an exact value")


def _endpoint_rational(x, side: str, digits: int | None = 30) -> sp.Rational:
    """An interval end point as an exact Rational, rounded *outward*: ``side="lower"`` rounds
    down, ``side="upper"`` rounds up (to ``digits`` significant decimals; ``None``: the exact
    binary value). Never round-to-nearest.

    >>> import mpmath
    >>> iv = mpmath.iv.mpf([1, 1]) / 3
    >>> lo, hi = _endpoint_rational(iv, "lower", 5), _endpoint_rational(iv, "upper", 5)
    >>> lo, hi, lo <= sp.Rational(1, 3) <= hi
    (33333/100000, 16667/50000, True)
    """
    if side not in ("lower", "upper"):
        raise ValueError("side must be 'lower' or 'upper'")
    if hasattr(x, "_mpi_"):                       # an mpmath.iv interval: take its end point
        raw = x._mpi_[0 if side == "lower" else 1]
    elif hasattr(x, "_mpf_"):
        raw = x._mpf_
    else:
        raw = mpmath.mpf(x)._mpf_
    if raw in (mpmath.libmp.finf, mpmath.libmp.fninf, mpmath.libmp.fnan):
        raise AnalysisError("an interval end point is not finite; raise the precision")
    p_, q_ = mpmath.libmp.to_rational(raw)
    exact = sp.Rational(int(p_), int(q_))
    if digits is None or exact == 0:
        return exact
    e = int(sp.floor(sp.log(abs(exact), 10))) if abs(exact) >= 1 else -len(str(int(1 / abs(exact))))
    scale = sp.Integer(10) ** (digits - 1 - e)
    n = exact * scale
    n = sp.floor(n) if side == "lower" else sp.ceiling(n)
    return sp.Rational(int(n)) / scale


def _decimal_text(r: sp.Rational) -> str:
    """The exact decimal expansion of a rational whose denominator divides a power of 10."""
    r = sp.Rational(r)
    q = int(r.q)
    s = 0
    while (10 ** s) % q:
        s += 1
        if s > 400:
            return sp.sstr(r)
    n = int(r * 10 ** s)
    sign, n = ("-" if n < 0 else ""), abs(n)
    if s == 0:
        return f"{sign}{n}"
    txt = str(n).rjust(s + 1, "0")
    return f"{sign}{txt[:-s]}.{txt[-s:]}".rstrip("0").rstrip(".")


def u_convergence_bound(u0_low, u0_high, *, levels: int = 60, prec: int = 128) -> Result:
    """Certified: for every ``u^0`` in ``[u0_low, u0_high]`` (``> -1``) and every ``k >= 0``,
    ``|1 - u^k| <= C 4^{-k}``, and ``4^k (1 - u^k)`` converges to ``arccos(u0)^2/2`` (u0 <= 1) or
    ``-arccosh(u0)^2/2`` (u0 >= 1) — the true rate is ``4^{-k}``, not the ``2^{-k}`` used in
    seed 001's proof of Theorem 3.6.

    >>> r = u_convergence_bound(0.5, 2, levels=20)
    >>> r.status, round(float(r.value), 6)          # C = max(acos(1/2)^2/2, 2 - 1)
    ('certified', 1.0)

    Algorithm
    ---------
    Analytic, for all k: ``u0 = cos(theta)``, ``0 <= theta < pi``: ``u^k = cos(theta/2^k)`` and
    ``1 - u^k = 2 sin^2(theta/2^{k+1}) <= theta^2 4^{-k}/2``. ``u0 = cosh(theta)``:
    ``u^k - 1 = 2 sinh^2(theta/2^{k+1}) <= 2 sinh^2(theta/2) 4^{-k} = (u0 - 1) 4^{-k}`` since
    ``sinh(x/2^k) <= sinh(x)/2^k`` (convexity). Both bounds are monotone in ``u0``, so the range's
    constant is attained at an end point; it is enclosed with ``mpmath.iv``. The recursion is
    also run in interval arithmetic for ``k <= levels`` as a consistency check (an enclosure of
    ``4^k |1-u^k|`` at both ends must stay below the constant).
    """
    lo_in, hi_in = float(u0_low), float(u0_high)
    if not (lo_in > -1) or not (hi_in >= lo_in) or not math.isfinite(hi_in):
        raise AnalysisError("need -1 < u0_low <= u0_high < oo")
    ctx = _Arith("iv", prec)
    iv = mpmath.iv
    with ctx.scope():
        a, b = ctx.scalar(u0_low), ctx.scalar(u0_high)
        parts = []
        if a.a < 1:
            parts.append(_iv_acos(iv.mpf([a.a, min(a.b, 1)])) ** 2 / 2)
        if b.b > 1:
            parts.append(b - 1)
        C = parts[0] if len(parts) == 1 else iv.mpf([max(p.a for p in parts), max(p.b for p in parts)])
        if not parts:
            C = iv.mpf(0)
        table = []
        ok = True
        for u0 in (a, b):
            v = 1 - u0
            for k in range(levels + 1):
                scaled = abs(v) * iv.mpf(4) ** k
                if scaled.a > C.b:  # a certain violation (the bound is approached in the limit)
                    ok = False
                if k in (0, 1, 2, 5, 10, 20, levels):
                    table.append({"u0": str(u0), "k": k, "4^k|1-u^k|": str(scaled)})
                v = _half_update(v, iv.sqrt)
    lim_lo = _limit_constant_iv(u0_low, prec) if lo_in != 1 else iv.mpf(0)
    lim_hi = _limit_constant_iv(u0_high, prec) if hi_in != 1 else iv.mpf(0)
    C_up = _endpoint_rational(C, "upper")      # exact Rational, rounded up (never to nearest)
    return Result(value=C_up, lower=None, upper=C_up,
                  status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"bound": "sup_k 4^k |1 - u^k| <= C", "C_enclosure": str(C),
                           "limit_at_low": str(lim_lo), "limit_at_high": str(lim_hi),
                           "interval_recursion_check": table, "recursion_consistent": ok},
                  provenance={"method": "analytic bound (cos/cosh half-angle) + mpmath.iv enclosure; the "
                                        "reported C is the enclosure's upper end point rounded up to a Rational",
                              "prec_bits": prec, "u0_range": [str(u0_low), str(u0_high)]})


def lemma_2_1(u0_low, u0_high, *, levels: int = 60, prec: int = 128) -> Result:
    """Seed 001, Lemma 2.1 on the range ``u^0 in [u0_low, u0_high]``: ``u^k -> 1`` uniformly and
    ``||U^k||_inf <= C max(1, ||U^0||_inf)`` (certified with ``C = 1``), with the rate.

    >>> r = lemma_2_1(0.1, 10)
    >>> r.status, r.value
    ('certified', 1)

    Algorithm
    ---------
    ``phi(u) = sqrt((1+u)/2)`` is increasing with fixed point 1, ``phi(u) < u`` for ``u > 1`` and
    ``u < phi(u) <= 1`` for ``-1 <= u < 1``; so ``max_n u^k_n = phi^k(max u^0)`` and
    ``||U^k|| <= max(1, ||U^0||)`` for every k (the lemma with C = 1, exact), and
    ``sup_n |1 - u^k_n| <= C' 4^{-k}`` (:func:`u_convergence_bound`). The monotonicity is checked in
    interval arithmetic at both ends for ``k <= levels``.
    """
    bound = u_convergence_bound(u0_low, u0_high, levels=levels, prec=prec)
    iv = mpmath.iv
    ok = bound.status == CERTIFIED
    with _ivprec(prec):
        a, b = _Arith("iv", prec).scalar(u0_low), _Arith("iv", prec).scalar(u0_high)
        norm0 = iv.mpf([max(abs(a).b, abs(b).b), max(abs(a).b, abs(b).b)])
        hi = b
        for k in range(levels + 1):
            if hi.b > max(1, norm0.b) and not (hi.a <= 1 <= hi.b):
                ok = False
            hi = iv.sqrt((1 + hi) / 2)
    return Result(value=1, status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"C": 1, "rate": "sup_n |1-u^k_n| <= C' 4^-k", "C'": bound.witness["C_enclosure"],
                           "limits": [bound.witness["limit_at_low"], bound.witness["limit_at_high"]],
                           "note": "needs u0 > -1 for the real square root; the papers assume u0 > 0"},
                  provenance={"method": "monotonicity of phi + interval check", "prec_bits": prec})


def mask_decay(u0, degree: int = 2, *, levels: int = 12, closed: bool = False, rule: str = "seed001",
               prec: int = 128) -> Result:
    """``sup_j ||S^{k} - S_a||_inf`` (operator rows) for ``k = 0..levels`` starting from the edge
    parameters ``u0``; certified enclosure ``[c_d max_pure |delta|, 2 max_e |delta^k_e|]`` and the
    ratio of consecutive levels (-> 1/4) and ``4^k sup_j`` (-> ``max_e |arccos or arccosh(u0_e)|^2/8``
    times ``c_d``).

    >>> r = mask_decay([0.5, 0.5], degree=2, levels=6)
    >>> r.status, [round(x, 4) for x in r.witness["ratios"][-2:]]
    ('certified', [0.2499, 0.25])
    >>> r.lower <= r.upper, type(r.upper).__name__      # exact end points, rounded outward
    (True, 'Rational')

    Algorithm
    ---------
    Descendants of an edge share its parameter, so level k has finitely many distinct values
    ``delta^k_e = v/(4(2-v))`` (enclosed by iterating the cancellation-free update in
    ``mpmath.iv``). ``a^{k,i} - a = sum_l w_l z^{-l} delta_{e(i+l)} z^{-2}(1-z)^2(1+z)`` gives the
    upper bound (``||z^{-2}(1-z)^2(1+z)||`` per parity is 2); a location whose window has one
    parameter attains ``c_d |delta|`` exactly (:func:`_pure_constant`). Which windows are pure
    is decided with the integer ancestry of the edges (exact). The exact sup over all locations
    is also evaluated in floats (``witness["float_sup"]``).
    """
    d = _check_degree(degree)
    _check_rule(rule)
    u0 = list(np.atleast_1d(np.asarray(u0, dtype=object)))
    if levels < 0 or levels > 30:
        raise AnalysisError("levels must be between 0 and 30")
    ctx = _Arith("iv", prec)
    c_d = _pure_constant(d)
    iv = mpmath.iv
    rows, ratios, scaled, bounds = [], [], [], []
    consistent = True
    with ctx.scope():
        v = [1 - ctx.scalar(x) for x in u0]
        for x in v:
            if not (2 - x).a > 0:
                raise AnalysisError("every u0 must be > -1")
        anc = np.arange(len(u0))
        prev_hi = None
        for k in range(levels + 1):
            delta = [x / (4 * (2 - x)) for x in v]
            absd = [abs(x) for x in delta]
            # pure windows: S_2 points i..i+d-2 from one ancestor
            edges = len(anc)
            nq = 2 * edges
            count = nq if closed else nq - (d - 2)
            idx = np.arange(count)
            first = anc[((idx) % nq if closed else idx) // 2]
            pure = np.ones(count, dtype=bool)
            for l in range(1, d - 1):
                q = (idx + l) % nq if closed else idx + l
                pure &= anc[q // 2] == first
            pure_anc = {par: sorted(set(first[pure & (idx % 2 == par)].tolist())) for par in (0, 1)}
            up = 2 * max(x.b for x in absd)
            lo_iv = iv.mpf(0)
            for par in (0, 1):
                cp = _pure_constant(d, par)
                for a_ in pure_anc[par]:
                    cand = iv.mpf(cp.numerator) / cp.denominator * absd[a_]
                    if cand.a > lo_iv.a:
                        lo_iv = cand
            # float sup over all locations (descendant values)
            if edges <= 2 ** 18:
                vk = np.array([float(mpmath.mpf(x.mid)) for x in v])[anc]
                fs = mask_distance(one_minus_u=vk, degree=d, closed=closed)["operator"]
            else:
                fs = None
            lo_q = _endpoint_rational(lo_iv, "lower")            # outward: lower end rounded down
            up_q = _endpoint_rational(iv.mpf(up), "upper")       # upper end rounded up
            consistent &= bool(0 <= lo_q <= up_q)
            bounds.append((lo_q, up_q))
            rows.append({"k": k, "lower": _decimal_text(lo_q), "upper": _decimal_text(up_q),
                         "float_sup": fs,
                         "pure_windows": bool(pure_anc[0] or pure_anc[1])})
            scaled.append(float(mpmath.mpf(up)) * 4 ** k)
            if prev_hi is not None:
                ratios.append(float(mpmath.mpf(up)) / prev_hi)
            prev_hi = float(mpmath.mpf(up))
            # next level
            v = [_half_update(x, iv.sqrt) for x in v]
            j = np.arange(count if closed else count - 1)
            anc = anc[_sources(j, d, closed, rule, edges)]
    s_lim = max(abs(float(mpmath.mpf(_limit_constant_iv(x, 64).mid))) if float(x) != 1 else 0.0 for x in u0)
    pos = [(k, lo * 4 ** k) for k, (lo, _) in enumerate(bounds) if lo > 0]
    scaled_lo = min(x for _, x in pos) if pos else sp.Integer(0)
    scaled_hi = max(up * 4 ** k for k, (_, up) in enumerate(bounds))
    return Result(value=None, lower=bounds[-1][0], upper=bounds[-1][1],
                  status=CERTIFIED if consistent else INCONCLUSIVE,
                  witness={"levels": rows, "ratios": ratios, "scaled_4k_upper": scaled,
                           "c_d": str(c_d), "predicted_limit_4k_upper": s_lim / 4,
                           "certified_4k_bounds": {"min_k 4^k lower_k": scaled_lo, "max_k 4^k upper_k": scaled_hi,
                                                   "levels_with_positive_lower": [k for k, _ in pos],
                                                   "k_range": [0, levels]},
                           "rate": ("c 4^-k <= sup_j ||S^k - S_a|| <= C 4^-k on k = 0..levels (certified "
                                    "end points)" if pos and len(pos) == len(bounds) else
                                    "upper bound C 4^-k on k = 0..levels (certified end points)"),
                           "ratios_note": "float quotients of consecutive upper bounds (an observation)"},
                  provenance={"method": "interval enclosures of delta^k_e + exact ancestry", "prec_bits": prec,
                              "degree": d, "rule": rule, "closed": closed})
