"""Regularity of stationary schemes: Hölder and Sobolev exponents, C^k verdicts, ranges, atlases.

What lives here: :func:`~analysis.regularity.holder.holder_exponent` — the one Hölder entry
point for exact (rational or algebraic), closed-form, ball and approximately read masks —
and the C^k verdict :func:`~analysis.regularity.holder.smoothness` (:mod:`.holder`); the
L2-Sobolev exponent (:mod:`.sobolev`); stability of the integer shifts (:mod:`.stability`);
C^k parameter ranges with certified boundaries, alpha curves and the proof or refutation of a
claimed interval (:mod:`.ranges`), with the interior of a C^j set certified by exact parametric
norm tests (:mod:`.interior`); two-parameter atlases (:mod:`.atlas`); the smoothest member of
a one-parameter family with a certified gap (:mod:`.maximize`), of a box of parameters or an
m-ary family (:mod:`.maximize_box`).

Layering: may import :mod:`analysis.algebra`, :mod:`analysis.stationary` and :mod:`analysis.jsr`.
"""

from .atlas import holder_atlas
from .convergence import NotConvergent, convergence_failure, difference_mask
from .holder import holder_exponent, smoothness
from .ranges import alpha_curve, ck_parameter_set, verify_smoothness_interval
from .sobolev import sobolev_exponent
from .stability import stable_shifts

__all__ = ["NotConvergent", "alpha_curve", "ck_parameter_set", "convergence_failure", "difference_mask",
           "holder_atlas", "holder_exponent", "smoothness", "sobolev_exponent", "stable_shifts",
           "verify_smoothness_interval"]
