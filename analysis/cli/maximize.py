"""``--maximize holder`` on a family with several parameters or of arity m (``subdiv derive``,
``subdiv range``, ``subdiv atlas``): :func:`analysis.regularity.maximize_box.maximize_holder_box`.

Examples
--------
::

    subdiv derive --support 11 --interpolatory --symmetric primal --reproduce 1 \\
        --maximize holder --box t1=0,1/32 --box t2=-1/8,0
    subdiv derive --arity 3 --support 11 --interpolatory --symmetric primal --reproduce 2 \\
        --maximize holder --within=-1/16,0
    subdiv atlas --family FAMILY.json --x t1=0:1/32:5 --y t2=-1/8:0:5 --maximize holder
"""

from __future__ import annotations

from ..result import AnalysisError


def parse_boxes(items) -> dict:
    """``["t1=0,1/32", "t2=-1/8,0"]`` -> ``{"t1": (0, 1/32), "t2": (-1/8, 0)}`` (exact)."""
    from .common import _parse_within

    out = {}
    for item in items or []:
        if "=" not in item:
            raise AnalysisError(f"malformed --box {item!r}: use NAME=LO,HI, e.g. t1=0,1/32")
        name, rng = (s.strip() for s in item.split("=", 1))
        if not name.isidentifier():
            raise AnalysisError(f"malformed --box {item!r}: {name!r} is not a parameter name")
        lo, hi = _parse_within(rng)
        if not (lo.is_finite and hi.is_finite):
            raise AnalysisError(f"--box {name} needs finite bounds")
        out[name] = (lo, hi)
    return out


def maximize_part(a, box: dict, arity: int, gap, budget: int, lines: list, data: dict) -> None:
    """Run the box maximisation (``budget`` in work units) and append its lines and JSON data."""
    import sympy as sp

    from ..regularity.maximize_box import maximize_holder_box

    m = maximize_holder_box(a, box, arity=arity, gap=gap, budget=budget)
    data["maximize"] = {"status": m.status, "maximiser": m.value, "alpha_lower_at_maximiser": m.lower,
                        "alpha_upper_on_box": m.upper, "gap": m.witness.get("gap"),
                        "exceptional": m.witness.get("exceptional"), "work": m.provenance.get("work"),
                        "message": m.provenance.get("message"), "timing": m.provenance.get("timing")}
    where = ", ".join(f"{k} in [{sp.sstr(lo)}, {sp.sstr(hi)}]" for k, (lo, hi) in box.items())
    if m.value is None or m.lower is None:
        lines.append(f"maximize holder: {m.status} ({m.provenance.get('message')})")
        return
    point = ", ".join(f"{k} = {sp.sstr(v)} (~{float(v):.8g})" for k, v in m.value.items())
    lines.append(f"smoothest member: {point}; alpha there >= {float(m.lower):.6f} (certified)")
    if m.upper is not None:
        lines.append(f"alpha <= {float(m.upper):.6f} on the whole box {where}: certified gap "
                     f"{float(m.witness['gap']):.2e} ({m.status}; {(m.provenance.get('timing') or {}).get('seconds')} s)"
                     + (f"; {m.provenance['message']}" if "message" in m.provenance else ""))
    for e in m.witness.get("exceptional") or []:
        if e.get("upper") is not None:
            lines.append(f"  exceptional {e['condition']} (more smoothing factors): alpha <= {float(e['upper']):.6f}"
                         + (f", maximiser {', '.join(f'{k} = {sp.sstr(v)}' for k, v in e['maximiser'].items())}"
                            if e.get("maximiser") else ""))
