"""Exact real algebraic numbers and rigorous enclosures.

Two tools that let every comparison in the workbench be decided exactly:

* :func:`enclose` — a rigorous ``mpmath.iv`` interval for a closed-form real expression
  (rationals, radicals, ``CRootOf``, ``pi``, elementary functions), at a given precision;
* :func:`sign` — the exact sign of an algebraic number: the enclosure is refined until it excludes
  0, and a possible zero is decided exactly with its minimal polynomial;
* :class:`RealAlgebraic` — a real root of a square-free rational polynomial, held as the polynomial
  and an isolating interval with rational endpoints (the representation of real root isolation).
  It compares exactly with other algebraic numbers, decides the sign of a polynomial at itself,
  and prints as radicals when the degree is at most 2 (``CRootOf`` otherwise).

Examples
--------
>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> r = RealAlgebraic.roots_of(sp.Poly(1280*x**2 + 32*x - 1, x))[1]
>>> r.expr
-1/80 + sqrt(6)/80
>>> sign((sp.sqrt(6) - 1)/80 - sp.Rational(1, 50))     # 0.0181... < 0.02
-1
>>> r.sign_of(sp.Poly(80*x + 1, x))
1

Algorithm
---------
Root isolation is sympy's (continued-fraction / Vincent–Akritas–Strzeboński) ``Poly.intervals``;
refinement bisects the isolating interval with exact rational arithmetic. The sign of ``p`` at a
root ``r`` of ``f`` is 0 exactly when ``gcd(f, p)`` has a root in the isolating interval; otherwise
the interval is refined until ``p`` has no root in it, and the sign of ``p`` at any rational point
of the interval is the answer. Enclosures use ``mpmath.iv`` (outward rounding).

References
----------
A. Strzeboński, *Computing in the field of complex algebraic numbers*, J. Symb. Comput. 24 (1997).
F. Johansson et al., *mpmath interval arithmetic* (``mpmath.iv``) documentation.
"""

from __future__ import annotations

from functools import cached_property
from typing import Iterable

import mpmath
import sympy as sp

from ..result import AnalysisError
from .reader import as_expr

iv = mpmath.iv


# --------------------------------------------------------------------------------------------
# enclosures
# --------------------------------------------------------------------------------------------

def enclose(x, prec: int = 80):
    """A rigorous interval (``mpmath.iv.mpf``) containing the real number ``x``.

    ``x`` is a sympy expression built from rationals, radicals, ``CRootOf``, ``pi``, ``E`` and
    ``sin cos tan exp log sqrt sinh cosh tanh``. Raises :class:`AnalysisError` for anything else.

    >>> import sympy as sp
    >>> I = enclose(sp.sqrt(2), 60)
    >>> _q(I.a)**2 < 2 < _q(I.b)**2, float(I.b - I.a) < 1e-17
    (True, True)
    """
    with _ivprec(prec):
        return _enc(as_expr(x), prec)


