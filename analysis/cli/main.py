"""The ``subdiv`` command line: the parser and :func:`main` (the one place that turns errors into
one line on stderr and an exit code, and guards standard output).

The command groups live in their own modules and register themselves (:data:`COMMAND_MODULES`):
:mod:`.stationary`, :mod:`.regularity`, :mod:`.atlas`, :mod:`.levels`, :mod:`.nonuniform`,
:mod:`.report`, :mod:`.derive`; what they share is in :mod:`.common`.

Every command takes a scheme in one of four ways — a catalogue name, a mask, paper-style
rules, or a symbol expression — and parameter values with ``--param NAME=VALUE`` (exact:
``1/100``, ``(sqrt(6)-1)/80``; decimals are read exactly). ``--json`` prints machine-readable
output. Bad input prints one line ``subdiv: error: ...`` on stderr and exits with code 2.

Examples
--------
::

    subdiv symbol --mask "1/4,3/4,3/4,1/4" --start -2
    subdiv factor --scheme dfh-chaikin-perturbation
    subdiv norm --scheme dfh-chaikin-perturbation --m 3 --L 1,2,3,4 --solve omega --within 0,oo
    subdiv norm --scheme dfh-chaikin-perturbation --param omega=1/100 --m 3 --L 2
    subdiv refine --scheme four-point --param w=1/16 --points "0,0;1,0;1,1;0,1" --steps 3
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from typing import Sequence

from ..result import AnalysisError
from .common import _Parser, _StdoutGuard, _version, attach_dash_values

COMMAND_MODULES: tuple[str, ...] = ("analysis.cli.stationary", "analysis.cli.regularity", "analysis.cli.atlas",
                                     "analysis.cli.levels", "analysis.cli.nonuniform", "analysis.cli.report",
                                     "analysis.cli.paperfile", "analysis.cli.derive")


def build_parser(extra_modules: Sequence[str] = ()) -> argparse.ArgumentParser:
    p = _Parser(prog="subdiv", description="Exact and certified analysis of binary subdivision schemes. "
                "Convention: (S_a f)_i = sum_j a_{i-2j} f_j, a(z) = sum_i a_i z^i.")
    p.add_argument("--version", action="version", version=f"subdiv {_version()}")
    sub = p.add_subparsers(dest="command", parser_class=_Parser)
    sub.required = True
    for name in dict.fromkeys((*COMMAND_MODULES, *extra_modules)):  # each module once
        importlib.import_module(name).register(sub)
    return p


def main(argv: Sequence[str] | None = None, *, extra_modules: Sequence[str] = ()) -> int:
    parser = build_parser(extra_modules)
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        args = parser.parse_args(attach_dash_values(parser, argv))
        with _StdoutGuard():
            args.func(args)
    except AnalysisError as exc:
        print(f"subdiv: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("subdiv: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `subdiv symbol ... | head`
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:  # pragma: no cover
            pass
        return 0
    except Exception as exc:  # never a traceback for users; SUBDIV_DEBUG=1 shows it
        if os.environ.get("SUBDIV_DEBUG"):
            raise
        print(f"subdiv: internal error: {type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''} "
              "(please report; SUBDIV_DEBUG=1 shows the traceback)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
