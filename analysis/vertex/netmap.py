"""The characteristic map of an interpolating scheme sampled on a fine net, in floats: numerical evidence,
never a certificate.

For the butterfly family every ring R is closed under the rules, so the block-1 eigenvector ``v_R`` of the
local matrix on the R-ring for lambda exists, and because the scheme is interpolating the control points at
level m are points of the limit: the characteristic map at the lattice point p of ring <= R (level-0 units)
is ``w^j v_R(p)`` in sector j. The annulus between rings R/2 and R is a fundamental annulus of the map
(``Phi(x/2) = lambda Phi(x)``) sampled with spacing 1/R of its width. The check: every lattice triangle of
sector 0 in that annulus has a discrete Jacobian ``Im(conj(b - a)(c - a))`` of one sign, and the ring-R
polygon winds once round 0. Both are float computations on a finite sample (numpy): the result's status is
*numerical*. It says nothing certain between the samples; a certificate needs enclosures of the limit map's
derivatives (Zorin 2000), which :mod:`.charmap` has only for schemes with polynomial patches.

Examples
--------
>>> from analysis.vertex.rules import scheme_rules
>>> r = numerical_characteristic_map(scheme_rules("modified-butterfly", 3, 5), 5, 0.5, resolution=8)
>>> r["status"], r["regular"], r["winding_number"]
('numerical', True, 1)

References
----------
D. Zorin, A method for analysis of C^1-continuity of subdivision surfaces, SIAM J. Numer. Anal. 37 (2000)
(the characteristic map of the butterfly schemes; verification from refined nets); U. Reif, A unified
approach to subdivision algorithms near extraordinary vertices, CAGD 12 (1995).
"""

from __future__ import annotations

import sympy as sp

from ..result import NUMERICAL, AnalysisError
from .blocks import _laurent
from .rules import ALL, C1, CENTRE, W, LocalRules, _tri_home, butterfly_rules, modified_butterfly_rules, n_sym

#: the default number of rings of the sampled net
RESOLUTION = 16


def _block1(rules: LocalRules, n: int):
    """Fourier block 1 of the local matrix as a complex numpy array."""
    import numpy as np

    w = np.exp(2j * np.pi / n)
    m = len(rules.points)
    B = np.zeros((m, m), dtype=complex)
    cache: dict = {}

    def val(expr):
        if expr not in cache:
            cache[expr] = complex(sp.N(expr.subs({n_sym: n, C1: sp.cos(2 * sp.pi / n)})))
        return cache[expr]

    for q, rule in enumerate(rules.sector_rules()):
        for t in rule:
            if t.source == (CENTRE,):
                continue
            p, d = t.source
            if d == ALL:
                coeffs = _laurent(t.weight, W)
                B[q, p] += n * sum(val(a) for l_, a in coeffs.items() if (l_ + 1) % n == 0)
            else:
                B[q, p] += val(t.weight) * w ** d
    return B


def _phi(rules: LocalRules, n: int, lam: float, resolution: int):
    """The sampled characteristic map: a function of a lattice point of ring <= resolution, and the
    eigenvalue used (block 1's eigenvalue of the big local matrix nearest to ``lam``)."""
    import numpy as np

    if rules.lattice != "triangle, interpolating" or rules.tension is None:
        raise AnalysisError("the sampled characteristic net is built for the butterfly family only")
    build = butterfly_rules if rules.name == "butterfly" else None
    if rules.name == "modified-butterfly":
        big = modified_butterfly_rules(resolution, n, rules.tension)
    elif build is not None:
        big = build(resolution, rules.tension)
    else:
        raise AnalysisError(f"no sampled characteristic net for {rules.name}")
    B = _block1(big, n)
    vals, vecs = np.linalg.eig(B)
    i = int(np.argmin(abs(vals - lam)))
    v = vecs[:, i] / vecs[int(np.argmax(abs(vecs[:, i]))), i]
    index = {p: k for k, p in enumerate(big.coords)}
    w = np.exp(2j * np.pi / n)

    def phi(x, y):
        if (x, y) == (0, 0):
            return 0j
        d, hx, hy = _tri_home(x, y)
        return w ** d * v[index[(hx, hy)]]

    return phi, complex(vals[i]).real


def _annulus(R: int):
    """The lattice triangles of sector 0 between rings R/2 and R."""
    for x in range(R + 1):
        for y in range(R + 1 - x):
            for tri in (((x, y), (x + 1, y), (x, y + 1)), ((x + 1, y), (x + 1, y + 1), (x, y + 1))):
                rings = [a + b for a, b in tri]
                if max(rings) > R or min(rings) < R // 2:
                    continue
                yield tri


def net_triangles(rules: LocalRules, n: int, lam: float, resolution: int = RESOLUTION) -> list:
    """The images of sector 0's lattice triangles in the annulus (floats, for a picture)."""
    phi, _ = _phi(rules, n, lam, resolution)
    return [tuple(complex(phi(*p)) for p in tri) for tri in _annulus(resolution)]


def numerical_characteristic_map(rules: LocalRules, n: int, lam: float, resolution: int = RESOLUTION) -> dict:
    """Discrete Jacobians and winding number of the characteristic net on ``resolution`` rings (floats)."""
    import numpy as np

    phi, used = _phi(rules, n, lam, resolution)
    w = np.exp(2j * np.pi / n)
    R = resolution
    jac = []
    for tri in _annulus(R):
        a, b, c = (phi(*p) for p in tri)
        jac.append(((b - a).conjugate() * (c - a)).imag)
    jac = np.array(jac)
    sign = 1 if jac.max() >= -jac.min() else -1
    regular = bool(np.all(sign * jac > 0))
    ring = [w ** j * phi(R - i, i) for j in range(n) for i in range(R)]
    if min(abs(z) for z in ring) < 1e-12 * max(abs(z) for z in ring):
        winding = None                                    # the sampled ring passes through 0
    else:
        turns = sum(np.angle(ring[(k + 1) % len(ring)] / ring[k]) for k in range(len(ring)))
        winding = int(round(turns / (2 * np.pi)))
    scale = float(np.abs(jac).max())
    return {"status": NUMERICAL, "regular": regular, "jacobian_sign": sign, "winding_number": winding,
            "injective": regular and winding == sign, "resolution": R, "triangles": int(jac.size),
            "min_jacobian_ratio": float((sign * jac).min() / scale),
            "eigenvalue_used": used,
            "method": "block-1 eigenvector on the R-ring (numpy), interpolating: net points lie on the limit; "
                      "discrete Jacobians on the annulus R/2..R and the ring-R polygon's winding (floats)"}

