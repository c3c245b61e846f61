"""Difference schemes and exact norms ``||S_a||_inf`` and ``||(1/M S_{a_m})^L||_inf``, any arity ``M``.

Convention: ``(S_a f)_i = sum_j a_{i-Mj} f_j``, ``q_M(z) = 1 + z + ... + z^{M-1}`` (the keyword
``arity``, default 2: ``q_2 = 1+z``). With ``(Delta f)(z) = (z^{-1} - 1) f(z)``, ``Delta S_a f = S_b Delta f``
iff ``b(z) = z^{M-1} a(z)/q_M(z)``. Two spellings of the m-th difference scheme (both supported, see DESIGN.md):

* ``"divided"``: ``b(z) = (M/q_M(z))^m a(z)`` — the scheme refining ``M^{nm} Delta^m f^n``;
* ``"paper"``:   ``a_m(z) = (M z^{M-1}/q_M(z))^m a(z) = z^{m(M-1)} b(z)`` — as papers write it
  (``(2z/(1+z))^m a`` for M = 2; seed 003, 004).

The extra ``z^{m(M-1)}`` is a shift: every norm below is the same for both.

Norms (``DESIGN.md``): ``||S_a||_inf = max_r sum_j |a_{r+Mj}|``; for L steps the same over
residues mod ``M^L`` of ``a^[L](z) = a(z) a(z^M) ... a(z^{M^{L-1}})``. The Dyn–Levin C^m test:
``||(1/M S_{a_{m+1}})^L||_inf < 1`` for some ``L`` implies the scheme is C^m.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> chaikin = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
>>> scheme_norm(chaikin).value
1
>>> r = difference_norm(chaikin, m=2, L=1)
>>> r.value, r.witness["contractive"]
(1/2, True)
>>> b3 = LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)")           # ternary quadratic B-spline
>>> difference_symbol(b3, 1, arity=3)
LaurentSymbol([1/3, 2/3, 1, 2/3, 1/3], start=-1, domain=QQ)
>>> r = difference_norm(b3, 2, arity=3)                                 # ||(1/3 S_{a_2})|| < 1: C^1
>>> r.value, r.witness["contractive"]
(1/3, True)

Algorithm
---------
Rational symbols: the coefficients are brought to a common denominator and the product
``a(z) a(z^2) ... a(z^{2^{L-1}})`` is formed with FLINT integer polynomials (python-flint); the
residue sums are exact integers. Algebraic coefficients (``QQ<theta>``): the product is formed in
sympy over the algebraic field and every absolute value is decided by
:func:`analysis.algebra.algebraic.sign` (rigorous enclosures plus an exact zero test). Symbols with one
free parameter are handled in :mod:`analysis.stationary.normset`.

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Thm 3.3
and Sect. 3.4 (L-step norms).
"""

from __future__ import annotations

from fractions import Fraction
from math import lcm

import sympy as sp

from ..algebra.algebraic import sign
from ..algebra.factorization import arity_key, check_arity, factor_out
from ..result import CERTIFIED, AnalysisError, Result
from ..algebra.symbol import LaurentSymbol
from ..algebra.reader import as_expr

SPELLINGS = ("divided", "paper")


def difference_symbol(a: LaurentSymbol, m: int, *, spelling: str = "paper", arity: int = 2) -> LaurentSymbol:
    """The m-th difference symbol: ``(M/q_M)^m a`` ("divided") or ``(M z^{M-1}/q_M)^m a`` ("paper"),
    ``M`` the arity (``(2/(1+z))^m a`` and ``(2z/(1+z))^m a`` for ``M = 2``).

    Raises :class:`AnalysisError` when ``q_M^m`` does not divide ``a`` identically.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
    >>> difference_symbol(a, 1, spelling="divided"), difference_symbol(a, 1)
    (LaurentSymbol([1/2, 1, 1/2], start=-2, domain=QQ), LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ))
    """
    M = check_arity(arity)
    if spelling not in SPELLINGS:
        raise AnalysisError(f"unknown spelling {spelling!r}; use 'divided' or 'paper'")
    if not isinstance(m, int) or m < 0:
        raise AnalysisError(f"the difference order must be a non-negative integer, not {m!r}")
    b = factor_out(a, m, arity=M)
    return b.shift(m * (M - 1)) if spelling == "paper" else b


def iterated_symbol(a: LaurentSymbol, L: int, *, arity: int = 2) -> LaurentSymbol:
    """``a(z) a(z^M) ... a(z^{M^{L-1}})``, the symbol of ``S_a^L`` (exact, sympy; ``M`` the arity)."""
    if L < 1:
        raise AnalysisError("L must be a positive integer")
    out = a
    for j in range(1, L):
        out = out * a.upsample(arity ** j)
    return out


# --------------------------------------------------------------------------------------------
# exact numeric norms
# --------------------------------------------------------------------------------------------

