"""Seed 004: *Modeling of curves by a design-control approximating refinement scheme*
(Taylor & Francis, pp. 164-178, received 22 Apr 2022, published online 28 Mar 2023).

The paper's checkable claims: ``PAPER`` (``subdiv report 004``). Its schemes, the 6-point
scheme (3.6) and the sub-schemes (3.7), (3.8), with the printed rules (3.1)-(3.8), are catalogue
entries (:mod:`schemes.seed004`). Here:

* :mod:`.transcription` — the garbled printed text (lost minus signs and fraction bars);
* :mod:`.derivations` — the construction Steps 1-4, the boundary rules, exact parameter sets;
* :mod:`.figures` — basic limit functions, norm curves, the Gibbs experiment;
* the evaluators by section: :mod:`.claims_sec2_3` (sum rules, construction, sub-schemes,
  boundary rules), :mod:`.claims_sec4_5` (supports, eigenvalues, C^k ranges),
  :mod:`.claims_sec6_7` (Gibbs, C^6);
* below, the claims in the paper's order. Every claim keeps the statement as printed; the reading
  says how it was restored. Verdicts come from the engine, never typed in.

Examples
--------
>>> from papers.seed004 import PAPER
>>> PAPER.id, len(PAPER.claims)
('004', 47)
>>> PAPER.claim("004:(3.6)").kind
'mask identity'
"""

from __future__ import annotations

import functools

import sympy as sp

from analysis import claims as C
from schemes.seed004 import _SOURCE, L_3_8, MU, NU, OMEGA, SUBSTITUTION_3_7, SUBSTITUTION_3_8, T_3_7

from .claims_sec2_3 import (_displacements, _end_rule, _matrix_3_6, _parents, _remark_3_2, _remark_3_3, _rule_3_2,
                            _rule_3_6, _subscheme, _sum_rules, _symmetry)
from .claims_sec4_5 import (_eigen_l, _eigen_t, _ineq_5_6, _ineq_5_7, _ineq_5_8, _ineq_5_9, _lemma_steps, _support,
                            _table, _thm51_convergence, _thm51_necessary, _thm52, _thm53, _thm54)
from .claims_sec6_7 import _c6, _thm61, _thm62
from .transcription import (_END_STATEMENT, _PRINTED_3_3, _PRINTED_3_4, _PRINTED_3_7, _PRINTED_3_8, _SIGNS_LOST,
                            PRINTED_END_RULES)


# -------------------------------------------------------------------------- the claims
_CMD = "subdiv report 004 --claim '{}'"


def _c(cid, kind, statement, fn, title, *, reading=None, note=None, objects=(), params=(), command=None,
       location=""):
    return C.Claim(id=cid, kind=kind, statement=statement, evaluate=fn, title=title, reading=reading,
                   reading_note=note, objects=objects, params=params,
                   command=command or _CMD.format(cid), location=location)


_ALL3 = ("seed004-design-control", "seed004-t-nu", "seed004-l-mu")

