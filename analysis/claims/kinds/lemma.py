"""Lemma claims as data: inequalities over (level n, parameter box), exact identities and printed
factorizations of a symbol, in the paper's own notation (issue 11).

A claim may name a ``scheme`` of the file; its expressions can then use the mask coefficients
``a(k)`` (the coefficient of ``z^k``; of level ``n`` for a level-dependent scheme), the symbol
``symbol`` (``a(z)`` or ``a^n(z)``) and, for a level-dependent scheme, its exact limit ``limit``.
``where = { x = "alpha/2**n", beta_1 = "a(0)" }`` defines the paper's names in order (each may use
the earlier ones). The level is ``n`` (or ``h = 2^-n``).

* **inequality** — ``lhs <relation> rhs`` for every integer ``n >= n0`` and every parameter of
  ``box`` (the plain form of the first edition), or every inequality of ``parts`` (a two-sided
  lemma item is two parts). ``dilation = "alpha"``: the claim is over ``alpha in (0, X)``, and
  every side depends on ``(n, alpha)`` only through ``alpha/2^n`` — verified exactly — so
  ``alpha in [X/2, X]`` covers it. A box parameter that cancels exactly from ``rhs - lhs`` is
  dropped. ``identities`` are exact side conditions (a derivative, ``cosh - sinh = e^-x``),
  ``argument`` the one-line reduction that joins them, ``corrected`` the correction checked when the
  printed statement is refuted, ``asymptotics`` the exact ``lim_{h->0} of/h^order`` (the best
  constant of an ``O(4^-n)`` bound).
* **identity** — ``lhs == rhs`` (or every identity of ``parts``) exactly; refuted by a certified
  nonzero difference at a rational point; ``numbers`` are exact values reported with the verdict.
* **factorization** — the printed ``factor * cofactor`` is the scheme's symbol exactly.

Examples
--------
>>> v = Inequality({"parts": [{"label": "lower", "lhs": "3/4", "rhs": "sin(3*x/4)/sin(x)"},
...                           {"label": "upper", "lhs": "sin(3*x/4)/sin(x)", "rhs": "3/(4*cos(x))"}],
...                 "where": {"x": "alpha/2**n"}, "n0": 1, "box": {"alpha": "(0, pi/3)"},
...                 "dilation": "alpha"}, {}, "x").evaluate()
>>> v.label
'CERTIFIED TRUE'
>>> v = Identity({"lhs": "sin(2*t)", "rhs": "2*sin(t)*cos(t)", "numbers": {"at 0": "cos(0)"}}, {}, "x").evaluate()
>>> v.label, [(n.name, n.value) for n in v.numbers]
('CERTIFIED TRUE', [('at 0', 1)])
>>> Identity({"lhs": "(1+z)**2", "rhs": "1 + z**2"}, {}, "x").evaluate().label
'REFUTED'
>>> v = Identity({"lhs": "ceiling(d/2)", "rhs": "floor(d/2) + 1", "integers": {"d": "[1, 6]"}}, {}, "x").evaluate()
>>> v.label, [(n.name, n.value) for n in v.numbers]
('REFUTED', [('first counterexample d', 2)])

Algorithm
---------
Inequalities: :func:`analysis.levels.bounds.check_inequality` (Arb branch and bound for the first
levels, a rigorous Taylor model in ``h = 2^-n`` for the tail). Identities:
:func:`analysis.levels.bounds.check_identity` (exact sympy simplification, or an acb ball that
excludes 0 at a rational point). Dilation invariance ``E(2 alpha, h/2) = E(alpha, h)`` is an exact
simplification. Asymptotic constants: exact sympy limits.

References
----------
F. Johansson, *Arb*, IEEE Trans. Comput. 66 (2017). W. Tucker, *Validated Numerics*, Princeton
(2011), ch. 5.
"""

from __future__ import annotations

import itertools
from typing import Any

import sympy as sp

