"""The sharp derivative error bound of the regular part (analysis/vertex/defectsum.py): its norm bounds, the
constants against exact nested-cell sums, its failures, and Zorin's cell test of the modified butterfly with it
on a small annulus."""

import random
from fractions import Fraction

import numpy as np
import pytest
from flint import arb_mat, fmpq, fmpq_mat

from analysis.vertex.defectsum import defect_sum_bound, euclidean_upper, spectral_norm_upper
from analysis.vertex.derived import DIRECTIONS, defect_functionals
from schemes.surfaces import get


def test_spectral_norm_upper_encloses_and_is_tight():
    """||M||_2 <= bound <= rank^(1/16) ||M||_2 on random rational matrices (numpy only checks the Arb bound)."""
    rng = random.Random(5)
    for size in (1, 3, 8):
        M = [[Fraction(rng.randint(-9, 9), rng.randint(1, 7)) for _ in range(size)] for _ in range(size)]
        exact = np.linalg.norm(np.array(M, dtype=float), 2)
        b = spectral_norm_upper(arb_mat(fmpq_mat([[fmpq(x.numerator, x.denominator) for x in r] for r in M])))
        assert exact * (1 - 1e-12) <= b <= exact * size ** (1 / 16) * (1 + 1e-12)
    assert spectral_norm_upper(arb_mat(2, 2)) < Fraction(1, 10 ** 9)          # the zero matrix


def test_euclidean_upper():
    from flint import acb, arb

    b = euclidean_upper([acb(3, 4), arb(12)])
    assert 13 <= b < Fraction(13) * (1 + Fraction(1, 10 ** 20))


_LOOP = {}


def _loop():
    if not _LOOP:
        a = get("loop").mask()
        _LOOP["a"], _LOOP["k"] = a, defect_sum_bound(a, theta=Fraction(1, 2))
    return _LOOP["a"], _LOOP["k"]


def test_constants_bound_exact_nested_sums():
    """|d_M - d_0| <= K_e (||W c(u_0)||_2 + 2^M ||W c(u_M)||_2) along random digit paths of random integer nets
    (exact nets and differences; the norms compared squared, exactly)."""
    a, k = _loop()
    assert k.status == "certified" and k.witness["q_max"] <= Fraction(1, 2)
    W = k.witness["W"]
    rng = random.Random(2)
    for e in DIRECTIONS:
        Ke = k.witness["K_by_direction"][e]
        d = defect_functionals(a, e)
        fam, B = d["family"], d["basis"]
        idx = {p: s for s, p in enumerate(fam.omega)}

        def norm2(u):
            z = W * (B.transpose() * u)
            return sum((Fraction(int(z[t, 0].p), int(z[t, 0].q)) ** 2 for t in range(z.nrows())), Fraction(0))

        for _ in range(2):
            u0 = fmpq_mat([[rng.randint(-50, 50)] for _ in fam.omega])
            u, M = u0, 6
            for _ in range(M):
                u = fam.full[rng.randrange(4)].transpose() * u
            g = (u[idx[(-e[0], -e[1])], 0] - u[idx[(0, 0)], 0]) * 2 ** M - (u0[idx[(-e[0], -e[1])], 0]
                                                                             - u0[idx[(0, 0)], 0])
            gap = Fraction(int(g.p), int(g.q))
            assert gap != 0                                           # the nets are not linear: not vacuous
            # gap <= K (s0 + s1) with s0^2 = norm2(u0), s1^2 = 4^M norm2(u): squared twice, exact
            s0, s1 = norm2(u0), 4 ** M * norm2(u)
            rhs = gap ** 2 / Ke ** 2 - s0 - s1                         # need rhs <= 2 sqrt(s0 s1)
            assert rhs <= 0 or rhs ** 2 <= 4 * s0 * s1


def test_tighter_leaves_give_a_smaller_constant_and_the_tree_can_fail():
    a, k = _loop()
    k4 = defect_sum_bound(a, holder=k.witness["holder"], theta=Fraction(1, 4))
    assert k4.status == "certified" and k4.value < k.value and k4.witness["depth"] > k.witness["depth"]
    stuck = defect_sum_bound(a, holder=k.witness["holder"], theta=Fraction(1, 100), max_depth=1)
    assert stuck.status == "inconclusive" and len(stuck.witness["stuck_word"]) == 1
    assert "no bound proven" in stuck.provenance["message"]
    # without the ellipsoid's coordinates two steps do not contract in the Euclidean norm
    m = k.witness["W"].nrows()
    eye = fmpq_mat([[int(i == j) for j in range(m)] for i in range(m)])
    plain = defect_sum_bound(a, holder=k.witness["holder"], W=eye, max_depth=2)
    assert plain.status == "inconclusive" and "length 2" in plain.provenance["message"]


def test_not_c1_is_inconclusive():
    k = defect_sum_bound(get("box-111").mask())
    assert k.status == "inconclusive" and "C^1" in k.provenance["message"]


def test_modified_butterfly_at_valence_3_on_a_small_annulus():
    """Zorin's cell test with the sharp bound on rings 5..10 (45 cells, the 14-ring): certified at n = 3, which
    the tree bound left inconclusive on rings 8..16."""
    from analysis.vertex.zorin import modified_butterfly_zorin

    r = modified_butterfly_zorin(3, lo=5, hi=10)
    w = r.witness
    assert r.status == "certified" and w["cells"] == "45 of 45" and w["ring"] == 14 and w["norm"] == "2"
    assert w["jacobian_sign_mask"] == -1 and w["winding"] and w["subcells"] > 45 and 1 <= w["depth"] <= 8
