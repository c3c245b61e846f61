"""C^k of level-dependent schemes through *generalized* divided differences (exponential factors).

A binary level-dependent scheme ``{S_{a^n}}`` whose symbols all contain the factor

    p_n(z) = prod_{i<=j} (1 + e^{lambda_i h_{n+1}} z),     h_n = 2^-n,

(``Lambda = (lambda_1, ..., lambda_j)`` closed under conjugation; a pair ``a +- ib`` gives the real
factor ``1 + 2 e^{a h/2} cos(b h/2) z + e^{a h} z^2``, ``+-mu`` real gives ``1 + 2 cosh(mu h/2) z + z^2``,
``lambda = 0`` gives ``1 + z``) has a *generalized divided difference scheme*
``c^n = 2^j a^n / p_n``: the scheme that refines the scaled generalized differences
``2^{jn} Delta_n f^n``, where ``Delta_n`` has the symbol ``prod_i (1 - e^{lambda_i h_n} z)`` and annihilates
the sampled exponentials ``e^{lambda_i x}`` (the idea of Dyn–Levin–Luzzatto 2003 and of the
generalized difference operators of Conti–Romani 2011). With ``lambda_i = 0`` only, it is the
ordinary divided difference scheme ``(2/(1+z))^j a^n`` of route 2 of :mod:`.ck`.

Theorem (what is certified; the proof is given here)
----------------------------------------------------
Let ``Lambda`` be closed under conjugation and

* **(H1)** ``p_n`` divides ``a^n`` for *every* ``n >= 0`` (``b^n = a^n / p_n``, ``c^n = 2^j b^n``; the
  closure under conjugation makes ``p_n``, ``b^n`` and ``c^n`` real);
* **(H2)** ``{S_{a^n}}`` converges;
* **(H3)** ``{S_{c^n}}`` is C^r, ``r >= 0`` (here: Dyn–Levin 1995 — same support for every level,
  the stationary limit ``c = 2^j a/(1+z)^j`` certified C^r and ``sum_n 2^{rn} ||S_{c^n} - S_c|| < oo``).

Then the limit functions of ``{S_{a^n}}`` are C^{j+r}.

*Proof.* (1) ``Delta_{n+1} S_{a^n} = S_{b^n} Delta_n``: in symbols, with ``v = e^{lambda h_{n+1}}``,
``(1 - v z)(1 + v z) = 1 - v^2 z^2`` and ``v^2 = e^{lambda h_n}``, so
``prod_i (1 - e^{lambda_i h_{n+1}} z) a^n(z) F(z^2) = b^n(z) [prod_i (1 - e^{lambda_i h_n} z^2)] F(z^2)``.
Hence ``g^n := 2^{jn} Delta_n f^n`` satisfies ``g^{n+1} = S_{c^n} g^n`` and, by (H3), converges
uniformly on compacts to a function ``g`` in C^r.
(2) Let ``L = prod_i (D - lambda_i)`` and ``Phi`` a C^{j+r} solution of ``L Phi = g`` (variation of
constants). For ``u`` in C^1, ``d/dt [e^{lambda (h-t)} u(x+t)] = e^{lambda (h-t)} (u' - lambda u)(x+t)``
gives ``h^-1 (u(x+h) - e^{lambda h} u(x)) = int k_{lambda,h}(t) (u' - lambda u)(x+t) dt`` with
``k_{lambda,h} = h^-1 e^{lambda (h-t)}`` on ``[0, h]``; the operators commute, so by induction, for
``u`` in C^j, ``h^-j prod_i (E_h - e^{lambda_i h}) u(x) = int K_h(t) (L u)(x+t) dt`` with
``K_h = k_{lambda_1,h} * ... * k_{lambda_j,h}`` supported in ``[0, jh]``,
``int K_h = prod_i (e^{lambda_i h} - 1)/(lambda_i h) -> 1`` (a factor 1 for ``lambda_i = 0``) and ``int |K_h| <= e^{h sum |Re lambda_i|}``.
As ``g`` is uniformly continuous on compacts, the scaled generalized differences of ``Phi`` on the
level-n grid converge to ``g`` uniformly on compacts.
(3) So ``e^n := f^n - Phi|_{grid n}`` converges to ``e := f - Phi`` (by (H2)) and
``2^{jn} Delta_n e^n -> 0``, uniformly on compacts. Fix a level ``N``; for ``n >= N`` and
``M = 2^{n-N}``, ``1 - e^{lambda h_N} z^M = (1 - e^{lambda h_n} z) q(z)`` with
``q(z) = sum_{k<M} e^{lambda k h_n} z^k``, ``||q||_1 <= M e^{|Re lambda| h_N}``: the operator
``Delta_N^{(M)} = prod_i (1 - e^{lambda_i h_N} z^M)`` (step ``h_N`` on the level-n grid) is
``Q Delta_n`` with ``||Q||_1 <= M^j C``, so
``|Delta_N^{(M)} e^n| <= C M^j 2^{-jn} sup |2^{jn} Delta_n e^n| = C h_N^j o(1) -> 0``. In the limit,
``prod_i (E_{h_N} - e^{lambda_i h_N}) e(x) = 0`` at every dyadic ``x`` of level ``>= N``, hence at
every ``x`` (continuity). For ``N >= N_0`` the numbers ``e^{lambda h_N}`` of distinct ``lambda`` are
distinct (and non-zero), so the restriction of ``ker L`` (spanned by ``x^m e^{lambda x}``) to
``x_0 + h_N Z`` is the whole solution space of this recurrence: ``e = u_N`` on ``h_N Z`` for a unique
``u_N`` in ``ker L``; ``u_{N+1}`` agrees with ``e = u_N`` on ``h_N Z``, so ``u_{N+1} = u_N =: u``.
Thus ``e = u`` on all dyadic points, ``e`` is continuous, ``e = u`` and ``f = Phi + u`` is C^{j+r}. ∎

(The level-N uniqueness needs no hypothesis: it holds for all large N. (H2) is used to know that
``f^n`` converges; it is checked, not assumed.)

Dilation m (arity m >= 2; ``h_n = m^-n``)
-----------------------------------------
``(S_{a^n} f)_i = sum_j a^n_{i-mj} f_j``; with ``q(x) = 1 + x + ... + x^(m-1)`` the exponential factors are

    p_n(z) = prod_{i<=j} q(v_i z),    v_i = e^{lambda_i h_{n+1}},

(``lambda = 0``: ``q(z) = 1 + z + ... + z^(m-1)``; a pair ``a +- ib``: ``q(vz) q(v̄z) = sum_k e^{a k h/m}
(sum_l cos((2l-k) b h/m)) z^k``, real) and ``c^n = m^j a^n / p_n``. The theorem holds verbatim with ``2 -> m``;
the proof changes only where the dilation enters:
(1) ``(1 - v z) q(v z) = 1 - v^m z^m`` and ``v^m = e^{lambda h_n}``, so
``prod_i (1 - e^{lambda_i h_{n+1}} z) a^n(z) F(z^m) = b^n(z) [prod_i (1 - e^{lambda_i h_n} z^m)] F(z^m)``,
i.e. ``Delta_{n+1} S_{a^n} = S_{b^n} Delta_n``, and ``g^n := m^{jn} Delta_n f^n = h_n^{-j} Delta_n f^n`` satisfies
``g^{n+1} = S_{c^n} g^n``, ``c^n = m^j b^n``.
(2) does not see the dilation (``h = h_n`` is any mesh size tending to 0).
(3) For ``n >= N`` and ``M = m^{n-N}``: ``e^{lambda h_n M} = e^{lambda h_N}``, so
``1 - e^{lambda h_N} z^M = (1 - e^{lambda h_n} z) q_M(z)``, ``q_M(z) = sum_{k<M} e^{lambda k h_n} z^k``,
``||q_M||_1 = sum_{k<M} e^{Re(lambda) k h_n} <= M e^{|Re lambda| M h_n} = M e^{|Re lambda| h_N}``; hence
``|Delta_N^{(M)} e^n| <= C M^j m^{-jn} sup |m^{jn} Delta_n e^n| = C m^{-jN} o(1) -> 0``: the recurrence
``prod_i (E_{h_N} - e^{lambda_i h_N}) e = 0`` holds at the m-adic points of level ``>= N``, hence everywhere, and
the uniqueness argument is unchanged (``h_N Z`` is contained in ``h_{N+1} Z``). ∎
With ``Lambda = (0, ..., 0)`` this is the m-ary divided difference scheme ``(m/q)^j a^n`` (route 2 of :mod:`.ck`
for arity m, which therefore also checks (H2)).

What is computed
----------------
:func:`exponential_factors` finds the largest conjugation-closed multiset ``Lambda`` (``0`` allowed,
for the factors ``1+z``) whose ``p_n`` divides every ``a^n`` exactly; :func:`generalized_difference`
builds ``c^n = 2^j a^n / p_n`` for a sub-multiset as a
:class:`~analysis.levels.level_dependent.LevelDependentScheme` (the series code accepts it);
:func:`gendiff_smoothness` returns, for a requested k, a certified C^k (witness: ``Lambda``, ``j``,
``r``, each hypothesis with its status and witness) or an inconclusive naming the hypothesis that
failed.

Examples
--------
>>> from analysis.levels.level_dependent import LevelDependentScheme
>>> s = LevelDependentScheme.from_symbol(
...     "2*(1+2*c1*z+z**2)*(1+2*c2*z+z**2)/((2+2*c1)*(2+2*c2))/z**2",
...     where=["c1=cos(theta/2**(n+1))", "c2=cos(2*theta/2**(n+1))"]).subs({"theta": 1})
>>> exponential_factors(s).value
(-2*I, -I, I, 2*I)
>>> r = gendiff_smoothness(s, 2)
>>> r.status, r.value, r.witness["j"], r.witness["r"], r.witness["subset"]
('certified', True, 2, 0, (-I, I))

Ternary (``q(v z) q(v̄ z)`` for ``+-i theta`` and ``+-2i theta``, no factor ``1+z+z^2``):

>>> t = LevelDependentScheme.from_symbol(
...     "3*(1+2*c1*z+(1+2*c2)*z**2+2*c1*z**3+z**4)*(1+2*c2*z+(1+2*c4)*z**2+2*c2*z**3+z**4)"
...     "/((3+4*c1+2*c2)*(3+4*c2+2*c4))/z**4", arity=3, where=["c1=cos(theta/3**(n+1))", "c2=cos(2*theta/3**(n+1))",
...     "c4=cos(4*theta/3**(n+1))"]).subs({"theta": 1})
>>> exponential_factors(t, 3).value
(-2*I, -I, I, 2*I)
>>> generalized_difference(t, (-sp.I, sp.I), 3)[1].witness["p_n"]
['1 + 2*cos(h/3)*z + (2*cos(2*h/3) + 1)*z**2 + 2*cos(h/3)*z**3 + z**4']

Algorithm
---------
1. (H1) Every coefficient is rewritten with ``exp``; each ``exp(c h + b)`` must be linear in ``h``
   and becomes ``e^b X^m`` with generators ``X = exp(g h)`` (:mod:`.expbspline`); ``h`` may remain
   as a further indeterminate. The numerator of ``z^-s a^n(z)`` is factored over ``Q[z, h, X]``
   (sympy ``factor_list``); factors ``alpha (1 + w z)`` with ``w`` a monomial in the ``X`` give
   ``lambda = 2 log(w)/h``. Treating ``h`` and the ``X`` as independent indeterminates makes this
   *sufficient*: ``a^n = p_n b^n`` as polynomials over that ring specialises to every level.
2. The quotient is computed in real form (bottom-up synthetic division by the real ``p_n``: no
   division, ``p_n(0) = 1``) and the identity ``a^n = p_n b^n`` re-checked exactly (the ``j`` top
   coefficients of ``a^n - p_n q`` are proved 0 as rational functions of ``h`` and the ``X``).
3. (H3) :func:`analysis.levels.series.smoothness` on ``c^n`` with weight ``2^{rn}`` (Arb partial sums,
   Cauchy Taylor tails); ``j = k`` (``r = 0``) first, then smaller ``j``; the sub-multisets are
   tried with the real unpaired frequencies first (their factors make ``c^n - c = O(h)`` only).

References
----------
N. Dyn, D. Levin, A. Luzzatto, *Exponentials reproducing subdivision schemes*, Found. Comput.
Math. 3 (2003) 187-206.
C. Conti, L. Romani, *Algebraic conditions on non-stationary subdivision symbols for exponential
polynomial reproduction*, J. Comput. Appl. Math. 236 (2011) 543-556 (generalized differences).
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*,
J. Math. Anal. Appl. 193 (1995) 594-621.
"""

