"""Level-dependent schemes whose level enters through rational functions of n (and powers of 2^-n).

:class:`~analysis.levels.level_dependent.LevelDependentScheme` needs every coefficient to be a
function of ``h = 2^-n`` alone (the Taylor models and Cauchy tails are in h). Here a coefficient
may be any

    a^n_k = sum_j rho_{k,j}(n) 2^{-j n},     rho_{k,j} rational functions of n,

e.g. ``(n+1)/2**n`` or ``1/(n+2)**3``: :class:`RationalLevelScheme`. For such masks the Dyn–Levin
quantities are decided **exactly** and bounded with **rigorous tails**:

* the limit ``a_k = lim rho_{k,0}(n)`` (exact: ratio of leading coefficients);
* each piece ``rho(n) 2^{-jn}`` of ``g_k = a^n_k - a_k`` has the exact decay ``rho(n) ~ C n^{-p}``
  and a certified bound ``|rho(n)| <= A n^{-p}`` for ``n >= N`` (``u = 1/n``: the reversed
  polynomials are enclosed in Arb over ``u in [0, 1/N]``, cut in pieces);
* ``sum_n 2^{mn} ||S_{a^n} - S_a||_inf`` **converges** iff for every k the dominant piece
  (smallest j, then its p) has ``j > m`` or ``j = m, p > 1``; then the sum is enclosed by the Arb
  partial sum over ``n < N`` plus the tail ``sum_{n>=N}`` of the majorants (geometric for
  ``j > m``, the p-series bound ``N^-p + N^{1-p}/(p-1)`` for ``j = m``). Otherwise it **diverges**:
  ``2^{mn} |g_k(n)| ~ |C| n^{-p} 2^{(m-j)n}`` (exact leading term, C != 0) is not summable;
* same support (exact outside the limit's support; Arb for ``n < N``, the tail bound for ``n >= N``).

:func:`level_smoothness_rational` then gives the C^k verdicts by Dyn–Levin 1995 (direct and on the
divided difference schemes ``(2/(1+z))^j a^n``, exact division), as :mod:`.ck` does for masks in h.
Not implemented here: the asymptotic-similarity route (approximate sum rules) and "not C^k".

Examples
--------
>>> s = RationalLevelScheme.from_symbol("(1+z)**3/4/z**2 + (z-1)**4/z**2/(n+2)**3")
>>> s.limit()
LaurentSymbol([1/4, 3/4, 3/4, 1/4], start=-2, domain=QQ)
>>> r = weighted_series_rational(s, 0)
>>> r.witness["verdict"], r.witness["decay"]
('convergent', '1 * n^-3')
>>> weighted_series_rational(s, 1).witness["verdict"]
'divergent'
>>> same_support_rational(s).witness["failed"]     # a_2 = 0, a^n_2 = 1/(n+2)^3: Dyn-Levin does not apply
['a^n_2 is not identically 0 while a_2 = 0']

References
----------
N. Dyn, D. Levin, *Analysis of asymptotically equivalent binary subdivision schemes*,
J. Math. Anal. Appl. 193 (1995) 594-621.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import flint
import sympy as sp

from .balls import _ball, ball_to_interval, workprec
from .level_dependent import H, N, _Z, _grows, _read, resolve_where
from ..algebra.reader import substitute
from ..algebra.symbol import LaurentSymbol
from ..jsonable import fmt_upper
from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..algebra.reader import as_expr

__all__ = ["RationalLevelScheme", "weighted_series_rational", "same_support_rational", "level_smoothness_rational"]


def _in_n_and_h(c: sp.Expr) -> sp.Expr:
    e = as_expr(c).subs(sp.Symbol("n"), N)
    e = sp.powsimp(sp.expand_power_exp(sp.expand(e))).subs(2 ** N, 1 / H)
    return e.subs(2 ** (-N), H)


@dataclass(frozen=True)
class _Piece:
    j: int            # power of 2^-n
    rho: sp.Expr      # rational function of n, not identically 0
    num: sp.Poly
    den: sp.Poly

    @property
    def p(self) -> int:
        """Decay order: ``rho(n) ~ C n^-p``."""
        return self.den.degree() - self.num.degree()

    @property
    def leading(self) -> sp.Expr:
        return self.num.LC() / self.den.LC()

    def bound(self, Nmin: int, parts: int = 16):
        """``A`` (arb) with ``|rho(n)| <= A n^-p`` for all ``n >= Nmin``, or ``None``."""
        # rho(1/u) u^-p = numrev(u) / denrev(u); all_coeffs() (highest degree first) are the
        # coefficients of the reversed polynomials in increasing powers of u = 1/n
        nrev = [_ball(as_expr(x), {}, False) for x in self.num.all_coeffs()]
        drev = [_ball(as_expr(x), {}, False) for x in self.den.all_coeffs()]
        best = flint.arb(0)
        w = flint.arb(1) / (Nmin * parts)
        for i in range(parts):
            u = flint.arb(i) * w + w / 2
            u = flint.arb(u.mid(), (w / 2).mid() * 1.0001)

            def horner(cs):
                v = flint.arb(0)
                for c in reversed(cs):
                    v = v * u + c
                return v
            dv = horner(drev)
            if dv.contains(0):
                return None
            best = best.max(flint.arb((horner(nrev) / dv).abs_upper()))
        return best


def _split(c: sp.Expr, where: str) -> list[_Piece]:
    """``c = sum_j rho_j(n) h^j`` with ``rho_j`` rational in n (one-line error otherwise)."""
    c = sp.together(_in_n_and_h(c))
    free = c.free_symbols - {N, H}
    if free:
        raise AnalysisError(f"undefined name(s) {', '.join(sorted(map(str, free)))} in {where}: give --param NAME=VALUE")
    num, den = sp.fraction(c)
    try:
        dpol = sp.Poly(den, H, N)
        npol = sp.Poly(num, H, N)
    except sp.PolynomialError:
        raise AnalysisError(f"cannot write {where} ({sp.sstr(c.subs(H, 2 ** -N))}) as a polynomial in 2^-n with "
                            "coefficients rational in n") from None
    if dpol.degree(H) > 0:
        if len(sp.Poly(den, H).terms()) != 1:
            raise AnalysisError(f"{where}: 2^-n in a denominator ({sp.sstr(den.subs(H, 2 ** -N))}) is not supported")
        raise AnalysisError(f"{where} grows like a power of 2^n: no finite limit as n -> oo")
    dn = sp.Poly(den, N)
    try:
        bad = [r for r in dn.real_roots() if r.is_Integer and r >= 0]
    except (sp.PolynomialError, NotImplementedError, sp.polys.polyerrors.DomainError):
        raise AnalysisError(f"{where}: cannot certify that the denominator {sp.sstr(den)} never vanishes "
                            "at a level n >= 0 (give rational coefficients)") from None
    if bad:
        raise AnalysisError(f"{where} is undefined at level n = {bad[0]} (its denominator vanishes)")
    pieces = []
    for j in range(npol.degree(H) + 1 if not npol.is_zero else 0):
        nj = sp.Poly(sp.expand(num).coeff(H, j), N)
        if nj.is_zero:
            continue
        rho = sp.cancel(nj.as_expr() / den)
        rn, rd = sp.fraction(rho)
        pieces.append(_Piece(j, rho, sp.Poly(rn, N), sp.Poly(rd, N)))
    return pieces


@dataclass(frozen=True)
class RationalLevelScheme:
    """A binary level-dependent scheme with ``a^n_k = sum_j rho_{k,j}(n) 2^-jn`` (``rho`` rational in n)."""

    mask: tuple
    start: int
    slug: str = "symbol"

    @classmethod
    def from_symbol(cls, expr, *, where=None, params=None, slug: str = "symbol") -> "RationalLevelScheme":
        """From a symbol in ``z`` and ``n`` (``--where`` helpers and ``--param`` values substituted)."""
        defs = resolve_where(where)
        e = substitute(_read(expr, defs, "symbol"), defs, what="the symbol")
        if params:
            e = e.subs({sp.Symbol(k): v for k, v in params.items()})
        num, den = sp.fraction(sp.together(e))
        try:
            dp, np_ = sp.Poly(den, _Z), sp.Poly(num, _Z)
        except sp.PolynomialError:
            raise AnalysisError("the support of a^n grows with the level n" if _grows(e) else
                                "the symbol must be a Laurent polynomial in z") from None
        if len(dp.terms()) != 1:
            raise AnalysisError("the symbol must be a Laurent polynomial in z (only powers of z may divide)")
        shift, dc = -dp.monoms()[0][0], dp.coeffs()[0]
        coeffs = [sp.cancel(c / dc) for c in reversed(np_.all_coeffs())]
        return cls.from_mask(coeffs, shift, slug=slug)

    @classmethod
    def from_mask(cls, coeffs, start: int = 0, *, where=None, params=None, slug: str = "mask") -> "RationalLevelScheme":
        defs = resolve_where(where)
        cs = [substitute(_read(c, defs, "coefficient"), defs, what="a coefficient") if isinstance(c, str) else as_expr(c) for c in coeffs]
        if params:
            cs = [c.subs({sp.Symbol(k): v for k, v in params.items()}) for c in cs]
        cs = [sp.cancel(sp.together(_in_n_and_h(c))) for c in cs]
        while len(cs) > 1 and cs[-1] == 0:
            cs.pop()
        while len(cs) > 1 and cs[0] == 0:
            cs.pop(0)
            start += 1
        s = cls(tuple(cs), int(start), slug)
        s.pieces    # validates every coefficient (one-line errors)
        return s

    @cached_property
    def pieces(self) -> tuple:
        """Per coefficient: its limit ``a_k`` and the pieces of ``g_k = a^n_k - a_k``."""
        out = []
        for i, c in enumerate(self.mask):
            ps = _split(c, f"the coefficient of z^{self.start + i}")
            p0 = next((p for p in ps if p.j == 0), None)
            if p0 is not None and p0.p < 0:
                raise AnalysisError(f"the coefficient of z^{self.start + i} has no finite limit as n -> oo")
            lim = sp.Integer(0) if p0 is None or p0.p > 0 else sp.simplify(p0.leading)
            g = [p for p in ps if p.j > 0]
            if p0 is not None:
                r = sp.cancel(p0.rho - lim)
                if r != 0:
                    rn, rd = sp.fraction(r)
                    g.insert(0, _Piece(0, r, sp.Poly(rn, N), sp.Poly(rd, N)))
            out.append((lim, tuple(g)))
        return tuple(out)

    def limit(self) -> LaurentSymbol:
        return LaurentSymbol.from_mask([lim for lim, _ in self.pieces], start=self.start)

    @property
    def depends_on_level(self) -> bool:
        return any(g for _, g in self.pieces)

    def difference(self) -> "RationalLevelScheme":
        """``(2/(1+z)) a^n`` (exact division; AnalysisError when ``a^n(-1) != 0`` identically)."""
        q, rem = [], sp.Integer(0)
        for c in self.mask[:-1]:
            rem = sp.cancel(c - rem)
            q.append(rem)
        if sp.cancel(self.mask[-1] - rem) != 0:
            raise AnalysisError("(1+z) does not divide a^n(z) identically in n")
        return RationalLevelScheme(tuple(sp.cancel(2 * c) for c in q), self.start, f"{self.slug}-diff")

    def level_values(self, n: int) -> list:
        """Arb enclosures of ``a^n_k - a_k`` at level n."""
        out = []
        for lim, g in self.pieces:
            v = flint.arb(0)
            for p in g:
                v += _ball(p.rho.subs(N, n), {}, False) * flint.arb(2) ** (-p.j * n)
            out.append(v)
        return out


def weighted_series_rational(s: RationalLevelScheme, m: int = 0, *, N_sum: int = 40) -> Result:
    """``sum_n 2^{mn} ||S_{a^n} - S_a||_inf``: convergent (certified enclosure) or divergent (exact).

    ``witness["verdict"]``: ``"convergent"`` / ``"divergent"``; ``witness["decay"]``: the slowest
    decaying coefficient difference ``|a^n_k - a_k| ~ C n^-p 2^(-jn)`` (exact leading term).
    """
    dom = []
    for k, (_, g) in enumerate(s.pieces):
        if g:
            p0 = min(g, key=lambda p: (p.j, -p.p))
            dom.append((k, p0))
    if not dom:
        raise AnalysisError("the scheme does not depend on the level: use the stationary analysis")
    worst = min(dom, key=lambda kp: (kp[1].j, kp[1].p))
    kw, pw = worst
    decay = " * ".join([sp.sstr(sp.Abs(pw.leading))] + ([f"n^{-pw.p}"] if pw.p else [])
                       + ([f"2^(-{pw.j}n)"] if pw.j else []))
    prov = {"method": "exact decay orders of rational pieces + Arb partial sums + majorant tails", "m": m}
    ok = all(p.j > m or (p.j == m and p.p > 1) for _, p in dom)
    if not ok:
        return Result(value=None, status=CERTIFIED,
                      witness={"verdict": "divergent", "decay": decay,
                               "reason": (f"the coefficient of z^{s.start + kw} differs from its limit by "
                                          f"~ {decay} (exact leading term), so 2^({m}n) times it is not summable")},
                      provenance=prov)
    with workprec(128):
        tail = flint.arb(0)
        for _, g in s.pieces:
            for p in g:
                A = p.bound(N_sum)
                if A is None:
                    return Result(value=None, status=INCONCLUSIVE,
                                  witness={"verdict": "inconclusive", "decay": decay,
                                           "reason": f"no bound of {sp.sstr(p.rho)} for n >= {N_sum}"},
                                  provenance=prov)
                Nb = flint.arb(N_sum)
                if p.j > m:
                    r = flint.arb(2) ** (m - p.j)
                    ratio = r * (1 + 1 / Nb) ** max(-p.p, 0)
                    if not ratio < 1:
                        return Result(value=None, status=INCONCLUSIVE, witness={"verdict": "inconclusive",
                                      "decay": decay, "reason": "tail ratio not < 1"}, provenance=prov)
                    tail += A * Nb ** (-p.p) * r ** N_sum / (1 - ratio)
                else:           # j == m, p > 1: p-series
                    tail += A * (Nb ** (-p.p) + Nb ** (1 - p.p) / (p.p - 1))
        part = flint.arb(0)
        for n in range(N_sum):
            d = s.level_values(n)
            sums = [flint.arb(0), flint.arb(0)]
            for k, v in enumerate(d):
                sums[(s.start + k) % 2] += abs(v)
            part += flint.arb(2) ** (m * n) * sums[0].max(sums[1])
        lo = ball_to_interval(part)[0]
        hi = ball_to_interval(part + tail)[1]
    return Result(lower=max(lo, sp.Integer(0)), upper=hi, status=CERTIFIED,
                  witness={"verdict": "convergent", "decay": decay, "N": N_sum,
                           "tail": f"sum_(n >= {N_sum}) <= {fmt_upper(ball_to_interval(tail)[1], 3, 'g')}",
                           "sum": f"[{float(max(lo, 0)):.12g}, {float(hi):.12g}]"},
                  provenance=prov)


def same_support_rational(s: RationalLevelScheme, *, N_sum: int = 40) -> Result:
    """``a^n`` has the support of ``a`` at every level (exact outside it; Arb + tail bound inside)."""
    bad = []
    with workprec(128):
        for k, (lim, g) in enumerate(s.pieces):
            e = s.start + k
            if lim == 0:
                if g:
                    bad.append(f"a^n_{e} is not identically 0 while a_{e} = 0")
                continue
            L = _ball(as_expr(lim), {}, False)
            for n in range(N_sum):
                v = L + s.level_values(n)[k]
                if v.contains(0):
                    bad.append(f"a^n_{e} not certified != 0 at n = {n}")
                    break
            sup = flint.arb(0)
            for p in g:
                A = p.bound(N_sum)
                mono = p.p >= 0 or (1 + flint.arb(1) / N_sum) ** (-p.p) * flint.arb(2) ** (-p.j) < 1
                if A is None or not mono:
                    sup = None
                    break
                sup += A * flint.arb(N_sum) ** (-p.p) * flint.arb(2) ** (-p.j * N_sum)
            if sup is None or not sup < abs(L):
                bad.append(f"a^n_{e} not certified != 0 for n >= {N_sum}")
    if bad:
        return Result(value=None, status=INCONCLUSIVE, witness={"same_support": None, "failed": bad})
    return Result(value=True, status=CERTIFIED, witness={"same_support": True, "support": (s.start, s.start + len(s.mask) - 1)},
                  provenance={"method": f"exact zeros; Arb for n < {N_sum}; |a^n_k - a_k| bound for n >= {N_sum}"})


def _ordinal(j: int) -> str:
    return f"{j}{ {1: 'st', 2: 'nd', 3: 'rd'}.get(j if j < 20 else j % 10, 'th')}"


def level_smoothness_rational(s: RationalLevelScheme, *, k_max: int | None = None, N_sum: int = 40) -> Result:
    """C^k verdicts (k up to the limit's smoothness) by Dyn–Levin 1995, direct and on divided differences."""
    from ..regularity import smoothness as stationary_smoothness
    from .series import stationary_smoothness as limit_smoothness

    if not s.depends_on_level:
        raise AnalysisError("the scheme does not depend on the level: use the stationary analysis")
    a = s.limit()
    k_lim, not_k = -1, None
    reasons = {}
    for k in range((12 if k_max is None else k_max) + 1):
        r = stationary_smoothness(a, k)
        if r.value is True and r.is_certified:
            k_lim = k
            continue
        if r.value is False and r.is_certified:
            not_k = k
            reasons[k] = r.witness.get("reason")
        break
    diffs = {0: s}
    for j in range(1, k_lim + 1):
        try:
            diffs[j] = diffs[j - 1].difference()
        except AnalysisError:
            break
    verdicts, best = [], -1
    for k in range(k_lim + 1):
        jmax = max(j for j in diffs if j <= k)
        order = ([jmax] if jmax == k and k > 0 else []) + [0] + [j for j in range(jmax, 0, -1) if j != k]
        tried, found = [], None
        for j in order:
            e = diffs[j]
            route = "Dyn-Levin direct" if j == 0 else f"Dyn-Levin on the {_ordinal(j)} divided difference scheme"
            try:
                ser = weighted_series_rational(e, k - j, N_sum=N_sum)
            except AnalysisError as exc:       # e^n does not depend on the level: e = e^n, stationary
                ser = Result(value=None, status=INCONCLUSIVE, witness={"verdict": "stationary", "reason": str(exc)})
            sup = same_support_rational(e, N_sum=N_sum) if ser.witness.get("verdict") != "stationary" else \
                Result(value=True, status=CERTIFIED, witness={"same_support": True})
            lim = limit_smoothness(e.limit(), k - j)
            hyps = {"same_support": sup, f"limit_C^{k - j}": lim,
                    f"series_m={k - j}": ser}
            conv = ser.witness.get("verdict") in ("convergent", "stationary")
            if sup.value is True and lim.is_certified and lim.value is True and conv:
                found = {"k": k, "verdict": f"C^{k}", "status": CERTIFIED, "route": route,
                         "theorem": "Dyn-Levin 1995: same support, S_e C^(k-j), sum 2^((k-j)n)||S_(e^n)-S_e|| < oo",
                         "hypotheses": hyps}
                break
            failed = [name for name, x in hyps.items()
                      if not ((x.value is True and x.is_certified) or x.witness.get("verdict") in ("convergent", "stationary"))]
            tried.append({"route": route, "failed": failed,
                          "why": "; ".join(str(hyps[f].witness.get("reason") or hyps[f].witness.get("failed") or "")
                                           for f in failed)})
        v = found or {"k": k, "verdict": "undecided", "status": INCONCLUSIVE, "route": None, "tried": tried}
        verdicts.append(v)
        if v["status"] == CERTIFIED and best == k - 1:
            best = k
    if not_k is not None and (k_max is None or not_k <= k_max):
        verdicts.append({"k": not_k, "verdict": "undecided", "status": INCONCLUSIVE, "route": None,
                         "reason": (f"the limit S_a is certified not C^{not_k} ({reasons[not_k]}), but no implemented "
                                    f"theorem transfers 'not C^{not_k}' to this level-dependent scheme")})
    return Result(value=best, status=CERTIFIED if best >= 0 else INCONCLUSIVE,
                  witness={"verdicts": verdicts, "max_certified_k": best,
                           "limit": {"symbol": a, "C^k_certified_up_to": k_lim, "not_C^k": not_k},
                           "upper_bound": "none certified (lower bound only)"},
                  provenance={"scheme": s.slug, "N": N_sum,
                              "method": "Dyn-Levin 1995 (direct, divided differences), level rational in n"})
