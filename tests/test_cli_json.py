"""`--json` is exactly one JSON document on stdout, for every command (issue 9.2).

Each command runs through :func:`analysis.cli.main.main` with file descriptors 1 and 2 captured
(``tests/cli_run.py``), so that output written by compiled libraries at the file-descriptor level is
caught too; ``subdiv report --json`` and the solver-banner tests run ``python -m analysis ...`` in a
fresh process (HiGHS prints its banner when the first ``Highs`` object of a process is built). The
inputs exercise the solver paths: the warm-started HiGHS LP (real invariant polytope), Clarabel's SOCP
(complex invariant polytope), Arb ball arithmetic (Daubechies D6), local worker processes and a
Dask cluster. The second half tests the guard of :func:`analysis.cli.main.main` itself: whatever a
library prints (Python ``print``, ``os.write(1, ...)``, C ``puts``) goes to stderr, in a
subprocess and under pytest's ``capsys``/``capfd``, and ``subdiv ... | head`` stays quiet."""

from __future__ import annotations

import json
import os
from fractions import Fraction
import subprocess
import sys
import textwrap

import pytest

from analysis.cli import main
from tests.cli_run import run_cli

FOUR_POINT = "-1/16,0,9/16,1,9/16,0,-1/16"          # the 4-point scheme, w = 1/16: alpha = 2 (LP path)
#: c = 2a/(1+z)^2 has transition matrix T0 with the complex leading eigenvalue (15 + i sqrt(479))/16
#: (spectral radius sqrt(11)/2 = the JSR): the real polytope cannot close, the complex one (Clarabel) does
COMPLEX = "-3/8,-1/4,17/16,15/8,7/8,-5/8,-9/16"
FAMILY = "(1+z)**2/(2*z)*(1 + s*(z-2+1/z) + t*(z**2-2+z**-2))"   # tests/test_atlas.py
ATLAS = ["atlas", "--symbol", FAMILY, "--x", "s=-1/8:1/8:3", "--y", "t=-1/8:0:2", "--j", "1", "--refine", "0",
         "--no-progress"]


