"""Issue 12/13 item 6: ``subdiv holder --box`` for level-dependent m-ary schemes (``level_smoothness_box(arity=m)``).

Expected values are computed independently: the point-mode chain ``analysis.levels.ck.level_smoothness(...,
arity=3)`` at a point of the box, and exact sympy evaluation of the normalisers ``q_m(v) = 1 + v + ... + v^(m-1)``.
The published fact behind the exact verdicts: the exponential B-spline of order d+1 (here the ternary scheme with
frequencies 0, +-i theta, order 3) is C^(d-1) and not C^d (Unser-Blu, IEEE Trans. Signal Process. 53 (2005)
1425-1438; m-ary: Charina-Conti-Romani, arXiv:1303.1678).
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.cli.main import main
from analysis.levels.ck import level_smoothness
from analysis.levels.ck_box import level_smoothness_box
from analysis.levels.expbspline_box import normalisers_nonzero_box, not_ck_box
from analysis.levels.level_dependent import LevelDependentScheme
from analysis.result import AnalysisError
from schemes.level_dependent import get

SYM = "(1+z+z**2)*(1+2*c*z+(1+2*d)*z**2+2*c*z**3+z**4)/((3+4*c+2*d)*z**3)"
WHERE = ["c=cos(theta/3**(n+1))", "d=cos(2*theta/3**(n+1))"]


@pytest.fixture(scope="module")
def ternary():
    return LevelDependentScheme.from_symbol(SYM, where=WHERE, slug="symbol", arity=3)


def test_inline_ternary_box_agrees_with_point_mode(capsys, ternary):
    argv = ["holder", "--arity", "3", "--symbol", SYM, "--where", WHERE[0], "--where", WHERE[1],
            "--box", "theta=1/2,2", "--json"]
    assert main(argv) == 0
    doc = json.loads(capsys.readouterr().out)
    r = doc["smoothness"]
    point = level_smoothness(ternary, {"theta": sp.Rational(1, 2)}, arity=3)   # independent: point chain
    assert doc["arity"] == 3 and r["status"] == "certified" and r["provenance"]["arity"] == 3
    assert (r["value"], r["witness"]["exact"], r["witness"]["not_C^k"]) == (point.value, point.witness["exact"],
                                                                           point.witness["not_C^k"]) == (1, True, 2)
    # the m-ary divided-difference route carries its convergence hypothesis (H2) like ck.py's
    c1 = r["witness"]["verdicts"][1]["cover"][0]
    assert c1["route"] == "Dyn-Levin on the 1st divided difference scheme" and "convergence" in c1["hypotheses"]


@pytest.mark.parametrize("m, box, zero_at", [(3, (6, 7), 2 * sp.pi), (4, (6, 7), 2 * sp.pi), (4, (3, 4), None)])
def test_normalisers_mary_box(m, box, zero_at):
    t = sp.Symbol("t", positive=True)
    r = normalisers_nonzero_box([sp.I * t], {"t": box}, arity=m)
    if zero_at is None:          # q_m(e^(i t/m)) = 0 needs t/m = 2 pi k/m, 0 < k < m: t >= 2 pi, outside [3, 4]
        assert r.status == "certified"
        return
    v = sp.exp(sp.I * zero_at / m)          # level 0: v = exp(i t m^-1) at t = 2 pi, in the box
    assert sp.simplify(sp.expand_complex(sum(v ** k for k in range(m)))) == 0 and v != 1
    assert r.status == "inconclusive" and f"q(exp(I*t {m}^-1))" in r.witness["reason"]


def test_not_ck_box_where_normaliser_vanishes_is_not_certified():
    # 1 + v + v^2 = 0 at t = 2 pi (level 0) inside [6, 7]: "not C^2" must not be certified there; on [1/2, 2] it is
    s = get("ternary-exp-bspline-2-trig")
    bad = not_ck_box(s, {"t": (sp.Integer(6), sp.Integer(7))}, arity=3)
    good = not_ck_box(s, {"t": (sp.Rational(1, 2), sp.Integer(2))}, arity=3)
    assert bad.status == "inconclusive" and bad.witness["failed"] == ["normalisers_nonzero"]
    assert "q(exp(" in bad.witness["reason"]
    assert (good.status, good.value, good.witness["k"]) == ("certified", False, 2)


@pytest.mark.parametrize("argv, message", [
    (["--scheme", "ternary-exp-bspline-2-trig", "--arity", "4", "--box", "t=1,2"], "has arity 3"),
    (["--scheme", "ternary-exp-bspline-2-trig", "--box", "t=1,2", "--open", "t"], "--open is available for binary"),
    (["--arity", "3", "--symbol", SYM, "--where", WHERE[0], "--where", WHERE[1], "--box", "phi=1,2"],
     "has no parameter phi"),
], ids=["arity-mismatch", "open", "unknown-name"])
def test_cli_bad_input_one_line(capsys, argv, message):
    assert main(["holder", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1 and err.startswith("subdiv: error:")


def test_arity_mismatch_in_python():
    with pytest.raises(AnalysisError, match="has arity 3"):
        level_smoothness_box(get("ternary-exp-bspline-1-trig"), {"t": (1, 2)}, arity=4)


def test_parametric_ternary_limit_ternary_four_point():
    # the catalogue's ternary-four-point family (mask typed from memory of Hassan-Ivrissimtzis-Dodgson-Sabin 2002,
    # NOT checked against the paper) has the C^2 set exactly (1/15, 1/9), certified by this code on both sides
    # (tests/test_strips_arity.py, `subdiv range --scheme ternary-four-point --C 2`); perturbed by 3^-n/100 at
    # level n, the limit is that scheme: C^2 on a box inside the set, not certified on a box through mu = 1/9
    # (the limit's exact m-ary norm sets decide the sub-boxes)
    mask = ["-1/18+m/6", "-1/18-m/6", "0", "7/18-m/2", "13/18+m/2", "1", "13/18+m/2", "7/18-m/2", "0",
            "-1/18-m/6", "-1/18+m/6"]
    s = LevelDependentScheme.from_mask(mask, -5, where=["m=mu+3**(-n)/100"], slug="mask", arity=3)
    inside = level_smoothness_box(s, {"mu": (sp.Rational(1, 14), sp.Rational(1, 10))})
    across = level_smoothness_box(s, {"mu": (sp.Rational(1, 10), sp.Rational(1, 8))}, depth=0, L_max=2)
    assert inside.value == 2 and inside.status == "certified"
    assert across.value == 1 and across.witness["verdicts"][2]["status"] == "inconclusive"
