"""Laurent symbols of binary subdivision schemes, with exact coefficients.

Convention (stated once, used everywhere; see README "Conventions")::

    (S_a f)_i = sum_j a_{i-2j} f_j,        a(z) = sum_i a_i z^i   (a Laurent polynomial).

A :class:`LaurentSymbol` stores ``a(z) = z^start * P(z)`` where ``P`` is a sympy ``Poly`` in ``z``
with ``P(0) != 0`` over an exact coefficient domain:

* ``QQ`` for rational masks,
* ``QQ<theta>`` for masks with algebraic numbers (``sqrt(6)``),
* ``QQ[omega, ...]`` or ``K[omega, ...]`` (``K`` an algebraic field) for symbolic parameters,
* ``QQ(omega, ...)`` when parameters appear in denominators.

Floats are never stored: decimal strings are read exactly (``"0.25"`` is ``1/4``); Python floats
are converted to the rational they represent exactly.

Paper-style rules
-----------------
Papers write the scheme as two stencils, e.g. seed 003, rule (1)::

    f_{2i}   = -7w f_{i-1} + (3/4+9w) f_i + (1/4+3w) f_{i+1} - 5w f_{i+2}
    f_{2i+1} = -5w f_{i-1} + (1/4+3w) f_i + (3/4+9w) f_{i+1} - 7w f_{i+2}

A stencil is a list of the coefficients of ``f_{i+p}``, ``p = first, first+1, ...``. With the
convention above the even rule's coefficient of ``f_{i+p}`` is ``a_{-2p}`` and the odd rule's is
``a_{1-2p}``; :meth:`LaurentSymbol.from_rules` and :meth:`LaurentSymbol.rules` convert both ways.

Examples
--------
>>> a = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)   # Chaikin
>>> a
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
>>> a(1), a(-1)
(2, 0)
>>> even, odd = a.subsymbols()
>>> even.mask, odd.mask
((1/4, 3/4), (3/4, 1/4))
>>> print(a.rules())
f[2i]   = 3/4 f[i] + 1/4 f[i+1]
f[2i+1] = 1/4 f[i] + 3/4 f[i+1]

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numerica 11 (2002) 73-144.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Iterable, Mapping, Sequence

import sympy as sp
from sympy.polys.constructor import construct_domain
from sympy.polys.polyerrors import PolynomialError, CoercionFailed, GeneratorsError

from ..result import AnalysisError
from .reader import as_expr, read_expression

#: The indeterminate of every symbol.
Z = sp.Symbol("z")

#: Names users may type for common parameters; the greek names print nicely.
_GREEK = {"w": "omega", "mu": "mu", "nu": "nu", "omega": "omega", "alpha": "alpha"}


# --------------------------------------------------------------------------------------------
# parsing exact numbers
# --------------------------------------------------------------------------------------------

def parse_coefficient(c, *, locals_: Mapping[str, sp.Symbol] | None = None, free: bool = True,
                      what: str = "coefficient") -> sp.Expr:
    """Turn ``c`` into an exact sympy expression.

    Strings are read by the input reader (:func:`analysis.algebra.reader.read_expression`: never
    evaluated), decimal literals exactly (``"0.1"`` -> ``1/10``); other names than ``locals_``
    become parameters unless ``free`` is false (then they are an error naming them). Python floats
    become the rational they represent; ``Fraction`` and sympy numbers pass through. Anything
    that is not a number or an expression in named parameters is an :class:`AnalysisError`.

    >>> parse_coefficient("3/4+9*omega")
    9*omega + 3/4
    >>> parse_coefficient("0.25")
    1/4
    >>> parse_coefficient("(sqrt(6)-1)/80")
    -1/80 + sqrt(6)/80
    """
    if isinstance(c, sp.Basic):
        expr = c
    elif isinstance(c, bool):
        raise AnalysisError(f"coefficient {c!r} is not a number")
    elif isinstance(c, int):
        expr = sp.Integer(c)
    elif isinstance(c, Fraction):
        expr = sp.Rational(c.numerator, c.denominator)
    elif isinstance(c, float):
        if c != c or c in (float("inf"), float("-inf")):
            raise AnalysisError(f"coefficient {c!r} is not a finite number")
        expr = sp.Rational(c)
    elif isinstance(c, str):
        text = c.strip()
        if not text:
            raise AnalysisError("empty coefficient in mask")
        expr = read_expression(text, names=locals_, free=free, what=what)
    else:
        try:
            import numpy as np

            if isinstance(c, np.integer):
                return sp.Integer(int(c))
            if isinstance(c, np.floating):
                return parse_coefficient(float(c))
        except ImportError:  # pragma: no cover
            pass
        raise AnalysisError(f"coefficient {c!r} of type {type(c).__name__} is not a number")
    if not isinstance(expr, sp.Expr) or isinstance(expr, (sp.Tuple,)) or expr.has(sp.zoo, sp.nan, sp.oo):
        raise AnalysisError(f"coefficient {c!r} is not a finite number or formula")
    if expr.has(sp.Float):
        expr = sp.nsimplify(expr, rational=True)
    reserved = {s for s in expr.free_symbols if s.name in ("inf", "nan", "oo", "I", "E", "pi", "zoo")}
    if reserved:
        raise AnalysisError(f"coefficient {c!r} is not a finite number or formula")
    return expr


def parameter_symbols(exprs: Iterable[sp.Expr], *, exclude: Sequence[sp.Symbol] = (Z,)) -> tuple[sp.Symbol, ...]:
    """The free symbols of ``exprs`` other than ``z``, sorted by name."""
    free: set[sp.Symbol] = set()
    for e in exprs:
        free |= e.free_symbols
    free -= set(exclude)
    return tuple(sorted(free, key=lambda s: s.name))


def _choose_domain(coeffs: Sequence[sp.Expr], params: Sequence[sp.Symbol]):
    """An exact sympy domain for ``coeffs`` (QQ, QQ<theta>, K[params] or K(params))."""
    if not params:
        dom, _ = construct_domain(list(coeffs), extension=True)
        if dom.is_EX or dom.is_EXRAW or dom.is_PolynomialRing or dom.is_FractionField:
            bad = next((c for c in coeffs if c.is_algebraic is not True), coeffs[0])
            raise AnalysisError(f"coefficient {sp.sstr(bad)} is not an exact algebraic number")
        return sp.QQ if dom.is_ZZ else dom
    # collect the numeric (algebraic) constants that multiply monomials in the parameters
    numeric: list[sp.Expr] = []
    polynomial = True
    for c in coeffs:
        num, den = sp.fraction(sp.together(c))
        if den.free_symbols & set(params):
            polynomial = False
        for part in (num, den):
            try:
                numeric.extend(sp.Poly(part, *params).coeffs())
            except (PolynomialError, GeneratorsError):
                raise AnalysisError(
                    f"coefficient {sp.sstr(c)} is not a rational function of the parameters "
                    f"{', '.join(p.name for p in params)}") from None
    ground, _ = construct_domain(numeric or [sp.Integer(1)], extension=True)
    if ground.is_EX or ground.is_EXRAW or ground.is_PolynomialRing or ground.is_FractionField:
        bad = next((c for c in numeric if not c.is_algebraic), numeric[0])
        raise AnalysisError(f"constant {sp.sstr(bad)} in a coefficient is not an exact algebraic number")
    if ground.is_ZZ:
        ground = sp.QQ
    return ground[tuple(params)] if polynomial else ground.frac_field(*params)


# --------------------------------------------------------------------------------------------
# paper-style rules
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Rules:
    """The even and odd stencils of a binary scheme.

    ``f[2i] = sum_p even[p - even_first] f[i+p]`` and likewise for ``f[2i+1]``.
    """

    even: tuple
    even_first: int
    odd: tuple
    odd_first: int

    def __str__(self) -> str:
        def rule(lhs: str, stencil: tuple, first: int) -> str:
            terms = []
            for k, c in enumerate(stencil):
                if c == 0:
                    continue
                p = first + k
                idx = "i" if p == 0 else (f"i+{p}" if p > 0 else f"i{p}")
                cs = sp.sstr(c)
                if isinstance(c, sp.Add):
                    cs = f"({cs})"
                terms.append(f"{cs} f[{idx}]")
            body = " + ".join(terms) if terms else "0"
            return f"{lhs} = {body.replace('+ -', '- ')}"

        return rule("f[2i]  ", self.even, self.even_first) + "\n" + rule("f[2i+1]", self.odd, self.odd_first)


# --------------------------------------------------------------------------------------------
# the symbol
# --------------------------------------------------------------------------------------------

class LaurentSymbol:
    """A Laurent polynomial ``a(z) = sum_i a_i z^i`` with exact coefficients.

    Build one with :meth:`from_mask`, :meth:`from_rules` or :meth:`from_expr`. Instances are
    immutable and hashable; arithmetic returns new symbols.

    Examples
    --------
    >>> w = sp.Symbol("omega")
    >>> a = LaurentSymbol.from_rules(even=[-7*w, sp.Rational(3, 4) + 9*w, sp.Rational(1, 4) + 3*w, -5*w],
    ...                              odd=[-5*w, sp.Rational(1, 4) + 3*w, sp.Rational(3, 4) + 9*w, -7*w],
    ...                              first=-1)
    >>> a.start, a.end, a.domain
    (-4, 3, QQ[omega])
    >>> a.mask
    (-5*omega, -7*omega, 3*omega + 1/4, 9*omega + 3/4, 9*omega + 3/4, 3*omega + 1/4, -7*omega, -5*omega)
    >>> LaurentSymbol.from_mask(a.mask, start=a.start) == a
    True
    """

    __slots__ = ("_poly", "_start", "_params", "_hash", "_mask")

    def __init__(self, poly: sp.Poly, start: int = 0, params: Sequence[sp.Symbol] = ()):
        if not isinstance(poly, sp.Poly) or poly.gens != (Z,):
            raise TypeError("LaurentSymbol expects a sympy Poly in z; use from_mask/from_expr")
        # normalise: pull powers of z out of the polynomial so that P(0) != 0
        if poly.is_zero:
            start = 0
        else:
            low = min(m[0] for m in poly.monoms())
            if low:
                poly = sp.Poly.from_dict({(m[0] - low,): c for m, c in poly.rep.to_dict().items()},
                                         Z, domain=poly.domain)
                start += low
        self._poly = poly
        self._start = int(start)
        self._params = tuple(params)
        self._hash = None
        self._mask = None

    # ---------------------------------------------------------------- constructors
    @classmethod
    def from_mask(cls, mask: Sequence, start: int = 0, params: Sequence[sp.Symbol] | None = None,
                  *, domain=None) -> "LaurentSymbol":
        """The symbol with coefficients ``mask[k]`` at ``z^(start+k)``.

        >>> LaurentSymbol.from_mask([1, 2, 1], start=-1) / 2
        LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
        """
        if isinstance(mask, (str, bytes)) or not hasattr(mask, "__len__"):
            raise AnalysisError("a mask is a list of coefficients")
        if len(mask) == 0:
            raise AnalysisError("the mask is empty")
        try:
            start = int(start)
        except (TypeError, ValueError):
            raise AnalysisError(f"the first index {start!r} is not an integer") from None
        coeffs = [parse_coefficient(c) for c in mask]
        if params is None:
            params = parameter_symbols(coeffs)
        else:
            params = tuple(params)
            unknown = set(parameter_symbols(coeffs)) - set(params)
            if unknown:
                raise AnalysisError("unknown parameter(s) in mask: "
                                    + ", ".join(sorted(s.name for s in unknown)))
        if domain is None:
            domain = _choose_domain(coeffs, params)
        try:
            poly = sp.Poly.from_list(list(reversed(coeffs)), Z, domain=domain)
        except (CoercionFailed, PolynomialError) as exc:
            raise AnalysisError(f"cannot represent the mask exactly over {domain}: {exc}") from None
        return cls(poly, start, params)

    @classmethod
    def from_rules(cls, even: Sequence, odd: Sequence, first: int = 0, *, even_first: int | None = None,
                   odd_first: int | None = None, params: Sequence[sp.Symbol] | None = None) -> "LaurentSymbol":
        """The symbol of ``f[2i] = sum_p even_p f[i+p]``, ``f[2i+1] = sum_p odd_p f[i+p]``.

        ``first`` is the offset ``p`` of the first coefficient of both stencils; ``even_first`` and
        ``odd_first`` override it per stencil. The even coefficient of ``f[i+p]`` is ``a_{-2p}``, the
        odd one ``a_{1-2p}``: :meth:`from_stencils` with ``M = 2``.

        >>> LaurentSymbol.from_rules(even=[1], odd=["1/2", "1/2"], first=0)   # linear B-spline
        LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
        """
        ef = first if even_first is None else even_first
        of = first if odd_first is None else odd_first
        return cls.from_stencils([even, odd], [ef, of], params=params)

    @classmethod
    def from_stencils(cls, stencils: Sequence[Sequence], first: int | Sequence[int] = 0, *,
                      params: Sequence[sp.Symbol] | None = None) -> "LaurentSymbol":
        """The symbol of the ``M = len(stencils)`` rules of an M-ary scheme,
        ``f[M i + r] = sum_p stencils[r][p - first_r] f[i + p]`` (``r = 0, ..., M-1``).

        With ``(S_a f)_i = sum_j a_{i-Mj} f_j`` the r-th rule's coefficient of ``f[i+p]`` is
        ``a_{r - M p}``. ``first`` is the offset ``p`` of the first coefficient of every stencil, or a
        list of M offsets (one per rule). For ``M = 2`` this is :meth:`from_rules`.

        >>> LaurentSymbol.from_stencils([[1], ["1/2", "1/2"]], [0, 0])        # linear B-spline (binary)
        LaurentSymbol([1/2, 1, 1/2], start=-1, domain=QQ)
        >>> LaurentSymbol.from_stencils([[1], ["2/3", "1/3"], ["1/3", "2/3"]], [0, 0, 0])   # ternary hat
        LaurentSymbol([1/3, 2/3, 1, 2/3, 1/3], start=-2, domain=QQ)
        """
        from .reader import LIMITS

        if isinstance(stencils, (str, bytes)) or not hasattr(stencils, "__len__"):
            raise AnalysisError("the rules are a list of M stencils (lists of coefficients), one per residue 0..M-1")
        M = len(stencils)
        if not 2 <= M <= LIMITS.arity:
            raise AnalysisError(f"an M-ary scheme has 2 <= M <= {LIMITS.arity} rules (stencils), not {M}")
        if isinstance(first, bool):
            raise AnalysisError("first must be an integer or a list of integers")
        firsts = [first] * M if isinstance(first, int) else list(first) if hasattr(first, "__len__") else None
        if firsts is None or len(firsts) != M or not all(isinstance(f, int) and not isinstance(f, bool) for f in firsts):
            raise AnalysisError(f"first must be an integer or a list of {M} integers (one offset per stencil)")
        entries: dict[int, sp.Expr] = {}
        total = 0
        for r, (stencil, f0) in enumerate(zip(stencils, firsts)):
            if isinstance(stencil, (str, bytes)) or not hasattr(stencil, "__len__"):
                raise AnalysisError(f"stencil {r} must be a list of coefficients")
            total += len(stencil)
            if total > LIMITS.coefficients:
                raise AnalysisError(f"the rules have more than {LIMITS.coefficients} coefficients (limit 'coefficients')")
            for k, c in enumerate(stencil):
                entries[r - M * (f0 + k)] = parse_coefficient(c)
        if not entries:
            raise AnalysisError("every stencil is empty")
        lo, hi = min(entries), max(entries)
        if hi - lo + 1 > LIMITS.coefficients:
            raise AnalysisError(f"the mask of these rules spans {hi - lo + 1} indices (offsets first = {firsts}): "
                                f"the limit is {LIMITS.coefficients} (limit 'coefficients')")
        mask = [entries.get(i, sp.Integer(0)) for i in range(lo, hi + 1)]
        return cls.from_mask(mask, start=lo, params=params)

    @classmethod
    def from_expr(cls, expr, params: Sequence[sp.Symbol] | None = None) -> "LaurentSymbol":
        """The symbol of a sympy expression (or string) in ``z``, e.g. ``"(1+z)**2/(2*z)"``.

        >>> LaurentSymbol.from_expr("(1+z)**3/(4*z**2)")
        LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
        """
        if isinstance(expr, str):
            expr = read_expression(expr, names={"z": Z}, what="symbol")
        expr = sp.expand(as_expr(expr))
        num, den = sp.fraction(sp.together(expr))
        try:
            den_poly = sp.Poly(den, Z)
        except PolynomialError:
            raise AnalysisError("the symbol must be a Laurent polynomial in z") from None
        if len(den_poly.terms()) != 1:
            raise AnalysisError("the symbol must be a Laurent polynomial in z "
                                "(only powers of z may divide)")
        shift = -den_poly.monoms()[0][0]
        num = num / den_poly.coeffs()[0]
        num = sp.expand(num)
        try:
            p = sp.Poly(num, Z)
        except PolynomialError:
            raise AnalysisError("the symbol must be a Laurent polynomial in z") from None
        coeffs = [as_expr(c) for c in reversed(p.all_coeffs())]
        return cls.from_mask(coeffs, start=shift, params=params)

    # ---------------------------------------------------------------- data
    @property
    def poly(self) -> sp.Poly:
        """``z^(-start) a(z)`` as a sympy ``Poly`` in ``z`` (constant term nonzero)."""
        return self._poly

    @property
    def start(self) -> int:
        """The lowest exponent with a nonzero coefficient."""
        return self._start

    @property
    def end(self) -> int:
        """The highest exponent with a nonzero coefficient."""
        return self._start + max(self._poly.degree(), 0)

    @property
    def support(self) -> tuple[int, int]:
        return (self.start, self.end)

    @property
    def params(self) -> tuple[sp.Symbol, ...]:
        return self._params

    @property
    def domain(self):
        return self._poly.domain

    @property
    def is_zero(self) -> bool:
        return self._poly.is_zero

    @property
    def is_numeric(self) -> bool:
        """True when no coefficient depends on a parameter."""
        d = self.domain
        return not (d.is_PolynomialRing or d.is_FractionField)

    @property
    def mask(self) -> tuple:
        """The coefficients ``a_start, ..., a_end`` as sympy expressions (formed once: a tuple of immutable
        expressions)."""
        m = getattr(self, "_mask", None)
        if m is None:
            m = (sp.Integer(0),) if self.is_zero else \
                tuple(self.domain.to_sympy(c) for c in reversed(self._poly.rep.to_list()))
            object.__setattr__(self, "_mask", m)
        return m

    def __len__(self) -> int:
        return 0 if self.is_zero else self.end - self.start + 1

    def coeff(self, i: int) -> sp.Expr:
        """The coefficient ``a_i`` (zero outside the support)."""
        if self.is_zero or i < self.start or i > self.end:
            return sp.Integer(0)
        return self.mask[i - self.start]

    def items(self):
        """Pairs ``(i, a_i)`` over the support (zeros inside included)."""
        return [(self.start + k, c) for k, c in enumerate(self.mask)]

    def expr(self) -> sp.Expr:
        """``a(z)`` as a sympy expression."""
        return sp.Add(*[c * Z**i for i, c in self.items()])

    def __call__(self, z0):
        """Evaluate ``a(z0)`` exactly (``z0`` a number or expression)."""
        z0 = as_expr(z0)
        if z0 == 1 or z0 == -1:
            total = self.domain.zero
            for k, c in enumerate(reversed(self._poly.rep.to_list())):
                total = total + c if (z0 == 1 or (self.start + k) % 2 == 0) else total - c
            return sp.expand(self.domain.to_sympy(total))
        return sp.simplify(self.expr().subs(Z, z0))

    # ---------------------------------------------------------------- algebra
    def _coerce(self, other) -> "LaurentSymbol":
        if isinstance(other, LaurentSymbol):
            return other
        return LaurentSymbol.from_mask([parse_coefficient(other)], 0)

    def _unify(self, other: "LaurentSymbol"):
        dom = self.domain.unify(other.domain)
        params = tuple(sorted(set(self.params) | set(other.params), key=lambda s: s.name))
        return self._poly.set_domain(dom), other._poly.set_domain(dom), params

    def __add__(self, other) -> "LaurentSymbol":
        other = self._coerce(other)
        p, q, params = self._unify(other)
        lo = min(self.start, other.start)
        p = p * sp.Poly(Z**(self.start - lo), Z, domain=p.domain)
        q = q * sp.Poly(Z**(other.start - lo), Z, domain=q.domain)
        return LaurentSymbol(p + q, lo, params)

    __radd__ = __add__

    def __neg__(self) -> "LaurentSymbol":
        return LaurentSymbol(-self._poly, self.start, self.params)

    def __sub__(self, other) -> "LaurentSymbol":
        return self + (-self._coerce(other))

    def __rsub__(self, other) -> "LaurentSymbol":
        return self._coerce(other) - self

    def __mul__(self, other) -> "LaurentSymbol":
        if isinstance(other, (int, sp.Rational)) and not isinstance(other, bool):
            return self._scaled(sp.Rational(other))
        other = self._coerce(other)
        p, q, params = self._unify(other)
        return LaurentSymbol(p * q, self.start + other.start, params)

    __rmul__ = __mul__

    def _scaled(self, c: sp.Rational) -> "LaurentSymbol":
        """``c * self`` for a rational ``c``: the product with the constant symbol ``c`` (domain QQ, as
        :meth:`from_mask` gives it), without building that symbol."""
        dom = self.domain.unify(sp.QQ)
        params = tuple(sorted(set(self.params), key=lambda s: s.name))
        return LaurentSymbol(self._poly.set_domain(dom).mul_ground(dom.from_sympy(c)), self.start, params)

    def __truediv__(self, scalar) -> "LaurentSymbol":
        s = parse_coefficient(scalar)
        if s == 0:
            raise ZeroDivisionError("division of a symbol by zero")
        return self * (1 / s)

    def __pow__(self, n: int) -> "LaurentSymbol":
        if not isinstance(n, int) or n < 0:
            raise ValueError("only non-negative integer powers")
        out = LaurentSymbol.from_mask([1])
        for _ in range(n):
            out = out * self
        return out

    def __eq__(self, other) -> bool:
        if not isinstance(other, LaurentSymbol):
            return NotImplemented
        if self.start != other.start and not (self.is_zero and other.is_zero):
            return False
        p, q, _ = self._unify(other)
        return p == q

    def __hash__(self) -> int:
        if self._hash is None:
            object.__setattr__(self, "_hash", hash((self.start, tuple(self.mask))))
        return self._hash

    def shift(self, s: int) -> "LaurentSymbol":
        """``z^s a(z)``."""
        return LaurentSymbol(self._poly, self.start + s, self.params)

    def reversed(self) -> "LaurentSymbol":
        """``a(1/z)`` — the mirrored scheme."""
        return LaurentSymbol.from_mask(tuple(reversed(self.mask)), start=-self.end, params=self.params,
                                       domain=self.domain)

    def upsample(self, q: int) -> "LaurentSymbol":
        """``a(z^q)``."""
        if q < 1:
            raise ValueError("q must be a positive integer")
        new = {(m[0] * q,): c for m, c in self._poly.rep.to_dict().items()}
        poly = sp.Poly.from_dict(new, Z, domain=self.domain) if new else self._poly
        return LaurentSymbol(poly, self.start * q, self.params)

    def subsymbols(self) -> tuple["LaurentSymbol", "LaurentSymbol"]:
        """``(a_0, a_1)`` with ``a(z) = a_0(z^2) + z a_1(z^2)``: the even and odd sub-symbols.

        ``a_0(1) = a_1(1) = 1`` is the sum-rule condition of convergence.
        """
        parts: list[list] = [[], []]
        for i, c in self.items():
            parts[i % 2].append((i // 2, c))
        out = []
        for r in (0, 1):
            if not parts[r]:
                out.append(LaurentSymbol.from_mask([0], params=self.params, domain=self.domain))
                continue
            lo = parts[r][0][0]
            hi = parts[r][-1][0]
            dense = dict(parts[r])
            out.append(LaurentSymbol.from_mask([dense.get(j, 0) for j in range(lo, hi + 1)], start=lo,
                                               params=self.params, domain=self.domain))
        return out[0], out[1]

    def residue_sums(self, modulus: int = 2) -> list:
        """``[sum_j a_{r + modulus j} for r in range(modulus)]`` (exact)."""
        sums = [sp.Integer(0)] * modulus
        for i, c in self.items():
            sums[i % modulus] += c
        return [sp.expand(s) for s in sums]

    def rules(self) -> Rules:
        """The paper-style even and odd stencils (inverse of :meth:`from_rules`)."""
        even: dict[int, sp.Expr] = {}
        odd: dict[int, sp.Expr] = {}
        for i, c in self.items():
            if i % 2 == 0:
                even[-i // 2] = c
            else:
                odd[(1 - i) // 2] = c

        def dense(d):
            if not d:
                return (), 0
            lo, hi = min(d), max(d)
            return tuple(d.get(p, sp.Integer(0)) for p in range(lo, hi + 1)), lo

        e, ef = dense(even)
        o, of = dense(odd)
        return Rules(e, ef, o, of)

    def subs(self, values: Mapping) -> "LaurentSymbol":
        """Substitute parameter values (exact numbers, strings or expressions).

        >>> w = sp.Symbol("omega")
        >>> LaurentSymbol.from_mask([w, 1 - w]).subs({"omega": "1/3"})
        LaurentSymbol([1/3, 2/3], start=0, domain=QQ)
        """
        by_name = {p.name: p for p in self.params}
        vals: dict[sp.Symbol, sp.Expr] = {}
        for k, v in values.items():
            key = k if isinstance(k, sp.Symbol) else by_name.get(str(k))
            if key is None or key not in self.params:
                known = ", ".join(by_name) or "none"
                raise AnalysisError(f"unknown parameter {str(k)!r} (this symbol's parameters: {known})")
            vals[key] = parse_coefficient(v)
        coeffs = self._at_rationals(vals)
        if coeffs is None:
            coeffs = [sp.expand(c.subs(vals)) for c in self.mask]
        params = tuple(p for p in self.params if p not in vals)
        params = tuple(sorted(set(params) | set(parameter_symbols(coeffs)), key=lambda s: s.name))
        for c in coeffs:
            if c.has(sp.zoo, sp.nan):
                raise AnalysisError("the parameter values make a coefficient infinite")
        return LaurentSymbol.from_mask(coeffs, start=self.start, params=params)

    def _at_rationals(self, vals: dict) -> list | None:
        """The coefficients at rational values of every parameter of a polynomial family over QQ, each
        coefficient evaluated in the polynomial ring (the same exact rationals as substituting and expanding,
        without sympy's expression substitution); None when that does not apply."""
        d = self.domain
        if (self.is_zero or not d.is_PolynomialRing or not d.dom.is_QQ or set(vals) != set(d.symbols)
                or not all(isinstance(v, sp.Rational) for v in vals.values())):
            return None
        point = [d.dom.from_sympy(vals[s]) for s in d.symbols]
        return [d.dom.to_sympy(c(*point)) for c in reversed(self._poly.rep.to_list())]

    def require_numeric(self, what: str = "this computation") -> None:
        """Raise a clear error when parameters are still free."""
        if not self.is_numeric:
            names = ", ".join(p.name for p in self.params)
            raise AnalysisError(f"{what} needs values for the parameter(s) {names} "
                                f"(e.g. --param {self.params[0].name}=1/100)")

    # ---------------------------------------------------------------- printing
    def __repr__(self) -> str:
        coeffs = ", ".join(sp.sstr(c) for c in self.mask)
        return f"LaurentSymbol([{coeffs}], start={self.start}, domain={self.domain})"

    def __str__(self) -> str:
        return self.pretty()

    def pretty(self) -> str:
        """Plain text ``a(z) = ...`` in increasing powers of z."""
        terms = []
        for i, c in self.items():
            if c == 0:
                continue
            cs = sp.sstr(c)
            if isinstance(c, sp.Add):
                cs = f"({cs})"
            zp = "" if i == 0 else ("z" if i == 1 else f"z^{i}" if i > 0 else f"z^({i})")
            terms.append(cs if not zp else (zp if cs == "1" else f"{cs}*{zp}"))
        return " + ".join(terms).replace("+ -", "- ") if terms else "0"

    def latex(self) -> str:
        """LaTeX in increasing powers of z."""
        terms = []
        for i, c in self.items():
            if c == 0:
                continue
            cs = sp.latex(c)
            if isinstance(c, sp.Add):
                cs = rf"\left({cs}\right)"
            zp = "" if i == 0 else ("z" if i == 1 else f"z^{{{i}}}")
            if zp and c == 1:
                terms.append(zp)
            elif zp and c == -1:
                terms.append("-" + zp)
            else:
                terms.append(cs + (" " + zp if zp else ""))
        out = " + ".join(terms) if terms else "0"
        return out.replace("+ -", "- ")

    def _repr_latex_(self) -> str:  # notebooks
        return f"${self.latex()}$"

    def to_json(self) -> dict:
        return {"start": self.start, "mask": [sp.sstr(c) for c in self.mask], "domain": str(self.domain),
                "params": [p.name for p in self.params]}


def one_plus_z() -> LaurentSymbol:
    """``(1+z)``."""
    return LaurentSymbol.from_mask([1, 1])


def half_one_plus_z() -> LaurentSymbol:
    """``(1+z)/2``, the smoothing factor."""
    return LaurentSymbol.from_mask([sp.Rational(1, 2), sp.Rational(1, 2)])
