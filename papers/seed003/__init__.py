"""Seed 003: W. us Salam, S. S. Siddiqi, K. Rehan, *Chaikin's perturbation subdivision scheme in
non-stationary forms*, Alexandria Engineering Journal (2016), doi:10.1016/j.aej.2016.07.002.

The paper's checkable claims: ``PAPER`` (``subdiv report 003``), read from the paper file
``papers/seed003/paper.toml`` (issue 11): every claim's statement as printed (LaTeX of the
extraction, lightly de-marked-up), our reading, the kind and its fields. Its schemes, rule (1)
(``dfh-chaikin-perturbation``) and the level-dependent forms (2)-(5) with the comparison scheme
[11], are catalogue entries (:mod:`schemes.seed003`; the file names (2) and (3) ``form2``, ``form3``).

Data, no Python (issue 11): the inequalities (1)-(6) of Sect. 3.3 and Lemmas 3.1-3.2 (kind
``inequality``: parts, dilation cover, exact cancellation, corrections), the definition items and
stencil sums (kind ``identity``), the factorizations of Lemma 3.3 and Corollary 3.1 (kind
``factorization``), the printed d(z) of Lemma 3.4, the curve comparisons of Sects. 6-7 (kind
``curve comparison``) and the smoothness profile of rule (1). The
bespoke evaluators that the remaining ``python`` claims name are here:

* :mod:`.derivations` — computations shared by several claims (C^2 set of rule (1), norm sets);
* :mod:`.figures` — the alpha(omega) plot;
* the evaluators by section: :mod:`.claims_sec2`, :mod:`.claims_sec3_lemmas` (Lemma 3.4),
  :mod:`.claims_sec3_theorem` (Theorem 3.1, Corollary 3.2), :mod:`.claims_sec4_5` (normalized
  schemes, (7), Theorem 5.1); :mod:`.by_name` calls
  those whose arguments are scheme objects by the form's name.

Every verdict is computed by the engine, never typed in.

Examples
--------
>>> from papers.seed003 import PAPER
>>> PAPER.id, len(PAPER.claims)
('003', 42)
>>> PAPER.claim("003:Lemma3.4(d)").kind, PAPER.claim("003:Lemma3.3").kind
('identity', 'factorization')
>>> PAPER.claim("003:Sec2(profile)").kind
'smoothness profile'
"""

from __future__ import annotations

from papers import load_bundled

#: the claims and metadata are data (issue 11): papers/seed003/paper.toml
PAPER = load_bundled(__file__)
CLAIMS = list(PAPER.claims)
