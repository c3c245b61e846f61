"""Certified bounds between the divided differences of a control net and the derivatives of its limit
(the regular-part ingredient of Zorin's C^1 test); pieces of a proof, not a C^1 verdict.

Setting (:mod:`analysis.bivariate`): a dyadic mask ``a`` on ``Z^2`` (the three-direction grid in lattice
coordinates), ``f = sum_i f_k(i) phi(2^k x - i)`` the limit of the level-k net ``f_k``. On the cell
``Q = 2^-k (i0 + [0, 1]^2)`` the *local net* is ``u(j) = f_k(i0 - j)``, ``j`` in the invariant support
``Omega`` (:func:`analysis.bivariate.transition.invariant_support`), and the child cell of digit ``eps`` has the
local net ``T_eps^T u`` (``(T_eps)_{j,i} = a(eps + 2 j - i)``). Along a lattice direction ``e`` the divided
difference of the cell is ``d_k(Q) = 2^k (u(-e) - u(0))`` (the edge from ``2^-k i0`` to ``2^-k (i0 + e)``).

Algorithm
---------
1. *Defect functionals.* Following the point x through nested cells ``Q_k ⊃ Q_{k+1} ⊃ ...``,
   ``d_{m+1}(Q_{m+1}) - d_m(Q_m) = 2^m g_eps(u_m)`` with ``g_eps = 2 l_e T_eps^T - l_e``,
   ``l_e(u) = u(-e) - u(0)``. When the mask reproduces linear polynomials, ``g_eps`` vanishes on them, so
   ``g_eps(u) = h_eps . c(u)`` with ``c(u) = B^T u`` the coordinates of ``u`` modulo linear polynomials
   (``B`` the exact basis of ``V_2``, :func:`analysis.bivariate.transition.difference_subspace`: ``c_t(u)`` is
   ``u`` at a point minus its linear interpolant from three fixed points). :func:`defect_functionals`
   computes ``h_eps`` exactly and checks ``g_eps = (B h_eps)^T`` exactly.
2. *Contraction.* ``c(T_eps^T u) = A_eps c(u)`` with ``A_eps = X_eps^T``, ``X_eps = T_eps|V_2``
   (:func:`analysis.bivariate.transition.restricted_transition`). In coordinates ``z = W c`` (``W`` an exact
   rational matrix; a near-extremal ellipsoid of the family, found in floats, only conditions the search)
   :func:`contraction_certificate` builds a finite complete product tree: every node's product
   ``P_w = W A_{w_L} ... A_{w_1} W^{-1}`` is enclosed in Arb and a node is a leaf when
   ``||P_w||_inf <= r^|w|`` is proven. Every word then splits into leaves and one internal node, so
   ``||W A_w W^{-1}||_inf <= C r^|w|`` with ``C = max`` over internal nodes of ``||P_w|| / r^|w|`` (an upper
   bound, rounded up to a rational).
3. *Error bound.* With ``2 r < 1`` the increments of step 1 decay geometrically, so the divided-difference
   nets converge uniformly to a continuous ``g``; the scheme converges (its Hölder exponent > 1 is certified),
   and Riemann sums give ``f(y + t e) - f(y) = int_0^t g``, so ``d_m(Q_m) -> D_e f(x)`` (the argument is
   written out in :mod:`analysis.vertex.defectsum`). Summing step 1 with step 2::

       |D_e f(x) - d_k(Q)| <= 2^k K ||W c(u_k)||_inf,   K = H C / (1 - 2 r),   H = max_eps ||h_eps W^{-1}||_1

   for every x in the closed cell Q (:func:`derivative_error_bound`; ``W^{-1}`` and ``H`` enclosed in Arb).

4. *One cell.* :func:`jacobian_sign_on_cell` proves the Jacobian of the limit of one sign on a cell from the
   discrete Jacobian minus the propagated error, refining where needed. :mod:`analysis.vertex.zorin` applies
   it to the characteristic map of the modified butterfly.

Examples
--------
>>> from schemes.surfaces import get
>>> h = defect_functionals(get("butterfly").mask(w="1/16"), (1, 0))
>>> len(h["h"]), h["dimension"], h["omega_size"]
(4, 43, 46)

References
----------
D. Zorin, *A method for analysis of C^1-continuity of subdivision surfaces*, SIAM J. Numer. Anal. 37 (2000)
1677-1708 (divided differences of the control net, difference schemes, error bounds of the derivatives).
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numerica 11 (2002) 73-144 (difference
schemes and the convergence of divided differences). C. Cabrelli, C. Heil, U. Molter, *Self-similarity and
multiwavelets in higher dimensions*, Mem. AMS 170 (2004) (transition operators on the invariant support).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result

__all__ = ["defect_functionals", "ellipsoid_coordinates", "contraction_certificate", "derivative_error_bound",
           "jacobian_sign_on_cell", "net_size",
           "DIRECTIONS", "MAX_NODES", "MAX_DEPTH"]

#: the three edge directions of the three-direction grid in lattice coordinates
DIRECTIONS = ((1, 0), (0, 1), (1, 1))
#: default limits on the nodes and the depth of the product tree
MAX_NODES = 20_000
MAX_DEPTH = 24


def _second_difference_family(a):
    from ..bivariate.transition import restricted_transition

    if tuple(map(tuple, a.dilation.matrix)) != ((2, 0), (0, 2)):
        raise AnalysisError("the divided-difference bounds are for the dilation 2I (dyadic refinement) only")
    return restricted_transition(a, 2)


def defect_functionals(a, e: tuple[int, int]) -> dict[str, Any]:
    """The exact vectors ``h_eps`` with ``2 l_e T_eps^T - l_e = (B h_eps)^T`` (step 1 of the module docstring).

    Returns ``{"h": [h_eps as lists of fmpq], "omega_size", "dimension", "basis", "family"}``; an
    :class:`AnalysisError` when ``0`` or ``-e`` is not in ``Omega`` or the defect does not vanish on linear
    polynomials (the mask does not reproduce them).
    """
    from flint import fmpq, fmpq_mat

    from ..bivariate.transition import difference_subspace

    fam = _second_difference_family(a)
    omega = fam.omega
    index = {p: s for s, p in enumerate(omega)}
    if (0, 0) not in index or (-e[0], -e[1]) not in index:
        raise AnalysisError(f"the edge (0, 0) -> {e} is not inside the invariant support")
    N = len(omega)
    ell = fmpq_mat(N, 1)
    ell[index[(-e[0], -e[1])], 0] = 1
    ell[index[(0, 0)], 0] = -1
    B, free = difference_subspace(omega, 2)
    hs = []
    for T in fam.full:
        g = T * ell * fmpq(2) - ell                 # column form of 2 l_e T^T - l_e
        h = fmpq_mat(B.ncols(), 1)
        for t, f in enumerate(free):
            h[t, 0] = g[f, 0]
        if B * h != g:
            raise AnalysisError(f"the defect along {e} does not vanish on linear polynomials: the mask does "
                                "not reproduce them on this lattice")
        hs.append([h[t, 0] for t in range(B.ncols())])
    return {"h": hs, "omega_size": N, "dimension": B.ncols(), "basis": B, "family": fam}


def ellipsoid_coordinates(mats) -> "Any":
    """An exact rational ``W`` (``fmpq_mat``, entries with denominators <= 2^40) making the family's
    sum-of-squares ellipsoid round (:func:`analysis.jsr._search.balancing_transform`; floats only choose ``W``,
    every bound proven with it is exact or Arb).

    >>> from flint import fmpq_mat
    >>> W = ellipsoid_coordinates([fmpq_mat([[1, 0], [0, 1]])])
    >>> W.nrows()
    2
    """
    import numpy as np
    from flint import fmpq, fmpq_mat

    from ..jsr._search import balancing_transform

    fl = [np.array([[float(M[i, j]) for j in range(M.ncols())] for i in range(M.nrows())]) for M in mats]
    R, _ = balancing_transform(fl)
    R = R / np.abs(R).max()
    n = R.shape[0]
    return fmpq_mat([[fmpq(*Fraction(float(R[i, j])).limit_denominator(2 ** 40).as_integer_ratio())
                      for j in range(n)] for i in range(n)])


def _arb_inf_norm_upper(M) -> Fraction:
    """A rational upper bound of ``||M||_inf`` for an ``arb_mat`` (row sums of the balls' moduli)."""
    from flint import arb

    best = arb(0)
    entries, m = M.entries(), M.ncols()
    for i in range(M.nrows()):
        s = sum(map(abs, entries[i * m:(i + 1) * m]), arb(0))      # the same additions, in order
        best = best.max(s) if i else s
    return _upper(best)


def _arb_inverse(W):
    """An Arb enclosure of ``W^{-1}`` (at the current precision); an error when W is not proven invertible."""
    from flint import arb_mat

    try:
        return arb_mat(W).inv()
    except ZeroDivisionError:
        raise AnalysisError("the coordinate matrix W is not proven invertible") from None


def _upper(x) -> Fraction:
    """A rational upper bound of ``|x|`` for an arb ball (its exact upper endpoint, a dyadic)."""
    u = abs(x).upper()
    m, ex = u.man_exp()
    return Fraction(int(m)) * (Fraction(2) ** int(ex))


def contraction_certificate(mats, r, *, W=None, max_nodes: int = MAX_NODES, max_depth: int = MAX_DEPTH,
                            prec: int = 128) -> Result:
    """A certified bound ``||W A_w W^{-1}||_inf <= C r^|w|`` for every word ``w`` over ``mats`` (``fmpq_mat``;
    the word ``w`` acts as ``A_{w_L} ... A_{w_1}``), by a finite complete product tree (step 2 of the module
    docstring). ``r`` rational. ``value = C`` (an exact rational upper bound) when certified; *inconclusive*
    when the tree exceeds ``max_nodes`` nodes or ``max_depth`` levels (``witness["stuck_word"]`` is a word still
    above ``r^|w|``).

    >>> from flint import fmpq, fmpq_mat
    >>> A = [fmpq_mat([[1, 1], [0, 1]]) * fmpq(1, 4), fmpq_mat([[1, 0], [0, 1]]) * fmpq(1, 3)]
    >>> res = contraction_certificate(A, Fraction(2, 5))
    >>> res.status, res.value >= 1, res.witness["leaves"] > 0
    ('certified', True, True)
    """
    from flint import arb_mat, ctx, fmpq_mat

    r = Fraction(r)
    if not 0 < r:
        raise AnalysisError("the contraction factor r must be positive")
    n = mats[0].nrows()
    if W is None:
        W = fmpq_mat([[int(i == j) for j in range(n)] for i in range(n)])
    old = ctx.prec
    ctx.prec = prec
    try:
        Wi = _arb_inverse(W)
        fam = [arb_mat(W) * arb_mat(A) * Wi for A in mats]
        C = Fraction(1)
        nodes = leaves = depth = 0
        stack = [((), arb_mat(fmpq_mat([[int(i == j) for j in range(n)] for i in range(n)])))]
        while stack:
            word, P = stack.pop()
            nodes += 1
            if nodes > max_nodes or len(word) > max_depth:
                return Result(status=INCONCLUSIVE, witness={"stuck_word": word, "nodes": nodes, "r": r},
                              provenance={"method": "product tree (Arb)", "message":
                                          f"the product tree exceeded {max_nodes} nodes or {max_depth} levels "
                                          f"(the word {''.join(map(str, word[:12]))}{'...' if len(word) > 12 else ''}"
                                          f" is not below r^|w|): no bound C r^|w| proven"})
            norm = _arb_inf_norm_upper(P)
            rd = r ** len(word)
            if word and norm <= rd:
                leaves += 1
                depth = max(depth, len(word))
                continue
            C = max(C, norm / rd)
            for k, A in enumerate(fam):
                stack.append((word + (k,), A * P))
    finally:
        ctx.prec = old
    return Result(value=C, status=CERTIFIED,
                  witness={"r": r, "C": C, "nodes": nodes, "leaves": leaves, "depth": depth},
                  provenance={"method": "complete product tree: ||P_w||_inf <= r^|w| proven at every leaf (Arb); "
                                        "C = max over internal nodes of ||P_w||_inf / r^|w|",
                              "arithmetic": f"exact W, Arb products at {prec} bits"})


def derivative_error_bound(a, r, *, W=None, holder=None, max_nodes: int = MAX_NODES) -> Result:
    """The constant ``K`` of ``|D_e f(x) - d_k(Q)| <= 2^k K ||W c(u_k)||_inf`` for the three directions ``e`` and
    every x in the closed cell ``Q`` (step 3 of the module docstring).

    Certified when (i) the scheme is C^1 — from ``holder`` (a :func:`analysis.bivariate.holder.holder_exponent`
    result, computed here when not given) with a certified Hölder exponent > 1; then the divided differences of
    the nets converge uniformly to the derivatives (Dyn–Levin 2002), so ``d_m(Q_m) -> D_e f(x)`` — and (ii) the
    product tree closes for the given ``r < 1/2``. Otherwise *inconclusive*, saying which part is missing.

    ``witness``: ``r``, ``C``, ``H`` (per direction), ``W`` (the coordinates ``z = W c``), ``tree``, ``holder``.

    Examples
    --------
    >>> from schemes.surfaces import get
    >>> k = derivative_error_bound(get("loop").mask(), Fraction(2, 5))
    >>> k.status, 100 < k.value < 200, k.witness["tree"].witness["depth"]
    ('certified', True, 4)
    """
    from ..bivariate.holder import holder_exponent, smoothness_verdicts

    r = Fraction(r)
    if not 0 < 2 * r < 1:
        raise AnalysisError("the error bound needs 0 < r < 1/2 (the divided differences' defects must sum)")
    if holder is None:
        holder = holder_exponent(a)
    defects = {e: defect_functionals(a, e) for e in DIRECTIONS}
    fam = defects[DIRECTIONS[0]]["family"]
    mats = [X.transpose() for X in fam.matrices]
    if W is None:
        W = ellipsoid_coordinates(mats)
    wit: dict[str, Any] = {"r": r, "W": W, "holder": holder, "norm": "inf"}
    prov = {"method": "K = H C / (1 - 2r): defect functionals (exact) summed along nested cells with the "
                      "product-tree contraction of the second differences (Zorin 2000)"}
    if smoothness_verdicts(holder).get(1) is not True:
        return Result(status=INCONCLUSIVE, witness=wit,
                      provenance={**prov, "message": "the scheme is not certified C^1 (Hölder exponent > 1 not "
                                                     "proven): the divided differences need not tend to D_e f"})
    tree = contraction_certificate(mats, r, W=W, max_nodes=max_nodes)
    wit["tree"] = tree
    if not tree.is_certified:
        return Result(status=INCONCLUSIVE, witness=wit,
                      provenance={**prov, "message": tree.provenance.get("message", "the product tree did not close")})
    from flint import arb, ctx

    old = ctx.prec
    ctx.prec = 128
    try:
        Wi = _arb_inverse(W)
        H = {}
        for e, d in defects.items():
            best = Fraction(0)
            for h in d["h"]:
                total = arb(0)
                for s in range(Wi.ncols()):
                    total += abs(sum((arb(h[t]) * Wi[t, s] for t in range(len(h)) if h[t] != 0), start=arb(0)))
                best = max(best, _upper(total))
            H[e] = best
    finally:
        ctx.prec = old
    C = tree.value
    K = max(H.values()) * C / (1 - 2 * r)
    wit.update({"C": C, "H": H})
    return Result(value=K, status=CERTIFIED, witness=wit, provenance=prov)


def cell_frame(a, bound: Result, direction):
    """What a cell test needs from a certified :func:`derivative_error_bound`: ``(K, W, family, basis, omega,
    index)`` — the constant, the coordinate matrix, the defect family along ``direction`` with its basis, its
    invariant support and the position of each support point."""
    if not bound.is_certified:
        raise AnalysisError("the derivative error bound of the regular part is not certified")
    d = defect_functionals(a, direction)
    fam = d["family"]
    return bound.value, bound.witness["W"], fam, d["basis"], fam.omega, {p: s for s, p in enumerate(fam.omega)}


def net_size(z, norm: str = "inf"):
    """``||z||`` of a column ``acb_mat`` as an Arb ball: the maximum modulus (``norm="inf"``, the bound of
    :func:`derivative_error_bound`) or the Euclidean norm (``"2"``, :func:`analysis.vertex.defectsum.defect_sum_bound`).

    >>> from flint import acb_mat
    >>> z = acb_mat([[3], [4j]])
    >>> float(net_size(z).mid()), float(net_size(z, "2").mid())
    (4.0, 5.0)
    """
    from flint import arb

    if norm == "2":
        total = arb(0)
        for t in range(z.nrows()):
            y = abs(z[t, 0])
            total += y * y
        return (total.mid() + total.rad()).sqrt()          # an enclosure of an upper bound (total >= 0)
    if norm != "inf":
        raise AnalysisError(f"unknown norm {norm!r} of the second differences")
    zmax = arb(0)
    for t in range(z.nrows()):
        zmax = zmax.max(abs(z[t, 0])) if t else abs(z[t, 0])
    return zmax


def jacobian_sign_on_cell(a, net, bound: Result, *, max_depth: int = 6, max_cells: int = 5000,
                          prec: int = 128, frame=None) -> Result:
    """Prove that the Jacobian ``Im(conj(D_e1 f) D_e2 f)`` of the limit ``f`` (complex valued) has one sign on
    the closed cell ``Q = [0, 1]^2`` of the net ``net`` (the local net ``u(j) = f_0(-j)``, ``j`` in ``Omega``:
    exact numbers or complex balls), refining the cell where the bound does not suffice.

    On a cell of level m with local net u: ``d_i = 2^m (u(-e_i) - u(0))``, ``E_i = 2^m K_i ||W c(u)||``
    (``bound`` a certified :func:`derivative_error_bound`, maximum norm and one K, or
    :func:`analysis.vertex.defectsum.defect_sum_bound`, Euclidean norm and ``K_i`` per direction), and for every x
    in the cell ``|J(x) - Im(conj(d_1) d_2)| <= E_1 |d_2| + E_2 |d_1| + E_1 E_2`` (``|D_i f - d_i| <= E_i``). The cell is proven
    when ``s Im(conj(d_1) d_2)`` minus that exceeds 0 in Arb for one sign ``s`` shared by all cells; otherwise
    its four children (``T_eps^T u``) are tried, down to ``max_depth`` levels.

    ``frame``: ``cell_frame(a, bound, (1, 0))`` when the caller tests many cells (computed here otherwise).

    ``value``: the sign (+1 or -1) when certified; ``witness``: ``cells`` proven, ``depth`` reached,
    ``unproven`` (cells left at ``max_depth``, with the first one's digits).

    Examples
    --------
    >>> from schemes.surfaces import get
    >>> loop = get("loop").mask()
    >>> k = derivative_error_bound(loop, Fraction(2, 5))
    >>> omega = defect_functionals(loop, (1, 0))["family"].omega
    >>> lin = [complex(-x + 0.5 * y, -y) for x, y in omega]        # f(x, y) = x - y/2 + i y, sampled
    >>> r = jacobian_sign_on_cell(loop, lin, k)
    >>> r.status, r.value, r.witness["cells"]
    ('certified', 1, 1)
    """
    from flint import acb, acb_mat, arb, ctx

    K, W, fam, B, omega, idx = frame if frame is not None else cell_frame(a, bound, (1, 0))
    K1, K2 = (bound.witness.get("K_by_direction", {}).get(e, K) for e in ((1, 0), (0, 1)))
    norm = bound.witness["norm"]                 # the norm of W c the constants were proven in ("inf" or "2")
    if frame is not None and frame[1] != bound.witness["W"]:
        raise AnalysisError("the frame's coordinates W are not the bound's")
    if len(net) != len(omega):
        raise AnalysisError(f"the local net has {len(net)} values, the invariant support {len(omega)} points")
    i0, i1, i2 = idx[(0, 0)], idx[(-1, 0)], idx[(0, -1)]
    old = ctx.prec
    ctx.prec = prec
    try:
        Tt = [acb_mat(T.transpose()) for T in fam.full]
        WBt = acb_mat(W * B.transpose())
        Ka, Kb = (arb(k.numerator) / k.denominator for k in (K1, K2))
        u0 = acb_mat([[acb(x.real, x.imag) if isinstance(x, complex) else acb(x)] for x in net])
        sign = 0
        proven = 0
        depth = 0
        stack = [((), u0)]
        unproven: list = []
        while stack:
            word, u = stack.pop()
            if proven + len(stack) + len(unproven) > max_cells:
                unproven.append(word)
                break
            m = len(word)
            depth = max(depth, m)
            scale = 2 ** m
            da = (u[i1, 0] - u[i0, 0]) * scale
            db = (u[i2, 0] - u[i0, 0]) * scale
            size = net_size(WBt * u, norm) * scale
            Ea, Eb = Ka * size, Kb * size
            jd = (da.conjugate() * db).imag
            err = Ea * abs(db) + Eb * abs(da) + Ea * Eb
            ok = 0
            for s in ((sign,) if sign else (1, -1)):
                if (jd * s - err) > 0:
                    ok = s
                    break
            if ok:
                sign = ok
                proven += 1
            elif m < max_depth:
                for k in range(len(Tt)):
                    stack.append((word + (k,), Tt[k] * u))
            else:
                unproven.append(word)
    finally:
        ctx.prec = old
    wit = {"cells": proven, "depth": depth, "unproven": len(unproven),
           "first_unproven": unproven[0] if unproven else None, "K": K}
    prov = {"method": "Jacobian of the limit bounded by the discrete Jacobian of the cell minus the propagated "
                      "derivative error bound; adaptive refinement (Zorin 2000)", "arithmetic": f"Arb, {prec} bits"}
    if unproven or not sign:
        return Result(status=INCONCLUSIVE, witness=wit,
                      provenance={**prov, "message": f"{len(unproven)} cell(s) not proven within {max_depth} levels "
                                                     f"or {max_cells} cells"})
    return Result(value=sign, status=CERTIFIED, witness=wit, provenance=prov)
