"""Issue 12: ternary and m-ary schemes (algebra, stationary, regularity, catalogue, CLI).

Expected values are computed independently (Lagrange weights by hand, factor counts, norms from the
residue-sum code versus the JSR code, the binary code paths for m = 2) or are classical facts:
the degree-d B-spline is C^(d-1) with Hölder exponent exactly d (de Boor, *A Practical Guide to
Splines*; it is the same piecewise polynomial for every arity), its support has length d + 1, and
its local subdivision matrix has eigenvalues among 1, 1/m, ..., 1/m^d (Dyn–Levin 2002, Sect. 4).
"""

from __future__ import annotations

import json

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings, strategies as st

import schemes
from analysis.algebra import factorization as F
from analysis.algebra.factorization import (check_arity, polynomial_generation, polynomial_reproduction,
                                   smoothing_factor, sum_rules)
from analysis.algebra.symbol import LaurentSymbol
from analysis.regularity.holder import holder_exponent
from analysis.regularity.ranges import ck_range
from analysis.regularity.convergence import difference_mask
from analysis.regularity.holder import holder_exponent, smoothness
from analysis.result import AnalysisError, CERTIFIED
from analysis.stationary import difference as D, transition as T
from analysis.stationary.difference import difference_norm, difference_symbol, scheme_norm
from analysis.stationary.transition import (basic_limit_support, local_eigenvalues, local_subdivision_matrix,
                                            transition_matrices)
from analysis.stationary.refinement import refine
from tests.cli_run import run_cli

R = sp.Rational
MU = sp.Symbol("mu")


# --------------------------------------------------------------------------------------------
# 1. m-ary B-splines: alpha = d exactly (certified), C^(d-1) and not C^d
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("m", [3, 4])
@pytest.mark.parametrize("d", [1, 2, 3, 4, 5])
def test_mary_bspline_alpha_is_degree(m, d):
    e = schemes.get({3: "ternary", 4: "quaternary"}[m] + f"-bspline-{d}")
    assert e.arity == m
    # transcription: the symbol is q_m^(d+1)/m^d up to a shift
    q = sum(sp.Symbol("z") ** i for i in range(m))
    assert sp.expand(e.symbol.expr() * sp.Symbol("z") ** (-e.symbol.start) * m ** d - sp.expand(q ** (d + 1))) == 0
    h = holder_exponent(e.symbol, arity=m)
    assert (h.value, h.status) == (d, CERTIFIED)
    assert smoothness(e.symbol, d - 1, arity=m).value is True
    assert smoothness(e.symbol, d, arity=m).value is False
    sup = basic_limit_support(e.symbol, arity=m).value
    assert sup[1] - sup[0] == d + 1                       # B-spline of degree d: support length d + 1
    ev = local_eigenvalues(e.symbol, arity=m)
    size = ev.witness["matrix"].shape[0]                  # minimal invariant window (<= d + 1 points)
    assert 1 <= size <= d + 1
    assert sorted(ev.value, reverse=True) == [R(1, m ** i) for i in range(size)]
    assert polynomial_reproduction(e.symbol, arity=m).value == 1   # B-splines reproduce linears only


# --------------------------------------------------------------------------------------------
# 2. m = 2: the m-ary code equals the binary code (property test over random masks)
# --------------------------------------------------------------------------------------------

_ints = st.lists(st.integers(-4, 6), min_size=1, max_size=4).filter(lambda v: sum(v) != 0)


def _mask(b, N, start):
    """A convergent-looking mask ((1+z)/2)^N b(z) normalised to a(1) = 2."""
    z = sp.Symbol("z")
    expr = sp.expand(((1 + z) / 2) ** N * sum(c * z ** i for i, c in enumerate(b)))
    expr = 2 * expr / expr.subs(z, 1)
    return LaurentSymbol.from_expr(expr).shift(start)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_ints, st.integers(0, 4), st.integers(-4, 1))
