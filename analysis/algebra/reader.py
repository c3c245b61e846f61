"""The one reader of text from users and paper files: formulas become sympy expressions built
from a whitelist, never by evaluating the text.

Every text a user or a paper file gives — mask coefficients, symbols, ``--param`` values,
``--where`` helpers, intervals, boxes, inequality sides, claimed values — goes through
:func:`read_expression`. The text is parsed by Python's :mod:`ast` in ``eval`` mode (parsing runs
no code) and the expression is built node by node from what the grammar below allows; anything
else is a one-line :class:`InputError` that says what to type instead. :func:`as_expr` converts a
*value* (an int, a ``Fraction``, a float, a sympy object, or text through the reader) and is what
the engine uses wherever a value may arrive from outside.

Grammar
-------
* numbers: integers and decimals, read exactly (``0.1`` is ``1/10``, ``1e-3`` is ``1/1000``);
* ``+ - * / **`` (``^`` is read as ``**``), unary minus, parentheses;
* the names the context allows (``z``, the level ``n``, ``h``, declared parameters, ``--where``
  names) and, where free parameters are expected, any other plain name (``omega``, ``w``, ``t1``);
* the constants ``pi``, ``E``, ``I`` (and ``oo`` where an interval end may be infinite);
* the functions of :data:`FUNCTIONS` (``sqrt``, ``cos``, ``sinh``, ``log``, ``log2``, ``Abs``, ...;
  ``diff(EXPR, NAME)`` and ``subs(EXPR, NAME, VALUE, ...)``) and the ones a context adds (e.g.
  ``a(k)``, a mask coefficient, in a paper's lemma); ``CRootOf(POLYNOMIAL, k)``, the form in which a
  computer algebra system prints a root of a rational polynomial.

Nothing else: no attributes, subscripts, keywords, lambdas, comprehensions, strings,
comparisons or ``//``. Sizes are limited (:data:`LIMITS`); a text over a limit is an error that
names the limit.

Examples
--------
>>> read_expression("(sqrt(6)-1)/80")
-1/80 + sqrt(6)/80
>>> read_expression("0.3258034280512983482745201730704003435580")
162901714025649174137260086535200171779/500000000000000000000000000000000000000
>>> read_expression("3/4+9*omega")
9*omega + 3/4
>>> read_expression("(1+z)^4/(8*z^2)")
(z + 1)**4/(8*z**2)
>>> read_expression("__import__('os').system('true')")
Traceback (most recent call last):
...
analysis.algebra.limits.InputError: cannot read "__import__('os').system('true')": an attribute (x.y) is not allowed
>>> read_expression("1//2")
Traceback (most recent call last):
...
analysis.algebra.limits.InputError: cannot read "1//2": '//' is not allowed: write / (exact division), e.g. 1/2
>>> read_expression("10**10**10")
Traceback (most recent call last):
...
analysis.algebra.limits.InputError: cannot read "10**10**10": the exponent 10000000000 exceeds the limit 10000 (limit 'exponent')
>>> read_expression("abc", free=False, what="mask coefficient")
Traceback (most recent call last):
...
analysis.algebra.limits.InputError: unknown name 'abc' in mask coefficient "abc": give its value with --param abc=VALUE, or correct the typo

Algorithm
---------
``ast.parse(text, mode="eval")`` builds the syntax tree (no evaluation); an explicit stack walks
it (chains ``a + b + c + ...`` are flattened, so only true nesting counts towards the depth
limit). Numbers are read from their source text with :class:`fractions.Fraction`, so decimals are
exact. Powers check the size of the result before computing it (a rational ``p/q`` to the power
``k`` has about ``k * log2(max(|p|, q))`` bits), every arithmetic step checks the size of its
rational result, and the polynomial degree of the expression is bounded (the degree of ``x**k``
is ``k`` times the degree of ``x``), so no text can ask for more than a few megabytes.

References
----------
Python Language Reference, "Full grammar specification" (the ``eval`` input mode);
:func:`ast.parse`.
"""

from __future__ import annotations

import ast
import math
import re
from fractions import Fraction
from typing import Any, Callable, Mapping

import sympy as sp

from ..result import AnalysisError
from .limits import LIMITS, InputError, Limits  # noqa: F401  (the reader's errors and limits)




def _sqrt(x):
    return sp.sqrt(x)


def _log(x, base=None):
    return sp.log(x) if base is None else sp.log(x, base)


