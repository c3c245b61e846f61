"""Masks typed in closed form (nested radicals, ``I`` that cancels, ``CRootOf``): exact zero tests
and the certified ball route.

Exact arithmetic in the number field of such a mask can be very slow (a primitive element of
``Q(sqrt 10, sqrt(5 + 2 sqrt 10))`` is still cheap, that of sympy's radical roots of the D8
spectral factorisation is not). The Hölder exponent only needs

1. the number ``N`` of factors ``(1+z)``, ``a(1) = 2`` and the reality of the coefficients --
   decided **exactly** here by :func:`~analysis.algebra.zero_test.is_zero`, a rigorous zero test of algebraic expressions
   (below), and
2. certified balls around the coefficients (``zero_test``, Arb), for
   :func:`analysis.regularity.holder_exponent` (ball route) -- the same certificate as for the
   catalogue's Daubechies masks.

The zero test and its proofs are in :mod:`analysis.algebra.zero_test`.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Sequence

import sympy as sp

from ..result import AnalysisError
from .expressions import Undecided, _deep_recursion, _ir, _n, _sub, degree_bound
from .zero_test import _Algebra


def _linear(terms: Sequence[tuple[int, object]]):
    """IR of ``sum c_k x_k`` (integer ``c_k``)."""
    parts = tuple(_n("mul", (_n("q", Fraction(c)), x)) for c, x in terms if c != 0)
    return _n("add", parts) if parts else _n("q", Fraction(0))


def _method_text(methods: set) -> str:
    names = {"formal": "formal identity in the atoms", "separation": "root-separation bound"}
    return " and ".join(names[m] for m in sorted(methods)) or "zero test"


class ClosedFormMask:
    """A real mask typed with algebraic closed forms, analysed by the certified ball route.

    ``sum_rules`` (``N``) and ``a(1) = 2`` are decided exactly (:func:`is_zero`); reality of each
    coefficient is proven the same way (``x - conj(x) = 0``) when it is not real by construction.
    ``enclosure(prec)`` gives Arb balls for :func:`analysis.regularity.holder_exponent` (the ball route).

    >>> m = ClosedFormMask(["(1+sqrt(3))/4", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3))/4"])
    >>> m.sum_rules
    2
    """

    def __init__(self, mask: Sequence, start: int = 0):
        from .symbol import parse_coefficient

        if isinstance(mask, (str, bytes)) or len(mask) == 0:
            raise AnalysisError("a mask is a non-empty list of coefficients")
        self.start = int(start)
        self.exprs = [parse_coefficient(c) for c in mask]
        for k, e in enumerate(self.exprs):
            if e.free_symbols:
                raise AnalysisError(f"coefficient {k} ({_cut(e)}) has free symbols "
                                    f"{', '.join(sorted(s.name for s in e.free_symbols))}: give their values")
        memo: dict = {}
        self.nodes = [_ir(e, memo) for e in self.exprs]
        self.algebra = _Algebra()
        self.algebra.register(self.nodes)
        self.slug = "mask (closed form)"
        self.how: list[str] = []
        self.undecided: str | None = None
        self.failure: str | None = None
        self.sum_rules = 0
        self._methods: set = set()
        with _deep_recursion():
            try:
                self._check_real()
                self._decide_sum_rules()
            except Undecided as exc:   # not bad input: the exact decision is out of reach
                self.undecided = str(exc)  # -> inconclusive

    # -- exact decisions
    def _zero(self, node) -> tuple[bool, dict]:
        zero, how = self.algebra.zero(node)
        if zero:
            self._methods.add(how.get("method", "separation"))
        return zero, how

    def _check_real(self) -> None:
        alg = self.algebra
        proofs = 0
        conjs = [alg.conj(node) for node in self.nodes if not alg.real_by_construction(node)]
        alg.prepare(self.nodes + conjs)
        for k, node in enumerate(self.nodes):
            if alg.real_by_construction(node):
                continue
            b = alg.enclose(node, 96)
            if not b.imag.contains(0):
                raise AnalysisError(f"coefficient {k} ({_cut(self.exprs[k])}) is not real: its imaginary "
                                    f"part is {b.imag.str(5, radius=False)} (certified nonzero)")
            zero, _how = self._zero(_sub(node, alg.conj(node)))
            if not zero:
                raise AnalysisError(f"coefficient {k} ({_cut(self.exprs[k])}) is not real "
                                    "(its imaginary part is certified nonzero)")
            proofs += 1
        if proofs:
            rewrites = len(alg.identities)
            self.how.append(f"{proofs} coefficient(s) written with I or complex CRootOf proven "
                            f"real (x - conj(x) = 0 by the {_method_text(self._methods)}"
                            + (f"; {rewrites} conjugate atom(s) rewritten in the atoms by proven "
                               "identities" if rewrites else "") + ")")

    def _decide_sum_rules(self) -> None:
        n = len(self.nodes)
        methods_before = set(self._methods)
        self._methods = set()
        s1 = _n("add", (_linear([(1, x) for x in self.nodes]), _n("q", Fraction(-2))))
        zero, how = self._zero(s1)
        if not zero:
            self.failure = f"a(1) - 2 in {self._ball_text(s1, how)} != 0"
            self.sum_rules = 0
            return
        N = 0
        while N < n - 1:
            M = _linear([((-1) ** k * k ** N, x) for k, x in enumerate(self.nodes)])
            zero, how = self._zero(M)
            if not zero:
                if N == 0:
                    self.failure = f"a(-1) in {self._ball_text(M, how)} != 0"
                break
            N += 1
        self.sum_rules = N
        self.failure = None if N >= 1 else (self.failure or "a(-1) != 0")
        self.how.append(f"N = {N} decided exactly (a(1) = 2 and a^(j)(-1) = 0 for j < {N} by the "
                        f"{_method_text(self._methods)}; a^({N})(-1) != 0 by an Arb ball "
                        "excluding 0)")
        self._methods |= methods_before

    def _ball_text(self, node, how: dict) -> str:
        """A certified ball of a value proven nonzero, with a few correct digits."""
        prec = max(int(how.get("prec", 64)), 64)
        while True:
            alg = self.algebra
            v = alg.enclose(node, prec) if prec <= 4096 else alg._enclose(node, prec, {})
            part = v.real if v.imag.contains(0) else v
            if prec >= 1 << 16 or (not part.contains(0)
                                   and part.rad() < abs(part.mid()) * 2.0 ** -48):
                return part.str(12)
            prec *= 2

    # -- the ball route
    def enclosure(self, prec: int) -> list:
        with _deep_recursion():
            out = [self.algebra.enclose(node, prec + 64).real for node in self.nodes]
            rad = max(float(b.rad()) for b in out)
            if rad > 2.0 ** (-prec + 8):
                out = [self.algebra.enclose(node, 2 * prec + 128).real for node in self.nodes]
        return out

    def description(self, prec: int) -> tuple[str, str]:
        """``(source, message)`` for the provenance of a result computed on :meth:`enclosure`
        at ``prec`` bits: how N, ``a(1) = 2`` and reality were decided exactly."""
        source = f"exact algebraic mask enclosed in Arb balls at {prec} bits; " + "; ".join(self.how)
        message = ("exact algebraic mask enclosed in Arb balls at "
                   f"{prec} bits; N = {self.sum_rules} decided exactly by the zero test "
                   f"({_method_text(self.algebra.methods)})")
        return source, message


def _cut(e) -> str:
    s = sp.sstr(e, order="none")      # (sympy's default order evaluates CRootOfs numerically)
    return s if len(s) <= 50 else s[:47] + "..."


def needs_ball_route(mask: Sequence) -> bool:
    """Whether exact number-field arithmetic would likely be slow for this numeric mask: it is
    written with ``I``, ``CRootOf``, or atoms whose degree bound exceeds 16."""
    return ball_route_exprs(mask) is not None


def ball_route_exprs(mask: Sequence) -> list | None:
    """The coefficients of ``mask`` read (for :class:`ClosedFormMask`, which then need not read them again)
    when it :func:`needs_ball_route`; ``None`` otherwise (or when they cannot be read)."""
    from .symbol import parse_coefficient

    try:
        exprs = [parse_coefficient(c) for c in mask]
    except AnalysisError:
        return None
    if any(e.free_symbols for e in exprs) or all(e.is_Rational for e in exprs):
        return None
    if any(e.has(sp.I) or e.has(sp.CRootOf) for e in exprs):
        return exprs
    memo: dict = {}
    try:
        nodes = [_ir(e, memo) for e in exprs]
    except AnalysisError:
        return None
    return exprs if degree_bound(("add", tuple(nodes))) > 16 else None


def split_mask(text: str) -> list[str]:
    """Split a typed mask at the commas outside parentheses (``CRootOf(p, k)`` stays whole).

    >>> split_mask("1/2, CRootOf(x**2-2, 1)/2")
    ['1/2', 'CRootOf(x**2-2, 1)/2']
    """
    out, depth, cur = [], 0, []
    for ch in text:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            out.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    out.append("".join(cur).strip())
    if any(not x for x in out):
        raise AnalysisError("empty coefficient in mask")
    return out