from __future__ import annotations

from functools import lru_cache
from itertools import product

import sympy as sp

from .expbspline import _NotOfForm, q_factors, to_exponential_generators
from .hseries import prefill_taylor
from .level_dependent import H, LevelDependentScheme
from .series import smoothness, stationary_smoothness
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..algebra.reader import as_expr

__all__ = ["exponential_factors", "generalized_difference", "gendiff_smoothness", "GeneralizedDifferences"]

_Z = sp.Symbol("z")


def _to_polynomial_ring(exprs) -> tuple[list[sp.Expr], tuple, list]:
    """Rewrite expressions in ``h`` as rational functions of ``h`` and generators ``X_j = exp(g_j h)``."""
    return to_exponential_generators(exprs, in_h=True)


def _exact_zero(expr) -> bool:
    """``expr == 0`` as a rational function of ``h`` and independent ``exp(g h)`` (a sufficient test)."""
    try:
        (e,), _, _ = _to_polynomial_ring([expr])
    except Exception:  # noqa: BLE001 - no proof of zero
        return False
    return e == 0


def _conjugate(lam: sp.Expr) -> sp.Expr:
    return sp.simplify(sp.conjugate(lam))


def _is_real(lam: sp.Expr) -> bool | None:
    im = sp.simplify(sp.im(lam))
    return True if im == 0 else (False if im.is_nonzero else None)


