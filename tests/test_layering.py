"""The layers of the engine cannot decay (issue 10): an AST walk over every import.

algebra -> stationary -> jsr -> regularity -> bivariate -> levels / nonuniform -> claims -> report -> cli / api
(the notebook façade ``analysis.api``, a sibling of the command line):
a module may import its own layer and the layers to its left (and the base modules
``analysis.result``, ``analysis.jsonable``, ``analysis.progress``, ``analysis._lazy``), never one to its right; ``levels`` and
``nonuniform`` are siblings and do not import each other. Nothing in the engine imports the
catalogue (``schemes``) or the papers (``papers``) (the command line and the façade may use the
catalogue); the catalogue imports no layer above
``levels``; a paper imports anything but ``analysis.cli``. Every import counts, including the
ones inside functions, and there is no import cycle between modules. No module is longer than
about 700 lines.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("analysis", "schemes", "papers")

#: rank of each engine layer; equal rank = siblings (may not import each other)
LAYERS = {"result": 0, "jsonable": 0, "progress": 0, "_lazy": 0, "algebra": 1, "stationary": 2, "jsr": 3, "regularity": 4,
          "bivariate": 4.5,
          "levels": 5, "nonuniform": 5, "claims": 6, "report": 7, "cli": 8, "api": 8, "__main__": 9}
#: extraordinary vertices of surface schemes: above the algebra (local matrices, their spectra)
LAYERS["vertex"] = 5
#: the base layer: the results contract, progress announcements, lazy re-exports
BASE = {"result", "jsonable", "progress", "_lazy"}
MAX_LINES = 720


def _modules():
    out = {}
    for pkg in PACKAGES:
        for f in sorted((ROOT / pkg).rglob("*.py")):
            rel = f.relative_to(ROOT).with_suffix("")
            parts = list(rel.parts)
            is_pkg = parts[-1] == "__init__"
            if is_pkg:
                parts = parts[:-1]
            out[".".join(parts)] = (f, is_pkg)
    return out


MODULES = _modules()


@functools.lru_cache(maxsize=None)
def _imports(name: str) -> frozenset[str]:
    """Every module ``name`` imports (absolute names, resolved, restricted to our packages); parsed when
    a test asks (not at collection, in every test process)."""
    f, is_pkg = MODULES[name]
    tree = ast.parse(f.read_text(encoding="utf-8"))
    base = name.split(".") if is_pkg else name.split(".")[:-1]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                stem = base[: len(base) - (node.level - 1)]
                mod = ".".join(stem + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            # `from pkg import submodule` imports the submodule (and not the rest of the package)
            subs = [f"{mod}.{a.name}" for a in node.names if f"{mod}.{a.name}" in MODULES]
            targets = subs + ([mod] if len(subs) < len(node.names) else [])
        else:
            continue
        for t in targets:
            while t and t not in MODULES:        # `import a.b.c` -> the longest known module
                t = t.rpartition(".")[0]
            if t and t.split(".")[0] in PACKAGES and t != name:
                found.add(t)
    return frozenset(found)


def _layer(mod: str) -> str | None:
    parts = mod.split(".")
    if parts[0] != "analysis" or len(parts) < 2:
        return None
    return parts[1]


def _violation(src: str, dst: str) -> str | None:
    top_s, top_d = src.split(".")[0], dst.split(".")[0]
    if top_s == "analysis":
        if top_d == "schemes" and _layer(src) not in ("cli", "api"):
            return "the engine does not import the catalogue (only analysis.cli and analysis.api do)"
        if top_d == "papers" and _layer(src) != "cli":
            return "the engine does not import the papers (only analysis.cli does)"
        ls, ld = _layer(src), _layer(dst)
        if ls is None or ld is None or top_d != "analysis":
            return None
        if ld not in LAYERS or ls not in LAYERS:
            return f"unknown layer {ld if ld not in LAYERS else ls}: add it to LAYERS"
        if LAYERS[ld] > LAYERS[ls]:
            return f"layer {ls} imports the higher layer {ld}"
        if LAYERS[ld] == LAYERS[ls] and ld != ls and not {ls, ld} <= BASE:
            return f"siblings {ls} and {ld} import each other"
        return None
    if top_s == "schemes":
        if top_d == "papers":
            return "the catalogue does not import the papers"
        ld = _layer(dst)
        if ld is not None and LAYERS.get(ld, 99) > LAYERS["levels"]:
            return f"the catalogue imports the layer {ld} (at most levels)"
        return None
    if top_s == "papers" and _layer(dst) == "cli":
        return "a paper does not import the command line"
    return None


@functools.lru_cache(maxsize=None)
def _graph() -> dict[str, frozenset[str]]:
    """The module import graph: module -> the modules it imports."""
    return {m: _imports(m) for m in MODULES}


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_respect_the_layers(module):
    bad = [(dst, why) for dst in sorted(_imports(module)) if (why := _violation(module, dst))]
    assert not bad, "\n".join(f"{module} imports {dst}: {why}" for dst, why in bad)


def test_no_import_cycles():
    """Tarjan's strongly connected components of the module import graph (packages importing
    their own submodules in ``__init__`` are edges like any other)."""
    index, low, stack, on, sccs = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in _graph()[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                sccs.append(sorted(comp))

    for v in sorted(_graph()):
        if v not in index:
            visit(v)
    # a package __init__ re-exporting its submodules, whose submodules import the package's
    # siblings through it, is not a cycle of code: drop edges submodule -> own package
    real = [c for c in sccs if not all(_package_edge_only(c))]
    assert not real, "import cycles: " + "; ".join(" <-> ".join(c) for c in real)


def _package_edge_only(comp):
    for m in comp:
        for w in _graph()[m]:
            if w in comp and not (m.startswith(w + ".") or w.startswith(m + ".")):
                yield False
                return
    yield True


@pytest.mark.parametrize("module", sorted(MODULES))
def test_modules_are_small(module):
    f, _ = MODULES[module]
    n = len(f.read_text(encoding="utf-8").splitlines())
    assert n <= MAX_LINES, f"{f.relative_to(ROOT)} has {n} lines (at most about 700: split it by job)"


def test_every_layer_package_says_what_it_may_import():
    for layer in LAYERS:
        init = ROOT / "analysis" / layer / "__init__.py"
        if init.exists():
            doc = ast.get_docstring(ast.parse(init.read_text(encoding="utf-8"))) or ""
            assert "import" in doc.lower() and len(doc) > 80, f"analysis/{layer}/__init__.py: say what lives here and what it may import"