def _log2(x):
    """``log2(x) = log(x)/log(2)``, exact (the form papers write Hölder exponents in).

    >>> read_expression("2 - log2(1 + sqrt(3))")
    -log(1 + sqrt(3))/log(2) + 2
    >>> read_expression("log2(8)")
    3
    """
    return sp.log(x, 2)


def _diff(expr, var):
    if not isinstance(var, sp.Symbol):
        raise InputError("diff(EXPR, NAME): the second argument must be a name, e.g. diff(sin(t)/t, t)", "value")
    return sp.diff(expr, var)


def _subs(expr, *pairs):
    names, values = pairs[0::2], pairs[1::2]
    if not all(isinstance(v, sp.Symbol) for v in names):
        raise InputError("subs(EXPR, NAME, VALUE, ...): give names and values in turn, e.g. subs(a(0), h, 1)", "value")
    return expr.subs(dict(zip(names, values)))


#: Named functions every formula may use: name -> (function, allowed numbers of arguments).
FUNCTIONS: dict[str, tuple[Callable, tuple[int, ...]]] = {
    "sqrt": (_sqrt, (1,)), "cbrt": (sp.cbrt, (1,)), "root": (sp.root, (2,)),
    "exp": (sp.exp, (1,)), "log": (_log, (1, 2)), "log2": (_log2, (1,)), "ln": (sp.log, (1,)),
    "sin": (sp.sin, (1,)), "cos": (sp.cos, (1,)), "tan": (sp.tan, (1,)), "cot": (sp.cot, (1,)),
    "sec": (sp.sec, (1,)), "csc": (sp.csc, (1,)),
    "sinh": (sp.sinh, (1,)), "cosh": (sp.cosh, (1,)), "tanh": (sp.tanh, (1,)), "coth": (sp.coth, (1,)),
    "sech": (sp.sech, (1,)), "csch": (sp.csch, (1,)),
    "asin": (sp.asin, (1,)), "acos": (sp.acos, (1,)), "atan": (sp.atan, (1,)), "acot": (sp.acot, (1,)),
    "asinh": (sp.asinh, (1,)), "acosh": (sp.acosh, (1,)), "atanh": (sp.atanh, (1,)),
    "atan2": (sp.atan2, (2,)), "sinc": (sp.sinc, (1,)),
    "Abs": (sp.Abs, (1,)), "abs": (sp.Abs, (1,)), "sign": (sp.sign, (1,)),
    "floor": (sp.floor, (1,)), "ceiling": (sp.ceiling, (1,)), "ceil": (sp.ceiling, (1,)),
    "Min": (sp.Min, tuple(range(1, 33))), "Max": (sp.Max, tuple(range(1, 33))),
    "min": (sp.Min, tuple(range(1, 33))), "max": (sp.Max, tuple(range(1, 33))),
    "re": (sp.re, (1,)), "im": (sp.im, (1,)), "conjugate": (sp.conjugate, (1,)),
    "diff": (_diff, (2,)), "subs": (_subs, (3, 5, 7, 9)),
}

#: Constants every formula may use.
CONSTANTS: dict[str, sp.Expr] = {"pi": sp.pi, "E": sp.E, "I": sp.I}

#: Names that are never parameters (sympy or Python meanings a user would not expect).
_RESERVED = frozenset({"oo", "inf", "nan", "zoo", "infinity", "None", "True", "False", "lambda"})

_NAME = re.compile(r"[^\W\d_]\w*\Z")
_NUMBER = re.compile(r"(?:\d[\d_]*(?:\.[\d_]*)?|\.\d[\d_]*)(?:[eE][+-]?\d+)?\Z")
_DIGIT_LETTER = re.compile(r"(?<![\w.])\d+(?:\.\d*)?[A-Za-z(]")

_OPS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}
_FORBIDDEN_OPS = {ast.FloorDiv: "'//' is not allowed: write / (exact division), e.g. 1/2",
                  ast.Mod: "'%' is not allowed", ast.MatMult: "'@' is not allowed",
                  ast.LShift: "'<<' is not allowed", ast.RShift: "'>>' is not allowed",
                  ast.BitOr: "'|' is not allowed", ast.BitAnd: "'&' is not allowed",
                  ast.BitXor: "'^' is not allowed"}
