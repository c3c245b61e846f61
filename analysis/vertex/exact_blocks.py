"""Exact linear algebra of one Fourier block of the local subdivision matrix over ``Q(zeta)``,
``zeta = exp(2 pi i/n)``: eigenspaces (as complex balls, for the curvature test) and the Jordan structure of an
eigenvalue (ranks of the powers of ``B_k - mu I``, for the necessary condition of C^1).

Examples
--------
>>> import sympy as sp
>>> from analysis.vertex.rules import butterfly_rules
>>> jordan_ranks(butterfly_rules(2), 3, 0, sp.Rational(1, 4), 4)
[4, 3, 2, 1, 1]

Algorithm: the entries of ``B_k`` are Laurent polynomials in ``w = zeta^k`` with coefficients polynomial in
``C1 = cos(2 pi/n) = (zeta + 1/zeta)/2``; each is mapped into sympy's ``QQ.algebraic_field(zeta)`` and the matrix
is a ``DomainMatrix`` there (kernel, rank: exact).

References
----------
J. Peters, U. Reif, *Subdivision Surfaces*, Springer 2008, ch. 4 (the Fourier blocks of the subdivision matrix).
"""

from __future__ import annotations

import sympy as sp

from .blocks import fourier_block
from .rules import C1, LocalRules


def _exact_eigenspace(rules: LocalRules, n: int, k: int, mu_c1: sp.Expr):
    """Block k's size and a basis (as complex balls) of the kernel of B_k - mu I, computed exactly over
    Q(zeta), zeta = exp(2 pi i/n) (w = zeta^k, C1 = (zeta + 1/zeta)/2; mu a polynomial in C1), with sympy's
    DomainMatrix; None if an entry is not a rational polynomial in w and C1."""
    from flint import acb, fmpq

    got = _exact_shifted_block(rules, n, k, mu_c1)
    if got is None:
        return None
    K, M = got
    size = M.shape[0]
    kernel = M.nullspace().to_Matrix()
    z = acb(fmpq(2, n)).exp_pi_i()
    basis = []
    for r in range(kernel.rows):
        vec = []
        for j in range(size):
            x = K.from_sympy(kernel[r, j])
            coeffs = [sp.Rational(q) for q in x.to_list()]
            val = acb(0)
            for q in coeffs:
                val = val * z + acb(fmpq(int(q.p), int(q.q)))
            vec.append(val)
        basis.append(vec)
    return size, basis


def jordan_ranks(rules: LocalRules, n: int, k: int, mu_c1: sp.Expr, upto: int) -> list[int] | None:
    """``[size, rank(B_k - mu I), rank((B_k - mu I)^2), ..., rank((B_k - mu I)^upto)]``, exact over
    Q(exp(2 pi i/n)) (mu a polynomial in C1): the Jordan structure of mu in block k (the number of Jordan
    blocks of size >= j is ``r_(j-1) - r_j``); None if an entry is not a rational polynomial in w and C1.

    >>> from analysis.vertex.rules import butterfly_rules
    >>> jordan_ranks(butterfly_rules(2), 3, 0, sp.Rational(1, 4), 4)
    [4, 3, 2, 1, 1]
    """
    got = _exact_shifted_block(rules, n, k, mu_c1)
    if got is None:
        return None
    _, M = got
    ranks, P = [M.shape[0]], M
    for _ in range(upto):
        ranks.append(P.rank())
        P = P * M
    return ranks


def _exact_shifted_block(rules: LocalRules, n: int, k: int, mu_c1: sp.Expr):
    """``(K, B_k - mu I)`` as a DomainMatrix over ``K = Q(exp(2 pi i/n))``, or None (see :func:`_exact_eigenspace`)."""
    from sympy.polys.matrices import DomainMatrix

    from .blocks import _laurent, w

    K = sp.QQ.algebraic_field(sp.exp(2 * sp.pi * sp.I / n))
    zeta = K.from_sympy(sp.exp(2 * sp.pi * sp.I / n))
    zinv = zeta ** (n - 1)
    c1 = (zeta + zinv) * K.from_sympy(sp.Rational(1, 2))

    def elem(expr: sp.Expr):
        total = K.zero
        for l_, co in _laurent(sp.expand(expr), w).items():
            poly = sp.Poly(co, C1, domain="QQ")
            val = K.zero
            for (i,), q in poly.terms():
                val += K.from_sympy(sp.Rational(q)) * c1 ** i
            total += val * zeta ** ((l_ * k) % n)
        return total

    B = fourier_block(rules, k, n)
    size = B.rows
    try:
        mu = elem(mu_c1)
        rows = [[elem(B[i, j]) - (mu if i == j else K.zero) for j in range(size)] for i in range(size)]
    except (sp.PolificationFailed, sp.CoercionFailed, sp.GeneratorsNeeded):
        return None
    return K, DomainMatrix(rows, (size, size), K)
