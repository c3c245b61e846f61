"""Claim kinds decided by exact algebra on the symbol: mask identity, sum rules and smoothing
factors, symmetry, interpolation (``a_(mj) = delta_(j,0)``), support, local-matrix eigenvalues,
polynomial generation/reproduction.

Examples
--------
>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> from analysis.claims.kinds.base import SchemeSpec
>>> w = sp.Symbol("w")
>>> four = LaurentSymbol.from_mask([-w, 0, sp.Rational(1, 2) + w, 1, sp.Rational(1, 2) + w, 0, -w], start=-3)
>>> S = {"4pt": SchemeSpec("4pt", four)}
>>> SumRules({"factors": 2, "exceptional": [{"at": {"w": "1/16"}, "factors": 4}]}, S, "x").evaluate().label
'CERTIFIED TRUE'
>>> v = SumRules({"factors": 3}, S, "x").evaluate()
>>> v.label, v.corrected
('REFUTED', 'a(z) = ((1+z)/2)^2 b(z) for generic parameters (sum rules of order 2); exceptional: w = 1/16: 4 factors')

Algorithm
---------
Exact synthetic division by ``(1+z)`` (:func:`analysis.algebra.factorization.smoothing_factor`),
exact coefficient comparison, the exact characteristic polynomial of the local subdivision
matrix (:func:`analysis.stationary.transition.local_eigenvalues`), Conti–Hormann derivative
conditions (:func:`analysis.algebra.factorization.polynomial_reproduction`).

References
----------
N. Dyn, D. Levin, *Subdivision schemes in geometric modelling*, Acta Numer. 11 (2002).
C. Conti, K. Hormann, *Polynomial reproduction for univariate subdivision schemes of any arity*,
J. Approx. Theory 163 (2011) 413-437.
"""

from __future__ import annotations

import sympy as sp

from ...algebra.factorization import polynomial_generation, polynomial_reproduction, smoothing_factor, sum_rules, symmetry
from ...algebra.symbol import LaurentSymbol
from ...result import AnalysisError
from ...stationary.transition import basic_limit_support, local_eigenvalues
from ..model import Number, Verdict, exact_result
from .base import Kind, evidence, parse_number, rules_symbol
from ...algebra.reader import as_expr, read_in_context

__all__ = ["MaskIdentity", "SumRules", "Symmetry", "Interpolatory", "Support", "Eigenvalues", "Reproduction"]


def _same(x, y) -> bool:
    return sp.simplify(as_expr(x) - as_expr(y)) == 0


def _cond_text(cond) -> str:
    return ", ".join(f"{k} = {sp.sstr(v)}" for k, v in cond.items())


