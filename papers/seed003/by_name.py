"""Seed 003: the evaluators whose arguments are scheme objects, called by name from
``paper.toml`` (issue 11) with TOML arguments: the form ``"(2)"`` (trigonometric) or ``"(3)"``
(hyperbolic).
"""
from __future__ import annotations

from schemes.seed003 import HYPERBOLIC, TRIGONOMETRIC

from .claims_sec3_theorem import _theorem31_c2, _theorem31_equivalence

_FORMS = {"(2)": TRIGONOMETRIC, "(3)": HYPERBOLIC}


def equivalence(form: str):
    """Theorem 3.1 / Corollary 3.2: ``form`` is asymptotically equivalent to rule (1)."""
    return _theorem31_equivalence(_FORMS[form], form)


def c2(form: str):
    """Theorem 3.1 / Corollary 3.2: ``form`` is C^2."""
    return _theorem31_c2(_FORMS[form], form)
