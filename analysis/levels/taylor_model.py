"""Rigorous Taylor models, in ``h = 2^-n``, of the coefficient differences ``g_k = a^n_k - a_k`` of a
level-dependent mask over a parameter box: the Taylor coefficients (exact, from
:meth:`analysis.levels.level_dependent.LevelDependentScheme.taylor`) as Arb balls, and a Cauchy remainder from
a bound of ``|g_k|`` on a complex disk ``|h| <= rho`` on which every coefficient is analytic.

Algorithm
---------
The disk bound covers the disk by a grid of complex balls (squares outside the disk skipped) and evaluates
the entire form of ``g_k`` on each; a non-finite value rejects the radius, and the next, smaller one of
``rhos`` is tried. With ``M >= max |g|`` on the disk, Cauchy's estimate gives
``|g(h) - sum_{j<J} g_j h^j| <= M (h/rho)^J / (1 - h/rho)`` for ``0 <= h < rho``.

Examples
--------
>>> import flint
>>> from analysis.levels.level_dependent import LevelDependentScheme
>>> s = LevelDependentScheme.from_mask(["1/4 + 2**(-n)", "3/4", "3/4", "1/4 - 2**(-n)"])
>>> s.mask
(h + 1/4, 3/4, 3/4, 1/4 - h)
>>> m = taylor_models(s)[0]               # g_0 = h exactly: the model encloses h = 1/8
>>> m.J, m.enclose(flint.arb(1) / 8).contains(flint.arb(1) / 8)
(3, True)

References
----------
R. E. Moore, R. B. Kearfott, M. J. Cloud, *Introduction to Interval Analysis*, SIAM (2009), ch. 9
(Taylor models).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import flint
import sympy as sp

from ..result import AnalysisError
from .balls import _ball, _to_ball, arb_abs, workprec
from .level_dependent import H, LevelDependentScheme, _env_key, _env_values, entire_form

__all__ = ["TaylorModel", "taylor_models"]



@dataclass(frozen=True)
class TaylorModel:
    """``g(h) in sum_{j<J} coeffs[j] h^j +- M (h/rho)^J / (1 - h/rho)`` for ``0 <= h < rho``.

    ``coeffs`` are arb balls (valid over the whole parameter box); ``M`` bounds ``|g|`` on the
    closed disk ``|h| <= rho`` (upper bound, an arb), so also ``|coeffs[j]| <= M rho^-j``.
    """

    coeffs: tuple
    M: Any
    rho: Any
    J: int

    def remainder(self, h):
        """Upper bound of the remainder at ``h`` (an arb; ``h < rho``)."""
        t = h / self.rho
        return self.M * t ** self.J / (1 - t)

    def enclose(self, h):
        """An arb ball containing ``g(h)``."""
        v = flint.arb(0)
        for j, c in enumerate(self.coeffs):
            v = v + c * h ** j
        r = self.remainder(h)
        return v + flint.arb(0, 1) * r

    def abs_upper_over(self, q: int, h_max):
        """``A`` with ``|g(h)| <= A h^q`` for ``0 < h <= h_max`` (needs ``coeffs[j] = 0``, j < q)."""
        A = flint.arb(0)
        for j in range(q, len(self.coeffs)):
            A = A + arb_abs(self.coeffs[j]) * h_max ** (j - q)
        t = h_max / self.rho
        A = A + self.M * self.rho ** (-q) * t ** (self.J - q) / (1 - t)
        return A


def _disk_max(expr: sp.Expr, envc: dict, rho, grid: int):
    """Upper bound of ``|expr|`` on the closed disk ``|h| <= rho`` (None if not finite)."""
    best = flint.arb(0)
    step = 2 * rho / grid
    half = step / 2
    for i in range(grid):
        for j in range(grid):
            re = -rho + half + i * step
            im = -rho + half + j * step
            # skip squares entirely outside the disk (their nearest point is farther than rho)
            dx = max(abs(float(re.mid())) - float(half.mid()), 0.0)
            dy = max(abs(float(im.mid())) - float(half.mid()), 0.0)
            if dx * dx + dy * dy > float(rho.mid()) ** 2 * (1 + 1e-9):
                continue
            hb = flint.acb(flint.arb(re.mid(), half.mid() * 1.0001), flint.arb(im.mid(), half.mid() * 1.0001))
            env = dict(envc)
            env["h"] = hb
            v = _ball(expr, env, True)
            if not v.is_finite():
                return None
            best = best.max(flint.arb(abs(v).upper()))
    return best


def _hashable(x) -> bool:
    try:
        hash(x)
    except TypeError:
        return False
    return True


@lru_cache(maxsize=1024)
def _taylor_models(env: tuple, mask: tuple, limits: tuple, rows: tuple, J: int, rhos: tuple, grid: int,
                   prec: int) -> tuple | None:
    """The models of :func:`taylor_models` (``None``: no radius works); a pure function of its arguments, remembered
    (the weighted series and the support test of one scheme on one box ask for the same models)."""
    with workprec(prec):
        envr = {k: _to_ball(v, False) for k, v in env}
        envc = {k: flint.acb(v) for k, v in envr.items()}
        for rho_s in rhos:
            rho = flint.arb(int(sp.Rational(rho_s).p)) / int(sp.Rational(rho_s).q)
            models = []
            ok = True
            for c, c0, row in zip(mask, limits, rows):
                if H not in c.free_symbols:
                    models.append(TaylorModel(tuple(flint.arb(0) for _ in range(J)), flint.arb(0), rho, J))
                    continue
                g = entire_form(c - c0)
                M = _disk_max(g, envc, rho, grid)
                if M is None:
                    ok = False
                    break
                coeffs = tuple(_ball(x, envr, False) for x in row)
                models.append(TaylorModel(coeffs, M, rho, J))
            if ok:
                return tuple(models)
    return None


def taylor_models(s: LevelDependentScheme, values=None, *, J: int | None = None,
                  rhos=(2, 1, sp.Rational(1, 2), sp.Rational(1, 4), sp.Rational(1, 16)),
                  grid: int = 12, prec: int = 96) -> list[TaylorModel]:
    """Rigorous Taylor models of ``g_k = a^n_k - a_k`` in ``h`` over a parameter box.

    ``values``: parameter -> exact value or ``(lo, hi)`` box. The radius ``rho`` is the first of
    ``rhos`` on whose disk every coefficient evaluates finitely (a proof of analyticity there).
    Raises :class:`AnalysisError` when none works.
    """
    env = _env_values(s, values)
    q = s.order()
    J = J or q + 2
    rows = s.taylor(J)
    key = _env_key(env)
    args = (s.mask, s._limits, rows, J, tuple(rhos), grid, prec)
    models = (_taylor_models.__wrapped__(tuple(env.items()), *args) if key is None or not _hashable(args[4]) else
              _taylor_models(key, *args))
    if models is not None:
        return list(models)
    boxed = any(isinstance(v, tuple) for v in (values or {}).values())
    raise AnalysisError(f"could not certify analyticity of a^n - a on any disk |h| <= rho, rho >= {sp.sstr(rhos[-1])}: "
                        "a coefficient may have a singularity close to h = 0, i.e. the mask may be undefined at "
                        "some high level n = -log2(h)" + (" (or split the parameter box)" if boxed else ""))
