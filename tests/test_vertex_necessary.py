"""Certified "not C^1" at extraordinary vertices (analysis.vertex.necessary): the original butterfly at
n = 3 (a Jordan chain of length 3 in block 0: the leading eigenfunction has one sign, winding 0) and at n = 8
(the dominant eigenvalue simple in block 2: the eigenfunction winds twice); where a hypothesis is missing the
verdict stays inconclusive and says which."""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

from analysis.vertex.necessary import HI, HOLDER_BUDGET, R_BOUND, RING, interpolating, not_c1
from analysis.vertex.rules import butterfly_rules, modified_butterfly_rules, scheme_rules
from analysis.vertex.exact_blocks import jordan_ranks


def test_interpolating_is_read_from_the_rules():
    assert interpolating(butterfly_rules(2)) and interpolating(modified_butterfly_rules(3, 5))
    assert not interpolating(scheme_rules("loop", 2)) and not interpolating(scheme_rules("catmull-clark", 2))


def test_jordan_structure_of_the_butterfly_at_valence_3_is_exact():
    """lambda = 1/4 has algebraic multiplicity 7 on the 2-ring but only 3 eigenvectors: one chain of length 3
    in block 0 and one of length 2 in blocks 1 and 2 (full matrix: nullity 3)."""
    quarter = sp.Rational(1, 4)
    assert jordan_ranks(butterfly_rules(2), 3, 0, quarter, 4) == [4, 3, 2, 1, 1]
    assert jordan_ranks(butterfly_rules(2), 3, 1, quarter, 3) == [3, 2, 1, 1]
    assert jordan_ranks(butterfly_rules(2), 3, 1, sp.Rational(1, 8), 1) == [3, 3]      # not an eigenvalue


def test_butterfly_is_not_c1_at_valence_3():
    r = not_c1(butterfly_rules(3), 3)
    assert r.status == "refuted" and r.value is False
    w = r.witness
    assert (w["block"], w["jordan_chain"], w["winding_number"], w["loop_ring"], w["ring"]) == (0, 3, 0, HI, RING)
    assert "Jordan chain of length 3 in block 0" in w["verdict"] and "winding 0 times" in w["verdict"]
    assert "the others (blocks 1, 2) proven equal to lambda exactly, with shorter Jordan chains" in w["verdict"]
    assert any("nilpotent" in h for h in w["hypotheses"])
    assert "lambda real, 0 < |lambda| < 1 (certified)" in w["hypotheses"]
    assert isinstance(w["K"], Fraction) and w["K_float"] == float(w["K"])


def test_butterfly_is_not_c1_at_valence_8_and_the_verdict_reaches_the_command():
    from analysis.vertex.valence import vertex_results

    res = vertex_results(butterfly_rules(3), 8)
    c1, nc = res["c1"], res["not_c1"]
    assert nc.status == "refuted" and (nc.witness["block"], nc.witness["winding_number"]) == (2, 2)
    assert c1.status == "refuted" and c1.value is False and "Fourier block 2" in c1.witness["verdict"]
    assert c1.witness["theorem"] == nc.witness["theorem"] and len(c1.witness["hypotheses"]) == 8
    # lambda is shown as the root of its factor (cos(2 pi 2/8) = 0 set) in its isolating ball, not rounded
    assert "lambda = root of 128*lam**3 - 96*lam**2 + 19*lam - 1 in [0.46904152" in nc.witness["verdict"]


def test_not_c1_stays_inconclusive_where_a_hypothesis_is_missing():
    seven = not_c1(butterfly_rules(3), 7)                 # Reif's case: block 1 dominant
    assert seven.status == "inconclusive" and "block 1" in seven.witness["verdict"]
    modified = not_c1(modified_butterfly_rules(3, 8), 8)
    assert modified.status == "inconclusive" and "block 1" in modified.witness["verdict"]
    loop = not_c1(scheme_rules("loop", 2), 8)
    assert loop.status == "inconclusive" and "butterfly family only" in loop.witness["verdict"]


