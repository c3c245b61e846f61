"""One file form for a bivariate mask (TOML or JSON, the same keys): ``subdiv surface --file MASK.toml``.

Keys (nothing else is accepted)::

    name = "butterfly"                      # optional, a label
    dilation = "dyadic"                     # optional: dyadic (default), quincunx, sqrt3, triadic, or [[a, b], [c, d]]
    symbol = "(1+z1)*(1+z2)/2"              # a Laurent polynomial in z1, z2 (other names are parameters), or
    mask = "0,0: 1; 1,0: 1/2; ..."          # the list i,j:coef as one text, or
    mask = [[0, 0, "1"], [1, 0, "1/2"]]     # a list of [i, j, coefficient] (coefficient a text or an integer)

Exactly one of ``symbol`` and ``mask``. Every text goes through :mod:`analysis.algebra.reader` (numbers exact,
no code); a decimal coefficient is read as the exact decimal. Limits: the file at most ``MAX_BYTES``, the
mask at most :data:`analysis.algebra.reader.LIMITS` ``.coefficients`` entries, indices ``|i|, |j| <= 40``.

Examples
--------
>>> import json, os, tempfile
>>> f = os.path.join(tempfile.mkdtemp(), "hat.json")
>>> _ = open(f, "w").write(json.dumps({"dilation": "quincunx", "mask": [[0, 0, "1"], [1, 0, "1"]]}))
>>> read_mask_file(f)
BivariateMask(z1 + 1, Dilation(quincunx))
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from ..result import AnalysisError
from .mask import BivariateMask

__all__ = ["read_mask_file", "mask_from_data", "MAX_BYTES", "KEYS"]

#: the largest mask file read
MAX_BYTES = 256_000
KEYS = ("name", "dilation", "symbol", "mask")


def read_mask_file(path: str) -> BivariateMask:
    """The mask of a ``.toml`` or ``.json`` file (module docstring)."""
    p = Path(path)
    give = "give the path of a mask file MASK.toml or MASK.json (docs/surfaces.md)"
    if p.is_dir():
        raise AnalysisError(f"{path!r} is a folder: {give}")
    if p.suffix.lower() not in (".toml", ".json"):
        what = f"ends in {p.suffix!r}" if p.suffix else "has no suffix"
        raise AnalysisError(f"{path!r} {what}: {give}")
    try:
        size = p.stat().st_size
    except OSError as exc:
        raise AnalysisError(f"cannot read the mask file {path!r}: {exc.strerror or exc}; {give}") from None
    if size > MAX_BYTES:
        raise AnalysisError(f"the mask file has {size} bytes (limit {MAX_BYTES})")
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise AnalysisError(f"the mask file {path!r} is not UTF-8 text: {give}") from None
    except OSError as exc:
        raise AnalysisError(f"cannot read the mask file {path!r}: {exc.strerror or exc}") from None
    if p.suffix.lower() == ".json":
        try:
            data = json.loads(text)
        except (json.JSONDecodeError, RecursionError) as exc:
            raise AnalysisError(f"the mask file is not valid JSON: {str(exc)[:80]}") from None
    else:
        import tomllib

        try:
            data = tomllib.loads(text)
        except (tomllib.TOMLDecodeError, RecursionError) as exc:
            raise AnalysisError(f"the mask file is not valid TOML: {str(exc)[:80]}") from None
    return mask_from_data(data)


def mask_from_data(data: Any, *, where: str = "the mask file") -> BivariateMask:
    """The mask of the parsed keys (a dict; module docstring); used by paper files too."""
    if not isinstance(data, dict):
        raise AnalysisError(f"{where} holds a table with the keys {', '.join(KEYS)}")
    unknown = sorted(str(k)[:30] for k in data if k not in KEYS)
    if unknown:
        raise AnalysisError(f"{where}: unknown key(s) {', '.join(unknown)}; the keys are {', '.join(KEYS)}")
    name = data.get("name", "")
    if not isinstance(name, str) or len(name) > 80:
        raise AnalysisError(f"{where}: name is a text of at most 80 characters")
    dil = data.get("dilation")
    if dil is not None and not isinstance(dil, (str, list)):
        raise AnalysisError(f"{where}: dilation is a name (dyadic, quincunx, sqrt3, triadic) or [[a, b], [c, d]]")
    given = [k for k in ("symbol", "mask") if k in data]
    if len(given) != 1:
        raise AnalysisError(f"{where}: give exactly one of symbol = \"...\" and mask = [...]")
    if "symbol" in data:
        if not isinstance(data["symbol"], str):
            raise AnalysisError(f"{where}: symbol is a text, e.g. \"(1+z1)*(1+z2)/2\"")
        return BivariateMask.from_symbol(data["symbol"], dil, name=name)
    m = data["mask"]
    if isinstance(m, str):
        return BivariateMask.from_list(m, dil, name=name)
    if not isinstance(m, list):
        raise AnalysisError(f"{where}: mask is a text 'i,j:coef; ...' or a list of [i, j, coefficient]")
    from ..algebra.reader import LIMITS, read_expression

    if len(m) > LIMITS.coefficients:
        raise AnalysisError(f"a mask has at most {LIMITS.coefficients} coefficients")
    coeffs = {}
    for e in m:
        if not (isinstance(e, list) and len(e) == 3 and all(type(x) is int for x in e[:2])
                and (isinstance(e[2], str) or type(e[2]) is int)):
            raise AnalysisError(f"{where}: each mask entry is [i, j, coefficient] with integers i, j and the "
                                f"coefficient a text or an integer, e.g. [1, 0, \"1/2\"] (not {str(e)[:40]})")
        i, j, c = e
        if (i, j) in coeffs:
            raise AnalysisError(f"the index {i},{j} appears twice in the mask")
        coeffs[(i, j)] = read_expression(str(c), what=f"coefficient {i},{j}")
    if not coeffs:
        raise AnalysisError(f"{where}: the mask is empty")
    from .mask import _dilation

    return BivariateMask(coeffs, _dilation(dil), name)
