"""Bivariate stationary schemes on regular grids with a dilation matrix.

Convention (stated once; the modules below refer to it)::

    (S_a f)(alpha) = sum_{beta in Z^2} a(alpha - M beta) f(beta),      a(z) = sum_alpha a(alpha) z^alpha,

``z^alpha = z1^alpha_1 z2^alpha_2``, ``M`` a 2 x 2 integer dilation (:mod:`analysis.bivariate.dilation`),
``sum_alpha a(alpha) = |det M|``. The refinable function solves ``phi(x) = sum_alpha a(alpha) phi(M x - alpha)``.
Quad grids use the coordinates of ``Z^2``; the three-direction (triangular) grid uses the lattice coordinates in
which the three edge directions are ``e1 = (1, 0)``, ``e2 = (0, 1)`` and ``e1 + e2 = (1, 1)`` (drawn as unit
vectors at 0, 120 and 60 degrees), so that Loop's and the butterfly masks are masks on ``Z^2``.

Modules: :mod:`.dilation` (digits, dual points, isotropy), :mod:`.mask` (the mask and its readers),
:mod:`.algebra` (sum rules, generation and reproduction degree, symmetry, box-spline factors),
:mod:`.transition` (invariant support, transition operators, difference subspaces),
:mod:`.holder` (certified Hölder exponent and C^k verdicts), :mod:`.ranges` (C^l sets of one-parameter
families), :mod:`.tensor` (tensor-product masks reduced exactly to two univariate schemes),
:mod:`.differences` (difference schemes in the quotient-ideal form for ``M = m I``, and their norm tests).

Layering: just above :mod:`analysis.regularity`; may import :mod:`analysis.algebra` (the reader),
:mod:`analysis.jsr` (the certified joint spectral radius) and :mod:`analysis.regularity` (the univariate analysis,
to which a tensor-product mask reduces: :mod:`.tensor`), nothing above.
"""
