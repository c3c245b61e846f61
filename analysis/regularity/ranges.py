"""C^k parameter ranges of one-parameter families: where ``S_a(p)`` is C^j, with boundaries
certified on both sides (:func:`ck_parameter_set`; for any arity from exact norm and eigenvalue sets,
:func:`ck_range`), the curve ``alpha(p)`` (:func:`alpha_curve`), and the proof or refutation of a
claimed range (:func:`verify_smoothness_interval`).

:func:`ck_parameter_set` samples a grid, locates every change of the C^j verdict by bisection
with certified verdicts on both sides, and makes a boundary exact where an eigenvalue of a fixed
spectrum-maximizing product crosses ``2^(-k)``; the interior of a run is proven only when the
norm tests below cover it (otherwise it is "certified at the grid points only").

Verifying a claimed smoothness range "S_a(p) is C^j for every p in (p0, p1)" has four routes,
tried in this order, and the result says which one decided:

1. **exact norm inequality** — the Dyn–Levin test ``||(1/2 S_{a_{j+1}})^L||_inf < 1`` solved exactly
   as a set of parameters (:func:`analysis.stationary.normset.norm_solution_set`) for L = 1, 2, ...; if the
   claimed interval lies inside the set for one L, the claim is proven on the whole interval;
2. **interval arithmetic over a subdivision** — the L-step norm evaluated in Arb ball arithmetic on
   sub-intervals (boxes) of the parameter, bisected adaptively; every box with a certified norm
   bound below 1 is proven C^j;
3. **refutation** — certified verdicts at rational points of the interval
   (:func:`analysis.regularity.holder.smoothness`): one point certified *not* C^j refutes the claim;
4. **parametric norms and invariant polytopes** — what routes 1 and 2 leave is given to
   :func:`analysis.regularity.interior.ck_interior` (exact Bernstein bounds of the parametric norms
   on rational pieces, exact end tests, and the strips next to an end of eigenvalue type closed by a
   parametric invariant polytope), which certifies closed sub-intervals up to the true boundary;
   if a strip stays open, rational points in it are tried as counterexamples (route 3 again).

Examples
--------
>>> import sympy as sp, schemes
>>> a = schemes.get("dfh-chaikin-perturbation").symbol
>>> r = verify_smoothness_interval(a, 2, (0, (sp.sqrt(6) - 1) / 80))
>>> r.status, r.witness["route"]
('certified', 'exact norm inequality, L = 2')

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002), Thm 3.3.
F. Johansson, *Arb: efficient arbitrary-precision midpoint-radius interval arithmetic*, IEEE
Trans. Comput. 66 (2017).
"""

from __future__ import annotations

import sympy as sp

import math
from typing import Sequence

from ..algebra.algebraic import RealAlgebraic
from ..algebra.factorization import arity_key, check_arity, factor_out, smoothing_factor
from ..algebra.symbol import LaurentSymbol
from ..result import CERTIFIED, INCONCLUSIVE, REFUTED, AnalysisError, Result
from ..stationary.ballnorm import mask_terms, norm_below_one_on_box
from ..stationary.difference import difference_symbol
from ..stationary.normset import _parameter, norm_solution_set
from ..stationary.transition import transition_matrices
from .crossings import _complement_stretches, _exact_boundaries, _support_shrinks
from .holder import holder_exponent, smoothness
from ..algebra.reader import as_expr
from .. import progress


def _interior_route(a: LaurentSymbol, p, j: int, lo: RealAlgebraic, hi: RealAlgebraic, closed, budget) -> Result:
    """Route 4 of :func:`verify_smoothness_interval`: :func:`~analysis.regularity.interior.ck_interior`
    on the claimed interval (a closed end only where it is rational)."""
    from .interior import DEFAULT_INTERIOR_BUDGET, ck_interior

    lo_closed = bool(closed[0]) and lo.is_rational
    hi_closed = bool(closed[1]) and hi.is_rational
    return ck_interior(a, j, lo.expr, hi.expr, p, lo_open=not lo_closed, hi_open=not hi_closed,
                       budget=DEFAULT_INTERIOR_BUDGET if budget is None else budget)


def _counterexample(a, p, j: int, lo: RealAlgebraic, hi: RealAlgebraic, points, budget: int, tried,
                    method: str) -> Result | None:
    """The refutation at the first of ``points`` inside ``(lo, hi)`` certified not C^j, or None."""
    for q in points:
        x = RealAlgebraic.rational(q)
        if not (lo.compare(x) < 0 < hi.compare(x)):
            continue
        v = smoothness(a.subs({p: q}), j, budget=budget)
        if v.value is False:
            return Result(value=False, status=REFUTED,
                          witness={"route": "certified counterexample", "counterexample": q,
                                   "reason": v.witness.get("reason"), "tried": tried},
                          provenance={"method": method})
    return None


