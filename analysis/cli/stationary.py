"""``subdiv symbol | factor | norm | refine | matrices | list``: the stationary commands
(Laurent symbol and sum rules, the factorization and its exceptional parameter values, exact
norm tests and their parameter sets, refinement of polygons, local and transition matrices, the
catalogue).

Examples
--------
::

    subdiv symbol --mask "1/4,3/4,3/4,1/4" --start -2
    subdiv factor --scheme dfh-chaikin-perturbation
    subdiv norm --scheme dfh-chaikin-perturbation --m 3 --L 1,2,3,4 --solve omega --within 0,oo
    subdiv norm --scheme dfh-chaikin-perturbation --param omega=1/100 --m 3 --L 2
    subdiv refine --scheme four-point --param w=1/16 --points "0,0;1,0;1,1;0,1" --steps 3
"""

from __future__ import annotations

import json

from ..result import AnalysisError


from .common import (check_refined_size, norm_order, read_number, read_points, scheme_arity, _emit, _int_arg, _parse_Ls,
                     _parse_within, _print, check_writable, json_document, scheme_from_args)


def _input_with_arity(args, m: int):
    a, label = scheme_from_args(args, arity_ok=True)
    return a, label, f"scheme: {label}   (arity {m}, domain {a.domain})"


def cmd_symbol(args) -> None:
    import sympy as sp

    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        from ..algebra.factorization import sum_rules, symmetry

        a, label, head = _input_with_arity(args, m)
        sr, sym = sum_rules(a, arity=m), symmetry(a, arity=m)
        lines = [head, f"support:  [{a.start}, {a.end}]", f"mask:     {', '.join(sp.sstr(c) for c in a.mask)}",
                 f"a(z) =    {a.pretty()}",
                 f"residue sums A_r = sum_j a_(r+{m}j): {', '.join(sp.sstr(x) for x in sr.witness['residue_sums'])}",
                 ("sum rules hold: a(1) = %d, a(eps) = 0 for eps^%d = 1, eps != 1" % (m, m)) if sr.value else
                 "sum rules FAIL: " + "; ".join(sr.witness["failures"])
                 + (f" (they hold for {sr.witness['solutions']})" if sr.witness.get("solutions") else ""),
                 (f"symmetric: yes (mask centre {sym.witness['centre']}, limit function centre "
                  f"{sym.witness['limit_centre']})" if sym.value else
                  f"symmetric: no (about the centre {sym.witness['centre']} of the support)")]
        _emit(args, {"scheme": label, "arity": m, "start": a.start, "end": a.end, "mask": list(a.mask),
                     "sum_rules": sr.to_json(), "symmetry": sym.to_json()}, "\n".join(lines))
        return
    from ..algebra.factorization import sum_rules, symmetry

    a, label = scheme_from_args(args)
    even, odd = a.subsymbols()
    sr, sym = sum_rules(a), symmetry(a)
    data = {"scheme": label, "start": a.start, "end": a.end, "mask": list(a.mask), "domain": str(a.domain),
            "params": [p.name for p in a.params], "symbol": a.pretty(), "latex": a.latex(),
            "rules": {"even": list(a.rules().even), "even_first": a.rules().even_first,
                      "odd": list(a.rules().odd), "odd_first": a.rules().odd_first},
            "even_subsymbol": even, "odd_subsymbol": odd,
            "sum_rules": sr.to_json(), "symmetry": sym.to_json()}
    lines = [f"scheme:   {label}",
             f"domain:   {a.domain}" + (f"   parameters: {', '.join(p.name for p in a.params)}" if a.params else ""),
             f"support:  [{a.start}, {a.end}]",
             f"mask:     {', '.join(sp.sstr(c) for c in a.mask)}",
             f"a(z) =    {a.pretty()}",
             "rules:",
             *("  " + line for line in str(a.rules()).splitlines()),
             f"a_0(z) =  {even.pretty()}",
             f"a_1(z) =  {odd.pretty()}",
             f"a(1) = {sp.sstr(sr.witness['a(1)'])}, a(-1) = {sp.sstr(sr.witness['a(-1)'])}"
             + ("   (sum rules hold)" if sr.value else "   (sum rules FAIL" +
                (f"; they hold for {sr.witness.get('solutions')})" if sr.witness.get("solutions") else ")")),
             (f"symmetric: yes (centre {sym.witness['centre']}, {sym.witness['kind']})" if sym.value else
              f"symmetric: no (about the centre {sym.witness['centre']} of the support)"),
             f"LaTeX:    {a.latex()}"]
    _emit(args, data, "\n".join(lines))


