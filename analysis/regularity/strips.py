"""Closing the strips next to eigenvalue-type ends of a C^j set: a parametric invariant polytope.

Next to an end ``t*`` where the spectral radius of a product ``Pi(t)`` of the transition matrices
of ``c = (1/m) a_{j+1}`` reaches 1, no norm test reaches ``t*`` (the norms stay above the joint
spectral radius). :func:`close_strip` certifies ``JSR(t) = rho(Pi(t))^(1/p) < 1`` on a strip
``[u, t*)`` instead, with a Guglielmi–Protasov invariant polytope whose vertices move with ``t``.

Arity ``m >= 2`` (normalisation). ``a_{j+1} = (m z^{m-1}/q_m)^{j+1} a`` is the m-ary difference symbol
(:func:`analysis.stationary.difference.difference_symbol`; ``q_m = 1 + ... + z^{m-1}``), so
``c = (1/m) a_{j+1} = z^{(m-1)(j+1)} m^j a / q_m^{j+1}``: a shift of the mask whose joint spectral radius
gives ``alpha = j - log_m rho(c)`` (:func:`analysis.regularity.holder.holder_exponent`). ``JSR(T_0, ..., T_{m-1}) < 1`` of its
``m`` transition matrices (:func:`analysis.stationary.transition.transition_matrices`, which are
:func:`analysis.stationary.transition.transition_matrices` for ``m = 2``) is therefore ``alpha > j``:
``C^j``, the condition of the m-ary Dyn–Levin test ``||(1/m S_{a_{j+1}})^L|| < 1`` with the norm replaced
by the extremal one. Words are over ``{0, ..., m-1}``; the flip of a symmetric family maps the letter
``eps`` to ``m - 1 - eps``. Binary (``m = 2``) is the same code.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.stationary.difference import difference_symbol
>>> t = sp.Symbol("t1")
>>> a = LaurentSymbol.from_mask("t1,0,-3*t1-1/16,0,2*t1+9/16,1,2*t1+9/16,0,-3*t1-1/16,0,t1".split(","), start=-5)
>>> ts = sp.CRootOf(524288*t**5 - 65536*t**4 + 12800*t**3 - 352*t**2 + 61*t - 3, 0)
>>> r = close_strip(difference_symbol(a, 3), t, sp.Rational(5860, 131072), ts, hi_open=True)   # C^2 up to t*
>>> r["closed"], r["word"], r["mu"], r["pieces"][-1]["to"] == sp.sstr(ts)
(True, (0, 1), '1/2', True)

``word`` is in the order of application: ``Pi = T_1 T_0``. Beyond the end there is no certificate:

>>> close_strip(difference_symbol(a, 3), t, sp.Rational(5860, 131072), sp.Rational(1, 20), max_depth=8)["closed"]
False

Ternary: the interpolatory 4-point family with tension ``mu`` (catalogue ``ternary-four-point``) is C^1
up to ``mu = -1/5``, where ``T_1`` of ``(1/3) a_2`` has the eigenvalue ``1/2 - 5 mu/2 = 1``:

>>> from analysis.stationary.difference import difference_symbol
>>> mu = sp.Symbol("mu")
>>> a0, a1, a2, a3 = -sp.Rational(1, 18) - mu/6, sp.Rational(13, 18) + mu/2, sp.Rational(7, 18) - mu/2, -sp.Rational(1, 18) + mu/6
>>> t4 = LaurentSymbol.from_mask([a3, a0, 0, a2, a1, 1, a1, a2, 0, a0, a3], start=-5)
>>> r = close_strip(difference_symbol(t4, 2, arity=3), mu, sp.Rational(-1, 5), sp.Rational(-11455, 65536), lo_open=True, arity=3)
>>> r["closed"], r["word"], r["mu"], r["pieces"][0]["from"]
(True, (1,), '1/3', '-1/5')

Algorithm
---------
1. The transition matrices ``T_0(t), ..., T_{m-1}(t)`` of ``c`` (exact polynomials in ``t``). Every constant
   common left eigenvector ``y^T T_eps(t) = mu y^T`` (all t; rational ``|mu| < 1``; the sum rules give
   them) is split off exactly: the family is block triangular and ``JSR = max(JSR(R), |mu|, ...)``
   with ``R_eps`` the restriction to the common kernel (rational basis). For a symmetric family the
   exact flip ``J`` of the restricted coordinates with ``J R_eps J = R_{m-1-eps}`` is found too.
2. At the end point (float), the s.m.p. candidate ``Pi`` (best ``rho^(1/|w|)``, ``|w| <= 6`` for
   ``m <= 3``, ``m^|w| <= 2000`` beyond) with a simple real positive leading eigenvalue (a simple real
   negative one of ``B``: ``Pi = B^2``, and the cycle stripped below is ``B``, ``B v = -lambda^(1/2) v``,
   minus a vertex, of the same norm) and its eigenvector ``v``; the float invariant polytope
   (:func:`analysis.jsr._polytope.build_polytope`, roots ``v`` and, when the mirrored product is
   not a rotation of ``Pi``, ``J v``; the vertex set closed under ``J``) gives vertex *words*:
   ``v_k(t) = R_{w_k}(t) r_k(t) / lambda(t)^(|w_k|/p)``. An image ``R_i v_k / lambda^(1/p)`` whose
   word is (cycles of its root's product followed by) a vertex word *is* that vertex for every
   ``t`` (an identity, no slack needed); every other image must be strictly inside at the end
   point (``min ||c||_1 < 1``, an LP), else the method refuses (a second s.m.p.).
3. On a rational interval ``I = [t_m - h, t_m + h]`` (the strip is marched from left to right with
   dyadic steps, halved after a failure, doubled after two successes): the eigenpair
   ``(v(t), lambda(t))`` (normalisation ``v_m = 1``) is enclosed for all ``t in I`` at once by the
   Krawczyk operator in Arb (``K(X) in int X`` proves a unique eigenpair in ``X``, the same branch
   as at ``t_m``), its derivative by the implicit function theorem (an Arb solve over ``I``); every
   vertex and residual is then enclosed in the centred form ``f(t_m) + f'(I) [-h, h]``. For every
   non-identity image ``x``, with coefficients ``c`` fixed (an L1 LP at ``t_m``, polished, rounded to
   dyadics), ``||x||_P <= ||c||_1 + ||G^-1 (x - V c)||_1`` (``G`` a basis of vertices, inverted in
   Arb). All bounds ``< 1`` prove ``||R_i||_P(t) <= lambda(t)^(1/p)``, hence ``JSR(t) =
   lambda(t)^(1/p)`` on ``I``.
4. ``lambda(t) < 1`` on ``I`` (minus the open end): from the enclosure when its upper end is below 1;
   otherwise exactly: ``det(Pi(t) - I)`` has no real root in ``I`` before the end (exact root
   isolation; a rational open end that is an end of ``I`` is excluded) and ``lambda < 1`` at an
   end of ``I`` that is not the open end (continuity).

Precision and conditioning: Arb at 128 bits. The enclosure widths are ``~ |f'| h``, so the step
``h`` is about (slack at the end) / (||G^-1|| |residual'|): 4.4e-6 for the C^2 end of the 6-point
family (slack 1.35e-2, 372 pieces, ~6 s), much less for its C^1 ends (smaller slack: ~1e4 pieces,
~100 s). Floats only propose (the s.m.p., the vertex words, the coefficients); every inequality is
decided in Arb or exactly.

References
----------
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear
operators*, Found. Comput. Math. 13 (2013) 37-97.
T. Mejstrik, *Algorithm 1011: Improved invariant polytope algorithm and applications*, ACM Trans.
Math. Softw. 46(3) (2020) 29.
R. Krawczyk, *Newton-Algorithmen zur Bestimmung von Nullstellen mit Fehlerschranken*, Computing 4
(1969) 187-201.
"""