def _enc(x, prec):
    if isinstance(x, RealAlgebraic):
        return x.enclosure(prec)
    if x.is_Integer:
        return iv.mpf(int(x))
    if x.is_Rational:
        return iv.mpf(int(x.p)) / int(x.q)
    if x is sp.pi:
        return iv.pi
    if x is sp.E:
        return iv.e
    if x.is_Add:
        out = iv.mpf(0)
        for t in x.args:
            out = out + _enc(t, prec)
        return out
    if x.is_Mul:
        out = iv.mpf(1)
        for t in x.args:
            out = out * _enc(t, prec)
        return out
    if x.is_Pow:
        base, e = x.args
        b = _enc(base, prec)
        if e.is_Integer:
            n = int(e)
            if n >= 0:
                return b ** n
            return iv.mpf(1) / (b ** (-n))
        if e.is_Rational:
            if b.a < 0:
                raise AnalysisError(f"cannot enclose {x}: even root of a possibly negative number")
            if e == sp.Rational(1, 2):
                return iv.sqrt(b)
            if e == sp.Rational(-1, 2):
                return iv.mpf(1) / iv.sqrt(b)
            return iv.exp(iv.log(b) * (iv.mpf(int(e.p)) / int(e.q)))
        return iv.exp(iv.log(b) * _enc(e, prec))
    if isinstance(x, sp.CRootOf):
        if not x.is_real:
            raise AnalysisError(f"{x} is not real")
        return RealAlgebraic.from_crootof(x).enclosure(prec)
    funcs = {sp.sin: iv.sin, sp.cos: iv.cos, sp.tan: iv.tan, sp.exp: iv.exp, sp.log: iv.log,
             sp.sinh: iv.sinh, sp.cosh: iv.cosh, sp.tanh: iv.tanh}
    if x.func in funcs:
        return funcs[x.func](_enc(x.args[0], prec))
    raise AnalysisError(f"cannot enclose {sp.sstr(x)}: unsupported expression")


def sign(x, *, max_prec: int = 8192) -> int:
    """The exact sign (-1, 0, 1) of a real algebraic (or closed-form) number.

    The zero case is decided exactly for algebraic numbers (minimal polynomial); for
    transcendental expressions a zero that the enclosures cannot exclude raises
    :class:`AnalysisError`.
    """
    if isinstance(x, RealAlgebraic):
        return x.sign()
    x = as_expr(x)
    if x.is_Rational:
        return int(sp.sign(x))
    prec = 64
    zero_checked = False
    while prec <= max_prec:
        I = enclose(x, prec)
        if I.a > 0:
            return 1
        if I.b < 0:
            return -1
        if not zero_checked and prec >= 128:
            zero_checked = True
            if x.is_algebraic:
                t = sp.Dummy("t")
                mp = sp.minimal_polynomial(x, t, polys=True)
                if mp.degree() == 1 and mp.eval(0) == 0:
                    return 0
        prec *= 2
    raise AnalysisError(f"could not decide the sign of {sp.sstr(x)} at {max_prec} bits")


def compare(x, y) -> int:
    """``sign(x - y)`` exactly."""
    if isinstance(x, RealAlgebraic) or isinstance(y, RealAlgebraic):
        xa = x if isinstance(x, RealAlgebraic) else RealAlgebraic.from_expr(x)
        ya = y if isinstance(y, RealAlgebraic) else RealAlgebraic.from_expr(y)
        return xa.compare(ya)
    return sign(as_expr(x) - as_expr(y))


# --------------------------------------------------------------------------------------------
# real algebraic numbers by isolating intervals
# --------------------------------------------------------------------------------------------

#: the variable of the linear polynomials of rational numbers (one symbol for all of them)
_X = sp.Dummy("x")

#: Sturm sequences of the last polynomials whose real roots were counted (:func:`_count_roots`), keyed on the
#: exact coefficients; at most ``_STURM_MAX``
_STURM: dict = {}
_STURM_MAX = 256


def _count_roots(p: sp.Poly, a, b) -> int:
    """``p.count_roots(a, b)`` for ``p`` univariate over QQ and rational ``a <= b``: the number of distinct real
    roots in ``[a, b]``, computed as sympy's ``dup_count_real_roots`` does, with the Sturm sequence of ``p``
    formed once and kept (comparisons refine an interval and count the roots of the same polynomial again
    and again)."""
    from sympy.polys.densebasic import dup_degree
    from sympy.polys.densetools import dup_eval, dup_sign_variations
    from sympy.polys.rootisolation import dup_sturm

    if len(p.gens) != 1 or p.domain not in (sp.QQ, sp.ZZ):
        return int(p.count_roots(a, b))
    K = sp.QQ
    f = [K.convert(c, p.domain) for c in p.rep.to_list()]
    if dup_degree(f) <= 0:
        return 0
    key = tuple(f)
    sturm = _STURM.get(key)
    if sturm is None:
        if len(_STURM) >= _STURM_MAX:
            _STURM.pop(next(iter(_STURM)))
        sturm = _STURM[key] = dup_sturm(f, K)
    inf, sup = K.convert(a), K.convert(b)
    count = abs(dup_sign_variations([dup_eval(s, inf, K) for s in sturm], K)
                - dup_sign_variations([dup_eval(s, sup, K) for s in sturm], K))
    if not dup_eval(f, inf, K):
        count += 1
    return count


