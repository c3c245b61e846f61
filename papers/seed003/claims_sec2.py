"""Seed 003, Section 2: rule (1) is C^2 for 0 < omega < (sqrt6-1)/80 (the omega = 0 claim and the
smoothness profile are data in paper.toml)."""

from __future__ import annotations

import sympy as sp

from analysis import claims as C
from .derivations import (_C2_PROVEN_HI, _OM_HI, _c2_interval, _c2_range, _f, _interval_statement, _norm_sets,
                          _range_statement, _s)
from .figures import _alpha_figure


def _sec2_c2():
    sets = _norm_sets()
    s2 = sets[2].value
    (lo, hi, lc, hc), = s2.parts
    exact = (lo.expr == 0 and sp.simplify(hi.expr - _OM_HI) == 0 and not lc and not hc)
    rng = _c2_range()
    (run,) = rng.value
    left, right = run["left"], run["right"]
    star = right["exact"]
    fig, extra = _alpha_figure(rng, _OM_HI, star)
    whole = _c2_interval()
    ev = [C.Evidence("exact set where ||(1/2 S_(a_3))^L||_inf < 1 (Dyn-Levin C^2 test), omega > 0",
                     result=sets[2], text="; ".join(f"L = {L}: {r.value} ≈ ({_f(r.value.parts[0][0].expr) if r.value.parts else ''}, "
                                                    f"{_f(r.value.parts[0][1].expr) if r.value.parts else ''})" if r.value.parts else f"L = {L}: empty"
                                                    for L, r in sets.items())),
          C.Evidence("C^2 verdicts on a grid of (-1/20, 1/20) and certified boundaries "
                     "(analysis.regularity.ranges.ck_parameter_set)", result=rng if rng.status == "certified" else None,
                     text=("" if rng.status == "certified" else f"[{rng.status} as a whole (the interior between "
                           "grid points is not proven), so not attached as evidence] ")
                          + f"{_range_statement(star, right)}; left end: {left['how']}; right end: "
                          f"{right['how']}; certified C^2 at {_s(right['certified_C^j_at'])} and not C^2 at omega* "
                          f"(the s.m.p. eigenvalue crosses 1 exactly there)"),
          C.Evidence(f"C^2 on the whole interval (0, {_s(_C2_PROVEN_HI)})", result=whole,
                     text=_interval_statement(whole)),
          C.Evidence(f"alpha(omega) at extra points (figure; analysis.regularity.holder.holder_exponent, {extra.status})",
                     text="; ".join(f"{_s(r['p'])}: [{_f(r['lower'], 8)}, {_f(r['upper'], 8)}] ({r['status']})"
                                    for r in extra.value if r.get("lower") is not None))]
    nums = [C.Number("L2_right_end", hi.expr),
            C.Number("true_right_end", star, tol=1e-12, note=f"{_s(star)}: {right['how']}"),
            C.Number("certified_C2_at", right["certified_C^j_at"], tol=1e-8),
            C.Number("L3_right_end", sets[3].value.parts[0][1].expr, tol=1e-12)]
    if exact and whole.status == "certified" and whole.value is True:
        near = (_range_statement(star, right) if rng.witness.get("boundaries_certified") else
                f"the grid verdicts and boundaries are {rng.status}")
        return C.certified("True: the Dyn-Levin test with L = 2 holds exactly on 0 < omega < (sqrt6-1)/80, so rule (1) "
                           "is C^2 there (the paper's interval is exactly this L = 2 norm set).",
                           sharpness=f"not sharp: {_interval_statement(whole)}, beyond (sqrt6-1)/80 ≈ "
                                     f"{_f(_OM_HI, 10)}; L = 3 alone proves C^2 up to "
                                     f"{_f(sets[3].value.parts[0][1].expr)}. Near 0: {near}.",
                           evidence=ev, numbers=nums, figures=[fig])
    if exact:
        return C.certified("True: the L = 2 norm test holds exactly on the claimed interval.",
                           sharpness="the extent of the C^2 set beyond it could not be certified in the budget",
                           evidence=[e for e in ev if e.result is None or e.result.status == "certified"],
                           numbers=nums, figures=[fig])
    return C.refuted("the L = 2 norm set is not the claimed interval", f"C^2 (norm test) on {s2}", evidence=ev,
                     numbers=nums, figures=[fig])
