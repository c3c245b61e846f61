"""Certified JSR bounds from products when no invariant polytope closes: a best-first
branch-and-bound tree of products (Gripenberg 1996) in a balanced norm, certified in Arb.

Upper bound
-----------
Let ``||.||`` be a submultiplicative matrix norm and ``T`` a finite set of words such that every
infinite word has a prefix in ``T`` (a *complete* prefix set). Cutting a long product greedily
into blocks from ``T`` gives ``||P_w|| <= C beta^|w|`` with ``beta = max_{u in T} ||P_u||^(1/|u|)``,
hence ``JSR <= beta``. The tree grows ``T``: a node ``w`` has the value
``m(w) = min_{u prefix of w} ||P_u||^(1/|u|)`` (a node is as good as its best prefix), the leaf
with the largest ``m`` is expanded first (its ``k`` children replace it), and the bound, the
largest ``m`` over the leaves, decreases with every step, so the tree can stop anywhere. For the
certificate each leaf is cut at its shortest prefix whose value is within the bound; those
prefixes form a complete prefix set ``T`` whose products are recomputed in Arb ball arithmetic.

The norm is the spectral norm in the basis of the sum-of-squares ellipsoid (the dyadic ``R`` of
:func:`analysis.jsr._norms._balanced_arb`, exactly similar: ``B_i = R A_i R^-1``), bounded above by
``||P||_2 <= trace((P^T P)^4)^(1/8)`` (the ``l^8`` norm of the singular values; the excess
``(sum_i (s_i / s_1)^8)^(1/8)`` fades quickly with the length of a product). The float search
and the Arb certificate use the same quantity, so they agree up to rounding.

Lower bound
-----------
Every node's ``rho(P_w)^(1/|w|)`` is a lower-bound candidate; the best word is returned for the
caller to certify (:func:`analysis.jsr._bounds._lower_from_word`).

Examples
--------
>>> from analysis.jsr._exact import parse_family
>>> from analysis.jsr._work import Work
>>> F = parse_family([[[1, 1], [0, 1]], [[1, 0], [1, 1]]])
>>> t = tree_bounds(F, Work(200), lower_hint=1.618, rel_gap=1e-3)
>>> t.word, 1.618 < float(t.upper) < 1.63
((0, 1), True)

References
----------
G. Gripenberg, *Computing the joint spectral radius*, Linear Algebra Appl. 234 (1996) 43-60.
V. D. Blondel, Y. Nesterov, *Computationally efficient approximations of the joint spectral
radius*, SIAM J. Matrix Anal. Appl. 27 (2005) 256-272.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np

from ._exact import Family, arb_precision, arb_to_fraction_bounds, root_upper
from ._norms import _balanced_arb
from ._search import canonical_word
from ._work import Work

#: work units of the float tree (about a millisecond of CPU each on the reference machine): one
#: unit per this many "entries" of evaluated nodes, a node of size ``n`` counting ``n^2 + 16``
#: (its product, three products for the norm and its eigenvalues; the 16 for the per-node
#: overhead), at least one unit per batch
TREE_ENTRIES_PER_UNIT = 3500
#: work units of the Arb certificate: one unit per this many "entries" of ball matrix products
#: (128 bits), a product of size ``n`` counting ``n^3 + 400``; a prefix costs its new path
#: products and three more for its norm bound. The tree stops early enough to leave the
#: certificate of its leaves this much
CERT_ENTRIES_PER_UNIT = 16000
#: Arb precision of the certificate (bits)
CERT_PREC = 128
#: products kept in memory at most (entries); others are recomputed from their word when needed
MAX_STORED_ENTRIES = 4_000_000
#: nodes expanded together (one numpy batch)
BATCH = 32
#: deepest node of the tree
MAX_DEPTH = 80


@dataclass
class TreeResult:
    upper: Fraction                      # certified JSR <= upper
    float_upper: float                   # the float value of the same bound
    word: tuple[int, ...]                # best product found (rho^(1/L) largest)
    float_lower: float
    nodes: int = 0
    depth: int = 0
    leaves: int = 0
    certified_products: int = 0
    stop_reason: str = ""
    stats: dict = field(default_factory=dict)


def _units(nodes: int, n: int) -> int:
    return max(1, -(-nodes * (n * n + 16) // TREE_ENTRIES_PER_UNIT))


def _arb_units(n: int) -> float:
    return (n ** 3 + 400) / CERT_ENTRIES_PER_UNIT


def _log_norm_bound(P: np.ndarray) -> np.ndarray:
    """``log trace((P^T P)^4) / 8`` (``>= log ||P||_2``) for a stack of matrices, scaled safely."""
    c = np.max(np.abs(P), axis=(1, 2))
    c = np.where(c > 0, c, 1.0)
    Q = P / c[:, None, None]
    G = np.matmul(np.swapaxes(Q, 1, 2), Q)
    H = np.matmul(G, G)
    t = np.einsum("aij,aij->a", H, H)
    with np.errstate(divide="ignore"):
        return np.log(c) + np.log(t) / 8


def tree_bounds(F: Family, work: Work, *, lower_hint: float, rel_gap: float,
                max_depth: int = MAX_DEPTH) -> TreeResult:
    """Certified ``JSR <= upper`` from a best-first product tree (module docstring).

    ``lower_hint``: the best known ``rho(P_w)^(1/|w|)`` (float); the tree stops when its bound is
    within ``rel_gap / 2`` of the best lower value. ``work`` is charged :func:`_units` per batch
    of nodes and :func:`_arb_units` per Arb product of the certificate; the tree stops while
    what is left still pays for the certificate of its leaves (estimated, and the certificate
    always completes). Deterministic: ties are broken by creation order.
    """
    k, n = F.k, F.n
    Barb = _balanced_arb(F)
    Bf = np.array([[[float(Barb[i][a, b].mid()) for b in range(n)] for a in range(n)]
                   for i in range(k)])
    s = lower_hint if lower_hint > 0 else float(np.max(np.linalg.norm(Bf, 2, axis=(1, 2)))) or 1.0
    Bf = Bf / s
    log_s = math.log(s)
    best_lower = math.log(lower_hint / s) if lower_hint > 0 else -math.inf
    best_word: tuple[int, ...] = ()
    log_tol = math.log1p(rel_gap / 2)
    seq = 0
    # node: [-m, seq, word, prefix log-values, log-scale, normalised product or None]
    heap: list[list] = [[-math.inf, -1, (), (), 0.0, np.eye(n)]]   # the root: expanded first
    stuck: list[list] = []
    stored = 1
    nodes = 0
    depth = 0
    stop = "bound within the target gap"
    while heap:
        if -heap[0][0] <= best_lower + log_tol:
            break
        if nodes and work.left <= (len(heap) + len(stuck)) * 4.5 * _arb_units(n):
            stop = "work budget exhausted (the rest certifies the leaves)"
            break
        batch = []
        while heap and len(batch) < BATCH and -heap[0][0] > best_lower + log_tol:
            node = heapq.heappop(heap)
            if len(node[2]) >= max_depth:
                stuck.append(node)
                continue
            batch.append(node)
        if not batch:
            continue
        prods = []
        for node in batch:
            if node[5] is None:                       # dropped to save memory: recompute
                P = np.eye(n)
                for i in node[2]:
                    P = P @ Bf[i]
                c = float(np.max(np.abs(P))) or 1.0
                node[4], node[5] = math.log(c), P / c
                work.charge(_units(len(node[2]), n))
            prods.append(node[5])
            stored -= 1
        Pb = np.array(prods)
        C = np.einsum("aij,kjl->akil", Pb, Bf).reshape(len(batch) * k, n, n)
        c = np.max(np.abs(C), axis=(1, 2))
        c = np.where(c > 0, c, 1.0)
        C = C / c[:, None, None]
        ln = _log_norm_bound(C)
        with np.errstate(divide="ignore"):
            lr = np.log(np.max(np.abs(np.linalg.eigvals(C)), axis=-1))
        nodes += len(C)
        work.charge(_units(len(C), n))
        for a, node in enumerate(batch):
            L = len(node[2]) + 1
            depth = max(depth, L)
            m_parent = -node[0] if node[2] else math.inf
            for i in range(k):
                j = a * k + i
                base = node[4] + math.log(c[j])
                val = (base + ln[j]) / L
                rho = (base + lr[j]) / L
                word = node[2] + (i,)
                if rho > best_lower + 1e-13:
                    best_lower, best_word = rho, word
                seq += 1
                heapq.heappush(heap, [-min(m_parent, val), seq, word, node[3] + (val,), base,
                                      C[j]])
                stored += 1
        if stored * n * n > MAX_STORED_ENTRIES:
            # keep the products of the better half of the leaves
            keys = sorted(-nd[0] for nd in heap)
            cut = keys[len(keys) // 2]
            for nd in heap:
                if nd[5] is not None and -nd[0] < cut:
                    nd[5] = None
                    stored -= 1
    leaves = heap + stuck
    bound = max(-nd[0] for nd in leaves)
    # the complete prefix set: each leaf cut at its shortest prefix within the bound
    T = sorted({nd[2][: next(j for j, v in enumerate(nd[3]) if v <= bound + 1e-12) + 1]
                for nd in leaves})
    upper = _certify(Barb, T, work)
    return TreeResult(upper, math.exp(bound + log_s), canonical_word(best_word) if best_word else (0,),
                      math.exp(best_lower + log_s), nodes, depth, len(leaves), len(T), stop,
                      {"prefix_set_lengths": [min(map(len, T)), max(map(len, T))]})


def _certify(Barb, T: list[tuple[int, ...]], work: Work) -> Fraction:
    """``max_{u in T} trace((P_u^T P_u)^4)^(1/(8|u|))`` rounded up, in Arb (``T`` sorted)."""
    n = Barb[0].nrows()
    per = _arb_units(n)
    acc = 0.0
    best = Fraction(0)
    best_log2 = -math.inf
    stack: list[tuple[tuple[int, ...], object]] = []
    with arb_precision(CERT_PREC):
        for u in T:
            while stack and stack[-1][0] != u[: len(stack[-1][0])]:
                stack.pop()
            P = stack[-1][1] if stack else None
            for t in range(len(stack[-1][0]) if stack else 0, len(u)):
                P = Barb[u[t]] if P is None else P * Barb[u[t]]
                stack.append((u[: t + 1], P))
                acc += per
            G = P.transpose() * P
            H = G * G
            tr = (H * H).trace()
            acc += 3 * per
            if not tr.is_finite():
                raise ArithmeticError("Arb trace of a product is not finite")
            # the exact root only for a leaf that may beat the best: log2 of the upper end of
            # the trace is known to ~1e-15, far inside the 1e-9 margin, so the maximum is the
            # one every leaf's exact root gives
            man, exp = tr.upper().man_exp()
            if int(man) <= 0 or (math.log2(int(man)) + int(exp)) / (8 * len(u)) >= best_log2 - 1e-9:
                b = root_upper(arb_to_fraction_bounds(tr)[1], 8 * len(u))
                if b > best:
                    best = b
                    best_log2 = math.log2(b.numerator) - math.log2(b.denominator)
            if acc >= 1:
                work.charge(int(acc))
                acc -= int(acc)
    return best
