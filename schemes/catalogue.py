"""The catalogue of named binary subdivision schemes (like PyWavelets' ``Wavelet('db3')`` registry).

Every scheme is a :class:`SchemeEntry` with a stable kebab-case slug, its Laurent symbol (exact,
possibly with free sympy parameters), its bibliographic source and, for schemes defined by a
paper's rules, the stencils as printed. Classic schemes live in :mod:`schemes.classic`, and each
paper's schemes have a module of their own (:mod:`schemes.seed003`, :mod:`schemes.seed004`); the
paper's transcriptions, derivations and claims are in its folder of :mod:`papers`
(``papers/seed003/``).

Convention (see :mod:`analysis.algebra.symbol`): ``(S_a f)_i = sum_j a_{i-2j} f_j``,
``a(z) = sum_i a_i z^i``.

Examples
--------
>>> from schemes import get, names
>>> names()[:3]
['bspline-1', 'bspline-2', 'bspline-3']
>>> e = get("four-point")
>>> e.params
(w,)
>>> e.symbol_at(w="1/16")
LaurentSymbol([-1/16, 0, 9/16, 1, 9/16, 0, -1/16], start=-3, domain=QQ)
>>> e.default_symbol() == e.symbol_at(w="1/16")
True
>>> get("cubic-bspline").slug                 # an alias resolves to its entry
'bspline-3'
>>> get("four-piont")
Traceback (most recent call last):
...
analysis.result.AnalysisError: unknown scheme 'four-piont'; did you mean: dual-four-point, four-point?
"""

from __future__ import annotations

import difflib
import importlib
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Callable

from analysis.result import AnalysisError

if TYPE_CHECKING:  # pragma: no cover
    import sympy as sp

    from analysis.algebra.symbol import LaurentSymbol, Rules

# Importing the catalogue is cheap: no sympy here. The names, titles and sources are in the
# generated :mod:`schemes.index`; an entry (its exact symbol) is built on first use, by the module
# that defines it (:func:`get`), and all of them only by :func:`entries`.

#: Modules that define catalogue entries, each with a module-level ``ENTRIES`` tuple, in the
#: order in which :func:`names` lists them.
ENTRY_MODULES = ("schemes.classic", "schemes.seed003", "schemes.seed004", "schemes.interpolatory",
                 "schemes.wavelets")
# A module may also define ``NUMERIC_ENTRIES`` (:class:`NumericSchemeEntry`: masks known only as
# certified enclosures, or not symmetric, e.g. Daubechies) and ``ALIASES`` (``alias -> slug`` for
# entries defined elsewhere). Numeric entries are found by :func:`get`; :func:`names` and
# :func:`entries` list them only with ``numeric=True``.

_SLUG = re.compile(r"^[a-z0-9]+(?:-[a-z0-9]+)*$")