def exponential_factors(s: LevelDependentScheme, arity: int = 2) -> Result:
    """The largest conjugation-closed ``Lambda`` with ``prod_i (1 + e^{lambda_i 2^-(n+1)} z) | a^n`` for all n
    (``arity`` m: ``prod_i q_m(e^{lambda_i m^-(n+1)} z)``, ``q_m(x) = 1 + x + ... + x^(m-1)``, ``h = m^-n``).

    ``value``: the sorted tuple of frequencies (with multiplicity; ``0`` for each factor ``1+z``),
    certified (exact factorization over ``Q[z, h, exp(g h)]``; see the module). ``witness``:
    ``"nonzero"`` (the frequencies other than 0), ``"unpaired"`` (complex frequencies whose conjugate
    is missing: dropped), ``"generators"``. Inconclusive (``value=None``) when the symbol is not a
    polynomial in z over that ring (``witness["reason"]``).

    >>> from schemes.level_dependent import get
    >>> exponential_factors(get("exp-cubic-trig")).value
    (0, 0, -I*t, I*t)
    """
    return _exponential_factors(s, arity)


@lru_cache(maxsize=256)
def _exponential_factors(s: LevelDependentScheme, arity: int) -> Result:
    """:func:`exponential_factors` (a pure function of the scheme, remembered: every k and route asks)."""
    prov = {"method": "exp rewriting + factorization over Q[z, h, exp(g h)] (sympy)", "scheme": s.slug}
    try:
        coeffs, X, gens = _to_polynomial_ring(s.mask)
        num, _ = sp.fraction(sp.together(sum(c * _Z ** k for k, c in enumerate(coeffs))))
        if arity != 2:
            found = q_factors(num, X, gens, arity)[0]
        else:
            _, factors = sp.factor_list(num, _Z, H, *X) if X else sp.factor_list(num, _Z, H)
    except Exception as e:  # noqa: BLE001 - a failed rewriting/factorization proves nothing: H1 not established
        why = str(e) if isinstance(e, _NotOfForm) else f"not a polynomial in z over Q(h, exp(c h)) ({e})"
        return Result(value=None, status=INCONCLUSIVE, witness={"reason": why[:200]}, provenance=prov)
    mult: dict = {}
    for lam, _ in (found if arity != 2 else ()):
        mult[lam] = mult.get(lam, 0) + 1
    for f, m in (factors if arity == 2 else ()):
        if sp.degree(f, _Z) != 1:
            continue
        alpha, beta = f.coeff(_Z, 0), f.coeff(_Z, 1)
        if alpha == 0:
            continue
        w = sp.cancel(beta / alpha)
        coeff, mono = w.as_coeff_Mul()
        powers = sp.powsimp(mono).as_powers_dict() if mono != 1 else {}
        if coeff != 1 or any(b not in X or not as_expr(e).is_Integer for b, e in powers.items()):
            continue
        lam = sp.simplify(2 * sum((int(e) * gens[X.index(b)] for b, e in powers.items()), sp.Integer(0)))
        mult[lam] = mult.get(lam, 0) + int(m)
    closed, unpaired = {}, []
    for lam, m in mult.items():
        real = _is_real(lam)
        if real:
            closed[lam] = m
            continue
        mc = mult.get(_conjugate(lam), 0) if real is False else 0
        if min(m, mc):
            closed[lam] = min(m, mc)
        if m > mc:
            unpaired.append(sp.sstr(lam))
    lams = tuple(sorted((lam for lam, m in closed.items() for _ in range(m)), key=sp.default_sort_key))
    res = Result(value=lams, status=CERTIFIED,
                 witness={"frequencies": [sp.sstr(x) for x in lams],
                          "nonzero": [sp.sstr(x) for x in lams if x != 0], "unpaired": unpaired,
                          "generators": [f"exp({sp.sstr(g)}*h)" for g in gens],
                          "statement": ("prod_i (1 + exp(lambda_i 2^-(n+1)) z) divides a^n(z) for every n >= 0"
                                        if arity == 2 else f"prod_i q(exp(lambda_i {arity}^-(n+1)) z) divides a^n(z) "
                                        f"for every n >= 0, q(x) = 1 + x + ... + x^{arity - 1}")},
                 provenance=prov)
    return res


