"""Joint spectral radius (JSR) of a finite family of real square matrices, with certificates.

``JSR(A_0, ..., A_{k-1}) = lim_L max_{|w| = L} ||A_{w_1} ... A_{w_L}||^(1/L)``. For a binary
subdivision scheme with difference mask ``c`` and transition matrices ``T_0, T_1``, the Hölder
exponent is ``alpha = k - log2 JSR(T_0, T_1)`` (see ``DESIGN.md``).

Main entry point: :func:`jsr_bounds` returns a :class:`~analysis.result.Result` with a rigorous
interval ``[lower, upper]`` (sympy Rationals; Python rationals for ball input), a status, the witness product and polytope, and
provenance.

Examples
--------
The classic pair whose JSR is the golden ratio, attained by ``A_0 A_1`` (length 2):

>>> r = jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], budget=5000)
>>> r.status, r.witness["product"], r.witness["length"], r.witness["closed"]
('certified', (0, 1), 2, True)
>>> import sympy as sp
>>> phi = (1 + sp.sqrt(5)) / 2
>>> bool(r.lower <= phi <= r.upper), float(r.upper / r.lower - 1) < 1e-12
(True, True)

Entries may be ``flint.arb`` balls (uncertain reals, e.g. a mask known only by certified
enclosures): the bounds then hold for every family inside the balls (see :func:`jsr_bounds`).

Float input gives the same numbers but the status ``numerical`` (the floats are taken as the
binary rationals they are only with ``floats_exact=True``):

>>> import numpy as np
>>> jsr_bounds([np.array([[0.5, 0.25], [0.0, 0.5]])]).status
'numerical'
>>> jsr_bounds([np.array([[0.5, 0.25], [0.0, 0.5]])], floats_exact=True).status
'certified'

Algorithm (``method="auto"``)
-----------------------------
1. Exact reductions: duplicates are removed; a single matrix has ``JSR = rho``; a common
   block-triangular structure (strongly connected components of the union of the sparsity
   patterns, as in Mejstrik 2020) splits the family into diagonal blocks with
   ``JSR = max_b JSR(block_b)``; for rational families, exact common invariant subspaces that
   are not coordinate subspaces are found by Krylov spins (:mod:`analysis.jsr._subspace`) and
   split off the same way; an exactly commuting family has ``JSR = max_i rho(A_i)``. An exact
   cyclic conjugation symmetry ``G A_{c_j} G^{-1} = A_{c_{j+1}}``, ``G^k = I``, replaces the family
   by ``B_d = A_{c_0} G^d`` (same JSR) when that splits it (:mod:`analysis.jsr._symmetry`).
2. Lower bound: a Gripenberg-type branch and bound for spectrum-maximizing products
   (:func:`analysis.jsr._search.smp_search`); the best word ``w`` gives
   ``JSR >= rho(P_w)^(1/|w|)``, certified from isolated roots of the exact characteristic
   polynomial (FLINT) or Arb eigenvalue enclosures.
3. Upper bound: the invariant polytope algorithm (Guglielmi–Protasov 2013; Mejstrik 2020),
   real symmetric case, started from the leading eigenvectors of the best product, of every
   product within ``1e-9`` of it (several s.m.p.s) and of the near ties within ``NEAR_ROOTS``
   that are no longer than it, scaled by *balancing* factors (Guglielmi–Protasov 2016), plus
   small *interior fillers* that make the polytope full-dimensional at once
   (:mod:`analysis.jsr._balance`). A badly scaled family (fast-decaying
   spectrum, e.g. Daubechies D20+) is first replaced by the exactly similar family in which its
   sum-of-squares ellipsoid is a ball. Restarts when a vertex path reveals a better product.
   A leading plane rotated by a rational angle (``rotation_order``: a finite orbit of ``Re u``)
   gets the share of a real leading eigenvalue, with smaller fillers (``theta = 1/8``).
   A polytope that is still *thin* (vertex matrix condition number above ``THIN_COND``) is
   decided on float rounding noise in its thin directions and never closes; it is then rebuilt
   for the exactly similar family ``S^{-1} A_i S`` (``S`` dyadic, from the SVD of the vertex
   matrix; matrices computed exactly or in Arb balls), in which it is round
   (:mod:`analysis.jsr._precondition`; up to 3 rounds).
4. Certificate: every membership ``A_i v_j / r in absconv(V)`` is re-checked exactly
   (:func:`analysis.jsr._polytope.certify_polytope`), giving ``JSR <= r * c`` rigorously.
5. A complex leading eigenvalue (an irrational rotation): the *complex* polytope, the complex
   balanced hull of ``u``, ``conj(u)`` and their orbits, closes exactly; memberships are second
   order cone programs and the certificate is re-checked in Arb complex balls
   (:mod:`analysis.jsr._complex`).
6. If no polytope closes: a best-first product tree (Gripenberg's branch and bound,
   :mod:`analysis.jsr._tree`) in the balanced ellipsoidal norm, certified in Arb balls: every
   infinite product has a prefix ``u`` among the leaves, so ``JSR <= max_u ||P_u||^(1/|u|)``; its
   longer products also raise the lower bound. Then the same polytope algorithm for
   ``A_i / (r (1 + eps))`` with decreasing ``eps`` below the tree's gap (a certified
   ``upper <= rho (1 + eps) c``); the rigorous norm bound ``max_{|w|=l} ||P_w||^(1/l)`` in a
   balanced basis is the last resort.

``method="polytope"`` skips step 1's structural shortcuts (not the single-matrix case);
``method="norms"`` is the textbook method: exhaustive products up to ``max_length``.

References
----------
G.-C. Rota, G. Strang, *A note on the joint spectral radius*, Indag. Math. 22 (1960) 379-381.
G. Gripenberg, *Computing the joint spectral radius*, Linear Algebra Appl. 234 (1996) 43-60.
N. Guglielmi, V. Yu. Protasov, *Exact computation of joint spectral characteristics of linear
operators*, Found. Comput. Math. 13 (2013) 37-97.
T. Mejstrik, *Algorithm 1011: Improved invariant polytope algorithm and applications*, ACM Trans.
Math. Softw. 46(3) (2020) 29.
R. Jungers, *The joint spectral radius: theory and applications*, LNCIS 385, Springer 2009.
"""