_NODE_WORDS = {ast.Attribute: "an attribute (x.y) is not allowed", ast.Subscript: "a subscript (x[...]) is not allowed",
               ast.Lambda: "a lambda is not allowed", ast.ListComp: "a comprehension is not allowed",
               ast.SetComp: "a comprehension is not allowed", ast.DictComp: "a comprehension is not allowed",
               ast.GeneratorExp: "a comprehension is not allowed",
               ast.Compare: "a comparison (<, ==, ...) is not allowed", ast.BoolOp: "'and'/'or' are not allowed",
               ast.IfExp: "'if ... else' is not allowed",
               ast.Tuple: "one value is expected here, not a list (separate values with commas only where a list is asked for)",
               ast.List: "drop the brackets [...]", ast.Dict: "braces {...} are not allowed",
               ast.Set: "braces {...} are not allowed", ast.JoinedStr: "a string is not a number: drop the quotes",
               ast.Starred: "'*' unpacking is not allowed", ast.NamedExpr: "':=' is not allowed",
               ast.Await: "'await' is not allowed", ast.Yield: "'yield' is not allowed", ast.YieldFrom: "'yield' is not allowed"}

#: Unicode signs that PDFs put where ASCII is meant.
_UNICODE = str.maketrans({"\u2212": "-", "\u2013": "-", "\u00d7": "*", "\u22c5": "*", "\u00b7": "*",
                          "\u2044": "/", "\u00a0": " ", "\u2009": " ", "\u202f": " "})


def _quote(text: str, width: int = 60) -> str:
    t = text if len(text) <= width else text[:width - 3] + "..."
    return '"' + t.replace('"', '\\"') + '"'


def _bits(x: sp.Rational) -> int:
    return max(int(x.p).bit_length(), int(x.q).bit_length())


def _degree(e: sp.Expr, weights: Mapping[sp.Symbol, int] | None = None) -> int:
    """A cheap bound of the polynomial degree of ``e`` in its free symbols (0 for numbers); a
    symbol in ``weights`` counts with its weight (the degree of what will be substituted for it)."""
    if e.is_Number or not e.free_symbols:
        return 0
    if e.is_Symbol:
        return weights.get(e, 1) if weights else 1
    if e.is_Pow and e.exp.is_Rational:
        return abs(int(e.exp.p)) * _degree(e.base, weights)
    if e.is_Mul:
        return sum(_degree(a, weights) for a in e.args)
    return max((_degree(a, weights) for a in e.args), default=0)


def substitute(e: sp.Expr, defs: Mapping[sp.Symbol, sp.Expr], *, what: str = "the formula",
               limits: Limits = LIMITS) -> sp.Expr:
    """``e.subs(defs)``, refused before the substitution when the degree of the result, bounded by
    the degrees of ``e`` and of the definitions, exceeds ``limits.degree`` (chains of definitions
    ``b0 = b1**2, b1 = b2**2, ...`` multiply degrees).

    >>> b, z = sp.symbols("b z")
    >>> substitute(b**2 + 1, {b: 1 + z})
    (z + 1)**2 + 1
    >>> substitute(b**2, {b: z**1500}, what="the mask")
    Traceback (most recent call last):
    ...
    analysis.algebra.limits.InputError: the mask after substituting the definitions has degree up to 3000: the limit is 2000 (limit 'degree'); use definitions of lower degree
    """
    used = check_substitution(e, defs, what=what, limits=limits)
    return e.subs(used) if used else e


def check_substitution(e: sp.Expr, defs: Mapping[sp.Symbol, sp.Expr], *, what: str = "the formula",
                       limits: Limits = LIMITS) -> dict:
    """The definitions ``e`` uses, after checking the degree bound of :func:`substitute`."""
    used = {d: v for d, v in defs.items() if d in e.free_symbols}
    if used:
        d = _degree(e, {k: _degree(v) for k, v in used.items()})
        if d > limits.degree:
            raise InputError(f"{what} after substituting the definitions has degree up to {d}: the limit is "
                             f"{limits.degree} (limit 'degree'); use definitions of lower degree", "limit")
    return used


