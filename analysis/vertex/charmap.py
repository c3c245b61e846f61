"""The characteristic map, certified regular and injective with Arb balls: Catmull–Clark-type rules
(bicubic patches), Loop-type rules (quartic box-spline patches, :mod:`.boxspline`) and Doo–Sabin
(biquadratic patches on the dual lattice).

The characteristic map is the limit of the planar control net given by the subdominant eigenvector:
with ``v`` the eigenvector of Fourier block 1 for lambda (normalised ``v_e = 1``), sector j of the net
is ``w^j v`` (``w = exp(2 pi i / n)``, a point of the plane as a complex number) and the centre is 0.
By the eigen-relation it is scaled by lambda per step, so it is determined by one *segment*: the three
level-1 quads of sector 0 that lie in the level-0 1-ring but not in the level-1 1-ring,
``[1,2]x[0,1]``, ``[1,2]x[1,2]``, ``[0,1]x[1,2]`` in level-1 lattice coordinates. Each is a bicubic
patch whose 4 x 4 B-spline net is read from the level-1 points (the 2-ring ones are ``lambda v``, the
others come from the regular stencils); it is converted to Bézier form.

Regularity: the Jacobian ``det D Psi = Im(conj(Psi_u) Psi_v)`` of each patch is a polynomial of degree
(5, 5) whose Bernstein coefficients are computed in Arb from an Arb enclosure of the eigenvector; all
coefficients of one sign prove the sign on the closed patch (the patch is subdivided by de Casteljau where
they are not). Injectivity: a regular characteristic map whose restriction to the outer boundary of the
segment ring has winding number +-1 around the origin (the sign of the Jacobian) is injective (Reif
1995; Peters–Reif 2008, ch. 5); a regular map whose boundary winds any other number of times is not;
the winding number is certified from the argument increments of the boundary's Bézier pieces, each
proven to lie in an open cone of angle < pi (subdivided until it does).

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> from analysis.vertex.spectrum import analyse
>>> cc = scheme_rules("catmull-clark", ring=2)
>>> r = characteristic_map(cc, 5, analyse(cc, 5).lam.ball.real)
>>> r["status"], r["regular"], r["winding_number"]
('certified', True, 1)

References
----------
U. Reif, A unified approach to subdivision algorithms near extraordinary vertices, CAGD 12 (1995);
J. Peters, U. Reif, Subdivision Surfaces, Springer 2008, ch. 5 (the characteristic map, regularity,
injectivity) and ch. 6 (Catmull–Clark); D. Zorin, A method for analysis of C^1-continuity of subdivision
surfaces, SIAM J. Numer. Anal. 37 (2000) (verification by interval bounds on Jacobians).
"""

from __future__ import annotations

from math import comb

import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, REFUTED, AnalysisError
from .blocks import _laurent, fourier_block, w
from .rules import C1, LocalRules, _quad_home, _tri_home

#: the segment: lower-left corners of its three level-1 quads in sector 0
SEGMENT = ((1, 0), (1, 1), (0, 1))
#: uniform cubic B-spline -> Bézier (rows: Bézier points, columns: B-spline points)
_BSPLINE_TO_BEZIER = ((1, 4, 1, 0), (0, 4, 2, 0), (0, 2, 4, 0), (0, 1, 4, 1))
MAX_DEPTH = 5


def _acb_entry(expr: sp.Expr, n: int, k: int = 1):
    """An entry of Fourier block k (a Laurent polynomial in w = exp(2 pi i k/n)) as a complex ball."""
    from flint import acb, arb, fmpq

    if expr == 0:                                    # most entries of a block on many rings
        return acb(0)
    c1 = arb.cos_pi_fmpq(fmpq(2, n))
    total = acb(0)
    for l_, co in _laurent(expr, w).items():
        poly = sp.Poly(co, C1)
        val = arb(0)
        for (i,), q in poly.terms():
            q = sp.Rational(q)
            val += arb(int(q.p)) / int(q.q) * c1 ** i
        total += acb(val) * acb(fmpq(2 * l_ * k, n)).exp_pi_i()
    return total


