"""Claims of papers and their verdicts: the proof-check model behind ``subdiv report``/``check``.

A paper module in :mod:`schemes` (one per paper) exposes ``PAPER = Paper(...)`` with a list of
:class:`Claim`. Each claim has

* an **id**: the paper's file number and the paper's own numbering, ``"004:Theorem5.2"``,
  ``"004:(3.6)"``, ``"004:Corollary4.5"``;
* the **statement as printed** (verbatim, garbled extraction kept) and, when the print is
  garbled, **our reading** of it with the explanation;
* a **kind** (:data:`KINDS`), the **objects** it speaks of (catalogue slugs, parameters);
* an **evaluate** function returning a :class:`Verdict`, and the **CLI command** that
  reproduces the computation.

A :class:`Verdict` has a status from :mod:`analysis.result` used the same way everywhere:

========================  =====================================================================
status (label)            meaning
========================  =====================================================================
certified (CERTIFIED      exact arithmetic or rigorous enclosures prove the statement
TRUE)
refuted (REFUTED)         a certified counterexample or certified different value; the verdict
                          carries the **corrected statement**
numerical (NUMERICAL)     strong floating-point evidence, not a proof
inconclusive              not settled; the verdict says **what would settle it**
(INCONCLUSIVE)
========================  =====================================================================

plus the evidence (analysis :class:`~analysis.result.Result` objects, formulas, tables), key
**numbers** with regression tolerances, optional **sharpness** information ("true but not
sharp: the exact set is ...") and figure data. A verdict never says more than its evidence:
a certified or refuted verdict whose evidence contains a numerical or inconclusive Result is
rejected when it is built.

Nothing here formats reports (:mod:`analysis.report.render` renders, :mod:`analysis.cli.report` runs).

Examples
--------
>>> from analysis.result import Result, CERTIFIED, REFUTED
>>> def two_plus_two():
...     r = Result(value=4, status=CERTIFIED, provenance={"method": "exact"})
...     return Verdict(REFUTED, "2 + 2 = 4, not 5", corrected="2 + 2 = 4",
...                    evidence=[Evidence("exact sum", result=r)], numbers=[Number("sum", 4)])
>>> c = Claim(id="999:(1.1)", kind="identity", statement="2 + 2 = 5", evaluate=two_plus_two)
>>> paper = Paper(id="999", title="A toy", citation="nobody (2024)", claims=[c])
>>> [e.verdict.label for e in evaluate_paper(paper)]
['REFUTED']
>>> Verdict(CERTIFIED, "x", evidence=[Evidence("float", result=Result(1.0, status="numerical"))])
Traceback (most recent call last):
...
ValueError: a certified verdict cannot rest on numerical evidence (float)

Algorithm
---------
Evaluation calls each claim's function, times it, and turns an exception into an
INCONCLUSIVE verdict that names the error (so one failing claim never hides the others).
:func:`verdicts_json` keeps statuses and key numbers; :func:`compare_verdicts` compares a fresh
evaluation with the reviewed golden file: statuses must be equal, numbers equal within their
tolerances (exact strings when the tolerance is 0).

References
----------
DESIGN.md ("Results contract"); STYLE.md ("Claims tested against published tables").
"""

from __future__ import annotations

import importlib
import math
from pathlib import Path
import pkgutil
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Mapping, Sequence

import sympy as sp

from ..jsonable import jsonable
from ..result import CERTIFIED, INCONCLUSIVE, NUMERICAL, REFUTED, STATUSES, Result
from ..algebra.reader import as_expr

__all__ = ["golden_path", "KINDS", "LABELS", "Number", "Evidence", "Series", "Figure", "Verdict", "Claim", "Paper",
           "Evaluated", "papers", "get_paper", "evaluate_claim", "evaluate_paper", "verdicts_json", "python_notice",
           "compare_verdicts", "exact_set", "contains_interval", "certified", "refuted",
           "inconclusive", "exact_result"]

#: Human-readable labels of the four statuses in reports.
LABELS = {CERTIFIED: "CERTIFIED TRUE", REFUTED: "REFUTED", NUMERICAL: "NUMERICAL",
          INCONCLUSIVE: "INCONCLUSIVE"}

