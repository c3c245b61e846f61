"""The invariant polytope algorithm (real, symmetric case) and its rigorous certificate.

Float phase (:func:`build_polytope`)
------------------------------------
Given the family scaled by a rational ``r`` close to the candidate value ``rho(P_w)^(1/L)``,
``B_i = A_i / r``, and *roots* (the balanced leading eigenvectors of the candidate products and
the interior fillers, :mod:`analysis.jsr._balance`; for a complex leading eigenvalue its real and
imaginary parts), the vertex set ``V`` starts with the roots and grows as in Guglielmi–Protasov (2013): every image ``B_i v`` of a new vertex ``v`` is
tested for membership in the absolutely convex hull ``absconv(V)`` by the linear program

    min ||lambda||_1  subject to  V lambda = x          (HiGHS: :mod:`analysis.jsr._lp`),

whose value is the Minkowski norm ``||x||_P``. Images with ``||x||_P <= 1 + tol`` are inside and
their coefficient vector is kept (the certificate needs it); the others become new vertices. The
polytope *closes* when every vertex has all ``k`` images inside. If ``V`` closes without spanning
``R^n`` (a common invariant subspace), orthonormal complement vectors are added as extra roots.
A vertex whose path ``B_{i_d} ... B_{i_1}`` has ``rho > 1`` reveals a better product than the
candidate; the caller restarts with it (Mejstrik 2020 uses the same idea).

Cheap tests avoid most LPs: ``||x||_2 > max_j ||v_j||_2`` proves ``x`` outside, and
``||B^{-1} x||_1 <= 1`` for a basis ``B`` of vertices proves it inside (with coefficients).
Every LP solution is *polished*: the coefficients on its support are recomputed by least squares,
so the float residual is ~1e-16 instead of HiGHS's 1e-7 feasibility tolerance.

Certificate (:func:`certify_polytope`)
--------------------------------------
Vertices are rounded to dyadic rationals when created and coefficients are rounded to multiples
of ``2^-60``; so the polytope ``P = absconv(V)`` is an exactly known rational object. For every
vertex ``v_j`` and matrix ``i``, with float coefficients ``lambda``:

    ||B_i v_j||_P <= ||lambda||_1 + ||B^{-1}||_1 * ||B_i v_j - V lambda||_1,

where ``B`` is a basis of vertices and the right side is evaluated **exactly** (integers and
rationals; for irrational inputs in Arb ball arithmetic enclosing the exact entries). Hence
``||A_i||_P <= r * c`` with ``c = max_{i,j}`` of these bounds and ``JSR <= r * c``, a rigorous
upper bound whether or not the float phase closed (if it did, ``c = 1 + O(1e-13)``).

References
----------
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear
operators*, Found. Comput. Math. 13 (2013) 37-97.
T. Mejstrik, *Algorithm 1011: Improved invariant polytope algorithm and applications*, ACM Trans.
Math. Softw. 46(3) (2020) 29.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Sequence

import numpy as np
from flint import arb, arb_mat, fmpq_mat, fmpz_mat

from ._exact import Family, arb_precision, arb_to_fraction_bounds, fraction_to_arb
from ._lp import WarmLP, small_lp
from ._lsq import lstsq_solution
from ._pivots import qr_pivots
from ._work import Work

#: work units of the float polytope (calibrated so that a unit is about a millisecond of CPU on the
#: reference machine): a membership test (:meth:`_Member.norm`, the cheap pre-tests) costs
#: ``TEST_UNITS``, plus each linear program it solves: the small one over ``~3 n`` aligned vertices
#: (a fresh HiGHS model) ``SMALL_LP_UNITS``, the full warm-started one ``m n / LP_ENTRIES_PER_UNIT``
#: for ``m`` vertices in ``R^n``; a new vertex (its basis update) ``m n^2 / VERTEX_ENTRIES_PER_UNIT``
TEST_UNITS = 0.5
SMALL_LP_UNITS = 4.0
LP_ENTRIES_PER_UNIT = 500.0
VERTEX_ENTRIES_PER_UNIT = 30000.0

#: mantissa bits kept when a float vertex is rounded to a dyadic rational
VERTEX_BITS = 52
#: coefficients are multiples of 2^-COEF_BITS
COEF_BITS = 60


def _round_vertex(x: np.ndarray) -> tuple[np.ndarray, int]:
    """Round ``x`` to ``m * 2^-s`` (integers ``m``) with ~VERTEX_BITS bits; returns (float, s)."""
    amax = float(np.max(np.abs(x)))
    if amax == 0.0:
        return x * 0.0, 0
    e = int(np.floor(np.log2(amax)))
    s = VERTEX_BITS - e
    m = np.round(np.ldexp(x, s))
    return np.ldexp(m, -s), s


@dataclass
class PolytopeState:
    """Float vertices (exact dyadics), their path words and the coefficient representations."""

    n: int
    k: int
    V: list[np.ndarray] = field(default_factory=list)
    shifts: list[int] = field(default_factory=list)       # v_j = integer vector * 2^-shift_j
    root_of: list[int] = field(default_factory=list)
    path: list[tuple[int, ...]] = field(default_factory=list)
    reps: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    closed: bool = False
    better_word: tuple[int, ...] | None = None
    better_rho: float = 0.0
    lp_calls: int = 0
    stop_reason: str = ""
    max_norm_seen: float = 0.0
    tests: int = 0                        # membership tests made
    work_units: float = 0.0               # their cost in work units (see TEST_UNITS)
    work_charged: int = 0                 # whole units of it charged to the budget

    def matrix(self) -> np.ndarray:
        return np.array(self.V).T if self.V else np.zeros((self.n, 0))


class _Member:
    """Membership oracle for absconv(V) with cheap pre-tests (see module docstring)."""

    def __init__(self, st: PolytopeState):
        self.st = st
        self._basis: tuple[np.ndarray, np.ndarray] | None = None
        self._basis_m = -1
        self._basis_idx: np.ndarray | None = None    # the vertex indices the basis was built from
        self._r2 = 0.0
        self._r2_m = 0                    # vertices included in _r2
        self._buf = np.empty((0, st.n))   # vertex rows (see matrix())
        self._rows = 0
        self._Y = np.zeros((0, st.n))     # functionals y with |<y, v_j>| <= 1 for all vertices
        self.shortcuts = True             # False: always return a representation if one exists
        self._warm = WarmLP.create(st.n)  # persistent HiGHS model of the full LP (or None)

    def matrix(self) -> np.ndarray:
        """``st.matrix()`` (the vertices as columns), kept in a growing buffer: the same values and
        the same memory layout (the transpose of a C-ordered vertices-by-coordinates block)."""
        st = self.st
        m = len(st.V)
        if m > len(self._buf):
            buf = np.empty((max(2 * len(self._buf), m, 16), st.n))
            buf[: self._rows] = self._buf[: self._rows]
            self._buf = buf
        if m > self._rows:
            self._buf[self._rows: m] = st.V[self._rows: m]
            self._rows = m
        return self._buf[:m].T

    def refresh(self) -> None:
        """Update the pre-test data after vertices were appended to ``st.V``: the largest squared
        vertex length, the separating functionals and the basis of vertices (a pivoted QR of the
        vertex matrix picks it; its inverse is recomputed only when the pick changes)."""
        st = self.st
        m = len(st.V)
        st.work_units += m * st.n * st.n / VERTEX_ENTRIES_PER_UNIT
        for v in st.V[self._r2_m:]:
            self._r2 = max(self._r2, float(v @ v))
        self._r2_m = m
        if len(self._Y) and m:
            ok = np.abs(self._Y @ st.V[-1]) <= 1.0
            self._Y = self._Y[ok]
        if m >= st.n and m != self._basis_m:
            Vm = self.matrix()
            piv = qr_pivots(Vm)
            idx = np.sort(piv[: st.n])
            if self._basis_idx is None or not np.array_equal(idx, self._basis_idx):
                Bm = Vm[:, idx]
                # one singular value decomposition for numpy's matrix_rank and cond tests
                sv = np.linalg.svd(Bm, compute_uv=False)
                rank = int(np.count_nonzero(sv > sv.max(initial=0.0) * (st.n * np.finfo(float).eps)))
                if rank == st.n and sv[0] / sv[-1] < 1e12:
                    self._basis = (idx, np.linalg.inv(Bm))
                else:
                    self._basis = None
                self._basis_idx = idx
            self._basis_m = m

    def norm(self, x: np.ndarray) -> tuple[float, np.ndarray | None, np.ndarray | None]:
        """``(||x||_P, support, coefficients)``; ``inf`` (and no representation) when ``x`` is
        outside ``span(V)`` or certainly outside ``P``."""
        st = self.st
        st.tests += 1
        st.work_units += TEST_UNITS
        xx = float(x @ x)
        if self.shortcuts and xx > self._r2 * (1 + 1e-9):
            return np.inf, None, None
        if self.shortcuts and len(self._Y) and float(np.max(np.abs(self._Y @ x))) > 1 + 1e-9:
            return np.inf, None, None              # a supporting functional separates x
        if self._basis is not None:
            idx, Binv = self._basis
            lam = Binv @ x
            s = float(np.sum(np.abs(lam)))
            if s <= 1.0:
                return s, idx, lam
        Vm = self.matrix()
        m = Vm.shape[1]
        if m > 6 * st.n and self.shortcuts:
            # a small LP over the vertices best aligned with x: inside it means inside P
            cos = np.abs(x @ Vm) / np.maximum(np.linalg.norm(Vm, axis=0), 1e-300)
            sub = np.argsort(-cos)[: 3 * st.n]
            if self._basis is not None:
                sub = np.union1d(sub, self._basis[0])
            out = self._lp(Vm[:, sub], x)
            if out is not None and out[0] <= 1.0:
                nx, supp, lam = self._polish(Vm, x, sub[out[1]], out[2])
                if nx <= 1.0:
                    return nx, supp, lam
        out = self._full_lp(Vm, x)
        if out is None:
            return np.inf, None, None
        return self._polish(Vm, x, out[1], out[2])

    def _full_lp(self, Vm: np.ndarray, x: np.ndarray):
        """The LP over all vertices: warm-started on the persistent model when available."""
        w = self._warm
        if w is None:
            return self._lp(Vm, x, keep_dual=True)
        w.sync(self.st.V)
        self.st.lp_calls += 1
        self.st.work_units += len(self.st.V) * self.st.n / LP_ENTRIES_PER_UNIT
        out = w.solve(x)
        if out is None:
            return None
        fun, lam, y = out
        if fun > 1.0 and y is not None and np.all(np.isfinite(y)):
            y = y / max(1.0, float(np.max(np.abs(y @ Vm))))
            self._Y = np.vstack([self._Y, y[None, :]])[-200:]
        supp = np.nonzero(np.abs(lam) > 1e-15 * max(1.0, float(np.max(np.abs(lam)))))[0]
        return fun, supp, lam[supp]

    def _lp(self, Vm: np.ndarray, x: np.ndarray, keep_dual: bool = False):
        m = Vm.shape[1]
        self.st.lp_calls += 1
        self.st.work_units += SMALL_LP_UNITS if m <= 6 * self.st.n else m * self.st.n / LP_ENTRIES_PER_UNIT
        out = small_lp(Vm, x)
        if out is None:
            return None
        fun, lam, y = out
        if keep_dual and fun > 1.0:
            if y.shape == (self.st.n,) and np.all(np.isfinite(y)):
                y = y / max(1.0, float(np.max(np.abs(y @ Vm))))
                self._Y = np.vstack([self._Y, y[None, :]])[-200:]
        supp = np.nonzero(np.abs(lam) > 1e-15 * max(1.0, float(np.max(np.abs(lam)))))[0]
        return fun, supp, lam[supp]

    def _polish(self, Vm: np.ndarray, x: np.ndarray, supp: np.ndarray, lam0: np.ndarray):
        m = Vm.shape[1]
        lam = np.zeros(m)
        lam[supp] = lam0
        if len(supp) == 0:
            return 0.0, np.array([0]), np.array([0.0])
        sol = lstsq_solution(Vm[:, supp], x)
        if np.linalg.norm(Vm[:, supp] @ sol - x, 1) <= np.linalg.norm(Vm[:, supp] @ lam[supp] - x, 1):
            lam_s = sol
        else:
            lam_s = lam[supp]
        res = x - Vm[:, supp] @ lam_s
        if self._basis is not None and np.any(res):
            # absorb what is left (HiGHS is feasible only to ~1e-9) through the basis
            idx, Binv = self._basis
            full = np.zeros(m)
            full[supp] = lam_s
            full[idx] += Binv @ res
            supp = np.nonzero(full)[0]
            lam_s = full[supp]
        return float(np.sum(np.abs(lam_s))), supp, lam_s


def better_product(B: Sequence[np.ndarray], path: tuple[int, ...], r: float, st) -> bool:
    """Whether the vertex path ``B_{i_d} ... B_{i_1}`` has ``rho > 1`` (a product better than the
    candidate); if so it is recorded in ``st`` (``better_word``, ``better_rho``, ``stop_reason``)
    for the caller to restart with. Shared by the real and the complex polytope."""
    P = np.eye(B[0].shape[0])
    for t in path:
        P = B[t] @ P
    rho = float(np.max(np.abs(np.linalg.eigvals(P)))) ** (1.0 / len(path))
    if rho <= 1 + 1e-10:
        return False
    st.better_word = tuple(reversed(path))
    st.better_rho = rho * r
    st.stop_reason = "found a product with larger spectral radius"
    return True


def leading_is_real(mats: Sequence[np.ndarray], word: Sequence[int], rel: float = 1e-8) -> bool:
    """Whether every eigenvalue of maximal modulus of ``P_w`` is real (float test)."""
    P = np.eye(mats[0].shape[0])
    for i in word:
        P = P @ mats[i]
    w = np.linalg.eigvals(P)
    top = float(np.max(np.abs(w)))
    return bool(np.all(np.abs(w[np.abs(w) >= top * (1 - rel)].imag) <= 1e-9 * max(top, 1e-300)))


def rotation_order(mats: Sequence[np.ndarray], word: Sequence[int], max_order: int = 12,
                   rel: float = 1e-8) -> int | None:
    """The least ``q <= max_order`` with ``(lambda / |lambda|)^q = 1`` for every eigenvalue of maximal
    modulus of ``P_w`` (float test), or None. ``q = 1``: a positive leading eigenvalue; ``q > 2``: ``P_w``
    rotates its leading plane by a rational angle, so the orbit of ``Re u`` is finite and the real
    polytope can close exactly (an irrational angle needs the complex polytope).

    >>> import numpy as np
    >>> rotation_order([np.array([[0.0, -1.0], [1.0, 0.0]])], (0,))
    4
    """
    P = np.eye(mats[0].shape[0])
    for i in word:
        P = P @ mats[i]
    w = np.linalg.eigvals(P)
    top = float(np.max(np.abs(w)))
    if top <= 0:
        return None
    z = w[np.abs(w) >= top * (1 - rel)] / top
    for q in range(1, max_order + 1):
        if np.all(np.abs(z ** q - 1) <= 1e-7 * q):
            return q
    return None


def _charge(work: Work, st) -> None:
    """Charge ``work`` the whole units of ``st.work_units`` not charged yet (the fractional rest
    is carried to the next test, so the total charged does not depend on how tests group)."""
    due = int(st.work_units) - st.work_charged
    if due > 0:
        work.charge(due)
        st.work_charged += due


def build_polytope(mats: Sequence[np.ndarray], r: float, roots: Sequence[np.ndarray], *,
                   work: Work, max_vertices: int = 1500, tol: float = 1e-11,
                   check_better: bool = True, thin_stop: float | None = None) -> PolytopeState:
    """The float phase of the invariant polytope algorithm (see module docstring).

    ``work``: the :class:`~analysis.jsr._work.Work` budget, charged for every membership test
    (``TEST_UNITS`` and the linear programs it solves); no image is tested once it is exhausted
    (``stop_reason`` "work budget exhausted").

    ``thin_stop``: stop early (``stop_reason`` starting with ``"thin polytope"``) when the vertex
    matrix spans but its condition number exceeds this value (checked every ``2 n`` vertices from ``8 n`` on):
    the caller then rounds the polytope by a similarity (:mod:`analysis.jsr._precondition`)."""
    n, k = mats[0].shape[0], len(mats)
    B = [np.asarray(A, dtype=float) / r for A in mats]
    st = PolytopeState(n, k)
    mem = _Member(st)

    def add(x: np.ndarray, root: int, path: tuple[int, ...]) -> int:
        v, s = _round_vertex(x)
        st.V.append(v)
        st.shifts.append(s)
        st.root_of.append(root)
        st.path.append(path)
        mem.refresh()
        return len(st.V) - 1

    frontier: list[int] = []
    root_list = [np.asarray(x, dtype=float) for x in roots]
    ri = 0
    while True:
        for x in root_list:
            nx, _, _ = mem.norm(x)
            _charge(work, st)
            if nx > 1 + tol:
                frontier.append(add(x, ri, ()))
            ri += 1
        root_list = []
        while frontier:
            new: list[int] = []
            for j in frontier:
                for i in range(k):
                    if work.exhausted:
                        st.stop_reason = "work budget exhausted"
                        return st
                    x = B[i] @ st.V[j]
                    nx, supp, lam = mem.norm(x)
                    _charge(work, st)
                    if nx <= 1 + tol:
                        st.reps[(i, j)] = (supp, lam)
                        continue
                    path = st.path[j] + (i,)
                    if check_better and np.isfinite(nx) and nx > 1 + 1e-9 and \
                            better_product(B, path, r, st):
                        return st
                    if len(st.V) >= max_vertices:
                        st.stop_reason = f"vertex budget ({max_vertices}) exhausted"
                        return st
                    if np.isfinite(nx):
                        st.max_norm_seen = max(st.max_norm_seen, nx)
                    jn = add(x, st.root_of[j], path)
                    if thin_stop is not None and len(st.V) % (2 * n) == 0 and len(st.V) >= 8 * n:
                        sv = np.linalg.svd(st.matrix(), compute_uv=False)
                        # numerically rank deficient counts as thin; exact zeros (an exactly
                        # invariant subspace) do not
                        sv = sv[sv > 0]
                        if len(sv) and sv[0] > thin_stop * sv[-1]:
                            st.stop_reason = f"thin polytope (cond {sv[0] / sv[-1]:.2g})"
                            return st
                    st.reps[(i, j)] = (np.array([jn]), np.array([1.0]))
                    new.append(jn)
            frontier = new
        # closed in float; make sure the polytope is a body
        Vm = st.matrix()
        rank = np.linalg.matrix_rank(Vm) if Vm.shape[1] else 0
        if rank == n:
            st.closed = True
            st.stop_reason = "closed"
            return st
        U, _, _ = np.linalg.svd(Vm if Vm.shape[1] else np.zeros((n, 1)))
        comp = U[:, rank:]
        scale = max((float(np.max(np.abs(v))) for v in st.V), default=1.0)
        root_list = [c / np.max(np.abs(c)) * scale for c in comp.T]


def complete_reps(mats: Sequence[np.ndarray], r: float, st: PolytopeState, *,
                  work: Work) -> bool:
    """For an unclosed polytope: representations of the missing images (norms may exceed 1), so
    that :func:`certify_polytope` can still bound ``||A_i||_P``. False if ``V`` does not span or
    the ``work`` budget runs out (charged as in :func:`build_polytope`)."""
    if not st.V or np.linalg.matrix_rank(st.matrix()) < st.n:
        return False
    B = [np.asarray(A, dtype=float) / r for A in mats]
    mem = _Member(st)
    mem.refresh()
    mem.shortcuts = False  # we need coefficients for every image, inside or not
    for j in range(len(st.V)):
        for i in range(st.k):
            if (i, j) in st.reps:
                continue
            if work.exhausted:
                return False
            nx, supp, lam = mem.norm(B[i] @ st.V[j])
            _charge(work, st)
            if supp is None:
                return False
            st.reps[(i, j)] = (supp, lam)
    return True


def _scaled_integer(x: float, S: int) -> int:
    """The integer ``x 2^S`` exactly (integer arithmetic: no overflow when the vertices' scales differ by more
    than the float range); an ``ArithmeticError`` if ``x`` is not a multiple of ``2^-S``.

    >>> _scaled_integer(0.75, 2), _scaled_integer(1e300, 600) == int(1e300) << 600
    (3, True)
    """
    num, den = x.as_integer_ratio()                 # den is a power of 2
    q, r = divmod(num << S if S >= 0 else num, den if S >= 0 else den << -S)
    if r:
        raise ArithmeticError("vertex is not the dyadic it claims to be")
    return q


@dataclass
class Certificate:
    bound: Fraction            # c with ||A_i / r||_P <= c for all i (rigorous)
    upper: Fraction            # r * c >= JSR
    basis_inverse_norm: Fraction
    arithmetic: str
    worst: tuple[int, int]


def certify_polytope(F: Family, r: Fraction, st: PolytopeState) -> Certificate | None:
    """Rigorous bound ``JSR <= r * max_{i,j} ||A_i v_j / r||_P`` from the float representations
    (see module docstring); ``None`` if representations are missing or the basis is singular."""
    n, k, m = st.n, st.k, len(st.V)
    if m < n or any((i, j) not in st.reps for j in range(m) for i in range(k)):
        return None
    S = max(st.shifts)
    # V = Vint / 2^S exactly
    Vint = [[_scaled_integer(float(st.V[j][a]), S) for j in range(m)] for a in range(n)]
    Vz = fmpz_mat(Vint)
    # basis and ||B^{-1}||_1, exactly
    Vm = st.matrix()
    piv = qr_pivots(Vm)
    idx = sorted(int(p) for p in piv[:n])
    Bq = fmpq_mat([[Vint[a][j] for j in idx] for a in range(n)])
    try:
        Binv = Bq.inv()
    except ZeroDivisionError:
        return None
    C = max(sum(abs(Fraction(int(Binv[a, b].p), int(Binv[a, b].q))) for a in range(n))
            for b in range(n)) * 2 ** S
    T = COEF_BITS
    best = Fraction(-1)
    worst = (0, 0)
    bounds: dict[tuple[int, int], tuple[Fraction, Fraction]] = {}
    p, q = r.numerator, r.denominator
    if F.exact_q is not None:
        arithmetic = "exact rational (FLINT fmpz/fmpq)"
        for i in range(k):
            N, D = F.exact_q[i].numer_denom()
            D = int(D)
            W = N * Vz                                   # A_i V = W / (D 2^S)
            for j in range(m):
                supp, lam = st.reps[(i, j)]
                lint, comb = _integer_combination(supp, lam, T, Vint, n)
                # residual numerator over den = p D 2^(S+T)
                res_abs = 0
                for a in range(n):
                    res_abs += abs(q * int(W[a, j]) * 2 ** T - p * D * comb[a])
                den = p * D * 2 ** (S + T)
                coef = Fraction(sum(abs(c) for c in lint), 2 ** T)
                bnd = coef + C * Fraction(res_abs, den)
                bounds[(i, j)] = (bnd, coef)
    else:
        arithmetic = "Arb ball arithmetic enclosing the exact entries"
        with arb_precision():
            two_S = arb(2) ** S
            Vb = arb_mat(n, m, [arb(Vint[a][j]) / two_S for a in range(n) for j in range(m)])
            rb = fraction_to_arb(r)
            Cb = fraction_to_arb(C)
            for i in range(k):
                W = (F.arb(i) * Vb) * (1 / rb)
                for j in range(m):
                    supp, lam = st.reps[(i, j)]
                    lint, comb = _integer_combination(supp, lam, T, Vint, n)
                    den = arb(2) ** (S + T)
                    res = arb(0)
                    for a in range(n):
                        res += abs(W[a, j] - arb(comb[a]) / den)
                    coef = Fraction(sum(abs(c) for c in lint), 2 ** T)
                    tot = fraction_to_arb(coef) + Cb * res
                    _, hi = arb_to_fraction_bounds(tot)
                    bounds[(i, j)] = (hi, coef)
    # local bases: where the global-basis residual term matters, re-solve in ball arithmetic
    local = _local_basis_bounds(F, r, st, Vint, S, bounds)
    for key, (bnd, _coef) in bounds.items():
        if key in local and local[key] < bnd:
            bnd = local[key]
        if bnd > best:
            best, worst = bnd, key
    if local:
        arithmetic += ("; memberships with a significant residual re-solved exactly in local "
                       "vertex bases (Arb linear solves)")
    return Certificate(best, r * best, C, arithmetic, worst)


#: a per-image bound whose residual term exceeds this is re-certified in a local basis
LOCAL_RESIDUAL_THRESHOLD = Fraction(1, 2 ** 44)


def _local_basis_bounds(F: Family, r: Fraction, st: PolytopeState, Vint: list[list[int]],
                        S: int, bounds: dict) -> dict:
    """Sharper rigorous bounds ``||A_i v_j / r||_P <= ||lambda||_1`` for the images whose
    global-basis bound ``||lambda~||_1 + ||B^{-1}||_1 ||residual||_1`` is dominated by the
    residual term (an ill-conditioned global basis ``B`` amplifies the float residual).

    The LP support of the image is completed to ``n`` linearly independent vertices ``M`` (in
    the order of a pivoted QR of the remaining vertices) and ``M lambda = A_i v_j / r`` is solved
    in Arb ball arithmetic (``arb_mat.solve``: a certified enclosure of the exact solution, the
    vertices being exact dyadics and ``A_i`` exact or balls). Then ``A_i v_j / r`` is exactly
    ``M lambda`` and its Minkowski norm is at most ``||lambda||_1``. Columns sharing one local
    basis are solved together.
    """
    n = st.n
    todo = [key for key, (bnd, coef) in bounds.items()
            if bnd - coef > LOCAL_RESIDUAL_THRESHOLD]
    if not todo:
        return {}
    Vm = st.matrix()
    piv = qr_pivots(Vm)
    order = [int(p) for p in piv]
    groups: dict[tuple[int, ...], list[tuple[int, int]]] = {}
    for (i, j) in todo:
        supp, _lam = st.reps[(i, j)]
        cols = sorted({int(t) for t in supp})
        if len(cols) > n:
            continue
        rank = np.linalg.matrix_rank(Vm[:, cols]) if cols else 0
        if rank < len(cols):
            continue
        for t in order:
            if len(cols) == n:
                break
            if t in cols:
                continue
            trial = cols + [t]
            if np.linalg.matrix_rank(Vm[:, trial]) == len(trial):
                cols = trial
        if len(cols) < n:
            continue
        groups.setdefault(tuple(sorted(cols)), []).append((i, j))
    out: dict = {}
    with arb_precision():
        two_S = arb(2) ** S
        rinv = 1 / fraction_to_arb(r)
        for cols, keys in groups.items():
            M = arb_mat(n, n, [arb(Vint[a][t]) / two_S for a in range(n) for t in cols])
            for i in sorted({i for i, _ in keys}):
                js = [j for (ii, j) in keys if ii == i]
                X = arb_mat(n, len(js), [arb(Vint[a][j]) / two_S for a in range(n) for j in js])
                W = (F.arb(i) * X) * rinv
                try:
                    lam = M.solve(W)
                except ZeroDivisionError:
                    continue
                for col, j in enumerate(js):
                    tot = arb(0)
                    for a in range(n):
                        tot += abs(lam[a, col])
                    if tot.is_finite():
                        out[(i, j)] = arb_to_fraction_bounds(tot)[1]
    return out


def _integer_combination(supp, lam, T: int, Vint, n: int):
    """Coefficients ``lam`` rounded to integers ``lint`` = round(lam 2^T) and the exact integer
    combination ``comb = sum_s lint_s V[:, s]`` of the (integer-scaled) vertices."""
    lint = [int(round(float(np.ldexp(c, T)))) for c in lam]
    comb = [0] * n
    for s_, c in zip(supp, lint):
        if c:
            s_ = int(s_)
            for a in range(n):
                comb[a] += c * Vint[a][s_]
    return lint, comb
