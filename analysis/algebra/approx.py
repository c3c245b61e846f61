"""The approximate reading of a mask copied from a table (``subdiv holder --approx``).

Decimals are exact by default (``0.25`` is ``1/4``): a 42-digit D8 table then misses the sum
rules by about ``1e-43`` and the typed mask itself does not converge (certified). Under the
*approximate reading* every decimal coefficient is a ball of half a unit in its last typed digit
(integers, fractions and formulas stay exact), and the question becomes: what is alpha for the
masks in those balls that satisfy the sum rules?

:class:`ApproximateMask` answers it honestly:

1. for ``N = 1, 2, ...`` it constructs an **exact rational** mask with ``a(1) = 2`` and
   ``(1+z)^N | a`` -- the least-norm correction of the typed mask (weighted by the radii) onto
   that affine space -- and checks **exactly** that it lies in the balls; ``N`` is the largest
   order for which this witness exists (so the balls are proven to contain such a mask);
2. :func:`analysis.regularity.holder_exponent` on an :class:`ApproximateMask` (the ball route,
   ``sum_rules=N``) certifies alpha for **every** mask in the balls with ``a(1) = 2`` and
   ``(1+z)^N | a``; so do the stability and Sobolev routines for their results.

>>> m = ApproximateMask(["0.25", "0.75", "0.75", "0.25"], start=-2)   # Chaikin to 2 decimals
>>> m.sum_rules, m.radius[0]                     # (1+z)^3 | a for a mask in the balls of +-0.005
(3, Fraction(1, 200))

``analysis.regularity.holder_exponent(m)`` then certifies alpha for every such mask.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Sequence

import sympy as sp

from ..result import AnalysisError

_DECIMAL = re.compile(r"^\s*[+-]?(\d*)\.(\d+)(?:[eE]([+-]?\d+))?\s*$|^\s*[+-]?(\d+)\.?()[eE]([+-]?\d+)\s*$")


#: Radius of a coefficient that is a double (a Python/numpy float, or its shortest text such as
#: ``0.7148465705529157``): this many units in its last place. Tables computed in double precision
#: are correctly rounded at best (PyWavelets' ``db4`` is within half an ulp); a few ulps leave room
#: for the rounding of the algorithm that produced them.
FLOAT64_ULPS = 4


def is_float64_text(text) -> bool:
    """Is ``text`` the shortest decimal of a double with 15 or more significant digits (what Python,
    numpy and most tools print for a float64), rather than a value typed to its digits?

    >>> is_float64_text("0.7148465705529157"), is_float64_text("0.25"), is_float64_text("0.3258034280512983482745")
    (True, False, False)
    """
    import math

    if not isinstance(text, str) or not _DECIMAL.match(text):
        return False
    t = text.strip()
    try:
        x = float(t)
    except ValueError:
        return False
    if not math.isfinite(x) or repr(x) != t.lstrip("+"):
        return False
    digits = len(t.lower().split("e")[0].replace("-", "").replace("+", "").replace(".", "").lstrip("0"))
    return digits >= 15


def float64_radius(x: float) -> Fraction:
    """:data:`FLOAT64_ULPS` units in the last place of the double ``x``.

    >>> float64_radius(0.5) == 4 * Fraction(2) ** -53
    True
    """
    import math

    return FLOAT64_ULPS * Fraction(math.ulp(float(x)))


def typed_radius(text) -> Fraction:
    """Half a unit in the last typed digit of a decimal literal (a double's shortest text: a few
    ulps, :func:`float64_radius`); 0 for anything else (exact).

    >>> typed_radius("0.125"), typed_radius("1.5e-3"), typed_radius("1/3"), typed_radius("2")
    (Fraction(1, 2000), Fraction(1, 20000), Fraction(0, 1), Fraction(0, 1))
    >>> typed_radius("0.7148465705529157") == float64_radius(0.7148465705529157)
    True
    """
    if isinstance(text, float):
        return float64_radius(text)
    if not isinstance(text, str):
        return Fraction(0)
    if is_float64_text(text):
        return float64_radius(float(text))
    m = _DECIMAL.match(text)
    if not m:
        return Fraction(0)
    if m.group(2) is not None:
        digits, exp = len(m.group(2)), int(m.group(3) or 0)
    else:
        digits, exp = 0, int(m.group(6))
    return Fraction(1, 2) * Fraction(10) ** (exp - digits)


def _centres(mask: Sequence) -> list[Fraction]:
    from .symbol import parse_coefficient

    out = []
    for c in mask:
        if isinstance(c, float):
            out.append(Fraction(c))                # the double's exact binary value
            continue
        e = parse_coefficient(c)
        if not e.is_Rational:
            raise AnalysisError(f"--approx reads decimal tables: coefficient {sp.sstr(e)} is not a rational number")
        out.append(Fraction(int(e.p), int(e.q)))
    return out


def _constraints(m: int, N: int):
    """Rows of ``A a = b``: a(1) = 2 and the moments sum (-1)^k k^j a_k = 0, j < N."""
    A = [[Fraction(1)] * m]
    b = [Fraction(2)]
    for j in range(N):
        A.append([Fraction((-1) ** k * k ** j) for k in range(m)])
        b.append(Fraction(0))
    return A, b


def _solve(M, v):
    """Exact solution of the square system ``M x = v`` (FLINT ``fmpq_mat``, rationals), or None if singular."""
    from flint import fmpq, fmpq_mat

    S = fmpq_mat([[fmpq(x.numerator, x.denominator) for x in row] for row in M])
    if S.det() == 0:
        return None
    x = S.solve(fmpq_mat([[fmpq(t.numerator, t.denominator)] for t in v]))
    return [Fraction(int(x[i, 0].p), int(x[i, 0].q)) for i in range(x.nrows())]


def least_norm_correction(centre: Sequence[Fraction], radius: Sequence[Fraction], N: int):
    """The exact rational mask ``a`` with ``a(1) = 2``, ``(1+z)^N | a`` nearest to ``centre`` in
    the norm ``sum (delta_k / r_k)^2`` (exact coefficients, ``r_k = 0``, do not move); None when
    the constraints cannot be met by moving the inexact coefficients."""
    m = len(centre)
    A, b = _constraints(m, N)
    W = [r * r for r in radius]
    res = [bi - sum(a * c for a, c in zip(row, centre)) for row, bi in zip(A, b)]
    G = [[sum(A[i][k] * W[k] * A[j][k] for k in range(m)) for j in range(len(A))] for i in range(len(A))]
    y = _solve(G, res)
    if y is None:
        return None
    delta = [W[k] * sum(A[i][k] * y[i] for i in range(len(A))) for k in range(m)]
    return [c + d for c, d in zip(centre, delta)]


def chebyshev_correction(centre: Sequence[Fraction], radius: Sequence[Fraction], N: int):
    """An exact rational mask ``a`` with ``a(1) = 2``, ``(1+z)^N | a`` and the smallest largest
    deviation in radii ``max_k |a_k - c_k| / r_k`` we can find, with that deviation (exact); None
    when no such mask exists with the exact coefficients fixed.

    The least-norm correction (:func:`least_norm_correction`) minimises a sum of squares, so it can
    leave a ball although a mask of the same order lies inside all of them (a table's true mask sits
    at 0.99 radii): the largest deviation is what decides membership. Algorithm: the linear program
    ``min t, M u = d, |u_k| <= t`` in the scaled unknowns ``u = (a - c)/r`` (rows scaled to unit
    size, so double precision resolves deviations of 1e-40) is solved in floating point by HiGHS;
    its solution is then projected **exactly** (rational least-norm step) onto ``M u = d``, and the
    deviation is computed exactly: the float solve only proposes, the rationals decide.

    >>> a, t = chebyshev_correction([Fraction(1, 4), Fraction(3, 4), Fraction(3, 4), Fraction(1, 4)],
    ...                             [Fraction(1, 200)] * 4, 3)
    >>> a, t
    ([Fraction(1, 4), Fraction(3, 4), Fraction(3, 4), Fraction(1, 4)], Fraction(0, 1))
    """
    import numpy as np
    from scipy.optimize import linprog

    m = len(centre)
    A, b = _constraints(m, N)
    free = [k for k in range(m) if radius[k]]
    if not free:
        return None
    M = [[row[k] * radius[k] for k in free] for row in A]
    d = [bi - sum(x * c for x, c in zip(row, centre)) for row, bi in zip(A, b)]
    scale = [max((abs(x) for x in row), default=Fraction(1)) or Fraction(1) for row in M]
    Mf = np.array([[float(x / s) for x in row] for row, s in zip(M, scale)])
    df = np.array([float(x / s) for x, s in zip(d, scale)])
    n = len(free)
    # variables (u_1..u_n, t): minimise t, M u = d, u - t <= 0, -u - t <= 0
    cost = np.zeros(n + 1)
    cost[-1] = 1.0
    A_ub = np.vstack([np.hstack([np.eye(n), -np.ones((n, 1))]), np.hstack([-np.eye(n), -np.ones((n, 1))])])
    res = linprog(cost, A_ub=A_ub, b_ub=np.zeros(2 * n), A_eq=np.hstack([Mf, np.zeros((len(M), 1))]), b_eq=df,
                  bounds=[(None, None)] * n + [(0, None)], method="highs")
    if res.status != 0:
        return None
    u = [Fraction(float(x)) for x in res.x[:n]]
    # exact projection onto M u = d: u += M^T (M M^T)^-1 (d - M u)
    resid = [di - sum(x * y for x, y in zip(row, u)) for row, di in zip(M, d)]
    G = [[sum(x * y for x, y in zip(ri, rj)) for rj in M] for ri in M]
    y = _solve(G, resid)
    if y is None:
        return None
    u = [uk + sum(M[i][k] * y[i] for i in range(len(M))) for k, uk in enumerate(u)]
    a = list(centre)
    for k, uk in zip(free, u):
        a[k] = centre[k] + radius[k] * uk
    if sum(a) != 2 or any(sum((-1) ** k * k ** j * x for k, x in enumerate(a)) != 0 for j in range(N)):
        return None                                                      # pragma: no cover
    return a, max(abs(uk) for uk in u)


class ApproximateMask:
    """A typed decimal mask under the approximate reading (module docstring): each decimal a
    ball of half a unit in its last digit, ``sum_rules`` (N) the largest order for which an exact
    rational mask with ``a(1) = 2`` and ``(1+z)^N | a`` is proven to lie in the balls.

    Like :class:`analysis.algebra.closed_form.ClosedFormMask` and the catalogue's ball entries it has
    ``enclosure(prec)`` and ``sum_rules``, so the ball routes (Hölder exponent, stability of the
    shifts, Sobolev exponent) apply to it; each of them then holds for **every** mask in the balls
    with ``a(1) = 2`` and ``(1+z)^N | a``.

    >>> m = ApproximateMask(["0.25", "0.75", "0.75", "0.25"], start=-2)
    >>> m.sum_rules, m.witness_mask
    (3, [Fraction(1, 4), Fraction(3, 4), Fraction(3, 4), Fraction(1, 4)])
    """

    slug = "mask (approximate reading)"

    def __init__(self, mask: Sequence, start: int = 0, *, radius=None):
        try:
            import numpy as np

            if isinstance(mask, np.ndarray):
                mask = [float(x) if np.issubdtype(mask.dtype, np.floating) else int(x) for x in mask.ravel()]
        except ImportError:  # pragma: no cover
            pass
        if isinstance(mask, (str, bytes)) or len(mask) == 0:
            raise AnalysisError("a mask is a non-empty list of coefficients")
        self.typed = [float(x) if type(x).__module__ == "numpy" and isinstance(x, float) else x for x in mask]
        self.start = int(start)
        self.centre = _centres(self.typed)
        if radius is None:
            self.radius = [typed_radius(c) for c in self.typed]
            self.radius_rule = "typed"
        else:
            r = _centres([radius])[0] if not isinstance(radius, Fraction) else radius
            if not r > 0:
                raise AnalysisError(f"the radius must be a positive number, not {radius!r}")
            self.radius = [r if typed_radius(c) or isinstance(c, float) else Fraction(0) for c in self.typed]
            self.radius_rule = f"given: {r}"
        if not any(self.radius):
            raise AnalysisError("--approx: no coefficient is a decimal with a last digit to be read "
                                "approximately (integers, fractions and formulas are exact)")
        self.normalisation = _sqrt2_normalised(self.centre, self.radius)
        if self.normalisation is not None:                 # a table with sum sqrt(2): times sqrt(2)
            self.centre, self.radius = self.normalisation
            self.normalisation = "sqrt(2)"
        best, why_not = None, None
        for N in range(1, len(self.centre)):
            a = least_norm_correction(self.centre, self.radius, N)
            dev = None if a is None else [abs(x - c) for x, c in zip(a, self.centre)]
            if dev is None or any(d > r for d, r in zip(dev, self.radius)):
                cheb = chebyshev_correction(self.centre, self.radius, N)
                if cheb is not None and cheb[1] <= 1:
                    a = cheb[0]
                    dev = [abs(x - c) for x, c in zip(a, self.centre)]
                else:
                    why_not = (f"order {N}: the exact coefficients cannot satisfy it" if a is None and cheb is None
                               else f"order {N}: no exact mask of that order found in the balls"
                                    + (f" (the nearest found deviates {float(cheb[1]):.3g} radii)" if cheb else "")
                                    + "; one is not excluded")
                    break
            best = (N, a, dev)
        if best is None:
            raise AnalysisError("--approx: the balls of the typed digits contain no mask with a(1) = 2 and "
                                "a(-1) = 0 that we could construct (" + (why_not or "") + ")")
        N, a, dev = best
        # exact re-check of the witness: sum rules, and inside the balls
        if not (sum(a) == 2 and all(sum((-1) ** k * k ** j * x for k, x in enumerate(a)) == 0 for j in range(N))
                and all(d <= r for d, r in zip(dev, self.radius))):  # pragma: no cover - by construction
            raise ArithmeticError("the least-norm correction is not a witness")
        self.sum_rules, self.witness_mask, self.deviation, self.next_order = N, a, dev, why_not

    def enclosure(self, prec: int) -> list:
        """The balls ``centre +- radius`` (exact coefficients: radius 0) as ``flint.arb``."""
        import flint

        with flint.ctx.workprec(prec + 64):
            balls = []
            for c, r in zip(self.centre, self.radius):
                ball = flint.arb(flint.fmpq(c.numerator, c.denominator))
                if r:
                    ball += flint.arb(0, 1) * flint.arb(flint.fmpq(r.numerator, r.denominator))
                balls.append(ball)
        return balls

    def description(self) -> str:
        """One sentence: what the balls are and the witness that they contain a convergent mask."""
        maxdev = max(self.deviation)
        in_radii = max((d / r for d, r in zip(self.deviation, self.radius) if r), default=Fraction(0))
        if self.radius_rule != "typed":
            how = f"each decimal a ball of radius {self.radius_rule.removeprefix('given: ')} (--approx-radius)"
        elif any(isinstance(x, float) or is_float64_text(x) for x in self.typed):
            how = f"each double a ball of {FLOAT64_ULPS} units in its last place"
        else:
            digits = sorted({_digits(x) for x in self.typed if typed_radius(x)})
            how = f"each decimal a ball of half a unit in its last digit ({'/'.join(map(str, digits))} digits)"
        if self.normalisation:
            how += "; the coefficients sum to sqrt(2) (a wavelet filter): read as the mask times sqrt(2)"
        return (f"approximate reading: {how}; the result holds for every mask in the balls with "
                f"a(1) = 2 and (1+z)^{self.sum_rules} | a; the balls contain one (an exact rational mask, "
                f"max deviation {float(maxdev):.3g} = {float(in_radii):.3g} radii); "
                + (self.next_order or f"N = {self.sum_rules} is the largest order"))

    def witness(self) -> dict:
        """What a result on :meth:`enclosure` adds to its witness: N, the exact witness mask in
        the balls, its deviation (absolute and in radii), the radii, why N + 1 was not taken."""
        maxdev = max(self.deviation)
        in_radii = max((d / r for d, r in zip(self.deviation, self.radius) if r), default=Fraction(0))
        return {"reading": "approximate", "sum_rules": self.sum_rules, "normalisation": self.normalisation,
                "witness_mask": [sp.Rational(x.numerator, x.denominator) for x in self.witness_mask],
                "max_deviation": sp.Rational(maxdev.numerator, maxdev.denominator),
                "max_deviation_in_radii": sp.Rational(in_radii.numerator, in_radii.denominator),
                "radii": [sp.Rational(r.numerator, r.denominator) for r in self.radius],
                "next_order": self.next_order}


def _sqrt2_normalised(centre: list[Fraction], radius: list[Fraction]):
    """``(centre, radius)`` of the mask times sqrt(2) when the typed coefficients sum to sqrt(2)
    within their radii (wavelet tables, PyWavelets' ``dec_lo``: filters normalised to sum
    sqrt(2)), else None. The product is enclosed rigorously: ``q`` a rational within ``eps`` of
    sqrt(2), centre ``q c``, radius ``q r + (|c| + r) eps``."""
    import math

    total, slack = sum(centre), sum(radius)
    s2 = Fraction(math.sqrt(2))
    if abs(total - 2) <= slack or abs(total - s2) > slack + Fraction(1, 10 ** 15):
        return None
    num, ok = sp.integer_nthroot(2 * 10 ** 120, 2)
    q, eps = Fraction(int(num), 10 ** 60), Fraction(1, 10 ** 59)          # |sqrt(2) - q| < eps
    return [q * c for c in centre], [q * r + (abs(c) + r) * eps for c, r in zip(centre, radius)]


def _digits(text: str) -> int:
    m = _DECIMAL.match(text)
    return len(m.group(2)) if m and m.group(2) is not None else 0


def sum_rule_hint(mask: Sequence) -> str | None:
    """A hint when a typed decimal mask misses a sum rule by less than its digits resolve, or
    sums to sqrt(2) or 1 (other normalisations of the same table)."""
    try:
        centre = _centres(mask)
    except AnalysisError:
        return None
    radius = [typed_radius(c) for c in mask]
    if not any(radius):
        return None
    res = sum(radius)
    s1 = sum(centre)
    sm1 = sum((-1) ** k * c for k, c in enumerate(centre))
    digits = max(_digits(x) for x in mask if typed_radius(x))
    if abs(s1 - 2) <= res and abs(sm1) <= res:
        return (f"the miss is below the resolution of its {digits} digits (each coefficient +- half a "
                "unit in its last digit): try --approx")
    import math

    for name, target, fix in (("sqrt(2)", math.sqrt(2), "multiply every coefficient by sqrt(2)"),
                              ("1", 1.0, "multiply every coefficient by 2")):
        if abs(float(s1) - target) <= float(res) + 1e-15 and abs(sm1) <= res * 2:
            return (f"the coefficients sum to {float(s1):.6g} ~ {name}, not 2 (our masks have a(1) = 2): "
                    f"{fix}" + (", or use --approx, which reads a filter with sum sqrt(2) as the mask times sqrt(2)"
                                if name == "sqrt(2)" else ""))
    return None
