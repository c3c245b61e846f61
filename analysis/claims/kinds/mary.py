"""The m-ary evaluation of the claim kinds ``ck range`` and ``smoothness profile`` (issue 12).

A scheme of a paper file with ``arity = m != 2`` is analysed with the m-ary engine: for each ``j``
the C^j set of a one-parameter family is :func:`analysis.regularity.mary.ck_range_mary` — the union
of the exact sets where the m-ary Dyn–Levin test ``||(1/m S_{a_{j+1}})^L||_inf < 1`` holds (C^j
proven) and the exact set where one transition matrix of ``c = m^k a/q_m^(k+1)`` has a real
eigenvalue of modulus ``>= m^(k-j)`` (``alpha <= j``: not C^j proven). What neither covers is
reported as *undecided*: the verdict is then inconclusive (never certified), with the strip named.
The Hölder exponent is enclosed (certified, :func:`analysis.regularity.mary.alpha_curve_mary`)
at ``samples + 1`` rational points only: its maximum over the interval is sampled, not certified.

The other kinds dispatch in their own ``evaluate`` (``self.arity``): sum rules, symmetry, support,
eigenvalues, reproduction, norm test and holder use the m-ary functions of
:mod:`analysis.algebra.mary`, :mod:`analysis.stationary.mary` and :mod:`analysis.regularity.mary`.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> from analysis.claims.kinds.regularity import CkRange
>>> mu = sp.Symbol("mu")
>>> r = sp.Rational
>>> a0, a1, a2, a3 = -r(1, 18) - mu/6, r(13, 18) + mu/2, r(7, 18) - mu/2, -r(1, 18) + mu/6
>>> a = LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)
>>> S = {"t4": SchemeSpec("t4", a, arity=3)}
>>> CkRange({"j": 2, "interval": "(1/15, 1/9)"}, S, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = CkRange({"j": 2, "interval": "(0, 1/9)"}, S, "x").evaluate()
>>> v.label, v.numbers[0].value
('REFUTED', 1/30)

Algorithm
---------
``ck_range_mary(a, m, j, p, Ls=(1, 2), within=...)`` for each ``j`` (exact norm sets in the parameter,
exact linear eigenvalue factors of the characteristic polynomials of the transition matrices); a
claimed open interval is proven when it lies in the C^j set, refuted at a rational point of the
not-C^j set inside it.

References
----------
N. Dyn, D. Levin, Acta Numer. 11 (2002) 73-144; M. F. Hassan, I. P. Ivrissimitzis, N. A. Dodgson,
M. A. Sabin, Comput. Aided Geom. Design 19 (2002) 1-18; O. Rioul, SIAM J. Math. Anal. 23 (1992).
"""

from __future__ import annotations

import sympy as sp

from ...algebra.mary import smoothing_factor_mary
from ...regularity.mary import alpha_curve_mary, ck_range_mary
from ..model import Number, Verdict
from .base import Kind, evidence, interval_text, parse_interval, alpha_maximum

__all__ = ["ck_range_verdict", "profile_verdict", "set_text", "point_in"]

#: the L of the m-ary norm sets (as `subdiv range --arity`)
LS = (1, 2)
#: work units of JSR search per alpha sample point (analysis.jsr.jsr_bounds)
ALPHA_BUDGET = 2_000


def set_text(S) -> str:
    """A sympy set as ``(a, b) U [c, d]`` (``empty`` for the empty set)."""
    if S == sp.EmptySet or S.is_empty is True:
        return "empty"
    parts = S.args if isinstance(S, sp.Union) else (S,)
    out = []
    for x in parts:
        if isinstance(x, sp.Interval):
            out.append(f"{'(' if x.left_open else '['}{sp.sstr(x.start)}, {sp.sstr(x.end)}{')' if x.right_open else ']'}")
        else:
            out.append(sp.sstr(x))
    return " U ".join(out)


def point_in(S):
    """A simple exact point of the sympy set ``S`` (a rational inside an interval of positive length,
    else an element of a finite part), or None."""
    parts = S.args if isinstance(S, sp.Union) else (S,)
    for x in parts:
        if isinstance(x, sp.Interval) and bool(x.end > x.start):
            lo, hi = x.start, x.end
            if lo == -sp.oo:
                lo = hi - 2
            if hi == sp.oo:
                hi = lo + 2
            for den in (1, 2, 3, 5, 10, 30, 100, 1000, 10 ** 6):
                q = sp.Rational(round(float((lo + hi) / 2) * den), den)
                if S.contains(q) is sp.true:
                    return q
    for x in parts:
        if isinstance(x, sp.FiniteSet) and x.args:
            return x.args[0]
    return None


def _range(kind: Kind, a, p, j: int, lo, hi):
    return ck_range_mary(a, kind.arity, j, p, Ls=LS, within=(lo, hi))