def _real_q_factors(subset, m: int) -> list[tuple[list[sp.Expr], str]]:
    """:func:`_real_factors` for arity ``m >= 3``: ``q_m(v z)``, ``v = e^{lambda h/m}``; a pair ``a +- ib`` gives
    ``sum_j e^{a j h/m} (sum_k cos((2k-j) b h/m)) z^j``, ``+-mu`` real ``sum_j (sum_k cosh((2k-j) mu h/m)) z^j``
    (``max(0, j-m+1) <= k <= min(j, m-1)``)."""
    rest, out, tau = list(subset), [], H / m

    def pair(f, b, a=0):
        cs = [sp.exp(a * j * tau) * sum(f((2 * k - j) * b * tau) for k in range(max(0, j - m + 1), min(j, m - 1) + 1))
              for j in range(2 * m - 1)]
        return [sp.expand(c) for c in cs]

    while rest:
        lam = rest.pop(0)
        if lam == 0:
            cs = [sp.Integer(1)] * m
        elif _is_real(lam) and -lam in rest:
            rest.remove(-lam)
            cs = pair(sp.cosh, abs(lam))
        elif _is_real(lam):
            cs = [sp.exp(lam * i * tau) for i in range(m)]
        else:
            rest.remove(_conjugate(lam))
            a, b = sp.simplify(sp.re(lam)), sp.simplify(sp.im(lam))
            cs = pair(sp.cos, -b if b.is_negative else b, a)
        terms = [("1" if c == 1 else f"({sp.sstr(c)})" if c.is_Add else sp.sstr(c)) if j == 0 else
                 ("z" if j == 1 else f"z**{j}") if c == 1 else
                 (f"({sp.sstr(c)})" if c.is_Add else sp.sstr(c)) + ("*z" if j == 1 else f"*z**{j}")
                 for j, c in enumerate(cs)]
        out.append((cs, " + ".join(terms)))
    return out


