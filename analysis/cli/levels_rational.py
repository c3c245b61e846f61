"""``subdiv holder`` / ``subdiv series`` on level-dependent input whose level enters through n itself
(rational functions of n times powers of 2^-n; :mod:`analysis.levels.rational_level`)."""

from __future__ import annotations

from ..result import AnalysisError
from .common import _emit
from .level_args import k_max_arg, stationary_options_refused
from .level_text import limit_line, series_line, verdict_lines


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
    import sympy as sp

    n = sp.Symbol("n")
    expr = sum(c.subs(sp.Symbol("h", positive=True), 2 ** (-n)) * sp.Symbol("z") ** (s.start + k)
               for k, c in enumerate(s.mask))
    return [f"scheme: {s.slug} (level-dependent; the level enters through n and 2^-n)",
            f"  a^n(z) = {sp.sstr(sp.factor(expr))}"]


def holder_rational(args, s) -> None:
    from ..levels.rational_level import level_smoothness_rational

    stationary_options_refused(args)
    r = level_smoothness_rational(s, k_max=k_max_arg(args))
    lines = _header(s) + [limit_line(r.witness["limit"])] + verdict_lines(r, why=True)
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
        lines.append(series_line(f"m = {m}", r, lambda v, r=r: (
            f"{r.witness['tail']}; slowest |a^n_k - a_k| ~ {r.witness['decay']}" if v == "convergent" else
            f": {r.witness['reason']}" if v == "divergent" else f" — {r.witness.get('reason')}")))
    _emit(args, {"scheme": s.slug, "level": "rational in n", "series": rows}, "\n".join(lines))
