"""Seed 004 (catalogue): *Modeling of curves by a design-control approximating refinement scheme*
(Taylor & Francis, pp. 164-178, received 22 Apr 2022, published online 28 Mar 2023).

Section 3 builds a 6-point scheme with three design-control parameters mu, nu, omega:

* (3.1) Q: the cubic-reproducing dual 4-point scheme, ``Q_{2i} = [-7, 105, 35, -5]/128`` on
  ``P_{i-1..i+2}`` (the paper calls it "4-point approximating", after Deslauriers-Dubuc);
* (3.2) R: the degree-6 B-spline, ``R_{2i} = [7, 35, 21, 1]/64`` on ``P_{i-1..i+2}``;
* (3.3)-(3.4) displacements ``D_j = Q_j - R_j`` and their shifts ``D_{2i±2}``, ``D_{2i-1}``,
  ``D_{2i+3}``;
* (3.5) ``DE = mu D_{2i-2} + nu D_{2i} + omega D_{2i+2}``,
  ``DO = omega D_{2i-1} + nu D_{2i+1} + mu D_{2i+3}``;
* (3.6) ``P_{2i} = Q_{2i} - DE``, ``P_{2i+1} = Q_{2i+1} - DO``;
* sub-schemes (3.7) ``mu = omega = 0`` and (3.8) ``omega = mu, nu = 1 - 2 mu``.

The text extraction dropped minus signs and fraction bars (``7128`` is ``-7/128`` or ``7/128``);
the transcriptions below are the readings that the construction reproduces exactly
(``tests/test_catalogue.py`` rebuilds (3.6) from (3.1)-(3.5)).

This module holds the paper's schemes only: the printed rules (3.1)-(3.8) and the catalogue
entries ``seed004-design-control``, ``seed004-t-nu`` and ``seed004-l-mu``. The text as printed
(garbled), the derivations and the checkable claims are in :mod:`papers.seed004`
(``subdiv report 004``).

Examples
--------
>>> from schemes import get
>>> e = get("seed004-design-control")
>>> e.param_names, e.symbol.support
(('mu', 'nu', 'omega'), (-6, 5))
>>> e.symbol_at(mu=0, nu=0, omega=0).mask        # mu = nu = omega = 0 is Q, rule (3.1)
(-5/128, -7/128, 35/128, 105/128, 105/128, 35/128, -7/128, -5/128)
>>> get("seed004-l-mu").symbol_at(mu=0) == get("bspline-6").symbol.shift(-1)   # R, rule (3.2)
True
"""
from __future__ import annotations

import sympy as sp

from analysis.algebra.symbol import LaurentSymbol, Rules

from .catalogue import SchemeEntry

MU, NU, OMEGA = sp.symbols("mu nu omega")

_SOURCE = ("Modeling of curves by a design-control approximating refinement scheme, pp. 164-178 "
           "(published online 28 Mar 2023), seed 004")


def _r(n: int, d: int = 128) -> sp.Rational:
    return sp.Rational(n, d)


# --------------------------------------------------------------------------------------------
# transcriptions of the printed rules (coefficients of P_{i+p}, p = first, first+1, ...)
# --------------------------------------------------------------------------------------------

#: (3.1) the 4-point rule Q on P_{i-1}..P_{i+2}.
RULE_3_1 = Rules(even=(_r(-7), _r(105), _r(35), _r(-5)), even_first=-1,
                 odd=(_r(-5), _r(35), _r(105), _r(-7)), odd_first=-1)

#: (3.2) the degree-6 B-spline rule R on P_{i-1}..P_{i+2}.
RULE_3_2 = Rules(even=(_r(7, 64), _r(35, 64), _r(21, 64), _r(1, 64)), even_first=-1,
                 odd=(_r(1, 64), _r(21, 64), _r(35, 64), _r(7, 64)), odd_first=-1)

#: (3.3) the displacements D_{2i} = Q_{2i} - R_{2i}, D_{2i+1} = Q_{2i+1} - R_{2i+1}
#: on P_{i-1}..P_{i+2}.
RULE_3_3 = Rules(even=(_r(-21), _r(35), _r(-7), _r(-7)), even_first=-1,
                 odd=(_r(-7), _r(-7), _r(35), _r(-21)), odd_first=-1)

#: (3.6) the coefficients under the paper's labels a_k (the paper's label k is our index k-1).
A_3_6 = {
    5: 21 * MU / 128,                               # a_5 = a_-4
    3: (-7 - 35 * MU + 21 * NU) / 128,              # a_3 = a_-2
    1: (105 + 7 * MU - 35 * NU + 21 * OMEGA) / 128,  # a_1 = a_0
    -1: (35 + 7 * MU + 7 * NU - 35 * OMEGA) / 128,  # a_-1 = a_2
    -3: (-5 + 7 * NU + 7 * OMEGA) / 128,            # a_-3 = a_4
    -5: 7 * OMEGA / 128,                            # a_-5 = a_6
}
A_3_6.update({-4: A_3_6[5], -2: A_3_6[3], 0: A_3_6[1], 2: A_3_6[-1], 4: A_3_6[-3], 6: A_3_6[-5]})

#: (3.6) P_{2i} = a5 P_{i-2} + a3 P_{i-1} + a1 P_i + a-1 P_{i+1} + a-3 P_{i+2} + a-5 P_{i+3},
#: P_{2i+1} = a6 P_{i-2} + a4 P_{i-1} + a2 P_i + a0 P_{i+1} + a-2 P_{i+2} + a-4 P_{i+3}.
RULE_3_6 = Rules(even=tuple(A_3_6[k] for k in (5, 3, 1, -1, -3, -5)), even_first=-2,
                 odd=tuple(A_3_6[k] for k in (6, 4, 2, 0, -2, -4)), odd_first=-2)

