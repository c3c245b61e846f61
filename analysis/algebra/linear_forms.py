"""Symbolic derivations of refinement rules from a paper's construction, and of end rules.

Papers build schemes by combining rules ("translate the points of scheme Q by a combination of
displacement vectors Q - R") and derive end rules for open polygons by substituting ghost
points. Both are exact linear algebra on *linear forms* in the control points ``P_{i+p}``; this
module performs them in sympy so that a printed rule can be compared with the derived one
coefficient by coefficient.

A rule is a :class:`LinearForm`: a mapping ``offset -> coefficient`` meaning
``sum_p c_p P_{i+p}`` (relative to a symbolic centre index ``i``), or, for end rules, a mapping
from absolute index labels (``0, 1, ...`` and ``n-3, ..., n``) to coefficients.

Examples
--------
Seed 004, Steps 1-4: ``P_{2i} = Q_{2i} - (mu D_{2i-2} + nu D_{2i} + omega D_{2i+2})``:

>>> import sympy as sp
>>> mu, nu, omega = sp.symbols("mu nu omega")
>>> Q = LinearForm({-1: sp.Rational(-7, 128), 0: sp.Rational(105, 128),
...                 1: sp.Rational(35, 128), 2: sp.Rational(-5, 128)})
>>> R = LinearForm({-1: sp.Rational(7, 64), 0: sp.Rational(35, 64),
...                 1: sp.Rational(21, 64), 2: sp.Rational(1, 64)})
>>> D = Q - R
>>> D.coefficients()
(-21/128, 35/128, -7/128, -7/128)
>>> E = Q - (D.shift(-1) * mu + D * nu + D.shift(1) * omega)
>>> E[0]
7*mu/128 - 35*nu/128 + 21*omega/128 + 105/128
>>> E.offsets(), E[3]
((-2, -1, 0, 1, 2, 3), 7*omega/128)

Reading garbled coefficients (extraction dropped minus signs, e.g. ``"21μ+7ν+7ω5"``):

>>> [sp.sstr(c) for c in read_garbled_linear("21μ+7ν+7ω5", {"μ": mu, "ν": nu, "ω": omega})]
['21*mu + 7*nu + 7*omega - 5', '-21*mu + 7*nu + 7*omega - 5']

Algorithm
---------
Linear forms are dictionaries of exact sympy coefficients; shifting re-indexes, substitution of
a ghost point ``P_g = sum_j w_j P_j`` moves ``c_g`` onto the ``P_j``. Everything is exact.

References
----------
Seed paper 004, *Modeling of curves by a design-control approximating refinement scheme* (2023),
Sect. 3.1-3.7 (construction Steps 1-4 and end rules (3.9)-(3.10)).
"""

from __future__ import annotations

import re
from typing import Iterable, Mapping

import sympy as sp
from .reader import as_expr

__all__ = ["LinearForm", "P", "I_SYM", "N_SYM", "ghost_substitute", "read_garbled_linear",
           "displacement_construction",
           "end_rules"]

#: The control points ``P[j]`` and the symbolic indices ``i`` (centre) and ``n`` (last point).
P = sp.IndexedBase("P")
I_SYM = sp.Symbol("i", integer=True)
N_SYM = sp.Symbol("n", integer=True)


