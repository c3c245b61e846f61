"""JSON files a user gives (matrices, families, verdicts, golden files) read within a byte limit:
at most ``limit + 1`` bytes are read, so ``/dev/zero`` or a file of gigabytes is refused in one line
before it is parsed, and an integer of more digits than the reader allows (``LIMITS.digits``) is
refused before Python converts it (Python stops at 4 300 digits with an internal error).

Examples
--------
>>> import tempfile, os
>>> with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as fh:
...     _ = fh.write('[1, 2.5]')
>>> load_json(fh.name, limit=100, what="the matrix file", parse_float=str)
[1, '2.5']
>>> load_json(fh.name, limit=4, what="the matrix file")
Traceback (most recent call last):
...
analysis.result.AnalysisError: the matrix file ... is larger than the limit of 4 bytes: give a smaller file
>>> os.unlink(fh.name)
"""

from __future__ import annotations

import json
import os

from .limits import LIMITS, InputError
from ..result import AnalysisError

__all__ = ["read_text_limited", "load_json", "MIB", "MAX_VERDICTS_BYTES"]

MIB = 1 << 20
#: Verdicts and golden files (a paper's verdicts take tens of kB; a folder holds many papers).
MAX_VERDICTS_BYTES = 16 * MIB


def _size(n: int) -> str:
    return f"{n // MIB} MiB" if n >= MIB and n % MIB == 0 else f"{n} bytes"


def read_text_limited(path, *, limit: int, what: str) -> str:
    """The UTF-8 text of ``path``, reading at most ``limit + 1`` bytes (more is an error).
    ``OSError`` and ``UnicodeDecodeError`` pass to the caller, which knows what to suggest."""
    with open(os.fspath(path), "rb") as fh:
        data = fh.read(limit + 1)
    if len(data) > limit:
        raise AnalysisError(f"{what} {os.fspath(path)} is larger than the limit of {_size(limit)}: give a smaller file")
    return data.decode("utf-8")


def _int(text: str) -> int:
    digits = len(text.lstrip("-"))
    if digits > LIMITS.digits:
        raise InputError(f"a JSON integer of {digits} digits exceeds the limit {LIMITS.digits} digits "
                         "(limit 'digits'): write it as a fraction or formula of fewer digits", "limit")
    return int(text)


def load_json(path, *, limit: int, what: str, **kw):
    """``json.loads`` of :func:`read_text_limited`, integers checked for their number of digits
    (keywords such as ``parse_float`` pass to :func:`json.loads`)."""
    return json.loads(read_text_limited(path, limit=limit, what=what), parse_int=_int, **kw)
