"""A parametric invariant polytope: ``JSR(R_0(t), ..., R_{m-1}(t)) < 1`` certified on a whole interval of ``t`` for
matrix polynomials ``R_eps(t)`` (exact), up to an end where the spectral radius of the spectrum-maximising product
reaches 1 (an open end). The algorithm (Guglielmi–Protasov vertices that move with ``t``, Krawczyk enclosures of
the eigenpair, centred forms, exact root isolation near the end) is described in :mod:`analysis.regularity.strips`,
which applies it to the transition matrices of a univariate difference scheme; :mod:`analysis.bivariate.ranges`
applies it to the restricted transition operators of a bivariate family. Where the matrices come from does not
matter here.

References
----------
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear operators*, Found.
Comput. Math. 13 (2013) 37-97.
R. Krawczyk, *Newton-Algorithmen zur Bestimmung von Nullstellen mit Fehlerschranken*, Computing 4 (1969) 187-201.
"""

from __future__ import annotations

import itertools
import time
from fractions import Fraction

import numpy as np
import sympy as sp
from flint import arb, arb_mat, ctx, fmpq

from ..algebra.algebraic import RealAlgebraic
from ..algebra.reader import as_expr
from ._lsq import lstsq_solution
from ._pivots import qr_pivots
from ._polytope import build_polytope
from ._work import Work

__all__ = ["ParametricStrip", "close_family", "DEFAULT_STRIP_BUDGET"]

PREC = 128
#: default work budget of :func:`close_strip` (units: see there)
DEFAULT_STRIP_BUDGET = 30_000
#: work budget of the float invariant polytope at the end point (units of :func:`build_polytope`)
SETUP_BUDGET = 20_000
#: work units of a certification step on a sub-interval (about a millisecond of CPU each on the
#: reference machine): ``STEP_UNITS`` for the eigenpair enclosure, ``VERTEX_UNITS`` per vertex and
#: letter of the vertex words (centred forms along the words), ``IMAGE_UNITS`` per image bounded and
#: ``LP_UNITS`` per fresh coefficient LP
STEP_UNITS = 1.3
VERTEX_UNITS = 0.005
IMAGE_UNITS = 0.03
LP_UNITS = 3.5


def _poly_entries(M: sp.Matrix, p: sp.Symbol):
    return [[[fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q)) for c in reversed(sp.Poly(e, p).all_coeffs())]
             for e in M.row(i)] for i in range(M.rows)]


def _eval_arb(P, t: arb) -> arb_mat:
    """Horner evaluation of a matrix of rational polynomials at a ball ``t``."""
    rows = []
    for row in P:
        r = []
        for cs in row:
            acc = arb(0)
            for c in reversed(cs):
                acc = acc * t + arb(c)
            r.append(acc)
        rows.append(r)
    return arb_mat(rows)


def _word_matrix(mats, word):
    P = np.eye(mats[0].shape[0])
    for i in word:             # application order: first letter applied first
        P = mats[i] @ P
    return P


def _smp(mats, max_len=6):
    best = (-1.0, None)
    for L in range(1, max_len + 1):
        for w in itertools.product(range(len(mats)), repeat=L):
            rho = float(np.max(np.abs(np.linalg.eigvals(_word_matrix(mats, w))))) ** (1.0 / L)
            if rho > best[0] * (1 + 1e-9):
                best = (rho, w)
    return best


def _float_eig(mats, word, m=None):
    P = _word_matrix(mats, word)
    w, U = np.linalg.eig(P)
    i = int(np.argmax(np.abs(w)))
    lam = w[i]
    others = np.delete(np.abs(w), i)
    if abs(lam.imag) > 1e-9 * abs(lam) or lam.real <= 0 or (len(others) and others.max() > abs(lam) * (1 - 1e-6)):
        return None
    v = np.real(U[:, i])
    if m is None:
        m = int(np.argmax(np.abs(v)))
    return float(lam.real), v / v[m], m


