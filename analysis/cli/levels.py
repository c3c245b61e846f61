"""``subdiv series``, ``subdiv bound``, ``subdiv reproduce``: level-dependent schemes on the command line.

Level-dependent schemes are named from :mod:`schemes.level_dependent` (``--scheme
seed003-trigonometric``); parameters are exact values (``--param alpha=pi/5``) or, for one
parameter, a closed box (``--box alpha=1/10,pi/3``); ``--box`` is repeatable (two-parameter boxes,
issue 13) in ``series``, ``bound`` and ``reproduce --lambdas``, with ``--depth`` for adaptive bisection.

Examples
--------
::

    subdiv series --scheme seed003-trigonometric --param alpha=1 --param omega=1/100 --m 0,1,2
    subdiv series --scheme seed003-trigonometric --box alpha=1/10,pi/3 --param omega=1/100 --m 1 --pieces 8
    subdiv bound --claim "003:Lemma3.1(iii)-upper" --box alpha=1/100,pi/3 --param omega=1/100
    subdiv bound --lhs "3/4" --rhs "sin(3*alpha/2**(n+2))/sin(alpha/2**n)" --n0 1 --box alpha=1/100,1
    subdiv reproduce --scheme exp-chaikin-trig --lambdas "I*t,-I*t" --curve circle --param t=pi/4 --points 8
    subdiv series --symbol "(1+z)**2*(1+2*v*z+z**2)/(4*(1+v)*z**2)" --where "v=cosh(t/2**(n+1))" --param t=1
    subdiv reproduce --scheme exp-cubic-trig --frequencies
    subdiv bound --claim "003:Lemma3.1(ii)-lower" --box alpha=1/100,pi/3 --box "omega=0,(sqrt(6)-1)/80"
    subdiv reproduce --scheme exp-chaikin-trig --lambdas "I*t,-I*t" --box t=1/10,3
"""

from __future__ import annotations

from .common import _emit, _parse_params, check_figure
from .level_args import k_max_arg, param_box_values, parse_boxes, stationary_options_refused
from .level_text import limit_line, series_line, verdict_lines
from ..result import AnalysisError


def _level_scheme(args):
    """The level-dependent scheme: a catalogue name, or inline --mask/--symbol with n and --where."""
    from schemes.level_dependent import get

    from .level_input import is_stationary, level_scheme_from_args

    inline = [x for x in ("mask", "symbol", "where") if getattr(args, x, None)]
    if not inline:
        if not args.scheme:
            raise AnalysisError("give --scheme NAME (a level-dependent scheme), or --symbol/--mask using the level n")
        return get(args.scheme)
    if args.scheme:
        raise AnalysisError("give --scheme NAME or --symbol/--mask, not both")
    s = level_scheme_from_args(args, keep_params=True)
    if s is None or is_stationary(s):
        raise AnalysisError("the scheme does not depend on the level n: use a stationary command (e.g. subdiv holder)")
    return s


def _add_inline(s) -> None:
    s.add_argument("--symbol", metavar="EXPR", help='a^n(z), may use the level n, e.g. "(1+z)**2*(1+2*v*z+z**2)/(4*(1+v)*z**2)"')
    s.add_argument("--mask", metavar="LIST", help="level-n mask coefficients (may use n)")
    s.add_argument("--start", default="0", metavar="N", help="exponent of the first --mask coefficient")
    s.add_argument("--where", action="append", metavar="NAME=EXPR", help="helper definition (may use n), repeatable")


#: the shared argument readers (:mod:`analysis.cli.level_args`) under their old names here
_box = parse_boxes
_values = param_box_values


def _ints(text, what):
    try:
        return [int(x) for x in str(text).split(",")]
    except ValueError:
        raise AnalysisError(f"{what} must be integers like 0,1,2, not {text!r}") from None