@dataclass(frozen=True)
class SchemeEntry:
    """A named, possibly parametrised, binary subdivision scheme.

    Attributes
    ----------
    slug : str
        Stable kebab-case name, the registry key (``"four-point"``).
    title : str
        Human-readable name.
    symbol : LaurentSymbol
        The symbol ``a(z)``; its coefficients may contain the free parameters ``params``.
    params : tuple of sympy.Symbol
        The free parameters, in the order the paper lists them.
    source : str
        Bibliographic source; for paper schemes with the equation number ("seed 003, rule (1)").
    notes : str
        How the entry was read (garbled formulas, conventions, index shifts).
    defaults : mapping
        ``name -> exact value`` of customary parameter values (``w = 1/16``).
    stencils : Rules or None
        The even/odd rules as printed, when the entry is defined from rules.
    aliases : tuple of str
        Other names :func:`get` accepts for this entry.
    arity : int
        ``m`` in ``(S_a f)_i = sum_j a_{i-mj} f_j`` (2 for binary). Entries of arity ``m > 2`` live beside
        their binary relatives (:mod:`schemes.classic`, :mod:`schemes.interpolatory`); they are found by
        :func:`get` and listed only with ``names(mary=True)`` / ``entries(mary=True)``.

    Examples
    --------
    >>> import sympy as sp
    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> w = sp.Symbol("w")
    >>> e = SchemeEntry(slug="toy", title="Toy", params=(w,), source="none",
    ...                 symbol=LaurentSymbol.from_mask([w, 1, 1 - w], start=-1))
    >>> e.symbol_at(w=0).mask, e.symbol_at(w=0).start
    ((1, 1), 0)
    """

    slug: str
    title: str
    symbol: LaurentSymbol
    params: tuple
    source: str
    notes: str = ""
    defaults: Mapping[str, sp.Expr] = field(default_factory=dict, hash=False)
    stencils: Rules | None = None
    aliases: tuple = ()
    arity: int = 2

    def __post_init__(self) -> None:
        if not isinstance(self.arity, int) or self.arity < 2:
            raise ValueError(f"{self.slug}: arity must be an integer >= 2")
        if not _SLUG.match(self.slug):
            raise ValueError(f"slug {self.slug!r} is not kebab-case")
        for a in self.aliases:
            if not _SLUG.match(a):
                raise ValueError(f"alias {a!r} of {self.slug!r} is not kebab-case")
        params = tuple(self.params)
        object.__setattr__(self, "params", params)
        object.__setattr__(self, "aliases", tuple(self.aliases))
        if set(params) != set(self.symbol.params):
            raise ValueError(f"{self.slug}: params {params} differ from the symbol's "
                             f"{self.symbol.params}")
        from analysis.algebra.symbol import parse_coefficient

        names = {p.name for p in params}
        defaults = {str(k): parse_coefficient(v) for k, v in dict(self.defaults).items()}
        unknown = set(defaults) - names
        if unknown:
            raise ValueError(f"{self.slug}: defaults for unknown parameter(s) {sorted(unknown)}")
        object.__setattr__(self, "defaults", MappingProxyType(defaults))

    @property
    def param_names(self) -> tuple[str, ...]:
        """The parameter names, e.g. ``('mu', 'nu', 'omega')``."""
        return tuple(p.name for p in self.params)

    def symbol_at(self, **values) -> LaurentSymbol:
        """The symbol with the given parameters substituted (exact values, strings or expressions).

        Parameters not named stay free. Unknown names are an :class:`AnalysisError`.

        >>> get("dfh-chaikin-perturbation").symbol_at(omega=0)
        LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
        """
        unknown = set(values) - set(self.param_names)
        if unknown:
            known = ", ".join(self.param_names) or "none"
            raise AnalysisError(f"scheme {self.slug!r} has no parameter "
                                f"{', '.join(sorted(unknown))} (its parameters: {known})")
        if not values:
            return self.symbol
        return self.symbol.subs(values)

    def default_symbol(self) -> LaurentSymbol:
        """The symbol at :attr:`defaults` (parameters without a default stay free).

        >>> get("four-point").default_symbol().mask
        (-1/16, 0, 9/16, 1, 9/16, 0, -1/16)
        """
        return self.symbol_at(**dict(self.defaults))


