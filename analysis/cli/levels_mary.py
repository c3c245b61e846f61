"""``subdiv series`` and ``subdiv holder`` on a level-dependent m-ary scheme (``--arity M``; issue 12, issue 13 item 6).

The scheme is inline: ``--symbol`` or ``--mask`` using the level ``n`` through ``M^n`` (e.g.
``cos(theta/3**(n+1))``) and repeatable ``--where NAME=EXPR``; parameters by ``--param NAME=VALUE``
(``series`` also takes ``--box NAME=LOW,HIGH``, several boxes, ``--pieces P`` (sub-boxes per boxed parameter),
``--depth D`` (adaptive bisection of undecided sub-boxes) and ``--difference J`` (the divided difference scheme
``(M/(1+z+...+z^(M-1)))^J a^n``; issue 12, second round)).

Examples
--------
::

    subdiv series --arity 3 --symbol "(1+z+z**2)*(1+2*c*z+(1+2*d)*z**2+2*c*z**3+z**4)/((3+4*c+2*d)*z**3)" \\
        --where "c=cos(theta/3**(n+1))" --where "d=cos(2*theta/3**(n+1))" --param theta=1 --m 0,1,2
    subdiv holder --arity 3 --symbol "..." --where ... --param theta=1
"""

from __future__ import annotations

from ..result import AnalysisError
from .common import _emit
from .level_args import k_max_arg, param_box_values, stationary_options_refused
from .level_text import limit_line, series_line, verdict_lines


def level_scheme_mary_from_args(args, m: int):
    """The :class:`~analysis.levels.mary.LevelDependentMary` of the inline arguments."""
    from ..levels.mary import level_scheme_mary
    from .level_input import _int, _items

    sym, mask = getattr(args, "symbol", None), getattr(args, "mask", None)
    if getattr(args, "scheme", None):                   # the level-dependent m-ary catalogue (schemes.level_mary)
        from schemes.level_mary import get_mary

        if sym is not None or mask is not None or getattr(args, "where", None):
            raise AnalysisError("give --scheme NAME or --symbol/--mask, not both")
        s = get_mary(args.scheme)
        if s.arity != m:
            raise AnalysisError(f"scheme {args.scheme!r} has arity {s.arity}; drop --arity or give --arity {s.arity}")
        return s
    if (sym is None) == (mask is None):
        raise AnalysisError("give exactly one of --symbol EXPR, --mask LIST (using the level n)")
    where = getattr(args, "where", None) or []
    if sym is not None:
        s = level_scheme_mary(sym, m, where=where, slug="symbol")
    else:
        s = level_scheme_mary(None, m, mask=_items(mask, "mask"), start=_int(getattr(args, "start", "0"), "--start"),
                              where=where, slug="mask")
    from ..levels.level_dependent import H

    if all(H not in c.free_symbols for c in s.mask):
        raise AnalysisError("the scheme does not depend on the level n: use a stationary command (e.g. subdiv holder)")
    return s


def _values(args, s) -> dict:
    """``--param`` and ``--box`` (:func:`analysis.cli.level_args.param_box_values`); every parameter needs one."""
    vals = param_box_values(args, "theta=1/2,2")
    missing = [p for p in s.scheme.param_names if p not in vals]
    if missing:
        raise AnalysisError(f"undefined name(s) {', '.join(missing)}: define them with --where NAME=EXPR "
                            "or give --param NAME=VALUE")
    return vals


def cmd_series(args, m: int) -> None:
    import sympy as sp
    from ..jsonable import fmt_lower, fmt_upper

    from ..levels.mary import difference_scheme_mary, weighted_series_boxes_mary

    if getattr(args, "C", None) is not None or getattr(args, "open", None):
        raise AnalysisError("--C/--open (C^k on a parameter region) are not available for m-ary schemes; "
                            "use subdiv holder --arity M at parameter values")
    s = level_scheme_mary_from_args(args, m)
    vals = _values(args, s)
    d = getattr(args, "difference", 0) or 0
    pieces, depth = getattr(args, "pieces", 1) or 1, getattr(args, "depth", 0) or 0
    for name, v in (("--difference", d), ("--pieces", pieces), ("--depth", depth)):
        if isinstance(v, bool) or not isinstance(v, int) or v < (1 if name == "--pieces" else 0):
            raise AnalysisError(f"{name} must be an integer >= {1 if name == '--pieces' else 0}, not {v!r}")
    if d:
        s = difference_scheme_mary(s, d)
    rows, lines = [], []
    try:
        weights = [int(x) for x in str(args.m).split(",")]
    except ValueError:
        raise AnalysisError(f"--m must be integers like 0,1,2, not {args.m!r}") from None
    for k in weights:
        r = weighted_series_boxes_mary(s, vals, k, pieces=pieces, depth=depth, N=args.N)
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


def cmd_holder(args, m: int) -> None:
    """``subdiv holder`` on a level-dependent m-ary scheme: convergence and C^k for each k, each with its theorem
    and status, and "not C^k" where a theorem gives it (:func:`analysis.levels.mary.level_smoothness_mary`, the
    binary routes with dilation m; the lines are those of the binary command, :mod:`analysis.cli.level_text`)."""
    import sympy as sp

    from ..levels.mary import level_smoothness_mary

    stationary_options_refused(args)
    s = level_scheme_mary_from_args(args, m)
    vals = _values(args, s)
    k_max = k_max_arg(args)
    r = level_smoothness_mary(s, vals, k_max=k_max)
    lines = [f"scheme: {s.slug} (level-dependent, arity {m}, h = {m}^-n)",
             f"  a^n(z) = {sp.sstr(sp.factor(s.symbol_in_n().subs({q: vals[q.name] for q in s.params if not isinstance(vals[q.name], tuple)})))}",
             limit_line(r.witness["limit"])] + verdict_lines(r)
    _emit(args, {"scheme": s.slug, "arity": m, "level_dependent": True, "smoothness": r.to_json()}, "\n".join(lines))
