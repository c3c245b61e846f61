"""``subdiv atlas``: a two-parameter map of the Hölder exponent (see :mod:`analysis.regularity.atlas`).

Examples
--------
::

    subdiv atlas --scheme seed004-design-control --param omega=0 \\
        --x mu=-1/5:1/5:9 --y nu=0:2:9 --refine 1 --figure atlas.png
    subdiv atlas --scheme seed004-design-control --param omega=0 --x mu=-0.2:0.2:5 --y nu=0:2:5 \\
        --executor dask://127.0.0.1:8786 --json

Register with ``analysis.cli.main.main(argv, extra_modules=["analysis.cli.atlas"])`` (or by listing
the module in ``analysis.cli.main.COMMAND_MODULES``).
"""

from __future__ import annotations

from ..result import AnalysisError
from .common import WORK_HELP, work_arg


def _int(text: str, what: str, lo: int, hi: int | None = None) -> int:
    try:
        v = int(text)
    except (TypeError, ValueError):
        raise AnalysisError(f"{what} must be an integer, not {text!r}") from None
    if v < lo or (hi is not None and v > hi):
        raise AnalysisError(f"{what} must be between {lo} and {hi}" if hi is not None else f"{what} must be >= {lo}")
    return v


def _verdict_char(v) -> str:
    return "y" if v is True else ("n" if v is False else "?")


def _ascii_map(result, js) -> list[str]:
    """The level-0 grid as characters: the largest certified j (of ``js``) with C^j, '.' for none,
    '?' when a verdict is undecided, '*' on an exceptional set; rows from the top (largest p2)."""
    import sympy as sp

    rows = [r for r in result.value if r["level"] == 0]
    xs = sorted({r["p1"] for r in rows})
    ys = sorted({r["p2"] for r in rows}, reverse=True)
    at = {(r["p1"], r["p2"]): r for r in rows}
    out = []
    for y in ys:
        line = []
        for x in xs:
            r = at[(x, y)]
            if any(r[f"C^{j}"] is None for j in js):
                ch = "?"
            else:
                best = max((j for j in js if r[f"C^{j}"]), default=None)
                ch = "." if best is None else (str(best) if best < 10 else "+")
            line.append("*" if r.get("exceptional") and ch != "?" else ch)
        out.append(f"  {sp.sstr(y):>8} | " + " ".join(line))
    return out