#: Claim kinds (free to extend; a report groups nothing by kind, it only shows it).
KINDS = ("mask identity", "factorization", "sum rules", "norm test", "smoothness", "holder value",
         "eigenvalues", "support", "series convergence", "inequality", "identity", "reproduction",
         "symmetry", "gibbs condition", "end rules", "necessary condition", "convergence")


# --------------------------------------------------------------------------------------------
# verdict pieces
# --------------------------------------------------------------------------------------------

def _to_float(x) -> float | None:
    try:
        v = complex(sp.N(as_expr(x), 30))
    except (TypeError, ValueError, AttributeError, sp.SympifyError):   # text such as "(0, 1/8)": no float
        return None
    if v.imag != 0 or math.isnan(v.real):
        return None
    return v.real


@dataclass(frozen=True)
class Number:
    """A key number of a verdict, kept under regression.

    ``value`` is exact (sympy) when possible, else a float; ``tol`` is the absolute tolerance of
    the regression check (0: the exact string must not change). ``lower``/``upper`` give an
    enclosure when the value is not exact.

    >>> Number("upper end", sp.Rational(25, 7)).to_json()["float"]
    3.5714285714285716
    """

    name: str
    value: Any
    tol: float = 0.0
    lower: Any = None
    upper: Any = None
    note: str = ""

    @property
    def float(self) -> float | None:
        if isinstance(self.value, bool):
            return float(self.value)
        return _to_float(self.value)

    def exact_text(self) -> str:
        if isinstance(self.value, float):
            return repr(self.value)
        if isinstance(self.value, (bool, str)):
            return str(self.value)
        return sp.sstr(as_expr(self.value))

    def to_json(self) -> dict:
        out = {"exact": self.exact_text(), "float": self.float, "tol": self.tol}
        if self.lower is not None or self.upper is not None:
            out["lower"] = jsonable(self.lower)
            out["upper"] = jsonable(self.upper)
        return out


@dataclass(frozen=True)
class Evidence:
    """One piece of evidence: a title, Unicode text, an optional formula (LaTeX, rendered
    offline by the report), an optional analysis :class:`Result`, and an optional table
    (a header row followed by rows of strings)."""

    title: str
    text: str = ""
    latex: str | None = None
    result: Result | None = None
    table: tuple | None = None


@dataclass(frozen=True)
class Series:
    """A polyline for a figure: ``label``, ``x``, ``y`` (floats) and a matplotlib format."""

    label: str
    x: tuple
    y: tuple
    style: str = "-"


@dataclass(frozen=True)
class Figure:
    """Data for one figure (the report draws it; nothing is computed there).

    ``bands`` are shaded parameter ranges ``(lo, hi, label, colour)``; ``hlines`` horizontal
    lines ``(y, label)``; ``equal_aspect`` for curves in the plane.
    """

    name: str
    title: str
    series: tuple
    xlabel: str = ""
    ylabel: str = ""
    bands: tuple = ()
    hlines: tuple = ()
    equal_aspect: bool = False
    ylim: tuple | None = None


@dataclass(frozen=True)
class Verdict:
    """The outcome of checking a claim (see the module docstring for the statuses)."""

    status: str
    summary: str
    corrected: str | None = None
    settle: str | None = None
    sharpness: str | None = None
    evidence: tuple = ()
    numbers: tuple = ()
    figures: tuple = ()
    #: a smoothness profile of a family (kind ``smoothness profile``): its C^j sets in short, the largest
    #: alpha, the exceptional values and ``beside`` (claim id, sentence) for the claims it speaks to
    profile: Mapping | None = field(default=None, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "evidence", tuple(self.evidence))
        object.__setattr__(self, "numbers", tuple(self.numbers))
        object.__setattr__(self, "figures", tuple(self.figures))
        if self.status not in STATUSES:
            raise ValueError(f"unknown status {self.status!r}; expected one of {STATUSES}")
        if self.status == REFUTED and not self.corrected:
            raise ValueError("a refuted verdict needs the corrected statement")
        if self.status == INCONCLUSIVE and not self.settle:
            raise ValueError("an inconclusive verdict must say what would settle it")
        if self.status in (CERTIFIED, REFUTED):
            for ev in self.evidence:
                r = ev.result
                if r is not None and r.status in (NUMERICAL, INCONCLUSIVE):
                    raise ValueError(f"a {self.status} verdict cannot rest on {r.status} evidence "
                                     f"({ev.title})")
            if not any(ev.result is not None and ev.result.status in (CERTIFIED, REFUTED) for ev in self.evidence):
                raise ValueError(f"a {self.status} verdict needs at least one certified or refuted Result "
                                 "in its evidence")
        names = [n.name for n in self.numbers]
        if len(set(names)) != len(names):
            raise ValueError(f"duplicate number names in a verdict: {names}")

    @property
    def label(self) -> str:
        return LABELS[self.status]