def _points_in(u, v) -> list:
    """Rational points strictly inside ``(u, v)`` (exact ends): the middle, the quarters, then
    closer and closer to each end (a true boundary inside a strip the norm tests left is often
    near one of its ends)."""
    U, V = RealAlgebraic.from_expr(as_expr(u)), RealAlgebraic.from_expr(as_expr(v))
    a0, b0 = U.b, V.a                  # rational bounds inside the interval when it is not tiny
    if not a0 < b0:
        a0, b0 = U.a, V.b
    fractions = [sp.Rational(1, 2), sp.Rational(1, 4), sp.Rational(3, 4)]
    for k in (3, 5, 7):
        fractions += [sp.Rational(1, 2**k), 1 - sp.Rational(1, 2**k)]
    return [a0 + (b0 - a0) * t for t in fractions]


def _single_parameter(a: LaurentSymbol, param) -> sp.Symbol:
    if len(a.params) != 1:
        if not a.params:
            raise AnalysisError("the scheme has no free parameter")
        names = ", ".join(p.name for p in a.params)
        raise AnalysisError(f"several free parameters ({names}): fix all but one with --param")
    p = a.params[0]
    if param is not None and str(param) != p.name:
        raise AnalysisError(f"unknown parameter {str(param)!r} (the scheme's parameter is {p.name})")
    return p


def _verdict_at(a, p, value, j, budget):
    r = smoothness(a.subs({p: value}), j, budget=budget)
    return r.value, r


