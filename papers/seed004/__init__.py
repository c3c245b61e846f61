"""Seed 004: *Modeling of curves by a design-control approximating refinement scheme*
(Taylor & Francis, pp. 164-178, received 22 Apr 2022, published online 28 Mar 2023).

The paper's checkable claims: ``PAPER`` (``subdiv report 004``), read from the paper file
``papers/seed004/paper.toml`` (issue 11). Its schemes (3.6), (3.7), (3.8) are catalogue entries
(:mod:`schemes.seed004`). Every claim that fits a kind is data (the construction Steps 1-4 too: kind
``construction``); the genuinely special evaluators that the file's ``python`` claims name are in
:mod:`.special` (the printed matrix form of (3.6), the nonzero points after L steps).

Examples
--------
>>> from papers.seed004 import PAPER
>>> PAPER.id, len(PAPER.claims)
('004', 49)
>>> PAPER.claim("004:(3.9)-(3.10)/P0").kind, PAPER.claim("004:Theorem5.1").kind
('end rules', 'eigenvalue inequality')
"""

from __future__ import annotations

from papers import load_bundled

#: the claims and metadata are data (issue 11): papers/seed004/paper.toml
PAPER = load_bundled(__file__)
CLAIMS = list(PAPER.claims)
