"""Level-dependent m-ary catalogue: m-ary exponential B-spline schemes (ternary and quaternary, degrees 1-3,
trigonometric and hyperbolic), as :class:`~analysis.levels.mary.LevelDependentMary` (``h = m^-n``).

Derivation (derived here; the `search` corpora hold no m-ary exponential B-spline paper of Conti–Romani or
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
>>> s = get_mary("ternary-exp-bspline-2-trig")
>>> s.arity, s.limit().expr().factor()
(3, (z**2 + z + 1)**3/(9*z**3))
>>> sorted(MARY_ENTRIES)[:2]
['quaternary-exp-bspline-1-hyp', 'quaternary-exp-bspline-1-trig']

References
----------
M. Unser, T. Blu, *Cardinal exponential splines: part I — theory and filtering algorithms*, IEEE Trans. Signal
Process. 53 (2005) 1425-1438.
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*, J. Approx.
Theory 163 (2011) 413-437 (the m-ary conventions).
"""

from __future__ import annotations

import sympy as sp

from analysis.levels.level_dependent import H, LevelDependentScheme
from analysis.levels.mary import LevelDependentMary
from analysis.result import AnalysisError

from .level_dependent import LazyEntries, lookup

#: the frequency / tension parameter (as in :mod:`schemes.level_dependent`)
T = sp.Symbol("t", positive=True)
_Z = sp.Symbol("z")
_NAMES = {3: "ternary", 4: "quaternary"}
_KINDS = {"trig": (sp.cos, "trigonometric", "+-i t"), "hyp": (sp.cosh, "hyperbolic", "+-t")}


def pair_factor(m: int, kind: str) -> sp.Expr:
    """``prod_{+-lambda} (1 + v z + ... + v^{m-1} z^{m-1})`` written with ``cos``/``cosh`` of ``t h/m``.

    >>> pair_factor(3, "trig")
    z**4 + 2*z**3*cos(h*t/3) + z**2*(2*cos(2*h*t/3) + 1) + 2*z*cos(h*t/3) + 1
    """
    f = _KINDS[kind][0]
    tau = T * H / m
    out = 0
    for j in range(2 * m - 1):
        c = sum(f((2 * k - j) * tau) for k in range(max(0, j - m + 1), min(j, m - 1) + 1))
        out += sp.expand(c) * _Z ** j
    return out


def exponential_bspline_mary(m: int, d: int, kind: str) -> LevelDependentMary:
    """The m-ary exponential B-spline scheme of degree ``d`` (frequencies ``0`` (d-1 times), ``+-i t`` or ``+-t``)."""
    if m not in _NAMES or d not in (1, 2, 3) or kind not in _KINDS:
        raise AnalysisError(f"no m-ary exponential B-spline entry for m = {m}, degree {d}, kind {kind!r}")
    box = sum(_Z ** i for i in range(m))
    P = pair_factor(m, kind)
    s = (d + 1) * (m - 1) // 2
    num = sp.expand(box ** (d - 1) * P)
    den = sp.Integer(m) ** (d - 2) * P.subs(_Z, 1)
    coeffs = [sp.factor(num.coeff(_Z, i) / den) for i in range((d + 1) * (m - 1) + 1)]
    name = _NAMES[m]
    return LevelDependentMary(LevelDependentScheme(
        tuple(coeffs), -s, (T,), slug=f"{name}-exp-bspline-{d}-{kind}",
        title=f"{name} {_KINDS[kind][1]} exponential B-spline of degree {d} (frequencies 0 x {d - 1}, "
              f"{_KINDS[kind][2]})",
        source="derived here (module docstring of schemes.level_mary)",
        notes=f"v = exp(lambda {m}^-(n+1))", defaults={"t": 1}), m)


MARY_ENTRIES = LazyEntries({f"{_NAMES[m]}-exp-bspline-{d}-{k}": (lambda m=m, d=d, k=k: exponential_bspline_mary(m, d, k))
                            for m in (3, 4) for d in (1, 2, 3) for k in ("trig", "hyp")})


def get_mary(slug: str) -> LevelDependentMary:
    """The level-dependent m-ary catalogue entry ``slug`` (one-line AnalysisError when unknown)."""
    return lookup(MARY_ENTRIES, slug, "level-dependent m-ary scheme")