class RealAlgebraic:
    """A real root of a square-free polynomial over QQ, isolated in ``[a, b]`` (rationals).

    Immutable in value; the isolating interval is refined in place as comparisons demand.
    """

    __slots__ = ("poly", "a", "b", "__dict__")

    def __init__(self, poly: sp.Poly, a, b):
        self.poly = poly
        self.a = sp.Rational(a)
        self.b = sp.Rational(b)

    # ------------------------------------------------------------- constructors
    @classmethod
    def rational(cls, q) -> "RealAlgebraic":
        q = sp.Rational(q)
        return cls(sp.Poly.from_list([1, -q], _X, domain=sp.QQ), q, q)

    @classmethod
    def roots_of(cls, poly: sp.Poly) -> list["RealAlgebraic"]:
        """All distinct real roots of ``poly`` (rational coefficients), in increasing order."""
        if poly.is_zero:
            raise ValueError("the zero polynomial has every number as a root")
        poly = poly.set_domain(sp.QQ) if poly.domain != sp.QQ else poly
        out: list[RealAlgebraic] = []
        if poly.degree() <= 0:
            return out
        _, factors = poly.factor_list()
        for f, _mult in factors:
            f = f.monic()
            if f.degree() == 1:
                r = -f.nth(0)
                out.append(cls(f, r, r))
                continue
            for (a, b), _m in f.intervals():
                out.append(cls(f, a, b))
        out.sort(key=lambda r: float(r.a + r.b) / 2)  # approximate; fixed exactly below
        return _exact_sort(out)

    @classmethod
    def from_crootof(cls, r: sp.CRootOf) -> "RealAlgebraic":
        poly = sp.Poly(r.poly.as_expr(), r.poly.gen, domain=sp.QQ)
        roots = cls.roots_of(poly)
        return roots[r.index]

    @classmethod
    def from_expr(cls, x) -> "RealAlgebraic":
        """The algebraic number given by a closed-form expression (via its minimal polynomial)."""
        x = as_expr(x)
        if isinstance(x, RealAlgebraic):
            return x
        if x.is_Rational:
            return cls.rational(x)
        if isinstance(x, sp.CRootOf):
            return cls.from_crootof(x)
        t = sp.Dummy("t")
        mp = sp.minimal_polynomial(x, t, polys=True)
        cands = cls.roots_of(mp)
        prec = 64
        while True:
            I = enclose(x, prec)
            hits = [r for r in cands if not (r.b < _q(I.a) or r.a > _q(I.b))]
            if len(hits) == 1:
                r = hits[0]
                r.__dict__["expr"] = x
                return r
            if not hits:
                raise AnalysisError(f"inconsistent enclosure for {sp.sstr(x)}")
            for r in hits:
                r.refine()
            prec *= 2

    # ------------------------------------------------------------- basic operations
    @property
    def is_rational(self) -> bool:
        return self.poly.degree() == 1

    def refine(self) -> None:
        """Halve the isolating interval (exactly)."""
        if self.a == self.b:
            return
        m = (self.a + self.b) / 2
        pm = self.poly.eval(m)
        if pm == 0:
            self.a = self.b = m
            return
        pa = self.poly.eval(self.a)
        if pa != 0:
            # the one root in [a, b] is simple (square-free polynomial): it lies in (a, m) exactly when
            # the polynomial changes sign there (the same answer as counting roots, without a Sturm sequence)
            inside = (pa > 0) != (pm > 0)
        else:
            inside = _count_roots(self.poly, self.a, m) > 0
        if inside:
            self.b = m
        else:
            self.a = m

    def enclosure(self, prec: int = 80):
        with _ivprec(prec):
            while True:
                width = float(self.b - self.a)
                if width == 0 or width < 2.0 ** (-prec) * max(1.0, abs(float(self.a))):
                    break
                self.refine()
            lo = _enc(self.a, prec)._mpi_[0]
            hi = _enc(self.b, prec)._mpi_[1]
            return _make_iv(lo, hi)

    def sign_of(self, p: sp.Poly) -> int:
        """The exact sign of the polynomial ``p`` (rational coefficients) at this number."""
        if self.a == self.b and len(p.gens) == 1 and p.domain in (sp.QQ, sp.ZZ):
            return 0 if p.is_zero else int(sp.sign(p.eval(self.a)))       # a rational number
        if len(p.gens) == 1 and p.domain in (sp.QQ, sp.ZZ):
            p = sp.Poly.from_list(p.set_domain(sp.QQ).all_coeffs(), self.poly.gen, domain=sp.QQ)
        else:
            p = sp.Poly(p.as_expr().subs(p.gen, self.poly.gen), self.poly.gen, domain=sp.QQ)
        if p.is_zero:
            return 0
        if self.a == self.b:
            return int(sp.sign(p.eval(self.a)))
        g = sp.gcd(self.poly, p)
        if g.degree() > 0 and _count_roots(g, self.a, self.b) > 0:
            return 0
        while _count_roots(p, self.a, self.b) > 0:
            self.refine()
            if self.a == self.b:
                return int(sp.sign(p.eval(self.a)))
        return int(sp.sign(p.eval((self.a + self.b) / 2)))

    def sign(self) -> int:
        x = self.poly.gen
        return self.sign_of(sp.Poly(x, x, domain=sp.QQ))

    def compare(self, other: "RealAlgebraic") -> int:
        """``sign(self - other)``, exactly."""
        if not isinstance(other, RealAlgebraic):
            other = RealAlgebraic.from_expr(other)
        if other.a == other.b and self.a != self.b:
            return self._compare_rational(other.a)
        if self.a == self.b and other.a != other.b:
            return -other._compare_rational(self.a)
        for _ in range(10_000):
            if self.b < other.a:
                return -1
            if other.b < self.a:
                return 1
            if self.a == self.b and other.a == other.b:
                return int(sp.sign(self.a - other.a))
            # overlapping intervals: equal iff self is a root of other's polynomial inside
            if self.a >= other.a and self.b <= other.b and other.sign_of(self.poly) == 0:
                if self.sign_of(other.poly) == 0:
                    return 0
            if other.a >= self.a and other.b <= self.b and self.sign_of(other.poly) == 0:
                if other.sign_of(self.poly) == 0:
                    return 0
            self.refine()
            other.refine()
        raise AnalysisError("could not separate two algebraic numbers")  # pragma: no cover

    def _compare_rational(self, q) -> int:
        """``sign(self - q)`` for a rational ``q``: the isolating interval holds one root of
        ``self.poly``, so ``q`` inside it with ``poly(q) = 0`` is that root; otherwise halve the
        interval (exactly as the general comparison does: until ``q`` is outside, then once more)."""
        if q < self.a or self.b < q:
            return 1 if q < self.a else -1
        if self.poly.eval(q) == 0:
            return 0
        for _ in range(10_000):
            if q < self.a or self.b < q:
                break
            if q == self.a or q == self.b:
                # q is an end and not the root: the root lies strictly on the other side
                s = 1 if q == self.a else -1
                self.refine()
                return s
            self.refine()
        else:  # pragma: no cover
            raise AnalysisError("could not separate an algebraic number from a rational")
        s = 1 if q < self.a else -1
        self.refine()
        return s

    def __lt__(self, other) -> bool:
        return self.compare(other) < 0

    def __le__(self, other) -> bool:
        return self.compare(other) <= 0

    def __gt__(self, other) -> bool:
        return self.compare(other) > 0

    def __ge__(self, other) -> bool:
        return self.compare(other) >= 0

    def __eq__(self, other) -> bool:
        if not isinstance(other, (RealAlgebraic, sp.Basic, int)):
            return NotImplemented
        return self.compare(other) == 0

    def __hash__(self):  # equal numbers must hash equal: hash the minimal polynomial only
        return hash(tuple(self.poly.monic().all_coeffs()))

    def __float__(self) -> float:
        I = self.enclosure(80)
        return float((_q(I.a) + _q(I.b)) / 2)

    def rational_below(self):
        """A rational number strictly less than this one."""
        return self.a - 1 if self.a == self.b else self.a

    def rational_above(self):
        """A rational number strictly greater than this one."""
        return self.b + 1 if self.a == self.b else self.b

    @cached_property
    def expr(self) -> sp.Expr:
        """A closed form: a rational, radicals (degree 2), or ``CRootOf``."""
        if self.a == self.b:
            return self.a
        deg = self.poly.degree()
        if deg == 1:
            return -self.poly.nth(0) / self.poly.nth(1)
        if deg == 2:
            for r in sp.roots(self.poly, multiple=True):
                I = enclose(r, 100)
                if not (_q(I.b) < self.a or _q(I.a) > self.b):
                    # the other root is outside the isolating interval: this is it
                    return sp.radsimp(r)
        # CRootOf index: count real roots below
        idx = self.poly.count_roots(-sp.oo, self.a) - (1 if self.poly.eval(self.a) == 0 else 0)
        return sp.CRootOf(self.poly.as_expr(), idx)

    def __repr__(self) -> str:
        return f"RealAlgebraic({sp.sstr(self.expr)})"

    def __str__(self) -> str:
        return sp.sstr(self.expr)


