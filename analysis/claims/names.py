"""Names that become file names: a paper file's ``[paper] id`` (``<id>.md``), its scheme names and
figure names (``figures/<name>.png``) are *slugs*, so that no name from a paper file can point a
report somewhere else (``/etc/x``, ``../../x``) or collide with the tool's own files.

A slug is 1 to 64 characters from ``A-Z a-z 0-9 . _ -``, starting with a letter or a digit, without
``..``.

Examples
--------
>>> check_slug("four-point", "scheme name", '"four-point"')
'four-point'
>>> is_slug("../evil"), is_slug("/tmp/evil"), is_slug("a..b"), is_slug("004"), is_slug("blf-l-mu")
(False, False, False, True, True)
>>> check_slug("/tmp/evil", "[paper] id", '"900"')
Traceback (most recent call last):
...
analysis.result.AnalysisError: [paper] id '/tmp/evil' cannot be a file name: write 1 to 64 letters, digits, '.', '_' or '-', starting with a letter or digit, without '..' (e.g. "900")
"""

from __future__ import annotations

import re

from ..result import AnalysisError

__all__ = ["SLUG", "MAX_LENGTH", "MAX_GENERATED", "is_slug", "check_slug"]

#: the characters of a name that becomes (part of) a file name
SLUG = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]*")
#: the longest name a paper file may give; generated names built from them (``norm-<scheme>-j2-L1``) may
#: be longer, up to :data:`MAX_GENERATED`
MAX_LENGTH = 64
MAX_GENERATED = 128


def is_slug(name, max_length: int = MAX_LENGTH) -> bool:
    """Whether ``name`` is a string usable as a file name (see the module docstring)."""
    return (isinstance(name, str) and 0 < len(name) <= max_length and SLUG.fullmatch(name) is not None
            and ".." not in name)


def check_slug(name, what: str, example: str, max_length: int = MAX_LENGTH) -> str:
    """``name`` when it is a slug, else a one-line :class:`AnalysisError` naming the field (``what``)
    and showing what to type instead (``example``)."""
    if not is_slug(name, max_length):
        shown = repr(name) if not isinstance(name, str) or len(name) <= 80 else repr(name[:77] + "...")
        raise AnalysisError(f"{what} {shown} cannot be a file name: write 1 to {max_length} letters, digits, '.', "
                            f"'_' or '-', starting with a letter or digit, without '..' (e.g. {example})")
    return name
