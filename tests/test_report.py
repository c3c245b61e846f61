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
    assert 'id="verdicts"' in html and "figures/formulas/" in html
    assert (report_dir / "figures" / "blf-design-control.png").exists()
    assert list((report_dir / "figures" / "formulas").glob("f-*.svg"))
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


@pytest.mark.skipif(_chromium() is None, reason="no chromium: `apt-get install -y chromium` to run the "
                    "headless rendering check")
def test_html_renders_with_figures_and_formulas_in_headless_chromium(report_dir, tmp_path):
    page = (report_dir / "004.html").resolve()
    # a tiny probe page: loads the report in an iframe-free way by appending a script that records
    # how many images finished loading with a nonzero natural size
    probe = report_dir / "probe.html"
    text = page.read_text(encoding="utf-8").replace(
        "</body>", "<script>window.addEventListener('load',()=>{const im=[...document.images];"
        "document.title='IMAGES '+im.filter(i=>i.complete&&i.naturalWidth>0).length+'/'+im.length;});"
        "</script></body>")
    probe.write_text(text, encoding="utf-8")
    cmd = [_chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--no-first-run",
           f"--user-data-dir={tmp_path / 'profile'}", "--allow-file-access-from-files",
           "--virtual-time-budget=5000", "--dump-dom", probe.as_uri()]
    try:
        dom = subprocess.run(cmd, capture_output=True, text=True, timeout=60).stdout
    except (subprocess.TimeoutExpired, OSError) as exc:
        pytest.skip(f"chromium did not run: {exc}")
    assert "<title>IMAGES" in dom, dom[:500]
    loaded, total = dom.split("<title>IMAGES ", 1)[1].split("</title>", 1)[0].split("/")
    assert int(total) > 3 and loaded == total
    shot = tmp_path / "shot.png"
    subprocess.run(cmd[:-2] + [f"--screenshot={shot}", "--window-size=1200,1600", page.as_uri()],
                   capture_output=True, timeout=60)
    assert shot.exists() and shot.stat().st_size > 100_000     # a blank page is ~13 kB
