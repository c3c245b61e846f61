"""Seed 000, the claims: engine results per statement (``claim_*``, the dict-based ``CLAIMS`` and
:func:`check` run by ``subdiv nonuniform claims --seed 000``), ``SCHEMES``, and the proof-check
``PAPER`` (evaluated by ``subdiv report 000``). The exact identities shared with seed 001 come
from :mod:`papers.seed001`.
"""
from __future__ import annotations

from pathlib import Path
from typing import Callable

import sympy as sp

from analysis import claims as C
from analysis.claims.paperfile import load_paper
from analysis import nonuniform as nu
from analysis.jsonable import roundoff_text
from analysis.result import CERTIFIED, NUMERICAL, REFUTED, AnalysisError, Result
# shared with seed 001 (the journal version of the same NVPS)
from papers.seed001.figures import blended_figure
from papers.seed001.identities import bspline_special_case, exponential_evidence
from papers.seed001.claims_sec1_3 import _v_equivalence

SOURCE = ("M. Fang, B. Jeong, J. Yoon, Non-uniform subdivision schemes reproducing locally different curves "
          "(conference abstract), seed 000")

SCHEMES = {f"nvps000-{d}": nu.NVPS(d, "seed000") for d in range(2, 9)}


def claim_eta() -> Result:
    """S_2 of seed 000 (eta(x) = 1/(2(1+x))) is seed 001's rule (3) with u = lambda."""
    lam = sp.Symbol("lambda")
    eta = 1 / (2 * (1 + lam))
    ok = sp.simplify((1 - eta) - (1 + 2 * lam) / (2 * (1 + lam))) == 0
    return Result(value=ok, status=CERTIFIED if ok else REFUTED,
                  witness={"1 - eta(lambda)": "(1 + 2 lambda)/(2(1 + lambda))"},
                  provenance={"method": "sympy, generic lambda"})


def claim_s_d() -> Result:
    """S_d of seed 000 vs seed 001: same data rule up to tau_d; parameter inheritance equal for odd d,
    mirror images for even d."""
    rows = {d: nu.compare_definitions(d, levels=3) for d in range(2, 7)}
    ok = all(r.status == CERTIFIED for r in rows.values())
    return Result(value={d: r.value for d, r in rows.items()}, status=CERTIFIED if ok else NUMERICAL,
                  witness={d: {"tau_d": r.witness["tau_d"], "multi_level_equal": r.witness["multi_level_equal"],
                               "mirror": r.witness["seed000_is_mirror_of_seed001"]} for d, r in rows.items()},
                  provenance={"method": "exact rational arithmetic"})


def claim_reproduction() -> Result:
    """'locally different analytic curves like trigonometric curves can be reproduced and blended'."""
    r = nu.reproduce("circle", degree=2, levels=8)
    b = nu.junction_smoothness(2, 0.5, 2.0, levels=12, rule="seed000")
    return Result(value="circle arcs reproduced exactly up to rounding; blends are C^1 for d = 2",
                  status=NUMERICAL, witness={"circle_form_error": r.witness["form_error"][-1],
                                             "blend_d2": b.value},
                  provenance={"method": "float64 / mpmath"})


CLAIMS: list[dict] = [
    {"id": "000:eta", "statement": "f_{2i} = (1 - eta(lambda_i)) f_i + eta(lambda_i) f_{i+1}, eta(x) = 1/(2(1+x))",
     "check": claim_eta},
    {"id": "000:S_d", "statement": "(S_d f)_i = 2^{2-d} sum_j binom(d-2,j) (S_2 f)_{i+j-tau_d}, tau_d = ceil((d-2)/2); "
     "lambda_{2i} = lambda_{2i+1} = sqrt((1+lambda_i)/2)", "check": claim_s_d},
    {"id": "000:reproduction", "statement": "locally different analytic curves like trigonometric curves can be "
     "reproduced and blended", "check": claim_reproduction},
]

_BY_ID: dict[str, Callable[[], Result]] = {c["id"]: c["check"] for c in CLAIMS}


def check(claim_id: str) -> Result:
    """Evaluate one claim by id."""
    try:
        return _BY_ID[claim_id]()
    except KeyError:
        raise AnalysisError(f"unknown claim {claim_id!r}; seed 000 has {', '.join(_BY_ID)}") from None


# ============================================================================================
# The paper's claims (proof-check): PAPER = Paper(...), evaluated by `subdiv report 000`.
# Verdicts come from the engine (analysis.nonuniform) and exact identities, never typed in.
# ============================================================================================



def _v_s_d():
    r = claim_s_d()
    ok_b, ev_b = bspline_special_case()
    per = r.witness
    rows = tuple((str(d), r.value[d], str(per[d]["tau_d"])) for d in per)
    cmp_ok = all(nu.compare_definitions(d, levels=1).witness["one_step_equal_up_to_shift"] for d in range(2, 7))
    ev = [C.Evidence("seed 000's S_d vs seed 001's (6) (exact rational refinement)", result=r,
                     table=(("d", "relation", "tau_d"),) + rows),
          C.Evidence("one step with equal edge parameters: equal up to the shift tau_d, d = 2..6",
                     result=C.exact_result(cmp_ok, "exact rational refinement")), ev_b]
    if r.status != "certified":
        return C.inconclusive("the relation of the two definitions is seen on an exact example but not proved "
                              "symbolically", settle="a symbolic comparison (analysis.nonuniform.compare_definitions)",
                              evidence=ev)
    if cmp_ok and ok_b:
        return C.certified("True as a definition: (S_d f)_i is d - 2 pairwise averages of S_2 f (seed 001's (6)) "
                           "shifted by tau_d; with lambda = 1 it is the uniform B-spline of degree d (so 'order d' "
                           "here means degree d: the B-spline of order d + 1).",
                           evidence=ev, numbers=[C.Number("tau_4", per[4]["tau_d"]), C.Number("tau_5", per[5]["tau_d"])])
    return C.refuted("S_d is not the averaged S_2", "see evidence", evidence=ev)


