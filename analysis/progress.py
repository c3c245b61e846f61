"""Progress of long computations, shown on a terminal and nowhere else.

The engine announces its stages (:func:`stage`) and steps (:func:`step`); by default nothing
listens, so library use, tests, pipes and ``--json`` output are unaffected, and results never
depend on it. The command line installs a listener (:func:`on_terminal`) that writes one line,
rewritten in place, to standard error when standard error is a terminal (at most ten times a
second: the clock decides only how often the line is redrawn, never what is computed).

A long task made of parts (the claims of a paper, the valences of a vertex) names the part running
now with :func:`part`; the stages of the engine inside it are shown after that name. A command that
prints a line of its own while the progress line is shown calls :func:`clear` first (``_print`` of
the command line does).

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
>>> with progress.listening(seen.append), progress.part("claim 2/5 004:Lemma2"):
...     progress.stage("boundaries", 2)
>>> seen[-1]
'claim 2/5 004:Lemma2 · boundaries 0/2'
>>> progress.step()          # nobody listens: nothing happens
"""

from __future__ import annotations

import sys
from contextlib import contextmanager
from typing import Callable

_listener: Callable[[str], None] | None = None
_stage: list = ["", 0, 0]           # name, done, total
_part: list = [""]                  # the part of a long task running now (shown before the stage)
_erase: Callable[[], None] | None = None


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
    text = f"{name} {done}/{total}" if total else f"{name} {done}" if done else name
    return " · ".join(t for t in (_part[0], text) if t)


@contextmanager
def part(name: str):
    """Inside the block, show ``name`` (e.g. ``claim 3/42 003:Lemma3.1``) before the engine's stages."""
    old = _part[0]
    _part[0], _stage[:] = name, ["", 0, 0]
    if _listener is not None:
        _listener(_text())
    try:
        yield
    finally:
        _part[0], _stage[:] = old, ["", 0, 0]


def clear() -> None:
    """Erase the progress line from the terminal (before a line of the command's own output); the
    next stage or step draws it again. Nothing happens when no line is shown."""
    if _erase is not None:
        _erase()


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
    terminal (and ``enabled``: commands pass ``not args.json``); the line is erased at the end.
    The line is redrawn at most every 0.1 s (and whenever the stage changes)."""
    global _erase
    stream = sys.stderr
    tty = enabled and hasattr(stream, "isatty") and stream.isatty()
    if not tty:
        yield
        return
    import time

    width, last = [0], [-1.0, ""]

    def show(text: str) -> None:
        now, (head, _, count) = time.monotonic(), text.rpartition(" ")
        done, _, total = count.partition("/")
        if now - last[0] < 0.1 and head == last[1] and not (total and done == total):   # a last step is shown
            return
        last[:] = [now, head]
        line = f"subdiv {command}: {text}"[:100]
        stream.write("\r" + line.ljust(width[0]))
        stream.flush()
        width[0] = len(line)

    def erase() -> None:
        if width[0]:
            stream.write("\r" + " " * width[0] + "\r")
            stream.flush()
            width[0], last[1] = 0, ""

    old_erase, _erase = _erase, erase
    try:
        with listening(show):
            yield
    finally:
        erase()
        _erase = old_erase
