"""Input parsing and rigorous arithmetic for the JSR engine.

A family of matrices is read once into a :class:`Family` that keeps

* ``floats`` — float64 images, used by every search (never by a certificate);
* ``kind`` — ``"rational"`` (every entry in QQ: certificates use exact FLINT ``fmpq``
  arithmetic), ``"real"`` (exact real numbers such as ``sqrt(3)``: certificates use Arb balls
  that enclose the exact entries), or ``"float"`` (at least one Python/numpy float: the float is
  read as the binary rational it represents, and certificates are exact for *those* rationals),
  or ``"ball"`` (at least one ``flint.arb`` entry: each ball stands for an *uncertain* real
  number, and every certificate is evaluated in Arb ball arithmetic over the balls, so it holds
  for **every** family of real matrices whose entries lie in the balls);
* ``exact_q`` — ``fmpq_mat`` images (kinds ``rational`` and ``float``);
* ``exact_sym`` — sympy matrices (kind ``real``), enclosed by :func:`arb_matrix` on demand;
* ``balls`` — ``arb_mat`` images (kind ``ball``; exact and sympy entries enclosed).

Rigorous helpers: :func:`rho_enclosure` (the spectral radius of an exact or ball matrix, from
isolated roots of the exact characteristic polynomial or Arb eigenvalue enclosures),
:func:`root_lower` / :func:`root_upper` (rigorous L-th roots of rationals), and dyadic rounding.
"""

from __future__ import annotations

import contextlib
import math
import sys
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Iterator, Sequence

import numpy as np
import flint
from flint import acb_mat, arb, arb_mat, fmpq, fmpq_mat, fmpz

from ..result import AnalysisError

if TYPE_CHECKING:  # pragma: no cover
    import sympy as sp

# No sympy at import: a family of balls or rationals (the ball route of the Hölder exponent) is
# solved without it. A value can only be a sympy object once sympy is imported, so the readers
# below look for sympy in ``sys.modules``; the functions that build sympy values import it.


def _sympy():
    """The sympy module if it is imported (then an input may be a sympy object), else None."""
    return sys.modules.get("sympy")

#: Working precision (bits) of every Arb computation in this package.
ARB_PREC = 192


@contextlib.contextmanager
def arb_precision(bits: int = ARB_PREC) -> Iterator[None]:
    """Temporarily set FLINT's global real/complex precision (restored on exit)."""
    old = flint.ctx.prec
    flint.ctx.prec = bits
    try:
        yield
    finally:
        flint.ctx.prec = old


# --------------------------------------------------------------------------------------------
# numbers
# --------------------------------------------------------------------------------------------

def arb_to_fraction_bounds(x: arb) -> tuple[Fraction, Fraction]:
    """Exact dyadic ``(lo, hi)`` with ``lo <= every point of x <= hi``."""
    if not x.is_finite():
        raise ArithmeticError("non-finite ball")
    lo_m, lo_e = x.lower().man_exp()
    hi_m, hi_e = x.upper().man_exp()
    return _dyadic(int(lo_m), int(lo_e)), _dyadic(int(hi_m), int(hi_e))


def _dyadic(m: int, e: int) -> Fraction:
    return Fraction(m * 2 ** e) if e >= 0 else Fraction(m, 2 ** (-e))


def fraction_to_arb(q: Fraction) -> arb:
    return arb(fmpq(q.numerator, q.denominator))


def round_down(x: Fraction, bits: int = 96) -> Fraction:
    """The largest dyadic ``<= x`` with about ``bits`` significant bits (``x >= 0``)."""
    if x <= 0:
        return Fraction(math.floor(x * 2 ** bits), 2 ** bits) if x < 0 else Fraction(0)
    e = x.numerator.bit_length() - x.denominator.bit_length() - bits
    return Fraction(math.floor(x / Fraction(2) ** e)) * Fraction(2) ** e


def round_up(x: Fraction, bits: int = 96) -> Fraction:
    """The smallest dyadic ``>= x`` with about ``bits`` significant bits (``x >= 0``)."""
    if x <= 0:
        return Fraction(math.ceil(x * 2 ** bits), 2 ** bits)
    e = x.numerator.bit_length() - x.denominator.bit_length() - bits
    return Fraction(math.ceil(x / Fraction(2) ** e)) * Fraction(2) ** e


def root_lower(x: Fraction, L: int) -> Fraction:
    """A rational ``q <= x**(1/L)`` (rigorous, tight to ~ARB_PREC bits); ``x >= 0``."""
    if x <= 0:
        return Fraction(0)
    if L == 1:
        return x
    with arb_precision():
        lo, _ = arb_to_fraction_bounds(fraction_to_arb(x).root(L))
    return max(lo, Fraction(0))


