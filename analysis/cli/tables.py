"""``--table FILE.csv`` / ``--table FILE.tex``: a command's result table for a spreadsheet or a paper
(``subdiv holder``, ``range``, ``atlas``, ``report``, ``check``).

The cells are the computed values: exact numbers stay exact (``sstr`` in CSV, ``sympy.latex`` in
LaTeX), enclosure ends are the outward-rounded decimals the command prints, verdicts are words.
The LaTeX is a ``booktabs`` tabular (``\\usepackage{booktabs}``) with the caption as a comment
and every text cell escaped. A paper's statement (:class:`Quote`) keeps its formulas in ``$...$``
when they use only standard LaTeX math (``amsmath``/``amssymb`` commands, balanced braces); any
other statement is written as escaped text, so the table always compiles.

Where the file goes: the named file itself (checked before any computation by :func:`check_table`;
a symbolic link at that name is refused, and the file is replaced atomically, never written
through); for ``subdiv report``, a name inside its output folder (``--output``), refused when it
leads out of it.

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

__all__ = ["check_table", "write_table", "latex_table", "csv_table", "Quote", "Name"]

FORMATS = (".csv", ".tex")
_TEX = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{",
        "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "<": r"\textless{}",
        ">": r"\textgreater{}", "|": r"\textbar{}"}


def check_table(path: str, folder=None) -> str:
    """Fail at once (one line) when ``path`` is not a writable ``.csv`` or ``.tex`` file name; the path to
    write. With ``folder`` (an output folder that exists) ``path`` is a name inside it: a name that leads
    out of the folder (``..``, an absolute path, a symbolic link) is refused."""
    from .common import check_writable

    ext = os.path.splitext(str(path))[1].lower()
    if ext not in FORMATS:
        raise AnalysisError(f"cannot write --table {path!r}: end the name in .csv (a spreadsheet) or .tex "
                            "(a LaTeX tabular)")
    if folder is not None:
        from ..report.files import inside

        try:
            path = str(inside(folder, str(path)))
        except AnalysisError:
            raise AnalysisError(f"refusing to write --table {path!r}: it leads out of the output folder {folder} "
                                "(give a file name inside it, e.g. --table verdicts.tex)") from None
    elif os.path.islink(os.path.expanduser(str(path))):
        raise AnalysisError(f"refusing to write --table {path!r}: it is a symbolic link (to "
                            f"{os.path.realpath(os.path.expanduser(str(path)))}); give the name of a file")
    check_writable(path, "--table")
    return path


#: words of the command's text that a paper typesets as mathematics
_MATH_WORDS = re.compile(r"C\^(-?\d+)|\balpha\b")


def _tex_text(text: str, math: bool = True) -> str:
    if not math:
        return "".join(_TEX.get(c, c) for c in text)
    out, pos = [], 0
    for m in _MATH_WORDS.finditer(text):
        out.append("".join(_TEX.get(c, c) for c in text[pos:m.start()]))
        out.append(f"$C^{{{m.group(1)}}}$" if m.group(1) is not None else r"$\alpha$")
        pos = m.end()
    out.append("".join(_TEX.get(c, c) for c in text[pos:]))
    return "".join(out)


class Quote(str):
    """A paper's statement in a table cell: its formulas typeset in LaTeX (:func:`_tex_quote`)."""


class Name(str):
    """A name in a table cell (a claim id): escaped, never typeset (``FourPoint.alpha`` stays a word)."""


#: the control words a statement's formula may keep in the LaTeX table (standard LaTeX, amsmath, amssymb;
#: no text-mode commands such as ``\\text``, whose argument may hold characters that end math)
_SAFE_COMMANDS = frozenset("""
alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi varpi rho varrho
sigma varsigma tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega
frac dfrac tfrac sqrt binom left right big Big bigl bigr Bigl Bigr bigg Bigg middle
leq le geq ge neq ne approx sim simeq equiv cong propto ll gg prec succ preceq succeq subset supset subseteq
supseteq in notin ni to mapsto rightarrow leftarrow Rightarrow Leftarrow Leftrightarrow leftrightarrow implies iff
infty partial nabla forall exists emptyset varnothing setminus smallsetminus cup cap bigcup bigcap times cdot
cdots ldots dots vdots ddots pm mp circ ast star oplus otimes sum prod int oint lim limsup liminf sup inf max min
sin cos tan cot sec csc sinh cosh tanh coth log ln exp det deg arg dim ker gcd mod bmod pmod
operatorname mathbb mathcal mathrm mathbf mathit mathsf hat bar tilde vec dot ddot
overline underline widehat widetilde quad qquad langle rangle lfloor rfloor lceil rceil vert Vert mid
prime ell hbar Re Im aleph colon
""".split())
_CONTROL_WORD = re.compile(r"\\([A-Za-z]+)|\\(.)")