CLAIMS = [
    _c("004:(2.2)-(2.3)", "sum rules",
       "(2.2) jZa2j=1,jZa2j+1=1. ... (2.3) a(1)=2 and a(1)=0.", _sum_rules,
       "The schemes satisfy the necessary conditions for convergence",
       reading="sum_j a_{2j} = sum_j a_{2j+1} = 1, i.e. a(1) = 2 and a(-1) = 0, for (3.6), (3.7), (3.8)",
       note=_SIGNS_LOST + "'a(1)=0' is a(-1) = 0.", objects=_ALL3, location="Sect. 2",
       command="subdiv symbol --scheme seed004-design-control"),
    _c("004:(3.2)", "mask identity", "the 4-point approximating B-spline refinement scheme which is constructed "
       "by B-spline basis function of degree-6 is (3.2) R2ik+1=764Pi1k+3564Pik+2164Pi+1k+164Pi+2k, ...",
       _rule_3_2, "R is the degree-6 B-spline scheme", objects=("bspline-6",), location="Sect. 3.1",
       command="subdiv symbol --scheme bspline-6"),
    _c("004:(3.3)", "identity", "D2ik+1=Q2ik+1R2ik+1 ... (3.3) {D2ik+1=21128Pi1k+35128Pik7128Pi+1k7128Pi+2k, "
       "D2i+1k+1=7128Pi1k7128Pik+35128Pi+1k21128Pi+2k.",
       lambda: _displacements(_PRINTED_3_3, "(3.3)"), "Displacement vectors D = Q - R",
       reading="D_{2i} = (-21 P_{i-1} + 35 P_i - 7 P_{i+1} - 7 P_{i+2})/128, "
               "D_{2i+1} = (-7 P_{i-1} - 7 P_i + 35 P_{i+1} - 21 P_{i+2})/128",
       note=_SIGNS_LOST + "signs as derived from (3.1) - (3.2).", location="Sect. 3.2"),
    _c("004:(3.4)", "identity", "(3.4) {D2i2k+1=21128Pi2k+35128Pi1k7128Pik7128Pi+1k, D2i1k+1=..., "
       "D2i+2k+1=..., D2i+3k+1=7128Pik7128Pi+1k+35128Pi+2k21128Pi+3k.",
       lambda: _displacements(_PRINTED_3_4, "(3.4)"), "Shifted displacement vectors",
       note=_SIGNS_LOST + "the shifts of (3.3).", location="Sect. 3.2"),
    _c("004:(3.6)", "mask identity", "P2ik+1=Q2ik+1QE ... (3.6) {P2ik+1=a5Pi2k+a3Pi1k+a1Pik+a1Pi+1k+a3Pi+2k+"
       "a5Pi+3k, P2i+1k+1=a6Pi2k+a4Pi1k+a2Pik+a0Pi+1k+a2Pi+2k+a4Pi+3k, where, a5=a4=21128μ, "
       "a3=a2=712835128μ+21128ν, a1=a0=105128+7128μ35128ν+21128ω, a1=a2=35128+7128μ+7128ν35128ω, "
       "a3=a4=5128+7128ν+7128ω, a5=a6=7128ω.", _rule_3_6,
       "The 6-point rule (3.6) follows from the construction Steps 1-4",
       reading="P_{2i} = Q_{2i} - DE with a_5 = a_-4 = 21mu/128, a_3 = a_-2 = (-7 - 35mu + 21nu)/128, "
               "a_1 = a_0 = (105 + 7mu - 35nu + 21omega)/128, a_-1 = a_2 = (35 + 7mu + 7nu - 35omega)/128, "
               "a_-3 = a_4 = (-5 + 7nu + 7omega)/128, a_-5 = a_6 = 7omega/128",
       note=_SIGNS_LOST + "'Q2ik+1QE' is Q_{2i} - DE (the minus is confirmed by the paper's own numbers: "
            "nu = 1 must give the B-spline R, and Theorem 5.1's eigenvalue 9/64 - 7nu/64 and range 5/7 < nu "
            "< 13/7 need it); labels a_k with lost minus signs are read from the pattern a_k = a_{1-k}.",
       objects=("seed004-design-control",), params=("mu", "nu", "omega"), location="Sect. 3.3-3.4"),
    _c("004:(3.6)matrix", "identity", "... =(a5a3a1a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a50000a6a4a2a0a2a4"
       "00000a5a3a1a1a3a50000a6a4a2a0a2a400000a5a3a2a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a50000a6a4a2a0a2a4)",
       _matrix_3_6, "The 10x10 matrix form of (3.6)",
       note="Labels without their minus signs; rows read with the pattern of (3.6).",
       objects=("seed004-design-control",), location="Sect. 3.4",
       command="subdiv matrices --scheme seed004-design-control"),
    _c("004:(3.7)", "mask identity", "We set μ=ω=0 in Equation(3.6) ... t3=t2=7128+21128ν, t1=t0=10512835128ν, "
       "t1=t2=35128+7128ν, t3=t4=5128+7128ν.",
       lambda: _subscheme(_PRINTED_3_7, T_3_7, SUBSTITUTION_3_7, "seed004-t-nu", "t"),
       "Sub-scheme S_t,nu", reading="t_3 = t_-2 = (-7 + 21nu)/128, t_1 = t_0 = (105 - 35nu)/128, "
       "t_-1 = t_2 = (35 + 7nu)/128, t_-3 = t_4 = (-5 + 7nu)/128", note=_SIGNS_LOST,
       objects=("seed004-t-nu",), params=("nu",), location="Sect. 3.5"),
    _c("004:Remark3.2", "identity", "For the scheme St,ν, the vectors defined in Equation(3.5) reduce to "
       "QE=νD2ik+1 and DO=νD2i+1k+1.", _remark_3_2, "Resultant vectors of S_t,nu", location="Sect. 3.5"),
    _c("004:(3.8)", "mask identity", "We set μ=ω and ν=2μ+1 in Equation(3.6) ... 5=4=21128μ, 3=2=76477128μ, "
       "1=0=3564+4964μ,1=2=21642164μ, 3=4=1647128μ, 5=6=7128μ",
       lambda: _subscheme(_PRINTED_3_8, L_3_8, SUBSTITUTION_3_8, "seed004-l-mu", "l"),
       "Sub-scheme S_l,mu", reading="omega = mu, nu = 1 - 2mu: l_5 = 21mu/128, l_3 = 7/64 - 77mu/128, "
       "l_1 = 35/64 + 49mu/64, l_-1 = 21/64 - 21mu/64, l_-3 = 1/64 - 7mu/128, l_-5 = 7mu/128",
       note=_SIGNS_LOST + "'ν=2μ+1' is nu = -2mu + 1 (Corollary 4.6 prints 'ν=12μ', i.e. 1 - 2mu); the "
            "letter l (ℓ) of the coefficients was lost.",
       objects=("seed004-l-mu",), params=("mu",), location="Sect. 3.6"),
    _c("004:Remark3.3", "identity", "QE=D2ik+1+μ[(D2i2k+1D2ik+1)+(D2i+2k+1D2ik+1)], "
       "DO=D2i+1k+1+μ[(D2i1k+1D2i+1k+1)+(D2i+3k+1D2i+1k+1)].", _remark_3_3, "Resultant vectors of S_l,mu",
       reading="DE = D_{2i} + mu[(D_{2i-2} - D_{2i}) + (D_{2i+2} - D_{2i})], and the odd analogue",
       note=_SIGNS_LOST, location="Sect. 3.6"),
    _c("004:Sec1(parents)", "identity", "it contains the geometric behavior of both parent schemes as those are "
       "the special cases of the new design-control scheme.", _parents, "The parent schemes are special cases",
       location="Sect. 1"),
    _c("004:symmetry", "symmetry", "a5=a4, a3=a2, a1=a0, a1=a2, a3=a4, a5=a6 (Sect. 3.4); t3=t2, ... (3.7); "
       "5=4, ... (3.8)", _symmetry, "The masks are symmetric",
       reading="a_k = a_{1-k} (paper labels): a_i = a_{-1-i} in ours", note=_SIGNS_LOST, objects=_ALL3,
       command="subdiv symbol --scheme seed004-design-control"),
]

