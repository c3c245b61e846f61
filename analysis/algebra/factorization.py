"""Smoothing factors, sum rules, polynomial generation/reproduction and symmetry of a symbol.

``a(z) = ((1+z)/2)^k b(z)`` with ``k`` maximal. With parameters, ``k`` is the generic value (the
division is exact identically in the parameters) and the *exceptional* parameter values, where
``b(-1) = 0`` and more factors appear, are found exactly and analysed recursively.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> w = sp.Symbol("omega")
>>> a = LaurentSymbol.from_mask([-5*w, -7*w, sp.Rational(1,4)+3*w, sp.Rational(3,4)+9*w,
...                              sp.Rational(3,4)+9*w, sp.Rational(1,4)+3*w, -7*w, -5*w], start=-4)
>>> f = smoothing_factor(a)
>>> f.value, f.status
(3, 'certified')
>>> [(str(e["condition"]), e["k"]) for e in f.witness["exceptional"]]
[('{omega: 1/128}', 5)]

(At ``omega = 1/128`` the scheme is Dyn–Floater–Hormann's fourth-order C^2 scheme.)

Algorithm
---------
Synthetic division by ``1+z`` in the coefficient domain (QQ, QQ<theta>, QQ[params]): the
remainder is ``a(-1)``, an element of the domain, so "identically zero" is an exact test.
Exceptional values solve ``b(-1) = 0`` exactly (real algebraic roots for one parameter, sympy's
``solve`` for several) and the substituted symbol is factored again.

Polynomial reproduction follows Conti–Hormann (2011): with ``tau = a'(1)/2`` the scheme
reproduces degree ``d`` (for the parametrisation ``t_i^n = (i + tau)/2^n``) iff it generates
degree ``d`` and ``D^j a(1) = 2 tau (tau-1) ... (tau-j+1)`` for ``j = 1..d``.

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002).
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*,
J. Approx. Theory 163 (2011) 413-437.
"""

from __future__ import annotations

import sympy as sp

from .algebraic import RealAlgebraic
from ..result import CERTIFIED, AnalysisError, Result
from .symbol import LaurentSymbol


# --------------------------------------------------------------------------------------------
# exact division by (1+z)
# --------------------------------------------------------------------------------------------

def divide_one_plus_z(a: LaurentSymbol):
    """``(q, r)`` with ``a(z) = (1+z) q(z) + r`` and ``r = a(-1)`` (``r`` a domain element).

    The quotient keeps the exponent bookkeeping: ``q`` starts at ``a.start``.
    """
    dom = a.domain
    coeffs = a.poly.rep.to_list()  # highest degree first
    if not coeffs:
        return a, dom.zero
    # synthetic division by (z + 1): b_0 = c_0, b_i = c_i - b_{i-1}; the last value is P(-1)
    out = []
    for c in coeffs:
        out.append(c - out[-1] if out else c)
    quotient, rem = out[:-1], out[-1]
    if not quotient:
        q = LaurentSymbol.from_mask([0], params=a.params, domain=dom)
    else:
        q = LaurentSymbol(sp.Poly.from_list(quotient, a.poly.gen, domain=dom), a.start, a.params)
    return q, rem


def _is_zero(dom, x) -> bool:
    return dom.is_zero(x) if hasattr(dom, "is_zero") else x == dom.zero


def factor_out(a: LaurentSymbol, m: int) -> LaurentSymbol:
    """``b = 2^m a / (1+z)^m`` exactly, or :class:`AnalysisError` if ``(1+z)^m`` does not divide.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> factor_out(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2), 2)
    LaurentSymbol([1, 1], start=-2, domain=QQ)
    """
    b = a
    for j in range(m):
        q, r = divide_one_plus_z(b)
        if not _is_zero(b.domain, r):
            raise AnalysisError(
                f"the symbol has only {j} factor(s) (1+z) identically in its parameters; "
                f"the difference scheme of order {m} needs {m}")
        b = q * 2
    return b


# --------------------------------------------------------------------------------------------
# smoothing factor with exceptional parameter values
# --------------------------------------------------------------------------------------------

def _generic_k(a: LaurentSymbol) -> tuple[int, LaurentSymbol]:
    if a.is_zero:
        raise AnalysisError("the zero symbol has no smoothing factor")
    k, b = 0, a
    while True:
        q, r = divide_one_plus_z(b)
        if not _is_zero(b.domain, r):
            return k, b
        k, b = k + 1, q * 2


