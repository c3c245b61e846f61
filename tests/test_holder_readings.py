"""Issue 9, items 5-7 and C^k from enclosures: closed-form masks (nested radicals, I), masks
copied from decimal tables (--approx), non-convergent schemes as certified results."""

from __future__ import annotations

import csv
import functools
import json
import time
from fractions import Fraction
from math import comb
from pathlib import Path

import flint
import pytest
import sympy as sp

from analysis.cli import main
from analysis.algebra.closed_form import ClosedFormMask
from analysis.algebra.zero_test import is_zero
from analysis.regularity import NotConvergent, difference_mask, holder_exponent, smoothness
from analysis.result import AnalysisError
from analysis.algebra.symbol import LaurentSymbol
from schemes.wavelets import daubechies_enclosure


def _json(capsys, argv):
    assert main(argv + ["--json"]) == 0
    return json.loads(capsys.readouterr().out)


def _interval(alpha):
    return sp.Rational(alpha["lower"]), sp.Rational(alpha["upper"])


# ------------------------------------------------------------------ closed forms (item 5)

def _d6_real_radicals() -> list[str]:
    """D6 as a user types it: a = sqrt(2) h, h = (...)/(16 sqrt 2) (Daubechies' radicals)."""
    s = "sqrt(5+2*sqrt(10))"
    return [f"(1+sqrt(10)+{s})/16", f"(5+sqrt(10)+3*{s})/16", f"(10-2*sqrt(10)+2*{s})/16",
            f"(10-2*sqrt(10)-2*{s})/16", f"(5+sqrt(10)-3*{s})/16", f"(1+sqrt(10)-{s})/16"]


def _daubechies_radicals(N: int) -> list[str]:
    """Small generator: sympy's radical roots of the spectral factorisation (with I that cancels);
    a fresh list each call (the tests edit it), from one computation per process."""
    return list(_daubechies_radicals_once(N))


@functools.lru_cache(maxsize=None)
def _daubechies_radicals_once(N: int) -> tuple[str, ...]:
    """:func:`_daubechies_radicals`, computed once per ``N`` (printing the D8 radicals takes seconds)."""
    y = sp.Symbol("y")
    ys = sp.roots(sp.Poly(sum(comb(N - 1 + k, k) * y**k for k in range(N)), y), multiple=True)
    zs = []
    for yk in ys:
        w = 2 - 4 * yk
        zs.append(next(zc for zc in ((w + sg * sp.sqrt(w**2 - 4)) / 2 for sg in (1, -1))
                       if abs(complex(sp.N(zc, 30))) > 1))
    c = [sp.Integer(1)]
    for zc in zs:
        c = [(c[i - 1] if i else 0) - (zc * c[i] if i < len(c) else 0) for i in range(len(c) + 1)]
    den = sp.Mul(*[1 - zc for zc in zs])
    return tuple(sp.sstr(2 * sum(comb(N, i - j) * c[j] for j in range(len(c)) if 0 <= i - j <= N) / (2**N * den))
                 for i in range(N + len(c)))


def _certified_like_catalogue(capsys, mask, slug):
    """`subdiv holder --mask` on a closed form: certified within 15 s, a tight enclosure that
    overlaps the catalogue's ball value of the same scheme; returns the alpha JSON."""
    ref = _interval(_json(capsys, ["holder", "--scheme", slug])["alpha"])
    t = time.perf_counter()
    alpha = _json(capsys, ["holder", "--mask", ",".join(mask), "--start", "0"])["alpha"]
    assert time.perf_counter() - t < 15
    assert alpha["status"] == "certified" and alpha["convergent"] is True
    lo, hi = _interval(alpha)
    assert lo <= ref[1] and ref[0] <= hi and float(hi - lo) < 1e-8
    return alpha


def test_masks_with_nested_radicals_finish(capsys):
    """Item 5: D6 in closed form (sqrt(10), sqrt(5+2 sqrt 10)) certifies via the CLI within a few
    seconds and overlaps the catalogue's ball version; so does sympy's radical form with I."""
    for mask in (_d6_real_radicals(), _daubechies_radicals(3)):
        _certified_like_catalogue(capsys, mask, "d6")
    # the I-form goes the ball route, N decided exactly and said so
    cf = ClosedFormMask(_daubechies_radicals(3))
    assert cf.sum_rules == 3 and any("decided exactly" in h for h in cf.how)
    assert any("proven real" in h for h in cf.how)
    h = holder_exponent(cf, budget=10000)
    assert "enclosed in Arb balls" in h.provenance["source"]


