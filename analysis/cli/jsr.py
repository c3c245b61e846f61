"""``subdiv jsr FILE``: the certified joint spectral radius of any finite family of real matrices.

The file is JSON: a list of square matrices of one size, each a list of rows; an entry is an
integer, a JSON number (a decimal, read exactly: ``0.1`` is ``1/10``) or a string read by the
input reader (``"1/3"``, ``"-0.25"``, ``"sqrt(3)/4"``). Sizes are limited (:data:`MAX_MATRICES`,
:data:`MAX_DIMENSION`, :data:`MAX_ENTRY_CHARS`, :data:`MAX_FILE_BYTES`, and an entry other than 0 lies
between ``1e-50`` and ``1e50`` in absolute value: :data:`MAX_MAGNITUDE_DIGITS`).

Examples
--------
::

    subdiv jsr pair.json                  # [[[1,1],[0,1]], [[1,0],[1,1]]]: the golden ratio
    subdiv jsr pair.json --budget 20000 --json

Register with ``analysis.cli.main.COMMAND_MODULES`` (nothing heavy is imported at module level).
"""

from __future__ import annotations

import os

from ..result import AnalysisError
from .common import WORK_HELP, work_arg

#: most matrices in a family
MAX_MATRICES = 16
#: largest matrix size
MAX_DIMENSION = 64
#: characters of one entry written as a string
MAX_ENTRY_CHARS = 200
#: size of the file
MAX_FILE_BYTES = 4_000_000
#: largest |entry|, and smallest |entry| other than 0 (the float search squares products of the matrices)
MAX_MAGNITUDE_DIGITS = 50

_SHAPE_HINT = ('write the file as a JSON list of square matrices of one size, e.g. '
               '[[[1, 1], [0, 1]], [[1, 0], [1, 1]]]')


def read_family(path: str) -> list:
    """The matrices of a family file, entries as exact sympy numbers (see the module docstring).

    >>> import json, tempfile
    >>> with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    ...     json.dump([[[1, "1/2"], [0.25, "sqrt(2)"]]], f)
    >>> read_family(f.name)
    [[[1, 1/2], [1/4, sqrt(2)]]]
    >>> with open(f.name, "w") as g:
    ...     _ = g.write('[[[1, 2]]]')
    >>> read_family(f.name)
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: matrix 0 is not square (1 rows of length 2): write the file as a JSON list of square matrices of one size, e.g. [[[1, 1], [0, 1]], [[1, 0], [1, 1]]]
    """
    import json

    import sympy as sp

    from ..algebra.reader import InputError, exact_number
    from ..algebra.json_input import load_json

    try:
        size = os.path.getsize(path)
    except OSError as exc:
        raise AnalysisError(f"cannot read {path!r}: {exc.strerror or exc}; give the path of a JSON "
                            "file of matrices") from None
    if size > MAX_FILE_BYTES:
        raise AnalysisError(f"{path!r} has {size} bytes, more than the limit {MAX_FILE_BYTES}")
    try:
        # JSON numbers with a fraction or exponent arrive as their text: read exactly below
        data = load_json(path, limit=MAX_FILE_BYTES, what="the matrix file", parse_float=str,
                         parse_constant=lambda c: c)
    except UnicodeDecodeError:
        raise AnalysisError(f"{path!r} is not a text file (not UTF-8): {_SHAPE_HINT}") from None
    except OSError as exc:
        raise AnalysisError(f"cannot read {path!r}: {exc.strerror or exc}; give the path of a JSON "
                            "file of matrices") from None
    except json.JSONDecodeError as exc:
        raise AnalysisError(f"{path!r} is not JSON ({exc.msg} at line {exc.lineno} column "
                            f"{exc.colno}): {_SHAPE_HINT}") from None
    if not isinstance(data, list) or not data:
        raise AnalysisError(f"{path!r} holds no list of matrices: {_SHAPE_HINT}")
    if len(data) > MAX_MATRICES:
        raise AnalysisError(f"{len(data)} matrices: at most {MAX_MATRICES} are allowed")
    n = None
    out = []
    for t, M in enumerate(data):
        if not isinstance(M, list) or not M or not all(isinstance(row, list) for row in M):
            raise AnalysisError(f"matrix {t} is not a list of rows: {_SHAPE_HINT}")
        if len(M) > MAX_DIMENSION:
            raise AnalysisError(f"matrix {t} has {len(M)} rows: at most {MAX_DIMENSION} are allowed")
        if any(len(row) != len(M) for row in M):
            raise AnalysisError(f"matrix {t} is not square ({len(M)} rows of length "
                                f"{', '.join(sorted({str(len(r)) for r in M}))}): {_SHAPE_HINT}")
        if n is None:
            n = len(M)
        elif len(M) != n:
            raise AnalysisError(f"matrix {t} is {len(M)}x{len(M)} but matrix 0 is {n}x{n}: "
                                "all matrices of a family have one size")
        rows = []
        for a, row in enumerate(M):
            vals = []
            for b, x in enumerate(row):
                where = f"entry [{a}][{b}] of matrix {t}"
                if isinstance(x, bool) or not isinstance(x, (int, str)):
                    raise AnalysisError(f"{where} is {json.dumps(x)[:40]}: write a number such as "
                                        '3, 0.25 or "1/3"')
                if isinstance(x, str) and len(x) > MAX_ENTRY_CHARS:
                    raise AnalysisError(f"{where} has {len(x)} characters, more than the limit "
                                        f"{MAX_ENTRY_CHARS}")
                if isinstance(x, int) and x.bit_length() > 4 * MAX_ENTRY_CHARS:
                    raise AnalysisError(f"{where} has more than {MAX_ENTRY_CHARS} digits")
                try:
                    v = exact_number(x, what=where)
                except InputError as exc:
                    raise AnalysisError(str(exc)) from None
                if not v.is_real:
                    raise AnalysisError(f"{where} = {v} is not a real number: the JSR is for real "
                                        "matrices")
                if v != 0 and not _within_magnitude(v):
                    raise AnalysisError(f"{where} is {sp.Float(v, 3)}: entries other than 0 are limited to "
                                        f"1e-{MAX_MAGNITUDE_DIGITS} <= |x| <= 1e{MAX_MAGNITUDE_DIGITS}; "
                                        "scale the family (JSR(cA) = |c| JSR(A))")
                vals.append(v)
            rows.append(vals)
        out.append(rows)
    return out


