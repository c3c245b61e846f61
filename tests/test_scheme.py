"""Tests of analysis.stationary.refinement: refinement of polygons and basic limit functions.

Convention: (S_a f)_k = sum_j a_{k-2j} f_j, a(z) = sum_i a_i z^i.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from analysis.result import AnalysisError
from analysis.stationary.refinement import basic_limit_function, point_reflection, refine, refined_indices
from analysis.algebra.symbol import LaurentSymbol

# ---------------------------------------------------------------------------------------------
# schemes
# ---------------------------------------------------------------------------------------------

LINEAR = LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)
CHAIKIN = LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2)
CUBIC = LaurentSymbol.from_mask([1, 4, 6, 4, 1], start=-2) / 8
W = Fraction(1, 16)
FOUR = LaurentSymbol.from_mask([-W, 0, Fraction(1, 2) + W, 1, Fraction(1, 2) + W, 0, -W], start=-3)
FOUR_PARAM = LaurentSymbol.from_mask(["-w", 0, "1/2+w", 1, "1/2+w", 0, "-w"], start=-3)
# Dyn-Floater-Hormann / seed 003 scheme (1) at omega = (sqrt(6)-1)/80: an algebraic mask
_w = (sp.sqrt(6) - 1) / 80
_q = sp.Rational(1, 4)
DFH_SQRT6 = LaurentSymbol.from_rules(even=[-7 * _w, 3 * _q + 9 * _w, _q + 3 * _w, -5 * _w],
                                     odd=[-5 * _w, _q + 3 * _w, 3 * _q + 9 * _w, -7 * _w], first=-1)

SCHEMES = {"linear": LINEAR, "chaikin": CHAIKIN, "cubic": CUBIC, "four-point": FOUR}
RATIONAL_SCHEMES = [pytest.param(v, id=k) for k, v in SCHEMES.items()]
DIMS = [pytest.param(None, id="R1-flat"), pytest.param(1, id="R1"), pytest.param(2, id="R2"),
        pytest.param(3, id="R3")]


def coefficients(a: LaurentSymbol) -> dict[int, Fraction]:
    return {i: Fraction(int(c.p), int(c.q)) for i, c in a.items() if c != 0}


def brute(a: LaurentSymbol, f, ks, value):
    """(S_a f)_k = sum_j a_{k-2j} value(j) for k in ks, one point at a time (reference)."""
    coeff = coefficients(a)
    out = []
    for k in ks:
        total = 0
        for i, c in coeff.items():
            if (k - i) % 2 == 0:
                total = total + c * value((k - i) // 2)
        out.append(total)
    return np.array(out, dtype=object)


def data(n: int, dim, *, seed: int = 0, exact: bool = False):
    rng = np.random.default_rng(seed)
    ints = rng.integers(-50, 50, size=(n,) if dim is None else (n, dim))
    if exact:
        return np.vectorize(lambda v: Fraction(int(v), 3), otypes=[object])(ints)
    return ints / 3.0


def as_float(x) -> np.ndarray:
    return np.asarray(x, dtype=float)


# ---------------------------------------------------------------------------------------------
# linear B-spline, Chaikin: hand-checked values
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("dim", DIMS)
@pytest.mark.parametrize("closed", [True, False], ids=["closed", "open"])
def test_linear_bspline_interpolates_and_inserts_midpoints(dim, closed):
    f = data(7, dim)
    g = refine(LINEAR, f, closed=closed)
    assert g.shape[1:] == f.shape[1:]
    assert len(g) == (14 if closed else 13)
    np.testing.assert_array_equal(g[0::2], f)                         # interpolatory
    nxt = np.roll(f, -1, axis=0)
    np.testing.assert_allclose(g[1::2], ((f + nxt) / 2)[:len(g[1::2])], rtol=0, atol=1e-14)


def test_chaikin_closed_square():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    expected = [[1, 0], [3, 0], [4, 1], [4, 3], [3, 4], [1, 4], [0, 3], [0, 1]]
    out = refine(CHAIKIN, square)
    np.testing.assert_array_equal(out, np.array(expected) / 4)
    exact = refine(CHAIKIN, square, exact=True)
    assert exact.dtype == object and all(isinstance(v, Fraction) for v in exact.flat)
    assert (exact * 4 == np.array(expected)).all()
    # two steps: 16 points, still inside the square and symmetric about its centre
    two = refine(CHAIKIN, square, steps=2)
    assert two.shape == (16, 2)
    np.testing.assert_allclose(two + two[np.r_[8:16, 0:8]], 1.0, atol=1e-15)


# ---------------------------------------------------------------------------------------------
# correctness against the one-point-at-a-time definition
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("a", RATIONAL_SCHEMES)
@pytest.mark.parametrize("n", [1, 2, 3, 9], ids=lambda n: f"n{n}")
def test_closed_matches_definition(a, n):
    f = data(n, None, exact=True, seed=n)
    got = refine(a, f)
    want = brute(a, f, range(2 * n), lambda j: f[j % n])
    assert list(got) == list(want)


@pytest.mark.parametrize("a", RATIONAL_SCHEMES)
@pytest.mark.parametrize("rule", ["interior", "extrapolate"])
def test_open_matches_definition(a, rule):
    n = 9
    f = data(n, None, exact=True, seed=3)

    def value(j):
        if 0 <= j < n:
            return f[j]
        assert rule == "extrapolate", "interior rule read outside the data"
        return 2 * f[0] - f[-j] if j < 0 else 2 * f[n - 1] - f[2 * (n - 1) - j]

    ks = refined_indices(a, n, closed=False, end_rule=rule)
    assert list(refine(a, f, closed=False, end_rule=rule)) == list(brute(a, f, ks, value))


@pytest.mark.parametrize("a", RATIONAL_SCHEMES)
@pytest.mark.parametrize("closed,rule", [(True, "interior"), (False, "interior"),
                                         (False, "extrapolate")],
                         ids=["closed", "open-interior", "open-extrapolate"])
@pytest.mark.parametrize("dim", DIMS)
def test_exact_equals_float(a, closed, rule, dim):
    f_exact = data(12, dim, exact=True)
    f_float = data(12, dim)
    e = refine(a, f_exact, 3, closed=closed, end_rule=rule)
    x = refine(a, f_float, 3, closed=closed, end_rule=rule)
    assert e.dtype == object and x.dtype == np.float64 and e.shape == x.shape
    np.testing.assert_allclose(as_float(e), x, rtol=1e-13, atol=1e-13)
    # exact=True with float data reads the floats exactly and gives the same numbers
    np.testing.assert_allclose(as_float(refine(a, f_float, 3, closed=closed, end_rule=rule,
                                               exact=True)), x, rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("a", RATIONAL_SCHEMES)
def test_k_steps_is_repeated_application(a):
    f = data(10, 2)
    g = f
    for _ in range(3):
        g = refine(a, g)
    np.testing.assert_array_equal(refine(a, f, steps=3), g)
    assert len(g) == 10 * 2**3
    h = f
    for _ in range(3):
        h = refine(a, h, closed=False, end_rule="extrapolate")
    np.testing.assert_array_equal(refine(a, f, 3, closed=False, end_rule="extrapolate"), h)


def test_steps_zero_returns_a_copy():
    f = data(5, 2)
    g = refine(CUBIC, f, steps=0)
    np.testing.assert_array_equal(g, f)
    assert g is not f and not np.shares_memory(g, f)


# ---------------------------------------------------------------------------------------------
# 4-point scheme: interpolation and cubic reproduction (exact)
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("dim", DIMS)
@pytest.mark.parametrize("exact", [False, True], ids=["float", "exact"])
def test_four_point_is_interpolatory(dim, exact):
    f = data(11, dim, exact=exact)
    g = refine(FOUR, f)
    assert (g[0::2] == f).all()
    g = refine(FOUR, f, closed=False)                                 # interior: k = 2..2n-4
    assert (g[0::2] == f[1:-1]).all()


def cubic_poly(t):
    return 3 * t**3 - Fraction(5, 2) * t**2 + Fraction(1, 7) * t - 4


@pytest.mark.parametrize("steps", [1, 2, 3], ids=lambda s: f"steps{s}")
def test_four_point_reproduces_cubics_exactly(steps):
    n = 12
    t = [Fraction(j) for j in range(n)]
    f = np.array([[cubic_poly(s), s**3, 1 - s**2] for s in t], dtype=object)
    g = refine(FOUR, f, steps, closed=False, exact=True)
    # track the parameter of each output row: new point k sits at old parameter t0 + k h / 2
    params, h = t, Fraction(1)
    for _ in range(steps):
        ks = refined_indices(FOUR, len(params), closed=False)
        params = [params[0] + Fraction(k) * h / 2 for k in ks]
        h /= 2
    want = np.array([[cubic_poly(s), s**3, 1 - s**2] for s in params], dtype=object)
    assert g.shape == want.shape and (g == want).all()


def test_four_point_parameter_values_and_general_w():
    f = data(8, 2)
    np.testing.assert_array_equal(refine(FOUR_PARAM, f, params={"w": "1/16"}), refine(FOUR, f))
    # w = 0 is the linear B-spline
    np.testing.assert_array_equal(refine(FOUR_PARAM, f, params={"w": 0}), refine(LINEAR, f))


# ---------------------------------------------------------------------------------------------
# cubic B-spline: linear reproduction, basic limit function
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("dim", DIMS)
def test_cubic_bspline_reproduces_linear_data_away_from_ends(dim):
    n = 10
    rng = np.random.default_rng(1)
    shape = () if dim is None else (dim,)
    p0, p1 = rng.integers(-9, 9, size=shape) / 4, rng.integers(1, 9, size=shape) / 4
    line = lambda s: p0 + np.multiply.outer(s, p1)  # noqa: E731
    f = line(np.arange(n, dtype=float))
    # interior rule: every new point k sits at k/2 and is exactly on the line
    ks = np.array(refined_indices(CUBIC, n, closed=False))
    np.testing.assert_allclose(refine(CUBIC, f, closed=False), line(ks / 2), atol=1e-13)
    # closed: the wrap-around rows are off the line, those away from the ends are on it
    g = refine(CUBIC, f)
    k = np.arange(2, 2 * n - 3)
    np.testing.assert_allclose(g[k], line(k / 2), atol=1e-13)
    assert not np.allclose(g[[0, -1]], line(np.array([0.0, (2 * n - 1) / 2])))
    # point reflection keeps data linear, so the extrapolate rule is exact up to the ends
    ks = np.array(refined_indices(CUBIC, n, closed=False, end_rule="extrapolate"))
    np.testing.assert_allclose(refine(CUBIC, f, 2, closed=False, end_rule="extrapolate")[[0, -1]],
                               f[[0, -1]], atol=1e-13)
    np.testing.assert_allclose(refine(CUBIC, f, closed=False, end_rule="extrapolate"),
                               line(ks / 2), atol=1e-13)


def b3(x: Fraction) -> Fraction:
    """The centred cubic B-spline on [-2, 2]."""
    x = abs(x)
    if x >= 2:
        return Fraction(0)
    if x >= 1:
        return (2 - x) ** 3 / 6
    return Fraction(2, 3) - x**2 + x**3 / 2


def test_basic_limit_function_cubic_bspline_level6():
    level = 6
    x, v = basic_limit_function(CUBIC, level)
    assert x.dtype == np.float64 and len(x) == len(v) == 4 * (2**level - 1) + 1
    assert x[0] == -2 + 2 / 2**level and x[-1] == 2 - 2 / 2**level    # inside [start, end]
    phi = np.array([float(b3(Fraction(t).limit_denominator(2**level))) for t in x])
    # v_j - phi(x_j) = -(second difference of v)/6 = O(h^2 max|B3''|/6), h = 2^-6
    assert np.max(np.abs(v - phi)) < 2 / (6 * 4**level) + 1e-12
    np.testing.assert_allclose(v[np.isclose(x, 0)], 2 / 3, atol=1e-4)
    # exact: the level-6 values are the B-spline control points of phi, so
    # phi(j/64) = (v_{j-1} + 4 v_j + v_{j+1}) / 6 holds exactly
    xe, ve = basic_limit_function(CUBIC, level, exact=True)
    assert all(isinstance(t, Fraction) for t in list(xe) + list(ve))
    padded = [Fraction(0)] + list(ve) + [Fraction(0)]
    for j, t in enumerate(xe):
        assert (padded[j] + 4 * padded[j + 1] + padded[j + 2]) / 6 == b3(t)
    np.testing.assert_allclose(as_float(ve), v, atol=1e-15)
    np.testing.assert_array_equal(as_float(xe), x)


@pytest.mark.parametrize("a", RATIONAL_SCHEMES)
@pytest.mark.parametrize("level", [0, 1, 4], ids=lambda k: f"level{k}")
def test_basic_limit_function_support_and_partition_of_unity(a, level):
    x, v = basic_limit_function(a, level, exact=True)
    scale = 2**level
    assert x[0] == Fraction(a.start * (scale - 1), scale) and x[-1] == Fraction(a.end * (scale - 1), scale)
    assert a.start <= x[0] and x[-1] <= a.end
    for r in range(scale):                    # sum over each residue class mod 2^level is 1
        assert sum(v[j] for j in range(len(v)) if (x[j] * scale) % scale == r) == 1
    # refining the delta sequence as an open polygon padded with zeros gives the same numbers
    pad = (a.end - a.start) * scale
    delta = np.zeros(2 * pad + 1, dtype=object)
    delta[:] = Fraction(0)
    delta[pad] = Fraction(1)
    g = refine(a, delta, level, closed=True)  # periodic, but the padding keeps the ends apart
    lo = a.start * (scale - 1) + pad * scale
    assert list(g[lo:lo + len(v)]) == list(v)


def test_basic_limit_function_linear_is_hat_and_four_point_interpolates():
    x, v = basic_limit_function(LINEAR, 5, exact=True)
    assert all(vj == 1 - abs(xj) for xj, vj in zip(x, v))
    x, v = basic_limit_function(FOUR, 5, exact=True)
    at_integers = {int(xj): vj for xj, vj in zip(x, v) if xj.denominator == 1}
    assert at_integers == {-2: 0, -1: 0, 0: 1, 1: 0, 2: 0}
    x, v = basic_limit_function(CHAIKIN, 7)                          # dual: support [-2, 1]
    assert -2 < x[0] and x[-1] < 1
    # with x = j/2^k the samples' centre of mass is -1/2 + 2^-(k+1): an O(h) shift for dual schemes
    np.testing.assert_allclose(np.sum(x * v) / np.sum(v), -0.5 + 2.0**-8, atol=1e-12)
    xc, vc = basic_limit_function(CHAIKIN, 7, centre=True)          # x = (j + m)/2^k, m = -1/2
    np.testing.assert_array_equal(vc, v)
    np.testing.assert_array_equal(xc, x - 0.5 / 2**7)
    np.testing.assert_allclose(np.sum(xc * vc) / np.sum(vc), -0.5, atol=1e-12)


def quadratic_bspline(x: Fraction) -> Fraction:
    """The quadratic B-spline on [-2, 1] (Chaikin's basic limit function), centred at -1/2."""
    t = x + 2
    if t <= 0 or t >= 3:
        return Fraction(0)
    if t < 1:
        return t * t / 2
    if t < 2:
        return (-2 * t * t + 6 * t - 3) / 2
    return (3 - t) ** 2 / 2


@pytest.mark.parametrize("level", [4, 6, 8], ids=lambda k: f"level{k}")
def test_centred_samples_are_second_order_for_a_dual_scheme(level):
    x, v = basic_limit_function(CHAIKIN, level, exact=True)
    xc, _ = basic_limit_function(CHAIKIN, level, exact=True, centre=True)
    err_plain = max(abs(vj - quadratic_bspline(xj)) for xj, vj in zip(x, v))
    err_centred = max(abs(vj - quadratic_bspline(xj)) for xj, vj in zip(xc, v))
    h = Fraction(1, 2**level)
    assert h / 4 <= err_plain <= h                                  # first order
    assert err_centred <= h * h                                     # second order


def test_algebraic_mask_float_refinement():
    f = data(9, 2)
    got = refine(DFH_SQRT6, f, 2)
    coeff = {i: float(sp.N(c, 30)) for i, c in DFH_SQRT6.items()}
    g = f
    for _ in range(2):
        n = len(g)
        g = np.array([sum(c * g[((k - i) // 2) % n] for i, c in coeff.items() if (k - i) % 2 == 0)
                      for k in range(2 * n)])
    np.testing.assert_allclose(got, g, rtol=1e-13, atol=1e-13)
    x, v = basic_limit_function(DFH_SQRT6, 3)
    assert abs(v.sum() - 8) < 1e-12
    with pytest.raises(AnalysisError, match="rational"):
        refine(DFH_SQRT6, f, exact=True)
    with pytest.raises(AnalysisError, match="rational"):
        basic_limit_function(DFH_SQRT6, 3, exact=True)


# ---------------------------------------------------------------------------------------------
# open polygons: the three end rules
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name,rule,n,expected", [
    ("linear", "interior", 6, range(0, 11)),
    ("linear", "extrapolate", 6, range(0, 11)),
    ("chaikin", "interior", 6, range(0, 10)),
    ("chaikin", "extrapolate", 6, range(0, 10)),
    ("cubic", "interior", 6, range(1, 10)),
    ("cubic", "extrapolate", 6, range(0, 11)),
    ("four-point", "interior", 6, range(2, 9)),
    ("four-point", "extrapolate", 6, range(0, 11)),
    ("four-point", "closed", 6, range(0, 12)),
], ids=lambda v: v if isinstance(v, str) else None)
def test_refined_indices(name, rule, n, expected):
    closed = rule == "closed"
    got = refined_indices(SCHEMES[name], n, closed=closed,
                          end_rule="interior" if closed else rule)
    assert got == expected
    out = refine(SCHEMES[name], data(n, 2), closed=closed, end_rule="interior" if closed else rule)
    assert len(out) == len(expected)


@pytest.mark.parametrize("a", RATIONAL_SCHEMES)
def test_interior_rule_reads_only_the_data(a):
    """Change everything outside the data: the kept points must not move."""
    n = 8
    f = data(n, 2)
    ks = np.array(refined_indices(a, n, closed=False))
    for garbage in (0.0, 1e6):
        padded = np.full((3 * n, 2), garbage)
        padded[n:2 * n] = f
        full = refine(a, padded)                                  # closed, 6n points
        np.testing.assert_array_equal(full[ks + 2 * n], refine(a, f, closed=False))


@pytest.mark.parametrize("dim", DIMS)
def test_extrapolate_rule_boundary_stencils(dim):
    f = data(6, dim, exact=True)
    g = refine(FOUR, f, closed=False, end_rule="extrapolate")
    # ghost P_{-1} = 2 P_0 - P_1:  new[1] = 7/16 P0 + 10/16 P1 - 1/16 P2; end points kept
    assert np.all(g[1] == Fraction(7, 16) * f[0] + Fraction(10, 16) * f[1] - Fraction(1, 16) * f[2])
    assert np.all(g[-2] == Fraction(7, 16) * f[-1] + Fraction(10, 16) * f[-2] - Fraction(1, 16) * f[-3])
    assert np.all(g[0] == f[0]) and np.all(g[-1] == f[-1])
    c = refine(CUBIC, f, closed=False, end_rule="extrapolate")     # natural end: P0 interpolated
    assert np.all(c[0] == f[0]) and np.all(c[-1] == f[-1])


@pytest.mark.parametrize("dim", DIMS)
def test_callable_end_rule(dim):
    f = data(7, dim)
    calls = []

    def reflect(points, side, count):
        calls.append((points.shape, side, count))
        return point_reflection(points, side, count)

    np.testing.assert_array_equal(refine(FOUR, f, 2, closed=False, end_rule=reflect),
                                  refine(FOUR, f, 2, closed=False, end_rule="extrapolate"))
    assert calls[0] == (f.shape, "left", 1) and calls[1] == (f.shape, "right", 1)

    def repeat_end(points, side, count):                         # constant extension
        row = points[0] if side == "left" else points[-1]
        return np.stack([row] * count)

    g = refine(CUBIC, f, closed=False, end_rule=repeat_end)
    # new[0] = (P_{-1} + 6 P0 + P1)/8 with P_{-1} = P0
    np.testing.assert_allclose(g[0], (7 * f[0] + f[1]) / 8, atol=1e-14)
    # exact data: the callable sees Fractions and may return Fractions
    fe = data(7, dim, exact=True)
    seen = []

    def exact_rule(points, side, count):
        seen.append(type(points.flat[0]))
        return point_reflection(points, side, count)

    ge = refine(CUBIC, fe, closed=False, end_rule=exact_rule)
    assert seen and seen[0] is Fraction
    assert list(ge.flat) == list(refine(CUBIC, fe, closed=False, end_rule="extrapolate").flat)


def test_point_reflection_is_rule_3_9_and_3_10():
    p = np.array([[0, 0], [1, 2], [3, 3], [6, 3]], dtype=float)
    left = point_reflection(p, "left", 3)      # P_{-3}, P_{-2}, P_{-1}
    np.testing.assert_array_equal(left, [2 * p[0] - p[3], 2 * p[0] - p[2], 2 * p[0] - p[1]])
    right = point_reflection(p, "right", 2)    # P_4, P_5
    np.testing.assert_array_equal(right, [2 * p[3] - p[2], 2 * p[3] - p[1]])


def test_chaikin_extrapolate_equals_interior():
    """For a dual scheme the kept points' centres are inside the data: no ghost is read."""
    f = data(9, 2)
    np.testing.assert_array_equal(refine(CHAIKIN, f, 3, closed=False, end_rule="extrapolate"),
                                  refine(CHAIKIN, f, 3, closed=False))


def test_end_rule_is_ignored_for_closed_polygons():
    f = data(5, 2)
    np.testing.assert_array_equal(refine(FOUR, f, end_rule="extrapolate"), refine(FOUR, f))


# ---------------------------------------------------------------------------------------------
# data types
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("values,exact_expected", [
    pytest.param([0, 1, 2, 4], False, id="ints"),
    pytest.param([0.0, 1.0, 2.0, 4.0], False, id="floats"),
    pytest.param(np.array([0.0, 1.0, 2.0, 4.0], dtype=object), False, id="object-floats"),
    pytest.param([Fraction(0), Fraction(1), Fraction(2), Fraction(4)], True, id="fractions"),
    pytest.param([sp.Integer(0), sp.Rational(1), sp.Rational(2), sp.Integer(4)], True, id="sympy"),
    pytest.param(np.array([0, 1, 2, 4], dtype=object), True, id="object-ints"),
])
def test_data_types_choose_the_arithmetic(values, exact_expected):
    out = refine(CUBIC, values)
    assert (out.dtype == object) == exact_expected
    np.testing.assert_allclose(as_float(out), refine(CUBIC, [0.0, 1.0, 2.0, 4.0]), atol=1e-15)


def test_shapes_are_preserved():
    assert refine(CUBIC, np.zeros(5)).shape == (10,)
    assert refine(CUBIC, np.zeros((5, 1))).shape == (10, 1)
    assert refine(CUBIC, np.zeros((5, 3)), 2).shape == (20, 3)
    assert refine(CUBIC, np.zeros((1, 2))).shape == (2, 2)      # one point, closed


# ---------------------------------------------------------------------------------------------
# bad inputs: one-line AnalysisError
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("call,match", [
    (lambda: refine(FOUR_PARAM, [0.0, 1.0, 2.0]), "parameter"),
    (lambda: basic_limit_function(FOUR_PARAM, 3), "parameter"),
    (lambda: refine(FOUR_PARAM, [0.0, 1.0], params={"nope": 1}), "unknown parameter"),
    (lambda: refine(CUBIC, []), "no data"),
    (lambda: refine(CUBIC, np.zeros((0, 2))), "no data"),
    (lambda: refine(CUBIC, np.zeros((3, 0))), "no data"),
    (lambda: refine(CUBIC, [0.0, float("nan"), 1.0]), "NaN"),
    (lambda: refine(CUBIC, [[0.0, 1.0], [float("inf"), 1.0]]), "NaN or infinite"),
    (lambda: refine(CUBIC, [Fraction(1), float("nan")]), "NaN"),
    (lambda: refine(CUBIC, [[0.0, 1.0], [1.0]]), "shape"),
    (lambda: refine(CUBIC, np.zeros((2, 2, 2))), "shape"),
    (lambda: refine(CUBIC, ["a", "b"]), "real numbers"),
    (lambda: refine(CUBIC, [1 + 2j, 0j]), "real numbers"),
    (lambda: refine(CUBIC, [sp.sqrt(2), sp.Integer(1)]), "rational"),
    (lambda: refine([1, 2, 1], [0.0, 1.0]), "LaurentSymbol"),
    (lambda: refine(CUBIC, [0.0, 1.0], steps=-1), "steps"),
    (lambda: refine(CUBIC, [0.0, 1.0], steps=1.5), "steps"),
    (lambda: refine(CUBIC, [0.0, 1.0], closed=False, end_rule="mirror"), "end_rule"),
    (lambda: refine(CUBIC, [0.0, 1.0], closed=False, end_rule=3), "end_rule"),
    (lambda: refine(FOUR, [0.0, 1.0], closed=False), "too short"),
    (lambda: refine(FOUR, [0.0, 1.0, 2.0, 3.0], 3, closed=False), "too short"),  # 4 -> 3 -> 1 -> !
    (lambda: refine(CUBIC, [0.0], closed=False, end_rule="extrapolate"), "point reflection"),
    (lambda: refine(CUBIC, [0.0, 1.0, 2.0], closed=False, end_rule=lambda p, s, c: [0.0] * (c + 1)),
     "must return"),
    (lambda: refine(CUBIC, [0.0, 1.0, 2.0], closed=False, end_rule=lambda p, s, c: [np.nan] * c),
     "NaN"),
    (lambda: refine(CUBIC, [0.0, 1.0, 2.0], closed=False, end_rule=lambda p, s, c: 1 / 0),
     "callable failed"),
    (lambda: basic_limit_function(CUBIC, -1), "level"),
    (lambda: refined_indices(CUBIC, 0), "positive integer"),
], ids=["param-refine", "param-blf", "param-unknown", "empty-list", "empty-rows", "empty-cols",
        "nan", "inf", "nan-exact", "ragged", "3d", "strings", "complex", "irrational-data",
        "not-a-symbol", "negative-steps", "fractional-steps", "unknown-end-rule", "end-rule-type",
        "interior-too-short", "interior-shrinks-away", "reflection-too-short", "ghost-shape",
        "ghost-nan", "ghost-raises", "negative-level", "zero-points"])
def test_bad_inputs_raise_one_line_analysis_error(call, match):
    with pytest.raises(AnalysisError, match=match) as info:
        call()
    assert "\n" not in str(info.value)
