"""What the command line imports to start (a structural check; never a timing).

``subdiv --help``, ``subdiv holder --help`` and ``subdiv list`` import no sympy, numpy, scipy,
matplotlib, flint, mpmath, tqdm or dask and none of the claims/report layers; a small ``holder``
imports no scipy, matplotlib, claims or report module, and a catalogue entry known by Arb balls
(daubechies-8) no sympy either. Each command runs as ``python -m analysis ...`` does (runpy) in
a fresh interpreter from the checkout, and ``sys.modules`` is read when it ends, so that the test
sees what a user's ``subdiv ...`` imports. (``-X importtime`` does not log the modules imported by
``importlib.import_module``.) Timings are in ``benchmarks/bench_startup.py``, not here.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: libraries the parser, --help and the catalogue listing must not import
HEAVY = ("sympy", "numpy", "scipy", "matplotlib", "flint", "mpmath", "gmpy2", "tqdm", "dask", "highspy",
         "clarabel")
#: layers above the engine that only report and check commands use
UPPER = ("analysis.claims", "analysis.report", "papers")


def _env(extra: str | None = None) -> dict:
    path = os.pathsep.join(p for p in (str(ROOT), extra, os.environ.get("PYTHONPATH")) if p)
    return {**os.environ, "PYTHONPATH": path}


#: runs ``python -m analysis ARGS`` (runpy, as ``-m`` does) and writes the modules it imported to a file
_RUN = textwrap.dedent("""
    import runpy, sys
    out, sys.argv = sys.argv[1], ["analysis", *sys.argv[2:]]
    try:
        runpy.run_module("analysis", run_name="__main__", alter_sys=True)
    except SystemExit as exc:
        code = exc.code
    else:
        code = 0
    with open(out, "w", encoding="utf-8") as f:
        f.write("\\n".join([sys.modules["analysis"].__file__, *sorted(sys.modules)]))
    sys.exit(code)
""")


def imported(*args: str, code: int = 0) -> set[str]:
    """The modules ``python -m analysis ARGS`` has imported when it ends, run from the checkout in a
    fresh interpreter."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "modules.txt"
        p = subprocess.run([sys.executable, "-c", _RUN, str(out), *args], capture_output=True, text=True,
                           cwd=ROOT, env=_env(), timeout=300)
        assert p.returncode == code, p.stderr[-2000:]
        where, *mods = out.read_text(encoding="utf-8").splitlines()
    assert Path(where).resolve() == ROOT / "analysis" / "__init__.py"       # this checkout's package
    return set(mods)


def loaded(mods: set[str], roots) -> list[str]:
    """The modules of ``mods`` that are one of ``roots`` or inside one of them."""
    return sorted(m for m in mods if any(m == r or m.startswith(r + ".") for r in roots))


@pytest.mark.parametrize("argv", [["--help"], ["holder", "--help"], ["range", "--help"], ["list"],
                                  ["list", "--numeric", "--mary", "--json"], ["--version"], ["vertex", "--help"]],
                         ids=["help", "holder-help", "range-help", "list", "list-all", "version", "vertex-help"])
def test_help_and_list_import_no_heavy_library(argv):
    mods = imported(*argv)
    assert not loaded(mods, HEAVY), f"`subdiv {' '.join(argv)}` imports {loaded(mods, HEAVY)[:12]}"
    assert not loaded(mods, UPPER), f"`subdiv {' '.join(argv)}` imports {loaded(mods, UPPER)[:12]}"
    engine = [m for m in mods if m.startswith("analysis.") and not m.startswith(("analysis.cli.", "analysis.cli"))
              and m not in ("analysis.result", "analysis.jsonable", "analysis.algebra", "analysis.algebra.guard", "analysis._lazy")]
    assert not engine, f"`subdiv {' '.join(argv)}` imports engine modules {sorted(engine)[:12]}"


def test_building_the_parser_imports_no_engine():
    code = textwrap.dedent("""
        import sys
        from analysis.cli.main import build_parser
        build_parser().format_help()
        print(" ".join(sorted(sys.modules)))
    """)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, env=_env(),
                       timeout=300)
    assert p.returncode == 0, p.stderr
    mods = set(p.stdout.split())
    assert "analysis.cli.regularity" in mods and "analysis.cli.report" in mods   # every command registered
    assert not loaded(mods, HEAVY + UPPER + ("schemes",)), loaded(mods, HEAVY + UPPER + ("schemes",))
    assert {m for m in mods if m.startswith("analysis.") and not m.startswith("analysis.cli")} <= {"analysis.result", "analysis._lazy"}


@pytest.mark.parametrize("argv, exact", [
    (["holder", "--mask", "1/4,3/4,3/4,1/4"], True),
    (["holder", "--scheme", "chaikin", "--json"], True),
    (["holder", "--scheme", "daubechies-8"], False),
], ids=["mask", "chaikin", "daubechies-8"])
def test_small_holder_imports_only_what_it_uses(argv, exact):
    """An exact mask reads its symbol with sympy; a catalogue entry known by Arb balls
    (daubechies-8) needs no sympy at all, and its invariant polytope picks its bases without
    scipy (the pivots in numpy, the LPs through HiGHS)."""
    mods = imported(*argv)
    assert "analysis.regularity.holder" in mods and "analysis.jsr" in mods      # it did compute
    unused = ("scipy", "matplotlib", "tqdm", "dask", "clarabel", *UPPER,
              "analysis.regularity.atlas", "analysis.regularity.ranges", "analysis.regularity.sobolev",
              "analysis.nonuniform", "schemes.seed003", "schemes.seed004")
    assert not loaded(mods, unused), loaded(mods, unused)
    if exact:
        assert "sympy" in mods
    else:
        assert "analysis.jsr._polytope" in mods and "flint" in mods             # the ball route ran
        assert not loaded(mods, ("sympy", "analysis.algebra.symbol", "analysis.algebra.reader")), \
            loaded(mods, ("sympy", "analysis.algebra.symbol", "analysis.algebra.reader"))


def test_parser_guard_applies_when_a_command_imports_sympy_late(tmp_path):
    """The guard of sympy's string parser (analysis.algebra.guard) is in place even when sympy is
    first imported by the command itself, after the guard was entered."""
    (tmp_path / "late_sympy_cmd.py").write_text(textwrap.dedent("""
        def cmd(args):
            import sympy
            sympy.sympify("__import__('os').getcwd()")


        def register(sub):
            sub.add_parser("late").set_defaults(func=cmd)
    """))
    code = ("import sys\nfrom analysis.cli.main import main\n"
            "assert 'sympy' not in sys.modules\n"
            "sys.exit(main(['late'], extra_modules=['late_sympy_cmd']))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       env=_env(str(tmp_path)), timeout=300)
    assert p.returncode == 2, p.stderr
    assert p.stderr.startswith("subdiv: error: text") and "reached sympy's parser" in p.stderr
    assert "Traceback" not in p.stderr and p.stdout == ""