def _real_factors(subset, arity: int = 2) -> list[tuple[list[sp.Expr], str]]:
    """``p_n`` for a conjugation-closed multiset, as real factors ``(coefficients in z, label)``."""
    if arity != 2:
        return _real_q_factors(subset, arity)
    rest = list(subset)
    out = []
    while rest:
        lam = rest.pop(0)
        if lam == 0:
            out.append(([sp.Integer(1), sp.Integer(1)], "1 + z"))
            continue
        if _is_real(lam):
            if -lam in rest:
                rest.remove(-lam)
                v = sp.cosh(lam * H / 2)         # even: either sign of lambda
                out.append(([sp.Integer(1), 2 * v, sp.Integer(1)], f"1 + {sp.sstr(2 * v)}*z + z**2"))
            else:
                v = sp.exp(lam * H / 2)
                out.append(([sp.Integer(1), v], f"1 + {sp.sstr(v)}*z"))
            continue
        rest.remove(_conjugate(lam))
        a, b = sp.simplify(sp.re(lam)), sp.simplify(sp.im(lam))      # cos is even: either sign of b
        b = -b if b.is_negative else b
        e = sp.exp(a * H / 2)
        mid = 2 * e * sp.cos(b * H / 2)
        z2 = "z**2" if a == 0 else f"{sp.sstr(e ** 2)}*z**2"
        out.append(([sp.Integer(1), mid, e ** 2], f"1 + {sp.sstr(mid)}*z + {z2}"))
    return out


