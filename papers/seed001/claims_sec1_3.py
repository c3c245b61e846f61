"""Seed 001, the `python` evaluators of Sects. 1-3 (definition, convergence, smoothness), named by
``papers/seed001/paper.toml``: each ``_v_*`` returns a :class:`analysis.claims.Verdict` built from
the NVPS engine (:mod:`analysis.nonuniform`) and exact identities, never typed in.
"""

from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from analysis import claims as C
from analysis import nonuniform as nu

from .identities import _s, bspline_special_case, exponential_evidence
from analysis.algebra.reader import as_expr

_LOW, _HIGH = sp.Rational(1, 100), sp.Integer(100)     # the u0 range of the certified constants


def _sym():
    r = nu.symbol_identities()
    return r, r.witness


def _series(factor):
    """The rate constant C' on u0 in [1/100, 100] and ``factor * C' / (4 (1 + 1/100))`` (exact)."""
    b = nu.u_convergence_bound(_LOW, _HIGH)
    return b, factor * sp.Rational(str(b.upper)) / (4 * (1 + _LOW))


# -------------------------------------------------------------------------- Sects. 1-2
def _v_special_cases():
    ok, ev = bspline_special_case()
    ids, ev2 = exponential_evidence()
    nums = [C.Number("degrees_checked", 6)]
    if ok and ids["factor"] and ids["geometric"]:
        return C.certified(
            "True. u = 1 gives exactly the uniform B-spline of degree d at every location (d = 2..7, exact masks "
            "= catalogue bspline-d up to a shift); equal parameters give a uniform level-dependent scheme with "
            "symbol ((1+z)/2)^(d-2) h z^-2 (1+z)(z^2 + 2u^k z + 1), which generates 1, ..., t^(d-2) and "
            "e^(+-i w t) / e^(+-w t) exactly: the generalized B-spline spaces of Fang-Ma-Wang (2010).",
            sharpness="The identification with the exact rule text of Fang-Ma-Wang (2010) is not replayed here "
                      "(see 001:Remark1); the B-spline case is exact.", evidence=[ev, ev2], numbers=nums)
    return C.refuted("u = 1 does not give the B-spline", "see the table", evidence=[ev, ev2], numbers=nums)


def _v_chaikin():
    ok, ev = bspline_special_case(degrees=[2])
    fixed = sp.sqrt((1 + sp.Integer(1)) / 2) == 1
    ev2 = C.Evidence("u = 1 is a fixed point of the update (2)", result=C.exact_result(fixed, "sqrt((1+1)/2) = 1 exactly"))
    if ok and fixed:
        return C.certified("True: u = 1 is a fixed point of (2) (so the scheme is stationary) and (3) becomes "
                           "P_2i = 3/4 P_i + 1/4 P_i+1, P_2i+1 = 1/4 P_i + 3/4 P_i+1, Chaikin's mask [1,3,3,1]/4.",
                           evidence=[ev, ev2])
    return C.refuted("not Chaikin", "see evidence", evidence=[ev, ev2])


def _v_positivity():
    u = sp.Symbol("u", positive=True)
    phi = sp.sqrt((1 + u) / 2)
    ok = bool(sp.simplify(phi ** 2 - (1 + u) / 2) == 0) and sp.ask(sp.Q.positive(phi ** 2 - sp.Rational(1, 2)),
                                                                     sp.Q.positive(u)) is True
    res = C.exact_result(ok, "sympy: phi(u)^2 - 1/2 = u/2 > 0 for u > 0", phi=phi,
                         phi_minus_1_over_sqrt2=sp.simplify(phi - sp.sqrt(2) / 2))
    if ok:
        return C.certified("True: phi(u) = sqrt((1+u)/2) > 1/sqrt(2) > 0 for u > 0, so by induction u^k_n > 0 "
                           "(in fact > 1/sqrt(2) for k >= 1).", evidence=[C.Evidence("phi(u) > 0", result=res)])
    return C.inconclusive("could not decide", settle="a proof of phi(u) > 0", evidence=[C.Evidence("phi", result=res)])