def _krawczyk(PiA, xt: np.ndarray, lam: float, m: int):
    """Enclosure ``(v, lambda)`` (arb lists) of the unique eigenpair of ``PiA`` (an arb_mat valid
    for every t in the interval) near ``(xt, lam)`` with ``v_m = 1``, or None."""
    d = PiA.nrows()
    idx = [k for k in range(d) if k != m]

    def F(v, l):
        return [sum((PiA[r, s] * v[s] for s in range(d)), arb(0)) - l * v[r] for r in range(d)]

    def J(v, l):
        return arb_mat([[PiA[r, s] - (l if r == s else 0) for s in idx] + [-v[r]] for r in range(d)])

    # float Jacobian inverse
    Pf = np.array([[float(PiA[r, s].mid()) for s in range(d)] for r in range(d)])
    Jf = np.column_stack([Pf[:, idx] - lam * np.eye(d)[:, idx], -xt])
    try:
        Y = np.linalg.inv(Jf)
    except np.linalg.LinAlgError:
        return None
    Ya = arb_mat([[arb(float(y)) for y in row] for row in Y])
    xa = [arb(float(x)) for x in xt]
    xa[m] = arb(1)
    la = arb(lam)
    Fx = F(xa, la)
    YF = Ya * arb_mat([[f] for f in Fx])
    I_d = arb_mat([[1 if r_ == s else 0 for s in range(d)] for r_ in range(d)])

    def K_of(box):
        X = list(xa)
        for k, i in enumerate(idx):
            X[i] = xa[i] + box[k]
        M = I_d - Ya * J(X, la + box[d - 1])
        return [-YF[k, 0] + sum((M[k, s] * box[s] for s in range(d)), arb(0)) for k in range(d)]

    r = 2 * max(float(abs(YF[k, 0]).upper()) for k in range(d)) + 1e-30
    for _ in range(40):
        box = [arb(0, r) for _ in range(d)]
        K = K_of(box)
        if all(box[k].contains_interior(K[k]) for k in range(d)):
            v = list(xa)
            for k, i in enumerate(idx):
                v[i] = xa[i] + K[k]
            return v, la + K[d - 1]
        r *= 2
        if r > 0.1:
            break
    return None