def _v_update():
    rows, even_diff, odd_same = [], [], []
    for d in range(2, 8):
        r = nu.compare_definitions(d, levels=3)
        w = r.witness
        rows.append((str(d), str(w["multi_level_equal"]), str(w["seed000_is_mirror_of_seed001"]), r.value))
        (odd_same if d % 2 and w["multi_level_equal"] else even_diff if not w["multi_level_equal"] else []).append(d)
    lam = nu.lemma_2_1(0, 100)
    res = C.exact_result({"differ": even_diff, "equal": odd_same}, "exact rational refinement (compare_definitions)")
    ev = [C.Evidence("3 levels of seed 000 vs seed 001 (same data, same initial parameters, exact)", result=res,
                     table=(("d", "equal after 3 levels", "seed 000 = mirror image of 001", "relation"),) + tuple(rows)),
          C.Evidence("lambda^k -> 1, ||Lambda^k|| <= max(1, ||Lambda^0||) for lambda^0 in [0, 100]", result=lam)]
    if even_diff and all(d % 2 == 0 for d in even_diff):
        return C.refuted(
            "As the parameter update of seed 001's NVPS (the journal version) it disagrees for even d: seed 000 gives "
            "both children of edge i the parameter of edge i, seed 001's (2) gives the corner edge 2i+1 that of edge "
            "i+1. Both are valid schemes (for even d mirror images of each other; for odd d, with the shift tau_d, "
            "the same scheme), and lambda^k -> 1 in both.",
            corrected="lambda^{k+1}_{2i} = lambda^{k+1}_{2i+1} = sqrt((1 + lambda^k_i)/2) defines seed 001's NVPS only "
                      "for odd d; for even d seed 001 uses u^{k+1}_{2i} = sqrt((1+u^k_i)/2), "
                      "u^{k+1}_{2i+1} = sqrt((1+u^k_{i+1})/2), the mirror image of this rule",
            evidence=ev, numbers=[C.Number("even_degrees_differing", len(even_diff)),
                                  C.Number("odd_degrees_equal", len(odd_same))])
    return C.certified("the updates agree", evidence=ev)


def _v_reproduction():
    ids, ev_exact = exponential_evidence()
    r = nu.reproduce("circle", degree=2, levels=8)
    ev_num = C.Evidence("float64 replay, circle, d = 2, 8 levels (illustration)",
                        text=f"form error of the level-8 polygon {roundoff_text(r.witness['form_error'][-1])}")
    ok = all(ids[k] for k in ("geometric", "update", "factor"))
    fig = blended_figure("000-blended", "seed000")
    if ok:
        return C.certified(
            "True: an edge sequence with lambda = cos(phi) on a regular polygon of angle step 2 phi (suitably scaled) "
            "is mapped by S_2 and the update to a regular polygon of step phi with lambda = cos(phi/2) (exact "
            "identities), so trigonometric (and, with cosh, hyperbolic) pieces are reproduced; pieces with "
            "different lambda are blended in one curve (figure).",
            evidence=[ev_exact, ev_num], figures=[fig],
            numbers=[C.Number("form_error_below_1e-12", bool(r.witness["form_error"][-1] < 1e-12))])
    return C.refuted("an identity fails", "see evidence", evidence=[ev_exact, ev_num], figures=[fig])


def _v_regularity():
    eq = _v_equivalence()
    js = {d: nu.junction_smoothness(d, 0.3, 4.0, levels=14, rule="seed000") for d in (2, 3, 4)}
    ev = list(eq.evidence) + [C.Evidence(
        "(d-1)-th divided differences at a junction lambda = 0.3 | 4, seed 000's rules (mpmath)",
        result=js[4], table=(("d", "verdict", "last omega_k"),) + tuple(
            (str(d), j.value, f"{j.witness['omega_junction'][-1]:.3e}") for d, j in js.items()))]
    return C.inconclusive(
        "The relation holds (certified for seed 001's indexing, the same masks up to the index shift): the scheme "
        "is asymptotically equivalent to the uniform B-spline of degree d, the mask distances decaying like 4^-k. "
        "The abstract states no regularity result; numerically the limit is C^(d-1) at parameter junctions for "
        "d = 2, 3 only (d = 4: the third divided differences do not converge), as for seed 001 (Theorem 3.6).",
        settle="the regularity theorem itself (not in the abstract): see 001:Theorem3.6 and 001:(19); asymptotic "
               "equivalence gives C^0 and, with sum 2^k ||.|| < oo, C^1 only; higher orders need Property A.",
        evidence=ev, numbers=[C.Number("omega_d4_junction", js[4].witness["omega_junction"][-1], tol=0.05)])


#: the claims and metadata are data (issue 11): papers/seed000/paper.toml; S_2 and tau_d are identities
#: (kind identity), the other claims `python` claims naming their evaluators above (imported by name)
PAPER = load_paper(Path(__file__).with_name("paper.toml"), python="bundled")   # the tool's own evaluators
PAPER_CLAIMS = list(PAPER.claims)
