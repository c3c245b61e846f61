"""Seed 001: M. Fang, B. Jeong, J. Yoon, *A non-uniform subdivision scheme with variable
parameters for curve design* (preprint, 17 pp.) — the NVPS of degree d and its claims.

The schemes are :class:`analysis.nonuniform.nvps.NVPS` objects (non-uniform: the mask depends on the
level and the location through the edge parameters), so they are **not** catalogue
``SchemeEntry`` objects (those hold one Laurent symbol). Their limit masks are the uniform
B-splines (catalogue ``bspline-d``, up to the shift ``z^{-d}`` vs the catalogue's centring).

``CLAIMS`` lists the paper's checkable statements, as printed (the text extraction garbled some
formulas; readings are noted), each with a function returning an :class:`analysis.result.Result`.

Examples
--------
>>> SCHEMES["nvps-2"]
NVPS(degree=2, rule='seed001')
>>> [c["id"] for c in CLAIMS][:3]
['001:(2)-(6)', '001:Lemma2.1', '001:(12)']
>>> check("001:(17)").status
'refuted'
"""

from __future__ import annotations

from typing import Callable

import sympy as sp

from analysis import nonuniform as nu
from analysis.result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, AnalysisError, Result

SOURCE = ("M. Fang, B. Jeong, J. Yoon, A non-uniform subdivision scheme with variable parameters for curve "
          "design (preprint), seed 001")

#: NVPS of degree 2..8 with seed 001's indexing and parameter inheritance (rules (2), (6), Algorithm 1).
SCHEMES = {f"nvps-{d}": nu.NVPS(d, "seed001") for d in range(2, 9)}


# --------------------------------------------------------------------------------------------
# one function per claim
# --------------------------------------------------------------------------------------------

def claim_rules() -> Result:
    """(2)-(6), Algorithm 1: the scheme as defined; compared with seed 000's definition."""
    rows = {d: nu.compare_definitions(d, levels=3) for d in range(2, 7)}
    ok = all(r.witness["one_step_equal_up_to_shift"] for r in rows.values())
    return Result(value={d: r.value for d, r in rows.items()}, status=CERTIFIED if ok else REFUTED,
                  witness={"per_degree": {d: r.to_json()["witness"] for d, r in rows.items()}},
                  provenance={"method": "exact rational refinement (analysis.nonuniform.nvps.compare_definitions)"})


def claim_lemma_2_1() -> Result:
    """Lemma 2.1: u^k -> 1 uniformly; ||U^k|| <= C max(1, ||U^0||). Checked on u^0 in [1/100, 100]."""
    return nu.lemma_2_1(sp.Rational(1, 100), 100)


def claim_12() -> Result:
    """(12): 2^k ||a_2^{k,j} - a_2|| = 2^{k-2} |1-u|/(1+u) (coefficient max-norm)."""
    r = nu.symbol_identities()
    ok = r.witness["(12)_identities_hold"]
    return Result(value=ok, status=CERTIFIED if ok else REFUTED, witness={"identity": "exact, generic u"},
                  provenance=r.provenance)


def claim_lemma_3_3() -> Result:
    """Lemma 3.3: sum_k 2^k max_j ||a_2^{k,j} - a_2|| < oo (and the ratio identity of its proof)."""
    b = nu.u_convergence_bound(sp.Rational(1, 100), 100)
    r = nu.symbol_identities()
    # ||a_2^{k,j} - a_2|| (coefficients) = |1-u|/(4(1+u)) <= C 4^-k / (4 (1 + 1/100)) for u0 >= 1/100
    C = float(b.upper)
    total = sum(2 ** k * C * 4.0 ** (-k) / (4 * (1 + 0.01)) for k in range(200)) * (1 + 1e-12)
    ok = b.status == CERTIFIED and r.witness["Lemma3.3_ratio_2(u/(1+u))^2_holds"]
    return Result(value=True, upper=total, status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"bound": "sum_k 2^k sup_j ||.|| <= sum_k 2^k C 4^-k / (4(1+min u)) = C/(2(1+min u))",
                           "C": b.witness["C_enclosure"], "u0_range": "[1/100, 100]",
                           "ratio_identity": r.witness["Lemma3.3_ratio_2(u/(1+u))^2_holds"]},
                  provenance={"method": "analytic bound + interval constants"})


def claim_corollary_3_4() -> Result:
    """Corollary 3.4: max_j ||a_2^{k,j} - a_2|| < c 2^-k. True, but the exact rate is 4^-k."""
    import mpmath

    u0 = [sp.Rational(1, 10), sp.Rational(1, 2), sp.Integer(2), sp.Integer(10)]
    r = nu.mask_decay(u0, degree=2, levels=14)
    # for every k >= 0 (analytic, Lemma 2.1's half-angle argument, constants enclosed rigorously):
    # upper: sup_j ||S^k - S_a|| <= 2 max_e |delta^k_e| = 2 max |1-u^k|/(4(1+u^k)) <= C' 4^-k / (2 (1 + 1/10))
    #        (u^k lies between u0 and 1, so 1 + u^k >= 11/10; C' from u_convergence_bound);
    # lower: u0 = 1/10 = cos(theta): 1 - u^k = 2 sin^2(theta/2^(k+1)) >= 2 theta^2/(pi^2 4^k) (sin x >= 2x/pi),
    #        |delta^k| >= (1 - u^k)/8, and a pure window attains c_2 |delta^k| (every window is pure for d = 2).
    b = nu.u_convergence_bound(min(u0), max(u0))
    upper_const = b.upper / (2 * (1 + min(u0))) if b.upper is not None else None
    c2 = nu._pure_constant(2)
    with mpmath.workprec(128):
        iv = mpmath.iv
        theta = nu._iv_acos(iv.mpf(1) / 10)
        low_iv = iv.mpf(c2.numerator) / c2.denominator * theta ** 2 / (4 * iv.pi ** 2)
    lower_const = nu._endpoint_rational(low_iv, "lower")
    levels = r.witness["levels"]
    consistent = upper_const is not None and all(
        sp.Rational(row["lower"]) * 4 ** row["k"] >= lower_const and sp.Rational(row["upper"]) * 4 ** row["k"]
        <= upper_const for row in levels)
    ok = r.status == CERTIFIED and b.status == CERTIFIED and lower_const > 0 and consistent
    return Result(value="true; rate Theta(4^-k)" if ok else "not settled", lower=r.lower, upper=r.upper,
                  status=CERTIFIED if ok else INCONCLUSIVE,
                  witness={"lower_constant": lower_const, "upper_constant": upper_const,
                           "bound": "lower_constant 4^-k <= sup_j ||S^k - S_a||_inf <= upper_constant 4^-k, every k >= 0",
                           "enclosures_consistent_with_bounds": consistent,
                           "certified_4k_bounds_levels_0_14": r.witness["certified_4k_bounds"],
                           "ratios": r.witness["ratios"], "scaled_4k_upper": r.witness["scaled_4k_upper"],
                           "ratios_note": "float quotients of consecutive upper enclosures (an observation)"},
                  provenance={**dict(r.provenance), "bounds": "analytic half-angle bounds, mpmath.iv constants "
                                                              "rounded outward to Rationals"})


def claim_16() -> Result:
    """(16): a_d^{k,j}(z) = ((z+1)/2)^{d-2} a_2^{k,j}(z). Holds where the d-1 degree-2 points of the
    window share one parameter; at a junction the mask is a mixture without the factor (1+z)^{d-1}."""
    import numpy as np

    z = sp.Symbol("z")
    M, start = nu.location_masks([sp.Rational(1, 2)] * 3 + [sp.Integer(3)] * 3, degree=4, arithmetic="exact")
    mixed = None
    for row in M:
        poly = sp.Poly(sum(c * z ** t for t, c in enumerate(row)), z)
        k = 0
        while poly.eval(-1) == 0 and k < 10:
            poly = sp.Poly(sp.cancel(poly.as_expr() / (1 + z)), z)
            k += 1
        if k < 3:
            mixed = {"mask": [str(c) for c in row], "start": start, "(1+z)_factors": k}
            break
    return Result(value="holds for locally constant parameters only", status=REFUTED if mixed else CERTIFIED,
                  witness={"counterexample_degree_4_junction": mixed,
                           "note": "with one parameter per window the identity is exact (limit_mask and "
                                   "location_masks agree); the printed (16) is stated for every location"},
                  provenance={"method": "exact sympy masks, u = 1/2 | 3"})


def claim_17() -> Result:
    """(17): a_2^{k,j}(1) = 1, a_2'(1) = 2, a_2''(1) = 1 (as printed)."""
    return nu.symbol_identities()