def eigenvector(rules: LocalRules, n: int, lam_ball, k: int = 1) -> list:
    """An Arb enclosure of an eigenvector of Fourier block k for the eigenvalue in ``lam_ball`` (block 1 and
    lambda: the characteristic map's), normalised so that one entry is 1 (the first one that works): the
    remaining entries solve all but one equation of ``(B - lambda I) v = 0``, for every lambda in the ball
    (a solve that succeeds proves the reduced system nonsingular there, so the eigenvalue is geometrically
    simple in the block).

    The dropped equation is not checked: the result encloses an eigenvector only if ``lam_ball`` contains the
    true eigenvalue (then that equation holds there, as ``B - lambda I`` is singular). Callers pass an
    isolating ball of a certified eigenvalue of the block (:func:`analysis.vertex.spectrum.analyse`)."""
    from flint import acb, acb_mat

    B = fourier_block(rules, k, n)
    m = B.rows
    M = [[_acb_entry(B[i, j], n, k) - (acb(lam_ball) if i == j else 0) for j in range(m)] for i in range(m)]
    for one in range(m):
        cols = [j for j in range(m) if j != one]
        for drop in range(m):
            rows = [i for i in range(m) if i != drop]
            A = acb_mat([[M[i][j] for j in cols] for i in rows])
            b = acb_mat([[-M[i][one]] for i in rows])
            try:
                x = A.solve(b)
            except (ZeroDivisionError, ValueError):
                continue
            v = [x[i, 0] for i in range(m - 1)]
            return v[:one] + [acb(1)] + v[one:]
    raise AnalysisError(f"the eigenvector of lambda at valence {n} could not be enclosed")


class _Net:
    """Level-0 and level-1 control points of the characteristic net (complex balls), sector 0 and its
    rotations."""

    def __init__(self, rules: LocalRules, n: int, v: list, lam_ball, k: int = 1):
        from flint import acb, fmpq

        off = 1 if (rules.centre and k == 0) else 0           # block 0 has the centre first
        self.n, self.v, self.lam = n, v[off:], acb(lam_ball)
        self.centre = v[0] if off else acb(0)
        self.index = {p: i for i, p in enumerate(rules.coords)}
        self.rot = [acb(fmpq(2 * d * k, n)).exp_pi_i() for d in range(n)]
        self.cache: dict = {}

    home = staticmethod(_quad_home)

    def _home(self, x, y):
        d, hx, hy = self.home(x, y)
        return self.rot[d % self.n], (hx, hy)

    def level0(self, x, y):
        r, h = self._home(x, y)
        if h == (0, 0):
            return self.centre
        if h not in self.index:
            raise AnalysisError(f"level-0 point {h} is outside the rings")
        return r * self.v[self.index[h]]

    def level1(self, X, Y):
        r, (hx, hy) = self._home(X, Y)
        if (hx, hy) == (0, 0):
            return self.lam * self.centre
        if (hx, hy) in self.index:                 # in the 2-ring: lambda v (the eigen-relation)
            return r * self.lam * self.v[self.index[(hx, hy)]]
        if (hx, hy) not in self.cache:
            self.cache[(hx, hy)] = self._regular(hx, hy)
        return r * self.cache[(hx, hy)]

    def _regular(self, X, Y):
        from flint import acb

        L0 = self.level0
        if X % 2 == 0 and Y % 2 == 0:
            x, y = X // 2, Y // 2
            return (acb(9) / 16 * L0(x, y) + acb(3) / 32 * sum((L0(x + a, y + b) for a, b in
                                                                 ((1, 0), (0, 1), (-1, 0), (0, -1))), acb(0))
                    + acb(1) / 64 * sum((L0(x + a, y + b) for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1))), acb(0)))
        if X % 2 == 1 and Y % 2 == 1:
            x, y = (X - 1) // 2, (Y - 1) // 2
            return acb(1) / 4 * (L0(x, y) + L0(x + 1, y) + L0(x, y + 1) + L0(x + 1, y + 1))
        if X % 2 == 1:
            x, y = (X - 1) // 2, Y // 2
            return (acb(3) / 8 * (L0(x, y) + L0(x + 1, y))
                    + acb(1) / 16 * (L0(x, y - 1) + L0(x + 1, y - 1) + L0(x, y + 1) + L0(x + 1, y + 1)))
        x, y = X // 2, (Y - 1) // 2
        return (acb(3) / 8 * (L0(x, y) + L0(x, y + 1))
                + acb(1) / 16 * (L0(x - 1, y) + L0(x - 1, y + 1) + L0(x + 1, y) + L0(x + 1, y + 1)))

    def bezier(self, a: int, b: int) -> list[list]:
        """The 4 x 4 Bézier net of the level-1 quad [a, a+1] x [b, b+1] (index [i][j]: i along x)."""
        P = [[self.level1(a - 1 + i, b - 1 + j) for j in range(4)] for i in range(4)]
        T = _BSPLINE_TO_BEZIER
        rows = [[sum((P[i][j] * T[r][i] for i in range(4)), 0 * P[0][0]) / 6 for j in range(4)] for r in range(4)]
        return [[sum((rows[r][j] * T[s][j] for j in range(4)), 0 * P[0][0]) / 6 for s in range(4)] for r in range(4)]


