"""m-ary stationary schemes: difference schemes, exact norms, the Dyn–Levin test, transition matrices,
local subdivision matrices, support of the basic limit function, refinement of polygons.

Convention (arity ``m >= 2``; README "Conventions")::

    (S_a f)_i = sum_j a_{i-mj} f_j,     (S_a f)(z) = a(z) f(z^m),     q_m(z) = 1 + z + ... + z^{m-1}.

Difference schemes (derivation). With ``(Delta f)_i = f_{i+1} - f_i``, i.e. ``(Delta f)(z) = (z^{-1} - 1) f(z)``,
``Delta S_a f = S_b Delta f`` holds iff ``(z^{-1} - 1) a(z) = b(z) (z^{-m} - 1)``, i.e.
``b(z) = z^{m-1} a(z) / q_m(z)``. The divided differences ``m^{nk} Delta^k f^n`` (spacing ``m^{-n}``) are
refined by

* ``"paper"``:   ``a_k(z) = (m z^{m-1} / q_m(z))^k a(z)``   (for ``m = 2``: ``(2z/(1+z))^k a``, as today);
* ``"divided"``: ``b_k(z) = (m / q_m(z))^k a(z)`` — the same up to the shift ``z^{k(m-1)}``.

``S_{a_k}`` converges iff its difference scheme ``z^{m-1} a_k/q_m = (1/m) a_{k+1}`` is contractive, hence the
m-ary Dyn–Levin test: ``||(1/m S_{a_{k+1}})^L||_inf < 1`` for some ``L`` implies ``C^k``.

Norms: ``||S_a||_inf = max_r sum_j |a_{r+mj}|``; the L-step symbol is
``a^[L](z) = a(z) a(z^m) ... a(z^{m^{L-1}})`` and its residues are taken mod ``m^L``.

Transition matrices of a mask ``c`` with support ``[0, N]``: ``(T_eps)_{ij} = c_{m i - j + eps}``,
``eps = 0..m-1``, ``i, j = 0..n-1`` with ``n = max(ceil(N/(m-1)), 1)`` (``phi`` has support ``[0, N/(m-1)]``;
``v(x) = (phi(x+j))_j``, ``v((x+eps)/m) = T_eps v(x)``). For ``m = 2``, ``n = N`` as in
:func:`analysis.stationary.transition.transition_matrices`.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> a = LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)")           # ternary quadratic B-spline
>>> difference_symbol_mary(a, 1, 3)
LaurentSymbol([1/3, 2/3, 1, 2/3, 1/3], start=-1, domain=QQ)
>>> r = difference_norm_mary(a, 2, 3)                                 # ||(1/3 S_{a_2})|| < 1: C^1
>>> r.value, r.witness["contractive"]
(1/3, True)
>>> basic_limit_support_mary(a, 3).value                              # [s, e]/(m - 1)
(-3/2, 3/2)

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002) 73-144 (Sect. 3).
M. F. Hassan, I. P. Ivrissimitzis, N. A. Dodgson, M. A. Sabin, *An interpolating 4-point C^2 ternary
stationary subdivision scheme*, Comput. Aided Geom. Design 19 (2002) 1-18 (m-ary Laurent analysis).
I. Daubechies, J. C. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23 (1992).
"""

from __future__ import annotations

from fractions import Fraction
from math import lcm
from typing import Sequence

import numpy as np
import sympy as sp

from ..algebra.algebraic import sign
from ..algebra.mary import check_arity, factor_out_mary
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, AnalysisError, Result
from ..algebra.reader import as_expr

SPELLINGS = ("divided", "paper")

__all__ = ["difference_symbol_mary", "iterated_symbol_mary", "residue_sums_mary", "scheme_norm_mary",
           "difference_norm_mary", "transition_matrices_mary", "invariant_window_mary",
           "local_subdivision_matrix_mary", "local_eigenvalues_mary", "basic_limit_support_mary",
           "refine_mary"]


def difference_symbol_mary(a: LaurentSymbol, k: int, m: int, *, spelling: str = "paper") -> LaurentSymbol:
    """``(m z^{m-1}/q_m)^k a`` ("paper") or ``(m/q_m)^k a`` ("divided"); an :class:`AnalysisError`
    when ``q_m^k`` does not divide ``a`` identically.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
    >>> difference_symbol_mary(a, 1, 2)
    LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
    """
    m = check_arity(m)
    if spelling not in SPELLINGS:
        raise AnalysisError(f"unknown spelling {spelling!r}; use 'divided' or 'paper'")
    if not isinstance(k, int) or k < 0:
        raise AnalysisError(f"the difference order must be a non-negative integer, not {k!r}")
    b = factor_out_mary(a, k, m)
    return b.shift(k * (m - 1)) if spelling == "paper" else b


