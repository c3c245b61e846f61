"""Smoothing factors, sum rules, polynomial generation/reproduction and symmetry of a symbol, any arity.

Convention (arity ``m >= 2``, the keyword ``arity``, default 2)::

    (S_a f)_i = sum_j a_{i-mj} f_j,        a(z) = sum_i a_i z^i,      q_m(z) = 1 + z + ... + z^{m-1}.

``a(z) = (q_m(z)/m)^k b(z)`` with ``k`` maximal (``((1+z)/2)^k b`` for ``m = 2``). With parameters, ``k``
is the generic value (the division is exact identically in the parameters) and the *exceptional*
parameter values, where ``q_m`` divides ``b`` again and more factors appear, are found exactly and
analysed recursively. The arity is passed to the analyses, it is not stored on
:class:`~analysis.algebra.symbol.LaurentSymbol`: a symbol is a Laurent polynomial.

* **sum rules**: ``a(1) = m`` and ``a(eps) = 0`` for every m-th root of unity ``eps != 1``;
  equivalently every residue sum ``A_r = sum_j a_{r+mj}`` equals 1. A failure names the root.
* **generation** of degree ``k - 1`` when ``a(1) = m`` and ``q_m^k | a`` (Dyn–Levin; Conti–Hormann 2011, Thm 3).
* **reproduction**: with ``tau = a'(1)/m``, for the parametrisation ``t_i^n = (i + tau/(m-1))/m^n``
  (Conti–Hormann 2011).

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

>>> b3 = LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)")            # ternary quadratic B-spline
>>> sum_rules(b3, arity=3).value, smoothing_factor(b3, arity=3).value
(True, 3)
>>> r = sum_rules(LaurentSymbol.from_mask([1, 2]), arity=3)        # a(1) = 3, residue sums 1, 2, 0
>>> r.value, r.witness["failures"]
(False, ['a(exp(2*pi*i/3)) = sqrt(3)*I != 0', 'a(exp(4*pi*i/3)) = -sqrt(3)*I != 0'])

Algorithm
---------
Division by ``q_m`` in the coefficient domain (QQ, QQ<theta>, QQ[params]); for ``m = 2`` synthetic
division by ``1+z``, whose remainder is ``a(-1)``, an element of the domain, so "identically zero" is an
exact test. Exceptional values solve the remainder's coefficients ``= 0`` exactly (real algebraic roots
for one parameter, sympy's ``solve`` for several) and the substituted symbol is factored again.
The value ``a(eps)`` at a root of unity is decided with cyclotomic remainders (rational masks) or the
exact sign of its real and imaginary parts (:func:`analysis.algebra.algebraic.sign`).

Polynomial reproduction follows Conti–Hormann (2011): with ``tau = a'(1)/2`` a binary scheme
reproduces degree ``d`` (for the parametrisation ``t_i^n = (i + tau)/2^n``) iff it generates
degree ``d`` and ``D^j a(1) = 2 tau (tau-1) ... (tau-j+1)`` for ``j = 1..d``; for ``m > 2`` the
definition is checked (see :func:`polynomial_reproduction`).

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002).
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*,
J. Approx. Theory 163 (2011) 413-437.
"""

from __future__ import annotations

import sympy as sp

from .algebraic import RealAlgebraic
from .limits import arity_key, check_arity  # noqa: F401  (re-exported: the arity of every analysis)
from ..result import CERTIFIED, AnalysisError, Result
from .symbol import LaurentSymbol, Z


def q_symbol(m: int) -> LaurentSymbol:
    """``q_m(z) = 1 + z + ... + z^{m-1}``.

    >>> q_symbol(3)
    LaurentSymbol([1, 1, 1], start=0, domain=QQ)
    """
    return LaurentSymbol.from_mask([1] * check_arity(m))


def q_name(m: int) -> str:
    """How messages name ``q_m``: ``(1+z)`` for ``m = 2``, else ``1+z+...+z^{m-1}``."""
    return "(1+z)" if m == 2 else f"1+z+...+z^{m - 1}"


# --------------------------------------------------------------------------------------------
# exact division by q_m = 1 + z + ... + z^{m-1}
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