def _within_magnitude(v) -> bool:
    """``1e-50 <= |v| <= 1e50`` (:data:`MAX_MAGNITUDE_DIGITS`), decided exactly for a real sympy number.

    >>> import sympy as sp
    >>> _within_magnitude(sp.Integer(10) ** 50), _within_magnitude(sp.Integer(10) ** 50 + 1)
    (True, False)
    >>> _within_magnitude(sp.sqrt(2) / 10 ** 50), _within_magnitude(sp.Rational(1, 10 ** 51))
    (True, False)
    """
    import sympy as sp

    big = sp.Integer(10) ** MAX_MAGNITUDE_DIGITS
    return bool(1 / big <= abs(v) <= big)


def _decimal(q, up: bool, digits: int = 17) -> str:
    """The rational ``q`` as a decimal of ``digits`` significant digits, rounded outward
    (down for a lower end, up for an upper end), so that the printed interval still encloses;
    in exponent notation from ``10^digits`` up and below ``10^-6``.

    >>> _decimal(1, False), _decimal(__import__("fractions").Fraction(2, 3), True, 5)
    ('1.0000000000000000', '0.66667')
    >>> _decimal(10 ** 17 + 1, False), _decimal(10 ** 17 + 1, True)
    ('1.0000000000000000e+17', '1.0000000000000001e+17')
    >>> _decimal(__import__("fractions").Fraction(-1, 3 * 10 ** 7), False, 5)
    '-3.3334e-8'
    """
    import decimal
    from fractions import Fraction

    q = Fraction(int(q.p), int(q.q)) if hasattr(q, "p") else Fraction(q)
    ctx = decimal.Context(prec=digits, rounding=decimal.ROUND_CEILING if up else decimal.ROUND_FLOOR)
    d = ctx.divide(decimal.Decimal(q.numerator), decimal.Decimal(q.denominator))
    if not d:
        return "0"
    places = digits - 1 - d.adjusted()
    if 0 <= places and d.adjusted() >= -6:
        return f"{d:.{places}f}"
    return f"{d:.{digits - 1}e}"                  # d has ``digits`` significant digits: printed exactly


def _word(word) -> str:
    """The product ``A_{w_1} ... A_{w_L}`` with powers for runs: ``(0, 0, 0, 1) -> 'A0^3 A1'``."""
    out: list[str] = []
    for i in word:
        if out and out[-1][0] == i:
            out[-1][1] += 1
        else:
            out.append([i, 1])
    return " ".join(f"A{i}" + (f"^{c}" if c > 1 else "") for i, c in out)