from __future__ import annotations

import itertools
import time
from fractions import Fraction
from typing import Any, Sequence

import numpy as np
from flint import fmpq_mat

from ..result import CERTIFIED, INCONCLUSIVE, NUMERICAL, AnalysisError, Result
from ._bounds import _Bounds, _lower_from_word, _rho_word
from ._norms import _solve_norms, arithmetic_of, rigorous_norm_upper
from ._exact import Family, exact_rho_expression, parse_family, rho_enclosure, round_down, round_up
from ._hp import certify_polytope_hp
from ._polytope import build_polytope, certify_polytope, leading_is_real, rotation_order
from ._balance import balanced_roots, interior_fillers
from ._complex import build_complex_polytope, certify_complex_polytope
from ._precondition import ellipsoid_transform, rounding_transform, transform_family
from ._subspace import invariant_subspace, split_family, strong_components
from ._symmetry import reduction_that_splits, solve_reduced
from ._search import brute_force_bounds, canonical_word, smp_search
from ._tree import tree_bounds
from ._work import Work

__all__ = ["jsr_bounds", "brute_force_bounds", "parse_family", "canonical_word", "Work", "DEFAULT_BUDGET"]

METHODS = ("auto", "polytope", "norms")
#: products within this relative distance of the best one also start the polytope (balanced)
NEAR_ROOTS = 1e-5
#: exact invariant subspaces are searched for rational families up to this size
SUBSPACE_MAX_N = 40
#: a float polytope whose vertex matrix is worse conditioned than this is rebuilt for a
#: similar family that rounds it (see :mod:`analysis.jsr._precondition`)
THIN_COND = 1e10
#: default work budget of :func:`jsr_bounds` (units: see its docstring)
DEFAULT_BUDGET = 10_000
#: the fallback bounds always get at least this many units
MIN_UNITS = 50
#: share of what is left that the product tree gets when the invariant polytope did not close
TREE_SHARE = 0.6


# --------------------------------------------------------------------------------------------
# the solvers
# --------------------------------------------------------------------------------------------

def _single(F: Family, i: int) -> _Bounds:
    lo, hi = rho_enclosure(F, (i,))
    return _Bounds(lo, hi, (i,), (lo, hi), "spectral radius (single matrix)", arithmetic_of(F),
                   {"closed": True, "polytope_vertices": 0})


def _blocks(F: Family) -> list[list[int]]:
    """Strongly connected components of the union sparsity graph (exact zero tests)."""
    n = F.n
    succ = [[b for b in reversed(range(n))
             if a != b and any(not F.is_zero_entry(i, a, b) for i in range(F.k))] for a in range(n)]
    return strong_components(succ)


def _commuting(F: Family) -> bool:
    if F.n == 1:                       # 1 x 1 matrices commute, whatever the entries
        return True
    if F.exact_q is None:
        return False
    for i, j in itertools.combinations(range(F.k), 2):
        if F.exact_q[i] * F.exact_q[j] != F.exact_q[j] * F.exact_q[i]:
            return False
    return True