def test_closed_form_zero_test_and_rejections(capsys):
    assert is_zero(sp.sqrt(2) * sp.sqrt(5) - sp.sqrt(10))
    assert not is_zero(sp.sqrt(2) - sp.Rational(665857, 470832))         # 1e-12 away, not zero
    assert is_zero(sp.sqrt(5 + 2 * sp.sqrt(6)) - sp.sqrt(2) - sp.sqrt(3))
    with pytest.raises(AnalysisError, match="not real"):
        ClosedFormMask(["(1+sqrt(3))/4", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3)*I)/4"])
    assert main(["holder", "--mask", "(1+sqrt(3))/4,(3+sqrt(3))/4,(3-sqrt(3))/4,(1-sqrt(3)*I)/4"]) == 2
    assert "not real" in capsys.readouterr().err
    # a perturbed closed form: the sum rule fails, exactly
    bad = _daubechies_radicals(3)
    bad[0] = f"({bad[0]}) + sqrt(2)/10**30"
    assert ClosedFormMask(bad).failure is not None


def test_daubechies_d8_closed_form_certifies(capsys):
    """Masks with nested radicals do not finish: D8 typed in closed form (sympy's radical roots of
    the spectral factorisation -- Cardano with I, a cube root, nested square roots; degree bound
    192) certifies through the CLI, overlaps the catalogue's ball version and says how N and the
    reality of the coefficients were proven."""
    alpha = _certified_like_catalogue(capsys, _daubechies_radicals(4), "d8")
    assert abs(float(sp.Rational(alpha["lower"])) - 1.6179263111) < 1e-9
    src = alpha["provenance"]["source"]
    assert "N = 4 decided exactly" in src and "proven real" in src and "formal identity" in src
    assert "enclosed in Arb balls" in src


def test_daubechies_d8_wrong_closed_form_is_never_certified(capsys):
    """A deliberately wrong D8 closed form (one coefficient off by sqrt(2)/10**40) is not
    convergent [certified] (or inconclusive) -- never a certified alpha; so is one whose a(1) = 2
    still holds exactly but a(-1) = 2 sqrt(2)/10**100 (invisible at 256 bits: the formal identity
    fails and the root-separation step finds the nonzero ball)."""
    mask = _daubechies_radicals(4)
    bad = list(mask)
    bad[0] = f"({bad[0]}) + sqrt(2)/10**40"
    alpha = _json(capsys, ["holder", "--mask", ",".join(bad), "--start", "0"])["alpha"]
    assert alpha.get("lower") is None and alpha.get("upper") is None
    assert alpha["status"] in ("certified", "inconclusive") and alpha.get("convergent") is not True
    if alpha["status"] == "certified":
        assert alpha["convergent"] is False and "a(1) - 2 in [1.41421356237e-40 +/- " in alpha["reason"]
    assert main(["holder", "--mask", ",".join(bad), "--start", "0"]) == 0
    assert "not convergent [certified]" in capsys.readouterr().out
    bad = list(mask)
    bad[0] = f"({bad[0]}) + sqrt(2)/10**100"
    bad[1] = f"({bad[1]}) - sqrt(2)/10**100"
    cf = ClosedFormMask(bad)
    assert cf.undecided is None and cf.failure is not None
    assert "a(-1) in [2.82842712475e-100 +/- " in cf.failure
    with pytest.raises(NotConvergent):
        holder_exponent(cf, budget=5000)
    # a true identity that is neither formal (it needs Vieta: the roots of the D12 quintic sum to
    # -1/2) nor within the root-separation budget (degree <= 23040): inconclusive, with the reason
    roots = "+".join(f"CRootOf(252*x**5 + 126*x**4 + 56*x**3 + 21*x**2 + 6*x + 1, {j})" for j in range(5))
    und = [f"(1+sqrt(3))/4 + ({roots} + 1/2)*({mask[3]})", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3))/4"]
    alpha = _json(capsys, ["holder", "--mask", ",".join(und), "--start", "0"])["alpha"]
    assert alpha["status"] == "inconclusive" and alpha.get("lower") is None
    assert "not a formal identity" in alpha["reason"] and "root-separation bound" in alpha["reason"]


