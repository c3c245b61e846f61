"""Paper files: a paper's schemes and claims as data (TOML), checked without writing Python.

A paper file has a ``[paper]`` table (``id``, ``title``, ``authors``, ``citation``, ``source``,
``notes``), one ``[schemes.NAME]`` table per scheme and one ``[[claims]]`` table per claim::

    [paper]
    id = "900"
    title = "The four-point scheme"
    authors = ["N. Dyn", "D. Levin", "J. A. Gregory"]
    citation = "Comput. Aided Geom. Design 4 (1987) 257-268"

    [schemes.four-point]
    mask = ["-w", 0, "1/2+w", 1, "1/2+w", 0, "-w"]   # or: catalogue / rules / symbol / level_mask
    start = -3
    parameters = { w = "(0, 1/4)" }                   # name = domain ("real", "(a, b)", "[a, oo)")
    notes = "how garbled print was read"

    [[claims]]
    id = "900:Theorem1"            # the paper's numbering ("Theorem1" alone is prefixed with the id)
    statement = "verbatim, as printed"
    reading = "our reading, when the print is garbled"
    kind = "sum rules"             # one of analysis.claims.kinds.KIND_CLASSES
    # optional: title, reading_note, location, command (reproduces it), objects (names it speaks of)
    scheme = "four-point"          # optional when the file has one scheme
    factors = 2                    # the kind's fields

A scheme is given by exactly one of ``catalogue`` (a catalogue slug, resolved by the
``catalogue`` callable the command line passes in: the engine does not import the catalogue),
``mask`` + ``start``, ``rules = { even = [...], odd = [...], first = p }`` (binary) or
``rules = { stencils = [[...], ...], first = p }`` (M stencils for an M-ary scheme), ``symbol`` (an
expression in ``z``) or ``level_mask`` + ``start`` (a level-dependent scheme, coefficients in
``n`` or ``h = 2^-n``) or ``level_symbol`` (an expression in ``z`` and ``n``); the two level-dependent
forms take helper definitions ``where = { c = "cos(theta/2**(n+1))" }``. ``arity = M`` (issue 12;
default 2, or the catalogue entry's arity) makes the scheme m-ary, ``(S_a f)_i = sum_j a_{i-Mj} f_j``:
the kinds of :data:`analysis.claims.kinds.base.ANY_ARITY_KINDS` then analyse it with that arity, the
others refuse the claim when the file is loaded. A level-dependent m-ary scheme (``level_mask`` or
``level_symbol`` with ``arity = M``) uses ``h = M^-n`` (the level enters only through ``M^n``) and carries
its arity into every analysis.

A paper file is data, never code. Its ``python`` claims (``evaluator = "package.module:function"``)
are not imported or run unless the caller says so (``python="allowed"``: ``subdiv report/check
--allow-python``; ``python="bundled"``: the papers shipped with the tool): otherwise they are
inconclusive and say that they were not run. The evaluator string is checked (dotted Python names)
before anything else. Names that become file names (``[paper] id``, scheme names, figure names) must be
slugs (:mod:`analysis.claims.names`). Files above :data:`MAX_BYTES` or nesting deeper than
:data:`MAX_DEPTH` are refused with a one-line error.

Bad files are one-line :class:`~analysis.result.AnalysisError` messages: a TOML syntax error
names the file and line; an unknown kind lists the kinds; an unknown scheme, parameter or field
is named. A claim whose *evaluation* raises becomes inconclusive with the error
(:func:`analysis.claims.model.evaluate_claim`) while the other claims are still evaluated.

Examples
--------
>>> text = '''
... [paper]
... id = "900"
... title = "Chaikin"
... citation = "G. Chaikin (1974)"
... [schemes.chaikin]
... mask = ["1/4", "3/4", "3/4", "1/4"]
... start = -2
... [[claims]]
... id = "Prop1"
... statement = "Chaikin's scheme has three smoothing factors."
... kind = "sum rules"
... factors = 3
... '''
>>> p = parse_paper(text, "chaikin.toml")
>>> p.id, [c.id for c in p.claims]
('900', ['900:Prop1'])
>>> from analysis.claims.model import evaluate_paper
>>> [e.verdict.label for e in evaluate_paper(p)]
['CERTIFIED TRUE']
>>> parse_paper(text.replace('"sum rules"', '"sum rule"'), "chaikin.toml")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
analysis.result.AnalysisError: chaikin.toml: claim 900:Prop1: unknown kind 'sum rule'; the kinds are: all of, asymptotic equivalence, cited, ck range, construction, ...
>>> parse_paper("[paper\\nid = 1", "bad.toml")
Traceback (most recent call last):
...
analysis.result.AnalysisError: bad.toml:1: TOML syntax error: Expected ']' at the end of a table declaration

Algorithm
---------
``tomllib`` (``tomli`` on Python 3.10) reads the file; every table is checked against its allowed
keys; schemes are built exactly (:class:`~analysis.algebra.symbol.LaurentSymbol`,
:class:`~analysis.levels.level_dependent.LevelDependentScheme`); each claim's kind class
validates its fields at load time, so a bad field fails before any computation.

References
----------
TOML v1.0.0 (https://toml.io/en/v1.0.0); issue 11.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Callable, Mapping

import sympy as sp

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib

from ..algebra.symbol import LaurentSymbol, parse_coefficient
from ..levels.level_dependent import H, N, LevelDependentScheme, to_h
from ..result import AnalysisError
from .kinds import Domain, SchemeSpec, kind_class
from .kinds.base import rules_symbol
from .kinds.other import PYTHON_MODES, Python
from .model import Claim, Paper
from ..algebra.reader import LIMITS, as_expr
from .names import check_claim_id, check_slug

__all__ = ["load_paper", "parse_paper", "golden_file", "CLAIM_META", "MAX_BYTES", "MAX_DEPTH"]

PAPER_KEYS = {"id", "title", "authors", "citation", "source", "notes"}
SCHEME_KEYS = {"catalogue", "mask", "start", "rules", "symbol", "level_mask", "level_symbol", "where", "parameters",
               "bivariate",
               "notes", "title", "arity"}
#: the keys of a claim table that are not fields of its kind
CLAIM_META = {"id", "title", "statement", "reading", "reading_note", "location", "kind", "command", "objects"}
_DEFS = ("catalogue", "mask", "rules", "symbol", "level_mask", "level_symbol", "bivariate")

Catalogue = Callable[[str], Any]

#: the largest paper file read (the bundled ones are below 40 kB)
MAX_BYTES = 1 << 20
#: the deepest nesting of arrays and tables in a paper file (the bundled ones nest 6 deep)
MAX_DEPTH = 16


def golden_file(path: str | Path) -> Path:
    """The golden verdicts beside a paper file: ``FILE.verdicts.json`` for ``FILE.toml``."""
    p = Path(path)
    stem = p.name[: -len(".toml")] if p.name.endswith(".toml") else p.name
    return p.with_name(stem + ".verdicts.json")


def load_paper(path: str | Path, *, catalogue: Catalogue | None = None, python: str = "skip") -> Paper:
    """Read and validate the paper file ``path`` (see the module docstring; ``python`` as in
    :func:`parse_paper`). Files larger than :data:`MAX_BYTES` and anything but a regular file are refused."""
    p = Path(path)
    try:
        if not p.is_file():
            raise AnalysisError(f"no paper file {p}" if not p.exists() else
                                f"{p} is not a regular file: give the path of a paper file FILE.toml")
        with open(p, "rb") as fh:
            data = fh.read(MAX_BYTES + 1)
        if len(data) > MAX_BYTES:
            raise AnalysisError(f"the paper file {p} is larger than {MAX_BYTES // 1024} kB: split it into several "
                                "paper files")
        text = data.decode("utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise AnalysisError(f"cannot read the paper file {p}: {getattr(exc, 'strerror', None) or exc}") from None
    return parse_paper(text, str(p), catalogue=catalogue, python=python)


#: Names that are constants in every formula (or reserved), never parameters.
_CONSTANT_NAMES = {"pi": "3.14159...", "E": "2.71828...", "I": "the imaginary unit", "oo": "infinity",
                   "inf": "infinity", "nan": "not a number", "zoo": "complex infinity"}


def _check_digit_runs(text: str, where: str) -> None:
    """A number of more than ``LIMITS.digits`` digits is refused before TOML converts it (Python
    stops at 4 300 digits with an internal error; the reader allows ``LIMITS.digits``)."""
    m = re.search(r"\d{%d,}" % (LIMITS.digits + 1), text)
    if m:
        line = text.count("\n", 0, m.start()) + 1
        raise AnalysisError(f"{where}, line {line}: a number of {len(m.group())} digits exceeds the limit "
                            f"{LIMITS.digits} digits (limit 'digits'): write it with fewer digits")


def _syntax_error(exc: Exception, text: str, where: str) -> AnalysisError:
    msg = str(exc)
    m = re.search(r"\(at line (\d+), column \d+\)", msg)
    line = int(m.group(1)) if m else (len(text.splitlines()) or 1)
    msg = re.sub(r"\s*\(at (line \d+, column \d+|end of document)\)", "", msg)
    return AnalysisError(f"{where}:{line}: TOML syntax error: {msg}")


def _text(table: Mapping, key: str, where: str, required: bool = False) -> str:
    v = table.get(key)
    if v is None:
        if required:
            raise AnalysisError(f"{where}: missing '{key}'")
        return ""
    if not isinstance(v, str):
        raise AnalysisError(f"{where}: '{key}' must be a string")
    return v


def _unknown(table: Mapping, allowed: set, where: str) -> None:
    extra = sorted(set(table) - allowed)
    if extra:
        raise AnalysisError(f"{where}: unknown key {extra[0]!r} (allowed: {', '.join(sorted(allowed))})")


def _scheme(name: str, t: Mapping, where: str, catalogue: Catalogue | None) -> SchemeSpec:
    w = f"{where}: scheme {name!r}"
    if not isinstance(t, Mapping):
        raise AnalysisError(f"{w}: expected a table [schemes.{name}]")
    _unknown(t, SCHEME_KEYS, w)
    given = [k for k in _DEFS if k in t]
    if len(given) != 1:
        raise AnalysisError(f"{w}: give exactly one of {', '.join(_DEFS)}")
    how = given[0]
    params = t.get("parameters", {})
    if not isinstance(params, Mapping):
        raise AnalysisError(f"{w}: parameters = {{ name = \"domain\" }}")
    for k in params:
        if k == "z" or k in _CONSTANT_NAMES:
            raise AnalysisError(f"{w}: the parameter {k!r} is "
                                + ("a constant (" + _CONSTANT_NAMES[k] + ")" if k in _CONSTANT_NAMES
                                   else "the variable of the symbol") + f": rename it, e.g. {k}1 or w")
    try:
        domains = {k: Domain.parse(v) for k, v in params.items()}
    except AnalysisError as exc:
        raise AnalysisError(f"{w}: {exc}") from None
    positive = {k for k, d in domains.items() if d.lo != -sp.oo and bool(d.lo >= 0)}
    syms = {k: sp.Symbol(k, positive=True) if how == "level_mask" and k in positive else sp.Symbol(k) for k in domains}
    start = t.get("start", 0)
    if isinstance(start, bool) or not isinstance(start, int):
        raise AnalysisError(f"{w}: start must be an integer")
    declared = tuple(syms.values()) if params else None
    arity = _arity(t, how, w)
    if "where" in t and how not in ("level_mask", "level_symbol"):
        raise AnalysisError(f"{w}: 'where' (helper definitions in the level n) needs level_mask or level_symbol")
    symbol, level, definition = None, None, ""
    if how == "bivariate":
        return _bivariate_scheme(name, t, w, domains)
    try:
        if how == "catalogue":
            if catalogue is None:
                raise AnalysisError("catalogue names need the catalogue (run the file with `subdiv`)")
            entry = catalogue(str(t["catalogue"]))
            if isinstance(entry, LevelDependentScheme):       # a level-dependent catalogue entry
                level, symbol = entry, None
            else:
                symbol = getattr(entry, "symbol", entry)
            own = getattr(entry, "arity", 2)
            if arity is not None and arity != own:
                raise AnalysisError(f"catalogue entry {t['catalogue']!r} has arity {own}, not {arity} "
                                    f"(drop 'arity' or write arity = {own})")
            arity = own
            definition = f"catalogue entry {t['catalogue']!r}"
        elif how == "mask":
            coeffs = [parse_coefficient(c, locals_=syms) for c in t["mask"]]
            symbol = LaurentSymbol.from_mask(coeffs, start=start, params=declared)
            definition = f"mask {[sp.sstr(c) for c in coeffs]} from index {start}"
        elif how == "rules":
            symbol, m, definition = rules_symbol(t["rules"], locals_=syms, params=declared)
            if arity is not None and arity != m:
                raise AnalysisError(f"arity {arity} but the rules have {m} stencils (drop 'arity' or give "
                                    f"{arity} stencils: rules = {{ stencils = [...], first = p }})")
            arity = m
        elif how == "symbol":
            expr = parse_coefficient(str(t["symbol"]), locals_={**syms, "z": sp.Symbol("z")})
            symbol = LaurentSymbol.from_expr(expr, params=declared)
            definition = f"a(z) = {t['symbol']}"
        elif (arity or 2) != 2 or how == "level_symbol" or "where" in t:
            level, definition = _level_scheme(t, how, arity or 2, name)
        else:
            coeffs = [to_h(parse_coefficient(str(c), locals_={**syms, "n": N, "h": H})) for c in t["level_mask"]]
            level = LevelDependentScheme(tuple(coeffs), start, tuple(syms.values()) if params else
                                         tuple(sorted(set().union(*(c.free_symbols for c in coeffs)) - {H}, key=str)),
                                         slug=name)
            definition = f"level-dependent mask {[sp.sstr(c) for c in coeffs]} from index {start} (h = 2^-n)"
    except AnalysisError as exc:
        raise AnalysisError(f"{w}: {exc}") from None
    except (TypeError, KeyError) as exc:
        raise AnalysisError(f"{w}: cannot read {how}: {exc}") from None
    if symbol is not None:
        have = {x.name for c in symbol.mask for x in as_expr(c).free_symbols}
    else:
        have = {x.name for x in level.params}
    unknown = sorted(set(domains) - have)
    if unknown:
        raise AnalysisError(f"{w}: unknown parameter {unknown[0]!r}: it does not occur in the scheme "
                            f"(its parameters: {', '.join(sorted(have)) or 'none'})")
    arity = arity or 2
    if arity != 2:
        definition += f" (arity {arity})"
    return SchemeSpec(name, symbol, domains, definition, _text(t, "notes", w), level=level, arity=arity)


def _bivariate_scheme(name: str, t: Mapping, w: str, domains: Mapping) -> SchemeSpec:
    """A bivariate scheme ``bivariate = { dilation = "...", symbol = "..." }`` (or ``mask = [[i, j, "c"], ...]``):
    the keys of a mask file (:mod:`analysis.bivariate.mask_file`); nothing else of a scheme table but
    ``parameters`` and ``notes``."""
    from ..bivariate.mask_file import mask_from_data

    extra = sorted(set(t) - {"bivariate", "parameters", "notes"})
    if extra:
        raise AnalysisError(f"{w}: a bivariate scheme takes bivariate = {{...}}, parameters and notes, not {extra[0]!r}")
    try:
        a = mask_from_data(t["bivariate"], where="bivariate")
    except AnalysisError as exc:
        raise AnalysisError(f"{w}: {exc}") from None
    have = {p.name for p in a.params}
    unknown = sorted(set(domains) - have)
    if unknown:
        raise AnalysisError(f"{w}: unknown parameter {unknown[0]!r}: it does not occur in the scheme "
                            f"(its parameters: {', '.join(sorted(have)) or 'none'})")
    rows = [list(r) for r in a.dilation.matrix]
    definition = f"bivariate symbol {sp.sstr(sp.factor(a.symbol))} with dilation M = {rows}"
    return SchemeSpec(name, None, domains, definition, _text(t, "notes", w), bivariate=a)


def _level_scheme(t: Mapping, how: str, m: int, name: str):
    """A level-dependent scheme from ``level_symbol`` (an expression in ``z`` and ``n``) or ``level_mask``
    with the helper definitions ``where = { c = "cos(theta/3**(n+1))" }``: binary
    (:class:`~analysis.levels.level_dependent.LevelDependentScheme`, ``h = 2^-n``) or m-ary
    (``arity = m``, ``h = m^-n``)."""

    where = t.get("where", {})
    if not isinstance(where, Mapping) or not all(isinstance(v, (str, int, float)) for v in where.values()):
        raise AnalysisError('where = { NAME = "EXPR" } (expressions in the level n and the parameters)')
    where = {k: str(v) for k, v in where.items()}
    start = t.get("start", 0)
    if how == "level_symbol":
        if not isinstance(t["level_symbol"], str):
            raise AnalysisError("level_symbol must be a string: an expression in z and the level n")
        level = LevelDependentScheme.from_symbol(t["level_symbol"], where=where, slug=name, arity=m)
        what = f"level-dependent symbol a^n(z) = {t['level_symbol']}"
    else:
        if not isinstance(t["level_mask"], list):
            raise AnalysisError("level_mask must be a list of coefficients")
        items = [str(c) for c in t["level_mask"]]
        level = LevelDependentScheme.from_mask(items, start, where=where, slug=name, arity=m)
        what = f"level-dependent mask {items} from index {start}"
    if where:
        what += " where " + ", ".join(f"{k} = {v}" for k, v in where.items())
    return level, what + f" (h = {m}^-n)"


def _arity(t: Mapping, how: str, w: str) -> int | None:
    """The scheme's ``arity`` (issue 12): an integer >= 2; m-ary schemes are given by mask, symbol,
    catalogue, ``rules = { stencils = [...], first }`` (M stencils; the even/odd form is binary) or
    (level-dependent) ``level_mask`` / ``level_symbol``."""
    if "arity" not in t:
        return None
    m = t["arity"]
    if isinstance(m, bool) or not isinstance(m, int) or m < 2:
        raise AnalysisError(f"{w}: arity must be an integer >= 2, not {m!r}")
    if m != 2 and how == "rules" and isinstance(t.get("rules"), Mapping) and "stencils" not in t["rules"]:
        raise AnalysisError(f"{w}: arity {m} needs {m} stencils, rules = {{ stencils = [[...], ...], first = p }} "
                            "(even/odd rules describe binary schemes)")
    return m


def _too_deep(data: Any) -> bool:
    """Whether ``data`` nests arrays and tables more than :data:`MAX_DEPTH` deep (no recursion)."""
    stack = [(data, 0)]
    while stack:
        x, d = stack.pop()
        if isinstance(x, (dict, list)):
            if d >= MAX_DEPTH:
                return True
            stack.extend((v, d + 1) for v in (x.values() if isinstance(x, dict) else x))
    return False


def parse_paper(text: str, where: str = "<paper file>", *, catalogue: Catalogue | None = None,
                python: str = "skip") -> Paper:
    """A :class:`~analysis.claims.model.Paper` from the TOML ``text`` (``where`` names it in errors).

    ``python`` says what happens to the file's ``python`` claims (:data:`~analysis.claims.kinds.other.PYTHON_MODES`):
    ``"skip"`` (the default: a paper file is data; the claims are not run and say so), ``"allowed"`` (the user
    passed ``--allow-python``: they run, and each such claim records its evaluator in ``Claim.runs_python`` so
    that the report says it ran code from the file) or ``"bundled"`` (a paper shipped with the tool).
    """
    if python not in PYTHON_MODES:
        raise ValueError(f"python must be one of {PYTHON_MODES}, not {python!r}")
    _check_digit_runs(text, where)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise _syntax_error(exc, text, where) from None
    except ValueError:      # an integer over Python's conversion limit (digits joined by '_')
        raise AnalysisError(f"{where}: a number has more than {LIMITS.digits} digits: write it with fewer "
                            "digits (or as a formula in quotes, e.g. \"10**40\")") from None
    except RecursionError:
        raise AnalysisError(f"{where}: arrays or tables nested too deeply (at most {MAX_DEPTH} levels): "
                            "write the values as flat lists and tables") from None
    if _too_deep(data):
        raise AnalysisError(f"{where}: arrays or tables nested too deeply (at most {MAX_DEPTH} levels): "
                            "write the values as flat lists and tables")
    _unknown(data, {"paper", "schemes", "claims"}, where)
    meta = data.get("paper")
    if not isinstance(meta, Mapping):
        raise AnalysisError(f"{where}: missing the [paper] table (id, title, citation)")
    _unknown(meta, PAPER_KEYS, f"{where}: [paper]")
    pid = meta.get("id")
    if not isinstance(pid, str) or not pid or ":" in pid:
        raise AnalysisError(f"{where}: [paper] id must be a short string without ':' (e.g. \"900\")")
    check_slug(pid, f"{where}: [paper] id", '"900" or "my-paper"')     # it names <id>.md and <id>.html
    authors = meta.get("authors", [])
    if isinstance(authors, str):
        authors = [authors]
    tables = data.get("schemes", {})
    if not isinstance(tables, Mapping):
        raise AnalysisError(f"{where}: schemes are tables [schemes.NAME]")
    for name in tables:                      # scheme names become figure file names (blf-<scheme>.png)
        check_slug(name, f"{where}: scheme name", "[schemes.four-point]")
    schemes = {name: _scheme(name, t, where, catalogue) for name, t in tables.items()}
    claims_t = data.get("claims", [])
    if not isinstance(claims_t, list):
        raise AnalysisError(f"{where}: claims are an array of tables [[claims]]")
    claims, besides = [], []
    for k, t in enumerate(claims_t, start=1):
        if not isinstance(t, Mapping):
            raise AnalysisError(f"{where}: claim #{k} is not a table (write [[claims]] and key = value lines)")
        cid = t.get("id")
        if not isinstance(cid, str) or not cid:
            raise AnalysisError(f"{where}: claim #{k} needs an id (the paper's numbering, e.g. \"Theorem3.1\")")
        check_claim_id(cid, f"{where}: claim #{k}")
        cid = cid if ":" in cid else f"{pid}:{cid}"
        w = f"{where}: claim {cid}"
        kind = t.get("kind")
        if not isinstance(kind, str):
            raise AnalysisError(f"{w}: missing 'kind'")
        cls = kind_class_named(kind, w)
        fields = {x: v for x, v in t.items() if x not in CLAIM_META}
        obj = cls(fields, schemes, w, python=python) if cls is Python else cls(fields, schemes, w)
        runs = str(obj.get("evaluator")) if cls is Python and python == "allowed" else ""
        besides += [(w, str(b.get("claim"))) for b in (obj.get("beside") or ()) if isinstance(b, Mapping)]
        objects = t.get("objects", [obj.fields["scheme"]] if obj.uses_scheme else [])
        if not isinstance(objects, list) or not all(isinstance(x, str) for x in objects):
            raise AnalysisError(f"{w}: 'objects' must be a list of names")
        claims.append(Claim(id=cid, kind=obj.shown_kind(), statement=_text(t, "statement", w, required=True),
                            evaluate=obj.evaluate, title=_text(t, "title", w), reading=_text(t, "reading", w) or None,
                            reading_note=_text(t, "reading_note", w) or None,
                            objects=tuple(objects),
                            command=_text(t, "command", w) or f"subdiv report {where} --claim '{cid}'"
                            + (" --allow-python" if runs else ""),
                            location=_text(t, "location", w), runs_python=runs))
    ids = {c.id for c in claims}
    for w, b in besides:                     # a profile speaks beside claims of this paper: they must exist
        if (b if ":" in b else f"{pid}:{b}") not in ids:
            raise AnalysisError(f"{w}: beside names the claim {b!r}, which the file does not define "
                                f"(its claims: {', '.join(sorted(c.split(':', 1)[1] for c in ids))})")
    notes = [_text(meta, "notes", f"{where}: [paper]")]
    if authors:
        notes.insert(0, "Authors: " + ", ".join(map(str, authors)) + ".")
    for s in schemes.values():
        notes.append(f"Scheme {s.name}: {s.definition}"
                     + (f"; parameters {', '.join(f'{k} in {d}' for k, d in s.domains.items())}" if s.domains else "")
                     + (f". {s.notes}" if s.notes else ""))
    try:
        return Paper(id=pid, title=_text(meta, "title", f"{where}: [paper]", required=True),
                     citation=_text(meta, "citation", f"{where}: [paper]"), claims=claims,
                     source=_text(meta, "source", f"{where}: [paper]"), notes="\n".join(x for x in notes if x))
    except ValueError as exc:
        raise AnalysisError(f"{where}: {exc}") from None


def kind_class_named(kind: str, where: str):
    try:
        return kind_class(kind)
    except AnalysisError as exc:
        raise AnalysisError(f"{where}: {exc}") from None
