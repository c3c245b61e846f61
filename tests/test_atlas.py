"""Tests of analysis.regularity.atlas (two-parameter Hölder atlases) and the `subdiv atlas` command.

The family ``a(z) = (1+z)^2/(2z) (1 + s (z - 2 + 1/z) + t (z^2 - 2 + z^-2))`` passes through the
linear (s = t = 0, alpha = 1), cubic (s = 1/4, t = 0) and quintic (s = 1/4, t = 1/16) B-splines;
on s, t in [-1/8, 1/8] x [-1/8, 0] every point certifies in well under a second and the C^1
boundary (alpha = 1) crosses the square.
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from analysis.regularity.atlas import _disagree, evaluate_point, holder_atlas, plot_atlas
from analysis.regularity.atlas_axes import parse_axis
from analysis.cli import main
from analysis.result import CERTIFIED, AnalysisError
from analysis.algebra.symbol import LaurentSymbol

Z, S, T = sp.symbols("z s t")
FAMILY = LaurentSymbol.from_expr((1 + Z)**2 / (2 * Z) * (1 + S * (Z - 2 + 1 / Z) + T * (Z**2 - 2 + Z**-2)))
FAMILY_EXPR = "(1+z)**2/(2*z)*(1 + s*(z-2+1/z) + t*(z**2-2+z**-2))"
GRID = dict(p1="s", range1=("-1/8", "1/8"), p2="t", range2=("-1/8", 0), n1=3, n2=3, j_levels=(1, 2),
            refine_levels=1, budget=30000, progress=False)
R = sp.Rational


def _essential(result):
    """The samples (what must not depend on the executor; the timings are in the provenance)."""
    assert all("seconds" not in s and "timing" not in s for s in result.value)
    return list(result.value)


@pytest.fixture(scope="module")
def serial():
    return holder_atlas(FAMILY, executor=None, **GRID)


def test_serial_atlas_contents(serial):
    w = serial.witness
    assert serial.status == CERTIFIED
    assert w["counts"]["per_level"][0] == 9 and w["counts"]["samples"] == len(serial.value)
    assert w["counts"]["certified"] + w["counts"]["inconclusive"] == w["counts"]["samples"]
    at = {(s["p1"], s["p2"]): s for s in serial.value}
    lin = at[(0, 0)]                              # linear B-spline: alpha = 1 exactly, not C^1
    assert lin["alpha"] == 1 and lin["C^1"] is False and lin["C^2"] is False
    for s in serial.value:                        # exact rational points, rigorous enclosures
        assert isinstance(s["p1"], sp.Rational) and isinstance(s["p2"], sp.Rational)
        assert s["alpha_lower"] <= s["alpha_upper"]
        assert s["C^1"] == (s["alpha_lower"] > 1)  # no point sits on alpha = 1 but (0, 0)
        assert s["C^2"] is False                  # generic k = 1: C^2 impossible
        assert sp.Rational(-1, 8) <= s["p1"] <= sp.Rational(1, 8)
    assert w["exceptional"][0]["condition"] == {"s": R(1, 4)}
    assert serial.to_json()["witness"]["counts"]["samples"] == len(serial.value)


def test_local_processes_equal_serial(serial):
    local = holder_atlas(FAMILY, executor="local", workers=2, **GRID)
    assert local.witness["executor"] == "local processes (2)"
    assert _essential(local) == _essential(serial)
    assert local.witness["counts"] == serial.witness["counts"]


def test_dask_cluster_equals_serial(serial):
    """Two Dask workers over TCP (tasks and results are pickled through the scheduler, results come back
    in completion order); the workers are threads of this process (``processes=False``): a worker
    process would only add its start-up imports, not another code path of the engine."""
    import distributed   # a test dependency: the Dask path must run in CI, not be skipped
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, protocol="tcp",
                                  dashboard_address=None) as cluster:
        address = cluster.scheduler_address          # "tcp://127.0.0.1:PORT"
        r = holder_atlas(FAMILY, executor="dask://" + address.split("://", 1)[1], **GRID)
    assert r.witness["executor"].startswith("dask cluster at tcp://127.0.0.1")
    assert _essential(r) == _essential(serial)


def test_refinement_adds_points_only_near_the_boundary(serial):
    plain = holder_atlas(FAMILY, executor=None, **{**GRID, "refine_levels": 0})
    assert len(plain.value) == 9 < len(serial.value)
    at = {(s["p1"], s["p2"]): s for s in serial.value}
    added = [s for s in serial.value if s["level"] == 1]
    assert added and serial.witness["counts"]["refined_cells"] == [2]
    hs, ht = R(1, 8), R(1, 16)                    # level-0 steps in s and t
    for s in added:
        # the level-0 cell holding the new point has corners that disagree on C^1
        i0 = min((s["p1"] + R(1, 8)) // hs, 1)
        j0 = min((s["p2"] + R(1, 8)) // ht, 1)
        corners = [at[(-R(1, 8) + (i0 + di) * hs, -R(1, 8) + (j0 + dj) * ht)]
                   for di in (0, 1) for dj in (0, 1)]
        assert len({c["C^1"] for c in corners}) == 2
    # the cell [-1/8, 0] x [-1/8, -1/16] (all corners not C^1) is not refined
    assert (R(-1, 16), R(-3, 32)) not in at
    # the refined points locate the boundary more finely: C^1 at (1/16, -1/16), not at (0, -1/16)
    assert at[(R(1, 16), R(-1, 16))]["C^1"] is True and at[(0, R(-1, 16))]["C^1"] is False


def test_exceptional_corners_do_not_trigger_refinement():
    samples = {(0, 0): {"C^1": True, "k": 1}, (1, 0): {"C^1": True, "k": 1},
               (0, 1): {"C^1": True, "k": 1}, (1, 1): {"C^1": False, "k": 3}}
    assert not _disagree((0, 0, 1), samples, (1,), 1, 1, generic_k=1)
    assert _disagree((0, 0, 1), samples, (1,), 1, 1, generic_k=None)


def test_exceptional_point_on_the_grid():
    # s = 1/4 is exceptional (four factors (1+z)): the cubic B-spline at t = 0, alpha = 3
    r = holder_atlas(FAMILY, "s", ("1/8", "1/4"), "t", (0, "1/32"), n1=2, n2=2, j_levels=(1, 2),
                     refine_levels=0, executor=None, progress=False, budget=30000)
    at = {(s["p1"], s["p2"]): s for s in r.value}
    assert at[(R(1, 4), 0)]["exceptional"] and at[(R(1, 4), 0)]["alpha"] == 3
    assert not at[(R(1, 8), 0)]["exceptional"]
    assert r.witness["exceptional_samples"] == 2 and r.witness["generic_k"] == 1


def test_figure_is_written(serial, tmp_path):
    path = plot_atlas(serial, tmp_path / "atlas.png")
    with open(path, "rb") as fh:
        assert fh.read(8) == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "atlas.png").stat().st_size > 10_000


def test_evaluate_point_verdicts():
    p = evaluate_point(FAMILY, {"s": "1/8", "t": 0}, (0, 1, 2))
    assert p["C^0"] and p["C^1"] and p["C^2"] is False and p["status"] == CERTIFIED
    assert 1.41 < float(p["alpha_lower"]) <= float(p["alpha_upper"]) < 1.42   # 2 - log2(3/2)


@pytest.mark.parametrize("kwargs, message", [
    (dict(p1="s", p2="s"), "must be different"),
    (dict(p1="x"), "unknown parameter 'x'"),
    (dict(range1=("1/8", "-1/8")), "low <= high"),
    (dict(range1=("sqrt(2)", 1)), "exact rational"),
    (dict(n1=0), "positive integer"),
    (dict(n1=1), "needs low == high"),
    (dict(refine_levels=-1), "refine_levels"),
    (dict(j_levels=()), "j_levels"),
    (dict(budget=0), "budget must be a positive number of work units"),
    (dict(executor="cluster"), "unknown executor"),
    (dict(executor="dask://"), "scheduler address"),
    (dict(executor="local", workers=0), "workers"),
])
def test_bad_input(kwargs, message):
    args = {**GRID, "executor": None, **kwargs}
    with pytest.raises(AnalysisError, match=message):
        holder_atlas(FAMILY, **args)


def test_free_parameter_not_on_an_axis():
    import schemes

    a = schemes.get("seed004-design-control").symbol
    with pytest.raises(AnalysisError, match="omega not on an axis"):
        holder_atlas(a, "mu", (0, 1), "nu", (0, 1), n1=2, n2=2, executor=None)


def test_parse_axis():
    assert parse_axis("nu=0:2:5") == ("nu", 0, 2, 5)
    assert parse_axis("mu=-0.2:0.2:3")[1] == R(-1, 5)
    for bad in ("nu", "nu=0:2", "nu=0:2:x", "1nu=0:1:2", "nu=a:1:2"):
        with pytest.raises(AnalysisError):
            parse_axis(bad)


# ------------------------------------------------------------------------------- CLI

def _run(capsys, *argv):
    code = main(list(argv), extra_modules=["analysis.cli.atlas"])
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_text_and_figure(capsys, tmp_path):
    fig = tmp_path / "a.png"
    code, out, err = _run(capsys, "atlas", "--symbol", FAMILY_EXPR, "--x", "s=-1/8:1/8:3", "--y", "t=-1/8:0:2",
                          "--j", "1", "--refine", "0", "--executor", "serial", "--figure", str(fig))
    assert code == 0, err
    assert "samples: 6" in out and "C^1: yes" in out and fig.exists()
    assert "exceptional: s = 1/4" in out


def test_cli_json(capsys):
    code, out, err = _run(capsys, "atlas", "--scheme", "seed004-design-control", "--param", "omega=0",
                          "--param", "nu=1", "--x", "mu=0:0:1", "--y", "omega=0:0:1", "--json")
    assert code == 2 and "unknown parameter 'omega'" in err   # omega was fixed by --param
    code, out, err = _run(capsys, "atlas", "--symbol", FAMILY_EXPR, "--x", "s=0:1/8:2", "--y", "t=0:0:1",
                          "--j", "1", "--executor", "serial", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["status"] == "certified" and data["witness"]["counts"]["per_level"] == [2, 1]
    assert [s["p1"] for s in data["value"]] == [0, "1/16", "1/8"]     # exact: ints or "p/q"


@pytest.mark.parametrize("argv, message", [
    (["--x", "s=0:1:2"], "give both axes"),
    (["--x", "s=0:1", "--y", "t=0:1:2"], "malformed axis"),
    (["--x", "s=0:1:2", "--y", "t=0:1:2", "--refine", "-1"], "--refine must be between 0 and 8"),
    (["--x", "s=0:1:2", "--y", "t=0:1:2", "--budget", "x"], "--budget must be a number"),
    (["--x", "s=0:1:2", "--y", "t=0:1:2", "--executor", "mpi"], "unknown executor"),
    (["--x", "s=0:1:2", "--y", "t=0:1:2", "--workers", "0"], "--workers must be between 1 and 64"),
    (["--x", "s=0:1:2", "--y", "s=0:1:2"], "must be different"),
])
def test_cli_bad_input(capsys, argv, message):
    code, out, err = _run(capsys, "atlas", "--symbol", FAMILY_EXPR, "--no-progress", *argv)
    assert code == 2
    assert err.startswith("subdiv: error: ") and message in err and err.count("\n") == 1
