"""``subdiv holder`` and ``subdiv range``: certified Hölder exponents and C^k parameter ranges.

Examples
--------
::

    subdiv holder --scheme four-point --param w=1/16
    subdiv holder --scheme dfh-chaikin-perturbation --param omega=1/50 --C 2
    subdiv range --scheme dfh-chaikin-perturbation --C 2 --within=-1/20,1/20 --figure alpha.png
"""

from __future__ import annotations

from fractions import Fraction

from .common import (WORK_HELP, _add_scheme_args, _emit, _int_arg, _parse_params, _parse_within, check_figure,
                     require_values, scheme_arity, scheme_from_args, work_arg)
from ..result import AnalysisError


def _fmt(x, side: str | None = None, digits: int = 10) -> str:
    """``x`` with ``digits`` decimals, never ``-0.0...``. An end of an enclosure is rounded outward
    exactly: ``_fmt(lower, "lower")`` down, ``_fmt(upper, "upper")`` up (so the printed interval
    contains the true one); without ``side`` (an approximation) to nearest."""
    from ..jsonable import _as_fraction, fmt_bound

    if x is None:
        return "?"
    if side is not None:
        return fmt_bound(x, side, digits)
    lo, hi = fmt_bound(x, "lower", digits), fmt_bound(x, "upper", digits)
    if lo == hi:                              # exactly representable
        return lo
    from fractions import Fraction

    q = Fraction(lo) + Fraction(hi)           # nearest of the two (ties: the upper one)
    return hi if 2 * _as_fraction(x, "lower") >= q else lo


def _sstr(x) -> str:
    """sympy's ``sstr`` of an exact value; text, ints and Fractions (the ball route's numbers) read the
    same without importing sympy."""
    if isinstance(x, (str, int, Fraction)):
        return str(x)
    import sympy as sp

    return sp.sstr(x)


def _numeric_entry(args):
    """The catalogue entry when --scheme names a scheme known only by enclosures (Daubechies)."""
    if getattr(args, "scheme", None) is None:
        return None
    import schemes
    from schemes.catalogue import NumericSchemeEntry

    entry = schemes.get(args.scheme)
    return entry if isinstance(entry, NumericSchemeEntry) else None


def _row(args, quantity: str, r, value=None, witness: str = "", digits: int = 10) -> None:
    """One row of the ``holder --table`` table: the quantity, its value (``r``'s exact value or certified
    enclosure, outward-rounded to the ``digits`` printed; or ``value``), ``r``'s status and how it was obtained."""
    if value is None:
        if r.value is not None and not isinstance(r.value, bool):
            value = r.value
        elif r.lower is not None and r.upper is None:
            value = f">= {_fmt(r.lower, 'lower', digits)}"
        elif r.lower is not None:
            value = f"[{_fmt(r.lower, 'lower', digits)}, {_fmt(r.upper, 'upper', digits)}]"
        else:
            value = "?"
    args.__dict__.setdefault("_table_rows", []).append([quantity, value, r.status, witness])


def _write_holder_table(args, label: str, lines: list, data: dict) -> None:
    """``holder --table FILE``: the rows of :func:`_row` (alpha, stability, C^k, Sobolev) as CSV or LaTeX."""
    if not args.table:
        return
    from .tables import write_table

    write_table(args.table, ["", "value", "status", "witness"], args.__dict__.get("_table_rows", []),
                f"subdiv holder: {label}")
    lines.append(f"table written to {args.table}")
    data["table"] = args.table


def _no_table(args, what: str) -> None:
    if getattr(args, "table", None):
        raise AnalysisError(f"--table is not available for {what} yet: use --json")


def _part(name: str, compute, lines: list, data: dict, args=None) -> None:
    """Run one part of ``subdiv holder`` (alpha, C^k, Sobolev): each reports its own result, or its
    own inconclusive with the reason, so that one failing part never hides the others."""
    try:
        part_lines, part_data = compute()
    except AnalysisError as exc:
        lines.append(f"{name}: inconclusive — {exc}")
        data[name] = {"status": "inconclusive", "reason": str(exc)}
        if args is not None:
            args.__dict__.setdefault("_table_rows", []).append([name, "?", "inconclusive", str(exc)])
        return
    lines.extend(part_lines)
    data[name] = part_data


