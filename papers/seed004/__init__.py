"""Seed 004: *Modeling of curves by a design-control approximating refinement scheme*
(Taylor & Francis, pp. 164-178, received 22 Apr 2022, published online 28 Mar 2023).

The paper's checkable claims: ``PAPER`` (``subdiv report 004``), read from the paper file
``papers/seed004/paper.toml`` (issue 11): every claim's statement as printed, the reading, the
kind and its fields. Its schemes, the 6-point scheme (3.6) and the sub-schemes (3.7), (3.8), with
the printed rules (3.1)-(3.8), are catalogue entries (:mod:`schemes.seed004`). The bespoke
evaluators that the ``python`` claims of the file name are here:

* :mod:`.transcription` — the garbled printed text (lost minus signs and fraction bars);
* :mod:`.derivations` — the construction Steps 1-4, the boundary rules, exact parameter sets;
* :mod:`.figures` — basic limit functions, norm curves, the Gibbs experiment;
* the evaluators by section: :mod:`.claims_sec2_3` (sum rules, construction, sub-schemes,
  boundary rules), :mod:`.claims_sec4_5` (supports, eigenvalues, C^k ranges),
  :mod:`.claims_sec6_7` (Gibbs, C^6).

The smoothness profiles of (3.7) and (3.8) (issue 11, item 5) are ``smoothness profile`` claims
of the file: no Python. Verdicts come from the engine, never typed in.

Examples
--------
>>> from papers.seed004 import PAPER
>>> PAPER.id, len(PAPER.claims)
('004', 49)
>>> PAPER.claim("004:(3.6)").kind
'mask identity'
>>> PAPER.claim("004:Theorem5.1(profile)").kind
'smoothness profile'
"""

from __future__ import annotations

from papers import load_bundled

#: the claims and metadata are data (issue 11): papers/seed004/paper.toml
PAPER = load_bundled(__file__)
CLAIMS = list(PAPER.claims)