class _Reader:
    def __init__(self, text, names, free, functions, what, allow_infinity, limits, hint):
        self.text, self.names, self.free = text, names, free
        self.functions, self.what, self.infinity = functions, what, allow_infinity
        self.limits, self.hint = limits, hint

    # ------------------------------------------------------------------ errors
    def fail(self, reason: str, kind: str = "syntax"):
        raise InputError(f"cannot read {self.where()}: {reason}", kind)

    def where(self) -> str:
        return (f"{self.what} " if self.what else "") + _quote(self.text)

    def limit(self, key: str, what: str, value, limit) -> None:
        raise InputError(f"cannot read {self.where()}: {what} {value} exceeds the limit {limit} "
                         f"(limit '{key}')", "limit")

    # ------------------------------------------------------------------ leaves
    def number(self, node: ast.Constant) -> sp.Expr:
        v = node.value
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            if isinstance(v, str):
                self.fail("a string is not a number: drop the quotes")
            if isinstance(v, complex):
                self.fail("write complex numbers with I, e.g. 1 + 2*I")
            self.fail(f"{v!r} is not a number")
        # one line: the column offsets (UTF-8 bytes) cut the literal's own text out of the source
        src = self.src_bytes[node.col_offset:node.end_col_offset].decode("utf-8", "replace").strip() or repr(v)
        if not _NUMBER.match(src):
            self.fail(f"the number {src!r} must be written in decimal, e.g. 16 or 0.25")
        digits = sum(ch.isdigit() for ch in src.split("e")[0].split("E")[0])
        if digits > self.limits.digits:
            self.limit("digits", "a number with", f"{digits} digits", f"{self.limits.digits} digits")
        m = re.search(r"[eE]([+-]?\d+)\Z", src)
        if m and abs(int(m.group(1))) > self.limits.exponent:
            self.limit("exponent", "the exponent", abs(int(m.group(1))), self.limits.exponent)
        # bits of the exact value, bounded before it is built: digits + |exponent| decimal digits
        bits = math.ceil((digits + (abs(int(m.group(1))) if m else 0)) * math.log2(10))
        if bits > self.limits.bits + 4:
            self.limit("bits", "a number of about", f"{bits} bits", f"{self.limits.bits} bits")
        f = Fraction(src.replace("_", ""))
        return self.check(sp.Rational(f.numerator, f.denominator))

    def name(self, node: ast.Name) -> sp.Expr:
        nm = node.id
        if nm in self.names:
            return self.names[nm]
        if nm in CONSTANTS:
            return CONSTANTS[nm]
        if nm in ("oo", "inf") and self.infinity:
            return sp.oo
        if nm in self.functions:
            self.fail(f"{nm} is a function: write {nm}(...)", "name")
        if nm.startswith("_") or not _NAME.match(nm):
            self.fail(f"{nm!r} is not an allowed name (names begin with a letter)", "name")
        if len(nm) > self.limits.name:
            self.limit("name", "a name of", f"{len(nm)} characters", f"{self.limits.name} characters")
        if nm in _RESERVED:
            self.fail(f"{nm!r} is not a finite number" + (" (infinity is allowed only as an interval end)"
                                                          if nm in ("oo", "inf", "infinity") else ""), "value")
        free = self.free(nm) if callable(self.free) else self.free
        if not free:
            raise InputError(f"unknown name {nm!r} in {self.where()}: "
                             + (self.hint.format(name=nm) if self.hint else
                                f"give its value with --param {nm}=VALUE, or correct the typo"), "name")
        return sp.Symbol(nm)

    # ------------------------------------------------------------------ arithmetic
    def check(self, e: sp.Expr) -> sp.Expr:
        """Size of a rational result; an atom that is not finite. Structural tests only: asking
        sympy whether a large algebraic expression is infinite can take minutes."""
        if e.is_Rational and _bits(e) > self.limits.bits:
            self.limit("bits", "a number of", f"{_bits(e)} bits", f"{self.limits.bits} bits")
        if e.is_Atom and (e in (sp.zoo, sp.nan) or (e in (sp.oo, -sp.oo) and not self.infinity)):
            self.fail("the value is not a finite number (a division by zero?)", "value")
        return e

    def check_finite(self, e: sp.Expr) -> sp.Expr:
        """The whole result (and each function value): no ``zoo``/``nan`` (``log(0)``, ``tan(pi/2)``)
        and no infinity inside an expression."""
        bad = (sp.zoo, sp.nan) if self.infinity else (sp.zoo, sp.nan, sp.oo, -sp.oo)
        if e.has(*bad) and not (self.infinity and e in (sp.oo, -sp.oo)):
            self.fail("the value is not a finite number (a division by zero?)", "value")
        return e

    def power(self, base: sp.Expr, exp: sp.Expr) -> sp.Expr:
        if exp.is_Number:
            if not exp.is_Rational:
                self.fail("the exponent must be exact", "value")
            for part in (exp.p, exp.q):
                if abs(int(part)) > self.limits.exponent:
                    self.limit("exponent", "the exponent", exp, self.limits.exponent)
            if base.is_Rational:
                if base == 0 and exp < 0:
                    self.fail("division by zero (0 to a negative power: not a finite number)", "value")
                if exp.is_Integer and _bits(base) * abs(int(exp)) > self.limits.bits:
                    self.limit("bits", "a power of about", f"{_bits(base) * abs(int(exp))} bits",
                               f"{self.limits.bits} bits")
            d = _degree(base) * abs(int(exp.p))
            if d > self.limits.degree:
                self.limit("degree", "the degree", d, self.limits.degree)
        elif base.is_Number and base.is_Rational and abs(base) != 1 and exp.is_number:
            # a numeric but irrational exponent (2**sqrt(2)): fine, sympy keeps it symbolic
            pass
        return self.check(base ** exp)

    def binop(self, op, x: sp.Expr, y: sp.Expr) -> sp.Expr:
        if op is ast.Add:
            r = x + y
        elif op is ast.Sub:
            r = x - y
        elif op is ast.Mult:
            r = x * y
        elif op is ast.Div:
            if y == 0:
                self.fail("division by zero (not a finite number)", "value")
            r = x / y
        else:
            return self.power(x, y)
        if op in (ast.Mult, ast.Div):
            d = _degree(r)
            if d > self.limits.degree:
                self.limit("degree", "the degree", d, self.limits.degree)
        return self.check(r)

    def crootof(self, node: ast.Call, depth: int) -> sp.Expr:
        """``CRootOf(POLY, k)``: the k-th root of a rational polynomial in one variable of its own
        (the form a computer algebra system prints a closed form in)."""
        if len(node.args) != 2 or node.keywords:
            self.fail("write CRootOf(POLYNOMIAL, INDEX), e.g. CRootOf(x**3 - x - 1, 0)")
        inner = _Reader(self.text, {}, True, self.functions, self.what, False, self.limits, self.hint)
        inner.src, inner.src_bytes = self.src, self.src_bytes
        poly_expr = inner.build(node.args[0], depth + 1)
        index = self.build(node.args[1], depth + 1)
        syms = poly_expr.free_symbols
        if len(syms) != 1 or not index.is_Integer:
            self.fail("CRootOf(POLYNOMIAL, INDEX) needs a polynomial in one variable and an integer index", "value")
        try:
            P = sp.Poly(poly_expr, *syms, domain=sp.QQ)
        except (sp.PolynomialError, sp.CoercionFailed, sp.GeneratorsError):
            self.fail("CRootOf needs a polynomial with rational coefficients", "value")
        if not 1 <= P.degree() <= self.limits.crootof:
            self.limit("crootof", "the degree of the CRootOf polynomial", P.degree(), self.limits.crootof)
        k = int(index)
        if not -P.degree() <= k < P.degree():
            self.fail(f"CRootOf index {k}: a polynomial of degree {P.degree()} has roots 0..{P.degree() - 1}", "value")
        return sp.CRootOf(P.as_expr(), k)

    def subs_degree(self, args) -> None:
        """The degree of ``subs(EXPR, NAME, VALUE, ...)`` is at most deg(EXPR) * max deg(VALUE):
        bounded before sympy substitutes (and later code expands) the result."""
        d = _degree(args[0]) * max([1] + [_degree(v) for v in args[2::2]])
        if d > self.limits.degree:
            self.limit("degree", "the degree of the subs(...) result, up to", d, self.limits.degree)

    # ------------------------------------------------------------------ the walk
    def run(self) -> sp.Expr:
        text = self.text
        if len(text) > self.limits.text:
            raise InputError(f"cannot read {self.what or 'a formula'} of {len(text)} characters: "
                             f"the limit is {self.limits.text} (limit 'text')", "limit")
        src = text.translate(_UNICODE).replace("^", "**").strip()
        if not src:
            raise InputError(f"empty {self.what or 'formula'}: give a number or a formula, e.g. 1/4", "syntax")
        if "\n" in src or "\r" in src:
            self.fail("a formula is one line")
        self.src = src
        self.src_bytes = src.encode("utf-8")
        run = max((len(m) for m in re.findall(r"\d+", src)), default=0)
        if run > self.limits.digits:
            self.limit("digits", "a number with", f"{run} digits", f"{self.limits.digits} digits")
        try:
            tree = ast.parse(src, mode="eval")
        except SyntaxError as exc:
            self.fail(self.syntax_hint(src, exc))
        except (RecursionError, MemoryError):
            self.limit("depth", "the nesting depth", "of the formula", self.limits.depth)
        except ValueError as exc:      # e.g. an integer literal over Python's digit limit
            self.fail(str(exc).split("\n")[0], "limit")
        diffs = sum(isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id == "diff"
                    and "diff" not in self.names for n in ast.walk(tree))
        if diffs > self.limits.diffs:
            self.limit("diffs", "the number of diff(...) calls", diffs, self.limits.diffs)
        return self.check_finite(self.build(tree.body))

    def syntax_hint(self, src: str, exc: SyntaxError) -> str:
        if src.startswith("[") or src.endswith("]"):
            return "drop the brackets"
        if _DIGIT_LETTER.search(src):
            return "write * for multiplication, e.g. 2*z, not 2z"
        if src.count("(") != src.count(")"):
            return "unbalanced parentheses"
        if "=" in src:
            return "'=' is not part of a formula (give NAME=VALUE only where an option asks for it)"
        return f"not a formula ({exc.msg})"

    def build(self, root: ast.AST, depth: int = 1) -> sp.Expr:
        """Post-order walk with an explicit stack; chains of + - and * / are flattened."""
        # stack items: (node, depth, state); results go on `out`
        out: list[sp.Expr] = []
        stack: list[tuple] = [("visit", root, depth)]
        while stack:
            item = stack.pop()
            if item[0] == "visit":
                _, node, depth = item
                if depth > self.limits.depth:
                    self.limit("depth", "the nesting depth", depth, self.limits.depth)
                self.visit(node, depth, stack, out)
            else:
                item[1](out)
        assert len(out) == 1
        return out[0]

    def visit(self, node, depth, stack, out) -> None:
        if isinstance(node, ast.Constant):
            out.append(self.number(node))
        elif isinstance(node, ast.Name):
            out.append(self.name(node))
        elif isinstance(node, ast.UnaryOp):
            if isinstance(node.op, ast.USub):
                stack.append(("apply", lambda o: o.append(self.check(-o.pop()))))
            elif isinstance(node.op, ast.UAdd):
                pass
            else:
                self.fail("only unary - and + are allowed")
            stack.append(("visit", node.operand, depth + 1))
        elif isinstance(node, ast.BinOp):
            op = type(node.op)
            if op in _FORBIDDEN_OPS:
                self.fail(_FORBIDDEN_OPS[op])
            if op is ast.Pow:
                def apply_pow(o):
                    e = o.pop()
                    b = o.pop()
                    o.append(self.power(b, e))
                stack.append(("apply", apply_pow))
                stack.append(("visit", node.right, depth + 1))
                stack.append(("visit", node.left, depth + 1))
                return
            # flatten a left spine of the same precedence class
            group = (ast.Add, ast.Sub) if op in (ast.Add, ast.Sub) else (ast.Mult, ast.Div)
            terms, ops = [], []
            cur = node
            while isinstance(cur, ast.BinOp) and type(cur.op) in group:
                terms.append(cur.right)
                ops.append(type(cur.op))
                cur = cur.left
            if isinstance(cur, ast.BinOp) and type(cur.op) in _FORBIDDEN_OPS:
                self.fail(_FORBIDDEN_OPS[type(cur.op)])
            terms.append(cur)
            terms.reverse()
            ops.reverse()
            n = len(terms)

            def apply_chain(o, ops=ops, n=n):
                vals = o[-n:]
                del o[-n:]
                acc = vals[0]
                if group[0] is ast.Add:
                    pos, neg = [vals[0]], []
                    for op_, v in zip(ops, vals[1:]):
                        (pos if op_ is ast.Add else neg).append(v)
                    acc = self.check(sp.Add(*pos) - sp.Add(*neg))
                else:
                    for op_, v in zip(ops, vals[1:]):
                        acc = self.binop(op_, acc, v)
                o.append(acc)
            stack.append(("apply", apply_chain))
            for t in reversed(terms):
                stack.append(("visit", t, depth + 1))
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in ("CRootOf", "RootOf") \
                and node.func.id not in self.names:
            out.append(self.crootof(node, depth))
        elif isinstance(node, ast.Call):
            f = node.func
            if not isinstance(f, ast.Name) or f.id not in self.functions:
                what = ("an attribute (x.y)" if isinstance(f, ast.Attribute)
                        else f"the function {f.id!r}" if isinstance(f, ast.Name) and _NAME.match(f.id)
                        and not f.id.startswith("_") and f.id not in self.names
                        else "a function call other than the named functions (sqrt, cos, exp, ...)")
                if isinstance(f, ast.Name) and f.id in self.names:
                    self.fail(f"{f.id} is a value, not a function: write {f.id}*(...) for a product")
                if what.startswith("the function"):
                    self.fail(f"{what} is not one of the named functions ({', '.join(sorted(self.functions)[:12])}, ...)")
                self.fail(f"{what} is not allowed")
            if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
                self.fail(f"{f.id}(...) takes plain arguments, no keywords")
            fn, counts = self.functions[f.id]
            if len(node.args) not in counts:
                self.fail(f"{f.id} takes {' or '.join(map(str, counts[:3]))} argument(s), not {len(node.args)}")
            n = len(node.args)

            def apply_call(o, fn=fn, n=n, name=f.id):
                args = o[-n:]
                del o[-n:]
                if name == "subs" and fn is _subs:
                    self.subs_degree(args)
                try:
                    r = fn(*args)
                except InputError:
                    raise
                except AnalysisError as exc:
                    self.fail(str(exc), "value")
                except (TypeError, ValueError, ArithmeticError, IndexError, KeyError) as exc:
                    self.fail(f"{name}(...) cannot take these arguments ({type(exc).__name__})", "value")
                if not isinstance(r, sp.Expr):
                    r = sp.sympify(r, strict=True)
                o.append(self.check_finite(self.check(r)))
            stack.append(("apply", apply_call))
            for a in reversed(node.args):
                stack.append(("visit", a, depth + 1))
        else:
            for cls, reason in _NODE_WORDS.items():
                if isinstance(node, cls):
                    self.fail(reason)
            self.fail(f"{type(node).__name__} is not allowed")



