"""Rendering of proof-check reports: ``reports/<paper>.md``, ``reports/<paper>.html`` and figures.

Nothing here computes: the verdicts, numbers, tables and figure data come from
:mod:`analysis.claims.model`; this module only lays them out.

Formulas
--------
MathJax/KaTeX need network or bundled JavaScript, which the reports must not depend on. Each
formula's LaTeX is rendered by **matplotlib mathtext to a small SVG** (no TeX installation, no
JavaScript; every browser and Markdown viewer shows SVG offline), stored under
``reports/figures/formulas/`` with a name derived from a hash of the formula. Every run rewrites
every file it refers to (atomically: a damaged or stale file is replaced; the output is
deterministic, so re-rendering an unchanged report leaves the bytes unchanged), and the CLI then
removes the figures no report refers to (:func:`analysis.report.files.remove_orphans`). The
Unicode/plain-text form is always printed beside it (and is the image's ``alt`` text); when
mathtext cannot parse a formula, only the text is shown.

Files
-----
Every file is written inside the output folder (:func:`analysis.report.files.inside`): the paper id
and the figure names must be slugs (:mod:`analysis.claims.names`), and a symbolic link leading out of
the folder is refused. When evaluating the claims ran Python code from a paper file
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
from pathlib import Path
from typing import Mapping, Sequence

from ..claims.model import Evaluated, Figure, Paper, python_notice
from ..claims.names import MAX_GENERATED, check_slug
from .files import atomic_write_bytes, atomic_write_text, inside

__all__ = ["render_paper", "markdown", "html", "render_figure", "render_formula", "summary_table"]

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


def _md_cell(s: str) -> str:
    return str(s).replace("|", "\\|").replace("\n", " ")


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
    L = [f"# Proof-check report {paper.id}: {paper.title}", "",
         f"*Source:* {paper.citation}  ", f"*Text:* `{paper.source}`  ",
         "*Generated by* `subdiv report " + paper.id + "` — do not edit by hand.", ""]
    notice = python_notice(results)
    if notice:
        L += [f"> **Warning: {notice[0].upper() + notice[1:]}.** The verdicts of those claims are what that code "
              "returned, not computations of this tool.", ""]
    if paper.notes:
        L += [paper.notes, ""]
    L += ["Statuses: **CERTIFIED TRUE** (exact arithmetic or rigorous enclosures prove it), **REFUTED** "
          "(certified counterexample or different value; the corrected statement is given), "
          "**NUMERICAL** (floating-point evidence only), **INCONCLUSIVE** (not settled; what would settle "
          "it is given).", "", f"**{len(results)} claims:** {_counts(results)}.", "",
          "## Verdicts", "", "| claim | kind | verdict | summary |", "|---|---|---|---|"]
    for cid, kind, label, summ in summary_table(results):
        L.append(f"| {cid} | {kind} | {label} | {_md_cell(summ)} |")
    L.append("")
    for ev in results:
        c, v = ev.claim, ev.verdict
        L += [f"## {c.id} — {c.title}" if c.title else f"## {c.id}", "",
              f"<a id=\"{_anchor(c.id)}\"></a>", "",
              f"*Kind:* {c.kind}. *Where:* {c.location or '-'}. *Objects:* "
              f"{', '.join(c.objects) or '-'}.", "",
              "**As printed:**", "", "> " + c.statement.replace("\n", " "), ""]
        if c.reading:
            L += [f"**As read:** {c.reading}", ""]
        if c.reading_note:
            L += [f"*Reading:* {c.reading_note}", ""]
        if c.runs_python:
            L += [f"*Ran Python code from the paper file:* evaluator `{c.runs_python}`.", ""]
        L += [f"**Verdict: {v.label}.** {v.summary}", ""]
        if v.corrected:
            L += [f"**Corrected statement:** {v.corrected}", ""]
        if v.sharpness:
            L += [f"**Sharpness:** {v.sharpness}", ""]
        if v.settle:
            L += [f"**What would settle it:** {v.settle}", ""]
        if v.evidence:
            L += ["**Evidence:**", ""]
        for e in v.evidence:
            line = f"- *{e.title}*"
            if e.result is not None:
                line += f" [{e.result.status}; {e.result.provenance.get('method', '')}]"
            if e.text:
                line += f": {e.text}"
            L.append(line)
            if e.latex:
                f = formulas.get(e.latex)
                if f:
                    L.append(f"\n  ![formula](figures/formulas/{f})\n")
                L.append(f"  `{e.latex}`")
            if e.table:
                L += ["", "  | " + " | ".join(_md_cell(h) for h in e.table[0]) + " |",
                      "  |" + "---|" * len(e.table[0])]
                L += ["  | " + " | ".join(_md_cell(x) for x in row) + " |" for row in e.table[1:]]
                L.append("")
        if v.numbers:
            L += ["", "**Key numbers (regression):**", "", "| name | exact | float | tolerance |", "|---|---|---|---|"]
            for n in v.numbers:
                fl = n.float
                L.append(f"| {n.name} | `{_md_cell(n.exact_text())}` | {'' if fl is None else repr(fl)} | {n.tol:g} |")
        for fig in v.figures:
            if fig.name in figures:
                L += ["", f"![{fig.title}](figures/{figures[fig.name]})"]
        L += ["", f"*Reproduce:* `{c.command}`", ""]
    return "\n".join(L).replace("\n\n\n", "\n\n")


_CSS = """body{font-family:system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;line-height:1.45}
table{border-collapse:collapse;margin:.5em 0;font-size:.9em}td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top}
th{background:#f3f3f3}.badge{color:#fff;padding:1px 6px;border-radius:4px;font-weight:bold;white-space:nowrap}
blockquote{border-left:4px solid #ccc;margin:0;padding:.3em 1em;color:#444;font-family:monospace;font-size:.85em;word-break:break-all}
code{background:#f6f8fa;padding:1px 3px;font-size:.85em;word-break:break-all}.claim{border-top:2px solid #ddd;margin-top:1.5em}
img.formula{vertical-align:middle;max-width:100%}img.fig{max-width:100%;border:1px solid #eee}
.warning{background:#fff8c5;border:1px solid #d4a72c;padding:.4em .8em}"""


def _badge(status: str, label: str) -> str:
    return f'<span class="badge" style="background:{_COLOURS.get(status, "#888")}">{_html.escape(label)}</span>'


def html(paper: Paper, results: Sequence[Evaluated], figures: Mapping[str, str],
         formulas: Mapping[str, str | None] | None = None) -> str:
    """The HTML report: self-contained except for the figure files (PNG/SVG, no scripts)."""
    formulas = formulas or {}
    e_ = _html.escape
    H = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
         f"<title>Proof-check report {e_(paper.id)}</title><style>{_CSS}</style></head><body>",
         f"<h1>Proof-check report {e_(paper.id)}: {e_(paper.title)}</h1>",
         f"<p><em>Source:</em> {e_(paper.citation)}<br><em>Text:</em> <code>{e_(paper.source)}</code><br>"
         f"<em>Generated by</em> <code>subdiv report {e_(paper.id)}</code> — do not edit by hand.</p>"]
    notice = python_notice(results)
    if notice:
        H.append(f'<p class="warning" id="ran-python"><strong>Warning: {e_(notice[0].upper() + notice[1:])}.</strong> '
                 "The verdicts of those claims are what that code returned, not computations of this tool.</p>")
    if paper.notes:
        H.append(f"<p>{e_(paper.notes)}</p>")
    H.append(f"<p><strong>{len(results)} claims:</strong> {e_(_counts(results))}.</p>")
    H.append('<h2>Verdicts</h2><table id="verdicts"><tr><th>claim</th><th>kind</th><th>verdict</th><th>summary</th></tr>')
    for ev in results:
        H.append(f'<tr><td><a href="#{_anchor(ev.claim.id)}">{e_(ev.claim.id)}</a></td><td>{e_(ev.claim.kind)}</td>'
                 f"<td>{_badge(ev.verdict.status, ev.verdict.label)}</td><td>{e_(ev.verdict.summary)}</td></tr>")
    H.append("</table>")
    for ev in results:
        c, v = ev.claim, ev.verdict
        H.append(f'<div class="claim" id="{_anchor(c.id)}"><h2>{e_(c.id)}{" — " + e_(c.title) if c.title else ""}</h2>')
        H.append(f"<p><em>Kind:</em> {e_(c.kind)}. <em>Where:</em> {e_(c.location or '-')}. "
                 f"<em>Objects:</em> {e_(', '.join(c.objects) or '-')}.</p>")
        H.append(f"<p><strong>As printed:</strong></p><blockquote>{e_(c.statement)}</blockquote>")
        if c.reading:
            H.append(f"<p><strong>As read:</strong> {e_(c.reading)}</p>")
        if c.reading_note:
            H.append(f"<p><em>Reading:</em> {e_(c.reading_note)}</p>")
        if c.runs_python:
            H.append(f'<p class="warning"><em>Ran Python code from the paper file:</em> evaluator '
                     f"<code>{e_(c.runs_python)}</code>.</p>")
        H.append(f"<p>{_badge(v.status, v.label)} {e_(v.summary)}</p>")
        for title, text in (("Corrected statement", v.corrected), ("Sharpness", v.sharpness),
                            ("What would settle it", v.settle)):
            if text:
                H.append(f"<p><strong>{title}:</strong> {e_(text)}</p>")
        if v.evidence:
            H.append("<p><strong>Evidence:</strong></p><ul>")
        for e in v.evidence:
            item = f"<li><em>{e_(e.title)}</em>"
            if e.result is not None:
                item += f" [{e_(e.result.status)}; {e_(str(e.result.provenance.get('method', '')))}]"
            if e.text:
                item += f": {e_(e.text)}"
            if e.latex:
                f = formulas.get(e.latex)
                if f:
                    item += (f'<br><img class="formula" src="figures/formulas/{f}" alt="{e_(e.latex)}">')
                else:
                    item += f"<br><code>{e_(e.latex)}</code>"
            if e.table:
                item += "<table><tr>" + "".join(f"<th>{e_(str(h))}</th>" for h in e.table[0]) + "</tr>"
                for row in e.table[1:]:
                    item += "<tr>" + "".join(f"<td>{e_(str(x))}</td>" for x in row) + "</tr>"
                item += "</table>"
            H.append(item + "</li>")
        if v.evidence:
            H.append("</ul>")
        if v.numbers:
            H.append("<p><strong>Key numbers (regression):</strong></p><table><tr><th>name</th><th>exact</th>"
                     "<th>float</th><th>tolerance</th></tr>")
            for n in v.numbers:
                fl = n.float
                H.append(f"<tr><td>{e_(n.name)}</td><td><code>{e_(n.exact_text())}</code></td>"
                         f"<td>{'' if fl is None else repr(fl)}</td><td>{n.tol:g}</td></tr>")
            H.append("</table>")
        for fig in v.figures:
            if fig.name in figures:
                H.append(f'<p><img class="fig" src="figures/{figures[fig.name]}" alt="{e_(fig.title)}"></p>')
        H.append(f"<p><em>Reproduce:</em> <code>{e_(c.command)}</code></p></div>")
    H.append("</body></html>")
    return "\n".join(H)


def render_paper(paper: Paper, results: Sequence[Evaluated], outdir: str | os.PathLike,
                 *, with_figures: bool = True) -> list[Path]:
    """Write ``<outdir>/<paper>.md``, ``<outdir>/<paper>.html`` and the figures (every file inside
    ``outdir``, rewritten atomically); the paths."""
    check_slug(paper.id, "paper id", '"900"')
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    figdir = inside(out, "figures")
    figures = {f.name: render_figure(f, figdir) for f in _all_figures(results)} if with_figures else {}
    formulas = _formula_files(results, figdir) if with_figures else {}
    written = []
    for ext, fn in (("md", markdown), ("html", html)):
        p = inside(out, f"{paper.id}.{ext}")
        atomic_write_text(p, fn(paper, results, figures, formulas))
        written.append(p)
    return written
