"""The catalogue of named binary subdivision schemes (like PyWavelets' ``Wavelet('db3')`` registry).

Every scheme is a :class:`SchemeEntry` with a stable kebab-case slug, its Laurent symbol (exact,
possibly with free sympy parameters), its bibliographic source and, for schemes defined by a
paper's rules, the stencils as printed. Classic schemes live in :mod:`schemes.classic`, and each
paper has a module of its own (:mod:`schemes.seed003`, :mod:`schemes.seed004`) which will also
hold that paper's claims.

Convention (see :mod:`analysis.symbol`): ``(S_a f)_i = sum_j a_{i-2j} f_j``,
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
analysis.result.AnalysisError: unknown scheme 'four-piont'; did you mean: four-point?
"""

from __future__ import annotations

import difflib
import importlib
import re
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import sympy as sp

from analysis.result import AnalysisError
from analysis.symbol import LaurentSymbol, Rules, parse_coefficient

#: Modules that define catalogue entries, each with a module-level ``ENTRIES`` tuple, in the
#: order in which :func:`names` lists them.
ENTRY_MODULES = ("schemes.classic", "schemes.seed003", "schemes.seed004")

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

    Examples
    --------
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

    def __post_init__(self) -> None:
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


# --------------------------------------------------------------------------------------------
# the registry
# --------------------------------------------------------------------------------------------

_REGISTRY: dict[str, SchemeEntry] | None = None
_ALIASES: dict[str, str] = {}


def _registry() -> dict[str, SchemeEntry]:
    global _REGISTRY
    if _REGISTRY is None:
        reg: dict[str, SchemeEntry] = {}
        aliases: dict[str, str] = {}
        for modname in ENTRY_MODULES:
            for e in importlib.import_module(modname).ENTRIES:
                if e.slug in reg or e.slug in aliases:
                    raise RuntimeError(f"duplicate scheme slug {e.slug!r} in {modname}")
                reg[e.slug] = e
                for a in e.aliases:
                    if a in reg or a in aliases:
                        raise RuntimeError(f"alias {a!r} of {e.slug!r} is already taken")
                    aliases[a] = e.slug
        clash = set(aliases) & set(reg)
        if clash:
            raise RuntimeError(f"aliases shadow slugs: {sorted(clash)}")
        _ALIASES.clear()
        _ALIASES.update(aliases)
        _REGISTRY = reg
    return _REGISTRY


def names(*, aliases: bool = False) -> list[str]:
    """The slugs of all entries, in catalogue order (with ``aliases=True`` also the aliases).

    >>> "four-point" in names() and "chaikin" in names()
    True
    >>> "cubic-bspline" in names(), "cubic-bspline" in names(aliases=True)
    (False, True)
    """
    out = list(_registry())
    if aliases:
        out += list(_ALIASES)
    return out


def entries() -> list[SchemeEntry]:
    """All entries, in catalogue order.

    >>> all(e.symbol(1) == 2 for e in entries())
    True
    """
    return list(_registry().values())


def get(slug: str) -> SchemeEntry:
    """The entry named ``slug`` (or one of its aliases).

    An unknown name is an :class:`AnalysisError` whose one-line message lists close matches.

    >>> get("bspline-3").symbol
    LaurentSymbol([1/8, 1/2, 3/4, 1/2, 1/8], start=-2, domain=QQ)
    >>> get("chaikn")
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: unknown scheme 'chaikn'; did you mean: chaikin?
    """
    reg = _registry()
    key = str(slug).strip().lower()
    if key in reg:
        return reg[key]
    if key in _ALIASES:
        return reg[_ALIASES[key]]
    candidates = list(reg) + list(_ALIASES)
    close = sorted(difflib.get_close_matches(key, candidates, n=5, cutoff=0.6))
    if not close:
        close = [c for c in candidates if key and (key in c or c in key)][:5]
    hint = (f"; did you mean: {', '.join(close)}?" if close
            else "; see schemes.names() for the catalogue")
    raise AnalysisError(f"unknown scheme {slug!r}{hint}")
