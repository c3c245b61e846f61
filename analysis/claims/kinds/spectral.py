"""Claim kind "eigenvalue inequality": the set of a parameter where the eigenvalues of the local
subdivision matrix satisfy the necessary conditions for C^j, as an exact set, against a printed set.

The conditions (Dyn–Levin, Acta Numer. 2002, Sect. 4; seed 004's Theorem 2.1): ``1, 1/2, ...,
2^-j`` are eigenvalues and every other eigenvalue has modulus ``< 2^-j``. With ``relation =
"inside"`` (default) the claim is "the conditions hold on the printed set" (proven when the printed
interval lies in the exact set; ``sharpness`` then gives the exact set); with ``relation = "equal"``
the printed set must be the exact set.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> w = sp.Symbol("w")
>>> four = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
>>> S = {"4pt": SchemeSpec("4pt", four)}
>>> v = EigenvalueInequality({"j": 1, "interval": "(0, 1/8)"}, S, "x").evaluate()   # 2w, (1 ± sqrt(1-16w))/4
>>> v.label, v.sharpness
('CERTIFIED TRUE', 'the conditions hold exactly for w in (0, 1/4)')
>>> EigenvalueInequality({"j": 1, "interval": "(0, 1/8)", "relation": "equal"}, S, "x").evaluate().label
'REFUTED'
>>> stable_in_disk([sp.Rational(1, 8), 1], sp.Rational(1, 4))        # lambda = -1/8
True

Algorithm
---------
The exact characteristic polynomial of the local subdivision matrix
(:func:`analysis.stationary.transition.local_eigenvalues`) is divided by ``prod (lambda - 2^-i)``,
``i <= j``, and factored over ``Q[lambda, p]``. A factor ``f`` can gain or lose a root of modulus
``r = 2^-j`` only at the real roots in ``p`` of ``f(r)``, ``f(-r)`` and the resultant
``Res_lambda(f(lambda), lambda^d f(r^2/lambda))`` (a pair ``lambda, r^2/conj(lambda)`` of roots),
so those are the critical points of :func:`analysis.claims.model.exact_set`; at every sample
point (a rational in each gap, and each algebraic critical point) the Schur–Cohn test decides
exactly whether all roots lie in ``|lambda| < r`` (fraction-free, coefficients in ``Q[x]/(m(x))``
for the minimal polynomial ``m`` of the point, signs by :class:`~analysis.algebra.algebraic.RealAlgebraic`).

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Sect. 4;
P. Henrici, *Applied and Computational Complex Analysis* I (1974), Sect. 6.8 (the Schur–Cohn test).
"""

from __future__ import annotations

import sympy as sp

from ...algebra.algebraic import RealAlgebraic
from ...result import AnalysisError
from ...stationary.transition import LAMBDA, local_eigenvalues
from ..model import Number, Verdict, contains_interval, exact_result, exact_set
from .base import Kind, evidence, interval_text

__all__ = ["EigenvalueInequality", "stable_in_disk", "set_numbers"]


def stable_in_disk(coeffs, r, sign=lambda c: int(sp.sign(c)), reduce=lambda c: c) -> bool:
    """Whether every root of ``sum_k coeffs[k] lambda^k`` (real, leading last) has ``|lambda| < r``.

    Schur–Cohn, fraction-free: ``q = (c_n p - c_0 p*)/z`` keeps the number of roots inside when
    ``|c_n| > |c_0|`` (Rouché). ``sign``/``reduce`` let the coefficients live in a number field."""
    c = [reduce(x * r ** k) for k, x in enumerate(coeffs)]
    while len(c) > 1:
        if sign(reduce(c[-1] * c[-1] - c[0] * c[0])) <= 0:
            return False
        n = len(c) - 1
        c = [reduce(c[-1] * c[k + 1] - c[0] * c[n - 1 - k]) for k in range(n)]
    return True


def set_numbers(prefix: str, iset) -> list[Number]:
    """Key numbers: the finite end points of an exact set (``prefix[k].lower`` / ``.upper``)."""
    return [Number(f"{prefix}[{k}].{side}", x.expr, tol=1e-12) for k, part in enumerate(iset.parts)
            for side, x in (("lower", part[0]), ("upper", part[1])) if x is not None]


def _stable_at(factors, p, r, v) -> bool:
    ra = RealAlgebraic.from_expr(v)
    m = ra.poly
    x = m.gen

    def reduce(c):
        return (c if isinstance(c, sp.Poly) else sp.Poly(c, x, domain=sp.QQ)).rem(m)
    for f in factors:
        coeffs = [sp.Poly(sp.sympify(c).subs(p, x), x, domain=sp.QQ)
                  for c in reversed(sp.Poly(f.as_expr(), LAMBDA).all_coeffs())]
        if not stable_in_disk(coeffs, r, sign=ra.sign_of, reduce=reduce):
            return False
    return True


