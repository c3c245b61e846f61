"""Route 4 of :mod:`.ck_box` on a parameter box: "not C^d at every point" of an exponential B-spline scheme.

:func:`not_ck_box` recognises the exponential B-spline form *identically in the parameters*
(:func:`analysis.levels.expbspline.recognise` on the parametric scheme, any arity m), proves the
frequencies closed under conjugation on the whole box (:func:`conjugation_closed_box`: the mask is real
there) and certifies the normalisers non-zero at every level and every parameter value of the box
(:func:`normalisers_nonzero_box`, the box version of ``expbspline._normalisers_nonzero``): binary
``1 + exp(lambda 2^-(n+1))``, arity m ``q_m(exp(lambda m^-(n+1)))``, ``q_m(x) = 1 + x + ... + x^(m-1)``.

Examples
--------
>>> t = sp.Symbol("t", positive=True)
>>> normalisers_nonzero_box([sp.I * t], {"t": (1, 2)}, arity=3).status
'certified'

Algorithm
---------
Complex Arb enclosures of ``lambda`` over the box; ``q_m(e^mu) = 0`` needs ``Re mu = 0`` and
``|mu| >= 2 pi/m``, so only the finitely many levels with ``sup |lambda| m^-(n+1) >= 2 pi/m`` are enclosed
directly; a box where an enclosure contains 0 is bisected (``depth`` times at most).

References
----------
M. Unser, T. Blu, *Cardinal exponential splines: part I*, IEEE Trans. Signal Process. 53 (2005)
1425-1438 (exponential B-splines: the "not C^d").
C. Conti, L. Romani, *On the reproduction properties of non-stationary subdivision schemes*,
arXiv:1004.1297 (2010).
M. Charina, C. Conti, L. Romani, *Reproduction of exponential polynomials by multivariate
non-stationary subdivision schemes with a general dilation matrix*, arXiv:1303.1678 (2013) (dilation m).
"""

from __future__ import annotations

from typing import Any, Mapping

import flint
import sympy as sp

from .balls import _ball, _to_ball, workprec
from .divided import q_label
from .expbspline import recognise
from .level_dependent import LevelDependentScheme
from .region import _describe
from .series import _bisect
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..algebra.reader import as_expr

__all__ = ["conjugation_closed_box", "exact_box", "normalisers_nonzero_box", "not_ck_box"]


def exact_box(box: Mapping) -> dict:
    """``{name: [lo, hi]}`` with exact ends (strings), for reports."""
    return {k: [sp.sstr(v[0]), sp.sstr(v[1])] if isinstance(v, tuple) else sp.sstr(v) for k, v in box.items()}


