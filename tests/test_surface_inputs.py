"""Bivariate input read as written, and the algebra exact in every corner: integer dilations only (never rounded),
the complete symmetry group (or "infinite" for a support on a line), exceptional sum-rule values only where the
order is higher, coefficients that are rational functions of a parameter, and paper-file claims on anisotropic
and tensor-product schemes."""

from __future__ import annotations

import pytest
import sympy as sp

from analysis.bivariate.algebra import sum_rules, symmetry_group
from analysis.bivariate.dilation import Dilation
from analysis.bivariate.mask import BivariateMask
from analysis.claims.model import evaluate_paper
from analysis.claims.paperfile import parse_paper
from analysis.cli.main import main
from analysis.result import AnalysisError
from schemes.surfaces import get


@pytest.mark.parametrize("matrix", [[[2.5, 0], [0, 2]], [[2, 0], [0, 2.0]], [[True, 0], [0, 2]], [["2", 0], [0, 2]]])
def test_a_dilation_is_integers_never_rounded(matrix):
    with pytest.raises(AnalysisError, match="2 x 2 integers"):
        Dilation(matrix)


def test_a_non_integer_dilation_in_a_paper_file_is_refused():
    text = ('[paper]\nid = "t"\ntitle = "t"\n[schemes.s]\nbivariate = { symbol = "(1+z1)*(1+z2)/2", '
            'dilation = [[2.9, 0], [0, 2.9]] }\n')
    with pytest.raises(AnalysisError, match=r"2 x 2 integers.*2\.9"):
        parse_paper(text, "t.toml")


def test_the_symmetry_group_is_complete_in_any_lattice_coordinates():
    """Loop's mask in the coordinates alpha -> U alpha, U = [[1, 2], [0, 1]]: its 12 symmetries are U R U^-1, with
    entries up to 7 (a search over entries in {-1, 0, 1} finds only some of them)."""
    loop = get("loop").mask()
    moved = BivariateMask({(i + 2 * j, j): v for (i, j), v in loop}, loop.dilation)
    r = symmetry_group(moved)
    assert r.value == symmetry_group(loop).value == 12
    assert max(abs(x) for R in r.witness["matrices"] for row in R for x in row) > 1


def test_a_support_on_a_line_has_infinitely_many_symmetries(capsys):
    assert symmetry_group(BivariateMask.from_symbol("1")).value is None
    assert symmetry_group(BivariateMask.from_symbol("(1+z1)**2/2")).value is None
    main(["surface", "--symbol", "(1+z1)**2*z2/2"])
    assert "symmetry group: infinite (the support of the mask lies on a line" in capsys.readouterr().out


def test_an_exceptional_value_is_listed_only_where_the_order_is_higher():
    """At t = 1/2 the x-moment is fixed but the y-moment still differs: the order stays 1, so nothing is listed;
    the butterfly's w = 1/16 (order 4) is."""
    a = BivariateMask.from_list("0,0:1+(t-1/2)*(-1)+(t-1/3)*(-1); 1,0:1/2; -1,0:1/2; 0,1:1/2; 0,-1:1/2; 1,1:1/4; "
                                "-1,-1:1/4; 1,-1:1/4; -1,1:1/4; 2,0:t-1/2; 0,2:t-1/3")
    r = sum_rules(a)
    assert r.value == 1 and r.witness["exceptional"] == []
    b = sum_rules(get("butterfly").mask(general=True))
    assert [(e["value"], e["order"]) for e in b.witness["exceptional"]] == [(sp.Rational(1, 16), 4)]


def test_coefficients_that_are_rational_functions_of_a_parameter():
    """1/4 written as (2w + 1)/(4 (1 + 2w)): the bilinear mask's sum rules (order 2) for every w, decided exactly
    (term-by-term expansion does not see that the coset sums are 1); a symbol with w/(1 + 2w); a pole refused."""
    q = "(2*w+1)/(4*(1+2*w))"
    a = BivariateMask.from_list(f"0,0:{q}; 1,0:1/2; 2,0:1/4; 0,1:1/2; 1,1:1; 2,1:1/2; 0,2:1/4; 1,2:1/2; 2,2:1/4")
    assert sum_rules(a).value == 2
    s = BivariateMask.from_symbol("(1+z1)**2*(1+z2)**2/(4*z1*z2) + w/(1+2*w)*(1-z1**2)*(1-z2**2)/(z1*z2)")
    assert sum_rules(s).value == 2 and sum_rules(s.at(w="1/8")).value == 2
    with pytest.raises(AnalysisError, match="pole at w = -1/2"):
        s.at(w="-1/2")