def _alpha_part(args, a, budget):
    from ..regularity import NotConvergent

    try:
        h = _holder(a, budget, args)
    except NotConvergent as exc:           # a certified verdict, not an error
        hint = exc.hint
        if hint is None and getattr(args, "mask", None) is not None:
            from ..algebra.approx import sum_rule_hint
            from .common import _split_list

            hint = sum_rule_hint(_split_list(args.mask, "mask"))
        lines = [f"not convergent [certified]: {exc.reason}"]
        if hint:
            lines.append(f"  {hint}")
        r = exc.result()
        _row(args, "convergent", r, "no", exc.reason)
        data = {**r.to_json(), "convergent": False, "reason": exc.reason}
        if hint:
            data["hint"] = hint
        return lines, data
    lines = []
    if h.value is not None:
        lines.append(f"Hölder exponent alpha = {_sstr(h.value)} exactly   [{h.status}]")
    elif h.upper is None and h.lower is not None:
        lines.append(f"Hölder exponent alpha >= {_fmt(h.lower, 'lower')}   [{h.status}: a lower bound, not the value]")
    else:
        lines.append(f"Hölder exponent alpha in [{_fmt(h.lower, 'lower')}, {_fmt(h.upper, 'upper')}]   [{h.status}]")
    w = h.witness
    prod = w.get("product")
    _row(args, "alpha", h, witness=(f"k = {w['k']}, spectrum-maximizing product T_{''.join(map(str, prod))}"
                                    + (f"; alpha = {_sstr(w['alpha_exact'])}" if w.get("alpha_exact") is not None
                                       and h.value is None else "")
                                    if prod and w.get("k") is not None else h.provenance.get("method", "")))
    if prod and w.get("k") is not None:
        lines.append(f"  c(z) = 2^{w['k']} a(z)/(1+z)^{w['k'] + 1};  spectrum-maximizing product T_{''.join(map(str, prod))}"
                     + (f";  alpha = {_sstr(w['alpha_exact'])}" if w.get("alpha_exact") is not None else ""))
    if "message" in h.provenance:
        lines.append(f"  {h.provenance['message']}")
    if (every := w.get("every_convergent_mask")) is not None:
        lines.append(f"  every convergent mask in the balls (a(1) = 2, (1+z) | a): alpha >= "
                     f"{_fmt(every['lower'], 'lower')}   [{every['status']}: a lower bound]")
    data = h.to_json()
    data["convergent"] = True
    return lines, data


def _holder(a, budget, args=None):
    """The alpha Result of ``a`` (cached on ``args`` so that --C reuses it)."""
    from ..regularity import holder_exponent

    cache = getattr(args, "_holder_cache", None) if args is not None else None
    if cache is not None and cache[0] is a:
        return cache[1]
    h = holder_exponent(a, budget=budget)
    if args is not None:
        args._holder_cache = (a, h)
    return h


def _smoothness_part(args, a, budget):
    from ..algebra.symbol import LaurentSymbol

    from ..regularity import NotConvergent, smoothness
    from ..regularity.holder import verdict_from_enclosure

    j = _int_arg(args.C, "--C")
    if j < 0:
        raise AnalysisError("--C must be >= 0")
    if not isinstance(a, LaurentSymbol):
        try:
            h = _holder(a, budget, args)
        except NotConvergent as exc:
            s = exc.result()
        else:
            s = verdict_from_enclosure(h, j)
    else:
        s = smoothness(a, j, budget=budget)
    verdict = {True: f"C^{j}: yes", False: f"C^{j}: no", None: f"C^{j}: undecided"}[s.value]
    _row(args, f"C^{j}", s, {True: "yes", False: "no", None: "undecided"}[s.value], s.witness.get("reason") or "")
    return ([f"{verdict}   [{s.status}] — {s.witness.get('reason')}"],
            {"j": j, "value": s.value, "status": s.status, "reason": s.witness.get("reason"),
             **({"convergent": False} if s.witness.get("convergent") is False else {})})


