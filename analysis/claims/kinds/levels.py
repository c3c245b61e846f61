"""Claim kinds of level-dependent schemes: weighted-series convergence, asymptotic equivalence,
exponential generation/reproduction.

A paper file defines a level-dependent scheme by ``level_mask`` (coefficients in the level ``n``
or ``h = 2^-n``) and ``start``; parameters with a domain in ``[0, oo)`` are declared positive.
With ``arity = M`` the scheme carries its arity, ``h = M^-n`` and the weights are ``M^(mn)``
(:func:`analysis.levels.series.weighted_series`, :func:`analysis.levels.reproduction.generation` /
``reproduction`` read it from the scheme).

Examples
--------
>>> import sympy as sp
>>> from analysis.levels.level_dependent import H, LevelDependentScheme
>>> from analysis.claims.kinds.base import SchemeSpec
>>> t = sp.Symbol("t", positive=True)
>>> v = sp.cosh(t * H / 2)
>>> z = sp.Symbol("z")
>>> c = sp.Poly(sp.expand((1 + z) * (1 + 2 * v * z + z**2)), z).all_coeffs()[::-1]
>>> s = LevelDependentScheme(tuple(sp.simplify(x / (2 * (1 + v))) for x in c), -2, (t,))
>>> S = {"e": SchemeSpec("e", None, level=s)}
>>> ExponentialReproduction({"lambdas": ["0", "t", "-t"], "at": {"t": 1}}, S, "x").evaluate().label
'CERTIFIED TRUE'
>>> AsymptoticEquivalence({"converges": True, "at": {"t": 1}}, S, "x").evaluate().label
'CERTIFIED TRUE'

Algorithm
---------
:func:`analysis.levels.series.weighted_series` (Arb partial sums and a Cauchy-estimate Taylor
tail) and :func:`analysis.levels.reproduction.generation` / ``reproduction`` (exact identities in
``h``, certified nonzero values by acb balls).

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*, J. Math.
Anal. Appl. 193 (1995) 594-621.
"""

from __future__ import annotations

import sympy as sp

from ...levels.reproduction import generation, reproduction
from ...levels.leading_term import series_by_leading_term
from ...levels.series import weighted_series
from ...result import CERTIFIED, AnalysisError
from ..model import Number, Verdict
from ...algebra.reader import read_in_context
from .base import Kind, evidence, parse_interval, parse_number

__all__ = ["WeightedSeries", "AsymptoticEquivalence", "ExponentialReproduction"]


class _LevelKind(Kind):
    level_scheme = True
    #: m-ary level-dependent schemes (``arity = M``, ``h = M^-n``) are evaluated by the m-ary engine
    any_arity = True

    def level(self):
        if self.scheme.level is None:
            raise AnalysisError(f"{self.where}: kind {self.name!r} needs a level-dependent scheme (level_mask)")
        return self.scheme.level

    def level_values(self) -> dict:
        """``at``: exact values or closed boxes ``"[lo, hi]"`` per parameter."""
        names = {p.name for p in self.scheme.params}
        out = {}
        for k, v in (self.get("at") or {}).items():
            if k not in names:
                raise AnalysisError(f"{self.where}: unknown parameter {k!r} of scheme {self.scheme.name!r}")
            if isinstance(v, str) and v.strip()[:1] in "([":
                lo, hi, _, _ = parse_interval(v, f"{self.where}: at {k}")
                out[k] = (lo, hi)
            else:
                out[k] = parse_number(v, f"{self.where}: at {k}")
        return out

    def check(self) -> None:
        self.level()
        self.level_values()


