"""What every command of ``subdiv`` shares: reading a scheme and its parameters from the
command line, option values that begin with ``-`` (:func:`attach_dash_values`), printing through
the guarded standard output (:func:`_print`, :func:`_emit`: one JSON document with ``--json``,
nothing of a library), and checking output paths before any computation (:func:`check_writable`;
:func:`check_figure` for figures: an extension matplotlib writes, and a writable place).

A scheme is given in one of four ways — a catalogue name (``--scheme``), a mask (``--mask``,
``--start``), paper-style rules (``--rules``) or a symbol expression (``--symbol``) — with
parameter values ``--param NAME=VALUE`` (exact: ``1/100``, ``(sqrt(6)-1)/80``; decimals are read
exactly). Masks, rules and symbols may use the level ``n`` and ``--where NAME=EXPR`` helper
definitions: a level-dependent scheme (:mod:`analysis.cli.level_input`).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import TYPE_CHECKING, Sequence

from ..result import AnalysisError

if TYPE_CHECKING:  # pragma: no cover
    import sympy as sp

    from ..algebra.symbol import LaurentSymbol

# This module is imported to build the parser (``subdiv --help``): it imports no sympy, numpy or
# engine module at the top; the functions that need them import them (tests/test_startup.py).


def __getattr__(name: str):
    """``LaurentSymbol`` and ``parse_coefficient``, imported from the symbol algebra on first use."""
    if name in ("LaurentSymbol", "parse_coefficient"):
        from ..algebra import symbol

        return getattr(symbol, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit code 2)."""

    def error(self, message: str) -> None:  # noqa: D401
        raise AnalysisError(message)


# --------------------------------------------------------------------------------------------
# scheme input
# --------------------------------------------------------------------------------------------

def short(text, width: int = 60) -> str:
    """``repr`` of a user's text for a message, cut to ``width`` characters."""
    t = str(text)
    return repr(t if len(t) <= width else t[:width - 3] + "...")


def _split_list(text: str, what: str) -> list[str]:
    from ..algebra.reader import LIMITS, InputError

    t = text.strip()
    if t[:1] == "[" and t[-1:] == "]":
        raise AnalysisError(f"malformed {what} {short(text)}: drop the brackets, e.g. \"1/4,3/4,3/4,1/4\"")
    items = [t.strip() for t in text.replace(";", ",").split(",")]
    if not text.strip() or any(not t for t in items):
        raise AnalysisError(f"malformed {what} {short(text)}: give comma-separated numbers, e.g. \"1/4,3/4,3/4,1/4\"")
    if len(items) > LIMITS.coefficients:
        raise InputError(f"{what} has {len(items)} entries: the limit is {LIMITS.coefficients} (limit 'coefficients')",
                         "limit")
    return items


def _int_arg(text: str, what: str) -> int:
    try:
        return int(text)
    except (TypeError, ValueError):
        raise AnalysisError(f"{what} must be an integer, not {text!r}") from None


def _parse_params(items: Sequence[str] | None) -> dict[str, sp.Expr]:
    out: dict[str, sp.Expr] = {}
    for item in items or []:
        if "=" not in item:
            raise AnalysisError(f"malformed --param {item!r}: use NAME=VALUE, e.g. omega=1/100")
        name, value = (s.strip() for s in item.split("=", 1))
        if not name.isidentifier():
            raise AnalysisError(f"malformed parameter name {name!r}")
        if name in out:
            import sympy as sp

            raise AnalysisError(f"--param {name} is given twice ({sp.sstr(out[name])} and {value}): give it once")
        out[name] = read_number(value, f"--param {name}")
    return out