def root_upper(x: Fraction, L: int) -> Fraction:
    """A rational ``q >= x**(1/L)`` (rigorous); ``x >= 0``."""
    if x <= 0:
        return Fraction(0)
    if L == 1:
        return x
    with arb_precision():
        _, hi = arb_to_fraction_bounds(fraction_to_arb(x).root(L))
    return hi


# --------------------------------------------------------------------------------------------
# sympy expressions -> Arb balls
# --------------------------------------------------------------------------------------------

class NoEnclosure(ValueError):
    """An exact real expression that :func:`sympy_to_arb` cannot enclose rigorously."""


_ARB_FUNCS = {"sin", "cos", "tan", "exp", "log", "atan", "asin", "acos", "sinh", "cosh", "tanh"}


def sympy_to_arb(e: sp.Expr, known: dict | None = None) -> arb:
    """A rigorous Arb ball containing the real number ``e`` (numbers, +, *, powers, pi, E, sqrt,
    and the elementary functions in ``_ARB_FUNCS``; ``cos(q pi)`` for rational ``q`` through Arb's exact-argument
    cosine); ``known`` maps symbols to the balls they stand for."""
    import sympy as sp

    if known and e in known:
        return known[e]
    if e.is_Rational:
        return arb(fmpq(int(e.p), int(e.q)))
    if isinstance(e, sp.cos) and (e.args[0] / sp.pi).is_Rational:
        q = e.args[0] / sp.pi
        return arb.cos_pi_fmpq(fmpq(int(q.p), int(q.q)))
    if e is sp.pi:
        return arb.pi()
    if e is sp.E:
        return arb.const_e()
    if e.is_Add:
        out = arb(0)
        for t in e.args:
            out += sympy_to_arb(t, known)
        return out
    if e.is_Mul:
        out = arb(1)
        for t in e.args:
            out *= sympy_to_arb(t, known)
        return out
    if e.is_Pow:
        b, x = e.args
        bb = sympy_to_arb(b, known)
        if x.is_Integer:
            n = int(x)
            return bb ** n if n >= 0 else 1 / (bb ** (-n))
        if x.is_Rational:
            if not bb > 0:
                raise NoEnclosure(f"cannot enclose {e}")
            r = bb.root(int(x.q))
            p = int(x.p)
            return r ** p if p >= 0 else 1 / (r ** (-p))
        if not bb > 0:
            raise NoEnclosure(f"cannot enclose {e}")
        return (bb.log() * sympy_to_arb(x, known)).exp()
    if isinstance(e, sp.Function) and e.func.__name__ in _ARB_FUNCS and len(e.args) == 1:
        return getattr(sympy_to_arb(e.args[0], known), e.func.__name__)()
    raise NoEnclosure(f"cannot enclose {e}")


# --------------------------------------------------------------------------------------------
# families
# --------------------------------------------------------------------------------------------