def _v_lemma_2_1():
    r, b = nu.lemma_2_1(_LOW, 100), nu.u_convergence_bound(_LOW, _HIGH)
    ev = [C.Evidence("Lemma 2.1 on u0 in [1/100, 100] (C = 1)", result=r, text=str(dict(r.witness))[:400]),
          C.Evidence("rate: sup_n |1 - u^k_n| <= C' 4^-k", result=b, text=f"C' enclosure {b.witness['C_enclosure']}; "
                     f"4^k(1 - u^k) -> acos(u0)^2/2 or -acosh(u0)^2/2")]
    nums = [C.Number("C", r.value), C.Number("rate_constant_u0_in_[1/100,100]", b.upper, tol=1e-9)]
    if r.status == "certified" and b.status == "certified":
        return C.certified("True with C = 1: ||U^k|| <= max(1, ||U^0||) for every k, and u^k_n -> 1 uniformly, at "
                           "the rate 4^-k (certified on u0 in [1/100, 100]; the monotonicity argument of "
                           "phi(u) = sqrt((1+u)/2) holds for every u0 > -1).",
                           sharpness="The rate is 4^-k (1 - u^k = 2 sin^2(theta/2^(k+1)) for u0 = cos theta), not "
                                     "the 2^-k used later in the proof of Theorem 3.6.", evidence=ev, numbers=nums)
    return C.inconclusive("the interval check did not close", settle="more precision / levels", evidence=ev, numbers=nums)


def _v_rules():
    rows = {d: nu.compare_definitions(d, levels=3) for d in range(2, 7)}
    ok = all(x.witness["one_step_equal_up_to_shift"] for x in rows.values())
    sym_ok = all(x.witness["symbolic_recursion_equals_binomial"] for x in rows.values())
    r = C.exact_result({d: x.value for d, x in rows.items()}, "exact rational refinement (compare_definitions)",
                       per_degree={d: x.to_json()["witness"] for d, x in rows.items()})
    ok_b, ev_b = bspline_special_case()
    ev = [C.Evidence("(6) unrolled vs the binomial form, and seed 000's definition (exact)", result=r,
                     table=(("d", "seed 000 vs 001"),) + tuple((str(d), x.value) for d, x in rows.items())), ev_b]
    if ok and sym_ok and ok_b:
        return C.certified("True: (6) unrolled is (S_d P)_i = 2^(2-d) sum_l binom(d-2, l) (S_2 P)_(i+l), with "
                           "2(n-1) - (d-2) new points; with u = 1 it is the uniform B-spline of degree d (the "
                           "Lane-Riesenfeld algorithm) -- the classical B-spline subdivision is the special case u = 1.",
                           evidence=ev)
    return C.refuted("(6) is not the binomial average", "see evidence", evidence=ev)


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
    ev = [C.Evidence("new edge j <- old edge (Algorithm 1 step (3) vs engine ceil((j + floor((d-2)/2))/2))",
                     result=C.exact_result(ok, "integer index computation, d = 2..9, n = d..15"),
                     table=(("d", "n", "Algorithm 1", "engine", "agree"),) + tuple(rows))]
    if ok:
        return C.certified("True under the reading: both cases of step (3) give 2n - d + 1 parameters, new edge j "
                           "inheriting (then updated by (2)) the parameter of old edge ceil((j + floor((d-2)/2))/2); "
                           "for d = 2 this is rule (2).", evidence=ev, numbers=[C.Number("cases_checked", 8)])
    return C.refuted("Algorithm 1 disagrees with the engine", "see table", evidence=ev)


# -------------------------------------------------------------------------- Sect. 3.1
def _v_12():
    r, w = _sym()
    ev = [C.Evidence("engine result", result=r, text="(12) as an identity in u: exact, generic u")]
    if w["(12)_identities_hold"]:
        return C.certified("True (exact identity for every u > 0, reading the lost bars as |1 - u^k_j|).", evidence=ev)
    return C.refuted("(12) fails", corrected="see evidence", evidence=ev)


def _v_equivalence():
    """Sect. 3.1: {a^{k,j}} ~ B-spline of degree d (Definition 3.1), certified bound on the series."""
    # sup_j ||S^k - S_a|| <= 2 max_e |delta^k_e|,  |delta| = |v|/(4(1+u)) <= C' 4^-k / (4 (1 + 1/100))
    b, total = _series(2 * sp.Rational(4, 3))
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


