"""Claim kind "vertex": what a paper says about a surface scheme at extraordinary vertices of valence
A..B — C^1 at every valence, the subdominant eigenvalue in closed form in n, or Reif's eigen-conditions.

The scheme is one of the catalogue of ``subdiv vertex`` (``surface = "loop"``, ...) or user rules on the
regular stencils of Loop or Catmull–Clark (``lattice`` and ``centre``, optionally ``edge``: the same text
as ``subdiv vertex --lattice ... --centre ... --edge ...``). ``property`` is one of

* ``"C1"``: C^1 at every valence of the range, for generic initial data;
* ``"not C1"``: not C^1 at any valence of the range, for generic initial data;
* ``"eigen-conditions"``: Reif's eigen-conditions (1 simple; lambda double, real, positive, semisimple;
  every other eigenvalue strictly smaller in modulus) at every valence;
* ``"subdominant eigenvalue"`` with ``value = "EXPR"``: lambda(n) = EXPR at every valence, EXPR an
  expression in ``n``, ``c`` (= cos(2*pi/n)), ``pi`` and cos, read by :mod:`analysis.algebra.reader`.

Examples
--------
>>> v = Vertex({"surface": "loop", "valence": "3..5", "property": "subdominant eigenvalue",
...             "value": "3/8 + cos(2*pi/n)/4", "ring": 1}, {}, "x").evaluate()
>>> v.label
'CERTIFIED TRUE'
>>> v = Vertex({"surface": "loop", "valence": "3..5", "property": "subdominant eigenvalue",
...             "value": "3/8 + cos(2*pi/n)/8", "ring": 1}, {}, "x").evaluate()
>>> v.label, v.summary[:46]
('REFUTED', 'lambda(n) = 3/8 + cos(2*pi/n)/8 fails at n = 3')
>>> Vertex({"surface": "loop", "valence": "3..80", "property": "C1"}, {}, "x")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
analysis.result.AnalysisError: x: field 'valence' must be A..B with 3 <= A <= B <= 50 ...

Algorithm
---------
Each valence is analysed by :mod:`analysis.vertex.spectrum` (certified eigenvalues of the Fourier blocks
of the local subdivision matrix) and, for C^1, :func:`analysis.vertex.valence.vertex_results` (with the
certified characteristic map where the module has one). The verdicts:

* C^1: certified when C^1 is certified at every valence (eigen-conditions and a certified regular,
  injective characteristic map: Reif's sufficient condition); refuted at the first valence where "not C^1
  for generic initial data" is certified (:mod:`analysis.vertex.necessary`: a theorem whose hypotheses are
  all checked — for the butterfly at n = 3 and 8..50); inconclusive otherwise, with the reason of the
  first undecided valence (e.g. the butterfly's characteristic map, which is not certified).
* not C^1: certified when "not C^1" is certified at every valence, refuted at a valence where C^1 is
  certified, inconclusive otherwise.
* eigen-conditions: certified / refuted at the first valence where they certainly fail / inconclusive.
* subdominant eigenvalue: at each valence ``E = EXPR(n)`` is compared with lambda, a root of the exact
  factor ``F(lam, cos(2 pi/n))`` of block 1 isolated in an Arb ball: if E's Arb enclosure misses that
  ball, E != lambda; otherwise ``F(E)`` is decided exactly (its minimal polynomial over Q, sympy): zero
  and E's enclosure meeting no other root's ball gives E = lambda, nonzero gives E != lambda. When another
  block's eigenvalue is certified larger in modulus than block 1's leading one, lambda is that block's
  eigenvalue (:func:`analysis.vertex.spectrum.subdominant`: the largest modulus below 1, certified above
  every other but 1) and E is compared with it the same way (its factor at cos(2 pi k/n)); if it is not
  certified, the claim is inconclusive.

References
----------
U. Reif, A unified approach to subdivision algorithms near extraordinary vertices, CAGD 12 (1995);
D. Zorin, A method for analysis of C^1-continuity of subdivision surfaces, SIAM J. Numer. Anal. 37 (2000);
J. Peters, U. Reif, Subdivision Surfaces, Springer 2008, ch. 5.
"""

from __future__ import annotations

import re

import sympy as sp

from ...algebra.reader import read_expression
from ...result import CERTIFIED, REFUTED, AnalysisError, Result
from ..model import Number, Verdict
from .base import Kind, evidence