def read_number(text: str, what: str, *, real: bool = True, infinity: bool = False) -> sp.Expr:
    """An exact number typed on the command line (``1/100``, ``(sqrt(6)-1)/80``, ``0.25``): no free
    names; real unless ``real=False``; ``oo``/``-oo`` only when ``infinity``.

    >>> read_number("(sqrt(6)-1)/80", "--param w")
    -1/80 + sqrt(6)/80
    >>> read_number("I", "--param w")
    Traceback (most recent call last):
    ...
    analysis.algebra.limits.InputError: --param w must be a real number, not I
    """
    import sympy as sp

    from ..algebra.reader import InputError, read_expression

    v = read_expression(text, what=what, free=False, allow_infinity=infinity,
                        hint="a number is expected here (e.g. 1/16, sqrt(2)/4, 0.0625)")
    if real and not (v.is_real or (infinity and v.is_infinite and v.is_extended_real)):
        raise InputError(f"{what} must be a real number, not {sp.sstr(v)}", "value")
    return v


def _catalogue_arity(name: str, level: bool = False) -> int:
    """The arity of a catalogue entry; the level-dependent catalogue (``schemes.level_dependent``,
    issue 13) is binary, the level-dependent m-ary entries (``schemes.level_dependent.ARITY_ENTRIES``) carry their arity.
    An unknown name keeps the stationary catalogue's error, or the level-dependent catalogue's
    (``level=True``: a command that takes level-dependent schemes)."""
    import schemes
    from schemes.index import ALIASES, BY_SLUG, LEVEL, LEVEL_ARITY   # names and arities: nothing is built

    key = str(name).strip().lower()
    if key in BY_SLUG or key in ALIASES:
        return BY_SLUG[ALIASES.get(key, key)].arity
    try:
        return getattr(schemes.get(name), "arity", 2)
    except AnalysisError as stationary_error:
        from schemes import level_dependent

        if key in LEVEL_ARITY:
            return LEVEL_ARITY[key]
        if key in LEVEL:
            return 2
        try:
            level_dependent.get(name)
        except AnalysisError:
            if level:
                raise
            raise stationary_error from None
        return 2


def scheme_arity(args, level: bool = False) -> int:
    """The arity of the scheme input: ``--arity M`` (an integer >= 2), else the catalogue entry's
    arity, else 2. A ``--arity`` that contradicts the entry's is an error (issue 12)."""
    text = getattr(args, "arity", None)
    given = None
    if text is not None:
        from ..algebra.factorization import check_arity

        try:
            given = check_arity(int(str(text).strip()))
        except ValueError:
            raise AnalysisError(f"--arity must be an integer >= 2, not {text!r}") from None
    own = 2
    if getattr(args, "scheme", None) is not None:
        own = _catalogue_arity(args.scheme, level)
        if given is not None and given != own:
            raise AnalysisError(f"scheme {args.scheme!r} has arity {own}; drop --arity or give --arity {own}")
    return own if given is None else given


def require_values(symbol, label: str, command: str) -> None:
    """A one-line error when the scheme still has free names but the command needs numbers: a name
    in a typed mask is most often a typo (``-1/l6``), a catalogue parameter needs ``--param``."""
    if not getattr(symbol, "params", ()):
        return
    names = [p.name for p in symbol.params]
    one = names[0]
    if label in ("mask", "rules", "symbol"):
        raise AnalysisError(f"unknown name{'s' if len(names) > 1 else ''} {', '.join(map(repr, names))} in the "
                            f"{label}: `subdiv {command}` needs numbers; give --param {one}=VALUE, or correct the typo")
    raise AnalysisError(f"{label} has the parameter{'s' if len(names) > 1 else ''} {', '.join(names)}: `subdiv {command}` "
                        f"needs values, e.g. --param {one}=1/16 (C^k for a range of values: subdiv range --C K --param-name {one})"
                        if command in ("holder",) else
                        f"{label} has the parameter{'s' if len(names) > 1 else ''} {', '.join(names)}: "
                        f"`subdiv {command}` needs values, e.g. --param {one}=1/16")