def test_closed_form_branch_cut_and_conjugate_rewrites():
    """The zero test's building blocks: a base exactly on the branch cut written with I, Cardano's
    cube root in the casus irreducibilis (conj(C) = rho / C, proven), conjugate CRootOf pairs, and
    the root-separation fallback with its (tightened) degree bound."""
    from analysis.algebra.expressions import _ir, _sub, degree_bound
    from analysis.algebra.zero_test import _Algebra

    cut = sp.sqrt(sp.Mul(1 + sp.I, sp.I - 1, evaluate=False))          # sqrt(-2) = I sqrt(2)
    assert is_zero(cut - sp.I * sp.sqrt(2)) and not is_zero(cut + sp.I * sp.sqrt(2))
    assert is_zero(sp.Pow(sp.Mul(-1, 8, evaluate=False), sp.Rational(1, 3)) - 1 - sp.sqrt(3) * sp.I)
    C = (sp.Rational(-9, 109760) + 3 * sp.sqrt(15) * sp.I / 78400) ** sp.Rational(1, 3)
    node = _ir(2 * C + sp.Rational(3, 490) / C, {})                      # real, written with I
    alg = _Algebra()
    alg.register([node])
    assert alg.is_real(node) and any("3/980" in s for s in alg.identities)
    assert alg.zero(_sub(node, alg.conj(node)))[1]["method"] == "formal"
    x = sp.Symbol("x")
    r = [sp.CRootOf(x**3 - 2, j) for j in range(3)]
    node = _ir(r[1] * r[2] - r[0] ** 2, {})
    alg = _Algebra()
    assert alg.zero(node)[0] and alg.conj(_ir(r[1], {})) == _ir(r[2], {})
    assert degree_bound(_ir(r[0] + r[1] + r[2] + sp.sqrt(3), {})) == 12      # 3! * 2
    # a mask whose coefficients carry a complex CRootOf pair (sum of all roots = 0): real, and
    # a(1) = 2 needs the root-separation step (no formal identity: sum of roots is Vieta)
    s = "+".join(f"CRootOf(x**3 - 2, {j})" for j in range(3))
    cf = ClosedFormMask([f"(1+sqrt(3))/4 + ({s})", "(3+sqrt(3))/4", "(3-sqrt(3))/4", "(1-sqrt(3))/4"])
    assert cf.undecided is None and cf.failure is None and cf.sum_rules == 2
    assert any("proven real" in h for h in cf.how) and "separation" in cf.algebra.methods


# ------------------------------------------------------------------ tables (item 6)

def _d8_digits(d: int) -> list[str]:
    return [b.mid().str(d, radius=False) for b in daubechies_enclosure(4, 200)]


def test_masks_copied_from_tables(capsys):
    mask = ",".join(_d8_digits(43))
    # exact reading: the typed mask itself does not converge (certified), with the hint
    assert main(["holder", "--mask", mask]) == 0
    text = capsys.readouterr().out
    assert "not convergent [certified]" in text and "below the resolution" in text and "--approx" in text
    # approximate reading: certified, agrees with the catalogue
    ref = _interval(_json(capsys, ["holder", "--scheme", "d8"])["alpha"])
    alpha = _json(capsys, ["holder", "--mask", mask, "--approx"])["alpha"]
    assert alpha["status"] == "certified"
    lo, hi = _interval(alpha)
    assert lo <= ref[1] and ref[0] <= hi and abs(float(lo) - 1.6179263111) < 1e-9
    # the witness mask of that result (exact rationals in the JSON): exact, in the balls, with a(1) = 2 and
    # (1+z)^N | a
    from analysis.algebra.approx import typed_radius

    N, w = alpha["witness"]["sum_rules"], [Fraction(x) for x in alpha["witness"]["witness_mask"]]
    assert N == 4
    assert sum(w) == 2 and all(sum((-1) ** k * k**j * x for k, x in enumerate(w)) == 0 for j in range(N))
    for x, s in zip(w, mask.split(",")):
        assert abs(Fraction(str(x)) - Fraction(s)) <= typed_radius(s)
    assert 0 < Fraction(alpha["witness"]["max_deviation_in_radii"]) <= 1


def test_table_normalised_to_sqrt2_says_so(capsys):
    rows = list(csv.DictReader((Path(__file__).parent / "data" / "daubechies_masks_published.csv").open()))
    assert main(["holder", "--mask", ",".join(r["h_k"] for r in rows)]) == 0
    out = capsys.readouterr().out
    assert "not convergent [certified]" in out and "sqrt(2)" in out and "multiply" in out
    assert main(["holder", "--scheme", "d8", "--approx"]) == 2


# ------------------------------------------------------------------ non-convergent (item 7)

