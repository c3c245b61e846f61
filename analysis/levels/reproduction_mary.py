"""Exponential generation and reproduction of level-dependent m-ary schemes (issue 12, second round).

A level-dependent m-ary scheme (:class:`~analysis.levels.mary.LevelDependentMary`, ``h = m^-n``)
*generates* ``e^{lambda x}`` at every level when ``S_{a^n}`` maps the samples ``e^{lambda j h}`` to
multiples of ``e^{lambda i h/m}``, and *reproduces* it (with the parametrisation
``t^n_i = (i + tau/(m-1)) m^-n``, ``tau = a'(1)/m`` of the limit symbol, Conti–Hormann 2011) when the
multiple is exactly the sample at level ``n+1``.

Examples
--------
>>> import sympy as sp
>>> from analysis.levels.mary import ternary_exponential_bspline_2
>>> s = ternary_exponential_bspline_2()
>>> t = s.params[0]
>>> generation_mary(s, [0, sp.I * t, -sp.I * t]).status          # 1, cos(theta x), sin(theta x)
'certified'
>>> r = generation_mary(s, [t], {"theta": 1})                       # not e^(theta x)
>>> r.status, r.witness["counterexample"]["n"]
('refuted', 0)

Algorithm
---------
Write ``i = m k + r`` and ``w = e^{-lambda h/m}``. Then ``(S_{a^n} e^{lambda . h})_i = e^{lambda k h}
sum_l a^n_{r+ml} e^{-lambda l h}``, which is ``c e^{lambda i h/m}`` for all ``i`` iff the m sub-symbols
``A_r(w) = sum_l a^n_{r+ml} w^{r+ml}`` are equal (to ``c``), i.e. iff ``a^n(eps^j w) = 0`` for the m-th roots of
unity ``eps^j != 1`` (for ``m = 2``: ``a^n(-e^{-lambda h/2}) = 0``, the binary condition of
:func:`analysis.levels.reproduction.generation`). With the data ``e^{lambda (j+sigma) h}`` the same computation
gives reproduction iff moreover ``A_r(w) = w^{sigma (m-1)}`` for every r, i.e. ``a^n(w) = m w^tau`` with
``tau = sigma (m-1)``; letting ``lambda -> 0`` gives ``tau = a'(1)/m`` (the polynomial-reproduction shift).
The conditions ``A_r(w) - A_0(w) = 0`` (and ``A_0(w) - w^tau = 0``) are proven as exact identities in ``h``
and the parameters (sympy simplification; no roots of unity are needed in this form) or refuted by a
certified nonzero ball value (Arb, ``h = m^-n`` at levels ``n = 0..3``, parameters at the given values
or at points of the given box). The exact/box reading of the values and the search for a certified nonzero
value are those of :mod:`analysis.levels.reproduction` with ``arity = m`` (one implementation for every arity);
this module adds the m sub-symbols and the m-ary statements.

References
----------
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*, J. Approx.
Theory 163 (2011) 413-437 (the m-ary parametrisation ``tau/(m-1)``).
C. Conti, L. Romani, *Algebraic conditions on non-stationary subdivision symbols for exponential
polynomial reproduction*, J. Comput. Appl. Math. 236 (2011) 543-556 (the binary conditions).
"""

from __future__ import annotations

from typing import Any, Mapping, Sequence

import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, REFUTED, AnalysisError, Result
from .bounds import _exact_zero
from .level_dependent import H
from .mary import LevelDependentMary
from .reproduction import _certify_nonzero_in, _prepare as _prepare_binary
from ..algebra.reader import as_expr

__all__ = ["generation_mary", "reproduction_mary", "sub_symbols_mary"]


def sub_symbols_mary(s: LevelDependentMary, w: sp.Expr) -> list[sp.Expr]:
    """``A_r(w) = sum_l a^n_{r+ml} w^{r+ml}`` for ``r = 0..m-1`` (expressions in ``h`` and the parameters).

    >>> from analysis.levels.mary import level_scheme_mary
    >>> [sp.factor(x) for x in sub_symbols_mary(level_scheme_mary("(1+z+z**2)**2/(3*z**2)", 3), sp.Integer(1))]
    [1, 1, 1]
    """
    m = s.arity
    out = [sp.Integer(0)] * m
    for k, c in enumerate(s.mask):
        e = s.start + k
        out[e % m] += c * w ** e
    return out


def _prepare(s: LevelDependentMary, values):
    """:func:`analysis.levels.reproduction._prepare` on the scheme of ``s`` (the arity kept)."""
    if not isinstance(s, LevelDependentMary):
        raise AnalysisError("generation_mary/reproduction_mary need a LevelDependentMary (level_scheme_mary)")
    sc, rep, boxes = _prepare_binary(s.scheme, values)
    return LevelDependentMary(sc, s.arity), rep, boxes


