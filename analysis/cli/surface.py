"""``subdiv surface``: a bivariate scheme on a regular grid with a dilation matrix — sum rules, polynomial
generation and reproduction, symmetry, box-spline factors, and the certified Hölder exponent with its C^l
verdicts.

The name follows the literature on *surface* subdivision: the command analyses the regular part of a surface
scheme (Loop, Catmull–Clark, butterfly, ...) and any other mask on ``Z^2`` with a dilation (quincunx, sqrt 3).
Convention: ``(S_a f)(alpha) = sum_beta a(alpha - M beta) f(beta)``, ``a(z) = sum a(alpha) z1^alpha_1 z2^alpha_2``
(see ``docs/surfaces.md``).

Examples
--------
::

    subdiv surface --scheme loop
    subdiv surface --symbol "(1+z1)**2*(1+z2)**2/(4*z1*z2)"
    subdiv surface --mask2 "0,0:1; 1,0:1/2; -1,0:1/2; 0,1:1/2; 0,-1:1/2; 1,1:1/4; -1,-1:1/4; 1,-1:1/4; -1,1:1/4"
    subdiv surface --scheme butterfly --param w=1/16 --json
    subdiv surface --scheme butterfly --C 1 --within=0,1/8 --grid 4
    subdiv surface --scheme kobbelt-quad --C 1 --within=0,1/4      # a tensor product: the univariate route
    subdiv surface --file mask.toml
    subdiv surface --scheme butterfly --differences 1
"""

from __future__ import annotations

from ..result import AnalysisError
from .common import _emit, _int_arg, _parse_params, work_arg


def _refine(args) -> None:
    from ..bivariate.refine import basic_limit_samples
    from .common import check_figure

    if args.figure:
        check_figure(args.figure, "--figure")
    _, a, label, _ = _mask_from_args(args)
    grid = args.grid
    if grid is None:
        grid = "quad"
        if args.scheme is not None:
            from schemes.surfaces import get

            grid = get(args.scheme).grid
    pts, vals = basic_limit_samples(a, args.refine, grid)
    data = {"scheme": label, "steps": args.refine, "grid": grid, "samples": int(len(vals)),
            "max": float(vals.max()), "min": float(vals.min()),
            "bounding_box": [[float(pts[:, 0].min()), float(pts[:, 1].min())],
                             [float(pts[:, 0].max()), float(pts[:, 1].max())]]}
    text = (f"{label}: S^{args.refine} delta on the {grid} grid: {len(vals)} samples (floating point), "
            f"values in [{data['min']:.6g}, {data['max']:.6g}], support within "
            f"[{data['bounding_box'][0][0]:.4g}, {data['bounding_box'][1][0]:.4g}] x "
            f"[{data['bounding_box'][0][1]:.4g}, {data['bounding_box'][1][1]:.4g}]")
    if args.figure:
        from ..report.surface_plots import plot_basic_limit

        plot_basic_limit(pts, vals, args.figure, f"{label}: S^{args.refine} delta")
        data["figure"] = args.figure
        text += f"\nwrote {args.figure}"
    _emit(args, data, text)


def _differences(args) -> None:
    """``--differences K``: the difference scheme of order ``K`` (M = m I), its exact identity, and the norm
    test of C^(K-1) (:mod:`analysis.bivariate.differences`)."""
    import sympy as sp

    from ..bivariate.differences import difference_scheme

    k = _int_arg(args.differences, "--differences")
    for option in _given(args, ("C", "within", "sweep", "refine", "figure", "grid", *RANGE_OPTIONS)):
        raise AnalysisError(f"--differences is a mode of its own: drop {option} (or drop --differences)")
    _, a, label, vals = _mask_from_args(args, keep="")
    B = difference_scheme(a, k).value
    m = B.m
    data = {"scheme": label, "dilation": [list(r) for r in a.dilation.matrix],
            "parameters": {key: sp.sstr(v) if isinstance(v, sp.Basic) else str(v) for key, v in vals.items()},
            "differences": None, "norm_test": None}
    if B.params:
        test = ("; the norm test needs values of " + ", ".join(p.name for p in B.params) +
                " (--param " + B.params[0].name + "=VALUE)")
    else:
        text, tested = _norm_test_text(a, k - 1, data)
        test = "; " + text
        B = tested if tested is not None else B            # show the scheme whose norm is certified
    n = len(B.indices)
    (i0, j0), (i1, j1) = B.support_box
    built = "" if B.shift == (0, 0) else f", B built from z^{B.shift} a"
    data["differences"] = {"order": k, "m": m, "shift": list(B.shift), **_scheme_json(B),
                           "identity": "checked exactly", "status": "certified"}
    text = (f"{label}: difference scheme of order {k} (M = {m}I{built}): B is {n} x {n} over {B.domain}, entries in "
            f"[{i0}, {i1}] x [{j0}, {j1}], nabla^mu(z) a(z) = sum_nu b_mu,nu(z) nabla^nu(z^{m}) checked exactly"
            + test)
    _emit(args, data, text)


