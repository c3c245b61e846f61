"""Certified Hölder exponents and C^j verdicts of m-ary schemes.

Normalisation (derivation). Let ``a = (q_m/m)^N b`` with ``N`` maximal (``q_m = 1 + ... + z^{m-1}``),
``k = N - 1`` and

    c(z) = m^k a(z) / q_m(z)^(k+1)          (for m = 2: c = 2^k a/(1+z)^(k+1), as today).

``b_k = (m/q_m)^k a`` refines the k-th divided differences ``m^{nk} Delta^k f^n``; its difference scheme is
``z^{m-1} b_k / q_m``, a shift of ``c``. The refinable function of ``S_c`` has support ``[0, N_c/(m-1)]``
and ``rho(c) = JSR(T_0, ..., T_{m-1})`` (:func:`analysis.stationary.mary.transition_matrices_mary`)
is the contraction rate ``lim_L ||S_c^L||^(1/L)``: the k-th divided differences of ``S_a^n f`` at spacing
``m^{-n}`` have differences of size ``rho(c)^n = (m^{-n})^{-log_m rho(c)}``, so

    alpha = k - log_m rho(c)            (Rioul 1992 for m = 2; Hassan et al. 2002 for m = 3).

The m-ary B-spline of degree ``d``, ``a = q_m^{d+1}/m^d`` (the (d+1)-fold convolution of the box
function ``chi_[0,1)``, whose mask is ``q_m``), has ``N = d + 1``, ``c = 1``, ``rho = 1`` and therefore
``alpha = d`` exactly: it is ``C^{d-1}`` and not ``C^d`` — the same as the binary B-spline of degree d
(the limit is the same piecewise polynomial; only the knot refinement differs).

C^j verdicts: ``C^j`` iff ``alpha > j`` (``j < N``); ``alpha <= j`` is proven by a product of transition
matrices with ``rho(Pi)^(1/L) >= m^(k-j)``, ``alpha > j`` by the JSR upper bound or the m-ary Dyn–Levin
norm test. A mask failing an m-ary sum rule is the certified verdict "not convergent", naming the root of
unity.

Examples
--------
>>> from analysis.algebra.symbol import LaurentSymbol
>>> h = holder_exponent_mary(LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)"), 3)   # ternary cubic B-spline
>>> h.value, h.status
(3, 'certified')
>>> smoothness_mary(LaurentSymbol.from_mask([1, 2]), 3, 0).witness["reason"]
'not convergent: a(exp(2*pi*i/3)) = sqrt(3)*I != 0; a(exp(4*pi*i/3)) = -sqrt(3)*I != 0'

References
----------
O. Rioul, *Simple regularity criteria for subdivision schemes*, SIAM J. Math. Anal. 23 (1992).
I. Daubechies, J. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23 (1992).
M. F. Hassan, I. P. Ivrissimitzis, N. A. Dodgson, M. A. Sabin, Comput. Aided Geom. Design 19 (2002) 1-18.
"""

from __future__ import annotations

from typing import Sequence

import mpmath
import sympy as sp

from ..algebra.mary import check_arity, convergence_failure_mary, factor_out_mary, smoothing_factor_mary
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..stationary.mary import difference_norm_mary, transition_matrices_mary
from .convergence import NotConvergent
from ..algebra.reader import as_expr

iv = mpmath.iv

__all__ = ["NotConvergentMary", "difference_mask_mary", "holder_exponent_mary", "smoothness_mary",
           "power_exponent", "ck_range_mary", "alpha_curve_mary"]


class NotConvergentMary(NotConvergent):
    """An m-ary sum rule fails (certified "not convergent"); ``reason`` names the root of unity."""

    def __init__(self, reason: str, m: int):
        self.reason, self.hint, self.arity = reason, None, m
        AnalysisError.__init__(self, f"the scheme does not satisfy the {m}-ary sum rules a(1) = {m}, "
                                     f"a(eps) = 0 for eps^{m} = 1, eps != 1 ({reason}): it does not converge")

    def result(self) -> Result:
        return Result(value=False, status=CERTIFIED,
                      witness={"convergent": False, "reason": f"not convergent: {self.reason}"},
                      provenance={"method": f"exact {self.arity}-ary sum rules (necessary for convergence)",
                                  "arity": self.arity})


