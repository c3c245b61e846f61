"""Claim kind ``support after steps``: the support of the mask of ``S_a^L`` (L refinement steps) and
of the basic limit function, exact, against the printed interval; binary and m-ary.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> chaikin = {"c": SchemeSpec("c", LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2))}
>>> SupportAfterSteps({"steps": 3, "support": [-14, 7]}, chaikin, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = SupportAfterSteps({"steps": 2, "support": [-2, 1], "of": "scaled"}, chaikin, "x").evaluate()
>>> v.label, v.numbers[0].value, v.numbers[1].value
('REFUTED', -3/2, 3/4)

Algorithm
---------
After L steps of ``(S_a f)_i = sum_j a_(i-mj) f_j`` applied to delta, the data are the coefficients
of ``a_L(z) = a(z) a(z^m) ... a(z^(m^(L-1)))`` (:meth:`LaurentSymbol.upsample`); for a mask with
support ``[s, e]`` its support is ``[s (m^L-1)/(m-1), e (m^L-1)/(m-1)]`` (end coefficients
``a_s^L, a_e^L`` are non-zero: no cancellation in a product of Laurent polynomials over a field).
The product is also formed explicitly (up to 20,000 coefficients, 1,000 with free parameters) and its
support read off, a second, independent computation. Scaled to level-0 units (divide by ``m^L``) it is
``(1 - m^-L) [s, e]/(m-1)``, increasing to the support ``[s, e]/(m-1)`` of the basic limit function
(:func:`analysis.stationary.transition.basic_limit_support`). With parameters the support is the
generic one; parameter values where ``a_s`` or ``a_e`` vanish are listed.

References
----------
A. S. Cavaretta, W. Dahmen, C. A. Micchelli, *Stationary subdivision*, Mem. AMS 93 (1991), Sect. 2;
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Sect. 2.
"""

from __future__ import annotations

import sympy as sp

from ...result import AnalysisError
from ...stationary.transition import basic_limit_support
from ..model import Number, Verdict, exact_result
from .base import Kind, evidence, parse_number

__all__ = ["SupportAfterSteps"]

#: the explicit product a(z) a(z^m) ... is formed only up to this many coefficients (fewer with parameters)
MAX_EXPLICIT, MAX_EXPLICIT_PARAMS = 20000, 1000
#: the largest L accepted (the end points have about L log10(m) digits)
MAX_STEPS = 64


def _iv(lo, hi) -> str:
    return f"[{sp.sstr(lo)}, {sp.sstr(hi)}]"


class SupportAfterSteps(Kind):
    """The support after ``steps`` refinement steps (mask of S^L, or scaled by m^-L) and of phi."""

    name = "support after steps"
    summary = "support of the mask of S^L (a(z)a(z^m)...a(z^(m^(L-1)))) or of S^L delta in level-0 units, and of the limit function"
    required = {"steps": "L >= 1 refinement steps", "support": "[s, e] as printed"}
    optional = {"of": "'mask' (default: indices of S^L delta) or 'scaled' (divided by m^L: level-0 units)",
                "at": "parameter values"}
    example = 'steps = 2\nsupport = [-9, 9]'
    any_arity = True

    OF = ("mask", "scaled")

    def check(self) -> None:
        self.values()
        if self.integer("steps", 1) > MAX_STEPS:
            raise AnalysisError(f"{self.where}: field 'steps' must be at most {MAX_STEPS}")
        if self.get("of", "mask") not in self.OF:
            raise AnalysisError(f"{self.where}: field 'of' must be one of {', '.join(self.OF)}")
        s = self.get("support")
        if not isinstance(s, list) or len(s) != 2:
            raise AnalysisError(f"{self.where}: field 'support' must be [s, e]")
        self.claimed = tuple(parse_number(x, f"{self.where}: support") for x in s)

    def evaluate(self) -> Verdict:
        a, m, L = self.symbol(), self.arity, self.integer("steps", 1)
        s, e = a.start, a.end
        geo = (m ** L - 1) // (m - 1)
        mask_iv = (s * geo, e * geo)
        explicit = None
        limit = MAX_EXPLICIT_PARAMS if a.params else MAX_EXPLICIT
        if (e - s) * geo + 1 <= limit:
            prod = a
            for k in range(1, L):
                prod = prod * a.upsample(m ** k)
            explicit = (prod.start, prod.end)
        scaled = (sp.Rational(mask_iv[0], m ** L), sp.Rational(mask_iv[1], m ** L))
        lim = basic_limit_support(a, arity=m)
        phi = (sp.Rational(s, m - 1), sp.Rational(e, m - 1))
        of = self.get("of", "mask")
        true = mask_iv if of == "mask" else scaled
        ok = explicit in (None, mask_iv) and all(sp.simplify(x - y) == 0 for x, y in zip(self.claimed, true))
        if explicit is not None and explicit != mask_iv:        # the two computations disagree: no verdict
            return self.inconclusive(f"the explicit product has support {_iv(*explicit)}, the formula {_iv(*mask_iv)}",
                                     settle="an exact recomputation of a(z)a(z^m)...")
        prod_txt = " ".join(f"a(z^{m ** k})" if k else "a(z)" for k in range(min(L, 4))) + (" ..." if L > 4 else "")
        exc = lim.witness.get("exceptional") or {}
        pname = f"{a.params[0]} = " if len(a.params) == 1 else ""
        exc_txt = ("; ".join(f"{pname}{sp.sstr(k)}: {_iv(*v)}" for k, v in exc.items()) if isinstance(exc, dict)
                   else str(exc))
        r = exact_result({"mask": mask_iv, "scaled": scaled, "limit function": phi},
                         "exact: support of a(z)a(z^m)...a(z^(m^(L-1)))", explicit_product=explicit)
        ev = [evidence(f"support after {L} step{'s' if L > 1 else ''}, arity {m}", r,
                       text=f"mask [{s}, {e}]; {prod_txt}: {_iv(*mask_iv)} ("
                            + ("the explicit product agrees" if explicit else "formula; the product has more than "
                               f"{limit} coefficients") + f"); scaled by {m}^-{L}: {_iv(*scaled)}; "
                            f"basic limit function: {_iv(*phi)}"),
              evidence("basic limit function (convex hull of its support)", lim, text=f"{_iv(*lim.value)} (arity {m})")]
        nums = [Number(f"support after {L} steps start", true[0]), Number(f"support after {L} steps end", true[1]),
                Number("limit function start", phi[0]), Number("limit function end", phi[1])]
        fact = (f"after {L} step{'s' if L > 1 else ''} the {'scaled support (level-0 units)' if of == 'scaled' else 'mask support'} of "
                f"{self.where_text()} is {_iv(*true)}; the basic limit function has support {_iv(*phi)}")
        sharp = f"generic parameters; the limit function's support is smaller where an end coefficient vanishes ({exc_txt})" if exc else None
        if ok:
            return self.certified(fact, evidence=ev, numbers=nums, sharpness=sharp)
        return self.refuted(f"{fact}, not {_iv(*self.claimed)}", corrected=fact, evidence=ev, numbers=nums)