class ParametricStrip:
    """The matrix polynomials ``R_0(t), ..., R_{m-1}(t)`` (sympy matrices, exact polynomials in ``p``) whose
    JSR is to be certified below 1 on an interval, with the eigenvalues ``mus`` split off before (reported) and an
    exact flip ``J`` (``J R_eps J = R_{m-1-eps}``) or None. ``det_minus_one(word)``: optional, the exact
    polynomial ``det(R_word(t) - I)`` (else a Berkowitz determinant)."""

    det_minus_one = None

    def __init__(self, R, p: sp.Symbol, mus=(), J=None, det_minus_one=None):
        self.det_minus_one = det_minus_one
        arity = len(R)
        self.p, self.arity = p, arity
        self.mus = list(mus)
        self.mu = self.mus[0] if self.mus else None
        self.R = R
        self.P = [_poly_entries(M, p) for M in R]
        self.dP = [_poly_entries(M.diff(p), p) for M in R]
        self.f = [sp.lambdify(p, M, "numpy") for M in R]
        self._supp: dict = {}
        self.J = None if J is None else arb_mat([[int(x) for x in J.row(i)] for i in range(J.rows)])
        self.Jf = None if J is None else np.array(J.tolist(), dtype=float)

    def floats(self, t: float):
        return [np.array(f(t), dtype=float) for f in self.f]

    def setup(self, t_end: float, work: Work):
        mats = self.floats(t_end)
        flip = self.arity - 1                 # the flip maps the letter eps to flip - eps
        rho, word = _smp(mats, 6 if self.arity <= 3 else max(2, int(np.log(2000) / np.log(self.arity))))
        fe, base = _float_eig(mats, word), word
        if fe is None and _float_eig(mats, word + word) is not None:
            word = word + word                # a simple real negative leading eigenvalue: Pi^2
            fe = _float_eig(mats, word)
        if fe is None:
            return f"the leading eigenvalue of the candidate product {word} is not simple, real and positive"
        lam, v, m = fe
        self.word, self.p_len, self.m = word, len(word), m
        r = lam ** (1.0 / len(word))
        mirrored = tuple(flip - x for x in word)
        if self.J is not None and any(mirrored == tuple(word[k:] + word[:k]) for k in range(len(word))):
            self.J = self.Jf = None          # J v is already on the orbit of v
        roots = [v] if self.J is None else [v, self.Jf @ v]
        setup = Work(SETUP_BUDGET)
        st = build_polytope(mats, r, roots, work=setup, max_vertices=400, check_better=True)
        work.charge(setup.spent)          # the march's budget pays for the setup too
        if not st.closed:
            return f"the float invariant polytope at the end does not close ({st.stop_reason})"
        if any(ro >= len(roots) for ro in st.root_of):
            return "the eigenvector orbit does not span the space (a further invariant subspace)"
        verts = list(zip(st.root_of, st.path))
        if self.J is not None:            # close the vertex set under the flip: J v_(r, w) = v_(1-r, mirror w)
            have = set(verts)
            for ro, pa in list(verts):
                mate = (1 - ro, tuple(flip - x for x in pa))
                if mate not in have:
                    have.add(mate)
                    verts.append(mate)
        self.roots = [ro for ro, _ in verts]
        self.paths = [pa for _, pa in verts]
        index = {vp: k for k, vp in enumerate(verts)}
        # the cycles of the roots' products (the mirrored root's: mirrored). With Pi = B^2 (B with a simple
        # negative leading eigenvalue) B v = -lambda^(1/2) v exactly: stripping B maps an image to minus a
        # vertex, of polytope norm 1 as well (the polytope is symmetric)
        cycles = [tuple(base), tuple(flip - x for x in base)]
        self.identity, self.checks = {}, []
        fl = self.vertices_float(t_end)
        if fl is None:
            return "the leading eigenvalue at the end is not simple"
        _, lam_e, _, Vf = fl
        Vm = np.array(Vf).T
        if np.linalg.matrix_rank(Vm) < Vm.shape[0]:
            return "the vertices do not span the space"
        for k, (ro, pa) in enumerate(verts):
            for i in range(len(mats)):
                w = pa + (i,)
                cyc = cycles[ro]
                while w[: len(cyc)] == cyc and len(w) >= len(cyc):
                    w = w[len(cyc):]
                if (ro, w) in index:
                    self.identity[(i, k)] = index[(ro, w)]
                    continue
                lp = _l1_coefficients(Vm, mats[i] @ Vf[k] / lam_e ** (1.0 / self.p_len))
                if lp is None or 1 - float(np.sum(np.abs(lp[1]))) <= 1e-9:
                    return (f"an image that is not a vertex lies on (or outside) the polytope's boundary at the end "
                            f"(vertex {k}, matrix {i}): a second s.m.p. or a non-generic end")
                self.checks.append((i, k, lp[0]))
        self.units = 0.0                  # work of the certification steps (STEP_UNITS, ...)
        return None

    def vertices_float(self, t: float):
        mats = self.floats(t)
        fe = _float_eig(mats, self.word, self.m)
        if fe is None:
            return None
        lam, v, _ = fe
        s = lam ** (1.0 / self.p_len)
        rv = [v] if self.J is None else [v, self.Jf @ v]
        # the vertex words form a tree: each prefix product is formed once (the same products, in
        # the same order, as :func:`_word_matrix` word by word)
        prods = {(): np.eye(mats[0].shape[0])}

        def prod(pa):
            P = prods.get(pa)
            if P is None:
                P = prods[pa] = mats[pa[-1]] @ prod(pa[:-1])
            return P

        V = [prod(pa) @ rv[ro] / s ** len(pa) for ro, pa in zip(self.roots, self.paths)]
        return mats, lam, v, V

    def certify(self, u: Fraction, w: Fraction):
        old = ctx.prec
        try:
            return self._certify(u, w)
        finally:
            ctx.prec = old              # the global precision is restored (other code and doctests rely on it)

    def _certify(self, u: Fraction, w: Fraction):
        """Certify invariance on ``[u, w]`` (rationals); ``((v, lambda) enclosures over the interval,
        witness)`` or None.

        Every vertex and residual is enclosed in the centred (mean-value) form ``f(t) in f(t_m) +
        f'(I) [-h, h]`` (``t_m`` the midpoint, ``h`` the half-width), the derivatives enclosed by
        forward differentiation over ``I``: the widths are ``O(h)`` without the dependency blow-up of
        a naive interval evaluation along long vertex words."""
        tmq = (u + w) / 2
        self.units += STEP_UNITS
        fl = self.vertices_float(float(tmq))
        if fl is None:
            return None
        mats, lam_f, v_f, Vf = fl
        ctx.prec = PREC
        T = arb(fmpq(u.numerator, u.denominator)).union(arb(fmpq(w.numerator, w.denominator)))
        Tm = arb(fmpq(tmq.numerator, tmq.denominator))
        hq = (w - u) / 2
        H = arb(fmpq(-hq.numerator, hq.denominator)).union(arb(fmpq(hq.numerator, hq.denominator)))
        RI = [_eval_arb(P, T) for P in self.P]             # over I
        RM = [_eval_arb(P, Tm) for P in self.P]            # at the midpoint
        DI = [_eval_arb(P, T) for P in self.dP]            # derivatives over I

        def word_prod(R, word):
            X = None
            for i in word:
                X = R[i] if X is None else R[i] * X
            return X

        PiI, PiM = word_prod(RI, self.word), word_prod(RM, self.word)
        # Pi'(I) by the product rule
        dPi = None
        X = None
        for i in self.word:
            if X is None:
                X, dPi = RI[i], DI[i]
            else:
                dPi = DI[i] * X + RI[i] * dPi
                X = RI[i] * X
        encI = _krawczyk(PiI, v_f, lam_f, self.m)
        encM = _krawczyk(PiM, v_f, lam_f, self.m)
        if encI is None or encM is None:
            return None
        vI, lI = encI
        vM, lM = encM
        if not (lI > 0 and all(x.contains(y) for x, y in zip(vI, vM)) and lI.contains(lM)):
            return None
        d = len(vI)
        idx = [k for k in range(d) if k != self.m]
        # (v', lambda') over I: J (v'_idx, lambda') = -Pi'(t) v (implicit function theorem); then
        # the centred forms v(I) in v(t_m) + v'(I) [-h, h] tighten v(I), and again
        for _ in range(3):
            J = arb_mat([[PiI[r, c] - (lI if r == c else 0) for c in idx] + [-vI[r]] for r in range(d)])
            rhs = -(dPi * arb_mat([[x] for x in vI]))
            try:
                sol = J.solve(rhs)
            except ZeroDivisionError:
                return None
            dv = [arb(0)] * d
            for k, i in enumerate(idx):
                dv[i] = sol[k, 0]
            dl = sol[d - 1, 0]
            vI = [x if x.rad() <= (y + z * H).rad() else y + z * H for x, y, z in zip(vI, vM, dv)]
            lI = lI if lI.rad() <= (lM + dl * H).rad() else lM + dl * H
        pinv = arb(1) / self.p_len
        # centred forms: (mid, over I, derivative over I)
        sM, sI = lM ** (-pinv), lI ** (-pinv)
        dsI = -pinv * lI ** (-pinv - 1) * dl
        col = lambda xs: arb_mat([[x] for x in xs])

        def step(i, xm, xi, dx):
            """x -> R_i x lambda^(-1/p)."""
            ym, yi = RM[i] * xm, RI[i] * xi
            dy = DI[i] * xi + RI[i] * dx
            zm = ym * sM
            zi = yi * sI
            dz = dy * sI + yi * dsI
            zi = _tighter(zi, zm + dz * H)
            return zm, zi, dz

        self.units += VERTEX_UNITS * d * sum(len(pa) + 1 for pa in self.paths)
        x0 = (col(vM), _tighter(col(vI), col(vM) + col(dv) * H), col(dv))
        starts = [x0] if self.J is None else [x0, tuple(self.J * y for y in x0)]
        # the centred form of R_w x_root lambda^(-|w|/p) along each vertex word; the words form a tree,
        # so each prefix is stepped once (``step`` is a function of its arguments: the same balls as
        # stepping every word from its root)
        walked = {}

        def walk(ro, pa):
            x = walked.get((ro, pa))
            if x is None:
                x = walked[(ro, pa)] = starts[ro] if not pa else step(pa[-1], *walk(ro, pa[:-1]))
            return x

        verts = [walk(ro, pa) for ro, pa in zip(self.roots, self.paths)]
        Vm = np.array(Vf).T
        piv = qr_pivots(Vm)
        basis = [int(b) for b in piv[:d]]
        G = arb_mat([[verts[b][1][r, 0] for b in basis] for r in range(d)])
        try:
            Gi = G.inv()
        except ZeroDivisionError:
            return None
        gi_norm = max((sum((abs(Gi[r, c]) for r in range(d)), arb(0)) for c in range(d)),
                      key=lambda b: float(b.upper()))
        worst = 0.0
        for i, k, supp in self.checks:
            xf = mats[i] @ Vf[k] / lam_f ** (1.0 / self.p_len)
            bound = None
            # the support of the previous interval first (a least-squares solve), then a fresh LP
            for fresh in ((False, True) if (i, k) in self._supp else (True,)):
                self.units += IMAGE_UNITS * d
                if fresh:
                    self.units += LP_UNITS
                    lp = _l1_coefficients(Vm, xf)
                    if lp is None:
                        return None
                    supp, cf = lp
                else:
                    supp = self._supp[(i, k)]
                    cf = lstsq_solution(Vm[:, supp], xf)
                bound = self._image_bound(walk(self.roots[k], self.paths[k] + (i,)), verts, Gi, H, supp, cf)
                if bound < 1:
                    self._supp[(i, k)] = supp
                    break
            worst = max(worst, float(bound.upper()))
            if not bound < 1:
                return None
        return (vI, lI), {"from": u, "to": w, "lambda": lI, "max_image_norm_upper": worst,
                          "basis_inverse_norm_upper": float(gi_norm.upper())}

    @staticmethod
    def _image_bound(image, verts, Gi, H, supp, cf) -> arb:
        """Upper bound (a ball) of ``||x||_P`` over the interval for the image ``x = R_i v_k / lambda^(1/p)``
        (``image``: its centred form): ``||c||_1 + ||G^-1 res||_1`` with the residual ``res = x - V c`` in its
        centred form (``res`` is a combination of the basis vertices, so ``||res||_P <= ||G^-1 res||_1``)."""
        d = Gi.nrows()
        # the coefficients rounded to multiples of 2^-50 (np.round rounds half to even, as round() does;
        # the scaling by 2^50 and back is exact, so each ball is the exact dyadic int(x) / 2^50)
        cq = [arb(x) for x in (np.round(np.asarray(cf, dtype=float) * 2.0 ** 50) * 2.0 ** -50).tolist()]
        rm, _, dr = image
        for j, cj in zip(supp, cq):
            rm, dr = rm - verts[j][0] * cj, dr - verts[j][2] * cj
        gres = Gi * (rm + dr * H)
        return sum((abs(cj) for cj in cq), arb(0)) + sum((abs(gres[r, 0]) for r in range(d)), arb(0))


