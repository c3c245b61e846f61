"""Exact recognition of exponential B-spline schemes, and their certified "not C^d".

A binary level-dependent scheme is an **exponential B-spline scheme of order d+1** with
frequencies ``Lambda = (lambda_1, ..., lambda_{d+1})`` (real, or closed under conjugation) when,
for every level ``n >= 0`` (``h = 2^-n``, :data:`~analysis.levels.level_dependent.H`),

    a^n(z) = 2 z^s prod_{i=1}^{d+1} (1 + w_i z) / (1 + w_i),    w_i = exp(lambda_i 2^-(n+1)) = exp(lambda_i h/2).

A conjugate pair ``lambda = a +- i b`` gives the real factor ``1 + 2 e^{ah/2} cos(bh/2) z + e^{ah} z^2``;
``lambda = 0`` gives ``(1+z)/2``. The catalogue's ``exp-*`` schemes (trigonometric ``+-i t`` and
hyperbolic ``+-t``, degrees 2..5) and inline input such as
``--symbol "(1+z)**2*(1+2*c*z+z**2)/(4*(1+c))/z**2" --where "c=cos(t/2**(n+1))"`` are of this form.

:func:`recognise` decides the form exactly (for all n at once); :func:`not_ck` turns it into a
certified "the scheme is not C^d".

Theorem (what is certified)
---------------------------
*If* ``a^n`` has the form above for every ``n >= 0`` and ``1 + w_i != 0`` at every level, the
scheme ``{S_{a^n}}`` is **not C^d**.

Proof sketch. Let ``B_Lambda = beta_{lambda_1} * ... * beta_{lambda_{d+1}}`` (``*`` convolution,
``beta_lambda(x) = e^{lambda x}`` on ``[0, 1)``, 0 elsewhere): the exponential B-spline of order
``d+1`` with integer knots (Unser–Blu 2005). With the spacing-h version
``beta_{lambda,h}(x) = e^{lambda x}`` on ``[0, h)``, ``beta_{lambda,h} = beta_{lambda,h/2} +
e^{lambda h/2} beta_{lambda,h/2}(. - h/2)``, so ``B_{Lambda,h} = sum_j p_j B_{Lambda,h/2}(. - jh/2)``
with ``p(z) = prod_i (1 + e^{lambda_i h/2} z)``: the unnormalised symbol. Starting the scheme at
level 0 from the delta sequence, ``f^n = C_n p^{(n)}`` with ``C_n = prod_{k<n} c_k``, ``c_k`` the
normalising constants, and ``B_Lambda = C_n^{-1} sum_j f^n_j B_{Lambda,2^-n}(. - j 2^-n)``.
``2^{nd} C_n -> kappa = prod_{k>=0} prod_i 2 / (1 + e^{lambda_i 2^-(k+1)})``, a convergent product
of non-zero factors (``1 + w_i != 0``; the factors are ``1 + O(2^-k)``), so ``kappa != 0``, and
``sum_j |B_{Lambda,h}(x - jh)| = O(h^d)``. Hence, if the scheme converges, its basic limit
function is ``kappa B_Lambda`` (Conti–Romani; Conti–Gemignani–Romani: exponential B-spline
schemes generate the exponential B-spline). ``B_Lambda`` is piecewise in the kernel of the
constant-coefficient operator ``L = prod_i (D - lambda_i)`` of order ``d+1`` between its integer
knots, and vanishes on ``(-oo, 0)``. If ``B_Lambda`` were C^d, at each knot the two pieces would
share ``y, y', ..., y^(d)``: ``d+1`` initial values of an order ``d+1`` linear ODE, so by
uniqueness of the initial value problem they would coincide, knot after knot, and ``B_Lambda``
would be the zero solution: a contradiction (``B_Lambda != 0``: its Fourier transform
``prod_i (1 - e^{lambda_i - i w}) / (i w - lambda_i)`` is not identically zero). So the limit
from the delta sequence is not C^d. If the scheme does not converge, it is not C^d either.
(``B_Lambda`` is C^{d-1}: a convolution of ``d+1`` bounded functions with compact support; the
C^{d-1} of the *scheme* is certified separately, by the Dyn–Levin routes of :mod:`.ck`.)

Dilation m (arity m >= 2, ``h = m^-n``)
---------------------------------------
The m-ary exponential B-spline scheme of order d+1 has the symbols

    a^n(z) = m z^s prod_{i=1}^{d+1} q(v_i z) / q(v_i),   q(x) = 1 + x + ... + x^(m-1),  v_i = e^{lambda_i m^-(n+1)}

(:mod:`schemes.level_dependent`). It generates the *same* ``B_Lambda``: splitting ``[0, h)`` into m pieces,
``beta_{lambda,h}(x) = sum_{k<m} e^{lambda k h/m} beta_{lambda,h/m}(x - k h/m)`` (on the k-th piece
``e^{lambda x} = e^{lambda k h/m} e^{lambda (x - k h/m)}``), so convolving the d+1 boxes,
``B_{Lambda,h} = sum_j p_j B_{Lambda,h/m}(. - j h/m)`` with ``p(z) = prod_i q(e^{lambda_i h/m} z)``: the
refinement equation with dilation m (tests: checked in mpmath at order 2). In Fourier terms
``hat beta_lambda(xi) = (1 - e^{lambda - i xi})/(i xi - lambda)`` does not depend on m. The normalisers
``c_k = m / prod_i q(v_i)`` satisfy ``m^{d} c_k -> 1`` geometrically (``q(v) = m + O(m^-k)``), so
``m^{nd} C_n -> kappa != 0`` provided ``q(v_i) != 0`` at every level: ``q(v) = (1 - v^m)/(1 - v)`` vanishes only
for ``v^m = 1 != v``, never when ``Re lambda != 0`` or ``lambda`` is real, and for ``lambda = i b`` not once
``|b| m^-(n+1) < 2 pi/m`` (the finitely many earlier levels are checked in Arb). ``sum_j |B_{Lambda,h}(x - jh)| =
O(h^d)`` holds as before. Hence the proof above applies verbatim: an m-ary exponential B-spline scheme of order
d+1 is not C^d. Recognition (step 3 below) takes, for arity m, the candidates ``w`` from the irreducible
factors (``beta/alpha`` of a factor of ``q(w z)``) and confirms each, with its multiplicity, by exact
division of the numerator by ``q(w z)``; the identity of step 4 is then checked exactly as for m = 2.

Algorithm
---------
1. Every mask coefficient is rewritten with ``exp`` (``cos, cosh, sin, ...`` -> ``exp``); each
   ``exp(c h + b)`` must be linear in ``h``; otherwise (``h`` outside an exponential, e.g.
   ``2^-3n``) the scheme is *not recognised*.
2. The slopes ``c`` are grouped by rational ratio; each group gets a generator
   ``X_j = exp(g_j h)`` with every slope an integer multiple ``m g_j`` (exact rational
   arithmetic), and ``exp(c h + b) = e^b X_j^m`` is substituted: the symbol becomes a rational
   function of ``z`` and the ``X_j``.
3. The numerator is factored over Q(X) (sympy ``factor_list``); every factor must be linear in
   ``z``, ``alpha + beta z`` with ``beta/alpha`` a monomial ``prod X_j^{m_j}`` (coefficient 1):
   ``w_i = exp(lambda_i h/2)`` with ``lambda_i = 2 sum_j m_j g_j``.
4. The identity ``a^n(z) = 2 z^s prod (1 + w_i z)/(1 + w_i)`` is checked as an identity of
   rational functions in ``z, X_j`` (exact ``cancel``): treating the ``X_j`` as independent
   variables makes this a *sufficient* test, so a scheme is never wrongly recognised.
5. ``1 + w_i != 0`` at every level: automatic unless ``Re lambda_i = 0``; then
   ``|lambda_i| 2^-(n+1) < pi`` for ``n >= n_0`` and the finitely many ``n < n_0`` are checked in
   Arb ball arithmetic.

Examples
--------
>>> from schemes.level_dependent import get
>>> r = recognise(get("exp-cubic-trig").subs({"t": 1}))
>>> r.status, r.value, r.witness["order"]
('certified', (0, 0, -I, I), 4)
>>> from analysis.levels.level_dependent import LevelDependentScheme
>>> recognise(LevelDependentScheme.from_symbol("(1+z)**4/(8*z**2) + 2**(-3*n)*(1-z)**4/(16*z**2)")).value is None
True
>>> c = not_ck(get("exp-chaikin-hyp").subs({"t": 2}))
>>> c.status, c.value, c.witness["k"]
('certified', False, 2)
>>> from schemes.level_dependent import get
>>> r = recognise(get("quaternary-exp-bspline-3-hyp").subs({"t": 1}), 4)
>>> r.value, r.witness["order"]
((-1, 0, 0, 1), 4)
>>> recognise(get("quaternary-exp-bspline-3-hyp").subs({"t": 1}), 3).value is None   # wrong arity
True

References
----------
M. Unser, T. Blu, *Cardinal exponential splines: part I — theory and filtering algorithms*,
IEEE Trans. Signal Process. 53(4) (2005) 1425-1438 (exponential B-splines ``beta_Lambda``).
C. Conti, L. Romani, *On the reproduction properties of non-stationary subdivision schemes*,
arXiv:1004.1297 (2010) (exponential-generation by non-stationary binary schemes).
C. Conti, L. Gemignani, L. Romani, *Exponential splines and pseudo-splines: generation versus
reproduction of exponential polynomials*, arXiv:1404.6624 (2014) (symbols of exponential
B-spline schemes).
M. Charina, C. Conti, L. Romani, *Reproduction of exponential polynomials by multivariate
non-stationary subdivision schemes with a general dilation matrix*, arXiv:1303.1678 (2013).
"""