def test_the_winding_certificate_can_fail():
    """Without refinement the tubes around the arc's images are too wide to miss the ray: not proven."""
    from flint import ctx

    from analysis.vertex.charmap import eigenvector
    from analysis.vertex.derived import cell_frame
    from analysis.vertex.spectrum import analyse
    from analysis.vertex.zorin import eigenfunction_nets, regular_bound, winding_of_arc

    a, bound = regular_bound(Fraction(1, 16), R_BOUND, HOLDER_BUDGET)
    K, W, fam, B, omega, idx = cell_frame(a, bound, (1, 1))
    top = max((e for e in analyse(butterfly_rules(3), 8, curvature=False).eigenvalues if e.k == 2),
              key=lambda e: float(e.modulus.lower()))
    old = ctx.prec
    ctx.prec = 128
    try:
        big = butterfly_rules(RING)
        phi, net = eigenfunction_nets(big, 8, eigenvector(big, 8, top.ball.real, 2), omega, 2)
        assert winding_of_arc(8, HI, net, phi, fam, B, W, K, idx, 8, 2)
        assert not winding_of_arc(8, HI, net, phi, fam, B, W, K, idx, 0, 2)
    finally:
        ctx.prec = old


def test_the_winding_certificate_refuses_a_function_that_changes_sign_at_full_depth():
    """n = 3, block 0: the eigenfunction minus 4/5 of its value at (5, 0) is positive at (5, 0) and negative at
    (3, 2), both on ring 5 (interpolating: the net's values are the function's), so it has a zero on the loop:
    at the full refinement depth of the theorem the test must not prove "one sign"."""
    from flint import acb, arb, ctx, fmpq

    from analysis.vertex.charmap import eigenvector
    from analysis.vertex.derived import cell_frame
    from analysis.vertex.zorin import eigenfunction_nets, regular_bound, winding_of_arc

    a, bound = regular_bound(Fraction(1, 16), R_BOUND, HOLDER_BUDGET)
    K, W, fam, B, omega, idx = cell_frame(a, bound, (1, 1))
    old = ctx.prec
    ctx.prec = 128
    try:
        big = butterfly_rules(RING)
        v = eigenvector(big, 3, arb(fmpq(1, 4)), 0)[1:]               # lambda = 1/4 exactly; centre dropped
        at = {p: big.coords.index(p) for p in ((HI, 0), (3, 2))}
        shift = acb(fmpq(4, 5)) * v[at[(HI, 0)]]
        shifted = [x - shift for x in v]
        assert shifted[at[(HI, 0)]].real > 0 and shifted[at[(3, 2)]].real < 0
        phi, net = eigenfunction_nets(big, 3, v, omega, 0)
        assert winding_of_arc(3, HI, net, phi, fam, B, W, K, idx, 8, 0)      # the eigenfunction itself: proven
        phi, net = eigenfunction_nets(big, 3, shifted, omega, 0)
        assert not winding_of_arc(3, HI, net, phi, fam, B, W, K, idx, 8, 0)
    finally:
        ctx.prec = old


def test_jordan_structure_at_valence_3_on_the_full_matrix():
    """Independent of the Fourier blocks: the full 19 x 19 local matrix on the 3-ring (the rules' own
    builder), ranks of (S - I/4)^j over Q for j = 0..3 — nullities 3, 6, 7: three chains, of lengths 3, 2, 2."""
    from flint import fmpq, fmpq_mat

    from analysis.vertex.blocks import local_matrix

    S = local_matrix(butterfly_rules(3), 3)
    m = S.rows
    A = fmpq_mat(m, m, [fmpq(int(x.p), int(x.q)) - (fmpq(1, 4) if i == j else 0)
                        for i, row in enumerate(S.tolist()) for j, x in enumerate(row)])
    P, ranks = fmpq_mat(m, m, [int(i == j) for i in range(m) for j in range(m)]), []
    for _ in range(4):
        ranks.append(P.rank())
        P = P * A
    assert (m, ranks) == (19, [19, 16, 13, 12])
    assert (P * A).rank() == 12                     # j = 4: no longer chain
