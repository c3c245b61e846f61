"""Seed 003: W. us Salam, S. S. Siddiqi, K. Rehan, *Chaikin's perturbation subdivision scheme in
non-stationary forms*, Alexandria Engineering Journal (2016), doi:10.1016/j.aej.2016.07.002.

The paper's checkable claims: ``PAPER`` (``subdiv report 003``). Its schemes, rule (1)
(``dfh-chaikin-perturbation``) and the level-dependent forms (2)-(5) with the comparison scheme
[11], are catalogue entries (:mod:`schemes.seed003`). Here:

* :mod:`.transcription` — the lemma inequalities and statements as printed;
* :mod:`.derivations` — computations shared by several claims (C^2 set of rule (1), norm sets,
  curve deviations);
* :mod:`.figures` — the alpha(omega) plot and the curve comparisons;
* the evaluators by section: :mod:`.claims_sec2`, :mod:`.claims_sec3_lemmas` (inequalities,
  Lemmas 3.1-3.4), :mod:`.claims_sec3_theorem` (Theorem 3.1, Corollary 3.2), :mod:`.claims_sec4_5`
  (normalized schemes, (7), Theorem 5.1), :mod:`.claims_sec6_7` (curve comparisons);
* below, the claims in the paper's order: statements as printed (LaTeX of the extraction, lightly
  de-marked-up), our readings, and the command that reproduces each verdict. Every verdict is
  computed by the engine, never typed in.

Examples
--------
>>> from papers.seed003 import PAPER
>>> PAPER.id, len(PAPER.claims)
('003', 41)
>>> PAPER.claim("003:Lemma3.4(d)").kind
'identity'
"""

from __future__ import annotations

import functools

from analysis import claims as C
from schemes.seed003 import _SOURCE, BETA, BETA_SUM, GAMMA, GAMMA_SUM, HYPERBOLIC, TRIGONOMETRIC

from .claims_sec2 import _sec2_c2, _sec2_omega0
from .claims_sec3_lemmas import (_factorization, _identity_item, _ineq_hyp, _ineq_trig, _lemma31, _lemma32,
                                 _lemma34_c2, _lemma34_d)
from .claims_sec3_theorem import _theorem31_c2, _theorem31_equivalence, _theorem31_proof
from .claims_sec4_5 import _eq7, _normalized_constants, _normalized_convergence, _sum_identity, _theorem51
from .claims_sec6_7 import _sec6_analytic, _sec6_conics
from .transcription import _DEF, _DEF2, _INEQ_PRINTED, _L31_PRINTED, _L32_PRINTED, LEMMA_3_1

_CMD = "subdiv report 003 --claim '{}'"


# -------------------------------------------------------------------------- the claims
def _c(cid, kind, statement, fn, title, *, reading=None, note=None, objects=(), params=(), command=None,
       location=""):
    return C.Claim(id=cid, kind=kind, statement=statement, evaluate=fn, title=title, reading=reading,
                   reading_note=note, objects=objects, params=params, command=command or _CMD.format(cid),
                   location=location)


_ST = ("dfh-chaikin-perturbation",)
_TR = ("seed003-trigonometric",)
_HY = ("seed003-hyperbolic",)
_BOUND_CMD = "subdiv bound --claim '{}' --box alpha=pi/6,pi/3 --param omega=0 --n0 {}"

