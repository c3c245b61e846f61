"""Certified bounds of the L-step norm of a one-parameter difference scheme over a parameter box.

For a difference symbol ``a_k(z; p)`` whose coefficients are polynomials in one parameter ``p``
over QQ, every coefficient ``c_i(p)`` of ``(1/m)^L a_k(z) a_k(z^m) ... a_k(z^{m^{L-1}})`` is a
polynomial of degree at most ``L deg`` in ``p``, and

    N_L(p) = ||(1/m S_{a_k})^L||_inf = max_r sum_{i = r mod m^L} |c_i(p)|.

:class:`ParametricNorm` holds the ``c_i`` as one integer matrix (computed with one FLINT
Kronecker product, so L = 10 costs milliseconds) and decides ``N_L < 1`` on a parameter piece:

* :meth:`ParametricNorm.box_bound` — on a closed rational box ``[u, v]``, the exact rational
  ``max_r max_j sum_{i in r} |B_j(c_i)|`` with ``B_j`` the Bernstein coefficients of ``c_i`` on the
  box: since the Bernstein basis is non-negative and sums to 1, ``|c_i(p)| <= sum_j |B_j(c_i)| b_j(p)``
  and the bound holds for every ``p`` in the box (where ``c_i`` has one sign it is exact:
  ``sum_i s_i B_j(c_i)`` are the Bernstein coefficients of the signed residue sum);
* :meth:`ParametricNorm.end_piece` — on a half-open piece ``(e, w]`` (or ``[w, e)``) next to a
  real algebraic end ``e``: the signs of the ``c_i`` on the open piece are fixed (Bernstein signs,
  or exact root isolation), each residue sum ``P_r = sum s_i c_i`` is one polynomial there, and
  ``P_r < 1`` on the piece is decided exactly: ``P_r(e) <= 1`` (exact sign at ``e``), ``P_r(w) < 1``
  and no root of ``P_r - 1`` strictly between. This lets a certificate reach an open end where
  ``N_L(e) = 1`` (a norm-type end), which no closed box can.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.stationary.difference import difference_symbol
>>> w = sp.Symbol("w")
>>> a = LaurentSymbol.from_mask([-w, 0, w + sp.Rational(1, 2), 1, w + sp.Rational(1, 2), 0, -w], start=-3)
>>> N = ParametricNorm(difference_symbol(a, 2), w, 3)
>>> N.box_bound(sp.Rational(1, 16), sp.Rational(1, 12)) < 1      # the 4-point scheme is C^1 there
True
>>> N.box_bound(sp.Rational(1, 6), sp.Rational(1, 5)) < 1
False

Algorithm
---------
1. Scale the difference symbol to integer coefficients (common denominator ``d``); encode
   ``z^i p^e`` as ``x^{iK + e}`` (``K = L deg + 1``), multiply the ``L`` dilated symbols in
   ``fmpz_poly`` and read the coefficient polynomials back: ``c_i = C_i / (d m)^L``.
2. Box bound: ``t = u + (v - u) s``; the Bernstein coefficients are ``C M`` with one rational
   ``(n+1) x (n+1)`` matrix ``M`` (Taylor shift, then the power-to-Bernstein change of basis);
   ``C M`` is an exact ``fmpz_mat`` product, and the residue sums of ``|C M|`` are exact integers.
   A float copy screens boxes first; only boxes the floats say are below 1 are checked exactly.
3. End piece: sign constancy from the Bernstein signs on a rational enclosure, else from exact
   root isolation (:class:`~analysis.algebra.algebraic.RealAlgebraic`); then the three exact
   tests above for every residue whose Bernstein bound does not already settle it.

Precision and conditioning
--------------------------
Everything that decides is exact (integers, rationals, real algebraic numbers); floats only
choose which boxes to check. The Bernstein bound converges quadratically as boxes shrink.

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Thm 3.3.
R. T. Farouki, *The Bernstein polynomial basis: a centennial retrospective*, CAGD 29 (2012).
"""

from __future__ import annotations

from fractions import Fraction
from functools import cached_property
from math import comb, lcm

import numpy as np
import sympy as sp

from ..algebra.algebraic import RealAlgebraic
from ..algebra.symbol import LaurentSymbol
from ..result import AnalysisError
from ..algebra.reader import as_expr


def _fr(q) -> Fraction:
    if isinstance(q, Fraction):
        return q
    q = sp.Rational(q)
    return Fraction(int(q.p), int(q.q))