def _l1_coefficients(Vm: np.ndarray, x: np.ndarray):
    """A basic solution of ``min ||c||_1, V c = x`` (HiGHS), polished on its support (float; the
    certificate re-checks everything in Arb). The LP is :func:`~analysis.jsr._lp.small_lp`, bit for bit
    ``linprog(ones(2N), A_eq=[V, -V], b_eq=x, bounds=(0, None), method="highs")`` without its overhead."""
    from ._lp import small_lp

    lp = small_lp(Vm, x)
    if lp is None:
        return None
    c = lp[1]
    supp = np.flatnonzero(np.abs(c) > 1e-12)
    if len(supp) == 0:
        return supp, c[supp]
    cs = lstsq_solution(Vm[:, supp], x)
    return supp, cs


def _tighter(a: arb_mat, b: arb_mat) -> arb_mat:
    """Entrywise the narrower of two enclosures of the same vector."""
    return arb_mat([[a[r, 0] if a[r, 0].rad() <= b[r, 0].rad() else b[r, 0]] for r in range(a.nrows())])


def _rq(x: sp.Expr) -> Fraction:
    x = sp.Rational(x)
    return Fraction(int(x.p), int(x.q))


def close_family(S: "ParametricStrip", lo, hi, *, lo_open: bool = False, hi_open: bool = False,
                 max_depth: int = 20, budget: int = 120_000, floor: list | None = None) -> dict:
    """Certify ``JSR(R_0(t), ..., R_{m-1}(t)) < 1`` for ``t`` between ``lo`` and ``hi`` (exact; an open end is
    where the spectral radius of the s.m.p. reaches 1) for the matrix polynomials of ``S``
    (:class:`ParametricStrip`; algorithm: :mod:`analysis.regularity.strips`).

    ``budget``: work units (counted, never timed; about a millisecond of CPU each on the reference
    machine) for the float polytope at the end (:func:`~analysis.jsr._polytope.build_polytope`'s units)
    and the march: every certification step on a sub-interval costs ``STEP_UNITS``, ``VERTEX_UNITS``
    per vertex and letter of the vertex words, ``IMAGE_UNITS`` per image it bounds and ``LP_UNITS`` per
    fresh coefficient LP (the dimension ``d`` of the restricted family scales the vertex and image
    terms). The march stops when the budget is spent, or early when, after every 20 sub-intervals, the
    work forecast for the rest of the strip exceeds 3 x ``budget``.

    Returns ``{"closed": bool, "reason": str, "word": Pi, "pieces": [...], "mu": ..., "work": units}``;
    each piece records its rational interval, the enclosure of ``lambda = rho(Pi)`` and the worst image
    norm; ``timing`` holds the wall-clock seconds (decides nothing).

    ``floor``: a one-element list; it receives the smallest budget that passes every budget check this
    march passed, so that every budget from it up gives the same answer (for callers that keep results).
    """
    old = ctx.prec
    t0 = time.perf_counter()
    work = Work(budget)
    floor = [0.0] if floor is None else floor
    try:
        out = _close_strip(S, lo, hi, lo_open=lo_open, hi_open=hi_open, max_depth=max_depth, work=work,
                           floor=floor)
    finally:
        ctx.prec = old
    out["work"] = work.spent
    out["timing"] = {"seconds": round(time.perf_counter() - t0, 2)}
    return out


