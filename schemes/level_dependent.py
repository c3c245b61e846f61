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

Arity m = 3, 4 (:data:`ARITY_ENTRIES`: ternary and quaternary exponential B-spline schemes, degrees 1-3,
trigonometric and hyperbolic; ``LevelDependentScheme(..., arity=m)``, ``h = m^-n``). Derivation (derived here; the `search` corpora hold no m-ary exponential B-spline paper of Conti–Romani or
others to cite). ``e^{lambda x} chi_[0,1)(x) = sum_{k<m} e^{lambda k tau} (e^{lambda .} chi_[0,tau))(x - k tau)``
with ``tau = m^-(n+1)``: the exponential box of frequency ``lambda`` has the m-ary mask
``1 + v z + ... + v^{m-1} z^{m-1}``, ``v = e^{lambda tau}``; the exponential B-spline is the convolution of the
boxes, so its level-n symbol is

    a^n(z) = m z^s prod_i (1 + v_i z + ... + v_i^{m-1} z^{m-1}) / (1 + v_i + ... + v_i^{m-1}),

normalised by ``a^n(1) = m``. Degree ``d`` (order ``d + 1``): the frequencies ``0`` (``d - 1`` times) and
``+-i t`` (trigonometric) or ``+-t`` (hyperbolic). The product of the two factors of ``+-lambda`` is real:
``sum_j c_j z^j``, ``c_j = sum_k cosh((2k - j) lambda tau)`` over ``max(0, j-m+1) <= k <= min(j, m-1)``
(``cos`` for ``lambda = i t``). The shift is ``s = -floor((d+1)(m-1)/2)``. The limit (``h -> 0``) is the m-ary
polynomial B-spline of degree d, ``m z^s ((1+...+z^{m-1})/m)^{d+1}``. The exponential B-spline of degree d is
C^{d-1} and not C^d (Unser–Blu 2005), for every dilation.

Examples
--------
>>> e = get("exp-chaikin-trig")
>>> e.limit()
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
>>> sorted(names())[:3]
['exp-chaikin-hyp', 'exp-chaikin-trig', 'exp-cubic-hyp']
>>> s = get("ternary-exp-bspline-2-trig")
>>> s.arity, s.limit().expr().factor()
(3, (z**2 + z + 1)**3/(9*z**3))

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*, J. Math.
Anal. Appl. 193 (1995) 594-621.
M. Unser, T. Blu, *Cardinal exponential splines: part I — theory and filtering algorithms*,
IEEE Trans. Signal Process. 53 (2005) 1425-1438.
L. Romani, *From approximating subdivision schemes for exponential splines to high-performance
interpolating algorithms*, J. Comput. Appl. Math. 224 (2009) 383-396.
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*, J. Approx.
Theory 163 (2011) 413-437 (the m-ary conventions).
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


def _once(f, xs) -> list:
    """``[f(x) for x in xs]`` with ``f`` applied once per distinct ``x`` (the masks are symmetric: each
    coefficient appears twice, and ``simplify``/``factor`` take a large part of building an entry)."""
    done: dict = {}
    for x in xs:
        if x not in done:
            done[x] = f(x)
    return [done[x] for x in xs]


def _from_symbol(expr, slug, title, v, shift=2) -> LevelDependentScheme:
    num = sp.Poly(sp.expand(expr * _Z ** shift), _Z)
    coeffs = _once(sp.simplify, list(reversed(num.all_coeffs())))
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


_NAMES = {3: "ternary", 4: "quaternary"}
_ARITY_KINDS = {"trig": (sp.cos, "trigonometric", "+-i t"), "hyp": (sp.cosh, "hyperbolic", "+-t")}


def pair_factor(m: int, kind: str) -> sp.Expr:
    """``prod_{+-lambda} (1 + v z + ... + v^{m-1} z^{m-1})`` written with ``cos``/``cosh`` of ``t h/m``.

    >>> pair_factor(3, "trig")
    z**4 + 2*z**3*cos(h*t/3) + z**2*(2*cos(2*h*t/3) + 1) + 2*z*cos(h*t/3) + 1
    """
    f = _ARITY_KINDS[kind][0]
    tau = T * H / m
    out = 0
    for j in range(2 * m - 1):
        c = sum(f((2 * k - j) * tau) for k in range(max(0, j - m + 1), min(j, m - 1) + 1))
        out += sp.expand(c) * _Z ** j
    return out


def exponential_bspline(m: int, d: int, kind: str) -> LevelDependentScheme:
    """The exponential B-spline scheme of arity ``m`` in (3, 4) and degree ``d`` (frequencies ``0`` (d-1 times),
    ``+-i t`` or ``+-t``; module docstring)."""
    if m not in _NAMES or d not in (1, 2, 3) or kind not in _ARITY_KINDS:
        raise AnalysisError(f"no m-ary exponential B-spline entry for m = {m}, degree {d}, kind {kind!r}")
    box = sum(_Z ** i for i in range(m))
    P = pair_factor(m, kind)
    s = (d + 1) * (m - 1) // 2
    num = sp.expand(box ** (d - 1) * P)
    den = sp.Integer(m) ** (d - 2) * P.subs(_Z, 1)
    coeffs = _once(sp.factor, [num.coeff(_Z, i) / den for i in range((d + 1) * (m - 1) + 1)])
    name = _NAMES[m]
    return LevelDependentScheme(
        tuple(coeffs), -s, (T,), slug=f"{name}-exp-bspline-{d}-{kind}",
        title=f"{name} {_ARITY_KINDS[kind][1]} exponential B-spline of degree {d} (frequencies 0 x {d - 1}, "
              f"{_ARITY_KINDS[kind][2]})",
        source="derived here (module docstring of schemes.level_dependent)",
        notes=f"v = exp(lambda {m}^-(n+1))", defaults={"t": 1}, arity=m)


#: the level-dependent entries of arity m > 2 (found by :func:`get`; :func:`names` lists the binary ones)
ARITY_ENTRIES = LazyEntries({f"{_NAMES[m]}-exp-bspline-{d}-{k}": (lambda m=m, d=d, k=k: exponential_bspline(m, d, k))
                            for m in (3, 4) for d in (1, 2, 3) for k in ("trig", "hyp")})


def _registry() -> Mapping[str, LevelDependentScheme]:
    from . import seed003

    return LazyEntries({**{k: (lambda k=k: ENTRIES[k]) for k in ENTRIES},
                        **{k: (lambda k=k: seed003.LEVEL_ENTRIES[k]) for k in seed003.LEVEL_ENTRIES},
                        **{k: (lambda k=k: ARITY_ENTRIES[k]) for k in ARITY_ENTRIES}})


def names() -> list[str]:
    """Slugs of the binary level-dependent schemes (nothing is built; the others: :data:`ARITY_ENTRIES`)."""
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
