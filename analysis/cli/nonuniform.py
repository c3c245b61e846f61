"""``subdiv nonuniform``: the NVPS of seeds 000/001 from the command line.

Sub-commands (every one has ``--json``)::

    subdiv nonuniform refine --degree 3 --points "0,0;1,0;1,1;0,1" --u "0.5,1,2,1" --closed --steps 4
    subdiv nonuniform compare-definitions --degree 4 --levels 3
    subdiv nonuniform decay --u0 "0.5,2" --degree 2 --levels 12
    subdiv nonuniform lemma --u0-range 0.01,100
    subdiv nonuniform property-a --degree 4
    subdiv nonuniform junction --degree 4 --u-left 0.3 --u-right 4 --levels 16
    subdiv nonuniform reproduce --kind circle --degree 3 --levels 8 [--figure out.png]
    subdiv nonuniform chamfer --levels 8 [--figure out.png]
    subdiv nonuniform claims --seed 001

Register with ``analysis.cli.main.main(argv, extra_modules=["analysis.cli.nonuniform"])``.
"""

from __future__ import annotations

import json
import math

from .common import _print, check_figure, check_writable, json_document
from ..result import AnalysisError


def _floats(text: str, what: str) -> list[float]:
    try:
        vals = [float(t) for t in text.replace(";", ",").split(",") if t.strip()]
    except ValueError:
        raise AnalysisError(f"malformed {what} {text!r}: give comma-separated numbers") from None
    if not vals:
        raise AnalysisError(f"{what} is empty")
    return vals


def _int(text, what: str, lo: int, hi: int) -> int:
    try:
        v = int(text)
    except (TypeError, ValueError):
        raise AnalysisError(f"{what} must be an integer, not {text!r}") from None
    if not lo <= v <= hi:
        raise AnalysisError(f"{what} must be between {lo} and {hi}")
    return v


def _param(text, what: str) -> float:
    """One tension parameter u > -1 (finite)."""
    try:
        v = float(text)
    except (TypeError, ValueError):
        raise AnalysisError(f"{what} must be a number, not {text!r}") from None
    if not math.isfinite(v):
        raise AnalysisError(f"{what} must be finite, not {text!r}")
    if not v > -1:
        raise AnalysisError(f"{what} must satisfy u > -1 (the papers take u > 0); got {text!r}")
    return v


def _figure(plot, path: str, **kw) -> None:
    """Write a figure; a path that cannot be written is a one-line input error."""
    import os

    parent = os.path.dirname(os.path.abspath(path)) or "."
    if not os.path.isdir(parent):
        raise AnalysisError(f"cannot write the figure {path!r}: directory {parent!r} does not exist")
    try:
        plot(path, **kw)
    except OSError as e:
        raise AnalysisError(f"cannot write the figure {path!r}: {e.strerror or e}") from None


def _out(args, data, text: str) -> None:
    if args.json:
        _print(json_document(data))
    else:
        _print(text)


def _points(text: str) -> np.ndarray:
    import numpy as np

    rows = [r for r in text.split(";") if r.strip()]
    if not rows:
        raise AnalysisError("--points is empty")
    pts = [_floats(r, "point") for r in rows]
    if len({len(p) for p in pts}) != 1:
        raise AnalysisError("every point in --points needs the same number of coordinates")
    return np.array(pts)


def cmd_refine(args) -> None:
    import numpy as np

    from .. import nonuniform as nu

    if args.output:
        check_writable(args.output, "--output")
    P = _points(args.points)
    u = _floats(args.u, "--u")
    r = nu.refine(P, u, degree=_int(args.degree, "--degree", 2, 64), steps=_int(args.steps, "--steps", 0, 30),
                  closed=args.closed, rule=args.rule)
    if args.output:
        try:
            np.savetxt(args.output, np.asarray(r.points, dtype=float), delimiter=",")
        except OSError as exc:
            raise AnalysisError(f"cannot write --output {args.output!r}: {exc.strerror or exc}") from None
    data = {"degree": r.degree, "rule": r.rule, "closed": r.closed, "steps": r.level, "count": len(r.points),
            "points": r.points.tolist(), "u": r.u.tolist()}
    lines = [f"NVPS degree {r.degree} ({r.rule}), {'closed' if r.closed else 'open'}: {len(P)} -> {len(r.points)} "
             f"points after {r.level} step(s)"]
    if args.output:
        lines.append(f"written to {args.output}")
    else:
        lines += [" ".join(f"{x:.12g}" for x in np.atleast_1d(row)) for row in r.points]
    _out(args, data, "\n".join(lines))