def scheme_from_args(args, *, arity_ok: bool = False) -> tuple[LaurentSymbol, str]:
    """The symbol (with --param values substituted) and a label for it.

    Commands without m-ary support refuse an m-ary input (``--arity M`` or an m-ary catalogue entry)
    with a one-line error; the commands' arity branches pass ``arity_ok=True``.
    Input naming the level ``n`` is a one-line error here (a stationary scheme is needed);
    ``--where`` definitions without ``n`` are substituted (:mod:`analysis.cli.level_input`)."""
    if not arity_ok and (m := scheme_arity(args)) != 2:
        raise AnalysisError(f"this command analyses binary schemes only (arity {m} given); m-ary schemes: "
                            "subdiv symbol, factor, norm, refine, matrices, holder, range with --arity")
    from .level_input import stationary_or_error

    inline = stationary_or_error(args, getattr(args, "command", None) or "this command",
                                 _parse_params(getattr(args, "param", None)))
    if inline is not None:
        return inline, next(x for x in ("scheme", "mask", "rules", "symbol")
                            if getattr(args, "even" if x == "rules" else x, None) is not None)
    given = [x for x in ("scheme", "mask", "even", "symbol") if getattr(args, x, None) is not None]
    if len(given) != 1:
        raise AnalysisError("give exactly one of --scheme NAME, --mask LIST, --even/--odd RULES, --symbol EXPR")
    kind = given[0]
    from ..algebra.symbol import LaurentSymbol

    if kind == "scheme":
        import schemes

        entry = schemes.get(args.scheme)
        symbol, label = entry.symbol, entry.slug
    elif kind == "mask":
        symbol = LaurentSymbol.from_mask(_split_list(args.mask, "mask"), start=_int_arg(args.start, "--start"))
        label = "mask"
    elif kind == "even":
        if args.odd is None:
            raise AnalysisError("--even needs --odd as well")
        first = _int_arg(args.first, "--first")
        symbol = LaurentSymbol.from_rules(
            _split_list(args.even, "even stencil"), _split_list(args.odd, "odd stencil"), first=first,
            even_first=None if args.even_first is None else _int_arg(args.even_first, "--even-first"),
            odd_first=None if args.odd_first is None else _int_arg(args.odd_first, "--odd-first"))
        label = "rules"
    else:
        symbol = LaurentSymbol.from_expr(args.symbol)
        label = "symbol"
    if kind != "even" and args.odd is not None:
        raise AnalysisError("--odd is only used together with --even")
    params = _parse_params(args.param)
    if params:
        symbol = symbol.subs(params)
    return symbol, label


def read_points(args):
    """``--points "x,y;x,y;..."`` (exact numbers) or ``--points-file FILE`` (whitespace or .csv; floats)."""
    import numpy as np

    if (args.points is None) == (args.points_file is None):
        raise AnalysisError("give the data with exactly one of --points \"x,y;x,y;...\" or --points-file FILE")
    if args.points is not None:
        rows = [r for r in args.points.split(";") if r.strip()]
        if not rows:
            raise AnalysisError("--points is empty")
        if len(rows) > MAX_POINTS:
            raise AnalysisError(f"--points has {len(rows)} points: the limit is {MAX_POINTS} (use --points-file)")
        data = [[read_number(v, "--points") for v in r.split(",")] for r in rows]
        widths = {len(r) for r in data}
        if len(widths) != 1:
            raise AnalysisError("every point in --points needs the same number of coordinates")
        if any(v.free_symbols for r in data for v in r):
            raise AnalysisError("--points must be numbers")
        return data
    try:
        size = os.path.getsize(args.points_file)
        if size > MAX_POINTS_FILE_BYTES:
            raise AnalysisError(f"--points-file {args.points_file} has {size} bytes: the limit is {MAX_POINTS_FILE_BYTES}")
        arr = np.loadtxt(args.points_file, delimiter=None if not args.points_file.endswith(".csv") else ",", ndmin=2)
    except (OSError, ValueError) as exc:
        raise AnalysisError(f"cannot read {args.points_file}: {exc}") from None
    if not np.all(np.isfinite(arr)):
        raise AnalysisError(f"{args.points_file} contains NaN or infinite values")
    return arr