def read_expression(text: str, *, names: Mapping[str, sp.Expr] | None = None,
                    free: bool | Callable[[str], bool] = True,
                    functions: Mapping[str, tuple[Callable, tuple[int, ...]]] | None = None,
                    what: str = "", allow_infinity: bool = False, hint: str | None = None,
                    limits: Limits = LIMITS) -> sp.Expr:
    """The sympy expression of ``text`` (the grammar of the module docstring).

    ``names`` maps the names the context defines (``z``, ``n``, parameters, ``--where`` helpers)
    to their values; any other plain name becomes a ``Symbol`` when ``free`` is true (or a
    predicate that accepts it), else it is an error (``hint`` replaces the suggestion; ``{name}``
    is the name). ``functions`` adds context functions to :data:`FUNCTIONS` (name -> (callable,
    argument counts)); ``what`` names the text in messages; ``allow_infinity`` admits ``oo``.

    >>> read_expression("2*c + 1", names={"c": sp.cos(sp.Symbol("t"))})
    2*cos(t) + 1
    >>> read_expression("-oo", allow_infinity=True)
    -oo
    """
    if not isinstance(text, str):
        raise InputError(f"expected a formula as text, not {type(text).__name__}", "value")
    fns = dict(FUNCTIONS)
    if functions:
        fns.update(functions)
    r = _Reader(text, dict(names or {}), free, fns, what, allow_infinity, limits, hint)
    return r.run()


