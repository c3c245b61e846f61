"""Seed 003: the evaluators whose arguments are scheme objects, called by name from
``paper.toml`` (issue 11) with TOML arguments: the form ``"(2)"`` (trigonometric, beta) or
``"(3)"`` (hyperbolic, gamma), the lemma and item of a definition identity.
"""
from __future__ import annotations

from schemes.seed003 import BETA, BETA_SUM, GAMMA, GAMMA_SUM, HYPERBOLIC, TRIGONOMETRIC

from .claims_sec3_lemmas import _factorization, _identity_item
from .claims_sec3_theorem import _theorem31_c2, _theorem31_equivalence
from .claims_sec4_5 import _sum_identity
from .transcription import _DEF, _DEF2

_FORMS = {"(2)": (TRIGONOMETRIC, BETA, BETA_SUM), "(3)": (HYPERBOLIC, GAMMA, GAMMA_SUM)}


def factorization(form: str, label: str):
    """Lemma 3.3 / Corollary 3.1: the printed factor e^n of the symbol of ``form``."""
    scheme, coeffs, _ = _FORMS[form]
    return _factorization(scheme, coeffs, label)


def equivalence(form: str):
    """Theorem 3.1 / Corollary 3.2: ``form`` is asymptotically equivalent to rule (1)."""
    return _theorem31_equivalence(_FORMS[form][0], form)


def c2(form: str):
    """Theorem 3.1 / Corollary 3.2: ``form`` is C^2."""
    return _theorem31_c2(_FORMS[form][0], form)


def sum_identity(form: str):
    """The sum of the mask of ``form``."""
    scheme, _, total = _FORMS[form]
    return _sum_identity(scheme, total, form)


def definition(lemma: str, item: str):
    """A definition identity of Lemma 3.1 (``"3.1"``) or 3.2 (``"3.2"``), item ``"i"``, ``"iv"``, ..."""
    return _identity_item(*{"3.1": _DEF, "3.2": _DEF2}[lemma][item])
