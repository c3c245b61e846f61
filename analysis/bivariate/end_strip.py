"""The strip next to an exact end of a C^l set, closed in exact arithmetic: split off the leading subspace, and
bound the JSR there by a moving eigenvalue through a convex hull in ``1/lambda(t)``.

Setting: an affine family ``T_eps(t) = C_eps0 + t C_eps1`` (exact rational matrices, the restricted transition
operators of :class:`~analysis.bivariate.ranges.ParametricFamily`), an exact end ``t*`` where some letters
``T_eps(t*)`` have the eigenvalue ``theta = rho(M)^-l``, and a point ``a`` on the C^l side. The boxes of
:func:`~analysis.bivariate.ranges.ck_set` never reach ``t*`` (the JSR tends to ``theta``); this closes
``[a, t*)`` when the family has the structure of the butterfly's right end:

1. **Leading eigenvectors that do not move.** Every eigenvector ``v`` of a ``T_eps(t*)`` for ``theta`` is an
   eigenvector of ``C_eps0`` and ``C_eps1`` (exact check): ``C_eps0 v = mu0 v``, ``C_eps1 v = mu1 v``, the same
   ``(mu0, mu1)`` for all of them. Then ``lambda(t) = mu0 + mu1 t`` is an eigenvalue of ``T_eps(t)`` for every
   ``t``: ``JSR(T(t)) >= lambda(t)``, with ``lambda(t*) = theta``. Otherwise ``lambda`` is the **tangent** at
   ``t*`` of the eigenvalue branches (semisimple ``theta``, rational derivatives: the eigenvalues of ``(L R)^-1
   L C_eps1 R``, ``L``, ``R`` the left and right kernels), the branch that is largest on the strip's side; it is
   then only a candidate bound, which step 3 proves or not.
2. **Split.** ``U`` = the smallest subspace holding these eigenvectors and invariant under every coefficient
   matrix ``C_eps,d`` (exact Krylov space; it does not depend on ``t``). In a basis ``[U | E]`` all ``T_eps(t)``
   are block upper triangular, and ``JSR(T(t)) = max(JSR(T(t)|U), JSR(T(t) on R^n/U))`` (Berger–Wang).
3. **The leading block: a convex hull in 1/lambda.** With ``T`` and ``lambda`` affine,
   ``T(t)/lambda(t) = (C_0 - (mu0/mu1) C_1) / lambda(t) + C_1 / mu1`` is affine in ``s = 1/lambda(t)``, which is
   monotone on ``[a, t*]`` (``lambda > 0`` there). So for every ``t`` in ``[a, t*]``, ``T_eps(t)|U / lambda(t)``
   is a convex combination of ``T_eps(a)|U / lambda(a)`` and ``T_eps(t*)|U / theta``, and the JSR of a set is
   that of its convex hull: an invariant polytope of these ``2m`` matrices with ``||.||_P <= 1``
   (:func:`analysis.jsr.exact_polytope.exact_polytope_bound`: exact vertices, products applied to the exact roots)
   proves ``JSR(T(t)|U) <= lambda(t)`` on the whole of ``[a, t*]`` (hence ``= lambda(t)`` in the first case). The
   roots are the exact eigenvectors of the ``T_eps(t*)`` for ``theta``.
4. **The quotient**: the convex hull in ``t`` (Bernstein coefficients = the end values for an affine family),
   ``JSR(T(a) on R^n/U, T(t*) on R^n/U) < theta`` certified by the engine (:func:`analysis.jsr.jsr_bounds`).

Then ``JSR(T(t)) <= max(lambda(t), q) < theta`` for ``t`` in ``[a, t*)`` (``lambda(t) < theta`` away from
``t*``, ``q`` the quotient's bound): ``C^l`` on ``[a, t*)``, and ``JSR = lambda(t)`` wherever ``lambda(t) >= q``.

Examples
--------
A 2 x 2 toy family with ``theta = 1/2`` at the end ``t* = 1/2``: ``T_0(t) = [[t, 1/16], [0, 1/8]]`` and
``T_1(t) = [[1/8, 0], [1/16, t]]`` keep the eigenvectors ``(1, 0)`` and ``(0, 1)`` for the eigenvalue
``lambda(t) = t``; on ``[1/4, 1/2)`` the JSR is ``t < 1/2``:

>>> from flint import fmpq, fmpq_mat
>>> C = [[fmpq_mat([[0, fmpq(1, 16)], [0, fmpq(1, 8)]]), fmpq_mat([[1, 0], [0, 0]])],
...      [fmpq_mat([[fmpq(1, 8), 0], [fmpq(1, 16), 0]]), fmpq_mat([[0, 0], [0, 1]])]]
>>> r = close_end_strip(C, fmpq(1, 2), fmpq(1, 2), fmpq(1, 4), budget=5000)
>>> r["closed"], r["lambda"], r["leading_dimension"], r["polytope_bound"]
(True, '0 + 1*t', 2, Fraction(1, 1))

References
----------
R. M. Jungers, *The joint spectral radius: theory and applications*, Springer (2009), Prop. 1.5 (block
triangular families) and Prop. 1.8 (convex hull).
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear operators*, Found.
Comput. Math. 13 (2013) 37-97.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Sequence

from flint import fmpq, fmpq_mat

from ..jsr._work import Work

__all__ = ["close_end_strip", "QUOTIENT_FIRST"]

#: work units of the first attempt at the quotient's JSR bound (the rest of the budget is the second)
QUOTIENT_FIRST = 15_000


def _eye(n: int, s: fmpq) -> fmpq_mat:
    return fmpq_mat(n, n, [s if i == j else 0 for i in range(n) for j in range(n)])


def _kernel_cols(M: fmpq_mat) -> list[fmpq_mat]:
    from ..jsr._subspace import _kernel

    return [fmpq_mat(M.ncols(), 1, v) for v in _kernel(M)]


def _eigen_ratio(M: fmpq_mat, v: fmpq_mat):
    """``mu`` with ``M v = mu v`` exactly, or None."""
    w = M * v
    n = v.nrows()
    k = next(a for a in range(n) if v[a, 0] != 0)
    mu = w[k, 0] / v[k, 0]
    return mu if all(w[a, 0] == mu * v[a, 0] for a in range(n)) else None


def _tangent_slopes(T: fmpq_mat, C1: fmpq_mat, theta: fmpq):
    """The derivatives in ``t`` of the branches of the eigenvalue ``theta`` of ``T = T(t*)`` (``T'(t) = C1``) when
    it is semisimple: the eigenvalues of ``(L R)^-1 L C1 R`` for the left and right kernels ``L``, ``R`` (Kato,
    first-order perturbation of a semisimple eigenvalue), when they are all rational; else None."""
    R = _kernel_cols(T - _eye(T.nrows(), theta))
    L = _kernel_cols((T - _eye(T.nrows(), theta)).transpose())
    k, n = len(R), T.nrows()
    if k == 0 or len(L) != k:
        return None
    Rm = fmpq_mat(n, k, [R[c][a, 0] for a in range(n) for c in range(k)])
    Lm = fmpq_mat(k, n, [L[r][a, 0] for r in range(k) for a in range(n)])
    try:
        D = (Lm * Rm).inv() * (Lm * C1 * Rm)
    except ZeroDivisionError:
        return None
    roots = []
    _, factors = D.charpoly().factor()
    for f, e in factors:
        if f.degree() != 1:
            return None
        roots += [-f[0] / f[1]] * e
    return roots


def _primitive(v: fmpq_mat) -> list[fmpq]:
    """``v`` scaled to a vector of coprime integers (the roots are exact and dyadic in floats)."""
    from math import gcd, lcm

    n = v.nrows()
    den = 1
    for a in range(n):
        den = lcm(den, int(v[a, 0].q))
    ints = [int(v[a, 0] * den) for a in range(n)]
    g = 0
    for x in ints:
        g = gcd(g, x)
    return [fmpq(x // g) for x in ints]


def close_end_strip(C: Sequence[Sequence[fmpq_mat]], theta: fmpq, end: fmpq, start: fmpq, *,
                    budget: int = 200_000) -> dict:
    """Certify ``JSR(T_eps(t)) < theta`` for ``t`` in ``[start, end)`` (or ``(end, start]``) for the affine family
    ``T_eps(t) = C[eps][0] + t C[eps][1]`` with the exact end ``end`` (module docstring).

    ``budget``: work units (:class:`~analysis.jsr._work.Work`) for the float polytope and the quotient's JSR (the
    exact certificate of a closed polytope is not counted, as in :func:`analysis.jsr.jsr_bounds`).

    Returns ``{"closed": bool, "reason": str, "work": units, ...}``; when closed: ``letters`` (those with the
    eigenvalue ``theta`` at the end), ``lambda`` (``mu0 + mu1*t``), ``leading_dimension`` (``dim U``),
    ``polytope_vertices``, ``polytope_bound`` (exact, ``<= 1``), ``quotient_upper`` (``< theta``, or None when
    ``U`` is everything).
    """
    from ..jsr import jsr_bounds
    from ..jsr._polytope import build_polytope
    from ..jsr._subspace import _Echelon, _images, _rref_rows, split_family
    from ..jsr.exact_polytope import exact_polytope_bound, floats

    work = Work(budget)
    out: dict = {"closed": False, "reason": "", "work": 0}

    def done(reason=""):
        out["reason"] = reason
        out["work"] = work.spent
        return out

    if any(len(cs) != 2 for cs in C):
        return done("the family is not affine in the parameter")
    n = C[0][0].nrows()
    ends = [cs[0] + cs[1] * end for cs in C]
    lead = [(e, v) for e, T in enumerate(ends) for v in _kernel_cols(T - _eye(n, theta))]
    if not lead:
        return done(f"no single letter has the eigenvalue {theta} at the end")
    mus = {(_eigen_ratio(C[e][0], v), _eigen_ratio(C[e][1], v)) for e, v in lead}
    if len(mus) == 1 and None not in next(iter(mus)):
        (mu0, mu1), = mus
        kind = "eigenvalue"
    else:
        slopes = []
        for e in sorted({e for e, _ in lead}):
            c = _tangent_slopes(ends[e], C[e][1], theta)
            if c is None:
                return done(f"the eigenvector of T_{e} for {theta} at the end moves with the parameter, and the "
                            "eigenvalue's derivatives there are not rational (or it is not semisimple)")
            slopes += c
        mu1 = min(slopes) if start < end else max(slopes)     # the largest lambda on the strip's side
        mu0 = theta - mu1 * end
        kind = "tangent"
    lam = lambda t: mu0 + mu1 * t  # noqa: E731
    out.update({"letters": sorted({e for e, _ in lead}), "lambda": f"{mu0} + {mu1}*t", "mu": (mu0, mu1),
                "lambda_kind": kind})
    if mu1 == 0 or not (0 < lam(start) < theta):
        return done("the moving eigenvalue is not below theta and positive at the other end of the strip")
    # the smallest subspace holding the eigenvectors, invariant under every coefficient matrix
    gens = [c for cs in C for c in cs]
    ech, vecs, frontier = _Echelon(n), [], []
    for _, v in lead:
        x = [v[a, 0] for a in range(n)]
        if ech.add(x):
            vecs.append(x)
            frontier.append(x)
    while frontier:
        new = []
        for x in _images(frontier, gens, n):
            if ech.add(x):
                new.append(x)
                vecs.append(x)
        frontier = new
    rows = _rref_rows(vecs, n)
    d = len(rows)
    out["leading_dimension"] = d
    W = fmpq_mat(n, d, [rows[c][a] for a in range(n) for c in range(d)])
    hull_a = [cs[0] + cs[1] * start for cs in C]
    if d < n:
        top_a, bot_a = split_family(hull_a, W)
        top_e, bot_e = split_family(ends, W)
        split_family(gens, W)                 # raises ArithmeticError unless every coefficient leaves U invariant
    else:
        top_a, bot_a, top_e, bot_e = hull_a, [], ends, []
    # the roots in the coordinates of the basis W (its rows are in reduced echelon form: pivot entries)
    pivots = [next(j for j in range(n) if rows[i][j] != 0) for i in range(d)]
    roots = [_primitive(fmpq_mat(d, 1, [v[p, 0] for p in pivots])) for _, v in lead]
    hull = [M * (1 / lam(start)) for M in top_a] + [M * (1 / theta) for M in top_e]
    fl = floats(hull)
    poly_work = work.share(0.7)
    st = build_polytope(fl, 1.0, [[float(x) for x in u] for u in roots], work=poly_work, max_vertices=3000,
                        check_better=True)
    out["polytope_vertices"] = len(st.V)
    if not st.closed:
        return done(f"the float invariant polytope of the hull does not close ({st.stop_reason or 'a better product'})")
    cert = exact_polytope_bound(hull, fmpq(1), roots, st)
    if cert["bound"] is None or cert["bound"] > 1:
        return done(f"the exact polytope bound is not <= 1 ({cert.get('reason') or float(cert['bound'])})")
    out["polytope_bound"] = cert["bound"]
    out["polytope_vertices"] = cert["vertices"]          # the certified polytope's (the float one's plus the added)
    out["polytope_counts"] = {k: cert[k] for k in ("vertex_images", "exact_solves", "residual_bounds",
                                                   "added_vertices")}
    out["quotient_upper"] = None
    if bot_a:
        th = Fraction(int(theta.p), int(theta.q))
        for share in (QUOTIENT_FIRST, None):        # a small budget first: the quotient is usually well below
            units = max(1, work.left if share is None else min(share, work.left))
            r = jsr_bounds(bot_a + bot_e, budget=units)
            work.charge(r.provenance.get("work") or 0)
            if r.upper is not None and Fraction(str(r.upper)) < th or work.exhausted:
                break
        if r.upper is None or not Fraction(str(r.upper)) < th:
            return done(f"the quotient's JSR bound {r.upper} on the hull is not below {theta}")
        out["quotient_upper"] = r.upper
    out["closed"] = True
    return done()
