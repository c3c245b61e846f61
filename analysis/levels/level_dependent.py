"""Level-dependent (non-stationary) binary schemes: masks ``a^n`` as exact expressions in the level.

A :class:`LevelDependentScheme` stores every mask coefficient as a sympy expression in
``h = 2^-n`` (:data:`H`) and the free parameters (``alpha``, ``omega``, ``t``...). Expressions
may be given in the level ``n`` (:data:`N`): ``2**(-n)`` is rewritten as ``h``. From this one
definition the module derives

* the limit symbol ``a = lim a^n`` exactly (a :class:`~analysis.algebra.symbol.LaurentSymbol`),
* the exact Taylor expansion of ``a^n_k - a_k`` in ``h`` and the leading asymptotics
  ``||S_{a^n} - S_a||_inf ~ C 2^{-q n}`` (:func:`leading_asymptotics`),
* ``||S_{a^n} - S_a||_inf`` at any level, in three arithmetics: ``"arb"`` (python-flint ball
  arithmetic: a certified enclosure), ``"mp"`` (mpmath at a precision chosen from the
  cancellation: numerical) and ``"float"`` (float64, only to show what goes wrong),
* a rigorous Taylor model ``g(h) in sum_{j<J} g_j h^j +- M (h/rho)^J / (1 - h/rho)`` of every
  coefficient difference ``g = a^n_k - a_k`` over a parameter box (:func:`taylor_models`), the
  basis of the analytic tail bounds in :mod:`analysis.levels.series` and :mod:`analysis.levels.bounds`.

Convention: ``(S_{a^n} f)_i = sum_j a^n_{i-2j} f_j``; ``a^n(z) = sum_i a^n_i z^i``;
``||S_a||_inf = max_r sum_j |a_{r+2j}|``.

Examples
--------
>>> import sympy as sp
>>> x = sp.Symbol("x", positive=True)
>>> s = LevelDependentScheme.from_rules(
...     even=[sp.sin(3 * x * H / 4) / sp.sin(x * H)], odd=[sp.sin(x * H / 4) / sp.sin(x * H)],
...     first=0, params=(x,), slug="toy")
>>> s.limit()
LaurentSymbol([3/4, 1/4], start=0, domain=QQ)
>>> r = leading_asymptotics(s)
>>> r.value, r.witness["order"], r.witness["rate"]
(7*x**2/128, 2, '7*x**2/128 * 2^(-2n)')
>>> d = distance(s, 60, {"x": 1})                 # certified enclosure at level 60
>>> d.status, float(d.lower) > 0, float((d.upper - d.lower) / d.lower) < 1e-15
('certified', True, True)
>>> float(d.lower) * 4**60                        # -> 7/128 = 0.0546875
0.0546875

Algorithm
---------
The limit and the Taylor coefficients come from ``sympy.series`` in ``h`` (exact; zero tests on
rational functions of the parameters). The Taylor-model remainder is a Cauchy estimate: the
coefficient is rewritten with ``sin(u) = u sinc(u)`` and ``sinh(u) = u sinc(iu)`` (the removable
singularity at ``h = 0`` disappears), the closed disk ``|h| <= rho`` is covered by complex balls
(``acb``) and the expression is evaluated on each; finiteness on every ball proves analyticity
on the disk, and the largest modulus ``M`` gives ``|g_j| <= M rho^-j`` for all ``j``.

Precision and conditioning
--------------------------
``a^n_k - a_k`` is ``O(h^q) = O(2^{-qn})`` while ``a^n_k`` is ``O(1)``: computing the difference
loses ``q n`` bits. ``"arb"`` and ``"mp"`` therefore work at ``64 + q n + 32`` bits by default; in
float64 the difference is pure rounding noise for ``n >~ 26`` (see the tests).

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*,
J. Math. Anal. Appl. 193 (1995) 594-621.
F. Johansson, *Arb: efficient arbitrary-precision midpoint-radius interval arithmetic*,
IEEE Trans. Comput. 66 (2017) 1281-1292.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any, Mapping, Sequence

import flint
import mpmath
import sympy as sp

from ..result import CERTIFIED, NUMERICAL, AnalysisError, Result
from ..algebra.symbol import LaurentSymbol, parse_coefficient
from .balls import (_FUNCS, _ball, _fraction, _to_ball, arb_abs, ball, ball_to_interval,  # noqa: F401
                    workprec)
from ..algebra.reader import as_expr, check_substitution, read_expression, substitute

#: ``h = 2^-n``, the variable of all expansions.
H = sp.Symbol("h", positive=True)
#: the level ``n``.
N = sp.Symbol("n", integer=True, nonnegative=True)

ARITHMETICS = ("arb", "mp", "float")


# --------------------------------------------------------------------------------------------
# expressions in h
# --------------------------------------------------------------------------------------------

def to_h(expr, arity: int = 2) -> sp.Expr:
    """Rewrite an expression in the level ``n`` as one in ``h = m^-n`` (``m`` the arity).

    >>> to_h(sp.sin(3 * sp.Symbol("alpha") / 2 ** (N + 2)))
    sin(3*alpha*h/4)
    >>> to_h("4**(-n) + 1/8**n")                 # bases that are powers of 2
    h**3 + h**2
    >>> to_h(sp.cos(sp.Symbol("theta") / 3 ** (N + 1)), 3)
    cos(h*theta/3)
    """
    m = arity
    if isinstance(expr, str):
        e = parse_coefficient(expr, locals_={"n": N, "h": H})
    else:
        e = as_expr(expr)
    e = e.subs(sp.Symbol("n"), N).subs(sp.Symbol("h", positive=True), H)
    if m == 2:
        e = e.replace(_power_of_two_base, lambda p: sp.Pow(2, (int(p.base).bit_length() - 1) * p.exp))  # 4**-n = 2**-2n
    e = e.subs(sp.Integer(m) ** N, 1 / H)
    if N in e.free_symbols:
        e = sp.powsimp(sp.expand_power_exp(e)).subs(sp.Integer(m) ** N, 1 / H)
    if N in e.free_symbols:
        raise AnalysisError(f"cannot write {expr} as a function of h = {m}^-n "
                            f"(the level must enter only through {m}^n)")
    return e


def _power_of_two_base(p) -> bool:
    """``b**e`` with ``b = 4, 8, 16, ...`` and the level in ``e`` (rewritten as ``2**(log2(b) e)``)."""
    return (isinstance(p, sp.Pow) and p.base.is_Integer and p.base > 2 and int(p.base) & (int(p.base) - 1) == 0
            and N in p.exp.free_symbols)


def _negative_h_power(c: sp.Expr) -> bool:
    return any(q.base == H and q.exp.is_negative for q in c.atoms(sp.Pow))


def entire_form(expr: sp.Expr) -> sp.Expr:
    """``sin(u) -> u sinc(u)``, ``sinh(u) -> u sinc(iu)``: removes the removable singularity at h=0.

    >>> a = sp.Symbol("alpha", positive=True)
    >>> entire_form(sp.sin(3 * a * H / 4) / sp.sin(a * H))
    3*sinc(3*alpha*h/4)/(4*sinc(alpha*h))
    """
    return _entire_form(as_expr(expr))


@lru_cache(maxsize=4096)
def _entire_form(e: sp.Expr) -> sp.Expr:
    """:func:`entire_form` of an expression (a pure function of it, remembered: the level loops ask again)."""
    return e.replace(sp.sin, lambda u: u * sp.sinc(u)).replace(sp.sinh, lambda u: u * sp.sinc(sp.I * u))


@lru_cache(maxsize=4096)
def _simplified_difference(c: sp.Expr, c0: sp.Expr) -> sp.Expr:
    """``simplify(c - c0)`` (a pure function of the pair, remembered)."""
    return sp.simplify(c - c0)


_Z = sp.Symbol("z")
_GROWING = ("the support of a^n grows with the level n (a power of z depends on n): such a scheme has no "
            "stationary limit with the same support")
_RESERVED = {"n", "h", "z", "I", "E", "pi", "oo", "nan", "zoo"}


def _grows(e: sp.Expr) -> bool:
    return any(p.base.has(_Z) and p.exp.has(N) for p in e.atoms(sp.Pow))


def _read(text, defs: Mapping, what: str) -> sp.Expr:
    loc = {"n": N, "z": _Z, **{k.name: k for k in defs}}
    if isinstance(text, str):
        e = read_expression(text, names=loc, what=f"the {what}")
    else:
        e = as_expr(text).subs({sp.Symbol("n"): N})
    if not isinstance(e, sp.Expr) or e.has(sp.zoo, sp.nan, sp.oo):
        raise AnalysisError(f"the {what} {text!r} is not a finite formula")
    return e


def resolve_where(where) -> dict:
    """Helper definitions ``NAME=EXPR`` resolved to expressions in ``n`` and the parameters.

    ``where`` is a mapping ``name -> expr`` or a sequence of ``"NAME=EXPR"`` strings (or pairs).
    A definition may use ``n``, parameters and other names, in any order; a name used in its own
    definition, directly or through others, is a cycle (:class:`AnalysisError`). Names that are
    not defined stay free (parameters).

    >>> resolve_where(["s=sin(x)", "c=sqrt(1-s**2)"])
    {s: sin(x), c: sqrt(1 - sin(x)**2)}
    >>> resolve_where(["a=b+1", "b=2*a"])
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: cycle in the --where definitions: a -> b -> a
    """
    if not where:
        return {}
    items = list(where.items()) if isinstance(where, Mapping) else []
    if not isinstance(where, Mapping):
        for it in where:
            if isinstance(it, str):
                if "=" not in it:
                    raise AnalysisError(f"malformed --where {it!r}: use NAME=EXPR, e.g. c=cos(theta/2**(n+1))")
                it = it.split("=", 1)
            items.append((str(it[0]).strip(), it[1]))
    syms: dict[str, sp.Symbol] = {}
    for name, _ in items:
        name = str(name).strip()
        if not name.isidentifier() or name in _RESERVED:
            raise AnalysisError(f"--where: {name!r} cannot be defined (a name like c or v_n, not n, z, h, I, E, pi)")
        if name in syms:
            raise AnalysisError(f"--where: {name} is defined twice")
        syms[name] = sp.Symbol(name)
    raw = {syms[str(k).strip()]: _read(v, syms.values(), f"definition of {k}") for k, v in items}
    done: dict = {}

    def visit(s, path):
        if s in done:
            return done[s]
        if s in path:
            cyc = path[path.index(s):] + [s]
            raise AnalysisError("cycle in the --where definitions: " + " -> ".join(x.name for x in cyc))
        e = raw[s]
        e = substitute(e, {d: visit(d, path + [s]) for d in e.free_symbols if d in raw},
                       what=f"--where {s.name}")
        done[s] = e
        return e

    for s in raw:
        visit(s, [])
    return {s: done[s] for s in raw}


# --------------------------------------------------------------------------------------------
# the scheme
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class LevelDependentScheme:
    """A level-dependent scheme ``{S_{a^n}}`` of arity ``m`` (``(S_{a^n} f)_i = sum_j a^n_{i-mj} f_j``), mask
    coefficients exact in ``h = m^-n`` (``2^-n`` for binary schemes, the default).

    Attributes
    ----------
    mask : tuple of sympy expressions
        ``mask[k]`` is the coefficient of ``z^(start + k)`` in ``a^n(z)``, a function of ``h``
        (:data:`H`) and ``params``.
    start : int
        The lowest exponent.
    params : tuple of sympy.Symbol
        Free parameters (declare them ``positive=True`` when they are).
    arity : int
        The dilation ``m >= 2``, read by every analysis (``h = m^-n``, ``m`` residue classes, weights ``m^{kn}``).
    """

    mask: tuple
    start: int
    params: tuple = ()
    slug: str = "level-dependent"
    title: str = ""
    source: str = ""
    notes: str = ""
    defaults: Mapping[str, Any] = field(default_factory=dict, hash=False, compare=False)
    arity: int = 2

    def __post_init__(self) -> None:
        from ..algebra.factorization import check_arity
        object.__setattr__(self, "arity", check_arity(self.arity))
        mask = tuple(to_h(c, self.arity) for c in self.mask)
        if not mask:
            raise AnalysisError("the mask is empty")
        object.__setattr__(self, "mask", mask)
        free = set().union(*(c.free_symbols for c in mask)) - {H}
        params = tuple(self.params)
        names = {p.name for p in params}
        unknown = {s.name for s in free} - names
        if unknown:
            raise AnalysisError(f"unknown parameter(s) in the mask: {', '.join(sorted(unknown))}")
        object.__setattr__(self, "params", tuple(p for p in params if p in free))

    # ---------------------------------------------------------------- constructors
    @classmethod
    def from_rules(cls, even: Sequence, odd: Sequence, first: int = 0, *,
                   params: Sequence[sp.Symbol] = (), **kw) -> "LevelDependentScheme":
        """``f[2i] = sum_p even_p f[i+first+p]``, ``f[2i+1] = sum_p odd_p f[i+first+p]``.

        The even coefficient of ``f[i+p]`` is ``a_{-2p}``, the odd one ``a_{1-2p}`` (as
        :meth:`analysis.algebra.symbol.LaurentSymbol.from_rules`).
        """
        entries: dict[int, sp.Expr] = {}
        for k, c in enumerate(even):
            entries[-2 * (first + k)] = as_expr(c)
        for k, c in enumerate(odd):
            entries[1 - 2 * (first + k)] = as_expr(c)
        lo, hi = min(entries), max(entries)
        return cls(tuple(entries.get(i, sp.Integer(0)) for i in range(lo, hi + 1)), lo,
                   tuple(params), **kw)

    @classmethod
    def from_symbol(cls, expr, *, where=None, params: Sequence[sp.Symbol] | None = None,
                    **kw) -> "LevelDependentScheme":
        """The scheme of a symbol ``a^n(z)`` given as a string or sympy expression in ``z`` and ``n``.

        ``where``: helper definitions ``NAME -> EXPR`` (a mapping, or ``"NAME=EXPR"`` strings) that
        may use ``n``, parameters and each other (:func:`resolve_where`). Every other free symbol
        is a parameter.

        >>> e = LevelDependentScheme.from_symbol("(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2",
        ...                                      where={"c": "cos(theta/2**(n+1))"})
        >>> e.params, e.limit()
        ((theta,), LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ))
        """
        defs = resolve_where(where)
        e = _read(expr, defs, "symbol")
        check_substitution(e, defs, what="the symbol")
        num, den = sp.fraction(sp.together(e))
        try:
            dp, np_ = sp.Poly(den, _Z), sp.Poly(num, _Z)
        except sp.PolynomialError:
            raise AnalysisError(_GROWING if e.has(_Z) and _grows(e) else
                                "the symbol must be a Laurent polynomial in z") from None
        if len(dp.terms()) != 1:
            raise AnalysisError("the symbol must be a Laurent polynomial in z (only powers of z may divide)")
        shift, dc = -dp.monoms()[0][0], dp.coeffs()[0]
        coeffs = [sp.cancel(c / dc) for c in reversed(np_.all_coeffs())]
        return cls._build(coeffs, shift, defs, params, kw)

    @classmethod
    def from_mask(cls, coeffs: Sequence, start: int = 0, *, where=None,
                  params: Sequence[sp.Symbol] | None = None, **kw) -> "LevelDependentScheme":
        """The scheme with ``a^n_{start+k} = coeffs[k]`` (strings or sympy, may use ``n`` and ``where`` names).

        >>> LevelDependentScheme.from_mask(["1/4", "3/4 - 2**(-n)", "3/4 + 2**(-n)", "1/4"], -2).mask[1]
        3/4 - h
        """
        defs = resolve_where(where)
        return cls._build([_read(c, defs, "coefficient") for c in coeffs], start, defs, params, kw)

    @classmethod
    def _build(cls, coeffs, start, defs, params, kw) -> "LevelDependentScheme":
        coeffs = [to_h(substitute(as_expr(c), defs, what="a coefficient"), kw.get("arity", 2)) for c in coeffs]
        # h (2 + 1/h) -> 2h + 1; (cos(h) + 4/h^3)/(16/h^3) -> (h^3 cos(h) + 4)/16: no negative power of h is left
        coeffs = [sp.cancel(c) if c.is_rational_function(H) or _negative_h_power(c) else c for c in coeffs]
        while len(coeffs) > 1 and coeffs[-1] == 0:
            coeffs.pop()
        while len(coeffs) > 1 and coeffs[0] == 0:
            coeffs.pop(0)
            start += 1
        if params is None:
            free = set().union(*(c.free_symbols for c in coeffs)) - {N, H, sp.Symbol("n"), sp.Symbol("h")}
            params = tuple(sp.Symbol(x.name, real=True) for x in sorted(free, key=lambda x: x.name))
            coeffs = [c.subs({sp.Symbol(p.name): p for p in params}) for c in coeffs]
        return cls(tuple(coeffs), int(start), tuple(params), **kw)

    # ---------------------------------------------------------------- data
    @property
    def end(self) -> int:
        return self.start + len(self.mask) - 1

    @property
    def param_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.params)

    def mask_in_n(self) -> tuple:
        """The coefficients as functions of the level ``n`` (``h = m^-n``)."""
        return tuple(c.subs(H, sp.Integer(self.arity) ** (-N)) for c in self.mask)

    def symbol_expr(self) -> sp.Expr:
        """``a^n(z)`` as a sympy expression in ``z`` and ``h``."""
        z = sp.Symbol("z")
        return sum(c * z ** (self.start + k) for k, c in enumerate(self.mask))

    def _param(self, name: str) -> sp.Symbol:
        for p in self.params:
            if p.name == name:
                return p
        known = ", ".join(self.param_names) or "none"
        raise AnalysisError(f"scheme {self.slug!r} has no parameter {name} (its parameters: {known})")

    def subs(self, values: Mapping[str, Any]) -> "LevelDependentScheme":
        """The scheme with exact parameter values substituted (names as keys)."""
        rep = {self._param(str(k)): parse_coefficient(v) if isinstance(v, str) else as_expr(v)
               for k, v in dict(values).items()}
        return LevelDependentScheme(tuple(c.subs(rep) for c in self.mask), self.start,
                                    tuple(p for p in self.params if p not in rep), slug=self.slug,
                                    title=self.title, source=self.source, notes=self.notes, arity=self.arity)

    def mask_at(self, n: int, values: Mapping[str, Any] | None = None) -> list[sp.Expr]:
        """The exact coefficients of ``a^n`` at level ``n`` (sympy expressions)."""
        s = self.subs(values) if values else self
        return [c.subs(H, sp.Rational(1, self.arity ** int(n))) for c in s.mask]

    # ---------------------------------------------------------------- limit and expansion
    @cached_property
    def _limits(self) -> tuple:
        return _limits_of(self.mask)

    def limit(self) -> LaurentSymbol:
        """The limit symbol ``a = lim_{n->oo} a^n`` (exact).

        Raises :class:`AnalysisError` when a coefficient has no finite limit.
        """
        return LaurentSymbol.from_mask(list(self._limits), start=self.start,
                                       params=tuple(p for p in self.params
                                                    if any(p in c.free_symbols for c in self._limits)))

    def taylor(self, J: int) -> tuple[tuple[sp.Expr, ...], ...]:
        """Exact Taylor coefficients ``g_{k,j}``, ``j = 0..J-1``, of ``g_k(h) = a^n_k - a_k``.

        ``g_{k,0} = 0`` always.
        """
        cache = self.__dict__.setdefault("_taylor_cache", {})
        if J in cache:
            return cache[J]
        longer = [Jc for Jc in cache if Jc > J]
        if longer:                          # the same series, truncated (no new sympy.series)
            return tuple(r[:J] for r in cache[min(longer)])
        cache[J] = _taylor_by_series(self.mask, self._limits, J)
        return cache[J]

    def order(self, J_max: int = 8) -> int:
        """The leading order ``q``: ``a^n - a = O(h^q)``, exactly (generic in the parameters)."""
        if all(H not in c.free_symbols for c in self.mask):
            raise AnalysisError("the scheme is stationary: a^n - a = 0")
        rows = self.taylor(J_max)
        for j in range(1, J_max):
            if any(r[j] != 0 for r in rows):
                return j
        raise AnalysisError(f"a^n - a vanishes to order h^{J_max} in every coefficient; "
                            "raise J_max")

    # ---------------------------------------------------------------- derived schemes
    def difference(self, k: int = 1, *, spelling: str = "divided") -> "LevelDependentScheme":
        """The k-th difference scheme ``(2/(1+z))^k a^n`` ("divided") or ``(2z/(1+z))^k a^n``.

        The remainder of each division, ``a^n(-1)``, must simplify to 0 exactly (else an
        :class:`AnalysisError`). Arity ``m > 2``: :func:`analysis.levels.divided.divided_difference`.
        """
        if self.arity != 2:
            raise AnalysisError(f"arity {self.arity}: use analysis.levels.divided.divided_difference(s, {k})")
        if spelling not in ("divided", "paper"):
            raise AnalysisError(f"unknown spelling {spelling!r}; use 'divided' or 'paper'")
        return _binary_difference(self, k, spelling)

    def normalized(self) -> "LevelDependentScheme":
        """The scheme divided by its (common) even/odd sum, so that constants are reproduced.

        The even and odd sums must agree exactly (checked).
        """
        ev = sum(c for i, c in enumerate(self.mask) if (self.start + i) % 2 == 0)
        od = sum(c for i, c in enumerate(self.mask) if (self.start + i) % 2 == 1)
        if sp.simplify((ev - od).rewrite(sp.exp)) != 0:
            raise AnalysisError("the even and odd sums differ: no normalization makes a^n(-1) = 0")
        return LevelDependentScheme(tuple(c / ev for c in self.mask), self.start, self.params,
                                    slug=f"{self.slug}-normalized", title=f"normalized {self.title}",
                                    source=self.source)

    def stencil_sum(self) -> sp.Expr:
        """The sum of the even stencil, ``sum_j a^n_{2j}`` (exact expression in h)."""
        return sum(c for i, c in enumerate(self.mask) if (self.start + i) % 2 == 0)


# pure functions of a scheme or of its mask, remembered (bounded): the C^k routes, the weighted series and the
# tests ask for the same limits, expansions and difference schemes again, on equal schemes built anew

@lru_cache(maxsize=512)
def _limits_of(mask: tuple) -> tuple:
    """The limits ``a_k = lim_{h -> 0} a^n_k`` of the coefficients (exact; :class:`AnalysisError` when one is not finite)."""
    out, done = [], {}                      # a symmetric mask repeats its coefficients: one limit each
    for c in mask:
        if H not in c.free_symbols:
            out.append(sp.simplify(c))
            continue
        if c not in done:
            c0 = sp.simplify(sp.limit(c, H, 0, "+"))
            if c0.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or isinstance(c0, sp.Limit):
                raise AnalysisError(f"the coefficient {c} has no finite limit as n -> oo")
            done[c] = c0
        out.append(done[c])
    return tuple(out)


@lru_cache(maxsize=512)
def _taylor_by_series(mask: tuple, limits: tuple, J: int) -> tuple:
    """:meth:`LevelDependentScheme.taylor` by ``sympy.series``: ``g_{k,j}``, ``j < J``, of ``a^n_k - a_k``."""
    rows, done = [], {}                     # a symmetric mask repeats its differences: one series each
    for c, c0 in zip(mask, limits):
        g = c - c0
        if H not in g.free_symbols:
            rows.append(tuple(sp.Integer(0) for _ in range(J)))
            continue
        if g not in done:
            from .hseries import taylor_polynomial

            ser = taylor_polynomial(g, J)       # the same polynomial by series arithmetic, or None
            if ser is None:
                ser = sp.expand(sp.series(g, H, 0, J).removeO())
            done[g] = tuple(sp.factor(sp.simplify(ser.coeff(H, j))) for j in range(J))
        rows.append(done[g])
    return tuple(rows)


def _zero_as_rational_in_exp(e: sp.Expr) -> bool:
    """True when ``e`` rewritten in ``exp`` cancels to 0 as a rational function of its atoms (a proof that ``e = 0``,
    cheaper than ``simplify``); False means nothing."""
    try:
        return sp.cancel(sp.together(e.rewrite(sp.exp))) == 0
    except Exception:  # noqa: BLE001 - a failed cancellation is not a proof either way
        return False


@lru_cache(maxsize=256)
def _binary_difference(s: LevelDependentScheme, k: int, spelling: str) -> LevelDependentScheme:
    """:meth:`LevelDependentScheme.difference` of a binary scheme (a failed division raises each time)."""
    coeffs = list(s.mask)
    for _ in range(k):
        q: list[sp.Expr] = []
        rem = sp.Integer(0)
        for c in coeffs[:-1]:
            rem = c - rem
            q.append(rem)
        last = coeffs[-1] - rem
        if not _zero_as_rational_in_exp(last) and sp.simplify(last.rewrite(sp.exp)) != 0:
            raise AnalysisError("(1+z) does not divide a^n(z) identically in n "
                                f"(a^n(-1) = {sp.simplify(last)})")
        coeffs = [2 * c for c in q]
    start = s.start + (k if spelling == "paper" else 0)
    return LevelDependentScheme(tuple(coeffs), start, s.params,
                                slug=f"{s.slug}-diff{k}", title=f"{k}-th difference of {s.title}",
                                source=s.source)


# --------------------------------------------------------------------------------------------
# leading asymptotics of ||S_{a^n} - S_a||
# --------------------------------------------------------------------------------------------

def _residue_groups(s: LevelDependentScheme, arity: int = 2) -> dict[int, list[int]]:
    """The mask indices ``k`` by the residue class ``(start + k) mod arity`` (the rows of ``S_{a^n}``)."""
    groups: dict[int, list[int]] = {r: [] for r in range(arity)}
    for k in range(len(s.mask)):
        groups[(s.start + k) % arity].append(k)
    return groups


def leading_asymptotics(s: LevelDependentScheme, arity: int | None = None) -> Result:
    """``||S_{a^n} - S_a||_inf = C 2^{-q n} + O(2^{-(q+1) n})``: the exact ``C`` and ``q``.

    ``C = max_r sum_{k = r mod 2} |g_{k,q}|`` with ``g_{k,q}`` the exact ``h^q`` Taylor
    coefficient of ``a^n_k - a_k``. Certified (exact series); where ``C`` vanishes for special
    parameter values the order there is higher (``witness["per_residue"]`` shows the pieces).
    """
    arity = s.arity if arity is None else arity
    q = s.order()
    rows = s.taylor(q + 1)
    per_res = {}
    for r, ks in _residue_groups(s, arity).items():
        per_res[r] = sp.simplify(sum(sp.Abs(rows[k][q]) for k in ks))
    vals = list(per_res.values())
    C = vals[0] if all(sp.simplify(vals[0] - v) == 0 for v in vals[1:]) else sp.Max(*vals)
    return Result(value=C, status=CERTIFIED,
                  witness={"order": q, "rate": f"{sp.sstr(C)} * {arity}^(-{q}n)", "per_residue": per_res,
                           "leading_coefficients": {s.start + k: rows[k][q] for k in range(len(rows))
                                                    if rows[k][q] != 0}},
                  provenance={"method": "exact sympy series in h = 2^-n", "scheme": s.slug})


# --------------------------------------------------------------------------------------------
# ||S_{a^n} - S_a|| at a level
# --------------------------------------------------------------------------------------------

def level_precision(q: int, n: int, arity: int = 2, target_bits: int = 64) -> int:
    """Working precision for level n of an arity-m scheme with leading order q: ``target + q n log2(m) + 32``.

    >>> level_precision(2, 10), level_precision(2, 10, 3)
    (116, 127)
    """
    return int(target_bits + q * n + 32) if arity == 2 else int(target_bits + q * n * math.log2(arity) + 32)


def default_precision(s: LevelDependentScheme, n: int, target_bits: int = 64, *, arity: int | None = None) -> int:
    """Working precision for level n: ``target + q n log2(m) + 32`` bits (q = the leading order, m the arity)."""
    arity = s.arity if arity is None else arity
    try:
        q = s.order()
    except AnalysisError:
        q = 0
    return level_precision(q, n, arity, target_bits)


def level_h(n: int, arity: int = 2):
    """``h_n = m^-n`` as an Arb ball (exact for m = 2; at the working precision otherwise)."""
    return flint.arb(2) ** (-int(n)) if arity == 2 else flint.arb(1) / flint.arb(arity) ** int(n)


def _env_values(s: LevelDependentScheme, values: Mapping[str, Any] | None) -> dict:
    values = dict(values or {})
    out = {}
    for k, v in values.items():
        s._param(str(k))
        out[str(k)] = parse_coefficient(v) if isinstance(v, str) else v
    missing = set(s.param_names) - set(out)
    if missing:
        raise AnalysisError(f"give a value for {', '.join(sorted(missing))} (--param NAME=VALUE)")
    return out


def coefficient_differences(s: LevelDependentScheme, n: int, values=None, *, prec: int | None = None,
                            arity: int | None = None):
    """Arb enclosures of ``a^n_k - a_k`` for every k (``h = m^-n``, m = ``arity``; params exact or boxes)."""
    arity = s.arity if arity is None else arity
    env = _env_values(s, values)
    prec = prec or default_precision(s, n, arity=arity)
    key = _env_key(env)
    if key is None:
        return list(_coefficient_differences.__wrapped__(s.mask, s._limits, tuple(env.items()), n, prec, arity))
    return list(_coefficient_differences(s.mask, s._limits, key, n, prec, arity))


def _env_key(env: Mapping) -> tuple | None:
    """``env`` as a hashable key (exact sympy values and boxes, no Float), or ``None``."""
    items = []
    for k, v in sorted(env.items()):
        for x in (v if isinstance(v, tuple) else (v,)):
            if not isinstance(x, sp.Basic) or x.atoms(sp.Float):
                return None
        items.append((k, v))
    return tuple(items)


@lru_cache(maxsize=4096)
def _coefficient_differences(mask: tuple, limits: tuple, env: tuple, n: int, prec: int, arity: int) -> tuple:
    """:func:`coefficient_differences` (a pure function of its arguments, remembered: the weighted series and the
    support test enclose the same levels)."""
    with workprec(prec):
        envb = {k: _to_ball(v, False) for k, v in env}
        envb["h"] = level_h(n, arity)
        out = []
        for c, c0 in zip(mask, limits):
            # the entire form (sinc) avoids the dependency problem of sin(u)/sin(v) over boxes
            out.append(_ball(entire_form(c), envb, False) - _ball(c0, envb, False)
                       if H in c.free_symbols else _ball(_simplified_difference(c, c0), envb, False))
    return tuple(out)


def distance(s: LevelDependentScheme, n: int, values: Mapping[str, Any] | None = None, *,
             arithmetic: str = "arb", prec: int | None = None, arity: int | None = None) -> Result:
    """``||S_{a^n} - S_a||_inf`` at level ``n`` (``arity`` m: ``h = m^-n``, m residue classes).

    ``arithmetic="arb"``: a certified enclosure ``[lower, upper]`` (exact rationals) from ball
    arithmetic at ``prec`` bits (default :func:`default_precision`); parameter values may be
    exact numbers or ``(lo, hi)`` boxes. ``"mp"``: mpmath at ``prec`` bits, numerical.
    ``"float"``: float64, numerical, and wrong at large n (cancellation).
    """
    arity = s.arity if arity is None else arity
    if arithmetic not in ARITHMETICS:
        raise AnalysisError(f"unknown arithmetic {arithmetic!r}; use one of {', '.join(ARITHMETICS)}")
    if not isinstance(n, int) or n < 0:
        raise AnalysisError(f"the level must be a non-negative integer, not {n!r}")
    groups = _residue_groups(s, arity)
    prec = prec or default_precision(s, n, arity=arity)
    prov = {"level": n, "scheme": s.slug, "arithmetic": arithmetic}
    if arithmetic == "arb":
        diffs = coefficient_differences(s, n, values, prec=prec, arity=arity)
        with workprec(prec):
            sums = [sum((arb_abs(diffs[k]) for k in ks), flint.arb(0)) for ks in groups.values()]
            best = sums[0]
            for x in sums[1:]:
                best = best.max(x)
        lo, hi = ball_to_interval(best)
        lo = max(lo, sp.Integer(0))
        return Result(lower=lo, upper=hi, status=CERTIFIED,
                      witness={"residue_sums": [ball_to_interval(x) for x in sums]},
                      provenance={**prov, "precision_bits": prec,
                                  "method": f"arb ball arithmetic, h = {arity}^-n exact"})
    env = _env_values(s, values)
    syms = [H] + list(s.params)
    diffs_expr = [c - c0 for c, c0 in zip(s.mask, s._limits)]
    if arithmetic == "mp":
        with mpmath.workprec(prec):
            f = sp.lambdify(syms, diffs_expr, "mpmath")
            args = [mpmath.mpf(arity) ** (-n)] + [mpmath.mpmathify(sp.N(env[p.name], prec // 3 + 20))
                                              for p in s.params]
            d = f(*args)
            val = max(sum(abs(d[k]) for k in ks) for ks in groups.values())
            value = sp.Float(val, prec // 3)
        return Result(value=value, status=NUMERICAL,
                      provenance={**prov, "precision_bits": prec, "method": "mpmath"})
    f = sp.lambdify(syms, diffs_expr, "math")
    d = f(float(arity) ** (-n), *[float(env[p.name]) for p in s.params])
    val = max(sum(abs(d[k]) for k in ks) for ks in groups.values())
    return Result(value=float(val), status=NUMERICAL, provenance={**prov, "method": "float64"})


def distance_table(s: LevelDependentScheme, values=None, n_max: int = 200, *,
                   arithmetic: str = "arb") -> list[Result]:
    """:func:`distance` for ``n = 0..n_max`` (precision chosen per level)."""
    return [distance(s, n, values, arithmetic=arithmetic) for n in range(n_max + 1)]