def claim_b_of_z() -> Result:
    """Proof of Theorem 3.6: b(z) = (1 + 2uz + z^2)/(z(1+u)), |b(-1)| = 2(1-u)/(1+u) = 8||a - a||."""
    r = nu.symbol_identities()
    ok = r.witness["b(z)_equals_printed"]
    return Result(value=r.witness["b(-1)"], status=CERTIFIED if ok else REFUTED,
                  witness={"b(-1)": r.witness["b(-1)"],
                           "note": "b(-1) = -2(1-u)/(1+u); |b(-1)| = 2|1-u|/(1+u) (the printed form drops the "
                                   "absolute value for u > 1) = 8 x the coefficient distance of (12)"},
                  provenance=r.provenance)


def claim_theorem_3_6(degrees=range(2, 7), levels: int = 16) -> Result:
    """Theorem 3.6: the NVPS of degree d generates C^{d-1} limit curves."""
    per = {}
    any_fail = False
    for d in degrees:
        table = nu.property_a_table(d)
        failing = [(x["m"], x["r"], x["z0"]) for x in table if x["fails_on_blended"]]
        js = nu.junction_smoothness(d, 0.3, 4.0, levels=levels)
        per[d] = {"property_A_fails_at(m,r,z0)": failing, "junction_(d-1)th_divided_differences": js.value,
                  "omega_last": js.witness["omega_junction"][-1]}
        any_fail |= js.value != "omega_k -> 0"
    return Result(value="C^{d-1} numerically false at junctions for d >= 4 (C^2 only); "
                        "proof step fails (certified) for d >= 4",
                  status=NUMERICAL,
                  witness={"per_degree": per,
                           "constant_parameters": "all Property A quantities vanish identically (certified) and "
                                                  "the scheme is asymptotically equivalent to the B-spline "
                                                  "(certified): the theorem's route is valid there",
                           "proof_gap": "the proof uses u^k -> 1 at rate 2^-k and 'n-th differences of h_k are "
                                        "O(2^-kn)'; h_k is piecewise constant in j with jumps Theta(4^-k) at "
                                        "junctions, so every n-th difference there is Theta(4^-k)",
                           "blended_data_fail": any_fail},
                  provenance={"method": "exact Property A structure + mpmath divided differences (windowed)",
                              "levels": levels, "u": "0.3 | 4.0"})


def claim_reproduction() -> Result:
    """Sect. 2/4: NVPS reproduces conics (circles with u = cos), hyperbolic curves (u = cosh),
    polynomial B-spline pieces (u = 1)."""
    out = {}
    for kind in ("circle", "hyperbola", "parabola"):
        for d in (2, 3, 4):
            r = nu.reproduce(kind, degree=d, levels=8)
            out[f"{kind}-d{d}"] = {"deviation_level_8": r.witness["deviation"][-1],
                                   "form_error_level_8": r.witness["form_error"][-1],
                                   "rate_last": r.witness["rate"][-1]}
    ok = all((v["form_error_level_8"] < 1e-12) or k.startswith("parabola") for k, v in out.items())
    return Result(value="reproduced (exact up to rounding)" if ok else "not reproduced", status=NUMERICAL,
                  witness=out, provenance={"method": "float64; closed-form limit radius"})


def claim_chamfer() -> Result:
    """Algorithm 2 / Fig. 3: chamfering the quadrangle ABCD with radii 3.650669, 2, 1, 1.691966."""
    r = nu.chamfer_example(levels=8)
    return Result(value=r.witness["midpoint_deviation"][-1], status=NUMERICAL, witness=r.witness,
                  provenance=r.provenance)


CLAIMS: list[dict] = [
    {"id": "001:(2)-(6)", "statement": "u^{k+1}_{2i} = sqrt((1+u^k_i)/2), u^{k+1}_{2i+1} = sqrt((1+u^k_{i+1})/2); "
     "P_{2i} = (1+2u)/(2(1+u)) P_i + 1/(2(1+u)) P_{i+1}, ...; (S_d P)_i = ((S_{d-1}P)_i + (S_{d-1}P)_{i+1})/2",
     "check": claim_rules},
    {"id": "001:Lemma2.1", "statement": "u^k_n converges to 1 uniformly in n; ||U^k|| <= C max(1, ||U^0||)",
     "check": claim_lemma_2_1},
    {"id": "001:(12)", "statement": "E^k_j = 2^k max(|1/(2(1+u)) - 1/4|, |(1+2u)/(2(1+u)) - 3/4|) = 2^{k-2}|1-u|/(1+u)",
     "check": claim_12},
    {"id": "001:Lemma3.3", "statement": "sum_k 2^k max_j ||a_2^{k,j} - a_2|| < oo", "check": claim_lemma_3_3},
    {"id": "001:Corollary3.4", "statement": "max_j ||a_2^{k,j} - a_2|| < c 2^-k", "check": claim_corollary_3_4},
    {"id": "001:(16)", "statement": "a_d^{k,j}(z) = ((z+1)/2)^{d-2} a_2^{k,j}(z)", "check": claim_16},
    {"id": "001:(17)", "statement": "a_2^{k,j}(1) = 1, d/dz a_2^{k,j}(1) = 2, d^2/dz^2 a_2^{k,j}(1) = 1",
     "check": claim_17},
    {"id": "001:b(z)", "statement": "b^{k,j}(z) = (1 + 2u z + z^2)/(z(1+u)); |b(-1)| = 2(1-u)/(1+u) = 8||a^{k,j} - a||",
     "check": claim_b_of_z},
    {"id": "001:Theorem3.6", "statement": "The NVPS scheme of degree d with d > 1 generates C^{d-1}-continuous "
     "limit curves.", "check": claim_theorem_3_6},
    {"id": "001:reproduction", "statement": "It can reproduce the curves such as conics, trigonometric curves and helix.",
     "check": claim_reproduction},
    {"id": "001:Algorithm2", "statement": "chamfering: arc of radius r_A tangent to both edges generated from P1 A P2",
     "check": claim_chamfer},
]

_BY_ID: dict[str, Callable[[], Result]] = {c["id"]: c["check"] for c in CLAIMS}


def check(claim_id: str) -> Result:
    """Evaluate one claim by id."""
    try:
        return _BY_ID[claim_id]()
    except KeyError:
        raise AnalysisError(f"unknown claim {claim_id!r}; seed 001 has {', '.join(_BY_ID)}") from None


# ============================================================================================
# The paper's claims (proof-check): PAPER = Paper(...), evaluated by `subdiv report 001`.
# Each claim keeps the statement as printed (the extraction garbled sub/superscripts and
# fraction bars); the reading says how it was read. Verdicts come from the engine (the
# ``claim_*`` functions above and the exact identities below), never typed in.
# ============================================================================================

import functools  # noqa: E402
import math  # noqa: E402

import numpy as np  # noqa: E402

from analysis import claims as C  # noqa: E402
from analysis.jsonable import roundoff_text, stable_float  # noqa: E402

_Q, _S, _U, _Z = sp.symbols("q s u z")
_GARBLED = ("The text extraction flattened sub/superscripts and fraction bars (e.g. 'uk+12i' is "
            "u^{k+1}_{2i}); ")
_CMD = "subdiv report 001 --claim '{}'"


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


def _exp_evidence():
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


def _bspline_special_case(degrees=range(2, 8)):
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
    table = (("d", "mask (u = 1)", "support", "all locations equal", f"= catalogue bspline-d (shifted)"),) + tuple(rows)
    return ok, C.Evidence("u = 1: masks of the NVPS of degree d", table=table,
                          result=C.exact_result(ok, "exact sympy masks (analysis.nonuniform.nvps.location_masks, "
                                                    "arithmetic='exact') vs catalogue"),
                          latex=r"a(z)=z^{-d}\,(1+z)^{d+1}/2^{d}")


def _verdict_from(res, summary_true, summary_false, corrected=None, **kw):
    """A certified Result -> certified verdict; a refuted Result -> refuted (needs ``corrected``)."""
    ev = [C.Evidence("engine result", result=res, text=_s(res.value)[:300])] + list(kw.pop("evidence", []))
    if res.status == "certified":
        return C.certified(summary_true, evidence=ev, **kw)
    if res.status == "refuted":
        return C.refuted(summary_false, corrected=corrected or summary_false, evidence=ev, **kw)
    return C.inconclusive(summary_false, settle="see the engine result", evidence=ev, **kw)


# -------------------------------------------------------------------------- Sect. 1/2 claims
def _v_special_cases():
    ok, ev = _bspline_special_case()
    ids, ev2 = _exp_evidence()
    nums = [C.Number("degrees_checked", 6)]
    if ok and ids["factor"] and ids["geometric"]:
        return C.certified(
            "True. u = 1 gives exactly the uniform B-spline of degree d at every location (d = 2..7, exact masks "
            "= catalogue bspline-d up to a shift); equal parameters give a uniform level-dependent scheme with "
            "symbol ((1+z)/2)^(d-2) h z^-2 (1+z)(z^2 + 2u^k z + 1), which generates 1, ..., t^(d-2) and "
            "e^(+-i w t) / e^(+-w t) exactly: the generalized B-spline spaces of Fang-Ma-Wang (2010).",
            sharpness="The identification with the exact rule text of Fang-Ma-Wang (2010) is not replayed here "
                      "(see 001:Remark1); the B-spline case is exact.",
            evidence=[ev, ev2], numbers=nums)
    return C.refuted("u = 1 does not give the B-spline", "see the table", evidence=[ev, ev2], numbers=nums)


