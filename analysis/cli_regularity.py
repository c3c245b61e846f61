"""``subdiv holder`` and ``subdiv range``: certified Hölder exponents and C^k parameter ranges.

Examples
--------
::

    subdiv holder --scheme four-point --param w=1/16
    subdiv holder --scheme dfh-chaikin-perturbation --param omega=1/50 --C 2
    subdiv range --scheme dfh-chaikin-perturbation --C 2 --within=-1/20,1/20 --figure alpha.png
"""

from __future__ import annotations

import sympy as sp

from .cli import _add_scheme_args, _emit, _int_arg, _parse_within, scheme_from_args
from .result import AnalysisError
from .symbol import LaurentSymbol


def _fmt(x) -> str:
    return "?" if x is None else f"{float(x):.10f}"


def _numeric_entry(args):
    """The catalogue entry when --scheme names a scheme known only by enclosures (Daubechies)."""
    if getattr(args, "scheme", None) is None:
        return None
    import schemes
    from schemes.catalogue import NumericSchemeEntry

    entry = schemes.get(args.scheme)
    return entry if isinstance(entry, NumericSchemeEntry) else None


def _part(name: str, compute, lines: list, data: dict) -> None:
    """Run one part of ``subdiv holder`` (alpha, C^k, Sobolev): each reports its own result, or its
    own inconclusive with the reason, so that one failing part never hides the others."""
    try:
        part_lines, part_data = compute()
    except AnalysisError as exc:
        lines.append(f"{name}: inconclusive — {exc}")
        data[name] = {"status": "inconclusive", "reason": str(exc)}
        return
    lines.extend(part_lines)
    data[name] = part_data


def _alpha_part(args, a, budget):
    h = _holder(a, budget)
    lines = []
    if h.value is not None:
        lines.append(f"Hölder exponent alpha = {sp.sstr(h.value)} exactly   [{h.status}]")
    else:
        lines.append(f"Hölder exponent alpha in [{_fmt(h.lower)}, {_fmt(h.upper)}]   [{h.status}]")
    w = h.witness
    prod = w.get("product")
    if prod and w.get("k") is not None:
        lines.append(f"  c(z) = 2^{w['k']} a(z)/(1+z)^{w['k'] + 1};  spectrum-maximizing product T_{''.join(map(str, prod))}"
                     + (f";  alpha = {sp.sstr(w['alpha_exact'])}" if w.get("alpha_exact") is not None else ""))
    if "message" in h.provenance:
        lines.append(f"  {h.provenance['message']}")
    return lines, h.to_json()


def _holder(a, budget):
    from .regularity import holder_exponent, holder_exponent_enclosure

    if not isinstance(a, LaurentSymbol):  # a catalogue entry known by enclosures (Daubechies)
        return holder_exponent_enclosure(a, budget_seconds=budget)
    return holder_exponent(a, budget_seconds=budget)


def _smoothness_part(args, a, budget):
    from .regularity import smoothness

    j = _int_arg(args.C, "--C")
    if not isinstance(a, LaurentSymbol):
        raise AnalysisError(f"--C is not available for {getattr(a, 'slug', a)} (known by enclosures only)")
    s = smoothness(a, j, budget_seconds=budget)
    verdict = {True: f"C^{j}: yes", False: f"C^{j}: no", None: f"C^{j}: undecided"}[s.value]
    return ([f"{verdict}   [{s.status}] — {s.witness.get('reason')}"],
            {"j": j, "value": s.value, "status": s.status, "reason": s.witness.get("reason")})


def _sobolev_part(args, a, budget):
    from .regularity import sobolev_exponent

    if not isinstance(a, LaurentSymbol):
        raise AnalysisError(f"the Sobolev exponent is not available for {getattr(a, 'slug', a)} "
                            "(known by enclosures only)")
    s2 = sobolev_exponent(a)
    return ([f"L2-Sobolev exponent s_2 in [{_fmt(s2.lower)}, {_fmt(s2.upper)}]   [{s2.status}; "
             f"valid for stable shifts]"], s2.to_json())


def cmd_holder(args) -> None:
    budget = float(args.budget)
    entry = _numeric_entry(args)
    if entry is not None:
        if args.param:
            raise AnalysisError(f"{entry.slug} is known by certified enclosures only: --param is not available for it")
        a, label = entry, entry.slug
        lines = [f"scheme: {entry.slug}   (mask known by Arb ball enclosures)"]
    else:
        a, label = scheme_from_args(args)
        lines = [f"scheme: {label}   (domain {a.domain})"]
    data: dict = {"scheme": label}
    _part("alpha", lambda: _alpha_part(args, a, budget), lines, data)
    if args.C is not None:
        _part("smoothness", lambda: _smoothness_part(args, a, budget), lines, data)
    if args.sobolev:
        _part("sobolev", lambda: _sobolev_part(args, a, budget), lines, data)
    _emit(args, data, "\n".join(lines))