def _jacobian_bernstein(Bz: list[list]) -> list[list]:
    """Bernstein coefficients (degree 2d-1 x 2d-1) of Im(conj(F_u) F_v) for a tensor Bézier net Bz of
    degree d x d (bicubic: d = 3, biquadratic: d = 2)."""
    d = len(Bz) - 1
    Fu = [[d * (Bz[i + 1][j] - Bz[i][j]) for j in range(d + 1)] for i in range(d)]     # degree (d-1, d)
    Fv = [[d * (Bz[i][j + 1] - Bz[i][j]) for j in range(d)] for i in range(d + 1)]     # degree (d, d-1)
    e = 2 * d - 1
    out = [[None] * (e + 1) for _ in range(e + 1)]
    for k in range(e + 1):
        for l_ in range(e + 1):
            s = None
            for i in range(max(0, k - d), min(d - 1, k) + 1):
                ii = k - i
                for j in range(max(0, l_ - d + 1), min(d, l_) + 1):
                    jj = l_ - j
                    wgt = comb(d - 1, i) * comb(d, ii) * comb(d, j) * comb(d - 1, jj)
                    t = (Fu[i][j].conjugate() * Fv[ii][jj]).imag * wgt
                    s = t if s is None else s + t
            out[k][l_] = s / (comb(e, k) * comb(e, l_))
    return out


def _split(coeffs: list[list], axis: int) -> tuple[list[list], list[list]]:
    """de Casteljau halves of a tensor Bernstein polynomial along ``axis`` (0: u, 1: v)."""
    def halves(row):
        left, right, cur = [], [], list(row)
        while cur:
            left.append(cur[0])
            right.append(cur[-1])
            cur = [(cur[i] + cur[i + 1]) / 2 for i in range(len(cur) - 1)]
        return left, right[::-1]

    if axis == 0:
        cols = [halves([coeffs[i][j] for i in range(len(coeffs))]) for j in range(len(coeffs[0]))]
        L = [[cols[j][0][i] for j in range(len(cols))] for i in range(len(coeffs))]
        R = [[cols[j][1][i] for j in range(len(cols))] for i in range(len(coeffs))]
        return L, R
    pairs = [halves(r) for r in coeffs]
    return [p[0] for p in pairs], [p[1] for p in pairs]


def _one_sign(jac, first, certified):
    """``(sign, pieces, regular)``: the sign of the first Bernstein coefficient ``first`` (0 when it is not
    certainly nonzero) and whether every Jacobian in ``jac`` is certified of that sign by ``certified(J,
    sign) -> (ok, pieces)`` (stopping at the first failure)."""
    sign = 1 if first > 0 else (-1 if first < 0 else 0)
    pieces, regular = 0, sign != 0
    for J in jac:
        if not regular:
            break
        ok, k = certified(J, sign)
        pieces += k
        regular = regular and ok
    return sign, pieces, regular


