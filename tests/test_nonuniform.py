"""NVPS (seeds 000/001): refinement vs a direct per-point implementation, limits, reproduction,
definitions compared, decay rates, Property A structure, CLI and bad inputs."""

import json
import math
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from analysis import nonuniform as nu
from analysis.cli import main
from analysis.result import AnalysisError

X = ["analysis.cli.nonuniform"]


# --------------------------------------------------------------------------------------------
# a direct per-point implementation, written from the papers' formulas (seed 001 (2), (3), (6),
# Algorithm 1 step 3 with its two cases; seed 000's binomial sum with tau_d), loops only
# --------------------------------------------------------------------------------------------

def direct_step_001(P, u, d):
    """Open polygon P_0..P_n, parameters u_0..u_{n-1}."""
    n = len(P) - 1

    def s2(i):  # (S_2 P)_i, rule (3)
        e, odd = divmod(i, 2)
        w = 1 / (2 * (1 + u[e]))
        a, b = P[e], P[e + 1]
        return w * a + (1 - w) * b if odd else (1 - w) * a + w * b

    def s(dd, i):  # recursion (6)
        return s2(i) if dd == 2 else (s(dd - 1, i) + s(dd - 1, i + 1)) / 2

    new = [s(d, i) for i in range(2 * n - (d - 2))]
    up = [math.sqrt((1 + x) / 2) for x in u]
    if d % 2 == 0:  # u^2 of rule (2), then u^d_j = u^{d-2}_{j+1}
        u2 = [up[(j + 1) // 2] for j in range(2 * n - 1)]
        unew = [u2[j + (d - 2) // 2] for j in range(2 * n - d + 1)]
    else:  # Case 1: u^3_0 = u_0, u^3_{2n-3} = u_{n-1}, u^3_{2i+1} = u^3_{2i+2} = u_{i+1}
        u3 = [None] * (2 * n - 2)
        u3[0], u3[2 * n - 3] = up[0], up[n - 1]
        for i in range(n - 2):
            u3[2 * i + 1] = u3[2 * i + 2] = up[i + 1]
        unew = [u3[j + (d - 3) // 2] for j in range(2 * n - d + 1)]
    return np.array(new), unew


def direct_step_000_closed(P, lam, d):
    n = len(P)
    tau = math.ceil((d - 2) / 2)

    def s2(i):
        e, odd = divmod(i % (2 * n), 2)
        w = 1 / (2 * (1 + lam[e]))
        a, b = P[e], P[(e + 1) % n]
        return w * a + (1 - w) * b if odd else (1 - w) * a + w * b

    new = [sum(math.comb(d - 2, j) * s2(i + j - tau) for j in range(d - 1)) / 2 ** (d - 2) for i in range(2 * n)]
    return np.array(new), [math.sqrt((1 + lam[j // 2]) / 2) for j in range(2 * n)]


@pytest.mark.parametrize("d", [2, 3, 4, 5, 6], ids=lambda d: f"d{d}")
def test_refine_matches_direct_open_seed001(d):
    rng = np.random.default_rng(d)
    P = rng.standard_normal(12)
    u = list(rng.uniform(0.05, 5, 11))
    r = nu.refine(P, u, degree=d, steps=3)
    Pd, ud = P, u
    for _ in range(3):
        Pd, ud = direct_step_001(Pd, ud, d)
    np.testing.assert_allclose(r.points, Pd, rtol=0, atol=1e-13)
    np.testing.assert_allclose(r.u, ud, rtol=1e-14)


@pytest.mark.parametrize("d", [2, 3, 4, 5], ids=lambda d: f"d{d}")
def test_refine_matches_direct_closed_seed000(d):
    rng = np.random.default_rng(10 + d)
    P = rng.standard_normal((7, 2))
    lam = list(rng.uniform(0.05, 5, 7))
    r = nu.refine(P, lam, degree=d, steps=2, closed=True, rule="seed000")
    Pd, ld = P, lam
    for _ in range(2):
        Pd, ld = direct_step_000_closed(Pd, ld, d)
    np.testing.assert_allclose(r.points, Pd, atol=1e-13)
    np.testing.assert_allclose(r.u, ld, rtol=1e-14)


@pytest.mark.parametrize("d", [2, 3, 4, 5], ids=lambda d: f"d{d}")
@pytest.mark.parametrize("closed", [False, True], ids=["open", "closed"])
def test_u_equal_one_is_uniform_bspline(d, closed):
    from analysis.stationary.refinement import refine as refine_stationary
    from schemes import get

    P = [Fraction(v) for v in (3, -1, 4, 1, -5, 9, 2, 6)]
    r = nu.refine(P, [1] * (len(P) if closed else len(P) - 1), degree=d, steps=2, closed=closed, arithmetic="exact")
    assert all(x == 0 for x in r.one_minus_u)
    if closed:
        a = get(f"bspline-{d}").symbol
        ref = refine_stationary(a, np.array(P, dtype=object), steps=1, closed=True, exact=True)
        one = [sp.Rational(x) for x in nu.refine(P, [1] * len(P), degree=d, steps=1, closed=True,
                                                    arithmetic="exact").points]
        ref = [sp.Rational(x.numerator, x.denominator) for x in ref]
        shift = [k for k in range(len(ref)) if list(np.roll(np.array(ref, dtype=object), k)) == one]
        assert shift, "NVPS(u=1) must equal the catalogue B-spline up to a cyclic index shift"
    # masks: all locations have the limit mask exactly
    M, start = nu.location_masks([1] * 5, degree=d, arithmetic="exact")
    lim = nu.limit_mask(d)
    assert start == lim.start and all(list(row) == list(lim.mask) for row in M)


def test_circle_reproduction_exact_up_to_rounding():
    for d in (2, 3, 5):
        r = nu.reproduce("circle", degree=d, levels=7)
        assert max(r.witness["form_error"]) < 1e-13  # every level is the predicted regular polygon
        assert all(3.9 < q < 4.1 for q in r.witness["rate"][2:])
    # d = 2: edge midpoints are limit points, and lie on the circle
    P, u = nu.circle_polygon(2.0, step_angle=math.pi / 5, count=9, degree=2)
    Q = nu.refine(P, u, degree=2, steps=6).points
    mid = (Q[1:] + Q[:-1]) / 2
    assert np.max(np.abs(np.hypot(mid[:, 0], mid[:, 1]) - 2.0)) < 1e-14


def test_hyperbola_and_parabola_deviation_decays_like_4_to_minus_k():
    for kind in ("hyperbola", "parabola"):
        r = nu.reproduce(kind, degree=3, levels=7)
        assert all(3.8 < q < 4.2 for q in r.witness["rate"][2:])
        assert r.witness["deviation"][-1] < 2e-5


def test_chamfer_example_midpoints_on_shape():
    r = nu.chamfer_example(levels=6)
    assert r.witness["midpoint_deviation"][-1] < 1e-12
    assert r.witness["rate"][-1] > 3.9


@pytest.mark.parametrize("d,same", [(2, False), (3, True), (4, False), (5, True)], ids=["d2", "d3", "d4", "d5"])
def test_definitions_compared(d, same):
    r = nu.compare_definitions(d, levels=3)
    w = r.witness
    assert w["symbolic_recursion_equals_binomial"] and w["one_step_equal_up_to_shift"]
    assert w["symbolic_one_step_equal"] is True          # 'same data rule' proved on symbolic data/parameters
    assert w["multi_level_equal"] is same
    if same:
        assert w["symbolic_multi_level_equal"] is True and w["first_difference"] is None
    else:
        assert w["seed000_is_mirror_of_seed001"] and w["symbolic_mirror"] is True
        fd = w["first_difference"]                       # the exact counterexample: a nonzero rational difference
        assert sp.Rational(fd["seed000"]) - sp.Rational(fd["seed001"]) == sp.Rational(fd["difference"]) != 0
    assert r.status == "certified"


def test_compare_definitions_same_needs_symbolic_proof(monkeypatch):
    # if the symbolic comparison cannot prove equality, "same" is only numerical (one rational example)
    monkeypatch.setattr("analysis.nonuniform.definitions._same_symbolic", lambda xs, ys: False)
    r = nu.compare_definitions(3, levels=2)
    assert r.witness["multi_level_equal"] and r.status == "numerical"
    r2 = nu.compare_definitions(2, levels=2)             # the 'same data rule' part is unproved too
    assert r2.status == "numerical"


def test_u_convergence_rate_is_4_to_minus_k_certified():
    b = nu.u_convergence_bound(sp.Rational(1, 2), 3, levels=40)
    assert b.status == "certified"
    assert isinstance(b.upper, sp.Rational)              # exact, rounded up: never a round-to-nearest float
    assert 2 <= b.upper < 2 + sp.Rational(1, 10 ** 25)   # max(acos(1/2)^2/2 = 0.548, 3 - 1 = 2)
    b2 = nu.u_convergence_bound(sp.Rational(1, 2), sp.Rational(3, 4), levels=10)
    exact = sp.acos(sp.Rational(1, 2)) ** 2 / 2          # pi^2/18: the constant is irrational
    assert isinstance(b2.upper, sp.Rational) and b2.upper > exact and b2.upper - exact < sp.Rational(1, 10 ** 25)
    lam = nu.lemma_2_1(sp.Rational(-1, 2), sp.Rational(1, 3))  # u0 < 1 only (trigonometric)
    assert lam.status == "certified"
    v = nu.parameter_from_angle(1.0)
    for k in range(30):  # 4^k (1 - cos(1/2^k)) -> 1/2
        v = nu._half_update(v, math.sqrt)
    assert abs(4 ** 30 * v - 0.5) < 1e-12


def test_mask_decay_ratio_quarter():
    r = nu.mask_decay([0.2, 1.0, 7.0], degree=3, levels=10)
    assert r.status == "certified"
    assert isinstance(r.lower, sp.Rational) and isinstance(r.upper, sp.Rational) and r.lower <= r.upper
    # end points rounded outward: the d = 2, u0 = 1/2 upper bound 2 |delta_k| encloses the exact value
    d2 = nu.mask_decay([sp.Rational(1, 2)], degree=2, levels=3, closed=True)
    u = sp.Rational(1, 2)
    for _ in range(3):
        u = sp.sqrt((1 + u) / 2)
    exact = 2 * (1 - u) / (4 * (1 + u))
    assert d2.lower <= exact <= d2.upper and d2.upper - d2.lower < sp.Rational(1, 10 ** 25)
    assert abs(r.witness["ratios"][-1] - 0.25) < 1e-3
    lvl = r.witness["levels"][-1]
    assert float(lvl["lower"]) <= lvl["float_sup"] * (1 + 1e-12) and lvl["float_sup"] <= float(lvl["upper"]) * (1 + 1e-12)


def test_symbol_identities_17_refuted_and_others_hold():
    u, z = sp.symbols("u z")
    a = (1 + (1 + 2 * u) * z + (1 + 2 * u) * z ** 2 + z ** 3) / (2 * (1 + u) * z)
    vals = [sp.simplify(sp.diff(a, z, n).subs(z, 1)) for n in range(3)]
    assert vals[0] == 2 and vals[1] == 1 and sp.simplify(vals[2] - 2 / (1 + u)) == 0
    r = nu.symbol_identities()
    assert r.witness["exact"] == {"a(1)": "2", "a'(1)": "1", "a''(1)": "2/(u + 1)"}
    # the status follows the computed comparison with the printed (17) = (1, 2, 1)
    differs = {k: sp.simplify(v - p) != 0 for k, v, p in zip(("a(1)", "a'(1)", "a''(1)"), vals, (1, 2, 1))}
    assert r.witness["differs_from_printed"] == differs
    assert r.status == ("refuted" if any(differs.values()) else "certified")
    assert r.witness["b(z)_equals_printed"] and r.witness["(12)_identities_hold"]
    assert r.witness["Lemma3.3_ratio_2(u/(1+u))^2_holds"] and r.witness["(11)_is_z_times_rule_(3)"]


def test_property_a_structure_fails_from_degree_4():
    assert nu.property_a_table(2) == []
    assert all(not x["fails_on_blended"] for x in nu.property_a_table(3))
    fails4 = [(x["m"], x["r"], x["z0"]) for x in nu.property_a_table(4) if x["fails_on_blended"]]
    assert fails4 == [(3, 1, -1)]
    r = nu.property_a([0.5] * 4 + [3.0] * 4, 4, 3, 1, -1, levels=10)
    assert r.value == "does not tend to 0"


def test_junction_third_derivative_jumps_for_degree_4():
    assert nu.junction_smoothness(3, 0.3, 4.0, levels=14).value == "omega_k -> 0"
    r = nu.junction_smoothness(4, 0.3, 4.0, levels=14)
    assert r.value == "omega_k bounded away from 0"
    assert r.witness["omega_uniform"][-1] < 1e-2 < r.witness["omega_junction"][-1]


def test_interval_and_mp_refinement_enclose_float():
    P, u = [0.0, 1.0, 3.0, 2.0], [0.3, 1.0, 2.5]
    f = nu.refine(P, u, degree=3, steps=3).points
    i = nu.refine(P, u, degree=3, steps=3, arithmetic="iv", prec=80).points
    m = nu.refine(P, u, degree=3, steps=3, arithmetic="mp", prec=200).points
    for a, b, c in zip(f, i, m):
        assert b.a <= c <= b.b and abs(float(c) - a) < 1e-14
        assert float(b.delta) < 1e-20


@pytest.mark.parametrize("kwargs,msg", [
    (dict(points=[0, 1, 2], u=[1, 1], degree=1), "degree must be an integer >= 2"),
    (dict(points=[0, 1, 2], u=[1, -1], degree=2), "u > -1"),
    (dict(points=[0, 1, 2], u=[1, 1, 1], degree=2), "give 2 edge parameters"),
    (dict(points=[0, 1], u=[1], degree=5), "needs at least"),
    (dict(points=[0, 1, 2], u=[1, float("nan")], degree=2), "NaN"),
    (dict(points=[0, 1, 2], u=[1, 1], degree=2, rule="seed002"), "unknown NVPS rule"),
    (dict(points=[0, 1, 2], u=[1, 1], degree=2, arithmetic="quad"), "unknown arithmetic"),
    (dict(points=[0, 1, 2], u=[1, 1], degree=2, steps=-1), "steps must be"),
], ids=["degree", "u", "count", "short", "nan", "rule", "arith", "steps"])
def test_bad_inputs(kwargs, msg):
    with pytest.raises(AnalysisError, match=msg):
        nu.refine(**kwargs)


def test_cli_json_and_errors(capsys):
    assert main(["nonuniform", "refine", "--degree", "2", "--points", "0,0;1,0;1,1", "--u", "1", "--json"],
                extra_modules=X) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["count"] == 4 and data["points"][0] == [0.25, 0.0]
    assert main(["nonuniform", "compare-definitions", "--degree", "3", "--json"], extra_modules=X) == 0
    assert json.loads(capsys.readouterr().out)["status"] == "certified"
    assert main(["nonuniform", "claims", "--seed", "001", "--id", "001:(17)", "--json"], extra_modules=X) == 0
    assert json.loads(capsys.readouterr().out)[0]["status"] == "refuted"
    assert main(["nonuniform", "refine", "--points", "0,0;1,0", "--u", "1,1"], extra_modules=X) == 2
    err = capsys.readouterr().err
    assert err.startswith("subdiv: error:") and err.count("\n") == 1


@pytest.mark.parametrize("argv,msg", [
    (["reproduce", "--levels", "2", "--figure", "/nonexistent/dir/x.png"], "cannot write the figure"),
    (["chamfer", "--levels", "2", "--figure", "/nonexistent/dir/x.png"], "cannot write the figure"),
    (["junction", "--u-left", "abc", "--levels", "4"], "--u-left must be a number"),
    (["junction", "--u-right", "nan", "--levels", "4"], "--u-right must be finite"),
    (["junction", "--u-left", "-3", "--levels", "4"], "u > -1"),
    (["junction", "--u-left", "-1", "--levels", "4"], "u > -1"),
], ids=["figure-dir", "chamfer-figure-dir", "u-left-text", "u-right-nan", "u-left-negative", "u-left-minus-one"])
def test_cli_bad_inputs_one_line(capsys, argv, msg):
    assert main(["nonuniform"] + argv, extra_modules=X) == 2
    err = capsys.readouterr().err
    assert err.startswith("subdiv: error:") and err.count("\n") == 1 and msg in err
    assert "Traceback" not in err


def test_figures(tmp_path):
    from analysis.report.plots import plot_blended, plot_chamfer

    p = plot_chamfer(str(tmp_path / "c.png"), levels=3)
    q = plot_blended(str(tmp_path / "b.png"), levels=3)
    assert (tmp_path / "c.png").stat().st_size > 1000 and (tmp_path / "b.png").stat().st_size > 1000
    assert p.endswith("c.png") and q.endswith("b.png")


@pytest.mark.parametrize("mod", ["papers.seed000", "papers.seed001"])
def test_seed_claims_ids_and_results(mod):
    import importlib

    m = importlib.import_module(mod)
    ids = [c["id"] for c in m.CLAIMS]
    assert len(ids) == len(set(ids)) and all(i.startswith(mod[-3:] + ":") for i in ids)
    with pytest.raises(AnalysisError, match="unknown claim"):
        m.check("nope")
