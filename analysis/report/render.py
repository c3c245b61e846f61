"""Rendering of proof-check reports: ``reports/<paper>.md``, ``reports/<paper>.html`` and figures.

Nothing here computes: the verdicts, numbers, tables and figure data come from
:mod:`analysis.claims.model`; this module only lays them out.

Formulas
--------
MathJax/KaTeX need network or bundled JavaScript, which the reports must not depend on. The HTML
report typesets mathematics as **MathML** (:mod:`analysis.report.mathml`; browsers render it
natively, offline): the evidence formulas, the exact key numbers, the paper's quoted LaTeX (with the
source beside it), and the plain-text formulas of the prose. For the Markdown report each
formula's LaTeX is rendered by **matplotlib mathtext to a small SVG** (no TeX installation, no
JavaScript; every browser and Markdown viewer shows SVG offline), stored under
``reports/figures/formulas/`` with a name derived from a hash of the formula. Every run rewrites
every file it refers to (atomically: a damaged or stale file is replaced; the output is
deterministic, so re-rendering an unchanged report leaves the bytes unchanged), and the CLI then
removes the figures it wrote earlier that no report refers to any more
(:func:`analysis.report.files.record_written`, :func:`analysis.report.files.remove_orphans`). The
Unicode/plain-text form is always printed beside it (and is the image's ``alt`` text); when
mathtext cannot parse a formula, only the text is shown.

Files
-----
Every file is written inside the output folder (:func:`analysis.report.files.inside`): the paper id
and the figure names must be slugs (:mod:`analysis.claims.names`), and a symbolic link leading out of
the folder is refused. Text from a paper file is escaped in both reports: in the Markdown report
``&``, ``<``, ``>`` become entities and ``[``, ``]`` (``|`` in tables) are escaped, so no paper text becomes
HTML or a link (``javascript:``); code spans are delimited so that their text cannot close them. When evaluating the claims ran Python code from a paper file
(``--allow-python``), the report says so at the top and at each such claim
(:func:`analysis.claims.model.python_notice`).

Examples
--------
>>> from analysis.claims.model import Claim, Evidence, Paper, certified, evaluate_paper, exact_result
>>> ok = lambda: certified("yes", evidence=[Evidence("1 - 1", result=exact_result(0, "exact"))])
>>> p = Paper(id="998", title="Toy", citation="-", claims=[
...     Claim(id="998:(1)", kind="identity", statement="1 = 1", evaluate=ok)])
>>> md = markdown(p, evaluate_paper(p), figures={})
>>> "| 998:(1) | identity | CERTIFIED TRUE |" in md
True

References
----------
matplotlib mathtext: https://matplotlib.org/stable/users/explain/text/mathtext.html
"""

from __future__ import annotations

import hashlib
import html as _html
import io
import os
import re
from pathlib import Path
from typing import Mapping, Sequence

from ..claims.model import Evaluated, Figure, Paper, python_notice
from ..claims.names import MAX_GENERATED, check_slug
from .files import atomic_write_bytes, atomic_write_text, inside, record_written
from .mathml import has_latex, latex_mathml, pretty_text, quote_html, sympy_mathml

__all__ = ["render_paper", "markdown", "html", "render_figure", "render_formula", "summary_table", "beside_notes",
           "profiles"]

_COLOURS = {"certified": "#1a7f37", "refuted": "#cf222e", "numerical": "#9a6700", "inconclusive": "#6e7781"}


def _mpl():
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "subdiv"        # deterministic SVG ids
    import matplotlib.pyplot as plt

    return plt


def render_formula(latex: str, outdir: Path) -> str | None:
    """Render ``$latex$`` with mathtext to ``outdir/f-<hash>.svg`` (always rewritten, atomically); the
    file name, or None when mathtext cannot parse the formula (a stale file of that name is removed)."""
    name = "f-" + hashlib.sha1(latex.encode()).hexdigest()[:12] + ".svg"
    path = inside(outdir, name)
    plt = _mpl()
    fig = plt.figure(figsize=(0.01, 0.01))
    try:
        fig.text(0, 0, f"${latex}$", fontsize=12)
        buf = io.BytesIO()
        fig.savefig(buf, format="svg", bbox_inches="tight", pad_inches=0.03, transparent=True,
                    metadata={"Date": None})
    except Exception:  # noqa: BLE001 - mathtext cannot parse this formula: text only
        if path.is_file():
            path.unlink()
        return None
    finally:
        plt.close(fig)
    outdir.mkdir(parents=True, exist_ok=True)
    atomic_write_bytes(path, buf.getvalue())
    return name