def difference_mask_mary(a: LaurentSymbol, m: int) -> tuple[int, LaurentSymbol]:
    """``(k, c)``: ``k = N - 1`` and ``c = m^k a / q_m^(k+1)``; :class:`NotConvergentMary` if a sum rule fails.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> difference_mask_mary(LaurentSymbol.from_expr("(1+z+z**2)**2/(3*z**2)"), 3)
    (1, LaurentSymbol([1], start=-2, domain=QQ))
    """
    m = check_arity(m)
    a.require_numeric("a Hölder exponent")
    why = convergence_failure_mary(a, m)
    if why is not None:
        raise NotConvergentMary(why, m)
    N = smoothing_factor_mary(a, m, exceptional=False).value
    return N - 1, factor_out_mary(a, N, m) / m


def power_exponent(x, m: int) -> int | None:
    """``e`` if ``x == m^e`` exactly (``e`` an integer), else None.

    >>> power_exponent(sp.Rational(1, 9), 3), power_exponent(2, 3)
    (-2, None)
    """
    x = sp.Rational(x)
    if x <= 0:
        return None
    p, q = int(x.p), int(x.q)
    if q == 1:
        e = 0
        while p % m == 0:
            p, e = p // m, e + 1
        return e if p == 1 else None
    if p == 1:
        e = 0
        while q % m == 0:
            q, e = q // m, e + 1
        return -e if q == 1 else None
    return None


def _logm_interval(lo: sp.Rational, hi: sp.Rational, m: int, prec: int = 90):
    from ..algebra.algebraic import _q

    old = iv.prec
    iv.prec = prec
    try:
        l1 = iv.log(iv.mpf(int(lo.p)) / int(lo.q)) / iv.log(iv.mpf(m))
        l2 = iv.log(iv.mpf(int(hi.p)) / int(hi.q)) / iv.log(iv.mpf(m))
        return _q(l1.a), _q(l2.b)
    finally:
        iv.prec = old


def holder_exponent_mary(a: LaurentSymbol, m: int, *, budget: int = 20_000, max_length: int = 12,
                         rel_gap: float = 1e-8) -> Result:
    """A certified enclosure of ``alpha = k - log_m JSR(T_0, ..., T_{m-1})`` (module docstring).

    ``budget``: work units of :func:`analysis.jsr.jsr_bounds` (counted, never timed; about a
    millisecond each on the reference machine).

    ``value`` is exact when the JSR is proven equal to ``m^e`` (B-splines); else ``lower``/``upper`` are
    rationals (outward rounding). Raises :class:`NotConvergentMary` when a sum rule fails.
    """
    from ..jsr import jsr_bounds

    if not isinstance(a, LaurentSymbol):
        raise AnalysisError(f"an m-ary Hölder exponent needs an exact symbol, not {type(a).__name__}")
    m = check_arity(m)
    k, c = difference_mask_mary(a, m)
    T = transition_matrices_mary(c, m)
    r = jsr_bounds(list(T), budget=budget, max_length=max_length, rel_gap=rel_gap)
    lo, hi = r.lower, r.upper
    if lo is None or lo <= 0:
        raise AnalysisError("the joint spectral radius lower bound is 0; the Hölder formula does not apply")
    value = None
    if r.value is not None:
        e = power_exponent(r.value, m)
        if e is not None:
            value = sp.Integer(k - e)
    if hi is not None:
        l_lo, l_hi = _logm_interval(sp.Rational(lo), sp.Rational(hi), m)
        a_lo, a_hi = k - l_hi, k - l_lo
    else:
        a_lo, a_hi = None, k - _logm_interval(sp.Rational(lo), sp.Rational(lo), m)[0]
    witness = {"k": k, "c": c, "arity": m, "jsr": r, "product": r.witness.get("product"),
               "rho_product": r.witness.get("rho_product")}
    return Result(value=value, lower=a_lo if value is None else value, upper=a_hi if value is None else value,
                  status=r.status, witness=witness,
                  provenance={"method": f"alpha = k - log_{m} JSR(T_0..T_{m - 1}) of c = {m}^k a/q_{m}^(k+1)",
                              "arity": m, "jsr_method": r.provenance.get("method"),
                              "work": r.provenance.get("work"), "timing": r.provenance.get("timing")})