def divide_q(a: LaurentSymbol, m: int = 2):
    """``(quotient, remainder, divisible)`` of ``a = q_m * quotient + remainder``; ``divisible`` is True
    exactly when ``q_m | a`` identically. For ``m = 2`` the remainder is the domain element ``a(-1)``
    (synthetic division, :func:`divide_one_plus_z`), else a polynomial of degree ``< m - 1``."""
    if m == 2:
        q, r = divide_one_plus_z(a)
        return q, r, _is_zero(a.domain, r)
    quo, rem = a.poly.div(sp.Poly([1] * m, Z, domain=a.domain))
    q = LaurentSymbol(quo, a.start, a.params) if not quo.is_zero else None
    return q, rem, rem.is_zero and q is not None


def _is_zero(dom, x) -> bool:
    return dom.is_zero(x) if hasattr(dom, "is_zero") else x == dom.zero


def factor_out(a: LaurentSymbol, k: int, *, arity: int = 2) -> LaurentSymbol:
    """``b = m^k a / q_m^k`` exactly (``2^k a/(1+z)^k`` for ``m = 2``), or :class:`AnalysisError` if
    ``q_m^k`` does not divide ``a`` identically.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> factor_out(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2), 2)
    LaurentSymbol([1, 1], start=-2, domain=QQ)
    >>> factor_out(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 2, arity=3)
    LaurentSymbol([3], start=-2, domain=QQ)
    """
    m = check_arity(arity)
    if m == 2 and k > 0 and not a.is_zero:
        return _factor_out_binary(a, k)
    b = a
    for j in range(k):
        q, _r, divisible = divide_q(b, m)
        if not divisible:
            raise AnalysisError(
                f"the symbol has only {j} factor(s) {q_name(m)} identically in its parameters; "
                f"the difference scheme of order {k} needs {k}")
        b = q * m
    return b


def _factor_out_binary(a: LaurentSymbol, k: int) -> LaurentSymbol:
    """:func:`factor_out` for ``m = 2`` on the coefficient list: ``k`` synthetic divisions by ``(1+z)``,
    each quotient times 2, in the domain ``a * 2`` has (the same symbol as dividing and scaling ``k`` times)."""
    dom = a.domain.unify(sp.QQ)
    two = dom.convert(2)
    coeffs = a.poly.set_domain(dom).rep.to_list()          # highest degree first
    for j in range(k):
        out = []
        for c in coeffs:
            out.append(c - out[-1] if out else c)
        if not _is_zero(dom, out[-1]) or len(out) < 2:
            raise AnalysisError(
                f"the symbol has only {j} factor(s) {q_name(2)} identically in its parameters; "
                f"the difference scheme of order {k} needs {k}")
        coeffs = [two * c for c in out[:-1]]
    params = tuple(sorted(set(a.params), key=lambda s: s.name))
    return LaurentSymbol(sp.Poly.from_list(coeffs, a.poly.gen, domain=dom), a.start, params)


# --------------------------------------------------------------------------------------------
# smoothing factor with exceptional parameter values
# --------------------------------------------------------------------------------------------

def _generic_k(a: LaurentSymbol, m: int = 2):
    """``(k, b, remainder)``: the generic number of factors ``q_m``, the quotient and the remainder of
    the next division."""
    if a.is_zero:
        raise AnalysisError("the zero symbol has no smoothing factor")
    k, b = 0, a
    while True:
        q, r, divisible = divide_q(b, m)
        if not divisible:
            return k, b, r
        k, b = k + 1, q * m


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


