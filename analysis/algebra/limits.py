"""The sizes one text may ask for, the error of a bad text, and the arity check: no sympy here,
so that a command that reads no formula (a catalogue entry known by balls) does not import it.

:mod:`analysis.algebra.reader` and :mod:`analysis.algebra.factorization` re-export these names.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..result import AnalysisError


class InputError(AnalysisError):
    """A text that is not a formula of the input grammar, or that exceeds a limit.

    ``kind`` says which (``"syntax"``, ``"name"``, ``"limit"``, ``"value"``) and goes into the
    ``--json`` error document."""

    def __init__(self, message: str, kind: str = "syntax"):
        super().__init__(message)
        self.kind = kind


@dataclass(frozen=True)
class Limits:
    """The sizes one text may ask for. Each is checked before the work it bounds is done."""

    #: characters of one formula
    text: int = 100_000
    #: nesting depth of the formula (parentheses and function calls; ``a+b+c`` counts once)
    depth: int = 100
    #: digits of one number as typed
    digits: int = 2_000
    #: |k| of a numeric power ``x**k`` (and of the decimal exponent in ``1e-5``)
    exponent: int = 10_000
    #: bits of any exact rational built while reading (about 4 000 decimal digits: every number
    #: read can still be printed, Python's str(int) stops at 4 300 digits)
    bits: int = 13_000
    #: polynomial degree of the formula in its names (``(1+z)**40`` has degree 40)
    degree: int = 2_000
    #: degree of the polynomial of ``CRootOf(POLY, k)`` (isolating roots of degree 40 takes seconds)
    crootof: int = 24
    #: calls of ``diff`` in one formula (each nested derivative multiplies the size of the result)
    diffs: int = 6
    #: characters of a name
    name: int = 64
    #: coefficients of a mask, entries of a stencil, values of a list typed in one option
    coefficients: int = 1_000
    #: the arity m of an m-ary scheme (transition operators have m matrices of size ~ support/(m-1))
    arity: int = 32


#: The limits of :func:`read_expression`; docs/input.md lists them.
LIMITS = Limits()


def check_arity(m) -> int:
    """``m`` as an int ``>= 2``, else a one-line :class:`AnalysisError`.

    >>> check_arity(3)
    3
    >>> check_arity(1)
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: the arity must be an integer >= 2, not 1
    """
    if isinstance(m, bool) or not isinstance(m, int):
        try:
            if isinstance(m, str) and m.strip().lstrip("+").isdigit():
                m = int(m)
            else:
                raise ValueError
        except ValueError:
            raise AnalysisError(f"the arity must be an integer >= 2, not {m!r}") from None
    if m < 2:
        raise AnalysisError(f"the arity must be an integer >= 2, not {m!r}")
    if m > LIMITS.arity:
        raise InputError(f"the arity {m} exceeds the limit {LIMITS.arity} (limit 'arity')", "limit")
    return m


def arity_key(m: int) -> dict:
    """``{"arity": m}`` for ``m > 2`` and ``{}`` for ``m = 2``: the provenance entry of a result (binary
    results carry no arity key, so their JSON and reports read as they always have)."""
    return {} if m == 2 else {"arity": m}