def render_figure(fig: Figure, outdir: Path) -> str:
    """Draw a :class:`~analysis.claims.model.Figure` to ``outdir/<name>.png`` (the name a slug; written
    atomically); returns the file name."""
    name = check_slug(fig.name, "figure name", '"blf-four-point"', MAX_GENERATED) + ".png"
    path = inside(outdir, name)
    plt = _mpl()
    f, ax = plt.subplots(figsize=(7, 4.2), dpi=110)
    for lo, hi, label, colour in fig.bands:
        ax.axvspan(lo, hi, alpha=0.15, color=colour, label=label)
    for y, label in fig.hlines:
        ax.axhline(y, color="k", lw=0.8, ls=":", label=label)
    for s in fig.series:
        ax.plot(s.x, s.y, s.style, lw=1.2, ms=3, label=s.label)
    ax.set_title(fig.title, fontsize=10)
    ax.set_xlabel(fig.xlabel)
    ax.set_ylabel(fig.ylabel)
    if fig.ylim:
        ax.set_ylim(*fig.ylim)
    if fig.equal_aspect:
        ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    outdir.mkdir(parents=True, exist_ok=True)
    f.tight_layout()
    buf = io.BytesIO()
    f.savefig(buf, format="png", metadata={"Software": None})
    plt.close(f)
    atomic_write_bytes(path, buf.getvalue())
    return name


def _all_figures(results: Sequence[Evaluated]):
    for ev in results:
        yield from ev.verdict.figures


def summary_table(results: Sequence[Evaluated]) -> list[tuple[str, str, str, str]]:
    """Rows ``(id, kind, label, summary)`` of the verdict table."""
    return [(ev.claim.id, ev.claim.kind, ev.verdict.label, ev.verdict.summary) for ev in results]


def _counts(results: Sequence[Evaluated]) -> str:
    from collections import Counter

    c = Counter(ev.verdict.label for ev in results)
    return ", ".join(f"{n} {k}" for k, n in sorted(c.items()))


_MD_ESCAPES = {"&": "&amp;", "<": "&lt;", ">": "&gt;", "[": "\\[", "]": "\\]"}


def _md(s) -> str:
    """Text from a paper (or computed from it) as Markdown prose that shows as written and cannot become
    markup: ``&``, ``<``, ``>`` as HTML entities (no raw HTML, no ``<javascript:...>`` autolink) and ``[``,
    ``]`` escaped (no link or image, so no ``javascript:`` link).

    >>> _md('<img src=x onerror=alert(2)> [l](javascript:alert(4))')
    '&lt;img src=x onerror=alert(2)&gt; \\\\[l\\\\](javascript:alert(4))'
    """
    return "".join(_MD_ESCAPES.get(ch, ch) for ch in str(s))


def _md_line(s) -> str:
    """:func:`_md` on one line (newlines become spaces)."""
    return _md(" ".join(str(s).splitlines()))


def _md_cell(s) -> str:
    """:func:`_md_line` for a table cell (``|`` escaped so it cannot split the cell)."""
    return _md_line(s).replace("|", "\\|")


def _md_code_cell(s) -> str:
    """:func:`_md_code` for a table cell (``|`` escaped: GitHub tables split at ``|`` even in code)."""
    return _md_code(s).replace("|", "\\|")


def _md_code(s) -> str:
    """``s`` as an inline code span on one line, its delimiter longer than any run of backticks inside
    (so the text cannot close the span and continue as Markdown).

    >>> _md_code("a`b"), _md_code("x")
    ('`` a`b ``', '`x`')
    """
    s = " ".join(str(s).splitlines())
    if "`" not in s:
        return f"`{s}`"
    fence = "`" * (max(len(run) for run in re.findall("`+", s)) + 1)
    return f"{fence} {s} {fence}"


def _anchor(cid: str) -> str:
    return "claim-" + "".join(ch if ch.isalnum() else "-" for ch in cid).strip("-").lower()