def _describe_exceptional(cases, indent="  ") -> list[str]:
    import sympy as sp

    out = []
    for c in cases:
        cond = ", ".join(f"{k} = {sp.sstr(v)}" for k, v in c["condition"].items())
        if c.get("k") is None:
            out.append(f"{indent}{cond}: {c.get('note', '')}")
            continue
        out.append(f"{indent}{cond}: k = {c['k']}, b(z) = {c['b'].pretty()}")
        out.extend(_describe_exceptional(c.get("exceptional", []), indent + "  "))
    return out


def cmd_factor(args) -> None:
    import sympy as sp

    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        from ..algebra.factorization import polynomial_generation, polynomial_reproduction, smoothing_factor

        a, label, head = _input_with_arity(args, m)
        f = smoothing_factor(a, arity=m)
        lines = [head, f"a(z) = ((1+...+z^{m - 1})/{m})^{f.value} b(z),  b(z) = {f.witness['b'].pretty()}   [{f.status}]"]
        for e in f.witness["exceptional"]:
            lines.append(f"  at {sp.sstr(e['condition'])}: k = {e['k']}")
        data = {"scheme": label, "arity": m, "k": f.value, "b": f.witness["b"],
                "exceptional": [{"condition": e["condition"], "k": e["k"]} for e in f.witness["exceptional"]]}
        if a.is_numeric or a.params:
            g = polynomial_generation(a, arity=m)
            r = polynomial_reproduction(a, arity=m)
            lines.append(f"generates polynomials of degree {g.value}; reproduces degree {r.value} "
                         f"(tau = a'(1)/{m} = {sp.sstr(r.witness['tau'])}, {r.provenance['parametrisation']})")
            for h in r.witness["higher"]:
                lines.append(f"  reproduces degree {h['degree']} at {sp.sstr(h['condition'])}")
            data.update({"generation_degree": g.value, "reproduction_degree": r.value, "tau": r.witness["tau"],
                         "higher": r.witness["higher"]})
        _emit(args, data, "\n".join(lines))
        return
    from ..algebra.factorization import polynomial_reproduction, smoothing_factor, sum_rules

    a, label = scheme_from_args(args)
    f = smoothing_factor(a)
    sr = sum_rules(a)
    rep = polynomial_reproduction(a)
    k, b = f.value, f.witness["b"]
    data = {"scheme": label, "k": k, "b": b, "identity": f.witness["identity"],
            "exceptional": f.witness["exceptional"], "sum_rules": sr.value,
            "generation_degree": rep.witness["generation_degree"] if sr.value else None,
            "reproduction_degree": rep.value, "tau": rep.witness["tau"],
            "reproduction_higher": rep.witness["higher"], "status": f.status}
    lines = [f"scheme: {label}   (domain {a.domain})",
             f"a(z) = ((1+z)/2)^{k} b(z)   [{f.status}: exact division]",
             f"b(z) = {b.pretty()}"]
    if f.witness["exceptional"]:
        lines.append("exceptional parameter values (more factors (1+z)):")
        lines.extend(_describe_exceptional(f.witness["exceptional"]))
    elif a.params:
        lines.append("no exceptional parameter values: k is the same for every real value")
    lines.append(f"sum rules a(1) = 2, a(-1) = 0: {'hold' if sr.value else 'FAIL'}")
    if sr.value:
        lines.append(f"polynomial generation: degree {rep.witness['generation_degree']}")
        lines.append(f"polynomial reproduction: degree {rep.value} (tau = a'(1)/2 = {sp.sstr(rep.witness['tau'])})")
        for h in rep.witness["higher"]:
            cond = ", ".join(f"{k_} = {sp.sstr(v)}" for k_, v in h["condition"].items())
            lines.append(f"  degree {h['degree']} at {cond}")
    _emit(args, data, "\n".join(lines))