def _sign_certified(coeffs: list[list], sign: int, depth: int = 0) -> tuple[bool, int]:
    """Is the Bernstein polynomial of one sign on its square? (pieces examined)"""
    flat = [x for row in coeffs for x in row]
    if all((x > 0) if sign > 0 else (x < 0) for x in flat):
        return True, 1
    if any((x < 0) if sign > 0 else (x > 0) for x in (coeffs[0][0], coeffs[0][-1], coeffs[-1][0], coeffs[-1][-1])):
        return False, 1                             # a corner value of the other sign: a certified failure
    if depth >= MAX_DEPTH:
        return False, 1
    pieces = 0
    for half in _split(coeffs, depth % 2):
        ok, k = _sign_certified(half, sign, depth + 1)
        pieces += k
        if not ok:
            return False, pieces
    return True, pieces


def _arg_increment(ctrl: list, depth: int = 0):
    """The certified argument increment along a Bézier curve with control points ``ctrl`` (complex
    balls), or None: each piece's control points lie in a cone of angle < pi around the first."""
    from flint import arb

    p0 = ctrl[0]
    try:
        rel = [(p / p0).arg() for p in ctrl]
    except ZeroDivisionError:
        rel = None
    if rel is not None and all(abs(r) < arb.pi() / 2 for r in rel):
        return rel[-1]
    if depth >= 8:
        return None
    left, right, cur = [], [], list(ctrl)
    while cur:
        left.append(cur[0])
        right.append(cur[-1])
        cur = [(cur[i] + cur[i + 1]) / 2 for i in range(len(cur) - 1)]
    a = _arg_increment(left, depth + 1)
    b = _arg_increment(right[::-1], depth + 1)
    return None if a is None or b is None else a + b


def _verdict(regular: bool, sign: int, pieces: int, curve: list, n: int, prec: int, arb, method: str) -> dict:
    """Winding number of the outer boundary (pieces of ``curve``, from sector 0's start to its rotation)
    and the status: certified (regular, winding = Jacobian sign), refuted (regular, other certified
    winding number), inconclusive. "Refuted" is about injectivity only: an injective map of the ring
    sends its outer boundary to a Jordan curve invariant under the rotation by 2 pi/n, which winds +-1
    around the fixed point 0 (with the orientation of the Jacobian); it is not a claim that the scheme
    is not C^1 (:func:`.valence.c1_verdict` reports that case inconclusive)."""
    incs = [_arg_increment(cp) for cp in curve]
    winding = None
    if all(x is not None for x in incs):
        total = sum(incs, arb(0))
        m = (total - 2 * arb.pi() / n) / (2 * arb.pi())
        mid = round(float(m.mid()))
        if abs(m - mid) < arb(1) / 2:
            winding = 1 + n * mid
    injective = bool(regular and winding is not None and winding == sign)
    if injective:
        status = CERTIFIED
    elif regular and winding is not None:
        status = REFUTED                      # regular, but its boundary winds |w| != 1 times (or against it)
    else:
        status = INCONCLUSIVE
    return {"status": status, "regular": regular, "jacobian_sign": sign, "pieces": pieces,
            "winding_number": winding, "injective": injective, "precision_bits": prec, "method": method}


def _segment_verdict(patches, jacobian, n: int, prec: int, kind: str) -> dict:
    """Regularity and injectivity from the three tensor-product Bézier patches of the segment (square
    patches of degree d): the Jacobian's Bernstein coefficients of one certified sign on every patch,
    then the winding number of the outer boundary, oriented from level-1 (2,0) to (0,2)."""
    from flint import arb

    jac = [jacobian(P) for P in patches]
    sign, pieces, regular = _one_sign(jac, jac[0][0][0], _sign_certified)
    A, Bq, C = patches
    d = len(A) - 1
    curve = [[A[d][j] for j in range(d + 1)], [Bq[d][j] for j in range(d + 1)],
             [Bq[d - i][d] for i in range(d + 1)], [C[d - i][d] for i in range(d + 1)]]
    return _verdict(regular, sign, pieces, curve, n, prec, arb,
                    f"{kind} Bézier patches of the segment; Arb Bernstein bounds of the Jacobian; "
                    "winding number of the outer boundary")


