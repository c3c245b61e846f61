"""The pieces of Zorin's cell test of the modified butterfly (analysis/vertex/zorin.py) that are cheap to check:
the cover of the fundamental annulus, the exact eigen-structure argument, the verdict's sign consistency, the
CLI's opt-in. (The whole test takes 3-12 s per valence after a one-off 10 s: docs/vertices.md gives the command and
timings; tests/test_vertex_defectsum.py runs it on a small annulus.)"""

import dataclasses
import subprocess
import sys
from fractions import Fraction

import pytest

from analysis.result import AnalysisError
from analysis.vertex.rules import Term, modified_butterfly_rules
from analysis.vertex.zorin import (_verdict, annulus_cells, covers_annulus, modified_butterfly_zorin,
                                   outer_rings_nilpotent)


@pytest.mark.parametrize("lo", [2, 3, 4, 5, 8])
def test_cells_cover_the_annulus(lo):
    """With the cells lo - 1 <= x + y <= 2 lo - 1 every lattice triangle of sector 0 between rings lo and 2 lo
    is half of a cell; without the band x + y = lo - 1 the triangles with an edge on ring lo are missed."""
    hi = 2 * lo
    cells = annulus_cells(lo, hi)
    assert all(x >= 0 and y >= 0 and lo - 1 <= x + y <= hi - 1 for x, y in cells)
    assert len(cells) == sum(s + 1 for s in range(lo - 1, hi))
    assert covers_annulus(cells, lo, hi)
    assert not covers_annulus([c for c in cells if sum(c) >= lo], lo, hi)
    assert not covers_annulus([c for c in cells if sum(c) <= hi - 2], lo, hi)     # the outer band too
    assert not covers_annulus([c for c in cells if c != (lo - 1, 0)], lo, hi)     # one cell on the sector edge


def test_annulus_must_double():
    """Phi(x/2) = Phi(x)/2 carries the annulus lo..2 lo to the punctured plane; any other annulus is refused
    (before any Arb work)."""
    with pytest.raises(AnalysisError, match="lo..2 lo"):
        modified_butterfly_zorin(5, lo=8, hi=15)


@pytest.mark.parametrize("n", [5, 7])
def test_outer_rings_nilpotent(n):
    """The 24-ring rules extend the 3-ring rules and every point beyond ring 3 uses only inner rings; a rule
    that reads its own ring, or a 3-ring rule that differs, is caught."""
    inner, rules = modified_butterfly_rules(3, n), modified_butterfly_rules(24, n)
    assert outer_rings_nilpotent(rules, inner)
    sect = list(rules.sector_rules())
    i4 = next(i for i, c in enumerate(rules.coords) if sum(c) == 4)
    j4 = next(i for i, c in enumerate(rules.coords) if sum(c) == 4 and i != i4)
    sect[i4] = sect[i4] + (Term(Fraction(0), (j4, 0)),)                        # a source on its own ring
    bad = dataclasses.replace(rules, rules=(rules.rules[0],) + tuple(sect))
    assert not outer_rings_nilpotent(bad, inner)
    assert not outer_rings_nilpotent(rules, modified_butterfly_rules(3, n, Fraction(1, 32)))


def test_eigenvector_is_exact_eigenvector_on_more_rings():
    """Step 0's consequence, checked on the 8-ring (block size 36): the enclosure solves every equation of
    (B - I/2) v = 0 (also the one the solve dropped) and extends the 3-ring eigenvector."""
    from flint import acb, ctx, fmpq

    from analysis.vertex.blocks import fourier_block
    from analysis.vertex.charmap import _acb_entry, eigenvector

    n = 5
    old = ctx.prec
    ctx.prec = 128
    try:
        half = acb(fmpq(1, 2))
        rules, inner = modified_butterfly_rules(8, n), modified_butterfly_rules(3, n)
        assert outer_rings_nilpotent(rules, inner)
        v, v3 = eigenvector(rules, n, half), eigenvector(inner, n, half)
        B = fourier_block(rules, 1, n)
        m = B.rows
        for i in range(m):
            row = sum((_acb_entry(B[i, j], n, 1) * v[j] for j in range(m)), acb(0)) - half * v[i]
            assert row.contains(0) and abs(row).upper() < 1e-30
        assert all(a.overlaps(b) for a, b in zip(v[:6], v3))
        assert not v[0].overlaps(v[1])                                          # not a vacuous comparison
    finally:
        ctx.prec = old


