"""Lemma checkers: inequalities ``f(n, p) <= g(n, p)`` for all ``n >= n0`` over parameter boxes, and
exact identities.

:func:`check_inequality` proves an inequality for every integer level ``n >= n0`` and every
parameter in a box, refutes it with a certified counterexample, or reports the worst case found.
:func:`check_identity` proves an identity exactly (sympy) or refutes it with a point where ball
arithmetic proves the two sides differ.

Examples
--------
>>> import sympy as sp
>>> from analysis.levels.level_dependent import N
>>> a = sp.Symbol("alpha", positive=True)
>>> r = check_inequality(sp.Rational(3, 4), sp.sin(3 * a / 2 ** (N + 2)) / sp.sin(a / 2 ** N),
...                      n0=1, box={"alpha": ("1/100", "1")})
>>> r.status, r.witness["tail"]["method"]
('certified', 'Taylor model in h: leading coefficient > remainder')
>>> r = check_inequality(sp.sin(a / 2 ** (N + 2)) / sp.sin(a / 2 ** N), 1 / (4 * sp.cosh(a / 2 ** N)),
...                      n0=1, box={"alpha": ("1/100", "1")})
>>> r.status, r.witness["counterexample"]["n"]
('refuted', 1)
>>> check_identity(sp.sin(2 * a), 2 * sp.sin(a) * sp.cos(a)).status
'certified'

Algorithm
---------
Levels ``n0 <= n < N``: ``D = g - f`` (written with ``sin u = u sinc u``, so no dependency blow-up
at small ``h``) is enclosed in arb over the box; a box with ``D > 0`` (``>= 0`` for ``<=``) is
proven, otherwise ``D`` is enclosed at the box midpoint: ``D < 0`` there is a certified
counterexample; otherwise the box is bisected (up to ``max_depth``). Levels ``n >= N``: a
rigorous Taylor model of ``D`` in ``h = 2^-n`` on ``[0, 2^-N]`` (exact Taylor coefficients from
sympy, Cauchy remainder from :func:`analysis.levels.taylor_model.taylor_models`): if ``D(0) > A h_N^q`` or
``D(0) = 0`` identically and the leading coefficient exceeds the remainder bound, the
inequality holds for every ``n >= N``.

References
----------
F. Johansson, *Arb*, IEEE Trans. Comput. 66 (2017). W. Tucker, *Validated Numerics*, Princeton
(2011), ch. 5 (branch and bound with interval arithmetic).
"""

from __future__ import annotations

import random
from typing import Any, Mapping

import flint
import sympy as sp

from .level_dependent import H, LevelDependentScheme, _ball, _to_ball, ball_to_interval, entire_form, to_h, workprec
from .taylor_model import taylor_models
from .. import progress
from ..result import CERTIFIED, INCONCLUSIVE, REFUTED, AnalysisError, Result
from .divided import _exact_zero  # noqa: F401 - re-exported: the exact zero test lives in .divided
from ..algebra.reader import as_expr


def _parse_box(box: Mapping[str, Any] | None) -> dict:
    out = {}
    for k, v in dict(box or {}).items():
        if isinstance(v, (tuple, list)):
            lo, hi = (as_expr(x, what=f"end of the box of {k}") for x in v)
            if not bool(lo <= hi):
                raise AnalysisError(f"empty box for {k}: [{lo}, {hi}]")
            out[str(k)] = (lo, hi)
        else:
            out[str(k)] = as_expr(v, what=f"value of {k}")
    return out


def _mid(box: dict) -> dict:
    return {k: ((v[0] + v[1]) / 2 if isinstance(v, tuple) else v) for k, v in box.items()}


def _bisect(box: dict) -> list[dict]:
    k = max((k for k, v in box.items() if isinstance(v, tuple)),
            key=lambda k: float(box[k][1] - box[k][0]), default=None)
    if k is None:
        return []
    lo, hi = box[k]
    m = (lo + hi) / 2
    if bool(lo > 0) and bool(hi > 2 * lo):  # geometric bisection: the relative width matters
        m = sp.Rational(str(sp.N(sp.sqrt(lo * hi), 15)))
    a, b = dict(box), dict(box)
    a[k], b[k] = (lo, m), (m, hi)
    return [a, b]


def _enc(D: sp.Expr, box: dict, n: int, prec: int):
    with workprec(prec):
        env = {k: _to_ball(v, False) for k, v in box.items()}
        env["h"] = flint.arb(2) ** (-n)
        return _ball(D, env, False)


def _interval(b) -> tuple:
    return tuple(float(x) for x in ball_to_interval(b)) if b.is_finite() else (float("-inf"), float("inf"))


