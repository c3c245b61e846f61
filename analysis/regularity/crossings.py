"""Exact eigenvalue crossings of one-parameter binary families, and the proof that a stretch is not C^j.

A product ``T_w(p)`` of the transition matrices of ``2^(N-1) a(p) / (1+z)^N`` (coefficients polynomial in
``p``) with an eigenvalue of modulus ``>= theta = 2^{(N-1-j)|w|}`` at ``p`` shows that ``S_a(p)`` is not C^j
(:mod:`analysis.regularity.ranges`). :func:`_exact_boundaries` finds the algebraic ``p`` where an eigenvalue
equals ``+-theta`` (the roots of ``det(T_w(p) -+ theta I)`` over ``Q[p]``); :func:`_prove_not_cj` proves a whole
closed stretch not C^j by the signs of the same determinants between their real roots, and
:func:`_complement_stretches` applies it to the stretches between the counterexamples of a grid.

Examples
--------
>>> import schemes, sympy as sp
>>> a = schemes.get("four-point").symbol
>>> print(_prove_not_cj(a, a.params[0], 1, sp.Rational(1, 5), sp.Rational(1, 4), []))    # doctest: +ELLIPSIS
a real eigenvalue >= 1 of T_01(p) on the whole of it (exact: ...)

Algorithm
---------
Determinants over the polynomial ring ``Q[p]`` (sympy ``DomainMatrix``), exact real root isolation
(:class:`analysis.algebra.algebraic.RealAlgebraic`), intermediate values of the characteristic polynomial.

References
----------
I. Daubechies, J. C. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23 (1992).
"""

from __future__ import annotations

import functools
from typing import Sequence

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from ..algebra.algebraic import RealAlgebraic
from ..algebra.factorization import factor_out, smoothing_factor
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED
from ..stationary.transition import transition_matrices


_TRANSITIONS: dict = {}


def _domain_transitions(a: LaurentSymbol, K):
    """``(N, (T_0, T_1))``: the smoothing order and the transition matrices of ``2^(N-1) a / (1+z)^N``
    as ``DomainMatrix`` over the coefficient ring ``K`` (computed once per symbol)."""
    key = (a, K)
    if key not in _TRANSITIONS:
        if len(_TRANSITIONS) > 64:
            _TRANSITIONS.clear()
        N = smoothing_factor(a, exceptional=False).value
        c = factor_out(a, N) / 2
        T = tuple(DomainMatrix([[K.from_sympy(sp.expand(e)) for e in row] for row in t.tolist()],
                               t.shape, K) for t in transition_matrices(c))
        _TRANSITIONS[key] = (N, T)
    return _TRANSITIONS[key]


_CROSSINGS: dict = {}


def _crossing_polynomial(a: LaurentSymbol, K, p: sp.Symbol, word: tuple, ev):
    """``det(T_word(p) - ev I)`` over ``QQ[p]`` as a polynomial in ``p`` with integer coefficients (``None``
    when the coefficients are not rational): it depends on the symbol, the word and ``ev`` only, so the
    boundaries of every C^j set of a family (each ``_locate`` tries the same short words) compute it once."""
    key = (a, K, p, word, ev)
    if key not in _CROSSINGS:
        if len(_CROSSINGS) >= 512:
            _CROSSINGS.clear()
        T = _domain_transitions(a, K)[1]
        P = T[word[0]]
        for i in word[1:]:
            P = P * T[i]
        # the determinant over the polynomial ring QQ[p] of the coefficients, products taken there:
        # exact, and far faster than a symbolic Berkowitz determinant of expression entries
        M = P - DomainMatrix.eye(P.shape[0], K) * K.from_sympy(ev)
        try:
            # the numerator with integer coefficients (as sp.fraction(sp.together(.)) gives it)
            num = sp.Poly.from_dict(dict(M.det().items()), p, domain=sp.QQ).clear_denoms()[1]
        except (sp.polys.polyerrors.CoercionFailed, sp.PolynomialError):
            num = None
        _CROSSINGS[key] = num
    return _CROSSINGS[key]


def _support_shrinks(a: LaurentSymbol, p: sp.Symbol) -> list:
    """The non-constant end coefficients of ``c = 2^(N-1) a / (1+z)^N`` as polynomials in ``p``: where one
    vanishes the support of ``c`` is smaller than the generic one, and an eigenvalue of the generic matrices
    ``T_eps(p)`` there may belong to no operator of the scheme (for example ``c_{N-1}`` when ``c_N = 0``), so it
    proves nothing by itself."""
    K = a.domain
    N = _domain_transitions(a, K)[0]
    c = factor_out(a, N) / 2
    out = []
    for e in (c.mask[0], c.mask[-1]):
        P = sp.Poly(e, p)
        if P.degree() >= 1:
            out.append(P)
    return out


