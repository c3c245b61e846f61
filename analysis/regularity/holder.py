"""The Hölder exponent of a scheme (one entry point for every kind of mask) and C^k verdicts.

Hölder exponent (Rioul 1992; Daubechies–Lagarias 1992), as in DESIGN.md: with ``N`` the number
of factors ``(1+z)`` of ``a`` and ``k = N - 1``,

    alpha = k - log2 rho(c),    c(z) = 2^k a(z) / (1+z)^(k+1),

``rho(c)`` the joint spectral radius of the two transition matrices of ``c``
(:func:`analysis.stationary.transition.transition_matrices`), bounded rigorously by
:func:`analysis.jsr.jsr_bounds`. The scheme is C^j exactly when ``alpha > j`` (for ``j < N``):
then the j-th divided-difference scheme converges; when ``alpha <= j`` it does not, since
``rho(1/2 S_{b_{j+1}}) >= 1`` (Dyn–Levin 2002, Thm 3.4 and Sect. 3.5).

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> r = holder_exponent(LaurentSymbol.from_mask(["1/8", "1/2", "3/4", "1/2", "1/8"], start=-2))
>>> r.value, r.status                                   # cubic B-spline: alpha = 3, attained
(3, 'certified')
>>> smoothness(LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2), 2).value   # Chaikin is not C^2
False

Kinds of mask
-------------
:func:`holder_exponent` takes an exact :class:`~analysis.algebra.symbol.LaurentSymbol`
(rational or algebraic coefficients: exact transition matrices, exact/Arb certificate), a mask
typed in closed form (:class:`~analysis.algebra.closed_form.ClosedFormMask`: N decided exactly,
then the ball route), a decimal table under the approximate reading
(:class:`~analysis.algebra.approx.ApproximateMask`), a catalogue entry known by Arb balls
(Daubechies: ``enclosure(prec)``, ``sum_rules``) or a list of ``flint.arb`` balls with
``sum_rules=N``; the ball route is :func:`analysis.regularity.balls.ball_route`.

Algorithm
---------
JSR bounds (lower: spectral radius of a spectrum-maximizing product; upper: an invariant
polytope norm, re-checked in exact/ball arithmetic) are turned into an enclosure of alpha with
outward rounding. C^j verdicts compare the rational JSR bounds with the power of two exactly;
when the lower bound is attained exactly (``rho(Pi) = 2^{(k-j)L}``, the borderline), the
comparison is decided with the exact characteristic polynomial of the product.

References
----------
O. Rioul, *Simple regularity criteria for subdivision schemes*, SIAM J. Math. Anal. 23 (1992).
I. Daubechies, J. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23 (1992).
N. Guglielmi, V. Protasov, *Exact computation of joint spectral characteristics of linear
operators*, Found. Comput. Math. 13 (2013).
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, Sequence

from ..algebra.limits import arity_key, check_arity
from ..result import CERTIFIED, INCONCLUSIVE, NUMERICAL, AnalysisError, Result
from .balls import _is_symbol, ball_route
from .convergence import NotConvergent, difference_mask, log_interval, power_exponent

if TYPE_CHECKING:  # pragma: no cover
    import sympy as sp

    from ..algebra.symbol import LaurentSymbol

# No sympy at import: a mask known by balls (a catalogue entry such as daubechies-8) takes the
# ball route without it; the exact route and the exact C^j tests import it.


#: default work budgets of :func:`holder_exponent` (units of :func:`analysis.jsr.jsr_bounds`)
EXACT_BUDGET = 20_000
BALL_BUDGET = 60_000


def holder_exponent(a: Any, *, arity: int = 2, budget: int | None = None, max_length: int | None = None,
                    rel_gap: float = 1e-8, arithmetic: str | None = None, sum_rules: int | None = None,
                    prec: int | None = None) -> Result:
    """A certified enclosure ``[lower, upper]`` of the Hölder exponent of the scheme ``S_a``.

    ``arity`` ``m`` (default 2): ``(S_a f)_i = sum_j a_{i-mj} f_j`` and ``alpha = k - log_m JSR`` of the
    ``m`` transition matrices; for ``m > 2`` the mask must be an exact symbol.

    ``a`` is any kind of mask (module docstring). ``arithmetic`` is ``"exact"`` (the default
    for a :class:`~analysis.algebra.symbol.LaurentSymbol`) or ``"ball"`` (the symbol's
    coefficients enclosed in Arb balls; the default for every other kind). ``sum_rules`` and
    ``prec`` are for the ball route (``N`` for a bare list of balls; ball radius ``2^-prec``).
    ``budget`` (default 20 000 work units exact, 60 000 ball), ``max_length`` and ``rel_gap`` go
    to :func:`analysis.jsr.jsr_bounds`. The budget counts work, never time, so the result does not
    depend on the machine or its load: a unit is about a millisecond of the reference machine,
    counted as the joint spectral radius search works (1000 product entries in the s.m.p. search,
    50 polytope membership tests or one linear program, a few Arb products in the norm bound; see
    :func:`analysis.jsr.jsr_bounds`). ``provenance["work"]`` says how many were spent,
    ``provenance["timing"]`` the wall-clock seconds (reported only).

    ``value`` is the exact exponent when the JSR is attained by a product with a rational
    spectral radius that is a power of two (B-splines); otherwise ``lower``/``upper`` are
    rationals and ``witness["alpha_exact"]`` gives ``k - log2(rho(Pi))/L`` when the JSR is proven
    equal to ``rho(Pi)^(1/L)``. The status is that of the JSR bounds. Raises
    :class:`~analysis.regularity.convergence.NotConvergent` (a certified verdict) when a sum rule
    fails.

    >>> import schemes
    >>> holder_exponent(schemes.get("four-point").symbol_at(w="1/16")).value
    2
    >>> r = holder_exponent(schemes.get("daubechies-6"))                  # Arb ball mask
    >>> r.status, round(float(r.lower), 9)
    ('certified', 1.087833926)
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> holder_exponent(LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)"), arity=3).value   # ternary cubic B-spline
    3
    """
    m = check_arity(arity)
    if arithmetic not in (None, "exact", "ball"):
        raise AnalysisError(f"arithmetic must be 'exact' or 'ball', not {arithmetic!r}")
    if m != 2 and not (_is_symbol(a) and arithmetic != "ball"):
        raise AnalysisError(f"an m-ary Hölder exponent needs an exact symbol, not {type(a).__name__}")
    if _is_symbol(a) and arithmetic != "ball":
        return _exact_route(a, arity=m, budget=EXACT_BUDGET if budget is None else budget,
                            max_length=12 if max_length is None else max_length, rel_gap=rel_gap)
    if arithmetic == "exact":
        raise AnalysisError(f"exact arithmetic needs an exact symbol, not {type(a).__name__}")
    kw = {"budget": BALL_BUDGET if budget is None else budget,
          "max_length": 16 if max_length is None else max_length, "rel_gap": rel_gap}
    if _is_instance(a, "analysis.algebra.closed_form", "ClosedFormMask"):
        return _closed_form_route(a, prec=prec, **kw)
    if _is_instance(a, "analysis.algebra.approx", "ApproximateMask"):
        return _approximate_route(a, **kw)
    return ball_route(a, sum_rules=sum_rules, prec=prec, **kw)


def _is_instance(x: Any, module: str, name: str) -> bool:
    """``isinstance(x, module.name)`` without importing ``module`` (sympy): an instance exists
    only once its module is imported."""
    mod = sys.modules.get(module)
    return mod is not None and isinstance(x, getattr(mod, name))


def _closed_form_route(m, *, prec: int | None = None, **kw) -> Result:
    """A mask typed in closed form: N, ``a(1) = 2`` and reality decided exactly, then balls."""
    if m.undecided is not None:
        raise AnalysisError(f"{m.undecided} (the ball route needs N decided exactly; "
                            "a ball containing 0 is no proof of zero)")
    if m.failure is not None:
        raise NotConvergent(m.failure)
    prec = prec if prec is not None else 128 + 4 * m.sum_rules
    h = ball_route(m, prec=prec, **kw)
    source, message = m.description(prec)
    return Result(value=h.value, lower=h.lower, upper=h.upper, status=h.status,
                  witness={**h.witness, "reading": "closed form, ball route"},
                  provenance={**h.provenance, "source": source, "message": message})


def _approximate_route(m, **kw) -> Result:
    """A decimal table under the approximate reading: alpha for every mask in the balls with
    ``a(1) = 2`` and ``(1+z)^N | a`` (``N`` the highest order of an exact witness mask found in
    the balls), and a lower bound for every convergent mask in them.

    ``k - log2 rho(c_k)`` is ``min(alpha, k + 1)``: the factors ``(1+z)`` that ``c_k`` keeps give its
    transition matrices the eigenvalue 1/2. So the enclosure is the exponent of every mask of the
    set only when its upper end is below ``N``; when it reaches ``N`` (the balls may hold masks with
    more factors than the witness has), only ``alpha >= lower`` is certified and said so. Masks in
    the balls with fewer factors are convergent too (one factor suffices): for all of them only the
    one-factor bound ``alpha >= -log2 rho(c_0)`` holds, reported in ``witness["every_convergent_mask"]``.
    """
    N = m.sum_rules
    prec = 128 + 4 * N
    h = ball_route(m.enclosure(prec), sum_rules=N, prec=prec, **kw)
    lower, upper, message = h.lower, h.upper, m.description()
    ceiling = upper is not None and bool(upper >= N)      # a JSON true/false (it was sympy's "False" text)
    if ceiling:
        upper = None
        message += (f"; alpha of these masks is >= {float(lower):.10g} only: {N} - log2 rho reaches its ceiling {N} "
                    f"(a mask with more than {N} factors (1+z) in the balls is not excluded)")
    witness = {**h.witness, **m.witness(), "ceiling_reached": ceiling}
    if N > 1:
        # a bound, not a value (its ceiling is 1): a small budget; the polytope would chase the
        # many products tied at 1/2
        one = ball_route(m.enclosure(132), sum_rules=1, prec=132, **{**kw, "budget": 2000, "max_length": 8})
        witness["every_convergent_mask"] = {"sum_rules": 1, "lower": one.lower, "status": CERTIFIED,
                                            "statement": "alpha >= lower (a rigorous bound; one factor caps it at 1)",
                                            "valid_for": "every mask in the balls with a(1) = 2 and (1+z) | a"}
    return Result(value=None, lower=lower, upper=upper, status=h.status, witness=witness,
                  provenance={**h.provenance, "message": message})


def _exact_route(a: LaurentSymbol, *, arity: int = 2, budget: int = EXACT_BUDGET, max_length: int = 12,
                 rel_gap: float = 1e-8) -> Result:
    """A certified enclosure ``[lower, upper]`` of the Hölder exponent of the scheme ``S_a`` of arity ``m``:
    ``alpha = k - log_m JSR(T_0, ..., T_{m-1})`` of ``c = m^k a/q_m^(k+1)``.

    ``value`` is the exact exponent when the JSR is attained by a product with a rational
    spectral radius that is a power of ``m`` (B-splines); otherwise ``lower``/``upper`` are
    rationals and (``m = 2``) ``witness["alpha_exact"]`` gives ``k - log2(rho(Pi))/L`` when the JSR is
    proven equal to ``rho(Pi)^(1/L)``. The status is that of the JSR bounds.
    """
    import sympy as sp

    from ..stationary.transition import transition_matrices

    from ..jsr import jsr_bounds

    m = arity
    k, c = difference_mask(a, arity=m)
    r = jsr_bounds(list(transition_matrices(c, arity=m)), budget=budget, max_length=max_length, rel_gap=rel_gap)
    lo, hi = r.lower, r.upper
    witness = {"k": k, "c": c, **arity_key(m), "jsr": r, "product": r.witness.get("product"),
               "rho_product": r.witness.get("rho_product")}
    value = None
    if lo is None or lo <= 0:
        raise AnalysisError("the joint spectral radius lower bound is 0; the Hölder formula does not apply")
    a_lo = a_hi = None
    if hi is not None:
        l2lo, l2hi = log_interval(sp.Rational(lo), sp.Rational(hi), m)
        a_lo, a_hi = k - l2hi, k - l2lo
    else:
        a_hi = k - log_interval(sp.Rational(lo), sp.Rational(lo), m)[0]
    if r.value is not None:
        e = power_exponent(r.value, m)
        if e is not None:
            value = sp.Integer(k - e)
    if m == 2 and r.status == CERTIFIED and r.witness.get("closed"):
        word = r.witness.get("product") or ()
        rho_expr = r.witness.get("rho_product_root_exact")
        if rho_expr is not None:
            witness["alpha_exact"] = sp.Integer(k) - sp.log(rho_expr, 2)
        elif word:
            witness["alpha_exact"] = f"{k} - log2(rho(T_{''.join(map(str, word))}))/{len(word)}"
    if m == 2:
        prov = {"method": "alpha = k - log2 JSR(T0, T1) of c = 2^k a/(1+z)^(k+1)",
                "jsr_method": r.provenance.get("method"), "arithmetic": r.provenance.get("arithmetic")}
    else:
        prov = {"method": f"alpha = k - log_{m} JSR(T_0..T_{m - 1}) of c = {m}^k a/q_{m}^(k+1)",
                "arity": m, "jsr_method": r.provenance.get("method")}
    return Result(value=value, lower=a_lo if value is None else value, upper=a_hi if value is None else value,
                  status=r.status, witness=witness,
                  provenance={**prov, "work": r.provenance.get("work"), "timing": r.provenance.get("timing"),
                              **({"message": r.provenance["message"]}
                                 if m == 2 and "message" in r.provenance else {})})


# --------------------------------------------------------------------------------------------
# C^j verdicts
# --------------------------------------------------------------------------------------------

def word_product(T: Sequence[sp.Matrix], word: Sequence[int]) -> sp.Matrix:
    import sympy as sp

    P = sp.eye(T[0].shape[0])
    for i in word:
        P = P * T[i]
    return P


def _spectral_radius_at_least_exact(P: sp.Matrix, theta: sp.Rational) -> bool | None:
    """Exactly: does the rational matrix ``P`` have an eigenvalue of modulus >= theta?

    Decided for real eigenvalues by Sturm counting; complex ones through certified complex
    root balls (python-flint). ``None`` when it cannot be decided.
    """
    import sympy as sp

    lam = sp.Symbol("lambda")
    cp = sp.Poly(P.charpoly(lam).as_expr(), lam, domain=sp.QQ)
    if cp.count_roots(theta, sp.oo) > 0 or cp.count_roots(-sp.oo, -theta) > 0:
        return True
    try:
        from flint import fmpq_poly, arb

        coeffs = [sp.Rational(c) for c in reversed(cp.all_coeffs())]
        den = 1
        for c in coeffs:
            den = sp.ilcm(den, c.q)
        fp = fmpq_poly([int(c * den) for c in coeffs])
        roots = fp.complex_roots()
        th = arb(int(theta.p)) / int(theta.q)
        undecided = False
        for root, _mult in roots:
            modulus = abs(root)
            if modulus > th:
                return True
            if not (modulus < th) and not root.imag.is_zero():
                undecided = True  # real roots were decided exactly above
        return None if undecided else False
    except Exception:  # pragma: no cover - flint unavailable
        return None


def smoothness(a: Any, j: int, *, arity: int = 2, budget: int = EXACT_BUDGET, max_length: int = 12,
               max_L: int = 4, max_word: int = 3) -> Result:
    """Is ``S_a`` C^j?  ``value`` True (alpha > j certified), False (alpha <= j certified), None.

    ``a``: any kind of mask :func:`holder_exponent` takes (ball masks: from the enclosure of alpha).

    ``witness["reason"]`` says which bound decided it: the JSR upper bound below ``m^(k-j)``
    (C^j), or a product ``Pi`` with ``rho(Pi)^(1/L) >= m^(k-j)`` (not C^j; decided exactly when
    equality holds). An inconclusive verdict says what would settle it.

    Arity ``m > 2`` (an exact symbol): :func:`_smoothness_dilated` — the same order of tests (sum rules
    naming the root of unity, factor count, Dyn–Levin norms for ``L <= max_L``, exact spectral radii
    of products of length ``<= max_word``, then the JSR bounds), with sympy products; the binary route
    below uses FLINT products, norms up to ``L = 6``, words up to length 4 and an exact borderline
    check. The two are kept apart because their witnesses (which test decided, in which words) are
    what the reports and goldens of each arity record; ``max_L``/``max_word`` apply to ``m > 2``.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> smoothness(LaurentSymbol.from_mask([1, 2]), 0, arity=3).witness["reason"]
    'not convergent: a(exp(2*pi*i/3)) = sqrt(3)*I != 0; a(exp(4*pi*i/3)) = -sqrt(3)*I != 0'
    """
    m = check_arity(arity)
    if m != 2:
        return _smoothness_dilated(a, m, j, budget=budget, max_length=max_length, max_L=max_L, max_word=max_word)
    if j < 0:
        raise AnalysisError("j must be >= 0")
    if not _is_symbol(a):
        try:
            return verdict_from_enclosure(holder_exponent(a, budget=budget), j)
        except NotConvergent as exc:
            return exc.result()
    import sympy as sp

    from ..stationary.transition import transition_matrices
    try:
        k, c = difference_mask(a)
    except NotConvergent as exc:          # certified: not even C^0
        return exc.result()
    if j > k:
        return Result(value=False, status=CERTIFIED,
                      witness={"reason": f"only {k + 1} factors (1+z): alpha <= {k + 1} and C^{j} needs "
                                         f"(1+z)^{j + 1} | a and alpha > {j}", "k": k},
                      provenance={"method": "factor count"})
    quick = _quick_verdict(a, c, k, j)
    if quick is not None:
        return quick
    h = holder_exponent(a, budget=budget, max_length=max_length)
    theta = sp.Integer(2) ** (k - j)
    jsr = h.witness["jsr"]
    lo, hi = jsr.lower, jsr.upper
    witness = {"alpha": h, "k": k, "threshold_jsr": theta}
    rigorous = jsr.provenance.get("input_kind") != "float"
    if hi is not None and hi < theta and rigorous:
        witness["reason"] = f"JSR <= {sp.sstr(hi)} < 2^{k - j}: alpha > {j}"
        return Result(value=True, status=CERTIFIED, witness=witness, provenance=h.provenance)
    if lo is not None and lo >= theta and rigorous:
        witness["reason"] = f"rho(Pi)^(1/L) >= {sp.sstr(lo)} >= 2^{k - j}: alpha <= {j}"
        return Result(value=False, status=CERTIFIED, witness=witness, provenance=h.provenance)
    word = jsr.witness.get("product") or ()
    if word and rigorous:
        T = transition_matrices(c)
        P = word_product(T, word)
        exact = _spectral_radius_at_least_exact(P, theta ** len(word))
        if exact:
            witness["reason"] = (f"the product T_{''.join(map(str, word))} has an eigenvalue of modulus >= "
                                 f"2^{(k - j) * len(word)} (exact characteristic polynomial): alpha <= {j}")
            return Result(value=False, status=CERTIFIED, witness=witness, provenance=h.provenance)
    witness["reason"] = (f"JSR in [{sp.sstr(lo)}, {sp.sstr(hi)}] straddles 2^{k - j}: a longer budget, "
                         "a better spectrum-maximizing product or exact borderline analysis would settle it")
    return Result(value=None, status=INCONCLUSIVE if rigorous else NUMERICAL, witness=witness, provenance=h.provenance)


def _smoothness_dilated(a: LaurentSymbol, m: int, j: int, *, budget: int, max_length: int, max_L: int,
                        max_word: int) -> Result:
    """:func:`smoothness` for arity ``m > 2`` (see there)."""
    import sympy as sp

    from ..stationary.transition import transition_matrices

    from itertools import product as words

    from ..stationary.difference import difference_norm

    if not isinstance(j, int) or j < 0:
        raise AnalysisError("j must be a non-negative integer")
    try:
        k, c = difference_mask(a, arity=m)
    except NotConvergent as exc:
        return exc.result()
    prov = {"arity": m}
    if j > k:
        return Result(value=False, status=CERTIFIED,
                      witness={"reason": f"only {k + 1} factors q_{m}: alpha <= {k + 1} and C^{j} needs "
                                         f"q_{m}^{j + 1} | a and alpha > {j}", "k": k},
                      provenance={**prov, "method": "factor count"})
    if a.domain.is_QQ or a.domain.is_ZZ:
        for L in range(1, max_L + 1):
            r = difference_norm(a, j + 1, L, arity=m)
            if r.witness["contractive"]:
                return Result(value=True, status=CERTIFIED,
                              witness={"reason": f"||(1/{m} S_a{j + 1})^{L}||_inf = {sp.sstr(r.value)} < 1 "
                                                 "(Dyn-Levin)", "k": k, "norm": r},
                              provenance={**prov, "method": "exact m-ary Dyn-Levin norm test"})
        T = transition_matrices(c, arity=m)
        theta = sp.Integer(m) ** (k - j)
        for L in range(1, max_word + 1):
            for w in words(range(m), repeat=L):
                if L > 1 and min(w[i:] + w[:i] for i in range(L)) != w:
                    continue
                P = sp.eye(T[0].shape[0])
                for i in w:
                    P = P * T[i]
                x = sp.Symbol("x")
                if _modulus_at_least([sp.Rational(c) for c in reversed(P.charpoly(x).all_coeffs())], theta ** L):
                    return Result(value=False, status=CERTIFIED,
                                  witness={"reason": f"the product T_{''.join(map(str, w))} has an eigenvalue of "
                                                     f"modulus >= {m}^{(k - j) * L}: alpha <= {j}",
                                           "k": k, "product": w},
                                  provenance={**prov, "method": "exact spectral radius of a short product"})
    h = holder_exponent(a, arity=m, budget=budget, max_length=max_length)
    jsr = h.witness["jsr"]
    lo, hi = jsr.lower, jsr.upper
    theta = sp.Integer(m) ** (k - j)
    witness = {"alpha": h, "k": k, "threshold_jsr": theta}
    if hi is not None and hi < theta:
        witness["reason"] = f"JSR <= {sp.sstr(hi)} < {m}^{k - j}: alpha > {j}"
        return Result(value=True, status=CERTIFIED, witness=witness, provenance=h.provenance)
    if lo is not None and lo >= theta:
        witness["reason"] = f"rho(Pi)^(1/L) >= {sp.sstr(lo)} >= {m}^{k - j}: alpha <= {j}"
        return Result(value=False, status=CERTIFIED, witness=witness, provenance=h.provenance)
    witness["reason"] = (f"JSR in [{sp.sstr(lo)}, {sp.sstr(hi)}] straddles {m}^{k - j}: a longer budget or a "
                         "better spectrum-maximizing product would settle it")
    return Result(value=None, status=INCONCLUSIVE, witness=witness, provenance=h.provenance)


def _modulus_at_least(charpoly_coeffs: list, theta: sp.Rational) -> bool | None:
    """Exactly: does the rational polynomial (coefficients low->high) have a root with |x| >= theta?"""
    import sympy as sp

    x = sp.Symbol("x")
    poly = sp.Poly(list(reversed(charpoly_coeffs)), x, domain=sp.QQ)
    if poly.count_roots(theta, sp.oo) > 0 or poly.count_roots(-sp.oo, -theta) > 0:
        return True
    from flint import arb, fmpq_poly

    roots = fmpq_poly([int(c * sp.ilcm(*[sp.Rational(d).q for d in charpoly_coeffs])) for c in charpoly_coeffs])
    th = arb(int(theta.p)) / int(theta.q)
    undecided = False
    for root, _ in roots.complex_roots():
        m = abs(root)
        if m > th:
            return True
        if not (m < th) and not root.imag.is_zero():
            undecided = True
    return None if undecided else False


def _quick_verdict(a: LaurentSymbol, c: LaurentSymbol, k: int, j: int, *, max_L: int = 6,
                   max_word: int = 4) -> Result | None:
    """Cheap exact verdicts before the JSR: the Dyn–Levin norm test (C^j) for L <= max_L, and
    exact spectral radii of all products of length <= max_word (not C^j)."""
    import sympy as sp

    from ..stationary.transition import transition_matrices

    if not (a.domain.is_QQ or a.domain.is_ZZ):
        return None
    from ..stationary.difference import difference_norm

    for L in range(1, max_L + 1):
        r = difference_norm(a, j + 1, L)
        if r.witness["contractive"]:
            return Result(value=True, status=CERTIFIED,
                          witness={"reason": f"||(1/2 S_a{j + 1})^{L}||_inf = {sp.sstr(r.value)} < 1 (Dyn-Levin)",
                                   "k": k, "norm": r},
                          provenance={"method": "exact Dyn-Levin norm test"})
    from itertools import product as words

    from flint import fmpq, fmpq_mat

    T = [fmpq_mat(M.rows, M.cols, [fmpq(int(sp.Rational(x).p), int(sp.Rational(x).q)) for x in M])
         for M in transition_matrices(c)]
    theta = sp.Integer(2) ** (k - j)
    for L in range(1, max_word + 1):
        for w in words(range(2), repeat=L):
            if L > 1 and (w[0] != 0 or min(w[i:] + w[:i] for i in range(L)) != w):
                continue  # cyclic rotations have the same spectrum
            P = T[w[0]]
            for i in w[1:]:
                P = P * T[i]
            cp = P.charpoly()
            coeffs = [sp.Rational(int(q.p), int(q.q)) for q in cp.coeffs()]
            if _modulus_at_least(coeffs, theta ** L):
                return Result(value=False, status=CERTIFIED,
                              witness={"reason": f"the product T_{''.join(map(str, w))} has an eigenvalue of modulus "
                                                 f">= 2^{(k - j) * L} (exact characteristic polynomial): alpha <= {j}",
                                       "k": k, "product": w},
                              provenance={"method": "exact spectral radius of a short product"})
    return None


def verdict_from_enclosure(h: Result, j: int) -> Result:
    """C^j iff alpha > j, decided from a rigorous enclosure of alpha (ball masks)."""
    from ..jsonable import fmt_bound

    jsr = h.witness.get("jsr")
    rigorous = jsr is None or jsr.provenance.get("input_kind") != "float"
    lo, hi = h.lower, h.upper
    if rigorous and lo is not None and lo > j:
        return Result(value=True, status=CERTIFIED,
                      witness={"reason": f"alpha >= {fmt_bound(lo, 'lower', 10)} > {j} (certified enclosure)"})
    if rigorous and hi is not None and hi <= j:
        return Result(value=False, status=CERTIFIED,
                      witness={"reason": f"alpha <= {fmt_bound(hi, 'upper', 10)} <= {j} (certified enclosure)"})
    lo_t = "?" if lo is None else fmt_bound(lo, "lower", 10)
    hi_t = "?" if hi is None else fmt_bound(hi, "upper", 10)
    return Result(value=None, status=INCONCLUSIVE if rigorous else NUMERICAL,
                  witness={"reason": f"alpha in [{lo_t}, {hi_t}] does not decide alpha > {j}: "
                                     "a longer budget would settle it"})

