"""The Python entry point for notebooks: :class:`Scheme`, one object per subdivision scheme.

A :class:`Scheme` is built from a mask, a symbol, the even/odd rules or a catalogue name, with an
arity (2 by default) and parameters; its methods call the engine (:func:`holder_exponent`,
:func:`smoothness`, :func:`sobolev_exponent`, the C^k sets and the maximiser of a family) and
return :class:`~analysis.result.Result` objects with a one-line ``repr`` and rich displays for
IPython/Jupyter (``_repr_html_``, ``_repr_latex_``, ``_repr_pretty_``).

Numbers
-------
Strings, integers, ``Fraction`` and sympy numbers are exact: ``"0.1"`` is ``1/10``. A Python float
(or a numpy float array) is a double, not a decimal: ``0.1`` is
``3602879701896397/36028797018963968``. What a double means is chosen by ``floats=``:

* ``"balls"`` (the default when the mask has a float): each double is a ball of a few units in its
  last place (:data:`analysis.algebra.approx.FLOAT64_ULPS`), the approximate reading of ``subdiv
  holder --approx``: results hold for **every** mask in the balls with the sum rules that the balls
  are proven to admit (:class:`analysis.algebra.approx.ApproximateMask`); ``radius=`` sets another
  radius. Filters that sum to ``sqrt(2)`` (PyWavelets' ``dec_lo``) are read as the mask times ``sqrt(2)``.
* ``"binary"``: the double's exact binary value (``0.1`` above); a table of doubles then usually
  misses a sum rule by an ulp and is certified *not* convergent.
* ``"decimal"``: the shortest decimal that prints the double (``repr``), read exactly, as the command
  line reads typed text: ``0.1`` becomes ``1/10``. You assert that the decimal is what you meant.

Examples
--------
>>> s = Scheme(["1/4", "3/4", "3/4", "1/4"], start=-2)            # Chaikin
>>> s.holder()
Result(2, certified)
>>> s.smoothness(1), s.smoothness(2)
(Result(True, certified), Result(False, certified))
>>> Scheme([0.25, 0.75, 0.75, 0.25], start=-2).reading
'balls: each double a ball of 4 units in its last place'

References
----------
The results contract and the statuses: ``DESIGN.md``; the approximate reading:
:mod:`analysis.algebra.approx`.
"""

from __future__ import annotations

from typing import Any, Mapping, Sequence

from .result import AnalysisError, Result

__all__ = ["Scheme"]

FLOAT_READINGS = ("balls", "binary", "decimal")


def _is_float(x) -> bool:
    return isinstance(x, float) or (type(x).__module__ == "numpy" and hasattr(x, "dtype")
                                    and getattr(x.dtype, "kind", "") == "f")


def _as_list(mask) -> list:
    if hasattr(mask, "tolist") and hasattr(mask, "dtype"):          # numpy array: flat list
        import numpy as np

        arr = np.asarray(mask)
        return [float(x) if arr.dtype.kind == "f" else int(x) if arr.dtype.kind in "iu" else x for x in arr.ravel()]
    if isinstance(mask, (str, bytes)) or not hasattr(mask, "__len__"):
        raise AnalysisError("a mask is a list of coefficients, e.g. Scheme(['1/4', '3/4', '3/4', '1/4'], start=-2)")
    return [float(x) if _is_float(x) else x for x in mask]


def _engine(concept: str, arity: int):
    """The engine function of ``concept``; each returned function takes ``(a, *args, **kw)`` with
    ``a`` the mask and passes the arity on (one engine serves every arity)."""
    if concept in ("holder", "smoothness"):
        from .regularity import holder

        f = holder.holder_exponent if concept == "holder" else holder.smoothness
    elif concept == "sobolev":
        from .regularity.sobolev import sobolev_exponent as f
    else:
        from .algebra import factorization

        f = {"sum_rules": factorization.sum_rules, "smoothing_factor": factorization.smoothing_factor}[concept]
    return lambda a, *args, **kw: f(a, *args, arity=arity, **kw)