def _solve(F: Family, *, method: str, max_length: int, work: Work, rel_gap: float,
           max_vertices: int) -> _Bounds:
    k = F.k
    if k == 1:
        return _single(F, 0)
    if method == "auto":
        blocks = _blocks(F) if F.n > 1 else [[0]]
        if len(blocks) > 1:
            return _solve_blocks(F, blocks, method=method, max_length=max_length,
                                 work=work, rel_gap=rel_gap, max_vertices=max_vertices)
        if F.exact_q is not None and 2 <= F.n <= SUBSPACE_MAX_N:
            W = invariant_subspace(F.exact_q)
            if W is not None:
                return _solve_subspace(F, W, method=method, max_length=max_length,
                                       work=work, rel_gap=rel_gap,
                                       max_vertices=max_vertices)
            red = reduction_that_splits(F, _blocks, _rational_family)
            if red is not None:
                return solve_reduced(F, *red, _solve, method=method, max_length=max_length,
                                     work=work, rel_gap=rel_gap, max_vertices=max_vertices)
        if _commuting(F):
            parts = [_single(F, i) for i in range(k)]
            best = max(parts, key=lambda b: b.lower)
            up = max(b.upper for b in parts)
            return _Bounds(best.lower, up, best.word, best.rho_product,
                           "commuting family: JSR = max_i rho(A_i)", arithmetic_of(F),
                           {"closed": True, "polytope_vertices": 0})
    if method == "norms":
        return _solve_norms(F, max_length=max_length, work=work)
    return _solve_polytope(F, max_length=max_length, work=work, rel_gap=rel_gap,
                           max_vertices=max_vertices)


def _combine(F: Family, parts: list[tuple[Any, _Bounds]], method: str, key: str,
             describe) -> _Bounds:
    """JSR = max over the diagonal blocks of a block-triangular family: bounds of the parts
    combined, the best part's witness, ``witness[key]`` listing every part (``describe``)."""
    best = max((bb for _, bb in parts), key=lambda b: b.lower)
    uppers = [bb.upper for _, bb in parts]
    up = None if any(u is None for u in uppers) else max(uppers)
    wit = dict(best.witness)
    wit[key] = describe(parts)
    notes = [f"block {b}: {nt}" for b, bb in parts for nt in bb.notes]
    # rho of the witness product for the whole family: max over the blocks (block triangular)
    rp = _lower_from_word(F, best.word)[1]
    return _Bounds(best.lower, up, best.word, rp, method, arithmetic_of(F), wit, notes)


def _solve_parts(subs: list[tuple[Any, Family]], kw: dict) -> list[tuple[Any, _Bounds]]:
    """Solve the diagonal blocks, sharing the work budget in proportion to their squared sizes."""
    shares = kw["work"].split([sub.n ** 2 for _, sub in subs])
    return [(label, _solve(sub, **dict(kw, work=share))) for (label, sub), share in zip(subs, shares)]


def _solve_blocks(F: Family, blocks: list[list[int]], **kw: Any) -> _Bounds:
    parts = _solve_parts([(b, F.subfamily(b)) for b in blocks], kw)
    return _combine(F, parts,
                    "block-triangular reduction (common invariant coordinate subspaces); "
                    f"diagonal blocks of sizes {[len(b) for b in blocks]}, JSR = max over blocks",
                    "blocks", lambda ps: [{"indices": b, "lower": bb.lower, "upper": bb.upper,
                                           "method": bb.method} for b, bb in ps])


def _rational_family(mats: list[fmpq_mat]) -> Family:
    fl = [np.array([[float(M[a, b]) for b in range(M.ncols())] for a in range(M.nrows())])
          for M in mats]
    return Family(fl, "rational", list(mats), None)


def _solve_subspace(F: Family, W: fmpq_mat, **kw: Any) -> _Bounds:
    """JSR = max(JSR(A|W), JSR(A on R^n/W)) for an exact common invariant subspace ``W``."""
    top, bottom = split_family(F.exact_q, W)
    sizes = [top[0].nrows(), bottom[0].nrows()]
    parts = _solve_parts([("W", _rational_family(top)), ("R^n/W", _rational_family(bottom))], kw)
    import sympy as sp

    basis = [[sp.Rational(int(W[a, c].p), int(W[a, c].q)) for c in range(W.ncols())]
             for a in range(W.nrows())]
    return _combine(F, parts,
                    "exact common invariant subspace (block-triangular in the basis [W | E]); "
                    f"diagonal blocks of sizes {sizes}, JSR = max over blocks",
                    "invariant_subspace",
                    lambda ps: {"dimension": sizes[0], "basis": basis,
                                "blocks": [{"block": b, "size": sz, "lower": bb.lower,
                                            "upper": bb.upper, "method": bb.method}
                                           for (b, bb), sz in zip(ps, sizes)]})


def _certify_closed(F: Family, r: Fraction, st, cands, lower: Fraction, rel_gap: float):
    """Certificate of a closed float polytope: the standard one, and the high-precision one when
    the standard one misses the target (or fails)."""
    cert = certify_polytope(F, r, st)
    if cert is None or not (lower > 0 and cert.upper <= lower * (1 + Fraction(rel_gap) / 4)):
        # the float roots are not exact eigenvectors: rebuild the same polytope at high
        # precision and re-solve every membership in a local basis
        try:
            hp = certify_polytope_hp(F, r, st, [w for _, w in cands], float(r))
        except (ArithmeticError, ValueError, ZeroDivisionError):  # pragma: no cover
            hp = None
        if hp is not None and (cert is None or hp.upper < cert.upper):
            cert = hp
    return cert