def generalized_difference(s: LevelDependentScheme, subset, arity: int = 2) -> tuple[LevelDependentScheme, Result]:
    """``c^n = 2^j a^n / p_n`` for the conjugation-closed multiset ``subset`` (``j = len(subset)``; ``arity`` m:
    ``c^n = m^j a^n / p_n``, ``p_n = prod q_m(e^{lambda_i m^-(n+1)} z)``).

    Returns the scheme and the (H1) result: certified when ``a^n = p_n b^n`` is proved exactly
    (see the module), with ``p_n`` in real form as witness; otherwise an :class:`AnalysisError`.

    >>> from schemes.level_dependent import get
    >>> import sympy as sp
    >>> c, h1 = generalized_difference(get("exp-chaikin-trig").subs({"t": 1}), (-sp.I, sp.I))
    >>> c.limit(), h1.witness["p_n"]
    (LaurentSymbol([1, 1], start=-2, domain=QQ), ['1 + 2*cos(h/2)*z + z**2'])
    """
    return _generalized_difference(s, tuple(subset), arity)


@lru_cache(maxsize=256)
def _generalized_difference(s: LevelDependentScheme, subset: tuple, arity: int) -> tuple[LevelDependentScheme, Result]:
    """:func:`generalized_difference` (a pure function of its arguments, remembered: every k and route asks)."""
    coeffs = list(s.mask)
    labels = []
    for p, label in _real_factors(subset, arity):
        d = len(p) - 1
        q: list[sp.Expr] = []
        for k in range(len(coeffs) - d):
            qk = coeffs[k] - sum(p[i] * q[k - i] for i in range(1, d + 1) if k - i >= 0)
            q.append(sp.cancel(qk))
        rem = [coeffs[k] - sum(p[i] * q[k - i] for i in range(0, d + 1) if 0 <= k - i < len(q))
               for k in range(len(coeffs) - d, len(coeffs))]
        if len(q) < 1 or not all(_exact_zero(r) for r in rem):
            raise AnalysisError(f"{label} does not divide a^n(z) identically in n (exact test)")
        coeffs = q
        labels.append(label)
    j = len(subset)
    c = LevelDependentScheme(tuple(arity ** j * x for x in coeffs), s.start, s.params,
                             slug=f"{s.slug}-gendiff{j}", title=f"generalized {j}-th difference of {s.title}",
                             source=s.source)
    prefill_taylor(c)          # exact Taylor coefficients by series arithmetic (sympy.series is slow here)
    h1 = Result(value=True, status=CERTIFIED,
                witness={"p_n": labels, "frequencies": [sp.sstr(x) for x in subset],
                         "identity": f"a^n(z) = p_n(z) b^n(z) for every n >= 0, h = {arity}^-n (exact: rational "
                                     "identity in h and independent exp(g h))"},
                provenance={"method": "synthetic division + exact zero test over Q(h, exp(g h))"})
    return c, h1