def _v_chaikin():
    ok, ev = _bspline_special_case(degrees=[2])
    fixed = sp.sqrt((1 + sp.Integer(1)) / 2) == 1
    res = C.exact_result(fixed, "sqrt((1+1)/2) = 1 exactly")
    ev2 = C.Evidence("u = 1 is a fixed point of the update (2)", result=res)
    if ok and fixed:
        return C.certified("True: u = 1 is a fixed point of (2) (so the scheme is stationary) and (3) becomes "
                           "P_2i = 3/4 P_i + 1/4 P_i+1, P_2i+1 = 1/4 P_i + 3/4 P_i+1, Chaikin's mask [1,3,3,1]/4.",
                           evidence=[ev, ev2])
    return C.refuted("not Chaikin", "see evidence", evidence=[ev, ev2])


def _v_mask_4():
    u = _U
    h = 1 / (2 * (1 + u))
    # rule (3): P_2i = (1+2u)/(2(1+u)) P_i + 1/(2(1+u)) P_i+1 ; with (1): P_n = sum_i a_{n-2i} P_i
    even = {0: (1 + 2 * u) / (2 * (1 + u)), -1: 1 / (2 * (1 + u))}    # a_{2i-2i}, a_{2i-2(i+1)}
    odd = {1: 1 / (2 * (1 + u)), -1: (1 + 2 * u) / (2 * (1 + u))}
    printed = [h, 1 - h, 1 - h, h]         # reading of (4): {1/(2(1+u)), (1+2u)/(2(1+u)), ..., 1/(2(1+u))}
    # P_2i uses a_0 (P_i) and a_-2 (P_i+1); P_2i+1 uses a_1 (P_i) and a_-1 (P_i+1)
    even2 = {0: even[0], -2: even[-1]}
    full = {-2: even2[-2], -1: odd[-1], 0: even2[0], 1: odd[1]}
    derived = [full[k] for k in (-2, -1, 0, 1)]
    ok = all(_zero(a - b) for a, b in zip(derived, printed))
    sums = [sp.simplify(full[-2] + full[0]), sp.simplify(full[-1] + full[1])]
    res = C.exact_result(ok, "sympy, generic u", mask=[_s(sp.simplify(x)) for x in derived])
    ev = [C.Evidence("mask of rule (3) in the convention (1) P_n = sum_i a_{n-2i} P_i", result=res,
                     table=(("exponent", "from rule (3)", "reading of (4)/(9)"),) + tuple(
                         (str(k), _s(sp.simplify(full[k])), _s(sp.simplify(p))) for k, p in zip((-2, -1, 0, 1), printed))),
          C.Evidence("sub-mask sums", text=f"even: {_s(sums[0])}, odd: {_s(sums[1])} (both 1 for every u)")]
    if ok and all(x == 1 for x in sums):
        return C.certified("True (with 'u^k_k' read as u^k_j): the mask of rule (3) is {h, 1-h, 1-h, h}, "
                           "h = 1/(2(1+u^k_j)), at exponents -2..1; each sub-mask sums to 1.", evidence=ev)
    return C.refuted("(4) differs from rule (3)", "the mask in the table", evidence=ev)


def _v_positivity():
    u = sp.Symbol("u", positive=True)
    phi = sp.sqrt((1 + u) / 2)
    lower = sp.simplify(phi - sp.sqrt(2) / 2)     # > 0 for u > 0
    ok = bool(sp.simplify(phi ** 2 - (1 + u) / 2) == 0) and sp.ask(sp.Q.positive(phi ** 2 - sp.Rational(1, 2)),
                                                                     sp.Q.positive(u)) is True
    res = C.exact_result(ok, "sympy: phi(u)^2 - 1/2 = u/2 > 0 for u > 0", phi=phi, phi_minus_1_over_sqrt2=lower)
    if ok:
        return C.certified("True: phi(u) = sqrt((1+u)/2) > 1/sqrt(2) > 0 for u > 0, so by induction u^k_n > 0 "
                           "(in fact > 1/sqrt(2) for k >= 1).", evidence=[C.Evidence("phi(u) > 0", result=res)])
    return C.inconclusive("could not decide", settle="a proof of phi(u) > 0", evidence=[C.Evidence("phi", result=res)])


def _v_lemma_2_1():
    r = claim_lemma_2_1()
    b = nu.u_convergence_bound(sp.Rational(1, 100), 100)
    ev = [C.Evidence("Lemma 2.1 on u0 in [1/100, 100] (C = 1)", result=r, text=str(dict(r.witness))[:400]),
          C.Evidence("rate: sup_n |1 - u^k_n| <= C' 4^-k", result=b, text=f"C' enclosure {b.witness['C_enclosure']}; "
                     f"4^k(1 - u^k) -> acos(u0)^2/2 or -acosh(u0)^2/2")]
    nums = [C.Number("C", r.value), C.Number("rate_constant_u0_in_[1/100,100]", b.upper, tol=1e-9)]
    if r.status == "certified" and b.status == "certified":
        return C.certified("True with C = 1: ||U^k|| <= max(1, ||U^0||) for every k, and u^k_n -> 1 uniformly, at "
                           "the rate 4^-k (certified on u0 in [1/100, 100]; the monotonicity argument of "
                           "phi(u) = sqrt((1+u)/2) holds for every u0 > -1).",
                           sharpness="The rate is 4^-k (1 - u^k = 2 sin^2(theta/2^(k+1)) for u0 = cos theta), not "
                                     "the 2^-k used later in the proof of Theorem 3.6.",
                           evidence=ev, numbers=nums)
    return C.inconclusive("the interval check did not close", settle="more precision / levels", evidence=ev, numbers=nums)


def _v_rules():
    r = claim_rules()
    ev = [C.Evidence("(6) unrolled vs the binomial form, and seed 000's definition (exact)", result=r,
                     table=(("d", "seed 000 vs 001"),) + tuple((str(d), v) for d, v in r.value.items()))]
    sym_ok = all(w["symbolic_recursion_equals_binomial"] for w in r.witness["per_degree"].values())
    ok, ev_b = _bspline_special_case()
    if r.status == "certified" and sym_ok and ok:
        return C.certified("True: (6) unrolled is (S_d P)_i = 2^(2-d) sum_l binom(d-2, l) (S_2 P)_(i+l), with "
                           "2(n-1) - (d-2) new points; with u = 1 it is the uniform B-spline of degree d (the "
                           "Lane-Riesenfeld algorithm) -- the classical B-spline subdivision is the special case u = 1.",
                           evidence=ev + [ev_b])
    return C.refuted("(6) is not the binomial average", "see evidence", evidence=ev + [ev_b])