def normalisers_nonzero_box(lams, env: Mapping[str, Any], *, depth: int = 8, n_levels_max: int = 4096,
                            arity: int = 2) -> Result:
    """``1 + exp(lambda_i(p) 2^-(n+1)) != 0`` for every level ``n >= 0`` and every ``p`` in the box.

    ``arity`` m: ``q_m(v) = 1 + v + ... + v^(m-1) != 0``, ``v = exp(lambda_i(p) m^-(n+1))`` (``q_m(v) = 0`` iff
    ``v^m = 1 != v``: needs ``Re lambda = 0`` and ``|lambda| m^-(n+1) >= 2 pi/m``, as in
    :func:`analysis.levels.expbspline._normalisers_nonzero`).

    ``lams``: frequencies (sympy, may use the boxed parameters). A frequency is enclosed over the
    (sub-)box in complex ball arithmetic; for ``n >= n_0`` (``sup |lambda| 2^-(n_0+1) < pi``)
    ``1 + e^mu = 0`` would need ``|mu| >= pi``; the levels ``n < n_0`` are enclosed directly, the
    box bisected (at most ``depth`` times) where an enclosure contains 0.

    >>> t = sp.Symbol("t", positive=True)
    >>> normalisers_nonzero_box([sp.I * t, -sp.I * t], {"t": (sp.Rational(1, 10), 3)}).status
    'certified'
    >>> r = normalisers_nonzero_box([sp.I * t], {"t": (6, 7)})     # t = 2 pi: 1 + e^(i pi) = 0 at n = 0
    >>> r.status, "(level n = 0;" in r.witness["reason"]
    ('inconclusive', True)
    >>> r = normalisers_nonzero_box([sp.I * t], {"t": (6, 7)}, arity=3)   # 1 + v + v^2 = 0 at v = e^(2 pi i/3)
    >>> r.status, r.witness["reason"].split(" on ")[0]
    ('inconclusive', 'q(exp(I*t 3^-1)) not certified != 0')
    >>> normalisers_nonzero_box([sp.I * t], {"t": (3, 4)}, arity=4).status   # |t/4| < 2 pi/4: v^4 != 1
    'certified'
    """
    m = arity
    checked = []
    for lam in lams:
        lam = as_expr(lam)
        names = {x.name for x in lam.free_symbols}
        if not names <= set(env):
            raise AnalysisError(f"the frequency {sp.sstr(lam)} uses names without values: "
                                f"{', '.join(sorted(names - set(env)))}")
        todo = [({k: v for k, v in env.items() if k in names}, 0)]
        while todo:
            box, d = todo.pop()
            bad = _normaliser_bad_level(lam, box, n_levels_max, m)
            if bad is None:
                continue
            if d >= depth or not any(isinstance(v, tuple) for v in box.values()):
                return Result(value=None, status=INCONCLUSIVE,
                              witness={"reason": (f"1 + exp({sp.sstr(lam)} 2^-{bad + 1})" if m == 2 else
                                                  f"q(exp({sp.sstr(lam)} {m}^-{bad + 1}))")
                                                 + f" not certified != 0 on {_describe(box, None)} (level n = {bad}; the mask may be "
                                                 "undefined there)", "box": exact_box(box)})
            todo.extend((c, d + 1) for c in _bisect(box))
        checked.append(sp.sstr(lam))
    return Result(value=True, status=CERTIFIED,
                  witness={"statement": ("1 + exp(lambda_i 2^-(n+1))" if m == 2 else f"q(exp(lambda_i {m}^-(n+1)))")
                           + " != 0 for all n >= 0 at every point of the box", "checked": checked},
                  provenance={"method": "complex Arb enclosure over (bisected) boxes at the levels with "
                                        + ("sup|lambda| 2^-(n+1) >= pi; |mu| < pi excludes 1 + e^mu = 0" if m == 2 else
                                           f"sup|lambda| {m}^-(n+1) >= 2 pi/{m}; |mu| < 2 pi/{m} excludes "
                                           f"q(e^mu) = 0, q(x) = {q_label(m).replace('z', 'x')}")})


def _normaliser_bad_level(lam, box, n_levels_max: int, m: int = 2) -> int | None:
    """The first level where ``1 + exp(lambda 2^-(n+1))`` (``q_m(exp(lambda m^-(n+1)))``) is not enclosed
    away from 0 on the box, or None."""
    with workprec(128):
        envb = {k: _to_ball(v, True) for k, v in box.items()}
        b = _ball(lam, envb, True)
        if not b.is_finite():
            return 0
        if not b.real.contains(0):
            return None              # |exp(lambda h)| != 1 for every h > 0
        pi = flint.arb.pi()
        mag = abs(b)
        n0 = 0
        while not (mag / m ** (n0 + 1) < 2 * pi / m):
            n0 += 1
            if n0 > n_levels_max:
                return 0
        for n in range(n0):
            if not abs(sum(((k * b / m ** (n + 1)).exp() for k in range(1, m)), flint.acb(1))) > 0:
                return n
    return None