def cmd_compare(args) -> None:
    from .. import nonuniform as nu

    r = nu.compare_definitions(_int(args.degree, "--degree", 2, 12), levels=_int(args.levels, "--levels", 1, 6),
                               closed=args.closed)
    _out(args, r.to_json(), f"degree {args.degree}: {r.value}   [{r.status}]\n"
         f"  one step equal up to shift: {r.witness['one_step_equal_up_to_shift']}; "
         f"{args.levels} levels equal: {r.witness['multi_level_equal']}; "
         f"seed 000 = mirror of seed 001: {r.witness['seed000_is_mirror_of_seed001']}")


def cmd_decay(args) -> None:
    from ..jsonable import fmt_lower, fmt_upper

    from .. import nonuniform as nu

    r = nu.mask_decay(_floats(args.u0, "--u0"), degree=_int(args.degree, "--degree", 2, 32),
                      levels=_int(args.levels, "--levels", 0, 30), closed=args.closed)
    lines = [f"sup_j ||S^k - S_a||_inf, NVPS degree {args.degree}, u0 = {args.u0}   [{r.status}]"]
    for row, sc in zip(r.witness["levels"], r.witness["scaled_4k_upper"]):
        lines.append(f"  k = {row['k']:2d}: [{fmt_lower(row['lower'], 6, 'e')}, {fmt_upper(row['upper'], 6, 'e')}]"
                     f"   4^k upper = {fmt_upper(sc, 6)}")
    lines.append(f"  ratios of consecutive upper bounds -> 1/4: {', '.join(f'{x:.5f}' for x in r.witness['ratios'][-3:])}")
    _out(args, r.to_json(), "\n".join(lines))


def cmd_lemma(args) -> None:
    from .. import nonuniform as nu

    lo, hi = _floats(args.u0_range, "--u0-range")[:2] if "," in args.u0_range else (None, None)
    if lo is None:
        raise AnalysisError("--u0-range needs LOW,HIGH")
    r = nu.lemma_2_1(lo, hi, levels=_int(args.levels, "--levels", 1, 200))
    b = nu.u_convergence_bound(lo, hi, levels=_int(args.levels, "--levels", 1, 200))
    _out(args, {"lemma_2_1": r.to_json(), "rate": b.to_json()},
         f"Lemma 2.1 on u0 in [{lo}, {hi}]: ||U^k|| <= max(1, ||U^0||) (C = 1)   [{r.status}]\n"
         f"  sup_k 4^k |1 - u^k| <= {b.witness['C_enclosure']}   [{b.status}]\n"
         f"  4^k (1 - u^k) -> {b.witness['limit_at_low']} (low end), {b.witness['limit_at_high']} (high end)")


def cmd_property_a(args) -> None:
    from .. import nonuniform as nu

    d = _int(args.degree, "--degree", 2, 12)
    full, used = nu.property_a_table(d), nu.property_a_table(d, part="used")
    lines = [f"Property A quantities (13)-(14), NVPS degree {d}, orders m = 1..{d - 1}; non-vanishing ones:"]
    for x in full:
        lines.append(f"  m={x['m']} r={x['r']} z0={x['z0']:+d}: {x['verdict']}, max|kappa| = {x['max_kappa']}"
                     f"{'  -> fails o(2^-k(m-r)) on blended data' if x['fails_on_blended'] else ''}")
    if not full:
        lines.append("  none: all vanish identically")
    _out(args, {"degree": d, "full_masks": full, "used_parity": used}, "\n".join(lines))