def _real_solutions(expr: sp.Expr, params: tuple[sp.Symbol, ...]) -> list[dict]:
    """Exact solutions of ``expr = 0``: real values for one parameter, sympy's solve otherwise."""
    num, _den = sp.fraction(sp.together(expr))
    num = sp.expand(num)
    if num == 0:
        return [{}]
    if not (num.free_symbols & set(params)):
        return []
    if len(params) == 1:
        p = params[0]
        poly = sp.Poly(num, p)
        if poly.domain.is_QQ or poly.domain.is_ZZ:
            return [{p: r.expr} for r in RealAlgebraic.roots_of(poly)]
        sols = sp.solve(num, p)
        return [{p: s} for s in sols if s.is_real is not False and not s.has(sp.I)]
    sols = sp.solve(num, list(params), dict=True)
    return [s for s in sols if all(not v.has(sp.I) for v in s.values())]


def smoothing_factor(a: LaurentSymbol, *, exceptional: bool = True, _depth: int = 0) -> Result:
    """The largest ``k`` with ``a = ((1+z)/2)^k b``, the quotient ``b``, and exceptional cases.

    ``witness["b"]`` is ``b``; ``witness["exceptional"]`` lists, for each exact solution of
    ``b(-1) = 0`` (real values for one parameter; parametrised solutions for several),
    ``{"condition": {param: value}, "k": k_there, "b": b_there}``. The status is certified:
    everything is exact algebra.
    """
    k, b = _generic_k(a)
    cases = []
    if exceptional and a.params and _depth < 4:
        cases = exceptional_cases(a, [b(-1)], lambda sub: smoothing_factor(sub, exceptional=True,
                                                                            _depth=_depth + 1))
    return Result(value=k, status=CERTIFIED,
                  witness={"b": b, "identity": f"a(z) = ((1+z)/2)^{k} b(z)", "exceptional": cases},
                  provenance={"method": "exact synthetic division by (1+z)", "domain": str(a.domain)})


def exceptional_cases(a: LaurentSymbol, conditions, factor_at) -> list[dict]:
    """The exceptional parameter values of a smoothing-factor count: the real solutions of
    ``conditions[0] = 0`` at which every other condition vanishes too, each with the count
    ``factor_at(a at that value)`` (a :class:`Result`; its own exceptional values nested).

    Shared by the binary (:func:`smoothing_factor`, condition ``b(-1) = 0``) and the m-ary
    (:func:`analysis.algebra.mary.smoothing_factor_mary`, the remainder's coefficients) counts.
    """
    cases = []
    first = conditions[0] if conditions else sp.Integer(0)
    for sol in _real_solutions(first, a.params):
        if not sol or any(sp.simplify(c.subs(sol)) != 0 for c in conditions[1:]):
            continue
        try:
            sub = a.subs(sol)
        except AnalysisError:
            continue
        if sub.is_zero:
            cases.append({"condition": sol, "k": None, "b": None, "note": "symbol vanishes"})
            continue
        inner = factor_at(sub)
        case = {"condition": sol, "k": inner.value, "b": inner.witness["b"]}
        if inner.witness.get("exceptional"):
            case["exceptional"] = inner.witness["exceptional"]
        cases.append(case)
    return cases


# --------------------------------------------------------------------------------------------
# sum rules, generation, reproduction, symmetry
# --------------------------------------------------------------------------------------------

def sum_rules(a: LaurentSymbol) -> Result:
    """The necessary conditions ``a(1) = 2`` and ``a(-1) = 0`` (each sub-symbol sums to 1).

    ``value`` is True/False for a numeric symbol; with parameters it is True when both hold
    identically, else ``witness["solutions"]`` gives the exact parameter values where they hold.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> sum_rules(LaurentSymbol.from_mask([1, 1])).value
    True
    >>> sum_rules(LaurentSymbol.from_mask([1, 2, 1])).value
    False
    """
    at1 = sp.expand(a(1))
    atm1 = sp.expand(a(-1))
    eqs = [sp.expand(at1 - 2), atm1]
    holds = all(e == 0 for e in eqs)
    witness = {"a(1)": at1, "a(-1)": atm1, "even_sum": a.residue_sums(2)[0], "odd_sum": a.residue_sums(2)[1]}
    if not holds and a.params:
        nonzero = [e for e in eqs if e != 0]
        sols = sp.solve(nonzero, list(a.params), dict=True)
        witness["solutions"] = sols
    return Result(value=holds, status=CERTIFIED, witness=witness,
                  provenance={"method": "exact evaluation at z = 1 and z = -1"})