def cmd_range(args) -> None:
    from .regularity import alpha_curve, ck_parameter_set

    a, label = scheme_from_args(args)
    j = _int_arg(args.C, "--C")
    within = _parse_within(args.within)
    if not all(w.is_finite for w in within):
        raise AnalysisError("--within needs finite bounds for a parameter range, e.g. -1/20,1/20")
    grid = _int_arg(args.grid, "--grid")
    if grid < 2 or grid > 400:
        raise AnalysisError("--grid must be between 2 and 400")
    try:
        tol = float(args.tol)
    except ValueError:
        raise AnalysisError(f"--tol must be a number, not {args.tol!r}") from None
    if not (1e-30 <= tol <= 1):
        raise AnalysisError("--tol must be between 1e-30 and 1")
    r = ck_parameter_set(a, j, args.param_name, within=within, grid=grid, tol=tol,
                         budget_seconds=float(args.budget))
    p = r.witness["parameter"]
    lines = [f"scheme: {label}; where is it C^{j}? parameter {p} in [{sp.sstr(within[0])}, {sp.sstr(within[1])}] "
             f"(grid {grid}, boundaries to {tol:g})   [{r.status}]"]
    if not r.value:
        lines.append("  nowhere on the grid")
    for run in r.value:
        def end(b, which):
            if "open_end" in b:
                return f"~{sp.sstr(b['open_end'])} (grid end)"
            if "exact" in b:
                return f"{sp.sstr(b['exact'])} ~ {b['exact_float']:.12g} [exact]"
            lo, hi = b["bracket"]
            return f"in [{float(lo):.12g}, {float(hi):.12g}]"
        lines.append(f"  C^{j} from {end(run['left'], 'left')} to {end(run['right'], 'right')}")
    for b in r.witness["boundaries"]:
        lo, hi = b["bracket"]
        lines.append(f"  boundary: certified C^{j} at {sp.sstr(b.get('certified_C^j_at'))}, certified not C^{j} at "
                     f"{sp.sstr(b.get('certified_not_C^j_at'))} ({b.get('how', b['status'])})")
    if r.witness["undecided"]:
        lines.append("  undecided grid points: " + ", ".join(sp.sstr(x) for x in r.witness["undecided"]))
    for run in r.value:
        it = run.get("interior")
        if it:
            lines.append(f"  interior [{float(it['from']):.10g}, {float(it['to']):.10g}]: "
                         + ("proven C^%d on the whole interval (%s)" % (j, it["route"]) if it["proven"] else
                            "certified at the grid points only (the norm tests do not cover it)"))
    if "message" in r.provenance:
        lines.append(f"  {r.provenance['message']}")
    data = {"scheme": label, "j": j, "parameter": p, "within": list(within), "result": r.to_json()}
    if args.figure:
        curve = alpha_curve(a, p, within=within, samples=max(grid, 8), budget_seconds=float(args.budget))
        from .plots import plot_alpha_curve

        try:
            plot_alpha_curve(curve, args.figure, j=j, boundaries=r.witness["boundaries"], label=label)
        except OSError as exc:
            raise AnalysisError(f"cannot write {args.figure}: {exc.strerror or exc}") from None
        lines.append(f"figure written to {args.figure}")
        data["figure"] = args.figure
    _emit(args, data, "\n".join(lines))


def register(sub) -> None:
    s = sub.add_parser("holder", help="certified Hölder exponent (joint spectral radius), C^k verdict, Sobolev exponent")
    _add_scheme_args(s)
    s.add_argument("--C", metavar="K", help="also decide whether the scheme is C^K")
    s.add_argument("--sobolev", action="store_true", help="also the L2-Sobolev exponent (transition operator)")
    s.add_argument("--budget", default="20", help="seconds for the joint spectral radius (default 20)")
    s.set_defaults(func=cmd_holder)

    s = sub.add_parser("range", help="where a one-parameter family is C^k: boundaries certified on both sides")
    _add_scheme_args(s)
    s.add_argument("--C", metavar="K", required=True, help="smoothness order k")
    s.add_argument("--param-name", metavar="NAME", help="the free parameter (default: the only one)")
    s.add_argument("--within", metavar="LOW,HIGH", required=True, help="finite parameter interval (use --within=-1,1)")
    s.add_argument("--grid", default="16", help="number of grid cells (default 16)")
    s.add_argument("--tol", default="1e-8", help="boundary tolerance (default 1e-8)")
    s.add_argument("--budget", default="20", help="seconds per joint spectral radius (default 20)")
    s.add_argument("--figure", metavar="PATH", help="write the curve alpha(p) with its certified error bars")
    s.set_defaults(func=cmd_range)
