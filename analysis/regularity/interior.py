"""The interior of a one-parameter C^j set, certified by exact parametric norm tests.

:func:`ck_interior` covers an interval ``(a, b)`` of the parameter (exact ends: rationals or real
algebraic numbers, each open or closed) by pieces on each of which the Dyn–Levin test
``||(1/m S_{a_{j+1}})^L||_inf < 1`` holds for every parameter value: closed rational boxes
(exact Bernstein bound below 1, :meth:`~analysis.stationary.normbox.ParametricNorm.box_bound`) and,
next to an open end, half-open end pieces decided exactly
(:meth:`~analysis.stationary.normbox.ParametricNorm.end_piece`). What is left is reported exactly
as inconclusive strips: next to an end of eigenvalue type (the joint spectral radius of the
difference scheme reaches 1 there while no norm ``N_L`` touches 1), the norms only reach 1 at a
distance ~ log(C)/L of the end, so a strip of that width remains for the largest L tried.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> w = sp.Symbol("w")
>>> a = LaurentSymbol.from_mask([-w, 0, w + sp.Rational(1, 2), 1, w + sp.Rational(1, 2), 0, -w], start=-3)
>>> r = ck_interior(a, 1, 0, sp.Rational(1, 8), hi_open=False, L_max=6)   # 4-point: C^1 on (0, 1/8]
>>> r.status, str(r.value["certified"])
('certified', '(0, 1/8]')

Algorithm
---------
A stack of pieces, largest first. A closed rational box is certified by the smallest L whose
float Bernstein bound is below 1 and whose exact bound confirms it; a piece next to an open end by
the exact end test. A piece that fails is bisected at a short dyadic rational unless the float
norms ``min_L N_L`` are >= 1 at its two ends and its midpoint (then no L <= L_max certifies a
neighbourhood of those points and the piece is reported as a strip) or it is narrower than
``min_width``. Adjacent strips are merged; their ends are exact.

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Thm 3.3
(the norm test, binary); its m-ary form with the m-ary difference symbols (Hassan–Ivrissimitzis–
Dodgson–Sabin 2002).
"""

from __future__ import annotations

import time
from fractions import Fraction

import numpy as np
import sympy as sp

from ..algebra.algebraic import RealAlgebraic
from ..algebra.symbol import LaurentSymbol
from ..jsr._work import Work
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..stationary.difference import difference_symbol
from ..stationary.normbox import ParametricNorm
from ..algebra.reader import as_expr


def _dyadic_between(x: RealAlgebraic, y: RealAlgebraic) -> sp.Rational:
    """A dyadic rational with the smallest denominator strictly between ``x < y``."""
    fx, fy = float(x), float(y)
    k = 0
    while True:
        s = 2 ** k
        q = sp.Rational(int(np.floor(fx * s)) + 1, s)
        if float(q) < fy:
            Q = RealAlgebraic.rational(q)
            if x.compare(Q) < 0 < y.compare(Q):
                return q
        k += 1
        if k > 200:   # pragma: no cover - x, y closer than 2^-200
            from ..algebra.algebraic import rational_between

            return rational_between(x, y)


#: default work budget of :func:`ck_interior` and of its strip closing (units: see there)
DEFAULT_INTERIOR_BUDGET = 120_000
DEFAULT_STRIP_BUDGET = 30_000
#: work units of the norm tests (about a millisecond of CPU each on the reference machine), by the
#: size ``s = rows K^2`` of a parametric norm N_L (``rows`` coefficient polynomials of ``K`` coefficients):
#: building N_L ``2 + s / 6000``, a box test (float Bernstein screen, exact bound) ``0.1 + s / 50000``,
#: an end-piece test (exact signs and roots) ``5 + s / 10000``
BUILD_UNITS, BUILD_SIZE_PER_UNIT = 2.0, 6000.0
BOX_UNITS, BOX_SIZE_PER_UNIT = 0.1, 50000.0
END_UNITS, END_SIZE_PER_UNIT = 5.0, 10000.0


def _size(N: ParametricNorm) -> int:
    return len(N.C) * (N.n + 1) ** 2


#: the last parametric norms built (:func:`_parametric_norm`), least recently used first; at most
#: ``_NORMS_MAX_ENTRIES`` coefficients in all (about 60 MB; the norms for L = 1..12 of a 6-point family hold about
#: 750 000)
_NORMS: dict = {}
_NORMS_MAX_ENTRIES = 800_000