def certified(summary: str, **kw) -> Verdict:
    """Shorthand for ``Verdict(CERTIFIED, summary, ...)``."""
    return Verdict(CERTIFIED, summary, **kw)


def refuted(summary: str, corrected: str, **kw) -> Verdict:
    """Shorthand for ``Verdict(REFUTED, summary, corrected=corrected, ...)``."""
    return Verdict(REFUTED, summary, corrected=corrected, **kw)


def inconclusive(summary: str, settle: str, **kw) -> Verdict:
    """Shorthand for ``Verdict(INCONCLUSIVE, summary, settle=settle, ...)``."""
    return Verdict(INCONCLUSIVE, summary, settle=settle, **kw)


def exact_result(value, method: str, **witness) -> Result:
    """A certified :class:`Result` for an exact (sympy) computation done in a claim.

    >>> exact_result(2, "exact evaluation").status
    'certified'
    """
    return Result(value=value, status=CERTIFIED, witness=witness,
                  provenance={"method": method, "arithmetic": "exact"})


# --------------------------------------------------------------------------------------------
# claims and papers
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Claim:
    """A checkable statement of a paper (see the module docstring).

    ``evaluate()`` returns a :class:`Verdict`. ``reading`` is our reading of a garbled
    ``statement`` and ``reading_note`` explains it. ``command`` is the ``subdiv`` command line
    that reproduces the computation. ``runs_python`` is the evaluator (``"package.module:function"``)
    when evaluating the claim runs Python code from a paper file that the user allowed with
    ``--allow-python`` (the report then says so); empty otherwise (bundled papers included).
    """

    id: str
    kind: str
    statement: str
    evaluate: Callable[[], Verdict] = field(repr=False, compare=False)
    title: str = ""
    reading: str | None = None
    reading_note: str | None = None
    objects: tuple = ()
    params: tuple = ()
    command: str = ""
    location: str = ""
    runs_python: str = ""

    def __post_init__(self) -> None:
        if ":" not in self.id or not self.id.split(":", 1)[1]:
            raise ValueError(f"claim id {self.id!r} must be '<paper>:<numbering>'")
        object.__setattr__(self, "objects", tuple(self.objects))
        object.__setattr__(self, "params", tuple(self.params))

    @property
    def paper(self) -> str:
        return self.id.split(":", 1)[0]


@dataclass(frozen=True)
class Paper:
    """A paper: id (its file number, ``"004"``), title, citation, claims, source file, notes."""

    id: str
    title: str
    citation: str
    claims: tuple = ()
    source: str = ""
    notes: str = ""
    #: the module that defines ``PAPER`` (set when the paper is found by :func:`papers`)
    origin: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "claims", tuple(self.claims))
        ids = [c.id for c in self.claims]
        dup = {i for i in ids if ids.count(i) > 1}
        if dup:
            raise ValueError(f"duplicate claim ids in paper {self.id}: {sorted(dup)}")
        wrong = [i for i in ids if not i.startswith(self.id + ":")]
        if wrong:
            raise ValueError(f"claim ids of paper {self.id} must start with '{self.id}:': {wrong}")

    def claim(self, cid: str) -> Claim:
        for c in self.claims:
            if c.id == cid:
                return c
        raise KeyError(cid)


#: Packages searched for papers: each module or sub-package with a module-level ``PAPER``.
PAPER_PACKAGES: tuple[str, ...] = ("papers",)


def papers(packages: str | Sequence[str] = PAPER_PACKAGES) -> dict[str, Paper]:
    """All papers: every module or sub-package of ``packages`` with a module-level ``PAPER``
    (sorted by id). A new paper needs nothing but its folder ``papers/<name>/`` whose
    ``__init__.py`` defines ``PAPER``.
    """
    found: dict[str, Paper] = {}
    for mod, paper in _paper_modules(packages):
        if paper.id in found:
            raise RuntimeError(f"two modules define paper {paper.id}")
        found[paper.id] = paper
    return dict(sorted(found.items()))


