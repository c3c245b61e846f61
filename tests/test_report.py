"""`subdiv report` / `subdiv check`: files written, the golden file regressed, readable diffs, and a
headless-browser check that the HTML shows its figures and formulas."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from analysis.cli import main

EXTRA = ["analysis.cli.report"]
FAST = ["004:(3.6)", "004:(3.6)matrix", "004:(3.9)-(3.10)/P2n-4", "004:Lemma4.1", "004:Theorem4.4",
        "004:Theorem5.1", "004:Sec7(C6)", "004:Table1"]
REPO_VERDICTS = Path(__file__).resolve().parent.parent / "reports" / "verdicts.json"


def _claims_args():
    out = []
    for c in FAST:
        out += ["--claim", c]
    return out


@pytest.fixture(scope="module")
def report_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("reports")
    rc = main(["report", "004", "--write", "--quiet", "--output", str(out)] + _claims_args(), extra_modules=EXTRA)
    assert rc == 0
    return out


def test_report_files_are_written(report_dir):
    md = (report_dir / "004.md").read_text(encoding="utf-8")
    assert "| claim | kind | verdict | summary |" in md
    assert "| 004:Sec7(C6) | holder | REFUTED |" in md
    html = (report_dir / "004.html").read_text(encoding="utf-8")
    assert 'id="verdicts"' in html and "<math" in html          # formulas typeset as MathML
    assert "figures/formulas/" in md                              # the Markdown report shows them as SVG
    assert (report_dir / "figures" / "blf-design-control.png").exists()
    assert list((report_dir / "figures" / "formulas").glob("f-*.svg"))
    index = (report_dir / "index.html").read_text(encoding="utf-8")
    assert 'href="004.html#claim-004-sec7-c6"' in index and 'href="index.html"' in html
    data = json.loads((report_dir / "verdicts.json").read_text())
    assert set(data["papers"]["004"]["claims"]) == set(FAST)


def test_check_passes_on_fresh_verdicts(report_dir, capsys):
    rc = main(["check", "--quiet", "--verdicts", str(report_dir / "verdicts.json")] + _claims_args(),
              extra_modules=EXTRA)
    assert rc == 0
    assert "claims agree" in capsys.readouterr().out


def test_check_fails_with_a_readable_diff_when_verdicts_are_altered(report_dir, tmp_path, capsys):
    data = json.loads((report_dir / "verdicts.json").read_text())
    claims = data["papers"]["004"]["claims"]
    claims["004:Theorem5.1"]["status"] = "refuted"
    claims["004:Sec7(C6)"]["numbers"]["alpha"]["float"] += 1e-3
    claims["004:Lemma4.1"]["numbers"]["last_nonzero_index"]["exact"] = "6"
    bad = tmp_path / "verdicts.json"
    bad.write_text(json.dumps(data))
    with pytest.raises(SystemExit) as info:
        main(["check", "--quiet", "--verdicts", str(bad)] + _claims_args(), extra_modules=EXTRA)
    assert info.value.code == 1
    out = capsys.readouterr().out
    assert "004:Theorem5.1: status changed: refuted -> certified" in out
    assert "004:Sec7(C6): number 'alpha' moved" in out
    assert "004:Lemma4.1: number 'last_nonzero_index' changed: 6 -> 5 (exact)" in out


def test_unknown_paper_is_a_one_line_error(capsys):
    assert main(["report", "123"], extra_modules=EXTRA) == 2
    assert "unknown paper" in capsys.readouterr().err


def _bundled_paper_ids():
    from analysis.claims import papers

    return sorted(papers())


#: papers whose claims another test evaluates anyway and compares with the golden file itself
#: (that test, in its file): not evaluated twice
CHECKED_ELSEWHERE = {"000": ("test_claims_000_001.py", "test_matches_golden_files"),
                     "001": ("test_claims_000_001.py", "test_matches_golden_files"),
                     "003": ("test_claims_003.py", "test_claim_evaluates_as_in_the_golden_file")}


@pytest.mark.parametrize("pid", _bundled_paper_ids())
def test_committed_verdicts_are_reproduced(capsys, pid):
    """The CI regression: every claim of every paper recomputed against its golden verdicts
    (``papers/<paper>/verdicts.json``), one paper per test so that they run in parallel."""
    if pid in CHECKED_ELSEWHERE:
        file, test = CHECKED_ELSEWHERE[pid]
        assert f"def {test}(" in (Path(__file__).parent / file).read_text(encoding="utf-8")
        return
    try:
        rc = main(["check", "--quiet", pid], extra_modules=EXTRA)
    except SystemExit as exc:        # `subdiv check` exits with 1 and a diff on stdout
        rc = exc.code
    assert rc == 0, capsys.readouterr().out


def test_the_committed_report_verdicts_are_the_golden_files():
    """``reports/verdicts.json`` (what ``subdiv report all`` wrote) is exactly the union of the
    papers' golden files: the two cannot drift apart."""
    from analysis.claims import golden_path, papers

    merged = {"papers": {}}
    for pid, paper in papers().items():
        golden = json.loads(golden_path(paper).read_text(encoding="utf-8"))
        merged["papers"].update(golden["papers"])
        merged["schema"] = golden["schema"]
    assert json.loads(REPO_VERDICTS.read_text(encoding="utf-8")) == merged