def _scheme_json(B) -> dict:
    """A difference scheme in the JSON: its indices, domain and matrix entry by entry (exact, sympy strings)."""
    import sympy as sp

    return {"indices": [list(mu) for mu in B.indices], "domain": B.domain,
            "matrix": [[sp.sstr(B.entry(mu, nu)) for nu in B.indices] for mu in B.indices]}


def _norm_test_text(a, l: int, data: dict):
    """The C^l norm test of ``--differences l+1`` (:func:`analysis.bivariate.differences.smoothness_by_norms`):
    its text, its JSON in ``data["norm_test"]`` (each level with the scheme its norms are of: order, shift,
    matrix), and the scheme of order ``l + 1`` whose norms are reported (``None`` when the test stopped below)."""
    import sympy as sp

    from ..bivariate.differences import smoothness_by_norms

    r = smoothness_by_norms(a, l)
    m = r.provenance["m"]
    levels = r.witness["levels"]
    data["norm_test"] = {"status": r.status, "C": l, "certified_up_to": r.value,
                         "levels": [{"C": v["C"], "L": v["L"], "order": v["C"] + 1,
                                     "shift": None if v["shift"] is None else list(v["shift"]),
                                     "scaled_by": m ** v["C"],
                                     "norms": [sp.sstr(x) for x in v["norms"]], "stopped": v["stopped"],
                                     **({} if v["scheme"] is None else {"matrix": _scheme_json(v["scheme"])["matrix"]})}
                                    for v in levels]}
    last = levels[-1]
    tested = last["scheme"] if last["C"] == l else None
    norm = (lambda L: f"||S_B^{L}||_inf") if l == 0 else (lambda L: f"||({m ** l} S_B)^{L}||_inf")
    if r.value == l:
        Ls = ", ".join(str(v["L"]) for v in levels[:-1])
        lower = ("" if l == 0 else f", C^0 by order 1 (L = {Ls})" if l == 1 else
                 f", C^0 to C^{l - 1} by the orders below (L = {Ls})")
        verdict = "it converges (C^0, certified)" if l == 0 else f"C^{l} (certified)"
        return f"{norm(last['L'])} = {sp.sstr(last['norms'][-1])} < 1{lower}: {verdict}", tested
    shown = f"; C^{r.value} is shown (certified)" if r.value >= 0 else ""
    if last["L"] is None and last["norms"]:
        stop = "the longest product tried" if last["stopped"].startswith("L = ") else last["stopped"]
        why = f"C^{last['C']} not shown by norms up to L = {len(last['norms'])} ({stop}){shown}"
    else:
        why = f"C^{last['C']} not shown by norms ({last['stopped']}){shown}"
    return f"{why}; inconclusive: the Hölder exponent decides C^{l}", tested


def _mask_from_args(args, keep=None):
    from ..bivariate.mask import BivariateMask

    given = [x for x in (args.scheme, args.symbol, args.mask2, args.file) if x is not None]
    if len(given) != 1:
        raise AnalysisError("give exactly one of --scheme NAME, --symbol 'EXPR in z1, z2', --mask2 'i,j:coef; ...' "
                            "or --file MASK.toml")
    params = {k: v for k, v in _parse_params(args.param).items()}
    if args.scheme is not None:
        from schemes.surfaces import get

        e = get(args.scheme)
        if args.dilation is not None:
            raise AnalysisError(f"{e.slug} has its own dilation; --dilation is for --symbol and --mask2")
        a = e.mask(general=True)
        label = e.slug
        ranging = getattr(args, "within", None) is not None
        vals = {**{k: v for k, v in e.defaults.items() if not ranging or (keep is not None and k != keep)},
                **params}
    elif args.file is not None:
        from ..bivariate.mask_file import read_mask_file

        if args.dilation is not None:
            raise AnalysisError("a mask file gives its own dilation (key dilation); drop --dilation")
        a = read_mask_file(args.file)
        label = a.name or "the mask"
        vals = params
    else:
        if args.symbol is not None:
            a = BivariateMask.from_symbol(args.symbol, args.dilation)
        else:
            a = BivariateMask.from_list(args.mask2, args.dilation)
        label = "the mask"
        vals = params
    general = a
    if vals:
        a = a.at(vals)
    if keep is not None or getattr(args, "within", None) is not None:     # a C^l set: one parameter stays free
        return a, a, label, vals
    if a.params:
        raise AnalysisError(f"give values to the parameters {', '.join(p.name for p in a.params)} with "
                            "--param NAME=VALUE (exact, e.g. w=1/16)")
    return general, a, label, vals


def _list(args) -> None:
    from schemes.surfaces import entries

    rows = [{"name": e.slug, "title": e.title, "dilation": e.dilation_name, "defaults": dict(e.defaults),
             "source": e.source} for e in entries()]
    text = "\n".join(f"{r['name']:<14} {r['title']}" + (f" [{', '.join(f'{k}={v}' for k, v in r['defaults'].items())}]"
                                                        if r["defaults"] else "") for r in rows)
    _emit(args, {"schemes": rows}, text)