def _formula_files(results, outdir: Path) -> dict[str, str | None]:
    out = {}
    for ev in results:
        for e in ev.verdict.evidence:
            if e.latex and e.latex not in out:
                out[e.latex] = render_formula(e.latex, inside(outdir, "formulas"))
    return out


def markdown(paper: Paper, results: Sequence[Evaluated], figures: Mapping[str, str],
             formulas: Mapping[str, str | None] | None = None) -> str:
    """The Markdown report (figure/formula files given relative to ``reports/figures``)."""
    formulas = formulas or {}
    L = [f"# Proof-check report {paper.id}: {_md_line(paper.title)}", "",
         f"*Source:* {_md_line(paper.citation)}  ", f"*Text:* {_md_code(paper.source)}  ",
         "*Generated by* `subdiv report " + paper.id + "` — do not edit by hand.", ""]
    notice = python_notice(results)
    if notice:
        L += [f"> **Warning: {notice[0].upper() + notice[1:]}.** The verdicts of those claims are what that code "
              "returned, not computations of this tool.", ""]
    if paper.notes:
        L += [_md(paper.notes), ""]
    L += ["Statuses: **CERTIFIED TRUE** (exact arithmetic or rigorous enclosures prove it), **REFUTED** "
          "(certified counterexample or different value; the corrected statement is given), "
          "**NUMERICAL** (floating-point evidence only), **INCONCLUSIVE** (not settled; what would settle "
          "it is given).", "", f"**{len(results)} claims:** {_counts(results)}.", "",
          "## Verdicts", "", "| claim | kind | verdict | summary |", "|---|---|---|---|"]
    for cid, kind, label, summ in summary_table(results):
        L.append(f"| {_md_cell(cid)} | {_md_cell(kind)} | {_md_cell(label)} | {_md_cell(summ)} |")
    L.append("")
    besides = beside_notes(paper, results)
    L += _md_profiles(paper, results)
    for ev in results:
        c, v = ev.claim, ev.verdict
        L += [f"## {_md_line(c.id)} — {_md_line(c.title)}" if c.title else f"## {_md_line(c.id)}", "",
              f"<a id=\"{_anchor(c.id)}\"></a>", "",
              f"*Kind:* {_md_line(c.kind)}. *Where:* {_md_line(c.location or '-')}. *Objects:* "
              f"{_md_line(', '.join(c.objects) or '-')}.", "",
              "**As printed:**", "", "> " + _md_line(c.statement), ""]
        if c.reading:
            L += [f"**As read:** {_md_line(c.reading)}", ""]
        if c.reading_note:
            L += [f"*Reading:* {_md_line(c.reading_note)}", ""]
        if c.runs_python:
            L += [f"*Ran Python code from the paper file:* evaluator {_md_code(c.runs_python)}.", ""]
        L += [f"**Verdict: {_md_line(v.label)}.** {_md_line(v.summary)}", ""]
        for src, text, _ in besides.get(c.id, ()):
            L += [f"**Certified profile beside the claim** (from {_md_line(src)}): {_md_line(text)}", ""]
        if v.corrected:
            L += [f"**Corrected statement:** {_md_line(v.corrected)}", ""]
        if v.sharpness:
            L += [f"**Sharpness:** {_md_line(v.sharpness)}", ""]
        if v.settle:
            L += [f"**What would settle it:** {_md_line(v.settle)}", ""]
        if v.evidence:
            L += ["**Evidence:**", ""]
        for e in v.evidence:
            line = f"- *{_md_line(e.title)}*"
            if e.result is not None:
                line += f" [{_md_line(e.result.status)}; {_md_line(e.result.provenance.get('method', ''))}]"
            if e.text:
                line += f": {_md_line(e.text)}"
            L.append(line)
            if e.latex:
                f = formulas.get(e.latex)
                if f:
                    L.append(f"\n  ![formula](figures/formulas/{f})\n")
                L.append(f"  {_md_code(e.latex)}")
            if e.table:
                L += ["", "  | " + " | ".join(_md_cell(h) for h in e.table[0]) + " |",
                      "  |" + "---|" * len(e.table[0])]
                L += ["  | " + " | ".join(_md_cell(x) for x in row) + " |" for row in e.table[1:]]
                L.append("")
        if v.numbers:
            L += ["", "**Key numbers (regression):**", "", "| name | exact | float | tolerance |", "|---|---|---|---|"]
            for n in v.numbers:
                fl = n.float
                L.append(f"| {_md_cell(n.name)} | {_md_code_cell(n.exact_text())} | {'' if fl is None else repr(fl)} | {n.tol:g} |")
        for fig in v.figures:
            if fig.name in figures:
                L += ["", f"![{_md_line(fig.title)}](figures/{figures[fig.name]})"]
        L += ["", f"*Reproduce:* {_md_code(c.command)}", ""]
    return "\n".join(L).replace("\n\n\n", "\n\n")