def ck_parameter_set(a: LaurentSymbol, j: int, param=None, *, within=(-1, 1), grid: int = 16,
                     tol: float = 1e-8, budget: int = 20_000, interior_L_max: int = 10,
                     strip_budget: int = 30_000) -> Result:
    """Where is the one-parameter family ``a(p)`` C^j?  Boundaries to ``tol``, bracketed by certified points.

    A grid of ``grid + 1`` rational points in ``within`` gets certified verdicts; between two
    grid points with different verdicts the boundary is located:

    * exactly when the spectrum-maximizing product ``Pi`` found on the non-C^j side has an
      eigenvalue ``+-2^{(k-j)L}`` at an algebraic ``p*`` in between (``p*`` is then certified
      not C^j by the exact identity ``det(Pi(p*) -+ 2^{(k-j)L} I) = 0``), and a rational point
      within ``tol`` of ``p*`` on the other side is certified C^j;
    * otherwise by bisection with certified verdicts until the bracket is narrower than ``tol``.

    ``value`` is the list of grid runs where the family is C^j, as ``(left, right)`` boundary
    records; ``witness["samples"]`` the grid verdicts. The interior of each run, from its exact
    (open) or certified (closed) ends, is covered by exact parametric norm tests
    (:func:`analysis.regularity.interior.ck_interior`, L <= ``interior_L_max``): ``run["interior"]``
    gives the certified part and the strips left (next to ends of eigenvalue type).

    Budgets are work units, counted, never timed (about a millisecond each on the reference machine):
    ``budget`` per certified verdict (:func:`~analysis.regularity.holder.smoothness`), ``strip_budget``
    for closing the strips (:func:`~analysis.regularity.strips.close_strip`).
    """
    p = _single_parameter(a, param)
    lo, hi = (sp.Rational(sp.nsimplify(as_expr(w))) for w in within)
    if not lo < hi:
        raise AnalysisError("within needs low < high")
    pts = [lo + (hi - lo) * sp.Rational(i, grid) for i in range(grid + 1)]
    samples, verdicts = [], {}
    progress.stage(f"C^{j} verdicts at the grid points", len(pts))
    for q in pts:
        progress.step()
        v, r = _verdict_at(a, p, q, j, budget)
        verdicts[q] = r
        samples.append({"p": q, "C^j": v, "alpha": (r.witness.get("alpha").lower, r.witness.get("alpha").upper)
                        if r.witness.get("alpha") is not None else None, "status": r.status})
    boundaries = []
    changes = [(s0, s1) for s0, s1 in zip(samples[:-1], samples[1:])
               if s0["C^j"] is not None and s1["C^j"] is not None and s0["C^j"] != s1["C^j"]]
    progress.stage("boundaries", len(changes))
    for s0, s1 in changes:
        progress.step()
        boundaries.append(_locate(a, p, j, s0, s1, tol, budget, verdicts))
    runs = []
    start = None
    for i, s in enumerate(samples):
        if s["C^j"] and start is None:
            start = i
        if start is not None and (not s["C^j"] or i == len(samples) - 1):
            end = i if s["C^j"] else i - 1
            left = next((b for b in boundaries if b["between"][1] == samples[start]["p"]), None)
            right = next((b for b in boundaries if b["between"][0] == samples[end]["p"]), None)
            runs.append({"left": left if left else {"open_end": samples[start]["p"]},
                         "right": right if right else {"open_end": samples[end]["p"]}})
            start = None
    undecided = [s["p"] for s in samples if s["C^j"] is None]
    boundaries_certified = not undecided and all(b["status"] == CERTIFIED for b in boundaries)
    # the interior of each run: proven only if the norm tests cover it (analysis.regularity.ranges)

    interiors = []
    progress.stage(f"C^{j} on the interior of each run", len(runs))
    for run in runs:
        progress.step()
        interiors.append(_run_interior(a, p, j, run, interior_L_max, budget, strip_budget))
    # the complement: every stretch of non-C^j grid verdicts, proven not C^j on the whole of it where one
    # product has a real eigenvalue of modulus >= the threshold throughout (exact sign of a determinant)
    stretches = _complement_stretches(a, p, j, samples, boundaries, verdicts,
                                      lambda q: verdicts[q].value if q in verdicts else _verdict_at(a, p, q, j, budget)[0])
    complement_proven = all(st["proven"] for st in stretches)
    if boundaries_certified and (runs or stretches) and all(interiors) and complement_proven:
        status = CERTIFIED
        message = None
    elif boundaries_certified and all(interiors) and not complement_proven:
        status = INCONCLUSIVE
        message = ("each reported boundary is certified on both sides and C^%d is proven on every run, but not C^%d "
                   "is proven only at the grid points of " % (j, j)
                   + ", ".join(f"[{sp.sstr(st['from'])}, {sp.sstr(st['to'])}]" for st in stretches if not st["proven"])
                   + " (no product of length <= 4 or found at the grid points has a real eigenvalue of modulus "
                     ">= the threshold on the whole of it): the C^%d set there is sampled, not proven" % j)
    else:
        status = INCONCLUSIVE
        strips = [s for run in runs for s in (run.get("interior") or {}).get("strips", [])]
        if strips and boundaries_certified:
            message = ("each reported boundary is certified on both sides and the norm tests prove C^%d on the "
                       "interior except the strips " % j
                       + ", ".join(f"[{sp.sstr(x)}, {sp.sstr(y)}] (width {float(y - x):.3g})" for x, y in strips)
                       + " next to ends of eigenvalue type, where no norm ||(1/2 S_a%d)^L|| with L <= %d is below 1"
                       % (j + 1, interior_L_max))
        else:
            message = ("each reported boundary is certified on both sides and every grid verdict is certified, "
                       "but the C^j set between grid points is sampled, not proven: the norm tests did not cover "
                       "the whole interior of every run")
    prov = {"method": "certified Hölder verdicts on a grid; exact s.m.p. eigenvalue crossings; certified "
                      "bisection; norm tests (exact sets, Arb boxes) for the interior", "tol": tol, "grid": grid}
    if message:
        prov["message"] = message
    return Result(value=runs, status=status,
                  witness={"samples": samples, "boundaries": boundaries, "parameter": p.name, "j": j,
                           "undecided": undecided, "boundaries_certified": boundaries_certified,
                           "not_Cj": stretches},
                  provenance=prov)


def _run_interior(a, p, j, run, L_max, budget, strip_budget: int = 30_000) -> bool:
    """Cover one run by the exact parametric norm tests (and the strips they leave next to ends of
    eigenvalue type by the parametric invariant polytope, ``strip_budget`` work units in all); records
    ``run["interior"]``."""
    from .interior import ck_interior

    ends = []
    for b in (run["left"], run["right"]):
        if "exact" in b:
            ends.append((b["exact"], True))
        else:
            ends.append((b.get("certified_C^j_at", b.get("open_end")), False))
    (lo, lo_open), (hi, hi_open) = ends
    if lo is None or hi is None or not as_expr(lo) < as_expr(hi):
        run["interior"] = None
        return False
    try:
        r = ck_interior(a, j, lo, hi, p, lo_open=lo_open, hi_open=hi_open, L_max=L_max,
                        budget=max(30_000, budget) + max(0, strip_budget - 30_000), strip_budget=strip_budget)
    except AnalysisError as exc:     # e.g. (1+z)^{j+1} divides a only at exceptional values
        run["interior"] = {"from": lo, "to": hi, "proven": False, "route": f"no norm test: {exc}",
                           "strips": [], "status": INCONCLUSIVE}
        return False
    run["interior"] = {"from": lo, "to": hi, "from_open": lo_open, "to_open": hi_open,
                       "proven": r.status == CERTIFIED, "certified": r.value["certified"],
                       "strips": r.value["strips"], "status": r.status,
                       "route": _route(r, L_max),
                       "pieces": r.witness["pieces"],
                       "strips_not_closed": r.provenance.get("strips not closed by the invariant polytope", [])}
    return r.status == CERTIFIED


