"""Level-dependent (non-stationary) schemes.

What lives here: level-dependent symbols ``a^n(z)`` with their limit, rigorous distances
``||S_{a^n} - S_a||`` and Taylor models in ``h = 2^-n`` (:mod:`.level_dependent`), weighted
series with analytic tails and the smoothness transfer (:mod:`.series`), lemma inequalities over
``(n, parameter box)`` (:mod:`.bounds`), exponential reproduction and curve deviation
(:mod:`.reproduction`).

Layering: may import :mod:`analysis.algebra`, :mod:`analysis.stationary`, :mod:`analysis.jsr`
and :mod:`analysis.regularity`; not :mod:`analysis.nonuniform` (a sibling).
"""