def _v_lemma_3_3():
    b, total = _series(2)                   # sum_k 2^k C' 4^-k / (4(1 + min u))
    _, w = _sym()
    ratio = w["Lemma3.3_ratio_2(u/(1+u))^2_holds"]
    ev = [C.Evidence("rate constant", result=b),
          C.Evidence("sum_k 2^k max_j ||a_2^{k,j} - a_2|| <= sum_k 2^k C' 4^-k / (4 (1 + 1/100))",
                     result=C.exact_result(total, "exact geometric series"), text=f"<= {_s(total)}"),
          C.Evidence("ratio identity of the proof: E^k/E^(k-1) = 2 (u/(1+u))^2 -> 1/2",
                     result=C.exact_result(ratio, "sympy, generic u"))]
    if b.status == "certified" and ratio:
        return C.certified(f"True (the printed sum over k in Z means k >= 0): the series is <= {_s(total)} for "
                           "u0 in [1/100, 100]; the proof's ratio identity 2(u/(1+u))^2 holds exactly.",
                           sharpness="The terms are Theta(2^-k) (masks converge like 4^-k), so even "
                                     "sum_k 4^k max_j ||.|| diverges only logarithmically-free: sum 2^(mk) converges "
                                     "for m < 2 only.",
                           evidence=ev, numbers=[C.Number("series_bound", total, tol=1e-9)])
    return C.inconclusive("not certified", settle="see evidence", evidence=ev)


def _v_corollary_3_4():
    u0 = [sp.Rational(1, 10), sp.Rational(1, 2), sp.Integer(2), sp.Integer(10)]
    r = nu.mask_decay(u0, degree=2, levels=14)
    # for every k >= 0 (analytic, Lemma 2.1's half-angle argument, constants enclosed rigorously):
    # upper: sup_j ||S^k - S_a|| <= 2 max_e |delta^k_e| = 2 max |1-u^k|/(4(1+u^k)) <= C' 4^-k / (2 (1 + 1/10))
    #        (u^k lies between u0 and 1, so 1 + u^k >= 11/10; C' from u_convergence_bound);
    # lower: u0 = 1/10 = cos(theta): 1 - u^k = 2 sin^2(theta/2^(k+1)) >= 2 theta^2/(pi^2 4^k) (sin x >= 2x/pi),
    #        |delta^k| >= (1 - u^k)/8, and a pure window attains c_2 |delta^k| (every window is pure for d = 2).
    b = nu.u_convergence_bound(min(u0), max(u0))
    upper = b.upper / (2 * (1 + min(u0))) if b.upper is not None else None
    c2 = nu._pure_constant(2)
    with mpmath.workprec(128):
        iv = mpmath.iv
        low_iv = iv.mpf(c2.numerator) / c2.denominator * nu._iv_acos(iv.mpf(1) / 10) ** 2 / (4 * iv.pi ** 2)
    lower = nu._endpoint_rational(low_iv, "lower")
    consistent = upper is not None and all(
        sp.Rational(row["lower"]) * 4 ** row["k"] >= lower and sp.Rational(row["upper"]) * 4 ** row["k"] <= upper
        for row in r.witness["levels"])
    ok = r.status == "certified" and b.status == "certified" and lower > 0 and consistent
    ratios = r.witness["ratios"]
    ev = [C.Evidence("sup_j ||S^k - S_a||, u0 = 1/10, 1/2, 2, 10 (d = 2): analytic bounds for every k and certified "
                     "enclosures for k = 0..14", result=r,
                     text=f"{_s(lower)} 4^-k <= sup_j ||S^k - S_a|| <= {_s(upper)} 4^-k "
                          f"(every k >= 0); the enclosures of k = 0..14 lie within these bounds: "
                          f"{consistent}; float ratios of consecutive upper enclosures "
                          "(observation): " + ", ".join(f"{x:.6f}" for x in ratios[-3:]))]
    nums = [C.Number("lower_constant", lower), C.Number("upper_constant", upper),
            C.Number("ratio_last", ratios[-1], tol=1e-6),
            C.Number("scaled_4k_last", r.witness["scaled_4k_upper"][-1], tol=1e-6)]
    if ok:
        return C.certified("True, but not sharp: c1 4^-k <= max_j ||a_2^{k,j} - a_2|| <= c2 4^-k for every k >= 0 "
                           f"(c1 = {float(lower):.4g}, c2 = {float(upper):.4g}, certified "
                           "for u0 in {1/10, 1/2, 2, 10}; the upper bound holds for all u0 in [1/10, 10]), i.e. "
                           "Theta(4^-k); the float ratios of consecutive levels are close to 1/4.",
                           sharpness="c 4^-k holds (Lemma 2.1's half-angle rate); the stated c 2^-k is weaker.",
                           evidence=ev, numbers=nums)
    return C.inconclusive("the bounds were not certified", settle="interval arithmetic at higher precision",
                          evidence=ev, numbers=nums)