def _rational_residue_sums(a: LaurentSymbol, L: int, M: int = 2) -> tuple[list[Fraction], int]:
    """Residue sums of ``|coeff|`` mod ``M^L`` for a rational symbol, with FLINT products.

    Returns the sums (as Fractions, indexed by residue r of the exponent mod M^L) and the
    lowest exponent of the product.
    """
    from flint import fmpz_poly

    fr = [Fraction(int(c.p), int(c.q)) for c in (sp.Rational(c) for c in a.mask)]
    den = lcm(*[f.denominator for f in fr])
    ints = [int(f * den) for f in fr]
    prod = fmpz_poly(ints)
    for j in range(1, L):
        step = M ** j
        spaced = [0] * ((len(ints) - 1) * step + 1)
        spaced[::step] = ints
        prod = prod * fmpz_poly(spaced)
    start = a.start * (M ** L - 1) // (M - 1)
    coeffs = [int(c) for c in prod.coeffs()]
    mod = M ** L
    # exponent e = start + idx; residue (start + idx) mod M^L = r
    sums = [sum(abs(c) for c in coeffs[(r - start) % mod::mod]) for r in range(mod)]
    total_den = den ** L
    return [Fraction(s, total_den) for s in sums], start


def residue_sums(a: LaurentSymbol, L: int = 1, *, arity: int = 2) -> list[sp.Expr]:
    """Exact ``sum_j |c_{r + M^L j}|`` for every residue r, c the symbol of ``S_a^L`` (``M`` the arity).

    The symbol must be numeric (rational or algebraic coefficients). Algebraic sums are simplified
    with ``radsimp`` (and, for ``M = 2``, ``nsimplify``, the form the binary reports record).
    """
    M = check_arity(arity)
    a.require_numeric("an exact norm")
    if a.domain.is_QQ or a.domain.is_ZZ:
        sums, _ = _rational_residue_sums(a, L, M)
        return [sp.Rational(s.numerator, s.denominator) for s in sums]
    prod = iterated_symbol(a, L, arity=M)
    mod = M ** L
    sums = [sp.Integer(0)] * mod
    for i, c in prod.items():
        s = sign(c)
        if s:
            sums[i % mod] += s * c
    if M != 2:
        return [sp.radsimp(sp.expand(s)) for s in sums]
    return [sp.nsimplify(sp.radsimp(sp.expand(s))) if s.free_symbols == set() else s for s in sums]


def _max_exact(values: list[sp.Expr]) -> tuple[sp.Expr, int]:
    best, arg = values[0], 0
    for i, v in enumerate(values[1:], start=1):
        if sign(v - best) > 0:
            best, arg = v, i
    return best, arg


def scheme_norm(a: LaurentSymbol, L: int = 1, *, scale=1, arity: int = 2) -> Result:
    """``||(scale * S_a)^L||_inf`` exactly (certified), for a numeric symbol of arity ``M``.

    ``witness``: the residue sums (for ``L <= 6``; ``L <= 4`` when ``M > 2``), the maximising residue and ``L``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> scheme_norm(LaurentSymbol.from_mask(["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"], start=-3)).value
    5/4
    >>> scheme_norm(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), arity=3).value
    1
    """
    M = check_arity(arity)
    if not isinstance(L, int) or L < 1:
        raise AnalysisError(f"L must be a positive integer, not {L!r}")
    scale = as_expr(scale)
    shown_up_to = 6 if M == 2 else 4
    if a.is_numeric and (a.domain.is_QQ or a.domain.is_ZZ):
        fsums, _ = _rational_residue_sums(a, L, M)
        arg = max(range(len(fsums)), key=fsums.__getitem__)
        f = sp.Rational(fsums[arg].numerator, fsums[arg].denominator)
        scale_L = scale ** L            # formed once: the same products as forming it per residue
        value = scale_L * f
        shown = [scale_L * sp.Rational(x.numerator, x.denominator) for x in fsums] if L <= shown_up_to else None
    else:
        sums = residue_sums(a, L, arity=M)
        best, arg = _max_exact(sums)
        value = sp.radsimp(sp.expand(scale ** L * best))
        shown = [sp.expand(scale ** L * x) for x in sums] if M == 2 or L <= shown_up_to else None
    method = ("exact residue sums of a(z)a(z^2)...a(z^(2^(L-1)))" if M == 2 else
              f"exact residue sums mod {M}^L of a(z)a(z^{M})...a(z^({M}^(L-1)))")
    return Result(value=value, status=CERTIFIED,
                  witness={"L": L, "residue_sums": shown, "argmax_residue": arg},
                  provenance={"method": method, **arity_key(M), "domain": str(a.domain)})


def difference_norm(a: LaurentSymbol, m: int, L: int = 1, *, spelling: str = "paper", arity: int = 2) -> Result:
    """``||(1/M S_{a_m})^L||_inf`` exactly (``M`` the arity), and whether it is below 1 (the Dyn–Levin test).

    ``witness["contractive"]`` is True when the norm is < 1, which proves the scheme is
    ``C^{m-1}`` (``witness["implies"]``). A norm >= 1 proves nothing.
    """
    M = check_arity(arity)
    a.require_numeric("an exact norm (use --solve PARAM for a parameter range)")
    am = difference_symbol(a, m, spelling=spelling, arity=M)
    r = scheme_norm(am, L, scale=sp.Rational(1, M), arity=M)
    contractive = sign(r.value - 1) < 0
    witness = dict(r.witness)
    witness.update({"m": m, **arity_key(M), "difference_symbol": am, "spelling": spelling, "contractive": contractive,
                    "implies": f"C^{m - 1} (Dyn-Levin)" if contractive else "nothing (norm >= 1)"})
    return Result(value=r.value, status=CERTIFIED, witness=witness, provenance=r.provenance)