def test_arity_two_general_methods_equal_binary(b, N, start):
    """At m = 2 the any-arity methods (residue sums, division by q_m, the definition of reproduction,
    the dilated refinement loop) agree with the binary specialisations (values at z = +-1, synthetic
    division, Conti-Hormann derivative conditions, the vectorised refinement)."""
    from analysis.stationary.refinement import _refine_dilated

    a = _mask(b, N, start)
    assert (all(x == 1 for x in a.residue_sums(2))) == sum_rules(a).value
    q, r, divisible = F.divide_q(a, 2)
    quo, rem = a.poly.div(sp.Poly([1, 1], a.poly.gen, domain=a.domain))
    assert divisible == rem.is_zero and (not divisible or q.poly == quo)
    if N >= 1:   # without sum rules the binary routine reports degree 0 from a(1) = 2 alone (see report)
        assert F._reproduction_degree(a, 2)[0] == polynomial_reproduction(a).value
    for L in (1, 2):
        prod = D.iterated_symbol(a, L)
        sums = [sum(abs(c) for i, c in prod.items() if i % 2 ** L == res) for res in range(2 ** L)]
        assert scheme_norm(a, L).value == max(sums)
    Ts = transition_matrices(a)
    mask, n = a.mask, max(len(a) - 1, 1)
    assert all(Ts[e] == sp.Matrix(n, n, lambda i, j: mask[2 * i - j + e] if 0 <= 2 * i - j + e < len(mask) else 0)
               for e in (0, 1))
    pts = [[R(i * i), R(-i)] for i in range(6)]
    assert (_refine_dilated(a, pts, 2, 2, exact=True) == refine(a, pts, steps=2, exact=True)).all()


@pytest.mark.parametrize("mask,start", [
    (["1/8", "1/2", "3/4", "1/2", "1/8"], -2),                     # cubic B-spline
    (["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"], -3),             # 4-point scheme, w = 1/16
    (["3/256", 0, "-25/256", 0, "75/128", 1, "75/128", 0, "-25/256", 0, "3/256"], -5),   # 6-point DD
    (["3/8", "5/8", "5/8", "3/8"], -2),
])
def test_arity_two_smoothness_routes_agree(mask, start):
    """The any-arity C^j route (:func:`analysis.regularity.holder._smoothness_dilated`) at m = 2 gives the
    binary route's certified verdicts."""
    from analysis.regularity.holder import _smoothness_dilated

    a = LaurentSymbol.from_mask(mask, start=start)
    for j in range(3):
        g, b = _smoothness_dilated(a, 2, j, budget=20_000, max_length=12, max_L=4, max_word=3), smoothness(a, j)
        assert (g.value, g.status) == (b.value, b.status)


# --------------------------------------------------------------------------------------------
# 3. sum rules name the root of unity; bad arity
# --------------------------------------------------------------------------------------------

def test_sum_rule_failure_names_root():
    a = LaurentSymbol.from_mask([2, 0, 2])               # a(1) = 4, a(i) = a(-i) = 0, a(-1) = 4
    r = sum_rules(a, arity=4)
    assert r.value is False and r.witness["failures"] == ["a(-1) = 4 != 0"]
    s = smoothness(a, 0, arity=4)
    assert (s.value, s.status) == (False, CERTIFIED) and "a(-1) = 4 != 0" in s.witness["reason"]
    b = LaurentSymbol.from_mask([1, 2])                  # a(1) = 3, residue sums 1, 2, 0
    assert [f.split(" =")[0] for f in sum_rules(b, arity=3).witness["failures"]] == \
        ["a(exp(2*pi*i/3))", "a(exp(4*pi*i/3))"]


@pytest.mark.parametrize("bad", [1, 0, -3, "x", 2.5, True])
def test_bad_arity(bad):
    with pytest.raises(AnalysisError, match="arity must be an integer >= 2"):
        check_arity(bad)


# --------------------------------------------------------------------------------------------
# 4. transition matrices: normalisation checked against the independent residue-sum norms
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("slug,param", [("ternary-dd-4", {}), ("quaternary-dd-4", {}),
                                        ("ternary-four-point", {"mu": R(1, 10)}),
                                        ("ternary-four-point", {"mu": R(-1, 10)})])
def test_jsr_between_spectral_radius_and_norms(slug, param):
    e = schemes.get(slug)
    a = e.symbol_at(**param)
    m = e.arity
    k, c = difference_mask(a, arity=m)
    h = holder_exponent(a, arity=m)
    # rho(c) <= ||S_c^L||^(1/L) (residue sums, no transition matrices): alpha >= k - log_m(norm)/L
    L = 3
    norm = scheme_norm(c, L, arity=m).value
    assert h.lower >= k - sp.log(norm, m) / L - R(1, 10 ** 12)
    # rho(c) >= rho(T_eps): alpha <= k - log_m rho(T_eps)
    for Te in transition_matrices(c, arity=m):
        import numpy as np

        rho = max(abs(np.linalg.eigvals(np.array(Te.evalf(20).tolist(), dtype=float))))
        if rho > 0:
            assert h.upper <= k - sp.log(sp.Float(rho) * (1 - 1e-12), m)


# --------------------------------------------------------------------------------------------
# 5. catalogue transcriptions and published claims
# --------------------------------------------------------------------------------------------

