"""The local subdivision matrix and its Fourier blocks: the discrete Fourier transform of the rotational
symmetry splits the (m n + 1) x (m n + 1) matrix into one (m + 1) x (m + 1) block (k = 0, with the
centre) and m x m blocks k = 1, ..., n - 1, exact in ``w = exp(2 pi i k / n)``; their characteristic
polynomials are polynomials in ``c = cos(2 pi k / n)`` (block k and block n - k are mirror images).

With sector points ``x[j, p] = sum_k w_k^j y[k, p]`` a rule ``x'[i, q] = sum_(d, p) B_qp(d) x[i + d, p]``
becomes ``y'[k, q] = sum_p (sum_d B_qp(d) w^d) y[k, p]``; a weight ``a(j) = sum_l a_l W^l`` on every
sector j (``W = exp(2 pi i j/n)``) contributes ``n * sum_(l = -k mod n) a_l``; the centre only meets
block 0, where its rule contributes ``n`` times its weight on each sector point.

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> B = fourier_block(scheme_rules("loop", ring=1), 1, 5)
>>> B == sp.Matrix([[sp.Rational(3, 8) + w / 8 + 1 / (8 * w)]])
True
>>> block_charpoly(B) == lam - c / 4 - sp.Rational(3, 8)
True

Algorithm
---------
Entries are Laurent polynomials in ``w``; the characteristic polynomial ``det(lam I - B)`` is computed by
sympy (Berkowitz) and rewritten with ``w^l + w^-l = 2 T_l(c)`` (Chebyshev). A polynomial that is not
symmetric in ``w <-> 1/w`` means rules without mirror symmetry, which this layer refuses.

References
----------
J. Peters, U. Reif, Subdivision Surfaces, Springer 2008, section 5.3 (the discrete Fourier transform of
the subdivision matrix); J. Stam, Exact evaluation of Catmull–Clark subdivision surfaces at arbitrary
parameter values, SIGGRAPH 1998 (the matrices of Catmull–Clark on the 2-ring).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from ..result import AnalysisError
from .rules import ALL, C1, CENTRE, W, LocalRules, n_sym

w = sp.Symbol("w")
c = sp.Symbol("c")
lam = sp.Symbol("lam")


def _laurent(expr: sp.Expr, var: sp.Symbol) -> dict[int, sp.Expr]:
    """Coefficients of a Laurent polynomial in ``var``."""
    expr = sp.expand(expr)
    out: dict[int, sp.Expr] = {}
    for t in sp.Add.make_args(expr):
        coeff, e = sp.S.One, 0
        for f in sp.Mul.make_args(t):
            b, ex = f.as_base_exp()
            if b == var and ex.is_Integer:
                e += int(ex)
            elif f.has(var):
                raise AnalysisError(f"weight {sp.sstr(expr)} is not a Laurent polynomial in {var}")
            else:
                coeff *= f
        out[e] = out.get(e, 0) + coeff
    return {k: v for k, v in out.items() if v != 0}


def _all_sum(weight: sp.Expr, k: int, n: int | None) -> sp.Expr:
    """``sum_j weight(W = w_n^j) w_n^(jk)``: n times the coefficients of W^l with l = -k (mod n).
    With ``n=None`` (n symbolic, taken large) only l = -k counts."""
    coeffs = _laurent(weight, W)
    if n is None:
        return n_sym * coeffs.get(-k, 0)
    return n * sum((a for l_, a in coeffs.items() if (l_ + k) % n == 0), sp.S.Zero)


def special_frequencies(rules: LocalRules) -> set[int]:
    """The frequencies l (as -l = k) at which weights on every sector contribute to a block k != 0."""
    out = set()
    for rule in rules.sector_rules():
        for t in rule:
            if t.source[-1] == ALL:
                out |= {abs(l_) for l_ in _laurent(t.weight, W)}
    return out


def fourier_block(rules: LocalRules, k: int, n: int | None) -> sp.Matrix:
    """Block k of the local subdivision matrix at valence ``n`` (``None``: symbolic n, taken larger than
    every frequency of the rules), as a matrix of Laurent polynomials in ``w = exp(2 pi i k/n)``. Block 0
    has the centre first (if the rules have one)."""
    m = len(rules.points)
    nn = n_sym if n is None else sp.Integer(n)
    off = 1 if (rules.centre and k == 0) else 0
    B = sp.zeros(m + off, m + off)
    if off:
        for t in rules.rules[0]:
            if t.source == (CENTRE,):
                B[0, 0] += t.weight
            elif t.source[1] == ALL:
                B[0, 1 + t.source[0]] += _all_sum(t.weight, 0, n)
            else:
                raise AnalysisError("the centre's rule must weigh every sector alike (a weight on 'all')")
    for q, rule in enumerate(rules.sector_rules()):
        for t in rule:
            if t.source == (CENTRE,):
                if off:
                    B[off + q, 0] += t.weight
                continue
            p, d = t.source
            B[off + q, off + p] += _all_sum(t.weight, k, n) if d == ALL else t.weight * w ** d
    if k == 0:                                 # w = exp(0) = 1: block 0 is a matrix of numbers
        B = B.subs(w, 1)
    return B.subs(n_sym, nn).applyfunc(sp.expand)


def _cos_form(expr: sp.Expr) -> sp.Expr:
    """A Laurent polynomial in w symmetric under w <-> 1/w, written in c = (w + 1/w)/2."""
    coeffs = _laurent(expr, w)
    out = coeffs.get(0, sp.S.Zero)
    for l_, a in coeffs.items():
        if l_ > 0:
            if sp.expand(a - coeffs.get(-l_, 0)) != 0:
                raise AnalysisError("the rules are not mirror-symmetric (block k and block n-k differ): "
                                    "give weights that depend on j through cos(2*pi*l*j/n) only")
            out += 2 * a * sp.chebyshevt(l_, c)
        elif -l_ not in coeffs:
            raise AnalysisError("the rules are not mirror-symmetric (block k and block n-k differ): "
                                "give weights that depend on j through cos(2*pi*l*j/n) only")
    return sp.expand(out)


def block_charpoly(B: sp.Matrix) -> sp.Expr:
    """``det(lam I - B)`` as a polynomial in lam and c = cos(2 pi k/n) (and n, C1 if the weights have them)."""
    p = B.charpoly(lam).as_expr()
    return sp.expand(sum(_cos_form(co) * lam ** i for (i,), co in
                         sp.Poly(sp.expand(p), lam).terms()))


@lru_cache(maxsize=256)
def cos_minimal_polynomial(d: int) -> sp.Poly:
    """The minimal polynomial over Q of cos(2 pi / d), in the variable C1 (monic).

    >>> cos_minimal_polynomial(5)
    Poly(C1**2 + 1/2*C1 - 1/4, C1, domain='QQ')
    """
    if d == 1:
        return sp.Poly(C1 - 1, C1, domain="QQ")
    if d == 2:
        return sp.Poly(C1 + 1, C1, domain="QQ")
    phi = sp.Poly(sp.cyclotomic_poly(d, w), w)
    h = phi.degree() // 2
    e = sp.expand(phi.as_expr() / w ** h)
    p = sp.Poly(_cos_form(e).subs(c, C1), C1, domain="QQ")
    return p.monic()


def local_matrix(rules: LocalRules, n: int) -> sp.Matrix:
    """The full local subdivision matrix at valence ``n`` (centre first, then sector 0's points, sector
    1's, ...), exact (``cos(2 pi l j/n)`` as sympy values): the object the Fourier blocks diagonalise, for
    checking them.

    >>> from analysis.vertex.rules import scheme_rules
    >>> local_matrix(scheme_rules("loop-warren", ring=1), 4)[0, :]
    Matrix([[5/8, 3/32, 3/32, 3/32, 3/32]])
    """
    m = len(rules.points)
    off = 1 if rules.centre else 0
    size = m * n + off
    S = sp.zeros(size, size)

    def col(p: int, j: int) -> int:
        return off + (j % n) * m + p

    def weight_at(wt: sp.Expr, j: int) -> sp.Expr:
        coeffs = _laurent(wt, W)
        return sum((a * sp.cos(2 * sp.pi * l_ * j / n) for l_, a in coeffs.items()), sp.S.Zero)

    def fill(row: int, rule, i: int) -> None:
        for t in rule:
            if t.source == (CENTRE,):
                S[row, 0] += t.weight
            elif t.source[1] == ALL:
                for j in range(n):
                    S[row, col(t.source[0], i + j)] += weight_at(t.weight, j)
            else:
                S[row, col(t.source[0], i + t.source[1])] += t.weight

    if rules.centre:
        fill(0, rules.rules[0], 0)
    for i in range(n):
        for q, rule in enumerate(rules.sector_rules()):
            fill(col(q, i), rule, i)
    return S.subs({n_sym: n, C1: sp.cos(2 * sp.pi / n)})
