"""``subdiv vertex``: a surface scheme at an extraordinary vertex, one line per valence.

Examples
--------
::

    subdiv vertex --scheme loop --valence 3..12
    subdiv vertex --scheme catmull-clark --valence 3..50 --json
    subdiv vertex --scheme butterfly --valence 3..12
    subdiv vertex --scheme modified-butterfly --valence 3..20
    subdiv vertex --scheme sqrt3 --valence 3..12
    subdiv vertex --lattice triangle --centre b --tune b --valence 3..8
    subdiv vertex --lattice triangle --centre "3/(8*n)" --valence 3..8
    subdiv vertex --lattice triangle --centre "3/(8*n)" --edge "3/8; (5/8 + cos(2*pi*j/n))/n" --valence 3..8

For each valence n: the subdominant eigenvalue lambda (exact and as a float), the subsubdominant mu, the
certified separation lambda - max|others|, Reif's eigen-conditions, the curvature behaviour (mu against
lambda^2) and the C^1 verdict with its status; then a summary with lambda in closed form in n.
"""

from __future__ import annotations

from ..result import AnalysisError

SCHEME_NAMES = ("loop", "loop-warren", "catmull-clark", "doo-sabin", "butterfly", "modified-butterfly", "sqrt3")
#: the default --ring of schemes that do not take the 2-ring
DEFAULT_RING = {"butterfly": 3, "modified-butterfly": 3}


def register(subparsers) -> None:
    """Add ``subdiv vertex`` to the sub-command parsers of :func:`analysis.cli.main.build_parser`."""
    s = subparsers.add_parser("vertex", help="eigen-structure, curvature and C^1 status at an extraordinary vertex")
    s.add_argument("--scheme", metavar="NAME",
                   help=f"a surface scheme: {', '.join(SCHEME_NAMES)}")
    s.add_argument("--lattice", choices=("triangle", "quad"),
                   help="user rules: the regular stencils of Loop (triangle) or Catmull-Clark (quad)")
    s.add_argument("--centre", metavar="W[,F]",
                   help="user rules: weight of each edge neighbour in the new centre (quad: edge, face); "
                        "expressions in n and c = cos(2*pi/n); the centre keeps the rest")
    s.add_argument("--edge", metavar="W0; W(j)[; F(j)]",
                   help="user rules: the new point on the edge to e_0: weight of the centre; of every edge "
                        "neighbour e_j (and face f_j), an expression in n and cos(2*pi*l*j/n)")
    s.add_argument("--valence", default="3..12", metavar="N|LO..HI",
                   help="valences (default 3..12; at most 200)")
    s.add_argument("--ring", choices=("1", "2", "3"),
                   help="rings of the local matrix: 2 (default; the support of the first ring's patches) or 1; "
                        "the butterfly schemes take 3 (default) or 2; sqrt3 counts two steps")
    s.add_argument("--tension", metavar="W",
                   help="the butterfly schemes' tension w, a rational number (default 1/16)")
    s.add_argument("--tune", metavar="NAME",
                   help="user rules: NAME is a free weight in --centre; print the exact set of its values for "
                        "which Reif's eigen-conditions hold at each valence")
    s.add_argument("--figure", metavar="FILE.png",
                   help="also draw lambda, mu and lambda^2 against n (png, svg, pdf, ...); with one valence "
                        "(--valence N): the characteristic map")
    s.add_argument("--charmap-cells", action="store_true",
                   help="with --scheme modified-butterfly: also run Zorin's cell test of the characteristic "
                        "map in Arb (certifies C^1; about 10 s once, then 3-12 s per valence; at most "
                        f"{MAX_CELL_VALENCES} valences)")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.set_defaults(func=cmd_vertex)


