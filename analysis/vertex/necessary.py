"""Certified failure of C^1 at an extraordinary vertex for generic initial data: one theorem whose hypotheses
are all checked here (exactly, or with Arb balls), for the interpolating butterfly family.

"C^1 at the vertex" is Reif's notion, the one :func:`.valence.c1_verdict` certifies: a neighbourhood U of the
vertex in the parameter domain on which the limit surface ``x`` is injective and ``x(U)`` is an embedded C^1
surface. "Generic" means: every initial net ``Q_0`` (the control points of a closed set of rings, in R^3)
outside the zero set of a linear or polynomial function of ``Q_0`` that is not identically zero — a closed set
of measure zero.

Theorem (a leading eigenfunction that does not wind once). Let ``S`` be the local subdivision matrix on a set
of rings closed under the rules, ``Q_m = S^m Q_0``, and suppose

1. the rules are interpolating (:func:`interpolating`, exact): every control point lies on the limit surface,
   ``x(2^-m p) = Q_m[p]``, and ``x(0) = c`` is the centre;
2. 1 is a simple eigenvalue; ``lambda`` is real, ``0 < |lambda| < 1``; every other eigenvalue is either equal to
   ``lambda`` or smaller in modulus;
3. the longest Jordan chains of ``lambda`` (length s) lie in one Fourier block pair ``k, n - k`` only, with
   ``k = 0`` or ``2 <= k < n/2``, and ``lambda`` has one eigenvector in block k (so one chain of length s);
4. the eigenfunction ``Psi`` of that eigenvector (the limit of the net ``w^(k j) v`` on sector j,
   ``w = exp(2 pi i/n)``, so ``Psi(R x) = w^k Psi(x)``; real for k = 0) is nonzero on a closed loop ``gamma``
   around the vertex and winds exactly k times around 0 along it (k = 0: one sign on ``gamma``);
5. on the cells of ``gamma`` the limit is the regular scheme's limit of the cells' local nets, and the regular
   scheme is C^1 (so the limit there is a bounded linear function of the net).

Then for generic ``Q_0`` the limit surface is not C^1 at the centre.

*Proof.* By the Jordan form, ``Q_m - 1 c^T = C_m L(V) + O(m^(s-2) |lambda|^m)``, ``C_m = binom(m, s-1)
lambda^(m-s+1)``, ``V`` the eigenvector (block k and its conjugate in block n - k), ``L`` real linear with
coefficients that are linear functions of ``Q_0``: ``b = l Q_0`` with ``l`` the left vector dual to the chain (a
nonzero row vector of block k), ``L(t) = t b`` (k = 0, ``l`` and ``b`` real) or ``L(z) = 2 Re(z b)`` (``b`` in
C^3); the remainder is ``o(|C_m|)``. ``L`` is injective for generic data: for k = 0 when ``b != 0``, outside the
kernel of ``Q_0 -> l Q_0``, a proper subspace; for k >= 2 when ``Re b = (Re l) Q_0`` and ``Im b = (Im l) Q_0`` are
R-independent. ``Re l`` and ``Im l`` are R-independent: ``l`` and its conjugate lie in different Fourier blocks
(``k != n - k``), so they are C-independent, and they span the same C-space as ``Re l, Im l``. Hence the 2 x 3
matrix ``[Re b; Im b]`` has rank 2 for some ``Q_0``, and the exceptional set is the zero set of the sum of the
squares of its 2 x 2 minors, a polynomial in ``Q_0`` that is not identically zero. (Block n/2 is self-conjugate:
there ``l`` may be real and ``L`` has rank 1, which is why k = n/2 is excluded.) Let E be the image of ``L``.
(a) Take the lattice point ``p = (HI, 0)`` of the chart, on ``gamma``, where ``Psi(p) != 0`` is proven
(hypothesis 4; by 1, ``Psi(p)`` is the eigenvector's entry at p). The secants ``(x(2^-m p) - c)/|x(2^-m p) - c|``
tend to ``+-L(Psi(p))/|L(Psi(p))|`` (``L(Psi(p)) != 0``: L is injective); for k >= 2 those at ``p`` and ``R p``
span E (``Psi(R p) = w^k Psi(p)``, and ``w^k`` is not real). An embedded C^1 surface through c is locally a graph
over its tangent plane T, and limits of secants lie in T, so E lies in T. (b) If x is injective on U and x(U) an
embedded C^1 surface, the orthogonal projection P onto T is injective on x(U') for some smaller U', so ``P o x`` is
injective on the closed disc ``D_m`` bounded by ``gamma_m = 2^-m gamma`` (m large), and an injective continuous map
of a closed disc into the plane sends its boundary to a Jordan curve that winds +-1 times around the image of every
interior point (Jordan curve theorem, invariance of domain): ``P(x o gamma_m) - P c`` winds +-1 times around 0.
(c) By 5, ``P(x o gamma_m) - P c = C_m L(Psi o gamma) + o(|C_m|)`` uniformly on ``gamma``, with
``min |Psi o gamma| > 0`` and P the identity on E: for m large it winds as ``L(Psi o gamma)``, that is ``+-k``
times (k >= 2), or 0 times (k = 0: the curve stays in the half-plane ``{y : y . b > 0}`` or its opposite). Neither
is +-1: a contradiction. []

[Zorin 2000 derives necessary conditions of this kind; Peters–Reif 2008, ch. 5, relate the characteristic
map's injectivity to single-sheetedness. The argument above is self-contained, so the verdict rests only on
the checks below.]

What is checked, on the 3-ring (spectrum, Jordan structure) and the ``RING``-ring (eigenfunction):
:func:`interpolating` (on both, exact), :func:`analysis.vertex.spectrum.analyse` (1 simple; every eigenvalue proven equal to lambda exactly — sign and
value — or certified smaller in modulus), :func:`analysis.vertex.exact_blocks.jordan_ranks` (ranks of the powers of
``B_k - lambda I``, exact over ``Q(exp(2 pi i/n))``, where lambda is exact), :func:`.zorin.outer_rings_nilpotent`
(rings 4..``RING`` add only the eigenvalue 0, so lambda's Jordan structure is the 3-ring's), the block-k
eigenvector in Arb (:func:`analysis.vertex.charmap.eigenvector`: geometrically simple), the regular butterfly's
certified derivative error bound and nested neighbourhoods (:mod:`.zorin`, :mod:`.derived`: hypothesis 5,
``gamma`` = ring ``HI`` of the chart, whose cells' neighbourhoods stay at ``x + y >= 1``), and the winding
(:func:`.zorin.winding_of_arc`: the sector-0 arc misses a ray from 0, proven with Arb tubes).

For the butterfly: at n = 3, lambda = 1/4 has a Jordan chain of length 3 in block 0 (chains of length 2 in
blocks 1, 2): the surface is drawn out to one side along one direction (winding 0); at n = 8..50 (each
valence certified; also at the samples n = 75, 100, 150, 200) the dominant eigenvalue is simple in a block k >= 2 (k
grows like n/5): the surface covers its tangent plane k times.

Examples
--------
>>> from analysis.vertex.rules import butterfly_rules
>>> r = not_c1(butterfly_rules(2), 3)
>>> r.status, r.witness["block"], r.witness["jordan_chain"], r.witness["winding_number"]
('refuted', 0, 3, 0)

References
----------
D. Zorin, Smoothness of stationary subdivision on irregular meshes, Constr. Approx. 16 (2000) (necessary
conditions); U. Reif, A unified approach to subdivision algorithms near extraordinary vertices, CAGD 12
(1995); J. Peters, U. Reif, Subdivision Surfaces, Springer 2008, ch. 5; D. Zorin, P. Schröder, W. Sweldens,
Interpolating subdivision for meshes with arbitrary topology, SIGGRAPH 1996 (the butterfly fails at n = 3
and n > 7).
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from typing import Any

from ..result import INCONCLUSIVE, REFUTED, AnalysisError, Result
from .rules import CENTRE, LocalRules

#: the loop gamma: ring ``HI`` of the chart (its cells' neighbourhoods stay at x + y >= 1), on the
#: ``RING``-ring (which holds those neighbourhoods)
HI, RING = 5, 10
#: the contraction factor of the regular part's derivative error bound, and the Hölder budget
R_BOUND, HOLDER_BUDGET = Fraction(9, 20), 20

THEOREM = ("a leading eigenfunction that does not wind once (module analysis.vertex.necessary): interpolating "
           "rules; 1 simple; lambda real, every other eigenvalue equal to it or smaller in modulus; its longest "
           "Jordan chains in one Fourier block pair k, n-k (k = 0 or 2 <= k < n/2) with one eigenvector there; "
           "that eigenfunction nonzero on a loop around the vertex, winding k times; a C^1 regular part")


def interpolating(rules: LocalRules) -> bool:
    """The centre's rule keeps the centre and every old vertex (even lattice coordinates) is kept, exactly.

    >>> from analysis.vertex.rules import butterfly_rules, scheme_rules
    >>> interpolating(butterfly_rules(2)), interpolating(scheme_rules("loop", 2))
    (True, False)
    """
    if not rules.centre or rules.coords is None:
        return False
    if [(t.weight, t.source) for t in rules.rules[0]] != [(1, (CENTRE,))]:
        return False
    index = {p: i for i, p in enumerate(rules.coords)}
    for p, rule in zip(rules.coords, rules.sector_rules()):
        if p[0] % 2 == 0 and p[1] % 2 == 0:
            home = (p[0] // 2, p[1] // 2)
            if [(t.weight, t.source) for t in rule] != [(1, (index.get(home), 0))]:
                return False
    return True


@lru_cache(maxsize=64)
def not_c1(rules: LocalRules, n: int) -> Result:
    """*refuted* (value False: not C^1 for generic initial data, certified by the theorem of the module
    docstring, every hypothesis checked) or *inconclusive* with the first hypothesis that is not established.
    ``rules``: the butterfly family (any ring; the checks use the 3-ring and the ``RING``-ring). Cached per
    rules and valence (a paper file and the command may ask twice)."""
    prov = {"method": "a necessary condition for C^1 with every hypothesis checked (module "
                      "analysis.vertex.necessary)", "valence": n, "rules": rules.source}
    if rules.lattice != "triangle, interpolating" or rules.name not in ("butterfly", "modified-butterfly"):
        return _undecided("the theorem is checked for the butterfly family only (its regular part's derivative "
                          "bounds)", prov)
    from .rules import butterfly_rules, modified_butterfly_rules

    make = {"butterfly": lambda ring: butterfly_rules(ring, rules.tension),
            "modified-butterfly": lambda ring: modified_butterfly_rules(ring, n, rules.tension)}[rules.name]
    inner = make(3)
    if not interpolating(inner):
        return _undecided("the rules are not interpolating", prov)
    lead = _leading_block(inner, n)
    if isinstance(lead, str):
        return _undecided(lead, prov)
    return _winding(make, inner, n, lead, prov)


def _is_one(e) -> bool:
    """The eigenvalue 1 of block 0 (its ball contains 1)."""
    return e.k == 0 and e.real and e.ball.real.contains(1)


def _undecided(why: str, prov: dict) -> Result:
    return Result(value=None, status=INCONCLUSIVE, witness={"verdict": f"not-C^1 theorem: {why}"}, provenance=prov)


def _leading_block(rules: LocalRules, n: int) -> dict | str:
    """Hypotheses 2 and 3 on the 3-ring: ``{"top", "k", "chain", "ties"}`` or why not."""
    import sympy as sp

    from .exact_blocks import jordan_ranks
    from .spectrum import _equal_exact, _exact_root, _lambda_in_c1, _siblings, analyse

    a = analyse(rules, n, curvature=False)
    if not a.checks.get("1 simple"):
        return "1 is not certified a simple eigenvalue"
    rest = [e for e in a.eigenvalues if not _is_one(e)]
    if not rest:
        return "no eigenvalue besides 1"
    top = max(rest, key=lambda e: float(e.modulus.lower()))
    if not (top.modulus < 1 and top.modulus > 0):
        return "the leading eigenvalue is not certified to lie strictly between 0 and 1 in modulus"
    tied = [e for e in rest if not (e.modulus < top.modulus)]
    if not all(e.real for e in tied):
        return "an eigenvalue of the leading modulus is not certified real"
    if len(tied) == 1 and top.mult == 1:
        if top.k == 0 or 2 <= top.k < n / 2:
            return {"top": top, "k": top.k, "chain": 1, "ties": {}}
        if 2 * top.k == n:
            return f"the dominant eigenvalue is simple in block {top.k} = n/2, which is real (self-conjugate): " \
                   "not this theorem's case"
        return f"the dominant eigenvalue is simple in block {top.k} (Reif's case when k = 1, not this theorem's)"
    exact = _exact_root(top.factor, top.ball, n, top.k, _siblings(a.eigenvalues, top))
    lam_c1 = _lambda_in_c1(top, exact) if top.k == 1 or (exact is not None and exact.is_Rational) else None
    if lam_c1 is None:
        return "the leading eigenvalue is multiple or tied, and not known exactly (its Jordan structure is undecided)"
    for e in tied:
        if e is not top and _equal_exact(e, top, exact, n, 1, a.eigenvalues, power=1) is not True:
            return f"an eigenvalue of block {e.k} is neither proven equal to lambda nor smaller in modulus"
    ranks: dict[int, list[int]] = {}
    for k in sorted({e.k for e in tied}):
        mult = sum(e.mult for e in tied if e.k == k)
        r = jordan_ranks(rules, n, k, sp.expand(lam_c1), mult)
        if r is None or r[0] - r[-1] != mult:
            return f"the Jordan structure of lambda in block {k} could not be decided exactly"
        ranks[k] = r
    chain = {k: next(j for j in range(1, len(r)) if r[j] == r[-1]) for k, r in ranks.items()}
    s = max(chain.values())
    longest = [k for k, c in chain.items() if c == s]
    if len(longest) != 1:
        return f"lambda's longest Jordan chains (length {s}) lie in blocks {', '.join(map(str, longest))}"
    k = longest[0]
    if not (k == 0 or 2 <= k < n / 2):
        return f"lambda's longest Jordan chains lie in block {k} (this theorem needs k = 0 or 2 <= k < n/2)"
    if ranks[k][0] - ranks[k][1] != 1:
        return f"lambda has {ranks[k][0] - ranks[k][1]} eigenvectors in block {k} (the theorem needs one)"
    top_k = next(e for e in tied if e.k == k)
    return {"top": top_k, "k": k, "chain": s, "ties": ranks, "exact": exact}


def _winding(make, inner: LocalRules, n: int, lead: dict, prov: dict) -> Result:
    """Hypotheses 4 and 5 on the ``RING``-ring, and the verdict."""
    from flint import ctx

    from .charmap import eigenvector
    from .derived import cell_frame
    from .zorin import eigenfunction_nets, nested_neighbourhoods, outer_rings_nilpotent, regular_bound, \
        winding_of_arc

    top, k = lead["top"], lead["k"]
    big = make(RING)
    if not interpolating(big):
        return _undecided(f"the rules on the {RING}-ring are not interpolating", prov)
    tension = Fraction(int(inner.tension.p), int(inner.tension.q))
    a, bound = regular_bound(tension, R_BOUND, HOLDER_BUDGET)
    if not bound.is_certified:
        return _undecided("the regular part's derivative error bound is not certified", prov)
    K, W, fam, B, omega, idx = cell_frame(a, bound, (1, 1))
    if not outer_rings_nilpotent(big, inner):
        return _undecided(f"rings 4..{RING} are not proven nilpotent", prov)
    if not nested_neighbourhoods(omega, a.dilation.digits):
        return _undecided("the refinements' neighbourhoods are not nested", prov)
    old = ctx.prec
    ctx.prec = 128
    try:
        v = eigenvector(big, n, top.ball.real, k)
        phi, net = eigenfunction_nets(big, n, v[1:] if k == 0 else v, omega, k)
        winds = winding_of_arc(n, HI, net, phi, fam, B, W, K, idx, 8, k, norm=bound.witness["norm"])
    except AnalysisError as e:
        return _undecided(f"the eigenfunction of block {k} could not be enclosed ({e})", prov)
    finally:
        ctx.prec = old
    if not winds:
        return _undecided(f"the winding number of block {k}'s eigenfunction along ring {HI} is not proven", prov)
    lam = _lambda_text(lead, n)
    s = lead["chain"]
    structure = (f"lambda = {lam} simple in Fourier block {k} (double: blocks {k}, {n - k})" if s == 1 else
                 f"lambda = {lam} has a Jordan chain of length {s} in block {k}, the only one that long "
                 "(exact ranks: " + "; ".join(f"block {b}: {r}" for b, r in lead["ties"].items()) + ")")
    others = sorted({b for t in lead["ties"] if t != k for b in (t, (n - t) % n)})
    rest = (f"every eigenvalue != lambda smaller in modulus (Arb); the others (blocks "
            f"{', '.join(map(str, others))}) proven equal to lambda exactly, with shorter Jordan chains" if others
            else "every eigenvalue != lambda smaller in modulus (Arb)")
    shape = (f"its eigenfunction winds {k} times around the vertex: the surface covers its tangent plane {k} times"
             if k else "its eigenfunction has one sign around the vertex: the surface is drawn out to one side "
                       "along one direction, winding 0 times")
    wit: dict[str, Any] = {
        "verdict": (f"not C^1 for generic initial data (certified; {structure}; {rest}; {shape}, proven on ring "
                    f"{HI} in Arb)"),
        "theorem": THEOREM, "block": k, "jordan_chain": s, "lambda": str(top.ball.real), "winding_number": k,
        "loop_ring": HI, "ring": RING, "K": bound.value, "K_float": float(bound.value),
        "hypotheses": [f"interpolating rules on the 3-ring and the {RING}-ring (exact)", "1 simple (certified)",
                       "lambda real, 0 < |lambda| < 1 (certified)", structure, f"on the 3-ring matrix: {rest}",
                       f"rings 4..{RING} nilpotent (exact)",
                       "regular butterfly C^1 with a certified derivative error bound; nested neighbourhoods",
                       f"block {k}'s eigenfunction nonzero on ring {HI}, winding {k} times (Arb tubes)"]}
    return Result(value=False, status=REFUTED, witness=wit, provenance=prov)


def _lambda_text(lead: dict, n: int) -> str:
    """lambda as text: its exact value, or the root of its block's factor ``F(lam, c)``, ``c = cos(2 pi k/n)``,
    in its isolating ball (the cosines set where that leaves rational coefficients), never a rounded midpoint."""
    import sympy as sp

    from .blocks import c, lam
    from .rules import C1

    if lead.get("exact") is not None:
        return sp.sstr(lead["exact"])
    top, k = lead["top"], lead["k"]
    F, ball = top.factor.as_expr(), top.ball.real

    def cos(q: sp.Rational, evaluate: bool = True) -> sp.Expr:
        return sp.cos(2 * sp.pi * q, evaluate=evaluate)

    at = sp.expand(F.subs({c: cos(sp.Rational(k, n)), C1: cos(sp.Rational(1, n))}))
    if at.free_symbols <= {lam} and all(q.is_Rational for q in sp.Poly(at, lam).all_coeffs()):
        return f"root of {sp.sstr(at)} in {ball}"
    shown = F.subs(C1, cos(sp.Rational(1, n), False))
    return f"root of {sp.sstr(shown)} (c = {sp.sstr(cos(sp.Rational(k, n), False))}) in {ball}"
