"""The certified C^l set of a one-parameter bivariate family ``a(t)``: where ``S_a(t)`` is ``C^l``, certified inside,
refuted outside, and the undecided gaps between them stated exactly.

Three certified ingredients (for an isotropic ``M``, :mod:`analysis.bivariate.holder`):

* **points**: the certified Hölder verdict at rational grid points (:func:`~analysis.bivariate.holder.holder_exponent`
  on the mask at that value, with its own invariant support);
* **closed boxes** ``[u, v]`` of C^l: the restricted transition operators ``T_eps(t)|V_{l+1}`` are matrix
  polynomials in ``t`` (exact, on the family's generic invariant support). On ``[u, v]`` each is a convex
  combination of its Bernstein coefficient matrices ``C_{eps,0..D}`` (``C_{eps,0} = T_eps(u)``,
  ``C_{eps,D} = T_eps(v)``), and the JSR of a set equals the JSR of its convex hull, so
  ``JSR(C_{eps,d}) < rho(M)^{-l}`` (the engine's certified upper bound, :func:`analysis.jsr.jsr_bounds`)
  proves ``C^l`` at every ``t`` of the box. At a value where a mask coefficient vanishes the support of the mask
  is smaller; its ``T|V`` is the restriction of the generic one to an invariant subspace, so the upper bound
  still holds there;
* **exact ends**: where a product ``Pi`` (the spectrum-maximising product found on the non-C^l side) has the
  eigenvalue ``+-rho(M)^{-l|Pi|}``: a root ``t*`` of ``det(Pi(t) -+ rho(M)^{-l|Pi|} I)`` (exact polynomial in
  ``t``, by evaluation at ``deg + 1`` rationals and interpolation), where ``JSR >= rho(M)^{-l}`` exactly, so
  ``S_a(t*)`` is not ``C^l`` (checked by a certified point verdict when ``t*`` is rational).

The boxes approach an end of eigenvalue type geometrically but never reach it (the JSR tends to
``rho(M)^{-l}``). The strip between the last C^l grid point and an exact rational end of an affine family is
first given to :func:`analysis.bivariate.end_strip.close_end_strip` (exact: the leading subspace split off, its
JSR bounded by an affine ``lambda(t)`` through an invariant polytope of the convex hull in ``1/lambda``, the
quotient by the engine; any number of letters with the eigenvalue at the end), then to the parametric invariant
polytope (:func:`analysis.jsr.parametric.close_family`, the one that closes such strips for curves; operators of
dimension at most ``MAX_STRIP_DIMENSION``, a single spectrum-maximising product with a simple leading eigenvalue
at the end). When neither closes it the strip stays *inconclusive*, reported with its width and the reasons. The same
concepts as the univariate ``range`` (:func:`analysis.regularity.ranges.ck_parameter_set`: certified grid
verdicts, exact eigenvalue crossings of the s.m.p., certified interior); the interior here is proven by the
convex-hull JSR on boxes instead of the Dyn–Levin norm sets (which need a factorisation the bivariate symbol
does not have). A tensor-product family (``M = m I``, a coefficient grid of rank 1) is reduced exactly to its two
univariate factors instead (:mod:`analysis.bivariate.tensor`; ``subdiv surface --C L --within`` takes that route).

Examples
--------
A perturbed tensor hat function: ``T_0(t)`` has the eigenvalue 1 exactly at ``t = 3/4`` (there the scheme is not
``C^0``), and its transition operators are affine in ``t``:

>>> from analysis.bivariate.mask import BivariateMask
>>> fam = BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2) + t*(1-z1**2)*(1-z2**2)/(z1*z2)")
>>> F = parametric_family(fam, 1)
>>> F.dim, F.special, F.degree
(15, (-1/4, 1/4), 1)
>>> f = F.crossing_polynomial((0,), 1)          # det(T_0(t) - I)
>>> [str(g) for g, _ in f.factor()[1] if g.degree() == 1]
['4*x + (-3)', '4*x + 3']

The whole C^0 set on ``[0, 1]`` (``ck_set(fam, 0, within=(0, 1), grid=2)``, about 5 s): C^0 certified on
``[0, 3/4)``, not C^0 at ``3/4`` (exact) and ``1``; the strip next to ``3/4`` by the leading subspace of
dimension 7, where the JSR is ``t + 1/4``.

References
----------
R. M. Jungers, *The joint spectral radius: theory and applications*, Springer (2009), Prop. 1.8 (the JSR of a
set equals that of its convex hull).
M. Charina, V. Yu. Protasov, *Regularity of anisotropic refinable functions*, ACHA 47 (2019) 795-821.
"""