class _TextReachedSympy(AnalysisError):
    """Unsafe text reached sympy's string parser while
    :func:`~analysis.algebra.guard.sympy_parser_guarded` was active (checked by :func:`_safe_for_sympy`).

    >>> from analysis.algebra.guard import sympy_parser_guarded
    >>> with sympy_parser_guarded():
    ...     ok = sp.sympify("sqrt(2)/2 + x")
    ...     bad = sp.sympify("__import__('os').getcwd()")
    Traceback (most recent call last):
    ...
    analysis.algebra.reader._TextReachedSympy: text "__import__('os').getcwd()" reached sympy's parser instead of the input reader (please report this)
    >>> ok
    x + sqrt(2)/2
    """


#: Functions sympy's own code may write into the strings it parses (``nsimplify`` builds its
#: candidates as text): the named functions and a few constructors, nothing that reaches Python.
_SYMPY_CALLS = frozenset(FUNCTIONS) | {"Integer", "Rational", "Float", "Mul", "Add", "Pow", "CRootOf",
                                       "RootOf", "log", "exp", "sqrt", "cbrt", "root", "gamma", "zeta",
                                       "polylog", "LambertW"}


def _safe_for_sympy(text: str) -> bool:
    """Is ``text`` built only of numbers, names, arithmetic and calls of :data:`_SYMPY_CALLS`?"""
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    for node in ast.walk(tree):
        if isinstance(node, (ast.Expression, ast.Load, ast.operator, ast.unaryop)):
            if isinstance(node, ast.operator) and not isinstance(node, tuple(_OPS)):
                return False
            continue
        if isinstance(node, ast.BinOp) or isinstance(node, ast.UnaryOp):
            continue
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
            continue
        if isinstance(node, ast.Name) and not node.id.startswith("_"):
            continue
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _SYMPY_CALLS
                and not node.keywords):
            continue
        return False
    return True


