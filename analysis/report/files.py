"""Report output: atomic files kept inside the output folder, and the removal of orphaned figures.

* **Atomic**: a report, a figure or a golden file is either the old one or the whole new one, never
  a truncated mix (an interrupted run, or two runs at once): :func:`atomic_write_text`,
  :func:`atomic_write_bytes` write a temporary file beside the target and rename it over the target
  (the rename replaces a symbolic link at the target's name; it never writes through it).
* **Inside the output folder**: :func:`output_folder` creates ``--output DIR`` (parents too) and checks
  that it accepts files; :func:`inside` turns a name relative to it into a path, refusing any path that
  leaves the folder once symbolic links are resolved (``../x``, an absolute name, ``figures`` linked to
  ``/etc``). Every file a report writes goes through :func:`inside`.
* **Orphans**: :func:`record_written` lists every figure a run writes, with the SHA-256 of its bytes, in
  the manifest ``figures/.subdiv-written.json``; :func:`remove_orphans` deletes, after a run, only the
  figures of that manifest that no report (``*.md``, ``*.html`` at the top of the folder) refers to and
  whose bytes are still the ones the tool wrote — a file the tool cannot prove it wrote (a user's own
  picture in ``figures/``, whatever its name) is never removed. See its docstring for the details.

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

import hashlib
import json
import os
import re
import tempfile
from pathlib import Path
from typing import Mapping

from ..result import AnalysisError

__all__ = ["atomic_write_text", "atomic_write_bytes", "output_folder", "inside", "remove_orphans",
           "record_written", "GENERATED_FIGURES", "MANIFEST"]

#: the figure files a report run generates (and may remove when no report refers to them)
GENERATED_FIGURES = (".png", ".svg")
#: the sub-folders of the output folder that hold generated figures
FIGURE_FOLDERS = ("figures", "figures/formulas")
#: the manifest of the figures the tool wrote (relative name -> SHA-256 of the bytes written)
MANIFEST = ("figures", ".subdiv-written.json")
#: the largest manifest read (a larger one is ignored: nothing is removed)
MAX_MANIFEST = 4_000_000


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


def _sha256(path: Path) -> str | None:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return None


def _read_manifest(base: Path) -> dict[str, str]:
    """The manifest of ``base`` (an empty one when missing, unreadable, too large or malformed); only
    entries naming a figure directly in a figure folder (:data:`FIGURE_FOLDERS`) are kept."""
    try:
        path = inside(base, *MANIFEST)
        if path.is_symlink() or not path.is_file() or path.stat().st_size > MAX_MANIFEST:
            return {}
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError, RecursionError, AnalysisError):
        return {}
    written = data.get("written") if isinstance(data, dict) else None
    if not isinstance(written, dict):
        return {}
    return {k: v for k, v in written.items() if isinstance(k, str) and isinstance(v, str)
            and _REFERENCE.fullmatch(k)}


def _write_manifest(base: Path, written: Mapping[str, str]) -> None:
    text = json.dumps({"about": "figures written by subdiv report (name: SHA-256); only these may be removed",
                       "written": dict(sorted(written.items()))}, indent=1) + "\n"
    atomic_write_text(inside(base, *MANIFEST), text)


def record_written(root: str | os.PathLike, paths) -> None:
    """Add the figure files ``paths`` (inside ``root``'s figure folders, just written by this run) to the
    manifest of ``root``, each with the SHA-256 of its bytes; the manifest is rewritten atomically."""
    paths = list(paths)
    if not paths:
        return
    base = Path(root).resolve()
    written = _read_manifest(base)
    for p in paths:
        rel = Path(p).resolve().relative_to(base).as_posix()
        digest = _sha256(Path(p))
        if digest is not None:
            written[rel] = digest
    _write_manifest(base, written)


def remove_orphans(root: str | os.PathLike, *, older_than: float | None = None) -> list[Path]:
    """Remove the figures the tool wrote in the output folder ``root`` that no report refers to any
    more; the removed paths.

    What is removed: a regular file (never a symbolic link or a folder) ending in ``.png`` or ``.svg``
    directly in ``root/figures/`` or ``root/figures/formulas/`` that the manifest
    (:func:`record_written`) lists, whose bytes still have the SHA-256 the manifest records (so the tool
    wrote exactly this file), that no ``*.md`` or ``*.html`` report at the top of ``root`` refers to
    (``figures/NAME`` in its text), and that was last modified before ``older_than`` (a time stamp: the
    start of this run, so that the figures a concurrent run has just written, before its report, are
    kept). What is never removed: a file the manifest does not list or whose bytes changed (a user's
    own file, whatever its name), reports, ``verdicts.json`` and any other file, anything outside those
    two folders, and anything at all when ``root/figures`` leads outside ``root``. The manifest then
    forgets the removed files and the files that are gone or were changed.

    >>> import tempfile, os
    >>> d = Path(tempfile.mkdtemp()); (d / "figures").mkdir()
    >>> ours, mine = d / "figures" / "x.png", d / "figures" / "holiday.png"
    >>> atomic_write_bytes(ours, b"png"); atomic_write_bytes(mine, b"mine"); record_written(d, [ours])
    >>> [p.name for p in remove_orphans(d)], mine.exists()
    (['x.png'], True)
    """
    base = Path(root).resolve()
    figs = base / "figures"
    if not figs.is_dir() or figs.is_symlink() or figs.resolve().parent != base:
        return []
    written = _read_manifest(base)
    if not written:
        return []
    keep = referenced_figures(base)
    removed = []
    for rel, digest in sorted(written.items()):
        f = base / rel
        if f.parent.is_symlink() or f.is_symlink() or not f.is_file() or _sha256(f) != digest:
            del written[rel]                                    # gone, or not (any more) the tool's file
            continue
        if f.suffix not in GENERATED_FIGURES or rel in keep:
            continue
        if older_than is not None and f.stat().st_mtime >= older_than:
            continue
        try:
            f.unlink()
        except OSError:
            continue
        del written[rel]
        removed.append(f)
    try:
        _write_manifest(base, written)
    except (OSError, AnalysisError):
        pass
    return removed
