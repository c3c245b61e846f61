"""Derived families as files: ``subdiv derive ... --output FAMILY.json`` and ``--family FAMILY.json``.

The file is one JSON document (written atomically, :func:`analysis.report.files.atomic_write_text`)::

    {"format": "subdiv-family", "version": 1, "arity": 2, "start": -5,
     "mask": ["t1", "0", "-3*t1 - 1/16", ...], "parameters": ["t1"], "dimension": 1,
     "requirements": [...], "free_coefficients": {"t1": "a-5"}}

``subdiv range --family F`` and ``subdiv atlas --family F`` read it back in place of
``--mask/--start/--arity``; a missing, unreadable or malformed file is a one-line error.

Examples
--------
>>> import tempfile, os
>>> d = tempfile.mkdtemp(); f = os.path.join(d, "fam.json")
>>> write_family(f, {"arity": 2, "start": -1, "mask": "t1,1,t1", "parameters": ["t1"], "dimension": 1,
...                  "requirements": ["symmetric"], "free_coefficients": {"t1": "a-1"}})
>>> read_family(f)["mask"]
['t1', '1', 't1']
"""

from __future__ import annotations

import json

from ..result import AnalysisError

FORMAT = "subdiv-family"
#: A family file holds one mask and its free coefficients: more is not a family file.
MAX_FAMILY_BYTES = 1 << 20


def _split_mask(mask) -> list[str]:
    if isinstance(mask, (list, tuple)):
        return [str(c) for c in mask]
    out, depth, cur = [], 0, ""
    for ch in str(mask):
        if ch == "," and depth == 0:
            out.append(cur.strip())
            cur = ""
            continue
        depth += ch in "([{"
        depth -= ch in ")]}"
        cur += ch
    out.append(cur.strip())
    return out


def write_family(path: str, data: dict) -> None:
    """Write a derived family (the ``subdiv derive`` data) to ``path`` atomically."""
    from ..report.files import atomic_write_text

    doc = {"format": FORMAT, "version": 1, "arity": int(data["arity"]), "start": int(data["start"]),
           "mask": _split_mask(data["mask"]), "parameters": [str(p) for p in data.get("parameters", [])],
           "dimension": int(data.get("dimension", len(data.get("parameters", [])))),
           "requirements": [str(r) for r in data.get("requirements", [])],
           "free_coefficients": {str(k): str(v) for k, v in (data.get("free_coefficients") or {}).items()}}
    try:
        atomic_write_text(path, json.dumps(doc, indent=2) + "\n")
    except OSError as exc:
        raise AnalysisError(f"cannot write {path}: {exc.strerror or exc}") from None


def read_family(path: str) -> dict:
    """The family stored in ``path`` (checked: format, arity, start, mask); one-line errors."""
    try:
        from ..algebra.json_input import load_json

        doc = load_json(path, limit=MAX_FAMILY_BYTES, what="the family file")
    except OSError as exc:
        raise AnalysisError(f"cannot read the family file {path}: {exc.strerror or exc}") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise AnalysisError(f"{path} is not a family file (invalid JSON: {str(exc).splitlines()[0]})") from None
    except RecursionError:
        raise AnalysisError(f"{path} is not a family file (arrays nested too deeply; write one with "
                            "subdiv derive ... --output FILE.json)") from None
    if not isinstance(doc, dict) or doc.get("format") != FORMAT:
        raise AnalysisError(f"{path} is not a family file (write one with subdiv derive ... --output FILE.json)")
    for key, typ in (("arity", int), ("start", int), ("mask", list)):
        if not isinstance(doc.get(key), typ) or isinstance(doc.get(key), bool):
            raise AnalysisError(f"{path}: '{key}' missing or not a{'n integer' if typ is int else ' list'}")
    if doc["arity"] < 2:
        raise AnalysisError(f"{path}: arity must be >= 2")
    if not doc["mask"] or not all(isinstance(c, str) and c.strip() for c in doc["mask"]):
        raise AnalysisError(f"{path}: 'mask' must be a non-empty list of coefficient strings")
    return doc


def apply_family(args) -> None:
    """``--family FILE``: set ``--mask/--start/--arity`` from the file (exclusive with other inputs)."""
    path = getattr(args, "family", None)
    if path is None:
        return
    others = [f"--{x}" for x in ("scheme", "mask", "even", "symbol") if getattr(args, x, None) is not None]
    if others:
        raise AnalysisError(f"--family replaces the scheme input: drop {', '.join(others)}")
    doc = read_family(path)
    given = getattr(args, "arity", None)
    if given is not None and str(given).strip() != str(doc["arity"]):
        raise AnalysisError(f"the family in {path} has arity {doc['arity']}; drop --arity or give --arity {doc['arity']}")
    args.mask = ",".join(doc["mask"])
    args.start = str(doc["start"])
    args.arity = str(doc["arity"])
