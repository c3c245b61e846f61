"""``subdiv holder`` / ``subdiv series`` on level-dependent input whose level enters through n itself
(rational functions of n times powers of 2^-n; :mod:`analysis.levels.rational_level`)."""

from __future__ import annotations

import sympy as sp

from ..jsonable import fmt_lower, fmt_upper
from ..result import AnalysisError
from .common import _emit


def rational_scheme_from_args(args, params):
    """The :class:`RationalLevelScheme` of ``--symbol``/``--mask`` (+ ``--where``, ``--param``), or ``None``."""
    from ..levels.rational_level import RationalLevelScheme
    from .level_input import _int, _items

    where = getattr(args, "where", None) or []
    if getattr(args, "symbol", None) is not None:
        return RationalLevelScheme.from_symbol(args.symbol, where=where, params=params)
    if getattr(args, "mask", None) is not None:
        return RationalLevelScheme.from_mask(_items(args.mask, "mask"), _int(getattr(args, "start", "0"), "--start"),
                                             where=where, params=params)
    return None


def fallback(args, params, exc: AnalysisError):
    """The rational-in-n scheme when ``exc`` is the 'cannot write ... as a function of h' error; else re-raise."""
    if "as a function of h = 2^-n" not in str(exc):
        raise exc
    try:
        s = rational_scheme_from_args(args, params)
    except AnalysisError as exc2:
        if str(exc2).startswith("cannot write"):
            raise AnalysisError(f"{exc}; nor as a polynomial in 2^-n with coefficients rational in n") from None
        raise exc2 from None
    if s is None:
        raise exc
    return s


def _header(s) -> list[str]:
    n = sp.Symbol("n")
    expr = sum(c.subs(sp.Symbol("h", positive=True), 2 ** (-n)) * sp.Symbol("z") ** (s.start + k)
               for k, c in enumerate(s.mask))
    return [f"scheme: {s.slug} (level-dependent; the level enters through n and 2^-n)",
            f"  a^n(z) = {sp.sstr(sp.factor(expr))}"]


def holder_rational(args, s) -> None:
    from ..levels.rational_level import level_smoothness_rational

    if getattr(args, "approx", False) or getattr(args, "sobolev", False):
        raise AnalysisError("--approx and --sobolev are for stationary schemes; this scheme depends on the level n")
    k_max = None
    if args.C is not None:
        try:
            k_max = int(args.C)
        except ValueError:
            raise AnalysisError(f"--C must be an integer, not {args.C!r}") from None
        if k_max < 0:
            raise AnalysisError("--C must be >= 0")
    r = level_smoothness_rational(s, k_max=k_max)
    lim = r.witness["limit"]
    lines = _header(s) + [f"  limit a(z) = {lim['symbol'].pretty()}: C^{lim['C^k_certified_up_to']} certified"
                          + (f", not C^{lim['not_C^k']} certified" if lim["not_C^k"] is not None else "")]
    for v in r.witness["verdicts"]:
        name = "convergence (C^0)" if v["k"] == 0 else f"C^{v['k']}"
        if v["status"] == "certified":
            lines.append(f"  {name}: yes [certified] — {v['route']}")
        elif "reason" in v:
            lines.append(f"  {name}: undecided [inconclusive] — {v['reason']}")
        else:
            why = "; ".join(f"{t['route']}: failed {', '.join(t['failed'])} ({t['why']})" for t in v["tried"])
            lines.append(f"  {name}: undecided [inconclusive] — {why}")
    best = r.value
    lines.append(f"  => C^{best} certified (a lower bound: 'not C^k' is not decided for this level-dependent scheme)"
                 if best >= 0 else "  => convergence not certified")
    _emit(args, {"scheme": s.slug, "level_dependent": True, "level": "rational in n",
                 "smoothness": r.to_json()}, "\n".join(lines))


def series_rational(args, s, ms) -> None:
    from ..levels.rational_level import weighted_series_rational

    if args.difference:
        for _ in range(args.difference):
            s = s.difference()
    rows, lines = [], _header(s)
    for m in ms:
        r = weighted_series_rational(s, m, N_sum=args.N)
        rows.append({"m": m, **r.to_json()})
        v = r.witness["verdict"]
        if v == "convergent":
            lines.append(f"m = {m}: convergent, sum in [{fmt_lower(r.lower, 15, 'g')}, {fmt_upper(r.upper, 15, 'g')}] "
                         f"({r.status}; {r.witness['tail']}; slowest |a^n_k - a_k| ~ {r.witness['decay']})")
        elif v == "divergent":
            lines.append(f"m = {m}: divergent ({r.status}): {r.witness['reason']}")
        else:
            lines.append(f"m = {m}: {r.status} — {r.witness.get('reason')}")
    _emit(args, {"scheme": s.slug, "level": "rational in n", "series": rows}, "\n".join(lines))