def run(*args, timeout=300):
    p = subprocess.run([sys.executable, "-m", "analysis", *args], capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def run_json(*args, code=0):
    rc, out, err = run(*args)
    assert rc == code, err
    assert "Traceback" not in err
    return json.loads(out)            # the whole of stdout: exactly one JSON document


def _jsr(data):
    return data["alpha"]["witness"]["jsr"]


# --------------------------------------------------------------------------------------------
# every command with --json
# --------------------------------------------------------------------------------------------

CASES = {
    "symbol": (["symbol", "--mask", FOUR_POINT, "--start", "-3"], lambda d: d["start"] == -3 and len(d["mask"]) == 7),
    "factor": (["factor", "--scheme", "dfh-chaikin-perturbation"], lambda d: d["k"] == 3),
    "norm": (["norm", "--scheme", "dfh-chaikin-perturbation", "--m", "3", "--L", "1,2", "--solve", "omega",
              "--within", "0,oo"], lambda d: [r["L"] for r in d["results"]] == [1, 2]),
    "refine": (["refine", "--scheme", "four-point", "--param", "w=1/16", "--points", "0,0;1,0;1,1;0,1",
                "--steps", "2"], lambda d: d["count"] == 16),
    "matrices": (["matrices", "--scheme", "four-point", "--param", "w=1/16", "--transition"],
                 lambda d: "T0" in d["transition"]),
    "list": (["list", "--numeric"], lambda d: any(s["slug"] == "chaikin" for s in d["schemes"])),
    "holder-lp": (["holder", "--mask", FOUR_POINT, "--start", "-3", "--C", "1", "--sobolev"],
                  lambda d: d["alpha"]["value"] == 2 and _jsr(d)["witness"]["lp_calls"] >= 1
                  and _jsr(d)["witness"]["leading_eigenvalue_real"] is True and "sobolev" in d),
    "holder-socp": (["holder", "--mask", COMPLEX, "--start", "0"],
                    lambda d: _jsr(d)["witness"]["leading_eigenvalue_real"] is False
                    and _jsr(d)["witness"]["complex_polytope"]["socp_calls"] >= 1
                    and d["alpha"]["status"] == "certified"),
    "holder-arb": (["holder", "--scheme", "d6"],
                   lambda d: "ball" in json.dumps(d["alpha"]["provenance"]).lower() and d["alpha"]["status"] == "certified"),
    "range": (["range", "--scheme", "four-point", "--C", "0", "--within=0,1/8", "--grid", "2"],
              lambda d: d["j"] == 0 and d["result"]["status"] in ("certified", "inconclusive")),
    "atlas-local-processes": ([*ATLAS, "--workers", "2"],
                              lambda d: d["witness"]["executor"] == "local processes (2)"),
    "series": (["series", "--scheme", "seed003-trigonometric", "--param", "alpha=1", "--param", "omega=1/100",
                "--m", "0,1"], lambda d: [r["m"] for r in d["series"]] == [0, 1]),
    "bound": (["bound", "--claim", "003:Lemma3.1(iii)-upper", "--box", "alpha=1/100,pi/3", "--param", "omega=1/100"],
              lambda d: "status" in d),
    "reproduce": (["reproduce", "--scheme", "exp-chaikin-trig", "--lambdas", "I*t,-I*t", "--curve", "circle",
                   "--param", "t=pi/4", "--points", "8"], lambda d: {"generation", "curve"} <= set(d)),
    "nonuniform-refine": (["nonuniform", "refine", "--degree", "3", "--points", "0,0;1,0;1,1;0,1", "--u", "0.5,1,2,1",
                           "--closed", "--steps", "2"], lambda d: d["count"] == len(d["points"])),
    "nonuniform-compare-definitions": (["nonuniform", "compare-definitions", "--degree", "3", "--levels", "2"],
                                       lambda d: "status" in d),
    "nonuniform-decay": (["nonuniform", "decay", "--u0", "0.5,2", "--degree", "2", "--levels", "4"],
                         lambda d: d["status"] == "certified"),
    "nonuniform-lemma": (["nonuniform", "lemma", "--u0-range", "0.01,100", "--levels", "20"],
                         lambda d: {"lemma_2_1", "rate"} == set(d)),
    "nonuniform-property-a": (["nonuniform", "property-a", "--degree", "4"], lambda d: d["degree"] == 4),
    "nonuniform-junction": (["nonuniform", "junction", "--degree", "3", "--u-left", "0.3", "--u-right", "4",
                             "--levels", "8"], lambda d: "omega_junction" in d["witness"]),
    "nonuniform-reproduce": (["nonuniform", "reproduce", "--kind", "circle", "--degree", "3", "--levels", "4"],
                             lambda d: "deviation" in d["witness"]),
    "nonuniform-chamfer": (["nonuniform", "chamfer", "--levels", "4"], lambda d: "midpoint_deviation" in d["witness"]),
    "nonuniform-claims": (["nonuniform", "claims", "--seed", "000"], lambda d: len(d) > 0 and "status" in d[0]),
    # one claim: the whole of every paper is checked by tests/test_report.py (and tests/test_claims_*.py)
    "check": (["check", "000", "--claim", "000:S_2"], lambda d: d["agree"] is True and d["claims"] == 1),
    "new-paper": (["new-paper", os.path.join(__import__("tempfile").mkdtemp(), "p.toml")],        # issue 11
                  lambda d: d["wrote"].endswith("p.toml") and "smoothness profile" in d["kinds"]),
    "surface": (["surface", "--scheme", "box-111"],
                lambda d: d["holder"]["value"] == "1" and d["smoothness"] == {"C0": True, "C1": False, "C2": False}),
    "derive": (["derive", "--support", "7", "--interpolatory", "--symmetric", "primal", "--reproduce", "1"],
               lambda d: d["dimension"] == 1 and d["status"] == "certified"),
    "jsr": (["jsr", os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples",
                                 "jsr-golden-pair.json")],
            # JSR of [[1,1],[0,1]], [[1,0],[1,1]] is the golden ratio 1.61803398874989...
            lambda d: d["status"] == "certified"
            and Fraction(161803398874, 10**11) < Fraction(d["lower"]) <= Fraction(d["upper"]) < Fraction(161803398875, 10**11)),
    "vertex": (["vertex", "--scheme", "loop", "--valence", "4", "--ring", "1"],
               lambda d: d["valences"][0]["reif"]["status"] == "certified" and d["closed_form"]["lambda"] == "c/4 + 3/8"),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_every_command_json_is_one_document(name, capfd):
    """In the test process (file descriptors captured: what a subprocess would print on stdout); a
    fresh process is tested by the report case below and by the guard tests further down."""
    argv, ok = CASES[name]
    r = run_cli(capfd, *argv, "--json")
    assert r.returncode == 0, r.stderr
    assert "Traceback" not in r.stderr
    data = json.loads(r.stdout)            # the whole of stdout: exactly one JSON document
    assert ok(data), data


def test_every_command_is_covered():
    """The table above (with `report` below) has a case for every command and `nonuniform` sub-command."""
    import argparse

    from analysis.cli.main import build_parser

    def commands(parser, prefix=()):
        out = set()
        for a in parser._actions:
            if isinstance(a, argparse._SubParsersAction):
                for n, sub in a.choices.items():
                    out |= commands(sub, (*prefix, n)) or {(*prefix, n)}
        return out

    covered = {tuple(argv[:2]) if argv[0] == "nonuniform" else (argv[0],) for argv, _ in CASES.values()}
    assert commands(build_parser()) - covered == {("report",)}     # report: test_report_json_... below


def test_report_json_writes_to_output_folder(tmp_path, capfd):
    """The writing path of ``report --json`` (two claims of paper 000 written with ``--write``: the same
    rendering and writing code as the whole paper, without its slow claims)."""
    r = run_cli(capfd, "report", "000", "--claim", "000:S_2", "--claim", "000:regularity", "--write",
                "--output", str(tmp_path), "--quiet", "--json")
    assert r.returncode == 0, r.stderr
    data = json.loads(r.stdout)
    assert set(data["papers"]) == {"000"}
    assert set(data["papers"]["000"]["claims"]) == {"000:S_2", "000:regularity"}
    assert (tmp_path / "000.md").exists() and (tmp_path / "verdicts.json").exists()


@pytest.mark.slow
def test_atlas_json_on_a_dask_cluster(capfd):
    """The command in this process (file descriptors captured), its two Dask workers threads of it
    talking TCP (``processes=False``): whatever a worker prints meets the same stdout guard."""
    distributed = pytest.importorskip("distributed")   # a test dependency ([test] extra)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, protocol="tcp",
                                  dashboard_address=None) as cluster:
        address = cluster.scheduler_address.split("://", 1)[1]
        r = run_cli(capfd, *ATLAS, "--executor", f"dask://{address}", "--json")
    assert r.returncode == 0, r.stderr
    assert "Traceback" not in r.stderr
    data = json.loads(r.stdout)            # the whole of stdout: exactly one JSON document
    assert data["witness"]["executor"].startswith("dask cluster at tcp://")
    assert data["witness"]["counts"]["samples"] == 6