CLAIMS = [
    _c("003:Sec2(omega=0)", "smoothness", "with omega = 0 corresponds to the Chaikin's scheme [12]. The scheme gives "
       "C^1 - continuous limit curves for omega = 0", _sec2_omega0, "omega = 0: Chaikin, C^1", objects=_ST + ("chaikin",),
       params=("omega",), location="Sect. 2", command="subdiv holder --scheme dfh-chaikin-perturbation --param omega=0 --C 2"),
    _c("003:Sec2(C2)", "smoothness", "and C^2 - continuous limit curves for 0 < omega < \\frac{\\sqrt{6}-1}{80}.",
       _sec2_c2, "C^2 for 0 < omega < (sqrt6-1)/80", objects=_ST, params=("omega",), location="Sect. 2",
       command="subdiv norm --scheme dfh-chaikin-perturbation --m 3 --L 1,2,3 --solve omega --within 0,oo && "
               "subdiv range --scheme dfh-chaikin-perturbation --C 2 --within=-1/20,1/20 --grid 10"),
]
for _k in (1, 2, 3):
    CLAIMS.append(_c(f"003:Sec3.3({_k})", "inequality", _INEQ_PRINTED[_k], functools.partial(_ineq_trig, _k),
                     f"Inequality {_k} of Sect. 3.3 (sin)", location="Sect. 3.3",
                     reading="s = sin, c = cos" + ("; '(2)' is sin(x)/x strictly decreasing" if _k == 2 else ""),
                     command="subdiv bound --lhs 'cos(alpha/2**n)' --rhs 'sin(alpha/2**n)/(alpha/2**n)' --strict "
                             "--box alpha=pi/4,pi/2"))
for _k in (4, 5, 6):
    CLAIMS.append(_c(f"003:Sec3.3({_k})", "inequality", _INEQ_PRINTED[_k], functools.partial(_ineq_hyp, _k),
                     f"Inequality {_k} of Sect. 3.3 (sinh)", location="Sect. 3.3",
                     reading="s' = sinh, c' = cosh; the exclusion of the points n'pi is void (sinh has no positive zero)",
                     command="subdiv bound --lhs 'sinh(alpha/2**n)/(alpha/2**n)' --rhs 'cosh(alpha/2**n)' --strict "
                             "--box alpha=1/2,1"))
for _it in ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii"):
    if _it in _DEF:
        _fn = functools.partial(_identity_item, *_DEF[_it])
        _cmd = None
    else:
        _fn = functools.partial(_lemma31, _it)
        _key = next(k for k in LEMMA_3_1 if k.startswith(f"003:Lemma3.1({_it})-"))
        _cmd = _BOUND_CMD.format(_key, 1)
    CLAIMS.append(_c(f"003:Lemma3.1({_it})", "identity" if _it in _DEF else "inequality",
                     "Lemma 3.1. For n > 0 and 0 < alpha < pi/3 ... " + _L31_PRINTED[_it], _fn, f"Lemma 3.1 ({_it})",
                     objects=_TR if _it in ("i", "ii", "iii", "iv") else _HY, params=("alpha", "omega"),
                     location="Sect. 3.3", command=_cmd,
                     note=("printed with c' (cosh) where the proof pattern of (ii) gives c (cos)" if _it == "iii" else
                           "printed with c (cos) where the pattern gives c' (cosh)" if _it == "vii" else None)))
for _it in ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii"):
    if _it in _DEF2:
        _fn = functools.partial(_identity_item, *_DEF2[_it])
        _cmd = None
    else:
        _fn = functools.partial(_lemma32, _it)
        _cmd = f"subdiv bound --claim '003:Lemma3.2({_it})' --box alpha=1/100,pi/3 --param omega=1/100"
    CLAIMS.append(_c(f"003:Lemma3.2({_it})", "identity" if _it in _DEF2 else "inequality",
                     "Lemma 3.2. For the constants C_i, i = 1, ..., 4, independent of n, the following inequalities "
                     "hold: ... " + _L32_PRINTED[_it] + (" ... where C_1 = \\frac{3}{8} \\frac{\\alpha^2}{c(\\alpha)}, "
                                                          "this proves (ii)." if _it == "ii" else ""),
                     _fn, f"Lemma 3.2 ({_it})", objects=_TR if _it in ("i", "ii", "iii", "iv") else _HY,
                     params=("alpha", "omega"), location="Sect. 3.3", command=_cmd,
                     reading=(None if _it in _DEF2 else "for all n >= 0 and 0 < alpha < pi/3 (the range of Lemma 3.1); "
                              "C_2..C_4 are not printed: the constants the paper's method gives are checked"),
                     note=("the proof says 'inequality (i) can be proved by taking ...' and ends 'this proves (ii)': "
                           "it proves (ii)" if _it == "ii" else None)))
