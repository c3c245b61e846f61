"""Transition matrices, local subdivision matrices, their eigenvalues, and the support of the
basic limit function, for any arity ``m`` (the keyword ``arity``, default 2).

Convention (as everywhere in :mod:`analysis`)::

    (S_a f)_i = sum_j a_{i-mj} f_j,        a(z) = sum_i a_i z^i.

The formulas below are written for ``m = 2``; for arity ``m`` read ``2`` as ``m``, the two transition
matrices as ``T_0..T_{m-1}`` of size ``max(ceil(N/(m-1)), 1)``, ``(1+z)`` as ``q_m = 1 + ... + z^{m-1}``
and the support of the basic limit function as the mask support divided by ``m - 1``.

The basic limit function ``phi = lim S_a^n delta`` is then refinable with the *same* mask,
``phi(x) = sum_k a_k phi(2x - k)``, and the two objects of this module are:

* the **transition matrices** ``T_0, T_1`` of a mask ``c`` (Daubechies–Lagarias), whose joint
  spectral radius is the contraction rate ``rho(c) = lim_L ||S_c^L||_inf^(1/L)``; with
  ``c(z) = 2^k a(z) / (1+z)^(k+1)`` it gives the Hölder exponent ``alpha = k - log2 rho(c)``;
* the **local subdivision matrix** of ``a``: the square block of ``S_a`` on the smallest
  window of control points ``f_l..f_r`` that is mapped into itself; its eigenvalues are the
  classical necessary conditions for smoothness (``1, 1/2, 1/4, ...``).

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> a = LaurentSymbol.from_mask(["1/8", "1/2", "3/4", "1/2", "1/8"], start=-2)   # cubic B-spline
>>> M, window = local_subdivision_matrix(a)
>>> window
(-1, 1)
>>> M
Matrix([
[1/2, 1/2,   0],
[1/8, 3/4, 1/8],
[  0, 1/2, 1/2]])
>>> local_eigenvalues(a).value
{1: 1, 1/2: 1, 1/4: 1}
>>> basic_limit_support(a).value
(-2, 2)

References
----------
I. Daubechies, J. C. Lagarias, *Two-scale difference equations II. Local regularity, infinite
products of matrices and fractals*, SIAM J. Math. Anal. 23 (1992) 1031-1079.
O. Rioul, *Simple regularity criteria for subdivision schemes*, SIAM J. Math. Anal. 23 (1992)
1544-1576.
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numerica 11 (2002) 73-144
(local subdivision matrices and their eigenvalues, Section 4).
A. S. Cavaretta, W. Dahmen, C. A. Micchelli, *Stationary subdivision*, Mem. AMS 453 (1991)
(support of the basic limit function).
"""

from __future__ import annotations

from typing import Any, Sequence

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from ..algebra.factorization import arity_key, check_arity
from ..result import CERTIFIED, AnalysisError, Result
from ..algebra.symbol import LaurentSymbol

__all__ = ["LAMBDA", "transition_matrices", "invariant_window", "is_invariant_window",
           "local_subdivision_matrix", "local_eigenvalues", "basic_limit_support"]

#: The variable of characteristic polynomials.
LAMBDA = sp.Symbol("lambda")


# --------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------

def _check_symbol(a: Any, what: str) -> LaurentSymbol:
    if not isinstance(a, LaurentSymbol):
        raise AnalysisError(f"{what} needs a LaurentSymbol, not {type(a).__name__}")
    if a.is_zero:
        raise AnalysisError(f"{what} needs a nonzero mask")
    return a


def _domain_coefficients(a: LaurentSymbol) -> list:
    """``[a_start, ..., a_end]`` as elements of ``a.domain`` (no conversion to expressions)."""
    return list(reversed(a.poly.rep.to_list()))


def _to_float(x: sp.Expr) -> float:
    value = complex(sp.N(x, 30))
    if value.imag != 0:
        raise AnalysisError(f"coefficient {sp.sstr(x)} is not real")
    return value.real


