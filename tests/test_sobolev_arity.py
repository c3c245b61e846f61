"""Issue 12, item "Sobolev exponents": the m-ary L2-Sobolev exponent s_2 = -(1/2) log_m lambda.

Expected values are computed independently or are classical facts:
* the B-spline of order d + 1 (degree d) is in H^s exactly for s < d + 1/2 (its Fourier transform decays like
  |xi|^-(d+1)); the m-ary B-spline of degree d is that same function, so s_2 = d + 1/2 for every arity;
* m = 2: the binary code (:func:`analysis.regularity.sobolev.sobolev_exponent`, stability reduction) is an
  independent route (the m-ary code uses the autocorrelation eigenvector instead) — property test;
* Hölder and Sobolev exponents of a compactly supported function satisfy alpha <= s_2 <= alpha + 1/2
  (L-infinity Hölder => H^s for s < alpha; Sobolev embedding H^s in C^(s - 1/2)), checked against the
  certified m-ary Hölder exponent on the ternary 4-point family;
* the stable-case formula s_2 = N - (1/2) log_m rho(T_Q) (Villemoes; Jia 1999 for dilation m), evaluated in
  floating point with numpy on random stable ternary masks.
"""

from __future__ import annotations

import contextlib
import io
import json
import random

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings, strategies as st

import schemes
from analysis.algebra.symbol import LaurentSymbol
from analysis.regularity.holder import holder_exponent
from analysis.regularity.sobolev import _autocorrelation_route, autocorrelation_symbol, sobolev_exponent
from analysis.regularity.stability import stable_shifts
from analysis.result import CERTIFIED, INCONCLUSIVE, AnalysisError

R = sp.Rational
Z = sp.Symbol("z")
MU = sp.Symbol("mu")


def _q(m):
    return sum(Z ** i for i in range(m))


@pytest.mark.parametrize("m", [3, 4])
@pytest.mark.parametrize("d", [1, 2, 3, 4, 5])
def test_mary_bspline_sobolev_is_d_plus_one_half(m, d):
    e = schemes.get({3: "ternary", 4: "quaternary"}[m] + f"-bspline-{d}")
    r = sobolev_exponent(e.symbol, arity=m)
    assert (r.value, r.status) == (R(2 * d + 1, 2), CERTIFIED)
    assert r.witness["minimal_polynomial_root"] == R(1, m ** (2 * d + 1))


# m = 2: the m-ary code against the binary code ------------------------------------------------

_ints = st.lists(st.integers(-4, 6), min_size=1, max_size=4).filter(lambda v: sum(v) != 0)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_ints, st.integers(0, 4), st.integers(-3, 1))
def test_arity_two_equals_binary_sobolev(b, N, start):
    expr = sp.expand(((1 + Z) / 2) ** N * sum(c * Z ** i for i, c in enumerate(b)))
    a = LaurentSymbol.from_expr(2 * expr / expr.subs(Z, 1)).shift(start)
    mine, binary = _autocorrelation_route(a, 2), sobolev_exponent(a)
    assert mine.status == binary.status
    if binary.status == CERTIFIED:
        assert mine.value == binary.value
        if binary.value is None:
            assert mine.lower <= binary.upper and binary.lower <= mine.upper
            assert mine.upper - mine.lower < R(1, 10 ** 9)


def test_arity_two_unstable_box_and_four_point():
    box = LaurentSymbol.from_mask([1, 0, 0, 1])                 # box on [0, 3]: unstable, s_2 = 1/2
    assert _autocorrelation_route(box, 2).value == sobolev_exponent(box).value == R(1, 2)
    four = LaurentSymbol.from_mask(["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"], start=-3)
    mine, binary = _autocorrelation_route(four, 2), sobolev_exponent(four)
    assert mine.lower <= binary.upper and binary.lower <= mine.upper


# ternary examples ----------------------------------------------------------------------------

def test_unstable_ternary_masks():
    # phi_a = (phi_b + phi_b(.-1) + phi_b(.-2))/3 with phi_b the ternary quadratic B-spline: unstable, s_2 = 5/2
    a = LaurentSymbol.from_expr((1 + Z ** 3 + Z ** 6) * _q(3) ** 2 / 9)
    st_ = stable_shifts(a, arity=3)
    assert st_.value is False and st_.witness["q"] == LaurentSymbol.from_mask([1, 1, 1])
    assert sobolev_exponent(a, arity=3).value == R(5, 2)
    # phi = (hat + hat(.-1))/2 (a zero at exp(i pi/3), not a cube root of unity): s_2 = 3/2
    a = LaurentSymbol.from_expr(_q(3) ** 2 * (1 - Z + Z ** 2) / 3)
    st_ = stable_shifts(a, arity=3)                                 # since round 2: blocking cycle {pi} (Phi_6 | a)
    assert st_.value is False and st_.witness["q"] == LaurentSymbol.from_mask([1, 1])
    assert sobolev_exponent(a, arity=3).value == R(3, 2)           # the autocorrelation route needs no stability


