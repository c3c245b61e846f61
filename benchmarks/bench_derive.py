"""Issue 14: mask derivation from requirements, and the smoothest member of a one-parameter family.

Run: ``python benchmarks/bench_derive.py`` (targets: each derivation with <= 12 coefficients under 2 s;
the one-parameter maximisation with certified gap 1e-3 under 60 s).
"""

from __future__ import annotations

import time

import sympy as sp

from analysis.algebra.derive import derive_mask, max_sum_rules
from analysis.regularity.maximize import maximize_holder


def _t(label, fn):
    t = time.perf_counter()
    out = fn()
    dt = time.perf_counter() - t
    print(f"{label:<62} {dt:7.3f} s   {out}")
    return dt


CASES = [
    ("DD 4-point (7 coeffs, interpolatory, reproduce 3)", dict(support=7, interpolatory=True, symmetric="primal", reproduction=3)),
    ("4-point family (7 coeffs, reproduce 1)", dict(support=7, interpolatory=True, symmetric="primal", reproduction=1)),
    ("6-point family (11 coeffs, reproduce 3)", dict(support=11, interpolatory=True, symmetric="primal", reproduction=3)),
    ("dual 6-point (12 coeffs, dual, reproduce 5)", dict(support=12, symmetric="dual", reproduction=5)),
    ("ternary 4-point family (11 coeffs, arity 3, reproduce 2)", dict(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=2)),
    ("12 coeffs, dual, sum rules 4 (a 3-parameter family)", dict(support=12, symmetric="dual", sum_rules=4)),
    ("4-point, exp(+-i pi/2 x) (7 coeffs, QQ<sqrt2, i>)", dict(support=7, interpolatory=True, symmetric="primal", reproduction=0, exponentials=["I*pi/2", "-I*pi/2"])),
]


def main() -> None:
    worst = 0.0
    for label, kw in CASES:
        worst = max(worst, _t(label, lambda kw=kw: f"dimension {derive_mask(**kw).witness['dimension']}"))
    worst = max(worst, _t("B-spline: most sum rules on 12 coefficients", lambda: f"order {max_sum_rules(support=12).witness['order']}"))
    print(f"slowest derivation: {worst:.3f} s (target < 2 s)")
    a = derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=3).value

    def smoothest():
        r = maximize_holder(a, within=(0, sp.Rational(1, 32)), gap=sp.Rational(1, 1000))
        return (f"{r.status}: t1* = {r.value}, alpha(t1*) >= {float(r.lower):.6f}, alpha <= {float(r.upper):.6f} "
                f"on [0, 1/32], gap {float(r.witness['gap']):.2e}, {r.witness['intervals']} sub-intervals")
    _t("6-point family: smoothest member on [0, 1/32], gap 1e-3", smoothest)


if __name__ == "__main__":
    main()
