"""Seed 003 as printed: the lemma inequalities and identities of Sect. 3.3 and the printed
statements that the claims quote (LaTeX of the extraction, lightly de-marked-up).

The lemma tables are checked in ``tests/test_bounds.py`` and by ``subdiv bound --claim ID``; the
stencils of rules (1)-(5) themselves belong to the catalogue entries (:mod:`schemes.seed003`).

Examples
--------
>>> import sympy as sp
>>> from papers.seed003.transcription import LEMMA_3_1, LEMMA_3_4_D
>>> sorted(LEMMA_3_1)[:2]
['003:Lemma3.1(ii)-lower', '003:Lemma3.1(ii)-upper']
>>> LEMMA_3_4_D.subs(sp.Symbol("z"), 1)            # the printed d(z): d(1) = -2, not 2
-2
"""

from __future__ import annotations

import sympy as sp

from schemes.seed003 import BETA, GAMMA, OMEGA
# Lemmas 3.1 and 3.2 item by item, id -> (lhs, rhs, strict): defined in the catalogue module for
# now, because `subdiv bound --claim ID` (analysis/cli/levels.py) reads them there; move them here
# when the command reads papers.seed003 (layout issue 10).
from schemes.seed003 import LEMMA_3_1, LEMMA_3_1_CORRECTED, LEMMA_3_2  # noqa: F401  (re-exported)

# --------------------------------------------------------------------------------------------
# the paper's lemma identities and symbols, as printed (checked in tests/test_bounds.py)
# --------------------------------------------------------------------------------------------

_Q = sp.Rational(1, 4)

_Zs = sp.Symbol("z")


def lemma_3_3_e(coeffs) -> sp.Expr:
    """The paper's e^n(z) of Lemma 3.3 / Corollary 3.1, as printed, from (b0, b1, b2, b3)."""
    b0, b1, b2, b3 = coeffs
    z = _Zs
    return 2 * (b3 * z ** -4 + (b0 - b3) * z ** -3 - (b0 - b2 - b3) * z ** -2
                + (b0 - b2 + b1 - b3) * z ** -1 + (-b0 + b3 + b2) + (b0 - b3) * z + b3 * z ** 2)


#: Lemma 3.4's d(z) as printed.
LEMMA_3_4_D = 2 * (5 * OMEGA * _Zs ** -4 + 2 * OMEGA * _Zs ** -3 - _Q * (1 + 20 * OMEGA) * _Zs ** -2
                   + sp.Rational(1, 2) * (-1 - 8 * OMEGA) * _Zs ** -1 + _Q * (-1 - 20 * OMEGA)
                   + 2 * OMEGA * _Zs + 5 * OMEGA * _Zs ** 2)

#: Lemma 3.1 (iii) and (vii) as corrected: statement and id in LEMMA_3_1_CORRECTED.
_L31_CORR = {"iii": ("1/4 + 3 omega <= beta_2^n <= (1/4)/c(alpha/2^n) + 3 omega", "003:Lemma3.1(iii)-upper-corrected"),
             "vii": ("1/4 + 3 omega >= gamma_2^n > (1/4)/c'(alpha/2^n) + 3 omega", "003:Lemma3.1(vii)-lower-corrected")}


# --------------------------------------------------------------------------------------------
# the definition items of the lemmas
# --------------------------------------------------------------------------------------------

# (the statements as printed are in paper.toml)
#: the items of Lemmas 3.1 and 3.2 that are definitions (checked as identities).
_DEF = {"i": (BETA[0], -7 * OMEGA, "beta_0^n = -7 omega"), "iv": (BETA[3], -5 * OMEGA, "beta_3^n = -5 omega"),
        "v": (GAMMA[0], -7 * OMEGA, "gamma_0^n = -7 omega"), "viii": (GAMMA[3], -5 * OMEGA, "gamma_3^n = -5 omega")}
_DEF2 = {"i": (sp.Abs(BETA[0] + 7 * OMEGA), 0, "|beta_0^n + 7 omega| = 0"),
         "iv": (sp.Abs(BETA[3] + 5 * OMEGA), 0, "|beta_3^n + 5 omega| = 0"),
         "v": (sp.Abs(GAMMA[0] + 7 * OMEGA), 0, "|gamma_0^n + 7 omega| = 0"),
         "viii": (sp.Abs(GAMMA[3] + 5 * OMEGA), 0, "|gamma_3^n + 5 omega| = 0")}
