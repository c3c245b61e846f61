"""``subdiv derive``: masks from requirements (see :mod:`analysis.algebra.derive`), and the smoothest member.

Examples
--------
::

    subdiv derive --support 7 --interpolatory --symmetric primal --reproduce 1
    subdiv derive --arity 3 --support 11 --interpolatory --symmetric primal --reproduce 2 --json
    subdiv derive --support 11 --interpolatory --symmetric primal --reproduce 3 \\
        --maximize holder --within 0,1/32
    subdiv derive --support 11 --interpolatory --symmetric primal --reproduce 3 --C 2 --within=-1/32,1/16
    subdiv derive --support 11 --interpolatory --symmetric primal --reproduce 1 --output fam.json \\
        --maximize holder --box t1=0,1/32 --box t2=-1/8,0

The printed mask string can be pasted into ``subdiv range --mask "..." --start S`` or
``subdiv atlas --mask "..." --start S`` (the free parameters ``t1, t2, ...`` are parameters there),
or the family written with ``--output`` read back by ``subdiv range|atlas --family FILE.json``.
"""

from __future__ import annotations



from ..result import AnalysisError


def register(subparsers) -> None:
    """Add ``subdiv derive`` to the sub-command parsers of :func:`analysis.cli.main.build_parser`."""
    s = subparsers.add_parser("derive", help="the exact family of masks satisfying requirements")
    s.add_argument("--arity", default="2", metavar="M", help="arity m >= 2 (default 2)")
    s.add_argument("--support", required=True, metavar="N", help="number of mask coefficients")
    s.add_argument("--start", metavar="S", help="first index (default centred: -(N // 2))")
    s.add_argument("--interpolatory", action="store_true", help="a_{mi} = delta_{i0}")
    s.add_argument("--symmetric", choices=("primal", "dual", "any"), help="a_i = a_{start+end-i}")
    s.add_argument("--sum-rules", metavar="K", help="sum rules of order K (generation of degree K-1)")
    s.add_argument("--generate", metavar="D", help="polynomial generation of degree D")
    s.add_argument("--reproduce", metavar="D", help="polynomial reproduction of degree D")
    s.add_argument("--tau", metavar="T", help="reproduction shift (default (start+end)/(2(m-1)))")
    s.add_argument("--exp", action="append", metavar="LAMBDA",
                   help="reproduce exp(LAMBDA x) (repeatable: 1, -1, I*pi/2)")
    s.add_argument("--level", default="0", metavar="N", help="level of the exponential reproduction (default 0)")
    s.add_argument("--fix", action="append", metavar="aI=V", help="fix a coefficient, e.g. a0=1/2 (repeatable)")
    s.add_argument("--names", metavar="LIST", help="names of the free parameters (default t1,t2,...)")
    s.add_argument("--max-sum-rules", action="store_true", help="the most sum rules on the support")
    s.add_argument("--maximize", choices=("holder",),
                   help="the smoothest member with a certified gap (any arity; several parameters with --box)")
    s.add_argument("--within", metavar="LO,HI", help="box of the parameter for --maximize")
    s.add_argument("--box", action="append", metavar="NAME=LO,HI",
                   help="range of one parameter for --maximize with several parameters (repeatable)")
    s.add_argument("--gap", default="1/1000", metavar="G", help="target certified gap in alpha (default 1/1000)")
    s.add_argument("--budget", default="60000", metavar="UNITS",
                   help="work budget of --maximize, in work units (default 60000; counted, not timed: about a "
                        "millisecond each on the reference machine)")
    s.add_argument("--output", metavar="FAMILY.json",
                   help="also write the family (read back by subdiv range|atlas --family FAMILY.json)")
    s.add_argument("--C", metavar="J", help="also the certified C^J set of a one-parameter family on --within")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.set_defaults(func=cmd_derive)


def _int(text, what: str, lo: int) -> int:
    try:
        v = int(str(text))
    except (TypeError, ValueError):
        raise AnalysisError(f"{what} must be an integer, not {text!r}") from None
    if v < lo:
        raise AnalysisError(f"{what} must be >= {lo}")
    return v