def _alternative_reading(args):
    """``(a, label, first line)`` for a --mask read approximately (--approx) or in closed form
    with nested radicals / I / CRootOf (the certified ball route); None otherwise."""
    if getattr(args, "mask", None) is None or args.param:
        return None
    from .common import _split_list

    if "(" in args.mask and "CRootOf" in args.mask:      # commas inside CRootOf(p, k)
        from ..algebra.closed_form import split_mask

        mask = split_mask(args.mask)
    else:
        mask = _split_list(args.mask, "mask")
    start = _int_arg(args.start, "--start")
    if getattr(args, "approx", False):
        from ..algebra.approx import ApproximateMask

        radius = None
        if getattr(args, "approx_radius", None) is not None:
            from .common import read_number

            radius = read_number(args.approx_radius, "--approx-radius")
            if not (radius.is_Rational and radius > 0):
                raise AnalysisError(f"--approx-radius must be a positive rational number, e.g. 1e-12, not {args.approx_radius}")
            radius = Fraction(int(radius.p), int(radius.q))
        m = ApproximateMask(mask, start, radius=radius)
        return (m, "mask (approximate reading)", "scheme: mask   (" + m.description().split(";")[0] + ")")
    from ..algebra.closed_form import ClosedFormMask, ball_route_exprs

    exprs = ball_route_exprs(mask)              # read once (reading the D8 radicals takes a while)
    if exprs is not None:
        cf = ClosedFormMask(exprs, start)
        return cf, "mask (closed form)", "scheme: mask   (closed form; certified ball route)"
    return None


def _sobolev_part(args, a, budget):
    """s_2 of the basic limit function (exact symbols: exact transfer-operator sequence, correct
    with or without stable shifts; ball catalogue entries: stable-case formula after certified
    stability), plus one line on the shifts."""
    import sympy as sp

    from ..regularity.sobolev import sobolev_exponent

    s2 = sobolev_exponent(a)
    if s2.value is not None:
        head = f"L2-Sobolev exponent s_2 = {sp.sstr(s2.value)} exactly   [{s2.status}]"
    elif s2.lower is not None or s2.upper is not None:
        head = f"L2-Sobolev exponent s_2 in [{_fmt(s2.lower, 'lower')}, {_fmt(s2.upper, 'upper')}]   [{s2.status}]"
    else:
        head = f"L2-Sobolev exponent s_2: [{s2.status}]"
    _row(args, "$s_2$", s2, witness=s2.witness.get("reason") or str(s2.witness.get("method") or ""))
    lines = [head]
    if s2.witness.get("reason"):
        lines.append(f"  {s2.witness['reason']}")
    st = s2.witness.get("stable_shifts")
    if st is not None:
        if st.value is True:
            lines.append(f"  shifts of phi stable [{st.status}]; method: {s2.witness.get('method')}")
        elif st.value is False:
            lines.append(f"  shifts of phi unstable [{st.status}]: phi_a = q(tau) phi_b / q(1) with q(z) = "
                         f"{s2.witness['q'].pretty()}, b(z) = {s2.witness['reduced_mask'].pretty()} (stable); "
                         "s_2 from the exact transfer-operator sequence of h = (2-z-1/z)^r q(z) q(1/z)")
    return lines, s2.to_json()


def _cycle_text(n: int) -> str:
    """The squaring cycle through e^(2πi/n) (n odd), e.g. ``{e^(2πi/3), e^(4πi/3)}``.

    >>> _cycle_text(3), _cycle_text(7)
    ('{e^(2πi/3), e^(4πi/3)}', '{e^(2πi/7), e^(4πi/7), e^(8πi/7)}')
    """
    ks, k = [], 1
    while k not in ks:
        ks.append(k)
        k = 2 * k % n
    return "{" + ", ".join(f"e^({2 * k}πi/{n})" for k in ks) + "}"


