"""Seed 001, the paper's claims as printed, and ``PAPER`` (evaluated by ``subdiv report 001``).

Each claim keeps the statement as printed (the extraction garbled sub/superscripts and fraction
bars); the reading says how it was read. The evaluators are in :mod:`papers.seed001.claims_sec1_3`
(Sects. 1-3) and :mod:`papers.seed001.examples` (Sect. 4, remarks).
"""

from __future__ import annotations

import functools

from analysis import claims as C

from .examples import (_v_algorithm_2, _v_fig2, _v_fig3_count, _v_locality, _v_remark_1,
                       _v_reproduction)
from .claims_sec1_3 import (_v_12, _v_16, _v_17, _v_19, _v_algorithm_1, _v_b_of_z, _v_chaikin,
                       _v_corollary_3_4, _v_equivalence, _v_lemma_2_1, _v_lemma_3_2, _v_lemma_3_3,
                       _v_mask_4, _v_positivity, _v_property_a_def, _v_rules, _v_special_cases,
                       _v_support, _v_theorem_3_5, _v_theorem_3_6)

_GARBLED = ("The text extraction flattened sub/superscripts and fraction bars (e.g. 'uk+12i' is "
            "u^{k+1}_{2i}); ")
_CMD = "subdiv report 001 --claim '{}'"


def _c(cid, kind, statement, fn, title, *, reading=None, note=None, objects=("nvps-d",), params=(), command=None,
       location=""):
    return C.Claim(id=cid, kind=kind, statement=statement, evaluate=fn, title=title, reading=reading,
                   reading_note=note, objects=objects, params=params, command=command or _CMD.format(cid),
                   location=location)