def _check_D(D: sp.Expr, box: dict, n0: int, strict: bool, N: int, max_depth: int, pieces: int) -> dict:
    """Decide D(h_n, p) > 0 (strict) or >= 0 for n >= n0, p in box."""
    Dorig, D = D, entire_form(D)
    done = n0
    result = None
    for NN in sorted({max(n0, x) for x in (4, 8, N)}):
        result = _levels(D, box, done, NN, strict, max_depth)
        if result["verdict"] == "refuted":
            return result
        done = NN
        tail = _tail(Dorig, box, NN, strict, pieces)
        if tail["verdict"] == "refuted":
            return tail
        if tail["verdict"] == "proven" and not result["unproven"]:
            return {"verdict": "proven", "worst": result["worst"], "tail": tail}
    return {"verdict": "unknown", "worst": result["worst"], "unproven": result["unproven"][:5],
            "tail": tail}


def _levels(D, box, n_from, n_to, strict, max_depth) -> dict:
    worst = None
    unproven = []
    progress.stage(f"levels {n_from}..{n_to - 1}: level", n_to - n_from)
    for n in range(n_from, n_to):
        prec = 64 + 2 * n + 32
        stack = [(box, 0)]
        while stack:
            b, depth = stack.pop()
            e = _enc(D, b, n, prec)
            ok = e.is_finite() and (e > 0 if strict else e >= 0)
            if ok:
                continue
            pt = _mid(b)
            ep = _enc(D, pt, n, prec + 64)
            if ep.is_finite() and (ep < 0 or (strict and ep.is_exact() and ep == 0)):
                return {"verdict": "refuted", "counterexample": {"n": n, "point": pt,
                                                                 "g_minus_f": ball_to_interval(ep)}}
            if worst is None or (ep.is_finite() and float(ep.mid()) < worst["g_minus_f"]):
                worst = {"n": n, "point": pt, "g_minus_f": float(ep.mid())}
            if depth < max_depth and _bisect(b):
                stack.extend((c, depth + 1) for c in _bisect(b))
            else:
                unproven.append({"n": n, "box": b})
                break
        progress.step()
    return {"verdict": "levels", "worst": worst, "unproven": unproven}


def _tail(D: sp.Expr, box: dict, N: int, strict: bool, pieces: int) -> dict:
    if H not in D.free_symbols:
        return {"verdict": "proven", "method": "no dependence on n"}
    params = sorted(D.free_symbols - {H}, key=lambda s: s.name)
    s = LevelDependentScheme((D,), 0, tuple(params), slug="inequality")
    D0 = s._limits[0]
    try:
        q = s.order()
    except AnalysisError:
        q = None
    box = {k: v for k, v in box.items() if k in {p.name for p in params}}
    boxed = [k for k, v in box.items() if isinstance(v, tuple)]
    subs = [box]
    if boxed and pieces > 1:
        from .series import _split

        subs = _split(box, pieces)
    stack = [(b, 0) for b in subs]
    progress.stage(f"tail n >= {N}: boxes")
    while stack:
        b, depth = stack.pop()
        progress.step()
        with workprec(128):
            hN = flint.arb(2) ** (-N)
            env = {k: _to_ball(v, False) for k, v in b.items()}
            d0 = _ball(D0, env, False)
            if q is None:
                if d0 > 0 or (not strict and d0 >= 0):
                    continue
                return {"verdict": "unknown", "method": "stationary"}
            try:
                mdl = taylor_models(s, b, J=q + 3)[0]
            except AnalysisError:
                if depth < 4 and _bisect(b):
                    stack.extend((c, depth + 1) for c in _bisect(b))
                    continue
                return {"verdict": "unknown", "method": "no Taylor model on this box"}
            A = mdl.abs_upper_over(q, hN) * hN ** q
            if d0 > A:
                continue
            if sp.simplify(D0) == 0:
                lead = mdl.coeffs[q]
                E = mdl.abs_upper_over(q + 1, hN) * hN
                if lead > E:
                    continue
                if lead < -E:
                    # D(h) < 0 for all small h: find a certified counterexample level
                    pt = _mid(b)
                    for n in range(N, N + 200, 7):
                        ep = _enc(entire_form(D), pt, n, 64 + 2 * n + 64)
                        if ep < 0:
                            return {"verdict": "refuted", "counterexample": {
                                "n": n, "point": pt, "g_minus_f": ball_to_interval(ep)}}
            elif d0 < 0:
                return {"verdict": "refuted", "counterexample": {"n": "oo (limit)", "point": b,
                                                                 "g_minus_f": ball_to_interval(d0)}}
            if depth < 4 and _bisect(b):
                stack.extend((c, depth + 1) for c in _bisect(b))
                continue
            return {"verdict": "unknown", "method": "Taylor model too weak on a sub-box", "box": b}
    return {"verdict": "proven", "N": N, "order": q,
            "method": ("Taylor model in h: leading coefficient > remainder" if sp.simplify(D0) == 0
                       else "Taylor model in h: D(0) > remainder")}