@dataclass(frozen=True)
class NumericSchemeEntry:
    """A named scheme whose mask is known as certified enclosures (Arb balls), not exactly.

    Used for masks with irrational coefficients in number fields too large for exact work
    (Daubechies' D6 ... D54; :mod:`schemes.wavelets`). Duck-compatible with
    :class:`SchemeEntry` where that makes sense (``slug``, ``title``, ``source``, ``notes``,
    ``aliases``, ``params == ()``, ``defaults``, ``stencils``); :attr:`symbol` is the exact symbol
    when one is known and otherwise a one-line :class:`AnalysisError` pointing to
    :meth:`enclosure`.

    Attributes
    ----------
    start, length : int
        The mask is ``a_start, ..., a_{start+length-1}``.
    enclosure : callable
        ``enclosure(prec) -> list[flint.arb]``: real balls, radius ``< 2^-prec``, each containing
        the true coefficient (``a(1) = 2`` normalisation).
    exact_symbol : LaurentSymbol or None
        The exact symbol when known (then it lies in the balls).
    sum_rules : int or None
        The number of ``(1+z)/2`` factors of the symbol, when known by construction.

    Examples
    --------
    >>> e = get("daubechies-6")
    >>> e.has_exact_symbol, e.support, e.sum_rules
    (False, (0, 5), 3)
    >>> e.enclosure(64)[0]                          # a ball, not a float
    [0.470467207784164 +/- ...]
    >>> e.symbol
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: scheme 'daubechies-6' has no exact symbol; use .enclosure(prec) (Arb balls), .mask_mpmath(dps) or .mask_float()
    """

    slug: str
    title: str
    source: str
    start: int
    length: int
    enclosure: Callable = field(repr=False, compare=False)
    notes: str = ""
    aliases: tuple = ()
    exact_symbol: LaurentSymbol | None = None
    sum_rules: int | None = None

    params = ()
    stencils = None

    def __post_init__(self) -> None:
        if not _SLUG.match(self.slug):
            raise ValueError(f"slug {self.slug!r} is not kebab-case")
        for a in self.aliases:
            if not _SLUG.match(a):
                raise ValueError(f"alias {a!r} of {self.slug!r} is not kebab-case")
        object.__setattr__(self, "aliases", tuple(self.aliases))
        if self.exact_symbol is not None and self.exact_symbol.support != self.support:
            raise ValueError(f"{self.slug}: exact symbol support {self.exact_symbol.support} "
                             f"differs from {self.support}")

    @property
    def defaults(self) -> Mapping[str, sp.Expr]:
        return MappingProxyType({})

    @property
    def param_names(self) -> tuple[str, ...]:
        return ()

    @property
    def support(self) -> tuple[int, int]:
        return (self.start, self.start + self.length - 1)

    @property
    def has_exact_symbol(self) -> bool:
        return self.exact_symbol is not None

    @property
    def symbol(self) -> LaurentSymbol:
        """The exact symbol, or a one-line :class:`AnalysisError` if there is none."""
        if self.exact_symbol is None:
            raise AnalysisError(f"scheme {self.slug!r} has no exact symbol; use .enclosure(prec) "
                                "(Arb balls), .mask_mpmath(dps) or .mask_float()")
        return self.exact_symbol

    def symbol_at(self, **values) -> LaurentSymbol:
        if values:
            raise AnalysisError(f"scheme {self.slug!r} has no parameter "
                                f"{', '.join(sorted(values))} (its parameters: none)")
        return self.symbol

    def default_symbol(self) -> LaurentSymbol:
        return self.symbol

    def mask_float(self) -> list[float]:
        """float64 values: midpoints of balls of radius ``< 2^-60`` (within one ulp)."""
        return [float(b.mid()) for b in self.enclosure(60)]

    def mask_mpmath(self, dps: int = 50) -> list:
        """mpmath ``mpf`` values accurate to about ``dps`` digits (exact ball midpoints)."""
        import mpmath

        prec = int(dps * 3.33) + 20
        out = []
        with mpmath.workprec(prec + 64):
            for b in self.enclosure(prec):
                man, exp = b.mid().man_exp()
                out.append(mpmath.ldexp(mpmath.mpf(int(man)), int(exp)))
        return out


# --------------------------------------------------------------------------------------------
# the registry
# --------------------------------------------------------------------------------------------

class LazyEntries(Mapping):
    """Catalogue entries by slug, each built on first use (building one computes its exact symbol;
    a command that needs one entry, or only the names, does not pay for all of them)."""

    def __init__(self, factories: dict):
        self._factories = dict(factories)
        self._built: dict = {}

    def __getitem__(self, slug):
        if slug not in self._built:
            self._built[slug] = self._factories[slug]()
        return self._built[slug]

    def __iter__(self):
        return iter(self._factories)

    def __len__(self) -> int:
        return len(self._factories)