#: Most points ``--points`` may list, most bytes of a ``--points-file``, most points a refinement may produce.
MAX_POINTS = 100_000
MAX_POINTS_FILE_BYTES = 50_000_000
MAX_REFINED_POINTS = 10_000_000


def check_refined_size(n_points: int, arity: int, steps: int) -> None:
    """A one-line error when ``steps`` refinements of ``n_points`` points would exceed :data:`MAX_REFINED_POINTS`."""
    if n_points * arity ** steps > MAX_REFINED_POINTS:
        raise AnalysisError(f"{steps} steps of arity {arity} from {n_points} points give about {n_points * arity ** steps} "
                            f"points: the limit is {MAX_REFINED_POINTS}; give fewer --steps")


def _add_scheme_args(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("scheme (exactly one of)")
    g.add_argument("--scheme", metavar="NAME", help="catalogue name (see `subdiv list`)")
    g.add_argument("--mask", metavar="LIST", help='coefficients a_start..a_end, e.g. "1/4,3/4,3/4,1/4"')
    g.add_argument("--start", default="0", metavar="N", help="exponent of the first mask coefficient (default 0)")
    g.add_argument("--even", metavar="LIST", help="even stencil: coefficients of f[i+first], f[i+first+1], ...")
    g.add_argument("--odd", metavar="LIST", help="odd stencil (same offsets as --even unless --odd-first)")
    g.add_argument("--first", default="0", metavar="P", help="offset of the first stencil coefficient (default 0)")
    g.add_argument("--even-first", metavar="P", help="offset of the even stencil (default: --first)")
    g.add_argument("--odd-first", metavar="P", help="offset of the odd stencil (default: --first)")
    g.add_argument("--symbol", metavar="EXPR", help='a Laurent polynomial in z, e.g. "(1+z)**4/(8*z**2)"')
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter value (repeatable)")
    p.add_argument("--arity", metavar="M", help="m-ary scheme: (S_a f)_i = sum_j a_{i-Mj} f_j (default 2, "
                   "or the catalogue entry's arity)")
    p.add_argument("--where", action="append", metavar="NAME=EXPR",
                   help="helper definition for --mask/--rules/--symbol; may use the level n, parameters and "
                        "other names, e.g. c=cos(theta/2**(n+1)) (repeatable)")
    p.add_argument("--json", action="store_true", help="machine-readable output")


# --------------------------------------------------------------------------------------------
# commands
# --------------------------------------------------------------------------------------------

#: The real standard output while :func:`main` runs a command (fd 1 and ``sys.stdout`` then point
#: at stderr, so that nothing a library prints can reach stdout); ``None`` outside :func:`main`.
_COMMAND_STDOUT = None


def command_stdout():
    """The stream for a command's own output (its text or its one JSON document)."""
    return _COMMAND_STDOUT if _COMMAND_STDOUT is not None else sys.stdout


def _print(*objects, **kw) -> None:
    """``print`` to :func:`command_stdout` — what every command uses for its own output (the progress
    line on a terminal, if shown, is erased first)."""
    progress = sys.modules.get("analysis.progress")        # imported only by commands that show progress
    if progress is not None:
        progress.clear()
    print(*objects, file=command_stdout(), **kw)


def check_writable(path: str, option: str) -> None:
    """Fail at once (one-line error) when ``path`` cannot be written — before any computation. The
    folder must exist and accept a new file (a temporary file is created there and removed: this also
    catches read-only and pseudo file systems such as ``/proc``, where permission bits say nothing)."""
    import tempfile

    if not str(path).strip():
        raise AnalysisError(f"{option} needs a file name")
    p = os.path.abspath(os.path.expanduser(str(path)))
    parent = os.path.dirname(p) or "."
    if os.path.isdir(p):
        raise AnalysisError(f"cannot write {option} {path!r}: it is a directory (give a file name in it)")
    if not os.path.isdir(parent):
        raise AnalysisError(f"cannot write {option} {path!r}: directory {parent!r} does not exist "
                            "(create it first, or give a path in an existing folder)")
    if os.path.exists(p) and not os.path.isfile(p):
        raise AnalysisError(f"cannot write {option} {path!r}: it exists and is not a regular file")
    if not os.access(parent, os.W_OK | os.X_OK) or (os.path.exists(p) and not os.access(p, os.W_OK)):
        raise AnalysisError(f"cannot write {option} {path!r}: permission denied (give a path in a writable folder)")
    try:
        fd, probe = tempfile.mkstemp(prefix=".subdiv-probe-", dir=parent)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise AnalysisError(f"cannot write {option} {path!r}: directory {parent!r} does not accept new files "
                            f"({exc.strerror or exc}; give a path in a writable folder)") from None


#: figure formats accepted by the ``--figure``/``--plot`` options: the ones matplotlib writes without
#: extra programs (``pgf`` needs LaTeX; ``raw``/``rgba`` are headerless pixel dumps, ``avif`` a Pillow plugin)
FIGURE_FORMATS = ("png", "svg", "pdf", "eps", "ps", "svgz", "jpg", "jpeg", "tif", "tiff", "webp", "gif")


def figure_formats() -> tuple[str, ...]:
    """The formats of :data:`FIGURE_FORMATS` that this matplotlib can write."""
    from matplotlib.backend_bases import FigureCanvasBase

    supported = FigureCanvasBase.get_supported_filetypes()
    return tuple(f for f in FIGURE_FORMATS if f in supported)


def check_figure(path: str, option: str) -> None:
    """Fail at once (one-line error) when the figure ``path`` has no extension matplotlib can write
    (``.png``, ``.svg``, ``.pdf``, ...) or cannot be written (:func:`check_writable`) — before any computation."""
    if os.path.isdir(os.path.expanduser(str(path))):
        raise AnalysisError(f"cannot write {option} {path!r}: it is a directory (give a file name in it, e.g. "
                            f"{os.path.join(str(path), 'figure.png')})")
    ext = os.path.splitext(str(path))[1].lower().lstrip(".")
    formats = figure_formats()
    if ext not in formats:
        what = f"'.{ext}' is not an image format matplotlib writes" if ext else "the file name has no extension"
        raise AnalysisError(f"cannot write {option} {path!r}: {what}; end the name in .png, .svg or .pdf "
                            f"(also: {', '.join('.' + f for f in formats if f not in ('png', 'svg', 'pdf'))})")
    check_writable(path, option)


def json_document(data) -> str:
    """The JSON text of a command's document: wall-clock times only under its top-level ``"timing"``
    key (:func:`analysis.jsonable.hoist_timing`), so that two runs differ only there."""
    from ..jsonable import hoist_timing, jsonable

    return json.dumps(hoist_timing(jsonable(data)), indent=2)


def _emit(args, data: dict, text: str) -> None:
    if args.json:
        _print(json_document(data))
    else:
        _print(text)


#: the largest work budget an option takes
MAX_WORK = 10 ** 9
#: what a work unit is, for --help texts
WORK_HELP = "counted, not timed: about a millisecond each on the reference machine"


def work_arg(text, option: str, *, minimum: int = 1) -> int:
    """A work-budget option (``--budget``, ``--strip-budget``): a number of work units such as ``20000``
    or ``2e4``. Work is counted, never timed, so the same input gives the same verdict on every machine."""
    try:
        v = float(str(text).strip().replace("_", ""))
    except ValueError:
        raise AnalysisError(f"{option} must be a number of work units, not {text!r}") from None
    if not minimum <= v <= MAX_WORK:
        raise AnalysisError(f"{option} must be between {minimum} and {MAX_WORK} work units")
    return int(v)


def _parse_Ls(text: str) -> list[int]:
    Ls = [_int_arg(t, "--L") for t in _split_list(text, "--L")]
    if any(L < 1 or L > 24 for L in Ls):
        raise AnalysisError("--L values must be between 1 and 24")
    return Ls


def _parse_within(text: str | None):
    import sympy as sp

    if text is None:
        return (-sp.oo, sp.oo)
    parts = [t.strip() for t in text.split(",")]
    if len(parts) != 2:
        raise AnalysisError(f"malformed --within {text!r}: use LOW,HIGH, e.g. 0,oo")
    vals = [read_number(t, "--within", infinity=True) for t in parts]
    if vals[0] >= vals[1]:
        raise AnalysisError("--within needs LOW < HIGH")
    return tuple(vals)


def _version() -> str:
    """The installed version of ``subdiv-workbench``, else the one in ``pyproject.toml``."""
    try:
        from importlib.metadata import PackageNotFoundError, version

        return version("subdiv-workbench")
    except PackageNotFoundError:
        import re
        from pathlib import Path

        try:
            text = (Path(__file__).resolve().parents[2] / "pyproject.toml").read_text(encoding="utf-8")
        except OSError:
            return "unknown"
        m = re.search(r'(?m)^version\s*=\s*"([^"]+)"', text)
        return m.group(1) if m else "unknown"


def _option_table(parser: argparse.ArgumentParser):
    """(options taking exactly one value, every option string, sub-command parsers) of one parser."""
    one, known, subs = set(), set(), {}
    for action in parser._actions:
        known.update(action.option_strings)
        if action.option_strings and action.nargs in (None, 1):   # store and append (one value each time)
            one.update(action.option_strings)
        if isinstance(action, argparse._SubParsersAction):
            subs.update(action.choices)
    return one, known, subs


def _option_name(token: str, known: set[str]) -> str | None:
    """The option string ``token`` stands for (exact, or an unambiguous ``--`` prefix as argparse
    accepts), ignoring an attached ``=value``; ``None`` when it is not an option of this parser."""
    head = token.split("=", 1)[0]
    if head in known:
        return head
    if head.startswith("--") and len(head) > 2:
        cands = [k for k in known if k.startswith(head)]
        if len(cands) == 1:
            return cands[0]
    return None


def attach_dash_values(parser: argparse.ArgumentParser, argv: Sequence[str]) -> list[str]:
    """Rewrite ``--opt VALUE`` as ``--opt=VALUE`` when ``--opt`` takes one value and ``VALUE``
    begins with ``-`` but is no option string (argparse would reject ``--mask -1/16,0,9/16,...``).
    Sub-command names switch to the sub-command's own options (recursively, e.g. ``nonuniform
    decay``); everything after ``--`` is left alone.

    >>> from analysis.cli.main import build_parser
    >>> p = build_parser()
    >>> attach_dash_values(p, ["holder", "--mask", "-1/16,0,9/16,1,9/16,0,-1/16", "--start", "-3", "--json"])
    ['holder', '--mask=-1/16,0,9/16,1,9/16,0,-1/16', '--start=-3', '--json']
    >>> attach_dash_values(p, ["symbol", "--mask", "--json"])        # a missing value stays an error
    ['symbol', '--mask', '--json']
    """
    out: list[str] = []
    one, known, subs = _option_table(parser)
    i = 0
    while i < len(argv):
        tok = argv[i]
        if tok == "--":
            out.extend(argv[i:])
            break
        if not tok.startswith("-"):
            if tok in subs:
                one, known, subs = _option_table(subs[tok])
            out.append(tok)
            i += 1
            continue
        name = None if "=" in tok else _option_name(tok, known)
        if name in one and i + 1 < len(argv):
            value = argv[i + 1]
            if value.startswith("-") and value != "--" and _option_name(value, known) is None:
                out.append(f"{name}={value}")
            else:
                out.extend((tok, value))
            i += 2
            continue
        out.append(tok)
        i += 1
    return out


def _flush_c_stdio() -> None:
    """Flush the C library's stdio buffers (output of compiled libraries not yet written)."""
    try:
        import ctypes

        ctypes.CDLL(None).fflush(None)
    except (OSError, AttributeError, TypeError):  # pragma: no cover - no C runtime reachable
        pass


class _StdoutGuard:
    """While a command runs, file descriptor 1 and ``sys.stdout`` point at stderr, so nothing a
    library prints (Python ``print`` or C-level writes such as HiGHS's banner) can reach stdout; the
    command writes its own output through :func:`command_stdout` to the real standard output.

    When ``sys.stdout`` is not file descriptor 1 (pytest's ``capsys``, ``contextlib.redirect_stdout``)
    the command's output goes to that object and fd 1 is diverted all the same."""

    def __enter__(self):
        global _COMMAND_STDOUT
        self.sys_stdout, self.saved_fd, self.own = sys.stdout, None, None
        try:
            sys.stdout.flush()
        except (OSError, ValueError, AttributeError):
            pass
        _flush_c_stdio()
        try:
            saved = os.dup(1)
        except OSError:      # no fd 1 (embedded use): only sys.stdout is diverted
            saved = None
        if saved is not None:
            try:
                os.dup2(2, 1)
                self.saved_fd = saved
            except OSError:
                os.close(saved)
        try:
            fd = self.sys_stdout.fileno()
        except (AttributeError, OSError, ValueError):
            fd = None
        if fd == 1 and self.saved_fd is not None:
            import io

            s = self.sys_stdout
            try:
                self.own = io.TextIOWrapper(open(self.saved_fd, "wb", closefd=False),
                                            encoding=getattr(s, "encoding", None) or "utf-8",
                                            errors=getattr(s, "errors", None) or "strict",
                                            line_buffering=bool(getattr(s, "line_buffering", False)))
            except Exception:
                os.dup2(self.saved_fd, 1)    # leave everything as it was
                os.close(self.saved_fd)
                raise
        _COMMAND_STDOUT = self.own if self.own is not None else self.sys_stdout
        sys.stdout = sys.stderr
        return self

    def __exit__(self, exc_type, exc, tb) -> bool:
        global _COMMAND_STDOUT
        _COMMAND_STDOUT = None
        try:
            sys.stdout.flush()
        except (OSError, ValueError, AttributeError):
            pass
        _flush_c_stdio()                     # what C code buffered while fd 1 was stderr goes there
        sys.stdout = self.sys_stdout
        broken = False
        try:
            if self.own is not None:
                self.own.flush()
        except BrokenPipeError:              # `subdiv ... | head`: the reader has gone
            broken = True
            if self.saved_fd is not None:
                devnull = os.open(os.devnull, os.O_WRONLY)
                os.dup2(devnull, self.saved_fd)
                os.close(devnull)
        finally:
            if self.own is not None:
                try:
                    self.own.close()
                except OSError:
                    pass
            if self.saved_fd is not None:
                os.dup2(self.saved_fd, 1)
                os.close(self.saved_fd)
        if broken and exc_type is None:
            raise BrokenPipeError
        return False



def norm_order(args) -> int:
    """The difference order of ``subdiv norm`` (``--m``): given, or 0 (the scheme itself) for plain
    norms and 1 (the convergence test, C^0) with ``--solve``. ``--solve`` asks where a smoothness
    test holds; with m = 0 it would solve ``||(1/M S_a)^L|| < 1``, which tests no smoothness."""
    if args.m is None:
        return 1 if args.solve is not None else 0
    try:
        m = int(str(args.m).strip())
    except ValueError:
        raise AnalysisError(f"--m must be an integer, not {short(args.m)}") from None
    if not 0 <= m <= 64:
        raise AnalysisError("--m must be between 0 and 64")
    if m == 0 and args.solve is not None:
        raise AnalysisError("--solve with --m 0 tests no smoothness: give --m 1 for convergence (C^0), "
                            "--m K+1 for C^K (without --m, --solve uses --m 1)")
    return m
