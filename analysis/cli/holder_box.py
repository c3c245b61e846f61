"""``subdiv holder ... --box NAME=LOW,HIGH``: C^k of a level-dependent scheme on a whole parameter box.

The box version of ``subdiv holder`` on a level-dependent scheme (:mod:`analysis.cli.levels`):
:func:`analysis.levels.ck_box.level_smoothness_box` decides C^k at every point of one or two closed
parameter boxes by an adaptive cover (``--pieces`` per parameter, ``--depth`` bisections), and
"not C^d" for exponential B-spline schemes recognised identically in the parameters. ``--open NAME``
reads the box of the limit's parameter as an open interval for the limit's hypothesis (as
``subdiv series --C K --open NAME``). ``--arity M`` (or an m-ary entry of :mod:`schemes.level_dependent`): the
same cover with dilation M (``h = M^-n``; ``--open`` binary only).

Examples
--------
::

    subdiv holder --scheme exp-cubic-trig --box t=1/10,3
    subdiv holder --symbol "(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2" --where "c=cos(theta/2**(n+1))" --box theta=1/10,pi/2
    subdiv holder --scheme seed003-trigonometric --box alpha=0,pi/3 --box "omega=0,(sqrt(6)-1)/80" --open omega
    subdiv holder --scheme ternary-exp-bspline-3-trig --box t=1/10,2

>>> box_line({"alpha": ["0", "pi/3"], "omega": ["0", "1/100"]})
'alpha in [0, pi/3], omega in [0, 1/100]'
"""

from __future__ import annotations

from ..result import AnalysisError
from .common import _emit
from .level_args import k_max_arg, param_box_values, stationary_options_refused
from .level_text import limit_line

#: the undecided sub-boxes printed in the text output per k (all of them are in --json)
SHOWN = 8


def box_line(box: dict) -> str:
    """``name in [lo, hi], ...`` of an exact box (``{name: [lo, hi]}``)."""
    return ", ".join(f"{k} in [{v[0]}, {v[1]}]" if isinstance(v, list) else f"{k} = {v}" for k, v in box.items())


def _options(args) -> tuple[int, int]:
    pieces = 1 if args.pieces is None else args.pieces
    depth = 2 if args.depth is None else args.depth
    if pieces < 1 or pieces > 16:
        raise AnalysisError(f"--pieces must be between 1 and 16, not {pieces}")
    if not 0 <= depth <= 8:
        raise AnalysisError(f"--depth must be between 0 and 8, not {depth}")
    return pieces, depth


def refuse_box_options(args) -> None:
    """``--pieces``, ``--depth``, ``--open`` without ``--box``: a one-line error."""
    given = [f"--{x}" for x in ("pieces", "depth", "open") if getattr(args, x, None) is not None]
    if given:
        raise AnalysisError(f"{', '.join(given)} need{'s' if len(given) == 1 else ''} --box NAME=LOW,HIGH "
                            "(C^k on a parameter box)")


def _scheme(args):
    from .level_input import is_stationary, level_scheme_from_args

    try:
        s = level_scheme_from_args(args, None, keep_params=True)
    except AnalysisError as exc:
        if str(exc).startswith("the support of a^n grows"):
            return None, str(exc)
        if "as a function of h = 2^-n" in str(exc):
            raise AnalysisError(f"{exc}; --box is available for levels entering through 2^-n with one bounded "
                                "support (give --param values)") from None
        raise
    if s is None:
        raise AnalysisError("--box is for level-dependent schemes (the level n, --where or a level-dependent "
                            "catalogue name); for a stationary family use `subdiv range --within LOW,HIGH`")
    if is_stationary(s):
        raise AnalysisError("the scheme does not depend on the level n: --box is for level-dependent schemes "
                            "(stationary families: `subdiv range --within LOW,HIGH`)")
    return s, None


