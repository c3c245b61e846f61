"""Level-dependent schemes: exponential B-splines, and the registry of all level-dependent entries.

Exponential B-spline schemes (Dyn–Levin; Romani) generate ``{1, e^{tx}, e^{-tx}}`` (``v > 1``) or
``{1, cos tx, sin tx}`` (``t -> i t``, ``v < 1``), with ``v_n = cosh(t/2^{n+1})`` resp.
``cos(t/2^{n+1})``:

* degree 2 (Chaikin-like): ``a^n(z) = (1+z)(1 + 2 v_n z + z^2) / (2 (1 + v_n)) z^-2``,
* degree 3 (cubic):       ``a^n(z) = (1+z)^2 (1 + 2 v_n z + z^2) / (4 (1 + v_n)) z^-2``,
* degree d (2..5):        ``a^n(z) = (1+z)^(d-1) (1 + 2 v_n z + z^2) / (2^(d-1) (1 + v_n)) z^-s``
  (``exp-quartic-*``: d = 4, s = 2; ``exp-quintic-*``: d = 5, s = 3).

The limits are the polynomial B-spline schemes ``(1+z)^(d+1) / 2^d``. The exponential B-spline of
degree d (order d + 1, frequencies ``0`` (d - 1 times) and ``+-t`` resp. ``+-i t``) is C^(d-1) and
not C^d (Unser–Blu 2005), like the polynomial one.

Examples
--------
>>> e = get("exp-chaikin-trig")
>>> e.limit()
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
>>> sorted(names())[:3]
['exp-chaikin-hyp', 'exp-chaikin-trig', 'exp-cubic-hyp']

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*, J. Math.
Anal. Appl. 193 (1995) 594-621.
M. Unser, T. Blu, *Cardinal exponential splines: part I — theory and filtering algorithms*,
IEEE Trans. Signal Process. 53 (2005) 1425-1438.
L. Romani, *From approximating subdivision schemes for exponential splines to high-performance
interpolating algorithms*, J. Comput. Appl. Math. 224 (2009) 383-396.
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping

import sympy as sp

from analysis.levels.level_dependent import H, LevelDependentScheme
from analysis.result import AnalysisError

from .catalogue import LazyEntries  # noqa: F401  (the catalogue's lazy mapping; imported from here too)

#: the frequency / tension parameter
T = sp.Symbol("t", positive=True)
_Z = sp.Symbol("z")


def _from_symbol(expr, slug, title, v, shift=2) -> LevelDependentScheme:
    num = sp.Poly(sp.expand(expr * _Z ** shift), _Z)
    coeffs = [sp.simplify(c) for c in reversed(num.all_coeffs())]
    return LevelDependentScheme(tuple(coeffs), -shift, (T,), slug=slug, title=title,
                                source="exponential B-spline (Dyn-Levin 1995; Romani 2009)",
                                notes=f"v_n = {v.subs(H, 2 ** -sp.Symbol('n'))}",
                                defaults={"t": 1})


def _chaikin(v):
    return (1 + _Z) * (1 + 2 * v * _Z + _Z ** 2) / (2 * (1 + v)) / _Z ** 2


def _cubic(v):
    return (1 + _Z) ** 2 * (1 + 2 * v * _Z + _Z ** 2) / (4 * (1 + v)) / _Z ** 2


def _degree(d, v):
    return (1 + _Z) ** (d - 1) * (1 + 2 * v * _Z + _Z ** 2) / (2 ** (d - 1) * (1 + v)) / _Z ** (d // 2 + 1)


_VH = sp.cosh(T * H / 2)
_VT = sp.cos(T * H / 2)

_KINDS = {"hyp": (_VH, "hyperbolic"), "trig": (_VT, "trigonometric")}
_SHAPES = {"chaikin": (_chaikin, "Chaikin", 2), "cubic": (_cubic, "cubic B-spline", 2),
           "quartic": (lambda v: _degree(4, v), "quartic B-spline", 3),
           "quintic": (lambda v: _degree(5, v), "quintic B-spline", 3)}

ENTRIES = LazyEntries({
    f"exp-{shape}-{kind}": (lambda f=f, v=v, shape=shape, kind=kind, t=t, w=w, s=s:
                            _from_symbol(f(v), f"exp-{shape}-{kind}", f"{w} exponential {t}", v, s))
    for shape, (f, t, s) in _SHAPES.items() for kind, (v, w) in _KINDS.items()})


def _registry() -> Mapping[str, LevelDependentScheme]:
    from . import seed003

    return LazyEntries({**{k: (lambda k=k: ENTRIES[k]) for k in ENTRIES},
                        **{k: (lambda k=k: seed003.LEVEL_ENTRIES[k]) for k in seed003.LEVEL_ENTRIES}})


def names() -> list[str]:
    """Slugs of all level-dependent schemes (nothing is built)."""
    from . import seed003

    return [*ENTRIES, *seed003.LEVEL_ENTRIES]


def get(slug: str) -> LevelDependentScheme:
    """The level-dependent scheme named ``slug`` (one-line AnalysisError when unknown)."""
    return lookup(_registry(), slug, "level-dependent scheme")


def lookup(reg: dict, slug: str, what: str):
    """``reg[slug]`` (case and spaces ignored), or a one-line AnalysisError naming ``what`` and the close names."""
    key = str(slug).strip().lower()
    if key in reg:
        return reg[key]
    close = difflib.get_close_matches(key, list(reg), n=4, cutoff=0.5)
    hint = f"; did you mean: {', '.join(close)}?" if close else f"; known: {', '.join(reg)}"
    raise AnalysisError(f"unknown {what} {slug!r}{hint}")
