"""Seed 003 (catalogue): W. us Salam, S. S. Siddiqi, K. Rehan, *Chaikin's perturbation subdivision
scheme in non-stationary forms*, Alexandria Engineering Journal (2016), doi:10.1016/j.aej.2016.07.002.

Section 2 recalls the stationary scheme that the paper's trigonometric and hyperbolic
(non-stationary) forms converge to: Dyn–Floater–Hormann's perturbation of Chaikin's scheme,
rule (1)::

    f_{2i}   = -7w f_{i-1} + (3/4+9w) f_i + (1/4+3w) f_{i+1} - 5w f_{i+2}
    f_{2i+1} = -5w f_{i-1} + (1/4+3w) f_i + (3/4+9w) f_{i+1} - 7w f_{i+2}

with w = omega. The paper states: omega = 0 is Chaikin's scheme; C^1 for omega = 0 and C^2 for
0 < omega < (sqrt(6)-1)/80. This module holds the paper's schemes only: rule (1) (catalogue
entry ``dfh-chaikin-perturbation``) and the level-dependent forms (2)-(5) with the comparison
scheme [11] (``LEVEL_ENTRIES``, listed by :mod:`schemes.level_dependent`), and, for now, the
lemma tables that ``subdiv bound --claim`` reads (see the end). The paper's transcriptions,
derivations and checkable claims are in :mod:`papers.seed003` (``subdiv report 003``).

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

from analysis.algebra.symbol import LaurentSymbol, Rules
from analysis.levels.level_dependent import N, LevelDependentScheme

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


# --------------------------------------------------------------------------------------------
# the level-dependent forms (2), (3) and their normalizations (4), (5)
# --------------------------------------------------------------------------------------------

#: the angle parameter of the trigonometric/hyperbolic forms (positive)
ALPHA = sp.Symbol("alpha", positive=True)

_SOURCE = ("W. us Salam, S. S. Siddiqi, K. Rehan, Alexandria Engineering Journal (2016), "
           "doi:10.1016/j.aej.2016.07.002, seed 003")

#: beta_i^n as printed (trigonometric form (2)), functions of the level n.
BETA = (-7 * OMEGA,
        sp.sin(3 * ALPHA / 2 ** (N + 2)) / sp.sin(ALPHA / 2 ** N) + 9 * OMEGA,
        sp.sin(ALPHA / 2 ** (N + 2)) / sp.sin(ALPHA / 2 ** N) + 3 * OMEGA,
        -5 * OMEGA)
#: gamma_i^n as printed (hyperbolic form (3)).
GAMMA = (-7 * OMEGA,
         sp.sinh(3 * ALPHA / 2 ** (N + 2)) / sp.sinh(ALPHA / 2 ** N) + 9 * OMEGA,
         sp.sinh(ALPHA / 2 ** (N + 2)) / sp.sinh(ALPHA / 2 ** N) + 3 * OMEGA,
         -5 * OMEGA)


def _form(coeffs, slug, title, eq) -> LevelDependentScheme:
    b0, b1, b2, b3 = coeffs
    return LevelDependentScheme.from_rules(
        even=[b0, b1, b2, b3], odd=[b3, b2, b1, b0], first=-1, params=(ALPHA, OMEGA), slug=slug,
        title=title, source=f"{_SOURCE}, rule ({eq})",
        notes="stencils on f_{i-1..i+2} (first offset -1), as rule (1); h = 2^-n",
        defaults={"alpha": sp.pi / 5, "omega": sp.Rational(1, 100)})


#: Scheme (2): the trigonometric form.
TRIGONOMETRIC = _form(BETA, "seed003-trigonometric", "trigonometric Chaikin perturbation", 2)
#: Scheme (3): the hyperbolic form.
HYPERBOLIC = _form(GAMMA, "seed003-hyperbolic", "hyperbolic Chaikin perturbation", 3)
#: The stencil sums as the paper prints them (Section 4): beta^n = c(a/2^{n+2})/c(a/2^{n+1}),
#: gamma^n = c'(a/2^{n+2})/c'(a/2^{n+1}). Proven equal to the sums of (2), (3) in
#: ``tests/test_bounds.py`` (analysis.levels.bounds.check_identity), so (4), (5) divide by them.
BETA_SUM = sp.cos(ALPHA / 2 ** (N + 2)) / sp.cos(ALPHA / 2 ** (N + 1))
GAMMA_SUM = sp.cosh(ALPHA / 2 ** (N + 2)) / sp.cosh(ALPHA / 2 ** (N + 1))


def _normalized(form: LevelDependentScheme, total, slug, eq) -> LevelDependentScheme:
    return LevelDependentScheme(tuple(c / total for c in form.mask), form.start, form.params,
                                slug=slug, title=f"normalized {form.title}",
                                source=f"{_SOURCE}, rule ({eq})",
                                notes="rule (" + str(eq - 2) + ") divided by its stencil sum",
                                defaults=form.defaults)


#: Scheme (4): (2) divided by its stencil sum.
TRIGONOMETRIC_NORMALIZED = _normalized(TRIGONOMETRIC, BETA_SUM, "seed003-trigonometric-normalized", 4)
#: Scheme (5): (3) divided by its stencil sum.
HYPERBOLIC_NORMALIZED = _normalized(HYPERBOLIC, GAMMA_SUM, "seed003-hyperbolic-normalized", 5)

#: The comparison scheme [11] of Sections 6-7 (M. K. Jena, P. Shunmugaraj, P. C. Das, ANZIAM J. 44
#: (2003) E216-E235), *as we reconstruct it*: the paper does not print it. It is the interpolatory
#: 4-point scheme ``f_{2i} = f_i``, ``f_{2i+1} = -w_n (f_{i-1} + f_{i+2}) + (1/2 + w_n)(f_i + f_{i+1})``
#: with ``w_n = 1/(16 cos^2(alpha/2^{n+2}) cos(alpha/2^{n+1}))``, the unique symmetric interpolatory
#: 4-point rule that reproduces {1, cos(alpha x), sin(alpha x)} (certified in the Sect. 6 claim);
#: w_n -> 1/16 (the DD 4-point scheme).
_W11 = 1 / (16 * sp.cos(ALPHA / 2 ** (N + 2)) ** 2 * sp.cos(ALPHA / 2 ** (N + 1)))
JENA_11 = LevelDependentScheme.from_rules(
    even=[0, 1, 0, 0], odd=[-_W11, sp.Rational(1, 2) + _W11, sp.Rational(1, 2) + _W11, -_W11], first=-1,
    params=(ALPHA,), slug="seed003-jena-11", title="interpolatory trigonometric 4-point scheme [11] (reconstructed)",
    source="M. K. Jena, P. Shunmugaraj, P. C. Das, ANZIAM J. 44 (E) (2003) E216-E235 (seed 003 ref. [11]), "
           "reconstructed from its defining property",
    notes="f_2i = f_i, f_2i+1 = -w (f_i-1 + f_i+2) + (1/2 + w)(f_i + f_i+1), "
          "w_n = 1/(16 cos^2(alpha/2^(n+2)) cos(alpha/2^(n+1)))",
    defaults={"alpha": sp.pi / 5})

#: The level-dependent schemes of the paper, by slug.
LEVEL_ENTRIES: dict[str, LevelDependentScheme] = {
    "seed003-trigonometric": TRIGONOMETRIC,
    "seed003-hyperbolic": HYPERBOLIC,
    "seed003-trigonometric-normalized": TRIGONOMETRIC_NORMALIZED,
    "seed003-hyperbolic-normalized": HYPERBOLIC_NORMALIZED,
    "seed003-jena-11": JENA_11,
}


# --------------------------------------------------------------------------------------------
# transitional: the paper's lemma inequalities, as printed (checked in tests/test_bounds.py)
# --------------------------------------------------------------------------------------------
# papers/seed003/paper.toml states the same items as data (kind inequality); `subdiv bound --claim ID`
# (analysis/cli/levels.py) reads these tables, and the catalogue may not import the papers: drop them
# when the command reads the paper file (layout issue 10).

_X = ALPHA / 2 ** N  # the paper's alpha/2^n
_C, _CH = sp.cos(_X), sp.cosh(_X)
_Q = sp.Rational(1, 4)

#: Lemma 3.1 (n > 0, 0 < alpha < pi/3), items (ii), (iii), (vi), (vii), each split into its two
#: inequalities ``lhs <= rhs`` (strict where printed ``<``/``>``): id -> (lhs, rhs, strict).
#: Items (i), (iv), (v), (viii) are the definitions beta_0 = -7 omega etc. (identities).
LEMMA_3_1 = {
    "003:Lemma3.1(ii)-lower": (3 * _Q + 9 * OMEGA, BETA[1], False),
    "003:Lemma3.1(ii)-upper": (BETA[1], 3 * _Q / _C + 9 * OMEGA, False),
    "003:Lemma3.1(iii)-lower": (_Q + 3 * OMEGA, BETA[2], False),
    "003:Lemma3.1(iii)-upper": (BETA[2], _Q / _CH + 3 * OMEGA, False),  # printed with c'
    "003:Lemma3.1(vi)-upper": (GAMMA[1], 3 * _Q + 9 * OMEGA, False),
    "003:Lemma3.1(vi)-lower": (3 * _Q / _CH + 9 * OMEGA, GAMMA[1], True),
    "003:Lemma3.1(vii)-upper": (GAMMA[2], _Q + 3 * OMEGA, False),
    "003:Lemma3.1(vii)-lower": (_Q / _C + 3 * OMEGA, GAMMA[2], True),  # printed with c
}
#: Lemma 3.1 with c and c' exchanged in (iii) and (vii) (our correction).
LEMMA_3_1_CORRECTED = {
    "003:Lemma3.1(iii)-upper-corrected": (BETA[2], _Q / _C + 3 * OMEGA, False),
    "003:Lemma3.1(vii)-lower-corrected": (_Q / _CH + 3 * OMEGA, GAMMA[2], True),
}

_H2 = 1 / sp.Integer(4) ** N
#: Lemma 3.2 with C1 = 3 alpha^2/(8 cos alpha) as proven in the paper; C2..C4 are not given in the
#: paper ("constants independent of n"): we check the constants the paper's method gives,
#: C2 = alpha^2/(8 cos alpha), C3 = 3 alpha^2/8, C4 = alpha^2/8. id -> (lhs, rhs, strict).
LEMMA_3_2 = {
    "003:Lemma3.2(ii)": (sp.Abs(BETA[1] - 3 * _Q - 9 * OMEGA), 3 * ALPHA ** 2 / (8 * sp.cos(ALPHA)) * _H2, False),
    "003:Lemma3.2(iii)": (sp.Abs(BETA[2] - _Q - 3 * OMEGA), ALPHA ** 2 / (8 * sp.cos(ALPHA)) * _H2, False),
    "003:Lemma3.2(vi)": (sp.Abs(GAMMA[1] - 3 * _Q - 9 * OMEGA), 3 * ALPHA ** 2 / 8 * _H2, True),
    "003:Lemma3.2(vii)": (sp.Abs(GAMMA[2] - _Q - 3 * OMEGA), ALPHA ** 2 / 8 * _H2, True),
}
