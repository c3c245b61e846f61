"""``subdiv new-paper FILE.toml``: write the commented paper-file template (issue 11).

The template (:func:`analysis.claims.template.template`) defines two schemes and one example
claim of every kind, and itself loads and evaluates: edit it into your paper, then run
``subdiv report FILE.toml`` and ``subdiv report FILE.toml --update-golden`` (the golden
verdicts ``FILE.verdicts.json``), and later ``subdiv check FILE.toml``. An existing file is not
replaced unless ``--force``; the file is written atomically.

Examples
--------
::

    subdiv new-paper my-paper.toml
    subdiv report my-paper.toml --output /tmp/r
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from ..result import AnalysisError
from .common import _print


def cmd_new_paper(args) -> None:
    from ..claims.template import template
    from ..report.files import atomic_write_text

    path = Path(args.file)
    if not path.name.endswith(".toml"):
        raise AnalysisError(f"a paper file ends in .toml, not {path.name!r}")
    if path.exists() and not args.force:
        raise AnalysisError(f"{path} exists: give --force to replace it")
    if not path.parent.is_dir():
        raise AnalysisError(f"folder {path.parent} does not exist")
    try:
        atomic_write_text(path, template())
    except OSError as exc:
        raise AnalysisError(f"cannot write {path}: {exc.strerror or exc}") from None
    print(f"wrote {path}", file=sys.stderr)
    if args.json:
        from ..claims.kinds import KIND_CLASSES

        _print(json.dumps({"wrote": str(path), "kinds": list(KIND_CLASSES)}))
        return
    _print(f"edit {path}, then: subdiv report {path} --output DIR  (and --update-golden; later: subdiv check {path})")


def register(subparsers) -> None:
    """Add ``new-paper`` to the ``subdiv`` command."""
    s = subparsers.add_parser("new-paper", help="write a commented paper-file template (one example claim of each kind)")
    s.add_argument("file", help="the new paper file, FILE.toml")
    s.add_argument("--force", action="store_true", help="replace an existing file")
    s.add_argument("--json", action="store_true", help="print what was written as JSON")
    s.set_defaults(func=cmd_new_paper)