# --------------------------------------------------------------------------------------------
# 1. transition matrices
# --------------------------------------------------------------------------------------------

def transition_matrices(c: LaurentSymbol, *, numeric: bool = False, arity: int = 2):
    """The Daubechies–Lagarias transition matrices ``(T_0, T_1)`` of the mask ``c`` (``T_0..T_{m-1}``
    for arity ``m``: ``(T_eps)_{ij} = c_{m i - j + eps}``, ``i, j < max(ceil(N/(m-1)), 1)``; ``phi`` has
    support ``[0, N/(m-1)]`` and ``v((x+eps)/m) = T_eps v(x)``).

    Convention: shift ``c`` so that its support is ``[0, N]`` (``c_0 != 0 != c_N``; the shift
    changes nothing below), then for ``eps in {0, 1}``::

        (T_eps)_{i,j} = c_{2i - j + eps},      i, j = 0, ..., N-1     (size max(N, 1)).

    These are the matrices of the refinement equation ``phi(x) = sum_k c_k phi(2x - k)``
    (the refinable function of ``S_c`` in our convention ``(S_c f)_i = sum_j c_{i-2j} f_j``):
    with ``v(x) = (phi(x), phi(x+1), ..., phi(x+N-1))`` for ``x in [0, 1]``,
    ``v((x + eps)/2) = T_eps v(x)``. Products encode the L-step mask: with
    ``c^[L](z) = c(z) c(z^2) ... c(z^(2^(L-1)))`` (support ``[0, (2^L - 1) N]``),

        ``(T_{e_1} T_{e_2} ... T_{e_L})_{i,j} = c^[L]_{2^L i - j + d}``,  ``d = sum_m e_m 2^(L-m)``,

    so every *column* of a product holds coefficients of one residue class mod ``2^L``, and
    column 0 of ``T_w``, ``w`` the binary digits of ``r``, is the whole class ``r``. Hence
    ``||S_c^L||_inf = max_{|w| = L} ||T_w||_1`` (max column sum), ``rho(T_eps)^L <= ||S_c^L||_inf``,
    and the joint spectral radius of ``{T_0, T_1}`` is ``rho(c) = lim_L ||S_c^L||_inf^(1/L)``. For the Hölder exponent of a
    scheme ``a`` with ``(1+z)^(k+1) | a(z)`` use ``c(z) = 2^k a(z)/(1+z)^(k+1)``:
    ``alpha = k - log2 JSR(T_0, T_1)`` (see ``DESIGN.md``). Note ``c`` is *not* normalised
    like a subdivision mask (``c(1) = 1`` for a convergent ``a``).

    Entries are exact sympy expressions (in the parameters if ``c`` has any). With
    ``numeric=True`` the matrices are ``numpy.float64`` arrays (``c`` must be numeric).

    Examples
    --------
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> T0, T1 = transition_matrices(LaurentSymbol.from_mask([1]))     # c = 1: B-splines
    >>> T0, T1
    (Matrix([[1]]), Matrix([[0]]))

    The 4-point scheme ``a = (-1, 0, 9, 16, 9, 0, -1)/16``: ``a = (1+z)^4 (-1 + 4z - z^2)/(16 z^3)``,
    so with ``k = 3``, ``c = (-1 + 4z - z^2)/2``:

    >>> c = LaurentSymbol.from_mask(["-1/2", 2, "-1/2"], start=-3)
    >>> T0, T1 = transition_matrices(c)
    >>> T0
    Matrix([
    [-1/2, 0],
    [-1/2, 2]])
    >>> T1
    Matrix([
    [2, -1/2],
    [0, -1/2]])
    >>> transition_matrices(c, numeric=True)[1]
    array([[ 2. , -0.5],
           [ 0. , -0.5]])
    >>> [T.tolist() for T in transition_matrices(LaurentSymbol.from_mask([1, 2, 3]), arity=3)]
    [[[1]], [[2]], [[3]]]

    Algorithm
    ---------
    Direct indexing of the mask; no arithmetic.

    References
    ----------
    I. Daubechies, J. C. Lagarias, SIAM J. Math. Anal. 23 (1992) 1031-1079, Section 2;
    O. Rioul, SIAM J. Math. Anal. 23 (1992) 1544-1576.
    """
    m = check_arity(arity)
    c = _check_symbol(c, "transition_matrices")
    mask = c.mask                      # c_0 .. c_N after the shift by -c.start
    n_coeff = len(mask)
    N = n_coeff - 1
    size = max(-(-N // (m - 1)), 1)

    def entry(k: int) -> sp.Expr:
        return mask[k] if 0 <= k < n_coeff else sp.Integer(0)

    mats = tuple(sp.Matrix(size, size, lambda i, j, eps=eps: entry(m * i - j + eps)) for eps in range(m))
    if not numeric:
        return mats
    c.require_numeric("float transition matrices")
    import numpy as np

    return tuple(np.array([[_to_float(x) for x in m.row(i)] for i in range(size)], dtype=float)
                 for m in mats)


# --------------------------------------------------------------------------------------------
# 2. local subdivision matrix
# --------------------------------------------------------------------------------------------

def is_invariant_window(a: LaurentSymbol, window: tuple[int, int], *, arity: int = 2) -> bool:
    """Whether every new point ``f_i``, ``l <= i <= r``, depends only on old ``f_l..f_r``.

    A coefficient counts as present when it is not identically zero (generic parameters).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)    # Chaikin
    >>> is_invariant_window(a, (0, 1)), is_invariant_window(a, (0, 0))
    (True, False)
    """
    l, r = window
    s, e = a.start, a.end
    m = arity
    for i in range(l, r + 1):
        # j with s <= i - mj <= e
        for j in range(-((e - i) // m), (i - s) // m + 1):
            if (j < l or j > r) and a.coeff(i - m * j) != 0:
                return False
    return True


def invariant_window(a: LaurentSymbol, *, arity: int = 2) -> tuple[int, int]:
    """The smallest invariant window ``(l, r)`` of ``S_a``: ``(1 - e, -s - 1)`` for support ``[s, e]``.

    Derivation: ``f^{n+1}_i`` uses ``f^n_j`` for ``(i - e)/2 <= j <= (i - s)/2``. The window
    ``[l, r]`` is invariant iff ``ceil((l - e)/2) >= l`` and ``floor((r - s)/2) <= r``, i.e. iff
    ``l <= 1 - e`` and ``r >= -s - 1`` (when the end coefficients ``a_s, a_e`` are nonzero). So
    the windows invariant for *every* mask with support ``[s, e]`` are exactly those containing
    ``[1 - e, -s - 1]``, which has ``e - s - 1`` points. Equivalently, ``1 - e <= j <= -s - 1``
    are exactly the control points whose basic function ``phi(x - j)`` (support
    ``[j + s, j + e]``) is nonzero near ``x = 0``: the window determines the limit on a
    neighbourhood of 0, which is what makes its eigenvalues meaningful.

    Masks with zero coefficients inside the support can have smaller invariant windows that do
    *not* determine the limit near 0: for interpolatory schemes (``a_{2j} = delta_j``) the single
    point ``(0, 0)`` is invariant (see :func:`is_invariant_window`). Such windows are not
    returned here. For masks with fewer than three coefficients (``e - s <= 1``) the interval
    above is empty and the 1-point window ``(-s, -s)`` is returned.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> invariant_window(LaurentSymbol.from_mask([1, 2, 1], start=-1))
    (0, 0)

    Arity ``m``: ``l = ceil((m - e)/(m-1)) - 1``, ``r = floor((-s - m)/(m-1)) + 1`` (the same derivation
    with ``(i - e)/m <= j <= (i - s)/m``; ``l > r`` only for masks with fewer than ``m + 1`` coefficients,
    then the two are swapped).

    >>> invariant_window(LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)"), arity=3)
    (-1, 1)
    """
    m = check_arity(arity)
    a = _check_symbol(a, "invariant_window")
    s, e = a.start, a.end
    if m != 2:
        l, r = -((e - m) // (m - 1)) - 1, (-s - m) // (m - 1) + 1
        return (min(l, r), max(l, r))
    if e - s >= 2:
        return (1 - e, -s - 1)
    return (-s, -s)


def _local_domain_matrix(a: LaurentSymbol, window: tuple[int, int], m: int = 2) -> DomainMatrix:
    l, r = window
    coeffs = _domain_coefficients(a)
    K = a.domain
    s = a.start

    def entry(k: int):
        k -= s
        return coeffs[k] if 0 <= k < len(coeffs) else K.zero

    n = r - l + 1
    rows = [[entry(i - m * j) for j in range(l, r + 1)] for i in range(l, r + 1)]
    return DomainMatrix(rows, (n, n), K)


def _resolve_window(a: LaurentSymbol, window: Sequence[int] | None, m: int = 2) -> tuple[int, int]:
    if window is None:
        return invariant_window(a, arity=m)
    try:
        l, r = (int(window[0]), int(window[1]))
    except (TypeError, ValueError, IndexError):
        raise AnalysisError(f"a window is a pair of integers (l, r), not {window!r}") from None
    if l > r:
        raise AnalysisError(f"empty window ({l}, {r})")
    if not is_invariant_window(a, (l, r), arity=m):
        lo, hi = invariant_window(a, arity=m)
        raise AnalysisError(f"window ({l}, {r}) is not invariant under the scheme; "
                            f"it must contain ({lo}, {hi})")
    return (l, r)


def local_subdivision_matrix(a: LaurentSymbol, window: Sequence[int] | None = None, *, arity: int = 2
                             ) -> tuple[sp.Matrix, tuple[int, int]]:
    """The local subdivision matrix of ``a`` and its window ``(l, r)``.

    ``M[i - l, j - l] = a_{i - mj}`` (``m`` the arity) for ``l <= i, j <= r``, so that
    ``(f^{n+1}_l, ..., f^{n+1}_r) = M (f^n_l, ..., f^n_r)``. By default the window is the
    smallest invariant one, ``(1 - e, -s - 1)`` for mask support ``[s, e]``
    (:func:`invariant_window`). A larger invariant window can be given explicitly (papers often
    use one); eigenvalues of a larger window are those of the minimal one plus extra ones.

    Entries are exact (sympy expressions, in the parameters if any).

    Examples
    --------
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)    # Chaikin
    >>> local_subdivision_matrix(a)
    (Matrix([
    [3/4, 1/4],
    [1/4, 3/4]]), (0, 1))

    Algorithm
    ---------
    Index the mask; the window is checked for invariance when given.

    References
    ----------
    N. Dyn, D. Levin, Acta Numerica 11 (2002), Section 4.
    """
    m = check_arity(arity)
    a = _check_symbol(a, "local_subdivision_matrix")
    win = _resolve_window(a, window, m)
    l, r = win
    n = r - l + 1
    return sp.Matrix(n, n, lambda p, q: a.coeff((l + p) - m * (l + q))), win


# --------------------------------------------------------------------------------------------
# 3. eigenvalues
# --------------------------------------------------------------------------------------------

def _sort_key(lam: sp.Expr):
    if lam.free_symbols:
        return (1,)                          # stable sort: keep the order of the factors
    v = complex(sp.N(lam, 30))
    return (0, -abs(v), -v.real, sp.default_sort_key(lam))


def _roots_of_factor(f: sp.Poly, K, parametric: bool) -> list[sp.Expr] | None:
    """Exact roots of an irreducible factor ``f`` (a Poly in LAMBDA over ``K``), or None."""
    coeffs = f.rep.to_list()                 # domain elements, leading first
    d = f.degree()
    if d == 1:
        root = sp.cancel(-K.to_sympy(coeffs[1]) / K.to_sympy(coeffs[0]))
        return [sp.expand(root) if sp.denom(root).is_number else root]
    if d == 2:
        A, B, C = (K.to_sympy(x) for x in coeffs)
        centre = sp.cancel(-B / (2 * A))
        if sp.denom(centre).is_number:
            centre = sp.expand(centre)
        disc = sp.factor(sp.expand(B**2 - 4 * A * C))
        content, prim = disc.as_content_primitive()
        root = sp.sqrt(content) * sp.sqrt(prim) / (2 * A)
        if parametric:
            return [centre + root, centre - root]
        return [sp.radsimp(centre + root), sp.radsimp(centre - root)]
    if not parametric and K.is_QQ:
        return list(f.all_roots())           # CRootOf: exact, indexed real roots first
    if not parametric:
        found = sp.roots(f.as_expr(), LAMBDA)
        if sum(found.values()) == d:
            return [r for r, m in found.items() for _ in range(m)]
    return None


#: the factorizations of characteristic polynomials already computed (a Poly and its factors are immutable;
#: keyed on the polynomial with its domain, so the same one is factored once per process)
_FACTORED: dict = {}


def _factor_list(P: sp.Poly):
    """``P.factor_list()``, remembered (bounded) for the polynomial ``P`` over its domain: the claims of a
    paper ask for the eigenvalues of the same local subdivision matrix again and again, and factoring a
    parametric characteristic polynomial (Wang's algorithm over ``QQ[params]``) is the costly step."""
    key = (P, P.domain)
    if key not in _FACTORED:
        if len(_FACTORED) >= 64:
            _FACTORED.clear()
        lc, factors = P.factor_list()
        _FACTORED[key] = (lc, tuple(factors))
    lc, factors = _FACTORED[key]
    return lc, list(factors)


def local_eigenvalues(a: LaurentSymbol, window: Sequence[int] | None = None, *, arity: int = 2) -> Result:
    """The exact eigenvalues, with multiplicities, of the local subdivision matrix of ``a``.

    ``value`` is a dict ``{eigenvalue: multiplicity}`` (numeric eigenvalues by decreasing
    modulus, then parametric ones). With parameters the eigenvalues are expressions in them,
    valid for generic values: at special values distinct eigenvalues may coincide, which the
    characteristic polynomial in the witness (valid for *all* values) shows.

    The witness holds ``charpoly`` (``det(lambda I - M)``, factored), ``factors`` (irreducible
    factors over the coefficient field ``K(params)`` with multiplicities), ``window`` and
    ``matrix``. Irreducible factors of degree >= 3 with parameters (no safe closed form) are
    listed in ``witness["implicit"]`` and left out of ``value``; ``provenance["complete"]``
    then is False.

    Examples
    --------
    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> w = sp.Symbol("omega")
    >>> a = LaurentSymbol.from_mask([-w, 0, w + sp.Rational(1, 2), 1, w + sp.Rational(1, 2), 0, -w],
    ...                             start=-3)                                # 4-point scheme
    >>> r = local_eigenvalues(a)
    >>> r.value
    {1: 1, 1/2: 1, 2*omega: 1, sqrt(1 - 16*omega)/4 + 1/4: 1, 1/4 - sqrt(1 - 16*omega)/4: 1}
    >>> r.status, r.witness["window"]
    ('certified', (-2, 2))
    >>> r.witness["charpoly"]
    (lambda - 1)*(lambda - 2*omega)*(2*lambda - 1)*(2*lambda**2 - lambda + 2*omega)/4
    >>> local_eigenvalues(a.subs({"omega": "1/16"})).value
    {1: 1, 1/2: 1, 1/4: 2, 1/8: 1}

    Algorithm
    ---------
    The matrix is built as a ``DomainMatrix`` over the symbol's own domain (``QQ``,
    ``QQ<sqrt(6)>``, ``QQ[omega]``, ``QQ(omega)``, ...); its characteristic polynomial comes
    from the division-free Berkowitz algorithm (``DomainMatrix.charpoly``) and is factored over
    that domain (for parameters: over ``QQ[params]``, equivalently ``QQ(params)`` by Gauss'
    lemma). Linear and quadratic factors are solved in closed form; numeric factors of higher
    degree give ``CRootOf`` roots over ``QQ`` (exact).

    Arity ``m > 2`` (necessary for ``C^k``: ``1, 1/m, ..., 1/m^k`` dominant): sympy's characteristic
    polynomial of the explicit matrix, factored, and its roots (``witness``: ``charpoly``, ``window``,
    ``matrix``). This older route is kept for ``m > 2`` because the m-ary reports and goldens record its
    factored form; both are exact.

    >>> local_eigenvalues(LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)"), arity=3).value
    {1: 1, 1/3: 1, 1/9: 1}

    References
    ----------
    N. Dyn, D. Levin, Acta Numerica 11 (2002), Section 4; S. J. Berkowitz, Inform. Process. Lett.
    18 (1984) 147-150.
    """
    m = check_arity(arity)
    a = _check_symbol(a, "local_eigenvalues")
    win = _resolve_window(a, window, m)
    if m != 2:
        Ms = local_subdivision_matrix(a, win, arity=m)[0]
        cp = sp.factor(Ms.charpoly(LAMBDA).as_expr())
        eig = sp.roots(sp.Poly(cp, LAMBDA)) if not a.params else Ms.eigenvals()
        complete = sum(eig.values()) == Ms.shape[0]
        value = dict(sorted(((sp.simplify(k), v) for k, v in eig.items()), key=lambda kv: _sort_key(kv[0])))
        return Result(value=value, status=CERTIFIED, witness={"charpoly": cp, "window": win, "matrix": Ms},
                      provenance={"method": "exact characteristic polynomial of the local subdivision matrix",
                                  "arity": m, "complete": complete})
    M = _local_domain_matrix(a, win)
    K = a.domain
    parametric = not a.is_numeric
    cp = M.charpoly()
    P = sp.Poly.from_list(cp, LAMBDA, domain=K)
    lc, factors = _factor_list(P)
    eigen: dict[sp.Expr, int] = {}
    implicit: list[tuple[sp.Expr, int]] = []
    for f, m in factors:
        roots = _roots_of_factor(f, K, parametric)
        if roots is None:
            implicit.append((f.as_expr(), m))
            continue
        for lam in roots:
            eigen[lam] = eigen.get(lam, 0) + m
    value = dict(sorted(eigen.items(), key=lambda kv: _sort_key(kv[0])))
    charpoly = sp.Mul(lc, *[f.as_expr() ** m for f, m in factors], evaluate=True)
    witness = {
        "charpoly": charpoly,
        "factors": tuple((f.as_expr(), m) for f, m in factors),
        "window": win,
        "matrix": M.to_Matrix(),
    }
    if implicit:
        witness["implicit"] = tuple(implicit)
    provenance = {
        "method": "local subdivision matrix; DomainMatrix.charpoly (Berkowitz), factored over the "
                  "coefficient domain",
        "domain": str(K),
        "parameters": tuple(p.name for p in a.params),
        "arithmetic": "exact",
        "complete": not implicit,
    }
    return Result(value=value, status=CERTIFIED, witness=witness, provenance=provenance)


# --------------------------------------------------------------------------------------------
# 4. support of the basic limit function
# --------------------------------------------------------------------------------------------

def _real_roots(expr: sp.Expr, p: sp.Symbol) -> list[sp.Expr]:
    num = sp.numer(sp.together(expr))
    poly = sp.Poly(num, p)
    if poly.degree() <= 0:
        return []
    try:
        if poly.domain.is_QQ or poly.domain.is_ZZ:
            return sorted(set(poly.real_roots()), key=lambda x: sp.N(x, 30))
    except (sp.PolynomialError, NotImplementedError):   # pragma: no cover
        pass
    found = sp.roots(poly)
    return sorted({r for r in found if r.is_real}, key=lambda x: sp.N(x, 30))


def basic_limit_support(a: LaurentSymbol, *, arity: int = 2) -> Result:
    """The support ``[s, e]`` of the basic limit function of ``a`` (``value = (s, e)``); for arity ``m``
    ``[s/(m-1), e/(m-1)]`` (after ``n`` steps the nonzero values of ``S^n delta`` sit at indices
    ``(m^n - 1)/(m-1) [s, e]``).

    In our convention the basic limit function ``phi = lim S_a^n delta`` satisfies
    ``phi = sum_k a_k phi(2 . - k)``, and its support (convex hull) is the mask support
    ``[s, e] = [a.start, a.end]``: after n steps the nonzero values sit at indices
    ``(2^n - 1) s .. (2^n - 1) e``, i.e. at parameters ``(1 - 2^-n) [s, e]``. The width is
    ``e - s`` (the number of mask coefficients minus one).

    Centred parametrisations: papers usually place the symmetry centre of a symmetric mask,
    ``m = (s + e)/2``, at 0; their interval is ours shifted by ``-m``, i.e.
    ``[-(e - s)/2, (e - s)/2]`` (witness ``centred``). A 12-coefficient mask with ``s = -6``
    has ``[-6, 5]`` here, centre ``-1/2``, and ``[-11/2, 11/2]`` centred.

    With parameters the support is the generic one (end coefficients not identically zero);
    ``witness["exceptional"]`` maps each real parameter value where ``a_s`` or ``a_e`` vanishes
    to the support there (one parameter; exact roots of the numerators), and
    ``witness["conditions"]`` states the vanishing conditions as equations (any number of
    parameters).

    Examples
    --------
    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> w = sp.Symbol("omega")
    >>> a = LaurentSymbol.from_mask([-w, 0, w + sp.Rational(1, 2), 1, w + sp.Rational(1, 2), 0, -w],
    ...                             start=-3)                                # 4-point scheme
    >>> r = basic_limit_support(a)
    >>> r.value, r.witness["width"], r.witness["centred"]
    ((-3, 3), 6, (-3, 3))
    >>> r.witness["exceptional"]
    {0: (-1, 1)}

    Algorithm
    ---------
    Read off the end exponents; for one parameter solve ``numer(a_s) = 0`` and
    ``numer(a_e) = 0`` exactly (real roots) and recompute the support of the substituted mask.

    References
    ----------
    A. S. Cavaretta, W. Dahmen, C. A. Micchelli, Mem. AMS 453 (1991), Chapter 2;
    N. Dyn, D. Levin, Acta Numerica 11 (2002), Section 2.
    """
    m = check_arity(arity)
    a = _check_symbol(a, "basic_limit_support")
    s, e = a.start, a.end
    left, right = a.coeff(s), a.coeff(e)
    if m != 2:                         # the generic support only (the exceptional values are binary-only)
        lo, hi = sp.Rational(s, m - 1), sp.Rational(e, m - 1)
        c = (lo + hi) / 2
        return Result(value=(lo, hi), status=CERTIFIED,
                      witness={"width": hi - lo, "centre": c, "centred": (lo - c, hi - c), "end_coefficients": (left, right)},
                      provenance={"method": "mask support / (m - 1)", "arity": m})
    width = e - s
    centre = sp.Rational(s + e, 2)
    witness: dict[str, Any] = {
        "width": width,
        "centre": centre,
        "centred": (s - centre, e - centre),
        "end_coefficients": (left, right),
    }
    if a.params:
        witness["conditions"] = {"left": sp.Eq(left, 0), "right": sp.Eq(right, 0)}
        if len(a.params) == 1:
            p = a.params[0]
            values = sorted(set(_real_roots(left, p)) | set(_real_roots(right, p)),
                            key=lambda x: sp.N(x, 30))
            exceptional: dict[sp.Expr, Any] = {}
            for v in values:
                try:
                    sub = a.subs({p: v})
                except AnalysisError:                         # e.g. a CRootOf value
                    exceptional[v] = None
                    continue
                exceptional[v] = None if sub.is_zero else (sub.start, sub.end)
            witness["exceptional"] = exceptional
    provenance = {
        "method": "mask support (convex hull of supp phi)",
        "parameters": tuple(q.name for q in a.params),
        "arithmetic": "exact",
    }
    return Result(value=(s, e), status=CERTIFIED, witness=witness, provenance=provenance)