class MaskIdentity(Kind):
    """The printed mask (or rules, or symbol, or another scheme) equals the constructed one."""

    name = "mask identity"
    summary = "the printed mask/rules/symbol equals the scheme's symbol (exact coefficients)"
    optional = {"mask": "printed coefficients (with start)", "start": "index of the first coefficient",
                "symbol": "printed symbol a(z)",
                "rules": "{even = [...], odd = [...], first = p} or {stencils = [[...], ...], first = p} (M-ary)",
                "same_as": "another scheme of the file", "at": "parameter values",
                "substitute": "{ parameter = \"expression\" }: a sub-family (e.g. nu = \"1 - 2*mu\")"}
    example = 'mask = ["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"]\nstart = -3\nat = { w = "1/16" }'
    any_arity = True

    def check(self) -> None:
        given = [k for k in ("mask", "symbol", "rules", "same_as") if k in self.fields]
        if len(given) != 1:
            raise AnalysisError(f"{self.where}: kind 'mask identity' needs exactly one of the fields "
                                "'mask', 'symbol', 'rules', 'same_as'")
        self.values()
        self.substitution()
        self.printed()

    def substitution(self) -> dict:
        """``substitute``: parameters replaced by expressions in the others (exact)."""
        sub = self.get("substitute", {})
        names = {p.name: p for p in self.scheme.params}
        if not isinstance(sub, dict) or set(sub) - set(names):
            raise AnalysisError(f"{self.where}: 'substitute' is {{ parameter = \"expression\" }} over the "
                                f"parameters {', '.join(sorted(names))}")
        try:
            return {names[k]: read_in_context(v, names, what=f"substitute {k}", free=True) for k, v in sub.items()}
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None

    def printed(self) -> tuple[LaurentSymbol, str]:
        f = self.fields
        try:
            if "mask" in f:
                return LaurentSymbol.from_mask(f["mask"], start=f.get("start", 0)), "the printed mask"
            if "symbol" in f:
                return LaurentSymbol.from_expr(f["symbol"]), "the printed symbol"
            if "rules" in f:
                a, m, _ = rules_symbol(f["rules"])
                if m != self.arity:
                    raise AnalysisError(f"the printed rules have {m} stencils, but scheme {self.scheme.name!r} has "
                                        f"arity {self.arity}: give {self.arity} stencils, rules = {{ stencils = [...] }}")
                return a, "the printed rules"
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None
        other = self.schemes.get(f["same_as"])
        if other is None:
            raise AnalysisError(f"{self.where}: unknown scheme {f['same_as']!r} in 'same_as' "
                                f"(the file defines: {', '.join(sorted(self.schemes))})")
        return other.at(self.values() if other.params == self.scheme.params else {}), f"scheme {f['same_as']!r}"

    def evaluate(self) -> Verdict:
        printed, what = self.printed()
        sub = self.substitution()
        built = self.symbol().subs(sub) if sub else self.symbol()
        lo, hi = min(printed.start, built.start), max(printed.end, built.end)
        diff = [(i, printed.coeff(i), built.coeff(i)) for i in range(lo, hi + 1) if not _same(printed.coeff(i), built.coeff(i))]
        r = exact_result(not diff, "exact coefficient comparison", printed=printed, constructed=built)
        where = self.where_text() + (" with " + _cond_text(sub) if sub else "")
        ev = [evidence(f"{what} vs the constructed symbol of {where}", r,
                       text=f"constructed: {built.mask} from index {built.start}")]
        if not diff:
            return self.certified(f"{what} is the symbol of {where} (exact)", evidence=ev,
                                  numbers=[Number("support length", len(built.mask))])
        first = ", ".join(f"a_{i}: printed {sp.sstr(p)}, constructed {sp.sstr(c)}" for i, p, c in diff[:3])
        return self.refuted(f"{what} differs from the constructed symbol in {len(diff)} coefficient(s) ({first})",
                            corrected=f"the mask is {list(map(sp.sstr, built.mask))} from index {built.start}",
                            evidence=ev, numbers=[Number("differing coefficients", len(diff))])


class SumRules(Kind):
    """The number of smoothing factors ``k`` in ``a(z) = ((1+z)/2)^k b(z)``, with exceptional values."""

    name = "sum rules"
    summary = "a(z) = ((1+z)/2)^k b(z) with k factors (sum rules of order k), exceptional parameter values"
    required = {"factors": "claimed k (generic)"}
    optional = {"exceptional": "[{ at = {...}, factors = k }] claimed exceptional values", "at": "parameter values",
                "at_least": "true: the claim is k or more factors (e.g. a(1) = 2, a(-1) = 0 is at least 1)"}
    example = 'factors = 2\nexceptional = [{ at = { w = "1/16" }, factors = 4 }]'
    any_arity = True
    bivariate = True              # factors = the order of the sum rules (analysis.claims.kinds.bivariate)

    def check(self) -> None:
        self.integer("factors")
        self.values()
        for e in self.get("exceptional", []):
            if not isinstance(e, dict) or set(e) != {"at", "factors"}:
                raise AnalysisError(f"{self.where}: each exceptional entry is {{ at = {{...}}, factors = k }}")
            self.scheme.values(e["at"], self.where)

    def evaluate(self) -> Verdict:
        if self.scheme.bivariate is not None:
            from .bivariate import sum_rules_verdict

            return sum_rules_verdict(self)
        a, m = self.symbol(), self.arity
        f = smoothing_factor(a, arity=m)
        sr = sum_rules(a, arity=m)
        k, found = f.value, f.witness["exceptional"]
        exc_text = "; ".join(f"{_cond_text(e['condition'])}: {e['k']} factors" for e in found) or "none"
        if m == 2:
            ev = [evidence("exact division by (1+z)", f, text=f"{f.witness['identity']}; exceptional: {exc_text}"),
                  evidence("a(1) = 2 and a(-1) = 0", sr, text=f"a(1) = {sp.sstr(sr.witness['a(1)'])}, "
                                                              f"a(-1) = {sp.sstr(sr.witness['a(-1)'])}")]
        else:
            ev = [evidence(f"exact division by 1+...+z^{m - 1}", f, text=f"{f.witness['identity']}; exceptional: {exc_text}"),
                  evidence(f"a(1) = {m} and a(eps) = 0 at the other {m}-th roots of unity", sr,
                           text=f"residue sums {', '.join(map(sp.sstr, sr.witness['residue_sums']))}"
                                + (f"; fails: {'; '.join(sr.witness['failures'])}" if sr.witness["failures"] else ""))]
        wrong = []
        if (k < self.get("factors")) if self.get("at_least") else (self.get("factors") != k):
            wrong.append(f"generic k = {k}, not {'at least ' if self.get('at_least') else ''}{self.get('factors')}")
        for e in self.get("exceptional", []):
            vals = self.scheme.values(e["at"], self.where)
            hit = [x for x in found if set(map(str, x["condition"])) == set(vals)
                   and all(_same(x["condition"][s], vals[str(s)]) for s in x["condition"])]
            kk = hit[0]["k"] if hit else smoothing_factor(a.subs(vals), exceptional=False, arity=m).value
            if kk != e["factors"]:
                wrong.append(f"at {_cond_text(vals)}: k = {kk}, not {e['factors']}")
        nums = [Number("factors", k), Number("exceptional values", len(found))]
        q = "(1+z)/2" if m == 2 else f"(1+...+z^{m - 1})/{m}"
        corrected = f"a(z) = ({q})^{k} b(z) for generic parameters (sum rules of order {k}); exceptional: {exc_text}"
        if wrong:
            return self.refuted("; ".join(wrong), corrected=corrected, evidence=ev, numbers=nums)
        claimed = len(self.get("exceptional", []))
        sharp = None if claimed == len(found) else f"complete list of exceptional values: {exc_text}"
        return self.certified(f"{k} smoothing factors for {self.where_text() or 'generic parameters'}"
                              + (f"; exceptional: {exc_text}" if found else ""), evidence=ev, numbers=nums,
                              sharpness=sharp)