def _alpha_text(h) -> str:
    import sympy as sp

    if h.value is not None:
        return f"alpha = {sp.sstr(h.value)} exactly ({h.status})"
    from ..jsonable import fmt_bound

    # decimals rounded outward (15 significant digits), so the printed interval encloses alpha
    lo = "?" if h.lower is None else fmt_bound(h.lower, "lower", 15, "g")
    hi = "?" if h.upper is None else (sp.sstr(h.upper) if h.witness.get("alpha_upper_exact")
                                      else fmt_bound(h.upper, "upper", 15, "g"))
    note = "; the upper end is exact" if h.witness.get("alpha_upper_exact") else ""
    jsr = h.witness.get("jsr")
    if h.status == "inconclusive" and jsr is not None and jsr.status == "inconclusive":
        note += f"; the JSR bounds did not meet: a larger --budget may settle it (now {h.provenance['budget']})"
    return f"alpha in [{lo}, {hi}] ({h.status}{note})"


#: the most parameter values one --sweep takes (each is a certified JSR computation)
MAX_SWEEP = 40


def _sweep(args) -> None:
    """``--sweep NAME=v1,v2,...``: the certified alpha enclosure and C^l verdicts at each value (a table; the
    parameter values between the points are not certified)."""
    import sympy as sp

    from ..bivariate.holder import holder_exponent, smoothness_verdicts
    from .common import read_number

    if "=" not in args.sweep:
        raise AnalysisError("--sweep takes NAME=v1,v2,..., e.g. w=0,1/32,1/16")
    name, vals = (t.strip() for t in args.sweep.split("=", 1))
    values = [v.strip() for v in vals.split(",") if v.strip()]
    if not values or len(values) > MAX_SWEEP:
        raise AnalysisError(f"--sweep takes 1 to {MAX_SWEEP} values, e.g. w=0,1/32,1/16")
    if args.param and any(p.split("=", 1)[0].strip() == name for p in args.param):
        raise AnalysisError(f"{name} is swept: do not also give --param {name}")
    budget = work_arg(args.budget, "--budget")
    rows, lines = [], []
    for v in values:
        x = read_number(v, f"--sweep {name}")
        args_one = list(args.param or []) + [f"{name}={sp.sstr(x)}"]
        args.param, saved = args_one, args.param
        try:
            _, a, label, _ = _mask_from_args(args)
        finally:
            args.param = saved
        h = holder_exponent(a, budget=budget)
        ck = smoothness_verdicts(h)
        lo = None if h.lower is None else sp.sstr(h.lower)
        hi = None if h.upper is None else sp.sstr(h.upper)
        rows.append({name: sp.sstr(x), "status": h.status, "lower": lo, "upper": hi,
                     "value": None if h.value is None else sp.sstr(h.value),
                     "smoothness": {f"C{l}": c for l, c in ck.items()}})
        enc = _alpha_text(h)
        top = max((l for l, c in ck.items() if c), default=None)
        smooth = "not C^0" if top is None and ck.get(0) is False else (
            f"C^{top}" + ("" if ck.get(top + 1) is False else ", C^" + str(top + 1) + " undecided")
            if top is not None else "C^0 undecided")
        lines.append(f"{name} = {sp.sstr(x)}: {enc}; {smooth}")
    lines.append("(each value certified on its own; the values between them are not)")
    _emit(args, {"sweep": name, "points": rows}, "\n".join(lines))


#: the defaults of the C^l-set options (``None`` in the parser, so that a given option is seen)
GRID_CELLS, RANGE_BUDGET = "8", "2000000"
#: the options of ``subdiv surface`` by their argparse names, with their defaults
OPTIONS = {"scheme": "--scheme", "symbol": "--symbol", "mask2": "--mask2", "file": "--file", "dilation": "--dilation",
           "param": "--param", "budget": "--budget", "sweep": "--sweep", "C": "--C", "within": "--within",
           "param_name": "--param-name", "grid_cells": "--grid-cells", "range_budget": "--range-budget",
           "refine": "--refine", "grid": "--grid", "figure": "--figure", "differences": "--differences"}
DEFAULTS = {"budget": "20000"}
#: the options used only by a C^l set (``--C L --within=LOW,HIGH``)
RANGE_OPTIONS = ("param_name", "grid_cells", "range_budget")


def _given(args, names) -> list[str]:
    """The options among ``names`` (argparse names) given on the command line, spelt as typed."""
    return [OPTIONS[n] for n in names if getattr(args, n, None) not in (None, False, DEFAULTS.get(n))]


def _grid_cells(args) -> int:
    """``--grid-cells N`` (default 8), checked against its range."""
    from ..bivariate.ranges import MAX_GRID
    from .common import _int_arg

    text = GRID_CELLS if args.grid_cells is None else args.grid_cells
    grid = _int_arg(text, "--grid-cells")
    if not 1 <= grid <= MAX_GRID:
        raise AnalysisError(f"--grid-cells must be between 1 and {MAX_GRID}, not {text}")
    return grid