def conjugation_closed_box(lams, env: Mapping[str, Any]) -> Result:
    """The frequency multiset is closed under complex conjugation for every parameter value of the box
    (then the mask is real there): each ``conj(lambda_i)`` equals some ``lambda_j`` identically, with every
    boxed parameter declared positive (negative) when its box lies in ``[0, oo)`` (``(-oo, 0]``), real
    otherwise. Inconclusive when this is not proved (e.g. ``sqrt(t)`` on a box through 0: complex masks
    for ``t < 0``).

    >>> t = sp.Symbol("t", real=True)
    >>> conjugation_closed_box([0, sp.I * t, -sp.I * t], {"t": (sp.Rational(1, 10), 3)}).status
    'certified'
    >>> conjugation_closed_box([0, sp.sqrt(t)], {"t": (-1, 3)}).status
    'inconclusive'
    >>> conjugation_closed_box([0, sp.sqrt(t)], {"t": (0, 3)}).status
    'certified'
    """
    rep = {}
    for x in set().union(*(as_expr(lam).free_symbols for lam in lams)) if lams else ():
        v = env.get(x.name)
        lo, hi = (v if isinstance(v, tuple) else (v, v)) if v is not None else (None, None)
        if lo is not None and as_expr(lo) >= 0:
            rep[x] = sp.Symbol(x.name, positive=True) if as_expr(hi) > 0 else sp.Integer(0)
        elif hi is not None and as_expr(hi) <= 0:
            rep[x] = -sp.Symbol(x.name, positive=True) if as_expr(lo) < 0 else sp.Integer(0)
        else:
            rep[x] = sp.Symbol(x.name, real=True)
    left = [as_expr(lam).xreplace(rep) for lam in lams]
    for lam in list(left):
        if lam not in left:
            continue
        c = sp.simplify(sp.conjugate(lam))
        match = next((i for i, mu in enumerate(left) if sp.simplify(mu - c) == 0), None)
        if match is None:
            return Result(value=None, status=INCONCLUSIVE,
                          witness={"reason": f"conj({sp.sstr(lam)}) is not among the frequencies for every parameter "
                                             "value of the box (the mask may be complex there)"})
        left.pop(match)
        if sp.simplify(lam - c) != 0:
            left.remove(lam)
    return Result(value=True, status=CERTIFIED, witness={"frequencies": [sp.sstr(x) for x in lams]})


def not_ck_box(s: LevelDependentScheme, env: Mapping[str, Any], *, depth: int = 8, arity: int = 2) -> Result:
    """Certified "not C^d at every point of the box" for an exponential B-spline scheme of order ``d+1``.

    The form is recognised identically in n and in the parameters; the normalisers are certified
    non-zero on the box (:func:`normalisers_nonzero_box`). Otherwise inconclusive naming the failure.
    ``arity`` m: the m-ary form (``h = m^-n``, :func:`analysis.levels.expbspline.recognise`), same theorem.
    """
    rec = recognise(s, arity)
    hyps = {"exponential_bspline_form": rec}
    prov = {"method": "exact recognition (identically in the parameters) + normalisers on the box"}
    if rec.value is None:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"k": None, "failed": ["exponential_bspline_form"], "reason": rec.witness["reason"],
                               "hypotheses": hyps}, provenance=prov)
    d = rec.witness["order"] - 1
    conj = conjugation_closed_box(rec.value, env)
    hyps["conjugation_closed"] = conj
    if not conj.is_certified:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"k": d, "failed": ["conjugation_closed"], "reason": conj.witness["reason"],
                               "hypotheses": hyps}, provenance=prov)
    norm = normalisers_nonzero_box(rec.value, env, depth=depth, arity=arity)
    hyps["normalisers_nonzero"] = norm
    if not (norm.is_certified and norm.value is True):
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"k": d, "failed": ["normalisers_nonzero"], "reason": norm.witness.get("reason"),
                               "hypotheses": hyps}, provenance=prov)
    freqs = ", ".join(rec.witness["frequencies"])
    return Result(value=False, status=CERTIFIED,
                  witness={"k": d, "order": d + 1, "frequencies": rec.value, "hypotheses": hyps,
                           "theorem": (f"exponential B-spline scheme of order {d + 1} (frequencies {freqs}) at every "
                                       "point of the box: its basic limit function is a non-zero multiple of "
                                       f"B_Lambda, C^{d - 1} and not C^{d} (Unser-Blu 2005, Conti-Romani 2010)"
                                       + ("" if arity == 2 else f"; dilation {arity}: the same B_Lambda (refinement "
                                          "identity in analysis.levels.expbspline)"))},
                  provenance=prov)