def characteristic_map(rules: LocalRules, n: int, lam_ball, prec: int = 128) -> dict:
    """Certified regularity (Jacobian of one sign on the segment) and injectivity (winding number of the
    outer boundary equal to that sign) of the characteristic map of quad or triangle rules on the 2-ring at
    valence n, at ``prec`` bits: status certified (regular and injective), refuted (regular, certified
    winding number of the wrong value: not injective) or inconclusive."""
    from flint import ctx

    if rules.lattice == "dual quad":
        return characteristic_map_doo_sabin(rules, n, lam_ball, prec)
    if rules.lattice not in ("quad", "triangle") or rules.ring != 2:
        raise AnalysisError("the characteristic map is checked for quad (bicubic) and triangle (Loop box-spline) "
                            "rules on the 2-ring, and for Doo-Sabin")
    if rules.lattice == "triangle":
        return characteristic_map_triangle(rules, n, lam_ball, prec)
    old = ctx.prec
    ctx.prec = prec
    try:
        v = eigenvector(rules, n, lam_ball)
        net = _Net(rules, n, v, lam_ball)
        return _segment_verdict([net.bezier(a, b) for a, b in SEGMENT], _jacobian_bernstein, n, prec, "bicubic")
    finally:
        ctx.prec = old


def segment_ordinates(rules: LocalRules, n: int, v: list, mu_ball, k: int) -> list:
    """The Bézier ordinates (complex balls) of the segment patches of the eigenfunction of block k with
    eigenvector ``v`` (entries as in :func:`eigenvector`) for the eigenvalue in ``mu_ball``: the same nets
    as the characteristic map's (bicubic patches on the quad lattice, quartic box-spline patches on the
    triangle lattice; rules on the 2-ring), with sector j scaled by exp(2 pi i j k/n).

    An ordinate that excludes 0 proves the eigenfunction nonzero on the segment (a polynomial patch with
    a nonzero Bézier ordinate is not the zero polynomial)."""
    from .boxspline import SUBTRIANGLES

    if rules.ring != 2 or rules.lattice not in ("quad", "triangle"):
        raise AnalysisError("eigenfunctions on the segment are evaluated for quad and triangle rules on the 2-ring")
    if rules.lattice == "triangle":
        net = _TriNet(rules, n, v, mu_ball, k)
        return [x for st in SUBTRIANGLES[1:] for x in net.bezier_tri(*st)]
    net = _Net(rules, n, v, mu_ball, k)
    return [x for a, b in SEGMENT for row in net.bezier(a, b) for x in row]


# --------------------------------------------------------------------------------------------------
# Loop-type rules: quartic box-spline patches

class _TriNet(_Net):
    """The characteristic net on the triangular lattice; level-1 points off the 2-ring by Loop's
    regular stencils."""

    home = staticmethod(_tri_home)

    def _regular(self, X, Y):
        from flint import acb

        from .boxspline import loop_stencil

        return sum((acb(int(w_.p)) / int(w_.q) * self.level0(*p) for w_, p in loop_stencil(X, Y)), acb(0))

    def bezier_tri(self, q0, a, b) -> list:
        """The 15 Bézier ordinates (order of ``BEZIER_INDEX``) of the level-1 sub-triangle (q0, a, b)."""
        from flint import acb

        from .boxspline import NET, loop_bezier_matrix

        net = [self.level1(q0[0] + x * a[0] + y * b[0], q0[1] + x * a[1] + y * b[1]) for x, y in NET]
        G = loop_bezier_matrix()
        out = []
        for i in range(G.rows):
            s = acb(0)
            for j in range(G.cols):
                if G[i, j] != 0:
                    s += net[j] * (acb(int(G[i, j].p)) / int(G[i, j].q))
            out.append(s)
        return out


