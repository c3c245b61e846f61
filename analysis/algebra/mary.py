"""m-ary symbols: sum rules, smoothing factor, polynomial generation/reproduction for arity ``m >= 2``.

Convention (README "Conventions", arity ``m``)::

    (S_a f)_i = sum_j a_{i-mj} f_j,        a(z) = sum_i a_i z^i,      q_m(z) = 1 + z + ... + z^{m-1}.

The arity is passed to the analyses (``arity=m``), it is not stored on
:class:`~analysis.algebra.symbol.LaurentSymbol`: a symbol is a Laurent polynomial, and the binary
code paths (``arity=2``, the default everywhere) stay exactly as they were.

* **sum rules**: ``a(1) = m`` and ``a(eps) = 0`` for every m-th root of unity ``eps != 1``;
  equivalently every residue sum ``A_r = sum_j a_{r+mj}`` equals 1 (the ``A_r`` are the inverse
  discrete Fourier transform of ``(a(eps^j))_j``). A failure names the root ``eps = exp(2 pi i j/m)``.
* **smoothing factor**: ``a(z) = (q_m(z)/m)^k b(z)`` with ``k`` maximal; with parameters the
  generic ``k`` plus the exact exceptional parameter values (where the remainder of the division
  by ``q_m`` vanishes identically).
* **generation** of degree ``k - 1`` when ``a(1) = m`` and ``q_m^k | a`` (Dyn–Levin; for arity m:
  Conti–Hormann 2011, Thm 3).
* **reproduction**: checked from the definition: with ``tau = a'(1)/m`` the scheme maps the samples
  ``p(j + tau/(m-1))`` of every polynomial ``p`` of degree ``<= d`` to ``p((i + tau/(m-1))/m)``
  (the only stationary parametrisation ``t_i^n = (i + tau/(m-1))/m^n``, Conti–Hormann 2011).
  For ``m = 2`` this is their derivative condition ``D^j a(1) = 2 tau (tau-1)...(tau-j+1)``.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> a = LaurentSymbol.from_expr("(1+z+z**2)**3/(9*z**3)")            # ternary quadratic B-spline
>>> sum_rules_mary(a, 3).value, smoothing_factor_mary(a, 3).value
(True, 3)
>>> r = sum_rules_mary(LaurentSymbol.from_mask([1, 2]), 3)        # a(1) = 3, residue sums 1, 2, 0
>>> r.value, r.witness["failures"]
(False, ['a(exp(2*pi*i/3)) = sqrt(3)*I != 0', 'a(exp(4*pi*i/3)) = -sqrt(3)*I != 0'])

Algorithm
---------
Residue sums and division by ``q_m`` in the exact coefficient domain (QQ, QQ<theta>, QQ[params]);
the value ``a(eps)`` at a root of unity is decided with cyclotomic remainders (rational masks) or
the exact sign of its real and imaginary parts (:func:`analysis.algebra.algebraic.sign`).

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002) 73-144.
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*,
J. Approx. Theory 163 (2011) 413-437.
"""

from __future__ import annotations

import sympy as sp

from .reader import LIMITS, InputError
from ..result import CERTIFIED, AnalysisError, Result
from .symbol import LaurentSymbol, Z
from .factorization import exceptional_cases

__all__ = ["check_arity", "q_symbol", "sum_rules_mary", "convergence_failure_mary", "divide_q",
           "factor_out_mary", "smoothing_factor_mary", "polynomial_generation_mary",
           "polynomial_reproduction_mary", "symmetry_mary"]


def check_arity(m) -> int:
    """``m`` as an int ``>= 2``, else a one-line :class:`AnalysisError`.

    >>> check_arity(3)
    3
    >>> check_arity(1)
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: the arity must be an integer >= 2, not 1
    """
    if isinstance(m, bool) or not isinstance(m, int):
        try:
            if isinstance(m, str) and m.strip().lstrip("+").isdigit():
                m = int(m)
            else:
                raise ValueError
        except ValueError:
            raise AnalysisError(f"the arity must be an integer >= 2, not {m!r}") from None
    if m < 2:
        raise AnalysisError(f"the arity must be an integer >= 2, not {m!r}")
    if m > LIMITS.arity:
        raise InputError(f"the arity {m} exceeds the limit {LIMITS.arity} (limit 'arity')", "limit")
    return m