def _cert_info(r: Fraction, st, cert) -> dict[str, Any]:
    return {"scale_r": r, "certified_norm_bound": cert.bound,
            "basis_inverse_norm": cert.basis_inverse_norm,
            "certificate_arithmetic": cert.arithmetic,
            "polytope_vertex_roots": sorted(set(st.root_of)),
            "vertices": [v.tolist() for v in st.V] if len(st.V) <= 300 else None}


def _start_vertices(mats: Sequence[np.ndarray], r: float, cands, theta: float = 0.5):
    """Balanced roots of the candidate words plus interior fillers (:mod:`._balance`)."""
    words = [w for _, w in cands]
    roots, info = balanced_roots(mats, r, words)
    return roots + interior_fillers(mats, r, words, info, theta=theta), info


def _at_least(work: Work, units: int) -> Work:
    """``work`` itself, or a fresh budget of ``units`` when less than that is left (the fallback
    bounds always get a minimum)."""
    return work if work.left >= units else Work(units)


def _solve_polytope(F: Family, *, max_length: int, work: Work, rel_gap: float,
                    max_vertices: int) -> _Bounds:
    # the phases share the budget as fractions of what is left (the search a quarter, the
    # polytope half of the rest, ...), counted in work units (see jsr_bounds)
    total = max(work.left, MIN_UNITS)
    notes: list[str] = []
    sr = smp_search(F.floats, max_length, work=work.share(0.25), near=NEAR_ROOTS)
    # roots: the exact ties, and the near ties no longer than the best word (a near tie such as
    # (0,0,1,1) next to the s.m.p. (0,0,1,1,1,1) of Daubechies D44 must be a balanced root, or
    # the polytope crawls towards its eigenvector; long concatenations add nothing)
    cands = [c for c in sr.candidates
             if c[0] >= sr.best_rho * (1 - 1e-9) or len(c[1]) <= len(sr.best_word)]
    word = sr.best_word
    witness: dict[str, Any] = {"search": {"levels": sr.levels_done,
                                          "products_evaluated": sr.products_evaluated,
                                          "exhaustive_to_length": sr.exhaustive_to,
                                          "work": sr.work},
                               "candidates": [c[1] for c in cands]}
    lower, rp = _lower_from_word(F, word)

    if sr.best_rho <= 0 or lower == 0:
        return _solve_zero(F, word, lower, rp, witness, max_length, work)

    # a badly scaled family (fast-decaying spectrum, e.g. Daubechies D20+) gives a thin polytope
    # decided on rounding noise: work from the start in the exactly similar family in which the
    # sum-of-squares ellipsoid is a ball (certificates hold for the input family unchanged)
    precond: list[dict[str, Any]] = []
    Fw = F
    S0, condR = ellipsoid_transform(F.floats)
    if S0 is not None:
        G = transform_family(F, S0)
        if G is not None:
            Fw = G
            precond.append({"kind": "sum-of-squares ellipsoid", "cond_R": condR})
    mats = Fw.floats

    upper: Fraction | None = None
    cert_info: dict[str, Any] = {}
    st = None
    restarts = 0
    balance: dict[str, Any] = {}
    while True:
        # a complex leading eigenvalue rotates the root: the real polytope closes exactly only
        # for a rational rotation (a finite orbit of Re u); for an irrational one the exact
        # attempt gets less time
        real_lead = all(leading_is_real(mats, w) for _, w in cands)
        finite_orbit = real_lead or all(rotation_order(mats, w) is not None for _, w in cands)
        poly_work = work.share(0.5 if finite_orbit else 0.15)
        # values recomputed from the words alone, so that the scale (hence the certificate)
        # does not depend on how a candidate was found
        cands = [(_rho_word(mats, w), w) for _, w in cands]
        rho_f = max(c[0] for c in cands)
        r = Fraction(rho_f)
        # smaller fillers for a rotating leading plane (sqrt 3 scheme: 178 vertices, 886 at 1/2)
        theta = 0.5 if real_lead or not finite_orbit else 0.125
        roots, balance = _start_vertices(mats, rho_f, cands, theta=theta)
        # after the ellipsoid rounding an early polytope (few directions filled) is thin
        # legitimately: no early stop then
        st = build_polytope(mats, rho_f, roots, work=poly_work,
                            max_vertices=max_vertices,
                            thin_stop=THIN_COND if Fw is F else None)
        if st.better_word is not None and restarts < 6:
            restarts += 1
            bw = canonical_word(st.better_word)
            notes.append(f"polytope found a better product {bw} (rho^(1/L) ~ {st.better_rho:.15g}); "
                         "restarted")
            nl, nrp = _lower_from_word(F, bw)
            if nl > lower:
                lower, rp, word = nl, nrp, bw
            cands = [(st.better_rho, bw)]
            continue
        break
    witness.update({"polytope_vertices": len(st.V), "closed": st.closed,
                    "lp_calls": st.lp_calls, "restarts": restarts,
                    "leading_eigenvalue_real": real_lead,
                    "stop_reason": st.stop_reason})
    if balance.get("groups", 0) > 1:
        witness["balancing"] = balance
    method = "invariant polytope (Guglielmi-Protasov), certified"
    if Fw is not F:
        method = ("invariant polytope (Guglielmi-Protasov) of an exactly similar family "
                  "S^-1 A_i S (S dyadic, from the sum-of-squares ellipsoid), certified")
    if st.closed:
        cert = _certify_closed(Fw, r, st, cands, lower, rel_gap)
        if cert is not None:
            upper = cert.upper
            cert_info = _cert_info(r, st, cert)
            if Fw is not F:
                cert_info["polytope_coordinates"] = ("preconditioned: vertices are in the "
                                                     "coordinates of S^-1 A_i S")
        else:
            notes.append("the closed float polytope could not be certified (singular basis)")

    def gap_ok(u: Fraction | None) -> bool:
        return u is not None and lower > 0 and u <= lower * (1 + Fraction(rel_gap))

    # a thin polytope (ill-conditioned vertex matrix): float memberships are decided on rounding
    # noise in the thin directions; rebuild it for an exactly similar, rounder family
    Fc, stc = Fw, st
    for _round in range(3):
        if gap_ok(upper) or work.left <= 0.15 * total:
            break
        Vc = stc.matrix()
        sv = np.linalg.svd(Vc, compute_uv=False) if Vc.shape[1] else np.zeros(1)
        sv = sv[sv > 0]
        if not (len(sv) and sv[0] > 1e6 * sv[-1]):
            break
        S = rounding_transform(Vc)
        G = transform_family(Fc, S) if S is not None else None
        if G is None:
            break
        roots, _ = _start_vertices(G.floats, float(r), cands, theta=0.125)
        st3 = build_polytope(G.floats, float(r), roots, work=work.sub(0.6 * max(work.left - 0.1 * total, 0)),
                             max_vertices=max_vertices, check_better=False,
                             thin_stop=THIN_COND if _round < 2 else None)
        info = {"cond_before": float(sv[0] / sv[-1]), "vertices": len(st3.V),
                "closed": st3.closed, "stop": st3.stop_reason, "lp_calls": st3.lp_calls}
        precond.append(info)
        Fc, stc = G, st3
        if st3.closed:
            c3 = _certify_closed(G, r, st3, cands, lower, rel_gap)
            if c3 is not None and (upper is None or c3.upper < upper):
                upper = c3.upper
                info["certified_norm_bound"] = c3.bound
                cert_info = _cert_info(r, st3, c3)
                cert_info["polytope_coordinates"] = ("preconditioned: vertices are in the "
                                                     "coordinates of S^-1 A_i S")
                witness.update({"polytope_vertices": len(st3.V), "closed": True,
                                "stop_reason": "closed (after preconditioning)"})
                method = ("invariant polytope (Guglielmi-Protasov) of an exactly similar family "
                          "S^-1 A_i S (S dyadic, rounding the thin polytope), certified")
            break
    if precond:
        witness["preconditioning"] = precond

    # a complex leading eigenvalue: the complex (elliptic) polytope can close exactly
    if not gap_ok(upper) and not real_lead and work.left > 0.1 * total:
        # (no interior fillers here: in the complex hull they slowed closure in the tests)
        croots, _ = balanced_roots(Fw.floats, float(r), [w for _, w in cands], complex_roots=True)
        stx = build_complex_polytope(Fw.floats, float(r), croots,
                                     work=work.sub(0.6 * max(work.left - 0.1 * total, 0)),
                                     max_vertices=min(max_vertices, 800), check_better=False)
        cinfo: dict[str, Any] = {"vertices": len(stx.V), "closed": stx.closed,
                                 "stop": stx.stop_reason, "socp_calls": stx.lp_calls}
        if stx.closed:
            cc = certify_complex_polytope(Fw, r, stx)
            if cc is not None:
                cinfo["certified_norm_bound"] = cc.bound
                if upper is None or cc.upper < upper:
                    upper = cc.upper
                    method = ("complex invariant polytope (Guglielmi-Wirth-Zennaro; "
                              "Guglielmi-Protasov), certified in Arb complex balls")
                    cert_info = {"scale_r": r, "certified_norm_bound": cc.bound,
                                 "certificate_arithmetic": cc.arithmetic,
                                 "polytope_kind": "complex balanced hull",
                                 "vertices": ([[[float(x.real), float(x.imag)] for x in v]
                                               for v in stx.V] if len(stx.V) <= 300 else None)}
                    if Fw is not F:
                        cert_info["polytope_coordinates"] = ("preconditioned: vertices are in "
                                                             "the coordinates of S^-1 A_i S")
                    witness.update({"polytope_vertices": len(stx.V), "closed": True,
                                    "stop_reason": "closed (complex polytope)"})
        witness["complex_polytope"] = cinfo

    # the product tree (Gripenberg's branch and bound in a balanced norm, certified in Arb):
    # bounds from products that are never worse than the textbook ones, and longer products
    # with a larger spectral radius (a better lower bound)
    if not gap_ok(upper):
        tr = tree_bounds(F, _at_least(work.share(TREE_SHARE), MIN_UNITS),
                         lower_hint=float(lower), rel_gap=rel_gap)
        nl, nrp = _lower_from_word(F, tr.word)
        if nl > lower:
            notes.append(f"the product tree found a better product {tr.word} "
                         f"(rho^(1/L) ~ {tr.float_lower:.15g})")
            lower, rp, word = nl, nrp, tr.word
        witness["product_tree"] = {"nodes": tr.nodes, "depth": tr.depth, "leaves": tr.leaves,
                                   "certified_products": tr.certified_products,
                                   "certified_bound": _q(round_up(tr.upper), F.kind),
                                   "stop": tr.stop_reason}
        if upper is None or tr.upper < upper:
            upper = tr.upper
            method = ("product tree (Gripenberg branch and bound) in the balanced ellipsoidal "
                      "norm, certified in Arb (the invariant polytope did not close)")

    # relaxed polytopes: A_i / (r (1 + eps)) contract, so the tree closes for eps > 0
    relaxed: dict[str, Any] = {}
    if not gap_ok(upper):
        rho_f = float(r)
        for eps in sorted({e for e in (1e-2, 1e-4, rel_gap / 4) if e >= rel_gap / 4},
                          reverse=True):
            if work.left <= 0.02 * total:
                break
            if upper is not None and r * (1 + Fraction(eps)) >= upper:
                continue                       # cannot improve on the bound already certified
            re = r * (1 + Fraction(eps))
            roots, _ = _start_vertices(Fc.floats, rho_f, cands)
            st2 = build_polytope(Fc.floats, float(re), roots,
                                 work=work.sub(max(work.left - 0.1 * total, 0) / 2),
                                 max_vertices=max_vertices, check_better=False)
            if not st2.closed:
                relaxed = {"eps_failed": eps, "vertices": len(st2.V), "stop": st2.stop_reason}
                break
            c2 = certify_polytope(Fc, re, st2)
            if c2 is None:
                break
            if upper is None or c2.upper < upper:
                upper = c2.upper
                relaxed = {"eps": eps, "vertices": len(st2.V), "certified_norm_bound": c2.bound}
                method = (f"relaxed invariant polytope for A_i / (rho (1 + {eps:g})), certified "
                          "(the exact polytope did not close)")
            if gap_ok(upper):
                break
        if relaxed:
            witness["relaxed_polytope"] = relaxed
    if upper is None:
        nu, nl_ = rigorous_norm_upper(F, max_length, _at_least(work, MIN_UNITS))
        if upper is None or nu < upper:
            upper = nu
            method = "norms of products in a balanced basis (polytope inconclusive)"
            witness["norm_length"] = nl_
    witness.update(cert_info)
    return _Bounds(lower, upper, word, rp, method, arithmetic_of(F), witness, notes)