from __future__ import annotations

import copy
from collections import OrderedDict

import sympy as sp

from ..algebra.symbol import LaurentSymbol
from ..algebra.factorization import check_arity
from ..stationary.transition import transition_matrices
from ..algebra.reader import as_expr
from ..jsr.parametric import ParametricStrip, close_family


def _restricted(c: LaurentSymbol, p: sp.Symbol, arity: int = 2):
    """``(R, mus, J)``: the ``m = arity`` transition matrices of ``c`` restricted to the common kernel
    of the constant common left eigenvectors ``y`` (``y^T T_eps(t) = mu y^T`` for every ``t``, rational
    ``|mu| < 1``; the sum rules give them), the eigenvalues ``mus`` split off, and the exact flip
    ``J`` of the restricted coordinates with ``J R_eps J = R_{m-1-eps}`` for every ``eps``, ``J^2 = I``
    (or None).

    The family is block triangular with the 1x1 blocks ``mus``, so ``JSR(T) = max(JSR(R), |mus|)``."""
    T = [sp.Matrix(M) for M in transition_matrices(c, arity=arity)]      # m = 2: transition_matrices(c)
    n0 = T[0].rows
    R, mus = list(T), []
    E_tot, P_tot = sp.eye(n0), sp.eye(n0)     # x_full = E_tot y, y = P_tot x_full on the subspace
    while R[0].rows > 1:
        n = R[0].rows
        blocks = []
        for M in R:
            coeffs = {}
            for r_ in range(n):
                for c_ in range(n):
                    for (k,), co in sp.Poly(M[r_, c_], p).terms():
                        coeffs.setdefault(k, sp.zeros(n, n))[r_, c_] = co
            blocks.append(coeffs)
        C00 = blocks[0].get(0, sp.zeros(n, n))
        found = None
        for mu in sorted({x for x in C00.eigenvals() if x.is_rational and abs(x) < 1}, key=lambda x: -abs(x)):
            stack = [b.get(0, sp.zeros(n, n)) - mu * sp.eye(n) for b in blocks]
            stack += [b[k] for b in blocks for k in b if k > 0]
            ns = sp.Matrix.hstack(*stack).T.nullspace()
            if ns:
                found = (mu, ns[0])
                break
        if found is None:
            break
        mu, y = found
        q = max(i_ for i_ in range(n) if y[i_] != 0)
        E = sp.zeros(n, n - 1)
        keep = [i_ for i_ in range(n) if i_ != q]
        for col, i_ in enumerate(keep):
            E[i_, col] = 1
            E[q, col] = -y[i_] / y[q]
        Pm = sp.eye(n).extract(keep, list(range(n)))
        R = [sp.expand(Pm * M * E) for M in R]
        E_tot, P_tot = E_tot * E, Pm * P_tot
        mus.append(mu)
    Jn = sp.Matrix(n0, n0, lambda i_, j_: 1 if i_ + j_ == n0 - 1 else 0)
    J = P_tot * Jn * E_tot
    if J * J != sp.eye(J.rows) or any(sp.expand(J * R[e] * J - R[arity - 1 - e]) != sp.zeros(*R[0].shape)
                                      for e in range(arity // 2 + arity % 2)):
        J = None
    return R, mus, J



def _strip_of(am: LaurentSymbol, p: sp.Symbol, arity: int = 2) -> ParametricStrip:
    """The restricted transition matrices of ``c = (1/m) a_{j+1}`` as a :class:`~analysis.jsr.parametric.ParametricStrip`."""
    c = LaurentSymbol.from_mask([sp.expand(as_expr(x) / arity) for x in am.mask], start=am.start)
    key = (c, p, arity)
    if key not in _RESTRICTED:
        if len(_RESTRICTED) >= 32:
            _RESTRICTED.clear()
        R, mus, J = _restricted(c, p, arity)
        _RESTRICTED[key] = (tuple(M.copy() for M in R), tuple(mus), None if J is None else J.copy())
    R, mus, J = _RESTRICTED[key]
    # fresh copies: sympy matrices are mutable and each strip owns its own
    return ParametricStrip([M.copy() for M in R], p, list(mus), None if J is None else J.copy())


#: :func:`_restricted` by symbol, parameter and arity (bounded): the strips of one C^j set, and the C^j sets
#: of a profile next to the same ends, restrict the same transition matrices
_RESTRICTED: dict = {}


def close_strip(am: LaurentSymbol, p: sp.Symbol, lo, hi, *, lo_open: bool = False, hi_open: bool = False,
                max_depth: int = 20, budget: int = 120_000, arity: int = 2) -> dict:
    """Certify ``JSR((1/m) T(a_{j+1}))(t) < 1`` for ``t`` between ``lo`` and ``hi`` (exact; an open end is
    where the spectral radius reaches 1). ``am`` is the difference symbol ``a_{j+1}`` of arity ``m``
    (:func:`analysis.stationary.difference.difference_symbol`), ``T`` its ``m`` transition matrices; the
    certificate is :func:`analysis.jsr.parametric.close_family` (budgets and the returned record: there).

    Returns ``{"closed": bool, "reason": str, "word": Pi, "pieces": [...], "mu": ..., "work": units}``;
    each piece records its rational interval, the enclosure of ``lambda = rho(Pi)`` and the worst image
    norm; ``timing`` holds the wall-clock seconds (decides nothing).

    The last results are kept (:data:`_RESULTS`): the same strip asked again (a C^j range and then
    its strip on its own) is not computed twice. A closed strip is closed, with the same pieces and work,
    by every budget that passes the march's budget checks (the budget only stops the march): that result
    answers every budget from the smallest such one up; any other result answers only its own budget.
    """
    arity = check_arity(arity)
    key = (am.start, tuple(am.mask), p, as_expr(lo), as_expr(hi), bool(lo_open), bool(hi_open), max_depth, arity)
    hit = _RESULTS.get(key)
    if hit is not None and (hit[0] == budget or (hit[2]["closed"] and hit[1] <= budget)):
        _RESULTS.move_to_end(key)
        out = copy.deepcopy(hit[2])
        out["timing"] = {"seconds": 0.0, "kept": True}     # no march: the kept result
        return out
    floor = [0.0]
    out = close_family(_strip_of(am, p, arity), lo, hi, lo_open=lo_open, hi_open=hi_open, max_depth=max_depth,
                       budget=budget, floor=floor)
    _RESULTS[key] = (budget, floor[0], copy.deepcopy(out))
    _RESULTS.move_to_end(key)
    while len(_RESULTS) > _RESULTS_MAX:
        _RESULTS.popitem(last=False)
    return out


#: the last results of :func:`close_strip`, keyed on everything they depend on (the difference symbol's mask,
#: the parameter, the exact ends and whether they are open, ``max_depth``, the arity), each with the budget it
#: was computed with and the smallest budget giving the same closed result; least recently used first, at most
#: ``_RESULTS_MAX``
_RESULTS: "OrderedDict[tuple, tuple[int, dict]]" = OrderedDict()
_RESULTS_MAX = 16