for _lab in PRINTED_END_RULES:
    CLAIMS.append(_c(f"004:(3.9)-(3.10)/{_lab}", "end rules", _END_STATEMENT[_lab],
                     functools.partial(_end_rule, _lab), f"Boundary rule for {_lab}^(k+1)",
                     reading=None,
                     note=_SIGNS_LOST + "each coefficient is read as its terms with a lost '-' wherever two terms "
                          "touch without an operator; the sign of the first term is the one the derivation "
                          "matches (the table shows both). Ghost points P_-m = 2P_0 - P_m (m = 1, 2), "
                          "P_(n+m) = 2P_n - P_(n-m) (m = 1, 2, 3), substituted into (3.6).",
                     objects=("seed004-design-control",), location="Sect. 3.7"))

CLAIMS += [
    _c("004:Lemma4.1", "support", "after first subdivision step the non-zero points are P61, P51, , P41, P51.",
       lambda: _lemma_steps(1), "Nonzero points after one step", reading="P_-6^1, P_-5^1, ..., P_4^1, P_5^1",
       note=_SIGNS_LOST, location="Sect. 4", command="subdiv matrices --scheme seed004-design-control"),
    _c("004:Lemma4.2", "support", "after second subdivision step, the non-zero points are P182, P172, , P142, P152.",
       lambda: _lemma_steps(2), "Nonzero points after two steps", reading="P_-18^2 .. P_15^2", note=_SIGNS_LOST,
       location="Sect. 4"),
    _c("004:Lemma4.3", "support", "after third subdivision step, the non-zero points are P423, P413, , P343, P353.",
       lambda: _lemma_steps(3), "Nonzero points after three steps", reading="P_-42^3 .. P_35^3", note=_SIGNS_LOST,
       location="Sect. 4"),
    _c("004:Theorem4.4", "support", "The support width of our binary refinement scheme Sa,μ,ν,ω defined in "
       "Equation(3.6) is 11. So, it vanishes outside the closed interval [−5.5,5.5].",
       lambda: _support("seed004-design-control", 11, "S_a,mu,nu,omega",
                        [("(mu,nu,omega) = (1/10, 6/5, 1/10)", {MU: sp.Rational(1, 10), NU: sp.Rational(6, 5),
                                                                OMEGA: sp.Rational(1, 10)}),
                         ("(0, 1, 0): B-spline", {MU: 0, NU: 1, OMEGA: 0}),
                         ("(-1/56, 29/28, -1/56): C^7 member", {MU: sp.Rational(-1, 56), NU: sp.Rational(29, 28),
                                                               OMEGA: sp.Rational(-1, 56)})]),
       "Support width 11", objects=("seed004-design-control",), location="Sect. 4",
       command="subdiv matrices --scheme seed004-design-control"),
    _c("004:Corollary4.5", "support", "The support width of our refinement scheme St,ν is 7. So, it vanishes "
       "outside the closed interval [−3.5, 3.5].",
       lambda: _support("seed004-t-nu", 7, "S_t,nu", [("nu = 5/7", {NU: sp.Rational(5, 7)}), ("nu = 1", {NU: 1}),
                                                      ("nu = 13/7", {NU: sp.Rational(13, 7)})]),
       "Support width 7 of S_t,nu", objects=("seed004-t-nu",), location="Sect. 4",
       command="subdiv matrices --scheme seed004-t-nu"),
    _c("004:Corollary4.6", "support", "The support width of our refinement scheme S,μ is 11. So, it vanishes "
       "outside the closed interval [−5.5, 5.5].",
       lambda: _support("seed004-l-mu", 11, "S_l,mu", [("mu = -1/56", {MU: sp.Rational(-1, 56)}), ("mu = 0", {MU: 0}),
                                                       ("mu = 1/100", {MU: sp.Rational(1, 100)})]),
       "Support width 11 of S_l,mu", objects=("seed004-l-mu",), location="Sect. 4",
       command="subdiv matrices --scheme seed004-l-mu"),
    _c("004:Sec7(support)", "support", "The support width of our scheme is 11 and its support region is "
       "[5.5,5.5].", lambda: _support("seed004-design-control", 11, "S_a,mu,nu,omega", []),
       "Summary: support", reading="[-5.5, 5.5]", note=_SIGNS_LOST, location="Sect. 7",
       command="subdiv matrices --scheme seed004-design-control"),
    _c("004:Theorem5.1(eigenvalues)", "eigenvalues", "the eigenvalues of the subdivision matrix T are: λ0=1,"
       "λ1=12,λ2=14,λ3=18,λ4=116,λ5=964764ν.", _eigen_t, "Eigenvalues of S_t,nu",
       reading="1, 1/2, 1/4, 1/8, 1/16, 9/64 - 7nu/64", note=_SIGNS_LOST + "fraction bars restored.",
       objects=("seed004-t-nu",), location="Sect. 5.1", command="subdiv matrices --scheme seed004-t-nu"),
    _c("004:Theorem5.1", "necessary condition", "The refinement scheme Equation(3.7) satisfies the necessary "
       "conditions for C2 continuity if the range of the tension parameter is 0.7142857143<ν<1.857142857.",
       _thm51_necessary, "Necessary conditions for C^2 of S_t,nu", reading="5/7 < nu < 13/7",
       objects=("seed004-t-nu",), params=("nu",), location="Sect. 5.1",
       command="subdiv matrices --scheme seed004-t-nu"),
    _c("004:Theorem5.1(convergence)", "convergence", "Which, implies that the given scheme is convergent in this "
       "interval 0.7142857143<ν<1.857142857.", _thm51_convergence, "Convergence of S_t,nu on the range",
       objects=("seed004-t-nu",), location="Sect. 5.1 (proof)",
       command="subdiv norm --scheme seed004-t-nu --m 1 --L 1 --solve nu"),
]
for _m in (1, 2, 3):
    CLAIMS.append(_c(f"004:Theorem5.2(m={_m})", "norm test",
                     "The binary refinement scheme Equation(3.7) satisfies the sufficient conditions of "
                     "C2-continuity for 0.7142857143<ν<1.857142857. [proof, m = %d: ... the scheme is C%d-continuous "
                     "for 0.7142857143<ν<1.857142857]" % (_m, _m - 1),
                     functools.partial(_thm52, _m), f"Norm test, m = {_m}, L = 1: C^{_m - 1}",
                     reading=f"||1/2 S_(t_{_m})||_inf < 1 for 5/7 < nu < 13/7, hence C^{_m - 1}",
                     note="The printed b_m^1(z) are read with the lost signs restored (see evidence).",
                     objects=("seed004-t-nu",), params=("nu",), location="Sect. 5.1",
                     command=f"subdiv norm --scheme seed004-t-nu --m {_m} --L 1,2,3 --solve nu"))