def beside_notes(paper: Paper, results: Sequence[Evaluated]) -> dict[str, list[tuple[str, str]]]:
    """Claim id -> [(profile claim id, sentence, short form)]: what each smoothness profile of the paper says beside
    the claims it names (``beside`` of kind ``smoothness profile``; ids relative to the paper or full)."""
    ids = {ev.claim.id for ev in results}
    out: dict[str, list[tuple[str, str]]] = {}
    for ev in results:
        prof = ev.verdict.profile
        for cid, text, short in (prof or {}).get("beside", ()):
            full = cid if cid in ids else f"{paper.id}:{cid}"
            if full in ids:
                out.setdefault(full, []).append((ev.claim.id, text, short))
    return out


def profiles(results: Sequence[Evaluated]) -> list[Evaluated]:
    """The evaluated claims that carry a smoothness profile of a family."""
    return [ev for ev in results if ev.verdict.profile]


def _md_profiles(paper: Paper, results) -> list[str]:
    found = profiles(results)
    if not found:
        return []
    L = ["## Certified smoothness profiles", "",
         "For each parametric family of the paper: the C^j sets of its parameter (boundaries certified on both "
         "sides, exact where an eigenvalue crosses), the largest Hölder exponent and where it is attained, the "
         "exceptional values; computed by the code and kept in the golden verdicts.", ""]
    for ev in found:
        pr = ev.verdict.profile
        L += [_md_line(f"### {ev.claim.title or ev.claim.id} ({', '.join(ev.claim.objects)}; {pr['parameter']} in "
                       f"{pr['within']}; claim {ev.claim.id})"), "", "| set | certified | status |", "|---|---|---|"]
        L += [f"| {_md_cell(j)} | {_md_cell(t)} | {_md_cell(st)} |" for j, t, st in pr["compact"]]
        L += ["", f"*Largest alpha:* {_md_line(pr['alpha'])}", ""]
        if pr["exceptional"]:
            L += ["*Exceptional values:* " + _md_line(", ".join(f"{pr['parameter']} = {q} ({k} smoothing factors)"
                                                               for q, k in pr["exceptional"])), ""]
        for cid, text, _ in pr["beside"]:
            L += [_md_line(f"- beside {cid if ':' in cid else paper.id + ':' + cid}: {text}")]
        L.append("")
    return L


_CSS = """body{font-family:system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;line-height:1.45;overflow-wrap:break-word}
table{border-collapse:collapse;margin:.5em 0;font-size:.9em}td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top;text-align:left}
th{background:#f3f3f3}.badge{color:#fff;padding:1px 6px;border-radius:4px;font-weight:bold;white-space:nowrap;font-size:.85em}
.scroll{max-width:100%;overflow-x:auto}
table.verdicts{width:100%;table-layout:fixed}table.verdicts td{overflow-wrap:anywhere}
.verdicts col.c-id{width:24%}.verdicts col.c-verdict{width:9.5em}.verdicts col.c-kind{width:13%}
blockquote{border-left:4px solid #ccc;margin:0;padding:.3em 1em;color:#333}
blockquote.plain{font-family:monospace;font-size:.85em;word-break:break-all}
pre.latex{white-space:pre-wrap;word-break:break-all;background:#f6f8fa;padding:.4em;font-size:.8em;margin:.2em 0}
details{margin:.3em 0 .3em 1em;font-size:.9em}summary{cursor:pointer;color:#555}
code{background:#f6f8fa;padding:1px 3px;font-size:.85em;word-break:break-all}.claim{border-top:2px solid #ddd;margin-top:1.5em}
.m{display:inline-block;max-width:100%;overflow-x:auto;vertical-align:middle}math{font-size:1.1em}
blockquote math,.m math{math-style:normal}
img.formula{vertical-align:middle;max-width:100%}img.fig{max-width:100%;border:1px solid #eee}
.warning{background:#fff8c5;border:1px solid #d4a72c;padding:.4em .8em}
.profile{background:#eef6ff;border:1px solid #9cc3ec;padding:.4em .8em;margin:.5em 0}
.beside{display:block;font-size:.85em;color:#0b4f8a;margin-top:.2em}
nav{font-size:.9em;border-bottom:1px solid #ddd;padding-bottom:.4em}
table.verdicts .badge{overflow-wrap:normal;word-break:keep-all}
@media (max-width:600px){body{margin:.5em auto;padding:0 .5em}.verdicts col.c-id{width:30%}.verdicts col.c-verdict{width:7.4em}
table.verdicts .badge{font-size:.72em}
.verdicts .c-kind,.verdicts col.c-kind{display:none}.badge{white-space:normal}h1{font-size:1.4em}}"""


