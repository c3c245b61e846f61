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
from fractions import Fraction
from functools import cached_property
from typing import Any, Mapping, Sequence

import flint
import mpmath
import sympy as sp

from ..result import CERTIFIED, NUMERICAL, AnalysisError, Result
from ..algebra.symbol import LaurentSymbol, parse_coefficient

#: ``h = 2^-n``, the variable of all expansions.
H = sp.Symbol("h", positive=True)
#: the level ``n``.
N = sp.Symbol("n", integer=True, nonnegative=True)

ARITHMETICS = ("arb", "mp", "float")


# --------------------------------------------------------------------------------------------
# expressions in h
# --------------------------------------------------------------------------------------------

def to_h(expr) -> sp.Expr:
    """Rewrite an expression in the level ``n`` as one in ``h = 2^-n``.

    >>> to_h(sp.sin(3 * sp.Symbol("alpha") / 2 ** (N + 2)))
    sin(3*alpha*h/4)
    """
    e = sp.sympify(expr)
    if isinstance(expr, str):
        e = parse_coefficient(expr, locals_={"n": N, "h": H})
    e = e.subs(sp.Symbol("n"), N).subs(sp.Symbol("h", positive=True), H)
    e = e.subs(2 ** N, 1 / H)
    if N in e.free_symbols:
        e = sp.powsimp(sp.expand_power_exp(e)).subs(2 ** N, 1 / H)
    if N in e.free_symbols:
        raise AnalysisError(f"cannot write {expr} as a function of h = 2^-n "
                            "(the level must enter only through 2^n)")
    return e


def entire_form(expr: sp.Expr) -> sp.Expr:
    """``sin(u) -> u sinc(u)``, ``sinh(u) -> u sinc(iu)``: removes the removable singularity at h=0.

    >>> a = sp.Symbol("alpha", positive=True)
    >>> entire_form(sp.sin(3 * a * H / 4) / sp.sin(a * H))
    3*sinc(3*alpha*h/4)/(4*sinc(alpha*h))
    """
    return sp.sympify(expr).replace(sp.sin, lambda u: u * sp.sinc(u)).replace(
        sp.sinh, lambda u: u * sp.sinc(sp.I * u))


# --------------------------------------------------------------------------------------------
# ball evaluation (python-flint arb/acb): rigorous
# --------------------------------------------------------------------------------------------

class workprec:
    """Context manager: python-flint working precision in bits (like ``mpmath.workprec``)."""

    def __init__(self, bits: int):
        self.bits = int(bits)

    def __enter__(self):
        self._old = flint.ctx.prec
        flint.ctx.prec = self.bits
        return self

    def __exit__(self, *exc):
        flint.ctx.prec = self._old


_FUNCS = {"sin": "sin", "cos": "cos", "sinh": "sinh", "cosh": "cosh", "tan": "tan", "tanh": "tanh",
          "exp": "exp", "log": "log", "sinc": "sinc", "sqrt": "sqrt", "sec": "sec", "csc": "csc",
          "cot": "cot", "coth": "coth", "sech": "sech", "csch": "csch"}


def ball(expr, env: Mapping[str, Any] | None = None, *, complex_: bool = False):
    """A rigorous ``arb`` (or ``acb``) enclosure of a sympy expression.

    ``env`` maps parameter names to arb/acb balls or exact sympy numbers (or ``(lo, hi)``
    pairs: the ball covering that interval). Use inside :class:`workprec`.

    >>> with workprec(80):
    ...     b = ball(sp.sin(sp.pi / 6) - sp.Rational(1, 2))
    >>> b.contains(0)
    True
    """
    env = dict(env or {})
    cenv = {k: _to_ball(v, complex_) for k, v in env.items()}
    return _ball(sp.sympify(expr), cenv, complex_)


def _to_ball(v, complex_: bool):
    if isinstance(v, (flint.arb, flint.acb)):
        return flint.acb(v) if complex_ and isinstance(v, flint.arb) else v
    if isinstance(v, tuple) and len(v) == 2:
        lo, hi = (_ball(sp.sympify(x), {}, False) for x in v)
        b = lo.union(hi)
        return flint.acb(b) if complex_ else b
    return _ball(sp.sympify(v), {}, complex_)