def cmd_junction(args) -> None:
    from .. import nonuniform as nu

    r = nu.junction_smoothness(_int(args.degree, "--degree", 2, 10), _param(args.u_left, "--u-left"),
                               _param(args.u_right, "--u-right"), levels=_int(args.levels, "--levels", 2, 40),
                               rule=args.rule)
    w = r.witness
    _out(args, r.to_json(), f"junction u = {args.u_left} | {args.u_right}, degree {args.degree}: {r.value}   [{r.status}]\n"
         "  omega_k (junction): " + ", ".join(f"{x:.3e}" for x in w["omega_junction"][-4:]) + "\n"
         "  omega_k (uniform):  " + ", ".join(f"{x:.3e}" for x in w["omega_uniform"][-4:]))


def cmd_reproduce(args) -> None:
    from .. import nonuniform as nu

    d = _int(args.degree, "--degree", 2, 16)
    levels = _int(args.levels, "--levels", 0, 20)
    if args.figure:
        check_figure(args.figure, "the figure")
    r = nu.reproduce(args.kind, degree=d, levels=levels)
    if args.figure:
        from ..report.plots import plot_blended

        _figure(plot_blended, args.figure, levels=min(levels, 7))
    w = r.witness
    lines = [f"{args.kind}, NVPS degree {d}: max distance of level-k points from the curve   [{r.status}]"]
    for k, (dv, fe) in enumerate(zip(w["deviation"], w["form_error"])):
        lines.append(f"  k = {k:2d}: {dv:.3e}   form error {fe:.1e}")
    if args.figure:
        lines.append(f"figure written to {args.figure}")
    _out(args, r.to_json(), "\n".join(lines))


def cmd_chamfer(args) -> None:
    from .. import nonuniform as nu

    levels = _int(args.levels, "--levels", 0, 16)
    if args.figure:
        check_figure(args.figure, "the figure")
    r = nu.chamfer_example(levels=levels, degree=_int(args.degree, "--degree", 2, 8))
    if args.figure:
        from ..report.plots import plot_chamfer

        _figure(plot_chamfer, args.figure, levels=min(levels, 8))
    w = r.witness
    _out(args, r.to_json(), f"chamfered quadrangle (seed 001 Fig. 3), degree {args.degree}   [{r.status}]\n"
         f"  max distance of points from the exact shape: {w['deviation'][-1]:.3e}\n"
         f"  max distance of edge midpoints (limit points for d = 2): {w['midpoint_deviation'][-1]:.3e}"
         + (f"\nfigure written to {args.figure}" if args.figure else ""))


def cmd_claims(args) -> None:
    import importlib

    from .. import progress

    mod = importlib.import_module({"000": "papers.seed000", "001": "papers.seed001"}[args.seed])
    rows = []
    chosen = [c for c in mod.CLAIMS if not args.id or c["id"] == args.id]
    with progress.on_terminal("nonuniform claims", enabled=not args.json):
        for k, c in enumerate(chosen, start=1):
            with progress.part(f"claim {k}/{len(chosen)} {c['id']}"):
                r = c["check"]()
            if hasattr(r, "summary"):          # seed 001: a proof-check Verdict of its paper file
                rows.append({"id": c["id"], "statement": c["statement"], "status": r.status, "value": r.summary,
                             "result": {"label": r.label, "numbers": {n.name: n.to_json() for n in r.numbers}}})
                continue
            rows.append({"id": c["id"], "statement": c["statement"], "status": r.status, "value": r.value,
                         "result": r.to_json()})
    if args.id and not rows:
        raise AnalysisError(f"unknown claim {args.id!r}")
    _out(args, rows, "\n".join(f"{x['id']:<22} {x['status']:<12} {str(x['value'])[:90]}" for x in rows))


