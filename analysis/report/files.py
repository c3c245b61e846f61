"""Report output: atomic files kept inside the output folder, and the removal of orphaned figures.

* **Atomic**: a report, a figure or a golden file is either the old one or the whole new one, never
  a truncated mix (an interrupted run, or two runs at once): :func:`atomic_write_text`,
  :func:`atomic_write_bytes` write a temporary file beside the target and rename it over the target
  (the rename replaces a symbolic link at the target's name; it never writes through it).
* **Inside the output folder**: :func:`output_folder` creates ``--output DIR`` (parents too) and checks
  that it accepts files; :func:`inside` turns a name relative to it into a path, refusing any path that
  leaves the folder once symbolic links are resolved (``../x``, an absolute name, ``figures`` linked to
  ``/etc``). Every file a report writes goes through :func:`inside`.
* **Orphans**: :func:`remove_orphans` deletes, after a run, the figures (``.png``, ``.svg``) in the
  folder's ``figures/`` and ``figures/formulas/`` that no report (``*.md``, ``*.html`` at the top of the
  folder) refers to — see its docstring for exactly what it removes and what it never touches.

>>> import tempfile, pathlib
>>> d = pathlib.Path(tempfile.mkdtemp())
>>> atomic_write_text(d / "a.md", "hello\\n"); (d / "a.md").read_text()
'hello\\n'
>>> inside(d, "figures", "x.png") == d.resolve() / "figures" / "x.png"
True
>>> inside(d, "..", "x.png")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
analysis.result.AnalysisError: refusing to write .../x.png: it is outside the output folder ... (a file name may not contain '/' or '..'; ...
"""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

from ..result import AnalysisError

__all__ = ["atomic_write_text", "atomic_write_bytes", "output_folder", "inside", "remove_orphans",
           "GENERATED_FIGURES"]

#: the figure files a report run generates (and may remove when no report refers to them)
GENERATED_FIGURES = (".png", ".svg")
#: the sub-folders of the output folder that hold generated figures
FIGURE_FOLDERS = ("figures", "figures/formulas")


def atomic_write_text(path: str | os.PathLike, text: str, encoding: str = "utf-8") -> None:
    """Write ``text`` to a temporary file beside ``path``, then rename it over ``path``."""
    atomic_write_bytes(path, text.encode(encoding))


def atomic_write_bytes(path: str | os.PathLike, data: bytes) -> None:
    """Write ``data`` to a temporary file beside ``path`` (same file system), then rename."""
    p = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{p.name}.", suffix=".tmp", dir=p.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, 0o644)
        os.replace(tmp, p)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def output_folder(path: str | os.PathLike, option: str = "--output") -> Path:
    """The output folder ``path``, created with its parents when missing, checked to accept new files
    (a temporary file is created and removed); returns its resolved path. One-line errors."""
    p = Path(os.path.expanduser(str(path)))
    if str(path) == "":
        raise AnalysisError(f"{option} needs a folder, e.g. {option} reports")
    if p.exists() and not p.is_dir():
        raise AnalysisError(f"{option} {str(path)!r} is a file, not a folder: give a folder, e.g. {option} reports")
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise AnalysisError(f"cannot create the output folder {str(path)!r}: {exc.strerror or exc} "
                            f"(give a folder in a writable place, e.g. {option} reports)") from None
    try:
        fd, probe = tempfile.mkstemp(prefix=".subdiv-probe-", dir=p)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise AnalysisError(f"cannot write to the output folder {str(path)!r}: {exc.strerror or exc} "
                            f"(give a writable folder, e.g. {option} reports)") from None
    return p.resolve()


def inside(root: str | os.PathLike, *parts: str) -> Path:
    """``root / parts...`` as a path that stays inside ``root`` once symbolic links are resolved
    (in ``root`` itself, in any folder between, and in the final name); an :class:`AnalysisError`
    otherwise; returns the resolved path. Nothing is created."""
    base = Path(root).resolve()
    target = base.joinpath(*parts)
    resolved = target.resolve()          # follows the links that exist; the rest is taken as written
    if resolved != base and base not in resolved.parents:
        lexical = Path(os.path.normpath(target))
        why = ("a symbolic link in the folder leads to " + str(resolved) if lexical == base or base in lexical.parents
               else "a file name may not contain '/' or '..'")
        raise AnalysisError(f"refusing to write {target}: it is outside the output folder {base} ({why}; "
                            "remove the link or choose another --output folder)")
    return resolved


_REFERENCE = re.compile(r"figures/((?:formulas/)?[A-Za-z0-9][A-Za-z0-9._-]*\.(?:png|svg))")


def referenced_figures(root: str | os.PathLike) -> set[str]:
    """The figure files (relative to ``root``, e.g. ``figures/formulas/f-0123.svg``) that the reports
    at the top of ``root`` (``*.md``, ``*.html``; regular files only) refer to."""
    base = Path(root)
    found: set[str] = set()
    for f in sorted(base.iterdir()):
        if f.suffix in (".md", ".html") and f.is_file() and not f.is_symlink():
            try:
                text = f.read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError):
                continue
            found.update("figures/" + m for m in _REFERENCE.findall(text))
    return found


def remove_orphans(root: str | os.PathLike, *, older_than: float | None = None) -> list[Path]:
    """Remove the generated figures of the output folder ``root`` that no report refers to; the
    removed paths.

    What is removed: regular files (never symbolic links or folders) ending in ``.png`` or ``.svg``
    directly in ``root/figures/`` or ``root/figures/formulas/`` that no ``*.md`` or ``*.html`` report at
    the top of ``root`` refers to (``figures/NAME`` in its text) and that were last modified before
    ``older_than`` (a time stamp: the start of this run, so that the figures a concurrent run has just
    written, before its report, are kept). What is never removed: reports (``*.md``, ``*.html``),
    ``verdicts.json`` and any other file, anything outside those two folders, and anything at all when
    ``root/figures`` leads outside ``root``.
    """
    base = Path(root).resolve()
    figs = base / "figures"
    if not figs.is_dir() or figs.is_symlink() or figs.resolve().parent != base:
        return []
    keep = referenced_figures(base)
    removed = []
    for sub in FIGURE_FOLDERS:
        folder = base / sub
        if not folder.is_dir() or folder.is_symlink():
            continue
        for f in sorted(folder.iterdir()):
            rel = f.relative_to(base).as_posix()
            if f.suffix not in GENERATED_FIGURES or rel in keep or f.is_symlink() or not f.is_file():
                continue
            if older_than is not None and f.stat().st_mtime >= older_than:
                continue
            try:
                f.unlink()
            except OSError:
                continue
            removed.append(f)
    return removed