#: module name -> its entries by slug (:func:`module_entries`)
_MODULE_ENTRIES: dict[str, LazyEntries] = {}
_REGISTRY: dict[str, SchemeEntry] | None = None
_NUMERIC: dict[str, NumericSchemeEntry] = {}
#: entries of arity m > 2: found by get(), listed only with names(mary=True) / entries(mary=True).
_MARY: dict[str, SchemeEntry] = {}
_ALIASES: dict[str, str] = {}


def module_entries(modname: str) -> Mapping:
    """The entries the module ``modname`` defines (its ``ENTRIES``, then its ``NUMERIC_ENTRIES``), by
    slug and in order; each group is a tuple of entries or a :class:`LazyEntries` (built on first use).

    >>> list(module_entries("schemes.classic"))[7:9]
    ['chaikin', 'four-point']
    """
    if modname not in _MODULE_ENTRIES:
        module = importlib.import_module(modname)
        factories: dict = {}
        for group in (module.ENTRIES, getattr(module, "NUMERIC_ENTRIES", ())):
            pairs = ([(k, lambda g=group, k=k: g[k]) for k in group] if isinstance(group, Mapping)
                     else [(e.slug, lambda e=e: e) for e in group])
            for slug, make in pairs:
                if slug in factories:
                    raise RuntimeError(f"duplicate scheme slug {slug!r} in {modname}")
                factories[slug] = make
        _MODULE_ENTRIES[modname] = LazyEntries(factories)
    return _MODULE_ENTRIES[modname]


def _registry() -> dict[str, SchemeEntry]:
    """Every entry, built (:func:`entries`; the check of :mod:`schemes.index` against the modules)."""
    global _REGISTRY
    if _REGISTRY is None:
        reg: dict[str, SchemeEntry] = {}
        numeric: dict[str, NumericSchemeEntry] = {}
        aliases: dict[str, str] = {}
        extra: dict[str, str] = {}
        _MARY.clear()
        for modname in ENTRY_MODULES:
            module = importlib.import_module(modname)
            for key, e in module_entries(modname).items():
                if e.slug != key:
                    raise RuntimeError(f"entry {e.slug!r} is listed as {key!r} in {modname}")
                if e.slug in reg or e.slug in numeric or e.slug in aliases or e.slug in _MARY:
                    raise RuntimeError(f"duplicate scheme slug {e.slug!r} in {modname}")
                (numeric if isinstance(e, NumericSchemeEntry) else _MARY if e.arity != 2 else reg)[e.slug] = e
                for a in e.aliases:
                    if a in reg or a in aliases:
                        raise RuntimeError(f"alias {a!r} of {e.slug!r} is already taken")
                    aliases[a] = e.slug
            for a, target in dict(getattr(module, "ALIASES", {})).items():
                if not _SLUG.match(a) or a in extra:
                    raise RuntimeError(f"bad or duplicate alias {a!r} in {modname}")
                extra[a] = target
        for a, target in extra.items():
            if target not in reg and target not in numeric:
                raise RuntimeError(f"alias {a!r} points to unknown scheme {target!r}")
            if a in aliases:
                raise RuntimeError(f"alias {a!r} of {target!r} is already taken")
            aliases[a] = target
        clash = set(aliases) & (set(reg) | set(numeric))
        if clash:
            raise RuntimeError(f"aliases shadow slugs: {sorted(clash)}")
        _ALIASES.clear()
        _ALIASES.update(aliases)
        _NUMERIC.clear()
        _NUMERIC.update(numeric)
        _REGISTRY = reg
    return _REGISTRY


def _rows(*, numeric: bool = False, mary: bool = False) -> list:
    """The :class:`schemes.index.Row` of each listed entry, in catalogue order (nothing is built)."""
    from .index import SCHEMES

    groups = {"exact"} | ({"numeric"} if numeric else set()) | ({"mary"} if mary else set())
    return [r for r in SCHEMES if r.group in groups]


