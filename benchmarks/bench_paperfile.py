"""Issue 11: paper files. Loading, and `subdiv report FILE.toml` end to end (subprocess, as a user runs it)
for the README example (4 claims) and the `subdiv new-paper` template (one claim of each kind).

Run: ``python benchmarks/bench_paperfile.py`` (targets: a 10-claim paper file under 30 s on 2 cores).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _t(label, fn):
    t = time.perf_counter()
    out = fn()
    dt = time.perf_counter() - t
    print(f"{label:<62} {dt:7.2f} s   {out}")
    return dt


def _report(path: Path, out: str) -> str:
    r = subprocess.run([sys.executable, "-m", "analysis", "report", str(path), "--output", out, "--quiet"],
                       capture_output=True, text=True, cwd=ROOT)
    labels = [ln.split()[1] for ln in r.stdout.splitlines() if ":" in ln.split(" ")[0]]
    return f"exit {r.returncode}; " + ", ".join(f"{labels.count(x)} {x.lower()}" for x in sorted(set(labels)))


def main() -> None:
    from analysis.claims.paperfile import load_paper
    from analysis.claims.template import template

    with tempfile.TemporaryDirectory() as d:
        tpl = Path(d) / "template.toml"
        tpl.write_text(template())
        n = len(load_paper(tpl).claims)
        _t("load_paper(template) (validation only)", lambda: f"{len(load_paper(tpl).claims)} claims")
        _t("subdiv report examples/four-point.toml (4 claims)", lambda: _report(ROOT / "examples" / "four-point.toml", d))
        _t(f"subdiv report template.toml ({n} claims, every kind)", lambda: _report(tpl, d))


if __name__ == "__main__":
    main()