def level_scheme_with_arity(args, m: int):
    """The level-dependent scheme of arity ``m > 2`` of the inline arguments or of the catalogue (``--scheme``):
    the level enters through ``m^n``."""
    from ..levels.level_dependent import LevelDependentScheme
    from .level_input import _int, _items

    sym, mask = getattr(args, "symbol", None), getattr(args, "mask", None)
    if getattr(args, "scheme", None):                   # the level-dependent catalogue (schemes.level_dependent)
        from schemes.level_dependent import get

        if sym is not None or mask is not None or getattr(args, "where", None):
            raise AnalysisError("give --scheme NAME or --symbol/--mask, not both")
        s = get(args.scheme)
        if s.arity != m:
            raise AnalysisError(f"scheme {args.scheme!r} has arity {s.arity}; drop --arity or give --arity {s.arity}")
        return s
    if (sym is None) == (mask is None):
        raise AnalysisError("give exactly one of --symbol EXPR, --mask LIST (using the level n)")
    where = getattr(args, "where", None) or []
    if sym is not None:
        s = LevelDependentScheme.from_symbol(sym, where=where, slug="symbol", arity=m)
    else:
        s = LevelDependentScheme.from_mask(_items(mask, "mask"), _int(getattr(args, "start", "0"), "--start"),
                                           where=where, slug="mask", arity=m)
    from ..levels.level_dependent import H

    if all(H not in c.free_symbols for c in s.mask):
        raise AnalysisError("the scheme does not depend on the level n: use a stationary command (e.g. subdiv holder)")
    return s


def _values_of(args, s) -> dict:
    """``--param`` and ``--box`` (:func:`analysis.cli.level_args.param_box_values`); every parameter needs one."""
    vals = param_box_values(args, "theta=1/2,2")
    missing = [p for p in s.param_names if p not in vals]
    if missing:
        raise AnalysisError(f"undefined name(s) {', '.join(missing)}: define them with --where NAME=EXPR "
                            "or give --param NAME=VALUE")
    return vals


def _weights(args):
    """The weights of ``--m``, each announced as the part running now (shown on a terminal, not with --json)."""
    from .. import progress

    ms = _ints(args.m, "--m")
    with progress.on_terminal("series", enabled=not args.json):
        for i, m in enumerate(ms, start=1):
            with progress.part(f"weight m = {m} ({i}/{len(ms)})"):
                yield m


def cmd_series(args) -> None:
    from ..jsonable import fmt_lower, fmt_upper

    from ..levels.level_dependent import leading_asymptotics
    from ..levels.leading_term import series_by_leading_term
    from ..levels.series import weighted_series
    from .common import scheme_arity

    if (arity := scheme_arity(args, level=True)) != 2:          # arity m > 2: the level through m^n
        import sympy as sp

        m = arity
        if getattr(args, "C", None) is not None or getattr(args, "open", None):
            raise AnalysisError("--C/--open (C^k on a parameter region) are not available for m-ary schemes; "
                                "use subdiv holder --arity M at parameter values")
        s = level_scheme_with_arity(args, m)
        vals = _values_of(args, s)
        d = getattr(args, "difference", 0) or 0
        pieces, depth = getattr(args, "pieces", 1) or 1, getattr(args, "depth", 0) or 0
        for name, v in (("--difference", d), ("--pieces", pieces), ("--depth", depth)):
            if isinstance(v, bool) or not isinstance(v, int) or v < (1 if name == "--pieces" else 0):
                raise AnalysisError(f"{name} must be an integer >= {1 if name == '--pieces' else 0}, not {v!r}")
        if d:
            from ..levels.divided import divided_difference

            s = divided_difference(s, d)
        rows, lines = [], []
        for k in _weights(args):
            r = series_by_leading_term(s, vals, k, pieces=pieces, depth=depth, N=args.N)
            if not lines:
                lines.append(f"scheme {s.slug} (arity {m}, h = {m}^-n"
                             + (f", divided difference scheme of order {d}" if d else "") + "): ||S_(a^n) - S_a|| ~ "
                             + (f"{r.witness['leading_asymptotics']} (exact)" if "leading_asymptotics" in r.witness else
                                "?"))
                if r.witness.get("sub_boxes", 1) > 1 or pieces > 1:
                    lines.append(f"  ({r.witness['sub_boxes']} sub-boxes: --pieces {pieces}, --depth {depth})")
            rows.append({"m": k, **r.to_json()})
            lines.append(series_line(f"weight {m}^({k}n)", r, lambda v, r=r: (
                f"tail <= {fmt_upper(r.witness['tail']['bound'], 3, 'g')}, ratio {r.witness['tail']['ratio']}"
                if v == "convergent" else
                f": terms >= {fmt_lower(r.witness['term_lower_bound'], 6, 'g')}; leading constant "
                f"{sp.sstr(r.witness['leading_constant'])}" if v == "divergent" else f" — {r.witness.get('reason')}")))
        _emit(args, {"scheme": s.slug, "arity": m, "difference": d, "series": rows}, "\n".join(lines))
        return
    if args.difference < 0:
        raise AnalysisError(f"--difference must be >= 0, not {args.difference}")
    try:
        s = _level_scheme(args)
    except AnalysisError as exc:                 # the level enters through n itself (rational in n)
        from .levels_rational import fallback, series_rational

        s = fallback(args, _parse_params(args.param), exc)
        if args.C is not None or args.box or args.pieces != 1 or args.depth:
            raise AnalysisError("--C, --box, --pieces and --depth are not available when the level enters "
                                "through n itself (coefficients rational in n): give --param values") from None
        return series_rational(args, s, _ints(args.m, "--m"))
    if args.pieces < 1:
        raise AnalysisError(f"--pieces must be >= 1, not {args.pieces}")
    if not 0 <= args.depth <= 8:
        raise AnalysisError(f"--depth must be between 0 and 8, not {args.depth}")
    if args.C is not None:
        return _series_region(args, s)
    if args.open:
        raise AnalysisError("--open needs --C K (C^K on the region)")
    if args.difference:
        s = s.difference(args.difference)
    vals = _values(args)
    lead = leading_asymptotics(s)
    rows, lines = [], [f"scheme {s.slug}: ||S_(a^n) - S_a|| ~ {lead.witness['rate']} (exact)"]
    for m in _weights(args):
        r = weighted_series(s, vals, m, N=args.N, pieces=args.pieces, depth=args.depth)
        rows.append({"m": m, **r.to_json()})
        lines.append(series_line(f"m = {m}", r, lambda v, r=r: (
            f"tail <= {fmt_upper(r.witness['tail']['bound'], 3, 'g')}" if v == "convergent" else
            f": terms >= {fmt_lower(r.witness['term_lower_bound'], 6, 'g')} "
            f"for n >= {r.witness['tail']['N'] if 'tail' in r.witness else args.N}; "
            f"leading constant {r.witness['leading_constant']}" if v == "divergent" else "")))
    _emit(args, {"scheme": s.slug, "leading": lead.to_json(), "series": rows}, "\n".join(lines))