def _verdict_lines(r) -> list[str]:
    import sympy as sp

    lines = []
    for v in r.witness["verdicts"]:
        name = "convergence (C^0)" if v["k"] == 0 else f"C^{v['k']}"
        if v["status"] == "certified" and v.get("holds") is False:
            fr = ", ".join(sp.sstr(x) for x in v["frequencies"])
            lines.append(f"  {name}: no at every point [certified] — {v['route']}, frequencies {fr}: it generates "
                         f"the exponential B-spline B_Lambda, C^{v['k'] - 1} and not C^{v['k']}")
        elif v["status"] == "certified" and "implied_by" in v:
            lines.append(f"  {name}: yes at every point [certified] — implied by {v['implied_by']} (certified on the "
                         f"whole box; {len(v['undecided_directly'])} sub-box(es) undecided by the routes for {name})")
        elif v["status"] == "certified":
            routes = "; ".join(f"{rt} ({n} sub-box{'es' if n > 1 else ''})" for rt, n in v["routes"].items())
            lines.append(f"  {name}: yes at every point [certified] — {routes}")
        elif "reason" in v:
            lines.append(f"  {name}: undecided [inconclusive] — {v['reason']}")
        else:
            done = v["sub_boxes"] - len(v["undecided"])
            lines.append(f"  {name}: undecided [inconclusive] — {done} of {v['sub_boxes']} sub-boxes certified; "
                         f"undecided:")
            for u in v["undecided"][:SHOWN]:
                why = "; ".join(f"{t['route']}: failed {', '.join(t['failed'])}" for t in u["tried"])
                lines.append(f"    {box_line(u['box'])} — {why}")
                reason = next((t["why"] for t in u["tried"] if t.get("why")), "")
                if reason:
                    lines.append(f"      ({reason})")
            if len(v["undecided"]) > SHOWN:
                lines.append(f"    ... and {len(v['undecided']) - SHOWN} more (--json)")
    best = r.value
    where = r.witness["region"]
    if r.witness.get("exact"):
        lines.append(f"  => C^{best} exactly at every point of {where} (certified: C^{best} and not C^{best + 1})")
    elif best >= 0:
        lines.append(f"  => C^{best} certified at every point of {where}"
                     + (f", not C^{r.witness['not_C^k']} certified" if r.witness.get("not_C^k") is not None else
                        " (a lower bound)"))
    else:
        lines.append(f"  => convergence not certified on the whole of {where}")
    return lines


def holder_box(args) -> None:
    """``subdiv holder --box ...`` on a level-dependent scheme (binary; ``--arity M`` or an m-ary entry of
    :mod:`schemes.level_dependent`: dilation M, ``h = M^-n``)."""
    import sympy as sp

    from ..levels.ck_box import level_smoothness_box
    from .common import scheme_arity

    stationary_options_refused(args)
    m = scheme_arity(args, level=True)
    pieces, depth = _options(args)
    k_max = k_max_arg(args)
    if m != 2:
        from .levels import level_scheme_with_arity

        if args.open is not None:
            raise AnalysisError("--open is available for binary schemes only (the open-interval limit test is "
                                "binary); drop --open or --arity")
        s = level_scheme_with_arity(args, m)
    else:
        s, growing = _scheme(args)
        if s is None:
            from .levels import holder_growing_support

            return holder_growing_support(args, growing)
    values = param_box_values(args, "theta=1/10,pi/2")
    if args.open is not None and not isinstance(values.get(args.open), tuple):
        raise AnalysisError(f"--open {args.open} needs a --box for {args.open}")
    r = level_smoothness_box(s, values, pieces=pieces, depth=depth, k_max=k_max, open_param=args.open, arity=m)
    lim = r.witness["limit"]
    h = sp.Symbol("h", positive=True)
    kind = "h = 2^-n" if m == 2 else f"arity {m}, h = {m}^-n"
    lines = [f"scheme: {s.slug} (level-dependent, {kind}) on {r.witness['region']}",
             f"  a^n(z) = {sp.sstr(sp.factor(s.symbol_expr().subs(h, m ** (-sp.Symbol('n')))))}"]
    if lim["parametric"]:
        lines.append(f"  limit a(z) = {lim['symbol'].pretty()} (depends on {', '.join(lim['parametric'])}: "
                     "its C^k is decided on each sub-box)")
    else:
        lines.append(limit_line(lim))
    if args.open:
        lines.append(f"  {args.open}: its interval is read as open for the limit's hypothesis (exact norm sets); "
                     "series and same support on the closed boxes")
    lines += _verdict_lines(r)
    _emit(args, {"scheme": s.slug, **({} if m == 2 else {"arity": m}), "level_dependent": True,
                 "box": r.witness["box"], "smoothness": r.to_json()},
          "\n".join(lines))
