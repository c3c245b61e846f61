"""Algebraic expressions as a small hashable IR (shared subexpressions evaluated once): atoms,
the tower degree bound, the Burnikel–Fleischer–Mehlhorn–Schirra bounds and printing.

The zero test that uses them is :mod:`analysis.algebra.zero_test` (see there for the
meaning of each bound and why it is sound).
"""

from __future__ import annotations

import contextlib
import sys
from fractions import Fraction

import flint
import sympy as sp

from ..result import AnalysisError


#: Largest precision (bits) the root-separation step may use before it gives up.
MAX_ZERO_BITS = 1 << 20


#: The formal identity step gives up (falls through to root separation) on polynomials with more
#: terms than this.
FORMAL_MAX_TERMS = 200_000


class _Node(tuple):
    """An IR node: a tuple whose hash is computed once (nodes are nested deeply and used as
    dictionary keys everywhere; a plain tuple would rehash its whole subtree at each lookup)."""

    def __hash__(self):
        try:
            return self._h
        except AttributeError:
            self._h = tuple.__hash__(self)
            return self._h


def _n(*parts) -> _Node:
    return _Node(parts)


_I = _n("i")
_MINUS1 = _n("q", Fraction(-1))


class Undecided(AnalysisError):
    """The zero test would need more than :data:`MAX_ZERO_BITS` bits."""


class _TooBig(Exception):
    """The formal identity step outgrew :data:`FORMAL_MAX_TERMS`."""


def _neg(node):
    return _n("mul", (_MINUS1, node))


def _sub(x, y):
    return _n("add", (x, _neg(y)))


def _rootof_node(e) -> tuple:
    poly = e.poly
    if not poly.domain.is_ZZ and not poly.domain.is_QQ:
        raise AnalysisError(f"{sp.sstr(e)}: only roots of rational polynomials are supported")
    coeffs = [sp.Rational(c) for c in poly.all_coeffs()]
    den = sp.ilcm(*[c.q for c in coeffs]) if coeffs else 1
    return _n("rootof", tuple(int(c * den) for c in coeffs), int(e.index), e)


def _ir(e: sp.Expr, memo: dict):
    if e in memo:
        return memo[e]
    if e.is_Rational:
        node = ("q", Fraction(int(e.p), int(e.q)))
    elif e is sp.I:
        node = _I
    elif e.is_Add:
        node = ("add", tuple(_ir(t, memo) for t in e.args))
    elif e.is_Mul:
        node = ("mul", tuple(_ir(t, memo) for t in e.args))
    elif e.is_Pow and e.exp.is_Rational:
        b = _ir(e.base, memo)
        p, q = int(e.exp.p), int(e.exp.q)
        if q != 1:
            b = _n("root", b, q)
        node = b if p == 1 else ("pow", b, p)
    elif isinstance(e, sp.CRootOf):
        node = _rootof_node(e)
    else:
        raise AnalysisError(f"{sp.sstr(e)} is not an exact algebraic number written with +, -, *, /, "
                            "rational powers, I and CRootOf")
    node = node if isinstance(node, _Node) else _Node(node)
    memo[e] = node
    return node


def _atom_closure(node, out: dict, seen: set) -> None:
    """The atoms of ``node`` and of the bases of its roots, every base's atoms before its root."""
    if id(node) in seen:
        return
    seen.add(id(node))
    kind = node[0]
    if kind == "i":
        out[node] = None
    elif kind in ("add", "mul"):
        for t in node[1]:
            _atom_closure(t, out, seen)
    elif kind == "pow":
        _atom_closure(node[1], out, seen)
    elif kind == "root":
        _atom_closure(node[1], out, seen)
        out[node] = None
    elif kind == "cjroot":
        _atom_closure(node[2], out, seen)
        out[node] = None
    elif kind == "rootof":
        out[node] = None


def _atoms_of(node) -> list:
    out: dict = {}
    _atom_closure(node, out, set())
    return list(out)


def degree_bound(node) -> int:
    """An upper bound ``D`` of the degree of a field containing the value of ``node``: the tower
    bound over its atoms (module docstring, "Zero test", step 3).

    >>> import sympy as sp
    >>> degree_bound(_ir(sp.sqrt(2) + sp.I * sp.sqrt(3), {}))
    8
    """
    D = 1
    groups: dict = {}
    for a in _atoms_of(node):
        kind = a[0]
        if kind == "i":
            D *= 2
        elif kind == "root":
            D *= a[2]
        elif kind == "cjroot":
            D *= a[3]
        else:   # rootof: count the distinct roots of each polynomial
            groups.setdefault(a[1], set()).add(a[2])
    for coeffs, idx in groups.items():
        n = len(coeffs) - 1
        for j in range(min(len(idx), n)):
            D *= n - j
    return D


