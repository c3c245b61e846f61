"""Seed 004's own inequalities (5.6)-(5.9) between the eigenvalues of S_l,mu (Sect. 5.2): the paper
orders ``|1/64| > |lambda_7| > |lambda_8| > |lambda_9|`` with ``lambda_7 = -7mu/32`` and
``lambda_8,9 = (7mu + 1 ± sqrt(833mu^2 + 70mu + 1))/128``; each is an exact set in mu compared with
the printed (rounded, sign-garbled) intervals. Genuinely special: the necessary condition itself is
the kind "eigenvalue inequality" (``004:Theorem5.3``).

Examples
--------
>>> str(inequality_sets()["5.6"])
'(-1/14, 1/14)'
"""

from __future__ import annotations

import functools

import sympy as sp

from analysis import claims as C
from analysis.algebra.algebraic import IntervalSet, RealAlgebraic as RA, sign as _sign
from analysis.claims.kinds.spectral import set_numbers
from schemes.seed004 import MU

_C8, _D8 = 7 * MU + 1, 833 * MU ** 2 + 70 * MU + 1
_R_PLUS = (-35 + 14 * sp.sqrt(2)) / 833     # -0.01824851156: root of 833mu^2 + 70mu + 1
_R_MINUS = (-35 - 14 * sp.sqrt(2)) / 833    # -0.06578510188


def _mod2(which: int, v):
    """|lambda|^2 * 128^2 for lambda_7 (which=7), lambda_8 (+ root), lambda_9 (- root) at mu = v."""
    c, D = _C8.subs(MU, v), _D8.subs(MU, v)
    if which == 7:
        return 784 * v ** 2
    if _sign(D) >= 0:
        return sp.expand((c + (1 if which == 8 else -1) * sp.sqrt(D)) ** 2)
    return sp.expand(c ** 2 - D)


def _gt(a: int, b: int, v) -> bool:
    return _sign(sp.expand(_mod2(a, v) - _mod2(b, v))) > 0


@functools.lru_cache(maxsize=None)
def inequality_sets() -> dict:
    """The exact sets of (5.6) |1/64| > |lambda_7|, (5.7) |lambda_7| > |lambda_8|, (5.8)
    |lambda_8| > |lambda_9| and their intersection (5.9)."""
    P = functools.partial(sp.Poly, gens=MU)
    c6 = [P(784 * MU ** 2 - 4)]
    c7 = [P(_D8), P(MU), P(_C8), P((784 * MU ** 2 - _C8 ** 2 - _D8) ** 2 - 4 * _C8 ** 2 * _D8), P(_C8 ** 2 - _D8 - 784 * MU ** 2)]
    return {"5.6": C.exact_set(lambda v: _sign(4 - _mod2(7, v)) > 0, c6),
            "5.7": C.exact_set(lambda v: _gt(7, 8, v), c7),
            "5.8": C.exact_set(lambda v: _gt(8, 9, v), [P(_D8), P(_C8)]),
            "5.9": C.exact_set(lambda v: _sign(4 - _mod2(7, v)) > 0 and _gt(7, 8, v) and _gt(8, 9, v), c6 + c7)}


def _approx(iset) -> str:
    f = lambda x, inf: inf if x is None else f"{float(x):.10g}"   # noqa: E731
    return " ∪ ".join(("[" if lc else "(") + f"{f(lo, '-oo')}, {f(hi, 'oo')}" + ("]" if hc else ")")
                      for lo, hi, lc, hc in iset.parts) or "empty"