def rational_between(lo: "RealAlgebraic | None", hi: "RealAlgebraic | None") -> sp.Rational:
    """A rational strictly between two real algebraic numbers (``None`` = -oo / +oo)."""
    if lo is None and hi is None:
        return sp.Integer(0)
    if lo is None:
        return sp.floor(hi.rational_below()) - 1
    if hi is None:
        return sp.ceiling(lo.rational_above()) + 1
    while not lo.b < hi.a:
        lo.refine()
        hi.refine()
        if lo.a == lo.b and hi.a == hi.b:
            break
    if lo.b < hi.a:
        return (lo.b + hi.a) / 2
    return (lo.a + hi.b) / 2  # pragma: no cover


def _q(x) -> sp.Rational:
    """An mpmath number or a degenerate interval endpoint as an exact sympy Rational."""
    raw = x._mpi_[0] if hasattr(x, "_mpi_") else x._mpf_
    p, q = mpmath.libmp.to_rational(raw)
    return sp.Rational(int(p), int(q))


def _make_iv(lo_raw, hi_raw):
    """An ``iv.mpf`` from two raw mpf tuples, without rounding."""
    out = iv.mpf(0)
    out._mpi_ = (lo_raw, hi_raw)
    return out


class _ivprec:
    """Context manager: ``mpmath.iv`` working precision in bits."""

    def __init__(self, prec: int):
        self.prec = prec

    def __enter__(self):
        self.saved = iv.prec
        iv.prec = self.prec
        return self

    def __exit__(self, *exc):
        iv.prec = self.saved
        return False