def smoothing_factor(a: LaurentSymbol, *, arity: int = 2, exceptional: bool = True, _depth: int = 0) -> Result:
    """The largest ``k`` with ``a = (q_m/m)^k b``, the quotient ``b``, and exceptional cases.

    ``witness["b"]`` is ``b``; ``witness["exceptional"]`` lists, for each exact parameter value where
    ``q_m`` divides ``b`` again (``b(-1) = 0`` for ``m = 2``; real values for one parameter, parametrised
    solutions for several), ``{"condition": {param: value}, "k": k_there, "b": b_there}``. The status is
    certified: everything is exact algebra.

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> mu = sp.Symbol("mu")
    >>> r = sp.Rational
    >>> a0, a1, a2, a3 = -r(1, 18) - mu/6, r(13, 18) + mu/2, r(7, 18) - mu/2, -r(1, 18) + mu/6
    >>> a = LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)  # Hassan et al. 2002
    >>> f = smoothing_factor(a, arity=3)
    >>> f.value, [(e["condition"], e["k"]) for e in f.witness["exceptional"]]
    (3, [({mu: 1/27}, 4)])
    """
    m = check_arity(arity)
    k, b, rem = _generic_k(a, m)
    cases = []
    if exceptional and a.params and _depth < 4:
        if m == 2:
            conditions = [b(-1)]
        else:
            conditions = [sp.expand(c) for c in rem.all_coeffs() if c != 0]
            conditions = [rem.domain.to_sympy(c) if not isinstance(c, sp.Basic) else c for c in conditions]
        cases = exceptional_cases(a, conditions, lambda sub: smoothing_factor(sub, arity=m, exceptional=True,
                                                                               _depth=_depth + 1))
    q = "1+z" if m == 2 else f"1+...+z^{m - 1}"
    method = "exact synthetic division by (1+z)" if m == 2 else f"exact division by 1+z+...+z^{m - 1}"
    return Result(value=k, status=CERTIFIED,
                  witness={"b": b, "identity": f"a(z) = (({q})/{m})^{k} b(z)", "exceptional": cases},
                  provenance={"method": method, **arity_key(m), "domain": str(a.domain)})