def _exact_boundaries(a: LaurentSymbol, p: sp.Symbol, j: int, word: Sequence[int], lo, hi):
    """Exact parameter values in (lo, hi) where the product T_word(p) has eigenvalue +-2^{(k-j)L}."""
    if not (a.domain.is_PolynomialRing and a.domain.domain.is_QQ):
        return []           # algebraic coefficients: no exact crossing over QQ (bisection decides)
    K = a.domain
    if tuple(K.symbols) != (p,):
        return []           # other free symbols: no exact crossing in p alone (bisection decides)
    N = _domain_transitions(a, K)[0]
    theta = sp.Integer(2) ** ((N - 1 - j) * len(word))
    out = []
    for sgn in (1, -1):
        num = _crossing_polynomial(a, K, p, tuple(word), sgn * theta)
        if num is None:
            return out      # algebraic coefficients: no exact crossing over QQ (bisection decides)
        if num.is_zero or num.degree() < 1 or num.count_roots(lo, hi) == 0:
            continue
        for r in RealAlgebraic.roots_of(num):
            if r.compare(RealAlgebraic.rational(lo)) >= 0 and r.compare(RealAlgebraic.rational(hi)) <= 0:
                out.append((r, sgn * theta, num))
    return out


def _complement_stretches(a, p, j, samples, boundaries, verdicts, point_verdict=None) -> list[dict]:
    """The stretches of consecutive non-C^j grid verdicts, each from the certified not-C^j point of the boundary
    on its left (or the grid's first point) to that on its right (or the last point), with ``proven``: whether
    :func:`_prove_not_cj` shows that no point of the closed stretch is C^j. A stretch next to an undecided grid
    point or an uncertified boundary is not attempted."""
    out = []
    n = len(samples)
    i = 0
    while i < n:
        if samples[i]["C^j"] is not False:
            i += 1
            continue
        s = i
        while i + 1 < n and samples[i + 1]["C^j"] is False:
            i += 1
        e = i
        i += 1
        ends = []
        for k, nb in ((s, s - 1), (e, e + 1)):
            if nb < 0 or nb >= n:
                ends.append(samples[k]["p"])
                continue
            pair = tuple(sorted((samples[k]["p"], samples[nb]["p"])))
            b = next((b for b in boundaries if tuple(b["between"]) == pair), None)
            if samples[nb]["C^j"] is None or b is None or b["status"] != CERTIFIED:
                ends.append(None)
            else:
                ends.append(b["exact"] if "exact" in b else b["certified_not_C^j_at"])
        st = {"from": ends[0], "to": ends[1], "proven": False}
        if None not in ends and RealAlgebraic.from_expr(ends[0]).compare(RealAlgebraic.from_expr(ends[1])) == 0:
            # one point: a grid point's certified verdict or the exact crossing of its boundary
            st.update(proven=True, how="a single point, certified not C^%d" % j)
        elif None not in ends:
            words = []
            for k in range(s, e + 1):
                r = verdicts.get(samples[k]["p"]) if verdicts else None
                for w in (r.witness.get("product") if r is not None else None,
                          r.witness["alpha"].witness.get("product")
                          if r is not None and r.witness.get("alpha") is not None else None):
                    if w and tuple(w) not in words:
                        words.append(tuple(w))
            proof = _prove_not_cj(a, p, j, ends[0], ends[1], words, point_verdict)
            if proof:
                st.update(proven=True, how=proof)
        out.append(st)
    return out