def _stability_part(args, a, budget):
    """Are the integer shifts of the basic limit function phi stable (Jia–Wang, exact)?

    The Hölder exponent alpha = k - log2 JSR and the C^k verdicts are properties of the SCHEME
    (uniform convergence of the divided-difference schemes, Dyn–Levin) and need no stability
    hypothesis; only reading alpha as the Hölder exponent of phi itself needs stable shifts.
    When the shifts are unstable, phi_a = q(tau) phi_b / q(1) is a finite combination of shifts
    of the stable phi_b, and phi_a is one limit of the scheme, so its exponent is >= alpha.
    """
    from ..regularity.stability import stable_shifts

    st = stable_shifts(a)
    w = st.witness
    _row(args, "shifts of phi", st, {True: "stable", False: "unstable", None: "undecided"}[st.value],
         w.get("reason") or "")
    if st.value is True:
        line = (f"basic limit function: shifts stable [{st.status}] ({w['reason']}): "
                "alpha (when the scheme converges) is also the Hölder exponent of phi")
        lines = [line]
    elif st.value is False:
        parts = []
        for h in w.get("symmetric_zeros_on_circle", []):
            parts.append(f"symmetric zeros on the unit circle (H(z^2) | a(z), H = {_sstr(h)})")
        for n in w.get("blocking_cycles", []):
            parts.append(f"the blocking cycle {_cycle_text(n)} (Phi_{2 * n} | a)")
        lines = [f"basic limit function: shifts unstable [{st.status}]: a(z) has " + " and ".join(parts)
                 + f"; phi_a = q(tau) phi_b / q(1), q(z) = {w['q'].pretty()}, b(z) = {w['reduced_mask'].pretty()} "
                 "(stable)", "  alpha above is the Hölder exponent of the scheme (all its limits); "
                 "the Hölder exponent of phi_a is >= alpha"]
    else:
        lines = [f"basic limit function: stability of the shifts undecided [{st.status}] — {w.get('reason')}"]
    return lines, st.to_json()


def _input_with_arity(args, m: int):
    a, label = scheme_from_args(args, arity_ok=True)
    return a, label, f"scheme: {label}   (arity {m}, domain {a.domain})"


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


def _sobolev_lines(a, m: int, lines: list, data: dict, args=None) -> None:
    """``holder --sobolev`` for a scheme of arity ``m > 2``: ``s_2 = -(1/2) log_m lambda``."""
    import sympy as sp

    from ..jsonable import fmt_bound
    from ..regularity.sobolev import sobolev_exponent

    s2 = sobolev_exponent(a, arity=m)
    if s2.value is not None:
        head = f"L2-Sobolev exponent s_2 = {sp.sstr(s2.value)} exactly   [{s2.status}]"
    elif s2.lower is not None:
        head = (f"L2-Sobolev exponent s_2 in [{fmt_bound(s2.lower, 'lower', 12)}, {fmt_bound(s2.upper, 'upper', 12)}]"
                f"   [{s2.status}]")
    else:
        head = f"L2-Sobolev exponent s_2: [{s2.status}]"
    lines.append(head)
    w = s2.witness
    if args is not None:
        _row(args, "$s_2$", s2, witness=f"s_2 = -(1/2) log_{m} lambda" if "lambda_lower" in w else w.get("reason") or "",
             digits=12)
    if "lambda_lower" in w:
        lines.append(f"  s_2 = -(1/2) log_{m} lambda, lambda = largest root of {sp.sstr(w['minimal_polynomial'])} "
                     f"(exact {m}-ary transfer-operator sequence, r = {w['r']})")
    if "weight" in w:
        lines.append(f"  weight h = (2-z-1/z)^r w: {w['weight']}")
    if "reason" in w:
        lines.append(f"  {w['reason']}")
    data["sobolev"] = {"value": s2.value, "lower": s2.lower, "upper": s2.upper, "status": s2.status,
                       "weight": w.get("weight"), "reason": w.get("reason")}


