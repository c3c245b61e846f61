"""Float search for spectrum-maximizing products (s.m.p. candidates) and textbook norm bounds.

Words and products
------------------
A word ``w = (w_1, ..., w_L)`` stands for the product ``P_w = A_{w_1} A_{w_2} ... A_{w_L}``.
``rho(P_w)`` is invariant under cyclic rotation of ``w``; :func:`canonical_word` returns the
lexicographically least rotation of the primitive root (``(1, 0, 1, 0) -> (0, 1)``).

Algorithm (:func:`smp_search`)
------------------------------
Breadth-first branch and bound in the spirit of Gripenberg (1996): level ``L`` holds products of
length ``L``; each is extended by every matrix; ``rho(P)^(1/L)`` of every child updates the best
lower bound; a child survives only if ``||P||^(1/L)`` in a balanced norm exceeds the current
lower bound (otherwise, in Gripenberg's argument, it cannot lead to a better product by more than
the norm's excess), and at most ``beam`` survivors (largest norms first) are kept. The balanced
norm is the ellipsoidal norm ``||x||_Q = sqrt(x^T Q x)`` where ``Q`` is the Perron eigenvector of
``Q -> sum_i A_i^T Q A_i`` (the "sum of squares" bound of Blondel–Nesterov, Parrilo–Jadbabaie),
computed by power iteration: it is within a factor ``sqrt(k)`` of extremal.
Levels are processed in order and ties keep the earlier (shorter) word, so a longer search never
loses what a shorter one found.

References
----------
G. Gripenberg, *Computing the joint spectral radius*, Linear Algebra Appl. 234 (1996) 43-60.
V. D. Blondel, Y. Nesterov, *Computationally efficient approximations of the joint spectral
radius*, SIAM J. Matrix Anal. Appl. 27 (2005) 256-272.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

from ._work import Work

#: work units of the s.m.p. search (about a millisecond of CPU each on the reference machine): one
#: unit per this many "entries" of evaluated products, a product of ``n x n`` matrices counting
#: ``n^2 + 8`` (its spectral radius and norm; the 8 stand for the per-product overhead of small
#: matrices), and at least one unit per level
SEARCH_ENTRIES_PER_UNIT = 4000


def canonical_word(word: Sequence[int]) -> tuple[int, ...]:
    """Least rotation of the primitive root of ``word``.

    >>> canonical_word((1, 0, 1, 0))
    (0, 1)
    >>> canonical_word((1, 1, 0))
    (0, 1, 1)
    """
    w = tuple(int(x) for x in word)
    L = len(w)
    for d in range(1, L + 1):
        if L % d == 0 and w[:d] * (L // d) == w:
            w = w[:d]
            break
    return min(w[i:] + w[:i] for i in range(len(w)))


def spectral_radii(P: np.ndarray) -> np.ndarray:
    """Spectral radii of a stack of matrices ``P`` of shape ``(N, n, n)``."""
    if P.shape[-1] == 1:
        return np.abs(P[:, 0, 0])
    return np.max(np.abs(np.linalg.eigvals(P)), axis=-1)


def word_product(mats: Sequence[np.ndarray], word: Sequence[int]) -> np.ndarray:
    P = np.eye(mats[0].shape[0])
    for i in word:
        P = P @ mats[i]
    return P


def balancing_transform(mats: Sequence[np.ndarray], iters: int = 200) -> tuple[np.ndarray, float]:
    """``(R, sos)``: ``||x||_Q = ||R x||_2`` is the sum-of-squares ellipsoidal norm, and
    ``sos = rho(sum_i A_i (x) A_i)^(1/2)`` is its (float) bound ``JSR <= sos <= sqrt(k) JSR``."""
    n = mats[0].shape[0]
    Q = np.eye(n)
    lam = 0.0
    for _ in range(iters):
        Qn = sum(A.T @ Q @ A for A in mats)
        lam = float(np.trace(Qn))
        if not np.isfinite(lam) or lam <= 0:
            return np.eye(n), 0.0
        Qn /= lam
        if np.max(np.abs(Qn - Q)) < 1e-13:
            Q = Qn
            break
        Q = Qn
    Q = (Q + Q.T) / 2
    w, U = np.linalg.eigh(Q)
    w = np.maximum(w, 1e-8 * max(w.max(), 1e-300))
    R = (U * np.sqrt(w)) @ U.T
    sos = float(np.sqrt(max(lam, 0.0)))
    return R, sos


@dataclass
class SearchResult:
    best_rho: float                      # float rho(P_w)^(1/L) of the best word
    best_word: tuple[int, ...]
    candidates: list[tuple[float, tuple[int, ...]]] = field(default_factory=list)
    levels_done: int = 0
    products_evaluated: int = 0
    exhaustive_to: int = 0               # every word up to this length was evaluated
    seconds: float = 0.0                 # wall clock (reported as timing only, decides nothing)
    work: int = 0                        # work units charged


def search_units(products: int, n: int) -> int:
    """Work units of evaluating ``products`` products of ``n x n`` matrices (at least 1)."""
    return max(1, -(-products * (n * n + 8) // SEARCH_ENTRIES_PER_UNIT))


def smp_search(mats: Sequence[np.ndarray], max_length: int, *, beam: int = 4000,
               work: Work | None = None, near: float = 1e-9) -> SearchResult:
    """Gripenberg-type branch and bound for the s.m.p.: see the module docstring.

    ``work``: a :class:`~analysis.jsr._work.Work` budget; every level is charged
    :func:`search_units` of its products, and no new level starts once it is exhausted (the
    search always evaluates the single matrices). ``None``: no limit but ``max_length``.

    ``candidates`` lists the canonical words whose ``rho^(1/L)`` is within relative ``near`` of
    the best (several s.m.p.s, or a rotation-free list of ties), best first, at most 8.

    >>> A = [np.array([[1., 1], [0, 1]]), np.array([[1., 0], [1, 1]])]
    >>> r = smp_search(A, 6)
    >>> r.best_word, round(r.best_rho, 9)
    ((0, 1), 1.618033989)
    """
    t0 = time.perf_counter()
    k, n = len(mats), mats[0].shape[0]
    A = np.array(mats, dtype=float)
    R, _ = balancing_transform(mats)
    try:
        Rinv = np.linalg.inv(R)
    except np.linalg.LinAlgError:  # pragma: no cover
        R, Rinv = np.eye(n), np.eye(n)
    B = np.einsum("ij,kjl,lm->kim", R, A, Rinv)           # balanced copies, same products
    # scale the family so that long products neither overflow nor underflow: rho^(1/L) and
    # ||P||^(1/L) scale by the same factor, undone on output
    s = float(np.max(spectral_radii(A)))
    if not s > 0:
        s = float(np.max(np.linalg.norm(B, ord=2, axis=(1, 2)))) or 1.0
    B = B / s
    A = A / s

    rho1 = spectral_radii(A)
    order = np.argsort(-rho1, kind="stable")
    best = float(rho1[order[0]])
    best_word: tuple[int, ...] = (int(order[0]),)
    found: dict[tuple[int, ...], float] = {}
    for i in range(k):
        found.setdefault(canonical_word((i,)), float(rho1[i]))

    words = np.arange(k, dtype=np.int64).reshape(k, 1)
    prods = B.copy()
    evaluated = k
    exhaustive_to = 1
    all_kept = True
    level = 1
    charged = 0
    while level < max_length:
        if work is not None and work.exhausted:
            break
        level += 1
        N = len(words)
        child_prods = np.einsum("aij,bjk->abik", prods, B).reshape(N * k, n, n)
        child_words = np.concatenate([np.repeat(words, k, axis=0),
                                      np.tile(np.arange(k), N).reshape(-1, 1)], axis=1)
        rho = spectral_radii(child_prods) ** (1.0 / level)
        evaluated += len(rho)
        u = search_units(len(rho), n)
        charged += u
        if work is not None:
            work.charge(u)
        # best, earliest wins ties (stable argmax)
        j = int(np.argmax(rho))
        if rho[j] > best * (1 + 1e-13):
            best, best_word = float(rho[j]), canonical_word(child_words[j])
        near_idx = np.nonzero(rho >= best * (1 - near))[0]
        for jj in near_idx[:64]:
            cw = canonical_word(child_words[jj])
            if cw not in found:
                found[cw] = float(rho[jj])
        # Gripenberg pruning in the balanced norm, then the beam
        norms = np.linalg.norm(child_prods, ord=2, axis=(1, 2)) ** (1.0 / level)
        keep = np.nonzero(norms > best * (1 + 1e-12))[0]
        if all_kept:
            exhaustive_to = level
        if len(keep) > beam:
            keep = keep[np.argsort(-norms[keep], kind="stable")[:beam]]
        all_kept = all_kept and len(keep) == N * k
        if len(keep) == 0:
            break
        words = child_words[keep]
        prods = child_prods[keep]
    cands = sorted(((r, w) for w, r in found.items() if r >= best * (1 - near)),
                   key=lambda t: (-t[0], len(t[1]), t[1]))
    cands = [(best, best_word)] + [c for c in cands if c[1] != best_word]
    cands = [(r * s, w) for r, w in cands[:8]]
    return SearchResult(best * s, best_word, cands, level, evaluated, exhaustive_to,
                        time.perf_counter() - t0, charged)


def brute_force_bounds(mats: Sequence[np.ndarray], max_length: int, *,
                       norm: str = "inf") -> dict:
    """The textbook bounds in floats: ``max_{|w|<=L} rho(P_w)^(1/|w|) <= JSR <=
    min_{l<=L} max_{|w|=l} ||P_w||^(1/l)``, over *all* ``k^l`` products (no pruning).

    Float arithmetic: the numbers are estimates, not certificates. ``norm`` is ``"inf"``
    (max row sum in the given basis) or ``"balanced"`` (the ellipsoidal norm of
    :func:`balancing_transform`).

    >>> A = [np.array([[1., 1], [0, 1]]), np.array([[1., 0], [1, 1]])]
    >>> b = brute_force_bounds(A, 8)
    >>> round(b["lower"], 9), b["lower_word"], b["upper"] > 1.618
    (1.618033989, (0, 1), True)
    """
    k, n = len(mats), mats[0].shape[0]
    A = np.array(mats, dtype=float)
    if norm == "balanced":
        R, _ = balancing_transform(mats)
        A = np.einsum("ij,kjl,lm->kim", R, A, np.linalg.inv(R))
    elif norm != "inf":
        raise ValueError(f"unknown norm {norm!r}")
    lower, lower_word, upper, upper_len = 0.0, (0,), np.inf, 0
    prods = A.copy()
    words = [(i,) for i in range(k)]
    per_length = []
    for L in range(1, max_length + 1):
        if L > 1:
            prods = np.einsum("aij,bjk->abik", prods, A).reshape(-1, n, n)
            words = [w + (i,) for w in words for i in range(k)]
        rho = spectral_radii(prods) ** (1.0 / L)
        j = int(np.argmax(rho))
        if rho[j] > lower * (1 + 1e-13):
            lower, lower_word = float(rho[j]), canonical_word(words[j])
        if norm == "inf":
            nm = np.max(np.sum(np.abs(prods), axis=2), axis=1)
        else:
            nm = np.linalg.norm(prods, ord=2, axis=(1, 2))
        u = float(np.max(nm)) ** (1.0 / L)
        if u < upper:
            upper, upper_len = u, L
        per_length.append((L, float(rho[j]), u))
    return {"lower": lower, "lower_word": lower_word, "upper": upper, "upper_length": upper_len,
            "per_length": per_length}