def cmd_norm(args) -> None:
    import sympy as sp
    from ..jsonable import exact_and_float

    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        from ..stationary.difference import difference_norm, scheme_norm

        a, label, head = _input_with_arity(args, m)
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
                r = scheme_norm(a, L, arity=m)
                lines.append(f"  L = {L}: ||S_a^L||_inf = {sp.sstr(r.value)}   [{r.status}]")
                rows.append({"L": L, "norm": exact_and_float(r.value), "status": r.status})
            else:
                r = difference_norm(a, k, L, spelling=args.spelling, arity=m)
                c = r.witness["contractive"]
                lines.append(f"  L = {L}: ||(1/{m} S_a{k})^{L}||_inf = {sp.sstr(r.value)} ~ {float(r.value):.12g}  "
                             f"{'< 1: C^' + str(k - 1) + ' (Dyn-Levin)' if c else '>= 1: proves nothing'}   [{r.status}]")
                rows.append({"L": L, "m": k, "norm": exact_and_float(r.value), "contractive": c, "status": r.status})
        _emit(args, {"scheme": label, "arity": m, "results": rows}, "\n".join(lines))
        return
    from ..stationary.difference import difference_norm, scheme_norm

    a, label = scheme_from_args(args)
    Ls = _parse_Ls(args.L)
    m = norm_order(args)
    rows, lines = [], [f"scheme: {label}   (domain {a.domain})"]
    if args.solve is not None or (not a.is_numeric and m >= 0):
        from ..stationary.normset import norm_solution_set

        if args.solve is None:
            names = ", ".join(p.name for p in a.params)
            raise AnalysisError(f"free parameter(s) {names}: give values with --param, or --solve NAME for the set where the norm < 1")
        within = _parse_within(args.within)
        lines.append(f"set of {args.solve} in ({sp.sstr(within[0])}, {sp.sstr(within[1])}) where "
                     f"||(1/2 S_a{m})^L||_inf < 1, a{m} = (2z/(1+z))^{m} a   [exact]")
        for L in Ls:
            r = norm_solution_set(a, m, L, args.solve, spelling=args.spelling, within=within)
            s = r.value
            floats = ", ".join(f"{float(e):.12g}" for e in s.endpoints())
            lines.append(f"  L = {L}: {s}" + (f"   ~ [{floats}]" if floats else "") + f"   [{r.status}]")
            row = {"L": L, "m": m, "set": s, "status": r.status, "implies": r.witness["implies"]}
            if args.piecewise:
                row["pieces"] = r.witness["pieces"]
                for pc in r.witness["pieces"]:
                    lo = "-oo" if pc.lo is None else sp.sstr(pc.lo.expr)
                    hi = "oo" if pc.hi is None else sp.sstr(pc.hi.expr)
                    lines.append(f"      on ({lo}, {hi}): {sp.sstr(pc.formula())}")
            rows.append(row)
        if any(not row["set"].is_empty for row in rows):
            lines.append(f"  on these sets the scheme is C^{m - 1} (Dyn-Levin); outside them this test proves nothing")
        _emit(args, {"scheme": label, "parameter": args.solve, "within": list(within), "results": rows}, "\n".join(lines))
        return
    if m == 0:
        lines.append("||S_a||_inf^(L) (m = 0: the scheme itself, no 1/2)")
        for L in Ls:
            r = scheme_norm(a, L)
            lines.append(f"  L = {L}: ||S_a^L||_inf = {sp.sstr(r.value)}   [{r.status}]")
            rows.append({"L": L, "norm": exact_and_float(r.value), "status": r.status})
    else:
        lines.append(f"||(1/2 S_a{m})^L||_inf, a{m}(z) = (2z/(1+z))^{m} a(z)   [{args.spelling} spelling]")
        for L in Ls:
            r = difference_norm(a, m, L, spelling=args.spelling)
            c = r.witness["contractive"]
            lines.append(f"  L = {L}: {sp.sstr(r.value)} ~ {float(sp.N(r.value, 20)):.12g}"
                         f"  {'< 1: C^' + str(m - 1) + ' (Dyn-Levin)' if c else '>= 1: proves nothing'}   [{r.status}]")
            rows.append({"L": L, "m": m, "norm": exact_and_float(r.value), "contractive": c,
                         "implies": r.witness["implies"], "status": r.status})
    _emit(args, {"scheme": label, "results": rows}, "\n".join(lines))