def _rules(args, n: int | None):
    from ..vertex.rules import scheme_rules, user_rules

    ring = int(args.ring) if args.ring else DEFAULT_RING.get(args.scheme, 2)
    if args.scheme and (args.lattice or args.centre or args.edge):
        raise AnalysisError("give either --scheme NAME or user rules (--lattice, --centre, --edge), not both")
    if args.scheme:
        if args.scheme not in SCHEME_NAMES:
            raise AnalysisError(f"unknown scheme {args.scheme!r}: use one of {', '.join(SCHEME_NAMES)}, "
                                "or user rules with --lattice and --centre")
        if args.scheme == "doo-sabin" and args.ring:
            raise AnalysisError("--ring does not apply to doo-sabin: its local matrix is fixed (the n-gon with its n "
                                "edge quads and n vertex quads, 4n points); omit --ring")
        return scheme_rules(args.scheme, ring, n, _tension(args.tension))
    if args.tension:
        raise AnalysisError("--tension applies to --scheme butterfly or modified-butterfly only")
    if args.lattice and args.centre:
        return user_rules(args.lattice, args.centre, args.edge, ring=ring)
    raise AnalysisError('give --scheme NAME (e.g. --scheme loop) or user rules: --lattice triangle --centre "3/(8*n)"')


def _tension(text: str | None):
    """The butterfly's tension, a rational number read as data."""
    if text is None:
        return None
    from ..algebra.reader import read_expression

    w = read_expression(text, names={}, free=False, what="--tension", hint="give a rational number, e.g. --tension 1/16")
    if not w.is_Rational:
        raise AnalysisError(f"--tension must be a rational number (e.g. 1/16), not {text[:40]!r}")
    return w


def _line(e: dict) -> str:
    n = e["n"]
    if "lambda" not in e:
        return f"n={n:<3d} {e['reif']['witness'].get('reason') or 'not decided'}  [inconclusive]"
    lam = e["lambda"]
    exact = lam["value"] if lam["value"] is not None else f"root of {lam['witness']['polynomial']}"
    im = lam["witness"].get("float_imag")
    approx = (f"{lam['witness']['float']:.10f}" if im is None
              else f"{lam['witness']['float']:.10f}{im:+.10f}i (complex)")
    parts = [f"n={n:<3d} lambda = {exact} ~ {approx}"]
    if "subdominant" in e:
        sub = e["subdominant"]
        parts.append("(block 1's leading eigenvalue; not subdominant: "
                     + (f"the subdominant eigenvalue is block {sub['witness']['block']}'s, ~ "
                        f"{_approx(sub['witness'])} [certified])" if sub["status"] == "certified"
                        else f"{sub['witness']['reason']} [inconclusive])"))
    cv = e["curvature"]
    if "mu" in e:
        cmp = cv["witness"]["mu_vs_lambda2"]
        rel = {"<": "< lambda^2", "=": "= lambda^2", ">": "> lambda^2"}.get(cmp, "vs lambda^2 undecided")
        parts.append(f"mu ~ {e['mu']['witness']['float']:.10f} ({rel}, block {e['mu']['witness']['block']})")
    if "separation" in e:
        sep = e["separation"]
        if -1e-12 < sep["witness"]["float"] < 0:     # a ball about 0 (a tie): no denormal bound printed
            parts.append("gap: not certified positive")
        else:
            parts.append(f"gap >= {sep['witness']['float']:.3g}")
    r = e["reif"]
    parts.append("Reif: " + ("holds" if r["value"] else ("fails: " + r["witness"]["reason"]) if r["status"] == "certified"
                             else "undecided") + f" [{r['status']}]")
    why = cv["witness"].get("reason")
    parts.append(f"curvature: {cv['value']}" + (f" ({why})" if why else "") + f" [{cv['status']}]")
    parts.append(f"C^1: {e['c1']['witness']['verdict']} [{e['c1']['status']}]")
    return "  ".join(parts)


def _approx(w: dict) -> str:
    """An eigenvalue's float from its witness (real, or the ball's midpoint when complex)."""
    if w.get("float") is not None:
        return f"{w['float']:.6g}"
    return str(w["ball"])