def _chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        p = shutil.which(name)
        if p:
            return p
    return None


_PROBE = ("<script>window.addEventListener('load',()=>{const im=[...document.images];"
          "const W=document.documentElement.clientWidth;const over=document.documentElement.scrollWidth>W+1;"
          "const b=[...document.querySelectorAll('#verdicts .badge')];"
          "const cut=b.filter(x=>x.getBoundingClientRect().right>W+1||x.getBoundingClientRect().width<2).length;"
          "const m=[...document.querySelectorAll('math')];"
          "document.title='PROBE '+[im.filter(i=>i.complete&&i.naturalWidth>0).length,im.length,"
          "m.filter(x=>x.getBoundingClientRect().width>0).length,m.length,over?1:0,cut,b.length].join(' ');});"
          "</script></body>")


def _probe(page: Path, tmp_path: Path, width: int) -> list[int]:
    """Load ``page`` in headless chromium at ``width`` px with a script that reports the images loaded,
    the MathML elements rendered with a nonzero width, horizontal overflow and verdict badges cut off."""
    probe = page.with_name(f"probe-{width}.html")
    probe.write_text(page.read_text(encoding="utf-8").replace("</body>", _PROBE), encoding="utf-8")
    cmd = [_chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
           f"--user-data-dir={tmp_path / 'profile'}", "--allow-file-access-from-files",
           f"--window-size={width},900", "--virtual-time-budget=5000", "--dump-dom", probe.as_uri()]
    try:
        dom = subprocess.run(cmd, capture_output=True, text=True, timeout=90).stdout
    except (subprocess.TimeoutExpired, OSError) as exc:
        pytest.fail(f"chromium did not run: {exc}")
    assert "<title>PROBE" in dom, dom[:500]
    return [int(x) for x in dom.split("<title>PROBE ", 1)[1].split("</title>", 1)[0].split()]


@pytest.mark.skipif(_chromium() is None, reason="no chromium: `apt-get install -y chromium` to run the "
                    "headless rendering check")
def test_html_renders_with_figures_and_formulas_in_headless_chromium(report_dir, tmp_path):
    page = (report_dir / "004.html").resolve()
    source = page.read_text(encoding="utf-8")
    loaded, images, drawn, maths, overflow, cut, badges = _probe(page, tmp_path, 1200)
    assert images >= 1 and loaded == images
    assert maths == source.count("<math") > 3 and drawn == maths      # every formula element rendered
    # phone width: nothing wider than the screen, every verdict badge fully visible
    loaded, images, drawn, maths, overflow, cut, badges = _probe(page, tmp_path, 420)
    assert badges == len(FAST) and cut == 0 and overflow == 0
    assert drawn == maths
    shot = tmp_path / "shot.png"
    cmd = [_chromium(), "--headless", "--no-sandbox", "--disable-gpu", f"--user-data-dir={tmp_path / 'profile'}",
           f"--screenshot={shot}", "--window-size=1200,1600", page.as_uri()]
    subprocess.run(cmd, capture_output=True, timeout=60)
    assert shot.exists() and shot.stat().st_size > 100_000     # a blank page is ~13 kB