from __future__ import annotations

from math import comb
from typing import Any, NamedTuple

import sympy as sp
from flint import fmpq, fmpq_mat, fmpq_poly

from ..algebra.algebraic import RealAlgebraic
from ..algebra.reader import as_expr
from ..jsr._work import Work
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from .holder import holder_exponent, smoothness_verdicts
from .mask import BivariateMask
from .transition import invariant_support, restricted_transition

__all__ = ["ParametricFamily", "parametric_family", "ck_set", "MAX_GRID", "MAX_DEGREE"]

#: the most grid cells of a C^l set
MAX_GRID = 64
#: the largest degree of a mask coefficient in the parameter
MAX_DEGREE = 6
#: the largest restricted dimension for which the strip next to an exact end is tried with the parametric
#: invariant polytope (:func:`analysis.jsr.parametric.close_family`)
MAX_STRIP_DIMENSION = 24
#: largest degree in t (word length x dimension x degree of the family) of a characteristic polynomial whose
#: square-free part is taken when proving a stretch not C^l
SQUAREFREE_DEGREE = 240
#: work budget of the exact end-strip argument (:func:`analysis.bivariate.end_strip.close_end_strip`: the leading
#: subspace split off, its JSR bounded by the moving eigenvalue through a convex hull in ``1/lambda``)
END_BUDGET = 250_000


def _q(x) -> fmpq:
    x = sp.Rational(x)
    return fmpq(int(x.p), int(x.q))


