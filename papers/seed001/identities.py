"""Seed 001, exact symbolic identities of the NVPS shared by several claims (and by seed 000's):
the generation of exponentials (circles, hyperbolas, helices) by rules (2), (3), (6), and the
B-spline special case u = 1 compared with the catalogue.
"""

from __future__ import annotations

import functools

import sympy as sp

from analysis import claims as C
from analysis import nonuniform as nu

_Q, _S, _U, _Z = sp.symbols("q s u z")


def _s(x) -> str:
    return sp.sstr(x) if isinstance(x, sp.Basic) else str(x)


def _zero(expr) -> bool:
    """Exact: a rational function of the symbols is identically zero."""
    return sp.simplify(sp.together(sp.expand(expr))) == 0


@functools.lru_cache(maxsize=None)
def exponential_identities() -> dict:
    """Exact identities behind the reproduction claims (``q = e^{i phi}`` or ``e^{phi}``,
    ``u = (q + 1/q)/2`` = cos(phi) or cosh(phi), ``h = 1/(2(1+u))``):

    * ``geometric``: rule (3) maps the geometric sequence ``f_i = q^{2i}`` (a regular polygon of
      angle step 2 phi, or a hyperbolic one) to a geometric sequence of ratio ``q``:
      ``h + (1-h) q^2 = q ((1-h) + h q^2)``;
    * ``update``: ``sqrt((1+u)/2) = (s + 1/s)/2`` with ``q = s^2`` (u = cos phi -> cos(phi/2)), i.e.
      rule (2) gives the parameter of the halved step;
    * ``parametrization``: ``F(q) = ((1-h) + h q^2)(1+q)/(2q)`` is invariant under ``q -> 1/q``, so after
      one averaging (d >= 3) the new point 2i sits at parameter i + 1/2 for exponentials exactly as
      for linear data (helix: circle and linear component with one parametrization);
    * ``factor``: the rule-(3) symbol ``h z^-2 + (1-h) z^-1 + (1-h) + h z = h z^-2 (1+z)(z^2 + 2uz + 1)``,
      zeros -1 and ``-q^{+-1}``;
    * ``linear_d3``: for d = 3 linear data ``f_i = i`` go to ``i/2 + 1/4`` exactly for every h (d = 2 does
      not: ``f_{2i} = i + h``).

    >>> all(exponential_identities()[k] for k in ("geometric", "update", "parametrization", "factor", "linear_d3"))
    True
    """
    q, s, u, z = _Q, _S, _U, _Z
    uq = (q + 1 / q) / 2
    h = 1 / (2 * (1 + uq))
    out = {"geometric": _zero(h + (1 - h) * q ** 2 - q * ((1 - h) + h * q ** 2))}
    out["update"] = _zero(((s + 1 / s) / 2) ** 2 - (1 + (s ** 2 + s ** -2) / 2) / 2)
    F = ((1 - h) + h * q ** 2) * (1 + q) / (2 * q)
    out["parametrization"] = _zero(F - F.subs(q, 1 / q))
    hu = 1 / (2 * (1 + u))
    out["factor"] = _zero(hu / z ** 2 + (1 - hu) / z + (1 - hu) + hu * z - hu * (1 + z) * (z ** 2 + 2 * u * z + 1) / z ** 2)
    i, hh = sp.symbols("i h")
    f2i, f2i1, f2i2 = (1 - hh) * i + hh * (i + 1), hh * i + (1 - hh) * (i + 1), (1 - hh) * (i + 1) + hh * (i + 2)
    g0, g1 = (f2i + f2i1) / 2, (f2i1 + f2i2) / 2
    out["linear_d3"] = _zero(g0 - (i + sp.Rational(1, 2))) and _zero(g1 - (i + 1))
    out["linear_d2_fails"] = not _zero(f2i - (i + sp.Rational(1, 4)))
    return out


def exponential_evidence():
    ids = exponential_identities()
    res = C.exact_result(all(ids[k] for k in ("geometric", "update", "parametrization", "factor")),
                         "sympy rational-function identities in q = e^{i phi} / e^{phi}", **ids)
    return ids, C.Evidence(
        "Exact generation of exponentials (u = cos phi or cosh phi)", result=res,
        latex=r"h+(1-h)q^2=q\,((1-h)+hq^2),\quad \sqrt{(1+u)/2}=\frac{s+s^{-1}}{2}\ (q=s^2)",
        text=("rule (3) maps q^{2i} (angle step 2phi, parameter u = cos phi) to a geometric sequence of ratio q "
              "(step phi), and rule (2) gives cos(phi/2): a regular (or hyperbolic) polygon stays one at every "
              "level, so its limit is the circle (hyperbola); averaging (6) keeps geometric sequences geometric. "
              f"Identities: {ids}"))


def bspline_special_case(degrees=range(2, 8)):
    """u = 1: every location mask equals the uniform B-spline of degree d (exact, catalogue)."""
    from schemes import get
    rows, ok = [], True
    for d in degrees:
        M, start = nu.location_masks([1] * 6, degree=d, arithmetic="exact")
        L = nu.limit_mask(d)
        rows_ok = all(tuple(sp.nsimplify(c) for c in row) == tuple(L.mask) for row in M) and start == L.support[0]
        b = get(f"bspline-{d}").symbol
        cat_ok = L == b.shift(L.support[0] - b.support[0])
        ok &= rows_ok and cat_ok
        rows.append((str(d), " ".join(_s(c) for c in L.mask), f"[{L.support[0]}, {L.support[1]}]",
                     "yes" if rows_ok else "NO", "yes" if cat_ok else "NO"))
    table = (("d", "mask (u = 1)", "support", "all locations equal", "= catalogue bspline-d (shifted)"),) + tuple(rows)
    return ok, C.Evidence("u = 1: masks of the NVPS of degree d", table=table,
                          result=C.exact_result(ok, "exact sympy masks (analysis.nonuniform.location_masks, "
                                                    "arithmetic='exact') vs catalogue"),
                          latex=r"a(z)=z^{-d}\,(1+z)^{d+1}/2^{d}")