def _series_region(args, s) -> None:
    """``subdiv series --C K``: C^K by Dyn-Levin at every point of the region (issue 13)."""
    from ..jsonable import fmt_lower, fmt_upper

    from ..levels.region import smoothness_on_region

    try:
        k = int(args.C)
    except ValueError:
        raise AnalysisError(f"--C must be an integer, not {args.C!r}") from None
    if k < args.difference:
        raise AnalysisError(f"--C {k} is smaller than --difference {args.difference}")
    vals = _values(args)
    if args.open and not isinstance(vals.get(args.open), tuple):
        raise AnalysisError(f"--open {args.open} needs a --box for {args.open}")
    r = smoothness_on_region(s, vals, k, difference=args.difference, open_param=args.open, N=args.N,
                             depth=max(args.depth, 2))
    lines = [f"scheme {s.slug}: C^{k} at every point of {r.witness['region']}: "
             f"{'yes' if r.value else 'undecided'} [{r.status}] — {r.witness['route']}"]
    for name, h in r.witness["hypotheses"].items():
        w = h.witness
        if name.startswith("series"):
            detail = (f"{w.get('verdict')}, sum in [{fmt_lower(h.lower, 8, 'g')}, {fmt_upper(h.upper, 8, 'g')}]"
                      if h.is_certified else w.get("verdict", ""))
        elif name == "same_support":
            detail = f"support {w.get('support')}" if h.is_certified else f"failed {w.get('failed')}"
        else:
            detail = (f"norm test L = {w.get('L')} on {w.get('set')}" if w.get("set") else
                      w.get("test") or w.get("reason") or "")
        lines.append(f"  {name}: {h.status} — {detail}")
    _emit(args, {"scheme": s.slug, "region": r.to_json()}, "\n".join(lines))