def _falling_factorial_derivative(a: LaurentSymbol, j: int) -> sp.Expr:
    """``D^j a(1) = sum_i a_i i (i-1) ... (i-j+1)``."""
    total = sp.Integer(0)
    for i, c in a.items():
        ff = sp.Integer(1)
        for t in range(j):
            ff *= (i - t)
        total += c * ff
    return sp.expand(total)


def polynomial_generation(a: LaurentSymbol) -> Result:
    """The degree of polynomials the scheme generates: ``k - 1`` when ``a(1) = 2`` (sum rules of order k)."""
    sr = sum_rules(a)
    f = smoothing_factor(a, exceptional=False)
    k = f.value
    deg = k - 1 if sp.expand(a(1) - 2) == 0 else -1
    return Result(value=deg, status=CERTIFIED, witness={"k": k, "a(1)": sr.witness["a(1)"]},
                  provenance={"method": "sum rules of order k <=> (1+z)^k | a and a(1) = 2"})


def polynomial_reproduction(a: LaurentSymbol, *, max_degree: int | None = None) -> Result:
    """The degree of polynomial reproduction (Conti–Hormann) and the shift ``tau = a'(1)/2``.

    ``value`` is the generic degree (``-1`` when even constants are not reproduced). With parameters,
    ``witness["higher"]`` lists the exact parameter values where the degree is larger.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> w = sp.Symbol("w")
    >>> four = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
    >>> r = polynomial_reproduction(four)
    >>> r.value, r.witness["tau"], r.witness["higher"]
    (1, 0, [{'condition': {w: 1/16}, 'degree': 3}])
    """
    gen = polynomial_generation(a).value
    tau = sp.expand(_falling_factorial_derivative(a, 1) / 2)

    def degree_for(sym: LaurentSymbol) -> int:
        g = polynomial_generation(sym).value
        t = sp.expand(_falling_factorial_derivative(sym, 1) / 2)
        d = -1 if sp.expand(sym(1) - 2) != 0 else 0
        if d < 0:
            return -1
        for j in range(1, g + 1):
            target = 2 * sp.prod([t - l for l in range(j)])
            if sp.expand(_falling_factorial_derivative(sym, j) - target) != 0:
                break
            d = j
        return d

    deg = degree_for(a)
    higher = []
    if a.params and deg >= 0 and (max_degree is None or deg < max_degree):
        # candidates: where the next derivative condition holds, or where more (1+z) factors appear
        j = deg + 1
        target = 2 * sp.prod([tau - l for l in range(j)])
        cond = sp.expand(_falling_factorial_derivative(a, j) - target)
        candidates = [s for s in _real_solutions(cond, a.params) if s]
        candidates += [e["condition"] for e in smoothing_factor(a).witness["exceptional"]]
        seen = []
        for sol in candidates:
            if sol in seen:
                continue
            seen.append(sol)
            d = degree_for(a.subs(sol))
            if d > deg:
                higher.append({"condition": sol, "degree": d})
    return Result(value=deg, status=CERTIFIED, witness={"tau": tau, "generation_degree": gen, "higher": higher},
                  provenance={"method": "Conti-Hormann derivative conditions at z = 1",
                              "parametrisation": "t_i^n = (i + tau) / 2^n"})


def symmetry(a: LaurentSymbol) -> Result:
    """Whether ``a_i = a_{c-i}`` with ``c = start + end`` (symmetric about ``c/2``).

    ``witness["kind"]`` is ``"primal"`` (centre an integer) or ``"dual"`` (half-integer). With
    parameters, a non-identical symmetry reports the exact values where it holds.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> symmetry(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)).witness["centre"]
    -1/2
    """
    c = a.start + a.end
    diffs = [sp.expand(a.coeff(i) - a.coeff(c - i)) for i in range(a.start, a.end + 1)]
    holds = all(d == 0 for d in diffs)
    witness = {"centre": sp.Rational(c, 2), "kind": "primal" if c % 2 == 0 else "dual"}
    if not holds and a.params:
        witness["solutions"] = sp.solve([d for d in diffs if d != 0], list(a.params), dict=True)
    return Result(value=holds, status=CERTIFIED, witness=witness,
                  provenance={"method": "exact comparison a_i = a_(start+end-i)"})