def cmd_jsr(args) -> None:
    import sympy as sp

    from ..jsr import jsr_bounds
    from .common import _emit

    from ..algebra.reader import InputError, exact_number

    budget = work_arg(args.budget, "--budget")
    try:
        g = exact_number(str(args.gap), what="--gap")
    except InputError:
        raise AnalysisError(f"--gap must be a number such as 1e-6 or 1/1000, not {args.gap!r}") from None
    gap = float(g) if g.is_real else -1.0
    if not 0 < gap < 1:
        raise AnalysisError("--gap must be between 0 and 1 (a relative gap upper/lower - 1)")
    mats = read_family(args.file)
    from .. import progress

    with progress.on_terminal("jsr", enabled=not args.json):
        progress.stage("work units", budget)
        r = jsr_bounds(mats, budget=budget, rel_gap=gap, on_work=progress.step)
    w = r.witness
    word = tuple(w["product"])
    L = len(word)
    method = r.provenance["method"]
    exact_jsr = None
    root = w.get("rho_product_root_exact")
    if root is not None and r.status == "certified" and (
            method.startswith("spectral radius (single matrix)") or method.startswith("commuting")):
        exact_jsr = root                     # JSR = rho(A_i) exactly: proven, not bounded
    elif r.value is not None:
        exact_jsr = r.value                  # the certified bounds coincide
    if r.witness.get("closed") and w.get("polytope_vertices"):
        how = (f"invariant polytope with {w['polytope_vertices']} vertices, closed; certified norm "
               f"bound {float(w['certified_norm_bound']):.17g} at scale {float(w['scale_r']):.17g}")
    elif "product_tree" in w and method.startswith("product tree"):
        t = w["product_tree"]
        how = (f"product tree: {t['certified_products']} products certified in Arb "
               f"({t['nodes']} nodes, depth {t['depth']}); the invariant polytope "
               f"({w['polytope_vertices']} vertices) did not close: {w.get('stop_reason')}")
    elif "norm_length" in w:
        how = f"norms of all products of length {w['norm_length']}"
    else:
        how = method
    lines = [f"family: {len(mats)} matri{'x' if len(mats) == 1 else 'ces'} of size {len(mats[0])}x{len(mats[0])} "
             f"({r.provenance['input_kind']} entries)",
             f"JSR in [{_decimal(r.lower, False)}, {_decimal(r.upper, True)}]   {r.status}"
             + (f"   (relative gap {r.provenance['relative_gap']:.3g})"
                if r.provenance.get("relative_gap") is not None else "")]
    if exact_jsr is not None:
        lines.append(f"exact value: JSR = {sp.sstr(exact_jsr)}")
    rp = "rho(P)" if L == 1 else f"rho(P)^(1/{L})"
    lines.append(f"s.m.p. candidate: {_word(word)} (length {L}), {rp} >= "
                 f"{_decimal(r.lower, False)} (the lower bound)" if root is None else
                 f"s.m.p. candidate: {_word(word)} (length {L}), {rp} = {sp.sstr(root)}"
                 " (exact; the lower bound)")
    lines.append(f"witness: {how}")
    lines.append(f"method: {method}")
    lines.append(f"work: {r.provenance['work']} of {budget} units")
    if r.status != "certified":
        lines.append(f"note: not certified to --gap {args.gap}: the invariant polytope did not close "
                     f"({w.get('stop_reason', 'not attempted')}); a larger --budget tightens the "
                     "bounds and may close it")
    data = {"file": args.file, "matrices": len(mats), "dimension": len(mats[0]),
            "lower": r.lower, "upper": r.upper, "status": r.status,
            "exact_value": exact_jsr, "smp_candidate": list(word),
            "rho_product_root_exact": root, "witness": w, "provenance": r.provenance}
    _emit(args, data, "\n".join(lines))


def register(subparsers) -> None:
    """Add ``subdiv jsr`` to the sub-command parsers of :func:`analysis.cli.main.build_parser`."""
    s = subparsers.add_parser("jsr", help="certified joint spectral radius of matrices in a JSON file")
    s.add_argument("file", metavar="FILE", help="JSON list of square matrices (integers, decimals, "
                   '"p/q" strings), e.g. [[[1,1],[0,1]],[[1,0],[1,1]]]')
    s.add_argument("--budget", default="10000", metavar="UNITS",
                   help=f"work budget in work units (default 10000; {WORK_HELP})")
    s.add_argument("--gap", default="1e-6", metavar="G",
                   help="target relative gap upper/lower - 1 for 'certified' (default 1e-6)")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.set_defaults(func=cmd_jsr)