from ...levels.bounds import _exact_zero, check_identity, check_inequality
from ...levels.level_dependent import H, N, to_h
from ...result import CERTIFIED, REFUTED, AnalysisError, Result
from ..model import Number, Verdict
from .base import Kind, evidence, parse_interval, parse_number
from ...algebra.reader import as_expr, read_in_context

__all__ = ["Inequality", "Identity", "Factorization"]

_Z = sp.Symbol("z")
_RELATIONS = {"<=": (False, False), "<": (True, False), ">=": (False, True), ">": (True, True)}


def _s(x) -> str:
    return sp.sstr(x)


class _Expressions(Kind):
    """Shared by the lemma kinds: the optional scheme, ``where`` definitions, reading expressions."""

    uses_scheme = False
    common = {"scheme": "a scheme of the file: a(k), symbol (and limit) become available",
              "where": "{ name = \"expr\" } the paper's names, in order"}

    def check(self) -> None:
        self._scheme = None
        name = self.get("scheme")
        if name is not None:
            if name not in self.schemes:
                raise AnalysisError(f"{self.where}: unknown scheme {name!r} (the file defines: "
                                    f"{', '.join(sorted(self.schemes)) or 'no scheme'})")
            self._scheme = self.schemes[name]
        if not isinstance(self.get("where", {}), dict):
            raise AnalysisError(f"{self.where}: field 'where' is a table {{ name = \"expr\" }}")
        self.locals()

    def locals(self) -> dict:
        """The names an expression may use (built once)."""
        if getattr(self, "_loc", None) is not None:
            return self._loc
        loc: dict[str, Any] = {"n": N, "h": H, "z": _Z}
        s = self._scheme
        if s is not None:
            loc.update({p.name: p for p in s.params})
            if s.level is not None:
                lv = s.level
                loc["a"] = lambda k: lv.mask[int(k) - lv.start] if lv.start <= int(k) <= lv.start + len(lv.mask) - 1 else 0
                loc["symbol"] = lv.symbol_expr()
                loc["limit"] = _LazyLimit(lv)
            else:
                sym = s.symbol
                loc["a"] = lambda k: sym.coeff(int(k))
                loc["symbol"] = sym.expr()
        for k, v in (self.get("box") or {}).items():
            loc.setdefault(k, sp.Symbol(k, real=True))
        self._loc = loc
        for k, v in (self.get("where") or {}).items():
            if k in ("n", "h", "z", "a", "symbol", "limit"):
                raise AnalysisError(f"{self.where}: 'where' cannot redefine {k!r}")
            loc[k] = self.expr(v, f"where {k}", free=self.free_names())
        return loc

    def free_names(self) -> bool:
        """May expressions use names that are neither defined nor parameters (free variables)?"""
        return False

    def expr(self, text, what: str, free: bool = False) -> sp.Expr:
        loc = self.locals()
        if "limit" in loc and isinstance(loc["limit"], _LazyLimit) and "limit" in str(text):
            loc["limit"] = loc["limit"].value()
        try:
            e = read_in_context(text, loc, what=what, free=True)
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None
        if not isinstance(e, sp.Expr):
            raise AnalysisError(f"{self.where}: {what} {text!r} is not an expression")
        unknown = sorted(x.name for x in e.free_symbols if x.name not in loc)
        if unknown and not free:
            raise AnalysisError(f"{self.where}: unknown name {unknown[0]!r} in {what} {text!r} "
                                "(define it in 'where', or give it in 'box')")
        return e

    def parts(self, keys=("lhs", "rhs")) -> list[dict]:
        """The claim's statements: the fields themselves, or the tables of ``parts``."""
        ps = self.get("parts")
        if ps is None:
            if not all(k in self.fields for k in keys):
                raise AnalysisError(f"{self.where}: kind {self.name!r} needs {' and '.join(map(repr, keys))} or 'parts'")
            return [{k: self.fields[k] for k in self.fields if k in self.part_keys}]
        if not isinstance(ps, list) or not ps or not all(isinstance(p, dict) for p in ps):
            raise AnalysisError(f"{self.where}: 'parts' is a list of tables [{{ lhs = ..., rhs = ... }}]")
        for p in ps:
            bad = sorted(set(p) - self.part_keys)
            if bad or not all(k in p for k in keys):
                raise AnalysisError(f"{self.where}: a part has " + (f"the unknown key {bad[0]!r}" if bad else
                                    f"no {'/'.join(keys)}") + f" (its keys: {', '.join(sorted(self.part_keys))})")
        return ps