def _check(key: str, readings: dict):
    """The exact set of ``key`` and, for each reading of the printed result, whether it equals it."""
    s = inequality_sets()[key]
    verdicts = {}
    for name, parts in readings.items():
        iset = IntervalSet([(None if lo is None else RA.from_expr(lo), None if hi is None else RA.from_expr(hi),
                             False, False) for lo, hi in parts])
        verdicts[name] = len(iset.parts) == len(s.parts) and all(
            (x is None) == (y is None) and (x is None or x.compare(y) == 0)
            for p, q in zip(iset.parts, s.parts) for x, y in zip(p[:2], q[:2]))
    ev = [C.Evidence(f"exact set of ({key})", result=C.exact_result(s, "exact sign decisions at rationals and algebraic "
                                                                         "critical points (analysis.claims.model.exact_set)"),
                     text=f"{s}  ≈  {_approx(s)}"),
          C.Evidence("readings of the printed result", table=(("reading", "equals the exact set"),) + tuple(
              (k, "yes" if v else "no") for k, v in verdicts.items()))]
    return s, verdicts, ev, set_numbers("set", s)


def _ineq_5_6():
    s, v, ev, nums = _check("5.6", {"-1/14 < mu < 1/14": [(-sp.Rational(1, 14), sp.Rational(1, 14))]})
    if all(v.values()):
        return C.certified("(5.6) is exact: |1/64| > |7mu/32| iff -1/14 < mu < 1/14.", evidence=ev, numbers=nums)
    return C.refuted("(5.6) differs", str(s), evidence=ev, numbers=nums)


def _ineq_5_7():
    lo, hi = sp.Rational(-1290803377, 10 ** 9), sp.Rational(7193748053, 10 ** 10)
    s, v, ev, nums = _check("5.7", {
        "pieces: (-1.290803377, -0.06578510188) ∪ (-0.01824851156, 0.7193748053)": [(lo, _R_MINUS), (_R_PLUS, hi)],
        "combined (5.7): -1.290803377 < mu < 0.7193748053": [(lo, hi)]})
    good = [k for k, ok in v.items() if ok]
    return C.refuted(f"|lambda_7| > |lambda_8| (lambda_8 the eigenvalue with +sqrt; moduli for complex pairs) "
                     f"holds exactly for mu in {s} ≈ {_approx(s)}. "
                     + (f"Readings equal to it: {good}" if good else "No reading of the printed pieces or of the combined (5.7) equals it")
                     + "; moreover a union of two disjoint intervals cannot be 'combined' into one interval.",
                     corrected=f"(5.7) holds exactly for mu in {s}", evidence=ev, numbers=nums)


def _ineq_5_8():
    s, v, ev, nums = _check("5.8", {
        "pieces: (-1/7, -0.06578510188) ∪ (-0.01824851156, oo)": [(-sp.Rational(1, 7), _R_MINUS), (_R_PLUS, None)],
        "combined (5.8) read as -1/7 < mu < 0.06578510188": [(-sp.Rational(1, 7), -_R_MINUS)],
        "combined (5.8) read as -1/7 < mu < -0.06578510188": [(-sp.Rational(1, 7), _R_MINUS)]})
    good, bad = [k for k, ok in v.items() if ok], [k for k, ok in v.items() if not ok]
    return C.refuted(f"|lambda_8| > |lambda_9| holds exactly on {s} ≈ {_approx(s)}: between the roots of "
                     "833mu^2 + 70mu + 1 the pair is complex with equal moduli. Readings that equal the exact "
                     f"set: {good or 'none'}; readings that do not: {bad}.",
                     corrected=f"(5.8) holds exactly for mu in {s}", evidence=ev, numbers=nums)


def _ineq_5_9():
    s = inequality_sets()["5.9"]
    ev = [C.Evidence("exact intersection of (5.6), (5.7), (5.8)", result=C.exact_result(s, "exact_set"),
                     text=f"{s} ≈ {_approx(s)}")]
    return C.refuted(f"The common part of (5.6)-(5.8) is {s}, not -0.1428571429 < mu < 0.06578510188 "
                     "(which is not even inside (5.6): -1/7 < -1/14).",
                     corrected=f"(5.6) ∩ (5.7) ∩ (5.8) = {s}", evidence=ev, numbers=set_numbers("set", s))
