"""Divided differences of the control net versus derivatives of the limit (analysis/vertex/derived.py)."""

import random
from fractions import Fraction

import numpy as np
import pytest
from flint import fmpq, fmpq_mat

from analysis.bivariate.mask import BivariateMask
from analysis.result import AnalysisError
from analysis.vertex.derived import (DIRECTIONS, contraction_certificate, defect_functionals,
                                     derivative_error_bound)
from schemes.surfaces import get


def _subdivide(a, f0):
    """One step ``f1(alpha) = sum_beta a(alpha - 2 beta) f0(beta)`` by the mask (independent of the transition
    operators)."""
    out = {}
    for beta, v in f0.items():
        for (i, j), c in a:
            al = (2 * beta[0] + i, 2 * beta[1] + j)
            out[al] = out.get(al, 0) + fmpq(int(c.p), int(c.q)) * v
    return out


@pytest.mark.parametrize("name", ["butterfly", "loop"])
def test_child_net_and_defect_identity(name):
    """The child cell's local net is T_eps^T u (checked against the mask applied directly), and
    d_1 - d_0 = 2^0 g_eps(u) = h_eps . c(u) exactly, in every direction."""
    a = get(name).mask(w="1/16") if name == "butterfly" else get(name).mask()
    rng = random.Random(7)
    f0 = {(x, y): fmpq(rng.randint(-20, 20)) for x in range(-9, 10) for y in range(-9, 10)}
    f1 = _subdivide(a, f0)
    for e in DIRECTIONS:
        d = defect_functionals(a, e)
        fam, B = d["family"], d["basis"]
        omega = fam.omega
        u = fmpq_mat([[f0[(-j[0], -j[1])]] for j in omega])
        c = B.transpose() * u
        idx = {p: s for s, p in enumerate(omega)}
        for k, (T, eps) in enumerate(zip(fam.full, a.dilation.digits)):
            child = T.transpose() * u
            for s, j in enumerate(omega):
                assert child[s, 0] == f1[(eps[0] - j[0], eps[1] - j[1])]
            d0 = u[idx[(-e[0], -e[1])], 0] - u[idx[(0, 0)], 0]
            d1 = 2 * (child[idx[(-e[0], -e[1])], 0] - child[idx[(0, 0)], 0])
            assert d1 - d0 == sum((d["h"][k][t] * c[t, 0] for t in range(c.nrows())), start=fmpq(0))


def test_defects_need_second_order_sum_rules():
    # the tensor Haar mask: sum rules of order 1 only, so V_2 is not invariant
    with pytest.raises(AnalysisError, match="sum rules of order 2"):
        defect_functionals(BivariateMask.from_symbol("(1 + z1)*(1 + z2)"), (1, 0))
    with pytest.raises(AnalysisError, match="2I"):
        defect_functionals(BivariateMask.from_list("0,0: 1; 1,0: 1", dilation="quincunx"), (1, 0))


def test_contraction_tree_bounds_sampled_products():
    """||W A_w W^-1||_inf <= C r^|w| on random words (floats only check the certified constants)."""
    a, k = _bound("loop")
    assert k.status == "certified"
    tree, W = k.witness["tree"], k.witness["W"]
    C, r = tree.value, k.witness["r"]
    fam = defect_functionals(a, (1, 0))["family"]
    Wf = np.array([[float(W[i, j]) for j in range(W.ncols())] for i in range(W.nrows())])
    Af = [np.array([[float(X[j, i]) for j in range(X.nrows())] for i in range(X.ncols())]) for X in fam.matrices]
    Bf = [Wf @ A @ np.linalg.inv(Wf) for A in Af]
    rng = random.Random(3)
    for _ in range(200):
        word = [rng.randrange(4) for _ in range(rng.randrange(1, 13))]
        P = np.eye(len(Wf))
        for e in word:
            P = Bf[e] @ P
        assert np.abs(P).sum(axis=1).max() <= float(C) * float(r) ** len(word) * (1 + 1e-9)


_BOUNDS = {}


def _bound(name):
    """The certified K of Loop (r = 2/5) or the butterfly (w = 1/16, r = 9/20), computed once. The butterfly's is
    the regular part's bound that the C^1 test of the modified butterfly uses (``analysis.vertex.zorin.regular_bound``
    with the arguments of ``analysis.vertex.necessary``: one computation per process), for the catalogue's mask."""
    if name not in _BOUNDS:
        a = get(name).mask(w="1/16") if name == "butterfly" else get(name).mask()
        if name == "butterfly":
            from analysis.vertex.necessary import HOLDER_BUDGET, R_BOUND
            from analysis.vertex.zorin import regular_bound

            assert R_BOUND == Fraction(9, 20)
            regular, k = regular_bound(Fraction(1, 16), R_BOUND, HOLDER_BUDGET)
            assert dict(regular.coeffs) == dict(a.coeffs) and regular.dilation.matrix == a.dilation.matrix
            _BOUNDS[name] = (a, k)
        else:
            from analysis.bivariate.holder import holder_exponent

            _BOUNDS[name] = (a, derivative_error_bound(a, Fraction(2, 5), holder=holder_exponent(a, budget=50)))
    return _BOUNDS[name]