def _figure(args, a, m: int, p: str, j: int, within, r, label: str, lines: list, data: dict) -> None:
    """``range --figure`` for an m-ary family: certified alpha enclosures at ``max(grid, 8) + 1`` points,
    the level alpha = j and the finite ends of the C^j set (issue 12)."""
    import sympy as sp

    from ..regularity.ranges import alpha_curve
    from ..report.plots import plot_alpha_curve

    grid = _int_arg(args.grid, "--grid")
    if grid < 2 or grid > 400:
        raise AnalysisError("--grid must be between 2 and 400")
    budget = work_arg(args.budget, "--budget")
    curve = alpha_curve(a, p, within=within, samples=max(grid, 8), budget=budget, arity=m)
    parts = r.value.args if isinstance(r.value, sp.Union) else (() if r.value == sp.EmptySet else (r.value,))
    ends = [{"exact_float": float(x)} for I in parts if isinstance(I, sp.Interval)
            for x in (I.start, I.end) if x.is_finite and x not in within]
    try:
        plot_alpha_curve(curve, args.figure, j=j, boundaries=ends, label=f"{label} (arity {m})")
    except OSError as exc:
        raise AnalysisError(f"cannot write the figure {args.figure!r}: {exc.strerror or exc}") from None
    lines.append(f"figure written to {args.figure} (alpha at {len(curve.value)} points, {curve.status})")
    data["figure"] = args.figure


def cmd_holder(args) -> None:
    from .holder_box import holder_box, refuse_box_options

    if args.C is not None:                           # options are checked before any computation
        j = _int_arg(args.C, "--C")
        if not 0 <= j <= 30:
            raise AnalysisError(f"--C must be between 0 and 30, not {j}")
    if args.table:
        from .tables import check_table

        check_table(args.table)
    args._table_rows = []
    if getattr(args, "box", None):                   # C^k on a parameter box, level-dependent (issue 13)
        _no_table(args, "a level-dependent scheme on a --box")
        return holder_box(args)
    refuse_box_options(args)
    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        import sympy as sp

        from ..jsonable import fmt_bound
        from ..regularity.convergence import NotConvergent
        from ..regularity.holder import holder_exponent, smoothness

        from .level_input import uses_level

        if uses_level(args):                        # a level-dependent scheme of arity m
            from .levels import holder_level_dependent

            return holder_level_dependent(args, None, arity=m)
        if getattr(args, "approx", False):
            raise AnalysisError("--approx is not available for m-ary schemes yet: give the mask exactly (fractions or radicals)")
        a, label, head = _input_with_arity(args, m)

        require_values(a, label, "holder")
        budget = work_arg(args.budget, "--budget")
        lines, data = [head], {"scheme": label, "arity": m}
        try:
            h = holder_exponent(a, budget=budget, arity=m)
        except NotConvergent as exc:
            r = exc.result()
            lines.append(f"{r.witness['reason']}   [{r.status}]")
            data["alpha"] = r.to_json()
            _row(args, "convergent", r, "no", r.witness["reason"])
            _write_holder_table(args, label, lines, data)
            _emit(args, data, "\n".join(lines))
            return
        if h.value is not None:
            lines.append(f"Hölder exponent alpha = {sp.sstr(h.value)} exactly   [{h.status}]")
        else:
            lines.append(f"Hölder exponent alpha in [{fmt_bound(h.lower, 'lower', 12)}, {fmt_bound(h.upper, 'upper', 12)}]"
                         f"   [{h.status}]")
        lines.append(f"  alpha = {h.witness['k']} - log_{m} JSR(T_0..T_{m - 1}), c = {h.witness['c'].pretty()}")
        _row(args, "alpha", h, witness=f"alpha = {h.witness['k']} - log_{m} JSR(T_0..T_{m - 1})", digits=12)
        data["alpha"] = {"value": h.value, "lower": h.lower, "upper": h.upper, "status": h.status, "k": h.witness["k"]}
        if args.C is not None:
            j = _int_arg(args.C, "--C")
            s = smoothness(a, j, budget=budget, arity=m)
            verdict = {True: f"C^{j}", False: f"not C^{j}", None: "undecided"}[s.value]
            lines.append(f"{verdict}: {s.witness['reason']}   [{s.status}]")
            _row(args, f"C^{j}", s, {True: "yes", False: "no", None: "undecided"}[s.value], s.witness["reason"])
            data["smoothness"] = {"j": j, "value": s.value, "status": s.status, "reason": s.witness["reason"]}
        if getattr(args, "sobolev", False):
            _sobolev_lines(a, m, lines, data, args)
        _write_holder_table(args, label, lines, data)
        _emit(args, data, "\n".join(lines))
        return
    budget = work_arg(args.budget, "--budget")
    from .level_input import is_stationary, level_scheme_from_args

    from .levels import holder_growing_support, holder_level_dependent

    try:
        level = level_scheme_from_args(args, _parse_params(args.param))
    except AnalysisError as exc:
        _no_table(args, "a level-dependent scheme whose level enters through n (or whose support grows)")
        if str(exc).startswith("the support of a^n grows"):
            return holder_growing_support(args, str(exc))
        from .levels_rational import fallback, holder_rational      # the level enters through n itself

        return holder_rational(args, fallback(args, _parse_params(args.param), exc))
    if level is not None and not is_stationary(level):
        return holder_level_dependent(args, level)
    entry = _numeric_entry(args)
    if entry is not None:
        if args.param:
            raise AnalysisError(f"{entry.slug} is known by certified enclosures only: --param is not available for it")
        if getattr(args, "approx", False):
            raise AnalysisError("--approx needs --mask (a typed decimal table)")
        a, label = entry, entry.slug
        lines = [f"scheme: {entry.slug}   (mask known by Arb ball enclosures)"]
    elif (alt := _alternative_reading(args)) is not None:    # --approx, or nested radicals / I / CRootOf
        a, label, first = alt
        lines = [first]
    else:
        if getattr(args, "approx", False):
            raise AnalysisError("--approx needs --mask (a typed decimal table)")
        a, label = scheme_from_args(args)
        require_values(a, label, "holder")
        lines = [f"scheme: {label}   (domain {a.domain})"]
    data: dict = {"scheme": label}
    _part("alpha", lambda: _alpha_part(args, a, budget), lines, data, args)
    _part("stability", lambda: _stability_part(args, a, budget), lines, data, args)
    if args.C is not None:
        _part("smoothness", lambda: _smoothness_part(args, a, budget), lines, data, args)
    if args.sobolev:
        _part("sobolev", lambda: _sobolev_part(args, a, budget), lines, data, args)
    _write_holder_table(args, label, lines, data)
    _emit(args, data, "\n".join(lines))