def _bernstein_change(n: int):
    """``W`` with ``W[k][j] = C(j, k) / C(n, k)`` (power basis on [0, 1] -> Bernstein), as fmpq_mat."""
    from flint import fmpq, fmpq_mat

    if n not in _W_CACHE:
        _W_CACHE[n] = fmpq_mat(n + 1, n + 1, [fmpq(comb(j, k), comb(n, k)) if k <= j else fmpq(0)
                                              for k in range(n + 1) for j in range(n + 1)])
    return _W_CACHE[n]


_W_CACHE: dict = {}
_WF_CACHE: dict = {}


def _bernstein_matrix(u: Fraction, v: Fraction, n: int):
    """``M`` (fmpq_mat) with ``(Bernstein coefficients on [u, v]) = (power coefficients) M``."""
    from flint import fmpq, fmpq_mat

    uu, hh = fmpq(u.numerator, u.denominator), fmpq(v.numerator - 0, v.denominator) - fmpq(u.numerator, u.denominator)
    T = fmpq_mat(n + 1, n + 1, [comb(e, k) * uu ** (e - k) * hh ** k if k <= e else fmpq(0)
                                for e in range(n + 1) for k in range(n + 1)])
    return T * _bernstein_change(n)


def _bernstein_matrix_float(u: float, v: float, n: int) -> np.ndarray:
    if n not in _WF_CACHE:
        W = np.array([[comb(j, k) / comb(n, k) if k <= j else 0.0 for j in range(n + 1)] for k in range(n + 1)])
        # the Taylor-shift pattern: binomials C(e, k) (as Python converts them in int * float) and the
        # index e - k of the power of u, on and below the diagonal
        e, k = np.indices((n + 1, n + 1))
        B = np.array([[float(comb(i, j)) if j <= i else 0.0 for j in range(n + 1)] for i in range(n + 1)])
        _WF_CACHE[n] = (W, B, np.where(k <= e, e - k, 0), k <= e)
    W, B, shift, lower = _WF_CACHE[n]
    h = v - u
    # T[e, k] = C(e, k) * u^(e-k) * h^k, the same float operations in the same order as element by element
    up = np.array([u ** i for i in range(n + 1)])
    hp = np.array([h ** i for i in range(n + 1)])
    T = np.where(lower, (B * up[shift]) * hp[None, :], 0.0)
    return T @ W


