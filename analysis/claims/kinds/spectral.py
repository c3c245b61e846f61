"""Claim kind "eigenvalue inequality": the set of a parameter where the eigenvalues of the local
subdivision matrix satisfy the necessary conditions for C^j, as an exact set, against a printed set.

The conditions (Dyn–Levin, Acta Numer. 2002, Sect. 4; seed 004's Theorem 2.1): ``1, 1/2, ...,
2^-j`` are eigenvalues and every other eigenvalue has modulus ``< 2^-j``. With ``relation =
"inside"`` (default) the claim is "the conditions hold on the printed set" (proven when the printed
interval lies in the exact set; ``sharpness`` then gives the exact set); with ``relation = "equal"``
the printed set must be the exact set. With ``moduli = [e_1, e_2, ...]`` instead of ``j`` the condition
is a printed ordering ``|e_1| > |e_2| > ...`` of eigenvalues (expressions in the parameter with at most
one square root each; a negative radicand makes a complex pair), e.g. seed 004's (5.6)-(5.9).

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
('CERTIFIED TRUE', 'the C^1 eigenvalue conditions hold exactly for w in (0, 1/4)')
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
For ``moduli``: ``|e|^2`` is ``(u + c r)^2`` (real, ``r = sqrt(D)``) or ``u^2 - c^2 D`` (complex pair);
the crossings ``|e_k|^2 = |e_(k+1)|^2`` in each of the four real/complex combinations are made polynomial
by eliminating ``r`` (``A + B r = 0`` gives ``A^2 - B^2 D = 0``); with the radicands they are the critical
points, and the ordering is decided exactly at the sample points.

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Sect. 4;
P. Henrici, *Applied and Computational Complex Analysis* I (1974), Sect. 6.8 (the Schur–Cohn test).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from ...algebra.algebraic import RealAlgebraic, sign
from ...result import AnalysisError
from ...stationary.transition import LAMBDA, local_eigenvalues
from ..model import Number, Verdict, contains_interval, exact_result, exact_set
from .base import Kind, evidence, interval_text
from ...algebra.reader import as_expr, read_in_context

__all__ = ["EigenvalueInequality", "stable_in_disk", "set_numbers", "moduli_chain_set"]


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


@lru_cache(maxsize=1024)
def _equal(e: sp.Expr, x: sp.Expr) -> bool:
    """``simplify(e - x) == 0``, remembered (bounded): the inequalities of one paper compare the same printed
    moduli with the same exact eigenvalues (``simplify`` is a function of the two expressions only).

    >>> mu = sp.Symbol("mu")
    >>> _equal(7 * mu / 32, sp.Rational(7, 32) * mu), _equal(mu, -mu)
    (True, False)
    """
    return sp.simplify(e - x) == 0


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
        coeffs = [sp.Poly(as_expr(c).subs(p, x), x, domain=sp.QQ)
                  for c in reversed(sp.Poly(f.as_expr(), LAMBDA).all_coeffs())]
        if not stable_in_disk(coeffs, r, sign=ra.sign_of, reduce=reduce):
            return False
    return True


def _radical_parts(e, p):
    """``e = u + c sqrt(D)`` (u, c rational in ``p``, D a polynomial; at most one square root)."""
    roots = {x for x in e.atoms(sp.Pow) if x.exp == sp.Rational(1, 2)}
    if len(roots) > 1:
        raise AnalysisError(f"{sp.sstr(e)}: at most one square root per eigenvalue")
    if not roots:
        return e, sp.Integer(0), sp.Integer(0)
    R = roots.pop()
    e = sp.expand(e)
    return e.subs(R, 0), sp.expand((e - e.subs(R, 0)) / R), R.base


def _modulus2(parts, v):
    """|u + c sqrt(D)|^2 at ``p = v`` (exact closed form; a negative D gives a complex pair)."""
    (u, c, D), p = parts
    u, c, D = (as_expr(x).subs(p, v) for x in (u, c, D))
    if c == 0 or sign(D) >= 0:
        return sp.expand((u + c * sp.sqrt(D)) ** 2)
    return sp.expand(u ** 2 - c ** 2 * D)


def _eliminate(G, radicals):
    """A polynomial vanishing where ``G`` (in the radical symbols r with r^2 = D) vanishes."""
    G = sp.numer(sp.together(sp.expand(G)))
    for r, D in radicals:
        G = sp.expand(G).subs(r ** 2, D)
        G = sp.expand(sp.Poly(G, r).rem(sp.Poly(r ** 2 - D, r)).as_expr())
        A, B = G.subs(r, 0), G.coeff(r, 1)
        G = sp.expand(A ** 2 - B ** 2 * D)
    return G


def moduli_chain_set(exprs, p, within=(-sp.oo, sp.oo)):
    """The exact set of ``p`` where ``|e_1| > |e_2| > ...`` (each ``e_i`` rational in ``p`` with at
    most one square root of a polynomial; a negative radicand makes ``e_i`` complex).

    >>> mu = sp.Symbol("mu")
    >>> print(moduli_chain_set([sp.Rational(1, 64), -7 * mu / 32], mu))
    (-1/14, 1/14)
    """
    parts = [_radical_parts(as_expr(e), p) for e in exprs]
    rad = {}
    for _, c, D in parts:
        if c != 0:
            rad.setdefault(D, sp.Dummy("r"))
    crit = [D for D in rad] + [sp.denom(sp.together(x)) for u, c, _ in parts for x in (u, c)]
    def M(k, real):
        u, c, D = parts[k]
        if c == 0:
            return u ** 2
        return (u + c * rad[D]) ** 2 if real else u ** 2 - c ** 2 * D
    for k in range(len(parts) - 1):
        for real_a in (True, False):
            for real_b in (True, False):
                G = M(k, real_a) - M(k + 1, real_b)
                crit.append(_eliminate(G, [(r, D) for D, r in rad.items() if G.has(r)]))
    polys = [sp.Poly(x, p) for x in crit if as_expr(x).has(p)]

    def pred(v):
        m = [_modulus2((q, p), v) for q in parts]
        return all(sign(m[k] - m[k + 1]) > 0 for k in range(len(m) - 1))
    return exact_set(pred, polys, within=within)


class EigenvalueInequality(Kind):
    """The necessary eigenvalue conditions for C^j hold on the printed set (or: exactly there), or a
    printed ordering ``|lambda_a| > |lambda_b| > ...`` of given eigenvalues holds there."""

    name = "eigenvalue inequality"
    summary = ("the set of the parameter where the local-matrix eigenvalues satisfy the C^j necessary conditions "
               "(1, 1/2, ..., 2^-j, all others below 2^-j), or a printed ordering of their moduli, exact, vs the printed set")
    required = {"interval": "printed parameter set"}
    optional = {"j": "the C^j necessary conditions", "moduli": "[e_1, e_2, ...]: the ordering |e_1| > |e_2| > ... "
                "of eigenvalues (instead of j)", "relation": "'inside' (default: the conditions hold on the printed set) or 'equal'",
                "at": "values of the other parameters", "window": "[lo, hi] of the local matrix"}
    example = 'j = 1\ninterval = "(0, 1/8)"\nrelation = "inside"'

    def check(self) -> None:
        self.integer("j"), self.interval("interval")
        self.values()
        if ("j" in self.fields) == ("moduli" in self.fields):
            raise AnalysisError(f"{self.where}: kind 'eigenvalue inequality' needs exactly one of 'j', 'moduli'")
        if self.get("relation", "inside") not in ("inside", "equal"):
            raise AnalysisError(f"{self.where}: field 'relation' must be 'inside' or 'equal'")
        names = {p.name: p for p in self.scheme.params}
        try:
            self.moduli = [read_in_context(x, names, what="modulus", free=True) for x in self.get("moduli", [])]
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: field 'moduli': {exc}") from None
        if "moduli" in self.fields and len(self.moduli) < 2:
            raise AnalysisError(f"{self.where}: field 'moduli' lists at least two eigenvalues")

    def _within(self, p):
        dom = self.scheme.domains.get(p.name)
        return (dom.lo, dom.hi) if dom is not None else (-sp.oo, sp.oo)

    def exact(self, res=None):
        """(the exact set, the eigenvalue factors, the local-eigenvalue Result); ``res``: that Result when
        already computed (:func:`~analysis.stationary.transition.local_eigenvalues` of the claim's scheme)."""
        a, p, j = self.symbol(), self.single_parameter(), self.get("j")
        if res is None:
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
        return exact_set(lambda v: _stable_at(factors, p, r, v), crit, within=self._within(p)), factors, res

    def evaluate(self) -> Verdict:
        p, j = self.single_parameter(), self.get("j")
        res = local_eigenvalues(self.symbol(), window=self.get("window"))
        spectrum = ", ".join(sp.sstr(x) for x in res.value)
        ev = [evidence("exact eigenvalues of the local subdivision matrix", res,
                       text=f"window {res.witness['window']}: {spectrum}")]
        if self.moduli:
            what = "|" + "| > |".join(sp.sstr(e) for e in self.moduli) + "|"
            missing = [e for e in self.moduli if not any(_equal(e, x) for x in res.value)]
            if missing:
                return self.inconclusive(f"not eigenvalues of the local matrix of {self.where_text()}: "
                                         f"{', '.join(map(sp.sstr, missing))}", evidence=ev,
                                         settle="the reading of the printed eigenvalues")
            S = moduli_chain_set(self.moduli, p, self._within(p))
            ev.append(evidence(f"exact set where {what}", exact_result(S, "exact_set: crossings by elimination of the "
                                                                          "square roots, exact moduli at the sample points"),
                               text=f"{p.name} in {S}"))
        else:
            S, factors, res = self.exact(res)
            dom = ", ".join(sp.sstr(sp.Rational(1, 2 ** i)) for i in range(j + 1))
            if S is None:
                return self.refuted(f"{dom} are not all eigenvalues of the local matrix of {self.where_text()} "
                                    f"identically in {p.name}", corrected=f"the eigenvalues are {spectrum}", evidence=ev)
            what = f"the C^{j} eigenvalue conditions"
            rest = " ".join(f"({sp.sstr(f.as_expr())})" for f in factors)
            ev.append(evidence(f"exact set where every eigenvalue other than {dom} has modulus < {sp.sstr(sp.Rational(1, 2 ** j))}",
                               exact_result(S, "exact_set with Schur-Cohn decisions at the sample points"),
                               text=f"the other eigenvalues are the roots of {rest or '1'}; {p.name} in {S}"))
        lo, hi, lc, hc = self.interval("interval")
        claim = interval_text(lo, hi, lc, hc)
        nums = set_numbers("exact set", S)
        holds = "hold" if j is not None else "holds"
        if self.get("relation", "inside") == "equal":
            equal = (len(S.parts) == 1 and S.parts[0][0] is not None and S.parts[0][1] is not None
                     and S.parts[0][0].compare(RealAlgebraic.from_expr(lo)) == 0
                     and S.parts[0][1].compare(RealAlgebraic.from_expr(hi)) == 0
                     and (S.parts[0][2], S.parts[0][3]) == (lc, hc))
            if equal:
                return self.certified(f"{what} {holds} exactly for {p.name} in {claim}", evidence=ev, numbers=nums)
            return self.refuted(f"{what} {holds} exactly for {p.name} in {S}, not {claim}",
                                corrected=f"{what} {holds} exactly for {p.name} in {S}", evidence=ev, numbers=nums)
        if contains_interval(S, lo, hi, closed=lc or hc):
            return self.certified(f"{what} {holds} for {p.name} in {claim}", evidence=ev,
                                  numbers=nums, sharpness=f"{what} {holds} exactly for {p.name} in {S}")
        return self.refuted(f"{what} fail{'' if j is not None else 's'} on part of {claim}: {holds} exactly for {p.name} in {S}",
                            corrected=f"{what} {holds} exactly for {p.name} in {S}", evidence=ev, numbers=nums)