def _route(r, L_max) -> str:
    """How the interior was covered: norm-test pieces, and the strips closed by the polytope."""
    norm = [x for x in r.witness["pieces"] if "polytope" not in x]
    poly = [x["polytope"] for x in r.witness["pieces"] if "polytope" in x]
    route = "exact parametric norm tests (L <= %d, %d pieces)" % (L_max, len(norm))
    if poly:
        route += "; %d strip(s) closed by a parametric invariant polytope (s.m.p. T_%s, %d sub-intervals)" % (
            len(poly), "/".join(x["product"] for x in poly), sum(x["pieces"] for x in poly))
    return route


def _locate(a, p, j, s0, s1, tol, budget, verdicts=None):
    """Boundary between two grid samples with different certified verdicts (``verdicts``: the smoothness
    results at the grid points, already computed)."""
    q0, q1 = s0["p"], s1["p"]
    good, bad = (q0, q1) if s0["C^j"] else (q1, q0)
    # the s.m.p. on the non-C^j side gives an exact candidate
    rbad = verdicts[bad] if verdicts and bad in verdicts else _verdict_at(a, p, bad, j, budget)[1]
    words = []
    if rbad.witness.get("product"):
        words.append(tuple(rbad.witness["product"]))
    if rbad.witness.get("alpha") is not None and rbad.witness["alpha"].witness.get("product"):
        words.append(tuple(rbad.witness["alpha"].witness["product"]))
    from itertools import product as all_words

    for L in range(1, 5):
        for w in all_words(range(2), repeat=L):
            if min(w[i:] + w[:i] for i in range(L)) == w and w not in words:
                words.append(w)
    tol_q = sp.nsimplify(tol, rational=True)
    side = 1 if good > bad else -1
    candidates = []
    for word in words:
        for r, ev, poly in _exact_boundaries(a, p, j, word, min(q0, q1), max(q0, q1)):
            candidates.append((r, ev, poly, word))
    # the crossing nearest to the C^j side is the first place where C^j is lost
    import functools

    candidates.sort(key=functools.cmp_to_key(lambda u, v: side * v[0].compare(u[0])))
    for r, ev, poly, word in candidates[:4]:
        if any(r.sign_of(P) == 0 for P in _support_shrinks(a, p)):
            # the support shrinks at r: the generic eigenvalue proves nothing there, the scheme's verdict does
            if not r.is_rational or (verdicts[r.expr].value if verdicts and r.expr in verdicts
                                     else _verdict_at(a, p, r.expr, j, budget)[0]) is not False:
                continue
        probe = _simple_rational_near(r, side, tol_q)
        if probe is None or (probe - good) * side > 0:
            continue
        v, _ = _verdict_at(a, p, probe, j, budget)
        if v is True:
            factors = [f for f, _ in sp.Poly(poly.as_expr(), p).factor_list()[1] if r.sign_of(f) == 0]
            return {"between": (min(q0, q1), max(q0, q1)), "exact": r.expr, "exact_float": float(r),
                    "bracket": (probe, r.expr) if side < 0 else (r.expr, probe),
                    "certified_C^j_at": probe, "certified_not_C^j_at": r.expr,
                    "how": f"eigenvalue {sp.sstr(ev)} of T_{''.join(map(str, word))}(p) at the root of "
                           f"{sp.sstr(factors[0].as_expr() if factors else poly.as_expr())}",
                    "status": CERTIFIED}
    # certified bisection
    g, b = good, bad
    while abs(g - b) > tol_q:
        mid = (g + b) / 2
        mid = sp.nsimplify(mid, rational=True)
        v, _ = _verdict_at(a, p, mid, j, budget)
        if v is None:
            return {"between": (min(q0, q1), max(q0, q1)), "bracket": tuple(sorted((g, b))),
                    "undecided_at": mid, "status": INCONCLUSIVE}
        if v:
            g = mid
        else:
            b = mid
    return {"between": (min(q0, q1), max(q0, q1)), "bracket": tuple(sorted((g, b))),
            "certified_C^j_at": g, "certified_not_C^j_at": b, "how": "certified bisection", "status": CERTIFIED}


