"""Seed 003: W. us Salam, S. S. Siddiqi, K. Rehan, *Chaikin's perturbation subdivision scheme in
non-stationary forms*, Alexandria Engineering Journal (2016), doi:10.1016/j.aej.2016.07.002.

Section 2 recalls the stationary scheme that the paper's trigonometric and hyperbolic
(non-stationary) forms converge to: Dyn–Floater–Hormann's perturbation of Chaikin's scheme,
rule (1)::

    f_{2i}   = -7w f_{i-1} + (3/4+9w) f_i + (1/4+3w) f_{i+1} - 5w f_{i+2}
    f_{2i+1} = -5w f_{i-1} + (1/4+3w) f_i + (3/4+9w) f_{i+1} - 7w f_{i+2}

with w = omega. The paper states: omega = 0 is Chaikin's scheme; C^1 for omega = 0 and C^2 for
0 < omega < (sqrt(6)-1)/80. (The claims will be added to this module.)

Examples
--------
>>> from schemes import get
>>> e = get("dfh-chaikin-perturbation")
>>> e.symbol.support, e.params
((-4, 3), (omega,))
>>> print(e.stencils)
f[2i]   = -7*omega f[i-1] + (9*omega + 3/4) f[i] + (3*omega + 1/4) f[i+1] - 5*omega f[i+2]
f[2i+1] = -5*omega f[i-1] + (3*omega + 1/4) f[i] + (9*omega + 3/4) f[i+1] - 7*omega f[i+2]

References
----------
N. Dyn, M. S. Floater, K. Hormann, *A C^2 four-point subdivision scheme with fourth order accuracy
and its extensions*, in: Mathematical Methods for Curves and Surfaces: Tromsø 2004, Nashboro Press
(2005) 145-156.
"""

from __future__ import annotations

import sympy as sp

from analysis.symbol import LaurentSymbol, Rules

from .catalogue import SchemeEntry

OMEGA = sp.Symbol("omega")

_Q = sp.Rational(1, 4)
#: Rule (1) as printed: coefficients of f_{i-1}, f_i, f_{i+1}, f_{i+2}.
RULE_1 = Rules(even=(-7 * OMEGA, 3 * _Q + 9 * OMEGA, _Q + 3 * OMEGA, -5 * OMEGA), even_first=-1,
               odd=(-5 * OMEGA, _Q + 3 * OMEGA, 3 * _Q + 9 * OMEGA, -7 * OMEGA), odd_first=-1)

ENTRIES: tuple[SchemeEntry, ...] = (
    SchemeEntry(
        slug="dfh-chaikin-perturbation",
        title="Dyn-Floater-Hormann perturbation of Chaikin's scheme",
        symbol=LaurentSymbol.from_rules(RULE_1.even, RULE_1.odd, first=-1),
        params=(OMEGA,),
        source=("W. us Salam, S. S. Siddiqi, K. Rehan, Alexandria Engineering Journal (2016), "
                "doi:10.1016/j.aej.2016.07.002, seed 003, rule (1); after N. Dyn, M. S. Floater, "
                "K. Hormann, Mathematical Methods for Curves and Surfaces: Tromsø 2004 (2005)"),
        notes=("Stencils on f_{i-1..i+2} (first offset -1); omega = 0 is Chaikin's scheme in the "
               "indexing of the 'chaikin' entry (start -2). Default omega = 1/128: the rules "
               "become [-7, 105, 35, -5]/128, the cubic-reproducing dual 4-point scheme "
               "(= seed 004 "
               "rule (3.1)), the 'fourth order accuracy' of the DFH title."),
        defaults={"omega": sp.Rational(1, 128)},
        stencils=RULE_1,
    ),
)
