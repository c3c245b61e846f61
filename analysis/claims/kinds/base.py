"""What every claim kind shares: the scheme a claim speaks of, parameter domains, exact
numbers and intervals read from a paper file, and the :class:`Kind` base class.

A kind is a small class: ``name`` (the ``kind = "..."`` of a paper file), its ``required``
and ``optional`` fields (name -> one-line description), ``example`` (the fields of one
example claim, used by the ``subdiv new-paper`` template), ``check()`` (validation when the
file is loaded: a bad field is an :class:`~analysis.result.AnalysisError` naming it) and
``evaluate() -> Verdict`` (computed by the engine; never a typed-in verdict).

Examples
--------
>>> d = Domain.parse("[0, 1/8)")
>>> d.contains(0), d.contains(sp.Rational(1, 8)), str(d)
(True, False, '[0, 1/8)')
>>> parse_interval("(0, (sqrt(5)-1)/8)")
(0, -1/8 + sqrt(5)/8, False, False)
>>> parse_number("1/16") + parse_number("0.25")
5/16

Algorithm
---------
Numbers are read exactly (decimals as the rationals they spell); membership in a domain is
decided exactly with real algebraic numbers (:class:`analysis.algebra.algebraic.RealAlgebraic`).

References
----------
DESIGN.md ("Results contract"); :mod:`analysis.claims.model` (verdicts).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar, Mapping

import sympy as sp

from ...algebra.symbol import LaurentSymbol, parse_coefficient
from ...result import AnalysisError, Result
from ..model import Evidence, Number, Verdict, certified, inconclusive, refuted
from ...algebra.reader import as_expr, read_expression

__all__ = ["Domain", "SchemeSpec", "Kind", "ANY_ARITY_KINDS", "set_text", "point_in", "parse_number", "parse_interval", "interval_text", "evidence",
           "rules_symbol", "RULES_FORMS"]


def parse_number(x, what: str = "number") -> sp.Expr:
    """An exact number (int, ``"1/16"``, ``"0.25"``, ``"(sqrt(5)-1)/8"``; ``"oo"``/``"-oo"`` allowed)."""
    try:
        if isinstance(x, str):
            v = read_expression(x, what="number", free=False, allow_infinity=True,
                                hint="a number is expected here (e.g. 1/16, pi/5, oo)")
        else:
            v = parse_coefficient(x)
    except AnalysisError as exc:
        raise AnalysisError(f"{what}: {exc}") from None
    if v.free_symbols:
        raise AnalysisError(f"{what}: {x!r} is not a number (free symbols {sorted(map(str, v.free_symbols))})")
    return v


def _split_top(text: str) -> list[str]:
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    return [p.strip() for p in parts]


def parse_interval(x, what: str = "interval") -> tuple:
    """``"(a, b)"``, ``"[a, b)"``, ... or a two-element list (open) -> ``(lo, hi, lo_closed, hi_closed)``."""
    if isinstance(x, (list, tuple)):
        if len(x) != 2:
            raise AnalysisError(f"{what}: expected two end points, got {len(x)}")
        lo, hi, lc, hc = parse_number(x[0], what), parse_number(x[1], what), False, False
    else:
        t = str(x).strip()
        if len(t) < 5 or t[0] not in "([" or t[-1] not in ")]":
            raise AnalysisError(f"{what}: cannot read {x!r} (write e.g. \"(0, 1/8)\" or \"[0, 1/8)\")")
        ends = _split_top(t[1:-1])
        if len(ends) != 2:
            raise AnalysisError(f"{what}: {x!r} needs exactly two end points")
        lo, hi = parse_number(ends[0], what), parse_number(ends[1], what)
        lc, hc = t[0] == "[", t[-1] == "]"
    if not bool(sp.N(hi - lo, 30) > 0):
        raise AnalysisError(f"{what}: {x!r} is empty (the left end must be smaller)")
    return lo, hi, lc, hc


#: the two ways to write a scheme's rules in a paper file (the message of a malformed ``rules``)
RULES_FORMS = ("rules = { even = [...], odd = [...], first = p } (binary; or even_first, odd_first instead of first), "
               "or rules = { stencils = [[...], [...], ...], first = p } (M stencils, one per residue r = 0..M-1; "
               "first = [p_0, ..., p_(M-1)] for one offset per stencil)")


def rules_symbol(r, *, locals_=None, params=None) -> tuple[LaurentSymbol, int, str]:
    """``(symbol, M, text)`` of the rules of a paper file: ``{even, odd, first | even_first, odd_first}``
    (binary) or ``{stencils = [s_0, ..., s_(M-1)], first}`` (M-ary: the r-th stencil gives ``f[M i + r]``,
    its coefficient of ``f[i+p]`` is ``a_(r - M p)``; :meth:`LaurentSymbol.from_stencils`, the binary form
    being the case M = 2). Coefficients are read by the input reader (``locals_``: the declared parameters).

    >>> a, M, _ = rules_symbol({"stencils": [[1], ["2/3", "1/3"], ["1/3", "2/3"]], "first": 0})
    >>> M, a.mask, a.start
    (3, (1/3, 2/3, 1, 2/3, 1/3), -2)
    >>> rules_symbol({"even": [1], "odd": ["1/2", "1/2"]})[0] == rules_symbol({"stencils": [[1], ["1/2", "1/2"]]})[0]
    True
    """
    from collections.abc import Mapping as _Mapping

    def coeffs(x, what):
        if not isinstance(x, list):
            raise AnalysisError(f"{what} must be a list of coefficients; {RULES_FORMS}")
        return [parse_coefficient(c, locals_=locals_) for c in x]

    if not isinstance(r, _Mapping):
        raise AnalysisError(RULES_FORMS)
    if "stencils" in r:
        if set(r) - {"stencils", "first"}:
            raise AnalysisError(f"unknown key {sorted(set(r) - {'stencils', 'first'})[0]!r} in rules: {RULES_FORMS}")
        st = r["stencils"]
        if not isinstance(st, list) or len(st) < 2:
            raise AnalysisError(f"stencils must be a list of M >= 2 stencils; {RULES_FORMS}")
        from ...algebra.reader import LIMITS

        if len(st) > LIMITS.arity:
            raise AnalysisError(f"{len(st)} stencils: the arity limit is {LIMITS.arity} (limit 'arity')")
        stencils = [coeffs(x, f"stencil {k}") for k, x in enumerate(st)]
        first = r.get("first", 0)
        a = LaurentSymbol.from_stencils(stencils, first, params=params)
        text = "; ".join(f"f[{len(st)}i+{k}]: {[sp.sstr(c) for c in x]}" for k, x in enumerate(stencils))
        return a, len(st), f"rules {text}, first {first}"
    if not {"even", "odd"} <= set(r) or set(r) - {"even", "odd", "first", "even_first", "odd_first"}:
        raise AnalysisError(RULES_FORMS)
    for key in ("first", "even_first", "odd_first"):
        if key in r and (isinstance(r[key], bool) or not isinstance(r[key], int)):
            raise AnalysisError(f"{key} must be an integer; {RULES_FORMS}")
    ev, od = coeffs(r["even"], "even"), coeffs(r["odd"], "odd")
    a = LaurentSymbol.from_rules(ev, od, r.get("first", 0), even_first=r.get("even_first"),
                                 odd_first=r.get("odd_first"), params=params)
    text = (f"rules even {[sp.sstr(c) for c in ev]}, odd {[sp.sstr(c) for c in od]}, first "
            + ", ".join(f"{k} {r[k]}" for k in ("first", "even_first", "odd_first") if k in r))
    return a, 2, text


def interval_text(lo, hi, lc=False, hc=False) -> str:
    return f"{'[' if lc else '('}{sp.sstr(lo)}, {sp.sstr(hi)}{']' if hc else ')'}"


def _ra(x):
    from ...algebra.algebraic import RealAlgebraic

    return RealAlgebraic.from_expr(as_expr(x))


def _compare(x, y) -> int:
    """The sign of ``x - y`` for exact real constants, certified (exact for algebraic numbers, else an
    Arb ball at up to 256 bits, and an exact zero test when the balls cannot separate them).

    >>> _compare("2 - log(1 + sqrt(3))/log(2)", "11/20"), _compare("pi/5", "pi/5"), _compare("sqrt(2)", "7/5")
    (1, 0, 1)
    """
    from ...algebra.algebraic import RealAlgebraic

    x, y = as_expr(x), as_expr(y)
    try:
        return RealAlgebraic.from_expr(x).compare(RealAlgebraic.from_expr(y))
    except Exception:   # not algebraic (pi/5, exp(1), log2(3), ...): Arb balls, then an exact zero test
        pass
    import flint

    from ...levels.balls import ball

    d = x - y
    for prec in (64, 128, 256):
        old, flint.ctx.prec = flint.ctx.prec, prec
        try:
            b = ball(d)
        except Exception:   # an expression the ball evaluator does not know: the exact test below
            break
        finally:
            flint.ctx.prec = old
        if b > 0:
            return 1
        if b < 0:
            return -1
    if sp.simplify(d) == 0:
        return 0
    raise AnalysisError(f"cannot decide the sign of {sp.sstr(d)} (256-bit balls contain 0)")


@dataclass(frozen=True)
class Domain:
    """The domain of a parameter: an interval (possibly unbounded) of the real line."""

    lo: Any = -sp.oo
    hi: Any = sp.oo
    lo_closed: bool = False
    hi_closed: bool = False

    @classmethod
    def parse(cls, x) -> "Domain":
        if x in ("real", "R", None):
            return cls()
        return cls(*parse_interval(x, "parameter domain"))

    def contains(self, v) -> bool:
        """Whether the exact number ``v`` lies in the domain, decided exactly: real algebraic numbers are
        compared exactly; other constants (``pi/5``, ``exp(1)``) by exact equality or a certified Arb
        ball comparison (an :class:`AnalysisError` if 256 bits cannot separate them).

        >>> d = Domain.parse("(0, pi/3)")
        >>> d.contains("pi/5"), d.contains("pi/3"), d.contains("sqrt(2)/2"), d.contains(-1)
        (True, False, True, False)
        """
        v = as_expr(v)
        if self.lo != -sp.oo:
            c = _compare(v, self.lo)
            if c < 0 or (c == 0 and not self.lo_closed):
                return False
        if self.hi != sp.oo:
            c = _compare(v, self.hi)
            if c > 0 or (c == 0 and not self.hi_closed):
                return False
        return True

    def __str__(self) -> str:
        return interval_text(self.lo, self.hi, self.lo_closed, self.hi_closed)


@dataclass(frozen=True)
class SchemeSpec:
    """A scheme of a paper file: its name, exact symbol, parameter domains and notes."""

    name: str
    symbol: LaurentSymbol | None
    domains: Mapping[str, Domain] = field(default_factory=dict)
    definition: str = ""
    notes: str = ""
    #: a level-dependent scheme (:class:`analysis.levels.level_dependent.LevelDependentScheme`)
    level: Any = None
    #: the arity m of ``(S_a f)_i = sum_j a_{i-mj} f_j`` (issue 12; 2 for binary schemes)
    arity: int = 2
    #: a bivariate scheme (:class:`analysis.bivariate.mask.BivariateMask`, its dilation included)
    bivariate: Any = None

    @property
    def params(self) -> tuple:
        if self.bivariate is not None:
            return tuple(self.bivariate.params)
        return tuple((self.level if self.symbol is None else self.symbol).params)

    def values(self, at: Mapping | None, where: str) -> dict:
        """Exact parameter values ``{name: value}`` checked against the names and domains."""
        out = {}
        if at is not None and not isinstance(at, Mapping):
            raise AnalysisError(f"{where}: field 'at' is a table {{ name = value }}")
        names = {p.name for p in self.params}
        for k, v in (at or {}).items():
            if k not in names:
                raise AnalysisError(f"{where}: unknown parameter {k!r} of scheme {self.name!r} "
                                    f"(its parameters: {', '.join(sorted(names)) or 'none'})")
            q = parse_number(v, f"{where}: parameter {k}")
            dom = self.domains.get(k)
            if dom is not None and not dom.contains(q):
                raise AnalysisError(f"{where}: {k} = {sp.sstr(q)} is outside its domain {dom}")
            out[k] = q
        return out

    def at(self, values: Mapping) -> LaurentSymbol:
        if self.bivariate is not None:
            raise AnalysisError(f"scheme {self.name!r} is bivariate: this kind needs a univariate scheme")
        if self.symbol is None:
            raise AnalysisError(f"scheme {self.name!r} is level-dependent: this kind needs a stationary scheme")
        return self.symbol.subs(values) if values else self.symbol


#: the kinds available for schemes of every arity (their ``any_arity = True``; the others are binary only)
ANY_ARITY_KINDS = ("mask identity", "sum rules", "symmetry", "interpolatory", "support", "eigenvalues", "reproduction", "norm test", "ck range",
              "smoothness", "holder",
              "smoothness profile", "sobolev", "support after steps", "limit symmetry",
              "weighted series", "asymptotic equivalence", "exponential reproduction")
#: the kinds available for bivariate schemes (their ``bivariate = True``; the others refuse at load time)
BIVARIATE_KINDS = ("sum rules", "reproduction", "smoothness", "holder", "ck range")


def evidence(title: str, result: Result | None = None, text: str = "", table=None) -> Evidence:
    return Evidence(title, text=text, result=result, table=table)


class Kind:
    """Base class of claim kinds (see the module docstring)."""

    name: ClassVar[str] = ""
    #: field -> description (the claim cannot be loaded without them)
    required: ClassVar[dict] = {}
    optional: ClassVar[dict] = {}
    #: does the claim speak of a scheme (field ``scheme``)?
    uses_scheme: ClassVar[bool] = True
    #: does the kind speak of a level-dependent scheme (``level_mask``) rather than a stationary one?
    #: (None: of either)
    level_scheme: ClassVar[bool | None] = False
    #: can the kind speak of a scheme of any arity (arity != 2)?  (the others refuse at load time)
    any_arity: ClassVar[bool] = False
    #: can the kind speak of a bivariate scheme (``bivariate = {...}``)?  (the others refuse at load time)
    bivariate: ClassVar[bool] = False
    #: example fields (TOML lines) for the template of ``subdiv new-paper``
    example: ClassVar[str] = ""
    summary: ClassVar[str] = ""

    def __init__(self, fields: Mapping[str, Any], schemes: Mapping[str, SchemeSpec], where: str):
        self.where = where
        self.fields = dict(fields)
        self.schemes = schemes
        allowed = set(self.required) | set(self.optional) | ({"scheme"} if self.uses_scheme else set())
        unknown = sorted(set(self.fields) - allowed)
        if unknown:
            raise AnalysisError(f"{where}: unknown field {unknown[0]!r} for kind {self.name!r} "
                                f"(its fields: {', '.join(sorted(allowed))})")
        missing = [k for k in self.required if k not in self.fields]
        if self.uses_scheme and "scheme" not in self.fields:
            if len(schemes) == 1:
                self.fields["scheme"] = next(iter(schemes))
            else:
                missing.insert(0, "scheme")
        if missing:
            raise AnalysisError(f"{where}: kind {self.name!r} needs the field {missing[0]!r}")
        self.scheme: SchemeSpec | None = None
        if self.uses_scheme:
            s = self.fields["scheme"]
            if not isinstance(s, str):
                raise AnalysisError(f"{where}: scheme must be the name of one scheme in quotes, e.g. "
                                    f"scheme = \"{next(iter(schemes), 'four-point')}\", not a {type(s).__name__}")
            if s not in schemes:
                raise AnalysisError(f"{where}: unknown scheme {s!r} (the file defines: "
                                    f"{', '.join(sorted(schemes)) or 'no scheme'})")
            self.scheme = schemes[s]
            if self.level_scheme is not None and (self.scheme.level is not None) != self.level_scheme:
                raise AnalysisError(f"{where}: kind {self.name!r} needs a "
                                    + ("level-dependent scheme (level_mask)" if self.level_scheme else
                                       f"stationary scheme; {s!r} is level-dependent (for C^k of a level-dependent "
                                       "scheme use kind 'smoothness')"))
            if self.scheme.bivariate is not None and not self.bivariate:
                raise AnalysisError(f"{where}: kind {self.name!r} is not available for the bivariate scheme {s!r}; "
                                    f"the bivariate kinds are: {', '.join(BIVARIATE_KINDS)}")
            if self.scheme.arity != 2 and not self.any_arity:
                raise AnalysisError(f"{where}: kind {self.name!r} is not available for arity {self.scheme.arity} "
                                    f"(scheme {s!r}); the m-ary kinds are: {', '.join(ANY_ARITY_KINDS)}")
        self.check()

    # ------------------------------------------------------------------ helpers for kinds
    def check(self) -> None:
        """Kind-specific validation at load time (override)."""

    def shown_kind(self) -> str:
        """The kind shown in reports and verdict files (the kind's name)."""
        return self.name

    @property
    def arity(self) -> int:
        """The arity of the claim's scheme (2 without a scheme)."""
        return self.scheme.arity if self.scheme is not None else 2

    def get(self, key: str, default=None):
        return self.fields.get(key, default)

    def values(self) -> dict:
        """The parameter values of field ``at`` (checked)."""
        return self.scheme.values(self.get("at"), self.where)

    def symbol(self) -> LaurentSymbol:
        """The scheme's symbol with the parameters of ``at`` substituted."""
        return self.scheme.at(self.values())

    def bivariate_mask(self):
        """The bivariate scheme's mask with the parameters of ``at`` substituted."""
        vals = self.values()
        return self.scheme.bivariate.at({k: v for k, v in vals.items()}) if vals else self.scheme.bivariate

    def integer(self, key: str, lo: int = 0) -> int | None:
        v = self.get(key)
        if v is None:
            return None
        if isinstance(v, bool) or not isinstance(v, int) or v < lo:
            raise AnalysisError(f"{self.where}: field {key!r} must be an integer >= {lo}, not {v!r}")
        return v

    def boolean(self, key: str, default=None) -> bool:
        """The field ``key`` as a TOML boolean (``default`` when absent; required when ``default`` is None)."""
        v = self.get(key, default)
        if not isinstance(v, bool):
            raise AnalysisError(f"{self.where}: field {key!r} must be true or false")
        return v

    def number(self, key: str):
        v = self.get(key)
        return None if v is None else parse_number(v, f"{self.where}: field {key!r}")

    def interval(self, key: str):
        v = self.get(key)
        return None if v is None else parse_interval(v, f"{self.where}: field {key!r}")

    def single_parameter(self) -> sp.Symbol:
        params = list(self.symbol().params)
        if len(params) != 1:
            raise AnalysisError(f"{self.where}: kind {self.name!r} needs exactly one free parameter "
                                f"(scheme {self.scheme.name!r} has {len(params)} after 'at'); fix the others with at = {{...}}")
        return params[0]

    def where_text(self) -> str:
        vals = self.values() if self.scheme is not None else {}
        name = self.scheme.name if self.scheme is not None else ""
        return name + (" at " + ", ".join(f"{k} = {sp.sstr(v)}" for k, v in vals.items()) if vals else "")

    # verdict shorthands
    certified, refuted, inconclusive = staticmethod(certified), staticmethod(refuted), staticmethod(inconclusive)

    def evaluate(self) -> Verdict:  # pragma: no cover - every kind overrides it
        raise NotImplementedError


#: work budget of the certified maximisation of alpha in a smoothness profile: a number of
#: sub-intervals and a generous number of work units (both counted, so a golden file does not
#: depend on the machine's speed or load)
ALPHA_MAX_INTERVALS = 800
ALPHA_MAX_WORK = 300_000


def alpha_maximum(a: LaurentSymbol, p, lo, hi, curve: list, *, arity: int = 2, note: str = ""):
    """The largest Hölder exponent of the one-parameter family ``a`` over ``[lo, hi]`` and where it is
    attained, certified: :func:`analysis.regularity.maximize_box.maximize_holder_box` (float search, the
    certified alpha at the maximiser t*, a certified upper bound of alpha over the whole interval from
    products of the transition matrices on sub-intervals) within :data:`ALPHA_MAX_INTERVALS` sub-intervals.
    Returns the text line, its key numbers and the evidence (with the sampled alpha curve as a table).
    When the maximisation is not certified, the maximum among the samples is reported and called sampled.

    Algorithm: branch and bound (see :mod:`analysis.regularity.maximize`); the gap target is 1/100.
    References: DESIGN.md (Hölder exponent); issue 11 item 5 ("the largest Hölder exponent and where it
    is attained").
    """
    from ...regularity.maximize_box import maximize_holder_box

    if arity == 2:
        from ...regularity.maximize import maximize_holder

        r1 = maximize_holder(a, p, within=(lo, hi), gap=sp.Rational(1, 100), max_intervals=ALPHA_MAX_INTERVALS,
                             budget=ALPHA_MAX_WORK)
        r = r1.__class__(value=None if r1.value is None else {p.name: r1.value}, lower=r1.lower, upper=r1.upper,
                         status=r1.status, witness=r1.witness, provenance=r1.provenance)
    else:
        r = maximize_holder_box(a, {p.name: (lo, hi)}, arity=arity, gap=sp.Rational(1, 100),
                                max_boxes=ALPHA_MAX_INTERVALS, budget=ALPHA_MAX_WORK)
    line, nums, ev = sampled_alpha_maximum(p, curve, note)
    if r.status != "certified" or r.value is None or r.upper is None:
        why = r.provenance.get("message", "not certified")
        return line + f" (certified maximisation: {why})", nums, ev
    t = r.value[p.name]
    alo, aup = sp.Rational(r.lower), sp.Rational(r.upper)
    h = r.witness.get("alpha_at")
    hup = sp.Rational(h.upper) if h is not None and h.upper is not None else alo
    exact = alo == aup
    line = (f"largest alpha over [{sp.sstr(lo)}, {sp.sstr(hi)}]: " +
            (f"exactly {float(alo):.10f} at {p.name} = {sp.sstr(t)}" if exact else
             f"in [{float(alo):.10f}, {float(aup):.10f}] (certified gap {float(aup - alo):.2g}), attained up to "
             f"the gap at {p.name} = {sp.sstr(t)} where alpha in [{float(alo):.10f}, {float(hup):.10f}]"))
    nums = [Number("alpha max at", t),
            Number("alpha max lower", alo, lower=alo, upper=hup) if alo == hup else
            Number("alpha max lower", float(alo), tol=1e-9, lower=alo, upper=hup),
            Number("alpha max upper", aup, lower=aup, upper=aup) if aup.q < 10 ** 6 else
            Number("alpha max upper", float(aup), tol=1e-9, lower=aup, upper=aup)]
    ev = evidence("Hölder exponent over the parameter", text=line + f"; {r.witness.get('intervals')} sub-intervals",
                  table=ev.table)
    return line, nums, ev


def sampled_alpha_maximum(p, curve: list, note: str = ""):
    """The largest certified Hölder exponent among the sample points of an alpha curve: the text
    line, its key numbers and the evidence table (the maximum is *sampled*, and says so).
    Used by the smoothness profile (:mod:`.profile`) of every arity."""
    best = max((x for x in curve if x["lower"] is not None), key=lambda x: x["lower"], default=None)
    alpha_line, nums = "no certified alpha", []
    if best is not None:
        alo, ahi = sp.Rational(best["lower"]), sp.Rational(best["upper"])
        alpha_line = (f"largest alpha at the {len(curve)} sample points"
                      f"{note}: {p.name} = {sp.sstr(best['p'])}, "
                      f"alpha in [{float(alo):.10f}, {float(ahi):.10f}] ({best['status']} enclosure at that point; "
                      "the maximum over the interval is sampled, not certified)")
        nums = [Number("alpha max (sampled) at", best["p"]),
                Number("alpha max (sampled)", alo, lower=alo, upper=ahi) if alo == ahi else
                Number("alpha max (sampled)", float((alo + ahi) / 2), tol=max(1e-6, 2 * float(ahi - alo)),
                       lower=alo, upper=ahi)]
    ev = evidence("Hölder exponent over the parameter", text=alpha_line,
                  table=(("p", "alpha lower", "alpha upper", "status"),
                         *((sp.sstr(x["p"]), f"{float(x['lower']):.8f}" if x["lower"] is not None else "-",
                            f"{float(x['upper']):.8f}" if x["upper"] is not None else "-", x["status"])
                           for x in curve)))
    return alpha_line, nums, ev


def set_text(S) -> str:
    """A sympy set as ``(a, b) U [c, d]`` (``empty`` for the empty set)."""
    if S == sp.EmptySet or S.is_empty is True:
        return "empty"
    parts = S.args if isinstance(S, sp.Union) else (S,)
    out = []
    for x in parts:
        if isinstance(x, sp.Interval):
            out.append(f"{'(' if x.left_open else '['}{sp.sstr(x.start)}, {sp.sstr(x.end)}{')' if x.right_open else ']'}")
        else:
            out.append(sp.sstr(x))
    return " U ".join(out)


def point_in(S):
    """A simple exact point of the sympy set ``S`` (a rational inside an interval of positive length,
    else an element of a finite part), or None."""
    parts = S.args if isinstance(S, sp.Union) else (S,)
    for x in parts:
        if isinstance(x, sp.Interval) and bool(x.end > x.start):
            lo, hi = x.start, x.end
            if lo == -sp.oo:
                lo = hi - 2
            if hi == sp.oo:
                hi = lo + 2
            for den in (1, 2, 3, 5, 10, 30, 100, 1000, 10 ** 6):
                q = sp.Rational(round(float((lo + hi) / 2) * den), den)
                if S.contains(q) is sp.true:
                    return q
    for x in parts:
        if isinstance(x, sp.FiniteSet) and x.args:
            return x.args[0]
    return None
