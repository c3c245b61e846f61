"""``subdiv surface``: sizes predicted before the work (refinement, invariant support), the fast refinement checked
against the definition, and options that would be ignored refused in one line."""

from __future__ import annotations

import json

import numpy as np
import pytest

from analysis.bivariate.mask import BivariateMask
from analysis.bivariate.refine import basic_limit_samples, support_boxes
from analysis.bivariate.transition import fixed_points, invariant_support
from analysis.cli.main import main
from schemes.surfaces import entries, get


def _reference_samples(a: BivariateMask, steps: int) -> dict:
    """``S_a^steps delta`` by the definition, term by term (the points reached from nonzero values)."""
    (m00, m01), (m10, m11) = a.dilation.matrix
    f = {(0, 0): 1.0}
    for _ in range(steps):
        g: dict = {}
        for (bx, by), fv in f.items():
            if fv != 0.0:
                for (i, j), v in a.coeffs.items():
                    key = (m00 * bx + m01 * by + i, m10 * bx + m11 * by + j)
                    g[key] = g.get(key, 0.0) + float(v) * fv
        f = g
    return f


@pytest.mark.parametrize("name, steps", [("loop", 3), ("sqrt3", 2), ("quincunx-zp", 4), ("butterfly", 2)])
def test_refinement_is_the_definition(name, steps):
    a = get(name).mask()
    ref = _reference_samples(a, steps)
    pts, vals = basic_limit_samples(a, steps)
    assert len(vals) == len(ref)
    assert np.allclose(vals, [ref[k] for k in sorted(ref)], rtol=0, atol=1e-12)
    # the points are M^-n alpha, in the order of alpha
    M = np.array(a.dilation.matrix, dtype=float)
    assert np.allclose(pts @ np.linalg.matrix_power(M, steps).T, sorted(ref))
    x0, y0, x1, y1 = support_boxes(a, steps)[-1]
    assert min(k[0] for k in ref) >= x0 and max(k[0] for k in ref) <= x1
    assert min(k[1] for k in ref) >= y0 and max(k[1] for k in ref) <= y1


def _error(capsys, *argv):
    code = main(list(argv))
    cap = capsys.readouterr()
    assert code == 2 and cap.out == "" and cap.err.count("\n") == 1 and cap.err.startswith("subdiv: error: ")
    assert main([*argv, "--json"]) == 2
    doc = json.loads(capsys.readouterr().out)
    assert doc["error"]["message"] == cap.err[len("subdiv: error: "):].strip()
    return cap.err


def test_too_many_refinement_steps_are_refused_before_the_work(capsys):
    # the bounding box after 8 steps of the bicubic B-spline: (4 (2^8 - 1) + 1)^2 points
    err = _error(capsys, "surface", "--scheme", "bicubic", "--refine", "8")
    assert "--refine 8 would give up to 1042441 samples" in err and "take --refine 7 or fewer" in err
    big = "; ".join(f"{i},{j}:1/240" for i in range(31) for j in range(31))
    err = _error(capsys, "surface", "--mask2", big, "--refine", "5")
    assert "take --refine 4 or fewer" in err


@pytest.mark.parametrize("name", [e.slug for e in entries()])
def test_fixed_points_lie_in_the_invariant_support(name):
    a = get(name).mask()
    assert fixed_points(a) <= set(invariant_support(a))


def test_a_too_large_invariant_support_is_refused_before_the_algebra(capsys):
    # 21 x 21 coefficients, M = 2I: supp(a) - {0,1}^2 (22 x 22 points) are fixed points, all in Omega
    big = "; ".join(f"{i},{j}:1/110" for i in range(21) for j in range(21))
    err = _error(capsys, "surface", "--mask2", big)
    assert "the invariant support has at least 484 points (limit 400" in err and "smaller support" in err
    # quincunx: 110 fixed points, 670 points in Omega (computed before the sum rules and the box factors)
    quincunx = "; ".join(f"{i},{j}:1/50" for i in range(10) for j in range(10))
    err = _error(capsys, "surface", "--mask2", quincunx, "--dilation", "quincunx")
    assert "the invariant support has 670 points (limit 400): give a mask with a smaller support" in err


@pytest.mark.parametrize("argv, message", [
    (["--grid-cells", "0"], "--grid-cells must be between 1 and 64, not 0"),
    (["--scheme", "loop", "--grid-cells", "4"], "--grid-cells goes with a C^l set of a free parameter"),
    (["--scheme", "butterfly", "--param-name", "w"], "drop --param-name or add --C L --within=LOW,HIGH"),
    (["--scheme", "loop", "--C", "1", "--param-name", "w"], "--param-name goes with a C^l set"),
    (["--scheme", "loop", "--range-budget", "5"], "--range-budget goes with a C^l set"),
    (["--scheme", "bicubic", "--list"], "--list lists the whole catalogue: drop --scheme (or drop --list)"),
    (["--scheme", "loop", "--differences", "1", "--param-name", "w"],
     "--differences is a mode of its own: drop --param-name"),
    (["--file", "."], "is a folder: give the path of a mask file MASK.toml or MASK.json"),
    (["--file", "mask"], "'mask' has no suffix: give the path of a mask file MASK.toml"),
    (["--scheme", "kobbelt-quad", "--C", "1", "--within=0,1/4", "--range-budget", "1000"],
     "this family is a tensor product, whose C^l set is computed by the univariate route: drop --range-budget"),
], ids=["grid-cells-0", "grid-cells-alone", "param-name", "param-name-fixed", "range-budget", "list", "differences",
        "folder", "no-suffix", "range-budget-tensor"])
def test_options_that_would_be_ignored_are_refused(capsys, argv, message):
    assert message in _error(capsys, "surface", *argv)


def test_a_mask_file_that_is_not_text_says_what_to_give(tmp_path, capsys):
    f = tmp_path / "mask.toml"
    f.write_bytes(b"\x93NUMPY\x01\x00")
    assert "is not UTF-8 text: give the path of a mask file" in _error(capsys, "surface", "--file", str(f))