@dataclass
class Family:
    """A parsed family of ``k`` real ``n x n`` matrices (see module docstring)."""

    floats: list[np.ndarray]
    kind: str
    exact_q: list[fmpq_mat] | None = None
    exact_sym: list[sp.Matrix] | None = None
    balls: list[arb_mat] | None = None
    _arb_cache: dict = field(default_factory=dict)

    @property
    def n(self) -> int:
        return self.floats[0].shape[0]

    @property
    def k(self) -> int:
        return len(self.floats)

    def arb(self, i: int) -> arb_mat:
        """Arb enclosure of matrix ``i`` at :data:`ARB_PREC` (exact entries stay exact)."""
        if self.balls is not None:
            return self.balls[i]
        key = (i, flint.ctx.prec)
        if key not in self._arb_cache:
            with arb_precision():
                if self.exact_q is not None:
                    m = arb_mat(self.exact_q[i])
                else:
                    M = self.exact_sym[i]
                    m = arb_mat(self.n, self.n, [sympy_to_arb(M[r, c])
                                                 for r in range(self.n) for c in range(self.n)])
            self._arb_cache[key] = m
        return self._arb_cache[key]

    def subfamily(self, rows: Sequence[int], members: Sequence[int] | None = None) -> "Family":
        """The principal submatrices on index set ``rows`` (a diagonal block), for ``members``."""
        members = list(range(self.k)) if members is None else list(members)
        idx = list(rows)
        fl = [self.floats[i][np.ix_(idx, idx)].copy() for i in members]
        q = sym = None
        if self.exact_q is not None:
            q = [fmpq_mat([[self.exact_q[i][r, c] for c in idx] for r in idx]) for i in members]
        if self.exact_sym is not None:
            sym = [self.exact_sym[i].extract(idx, idx) for i in members]
        balls = None
        if self.balls is not None:
            balls = [arb_mat(len(idx), len(idx), [self.balls[i][r, c] for r in idx for c in idx])
                     for i in members]
        return Family(fl, self.kind, q, sym, balls)

    def max_radius(self) -> Fraction:
        """The largest radius of an entry ball (0 unless the kind is ``ball``)."""
        if self.balls is None:
            return Fraction(0)
        out = Fraction(0)
        for M in self.balls:
            for r in range(M.nrows()):
                for c in range(M.ncols()):
                    out = max(out, arb_to_fraction_bounds(arb(M[r, c].rad()))[1])
        return out

    def is_zero_entry(self, i: int, r: int, c: int) -> bool:
        """Exact test ``A_i[r, c] == 0``."""
        if self.exact_q is not None:
            return self.exact_q[i][r, c] == 0
        if self.balls is not None:      # zero for every matrix in the ball only if exactly 0
            return bool(self.balls[i][r, c].is_zero())
        import sympy as sp

        return bool(sp.simplify(self.exact_sym[i][r, c]) == 0)

    def equal(self, i: int, j: int) -> bool:
        """Exact test ``A_i == A_j``."""
        if self.exact_q is not None:
            return self.exact_q[i] == self.exact_q[j]
        if self.balls is not None:      # equal as uncertain matrices only if both are exact
            A, B = self.balls[i], self.balls[j]
            return all(A[r, c].is_exact() and B[r, c].is_exact() and A[r, c].mid() == B[r, c].mid()
                       for r in range(self.n) for c in range(self.n))
        import sympy as sp

        return bool((self.exact_sym[i] - self.exact_sym[j]).applyfunc(sp.simplify).is_zero_matrix)

    def product_q(self, word: Sequence[int]) -> fmpq_mat:
        P = self.exact_q[word[0]]
        for i in word[1:]:
            P = P * self.exact_q[i]
        return P

    def product_arb(self, word: Sequence[int]) -> arb_mat:
        with arb_precision():
            P = self.arb(word[0])
            for i in word[1:]:
                P = P * self.arb(i)
        return P


def _entry(x: Any) -> tuple[str, Any]:
    """Classify one entry: ('q', Fraction) | ('f', Fraction of a float) | ('r', sympy real) |
    ('b', flint.arb ball)."""
    if isinstance(x, arb):
        if not x.is_finite():
            raise AnalysisError(f"matrix entry {x!r} is not a finite ball")
        if x.is_exact():
            m, e = x.mid().man_exp()
            return "q", _dyadic(int(m), int(e))
        return "b", x
    if isinstance(x, (bool, np.bool_)):
        raise AnalysisError(f"matrix entry {x!r} is a boolean, not a number")
    if isinstance(x, (int, np.integer)):
        return "q", Fraction(int(x))
    if isinstance(x, Fraction):
        return "q", x
    if isinstance(x, fmpq):
        return "q", Fraction(int(x.p), int(x.q))
    if isinstance(x, fmpz):
        return "q", Fraction(int(x))
    if isinstance(x, (float, np.floating)):
        if not math.isfinite(float(x)):
            raise AnalysisError(f"matrix entry {x!r} is not finite")
        return "f", Fraction(float(x))
    if isinstance(x, str):
        from ..algebra.symbol import parse_coefficient
        x = parse_coefficient(x)
    sp = _sympy()
    if sp is not None and isinstance(x, sp.Basic):
        from ..algebra.reader import as_expr

        x = as_expr(x)
        if x.free_symbols:
            raise AnalysisError(f"matrix entry {x} has free symbols {sorted(map(str, x.free_symbols))}; "
                                "substitute parameter values first")
        if x.is_Rational:
            return "q", Fraction(int(x.p), int(x.q))
        if isinstance(x, sp.Float):
            return "f", Fraction(float(x))
        if x.is_real is False or not x.is_number:
            raise AnalysisError(f"matrix entry {x} is not a real number")
        return "r", x
    raise AnalysisError(f"matrix entry {x!r} of type {type(x).__name__} is not a number")