def _summary(name: str, closed: dict, entries: list[dict], lattice: str = "") -> str:
    ns = [e["n"] for e in entries]
    ok = [e["n"] for e in entries if e["reif"]["value"]]
    lines = []
    if closed.get("lambda"):
        checked = [e["n"] for e in entries if e.get("lambda", {}).get("witness", {}).get("closed_form_checked")]
        lines.append(f"closed form: lambda(n) = {closed['lambda']}, c = cos(2*pi/n) (a root of block 1 for "
                     f"n >= {closed['valid_from']}; its Arb value lies in lambda's isolating ball at "
                     f"{len(checked)} of {len(ns)} valences)")
    else:
        lines.append(f"closed form: none ({closed.get('reason', 'block 1 not solvable by radicals here')})")
    lines.append(f"Reif's eigen-conditions: certified at {len(ok)} of {len(ns)} valences"
                 + ("" if len(ok) == len(ns) else f" (not at {_ranges([n for n in ns if n not in ok])})"))
    by: dict[str, list[int]] = {}
    for e in entries:
        by.setdefault(e.get("curvature", {}).get("value", "inconclusive"), []).append(e["n"])
    lines.append("curvature: " + "; ".join(f"{k} at n = {_ranges(v)}" for k, v in by.items()))
    c1: dict[str, list[int]] = {}
    for e in entries:          # a valence certified by Zorin's cell test (--charmap-cells) counts as certified
        cells = e.get("charmap_cells", {}).get("status")
        c1.setdefault("certified" if cells == "certified" else e["c1"]["status"], []).append(e["n"])
    tested = [e for e in entries if "charmap_cells" in e]
    if tested:
        by_cells: dict[str, list[int]] = {}
        for e in tested:
            by_cells.setdefault(e["charmap_cells"]["status"], []).append(e["n"])
        lines.append("C^1 for generic initial data by Zorin's cell test (--charmap-cells): "
                     + "; ".join(f"{k} at n = {_ranges(v)}" for k, v in by_cells.items()))
    if set(c1) == {"certified"}:
        lines.append("C^1: certified at every valence (eigen-conditions and a regular, injective characteristic map)")
    elif any("characteristic_map" in e for e in entries):
        lines.append("C^1: " + "; ".join(f"{k} at n = {_ranges(v)}" for k, v in c1.items()))
    else:
        from ..vertex.valence import NO_CHARACTERISTIC_MAP

        why = NO_CHARACTERISTIC_MAP.get(lattice, "the characteristic map is not checked for these rules")
        parts = []
        if "certified" in c1:
            parts.append(f"certified (for generic initial data, Zorin's cell test) at n = {_ranges(c1['certified'])}")
        if "refuted" in c1:
            parts.append(f"refuted (not C^1 for generic initial data, certified) at n = {_ranges(c1['refuted'])}")
        if "inconclusive" in c1:
            parts.append((f"inconclusive at n = {_ranges(c1['inconclusive'])}" if parts else
                          "inconclusive at every valence") + f" (eigen-conditions only; {why})")
        lines.append("C^1: " + "; ".join(parts))
        sampled = [e for e in entries if e.get("characteristic_map_numerical", {}).get("value")]
        if sampled:
            rings = sampled[0]["characteristic_map_numerical"]["witness"]["resolution"]
            lines.append(f"numerically (floats, not a proof): the characteristic net sampled on {rings} rings is "
                         f"regular and winds once at n = {_ranges([e['n'] for e in sampled])}")
    return f"{name}:\n  " + "\n  ".join(lines)


def _ranges(ns: list[int]) -> str:
    out, i = [], 0
    while i < len(ns):
        j = i
        while j + 1 < len(ns) and ns[j + 1] == ns[j] + 1:
            j += 1
        out.append(str(ns[i]) if i == j else f"{ns[i]}..{ns[j]}")
        i = j + 1
    return ", ".join(out)


