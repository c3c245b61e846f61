"""Stationary schemes: difference schemes and norm tests, transition and local matrices, refinement.

What lives here: difference symbols in both spellings and exact L-step norms
(:mod:`.difference`), the norm as an exact piecewise function of one parameter and the exact set
where the Dyn–Levin test holds (:mod:`.normset`), certified bounds of the parametric norm on
parameter boxes and end pieces (:mod:`.normbox`), transition matrices, local subdivision matrices,
exact eigenvalues and supports (:mod:`.transition`), refinement of closed and open polygons and
basic limit functions (:mod:`.refinement`).

Layering: may import :mod:`analysis.algebra` (and the results contract) only.
"""