def _paper_modules(packages: str | Sequence[str], prefer: str = ""):
    """``(module, PAPER)`` for the modules of ``packages`` that define a paper, each package's modules
    in name order, those whose name ends with ``prefer`` first (imported one at a time, as asked for:
    a paper's folder is usually named after its id, so a command on one paper imports that paper only)."""
    for package in ([packages] if isinstance(packages, str) else packages):
        try:
            pkg = importlib.import_module(package)
        except ModuleNotFoundError:
            continue
        infos = sorted(pkgutil.iter_modules(pkg.__path__), key=lambda m: m.name)
        if prefer:
            infos.sort(key=lambda m: not m.name.endswith(prefer))
        for info in infos:
            mod = importlib.import_module(f"{package}.{info.name}")
            paper = getattr(mod, "PAPER", None)
            if isinstance(paper, Paper):
                if not paper.origin:
                    object.__setattr__(paper, "origin", mod.__name__)
                yield mod, paper


def _find_paper(key: str, packages: str | Sequence[str] = PAPER_PACKAGES) -> Paper | None:
    """The paper with id ``key`` (exactly), loading no more paper modules than needed; None if none."""
    return next((paper for _, paper in _paper_modules(packages, prefer=key) if paper.id == key), None)


def golden_path(paper: Paper) -> Path | None:
    """The paper's golden verdicts, ``verdicts.json`` in its folder (package data, shipped with
    the wheel); ``None`` for a paper defined by a single module (no folder of its own)."""
    if not paper.origin:
        return None
    mod = importlib.import_module(paper.origin)
    f = getattr(mod, "__file__", None)
    if not f or Path(f).name != "__init__.py":
        return None
    return Path(f).parent / "verdicts.json"


def get_paper(pid: str, packages: str | Sequence[str] = PAPER_PACKAGES) -> Paper:
    """The paper with id ``pid`` (``"004"``; ``"4"`` and ``"seed004"`` are accepted too)."""
    from ..result import AnalysisError

    key = str(pid).strip().lower().removeprefix("seed")
    if key.isdigit():
        key = key.zfill(3)
    found = _find_paper(key, packages)
    if found is not None:
        return found
    allp = papers(packages)
    raise AnalysisError(f"unknown paper {pid!r}; known: {', '.join(allp) or 'none'}")


# --------------------------------------------------------------------------------------------
# evaluation
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Evaluated:
    """A claim with its verdict and the evaluation time in seconds."""

    claim: Claim
    verdict: Verdict
    seconds: float
    error: str | None = None


def evaluate_claim(claim: Claim) -> Evaluated:
    """Evaluate one claim; an exception becomes an INCONCLUSIVE verdict naming it."""
    t0 = time.perf_counter()
    try:
        v = claim.evaluate()
        if not isinstance(v, Verdict):
            raise TypeError(f"evaluate() returned {type(v).__name__}, not a Verdict")
        err = None
    except Exception as exc:  # noqa: BLE001 - reported in the verdict
        err = f"{type(exc).__name__}: {exc}"
        v = inconclusive(f"the evaluation failed ({err})",
                         settle="fix the evaluation error and re-run `subdiv report`")
    return Evaluated(claim, v, time.perf_counter() - t0, err)


def evaluate_paper(paper: Paper, progress: Callable[[int, int, Evaluated], None] | None = None,
                   only: Iterable[str] | None = None) -> list[Evaluated]:
    """Evaluate the claims of ``paper`` in order (``only``: a subset of claim ids); the claim running now
    is announced to :mod:`analysis.progress` (shown on a terminal by the command line)."""
    from .. import progress as announce

    wanted = None if only is None else set(only)
    claims = [c for c in paper.claims if wanted is None or c.id in wanted]
    out = []
    for k, c in enumerate(claims, start=1):
        with announce.part(f"claim {k}/{len(claims)} {c.id}"):
            ev = evaluate_claim(c)
        out.append(ev)
        if progress is not None:
            progress(k, len(claims), ev)
    return out