def _multinomial(d: int, idx) -> int:
    from math import factorial

    return factorial(d) // (factorial(idx[0]) * factorial(idx[1]) * factorial(idx[2]))


def _tri_jacobian(beta: list) -> list:
    """Bernstein ordinates (degree 6) of Im(conj(D1 F) D2 F), D1, D2 the derivatives along the edges
    (vertex 0 -> 1, vertex 0 -> 2) of the quartic with ordinates ``beta``."""
    from .boxspline import bezier_index

    i4, i3, i6 = bezier_index(4), bezier_index(3), bezier_index(6)
    at = {idx: beta[k] for k, idx in enumerate(i4)}
    D1 = {(i, j, k): 4 * (at[(i, j + 1, k)] - at[(i + 1, j, k)]) for i, j, k in i3}
    D2 = {(i, j, k): 4 * (at[(i, j, k + 1)] - at[(i + 1, j, k)]) for i, j, k in i3}
    out = {idx: None for idx in i6}
    for a in i3:
        for b in i3:
            s = tuple(x + y for x, y in zip(a, b))
            t = (D1[a].conjugate() * D2[b]).imag * (_multinomial(3, a) * _multinomial(3, b)) / _multinomial(6, s)
            out[s] = t if out[s] is None else out[s] + t
    return [out[idx] for idx in i6]


def _tri_sign_certified(coeffs: list, sign: int, depth: int = 0) -> tuple[bool, int]:
    from .boxspline import bezier_index, restriction_matrices

    if all((x > 0) if sign > 0 else (x < 0) for x in coeffs):
        return True, 1
    idx = bezier_index(6)
    corners = [coeffs[idx.index(c)] for c in ((6, 0, 0), (0, 6, 0), (0, 0, 6))]
    if any((x < 0) if sign > 0 else (x > 0) for x in corners):
        return False, 1
    if depth >= 4:
        return False, 1
    pieces = 0
    for R in restriction_matrices(6):
        sub = []
        for i in range(R.rows):
            acc = 0 * coeffs[0]
            for j in range(R.cols):
                if R[i, j] != 0:
                    acc += coeffs[j] * (int(R[i, j].p)) / int(R[i, j].q)
            sub.append(acc)
        ok, k = _tri_sign_certified(sub, sign, depth + 1)
        pieces += k
        if not ok:
            return False, pieces
    return True, pieces


def characteristic_map_triangle(rules: LocalRules, n: int, lam_ball, prec: int = 128) -> dict:
    """As :func:`characteristic_map` for Loop-type rules on the 2-ring: the segment is the three level-1
    triangles of sector 0 away from the centre, each a quartic box-spline patch (Bézier form from
    :mod:`.boxspline`); the outer boundary runs from level-1 (2,0) over (1,1) to (0,2)."""
    from flint import arb, ctx

    from .boxspline import SUBTRIANGLES, bezier_index

    old = ctx.prec
    ctx.prec = prec
    try:
        v = eigenvector(rules, n, lam_ball)
        net = _TriNet(rules, n, v, lam_ball)
        patches = [net.bezier_tri(*st) for st in SUBTRIANGLES[1:]]
        jac = [_tri_jacobian(P) for P in patches]
        sign, pieces, regular = _one_sign(jac, jac[0][0], _tri_sign_certified)
        i4 = bezier_index(4)
        edge = [(0, 4 - t, t) for t in range(5)]                 # from vertex 1 to vertex 2
        curve = [[patches[0][i4.index(e)] for e in edge], [patches[1][i4.index(e)] for e in edge]]
        return _verdict(regular, sign, pieces, curve, n, prec, arb,
                        "quartic box-spline (Bézier) patches of the segment; Arb Bernstein bounds of the "
                        "Jacobian; winding number of the outer boundary")
    finally:
        ctx.prec = old


# --------------------------------------------------------------------------------------------------
# Doo–Sabin at an n-gon: biquadratic patches on the dual lattice

