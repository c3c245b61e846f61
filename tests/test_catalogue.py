"""Tests of the scheme catalogue (schemes/): registry, exact identities, paper transcriptions.

The seed 004 tests rebuild scheme (3.6) from the paper's construction (3.1)-(3.5) and check the
transcribed coefficients (whose minus signs and fraction bars were lost in text extraction)
against it, and the sub-schemes (3.7), (3.8) against substitutions into (3.6).
"""

from __future__ import annotations

import dataclasses
import re

import pytest
import sympy as sp

import schemes
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol, Rules
from schemes import classic, seed003, seed004
from schemes.catalogue import SchemeEntry

ENTRIES = schemes.entries()
SLUGS = [e.slug for e in ENTRIES]
MU, NU, OMEGA = seed004.MU, seed004.NU, seed004.OMEGA


def _from(rules: Rules) -> LaurentSymbol:
    return LaurentSymbol.from_rules(rules.even, rules.odd, even_first=rules.even_first,
                                    odd_first=rules.odd_first)


# --------------------------------------------------------------------------------------------
# the registry
# --------------------------------------------------------------------------------------------

def test_names_are_unique_kebab_case_and_in_entry_order():
    assert schemes.names() == SLUGS
    assert len(set(SLUGS)) == len(SLUGS)
    for slug in schemes.names(aliases=True):
        assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", slug), slug


def test_expected_slugs_are_present():
    expected = {f"bspline-{d}" for d in range(1, 8)} | {
        "chaikin", "four-point", "dfh-chaikin-perturbation", "seed004-design-control",
        "seed004-t-nu", "seed004-l-mu"}
    assert expected <= set(SLUGS)


@pytest.mark.parametrize("alias, slug", [("cubic-bspline", "bspline-3"),
                                         ("linear-bspline", "bspline-1")],
                         ids=["cubic-bspline", "linear-bspline"])
def test_alias_resolves_to_its_entry(alias, slug):
    assert schemes.get(alias) is schemes.get(slug)
    assert alias not in schemes.names()


@pytest.mark.parametrize("name, hint", [("four-piont", "four-point"), ("chaikn", "chaikin"),
                                        ("bspline-9", "bspline-"), ("seed004", "seed004-")],
                         ids=["typo", "missing-letter", "bad-degree", "prefix"])
def test_unknown_slug_is_a_one_line_error_with_close_matches(name, hint):
    with pytest.raises(AnalysisError) as info:
        schemes.get(name)
    message = str(info.value)
    assert "\n" not in message
    assert f"unknown scheme {name!r}" in message
    assert hint in message


def test_unknown_slug_without_close_match_points_to_names():
    with pytest.raises(AnalysisError, match=r"schemes\.names\(\)"):
        schemes.get("zzzz")


def test_symbol_at_unknown_parameter_is_an_error():
    with pytest.raises(AnalysisError, match="no parameter nu"):
        schemes.get("four-point").symbol_at(nu=1)


def test_index_is_current():
    """``schemes/index.py`` (what ``subdiv list`` shows, and which module defines each name, without
    building an entry) is what the entry modules define now."""
    from schemes import indexer

    assert indexer.current() == indexer.stored(), "schemes/index.py is stale: run python -m schemes.indexer --write"


@pytest.mark.parametrize("numeric, mary", [(False, False), (True, False), (False, True), (True, True)])
def test_names_and_listing_are_the_entries(numeric, mary):
    """The names and the listing (read from the index, nothing built) agree with the built entries,
    in order; ``get`` returns the very entry ``entries`` lists."""
    built = schemes.entries(numeric=numeric, mary=mary)
    assert schemes.names(numeric=numeric, mary=mary) == [e.slug for e in built]
    assert [(r.slug, r.title, r.params, r.source, r.arity) for r in schemes.listing(numeric=numeric, mary=mary)] == \
        [(e.slug, e.title, tuple(p.name for p in e.params), e.source, getattr(e, "arity", 2)) for e in built]
    assert all(schemes.get(e.slug) is e for e in built)
    assert all(schemes.get(a) is schemes.get(t) for a, t in schemes.catalogue._ALIASES.items())


