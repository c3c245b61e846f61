"""Seed 003: the computations several claims share (cached per run) and the constants of the
checks.

* rule (1) (``dfh-chaikin-perturbation``), the limit of the divided differences e = 2a/(1+z);
* the C^2 set of rule (1): certified grid verdicts and boundaries near 0 (``_c2_range``, ~25 s),
  C^2 proven on the whole of (0, 1/50) (``_c2_interval``), the exact Dyn-Levin norm sets
  (``_norm_sets``).
"""

from __future__ import annotations

import functools

import sympy as sp

from schemes.seed003 import TRIGONOMETRIC
from analysis.algebra.reader import as_expr

_OM_HI = (sp.sqrt(6) - 1) / 80          # the paper's right end (sqrt(6) - 1)/80
_VALS = {"alpha": sp.pi / 5, "omega": sp.Rational(1, 100)}
_C2_PROVEN_HI = sp.Rational(1, 50)        # C^2 of rule (1) is proven on all of (0, 1/50)


def _s(x) -> str:
    return sp.sstr(as_expr(x))


def _f(x, d: int = 10) -> str:
    return f"{float(x):.{d}g}"


def _stationary():
    from schemes import get

    return get("dfh-chaikin-perturbation").symbol


def _diff_limit():
    """e = lim e^n = 2 a/(1+z): the first divided difference scheme of rule (1) (exact)."""
    return TRIGONOMETRIC.difference(1).limit()


@functools.lru_cache(maxsize=None)
def _c2_range():
    """Certified C^2 verdicts of rule (1) at grid points of (-1/20, 1/20) and certified boundaries
    (the ~25 s computation, shared by several claims): the interior between grid points is sampled."""
    from analysis.regularity.ranges import ck_parameter_set

    return ck_parameter_set(_stationary(), 2, within=(sp.Rational(-1, 20), sp.Rational(1, 20)), grid=10)


@functools.lru_cache(maxsize=None)
def _c2_interval():
    """C^2 proven on the whole open interval (0, 1/50) (exact norm sets + Arb norm boxes)."""
    from analysis.regularity.ranges import verify_smoothness_interval

    return verify_smoothness_interval(_stationary(), 2, (0, _C2_PROVEN_HI))


def _range_statement(star, right) -> str:
    """What analysis.regularity.ranges.ck_parameter_set certifies, and no more."""
    return (f"C^2 at every certified grid point of (0, omega*) and not C^2 at every grid point outside it "
            f"(in (-1/20, 1/20)); both boundaries 0 and omega* = {_s(star)} ≈ {_f(star, 12)} certified on both "
            f"sides within 1e-8 (omega* exact: {right['how']}); the interior between grid points is sampled, "
            "not proven")


def _interval_statement(r) -> str:
    if r.status == "certified" and r.value is True:
        return (f"C^2 is proven on the whole of (0, {_s(_C2_PROVEN_HI)}) ({r.witness.get('route')}; "
                "analysis.regularity.ranges.verify_smoothness_interval)")
    return f"C^2 on the whole of (0, {_s(_C2_PROVEN_HI)}): {r.status} (analysis.regularity.ranges.verify_smoothness_interval)"


@functools.lru_cache(maxsize=None)
def _norm_sets():
    from analysis.stationary.normset import norm_solution_set

    a = _stationary()
    return {L: norm_solution_set(a, m=3, L=L, within=(0, sp.oo)) for L in (1, 2, 3)}
