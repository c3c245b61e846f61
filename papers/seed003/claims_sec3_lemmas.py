"""Seed 003, Lemma 3.4: S_d is C^2 (the claim of issue 13's region, kept as it was). The other
claims of Sect. 3.3 up to Lemma 3.4 — the inequalities (1)-(6), Lemmas 3.1-3.2, the factorizations
of Lemma 3.3 and Corollary 3.1, the printed d(z) — are data in paper.toml (kinds inequality,
identity, factorization; issue 11)."""

from __future__ import annotations

import sympy as sp

from analysis import claims as C
from schemes.seed003 import OMEGA

from .derivations import _c2_range, _diff_limit, _f, _range_statement, _s


def _lemma34_c2():
    from analysis.algebra.factorization import smoothing_factor, sum_rules
    from analysis.stationary.normset import norm_solution_set
    from analysis.regularity.holder import smoothness
    from analysis.algebra.symbol import LaurentSymbol

    e = _diff_limit()
    d = LaurentSymbol.from_mask([-c for c in e.mask], start=e.start, params=e.params)
    sr = sum_rules(d)
    f = smoothing_factor(e)
    exc = [x["condition"] for x in f.witness["exceptional"]]
    at = smoothness(e.subs({OMEGA: sp.Rational(1, 128)}), 2)
    c1 = norm_solution_set(e, m=2, L=2, within=(0, sp.oo))
    rng = _c2_range()
    right = rng.value[0]["right"]
    star = right["exact"]
    ev = [C.Evidence("S_d with the printed d: sum rules", result=sr,
                     text=f"d(1) = {_s(sr.witness['a(1)'])}, d(-1) = {_s(sr.witness['a(-1)'])}: d(1) != 2, so S_d does not "
                          "even converge (constants are multiplied by -1 at every step)"),
          C.Evidence("e = -d = lim e^n: smoothing factor", result=f,
                     text=f"e = ((1+z)/2)^{f.value} b generically, exceptional values {exc}: C^2 needs (1+z)^3, so "
                          "S_e is not C^2 for omega != 1/128"),
          C.Evidence("omega = 1/128 (in the range): S_e C^2?", result=at,
                     text=f"certified {at.value} ({at.witness.get('reason', '')})"),
          C.Evidence("C^1 of S_e: exact norm set ||(1/2 S_(e_2))^2|| < 1", result=c1,
                     text=f"{c1.value} — the paper's interval is the C^1 (not C^2) range of the difference scheme"),
          C.Evidence("C^1 of S_e beyond the norm set", text=f"S_e is C^1 iff rule (1) is C^2 (claim 003:Sec2(C2)): "
                     f"{_range_statement(star, right)}")]
    nums = [C.Number("smoothing_factor_e", f.value), C.Number("d(1)", sr.witness["a(1)"])]
    not_c2 = f.value == 2 and at.value is False and [str(x) for x in exc] == ["{omega: 1/128}"]
    if not_c2 and sr.value is False:
        return C.refuted("S_d is not C^2 anywhere on ]0, (sqrt6-1)/80[: the printed d has d(1) = -2 (S_d does not "
                         "converge); its negative e = lim e^n (the first divided-difference scheme of rule (1)) has only "
                         "two factors (1+z) (four at omega = 1/128, where it is certified not C^2): it is C^1 at most.",
                         corrected="S_e, e = -d = lim e^n = 2a/(1+z), is C^1 (not C^2) for omega in ]0, (sqrt6-1)/80[ "
                                   "(exact norm test, L = 2); hence rule (1) is C^2 there (and beyond: C^2 at "
                                   f"the certified grid points up to omega* ≈ {_f(star)}, see claim 003:Sec2(C2))",
                         evidence=ev, numbers=nums)
    return C.inconclusive("not settled", settle="check the smoothing factor and the Hölder exponent at 1/128",
                          evidence=ev, numbers=nums)