# -------------------------------------------------------------------------- Sects. 3.2-3.3
def _v_16():
    z = sp.Symbol("z")
    M, start = nu.location_masks([sp.Rational(1, 2)] * 3 + [sp.Integer(3)] * 3, degree=4, arithmetic="exact")
    cx = None
    for row in M:                            # the first location with fewer than 3 factors (1+z)
        poly, k = sp.Poly(sum(c * z ** t for t, c in enumerate(row)), z), 0
        while poly.eval(-1) == 0 and k < 10:
            poly, k = sp.Poly(sp.cancel(poly.as_expr() / (1 + z)), z), k + 1
        if k < 3:
            cx = {"mask": [str(c) for c in row], "start": start, "(1+z)_factors": k}
            break
    res = C.exact_result("holds for locally constant parameters only", "exact sympy masks, u = 1/2 | 3",
                         counterexample_degree_4_junction=cx)
    ev = [C.Evidence("degree 4, u = 1/2 | 3: a junction mask", result=res,
                     text=f"mask {cx['mask'] if cx else None}, (1+z)-factors {cx['(1+z)_factors'] if cx else None} "
                          "(the B-spline-like (16) would have >= 3)")]
    if cx:
        return C.refuted("False at junctions: where the d-1 degree-2 points averaged by (6) carry different "
                         "parameters, the mask of (6) is a mixture of a_2 masks and has fewer than d-1 factors (1+z).",
                         corrected="a_d^{k,j}(z) = 2^(2-d) sum_l binom(d-2, l) z^(-l) a_2^{k, e(j+l)}(z); it equals "
                                   "((z+1)/2)^(d-2) a_2^{k,j}(z) only where the parameters of the window agree "
                                   "(e.g. for constant parameters).",
                         evidence=ev, numbers=[C.Number("junction_(1+z)_factors_d4", cx["(1+z)_factors"])])
    return C.certified("(16) holds", evidence=ev)


def _v_17():
    r, w = _sym()
    ev = [C.Evidence("(11) at z = 1", result=r, latex=r"a_2(z)=\frac{1+(1+2u)z+(1+2u)z^2+z^3}{2(1+u)z}",
                     table=(("quantity", "printed", "exact"),) + tuple(
                         (k, str(w["printed_(17)"][k]), w["exact"][k]) for k in ("a(1)", "a'(1)", "a''(1)")))]
    nums = [C.Number("a(1)", as_expr(w["exact"]["a(1)"])), C.Number("a'(1)", as_expr(w["exact"]["a'(1)"])),
            C.Number("a''(1)", w["exact"]["a''(1)"])]
    exact = "; ".join(f"{k} = {w['exact'][k]}" for k in ("a(1)", "a'(1)", "a''(1)"))
    if r.status == "refuted":
        wrong = [k for k, bad in w["differs_from_printed"].items() if bad]
        return C.refuted(f"False (exact, generic u): {exact}; printed values differ for {', '.join(wrong)} "
                         "(a(1) and a'(1) for every u; a''(1) = 2/(1+u) equals the printed 1 only at u = 1).",
                         corrected="a_2^{k,j}(1) = " + w["exact"]["a(1)"] + ", (d/dz) a_2^{k,j}(1) = "
                                   + w["exact"]["a'(1)"] + ", (d^2/dz^2) a_2^{k,j}(1) = "
                                   + w["exact"]["a''(1)"].replace("u", "u^k_j"), evidence=ev, numbers=nums)
    return C.certified(f"True (exact, generic u): {exact}.", evidence=ev, numbers=nums)