def _algorithm1_sources(n: int, d: int) -> list[int]:
    """Old edge index of each new parameter by Algorithm 1, step (3), as printed (recursive)."""
    if d == 2:                       # rule (2): u_2i <- u_i, u_2i+1 <- u_i+1
        return [(j + 1) // 2 for j in range(2 * n - 1)]
    if d == 3:
        out = [None] * (2 * n - 2)
        out[0], out[2 * n - 3] = 0, n - 1
        for i in range(0, n - 2):
            out[2 * i + 1] = out[2 * i + 2] = i + 1
        return out
    prev = _algorithm1_sources(n, d - 2)
    return [prev[j + 1] for j in range(2 * n - d + 1)]


def _v_algorithm_1():
    rows, ok = [], True
    for d in range(2, 10):
        for n in range(max(3, d), 16):
            a1 = _algorithm1_sources(n, d)
            eng = [int(x) for x in nu._sources(np.arange(2 * n - d + 1), d, False, "seed001", n)]
            good = a1 == eng and None not in a1 and len(a1) == 2 * n - d + 1
            ok &= good
            if n == max(3, d) or not good:
                rows.append((str(d), str(n), " ".join(map(str, a1)), " ".join(map(str, eng)), "yes" if good else "NO"))
    res = C.exact_result(ok, "integer index computation, d = 2..9, n = d..15")
    ev = [C.Evidence("new edge j <- old edge (Algorithm 1 step (3) vs engine ceil((j + floor((d-2)/2))/2))",
                     result=res, table=(("d", "n", "Algorithm 1", "engine", "agree"),) + tuple(rows))]
    if ok:
        return C.certified("True under the reading: both cases of step (3) give 2n - d + 1 parameters, new edge j "
                           "inheriting (then updated by (2)) the parameter of old edge ceil((j + floor((d-2)/2))/2); "
                           "for d = 2 this is rule (2).", evidence=ev, numbers=[C.Number("cases_checked", 8)])
    return C.refuted("Algorithm 1 disagrees with the engine", "see table", evidence=ev)


def _v_12():
    r = claim_12()
    return _verdict_from(r, "True (exact identity for every u > 0, reading the lost bars as |1 - u^k_j|).",
                         "(12) fails", corrected="see evidence")


def _v_equivalence():
    """Sect. 3.1: {a^{k,j}} ~ B-spline of degree d (Definition 3.1), certified bound on the series."""
    b = nu.u_convergence_bound(sp.Rational(1, 100), 100)
    C_up = sp.Rational(str(b.upper)) if b.upper is not None else None
    # sup_j ||S^k - S_a|| <= 2 max_e |delta^k_e|,  |delta| = |v|/(4(1+u)) <= C' 4^-k / (4 (1 + 1/100))
    total = 2 * C_up * sp.Rational(4, 3) / (4 * (1 + sp.Rational(1, 100)))
    dec = nu.mask_decay([sp.Rational(1, 2)] * 4 + [3] * 4, degree=4, levels=10)
    ev = [C.Evidence("rate of u^k -> 1 on u0 in [1/100, 100]", result=b),
          C.Evidence("sum_k sup_j ||S^k - S_a||_inf <= sum_k 2 C' 4^-k / (4 (1 + 1/100))",
                     result=C.exact_result(total, "exact geometric series with the certified C'"),
                     text=f"<= {_s(total)} ~ {float(total):.4f}; the engine's bound sup_j ||S^k - S_a|| <= "
                          "2 max_e |h_e - 1/4| holds for every degree d (mask_decay)"),
          C.Evidence("sup_j ||S^k - S_a|| for d = 4, u0 = 1/2 | 3 (certified enclosures)", result=dec,
                     text="ratios of consecutive levels: " + ", ".join(f"{x:.5f}" for x in dec.witness["ratios"][-3:]))]
    if b.status == "certified" and dec.status == "certified":
        return C.certified("True: the NVPS of degree d is asymptotically equivalent (Definition 3.1) to the uniform "
                           "B-spline of degree d (the paper says 'order d'; it uses order for degree): "
                           f"sum_k sup_j ||S^k - S_a|| <= {_s(total)} for every u0 in [1/100, 100]; the terms decay "
                           "like 4^-k.", evidence=ev,
                           numbers=[C.Number("series_bound", total, tol=1e-9),
                                    C.Number("ratio_d4_last", dec.witness["ratios"][-1], tol=1e-4)])
    return C.inconclusive("bound not certified", settle="interval arithmetic at higher precision", evidence=ev)


def _v_lemma_3_2():
    ev = _v_equivalence().evidence
    return C.inconclusive(
        "A cited result (Dyn-Levin-Yoon 2007, Lemma 2.5), not proved in the paper; its hypotheses hold for the "
        "NVPS: asymptotic equivalence to the B-spline of degree d is certified (001:Sect3.1), and the B-spline "
        "scheme is stable and C^0.",
        settle="the cited proof: DLY 2007 (SIAM J. Math. Anal. 39) treats non-stationary schemes; the non-uniform "
               "version is in Dyn-Levin-Yoon 2014 (Constr. Approx. 40), which should be cited instead.",
        evidence=ev)


def _v_lemma_3_3():
    r = claim_lemma_3_3()
    b = nu.u_convergence_bound(sp.Rational(1, 100), 100)
    C_up = sp.Rational(str(b.upper))
    total = C_up * 2 / (4 * (1 + sp.Rational(1, 100)))     # sum_k 2^k C' 4^-k / (4(1 + min u))
    ev = [C.Evidence("rate constant", result=b),
          C.Evidence("sum_k 2^k max_j ||a_2^{k,j} - a_2|| <= sum_k 2^k C' 4^-k / (4 (1 + 1/100))",
                     result=C.exact_result(total, "exact geometric series"), text=f"<= {_s(total)}"),
          C.Evidence("ratio identity of the proof: E^k/E^(k-1) = 2 (u/(1+u))^2 -> 1/2",
                     result=C.exact_result(r.witness["ratio_identity"], "sympy, generic u"))]
    if r.status == "certified" and r.witness["ratio_identity"]:
        return C.certified(f"True (the printed sum over k in Z means k >= 0): the series is <= {_s(total)} for "
                           "u0 in [1/100, 100]; the proof's ratio identity 2(u/(1+u))^2 holds exactly.",
                           sharpness="The terms are Theta(2^-k) (masks converge like 4^-k), so even "
                                     "sum_k 4^k max_j ||.|| diverges only logarithmically-free: sum 2^(mk) converges "
                                     "for m < 2 only.",
                           evidence=ev, numbers=[C.Number("series_bound", total, tol=1e-9)])
    return C.inconclusive("not certified", settle="see evidence", evidence=ev)


def _v_corollary_3_4():
    r = claim_corollary_3_4()
    w = r.witness
    ev = [C.Evidence("sup_j ||S^k - S_a||, u0 = 1/10, 1/2, 2, 10 (d = 2): analytic bounds for every k and certified "
                     "enclosures for k = 0..14", result=r,
                     text=f"{_s(w['lower_constant'])} 4^-k <= sup_j ||S^k - S_a|| <= {_s(w['upper_constant'])} 4^-k "
                          f"(every k >= 0); the enclosures of k = 0..14 lie within these bounds: "
                          f"{w['enclosures_consistent_with_bounds']}; float ratios of consecutive upper enclosures "
                          "(observation): " + ", ".join(f"{x:.6f}" for x in w["ratios"][-3:]))]
    nums = [C.Number("lower_constant", w["lower_constant"]), C.Number("upper_constant", w["upper_constant"]),
            C.Number("ratio_last", w["ratios"][-1], tol=1e-6),
            C.Number("scaled_4k_last", w["scaled_4k_upper"][-1], tol=1e-6)]
    if r.status == CERTIFIED:
        return C.certified("True, but not sharp: c1 4^-k <= max_j ||a_2^{k,j} - a_2|| <= c2 4^-k for every k >= 0 "
                           f"(c1 = {float(w['lower_constant']):.4g}, c2 = {float(w['upper_constant']):.4g}, certified "
                           "for u0 in {1/10, 1/2, 2, 10}; the upper bound holds for all u0 in [1/10, 10]), i.e. "
                           "Theta(4^-k); the float ratios of consecutive levels are close to 1/4.",
                           sharpness="c 4^-k holds (Lemma 2.1's half-angle rate); the stated c 2^-k is weaker.",
                           evidence=ev, numbers=nums)
    return C.inconclusive("the bounds were not certified", settle="interval arithmetic at higher precision",
                          evidence=ev, numbers=nums)


def _v_16():
    r = claim_16()
    cx = r.witness["counterexample_degree_4_junction"]
    ev = [C.Evidence("degree 4, u = 1/2 | 3: a junction mask", result=r,
                     text=f"mask {cx['mask'] if cx else None}, (1+z)-factors {cx['(1+z)_factors'] if cx else None} "
                          "(the B-spline-like (16) would have >= 3)")]
    if r.status == "refuted":
        return C.refuted("False at junctions: where the d-1 degree-2 points averaged by (6) carry different "
                         "parameters, the mask of (6) is a mixture of a_2 masks and has fewer than d-1 factors (1+z).",
                         corrected="a_d^{k,j}(z) = 2^(2-d) sum_l binom(d-2, l) z^(-l) a_2^{k, e(j+l)}(z); it equals "
                                   "((z+1)/2)^(d-2) a_2^{k,j}(z) only where the parameters of the window agree "
                                   "(e.g. for constant parameters).",
                         evidence=ev, numbers=[C.Number("junction_(1+z)_factors_d4", cx["(1+z)_factors"])])
    return C.certified("(16) holds", evidence=ev)


def _v_17():
    r = claim_17()
    w = r.witness
    ev = [C.Evidence("(11) at z = 1", result=r, latex=r"a_2(z)=\frac{1+(1+2u)z+(1+2u)z^2+z^3}{2(1+u)z}",
                     table=(("quantity", "printed", "exact"),) + tuple(
                         (k, str(w["printed_(17)"][k]), w["exact"][k]) for k in ("a(1)", "a'(1)", "a''(1)")))]
    nums = [C.Number("a(1)", sp.sympify(w["exact"]["a(1)"])), C.Number("a'(1)", sp.sympify(w["exact"]["a'(1)"])),
            C.Number("a''(1)", w["exact"]["a''(1)"])]
    exact = "; ".join(f"{k} = {w['exact'][k]}" for k in ("a(1)", "a'(1)", "a''(1)"))
    if r.status == REFUTED:
        wrong = [k for k, bad in w["differs_from_printed"].items() if bad]
        return C.refuted(f"False (exact, generic u): {exact}; printed values differ for {', '.join(wrong)} "
                         "(a(1) and a'(1) for every u; a''(1) = 2/(1+u) equals the printed 1 only at u = 1).",
                         corrected="a_2^{k,j}(1) = " + w["exact"]["a(1)"] + ", (d/dz) a_2^{k,j}(1) = "
                                   + w["exact"]["a'(1)"] + ", (d^2/dz^2) a_2^{k,j}(1) = "
                                   + w["exact"]["a''(1)"].replace("u", "u^k_j"),
                         evidence=ev, numbers=nums)
    if r.status == CERTIFIED:
        return C.certified(f"True (exact, generic u): {exact}.", evidence=ev, numbers=nums)
    return C.inconclusive("the values were not settled", settle="see evidence", evidence=ev, numbers=nums)


def _v_b_of_z():
    r = claim_b_of_z()
    return _verdict_from(r, "True: b(z) = 2 a_2(z)/(1+z) = (1 + 2uz + z^2)/(z(1+u)) and |b(-1)| = 2|1-u|/(1+u) "
                            "= 8 x the coefficient distance (12) (the printed form drops the absolute value).",
                         "b(z) differs", corrected="see evidence",
                         numbers=[C.Number("b(-1)", sp.sympify(r.witness["b(-1)"]))])


def _v_support():
    rows, ok = [], True
    for d in range(2, 8):
        M, start = nu.location_masks([sp.Rational(1, 2)] * 3 + [sp.Integer(3)] * 3, degree=d, arithmetic="exact")
        width = M.shape[1]
        nz = all(any(c != 0 for c in M[:, t]) for t in range(width))
        L = nu.limit_mask(d)
        ok &= width == len(L.mask) and nz
        rows.append((str(d), str(width), str(len(L.mask)), str(d + 1)))
    res = C.exact_result(ok, "exact masks (u = 1/2 | 3) and the B-spline limit")
    ev = [C.Evidence("mask lengths", result=res, table=(("d", "NVPS mask length", "B-spline degree d", "#(Z ∩ [0, d])"),)
                     + tuple(rows))]
    return C.refuted("Half true: the NVPS mask of degree d has the support of the B-spline of degree d (d + 2 "
                     "coefficients at every level and location), but Z ∩ [0, n] - ceil(n/2) with n = d has only d + 1 "
                     "points.",
                     corrected="supp(a^{k,j}) = Z ∩ [0, d+1] - shift (d + 2 coefficients; [-d, 1] in the convention "
                               "P^{k+1}_n = sum_i a_{n-2i} P^k_i), the support of the B-spline of degree d",
                     evidence=ev, numbers=[C.Number("mask_length_d4", 6)])


def _v_property_a_def():
    rows = []
    for d in (2, 3, 4):
        for m in range(1, d):
            for r_ in range(m):
                for z0 in (1, -1):
                    res = nu.property_a_structure(d, m, r_, z0)
                    rows.append((str(d), str(m), str(r_), f"{z0:+d}", res.value))
    const_ok = all(x[4] in ("identically zero", "nonzero at junctions") for x in rows)
    ev = [C.Evidence("d^(r)_m(+-1) of (14) for the NVPS (exact linear forms in delta_e = h_e - 1/4)",
                     result=C.exact_result(const_ok, "analysis.nonuniform.nvps.property_a_structure"),
                     table=(("d", "m", "r", "z0", "structure"),) + tuple(rows))]
    return C.inconclusive(
        "A definition quoted from Dyn-Levin-Yoon (2014); as extracted, (14) reads d_m(z) = sum_i (-1)^i binom(m,i) "
        "z^i a^{j-i,k}(z) ('pj-i,k' is the garbled mask). Nothing to prove; its NVPS quantities vanish identically "
        "for constant parameters and are non-zero only at parameter junctions (exact).",
        settle="compare (13)-(14) with Property A in DLY 2014, Constr. Approx. 40 (not in the corpus); (19) in the "
               "proof of Theorem 3.6 writes O(2^(-k(n-l))) where (13) has o(2^(-k(m-r))).",
        evidence=ev)


def _v_theorem_3_5():
    ok, ev = _bspline_special_case(degrees=range(2, 8))
    return C.inconclusive(
        "A cited theorem (Dyn-Levin-Yoon 2014), not proved in the paper ('where m is the mask' is a garble of "
        "'where a is the mask'). Its stationary hypothesis holds for the NVPS: the limit scheme is the B-spline "
        "of degree d (exact), C^(d-1) with a stable basic limit function.",
        settle="the cited source's statement (DLY 2014, Constr. Approx. 40, 173-188).", evidence=[ev])


def _v_19():
    rows, fails = [], {}
    for d in range(2, 7):
        t = nu.property_a_table(d)
        f = [(x["m"], x["r"], x["z0"]) for x in t if x["fails_on_blended"]]
        fails[d] = f
        rows.append((str(d), str(len(t)), ", ".join(f"(m={m}, r={r}, z={z:+d})" for m, r, z in f) or "none"))
    res = C.exact_result(fails, "exact linear forms (property_a_structure) x |delta_B - delta_A| >= c 4^-k")
    ev = [C.Evidence("Property A quantities that do not vanish identically, and those that violate o(2^(-k(m-r))) "
                     "at a junction", result=res,
                     table=(("d", "# non-vanishing (m, r, z0)", "violating at junctions"),) + tuple(rows),
                     text="At a junction between parameters A and B the quantity equals kappa (delta_B^k - delta_A^k) "
                          "with kappa != 0 exact and |delta_B^k - delta_A^k| >= c 4^-k (4^k v^k is monotone in k: "
                          "increasing to theta^2/2 for u0 = cos theta, decreasing for cosh), so for m - r >= 2 "
                          "2^(k(m-r)) |d^(r)_m| does not tend to 0.")]
    d4 = fails[4]
    if d4:
        return C.refuted("False for d >= 4 with non-constant parameters: Property A of order 3 fails at parameter "
                         f"junctions, e.g. (m, r, z0) = {d4[0]} for d = 4; it holds (all quantities vanish) for "
                         "constant parameters, and for d = 2, 3 every quantity is o(2^(-k(m-r))).",
                         corrected="(19) holds for d <= 3, and for every d when the parameters are constant "
                                   "(generalized subdivision); for d >= 4 and blended parameters, Property A holds "
                                   "only up to order 2 at the junctions (quantities Theta(4^-k)).",
                         evidence=ev, numbers=[C.Number("d4_violations", len(d4)),
                                               C.Number("d6_violations", len(fails[6]))])
    return C.certified("(19) holds", evidence=ev)


def _v_theorem_3_6():
    r = claim_theorem_3_6()
    per = r.witness["per_degree"]
    js2 = nu.junction_smoothness(4, 0.3, 4.0, levels=16, order=2)
    ev = [C.Evidence("per degree: Property A violations (exact) and (d-1)-th divided differences at a junction "
                     "u = 0.3 | 4 (mpmath)", result=r,
                     table=(("d", "Property A fails at (m, r, z0)", "(d-1)-th divided differences", "omega_16"),)
                     + tuple((str(d), str(v["property_A_fails_at(m,r,z0)"]), v["junction_(d-1)th_divided_differences"],
                              f"{v['omega_last']:.3e}") for d, v in per.items())),
          C.Evidence("d = 4, second divided differences at the same junction", result=js2,
                     text=f"{js2.value}: last omega_k " + ", ".join(f"{x:.3e}" for x in js2.witness["omega_junction"][-3:]))]
    nums = [C.Number("omega_d2", per[2]["omega_last"], tol=1e-6), C.Number("omega_d4", per[4]["omega_last"], tol=0.02),
            C.Number("omega_d4_order2", js2.witness["omega_junction"][-1], tol=1e-5)]
    return C.Verdict(
        "numerical",
        "Numerically false for d >= 4 with blended parameters: at a junction (u = 0.3 | 4) the third divided "
        "differences of the d = 4 limit do not converge (omega_k -> 1.13, a jump of the 3rd derivative), while the "
        "second ones do (C^2). d = 2, 3 behave as claimed. The proof's step fails (certified, see 001:(19)): it "
        "uses u^k -> 1 at rate 2^-k and n-th differences O(2^-kn), but h_k jumps by Theta(4^-k) at junctions.",
        evidence=ev, numbers=nums,
        sharpness="For constant parameters (generalized subdivision) all Property A quantities vanish and the theorem's "
                  "route is valid.")


# -------------------------------------------------------------------------- Sect. 4 examples, figures
def _blended_figure(name: str, rule: str, degrees=(2, 3, 4), levels: int = 6) -> C.Figure:
    P0, _, _ = nu.blended_example(2, rule)
    series = [C.Series("control polygon (d = 2)", tuple(map(float, P0[:, 0])), tuple(map(float, P0[:, 1])), "o--")]
    for d in degrees:
        P, u, _ = nu.blended_example(d, rule)
        r = nu.refine(P, u, degree=d, steps=levels, rule=rule)
        series.append(C.Series(f"NVPS degree {d}", tuple(map(float, r.points[:, 0])), tuple(map(float, r.points[:, 1]))))
    return C.Figure(name, f"Blended curve ({rule} rules): circle arc (u = cos), line (u = 1), hyperbola (u = cosh)",
                    tuple(series), xlabel="x", ylabel="y", equal_aspect=True)


def _chamfer_figure(levels: int = 7) -> C.Figure:
    P, u, arcs = nu.chamfer_polygon(nu.CHAMFER_QUADRANGLE, nu.CHAMFER_RADII)
    r = nu.refine(P, u, degree=2, steps=levels, closed=True)
    Q = np.vstack([nu.CHAMFER_QUADRANGLE, nu.CHAMFER_QUADRANGLE[:1]])
    Cc = np.vstack([P, P[:1]])
    R = np.vstack([r.points, r.points[:1]])
    series = [C.Series("quadrangle ABCD", tuple(Q[:, 0]), tuple(Q[:, 1]), "k:"),
              C.Series("control polygon (P1 A P2 per corner)", tuple(Cc[:, 0]), tuple(Cc[:, 1]), "o--"),
              C.Series(f"NVPS degree 2, {levels} steps", tuple(map(float, R[:, 0])), tuple(map(float, R[:, 1])), "-")]
    t = np.linspace(0, 2 * math.pi, 200)
    for a in arcs:
        c, rad = a["center"], a["radius"]
        series.append(C.Series(f"circle r = {rad:g}", tuple(c[0] + rad * np.cos(t)), tuple(c[1] + rad * np.sin(t)), ":"))
    return C.Figure("001-chamfer", "Chamfering (Fig. 3(c)-(d)): r_A, r_B, r_C, r_D = 3.650669, 2, 1, 1.691966",
                    tuple(series), xlabel="x", ylabel="y", equal_aspect=True)


def _v_reproduction():
    ids, ev_exact = _exp_evidence()
    r = claim_reproduction()
    worst = max(v["form_error_level_8"] for k, v in r.witness.items() if not k.startswith("parabola"))
    ev_num = C.Evidence("float64 replay: circle / hyperbola polygons, d = 2, 3, 4, 8 levels (illustration)",
                        text=f"max form error of the level-8 polygons {roundoff_text(worst)} (rounding level)")
    if all(ids[k] for k in ("geometric", "update", "parametrization", "factor", "linear_d3")):
        return C.certified(
            "True for conics and trigonometric/hyperbolic curves (u = cos or cosh of half the step, control points "
            "on a scaled regular polygon: exact identities) and, for d >= 3, helices (circle and linear component "
            "share one parametrization, exact); d = 2 does not reproduce linear data, so a helix needs d >= 3 "
            "(the paper uses d = 4).",
            evidence=[ev_exact, ev_num], numbers=[C.Number("form_error_below_1e-12", bool(worst < 1e-12))],
            figures=[_blended_figure("001-blended", "seed001")])
    return C.refuted("an identity fails", "see evidence", evidence=[ev_exact, ev_num])


def _v_remark_1():
    ids, ev = _exp_evidence()
    return C.inconclusive(
        "Equal parameters give a uniform level-dependent scheme with symbol ((1+z)/2)^(d-2) a_2(u^k; z), "
        "u^(k+1) = sqrt((1+u^k)/2), generating the generalized B-spline spaces (exact); whether these are "
        "literally the rules of Fang-Ma-Wang (2010) cannot be checked from this text.",
        settle="compare with the rules of M. Fang, W. Ma, G. Wang, CAGD 27 (2010) 720-733 (not in the corpus).",
        evidence=[ev])


def _v_fig2(which: str):
    ids, ev = _exp_evidence()
    if which == "a":
        txt = ("Fig. 2(a): degree 2, trigonometric, hyperbolic and polynomial pieces. The control data are not "
               "printed. Each piece type is reproduced exactly by the degree-2 rule (u = cos, cosh, 1; exact), "
               "but note that d = 2 generates span{1, cos, sin} / {1, cosh, sinh} only: a 'polynomial B-spline "
               "piece' (u = 1) is a quadratic B-spline curve, not a reproduced polynomial.")
    elif which == "b":
        txt = ("Fig. 2(b): torque spring, degree 4, a helix and an arc inserted. No data printed; the degree-4 "
               "NVPS reproduces helices exactly (see 001:Remark1(reproduction)).")
    else:
        txt = ("Fig. 2(c): swan sketch, degree 5, curves (22). No control polygons printed. Each curve of (22) lies in "
               "a space the degree-5 NVPS generates exactly: c1 circle (cos, sin), c2 quadratic polynomial, c3 and c4 "
               "in span{1, t, sinh 2t, cosh 2t} (polynomials up to degree d - 2 = 3 plus one exponential pair). "
               "'1.2t + .08t' in c3 is as printed (perhaps .08t^2: still in the space).")
    return C.inconclusive(txt, settle="the control polygons and parameter sequences of the figure (not printed); "
                                      "then `subdiv nonuniform refine` replays it", evidence=[ev],
                          figures=[_blended_figure("001-blended-fig2", "seed001", degrees=(2, 4, 5), levels=5)]
                          if which == "a" else ())


def _v_locality():
    """Remark 2: changing one parameter affects only d pieces of the curve (measured exactly)."""
    d_rows, ok = [], True
    rng = np.random.default_rng(3)
    levels = (2, 3, 4)
    for d in range(2, 7):
        n = 14
        data = [sp.Rational(int(x), 7) for x in rng.integers(-20, 20, n)]
        u0 = [sp.Integer(1)] * (n - 1)
        counts, spans = [], []
        for steps in levels:
            w = sp.Rational(11, 10)
            for _ in range(steps):                  # u = T_(2^steps)(11/10): the square-root updates stay rational
                w = 2 * w * w - 1
            u1 = list(u0)
            u1[6] = w                               # change one edge parameter
            a = nu.refine(data, u0, degree=d, steps=steps, arithmetic="exact").points
            b = nu.refine(data, u1, degree=d, steps=steps, arithmetic="exact").points
            diff = [i for i in range(len(a)) if a[i] != b[i]]
            counts.append(len(diff))
            spans.append((diff[-1] - diff[0] + 1) / 2 ** steps if diff else 0.0)
            ok &= len(diff) == (2 ** steps - 1) * d
        d_rows.append((str(d),) + tuple(map(str, counts)) + (f"{spans[1]:.3f}",))
    res = C.exact_result(ok, "exact rational refinement, one parameter changed (u_6: 1 -> T_(2^k)(11/10)), "
                             f"k = {', '.join(map(str, levels))} levels; compared with (2^k - 1) d",
                         counts={r[0]: r[1:-1] for r in d_rows})
    ev = [C.Evidence("changed points after k levels (exact arithmetic)", result=res,
                     table=(("d",) + tuple(f"# changed, k = {k}" for k in levels) + ("span / 2^3 (level-0 units)",),)
                     + tuple(d_rows))]
    nums = [C.Number("changed_points_d4_k3", int(d_rows[2][2])), C.Number("count_rule_holds", bool(ok))]
    if ok:
        return C.Verdict(
            "numerical",
            "Consistent: changing one edge parameter changes exactly (2^k - 1) d points after k = "
            f"{', '.join(map(str, levels))} levels (exact arithmetic, d = 2..6), spanning about d (1 - 2^-k) level-0 "
            "intervals, which tends to d: d pieces of the limit curve.",
            evidence=ev, numbers=nums,
            sharpness="A finite-level count only approximates the limit influence region.")
    return C.inconclusive(
        "The number of changed points after k levels is not (2^k - 1) d for every degree checked (see the table); "
        "the influence region of one parameter is not the one the remark describes at these levels.",
        settle="an exact description of the support of the limit's dependence on one parameter",
        evidence=ev, numbers=nums)


def _v_algorithm_2():
    r = claim_chamfer()
    w = r.witness
    V = np.array(nu.CHAMFER_QUADRANGLE)
    rows, ratios = [], []
    for i, name in enumerate("ABCD"):
        A, B, Cp = V[i], V[i - 1], V[(i + 1) % 4]
        eb, ec = (B - A) / np.linalg.norm(B - A), (Cp - A) / np.linalg.norm(Cp - A)
        th = math.acos(float(eb @ ec))
        rmax = min(np.linalg.norm(B - A), np.linalg.norm(Cp - A)) * math.tan(th / 2) / 2
        ratios.append(stable_float(nu.CHAMFER_RADII[i] / rmax, 12))   # float64 (libm): no machine-dependent last bits
        rows.append((name, f"{math.degrees(th):.4f}", f"{rmax:.6f}", f"{nu.CHAMFER_RADII[i]:g}", f"{ratios[-1]:.7f}"))
    ev = [C.Evidence("degree-2 replay of Fig. 3(c)-(d) (float64)", result=r,
                     text=f"max distance of edge midpoints (limit points for d = 2) from the exact chamfered shape: "
                          f"{roundoff_text(w['midpoint_deviation'][-1])}; of the level-8 points: {w['deviation'][-1]:.2e} "
                          f"(-> 0 like 4^-k)"),
          C.Evidence("r_max of each corner (arc from B1 A C1, |AB1| = |AC1| = min(|AB|, |AC|))",
                     table=(("corner", "angle (deg)", "r_max", "printed r", "r / r_max"),) + tuple(rows),
                     text="r_A and r_D are r_max/2 to all printed digits.")]
    ok = w["midpoint_deviation"][-1] < 1e-12
    if not ok:
        return C.inconclusive(
            f"Not reproduced in the float64 replay: the edge midpoints deviate by {roundoff_text(w['midpoint_deviation'][-1])} "
            "from the chamfered shape.", settle="an exact (algebraic) replay of the chamfer",
            evidence=ev, figures=[_chamfer_figure()],
            numbers=[C.Number("midpoint_deviation", stable_float(w["midpoint_deviation"][-1], 2), tol=1e-9),
                     C.Number("rA_over_rmax", ratios[0], tol=1e-6), C.Number("rD_over_rmax", ratios[3], tol=1e-6)])
    return C.Verdict(
        r.status,
        ("Reproduced: with P1, P2 at distance 2 r cot(theta/2) from A and u_A = sin(theta/2) on the two edges, the "
         "degree-2 NVPS gives straight segments joined by exact arcs of radius r_A (midpoint deviation "
         f"{roundoff_text(w['midpoint_deviation'][-1])}). " if ok else "Not reproduced. ")
        + "The printed coordinate formula is garbled (k_i depends on P_i itself; b2 uses y_A with x_C); the "
          "geometric description is what is replayed.",
        evidence=ev, figures=[_chamfer_figure()],
        # the float64 round-off deviation itself is no key number: it differs between machines
        numbers=[C.Number("midpoint_deviation_below_1e-12", bool(ok)),
                 C.Number("rA_over_rmax", ratios[0], tol=1e-6), C.Number("rD_over_rmax", ratios[3], tol=1e-6)])


def _v_fig3_count():
    pts = 3 * 5                     # A B C D A, each a triple control point, open polygon ABCDA
    ok = pts - 1 == 14              # parameters u_0..u_13
    res = C.exact_result(ok, "counting")
    if ok:
        return C.certified("True: the open polygon ABCDA with every vertex tripled has 15 points and 14 edges, i.e. "
                           "parameters u_0, ..., u_13.", evidence=[C.Evidence("count", result=res)])
    return C.refuted("count mismatch", "see evidence", evidence=[C.Evidence("count", result=res)])


# -------------------------------------------------------------------------- the claims
def _c(cid, kind, statement, fn, title, *, reading=None, note=None, objects=("nvps-d",), params=(), command=None,
       location=""):
    return C.Claim(id=cid, kind=kind, statement=statement, evaluate=fn, title=title, reading=reading,
                   reading_note=note, objects=objects, params=params, command=command or _CMD.format(cid),
                   location=location)


PAPER_CLAIMS = [
    _c("001:Abstract(special cases)", "identity",
       "Generalized subdivision and the classical B-spline subdivision are all special cases of the proposed variable "
       "parameter subdivision.", _v_special_cases, "B-spline and generalized subdivision are special cases",
       location="Abstract; Sect. 2.2", command="subdiv report 001 --claim '001:Abstract(special cases)'"),
    _c("001:(3)Chaikin", "identity", "When all the values of uji are 1, the above scheme becomes stationary and it is "
       "the well-known Chaikin’s algorithm.", _v_chaikin, "u = 1 is Chaikin's algorithm",
       reading="all u^k_j = 1", note=_GARBLED, location="Sect. 2.2",
       command="subdiv nonuniform refine --degree 2 --points '0,0;1,0;1,1;0,1' --u 1 --closed"),
    _c("001:(4)", "mask identity", "ak,j2 =n 1 2(1 + ukj), 1 + 2ukj 2(1 + ukk), 1 + 2ukj 2(1 + ukj), 1 2(1 + ukj)o. (4)",
       _v_mask_4, "The mask of the degree-2 NVPS",
       reading="a_2^{k,j} = {1/(2(1+u^k_j)), (1+2u^k_j)/(2(1+u^k_j)), (1+2u^k_j)/(2(1+u^k_j)), 1/(2(1+u^k_j))}",
       note=_GARBLED + "'ukk' in the second entry is read as u^k_j (typo); (9) repeats (4).", location="Sect. 2.2"),
    _c("001:Sect2.2(u>0)", "inequality", "Since u0n > 0, it is clear that ukn > 0 for every i ∈ Z.", _v_positivity,
       "Parameters stay positive", note=_GARBLED, location="Sect. 2.2"),
    _c("001:Lemma2.1", "convergence", "Then, ukn converges to 1, as k → ∞, uniformly in terms of n. Moreover, for any "
       "k ≥ 1, kUkk ≤ C max(1, kU0k). (5)", _v_lemma_2_1, "u^k -> 1 uniformly; ||U^k|| <= C max(1, ||U^0||)",
       reading="u^k_n -> 1 uniformly in n; ||U^k||_inf <= C max(1, ||U^0||_inf)", note=_GARBLED,
       location="Sect. 2.2", command="subdiv nonuniform lemma --u0-range 0.01,100"),
    _c("001:(6)", "identity", "the subdivision scheme Sd for higher degree d > 2 is defined recursively by (SdPk)i = 1 2 "
       "(Sd−1Pk)i + (Sd−1Pk)i+1 . (6) ... Certainly, the classical B-spline subdivision are special cases of the "
       "proposed subdivision.", _v_rules, "The degree-d rule (6); u = 1 is the uniform B-spline",
       reading="(S_d P)_i = ((S_{d-1}P)_i + (S_{d-1}P)_{i+1})/2", note=_GARBLED, location="Sect. 2.2",
       command="subdiv nonuniform compare-definitions --degree 4 --levels 3"),
    _c("001:Algorithm1", "identity", "Case 1: d is odd. u30 = u0, u32n−3 = un−1, u32i+1 = u32i+2 = ui+1, i = 0, · · · , "
       "n − 3, udj = ud−2j+1, j = 0, 1, . . . , 2n − d, d > 3 Case 1: d is even. udj = ud−2j+1, j = 0, 1, · · · , "
       "2n − d, d > 2;", _v_algorithm_1, "Algorithm 1: parameters of the new edges",
       reading="d odd: u^3_0 = u_0, u^3_{2n-3} = u_{n-1}, u^3_{2i+1} = u^3_{2i+2} = u_{i+1}; u^d_j = u^{d-2}_{j+1}; "
               "d even: u^d_j = u^{d-2}_{j+1}, u^2 from rule (2); then each inherited value is updated by (2)",
       note=_GARBLED + "the second 'Case 1' is Case 2. As printed step (3) assigns old values without the square "
            "root of (2); read literally the parameters of odd degrees would never change (then u^k does not tend "
            "to 1 and Lemma 2.1 would not apply), so the inherited values are read as updated by (2).",
       location="Sect. 2.2, Algorithm 1"),
    _c("001:(12)", "identity", "Ejk:= 2kkak,j2 − ak (11) = 2kmax 1 2(1 + ukj)− 1 4 , 1 + 2ukj 2(1 + ukj)− 3 4 = 2k−2 "
       "1 − ukj 1 + ukj . (12)", _v_12, "The distance (12)",
       reading="E^k_j = 2^k max(|1/(2(1+u)) - 1/4|, |(1+2u)/(2(1+u)) - 3/4|) = 2^(k-2) |1-u|/(1+u)", note=_GARBLED,
       location="Sect. 3.1, proof of Lemma 3.3"),
    _c("001:Sect3.1(equivalence)", "series convergence", "In this study, we shall see that the mask {ak,j} of the NVPS "
       "of degree d is asymptotically equivalent to the B-spline scheme of order d.", _v_equivalence,
       "Asymptotic equivalence to the B-spline", reading="sum_k sup_j ||a^{k,j} - a|| < oo, a the B-spline of degree d",
       location="Sect. 3.1", command="subdiv nonuniform decay --u0 0.5,3 --degree 4 --levels 10"),
    _c("001:Lemma3.2", "convergence", "Lemma 3.2 Assume that {ak,j} ∼ {˜ak,j} and the scheme defined by the masks "
       "{˜ak,j} is stable and C0, then the non-uniform scheme with the mask {ak,j} is also C0 and stable.",
       _v_lemma_3_2, "Cited: asymptotic equivalence transfers C^0 and stability", location="Sect. 3.1"),
    _c("001:Lemma3.3", "series convergence", "X k∈Z 2kmax j {kak,j2 − a2k} < ∞", _v_lemma_3_3,
       "Weighted series of the degree-2 masks", reading="sum_{k >= 0} 2^k max_j ||a_2^{k,j} - a_2|| < oo",
       note=_GARBLED + "'k ∈ Z' should be k >= 0.", location="Sect. 3.1"),
    _c("001:Corollary3.4", "inequality", "maxj {kak,j2 − a2k} < c2−k. with a constant c > 0 independent of k and j.",
       _v_corollary_3_4, "Decay of the degree-2 masks", reading="max_j ||a_2^{k,j} - a_2|| < c 2^-k",
       location="Sect. 3.1", command="subdiv nonuniform decay --u0 0.1,0.5,2,10 --degree 2 --levels 14"),
    _c("001:(13)-(14)", "necessary condition", "We say that the scheme S satisfies Property A of order m if dr dzrdj,ka "
       "(±1) = ¯o(2−k(m−r)), 0 ≤ r < m, (13) as k → ∞, where dj,km(z) ≡ m X i=0 (−1)i m i ! zipj−i,k(z). (14)",
       _v_property_a_def, "Property A (definition quoted from DLY 2014)",
       reading="d^r/dz^r d_m^{j,k}(±1) = o(2^{-k(m-r)}), 0 <= r < m, with d_m^{j,k}(z) = sum_i (-1)^i binom(m,i) z^i "
               "a^{j-i,k}(z)", note=_GARBLED, location="Sect. 3.2",
       command="subdiv nonuniform property-a --degree 4"),
    _c("001:Theorem3.5", "smoothness", "Theorem 3.5 Consider a non-uniform binary scheme S defined by masks {ak,j}, "
       "satisfying {ak,j} ∼ a, (15) where m is the mask of a stationary binary scheme Sa. Further assume that S "
       "satisfies Property A of orders 1 ≤ ℓ ≤ m. If Sa is a Cm scheme with a stable basic limit function, then also "
       "S is a Cm scheme.", _v_theorem_3_5, "Cited: smoothness transfer (DLY 2014)", location="Sect. 3.2"),
    _c("001:(16)", "factorization", "ak,jd (z) :=z + 1 2 d−2 ak,j2 (z). (16)", _v_16,
       "The degree-d symbol factorizes", reading="a_d^{k,j}(z) = ((z+1)/2)^{d-2} a_2^{k,j}(z) (as the symbol of (6))",
       note=_GARBLED, location="Sect. 3.3", command="subdiv report 001 --claim '001:(16)'"),
    _c("001:(17)", "identity", "ak,j2 (1) = 1, d dzak,j2 (1) = 2, d2 dz2aj,k2 (1) = 1. (17)", _v_17,
       "Values of the degree-2 symbol at z = 1",
       reading="a_2^{k,j}(1) = 1, a_2^{k,j}'(1) = 2, a_2^{k,j}''(1) = 1, for the symbol (11)", note=_GARBLED,
       location="Sect. 3.3"),
    _c("001:Sect3.3(support)", "support", "It is obvious that the mask of the proposed scheme has the support as one of "
       "the B-spline of degree n, i.e., supp(ak,j) = Z ∩ [0, n] − ⌈n/2⌉ which is indeed the same as the B-spline of "
       "degree n.", _v_support, "Support of the masks", reading="n is the degree d", location="Sect. 3.3"),
    _c("001:b(z)", "identity", "bk,j(z) = 1 z(1 + ukj)(1 + 2ukjz + z2). ... |bk,j(−1)| = 2(1 − ukj) 1 + ukj = "
       "8kak,j− ak≤ c2−k.", _v_b_of_z, "b(z) and |b(-1)| in the proof of Theorem 3.6",
       reading="b(z) = (1 + 2uz + z^2)/(z(1+u)); |b(-1)| = 2(1-u)/(1+u) = 8||a^{k,j} - a|| <= c 2^-k",
       note=_GARBLED, location="Sect. 3.3, proof of Theorem 3.6"),
    _c("001:(19)", "necessary condition", "we need to show that the NVPS of degree d satisfies the Property A of order "
       "1 ≤ m ≤ d − 1, that is, as k → ∞, d dzdj,km z=±1 = O(2−k(n−ℓ)), 0 ≤ ℓ < m. (19)", _v_19,
       "Property A of orders 1..d-1 for the NVPS",
       reading="d^l/dz^l d_m^{j,k}(±1) = o(2^{-k(m-l)}), 0 <= l < m, for 1 <= m <= d-1 (Property A (13))",
       note=_GARBLED + "'n' in the exponent is m; (13) asks o(), (19) prints O().", location="Sect. 3.3",
       command="subdiv nonuniform property-a --degree 4"),
    _c("001:Theorem3.6", "smoothness", "Theorem 3.6 (Smoothness of NVPS of degree d) The NVPS scheme of degree d with "
       "d > 1 generates Cd−1-continuous limit curves.", _v_theorem_3_6, "C^(d-1) limit curves",
       reading="C^{d-1} for every parameter sequence", location="Sect. 3.3",
       command="subdiv nonuniform junction --degree 4 --u-left 0.3 --u-right 4 --levels 16"),
    _c("001:Remark1", "identity", "Remark 1. When all parameters in the parameter sequence are equal, the NVPS is "
       "reduced to a generalized subdivision scheme in (Fang et al 2010).", _v_remark_1,
       "Equal parameters: the generalized subdivision of Fang et al. 2010", location="Sect. 2.2"),
    _c("001:Remark1(reproduction)", "reproduction", "It can reproduce the curves such as conics, trigonometric curves "
       "and helix.", _v_reproduction, "Reproduction of conics, trigonometric curves, helices", location="Sect. 2.2",
       command="subdiv nonuniform reproduce --kind circle --degree 3 --levels 8 --figure blended.png"),
    _c("001:Remark2(locality)", "support", "In fact, only d pieces of subdivision curves are effected when one "
       "parameter is changed for NVPS of degree d", _v_locality, "Locality of a parameter change",
       location="Sect. 2.2, Remark 2"),
    _c("001:Fig2(a)", "reproduction", "In Figure 2 (a), a blending curve similar to that in Figure 5 in paper (Wang and "
       "Fang 2008) is generated by NVPS of degree 2. It includes a piece of trigonometric B-spline curve, a piece of "
       "hyperbolic B-spline curve and a piece of polynomial B-spline curve", functools.partial(_v_fig2, "a"),
       "Blending example, degree 2", location="Sect. 4",
       command="subdiv nonuniform reproduce --kind hyperbola --degree 2 --levels 8 --figure blended.png"),
    _c("001:Fig2(b)", "reproduction", "In Figure 2 (b), a torque spring curve is generated by NVPS of degree 4 in which "
       "a piece of helix and a piece of arc are inserted.", functools.partial(_v_fig2, "b"), "Torque spring, degree 4",
       location="Sect. 4"),
    _c("001:Fig2(c)", "reproduction", "In Figure 2 (c), a sketch of swan is generated by NVPS of degree 5, in which four "
       "pieces of special curves with general parametric equations are inserted. (22)", functools.partial(_v_fig2, "c"),
       "Swan, degree 5, curves (22)", location="Sect. 4"),
    _c("001:Algorithm2", "reproduction", "Giving a radius rA in a suitable domain, we generate a piece of arc tangent to "
       "both edges of this angle with radius rA by generalized subdivision scheme. ... By our NVPS, the curve after "
       "chamfering is generated as illustrated in Figure 3 (d).", _v_algorithm_2, "Chamfering algorithm, Fig. 3",
       location="Sect. 4", command="subdiv nonuniform chamfer --levels 8 --figure chamfer.png"),
    _c("001:Fig3(c)", "identity", "It can be seen as a variable-parameter subdivision curve with each vertex being "
       "triple control point in its control polygon ABCDA and with a constant parameter sequence {u i ≡ 1}13i=0.",
       _v_fig3_count, "Parameter count of Fig. 3(c)", reading="u_i = 1, i = 0..13", location="Sect. 4"),
]

PAPER = C.Paper(
    id="001",
    title="A non-uniform subdivision scheme with variable parameters for curve design",
    citation=("M. Fang, B. Jeong, J. Yoon, A non-uniform subdivision scheme with variable parameters for curve "
              "design (preprint, 17 pp., c. 2014)"),
    claims=PAPER_CLAIMS,
    source="shared/seeds/001_6819d78b3590dec4.txt",
    notes=("The NVPS is non-uniform (masks depend on level and location through the edge parameters), so its "
           "schemes are analysis.nonuniform.nvps.NVPS objects, not catalogue entries; its limit is the uniform B-spline "
           "of degree d. Convention: P^{k+1}_n = sum_i a^{k,n}_{n-2i} P^k_i; the degree-2 mask is "
           "{h, 1-h, 1-h, h}, h = 1/(2(1+u)), at exponents -2..1 ((11) writes it times z). The extraction flattened "
           "sub/superscripts; each claim keeps the printed text and says how it was read. Definition 3.1 is a "
           "definition (nothing to check); Fig. 1 and the remark that Fig. 1(b) 'is impossible with existing "
           "generalized subdivision' are not checkable from the text."),
)
