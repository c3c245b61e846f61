"""The m-ary branch of ``subdiv symbol | factor | norm | refine | matrices | holder | range`` (issue 12).

The binary commands call these when the input has arity ``M != 2`` (``--arity M`` or an m-ary catalogue
entry); with arity 2 nothing here runs, so binary output is unchanged.

Examples
--------
::

    subdiv holder --scheme ternary-bspline-3
    subdiv holder --mask "1,2" --arity 3                   # not convergent, naming the root of unity
    subdiv range --scheme ternary-four-point --C 2 --L 1
    subdiv norm --scheme ternary-four-point --m 3 --solve mu
"""

from __future__ import annotations

from ..result import AnalysisError
from .common import _emit, _int_arg, _parse_Ls, _parse_within, norm_order, check_figure, check_writable, scheme_from_args, work_arg


def _fmt_set(S) -> str:
    """A sympy set of reals as ``(a, b] U [c, oo)``."""
    import sympy as sp

    if S == sp.EmptySet:
        return "empty"
    parts = S.args if isinstance(S, sp.Union) else (S,)
    out = []
    for I in parts:
        if isinstance(I, sp.Interval):
            out.append(("(" if I.left_open else "[") + f"{sp.sstr(I.start)}, {sp.sstr(I.end)}"
                       + (")" if I.right_open else "]"))
        else:
            out.append(sp.sstr(I))
    return " U ".join(out)


def _input(args, m: int):
    a, label = scheme_from_args(args, arity_ok=True)
    return a, label, f"scheme: {label}   (arity {m}, domain {a.domain})"


def cmd_symbol(args, m: int) -> None:
    import sympy as sp

    from ..algebra.mary import sum_rules_mary, symmetry_mary

    a, label, head = _input(args, m)
    sr, sym = sum_rules_mary(a, m), symmetry_mary(a, m)
    lines = [head, f"support:  [{a.start}, {a.end}]", f"mask:     {', '.join(sp.sstr(c) for c in a.mask)}",
             f"a(z) =    {a.pretty()}",
             f"residue sums A_r = sum_j a_(r+{m}j): {', '.join(sp.sstr(x) for x in sr.witness['residue_sums'])}",
             ("sum rules hold: a(1) = %d, a(eps) = 0 for eps^%d = 1, eps != 1" % (m, m)) if sr.value else
             "sum rules FAIL: " + "; ".join(sr.witness["failures"])
             + (f" (they hold for {sr.witness['solutions']})" if sr.witness.get("solutions") else ""),
             f"symmetric: {'yes' if sym.value else 'no'} (mask centre {sym.witness['centre']}, "
             f"limit function centre {sym.witness['limit_centre']})"]
    _emit(args, {"scheme": label, "arity": m, "start": a.start, "end": a.end, "mask": list(a.mask),
                 "sum_rules": sr.to_json(), "symmetry": sym.to_json()}, "\n".join(lines))


def cmd_factor(args, m: int) -> None:
    import sympy as sp

    from ..algebra.mary import polynomial_generation_mary, polynomial_reproduction_mary, smoothing_factor_mary

    a, label, head = _input(args, m)
    f = smoothing_factor_mary(a, m)
    lines = [head, f"a(z) = ((1+...+z^{m - 1})/{m})^{f.value} b(z),  b(z) = {f.witness['b'].pretty()}   [{f.status}]"]
    for e in f.witness["exceptional"]:
        lines.append(f"  at {sp.sstr(e['condition'])}: k = {e['k']}")
    data = {"scheme": label, "arity": m, "k": f.value, "b": f.witness["b"],
            "exceptional": [{"condition": e["condition"], "k": e["k"]} for e in f.witness["exceptional"]]}
    if a.is_numeric or a.params:
        g = polynomial_generation_mary(a, m)
        r = polynomial_reproduction_mary(a, m)
        lines.append(f"generates polynomials of degree {g.value}; reproduces degree {r.value} "
                     f"(tau = a'(1)/{m} = {sp.sstr(r.witness['tau'])}, {r.provenance['parametrisation']})")
        for h in r.witness["higher"]:
            lines.append(f"  reproduces degree {h['degree']} at {sp.sstr(h['condition'])}")
        data.update({"generation_degree": g.value, "reproduction_degree": r.value, "tau": r.witness["tau"],
                     "higher": r.witness["higher"]})
    _emit(args, data, "\n".join(lines))


