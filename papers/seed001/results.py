"""Seed 001, engine results: one function per checkable statement, each returning an
:class:`analysis.result.Result` computed by the NVPS engine (:mod:`analysis.nonuniform`); the
dict-based ``CLAIMS`` list and :func:`check` (what ``subdiv nonuniform claims --seed 001`` runs);
``SCHEMES``, the NVPS of degree 2..8 with seed 001's rules.

The proof-check verdicts (:mod:`papers.seed001.claims_sec1_3`, :mod:`papers.seed001.examples`) build on
these results.
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
                  provenance={"method": "exact rational refinement (analysis.nonuniform.compare_definitions)"})


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