def register(subparsers) -> None:
    """Add ``subdiv nonuniform ...`` to the ``subdiv`` parser."""
    p = subparsers.add_parser("nonuniform", help="non-uniform variable-parameter schemes (NVPS; the bundled papers 000, 001)")
    sub = p.add_subparsers(dest="nonuniform_command", parser_class=type(p))
    sub.required = True

    def add(name, func, help_):
        s = sub.add_parser(name, help=help_)
        s.add_argument("--json", action="store_true", help="machine-readable output")
        s.set_defaults(func=func)
        return s

    s = add("refine", cmd_refine, "refine a polygon with one tension parameter per edge")
    s.add_argument("--degree", default="2")
    s.add_argument("--points", required=True, metavar="X,Y;X,Y;...")
    s.add_argument("--u", required=True, metavar="LIST", help="one parameter per edge (one value = all edges)")
    s.add_argument("--steps", default="1")
    s.add_argument("--closed", action="store_true")
    s.add_argument("--rule", default="seed001", choices=("seed001", "seed000"))
    s.add_argument("--output", metavar="FILE")

    s = add("compare-definitions", cmd_compare, "paper 000's S_d vs paper 001's (exact)")
    s.add_argument("--degree", default="3")
    s.add_argument("--levels", default="3")
    s.add_argument("--closed", action="store_true")

    s = add("decay", cmd_decay, "sup_j ||S^k - S_a|| per level (certified enclosures)")
    s.add_argument("--u0", required=True, metavar="LIST")
    s.add_argument("--degree", default="2")
    s.add_argument("--levels", default="12")
    s.add_argument("--closed", action="store_true")

    s = add("lemma", cmd_lemma, "Lemma 2.1 and the rate of u^k -> 1 on a range of u0 (interval arithmetic)")
    s.add_argument("--u0-range", required=True, metavar="LOW,HIGH")
    s.add_argument("--levels", default="60")

    s = add("property-a", cmd_property_a, "Property A quantities (13)-(14): exact structure")
    s.add_argument("--degree", default="4")

    s = add("junction", cmd_junction, "divided differences of the limit at a parameter junction (numerical)")
    s.add_argument("--degree", default="4")
    s.add_argument("--u-left", default="0.3")
    s.add_argument("--u-right", default="4")
    s.add_argument("--levels", default="16")
    s.add_argument("--rule", default="seed001", choices=("seed001", "seed000"))

    s = add("reproduce", cmd_reproduce, "circle (u = cos), hyperbola (u = cosh), parabola (u = 1) reproduction")
    s.add_argument("--kind", default="circle", choices=("circle", "hyperbola", "parabola"))
    s.add_argument("--degree", default="2")
    s.add_argument("--levels", default="8")
    s.add_argument("--figure", metavar="PNG", help="also write the blended-curve figure here")

    s = add("chamfer", cmd_chamfer, "paper 001's chamfering example (Algorithm 2, Fig. 3)")
    s.add_argument("--levels", default="8")
    s.add_argument("--degree", default="2")
    s.add_argument("--figure", metavar="PNG")

    s = add("claims", cmd_claims, "evaluate the claims of paper 000 or 001")
    s.add_argument("--seed", default="001", choices=("000", "001"))
    s.add_argument("--id", help="one claim id, e.g. 001:(17)")
    for parser in sub.choices.values():                 # the options every sub-command shares
        for action in parser._actions:
            if action.help is None and action.dest in _HELP:
                action.help = _HELP[action.dest] + (f" (default {action.default})" if action.default not in
                                                    (None, False) else "")


#: help of the options shared by the ``nonuniform`` sub-commands
_HELP = {"degree": "degree d of the scheme", "points": "control points, one per ';'", "steps": "refinement steps",
         "closed": "closed polygon (default: open)", "rule": "the rule of paper 001 or of paper 000",
         "output": "write the points as CSV", "levels": "number of levels k", "u0": "the edge parameters at level 0, one per edge, e.g. 0.5,0.5",
         "u0_range": "range of the initial parameter u0", "u_left": "parameter on the left of the junction",
         "u_right": "parameter on the right of the junction", "kind": "the curve reproduced",
         "figure": "also write the figure here", "seed": "the bundled paper: 000 or 001"}
