"""Masks from requirements: the exact general solution of the linear conditions on a mask.

A researcher designs a scheme by asking for an arity ``m``, a support, and properties —
interpolatory, primal or dual symmetry, sum rules, polynomial generation or reproduction,
reproduction of exponentials, some fixed coefficients. Every one of these is a set of *linear*
equations in the unknown coefficients ``a_i`` (``i`` in the support), so the family of masks
satisfying them is an affine space, computed here exactly: a parametrised
:class:`~analysis.algebra.symbol.LaurentSymbol` with free parameters ``t1, t2, ...`` (or names
the user gives) and its dimension. When no mask satisfies the requirements,
:class:`InconsistentRequirements` names an irreducible conflicting subset.

Convention: ``(S_a f)_i = sum_j a_{i-mj} f_j``; the sub-symbols are the residues ``i mod m``.

Examples
--------
The 4-point family with tension (Dyn–Levin–Gregory 1987): interpolatory, primal symmetric,
support 7, reproducing linears — one free parameter ``t1 = a_{-3} = -w``:

>>> r = derive_mask(support=7, interpolatory=True, symmetric="primal", reproduction=1)
>>> r.value.mask, r.witness["dimension"], r.status
((t1, 0, 1/2 - t1, 1, 1/2 - t1, 0, t1), 1, 'certified')

Cubic reproduction fixes it: the Dubuc–Deslauriers 4-point scheme (``w = 1/16``):

>>> derive_mask(support=7, interpolatory=True, symmetric="primal", reproduction=3).value.mask
(-1/16, 0, 9/16, 1, 9/16, 0, -1/16)

Conflicting requirements are named (an irreducible subset):

>>> derive_mask(support=5, interpolatory=True, sum_rules=3)
Traceback (most recent call last):
...
analysis.algebra.derive.InconsistentRequirements: no mask on the support [-2, 2] (arity 2) satisfies: interpolatory; sum rules of order 3

Algorithm
---------
The unknowns are ordered from the centre of the support outwards (outermost last) and the
augmented system is brought to reduced row echelon form over its exact domain (``QQ``, or an
algebraic/expression domain for exponentials) with :class:`sympy.polys.matrices.DomainMatrix`;
the non-pivot columns — the outermost coefficients — become the free parameters. Consistency is
the exact rank test ``rank [A | b] = rank A``. A conflict is reduced by the *deletion filter*
(Chinneck–Dravnieks 1991): drop each requirement in turn and keep it dropped when the rest is
still inconsistent; what remains is irreducible (removing any one makes it consistent).

Conditions for arity ``m`` (``a_i`` with ``i = r + m j``, residue ``r = 0..m-1``):

* polynomial generation of degree ``d`` (sum rules of order ``d + 1``; Dyn–Levin 2002 for
  ``m = 2``, Conti–Hormann 2011 for any ``m``): ``D^l a(eps^j) = 0`` for the ``m``-th roots of
  unity ``eps^j != 1``, ``l <= d``, and ``a(1) = m``. By the discrete Fourier transform over the
  residues this is the rational system ``sum_{i = r mod m} a_i i^l`` independent of ``r``
  (``l = 1..d``) and ``sum_{i = r mod m} a_i = 1``;
* polynomial reproduction of degree ``d`` for the parametrisation ``t_i^n = (i + tau) / m^n``
  (Dyn–Hormann–Sabin–Shen 2008, Conti–Hormann 2011): ``sum_j a_{r+mj} (tau - j)^l = ((r + tau)/m)^l``
  for every ``r`` and ``l <= d``. The shift is ``tau = a'(1) / (m (m-1))``; symmetry about ``c/2``
  (``c = start + end``) forces ``tau = c / (2 (m-1))`` (0 primal, ``-1/2`` for a binary dual mask),
  which is the default (``tau`` may be given);
* reproduction of ``exp(lambda x)`` at level ``n`` (a level-dependent mask; Dyn–Levin–Luzzatto
  2003, Conti–Hormann 2011 Sect. 5): ``sum_j a_{r+mj} exp(lambda (tau - j)/m^n) = exp(lambda (r + tau)/m^(n+1))``;
* interpolatory: ``a_{mi} = delta_{i0}``; symmetric: ``a_i = a_{start+end-i}``.

References
----------
N. Dyn, K. Hormann, M. Sabin, Z. Shen, *Polynomial reproduction by symmetric subdivision
schemes*, J. Approx. Theory 155 (2008) 28-42.
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*,
J. Approx. Theory 163 (2011) 413-437.
N. Dyn, D. Levin, A. Luzzatto, *Exponentials reproducing subdivision schemes*, Found. Comput.
Math. 3 (2003) 187-206.
J. W. Chinneck, E. W. Dravnieks, *Locating minimal infeasible constraint sets in linear
programs*, ORSA J. Computing 3 (1991) 157-168.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from ..result import CERTIFIED, AnalysisError, Result
from .symbol import LaurentSymbol, parse_coefficient
from .reader import as_expr

__all__ = ["Requirement", "InconsistentRequirements", "requirements", "derive_mask", "max_sum_rules",
           "mask_string", "MAX_COEFFICIENTS"]

#: Larger supports are refused (the exact elimination is cubic in the number of coefficients).
MAX_COEFFICIENTS = 64


class InconsistentRequirements(AnalysisError):
    """No mask satisfies the requirements; ``conflict`` is an irreducible conflicting subset (names)."""

    def __init__(self, message: str, conflict: Sequence[str] = ()):
        super().__init__(message)
        self.conflict = tuple(conflict)


@dataclass(frozen=True)
class Requirement:
    """A named group of linear equations ``sum_i coeffs[i] a_i = rhs`` on the mask."""

    name: str
    rows: tuple  # of (dict index -> coefficient, rhs)


# --------------------------------------------------------------------------------------------
# the support and the requirements as linear equations
# --------------------------------------------------------------------------------------------

def _support(arity: int, support: int, start: int | None, symmetric: str | None) -> tuple[int, int]:
    if isinstance(arity, bool) or not isinstance(arity, int) or arity < 2:
        raise AnalysisError(f"the arity must be an integer >= 2, not {arity!r}")
    if isinstance(support, bool) or not isinstance(support, int) or support < 1:
        raise AnalysisError(f"the support must be a positive number of coefficients, not {support!r}")
    if support > MAX_COEFFICIENTS:
        raise AnalysisError(f"a support of {support} coefficients is too large to derive exactly "
                            f"(at most {MAX_COEFFICIENTS})")
    if symmetric not in (None, "primal", "dual", "any"):
        raise AnalysisError(f"symmetric must be 'primal', 'dual' or 'any', not {symmetric!r}")
    if start is None:
        if symmetric == "primal" and support % 2 == 0:
            raise AnalysisError(f"a primal symmetric mask has an odd number of coefficients, not {support}")
        if symmetric == "dual" and support % 2 == 1:
            raise AnalysisError(f"a dual symmetric mask has an even number of coefficients, not {support}")
        start = -(support // 2)          # centre 0 (odd length) or -1/2 (even length)
    return int(start), int(start) + support - 1


def _residue_classes(lo: int, hi: int, m: int) -> dict[int, list[int]]:
    out: dict[int, list[int]] = {r: [] for r in range(m)}
    for i in range(lo, hi + 1):
        out[i % m].append(i)
    return out


def _generation_rows(lo, hi, m, d) -> tuple:
    cls = _residue_classes(lo, hi, m)
    rows = [({i: 1 for i in cls[r]}, sp.Integer(1)) for r in range(m)]
    for l in range(1, d + 1):
        for r in range(1, m):
            row = {i: sp.Integer(i) ** l for i in cls[r]}
            for i in cls[0]:
                row[i] = row.get(i, 0) - sp.Integer(i) ** l
            rows.append((row, sp.Integer(0)))
    return tuple(rows)


def _reproduction_rows(lo, hi, m, d, tau) -> tuple:
    cls = _residue_classes(lo, hi, m)
    rows = []
    for l in range(d + 1):
        for r in range(m):
            row = {i: (tau - sp.Integer(i - r) / m) ** l for i in cls[r]}
            rows.append((row, ((r + tau) / m) ** l))
    return tuple(rows)


def _exponential_rows(lo, hi, m, lam, tau, level, base=None) -> tuple:
    """Rows for ``exp(lam x)``; with ``base = (lam0, u, D)`` every ``exp(lam0 q)`` is written ``u^(q D)``
    (``u = exp(lam0 / D)`` transcendental for a real ``lam0``, Lindemann), so the elimination is exact in ``QQ(u)``."""
    cls = _residue_classes(lo, hi, m)
    scale = sp.Integer(m) ** level

    def ex(x):
        if base is not None:
            lam0, u, D = base
            return u ** int(sp.Rational(x / lam0) * D)
        return sp.expand_complex(sp.exp(x))

    rows = []
    for r in range(m):
        row = {i: ex(lam * (tau - sp.Integer(i - r) / m) / scale) for i in cls[r]}
        rows.append((row, ex(lam * (r + tau) / (m * scale))))
    return tuple(rows)


#: ``u = exp(lambda_0 / D)`` in the exact elimination with real frequencies
_U = sp.Symbol("u_exp")


def _classify_frequencies(exponentials, m, level, tau):
    """``(lams, base)``: the frequencies and, for real ones, the common base ``(lam0, u, D)``."""
    lams = [parse_coefficient(lam, locals_={"I": sp.I, "pi": sp.pi}) for lam in exponentials]
    if not lams:
        return lams, None
    for lam in lams:
        if lam.free_symbols or lam == 0:
            raise AnalysisError(f"an exponential frequency must be a non-zero number, not {lam}")
    if all(lam.is_real for lam in lams):
        lam0 = lams[0]
        D = sp.Integer(sp.Rational(tau).q) * sp.Integer(m) ** (level + 1)
        for lam in lams:
            q = sp.nsimplify(lam / lam0)
            if not q.is_Rational:
                raise AnalysisError(f"real frequencies must be rational multiples of each other ({lam} / {lam0})")
            D = sp.ilcm(D, D * q.q)
        return lams, (lam0, _U, int(D))
    for lam in lams:
        q = sp.nsimplify(lam / (sp.I * sp.pi))
        if not q.is_Rational:
            raise AnalysisError(f"frequencies are all real, or all I*pi*(rational) (trigonometric), not {lam}")
        for k in range(2 * m ** (level + 1) * sp.Rational(tau).q * q.q + 1):
            v = sp.expand_complex(sp.exp(lam * sp.Rational(k, m ** (level + 1) * sp.Rational(tau).q)))
            if v.has(sp.cos, sp.sin, sp.exp):
                raise AnalysisError(f"exp({lam} x) gives values that are not radicals ({v}); not supported")
    return lams, None


def _index_of(name: str, lo: int, hi: int) -> int:
    text = name.strip().replace("a_", "a").replace("a[", "a").replace("]", "").replace("{", "").replace("}", "")
    if not text.startswith("a"):
        raise AnalysisError(f"fixed coefficients are named a<index> (a0, a-3, a_{{-3}}), not {name!r}")
    try:
        i = int(text[1:])
    except ValueError:
        raise AnalysisError(f"cannot read the index of the fixed coefficient {name!r}") from None
    if not lo <= i <= hi:
        raise AnalysisError(f"the fixed coefficient a{i} is outside the support [{lo}, {hi}]")
    return i


def requirements(arity: int = 2, support: int = 4, start: int | None = None, *, interpolatory: bool = False,
                 symmetric: str | None = None, sum_rules: int | None = None, generation: int | None = None,
                 reproduction: int | None = None, tau=None, exponentials: Sequence = (), level: int = 0,
                 fixed: Mapping | None = None) -> tuple:
    """The support ``(lo, hi)``, the shift ``tau``, the requirements as named linear groups and the
    exponential base ``(lambda_0, u, D)`` (``None`` without real frequencies).

    Arguments as in :func:`derive_mask`.

    >>> (lo, hi), tau, reqs, _ = requirements(support=4, symmetric="dual", reproduction=1)
    >>> (lo, hi), tau, [q.name for q in reqs]
    ((-2, 1), -1/2, ['symmetric (dual)', 'reproduction of degree 1 (tau = -1/2)'])
    """
    m = arity
    lo, hi = _support(m, support, start, symmetric)
    reqs: list[Requirement] = []
    if interpolatory:
        if not lo <= 0 <= hi:
            raise AnalysisError(f"an interpolatory mask needs a_0 = 1, but 0 is outside the support [{lo}, {hi}]")
        rows = tuple(({i: 1}, sp.Integer(1 if i == 0 else 0)) for i in range(lo, hi + 1) if i % m == 0)
        reqs.append(Requirement("interpolatory", rows))
    if symmetric is not None:
        c = lo + hi
        rows = tuple(({i: 1, c - i: -1}, sp.Integer(0)) for i in range(lo, hi + 1) if i < c - i)
        kind = "primal" if c % 2 == 0 else "dual"
        if symmetric in ("primal", "dual") and symmetric != kind:
            raise AnalysisError(f"the support [{lo}, {hi}] is symmetric about {sp.Rational(c, 2)}: "
                                f"a {kind} mask, not {symmetric}")
        reqs.append(Requirement(f"symmetric ({kind})", rows))
    for name, val in (("sum_rules", sum_rules), ("generation", generation), ("reproduction", reproduction)):
        if val is not None and (isinstance(val, bool) or not isinstance(val, int) or val < (1 if name == "sum_rules" else 0)):
            raise AnalysisError(f"{name.replace('_', ' ')} must be a non-negative integer (sum rules >= 1), not {val!r}")
    if sum_rules is not None:
        reqs.append(Requirement(f"sum rules of order {sum_rules}", _generation_rows(lo, hi, m, sum_rules - 1)))
    if generation is not None:
        reqs.append(Requirement(f"generation of degree {generation}", _generation_rows(lo, hi, m, generation)))
    if tau is None:
        tau = sp.Rational(lo + hi, 2 * (m - 1))
    else:
        tau = parse_coefficient(tau)
        if tau.free_symbols:
            raise AnalysisError(f"tau must be a number, not {tau}")
    if reproduction is not None:
        reqs.append(Requirement(f"reproduction of degree {reproduction} (tau = {tau})",
                                _reproduction_rows(lo, hi, m, reproduction, tau)))
    if isinstance(level, bool) or not isinstance(level, int) or level < 0:
        raise AnalysisError(f"the level must be a non-negative integer, not {level!r}")
    lams, base = _classify_frequencies(exponentials, m, level, tau)
    for lam in lams:
        reqs.append(Requirement(f"reproduction of exp({lam}*x) at level {level}",
                                _exponential_rows(lo, hi, m, lam, tau, level, base)))
    for key, val in (fixed or {}).items():
        i = _index_of(str(key), lo, hi)
        v = parse_coefficient(val)
        if v.free_symbols:
            raise AnalysisError(f"a fixed coefficient must be a number, not {v}")
        reqs.append(Requirement(f"fixed a{i} = {v}", (({i: 1}, v),)))
    return (lo, hi), tau, reqs, base


# --------------------------------------------------------------------------------------------
# exact elimination
# --------------------------------------------------------------------------------------------

def _unknown_order(lo: int, hi: int) -> list[int]:
    """From the centre outwards; the outermost (left) coefficient last, so it becomes ``t1``."""
    c2 = lo + hi
    return sorted(range(lo, hi + 1), key=lambda i: (abs(2 * i - c2), -i))


def _rref(rows: Sequence, order: Sequence[int]):
    n = len(order)
    col = {i: k for k, i in enumerate(order)}
    data = []
    for coeffs, rhs in rows:
        line = [sp.Integer(0)] * (n + 1)
        for i, v in coeffs.items():
            line[col[i]] += as_expr(v)
        line[n] = as_expr(rhs)
        data.append(line)
    if not data:
        return [], ()
    M = DomainMatrix.from_list_sympy(len(data), n + 1, data, extension=True)
    if M.domain.is_EX:
        raise AnalysisError("the requirement equations are not over an exact field (QQ, QQ<theta>, QQ(u))")
    R, pivots = M.to_field().rref()
    return R.to_Matrix(), tuple(pivots)


def _consistent(rows: Sequence, order: Sequence[int]) -> bool:
    _R, pivots = _rref(rows, order)
    return len(order) not in pivots


def _conflict(reqs: list[Requirement], order) -> list[Requirement]:
    """Deletion filter: an irreducible inconsistent subset of ``reqs`` (which is inconsistent)."""
    keep = list(reqs)
    for q in list(reqs):
        trial = [x for x in keep if x is not q]
        if not _consistent([row for x in trial for row in x.rows], order):
            keep = trial
    return keep


def derive_mask(arity: int = 2, support: int = 4, start: int | None = None, *, interpolatory: bool = False,
                symmetric: str | None = None, sum_rules: int | None = None, generation: int | None = None,
                reproduction: int | None = None, tau=None, exponentials: Sequence = (), level: int = 0,
                fixed: Mapping | None = None, names: Sequence[str] | None = None) -> Result:
    """The general mask of arity ``arity`` on ``support`` coefficients satisfying the requirements.

    ``start`` is the first index (default: centred, ``-(support // 2)``); ``symmetric`` is
    ``"primal"``, ``"dual"`` or ``"any"`` (about the centre of the support); ``sum_rules`` is an
    order ``k`` (``(1+z)^k``-type divisibility for ``m = 2``), ``generation``/``reproduction`` a
    polynomial degree, ``tau`` the reproduction shift (default ``(start+end)/(2(m-1))``),
    ``exponentials`` frequencies ``lambda`` (``"1"``, ``"I*pi/2"``) reproduced at ``level``,
    ``fixed`` a mapping ``{"a0": "1/2", ...}``, ``names`` the names of the free parameters.

    ``value`` is the parametrised :class:`LaurentSymbol` (``None`` when a coefficient is
    transcendental — real exponentials — then ``witness["coefficients"]`` has the exact
    expressions); ``witness`` has ``dimension``,
    ``parameters`` (names), ``free_coefficients`` (which ``a_i`` each parameter is), ``mask`` (a
    string for ``--mask``), ``start``, ``arity``, ``tau``, ``requirements`` and ``equations``.
    Status certified (exact elimination). Raises :class:`InconsistentRequirements` with an
    irreducible conflicting subset when no mask qualifies.

    >>> r = derive_mask(support=4, symmetric="dual", sum_rules=3)
    >>> r.value.mask, r.witness["parameters"]
    ((1/4, 3/4, 3/4, 1/4), ())
    """
    (lo, hi), tau_v, reqs, base = requirements(arity, support, start, interpolatory=interpolatory, symmetric=symmetric,
                                         sum_rules=sum_rules, generation=generation, reproduction=reproduction,
                                         tau=tau, exponentials=exponentials, level=level, fixed=fixed)
    order = _unknown_order(lo, hi)
    rows = [row for q in reqs for row in q.rows]
    R, pivots = _rref(rows, order)
    n = len(order)
    if n in pivots:
        conflict = _conflict(reqs, order)
        names_c = [q.name for q in conflict]
        raise InconsistentRequirements(
            f"no mask on the support [{lo}, {hi}] (arity {arity}) satisfies: " + "; ".join(names_c), names_c)
    free_cols = [k for k in range(n) if k not in pivots]
    free_cols.sort(key=lambda k: order[k])  # t1 = the leftmost free coefficient
    if names is not None:
        names = [str(x).strip() for x in names]
        if len(names) != len(free_cols):
            raise AnalysisError(f"the family has {len(free_cols)} free parameter(s), "
                                f"but {len(names)} name(s) were given")
        bad = [x for x in names if not x.isidentifier() or x in ("z", "I", "E", "pi", "oo")]
        if bad or len(set(names)) != len(names):
            raise AnalysisError(f"parameter names must be distinct identifiers (not z, I, E, pi): {names}")
    else:
        names = [f"t{j + 1}" for j in range(len(free_cols))]
    params = [sp.Symbol(x) for x in names]
    tsym = dict(zip(free_cols, params))
    values: dict[int, sp.Expr] = {}
    for k, t in tsym.items():
        values[order[k]] = t
    for r_idx, pc in enumerate(pivots):
        expr = R[r_idx, n] - sum((R[r_idx, k] * t for k, t in tsym.items()), sp.Integer(0))
        values[order[pc]] = sp.factor(expr) if base is not None else sp.expand(expr)
    for k in range(n):
        values.setdefault(order[k], sp.Integer(0))
    mask = [values[i] for i in range(lo, hi + 1)]
    if base is not None:   # u = exp(lambda_0 / D)
        mask = [sp.simplify(c.subs(base[1], sp.exp(base[0] / base[2]))) for c in mask]
    symbol = _make_symbol(mask, lo, params)
    witness = {"coefficients": tuple(mask), "dimension": len(params), "parameters": tuple(names),
               "free_coefficients": {x: f"a{order[k]}" for x, k in zip(names, free_cols)},
               "mask": mask_string(mask), "start": lo, "support": (lo, hi), "arity": arity, "tau": tau_v,
               "requirements": [q.name for q in reqs], "equations": len(rows), "rank": len(pivots)}
    return Result(value=symbol, status=CERTIFIED, witness=witness,
                  provenance={"method": "exact reduced row echelon form (DomainMatrix) of the linear "
                                        "requirement equations", "domain": str(_domain_name(rows, order))})


def _make_symbol(mask, lo, params):
    """The symbol, or ``None`` when a coefficient is transcendental (``exp`` of a real frequency)."""
    try:
        return LaurentSymbol.from_mask(mask, start=lo, params=params)
    except AnalysisError:
        return None


def _domain_name(rows, order) -> str:
    data = [as_expr(v) for coeffs, rhs in rows for v in (*coeffs.values(), rhs)]
    from sympy.polys.constructor import construct_domain

    return str(construct_domain(data, field=True, extension=True)[0]) if data else "QQ"


def mask_string(mask: Sequence) -> str:
    """The mask as a comma-separated string for ``--mask`` (``sstr`` of each coefficient).

    >>> t = sp.Symbol("t1")
    >>> mask_string([t, 0, sp.Rational(1, 2) - t])
    't1,0,1/2 - t1'
    """
    return ",".join(sp.sstr(c) for c in mask)


def max_sum_rules(arity: int = 2, support: int = 4, start: int | None = None, **requirements_) -> Result:
    """The family with the most sum rules on the support (under the other requirements).

    For ``m = 2`` with no other requirement this is the B-spline ``2 ((1+z)/2)^(n-1)`` of
    degree ``n - 2`` (``n`` coefficients), unique (dimension 0). ``witness["order"]`` is the
    maximal order; ``witness["next"]`` the conflict at ``order + 1``.

    >>> r = max_sum_rules(support=5)
    >>> r.witness["order"], r.value.mask
    (4, (1/8, 1/2, 3/4, 1/2, 1/8))
    """
    if "sum_rules" in requirements_:
        raise AnalysisError("max_sum_rules chooses the sum-rule order itself")
    best, k = None, 1
    while True:
        try:
            r = derive_mask(arity, support, start, sum_rules=k, **requirements_)
        except InconsistentRequirements as exc:
            if best is None:
                raise
            return Result(value=best.value, status=CERTIFIED,
                          witness={**best.witness, "order": k - 1, "next": list(exc.conflict)},
                          provenance=best.provenance)
        best, k = r, k + 1