#: the largest valence a paper-file claim may ask for
MAX_CLAIM_VALENCE = 50
PROPERTIES = ("C1", "not C1", "eigen-conditions", "subdominant eigenvalue")
_RANGE = re.compile(r"\s*(\d{1,3})\s*(?:\.\.\s*(\d{1,3})\s*)?")


class Vertex(Kind):
    """A surface scheme at extraordinary vertices of valence A..B: C^1, eigen-conditions, or lambda(n)."""

    name = "vertex"
    summary = ("a surface scheme at extraordinary vertices of valence A..B: C^1, Reif's eigen-conditions, "
               "or the subdominant eigenvalue in closed form in n")
    uses_scheme = False
    required = {"valence": "the valences, \"A..B\" or one integer (3 <= A <= B <= 50)",
                "property": "\"C1\", \"not C1\", \"eigen-conditions\" or \"subdominant eigenvalue\""}
    optional = {"surface": "a scheme of `subdiv vertex`: loop, loop-warren, catmull-clark, doo-sabin, butterfly, "
                           "modified-butterfly, sqrt3",
                "lattice": "user rules instead of surface: triangle (Loop's regular stencils) or quad "
                           "(Catmull-Clark's)",
                "centre": "user rules: the centre's weights, as `subdiv vertex --centre`",
                "edge": "user rules: the rule of the edge points next to the centre, as `subdiv vertex --edge`",
                "value": "with property = \"subdominant eigenvalue\": lambda as an expression in n, "
                         "c = cos(2*pi/n), pi and cos",
                "ring": "rings of the local matrix (default: 2; the butterfly schemes 3)",
                "tension": "the butterfly schemes' tension w (default 1/16)"}
    example = ('surface = "loop"\nvalence = "3..5"\nproperty = "subdominant eigenvalue"\n'
               'value = "3/8 + cos(2*pi/n)/4"')

    def check(self) -> None:
        from ...vertex.rules import SCHEMES

        prop = self.get("property")
        if prop not in PROPERTIES:
            raise AnalysisError(f"{self.where}: field 'property' must be one of {', '.join(PROPERTIES)}, "
                                f"not {_show(prop)}")
        self.valences = self._valences()
        surface, lattice = self.get("surface"), self.get("lattice")
        if (surface is None) == (lattice is None):
            raise AnalysisError(f"{self.where}: give either surface = \"loop\" (a scheme of `subdiv vertex`) or "
                                "user rules (lattice = \"triangle\" and centre = \"...\"), not both or neither")
        if surface is not None and surface not in SCHEMES:
            raise AnalysisError(f"{self.where}: field 'surface' must be one of {', '.join(SCHEMES)}, "
                                f"not {_show(surface)}")
        if lattice is not None and self.get("centre") is None:
            raise AnalysisError(f"{self.where}: user rules need centre = \"...\" (e.g. centre = \"3/(8*n)\")")
        if surface is not None and (self.get("centre") is not None or self.get("edge") is not None):
            raise AnalysisError(f"{self.where}: centre and edge go with lattice (user rules), not with surface")
        ring = self.get("ring")
        if ring is not None and (isinstance(ring, bool) or ring not in (1, 2, 3)):
            raise AnalysisError(f"{self.where}: field 'ring' must be 1, 2 or 3, not {_show(ring)}")
        if (prop == "subdominant eigenvalue") != (self.get("value") is not None):
            raise AnalysisError(f"{self.where}: field 'value' goes with property = \"subdominant eigenvalue\" "
                                "(and that property needs it), e.g. value = \"3/8 + cos(2*pi/n)/4\"")
        self.expr = None
        if prop == "subdominant eigenvalue":
            from ...vertex.rules import n_sym

            text = self.get("value")
            if not isinstance(text, str):
                raise AnalysisError(f"{self.where}: field 'value' must be a formula as text, "
                                    "e.g. \"3/8 + cos(2*pi/n)/4\"")
            self.expr = read_expression(text, names={"n": n_sym, "c": sp.cos(2 * sp.pi / n_sym)}, free=False,
                                        what=f"{self.where}: field 'value'",
                                        hint="use n, c = cos(2*pi/n), pi and cos, e.g. \"3/8 + cos(2*pi/n)/4\"")
        for key in ("surface", "lattice", "centre", "edge", "tension"):
            if self.get(key) is not None and not isinstance(self.get(key), str):
                raise AnalysisError(f"{self.where}: field {key!r} must be text")
        self._rules(self.valences[0])           # every rule and weight is read now: a bad one fails at load

    def _valences(self) -> list[int]:
        v = self.get("valence")
        m = _RANGE.fullmatch(v) if isinstance(v, str) else None
        if isinstance(v, int) and not isinstance(v, bool):
            lo = hi = v
        elif m:
            lo, hi = int(m.group(1)), int(m.group(2) or m.group(1))
        else:
            lo = hi = -1
        if not 3 <= lo <= hi <= MAX_CLAIM_VALENCE:
            raise AnalysisError(f"{self.where}: field 'valence' must be A..B with 3 <= A <= B <= {MAX_CLAIM_VALENCE} "
                                f"(e.g. valence = \"3..12\"), not {_show(v)}")
        return list(range(lo, hi + 1))

    def _rules(self, n: int):
        from ...vertex.rules import scheme_rules, user_rules

        surface = self.get("surface")
        tension = None
        if self.get("tension") is not None:
            tension = read_expression(self.get("tension"), names={}, free=False, what=f"{self.where}: field 'tension'",
                                      hint="give a rational number, e.g. tension = \"1/16\"")
            if not tension.is_Rational:
                raise AnalysisError(f"{self.where}: field 'tension' must be a rational number, e.g. \"1/16\"")
        if surface is not None:
            ring = self.get("ring") or (3 if surface in ("butterfly", "modified-butterfly") else 2)
            return scheme_rules(surface, ring, n, tension)
        if tension is not None:
            raise AnalysisError(f"{self.where}: tension goes with the butterfly schemes only")
        return user_rules(self.get("lattice"), self.get("centre"), self.get("edge"), ring=self.get("ring") or 2)

    def scheme_text(self) -> str:
        if self.get("surface"):
            return self.get("surface")
        return f"user rules ({self.get('lattice')}, centre {self.get('centre')})"

    def span(self) -> str:
        vs = self.valences
        return f"n = {vs[0]}" if len(vs) == 1 else f"n = {vs[0]}..{vs[-1]}"

    # ------------------------------------------------------------------ evaluation
    def evaluate(self) -> Verdict:
        prop = self.get("property")
        if prop == "subdominant eigenvalue":
            return self._eigenvalue()
        if prop == "not C1":
            return self._not_c1()
        return self._conditions(c1=prop == "C1")

    def _not_c1(self) -> Verdict:
        """Not C^1 (for generic initial data) at every valence: certified where
        :func:`analysis.vertex.valence.vertex_results` refutes C^1 at each, refuted where it certifies C^1
        at one, inconclusive otherwise."""
        from ...vertex.valence import vertex_results

        rows, results = [], []
        for n in self.valences:
            rules = self._rules(n)
            rules.check_valence(n)
            r = vertex_results(rules, n)["c1"]
            verdict = r.witness.get("verdict") or ""
            if r.status == CERTIFIED and r.value is True:
                rows.append((str(n), "C^1", verdict))
                return self.refuted(f"{self.scheme_text()} is C^1 at n = {n}: {verdict}",
                                    corrected=f"{self.scheme_text()} is C^1 at n = {n} (generic initial data)",
                                    evidence=[evidence(f"C^1 at n = {n}", r, text=verdict), _table(rows)],
                                    numbers=[Number("first C^1 valence", sp.Integer(n))])
            if r.status != REFUTED:
                rows.append((str(n), "undecided", verdict))
                return self.inconclusive(f"not C^1 of {self.scheme_text()} not decided at n = {n}: {verdict}",
                                         settle="a not-C^1 theorem whose hypotheses are certified at this valence",
                                         evidence=[_table(rows)])
            rows.append((str(n), "not C^1", verdict))
            results.append(r)
        at = f"every valence {self.span()}" if len(self.valences) > 1 else self.span()
        return self.certified(f"{self.scheme_text()} is not C^1 (generic initial data) at {at}",
                              evidence=[evidence(f"not C^1 at {self.span()}", results[-1],
                                                 text=f"certified at each of {len(results)} valences"),
                                        _table(rows)])

    def _conditions(self, c1: bool) -> Verdict:
        from ...vertex.valence import vertex_results

        what = "C^1" if c1 else "Reif's eigen-conditions"
        rows, results, undecided = [], [], None
        for n in self.valences:
            rules = self._rules(n)
            rules.check_valence(n)
            res = vertex_results(rules, n) if c1 else _reif_only(rules, n)
            reif = res["reif"]
            if reif.status == CERTIFIED and reif.value is False:
                why = reif.witness["reason"]
                rows.append((str(n), "fails", why))
                ev = evidence(f"Reif's eigen-conditions at n = {n}", reif, text=why)
                if c1 and res["c1"].status == REFUTED:
                    verdict = res["c1"].witness["verdict"]
                    return self.refuted(
                        f"C^1 of {self.scheme_text()} fails at n = {n}: {verdict}",
                        corrected=f"{self.scheme_text()} is not C^1 at n = {n} for generic initial data",
                        evidence=[evidence(f"not C^1 at n = {n}", res["c1"], text=verdict), ev, _table(rows)],
                        numbers=[Number("first failing valence", sp.Integer(n))])
                if c1:
                    # the failure of an eigen-condition is certified, but "not C^1" needs a theorem whose
                    # hypotheses are checked (analysis.vertex.necessary); where none applies the claim stays
                    # undecided, as in `subdiv vertex`
                    return self.inconclusive(
                        f"C^1 of {self.scheme_text()} not decided at n = {n}: Reif's eigen-conditions fail, "
                        f"certified ({why}); Reif's sufficient test does not apply, and no not-C^1 theorem has "
                        f"all its hypotheses checked here ({res['c1'].witness['verdict']})",
                        settle="a certified proof that the limit surface is not C^1 at this valence (e.g. the "
                               "dominant block's map certified to cover the tangent plane twice)",
                        evidence=[ev, _table(rows)])
                return self.refuted(
                    f"Reif's eigen-conditions of {self.scheme_text()} fail at n = {n} ({why})",
                    corrected=f"Reif's eigen-conditions of {self.scheme_text()} fail at n = {n} ({why})",
                    evidence=[ev, _table(rows)], numbers=[Number("first failing valence", sp.Integer(n))])
            r = res["c1"] if c1 else reif
            ok = r.status == CERTIFIED and (r.value is True)
            rows.append((str(n), "holds" if ok else "undecided",
                         (r.witness.get("verdict") or "") if c1 else (r.witness.get("reason") or "")))
            if ok:
                results.append(r)
            elif undecided is None:
                undecided = (n, rows[-1][2] or "not decided")
        if undecided is None:
            return self.certified(f"{what} of {self.scheme_text()} certified at every valence {self.span()}",
                                  evidence=[evidence(f"{what} at {self.span()}", results[-1],
                                                     text=f"certified at each of {len(results)} valences"),
                                            _table(rows)])
        n, why = undecided
        return self.inconclusive(
            f"{what} of {self.scheme_text()} not decided at n = {n}: {why}",
            settle=("a certificate of the characteristic map at these valences (regular and injective)" if c1
                    else "higher precision in the eigenvalue isolation"),
            evidence=[_table(rows)])

    def _eigenvalue(self) -> Verdict:
        from ...vertex.rules import n_sym
        from ...vertex.spectrum import _exact_root, _siblings, analyse, subdominant

        rows, results = [], []
        shown = self.get("value")
        for n in self.valences:
            rules = self._rules(n)
            rules.check_valence(n)
            a = analyse(rules, n, curvature=False)
            if a.lam is None:
                return self.inconclusive(f"lambda(n) = {shown}: the eigenvalues are not isolated at n = {n}",
                                         settle="higher precision in the eigenvalue isolation",
                                         evidence=[_table(rows)])
            prov = {"method": "Fourier blocks of the local subdivision matrix; Arb isolation; exact comparison",
                    "valence": n, "rules": rules.source}
            sub, why = (a.lam, "") if not a.above_lambda else subdominant(a)
            if sub is None:      # another block dominates block 1 but its eigenvalue is not certified subdominant
                rows.append((str(n), "not decided", "undecided"))
                return self.inconclusive(f"lambda(n) = {shown} not decided at n = {n}: {why}",
                                         settle="higher precision in the eigenvalue isolation",
                                         evidence=[_table(rows)])
            equal, how = compare_lambda(self.expr, a, n, sub)
            exact = a.lam_exact if sub is a.lam else _exact_root(sub.factor, sub.ball, n, sub.k,
                                                                  _siblings(a.eigenvalues, sub))
            lam_text = sp.sstr(exact) if exact is not None else \
                f"root of {sp.sstr(sub.factor.as_expr())} near {float(sub.ball.real.mid()):.10f}"
            if sub is not a.lam:
                lam_text += f" (block {sub.k}: it exceeds block 1's leading eigenvalue)"
            if equal is False:
                rows.append((str(n), lam_text, "differs"))
                r = Result(value=False, status=REFUTED, witness={"lambda": lam_text, "claimed": sp.sstr(
                    self.expr.subs(n_sym, n)), "how": how}, provenance=prov)
                return self.refuted(f"lambda(n) = {shown} fails at n = {n}: lambda = {lam_text} ({how})",
                                    corrected=f"at n = {n} the subdominant eigenvalue is {lam_text}",
                                    evidence=[evidence(f"lambda at n = {n}", r, text=how), _table(rows)],
                                    numbers=[Number("first failing valence", sp.Integer(n))])
            rows.append((str(n), lam_text, "equal" if equal else "undecided"))
            if equal is None:
                return self.inconclusive(f"lambda(n) = {shown} not decided at n = {n}: {how}",
                                         settle="an expression the Arb evaluator handles (rationals, n, cos(q*pi), "
                                                "sqrt)", evidence=[_table(rows)])
            results.append(Result(value=True, status=CERTIFIED, witness={"lambda": lam_text, "how": how},
                                  provenance=prov))
        return self.certified(f"lambda(n) = {shown} for {self.scheme_text()} at every valence {self.span()}",
                              evidence=[evidence(f"lambda at {self.span()}", results[-1],
                                                 text=f"equal exactly at each of {len(results)} valences"),
                                        _table(rows)])


