"""``--table FILE.csv`` / ``--table FILE.tex``: a command's result table for a spreadsheet or a paper.

The cells are the computed values: exact numbers stay exact (``sstr`` in CSV, ``sympy.latex`` in
LaTeX), enclosure ends are the outward-rounded decimals the command prints, verdicts are words.
The LaTeX is a ``booktabs`` tabular (``\\usepackage{booktabs}``) with the caption as a comment
and every text cell escaped.

Examples
--------
>>> import sympy as sp
>>> w = sp.Symbol("w")
>>> print(latex_table(["$w$", "C^1"], [[sp.Rational(1, 16), "yes"], [sp.CRootOf(32*w**3 + 4*w - 1, 0), "no"]],
...                   "four-point"), end="")
% four-point
\\begin{tabular}{ll}
\\toprule
$w$ & $C^{1}$ \\\\
\\midrule
$\\frac{1}{16}$ & yes \\\\
root $\\approx 0.1927292493$ of $32 w^{3} + 4 w - 1$ & no \\\\
\\bottomrule
\\end{tabular}
"""

from __future__ import annotations

import os
import re

from ..result import AnalysisError

FORMATS = (".csv", ".tex")
_TEX = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{",
        "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def check_table(path: str) -> None:
    """Fail at once (one line) when ``path`` is not a writable ``.csv`` or ``.tex`` file name."""
    from .common import check_writable

    ext = os.path.splitext(str(path))[1].lower()
    if ext not in FORMATS:
        raise AnalysisError(f"cannot write --table {path!r}: end the name in .csv (a spreadsheet) or .tex "
                            "(a LaTeX tabular)")
    check_writable(path, "--table")


#: words of the command's text that a paper typesets as mathematics
_MATH_WORDS = re.compile(r"C\^(-?\d+)|\balpha\b")


def _tex_text(text: str) -> str:
    out, pos = [], 0
    for m in _MATH_WORDS.finditer(text):
        out.append("".join(_TEX.get(c, c) for c in text[pos:m.start()]))
        out.append(f"$C^{{{m.group(1)}}}$" if m.group(1) is not None else r"$\alpha$")
        pos = m.end()
    out.append("".join(_TEX.get(c, c) for c in text[pos:]))
    return "".join(out)


def _tex_cell(x) -> str:
    import sys

    sp = sys.modules.get("sympy")
    if sp is not None and isinstance(x, sp.Basic):
        if isinstance(x, sp.CRootOf):          # a boundary: the root of a polynomial, not CRootOf(...)
            return (f"root $\\approx {float(x):.10g}$ of ${sp.latex(x.expr)}$" if x.is_real
                    else f"${sp.latex(x)}$")
        return f"${sp.latex(x)}$"
    text = str(x)
    if text.startswith("$") and text.endswith("$") and len(text) > 1:    # a header already in math mode
        return text
    return _tex_text(text)


def _csv_cell(x) -> str:
    import sys

    sp = sys.modules.get("sympy")
    if sp is not None and isinstance(x, sp.Basic):
        return sp.sstr(x)
    text = str(x)
    return text[1:-1] if text.startswith("$") and text.endswith("$") and len(text) > 1 else text


def latex_table(columns, rows, caption: str = "") -> str:
    """A booktabs tabular of ``rows`` under ``columns`` (``caption`` as a leading comment)."""
    out = [f"% {line}" for line in caption.splitlines()] if caption else []
    out += [r"\begin{tabular}{" + "l" * len(columns) + "}", r"\toprule",
            " & ".join(_tex_cell(c) for c in columns) + r" \\", r"\midrule"]
    out += [" & ".join(_tex_cell(c) for c in row) + r" \\" for row in rows]
    out += [r"\bottomrule", r"\end{tabular}"]
    return "\n".join(out) + "\n"


def write_table(path: str, columns, rows, caption: str = "") -> str:
    """Write the table to ``path`` (CSV or LaTeX by its extension); returns the path."""
    import csv

    try:
        if str(path).lower().endswith(".tex"):
            with open(path, "w", encoding="utf-8") as f:
                f.write(latex_table(columns, rows, caption))
        else:
            with open(path, "w", encoding="utf-8", newline="") as f:
                w = csv.writer(f)
                w.writerow([_csv_cell(c) for c in columns])
                w.writerows([[_csv_cell(c) for c in row] for row in rows])
    except OSError as exc:
        raise AnalysisError(f"cannot write --table {path!r}: {exc.strerror or exc}") from None
    return path
