"""One scheme over a range of valences: the subdominant eigenvalue in closed form in n, and for each n
the certified eigen-structure, the curvature behaviour and the C^1 verdict with its status.

The closed form comes from the characteristic polynomial of block 1 with the valence as a symbol (the
weights on every sector contribute through their frequency -1 only when n exceeds the rules'
frequencies): its factors of degree <= 2 in lambda are solved by radicals, and the root that is the
subdominant eigenvalue is chosen by its Arb value at each valence of the range, where it is checked to lie
in lambda's isolating ball (so the formula *is* lambda there, not a float match).

C^1: the eigen-conditions are necessary ingredients, not a proof. With them and a certified regular and
injective characteristic map (:mod:`.charmap`: quad and triangle rules on the 2-ring) the verdict is
certified C^1 for generic initial data (Reif 1995, a sufficient condition); a regular but not injective
characteristic map is reported inconclusive (the sufficient condition fails); without the characteristic map (rules on the 1-ring) it is
"inconclusive: eigen-conditions hold, characteristic map not checked"; where an eigen-condition fails
(certified), the standard C^1 test does not apply; the verdict is then *refuted* (not C^1 for generic
initial data) only where :mod:`.necessary` proves it with a theorem whose hypotheses are all checked (the
butterfly family: the leading eigenfunction does not wind once around the vertex), and otherwise stays
inconclusive with the missing hypothesis.

Curvature (J. Peters, U. Reif, Shape characterization of subdivision surfaces — basic principles, CAGD
21 (2004); K. Karčiauskas, J. Peters, U. Reif, Shape characterization of subdivision surfaces — case
studies, CAGD 21 (2004); Peters–Reif, Subdivision Surfaces, 2008, ch. 7), for schemes whose regular part
is C^2 and generic data: the second fundamental form near the vertex scales like (mu / lambda^2)^m on
the m-th ring, so mu < lambda^2 gives curvature tending to zero at the vertex (a flat spot), mu =
lambda^2 bounded curvature, mu > lambda^2 unbounded curvature. mu counts only eigenvalues whose
eigenfunctions are nonzero on the ring, and mu = lambda^2 must be semisimple: :mod:`.spectrum` certifies
both for the deciding eigenvalue (rules on the 2-ring) or leaves the verdict inconclusive with the reason.

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> closed_form_lambda(scheme_rules("catmull-clark", ring=1))["lambda"]
'c/16 + sqrt((c + 1)*(c + 9))/16 + 5/16'
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, AnalysisError, Result
from .blocks import block_charpoly, c, fourier_block, lam, special_frequencies
from .rules import C1, LocalRules, n_sym, regular_next_to_centre
from .spectrum import VertexAnalysis, analyse, arb_value, exact_rational

#: the largest valence range the command accepts
MAX_VALENCE = 200

CURVATURE_TEXT = {
    "zero": "curvature tends to zero at the vertex (mu < lambda^2: flat spot for generic data)",
    "bounded": "curvature bounded (mu = lambda^2)",
    "unbounded": "curvature unbounded for generic data (mu > lambda^2)",
    "inconclusive": "curvature behaviour not decided",
    "not applicable": "the regular part is only C^1 (biquadratic): the curvature criterion needs a C^2 regular part",
    "not applicable (butterfly)": "the regular butterfly scheme is only C^1 (Dyn-Gregory-Levin 1990): the curvature "
                                  "criterion needs a C^2 regular part",
}

#: why the characteristic map is not checked, by lattice (short, per valence; the long form in the docs)
NO_CHARACTERISTIC_MAP = {
    "triangle, interpolating": "characteristic map not certified (the butterfly's regular basis functions are not "
                               "piecewise polynomial: no Bernstein-form Jacobian certificate)",
    "sqrt3": "characteristic map not checked (no patch form of the regular sqrt(3) limit functions here)",
    "irregular": "characteristic map not checked (the new points next to the centre are not made by the regular "
                 "stencils, e.g. a given --edge rule: the segment's limit is not a box-spline patch of the level-1 "
                 "net, the only form certified here)",
}
#: the key of :data:`NO_CHARACTERISTIC_MAP` for rules that are not regular next to the centre
IRREGULAR = "irregular"


def closed_form_lambda(rules: LocalRules) -> dict[str, Any]:
    """The roots of block 1's characteristic polynomial with n symbolic, by factors of degree <= 2;
    ``lambda`` is the one that gives the largest value at n = 7 (checked per valence by :func:`valence_entry`)."""
    N0 = max(max(special_frequencies(rules) | {0}) + 2, rules.generic_from)
    P = block_charpoly(fourier_block(rules, 1, None))
    P = sp.expand(P.subs(C1, c))               # in block 1, c = C1 = cos(2 pi/n)
    gens = [g for g in (lam, c, n_sym) if P.has(g)]
    _, fl = sp.factor_list(sp.Poly(P, *gens))
    roots = []
    for f, _e in fl:
        if f.degree(lam) == 0:
            continue
        if f.degree(lam) > 2:
            return {"lambda": None, "valid_from": N0, "factors": [str(g.as_expr()) for g, _ in fl],
                    "reason": "block 1 has an irreducible factor of degree > 2 in lambda"}
        roots += sp.roots(sp.Poly(f.as_expr(), lam), multiple=True)
    best = None
    for r in roots:
        v = arb_value(r, 7)
        if v is not None and (best is None or v.mid() > best[1].mid()):
            best = (r, v)
    expr = sp.simplify(best[0]) if best else None
    return {"lambda": str(expr) if expr is not None else None, "expr": expr, "valid_from": N0,
            "factors": [str(g.as_expr()) for g, _ in fl if g.degree(lam) > 0]}


def c1_verdict(a: VertexAnalysis, charmap: dict | None = None, lattice: str = "",
               necessary: Result | None = None) -> tuple[str, str]:
    """The C^1 verdict: certified only with the eigen-conditions *and* a certified regular, injective
    characteristic map, and then for generic initial data (Reif 1995: a sufficient condition). A regular
    map that is certified not injective makes Reif's sufficient condition fail; that is reported
    inconclusive, not as a proof that the scheme is not C^1. Refuted (not C^1 for generic initial data) only
    by ``necessary``, a *refuted* :func:`analysis.vertex.necessary.not_c1` (a theorem whose hypotheses are all
    checked); where it is inconclusive, its missing hypothesis is added to the verdict."""
    if necessary is not None and necessary.status == REFUTED:
        return REFUTED, necessary.witness["verdict"]
    if a.reif_ok and charmap is not None:
        if charmap["status"] == CERTIFIED:
            return CERTIFIED, ("C^1 for generic initial data (Reif 1995: eigen-conditions; characteristic map "
                               "regular and injective)")
        if charmap["status"] == REFUTED:
            return INCONCLUSIVE, (f"inconclusive: the characteristic map is regular but not injective (its boundary "
                                  f"winds {charmap['winding_number']} times), so Reif's sufficient condition fails")
        if charmap.get("jacobian_sign_change"):
            return INCONCLUSIVE, ("inconclusive: eigen-conditions hold; the Jacobian of the characteristic map's "
                                  "segment patches changes sign (corner values of opposite sign, Arb: proven), so "
                                  "the map is not regular and Reif's sufficient condition fails")
        return INCONCLUSIVE, "inconclusive: eigen-conditions hold, characteristic map not certified at " \
                             f"{charmap['precision_bits']} bits"
    if a.reif_ok:
        why = NO_CHARACTERISTIC_MAP.get(lattice, "characteristic map not checked")
        return INCONCLUSIVE, f"inconclusive: eigen-conditions hold, {why}"
    if a.reif_status == CERTIFIED:
        why = f" ({necessary.witness['verdict']})" if necessary is not None else ""
        return INCONCLUSIVE, (f"inconclusive: an eigen-condition fails ({a.reif_reason}); the standard C^1 test "
                              f"does not apply{why}")
    return INCONCLUSIVE, "inconclusive: eigen-conditions not decided"


_q = exact_rational


def vertex_results(rules: LocalRules, n: int, closed: dict | None = None) -> dict[str, Result]:
    """The results at valence n (the results contract: value or enclosure, status, witness, provenance):
    ``lambda`` (exact value and certified enclosure), ``separation`` (certified lower bound of lambda - max
    |others|), ``mu`` (enclosure of the subsubdominant modulus), ``reif`` (the eigen-conditions),
    ``curvature``, ``characteristic_map`` (quad/triangle rules on the 2-ring) and ``c1``."""
    a = analyse(rules, n)
    prov = {"method": "Fourier blocks of the local subdivision matrix; FLINT exact roots or Arb isolation",
            "precision_bits": a.prec, "valence": n, "rules": rules.source, "ring": rules.ring}
    out: dict[str, Result] = {}
    lam_e = a.lam
    if lam_e is None:
        out["reif"] = Result(value=None, status=INCONCLUSIVE, witness={"reason": a.reif_reason}, provenance=prov)
        out["c1"] = Result(value=None, status=INCONCLUSIVE,
                           witness={"verdict": "inconclusive: eigenvalues not isolated"}, provenance=prov)
        return out
    ball = lam_e.ball.real
    wit = {"block": 1, "polynomial": str(lam_e.factor.as_expr().subs(C1, sp.Symbol("c1"))),
           "ball": str(ball) if lam_e.real else str(lam_e.ball), "float": float(ball.mid()),
           "c": f"cos(2*pi/{n})"}
    if not lam_e.real:                         # a complex pair: "float" is the real part
        wit["float_imag"] = float(lam_e.ball.imag.mid())
    if closed and closed.get("expr") is not None and n >= closed["valid_from"]:
        v = arb_value(closed["expr"], n, max(a.prec, 128))
        wit["closed_form"] = closed["lambda"]
        wit["closed_form_checked"] = bool(v is not None and ball.overlaps(v) and ball.rad() < 1e-6)
    if a.above_lambda:           # block 1's leading eigenvalue is then not the subdominant one
        from .spectrum import _fmt, subdominant

        big = a.above_lambda[0]
        wit["subdominant"] = False
        wit["role"] = (f"block 1's leading eigenvalue, not the subdominant eigenvalue: block {big.k}'s eigenvalue "
                       f"{_fmt(big.ball)} is larger in modulus (certified)")
        sub, why = subdominant(a)
        out["subdominant"] = Result(
            value=None, lower=_q(sub.modulus.lower()) if sub else None, upper=_q(sub.modulus.upper()) if sub else None,
            status=CERTIFIED if sub else INCONCLUSIVE,
            witness={"block": sub.k if sub else None, "ball": str(sub.ball) if sub else None,
                     "float": float(sub.ball.real.mid()) if sub and sub.real else None, "reason": why,
                     "bound": "modulus"}, provenance=prov)
    out["lambda"] = Result(value=a.lam_exact, lower=_q(ball.lower()), upper=_q(ball.upper()),
                           status=CERTIFIED if lam_e.real and not a.above_lambda else INCONCLUSIVE, witness=wit,
                           provenance=prov)
    if a.separation is not None:
        out["separation"] = Result(lower=_q(a.separation.lower()),
                                   status=CERTIFIED if a.separation > 0 else INCONCLUSIVE,
                                   witness={"ball": str(a.separation), "float": float(a.separation.lower())},
                                   provenance=prov)
    if a.mu is not None:
        m = a.mu.modulus
        out["mu"] = Result(lower=_q(m.lower()), upper=_q(m.upper()), status=CERTIFIED,
                           witness={"block": a.mu.k, "ball": str(m), "float": float(m.mid()), "real": bool(a.mu.real),
                                    "polynomial": str(a.mu.factor.as_expr().subs(C1, sp.Symbol("c1")))},
                           provenance=prov)
    out["reif"] = Result(value=a.reif_ok, status=a.reif_status,
                         witness={"checks": dict(a.checks), "reason": a.reif_reason}, provenance=prov)
    if rules.lattice in ("dual quad", "triangle, interpolating"):
        text = CURVATURE_TEXT["not applicable" if rules.lattice == "dual quad" else "not applicable (butterfly)"]
        out["curvature"] = Result(value="not applicable", status=INCONCLUSIVE,
                                  witness={"mu_vs_lambda2": a.mu_vs_lam2, "text": text,
                                           "notes": list(a.notes)}, provenance=prov)
    else:
        wit = {"mu_vs_lambda2": a.mu_vs_lam2, "text": CURVATURE_TEXT[a.curvature], "notes": list(a.notes)}
        if a.curvature_reason:
            wit["reason"] = a.curvature_reason
        out["curvature"] = Result(value=a.curvature, status=a.curvature_status, witness=wit, provenance=prov)
    cm = None
    irregular = a.reif_ok and has_characteristic_map(rules) and not regular_next_to_centre(rules)
    if a.reif_ok and has_characteristic_map(rules) and not irregular:
        from .charmap import characteristic_map

        for prec in (128, 256):
            cm = characteristic_map(rules, n, ball, prec)
            if cm["status"] != INCONCLUSIVE:
                break
        if cm["status"] == INCONCLUSIVE:        # injectivity not decided: no false that was not proven
            from .charsign import jacobian_sign_change

            cm = dict(cm, injective=None)
            if not cm["regular"]:
                cm["jacobian_sign_change"] = jacobian_sign_change(rules, n, ball, cm["precision_bits"])
                if not cm["jacobian_sign_change"]:
                    cm["regular"] = None            # not proven regular, not proven irregular either
        out["characteristic_map"] = Result(value=cm["injective"], status=cm["status"],
                                           witness={k: v for k, v in cm.items() if k not in ("status", "method")},
                                           provenance={"method": cm["method"], "precision_bits": cm["precision_bits"]})
    nc = None
    if a.reif_status == CERTIFIED and a.reif_ok is False and rules.lattice == "triangle, interpolating":
        from .necessary import not_c1

        nc = not_c1(rules, n)
        out["not_c1"] = nc
    status, verdict = c1_verdict(a, cm, IRREGULAR if irregular else rules.lattice, nc)
    c1_witness = {"verdict": verdict}
    if status == REFUTED:
        c1_witness.update({k: nc.witness[k] for k in ("theorem", "hypotheses")})
    if a.reif_ok and rules.lattice == "triangle, interpolating":
        from .netmap import numerical_characteristic_map

        nm = numerical_characteristic_map(rules, n, float(ball.mid()))
        out["characteristic_map_numerical"] = Result(
            value=nm["injective"], status=NUMERICAL,
            witness={k: v for k, v in nm.items() if k not in ("status", "method")},
            provenance={"method": nm["method"]})
        c1_witness["numerical_evidence"] = (
            f"the characteristic net sampled on {nm['resolution']} rings is "
            + ("regular and winds once (floats): evidence, not a proof" if nm["injective"]
               else f"{'regular' if nm['regular'] else 'not regular'}, winding number {nm['winding_number']} (floats)"))
    out["c1"] = Result(value={CERTIFIED: True, REFUTED: False}.get(status), status=status,
                       witness=c1_witness, provenance=prov)
    return out


def valence_entry(rules: LocalRules, n: int, closed: dict | None = None) -> dict[str, Any]:
    """The results at valence n as one JSON-ready document: ``n``, ``matrix_size`` and each result of
    :func:`vertex_results` as :meth:`Result.to_json`."""
    res = vertex_results(rules, n, closed)
    entry: dict[str, Any] = {"n": n, "matrix_size": len(rules.points) * n + (1 if rules.centre else 0)}
    entry.update({k: r.to_json() for k, r in res.items()})
    return entry


def has_characteristic_map(rules: LocalRules) -> bool:
    """Whether the characteristic map is checked for these rules (2-ring of the quad lattice: bicubic patches;
    of the triangle lattice: Loop's quartic box-spline patches; Doo–Sabin: biquadratic patches)."""
    return rules.lattice == "dual quad" or (rules.lattice in ("quad", "triangle") and rules.ring == 2)


def parse_valences(text: str) -> list[int]:
    """``"5"``, ``"3..12"`` or ``"3,5,7"``.

    >>> parse_valences("3..6"), parse_valences("4,7")
    ([3, 4, 5, 6], [4, 7])
    """
    t = str(text).strip()
    if len(t) > 2000:
        raise AnalysisError("--valence is too long: give N, LO..HI or N1,N2,... (e.g. --valence 3..12)")
    try:
        if ".." in t:
            lo, hi = (int(x) for x in t.split(".."))
            vals = [lo, hi] if lo < 3 or hi > MAX_VALENCE else list(range(lo, hi + 1))   # bounds checked below
        else:
            vals = [int(x) for x in t.split(",") if x.strip()]
    except ValueError:
        raise AnalysisError(f"--valence takes N, LO..HI or N1,N2,...; not {t[:40]!r} (e.g. --valence 3..12)") from None
    if not vals:
        raise AnalysisError(f"--valence {t[:40]!r} is empty: give e.g. --valence 3..12")
    if min(vals) < 3 or max(vals) > MAX_VALENCE:
        raise AnalysisError(f"valences must lie in 3..{MAX_VALENCE}")
    return vals