def _parametric_norm(am: LaurentSymbol, p: sp.Symbol, L: int, arity: int) -> ParametricNorm:
    """``ParametricNorm(am, p, L, arity)``, kept for the next C^j sets of the same family (a norm is not
    changed after it is built): an interval and a wider one, or a range and one of its strips, test the
    same norms."""
    key = (am.start, tuple(am.mask), p, L, arity)
    N = _NORMS.pop(key, None)
    if N is None:
        N = ParametricNorm(am, p, L, arity)
    _NORMS[key] = N
    total = sum(len(x.C) * (x.n + 1) for x in _NORMS.values())
    while total > _NORMS_MAX_ENTRIES and len(_NORMS) > 1:
        old = _NORMS.pop(next(iter(_NORMS)))
        total -= len(old.C) * (old.n + 1)
    return N


class _Norms:
    """``ParametricNorm`` for L = 1..L_max, built lazily, with float point evaluation; ``charge``
    bills a work budget for what is built and tested (fractions carried, whole units charged)."""

    def __init__(self, am, p, L_max, arity, work: Work | None = None):
        self.am, self.p, self.L_max, self.arity = am, p, L_max, arity
        self._cache: dict[int, ParametricNorm] = {}
        self.work, self._owed = work, 0.0

    def charge(self, units: float) -> None:
        if self.work is None:
            return
        self._owed += units
        if self._owed >= 1:
            self.work.charge(int(self._owed))
            self._owed -= int(self._owed)

    def __getitem__(self, L) -> ParametricNorm:
        if L not in self._cache:
            N = self._cache[L] = _parametric_norm(self.am, self.p, L, self.arity)
            self.charge(BUILD_UNITS + _size(N) / BUILD_SIZE_PER_UNIT)     # charged as built, kept or not
        return self._cache[L]

    def best_at(self, t: float) -> float:
        """``min_L N_L(t)`` in floating point (screening only)."""
        best = np.inf
        for L in range(1, self.L_max + 1):
            N = self[L]
            if not N.C:
                return 0.0
            powers = t ** np.arange(N.n + 1)
            vals = np.abs(N._Cf @ powers)
            best = min(best, float(np.add.reduceat(vals, N.starts).max()))
            if best < 1:
                return best
        return best