CLAIMS += [
    _c("004:Table1", "smoothness", "Table 1. The order of smoothness of the refinement scheme St,ν for specific "
       "range of parameter.", lambda: _table(1), "Table 1 (smoothness of S_t,nu)", location="Sect. 5.1"),
    _c("004:Theorem5.3(eigenvalues)", "eigenvalues", "λ0=1,λ1=12,λ2=14,λ3=18,λ4=116,λ5=132,λ6=164,λ6=164,"
       "λ7=732μ,λ8=7128μ+1128+1128833μ2+70μ+1,λ9=7128μ+11281128833μ2+70μ+1.", _eigen_l,
       "Eigenvalues of S_l,mu", reading="1, 1/2, 1/4, 1/8, 1/16, 1/32, 1/64, 1/64, ±7mu/32, "
       "(7mu + 1 ± sqrt(833mu^2 + 70mu + 1))/128", note=_SIGNS_LOST + "the sign of 7mu/32 cannot be read.",
       objects=("seed004-l-mu",), location="Sect. 5.2", command="subdiv matrices --scheme seed004-l-mu"),
    _c("004:(5.6)", "inequality", "Let |164|>|732μ|. This implies that 114<μ<114. Thus, we have (5.6) "
       "0.071429<μ<0.071429.", _ineq_5_6, "Inequality (5.6)", reading="-1/14 < mu < 1/14", note=_SIGNS_LOST,
       objects=("seed004-l-mu",), location="Sect. 5.2"),
    _c("004:(5.7)", "inequality", "Let, |732μ|>|7128μ+1128+1128833μ2+70μ+1|. This, implies that "
       "1.290803377<μ<0.06578510188 and0.01824851156<μ<0.7193748053. By combining the above we get result as: "
       "(5.7) 1.290803377<μ<0.7193748053.", _ineq_5_7, "Inequality (5.7)",
       reading="-1.290803377 < mu < -0.06578510188 and -0.01824851156 < mu < 0.7193748053; combined "
               "-1.290803377 < mu < 0.7193748053",
       note=_SIGNS_LOST + "0.06578510188 and 0.01824851156 are (up to sign) the roots of 833mu^2 + 70mu + 1, "
            "which are negative: -0.0657851 and -0.0182485.", objects=("seed004-l-mu",), location="Sect. 5.2"),
    _c("004:(5.8)", "inequality", "Let, |7128μ+1128+1128833μ2+70μ+1|>|7128μ+11281128833μ2+70μ+1|. This, implies "
       "that 0.1428571429<μ<0.06578510188 and 0.01824851156<μ. By combining above we get the result (5.8) "
       "0.1428571429<μ<0.06578510188.", _ineq_5_8, "Inequality (5.8)",
       reading="-1/7 < mu < -0.06578510188 and -0.01824851156 < mu; combined: -1/7 < mu < ±0.06578510188",
       note=_SIGNS_LOST, objects=("seed004-l-mu",), location="Sect. 5.2"),
    _c("004:(5.9)", "inequality", "If we take the common part of all inequalities Equation(5.6), Equation(5.7) "
       "and Equation(5.8), we get the following common interval (5.9) 0.1428571429<μ<0.06578510188.",
       _ineq_5_9, "Inequality (5.9): the common part", reading="-1/7 < mu < 0.06578510188", note=_SIGNS_LOST,
       objects=("seed004-l-mu",), location="Sect. 5.2"),
    _c("004:Theorem5.3", "necessary condition", "The refinement scheme Equation(3.8) satisfies the necessary "
       "conditions for C2 continuity if the range of the tension parameter is 0.1428571429<μ<0.06578510188.",
       _thm53, "Necessary conditions for C^2 of S_l,mu",
       reading="-1/7 < mu < 0.06578510188 (or < -0.06578510188: the sign is lost)", note=_SIGNS_LOST,
       objects=("seed004-l-mu",), params=("mu",), location="Sect. 5.2",
       command="subdiv matrices --scheme seed004-l-mu"),
    _c("004:Theorem5.4", "norm test", "The refinement scheme Equation(3.8) satisfies the sufficient conditions "
       "for C2-smoothness for 0.1071428571<μ<0.01824851156.", _thm54, "C^2 of S_l,mu by the norm test",
       reading="-3/28 < mu < 0.01824851156 (the sign of the upper end is lost; both readings are checked)",
       note=_SIGNS_LOST, objects=("seed004-l-mu",), params=("mu",), location="Sect. 5.2",
       command="subdiv norm --scheme seed004-l-mu --m 3 --L 1,2,3 --solve mu"),
    _c("004:Table2", "smoothness", "Table 2. The order of smoothness of the refinement scheme S,μ for specific "
       "range of parameter.", lambda: _table(2), "Table 2 (smoothness of S_l,mu)", location="Sect. 5.2"),
    _c("004:Sec7(C6)", "smoothness", "Our refinement scheme produces limiting curves up to C6 smoothness.", _c6,
       "Maximal smoothness of the family", reading="the smoothest members of S_a,mu,nu,omega are C^6",
       objects=("seed004-design-control",), location="Sect. 7",
       command="subdiv factor --scheme seed004-design-control && subdiv norm --scheme seed004-design-control "
               "--param mu=-1/56 --param nu=29/28 --param omega=-1/56 --m 8 --L 1"),
    _c("004:Theorem6.1", "gibbs condition", "The binary approximating refinement scheme St,ν defined in "
       "Equation(3.7) does not produce Gibbs oscillation in the limiting curves for 0.7142857ν7.", _thm61,
       "No Gibbs oscillation for S_t,nu", reading="5/7 <= nu <= 7 (0.7142857 is 5/7 rounded)",
       note="'≤' signs lost; Theorem 2.3 (Amat-Ruiz-Trillo) as quoted needs zeta_l^[k](i) >= 0 for all i, k.",
       objects=("seed004-t-nu",), params=("nu",), location="Sect. 6"),
    _c("004:Theorem6.2", "gibbs condition", "The binary approximating refinement scheme S,μ defined in "
       "Equation(3.8) does not produce Gibbs oscillation in limiting shapes for μ=0.", _thm62,
       "No Gibbs oscillation for S_l,mu at mu = 0", objects=("seed004-l-mu",), location="Sect. 6"),
]

PAPER = C.Paper(
    id="004",
    title="Modeling of curves by a design-control approximating refinement scheme",
    citation=_SOURCE,
    claims=CLAIMS,
    source="shared/seeds/004_052f7c3c8bb611ef.txt",
    notes=("The text extraction lost minus signs and fraction bars; every claim keeps the printed text and "
           "says how it was read. Convention: (S_a f)_i = sum_j a_{i-2j} f_j; the paper's coefficient label k "
           "is our index k - 1."),
)
