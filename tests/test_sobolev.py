"""The L2-Sobolev exponent with or without stable shifts (issue 9.4): regression and checks."""

import random
import time

import flint
import pytest
import sympy as sp

import schemes
from analysis.cli import main
from analysis.regularity import sobolev_exponent as regularity_sobolev_exponent
from analysis.result import AnalysisError
from analysis.regularity.sobolev import (_log2_bounds, berlekamp_massey, sobolev_exponent, sobolev_stable_formula,
                              sobolev_stable_formula_exact)
from analysis.regularity.stability import stable_shifts
from analysis.algebra.symbol import LaurentSymbol

Q = sp.Rational
D4 = ["(1+sqrt(3))/4", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3))/4"]


def sym(expr):
    return LaurentSymbol.from_expr(expr)


def exact(r, value):
    assert r.status == "certified" and r.value == value and r.lower == r.upper == value, r


def test_sobolev_of_box_on_0_3_is_one_half_not_zero():
    a = LaurentSymbol.from_mask([1, 0, 0, 1])
    r = sobolev_exponent(a)
    exact(r, Q(1, 2))
    assert r.witness["stable_shifts"].value is False
    assert r.witness["q"] == LaurentSymbol.from_mask([1, 1, 1])
    # the stable-case formula, wrongly applied, gives 0 (the bug): the two methods differ here
    N, lo, hi, k = sobolev_stable_formula_exact(a)
    assert N + Q(k, 2) == 0                                 # rho(T_Q) = 4 = 2^-k
    # the public name in analysis.regularity.holder is the same function
    exact(regularity_sobolev_exponent(a), Q(1, 2))


@pytest.mark.parametrize("d", range(0, 6))
def test_bspline_sobolev_is_n_minus_one_half(d):
    """B-spline of degree d (d + 1 factors (1+z)): s_2 = d + 1/2 (|phi^| ~ |xi|^-(d+1))."""
    a = LaurentSymbol.from_mask([1, 1]) if d == 0 else schemes.get(f"bspline-{d}").symbol
    exact(sobolev_exponent(a), Q(2 * d + 1, 2))


def test_hat_function():
    exact(sobolev_exponent(LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1)), Q(3, 2))


def test_four_point_matches_readme_value():
    r = sobolev_exponent(schemes.get("four-point").symbol_at(w=Q(1, 16)))
    assert r.status == "certified" and r.upper - r.lower < Q(1, 10**20)
    assert r.lower <= Q(244077, 100000) + Q(1, 10**5) and r.upper >= Q(244077, 100000) - Q(1, 10**5)


def test_sobolev_of_algebraic_daubechies_d4():
    """D4 over QQ(sqrt 3): s_2 = 1 (Villemoes 1994; Eirola 1992), exactly, in well under 2 s."""
    t = time.perf_counter()
    r = sobolev_exponent(LaurentSymbol.from_mask(D4))
    assert time.perf_counter() - t < 2
    exact(r, 1)
    assert r.witness["stable_shifts"].value is True


@pytest.mark.parametrize("expr,value,stable", [
    ("(1+z)*(1+z**2)/2", Q(3, 2), False),            # box[0,1] * box[0,2]/2: piecewise linear
    ("(1+z)**2*(1-z+z**2)/2", Q(3, 2), False),       # box[0,1] * box[0,3]/3
    ("(1+z)**2*(1+z**2)/4", Q(5, 2), False),         # hat * box[0,2]/2: piecewise quadratic
    ("(1+z)*(1+z**5)/2", Q(3, 2), False),            # blocking 5-cycle
    ("(1+z)*(z**2-4)/(-3)", None, True),             # symmetric zeros +-2 off the circle: stable
], ids=["1+z^2", "1-z+z^2", "hat*box2", "Phi10", "off-circle"])
def test_masks_with_cyclotomic_factors(expr, value, stable):
    """True values by the reduction phi_a = q(tau) phi_b / q(1): s_2(phi_a) = s_2(phi_b), phi_b a
    B-spline (q(tau) is a finite combination of shifts, and |q|^2 vanishes only at finitely many
    points mod 2pi, where the cancelled zeros of phi_b^'s periodisation are not)."""
    a = sym(expr)
    r = sobolev_exponent(a)
    assert r.witness["stable_shifts"].value is stable
    if value is not None:
        exact(r, value)
        b = r.witness["reduced_mask"]
        exact(sobolev_exponent(b), value)
    else:
        assert r.status == "certified"
        N, lo, hi, _ = sobolev_stable_formula_exact(a)         # stable: the formula applies
        l2lo, l2hi = _log2_bounds(lo, hi)
        assert N - l2hi / 2 <= r.upper and r.lower <= N - l2lo / 2


def test_algebraic_symmetric_pair_on_the_circle():
    """Over QQ(sqrt 3): zeros with z^2 = e^{+-5 i pi/6}; the reduced b is stable, and s_2(phi_a) =
    s_2(phi_b) is checked against the stable-case formula applied to b (an independent route)."""
    a = sym("(1+z)*(z**4+sqrt(3)*z**2+1)/(2+sqrt(3))")
    r = sobolev_exponent(a)
    assert r.witness["stable_shifts"].value is False and r.status == "certified"
    assert r.upper - r.lower < Q(1, 10**20)
    b = r.witness["reduced_mask"]
    assert stable_shifts(b).value is True
    N, lo, hi, _ = sobolev_stable_formula_exact(b)
    l2lo, l2hi = _log2_bounds(lo, hi)
    assert N - l2hi / 2 <= r.upper and r.lower <= N - l2lo / 2
    assert 0.998 < float(r.lower) < 0.999