#: The mask of (3.6) as printed after the matrix form: {..., 0, a6, a5, ..., a-4, 0, ...}.
PRINTED_MASK_3_6 = tuple(A_3_6[k] for k in range(6, -6, -1))

#: (3.7) the coefficients t_k (mu = omega = 0).
T_3_7 = {
    3: (-7 + 21 * NU) / 128,       # t_3 = t_-2
    1: (105 - 35 * NU) / 128,      # t_1 = t_0
    -1: (35 + 7 * NU) / 128,       # t_-1 = t_2
    -3: (-5 + 7 * NU) / 128,       # t_-3 = t_4
}
T_3_7.update({-2: T_3_7[3], 0: T_3_7[1], 2: T_3_7[-1], 4: T_3_7[-3]})
RULE_3_7 = Rules(even=tuple(T_3_7[k] for k in (3, 1, -1, -3)), even_first=-1,
                 odd=tuple(T_3_7[k] for k in (4, 2, 0, -2)), odd_first=-1)

#: (3.8) the coefficients l_k (omega = mu, nu = 1 - 2 mu), as printed.
L_3_8 = {
    5: 21 * MU / 128,                           # l_5 = l_-4
    3: sp.Rational(7, 64) - 77 * MU / 128,      # l_3 = l_-2
    1: sp.Rational(35, 64) + 49 * MU / 64,      # l_1 = l_0
    -1: sp.Rational(21, 64) - 21 * MU / 64,     # l_-1 = l_2
    -3: sp.Rational(1, 64) - 7 * MU / 128,      # l_-3 = l_4
    -5: 7 * MU / 128,                           # l_-5 = l_6
}
L_3_8.update({-4: L_3_8[5], -2: L_3_8[3], 0: L_3_8[1], 2: L_3_8[-1], 4: L_3_8[-3], 6: L_3_8[-5]})
RULE_3_8 = Rules(even=tuple(L_3_8[k] for k in (5, 3, 1, -1, -3, -5)), even_first=-2,
                 odd=tuple(L_3_8[k] for k in (6, 4, 2, 0, -2, -4)), odd_first=-2)

#: The mask of (3.8) as printed: {..., 0, l6, l5, ..., l-4, 0, ...}.
PRINTED_MASK_3_8 = tuple(L_3_8[k] for k in range(6, -6, -1))

#: The substitutions that give the sub-schemes from (3.6).
SUBSTITUTION_3_7 = {MU: 0, OMEGA: 0}
SUBSTITUTION_3_8 = {OMEGA: MU, NU: 1 - 2 * MU}


def _from(rules: Rules) -> LaurentSymbol:
    return LaurentSymbol.from_rules(rules.even, rules.odd, even_first=rules.even_first,
                                    odd_first=rules.odd_first)


_SIGNS = ("The extraction dropped minus signs and fraction bars; signs read so that the "
          "coefficients equal Q_{2i} - DE from (3.1)-(3.5) (checked in tests). ")
_LABELS = ("The paper labels the coefficient of P_{i-2} in P_{2i} as a_5; with "
           "(S_a f)_i = sum_j a_{i-2j} f_j it is a_4: the paper's label k is our index k-1, so the "
           "entry follows the printed rules, not the labels (support [-6, 5]). ")

ENTRIES: tuple[SchemeEntry, ...] = (
    SchemeEntry(
        slug="seed004-design-control",
        title="6-point design-control approximating scheme S_{a,mu,nu,omega}",
        symbol=_from(RULE_3_6),
        params=(MU, NU, OMEGA),
        source=_SOURCE + ", eq. (3.6)",
        notes=(_SIGNS + _LABELS + "mu = nu = omega = 0 is Q (3.1); "
               "mu = omega = 0, nu = 1 is R (3.2), "
               "the degree-6 B-spline ('bspline-6' times z^-1). The matrix form after (3.6) "
               "prints a2 for a1 in one row (typo or extraction error), and (3.5) calls DE 'QE'."),
        stencils=RULE_3_6,
    ),
    SchemeEntry(
        slug="seed004-t-nu",
        title="Sub-scheme S_{t,nu} (mu = omega = 0)",
        symbol=_from(RULE_3_7),
        params=(NU,),
        source=_SOURCE + ", eq. (3.7)",
        notes=(_SIGNS + "Transcribed from the printed t_k; equals (3.6) at mu = omega = 0 "
               "(checked in tests). nu = 0 is Q (3.1), nu = 1 is R (3.2)."),
        stencils=RULE_3_7,
    ),
    SchemeEntry(
        slug="seed004-l-mu",
        title="Sub-scheme S_{l,mu} (omega = mu, nu = 1 - 2 mu)",
        symbol=_from(RULE_3_8),
        params=(MU,),
        source=_SOURCE + ", eq. (3.8)",
        notes=(_SIGNS + "The text gives the substitution as 'nu=2mu+1' in Section 3.6 and "
               "'nu=12mu' in Corollary 4.6 (minus signs lost in extraction: -2mu+1 and 1-2mu); "
               "nu = 1 - 2 mu is the reading that "
               "reproduces the printed l_k (l_5 = 21/128 mu, l_3 = 7/64 - 77/128 mu, "
               "l_1 = 35/64 + 49/64 mu, l_-1 = 21/64 - 21/64 mu, l_-3 = 1/64 - 7/128 mu, "
               "l_-5 = 7/128 mu) and Remark 3.3 (DE = D_{2i} + mu[(D_{2i-2} - D_{2i}) + "
               "(D_{2i+2} - D_{2i})]); nu = 1 + 2 mu does not (checked in tests). "
               "mu = 0 is R (3.2), the degree-6 B-spline."),
        stencils=RULE_3_8,
    ),
)
