"""Rigorous norm bounds of all products (the textbook method, Arb, in a balanced basis): the
``method="norms"`` solver and the fallback upper bound of the polytope solver."""

from __future__ import annotations

from fractions import Fraction

from flint import arb, arb_mat, fmpq, fmpq_mat

from ._bounds import _Bounds, _lower_from_word
from ._exact import Family, arb_precision, arb_to_fraction_bounds, root_upper
from ._search import balancing_transform, brute_force_bounds
from ._work import Work

#: work units of the rigorous norm bound (about a millisecond of CPU each on the reference machine):
#: one unit per this many "entries" of Arb products, the product of two ``n x n`` ball matrices and
#: its row sums counting ``n^3 + 8 n^2 + 400`` (the 400 for the per-product overhead)
NORM_ENTRIES_PER_UNIT = 14000


def norm_units(n: int) -> float:
    """Work units of one Arb matrix product and its infinity norm (size ``n``)."""
    return (n ** 3 + 8 * n * n + 400) / NORM_ENTRIES_PER_UNIT


def _balanced_arb(F: Family) -> list[arb_mat]:
    """Arb enclosures of ``R A_i R^{-1}`` for a dyadic ``R`` near the sum-of-squares transform."""
    R, _ = balancing_transform(F.floats)
    n = F.n
    Rq = fmpq_mat([[fmpq(*Fraction(float(x)).as_integer_ratio()) for x in row] for row in R])
    try:
        Rinv = Rq.inv()
    except ZeroDivisionError:  # pragma: no cover - R is positive definite
        Rq = fmpq_mat([[1 if a == b else 0 for b in range(n)] for a in range(n)])
        Rinv = Rq
    with arb_precision():
        Ra, Ria = arb_mat(Rq), arb_mat(Rinv)
        return [Ra * F.arb(i) * Ria for i in range(F.k)]


def _inf_norm_upper(M: arb_mat) -> Fraction:
    """The exact upper end of the largest Arb row sum of ``|M|``. Only the rows whose float upper
    end is within ``1e-9`` of the largest are converted to fractions (the conversion dominated the
    cost); the result is the same as converting every row."""
    n, m = M.nrows(), M.ncols()
    entries = M.entries()
    with arb_precision():
        sums = []
        for a in range(n):
            s = arb(0)
            for x in entries[a * m:(a + 1) * m]:
                s += abs(x)
            sums.append(s)
        if not all(s.is_finite() for s in sums):
            return max(arb_to_fraction_bounds(s)[1] for s in sums)
        ups = [float(s.mid()) + float(s.rad()) for s in sums]
        top = max(ups)
        return max(arb_to_fraction_bounds(s)[1] for s, u in zip(sums, ups)
                   if u >= top - 1e-9 * abs(top))


def rigorous_norm_upper(F: Family, max_length: int, work: Work,
                        max_products: int = 1 << 14) -> tuple[Fraction, int]:
    """``min_{l <= L} max_{|w| = l} ||P_w||^(1/l)`` (rigorous, Arb) in a balanced basis; returns
    ``(bound, l)``. ``work`` is charged :func:`norm_units` per product; stops when it is
    exhausted (a length ``l`` is used only when all its products are done) or when ``k^l``
    exceeds ``max_products``, but always completes ``l = 1``."""
    B = _balanced_arb(F)
    best = root_upper(max(_inf_norm_upper(M) for M in B), 1)
    best_l = 1
    level = B
    per = norm_units(F.n)
    acc = 0.0                    # units not charged yet (whole units are charged as they add up)
    with arb_precision():
        for l in range(2, max_length + 1):
            if len(level) * F.k > max_products or work.exhausted:
                break
            new, mx = [], Fraction(0)
            for P in level:
                for M in B:
                    Q = P * M
                    new.append(Q)
                    mx = max(mx, _inf_norm_upper(Q))
                acc += per * F.k
                if acc >= 1:
                    work.charge(int(acc))
                    acc -= int(acc)
                if work.exhausted:
                    break
            else:
                u = root_upper(mx, l)
                if u < best:
                    best, best_l = u, l
                level = new
                continue
            break
    return best, best_l


def _solve_norms(F: Family, *, max_length: int, work: Work) -> _Bounds:
    L = max_length
    while F.k ** L > (1 << 16) and L > 1:
        L -= 1
    bf = brute_force_bounds(F.floats, L)
    word = bf["lower_word"]
    lower, rp = _lower_from_word(F, word)
    up, up_l = rigorous_norm_upper(F, max_length, work)
    return _Bounds(lower, up, word, rp, "norms of all products (textbook brute force)",
                   arithmetic_of(F), {"closed": False, "polytope_vertices": 0, "norm_length": up_l,
                               "products_enumerated_to": L})


def arithmetic_of(F: Family) -> str:
    """How the family's entries are represented (for the provenance)."""
    if F.kind == "ball":
        return ("Arb ball arithmetic over the input balls (the bounds hold for every family of "
                "real matrices with entries in the balls)")
    return ("exact rational (FLINT fmpq)" if F.exact_q is not None
            else "Arb ball arithmetic enclosing the exact entries")