def cmd_refine(args) -> None:
    import sympy as sp
    from ..algebra.reader import as_expr

    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        import numpy as np

        from ..stationary.refinement import refine

        if args.output:
            check_writable(args.output, "--output")
        a, label, _ = _input_with_arity(args, m)

        data = read_points(args)
        steps = _int_arg(args.steps, "--steps")
        if steps < 0 or steps > 12:
            raise AnalysisError("--steps must be between 0 and 12 with --arity")

        check_refined_size(len(data), m, steps)
        if args.exact:
            if any(not as_expr(v).is_Rational for row in data for v in np.atleast_1d(row)):
                raise AnalysisError("--exact refinement needs rational data")
            pts = [[sp.Rational(v) for v in np.atleast_1d(row)] for row in data]
        else:
            pts = [[float(v) for v in np.atleast_1d(row)] for row in data]
        out = refine(a, pts, steps, closed=not args.open, exact=args.exact,
                          end_rule=args.end_rule if args.open else "interior", arity=m)
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
        return
    import numpy as np

    from ..stationary import refinement

    if args.output:
        check_writable(args.output, "--output")
    a, label = scheme_from_args(args)
    a.require_numeric("refinement")
    data = read_points(args)
    steps = _int_arg(args.steps, "--steps")
    if steps < 0 or steps > 30:
        raise AnalysisError("--steps must be between 0 and 30")
    check_refined_size(len(data), 2, steps)
    if args.exact:
        from fractions import Fraction

        pts = np.array([[Fraction(int(sp.Rational(v).p), int(sp.Rational(v).q)) if as_expr(v).is_Rational
                         else _not_rational(v) for v in row] for row in data], dtype=object)
    else:
        pts = np.array([[float(v) for v in row] for row in data], dtype=float)
    out = refinement.refine(a, pts, steps=steps, closed=not args.open, end_rule=args.end_rule, exact=args.exact)
    if args.output:
        try:
            np.savetxt(args.output, np.asarray(out, dtype=float), delimiter=",")
        except OSError as exc:
            raise AnalysisError(f"cannot write {args.output}: {exc.strerror or exc}") from None
    data_out = {"scheme": label, "steps": steps, "closed": not args.open, "end_rule": args.end_rule if args.open else None,
                "count": len(out), "points": [[str(v) if args.exact else float(v) for v in np.atleast_1d(row)] for row in out]}
    if args.json:
        _print(json_document(data_out))
        return
    _print(f"scheme: {label}; {len(data)} -> {len(out)} points after {steps} step(s)"
           + (f" (open polygon, end rule {args.end_rule})" if args.open else " (closed polygon)"))
    if args.output:
        _print(f"written to {args.output}")
    else:
        for row in out:
            _print(", ".join(str(v) for v in np.atleast_1d(row)))


def _not_rational(v):
    raise AnalysisError(f"--exact refinement needs rational data, got {v}")


def cmd_matrices(args) -> None:
    import sympy as sp

    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        from ..regularity.convergence import difference_mask
        from ..stationary.transition import basic_limit_support, local_eigenvalues, transition_matrices

        a, label, head = _input_with_arity(args, m)
        ev = local_eigenvalues(a, arity=m)
        sup = basic_limit_support(a, arity=m)
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
            k, c = difference_mask(a, arity=m)
            T = transition_matrices(c, arity=m)
            lines.append(f"transition matrices of c = {m}^{k} a/q_{m}^{k + 1} = {c.pretty()} "
                         f"(alpha = {k} - log_{m} JSR):")
            lines += [f"  T{e} = {sp.sstr(M.tolist())}" for e, M in enumerate(T)]
            data["transition"] = {"k": k, "c": c, **{f"T{e}": M.tolist() for e, M in enumerate(T)}}
        _emit(args, data, "\n".join(lines))
        return
    from ..algebra.factorization import smoothing_factor
    from ..stationary.transition import basic_limit_support, local_eigenvalues, transition_matrices

    a, label = scheme_from_args(args)
    ev = local_eigenvalues(a)
    sup = basic_limit_support(a)
    data = {"scheme": label, "local_window": ev.witness["window"], "local_matrix": ev.witness["matrix"].tolist(),
            "eigenvalues": [{"value": k, "multiplicity": v} for k, v in ev.value.items()],
            "charpoly": ev.witness["charpoly"], "support": sup.to_json()}
    lines = [f"scheme: {label}   (domain {a.domain})",
             f"local subdivision matrix on f[{ev.witness['window'][0]}..{ev.witness['window'][1]}]:",
             *("  " + sp.sstr(list(row)) for row in ev.witness["matrix"].tolist()),
             f"characteristic polynomial: {sp.sstr(ev.witness['charpoly'])}",
             "eigenvalues: " + ", ".join(sp.sstr(k) + (f" (x{v})" if v > 1 else "") for k, v in ev.value.items())
             + f"   [{ev.status}]",
             f"support of the basic limit function: [{sup.value[0]}, {sup.value[1]}], width {sup.witness['width']}"
             f" (centred on the symmetry point: {sp.sstr(sup.witness['centred'])})"]
    for val, sp_ in (sup.witness.get("exceptional") or {}).items():
        lines.append(f"  support shrinks to {sp_} at {sp.sstr(val)}")
    if args.transition:
        k = smoothing_factor(a, exceptional=False).value
        if k < 1:
            raise AnalysisError("transition matrices of the difference mask need a factor (1+z)")
        from ..algebra.factorization import factor_out

        c = factor_out(a, k) / 2
        T0, T1 = transition_matrices(c)
        data["transition"] = {"k": k - 1, "c": c, "T0": T0.tolist(), "T1": T1.tolist()}
        lines.append(f"transition matrices of c = 2^{k - 1} a/(1+z)^{k} = {c.pretty()} "
                     f"(JSR gives the Hölder exponent {k - 1} - log2 JSR):")
        lines.append("  T0 = " + sp.sstr(T0.tolist()))
        lines.append("  T1 = " + sp.sstr(T1.tolist()))
    _emit(args, data, "\n".join(lines))


