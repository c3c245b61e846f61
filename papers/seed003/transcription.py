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
# printed statements quoted by the claims
# --------------------------------------------------------------------------------------------

#: Sect. 3.3, inequalities (1)-(6); Lemma 3.1 and Lemma 3.2, item by item.
_INEQ_PRINTED = {
    1: r"\frac{s(x)}{s(y)} \geq \frac{x}{y}, \quad 0 < x \leq y < \frac{\pi}{2},",
    2: r"\theta \csc(\theta) < t \csc(t), \quad 0 < \theta < t < \frac{\pi}{2}",
    3: r"c(x) < \frac{s(x)}{x}, \quad 0 < x < \frac{\pi}{2}.",
    4: r"\frac{s'(x)}{s'(y)} \leq \frac{x}{y}, \quad 0 < x \leq y, \quad x, y \in \mathbb{R}^+ \setminus n'\pi,",
    5: r"\theta \operatorname{csch}(\theta) > t \operatorname{csch}(t), \quad 0 < \theta < t, \quad \theta, t \in "
       r"\mathbb{R}^+ \setminus n'\pi",
    6: r"c'(x) > \frac{s'(x)}{x}, \quad x \in \mathbb{R}^+ \setminus n'\pi.",
}
_L31_PRINTED = {
    "i": r"\beta_0^n = -7\omega,", "ii": r"\frac{3}{4} + 9\omega \leq \beta_1^n \leq \frac{3}{4} \frac{1}{c(\frac{\alpha}{2^n})} + 9\omega,",
    "iii": r"\frac{1}{4} + 3\omega \leq \beta_2^n \leq \frac{1}{4} \frac{1}{c'(\frac{\alpha}{2^n})} + 3\omega,",
    "iv": r"\beta_3^n = -5\omega,", "v": r"\gamma_0^n = -7\omega,",
    "vi": r"\frac{3}{4} + 9\omega \geq \gamma_1^n > \frac{3}{4} \frac{1}{c'(\frac{\alpha}{2^n})} + 9\omega,",
    "vii": r"\frac{1}{4} + 3\omega \geq \gamma_2^n > \frac{1}{4} \frac{1}{c(\frac{\alpha}{2^n})} + 3\omega,",
    "viii": r"\gamma_3^n = -5\omega."}
_L32_PRINTED = {
    "i": r"|\beta_0^n + 7\omega| = 0,", "ii": r"|\beta_1^n - \frac{3}{4} - 9\omega| \leq C_1 \frac{1}{2^{2n}},",
    "iii": r"|\beta_2^n - \frac{1}{4} - 3\omega| \leq C_2 \frac{1}{2^{2n}},", "iv": r"|\beta_3^n + 5\omega| = 0,",
    "v": r"|\gamma_0^n + 7\omega| = 0,", "vi": r"|\gamma_1^n - \frac{3}{4} - 9\omega| < C_3 \frac{1}{2^{2n}},",
    "vii": r"|\gamma_2^n - \frac{1}{4} - 3\omega| < C_4 \frac{1}{2^{2n}},", "viii": r"|\gamma_3^n + 5\omega| = 0,"}
#: the items of Lemmas 3.1 and 3.2 that are definitions (checked as identities).
_DEF = {"i": (BETA[0], -7 * OMEGA, "beta_0^n = -7 omega"), "iv": (BETA[3], -5 * OMEGA, "beta_3^n = -5 omega"),
        "v": (GAMMA[0], -7 * OMEGA, "gamma_0^n = -7 omega"), "viii": (GAMMA[3], -5 * OMEGA, "gamma_3^n = -5 omega")}
_DEF2 = {"i": (sp.Abs(BETA[0] + 7 * OMEGA), 0, "|beta_0^n + 7 omega| = 0"),
         "iv": (sp.Abs(BETA[3] + 5 * OMEGA), 0, "|beta_3^n + 5 omega| = 0"),
         "v": (sp.Abs(GAMMA[0] + 7 * OMEGA), 0, "|gamma_0^n + 7 omega| = 0"),
         "viii": (sp.Abs(GAMMA[3] + 5 * OMEGA), 0, "|gamma_3^n + 5 omega| = 0")}