class _LazyLimit:
    """The exact limit symbol of a level-dependent scheme, computed only when an expression uses it."""

    def __init__(self, level):
        self.level = level

    def value(self):
        return self.level.limit().expr()


# ------------------------------------------------------------------------------------- inequality
class Inequality(_Expressions):
    """``lhs <= rhs`` (or every part) for all levels ``n >= n0`` and the parameter box (see the module)."""

    name = "inequality"
    summary = "a lemma inequality lhs <= rhs (or parts) for all levels n >= n0 and a parameter box (Arb, Taylor tail)"
    required: dict = {}
    optional = {"lhs": "expression in n (or h = 2^-n) and parameters", "rhs": "expression",
                "relation": "\"<=\" (default), \"<\", \">=\" or \">\"", "strict": "true for < (first edition)",
                "n0": "first level (default 0)", "box": "{ name = value or \"[lo, hi]\" }",
                "parts": "[{ label, lhs, relation, rhs, (n0, box, dilation) }]: every one must hold",
                "dilation": "parameter p: the sides depend on (n, p) only through p/2^n; box p = \"(0, X)\"",
                "identities": "[{ label, lhs, rhs }] exact side conditions", "argument": "the reduction, one line",
                "corrected": "{ statement, lhs, relation, rhs }: checked when the claim is refuted",
                "asymptotics": "{ of, order, over, name }: lim_(h->0) of/(h^order over), exact",
                **_Expressions.common}
    part_keys = {"label", "lhs", "rhs", "relation", "strict", "n0", "box", "dilation"}
    example = ('parts = [{ label = "lower", lhs = "3/4", rhs = "sin(3*x/4)/sin(x)" },\n'
               '         { label = "upper", lhs = "sin(3*x/4)/sin(x)", relation = "<=", rhs = "3/(4*cos(x))" }]\n'
               'where = { x = "alpha/2**n" }\nn0 = 1\nbox = { alpha = "(0, pi/3)" }\ndilation = "alpha"')

    def check(self) -> None:
        super().check()
        self.integer("n0")
        for p in self.parts() + ([self.get("corrected")] if self.get("corrected") else []):
            if not isinstance(p, dict):
                raise AnalysisError(f"{self.where}: 'corrected' is a table {{ statement, lhs, relation, rhs }}")
            self._relation(p)
            box = self._box(p.get("box", self.get("box")))
            dil = p.get("dilation", self.get("dilation"))
            if dil and dil not in box:
                raise AnalysisError(f"{self.where}: dilation {dil!r} names no parameter of the box "
                                    f"({', '.join(box) or 'none'}): give box {{ {dil} = \"(0, X)\" }}")
            if self.get("parts") is not None or p is self.get("corrected"):
                self.expr(p["lhs"], "lhs"), self.expr(p["rhs"], "rhs")     # unknown names fail at load time

    def _relation(self, p) -> tuple[bool, bool]:
        if "relation" in p and "strict" in p:
            raise AnalysisError(f"{self.where}: give 'relation' or 'strict', not both")
        rel = p.get("relation", "<" if p.get("strict") else "<=")
        if rel not in _RELATIONS:
            raise AnalysisError(f"{self.where}: relation must be one of {', '.join(_RELATIONS)}, not {rel!r}")
        return _RELATIONS[rel]

    def _box(self, box) -> dict:
        if box is None:
            return {}
        if not isinstance(box, dict):
            raise AnalysisError(f"{self.where}: field 'box' is a table {{ name = value or \"[lo, hi]\" }}")
        out = {}
        for k, v in box.items():
            if isinstance(v, str) and v.strip()[:1] in "([":
                lo, hi, _, _ = parse_interval(v, f"{self.where}: box {k}")
                out[k] = (lo, hi)
            else:
                out[k] = parse_number(v, f"{self.where}: box {k}")
        return out

    def _check_part(self, p) -> tuple:
        """(Result, text) for one inequality (dilation, exact cancellation, then check_inequality)."""
        strict, flip = self._relation(p)
        lhs, rhs = self.expr(p["lhs"], "lhs"), self.expr(p["rhs"], "rhs")
        if flip:
            lhs, rhs = rhs, lhs
        n0 = p.get("n0", self.get("n0", 0))
        box = self._box(p.get("box", self.get("box")))
        notes = []
        L, R = to_h(lhs), to_h(rhs)
        diffs = [R - L.args[0], R + L.args[0]] if isinstance(L, sp.Abs) else [R - L]
        used = set().union(*(sp.expand(d).free_symbols for d in diffs))
        gone = [k for k in box if k not in {x.name for x in used}]
        if gone:
            sub = {x: 0 for x in (L.free_symbols | R.free_symbols) if x.name in gone}
            lhs, rhs = lhs.subs(sub), rhs.subs(sub)
            box = {k: v for k, v in box.items() if k not in gone}
            notes.append(f"{', '.join(gone)} cancels exactly from rhs - lhs")
        dil = p.get("dilation", self.get("dilation"))
        if dil and dil in box:
            lo, hi = box[dil] if isinstance(box[dil], tuple) else (None, None)
            if lo != 0:
                raise AnalysisError(f"{self.where}: dilation {dil!r} needs box {dil} = \"(0, X)\"")
            sym = next((x for x in (L.free_symbols | R.free_symbols) if x.name == dil), sp.Symbol(dil))
            inv = all(_exact_zero(e.subs({sym: 2 * sym, H: H / 2}, simultaneous=True) - e) for e in diffs)
            if not inv:
                raise AnalysisError(f"{self.where}: the sides do not depend on (n, {dil}) through {dil}/2^n only")
            box[dil] = (hi / 2, hi)
            notes.append(f"depends on (n, {dil}) only through {dil}/2^n (exact): {dil} in [{_s(hi / 2)}, {_s(hi)}] "
                         f"with n >= {n0} covers 0 < {dil} <= {_s(hi)}")
        r = check_inequality(lhs, rhs, n0, box, strict=strict)
        dom = ", ".join(f"{k} in [{_s(v[0])}, {_s(v[1])}]" if isinstance(v, tuple) else f"{k} = {_s(v)}"
                        for k, v in box.items())
        text = f"{r.witness['statement']}{', ' + dom if dom else ''}: {r.status}"
        if r.status == REFUTED:
            ce = r.witness["counterexample"]
            text += f"; counterexample n = {ce['n']}" + "".join(f", {k} = {_s(v)}" for k, v in ce["point"].items())
        elif r.status == CERTIFIED and r.witness.get("tail"):
            text += f" (tail: {r.witness['tail'].get('method')})"
        return r, "; ".join([text] + notes)

    def evaluate(self) -> Verdict:
        if self.get("parts") is None and not any(k in self.fields for k in ("dilation", "identities", "corrected",
                                                                              "asymptotics", "relation", "where", "scheme")):
            return self._plain()
        ev, nums, bad, open_ = [], [], [], []
        for p in self.parts():
            r, text = self._check_part(p)
            label = p.get("label", "")
            ev.append(evidence(label or "inequality", r, text=text))
            if r.status == REFUTED:
                bad.append(label or text)
                if label:
                    nums.append(Number(f"{label}.counterexample_n", r.witness["counterexample"]["n"]))
            elif r.status != CERTIFIED:
                open_.append(label or text)
        for i in self.get("identities", []):
            r = check_identity(self.expr(i["lhs"], "identity", True), self.expr(i["rhs"], "identity", True))
            ev.append(evidence(i.get("label", "exact identity"), r, text=f"{r.witness['statement']}: {r.status}"))
            (bad if r.status == REFUTED else open_ if r.status != CERTIFIED else []).append(i.get("label", "identity"))
        if self.get("argument"):
            ev.append(evidence("reduction", text=self.get("argument")))
        sharp = None
        if self.get("asymptotics"):
            a = self.get("asymptotics")
            inner = to_h(self.expr(a["of"], "asymptotics"))
            c = sp.limit(inner / (H ** a.get("order", 0) * self.expr(a.get("over", "1"), "asymptotics")), H, 0)
            c = sp.simplify(sp.Abs(c))
            nums.append(Number(a.get("name", "asymptotic constant"), c))
            sharp = (f"not sharp: the optimal constant tends to {_s(c)} {a.get('over', '')} as n -> oo (exact limit); "
                     "the printed one is larger")
        if bad:
            summary = f"false: {', '.join(bad)} fails (certified counterexample)"
            corr = self.get("corrected")
            if corr is None:
                return self.refuted(summary, corrected="the inequality fails (see the counterexample)", evidence=ev,
                                    numbers=nums)
            rc, text = self._check_part(corr)
            ev.append(evidence("corrected statement", rc, text=text))
            if rc.status != CERTIFIED:
                return self.inconclusive(summary + "; the correction could not be certified",
                                         settle="finer boxes in check_inequality", evidence=ev, numbers=nums)
            return self.refuted(summary, corrected=f"{corr['statement']} (certified)", evidence=ev, numbers=nums)
        if open_:
            return self.inconclusive(f"not decided: {', '.join(open_)}", settle="finer boxes in check_inequality",
                                     evidence=ev, numbers=nums)
        stated = "; ".join(f"{p.get('label') + ': ' if p.get('label') else ''}{p['lhs']} "
                           f"{p.get('relation', '<' if p.get('strict') else '<=')} {p['rhs']}" for p in self.parts())
        return self.certified(f"True: {stated} — certified for every level and parameter of the claim"
                              + (", with the exact identities and the reduction" if self.get("identities") else ""),
                              evidence=ev, numbers=nums, sharpness=sharp)

    def _plain(self) -> Verdict:
        """The first edition's form: one inequality, its box as given."""
        box = self._box(self.get("box"))
        loc = {"n": N, "h": H, **{k: sp.Symbol(k, real=True) for k in box}}
        try:
            lhs, rhs = (read_in_context(self.get(x), loc, what=x, free=True) for x in ("lhs", "rhs"))
        except AnalysisError as exc:
            raise AnalysisError(f"{self.where}: {exc}") from None
        r = check_inequality(lhs, rhs, self.get("n0", 0), box, strict=bool(self.get("strict", False)))
        stmt = r.witness["statement"]
        if r.status == CERTIFIED:
            return self.certified(f"proven: {stmt}", evidence=[evidence("Arb branch and bound + Taylor tail", r)],
                                  numbers=[Number("proven", True)])
        if r.status == REFUTED:
            ce = r.witness["counterexample"]
            return self.refuted(f"false: {stmt} fails at {ce}", corrected=f"the inequality fails at {ce}",
                                evidence=[evidence("certified counterexample (Arb)", r)], numbers=[Number("proven", False)])
        return self.inconclusive(f"not decided: {stmt}", settle=r.witness.get("advice", "a finer box"),
                                 evidence=[evidence("worst case found", text=str(r.witness.get("worst")))])