def cmd_bound(args) -> None:
    import sympy as sp
    from ..jsonable import fmt_lower, fmt_upper
    from ..algebra.symbol import parse_coefficient
    from ..algebra.reader import as_expr

    from ..levels.bounds import check_inequality

    vals = _values(args)
    if args.claim:
        from schemes import seed003

        table = {**seed003.LEMMA_3_1, **seed003.LEMMA_3_1_CORRECTED, **seed003.LEMMA_3_2}
        if args.claim not in table:
            raise AnalysisError(f"unknown claim {args.claim!r}; known: {', '.join(table)}")
        lhs, rhs, strict = table[args.claim]
        n0 = 1 if "3.1" in args.claim else 0
        vals.setdefault("omega", sp.Rational(1, 100))
        vals = {k: v for k, v in vals.items()
                if k in {x.name for x in (as_expr(lhs).free_symbols | as_expr(rhs).free_symbols)}}
    else:
        if args.lhs is None or args.rhs is None:
            raise AnalysisError("give --claim ID, or --lhs EXPR and --rhs EXPR")
        lhs, rhs = (parse_coefficient(x, locals_={"n": sp.Symbol("n")}) for x in (args.lhs, args.rhs))
        strict, n0 = args.strict, args.n0
    if n0 < 0:
        raise AnalysisError(f"--n0 must be a non-negative level, not {n0}")
    if not 0 <= args.depth <= 30:
        raise AnalysisError(f"--depth must be between 0 and 30, not {args.depth}")
    if not 1 <= args.pieces <= 64:
        raise AnalysisError(f"--pieces must be between 1 and 64, not {args.pieces}")
    from .. import progress

    with progress.on_terminal("bound", enabled=not args.json):
        r = check_inequality(lhs, rhs, n0, vals, strict=strict, claim=args.claim or "", max_depth=args.depth,
                             pieces=args.pieces)
    text = f"{r.witness['statement']}: {r.status}"
    if "box" in r.provenance and any(isinstance(v, tuple) for v in r.provenance["box"].values()):
        text += " on " + ", ".join(f"{k} in [{sp.sstr(v[0])}, {sp.sstr(v[1])}]" if isinstance(v, tuple) else
                                   f"{k} = {sp.sstr(v)}" for k, v in r.provenance["box"].items())
    if "counterexample" in r.witness:
        w = r.witness["counterexample"]
        pt = w.get("point")
        pt = ", ".join(f"{k} = {sp.sstr(v)}" for k, v in pt.items()) if isinstance(pt, dict) else str(pt)
        gf = w.get("g_minus_f")
        gf = (f"rhs - lhs in [{fmt_lower(gf[0], 6, 'g')}, {fmt_upper(gf[1], 6, 'g')}]"
              if isinstance(gf, (tuple, list)) and len(gf) == 2 else f"rhs - lhs = {gf}")
        text += f"\ncounterexample: n = {w.get('n')}, {pt}: {gf} (certified < 0)"
    _emit(args, r.to_json(), text)


def cmd_reproduce(args) -> None:
    import sympy as sp
    from ..algebra.symbol import parse_coefficient

    from ..levels.reproduction import check_curve_options, curve_deviation, generation, reproduction

    if args.plot:
        check_figure(args.plot, "the plot")
    s = _level_scheme(args)
    if args.curve:
        check_curve_options(args.points, args.steps, args.plot)
    vals = _parse_params(args.param)
    box = _box(args.box)
    if box:
        if args.curve or args.frequencies:
            raise AnalysisError("--box works with --lambdas (generation/reproduction on the whole box); "
                                "--curve and --frequencies need exact --param values")
        both = sorted(set(vals) & set(box))
        if both:
            raise AnalysisError(f"{both[0]} is given both by --param and by --box: give one of them")
        vals.update(box)
    if not 0 <= args.depth <= 8:
        raise AnalysisError(f"--depth must be between 0 and 8, not {args.depth}")
    lams = [parse_coefficient(x, locals_={p.name: p for p in s.params})
            for x in args.lambdas.split(",")] if args.lambdas else []
    out, lines = {"scheme": s.slug}, []
    if lams:
        g = generation(s, lams, vals or None, depth=args.depth)
        rr = reproduction(s, lams, vals or None, depth=args.depth)
        out["generation"], out["reproduction"] = g.to_json(), rr.to_json()
        where = (" on " + ", ".join(f"{k} in [{sp.sstr(lo)}, {sp.sstr(hi)}]" for k, (lo, hi) in box.items())
                 if box else "")
        lines.append(f"generation of exp(lambda x), lambda in {args.lambdas}{where}: {g.status}")
        lines.append(f"reproduction{where}: {rr.status}")
        for res in (g, rr):
            if res.status == "refuted" and res.witness.get("counterexample"):
                w = res.witness["counterexample"]
                pt = ", ".join(f"{k} = {sp.sstr(v)}" for k, v in w["point"].items())
                lines.append(f"  counterexample ({'generation' if res is g else 'reproduction'}): level n = {w['n']}"
                             f"{', ' + pt if pt else ''}: {res.witness['statement']} (value {w['value']})")
                break
    if args.curve:
        c = curve_deviation(s, args.curve, vals, points=args.points, steps=args.steps, plot=args.plot)
        out["curve"] = c.to_json()
        lines.append(f"{args.curve}: deviation {c.value:.6g} (Hausdorff {c.witness['hausdorff']:.6g}; "
                     f"{c.status}, float64)")
    if args.frequencies:
        from ..levels.reproduction import exponential_frequencies

        fr = exponential_frequencies(s, vals or None)
        out["frequencies"] = fr.to_json()
        gen = ", ".join(f"{sp.sstr(k)}" + (f" (multiplicity {m})" if m > 1 else "") for k, m in fr.value["generated"].items())
        lines.append(f"frequencies generated at every level: {gen or 'none'} [{fr.status}]")
        lines.append(f"exponentials reproduced: {', '.join(sp.sstr(x) for x in fr.value['reproduced']) or 'none'} "
                     f"[{fr.status}]")
        if fr.witness["unsolved_factors"] or fr.witness["unverified_candidates"]:
            lines.append("  the list may be incomplete: factors not solved: "
                         f"{', '.join(fr.witness['unsolved_factors']) or 'none'}; candidates neither proved nor "
                         f"refuted: {', '.join(fr.witness['unverified_candidates']) or 'none'} (give --param values)")
    if len(out) == 1:
        raise AnalysisError("give --lambdas, --frequencies and/or --curve")
    _emit(args, out, "\n".join(lines))


