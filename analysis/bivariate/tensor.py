"""Tensor-product masks: an exact reduction of a bivariate scheme with ``M = m I`` to two univariate ones.

A mask ``a`` on ``Z^2`` with dilation ``M = m I`` is a **tensor product** when its coefficient grid
``A(t) = (a(i, j))_{i, j}`` (rows ``i``: the exponent of ``z1``; columns ``j``: that of ``z2``) has rank 1 over
``Q(t)``, ``t`` the free parameters: every ``2 x 2`` minor ``a(i, j) a(i', j') - a(i, j') a(i', j)`` vanishes
identically as a polynomial in ``t``. With the row sums ``r_i = sum_j a(i, j)``, the column sums
``s_j = sum_i a(i, j)`` and the total ``S = sum a != 0``, rank 1 is equivalent to the identity ``S A = r s^T``
(if ``A = u v^T`` then ``r = u sum v``, ``s = v sum u``, ``S = sum u sum v``; conversely ``r s^T / S`` has rank 1),
which :func:`tensor_factors` checks exactly, entry by entry, over ``Q[t]`` (sympy ``Poly``): ``n1 n2`` products
instead of the ``O(n1^2 n2^2)`` minors; when it fails, a minor that is not identically zero is the witness. The
factors are normalised to the m-ary sum ``m``:

    b_i = m r_i / S,    c_j = m s_j / S,    a(z1, z2) = b(z1) c(z2)   when  S = m^2 = |det M|.

The reduction is made only when ``S`` is the constant ``m^2`` (a polynomial of degree 0 in ``t``): then ``b`` and
``c`` are polynomials in ``t`` with rational coefficients, sum to ``m`` **for every** ``t`` (so on the whole
parameter interval, not only generically), and ``S A = r s^T`` is ``A = b c^T``, checked exactly coefficient
by coefficient. Otherwise (a minor not identically zero, a dilation other than ``m I`` with ``m >= 2``, a total
depending on ``t`` or other than ``m^2``, coefficients that are not polynomials over ``Q``) nothing is reduced, and
the reason is returned ("not reduced: ..."). What that certifies is the exact fact named in the reason, i.e. that this
reduction does not apply — **not** that no parameter value gives a tensor product: a minor that is a nonzero
polynomial in ``t`` leaves rank 1 possible at its zeros (where every minor may vanish), and a total depending on
``t`` says nothing about the rank at all. Only a minor that is a nonzero constant shows rank ``>= 2`` for every
parameter value.

Theorem
-------
Let ``M = m I`` with an integer ``m >= 2`` and ``a(z1, z2) = b(z1) c(z2)`` with univariate m-ary masks ``b, c``,
``sum b = sum c = m``. (``m >= 2`` is needed: with ``M = -m I``, ``(S_a f)(alpha) = sum_beta a(alpha + m beta) f(beta)``
is ``S_{b (x) c}`` applied to ``f(-.)``, and its factors ``f -> S_b f(-.)`` are not the m-ary schemes ``S_b``; two
of its steps have the symbol ``a(z) a(z^-m)``.)

(i) ``S_a = S_b (x) S_c``: ``(S_a f)(alpha) = sum_beta b(alpha_1 - m beta_1) c(alpha_2 - m beta_2) f(beta)``, and
the refinable distributions satisfy ``phi_a = phi_b (x) phi_c`` (Fourier transforms: ``M^{-k} = m^{-k} I``, so
``prod_k a(e^{-i M^{-k} xi}) / m^2 = prod_k b(e^{-i xi_1 / m^k}) / m * prod_k c(e^{-i xi_2 / m^k}) / m``).

(ii) ``S_a`` is ``C^l``-convergent if and only if ``S_b`` and ``S_c`` are.

(iii) For every non-integer ``alpha > 0`` the Hölder space ``C^alpha(R^2)`` contains ``phi_a`` if and only if
``C^alpha(R)`` contains ``phi_b`` and ``phi_c``; hence the Hölder exponent of ``phi_a`` is
``min(alpha_b, alpha_c)`` (and ``phi_a`` is ``C^l`` iff ``phi_b`` and ``phi_c`` are).

So the bivariate ``C^l`` set of a one-parameter tensor family is **exactly** the intersection of the two
univariate ``C^l`` sets (the point verdicts of :mod:`analysis.bivariate.holder` and of
:mod:`analysis.regularity.holder` both decide ``C^l`` convergence: ``JSR(T|V_{l+1}) < rho(M)^{-l}``, with
``rho(M) = m``), certified where both univariate sets are certified (:func:`tensor_ck_set`).

*Proof.* (ii) Write ``b_n = S_b^n delta``, ``c_n = S_c^n delta``; ``S_a^n`` has the mask ``b_n (x) c_n``. ``S_a`` is
``C^l``-convergent when for ``|beta| <= l`` the divided differences ``m^{n|beta|} Delta^beta S_a^n f`` converge
uniformly to ``d^beta F(m^{-n} .)``, ``F = sum_gamma f(gamma) phi_a(. - gamma)``, uniformly for ``||f||_inf <= 1``
(the form the JSR criteria characterise, with a geometric rate); by locality this is the convergence to 0, in the
level-``n`` coset norm ``N_n(e) = sup_k sum_j
|e(k - m^n j)|``, of ``u_n - U_n`` with ``u_n = m^{n|beta|} Delta^beta S^n delta`` and ``U_n`` the samples
``d^beta phi(m^{-n} .)`` (take ``f = +-1`` where the sum is attained). For the tensor product ``u_n = u'_n (x)
u''_n`` and ``U_n = U'_n (x) U''_n`` (``Delta^beta = Delta_1^{beta_1} Delta_2^{beta_2}``, ``d^beta phi_a =
phi_b^{(beta_1)} (x) phi_c^{(beta_2)}``), and ``N_n`` is multiplicative on tensors, so
``N_n(u_n - U_n) <= N_n(u'_n - U'_n) N_n(u''_n) + N_n(U'_n) N_n(u''_n - U''_n) -> 0`` when both factors are
``C^l``-convergent (``N_n(U'_n)`` is bounded by the support of ``phi_b`` times ``max |phi_b^{(beta_1)}|``).
Conversely let ``S_a`` be ``C^l``-convergent, ``g`` bounded, ``f = g (x) delta``: ``S_a^n f = (S_b^n g) (x) c_n``
and ``F = G (x) phi_c``, ``G = sum_k g(k) phi_b(. - k)``. Since ``sum c = m``, ``sum_k c_n(k) = m^n``; averaging
``X_n = m^{nj} Delta_1^j S_a^n f`` over its second index with weight ``m^{-n}`` gives exactly
``m^{nj} Delta^j S_b^n g``, and averaging ``d_1^j F(m^{-n} .)`` gives ``G^{(j)}(m^{-n} .) r_n`` with the Riemann
sum ``r_n = m^{-n} sum_k phi_c(m^{-n} k) -> integral phi_c = 1`` (``phi_a``, the limit from ``delta``, is
continuous; with ``psi`` as in (iii), ``phi_c(y) = integral phi_a(x, y) psi(x) dx`` is continuous with compact
support and ``G(x) = integral F(x, y) psi(y) dy`` is ``C^l``). Both averages run over ``O(m^n)`` indices (the
supports of ``c_n`` and of ``phi_c(m^{-n} .)``), and ``||g||_inf <= 1`` gives ``||f||_inf <= 1``, so ``|m^{nj} Delta^j S_b^n g - G^{(j)}(m^{-n} .)| <= C sup |X_n - d_1^j F(m^{-n} .)| + |r_n - 1|
max |G^{(j)}| -> 0``: ``S_b`` is ``C^l``-convergent; so is ``S_c``.
(iii) If ``phi_b, phi_c`` are in ``C^alpha``, ``alpha = n + s``, each ``d^beta phi_a``, ``|beta| <= n``, is a
product of bounded ``s``-Hölder functions of separate variables, hence ``s``-Hölder. Conversely take
``psi`` smooth with compact support and ``psi = 1`` near the supports of ``phi_b`` and ``phi_c``:
``<phi_c, psi> = hat phi_c(0) = 1``, so ``phi_b(x) = integral phi_a(x, y) psi(y) dy``, and derivatives and Hölder quotients in ``x`` pass under
the integral. (This needs no point ``y0`` with ``phi_c(y0) != 0``, and holds when ``phi_c`` is only a
distribution.) QED

The fixed-parameter Hölder exponent keeps its transition-operator route (:mod:`analysis.bivariate.holder`);
this module is used for the ``C^l`` sets of one-parameter families (``subdiv surface --C L --within``).

Examples
--------
>>> from analysis.bivariate.mask import BivariateMask
>>> r = tensor_factors(BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2)"))     # bilinear
>>> r.status, str(r.value.b), r.value.same
('certified', '1/2*z^(-1) + 1 + 1/2*z', True)
>>> q = tensor_factors(BivariateMask.from_symbol("(1+z1)*(1+z2)/2", "quincunx"))
>>> q.value, q.witness["reason"]
(None, 'not reduced: the dilation [[1, 1], [1, -1]] is not m I with m >= 2')

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002) 73-144 (Sect. 4.1:
tensor-product schemes, C^l convergence and divided differences).
A. S. Cavaretta, W. Dahmen, C. A. Micchelli, *Stationary subdivision*, Mem. AMS 453 (1991).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..algebra.algebraic import IntervalSet, RealAlgebraic, rational_between
from ..algebra.reader import as_expr
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .mask import BivariateMask

__all__ = ["TensorFactors", "tensor_factors", "tensor_ck_set", "univariate_ck_set"]


@dataclass(frozen=True)
class TensorFactors:
    """``a(z1, z2) = b(z1) c(z2)`` exactly, ``M = m I``, ``sum b = sum c = m`` for every parameter value."""

    m: int
    b: LaurentSymbol
    c: LaurentSymbol
    grid: tuple          # the size of the coefficient grid (rows: z1, columns: z2)

    @property
    def same(self) -> bool:
        return self.b == self.c


def _poly(v, gens):
    try:
        return sp.Poly(v, *gens, domain=sp.QQ)
    except (sp.PolynomialError, sp.polys.polyerrors.CoercionFailed):
        return None


def _not_tensor(reason: str, **extra) -> Result:
    """Not reduced: certified is the exact fact ``reason`` names, not "no parameter value is a tensor product"."""
    return Result(value=None, status=CERTIFIED, witness={"reason": f"not reduced: {reason}", **extra},
                  provenance={"method": "exact 2x2 minors of the coefficient grid over Q[t] (sympy Poly)",
                              "certified": "that the exact reduction does not apply, for the reason given"})


def tensor_factors(a: BivariateMask) -> Result:
    """Is ``a`` a tensor product ``b(z1) c(z2)`` with ``M = m I``?  (module docstring)

    ``value``: a :class:`TensorFactors` (certified: the exact identity ``S A = r s^T`` over ``Q[t]``), or ``None``
    with ``witness["reason"]`` = ``"not reduced: ..."``. Certified then is only the exact fact the reason names
    (the dilation, a total depending on ``t``, a minor not identically zero, ...), i.e. that the reduction does not
    apply on the whole parameter interval; the mask may still have rank 1 at exceptional values of ``t`` (the
    common zeros of the minors) or, when only the total depends on ``t``, at every value. A minor that is a
    nonzero constant shows that no parameter value gives a tensor product.
    """
    (m11, m12), (m21, m22) = a.dilation.matrix
    if not (m12 == m21 == 0 and m11 == m22 and m11 >= 2):
        return _not_tensor(f"the dilation {[list(r) for r in a.dilation.matrix]} is not m I with m >= 2"
                           + (" (M = -m I is not reduced: S_a f = S_{b (x) c} f(-.), so the factors are not m-ary "
                              "schemes S_b, S_c)" if m12 == m21 == 0 and m11 == m22 else ""))
    m = m11
    gens = a.params or (sp.Dummy("t"),)
    (i0, j0), (i1, j1) = a.support_box
    A = {}
    for ij, v in a:
        P = _poly(v, gens)
        if P is None:
            return _not_tensor(f"the coefficient {ij[0]},{ij[1]} is not a polynomial with rational coefficients "
                               "in the parameters")
        A[ij] = P
    zero = _poly(sp.Integer(0), gens)
    get = lambda i, j: A.get((i, j), zero)
    rows, cols = range(i0, i1 + 1), range(j0, j1 + 1)
    S = sum(A.values(), zero)
    if not S.is_ground or S.is_zero:
        return _not_tensor(f"the mask sums to {sp.sstr(S.as_expr())}, not a nonzero constant for every parameter "
                           "value: the factors cannot be normalised on the whole interval (the rank of the grid "
                           "is not examined)")
    r = [sum((get(i, j) for j in cols), zero) for i in rows]
    s = [sum((get(i, j) for i in rows), zero) for j in cols]
    # rank 1 over Q(t) with S != 0  <=>  S A = r s^T identically (then every 2x2 minor vanishes)
    for i, ri in zip(rows, r):
        for j, sj in zip(cols, s):
            if not (get(i, j) * S - ri * sj).is_zero:
                return _not_tensor(*_nonzero_minor(get, rows, cols, ", ".join(str(g) for g in gens)))
    if S.as_expr() != m * m:
        return _not_tensor(f"the mask sums to {sp.sstr(S.as_expr())}, not |det M| = {m * m}")
    # b = m r / S, c = m s / S with S = m^2, i.e. b = r / m, c = s / m: A = b c^T, sum b = sum c = m
    b = LaurentSymbol.from_mask([x.as_expr() / m for x in r], start=i0)
    c = LaurentSymbol.from_mask([x.as_expr() / m for x in s], start=j0)
    return Result(value=TensorFactors(m, b, c, (len(rows), len(cols))), status=CERTIFIED,
                  witness={"grid": (len(rows), len(cols)), "sum_b": m, "sum_c": m},
                  provenance={"method": "exact identity S A = r s^T over Q[t] (rank 1; r, s the row and column sums, "
                                        "S = m^2 the constant total); b = m r/S, c = m s/S"})


def _nonzero_minor(get, rows, cols, names: str) -> tuple:
    """The first ``2 x 2`` minor of the grid that is not identically zero (it exists: the rank over ``Q(t)`` is at
    least 2), and what it shows: rank ``>= 2`` for every parameter value when it is a nonzero constant, else only
    away from its zeros."""
    for i in rows:
        for i2 in (x for x in rows if x > i):
            for j in cols:
                for j2 in (y for y in cols if y > j):
                    d = get(i, j) * get(i2, j2) - get(i, j2) * get(i2, j)
                    if not d.is_zero:
                        what = (f"the 2x2 minor of rows z1^{i}, z1^{i2} and columns z2^{j}, z2^{j2} of the "
                                f"coefficient grid is {sp.sstr(d.as_expr())}")
                        if d.is_ground:
                            return (f"{what}, not zero: rank >= 2 (not a tensor product)",)
                        return (f"{what}, not identically zero: rank >= 2 over Q({names}), so not a tensor product on "
                                "the whole interval (rank 1 is still possible where every minor vanishes)",)
    raise AssertionError("rank >= 2 without a nonzero minor")          # pragma: no cover


# --------------------------------------------------------------------------------------------
# the univariate C^l sets, as exact pieces of the interval
# --------------------------------------------------------------------------------------------

C, NOT, UNDECIDED, SAMPLED = "C", "not", "undecided", "sampled"


@dataclass
class FactorSet:
    """One factor's certified ``C^l`` set on ``within`` (exact parts), with the univariate result."""

    symbol: LaurentSymbol
    cl: list            # parts (lo, hi, lo_closed, hi_closed) of RealAlgebraic: certified C^l
    not_cl: list        # certified not C^l
    undecided: list     # said undecided by the univariate machinery
    result: Result | None
    route: str
    ends: list          # (exact end, how) of the binary route
    sets: dict | None = None    # the factor's C^l, not C^l, undecided and sampled sets on within