def _spectral_radius_at_least(P: sp.Matrix, theta: sp.Rational) -> bool | None:
    from .holder import _modulus_at_least

    x = sp.Symbol("x")
    cp = P.charpoly(x)
    coeffs = [sp.Rational(c) for c in reversed(cp.all_coeffs())]
    return _modulus_at_least(coeffs, theta)


def smoothness_mary(a: LaurentSymbol, m: int, j: int, *, budget: int = 20_000, max_length: int = 12,
                    max_L: int = 4, max_word: int = 3) -> Result:
    """Is the m-ary scheme ``C^j``?  ``value`` True / False (certified) or None (inconclusive, with reason).

    Order: sum rules (not convergent, naming the root of unity), factor count, the m-ary Dyn–Levin norm
    test for ``L <= max_L`` (C^j), exact spectral radii of products of length ``<= max_word``
    (``rho(Pi) >= m^{(k-j)L}``: not C^j), then the JSR bounds.
    """
    from itertools import product as words

    m = check_arity(m)
    if not isinstance(j, int) or j < 0:
        raise AnalysisError("j must be a non-negative integer")
    try:
        k, c = difference_mask_mary(a, m)
    except NotConvergentMary as exc:
        return exc.result()
    prov = {"arity": m}
    if j > k:
        return Result(value=False, status=CERTIFIED,
                      witness={"reason": f"only {k + 1} factors q_{m}: alpha <= {k + 1} and C^{j} needs "
                                         f"q_{m}^{j + 1} | a and alpha > {j}", "k": k},
                      provenance={**prov, "method": "factor count"})
    exact = a.domain.is_QQ or a.domain.is_ZZ
    if exact:
        for L in range(1, max_L + 1):
            r = difference_norm_mary(a, j + 1, m, L)
            if r.witness["contractive"]:
                return Result(value=True, status=CERTIFIED,
                              witness={"reason": f"||(1/{m} S_a{j + 1})^{L}||_inf = {sp.sstr(r.value)} < 1 "
                                                 "(Dyn-Levin)", "k": k, "norm": r},
                              provenance={**prov, "method": "exact m-ary Dyn-Levin norm test"})
        T = transition_matrices_mary(c, m)
        theta = sp.Integer(m) ** (k - j)
        for L in range(1, max_word + 1):
            for w in words(range(m), repeat=L):
                if L > 1 and min(w[i:] + w[:i] for i in range(L)) != w:
                    continue
                P = sp.eye(T[0].shape[0])
                for i in w:
                    P = P * T[i]
                if _spectral_radius_at_least(P, theta ** L):
                    return Result(value=False, status=CERTIFIED,
                                  witness={"reason": f"the product T_{''.join(map(str, w))} has an eigenvalue of "
                                                     f"modulus >= {m}^{(k - j) * L}: alpha <= {j}",
                                           "k": k, "product": w},
                                  provenance={**prov, "method": "exact spectral radius of a short product"})
    h = holder_exponent_mary(a, m, budget=budget, max_length=max_length)
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


# --------------------------------------------------------------------------------------------
# C^j parameter ranges of one-parameter m-ary families
# --------------------------------------------------------------------------------------------

def _violation_set(a: LaurentSymbol, m: int, j: int, p: sp.Symbol, k: int) -> tuple[sp.Set, list]:
    """``{p : some T_eps(c(p)) has a real eigenvalue r(p) with |r(p)| >= m^(k-j)}`` from the linear
    factors (in lambda) of the characteristic polynomials; nonlinear factors are listed, not used."""
    lam = sp.Symbol("lambda")
    c = factor_out_mary(a, k + 1, m) / m
    theta = sp.Integer(m) ** (k - j)
    V: sp.Set = sp.EmptySet
    unused = []
    for eps, T in enumerate(transition_matrices_mary(c, m)):
        cp = sp.factor_list(sp.expand(T.charpoly(lam).as_expr()), lam)
        for f, _mult in cp[1]:
            poly = sp.Poly(f, lam)
            if poly.degree() != 1:
                if poly.degree() > 1:
                    unused.append((eps, f))
                continue
            A, B = poly.all_coeffs()
            r = sp.cancel(-B / A)
            if r.free_symbols - {p}:
                unused.append((eps, f))
                continue
            for ineq in (r >= theta, r <= -theta):
                V = V.union(sp.solveset(ineq, p, domain=sp.S.Reals))
    return V, unused


