"""The commented paper-file template of ``subdiv new-paper``: metadata, two schemes (the
four-point scheme by its mask, the exponential Chaikin scheme by its level-dependent mask) and one
example claim of every kind (:data:`analysis.claims.kinds.KIND_CLASSES`), each with its fields.
The template itself loads and evaluates (a test checks it).

Examples
--------
>>> from analysis.claims.paperfile import parse_paper
>>> p = parse_paper(template(), "new.toml")
>>> len(p.claims) == len(KIND_CLASSES), p.claims[0].id
(True, '900:Example.mask-identity')

Algorithm
---------
Each kind class carries its one-line summary, its required and optional fields and an example
(``example``); the template is generated from them, so a new kind appears in it automatically.

References
----------
TOML v1.0.0 (https://toml.io/en/v1.0.0).
"""

from __future__ import annotations

from .kinds import KIND_CLASSES

__all__ = ["template"]

HEADER = '''# A paper file for `subdiv report FILE.toml` / `subdiv check FILE.toml`.
# Numbers are exact: "1/16", "(sqrt(5)-1)/8", "0.25" (read as 1/4). Intervals: "(a, b)", "[a, b)".
# Our convention: (S_a f)_i = sum_j a_(i-2j) f_j, a(z) = sum_i a_i z^i.

[paper]
id = "900"                      # a short id; claim ids become "900:<numbering>"
title = "Example: the four-point scheme and the exponential Chaikin scheme"
authors = ["N. Dyn", "D. Levin", "J. A. Gregory"]
citation = "N. Dyn, D. Levin, J. A. Gregory, A 4-point interpolatory subdivision scheme for curve design, CAGD 4 (1987) 257-268"
source = "https://doi.org/10.1016/0167-8396(87)90001-X"
notes = "The template of `subdiv new-paper`: one example claim of every kind."

# A scheme: exactly one of catalogue = "four-point" | mask + start | rules = { even, odd, first }
#           | symbol = "(1+z)**3/(4*z**2)" | level_mask + start (level-dependent; n or h = 2^-n).
# An m-ary scheme adds arity = 3 (mask, symbol or catalogue; a catalogue entry brings its arity), or is
# given by its M rules: rules = { stencils = [[1], ["2/3", "1/3"], ["1/3", "2/3"]], first = 0 } (the r-th
# stencil gives f[M i + r]; its coefficient of f[i+p] is a_(r - M p); first = [p_0, ...] per stencil).
# The kinds mask identity, sum rules, symmetry, interpolatory, support, eigenvalues, reproduction,
# norm test, ck range, smoothness, holder, sobolev and smoothness profile then use the m-ary analyses.
# Exponents may be written in closed form: value = "2 - log2(1 + sqrt(3))" is compared exactly.
[schemes.four-point]
mask = ["-w", 0, "1/2 + w", 1, "1/2 + w", 0, "-w"]
start = -3
parameters = { w = "(-1/4, 1/4)" }     # name = domain
notes = "transcription notes: how garbled print was read"

[schemes.exp-chaikin]
level_mask = ["1/(2*(1 + cosh(t*h/2)))", "(2*cosh(t*h/2) + 1)/(2*(1 + cosh(t*h/2)))",
              "(2*cosh(t*h/2) + 1)/(2*(1 + cosh(t*h/2)))", "1/(2*(1 + cosh(t*h/2)))"]
start = -2
parameters = { t = "(0, oo)" }

# Claims: id (the paper's numbering), statement (verbatim), reading (ours, if garbled), kind,
# scheme (optional with one scheme), then the kind's fields.
'''

LEVEL_KINDS = {"weighted series", "asymptotic equivalence", "exponential reproduction"}


def _claim(name: str, cls) -> str:
    fields = [f"#   {k}: {v}" for k, v in {**cls.required, **cls.optional}.items()]
    lines = [f"# --- kind \"{name}\": {cls.summary}", "# fields:", *fields, "[[claims]]",
             f'id = "Example.{name.replace(" ", "-")}"',
             f'statement = "An example claim of kind {name}."', f'kind = "{name}"']
    if cls.uses_scheme:
        lines.append(f'scheme = "{"exp-chaikin" if name in LEVEL_KINDS else "four-point"}"')
    lines.append(cls.example)
    return "\n".join(lines) + "\n"


def template() -> str:
    """The commented template (TOML text)."""
    return HEADER + "\n" + "\n".join(_claim(n, c) for n, c in KIND_CLASSES.items())