def _ra(x) -> RealAlgebraic:
    return x if isinstance(x, RealAlgebraic) else RealAlgebraic.from_expr(as_expr(x))


def _point(x):
    x = _ra(x)
    return (x, x, True, True)


def _sympy_parts(S) -> list:
    """The parts of a sympy set (``Interval``, ``FiniteSet``, ``Union``) with exact ends."""
    if S == sp.EmptySet or S.is_empty is True:
        return []
    if isinstance(S, sp.Union):
        return [p for x in S.args for p in _sympy_parts(x)]
    if isinstance(S, sp.FiniteSet):
        return [_point(y) for y in S]
    if isinstance(S, sp.Interval):
        return [(_ra(S.start), _ra(S.end), not S.left_open, not S.right_open)]
    raise AnalysisError(f"cannot read the set {sp.sstr(S)} as intervals with exact ends")   # pragma: no cover


def univariate_ck_set(b: LaurentSymbol, l: int, m: int, within, *, grid: int = 8, budget: int = 20_000,
                      tol: float = 1e-8, strip_budget: int = 30_000) -> FactorSet:
    """The certified ``C^l`` set of the one-parameter univariate m-ary family ``b`` on ``within`` by the route of
    ``subdiv range``: binary, :func:`analysis.regularity.ranges.ck_parameter_set` (certified grid verdicts, exact
    s.m.p. crossings, the interior by exact parametric norm tests and invariant polytopes); ``m > 2``,
    :func:`analysis.regularity.ranges.ck_range` (exact norm and eigenvalue sets) and the verdicts at the two ends
    of ``within``; when the family has fewer than ``l + 1`` factors ``q_m`` identically, :func:`_too_few_factors`
    instead. A factor without a parameter: its verdict (:func:`analysis.regularity.holder.smoothness`) holds on the
    whole interval."""
    from ..regularity.holder import smoothness
    from ..regularity.ranges import ck_parameter_set, ck_range

    lo, hi = within
    whole = (_ra(lo), _ra(hi), True, True)
    if not b.params:
        v = smoothness(b, l, arity=m, budget=budget)
        parts = {True: ([whole], []), False: ([], [whole]), None: ([], [])}[v.value]
        return FactorSet(b, parts[0], parts[1], [] if v.value is not None else [whole], v,
                         "the point verdict (no parameter)", [])
    if m == 2:
        r = ck_parameter_set(b, l, within=(lo, hi), grid=grid, tol=tol, budget=budget, interior_L_max=12,
                             strip_budget=strip_budget)
        cl = [_point(s["p"]) for s in r.witness["samples"] if s["C^j"]]
        not_cl = [_point(s["p"]) for s in r.witness["samples"] if s["C^j"] is False]
        und = [_point(s["p"]) for s in r.witness["samples"] if s["C^j"] is None]
        ends = []
        for bd in r.witness["boundaries"]:
            if bd.get("certified_C^j_at") is not None:
                cl.append(_point(bd["certified_C^j_at"]))
            if bd.get("certified_not_C^j_at") is not None:
                not_cl.append(_point(bd["certified_not_C^j_at"]))
            if "exact" in bd:
                ends.append((bd["exact"], bd["how"]))
        for run in r.value:
            it = run.get("interior") or {}
            if isinstance(it.get("certified"), IntervalSet):
                cl += list(it["certified"].parts)
        for st in r.witness.get("not_Cj", []):          # stretches proven not C^l on the whole of them
            if st["proven"]:
                not_cl.append((_ra(st["from"]), _ra(st["to"]), True, True))
        return FactorSet(b, cl, not_cl, und, r, "ck_parameter_set", ends)
    few = _too_few_factors(b, l, m, (lo, hi), budget)
    if few is not None:
        return few
    r = ck_range(b, l, arity=m, within=(lo, hi), strip_budget=strip_budget)
    cl, not_cl = _sympy_parts(r.value), _sympy_parts(r.witness["not_Cj"])
    und = _sympy_parts(r.witness["undecided"])
    for x in (lo, hi):                                   # ck_range works on the open interval
        v = smoothness(b.subs({b.params[0]: x}), l, arity=m, budget=budget).value
        (cl if v else not_cl if v is False else und).append(_point(x))
    return FactorSet(b, cl, not_cl, und, r, "ck_range", [])