def cmd_list(args) -> None:
    import schemes

    rows = []
    for e in schemes.listing(numeric=args.numeric, mary=getattr(args, "mary", False)):   # nothing is built
        rows.append({"slug": e.slug, "title": e.title, "params": list(e.params), "source": e.source})
        if e.arity != 2:                                  # m-ary entries only (binary rows unchanged)
            rows[-1]["arity"] = e.arity
    text = "\n".join(f"{r['slug']:28s} {('(' + ', '.join(r['params']) + ') ') if r['params'] else ''}{r['title']}"
                     for r in rows)
    _emit(args, {"schemes": rows}, text)


# --------------------------------------------------------------------------------------------
# entry point
# --------------------------------------------------------------------------------------------

#: Modules that add sub-commands: each defines ``register(subparsers)`` and uses the helpers above
#: (``scheme_from_args``, ``_add_scheme_args``, ``_emit``). Listed here once they are complete.


def register(sub) -> None:
    """Add the stationary commands to the sub-command parsers of :func:`analysis.cli.main.build_parser`."""
    from .common import _add_scheme_args

    s = sub.add_parser("symbol", help="mask, symbol, rules, sub-symbols, sum rules, symmetry")
    _add_scheme_args(s)
    s.set_defaults(func=cmd_symbol)

    s = sub.add_parser("factor", help="a = ((1+z)/2)^k b, exceptional parameter values, generation/reproduction")
    _add_scheme_args(s)
    s.set_defaults(func=cmd_factor)

    s = sub.add_parser("norm", help="exact ||(1/2 S_{a_m})^L||_inf, or the exact parameter set where it is < 1")
    _add_scheme_args(s)
    s.add_argument("--m", default=None, help="difference order m (a_m = (2z/(1+z))^m a; the test proves C^(m-1)); "
                                         "default 0 = the scheme itself, with --solve 1 (convergence)")
    s.add_argument("--L", default="1", help="number of steps, or a list like 1,2,3,4")
    s.add_argument("--spelling", choices=("paper", "divided"), default="paper",
                   help="(2z/(1+z))^m a (paper) or (2/(1+z))^m a (divided); the norms agree")
    s.add_argument("--solve", metavar="PARAM", help="solve ||.|| < 1 for this (single free) parameter, exactly")
    s.add_argument("--within", metavar="LOW,HIGH", help="restrict --solve to an open interval, e.g. 0,oo")
    s.add_argument("--piecewise", action="store_true", help="with --solve: print the norm as a piecewise function")
    s.set_defaults(func=cmd_norm)

    s = sub.add_parser("refine", help="apply the scheme to a polygon")
    _add_scheme_args(s)
    s.add_argument("--points", metavar="X,Y;X,Y;...", help="control points, one per ';'")
    s.add_argument("--points-file", metavar="FILE", help="control points, one per line (whitespace or .csv)")
    s.add_argument("--steps", default="1", help="refinement steps (default 1)")
    s.add_argument("--open", action="store_true", help="open polygon (default: closed)")
    s.add_argument("--end-rule", default="interior", choices=("interior", "extrapolate"),
                   help="open polygons: keep interior points only, or reflect ghost points 2P0 - Pm")
    s.add_argument("--exact", action="store_true", help="exact rational arithmetic")
    s.add_argument("--output", metavar="FILE", help="write the points as CSV")
    s.set_defaults(func=cmd_refine)

    s = sub.add_parser("matrices", help="local subdivision matrix, its exact eigenvalues, support; transition matrices")
    _add_scheme_args(s)
    s.add_argument("--transition", action="store_true",
                   help="also the transition matrices of c = 2^k a/(1+z)^(k+1) (k+1 = all factors (1+z))")
    s.set_defaults(func=cmd_matrices)

    s = sub.add_parser("list", help="the catalogue of named schemes")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.add_argument("--numeric", action="store_true", help="also schemes known only by certified enclosures (Daubechies)")
    s.add_argument("--mary", action="store_true", help="also the m-ary schemes (ternary, quaternary)")
    s.set_defaults(func=cmd_list)
