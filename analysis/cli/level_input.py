"""Level-dependent schemes typed on the command line: the level ``n`` and ``--where NAME=EXPR``.

``--mask``, ``--even/--odd`` and ``--symbol`` may use the level ``n`` (``a^n`` maps level-n data to
level n+1; ``n`` must enter through ``2^n``, e.g. ``cos(theta/2**(n+1))``) and names defined by
repeatable ``--where NAME=EXPR`` (which may use ``n``, parameters and other names). ``--scheme``
also takes the level-dependent catalogue names (:mod:`schemes.level_dependent`).

:func:`level_scheme_from_args` returns the :class:`~analysis.levels.level_dependent.LevelDependentScheme`
(parameters substituted) or ``None`` when the input is a plain stationary scheme; commands that need
a stationary scheme call :func:`stationary_or_error`.

Examples
--------
>>> import argparse, sympy as sp
>>> ns = argparse.Namespace(scheme=None, mask=None, even=None, odd=None, start="0", first="0",
...     even_first=None, odd_first=None, symbol="(1+z)*(1+2*c*z+z**2)/(2*(1+c))/z**2",
...     where=["c=cos(theta/2**(n+1))"])
>>> s = level_scheme_from_args(ns, {"theta": sp.pi / 2})
>>> s.mask[0]
1/(2*cos(pi*h/4) + 2)
"""

from __future__ import annotations

import re

from ..result import AnalysisError

_LEVEL = re.compile(r"(?<![A-Za-z0-9_])n(?![A-Za-z0-9_])")


def _texts(args) -> list[str]:
    return [t for t in (getattr(args, x, None) for x in ("mask", "even", "odd", "symbol")) if t]


def uses_level(args) -> bool:
    """Does the input name the level ``n``, ``--where`` definitions or a level-dependent catalogue entry?"""
    if getattr(args, "where", None):
        return True
    if any(_LEVEL.search(t) for t in _texts(args)):
        return True
    name = getattr(args, "scheme", None)
    if name:
        from schemes.index import LEVEL, LEVEL_ARITY     # the names only: no entry is built

        return str(name).strip().lower() in LEVEL or str(name).strip().lower() in LEVEL_ARITY
    return False


def _items(text: str, what: str) -> list[str]:
    items = [t.strip() for t in text.replace(";", ",").split(",")]
    if not text.strip() or any(not t for t in items):
        raise AnalysisError(f"malformed {what} {text!r}: give comma-separated formulas")
    return items


def _int(text, what: str) -> int:
    try:
        return int(text)
    except (TypeError, ValueError):
        raise AnalysisError(f"{what} must be an integer, not {text!r}") from None


def level_scheme_from_args(args, params=None, *, keep_params: bool = False):
    """The level-dependent scheme given by the arguments, or ``None``; ``params``: the parsed
    ``--param`` values (name -> exact number), substituted; other free names are an error unless
    ``keep_params`` (commands that take parameter boxes)."""
    if not uses_level(args):
        return None
    from ..levels.level_dependent import LevelDependentScheme as L

    where = getattr(args, "where", None) or []
    given = [x for x in ("scheme", "mask", "even", "symbol") if getattr(args, x, None) is not None]
    if getattr(args, "odd", None) is not None and "even" not in given:
        raise AnalysisError("--odd is only used together with --even")
    if len(given) != 1:
        raise AnalysisError("give exactly one of --scheme NAME, --mask LIST, --even/--odd RULES, --symbol EXPR")
    kind = given[0]
    if kind == "scheme":
        if where:
            raise AnalysisError("--where goes with --mask, --even/--odd or --symbol, not with --scheme")
        from schemes.level_dependent import get

        s = get(args.scheme)
    elif kind == "symbol":
        s = L.from_symbol(args.symbol, where=where, slug="symbol")
    elif kind == "mask":
        s = L.from_mask(_items(args.mask, "mask"), _int(getattr(args, "start", "0"), "--start"), where=where,
                        slug="mask")
    else:
        if args.odd is None:
            raise AnalysisError("--even needs --odd as well")
        if args.even_first is not None or args.odd_first is not None:
            raise AnalysisError("--even-first/--odd-first are not available for level-dependent rules: use --first")
        from ..algebra.reader import substitute
        from ..levels.level_dependent import _read, resolve_where

        defs = resolve_where(where)
        ev = [substitute(_read(c, defs, "even stencil coefficient"), defs, what="an even stencil coefficient") for c in _items(args.even, "even stencil")]
        od = [substitute(_read(c, defs, "odd stencil coefficient"), defs, what="an odd stencil coefficient") for c in _items(args.odd, "odd stencil")]
        free = sorted(set().union(*(c.free_symbols for c in ev + od)), key=lambda x: x.name)
        s = L.from_rules(ev, od, first=_int(args.first, "--first"),
                         params=[p for p in free if p.name not in ("n", "h")], slug="rules")
    if params:
        s = s.subs(params)
    if s.params and not keep_params:
        names = ", ".join(s.param_names)
        raise AnalysisError(f"undefined name(s) {names}: define them with --where NAME=EXPR "
                            f"or give --param NAME=VALUE")
    return s


def is_stationary(s) -> bool:
    from ..levels.level_dependent import H

    return all(H not in c.free_symbols for c in s.mask)


def stationary_or_error(args, command: str, params=None):
    """The stationary symbol of inline input that uses ``--where`` but not the level, or ``None``.

    Raises the one-line error of a level variable given to a command that needs a stationary scheme.
    """
    s = level_scheme_from_args(args, params)
    if s is None:
        return None
    if not is_stationary(s):
        raise AnalysisError(f"the scheme depends on the level n: `subdiv {command}` needs a stationary scheme "
                            "(level-dependent schemes: `subdiv holder`, `subdiv series`)")
    return s.limit()
