"""The strip next to an exact end of a C^l set, closed exactly (analysis.bivariate.end_strip) and the invariant
polytope with exact vertices (analysis.jsr.exact_polytope)."""

from __future__ import annotations

from fractions import Fraction

from flint import fmpq, fmpq_mat

from analysis.bivariate.end_strip import close_end_strip
from analysis.jsr._polytope import build_polytope
from analysis.jsr._work import Work
from analysis.jsr.exact_polytope import exact_polytope_bound, floats

q = fmpq


def _family(quotient_slope):
    """``T_0(t) = [[t, 1/16, 1/8], [0, 1/8, 0], [0, 0, 1/5]]``, ``T_1(t) = [[1/8, 0, 0], [1/16, t, 1/8], [0, 0, 1/5 +
    s t]]``: the fixed eigenvectors ``e1``, ``e2`` of the eigenvalue ``t``, the invariant plane ``U = <e1, e2>``, the
    quotient ``(1/5, 1/5 + s t)``."""
    C0 = [fmpq_mat([[0, q(1, 16), q(1, 8)], [0, q(1, 8), 0], [0, 0, q(1, 5)]]),
          fmpq_mat([[q(1, 8), 0, 0], [q(1, 16), 0, q(1, 8)], [0, 0, q(1, 5)]])]
    C1 = [fmpq_mat([[1, 0, 0], [0, 0, 0], [0, 0, 0]]),
          fmpq_mat([[0, 0, 0], [0, 1, 0], [0, 0, quotient_slope]])]
    return [[C0[e], C1[e]] for e in range(2)]


def test_leading_plane_split_off_and_the_quotient_below_theta():
    r = close_end_strip(_family(q(1, 10)), q(1, 2), q(1, 2), q(1, 4), budget=20_000)
    assert r["closed"], r["reason"]
    assert r["letters"] == [0, 1] and r["lambda"] == "0 + 1*t" and r["leading_dimension"] == 2
    assert r["polytope_bound"] == 1                        # exactly: the roots are exact eigenvectors
    assert Fraction(str(r["quotient_upper"])) <= Fraction(1, 4) < Fraction(1, 2)


def test_a_quotient_at_theta_keeps_the_strip_open():
    # the quotient entry 1/5 + 3t/5 reaches 1/2 at t* = 1/2: the hull's quotient JSR is not below theta
    r = close_end_strip(_family(q(3, 5)), q(1, 2), q(1, 2), q(1, 4), budget=20_000)
    assert not r["closed"] and "quotient" in r["reason"]


def test_a_moving_eigenvector_is_refused():
    # T_0(t) = [[t, 0], [t - 1/2, 1/8]]: at t* = 1/2 the eigenvector (1, 0) for 1/2, which moves with t; the
    # tangent lambda(t) = t is the eigenvalue, but the hull's two leading eigenvectors give no finite polytope
    C = [[fmpq_mat([[0, 0], [q(-1, 2), q(1, 8)]]), fmpq_mat([[1, 0], [1, 0]])]]
    r = close_end_strip(C, q(1, 2), q(1, 2), q(1, 4), budget=5000)
    assert r["lambda_kind"] == "tangent" and r["lambda"] == "0 + 1*t"
    assert not r["closed"] and "polytope" in r["reason"]


def test_the_tangent_of_a_semisimple_double_eigenvalue():
    # T(t) = [[t, 0, 0], [0, t, 0], [t - 1/2, 0, 1/8]]: at t* = 1/2 the double eigenvalue 1/2 (eigenvectors e1,
    # e2; e1 moves with t), both branches with the derivative 1: the tangent lambda(t) = t
    C = [[fmpq_mat([[0, 0, 0], [0, 0, 0], [q(-1, 2), 0, q(1, 8)]]), fmpq_mat([[1, 0, 0], [0, 1, 0], [1, 0, 0]])]]
    r = close_end_strip(C, q(1, 2), q(1, 2), q(1, 4), budget=5000)
    assert r["lambda_kind"] == "tangent" and r["lambda"] == "0 + 1*t"


def test_no_letter_with_the_eigenvalue_at_the_end():
    C = [[fmpq_mat([[q(1, 8)]]), fmpq_mat([[q(1, 8)]])]]
    r = close_end_strip(C, q(1, 2), q(1, 2), q(1, 4), budget=1000)
    assert not r["closed"] and "no single letter" in r["reason"]


def _two():
    A = [fmpq_mat([[1, q(1, 4)], [0, q(1, 2)]]), fmpq_mat([[q(1, 2), 0], [q(1, 4), 1]])]
    roots = [[q(1), q(0)], [q(0), q(1)]]
    st = build_polytope(floats(A), 1.0, [[float(x) for x in u] for u in roots], work=Work(1000))
    assert st.closed
    return A, roots, st


def test_exact_bound_is_one_for_exact_eigenvectors():
    A, roots, st = _two()
    b = exact_polytope_bound(A, q(1), roots, st)
    assert b["bound"] == 1 and b["vertex_images"] >= 2


def test_exact_bound_exceeds_one_below_the_jsr():
    # scaled by 9/10 < JSR = 1: the roots' images are 10/9 times the roots, the bound says so exactly
    A, roots, st = _two()
    b = exact_polytope_bound(A, q(9, 10), roots, st)
    assert b["bound"] >= Fraction(10, 9)


def test_exact_bound_on_a_face_with_a_dependent_support():
    # the square absconv{e1, e2, e1 + e2, e1 - e2}: (1, 1)/... the image (1/2, 1/2) + (1/2, -1/2) = e1 lies in it;
    # an image on the edge between e1 + e2 and e1 - e2 (the point (1, 0) + (0, 1/3)) has norm exactly 1
    A = [fmpq_mat([[1, 0], [q(1, 3), 0]])]
    roots = [[q(1), q(1)], [q(1), q(-1)]]
    st = build_polytope(floats(A), 1.0, [[float(x) for x in u] for u in roots], work=Work(1000))
    b = exact_polytope_bound(A, q(1), roots, st)
    assert b["bound"] == 1


def test_cli_line_says_equal_or_at_most():
    import sympy as sp

    from analysis.cli.surface import _end_strip_line

    t = sp.Symbol("t")
    b = {"strip": {"from": sp.Rational(1, 2), "method": "m"}, "exact": sp.Rational(3, 4)}
    es = {"lambda": t + sp.Rational(1, 4), "lambda_kind": "eigenvalue", "letters": [0, 2], "leading_dimension": 7,
          "polytope_vertices": 14, "polytope_bound": 1, "quotient_upper": sp.Rational(1, 2)}
    line = _end_strip_line(0, "t", b, es, sp.sstr)
    assert "on t in [1/2, 3/4) the JSR is t + 1/4" in line and "the eigenvalue of T_0, T_2" in line
    assert "on the quotient the JSR is at most 0.5000 (certified)" in line
    b = {"strip": {"from": sp.Rational(1, 32), "method": "m"}, "exact": sp.Integer(0)}
    line = _end_strip_line(1, "w", b, {**es, "lambda_kind": "tangent", "quotient_upper": None}, sp.sstr)
    assert "on w in (0, 1/32] the JSR is at most" in line and "tangent" in line and "quotient" not in line