PAPER_CLAIMS = [
    _c("001:Abstract(special cases)", "identity",
       "Generalized subdivision and the classical B-spline subdivision are all special cases of the proposed variable "
       "parameter subdivision.", _v_special_cases, "B-spline and generalized subdivision are special cases",
       location="Abstract; Sect. 2.2", command="subdiv report 001 --claim '001:Abstract(special cases)'"),
    _c("001:(3)Chaikin", "identity", "When all the values of uji are 1, the above scheme becomes stationary and it is "
       "the well-known Chaikin’s algorithm.", _v_chaikin, "u = 1 is Chaikin's algorithm",
       reading="all u^k_j = 1", note=_GARBLED, location="Sect. 2.2",
       command="subdiv nonuniform refine --degree 2 --points '0,0;1,0;1,1;0,1' --u 1 --closed"),
    _c("001:(4)", "mask identity", "ak,j2 =n 1 2(1 + ukj), 1 + 2ukj 2(1 + ukk), 1 + 2ukj 2(1 + ukj), 1 2(1 + ukj)o. (4)",
       _v_mask_4, "The mask of the degree-2 NVPS",
       reading="a_2^{k,j} = {1/(2(1+u^k_j)), (1+2u^k_j)/(2(1+u^k_j)), (1+2u^k_j)/(2(1+u^k_j)), 1/(2(1+u^k_j))}",
       note=_GARBLED + "'ukk' in the second entry is read as u^k_j (typo); (9) repeats (4).", location="Sect. 2.2"),
    _c("001:Sect2.2(u>0)", "inequality", "Since u0n > 0, it is clear that ukn > 0 for every i ∈ Z.", _v_positivity,
       "Parameters stay positive", note=_GARBLED, location="Sect. 2.2"),
    _c("001:Lemma2.1", "convergence", "Then, ukn converges to 1, as k → ∞, uniformly in terms of n. Moreover, for any "
       "k ≥ 1, kUkk ≤ C max(1, kU0k). (5)", _v_lemma_2_1, "u^k -> 1 uniformly; ||U^k|| <= C max(1, ||U^0||)",
       reading="u^k_n -> 1 uniformly in n; ||U^k||_inf <= C max(1, ||U^0||_inf)", note=_GARBLED,
       location="Sect. 2.2", command="subdiv nonuniform lemma --u0-range 0.01,100"),
    _c("001:(6)", "identity", "the subdivision scheme Sd for higher degree d > 2 is defined recursively by (SdPk)i = 1 2 "
       "(Sd−1Pk)i + (Sd−1Pk)i+1 . (6) ... Certainly, the classical B-spline subdivision are special cases of the "
       "proposed subdivision.", _v_rules, "The degree-d rule (6); u = 1 is the uniform B-spline",
       reading="(S_d P)_i = ((S_{d-1}P)_i + (S_{d-1}P)_{i+1})/2", note=_GARBLED, location="Sect. 2.2",
       command="subdiv nonuniform compare-definitions --degree 4 --levels 3"),
    _c("001:Algorithm1", "identity", "Case 1: d is odd. u30 = u0, u32n−3 = un−1, u32i+1 = u32i+2 = ui+1, i = 0, · · · , "
       "n − 3, udj = ud−2j+1, j = 0, 1, . . . , 2n − d, d > 3 Case 1: d is even. udj = ud−2j+1, j = 0, 1, · · · , "
       "2n − d, d > 2;", _v_algorithm_1, "Algorithm 1: parameters of the new edges",
       reading="d odd: u^3_0 = u_0, u^3_{2n-3} = u_{n-1}, u^3_{2i+1} = u^3_{2i+2} = u_{i+1}; u^d_j = u^{d-2}_{j+1}; "
               "d even: u^d_j = u^{d-2}_{j+1}, u^2 from rule (2); then each inherited value is updated by (2)",
       note=_GARBLED + "the second 'Case 1' is Case 2. As printed step (3) assigns old values without the square "
            "root of (2); read literally the parameters of odd degrees would never change (then u^k does not tend "
            "to 1 and Lemma 2.1 would not apply), so the inherited values are read as updated by (2).",
       location="Sect. 2.2, Algorithm 1"),
    _c("001:(12)", "identity", "Ejk:= 2kkak,j2 − ak (11) = 2kmax 1 2(1 + ukj)− 1 4 , 1 + 2ukj 2(1 + ukj)− 3 4 = 2k−2 "
       "1 − ukj 1 + ukj . (12)", _v_12, "The distance (12)",
       reading="E^k_j = 2^k max(|1/(2(1+u)) - 1/4|, |(1+2u)/(2(1+u)) - 3/4|) = 2^(k-2) |1-u|/(1+u)", note=_GARBLED,
       location="Sect. 3.1, proof of Lemma 3.3"),
    _c("001:Sect3.1(equivalence)", "series convergence", "In this study, we shall see that the mask {ak,j} of the NVPS "
       "of degree d is asymptotically equivalent to the B-spline scheme of order d.", _v_equivalence,
       "Asymptotic equivalence to the B-spline", reading="sum_k sup_j ||a^{k,j} - a|| < oo, a the B-spline of degree d",
       location="Sect. 3.1", command="subdiv nonuniform decay --u0 0.5,3 --degree 4 --levels 10"),
    _c("001:Lemma3.2", "convergence", "Lemma 3.2 Assume that {ak,j} ∼ {˜ak,j} and the scheme defined by the masks "
       "{˜ak,j} is stable and C0, then the non-uniform scheme with the mask {ak,j} is also C0 and stable.",
       _v_lemma_3_2, "Cited: asymptotic equivalence transfers C^0 and stability", location="Sect. 3.1"),
    _c("001:Lemma3.3", "series convergence", "X k∈Z 2kmax j {kak,j2 − a2k} < ∞", _v_lemma_3_3,
       "Weighted series of the degree-2 masks", reading="sum_{k >= 0} 2^k max_j ||a_2^{k,j} - a_2|| < oo",
       note=_GARBLED + "'k ∈ Z' should be k >= 0.", location="Sect. 3.1"),
    _c("001:Corollary3.4", "inequality", "maxj {kak,j2 − a2k} < c2−k. with a constant c > 0 independent of k and j.",
       _v_corollary_3_4, "Decay of the degree-2 masks", reading="max_j ||a_2^{k,j} - a_2|| < c 2^-k",
       location="Sect. 3.1", command="subdiv nonuniform decay --u0 0.1,0.5,2,10 --degree 2 --levels 14"),
    _c("001:(13)-(14)", "necessary condition", "We say that the scheme S satisfies Property A of order m if dr dzrdj,ka "
       "(±1) = ¯o(2−k(m−r)), 0 ≤ r < m, (13) as k → ∞, where dj,km(z) ≡ m X i=0 (−1)i m i ! zipj−i,k(z). (14)",
       _v_property_a_def, "Property A (definition quoted from DLY 2014)",
       reading="d^r/dz^r d_m^{j,k}(±1) = o(2^{-k(m-r)}), 0 <= r < m, with d_m^{j,k}(z) = sum_i (-1)^i binom(m,i) z^i "
               "a^{j-i,k}(z)", note=_GARBLED, location="Sect. 3.2",
       command="subdiv nonuniform property-a --degree 4"),
    _c("001:Theorem3.5", "smoothness", "Theorem 3.5 Consider a non-uniform binary scheme S defined by masks {ak,j}, "
       "satisfying {ak,j} ∼ a, (15) where m is the mask of a stationary binary scheme Sa. Further assume that S "
       "satisfies Property A of orders 1 ≤ ℓ ≤ m. If Sa is a Cm scheme with a stable basic limit function, then also "
       "S is a Cm scheme.", _v_theorem_3_5, "Cited: smoothness transfer (DLY 2014)", location="Sect. 3.2"),
    _c("001:(16)", "factorization", "ak,jd (z) :=z + 1 2 d−2 ak,j2 (z). (16)", _v_16,
       "The degree-d symbol factorizes", reading="a_d^{k,j}(z) = ((z+1)/2)^{d-2} a_2^{k,j}(z) (as the symbol of (6))",
       note=_GARBLED, location="Sect. 3.3", command="subdiv report 001 --claim '001:(16)'"),
    _c("001:(17)", "identity", "ak,j2 (1) = 1, d dzak,j2 (1) = 2, d2 dz2aj,k2 (1) = 1. (17)", _v_17,
       "Values of the degree-2 symbol at z = 1",
       reading="a_2^{k,j}(1) = 1, a_2^{k,j}'(1) = 2, a_2^{k,j}''(1) = 1, for the symbol (11)", note=_GARBLED,
       location="Sect. 3.3"),
    _c("001:Sect3.3(support)", "support", "It is obvious that the mask of the proposed scheme has the support as one of "
       "the B-spline of degree n, i.e., supp(ak,j) = Z ∩ [0, n] − ⌈n/2⌉ which is indeed the same as the B-spline of "
       "degree n.", _v_support, "Support of the masks", reading="n is the degree d", location="Sect. 3.3"),
    _c("001:b(z)", "identity", "bk,j(z) = 1 z(1 + ukj)(1 + 2ukjz + z2). ... |bk,j(−1)| = 2(1 − ukj) 1 + ukj = "
       "8kak,j− ak≤ c2−k.", _v_b_of_z, "b(z) and |b(-1)| in the proof of Theorem 3.6",
       reading="b(z) = (1 + 2uz + z^2)/(z(1+u)); |b(-1)| = 2(1-u)/(1+u) = 8||a^{k,j} - a|| <= c 2^-k",
       note=_GARBLED, location="Sect. 3.3, proof of Theorem 3.6"),
    _c("001:(19)", "necessary condition", "we need to show that the NVPS of degree d satisfies the Property A of order "
       "1 ≤ m ≤ d − 1, that is, as k → ∞, d dzdj,km z=±1 = O(2−k(n−ℓ)), 0 ≤ ℓ < m. (19)", _v_19,
       "Property A of orders 1..d-1 for the NVPS",
       reading="d^l/dz^l d_m^{j,k}(±1) = o(2^{-k(m-l)}), 0 <= l < m, for 1 <= m <= d-1 (Property A (13))",
       note=_GARBLED + "'n' in the exponent is m; (13) asks o(), (19) prints O().", location="Sect. 3.3",
       command="subdiv nonuniform property-a --degree 4"),
    _c("001:Theorem3.6", "smoothness", "Theorem 3.6 (Smoothness of NVPS of degree d) The NVPS scheme of degree d with "
       "d > 1 generates Cd−1-continuous limit curves.", _v_theorem_3_6, "C^(d-1) limit curves",
       reading="C^{d-1} for every parameter sequence", location="Sect. 3.3",
       command="subdiv nonuniform junction --degree 4 --u-left 0.3 --u-right 4 --levels 16"),
    _c("001:Remark1", "identity", "Remark 1. When all parameters in the parameter sequence are equal, the NVPS is "
       "reduced to a generalized subdivision scheme in (Fang et al 2010).", _v_remark_1,
       "Equal parameters: the generalized subdivision of Fang et al. 2010", location="Sect. 2.2"),
    _c("001:Remark1(reproduction)", "reproduction", "It can reproduce the curves such as conics, trigonometric curves "
       "and helix.", _v_reproduction, "Reproduction of conics, trigonometric curves, helices", location="Sect. 2.2",
       command="subdiv nonuniform reproduce --kind circle --degree 3 --levels 8 --figure blended.png"),
    _c("001:Remark2(locality)", "support", "In fact, only d pieces of subdivision curves are effected when one "
       "parameter is changed for NVPS of degree d", _v_locality, "Locality of a parameter change",
       location="Sect. 2.2, Remark 2"),
    _c("001:Fig2(a)", "reproduction", "In Figure 2 (a), a blending curve similar to that in Figure 5 in paper (Wang and "
       "Fang 2008) is generated by NVPS of degree 2. It includes a piece of trigonometric B-spline curve, a piece of "
       "hyperbolic B-spline curve and a piece of polynomial B-spline curve", functools.partial(_v_fig2, "a"),
       "Blending example, degree 2", location="Sect. 4",
       command="subdiv nonuniform reproduce --kind hyperbola --degree 2 --levels 8 --figure blended.png"),
    _c("001:Fig2(b)", "reproduction", "In Figure 2 (b), a torque spring curve is generated by NVPS of degree 4 in which "
       "a piece of helix and a piece of arc are inserted.", functools.partial(_v_fig2, "b"), "Torque spring, degree 4",
       location="Sect. 4"),
    _c("001:Fig2(c)", "reproduction", "In Figure 2 (c), a sketch of swan is generated by NVPS of degree 5, in which four "
       "pieces of special curves with general parametric equations are inserted. (22)", functools.partial(_v_fig2, "c"),
       "Swan, degree 5, curves (22)", location="Sect. 4"),
    _c("001:Algorithm2", "reproduction", "Giving a radius rA in a suitable domain, we generate a piece of arc tangent to "
       "both edges of this angle with radius rA by generalized subdivision scheme. ... By our NVPS, the curve after "
       "chamfering is generated as illustrated in Figure 3 (d).", _v_algorithm_2, "Chamfering algorithm, Fig. 3",
       location="Sect. 4", command="subdiv nonuniform chamfer --levels 8 --figure chamfer.png"),
    _c("001:Fig3(c)", "identity", "It can be seen as a variable-parameter subdivision curve with each vertex being "
       "triple control point in its control polygon ABCDA and with a constant parameter sequence {u i ≡ 1}13i=0.",
       _v_fig3_count, "Parameter count of Fig. 3(c)", reading="u_i = 1, i = 0..13", location="Sect. 4"),
]

PAPER = C.Paper(
    id="001",
    title="A non-uniform subdivision scheme with variable parameters for curve design",
    citation=("M. Fang, B. Jeong, J. Yoon, A non-uniform subdivision scheme with variable parameters for curve "
              "design (preprint, 17 pp., c. 2014)"),
    claims=PAPER_CLAIMS,
    source="shared/seeds/001_6819d78b3590dec4.txt",
    notes=("The NVPS is non-uniform (masks depend on level and location through the edge parameters), so its "
           "schemes are analysis.nonuniform.NVPS objects, not catalogue entries; its limit is the uniform B-spline "
           "of degree d. Convention: P^{k+1}_n = sum_i a^{k,n}_{n-2i} P^k_i; the degree-2 mask is "
           "{h, 1-h, 1-h, h}, h = 1/(2(1+u)), at exponents -2..1 ((11) writes it times z). The extraction flattened "
           "sub/superscripts; each claim keeps the printed text and says how it was read. Definition 3.1 is a "
           "definition (nothing to check); Fig. 1 and the remark that Fig. 1(b) 'is impossible with existing "
           "generalized subdivision' are not checkable from the text."),
)