class Symmetry(Kind):
    """The mask is symmetric (``a_i = a_{c-i}``), optionally about a given centre ``c/2``."""

    name = "symmetry"
    summary = "the mask is symmetric (a_i = a_(c-i)), optionally about the given centre"
    optional = {"symmetric": "true (default) or false", "centre": "claimed centre c/2 (our indexing)",
                "at": "parameter values"}
    example = "symmetric = true\ncentre = 0"
    any_arity = True

    def check(self) -> None:
        self.values()
        self.number("centre")
        self.boolean("symmetric", True)

    def evaluate(self) -> Verdict:
        r = symmetry(self.symbol(), arity=self.arity)
        want, centre = self.get("symmetric", True), self.number("centre")
        ev = [evidence("exact comparison a_i = a_(start+end-i)", r,
                       text=f"centre {sp.sstr(r.witness['centre'])} ({r.witness['kind']})")]
        ok = r.value == want and (centre is None or not r.value or _same(centre, r.witness["centre"]))
        nums = [Number("symmetric", bool(r.value)), Number("centre", r.witness["centre"])]
        fact = (f"symmetric about {sp.sstr(r.witness['centre'])} ({r.witness['kind']})" if r.value
                else "not symmetric" + (f" (symmetric only at {r.witness.get('solutions')})" if r.witness.get("solutions") else ""))
        if ok:
            return self.certified(f"the mask of {self.where_text()} is {fact}", evidence=ev, numbers=nums)
        return self.refuted(f"the mask of {self.where_text()} is {fact}", corrected=f"the mask is {fact}",
                            evidence=ev, numbers=nums)