def _too_few_factors(b: LaurentSymbol, l: int, m: int, within, budget: int) -> FactorSet | None:
    """The ``C^l`` set of an m-ary family with fewer than ``l + 1`` factors ``q_m = 1 + z + ... + z^(m-1)``
    identically in its parameter (``None`` when it has enough): certified **not** ``C^l`` on the whole of
    ``within`` except at the exceptional values where ``q_m`` divides ``b`` more often, each decided by its own
    point verdict.

    ``C^l`` needs ``q_m^(l+1) | b`` (the factor-count verdict of :func:`analysis.regularity.holder.smoothness`:
    with ``k + 1`` factors, ``alpha <= k + 1``, and ``C^l`` needs ``q_m^(l+1) | b`` and ``alpha > l``). Away from the
    exceptional values of :func:`analysis.algebra.factorization.smoothing_factor` (the common real zeros of the
    remainder of the next division, exact) ``b`` has exactly the generic number of factors."""
    from ..algebra.factorization import smoothing_factor
    from ..regularity.holder import smoothness

    f = smoothing_factor(b, arity=m)
    if f.value >= l + 1:
        return None
    L, H = _ra(within[0]), _ra(within[1])
    special = []
    for case in f.witness["exceptional"]:
        (x,) = case["condition"].values()
        x = _ra(x)
        if _cmp(L, x) <= 0 <= _cmp(H, x) and (case["k"] is None or case["k"] >= l + 1):
            special.append(x)
    special = sorted(special, key=functools.cmp_to_key(_cmp))
    cl, not_cl, und = [], [], []
    cuts = [L] + special + [H]
    for k, (x, y) in enumerate(zip(cuts, cuts[1:])):
        if _cmp(x, y) < 0:
            not_cl.append((x, y, k == 0, k == len(cuts) - 2))
    for x in special:
        try:
            v = smoothness(b.subs({b.params[0]: x.expr}), l, arity=m, budget=budget).value
        except AnalysisError:
            v = None
        (cl if v else not_cl if v is False else und).append(_point(x))
    reason = (f"only {f.value} factors q_{m} identically in {b.params[0].name} and C^{l} needs {l + 1} "
              f"(q_{m}^{l + 1} | b): not C^{l} on the whole interval"
              + (f" except at {b.params[0].name} = {', '.join(sp.sstr(x.expr) for x in special)}, where q_{m} "
                 "divides b more often (each decided by its own verdict)" if special else ""))
    res = Result(value=False, status=CERTIFIED if not und else INCONCLUSIVE,
                 witness={"reason": reason, "factors": f.value, "exceptional": special},
                 provenance={"method": "factor count (exact division by q_m; exceptional values exact)"})
    return FactorSet(b, cl, not_cl, und, res, "factor count", [])