class ParametricFamily:
    """``T_eps(t)|V_k = sum_d t^d C[eps][d]`` (exact ``fmpq_mat``) on the generic invariant support of a
    one-parameter mask; ``special`` the rational values where a coefficient of the mask vanishes."""

    def __init__(self, general: BivariateMask, k: int):
        if len(general.params) != 1:
            raise AnalysisError("a C^l set needs a mask with exactly one free parameter (fix the others with --param)")
        p = general.params[0]
        degs = []
        special = set()
        self.vanishing = []             # the non-constant coefficient polynomials (their roots: smaller supports)
        for ij, v in general:
            try:
                P = sp.Poly(v, p)
            except sp.PolynomialError:
                raise AnalysisError(f"the coefficient {ij[0]},{ij[1]} is not a polynomial in {p.name}") from None
            degs.append(P.degree())
            if P.degree() >= 1:
                if not all(c.is_Rational for c in P.all_coeffs()):
                    raise AnalysisError("a C^l set needs rational coefficients in the parameter")
                special |= {r for r in sp.Poly(P, p).ground_roots() if r.is_Rational}
                self.vanishing.append(P)
        D = max(degs)
        if D > MAX_DEGREE:
            raise AnalysisError(f"the coefficients have degree {D} in {p.name} (limit {MAX_DEGREE})")
        self.param, self.degree, self.k = p, max(D, 1), k
        self.special = tuple(sorted(special))
        self.omega = invariant_support(general)
        nodes = [n for n in range(-MAX_DEGREE - 8, MAX_DEGREE + 9) if sp.Integer(n) not in special]
        nodes = sorted(nodes, key=abs)[: self.degree + 1]
        vals = [restricted_transition(general.at({p.name: sp.Integer(n)}), k, self.omega).matrices for n in nodes]
        self.dim = vals[0][0].nrows()
        self.n = len(vals[0])
        # power-basis coefficients by Newton interpolation, entry by entry (matrix arithmetic)
        self.C = [self._interpolate([fmpq(n) for n in nodes], [v[e] for v in vals]) for e in range(self.n)]

    @staticmethod
    def _interpolate(xs, ys):
        c = list(ys)
        m = len(xs)
        for j in range(1, m):
            for i in range(m - 1, j - 1, -1):
                c[i] = (c[i] - c[i - 1]) * (1 / (xs[i] - xs[i - j]))
        # Newton form to power basis: P = c0 + (t - x0)(c1 + (t - x1)(c2 + ...))
        coeffs = [c[-1]]
        for i in range(m - 2, -1, -1):
            new = [None] * (len(coeffs) + 1)
            # (t - x_i) * coeffs + c_i
            new[0] = c[i] - coeffs[0] * xs[i]
            for d in range(1, len(coeffs)):
                new[d] = coeffs[d - 1] - coeffs[d] * xs[i]
            new[len(coeffs)] = coeffs[-1]
            coeffs = new
        return coeffs

    def at(self, t) -> list[fmpq_mat]:
        t = t if isinstance(t, fmpq) else _q(t)
        out = []
        for cs in self.C:
            acc = cs[-1]
            for c in reversed(cs[:-1]):
                acc = acc * t + c
            out.append(acc)
        return out

    def bernstein(self, u, v) -> list[fmpq_mat]:
        """The Bernstein coefficient matrices of every ``T_eps`` on ``[u, v]`` (their convex hull holds
        ``T_eps(t)`` for every ``t`` in ``[u, v]``)."""
        u, h = _q(u), _q(v) - _q(u)
        D = len(self.C[0]) - 1
        out = []
        for cs in self.C:
            # Taylor shift t = u + h s: coefficients of s^d
            shifted = []
            for d in range(D + 1):
                acc = None
                for e in range(d, D + 1):
                    term = cs[e] * (fmpq(comb(e, d)) * u ** (e - d) * h ** d)
                    acc = term if acc is None else acc + term
                shifted.append(acc)
            for kk in range(D + 1):
                acc = None
                for d in range(kk + 1):
                    term = shifted[d] * fmpq(comb(kk, d), comb(D, d))
                    acc = term if acc is None else acc + term
                out.append(acc)
        return out

    def strip(self, theta):
        """The family ``T_eps(t)|V_k / theta`` as a :class:`analysis.jsr.parametric.ParametricStrip` (JSR < 1 there
        is C^l when ``theta = rho(M)^-l``)."""
        from ..jsr.parametric import ParametricStrip

        p, th = self.param, sp.Rational(theta)
        R = []
        for cs in self.C:
            n = cs[0].nrows()
            R.append(sp.Matrix(n, n, lambda i, j: sp.expand(sum(
                (sp.Rational(int(c[i, j].p), int(c[i, j].q)) * p ** d for d, c in enumerate(cs)), sp.Integer(0)) / th)))

        def det_minus_one(word):
            f = self.crossing_polynomial(word, _q(th) ** len(word))
            scale = _q(th) ** (len(word) * self.dim)        # det(Pi/theta^L - I) = det(Pi - theta^L I)/theta^(L d)
            return sp.Poly([sp.Rational(int(x.p), int(x.q)) / sp.Rational(int(scale.p), int(scale.q))
                            for x in reversed(f.coeffs())], p)

        return ParametricStrip(R, p, det_minus_one=det_minus_one)

    def crossing_polynomial(self, word, s: fmpq) -> fmpq_poly:
        """``det(Pi_word(t) - s I)`` as an exact polynomial in ``t`` (``word`` in the order of application)."""
        deg = len(word) * self.dim * (len(self.C[0]) - 1)
        xs = [fmpq(x) for x in range(deg + 1)]
        eye = fmpq_mat(self.dim, self.dim)
        for i in range(self.dim):
            eye[i, i] = s
        ys = []
        for x in xs:
            mats = self.at(x)
            P = None
            for i in word:
                P = mats[i] if P is None else mats[i] * P
            ys.append((P - eye).det())
        c = self._interpolate(xs, ys)
        return fmpq_poly(c)


def parametric_family(general: BivariateMask, k: int) -> ParametricFamily:
    """:class:`ParametricFamily` of the restrictions ``T_eps(t)|V_k``."""
    return ParametricFamily(general, k)


def _theta(m: int, l: int) -> sp.Rational:
    """``rho(M)^{-l} = |det M|^{-l/2}``, rational only when ``|det M|^l`` is a square."""
    r = sp.sqrt(sp.Integer(m) ** l)
    if not r.is_Rational:
        raise AnalysisError(f"rho(M)^-{l} = {m}^(-{l}/2) is irrational: the C^{l} set is computed only when "
                            f"|det M|^{l} is a square (e.g. an even order for the quincunx dilation)")
    return 1 / r


def _verdict(general, p, q, l, budget):
    try:
        h = holder_exponent(general.at({p.name: q}), budget=budget)
    except AnalysisError as exc:
        return {"t": q, "C^l": None, "alpha": None, "status": INCONCLUSIVE, "note": str(exc), "work": 0}
    v = smoothness_verdicts(h, max_l=max(l, h.witness["k"])).get(l)
    return {"t": q, "C^l": v, "alpha": (h.lower, h.upper), "status": h.status, "work": h.provenance.get("work") or 0,
            "product": tuple(h.witness["jsr"].witness.get("product") or ()), "k": h.witness["k"]}