def _norm_below_at(a, m, j, p, x, L_max):
    """The smallest L <= L_max with ``||(1/m S_{a_{j+1}})^L|| < 1`` exactly at the algebraic point x."""
    from ..algebra.algebraic import RealAlgebraic
    from ..stationary.normset import _norm_below_at_point, _residue_polys

    X = RealAlgebraic.from_expr(x)
    for L in range(1, min(L_max, 6) + 1):
        _, by_res = _residue_polys(a, j + 1, L, "paper", p, m)
        if _norm_below_at_point(by_res, X, 1):
            return L
    return None


def _cover_undecided(a, m, j, p, undecided, S, L_max, points_only=False, strip_budget: int = 30_000):
    """Shrink the undecided part with the exact parametric norm tests on each of its intervals, and the
    strips they leave next to ends of eigenvalue type with the parametric invariant polytope
    (:func:`analysis.regularity.strips.close_strip`, ``strip_budget`` work units per interval)."""
    from .interior import ck_interior

    parts = undecided.args if isinstance(undecided, sp.Union) else (undecided,)
    covered = []
    for part in parts:
        if isinstance(part, sp.FiniteSet):
            for x in part:
                L = _norm_below_at(a, m, j, p, x, L_max)
                if L is not None:
                    S = S.union(sp.FiniteSet(x))
                    covered.append({"point": sp.sstr(x), "L": L})
                    continue
                v = smoothness_mary(a.subs({p: x}), m, j, budget=10_000)   # certified verdict there
                if v.value is True and v.status == CERTIFIED:
                    S = S.union(sp.FiniteSet(x))
                    covered.append({"point": sp.sstr(x), "verdict": v.witness.get("reason")})
            continue
        if points_only or not isinstance(part, sp.Interval) or not (part.start.is_finite and part.end.is_finite):
            continue
        r = ck_interior(a, j, part.start, part.end, p, arity=m, L_max=L_max,
                        budget=30_000 + max(0, strip_budget - 30_000), strip_budget=strip_budget)
        C = r.value["certified"].to_sympy()
        polytopes = [{"from": x["from"], "to": x["to"], "kind": x["kind"], **x["polytope"]}
                     for x in r.witness["pieces"] if "polytope" in x]
        if C != sp.EmptySet:
            S = S.union(C)
            covered.append({"interval": str(part), "certified": str(r.value["certified"]),
                            "pieces": len(r.witness["pieces"]), **({"polytope": polytopes} if polytopes else {})})
        if r.provenance.get("strips not closed by the invariant polytope"):
            covered.append({"interval": str(part), "strips not closed by the invariant polytope":
                            r.provenance["strips not closed by the invariant polytope"]})
    return S, covered


