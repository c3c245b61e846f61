"""Level-dependent (non-stationary) schemes.

What lives here: level-dependent symbols ``a^n(z)`` with their limit, rigorous distances
``||S_{a^n} - S_a||`` and Taylor models in ``h = 2^-n``, and the constructors from symbols, masks
and ``where`` definitions (:mod:`.level_dependent`); ball evaluation of sympy expressions
(:mod:`.balls`); weighted series with analytic tails and the smoothness transfer (:mod:`.series`);
the C^k verdict for every k with its theorem (:mod:`.ck`), and at every point of a parameter box by
an adaptive cover (:mod:`.ck_box`, any arity; its "not C^d" on a box: :mod:`.expbspline_box`); C^k
through generalized divided differences of schemes with exponential factors (:mod:`.gendiff`); exact truncated power series in
``h`` of mask coefficients (:mod:`.hseries`); exact recognition of exponential
B-spline schemes and their certified "not C^d" (:mod:`.expbspline`); schemes whose level enters
through rational functions of n (:mod:`.rational_level`); lemma inequalities over
``(n, parameter box)`` (:mod:`.bounds`); exponential frequencies, reproduction and curve deviation
(:mod:`.reproduction`).

Layering: may import :mod:`analysis.algebra`, :mod:`analysis.stationary`, :mod:`analysis.jsr`
and :mod:`analysis.regularity`; not :mod:`analysis.nonuniform` (a sibling).
"""