def cmd_vertex(args) -> None:
    import time

    from ..vertex.valence import closed_form_lambda, parse_valences, valence_entry
    from .common import _emit, _print, check_figure

    valences = parse_valences(args.valence)
    if args.tune:
        return _cmd_tune(args, valences)
    if args.figure:
        check_figure(args.figure, "--figure")
    base = _rules(args, None)
    cells = getattr(args, "charmap_cells", False)
    if cells and args.scheme != "modified-butterfly":
        raise AnalysisError("--charmap-cells applies to --scheme modified-butterfly only")
    if cells and len(valences) > MAX_CELL_VALENCES:
        raise AnalysisError(f"--charmap-cells takes 3-12 s per valence: give at most {MAX_CELL_VALENCES} "
                            "valences, e.g. --valence 3..18")
    if args.figure and len(valences) == 1 and base.lattice == "sqrt3":
        raise AnalysisError("--figure with one valence draws the characteristic map, which is not available for "
                            "sqrt3: give a valence range (e.g. --valence 3..12) for the eigenvalue figure")
    closed = closed_form_lambda(base)
    from .. import progress

    entries = []
    with progress.on_terminal("vertex", enabled=not args.json):
        for k, n in enumerate(valences, start=1):
            rules = _rules(args, n)
            rules.check_valence(n)
            t0 = time.perf_counter()
            with progress.part(f"valence {n} ({k}/{len(valences)})"):
                entries.append(valence_entry(rules, n, closed))
            entries[-1]["timing"] = {"seconds": round(time.perf_counter() - t0, 3)}
            if not args.json:
                _print(_line(entries[-1]))
            if cells:
                t0 = time.perf_counter()
                with progress.part(f"valence {n}: Zorin's cell test"):
                    entries[-1]["charmap_cells"] = _zorin(args, n)
                entries[-1]["charmap_cells"]["timing"] = {"seconds": round(time.perf_counter() - t0, 3)}
                if not args.json:
                    _print(_cells_line(entries[-1]["charmap_cells"]))
    name = base.name if base.name != "user" else "user rules"
    doc = {"scheme": name, "rules": base.source, "ring": base.ring, "matrix_size": base.size,
           "closed_form": {k: v for k, v in closed.items() if k != "expr"}, "valences": entries,
           "c1_note": "C^1 is certified only with a certified regular and injective characteristic map "
                      "(checked for Loop- and Catmull-Clark-type rules on the 2-ring and for Doo-Sabin; not for "
                      "the butterfly family or sqrt3); refuted (not C^1 for generic initial data) only where "
                      "analysis.vertex.necessary proves it at that valence, by a theorem whose hypotheses are all "
                      "checked (so far the original butterfly at n = 3 and 8..50); otherwise the verdict is "
                      "inconclusive"}
    if cells:
        doc["c1_note"] += ("; --charmap-cells: Zorin's cell test of the modified butterfly's characteristic map, "
                           "in each valence's charmap_cells (certified: C^1 for generic initial data)")
    if args.figure and len(valences) == 1:
        doc["figure"] = _charmap_figure(args, valences[0], entries[0], name)
    elif args.figure:
        from ..report.vertex_plots import plot_vertex_spectrum

        doc["figure"] = plot_vertex_spectrum(entries, args.figure, name)
    if args.json:
        _emit(args, doc, "")
    else:
        _print(_summary(name, closed, entries, base.lattice))
        if args.figure:
            _print(f"figure: {args.figure}")


#: valences per run of ``--charmap-cells`` (each takes 3-12 s of CPU after the regular part's bound, about 10 s)
MAX_CELL_VALENCES = 16


def _zorin(args, n: int) -> dict:
    """Zorin's cell test of the modified butterfly's characteristic map at valence n, as JSON."""
    from fractions import Fraction

    from ..vertex.zorin import modified_butterfly_zorin

    w = _tension(args.tension)
    tension = Fraction(1, 16) if w is None else Fraction(int(w.p), int(w.q))
    return modified_butterfly_zorin(n, tension=tension).to_json()


def _cells_line(r: dict) -> str:
    w = r["witness"]
    head = ("C^1 for generic initial data (Reif's criterion)" if r["status"] == "certified"
            else r["provenance"]["message"])
    sign = {-1: "positive in the chart", 1: "negative in the chart"}.get(w["jacobian_sign_mask"], "not one sign")
    return (f"      Zorin's cell test: {head} [{r['status']}]: {w['cells']} cells of rings "
            f"{w['annulus'][0]}..{w['annulus'][1]} (cover {'proven' if w['cover'] else 'failed'}), Jacobian "
            f"{sign}, {'winds once' if w['winding'] else 'winding not proven'}, {w['subcells']} sub-cells")