def _interior_lines(it: dict, j: int) -> list:
    """The interior of one run: the certified pieces (exact ends) and the strips left."""
    import sympy as sp
    from ..algebra.reader import as_expr

    def b(x):
        x = as_expr(x)
        return sp.sstr(x) if x.is_Rational else f"{sp.sstr(x)} ~ {float(x):.10g}"

    left = "(" if it.get("from_open", False) else "["
    right = ")" if it.get("to_open", False) else "]"
    head = f"  interior {left}{b(it['from'])}, {b(it['to'])}{right}: "
    if it["proven"]:
        return [head + "proven C^%d on the whole of it (%s)" % (j, it["route"])]
    if "certified" not in it:
        return [head + "certified at the grid points only (%s)" % it["route"]]
    out = [head + "C^%d proven on %s (%s)" % (j, it["certified"], it["route"])]
    for x, y in it["strips"]:
        out.append(f"    inconclusive strip ({b(x)}, {b(y)}) (width {float(as_expr(y) - as_expr(x)):.3g})")
    return out


def cmd_range(args) -> None:
    import sympy as sp
    from ..jsonable import fmt_bound

    from .family import apply_family

    if args.figure:                                   # before any computation: format and place
        check_figure(args.figure, "the figure")
    if args.table:
        from .tables import check_table

        check_table(args.table)
    apply_family(args)                                # --family FILE.json (issue 14)
    if (arity := scheme_arity(args)) != 2:          # arity m > 2: the m-ary lines (residue sums, q_m, log_m)
        m = arity
        from ..regularity.ranges import ck_range

        if args.figure:
            check_figure(args.figure, "the figure")
        a, label, head = _input_with_arity(args, m)
        j = _int_arg(args.C, "--C")
        within = _parse_within(args.within)
        if args.figure and not all(w.is_finite for w in within):
            raise AnalysisError("--figure needs finite bounds in --within, e.g. --within=-1,1")
        strip_budget = work_arg(getattr(args, "strip_budget", 30_000), "--strip-budget", minimum=0)
        Ls = [1, 2]
        r = ck_range(a, j, args.param_name, Ls=Ls, within=within, strip_budget=strip_budget, arity=m)
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
        if args.table:
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
        return
    from ..regularity.ranges import alpha_curve, ck_parameter_set

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
    strip_budget = work_arg(args.strip_budget, "--strip-budget", minimum=0)
    budget = work_arg(args.budget, "--budget")
    from .. import progress

    with progress.on_terminal("range", enabled=not args.json):
        r = ck_parameter_set(a, j, args.param_name, within=within, grid=grid, tol=tol,
                             budget=budget, interior_L_max=12, strip_budget=strip_budget)
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
            return f"in [{fmt_bound(lo, 'lower', 12, 'g')}, {fmt_bound(hi, 'upper', 12, 'g')}]"
        lines.append(f"  C^{j} from {end(run['left'], 'left')} to {end(run['right'], 'right')}")
    for b in r.witness["boundaries"]:
        lines.append(f"  boundary: certified C^{j} at {sp.sstr(b.get('certified_C^j_at'))}, certified not C^{j} at "
                     f"{sp.sstr(b.get('certified_not_C^j_at'))} ({b.get('how', b['status'])})")
    if r.witness["undecided"]:
        lines.append("  undecided grid points: " + ", ".join(sp.sstr(x) for x in r.witness["undecided"]))
    pt = lambda x: sp.sstr(x) if x.is_Rational else f"{sp.sstr(x)} ~ {float(x):.12g}"  # noqa: E731
    lines += [f"  not C^{j} on [{pt(s['from'])}, {pt(s['to'])}] (certified: {s['how']})"
              for s in r.witness.get("not_Cj", []) if s["proven"] and s["from"] != s["to"]]
    for run in r.value:
        it = run.get("interior")
        if it:
            lines.extend(_interior_lines(it, j))
    if "message" in r.provenance:
        lines.append(f"  {r.provenance['message']}")
    data = {"scheme": label, "j": j, "parameter": p, "within": list(within), "result": r.to_json()}
    if args.table:
        from .tables import write_table

        def cell(b):
            if "open_end" in b:
                return f"{sp.sstr(b['open_end'])} (grid end)"
            if "exact" in b:
                return b["exact"]
            lo, hi = b["bracket"]
            return f"in [{fmt_bound(lo, 'lower', 12, 'g')}, {fmt_bound(hi, 'upper', 12, 'g')}]"
        rows = [[f"C^{j}", cell(run["left"]), cell(run["right"])] for run in r.value]
        rows += [["grid point " + sp.sstr(s["p"]), {True: "C^%d" % j, False: "not C^%d" % j}.get(s["C^j"], "undecided"),
                  "alpha in [%s, %s]" % (fmt_bound(s["alpha"][0], "lower", 6, "g"), fmt_bound(s["alpha"][1], "upper", 6, "g"))
                  if s["alpha"] else ""] for s in r.witness["samples"]]
        write_table(args.table, ["", f"from ({p})", "to"], rows,
                    f"subdiv range: {label}, where is it C^{j}? [{r.status}]")
        lines.append(f"table written to {args.table}")
        data["table"] = args.table
    if args.maximize:
        from .common import parse_coefficient
        from .maximize import maximize_part

        with progress.on_terminal("range", enabled=not args.json):
            maximize_part(a, {p: within}, 2, parse_coefficient(args.gap), 60_000, lines, data)
    if args.figure:
        curve = alpha_curve(a, p, within=within, samples=max(grid, 8), budget=budget)
        from ..report.plots import plot_alpha_curve

        try:
            plot_alpha_curve(curve, args.figure, j=j, boundaries=r.witness["boundaries"], label=label)
        except OSError as exc:
            raise AnalysisError(f"cannot write the figure {args.figure!r}: {exc.strerror or exc}") from None
        lines.append(f"figure written to {args.figure}")
        data["figure"] = args.figure
    _emit(args, data, "\n".join(lines))


