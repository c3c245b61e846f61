"""Formulas in HTML reports as MathML (browsers render it natively, offline, without scripts).

Three sources of mathematics, three routes, one sanitiser:

* **exact values the engine computed** (sympy expressions: key numbers, exact sets): sympy's
  presentation MathML printer (:func:`sympy_mathml`); ``CRootOf(P, k)`` is shown as
  ``root_(k+1)(P)``, the (k+1)-th real root of ``P`` in increasing order;
* **LaTeX** (the formulas of the evidence, and the paper's statements, which are extracted LaTeX
  without ``$`` delimiters): ``latex2mathml`` (:func:`latex_mathml`, :func:`quote_html`: the words of
  a quote stay text, the runs between them become formulas);
* **formulas inside prose** (verdict summaries, evidence text, written by the claim kinds in the
  plain-text notation ``sqrt(...)``, ``x**2``, ``2*w``): :func:`pretty_text` typesets powers as
  superscripts and ``sqrt``/``*`` as ``√``/``·`` after escaping.

Paper files are untrusted data, and ``latex2mathml`` passes some input through unescaped
(``\\text{<b>}``, ``\\href{...}``, a bare ``&``). So every MathML string is **parsed as XML and
rebuilt** from a whitelist of MathML elements and attributes (:func:`sanitise`): anything that does
not parse, or holds another element, is refused, and the caller shows the source text escaped
instead. Nothing from a paper reaches the page as markup.

Examples
--------
>>> print(latex_mathml(r"\\frac{1}{2}"))
<math display="inline"><mrow><mfrac><mrow><mn>1</mn></mrow><mrow><mn>2</mn></mrow></mfrac></mrow></math>
>>> latex_mathml(r"\\text{<b onclick=x>}") is None            # not MathML: refused
True
>>> pretty_text("sqrt(833*mu**2 + 70*mu + 1)/128")
'√(833·mu<sup>2</sup> + 70·mu + 1)/128'
>>> pretty_text("C^2 on (0, CRootOf(32*w**3 + 4*w - 1, 0)); <b>")
'C<sup>2</sup> on (0, root<sub>1</sub>(32·w<sup>3</sup> + 4·w - 1)); &lt;b&gt;'

References
----------
MathML Core: https://www.w3.org/TR/mathml-core/ ; latex2mathml: https://pypi.org/project/latex2mathml/
"""

from __future__ import annotations

import html as _html
import re
from typing import Any

__all__ = ["latex_mathml", "sympy_mathml", "quote_html", "quote_parts", "pretty_text", "sanitise", "has_latex"]

#: MathML elements a report may contain
ELEMENTS = frozenset("""math mrow mi mn mo ms mtext mspace msub msup msubsup mfrac msqrt mroot mover munder
munderover mtable mtr mtd mstyle mpadded mphantom menclose semantics annotation mfenced merror""".split())
#: attributes a report may keep (values: letters, digits, and a few punctuation marks)
ATTRIBUTES = frozenset("""display stretchy fence separator lspace rspace mathvariant accent accentunder movablelimits
largeop symmetric form linethickness columnalign rowalign columnspacing rowspacing displaystyle scriptlevel
width height depth minsize maxsize notation open close separators""".split())
_VALUE = re.compile(r"^[A-Za-z0-9 .%#+-]{0,40}$")
#: longest formula (characters of LaTeX) converted; longer ones are shown as text
MAX_LATEX = 4000


def sanitise(markup: str) -> str | None:
    """``markup`` rebuilt from whitelisted MathML elements and attributes, text escaped; None when it
    does not parse as one ``<math>`` or ``<mrow>`` element or holds anything else."""
    import xml.etree.ElementTree as ET

    text = markup.replace("&InvisibleTimes;", "&#8290;").replace("&ApplyFunction;", "&#8289;")
    try:
        root = ET.fromstring(text)
    except ET.ParseError:
        return None
    out: list[str] = []

    def walk(el) -> bool:
        tag = el.tag.rsplit("}", 1)[-1]
        if tag not in ELEMENTS:
            return False
        attrs = []
        for k, v in sorted(el.attrib.items()):
            k = k.rsplit("}", 1)[-1]
            if k == "xmlns":
                continue
            if k not in ATTRIBUTES or not _VALUE.match(v):
                return False
            attrs.append(f' {k}="{_html.escape(v, quote=True)}"')
        out.append(f"<{tag}{''.join(attrs)}>")
        if el.text:
            out.append(_html.escape(el.text, quote=False))
        for child in el:
            if not walk(child):
                return False
            if child.tail:
                out.append(_html.escape(child.tail, quote=False))
        out.append(f"</{tag}>")
        return True

    return "".join(out) if walk(root) else None


def latex_mathml(latex: str) -> str | None:
    """Inline MathML of a LaTeX formula (sanitised), or None when it cannot be converted."""
    if not latex or len(latex) > MAX_LATEX or not latex.strip():
        return None
    try:
        from latex2mathml.converter import convert
    except ImportError:  # pragma: no cover - a declared dependency
        return None
    try:
        markup = convert(latex)
    except Exception:  # noqa: BLE001 - any failure of the converter: show the text
        return None
    return sanitise(markup)


def _roots_named(expr):
    """``CRootOf(P, k)`` replaced by ``root_(k+1)(P)`` (an undefined function, printed with a subscript)."""
    import sympy as sp

    reps = {}
    for r in expr.atoms(sp.CRootOf):
        reps[r] = sp.Function(f"root_{int(r.index) + 1}")(r.expr)
    return expr.xreplace(reps) if reps else expr


