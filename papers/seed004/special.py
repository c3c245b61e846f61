"""Seed 004's two genuinely special claims: the 10x10 matrix form printed after (3.6) (its labels,
garbled, against the engine's local subdivision matrix) and the nonzero points after L steps
(Lemmas 4.1-4.3; a kind "support after L steps" would make these data). Everything else of the paper
is kind data in ``paper.toml``.

Examples
--------
>>> _matrix_rows_printed()[6][3:9]              # row 7 prints a2 where (3.6) has a1
[5, 3, 2, -1, -3, -5]
"""

from __future__ import annotations

import re

import sympy as sp

from analysis import claims as C
from schemes.seed004 import A_3_6, OMEGA, RULE_3_6, _from
from analysis.algebra.reader import as_expr

#: the printed 10x10 matrix after (3.6), its labels row after row (lost minus signs)
PRINTED_MATRIX = ("a5a3a1a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a5"
                  "0000a6a4a2a0a2a400000a5a3a2a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a50000a6a4a2a0a2a4")


def _s(x) -> str:
    return sp.sstr(as_expr(x))


def _matrix_rows_printed():
    """The printed rows, labels read by position (the lost minus signs of labels restored by the
    pattern a5 a3 a1 a-1 a-3 a-5 / a6 a4 a2 a0 a-2 a-4 wherever the magnitudes match)."""
    toks, rows, k = re.findall(r"a\d|0", PRINTED_MATRIX), [], 0
    for r in range(10):
        lead, row = r // 2, [None] * 10
        expect = (5, 3, 1, -1, -3, -5) if r % 2 == 0 else (6, 4, 2, 0, -2, -4)
        k += lead if r else 0
        for j, (tok, lab) in enumerate(zip(toks[k:k + 6], expect)):
            row[lead + j] = lab if tok == f"a{abs(lab)}" else int(tok[1:])
        k += 10 - lead
        rows.append(row)
    return rows


def _matrix_3_6():
    from analysis.stationary.transition import local_subdivision_matrix
    M, win = local_subdivision_matrix(_from(RULE_3_6), window=(-4, 5))
    rows, diffs = _matrix_rows_printed(), []
    for r in range(10):
        for c in range(10):
            lab = rows[r][c]
            val = sp.Integer(0) if lab is None else A_3_6[lab]
            if sp.expand(val - M[r, c]) != 0:
                should = sorted((k for k in A_3_6 if sp.expand(A_3_6[k] - M[r, c]) == 0), key=abs)
                diffs.append((r + 1, c + 1, f"a{lab}", _s(val), _s(M[r, c]), "a" + "/a".join(map(str, should))))
    res = C.exact_result(not diffs, "engine local subdivision matrix on P_-4..P_5 vs the printed labels", window=win)
    ev = [C.Evidence("engine: local_subdivision_matrix(a, window=(-4, 5))", result=res, latex=r"M = " + sp.latex(M)),
          C.Evidence("entries that differ", table=(("row", "column", "printed label", "its value", "engine",
                                                     "should read"),) + tuple(tuple(map(str, d)) for d in diffs))]
    if not diffs:
        return C.certified("The printed 10x10 matrix is the local subdivision matrix.", evidence=ev)
    d = diffs[0]
    return C.refuted(f"{len(diffs)} printed entr{'y differs' if len(diffs) == 1 else 'ies differ'}: row {d[0]}, "
                     f"column {d[1]} prints {d[2]} where the rule (3.6) gives {d[5]}.",
                     corrected=f"row {d[0]} is 0 0 0 a5 a3 a1 a-1 a-3 a-5 0 (a typo, or an extraction "
                               "error, in the printed matrix; (3.6) itself is right)",
                     evidence=ev, numbers=[C.Number("differing_entries", len(diffs))])


def _lemma_steps(L: int):
    """Lemmas 4.1-4.3: the nonzero points after L steps from a delta (a kind "support after L steps"
    would make this data; until then it stays here)."""
    from analysis.stationary.difference import iterated_symbol
    a = _from(RULE_3_6)
    it, it0 = iterated_symbol(a, L), iterated_symbol(a.subs({OMEGA: 0}), L)
    s, e = it.start, it.end
    left, right = sp.factor(it.coeff(s)), sp.factor(it.coeff(e))
    res = C.exact_result((s, e), "support of a(z) a(z^2) ... a(z^(2^(L-1))) (S_a^L applied to delta)", end_values=(left, right))
    ev = [C.Evidence(f"nonzero points after {L} step(s)", result=res,
                     text=f"P_{s}^{L} .. P_{e}^{L}; the end values are {_s(left)} and {_s(right)}, nonzero iff omega != 0; "
                          f"at omega = 0 the points are P_{it0.start}^{L} .. P_{it0.end}^{L}.")]
    nums = [C.Number("first_nonzero_index", s), C.Number("last_nonzero_index", e)]
    if (s, e) == (-6 * (2 ** L - 1), 5 * (2 ** L - 1)):
        return C.certified(f"After {L} step(s) the nonzero points are P_{s} .. P_{e} (for omega != 0).",
                           sharpness=f"exact condition: the end values are {_s(left)}, so the claim holds iff omega != 0; "
                                     f"for omega = 0 the support shrinks to [{it0.start}, {it0.end}].",
                           evidence=ev, numbers=nums)
    return C.refuted(f"the nonzero points are P_{s} .. P_{e}", f"P_{s}^{L} .. P_{e}^{L}", evidence=ev, numbers=nums)