def ck_interior(a: LaurentSymbol, j: int, lo, hi, param=None, *, lo_open: bool = True, hi_open: bool = True,
                arity: int = 2, L_max: int = 12, min_width=None, max_pieces: int = 4000,
                budget: int = DEFAULT_INTERIOR_BUDGET, close_strips: bool = True,
                strip_budget: int = DEFAULT_STRIP_BUDGET) -> Result:
    """Certify ``C^j`` on the interval from ``lo`` to ``hi`` (exact ends) by parametric norm tests.

    ``value``: ``{"certified": IntervalSet, "strips": [(lo, hi), ...]}`` (exact sympy ends of the
    inconclusive strips). Status certified when no strip remains. With ``close_strips`` (any
    arity) each strip the norm tests leave is then tried with a parametric invariant polytope
    (:func:`analysis.regularity.strips.close_strip`: ``JSR(t) = rho(Pi(t))^(1/|Pi|) < 1`` for the
    ``m`` transition matrices of ``(1/m) a_{j+1}``, up to an end of eigenvalue type). ``witness["pieces"]``: each
    certified piece with its L and exact Bernstein bound, or the end test and the residue sums
    that reach 1 at the end.

    ``budget`` is in work units (counted, never timed): building each norm ``N_L`` and every test of
    a piece (one ``L``) cost units by the size of ``N_L`` (``BUILD_UNITS``, ``BOX_UNITS``, ``END_UNITS``:
    about a millisecond each on the reference machine); once it is spent, the pieces not examined are
    reported as strips.
    ``strip_budget`` (work units of :func:`~analysis.regularity.strips.close_strip`) is shared by the
    strips, at least 10 000 and at most what ``budget`` has left; ``provenance["work"]`` says what was
    spent, ``provenance["timing"]`` the wall-clock seconds (reported only).
    """
    if len(a.params) != 1:
        raise AnalysisError("the interior of a C^j set needs a family with exactly one free parameter")
    p = a.params[0]
    if param is not None and str(param) != p.name:
        raise AnalysisError(f"unknown parameter {str(param)!r} (the scheme's parameter is {p.name})")
    am = difference_symbol(a, j + 1) if arity == 2 else difference_symbol(a, j + 1, arity=arity)
    A, B = RealAlgebraic.from_expr(as_expr(lo)), RealAlgebraic.from_expr(as_expr(hi))
    if A.compare(B) >= 0:
        raise AnalysisError("the interval is empty")
    width = float(B) - float(A)
    min_width = sp.Rational(sp.nsimplify(as_expr(min_width))) if min_width is not None else None
    min_w = float(min_width) if min_width is not None else width / 2 ** 14
    t0 = time.perf_counter()          # timing only
    work = Work(budget)
    norms = _Norms(am, p, L_max, arity, work)
    # a piece: (left, right, kind) with left/right RealAlgebraic; kind: "box" (closed rational),
    # "left-end" (left open end), "right-end", "both" (both ends open)
    kind0 = {(True, True): "both", (True, False): "left-end", (False, True): "right-end",
             (False, False): "box"}[(lo_open, hi_open)]
    if kind0 == "box" and not (A.is_rational and B.is_rational):
        raise AnalysisError("a closed end of the interval must be rational")
    stack = [(A, B, kind0)]
    certified, strips = [], []
    n_pieces = 0
    while stack:
        u, v, kind = stack.pop()
        n_pieces += 1
        if n_pieces > max_pieces or work.exhausted:
            strips.append((u, v))
            continue
        w = float(v) - float(u)
        if kind == "both":
            m = _dyadic_between(u, v)
            M = RealAlgebraic.rational(m)
            stack += [(u, M, "left-end"), (M, v, "right-end")]
            n_pieces -= 1
            continue
        wit = _try_piece(norms, u, v, kind, L_max)
        if wit is not None:
            certified.append((u, v, kind, wit))
            continue
        fu = float(u) if kind != "left-end" else None
        fv = float(v) if kind != "right-end" else None
        if w < min_w:
            strips.append((u, v))
            continue
        m = _dyadic_between(u, v)
        pts = [x for x in (fu, float(m), fv) if x is not None]
        if kind == "box" and all(norms.best_at(x) >= 1 for x in pts):
            strips.append((u, v))      # no L <= L_max reaches below 1 at these points
            continue
        M = RealAlgebraic.rational(m)
        left_kind = "left-end" if kind == "left-end" else "box"
        right_kind = "right-end" if kind == "right-end" else "box"
        # the larger piece is processed first (stack: push it last)
        stack += [(M, v, right_kind), (u, M, left_kind)] if kind == "right-end" else \
                 [(u, M, left_kind), (M, v, right_kind)]
    closed, reasons = [], []
    spent = work.spent
    if close_strips and strips:
        strips, closed, reasons, used = _close_strips(am, p, strips, A, B, lo_open, hi_open,
                                                      max(10_000, min(strip_budget, work.left)), arity)
        spent += used
        certified += [(u, v, kind, {"polytope": wit}) for u, v, kind, wit in closed]
    res = _assemble(certified, strips, A, B, lo_open, hi_open, p, j, arity, L_max, min_w, n_pieces,
                    spent, time.perf_counter() - t0)
    if closed:
        res.provenance["method"] += ("; the strips next to ends of eigenvalue type closed by a parametric invariant "
                                     "polytope (analysis.regularity.strips.close_strip)")
    if reasons:
        res.provenance["strips not closed by the invariant polytope"] = reasons
    return res