def _badge(status: str, label: str) -> str:
    return f'<span class="badge" style="background:{_COLOURS.get(status, "#888")}">{_html.escape(label)}</span>'


def _m(markup: str) -> str:
    return f'<span class="m">{markup}</span>'


def _quote(statement: str) -> str:
    """The paper's statement: typeset where it is LaTeX (with the source beside it), else as printed."""
    e_ = _html.escape
    if not has_latex(statement):
        return f'<blockquote class="plain">{e_(statement)}</blockquote>'
    typeset = quote_html(statement)
    src = f'<pre class="latex">{e_(statement)}</pre>'
    if typeset is None:
        return f"<p><em>The paper's LaTeX (not typeset):</em></p>{src}"
    return (f"<blockquote>{typeset}</blockquote><details><summary>the paper's LaTeX</summary>{src}</details>")


def _number_cell(n) -> str:
    import sympy as sp

    m = sympy_mathml(n.value) if isinstance(n.value, sp.Basic) and not isinstance(n.value, sp.Integer) else None
    text = _html.escape(n.exact_text())
    if m is None:
        return f"<code>{text}</code>"
    return _m(m) if len(text) <= 40 else f"{_m(m)}<details><summary>as text</summary><code>{text}</code></details>"


def _links(ids: Mapping[str, str]):
    """A function that turns the claim ids of ``ids`` (id -> href) in escaped prose into links."""
    import re

    if not ids:
        return lambda s: s
    names = sorted((_html.escape(i, quote=False) for i in ids), key=len, reverse=True)
    href = {_html.escape(i, quote=False): h for i, h in ids.items()}
    pat = re.compile(r"(?<![\w:])(" + "|".join(re.escape(n) for n in names) + r")(?![\w(])")
    return lambda s: pat.sub(lambda m: f'<a href="{_html.escape(href[m.group(1)], quote=True)}">{m.group(1)}</a>', s)