def _reif_only(rules, n: int) -> dict:
    from ...vertex.spectrum import analyse

    a = analyse(rules, n, curvature=False)
    return {"reif": Result(value=a.reif_ok, status=a.reif_status, witness={"reason": a.reif_reason},
                           provenance={"method": "Fourier blocks of the local subdivision matrix; Arb isolation",
                                       "valence": n, "rules": rules.source})}


def compare_lambda(expr: sp.Expr, a, n: int, e=None) -> tuple[bool | None, str]:
    """Is ``expr`` at valence n the subdominant eigenvalue ``a.lam`` (or ``e``, an eigenvalue of block
    ``e.k``)? (True / False / None: not decided, with how it was decided; see the module docstring).

    >>> from analysis.vertex.rules import scheme_rules, n_sym
    >>> from analysis.vertex.spectrum import analyse
    >>> a = analyse(scheme_rules("loop", 1, 7), 7, curvature=False)
    >>> compare_lambda(sp.Rational(3, 8) + sp.cos(2 * sp.pi / n_sym) / 4, a, 7)[0]
    True
    """
    from flint import acb

    from ...vertex.blocks import c, lam
    from ...vertex.rules import C1, n_sym
    from ...vertex.spectrum import _siblings, arb_value

    e = a.lam if e is None else e
    E = expr.subs(n_sym, n)
    if E.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        return False, f"the formula is undefined at n = {n}"
    enc = None
    for bits in (128, 512):
        enc = arb_value(E, n, bits)
        if enc is None:
            return None, "the formula is outside what the Arb evaluator encloses"
        if not e.ball.overlaps(acb(enc)):
            return False, f"its Arb enclosure {enc.str(10, radius=False)} misses lambda's isolating ball"
    meets = [s for s in _siblings(a.eigenvalues, e) if s.overlaps(acb(enc))]
    cos1, cosk = sp.cos(2 * sp.pi / n), sp.cos(2 * sp.pi * e.k / n)
    R = e.factor.as_expr().subs({lam: E, c: cosk, C1: cos1})
    R = sp.expand(R)
    x = sp.Dummy("x")
    zero = R == 0 or sp.minimal_polynomial(R, x) == x
    if not zero:
        return False, f"it is not a root of block {e.k}'s factor of lambda (exact minimal polynomial)"
    if len(meets) != 1:
        return None, "its enclosure meets more than one root's ball"
    return True, f"a root of block {e.k}'s factor (exact) in lambda's isolating ball and no other"


def _table(rows: list) -> object:
    return evidence("per valence", table=[("n", "value", "verdict")] + [tuple(r) for r in rows])


def _show(v) -> str:
    s = repr(v)
    return s if len(s) <= 40 else s[:37] + "..."