def _rows(M: Any) -> list[list[Any]]:
    if isinstance(M, fmpq_mat):
        return [[M[r, c] for c in range(M.ncols())] for r in range(M.nrows())]
    sp = _sympy()
    if sp is not None and isinstance(M, sp.MatrixBase):
        return [list(M.row(r)) for r in range(M.rows)]
    if isinstance(M, np.ndarray):
        if M.ndim != 2:
            raise AnalysisError(f"expected a 2-d matrix, got an array of shape {M.shape}")
        return [list(row) for row in M]
    try:
        rows = [list(r) for r in M]
    except TypeError:
        raise AnalysisError(f"cannot read a matrix from {type(M).__name__}") from None
    return rows


def parse_family(matrices: Any) -> Family:
    """Read a family of square matrices (numpy arrays, sympy matrices, nested lists of ints,
    Fractions, decimal strings, sympy numbers or floats, FLINT ``fmpq_mat``).

    >>> F = parse_family([[[1, 1], [0, 1]], [["1/2", 0], [1, 1]]])
    >>> F.kind, F.k, F.n
    ('rational', 2, 2)
    >>> parse_family([np.eye(2)]).kind
    'float'
    >>> import sympy as sp
    >>> parse_family([sp.Matrix([[sp.sqrt(3)]])]).kind
    'real'
    >>> parse_family([[[flint.arb(1) / 3]]]).kind          # an uncertain entry: a ball
    'ball'
    """
    if isinstance(matrices, np.ndarray) and matrices.ndim == 3:
        matrices = list(matrices)
    sp = _sympy()
    if isinstance(matrices, (np.ndarray, fmpq_mat)) or (sp is not None and isinstance(matrices, sp.MatrixBase)):
        raise AnalysisError("expected a sequence of matrices, got a single matrix; wrap it in a list")
    try:
        mats = list(matrices)
    except TypeError:
        raise AnalysisError("expected a sequence of matrices") from None
    if not mats:
        raise AnalysisError("the family of matrices is empty")
    parsed: list[list[list[tuple[str, Any]]]] = []
    n = None
    for idx, M in enumerate(mats):
        rows = _rows(M)
        if n is None:
            n = len(rows)
        if n == 0:
            raise AnalysisError("matrices must be at least 1 x 1")
        if len(rows) != n or any(len(r) != n for r in rows):
            raise AnalysisError(f"matrix {idx} is not square of the common size {n} x {n}")
        parsed.append([[_entry(x) for x in r] for r in rows])
    kinds = {t for P in parsed for r in P for (t, _) in r}
    kind = ("ball" if "b" in kinds else "real" if "r" in kinds else
            "float" if "f" in kinds else "rational")

    def _fl(t: str, v: Any) -> float:
        if t == "r":
            return float(sp.N(v, 30))
        if t == "b":
            return float(v.mid())
        return float(v)

    floats: list[np.ndarray] = []
    for P in parsed:
        floats.append(np.array([[_fl(t, v) for (t, v) in r] for r in P], dtype=float))
    for i, Mf in enumerate(floats):
        if not np.all(np.isfinite(Mf)):
            raise AnalysisError(f"matrix {i} has entries too large for float64")
    if kind == "ball":
        if "f" in kinds:
            raise AnalysisError("a family mixes float entries with Arb balls: give the uncertain "
                                "entries as balls and the known ones exactly")
        balls = []
        with arb_precision():
            for P in parsed:
                vals = []
                for r in P:
                    for (t, v) in r:
                        if t == "b":
                            vals.append(v)
                        elif t == "r":
                            vals.append(sympy_to_arb(v))
                        else:
                            vals.append(fraction_to_arb(v))
                balls.append(arb_mat(n, n, vals))
        return Family(floats, kind, None, None, balls)
    if kind == "real":
        import sympy as sp

        sym = [sp.Matrix([[sp.Rational(v.numerator, v.denominator) if t != "r" else v
                           for (t, v) in r] for r in P]) for P in parsed]
        return Family(floats, kind, None, sym)
    q = [fmpq_mat([[fmpq(v.numerator, v.denominator) for (_, v) in r] for r in P]) for P in parsed]
    return Family(floats, kind, q, None)


# --------------------------------------------------------------------------------------------
# spectral radius enclosures
# --------------------------------------------------------------------------------------------

def rho_enclosure_q(P: fmpq_mat) -> tuple[Fraction, Fraction]:
    """Rigorous ``(lo, hi)`` for the spectral radius of an exact rational matrix: roots of the
    exact characteristic polynomial isolated by FLINT (``fmpz_poly.complex_roots``)."""
    cp = P.charpoly().numer()
    with arb_precision():
        roots = cp.complex_roots()
        lo = hi = Fraction(0)
        for z, _mult in roots:
            a = abs(z)
            l, h = arb_to_fraction_bounds(a)
            lo, hi = max(lo, l), max(hi, h)
    return max(lo, Fraction(0)), hi