def test_get_builds_only_its_own_module():
    """``get`` imports the module that defines the name, not the rest of the catalogue."""
    import subprocess
    import sys

    code = ("import sys, schemes\nschemes.get('chaikin')\n"
            "print(sorted(m for m in sys.modules if m.startswith('schemes.')))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["['schemes.catalogue',", "'schemes.classic',", "'schemes.index']"]


def test_entries_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        schemes.get("four-point").slug = "x"


def test_entry_params_must_match_symbol():
    w = sp.Symbol("w")
    with pytest.raises(ValueError, match="params"):
        SchemeEntry(slug="bad", title="", symbol=LaurentSymbol.from_mask([w, 1, 1 - w]),
                    params=(), source="")


# --------------------------------------------------------------------------------------------
# identities of every entry
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("entry", ENTRIES, ids=SLUGS)
def test_params_are_the_symbols_parameters(entry):
    assert set(entry.params) == set(entry.symbol.params)
    assert entry.param_names == tuple(p.name for p in entry.params)
    assert set(entry.defaults) <= set(entry.param_names)


@pytest.mark.parametrize("entry", ENTRIES, ids=SLUGS)
def test_sum_rules_hold_identically_in_the_parameters(entry):
    assert sp.expand(entry.symbol(1) - 2) == 0
    assert sp.expand(entry.symbol(-1)) == 0
    even, odd = entry.symbol.subsymbols()
    assert sp.expand(even(1) - 1) == 0 and sp.expand(odd(1) - 1) == 0


@pytest.mark.parametrize("entry", ENTRIES, ids=SLUGS)
def test_symmetric(entry):
    a = entry.symbol
    c = a.start + a.end
    for i, ai in a.items():
        assert sp.expand(ai - a.coeff(c - i)) == 0, (entry.slug, i)


@pytest.mark.parametrize("entry", [e for e in ENTRIES if e.stencils is not None],
                         ids=[e.slug for e in ENTRIES if e.stencils is not None])
def test_stencils_define_the_symbol(entry):
    assert _from(entry.stencils) == entry.symbol


@pytest.mark.parametrize("entry", [e for e in ENTRIES if e.defaults],
                         ids=[e.slug for e in ENTRIES if e.defaults])
def test_default_symbol_substitutes_the_defaults(entry):
    a = entry.default_symbol()
    assert a == entry.symbol.subs(dict(entry.defaults))
    assert a(1) == 2 and a(-1) == 0


# --------------------------------------------------------------------------------------------
# classic schemes
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("d", list(classic.BSPLINE_DEGREES),
                         ids=[f"degree-{d}" for d in classic.BSPLINE_DEGREES])
def test_bspline_mask_is_binomial_over_power_of_two(d):
    a = schemes.get(f"bspline-{d}").symbol
    assert a.mask == tuple(sp.Rational(sp.binomial(d + 1, k), 2**d) for k in range(d + 2))
    assert a.start == -((d + 1) // 2)
    assert a.is_numeric


def test_chaikin_is_the_quadratic_bspline_shifted():
    chaikin = schemes.get("chaikin").symbol
    assert chaikin.mask == tuple(sp.Rational(n, 4) for n in (1, 3, 3, 1))
    assert chaikin.start == -2
    assert chaikin == schemes.get("bspline-2").symbol.shift(-1)


def test_four_point_is_interpolatory_for_every_w():
    entry = schemes.get("four-point")
    a = entry.symbol
    assert entry.param_names == ("w",)
    for i, ai in a.items():
        if i % 2 == 0:
            assert ai == (1 if i == 0 else 0), i


def test_four_point_default_is_the_cubic_deslauriers_dubuc_mask():
    entry = schemes.get("four-point")
    assert entry.defaults == {"w": sp.Rational(1, 16)}
    assert entry.default_symbol() == LaurentSymbol.from_mask(
        [sp.Rational(n, 16) for n in (-1, 0, 9, 16, 9, 0, -1)], start=-3)


def test_four_point_at_w_zero_is_the_linear_bspline():
    assert schemes.get("four-point").symbol_at(w=0) == schemes.get("bspline-1").symbol


# --------------------------------------------------------------------------------------------
# seed 003
# --------------------------------------------------------------------------------------------

def test_dfh_at_omega_zero_is_chaikin():
    dfh = schemes.get("dfh-chaikin-perturbation")
    assert dfh.symbol_at(omega=0) == schemes.get("chaikin").symbol


def test_dfh_at_one_over_128_is_seed004_rule_3_1():
    """omega = 1/128 (the default) gives the cubic-reproducing dual 4-point scheme."""
    dfh = schemes.get("dfh-chaikin-perturbation")
    assert dfh.defaults == {"omega": sp.Rational(1, 128)}
    assert dfh.default_symbol() == _from(seed004.RULE_3_1)


def test_dfh_mask_as_in_symbol_module():
    a = schemes.get("dfh-chaikin-perturbation").symbol
    w = seed003.OMEGA
    q = sp.Rational(1, 4)
    assert a.start == -4
    assert a.mask == (-5 * w, -7 * w, q + 3 * w, 3 * q + 9 * w,
                      3 * q + 9 * w, q + 3 * w, -7 * w, -5 * w)


# --------------------------------------------------------------------------------------------
# seed 004: the construction (3.1)-(3.5) reproduces the transcribed (3.6)
# --------------------------------------------------------------------------------------------

def _rule(stencil, first, shift=0) -> dict[int, sp.Expr]:
    """A rule as {p: coefficient of P_{i+p}}, for the refined point index moved by 2*shift."""
    return {first + k + shift: sp.sympify(c) for k, c in enumerate(stencil)}


def _combine(*terms) -> dict[int, sp.Expr]:
    out: dict[int, sp.Expr] = {}
    for scale, rule in terms:
        for p, c in rule.items():
            out[p] = sp.expand(out.get(p, 0) + scale * c)
    return out


def _rules_from(even: dict, odd: dict) -> Rules:
    def dense(d):
        lo, hi = min(d), max(d)
        return tuple(sp.expand(d.get(p, 0)) for p in range(lo, hi + 1)), lo
    e, ef = dense(even)
    o, of = dense(odd)
    return Rules(e, ef, o, of)


def _construction(mu, nu, omega) -> Rules:
    """P_{2i} = Q_{2i} - DE, P_{2i+1} = Q_{2i+1} - DO from (3.1), (3.2) and (3.5)."""
    Q, R = seed004.RULE_3_1, seed004.RULE_3_2
    q_even, q_odd = _rule(Q.even, Q.even_first), _rule(Q.odd, Q.odd_first)
    r_even, r_odd = _rule(R.even, R.even_first), _rule(R.odd, R.odd_first)
    d_even = _combine((1, q_even), (-1, r_even))                     # D_{2i}
    d_odd = _combine((1, q_odd), (-1, r_odd))                        # D_{2i+1}

    def shifted(d, m):                                               # D_{j+2m}
        return {p + m: c for p, c in d.items()}

    de = _combine((mu, shifted(d_even, -1)), (nu, d_even), (omega, shifted(d_even, 1)))
    do = _combine((omega, shifted(d_odd, -1)), (nu, d_odd), (mu, shifted(d_odd, 1)))
    return _rules_from(_combine((1, q_even), (-1, de)), _combine((1, q_odd), (-1, do)))


def test_seed004_displacements_3_3_are_q_minus_r():
    Q, R, D = seed004.RULE_3_1, seed004.RULE_3_2, seed004.RULE_3_3
    assert D.even == tuple(q - r for q, r in zip(Q.even, R.even))
    assert D.odd == tuple(q - r for q, r in zip(Q.odd, R.odd))


def test_seed004_displacements_3_4_are_shifts_of_3_3():
    """(3.4) as printed: D_{2i-2}, D_{2i-1} on P_{i-2..i+1}; D_{2i+2}, D_{2i+3} on P_{i..i+3}."""
    D = seed004.RULE_3_3
    printed_even = tuple(sp.Rational(n, 128) for n in (-21, 35, -7, -7))
    printed_odd = tuple(sp.Rational(n, 128) for n in (-7, -7, 35, -21))
    assert D.even == printed_even and D.odd == printed_odd
    # the shifted displacements of (3.4) are the same stencils one step left / right
    assert _rule(D.even, D.even_first, -1) == _rule(printed_even, -2)
    assert _rule(D.odd, D.odd_first, +1) == _rule(printed_odd, 0)


def test_seed004_parent_schemes():
    """(3.1) is the cubic-reproducing dual 4-point scheme, (3.2) the degree-6 B-spline."""
    assert _from(seed004.RULE_3_2) == schemes.get("bspline-6").symbol.shift(-1)
    q = _from(seed004.RULE_3_1)
    assert q(1) == 2 and q(-1) == 0


def test_seed004_construction_reproduces_the_transcribed_rules_3_6():
    built = _construction(MU, NU, OMEGA)
    printed = seed004.RULE_3_6
    assert (built.even_first, built.odd_first) == (printed.even_first, printed.odd_first)
    assert all(sp.expand(b - p) == 0 for b, p in zip(built.even, printed.even, strict=True))
    assert all(sp.expand(b - p) == 0 for b, p in zip(built.odd, printed.odd, strict=True))
    assert _from(built) == schemes.get("seed004-design-control").symbol


def test_seed004_odd_rule_is_the_mirror_of_the_even_rule():
    r = seed004.RULE_3_6
    assert r.odd == tuple(reversed(r.even))


def test_seed004_printed_mask_3_6_is_the_entry_mask():
    assert schemes.get("seed004-design-control").symbol.mask == seed004.PRINTED_MASK_3_6


@pytest.mark.parametrize("values, slug, shift", [
    ({"mu": 0, "nu": 0, "omega": 0}, None, 0),
    ({"mu": 0, "nu": 1, "omega": 0}, "bspline-6", -1),
], ids=["Q-is-rule-3.1", "R-is-bspline-6"])
def test_seed004_parents_are_special_cases(values, slug, shift):
    a = schemes.get("seed004-design-control").symbol_at(**values)
    expected = _from(seed004.RULE_3_1) if slug is None else schemes.get(slug).symbol.shift(shift)
    assert a == expected


# --------------------------------------------------------------------------------------------
# seed 004: sub-schemes (3.7), (3.8)
# --------------------------------------------------------------------------------------------

def test_seed004_t_nu_is_3_6_at_mu_omega_zero():
    full = schemes.get("seed004-design-control").symbol
    assert schemes.get("seed004-t-nu").symbol == full.subs({"mu": 0, "omega": 0})
    assert _from(_construction(0, NU, 0)) == schemes.get("seed004-t-nu").symbol


def test_seed004_l_mu_is_3_6_at_omega_mu_nu_one_minus_two_mu():
    full = schemes.get("seed004-design-control").symbol
    assert schemes.get("seed004-l-mu").symbol == full.subs({"omega": MU, "nu": 1 - 2 * MU})
    assert schemes.get("seed004-l-mu").symbol.mask == seed004.PRINTED_MASK_3_8


def test_seed004_remark_3_3_construction_gives_l_mu():
    """Remark 3.3: DE = D_{2i} + mu[(D_{2i-2} - D_{2i}) + (D_{2i+2} - D_{2i})], i.e. the
    construction with (mu, nu, omega) = (mu, 1 - 2 mu, mu), gives the printed (3.8)."""
    assert _from(_construction(MU, 1 - 2 * MU, MU)) == schemes.get("seed004-l-mu").symbol


@pytest.mark.parametrize("nu, matches", [(1 - 2 * MU, True), (2 * MU + 1, False), (12 * MU, False),
                                         (2 * MU - 1, False)],
                         ids=["1-2mu", "2mu+1-as-printed", "12mu-as-printed", "2mu-1"])
def test_seed004_reading_of_the_l_mu_substitution(nu, matches):
    """Only nu = 1 - 2 mu reproduces the printed l_k of (3.8)."""
    sub = schemes.get("seed004-design-control").symbol.subs({"omega": MU, "nu": nu})
    assert (sub == schemes.get("seed004-l-mu").symbol) is matches


@pytest.mark.parametrize("k, value", [
    (5, sp.Rational(21, 128) * MU),
    (3, sp.Rational(7, 64) - sp.Rational(77, 128) * MU),
    (1, sp.Rational(35, 64) + sp.Rational(49, 64) * MU),
    (-1, sp.Rational(21, 64) - sp.Rational(21, 64) * MU),
    (-3, sp.Rational(1, 64) - sp.Rational(7, 128) * MU),
    (-5, sp.Rational(7, 128) * MU),
], ids=["l5", "l3", "l1", "l-1", "l-3", "l-5"])
def test_seed004_printed_l_coefficients(k, value):
    """The paper's l_k is the coefficient of (3.6) at omega = mu, nu = 1 - 2 mu.

    The paper's label k is our index k - 1."""
    a = seed004.A_3_6[k].subs({OMEGA: MU, NU: 1 - 2 * MU}, simultaneous=True)
    assert sp.expand(a - value) == 0
    assert seed004.L_3_8[k] == value
    assert schemes.get("seed004-l-mu").symbol.coeff(k - 1) == value


def test_seed004_l_mu_at_zero_is_the_degree_6_bspline():
    assert schemes.get("seed004-l-mu").symbol_at(mu=0) == schemes.get("bspline-6").symbol.shift(-1)