def ck_range_mary(a: LaurentSymbol, m: int, j: int, param=None, *, Ls: Sequence = (1, 2, 3),
                  within=(-sp.oo, sp.oo), interior_L_max: int = 8, strip_budget: int = 30_000) -> Result:
    """Where is the one-parameter m-ary family ``C^j``?  Both sides certified where possible.

    * **C^j** (sufficient): the union over ``L in Ls`` of the exact sets where the m-ary Dyn–Levin test
      ``||(1/m S_{a_{j+1}})^L||_inf < 1`` holds (:func:`analysis.stationary.normset.norm_solution_set`).
    * **not C^j** (necessary): the exact set where a single transition matrix ``T_eps(c(p))``,
      ``c = m^k a/q_m^(k+1)``, has a real eigenvalue of modulus ``>= m^(k-j)`` (then ``alpha <= j``).

    ``value`` is the C^j set (a sympy set); ``witness["not_Cj"]`` the proven complement part,
    ``witness["undecided"]`` what neither covers inside ``within`` (empty: the range is exact, certified
    on both sides; otherwise points there can be decided one by one with :func:`smoothness_mary`).
    What the norm sets leave undecided is first covered, where possible, by the exact parametric
    norm tests with L <= ``interior_L_max`` (:func:`analysis.regularity.interior.ck_interior`;
    ``witness["interior_tests"]``; 0 turns this off), and the strips they leave next to ends of
    eigenvalue type by the parametric invariant polytope (:func:`analysis.regularity.strips.close_strip`,
    ``strip_budget`` work units per interval; ``interior_tests[...]["polytope"]``, or why a strip was not closed).
    Uses the generic ``k`` (``N - 1`` identically in the parameter).
    """
    from ..stationary.normset import _parameter, norm_solution_set

    m = check_arity(m)
    p = _parameter(a, param)
    k = smoothing_factor_mary(a, m, exceptional=False).value - 1
    if j > k:
        raise AnalysisError(f"the family has only {k + 1} factors q_{m} identically: C^{j} needs {j + 1}")
    lo, hi = (as_expr(w) for w in within)
    box = sp.Interval(lo, hi, left_open=True, right_open=True)
    S: sp.Set = sp.EmptySet
    per_L = {}
    for L in Ls:
        r = norm_solution_set(a, j + 1, L, p, within=(lo, hi), arity=m)
        per_L[L] = str(r.value)
        S = S.union(r.value.to_sympy())
    V, unused = _violation_set(a, m, j, p, k)
    V = V.intersect(box)
    undecided = box - S.union(V)
    covered = []
    if interior_L_max and undecided != sp.EmptySet:
        S, covered = _cover_undecided(a, m, j, p, undecided, S, interior_L_max, strip_budget=strip_budget)
        undecided = box - S.union(V)
        if undecided != sp.EmptySet:     # isolated points left (e.g. closed ends of the intervals)
            S, more = _cover_undecided(a, m, j, p, undecided, S, interior_L_max, points_only=True)
            covered += more
            undecided = box - S.union(V)
    exact = undecided.is_empty is True or undecided == sp.EmptySet
    return Result(value=S, status=CERTIFIED if exact else INCONCLUSIVE,
                  witness={"parameter": p.name, "j": j, "k": k, "arity": m, "not_Cj": V, "undecided": undecided,
                           "norm_sets": per_L, "nonlinear_factors": unused,
                           "exact": exact, "interior_tests": covered},
                  provenance={"method": "m-ary Dyn-Levin norm sets (C^j) and exact real eigenvalues of the "
                                        "transition matrices (not C^j)", "arity": m})


def alpha_curve_mary(a: LaurentSymbol, m: int, param=None, *, within=(-1, 1), samples: int = 24,
                     budget: int = 10_000) -> Result:
    """Certified enclosures of alpha(p) of a one-parameter m-ary family at ``samples + 1`` equally
    spaced rational points of ``within`` (ends included), as
    :func:`analysis.regularity.ranges.alpha_curve` for m = 2 (for a figure and the smoothness profile).
    A point where the exponent cannot be enclosed (e.g. not convergent) is an inconclusive row with a note.

    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> t = sp.Symbol("t")
    >>> fam = LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)") * (1 - t) + LaurentSymbol.from_expr(
    ...     "(1+z+z**2)**3/(9*z**3)") * t                           # cubic to quadratic ternary B-spline
    >>> [(r["p"], r["lower"]) for r in alpha_curve_mary(fam, 3, within=(0, 1), samples=1).value]
    [(0, 3), (1, 2)]
    """
    from ..stationary.normset import _parameter

    m = check_arity(m)
    p = _parameter(a, param)
    lo, hi = (sp.Rational(sp.nsimplify(as_expr(w))) for w in within)
    rows = []
    for i in range(samples + 1):
        q = lo + (hi - lo) * sp.Rational(i, samples)
        try:
            h = holder_exponent_mary(a.subs({p: q}), m, budget=budget)
            rows.append({"p": q, "lower": h.lower, "upper": h.upper, "status": h.status})
        except AnalysisError as exc:
            rows.append({"p": q, "lower": None, "upper": None, "status": INCONCLUSIVE, "note": str(exc)})
    status = CERTIFIED if all(r["status"] == CERTIFIED for r in rows) else INCONCLUSIVE
    return Result(value=rows, status=status, witness={"parameter": p.name, "arity": m},
                  provenance={"method": f"holder_exponent_mary (arity {m}) at rational sample points", "arity": m})