def _prove_not_cj(a, p, j, lo, hi, words, point_verdict=None) -> str | None:
    """A proof that ``S_a(p)`` is not C^j for every ``p`` in the closed interval ``[lo, hi]`` (exact or algebraic
    ends), or ``None``.

    Algorithm: for a word ``w`` of length ``L`` and a sign ``s``, with ``theta = 2^{(N-1-j)L}`` (the threshold of
    :func:`_exact_boundaries`: an eigenvalue of ``T_w(p)`` of modulus ``>= theta`` means not C^j) and ``n`` the size
    of the matrices, the characteristic polynomial ``chi_p(x) = det(x I - T_w(p))`` is monic of degree ``n``, so
    ``chi_p(theta) <= 0`` gives a real eigenvalue ``>= theta`` and ``(-1)^n chi_p(-theta) <= 0`` one ``<= -theta``
    (intermediate values). Both are polynomials ``f`` in ``p`` over Q (up to a positive factor:
    :func:`_crossing_polynomial`). The real roots of every candidate ``f`` inside ``(lo, hi)`` (exact isolation) cut
    the interval into pieces on which no candidate changes sign; a piece is covered when some ``f`` is negative at a
    rational point inside it (then ``f <= 0`` on the closed piece), and the stretch is proven when every piece is.
    Candidates, added one at a time until every piece is covered: the products found at the grid points of the
    stretch, then every product of length at most 4. Where the support of the mask shrinks
    (:func:`_support_shrinks`) the determinants prove nothing: such a point must be rational and
    ``point_verdict(value)`` (the scheme's certified C^j verdict there) ``False``. Where the mask has more smoothing
    factors than generically (exceptional ``p``), the generic matrices only gain eigenvalues ``2^-k``, ``k >= 1``,
    below ``theta >= 1`` (``j <= N - 1`` is required), so they never make a piece negative by themselves. Grid words
    longer than 8 are not tried (the determinant over ``Q[p]`` grows with the length).
    """
    from itertools import product as all_words

    if not (a.domain.is_PolynomialRing and a.domain.domain.is_QQ) or tuple(a.domain.symbols) != (p,):
        return None
    K = a.domain
    N, T = _domain_transitions(a, K)
    if j > N - 1:
        return None
    n = T[0].shape[0]
    L, H = RealAlgebraic.from_expr(lo), RealAlgebraic.from_expr(hi)
    if L.compare(H) >= 0:
        return None
    for P in _support_shrinks(a, p):            # there only the scheme's own verdict counts
        for r in RealAlgebraic.roots_of(P):
            if L.compare(r) <= 0 <= H.compare(r) and (
                    not r.is_rational or point_verdict is None or point_verdict(r.expr) is not False):
                return None
    cands = [w for w in words if len(w) <= 8]
    for length in range(1, 5):
        for w in all_words(range(2), repeat=length):
            if min(w[i:] + w[:i] for i in range(length)) == w and w not in cands:
                cands.append(w)
    def batches():      # the products of the grid points first: most stretches need nothing else
        for word in cands:
            theta = sp.Integer(2) ** ((N - 1 - j) * len(word))
            out = []
            for sgn in (1, -1):
                num = _crossing_polynomial(a, K, p, tuple(word), sgn * theta)
                if num is None:
                    return
                out.append((num if sgn < 0 else num * (-1) ** n, "a real eigenvalue %s %s of T_%s(p)" % (
                    ">=" if sgn > 0 else "<=", sp.sstr(sgn * theta), "".join(map(str, word)))))
            yield out

    return sign_cover(L, H, batches())


def sign_cover(L: RealAlgebraic, H: RealAlgebraic, batches) -> str | None:
    """Whether the polynomials ``f`` of ``batches`` (lists of ``(f, label)``, one-variable ``sp.Poly`` over Q, each
    ``f <= 0`` meaning "not C^j" there) cover the closed interval ``[L, H]``: the real roots of every ``f`` so far
    inside ``(L, H)`` (exact isolation) cut it into pieces on which none changes sign, and a piece is covered when
    one ``f`` is negative at a rational point inside it (then ``f <= 0`` on the closed piece). Batches are added
    one at a time until every piece is covered; the proof text, or ``None``."""
    from ..algebra.algebraic import rational_between

    polys, roots = [], [L, H]
    for batch in batches:
        for f, label in batch:
            if f.is_zero:
                return label + " identically"
            if f.degree() >= 1:
                roots += [r for r in RealAlgebraic.roots_of(f) if L.compare(r) < 0 < H.compare(r)]
            polys.append((f, label))
        cuts = sorted(roots, key=functools.cmp_to_key(lambda u, v: u.compare(v)))
        cuts = [c for k, c in enumerate(cuts) if k == 0 or cuts[k - 1].compare(c) != 0]
        used = []
        for left, right in zip(cuts[:-1], cuts[1:]):
            q = rational_between(left, right)
            hit = next((label for f, label in polys if f.eval(q) < 0), None)
            if hit is None:
                break
            if hit not in used:
                used.append(hit)
        else:
            return ("%s on the whole of it (exact: %d piece(s) cut at the real roots of the determinants, on each "
                    "of which one of them is negative)" % ("; ".join(used), len(cuts) - 1))
    return None