def _box_certified(F: ParametricFamily, u, v, theta, budget: int, work: Work):
    from ..jsr import jsr_bounds

    r = jsr_bounds(F.bernstein(u, v), budget=budget)
    work.charge(r.provenance.get("work") or 0)
    ok = r.upper is not None and sp.Rational(r.upper) < theta
    return ok, r


def _crossings(F, word, theta, lo, hi, work: Work):
    """The exact roots in ``[lo, hi]`` where ``Pi_word(t)`` has the eigenvalue ``+-theta^|word|``."""
    p = F.param
    s = _q(theta) ** len(word)
    out = []
    for sgn in (1, -1):
        poly = F.crossing_polynomial(word, s * sgn)
        work.charge(len(word) * F.dim * (F.degree + 1) // 4 + 1)
        if poly.is_zero():
            continue
        _, factors = poly.factor()
        for f, _e in factors:
            P = sp.Poly([sp.Rational(int(x.p), int(x.q)) for x in reversed(f.coeffs())], p)
            if P.degree() < 1:
                continue
            for r in RealAlgebraic.roots_of(P):
                if r.compare(RealAlgebraic.rational(lo)) >= 0 and r.compare(RealAlgebraic.rational(hi)) <= 0:
                    out.append((r, sgn, word))
    return out


def single_parameter(general: BivariateMask, param=None) -> sp.Symbol:
    """The one free parameter of a family (``param``, if given, must name it); an :class:`AnalysisError` otherwise."""
    if len(general.params) != 1:
        raise AnalysisError("a C^l set needs a mask with exactly one free parameter (fix the others with --param)")
    p = general.params[0]
    if param is not None and str(param) != p.name:
        raise AnalysisError(f"unknown parameter {str(param)!r} (the family's parameter is {p.name})")
    return p


def _squarefree_signs(F, word, s: fmpq, p: sp.Symbol, work: Work) -> list:
    """``[(f, label), ...]`` for the square-free part ``g(x, t)`` of ``chi(x, t) = det(x I - Pi_word(t))`` (``g``
    monic in ``x`` up to a rational constant, a divisor of ``chi`` in ``Q[t][x]``): ``g(s, t) <= 0`` forces a real
    eigenvalue ``>= s`` and ``(-1)^deg g(-s, t) <= 0`` one ``<= -s``. ``chi`` by interpolation in ``x`` from the
    exact determinants ``det(Pi - k I)``, ``k = 0..n``; ``[]`` when ``g`` is not monic up to a constant."""
    x = sp.Dummy("x")
    n = F.dim
    pts = []
    for k in range(n + 1):
        poly = F.crossing_polynomial(word, fmpq(k))
        work.charge(len(word) * F.dim * (F.degree + 1) // 4 + 1)
        pts.append((k, (-1) ** n * sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(poly.coeffs())] or [0],
                                           p).as_expr()))
    chi = sp.Poly(sp.expand(sp.interpolate(pts, x)), x, p)
    g = sp.Poly(sp.sqf_part(chi.as_expr(), x, p), x, p)
    lc = sp.Poly(g.as_expr(), x).LC()
    if not (lc.is_Rational and lc != 0):
        return []
    d = sp.Poly(g.as_expr(), x).degree()
    q = sp.Rational(int(s.p), int(s.q))
    name = "".join(map(str, word))
    return [(sp.Poly(sp.expand(g.as_expr().subs(x, q) / lc), p),
             f"a real eigenvalue >= {sp.sstr(q)} of T_{name}({p.name}) (square-free characteristic polynomial)"),
            (sp.Poly(sp.expand((-1) ** d * g.as_expr().subs(x, -q) / lc), p),
             f"a real eigenvalue <= {sp.sstr(-q)} of T_{name}({p.name}) (square-free characteristic polynomial)")]