def _solve_zero(F: Family, word, lower, rp, witness, max_length, work: Work) -> _Bounds:
    """Best product has spectral radius 0: the family may be jointly nilpotent."""
    n, k = F.n, F.k
    if k ** n <= 1 << 14:
        zero = True
        for w in itertools.product(range(k), repeat=n):
            if F.exact_q is not None:
                P = F.product_q(w)
                if any(P[a, b] != 0 for a in range(n) for b in range(n)):
                    zero = False
                    break
            else:
                zero = False
                break
        if zero:
            witness.update({"closed": True, "polytope_vertices": 0})
            return _Bounds(Fraction(0), Fraction(0), word, rp,
                           f"jointly nilpotent: every product of length n = {n} vanishes (exact)",
                           arithmetic_of(F), witness)
    up, l = rigorous_norm_upper(F, max_length, work)
    witness.update({"closed": False, "polytope_vertices": 0, "norm_length": l})
    return _Bounds(lower, up, word, rp, "norms of products (no product with rho > 0 found)",
                   arithmetic_of(F), witness)


# --------------------------------------------------------------------------------------------
# public API
# --------------------------------------------------------------------------------------------

def _q(x: Fraction | None, kind: str = "rational"):
    """``x`` as an exact number of the result: a sympy Rational, or for ball input an ``int`` or
    ``Fraction`` (the ball route runs without sympy). The JSON and the printed digits are the same."""
    if x is None:
        return None
    if kind == "ball":
        return x.numerator if x.denominator == 1 else x
    import sympy as sp

    return sp.Rational(x.numerator, x.denominator)