def _subsets(lams, j: int) -> list[tuple]:
    """The conjugation-closed sub-multisets of size ``j`` with a non-zero frequency, real unpaired ones first."""
    units: dict = {}
    rest = list(lams)
    while rest:
        lam = rest.pop(0)
        if lam != 0 and _is_real(lam) is False:
            rest.remove(_conjugate(lam))
            key = (lam, _conjugate(lam))
        else:
            key = (lam,)
        units[key] = units.get(key, 0) + 1
    keys = sorted(units, key=lambda u: (len(u) == 1 and u[0] == 0, len(u) == 2, sp.default_sort_key(u[0])))
    out = []
    for counts in product(*(range(units[u] + 1) for u in keys)):
        if sum(c * len(u) for c, u in zip(counts, keys)) != j:
            continue
        sub = tuple(x for c, u in zip(counts, keys) for _ in range(c) for x in u)
        if any(x != 0 for x in sub):
            out.append(tuple(sorted(sub, key=sp.default_sort_key)))
    # prefer (1) as few 1+z as possible (route 2 covers those), (2) real frequencies removed in +-pairs
    # (cosh factors: the remaining c^n - c = O(h^2), needed when r >= 1), (3) real unpaired ones removed
    real = [x for x in lams if x != 0 and _is_real(x)]

    def key(sub):
        zeros = sum(1 for x in sub if x == 0)
        split = sum(abs(sub.count(x) - sub.count(-x)) for x in set(real) if -x in real) // 2
        lone = sum(1 for x in sub if x in real and -x not in real)
        return zeros, split, -lone

    return sorted(out, key=key)


def _h3(c: LevelDependentScheme, r: int, N: int, arity: int = 2) -> Result:
    """(H3): ``{S_{c^n}}`` C^r by Dyn–Levin 1995 (or ``S_c`` C^r when ``c^n`` does not depend on n)."""
    if all(H not in x.free_symbols for x in c.mask):
        lim = stationary_smoothness(c.limit(), r, arity=arity)
        ok = lim.is_certified and lim.value is True
        return Result(value=True if ok else None, status=CERTIFIED if ok else INCONCLUSIVE,
                      witness={"claim": f"C^{r}", "route": "c^n = c for every n (stationary)",
                               "hypotheses": {f"limit_C^{r}": lim}, "failed": [] if ok else [f"limit_C^{r}"]},
                      provenance={"scheme": c.slug})
    return smoothness(c, None, r, N=N, arity=arity)


class GeneralizedDifferences:
    """The generalized difference schemes of one level-dependent scheme, built once (their Taylor
    caches are shared by every k and r)."""

    def __init__(self, s: LevelDependentScheme, arity: int = 2):
        self.s = s
        self.arity = arity
        self._schemes: dict = {}

    def factors(self) -> Result:
        return exponential_factors(self.s, self.arity)

    def get(self, subset) -> tuple[LevelDependentScheme, Result]:
        if subset not in self._schemes:
            try:
                self._schemes[subset] = generalized_difference(self.s, subset, self.arity)
            except AnalysisError as e:
                self._schemes[subset] = (None, Result(value=None, status=INCONCLUSIVE, witness={"reason": str(e)}))
        return self._schemes[subset]