def check_inequality(lhs, rhs, n0: int = 0, box: Mapping[str, Any] | None = None, *,
                     strict: bool = False, N: int = 12, max_depth: int = 10, pieces: int = 8,
                     claim: str = "") -> Result:
    """Prove ``lhs <= rhs`` (``<`` with ``strict``) for all integers ``n >= n0`` and the box.

    ``lhs``/``rhs`` are sympy expressions (or strings) in the level ``n`` (or ``h = 2^-n``) and
    the parameters; ``box`` maps parameter names to exact values or closed ``(lo, hi)`` boxes.
    ``lhs = Abs(u)`` is checked as ``u <= rhs`` and ``-u <= rhs``.

    Certified (proven), refuted (``witness["counterexample"]``: a level and a point where ball
    arithmetic proves ``lhs > rhs``), or inconclusive with the worst case found.
    """
    if isinstance(n0, bool) or not isinstance(n0, int) or n0 < 0:
        raise AnalysisError(f"n0 must be a non-negative integer level, not {n0!r}")
    L, R = to_h(lhs), to_h(rhs)
    bx = _parse_box(box)
    free = {s.name for s in (L.free_symbols | R.free_symbols) - {H}}
    missing = free - set(bx)
    if missing:
        raise AnalysisError(f"give a value or a box for {', '.join(sorted(missing))}")
    prov = {"method": "arb branch and bound (n < N) + Taylor model in h (n >= N)", "n0": n0, "N": N,
            "box": {k: v for k, v in bx.items()}}
    parts = [R - L.args[0], R + L.args[0]] if isinstance(L, sp.Abs) else [R - L]
    outs = []
    for D in parts:
        outs.append(_check_D(D, bx, n0, strict, N, max_depth, pieces))
    rel = "<" if strict else "<="
    stmt = f"{sp.sstr(lhs)} {rel} {sp.sstr(rhs)} for n >= {n0}"
    for o in outs:
        if o["verdict"] == "refuted":
            return Result(value=False, status=REFUTED,
                          witness={"claim": claim, "statement": stmt, "counterexample": o["counterexample"]},
                          provenance=prov)
    if all(o["verdict"] == "proven" for o in outs):
        return Result(value=True, status=CERTIFIED,
                      witness={"claim": claim, "statement": stmt, "tail": outs[0]["tail"]},
                      provenance=prov)
    worst = [o.get("worst") for o in outs]
    return Result(value=None, status=INCONCLUSIVE,
                  witness={"claim": claim, "statement": stmt, "worst": worst,
                           "details": [{k: v for k, v in o.items() if k != "worst"} for o in outs],
                           "advice": "raise max_depth / pieces, or shrink the box"},
                  provenance=prov)


def check_identity(lhs, rhs, *, claim: str = "", samples: int = 12, seed: int = 3) -> Result:
    """Prove ``lhs == rhs`` exactly (sympy) or refute it with a certified nonzero difference.

    Free symbols other than ``z`` and ``h`` are parameters; counterexamples are searched at
    rational points (``z`` and ``h`` too), and certified by ball arithmetic.
    """
    L, R = to_h(lhs), to_h(rhs)
    diff = as_expr(L - R)
    stmt = f"{sp.sstr(lhs)} == {sp.sstr(rhs)}"
    if _exact_zero(diff):
        return Result(value=True, status=CERTIFIED, witness={"claim": claim, "statement": stmt},
                      provenance={"method": "exact sympy simplification to 0"})
    rng = random.Random(seed)
    syms = sorted(diff.free_symbols, key=lambda s: s.name)
    for _ in range(samples):
        pt = {s.name: sp.Rational(rng.randint(1, 97), rng.choice([97, 193, 389])) for s in syms}
        try:
            with workprec(128):
                b = _ball(entire_form(diff), {k: _to_ball(v, True) for k, v in pt.items()}, True)
        except (AnalysisError, ZeroDivisionError):
            continue
        if b.is_finite() and not b.contains(0):
            return Result(value=False, status=REFUTED,
                          witness={"claim": claim, "statement": stmt, "point": pt,
                                   "difference": str(b),
                                   "simplified_difference": sp.simplify(diff)},
                          provenance={"method": "acb ball evaluation at a rational point"})
    return Result(value=None, status=INCONCLUSIVE, witness={"claim": claim, "statement": stmt},
                  provenance={"method": "no exact proof, no certified counterexample"})