class Interpolatory(Kind):
    """The scheme is interpolatory: ``a_(m j) = delta_(j,0)`` (``f[m i] = f[i]``), exactly, with parameters."""

    name = "interpolatory"
    summary = ("the scheme is interpolatory, a_(mj) = delta_(j,0) for arity m (f[mi] = f[i]); exact, with parameters; "
               "holds = false for 'not interpolatory'")
    optional = {"holds": "true (default): interpolatory for every parameter value; false: for none",
                "at": "parameter values"}
    example = "holds = true"
    any_arity = True

    def check(self) -> None:
        self.values()
        self.boolean("holds", True)

    def _conditions(self, a: LaurentSymbol) -> list[tuple[int, sp.Expr, sp.Expr]]:
        """``(i, a_i, a_i - delta_(i,0))`` for every index ``i = m j`` of the support and ``i = 0``."""
        m = self.arity
        idx = sorted({i for i in range(a.start, a.end + 1) if i % m == 0} | {0})
        return [(i, a.coeff(i), sp.expand(a.coeff(i) - (1 if i == 0 else 0))) for i in idx]

    def _solutions(self, bad: list, params: list) -> tuple[list | None, str]:
        """The parameter values (in their domains) where every condition holds, exactly; None if unsolved."""
        try:
            sols = sp.solve([e for _, _, e in bad], params, dict=True)
        except (NotImplementedError, ValueError, TypeError):
            return None, "sympy could not solve the conditions"
        out = []
        for sol in sols:
            if any(not as_expr(v).is_real for v in sol.values() if not as_expr(v).free_symbols):
                continue
            ok = True
            for p, v in sol.items():
                dom = self.scheme.domains.get(p.name)
                if dom is not None and not as_expr(v).free_symbols and not dom.contains(v):
                    ok = False
            if ok:
                out.append(sol)
        text = "; ".join(", ".join(f"{p} = {sp.sstr(v)}" for p, v in sol.items()) for sol in out) or "no parameter value"
        return out, text

    def _shift_note(self, a: LaurentSymbol) -> str:
        """When some residue class is a shifted Kronecker delta: the re-indexing that makes the mask interpolatory."""
        m = self.arity
        for r in range(m):
            nz = [(i, c) for i, c in a.items() if i % m == r and sp.expand(c) != 0]
            if len(nz) == 1 and sp.expand(nz[0][1] - 1) == 0 and nz[0][0] != 0:
                d = nz[0][0]
                return (f" (the mask is a shifted interpolatory mask: a_{d} = 1 is the only nonzero a_({d} + {m}j); "
                        f"with the indices shifted by {-d} (start {a.start - d}) it is interpolatory)")
        return ""

    def evaluate(self) -> Verdict:
        a, m = self.symbol(), self.arity
        want = self.boolean("holds", True)
        conds = self._conditions(a)
        bad = [c for c in conds if c[2] != 0]
        where = self.where_text()
        show = ", ".join(f"a_{i} = {sp.sstr(c)}" for i, c, _ in conds[:8]) + (", ..." if len(conds) > 8 else "")
        r = exact_result(not bad, f"exact coefficients a_({m}j), j in Z", conditions=[(i, c) for i, c, _ in conds])
        ev = [evidence(f"the coefficients a_({m}j) of {where}", r, text=show)]
        rule = f"a_({m}j) = delta_(j,0)" + (" (f[2i] = f[i])" if m == 2 else f" (f[{m}i] = f[i])")
        if not bad:
            fact = f"{where} is interpolatory: {rule}" + (" for every parameter value" if a.params else "")
            if want:
                return self.certified(fact + " (exact)", evidence=ev, numbers=[Number("interpolatory", True)])
            return self.refuted(fact + " (exact)", corrected=fact, evidence=ev, numbers=[Number("interpolatory", True)])
        i0, c0, _ = bad[0]
        offending = f"a_{i0} = {sp.sstr(c0)}, not {1 if i0 == 0 else 0}"
        params = list(a.params)
        constant = [c for c in bad if not c[2].free_symbols]
        if not params or constant:
            if constant:
                i0, c0, _ = constant[0]
                offending = f"a_{i0} = {sp.sstr(c0)}, not {1 if i0 == 0 else 0}"
            fact = f"{where} is not interpolatory: {offending}" + (" for every parameter value" if params else "")
            nums = [Number("interpolatory", False), Number("offending index", i0)]
            if want:
                return self.refuted(fact + self._shift_note(a), corrected=f"not interpolatory ({offending}){self._shift_note(a)}",
                                    evidence=ev, numbers=nums)
            return self.certified(fact, evidence=ev, numbers=nums)
        sols, where_text = self._solutions(bad, params)
        nums = [Number("interpolatory", False), Number("offending index", i0)]
        if want:
            return self.refuted(f"{where} is not interpolatory for every parameter value: {offending}",
                                corrected=f"interpolatory exactly for {where_text}" if sols is not None else
                                f"{rule} fails: {offending}", evidence=ev, numbers=nums,
                                sharpness=None if sols is None else f"interpolatory exactly for {where_text}")
        if sols is None:
            return self.inconclusive(f"{offending}; where the conditions hold was not decided ({where_text})",
                                     settle="solve the conditions a_(mj) = delta_(j,0) in the parameters", evidence=ev,
                                     numbers=nums)
        if sols:
            return self.refuted(f"{where} is interpolatory for {where_text}", corrected=f"interpolatory exactly for {where_text}",
                                evidence=ev, numbers=[Number("interpolatory", "at " + where_text), Number("offending index", i0)])
        return self.certified(f"{where} is not interpolatory for any parameter value in its domain: {offending}",
                              evidence=ev, numbers=nums)