def _close_strip(S, lo, hi, *, lo_open, hi_open, max_depth, work: Work, floor=None) -> dict:
    """The march of :func:`close_family`; ``floor[0]`` becomes the smallest budget that passes every budget
    check it passed (so that a larger budget gives the same answer)."""
    floor = [0.0] if floor is None else floor
    A, B = RealAlgebraic.from_expr(as_expr(lo)), RealAlgebraic.from_expr(as_expr(hi))
    out = {"closed": False, "reason": "", "word": None, "pieces": [], "mu": ", ".join(sp.sstr(m) for m in S.mus) or None}
    end = B if hi_open else (A if lo_open else B)
    if lo_open and hi_open and _smp(S.floats(float(A)), 3)[0] > _smp(S.floats(float(B)), 3)[0]:
        end = A                           # both ends open: set up at the one of eigenvalue type (larger rho)
    why = S.setup(float(end), work)
    if why:
        out["reason"] = why
        return out
    out["word"] = tuple(S.word)
    # rational cover of the closed hull
    ql, qh = _dyadic_cover(A, below=True), _dyadic_cover(B, below=False)
    # march from left to right with step (qh - ql) / 2^k: halve after a failure, double after two
    # successes (the steps stay dyadic, the pieces tile [ql, qh] exactly)
    chi = None
    pieces = []
    cur, k, wins, tries = ql, 0, 0, 0
    first = (0, ql)
    charged = 0
    while cur < qh:
        if work.exhausted:
            out["reason"] = f"work budget ({work.total} units) exhausted at t = {float(cur):.12g}"
            return out
        floor[0] = max(floor[0], work.spent + 1)
        u, w = cur, min(qh, cur + (qh - ql) / 2 ** k)
        tries += 1
        spent = work.spent
        if pieces and len(pieces) % 20 == 0 and cur > first[1]:   # forecast from the rate since the first success
            need = (spent - first[0]) * float((qh - cur) / (cur - first[1]))
            if spent + need > 3 * work.total:    # generous: the steps usually grow away from the end
                out["reason"] = (f"too slow for the budget: {len(pieces)} sub-intervals covered "
                                 f"{float((cur - ql) / (qh - ql)):.1%} of the strip in {spent} work units (the "
                                 f"polytope's slack is small; forecast {spent + need:.0f} > 3 x {work.total} units)")
                return out
            floor[0] = max(floor[0], (spent + need) / 3)
        r = S.certify(u, w)
        work.charge(int(S.units) - charged)
        charged = int(S.units)
        ok = r is not None
        if ok:
            (va, la), wit = r
            if not la < 1:
                chi = chi if chi is not None else _chi(S)
                ok = _below_one_exact(S, chi, u, w, A, B, lo_open, hi_open, va, la)
        if ok:
            if not pieces:
                first = (work.spent, w)
            pieces.append(wit)
            cur, wins = w, wins + 1
            if wins >= 2 and k > 0:
                k, wins = k - 1, 0
            continue
        wins, k = 0, k + 1
        if k > max_depth:
            out["reason"] = (f"no certificate on an interval of width 2^-{max_depth} of the strip at t = {float(u):.12g} "
                             "(the slack of the polytope is exhausted or the eigenpair enclosure fails)")
            return out
    out["tries"] = tries
    pieces.sort(key=lambda x: x["from"])
    out["closed"] = True
    out["pieces"] = [{"from": sp.sstr(sp.Rational(x["from"].numerator, x["from"].denominator)),
                      "to": sp.sstr(sp.Rational(x["to"].numerator, x["to"].denominator)),
                      "rho(Pi) in": str(x["lambda"]), "max image norm <=": round(x["max_image_norm_upper"], 6)}
                     for x in pieces]
    out["pieces"][0]["from"] = sp.sstr(A.expr)
    out["pieces"][-1]["to"] = sp.sstr(B.expr)
    return out


