"""Non-uniform (location-dependent) schemes: the NVPS of seeds 000/001.

The non-uniform variable-parameter subdivision (NVPS) of degree ``d >= 2`` (Fang, Jeong, Yoon)
refines a polygon whose edges carry tension parameters ``u``; its masks depend on the level and
the location. Seed 001 defines it by rules (2)-(6) and Algorithm 1, seed 000 (the conference
abstract) with a shifted indexing (``rule="seed001"`` / ``rule="seed000"``).

What lives where (split by job; every public name is re-exported here, use
``from analysis import nonuniform as nu`` and ``nu.<name>``):

* :mod:`.arithmetic` -- the number contexts ``float``, ``mp``, ``iv``, ``exact`` (``ARITHMETICS``);
* :mod:`.refinement` -- the scheme and its definition: :class:`NVPS`, :class:`Refinement`,
  :func:`step`, :func:`refine`, ``RULES``, :func:`parameter_from_angle`,
  :func:`angle_from_parameter`, the limit mask :func:`limit_mask` (the module docstring states
  the rules of both papers);
* :mod:`.masks` -- :func:`location_masks`, :func:`mask_distance` (the mask convention);
* :mod:`.decay` -- Lemma 2.1 and the rate of ``u^k -> 1`` (:func:`u_convergence_bound`,
  :func:`lemma_2_1`), :func:`mask_decay`; interval / Arb enclosures and outward rounding;
* :mod:`.definitions` -- seed 000 vs seed 001 (:func:`compare_definitions`) and seed 001's symbol
  identities (:func:`symbol_identities`);
* :mod:`.property_a` -- Property A quantities (13)-(14) (:func:`property_a_structure`,
  :func:`property_a_table`, :func:`property_a`) and :func:`junction_smoothness`;
* :mod:`.reproduction` -- circles, hyperbolas, parabolas (:func:`reproduce` and the polygons),
  chamfering (:func:`chamfer_polygon`, :func:`chamfer_example`, ``CHAMFER_*``),
  :func:`blended_example`.

The figures (``plot_blended``, ``plot_chamfer``) are rendering and live in
:mod:`analysis.report.plots`.

Layering: may import :mod:`analysis.algebra`, :mod:`analysis.stationary`, :mod:`analysis.jsr`
and :mod:`analysis.regularity`; not :mod:`analysis.levels` (a sibling), and never the higher
layers :mod:`analysis.claims`, :mod:`analysis.report`, :mod:`analysis.cli`. Inside the package:
arithmetic -> refinement -> masks -> decay / definitions / property_a / reproduction, no cycles
(``tests/test_layering.py``).

References
----------
Seed 000: M. Fang, B. Jeong, J. Yoon, *Non-uniform subdivision schemes reproducing locally
different curves* (conference abstract).
Seed 001: M. Fang, B. Jeong, J. Yoon, *A non-uniform subdivision scheme with variable parameters
for curve design* (preprint, 17 pp.).
N. Dyn, D. Levin, J. Yoon, *A new method for the analysis of univariate nonuniform subdivision
schemes*, Constr. Approx. 40 (2014) 173-188.

Examples
--------
>>> from analysis import nonuniform as nu
>>> nu.refine([0, 1, 2, 3], [1, 1, 1], degree=3, steps=1).points.tolist()    # u = 1: cubic B-spline
[0.5, 1.0, 1.5, 2.0, 2.5]
"""

# the private helpers imported here (_endpoint_rational, _half_update, _iv_acos, _pure_constant,
# _sources) are used by the seed 000/001 claim modules as ``nu._name``; they stay out of __all__
from .arithmetic import ARITHMETICS
from .decay import (_endpoint_rational, _iv_acos, lemma_2_1, mask_decay,  # noqa: F401
                    u_convergence_bound)
from .definitions import compare_definitions, symbol_identities
from .masks import _pure_constant, location_masks, mask_distance  # noqa: F401
from .property_a import junction_smoothness, property_a, property_a_structure, property_a_table
from .refinement import (NVPS, RULES, limit_mask, Refinement, _half_update, _sources,  # noqa: F401
                         angle_from_parameter, parameter_from_angle, refine, step)
from .reproduction import (CHAMFER_QUADRANGLE, CHAMFER_RADII, blended_example, chamfer_example,
                           chamfer_polygon, circle_polygon, hyperbola_polygon, parabola_polygon,
                           reproduce)

__all__ = [
    "NVPS", "Refinement", "refine", "step", "parameter_from_angle", "angle_from_parameter",
    "location_masks", "limit_mask", "mask_distance", "mask_decay", "u_convergence_bound",
    "lemma_2_1", "compare_definitions", "symbol_identities", "property_a", "property_a_structure",
    "property_a_table", "blended_example",
    "junction_smoothness", "circle_polygon", "hyperbola_polygon", "parabola_polygon",
    "reproduce", "chamfer_polygon", "chamfer_example", "CHAMFER_QUADRANGLE", "CHAMFER_RADII",
    "ARITHMETICS", "RULES",
]
