"""One atlas sample of an m-ary family (issue 12): :func:`analysis.regularity.atlas.holder_atlas` with
``arity=m != 2`` evaluates its grid points here; the binary samples are untouched.

A sample is a certified enclosure of ``alpha = k - log_m JSR(T_0, ..., T_{m-1})``
(:func:`analysis.regularity.mary.holder_exponent_mary`) and the C^j verdicts: ``j > k`` is not C^j
(too few factors ``1+...+z^{m-1}``), ``alpha_lower > j`` is C^j, ``alpha_upper <= j`` is not, and
otherwise :func:`analysis.regularity.mary.smoothness_mary` decides (m-ary Dyn–Levin norm test, exact
spectral radii of short products, JSR bounds) or leaves it undecided (None).

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> s = evaluate_point_mary(LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)"), {}, 3, (2, 3))
>>> s["alpha"], s["C^2"], s["C^3"], s["status"]           # ternary cubic B-spline: alpha = 3
(3, True, False, 'certified')

Algorithm
---------
As :func:`analysis.regularity.atlas.evaluate_point` with the m-ary difference mask
``c = m^k a/q_m^(k+1)`` and the m-ary smoothing factor (exceptional parameter sets where ``q_m``
divides the symbol once more).

References
----------
O. Rioul, SIAM J. Math. Anal. 23 (1992); M. F. Hassan, I. P. Ivrissimitzis, N. A. Dodgson, M. A. Sabin,
Comput. Aided Geom. Design 19 (2002) 1-18.
"""

from __future__ import annotations

import time
from typing import Any, Mapping, Sequence

import sympy as sp

from ..algebra.mary import check_arity, smoothing_factor_mary
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError
from .mary import difference_mask_mary, holder_exponent_mary, smoothness_mary
from ..algebra.reader import as_expr

__all__ = ["evaluate_point_mary", "generic_k_mary", "exceptional_mary"]


def evaluate_point_mary(symbol: LaurentSymbol, values: Mapping[str, Any], m: int, j_levels: Sequence[int] = (1, 2, 3),
                        budget: int = 2_000) -> dict[str, Any]:
    """Certified alpha enclosure and C^j verdicts of the m-ary ``symbol.subs(values)`` (the keys of
    :func:`analysis.regularity.atlas.evaluate_point`; ``alpha_exact`` is None; ``budget`` in work
    units per JSR computation)."""
    m = check_arity(m)
    t0 = time.perf_counter()
    a = symbol.subs(dict(values)) if values else symbol
    sample: dict[str, Any] = {"alpha_lower": None, "alpha_upper": None, "alpha": None, "alpha_exact": None,
                              "k": None, "status": INCONCLUSIVE}
    h = k = None
    try:
        k, _ = difference_mask_mary(a, m)
        h = holder_exponent_mary(a, m, budget=budget)
    except AnalysisError as exc:
        sample["note"] = str(exc)
    if h is not None:
        sample.update(alpha_lower=h.lower, alpha_upper=h.upper, alpha=h.value, k=k)
    for j in j_levels:
        key = f"C^{j}"
        if h is None or k is None:
            sample[key] = None
        elif j > k:
            sample[key] = False
        elif h.lower is not None and h.lower > j:
            sample[key] = True
        elif h.upper is not None and h.upper <= j:
            sample[key] = False
        else:
            sample[key] = smoothness_mary(a, m, j, budget=budget).value
    decided = all(sample[f"C^{j}"] is not None for j in j_levels)
    sample["status"] = CERTIFIED if h is not None and h.status == CERTIFIED and decided else INCONCLUSIVE
    sample["timing"] = {"seconds": round(time.perf_counter() - t0, 4)}
    return sample


def generic_k_mary(symbol: LaurentSymbol, m: int) -> int | None:
    """``N - 1`` for the generic number ``N`` of factors ``(1+...+z^{m-1})/m`` of the family."""
    try:
        return int(smoothing_factor_mary(symbol, m, exceptional=False).value) - 1
    except (AnalysisError, TypeError, ValueError):  # pragma: no cover - defensive
        return None


def exceptional_mary(symbol: LaurentSymbol, m: int) -> list[dict]:
    """The exact parameter values with more factors than generic: ``[{"condition": {name: value}, "factors": N}]``."""
    try:
        f = smoothing_factor_mary(symbol, m)
    except AnalysisError:  # pragma: no cover - defensive
        return []
    return [{"condition": {str(k): as_expr(v) for k, v in c["condition"].items()}, "factors": c.get("k")}
            for c in f.witness.get("exceptional", [])]