def cmd_norm(args, m: int) -> None:
    import sympy as sp
    from ..jsonable import exact_and_float

    from ..stationary.mary import difference_norm_mary, scheme_norm_mary

    a, label, head = _input(args, m)
    Ls = _parse_Ls(args.L)
    k = norm_order(args)
    if any(m ** L > 10 ** 6 for L in Ls):
        raise AnalysisError(f"--L too large for arity {m} (at most {m}^L = 10^6 residues)")
    lines, rows = [head], []
    if args.solve is not None or not a.is_numeric:
        from ..stationary.normset import norm_solution_set

        if args.solve is None:
            raise AnalysisError("free parameter(s): give values with --param, or --solve NAME")
        within = _parse_within(args.within)
        lines.append(f"set of {args.solve} where ||(1/{m} S_a{k})^L||_inf < 1, a{k} = ({m} z^{m - 1}/(1+...+z^{m - 1}))^{k} a")
        for L in Ls:
            r = norm_solution_set(a, k, L, args.solve, spelling=args.spelling, within=within, arity=m)
            lines.append(f"  L = {L}: {r.value}   [{r.status}]")
            rows.append({"L": L, "m": k, "set": r.value, "status": r.status})
        lines.append(f"  on these sets the scheme is C^{k - 1} (m-ary Dyn-Levin); outside them this test proves nothing")
        _emit(args, {"scheme": label, "arity": m, "parameter": args.solve, "results": rows}, "\n".join(lines))
        return
    for L in Ls:
        if k == 0:
            r = scheme_norm_mary(a, L, m)
            lines.append(f"  L = {L}: ||S_a^L||_inf = {sp.sstr(r.value)}   [{r.status}]")
            rows.append({"L": L, "norm": exact_and_float(r.value), "status": r.status})
        else:
            r = difference_norm_mary(a, k, m, L, spelling=args.spelling)
            c = r.witness["contractive"]
            lines.append(f"  L = {L}: ||(1/{m} S_a{k})^{L}||_inf = {sp.sstr(r.value)} ~ {float(r.value):.12g}  "
                         f"{'< 1: C^' + str(k - 1) + ' (Dyn-Levin)' if c else '>= 1: proves nothing'}   [{r.status}]")
            rows.append({"L": L, "m": k, "norm": exact_and_float(r.value), "contractive": c, "status": r.status})
    _emit(args, {"scheme": label, "arity": m, "results": rows}, "\n".join(lines))