class Scheme:
    """A subdivision scheme: give exactly one of ``mask`` (with ``start``, the index of its first
    coefficient), ``symbol`` (text in ``z`` or a sympy expression), ``rules`` (``(even, odd, first)``
    for binary schemes), or use :meth:`from_catalogue`.

    ``arity`` is ``m`` in ``(S_a f)_i = sum_j a_{i-mj} f_j``. ``params`` substitutes values for named
    parameters (``{"w": "1/16"}``); names left free make a family (:attr:`params`, :meth:`at`,
    :meth:`ck_set`, :meth:`max_holder`). ``floats`` says what a Python float means (module docstring);
    ``radius`` is the ball radius of every float under ``floats="balls"``.

    >>> Scheme(symbol="(1+z)**4/(8*z**2)").holder()                  # cubic B-spline
    Result(3, certified)
    >>> four = Scheme.from_catalogue("four-point")
    >>> four.params
    ('w',)
    >>> four.at(w="1/16").holder()
    Result(2, certified)
    """

    def __init__(self, mask: Sequence | None = None, start: int = 0, *, symbol: Any = None,
                 rules: Sequence | None = None, arity: int = 2, params: Mapping[str, Any] | None = None,
                 floats: str | None = None, radius: Any = None, name: str | None = None):
        from .algebra.factorization import check_arity
        from .algebra.symbol import LaurentSymbol

        given = [x for x, v in (("mask", mask), ("symbol", symbol), ("rules", rules)) if v is not None]
        if len(given) != 1:
            raise AnalysisError("give exactly one of a mask (Scheme([...], start=N)), symbol='...' or "
                                "rules=(even, odd, first)")
        self.arity = check_arity(arity)
        self.name = name or given[0]
        self._balls = None                 # the approximate reading of a float mask
        self.reading = "exact"
        if floats is not None and floats not in FLOAT_READINGS:
            raise AnalysisError(f"floats must be one of {', '.join(FLOAT_READINGS)}, not {floats!r}")
        if mask is not None:
            coeffs = _as_list(mask)
            has_float = any(isinstance(c, float) for c in coeffs)
            if has_float and (floats or "balls") == "balls":
                self._balls = self._read_balls(coeffs, start, radius)
                self._symbol = None
                return
            if has_float and floats == "decimal":
                coeffs = [repr(c) if isinstance(c, float) else c for c in coeffs]
                self.reading = "decimal: each double read as the shortest decimal that prints it"
            elif has_float:
                self.reading = "binary: each double read as its exact binary value"
            sym = LaurentSymbol.from_mask(coeffs, start=start)
        elif symbol is not None:
            sym = LaurentSymbol.from_expr(symbol)
        else:
            if self.arity != 2:
                raise AnalysisError("rules=(even, odd, first) are binary; for arity m give the mask or the symbol")
            even, odd, *first = rules
            sym = LaurentSymbol.from_rules(even, odd, first=first[0] if first else 0)
        self._symbol = sym.subs(dict(params)) if params else sym

    def _read_balls(self, coeffs, start, radius):
        from .algebra.approx import FLOAT64_ULPS, ApproximateMask

        if self.arity != 2:
            raise AnalysisError("floats are read as balls for binary masks only; give exact numbers "
                                "(strings such as '0.1', fractions) or floats='decimal' / floats='binary'")
        m = ApproximateMask(coeffs, start=start, radius=radius)
        self.reading = ("balls: each double a ball of %d units in its last place" % FLOAT64_ULPS if radius is None
                        else f"balls: each float a ball of radius {radius}")
        return m

    @classmethod
    def from_catalogue(cls, name: str, **params) -> "Scheme":
        """A named scheme of the catalogue (``subdiv list``; ``daubechies-8`` and the other wavelet
        masks are known by certified Arb balls), with parameter values ``params``."""
        import schemes

        entry = schemes.get(name)
        self = cls.__new__(cls)
        self.arity, self.name, self._balls, self.reading = getattr(entry, "arity", 2), entry.slug, None, "exact"
        if getattr(entry, "has_exact_symbol", True):
            self._symbol = entry.symbol_at(**params) if params else entry.symbol
        else:
            if params:
                entry.symbol_at(**params)                   # the one-line error: no parameters
            self._symbol, self._balls, self.reading = None, entry, "balls: certified Arb enclosures of the catalogue"
        return self

    # ---------------------------------------------------------------- data
    @property
    def symbol(self):
        """The exact :class:`~analysis.algebra.symbol.LaurentSymbol` ``a(z)``."""
        if self._symbol is None:
            raise AnalysisError(f"{self.name} is known by balls ({self.reading}), not exactly: "
                                "it has no exact symbol; see .mask for the centres")
        return self._symbol

    @property
    def mask(self) -> tuple:
        """The coefficients (exact; for a ball mask the exact rational centres)."""
        if self._symbol is not None:
            return self._symbol.mask
        import sympy as sp

        if hasattr(self._balls, "centre"):
            return tuple(sp.Rational(c.numerator, c.denominator) for c in self._balls.centre)
        return tuple(b.mid() for b in self._balls.enclosure(128))

    @property
    def params(self) -> tuple[str, ...]:
        """The names of the free parameters (empty for one scheme, one name for a family)."""
        return () if self._symbol is None else tuple(p.name for p in self._symbol.params)

    def at(self, **values) -> "Scheme":
        """The scheme with parameter values substituted (exact: strings, fractions, sympy)."""
        out = Scheme.__new__(Scheme)
        out.__dict__.update(self.__dict__)
        out._symbol = self.symbol.subs({k: v for k, v in values.items()})
        return out

    def _analysed(self):
        if self._balls is not None:
            return self._balls
        if self._symbol.params:
            raise AnalysisError(f"{self.name} has free parameters {', '.join(self.params)}: give values with "
                                ".at(name=value), or use .ck_set(k) / .max_holder() for the family")
        return self._symbol

    # ---------------------------------------------------------------- analyses
    def sum_rules(self) -> Result:
        """The number of sum rules (factors ``(1+z+...+z^(m-1))/m`` of the symbol), exact."""
        return _engine("sum_rules", self.arity)(self.symbol)

    def smoothing_factor(self) -> Result:
        """``a = ((1+...+z^(m-1))/m)^k b`` with k maximal (and the exceptional parameter values)."""
        return _engine("smoothing_factor", self.arity)(self.symbol)

    def holder(self, **kw) -> Result:
        """The Hölder exponent alpha: exact value or certified enclosure ``[lower, upper]``
        (keywords such as ``budget=`` go to the engine)."""
        return _engine("holder", self.arity)(self._analysed(), **kw)

    def smoothness(self, k: int, **kw) -> Result:
        """Is the scheme C^k?  ``value`` True/False with its status."""
        a = self._analysed()
        if a is self._balls:
            from .regularity.holder import verdict_from_enclosure

            return verdict_from_enclosure(self.holder(**kw), k)
        return _engine("smoothness", self.arity)(a, k, **kw)

    def sobolev(self, **kw) -> Result:
        """The L2-Sobolev exponent (exact value or certified enclosure)."""
        return _engine("sobolev", self.arity)(self._analysed(), **kw)

    def ck_set(self, k: int, within=(-1, 1), **kw) -> Result:
        """Where the one-parameter family is C^k within ``within``: the runs with certified ends
        (:func:`analysis.regularity.ranges.ck_parameter_set`; binary families)."""
        from .regularity.ranges import ck_parameter_set

        self._binary_family("ck_set")
        return ck_parameter_set(self.symbol, k, within=within, **kw)

    def max_holder(self, within=(-1, 1), **kw) -> Result:
        """The parameter value of largest alpha in ``within``, with a certified gap
        (:func:`analysis.regularity.maximize.maximize_holder`; binary families)."""
        from .regularity.maximize import maximize_holder

        self._binary_family("max_holder")
        return maximize_holder(self.symbol, within=within, **kw)

    def _binary_family(self, what: str) -> None:
        if self.arity != 2 or len(self.params) != 1:
            raise AnalysisError(f".{what}() takes a binary family with one free parameter "
                                f"({self.name}: arity {self.arity}, parameters {list(self.params) or 'none'})")

    # ---------------------------------------------------------------- display
    def __repr__(self) -> str:
        if self._symbol is None:
            return f"Scheme({self.name!r}, {self.reading})"
        arity = "" if self.arity == 2 else f", arity={self.arity}"
        return f"Scheme({self._symbol.pretty()}{arity})"

    def _repr_latex_(self) -> str:
        if self._symbol is None:
            return None
        return f"$a(z) = {self._symbol.latex()}$"