def _dyadic_cover(x: RealAlgebraic, *, below: bool, bits: int = 48) -> Fraction:
    """``x`` itself when rational, else a dyadic rational ``<= x`` (``below``) or ``>= x`` within
    ``2^-bits`` (checked exactly)."""
    if x.is_rational:
        return _rq(x.expr)
    f = float(x)
    k = int(np.floor(f * 2 ** bits)) + (0 if below else 1)
    for _ in range(64):
        q = Fraction(k, 2 ** bits)
        c = x.compare(RealAlgebraic.rational(sp.Rational(q.numerator, q.denominator)))
        if (c > 0) if below else (c < 0):
            return q
        k += -1 if below else 1
    raise ArithmeticError("no dyadic cover found")  # pragma: no cover


def _chi(S: ParametricStrip) -> sp.Poly:
    """``det(Pi(t) - I)`` for the s.m.p. ``Pi`` (exact; ``S.det_minus_one(word)`` when the caller has a faster
    exact route, e.g. evaluation and interpolation for large matrices)."""
    if S.det_minus_one is not None:
        return S.det_minus_one(tuple(S.word))
    # over the polynomial ring QQ[t]: the same polynomial as a Berkowitz determinant of the expression
    # matrix, hundreds of times faster
    from sympy.polys.matrices import DomainMatrix

    K = sp.QQ[S.p]
    R = [DomainMatrix([[K.from_sympy(sp.expand(e)) for e in M.row(i)] for i in range(M.rows)], M.shape, K)
         for M in S.R]
    n = S.R[0].rows
    Pi = DomainMatrix.eye(n, K)
    for i in S.word:
        Pi = R[i] * Pi
    return sp.Poly(K.to_sympy((Pi - DomainMatrix.eye(n, K)).det()), S.p)