def html(paper: Paper, results: Sequence[Evaluated], figures: Mapping[str, str],
         formulas: Mapping[str, str | None] | None = None, *, siblings: Mapping[str, Mapping[str, str]] | None = None) -> str:
    """The HTML report: self-contained except for the figure files (PNG/SVG, no scripts). Mathematics is
    MathML; every text from the paper is escaped (:mod:`analysis.report.mathml` sanitises the MathML).
    ``siblings``: paper id -> its claim ids and titles in the same folder, for links between reports."""
    formulas = formulas or {}
    siblings = dict(siblings or {})
    e_ = _html.escape
    ids = {ev.claim.id: "#" + _anchor(ev.claim.id) for ev in results}
    for pid, claims in siblings.items():
        if pid != paper.id:
            ids.update({cid: f"{pid}.html#{_anchor(cid)}" for cid in claims})
    link = _links(ids)

    def t(x) -> str:                      # prose: escaped, plain-text formulas typeset, claim ids linked
        return link(pretty_text(x))

    others = sorted(set(siblings) | {paper.id})
    nav = ('<nav><a href="index.html">All reports</a> · ' + " · ".join(
        f"<strong>{e_(pid)}</strong>" if pid == paper.id else f'<a href="{e_(pid)}.html">{e_(pid)}</a>' for pid in others)
        + "</nav>")
    H = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
         '<meta name="viewport" content="width=device-width, initial-scale=1">',
         f"<title>Proof-check report {e_(paper.id)}</title><style>{_CSS}</style></head><body>", nav,
         f"<h1>Proof-check report {e_(paper.id)}: {e_(paper.title)}</h1>",
         f"<p><em>Source:</em> {e_(paper.citation)}<br><em>Text:</em> <code>{e_(paper.source)}</code><br>"
         f"<em>Generated by</em> <code>subdiv report {e_(paper.id)}</code> — do not edit by hand.</p>"]
    notice = python_notice(results)
    if notice:
        H.append(f'<p class="warning" id="ran-python"><strong>Warning: {e_(notice[0].upper() + notice[1:])}.</strong> '
                 "The verdicts of those claims are what that code returned, not computations of this tool.</p>")
    if paper.notes:
        H.append(f"<p>{t(paper.notes)}</p>")
    besides = beside_notes(paper, results)
    H.append(f"<p><strong>{len(results)} claims:</strong> {e_(_counts(results))}.</p>")
    H.append('<h2>Verdicts</h2><div class="scroll"><table id="verdicts" class="verdicts"><colgroup><col class="c-id">'
             '<col class="c-verdict"><col class="c-kind"><col></colgroup>'
             '<tr><th>claim</th><th>verdict</th><th class="c-kind">kind</th><th>summary</th></tr>')
    for ev in results:
        note = "".join(f'<span class="beside">profile: {t(short)}</span>' for _, _, short in besides.get(ev.claim.id, ()))
        H.append(f'<tr><td><a href="#{_anchor(ev.claim.id)}">{e_(ev.claim.id)}</a></td>'
                 f"<td>{_badge(ev.verdict.status, ev.verdict.label)}</td><td class=\"c-kind\">{e_(ev.claim.kind)}</td>"
                 f"<td>{t(ev.verdict.summary)}{note}</td></tr>")
    H.append("</table></div>")
    H += _html_profiles(paper, results, t)
    for ev in results:
        c, v = ev.claim, ev.verdict
        H.append(f'<div class="claim" id="{_anchor(c.id)}"><h2>{e_(c.id)}{" — " + pretty_text(c.title) if c.title else ""}</h2>')
        H.append(f"<p><em>Kind:</em> {e_(c.kind)}. <em>Where:</em> {e_(c.location or '-')}. "
                 f"<em>Objects:</em> {e_(', '.join(c.objects) or '-')}.</p>")
        H.append(f"<p><strong>As printed:</strong></p>{_quote(c.statement)}")
        if c.reading:
            H.append(f"<p><strong>As read:</strong> {t(c.reading)}</p>")
        if c.reading_note:
            H.append(f"<p><em>Reading:</em> {t(c.reading_note)}</p>")
        if c.runs_python:
            H.append(f'<p class="warning"><em>Ran Python code from the paper file:</em> evaluator '
                     f"<code>{e_(c.runs_python)}</code>.</p>")
        H.append(f"<p>{_badge(v.status, v.label)} {t(v.summary)}</p>")
        for src, text, _ in besides.get(c.id, ()):
            H.append(f'<p class="profile"><strong>Certified profile beside the claim</strong> '
                     f'(<a href="#{_anchor(src)}">{e_(src)}</a>): {t(text)}</p>')
        for title, text in (("Corrected statement", v.corrected), ("Sharpness", v.sharpness),
                            ("What would settle it", v.settle)):
            if text:
                H.append(f"<p><strong>{title}:</strong> {t(text)}</p>")
        if v.evidence:
            H.append("<p><strong>Evidence:</strong></p><ul>")
        for e in v.evidence:
            item = f"<li><em>{t(e.title)}</em>"
            if e.result is not None:
                item += f" [{e_(e.result.status)}; {t(str(e.result.provenance.get('method', '')))}]"
            if e.text:
                item += f": {t(e.text)}"
            if e.latex:
                m = latex_mathml(e.latex)
                f = formulas.get(e.latex)
                if m:
                    item += "<br>" + _m(m)
                elif f:
                    item += f'<br><img class="formula" src="figures/formulas/{f}" alt="{e_(e.latex)}">'
                else:
                    item += f"<br><code>{e_(e.latex)}</code>"
            if e.table:
                item += '<div class="scroll"><table><tr>' + "".join(f"<th>{t(str(h))}</th>" for h in e.table[0]) + "</tr>"
                for row in e.table[1:]:
                    item += "<tr>" + "".join(f"<td>{t(str(x))}</td>" for x in row) + "</tr>"
                item += "</table></div>"
            H.append(item + "</li>")
        if v.evidence:
            H.append("</ul>")
        if v.numbers:
            H.append('<p><strong>Key numbers (regression):</strong></p><div class="scroll"><table><tr><th>name</th>'
                     "<th>exact</th><th>float</th><th>tolerance</th></tr>")
            for n in v.numbers:
                fl = n.float
                H.append(f"<tr><td>{t(n.name)}</td><td>{_number_cell(n)}</td>"
                         f"<td>{'' if fl is None else repr(fl)}</td><td>{n.tol:g}</td></tr>")
            H.append("</table></div>")
        for fig in v.figures:
            if fig.name in figures:
                H.append(f'<p><img class="fig" src="figures/{figures[fig.name]}" alt="{e_(fig.title)}"></p>')
        H.append(f"<p><em>Reproduce:</em> <code>{e_(c.command)}</code></p></div>")
    H.append("</body></html>")
    return "\n".join(H)


