"""Exact algebra of masks and symbols — the lowest layer of the engine.

What lives here: Laurent symbols over QQ, QQ<theta> and QQ[params] (:mod:`.symbol`), real
algebraic numbers, exact signs and interval sets (:mod:`.algebraic`), the smoothing factor,
sum rules, generation/reproduction degrees and symmetry (:mod:`.factorization`), linear forms in
control points for symbolic rule derivations (:mod:`.linear_forms`), masks typed in closed form
with an exact zero test (:mod:`.closed_form`) and decimal tables read as balls (:mod:`.approx`);
masks derived from linear requirements (:mod:`.derive`) and constructions of new symbols from old
ones — averaging, duals, convex combinations, pseudo-splines (:mod:`.constructions`).

Layering: imports only :mod:`analysis.result` and :mod:`analysis.jsonable` (checked by
``tests/test_layering.py``): algebra -> stationary -> jsr -> regularity -> levels / nonuniform
-> claims -> report -> cli.
"""