class Support(Kind):
    """The support of the mask or of the basic limit function (our indexing, or centred)."""

    name = "support"
    summary = "support [s, e] of the mask or of the basic limit function (our indexing or centred)"
    required = {"support": "[s, e]"}
    optional = {"of": "'mask' (default), 'limit function' or 'limit function, centred'", "at": "parameter values",
                "plot": "[{ parameter = value }, ...]: members whose basic limit functions the report draws"}
    example = 'support = [-3, 3]\nof = "limit function"'
    any_arity = True

    OF = ("mask", "limit function", "limit function, centred")

    def check(self) -> None:
        self.values()
        if self.get("of", "mask") not in self.OF:
            raise AnalysisError(f"{self.where}: field 'of' must be one of {', '.join(self.OF)}")
        s = self.get("support")
        if not isinstance(s, list) or len(s) != 2:
            raise AnalysisError(f"{self.where}: field 'support' must be [s, e]")
        [parse_number(x, f"{self.where}: support") for x in s]
        if not isinstance(self.get("plot", []), list):
            raise AnalysisError(f"{self.where}: field 'plot' is a list of parameter tables [{{ w = \"1/16\" }}, ...]")
        [self.scheme.values(v, self.where) for v in self.get("plot", [])]

    def evaluate(self) -> Verdict:
        a = self.symbol()
        of = self.get("of", "mask")
        r = basic_limit_support(a, arity=self.arity)
        true = r.witness["centred"] if of.endswith("centred") else r.value
        if of == "mask":
            true = (a.start, a.end)
        claim = tuple(parse_number(x) for x in self.get("support"))
        ok = all(_same(x, y) for x, y in zip(claim, true))
        text = f"[{sp.sstr(true[0])}, {sp.sstr(true[1])}]"
        ev = [evidence(f"support of the {of}", r, text=text)]
        nums = [Number("support start", true[0]), Number("support end", true[1])]
        figs = []
        if self.get("plot") and self.arity == 2:  # pictures of the basic limit functions (issue 11, seed 004)
            from .plots import limit_function_figure

            members = [self.scheme.values(v, self.where) for v in self.get("plot")]
            figs = [limit_function_figure(f"blf-{self.scheme.name}", f"Basic limit functions of {self.scheme.name}",
                                          [(_cond_text(v), a.subs(v)) for v in members])]
        if ok:
            return self.certified(f"the {of} of {self.where_text()} has support {text}", evidence=ev, numbers=nums,
                                  figures=figs)
        return self.refuted(f"the {of} of {self.where_text()} has support {text}, not "
                            f"[{sp.sstr(claim[0])}, {sp.sstr(claim[1])}]", corrected=f"support {text}",
                            evidence=ev, numbers=nums, figures=figs)