def cmd_derive(args) -> None:
    from ..algebra.derive import derive_mask, max_sum_rules
    from .common import _emit, _parse_within, _split_list

    kw = {"interpolatory": args.interpolatory, "symmetric": args.symmetric}
    for opt, key, lo in (("sum_rules", "sum_rules", 1), ("generate", "generation", 0),
                         ("reproduce", "reproduction", 0)):
        v = getattr(args, opt)
        if v is not None:
            kw[key] = _int(v, f"--{opt.replace('_', '-')}", lo)
    if args.tau is not None:
        kw["tau"] = args.tau
    if args.exp:
        kw["exponentials"] = args.exp
        kw["level"] = _int(args.level, "--level", 0)
    fixed = {}
    for item in args.fix or []:
        if "=" not in item:
            raise AnalysisError(f"malformed --fix {item!r}: use aI=VALUE, e.g. a0=1/2")
        k, v = (t.strip() for t in item.split("=", 1))
        fixed[k] = v
    if fixed:
        kw["fixed"] = fixed
    if args.names:
        kw["names"] = _split_list(args.names, "--names")
    arity = _int(args.arity, "--arity", 2)
    support = _int(args.support, "--support", 1)
    if args.output:
        from .common import check_writable

        check_writable(args.output, "the family file")
    start = None if args.start is None else _int(args.start, "--start", -10 ** 6)
    if args.max_sum_rules:
        if "sum_rules" in kw:
            raise AnalysisError("--max-sum-rules and --sum-rules exclude each other")
        r = max_sum_rules(arity, support, start, **kw)
    else:
        r = derive_mask(arity, support, start, **kw)
    w = r.witness
    data = {"status": r.status, "dimension": w["dimension"], "parameters": list(w["parameters"]),
            "free_coefficients": w["free_coefficients"], "mask": w["mask"], "start": w["start"],
            "arity": arity, "tau": w["tau"], "requirements": w["requirements"], "equations": w["equations"],
            "rank": w["rank"], "symbol": r.value, "method": r.provenance["method"], "domain": r.provenance["domain"]}
    if "order" in w:
        data["max_sum_rules"] = w["order"]
    lines = [f"family of arity {arity} on [{w['support'][0]}, {w['support'][1]}]: dimension {w['dimension']} "
             f"({r.status}, exact; {w['equations']} equations, rank {w['rank']}, {r.provenance['domain']})",
             "requirements: " + "; ".join(w["requirements"]),
             f"mask (start {w['start']}): {w['mask']}"]
    if "order" in w:
        lines.append(f"most sum rules on this support: {w['order']}")
    if w["parameters"]:
        lines.append("free parameters: " + ", ".join(f"{x} = {c}" for x, c in w["free_coefficients"].items()))
        if arity == 2 and r.value is not None:
            lines.append(f"analyse: subdiv range --mask \"{w['mask']}\" --start {w['start']} --C 1 --within=LO,HI")
    if args.output:
        from .family import write_family

        write_family(args.output, data)
        lines.append(f"family written to {args.output} (subdiv range|atlas --family {args.output})")
        data["output"] = args.output
    if args.C is not None:
        _ck_part(args, r, arity, lines, data)
    if args.maximize and (arity != 2 or len(w["parameters"]) != 1 or args.box):
        from .. import progress

        with progress.on_terminal("derive", enabled=not args.json):
            _maximize_box(args, r, arity, lines, data)
    elif args.maximize:
        from ..regularity.maximize import maximize_holder

        if args.within is None:
            raise AnalysisError("--maximize needs --within LO,HI (a box for the free parameter)")
        if r.value is None:
            raise AnalysisError("--maximize needs an algebraic mask (real exponentials give transcendental coefficients)")
        lo, hi = _parse_within(args.within)
        if not (lo.is_finite and hi.is_finite):
            raise AnalysisError("--within needs a finite box for --maximize")
        from .common import parse_coefficient, work_arg

        budget = work_arg(args.budget, "--budget")
        from .. import progress

        with progress.on_terminal("derive", enabled=not args.json):
            m = maximize_holder(r.value, within=(lo, hi), gap=parse_coefficient(args.gap), budget=budget)
        data["maximize"] = {"status": m.status, "maximiser": m.value, "alpha_lower_at_maximiser": m.lower,
                            "alpha_upper_on_box": m.upper, "gap": m.witness.get("gap"),
                            "intervals": m.witness.get("intervals"), "work": m.provenance.get("work"),
                            "message": m.provenance.get("message"), "timing": m.provenance.get("timing")}
        if m.value is None:
            lines.append(f"maximize holder: {m.status} ({m.provenance.get('message')})")
        else:
            h = m.witness["alpha_at"]
            p = m.witness["parameter"]
            lines.append(f"smoothest member: {p} = {m.value} (~{float(m.value):.8g}); alpha there in "
                         f"[{float(h.lower):.6f}, {float(h.upper):.6f}] ({h.status})")
            lines.append(f"alpha <= {float(m.upper):.6f} on the whole box [{lo}, {hi}]: certified gap "
                         f"{float(m.witness['gap']):.2e} ({m.status}; {m.witness['intervals']} sub-intervals, "
                         f"{m.provenance['timing']['seconds']} s)" + (f"; {m.provenance['message']}" if "message" in m.provenance else ""))
    _emit(args, data, "\n".join(lines))





