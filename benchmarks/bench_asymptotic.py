"""Seed 003: weighted series and lemma checks on one parameter box (alpha in [1/10, pi/3], omega = 1/100).

Run: ``python benchmarks/bench_asymptotic.py`` (target: under 10 s in total).
"""

from __future__ import annotations

import time

import sympy as sp

from analysis.levels.bounds import check_inequality
from analysis.levels.level_dependent import distance
from analysis.levels.series import weighted_series
from schemes import seed003 as S

BOX = {"alpha": (sp.Rational(1, 10), sp.pi / 3), "omega": sp.Rational(1, 100)}


def _t(label, fn):
    t = time.perf_counter()
    out = fn()
    dt = time.perf_counter() - t
    print(f"{label:<58} {dt:7.2f} s   {out}")
    return dt


def main() -> None:
    total = 0.0
    def table():
        vals = {"alpha": 1, "omega": sp.Rational(1, 100)}
        rs = [distance(S.TRIGONOMETRIC, n, vals) for n in range(201)]
        ok = all(r.is_certified for r in rs)
        return f"all certified: {ok}; 4^200 * ||.|| >= {float(rs[-1].lower * 4 ** 200):.12f} (-> 3/32)"
    total += _t("||S_a^n - S_a||, n = 0..200, arb (alpha=1)", table)
    for m in (0, 1, 2):
        def run(m=m):
            r = weighted_series(S.TRIGONOMETRIC, BOX, m, pieces=8)
            if r.witness["verdict"] == "convergent":
                return f"convergent, sum in [{float(r.lower):.6g}, {float(r.upper):.6g}]"
            return f"{r.witness['verdict']} (terms >= {float(r.witness.get('term_lower_bound', 0)):.3g})"
        total += _t(f"series m={m}, alpha box, 8 sub-boxes", run)
    def run_d():
        r = weighted_series(S.TRIGONOMETRIC, BOX, 1, difference=1, pieces=8)
        return f"{r.witness['verdict']}, sum in [{float(r.lower):.6g}, {float(r.upper):.6g}]"
    total += _t("difference scheme e^n, m=1, alpha box", run_d)
    box = {"alpha": ("1/10", "pi/3"), "omega": "1/100"}
    for cid, (lhs, rhs, strict) in {**S.LEMMA_3_1, **S.LEMMA_3_2}.items():
        names = {s.name for s in (sp.sympify(lhs).free_symbols | sp.sympify(rhs).free_symbols)}
        n0 = 1 if "3.1" in cid else 0
        total += _t(cid, lambda: check_inequality(lhs, rhs, n0, {k: v for k, v in box.items() if k in names},
                                                  strict=strict).status)
    print(f"{'total':<58} {total:7.2f} s")


if __name__ == "__main__":
    main()
