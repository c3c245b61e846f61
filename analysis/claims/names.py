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
>>> check_claim_id("Theorem5.2(m=1)", "claim #1"), check_claim_id("(3.9)-(3.10)/P2n+1", "claim #2")
('Theorem5.2(m=1)', '(3.9)-(3.10)/P2n+1')
>>> check_claim_id("<b>y</b>", "claim #3")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
analysis.result.AnalysisError: claim #3: id '<b>y</b>' ... letters, digits, spaces and . , : ; _ - + = ^ / ( ) > ' * #, ...
>>> check_slug("/tmp/evil", "[paper] id", '"900"')
Traceback (most recent call last):
...
analysis.result.AnalysisError: [paper] id '/tmp/evil' cannot be a file name: write 1 to 64 letters, digits, '.', '_' or '-', starting with a letter or digit, without '..' (e.g. "900")
"""

from __future__ import annotations

import re

from ..result import AnalysisError

__all__ = ["SLUG", "MAX_LENGTH", "MAX_GENERATED", "is_slug", "check_slug", "CLAIM_ID", "check_claim_id"]

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


#: the characters of a claim id (the paper's numbering: ``Theorem5.2(m=1)``, ``(3.9)-(3.10)/P2n+1``,
#: ``Sect2.2(u>0)``): letters, digits, spaces and this punctuation — no ``<``, ``&``, ``|``, ``[``,
#: backtick or quote that could become markup in a report, no control characters
CLAIM_ID = re.compile(r"[\w(][\w .,:;+=^/()>'*#-]*")
#: the longest claim id
MAX_CLAIM_ID = 120


def check_claim_id(cid, where: str) -> str:
    """``cid`` when it is a valid claim id (see :data:`CLAIM_ID`; no ``..``, no space at either end), else a
    one-line :class:`AnalysisError` saying which characters are allowed."""
    if (not isinstance(cid, str) or not 0 < len(cid) <= MAX_CLAIM_ID or CLAIM_ID.fullmatch(cid) is None
            or cid != cid.strip() or ".." in cid):
        shown = repr(cid) if not isinstance(cid, str) or len(cid) <= 80 else repr(cid[:77] + "...")
        raise AnalysisError(f"{where}: id {shown} is not a claim id: write 1 to {MAX_CLAIM_ID} letters, digits, "
                            "spaces and . , : ; _ - + = ^ / ( ) > ' * #, starting with a letter, digit or '(', without "
                            "'..' (e.g. \"Theorem3.1\" or \"Lemma2(m=1)\")")
    return cid