def python_notice(results: Sequence[Evaluated]) -> str | None:
    """The notice a report carries when evaluating its claims ran Python code from the paper file
    (claims with :attr:`Claim.runs_python`, allowed by ``--allow-python``); ``None`` when none did.

    >>> c = Claim(id="9:a", kind="python", statement="s", evaluate=lambda: None, runs_python="mypkg.ev:check")
    >>> python_notice([Evaluated(c, inconclusive("x", settle="y"), 0.0)])
    'this report ran Python code from the paper file: evaluator mypkg.ev:check (claim 9:a)'
    """
    ran = [ev.claim for ev in results if ev.claim.runs_python]
    if not ran:
        return None
    return "this report ran Python code from the paper file: " + "; ".join(
        f"evaluator {c.runs_python} (claim {c.id})" for c in ran)


def verdicts_json(results: Mapping[str, Sequence[Evaluated]], titles: Mapping[str, str] | None = None) -> dict:
    """The golden-file content: per paper, per claim, the status and key numbers.

    ``titles`` (paper id -> title) for papers that are not bundled (paper files).

    Only what :func:`compare_verdicts` checks goes in (plus kind and summary, for reading, and the
    :func:`python_notice` as ``ran_python`` when the evaluation ran Python code from a paper file); no
    timings or dates, so that regenerating an unchanged report leaves the file unchanged.
    """
    out: dict = {"schema": 1, "papers": {}}
    for pid, evs in sorted(results.items()):
        paper = _find_paper(pid) if titles is None else None
        claims = {}
        for ev in evs:
            claims[ev.claim.id] = {
                "kind": ev.claim.kind,
                "status": ev.verdict.status,
                "label": ev.verdict.label,
                "summary": ev.verdict.summary,
                "numbers": {n.name: n.to_json() for n in ev.verdict.numbers},
            }
            if ev.claim.runs_python:
                claims[ev.claim.id]["ran_python"] = ev.claim.runs_python
        title = titles[pid] if titles is not None and pid in titles else (paper.title if paper else "")
        out["papers"][pid] = {"title": title, "claims": claims}
        notice = python_notice(evs)
        if notice:
            out["papers"][pid]["ran_python"] = notice
    return out


def _fmt(x) -> str:
    return "missing" if x is None else str(x)


def compare_verdicts(golden: Mapping, fresh: Mapping, papers_: Iterable[str] | None = None) -> list[str]:
    """Readable differences between a golden verdicts file and a fresh one (empty: agree).

    Statuses must be equal; numbers must agree within the golden tolerance (exact text when
    the tolerance is 0); claims may not appear or disappear.

    >>> g = {"papers": {"9": {"claims": {"9:a": {"status": "certified",
    ...      "numbers": {"x": {"exact": "1/2", "float": 0.5, "tol": 1e-9}}}}}}}
    >>> f = {"papers": {"9": {"claims": {"9:a": {"status": "refuted",
    ...      "numbers": {"x": {"exact": "0.6", "float": 0.6, "tol": 1e-9}}}}}}}
    >>> for line in compare_verdicts(g, f): print(line)
    9:a: status changed: certified -> refuted
    9:a: number 'x' moved: 0.5 -> 0.6 (|diff| 0.1 > tol 1e-09)
    """
    diffs: list[str] = []
    gp, fp = golden.get("papers", {}), fresh.get("papers", {})
    keys = sorted(set(gp) | set(fp)) if papers_ is None else sorted(papers_)
    for pid in keys:
        if pid not in gp:
            diffs.append(f"paper {pid}: not in the golden file (run `subdiv report {pid}` and review)")
            continue
        if pid not in fp:
            diffs.append(f"paper {pid}: in the golden file but not evaluated")
            continue
        gc, fc = gp[pid].get("claims", {}), fp[pid].get("claims", {})
        for cid in sorted(set(gc) - set(fc)):
            diffs.append(f"{cid}: claim disappeared (in the golden file, not evaluated now)")
        for cid in sorted(set(fc) - set(gc)):
            diffs.append(f"{cid}: new claim, not in the golden file (status {fc[cid]['status']})")
        for cid in sorted(set(gc) & set(fc)):
            g, f = gc[cid], fc[cid]
            if g.get("status") != f.get("status"):
                diffs.append(f"{cid}: status changed: {g.get('status')} -> {f.get('status')}")
            gn, fn = g.get("numbers", {}), f.get("numbers", {})
            for name in sorted(set(gn) | set(fn)):
                a, b = gn.get(name), fn.get(name)
                if a is None or b is None:
                    diffs.append(f"{cid}: number '{name}' {'appeared' if a is None else 'disappeared'}")
                    continue
                tol = float(a.get("tol") or 0.0)
                fa, fb = a.get("float"), b.get("float")
                if tol == 0.0 or fa is None or fb is None:
                    if a.get("exact") != b.get("exact"):
                        diffs.append(f"{cid}: number '{name}' changed: {_fmt(a.get('exact'))} -> "
                                     f"{_fmt(b.get('exact'))} (exact)")
                    continue
                d = abs(fa - fb)
                if not d <= tol:
                    diffs.append(f"{cid}: number '{name}' moved: {fa!r} -> {fb!r} "
                                 f"(|diff| {d:.3g} > tol {tol:.3g})")
    return diffs


