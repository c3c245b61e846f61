"""Claim kind ``limit symmetry``: the basic limit function ``phi`` is symmetric (about a printed
centre; primal or dual), decided exactly from the mask; binary and m-ary.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> S = {"c": SchemeSpec("c", LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2))}
>>> v = LimitSymmetry({"centre": "-1/2", "type": "dual"}, S, "x").evaluate()
>>> v.label, v.numbers[0].value
('CERTIFIED TRUE', -1/2)
>>> v = LimitSymmetry({"centre": 0, "type": "primal"}, S, "x").evaluate()
>>> v.label, v.corrected
('REFUTED', 'phi is symmetric about -1/2 (dual: a half-integer centre)')

Algorithm
---------
With ``a(1) = m`` the refinement equation ``phi = sum_k a_k phi(m . - k)`` has exactly one compactly
supported distribution solution with ``phi^(0) = 1`` (it is the basic limit function whenever the
scheme converges), with support ``[s, e]/(m-1)``. ``psi = phi(2c - .)`` solves the equation with
the mask ``b_k = a_((m-1) 2c - k)``, so by uniqueness ``phi`` is symmetric about ``c`` iff the
mask is symmetric, ``a_k = a_(s+e-k)``, and then ``c = (s+e)/(2(m-1))``, the midpoint of the
support (the mask centre divided by ``m-1``). Conversely, if ``phi`` is symmetric about some
``c``, ``a(e^(-i xi)) e^(i (m-1) 2c xi / 2)`` is real wherever ``phi^(xi) != 0``, an open set
around 0, hence everywhere (a trigonometric polynomial): the mask is symmetric. So symmetry of
``phi`` is decided exactly by :func:`analysis.algebra.factorization.symmetry`. "Primal" means an
integer centre (vertex-centred), "dual" a half-integer one.

References
----------
I. Daubechies, J. C. Lagarias, *Two-scale difference equations I*, SIAM J. Math. Anal. 22 (1991);
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Sect. 2;
C. Conti, K. Hormann, J. Approx. Theory 163 (2011) (primal/dual, arity m).
"""

from __future__ import annotations

import sympy as sp

from ...algebra.factorization import symmetry
from ...result import AnalysisError
from ..model import Number, Verdict, exact_result
from .base import Kind, evidence
from ...algebra.reader import as_expr

__all__ = ["LimitSymmetry"]


def centre_type(c) -> str:
    """``primal`` (integer centre), ``dual`` (half-integer) or the centre modulo 1."""
    if as_expr(c).is_integer:
        return "primal"
    if as_expr(2 * c).is_integer:
        return "dual"
    return f"neither (centre in Z + {sp.sstr(c - sp.floor(c))})"


_TYPE_TEXT = {"primal": "primal: an integer centre", "dual": "dual: a half-integer centre"}


class LimitSymmetry(Kind):
    """The basic limit function is symmetric about ``centre`` (our indexing), of ``type`` primal/dual."""

    name = "limit symmetry"
    summary = "the basic limit function phi is symmetric (about the centre; primal or dual), exact from the mask"
    optional = {"symmetric": "true (default) or false", "centre": "claimed centre of phi (our indexing)",
                "type": "'primal' (integer centre) or 'dual' (half-integer)", "at": "parameter values"}
    example = 'centre = 0\ntype = "primal"'
    any_arity = True

    def check(self) -> None:
        self.values()
        self.number("centre")
        self.boolean("symmetric", True)
        if self.get("type", "primal") not in ("primal", "dual"):
            raise AnalysisError(f"{self.where}: field 'type' must be 'primal' or 'dual'")

    def evaluate(self) -> Verdict:
        a, m = self.symbol(), self.arity
        a1 = sp.simplify(sum(a.mask))
        if sp.simplify(a1 - m) != 0:
            return self.inconclusive(f"a(1) = {sp.sstr(a1)}, not {m}: the mask has no normalised refinable "
                                     "function (no basic limit function to be symmetric)",
                                     settle=f"a mask with a(1) = {m}",
                                     evidence=[evidence("a(1)", exact_result(a1, "exact sum of the mask"))])
        r = symmetry(a)
        c = sp.Rational(a.start + a.end, 2 * (m - 1))          # midpoint of supp phi = [s, e]/(m-1)
        kind = centre_type(c)
        want, centre, typ = self.get("symmetric", True), self.number("centre"), self.get("type")
        ev = [evidence("exact comparison a_k = a_(s+e-k) (symmetry of phi <=> of the mask, a(1) = m)", r,
                       text=f"a(1) = {m}; mask [{a.start}, {a.end}] symmetric: {bool(r.value)}; "
                            f"supp phi = [{sp.sstr(sp.Rational(a.start, m - 1))}, {sp.sstr(sp.Rational(a.end, m - 1))}], "
                            f"midpoint {sp.sstr(c)} (mask centre {sp.sstr(sp.Rational(a.start + a.end, 2))} / {m - 1})")]
        nums = [Number("centre", c), Number("symmetric", bool(r.value))]
        if r.value:
            fact = f"phi is symmetric about {sp.sstr(c)} ({_TYPE_TEXT.get(kind, kind)})"
        else:
            sol = r.witness.get("solutions")
            fact = "phi is symmetric about no point (the mask is not symmetric)" + (
                f"; it is for {sol}" if sol else "")
        wrong = bool(r.value) != want or (r.value and centre is not None and sp.simplify(centre - c) != 0) or (
            r.value and typ is not None and typ != kind)
        claimed = ("symmetric" + (f" about {sp.sstr(centre)}" if centre is not None else "")
                   + (f" ({typ})" if typ else "")) if want else "not symmetric"
        where = self.where_text()
        if wrong:
            return self.refuted(f"{fact} ({where}), not {claimed}", corrected=fact, evidence=ev, numbers=nums)
        return self.certified(f"{fact} ({where}; exact)", evidence=ev, numbers=nums,
                              sharpness=None if r.value or not r.witness.get("solutions") else
                              f"symmetric only at {r.witness['solutions']}")
