"""The ``subdiv`` command line: the parser and :func:`main` (the one place that turns errors into
one line on stderr and an exit code, and guards standard output).

Start-up is cheap: building the parser imports no engine module and no sympy, numpy or scipy (the
command modules import what a command needs inside the command's function), so ``subdiv --help``
and ``subdiv list`` start in a fraction of a second; ``tests/test_startup.py`` keeps it so.

The command groups live in their own modules and register themselves (:data:`COMMAND_MODULES`):
:mod:`.stationary`, :mod:`.regularity`, :mod:`.atlas`, :mod:`.levels`, :mod:`.nonuniform`,
:mod:`.report`, :mod:`.derive`, :mod:`.jsr`; what they share is in :mod:`.common`.

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
import errno
import functools
import importlib
import os
import sys
from typing import Sequence

from ..result import AnalysisError
from .common import _Parser, _StdoutGuard, _version, attach_dash_values


class _VersionAction(argparse._VersionAction):
    """``--version``: the version is looked up (``importlib.metadata``) only when asked for."""

    @property
    def version(self) -> str:
        return f"subdiv {_version()}"

    @version.setter
    def version(self, value) -> None:  # argparse sets it in __init__; the property answers
        pass


COMMAND_MODULES: tuple[str, ...] = ("analysis.cli.stationary", "analysis.cli.regularity", "analysis.cli.atlas",
                                     "analysis.cli.levels", "analysis.cli.nonuniform", "analysis.cli.report",
                                     "analysis.cli.paperfile", "analysis.cli.derive", "analysis.cli.vertex",
                                     "analysis.cli.jsr", "analysis.cli.surface")


#: one or two examples per command, shown at the end of ``subdiv COMMAND --help`` (the user guide, docs/,
#: has more; every line here must be a valid command: tests/test_cli_help.py parses them)
EXAMPLES: dict[str, tuple[str, ...]] = {
    "symbol": ('subdiv symbol --mask "1/4,3/4,3/4,1/4" --start -2',
               'subdiv symbol --even "3/4,1/4" --odd "1/4,3/4"'),
    "factor": ("subdiv factor --scheme four-point",
               "subdiv factor --scheme ternary-four-point"),
    "norm": ("subdiv norm --scheme four-point --m 2 --L 2 --solve w",
             'subdiv norm --scheme dfh-chaikin-perturbation --param "omega=(sqrt(6)-1)/80" --m 3 --L 2,3'),
    "refine": ('subdiv refine --scheme four-point --param w=1/16 --points "0,0;1,0;1,1;0,1" --steps 3',
               'subdiv refine --scheme ternary-dd-4 --points "0;1;8;27;64" --open --exact'),
    "matrices": ("subdiv matrices --scheme four-point --param w=1/16",
                 "subdiv matrices --scheme chaikin --transition"),
    "list": ("subdiv list", "subdiv list --mary --numeric"),
    "holder": ('subdiv holder --mask "-1/16,0,9/16,1,9/16,0,-1/16" --start -3 --C 2 --sobolev',
               'subdiv holder --symbol "(1+z)**2*(1+2*c*z+z**2)/(4*(1+c))/z**2" --where "c=cos(t/2**(n+1))" '
               '--param t=1',
               "subdiv holder --scheme four-point --param w=1/16 --C 1 --table alpha.tex"),
    "range": ("subdiv range --scheme four-point --C 1 --within=-1/8,1/4",
              "subdiv range --scheme ternary-four-point --C 2 --within=-1,1"),
    "atlas": ("subdiv atlas --scheme seed004-design-control --param omega=0 --x mu=-1/5:1/5:9 --y nu=0:2:9 "
              "--figure atlas.png",),
    "series": ("subdiv series --scheme seed003-trigonometric --param alpha=1 --param omega=1/100 --m 0,1,2",
               'subdiv series --symbol "(1+z)**3/4/z**2 + (z-1)**4/z**2/(n+2)**3" --m 0,1'),
    "bound": ("subdiv bound --claim '003:Lemma3.1(iii)-upper' --box alpha=1/100,pi/3",),
    "reproduce": ("subdiv reproduce --scheme exp-cubic-trig --frequencies",),
    "nonuniform": ("subdiv nonuniform compare-definitions", "subdiv nonuniform claims --seed 001"),
    "report": ("subdiv report all", "subdiv report examples/four-point.toml --output r --quiet",
               "subdiv report examples/four-point.toml --output r --table verdicts.tex"),
    "check": ("subdiv check", "subdiv check examples/first-paper.toml",
              "subdiv check examples/four-point.toml --table verdicts.csv"),
    "new-paper": ("subdiv new-paper mine.toml",),
    "derive": ("subdiv derive --support 7 --interpolatory --symmetric primal --reproduce 1",
               "subdiv derive --arity 3 --support 11 --interpolatory --symmetric primal --reproduce 2 "
               "--maximize holder --within=-1/16,0"),
    "vertex": ("subdiv vertex --scheme loop --valence 3..8",
               'subdiv vertex --lattice triangle --centre "3/(8*n)" --valence 3..5'),
    "jsr": ("subdiv jsr examples/jsr-gripenberg.json", "subdiv jsr examples/jsr-golden-pair.json --json"),
    "surface": ("subdiv surface --scheme loop", "subdiv surface --scheme butterfly --param w=1/16 --json"),
}


def build_parser(extra_modules: Sequence[str] = ()) -> argparse.ArgumentParser:
    p = _Parser(prog="subdiv", formatter_class=argparse.RawDescriptionHelpFormatter,
                description="Exact and certified analysis of subdivision schemes: binary and m-ary (--arity M),\n"
                "stationary, level-dependent (the level n, --where) and non-uniform; paper files of claims.\n"
                "Convention: (S_a f)_i = sum_j a_{i-Mj} f_j, a(z) = sum_i a_i z^i (M = 2: binary).",
                epilog="examples:\n  subdiv holder --scheme four-point --param w=1/16 --C 1\n"
                       "  subdiv report examples/four-point.toml --output r\n"
                       "`subdiv COMMAND --help` shows a command's options and examples;\n"
                       "the user guide is docs/index.md.")
    p.add_argument("--version", action=_VersionAction)
    sub = p.add_subparsers(dest="command", parser_class=_Parser)
    sub.required = True
    for name in dict.fromkeys((*COMMAND_MODULES, *extra_modules)):  # each module once
        importlib.import_module(name).register(sub)
    for command, examples in EXAMPLES.items():
        parser = sub.choices.get(command)
        if parser is not None and not parser.epilog:
            parser.epilog = "examples:\n" + "\n".join(f"  {line}" for line in examples)
            if parser.formatter_class is argparse.HelpFormatter:
                parser.formatter_class = argparse.RawDescriptionHelpFormatter
    return p


@functools.lru_cache(maxsize=1)
def _command_parser() -> argparse.ArgumentParser:
    """:func:`build_parser` of the built-in commands, built once per process (about 20 ms of CPU
    each time: every ``add_argument`` makes a help formatter and looks up its translations).
    Parsing never changes a parser (argparse writes only to the namespace it returns), so every
    :func:`main` call of a process may share it; ``extra_modules`` parsers are built afresh."""
    return build_parser()


def _suggest(parser: argparse.ArgumentParser, argv: Sequence[str], message: str) -> str:
    """The argparse message with "did you mean ...?" for a mistyped command or option."""
    import difflib
    import re

    from .common import _option_table

    _, _, subs = _option_table(parser)
    m = re.match(r"argument (\S+): invalid choice: '([^']*)'(?: \(choose from (.*)\))?", message)
    if m and m.group(1).startswith("-"):            # an option with choices (--grid quad|triangular)
        option, value = m.group(1).split("/")[-1], m.group(2)
        choices = [c.strip().strip("'") for c in (m.group(3) or "").split(",") if c.strip()]
        close = difflib.get_close_matches(value, choices, n=1)
        hint = f"; did you mean {option} {close[0]}?" if close else ""
        which = " or ".join(choices) if len(choices) <= 2 else "one of " + ", ".join(choices)
        return f"{option} takes {which}, not {value!r}{hint}"
    if m and m.group(1) != "command":               # a command's own sub-commands (subdiv nonuniform ...)
        command = next((a for a in argv if a in subs), "")
        choices = [c.strip().strip("'") for c in (m.group(3) or "").split(",") if c.strip()]
        close = difflib.get_close_matches(m.group(2), choices, n=1)
        hint = f"did you mean `subdiv {command} {close[0]}`? " if close else ""
        return (f"unknown {command} command {m.group(2)!r}: {hint}its commands are {', '.join(choices)} "
                f"(`subdiv {command} --help`)")
    if m and subs:
        close = difflib.get_close_matches(m.group(2), list(subs), n=1)
        if close:
            return (f"unknown command {m.group(2)!r}: did you mean `subdiv {close[0]}`? "
                    "(`subdiv --help` lists the commands)")
        return f"unknown command {m.group(2)!r}: `subdiv --help` lists the commands"
    if message.startswith("unrecognized arguments"):
        command = next((a for a in argv if a in subs), None)
        known = _option_table(subs[command])[1] if command else _option_table(parser)[1]
        hints = []
        for tok in argv:
            if tok.startswith("--") and tok.split("=", 1)[0] not in known:
                close = difflib.get_close_matches(tok.split("=", 1)[0], sorted(known), n=1, cutoff=0.6)
                if close:
                    hints.append(f"did you mean {close[0]} (not {tok.split('=', 1)[0]})?")
        if hints:
            return f"{message}; " + "; ".join(hints)
        return f"{message} (`subdiv {command or ''} --help` lists the options)".replace("  ", " ")
    return message


def _error_document(message: str, kind: str) -> str:
    import json

    return json.dumps({"error": {"message": message, "kind": kind}}, indent=2)


def main(argv: Sequence[str] | None = None, *, extra_modules: Sequence[str] = ()) -> int:
    """Run one ``subdiv`` command; the exit code: 0 done, 2 bad input (one line ``subdiv: error:``
    on stderr, and with ``--json`` also ``{"error": {"message", "kind"}}`` on stdout), 1 a bug
    (reported the same way), 130 interrupted."""
    from ..algebra.guard import sympy_parser_guarded

    parser = build_parser(extra_modules) if extra_modules else _command_parser()
    argv = list(sys.argv[1:] if argv is None else argv)
    want_json = "--json" in argv[:argv.index("--")] if "--" in argv else "--json" in argv

    def fail(message: str, kind: str, code: int) -> int:
        progress = sys.modules.get("analysis.progress")    # a progress line still shown is erased first
        if progress is not None:
            progress.clear()
        message = " ".join(str(message).split())           # one line, whatever the source said
        if len(message) > 600:                               # a message never repeats a huge input
            message = message[:400] + " ... " + message[-150:]
        print(f"subdiv: error: {message}" if code == 2 else f"subdiv: internal error: {message}", file=sys.stderr)
        if want_json:
            try:
                print(_error_document(message, kind), file=sys.stdout)
                sys.stdout.flush()
            except (BrokenPipeError, OSError):
                pass
        return code

    try:
        try:
            args = parser.parse_args(attach_dash_values(parser, argv))
        except AnalysisError as exc:
            return fail(_suggest(parser, argv, str(exc)), "usage", 2)
        with sympy_parser_guarded(), _StdoutGuard():
            args.func(args)
    except AnalysisError as exc:
        return fail(str(exc), getattr(exc, "kind", "input"), 2)
    except KeyboardInterrupt:
        print("subdiv: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `subdiv symbol ... | head`
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:  # pragma: no cover
            pass
        return 0
    except OSError as exc:
        if exc.errno != errno.ENAMETOOLONG:
            return _internal(fail, exc)
        name = exc.filename if isinstance(exc.filename, str) else ""
        shown = name if len(name) <= 60 else name[:40] + "..." + name[-15:]
        what = f"the file name {shown!r}" if shown else "a file name"
        return fail(f"{what} is too long for the file system (a name at most 255 bytes, a path at most 4096): "
                    "give a shorter path", "input", 2)
    except (RecursionError, MemoryError) as exc:
        return fail(f"the input is too large or nested too deeply ({type(exc).__name__}): give a smaller input",
                    "limit", 2)
    except Exception as exc:  # never a traceback for users; SUBDIV_DEBUG=1 shows it
        return _internal(fail, exc)
    return 0


def _internal(fail, exc: BaseException) -> int:
    """A bug: one line ``subdiv: internal error:`` (exit 1); ``SUBDIV_DEBUG=1`` shows the traceback."""
    if os.environ.get("SUBDIV_DEBUG"):
        raise exc
    first = str(exc).splitlines()[0] if str(exc) else ""
    return fail(f"{type(exc).__name__}: {first} (please report; SUBDIV_DEBUG=1 shows the traceback)",
                "internal", 1)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