def _certify_nonzero(expr: sp.Expr, s: LevelDependentMary, boxes: dict, depth: int) -> dict | None:
    """A level ``n`` (``h = m^-n``) and a parameter point (of the box, if any) where Arb proves ``expr != 0``
    (:func:`analysis.levels.reproduction._certify_nonzero_in` with ``arity = m``)."""
    return _certify_nonzero_in(expr, s.scheme, boxes, depth, arity=s.arity)


def generation_mary(s: LevelDependentMary, lambdas: Sequence, values: Mapping[str, Any] | None = None, *,
                    depth: int = 2) -> Result:
    """Certify that every level ``S_{a^n}`` (arity m) generates ``e^{lambda x}`` for each lambda (module docstring).

    ``values``: exact values or closed boxes ``(lo, hi)``; certified on a box means the identity is exact in the
    boxed parameters; a counterexample is a point of the box (midpoints of bisections up to ``depth``).
    """
    s, rep, boxes = _prepare(s, values)
    m = s.arity
    out = {}
    for lam in lambdas:
        lam = as_expr(lam).subs(rep)
        A = sub_symbols_mary(s, sp.exp(-lam * H / m))
        for r in range(1, m):
            e = A[r] - A[0]
            if _exact_zero(e):
                continue
            stmt = f"A_{r}(w) != A_0(w) at w = exp(-({lam}) h/{m}), i.e. a^n(eps^j w) != 0 for some j"
            w = _certify_nonzero(e, s, boxes, depth)
            if w:
                return Result(value=False, status=REFUTED, witness={"lambda": lam, "statement": stmt,
                                                                    "residue": r, "counterexample": w},
                              provenance={"method": "acb ball evaluation", "arity": m})
            return Result(value=None, status=INCONCLUSIVE, witness={"lambda": lam, "statement": stmt, "residue": r},
                          provenance={"method": "no exact zero proof, no certified nonzero value", "arity": m})
        out[sp.sstr(lam)] = f"A_0 = ... = A_{m - 1} at w = exp(-lambda h/{m}) identically"
    wit: dict[str, Any] = {"generated": [sp.sstr(as_expr(x)) for x in lambdas], "conditions": out, "arity": m}
    if boxes:
        wit["box"] = {k: tuple(v) for k, v in boxes.items()}
    return Result(value=True, status=CERTIFIED, witness=wit,
                  provenance={"method": f"exact: a^n(eps^j exp(-lambda h/{m})) == 0, j = 1..{m - 1}, for all h = "
                                        f"{m}^-n and all parameters (sympy)", "arity": m})


def reproduction_mary(s: LevelDependentMary, lambdas: Sequence, values: Mapping[str, Any] | None = None, *,
                      depth: int = 2) -> Result:
    """Certify reproduction: generation and ``a^n(w) = m w^tau``, ``w = e^{-lambda h/m}``, ``tau = a'(1)/m``.

    >>> from analysis.levels.mary import ternary_exponential_bspline_2
    >>> r = reproduction_mary(ternary_exponential_bspline_2(), [0])          # reproduces constants
    >>> r.status, r.witness["tau"]
    ('certified', 0)
    """
    g = generation_mary(s, lambdas, values, depth=depth)
    if g.status != CERTIFIED:
        return g
    s, rep, boxes = _prepare(s, values)
    m = s.arity
    a = s.limit()
    tau = sp.simplify(sum(c * (a.start + k) for k, c in enumerate(a.mask)) / m)
    for lam in lambdas:
        lam = as_expr(lam).subs(rep)
        w = sp.exp(-lam * H / m)
        e = sub_symbols_mary(s, w)[0] - w ** tau
        if not _exact_zero(e):
            cx = _certify_nonzero(e, s, boxes, depth)
            return Result(value=False if cx else None, status=REFUTED if cx else INCONCLUSIVE,
                          witness={"generation": True, "lambda": lam, "tau": tau,
                                   "statement": f"a^n(exp(-({lam}) h/{m})) != {m} exp(-({lam}) tau h/{m})",
                                   "counterexample": cx},
                          provenance={"method": "exact identity test + acb ball evaluation", "arity": m})
    wit: dict[str, Any] = {"tau": tau, "lambdas": list(lambdas), "arity": m,
                           "parametrisation": f"t_i^n = (i + tau/{m - 1}) {m}^-n"}
    if boxes:
        wit["box"] = {k: tuple(v) for k, v in boxes.items()}
    return Result(value=True, status=CERTIFIED, witness=wit,
                  provenance={"method": "exact generalized m-ary sum rules at every level and parameter (sympy)",
                              "arity": m})