from __future__ import annotations

from functools import lru_cache, reduce
from math import gcd, lcm

import flint
import sympy as sp

from .balls import _ball, workprec
from .level_dependent import H, LevelDependentScheme
from ..result import CERTIFIED, INCONCLUSIVE, Result
from ..algebra.reader import as_expr

__all__ = ["recognise", "not_ck"]

_Z = sp.Symbol("z")


class _NotOfForm(Exception):
    """The symbol is not (recognisably) an exponential B-spline symbol; the message says why."""


@lru_cache(maxsize=1024)
def _linear_in_h(arg: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``(c, b)`` with ``arg = c h + b`` (a pure function of ``arg``, remembered; :class:`_NotOfForm` otherwise)."""
    a = sp.expand(arg)
    c1, c0 = sp.simplify(a.coeff(H, 1)), sp.simplify(a.coeff(H, 0))
    if sp.simplify(a - c1 * H - c0) != 0 or H in c1.free_symbols or H in c0.free_symbols:
        raise _NotOfForm(f"exp({sp.sstr(arg)}) is not exp(c*h + b): the level enters otherwise")
    return c1, c0


def _generators(slopes: list[sp.Expr]) -> tuple[list[sp.Expr], dict]:
    """Group the slopes by rational ratio: generators ``g_j`` and ``slope -> (j, integer m)``."""
    groups: list[tuple[sp.Expr, list[tuple[sp.Expr, sp.Rational]]]] = []
    for c in slopes:
        for base, members in groups:
            r = sp.simplify(c / base)
            if r.is_Rational:
                members.append((c, r))
                break
        else:
            groups.append((c, [(c, sp.Integer(1))]))
    gens, where = [], {}
    for j, (base, members) in enumerate(groups):
        den = reduce(lcm, (int(r.q) for _, r in members), 1)
        num = reduce(gcd, (int(r.p * (den // r.q)) for _, r in members), 0)
        g = sp.simplify(base * sp.Rational(num, den))
        gens.append(g)
        for c, r in members:
            m = r / sp.Rational(num, den)
            if not (m.is_Integer and sp.simplify(m * g - c) == 0):
                raise _NotOfForm(f"cannot write exp({sp.sstr(c)} h) as a power of exp({sp.sstr(g)} h)")
            where[c] = (j, int(m))
    return gens, where


def to_exponential_generators(exprs, *, in_h: bool = False) -> tuple[list[sp.Expr], tuple, list]:
    """Rewrite expressions in ``h`` with generators ``X_j = exp(g_j h)`` (independent indeterminates).

    Every ``exp(c h + b)`` becomes ``exp(b) X_j^m`` (slopes grouped by rational ratio). ``in_h``: the result
    may still be a rational function of ``h`` (else ``h`` must disappear). Returns the cancelled
    expressions, the symbols ``X`` and the generators ``g_j``; raises :class:`_NotOfForm` otherwise.

    >>> out, X, gens = to_exponential_generators([sp.cosh(2 * H) + sp.exp(H)])
    >>> out, gens                                   # X0 = exp(-h)
    ([(X0**4 + 2*X0 + 1)/(2*X0**2)], [-1])
    """
    exprs = [as_expr(c) for c in exprs]
    rewritten, substituted, X, gens = _exponential_generators(tuple(exprs))
    out = []
    for c, e in zip(rewritten, substituted):
        if in_h and not e.is_rational_function(H, *X):
            raise _NotOfForm(f"the coefficient {sp.sstr(c)} is not a rational function of h and exponentials "
                             "exp(c h)")
        if not in_h and H in e.free_symbols:
            raise _NotOfForm(f"the coefficient {sp.sstr(c)} depends on the level otherwise than through "
                             "exponentials exp(c h) (e.g. a power of 2^-n)")
        out.append(_cancelled(e))
    return out, X, list(gens)


def _rational_zero(e: sp.Expr) -> bool:
    """``cancel(together(e)) == 0``: first as the numerator of ``together(e)`` being the zero polynomial in its
    symbols (a proof, and much cheaper than the gcds of ``cancel``), else by ``cancel`` itself."""
    num = sp.fraction(sp.together(e))[0]
    gens = sorted(as_expr(num).free_symbols, key=lambda x: x.name)
    if gens:
        try:
            if sp.Poly(num, *gens).is_zero:
                return True
        except sp.PolynomialError:
            pass
    return sp.cancel(sp.together(e)) == 0


@lru_cache(maxsize=1024)
def _cancelled(e: sp.Expr) -> sp.Expr:
    """``cancel(together(e))`` (a pure function of ``e``, remembered)."""
    return sp.cancel(sp.together(e))


@lru_cache(maxsize=256)
def _exponential_generators(exprs: tuple) -> tuple:
    """``(rewritten, substituted, X, gens)`` of :func:`to_exponential_generators` before its checks and
    ``cancel``: a pure function of the expressions, remembered (recognition and the generalized differences
    rewrite the same mask); :class:`_NotOfForm` raises anew each time."""
    exprs = [c.rewrite(sp.exp) for c in exprs]
    args = {e.args[0] for c in exprs for e in c.atoms(sp.exp) if H in e.free_symbols}
    lin = {a: _linear_in_h(a) for a in args}
    slopes = sorted({c1 for c1, _ in lin.values() if c1 != 0}, key=sp.default_sort_key)
    gens, where = _generators(slopes)
    X = sp.symbols(f"X0:{len(gens)}")      # no assumptions: X_j = exp(g_j h) may be complex

    def sub(arg):
        if H not in arg.free_symbols:
            return sp.exp(arg)
        c1, c0 = lin[arg]
        if c1 == 0:
            return sp.exp(c0)
        j, m = where[c1]
        return sp.exp(c0) * X[j] ** m

    return tuple(exprs), tuple(c.replace(sp.exp, sub) for c in exprs), X, tuple(gens)


def _to_exponential_polynomial(s: LevelDependentScheme):
    """The symbol ``z^-start a^n(z)`` as a rational function of ``z`` and generators ``X_j = exp(g_j h)``."""
    out, X, gens = to_exponential_generators(s.mask)
    return sum(c * _Z ** k for k, c in enumerate(out)), X, gens


def _monomial_root(f, X, gens, arity: int):
    """``(lambda, w)`` when the factor ``f = alpha + beta z + ...`` gives ``w = beta/alpha`` a monomial in the ``X_j``
    (coefficient 1): ``w = exp(lambda h/arity)``, ``lambda = arity sum_j m_j g_j``; else ``None``."""
    alpha, beta = f.coeff(_Z, 0), f.coeff(_Z, 1)
    if alpha == 0 or beta == 0:
        return None
    w = sp.cancel(beta / alpha)
    coeff, mono = w.as_coeff_Mul()
    powers = sp.powsimp(mono).as_powers_dict() if mono != 1 else {}
    if coeff != 1 or any(b not in X or not as_expr(e).is_Integer for b, e in powers.items()):
        return None
    return sp.simplify(arity * sum((int(e) * gens[X.index(b)] for b, e in powers.items()), sp.Integer(0))), w


def q_factor(w, m: int) -> sp.Expr:
    """``1 + w z + ... + (w z)^(m-1)``: the m-ary exponential box with ``w = exp(lambda h/m)``.

    >>> q_factor(sp.Symbol("w"), 3)
    w**2*z**2 + w*z + 1
    """
    return sum(((w * _Z) ** i for i in range(m)), sp.Integer(0))


def q_factors(num, X, gens, m: int) -> tuple[list[tuple[sp.Expr, sp.Expr]], sp.Expr]:
    """``(lambda_i, w_i)`` with ``prod_i q_m(w_i z)`` dividing ``num`` (a polynomial in z over Q[h, X]), and the
    cofactor. Candidates ``w`` come from the irreducible factors (``beta/alpha`` of ``Phi_p(w z)``, ``p`` the
    smallest prime factor of m); each is confirmed, with its multiplicity, by exact division.

    >>> X = sp.symbols("X0:1")
    >>> num = sp.expand((1 + _Z + _Z**2 + _Z**3) ** 2 * (1 + X[0] * _Z) * (1 + X[0] ** 2 * _Z ** 2) * (X[0] + _Z)
    ...                 * (X[0] ** 2 + _Z ** 2))                  # q_4(z)^2 q_4(X z) X^3 q_4(z/X)
    >>> pairs, rest = q_factors(num, X, [sp.I], 4)
    >>> sorted((lam for lam, _ in pairs), key=sp.default_sort_key), rest
    ([0, 0, -4*I, 4*I], 1)
    """
    gensyms = [x for x in (H, *X) if x in as_expr(num).free_symbols]
    _, factors = sp.factor_list(num, _Z, *gensyms) if gensyms else sp.factor_list(num, _Z)
    cands = []
    for f, _ in factors:
        if sp.degree(f, _Z) >= 1:
            r = _monomial_root(f, X, gens, m)
            if r is not None and all(sp.cancel(r[1] - w) != 0 for _, w in cands):
                cands.append(r)
    out, rest = [], sp.expand(num)
    for lam, w in cands:
        while sp.degree(rest, _Z) >= m - 1:
            qq, rr = sp.div(rest, sp.expand(sp.together(q_factor(w, m) * sp.denom(w) ** (m - 1))), _Z)
            if not _rational_zero(rr):
                break
            out.append((lam, w))
            rest = sp.expand(sp.cancel(sp.together(qq)))
    return out, rest


def _frequencies(poly_expr, X, gens, arity: int = 2) -> list[tuple[sp.Expr, sp.Expr]]:
    """``(lambda_i, w_i)`` for the factors ``1 + w_i z`` (``q_m(w_i z)`` for arity m; ``w_i`` a monomial in the ``X_j``)."""
    # the denominator of together(P) is free of z (P is a polynomial in z), so cancelling it changes only the
    # factors of degree 0 in z, which are not read: the same factors in z, without the gcds of cancel
    num, _ = sp.fraction(sp.together(poly_expr))
    if arity != 2:
        pairs, rest = q_factors(num, X, gens, arity)
        if not pairs or sp.degree(rest, _Z) != 0:
            raise _NotOfForm(f"the symbol's numerator does not split into factors 1 + w z + ... + (w z)^{arity - 1}")
        return pairs
    deg = sp.degree(num, _Z)
    if deg < 1:
        raise _NotOfForm("the symbol has no factor (1 + w z)")
    _, factors = sp.factor_list(num, _Z, *X) if X else sp.factor_list(num, _Z)
    lams: list[tuple[sp.Expr, sp.Expr]] = []
    for f, mult in factors:
        dz = sp.degree(f, _Z)
        if dz == 0:
            continue
        if dz > 1:
            raise _NotOfForm(f"a factor of degree {dz} in z of the symbol does not split over Q(exp(c h)): "
                             f"{sp.sstr(f)}")
        alpha, beta = f.coeff(_Z, 0), f.coeff(_Z, 1)
        if alpha == 0:
            raise _NotOfForm("z divides the symbol's numerator")
        w = sp.cancel(beta / alpha)
        coeff, mono = w.as_coeff_Mul()
        powers = sp.powsimp(mono).as_powers_dict() if mono != 1 else {}
        if coeff != 1 or any(b not in X or not as_expr(e).is_Integer for b, e in powers.items()):
            raise _NotOfForm(f"the root of {sp.sstr(f)} is not -exp(lambda h/2) (w = {sp.sstr(w)})")
        lam = 2 * sum((int(e) * gens[X.index(b)] for b, e in powers.items()), sp.Integer(0))
        lams.extend([(sp.simplify(lam), w)] * int(mult))
    if len(lams) != deg:
        raise _NotOfForm("the symbol's numerator does not split into factors (1 + w z)")
    return lams


def recognise(s: LevelDependentScheme, arity: int = 2) -> Result:
    """Is ``a^n(z) = 2 z^s prod_i (1 + e^{lambda_i h/2} z)/(1 + e^{lambda_i h/2})`` for every n? (exact)

    ``arity`` m: ``a^n(z) = m z^s prod_i q_m(w_i z)/q_m(w_i)``, ``w_i = e^{lambda_i h/m}``, ``h = m^-n``.

    ``value``: the frequencies ``(lambda_1, ..., lambda_{d+1})`` (sorted), certified, with
    ``witness["order"] = d + 1`` and ``witness["shift"] = s``; or ``None`` (inconclusive: not of
    this form, or not recognisably so; ``witness["reason"]``). The identity is checked exactly as
    a rational identity in ``z`` and independent generators ``exp(g_j h)`` (see the module).
    """
    return _recognise(s, arity)


@lru_cache(maxsize=256)
def _recognise(s: LevelDependentScheme, arity: int) -> Result:
    """:func:`recognise` (a pure function of the scheme, remembered)."""
    prov = {"method": "exp rewriting + factorization over Q(exp(g h)) + exact rational identity",
            "scheme": s.slug}
    try:
        P, X, gens = _to_exponential_polynomial(s)
        pairs = _frequencies(P, X, gens, arity)
        prod = sp.Integer(arity)
        for _, w in pairs:
            prod = prod * q_factor(w, arity) / q_factor(w, arity).subs(_Z, 1)
        if not _rational_zero(prod - P):
            raise _NotOfForm("the normalisation differs from 2 prod (1 + w_i z)/(1 + w_i)" if arity == 2 else
                             f"the normalisation differs from {arity} prod q(w_i z)/q(w_i)")
        lams = [lam for lam, _ in pairs]
    except (_NotOfForm, sp.PolynomialError, sp.polys.polyerrors.PolificationFailed, ValueError, TypeError) as e:
        why = str(e) if isinstance(e, _NotOfForm) else f"the symbol is not a polynomial in z over Q(exp(c h)) ({e})"
        why = why if len(why) <= 160 else why[:157] + "..."
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"exponential_bspline": False, "reason": f"not recognised: {why}"}, provenance=prov)
    lams = sorted(lams, key=sp.default_sort_key)
    d1 = len(lams)
    return Result(value=tuple(lams), status=CERTIFIED,
                  witness={"exponential_bspline": True, "order": d1, "degree": d1 - 1, "shift": s.start,
                           "frequencies": [sp.sstr(x) for x in lams],
                           "identity": (f"a^n(z) = 2 z^({s.start}) prod_i (1 + exp(lambda_i 2^-(n+1)) z) / "
                                        "(1 + exp(lambda_i 2^-(n+1))) for all n >= 0 (exact)" if arity == 2 else
                                        f"a^n(z) = {arity} z^({s.start}) prod_i q(v_i z)/q(v_i), q(x) = "
                                        f"1 + x + ... + x^{arity - 1}, v_i = exp(lambda_i {arity}^-(n+1)), for all "
                                        "n >= 0 (exact)"),
                           "generators": [f"exp({sp.sstr(g)}*h)" for g in gens]},
                  provenance=prov)


def _normalisers_nonzero(lams, n_levels_max: int = 4096, arity: int = 2) -> Result:
    """``1 + exp(lambda 2^-(n+1)) != 0`` for every ``n >= 0`` and every frequency (certified or not); arity m:
    ``q_m(v) = 1 + v + ... + v^(m-1) != 0``, ``v = exp(lambda m^-(n+1))`` (``q_m(v) = (1 - v^m)/(1 - v)``
    vanishes only for ``v^m = 1 != v``: never when ``Re lambda != 0``; for ``lambda = i b`` not once
    ``|b| m^-(n+1) < 2 pi/m``)."""
    m = arity
    free = set().union(*(as_expr(x).free_symbols for x in lams))
    if free:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"reason": f"free parameters {', '.join(sorted(map(str, free)))}: give values"})
    checked = []
    with workprec(128):
        pi = flint.arb.pi()
        for lam in lams:
            if sp.im(lam) == 0 or sp.simplify(sp.re(lam)) != 0 and _ball(sp.re(lam), {}, False).abs_lower() > 0:
                continue     # real part != 0 or lambda real: |w| != 1 or w > 0, so w != -1
            b = _ball(as_expr(lam), {}, True)
            mag = abs(b)
            n0 = 0
            while not (mag / m ** (n0 + 1) < 2 * pi / m):
                n0 += 1
                if n0 > n_levels_max:
                    return Result(value=None, status=INCONCLUSIVE, witness={"reason": "frequency too large"})
            for n in range(n0):
                v = sum(((k * b / m ** (n + 1)).exp() for k in range(m)), flint.acb(0))
                if not abs(v) > 0:
                    return Result(value=None, status=INCONCLUSIVE,
                                  witness={"reason": (f"1 + exp({sp.sstr(lam)} 2^-{n + 1}) not certified != 0 " if m == 2
                                                      else f"q(exp({sp.sstr(lam)} {m}^-{n + 1})) not certified != 0 ")
                                           + f"(level n = {n}; the mask may be undefined there)"})
            checked.append(f"{sp.sstr(lam)}: |lambda| 2^-(n+1) < pi for n >= {n0}, levels < {n0} by Arb" if m == 2
                           else f"{sp.sstr(lam)}: |lambda| {m}^-(n+1) < 2 pi/{m} for n >= {n0}, levels < {n0} by Arb")
    return Result(value=True, status=CERTIFIED,
                  witness={"statement": ("1 + exp(lambda_i 2^-(n+1)) != 0 for all n >= 0" if m == 2 else
                                         f"q(exp(lambda_i {m}^-(n+1))) != 0 for all n >= 0"), "checked": checked},
                  provenance={"method": "real part != 0, or |Im| < pi for n >= n_0 and Arb at n < n_0"})


def not_ck(s: LevelDependentScheme, arity: int = 2) -> Result:
    """Certified "not C^d" for an exponential B-spline scheme of order ``d+1`` (see the module's theorem);
    ``arity`` m: the m-ary form (``h = m^-n``), same theorem.

    ``value=False`` (the scheme is not C^d), ``witness["k"] = d``, with the hypotheses (exact
    recognition; non-zero normalisers at every level) as results; or ``value=None``,
    inconclusive, naming the hypothesis that failed.
    """
    rec = recognise(s, arity)
    hyps = {"exponential_bspline_form": rec}
    if rec.value is None:
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"k": None, "failed": ["exponential_bspline_form"], "reason": rec.witness["reason"],
                               "hypotheses": hyps},
                      provenance={"method": "exponential B-spline recognition"})
    d = rec.witness["order"] - 1
    norm = _normalisers_nonzero(rec.value, arity=arity)
    hyps["normalisers_nonzero"] = norm
    if not (norm.is_certified and norm.value is True):
        return Result(value=None, status=INCONCLUSIVE,
                      witness={"k": d, "failed": ["normalisers_nonzero"], "reason": norm.witness.get("reason"),
                               "hypotheses": hyps},
                      provenance={"method": "exponential B-spline recognition"})
    freqs = ", ".join(rec.witness["frequencies"])
    return Result(value=False, status=CERTIFIED,
                  witness={"k": d, "order": d + 1, "frequencies": rec.value, "hypotheses": hyps,
                           "theorem": (f"exponential B-spline scheme of order {d + 1} (frequencies {freqs}): its "
                                       f"basic limit function is a non-zero multiple of B_Lambda, piecewise in "
                                       f"ker prod(D - lambda_i) with integer knots, C^{d - 1} and not C^{d} "
                                       "(uniqueness for the order-d+1 ODE at a knot); Unser-Blu 2005, "
                                       "Conti-Romani 2010, Conti-Gemignani-Romani 2014"
                                       + ("" if arity == 2 else f"; dilation {arity}: the same B_Lambda (refinement "
                                          "identity in analysis.levels.expbspline)"))},
                  provenance={"method": "exact recognition + exponential B-spline theorem"})


def ternary_exponential_bspline_2(theta: sp.Symbol | None = None) -> LevelDependentScheme:
    """The ternary exponential B-spline scheme of degree 2 with frequencies ``{0, i theta, -i theta}``.

    Derivation. ``e^{lambda x} chi_[0,1)(x) = sum_{k<3} e^{lambda k/3} (e^{lambda .} chi_[0,1/3))(x - k/3)``: the
    exponential box with frequency ``lambda`` at spacing ``tau`` has the ternary mask ``1 + e^{lambda tau} z +
    e^{2 lambda tau} z^2``; the exponential B-spline is the convolution of the boxes, so its level-n symbol is
    the product of the factors with ``tau = 3^-(n+1)``. For ``lambda = +-i theta`` the product of the two factors is
    ``1 + 2 c_1 z + (1 + 2 c_2) z^2 + 2 c_1 z^3 + z^4``, ``c_j = cos(j theta/3^(n+1))``; with the factor
    ``1 + z + z^2`` (``lambda = 0``) and the normalisation ``a^n(1) = 3``:

        a^n(z) = (1+z+z^2)(1 + 2 c_1 z + (1 + 2 c_2) z^2 + 2 c_1 z^3 + z^4) / ((3 + 4 c_1 + 2 c_2) z^3).

    Check (tests): ``a^n(eps e^{-+ i theta tau}) = 0`` for ``eps = e^{+-2 pi i/3}`` (the scheme generates
    ``1, cos(theta x), sin(theta x)``), and the limit is the ternary quadratic B-spline ``(1+z+z^2)^3/(9 z^3)``.
    """
    t = theta if theta is not None else sp.Symbol("theta", positive=True)
    c1, c2 = sp.cos(t * H / 3), sp.cos(2 * t * H / 3)
    num = sp.expand((1 + _Z + _Z ** 2) * (1 + 2 * c1 * _Z + (1 + 2 * c2) * _Z ** 2 + 2 * c1 * _Z ** 3 + _Z ** 4))
    den = 3 + 4 * c1 + 2 * c2
    coeffs = [sp.factor(num.coeff(_Z, i) / den) for i in range(7)]
    return LevelDependentScheme(tuple(coeffs), -3, (t,), slug="ternary-exp-bspline-2",
                                title="ternary exponential B-spline of degree 2 (trigonometric)",
                                source="derived here (analysis.levels.expbspline.ternary_exponential_bspline_2)",
                                arity=3)