# --------------------------------------------------------------------------------------------
# exact sets of one parameter (helpers for claims about parameter ranges)
# --------------------------------------------------------------------------------------------

def _ra(x):
    from ..algebra.algebraic import RealAlgebraic

    return x if isinstance(x, RealAlgebraic) else RealAlgebraic.from_expr(as_expr(x))


def exact_set(predicate: Callable[[sp.Expr], bool], critical: Iterable, within=(-sp.oo, sp.oo)):
    """The exact set ``{x in within : predicate(x)}`` for a predicate that can only change its
    truth value at the given critical points (an :class:`~analysis.algebra.algebraic.IntervalSet`).

    ``critical`` holds sympy numbers, :class:`~analysis.algebra.algebraic.RealAlgebraic` numbers or
    rational polynomials (``sympy.Poly``, whose real roots are taken). ``predicate`` is called
    with exact sympy numbers (a rational in each gap, the closed form of each critical point)
    and must decide exactly (use :func:`analysis.algebra.algebraic.sign`).

    >>> x = sp.Symbol("x")
    >>> s = exact_set(lambda v: abs(9 - 7*v) < 16, [sp.Poly(9 - 7*x - 16, x), sp.Poly(9 - 7*x + 16, x)])
    >>> print(s)
    (-1, 25/7)

    Algorithm
    ---------
    Sort the critical points exactly, test one rational point per open gap and every critical
    point, merge adjacent members. Correct whenever the truth value is constant on each gap.
    """
    from ..algebra.algebraic import IntervalSet, RealAlgebraic, _exact_sort

    pts: list[RealAlgebraic] = []
    for c in critical:
        if isinstance(c, sp.Poly):
            for f, _ in c.factor_list()[1]:
                if f.degree() > 0:
                    pts.extend(RealAlgebraic.roots_of(f))
        else:
            pts.append(_ra(c))
    lo = None if as_expr(within[0]) == -sp.oo else _ra(within[0])
    hi = None if as_expr(within[1]) == sp.oo else _ra(within[1])
    pts = [p for p in pts if (lo is None or p.compare(lo) > 0) and (hi is None or p.compare(hi) < 0)]
    uniq: list[RealAlgebraic] = []
    for p in _exact_sort(pts):
        if not uniq or uniq[-1].compare(p) != 0:
            uniq.append(p)
    from ..algebra.algebraic import rational_between as _sample_between

    bounds = [lo] + uniq + [hi]
    members = []
    for k, (u, v) in enumerate(zip(bounds[:-1], bounds[1:])):
        q = _sample_between(u, v)
        members.append(("gap", (u, v), bool(predicate(sp.Rational(q)))))
        if k + 1 < len(bounds) - 1:
            x = bounds[k + 1]
            members.append(("point", x, bool(predicate(x.expr))))
    return IntervalSet.from_members(members)


def contains_interval(iset, lo, hi, *, closed: bool = False) -> bool:
    """Whether the interval ``(lo, hi)`` (``[lo, hi]`` if ``closed``) lies in ``iset``, exactly.

    >>> from analysis.algebra.algebraic import IntervalSet, RealAlgebraic as R
    >>> s = IntervalSet([(R.rational(-1), R.rational(sp.Rational(25, 7)), False, False)])
    >>> contains_interval(s, sp.Rational(5, 7), sp.Rational(13, 7)), contains_interval(s, -1, 4)
    (True, False)
    """
    a, b = _ra(lo), _ra(hi)
    for plo, phi, lc, hc in iset.parts:
        left_ok = plo is None or plo.compare(a) < 0 or (plo.compare(a) == 0 and (lc or not closed))
        right_ok = phi is None or phi.compare(b) > 0 or (phi.compare(b) == 0 and (hc or not closed))
        if left_ok and right_ok:
            return True
    return False