class Eigenvalues(Kind):
    """Claimed eigenvalues (with multiplicity by repetition) of the local subdivision matrix."""

    name = "eigenvalues"
    summary = "eigenvalues of the local subdivision matrix (a sub-multiset, or the whole spectrum)"
    required = {"eigenvalues": "list of claimed eigenvalues (repeat for multiplicity)"}
    optional = {"complete": "true: the list is the whole spectrum", "window": "[lo, hi] of the local matrix",
                "at": "parameter values"}
    example = 'eigenvalues = ["1", "1/2", "1/4", "1/4", "1/8"]\ncomplete = true\nat = { w = "1/16" }'
    any_arity = True

    def check(self) -> None:
        self.values()
        if not isinstance(self.get("eigenvalues"), list):
            raise AnalysisError(f"{self.where}: field 'eigenvalues' must be a list")
        loc = {p.name: p for p in self.scheme.symbol.params}
        self.claimed = []
        for x in self.get("eigenvalues"):
            try:
                self.claimed.append(read_in_context(x, loc, what="eigenvalue", free=True))
            except AnalysisError as exc:
                raise AnalysisError(f"{self.where}: {exc}") from None

    def evaluate(self) -> Verdict:
        a = self.symbol()
        r = local_eigenvalues(a, window=self.get("window"), arity=self.arity)
        spectrum = [lam for lam, m in r.value.items() for _ in range(m)]
        rest, missing = list(spectrum), []
        for c in self.claimed:
            c = c.subs({sp.Symbol(k): v for k, v in self.values().items()})
            hit = next((i for i, lam in enumerate(rest) if _same(lam, c)), None)
            if hit is None:
                missing.append(c)
            else:
                rest.pop(hit)
        complete = bool(self.get("complete", False)) and r.provenance.get("complete", True)
        text = ", ".join(sp.sstr(x) for x in spectrum)
        ev = [evidence("exact characteristic polynomial of the local subdivision matrix", r,
                       text=f"window {r.witness['window']}; spectrum {text}")]
        nums = [Number("matrix size", len(spectrum) + sum(m for _, m in r.witness.get("implicit", ()))),
                Number("largest eigenvalue", spectrum[0]) if spectrum and not as_expr(spectrum[0]).free_symbols
                else Number("eigenvalues found", len(spectrum))]
        if missing or (self.get("complete") and rest):
            why = (f"not eigenvalues (or with lower multiplicity): {', '.join(map(sp.sstr, missing))}" if missing
                   else f"the spectrum has more: {', '.join(map(sp.sstr, rest))}")
            if len(self.claimed) > nums[0].value:
                why += f" (the claim lists {len(self.claimed)} eigenvalues of a {nums[0].value}x{nums[0].value} matrix)"
            return self.refuted(f"{why}", corrected=f"the eigenvalues are {text}", evidence=ev, numbers=nums)
        if self.get("complete") and not complete:
            return self.inconclusive("the claimed eigenvalues occur, but part of the spectrum is implicit",
                                     settle="solve the implicit factors of the characteristic polynomial", evidence=[
                                         evidence(ev[0].title, text=ev[0].text)])
        return self.certified(f"the local matrix of {self.where_text()} has the eigenvalues {text}",
                              evidence=ev, numbers=nums)


class Reproduction(Kind):
    """The degree of polynomial generation and/or reproduction (Conti–Hormann)."""

    name = "reproduction"
    summary = "degree of polynomial generation and/or reproduction (Conti-Hormann)"
    optional = {"generation": "claimed generation degree", "reproduction": "claimed reproduction degree",
                "at": "parameter values"}
    example = "generation = 3\nreproduction = 3\nat = { w = \"1/16\" }"
    any_arity = True
    bivariate = True

    def check(self) -> None:
        self.values()
        if "generation" not in self.fields and "reproduction" not in self.fields:
            raise AnalysisError(f"{self.where}: kind 'reproduction' needs 'generation' or 'reproduction'")
        self.integer("generation", -1), self.integer("reproduction", -1)

    def evaluate(self) -> Verdict:
        if self.scheme.bivariate is not None:
            from .bivariate import reproduction_verdict

            return reproduction_verdict(self)
        a = self.symbol()
        m = self.arity
        g, r = polynomial_generation(a, arity=m), polynomial_reproduction(a, arity=m)
        higher = "; ".join(f"{_cond_text(h['condition'])}: degree {h['degree']}" for h in r.witness["higher"])
        ev = [evidence("sum rules (generation)", g, text=f"degree {g.value}"),
              evidence("Conti-Hormann conditions (reproduction)", r,
                       text=f"degree {r.value}, tau = {sp.sstr(r.witness['tau'])}" + (f"; higher at {higher}" if higher else ""))]
        wrong = [f"{what} degree is {res.value}, not {self.get(what)}" for what, res in
                 (("generation", g), ("reproduction", r)) if what in self.fields and self.get(what) != res.value]
        nums = [Number("generation degree", g.value), Number("reproduction degree", r.value)]
        fact = f"generates degree {g.value}, reproduces degree {r.value}"
        if wrong:
            return self.refuted("; ".join(wrong), corrected=f"{self.where_text()} {fact}", evidence=ev, numbers=nums)
        return self.certified(f"{self.where_text()} {fact}", evidence=ev, numbers=nums,
                              sharpness=f"higher degree at {higher}" if higher else None)