def _safe_formula(latex: str) -> bool:
    """Does ``latex`` (one formula of a statement) compile inside ``$...$`` whatever the document?
    Only standard control words, balanced braces, no characters that end math or a table cell."""
    depth = 0
    for ch in latex:
        depth += (ch == "{") - (ch == "}")
        if depth < 0:
            return False
    if depth or any(c in latex for c in "$%#&") or not latex.strip():
        return False
    words = [m.group(1) for m in _CONTROL_WORD.finditer(latex)]
    if words.count("left") != words.count("right"):
        return False
    for m in _CONTROL_WORD.finditer(latex):
        if m.group(1) is not None and m.group(1) not in _SAFE_COMMANDS:
            return False
        if m.group(2) is not None and m.group(2) not in ",;:!{}| ":
            return False
    return True


def _tex_quote(statement: str) -> str:
    """A paper's statement as a LaTeX cell: words escaped, formulas in ``$...$`` (all or nothing).

    >>> print(_tex_quote(r"C^2 for 0 < omega < \\frac{\\sqrt{6}-1}{80}."))
    $C^2$ for $0 < \\omega < \\frac{\\sqrt{6}-1}{80}.$
    >>> print(_tex_quote(r"x \\input{/etc/passwd} 100%"))
    x \\textbackslash{}input\\{/etc/passwd\\} 100\\%
    >>> print(_tex_quote(r"for \\left( x < 1"))             # an unclosed \\left would not compile
    for \\textbackslash{}left( x \\textless{} 1
    """
    from ..report.mathml import has_latex, quote_parts

    text = " ".join(str(statement).split())
    if has_latex(text):
        parts = quote_parts(text)
        if all(_safe_formula(t) for is_math, t in parts if is_math):
            return " ".join(f"${t}$" if is_math else _tex_text(t) for is_math, t in parts)
    return _tex_text(text)


def _tex_cell(x) -> str:
    import sys

    sp = sys.modules.get("sympy")
    if sp is not None and isinstance(x, sp.Basic):
        if isinstance(x, sp.CRootOf):          # a boundary: the root of a polynomial, not CRootOf(...)
            return (f"root $\\approx {float(x):.10g}$ of ${sp.latex(x.expr)}$" if x.is_real
                    else f"${sp.latex(x)}$")
        return f"${sp.latex(x)}$"
    if isinstance(x, Quote):
        return _tex_quote(x)
    if isinstance(x, Name):
        return _tex_text(" ".join(x.split()), math=False)
    text = str(x)
    if text.startswith("$") and text.endswith("$") and len(text) > 1:    # a header already in math mode
        return text
    return _tex_text(" ".join(text.split()))


def _csv_cell(x) -> str:
    import sys

    sp = sys.modules.get("sympy")
    if sp is not None and isinstance(x, sp.Basic):
        return sp.sstr(x)
    text = str(x)
    return text[1:-1] if text.startswith("$") and text.endswith("$") and len(text) > 1 else text


def latex_table(columns, rows, caption: str = "", spec: str | None = None) -> str:
    """A booktabs tabular of ``rows`` under ``columns`` (``caption`` as a leading comment; ``spec`` the
    column specification, default one ``l`` per column)."""
    out = [f"% {line}" for line in caption.splitlines()] if caption else []
    out += [r"\begin{tabular}{" + (spec or "l" * len(columns)) + "}", r"\toprule",
            " & ".join(_tex_cell(c) for c in columns) + r" \\", r"\midrule"]
    out += [" & ".join(_tex_cell(c) for c in row) + r" \\" for row in rows]
    out += [r"\bottomrule", r"\end{tabular}"]
    return "\n".join(out) + "\n"


def csv_table(columns, rows) -> str:
    """The table as CSV text (the ``csv`` module's quoting; exact numbers as ``sstr``)."""
    import csv
    import io

    buf = io.StringIO(newline="")
    w = csv.writer(buf)
    w.writerow([_csv_cell(c) for c in columns])
    w.writerows([[_csv_cell(c) for c in row] for row in rows])
    return buf.getvalue()


def write_table(path: str, columns, rows, caption: str = "", spec: str | None = None) -> str:
    """Write the table to ``path`` (CSV or LaTeX by its extension; atomically: a temporary file beside
    it, then renamed over it, so a symbolic link there is replaced, never written through); returns the path."""
    from ..report.files import atomic_write_text

    text = latex_table(columns, rows, caption, spec) if str(path).lower().endswith(".tex") else csv_table(columns, rows)
    try:
        atomic_write_text(os.path.expanduser(str(path)), text)
    except OSError as exc:
        raise AnalysisError(f"cannot write --table {path!r}: {exc.strerror or exc}") from None
    return path