def _prove_not_cl(F, general, p, l, theta, lo, hi, words, point_budget, work: Work) -> str | None:
    """A proof that the family is not C^l at any ``t`` of the closed interval ``[lo, hi]`` (exact or algebraic
    ends), or ``None`` -- the argument of :func:`analysis.regularity.crossings._prove_not_cj`: with ``n = F.dim``,
    ``(-1)^n det(Pi_w(t) - theta^L I) <= 0`` forces a real eigenvalue ``>= theta^L`` of ``Pi_w(t)`` and
    ``det(Pi_w(t) + theta^L I) <= 0`` one ``<= -theta^L`` (intermediate values of the characteristic polynomial),
    hence ``JSR >= theta``: not C^l. The interval is cut at the real roots of these determinants (exact
    polynomials in ``t``, :meth:`ParametricFamily.crossing_polynomial`) and every piece must have one of them
    negative at a rational point inside. Candidates, one word at a time: ``words``, then the single digits. A
    special value of the family in ``[lo, hi]`` (where the generic support is too large) is decided by its own
    certified point verdict. Where the mask has more sum rules than generically (exceptional ``t``), the extra
    eigenvalues of the restricted operators have modulus about ``rho(M)^{-(l+1)|w|}``, below ``theta^|w|`` (``M``
    isotropic), so they never make a piece negative by themselves."""
    from ..regularity.crossings import sign_cover

    L, H = RealAlgebraic.from_expr(lo), RealAlgebraic.from_expr(hi)
    if L.compare(H) >= 0:
        return None
    for P in F.vanishing:      # an irrational value where a coefficient vanishes: no point verdict there
        if any(not r.is_rational and L.compare(r) <= 0 <= H.compare(r) for r in RealAlgebraic.roots_of(P)):
            return None
    specials = []
    for q in F.special:
        Q = RealAlgebraic.rational(q)
        if L.compare(Q) <= 0 <= H.compare(Q):
            v = _verdict(general, p, q, l, point_budget)
            work.charge(v["work"])
            if v["C^l"] is not False:
                return None
            specials.append(q)
    cands = [tuple(w) for w in words if w]
    cands += [(e,) for e in range(F.n) if (e,) not in cands]

    def batches():
        for word in cands:
            if work.exhausted:
                return
            s = _q(theta) ** len(word)
            out = []
            for sgn in (1, -1):
                poly = F.crossing_polynomial(word, s * sgn)
                work.charge(len(word) * F.dim * (F.degree + 1) // 4 + 1)
                P = sp.Poly([sp.Rational(int(x.p), int(x.q)) for x in reversed(poly.coeffs())] or [0], p)
                out.append((P if sgn < 0 else P * (-1) ** F.dim, "a real eigenvalue %s %s of T_%s(%s)" % (
                    ">=" if sgn > 0 else "<=", sp.sstr(sgn * sp.Rational(int(s.p), int(s.q))),
                    "".join(map(str, word)), p.name)))
            yield out
        # an eigenvalue of even multiplicity (symmetric schemes) hides from det(Pi - s I): the same signs on the
        # square-free part of the characteristic polynomial, a divisor of it for every t (operators up to 24)
        for word in cands if F.dim <= MAX_STRIP_DIMENSION else ():
            if work.exhausted:
                return
            if len(word) * F.dim * F.degree > SQUAREFREE_DEGREE:
                continue        # the dense polynomial in (x, t) would be too large (its sympy time is not metered)
            out = _squarefree_signs(F, word, _q(theta) ** len(word), p, work)
            if out:
                yield out

    how = sign_cover(L, H, batches())
    if how and specials:
        how += "; special value(s) %s by their point verdicts" % ", ".join(map(sp.sstr, specials))
    return how


def ck_set(general: BivariateMask, l: int, param=None, *, within=(0, 1), grid: int = 8,
           budget: int = 400_000, point_budget: int = 20_000, box_budget: int = 20_000, approach: int = 6,
           tol=sp.Rational(1, 10 ** 6), strip_budget: int = 30_000, end_budget: int = END_BUDGET) -> Result:
    """Where is the one-parameter bivariate family ``general`` ``C^l`` on ``within``?  (module docstring)

    ``value``: ``{"certified": [Part, ...]`` (proven C^l: intervals and points with exact ends), ``"not_Cl": [exact points certified not
    C^l], "gaps": [(lo, hi), ...]}`` (undecided between a certified C^l part and a certified counterexample).
    ``witness``: the grid verdicts (alpha enclosures), the boundaries with how they were found, the boxes with
    their JSR upper bounds, and ``between_counterexamples``: the grid cells with a counterexample at both ends
    (sampled there, not examined between). Status *certified* only when no gap is left and every grid verdict is decided.

    Budgets are work units, counted, never timed: ``point_budget`` per grid verdict, ``box_budget`` per box,
    ``budget`` in all (what is not examined when it is spent is reported as a gap); ``approach`` boxes at most
    toward each end of a run (halving the distance), ``tol`` the narrowest box.
    """
    p = single_parameter(general, param)
    D = general.dilation
    if not D.isotropic:
        raise AnalysisError("M is anisotropic: the Hölder exponent is not -log_rho(M) JSR (Charina-Protasov 2019); "
                            "C^l sets are computed for isotropic dilations only")
    if not (isinstance(grid, int) and 1 <= grid <= MAX_GRID):
        raise AnalysisError(f"the grid has 1 to {MAX_GRID} cells")
    lo, hi = (sp.Rational(as_expr(w)) for w in within)
    if not lo < hi:
        raise AnalysisError("within needs low < high")
    theta = _theta(D.m, l)
    from .algebra import sum_rules

    k_gen = sum_rules(general).value
    if k_gen < l + 1:
        raise AnalysisError(f"the family satisfies sum rules of order {k_gen} identically in {p.name}: "
                            f"C^{l} needs order {l + 1}")
    F = ParametricFamily(general, l + 1)
    work = Work(budget)
    pts = [lo + (hi - lo) * sp.Rational(i, grid) for i in range(grid + 1)]
    samples = []
    for q in pts:
        s = _verdict(general, p, q, l, point_budget)
        work.charge(s["work"])
        samples.append(s)
    certified: list[tuple] = []             # closed rational boxes (u, v) and certified points
    not_cl: list[RealAlgebraic] = [RealAlgebraic.rational(s["t"]) for s in samples if s["C^l"] is False]
    boundaries, boxes, gaps, outer = [], [], [], []
    cells = list(zip(samples[:-1], samples[1:]))

    def try_box(u, v, depth=0, split=True):
        if work.exhausted:
            return False
        ok, r = _box_certified(F, u, v, theta, box_budget, work)
        boxes.append({"from": u, "to": v, "jsr_upper": r.upper, "certified_Cl": ok})
        if ok:
            certified.append((u, v))
            return True
        if split and depth < 2 and v - u > tol:
            m = (u + v) / 2
            return try_box(u, m, depth + 1) & try_box(m, v, depth + 1)
        return False

    for s0, s1 in cells:
        if s0["C^l"] and s1["C^l"]:
            if not try_box(s0["t"], s1["t"]):
                gaps.append((s0["t"], s1["t"]))
        elif s0["C^l"] is False and s1["C^l"] is False:
            outer.append((s0["t"], s1["t"]))      # between two counterexamples: sampled, not examined
        elif s0["C^l"] is None or s1["C^l"] is None:
            gaps.append((s0["t"], s1["t"]))
        else:
            good, bad = (s0, s1) if s0["C^l"] else (s1, s0)
            rec = _boundary(F, general, p, l, theta, good, bad, work, point_budget, approach, tol,
                            try_box, certified, not_cl, gaps, strip_budget, end_budget)
            boundaries.append(rec)
            if "exact" in rec and RealAlgebraic.from_expr(rec["exact"]).compare(RealAlgebraic.rational(bad["t"])):
                # from the exact end to the counterexample of the grid: sampled, not examined
                outer.append((rec["exact"], bad["t"]) if bad["t"] > good["t"] else (bad["t"], rec["exact"]))
    # between counterexamples: proven not C^l where one product has a real eigenvalue of modulus >= theta^L
    proven_not = []
    for a_, b_ in list(outer):
        words = [s.get("product") for s in samples if s["C^l"] is False and a_ <= s["t"] <= b_]
        words += [tuple(rec["word"]) for rec in boundaries if "word" in rec and rec["exact"] in (a_, b_)]
        how = _prove_not_cl(F, general, p, l, theta, a_, b_, words, point_budget, work)
        if how:
            outer.remove((a_, b_))
            proven_not.append({"from": a_, "to": b_, "how": how})
    for s in samples:
        if s["C^l"]:
            certified.append((s["t"], s["t"]))
    cert_set = sp.Union(*[sp.Interval(*c) for c in certified]) if certified else sp.EmptySet
    not_pts = sorted({x for x in not_cl}, key=float)
    gap_list = _merge([g for g in gaps])
    undecided = [s["t"] for s in samples if s["C^l"] is None]
    # a cell between two counterexamples is sampled, not examined: the set is then not proven there
    status = CERTIFIED if not gap_list and not undecided and not outer else INCONCLUSIVE
    prov: dict[str, Any] = {"method": "certified Hölder verdicts at grid points; exact s.m.p. eigenvalue crossings "
                                      "(not C^l); JSR of the Bernstein coefficient matrices on boxes (C^l on the box); next to an "
                                      "exact end, a leading invariant subspace and an exact invariant polytope of the "
                                      "convex hull in 1/lambda (the end strip)",
                            "work": work.spent, "budget": budget, "grid": grid}
    if gap_list:
        prov["message"] = ("undecided: " + ", ".join(f"({sp.sstr(a)}, {sp.sstr(b)}) (width {float(b - a):.3g})"
                                                      for a, b in gap_list)
                           + "; next to an end of eigenvalue type the boxes never reach the end (the JSR tends to "
                             "rho(M)^-l there)")
    if outer:
        prov["message"] = ((prov["message"] + "; " if "message" in prov else "")
                           + "not C^%d is certified at the counterexamples only (grid points and exact ends), not between "
                             "them: " % l
                           + ", ".join(f"({sp.sstr(a)}, {sp.sstr(b)})" for a, b in outer)
                           + " (sampled, not examined)")
    return Result(value={"certified": _intervals(cert_set), "not_Cl": [x.expr for x in not_pts], "gaps": gap_list},
                  status=status,
                  witness={"parameter": p.name, "l": l, "theta": theta, "samples": samples, "boundaries": boundaries,
                           "boxes": boxes, "undecided": undecided, "between_counterexamples": outer,
                           "not_Cl_proven": proven_not, "special": F.special, "dimension": F.dim,
                           "omega": len(F.omega)},
                  provenance=prov)


class Part(NamedTuple):
    """A part of a certified set: an interval with exact ends (a point when ``start == end``)."""

    start: sp.Expr
    end: sp.Expr
    left_open: bool = False
    right_open: bool = False


def _intervals(S) -> list[Part]:
    if S == sp.EmptySet:
        return []
    parts = S.args if isinstance(S, sp.Union) else (S,)
    out = []
    for x in parts:
        if isinstance(x, sp.FiniteSet):
            out += [Part(y, y) for y in x]
        else:
            out.append(Part(x.start, x.end, bool(x.left_open), bool(x.right_open)))
    return sorted(out, key=lambda I: float(I.start))


def _merge(gaps):
    out = []
    for a, b in sorted(gaps, key=lambda g: float(g[0])):
        if out and float(out[-1][1]) > float(a):
            out[-1] = (out[-1][0], max(out[-1][1], b, key=float))
        else:
            out.append((a, b))
    return out


def _boundary(F, general, p, l, theta, good, bad, work, point_budget, approach, tol, try_box, certified, not_cl,
              gaps, strip_budget=0, end_budget=0) -> dict:
    """Locate the end of C^l between a certified C^l grid point and a certified counterexample, and cover
    the part next to it by boxes; what stays between the last box and the end is a gap."""
    g, b = good["t"], bad["t"]
    side = 1 if b > g else -1
    words = []
    for w in (bad.get("product") or (), ):
        if w and w not in words:
            words.append(tuple(w))
    words += [(e,) for e in range(F.n) if (e,) not in words]
    cands = []
    for w in words[:F.n + 1]:
        if work.exhausted:
            break
        cands += _crossings(F, w, theta, min(g, b), max(g, b), work)
    G = RealAlgebraic.rational(g)
    cands = [c for c in cands if c[0].compare(G) != 0]
    cands.sort(key=lambda c: side * float(c[0]))
    rec: dict[str, Any] = {"between": (min(g, b), max(g, b)), "certified_Cl_at": g, "certified_not_Cl_at": b}
    end = RealAlgebraic.rational(b)
    for r, sgn, w in cands:
        # an eigenvalue +-theta^L of Pi(r) gives JSR >= theta at r: not C^l, exactly -- except at a value where a
        # coefficient vanishes (the generic support is too large there): decided by the point verdict
        if not r.is_rational and any(r.sign_of(P) == 0 for P in F.vanishing):
            continue        # a coefficient vanishes at this irrational t*: the generic eigenvalue proves nothing
        if r.is_rational and r.expr in F.special:
            v = _verdict(general, p, r.expr, l, point_budget)
            work.charge(v["work"])
            if v["C^l"] is not False:
                continue
        end = r
        rec.update({"exact": r.expr, "exact_float": float(r), "certified_not_Cl_at": r.expr, "word": list(w),
                    "how": f"eigenvalue {'-' if sgn < 0 else ''}{sp.sstr(theta ** len(w))} of "
                           f"T_{''.join(map(str, w))}({p.name})"})
        break
    not_cl.append(end)
    # boxes from the good point toward the end: halve the distance each time
    e_q = end.expr if end.is_rational else (end.rational_below() if side > 0 else end.rational_above())
    x = g
    last = g
    for _ in range(approach):
        nxt = x + (sp.Rational(e_q) - x) / 2
        nxt = sp.nsimplify(nxt, rational=True)
        u, v = (x, nxt) if side > 0 else (nxt, x)
        if abs(nxt - x) < tol or not try_box(u, v, split=False):
            break
        last = x = nxt
    rec["certified_Cl_to"] = last
    lo_gap, hi_gap = (last, end.expr) if side > 0 else (end.expr, last)
    if "exact" in rec and end.is_rational and F.degree == 1 and end_budget and not work.exhausted:
        closed = _end_strip(F, theta, g, end, side, rec, work, end_budget, certified)
        if closed:
            return {**rec, "status": CERTIFIED}
    if "exact" in rec and strip_budget and F.dim > MAX_STRIP_DIMENSION:
        rec["strip"] = {"closed": False, "reason": f"not attempted: the operators have dimension {F.dim} > "
                                                   f"{MAX_STRIP_DIMENSION} (the exact matrix polynomials are too large)"}
    elif "exact" in rec and strip_budget and not work.exhausted:
        from ..jsr.parametric import close_family

        try:
            c = close_family(F.strip(theta), lo_gap, hi_gap, lo_open=side < 0, hi_open=side > 0,
                             budget=min(strip_budget, max(1, int(work.left))))
        except (AnalysisError, ArithmeticError, ValueError) as exc:
            c = {"closed": False, "reason": f"{type(exc).__name__}: {exc}", "work": 0}
        work.charge(c.get("work", 0))
        rec["strip"] = {"closed": c["closed"], "reason": c.get("reason", ""), "work": c.get("work", 0),
                        **({"product": "".join(map(str, c["word"])), "pieces": len(c["pieces"])} if c["closed"] else {})}
        if c["closed"]:
            rec["certified_Cl_to"] = rec["exact"]
            certified.append((lo_gap, hi_gap, side < 0, side > 0))
            return {**rec, "status": CERTIFIED}
    gaps.append((lo_gap, hi_gap))
    rec["status"] = CERTIFIED if "exact" in rec else INCONCLUSIVE
    return rec


def _end_strip(F, theta, g, end, side, rec, work, end_budget, certified) -> bool:
    """The strip between the C^l grid point ``g`` and the exact rational end, by
    :func:`analysis.bivariate.end_strip.close_end_strip` (exact: leading subspace, hull in ``1/lambda``,
    quotient); records ``rec["end_strip"]`` and, when it closes, the certified half-open interval."""
    from .end_strip import close_end_strip

    try:
        c = close_end_strip(F.C, _q(theta), _q(end.expr), _q(g), budget=min(end_budget, max(1, int(work.left))))
    except (ArithmeticError, ValueError, ZeroDivisionError) as exc:
        c = {"closed": False, "reason": f"{type(exc).__name__}: {exc}", "work": 0}
    work.charge(c.get("work", 0))
    info = {k: c[k] for k in ("closed", "reason", "work", "letters", "lambda", "lambda_kind", "leading_dimension",
                              "polytope_vertices", "polytope_bound", "quotient_upper") if k in c}
    if "mu" in c:
        (m0, m1), q = c["mu"], lambda x: sp.Rational(int(x.p), int(x.q))
        info["lambda"] = q(m0) + q(m1) * F.param
    for k in ("polytope_bound", "quotient_upper"):
        if info.get(k) is not None:
            info[k] = sp.Rational(str(info[k]))
    rec["end_strip"] = info
    if not c["closed"]:
        return False
    lo, hi = (g, end.expr) if side > 0 else (end.expr, g)
    certified.append((lo, hi, side < 0, side > 0))
    rec["certified_Cl_to"] = rec["exact"]
    rec["strip"] = {"closed": True, "method": "leading subspace and convex hull in 1/lambda", "from": g,
                    "work": c.get("work", 0)}
    return True