def _below_one_exact(S, chi, u, w, A, B, lo_open, hi_open, va, la) -> bool:
    """``lambda(t) < 1`` on ``[u, w]`` minus the open ends: no root of ``det(Pi - I)`` there and
    ``lambda < 1`` at a point of it (continuity of the Krawczyk eigenpair)."""
    if chi.is_zero:
        return False
    U, W = RealAlgebraic.rational(sp.Rational(u.numerator, u.denominator)), \
        RealAlgebraic.rational(sp.Rational(w.numerator, w.denominator))
    lo_x = A if A.compare(U) >= 0 else U     # a rational end equal to u is the end itself (open or not)
    hi_x = B if B.compare(W) <= 0 else W
    for r in RealAlgebraic.roots_of(chi):
        below_hi = r.compare(hi_x) < 0 or (r.compare(hi_x) == 0 and not (hi_x is B and hi_open))
        above_lo = r.compare(lo_x) > 0 or (r.compare(lo_x) == 0 and not (lo_x is A and lo_open))
        if below_hi and above_lo:
            return False
    # a rational point strictly inside, where the eigenpair's lambda is certified < 1
    q = u if U.compare(lo_x) == 0 and not (lo_x is A and lo_open) else None
    if q is None:
        q = w if W.compare(hi_x) == 0 and not (hi_x is B and hi_open) else None
    if q is None:
        return False
    r = S.certify(q, q)
    if r is None:
        return False
    (vq, lq), _ = r
    # the point enclosure inside the interval enclosure: the same (unique) eigenpair branch
    same = la.contains(lq) and all(x.contains(y) for x, y in zip(va, vq))
    return same and bool(lq < 1)