def q_symbol(m: int) -> LaurentSymbol:
    """``q_m(z) = 1 + z + ... + z^{m-1}``.

    >>> q_symbol(3)
    LaurentSymbol([1, 1, 1], start=0, domain=QQ)
    """
    return LaurentSymbol.from_mask([1] * check_arity(m))


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


def sum_rules_mary(a: LaurentSymbol, m: int) -> Result:
    """The m-ary sum rules ``a(1) = m`` and ``a(eps) = 0`` at the m-th roots of unity ``eps != 1``.

    ``value`` True/False (numeric symbols; with parameters True only when they hold identically,
    and ``witness["solutions"]`` gives the exact parameter values where they hold).
    ``witness["residue_sums"]`` are ``A_r``; ``witness["failures"]`` names each failing condition,
    e.g. ``"a(1) = 2 != 3"`` or ``"a(exp(2*pi*i/3)) = sqrt(3)*I != 0"`` (long closed forms are shown
    rounded, ``"~ 0.5+0.866*I"``; the zero test itself is exact).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> sum_rules_mary(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"]), 2).witness["residue_sums"]
    [1, 1]
    """
    m = check_arity(m)
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


def convergence_failure_mary(a: LaurentSymbol, m: int) -> str | None:
    """``None`` when the m-ary sum rules hold exactly, else the reason naming the root of unity.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> convergence_failure_mary(LaurentSymbol.from_mask(["1/2", 1, 1, 1, "1/2"]), 4) is None
    True
    >>> convergence_failure_mary(LaurentSymbol.from_mask(["1/2", 1, 1, 1, "1/2"]), 3)
    'a(1) = 4 != 3; a(exp(2*pi*i/3)) = 1/4 + sqrt(3)*I/4 != 0; a(exp(4*pi*i/3)) = 1/4 - sqrt(3)*I/4 != 0'
    """
    a.require_numeric("the sum rules")
    r = sum_rules_mary(a, m)
    return None if r.value else "; ".join(r.witness["failures"])


def divide_q(a: LaurentSymbol, m: int):
    """``(quotient, remainder)`` of ``a = q_m * quotient + remainder`` (remainder a symbol of
    degree ``< m - 1`` relative to ``a.start``; zero exactly when ``q_m | a``)."""
    qp = sp.Poly([1] * m, Z, domain=a.domain)
    quo, rem = a.poly.div(qp)
    q = LaurentSymbol(quo, a.start, a.params) if not quo.is_zero else None
    return q, rem


def factor_out_mary(a: LaurentSymbol, k: int, m: int) -> LaurentSymbol:
    """``b = m^k a / q_m^k`` exactly, or :class:`AnalysisError` if ``q_m^k`` does not divide ``a``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> factor_out_mary(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 2, 3)
    LaurentSymbol([3], start=-2, domain=QQ)
    """
    m = check_arity(m)
    b = a
    for j in range(k):
        q, r = divide_q(b, m)
        if not r.is_zero or q is None:
            raise AnalysisError(f"the symbol has only {j} factor(s) 1+z+...+z^{m - 1} identically in its "
                                f"parameters; the difference scheme of order {k} needs {k}")
        b = q * m
    return b


def _generic_k(a: LaurentSymbol, m: int):
    if a.is_zero:
        raise AnalysisError("the zero symbol has no smoothing factor")
    k, b = 0, a
    while True:
        q, r = divide_q(b, m)
        if not r.is_zero or q is None:
            return k, b, r
        k, b = k + 1, q * m