def exceptional_cases(a: LaurentSymbol, conditions, factor_at) -> list[dict]:
    """The exceptional parameter values of a smoothing-factor count: the real solutions of
    ``conditions[0] = 0`` at which every other condition vanishes too, each with the count
    ``factor_at(a at that value)`` (a :class:`Result`; its own exceptional values nested).

    Used by :func:`smoothing_factor` (conditions: ``b(-1) = 0`` for ``m = 2``, else the coefficients of
    the remainder of the division by ``q_m``).
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

def _root_name(j: int, m: int) -> str:
    g = sp.gcd(j, m)
    jj, mm = j // g, m // g
    if mm == 2:
        return "-1"
    if mm == 4:
        return "i" if jj == 1 else "-i"
    return f"exp({2 * jj}*pi*i/{mm})"


def _value_at_root(A: list, j: int, m: int) -> tuple[bool, sp.Expr]:
    """``(is_zero, value)`` of ``a(eps^j) = sum_r A_r eps^{jr}``, ``eps = exp(2 pi i/m)``, exactly."""
    g = sp.gcd(j, m)
    d = m // g
    jj = j // g
    # reduce exponents mod d: a(eps^j) = sum_s B_s w^s, w a primitive d-th root (w = exp(2 pi i jj/d))
    B = [sp.Integer(0)] * d
    for r, Ar in enumerate(A):
        B[(r * jj) % d] += Ar
    B = [sp.expand(b) for b in B]
    value = sp.expand(sum(b * sp.exp(2 * sp.pi * sp.I * s / d) for s, b in enumerate(B)))
    if all(b.is_Rational for b in B):
        rem = sp.rem(sp.Poly(list(reversed(B)), Z), sp.Poly(sp.cyclotomic_poly(d, Z), Z))
        return rem.is_zero, value
    from .algebraic import sign

    re, im = sp.expand_complex(value).as_real_imag()
    return sign(sp.nsimplify(re)) == 0 and sign(sp.nsimplify(im)) == 0, value


def sum_rules(a: LaurentSymbol, *, arity: int = 2) -> Result:
    """The necessary conditions ``a(1) = m`` and ``a(eps) = 0`` at the m-th roots of unity ``eps != 1``
    (each sub-symbol sums to 1); ``a(1) = 2`` and ``a(-1) = 0`` for ``m = 2``.

    ``value`` is True/False for a numeric symbol; with parameters it is True when they hold
    identically, else ``witness["solutions"]`` gives the exact parameter values where they hold.

    Witness: for ``m = 2`` the values ``a(1)``, ``a(-1)`` and the even/odd sums (what the binary
    reports quote); for ``m > 2`` the residue sums ``A_r`` and ``witness["failures"]``, naming each
    failing condition, e.g. ``"a(exp(2*pi*i/3)) = sqrt(3)*I != 0"`` (long closed forms are shown
    rounded, ``"~ 0.5+0.866*I"``; the zero test itself is exact).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> sum_rules(LaurentSymbol.from_mask([1, 1])).value
    True
    >>> sum_rules(LaurentSymbol.from_mask([1, 2, 1])).value
    False
    """
    m = check_arity(arity)
    if m == 2:
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
    A = a.residue_sums(m)
    failures = []
    at1 = sp.expand(sum(A))
    if sp.expand(at1 - m) != 0:
        failures.append(f"a(1) = {sp.sstr(at1)} != {m}")
    if a.params:
        holds = all(sp.expand(x - 1) == 0 for x in A)
        witness = {"a(1)": at1, "residue_sums": A, "failures": [] if holds else ["residue sums not all 1"]}
        if not holds:
            witness["solutions"] = sp.solve([sp.expand(x - 1) for x in A if sp.expand(x - 1) != 0],
                                            list(a.params), dict=True)
        return Result(value=holds, status=CERTIFIED, witness=witness,
                      provenance={"method": "exact residue sums A_r = 1 (<=> m-ary sum rules)", "arity": m})
    for j in range(1, m):
        zero, value = _value_at_root(A, j, m)
        if not zero:
            v = sp.sstr(sp.nsimplify(value))
            if len(v) > 30:                     # long closed forms: a rounded value (the test was exact)
                c = complex(sp.N(value, 15))
                v = f"~ {c.real:.6g}{c.imag:+.6g}*I"
            failures.append(f"a({_root_name(j, m)}) = {v} != 0")
    return Result(value=not failures, status=CERTIFIED,
                  witness={"a(1)": at1, "residue_sums": A, "failures": failures},
                  provenance={"method": "exact residue sums and values at the m-th roots of unity", "arity": m})


def _falling_factorial_derivative(a: LaurentSymbol, j: int) -> sp.Expr:
    """``D^j a(1) = sum_i a_i i (i-1) ... (i-j+1)``."""
    total = sp.Integer(0)
    for i, c in a.items():
        ff = sp.Integer(1)
        for t in range(j):
            ff *= (i - t)
        total += c * ff
    return sp.expand(total)


def polynomial_generation(a: LaurentSymbol, *, arity: int = 2) -> Result:
    """The degree of polynomials the scheme generates: ``k - 1`` when ``a(1) = m`` and ``q_m^k | a``
    (sum rules of order k), else ``-1``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> polynomial_generation(LaurentSymbol.from_expr("(1+z+z**2+z**3)**4/(64*z**4)"), arity=4).value
    3
    """
    m = check_arity(arity)
    k = smoothing_factor(a, arity=m, exceptional=False).value
    at1 = sp.expand(a(1))
    deg = k - 1 if sp.expand(at1 - m) == 0 else -1
    q = "(1+z)" if m == 2 else "q_m"
    return Result(value=deg, status=CERTIFIED, witness={"k": k, "a(1)": at1},
                  provenance={"method": f"sum rules of order k <=> {q}^k | a and a(1) = {2 if m == 2 else 'm'}",
                              **arity_key(m)})


def _reproduces(a: LaurentSymbol, m: int, d: int, shift: sp.Expr) -> bool:
    """Exact check: ``sum_j a_{i-mj} p(j + shift) = p((i + shift)/m)`` for ``p = x^d``, all ``i``."""
    s = sp.Symbol("s", integer=True)
    x = sp.Symbol("x")
    p = sp.Lambda(x, x ** d)
    for r in range(m):
        i = r + m * s
        lhs = sp.Integer(0)
        for l, c in a.items():
            if (r - l) % m:
                continue
            j = (i - l) / m                   # exact: i - l = r - l + m s is divisible by m
            lhs += c * p(j + shift)
        if sp.expand(lhs - p((i + shift) / m)) != 0:
            return False
    return True


def _reproduction_degree(a: LaurentSymbol, m: int) -> tuple[int, sp.Expr]:
    """The reproduction degree and ``tau`` from the definition (any arity)."""
    gen = polynomial_generation(a, arity=m).value
    tau = sp.expand(sum(i * c for i, c in a.items()) / m)
    shift = tau / (m - 1)
    deg = -1
    for d in range(0, max(gen, 0) + 1):
        if gen < 0 or not _reproduces(a, m, d, shift):
            break
        deg = d
    return deg, tau


def polynomial_reproduction(a: LaurentSymbol, *, arity: int = 2, max_degree: int | None = None) -> Result:
    """The degree of polynomial reproduction (Conti–Hormann) and the shift ``tau = a'(1)/m``.

    ``value`` is the generic degree (``-1`` when even constants are not reproduced). With parameters,
    ``witness["higher"]`` lists the exact parameter values where the degree is larger.

    Two methods, by arity. For ``m = 2``: Conti–Hormann's derivative conditions at ``z = 1``
    (``D^j a(1) = 2 tau (tau-1)...(tau-j+1)``, parametrisation ``t_i^n = (i + tau)/2^n``), whose next
    condition also yields the candidate parameter values of a higher degree. For ``m > 2``: the definition
    is checked exactly — the scheme maps the samples ``p(j + tau/(m-1))`` of every polynomial of degree
    ``<= d`` to ``p((i + tau/(m-1))/m)`` — with the exceptional values of the smoothing factor as
    candidates. Both are kept because the binary route's witness (``generation_degree``) and candidate
    set are what the binary reports and goldens record.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> w = sp.Symbol("w")
    >>> four = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
    >>> r = polynomial_reproduction(four)
    >>> r.value, r.witness["tau"], r.witness["higher"]
    (1, 0, [{'condition': {w: 1/16}, 'degree': 3}])
    >>> polynomial_reproduction(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), arity=3).value   # ternary linear B-spline
    1
    """
    m = check_arity(arity)
    if m != 2:
        deg, tau = _reproduction_degree(a, m)
        higher = []
        if a.params and deg >= 0:
            seen = []
            for sol in (e["condition"] for e in smoothing_factor(a, arity=m).witness["exceptional"]):
                if sol in seen:
                    continue
                seen.append(sol)
                d, _ = _reproduction_degree(a.subs(sol), m)
                if d > deg:
                    higher.append({"condition": sol, "degree": d})
        return Result(value=deg, status=CERTIFIED,
                      witness={"tau": tau, "shift": sp.expand(tau / (m - 1)), "higher": higher},
                      provenance={"method": "exact check of p(j + tau/(m-1)) -> p((i + tau/(m-1))/m), deg p <= d",
                                  "parametrisation": f"t_i^n = (i + tau/{m - 1}) / {m}^n", "arity": m})
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


def symmetry(a: LaurentSymbol, *, arity: int = 2) -> Result:
    """Whether ``a_i = a_{c-i}`` with ``c = start + end`` (symmetric about ``c/2``).

    ``witness["kind"]`` is ``"primal"`` (centre an integer) or ``"dual"`` (half-integer). With
    parameters, a non-identical symmetry reports the exact values where it holds. For ``m > 2`` the
    limit function is then symmetric about ``witness["limit_centre"] = c/(2(m-1))`` (its support is
    ``[start, end]/(m-1)``; for ``m = 2`` that is the mask centre itself).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> symmetry(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)).witness["centre"]
    -1/2
    >>> r = symmetry(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), arity=3)
    >>> r.value, r.witness["limit_centre"]
    (True, 0)
    """
    m = check_arity(arity)
    c = a.start + a.end
    diffs = [sp.expand(a.coeff(i) - a.coeff(c - i)) for i in range(a.start, a.end + 1)]
    holds = all(d == 0 for d in diffs)
    witness = {"centre": sp.Rational(c, 2), "kind": "primal" if c % 2 == 0 else "dual"}
    if not holds and a.params:
        witness["solutions"] = sp.solve([d for d in diffs if d != 0], list(a.params), dict=True)
    if m != 2:
        witness["limit_centre"] = sp.Rational(c, 2 * (m - 1))
    return Result(value=holds, status=CERTIFIED, witness=witness,
                  provenance={"method": "exact comparison a_i = a_(start+end-i)", **arity_key(m)})