def _ck_part(args, r, arity: int, lines: list, data: dict) -> None:
    """``--C J``: the C^J set of a one-parameter family on ``--within`` with its certified interior."""
    from .common import _parse_within

    j = _int(args.C, "--C", 0)
    if args.within is None:
        raise AnalysisError("--C needs --within LO,HI (an interval of the free parameter)")
    if r.value is None or len(r.value.params) != 1:
        raise AnalysisError("--C needs a family with exactly one free parameter and an algebraic mask")
    lo, hi = _parse_within(args.within)
    if not (lo.is_finite and hi.is_finite):
        raise AnalysisError("--within needs finite bounds for --C")
    if arity != 2:
        from ..regularity.ranges import ck_range

        c = ck_range(r.value, j, within=(lo, hi), arity=arity)
        lines.append(f"C^{j} set on [{lo}, {hi}]: {c.value} ({c.status}); undecided: {c.witness['undecided']}")
        data["C"] = {"j": j, "status": c.status, "set": str(c.value), "undecided": str(c.witness["undecided"])}
        return
    from ..regularity.ranges import ck_parameter_set
    from .regularity import _interior_lines

    c = ck_parameter_set(r.value, j, within=(lo, hi), interior_L_max=12)
    lines.append(f"C^{j} set on [{lo}, {hi}] ({c.status}):")
    for run in c.value:
        if run.get("interior"):
            lines.extend(_interior_lines(run["interior"], j))
    if not c.value:
        lines.append("  empty on the grid")
    data["C"] = {"j": j, "status": c.status, "result": c.to_json()}


def _maximize_box(args, r, arity: int, lines: list, data: dict) -> None:
    """``--maximize holder`` for several parameters (``--box``) or arity m (:mod:`analysis.cli.maximize`)."""
    from .common import _parse_within, parse_coefficient
    from .maximize import maximize_part, parse_boxes

    if r.value is None:
        raise AnalysisError("--maximize needs an algebraic mask (real exponentials give transcendental coefficients)")
    names = [str(p) for p in r.witness["parameters"]]
    if not names:
        raise AnalysisError("nothing to maximise: the family has no free parameter (dimension 0)")
    box = parse_boxes(args.box)
    if not box:
        if args.within is None or len(names) != 1:
            raise AnalysisError("--maximize needs a box: --within LO,HI (one parameter) or --box NAME=LO,HI for "
                                "each of " + ", ".join(names))
        box = {names[0]: _parse_within(args.within)}
    from .common import work_arg

    maximize_part(r.value, box, arity, parse_coefficient(args.gap), work_arg(args.budget, "--budget"), lines, data)
