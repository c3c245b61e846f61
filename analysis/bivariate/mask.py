"""The bivariate mask: exact coefficients on ``Z^2``, a dilation matrix, free parameters.

Convention (:mod:`analysis.bivariate`): ``(S_a f)(alpha) = sum_beta a(alpha - M beta) f(beta)`` and
``a(z) = sum_alpha a(alpha) z1^alpha_1 z2^alpha_2``.

Three ways in, all through :mod:`analysis.algebra.reader` (no text reaches ``eval`` or sympy's parser):

* a symbol in ``z1, z2`` (a Laurent polynomial; other names are parameters):
  :meth:`BivariateMask.from_symbol`;
* a list ``i,j:coef`` separated by ``;`` or new lines: :meth:`BivariateMask.from_list`;
* a catalogue name (:mod:`schemes.surfaces`).

Examples
--------
>>> a = BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)")        # bilinear (tensor hat)
>>> a.support_box, a.total
(((-1, -1), (1, 1)), 4)
>>> a[(0, 0)], a[(1, 0)], a[(1, 1)]
(1, 1/2, 1/4)
>>> b = BivariateMask.from_list("0,0: 1; 1,0: 1", dilation="quincunx")    # the quincunx Haar mask
>>> b.dilation, b.symbol
(Dilation(quincunx), z1 + 1)
>>> c = BivariateMask.from_symbol("1 + w*z1")
>>> c.params, c.at(w="1/2")[(1, 0)]
((w,), 1/2)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Iterator, Mapping

import sympy as sp

from ..algebra.reader import LIMITS, as_expr, read_expression
from ..result import AnalysisError
from .dilation import Dilation, parse_dilation

__all__ = ["BivariateMask", "Z1", "Z2", "MAX_EXPONENT"]

Z1, Z2 = sp.symbols("z1 z2")
#: the largest |exponent| of a mask coefficient
MAX_EXPONENT = 40


@dataclass(frozen=True)
class BivariateMask:
    """Exact mask coefficients ``{(i, j): value}`` (nonzero only), the dilation and the free parameters."""

    coeffs: Mapping[tuple[int, int], sp.Expr]
    dilation: Dilation = field(default_factory=lambda: Dilation.named("dyadic"))
    name: str = ""

    def __post_init__(self):
        clean = {}
        for (i, j), v in self.coeffs.items():
            if isinstance(v, (float, sp.Float)):
                raise AnalysisError(f"the coefficient {i},{j} is a float; give it exactly (e.g. 1/16)")
            v = sp.expand(as_expr(v, what=f"coefficient {i},{j}"))
            if v != 0:
                clean[(int(i), int(j))] = v
        if not clean:
            raise AnalysisError("the mask is zero")
        if len(clean) > LIMITS.coefficients:
            raise AnalysisError(f"a mask has at most {LIMITS.coefficients} coefficients")
        if any(abs(x) > MAX_EXPONENT for ij in clean for x in ij):
            raise AnalysisError(f"mask indices are limited to |i|, |j| <= {MAX_EXPONENT}")
        for v in clean.values():
            if v.free_symbols & {Z1, Z2}:
                raise AnalysisError("a mask coefficient may not contain z1 or z2")
        object.__setattr__(self, "coeffs", dict(sorted(clean.items())))
        if isinstance(self.dilation, str):
            object.__setattr__(self, "dilation", parse_dilation(self.dilation))

    # -- readers -----------------------------------------------------------------------------
    @classmethod
    def from_symbol(cls, text: Any, dilation: Any = None, *, name: str = "") -> "BivariateMask":
        """The mask of a Laurent polynomial in ``z1, z2`` (text or a sympy expression)."""
        if isinstance(text, str):
            expr = read_expression(text, names={"z1": Z1, "z2": Z2}, what="symbol")
        elif isinstance(text, sp.Basic):
            expr = text
        else:
            raise AnalysisError("a symbol is a formula in z1, z2, e.g. (1+z1)**2*(1+z2)**2/(4*z1*z2)")
        not_laurent = ("the symbol must be a Laurent polynomial in z1, z2 (integer powers, a monomial denominator; "
                       "the parameters may appear anywhere in the coefficients), e.g. (1+z1)**2*(1+z2)**2/(4*z1*z2)")
        num, den = sp.fraction(sp.together(expr))
        c, mono = den.as_independent(Z1, Z2, as_Add=False)     # den = c(params) * z1^p z2^q, or not Laurent
        powers = mono.as_powers_dict()
        if set(powers) - {Z1, Z2, sp.Integer(1)} or not all(
                getattr(e, "is_Integer", False) and e >= 0 for b, e in powers.items() if b != 1):
            raise AnalysisError(not_laurent)
        p, q = int(powers.get(Z1, 0)), int(powers.get(Z2, 0))
        try:
            terms = sp.Poly(sp.expand(num), Z1, Z2).terms()
        except sp.PolynomialError:
            raise AnalysisError(not_laurent) from None
        coeffs = {}
        for (i, j), v in terms:
            v = sp.cancel(v / c)
            if v.has(Z1, Z2):
                raise AnalysisError(not_laurent)
            coeffs[(i - p, j - q)] = v
        return cls(coeffs, _dilation(dilation), name)

    @classmethod
    def from_list(cls, text: str, dilation: Any = None, *, name: str = "") -> "BivariateMask":
        """The mask ``i,j:coef; i,j:coef; ...`` (entries separated by ``;`` or new lines; repeated
        indices are an error)."""
        if not isinstance(text, str):
            raise AnalysisError("a mask list is text 'i,j:coef; i,j:coef', e.g. '0,0:1; 1,0:1'")
        coeffs: dict[tuple[int, int], sp.Expr] = {}
        entries = [e.strip() for e in text.replace("\n", ";").split(";") if e.strip()]
        if len(entries) > LIMITS.coefficients:
            raise AnalysisError(f"a mask has at most {LIMITS.coefficients} coefficients")
        for e in entries:
            if ":" not in e:
                raise AnalysisError(f"cannot read the mask entry {e[:40]!r}: type i,j:coef, e.g. 1,0:1/2")
            idx, val = e.split(":", 1)
            try:
                i, j = (int(x) for x in idx.split(","))
            except ValueError:
                raise AnalysisError(f"cannot read the index {idx[:40]!r}: type two integers i,j before ':'") from None
            if (i, j) in coeffs:
                raise AnalysisError(f"the index {i},{j} appears twice in the mask")
            coeffs[(i, j)] = read_expression(val.strip(), what=f"coefficient {i},{j}")
        return cls(coeffs, _dilation(dilation), name)

    # -- views -------------------------------------------------------------------------------
    def __getitem__(self, ij: tuple[int, int]) -> sp.Expr:
        return self.coeffs.get((int(ij[0]), int(ij[1])), sp.Integer(0))

    def __iter__(self) -> Iterator[tuple[tuple[int, int], sp.Expr]]:
        return iter(self.coeffs.items())

    @property
    def params(self) -> tuple[sp.Symbol, ...]:
        s = set()
        for v in self.coeffs.values():
            s |= v.free_symbols
        return tuple(sorted(s, key=lambda x: x.name))

    @property
    def support_box(self) -> tuple[tuple[int, int], tuple[int, int]]:
        xs = [i for i, _ in self.coeffs]
        ys = [j for _, j in self.coeffs]
        return (min(xs), min(ys)), (max(xs), max(ys))

    @property
    def total(self) -> sp.Expr:
        return sp.expand(sum(self.coeffs.values()))

    @property
    def symbol(self) -> sp.Expr:
        return sp.expand(sp.Add(*(v * Z1 ** i * Z2 ** j for (i, j), v in self.coeffs.items())))

    def at(self, values: Mapping[str, Any] | None = None, **kw: Any) -> "BivariateMask":
        """The mask with parameters replaced by exact values (text through the reader)."""
        vals = dict(values or {}, **kw)
        subs = {}
        names = {p.name: p for p in self.params}
        for k, v in vals.items():
            if k not in names:
                raise AnalysisError(f"the mask has no parameter {k!r}" +
                                    (f"; its parameters: {', '.join(names)}" if names else ""))
            subs[names[k]] = (read_expression(v, free=False, what=f"value of {k}") if isinstance(v, str)
                              else as_expr(v, what=f"value of {k}"))
        coeffs = {}
        for ij, v in self.coeffs.items():
            num, den = sp.fraction(sp.cancel(v))
            if den.subs(subs) == 0:
                raise AnalysisError("the coefficient " + f"{ij[0]},{ij[1]} has a pole at "
                                    + ", ".join(f"{k} = {sp.sstr(x)}" for k, x in subs.items())
                                    + ": the mask is not defined there; give another value")
            coeffs[ij] = v.subs(subs)
        return BivariateMask(coeffs, self.dilation, self.name)

    def grid(self) -> list[list[sp.Expr]]:
        """The coefficients as rows ``j = max .. min`` (top to bottom) of columns ``i = min .. max``."""
        (i0, j0), (i1, j1) = self.support_box
        return [[self[(i, j)] for i in range(i0, i1 + 1)] for j in range(j1, j0 - 1, -1)]

    def __repr__(self) -> str:
        return f"BivariateMask({sp.sstr(sp.factor(self.symbol))}, {self.dilation!r})"


def _dilation(d: Any) -> Dilation:
    if isinstance(d, Dilation):
        return d
    if d is None or isinstance(d, str):
        return parse_dilation(d)
    return Dilation(d)