def test_verdict_needs_every_step_and_a_consistent_sign():
    """Certified only with every step proven and the mask's sign -1 (positive in the chart, as the winding
    requires); a positive mask sign is a contradiction and leaves the result inconclusive."""
    ok = {"cover": True, "regular": True, "winding": True, "jacobian_sign_mask": -1}
    r = _verdict(5, ok, True)
    assert r.status == "certified" and r.value is True
    assert "C^1 for generic initial data (Reif's criterion), certified" in r.provenance["message"]
    assert "regular case" in _verdict(6, ok, True).provenance["message"]
    assert "regular case" not in r.provenance["message"]
    flipped = _verdict(5, dict(ok, jacobian_sign_mask=1), True)
    assert flipped.status == "inconclusive" and "agreeing with the winding" in flipped.provenance["message"]
    for key in ("cover", "regular", "winding"):
        assert _verdict(5, dict(ok, **{key: False}), True).status == "inconclusive"
    assert _verdict(5, ok, False).status == "inconclusive"


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "analysis", "vertex", *args], capture_output=True, text=True,
                          cwd=__import__("pathlib").Path(__file__).resolve().parents[1])


def test_cli_cells_is_an_opt_in_for_the_modified_butterfly():
    r = _cli("--scheme", "loop", "--valence", "5", "--charmap-cells")
    assert r.returncode == 2 and r.stderr.startswith("subdiv: error: --charmap-cells applies to")
    r = _cli("--scheme", "modified-butterfly", "--valence", "3..30", "--charmap-cells")
    assert r.returncode == 2 and "at most 16 valences" in r.stderr


def test_cli_cells_line():
    """The line printed under a valence names the verdict, the cells, the sign and the winding."""
    from analysis.cli.vertex import _cells_line

    wit = {"cells": "108 of 108", "annulus": [8, 16], "cover": True, "jacobian_sign_mask": -1, "winding": True,
           "subcells": 108}
    line = _cells_line({"status": "certified", "witness": wit, "provenance": {"message": "x"}})
    assert "C^1 for generic initial data (Reif's criterion) [certified]: 108 of 108 cells of rings 8..16" in line
    assert "positive in the chart, winds once" in line
    line = _cells_line({"status": "inconclusive", "witness": dict(wit, winding=False, jacobian_sign_mask=None),
                        "provenance": {"message": "not every step was proven: the winding number"}})
    assert "not every step was proven: the winding number [inconclusive]" in line
    assert "not one sign" in line and "winding not proven" in line


def test_the_regular_mask_is_the_catalogue_butterfly():
    """zorin.py builds the regular part from the vertex rules' stencil (the engine does not import the
    catalogue); it must be the catalogue's butterfly mask, coefficient for coefficient, at any tension."""
    from schemes.surfaces import get

    from analysis.vertex.zorin import regular_butterfly_mask

    for w in ("1/16", "1/20", "-1/7"):
        assert dict(regular_butterfly_mask(w).coeffs) == dict(get("butterfly").mask(w=w).coeffs)


def test_summary_counts_a_valence_the_cell_test_certified():
    """The summary's C^1 line: a valence certified by Zorin's cell test is certified there (not "inconclusive at
    every valence" next to the cell test's certificate); the other valences keep their own status."""
    from analysis.cli.vertex import _summary

    def entry(n, c1, cells=None):
        e = {"n": n, "reif": {"value": True}, "curvature": {"value": "not applicable"}, "c1": {"status": c1}}
        if cells:
            e["charmap_cells"] = {"status": cells}
        return e

    text = _summary("modified-butterfly", {}, [entry(3, "inconclusive", "inconclusive"), entry(5, "inconclusive", "certified")],
                    "triangle")
    line = next(t.strip() for t in text.splitlines() if t.strip().startswith("C^1:"))
    assert line.startswith("C^1: certified (for generic initial data, Zorin's cell test) at n = 5; inconclusive at n = 3")
    text = _summary("modified-butterfly", {}, [entry(5, "inconclusive", "certified")], "triangle")
    assert "C^1: certified at every valence" in text
    text = _summary("butterfly", {}, [entry(3, "refuted"), entry(4, "inconclusive")], "triangle")
    assert "C^1: refuted (not C^1 for generic initial data, certified) at n = 3; inconclusive at n = 4" in text