def _simple_rational_near(r, side: int, tol_q):
    """A rational with few digits strictly on ``side`` of the algebraic ``r``, within ``tol_q``."""
    from ..algebra.algebraic import RealAlgebraic

    r.enclosure(int(-math.log2(float(tol_q))) + 40)
    centre = (r.a + r.b) / 2
    for digits in range(int(-math.log10(float(tol_q))) + 1, 60):
        scale = sp.Integer(10) ** digits
        q = (sp.floor(centre * scale) + (1 if side > 0 else 0) + side) / scale
        if abs(q - centre) < tol_q and (r.compare(RealAlgebraic.rational(q)) < 0) == (side > 0):
            return q
    return None


# --------------------------------------------------------------------------------------------
# C^j ranges from exact norm sets and eigenvalue sets (any arity)
# --------------------------------------------------------------------------------------------

_VIOLATIONS: dict = {}


def _violation_set(a: LaurentSymbol, m: int, j: int, p: sp.Symbol, k: int) -> tuple[sp.Set, list]:
    """``{p : some T_eps(c(p)) has a real eigenvalue r(p) with |r(p)| >= m^(k-j)}`` from the linear
    factors (in lambda) of the characteristic polynomials; nonlinear factors are listed, not used.

    Computed once per process for the same arguments (bounded; the set and the factors are immutable
    sympy objects): a smoothness profile and the claims beside it ask for the same family and ``j``."""
    key = (a, m, j, p, k)
    if key not in _VIOLATIONS:
        if len(_VIOLATIONS) >= 64:
            _VIOLATIONS.clear()
        V, unused = _violation_set_of(a, m, j, p, k)
        _VIOLATIONS[key] = (V, tuple(unused))
    V, unused = _VIOLATIONS[key]
    return V, list(unused)


def _violation_set_of(a: LaurentSymbol, m: int, j: int, p: sp.Symbol, k: int) -> tuple[sp.Set, list]:
    lam = sp.Symbol("lambda")
    c = factor_out(a, k + 1, arity=m) / m
    theta = sp.Integer(m) ** (k - j)
    V: sp.Set = sp.EmptySet
    unused = []
    for eps, T in enumerate(transition_matrices(c, arity=m)):
        cp = sp.factor_list(sp.expand(T.charpoly(lam).as_expr()), lam)
        for f, _mult in cp[1]:
            poly = sp.Poly(f, lam)
            if poly.degree() != 1:
                if poly.degree() > 1:
                    unused.append((eps, f))
                continue
            A, B = poly.all_coeffs()
            r = sp.cancel(-B / A)
            if r.free_symbols - {p}:
                unused.append((eps, f))
                continue
            for ineq in (r >= theta, r <= -theta):
                V = V.union(sp.solveset(ineq, p, domain=sp.S.Reals))
    return V, unused


def _norm_below_at(a, m, j, p, x, L_max):
    """The smallest L <= L_max with ``||(1/m S_{a_{j+1}})^L|| < 1`` exactly at the algebraic point x."""
    from ..algebra.algebraic import RealAlgebraic
    from ..stationary.normset import _norm_below_at_point, _residue_polys

    X = RealAlgebraic.from_expr(x)
    for L in range(1, min(L_max, 6) + 1):
        _, by_res = _residue_polys(a, j + 1, L, "paper", p, m)
        if _norm_below_at_point(by_res, X, 1):
            return L
    return None