CLAIMS += [
    _c("003:Lemma3.3", "factorization", "The symbol d^n(z) corresponding to the n^{th} level of the non-stationary "
       "subdivision scheme {S_{d^n}} can be written in the form of d^n(z) = (\\frac{1+z}{2}) e^n(z) where e^n(z) = "
       "2{beta_3^n z^{-4} + (beta_0^n - beta_3^n)z^{-3} - (beta_0^n - beta_2^n - beta_3^n)z^{-2} + (beta_0^n - beta_2^n "
       "+ beta_1^n - beta_3^n)z^{-1} + (-beta_0^n + beta_3^n + beta_2^n) + (beta_0^n - beta_3^n)z + beta_3^n z^2}",
       lambda: _factorization(TRIGONOMETRIC, BETA, "Lemma 3.3"), "Factorization of the trigonometric symbol",
       objects=_TR, location="Sect. 3.3"),
    _c("003:Corollary3.1", "factorization", "The symbol d^m(z) corresponding to the n^{th} level of the non-stationary "
       "scheme {S_{d^m}} can be written in the form of d^m(z) = (\\frac{1+z}{2}) e^m(z) where e^m(z) = 2{gamma_3^n z^{-4} "
       "+ ... + gamma_3^n z^2}.", lambda: _factorization(HYPERBOLIC, GAMMA, "Corollary 3.1"),
       "Factorization of the hyperbolic symbol", objects=_HY, location="Sect. 3.3",
       reading="as Lemma 3.3 with gamma for beta ('d^m' is the hyperbolic symbol, not a power)"),
    _c("003:Lemma3.4(d)", "identity", "The stationary subdivision scheme S_d associated with the symbol d(z) = 2{5omega "
       "z^{-4} + 2omega z^{-3} - \\frac{1}{4}(1 + 20omega)z^{-2} + \\frac{1}{2}(-1 - 8omega)z^{-1} + \\frac{1}{4}(-1 - "
       "20omega) + 2omega z + 5omega z^2}", _lemma34_d, "Lemma 3.4: the symbol d(z)", objects=_ST,
       reading="d is meant as the limit of the e^n of Lemma 3.3 (the schemes are 'compared with S_d')",
       location="Sect. 3.3"),
    _c("003:Lemma3.4", "smoothness", "[S_d] is C^2 for the range omega in ]0, \\frac{\\sqrt{6}-1}{80}[.", _lemma34_c2,
       "Lemma 3.4: S_d is C^2", objects=_ST, params=("omega",), location="Sect. 3.3",
       command="subdiv factor --symbol '2*(-5*omega*z**-4-2*omega*z**-3+(1+20*omega)/4*z**-2+(1+8*omega)/2*z**-1"
               "+(1+20*omega)/4-2*omega*z-5*omega*z**2)' && subdiv norm --scheme dfh-chaikin-perturbation --m 3 --L 2 "
               "--solve omega --within 0,oo"),
    _c("003:Theorem3.1(equivalence)", "series convergence", "The non-stationary subdivision scheme defined in (2) is "
       "asymptotically equivalent to the stationary scheme (1).",
       lambda: _theorem31_equivalence(TRIGONOMETRIC, "(2)"), "Theorem 3.1: asymptotic equivalence", objects=_TR + _ST,
       params=("alpha", "omega"), location="Sect. 3.3",
       command="subdiv series --scheme seed003-trigonometric --box alpha=0,pi/3 --param omega=1/100 --m 0"),
    _c("003:Theorem3.1", "smoothness", "Hence, it generates C^2 limit curves.",
       lambda: _theorem31_c2(TRIGONOMETRIC, "(2)"), "Theorem 3.1: (2) is C^2", objects=_TR, params=("alpha", "omega"),
       reading="for 0 < alpha < pi/3 and 0 < omega < (sqrt6-1)/80 (the ranges of Lemma 3.1 and Lemma 3.4)",
       location="Sect. 3.3",
       command="subdiv series --scheme seed003-trigonometric --box alpha=1/100,pi/3 --param omega=1/100 --m 1 "
               "--difference 1"),
    _c("003:Theorem3.1(proof)", "series convergence", "Proof. sum_{n=0}^{oo} 2^n ||S_{d^n} - S_d||_oo < oo where ... "
       "= |beta_0^n + 7omega| + |beta_1^n - 3/4 - 9omega| + |beta_2^n - 1/2 - 3omega| + |beta_3^n + 5omega| ... and hence "
       "{S_{d^n}} is C^1 and the scheme (2) is C^2.", _theorem31_proof, "Theorem 3.1: the printed proof",
       objects=_TR, params=("alpha", "omega"), location="Sect. 3.3",
       command="subdiv series --scheme seed003-trigonometric --param alpha=pi/5 --param omega=1/100 --m 1,2 && "
               "subdiv series --scheme seed003-trigonometric --box alpha=0,pi/3 --param omega=1/100 --m 1 --difference 1"),
    _c("003:Corollary3.2", "smoothness", "The hyperbolic form of the Chaikin's perturbation scheme defined in (3) is C^2.",
       lambda: _theorem31_c2(HYPERBOLIC, "(3)"), "Corollary 3.2: (3) is C^2", objects=_HY, params=("alpha", "omega"),
       reading="for 0 < alpha < pi/3 and 0 < omega < (sqrt6-1)/80; no proof is printed (same route as Theorem 3.1, "
               "with the same flaw)", location="Sect. 3.3",
       command="subdiv series --scheme seed003-hyperbolic --box alpha=1/100,pi/3 --param omega=1/100 --m 1 --difference 1"),
    _c("003:Corollary3.2(equivalence)", "series convergence", "[(3) is asymptotically equivalent to (1): implicit in "
       "Corollary 3.2]", lambda: _theorem31_equivalence(HYPERBOLIC, "(3)"), "Corollary 3.2: asymptotic equivalence",
       objects=_HY + _ST, params=("alpha", "omega"), location="Sect. 3.3",
       command="subdiv series --scheme seed003-hyperbolic --box alpha=0,pi/3 --param omega=1/100 --m 0"),
    _c("003:Sec4(beta^n)", "identity", "beta^n = sum_{i=0}^3 beta_i^n = \\frac{c(\\frac{alpha}{2^{n+2}})}"
       "{c(\\frac{alpha}{2^{n+1}})}", lambda: _sum_identity(TRIGONOMETRIC, BETA_SUM, "(2)"), "Sum of the mask of (2)",
       objects=_TR, location="Sect. 4"),
    _c("003:Sec4(gamma^n)", "identity", "gamma^n = sum_{i=0}^3 gamma_i^n = \\frac{c'(\\frac{alpha}{2^{n+2}})}"
       "{c'(\\frac{alpha}{2^{n+1}})}", lambda: _sum_identity(HYPERBOLIC, GAMMA_SUM, "(3)"), "Sum of the mask of (3)",
       objects=_HY, location="Sect. 4"),
    _c("003:Sec4(constants)", "reproduction", "Moreover, the normalized schemes reproduce the function f(x) = 1 because "
       "sum_{i=0}^3 beta_i^n = 1 and sum_{i=0}^3 gamma_i^n = 1.", _normalized_constants,
       "Normalized schemes reproduce constants", objects=("seed003-trigonometric-normalized",
                                                          "seed003-hyperbolic-normalized"), location="Sect. 4",
       reading="the beta_i^n, gamma_i^n here are the normalized ones (the print reuses the names)",
       command="subdiv reproduce --scheme seed003-trigonometric-normalized --lambdas 0 --param alpha=pi/5 "
               "--param omega=1/100"),
    _c("003:Sec4(convergence)", "smoothness", "The convergence analysis of the normalized schemes is similar as in "
       "Section 3.", _normalized_convergence, "Normalized schemes: same analysis",
       objects=("seed003-trigonometric-normalized", "seed003-hyperbolic-normalized"), location="Sect. 4",
       reading="(4) and (5) are C^2 like (2) and (3)",
       command="subdiv series --scheme seed003-trigonometric-normalized --param alpha=pi/5 --param omega=1/100 --m 1 "
               "--difference 1"),
    _c("003:(7)", "identity", "It is easy to check that restriction of L to D_k satisfies L(\\frac{j}{2^k}) = f_j^k, "
       "forall j. (7)", _eq7, "Equation (7): L on dyadic points", objects=_TR, location="Sect. 5"),
    _c("003:Theorem5.1", "symmetry", "The basic limit function L of the scheme (2) is symmetric about the Y-axis.",
       _theorem51, "Theorem 5.1: symmetry of the basic limit function", objects=_TR, location="Sect. 5",
       reading="L(t) = L(-t) for all t, with L(j/2^k) ~ f_j^k as in (7) and Definition 1.2",
       command="subdiv symbol --scheme dfh-chaikin-perturbation"),
    _c("003:Sec6-7(circles,ellipses)", "reproduction", "the trigonometric form is more efficient in the reproduction of "
       "circles and ellipses [Abstract]; ... the proposed trigonometric form is more suitable in the construction of "
       "circles and ellipses as compared to the proposed hyperbolic form and the scheme [11]. [Sect. 6; again Sect. 7]",
       _sec6_conics, "Circles and ellipses: trigonometric form best",
       objects=("seed003-trigonometric-normalized", "seed003-hyperbolic-normalized", "seed003-jena-11"),
       params=("alpha", "omega"), location="Abstract, Sect. 6, Sect. 7",
       reading="measured as the radial deviation of the limit curve from 10 control points on the curve",
       note="the paper compares curvature plots by eye with unstated omega; [11] is not printed and is reconstructed "
            "(see schemes.seed003.JENA_11)",
       command="subdiv reproduce --scheme seed003-trigonometric-normalized --param alpha=pi/5 --param omega=1/100 "
               "--curve circle --points 10 --steps 6"),
    _c("003:Sec6-7(cardioid,astroid,lemniscate)", "reproduction", "the cardioid, astroid and lemniscate constructed using "
       "the proposed hyperbolic form are more close to the corresponding standard curves. Therefore, it can be said that "
       "the proposed hyperbolic form is more suitable in the construction of astroid and lemniscate than the proposed "
       "trigonometric form and the scheme [11]. [Sect. 6; Sect. 7: hyperbolic form is more precise in the reproduction "
       "of cardioid, astroid and lemniscate]", _sec6_analytic, "Cardioid, astroid, lemniscate: hyperbolic form best",
       objects=("seed003-trigonometric-normalized", "seed003-hyperbolic-normalized", "seed003-jena-11"),
       params=("alpha", "omega"), location="Sect. 6, Sect. 7",
       reading="measured as the discrete Hausdorff distance of the refined polygon to the exact curve",
       note="cardioid a = 1/2, astroid b = 2 (alpha = pi/5, Fig. 4), lemniscate a = 2 (alpha = 3pi/20, Fig. 5)",
       command="subdiv reproduce --scheme seed003-hyperbolic-normalized --param alpha=pi/5 --param omega=1/100 "
               "--curve astroid --points 10 --steps 6"),
]

PAPER = C.Paper(
    id="003",
    title="Chaikin's perturbation subdivision scheme in non-stationary forms",
    citation=_SOURCE,
    claims=CLAIMS,
    source="shared/seeds/003_497e1d19b122b5d7.txt",
    notes=("Not checked: Definitions 1.1-1.3 and Theorem 1.1 are quoted results (Daniel-Shunmugaraj; Dyn-Levin 1995); "
           "the claims model has no 'cited theorem' kind, so they are not entered as claims. Definition 1.1's rule and "
           "Definition 1.3's norm are exactly our conventions ((S_a f)_i = sum_j a_{i-2j} f_j, ||S_a|| = max over the "
           "two residues), and Theorem 1.1 is the theorem analysis.levels.series.smoothness applies (its hypotheses are "
           "checked there). Statements are quoted from the extracted LaTeX. Notation: beta_i^n, gamma_i^n are the "
           "coefficients of (2), (3); a = rule (1); e^n = 2 d^n/(1+z) (Lemma 3.3); omega* ≈ 0.0214640075 is the certified "
           "right boundary of the C^2 grid verdicts of rule (1) near 0 (see claim 003:Sec2(C2) for what is proven "
           "and what is sampled)."),
)