@pytest.mark.parametrize("symbol", ["(1+z1)**(1/2)", "exp(z1)", "z1**w", "1/(1+z1)"])
def test_a_symbol_that_is_not_a_laurent_polynomial_is_a_one_line_error(symbol):
    with pytest.raises(AnalysisError, match="Laurent polynomial in z1, z2") as e:
        BivariateMask.from_symbol(symbol)
    assert "\n" not in str(e.value)


def _paper(schemes: str, claims: str) -> dict:
    text = f'[paper]\nid = "t"\ntitle = "t"\n{schemes}\n{claims}'
    return {e.claim.id.split(":", 1)[1]: e.verdict for e in evaluate_paper(parse_paper(text, "t.toml"))}


def test_claims_on_an_anisotropic_scheme_are_judged_without_a_crash():
    v = _paper('[schemes.an]\nbivariate = { symbol = "(1+z1)**2*(1+z2+z2**2)**2/(6*z1*z2**2)", '
               'dilation = [[2, 0], [0, 3]] }',
               '[[claims]]\nid = "h"\nstatement = "s"\nkind = "holder"\nscheme = "an"\nvalue = 1\n'
               '[[claims]]\nid = "c0"\nstatement = "s"\nkind = "smoothness"\nscheme = "an"\nC = 0\n')
    assert v["h"].label == "INCONCLUSIVE" and "anisotropic" in v["h"].summary
    assert [n.to_json() for n in v["h"].numbers]                   # the report writes them (this used to raise)
    assert v["c0"].label == "CERTIFIED TRUE" and "JSR(T|V_2)" in v["c0"].summary and "[?" not in v["c0"].summary


def test_a_ck_range_of_a_tensor_product_family_takes_the_univariate_route():
    """Kobbelt's quad scheme as b(z1) b(z2): C^1 exactly on (0, w*), w* the real root of 32 w^3 + 4 w - 1, so the
    claim "C^1 on (0, 1/4)" is refuted at w* (before: inconclusive after minutes of bivariate boxes)."""
    b = "(-w/z1**3 + (w+1/2)/z1 + 1 + (w+1/2)*z1 - w*z1**3)"
    v = _paper(f'[schemes.kq]\nbivariate = {{ symbol = "{b}*{b.replace("z1", "z2")}" }}\n'
               'parameters = { w = "(0, 1/4)" }',
               '[[claims]]\nid = "c"\nstatement = "s"\nkind = "ck range"\nscheme = "kq"\nj = 1\ninterval = "(0, 1/4)"\n')
    assert v["c"].label == "REFUTED" and "32*w**3 + 4*w - 1" in v["c"].summary and "0.1927292493" in v["c"].summary


def test_paper_file_mistakes_on_bivariate_schemes_are_caught_at_load_time():
    head = ('[paper]\nid = "t"\ntitle = "t"\n[schemes.s]\nbivariate = { symbol = '
            '"(1+z1)**2*(1+z2)**2/(4*z1*z2)+w*(1-z1**2)*(1-z2**2)/(z1*z2)" }\nparameters = { w = "(0, 1)" }\n')
    with pytest.raises(AnalysisError, match="rational ends"):
        parse_paper(head + '[[claims]]\nid = "c"\nstatement = "s"\nkind = "ck range"\nscheme = "s"\nj = 0\n'
                           'interval = "(0, sqrt(2)/2)"\n', "t.toml")
    with pytest.raises(AnalysisError, match="use kind 'ck range'$"):       # no 'smoothness profile' for surfaces
        parse_paper(head + '[[claims]]\nid = "c"\nstatement = "s"\nkind = "smoothness"\nscheme = "s"\nC = 0\n',
                    "t.toml")


def test_an_exact_jsr_is_printed_as_a_value(capsys):
    main(["surface", "--symbol", "(1+z1)**2*(1+z2+z2**2)**2/(6*z1*z2**2)", "--dilation", "2,0;0,3"])
    assert "JSR(T|V_2) = 1/2 (rho(T_4)^(1/1), exact; certified)" in capsys.readouterr().out