def _dual_home(x: int, y: int) -> tuple[int, int, int]:
    """Sector offset and doubled coordinates (odd integers, x > 0, y > 0) of the dual-lattice point
    (x/2, y/2) of sector 0 (rotation by one sector: (x, y) -> (y, -x) in the next sector)."""
    d = 0
    while not (x > 0 and y > 0):
        if y < 0:
            x, y, d = -y, x, d - 1
        else:
            x, y, d = y, -x, d + 1
    return d, x, y


#: Doo–Sabin's sector points (p, a, b, c) at doubled dual coordinates: point index and the sector offset
#: of the rules' point that sits there (b of sector j - 1 lies in sector j's quadrant)
_DS_COORDS = {(1, 1): (0, 0), (1, 3): (1, 0), (3, 1): (2, -1), (3, 3): (3, 0)}


class _DualNet(_Net):
    """The characteristic net of Doo–Sabin: level-1 points of the 4n set are lambda v; the others come
    from the regular rule of a quad (9/16, 3/16, 3/16, 1/16) on level-0 points."""

    def __init__(self, rules: LocalRules, n: int, v: list, lam_ball):
        super().__init__(rules, n, v, lam_ball)

    def _value(self, x, y, scale):
        d, hx, hy = _dual_home(x, y)
        if (hx, hy) not in _DS_COORDS:
            return None, d, (hx, hy)
        p, off = _DS_COORDS[(hx, hy)]
        return scale * self.rot[(d + off) % self.n] * self.v[p], d, (hx, hy)

    def level0(self, x, y):
        val, _, h = self._value(x, y, 1)
        if val is None:
            raise AnalysisError(f"level-0 point {h} is outside the rings")
        return val

    def level1(self, X, Y):
        val, d, (hx, hy) = self._value(X, Y, self.lam)
        if val is not None:
            return val
        if (hx, hy) not in self.cache:
            self.cache[(hx, hy)] = self._regular(hx, hy)
        return self.rot[d % self.n] * self.cache[(hx, hy)]

    def _regular(self, X, Y):
        from flint import acb

        # level-1 point (X/2, Y/2) lies in the level-0 dual face around the primal vertex (i, k), near its
        # corner (i + s/2, k + t/2); level-0 points in doubled coordinates
        i, k = round(X / 4), round(Y / 4)
        s = 1 if X > 4 * i else -1
        t = 1 if Y > 4 * k else -1
        P = lambda a, b: self.level0(2 * i + a, 2 * k + b)      # noqa: E731
        return (acb(9) / 16 * P(s, t) + acb(3) / 16 * (P(-s, t) + P(s, -t)) + acb(1) / 16 * P(-s, -t))

    def bezier_dual(self, a: int, b: int) -> list[list]:
        """The 3 x 3 Bézier net of the level-1 primal square [a, a+1] x [b, b+1] (index [i][j], i along x)."""
        Q = [[self.level1(2 * a - 1 + 2 * i, 2 * b - 1 + 2 * j) for j in range(3)] for i in range(3)]
        T = ((1, 1, 0), (0, 2, 0), (0, 1, 1))                       # quadratic B-spline -> Bézier, halves
        rows = [[sum((Q[i][j] * T[r][i] for i in range(3)), 0 * Q[0][0]) / 2 for j in range(3)] for r in range(3)]
        return [[sum((rows[r][j] * T[s][j] for j in range(3)), 0 * Q[0][0]) / 2 for s in range(3)] for r in range(3)]


def characteristic_map_doo_sabin(rules: LocalRules, n: int, lam_ball, prec: int = 128) -> dict:
    """As :func:`characteristic_map` for Doo–Sabin at an n-gon: the segment is the three level-1 squares
    [1,2]x[0,1], [1,2]x[1,2], [0,1]x[1,2] (primal lattice, sector 0), each a biquadratic patch."""
    from flint import ctx

    old = ctx.prec
    ctx.prec = prec
    try:
        v = eigenvector(rules, n, lam_ball)
        net = _DualNet(rules, n, v, lam_ball)
        return _segment_verdict([net.bezier_dual(a, b) for a, b in SEGMENT], _jacobian_bernstein, n, prec,
                                "biquadratic")
    finally:
        ctx.prec = old