def cmd_refine(args, m: int) -> None:
    """``subdiv refine --arity M``: closed polygons, open ones with the end rules ``interior`` / ``extrapolate``,
    ``--points`` or ``--points-file``, ``--exact``, ``--output FILE`` (CSV) — as the binary command."""
    import sympy as sp
    from ..algebra.reader import as_expr

    import numpy as np

    from ..stationary.mary import refine_mary
    from .common import check_writable

    if args.output:
        check_writable(args.output, "--output")
    a, label, _ = _input(args, m)
    from .common import read_points

    data = read_points(args)
    steps = _int_arg(args.steps, "--steps")
    if steps < 0 or steps > 12:
        raise AnalysisError("--steps must be between 0 and 12 with --arity")
    from .common import check_refined_size

    check_refined_size(len(data), m, steps)
    if args.exact:
        if any(not as_expr(v).is_Rational for row in data for v in np.atleast_1d(row)):
            raise AnalysisError("--exact refinement needs rational data")
        pts = [[sp.Rational(v) for v in np.atleast_1d(row)] for row in data]
    else:
        pts = [[float(v) for v in np.atleast_1d(row)] for row in data]
    out = refine_mary(a, pts, m, steps, closed=not args.open, exact=args.exact,
                      end_rule=args.end_rule if args.open else "interior")
    if args.output:
        try:
            np.savetxt(args.output, np.asarray(out, dtype=float), delimiter=",")
        except OSError as exc:
            raise AnalysisError(f"cannot write {args.output}: {exc.strerror or exc}") from None
    rows = [[str(v) if args.exact else float(v) for v in np.atleast_1d(row)] for row in out]
    head = (f"scheme: {label} (arity {m}); {len(data)} -> {len(out)} points after {steps} step(s)"
            + (f" (open polygon, end rule {args.end_rule})" if args.open else " (closed polygon)"))
    text = "\n".join([head] + ([f"written to {args.output}"] if args.output else
                               [", ".join(str(v) for v in r) for r in rows]))
    _emit(args, {"scheme": label, "arity": m, "steps": steps, "closed": not args.open,
                 "end_rule": args.end_rule if args.open else None, "count": len(out), "points": rows}, text)


def cmd_matrices(args, m: int) -> None:
    import sympy as sp

    from ..regularity.mary import difference_mask_mary
    from ..stationary.mary import basic_limit_support_mary, local_eigenvalues_mary, transition_matrices_mary

    a, label, head = _input(args, m)
    ev = local_eigenvalues_mary(a, m)
    sup = basic_limit_support_mary(a, m)
    w = ev.witness["window"]
    lines = [head, f"local subdivision matrix on f[{w[0]}..{w[1]}]:",
             *("  " + sp.sstr(list(row)) for row in ev.witness["matrix"].tolist()),
             f"characteristic polynomial: {sp.sstr(ev.witness['charpoly'])}",
             "eigenvalues: " + ", ".join(sp.sstr(k) + (f" (x{v})" if v > 1 else "") for k, v in ev.value.items())
             + f"   [{ev.status}]",
             f"support of the basic limit function: [{sp.sstr(sup.value[0])}, {sp.sstr(sup.value[1])}] "
             f"(mask support / {m - 1})"]
    data = {"scheme": label, "arity": m, "local_window": w, "local_matrix": ev.witness["matrix"].tolist(),
            "eigenvalues": [{"value": k, "multiplicity": v} for k, v in ev.value.items()],
            "charpoly": ev.witness["charpoly"], "support": sup.to_json()}
    if args.transition:
        k, c = difference_mask_mary(a, m)
        T = transition_matrices_mary(c, m)
        lines.append(f"transition matrices of c = {m}^{k} a/q_{m}^{k + 1} = {c.pretty()} "
                     f"(alpha = {k} - log_{m} JSR):")
        lines += [f"  T{e} = {sp.sstr(M.tolist())}" for e, M in enumerate(T)]
        data["transition"] = {"k": k, "c": c, **{f"T{e}": M.tolist() for e, M in enumerate(T)}}
    _emit(args, data, "\n".join(lines))