def holder_level_dependent(args, s, arity: int = 2) -> None:
    """``subdiv holder`` on a level-dependent scheme: convergence and C^k for each k (theorem, status).

    Arity ``m > 2`` (``s`` None: read from the arguments with :func:`level_scheme_with_arity`): parameters by
    ``--param``; the lines name the arity and ``h = m^-n``."""
    import sympy as sp

    from ..levels.ck import level_smoothness
    from ..levels.level_dependent import H, N

    stationary_options_refused(args)
    if arity != 2:
        s = level_scheme_with_arity(args, arity)
        vals = _values_of(args, s)
        r = level_smoothness(s, vals, k_max=k_max_arg(args))
        point = {q: vals[q.name] for q in s.params if not isinstance(vals[q.name], tuple)}
        lines = [f"scheme: {s.slug} (level-dependent, arity {arity}, h = {arity}^-n)",
                 f"  a^n(z) = {sp.sstr(sp.factor(s.symbol_expr().subs(H, sp.Integer(arity) ** (-N)).subs(point)))}",
                 limit_line(r.witness["limit"])] + verdict_lines(r)
        data = {"scheme": s.slug, "arity": arity, "level_dependent": True, "smoothness": r.to_json()}
        _level_table(args, s.slug, r, lines, data)
        _emit(args, data, "\n".join(lines))
        return
    k_max = k_max_arg(args)
    r = level_smoothness(s, k_max=k_max)
    lim = r.witness["limit"]
    lines = [f"scheme: {s.slug} (level-dependent, h = 2^-n)",
             f"  a^n(z) = {sp.sstr(sp.factor(s.symbol_expr().subs(sp.Symbol('h', positive=True), 2 ** (-sp.Symbol('n')))))}",
             limit_line(lim)] + verdict_lines(r)
    data = {"scheme": s.slug, "level_dependent": True, "smoothness": r.to_json()}
    _level_table(args, s.slug, r, lines, data)
    _emit(args, data, "\n".join(lines))


def _level_table(args, label: str, r, lines: list, data: dict) -> None:
    """``holder --table FILE`` of a level-dependent scheme: its C^k verdicts (:func:`verdict_rows`)."""
    if not getattr(args, "table", None):
        return
    from .level_text import verdict_rows
    from .tables import write_table

    write_table(args.table, ["", "verdict", "status", "theorem"], verdict_rows(r),
                f"subdiv holder: {label} (level-dependent)")
    lines.append(f"table written to {args.table}")
    data["table"] = args.table