def smoothing_factor_mary(a: LaurentSymbol, m: int, *, exceptional: bool = True, _depth: int = 0) -> Result:
    """The largest ``k`` with ``a = (q_m/m)^k b``, the quotient ``b`` and the exceptional values.

    ``witness["exceptional"]``: for each exact parameter value where ``q_m`` divides ``b`` again,
    ``{"condition": {param: value}, "k": k_there, "b": b_there}``.

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> mu = sp.Symbol("mu")
    >>> r = sp.Rational
    >>> a0, a1, a2, a3 = -r(1, 18) - mu/6, r(13, 18) + mu/2, r(7, 18) - mu/2, -r(1, 18) + mu/6
    >>> a = LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)  # Hassan et al. 2002
    >>> f = smoothing_factor_mary(a, 3)
    >>> f.value, [(e["condition"], e["k"]) for e in f.witness["exceptional"]]
    (3, [({mu: 1/27}, 4)])
    """
    m = check_arity(m)
    k, b, rem = _generic_k(a, m)
    cases = []
    if exceptional and a.params and _depth < 4:
        coeffs = [sp.expand(c) for c in rem.all_coeffs() if c != 0]
        coeffs = [rem.domain.to_sympy(c) if not isinstance(c, sp.Basic) else c for c in coeffs]
        cases = exceptional_cases(a, coeffs, lambda sub: smoothing_factor_mary(sub, m, exceptional=True,
                                                                                _depth=_depth + 1))
    return Result(value=k, status=CERTIFIED,
                  witness={"b": b, "identity": f"a(z) = ((1+...+z^{m - 1})/{m})^{k} b(z)", "exceptional": cases},
                  provenance={"method": f"exact division by 1+z+...+z^{m - 1}", "arity": m,
                              "domain": str(a.domain)})


def polynomial_generation_mary(a: LaurentSymbol, m: int) -> Result:
    """Generation degree ``k - 1`` (``q_m^k | a`` and ``a(1) = m``), else ``-1``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> polynomial_generation_mary(LaurentSymbol.from_expr("(1+z+z**2+z**3)**4/(64*z**4)"), 4).value
    3
    """
    m = check_arity(m)
    k = smoothing_factor_mary(a, m, exceptional=False).value
    deg = k - 1 if sp.expand(a(1) - m) == 0 else -1
    return Result(value=deg, status=CERTIFIED, witness={"k": k, "a(1)": sp.expand(a(1))},
                  provenance={"method": "sum rules of order k <=> q_m^k | a and a(1) = m", "arity": m})


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
    gen = polynomial_generation_mary(a, m).value
    tau = sp.expand(sum(i * c for i, c in a.items()) / m)
    shift = tau / (m - 1)
    deg = -1
    for d in range(0, max(gen, 0) + 1):
        if gen < 0 or not _reproduces(a, m, d, shift):
            break
        deg = d
    return deg, tau


def polynomial_reproduction_mary(a: LaurentSymbol, m: int) -> Result:
    """The degree of polynomial reproduction for arity ``m`` and ``tau = a'(1)/m``.

    With parameters: the generic degree and, in ``witness["higher"]``, exact parameter values where
    it is larger (candidates: the exceptional values of the smoothing factor and the roots of the
    next reproduction condition).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> polynomial_reproduction_mary(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 3).value   # ternary linear B-spline
    1
    """
    m = check_arity(m)
    deg, tau = _reproduction_degree(a, m)
    higher = []
    if a.params and deg >= 0:
        cands = [e["condition"] for e in smoothing_factor_mary(a, m).witness["exceptional"]]
        seen = []
        for sol in cands:
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


def symmetry_mary(a: LaurentSymbol, m: int) -> Result:
    """Symmetry ``a_i = a_{c-i}`` (``c = start + end``); for arity m the limit function is then
    symmetric about ``c/(2(m-1))`` (its support is ``[start, end]/(m-1)``).

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> r = symmetry_mary(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 3)
    >>> r.value, r.witness["limit_centre"]
    (True, 0)
    """
    from .factorization import symmetry

    m = check_arity(m)
    r = symmetry(a)
    c = a.start + a.end
    return Result(value=r.value, status=r.status,
                  witness={**r.witness, "limit_centre": sp.Rational(c, 2 * (m - 1))},
                  provenance={**r.provenance, "arity": m})