def _html_profiles(paper: Paper, results, t) -> list[str]:
    e_ = _html.escape
    found = profiles(results)
    if not found:
        return []
    H = ['<h2 id="profiles">Certified smoothness profiles</h2>',
         "<p>For each parametric family of the paper: the C<sup>j</sup> sets of its parameter (boundaries certified on "
         "both sides, exact where an eigenvalue crosses), the largest Hölder exponent and where it is attained, the "
         "exceptional values; computed by the code and kept in the golden verdicts. Beside each claim of the paper "
         "about the family, the report says what the certified set says about it.</p>"]
    for ev in found:
        pr = ev.verdict.profile
        H.append(f'<div class="profile"><h3>{t(ev.claim.title or ev.claim.id)}</h3><p>{e_(", ".join(ev.claim.objects))}; '
                 f"{e_(pr['parameter'])} in {t(pr['within'])}; from claim "
                 f'<a href="#{_anchor(ev.claim.id)}">{e_(ev.claim.id)}</a> ({_badge(ev.verdict.status, ev.verdict.label)})</p>'
                 '<div class="scroll"><table><tr><th>set</th><th>certified</th><th>status</th></tr>')
        H += [f"<tr><td>{t(j)}</td><td>{t(x)}</td><td>{t(st)}</td></tr>" for j, x, st in pr["compact"]]
        H.append(f"</table></div><p><em>Largest alpha:</em> {t(pr['alpha'])}</p>")
        if pr["exceptional"]:
            H.append("<p><em>Exceptional values:</em> " + ", ".join(
                f"{e_(pr['parameter'])} = {t(q)} ({k} smoothing factors)" for q, k in pr["exceptional"]) + "</p>")
        if pr["beside"]:
            H.append("<ul>" + "".join(f"<li>beside {t(cid if ':' in cid else paper.id + ':' + cid)}: {t(text)}</li>"
                                      for cid, text, _ in pr["beside"]) + "</ul>")
        H.append("</div>")
    return H


def render_paper(paper: Paper, results: Sequence[Evaluated], outdir: str | os.PathLike,
                 *, with_figures: bool = True, siblings: Mapping[str, Sequence[str]] | None = None) -> list[Path]:
    """Write ``<outdir>/<paper>.md``, ``<outdir>/<paper>.html`` and the figures (every file inside
    ``outdir``, rewritten atomically); the paths. ``siblings`` (paper id -> claim ids) are the other
    reports of the folder, linked from this one (:func:`analysis.report.index.siblings`)."""
    check_slug(paper.id, "paper id", '"900"')
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    figdir = inside(out, "figures")
    figures = {f.name: render_figure(f, figdir) for f in _all_figures(results)} if with_figures else {}
    formulas = _formula_files(results, figdir) if with_figures else {}
    record_written(out, [figdir / n for n in figures.values()]
                   + [figdir / "formulas" / n for n in formulas.values() if n])
    written = []
    for ext, fn in (("md", markdown), ("html", html)):
        p = inside(out, f"{paper.id}.{ext}")
        text = (html(paper, results, figures, formulas, siblings=siblings) if fn is html
                else fn(paper, results, figures, formulas))
        atomic_write_text(p, text)
        written.append(p)
    return written