def test_text_output_has_no_solver_banner():
    rc, out, err = run("holder", "--mask", FOUR_POINT, "--start", "-3")
    assert rc == 0 and "alpha = 2 exactly" in out
    assert "HiGHS" not in out and "third-party" not in out


def test_highs_banner_is_suppressed_at_the_source():
    """HiGHS prints its banner when the first Highs object of a process is built; WarmLP builds
    it with fd 1 pointed at /dev/null. The reference run shows the banner exists to be caught."""
    ref = subprocess.run([sys.executable, "-c", "import highspy; highspy.Highs()"], capture_output=True, text=True)
    if "HiGHS" not in ref.stdout:
        pytest.skip("this highspy prints no banner: nothing to suppress")
    p = subprocess.run([sys.executable, "-c", "from analysis.jsr._lp import WarmLP, small_lp\n"
                        "import numpy as np\n"
                        "s = small_lp(np.eye(2), np.ones(2))\n"
                        "a = WarmLP.create(3); b = WarmLP.create(2); print('done')"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout == "done\n" and "HiGHS" not in p.stderr


# --------------------------------------------------------------------------------------------
# the guard in main(): nothing of a library reaches stdout
# --------------------------------------------------------------------------------------------

NOISY = textwrap.dedent('''
    """A sub-command that prints like a badly behaved library, then emits its own output."""
    import ctypes
    import os
    import sys


    def cmd(args):
        print("python-print-from-library")
        sys.stdout.flush()
        os.write(1, b"fd1-write-from-library\\n")
        ctypes.CDLL(None).puts(b"c-puts-from-library")      # C stdio, buffered
        from analysis.cli.common import _emit
        _emit(args, {"ok": True}, "own text output")


    def register(sub):
        s = sub.add_parser("noisy")
        s.add_argument("--json", action="store_true")
        s.set_defaults(func=cmd)
''')
LIBRARY_LINES = ("python-print-from-library", "fd1-write-from-library", "c-puts-from-library")


@pytest.fixture
def noisy(tmp_path, monkeypatch):
    (tmp_path / "noisy_cmd.py").write_text(NOISY)
    monkeypatch.syspath_prepend(str(tmp_path))
    return tmp_path


@pytest.mark.parametrize("json_mode", [True, False])
def test_library_output_never_reaches_stdout(noisy, json_mode):
    code = ("import sys\nfrom analysis.cli.main import main\n"
            "sys.exit(main(sys.argv[1:], extra_modules=['noisy_cmd']))")
    p = subprocess.run([sys.executable, "-c", code, "noisy", *(["--json"] if json_mode else [])],
                       capture_output=True, text=True, cwd=noisy, timeout=120,
                       env={**os.environ, "PYTHONPATH": str(noisy)})
    assert p.returncode == 0, p.stderr
    if json_mode:
        assert json.loads(p.stdout) == {"ok": True}
    else:
        assert p.stdout == "own text output\n"
    for line in LIBRARY_LINES:              # diverted, not lost
        assert line in p.stderr


def test_guard_cooperates_with_capsys(noisy, capsys):
    assert main(["noisy", "--json"], extra_modules=["noisy_cmd"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out) == {"ok": True}
    assert "python-print-from-library" in err
    assert sys.stdout is not sys.stderr                  # restored


def test_guard_cooperates_with_capfd(noisy, capfd):
    assert main(["noisy"], extra_modules=["noisy_cmd"]) == 0
    out, err = capfd.readouterr()
    assert out == "own text output\n"
    for line in LIBRARY_LINES:
        assert line in err


@pytest.mark.parametrize("extra", [[], ["--json"]])
def test_broken_pipe_is_quiet(extra):
    """`subdiv refine ... | head -1`: the reader goes away; exit 0, nothing on stderr. (12 steps print
    650 kB as text, 1 MB as JSON: ten times a pipe's buffer, so the writer always meets the closed pipe.)"""
    p = subprocess.Popen([sys.executable, "-m", "analysis", "refine", "--scheme", "chaikin", "--points",
                          "0,0;1,0;1,1;0,1", "--steps", "12", *extra], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    first = p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read()
    assert p.wait(timeout=120) == 0
    assert first and err == b""