def test_ternary_lagrange_weights_by_hand():
    # f_{3i+1} from cubic interpolation of f_{i-1..i+2} at i + 1/3: L_p(1/3), computed by hand
    a = schemes.get("ternary-dd-4").symbol
    assert [a.coeff(1 - 3 * p) for p in (-1, 0, 1, 2)] == [R(-5, 81), R(60, 81), R(30, 81), R(-4, 81)]
    assert polynomial_reproduction(a, arity=3).value == 3
    assert polynomial_reproduction(schemes.get("quaternary-dd-4").symbol, arity=4).value == 3


def test_ternary_four_point_transcription():
    e = schemes.get("ternary-four-point")
    a = e.symbol
    assert [a.coeff(3 * j) for j in (-1, 0, 1)] == [0, 1, 0]                 # interpolatory
    assert F.symmetry(a).value is True
    assert sum_rules(a, arity=3).value is True                                # every mu
    assert a.subs({MU: R(1, 27)}) == schemes.get("ternary-dd-4").symbol      # the Lagrange member
    f = smoothing_factor(a, arity=3)
    assert f.value == 3 and [(c["condition"], c["k"]) for c in f.witness["exceptional"]] == [({MU: R(1, 27)}, 4)]


def test_ternary_four_point_c2_range_exact():
    """True C^2 range of the catalogue mask: (1/15, 1/9), certified on both sides (computed, not a
    published value: the mask and the paper's parameter ranges could not be checked against the paper,
    see the entry's notes; the published claims that were retrieved are checked below)."""
    a = schemes.get("ternary-four-point").symbol
    r = ck_range(a, 2, "mu", Ls=(1,), arity=3)
    assert r.status == CERTIFIED and r.witness["exact"]
    assert r.value == sp.Interval.open(R(1, 15), R(1, 9))
    # boundaries, point by point with the JSR route (independent of the norm sets)
    for mu, expected in [(R(1, 15), False), (R(1, 15) + R(1, 1000), True), (R(1, 9) - R(1, 1000), True),
                         (R(1, 9), False)]:
        s = smoothness(a.subs({MU: mu}), 2, max_L=0, max_word=0, arity=3)
        assert (s.value, s.status) == (expected, CERTIFIED), mu


def test_ternary_four_point_c1_boundaries():
    a = schemes.get("ternary-four-point").symbol
    r = ck_range(a, 1, "mu", Ls=(1, 2), arity=3)
    V = r.witness["not_Cj"]
    assert V == sp.Union(sp.Interval(-sp.oo, R(-1, 5)), sp.Interval(R(1, 3), sp.oo))
    assert r.value.sup == R(1, 3)                                         # upper boundary exact
    for mu in (R(-1, 5) + R(1, 100), R(1, 3) - R(1, 100)):
        s = smoothness(a.subs({MU: mu}), 1, max_L=0, max_word=0, arity=3)
        assert (s.value, s.status) == (True, CERTIFIED), mu


def test_ternary_four_point_published_claims():
    """The published claims that could be retrieved (the mask itself could not: see the entry's notes).

    (T) Title of Hassan, Ivrissimitzis, Dodgson, Sabin, CAGD 19 (2002) 1-18: "An interpolating 4-point
        C2 ternary stationary subdivision scheme" -- interpolatory, 4 old points per new point, C^2 for
        some tension mu.
    (B) Beccari, Casciola, Romani, "An interpolating 4-point C2 ternary non-stationary subdivision
        scheme with tension control", Introduction (https://123dok.org/document/zlgj223o-an-interpolating-point-c.html):
        "Hassan et al. (2002) showed that we can achieve higher smoothness and smaller support for the
        so-called interpolating 4-point stationary scheme, by going from binary (Dyn et al., 1987) to
        ternary."
    Each is checked against the workbench's computation on the catalogue mask, not assumed.
    """
    a = schemes.get("ternary-four-point").symbol
    # (T) interpolatory, and every rule f_{3i+r} (r = 1, 2) uses exactly 4 coarse points for generic mu
    assert [a.coeff(3 * j) for j in (-2, -1, 0, 1, 2)] == [0, 0, 1, 0, 0]
    for r in (1, 2):
        assert sum(1 for j in range(-3, 4) if a.coeff(r - 3 * j) != 0) == 4
    # (T) C^2 for some mu: the certified C^2 range is non-empty (it is (1/15, 1/9), test above)
    c2 = ck_range(a, 2, "mu", Ls=(1,), arity=3)
    assert c2.status == CERTIFIED and not c2.value.is_empty
    mu0 = (c2.value.inf + c2.value.sup) / 2
    s = smoothness(a.subs({MU: mu0}), 2, max_L=0, max_word=0, arity=3)       # independent JSR route
    assert (s.value, s.status) == (True, CERTIFIED)
    # (B) smaller support: ternary [-5/2, 5/2] (length 5) vs binary 4-point [-3, 3] (length 6), generic parameters
    b = schemes.get("four-point")
    w = b.params[0]
    assert basic_limit_support(a.subs({MU: mu0}), arity=3).value == (R(-5, 2), R(5, 2))
    assert basic_limit_support(b.symbol.subs({w: R(1, 16)}), arity=2).value == (-3, 3)
    # (B) higher smoothness: the binary 4-point scheme is C^2 for no w: for w != 1/16 it has two smoothing
    # factors and C^2 needs three (Dyn-Levin, Acta Numerica 2002, Sect. 4); at w = 1/16 certified not C^2
    f = smoothing_factor(b.symbol, arity=2)
    assert f.value == 2 and [(c["condition"], c["k"]) for c in f.witness["exceptional"]] == [({w: R(1, 16)}, 4)]
    s = smoothness(b.symbol.subs({w: R(1, 16)}), 2, arity=2)
    assert (s.value, s.status) == (False, CERTIFIED)