def names(*, aliases: bool = False, numeric: bool = False, mary: bool = False) -> list[str]:
    """The slugs of all entries, in catalogue order (with ``aliases=True`` also the aliases); no
    entry is built (the names come from :mod:`schemes.index`).

    With ``numeric=True`` the :class:`NumericSchemeEntry` slugs (Daubechies) follow the exact
    entries; aliases of numeric entries are listed only then.

    >>> "four-point" in names() and "chaikin" in names()
    True
    >>> "cubic-bspline" in names(), "cubic-bspline" in names(aliases=True)
    (False, True)
    >>> "daubechies-4" in names(), "daubechies-4" in names(numeric=True)
    (False, True)
    """
    from .index import ALIASES, BY_SLUG

    out = [r.slug for r in _rows(numeric=numeric, mary=mary)]
    if aliases:
        out += [a for a, t in ALIASES.items() if numeric or BY_SLUG[t].group == "exact"]
    return out


def listing(*, numeric: bool = False, mary: bool = False) -> list:
    """What ``subdiv list`` shows of each entry — ``slug``, ``title``, ``params`` (names), ``source``,
    ``arity`` — in catalogue order, without building any entry (:class:`schemes.index.Row`).

    >>> [(r.slug, r.params) for r in listing() if r.slug == "four-point"]
    [('four-point', ('w',))]
    """
    return _rows(numeric=numeric, mary=mary)


def entries(*, numeric: bool = False, mary: bool = False) -> list:
    """All entries with an exact symbol, in catalogue order (``numeric=True``: then the
    :class:`NumericSchemeEntry` ones). Builds every entry; :func:`listing` does not.

    >>> all(e.symbol(1) == 2 for e in entries())
    True
    >>> all(sum(e.enclosure(53)).contains(2) for e in entries(numeric=True)[len(entries()):])
    True
    """
    out: list = list(_registry().values())
    if numeric:
        out += list(_NUMERIC.values())
    if mary:
        out += list(_MARY.values())
    return out


def get(slug: str) -> SchemeEntry:
    """The entry named ``slug`` (or one of its aliases), built on first use by the module that
    defines it (:func:`module_entries`; the other modules are not imported).

    An unknown name is an :class:`AnalysisError` whose one-line message lists close matches.

    >>> get("bspline-3").symbol
    LaurentSymbol([1/8, 1/2, 3/4, 1/2, 1/8], start=-2, domain=QQ)
    >>> get("chaikn")
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: unknown scheme 'chaikn'; did you mean: chaikin?
    """
    from .index import ALIASES, BY_SLUG

    key = str(slug).strip().lower()
    target = key if key in BY_SLUG else ALIASES.get(key)
    if target is not None:
        return module_entries(BY_SLUG[target].module)[target]
    exact_and_numeric = [r.slug for r in _rows(numeric=True)]
    candidates = exact_and_numeric + list(ALIASES)
    close = sorted(difflib.get_close_matches(key, candidates, n=5, cutoff=0.6))
    if not close:                      # m-ary names are suggested only when no binary name is close
        candidates = candidates + [r.slug for r in _rows(mary=True) if r.group == "mary"]
        close = sorted(difflib.get_close_matches(key, candidates, n=5, cutoff=0.6))
    m = re.fullmatch(r"(.*?)(\d+)", key)
    if m:
        # a numbered family ("daubechies-5"): the numerically nearest members
        same = [c for c in candidates if re.fullmatch(re.escape(m[1]) + r"\d+", c)]
        if same:
            close = sorted(same, key=lambda c: (abs(int(re.search(r"\d+$", c)[0]) - int(m[2])),
                                                c))[:4]
    if not close:
        close = [c for c in candidates if key and (key in c or c in key)][:5]
    hint = (f"; did you mean: {', '.join(close)}?" if close
            else "; see schemes.names() for the catalogue")
    raise AnalysisError(f"unknown scheme {slug!r}{hint}")
