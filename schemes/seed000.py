"""Seed 000: M. Fang, B. Jeong, J. Yoon, *Non-uniform subdivision schemes reproducing locally
different curves* (conference abstract) — the conference version of seed 001's NVPS.

Seed 000 writes the shape parameters ``lambda`` on the edges, ``eta(x) = 1/(2(1+x))``,
``f_{2i} = (1 - eta(lambda_i)) f_i + eta(lambda_i) f_{i+1}``,
``f_{2i+1} = eta(lambda_i) f_i + (1 - eta(lambda_i)) f_{i+1}``, the update
``lambda_{2i} = lambda_{2i+1} = sqrt((1 + lambda_i)/2)``, and for d > 2
``(S_d f)_i = 2^{2-d} sum_j binom(d-2, j) (S_2 f)_{i+j-tau_d}``, ``tau_d = ceil((d-2)/2)``.
(The abstract glosses ceil(x) as "the smallest integer larger than x"; with that reading tau_d is
one larger for even d — again only an index shift.)

The schemes are :class:`analysis.nonuniform.NVPS` objects with ``rule="seed000"`` (not catalogue
``SchemeEntry`` objects: the masks depend on level and location).

Examples
--------
>>> SCHEMES["nvps000-3"]
NVPS(degree=3, rule='seed000')
>>> check("000:eta").status
'certified'
"""

from __future__ import annotations

from typing import Callable

import sympy as sp

from analysis import nonuniform as nu
from analysis.result import CERTIFIED, NUMERICAL, REFUTED, AnalysisError, Result

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
    return Result(value={d: r.value for d, r in rows.items()}, status=CERTIFIED,
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