def cmd_holder(args, m: int) -> None:
    import sympy as sp

    from ..jsonable import fmt_bound
    from ..regularity.mary import NotConvergentMary, holder_exponent_mary, smoothness_mary

    from .level_input import uses_level

    if uses_level(args):                        # a level-dependent m-ary scheme (analysis.levels.mary)
        from .levels_mary import cmd_holder as holder_levels

        return holder_levels(args, m)
    if getattr(args, "approx", False):
        raise AnalysisError("--approx is not available for m-ary schemes yet: give the mask exactly (fractions or radicals)")
    a, label, head = _input(args, m)
    from .common import require_values

    require_values(a, label, "holder")
    budget = work_arg(args.budget, "--budget")
    lines, data = [head], {"scheme": label, "arity": m}
    try:
        h = holder_exponent_mary(a, m, budget=budget)
    except NotConvergentMary as exc:
        r = exc.result()
        lines.append(f"{r.witness['reason']}   [{r.status}]")
        data["alpha"] = r.to_json()
        _emit(args, data, "\n".join(lines))
        return
    if h.value is not None:
        lines.append(f"Hoelder exponent alpha = {sp.sstr(h.value)}   [{h.status}]")
    else:
        lines.append(f"Hoelder exponent alpha in [{fmt_bound(h.lower, 'lower', 12)}, {fmt_bound(h.upper, 'upper', 12)}]"
                     f"   [{h.status}]")
    lines.append(f"  alpha = {h.witness['k']} - log_{m} JSR(T_0..T_{m - 1}), c = {h.witness['c'].pretty()}")
    data["alpha"] = {"value": h.value, "lower": h.lower, "upper": h.upper, "status": h.status, "k": h.witness["k"]}
    if args.C is not None:
        j = _int_arg(args.C, "--C")
        s = smoothness_mary(a, m, j, budget=budget)
        verdict = {True: f"C^{j}", False: f"not C^{j}", None: "undecided"}[s.value]
        lines.append(f"{verdict}: {s.witness['reason']}   [{s.status}]")
        data["smoothness"] = {"j": j, "value": s.value, "status": s.status, "reason": s.witness["reason"]}
    if getattr(args, "sobolev", False):
        _sobolev_part(a, m, lines, data)
    _emit(args, data, "\n".join(lines))


def _sobolev_part(a, m: int, lines: list, data: dict) -> None:
    """``holder --sobolev`` for an m-ary scheme: ``s_2 = -(1/2) log_m lambda`` (issue 12)."""
    import sympy as sp

    from ..jsonable import fmt_bound
    from ..regularity.sobolev_mary import sobolev_exponent_mary

    s2 = sobolev_exponent_mary(a, m)
    if s2.value is not None:
        head = f"L2-Sobolev exponent s_2 = {sp.sstr(s2.value)} exactly   [{s2.status}]"
    elif s2.lower is not None:
        head = (f"L2-Sobolev exponent s_2 in [{fmt_bound(s2.lower, 'lower', 12)}, {fmt_bound(s2.upper, 'upper', 12)}]"
                f"   [{s2.status}]")
    else:
        head = f"L2-Sobolev exponent s_2: [{s2.status}]"
    lines.append(head)
    w = s2.witness
    if "lambda_lower" in w:
        lines.append(f"  s_2 = -(1/2) log_{m} lambda, lambda = largest root of {sp.sstr(w['minimal_polynomial'])} "
                     f"(exact {m}-ary transfer-operator sequence, r = {w['r']})")
    if "weight" in w:
        lines.append(f"  weight h = (2-z-1/z)^r w: {w['weight']}")
    if "reason" in w:
        lines.append(f"  {w['reason']}")
    data["sobolev"] = {"value": s2.value, "lower": s2.lower, "upper": s2.upper, "status": s2.status,
                       "weight": w.get("weight"), "reason": w.get("reason")}