class EigenvalueInequality(Kind):
    """The necessary eigenvalue conditions for C^j hold on the printed set (or: exactly there)."""

    name = "eigenvalue inequality"
    summary = ("the set of the parameter where the local-matrix eigenvalues satisfy the C^j necessary conditions "
               "(1, 1/2, ..., 2^-j, all others below 2^-j), exact, vs the printed set")
    required = {"j": "the C^j necessary conditions", "interval": "printed parameter set"}
    optional = {"relation": "'inside' (default: the conditions hold on the printed set) or 'equal'",
                "at": "values of the other parameters", "window": "[lo, hi] of the local matrix"}
    example = 'j = 1\ninterval = "(0, 1/8)"\nrelation = "inside"'

    def check(self) -> None:
        self.integer("j"), self.interval("interval")
        self.values()
        if self.get("relation", "inside") not in ("inside", "equal"):
            raise AnalysisError(f"{self.where}: field 'relation' must be 'inside' or 'equal'")

    def exact(self):
        """(the exact set, the eigenvalue factors, the local-eigenvalue Result)."""
        a, p, j = self.symbol(), self.single_parameter(), self.get("j")
        res = local_eigenvalues(a, window=self.get("window"))
        chi = sp.Poly(sp.expand(res.witness["charpoly"]), LAMBDA, p)
        dominant = sp.Poly(sp.prod([LAMBDA - sp.Rational(1, 2 ** i) for i in range(j + 1)]), LAMBDA, p)
        g, rem = sp.div(chi, dominant)
        r = sp.Rational(1, 2 ** j)
        if not rem.is_zero:
            return None, [], res
        factors = [sp.Poly(f, LAMBDA, p) for f, _ in g.factor_list()[1] if sp.Poly(f, LAMBDA, p).degree(LAMBDA) > 0]
        crit = []
        for f in factors:
            d = f.degree(LAMBDA)
            fe = f.as_expr()
            recip = sp.expand(LAMBDA ** d * fe.subs(LAMBDA, r ** 2 / LAMBDA))
            for e in (fe.subs(LAMBDA, r), fe.subs(LAMBDA, -r), sp.resultant(fe, recip, LAMBDA)):
                e = sp.expand(e)
                if e.free_symbols:
                    crit.append(sp.Poly(e, p))
        dom = self.scheme.domains.get(p.name)
        within = (dom.lo, dom.hi) if dom is not None else (-sp.oo, sp.oo)
        return exact_set(lambda v: _stable_at(factors, p, r, v), crit, within=within), factors, res

    def evaluate(self) -> Verdict:
        p, j = self.single_parameter(), self.get("j")
        S, factors, res = self.exact()
        lo, hi, lc, hc = self.interval("interval")
        claim = interval_text(lo, hi, lc, hc)
        spectrum = ", ".join(sp.sstr(x) for x in res.value)
        dom = ", ".join(sp.sstr(sp.Rational(1, 2 ** i)) for i in range(j + 1))
        ev = [evidence("exact eigenvalues of the local subdivision matrix", res,
                       text=f"window {res.witness['window']}: {spectrum}")]
        if S is None:
            return self.refuted(f"{dom} are not all eigenvalues of the local matrix of {self.where_text()} "
                                f"identically in {p.name}", corrected=f"the eigenvalues are {spectrum}", evidence=ev)
        rest = " ".join(f"({sp.sstr(f.as_expr())})" for f in factors)
        ev.append(evidence(f"exact set where every eigenvalue other than {dom} has modulus < {sp.sstr(sp.Rational(1, 2 ** j))}",
                           exact_result(S, "exact_set with Schur-Cohn decisions at the sample points"),
                           text=f"the other eigenvalues are the roots of {rest or '1'}; {p.name} in {S}"))
        nums = set_numbers("exact set", S)
        if self.get("relation", "inside") == "equal":
            equal = (len(S.parts) == 1 and S.parts[0][0] is not None and S.parts[0][1] is not None
                     and S.parts[0][0].compare(RealAlgebraic.from_expr(lo)) == 0
                     and S.parts[0][1].compare(RealAlgebraic.from_expr(hi)) == 0
                     and (S.parts[0][2], S.parts[0][3]) == (lc, hc))
            if equal:
                return self.certified(f"the C^{j} eigenvalue conditions hold exactly for {p.name} in {claim}",
                                      evidence=ev, numbers=nums)
            return self.refuted(f"the C^{j} eigenvalue conditions hold exactly for {p.name} in {S}, not {claim}",
                                corrected=f"the conditions hold exactly for {p.name} in {S}", evidence=ev, numbers=nums)
        if contains_interval(S, lo, hi, closed=lc or hc):
            return self.certified(f"the C^{j} eigenvalue conditions hold for {p.name} in {claim}", evidence=ev,
                                  numbers=nums, sharpness=f"the conditions hold exactly for {p.name} in {S}")
        return self.refuted(f"the C^{j} eigenvalue conditions fail on part of {claim}: they hold exactly for {p.name} in {S}",
                            corrected=f"the conditions hold exactly for {p.name} in {S}", evidence=ev, numbers=nums)
