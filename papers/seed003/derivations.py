"""Seed 003: the computations several claims share (cached per run), the constants of the
checks, and the curve comparisons of Sections 6-7.

* rule (1) (``dfh-chaikin-perturbation``), the limit of the divided differences e = 2a/(1+z);
* the C^2 set of rule (1): certified grid verdicts and boundaries near 0 (``_c2_range``, ~25 s),
  C^2 proven on the whole of (0, 1/50) (``_c2_interval``), the exact Dyn-Levin norm sets
  (``_norm_sets``);
* the deviation of the refined curves of (4), (5) and [11] from circles, ellipses, cardioid,
  astroid and lemniscate (``_deviation_table``) and who wins (``_best``).
"""

from __future__ import annotations

import functools

import sympy as sp

from schemes.seed003 import HYPERBOLIC_NORMALIZED, JENA_11, TRIGONOMETRIC, TRIGONOMETRIC_NORMALIZED

_OM_HI = (sp.sqrt(6) - 1) / 80          # the paper's right end (sqrt(6) - 1)/80
_VALS = {"alpha": sp.pi / 5, "omega": sp.Rational(1, 100)}
_C2_PROVEN_HI = sp.Rational(1, 50)        # C^2 of rule (1) is proven on all of (0, 1/50)


def _s(x) -> str:
    return sp.sstr(sp.sympify(x))


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


# -------------------------------------------------------------------------- Sections 6-7
_CMP = (("trigonometric (4)", TRIGONOMETRIC_NORMALIZED), ("hyperbolic (5)", HYPERBOLIC_NORMALIZED),
        ("[11] (reconstructed)", JENA_11))
_CMP_OMEGAS = (sp.Integer(0), sp.Rational(1, 200), sp.Rational(1, 100), sp.Rational(3, 200))
#: alpha per curve: 2 pi / 10 (10 control points) for the conics and the cardioid; the paper's
#: alpha for the astroid (pi/5, Fig. 4) and the lemniscate (3 pi/20, Fig. 5).
_CMP_ALPHA = {"circle": sp.pi / 5, "ellipse": sp.pi / 5, "cardioid": sp.pi / 5, "astroid": sp.pi / 5,
              "lemniscate": 3 * sp.pi / 20}


@functools.lru_cache(maxsize=None)
def _deviation_table(curve: str):
    from analysis.levels.reproduction import curve_deviation

    out = {}
    for name, s in _CMP:
        for om in (_CMP_OMEGAS if s is not JENA_11 else (None,)):
            vals = {"alpha": _CMP_ALPHA[curve]}
            if om is not None:
                vals["omega"] = om
            out[(name, om)] = curve_deviation(s, curve, vals, points=10, steps=6)
    return out


def _best(curve, om):
    t = _deviation_table(curve)
    row = {name: t[(name, om if name != "[11] (reconstructed)" else None)].value for name, _ in _CMP}
    lo = min(row.values())
    tied = [n for n, v in row.items() if v <= lo + 1e-12]      # rounding-level differences are ties
    return (tied[0] if len(tied) == 1 else "tie: " + " = ".join(tied)), row


def _cmp_table(curves):
    rows = [("curve", "omega") + tuple(n for n, _ in _CMP) + ("best",)]
    for curve in curves:
        for om in _CMP_OMEGAS:
            best, row = _best(curve, om)
            rows.append((curve, _s(om)) + tuple(f"{row[n]:.3e}" for n, _ in _CMP) + (best,))
    return tuple(rows)


def _winners(wins) -> str:
    by: dict = {}
    for (c, o), w in wins.items():
        by.setdefault(w, []).append(f"{c}@{o}")
    return "; ".join(f"{w}: {', '.join(v)}" for w, v in by.items())