def cmd_atlas(args) -> None:
    import sympy as sp

    from ..regularity.atlas import MAX_WORKERS, holder_atlas, plot_atlas
    from ..regularity.atlas_axes import parse_axis
    from .common import _emit, check_figure, scheme_arity, scheme_from_args
    from ..jsonable import fmt_lower, fmt_upper

    from .family import apply_family

    if args.figure:                              # before any computation: format and place
        check_figure(args.figure, "the figure")
    if args.table:
        from .tables import check_table

        check_table(args.table)
    apply_family(args)                           # --family FILE.json (issue 14)
    m = scheme_arity(args)                       # m-ary families (issue 12)
    a, label = scheme_from_args(args, arity_ok=True)
    if args.x is None or args.y is None:
        raise AnalysisError("give both axes: --x NAME=LO:HI:N --y NAME=LO:HI:N")
    xn, xlo, xhi, xN = parse_axis(args.x)
    yn, ylo, yhi, yN = parse_axis(args.y)
    refine = _int(args.refine, "--refine", 0, 8)
    workers = None if args.workers is None else _int(args.workers, "--workers", 1, MAX_WORKERS)
    budget = work_arg(args.budget, "--budget")
    js = [_int(t.strip(), "--j", 0, 64) for t in args.j.split(",") if t.strip()]
    if not js:
        raise AnalysisError("--j needs a list of integers, e.g. 1,2,3")
    executor = None if args.executor == "serial" else args.executor
    from .. import progress

    with progress.on_terminal("atlas", enabled=not (args.no_progress or args.json)):
        r = holder_atlas(a, xn, (xlo, xhi), yn, (ylo, yhi), n1=xN, n2=yN, j_levels=js, refine_levels=refine,
                         executor=executor, workers=workers, budget=budget,
                         progress=not args.no_progress, **({"arity": m} if m != 2 else {}))
    try:
        figure = plot_atlas(r, args.figure) if args.figure else None
    except OSError as exc:
        raise AnalysisError(f"cannot write the figure {args.figure!r}: {exc.strerror or exc}") from None
    w, c = r.witness, r.witness["counts"]
    js = list(w["grid"]["j_levels"])
    fixed = ", ".join(f"{p}" for p in (args.param or []))
    lines = [f"scheme: {label}" + (f"   ({fixed})" if fixed else "") + (f"   (arity {m})" if m != 2 else ""),
             f"atlas of alpha over {xn} in [{sp.sstr(xlo)}, {sp.sstr(xhi)}] ({xN} points) x "
             f"{yn} in [{sp.sstr(ylo)}, {sp.sstr(yhi)}] ({yN} points), refine {refine}, budget {budget} work units "
             "per point",
             f"samples: {c['samples']} (per level {c['per_level']}); certified {c['certified']}, "
             f"inconclusive {c['inconclusive']}   [{r.status}]",
             f"time: {r.provenance['timing']['seconds']:.1f} s wall, "
             f"{r.provenance['timing']['task_seconds']:.1f} s in point evaluations; {w['executor']}"]
    for key, v in c["verdicts"].items():
        lines.append(f"{key}: yes {v['yes']}, no {v['no']}, undecided {v['undecided']}")
    for ex in w["exceptional"]:
        cond = ", ".join(f"{k} = {sp.sstr(v)}" for k, v in ex["condition"].items())
        q = "(1+z)" if m == 2 else f"(1+...+z^{m - 1})"
        lines.append(f"exceptional: {cond}: {ex['factors']} factors {q} (generic {w['generic_k'] + 1}); "
                     f"alpha can jump up there ({w['exceptional_samples']} samples on such sets in all)")
    gen = [s for s in r.value if not s.get("exceptional") and s["alpha_lower"] is not None]
    if gen:
        lo = min(gen, key=lambda s: s["alpha_lower"])
        hi = max(gen, key=lambda s: s["alpha_lower"])
        lines.append(f"generic alpha from {fmt_lower(lo['alpha_lower'], 4)} ({xn} = {sp.sstr(lo['p1'])}, "
                     f"{yn} = {sp.sstr(lo['p2'])}) to {fmt_lower(hi['alpha_lower'], 4)} "
                     f"({xn} = {sp.sstr(hi['p1'])}, {yn} = {sp.sstr(hi['p2'])})")
    lines.append(f"initial grid: largest j in {js} with certified C^j ('.' none, '?' undecided, "
                 f"'*' exceptional); rows {yn} (top = largest), columns {xn} increasing")
    lines.extend(_ascii_map(r, js))
    lines.append("")
    head = f"{xn:>10} {yn:>10}  {'alpha_lower':>12} {'alpha_upper':>12}  {'status':<12} " + \
        " ".join(f"C^{j}" for j in js) + "  level"
    lines.append(head)
    for s in r.value:
        al = "-" if s["alpha_lower"] is None else fmt_lower(s["alpha_lower"], 6)   # outward
        au = "-" if s["alpha_upper"] is None else fmt_upper(s["alpha_upper"], 6)
        flags = ("  exceptional" if s.get("exceptional") else "") + (f"  ({s['note']})" if s.get("note") else "")
        lines.append(f"{sp.sstr(s['p1']):>10} {sp.sstr(s['p2']):>10}  {al:>12} {au:>12}  {s['status']:<12} "
                     + " ".join(f"{_verdict_char(s[f'C^{j}']):>{len(str(j)) + 2}}" for j in js)
                     + f"  {s['level']}{flags}")
    if figure:
        lines.append(f"figure: {figure}")
    if args.table:
        from .tables import write_table

        yes = {True: "yes", False: "no", None: "?"}
        rows = [[s["p1"], s["p2"], "-" if s["alpha_lower"] is None else fmt_lower(s["alpha_lower"], 6),
                 "-" if s["alpha_upper"] is None else fmt_upper(s["alpha_upper"], 6), s["status"],
                 *(yes[s[f"C^{j}"]] for j in js)] for s in r.value]
        write_table(args.table, [f"${sp.latex(sp.Symbol(xn))}$", f"${sp.latex(sp.Symbol(yn))}$", "alpha lower",
                                 "alpha upper", "status", *(f"C^{j}" for j in js)], rows,
                    f"subdiv atlas: {label}, certified Hölder exponents (outward-rounded enclosures)")
        lines.append(f"table written to {args.table}")
    data = r.to_json()
    data["scheme"] = label
    data["figure"] = figure
    if args.maximize:                            # issue 14: the smoothest member of the box
        from .common import parse_coefficient
        from .maximize import maximize_part

        with progress.on_terminal("atlas", enabled=not (args.no_progress or args.json)):
            maximize_part(a, {xn: (xlo, xhi), yn: (ylo, yhi)}, m, parse_coefficient(args.gap), 120_000, lines, data)
    _emit(args, data, "\n".join(lines))


def register(subparsers) -> None:
    """Add ``subdiv atlas`` to the sub-command parsers of :func:`analysis.cli.main.build_parser`."""
    from .common import _add_scheme_args

    s = subparsers.add_parser("atlas", help="two-parameter map of the Hölder exponent with C^j boundaries")
    _add_scheme_args(s)
    s.add_argument("--x", metavar="NAME=LO:HI:N", help="first axis: parameter, exact range, number of points")
    s.add_argument("--y", metavar="NAME=LO:HI:N", help="second axis")
    s.add_argument("--j", default="1,2,3", metavar="LIST", help="C^j verdicts to compute and refine (default 1,2,3)")
    s.add_argument("--refine", default="1", metavar="R",
                   help="refinement levels near C^j boundaries (default 1; 0 = plain grid)")
    s.add_argument("--executor", default="local", metavar="KIND",
                   help="local (process pool, default), serial, or dask://HOST:PORT (a running scheduler)")
    s.add_argument("--workers", metavar="N", help="local processes, 1 to 64 (default: all cores)")
    s.add_argument("--budget", default="2000", metavar="UNITS",
                   help=f"work budget of the joint spectral radius per point, in work units (default 2000; {WORK_HELP})")
    s.add_argument("--figure", metavar="PATH", help="write a heat map (PNG/PDF/SVG)")
    s.add_argument("--no-progress", action="store_true", help="no progress line on a terminal")
    s.add_argument("--table", metavar="FILE", help="also write the table of points as FILE.csv or FILE.tex "
                                                  "(a LaTeX booktabs tabular)")
    s.add_argument("--family", metavar="FILE.json", help="a family written by subdiv derive --output (replaces --mask)")
    s.add_argument("--maximize", choices=("holder",),
                   help="also the smoothest member on the box of the two axes (certified gap)")
    s.add_argument("--gap", default="1/1000", metavar="G", help="target certified gap of --maximize (default 1/1000)")
    s.set_defaults(func=cmd_atlas)