def test_non_convergent_scheme_is_a_result(capsys):
    assert main(["holder", "--mask", "1/4,1/2,1,1/4"]) == 0
    out = capsys.readouterr().out
    assert "not convergent [certified]: a(-1) = 1/2 != 0" in out
    assert main(["holder", "--mask", "1/4,1/2,1,1/4", "--C", "1"]) == 0
    assert "C^1: no   [certified] — not convergent: a(-1) = 1/2 != 0" in capsys.readouterr().out
    data = _json(capsys, ["holder", "--mask", "1/2,1/2,1,1/2"])
    assert data["alpha"]["status"] == "certified" and data["alpha"]["convergent"] is False
    assert "a(1) = 5/2 != 2" in data["alpha"]["reason"]
    assert main(["holder", "--mask", "1/4,(1+"]) == 2                      # malformed input
    a = LaurentSymbol.from_mask(["1/4", "1/2", "1", "1/4"])
    with pytest.raises(NotConvergent) as exc:
        difference_mask(a)
    assert isinstance(exc.value, AnalysisError) and exc.value.reason == "a(-1) = 1/2 != 0"
    s = smoothness(a, 0)
    assert s.value is False and s.status == "certified" and "a(-1) = 1/2" in s.witness["reason"]
    with pytest.raises(AnalysisError):
        holder_exponent(a)


def test_ck_from_certified_enclosure(capsys):
    d = _json(capsys, ["holder", "--scheme", "d6", "--C", "1"])["smoothness"]
    assert d["value"] is True and d["status"] == "certified"
    d = _json(capsys, ["holder", "--scheme", "d6", "--C", "2"])["smoothness"]
    assert d["value"] is False and d["status"] == "certified"


# ------------------------------------------------------------------ tables as people copy them

#: PyWavelets 1.x, ``pywt.Wavelet("db4").dec_lo`` as ``repr`` prints it (4 vanishing moments, our D8;
#: normalised to sum sqrt(2), in reverse order): the doubles are within half an ulp of the true filter.
PYWT_DB4 = ["-0.010597401785069032", "0.0328830116668852", "0.030841381835560764", "-0.18703481171909309",
            "-0.027983769416859854", "0.6308807679298589", "0.7148465705529157", "0.2303778133088965"]


def test_d8_from_a_42_digit_table_is_never_certified_wrong(capsys):
    """At 42 digits the true D8 sits at 0.998 radii: the least-norm correction of order 4 leaves the
    balls, the Chebyshev one does not. Before, N = 1 was taken and alpha in [0.99999, 1.0000]
    was 'certified' -- the ceiling N of k - log2 rho, not the exponent of D8 (1.6179)."""
    alpha = _json(capsys, ["holder", "--mask", ",".join(_d8_digits(42)), "--approx"])["alpha"]
    lo, hi = _interval(alpha)
    assert alpha["status"] == "certified" and alpha["witness"]["sum_rules"] == 4
    assert lo < 1.6179263112 and hi > 1.6179263111 and float(hi - lo) < 1e-8
    every = alpha["witness"]["every_convergent_mask"]            # what holds for every mask in the balls
    assert every["status"] == "certified" and 0.9 < float(sp.Rational(every["lower"])) <= 1


def test_the_ceiling_of_a_partial_factorisation_is_only_a_lower_bound():
    """With fewer factors than the masks in the balls may have, k - log2 rho(c_k) = min(alpha, k+1):
    reaching k + 1 = N gives alpha >= lower only (cubic B-spline, alpha = 3, read with N = 1)."""
    from analysis.algebra.approx import ApproximateMask
    from analysis.regularity import holder_exponent

    m = ApproximateMask(["0.125", "0.5", "0.75", "0.5", "0.125"])
    assert m.sum_rules == 4
    m.sum_rules = 1
    r = holder_exponent(m, budget=1000)      # the polytope does not close (budget 5000 neither): the same bounds
    assert r.upper is None and r.value is None and float(r.lower) <= 1 and r.witness["ceiling_reached"]
    assert "lower" in r.provenance["message"] or ">=" in r.provenance["message"]


def test_pywavelets_filter_as_pasted(capsys):
    """Doubles with sum sqrt(2), pasted as printed: read as the mask times sqrt(2), 4 ulps each, and
    the same alpha as the catalogue's D8; the same through numpy floats in Python."""
    import numpy as np

    from analysis.algebra.approx import ApproximateMask

    alpha = _json(capsys, ["holder", "--mask", ",".join(PYWT_DB4), "--approx"])["alpha"]
    ref = _interval(_json(capsys, ["holder", "--scheme", "d8"])["alpha"])
    lo, hi = _interval(alpha)
    assert alpha["status"] == "certified" and alpha["witness"]["normalisation"] == "sqrt(2)"
    assert lo <= ref[1] and ref[0] <= hi
    m = ApproximateMask(np.array([float(x) for x in PYWT_DB4]))
    assert m.sum_rules == 4 and m.normalisation == "sqrt(2)"
    # a radius given by the user
    assert main(["holder", "--mask", ",".join(PYWT_DB4), "--approx", "--approx-radius", "1e-15", "--json"]) == 0
    assert "radius 1/1000000000000000" in json.loads(capsys.readouterr().out)["alpha"]["provenance"]["message"]