def _v_b_of_z():
    r, w = _sym()
    ev = [C.Evidence("engine result", result=r, text=f"b(-1) = {w['b(-1)']}; |b(-1)| = 2|1-u|/(1+u) (the printed "
                     "form drops the absolute value for u > 1) = 8 x the coefficient distance of (12)")]
    nums = [C.Number("b(-1)", as_expr(w["b(-1)"]))]
    if w["b(z)_equals_printed"]:
        return C.certified("True: b(z) = 2 a_2(z)/(1+z) = (1 + 2uz + z^2)/(z(1+u)) and |b(-1)| = 2|1-u|/(1+u) "
                           "= 8 x the coefficient distance (12) (the printed form drops the absolute value).",
                           evidence=ev, numbers=nums)
    return C.refuted("b(z) differs", corrected="see evidence", evidence=ev, numbers=nums)


def _v_support():
    rows, ok = [], True
    for d in range(2, 8):
        M, start = nu.location_masks([sp.Rational(1, 2)] * 3 + [sp.Integer(3)] * 3, degree=d, arithmetic="exact")
        width = M.shape[1]
        ok &= width == len(nu.limit_mask(d).mask) and all(any(c != 0 for c in M[:, t]) for t in range(width))
        rows.append((str(d), str(width), str(len(nu.limit_mask(d).mask)), str(d + 1)))
    ev = [C.Evidence("mask lengths", result=C.exact_result(ok, "exact masks (u = 1/2 | 3) and the B-spline limit"),
                     table=(("d", "NVPS mask length", "B-spline degree d", "#(Z ∩ [0, d])"),) + tuple(rows))]
    if not ok:
        return C.inconclusive("the NVPS masks do not all have the B-spline's length", settle="see the table", evidence=ev)
    return C.refuted("Half true: the NVPS mask of degree d has the support of the B-spline of degree d (d + 2 "
                     "coefficients at every level and location), but Z ∩ [0, n] - ceil(n/2) with n = d has only d + 1 "
                     "points.",
                     corrected="supp(a^{k,j}) = Z ∩ [0, d+1] - shift (d + 2 coefficients; [-d, 1] in the convention "
                               "P^{k+1}_n = sum_i a_{n-2i} P^k_i), the support of the B-spline of degree d",
                     evidence=ev, numbers=[C.Number("mask_length_d4", int(rows[2][1]))])


def _property_a_fails(degrees):
    """Per degree, the (m, r, z0) whose Property A quantity violates o(2^(-k(m-r))) at a junction (exact)."""
    return {d: [(x["m"], x["r"], x["z0"]) for x in nu.property_a_table(d) if x["fails_on_blended"]] for d in degrees}


def _v_19():
    fails = _property_a_fails(range(2, 7))
    rows = [(str(d), str(len(nu.property_a_table(d))), ", ".join(f"(m={m}, r={r}, z={z:+d})" for m, r, z in f) or "none")
            for d, f in fails.items()]
    ev = [C.Evidence("Property A quantities that do not vanish identically, and those that violate o(2^(-k(m-r))) "
                     "at a junction", result=C.exact_result(fails, "exact linear forms (property_a_structure) x "
                                                                   "|delta_B - delta_A| >= c 4^-k"),
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


def _v_theorem_3_6(levels: int = 16):
    fails = _property_a_fails(range(2, 7))
    js = {d: nu.junction_smoothness(d, 0.3, 4.0, levels=levels) for d in fails}
    js2 = nu.junction_smoothness(4, 0.3, 4.0, levels=levels, order=2)
    omega = {d: j.witness["omega_junction"][-1] for d, j in js.items()}
    r = C.exact_result({d: j.value for d, j in js.items()}, "exact Property A structure + mpmath divided differences")
    ev = [C.Evidence("per degree: Property A violations (exact) and (d-1)-th divided differences at a junction "
                     "u = 0.3 | 4 (mpmath)", result=r,
                     table=(("d", "Property A fails at (m, r, z0)", "(d-1)-th divided differences", "omega_16"),)
                     + tuple((str(d), str(fails[d]), js[d].value, f"{omega[d]:.3e}") for d in fails)),
          C.Evidence("d = 4, second divided differences at the same junction", result=js2,
                     text=f"{js2.value}: last omega_k " + ", ".join(f"{x:.3e}" for x in js2.witness["omega_junction"][-3:]))]
    nums = [C.Number("omega_d2", omega[2], tol=1e-6), C.Number("omega_d4", omega[4], tol=0.02),
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