def ck_range_verdict(kind: Kind) -> Verdict:
    """The ``ck range`` kind for an m-ary scheme: C^j on the claimed open interval."""
    a, m = kind.symbol(), kind.arity
    p = kind.single_parameter()
    j = kind.get("j")
    lo, hi, lc, hc = kind.interval("interval")
    claim = interval_text(lo, hi, lc, hc)
    r = _range(kind, a, p, j, lo, hi)
    S, V, U = r.value, r.witness["not_Cj"], r.witness["undecided"]
    text = (f"C^{j} (m-ary norm sets, L in {list(LS)}): {set_text(S)}; not C^{j} (transition-matrix eigenvalue "
            f"of modulus >= {m}^{r.witness['k'] - j}): {set_text(V)}; undecided: {set_text(U)}")
    ev = [evidence(f"C^{j} of the {m}-ary scheme on {claim}", r, text=text)]
    note = " (the closed ends are not checked: the interval is treated as open)" if lc or hc else ""
    if r.witness["exact"] and (V == sp.EmptySet or V.is_empty is True):
        return kind.certified(f"C^{j} for every {p.name} in {claim} ({m}-ary Dyn-Levin norm sets){note}", evidence=ev,
                              numbers=[Number("proven", True)])
    q = point_in(V)
    if q is not None:
        return kind.refuted(f"not C^{j} at {p.name} = {sp.sstr(q)} in {claim} (certified: a transition matrix has an "
                            f"eigenvalue of modulus >= {m}^{r.witness['k'] - j})",
                            corrected=f"on {claim} the scheme is C^{j} exactly on {set_text(S)}"
                                      + (f" and undecided on {set_text(U)}" if not r.witness["exact"] else ""),
                            evidence=ev, numbers=[Number("counterexample", q)])
    return kind.inconclusive(f"C^{j} on {claim} neither proven nor refuted: undecided on {set_text(U)}",
                             settle=f"decide points of {set_text(U)} with `subdiv holder --arity {m} --C {j}` "
                                    "or longer norm tests", evidence=ev)


def profile_verdict(kind) -> Verdict:
    """The ``smoothness profile`` kind for an m-ary one-parameter family (see the module docstring)."""
    a, m = kind.symbol(), kind.arity
    p = kind.single_parameter()
    lo, hi = kind._within()
    N = smoothing_factor_mary(a, m, exceptional=False).value
    max_j = kind.get("max_j", max(N - 1, 0))
    sets, rows, nums, all_cert = {}, [], [], True
    for j in range(0, min(max_j, N - 1) + 1):
        r = _range(kind, a, p, j, lo, hi)
        sets[j] = r
        all_cert &= bool(r.witness["exact"])
        rows.append((f"C^{j}", set_text(r.value), "certified" if r.witness["exact"] else
                     f"undecided on {set_text(r.witness['undecided'])}"))
        nums.append(Number(f"C^{j} set", set_text(r.value)))
        if not r.witness["exact"]:
            nums.append(Number(f"C^{j} undecided", set_text(r.witness["undecided"])))
        if r.value == sp.EmptySet and r.witness["exact"]:
            break
    largest = max([j for j, r in sets.items() if r.value != sp.EmptySet], default=-1)
    ev = [evidence(f"C^j sets of {p.name} in {interval_text(lo, hi)} ({m}-ary)", table=(("j", "set", "status"), *rows),
                   text=f"{N} generic factors (1+...+z^{m - 1})/{m}; largest j with a non-empty C^j set: {largest}")]
    curve = alpha_curve_mary(a, m, p, within=(lo, hi), samples=kind.get("samples", 8), budget=ALPHA_BUDGET).value
    alpha_line, alpha_nums, alpha_ev = alpha_maximum(a, p, lo, hi, curve, arity=m)
    nums += alpha_nums
    ev.append(alpha_ev)
    nums.insert(0, Number("largest j", largest))
    profile = "; ".join(f"{r[0]}: {r[1]}" + ("" if r[2] == "certified" else f" ({r[2]})") for r in rows) + f"; {alpha_line}"
    claim = kind.get("claimed")
    where = kind.where_text()
    if claim is None:
        if all_cert:
            return kind.certified(f"smoothness profile of {where} ({m}-ary)", evidence=ev, numbers=nums,
                                  sharpness=profile)
        return kind.inconclusive(f"smoothness profile of {where} ({m}-ary; some C^j sets have undecided strips)",
                                 settle="longer norm tests or point-wise JSR verdicts on the undecided strips",
                                 evidence=ev, numbers=nums, sharpness=profile)
    cj = claim["j"]
    clo, chi, _, _ = parse_interval(claim["interval"])
    if cj > N - 1:
        return kind.refuted(f"false: C^{cj} needs {cj + 1} factors 1+...+z^{m - 1}; the family has {N}",
                            corrected=f"at most C^{N - 1}", evidence=ev, numbers=nums, sharpness=profile)
    r = sets.get(cj)
    if r is None or not (bool(clo >= lo) and bool(chi <= hi)):
        r = _range(kind, a, p, cj, clo, chi)
    V = r.witness["not_Cj"].intersect(sp.Interval.open(clo, chi))
    inside = sp.Interval.open(clo, chi).is_subset(r.value)
    exact_set = r.witness["exact"] and r.value == sp.Interval.open(clo, chi)
    which = (f"the printed interval {interval_text(clo, chi)} is the C^{cj} set" if exact_set else
             f"the C^{cj} set (within {interval_text(lo, hi)}) is {set_text(r.value)}"
             + ("" if r.witness["exact"] else f", undecided on {set_text(r.witness['undecided'])}"))
    ev.insert(0, evidence(f"claimed: C^{cj} on {interval_text(clo, chi)}", r, text=which))
    sharp = f"{which}. {profile}"
    if inside:
        return kind.certified(f"true: C^{cj} on {interval_text(clo, chi)} proven ({m}-ary Dyn-Levin norm sets)",
                              evidence=ev, numbers=nums, sharpness=sharp)
    q = point_in(V)
    if q is not None:
        return kind.refuted(f"false: not C^{cj} at {p.name} = {sp.sstr(q)} (certified: a transition matrix has an "
                            f"eigenvalue of modulus >= {m}^{N - 1 - cj}); {which}",
                            corrected=f"C^{cj} exactly on {set_text(r.value)}" if r.witness["exact"] else which,
                            evidence=ev, numbers=nums, sharpness=sharp)
    return kind.inconclusive(f"C^{cj} on {interval_text(clo, chi)} neither proven nor refuted; {which}",
                             settle="longer norm tests or point-wise JSR verdicts", evidence=ev, numbers=nums,
                             sharpness=sharp)
