"""Smoothness conditions of the non-uniform analysis: Property A (Dyn-Levin-Yoon 2014), seed
001's quantities (13)-(14), exactly and per level; numerical smoothness at parameter junctions.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import numpy as np

from ..result import CERTIFIED, NUMERICAL, AnalysisError, Result
from .arithmetic import _Arith
from .masks import _mask_array
from .refinement import _check_degree, _sources, refine, step


def _falling(x: int, r: int) -> int:
    out = 1
    for t in range(r):
        out *= x - t
    return out


def _property_a_values(D: np.ndarray, start: int, m: int, r: int, z0: int, closed: bool):
    """``d^{(r)}_m(z0)`` at every location ``j`` (``j >= m`` for open polygons) from the mask
    differences ``D`` (the limit mask contributes 0 for r < m at z = 1 and r <= d at z = -1)."""
    count, width = D.shape
    exps = np.arange(width) + start
    total = None
    js = np.arange(count) if closed else np.arange(m, count)
    for i in range(m + 1):
        g = np.array([_falling(int(e + i), r) * (z0 ** int(e + i - r)) if _falling(int(e + i), r) else 0
                      for e in exps], dtype=object)
        rows = (js - i) % count if closed else js - i
        if D.dtype == float:
            part = D[rows].dot(g.astype(float))
        else:
            part = D[rows].dot(g)
        term = (-1) ** i * math.comb(m, i) * part
        total = term if total is None else total + term
    return js, total


def property_a_structure(degree: int, m: int, r: int, z0: int, *, part: str = "full") -> Result:
    """Exact structure of seed 001's (13)-(14) quantity ``d^{(r)}_m(z0)`` for the NVPS of degree d:
    a linear form in ``delta_e = h_e - 1/4`` of the edges around the location. Certified:

    * whether it vanishes identically (then Property A holds trivially for this (m, r, z0));
    * whether it vanishes on constant parameter sequences (``sum of coefficients = 0``): then on
      blended data it equals ``kappa (delta_B - delta_A)`` at a junction, ``= Theta(4^{-k})``, and
      Property A of order m (``o(2^{-k(m-r)})``) fails there as soon as ``m - r >= 2``.

    ``part="full"`` uses the full masks (both parities; the unused parity completed as described
    in :mod:`.masks`), ``part="used"`` only the coefficients that act (parity of the new
    point), evaluated at ``z = 1`` (``z0`` is then ignored): a completion-independent variant.

    >>> property_a_structure(4, 3, 1, -1).value
    'nonzero at junctions'
    >>> property_a_structure(3, 2, 1, -1).witness["property_A_fails_on_blended_data"]
    False
    >>> property_a_structure(4, 2, 0, 1).value
    'identically zero'
    """
    d = _check_degree(degree)
    if not (0 <= r < m):
        raise AnalysisError("Property A uses 0 <= r < m")
    if z0 not in (1, -1):
        raise AnalysisError("z0 must be 1 or -1")
    if m > d + 1:
        raise AnalysisError("m must be <= d + 1")
    if part not in ("full", "used"):
        raise AnalysisError("part must be 'full' or 'used'")
    edges = 2 * ((m + d) // 2 + 4)
    scale = 2 ** (d - 2)

    def values(delta):
        # integer masks: weights binom(d-2, l) (the factor 2^{2-d} is put back at the end)
        count = 2 * edges - (d - 2)
        D = np.zeros((count, d + 2), dtype=object)
        D[:] = 0
        idx = np.arange(count)
        for l in range(d - 1):
            x = delta[(idx + l) // 2]
            for s_, sg in enumerate((1, -1, -1, 1)):
                D[:, (s_ - 2) - l + d] += math.comb(d - 2, l) * sg * x
        if part == "used":
            exps = np.arange(d + 2) - d
            par = (exps[None, :] - idx[:, None]) % 2 == 0
            D = np.where(par, D, 0)
            return _property_a_values(D, -d, m, r, 1, False)[1]
        return _property_a_values(D, -d, m, r, z0, False)[1]

    kappas = []
    for junction in range(1, edges):
        delta = np.array([0] * junction + [1] * (edges - junction), dtype=object)
        kappas.extend(Fraction(int(x), scale) for x in values(delta))
    cvals = values(np.array([1] * edges, dtype=object))
    const_zero = all(x == 0 for x in cvals)
    nonzero = any(x != 0 for x in kappas)
    kmax = max(abs(x) for x in kappas) if kappas else 0
    if not nonzero and const_zero:
        verdict = "identically zero"
    elif const_zero:
        verdict = "nonzero at junctions"
    else:
        verdict = "nonzero on constant sequences"
    fails = bool(nonzero or not const_zero) and (m - r) >= 2
    return Result(value=verdict, status=CERTIFIED,
                  witness={"max_|kappa|": str(kmax), "required": f"o(2^(-k({m}-{r})))",
                           "junction_order": "Theta(4^-k) (delta_B - delta_A) when nonzero",
                           "property_A_fails_on_blended_data": fails, "m": m, "r": r,
                           "z0": z0 if part == "full" else 1, "degree": d, "part": part},
                  provenance={"method": "exact integer linear forms on unit step sequences", "arithmetic": "exact"})


def property_a_table(degree: int, *, part: str = "full") -> list[dict]:
    """All (m, r, z0) with ``1 <= m <= d-1`` (the orders Theorem 3.6 needs) whose quantity does not
    vanish identically, with whether Property A then fails on blended parameters.

    >>> [(x["m"], x["r"], x["z0"]) for x in property_a_table(3)]
    [(2, 1, -1)]
    """
    d = _check_degree(degree)
    out = []
    for m in range(1, d):
        for r in range(m):
            for z0 in ((1, -1) if part == "full" else (1,)):
                res = property_a_structure(d, m, r, z0, part=part)
                if res.value != "identically zero":
                    out.append({"m": m, "r": r, "z0": z0, "verdict": res.value,
                                "max_kappa": res.witness["max_|kappa|"],
                                "fails_on_blended": res.witness["property_A_fails_on_blended_data"]})
    return out


def property_a(u0, degree: int, m: int, r: int, z0: int, *, levels: int = 12, closed: bool = False,
               rule: str = "seed001") -> Result:
    """``max_j |d^{(r)}_m(z0)|`` at levels ``k = 0..levels`` for the initial edge parameters
    ``u0`` (floats, cancellation-free), its scaled value ``2^{k(m-r)} max_j |.|`` (Property A of
    order m asks that this -> 0) and ``4^k max_j |.|``. NUMERICAL (double precision on exact
    linear forms of accurately computed ``delta``).

    >>> r = property_a([0.5] * 4 + [3.0] * 4, 4, 3, 1, -1, levels=10)
    >>> r.value                                     # does 2^{k(m-r)} max_j|.| -> 0 ?
    'does not tend to 0'
    """
    d = _check_degree(degree)
    if not (0 <= r < m <= d + 1) or z0 not in (1, -1):
        raise AnalysisError("need 0 <= r < m <= d + 1 and z0 in {1, -1}")
    res = refine(np.zeros(len(u0) + (0 if closed else 1)), u0, degree=d, steps=0, closed=closed, rule=rule)
    v = res.one_minus_u
    rows = []
    for k in range(levels + 1):
        delta = v / (4 * (2 - v))
        D = _mask_array(delta, d, closed)
        if D.shape[0] > m:
            _, vals = _property_a_values(D, -d, m, r, z0, closed)
            mx = float(np.max(np.abs(vals.astype(float)))) if len(vals) else 0.0
        else:
            mx = float("nan")
        rows.append({"k": k, "max": mx, "scaled_2^{k(m-r)}": mx * 2.0 ** (k * (m - r)), "scaled_4^k": mx * 4.0 ** k})
        if k < levels:
            _, v = step(np.zeros(len(v) + (0 if closed else 1)), v, d, closed=closed, rule=rule)
    tail = [x["scaled_2^{k(m-r)}"] for x in rows[-3:]]
    if all(x == 0 for x in tail):
        verdict = "identically 0"
    elif tail[-1] < 0.3 * tail[0]:
        verdict = "tends to 0"
    else:
        verdict = "does not tend to 0"
    return Result(value=verdict, status=NUMERICAL, witness={"levels": rows, "m": m, "r": r, "z0": z0},
                  provenance={"method": "float64 on exact linear forms; delta = v/(4(2-v)) without cancellation",
                              "degree": d, "rule": rule, "closed": closed})


# --------------------------------------------------------------------------------------------
# smoothness at junctions (numerical)
# --------------------------------------------------------------------------------------------

def junction_smoothness(degree: int, u_left, u_right, *, levels: int = 16, rule: str = "seed001",
                        order: int | None = None, seed: int = 0, half_width: int = 12) -> Result:
    """Numerical evidence on the C^{d-1} claim at a junction between two parameter values.

    Scalar data (random, fixed seed) on an open polygon whose left edges carry ``u_left`` and
    right edges ``u_right``; a window of ``2 half_width`` points around the junction is refined
    ``levels`` times in ``mpmath`` (precision grown with the level so that divided differences
    keep ~60 correct bits). Reports ``omega_k = max |Delta D^k|`` where
    ``D^k = 2^{k q} Delta^q f^k`` are the q-th divided differences (``q = order``, default d-1).
    If the limit is C^q near the junction, ``omega_k -> 0``; a jump of the q-th derivative shows
    as ``omega_k`` bounded away from 0. Also reported for a uniform window as a control.

    >>> r = junction_smoothness(2, 0.3, 4.0, levels=10)
    >>> r.value
    'omega_k -> 0'
    """
    d = _check_degree(degree)
    q = d - 1 if order is None else int(order)
    rng = np.random.default_rng(seed)
    n0 = 2 * half_width
    data = [float(x) for x in rng.standard_normal(n0)]

    def run(ul, ur):
        prec = 64 + levels * (q + 1) + 8 * d
        ctx = _Arith("mp", prec)
        out = []
        with ctx.scope():
            P = ctx.array(data)
            v = ctx.array([1 - ul] * (half_width - 1) + [1 - ur] * (half_width))
            anc = np.array([0] * (half_width - 1) + [1] * half_width)
            for k in range(levels + 1):
                # q-th divided differences and their first differences near the junction
                diffs = P.copy()
                for _ in range(q):
                    diffs = diffs[1:] - diffs[:-1]
                Dk = diffs * mpmath.mpf(2) ** (k * q)
                jumps = [abs(Dk[i + 1] - Dk[i]) for i in range(len(Dk) - 1)]
                out.append(float(max(jumps)))
                if k == levels:
                    break
                P, v_new = step(P, v, d, rule=rule, sqrt=ctx.sqrt)
                j = np.arange(len(P) - 1)
                anc = anc[_sources(j, d, False, rule, len(v))]
                v = v_new
                # crop to a window around the junction (first edge inheriting from the right side)
                jn = int(np.argmax(anc == 1)) if (anc == 1).any() else len(anc) // 2
                a = max(0, jn - half_width)
                b = min(len(P), jn + half_width)
                P, v, anc = P[a:b], v[a:b - 1], anc[a:b - 1]
        return out

    junction = run(float(u_left), float(u_right))
    uniform = run(float(u_left), float(u_left))
    mid = junction[len(junction) // 2]
    verdict = "omega_k -> 0" if junction[-1] < 0.25 * mid else "omega_k bounded away from 0"
    rates = [math.log2(junction[k] / junction[k + 1]) if junction[k + 1] > 0 else float("inf")
             for k in range(len(junction) - 1)]
    return Result(value=verdict, status=NUMERICAL,
                  witness={"omega_junction": junction, "omega_uniform": uniform, "log2_ratios": rates,
                           "order": q, "levels": levels},
                  provenance={"method": "windowed refinement in mpmath, divided differences", "degree": d,
                              "rule": rule, "seed": seed})