def _range(args) -> None:
    """``--C L --within=LOW,HIGH``: the certified C^l set of a one-parameter family
    (:func:`analysis.bivariate.ranges.ck_set`)."""
    import sympy as sp

    from ..bivariate.ranges import ck_set
    from .common import _int_arg, _parse_within

    if args.within is None or args.C is None:
        raise AnalysisError("a C^l set needs both --C L and --within=LOW,HIGH (e.g. --C 1 --within=0,1/8); "
                            "for the verdict at one value give it with --param (e.g. --param w=1/16 --C 1)")
    l = _int_arg(args.C, "--C")
    if not 0 <= l <= 8:
        raise AnalysisError("--C takes 0 to 8")
    within = _parse_within(args.within)
    if not all(w.is_finite for w in within):
        raise AnalysisError("--within needs finite bounds, e.g. --within=0,1/8")
    grid = _grid_cells(args)
    budget = work_arg(args.budget, "--budget")
    total = work_arg(RANGE_BUDGET if args.range_budget is None else args.range_budget, "--range-budget")
    general, _, label, vals = _mask_from_args(args, keep=args.param_name)
    if not general.params:
        raise AnalysisError(f"{label} has no free parameter: drop --within (--C {l} alone gives its C^{l} verdict)")
    if len(general.params) != 1:
        raise AnalysisError("a C^l set needs exactly one free parameter: fix the others with --param NAME=VALUE")
    from ..bivariate.tensor import tensor_factors

    t = tensor_factors(general)
    if t.value is not None:                       # b(z1) c(z2), M = m I: the univariate route, exactly
        if args.range_budget is not None:
            raise AnalysisError("--range-budget bounds the bivariate boxes; this family is a tensor product, whose "
                                "C^l set is computed by the univariate route: drop --range-budget (--budget sets the "
                                "work of each verdict)")
        return _tensor_range(args, general, t.value, label, l, within, grid, budget)
    r = ck_set(general, l, args.param_name, within=within, grid=grid, budget=total, point_budget=budget,
               box_budget=budget)
    p = r.witness["parameter"]
    v = r.value
    fmt = lambda x: sp.sstr(x)
    lines = [f"{label}: where is it C^{l}? {p} in [{fmt(within[0])}, {fmt(within[1])}] (grid {grid}; "
             f"T_eps({p}) restricted to V_{l + 1}, dimension {r.witness['dimension']})   [{r.status}]"]
    for s in r.witness["samples"]:
        a = s["alpha"]
        enc = "alpha ?" if a is None or a[0] is None else (
            f"alpha in [{float(a[0]):.10g}, {float(a[1]):.10g}]" if a[1] is not None else f"alpha >= {float(a[0]):.10g}")
        verdict = {True: f"C^{l}", False: f"not C^{l}", None: "undecided"}[s["C^l"]]
        lines.append(f"  {p} = {fmt(s['t'])}: {enc} ({s['status']}); {verdict}")
    cert = " u ".join(f"{'(' if I.left_open else '['}{fmt(I.start)}, {fmt(I.end)}{')' if I.right_open else ']'}"
                      if I.start != I.end else f"{{{fmt(I.start)}}}" for I in v["certified"]) or "nowhere"
    ends = any((b.get("strip") or {}).get("method") for b in r.witness["boundaries"])
    lines.append(f"C^{l} (certified: point verdicts, JSR of the Bernstein coefficient matrices on boxes"
                 f"{', the strips next to exact ends as below' if ends else ''}): {p} in {cert}")
    lines.append(f"not C^{l} (certified counterexamples): " + (f"{p} = " + ", ".join(
        f"{fmt(x)}" + ("" if x.is_Rational else f" ~ {float(x):.12g}") for x in v["not_Cl"]) if v["not_Cl"] else "none"))
    for b in r.witness["boundaries"]:
        if "exact" in b:
            st = b.get("strip") or {}
            es = b.get("end_strip") or {}
            upto = (_end_strip_line(l, p, b, es, fmt) if st.get("method") else
                    f"C^{l} certified up to the end (the strip next to it by a parametric invariant polytope, "
                    f"s.m.p. T_{st['product']}, {st['pieces']} sub-intervals)" if st.get("closed") else
                    (f"C^{l} certified up to {fmt(b['certified_Cl_to'])}" if b["certified_Cl_to"] != b["certified_Cl_at"]
                     else f"no box toward it certified: the nearest certified C^{l} point is {fmt(b['certified_Cl_at'])}")
                    + (f"; the strip next to the end not closed: {st['reason']}" if st else ""))
            lines.append(f"  end {fmt(b['exact'])} exact: {b['how']} (JSR >= rho(M)^-{l} there); {upto}")
            if es and not es.get("closed") and es.get("reason"):
                lines.append(f"    (the exact end-strip argument: {es['reason']})")
        else:
            lines.append(f"  end between {fmt(b['certified_Cl_to'])} (C^{l}) and {fmt(b['certified_not_Cl_at'])} "
                         f"(not C^{l}): no exact crossing found")
    if v["gaps"]:
        lines.append("undecided (inconclusive): " + ", ".join(
            f"({fmt(a)}, {fmt(b)}) width {float(b - a):.3g}" for a, b in v["gaps"]))
    for st in r.witness.get("not_Cl_proven", []):
        lines.append(f"not C^{l} on [{fmt(st['from'])}, {fmt(st['to'])}] (certified: {st['how']})")
    if r.witness["between_counterexamples"]:
        lines.append("between counterexamples (sampled, not examined): " + ", ".join(
            f"({fmt(a)}, {fmt(b)})" for a, b in r.witness["between_counterexamples"]))
    data = {"scheme": label, "parameter": p, "l": l, "within": [fmt(w) for w in within], "status": r.status,
            "not_Cl_proven": [{"from": fmt(st["from"]), "to": fmt(st["to"]), "how": st["how"]}
                              for st in r.witness.get("not_Cl_proven", [])],
            "certified": [{"from": fmt(I.start), "to": fmt(I.end), "from_open": bool(I.left_open),
                           "to_open": bool(I.right_open)} for I in v["certified"]],
            "not_Cl": [fmt(x) for x in v["not_Cl"]], "gaps": [[fmt(a), fmt(b)] for a, b in v["gaps"]],
            "between_counterexamples": [[fmt(a), fmt(b)] for a, b in r.witness["between_counterexamples"]],
            "samples": [{"t": fmt(s["t"]), "Cl": s["C^l"], "status": s["status"],
                         "alpha": None if s["alpha"] is None else [None if x is None else fmt(x) for x in s["alpha"]]}
                        for s in r.witness["samples"]],
            "boundaries": [{k: (fmt(x) if isinstance(x, sp.Basic) else x) for k, x in b.items() if k != "between"}
                           for b in r.witness["boundaries"]],
            "work": r.provenance["work"]}
    _emit(args, data, "\n".join(lines))