class WeightedSeries(_LevelKind):
    """``sum_n 2^(m n) ||S_(a^n) - S_a||_inf`` converges (or diverges), certified."""

    name = "weighted series"
    summary = "sum_n 2^(mn) ||S_(a^n) - S_a|| converges/diverges (Arb partial sum + Taylor tail)"
    required = {"converges": "true or false"}
    optional = {"m": "weight exponent (default 0)", "difference": "analyse the k-th difference scheme",
                "at": "parameter values or boxes \"[lo, hi]\""}
    example = 'converges = true\nm = 1\nat = { t = 1 }'
    fixed_m: int | None = None

    def check(self) -> None:
        super().check()
        self.integer("m"), self.integer("difference")
        self.boolean("converges")

    def evaluate(self) -> Verdict:
        m = self.fixed_m if self.fixed_m is not None else self.get("m", 0)
        M = self.arity
        d = self.get("difference", 0)
        if M == 2:
            r = weighted_series(self.level(), self.level_values(), m, difference=d)
        else:                        # the m-ary witness layout (series_by_leading_term)
            r = series_by_leading_term(self.level(), self.level_values(), m, difference=d)
        what = f"sum_n {M}^({m}n) ||S_(a^n) - S_a||" if m else "sum_n ||S_(a^n) - S_a|| (asymptotic equivalence)"
        if d and M != 2:            # (binary summaries unchanged)
            what += f" of the divided difference scheme of order {d}"
        verdict = r.witness.get("verdict")
        if r.status != CERTIFIED:
            return self.inconclusive(f"{what}: not decided", settle=r.witness.get("advice", "split the box"),
                                     evidence=[evidence(what, text=str(r.witness.get("per_box") or
                                                                       r.witness.get("reason")))])
        conv = verdict == "convergent"
        text = (f"converges, sum in [{float(r.lower):.6g}, {float(r.upper):.6g}]" if conv
                else f"diverges ({r.witness.get('statement')})")
        nums = [Number("converges", conv)] + ([Number("sum", float((r.lower + r.upper) / 2),
                                                      tol=max(1e-9, float(r.upper - r.lower)), lower=r.lower, upper=r.upper)]
                                              if conv else [])
        ev = [evidence(what, r, text=text)]
        if conv == self.get("converges"):
            return self.certified(f"{what} {text}", evidence=ev, numbers=nums)
        return self.refuted(f"{what} {text}", corrected=f"{what} {'converges' if conv else 'diverges'}",
                            evidence=ev, numbers=nums)


class AsymptoticEquivalence(WeightedSeries):
    """``S_(a^n)`` is asymptotically equivalent to its limit ``S_a`` (the weighted series with m = 0)."""

    name = "asymptotic equivalence"
    summary = "sum_n ||S_(a^n) - S_a|| < oo (Dyn-Levin asymptotic equivalence)"
    optional = {"difference": WeightedSeries.optional["difference"], "at": WeightedSeries.optional["at"]}
    example = 'converges = true\nat = { t = 1 }'
    fixed_m = 0


class ExponentialReproduction(_LevelKind):
    """Every level generates (and, with ``reproduction = true``, reproduces) ``e^(lambda x)``."""

    name = "exponential reproduction"
    summary = "every level generates / reproduces e^(lambda x) for the given lambdas (exact in h)"
    required = {"lambdas": "list of lambda (\"t\", \"-t\", \"I*t\", \"0\")"}
    optional = {"reproduction": "true: reproduction, not only generation", "holds": "claimed (default true)",
                "at": "parameter values"}
    example = 'lambdas = ["0", "t", "-t"]\nat = { t = 1 }'

    def check(self) -> None:
        super().check()
        self.lambdas()                               # bad text fails when the file is loaded

    def lambdas(self) -> list:
        loc = {p.name: p for p in self.level().params}
        if not isinstance(self.get("lambdas"), list):
            raise AnalysisError(f"{self.where}: field 'lambdas' is a list, e.g. [\"0\", \"t\", \"-t\"]")
        try:
            return [read_in_context(x, loc, what="lambda", free=True) for x in self.get("lambdas")]
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None

    def evaluate(self) -> Verdict:
        s = self.level()
        lams = self.lambdas()
        vals = self.level_values()
        fn = reproduction if self.get("reproduction") else generation
        r = fn(s, lams, vals or None)
        what = f"{'reproduction' if self.get('reproduction') else 'generation'} of e^(lambda x), lambda in {self.get('lambdas')}"
        want = self.get("holds", True)
        if r.value is None:
            return self.inconclusive(f"{what}: not decided", settle="an exact zero proof or a certified nonzero value",
                                     evidence=[evidence(what, text=str(r.witness.get("statement")))])
        ev = [evidence(what, r, text=str(r.witness.get("statement", r.witness.get("conditions", ""))))]
        nums = [Number("holds", bool(r.value))]
        if bool(r.value) == want:
            return self.certified(f"{what}: {'holds' if r.value else 'fails'} at every level", evidence=ev, numbers=nums)
        return self.refuted(f"{what}: {'holds' if r.value else 'fails'}",
                            corrected=f"{what} {'holds' if r.value else 'fails'}", evidence=ev, numbers=nums)
