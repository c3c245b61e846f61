"""Certified Hölder exponent and C^l verdicts of a bivariate scheme with an isotropic dilation.

With ``k`` the order of the sum rules (:func:`analysis.bivariate.algebra.sum_rules`) and ``T_eps|V_k`` the
transition operators restricted to the differences of order ``k``
(:func:`analysis.bivariate.transition.restricted_transition`),

    alpha = -log_{rho(M)} JSR(T_eps|V_k),        rho(M) = sqrt(|det M|),

is the Hölder exponent of the scheme for an isotropic ``M`` (Cabrelli–Heil–Molter 2004; Charina–Protasov 2019,
Sect. 2): ``S_a`` converges in ``C^l`` (``l < k``) exactly when ``JSR(T|V_{l+1}) < rho(M)^{-l}``; since
``V_k`` is contained in ``V_{l+1}``, ``alpha > l`` certifies ``C^l`` and ``alpha <= l`` refutes it; without sum
rules of order ``l + 1`` the scheme is not ``C^l`` (it does not even generate polynomials of degree ``l``). The
univariate formula ``alpha = k - log2 rho(c)`` (:mod:`analysis.regularity.holder`) is the case ``M = 2``.

For an anisotropic ``M`` (eigenvalues of different moduli, or a Jordan block) the Hölder exponent is not this
number (Charina–Protasov 2019 give it through the invariant subspaces of ``M``); the JSR is still certified, and
only the verdicts that hold for every expanding ``M`` are given: ``C^0`` (convergence) exactly when
``JSR(T|V_1) < 1``, i.e. ``JSR(T|V_k) < 1``. The Hölder exponent itself is reported as inconclusive.

Examples
--------
>>> from analysis.bivariate.mask import BivariateMask
>>> r = holder_exponent(BivariateMask.from_symbol("(1+z1)*(1+z2)*(1+z1*z2)/(2*z1*z2)"))    # Courant element
>>> r.value, r.status, r.witness["jsr"].value
(1, 'certified', 1/2)
>>> [smoothness_verdicts(r)[l] for l in (0, 1)]
[True, False]

References
----------
C. Cabrelli, C. Heil, U. Molter, *Self-similarity and multiwavelets in higher dimensions*, Mem. AMS 170 (2004).
M. Charina, V. Yu. Protasov, *Regularity of anisotropic refinable functions*, ACHA 47 (2019) 795-821.
R.-Q. Jia, *Subdivision schemes in L_p spaces*, Adv. Comput. Math. 3 (1995) 309-341.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .algebra import sum_rules
from .mask import BivariateMask
from .transition import restricted_transition

__all__ = ["holder_exponent", "smoothness_verdicts", "BUDGET", "log_interval"]

#: default work budget of the JSR engine (units of :func:`analysis.jsr.jsr_bounds`)
BUDGET = 20_000


def log_interval(lo, hi, base2: int, prec: int = 90) -> tuple[sp.Rational, sp.Rational]:
    """Rational outward bounds of ``[log_b lo, log_b hi]`` with ``b = sqrt(base2)`` (Arb-free: mpmath.iv)."""
    from mpmath import iv

    from ..algebra.algebraic import _q

    old = iv.prec
    iv.prec = prec
    try:
        lb = iv.log(iv.mpf(base2)) / 2
        L1 = iv.log(iv.mpf(int(sp.Rational(lo).p)) / int(sp.Rational(lo).q)) / lb
        L2 = iv.log(iv.mpf(int(sp.Rational(hi).p)) / int(sp.Rational(hi).q)) / lb
        return _q(L1.a), _q(L2.b)
    finally:
        iv.prec = old


def _power_exponent(x: sp.Rational, m: int) -> sp.Rational | None:
    """``s`` with ``x = sqrt(m)^s`` exactly (``s`` rational), else None."""
    x = sp.Rational(x)
    if x <= 0:
        return None
    fx = sp.factorint(x.p)
    fx.update({p: -e for p, e in sp.factorint(x.q).items()})
    fx.pop(1, None)
    fm = sp.factorint(m)
    if set(fx) - set(fm):
        return None
    ratios = {sp.Rational(fx.get(p, 0), e) for p, e in fm.items()}
    if len(ratios) != 1:
        return None
    return 2 * ratios.pop()


def holder_exponent(a: BivariateMask, *, budget: int = BUDGET, max_length: int = 10, k: int | None = None) -> Result:
    """A certified enclosure of the Hölder exponent of ``S_a`` (module docstring); ``value`` is exact when the
    JSR is a rational power of ``rho(M)`` proven equal to its bounds; ``witness["alpha_closed_form"]`` the
    closed form ``-log_{rho(M)}(JSR)`` when the JSR is known exactly.

    ``witness``: ``k`` (sum rules used), ``omega`` (the invariant support), ``dimension`` of ``V_k``, ``jsr``
    (the :func:`analysis.jsr.jsr_bounds` result), ``isotropic``.
    """
    from ..jsr import jsr_bounds

    D = a.dilation
    if k is None:
        sr = sum_rules(a)
        k = sr.value
        if sr.witness["failing"] is None:
            raise AnalysisError(f"the mask satisfies sum rules of every order up to {k} (the limit): the "
                                "Hölder formula needs the exact order")
    if k == 0:
        raise AnalysisError("the mask does not satisfy the sum rules of order 1 (each coset summing to 1): "
                            "the scheme does not converge")
    fam = restricted_transition(a, k)
    r = jsr_bounds(list(fam.matrices), budget=budget, max_length=max_length)
    m = D.m
    wit: dict[str, Any] = {"k": k, "omega": fam.omega, "dimension": fam.dimension, "jsr": r,
                           "isotropic": D.isotropic, "rho_M": sp.sqrt(m), "digits": D.digits}
    prov = {"method": "alpha = -log_rho(M) JSR(T_eps|V_k) (Cabrelli-Heil-Molter; Charina-Protasov)",
            "jsr_method": r.provenance.get("method"), "work": r.provenance.get("work"),
            "budget": budget}
    if not D.isotropic:
        return Result(value=None, lower=None, upper=None, status=INCONCLUSIVE, witness=wit,
                      provenance={**prov, "message": "M is anisotropic: -log_rho(M) JSR(T|V_k) is not the Hölder "
                                  "exponent (Charina-Protasov 2019); only C^0 is decided"})
    lo, hi = r.lower, r.upper
    if lo is None or lo <= 0:
        raise AnalysisError("the JSR lower bound is 0: the Hölder formula does not apply")
    value = None
    jsr_value = r.value if r.value is not None else (lo if hi is not None and lo == hi else None)
    if jsr_value is not None:
        wit["jsr_value"] = jsr_value
        s = _power_exponent(jsr_value, m)
        if s is not None:
            value = -s
            wit["alpha_closed_form"] = value
        else:
            wit["alpha_closed_form"] = -2 * sp.log(sp.Rational(jsr_value)) / sp.log(m)
    if hi is not None:
        l_lo, l_hi = log_interval(lo, hi, m)
        a_lo, a_hi = -l_hi, -l_lo
    else:
        a_lo, a_hi = None, -log_interval(lo, lo, m)[0]
    s_lo = _power_exponent(lo, m)
    if s_lo is not None:                     # JSR >= rho(M)^s exactly: alpha <= -s exactly
        a_hi = -s_lo
        wit["alpha_upper_exact"] = True
    return Result(value=value, lower=value if value is not None else a_lo,
                  upper=value if value is not None else a_hi, status=r.status, witness=wit, provenance=prov)


def smoothness_verdicts(h: Result, max_l: int | None = None) -> dict[int, bool | None]:
    """``{l: True (C^l) / False (not C^l) / None}`` for ``l = 0 .. k`` from a :func:`holder_exponent` result.

    Isotropic ``M``: ``C^l`` iff ``alpha > l`` (for ``l < k``); not ``C^l`` for ``l >= k`` (no sum rules of
    order ``l + 1``). Anisotropic: only ``C^0`` (``JSR(T|V_k) < 1``: the quotient ``V_1/V_k`` carries only
    eigenvalues of ``M^{-1}``) and the sum-rule refutations.
    """
    k = h.witness["k"]
    top = k if max_l is None else max_l
    out: dict[int, bool | None] = {}
    certified = h.status == CERTIFIED
    for l in range(top + 1):
        if l >= k:
            out[l] = False
        elif not h.witness["isotropic"]:
            # V_1 / V_k carries only the eigenvalues of M^-1 (modulus < 1): C^0 iff JSR(T|V_k) < 1
            r = h.witness["jsr"]
            if l == 0 and r.status == CERTIFIED and r.upper is not None and r.upper < 1:
                out[l] = True
            elif l == 0 and r.lower is not None and r.lower >= 1:
                out[l] = False
            else:
                out[l] = None
        elif h.value is not None and certified:
            out[l] = bool(h.value > l)
        elif h.lower is not None and h.lower > l:          # from the rigorous upper bound of the JSR
            out[l] = True
        elif h.upper is not None and h.upper <= l:          # from the certified lower bound of the JSR
            out[l] = False
        else:
            out[l] = None
    return out