def _set_text(S, p: str | None = None) -> str:
    """An :class:`~analysis.algebra.algebraic.IntervalSet` with its irrational ends also as decimals."""
    import sympy as sp

    def end(x):
        return sp.sstr(x.expr) if x.is_rational else f"{sp.sstr(x.expr)} ~ {float(x):.10g}"

    out = []
    for lo, hi, lc, hc in S.parts:
        if lo.compare(hi) == 0:
            out.append(end(lo) if p else "{" + end(lo) + "}")
        else:
            out.append(f"{'[' if lc else '('}{end(lo)}, {end(hi)}{']' if hc else ')'}")
    if p:
        return f"{p} = " + ", ".join(out) if out else ""
    return " u ".join(out) or "nowhere"


def _in_text(p: str, S) -> str:
    return "nowhere" if S.is_empty else f"{p} in {_set_text(S)}"


def _tensor_range(args, general, tf, label, l, within, grid, budget) -> None:
    """``--C L --within`` on a tensor-product family (:func:`analysis.bivariate.tensor.tensor_ck_set`): the factors,
    their univariate C^L sets (the route of ``subdiv range``) and the intersection."""
    import sympy as sp

    from ..algebra.reader import as_expr
    from ..bivariate.tensor import tensor_ck_set
    from .regularity import _interior_lines

    r = tensor_ck_set(general, l, args.param_name, within=within, grid=grid, budget=budget, factors=tf)
    p, m, v = r.witness["parameter"], tf.m, r.value
    fmt = sp.sstr
    same = tf.same
    lines = [f"{label}: where is it C^{l}? {p} in [{fmt(within[0])}, {fmt(within[1])}]   [{r.status}]",
             f"the mask is a tensor product a(z1, z2) = b(z1) {'b' if same else 'c'}(z2) with M = {m}I (exact: its "
             f"{tf.grid[0]} x {tf.grid[1]} coefficient grid A has rank 1 over Q({p}), {m * m} A = r s^T identically "
             f"with r, s its row and column sums; the mask sums to {m * m} for every {p}, so "
             f"{'b sums' if same else 'b and c sum'} to {m} on the whole interval):",
             f"  b(z) = {tf.b}"]
    if not same:
        lines.append(f"  c(z) = {tf.c}")
    lines.append(f"  so phi = phi_b (x) phi_{'b' if same else 'c'}, and S_a is C^{l} exactly where "
                 + ("S_b is" if same else "S_b and S_c are") + f" C^{l} (docs/surfaces.md)")
    factors = [("b", r.witness["b"])] + ([] if same else [("c", r.witness["c"])])
    data_f = []
    for name, f in factors:
        st = "certified" if f.sets["undecided"].is_empty else "inconclusive"
        how = {"ck_parameter_set": f"univariate, as subdiv range --grid {grid}",
               "ck_range": f"univariate {m}-ary, as subdiv range: exact norm and eigenvalue sets",
               "factor count": f"univariate {m}-ary: {f.result.witness.get('reason')}"}.get(
            f.route, "no parameter: one certified verdict")
        lines.append(f"C^{l} of S_{name} ({how}): {_in_text(p, f.sets['Cl'])}   [{st}]")
        for x, why in f.ends:
            x = as_expr(x)
            lines.append(f"  end {fmt(x)}{'' if x.is_Rational else f' ~ {float(x):.10g}'} exact: {why}")
        for run in (f.result.value if f.route == "ck_parameter_set" else []):
            if run.get("interior"):
                lines.extend(_interior_lines(run["interior"], l))
        data_f.append({"factor": name, "symbol": str(f.symbol), "mask": [fmt(x) for x in f.symbol.mask],
                       "start": f.symbol.start, "status": st,
                       **{k: S.to_json() for k, S in f.sets.items()},
                       "ends": [{"exact": fmt(x), "how": why} for x, why in f.ends]})
    lines.append(f"C^{l} (certified: the intersection of the univariate C^{l} sets): {_in_text(p, v['Cl'])}")
    lines.append(f"not C^{l} (certified: counterexamples and proven stretches): " + (_set_text(v["not_Cl"], p) or "none"))
    if not v["undecided"].is_empty:
        lines.append(f"undecided (inconclusive): {_set_text(v['undecided'])}")
    if not v["sampled"].is_empty:
        lines.append(f"between counterexamples (sampled, not examined): {_set_text(v['sampled'])}")

    def part(lo, hi, lc, hc):
        return {"from": fmt(lo.expr), "to": fmt(hi.expr), "from_open": not lc, "to_open": not hc}

    data = {"scheme": label, "parameter": p, "l": l, "within": [fmt(w) for w in within], "status": r.status,
            "route": "tensor product",
            "tensor": {"m": m, "b": str(tf.b), "c": str(tf.c), "same_factor": same, "grid": list(tf.grid)},
            "factors": data_f,
            "certified": [part(*x) for x in v["Cl"].parts],
            "not_Cl": [fmt(lo.expr) if lo.compare(hi) == 0 else part(lo, hi, lc, hc)
                       for lo, hi, lc, hc in v["not_Cl"].parts],
            "gaps": [[fmt(lo.expr), fmt(hi.expr)] for lo, hi, _, _ in v["undecided"].parts],
            "between_counterexamples": [[fmt(lo.expr), fmt(hi.expr)] for lo, hi, _, _ in v["sampled"].parts]}
    _emit(args, data, "\n".join(lines))