def _rho_eig_arb(P: arb_mat) -> tuple[Fraction, Fraction] | None:
    """Arb eigenvalue enclosures (clustered for multiple eigenvalues) at the current precision;
    ``None`` if they cannot be isolated."""
    try:
        ev = acb_mat(P).eig(multiple=True)
    except (ValueError, ArithmeticError):
        return None
    lo = hi = Fraction(0)
    for z in ev:
        l, h = arb_to_fraction_bounds(abs(z))
        lo, hi = max(lo, l), max(hi, h)
    return max(lo, Fraction(0)), hi


def rho_enclosure_arb(P: arb_mat) -> tuple[Fraction, Fraction]:
    """Rigorous ``(lo, hi)`` for the spectral radius of any matrix in the ball ``P``.

    Arb eigenvalue enclosures (``acb_mat.eig``, clustered for multiple eigenvalues); if those
    fail, the crude but rigorous ``|det P|^(1/n) <= rho(P) <= ||P||_inf``.
    """
    n = P.nrows()
    with arb_precision():
        out = _rho_eig_arb(P)
        if out is not None:
            return out
        d_lo, _ = arb_to_fraction_bounds(abs(P.det()))
        hi = max(arb_to_fraction_bounds(sum((abs(P[r, c]) for c in range(n)), arb(0)))[1]
                 for r in range(n))
    return root_lower(max(d_lo, Fraction(0)), n), hi


def rho_enclosure(F: Family, word: Sequence[int]) -> tuple[Fraction, Fraction]:
    """Rigorous enclosure of ``rho(A_{w1} A_{w2} ... A_{wL})`` for the exact family ``F``.

    For ball and algebraic families the Arb eigenvalue isolation is retried with the product
    recomputed at 2x and 4x the precision (Daubechies D44 and beyond need ~400 bits) before the
    crude determinant/norm fallback of :func:`rho_enclosure_arb`."""
    if F.exact_q is not None:
        return rho_enclosure_q(F.product_q(word))
    for bits in (ARB_PREC, 2 * ARB_PREC, 4 * ARB_PREC):
        with arb_precision(bits):
            P = F.arb(word[0])
            for i in word[1:]:
                P = P * F.arb(i)
            out = _rho_eig_arb(P)
        if out is not None:
            return out
    return rho_enclosure_arb(F.product_arb(word))


def exact_rho_expression(F: Family, word: Sequence[int]) -> sp.Expr | None:
    """For rational families and small sizes: the exact algebraic number ``rho(P_w)^(1/L)`` as a
    sympy expression (radicals when the dominant eigenvalue's factor has degree <= 2, else a real
    ``CRootOf``); None when the dominant eigenvalue is a non-real root of degree > 2.

    The dominant root is chosen with FLINT's certified complex root balls (fast); the expression
    is only a witness for display — the bounds never depend on it."""
    if F.exact_q is None or F.n > 8:
        return None
    import sympy as sp

    try:
        from flint import fmpq_poly

        P = F.product_q(word)
        M = sp.Matrix([[sp.Rational(int(P[r, c].p), int(P[r, c].q)) for c in range(F.n)]
                       for r in range(F.n)])
        x = sp.Symbol("x")
        cp = sp.Poly(M.charpoly(x).as_expr(), x, domain=sp.QQ)
        best = None  # (modulus upper, modulus lower, factor, root ball)
        for fac, _m in cp.factor_list()[1]:
            coeffs = [sp.Rational(c) for c in reversed(fac.all_coeffs())]
            den = sp.ilcm(*[c.q for c in coeffs])
            for root, _k in fmpq_poly([int(c * den) for c in coeffs]).complex_roots():
                m = abs(root)
                if best is None or float(m.mid()) > float(best[0].mid()):
                    best = (m, fac, root)
        if best is None:
            return None
        m, fac, root = best
        d = fac.degree()
        if root.imag.is_zero() or (d % 2 == 1 and fac.count_roots() == d):
            from ..algebra.algebraic import RealAlgebraic

            target = float(root.real.mid())
            reals = RealAlgebraic.roots_of(fac)
            r = min(reals, key=lambda t: abs(float(t) - target))
            e = r.expr
            if float(r) < 0:
                e = -e
        elif d == 2:
            a2, a1, a0 = (sp.Rational(c) for c in fac.all_coeffs())
            e = sp.sqrt(a0 / a2)          # |lambda|^2 = product of the conjugate pair
        else:
            return None
        L = len(word)
        return e if L == 1 else e ** sp.Rational(1, L)
    except Exception:  # pragma: no cover - an optional nicety, never essential
        return None