def _close_strips(am, p, strips, A, B, lo_open, hi_open, budget, arity=2):
    """Try :func:`analysis.regularity.strips.close_strip` on each merged strip, one after the other
    from one work budget; returns the strips left, the closed ones as ``(u, v, kind, witness)``, why
    each strip left was not closed, and the work units spent."""
    import functools

    from .strips import close_strip

    key = functools.cmp_to_key(lambda x, y: x[0].compare(y[0]))
    merged = []
    for u, v in sorted(strips, key=key):
        if merged and merged[-1][1].compare(u) == 0:
            merged[-1] = (merged[-1][0], v)
        else:
            merged.append((u, v))
    left, closed, reasons = [], [], []
    work = Work(budget)
    for u, v in merged:
        lo_o = lo_open and u.compare(A) == 0
        hi_o = hi_open and v.compare(B) == 0
        rest = work.left
        try:
            r = close_strip(am, p, u.expr, v.expr, lo_open=lo_o, hi_open=hi_o, budget=rest, arity=arity) \
                if rest > 1000 else {"closed": False, "reason": "work budget exhausted"}
        except (AnalysisError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:   # no certificate, say why
            r = {"closed": False, "reason": f"the polytope construction failed: {type(exc).__name__}: {exc}"}
        work.charge(r.get("work", 0))
        if r["closed"]:
            kind = {(False, False): "strip", (True, False): "strip-left-end", (False, True): "strip-right-end",
                    (True, True): "strip-both"}[(lo_o, hi_o)]
            wit = {"product": "".join(map(str, reversed(r["word"]))), "pieces": len(r["pieces"]),
                   "max image norm <=": max(x["max image norm <="] for x in r["pieces"]),
                   "mu": r["mu"], "work": r["work"]}
            closed.append((u, v, kind, wit))
        else:
            left.append((u, v))
            reasons.append(f"[{sp.sstr(u.expr)}, {sp.sstr(v.expr)}]: {r['reason']}")
    return left, closed, reasons, work.spent


def _try_piece(norms: _Norms, u: RealAlgebraic, v: RealAlgebraic, kind: str, L_max: int):
    if kind == "box":
        for L in range(1, L_max + 1):
            norms.charge(BOX_UNITS + _size(norms[L]) / BOX_SIZE_PER_UNIT)
            b = norms[L].box_below(u.a, v.a)
            if b is not None:
                return {"L": L, "bound": b}
        return None
    e, wq, side = (u, v.a, 1) if kind == "left-end" else (v, u.a, -1)
    ef = float(e)
    box = (min(ef, float(wq)), max(ef, float(wq)))
    for L in range(1, L_max + 1):
        N = norms[L]
        norms.charge(BOX_UNITS + _size(N) / BOX_SIZE_PER_UNIT)
        if N.float_box_bound(Fraction(box[0]), Fraction(box[1])) > 1 + 1e-6:
            continue
        norms.charge(END_UNITS + _size(N) / END_SIZE_PER_UNIT)
        wit = N.end_piece(e, wq, side)
        if wit is not None:
            return {"L": L, "end": "left" if side > 0 else "right", **wit}
    return None


def _assemble(certified, strips, A, B, lo_open, hi_open, p, j, arity, L_max, min_w, n_pieces, work, seconds):
    from ..algebra.algebraic import IntervalSet
    import functools

    key = functools.cmp_to_key(lambda x, y: x[0].compare(y[0]))
    certified.sort(key=key)
    strips.sort(key=key)
    parts = []
    for u, v, kind, wit in certified:
        lc = kind in ("box", "right-end", "strip", "strip-right-end")
        hc = kind in ("box", "left-end", "strip", "strip-left-end")
        if parts and parts[-1][1].compare(u) == 0:
            lo0, _, lc0, _ = parts[-1]
            parts[-1] = (lo0, v, lc0, hc)
        else:
            parts.append((u, v, lc, hc))
    merged = []
    for u, v in strips:
        if merged and merged[-1][1].compare(u) == 0:
            merged[-1] = (merged[-1][0], v)
        else:
            merged.append((u, v))
    pieces = [{"from": sp.sstr(u.expr), "to": sp.sstr(v.expr), "kind": kind,
               **{k: (sp.sstr(sp.Rational(x.numerator, x.denominator)) if isinstance(x, Fraction) else x)
                  for k, x in wit.items()}} for u, v, kind, wit in certified]
    strip_list = [(u.expr, v.expr) for u, v in merged]
    status = CERTIFIED if not merged else INCONCLUSIVE
    prov = {"method": f"Dyn-Levin norm test ||(1/{arity} S_a{j + 1})^L||_inf < 1 with the coefficients exact "
                      f"polynomials in {p.name}: exact Bernstein bounds on rational boxes, exact sign and root "
                      f"isolation on the pieces next to open ends (L <= {L_max})",
            "L_max": L_max, "min_width": min_w, "pieces_tried": n_pieces, "work": work,
            "timing": {"seconds": round(seconds, 2)}}
    if merged:
        prov["message"] = (f"not covered by the norm tests with L <= {L_max}: "
                           + ", ".join(f"[{sp.sstr(x)}, {sp.sstr(y)}] (width {float(y) - float(x):.3g})"
                                       for x, y in strip_list)
                           + "; next to an end of eigenvalue type no finite L reaches it")
    return Result(value={"certified": IntervalSet(parts), "strips": strip_list}, status=status,
                  witness={"pieces": pieces, "parameter": p.name, "j": j, "arity": arity,
                           "interval": (A.expr, B.expr, lo_open, hi_open)},
                  provenance=prov)