# ------------------------------------------------------------------------------------- identities
class Identity(_Expressions):
    """``lhs == rhs`` exactly (or every part), in the paper's notation (see the module)."""

    name = "identity"
    summary = "an exact identity lhs == rhs (or parts) in z, n and the parameters (sympy; acb counterexample)"
    optional = {"lhs": "expression", "rhs": "expression", "parts": "[{ label, lhs, rhs }]: every one must hold",
                "numbers": "{ name = \"expr\" } exact values reported with the verdict",
                "corrected": "{ statement, lhs, rhs }: checked when the claim is refuted (a statement alone is "
                             "reported as not checked)",
                "argument": "how the identities settle the claim, one line",
                "integers": "{ d = \"[3, 10]\" }: integer variables, checked exactly at every value of the range",
                "at": "{ name = value }: parameter values substituted first (checked against the scheme's domains)",
                **_Expressions.common}
    part_keys = {"label", "lhs", "rhs"}
    example = 'lhs = "sin(2*t)"\nrhs = "2*sin(t)*cos(t)"\nnumbers = { "value at t = 0" = "cos(0)" }'

    def check(self) -> None:
        super().check()
        self.statements()                    # unknown names fail at load time
        if not isinstance(self.get("numbers", {}), dict):
            raise AnalysisError(f"{self.where}: field 'numbers' is a table {{ name = \"expr\" }}")
        for k, v in (self.get("numbers") or {}).items():
            self.expr(v, f"number {k}", self.free_names())      # bad text fails when the file is loaded
        self.ranges = {}
        for k, v in (self.get("integers") or {}).items():
            lo, hi, _, _ = parse_interval(v, f"{self.where}: integers {k}")
            if not (lo.is_Integer and hi.is_Integer and hi - lo <= 1000):
                raise AnalysisError(f"{self.where}: integers {k} = \"[lo, hi]\" with integer ends (at most 1000 values)")
            self.ranges[k] = range(int(lo), int(hi) + 1)

    def _check(self, lhs, rhs, label) -> Result:
        """check_identity, or exact evaluation at every integer of ``integers``."""
        if not self.ranges:
            return check_identity(lhs, rhs, claim=label)
        names = list(self.ranges)
        syms = {x.name: x for x in (as_expr(lhs).free_symbols | as_expr(rhs).free_symbols)}
        rows, bad = [], None
        for vals in itertools.product(*self.ranges.values()):
            sub = {syms[k]: v for k, v in zip(names, vals) if k in syms}
            a, b = sp.simplify(as_expr(lhs).subs(sub)), sp.simplify(as_expr(rhs).subs(sub))
            ok = sp.simplify(a - b) == 0
            rows.append(tuple(map(str, vals)) + (_s(a), _s(b), "yes" if ok else "NO"))
            if not ok and bad is None:
                bad = dict(zip(names, vals))
        stmt = f"{_s(lhs)} == {_s(rhs)} for " + ", ".join(f"{k} = {r.start}..{r.stop - 1}" for k, r in self.ranges.items())
        return Result(value=bad is None, status=CERTIFIED if bad is None else REFUTED,
                      witness={"claim": label, "statement": stmt, "point": bad, "table": (tuple(names) + ("lhs", "rhs",
                               "equal"),) + tuple(rows)},
                      provenance={"method": "exact evaluation at every integer of the range"})

    def free_names(self) -> bool:
        return self._scheme is None          # free variables (t, lambda, d) unless the claim names a scheme

    def _at(self) -> dict:
        """The substitution of ``at`` (exact values; in the scheme's domains when it has them)."""
        at = self.get("at") or {}
        vals = {k: parse_number(v, f"{self.where}: at {k}") for k, v in at.items()}
        if self._scheme is not None:
            names = {p.name for p in self._scheme.params}
            for k, v in vals.items():
                if k not in names:
                    raise AnalysisError(f"{self.where}: unknown parameter {k!r} of scheme {self._scheme.name!r}")
                d = self._scheme.domains.get(k)      # sympy decides pi/5 < pi/3 (RealAlgebraic cannot)
                if d is not None and not ((d.lo == -sp.oo or bool(v >= d.lo if d.lo_closed else v > d.lo)) and
                                          (d.hi == sp.oo or bool(v <= d.hi if d.hi_closed else v < d.hi))):
                    raise AnalysisError(f"{self.where}: {k} = {_s(v)} is outside its domain {d}")
        loc = self.locals()
        return {loc.get(k, sp.Symbol(k)): v for k, v in vals.items()}

    def statements(self) -> list[tuple[str, sp.Expr, sp.Expr]]:
        free, at = self.free_names(), self._at()
        return [(p.get("label", ""), self.expr(p["lhs"], "lhs", free).subs(at), self.expr(p["rhs"], "rhs", free).subs(at))
                for p in self.parts()]

    def evaluate(self) -> Verdict:
        ev, bad, open_, nums = [], [], [], []
        for p, (label, lhs, rhs) in zip(self.parts(), self.statements()):
            r = self._check(lhs, rhs, label)
            label = label or f"{p['lhs']} = {p['rhs']}"
            text = f"{r.witness['statement']}: {r.status}"
            if r.status == REFUTED and "difference" in r.witness:
                text += (f" (certified nonzero difference {r.witness['difference']} at {r.witness['point']}; "
                         f"difference {_s(r.witness['simplified_difference'])})")
            elif r.status == REFUTED:
                text += f" (first counterexample {r.witness['point']})"
                nums.extend(Number(f"first counterexample {k}", v) for k, v in r.witness["point"].items())
            (bad if r.status == REFUTED else open_ if r.status != CERTIFIED else []).append(label)
            ev.append(evidence(label, r, text=text, table=r.witness.get("table")))
        vals = [Number(k, sp.simplify(self.expr(v, f"number {k}", self.free_names())))
                for k, v in (self.get("numbers") or {}).items()]
        if vals:
            ev.append(evidence("exact values", text="; ".join(f"{n.name} = {_s(n.value)} ≈ {float(n.value):.12g}"
                                                               for n in vals)))
        nums += vals
        if self.get("argument"):
            ev.append(evidence("argument", text=self.get("argument")))
        if bad:
            at = ", ".join(f"{k} = {v}" for k, v in (self.get("at") or {}).items())
            summary = f"false: {', '.join(bad)} " + ("(exact counterexample)" if self.ranges else
                                                      f"(certified nonzero difference at {at or 'a rational point'})")
            corr = self.get("corrected")
            if corr is None or "lhs" not in corr:
                return self.refuted(summary, corrected=(corr or {}).get("statement", "see the certified difference")
                                    + (" (a reading, not checked here)" if corr else ""), evidence=ev, numbers=nums)
            free = self.free_names()
            rc = self._check(self.expr(corr["lhs"], "corrected", free), self.expr(corr["rhs"], "corrected", free),
                             "corrected")
            ev.append(evidence("corrected statement", rc, text=f"{rc.witness['statement']}: {rc.status}"))
            if rc.status != CERTIFIED:
                return self.inconclusive(summary + "; the correction could not be certified",
                                         settle="an exact simplification", evidence=ev, numbers=nums)
            return self.refuted(summary, corrected=f"{corr['statement']} (certified)", evidence=ev, numbers=nums)
        if open_:
            return self.inconclusive(f"neither proven nor refuted: {', '.join(open_)}",
                                     settle="an exact simplification or a certified nonzero value", evidence=ev,
                                     numbers=nums)
        stated = "; ".join(p.get("label") or f"{p['lhs']} = {p['rhs']}" for p in self.parts())
        where = (", ".join(f"every integer {k} in [{r.start}, {r.stop - 1}]" for k, r in self.ranges.items())
                 if self.ranges else "every level and parameter")
        return self.certified(f"True (exact, for {where}): {stated}", evidence=ev, numbers=nums)


class Factorization(Identity):
    """The scheme's symbol is the printed ``factor * cofactor`` exactly (e.g. ``d^n = (1+z)/2 e^n``)."""

    name = "factorization"
    summary = "the scheme's symbol equals the printed factor * cofactor (exact, all levels and parameters)"
    required = {"scheme": "the scheme whose symbol is factored", "factor": "e.g. \"(1+z)/2\"",
                "cofactor": "the printed cofactor e(z)"}
    optional = {"numbers": Identity.optional["numbers"], "where": _Expressions.common["where"]}
    example = ('scheme = "exp-chaikin"\nfactor = "(1 + z)/2"\n'
               'cofactor = "(1 + 2*cosh(t*h/2)*z + z**2)/((1 + cosh(t*h/2))*z**2)"')

    def parts(self, keys=("lhs", "rhs")) -> list[dict]:
        return [{"label": f"a(z) = ({self.get('factor')}) e(z)", "lhs": "symbol",
                 "rhs": f"({self.get('factor')})*({self.get('cofactor')})"}]
