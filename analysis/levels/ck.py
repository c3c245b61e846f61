"""C^k verdicts of a level-dependent scheme for every k up to its limit's, each with its theorem.

:func:`level_smoothness` decides, for ``k = 0, 1, ...`` up to the largest k for which the
stationary limit ``S_a`` (``a = lim a^n``) is certified C^k, whether ``{S_{a^n}}`` is C^k, trying
in order

1. **Dyn–Levin 1995, asymptotic equivalence** (direct; tried second when ``(1+z)^k`` divides
   every ``a^n``): same support for all n, ``S_a`` C^k,
   ``sum_n 2^{kn} ||S_{a^n} - S_a||_inf < oo`` (:func:`analysis.levels.series.smoothness`);
2. **Dyn–Levin 1995 on the j-th divided difference scheme** ``e^n = (2/(1+z))^j a^n`` (``j <= k``,
   ``(1+z)^j`` divides every ``a^n`` identically in n): same support, ``S_e`` C^{k-j} and
   ``sum_n 2^{(k-j)n} ||S_{e^n} - S_e|| < oo`` give ``S_{e^n}`` C^{k-j}, hence ``S_{a^n}`` C^k —
   this is what makes exponential B-splines reach their true smoothness;
2′. **Dyn–Levin on a j-th generalized divided difference scheme** ``c^n = 2^j a^n / p_n``,
   ``p_n = prod_{i<=j} (1 + e^{lambda_i 2^-(n+1)} z)`` (exponential factors, ``Lambda`` closed under
   conjugation, ``0`` allowed, ``p_n | a^n`` proved exactly for every n; :mod:`.gendiff`, where the
   theorem is proved): ``{S_(a^n)}`` convergent and ``S_{c^n}`` C^{k-j} give C^k — exponential
   B-splines *without* the frequency 0 (``(1+z)`` does not divide ``a^n``);
3. **asymptotic similarity + approximate sum rules** (Conti–Dyn–Manni–Mazure 2015 for k = 0;
   Charina–Conti–Guglielmi–Protasov 2017 for C^k): the masks have one common support, converge to
   ``a`` (asymptotic similarity), satisfy approximate sum rules of order ``k+1`` with
   ``sum_n 2^{kn} mu_n < oo``, ``mu_n = max(|a^n(1) - 2|, max_{j<=k} |D^j a^n(-1)|)``, and the
   limit satisfies the joint-spectral-radius condition ``alpha(S_a) > k``.

Each hypothesis is checked with exact (sympy) or ball (Arb) arithmetic; a k for which every route
fails is *inconclusive* and names, per route, the hypothesis that failed. Past the limit's
smoothness (``S_a`` certified not C^k) one theorem decides "not C^k":

4. **exponential B-spline schemes** (:mod:`.expbspline`): when ``a^n(z) = 2 z^s prod_{i<=d+1}
   (1 + e^{lambda_i 2^-(n+1)} z)/(1 + e^{lambda_i 2^-(n+1)})`` for every n (recognised exactly),
   the scheme generates the exponential B-spline of order d+1, which is not C^d: "C^d: no
   [certified]", and with C^{d-1} certified by the routes above the smoothness is *exactly*
   C^{d-1}.

**Arity m** (carried by the scheme, ``LevelDependentScheme(..., arity=m)``, ``h = m^-n``):
routes 1, 2, 2′ and 4 with dilation m — Dyn–Levin with weight ``m^{kn}`` and the limit's C^k by the m-ary
analysis (:func:`analysis.regularity.holder.smoothness`); the divided difference schemes
``(m/(1+z+...+z^(m-1)))^j a^n`` (:mod:`.divided`), which for ``m >= 3`` also need the convergence of
``{S_(a^n)}`` (they are the case ``Lambda = (0, ..., 0)`` of the generalized theorem, proved for dilation m in
:mod:`.gendiff`); the exponential factors ``q(e^{lambda m^-(n+1)} z)``; m-ary exponential B-spline schemes
(:mod:`.expbspline`). Route 3 is binary only (its moment conditions at ``-1`` are the binary sum rules) and
says so.

Otherwise the verdict stays inconclusive: no theorem implemented here transfers "not C^k" from
``S_a`` to ``{S_{a^n}}`` in general. The theorem that would (an upper bound of the Hölder exponent
of an asymptotically similar non-stationary scheme by that of its limit: the Hölder-exponent
formula of Charina–Conti–Guglielmi–Protasov 2017 for dilation ``mI``) was not implemented because
its exact hypotheses could not be quoted from the sources at hand (issue 13).

Examples
--------
>>> from schemes.level_dependent import get
>>> r = level_smoothness(get("exp-cubic-trig").subs({"t": 1}))
>>> r.value, r.status, [v["route"] for v in r.witness["verdicts"]][:3]
(2, 'certified', ['Dyn-Levin direct', 'Dyn-Levin on the 1st divided difference scheme', 'Dyn-Levin on the 2nd divided difference scheme'])
>>> r.witness["verdicts"][3]["verdict"], r.witness["verdicts"][3]["status"], r.witness["exact"]
('not C^3', 'certified', True)
>>> from schemes.level_dependent import get
>>> r = level_smoothness(get("ternary-exp-bspline-1-hyp"), {"t": 1})
>>> r.value, r.witness["exact"], [v["verdict"] for v in r.witness["verdicts"]]
(0, True, ['C^0', 'not C^1'])

Algorithm
---------
Routes 1–2: :func:`analysis.levels.series.smoothness` (arb partial sums + Cauchy Taylor tails); route
2′: :func:`analysis.levels.gendiff.gendiff_smoothness`. The exact Taylor coefficients in ``h`` are
computed once per scheme by series arithmetic (:func:`analysis.levels.hseries.prefill_taylor`) where
the mask allows it (``sympy.series`` otherwise).
Route 3: ``a^n(1) - 2`` and ``D^j a^n(-1)`` are fixed linear combinations ``sum_i w_i g_i(h)`` of
the coefficient differences ``g_i = a^n_i - a_i`` (``w_i`` exact, ``h = 2^-n``); their exact
Taylor coefficients in h vanish below ``h^{k+1}`` (exact zero test), and the combined rigorous
Taylor model bounds them by ``A h^{k+1}`` for ``n >= N``, so ``sum_n 2^{kn} mu_n`` converges
geometrically (ratio 1/2).

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*,
J. Math. Anal. Appl. 193 (1995) 594-621.
N. Dyn, D. Levin, A. Luzzatto, *Exponentials reproducing subdivision schemes*, Found. Comput.
Math. 3 (2003) 187-206 (generalized differences: route 2′).
C. Conti, N. Dyn, C. Manni, M.-L. Mazure, *Convergence of univariate non-stationary subdivision
schemes via asymptotic similarity*, Comput. Aided Geom. Des. 37 (2015) 1-8.
M. Charina, C. Conti, N. Guglielmi, V. Protasov, *Regularity of non-stationary subdivision: a
matrix approach*, Numer. Math. 135 (2017) 639-678.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Mapping

import flint
import sympy as sp

from .balls import _ball, arb_abs, ball_to_interval, workprec
from .divided import certainly_not_divisible, divided_difference, q_label
from .expbspline import not_ck
from .gendiff import GeneralizedDifferences, gendiff_smoothness
from .hseries import prefill_taylor
from .level_dependent import H, LevelDependentScheme, level_h
from .taylor_model import TaylorModel, taylor_models
from .series import REGULARITY_HOOKS, same_support, smoothness, stationary_smoothness as series_stationary
from ..jsonable import fmt_upper
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result


def check_real(s: LevelDependentScheme, levels=range(0, 24), arity: int = 2) -> None:
    """One-line :class:`AnalysisError` when a coefficient is certified non-real (or undefined) at a level.

    ``s`` has no free parameters. Each coefficient is enclosed in complex ball arithmetic at the
    given levels; an imaginary part that excludes 0, or a non-finite value, is an error.
    """
    if s.params:
        raise AnalysisError(f"give values for {', '.join(s.param_names)} (--param NAME=VALUE)")
    with workprec(128):
        for n in levels:
            env = {"h": flint.acb(level_h(n, arity))}
            for k, c in enumerate(s.mask):
                try:
                    v = _ball(c, env, True)
                except ZeroDivisionError:
                    v = flint.acb("nan")
                if not v.is_finite():
                    raise AnalysisError(f"the coefficient of z^{s.start + k} is undefined at level n = {n}: "
                                        f"{sp.sstr(c.subs(H, sp.Rational(1, arity ** n)))}")
                if not v.imag.contains(0):
                    raise AnalysisError(f"the coefficient of z^{s.start + k} is not real at level n = {n} "
                                        f"({v}): the scheme must be real")
                if not _ball(c, {"h": env["h"].real}, False).is_finite():
                    raise AnalysisError(f"the coefficient of z^{s.start + k} passes through non-real values at "
                                        f"level n = {n} (e.g. acos of a number > 1): rewrite it in real terms, "
                                        "e.g. cosh(acosh(w)/2**(n+1)) instead of cos(acos(w)/2**(n+1)) for w > 1")


def _moment_weights(s: LevelDependentScheme, k: int) -> list[tuple[str, list[sp.Integer], sp.Integer]]:
    """``(name, w, target)``: ``sum_i w_i a_i`` is ``a(1)`` (target 2) or ``D^j a(-1)`` (target 0)."""
    ex = [s.start + i for i in range(len(s.mask))]
    out = [("a(1) - 2", [sp.Integer(1)] * len(ex), sp.Integer(2))]
    for j in range(k + 1):
        w = [sp.ff(e, j) * (-1) ** ((e - j) % 2) for e in ex]
        out.append((f"D^{j} a(-1)", [sp.Integer(x) for x in w], sp.Integer(0)))
    return out


def approximate_sum_rules(s: LevelDependentScheme, k: int, *, N: int = 40) -> Result:
    """Certify approximate sum rules of order ``k+1`` with ``sum_n 2^{kn} mu_n < oo``.

    ``mu_n = max(|a^n(1) - 2|, max_{j<=k} |D^j a^n(-1)|)`` (Charina–Conti–Guglielmi–Protasov
    2017). Needs exact sum rules of order ``k+1`` of the limit ``a`` (checked exactly) and
    ``D^j a^n(-1) = O(2^{-(k+1)n})`` (exact Taylor coefficients in ``h``, rigorous remainder).
    Certified ``value=True`` with the bound ``mu_n <= A 2^{-(k+1)n}`` (``n >= N``), or
    inconclusive naming the failed condition.
    """
    lim = s._limits
    J = k + 3
    rows = s.taylor(J)
    checks, bad = {}, []
    for name, w, target in _moment_weights(s, k):
        at_lim = sp.simplify(sum(wi * c for wi, c in zip(w, lim)) - target)
        if at_lim != 0:
            bad.append(f"the limit violates {name} = {target} exactly (value {sp.sstr(at_lim + target)})")
            continue
        series = [sp.simplify(sum(wi * r[j] for wi, r in zip(w, rows))) for j in range(J)]
        order = next((j for j in range(J) if series[j] != 0), J)
        checks[name] = {"order_in_h": order if order < J else f">= {J}",
                        "leading": series[order] if order < J else 0}
        if order <= k:
            bad.append(f"{name} = O(2^-{order}n) only: sum_n 2^({k}n) mu_n diverges")
    if bad:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"approximate_sum_rules": None, "order": k + 1, "failed": bad, "checks": checks},
                      provenance={"method": "exact Taylor coefficients in h = 2^-n"})
    models = taylor_models(s, None, J=J)
    with workprec(128):
        hN = flint.arb(2) ** (-N)
        A = flint.arb(0)
        for _, w, _ in _moment_weights(s, k):
            rho = models[0].rho
            coeffs = tuple(sum((int(wi) * m.coeffs[j] for wi, m in zip(w, models)), flint.arb(0)) for j in range(J))
            M = sum((abs(int(wi)) * m.M for wi, m in zip(w, models)), flint.arb(0))
            A = A.max(TaylorModel(coeffs, M, rho, J).abs_upper_over(k + 1, hN))
        A = flint.arb(arb_abs(A).upper())
    return Result(value=True, status=CERTIFIED,
                  witness={"approximate_sum_rules": True, "order": k + 1, "checks": checks,
                           "bound": f"mu_n <= {fmt_upper(ball_to_interval(A)[1], 3, 'g')} * 2^(-{k + 1}n) for n >= {N}",
                           "series": f"sum_n 2^({k}n) mu_n < oo (ratio 1/2 tail)"},
                  provenance={"method": "exact Taylor coefficients + Cauchy-estimate Taylor model"})


class _Differences:
    """The divided difference schemes ``e_j = (2/(1+z))^j a^n`` (arity m: ``(m/q_m)^j a^n``), computed once
    (their Taylor caches are shared by every k); ``None`` once ``(1+z)^j`` does not divide ``a^n`` identically."""

    def __init__(self, s: LevelDependentScheme, arity: int = 2):
        self.arity = arity
        self.schemes: dict[int, LevelDependentScheme | None] = {0: s}

    def get(self, j: int) -> LevelDependentScheme | None:
        if j not in self.schemes:
            prev = self.get(j - 1)
            try:
                # certainly_not_divisible: the exact test would fail too (cheap, skips its simplifications)
                self.schemes[j] = (None if prev is None or certainly_not_divisible(prev.mask, self.arity) else
                                   divided_difference(prev, 1, self.arity))
                if self.schemes[j] is not None:
                    prefill_taylor(self.schemes[j])
            except AnalysisError:
                self.schemes[j] = None
        return self.schemes[j]

    def divisibility(self, k: int) -> int:
        """The largest ``j <= k`` with ``(1+z)^j | a^n`` (``q_m^j``) identically in n."""
        j = 0
        while j < k and self.get(j + 1) is not None:
            j += 1
        return j


def _ordinal(j: int) -> str:
    return f"{j}{ {1: 'st', 2: 'nd', 3: 'rd'}.get(j if j < 20 else j % 10, 'th')}"


def _ok(r: Result) -> bool:
    return r.is_certified and r.value is True


def _verdict_k(s: LevelDependentScheme, a_smooth: dict, k: int, sup: Result, N: int, diffs: _Differences,
               gd: GeneralizedDifferences | None = None, converges: Result | None = None) -> dict:
    tried = []
    # all (1+z)^k divide a^n: the k-th divided difference route first (weight 2^0: the likeliest to
    # converge), then the direct series, then the intermediate differences
    m = diffs.arity
    jmax = diffs.divisibility(k)
    order = ([jmax] if jmax == k and k > 0 else []) + [0] + [j for j in range(jmax, 0, -1) if j != k]
    for j in order:
        # Dyn-Levin on e_j with weight 2^((k-j)n): what smoothness(s, k, difference=j) computes
        r = smoothness(diffs.get(j), None, k - j, N=N, arity=m)
        if j == 0:
            if _ok(r):
                return {"k": k, "verdict": f"C^{k}", "status": CERTIFIED, "route": "Dyn-Levin direct",
                        "theorem": r.witness["theorem"], "hypotheses": r.witness["hypotheses"]}
            tried.append({"route": "Dyn-Levin direct", "failed": r.witness["failed"]})
            continue
        route = f"Dyn-Levin on the {_ordinal(j)} divided difference scheme"
        if _ok(r) and m != 2 and not (converges is not None and _ok(converges)):
            # arity m: the divided-difference argument is the generalized one with Lambda = (0, ..., 0)
            # (analysis.levels.gendiff), which needs the convergence of {S_(a^n)} (H2)
            tried.append({"route": route, "failed": ["H2: convergence of {S_(a^n)} not certified"]})
            continue
        if _ok(r):
            if m != 2:
                return {"k": k, "verdict": f"C^{k}", "status": CERTIFIED, "route": route,
                        "theorem": (f"Dyn-Levin 1995 with dilation {m} applied to e^n = ({m}/({q_label(m)}))^{j} a^n "
                                    f"(S_(e^n) C^{k - j}), {{S_(a^n)}} convergent  =>  C^{k} (generalized differences "
                                    "with Lambda = (0, ..., 0); proof in analysis.levels.gendiff)"),
                        "hypotheses": {**r.witness["hypotheses"], "convergence": converges}}
            return {"k": k, "verdict": f"C^{k}", "status": CERTIFIED, "route": route,
                    "theorem": (f"Dyn-Levin 1995 applied to e^n = (2/(1+z))^{j} a^n (S_(e^n) C^{k - j}) "
                                f"+ the divided-difference argument: S_(a^n) C^{k}"),
                    "hypotheses": r.witness["hypotheses"]}
        tried.append({"route": route, "failed": r.witness["failed"]})
    if gd is not None and k > 0:
        g = gendiff_smoothness(s, k, converges=converges, N=N, cache=gd, arity=m)
        if _ok(g):
            w = g.witness
            names = ", ".join(sp.sstr(x) for x in w["subset"])
            return {"k": k, "verdict": f"C^{k}", "status": CERTIFIED,
                    "route": (f"Dyn-Levin on the {_ordinal(w['j'])} generalized divided difference scheme "
                              f"(exponential factors {names})"),
                    "theorem": w["theorem"], "hypotheses": w["hypotheses"], "j": w["j"], "r": w["r"],
                    "Lambda": [sp.sstr(x) for x in w["Lambda"]]}
        tried.append({"route": "Dyn-Levin on a generalized divided difference scheme (exponential factors)",
                      "failed": g.witness["failed"]})
    route = ("Conti-Dyn-Manni-Mazure 2015 (asymptotic similarity)" if k == 0 else
             "Charina-Conti-Guglielmi-Protasov 2017 (asymptotic similarity + approximate sum rules)")
    if m != 2:
        tried.append({"route": route, "failed": [f"not implemented for arity {m} (the m-ary approximate sum rules at "
                                                 "the m-th roots of unity are not coded)"]})
        return {"k": k, "verdict": "undecided", "status": INCONCLUSIVE, "route": None, "tried": tried}
    asr = approximate_sum_rules(s, k, N=N)
    lim = a_smooth[k]
    hyps = {"same_support": sup, f"approximate_sum_rules_order_{k + 1}": asr, f"alpha(S_a) > {k}": lim}
    failed = [name for name, x in hyps.items() if not _ok(x)]
    if not failed:
        return {"k": k, "verdict": f"C^{k}", "status": CERTIFIED, "route": route,
                "theorem": (f"common support, a^n -> a, approximate sum rules of order {k + 1} with "
                            f"sum 2^({k}n) mu_n < oo, JSR condition alpha(S_a) > {k}  =>  C^{k}"),
                "hypotheses": hyps}
    tried.append({"route": route, "failed": failed})
    return {"k": k, "verdict": "undecided", "status": INCONCLUSIVE, "route": None, "tried": tried}


def limit_smoothness(a, top: int, stationary_smoothness) -> tuple[int, int | None, dict[int, Result]]:
    """``(k_lim, not_k, results)``: the stationary limit's C^k tested for ``k = 0..top`` until the first
    k that is not certified; ``k_lim`` the last certified k, ``not_k`` the k certified *not* C^k (or None)."""
    a_smooth: dict[int, Result] = {}
    k_lim, not_k = -1, None
    for k in range(top + 1):
        r = stationary_smoothness(a, k)
        a_smooth[k] = r
        if r.value is True and r.is_certified:
            k_lim = k
            continue
        if r.value is False and r.is_certified:
            not_k = k
        break
    return k_lim, not_k, a_smooth


def level_smoothness(s: LevelDependentScheme, values: Mapping[str, Any] | None = None, *,
                     k_max: int | None = None, N: int | None = None, arity: int | None = None) -> Result:
    """Convergence and the C^k verdict for each k up to the limit's smoothness (see the module).

    ``arity`` m: ``s`` is read with ``h = m^-n`` (routes 1, 2, 2' and 4 with dilation m; route 3 is binary
    only and says so); ``arity`` defaults to the scheme's. The C^k verdicts need exact values (no boxes:
    :func:`analysis.levels.ck_box.level_smoothness_box`). ``N``: levels enclosed explicitly before the
    analytic tails (default 40; 30 for ``m > 2``, as the m-ary results have always been computed).

    ``value``: the largest k with C^k certified for every ``k' <= k`` (``-1``: not even
    convergence certified). ``witness["verdicts"]``: one dict per k with ``verdict``, ``status``,
    ``route`` and ``theorem`` (or ``tried``: the failed hypotheses of each route);
    ``witness["limit"]``: the stationary limit and its certified smoothness;
    ``witness["not_C^k"]``: the k certified *not* C^k (exponential B-spline schemes) or ``None``,
    and ``witness["exact"]``: True when that k is ``value + 1`` (the smoothness is exactly C^value).
    """
    arity = s.arity if arity is None else arity
    N = (40 if arity == 2 else 30) if N is None else N
    boxed = [k for k, v in dict(values or {}).items() if isinstance(v, tuple)]
    if boxed:
        raise AnalysisError(f"the C^k verdicts need exact values: give --param {boxed[0]}=VALUE, not a box")
    if values:
        s = s.subs(values)
    if any(c.atoms(sp.Float) for c in s.mask):
        return _level_smoothness.__wrapped__(s, k_max, N, arity, ())
    return _level_smoothness(s, k_max, N, arity, tuple(REGULARITY_HOOKS))


@lru_cache(maxsize=64)
def _level_smoothness(s: LevelDependentScheme, k_max: int | None, N: int, arity: int, hooks: tuple) -> Result:
    """:func:`level_smoothness` of the scheme with its values substituted: a pure function of the scheme, ``k_max``,
    ``N``, the arity and the registered regularity ``hooks`` (:data:`analysis.levels.series.REGULARITY_HOOKS`),
    remembered (the command line and the claims ask again for a scheme already analysed)."""
    from ..regularity import smoothness as binary_smoothness

    def stationary_smoothness(a, k):
        return binary_smoothness(a, k) if arity == 2 else series_stationary(a, k, arity=arity)

    check_real(s, arity=arity)
    a = s.limit()
    prefill_taylor(s)          # the same exact Taylor coefficients as sympy.series, faster (or nothing)
    if all(H not in c.free_symbols for c in s.mask):
        raise AnalysisError("the scheme does not depend on the level: use the stationary analysis")
    k_lim, not_k, a_smooth = limit_smoothness(a, 12 if k_max is None else k_max, stationary_smoothness)
    sup = same_support(s, None, N=N, arity=arity)
    diffs = _Differences(s, arity)
    gd = GeneralizedDifferences(s, arity)
    verdicts = []
    best = -1
    for k in range(k_lim + 1):
        conv = None
        if verdicts:
            v0 = verdicts[0]
            conv = Result(value=True if v0["status"] == CERTIFIED else None, status=v0["status"],
                          witness={"statement": "{S_(a^n)} converges (C^0)", "route": v0["route"]},
                          provenance={"method": "the C^0 verdict above"})
        v = _verdict_k(s, a_smooth, k, sup, N, diffs, gd, conv)
        verdicts.append(v)
        if v["status"] == CERTIFIED and best == k - 1:
            best = k
    cert = None
    if not_k is not None and (k_max is None or not_k <= k_max):
        cert = not_ck(s, arity)
        d = cert.witness.get("k")
        if not (cert.is_certified and cert.value is False and d is not None and k_lim < d <= not_k):
            cert = None
    if cert is not None:
        d = cert.witness["k"]
        verdicts.append({"k": d, "verdict": f"not C^{d}", "holds": False, "status": CERTIFIED,
                         "route": f"exponential B-spline of order {d + 1} (recognised exactly)",
                         "theorem": cert.witness["theorem"], "hypotheses": cert.witness["hypotheses"],
                         "frequencies": cert.witness["frequencies"]})
    elif not_k is not None and (k_max is None or not_k <= k_max):
        verdicts.append({"k": not_k, "verdict": "undecided", "status": INCONCLUSIVE, "route": None,
                         "reason": (f"the limit S_a is certified not C^{not_k} "
                                    f"({a_smooth[not_k].witness.get('reason')}), but no implemented theorem "
                                    f"transfers 'not C^{not_k}' to the level-dependent scheme (missing: an "
                                    "upper bound for the Hoelder exponent of {S_(a^n)} from that of S_a, e.g. "
                                    "the Hoelder-exponent formula of Charina-Conti-Guglielmi-Protasov 2017, "
                                    "Numer. Math. 135; its exact hypotheses are not implemented)")})
    status = CERTIFIED if best >= 0 else INCONCLUSIVE
    upper = ("none certified (lower bound only)" if cert is None else
             f"not C^{cert.witness['k']} (certified: exponential B-spline of order {cert.witness['k'] + 1})")
    return Result(value=best, status=status,
                  witness={"verdicts": verdicts, "max_certified_k": best,
                           "limit": {"symbol": a, "C^k_certified_up_to": k_lim, "not_C^k": not_k},
                           "upper_bound": upper, "not_C^k": None if cert is None else cert.witness["k"],
                           "exact": cert is not None and best == cert.witness["k"] - 1},
                  provenance={"scheme": s.slug, "N": N,
                              "method": ("Dyn-Levin 1995 (direct, divided differences, generalized divided differences); "
                                         "CDMM 2015 / CCGP 2017"), **({} if arity == 2 else {"arity": arity})})
