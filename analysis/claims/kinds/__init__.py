"""The library of claim kinds (issue 11): each kind a small class with its fields, its
validation and ``evaluate() -> Verdict`` computed by the engine (never a typed-in verdict).

A paper file (:mod:`analysis.claims.paperfile`) names a kind by ``kind = "..."``; :data:`KIND_CLASSES`
maps each name to its class. Layering: part of :mod:`analysis.claims`; imports the engine layers
below (algebra, stationary, regularity, levels) and :mod:`analysis.claims.model`, never the
report or the command line, the catalogue or the papers (a ``python`` claim imports its
evaluator by name at evaluation time).

Examples
--------
>>> sorted(KIND_CLASSES)[:4]
['all of', 'asymptotic equivalence', 'cited', 'ck range']
>>> kind_class("sum rule")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
analysis.result.AnalysisError: unknown kind 'sum rule'; the kinds are: all of, asymptotic equivalence, cited, ck range, construction, ...

Kinds added with the bundled papers' conversion: ``identity``, ``factorization``, ``inequality``
(:mod:`.lemma`), ``curve comparison``, ``all of`` (seeds 003/000); ``support after steps``,
``limit symmetry`` (seed 001); ``eigenvalue inequality`` (:mod:`.spectral`), ``end rules`` and ``gibbs``
(:mod:`.open_curves`), ``construction`` (:mod:`.construction`) (seed 004); ``smoothness`` (:mod:`.smoothness`:
C^k or not C^k of one scheme, stationary or level-dependent) and ``interpolatory`` (:mod:`.algebraic`).

References
----------
DESIGN.md ("Results contract"); issue 11.
"""

from __future__ import annotations

from ...result import AnalysisError
from .algebraic import Eigenvalues, Interpolatory, MaskIdentity, Reproduction, SumRules, Support, Symmetry
from .base import Domain, Kind, SchemeSpec, parse_interval, parse_number
from .compound import AllOf
from .construction import Construction
from .curves import CurveComparison
from .lemma import Factorization, Identity
from .levels import AsymptoticEquivalence, ExponentialReproduction, WeightedSeries
from .limit_symmetry import LimitSymmetry
from .open_curves import EndRules, Gibbs
from .other import Cited, Inequality, Python
from .profile import SmoothnessProfile
from .regularity import CkRange, Holder, NormTest, Sobolev
from .smoothness import Smoothness
from .spectral import EigenvalueInequality
from .support_steps import SupportAfterSteps
from .vertex import Vertex

#: kind name -> class, in the order of the ``subdiv new-paper`` template
KIND_CLASSES: dict[str, type[Kind]] = {k.name: k for k in (
    MaskIdentity, SumRules, Symmetry, Interpolatory, Support, Eigenvalues, Reproduction, NormTest, CkRange, Smoothness, Holder, Sobolev,
    SmoothnessProfile, WeightedSeries, AsymptoticEquivalence, ExponentialReproduction, Inequality, Identity,
    Factorization, EigenvalueInequality, SupportAfterSteps, LimitSymmetry, EndRules, Gibbs, Construction,
    CurveComparison, Vertex, AllOf, Cited, Python)}


def kind_class(name: str) -> type[Kind]:
    """The class of the kind ``name`` (an :class:`AnalysisError` listing the kinds otherwise)."""
    if name in KIND_CLASSES:
        return KIND_CLASSES[name]
    raise AnalysisError(f"unknown kind {name!r}; the kinds are: {', '.join(sorted(KIND_CLASSES))}")


__all__ = ["KIND_CLASSES", "kind_class", "Kind", "SchemeSpec", "Domain", "parse_number", "parse_interval"]