@pytest.mark.parametrize("name,literature", [("d6", "1.4150"), ("d8", "1.7756"), ("d10", "2.0968")])
def test_daubechies_ball_masks(name, literature):
    """Villemoes (1994), Table 1, compared at the printed digits."""
    r = sobolev_exponent(schemes.get(name))
    assert r.status == "certified" and r.witness["stable_shifts"].value is True
    assert r.upper - r.lower < Q(1, 10**20)
    assert round(float(r.lower), 4) == float(literature)


def test_ball_route_agrees_with_exact_route_for_d4():
    r_exact = sobolev_exponent(LaurentSymbol.from_mask(D4))
    r_ball = sobolev_exponent(schemes.get("d4"))
    assert r_ball.status == "certified" and r_ball.lower <= r_exact.value <= r_ball.upper


def _random_stable_masks(count, seed=20240609):
    rng = random.Random(seed)
    out = []
    while len(out) < count:
        N, m = rng.randint(1, 4), rng.randint(0, 3)
        c = [Q(rng.randint(-4, 6)) for _ in range(m + 1)]
        if sum(c) == 0 or c[0] == 0 or c[-1] == 0:
            continue
        a = LaurentSymbol.from_mask([x * 2 / sum(c) for x in c]) * LaurentSymbol.from_mask(["1/2", "1/2"]) ** N
        if stable_shifts(a).value is True:
            out.append(a)
    return out


def test_stable_formula_agrees_with_sequence_method():
    """Before trusting N - (1/2) log2 rho(T_Q) for ball masks: on 40 random stable rational masks it
    agrees with the exact sequence method (enclosures overlap, both certified)."""
    compared = 0
    for a in _random_stable_masks(40):
        r = sobolev_exponent(a)
        if r.status != "certified":          # s_2 <= 0: only [lower, 0] is proven
            continue
        N, lo, hi, _ = sobolev_stable_formula_exact(a)
        l2lo, l2hi = _log2_bounds(lo, hi)
        assert N - l2hi / 2 <= r.upper and r.lower <= N - l2lo / 2, a
        compared += 1
    assert compared >= 30


def test_ball_formula_on_enclosed_rational_masks():
    for a in _random_stable_masks(10, seed=7):
        N, lo, hi, _ = sobolev_stable_formula_exact(a)
        with flint.ctx.workprec(300):
            from analysis.jsr._exact import sympy_to_arb
            balls = [sympy_to_arb(x) for x in a.mask]
        enc = sobolev_stable_formula(balls, N)
        if enc is None:                      # defective eigenvalues: the ball route says inconclusive
            continue
        blo, bhi, _ = enc
        assert blo <= hi and lo <= bhi


def test_berlekamp_massey_fibonacci():
    fib = [sp.QQ(1), sp.QQ(1)]
    for _ in range(10):
        fib.append(fib[-1] + fib[-2])
    assert berlekamp_massey(fib, sp.QQ) == [1, -1, -1]


def test_non_convergent_mask_and_normalisation():
    r = sobolev_exponent(LaurentSymbol.from_mask(["1/2", 1, "1/2"], start=-1) * LaurentSymbol.from_mask(["3/4", "1/4"])
                         * 1)                                      # a(-1) = 0 still; sanity
    assert r.status == "certified"
    nc = LaurentSymbol.from_mask(["3/4", "1/2", "3/4"], start=-1)  # a(1) = 2, a(-1) = 1: no sum rule
    r = sobolev_exponent(nc)
    assert r.witness["N"] == 0 and r.upper is not None
    delta = sobolev_exponent(LaurentSymbol.from_mask([2]))       # phi = delta: s_2 = -1/2, not in L2
    assert delta.status == "inconclusive" and delta.lower <= Q(-1, 2) and delta.upper == 0
    with pytest.raises(AnalysisError, match=r"a\(1\) = 2"):
        sobolev_exponent(LaurentSymbol.from_mask([1, 1, 1]))


def test_cli_box_prints_one_half_and_the_reduction(capsys):
    assert main(["holder", "--mask", "1,0,0,1", "--start", "0", "--sobolev"]) in (0, None)
    out = capsys.readouterr().out
    assert "s_2 = 1/2 exactly   [certified]" in out
    assert "shifts unstable [certified]" in out and "{e^(2πi/3), e^(4πi/3)}" in out
    assert "q(z) = 1 + z + z^2, b(z) = 1 + z" in out


def test_one_failing_part_does_not_hide_the_others(capsys):
    """phi = delta (a = 2): the scheme does not converge (a certified verdict), and stability
    and the Sobolev part still report."""
    assert main(["holder", "--mask", "2", "--start", "0", "--sobolev"]) in (0, None)
    out = capsys.readouterr().out
    assert "not convergent [certified]: a(-1) = 2 != 0" in out
    assert "shifts stable [certified]" in out
    assert "s_2 in [-0.5000000000, 0.0000000000]   [inconclusive]" in out


def test_cli_daubechies_ball_entry(capsys):
    assert main(["holder", "--scheme", "d6", "--sobolev"]) in (0, None)
    out = capsys.readouterr().out
    assert "s_2 in [1.4150374992, 1.4150374993]   [certified]" in out
    assert "shifts stable [certified]" in out
