"""Internal: the rigorous bounds record of the solvers and small shared helpers."""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Sequence

import numpy as np

from ._exact import Family, rho_enclosure, root_lower
from ._search import canonical_word


@dataclass
class _Bounds:
    """Internal: rigorous bounds for the exact family ``F`` (``upper`` may be ``None``)."""

    lower: Fraction
    upper: Fraction | None
    word: tuple[int, ...]
    rho_product: tuple[Fraction, Fraction]
    method: str
    arithmetic: str
    witness: dict = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def _lower_from_word(F: Family, word: Sequence[int]) -> tuple[Fraction, tuple[Fraction, Fraction]]:
    lo, hi = rho_enclosure(F, word)
    return root_lower(lo, len(word)), (lo, hi)


def _rho_word(mats: Sequence[np.ndarray], word: Sequence[int]) -> float:
    """Float ``rho(P_w)^(1/|w|)`` of the canonical rotation of ``w`` (deterministic)."""
    w = canonical_word(word)
    P = np.eye(mats[0].shape[0])
    for i in w:
        P = P @ mats[i]
    return float(np.max(np.abs(np.linalg.eigvals(P)))) ** (1.0 / len(w))