def gendiff_smoothness(s: LevelDependentScheme, k: int, *, converges: Result | None = None, N: int = 40,
                       cache: GeneralizedDifferences | None = None, max_tries: int = 6, arity: int = 2) -> Result:
    """C^k of ``{S_{a^n}}`` by Dyn–Levin on a j-th generalized divided difference scheme (see the module).

    ``converges``: the (H2) result (C^0 of ``{S_{a^n}}``, e.g. from :func:`analysis.levels.ck.level_smoothness`);
    ``None``: checked here by Dyn–Levin direct. ``k = j + r`` with ``1 <= j <= |Lambda|``, ``j = k``
    first; at most ``max_tries`` (subset, j) pairs. Certified ``value=True`` with ``witness``:
    ``Lambda``, ``subset``, ``j``, ``r``, ``hypotheses`` (H1, H2, H3 as Results) and ``theorem``; or
    ``value=None``, inconclusive, with ``failed`` (the hypotheses that failed, per try).
    """
    cache = cache or GeneralizedDifferences(s, arity)
    arity = cache.arity
    fac = cache.factors()
    prov = {"method": "generalized divided differences + Dyn-Levin 1995", "scheme": s.slug, "N": N}
    if fac.value is None or not fac.witness["nonzero"]:
        why = (fac.witness["reason"] if fac.value is None else
               ("no exponential factor 1 + exp(lambda 2^-(n+1)) z" if arity == 2 else
                f"no exponential factor q(exp(lambda {arity}^-(n+1)) z)")
               + ", lambda != 0 (closed under conjugation), divides "
               f"a^n(z) identically in n (frequencies found: {', '.join(fac.witness['frequencies']) or 'none'}"
               + (f"; unpaired: {', '.join(fac.witness['unpaired'])}" if fac.witness["unpaired"] else "") + ")")
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"failed": ["H1: exponential factor p_n | a^n for every n"], "reason": why,
                               "Lambda": fac.value, "hypotheses": {"H1": fac}}, provenance=prov)
    if converges is None:
        prefill_taylor(s)      # as level_smoothness does: the exact Taylor coefficients without sympy.series
        converges = smoothness(s, None, 0, N=N, arity=arity)
    h2 = converges if converges.is_certified and converges.value is True else Result(
        value=None, status=INCONCLUSIVE, witness={"reason": "convergence of {S_(a^n)} not certified"})
    if not h2.is_certified:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"failed": ["H2: convergence of {S_(a^n)}"], "Lambda": fac.value,
                               "hypotheses": {"H1": fac, "H2": h2}}, provenance=prov)
    lams = fac.value
    tried = []
    for j in range(min(k, len(lams)), 0, -1):
        r = k - j
        for subset in _subsets(lams, j):
            if len(tried) >= max_tries:
                break
            c, h1 = cache.get(subset)
            if c is None:
                tried.append({"subset": [sp.sstr(x) for x in subset], "j": j, "r": r,
                              "failed": [f"H1: {h1.witness['reason']}"]})
                continue
            try:
                h3 = _h3(c, r, N, arity)
            except AnalysisError as e:
                h3 = Result(value=None, status=INCONCLUSIVE, witness={"failed": [str(e)]})
            if h3.is_certified and h3.value is True:
                names = ", ".join(sp.sstr(x) for x in subset)
                return Result(value=True, status=CERTIFIED,
                              witness={"Lambda": lams, "subset": subset, "j": j, "r": r,
                                       "hypotheses": {"H1": h1, "H2": h2, "H3": h3},
                                       "theorem": (f"p_n = {' * '.join(h1.witness['p_n'])} divides a^n for every n "
                                                   f"(frequencies {names}), {{S_(a^n)}} converges, the generalized "
                                                   f"divided difference scheme c^n = {arity}^{j} a^n/p_n is C^{r} "
                                                   f"(Dyn-Levin 1995)  =>  C^{j + r} (generalized differences; "
                                                   "proof in analysis.levels.gendiff)")},
                              provenance=prov)
            tried.append({"subset": [sp.sstr(x) for x in subset], "j": j, "r": r,
                          "failed": [f"H3: {x}" for x in h3.witness.get("failed", ["C^r not certified"])]})
    failed = sorted({f for t in tried for f in t["failed"]}) or ["H3: no sub-multiset of Lambda to try"]
    return Result(value=None, status=INCONCLUSIVE,
                  witness={"failed": failed, "Lambda": lams, "tried": tried, "hypotheses": {"H1": fac, "H2": h2}},
                  provenance=prov)
