"""Progress of long computations, shown on a terminal and nowhere else.

The engine announces its stages (:func:`stage`) and steps (:func:`step`); by default nothing
listens, so library use, tests, pipes and ``--json`` output are unaffected, and results never
depend on it. The command line installs a listener (:func:`on_terminal`) that writes one line,
rewritten in place, to standard error when standard error is a terminal.

Examples
--------
>>> from analysis import progress
>>> seen = []
>>> with progress.listening(lambda text: seen.append(text)):
...     progress.stage("grid points", 3)
...     for i in range(3):
...         progress.step()
>>> seen[-1]
'grid points 3/3'
>>> progress.step()          # nobody listens: nothing happens
"""

from __future__ import annotations

import sys
from contextlib import contextmanager
from typing import Callable

_listener: Callable[[str], None] | None = None
_stage: list = ["", 0, 0]           # name, done, total


def stage(name: str, total: int = 0) -> None:
    """A new stage of ``total`` steps (0: unknown)."""
    _stage[:] = [name, 0, total]
    if _listener is not None:
        _listener(_text())


def step(n: int = 1) -> None:
    """``n`` more steps of the current stage are done."""
    if _listener is None:
        return
    _stage[1] += n
    _listener(_text())


def _text() -> str:
    name, done, total = _stage
    return f"{name} {done}/{total}" if total else f"{name} {done}" if done else name


@contextmanager
def listening(listener: Callable[[str], None]):
    """Send every stage and step to ``listener(text)`` inside the block."""
    global _listener
    old, _listener = _listener, listener
    try:
        yield
    finally:
        _listener = old


@contextmanager
def on_terminal(command: str, enabled: bool = True):
    """While the block runs, show ``subdiv COMMAND: stage i/n`` on standard error if it is a
    terminal (and ``enabled``); the line is erased at the end."""
    tty = enabled and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
    if not tty:
        yield
        return
    width = [0]

    def show(text: str) -> None:
        line = f"subdiv {command}: {text}"[:100]
        sys.stderr.write("\r" + line.ljust(width[0]))
        sys.stderr.flush()
        width[0] = len(line)

    try:
        with listening(show):
            yield
    finally:
        sys.stderr.write("\r" + " " * width[0] + "\r")
        sys.stderr.flush()
