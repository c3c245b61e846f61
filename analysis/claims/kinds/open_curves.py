"""Claim kinds about curves from open polygons and step data: "end rules" (a printed boundary
rule vs the one derived by ghost points) and "gibbs" (the Amat–Ruiz–Trillo conditions that exclude
Gibbs oscillations).

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> S = {"chaikin": SchemeSpec("chaikin", LaurentSymbol.from_mask(["1/4", "3/4", "3/4", "1/4"], start=-2))}
>>> EndRules({"point": "P2n", "printed": [["5/4", "n"], ["-1/4", "n-1"]]}, S, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = EndRules({"point": "P2n", "printed": [["1", "n"]]}, S, "x").evaluate()   # P_2n = (3 P_n + P_n+1)/4
>>> v.label, v.corrected                                                         # with P_n+1 = 2 P_n - P_n-1
('REFUTED', 'P2n^(k+1) = -P[n - 1]/4 + 5*P[n]/4')
>>> Gibbs({}, S, "x").evaluate().label                          # a nonnegative mask
'CERTIFIED TRUE'

Algorithm
---------
End rules: the scheme's rules ``P_{2i} = sum_p a_{-2p} P_{i+p}``, ``P_{2i+1} = sum_p a_{1-2p} P_{i+p}``
with the ghost points ``P_{-m} = 2 P_0 - P_m``, ``P_{n+m} = 2 P_n - P_{n-m}`` substituted
(:func:`analysis.algebra.linear_forms.end_rules`); printed coefficients whose minus signs were lost
are read with :func:`~analysis.algebra.linear_forms.read_garbled_linear` (both signs of the first
term; the one the derivation matches is taken, and said); with ``check_at`` the derived rule is
also compared with the engine's exact refinement of an open polygon
(:func:`analysis.stationary.refinement.refine`, ``end_rule="extrapolate"``).
Gibbs: ``zeta_l^[k](i)`` are the partial sums of the k-step mask ``a(z) a(z^2) ... a(z^(2^(k-1)))``
on the residue class ``l`` mod ``2^k`` (from the left for ``i < 0``, from the right for ``i > 0``);
Theorem 2.3 of seed 004 (Amat–Ruiz–Trillo) excludes Gibbs oscillations when all are ``>= 0`` for
every k. A nonnegative mask gives that for every k (products of nonnegative polynomials);
otherwise the exact parameter sets for ``k = 1 .. levels`` are given and the verdict is inconclusive
(the condition is only sufficient, and needed for every k).

References
----------
S. Amat, J. Ruiz, J. C. Trillo, *On the Gibbs phenomenon in subdivision*, quoted as Theorem 2.3
in seed 004 (2023); seed 004, Sect. 3.7, (3.9)-(3.10) (ghost points), Sect. 6.
"""

from __future__ import annotations

import sympy as sp

from ...algebra.algebraic import sign
from ...algebra.linear_forms import LinearForm, end_rules, read_garbled_linear
from ...algebra.symbol import parse_coefficient
from ...result import AnalysisError
from ..model import Evidence, Number, Verdict, contains_interval, exact_result, exact_set
from .base import Kind, evidence, interval_text
from .spectral import set_numbers
from ...algebra.reader import as_expr

__all__ = ["EndRules", "Gibbs", "zeta_conditions"]


def _label(point: str):
    """``"P3"`` -> (left, i = 1, eps = 1); ``"P2n-4"`` -> (right, r = -2, eps = 0)."""
    t = point.replace(" ", "")
    try:
        if not t.startswith("P"):
            raise ValueError(t)
        if t.startswith("P2n"):
            k = int(t[3:] or 0)
            return "right", k // 2, k % 2
        k = int(t[1:])
        if k >= 0:
            return "left", k // 2, k % 2
    except ValueError:
        pass
    raise AnalysisError(f"cannot read the point {point!r} (write \"P0\", \"P3\", \"P2n-4\", \"P2n+1\")")


def _offset(idx: str) -> int:
    t = str(idx).replace(" ", "")
    try:
        return int(t[1:] or 0) if t.startswith("n") else int(t)
    except ValueError:
        raise AnalysisError(f"cannot read the point index {idx!r} (write \"0\", \"3\", \"n\", \"n-3\")") from None


