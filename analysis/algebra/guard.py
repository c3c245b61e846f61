"""The second wall behind the input reader: sympy's string parser guarded while a command runs.

:func:`sympy_parser_guarded` is entered by the command line around every command. It imports no
sympy of its own: when sympy is already imported, its parser is guarded at once; otherwise the
guard is put in place by an import hook the moment a command first imports sympy's parser (so
that a command which never needs sympy, such as ``subdiv list``, never pays for importing it).
The check itself (:func:`analysis.algebra.reader._safe_for_sympy`) lives with the reader.
"""

from __future__ import annotations

import contextlib
import sys

#: the module whose ``parse_expr`` is guarded (``sympify`` of a ``str`` ends there, in ``eval``)
PARSER_MODULE = "sympy.parsing.sympy_parser"


class _PatchOnImport:
    """A meta-path finder that lets the other finders find :data:`PARSER_MODULE` and calls
    ``patch(module)`` right after the module has executed (nothing else is changed)."""

    def __init__(self, patch):
        self.patch = patch
        self.loaders: list = []

    def find_spec(self, name, path=None, target=None):
        if name != PARSER_MODULE:
            return None
        for finder in sys.meta_path:
            if finder is self or not hasattr(finder, "find_spec"):
                continue
            spec = finder.find_spec(name, path, target)
            if spec is not None:
                break
        else:
            return None
        loader = spec.loader
        if loader is None or not hasattr(loader, "exec_module"):
            return spec  # pragma: no cover - sympy's parser is a plain source module
        run, patch = loader.exec_module, self.patch

        def exec_module(module):
            run(module)
            patch(module)

        loader.exec_module = exec_module   # this spec's own loader instance: nothing shared
        self.loaders.append(loader)
        return spec

    def remove(self) -> None:
        """Take the hook out of ``sys.meta_path`` and the wrappers off the loaders it wrapped."""
        try:
            sys.meta_path.remove(self)
        except ValueError:  # pragma: no cover - removed by someone else
            pass
        for loader in self.loaders:
            loader.__dict__.pop("exec_module", None)

    def invalidate_caches(self) -> None:  # pragma: no cover - importlib protocol
        pass


@contextlib.contextmanager
def sympy_parser_guarded():
    """A second wall behind :func:`~analysis.algebra.reader.read_expression`. Our code never hands
    text to sympy, but sympy may parse text of its own (``nsimplify`` does) and a forgotten path
    might hand it ours: while this is active, sympy's string parser (where ``sympify`` of a ``str``
    ends in ``eval``) accepts only numbers, names, arithmetic and named functions, and refuses
    everything else. The command line runs every command inside it. (What it refuses: see
    :class:`analysis.algebra.reader._TextReachedSympy`.)

    >>> import sympy.parsing.sympy_parser as spp
    >>> original = spp.parse_expr
    >>> with sympy_parser_guarded():
    ...     spp.parse_expr is original
    False
    >>> spp.parse_expr is original
    True
    """
    patched: list = []

    def patch(spp) -> None:
        saved = spp.parse_expr

        def guarded(s, *args, **kwargs):
            from .reader import _TextReachedSympy, _safe_for_sympy

            if not isinstance(s, str) or not _safe_for_sympy(s):
                raise _TextReachedSympy(f"text {str(s)[:40]!r} reached sympy's parser instead of the input reader "
                                        "(please report this)")
            return saved(s, *args, **kwargs)

        spp.parse_expr = guarded
        patched.append((spp, saved))

    hook = None
    if PARSER_MODULE in sys.modules:
        patch(sys.modules[PARSER_MODULE])
    else:
        hook = _PatchOnImport(patch)
        sys.meta_path.insert(0, hook)
    try:
        yield
    finally:
        if hook is not None:
            hook.remove()
        for spp, saved in patched:
            spp.parse_expr = saved
