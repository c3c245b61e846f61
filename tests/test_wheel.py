"""Issue 10: the wheel works from any directory.

The wheel (built from the sources by the project's build backend, the hook ``pip wheel .`` calls; not the
editable checkout) is built offline, installed into a fresh
virtual environment, and ``subdiv report 000`` and ``subdiv check 003`` run from an empty temporary
directory (the smallest paper's report and ``check`` on two claims of 003, to keep the suite fast: the full
reports are reproduced by tests/test_report.py and tests/test_claims_003.py): the report goes to ``./reports`` of that directory, and ``check`` finds the golden
verdicts shipped inside the installed ``papers`` package.

The venv does not inherit the editable install: its only link to the dependencies (sympy,
python-flint, ...) is a ``.pth`` line naming the interpreter's site-packages, and a path added
that way has its own ``.pth`` files (among them the editable finder of this checkout) ignored.
The test asserts that ``analysis`` and ``papers`` are imported from the venv.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import sysconfig
import venv
from pathlib import Path

import pytest

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.slow


#: the environment of every subprocess: no PYTHONPATH (a checkout on it would shadow the wheel, and
#: its egg-info would make pip think the wheel is installed already)
CLEAN_ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}


def _run(cmd, cwd, env=None, timeout=600):
    proc = subprocess.run(cmd, cwd=cwd, env=CLEAN_ENV if env is None else env, capture_output=True, text=True,
                          timeout=timeout)
    assert proc.returncode == 0, f"{cmd} failed ({proc.returncode}):\n{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}"
    return proc


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    build = tmp_path_factory.mktemp("wheel")
    # the PEP 517 hook that `pip wheel . --no-build-isolation` calls (the backend of pyproject.toml, building
    # from the sources in the checkout), without pip's start-up and its separate subprocess per hook
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    backend = project["build-system"]["build-backend"]
    _run([sys.executable, "-c", f"import importlib; importlib.import_module({backend!r}).build_wheel({str(build)!r})"],
         cwd=ROOT)
    wheels = list(build.glob("subdiv_workbench-*.whl"))
    assert len(wheels) == 1, wheels
    env_dir = tmp_path_factory.mktemp("venv") / "env"
    venv.EnvBuilder(with_pip=False).create(env_dir)
    py = env_dir / "bin" / "python"
    site = Path(subprocess.check_output([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                                        text=True, env=CLEAN_ENV).strip())
    deps = {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}
    (site / "_subdiv_test_deps.pth").write_text("\n".join(sorted(deps)) + "\n")
    _run([sys.executable, "-m", "pip", "--python", str(py), "install", "--no-deps", "--no-index",
          "--force-reinstall", str(wheels[0]), "-q"], cwd=build)
    return env_dir, site


def test_the_wheel_ships_every_subpackage_and_the_golden_verdicts(installed):
    env_dir, site = installed
    for pkg in ("analysis/algebra", "analysis/regularity", "analysis/cli", "papers/seed003", "schemes"):
        assert (site / pkg / "__init__.py").is_file(), pkg
    for pid in ("000", "001", "003", "004"):
        golden = json.loads((site / "papers" / f"seed{pid}" / "verdicts.json").read_text())
        assert pid in golden["papers"]


def test_report_and_check_from_an_empty_directory(installed, tmp_path):
    env_dir, site = installed
    work = tmp_path / "empty"
    work.mkdir()
    env = CLEAN_ENV
    where = _run([str(env_dir / "bin" / "python"), "-c",
                  "import analysis, papers; print(analysis.__file__); print(papers.__file__)"], cwd=work, env=env)
    for line in where.stdout.split():
        assert Path(line).resolve().is_relative_to(site.resolve()), f"imported from the checkout: {line}"
    subdiv = str(env_dir / "bin" / "subdiv")
    _run([subdiv, "report", "000"], cwd=work, env=env)
    assert (work / "reports" / "000.md").is_file()
    assert "000" in json.loads((work / "reports" / "verdicts.json").read_text())["papers"]
    # the comparison itself is what is tested here (the full recomputation against the golden files
    # is tests/test_report.py::test_committed_verdicts_are_reproduced): two fast claims suffice
    check = _run([subdiv, "check", "003", "--claim", "003:Sec4(*^n)"], cwd=work, env=env)
    assert "claims agree with" in check.stdout and str(site / "papers") in check.stdout, check.stdout
    assert sorted(p.name for p in work.iterdir()) == ["reports"]      # nothing else written