def iterated_symbol_mary(a: LaurentSymbol, L: int, m: int) -> LaurentSymbol:
    """``a(z) a(z^m) ... a(z^{m^{L-1}})``, the symbol of ``S_a^L``."""
    if not isinstance(L, int) or L < 1:
        raise AnalysisError(f"L must be a positive integer, not {L!r}")
    out = a
    for j in range(1, L):
        out = out * a.upsample(m ** j)
    return out


def _rational_residue_sums(a: LaurentSymbol, L: int, m: int) -> list[Fraction]:
    from flint import fmpz_poly

    fr = [Fraction(int(c.p), int(c.q)) for c in (sp.Rational(c) for c in a.mask)]
    den = lcm(*[f.denominator for f in fr])
    ints = [int(f * den) for f in fr]
    prod = fmpz_poly(ints)
    for j in range(1, L):
        step = m ** j
        spaced = [0] * ((len(ints) - 1) * step + 1)
        spaced[::step] = ints
        prod = prod * fmpz_poly(spaced)
    start = a.start * (m ** L - 1) // (m - 1)
    coeffs = [int(c) for c in prod.coeffs()]
    mod = m ** L
    sums = [sum(abs(c) for c in coeffs[(r - start) % mod::mod]) for r in range(mod)]
    return [Fraction(s, den ** L) for s in sums]


def residue_sums_mary(a: LaurentSymbol, L: int, m: int) -> list[sp.Expr]:
    """Exact ``sum_j |c_{r + m^L j}|`` for every residue ``r`` mod ``m^L``, ``c`` the symbol of ``S_a^L``."""
    m = check_arity(m)
    a.require_numeric("an exact norm")
    if a.domain.is_QQ or a.domain.is_ZZ:
        return [sp.Rational(s.numerator, s.denominator) for s in _rational_residue_sums(a, L, m)]
    prod = iterated_symbol_mary(a, L, m)
    mod = m ** L
    sums = [sp.Integer(0)] * mod
    for i, c in prod.items():
        s = sign(c)
        if s:
            sums[i % mod] += s * c
    return [sp.radsimp(sp.expand(s)) for s in sums]


def scheme_norm_mary(a: LaurentSymbol, L: int, m: int, *, scale=1) -> Result:
    """``||(scale S_a)^L||_inf`` exactly (certified) for arity ``m``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> scheme_norm_mary(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 1, 3).value
    1
    """
    m = check_arity(m)
    if not isinstance(L, int) or L < 1:
        raise AnalysisError(f"L must be a positive integer, not {L!r}")
    scale = as_expr(scale)
    sums = [sp.expand(scale ** L * s) for s in residue_sums_mary(a, L, m)]
    best, arg = sums[0], 0
    for i, v in enumerate(sums[1:], start=1):
        if sign(v - best) > 0:
            best, arg = v, i
    return Result(value=sp.radsimp(best), status=CERTIFIED,
                  witness={"L": L, "residue_sums": sums if L <= 4 else None, "argmax_residue": arg},
                  provenance={"method": f"exact residue sums mod {m}^L of a(z)a(z^{m})...a(z^({m}^(L-1)))",
                              "arity": m, "domain": str(a.domain)})


def difference_norm_mary(a: LaurentSymbol, k: int, m: int, L: int = 1, *, spelling: str = "paper") -> Result:
    """``||(1/m S_{a_k})^L||_inf`` exactly; ``witness["contractive"]`` (norm < 1) proves ``C^{k-1}``
    (m-ary Dyn–Levin test). A norm >= 1 proves nothing."""
    a.require_numeric("an exact norm (use norm_solution_set(..., arity=m) for a parameter range)")
    ak = difference_symbol_mary(a, k, m, spelling=spelling)
    r = scheme_norm_mary(ak, L, m, scale=sp.Rational(1, m))
    contractive = sign(r.value - 1) < 0
    return Result(value=r.value, status=CERTIFIED,
                  witness={**r.witness, "m": k, "arity": m, "difference_symbol": ak, "spelling": spelling,
                           "contractive": contractive,
                           "implies": f"C^{k - 1} (Dyn-Levin)" if contractive else "nothing (norm >= 1)"},
                  provenance=r.provenance)


# --------------------------------------------------------------------------------------------
# transition matrices, local subdivision matrices, support
# --------------------------------------------------------------------------------------------