def _has_free_parameter(args) -> bool:
    """Does ``--C L`` ask for a C^l set (the mask keeps a parameter that ``--param`` does not fix; a catalogue
    default does not fix it) rather than for one verdict?"""
    if args.scheme is not None:
        from schemes.surfaces import get

        given = set(_parse_params(args.param))
        return any(p.name not in given for p in get(args.scheme).mask(general=True).params)
    _, a, _, _ = _mask_from_args(args, keep="")
    return bool(a.params)


def _decimal_up(q, digits: int = 4) -> str:
    """``q`` (a rational upper bound) rounded UP to ``digits`` decimals, so the printed bound stays a bound.

    >>> _decimal_up("38284/100000"), _decimal_up(1)
    ('0.3829', '1.0000')
    """
    from fractions import Fraction
    from math import ceil

    x = Fraction(str(q))
    n = ceil(x * 10 ** digits)
    return f"{'-' if n < 0 else ''}{abs(n) // 10 ** digits}.{abs(n) % 10 ** digits:0{digits}d}"


def _end_strip_line(l, p, b, es, fmt) -> str:
    """The boundary line of a strip closed by :func:`analysis.bivariate.end_strip.close_end_strip`."""
    q = es.get("quotient_upper")
    quo = (f"; on the quotient the JSR is at most {_decimal_up(q)} (certified)" if q is not None else "")
    a, e = b["strip"]["from"], b["exact"]
    iv = f"[{fmt(a)}, {fmt(e)})" if a < e else f"({fmt(e)}, {fmt(a)}]"
    how = ("the eigenvalue of " + ", ".join(f"T_{e}" for e in es["letters"]) if es.get("lambda_kind") == "eigenvalue"
           else "the tangent of the eigenvalue of " + ", ".join(f"T_{e}" for e in es["letters"]))
    rel = "is" if es.get("lambda_kind") == "eigenvalue" else "is at most"
    return (f"C^{l} certified up to the end: on {p} in {iv} the JSR {rel} {fmt(es['lambda'])} on a common "
            f"invariant subspace of dimension {es['leading_dimension']} ({how}; invariant polytope of the convex "
            f"hull in 1/lambda, {es['polytope_vertices']} exact vertices, norm bound {fmt(es['polytope_bound'])}){quo}")