# --------------------------------------------------------------------------------------------
# 6. CLI
# --------------------------------------------------------------------------------------------

def _run(*argv):
    from analysis.cli.main import main
    import contextlib
    import io

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(argv))
    return rc, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("bad", ["1", "0", "x", "2.5", "-3"])
def test_cli_bad_arity_one_line(bad, capfd):
    p = run_cli(capfd, "holder", "--mask", "1,1", f"--arity={bad}")
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr.count("\n") == 1 and p.stderr.startswith("subdiv: error: --arity must be an integer >= 2")


def test_cli_mary_json_and_binary_only_commands(capfd):
    p = run_cli(capfd, "holder", "--scheme", "ternary-bspline-3", "--C", "2", "--json")
    doc = json.loads(p.stdout)
    assert doc["arity"] == 3 and doc["alpha"]["value"] == 3 and doc["smoothness"]["value"] is True
    # atlas takes m-ary input since the second half of issue 12 (tests/test_arity_claims.py):
    # a missing axis is still a one-line error
    p = run_cli(capfd, "atlas", "--scheme", "ternary-bspline-2")
    assert p.returncode == 2 and "give both axes" in p.stderr and p.stderr.count("\n") == 1


@pytest.mark.parametrize("argv", [
    ["symbol", "--mask", "1/4,3/4,3/4,1/4", "--start", "-2"],
    ["norm", "--scheme", "four-point", "--param", "w=1/16", "--m", "2", "--L", "1,2"],
    ["norm", "--scheme", "four-point", "--m", "2", "--solve", "w"],
    ["matrices", "--scheme", "bspline-3", "--transition"],
    ["holder", "--scheme", "bspline-2", "--C", "1", "--json"],
    ["refine", "--scheme", "chaikin", "--points", "0,0;1,0;1,1", "--steps", "2", "--exact"],
])
def test_cli_arity_two_equals_default(argv):
    def timeless(r):          # wall-clock times (top-level "timing" of a JSON document) differ from run to run
        try:
            out = json.loads(r[1])
        except ValueError:
            return r
        out.pop("timing", None)
        return r[0], out, r[2]

    assert timeless(_run(*argv)) == timeless(_run(*argv, "--arity", "2"))


def test_cli_list_mary_and_sobolev():
    rc, out, _ = _run("list", "--mary", "--json")
    rows = {r["slug"]: r for r in json.loads(out)["schemes"]}
    assert rows["ternary-four-point"]["arity"] == 3 and "arity" not in rows["chaikin"]
    rc, out, _ = _run("holder", "--scheme", "ternary-bspline-2", "--sobolev", "--json")
    s2 = json.loads(out)["sobolev"]                # B-spline of degree 2: s_2 = 5/2 (tests/test_sobolev_arity.py)
    assert rc == 0 and (s2["status"], s2["value"]) == ("certified", "5/2")


def test_cli_arity_two_is_byte_identical(capfd):
    p1 = run_cli(capfd, "factor", "--mask", "1/4,3/4,3/4,1/4", "--start", "-2")
    p2 = run_cli(capfd, "factor", "--mask", "1/4,3/4,3/4,1/4", "--start", "-2", "--arity", "2")
    assert p1.returncode == 0 and p1.stdout == p2.stdout and p1.stderr == p2.stderr