class LinearForm:
    """An exact linear form ``sum_p c_p P_{base+p}`` (immutable; keys are integer offsets).

    ``base`` is a sympy expression (``i`` for rules, ``0`` or ``n`` for end rules).
    """

    __slots__ = ("_c", "base")

    def __init__(self, coeffs: Mapping[int, object], base=I_SYM):
        self._c = {int(k): sp.expand(as_expr(v)) for k, v in coeffs.items()
                   if sp.expand(as_expr(v)) != 0}
        self.base = as_expr(base)

    # ------------------------------------------------------------------ access
    def __getitem__(self, p: int):
        return self._c.get(int(p), sp.Integer(0))

    def items(self):
        return sorted(self._c.items())

    def offsets(self) -> tuple[int, ...]:
        return tuple(sorted(self._c))

    def coefficients(self) -> tuple:
        """The coefficients from the lowest to the highest offset (zeros inside kept)."""
        if not self._c:
            return ()
        lo, hi = min(self._c), max(self._c)
        return tuple(self[p] for p in range(lo, hi + 1))

    # ------------------------------------------------------------------ algebra
    def _check(self, other: "LinearForm") -> None:
        if sp.simplify(self.base - other.base) != 0:
            raise ValueError("linear forms with different bases")

    def __add__(self, other: "LinearForm") -> "LinearForm":
        self._check(other)
        keys = set(self._c) | set(other._c)
        return LinearForm({k: self[k] + other[k] for k in keys}, self.base)

    def __sub__(self, other: "LinearForm") -> "LinearForm":
        return self + other * -1

    def __mul__(self, s) -> "LinearForm":
        return LinearForm({k: v * s for k, v in self._c.items()}, self.base)

    __rmul__ = __mul__

    def __eq__(self, other) -> bool:
        if not isinstance(other, LinearForm):
            return NotImplemented
        keys = set(self._c) | set(other._c)
        return (sp.simplify(self.base - other.base) == 0
                and all(sp.expand(self[k] - other[k]) == 0 for k in keys))

    def __hash__(self):  # pragma: no cover - forms are compared, not hashed
        return hash(tuple(self.items()))

    def shift(self, s: int) -> "LinearForm":
        """The same form with every index raised by ``s`` (``P_{i+p} -> P_{i+p+s}``)."""
        return LinearForm({k + s: v for k, v in self._c.items()}, self.base)

    def subs(self, values: Mapping) -> "LinearForm":
        return LinearForm({k: sp.expand(v.subs(values)) for k, v in self._c.items()}, self.base)

    def rebase(self, base) -> "LinearForm":
        """The same points written relative to another base: offsets change by ``old - new``."""
        d = sp.simplify(self.base - as_expr(base))
        if not d.is_Integer:
            raise ValueError(f"cannot rebase {self.base} to {base}")
        return LinearForm({k + int(d): v for k, v in self._c.items()}, base)

    def total(self):
        """``sum_p c_p``: 1 for an affine-invariant rule."""
        return sp.expand(sum(self._c.values(), sp.Integer(0)))

    # ------------------------------------------------------------------ printing
    def to_expr(self) -> sp.Expr:
        return sp.Add(*[v * P[self.base + k] for k, v in self.items()])

    def label(self, p: int) -> str:
        """``'P[i-1]'``-style label of offset ``p``."""
        return sp.sstr(P[self.base + p])

    def latex(self) -> str:
        parts = []
        for k, v in self.items():
            c = sp.latex(v)
            if isinstance(v, sp.Add):
                c = rf"\left({c}\right)"
            parts.append(f"{c}\\,P_{{{sp.latex(self.base + k)}}}")
        return " + ".join(parts).replace("+ -", "- ") if parts else "0"

    def __repr__(self) -> str:
        return f"LinearForm({dict(self.items())}, base={self.base})"


def ghost_substitute(form: LinearForm, ghosts: Mapping[int, LinearForm]) -> LinearForm:
    """Replace the points ``P_{base+g}`` (``g`` in ``ghosts``) by the given forms (same base).

    >>> f = LinearForm({-1: 1, 0: 2}, base=0)          # P_{-1} + 2 P_0
    >>> ghost_substitute(f, {-1: LinearForm({0: 2, 1: -1}, base=0)}).items()
    [(0, 4), (1, -1)]
    """
    out = LinearForm({k: v for k, v in form.items() if k not in ghosts}, form.base)
    for g, repl in ghosts.items():
        c = form[g]
        if c != 0:
            out = out + repl.rebase(form.base) * c
    return out


def end_rules(even: LinearForm, odd: LinearForm, *, left_ghosts: Iterable[int] = (1, 2),
              right_ghosts: Iterable[int] = (1, 2, 3), left_i: Iterable[int] = (0, 1),
              right_i: Iterable[int] = (-2, -1, 0)) -> dict[str, LinearForm]:
    """End rules of an open polygon ``P_0..P_n`` by ghost points (seed 004, (3.9)-(3.10)).

    ``P_{-m} = 2 P_0 - P_m`` for ``m`` in ``left_ghosts`` and ``P_{n+m} = 2 P_n - P_{n-m}`` for
    ``m`` in ``right_ghosts`` are substituted into the even/odd rules ``P_{2i}, P_{2i+1}`` at
    ``i`` in ``left_i`` (absolute) and ``i = n + r``, ``r`` in ``right_i``. Returns
    ``{"P_{2i+e}": form}`` with labels ``"P0", "P1", ..., "P2n-4", ..., "P2n+1"``; left forms
    have base 0, right forms base ``n``.

    >>> e = LinearForm({-1: sp.Rational(1, 2), 0: sp.Rational(1, 2)})
    >>> o = LinearForm({0: 1})
    >>> end_rules(e, o, left_ghosts=(1,), right_ghosts=(), left_i=(0,), right_i=())["P0"].items()
    [(0, 3/2), (1, -1/2)]
    """
    out: dict[str, LinearForm] = {}
    left = {-m: LinearForm({0: 2, m: -1}, base=0) for m in left_ghosts}
    right = {m: LinearForm({0: 2, -m: -1}, base=N_SYM) for m in right_ghosts}
    for i in left_i:
        for eps, rule in ((0, even), (1, odd)):
            f = LinearForm(dict(rule.items()), base=0).shift(i)
            out[f"P{2 * i + eps}"] = ghost_substitute(f, left)
    for r in right_i:
        for eps, rule in ((0, even), (1, odd)):
            f = LinearForm(dict(rule.items()), base=N_SYM).shift(r)
            k = 2 * r + eps
            lab = "P2n" + ("" if k == 0 else (f"+{k}" if k > 0 else f"{k}"))
            out[lab] = ghost_substitute(f, right)
    return out