def cmd_surface(args) -> None:
    import sympy as sp

    if args.list:
        for option in _given(args, OPTIONS):
            raise AnalysisError(f"--list lists the whole catalogue: drop {option} (or drop --list)")
        return _list(args)
    if args.grid_cells is not None:                  # options before any computation
        _grid_cells(args)
    if args.differences is not None:
        return _differences(args)
    if args.C is not None and not 0 <= _int_arg(args.C, "--C") <= 30:
        raise AnalysisError(f"--C must be between 0 and 30, not {args.C}")
    if args.within is not None or (args.C is not None and _has_free_parameter(args)):
        return _range(args)
    for option in _given(args, RANGE_OPTIONS):
        raise AnalysisError(f"{option} goes with a C^l set of a free parameter (--C L --within=LOW,HIGH): "
                            f"drop {option}" + ("" if args.C is not None else " or add --C L --within=LOW,HIGH"))
    if args.sweep:
        return _sweep(args)
    if args.refine is not None:
        return _refine(args)
    if args.figure or args.grid:
        raise AnalysisError("--figure and --grid go with --refine N (e.g. --refine 4 --figure phi.png)")

    from ..bivariate.algebra import box_factors, reproduction, sum_rules, symmetry_group
    from ..bivariate.holder import holder_exponent, smoothness_verdicts
    from ..jsonable import fmt_bound

    from ..bivariate.transition import invariant_support

    budget = work_arg(args.budget, "--budget")
    general, a, label, vals = _mask_from_args(args)
    invariant_support(a)                             # its limit before the algebra: it depends on supp(a) and M only
    D = a.dilation
    sr_general = sum_rules(general)
    sr = sum_rules(a)
    rep = reproduction(a)
    sym = symmetry_group(a)
    box = box_factors(a)
    data = {"scheme": label, "dilation": [list(r) for r in D.matrix], "det": D.det, "isotropic": D.isotropic,
            "digits": [list(e) for e in D.digits],
            "dual_points": [[str(x) for x in w] for w in D.dual_points],
            "parameters": {k: sp.sstr(v) if isinstance(v, sp.Basic) else str(v) for k, v in vals.items()},
            "symbol": sp.sstr(sp.factor(a.symbol)),
            "sum_rules": sr.value, "generation_degree": sr.value - 1,
            "reproduction_degree": rep.value,
            "reproduction_shift": None if rep.witness["tau"] is None else [sp.sstr(t) for t in rep.witness["tau"]],
            "symmetry_order": sym.value, **({"symmetry_infinite": sym.witness["degenerate"]} if sym.value is None else {}),
            "box_factors": {f"{x},{y}": n for (x, y), n in box.value.items()}}
    if general.params:
        data["sum_rules_generic"] = sr_general.value
        data["sum_rules_exceptional"] = [{"value": sp.sstr(e["value"]), "order": e["order"]}
                                         for e in sr_general.witness.get("exceptional", [])]
    lines = [f"{label}: dilation M = {[list(r) for r in D.matrix]} (|det M| = {D.m}, "
             f"{'isotropic' if D.isotropic else 'anisotropic'}), symbol {data['symbol']}"]
    if vals:
        lines.append("parameters: " + ", ".join(f"{k} = {data['parameters'][k]}" for k in vals))
    lines.append(f"sum rules: order {sr.value} (polynomial generation degree {sr.value - 1}), certified (exact)")
    if general.params and data["sum_rules_exceptional"]:
        lines.append("  generic order " + str(sr_general.value) + "; higher at " +
                     ", ".join(f"{e['value']} (order {e['order']})" for e in data["sum_rules_exceptional"]))
    if rep.value >= 0:
        lines.append(f"reproduction: degree {rep.value}, shift tau = ({', '.join(data['reproduction_shift'])})")
    else:
        lines.append("reproduction: none")
    lines.append(f"symmetry group: order {sym.value}" if sym.value is not None else
                 f"symmetry group: infinite ({sym.witness['degenerate'].replace(': infinitely', ', and infinitely')})")
    lines.append("box-spline factors (1+z^xi): " +
                 (", ".join(f"xi=({x},{y})^{n}" for (x, y), n in box.value.items()) or "none"))
    if sr.value == 0:
        data["holder"] = None
        lines.append("not convergent: the cosets of the mask do not each sum to 1 (sum rules of order 1 fail)")
        _emit(args, data, "\n".join(lines))
        return
    h = holder_exponent(a, budget=budget)
    j = h.witness["jsr"]
    ck = smoothness_verdicts(h)
    data["holder"] = {"status": h.status, "value": None if h.value is None else sp.sstr(h.value),
                      "lower": None if h.lower is None else sp.sstr(h.lower),
                      "upper": None if h.upper is None else sp.sstr(h.upper),
                      "closed_form": None if "alpha_closed_form" not in h.witness else sp.sstr(h.witness["alpha_closed_form"]),
                      "k": h.witness["k"], "omega_size": len(h.witness["omega"]), "dimension": h.witness["dimension"],
                      "jsr": {"lower": sp.sstr(j.lower), "upper": None if j.upper is None else sp.sstr(j.upper),
                              "status": j.status, "method": j.provenance.get("method"),
                              "product": list(j.witness.get("product") or ())},
                      "work": j.provenance.get("work"), "timing": j.provenance.get("timing")}
    data["smoothness"] = {f"C{l}": v for l, v in ck.items()}
    lines.append(f"transition operators: {D.m} matrices on |Omega| = {len(h.witness['omega'])} points, "
                 f"restricted to V_{h.witness['k']} (dimension {h.witness['dimension']})")
    kk = h.witness["k"]
    if "jsr_value" in h.witness:
        jl = f"JSR(T|V_{kk}) = {sp.sstr(h.witness['jsr_value'])} ({j.status})"
    else:
        w = "".join(map(str, j.witness.get("product") or ()))
        exact = sp.Rational(j.lower).q < 10 ** 6
        lo_j = sp.sstr(j.lower) if exact else fmt_bound(j.lower, "lower", 15, "g")
        jl = (f"JSR(T|V_{kk}) >= {lo_j} (rho(T_{w})^(1/{len(w)})"
              + (", exact)" if exact else ", rounded down)"))
        if j.upper is not None and exact and sp.Rational(j.upper) == sp.Rational(j.lower):
            jl = f"JSR(T|V_{kk}) = {lo_j} (rho(T_{w})^(1/{len(w)}), exact; {j.status})"
        elif j.upper is not None:
            jl += f", <= lower + {float(sp.Rational(j.upper) - sp.Rational(j.lower)):.2g} ({j.status})"
    lines.append(jl)
    if not D.isotropic:
        lines.append("alpha: inconclusive — M is anisotropic, -log_rho(M) JSR is not the Hölder exponent "
                     "(Charina-Protasov 2019); only C^0 is decided")
    else:
        lines.append(_alpha_text(h))
    verdicts = []
    for l, v in ck.items():
        verdicts.append(f"C^{l}: " + ("yes" if v else "no" if v is False else "undecided"))
    lines.append("; ".join(verdicts))
    if args.C is not None:                           # --C L on a scheme without a free parameter: the verdict asked
        l = _int_arg(args.C, "--C")
        v = smoothness_verdicts(h, max_l=l)[l]
        word = {True: "yes", False: "no", None: "undecided"}[v]
        status = "inconclusive" if v is None else "certified"   # decided verdicts rest on rigorous bounds
        lines.append(f"C^{l}: {word}   [{status}]")
        data["C"] = {"l": l, "value": v, "status": status}
    _emit(args, data, "\n".join(lines))