class EndRules(Kind):
    """A printed end rule of an open polygon vs the rule derived from the scheme by ghost points."""

    name = "end rules"
    summary = "a printed end rule of an open polygon vs the one derived by the ghost points P_-m = 2P_0 - P_m"
    required = {"point": "the new point: \"P0\", \"P1\", ..., \"P2n-4\", ..., \"P2n+1\"",
                "printed": "[[coefficient, index], ...]: index \"0\", \"1\", ... or \"n\", \"n-1\", ..."}
    optional = {"scale": "common factor of the printed coefficients (e.g. \"1/128\")",
                "garbled": "{ \"μ\" = \"mu\", ... }: coefficients lost their minus signs (both readings tried)",
                "check_at": "{ parameter = value }: also compare with the engine's refinement there"}
    example = 'point = "P1"\nprinted = [["1/2 - w", "0"], ["1/2 + 2*w", "1"], ["-w", "2"]]'

    def check(self) -> None:
        pr = self.get("printed")
        if not isinstance(pr, list) or not all(isinstance(x, list) and len(x) == 2 for x in pr):
            raise AnalysisError(f"{self.where}: field 'printed' is [[coefficient, index], ...]")
        try:
            self.side = _label(str(self.get("point")))
            self.offsets = [_offset(i) for _, i in pr]
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None
        self.scale = self.number("scale") or sp.Integer(1)
        g = self.get("garbled")
        names = {p.name for p in self.scheme.params}
        if g is not None and (not isinstance(g, dict) or not set(map(str, g.values())) <= names):
            raise AnalysisError(f"{self.where}: field 'garbled' is a table {{ letter = \"parameter\" }} over the "
                                f"parameters {', '.join(sorted(names))}")
        self.letters = {k: sp.Symbol(v) for k, v in (g or {}).items()}
        for text, _ in pr:                        # every printed coefficient must be readable now
            try:
                r = (read_garbled_linear(str(text), self.letters)[0] if self.letters else
                     parse_coefficient(text, locals_={p.name: p for p in self.scheme.params}))
            except (ValueError, AnalysisError) as exc:
                raise AnalysisError(f"{self.where}: cannot read the printed coefficient {text!r}: {exc}") from None
            extra = sorted({x.name for x in as_expr(r).free_symbols} - names)
            if extra:
                raise AnalysisError(f"{self.where}: unknown parameter {extra[0]!r} in the printed coefficient {text!r}")
        self.scheme.values(self.get("check_at"), self.where)

    def derived(self) -> LinearForm:
        a = self.symbol()
        even = LinearForm({p: a.coeff(-2 * p) for p in range(-a.end // 2 - 1, -a.start // 2 + 2)})
        odd = LinearForm({p: a.coeff(1 - 2 * p) for p in range((1 - a.end) // 2 - 1, (1 - a.start) // 2 + 2)})
        side, i, eps = self.side
        rules = end_rules(even, odd, left_ghosts=range(1, 12), right_ghosts=range(1, 12),
                          left_i=(i,) if side == "left" else (), right_i=(i,) if side == "right" else ())
        return rules[str(self.get("point")).replace(" ", "")]

    def reading(self, text, want):
        """Our reading of one printed coefficient (and whether the derivation matches it)."""
        if self.letters:
            plus, minus = (x * self.scale for x in read_garbled_linear(str(text), self.letters))
            for r in (plus, minus):
                if sp.expand(r - want) == 0:
                    return r, True
            return plus, False
        r = parse_coefficient(text, locals_={p.name: p for p in self.scheme.params}) * self.scale
        return r, sp.expand(r - want) == 0

    def evaluate(self) -> Verdict:
        d, point = self.derived(), str(self.get("point"))
        right = self.side[0] == "right"
        name = (lambda q: f"P_{'n' + (f'{q:+d}' if q else '')}") if right else (lambda q: f"P_{q}")
        s = 1 / self.scale
        rows, bad, total = [], [], sp.Integer(0)
        for (text, _), q in zip(self.get("printed"), self.offsets):
            r, ok = self.reading(text, d[q])
            total += r
            rows.append((name(q), str(text), sp.sstr(sp.expand(r * s)), sp.sstr(sp.expand(d[q] * s)), "yes" if ok else "NO"))
            if not ok:
                bad.append(rows[-1])
        for q, c in d.items():
            if q not in self.offsets:
                rows.append((name(q), "(missing)", "0", sp.sstr(sp.expand(c * s)), "NO"))
                bad.append(rows[-1])
        res = exact_result(not bad, "ghost points P_-m = 2P_0 - P_m, P_(n+m) = 2P_n - P_(n-m) substituted into the rules")
        ev = [Evidence("derived rule", result=res, text=f"{point}^(k+1) = {sp.sstr(d.to_expr())}",
                       latex="P_{" + point.replace(" ", "")[1:] + "}^{k+1} = " + d.latex()),
              evidence(f"printed coefficients vs derived (x {sp.sstr(s)})",
                       table=(("coefficient of", "printed", "our reading", "derived", "agree"), *rows)),
              evidence("affine invariance", text=f"sum of the derived coefficients = {sp.sstr(d.total())}; "
                                                 f"of the printed (as read) = {sp.sstr(sp.expand(total))}")]
        engine = self._engine_check(d, point) if self.get("check_at") else None
        if engine is not None:
            ev.append(engine[1])
        nums = [Number("derived_sum_of_coefficients", d.total())]
        if engine is not None and not engine[0]:
            return self.inconclusive("the derivation and the engine's refinement disagree", evidence=ev, numbers=nums,
                                     settle="find the bug in analysis.algebra.linear_forms or analysis.stationary.refinement")
        lost = " after restoring the lost minus signs" if self.letters else ""
        if not bad:
            return self.certified(f"The printed rule is the derived one{lost}.", evidence=ev, numbers=nums)
        printed_total = sp.expand(total)
        per = "" if s == 1 else f"/{sp.sstr(s)}" if s.is_Integer else f"*{sp.sstr(self.scale)}"
        return self.refuted(f"{len(bad)} printed coefficient(s) differ from the derivation: "
                            + "; ".join(f"{r[0]}: printed ({r[2]}){per}, derived ({r[3]}){per}" for r in bad)
                            + f". Printed coefficients (as read) sum to {sp.sstr(printed_total)}"
                            + ("" if sp.expand(printed_total - 1) == 0 else " (not 1: the printed rule does not even "
                                                                           "reproduce constants)") + ".",
                            corrected=f"{point}^(k+1) = {sp.sstr(d.to_expr())}", evidence=ev, numbers=nums)

    def _engine_check(self, d: LinearForm, point: str):
        import numpy as np
        from fractions import Fraction

        from ...stationary.refinement import refine
        vals = self.scheme.values(self.get("check_at"), self.where)
        data = [Fraction(v) for v in (3, -1, 4, 1, -5, 9, 2, -6, 5, 3, 5, 8)]
        n = len(data) - 1
        side, i, eps = self.side
        k = 2 * i + eps + (2 * n if side == "right" else 0)
        if not 0 <= k <= 2 * n - 1:
            return None
        out = refine(self.scheme.at(vals), np.array(data, dtype=object), 1, closed=False, end_rule="extrapolate", exact=True)
        f = d.subs({sp.Symbol(x): v for x, v in vals.items()})
        base = n if side == "right" else 0
        val = sum((sp.Rational(data[base + q].numerator, data[base + q].denominator) * c for q, c in f.items()), sp.Integer(0))
        eng = sp.Rational(out[k].numerator, out[k].denominator)
        at = ", ".join(f"{x} = {sp.sstr(v)}" for x, v in vals.items())
        return val == eng, evidence("engine cross-check (analysis.stationary.refinement.refine, end_rule='extrapolate')",
                                    exact_result(val == eng, "exact refinement"),
                                    text=f"at {at} on 12 rational points: the derived rule gives {sp.sstr(val)}, the "
                                         f"engine's point {k} is {sp.sstr(eng)}: {'equal' if val == eng else 'DIFFERENT'}")


def zeta_conditions(a, k: int) -> dict:
    """``{(l, i): zeta_l^[k](i)}`` of the k-step mask (see the module docstring), for the ``i`` where
    it can be nonzero."""
    from ...stationary.difference import iterated_symbol

    ak = iterated_symbol(a, k) if k > 1 else a
    M, out = 2 ** k, {}
    for l in range(M):
        taus = {(j - l) // M: c for j, c in ak.items() if (j - l) % M == 0}
        if not taus:
            continue
        lo, hi = min(taus), max(taus)
        for i in range(lo, 0):
            out[(l, i)] = sp.expand(sum((taus.get(t, 0) for t in range(lo, i + 1)), sp.Integer(0)))
        for i in range(1, hi + 1):
            out[(l, i)] = sp.expand(sum((taus.get(t, 0) for t in range(i, hi + 1)), sp.Integer(0)))
    return out


def _nonneg_set(exprs, p):
    exprs = list(exprs)
    polys = [sp.Poly(e, p) for e in exprs if e.free_symbols]
    return exact_set(lambda v: all(sign(as_expr(e).subs(p, v)) >= 0 for e in exprs), polys)


class Gibbs(Kind):
    """No Gibbs oscillation: the Amat–Ruiz–Trillo conditions ``zeta^[k] >= 0`` on the claimed set."""

    name = "gibbs"
    summary = "no Gibbs oscillation: zeta_l^[k](i) >= 0 for every level k (Amat-Ruiz-Trillo) on the claimed set or point"
    optional = {"interval": "claimed parameter set (e.g. \"[5/7, 7]\")", "at": "claimed parameter values",
                "levels": "levels k = 1 .. levels whose exact sets are shown (default 2)"}
    example = 'interval = "[-1/16, 0]"\nlevels = 1'

    def check(self) -> None:
        self.values(), self.interval("interval"), self.integer("levels", 1)
        free = len(self.symbol().params)
        if free > 1 or (free == 1) != ("interval" in self.fields):
            raise AnalysisError(f"{self.where}: kind 'gibbs' needs one free parameter with 'interval', or 'at' "
                                f"fixing every parameter ({free} free)")

    def evaluate(self) -> Verdict:
        a = self.symbol()
        levels = self.get("levels", 2)
        whole = self.scheme.symbol
        p = a.params[0] if len(a.params) == 1 else (whole.params[0] if len(whole.params) == 1 else None)
        ev, nums = [], []
        if a.params:
            lo, hi, lc, hc = self.interval("interval")
            claim = f"{p.name} in {interval_text(lo, hi, lc, hc)}"
            N = _nonneg_set(a.mask, p)
            positive = contains_interval(N, lo, hi, closed=lc or hc)
            ev.append(evidence("exact set where the mask is nonnegative", exact_result(N, "exact_set"), text=str(N)))
        else:
            claim = self.where_text()
            positive = all(sign(c) >= 0 for c in a.mask)
            ev.append(evidence(f"the mask of {claim}", exact_result(positive, "exact signs of the mask"),
                               text=f"{[sp.sstr(c) for c in a.mask]}: " + ("nonnegative" if positive else "has negative entries")))
        sets = {}
        if p is not None:
            for k in range(1, levels + 1):
                z = zeta_conditions(whole if not a.params else a, k)
                sets[k] = _nonneg_set(z.values(), p)
                nums += set_numbers(f"k{k}_set", sets[k])
            ev.append(evidence(f"exact {p.name}-sets where all zeta^[k] >= 0",
                               exact_result(sets[levels], "exact_set"),
                               text="; ".join(f"k = {k}: {s}" for k, s in sets.items())))
        figs = [self.figure(a, lo, hi) if a.params else self.figure(a)]
        if positive:
            return self.certified(f"True: for {claim} the mask is nonnegative, so every k-step mask is a product of "
                                  "nonnegative polynomials and all zeta^[k] >= 0 for every level k.",
                                  evidence=ev, numbers=nums,
                                  sharpness=(f"the level-1 conditions hold on {sets[1]} (all levels would still need "
                                             "checking there)") if sets else None, figures=figs)
        if not sets:
            return self.inconclusive(f"the mask of {claim} has negative entries: the conditions need every level k",
                                     settle="the conditions zeta^[k] >= 0 for every k", evidence=ev, figures=figs)
        inside = [k for k, s in sets.items() if not contains_interval(s, lo, hi, closed=lc or hc)]
        return self.inconclusive(
            f"The level-1 conditions hold exactly for {p.name} in {sets[1]}; Theorem 2.3 (as quoted) needs them for every "
            "level k: " + "; ".join(f"k = {k} gives {s}" for k, s in sets.items() if k > 1)
            + (f" — smaller than the printed range at k = {inside[0]}" if inside else "")
            + ". Gibbs-freeness on the range is therefore not established by this sufficient condition.",
            settle="the conditions for every k (an induction, or a lemma reducing to k = 1), or a direct analysis of "
                   "the limit of the step data", evidence=ev, numbers=nums,
            sharpness=f"level 1 exact set {sets[1]}; every level holds where the mask is nonnegative: {N}",
            figures=figs)

    def figure(self, a, lo=None, hi=None):
        """Step data refined by the claimed member, or by the ends and the middle of the claimed set."""
        from .plots import step_figure

        if lo is None:
            members = [(self.where_text(), a)]
        else:
            p = a.params[0]
            members = [(f"{p.name} = {sp.sstr(v)}", a.subs({p: v})) for v in (lo, (lo + hi) / 2, hi)]
        return step_figure(f"gibbs-{self.scheme.name}", f"Step data refined by {self.scheme.name}", members)

