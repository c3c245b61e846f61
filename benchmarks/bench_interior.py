"""Issue 14: the certified interior of C^j sets, and --maximize beyond one binary parameter.

Run: ``python benchmarks/bench_interior.py`` (process time and wall time; the machine's 2 cores
may be shared). Prints, for each case, what is certified and what is left.
"""

from __future__ import annotations

import time

import sympy as sp

from analysis.algebra.derive import derive_mask
from analysis.regularity.interior import ck_interior
from analysis.regularity.maximize_box import maximize_holder_box


def _t(label, fn):
    t, c = time.perf_counter(), time.process_time()
    out = fn()
    print(f"{label:<58} {time.process_time() - c:7.2f} s cpu {time.perf_counter() - t:7.2f} s wall   {out}")


def _interior(a, j, lo, hi):
    def run():
        r = ck_interior(a, j, lo, hi)
        strips = ", ".join(f"width {float(y - x):.2e}" for x, y in r.value["strips"])
        return f"{r.status}: {r.value['certified']}; strips: {strips or 'none'}; {len(r.witness['pieces'])} pieces"
    return run


def _maximize(a, box, arity, gap):
    def run():
        r = maximize_holder_box(a, box, arity=arity, gap=gap, budget=120_000)
        pt = ", ".join(f"{k} = {v}" for k, v in r.value.items())
        return (f"{r.status}: {pt}, alpha >= {float(r.lower):.6f}, <= {float(r.upper):.6f} on the box, "
                f"gap {float(r.witness['gap']):.2e}")
    return run


def main() -> None:
    six = derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=3).value
    t = six.params[0]
    _t("6-point family, C^1 interior", _interior(six, 1, -sp.Rational(3, 16) + 3 * sp.sqrt(2) / 32,
                                                  -sp.Rational(1, 32) + sp.sqrt(19) / 32))
    star = sp.CRootOf(524288 * t**5 - 65536 * t**4 + 12800 * t**3 - 352 * t**2 + 61 * t - 3, 0)
    _t("6-point family, C^2 interior", _interior(six, 2, 0, star))
    ternary = derive_mask(arity=3, support=11, interpolatory=True, symmetric="primal", reproduction=2).value
    _t("ternary 4-point family: smoothest on [-1/16, 0], gap 1e-3",
       _maximize(ternary, {"t1": (sp.Rational(-1, 16), 0)}, 3, sp.Rational(1, 1000)))
    two = derive_mask(support=11, interpolatory=True, symmetric="primal", reproduction=1).value
    _t("2-parameter family: smoothest on [0,1/32]x[-1/8,0], gap 1e-3",
       _maximize(two, {"t1": (0, sp.Rational(1, 32)), "t2": (sp.Rational(-1, 8), 0)}, 2, sp.Rational(1, 1000)))


if __name__ == "__main__":
    main()