# --------------------------------------------------------------------------------------------
# the intersection
# --------------------------------------------------------------------------------------------

def _cmp(u: RealAlgebraic, v: RealAlgebraic) -> int:
    return u.compare(v)


def _in(parts, piece) -> bool:
    kind, x, y = piece
    if kind == "point":
        for lo, hi, lc, hc in parts:
            a, b = _cmp(lo, x), _cmp(x, hi)
            if (a < 0 or (a == 0 and lc)) and (b < 0 or (b == 0 and hc)):
                return True
        return False
    q = RealAlgebraic.rational(rational_between(x, y))     # the pieces never straddle an end of a part
    return _in(parts, ("point", q, q))


def _pieces(ends) -> list:
    """The elementary pieces of ``[ends[0], ends[-1]]``: the points and the open gaps between them."""
    out = []
    for k, x in enumerate(ends):
        out.append(("point", x, x))
        if k + 1 < len(ends):
            out.append(("gap", x, ends[k + 1]))
    return out


def _classify(f: FactorSet, pieces) -> list:
    """Each piece for one factor: C (certified), not (certified), undecided, or sampled (between two certified
    counterexamples with nothing certified C^l between: the univariate route does not examine it)."""
    lab = []
    for p in pieces:
        lab.append(NOT if _in(f.not_cl, p) else C if _in(f.cl, p) else UNDECIDED if _in(f.undecided, p) else None)
    out = list(lab)
    for k, x in enumerate(lab):
        if x is None:
            left = next((lab[i] for i in range(k - 1, -1, -1) if lab[i] is not None), None)
            right = next((lab[i] for i in range(k + 1, len(lab)) if lab[i] is not None), None)
            out[k] = SAMPLED if left == right == NOT else UNDECIDED
    return out