def _ball(e: sp.Expr, env, cx: bool):
    T = flint.acb if cx else flint.arb
    if e.is_Integer:
        return T(int(e))
    if e.is_Rational:
        return T(int(e.p)) / int(e.q)
    if e is sp.pi:
        return T(flint.arb.pi())
    if e is sp.E:
        return T(flint.arb(1).exp())
    if e is sp.I:
        if not cx:
            raise AnalysisError("the expression is complex: evaluate with complex_=True")
        return flint.acb(0, 1)
    if isinstance(e, sp.Float):
        return T(flint.arb(mpmath.mpf(e)))
    if e.is_Symbol:
        try:
            return env[e.name]
        except KeyError:
            raise AnalysisError(f"no value for the parameter {e.name}") from None
    if e.is_Add:
        out = T(0)
        for t in e.args:
            out = out + _ball(t, env, cx)
        return out
    if e.is_Mul:
        out = T(1)
        for t in e.args:
            out = out * _ball(t, env, cx)
        return out
    if e.is_Pow:
        b, x = e.args
        if x.is_Integer:
            bb = _ball(b, env, cx)
            k = int(x)
            return bb ** k if k >= 0 else 1 / bb ** (-k)
        if x == sp.Rational(1, 2):
            return _ball(b, env, cx).sqrt()
        return (_ball(x, env, cx) * _ball(b, env, cx).log()).exp()
    if isinstance(e, sp.Abs):
        v = _ball(e.args[0], env, cx)
        return abs(v)
    name = type(e).__name__
    if name == "sinc" and not cx and e.args[0].has(sp.I):
        # real sinc(i v) = sinh(v)/v, even and increasing in |v|: enclose by its values at the ends
        v = _ball(sp.expand(e.args[0] / sp.I), env, False)
        lo, hi = flint.arb(v.abs_lower()), flint.arb(v.abs_upper())
        f = [flint.arb(1) if x == 0 else x.sinh() / x for x in (lo, hi)]
        return f[0].union(f[1])
    if name in _FUNCS and len(e.args) == 1:
        return getattr(_ball(e.args[0], env, cx), _FUNCS[name])()
    raise AnalysisError(f"cannot evaluate {name} in ball arithmetic")


def arb_abs(x):
    """``|x|`` for an arb ball, with lower end clipped at 0 (arb's ``abs`` may dip below 0)."""
    if x.contains(0):
        return flint.arb(0).union(flint.arb(x.abs_upper()))
    return abs(x)


def ball_to_interval(b) -> tuple[sp.Rational, sp.Rational]:
    """The exact rational endpoints ``(mid - rad, mid + rad)`` of an arb ball."""
    if not b.is_finite():
        raise AnalysisError("the enclosure is not finite (a pole or a too wide parameter box)")
    m, e = b.mid().man_exp()
    r, f = b.rad().man_exp()
    mid = sp.Rational(int(m)) * sp.Rational(2) ** int(e)
    rad = sp.Rational(int(r)) * sp.Rational(2) ** int(f)
    return mid - rad, mid + rad


def _fraction(x: sp.Rational) -> Fraction:
    return Fraction(int(x.p), int(x.q))


