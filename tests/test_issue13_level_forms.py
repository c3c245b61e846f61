"""Issue 13, inline input: the level through powers of 4, 8, ... and symbols whose together-form has 1/h^k.

Found while testing the generalized-difference route: a symbol ``<exp B-spline> + 2**(-3n) (...)`` was read with
``1/h^3`` in its coefficients (algebraically right, but the analyticity certificate at h = 0 then failed with a
one-line error). The coefficients are now cancelled so that no negative power of h is left.
"""

import sympy as sp

from analysis.levels.ck import level_smoothness
from analysis.levels.level_dependent import H, LevelDependentScheme, to_h


def test_powers_of_two_bases_are_read_in_h():
    assert sp.simplify(to_h("4**(-n)") - H ** 2) == 0
    assert sp.simplify(to_h("8**(-(n+1))") - H ** 3 / 8) == 0
    a = LevelDependentScheme.from_mask(["1/4", "3/4 - 4**(-n)", "3/4 + 4**(-n)", "1/4"], -2)
    b = LevelDependentScheme.from_mask(["1/4", "3/4 - 2**(-2*n)", "3/4 + 2**(-2*n)", "1/4"], -2)
    assert a.mask == b.mask


def test_other_bases_are_still_refused():
    import pytest

    from analysis.result import AnalysisError
    with pytest.raises(AnalysisError, match="only through 2"):
        to_h("3**(-n)")


def test_no_negative_power_of_h_and_the_verdict_is_reached():
    sym = ("2*(1+2*c*z+z**2)*(1+z)**2/((2+2*c)*4)/z**2 + 2**(-3*n)*(1+z)**2*(1-z)**2/(16*z**2)")
    s = LevelDependentScheme.from_symbol(sym, where={"c": "cos(t/2**(n+1))"})
    for c in s.mask:
        assert not any(p.base == H and p.exp.is_negative for p in c.atoms(sp.Pow)), c
    # the same symbol, evaluated at a level: the cancelled coefficients equal the typed symbol
    z, n, t = sp.symbols("z n t")
    typed = sp.sympify(sym.replace("c", "cos(t/2**(n+1))")).subs({n: 3, t: sp.Rational(7, 5)})
    ours = sum(c.subs({H: sp.Rational(1, 8), sp.Symbol("t", real=True): sp.Rational(7, 5)}) * z ** (s.start + k)
               for k, c in enumerate(s.mask))
    assert abs(sp.N((typed - ours).subs(z, sp.Rational(3, 7)), 30)) < 1e-25
    # the perturbation is O(h^3) = O(2^-3n) after dividing (1+z)^2: Dyn-Levin on the 2nd divided differences
    # (weight 4^n) converges, so C^2 is certified; the route is named
    r = level_smoothness(s.subs({"t": 1}))
    assert r.value >= 2 and r.status == "certified"
    assert r.witness["verdicts"][2]["status"] == "certified"