def _combine(u: str, v: str) -> str:
    if NOT in (u, v):
        return NOT
    if u == v == C:
        return C
    return UNDECIDED if UNDECIDED in (u, v) else SAMPLED


def _as_set(pieces, labels, kind) -> IntervalSet:
    members = [("gap" if p[0] == "gap" else "point", (p[1], p[2]) if p[0] == "gap" else p[1], lab == kind)
               for p, lab in zip(pieces, labels)]
    return IntervalSet.from_members(members)


def _sets(pieces, labels) -> dict:
    return {k: _as_set(pieces, labels, lab) for k, lab in
            (("Cl", C), ("not_Cl", NOT), ("undecided", UNDECIDED), ("sampled", SAMPLED))}


def tensor_ck_set(general: BivariateMask, l: int, param=None, *, within=(0, 1), grid: int = 8,
                  budget: int = 20_000, tol: float = 1e-8, strip_budget: int = 30_000,
                  factors: TensorFactors | None = None) -> Result:
    """The ``C^l`` set of a one-parameter tensor-product family on ``within``: the intersection of the univariate
    ``C^l`` sets of its factors (module docstring, Theorem (ii)), exact ends where the univariate ones are exact.

    ``value``: ``{"Cl": IntervalSet (certified C^l), "not_Cl": IntervalSet (certified not C^l),
    "undecided": IntervalSet, "sampled": IntervalSet (between certified counterexamples, not examined)}``;
    status *certified* when nothing is undecided. ``witness``: the factors (``factors``, a
    :class:`TensorFactors`), each factor's :class:`FactorSet` (``b``, ``c``: its univariate result and its
    ``sets`` in the same form as ``value``). Budgets are those of the univariate route
    (work units per verdict and per strip, counted, never timed).
    """
    from .ranges import single_parameter

    p = single_parameter(general, param)
    lo, hi = (sp.Rational(as_expr(w)) for w in within)
    if not lo < hi:
        raise AnalysisError("within needs low < high")
    if factors is None:
        t = tensor_factors(general)
        if t.value is None:
            raise AnalysisError(f"the tensor-product route does not apply ({t.witness['reason']})")
        factors = t.value
    fb = univariate_ck_set(factors.b, l, factors.m, (lo, hi), grid=grid, budget=budget, tol=tol,
                           strip_budget=strip_budget)
    fc = fb if factors.same else univariate_ck_set(factors.c, l, factors.m, (lo, hi), grid=grid, budget=budget,
                                                    tol=tol, strip_budget=strip_budget)
    L, H = RealAlgebraic.rational(lo), RealAlgebraic.rational(hi)
    ends = [L, H]
    for f in (fb, fc):
        for part in f.cl + f.not_cl + f.undecided:
            ends += [e for e in part[:2] if _cmp(L, e) <= 0 <= _cmp(H, e)]
    ends = sorted(ends, key=functools.cmp_to_key(_cmp))
    uniq = [e for k, e in enumerate(ends) if k == 0 or _cmp(ends[k - 1], e) != 0]
    pieces = _pieces(uniq)
    lb, lc = _classify(fb, pieces), _classify(fc, pieces)
    labels = [_combine(u, v) for u, v in zip(lb, lc)]
    value = _sets(pieces, labels)
    fb.sets, fc.sets = _sets(pieces, lb), _sets(pieces, lc)
    # certified only when every piece is decided: a piece between counterexamples is sampled, not proven
    status = CERTIFIED if value["undecided"].is_empty and value["sampled"].is_empty else INCONCLUSIVE
    prov: dict[str, Any] = {"method": "exact tensor-product reduction (rank-1 coefficient grid, M = m I): the "
                                      "intersection of the univariate C^l sets of the factors",
                            "univariate": fb.route, "grid": grid}
    if status != CERTIFIED:
        prov["message"] = "; ".join(f"{k}: {value[k]}" for k in ("undecided", "sampled") if not value[k].is_empty)
    return Result(value=value, status=status,
                  witness={"parameter": p.name, "l": l, "m": factors.m, "factors": factors, "b": fb, "c": fc,
                           "same_factor": factors.same},
                  provenance=prov)
