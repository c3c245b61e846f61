"""Difference schemes of bivariate masks with M = m I (the quotient-ideal form) and the C^0 norm test.

The identity nabla^mu(z) a(z) = sum_nu b_mu,nu(z) nabla^nu(z^m) is re-checked here with sympy expressions,
independently of the module's own check; the norms are re-computed from the product of sympy matrices.
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.bivariate.differences import (_verify, convergence_by_norms, difference_scheme, scheme_norm,
                                            smoothness_by_norms)
from analysis.bivariate.mask import Z1, Z2, BivariateMask
from analysis.cli.main import main
from analysis.result import CERTIFIED, INCONCLUSIVE, AnalysisError
from schemes.surfaces import get


def _nabla(mu, m=1):
    return (1 - Z1 ** m) ** mu[0] * (1 - Z2 ** m) ** mu[1]


def _entry(B, mu, nu):
    return sum((c * Z1 ** i * Z2 ** j for (i, j), c in B.entries.get((mu, nu), {}).items()), sp.Integer(0))


def _identity_holds(a: BivariateMask, B) -> bool:
    for mu in B.indices:
        rhs = sum(_entry(B, mu, nu) * _nabla(nu, B.m) for nu in B.indices)
        if sp.expand(_nabla(mu) * a.symbol - rhs) != 0:
            return False
    return True


@pytest.mark.parametrize("name,general,k", [
    ("loop", False, 1), ("loop", False, 4),
    ("butterfly", True, 1), ("butterfly", True, 2), ("butterfly", False, 4),
    ("kobbelt-quad", False, 1), ("kobbelt-quad", True, 2), ("kobbelt-quad", False, 4),
], ids=lambda x: str(x))
def test_the_identity_holds_exactly(name, general, k):
    a = get(name).mask(general=general)
    B = difference_scheme(a, k).value
    assert len(B.indices) == k + 1 and all(sum(mu) == k for mu in B.indices)
    assert _identity_holds(a, B)
    assert B.domain == ("QQ[w]" if general else "QQ")


@pytest.mark.parametrize("name,k,shift", [("butterfly", 2, (1, 1)), ("zwart-powell", 2, (1, 0))],
                         ids=lambda x: str(x))
def test_a_shifted_construction_is_a_difference_scheme_of_the_mask(name, k, shift):
    a = get(name).mask()
    B = difference_scheme(a, k, shift).value
    assert B.shift == shift and _identity_holds(a, B)


def test_rational_functions_of_a_parameter_and_what_is_refused():
    hat = "(1+z1)**2*(1+z2)**2/(4*z1*z2)"
    a = BivariateMask.from_symbol(hat + " + w/(1+w)*(1-z1**2)*(1-z2**2)/(z1*z2)")
    B = difference_scheme(a, 1).value
    assert B.domain == "QQ(w)"
    for mu in B.indices:                                       # the identity over QQ(w)
        rhs = sum(_entry(B, mu, nu) * _nabla(nu, 2) for nu in B.indices)
        assert sp.cancel(_nabla(mu) * a.symbol - rhs) == 0
    with pytest.raises(AnalysisError, match="rational functions of the parameters"):
        difference_scheme(BivariateMask.from_symbol(hat + " + sqrt(w)*(1-z1**2)*(1-z2**2)/(z1*z2)"), 1)


def test_a_wrong_entry_is_caught_by_the_check():
    a = get("loop").mask()
    B = difference_scheme(a, 1).value
    entries = dict(B.entries)
    key = ((1, 0), (1, 0))
    entries[key] = {**entries[key], (0, 0): entries[key].get((0, 0), 0) + sp.Rational(1, 64)}
    bad = type(B)(B.k, B.m, B.indices, entries, B.params)
    assert not _identity_holds(a, bad)
    with pytest.raises(AssertionError):
        _verify(a, bad)


def test_a_box_spline_gets_the_diagonal_scheme():
    a = get("loop").mask()
    B = difference_scheme(a, 1).value
    assert B.entry((1, 0), (0, 1)) == 0 and B.entry((0, 1), (1, 0)) == 0
    assert sp.cancel(B.entry((1, 0), (1, 0)) - a.symbol / (1 + Z1)) == 0


def _coset_norm(P, N):
    """max over rows and cosets mod N of the sums of |coefficients| of a sympy matrix of Laurent polynomials."""
    best = 0
    for i in range(P.rows):
        sums: dict = {}
        for j in range(P.cols):
            e = sp.expand(P[i, j] * (Z1 * Z2) ** (8 * N))
            if e != 0:
                for (x, y), c in sp.Poly(e, Z1, Z2).terms():
                    sums[(x % N, y % N)] = sums.get((x % N, y % N), 0) + abs(c)
        best = max(best, max(sums.values()))
    return best


def _brute_norm(B, L):
    """||S_B^L||_inf from the product B(z) B(z^m) ... of sympy matrices."""
    P = sp.eye(len(B.indices))
    for l in range(L):
        up = {Z1: Z1 ** B.m ** l, Z2: Z2 ** B.m ** l}
        P = (P * sp.Matrix([[_entry(B, mu, nu).subs(up, simultaneous=True) for nu in B.indices]
                            for mu in B.indices])).applyfunc(sp.expand)
    return _coset_norm(P, B.m ** L)


@pytest.mark.parametrize("name", ["loop", "butterfly"])
def test_the_norm_test_shows_convergence(name):
    a = get(name).mask()                     # the butterfly at its default w = 1/16
    r = convergence_by_norms(a)
    assert r.status == CERTIFIED and r.value is not None
    B = r.witness["scheme"]
    assert r.witness["norms"][-1] == scheme_norm(B, r.value) == _brute_norm(B, r.value) < 1
    assert all(x >= 1 for x in r.witness["norms"][:-1])


def test_norms_agree_with_the_product_of_sympy_matrices():
    # not diagonal, and B(z^2) B(z) would have the norm 1/4 at L = 2: the order of the product is tested
    B = difference_scheme(get("zwart-powell").mask(), 2, (1, 1)).value
    assert len(B.entries) > len(B.indices)
    assert [scheme_norm(B, L) for L in (1, 2)] == [_brute_norm(B, L) for L in (1, 2)]


@pytest.mark.parametrize("mask,limits", [
    (BivariateMask.from_list("0,0:1; 1,0:1; 0,1:1; 1,1:1"), {}),          # Haar: its limits are discontinuous
    (get("butterfly").mask(w="1/4"), {"max_L": 3}),                        # alpha = 0 there: not C^0
], ids=["haar", "butterfly-1/4"])
def test_the_norm_test_is_inconclusive_where_it_must_be(mask, limits):
    r = convergence_by_norms(mask, **limits)
    assert r.status == INCONCLUSIVE and r.value is None and all(x >= 1 for x in r.witness["norms"])
    assert r.witness["stopped"]


def test_the_size_limit_stops_the_products():
    r = convergence_by_norms(get("butterfly").mask(w="1/4"), max_terms=10_000)
    assert r.status == INCONCLUSIVE and len(r.witness["norms"]) < 8 and "size limit" in r.witness["stopped"]


@pytest.mark.parametrize("name,l", [("zwart-powell", 1), ("kobbelt-quad", 1), ("bicubic", 2)])
def test_c_l_by_norms_shows_what_the_sources_state(name, l):
    e = get(name)
    assert e.claims["C"] == l
    r = smoothness_by_norms(e.mask(), l)
    assert r.status == CERTIFIED and r.value == l
    assert [v["C"] for v in r.witness["levels"]] == list(range(l + 1))
    for v in r.witness["levels"]:                          # each level: its norm, recomputed from its scheme
        B = difference_scheme(e.mask(), v["C"] + 1, v["shift"]).value
        assert v["norms"][-1] == scheme_norm(B, v["L"]) * 2 ** (v["C"] * v["L"]) < 1


def test_c_l_by_norms_is_inconclusive_where_it_must_be():
    r = smoothness_by_norms(get("box-111").mask(), 1, max_L=4)        # the Courant element is not C^1
    assert r.status == INCONCLUSIVE and r.value == 0 and r.witness["levels"][-1]["L"] is None
    hat3 = BivariateMask.from_symbol("(1+z1+z1**2)**2*(1+z2+z2**2)**2/(9*z1**2*z2**2)", "triadic")
    r = smoothness_by_norms(hat3, 1, max_L=2)                       # the triadic hat: C^0, not C^1
    assert r.status == INCONCLUSIVE and r.value == 0 and [v["L"] for v in r.witness["levels"]] == [1, None]


def test_c_l_by_norms_for_a_triadic_dilation():
    """M = 3I: the divided differences are scaled by 3^j (the proof in the module docstring is for every m). The
    triadic quadratic and cubic tensor B-splines (C^1, C^2) are shown at L = 1; each norm is recomputed from its
    scheme with the factor 3^(jL), so a factor 2^j (the dyadic one) fails here."""
    quad3 = BivariateMask.from_symbol("(1+z1+z1**2)**3*(1+z2+z2**2)**3/(81*z1**2*z2**2)", "triadic")
    cubic3 = BivariateMask.from_symbol("(1+z1+z1**2)**4*(1+z2+z2**2)**4/(729*z1**2*z2**2)", "triadic")
    for mask, l in ((quad3, 1), (cubic3, 2)):
        r = smoothness_by_norms(mask, l)
        assert r.status == CERTIFIED and r.value == l and r.provenance["m"] == 3
        for v in r.witness["levels"]:
            B = difference_scheme(mask, v["C"] + 1, v["shift"]).value
            assert v["norms"][-1] == scheme_norm(B, v["L"]) * 3 ** (v["C"] * v["L"]) < 1
    assert [v["norms"] for v in smoothness_by_norms(quad3, 1).witness["levels"]] == [[sp.Rational(1, 3)],
                                                                                     [sp.Rational(1, 3)]]


def test_without_the_sum_rules_it_is_a_one_line_error():
    with pytest.raises(AnalysisError, match="sum rules of order 3") as e:
        difference_scheme(get("box-111").mask(), 3)
    assert "\n" not in str(e.value) and "order 1 to 2" in str(e.value)
    with pytest.raises(AnalysisError, match="sum rules of order 3"):          # generic order 2 in w
        difference_scheme(get("butterfly").mask(general=True), 3)


@pytest.mark.parametrize("dilation", ["quincunx", "sqrt3", "2,0;0,3", "2,1;0,2"])
def test_other_dilations_say_not_available(dilation):
    a = BivariateMask.from_symbol("(1+z1)*(1+z2)", dilation)
    with pytest.raises(AnalysisError, match="not available"):
        difference_scheme(a, 1)


def test_cli_differences(capsys):
    assert main(["surface", "--scheme", "loop", "--differences", "1"]) == 0
    out = capsys.readouterr().out
    assert out.count("\n") == 1 and "checked exactly" in out and "it converges (C^0, certified)" in out
    assert main(["surface", "--symbol", "(1+z1)**2*(1+z2)**2/(4*z1*z2) + t*(1-z1**2)*(1-z2**2)/(z1*z2)",
                 "--differences", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["differences"]["domain"] == "QQ[t]" and doc["norm_test"] is None
    assert len(doc["differences"]["matrix"]) == 2
    assert main(["surface", "--scheme", "zwart-powell", "--differences", "2", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["norm_test"]["status"] == CERTIFIED and doc["norm_test"]["certified_up_to"] == 1


@pytest.mark.parametrize("argv,match", [
    (["--scheme", "sqrt3"], "not available"),
    (["--scheme", "box-111", "--differences", "3"], "sum rules of order 3"),
    (["--scheme", "loop", "--differences", "0"], "from 1 to"),
    (["--scheme", "loop", "--C", "1"], "mode of its own"),
])
def test_cli_differences_errors_are_one_line(argv, match, capsys):
    argv = ["surface", *argv] + ([] if "--differences" in argv else ["--differences", "1"])
    assert main(argv + ["--json"]) == 2
    cap = capsys.readouterr()
    assert cap.err.count("\n") == 1 and cap.err.startswith("subdiv: error:") and match in cap.err
    assert "error" in json.loads(cap.out)


def _json_norm(matrix, L, m=2):
    """||S_B^L||_inf of a matrix given as JSON strings (read back with the input reader)."""
    from analysis.algebra.reader import read_expression

    B = sp.Matrix([[read_expression(e, names={"z1": Z1, "z2": Z2}) for e in row] for row in matrix])
    P = sp.eye(B.rows)
    for l in range(L):
        P = (P * B.subs({Z1: Z1 ** m ** l, Z2: Z2 ** m ** l}, simultaneous=True)).applyfunc(sp.expand)
    return B, _coset_norm(P, m ** L)


def test_the_json_shows_the_scheme_whose_norm_is_certified(capsys):
    """Zwart-Powell C^1: the norm 1/2 at L = 2 is that of the scheme built from z^(1, 1) a, not of the unshifted one;
    the JSON gives each level's scheme, so every certified norm and identity is checked here from the JSON alone."""
    assert main(["surface", "--scheme", "zwart-powell", "--differences", "2", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    a = get("zwart-powell").mask()
    assert doc["differences"]["shift"] == [1, 1]
    top = doc["norm_test"]["levels"][-1]
    assert top["shift"] == [1, 1] and top["order"] == 2 and top["matrix"] == doc["differences"]["matrix"]
    for v in doc["norm_test"]["levels"]:
        k = v["order"]
        B, norm = _json_norm(v["matrix"], v["L"])
        indices = [(k - i, i) for i in range(k + 1)]
        for r, mu in enumerate(indices):            # the identity, from the JSON matrix
            assert sp.expand(_nabla(mu) * a.symbol - sum(B[r, c] * _nabla(nu, 2) for c, nu in enumerate(indices))) == 0
        assert sp.Rational(v["norms"][-1]) == norm * v["scaled_by"] ** v["L"] < 1
    unshifted = difference_scheme(a, 2).value
    assert scheme_norm(unshifted, 2) * 4 >= 1                  # the unshifted scheme does not show it at L = 2
    assert main(["surface", "--scheme", "zwart-powell", "--differences", "2"]) == 0
    out = capsys.readouterr().out
    assert "difference scheme of order 2 (M = 2I, B built from z^(1, 1) a): B is 3 x 3 over QQ, entries in [-1, 2]" in out


@pytest.mark.parametrize("name,j,shift", [("loop", 1, (0, 0)), ("loop", 3, (0, 0)), ("butterfly", 1, (1, 1)),
                                          ("zwart-powell", 1, (1, 0)), ("bicubic", 2, (0, 0))], ids=lambda x: str(x))
def test_with_the_sum_rules_of_order_j_plus_1_two_to_the_j_s_b_j_keeps_constant_vectors(name, j, shift):
    """Step (a) of the C^l proof in the module docstring: when B_{j+1} exists, every coset of B_j sums to 2^-j I,
    i.e. 2^j S_{B_j} maps constant vectors to themselves (for every difference scheme of order j, shifted or not)."""
    a = get(name).mask()
    difference_scheme(a, j + 1)                                       # the sum rules of order j + 1 hold
    B = difference_scheme(a, j, shift).value
    for eps in [(0, 0), (1, 0), (0, 1), (1, 1)]:
        coset = sp.Matrix([[sum((c for (x, y), c in B.entries.get((mu, nu), {}).items()
                                 if (x % 2, y % 2) == eps), sp.Integer(0)) for nu in B.indices] for mu in B.indices])
        assert coset == sp.eye(j + 1) / 2 ** j