def register(subparsers) -> None:
    """Add ``surface`` to the ``subdiv`` command."""
    s = subparsers.add_parser(
        "surface", help="bivariate scheme with a dilation matrix: sum rules, symmetry, box factors, certified alpha",
        description="Analyse a bivariate scheme (S_a f)(alpha) = sum_beta a(alpha - M beta) f(beta): sum rules, "
                    "polynomial generation/reproduction, symmetry group, box-spline factors, the certified Hölder "
                    "exponent alpha = -log_rho(M) JSR(T_eps|V_k) and C^l verdicts.")
    s.add_argument("--scheme", help="a surface catalogue name (loop, bicubic, butterfly, sqrt3, ...)")
    s.add_argument("--symbol", help="the symbol, a Laurent polynomial in z1, z2 (other names are parameters)")
    s.add_argument("--mask2", help="the mask as 'i,j:coef; i,j:coef; ...'")
    s.add_argument("--file", metavar="MASK.toml", help="the mask from a TOML or JSON file (docs/surfaces.md)")
    s.add_argument("--dilation", help="dyadic (2I, default), quincunx, sqrt3, triadic, or the rows a,b;c,d")
    s.add_argument("--param", action="append", metavar="NAME=VALUE", help="a parameter value (exact), repeatable")
    s.add_argument("--budget", default="20000", help="work budget of the JSR certification (units counted, not timed)")
    s.add_argument("--sweep", metavar="NAME=v1,v2,...",
                   help="the certified alpha and C^l at each value of one parameter (a table)")
    s.add_argument("--C", metavar="L", help="with --within: the certified set of parameter values where it is C^L")
    s.add_argument("--within", metavar="LOW,HIGH", help="with --C: the parameter interval (use --within=0,1/8)")
    s.add_argument("--param-name", metavar="NAME", help="with --C: the free parameter (default: the only one; a "
                                                       "catalogue default of it is dropped)")
    s.add_argument("--grid-cells", metavar="N", help="with --C: grid cells of certified point verdicts "
                                                     "(default 8)")
    s.add_argument("--range-budget", metavar="UNITS",
                   help="with --C: total work budget of the C^L set (units counted, not timed; default 2000000)")
    s.add_argument("--refine", type=int, metavar="N",
                   help="apply N steps to the delta sequence (samples of the basic limit function, floating point)")
    s.add_argument("--grid", choices=("quad", "triangular"),
                   help="how to draw the lattice for --refine (default: the catalogue entry's grid, else quad)")
    s.add_argument("--figure", help="with --refine: write a heat map (.png, .svg, .pdf)")
    s.add_argument("--differences", metavar="K",
                   help="the difference scheme of order K (M = m I): the matrix B with nabla^mu a = sum_nu b_mu,nu "
                        "nabla^nu(z^m), checked exactly; and the norm test of C^(K-1) (C^0 for K = 1, C^(K-1) for K >= 2)")
    s.add_argument("--list", action="store_true", help="list the surface catalogue (names, titles, sources)")
    s.add_argument("--json", action="store_true", help="print one JSON document")
    s.set_defaults(func=cmd_surface)