def _cover_undecided(a, m, j, p, undecided, S, L_max, points_only=False, strip_budget: int = 30_000):
    """Shrink the undecided part with the exact parametric norm tests on each of its intervals, and the
    strips they leave next to ends of eigenvalue type with the parametric invariant polytope
    (:func:`analysis.regularity.strips.close_strip`, ``strip_budget`` work units per interval)."""
    from .interior import ck_interior

    parts = undecided.args if isinstance(undecided, sp.Union) else (undecided,)
    covered = []
    for part in parts:
        if isinstance(part, sp.FiniteSet):
            for x in part:
                L = _norm_below_at(a, m, j, p, x, L_max)
                if L is not None:
                    S = S.union(sp.FiniteSet(x))
                    covered.append({"point": sp.sstr(x), "L": L})
                    continue
                v = smoothness(a.subs({p: x}), j, budget=10_000, arity=m)   # certified verdict there
                if v.value is True and v.status == CERTIFIED:
                    S = S.union(sp.FiniteSet(x))
                    covered.append({"point": sp.sstr(x), "verdict": v.witness.get("reason")})
            continue
        if points_only or not isinstance(part, sp.Interval) or not (part.start.is_finite and part.end.is_finite):
            continue
        r = ck_interior(a, j, part.start, part.end, p, arity=m, L_max=L_max,
                        budget=30_000 + max(0, strip_budget - 30_000), strip_budget=strip_budget)
        C = r.value["certified"].to_sympy()
        polytopes = [{"from": x["from"], "to": x["to"], "kind": x["kind"], **x["polytope"]}
                     for x in r.witness["pieces"] if "polytope" in x]
        if C != sp.EmptySet:
            S = S.union(C)
            covered.append({"interval": str(part), "certified": str(r.value["certified"]),
                            "pieces": len(r.witness["pieces"]), **({"polytope": polytopes} if polytopes else {})})
        if r.provenance.get("strips not closed by the invariant polytope"):
            covered.append({"interval": str(part), "strips not closed by the invariant polytope":
                            r.provenance["strips not closed by the invariant polytope"]})
    return S, covered


def ck_range(a: LaurentSymbol, j: int, param=None, *, arity: int = 2, Ls: Sequence = (1, 2, 3),
             within=(-sp.oo, sp.oo), interior_L_max: int = 8, strip_budget: int = 30_000) -> Result:
    """Where is the one-parameter family of arity ``m`` ``C^j``?  Both sides certified where possible.

    Unlike :func:`ck_parameter_set` (sampling and bisection, the binary ``subdiv range``), the sets
    here are exact unions of intervals, for any arity (the ``range`` command for ``m > 2``):

    * **C^j** (sufficient): the union over ``L in Ls`` of the exact sets where the m-ary Dyn–Levin test
      ``||(1/m S_{a_{j+1}})^L||_inf < 1`` holds (:func:`analysis.stationary.normset.norm_solution_set`).
    * **not C^j** (necessary): the exact set where a single transition matrix ``T_eps(c(p))``,
      ``c = m^k a/q_m^(k+1)``, has a real eigenvalue of modulus ``>= m^(k-j)`` (then ``alpha <= j``).

    ``value`` is the C^j set (a sympy set); ``witness["not_Cj"]`` the proven complement part,
    ``witness["undecided"]`` what neither covers inside ``within`` (empty: the range is exact, certified
    on both sides; otherwise points there can be decided one by one with :func:`smoothness`).
    What the norm sets leave undecided is first covered, where possible, by the exact parametric
    norm tests with L <= ``interior_L_max`` (:func:`analysis.regularity.interior.ck_interior`;
    ``witness["interior_tests"]``; 0 turns this off), and the strips they leave next to ends of
    eigenvalue type by the parametric invariant polytope (:func:`analysis.regularity.strips.close_strip`,
    ``strip_budget`` work units per interval; ``interior_tests[...]["polytope"]``, or why a strip was not closed).
    Uses the generic ``k`` (``N - 1`` identically in the parameter).
    """

    m = check_arity(arity)
    p = _parameter(a, param)
    k = smoothing_factor(a, exceptional=False, arity=m).value - 1
    if j > k:
        raise AnalysisError(f"the family has only {k + 1} factors q_{m} identically: C^{j} needs {j + 1}")
    lo, hi = (as_expr(w) for w in within)
    box = sp.Interval(lo, hi, left_open=True, right_open=True)
    S: sp.Set = sp.EmptySet
    per_L = {}
    for L in Ls:
        r = norm_solution_set(a, j + 1, L, p, within=(lo, hi), arity=m)
        per_L[L] = str(r.value)
        S = S.union(r.value.to_sympy())
    V, unused = _violation_set(a, m, j, p, k)
    V = V.intersect(box)
    undecided = box - S.union(V)
    covered = []
    if interior_L_max and undecided != sp.EmptySet:
        S, covered = _cover_undecided(a, m, j, p, undecided, S, interior_L_max, strip_budget=strip_budget)
        undecided = box - S.union(V)
        if undecided != sp.EmptySet:     # isolated points left (e.g. closed ends of the intervals)
            S, more = _cover_undecided(a, m, j, p, undecided, S, interior_L_max, points_only=True)
            covered += more
            undecided = box - S.union(V)
    exact = undecided.is_empty is True or undecided == sp.EmptySet
    return Result(value=S, status=CERTIFIED if exact else INCONCLUSIVE,
                  witness={"parameter": p.name, "j": j, "k": k, "arity": m, "not_Cj": V, "undecided": undecided,
                           "norm_sets": per_L, "nonlinear_factors": unused,
                           "exact": exact, "interior_tests": covered},
                  provenance={"method": "m-ary Dyn-Levin norm sets (C^j) and exact real eigenvalues of the "
                                        "transition matrices (not C^j)", "arity": m})


