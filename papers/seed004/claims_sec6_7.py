"""Seed 004, Sections 6-7: no Gibbs oscillation (Theorems 6.1-6.2) and the maximal smoothness
of the family (C^6, Sect. 7)."""

from __future__ import annotations

import sympy as sp

from analysis import claims as C
from schemes.seed004 import MU, NU, RULE_3_6, _from

from .derivations import _iset_numbers, _s, _sym, _zeta_set
from .figures import _gibbs_figure


# -------------------------------------------------------------------------- Gibbs (Sect. 6)
def _thm61():
    t = _sym("seed004-t-nu")
    s1, z1 = _zeta_set(t, 1, NU)
    s2, _ = _zeta_set(t, 2, NU)
    claimed = (sp.Rational(5, 7), sp.Integer(7))
    exact_k1 = (str(s1) == "[5/7, 7]")
    rows = [(f"zeta_{l}^[1]({i})", _s(e)) for (l, i), e in sorted(z1.items())]
    ev = [C.Evidence("zeta_l^[1](i), l = 0, 1 (exact, in nu)", table=(("condition", "value"),) + tuple(rows),
                     result=C.exact_result(s1, "exact_set of all zeta^[1] >= 0")),
          C.Evidence("exact nu-sets where all zeta^[k] >= 0", text=f"k = 1: {s1}; k = 2: {s2} (k = 3 costs ~10 s: not run by default)",
                     result=C.exact_result(s2, "exact_set")),
          C.Evidence("reading", text="case 1 alone (l = 0) gives nu >= 5/7 with no upper bound; the paper's "
                                     "'case 1: 0.7142857 <= nu <= 7' is a slip, the bound 7 comes from case 2.")]
    k_ok = [C.contains_interval(s2, *claimed, closed=True)]
    nums = _iset_numbers("k1_set", s1) + _iset_numbers("k2_set", s2)
    return C.inconclusive(
        f"The level-1 conditions hold exactly for nu in {s1}{' (the printed range)' if exact_k1 else ''}; "
        f"Theorem 2.3 (as quoted) needs them for every level k: k = 2 gives {s2}"
        + ("" if all(k_ok) else " — smaller than the printed range") + ". Gibbs-freeness on the range is "
        "therefore not established by the paper's argument"
        + (" (and the sufficient condition fails at level 2 on part of it)." if not all(k_ok) else "."),
        settle="the conditions for every k (an induction, or a lemma reducing to k = 1), or a direct "
               "analysis of the limit of the step data",
        sharpness=f"level 1 exact set {s1}", evidence=ev, numbers=nums, figures=[_gibbs_figure()])


def _thm62():
    l = _sym("seed004-l-mu")
    s1, _ = _zeta_set(l, 1, MU)
    at0 = l.subs({MU: 0})
    positive = all(c >= 0 for c in at0.mask)
    ev = [C.Evidence("mu = 0 is the degree-6 B-spline: a nonnegative mask", latex="a(z) = " + at0.latex(),
                     text="every k-step mask is a product of nonnegative polynomials, so every zeta^[k] >= 0",
                     result=C.exact_result(positive, "exact signs of the mask")),
          C.Evidence("exact mu-set where all zeta^[1] >= 0", text=str(s1), result=C.exact_result(s1, "exact_set"))]
    if positive:
        return C.certified("True: at mu = 0 (the degree-6 B-spline, a positive mask) all conditions hold for "
                           "every level k.",
                           sharpness=f"mu = 0 is not the only candidate: the level-1 conditions hold on {s1} "
                                     "(all levels would still need checking there).",
                           evidence=ev, numbers=_iset_numbers("k1_set", s1))
    return C.refuted("negative mask", "see evidence", evidence=ev)


# -------------------------------------------------------------------------- C^6 (Sect. 7)
def _c6():
    from analysis.stationary.difference import difference_norm
    from analysis.algebra.factorization import factor_out, smoothing_factor
    from analysis.stationary.transition import transition_matrices
    a = _from(RULE_3_6)
    f = smoothing_factor(a)

    def walk(ex, cond=()):
        for e in ex:
            c = cond + (e["condition"],)
            yield c, e["k"]
            yield from walk(e.get("exceptional", []), c)
    tree = list(walk(f.witness["exceptional"]))
    best_cond, best_k = max(tree, key=lambda t: t[1])
    vals: dict = {}
    for c in best_cond:
        vals = {k: sp.sympify(v).subs(vals) for k, v in vals.items()}
        vals.update({k: sp.sympify(v).subs(vals) for k, v in c.items()})
    for _ in range(3):
        vals = {k: sp.simplify(sp.sympify(v).subs(vals)) for k, v in vals.items()}
    best = a.subs(vals)
    m = best_k - 1
    dn = difference_norm(best, m, 1)
    c = factor_out(best, best_k) / 2
    T0, T1 = transition_matrices(c)
    rho = max(abs(e) for e in list(T0.eigenvals()) + list(T1.eigenvals()))
    alpha_upper = (best_k - 1) - sp.log(rho, 2)
    ev = [C.Evidence("smoothing factors of (3.6) with exceptional parameter values", result=f,
                     text="; ".join(f"{' & '.join(_s(x) for x in cs)}: k = {k}" for cs, k in tree)),
          C.Evidence(f"the best member: {', '.join(f'{k} = {_s(v)}' for k, v in vals.items())}",
                     latex="a(z) = " + best.latex(),
                     text=f"(1+z)^{best_k} divides a; ||1/2 S_(a_{m})||_inf = {_s(dn.value)} < 1 "
                          f"⇒ C^{m - 1} (Dyn-Levin, exact)", result=dn),
          C.Evidence("upper bound", text=f"c = 2^{best_k - 1} a/(1+z)^{best_k} = {c.mask}; the transition "
                     f"matrices have spectral radius {_s(rho)}, so the joint spectral radius is ≥ {_s(rho)} and the Hölder exponent ≤ {best_k - 1} - log2({_s(rho)}) "
                     f"≈ {float(alpha_upper):.4f} < {best_k - 1}: not C^{best_k - 1}",
                     result=C.exact_result(rho, "exact eigenvalues of the transition matrices"))]
    nums = [C.Number("max_k", best_k), C.Number("norm_m%d_L1" % m, dn.value),
            C.Number("holder_upper_bound", float(alpha_upper), tol=1e-9)]
    if dn.witness["contractive"] and m - 1 > 6:
        return C.refuted(f"The family reaches C^{m - 1}, more than C^6: at {', '.join(f'{k} = {_s(v)}' for k, v in vals.items())} "
                         f"the symbol has (1+z)^{best_k} and the exact norm test proves C^{m - 1}; C^{m} is "
                         f"impossible anywhere in the family (C^{m} needs (1+z)^{m + 1}, only at this point, where the "
                         f"Hölder exponent is ≤ {float(alpha_upper):.4f}).",
                         corrected=f"the family produces limit curves up to C^{m - 1} (attained only at "
                                   f"{', '.join(f'{k} = {_s(v)}' for k, v in vals.items())})",
                         evidence=ev, numbers=nums)
    if dn.witness["contractive"] and m - 1 >= 6:
        return C.certified("C^6 is attained", evidence=ev, numbers=nums)
    return C.inconclusive("the norm test does not settle the maximal smoothness",
                          settle="needs the Hölder exponent (issue 3)", evidence=ev, numbers=nums)