def read_in_context(text: Any, context: Mapping[str, Any], *, what: str = "",
                    free: bool | Callable[[str], bool] = False, hint: str | None = None) -> sp.Expr:
    """:func:`read_expression` with a context that maps names to values *or* to functions of
    one argument (a paper's ``a(k)``: the mask coefficient of ``z^k``). Non-text values (TOML
    numbers) are converted by :func:`as_expr`; a TOML float is read from its decimal text.

    >>> read_in_context("a(1) + w", {"a": lambda k: 2 * k, "w": sp.Symbol("w")})
    w + 2
    """
    if isinstance(text, float):
        text = repr(text)
    if not isinstance(text, str):
        return as_expr(text, what=what)
    names, functions = {}, {}
    for k, v in context.items():
        if isinstance(v, sp.Basic) or isinstance(v, (int, Fraction)):
            names[k] = as_expr(v)
        elif callable(v):
            functions[k] = (v, (1,))
    return read_expression(text, names=names, functions=functions, what=what, free=free, hint=hint)


def as_expr(x: Any, *, what: str = "", names: Mapping[str, sp.Expr] | None = None,
            free: bool | Callable[[str], bool] = True, allow_infinity: bool = False) -> sp.Expr:
    """A sympy object for a *value*: text goes through :func:`read_expression`; ints, fractions,
    sympy and numpy numbers convert exactly; Python floats stay floats (as ``sympy.sympify``
    does; say ``exact_number`` for the rational a float represents). Lists, dicts and other
    objects are refused — nothing reaches sympy's string parser.

    >>> as_expr("1/3"), as_expr(2), as_expr(sp.pi)
    (1/3, 2, pi)
    >>> as_expr(("1", "2"))
    Traceback (most recent call last):
    ...
    analysis.algebra.limits.InputError: expected one number or formula, not a tuple
    """
    if isinstance(x, sp.Basic):
        return x
    if isinstance(x, str):
        return read_expression(x, what=what, names=names, free=free, allow_infinity=allow_infinity)
    if isinstance(x, bool):
        raise InputError(f"{x!r} is not a number", "value")
    if isinstance(x, (int, Fraction)):
        r = sp.Rational(x.numerator, x.denominator)
        if _bits(r) > LIMITS.bits:
            raise InputError(f"{what or 'a number'} of {_bits(r)} bits exceeds the limit {LIMITS.bits} bits "
                             "(limit 'bits'): give a number of fewer digits", "limit")
        return r
    if isinstance(x, (list, tuple, dict, set, frozenset, bytes)):
        raise InputError(f"expected one number or formula, not a {type(x).__name__}", "value")
    try:
        import numpy as np

        if isinstance(x, np.str_):
            return read_expression(str(x), what=what, names=names, free=free, allow_infinity=allow_infinity)
        if isinstance(x, np.ndarray):
            raise InputError("expected one number or formula, not an array", "value")
    except ImportError:  # pragma: no cover
        pass
    try:
        return sp.sympify(x, strict=True)
    except (sp.SympifyError, TypeError, ValueError):
        raise InputError(f"{type(x).__name__} value {str(x)[:40]!r} is not a number or formula", "value") from None


def exact_number(x: Any, *, what: str = "number") -> sp.Expr:
    """An exact real or complex number without free names: text through the reader, floats
    as the rational they represent.

    >>> exact_number(0.5), exact_number("sqrt(2)/2")
    (1/2, sqrt(2)/2)
    >>> exact_number("w")
    Traceback (most recent call last):
    ...
    analysis.algebra.limits.InputError: unknown name 'w' in number "w": a number is expected here
    """
    if isinstance(x, float):
        if x != x or x in (float("inf"), float("-inf")):
            raise InputError(f"{what} {x!r} is not a finite number", "value")
        return sp.Rational(x)
    if isinstance(x, str):
        return read_expression(x, what=what, free=False, hint="a number is expected here")
    e = as_expr(x, what=what)
    if e.free_symbols:
        raise InputError(f"{what} {sp.sstr(e)} must be a number", "value")
    return e
