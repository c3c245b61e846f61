"""Seed 004 as printed: the garbled text of the extraction (minus signs and fraction bars lost,
``7128`` is 7/128 or -7/128) that the claims compare with the derivations.

The readings of the rules (3.1)-(3.8) themselves are the catalogue's (:mod:`schemes.seed004`);
here are the printed displacements (3.3)-(3.4), the coefficient lists of (3.6)-(3.8), the 10x10
matrix after (3.6) and the boundary rules (3.9)-(3.10) (the statements as printed are in
``paper.toml``).

Examples
--------
>>> from papers.seed004.transcription import PRINTED_END_RULES, _matrix_rows_printed
>>> PRINTED_END_RULES["P0"][0]
('21μ+7ν+21ω+91', '0')
>>> _matrix_rows_printed()[6][3:9]           # row 7 prints a2 where (3.6) has a1
[5, 3, 2, -1, -3, -5]
"""

from __future__ import annotations

from schemes.seed004 import MU, NU, OMEGA, RULE_3_3


#: the Greek letters of the extracted text
_GREEK = {"μ": MU, "ν": NU, "ω": OMEGA}


# -------------------------------------------------------------------------- (3.3), (3.4)
_PRINTED_3_3 = {
    "D_{2i}": ("21128Pi1k+35128Pik7128Pi+1k7128Pi+2k", RULE_3_3.even, -1),
    "D_{2i+1}": ("7128Pi1k7128Pik+35128Pi+1k21128Pi+2k", RULE_3_3.odd, -1),
}
_PRINTED_3_4 = {
    "D_{2i-2}": ("21128Pi2k+35128Pi1k7128Pik7128Pi+1k", RULE_3_3.even, -2),
    "D_{2i-1}": ("7128Pi2k7128Pi1k+35128Pik21128Pi+1k", RULE_3_3.odd, -2),
    "D_{2i+2}": ("21128Pik+35128Pi+1k7128Pi+2k7128Pi+3k", RULE_3_3.even, 0),
    "D_{2i+3}": ("7128Pik7128Pi+1k+35128Pi+2k21128Pi+3k", RULE_3_3.odd, 0),
}


# -------------------------------------------------------------------------- (3.6) and the matrix
_PRINTED_3_6 = {5: "a5=a4=21128μ", 3: "a3=a2=712835128μ+21128ν", 1: "a1=a0=105128+7128μ35128ν+21128ω",
                -1: "a1=a2=35128+7128μ+7128ν35128ω", -3: "a3=a4=5128+7128ν+7128ω", -5: "a5=a6=7128ω"}


#: The printed 10x10 matrix after (3.6), as the labels of its rows (0 = empty entry).
_PRINTED_MATRIX = ("a5a3a1a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a5"
                   "0000a6a4a2a0a2a400000a5a3a2a1a3a50000a6a4a2a0a2a400000a5a3a1a1a3a50000a6a4a2a0a2a4")
_EVEN_LABELS = (5, 3, 1, -1, -3, -5)
_ODD_LABELS = (6, 4, 2, 0, -2, -4)


def _matrix_rows_printed():
    """The printed rows, labels read by position (the lost minus signs of labels restored by
    the pattern a5 a3 a1 a-1 a-3 a-5 / a6 a4 a2 a0 a-2 a-4 wherever the magnitudes match)."""
    import re
    toks = re.findall(r"a\d|0", _PRINTED_MATRIX)
    rows, k = [], 0
    for r in range(10):
        lead = r // 2
        row = [None] * 10
        expect = _EVEN_LABELS if r % 2 == 0 else _ODD_LABELS
        k += lead if r else 0
        mags = toks[k:k + 6]
        k += 6 + (10 - lead - 6)
        for j, (tok, lab) in enumerate(zip(mags, expect)):
            row[lead + j] = lab if tok == f"a{abs(lab)}" else int(tok[1:])
        rows.append(row)
    return rows


# -------------------------------------------------------------------------- (3.7), (3.8)
_PRINTED_3_7 = {3: "t3=t2=7128+21128ν", 1: "t1=t0=10512835128ν", -1: "t1=t2=35128+7128ν",
                -3: "t3=t4=5128+7128ν"}
_PRINTED_3_8 = {5: "5=4=21128μ", 3: "3=2=76477128μ", 1: "1=0=3564+4964μ", -1: "1=2=21642164μ",
                -3: "3=4=1647128μ", -5: "5=6=7128μ"}


# -------------------------------------------------------------------------- (3.9)-(3.10) end rules
def _ix(label: str) -> tuple[str, int]:
    if label.startswith("n"):
        return ("n", int(label[1:] or 0))
    return ("0", int(label))


#: The printed boundary rules: (lhs, [(garbled coefficient of 1/128[...], point index), ...]).
PRINTED_END_RULES = {
    "P0": [("21μ+7ν+21ω+91", "0"), ("42+42μ14ν35ω", "1"), ("21μ+7ν+7ω5", "2"), ("7ω", "3")],
    "P1": [("7μ+21ν7ω+25", "0"), ("7μ42ν+14ω+110", "1"), ("35μ+21ν7ω7", "2"), ("21μ", "3")],
    "P2": [("7μ+21ν7", "0"), ("14μ35ν+21ω+105", "1"), ("7μ+7ν35ω+35", "2"), ("7ν+7ω5", "3"), ("7ω", "4")],
    "P3": [("7ν+21ω5", "0"), ("7μ+7ν42ω+35", "1"), ("7μ35ν+21ω+105", "2"), ("35μ+21ν7", "3"), ("21μ", "4")],
    "P2n-4": [("21μ", "n-4"), ("35μ+21ν7", "n-3"), ("7μ35ν+21ω+105", "n-2"), ("7μ+7ν42ω+35", "n-1"),
              ("7ν+7ω5", "n")],
    "P2n-3": [("7ω", "n-4"), ("7ν+7ω5", "n-3"), ("7μ+7ν35ω+35", "n-2"), ("14μ35ν+21ω+105", "n-1"),
              ("7μ+21ν7", "n")],
    "P2n-2": [("21μ", "n-3"), ("35μ+21ν7ω7", "n-2"), ("7μ42ν+14ω+110", "n-1"), ("7μ+21ν7ω+25", "n")],
    "P2n-1": [("7ω", "n-3"), ("21μ+7ν+7ω5", "n-2"), ("42μ+14ν35ω+14", "n-1"), ("21μ+7ν+21ω+91", "n")],
    "P2n": [("7μ", "n-3"), ("21μ7ν7ω+5", "n-2"), ("42μ42ν+35ω42", "n-1"), ("21μ7ν21ω+165", "n")],
    "P2n+1": [("21μ", "n-3"), ("35μ21ν+7ω+7", "n-2"), ("7μ+42ν14ω110", "n-1"), ("7μ21ν+7ω+231", "n")],
}
