"""The complex invariant polytope, for a leading product with a complex leading eigenvalue.

When the s.m.p. ``P`` has a leading eigenvalue ``lambda = rho e^{i theta}`` with ``theta / pi``
irrational, the real polytope (started from ``Re u`` and ``Im u``) cannot close: ``P`` rotates
the plane ``span(Re u, Im u)`` by an irrational angle and the orbit of ``Re u`` never becomes
interior. The remedy (Guglielmi–Wirth–Zennaro 2005; Guglielmi–Protasov 2013, complex case) is
to work in ``C^n`` with the **complex balanced hull**

    P = absconv_C(V) = { sum_j z_j v_j : z_j in C, sum_j |z_j| <= 1 },

whose Minkowski norm ``||x||_P = min { sum |z_j| : sum z_j v_j = x }`` is a norm on ``C^n`` (an
*elliptic polytope* on ``R^n``: its real section is the convex hull of the ellipses
``{Re(e^{it} v_j)}``). Then ``P u = e^{i theta} u`` (normalized) is a boundary membership with
the single coefficient ``z = e^{i theta}``, ``|z| = 1``: the polytope can close exactly. If
``B_i v_j in P`` for all ``i, j`` with ``B_i = A_i / r``, the induced operator norms are
``<= 1`` and ``JSR <= r`` (real matrices have the same JSR on ``C^n`` and ``R^n``).

Float phase (:func:`build_complex_polytope`): as the real algorithm, with the membership LP
replaced by the second-order cone program

    min sum_j s_j  s.t.  sum_j (a_j + i b_j) v_j = x,  ||(a_j, b_j)||_2 <= s_j

(solved with Clarabel), polished by least squares on its support.

Certificate (:func:`certify_complex_polytope`): vertices are rounded to dyadic complex vectors
and coefficients to complex multiples of ``2^-COEF_BITS`` when stored, so ``P`` is an exactly
known object. For every vertex and matrix, in Arb complex ball arithmetic (``acb``),

    ||B_i v_j||_P <= sum_l |z_l| + ||C^{-1} (B_i v_j - sum_l z_l v_l)||_1,

with ``C`` a basis of ``n`` vertices (the second term: the exact residual written in that basis,
enclosed by one ball linear solve for all residuals). The maximum ``c`` gives ``JSR <= r c``
rigorously, for exact, algebraic and ball-valued families alike.

Examples
--------
A rotation by an irrational angle (``cos theta = 3/5``) scaled by 2 and a contraction: the JSR
is 2, attained by the rotation, whose eigenvalues ``2 e^{+-i theta}`` are complex. The real
polytope cannot close; the complex one closes with the two vertices ``u`` and ``conj(u)``
(for a real family the polytope must contain both: a real vector is ``a u + conj(a u)``):

>>> import numpy as np
>>> A = [np.array([[1.2, -1.6], [1.6, 1.2]]), np.array([[0.5, 0.0], [0.0, 0.25]])]
>>> u = np.array([1.0, -1.0j])
>>> from analysis.jsr._work import Work
>>> st = build_complex_polytope(A, 2.0, [u, u.conj()], work=Work(1000))
>>> st.closed, len(st.V)
(True, 2)

References
----------
N. Guglielmi, F. Wirth, M. Zennaro, *Complex polytope extremality results for families of
matrices*, SIAM J. Matrix Anal. Appl. 27 (2005) 721-743.
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear
operators*, Found. Comput. Math. 13 (2013) 37-97.
T. Mejstrik, V. Yu. Protasov, *Elliptic polytopes and invariant norms of linear operators*,
Calcolo 60 (2023) 56.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Sequence

import numpy as np
from flint import acb, acb_mat, arb, arb_mat

from ._exact import Family, arb_precision, arb_to_fraction_bounds, fraction_to_arb
from ._pivots import qr_pivots
from ._polytope import COEF_BITS, VERTEX_BITS, Certificate, better_product
from ._work import Work

#: work units of the complex polytope (about a millisecond of CPU each on the reference machine): a
#: membership test (the cheap pre-tests) ``CTEST_UNITS``, plus each cone program (Clarabel, interior
#: point) ``SOCP_UNITS + m n / SOCP_ENTRIES_PER_UNIT`` for ``m`` vertices in ``C^n``
CTEST_UNITS = 0.5
SOCP_UNITS = 5.0
SOCP_ENTRIES_PER_UNIT = 20.0


def _round_complex(x: np.ndarray) -> tuple[np.ndarray, int]:
    """Round ``x`` to ``(m + i m') 2^-s`` with ~VERTEX_BITS bits; returns (complex float, s)."""
    amax = float(max(np.max(np.abs(x.real)), np.max(np.abs(x.imag))))
    if amax == 0.0:
        return x * 0.0, 0
    s = VERTEX_BITS - int(np.floor(np.log2(amax)))
    re = np.ldexp(np.round(np.ldexp(x.real, s)), -s)
    im = np.ldexp(np.round(np.ldexp(x.imag, s)), -s)
    return re + 1j * im, s


def _round_coef(z: np.ndarray) -> np.ndarray:
    T = COEF_BITS
    return np.ldexp(np.round(np.ldexp(z.real, T)), -T) + 1j * np.ldexp(np.round(np.ldexp(z.imag, T)), -T)


@dataclass
class ComplexPolytopeState:
    """Complex dyadic vertices, their paths and the coefficient representations."""

    n: int
    k: int
    V: list[np.ndarray] = field(default_factory=list)
    shifts: list[int] = field(default_factory=list)
    root_of: list[int] = field(default_factory=list)
    path: list[tuple[int, ...]] = field(default_factory=list)
    reps: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    closed: bool = False
    better_word: tuple[int, ...] | None = None
    better_rho: float = 0.0
    lp_calls: int = 0
    stop_reason: str = ""
    tests: int = 0                        # membership tests made
    work_units: float = 0.0               # their cost in work units (CTEST_UNITS, SOCP_UNITS)
    work_charged: int = 0

    def matrix(self) -> np.ndarray:
        return np.array(self.V).T if self.V else np.zeros((self.n, 0), dtype=complex)


def socp_norm(Vm: np.ndarray, x: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """``(||x||_P, support, z)`` for ``P = absconv_C(columns of Vm)`` by the cone program of the
    module docstring (Clarabel); ``None`` if ``x`` is not in the complex span or the solver
    fails."""
    import scipy.sparse as sps

    import clarabel

    n, m = Vm.shape
    # variables: a (m), b (m), s (m); rows: [Re V, -Im V, 0; Im V, Re V, 0] (a + ib) = x, then for each
    # vertex j the cone rows -(s_j, a_j, b_j) (built as one coordinate list: the same canonical CSC
    # matrix as stacking the blocks, without m small sparse matrices)
    dense = np.vstack([np.hstack([Vm.real, -Vm.imag]), np.hstack([Vm.imag, Vm.real])])
    r0, c0 = np.nonzero(dense)
    j = np.arange(m)
    rows = np.concatenate([r0, 2 * n + 3 * j, 2 * n + 3 * j + 1, 2 * n + 3 * j + 2])
    cols = np.concatenate([c0, 2 * m + j, j, m + j])
    vals = np.concatenate([dense[r0, c0], -np.ones(3 * m)])
    A = sps.csc_matrix((vals, (rows, cols)), shape=(2 * n + 3 * m, 3 * m))
    cones = [clarabel.ZeroConeT(2 * n)] + [clarabel.SecondOrderConeT(3) for _ in range(m)]
    b = np.concatenate([x.real, x.imag, np.zeros(3 * m)])
    q = np.concatenate([np.zeros(2 * m), np.ones(m)])
    P = sps.csc_matrix((3 * m, 3 * m))
    settings = clarabel.DefaultSettings()
    settings.verbose = False
    settings.tol_gap_abs = settings.tol_gap_rel = 1e-11
    settings.tol_feas = 1e-11
    settings.max_threads = 1              # deterministic, and the machine is shared
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = clarabel.DefaultSolver(P, q, A, b, cones, settings).solve()
    if str(sol.status) not in ("Solved", "AlmostSolved", "SolverStatus.Solved",
                               "SolverStatus.AlmostSolved"):
        return None
    y = np.asarray(sol.x)
    z = y[:m] + 1j * y[m:2 * m]
    supp = np.nonzero(np.abs(z) > 1e-13 * max(1.0, float(np.max(np.abs(z)))))[0]
    return float(np.sum(np.abs(z))), supp, z[supp]


class _CMember:
    """Membership oracle for ``absconv_C(V)`` with cheap pre-tests and least-squares polish."""

    def __init__(self, st: ComplexPolytopeState):
        self.st = st
        self._basis: tuple[np.ndarray, np.ndarray] | None = None
        self._r2 = 0.0

    def refresh(self) -> None:
        st = self.st
        self._r2 = max((float(np.vdot(v, v).real) for v in st.V), default=0.0)
        if len(st.V) >= st.n:
            Vm = st.matrix()
            piv = qr_pivots(Vm)
            idx = np.sort(piv[: st.n])
            Bm = Vm[:, idx]
            if np.linalg.matrix_rank(Bm) == st.n and np.linalg.cond(Bm) < 1e12:
                self._basis = (idx, np.linalg.inv(Bm))
            else:
                self._basis = None

    def norm(self, x: np.ndarray):
        st = self.st
        st.tests += 1
        st.work_units += CTEST_UNITS
        if float(np.vdot(x, x).real) > self._r2 * (1 + 1e-9):
            return np.inf, None, None          # ||x||_2 <= max ||v_j||_2 on P
        if self._basis is not None:
            idx, Binv = self._basis
            z = Binv @ x
            s = float(np.sum(np.abs(z)))
            if s <= 1.0:
                return s, idx, z
        Vm = st.matrix()
        st.lp_calls += 1
        st.work_units += SOCP_UNITS + Vm.shape[1] * st.n / SOCP_ENTRIES_PER_UNIT
        out = socp_norm(Vm, x)
        if out is None:
            return np.inf, None, None
        _, supp, z = out
        # polish: least squares on the support, then absorb what is left through the basis
        sol, *_ = np.linalg.lstsq(Vm[:, supp], x, rcond=None)
        if np.linalg.norm(Vm[:, supp] @ sol - x) < np.linalg.norm(Vm[:, supp] @ z - x):
            z = sol
        res = x - Vm[:, supp] @ z
        if self._basis is not None and np.any(res):
            idx, Binv = self._basis
            full = np.zeros(Vm.shape[1], dtype=complex)
            full[supp] = z
            full[idx] += Binv @ res
            supp = np.nonzero(full)[0]
            z = full[supp]
        return float(np.sum(np.abs(z))), supp, z


def build_complex_polytope(mats: Sequence[np.ndarray], r: float, roots: Sequence[np.ndarray], *,
                           work: Work, max_vertices: int = 600, tol: float = 1e-11,
                           check_better: bool = True) -> ComplexPolytopeState:
    """Float phase of the complex polytope algorithm (module docstring); ``roots`` are complex
    vectors (leading eigenvectors of the candidate products, balanced). ``work`` is charged for
    every membership test (``CTEST_UNITS`` and the cone programs); no image is tested once it is
    exhausted."""
    from ._polytope import _charge

    n, k = mats[0].shape[0], len(mats)
    B = [np.asarray(A, dtype=float) / r for A in mats]
    st = ComplexPolytopeState(n, k)
    mem = _CMember(st)

    def add(x: np.ndarray, root: int, path: tuple[int, ...]) -> int:
        v, s = _round_complex(np.asarray(x, dtype=complex))
        st.V.append(v)
        st.shifts.append(s)
        st.root_of.append(root)
        st.path.append(path)
        mem.refresh()
        return len(st.V) - 1

    frontier = []
    for ri, x in enumerate(roots):
        nx, _, _ = mem.norm(np.asarray(x, dtype=complex))
        _charge(work, st)
        if nx > 1 + tol:
            frontier.append(add(x, ri, ()))
    while frontier:
        new = []
        for j in frontier:
            for i in range(k):
                if work.exhausted:
                    st.stop_reason = "work budget exhausted"
                    return st
                x = B[i] @ st.V[j]
                nx, supp, z = mem.norm(x)
                _charge(work, st)
                if nx <= 1 + tol:
                    st.reps[(i, j)] = (np.asarray(supp), _round_coef(np.asarray(z)))
                    continue
                path = st.path[j] + (i,)
                if check_better and np.isfinite(nx) and better_product(B, path, r, st):
                    return st
                if len(st.V) >= max_vertices:
                    st.stop_reason = f"vertex budget ({max_vertices}) exhausted"
                    return st
                jn = add(x, st.root_of[j], path)
                st.reps[(i, j)] = (np.array([jn]), np.array([1.0 + 0j]))
                new.append(jn)
        frontier = new
    if st.V and np.linalg.matrix_rank(st.matrix()) == n:
        st.closed = True
        st.stop_reason = "closed"
    else:
        st.stop_reason = "closed without spanning C^n (an invariant subspace)"
    return st


def certify_complex_polytope(F: Family, r: Fraction, st: ComplexPolytopeState) -> Certificate | None:
    """Rigorous ``JSR <= r max_{i,j} ||A_i v_j / r||_P`` (module docstring), in Arb complex
    balls; ``None`` if representations are missing or the basis is singular."""
    n, k, m = st.n, st.k, len(st.V)
    if m < n or any((i, j) not in st.reps for j in range(m) for i in range(k)):
        return None
    S = max(st.shifts)
    T = COEF_BITS
    Vre = [[int(np.ldexp(st.V[j][a].real, S)) for j in range(m)] for a in range(n)]
    Vim = [[int(np.ldexp(st.V[j][a].imag, S)) for j in range(m)] for a in range(n)]
    for j in range(m):
        for a in range(n):
            if (np.ldexp(float(Vre[a][j]), -S) != st.V[j][a].real
                    or np.ldexp(float(Vim[a][j]), -S) != st.V[j][a].imag):
                raise ArithmeticError("vertex is not the dyadic it claims to be")
    Vm = st.matrix()
    piv = qr_pivots(Vm)
    idx = sorted(int(p) for p in piv[:n])
    with arb_precision():
        two_S, two_T = arb(2) ** S, arb(2) ** T
        Vr = arb_mat(n, m, [arb(Vre[a][j]) / two_S for a in range(n) for j in range(m)])
        Vi = arb_mat(n, m, [arb(Vim[a][j]) / two_S for a in range(n) for j in range(m)])
        C = acb_mat(n, n, [acb(Vr[a, j], Vi[a, j]) for a in range(n) for j in idx])
        rinv = 1 / fraction_to_arb(r)
        cols: list[tuple[int, int]] = []
        res_re: list[list[arb]] = []
        res_im: list[list[arb]] = []
        coef_sum: list[arb] = []
        for i in range(k):
            Ai = F.arb(i)
            Wr, Wi = (Ai * Vr) * rinv, (Ai * Vi) * rinv
            for j in range(m):
                supp, z = st.reps[(i, j)]
                zr = [int(np.ldexp(c.real, T)) for c in z]
                zi = [int(np.ldexp(c.imag, T)) for c in z]
                er, ei = [Wr[a, j] for a in range(n)], [Wi[a, j] for a in range(n)]
                tot = arb(0)
                for s_, a_, b_ in zip(supp, zr, zi):
                    s_ = int(s_)
                    if a_ == 0 and b_ == 0:
                        continue
                    za, zb = arb(a_) / two_T, arb(b_) / two_T
                    tot += (za * za + zb * zb).sqrt()
                    for a in range(n):    # residual -= (za + i zb) (Vr + i Vi)[:, s]
                        er[a] -= za * Vr[a, s_] - zb * Vi[a, s_]
                        ei[a] -= za * Vi[a, s_] + zb * Vr[a, s_]
                cols.append((i, j))
                res_re.append(er)
                res_im.append(ei)
                coef_sum.append(tot)
        E = acb_mat(n, len(cols), [acb(res_re[c][a], res_im[c][a])
                                   for a in range(n) for c in range(len(cols))])
        try:
            Y = C.solve(E)
        except ZeroDivisionError:
            return None
        best, worst = Fraction(-1), (0, 0)
        for c, key in enumerate(cols):
            tot = coef_sum[c]
            for a in range(n):
                tot += abs(Y[a, c])
            if not tot.is_finite():
                return None
            hi = arb_to_fraction_bounds(tot)[1]
            if hi > best:
                best, worst = hi, key
    return Certificate(best, r * best, Fraction(0),
                       "complex polytope: every membership re-checked in Arb complex ball "
                       "arithmetic (exact dyadic vertices and coefficients, residual solved in a "
                       "vertex basis)", worst)