def test_autocorrelation_of_the_ternary_hat():
    # hat on [0, 2]: int hat(x) hat(x - k) dx = 2/3, 1/6 (k = 0, +-1)
    w, dim = autocorrelation_symbol(schemes.get("ternary-bspline-1").symbol, 3)
    assert dim == 1 and w.mask == (R(1, 6), R(2, 3), R(1, 6)) and w.start == -1


@pytest.mark.parametrize("mu", ["-1/10", "0", "1/27", "1/15", "1/10", "1/5"])
def test_ternary_four_point_between_holder_and_holder_plus_half(mu):
    a = schemes.get("ternary-four-point").symbol.subs({MU: R(mu)})
    s2, h = sobolev_exponent(a, arity=3), holder_exponent(a, arity=3)
    assert s2.status == h.status == CERTIFIED
    assert h.lower <= s2.upper and s2.lower <= h.upper + R(1, 2)
    assert s2.upper - s2.lower < R(1, 10 ** 9)


def _random_stable_ternary(count, seed=20261124):
    rng = random.Random(seed)
    out = []
    while len(out) < count:
        b = [rng.randint(-3, 8) for _ in range(rng.randint(1, 4))]
        N = rng.randint(1, 3)
        expr = sp.expand(_q(3) ** N * sum(c * Z ** i for i, c in enumerate(b)))
        if expr.subs(Z, 1) == 0:
            continue
        a = LaurentSymbol.from_expr(3 * expr / expr.subs(Z, 1))
        if stable_shifts(a, arity=3).value is True:
            out.append((a, N + sp.degree(sp.gcd(sp.Poly(sum(c * Z ** i for i, c in enumerate(b)), Z),
                                                  sp.Poly(_q(3), Z)), Z)))
    return out


def test_stable_formula_agrees_on_random_ternary_masks():
    """s_2 = N - (1/2) log_3 rho(T_Q), Q = c c*/3, c = 3^N a/q_3^N, (T_Q)_ij = Q_(3i-j): numpy eigenvalues."""
    checked = 0
    for a, N in _random_stable_ternary(12):
        c = sp.Poly(sp.cancel(a.expr() * Z ** (-a.start) * 3 ** N / _q(3) ** N), Z).all_coeffs()[::-1]
        c = np.array([float(x) for x in c])
        Q = np.convolve(c, c[::-1]) / 3
        n = len(c) - 1
        idx = range(-n, n + 1)
        T = np.array([[Q[3 * i - j + n] if abs(3 * i - j) <= n else 0.0 for j in idx] for i in idx])
        expected = N - 0.5 * np.log(max(abs(np.linalg.eigvals(T)))) / np.log(3)
        r = sobolev_exponent(a, arity=3)
        if expected < 0.01:                     # phi not in L2: lambda >= 1, an inconclusive is the answer
            assert r.status == INCONCLUSIVE
            continue
        checked += 1
        assert r.status == CERTIFIED
        assert float(r.lower) - 1e-9 <= expected <= float(r.upper) + 1e-9
    assert checked >= 6


def test_bad_input():
    with pytest.raises(AnalysisError, match="a\\(1\\) = 3"):
        sobolev_exponent(LaurentSymbol.from_mask([1, 1]), arity=3)
    with pytest.raises(AnalysisError, match="arity"):
        sobolev_exponent(LaurentSymbol.from_mask([1, 1]), arity=1)
    with pytest.raises(AnalysisError):
        sobolev_exponent(schemes.get("ternary-four-point").symbol, arity=3)       # a parameter left
    r = sobolev_exponent(LaurentSymbol.from_mask([3]), arity=3)                 # phi = delta, not in L2
    assert r.status == INCONCLUSIVE and "L2" in r.witness["reason"]


def _run(*argv):
    from analysis.cli.main import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(argv))
    return rc, out.getvalue(), err.getvalue()


def test_cli_holder_sobolev_mary():
    rc, out, err = _run("holder", "--scheme", "ternary-bspline-3", "--sobolev")
    assert rc == 0 and "L2-Sobolev exponent s_2 = 7/2 exactly   [certified]" in out
    rc, out, _ = _run("holder", "--scheme", "ternary-four-point", "--param", "mu=1/10", "--sobolev", "--json")
    d = json.loads(out)["sobolev"]
    assert d["status"] == CERTIFIED and 2.41 < float(sp.Rational(d["lower"])) < 2.42
