"""Regularity of stationary schemes: Hölder and Sobolev exponents, C^k verdicts, ranges, atlases.

What lives here: :func:`~analysis.regularity.holder.holder_exponent` — the one Hölder entry
point for exact (rational or algebraic), closed-form, ball and approximately read masks —
and the C^k verdict :func:`~analysis.regularity.holder.smoothness` (:mod:`.holder`); the
L2-Sobolev exponent (:mod:`.sobolev`); stability of the integer shifts (:mod:`.stability`);
C^k parameter ranges with certified boundaries, alpha curves and the proof or refutation of a
claimed interval (:mod:`.ranges`); two-parameter atlases (:mod:`.atlas`).

Layering: may import :mod:`analysis.algebra`, :mod:`analysis.stationary` and :mod:`analysis.jsr`.
"""
