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

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover - resolved lazily below
    from .atlas import holder_atlas
    from .convergence import NotConvergent, convergence_failure, difference_mask
    from .holder import holder_exponent, smoothness
    from .ranges import alpha_curve, ck_parameter_set, verify_smoothness_interval
    from .sobolev import sobolev_exponent
    from .stability import stable_shifts

__all__ = ["NotConvergent", "alpha_curve", "ck_parameter_set", "convergence_failure", "difference_mask",
           "holder_atlas", "holder_exponent", "smoothness", "sobolev_exponent", "stable_shifts",
           "verify_smoothness_interval"]

#: each re-export and its submodule: imported on first use (PEP 562), so that ``holder`` does not
#: import the atlas (parallel sweeps), the parameter ranges or the Sobolev code it does not run
_LAZY = {"holder_atlas": ".atlas", "NotConvergent": ".convergence", "convergence_failure": ".convergence",
         "difference_mask": ".convergence", "holder_exponent": ".holder", "smoothness": ".holder",
         "alpha_curve": ".ranges", "ck_parameter_set": ".ranges", "verify_smoothness_interval": ".ranges",
         "sobolev_exponent": ".sobolev", "stable_shifts": ".stability"}


from .._lazy import lazy_exports  # noqa: E402

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