# --------------------------------------------------------------------------------------------
# the scheme
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class LevelDependentScheme:
    """A binary level-dependent scheme ``{S_{a^n}}``, mask coefficients exact in ``h = 2^-n``.

    Attributes
    ----------
    mask : tuple of sympy expressions
        ``mask[k]`` is the coefficient of ``z^(start + k)`` in ``a^n(z)``, a function of ``h``
        (:data:`H`) and ``params``.
    start : int
        The lowest exponent.
    params : tuple of sympy.Symbol
        Free parameters (declare them ``positive=True`` when they are).
    """

    mask: tuple
    start: int
    params: tuple = ()
    slug: str = "level-dependent"
    title: str = ""
    source: str = ""
    notes: str = ""
    defaults: Mapping[str, Any] = field(default_factory=dict, hash=False, compare=False)

    def __post_init__(self) -> None:
        mask = tuple(to_h(c) for c in self.mask)
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
            entries[-2 * (first + k)] = sp.sympify(c)
        for k, c in enumerate(odd):
            entries[1 - 2 * (first + k)] = sp.sympify(c)
        lo, hi = min(entries), max(entries)
        return cls(tuple(entries.get(i, sp.Integer(0)) for i in range(lo, hi + 1)), lo,
                   tuple(params), **kw)

    # ---------------------------------------------------------------- data
    @property
    def end(self) -> int:
        return self.start + len(self.mask) - 1

    @property
    def param_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.params)

    def mask_in_n(self) -> tuple:
        """The coefficients as functions of the level ``n`` (``h = 2^-n``)."""
        return tuple(c.subs(H, 2 ** (-N)) for c in self.mask)

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
        rep = {self._param(str(k)): parse_coefficient(v) if isinstance(v, str) else sp.sympify(v)
               for k, v in dict(values).items()}
        return LevelDependentScheme(tuple(c.subs(rep) for c in self.mask), self.start,
                                    tuple(p for p in self.params if p not in rep), slug=self.slug,
                                    title=self.title, source=self.source, notes=self.notes)

    def mask_at(self, n: int, values: Mapping[str, Any] | None = None) -> list[sp.Expr]:
        """The exact coefficients of ``a^n`` at level ``n`` (sympy expressions)."""
        s = self.subs(values) if values else self
        return [c.subs(H, sp.Rational(1, 2 ** int(n))) for c in s.mask]

    # ---------------------------------------------------------------- limit and expansion
    @cached_property
    def _limits(self) -> tuple:
        out = []
        for c in self.mask:
            if H not in c.free_symbols:
                out.append(sp.simplify(c))
                continue
            c0 = sp.simplify(sp.limit(c, H, 0, "+"))
            if c0.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or isinstance(c0, sp.Limit):
                raise AnalysisError(f"the coefficient {c} has no finite limit as n -> oo")
            out.append(c0)
        return tuple(out)

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
        rows = []
        for c, c0 in zip(self.mask, self._limits):
            g = c - c0
            if H not in g.free_symbols:
                rows.append(tuple(sp.Integer(0) for _ in range(J)))
                continue
            ser = sp.series(g, H, 0, J).removeO()
            ser = sp.expand(ser)
            coeffs = [sp.factor(sp.simplify(ser.coeff(H, j))) for j in range(J)]
            rows.append(tuple(coeffs))
        cache[J] = tuple(rows)
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
        :class:`AnalysisError`).
        """
        if spelling not in ("divided", "paper"):
            raise AnalysisError(f"unknown spelling {spelling!r}; use 'divided' or 'paper'")
        coeffs = list(self.mask)
        for _ in range(k):
            q: list[sp.Expr] = []
            rem = sp.Integer(0)
            for c in coeffs[:-1]:
                rem = c - rem
                q.append(rem)
            last = coeffs[-1] - rem
            if sp.simplify(last.rewrite(sp.exp)) != 0:
                raise AnalysisError("(1+z) does not divide a^n(z) identically in n "
                                    f"(a^n(-1) = {sp.simplify(last)})")
            coeffs = [2 * c for c in q]
        start = self.start + (k if spelling == "paper" else 0)
        return LevelDependentScheme(tuple(coeffs), start, self.params,
                                    slug=f"{self.slug}-diff{k}", title=f"{k}-th difference of {self.title}",
                                    source=self.source)

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


# --------------------------------------------------------------------------------------------
# leading asymptotics of ||S_{a^n} - S_a||
# --------------------------------------------------------------------------------------------

def _residue_groups(s: LevelDependentScheme) -> dict[int, list[int]]:
    groups: dict[int, list[int]] = {0: [], 1: []}
    for k in range(len(s.mask)):
        groups[(s.start + k) % 2].append(k)
    return groups


def leading_asymptotics(s: LevelDependentScheme) -> Result:
    """``||S_{a^n} - S_a||_inf = C 2^{-q n} + O(2^{-(q+1) n})``: the exact ``C`` and ``q``.

    ``C = max_r sum_{k = r mod 2} |g_{k,q}|`` with ``g_{k,q}`` the exact ``h^q`` Taylor
    coefficient of ``a^n_k - a_k``. Certified (exact series); where ``C`` vanishes for special
    parameter values the order there is higher (``witness["per_residue"]`` shows the pieces).
    """
    q = s.order()
    rows = s.taylor(q + 1)
    per_res = {}
    for r, ks in _residue_groups(s).items():
        per_res[r] = sp.simplify(sum(sp.Abs(rows[k][q]) for k in ks))
    vals = list(per_res.values())
    C = vals[0] if sp.simplify(vals[0] - vals[1]) == 0 else sp.Max(*vals)
    return Result(value=C, status=CERTIFIED,
                  witness={"order": q, "rate": f"{sp.sstr(C)} * 2^(-{q}n)", "per_residue": per_res,
                           "leading_coefficients": {s.start + k: rows[k][q] for k in range(len(rows))
                                                    if rows[k][q] != 0}},
                  provenance={"method": "exact sympy series in h = 2^-n", "scheme": s.slug})


# --------------------------------------------------------------------------------------------
# ||S_{a^n} - S_a|| at a level
# --------------------------------------------------------------------------------------------

def default_precision(s: LevelDependentScheme, n: int, target_bits: int = 64) -> int:
    """Working precision for level n: ``target + q n + 32`` bits (q = the leading order)."""
    try:
        q = s.order()
    except AnalysisError:
        q = 0
    return int(target_bits + q * n + 32)


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


def coefficient_differences(s: LevelDependentScheme, n: int, values=None, *, prec: int | None = None):
    """Arb enclosures of ``a^n_k - a_k`` for every k (exact h = 2^-n, params exact or boxes)."""
    env = _env_values(s, values)
    prec = prec or default_precision(s, n)
    with workprec(prec):
        envb = {k: _to_ball(v, False) for k, v in env.items()}
        envb["h"] = flint.arb(2) ** (-int(n))
        out = []
        for c, c0 in zip(s.mask, s._limits):
            # the entire form (sinc) avoids the dependency problem of sin(u)/sin(v) over boxes
            out.append(_ball(entire_form(c), envb, False) - _ball(c0, envb, False)
                       if H in c.free_symbols else _ball(sp.simplify(c - c0), envb, False))
    return out


def distance(s: LevelDependentScheme, n: int, values: Mapping[str, Any] | None = None, *,
             arithmetic: str = "arb", prec: int | None = None) -> Result:
    """``||S_{a^n} - S_a||_inf`` at level ``n``.

    ``arithmetic="arb"``: a certified enclosure ``[lower, upper]`` (exact rationals) from ball
    arithmetic at ``prec`` bits (default :func:`default_precision`); parameter values may be
    exact numbers or ``(lo, hi)`` boxes. ``"mp"``: mpmath at ``prec`` bits, numerical.
    ``"float"``: float64, numerical, and wrong at large n (cancellation).
    """
    if arithmetic not in ARITHMETICS:
        raise AnalysisError(f"unknown arithmetic {arithmetic!r}; use one of {', '.join(ARITHMETICS)}")
    if not isinstance(n, int) or n < 0:
        raise AnalysisError(f"the level must be a non-negative integer, not {n!r}")
    groups = _residue_groups(s)
    prec = prec or default_precision(s, n)
    prov = {"level": n, "scheme": s.slug, "arithmetic": arithmetic}
    if arithmetic == "arb":
        diffs = coefficient_differences(s, n, values, prec=prec)
        with workprec(prec):
            sums = [sum((arb_abs(diffs[k]) for k in ks), flint.arb(0)) for ks in groups.values()]
            best = sums[0].max(sums[1])
        lo, hi = ball_to_interval(best)
        lo = max(lo, sp.Integer(0))
        return Result(lower=lo, upper=hi, status=CERTIFIED,
                      witness={"residue_sums": [ball_to_interval(x) for x in sums]},
                      provenance={**prov, "precision_bits": prec,
                                  "method": "arb ball arithmetic, h = 2^-n exact"})
    env = _env_values(s, values)
    syms = [H] + list(s.params)
    diffs_expr = [c - c0 for c, c0 in zip(s.mask, s._limits)]
    if arithmetic == "mp":
        with mpmath.workprec(prec):
            f = sp.lambdify(syms, diffs_expr, "mpmath")
            args = [mpmath.mpf(2) ** (-n)] + [mpmath.mpmathify(sp.N(env[p.name], prec // 3 + 20))
                                              for p in s.params]
            d = f(*args)
            val = max(sum(abs(d[k]) for k in ks) for ks in groups.values())
            value = sp.Float(val, prec // 3)
        return Result(value=value, status=NUMERICAL,
                      provenance={**prov, "precision_bits": prec, "method": "mpmath"})
    f = sp.lambdify(syms, diffs_expr, "math")
    d = f(2.0 ** (-n), *[float(env[p.name]) for p in s.params])
    val = max(sum(abs(d[k]) for k in ks) for ks in groups.values())
    return Result(value=float(val), status=NUMERICAL, provenance={**prov, "method": "float64"})


def distance_table(s: LevelDependentScheme, values=None, n_max: int = 200, *,
                   arithmetic: str = "arb") -> list[Result]:
    """:func:`distance` for ``n = 0..n_max`` (precision chosen per level)."""
    return [distance(s, n, values, arithmetic=arithmetic) for n in range(n_max + 1)]


# --------------------------------------------------------------------------------------------
# Taylor models with Cauchy remainders (rigorous, over parameter boxes)
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class TaylorModel:
    """``g(h) in sum_{j<J} coeffs[j] h^j +- M (h/rho)^J / (1 - h/rho)`` for ``0 <= h < rho``.

    ``coeffs`` are arb balls (valid over the whole parameter box); ``M`` bounds ``|g|`` on the
    closed disk ``|h| <= rho`` (upper bound, an arb), so also ``|coeffs[j]| <= M rho^-j``.
    """

    coeffs: tuple
    M: Any
    rho: Any
    J: int

    def remainder(self, h):
        """Upper bound of the remainder at ``h`` (an arb; ``h < rho``)."""
        t = h / self.rho
        return self.M * t ** self.J / (1 - t)

    def enclose(self, h):
        """An arb ball containing ``g(h)``."""
        v = flint.arb(0)
        for j, c in enumerate(self.coeffs):
            v = v + c * h ** j
        r = self.remainder(h)
        return v + flint.arb(0, 1) * r

    def abs_upper_over(self, q: int, h_max):
        """``A`` with ``|g(h)| <= A h^q`` for ``0 < h <= h_max`` (needs ``coeffs[j] = 0``, j < q)."""
        A = flint.arb(0)
        for j in range(q, len(self.coeffs)):
            A = A + arb_abs(self.coeffs[j]) * h_max ** (j - q)
        t = h_max / self.rho
        A = A + self.M * self.rho ** (-q) * t ** (self.J - q) / (1 - t)
        return A


def _disk_max(expr: sp.Expr, envc: dict, rho, grid: int):
    """Upper bound of ``|expr|`` on the closed disk ``|h| <= rho`` (None if not finite)."""
    best = flint.arb(0)
    step = 2 * rho / grid
    half = step / 2
    for i in range(grid):
        for j in range(grid):
            re = -rho + half + i * step
            im = -rho + half + j * step
            # skip squares entirely outside the disk (their nearest point is farther than rho)
            dx = max(abs(float(re.mid())) - float(half.mid()), 0.0)
            dy = max(abs(float(im.mid())) - float(half.mid()), 0.0)
            if dx * dx + dy * dy > float(rho.mid()) ** 2 * (1 + 1e-9):
                continue
            hb = flint.acb(flint.arb(re.mid(), half.mid() * 1.0001), flint.arb(im.mid(), half.mid() * 1.0001))
            env = dict(envc)
            env["h"] = hb
            v = _ball(expr, env, True)
            if not v.is_finite():
                return None
            best = best.max(flint.arb(abs(v).upper()))
    return best


def taylor_models(s: LevelDependentScheme, values=None, *, J: int | None = None,
                  rhos=(2, 1, sp.Rational(1, 2), sp.Rational(1, 4), sp.Rational(1, 16)),
                  grid: int = 12, prec: int = 96) -> list[TaylorModel]:
    """Rigorous Taylor models of ``g_k = a^n_k - a_k`` in ``h`` over a parameter box.

    ``values``: parameter -> exact value or ``(lo, hi)`` box. The radius ``rho`` is the first of
    ``rhos`` on whose disk every coefficient evaluates finitely (a proof of analyticity there).
    Raises :class:`AnalysisError` when none works.
    """
    env = _env_values(s, values)
    q = s.order()
    J = J or q + 2
    rows = s.taylor(J)
    with workprec(prec):
        envr = {k: _to_ball(v, False) for k, v in env.items()}
        envc = {k: flint.acb(v) for k, v in envr.items()}
        for rho_s in rhos:
            rho = flint.arb(int(sp.Rational(rho_s).p)) / int(sp.Rational(rho_s).q)
            models = []
            ok = True
            for c, c0, row in zip(s.mask, s._limits, rows):
                if H not in c.free_symbols:
                    models.append(TaylorModel(tuple(flint.arb(0) for _ in range(J)), flint.arb(0), rho, J))
                    continue
                g = entire_form(c - c0)
                M = _disk_max(g, envc, rho, grid)
                if M is None:
                    ok = False
                    break
                coeffs = tuple(_ball(x, envr, False) for x in row)
                models.append(TaylorModel(coeffs, M, rho, J))
            if ok:
                return models
    raise AnalysisError("could not certify analyticity of a^n - a on any disk |h| <= rho "
                        "(split the parameter box or give smaller radii)")
