"""Seed 001: M. Fang, B. Jeong, J. Yoon, *A non-uniform subdivision scheme with variable
parameters for curve design* (preprint, 17 pp.) — the NVPS of degree d and its claims.

The schemes are :class:`analysis.nonuniform.NVPS` objects (non-uniform: the mask depends on the
level and the location through the edge parameters), so they are **not** catalogue
``SchemeEntry`` objects (those hold one Laurent symbol). Their limit masks are the uniform
B-splines (catalogue ``bspline-d``, up to the shift ``z^{-d}`` vs the catalogue's centring).

The folder, by job:

* :mod:`~papers.seed001.transcription` — the claims as printed (the text extraction garbled some
  formulas; each claim says how it was read) and ``PAPER``, evaluated by ``subdiv report 001``;
* :mod:`~papers.seed001.results` — one engine :class:`analysis.result.Result` per statement, the
  dict-based ``CLAIMS`` and :func:`check` (``subdiv nonuniform claims --seed 001``), ``SCHEMES``;
* :mod:`~papers.seed001.identities` — exact symbolic identities shared by several claims (and seed 000);
* :mod:`~papers.seed001.claims_sec1_3` — the evaluators of Sects. 1-3 (definition, convergence, smoothness);
* :mod:`~papers.seed001.examples` — the evaluators of Sect. 4 and the remarks (reproduction, locality,
  chamfering);
* :mod:`~papers.seed001.figures` — the figure data of the report.

Examples
--------
>>> SCHEMES["nvps-2"]
NVPS(degree=2, rule='seed001')
>>> [c["id"] for c in CLAIMS][:3]
['001:(2)-(6)', '001:Lemma2.1', '001:(12)']
>>> check("001:(17)").status
'refuted'
>>> PAPER.id, len(PAPER.claims)
('001', 28)
"""

from __future__ import annotations

from .results import CLAIMS, SCHEMES, SOURCE, check
from .transcription import PAPER

__all__ = ["CLAIMS", "PAPER", "SCHEMES", "SOURCE", "check"]