def _charmap_figure(args, n: int, entry: dict, name: str) -> str:
    """The picture of the characteristic map at valence n (block 1's subdominant eigenvector)."""
    from ..report.vertex_plots import plot_characteristic_map
    from ..vertex.charpicture import characteristic_map_lines
    from ..vertex.spectrum import analyse

    rules = _rules(args, n)
    a = analyse(rules, n, curvature=False)
    if a.lam is None:
        raise AnalysisError(f"no characteristic map to draw at n = {n}: the eigenvalues are not isolated")
    segment = characteristic_map_lines(rules, n, a.lam.ball.real)
    status = f"C^1: {entry['c1']['status']}" + ("" if a.reif_ok else
                                                 f"; the map of block 1's leading eigenvector, not a characteristic "
                                                 f"map: eigen-conditions fail ({a.reif_reason})")
    return plot_characteristic_map(segment, n, args.figure, name, status)


def _cmd_tune(args, valences: list[int]) -> None:
    """``--tune NAME``: the values of a free centre weight for which the eigen-conditions hold, per valence."""
    import re

    from ..vertex.tuning import tune_centre
    from .common import _emit, _print

    if args.scheme or not (args.lattice and args.centre):
        raise AnalysisError('--tune works on user rules: give --lattice and --centre with the free weight, '
                            'e.g. --lattice triangle --centre b --tune b')
    if args.edge or args.figure or args.tension:
        raise AnalysisError("--tune takes --lattice, --centre, --ring and --valence only")
    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,15}", args.tune) or args.tune in ("n", "c", "j"):
        raise AnalysisError(f"--tune takes a name (letters, digits, _; not n, c or j), not {args.tune[:20]!r}")
    ring = int(args.ring) if args.ring else 2
    out = []
    for n in valences:
        r = tune_centre(args.lattice, args.centre, args.tune, n, ring=ring)
        out.append(_tune_json(r))
        if not args.json:
            _print(_tune_line(out[-1], args.tune))
    doc = {"parameter": args.tune, "lattice": args.lattice, "centre": args.centre, "ring": ring, "valences": out,
           "note": "the eigen-conditions only (not C^1): open intervals decided at a rational sample, no critical "
                   "value inside; endpoints decided only when rational"}
    if args.json:
        _emit(args, doc, "")


def _tune_json(r: dict) -> dict:
    def show(v):
        return v if isinstance(v, str) else str(v)

    return {"n": r["n"], "status": r["status"], "reason": r.get("reason", ""),
            "lambda_ball": r.get("lambda_ball"),
            "factors": [f.replace(f"free_{r.get('parameter')}", str(r.get("parameter"))) for f in r.get("factors", [])],
            "critical": [{"value": show(p["value"]), "holds": p["holds"]} for p in r.get("critical", [])],
            "intervals": [{"lower": show(i["lower"]), "upper": show(i["upper"]), "holds": i["holds"],
                           "sample": str(i["sample"]), "status": i["status"], "reason": i["reason"]}
                          for i in r["intervals"]]}


def _tune_line(e: dict, name: str) -> str:
    if e["status"] != "certified" and not e["intervals"]:
        return f"n={e['n']:<3d} not decided: {e['reason']} [inconclusive]"
    good = [f"({i['lower']}, {i['upper']})" for i in e["intervals"] if i["holds"]]
    points = [p for p in e["critical"] if p["holds"] is not None]
    extra = [f"{name} = {p['value']}" for p in points if p["holds"]]
    where = " U ".join(good + extra) if (good or extra) else "no value"
    ends = ""
    if points:
        ends = "; at " + ", ".join(f"{name} = {p['value']}: {'holds' if p['holds'] else 'fails'}" for p in points)
    undecided = [i for i in e["intervals"] if i["holds"] is None]
    tail = f"; {len(undecided)} interval(s) undecided" if undecided else ""
    return f"n={e['n']:<3d} eigen-conditions hold for {name} in {where}{ends}{tail} [{e['status']}]"
