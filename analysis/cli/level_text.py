"""The text of the level-dependent commands: one line per weighted series, the C^k verdict lines.

One implementation for :mod:`analysis.cli.levels` (``h = 2^-n``; ``--arity M``: ``h = M^-n``) and
:mod:`analysis.cli.levels_rational` (the level through n itself); each
passes the label of the weight (``m = 1``, ``weight 3^(1n)``) and the detail its engine provides.

Examples
--------
>>> import sympy as sp
>>> from analysis.result import Result
>>> r = Result(lower=sp.Rational(1, 3), upper=sp.Rational(1, 2), status="certified",
...            witness={"verdict": "convergent"})
>>> series_line("m = 0", r, lambda verdict: "tail <= 1e-9")
'm = 0: convergent, sum in [0.333333333333333, 0.5] (certified; tail <= 1e-9)'
"""

from __future__ import annotations

from typing import Callable


def series_line(label: str, r, detail: Callable[[str | None], str]) -> str:
    """``label: convergent, sum in [lo, hi] (status; detail)``, ``label: divergent (status)detail`` or
    ``label: status detail``; ``detail(verdict)`` is the engine's own part of the line."""
    from ..jsonable import fmt_lower, fmt_upper

    v = r.witness.get("verdict")
    if v == "convergent":
        return (f"{label}: convergent, sum in [{fmt_lower(r.lower, 15, 'g')}, {fmt_upper(r.upper, 15, 'g')}] "
                f"({r.status}; {detail(v)})")
    if v == "divergent":
        return f"{label}: divergent ({r.status}){detail(v)}"
    return f"{label}: {r.status}{detail(v)}"


def limit_line(lim: dict) -> str:
    """``  limit a(z) = ...: C^k certified[, not C^k' certified]`` of a C^k verdict's ``witness["limit"]``."""
    return (f"  limit a(z) = {lim['symbol'].pretty()}: C^{lim['C^k_certified_up_to']} certified"
            + (f", not C^{lim['not_C^k']} certified" if lim["not_C^k"] is not None else ""))


def verdict_rows(r) -> list[list]:
    """The rows ``[C^k, yes/no/undecided, status, theorem or reason]`` of a level-dependent C^k result (the
    ``holder --table`` of a level-dependent scheme; the same verdicts as :func:`verdict_lines`)."""
    rows = []
    for v in r.witness["verdicts"]:
        name = "convergence (C^0)" if v["k"] == 0 else f"C^{v['k']}"
        if v["status"] == "certified":
            rows.append([name, "no" if v.get("holds") is False else "yes", "certified", v["route"]])
        else:
            rows.append([name, "undecided", v["status"], v.get("reason") or "; ".join(
                f"{t['route']}: failed {', '.join(t['failed'])}" for t in v.get("tried", []))])
    return rows


def verdict_lines(r, *, why: bool = False) -> list[str]:
    """The lines ``  C^k: yes/no/undecided [status] — theorem`` of a level-dependent C^k result and the
    conclusion ``  => ...``; ``why``: each failed route also says why (its ``"why"``)."""
    import sympy as sp

    lines = []
    for v in r.witness["verdicts"]:
        name = "convergence (C^0)" if v["k"] == 0 else f"C^{v['k']}"
        if v["status"] == "certified" and v.get("holds") is False:
            fr = ", ".join(sp.sstr(x) for x in v["frequencies"])
            lines.append(f"  {name}: no [certified] — {v['route']}, frequencies {fr}: it generates the "
                         f"exponential B-spline B_Lambda, C^{v['k'] - 1} and not C^{v['k']} (pieces in "
                         "ker prod(D - lambda_i) joined at integer knots; Unser-Blu 2005, Conti-Romani 2010)")
        elif v["status"] == "certified":
            lines.append(f"  {name}: yes [certified] — {v['route']}")
        elif "reason" in v:
            lines.append(f"  {name}: undecided [inconclusive] — {v['reason']}")
        else:
            tried = "; ".join(f"{t['route']}: failed {', '.join(t['failed'])}" + (f" ({t['why']})" if why else "")
                              for t in v["tried"])
            lines.append(f"  {name}: undecided [inconclusive] — {tried}")
    best = r.value
    if r.witness.get("exact"):
        lines.append(f"  => C^{best} exactly (certified: C^{best} and not C^{best + 1})")
    elif best >= 0 and r.witness.get("not_C^k") is not None:
        lines.append(f"  => C^{best} certified, not C^{r.witness['not_C^k']} certified")
    else:
        lines.append(f"  => C^{best} certified (a lower bound: 'not C^k' is not decided for this level-dependent scheme)"
                     if best >= 0 else "  => convergence not certified")
    return lines