def _bounds(node, memo: dict):
    """``(U, L)`` as Arb balls (upper bounds over all conjugates of ``u`` and ``l``, ``x = u/l``)."""
    if node in memo:
        return memo[node]
    kind = node[0]
    one = flint.arb(1)
    if kind == "q":
        out = (flint.arb(abs(node[1].numerator)), flint.arb(node[1].denominator))
    elif kind == "i":
        out = (one, one)
    elif kind == "add":
        U, L = _bounds(node[1][0], memo)
        for t in node[1][1:]:
            U2, L2 = _bounds(t, memo)
            U, L = U * L2 + U2 * L, L * L2
        out = (U, L)
    elif kind == "mul":
        U, L = one, one
        for t in node[1]:
            U2, L2 = _bounds(t, memo)
            U, L = U * U2, L * L2
        out = (U, L)
    elif kind == "pow":
        U, L = _bounds(node[1], memo)
        n = node[2]
        out = (U ** n, L ** n) if n >= 0 else (L ** (-n), U ** (-n))
    elif kind in ("root", "cjroot"):
        U, L = _bounds(node[1] if kind == "root" else node[2], memo)     # the base whose root it is
        k = node[-1]
        out = ((U * L ** (k - 1)).root(k), L)
    elif kind == "rootof":
        c = node[1]
        lc = abs(c[0])
        cauchy = 1 + max((Fraction(abs(x), lc) for x in c[1:]), default=Fraction(0))
        out = (flint.arb(lc) * flint.arb(flint.fmpq(cauchy.numerator, cauchy.denominator)), flint.arb(lc))
    else:  # pragma: no cover
        raise AssertionError(kind)
    memo[node] = out
    return out


def _short(node, width: int = 60) -> str:
    """The start of the expression, for messages (rendered from the IR, never the whole tree:
    printing a large sympy expression with CRootOf sorts its terms numerically, which is slow)."""
    out: list[str] = []
    budget = [width + 1]

    def emit(text: str) -> None:
        if budget[0] > 0:
            out.append(text)
            budget[0] -= len(text)

    def walk(n) -> None:
        if budget[0] <= 0:
            return
        kind = n[0]
        if kind == "q":
            emit(str(n[1]) if n[1] >= 0 else f"({n[1]})")
        elif kind == "i":
            emit("I")
        elif kind in ("add", "mul"):
            emit("(")
            for j, t in enumerate(n[1]):
                if j:
                    emit(" + " if kind == "add" else "*")
                walk(t)
            emit(")")
        elif kind == "pow":
            walk(n[1])
            emit(f"**{n[2]}" if n[2] >= 0 else f"**({n[2]})")
        elif kind == "root":
            emit("sqrt(" if n[2] == 2 else "(")
            walk(n[1])
            emit(")" if n[2] == 2 else f")**(1/{n[2]})")
        elif kind == "cjroot":
            emit("conjugate(")
            walk(_n("root", n[1], n[3]))
            emit(")")
        else:
            emit(f"CRootOf({sp.sstr(n[3].poly.as_expr())}, {n[2]})")

    walk(node)
    s = "".join(out)
    return s if len(s) < width else s[:width - 3] + "..."


@contextlib.contextmanager
def _deep_recursion(limit: int = 10000):
    """Closed forms pasted from a CAS nest deeply; the IR is walked recursively."""
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, limit))
    try:
        yield
    finally:
        sys.setrecursionlimit(old)


def _guess_rational(x: flint.arb, max_den: int = 1 << 64) -> Fraction | None:
    """A rational with denominator ``<= max_den`` inside the ball ``x`` (a guess, to be proven)."""
    if not x.is_finite() or x.rad() > 2.0 ** -150:
        return None
    man, exp = x.mid().man_exp()
    f = Fraction(int(man)) * (Fraction(2) ** int(exp))
    g = f.limit_denominator(max_den)
    with flint.ctx.workprec(1024):
        return g if (x - flint.fmpq(g.numerator, g.denominator)).contains(0) else None


def _rational_root(R: Fraction, k: int) -> Fraction | None:
    """The positive rational ``k``-th root of ``R > 0`` if it exists.

    >>> _rational_root(Fraction(27, 941192000), 3), _rational_root(Fraction(2), 2)
    (Fraction(3, 980), None)
    """
    if R <= 0:
        return None
    num, ok1 = sp.integer_nthroot(R.numerator, k)
    den, ok2 = sp.integer_nthroot(R.denominator, k)
    return Fraction(int(num), int(den)) if ok1 and ok2 else None
