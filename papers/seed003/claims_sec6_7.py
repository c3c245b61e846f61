"""Seed 003, Sections 6-7: which form constructs circles and ellipses, and cardioid, astroid and
lemniscate, best (numerical comparisons of the refined curves)."""

from __future__ import annotations

import sympy as sp

from analysis import claims as C
from schemes.seed003 import ALPHA, JENA_11

from .derivations import _CMP, _CMP_OMEGAS, _best, _cmp_table, _deviation_table, _s, _winners
from .figures import _cmp_figure, _curves_figure


def _sec6_conics():
    from analysis.levels.reproduction import generation

    curves = ("circle", "ellipse")
    gens = {(n, _s(om)): generation(s, [sp.I * ALPHA, -sp.I * ALPHA], {"omega": om} if s is not JENA_11 else None)
            for n, s in _CMP[:1] + _CMP[2:] for om in ((0, sp.Rational(1, 100)) if s is not JENA_11 else (0,))}
    wins = {(c, _s(om)): _best(c, om)[0] for c in curves for om in _CMP_OMEGAS}
    trig_wins = [k for k, v in wins.items() if v == "trigonometric (4)"]
    ev = [C.Evidence("deviation after 6 steps from 10 control points on the curve (alpha = 2 pi/10)",
                     table=_cmp_table(curves), result=_deviation_table("circle")[("trigonometric (4)", sp.Integer(0))],
                     text="value: maximal relative radial deviation (shape; 0 = an exact circle/ellipse, whatever its size)")]
    for (n, om), r in gens.items():
        ev.append(C.Evidence(f"exact generation of cos/sin (alpha x): {n}, omega = {om}", result=r, text=r.status))
    nums = [C.Number(f"{c}.{n}.omega={_s(om)}", _deviation_table(c)[(n, om if s is not JENA_11 else None)].value, tol=1e-6)
            for c in curves for n, s in _CMP for om in ((sp.Integer(0), sp.Rational(1, 100)) if s is not JENA_11 else (None,))]
    gtxt = "; ".join(f"{n} omega = {om}: {r.status}" for (n, om), r in gens.items())
    return C.Verdict("numerical",
                     f"Not as a general statement: (4) is strictly closest in {len(trig_wins)} of {len(wins)} "
                     f"(curve, omega) cases ({', '.join(f'{c} at omega = {o}' for c, o in trig_wins) or 'none'}); "
                     f"winners: {_winners(wins)}. Exact generation of cos/sin(alpha x): {gtxt} — (4) generates "
                     "circles only at omega = 0, where it ties with [11] in shape; [11] (interpolatory, reconstructed) "
                     "also keeps the radius.",
                     sharpness="depends on omega (and on alpha matching the sampling 2 pi/N); the paper's curvature plots "
                               "do not state omega", evidence=ev, numbers=nums,
                     figures=[_cmp_figure(curves, "conics-003", "Circle/ellipse: radial deviation vs omega"),
                              _curves_figure("ellipse")])


def _sec6_analytic():
    curves = ("cardioid", "astroid", "lemniscate")
    wins = {(c, _s(om)): _best(c, om)[0] for c in curves for om in _CMP_OMEGAS}
    hyp = [k for k, v in wins.items() if v == "hyperbolic (5)"]
    ev = [C.Evidence("Hausdorff distance after 6 steps from 10 control points (alpha: pi/5; lemniscate 3pi/20 as in "
                     "Fig. 5)", table=_cmp_table(curves), result=_deviation_table("astroid")[("hyperbolic (5)", sp.Integer(0))],
                     text="discrete Hausdorff distance to the exact curve (floor ~5e-3 from the point spacing)")]
    nums = [C.Number(f"{c}.{n}.omega={_s(om)}", _deviation_table(c)[(n, om if s is not JENA_11 else None)].value, tol=1e-6)
            for c in curves for n, s in _CMP for om in ((sp.Integer(0), sp.Rational(1, 100)) if s is not JENA_11 else (None,))]
    return C.Verdict("numerical",
                     f"Not as a general statement: the hyperbolic form (5) is closest in {len(hyp)} of {len(wins)} "
                     f"(curve, omega) cases ({', '.join(f'{c} at omega = {o}' for c, o in hyp) or 'none'}); winners: "
                     f"{_winners(wins)}. The ranking depends on omega (approximating schemes also shrink the curve, "
                     "the interpolatory [11] does not).",
                     sharpness="numerical (float64 refinement); depends on omega and alpha; the paper's Figs 3-5 do not "
                               "state omega", evidence=ev, numbers=nums,
                     figures=[_cmp_figure(curves, "analytic-003", "Cardioid/astroid/lemniscate: Hausdorff distance vs omega"),
                              _curves_figure("astroid")])