_TERM = re.compile(r"(\+?)(\d+)([^\d+\s]?)")


def read_garbled_linear(text: str, symbols: Mapping[str, sp.Symbol]) -> tuple[sp.Expr, sp.Expr]:
    """The two readings of a linear coefficient whose minus signs were lost in extraction.

    ``text`` is a sequence of terms ``<integer><symbol?>`` joined by ``+`` or by nothing; a
    missing operator between two terms is a lost ``-`` (the only operator that can vanish),
    and the sign of the first term is unknown. Returns ``(reading with leading +, with leading
    -)``.

    >>> mu, nu = sp.symbols("mu nu")
    >>> read_garbled_linear("7μ42ν+14", {"μ": mu, "ν": nu})
    (7*mu - 42*nu + 14, -7*mu - 42*nu + 14)
    """
    t = text.replace(" ", "").replace("×", "")
    pos, terms = 0, []
    while pos < len(t):
        m = _TERM.match(t, pos)
        if not m or m.end() == pos:
            raise ValueError(f"cannot read garbled coefficient {text!r} at {t[pos:]!r}")
        plus, num, sym = m.groups()
        if sym and sym not in symbols:
            raise ValueError(f"unknown symbol {sym!r} in {text!r}")
        val = sp.Integer(int(num)) * (symbols[sym] if sym else 1)
        terms.append((plus == "+" or not terms, val, bool(terms)))
        pos = m.end()
    rest = sp.Integer(0)
    for plus, val, not_first in terms[1:]:
        rest += val if plus else -val
    first = terms[0][1]
    return (sp.expand(first + rest), sp.expand(-first + rest))


def displacement_construction(Q_even: LinearForm, Q_odd: LinearForm, R_even: LinearForm,
                              R_odd: LinearForm, weights_even: Mapping[int, object],
                              weights_odd: Mapping[int, object]) -> dict[str, LinearForm]:
    """Steps 1-4 of a "translate Q by displacement vectors Q - R" construction (seed 004, Sect. 3).

    Step 2: ``D_{2i} = Q_{2i} - R_{2i}``, ``D_{2i+1} = Q_{2i+1} - R_{2i+1}`` and their shifts
    ``D_{2i+2s} = D_{2i}`` with indices raised by ``s`` (likewise for odd ones). Step 3:
    ``DE = sum_s w_s D_{2i+2s}`` (``weights_even``), ``DO = sum_s w'_s D_{2i+1+2s}``
    (``weights_odd``). Step 4: ``P_{2i} = Q_{2i} - DE``, ``P_{2i+1} = Q_{2i+1} - DO``.

    Returns every intermediate form: ``"D_{2i}"``, ``"D_{2i+1}"``, the shifted ones (``"D_{2i-2}"``
    ...), ``"DE"``, ``"DO"``, ``"P_{2i}"``, ``"P_{2i+1}"``.

    >>> h = sp.Rational(1, 2)
    >>> out = displacement_construction(LinearForm({0: 1}), LinearForm({0: h, 1: h}),
    ...                                 LinearForm({0: h, 1: h}), LinearForm({0: 1}), {0: 1}, {0: 1})
    >>> out["P_{2i}"].items(), out["P_{2i+1}"].items()         # Q - (Q - R) = R
    ([(0, 1/2), (1, 1/2)], [(0, 1)])
    """
    D0, D1 = Q_even - R_even, Q_odd - R_odd
    out = {"D_{2i}": D0, "D_{2i+1}": D1}
    DE = LinearForm({}, Q_even.base)
    DO = LinearForm({}, Q_odd.base)
    for s, w in sorted(weights_even.items()):
        if s:
            out[f"D_{{2i{2 * s:+d}}}"] = D0.shift(s)
        DE = DE + D0.shift(s) * w
    for s, w in sorted(weights_odd.items()):
        if s:
            out[f"D_{{2i{2 * s + 1:+d}}}"] = D1.shift(s)
        DO = DO + D1.shift(s) * w
    out.update({"DE": DE, "DO": DO, "P_{2i}": Q_even - DE, "P_{2i+1}": Q_odd - DO})
    return out