def transition_matrices_mary(c: LaurentSymbol, m: int, *, numeric: bool = False) -> tuple:
    """The ``m`` Daubechies–Lagarias matrices ``(T_eps)_{ij} = c_{m i - j + eps}`` (module docstring).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> [T.tolist() for T in transition_matrices_mary(LaurentSymbol.from_mask([1, 2, 3]), 3)]
    [[[1]], [[2]], [[3]]]
    """
    m = check_arity(m)
    if not isinstance(c, LaurentSymbol) or c.is_zero:
        raise AnalysisError("transition matrices need a nonzero LaurentSymbol")
    mask = c.mask
    N = len(mask) - 1
    n = max(-(-N // (m - 1)), 1)

    def entry(k: int):
        return mask[k] if 0 <= k <= N else sp.Integer(0)

    mats = tuple(sp.Matrix(n, n, lambda i, j, e=e: entry(m * i - j + e)) for e in range(m))
    if not numeric:
        return mats
    c.require_numeric("float transition matrices")
    return tuple(np.array(M.evalf(30).tolist(), dtype=float) for M in mats)


def invariant_window_mary(a: LaurentSymbol, m: int) -> tuple[int, int]:
    """The smallest window ``(l, r)`` invariant for every mask with support ``[s, e]``:
    ``l = ceil((m - e)/(m-1)) - 1``, ``r = floor((-s - m)/(m-1)) + 1`` (``(1-e, -s-1)`` for ``m = 2``).

    Derivation: ``f^{n+1}_i`` uses ``f^n_j`` for ``(i - e)/m <= j <= (i - s)/m``; ``[l, r]`` is invariant iff
    ``ceil((l - e)/m) >= l`` and ``floor((r - s)/m) <= r``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> invariant_window_mary(LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)"), 3)
    (-1, 1)
    """
    m = check_arity(m)
    s, e = a.start, a.end
    l = -((e - m) // (m - 1)) - 1
    r = (-s - m) // (m - 1) + 1
    return (min(l, r), max(l, r))   # l > r only for masks with fewer than m + 1 coefficients


def local_subdivision_matrix_mary(a: LaurentSymbol, m: int, window: Sequence[int] | None = None):
    """``(M, (l, r))`` with ``M[i-l, j-l] = a_{i - m j}`` on the invariant window."""
    m = check_arity(m)
    l, r = invariant_window_mary(a, m) if window is None else (int(window[0]), int(window[1]))
    for i in range(l, r + 1):
        for j in range(-((a.end - i) // m) - 1, (i - a.start) // m + 2):
            if (j < l or j > r) and a.coeff(i - m * j) != 0:
                raise AnalysisError(f"window ({l}, {r}) is not invariant under the {m}-ary scheme")
    n = r - l + 1
    return sp.Matrix(n, n, lambda p, q: a.coeff((l + p) - m * (l + q))), (l, r)


def local_eigenvalues_mary(a: LaurentSymbol, m: int, window: Sequence[int] | None = None) -> Result:
    """Exact eigenvalues ``{lambda: multiplicity}`` of the m-ary local subdivision matrix
    (necessary for ``C^k``: ``1, 1/m, ..., 1/m^k`` dominant).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> local_eigenvalues_mary(LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)"), 3).value
    {1: 1, 1/3: 1, 1/9: 1}
    """
    from .transition import _sort_key

    M, win = local_subdivision_matrix_mary(a, m, window)
    lam = sp.Symbol("lambda")
    cp = sp.factor(M.charpoly(lam).as_expr())
    eig = sp.roots(sp.Poly(cp, lam)) if not a.params else M.eigenvals()
    complete = sum(eig.values()) == M.shape[0]
    value = dict(sorted(((sp.simplify(k), v) for k, v in eig.items()), key=lambda kv: _sort_key(kv[0])))
    return Result(value=value, status=CERTIFIED,
                  witness={"charpoly": cp, "window": win, "matrix": M},
                  provenance={"method": "exact characteristic polynomial of the local subdivision matrix",
                              "arity": m, "complete": complete})


def basic_limit_support_mary(a: LaurentSymbol, m: int) -> Result:
    """The support ``[s/(m-1), e/(m-1)]`` of the basic limit function (mask support ``[s, e]``):
    after ``n`` steps the nonzero values of ``S^n delta`` sit at indices ``(m^n - 1)/(m-1) [s, e]``, i.e.
    at parameters ``(1 - m^-n) [s, e]/(m-1)``."""
    m = check_arity(m)
    s, e = a.start, a.end
    lo, hi = sp.Rational(s, m - 1), sp.Rational(e, m - 1)
    c = (lo + hi) / 2
    return Result(value=(lo, hi), status=CERTIFIED,
                  witness={"width": hi - lo, "centre": c, "centred": (lo - c, hi - c),
                           "end_coefficients": (a.coeff(s), a.coeff(e))},
                  provenance={"method": "mask support / (m - 1)", "arity": m})


# --------------------------------------------------------------------------------------------
# refinement of polygons
# --------------------------------------------------------------------------------------------

def _convert(c, exact: bool):
    return sp.Rational(c) if exact else float(c)


def refine_mary(a: LaurentSymbol, points, m: int, steps: int = 1, *, closed: bool = True,
                exact: bool = False, end_rule: str = "interior") -> np.ndarray:
    """``steps`` rounds of ``f_i <- sum_j a_{i-mj} f_j`` on a polygon (rows = points, any dimension).

    Closed polygons are periodic (``n`` points -> ``m n`` points per round, new point ``i`` attached to
    index ``i`` of the refined periodic sequence). Open polygons (issue 12, second round: both end rules of
    :func:`analysis.stationary.refinement.refine`, with dilation ``m``):

    * ``end_rule="interior"`` keeps only the new points that depend on old points alone:
      ``f^{n+1}_i`` for ``e - m + 1 <= i <= m n + s - 1`` (``[s, e]`` the support of the mask);
    * ``end_rule="extrapolate"`` extends the data by ghost points reflected through the end points,
      ``P_{-k} = 2 P_0 - P_k`` and ``P_{n-1+k} = 2 P_{n-1} - P_{n-1-k}``
      (:func:`analysis.stationary.refinement.point_reflection`), and keeps the new points whose stencil centre
      lies in the data's index range: with ``c = (s + e)/2``, new point ``i`` is centred at old index
      ``(i - c)/m`` (data at ``x_j = (j + p) h``, new points at ``(i + p) h/m``, ``p = c/(m-1)``: the
      parametrisation in which the symmetric mask is centred), so ``i = ceil(c) .. m (n-1) + floor(c)``. For
      ``m = 2`` these are the binary ranges; primal schemes (``c = 0``) map ``n`` points to ``m (n-1) + 1``
      and keep the end points when ``sum_j a_{mj} = 1`` and the mask is symmetric (reflected data are
      odd-symmetric about them), so linear data stay linear.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> tri = LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)")          # ternary linear B-spline
    >>> refine_mary(tri, [[0.0], [3.0]], 3, closed=False).ravel().tolist()
    [0.0, 1.0, 2.0, 3.0]
    >>> q = LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)")            # ternary quadratic B-spline
    >>> refine_mary(q, [[0], [9], [18]], 3, closed=False, exact=True, end_rule="extrapolate").ravel().tolist()
    [0, 3, 6, 9, 12, 15, 18]
    """
    m = check_arity(m)
    a.require_numeric("refinement")
    if not isinstance(steps, int) or steps < 0:
        raise AnalysisError(f"steps must be a non-negative integer, not {steps!r}")
    if end_rule not in ("interior", "extrapolate"):
        raise AnalysisError(f"unknown end_rule {end_rule!r}; use 'interior' or 'extrapolate'")
    data = np.array(points, dtype=object if exact else float)
    if data.ndim == 1:
        data = data[:, None]
    if exact:
        data = np.vectorize(lambda x: sp.Rational(x))(data).astype(object)
    coeffs = {i: _convert(c, exact) for i, c in a.items()}
    s, e = a.start, a.end
    for _ in range(steps):
        n = data.shape[0]
        if n == 0:
            raise AnalysisError("the polygon has no points")
        if closed:
            lo, hi, src, off = 0, m * n - 1, None, 0
        elif end_rule == "interior":
            lo, hi, src, off = e - m + 1, m * n + s - 1, data, 0
            if hi < lo:
                raise AnalysisError(f"an open polygon of {n} points is too short for a mask of support "
                                    f"[{s}, {e}] (no new point depends on old points only); use more points, "
                                    "fewer steps or --end-rule extrapolate")
        else:
            src, off, lo, hi = _extrapolated(data, s, e, m, n)
        out = np.zeros((hi - lo + 1, data.shape[1]), dtype=data.dtype)
        if exact:
            out[:] = sp.Integer(0)
        for i in range(lo, hi + 1):
            for j in range(-((e - i) // m), (i - s) // m + 1):
                x = data[j % n] if src is None else src[j + off]
                out[i - lo] = out[i - lo] + coeffs.get(i - m * j, 0) * x
        data = out
    return data


def _extrapolated(data: np.ndarray, s: int, e: int, m: int, n: int):
    """``(extended data, index offset, first kept i, last kept i)`` of the ``"extrapolate"`` end rule."""
    from .refinement import point_reflection

    lo = -((-(s + e)) // 2)                      # ceil(c), c = (s + e)/2
    hi = m * (n - 1) + (s + e) // 2              # m(n-1) + floor(c)
    if hi < lo:
        raise AnalysisError(f"an open polygon of {n} point(s) keeps no new point; give at least 2 points")
    jmin, jmax = -((e - lo) // m), (hi - s) // m
    left, right = max(0, -jmin), max(0, jmax - (n - 1))
    parts = []
    if left:
        parts.append(point_reflection(data, "left", left))
    parts.append(data)
    if right:
        parts.append(point_reflection(data, "right", right))
    return np.concatenate(parts, axis=0), left, lo, hi
