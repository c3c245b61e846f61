"""The product tree (certified bounds when no invariant polytope closes) and ``subdiv jsr FILE``."""

from __future__ import annotations

import json

import numpy as np
import pytest
import sympy as sp

from analysis.cli.main import main
from analysis.jsr import brute_force_bounds, jsr_bounds
from analysis.jsr._exact import parse_family
from analysis.jsr._tree import tree_bounds
from analysis.jsr._work import Work

PHI = (1 + sp.sqrt(5)) / 2
GOLDEN = [[[1, 1], [0, 1]], [[1, 0], [1, 1]]]


def signed_pair(seed: int, n: int) -> list:
    """A random signed integer pair (the generator of the hard benchmark families)."""
    A = np.random.default_rng(seed).integers(-9, 10, size=(2, n, n))
    return [A[0].tolist(), A[1].tolist()]


def test_tree_bound_encloses_every_product_and_tightens_with_work():
    F = parse_family(signed_pair(1, 8))
    bf = brute_force_bounds(F.floats, 10)
    small = tree_bounds(F, Work(100), lower_hint=bf["lower"], rel_gap=1e-6)
    large = tree_bounds(F, Work(600), lower_hint=bf["lower"], rel_gap=1e-6)
    # rigorous upper bounds lie above every spectral radius of a product ...
    assert float(small.upper) >= bf["lower"] and float(large.upper) >= large.float_lower
    # ... and the certified value is the float bound up to rounding
    assert abs(float(large.upper) / large.float_upper - 1) < 1e-9
    assert large.upper <= small.upper


def test_hard_signed_pair_beats_brute_force_in_the_same_work():
    """The invariant polytope does not close on this family; the certified interval within a
    budget of 1500 units (~1 s) is tighter than the float brute force over all 2^12 products in
    the sum-of-squares norm (~0.15 s), and than the plain infinity norm at length 14 (~0.4 s)."""
    mats = signed_pair(1, 8)
    r = jsr_bounds(mats, budget=1500)
    assert r.status == "inconclusive" and r.lower < r.upper
    gap = float(r.upper / r.lower - 1)
    bf = brute_force_bounds(parse_family(mats).floats, 12, norm="balanced")
    assert gap < bf["upper"] / bf["lower"] - 1
    assert gap < 0.03
    assert "product_tree" in r.witness and "s.m.p." in r.provenance["message"]


def _run(tmp_path, capsys, payload, *args) -> tuple[int, str, str]:
    path = tmp_path / "family.json"
    if isinstance(payload, bytes):
        path.write_bytes(payload)
    else:
        path.write_text(payload if isinstance(payload, str) else json.dumps(payload))
    code = main(["jsr", str(path), *args])
    out = capsys.readouterr()
    return code or 0, out.out, out.err


def test_cli_golden_pair_certified(tmp_path, capsys):
    code, out, _ = _run(tmp_path, capsys, GOLDEN, "--json")
    assert code == 0
    doc = json.loads(out)
    assert doc["status"] == "certified" and doc["smp_candidate"] == [0, 1]
    lo, hi = sp.Rational(doc["lower"]), sp.Rational(doc["upper"])
    assert lo <= PHI <= hi and hi / lo - 1 < sp.Rational(1, 10 ** 12)


def test_cli_text_single_matrix_is_exact(tmp_path, capsys):
    code, out, _ = _run(tmp_path, capsys, [[[2, 1], [0, "1/3"]]])
    assert code == 0
    assert "exact value: JSR = 2" in out and "certified" in out


@pytest.mark.parametrize("payload, message", [
    ("[[[1, 2]]]", "not square"),
    ("[[[1, 0], [0, 1]], [[1]]]", "one size"),
    ('[[["x"]]]', "unknown name 'x'"),
    ("[[[true]]]", "write a number"),
    ("[[1, 2]", "is not JSON"),
    (json.dumps([[[1]]] * 17), "at most 16"),
    ("[[[1e308]]]", "limited to 1e-50 <= |x| <= 1e50"),
    ('[[[1, "1/10**51"], [0, 1]]]', "limited to 1e-50 <= |x| <= 1e50"),
    (b"\x93NUMPY\x01\x00v\x00", "not a text file (not UTF-8): write the file as a JSON list"),
], ids=["not-square", "sizes", "name", "bool", "syntax", "too-many", "huge", "tiny", "binary"])
def test_cli_errors_are_one_line(tmp_path, capsys, payload, message):
    code, out, err = _run(tmp_path, capsys, payload)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("subdiv: error: ") and message in err
    code, out, _ = _run(tmp_path, capsys, payload, "--json")
    assert code == 2 and message in json.loads(out)["error"]["message"]


def test_cli_decimals_are_exact(tmp_path, capsys):
    code, out, _ = _run(tmp_path, capsys, "[[[0.1, 0], [0, 0.2]]]", "--json")
    assert code == 0 and json.loads(out)["exact_value"] == "1/5"


def test_cli_prints_a_jsr_of_1e17_and_more_in_exponent_notation(tmp_path, capsys):
    code, out, err = _run(tmp_path, capsys, [[[10 ** 17 + 1]], [[1]]])
    assert code == 0 and err == ""
    assert "JSR in [1.0000000000000000e+17, 1.0000000000000001e+17]   certified" in out
    code, out, err = _run(tmp_path, capsys, [[[1, 2], [3, "10**50"]], [["10**49", 0], [1, 1]]], "--json")
    doc = json.loads(out)
    assert code == 0 and err == "" and doc["status"] == "certified"
    assert sp.Rational(doc["lower"]) <= 10 ** 50 + 1 <= sp.Rational(doc["upper"])   # rho(A0) = 10^50 + 6/10^50 + ...
