"""Issue 13: the level may enter through n itself (rational functions of n times powers of 2^-n).

Reference values computed independently of the code under test:
* a^n - a = (z-1)^4 z^-2 / (n+2)^3 has ||S_(a^n) - S_a||_inf = 8/(n+2)^3 (both residue classes sum
  |1| + |6| + |1| = |-4| + |-4| = 8), so sum_n ||.|| = 8 (zeta(3) - 1), zeta(3) = 1.2020569031595942...
  (Apery's constant), and sum_n 2^n ||.|| diverges;
* a perturbation ~ 1/(n+1) gives the harmonic series: divergent.
"""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from analysis.cli import main
from analysis.levels.balls import workprec
from analysis.levels.level_dependent import N
from analysis.levels.rational_level import (RationalLevelScheme, _Piece, level_smoothness_rational,
                                            same_support_rational, weighted_series_rational)
from analysis.result import AnalysisError

BRIEF = "(1+z)**3/4/z**2 + (z-1)**4/z**2/(n+2)**3"
CUBIC_PERTURBED = "(1+z)**4/8/z**2 + (n+1)/2**(3*n)*(1+z)**3*(1-z)/z**2/16"


def test_p_series_sum_encloses_8_zeta3_minus_1():
    s = RationalLevelScheme.from_symbol(BRIEF)
    r = weighted_series_rational(s, 0)
    exact = 8 * (mpmath.zeta(3) - 1)
    assert r.witness["verdict"] == "convergent" and r.status == "certified"
    assert float(r.lower) <= exact <= float(r.upper) and float(r.upper - r.lower) < 1e-2
    assert weighted_series_rational(s, 1).witness["verdict"] == "divergent"
    # the tail bound follows N: more levels summed, a tighter enclosure, still containing the value
    r80 = weighted_series_rational(s, 0, N_sum=80)
    assert float(r80.lower) <= exact <= float(r80.upper) and r80.upper - r80.lower < r.upper - r.lower


def test_harmonic_perturbation_diverges():
    s = RationalLevelScheme.from_symbol("(1+z)**3/4/z**2 + (z-1)**2/z/(n+1)")
    r = weighted_series_rational(s, 0)
    assert r.witness["verdict"] == "divergent" and "n^-1" in r.witness["decay"]


def test_piece_bound_is_a_majorant():
    rho = (N ** 2 - 5 * N + 7) / (N ** 3 + 1)
    p = _Piece(0, rho, sp.Poly(N ** 2 - 5 * N + 7, N), sp.Poly(N ** 3 + 1, N))
    with workprec(96):
        A = p.bound(10)
    assert p.p == 1
    for n in range(10, 400, 7):
        assert abs(float(rho.subs(N, n))) * n <= float(A.upper())
    assert float(A.upper()) < 1.5          # sup_{n >= 10} |rho| n = 1 + O(1/n): not a crude bound


def test_same_support_names_the_failure():
    s = RationalLevelScheme.from_symbol(BRIEF)
    r = same_support_rational(s)
    assert r.status == "inconclusive" and r.witness["failed"] == ["a^n_2 is not identically 0 while a_2 = 0"]
    r = level_smoothness_rational(s)
    assert r.value == -1 and r.witness["verdicts"][0]["tried"][0]["failed"] == ["same_support"]


def test_cubic_with_polynomial_times_geometric_perturbation_is_c2():
    # a^n - a = (n+1) 2^-3n (1+z)^3 (1-z) z^-2 / 16: (1+z)^3 divides a^n, the 2nd divided differences
    # differ from their limit by O(n 2^-3n): Dyn-Levin gives C^2 (the limit, the cubic B-spline, is C^2 not C^3)
    r = level_smoothness_rational(RationalLevelScheme.from_symbol(CUBIC_PERTURBED))
    ks = {v["k"]: v for v in r.witness["verdicts"]}
    assert r.value == 2 and ks[2]["route"] == "Dyn-Levin on the 2nd divided difference scheme"
    assert ks[3]["status"] == "inconclusive"


@pytest.mark.parametrize("symbol, message", [
    ("(1+z)**3/4/z**2 + cos(n)*(z-1)**4/z**2", "nor as a polynomial in 2^-n with coefficients rational in n"),
    ("(1+z)**3/4/z**2 + (z-1)**4/z**2/(n-3)**3", "undefined at level n = 3"),
    ("(1+z)**3/4/z**2 + n*(z-1)**4/z**2", "no finite limit"),
], ids=["cos(n)", "pole", "grows"])
def test_bad_input_is_one_line(capsys, symbol, message):
    assert main(["holder", "--symbol", symbol]) == 2
    err = capsys.readouterr().err
    assert err.startswith("subdiv: error: ") and err.count("\n") == 1 and message in err, err


def test_cli_holder_and_series(capsys):
    assert main(["holder", "--symbol", CUBIC_PERTURBED]) == 0
    out = capsys.readouterr().out
    assert "C^2: yes [certified] — Dyn-Levin on the 2nd divided difference scheme" in out
    assert main(["series", "--symbol", BRIEF, "--m", "0,1"]) == 0
    out = capsys.readouterr().out
    assert "m = 0: convergent" in out and "m = 1: divergent (certified)" in out


def test_non_rational_level_dependence_is_not_accepted():
    with pytest.raises(AnalysisError, match="polynomial in 2\\^-n"):
        RationalLevelScheme.from_symbol("(1+z)**2/2/z + sqrt(n)/2**n*(1-z)**2/z")