def alpha_curve(a: LaurentSymbol, param=None, *, within=(-1, 1), samples: int = 24,
                budget: int = 10_000, arity: int = 2) -> Result:
    """Certified enclosures of alpha(p) at ``samples + 1`` equally spaced rational points of ``within``
    (ends included; for a figure and the smoothness profile); ``budget`` in work units per point
    (:func:`~analysis.regularity.holder.holder_exponent`, arity ``m``). A point where the exponent cannot
    be enclosed (e.g. not convergent) is an inconclusive row with a note.

    >>> import sympy as sp
    >>> t = sp.Symbol("t")
    >>> fam = LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)") * (1 - t) + LaurentSymbol.from_expr(
    ...     "(1+z+z**2)**3/(9*z**3)") * t                           # cubic to quadratic ternary B-spline
    >>> [(r["p"], r["lower"]) for r in alpha_curve(fam, within=(0, 1), samples=1, arity=3).value]
    [(0, 3), (1, 2)]
    """
    m = check_arity(arity)
    p = _single_parameter(a, param) if m == 2 else _parameter(a, param)
    lo, hi = (sp.Rational(sp.nsimplify(as_expr(w))) for w in within)
    rows = []
    for i in range(samples + 1):
        q = lo + (hi - lo) * sp.Rational(i, samples)
        try:
            h = holder_exponent(a.subs({p: q}), budget=budget, arity=m)
            rows.append({"p": q, "lower": h.lower, "upper": h.upper, "status": h.status})
        except AnalysisError as exc:
            rows.append({"p": q, "lower": None, "upper": None, "status": INCONCLUSIVE, "note": str(exc)})
    status = CERTIFIED if all(r["status"] == CERTIFIED for r in rows) else INCONCLUSIVE
    return Result(value=rows, status=status, witness={"parameter": p.name, **arity_key(m)},
                  provenance={"method": "holder_exponent at rational sample points" if m == 2 else
                              f"holder_exponent (arity {m}) at rational sample points", **arity_key(m)})


# --------------------------------------------------------------------------------------------
# a claimed interval: proven on the whole interval, or refuted at a certified point
# --------------------------------------------------------------------------------------------

def _interval_inside(set_, lo: RealAlgebraic, hi: RealAlgebraic, *, lo_closed: bool = False,
                     hi_closed: bool = False) -> bool:
    """Is the interval from lo to hi (open, or closed at the flagged ends) inside ``set_``?"""
    for plo, phi, plc, phc in set_.parts:
        if plo is None:
            left_ok = True
        else:
            c = plo.compare(lo)
            left_ok = c < 0 or (c == 0 and (plc or not lo_closed))
        if phi is None:
            right_ok = True
        else:
            c = phi.compare(hi)
            right_ok = c > 0 or (c == 0 and (phc or not hi_closed))
        if left_ok and right_ok:
            return True
    return False