def register(sub) -> None:
    s = sub.add_parser("holder", help="certified Hölder exponent (joint spectral radius), C^k verdict, Sobolev exponent")
    _add_scheme_args(s)
    s.add_argument("--C", metavar="K", help="also decide whether the scheme is C^K")
    s.add_argument("--sobolev", action="store_true", help="also the L2-Sobolev exponent (transition operator)")
    s.add_argument("--table", metavar="FILE", help="also write the results as FILE.csv or FILE.tex (a LaTeX booktabs tabular): "
                                                  "alpha, stability, C^K, s_2 (of a level-dependent scheme: its C^k "
                                                  "verdicts), each with its value, status and witness")
    s.add_argument("--budget", default="20000", metavar="UNITS",
                   help=f"work budget of the joint spectral radius, in work units (default 20000; {WORK_HELP})")
    s.add_argument("--approx", action="store_true",
                   help="approximate reading of a decimal --mask: each coefficient a ball of half a unit in its "
                        "last digit (a double's 17 digits: 4 ulps), sum rules imposed inside the balls (alpha "
                        "certified for every such mask); a filter with sum sqrt(2) is read as the mask times sqrt(2)")
    s.add_argument("--approx-radius", metavar="R",
                   help="with --approx: the radius of every decimal coefficient's ball (e.g. 1e-12), instead of "
                        "the one its digits imply")
    s.add_argument("--box", action="append", metavar="NAME=LOW,HIGH",
                   help="level-dependent scheme: C^k at every point of a closed parameter box (repeatable: two "
                        "parameters)")
    s.add_argument("--pieces", type=int, metavar="P", help="with --box: sub-boxes of each parameter box (default 1)")
    s.add_argument("--depth", type=int, metavar="D",
                   help="with --box: bisect an undecided sub-box up to D times (default 2)")
    s.add_argument("--open", metavar="NAME", help="with --box: the limit's parameter; its box is read as an open "
                                                  "interval for the limit's C^k (exact norm set)")
    s.set_defaults(func=cmd_holder)

    s = sub.add_parser("range", help="where a one-parameter family is C^k: boundaries certified on both sides")
    _add_scheme_args(s)
    s.add_argument("--C", metavar="K", required=True, help="smoothness order k")
    s.add_argument("--param-name", metavar="NAME", help="the free parameter (default: the only one)")
    s.add_argument("--within", metavar="LOW,HIGH", required=True, help="finite parameter interval (use --within=-1,1)")
    s.add_argument("--grid", default="16", help="number of grid cells (default 16)")
    s.add_argument("--tol", default="1e-8", help="boundary tolerance (default 1e-8)")
    s.add_argument("--budget", default="20000", metavar="UNITS",
                   help=f"work budget per joint spectral radius, in work units (default 20000; {WORK_HELP})")
    s.add_argument("--strip-budget", default="30000", metavar="UNITS",
                   help="work budget for closing the strips next to ends of eigenvalue type by the parametric "
                        "invariant polytope, in work units (default 30000; the 6-point family's C^1 set needs "
                        "about 800000)")
    s.add_argument("--figure", metavar="PATH", help="write the curve alpha(p) with its certified error bars")
    s.add_argument("--family", metavar="FILE.json", help="a family written by subdiv derive --output (replaces --mask)")
    s.add_argument("--table", metavar="FILE", help="also write the C^k set (and the grid verdicts) as FILE.csv or "
                                                  "FILE.tex (a LaTeX booktabs tabular)")
    s.add_argument("--maximize", choices=("holder",), help="also the smoothest member on --within (certified gap)")
    s.add_argument("--gap", default="1/1000", metavar="G", help="target certified gap of --maximize (default 1/1000)")
    s.set_defaults(func=cmd_range)
