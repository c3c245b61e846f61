"""Seed 001: M. Fang, B. Jeong, J. Yoon, *A non-uniform subdivision scheme with variable
parameters for curve design* (preprint, 17 pp.) — the NVPS of degree d and its claims.

The claims and metadata are data: ``papers/seed001/paper.toml`` (issue 11). The schemes are
:class:`analysis.nonuniform.NVPS` objects (non-uniform: the mask depends on the level and the
location through the edge parameters), not catalogue entries, so the claims about them are
``python`` claims naming their evaluators here: :mod:`~papers.seed001.claims_sec1_3` (Sects. 1-3),
:mod:`~papers.seed001.examples` (Sect. 4, remarks), with the exact identities of
:mod:`~papers.seed001.identities` and the figure data of :mod:`~papers.seed001.figures` (both shared
with seed 000). ``CLAIMS`` / :func:`check` (``subdiv nonuniform claims --seed 001``) evaluate the
claims of the paper file.

Examples
--------
>>> SCHEMES["nvps-2"]
NVPS(degree=2, rule='seed001')
>>> [c["id"] for c in CLAIMS][:3]
['001:Abstract(special cases)', '001:(3)Chaikin', '001:(4)']
>>> check("001:(17)").status
'refuted'
>>> PAPER.id, len(PAPER.claims)
('001', 28)
"""

from __future__ import annotations

from analysis import nonuniform as nu
from analysis.result import AnalysisError

from .. import load_bundled

SOURCE = ("M. Fang, B. Jeong, J. Yoon, A non-uniform subdivision scheme with variable parameters for curve "
          "design (preprint), seed 001")
#: NVPS of degree 2..8 with seed 001's indexing and parameter inheritance (rules (2), (6), Algorithm 1).
SCHEMES = {f"nvps-{d}": nu.NVPS(d, "seed001") for d in range(2, 9)}
PAPER = load_bundled(__file__)
#: the claims of the paper file, as ``subdiv nonuniform claims --seed 001`` lists them
CLAIMS = [{"id": c.id, "statement": c.statement, "check": c.evaluate} for c in PAPER.claims]


def check(claim_id: str):
    """The :class:`~analysis.claims.Verdict` of one claim, by id."""
    for c in CLAIMS:
        if c["id"] == claim_id:
            return c["check"]()
    raise AnalysisError(f"unknown claim {claim_id!r}; seed 001 has {', '.join(c['id'] for c in CLAIMS)}")


__all__ = ["CLAIMS", "PAPER", "SCHEMES", "SOURCE", "check"]
