"""The catalogue of named binary subdivision schemes.

``get(slug)`` returns a :class:`~schemes.catalogue.SchemeEntry` (symbol, parameters, source,
notes); ``names()`` lists the slugs and ``listing()`` what ``subdiv list`` shows (neither builds an
entry: both read :mod:`schemes.index`), ``entries()`` the entries. Classic schemes are in
:mod:`schemes.classic`, each paper's schemes in a module of its own (the paper's claims are in
:mod:`papers`).

Examples
--------
>>> import schemes
>>> schemes.get("chaikin").symbol.mask
(1/4, 3/4, 3/4, 1/4)
>>> len(schemes.names()) == len(schemes.entries())
True
"""

from .catalogue import SchemeEntry, entries, get, listing, names

__all__ = ["SchemeEntry", "entries", "get", "listing", "names"]
