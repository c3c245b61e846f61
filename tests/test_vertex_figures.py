"""``subdiv vertex --figure``: with one valence the characteristic map (its segment's parameter lines in every
sector and on the inner rings), with a range the eigenvalues against n; only the named file is written."""

from __future__ import annotations

import json

from analysis.cli.main import main
from analysis.vertex.charpicture import characteristic_map_lines
from analysis.vertex.rules import scheme_rules
from analysis.vertex.spectrum import analyse


def test_one_valence_draws_the_characteristic_map_and_nothing_else(tmp_path, capsys):
    path = tmp_path / "cc5.svg"
    assert main(["vertex", "--scheme", "catmull-clark", "--valence", "5", "--figure", str(path), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["figure"] == str(path) and sorted(p.name for p in tmp_path.iterdir()) == ["cc5.svg"]
    text = path.read_text(encoding="utf-8")
    assert "characteristic map (bicubic Bézier patches)" in text and "ring 3" in text


def test_the_segment_lines_start_on_the_characteristic_nets_scale():
    """The segment lies between the level-1 and level-0 rings: its points' moduli stay within a band that
    lambda maps into itself (the ring and its scaled copy touch, they do not overlap by a factor)."""
    rules = scheme_rules("loop", ring=2)
    a = analyse(rules, 6, curvature=False)
    seg = characteristic_map_lines(rules, 6, a.lam.ball.real, resolution=2)
    radii = [abs(z) for line in seg["lines"] for z in line]
    assert seg["lambda"] == 0.5 and min(radii) > 0 and 0.4 < min(radii) / max(radii) < 0.6


def test_one_valence_of_sqrt3_is_refused_before_any_computation(tmp_path, capsys):
    path = tmp_path / "s.png"
    assert main(["vertex", "--scheme", "sqrt3", "--valence", "5", "--figure", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("subdiv: error:") and "give a valence range" in err and "\n" not in err
    assert not path.exists()


def test_a_figure_outside_an_existing_folder_is_refused(tmp_path, capsys):
    assert main(["vertex", "--scheme", "loop", "--valence", "4", "--figure", str(tmp_path / "no" / "x.png")]) == 2
    assert "does not exist" in capsys.readouterr().err and list(tmp_path.iterdir()) == []
