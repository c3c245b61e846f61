"""Run the `subdiv` command in the test process, as a subprocess would see it.

``run_cli(capfd, *argv)`` calls :func:`analysis.cli.main.main` and captures file descriptors 1 and 2
(``capfd``), so that output written below Python (C libraries, ``os.write``) is seen as well: what
``python -m analysis ARGV`` prints, without paying a fresh interpreter and its imports for every call
(about a second of CPU each). A fresh process is tested where it matters: the end-to-end tests of
``tests/test_cli.py``, the library-output guard and the solver banner (``tests/test_cli_json.py``),
the start-up imports (``tests/test_startup.py``).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Ran:
    """What a finished `subdiv` run returned and printed (the fields of ``subprocess.CompletedProcess``)."""

    returncode: int
    stdout: str
    stderr: str


def run_cli(capfd, *argv: str) -> Ran:
    """``subdiv ARGV`` in this process: exit code (``SystemExit`` included), stdout and stderr."""
    from analysis.cli.main import main

    capfd.readouterr()                     # what earlier code printed is not this run's output
    try:
        code = main(list(argv))
    except SystemExit as exc:              # argparse and `subdiv check` exit
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    out, err = capfd.readouterr()
    return Ran(code, out, err)


def run_main(capsys, *argv) -> tuple[int, str, str]:
    """``main(ARGV)`` (arguments turned into text) with ``capsys``: (exit code, stdout, stderr)."""
    from analysis.cli import main

    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_line_error(code: int, err: str, *needles: str) -> None:
    """Exit code 2 and one line ``subdiv: error: ...`` holding every needle."""
    assert code == 2, err
    assert err.startswith("subdiv: error: ") and err.count("\n") == 1, err
    for n in needles:
        assert n in err, err