def jsr_bounds(matrices: Any, *, max_length: int = 12, budget: int = DEFAULT_BUDGET,
               method: str = "auto", rel_gap: float = 1e-6, floats_exact: bool = False,
               max_vertices: int = 1500, on_work=None) -> Result:
    """Rigorous bounds ``lower <= JSR(A_0, ..., A_{k-1}) <= upper`` (see the module docstring).

    Parameters
    ----------
    matrices
        A sequence of square matrices of one size: sympy matrices, nested lists (ints,
        ``Fraction``, decimal strings such as ``"0.25"``, sympy numbers such as ``sqrt(3)/4``),
        numpy arrays or FLINT ``fmpq_mat``. Exact entries are used exactly. Entries may also be
        ``flint.arb`` balls (nested lists or ``flint.arb_mat``): each ball is an *uncertain*
        real number, and the bounds are then valid for **every** family whose entries lie in
        the balls (lower: the lower end of the ball enclosure of ``rho(P_w)``; upper: the
        polytope or norm certificate evaluated in ball arithmetic over the balls).
    max_length
        Longest product examined by the s.m.p. search and by the norm bounds.
    budget
        Work budget in work units (default ``DEFAULT_BUDGET`` = 10 000). Work is counted, never
        timed, so the same input gives the same result on every machine, idle or loaded; a unit is
        calibrated to about a millisecond of CPU on the reference machine (2 cores). What one unit
        is, phase by phase: in the s.m.p. search, 4000 product entries evaluated (a product of
        ``n x n`` matrices counts ``n^2 + 8``; at least one unit per level); in the invariant
        polytope, two membership tests (0.5 each), a quarter of a small LP, ``500 / (m n)`` of a
        full LP over ``m`` vertices, and a new vertex ``m n^2 / 30000``; in the complex polytope, two
        tests or ``1 / (5 + m n / 20)`` of a cone program; in the rigorous norm bound,
        ``14000 / (n^3 + 8 n^2 + 400)`` Arb products; in the product tree, ``3500`` node entries (a
        node counting ``n^2 + 16``) and ``16000 / (n^3 + 400)`` Arb products of its certificate.
        The search gets a quarter of the budget, the polytope half of what is left (0.15 for a
        complex leading eigenvalue), the rebuilt and complex polytopes shares of the rest; when no
        polytope closed, the product tree ``TREE_SHARE`` (0.6) of what is then left (at least
        ``MIN_UNITS``), the relaxed polytopes the rest. Soft: a phase may overrun its share by one step, and the certificate of a
        closed polytope always completes (it is not counted). ``provenance["work"]`` says how many
        units were spent, ``provenance["timing"]`` the wall-clock seconds (reported only).
    method
        ``"auto"`` (all reductions, search, invariant polytope), ``"polytope"`` (no structural
        shortcuts), ``"norms"`` (the textbook exhaustive method).
    rel_gap
        Target ``upper / lower - 1``: the status is *certified* only when it is reached.
    floats_exact
        Read float entries as the binary rationals they are and certify for those (status
        *certified* is then possible for float input; provenance says so).
    max_vertices
        Vertex budget of the invariant polytope.
    on_work
        Called with the units of every charge to the budget (``subdiv jsr`` shows them as progress on a
        terminal); it observes, it decides nothing.

    Returns
    -------
    Result
        ``lower``/``upper`` sympy Rationals (dyadic, rounded outward; for ball input ``int`` or
        ``Fraction``, the same numbers without sympy); ``value`` only when they coincide. ``status``: *certified* (rigorous and ``upper/lower - 1 <= rel_gap``),
        *numerical* (float input, tight), *inconclusive* (otherwise: the bounds are still
        rigorous for exact input; ``provenance["message"]`` says what would settle it).
        ``witness``: ``product`` (word ``w``, meaning ``A_{w_1} A_{w_2} ... A_{w_L}``),
        ``length``, ``rho_product`` (enclosure of ``rho(P_w)``), ``polytope_vertices``,
        ``closed``, ``certified_norm_bound``, ``scale_r``, ``vertices`` (the dyadic vertex
        coordinates of the certified polytope when at most 300), and search statistics.

    Examples
    --------
    >>> r = jsr_bounds([[[2, 0], [0, 1]], [[1, 0], [0, 3]]])    # commuting: max rho = 3
    >>> r.value, r.status
    (3, 'certified')
    >>> r = jsr_bounds([[[1, 1], [0, 1]], [[1, 0], [1, 1]]], method="norms", max_length=6)
    >>> r.status, float(r.lower) > 1.618, float(r.upper) > 1.62
    ('inconclusive', True, True)

    Uncertain entries as Arb balls (here ``1 +/- 2^-100``): the interval covers the JSR of every
    family inside the balls, and it is still tight:

    >>> from flint import arb
    >>> one = arb(1, arb(2) ** -100)
    >>> r = jsr_bounds([[[one, 1], [0, 1]], [[1, 0], [1, one]]], budget=5000)
    >>> import sympy as sp
    >>> phi = (1 + sp.sqrt(5)) / 2
    >>> r.status, r.provenance["input_kind"], bool(r.lower <= phi <= r.upper)
    ('certified', 'ball', True)
    """
    if method not in METHODS:
        raise AnalysisError(f"unknown method {method!r}; expected one of {METHODS}")
    if not (isinstance(max_length, int) and max_length >= 1):
        raise AnalysisError("max_length must be a positive integer")
    if isinstance(budget, bool) or not isinstance(budget, (int, float)) or not 0 < budget < float("inf"):
        raise AnalysisError(f"budget must be a positive number of work units, not {budget!r}")
    t0 = time.perf_counter()            # reported under provenance["timing"], decides nothing
    work = Work(max(int(budget), 1), listener=on_work)
    F = parse_family(matrices)
    # exact duplicates
    members: list[int] = []
    for i in range(F.k):
        if not any(F.equal(i, j) for j in members):
            members.append(i)
    G = F.subfamily(range(F.n), members) if len(members) < F.k else F
    b = _solve(G, method=method, max_length=max_length, work=work, rel_gap=rel_gap,
               max_vertices=max_vertices)
    word = tuple(members[i] for i in b.word)

    lower = round_down(b.lower)
    upper = round_up(b.upper) if b.upper is not None else None
    if upper is not None and upper < lower:   # cannot happen for rigorous bounds
        raise ArithmeticError(f"JSR bounds crossed: {lower} > {upper}")
    rigorous = F.kind != "float" or floats_exact
    if upper is None:
        tight = False
    elif lower == upper:
        tight = True
    else:
        tight = lower > 0 and upper <= lower * (1 + Fraction(rel_gap))
    if tight:
        status = CERTIFIED if rigorous else NUMERICAL
    else:
        status = INCONCLUSIVE
    witness: dict[str, Any] = {
        "product": word, "length": len(word),
        "rho_product": {"lower": _q(round_down(b.rho_product[0]), F.kind),
                        "upper": _q(round_up(b.rho_product[1]), F.kind)},
        "polytope_vertices": b.witness.get("polytope_vertices", 0),
        "closed": bool(b.witness.get("closed", False)),
    }
    for key, val in b.witness.items():
        if key in witness:
            continue
        if isinstance(val, Fraction):
            val = _q(val, F.kind)
        if key == "blocks":
            val = [{**d, "lower": _q(d["lower"], F.kind), "upper": _q(d["upper"], F.kind)} for d in val]
        if key == "candidates":
            val = [tuple(members[i] for i in w) for w in val]
        witness[key] = val
    if status == CERTIFIED and F.exact_q is not None and F.kind == "rational":
        expr = exact_rho_expression(F, word)
        if expr is not None:
            witness["rho_product_root_exact"] = expr
    gap = None if (upper is None or lower == 0) else float(upper / lower - 1)
    arithmetic = b.arithmetic
    if F.kind == "float":
        arithmetic += ("; float inputs read as exact binary rationals" if floats_exact else
                       "; float inputs read as exact binary rationals, but they approximate the"
                       " intended matrices, so the status is at most numerical")
    prov: dict[str, Any] = {
        "method": b.method, "arithmetic": arithmetic, "input_kind": F.kind,
        "max_length": max_length, "budget": int(budget), "work": work.spent,
        "rel_gap_target": rel_gap, "relative_gap": gap, "duplicates_removed": F.k - len(members),
        "timing": {"seconds": round(time.perf_counter() - t0, 4)},
    }
    if F.kind == "ball":
        prov["input_max_radius"] = _q(round_up(F.max_radius()), F.kind)
        prov["valid_for"] = "every family of real matrices whose entries lie in the input balls"
    if b.notes:
        prov["notes"] = b.notes
    if status == INCONCLUSIVE:
        prov["message"] = (
            f"upper/lower - 1 = {gap:.3g} > {rel_gap:g}: the invariant polytope did not close "
            f"({b.witness.get('stop_reason', 'not attempted')}) for the candidate s.m.p. "
            f"{word}; the bounds are certified ({b.method}). What may settle it: a larger budget "
            "(it tightens the product tree's bound and may close the polytope), a longer "
            "max_length or a larger max_vertices (a better s.m.p. candidate). Families with many near-tied "
            "products (the polytope grows towards each of them) or a reducible family without "
            "an exact invariant subspace (ball or algebraic entries) can need an analysis of "
            "their s.m.p.s by hand." if gap is not None else
            "no rigorous upper bound within the budget")
    value = _q(lower, F.kind) if (upper is not None and lower == upper) else None
    return Result(value=value, status=status, lower=_q(lower, F.kind), upper=_q(upper, F.kind),
                  witness=witness, provenance=prov)