def holder_growing_support(args, message: str) -> None:
    """``subdiv holder`` on a symbol whose support grows with the level: an inconclusive, saying why."""
    reason = (f"{message}; the theorems implemented (Dyn-Levin 1995, Conti-Dyn-Manni-Mazure 2015, "
              "Charina-Conti-Guglielmi-Protasov 2017) all need one bounded support for every level")
    data = {"scheme": "symbol", "level_dependent": True,
            "smoothness": {"status": "inconclusive", "value": None, "witness": {"reason": reason}}}
    _emit(args, data, f"scheme: symbol (level-dependent)\n  convergence: undecided [inconclusive] — {reason}")


def register(sub) -> None:
    """Add the sub-commands to the ``subdiv`` parser."""
    s = sub.add_parser("series", help="weighted series sum 2^(mn)||S_(a^n) - S_a||: verdict and enclosure")
    s.add_argument("--scheme", metavar="NAME", help="level-dependent scheme (schemes.level_dependent)")
    s.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter value (repeatable)")
    s.add_argument("--box", action="append", metavar="NAME=LOW,HIGH",
                   help="a closed parameter box instead of a value (repeatable)")
    s.add_argument("--m", default="0,1,2", help="weights, e.g. 0,1,2")
    s.add_argument("--difference", type=int, default=0, help="k: use the k-th divided difference scheme")
    s.add_argument("--N", type=int, default=40, help="levels summed explicitly")
    s.add_argument("--pieces", type=int, default=1, help="sub-boxes of each parameter box")
    s.add_argument("--depth", type=int, default=0,
                   help="adaptive subdivision: bisect an undecided sub-box up to DEPTH times (default 0)")
    s.add_argument("--C", metavar="K", help="decide C^K at every point of the boxes (Dyn-Levin, hypotheses "
                                            "pointwise; with --difference: on the divided-difference scheme)")
    s.add_argument("--open", metavar="NAME", help="with --C: the limit's parameter; its box is read as an open "
                                                  "interval (exact norm set for the limit)")
    _add_inline(s)
    s.add_argument("--arity", metavar="M", help="m-ary level-dependent scheme, level through M^n")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.set_defaults(func=cmd_series)

    s = sub.add_parser("bound", help="prove/refute f(n,p) <= g(n,p) for n >= n0 over a parameter box")
    s.add_argument("--claim", metavar="ID", help='a lemma item of the bundled paper 003, e.g. "003:Lemma3.2(ii)"')
    s.add_argument("--lhs", metavar="EXPR", help="left side f(n, parameters), e.g. 1/2**n")
    s.add_argument("--rhs", metavar="EXPR", help="right side g(n, parameters)")
    s.add_argument("--n0", type=int, default=0, help="first level n (>= 0)")
    s.add_argument("--strict", action="store_true", help="prove f < g (default: f <= g)")
    s.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter value (repeatable)")
    s.add_argument("--box", action="append", metavar="NAME=LOW,HIGH", help="a closed box; repeatable (several parameters)")
    s.add_argument("--depth", type=int, default=10,
                   help="adaptive subdivision: bisect an undecided box up to DEPTH times per level (default 10)")
    s.add_argument("--pieces", type=int, default=8, help="sub-boxes of each parameter box for the tail n >= N (default 8)")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.set_defaults(func=cmd_bound)

    s = sub.add_parser("reproduce", help="exponential generation/reproduction; distance to curves")
    s.add_argument("--scheme", metavar="NAME", help="level-dependent scheme (schemes.level_dependent)")
    s.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter value (repeatable)")
    s.add_argument("--box", action="append", metavar="NAME=LOW,HIGH",
                   help="with --lambdas: decide on the whole closed box (repeatable)")
    s.add_argument("--depth", type=int, default=2,
                   help="with --box: bisect the box up to DEPTH times looking for a counterexample (default 2)")
    s.add_argument("--lambdas", metavar="LIST", help='e.g. "I*t,-I*t" or "0,t,-t"')
    s.add_argument("--curve", choices=("circle", "ellipse", "cardioid", "astroid", "lemniscate"))
    s.add_argument("--points", type=int, default=10, help="control points on the curve (>= 3)")
    s.add_argument("--steps", type=int, default=6, help="refinement steps (0..12)")
    s.add_argument("--plot", metavar="FILE", help="write the curve and curvature plot (PNG)")
    s.add_argument("--frequencies", action="store_true",
                   help="the frequencies generated and reproduced at every level (exact)")
    _add_inline(s)
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.set_defaults(func=cmd_reproduce)
