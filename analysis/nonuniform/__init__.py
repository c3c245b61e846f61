"""Non-uniform (location-dependent) schemes: the NVPS of seeds 000/001.

Layering: may import :mod:`analysis.algebra`, :mod:`analysis.stationary`, :mod:`analysis.jsr`
and :mod:`analysis.regularity`; not :mod:`analysis.levels` (a sibling).
"""

from .nvps import *  # noqa: F401,F403  (transitional: the split into modules by job follows)
from .nvps import (CHAMFER_QUADRANGLE, CHAMFER_RADII, NVPS, _endpoint_rational, _half_update,  # noqa: F401
                   _iv_acos, _pure_constant, _sources)
