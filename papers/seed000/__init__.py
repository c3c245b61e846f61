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
``SchemeEntry`` objects: the masks depend on level and location). The claims, their evaluators
and ``PAPER`` are in :mod:`papers.seed000.claims`.

Examples
--------
>>> SCHEMES["nvps000-3"]
NVPS(degree=3, rule='seed000')
>>> check("000:eta").status
'certified'
>>> PAPER.id, len(PAPER.claims)
('000', 6)
"""

from __future__ import annotations

from .claims import CLAIMS, PAPER, SCHEMES, SOURCE, check

__all__ = ["CLAIMS", "PAPER", "SCHEMES", "SOURCE", "check"]