def _exact_sort(xs: Iterable[RealAlgebraic]) -> list[RealAlgebraic]:
    import functools

    return sorted(xs, key=functools.cmp_to_key(lambda u, v: u.compare(v)))


# --------------------------------------------------------------------------------------------
# finite unions of intervals with algebraic endpoints
# --------------------------------------------------------------------------------------------

class IntervalSet:
    """A finite union of disjoint intervals of the real line with exact endpoints.

    Each part is ``(lo, hi, lo_closed, hi_closed)`` with ``lo``/``hi`` a :class:`RealAlgebraic`,
    or ``None`` for ``-oo``/``+oo``. Parts are sorted and pairwise disjoint.

    >>> s = IntervalSet([(RealAlgebraic.rational(0), RealAlgebraic.rational(1), False, False)])
    >>> str(s), s.contains(sp.Rational(1, 2)), s.contains(1)
    ('(0, 1)', True, False)
    """

    def __init__(self, parts=()):
        self.parts = tuple(parts)

    @classmethod
    def from_members(cls, members) -> "IntervalSet":
        """Merge an alternating left-to-right sequence of elementary pieces into a set.

        ``members`` is a list of ``("gap", (lo, hi), included)`` (open intervals) and
        ``("point", x, included)`` (their common endpoints); adjacent included pieces merge.
        """
        parts, run = [], None
        for k, (_kind, _data, inc) in enumerate(members):
            if inc and run is None:
                run = k
            if run is not None and (not inc or k == len(members) - 1):
                last = k if inc else k - 1
                first_kind, first_data, _ = members[run]
                last_kind, last_data, _ = members[last]
                left = first_data[0] if first_kind == "gap" else first_data
                right = last_data[1] if last_kind == "gap" else last_data
                parts.append((left, right, first_kind == "point", last_kind == "point"))
                run = None
        return cls(parts)

    @property
    def is_empty(self) -> bool:
        return not self.parts

    def contains(self, x) -> bool:
        for lo, hi, lc, hc in self.parts:
            left = True if lo is None else (lo.compare(RealAlgebraic.from_expr(x)) < 0
                                            or (lc and lo.compare(RealAlgebraic.from_expr(x)) == 0))
            right = True if hi is None else (hi.compare(RealAlgebraic.from_expr(x)) > 0
                                             or (hc and hi.compare(RealAlgebraic.from_expr(x)) == 0))
            if left and right:
                return True
        return False

    def endpoints(self):
        """The finite endpoints as closed-form sympy numbers."""
        out = []
        for lo, hi, _, _ in self.parts:
            out.extend(e.expr for e in (lo, hi) if e is not None)
        return out

    def to_sympy(self):
        """The set as a sympy ``Union`` of ``Interval``s (exact endpoints)."""
        pieces = []
        for lo, hi, lc, hc in self.parts:
            a = -sp.oo if lo is None else lo.expr
            b = sp.oo if hi is None else hi.expr
            if lo is not None and hi is not None and lo.compare(hi) == 0:
                pieces.append(sp.FiniteSet(a))
            else:
                pieces.append(sp.Interval(a, b, left_open=not lc, right_open=not hc))
        return sp.Union(*pieces) if pieces else sp.EmptySet

    def __str__(self) -> str:
        if not self.parts:
            return "empty"
        out = []
        for lo, hi, lc, hc in self.parts:
            a = "-oo" if lo is None else sp.sstr(lo.expr)
            b = "oo" if hi is None else sp.sstr(hi.expr)
            if lo is not None and hi is not None and lo.compare(hi) == 0:
                out.append("{" + a + "}")
            else:
                out.append(("[" if lc else "(") + f"{a}, {b}" + ("]" if hc else ")"))
        return " U ".join(out)

    def __repr__(self) -> str:
        return f"IntervalSet({self})"

    def to_json(self) -> list:
        out = []
        for lo, hi, lc, hc in self.parts:
            out.append({
                "lower": None if lo is None else sp.sstr(lo.expr),
                "upper": None if hi is None else sp.sstr(hi.expr),
                "lower_float": None if lo is None else float(lo),
                "upper_float": None if hi is None else float(hi),
                "lower_closed": lc, "upper_closed": hc,
            })
        return out