class ParametricNorm:
    """``N_L(p) = ||(1/m S_{a_k})^L||_inf`` of a difference symbol over ``QQ[p]`` (see module)."""

    def __init__(self, am: LaurentSymbol, p: sp.Symbol, L: int, arity: int = 2):
        from flint import fmpz_poly

        if L < 1:
            raise AnalysisError("L must be a positive integer")
        self.L, self.arity, self.p = L, arity, p
        polys = []
        for c in am.mask:
            c = as_expr(c)
            if c.free_symbols - {p}:
                raise AnalysisError(f"the coefficients must depend on {p.name} only")
            try:
                polys.append(sp.Poly(c, p, domain=sp.QQ))
            except (sp.PolificationFailed, sp.PolynomialError, sp.polys.polyerrors.CoercionFailed):
                raise AnalysisError(f"the parametric norm needs coefficients that are polynomials in {p.name} "
                                    f"over the rationals, not {sp.sstr(c)}") from None
        deg = max((q.degree() for q in polys if not q.is_zero), default=0)
        d = lcm(*[int(sp.Rational(co).q) for q in polys for co in q.all_coeffs()])
        ints = [[int(co * d) for co in reversed(q.all_coeffs())] if not q.is_zero else [] for q in polys]
        K = L * max(deg, 0) + 1
        prod = None
        for level in range(L):
            step = arity ** level
            if prod is None:
                coeffs = [0] * ((len(ints) - 1) * step * K + K)
                for i, cs in enumerate(ints):
                    for e, v in enumerate(cs):
                        coeffs[i * step * K + e] = v
                prod = fmpz_poly(coeffs)
                continue
            # times a(z^step): a sum of shifted copies of prod (the factor is sparse: a dense product
            # would multiply through its long runs of zeros)
            nxt = None
            for i, cs in enumerate(ints):
                if cs:
                    term = (prod * fmpz_poly(cs)).left_shift(i * step * K)
                    nxt = term if nxt is None else nxt + term
            prod = nxt
        flat = [int(x) for x in prod.coeffs()]
        flat += [0] * (-len(flat) % K)
        mod = arity ** L
        rows = []
        for i in range(len(flat) // K):
            row = flat[i * K:(i + 1) * K]
            if any(row):
                rows.append((i % mod, row))
        rows.sort(key=lambda t: t[0])
        self.n = K - 1
        self.residues = [r for r, _ in rows]
        self.C = [row for _, row in rows]
        self.scale = (d * arity) ** L
        self.starts = [k for k in range(len(rows)) if k == 0 or rows[k][0] != rows[k - 1][0]]
        self._Cf = np.array(self.C, dtype=float) / float(self.scale) if rows else np.zeros((0, K))
        self._sizes_max = max(b - a for a, b in zip(self.starts, self.starts[1:] + [len(rows)])) if rows else 0

    @cached_property
    def _Cz(self):
        """The rows as an ``fmpz_mat`` for the exact tests, formed when one is first made (most norms are
        only screened in floating point)."""
        from flint import fmpz_mat

        return fmpz_mat(self.C) if self.C else None

    # ------------------------------------------------------------------ closed rational boxes
    def float_box_bound(self, u, v) -> float:
        """The Bernstein bound in floating point (for screening only)."""
        if not self.C:
            return 0.0
        M = _bernstein_matrix_float(float(_fr(u)), float(_fr(v)), self.n)
        B = np.abs(self._Cf @ M)
        return float(np.add.reduceat(B, self.starts, axis=0).max())

    def _bernstein_ints(self, u: Fraction, v: Fraction):
        """The integer Bernstein coefficients of every row on ``[u, v]`` (an object array of ``fmpz``:
        exact integers, compared and summed as Python ints are) and their common denominator."""
        Mz, Q = _bernstein_matrix(u, v, self.n).numer_denom()
        Q = int(Q)
        B = self._Cz * Mz
        vals = np.array(B.entries(), dtype=object).reshape(len(self.C), self.n + 1)
        return vals, Q

    def box_bound(self, u, v) -> Fraction:
        """Exact rational upper bound of ``N_L`` on the closed box ``[u, v]`` (Bernstein).

        The bound is the exact maximum over residues ``r`` and Bernstein indices ``j`` of
        ``S_rj = sum_{i in r} |B_ij|``. Only the residues that can hold the maximum are summed
        exactly: a float copy of every ``S_rj`` with an a-priori error bound (below) excludes the
        others; when the floats cannot exclude enough (or are not finite) every residue is summed
        exactly. The error bound: with ``B = C M`` computed from the float copies ``C / scale`` and
        ``M`` (each entry correctly rounded, at most two roundings), each ``|B_ij|`` is off by at most
        ``(K + 3) u (|C| |M|)_ij`` (``K = n + 1`` products, ``u = 2^-53``; Higham, Accuracy and Stability
        of Numerical Algorithms, 2nd ed., Sect. 3.5), and the sum over the ``g`` rows of a residue adds
        ``g u S``; ``1e-9`` times the float ``sum_{i in r} (|C| |M|)_ij`` exceeds both by a factor of
        more than 10^4 for the sizes built here (``K + g < 10^4``), plus ``1e-280`` for underflow."""
        if not self.C:
            return Fraction(0)
        Mz, Q = _bernstein_matrix(_fr(u), _fr(v), self.n).numer_denom()
        Q = int(Q)
        groups = self._candidate_residues(Mz, Q)
        if groups is None:
            B = self._Cz * Mz
            vals = np.array([int(x) for x in B.entries()], dtype=object).reshape(len(self.C), self.n + 1)
            sums = np.add.reduceat(np.abs(vals), self.starts, axis=0)
            return Fraction(int(sums.max()), self.scale * Q)
        K = self.n + 1
        M = [[int(Mz[e, j]) for j in range(K)] for e in range(K)]
        ends = self.starts + [len(self.C)]
        best = 0
        for g in groups:
            S = [0] * K
            for row in self.C[ends[g]:ends[g + 1]]:
                for j in range(K):
                    S[j] += abs(sum(c * M[e][j] for e, c in enumerate(row) if c))
            best = max(best, max(S))
        return Fraction(best, self.scale * Q)

    def _candidate_residues(self, Mz, Q: int) -> list[int] | None:
        """The residue groups whose float ``max_j S_rj`` (plus its error bound, see :meth:`box_bound`)
        reaches the largest float ``S_rj`` minus its error bound; None when the floats do not settle it."""
        if self._sizes_max + self.n + 1 >= 10 ** 4:
            return None
        K = self.n + 1
        Mf = np.array([[int(Mz[e, j]) / Q for j in range(K)] for e in range(K)])
        with np.errstate(all="ignore"):
            Bf = self._Cf @ Mf
            Af = np.add.reduceat(np.abs(self._Cf) @ np.abs(Mf), self.starts, axis=0)
            Sf = np.add.reduceat(np.abs(Bf), self.starts, axis=0)
            err = 1e-9 * Af + 1e-280
            if not (np.isfinite(Sf).all() and np.isfinite(err).all()):
                return None
            low = float((Sf - err).max())
            keep = np.flatnonzero(((Sf + err) >= low).any(axis=1))
        if len(keep) > 64:
            return None
        return [int(g) for g in keep]

    def box_below(self, u, v, bound=1, *, margin: float = 1e-9) -> Fraction | None:
        """The exact Bernstein bound when it is below ``bound`` on ``[u, v]``, else ``None``."""
        if self.float_box_bound(u, v) >= float(bound) + margin:
            return None
        b = self.box_bound(u, v)
        return b if b < _fr(bound) else None

    # ------------------------------------------------------------------ a piece next to an end
    def _poly(self, row) -> sp.Poly:
        return sp.Poly(list(reversed(row)), self.p, domain=sp.QQ)

    def end_piece(self, e: RealAlgebraic, w, side: int, bound=1) -> dict | None:
        """Decide ``N_L < bound`` on ``(e, w]`` (``side = +1``) or ``[w, e)`` (``side = -1``) exactly.

        Returns a witness (the residue polynomials that reach ``bound`` at ``e``) or ``None``
        when the test fails (signs not constant on the piece, or a residue sum reaches ``bound``).
        """
        w = _fr(w)
        if not self.C:
            return {"touching": []}
        wq = sp.Rational(w.numerator, w.denominator)
        W = RealAlgebraic.rational(wq)
        if (W.compare(e) if side > 0 else e.compare(W)) <= 0:
            raise AnalysisError("the end piece is empty")
        # a rational enclosure of e on the far side: [e_out, w] contains the piece
        while (side > 0 and not e.b < wq) or (side < 0 and not e.a > wq):
            e.refine()
        e_out = _fr(e.a if side > 0 else e.b)
        box = (e_out, w) if side > 0 else (w, e_out)
        vals, Q = self._bernstein_ints(*box)
        signs = []
        mid = None
        for k, row in enumerate(vals):
            if all(x >= 0 for x in row):
                signs.append(1)
            elif all(x <= 0 for x in row):
                signs.append(-1)
            else:   # exact: no root of c_k strictly inside the piece, sign at an inner rational
                poly = self._poly(self.C[k])
                for r in RealAlgebraic.roots_of(poly):
                    inside = (r.compare(e) > 0 and r.compare(W) < 0) if side > 0 else \
                             (r.compare(W) > 0 and r.compare(e) < 0)
                    if inside:
                        return None
                if mid is None:
                    from ..algebra.algebraic import rational_between

                    mid = rational_between(e, W) if side > 0 else rational_between(W, e)
                s = int(sp.sign(poly.eval(mid)))
                if s == 0:
                    return None
                signs.append(s)
        signs = np.array(signs, dtype=object)
        bnd = _fr(bound)
        touching = []
        ends = self.starts + [len(self.C)]
        for g in range(len(self.starts)):
            lo, hi = ends[g], ends[g + 1]
            sb = (signs[lo:hi, None] * vals[lo:hi]).sum(axis=0)
            if Fraction(int(max(sb)), self.scale * Q) < bnd:
                continue                       # the Bernstein bound settles this residue
            coeffs = [sum(int(signs[i]) * self.C[i][c] for i in range(lo, hi)) for c in range(self.n + 1)]
            P = self._poly(coeffs) - sp.Poly(sp.Rational(bnd.numerator, bnd.denominator) * self.scale, self.p)
            if P.is_zero or P.eval(wq) >= 0 or e.sign_of(P) > 0:
                return None
            roots = RealAlgebraic.roots_of(P)
            for r in roots:
                inside = (r.compare(e) > 0 and r.compare(W) < 0) if side > 0 else \
                         (r.compare(W) > 0 and r.compare(e) < 0)
                if inside:
                    return None
            touching.append({"residue": self.residues[lo],
                             "sum": sp.sstr(sp.expand(P.as_expr() / self.scale + sp.Rational(bnd.numerator, bnd.denominator))),
                             "at_end": "= bound" if e.sign_of(P) == 0 else "< bound",
                             # the root isolation: every real root of sum - bound, none strictly inside the piece
                             "roots_of_sum_minus_bound": [f"[{sp.sstr(r.a)}, {sp.sstr(r.b)}]" for r in roots]})
        return {"touching": touching}
