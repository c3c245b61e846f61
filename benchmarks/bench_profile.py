"""Issue 11, second half: the smoothness-profile claims of the bundled papers, and the exact C^j
boundary determinant (over Q[p] vs the symbolic Berkowitz expansion it replaced).

Run: ``python benchmarks/bench_profile.py`` (CPU seconds, one process).
"""

from __future__ import annotations

import time

import sympy as sp

import schemes
from analysis.algebra.factorization import factor_out, smoothing_factor
from analysis.claims.model import evaluate_paper, get_paper
from analysis.regularity.holder import word_product
from analysis.regularity.crossings import _exact_boundaries
from analysis.stationary.transition import transition_matrices


def _cpu(label, fn):
    t = time.process_time()
    out = fn()
    print(f"{label:<58} {time.process_time() - t:7.2f} s CPU   {out}")


def _claim(pid, cid):
    paper = get_paper(pid)
    return lambda: evaluate_paper(paper, only=[cid])[0].verdict.label


def _berkowitz(a, p, j, word):
    N = smoothing_factor(a, exceptional=False).value
    P = word_product(transition_matrices(factor_out(a, N) / 2), word)
    th = sp.Integer(2) ** ((N - 1 - j) * len(word))
    return [sp.Poly(sp.fraction(sp.together(sp.together((P - s * th * sp.eye(P.shape[0])).det(method="berkowitz"))))[0], p)
            for s in (1, -1)]


if __name__ == "__main__":
    import sys
    for pid, cid in ([] if "--det" in sys.argv else (("004", "004:Theorem5.1(profile)"), ("004", "004:Theorem5.4(profile)"), ("003", "003:Sec2(profile)"))):
        _cpu(f"subdiv report {pid} --claim '{cid}'", _claim(pid, cid))
    for slug, j in (("seed004-l-mu", 5), ("dfh-chaikin-perturbation", 1)):
        a = schemes.get(slug).symbol
        p = a.params[0]
        for word in ((0, 1), (0, 1, 1, 0)):
            _cpu(f"{slug}, j = {j}, word {word}: det over Q[p] (new)",
                 lambda: len(_exact_boundaries(a, p, j, word, sp.Integer(-1), sp.Integer(1))))
            _cpu(f"{slug}, j = {j}, word {word}: Berkowitz (old)", lambda: [q.degree() for q in _berkowitz(a, p, j, word)])