def verify_smoothness_interval(a: LaurentSymbol, j: int, interval, param=None, *, max_L_exact: int = 3,
                               max_L_boxes: int = 8, max_boxes: int = 400, samples: int = 8,
                               budget: int = 10_000, closed=(False, False),
                               interior_budget: int | None = None) -> Result:
    """Check the claim "C^j for every parameter value in the interval" (see module docstring).

    ``value`` True (proven on the whole interval), False (refuted at a certified point), None.
    ``witness["route"]`` names the route; for a refutation ``witness["counterexample"]``.
    ``closed``: whether each end belongs to the claim (a closed end must be rational); routes 1-3
    prove the open interval, route 4 the interval as claimed. ``witness["ends checked"]`` says
    whether the closed ends were proven too. ``budget`` (work units) is per Hölder verdict at a
    point, ``interior_budget`` that of route 4 (default that of
    :func:`~analysis.regularity.interior.ck_interior`).
    """
    if len(a.params) != 1:
        raise AnalysisError("a claimed interval needs a scheme with exactly one free parameter")
    p = a.params[0]
    if param is not None and str(param) != p.name:
        raise AnalysisError(f"unknown parameter {str(param)!r} (the scheme's parameter is {p.name})")
    lo, hi = (RealAlgebraic.from_expr(as_expr(x)) for x in interval)
    if lo.compare(hi) >= 0:
        raise AnalysisError("the claimed interval is empty")
    # 1. exact norm sets
    tried, sets = [], []
    for L in range(1, max_L_exact + 1):
        S = norm_solution_set(a, j + 1, L, within=(lo.expr, hi.expr)).value
        tried.append((L, str(S)))
        sets.append(S)
        if _interval_inside(S, lo, hi):
            return Result(value=True, status=CERTIFIED,
                          witness={"route": f"exact norm inequality, L = {L}", "set": S, "tried": tried},
                          provenance={"method": "Dyn-Levin norm test solved exactly in the parameter"})
    # 2. certified counterexample at sample points

    ql = lo.a if lo.a == lo.b else lo.b
    qh = hi.b if hi.a == hi.b else hi.a
    points = [ql + (qh - ql) * sp.Rational(i, samples + 1) for i in range(1, samples + 1)]
    r2 = _counterexample(a, p, j, lo, hi, points, budget, tried, "certified Hölder verdict at a rational point")
    if r2 is not None:
        return r2
    # 3. cover [lo, hi] by boxes, breadth first: each box (as an open interval) inside an exact
    #    norm set, or (as a closed interval, which proves more) with an Arb norm bound below 1
    am = difference_symbol(a, j + 1)
    terms = mask_terms(am, p)
    lo_q, hi_q = lo.a, hi.b  # rational outer bounds of the claimed interval
    todo = [(lo_q, hi_q)]
    proven, boxes, smallest = 0, 0, None
    while todo and boxes < max_boxes:
        b0, b1 = todo.pop(0)
        boxes += 1
        B0, B1 = RealAlgebraic.rational(b0), RealAlgebraic.rational(b1)
        # the part of the box inside the claim
        c0 = lo if lo.compare(B0) > 0 else B0
        c1 = hi if hi.compare(B1) < 0 else B1
        if c0.compare(c1) >= 0:
            proven += 1
            continue
        # box ends inside the claim must belong to the set too (no hole at a split point)
        c0_in, c1_in = c0 is B0 and lo.compare(B0) < 0, c1 is B1 and hi.compare(B1) > 0
        if any(_interval_inside(S, c0, c1, lo_closed=c0_in, hi_closed=c1_in) for S in sets):
            proven += 1
            continue
        if norm_below_one_on_box(terms, am.start, (b0, b1), max_L_boxes):
            proven += 1
            continue
        m = (b0 + b1) / 2
        smallest = b1 - b0 if smallest is None else min(smallest, b1 - b0)
        todo += [(b0, m), (m, b1)]
    if not todo:
        return Result(value=True, status=CERTIFIED,
                      witness={"route": "exact norm sets and interval arithmetic over a subdivision",
                               "boxes": proven, "tried": tried},
                      provenance={"method": "exact Dyn-Levin norm sets (L <= %d) and Arb ball norms (L <= %d) "
                                            "on parameter boxes" % (max_L_exact, max_L_boxes)})
    # 4. parametric norms with exact ends and the invariant polytope on the strips; then
    #    counterexamples in what stays open (a true boundary inside the claim lies there)
    r4 = _interior_route(a, p, j, lo, hi, closed, interior_budget)
    if r4.status == CERTIFIED:
        return Result(value=True, status=CERTIFIED,
                      witness={"route": "parametric norm tests and invariant polytopes on sub-intervals",
                               "ends checked": (not closed[0] or lo.is_rational) and (not closed[1] or hi.is_rational),
                               "pieces": len(r4.witness["pieces"]), "tried": tried},
                      provenance={"method": r4.provenance["method"], "work": r4.provenance["work"]})
    for u, v in r4.value["strips"] if r4.value else []:
        r5 = _counterexample(a, p, j, lo, hi, _points_in(u, v), budget, tried,
                             "certified Hölder verdict at a rational point of a part the parametric norm tests "
                             "could not prove")
        if r5 is not None:
            return r5
    left = sorted(todo)
    return Result(value=None, status=INCONCLUSIVE,
                  witness={"route": "none decided", "tried": tried, "boxes_proven": proven,
                           "uncovered": [(float(x), float(y)) for x, y in left[:5]],
                           "uncovered_width": float(sum(y - x for x, y in left))},
                  provenance={"message": "the norm tests did not cover these parts of the interval "
                                         "(near a true C^j boundary they never will); finer boxes, a "
                                         "larger L or certified Hölder exponents on them would"})
