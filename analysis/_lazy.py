"""Lazy re-exports of a package (PEP 562): a name is imported from its module on first use, so that
importing the package costs nothing it does not use (the command line starts fast).

Examples
--------
>>> import analysis.regularity as r
>>> "holder_exponent" in dir(r)
True
"""

from __future__ import annotations

import importlib


def lazy_exports(package: str, table: dict, namespace: dict):
    """``(__getattr__, __dir__)`` for ``package``: ``table`` maps each exported name to the module
    (relative to ``package``) that defines it; a value is cached in ``namespace`` when first asked."""

    def __getattr__(name: str):
        if name in table:
            value = getattr(importlib.import_module(table[name], package), name)
            namespace[name] = value
            return value
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__() -> list[str]:
        return sorted(set(namespace) | set(table))

    return __getattr__, __dir__