def sympy_mathml(value: Any) -> str | None:
    """Inline MathML of an exact value the engine computed (a sympy expression), or None."""
    import sympy as sp

    if not isinstance(value, sp.Basic) or isinstance(value, (sp.Integer,)) and abs(value) < 10 ** 6:
        return None if not isinstance(value, sp.Integer) else f"<math><mn>{int(value)}</mn></math>"
    try:
        from sympy.printing.mathml import mathml

        body = mathml(_roots_named(value), printer="presentation")
    except Exception:  # noqa: BLE001 - a value the printer does not know: show the text
        return None
    if len(body) > 20 * MAX_LATEX:
        return None
    body = re.sub(r"<mi>root_(\d+)</mi>", r"<msub><mi>root</mi><mn>\1</mn></msub>", body)
    return sanitise(f'<math display="inline">{body}</math>')


_LATEX_COMMAND = re.compile(r"\\[A-Za-z]+|\\[{}|,;!]")
_GREEK = ("alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau upsilon phi "
          "chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega").split()
_BARE_GREEK = re.compile(r"(?<![\\A-Za-z])(" + "|".join(_GREEK) + r")(?![A-Za-z])")
_WORD = re.compile(r"^\(?[A-Za-z][a-z]+[.,;:)]?$|^\[?[A-Za-z]+\]?$")
_MATHY_WORDS = set(_GREEK) | {"sin", "cos", "tan", "csc", "sec", "cot", "sinh", "cosh", "csch", "log", "exp", "sum",
                              "max", "min", "sup", "inf", "lim", "forall"}


def has_latex(text: str) -> bool:
    """Does a quoted statement contain LaTeX commands (``\\frac``, ``\\leq``, ...)?"""
    return bool(_LATEX_COMMAND.search(text or ""))


def _is_text_word(tok: str) -> bool:
    core = tok.strip("().,;:[]")
    return bool(_WORD.match(tok)) and len(core) >= 2 and core not in _MATHY_WORDS and "\\" not in tok


def quote_parts(statement: str) -> list[tuple[bool, str]]:
    """A quoted statement cut into words and formulas: ``(False, words)`` and ``(True, latex)`` in order
    (bare Greek names in a formula get their backslash). The one reading of a quote, for the HTML
    report (:func:`quote_html`) and the LaTeX verdict table (:mod:`analysis.cli.tables`).

    >>> quote_parts(r"and C^2 for 0 < omega < \\frac{1}{80}.")
    [(False, 'and'), (True, 'C^2'), (False, 'for'), (True, '0 < \\\\omega < \\\\frac{1}{80}.')]
    """
    parts: list[tuple[bool, str]] = []
    run: list[str] = []
    words: list[str] = []

    def flush_math() -> None:
        if run:
            parts.append((True, _BARE_GREEK.sub(r"\\\1", " ".join(run))))
            run.clear()

    def flush_words() -> None:
        if words:
            parts.append((False, " ".join(words)))
            words.clear()

    for tok in statement.split():
        if _is_text_word(tok) and tok.count("{") == tok.count("}"):
            # a word inside an open brace group belongs to the formula
            if run and " ".join(run).count("{") != " ".join(run).count("}"):
                run.append(tok)
                continue
            flush_math()
            words.append(tok)
        else:
            flush_words()
            run.append(tok)
    flush_words()
    flush_math()
    return parts


def quote_html(statement: str) -> str | None:
    """A quoted statement with its LaTeX typeset: words stay text (escaped), the runs of other tokens
    between them become MathML. None when a run does not convert (then show the source)."""
    if not has_latex(statement) or len(statement) > 4 * MAX_LATEX:
        return None
    out = []
    for is_math, text in quote_parts(statement):
        if not is_math:
            out.append(_html.escape(text))
            continue
        m = latex_mathml(text.replace("\\setminus", "\\smallsetminus"))
        if m is None:
            return None
        out.append(m)
    return " ".join(out)


_POWER = re.compile(r"\*\*(\(-?[\w/]+\)|-?[\w.]+)")
_ROOT = re.compile(r"CRootOf\(")
_CARET = re.compile(r"(?<=[A-Za-z0-9)])\^(\(-?[\w/+-]+\)|-?\w+)")


def _roots_text(s: str) -> str:
    """``CRootOf(P, k)`` -> ``root_(k+1)(P)`` in plain text (balanced parentheses)."""
    out, i = [], 0
    while True:
        m = _ROOT.search(s, i)
        if not m:
            out.append(s[i:])
            return "".join(out)
        out.append(s[i:m.start()])
        depth, j = 1, m.end()
        while j < len(s) and depth:
            depth += {"(": 1, ")": -1}.get(s[j], 0)
            j += 1
        inner = s[m.end():j - 1]
        poly, _, idx = inner.rpartition(",")
        if depth or not idx.strip().isdigit():
            out.append(s[m.start():j])
        else:
            out.append(f"root<sub>{int(idx) + 1}</sub>({poly.strip()})")
        i = j


def pretty_text(text: str) -> str:
    """Escaped ``text`` with the plain-text formulas typeset: ``x**2`` and ``C^2`` -> x<sup>2</sup>, C<sup>2</sup>,
    ``sqrt(`` -> √(,
    ``*`` -> ·, ``CRootOf(P, k)`` -> root<sub>k+1</sub>(P). Only markup this function adds is left unescaped."""
    s = _html.escape(str(text), quote=False)
    s = _roots_text(s)
    s = _POWER.sub(lambda m: f"<sup>{m.group(1).strip('()') if m.group(1).startswith('(') and '/' not in m.group(1) else m.group(1)}</sup>", s)
    s = _CARET.sub(lambda m: f"<sup>{m.group(1)}</sup>", s)
    s = re.sub(r"\bsqrt\(", "√(", s)
    s = re.sub(r"(?<=[\w)\]>])\*(?=[\w(√])", "·", s)
    return s