def cmd_range(args, m: int) -> None:
    from ..regularity.mary import ck_range_mary

    if args.figure:
        check_figure(args.figure, "the figure")
    a, label, head = _input(args, m)
    j = _int_arg(args.C, "--C")
    within = _parse_within(args.within)
    if args.figure and not all(w.is_finite for w in within):
        raise AnalysisError("--figure needs finite bounds in --within, e.g. --within=-1,1")
    strip_budget = work_arg(getattr(args, "strip_budget", 30_000), "--strip-budget", minimum=0)
    Ls = [1, 2]
    r = ck_range_mary(a, m, j, args.param_name, Ls=Ls, within=within, strip_budget=strip_budget)
    p = r.witness["parameter"]
    tests = r.witness.get("interior_tests") or []
    extra = " and parametric norm tests, L <= 8" if tests else ""
    polytopes = [x for t in tests for x in t.get("polytope", [])]
    if polytopes:
        def strip(x):
            lo_open, hi_open = x["kind"] in ("strip-left-end", "strip-both"), x["kind"] in ("strip-right-end", "strip-both")
            return f"{'(' if lo_open else '['}{x['from']}, {x['to']}{')' if hi_open else ']'}"
        extra += ", the strip" + ("s " if len(polytopes) > 1 else " ") + ", ".join(map(strip, polytopes)) \
            + " by a parametric invariant polytope (product " + ", ".join(f"T_{x['product']}" for x in polytopes) + ")"
    lines = [head, f"C^{j} (m-ary Dyn-Levin norm sets, L in {Ls}{extra}): {p} in {_fmt_set(r.value)}",
             f"not C^{j} (a transition matrix eigenvalue of modulus >= {m}^{r.witness['k'] - j}): "
             f"{_fmt_set(r.witness['not_Cj'])}",
             (f"the C^{j} range is exactly {_fmt_set(r.value)}, certified on both sides" if r.witness["exact"] else
              f"undecided: {_fmt_set(r.witness['undecided'])} (decide points with `subdiv holder --C {j}`)")
             + f"   [{r.status}]"]
    data = {"scheme": label, "arity": m, "j": j, "parameter": p, "Cj": _fmt_set(r.value),
            "not_Cj": _fmt_set(r.witness["not_Cj"]), "undecided": _fmt_set(r.witness["undecided"]),
            "status": r.status}
    if polytopes:
        data["strips_closed"] = polytopes
    if getattr(args, "table", None):
        from .tables import write_table

        rows = [[f"C^{j}", _fmt_set(r.value)], [f"not C^{j}", _fmt_set(r.witness["not_Cj"])],
                ["undecided", _fmt_set(r.witness["undecided"])]]
        write_table(args.table, ["", f"{p} in"], rows, f"subdiv range: {label} (arity {m}), where is it C^{j}? "
                                                     f"[{r.status}]")
        lines.append(f"table written to {args.table}")
        data["table"] = args.table
    for why in (w for t in tests for w in t.get("strips not closed by the invariant polytope", [])):
        lines.append(f"  strip not closed by the parametric invariant polytope: {why}")
        data.setdefault("strips_not_closed", []).append(why)
    if getattr(args, "maximize", None):          # issue 14: the smoothest member on --within
        from .common import parse_coefficient
        from .maximize import maximize_part

        maximize_part(a, {p: within}, m, parse_coefficient(args.gap), 60_000, lines, data)
    if args.figure:
        _figure(args, a, m, p, j, within, r, label, lines, data)
    _emit(args, data, "\n".join(lines))


def _figure(args, a, m: int, p: str, j: int, within, r, label: str, lines: list, data: dict) -> None:
    """``range --figure`` for an m-ary family: certified alpha enclosures at ``max(grid, 8) + 1`` points,
    the level alpha = j and the finite ends of the C^j set (issue 12)."""
    import sympy as sp

    from ..regularity.mary import alpha_curve_mary
    from ..report.plots import plot_alpha_curve

    grid = _int_arg(args.grid, "--grid")
    if grid < 2 or grid > 400:
        raise AnalysisError("--grid must be between 2 and 400")
    budget = work_arg(args.budget, "--budget")
    curve = alpha_curve_mary(a, m, p, within=within, samples=max(grid, 8), budget=budget)
    parts = r.value.args if isinstance(r.value, sp.Union) else (() if r.value == sp.EmptySet else (r.value,))
    ends = [{"exact_float": float(x)} for I in parts if isinstance(I, sp.Interval)
            for x in (I.start, I.end) if x.is_finite and x not in within]
    try:
        plot_alpha_curve(curve, args.figure, j=j, boundaries=ends, label=f"{label} (arity {m})")
    except OSError as exc:
        raise AnalysisError(f"cannot write the figure {args.figure!r}: {exc.strerror or exc}") from None
    lines.append(f"figure written to {args.figure} (alpha at {len(curve.value)} points, {curve.status})")
    data["figure"] = args.figure