@pytest.mark.parametrize("name", ["loop", "butterfly"])
def test_error_bound_along_nested_cells(name):
    """|d_M - d_0| <= K (||W c(u_0)|| + 2^M ||W c(u_M)||) along random digit paths of random nets (exact)."""
    a, k = _bound(name)
    assert k.status == "certified"
    K, W = k.value, k.witness["W"]
    rng = random.Random(11)
    for e in DIRECTIONS:
        d = defect_functionals(a, e)
        fam, B = d["family"], d["basis"]
        idx = {p: s for s, p in enumerate(fam.omega)}

        def norm(u):
            z = W * (B.transpose() * u)
            return max(Fraction(int(abs(z[t, 0]).p), int(abs(z[t, 0]).q)) for t in range(z.nrows()))

        def diff(u, m):
            v = u[idx[(-e[0], -e[1])], 0] - u[idx[(0, 0)], 0]
            return Fraction(int(v.p), int(v.q)) * 2 ** m

        for _ in range(2):
            u0 = fmpq_mat([[rng.randint(-50, 50)] for _ in fam.omega])
            u, M = u0, 8
            for _ in range(M):
                u = fam.full[rng.randrange(4)].transpose() * u
            gap = abs(diff(u, M) - diff(u0, 0))
            assert gap <= K * (norm(u0) + 2 ** M * norm(u))
            assert gap > 0                     # the random nets are not linear: the check is not vacuous


def test_butterfly_error_constant():
    """The butterfly's regular part: C^1 certified (Hölder exponent > 1) and the tree closes at r = 9/20."""
    _, k = _bound("butterfly")
    tree = k.witness["tree"].witness
    assert k.status == "certified" and tree["depth"] == 8 and tree["nodes"] == 701
    assert 700 < k.value < 740 and k.value == max(k.witness["H"].values()) * k.witness["C"] / (1 - 2 * k.witness["r"])


def test_not_c1_or_not_contracting_is_inconclusive():
    courant = get("box-111").mask()
    k = derivative_error_bound(courant, Fraction(2, 5))
    assert k.status == "inconclusive" and "C^1" in k.provenance["message"]
    fam = defect_functionals(courant, (1, 0))["family"]
    t = contraction_certificate([X.transpose() for X in fam.matrices], Fraction(2, 5), max_depth=6)
    assert t.status == "inconclusive" and t.witness["stuck_word"]
    with pytest.raises(AnalysisError, match="r < 1/2"):
        derivative_error_bound(courant, Fraction(1, 2))


def test_butterfly_defects_exact_and_small_tree_inconclusive():
    """The butterfly's defect functionals are exact in the three directions; the identity coordinates do not
    give a contraction within a tiny tree (the ellipsoid coordinates are needed: see docs/vertices.md)."""
    a = get("butterfly").mask(w="1/16")
    d = defect_functionals(a, (1, 1))
    assert d["omega_size"] == 46 and d["dimension"] == 43
    fam = d["family"]
    t = contraction_certificate([X.transpose() for X in fam.matrices], Fraction(9, 20), max_nodes=5)
    assert t.status == "inconclusive"


def test_jacobian_sign_on_cell():
    """The butterfly reproduces cubics, so the limit of polynomial data is the polynomial itself: a map with a
    Jacobian of one sign on the cell is proven (after refinement), a fold inside the cell never is."""
    from analysis.vertex.derived import jacobian_sign_on_cell

    a, k = _bound("butterfly")
    omega = defect_functionals(a, (1, 0))["family"].omega

    def net(p):
        return [p(complex(-x, -y)) for x, y in omega]      # u(j) = f_0(-j)

    r = jacobian_sign_on_cell(a, net(lambda z: z + 0.01 * z * z), k, max_depth=6)
    assert r.status == "certified" and r.value == 1 and r.witness["depth"] >= 3
    r = jacobian_sign_on_cell(a, net(lambda z: (z.conjugate() + 0.01 * z.conjugate() ** 2)), k, max_depth=6)
    assert r.status == "certified" and r.value == -1                   # orientation reversed
    r = jacobian_sign_on_cell(a, net(lambda z: (z - complex(0.5, 0.5)) ** 2), k, max_depth=4)
    assert r.status == "inconclusive" and r.witness["unproven"] > 0     # J = 0 at the cell's centre
    with pytest.raises(AnalysisError, match="invariant support"):
        jacobian_sign_on_cell(a, [0, 1], k)


def test_tube_and_ray():
    """The tube [p, q] + disk(rad) against the ray from 0 along rho (the winding step of the Zorin check)."""
    from flint import acb, arb

    from analysis.vertex.zorin import _tube_misses_ray

    one = acb(1)
    assert _tube_misses_ray(acb(1, 1), acb(3, 2), arb("0.5"), one)          # above the positive axis
    assert not _tube_misses_ray(acb(1, 1), acb(3, -2), arb("0.5"), one)     # crosses it
    assert _tube_misses_ray(acb(-2, 1), acb(-3, -2), arb("0.5"), one)       # crosses the negative axis only
    assert not _tube_misses_ray(acb(1, 1), acb(3, 2), arb(2), one)          # the disk reaches the ray
    assert _tube_misses_ray(acb(1, -1), acb(3, -2), arb("0.5"), acb(0, 1))  # the ray is the positive imaginary axis
    assert not _tube_misses_ray(acb(-1, 1), acb(1, 1), arb("0.5"), acb(0, 1))


def test_butterfly_neighbourhoods_nested():
    """Every refinement of a cell of the butterfly uses points inside the convex hull of the cell's
    neighbourhood (the cover argument of the Zorin check)."""
    from analysis.bivariate.transition import invariant_support
    from analysis.vertex.zorin import nested_neighbourhoods

    a = get("butterfly").mask(w="1/16")
    om = invariant_support(a)
    assert nested_neighbourhoods(om, a.dilation.digits)
    assert not nested_neighbourhoods([(x + 3, y) for x, y in om], a.dilation.digits)   # shifted off the origin
