"""Every example of the guide runs: README.md and docs/*.md are executed and their shown output checked.

Conventions for writers (docs/index.md repeats them):

* A ```console block holds commands ``$ subdiv ...`` (a line ending in ``\\`` continues on the next), each
  followed by the output it prints. The commands of one block run in order, in one fresh temporary folder
  that holds a link ``examples`` to the repository's ``examples/`` (so ``subdiv report examples/x.toml
  --output r`` works and writes into the temporary folder), in process through
  :func:`analysis.cli.main.main` (``shlex``-split; no shell: no pipes or variables). The output compared is
  standard output followed by the lines of standard error that begin with ``subdiv`` (error lines and
  notices). Trailing spaces and blank lines at the end are ignored; a line that is exactly ``...`` stands
  for any number of lines (zero included). Wall-clock times differ between runs: lines ``time: ...`` are
  dropped and a number of seconds before ``)``, `` wall`` or `` CPU`` is read as any number, on both sides.
* The ```python blocks of a page run in order in one namespace (as the cells of a notebook), in a fresh
  temporary folder: a block with ``>>>`` prompts as a doctest (``ELLIPSIS``, ``NORMALIZE_WHITESPACE``),
  any other block executed as a script.
* A ```bash block shows a longer run without its output: every line that starts with ``subdiv`` is
  checked to be a valid command line (the parser accepts it); it is not run.
* A ```toml block must parse. Preceded by ``<!-- file: PATH -->`` it must be the file PATH of the
  repository byte for byte. A block with ``[paper]`` is loaded as a paper file (every scheme and claim
  validated, nothing evaluated); a block of ``[[claims]]`` only is appended to the last such block above it
  on the same page and the whole is loaded.

Each example must be cheap (well under 2 s): longer runs go in ```bash blocks.

To write the output of a new example, leave the lines after its ``$ subdiv ...`` line empty and run
``python tests/test_docs_examples.py docs/page.md``: commands without shown output get the output they
print (review it before committing). With ``--refresh`` every command whose shown output has no ``...``
line gets what it prints now (after a change of wording; review the diff).
"""

from __future__ import annotations

import contextlib
import doctest
import io
import os
import re
import shlex
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
TIMING = re.compile(r"^\s*time:")
SECONDS = re.compile(r"\b\d+(?:\.\d+)? s(?=\)| wall| CPU)")
FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```[ \t]*$", re.S | re.M)
FILE_MARK = re.compile(r"<!--\s*file:\s*(\S+)\s*-->\s*$")


@dataclass
class Block:
    page: Path
    line: int
    lang: str
    text: str
    before: str          # the page's text before the fence

    @property
    def id(self) -> str:
        return f"{self.page.relative_to(ROOT)}:{self.line}"


def blocks(page: Path) -> list[Block]:
    text = page.read_text(encoding="utf-8")
    return [Block(page, text.count("\n", 0, m.start()) + 1, m.group(1), m.group(2), text[:m.start()])
            for m in FENCE.finditer(text)]


def _all(lang: str) -> list[Block]:
    return [b for p in PAGES for b in blocks(p) if b.lang == lang]


# --------------------------------------------------------------------------------------------
# console sessions
# --------------------------------------------------------------------------------------------

def session(text: str) -> list[tuple[str, list[str]]]:
    """The (command, expected output lines) pairs of a console block."""
    out: list[tuple[str, list[str]]] = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if not line.startswith("$ "):
            if out:
                out[-1][1].append(line)
            elif line.strip():
                raise ValueError(f"a console block must start with a '$ subdiv ...' line, not {line!r}")
            i += 1
            continue
        command = line[2:]
        while command.endswith("\\") and i + 1 < len(lines):
            i += 1
            command = command[:-1] + " " + lines[i].strip()
        out.append((command, []))
        i += 1
    return out


def run(command: str) -> str:
    """What ``command`` (``subdiv ...``) shows: stdout, then the stderr lines that begin with ``subdiv``."""
    from analysis.cli.main import main

    argv = shlex.split(command)
    if not argv or argv[0] != "subdiv":
        raise ValueError(f"a console command must start with 'subdiv': {command!r}")
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            main(argv[1:])
        except SystemExit:               # --help
            pass
    notes = [ln for ln in err.getvalue().splitlines() if ln.startswith("subdiv")]
    return "\n".join([*out.getvalue().rstrip("\n").splitlines(), *notes])


def _clean(lines: list[str]) -> list[str]:
    kept = [SECONDS.sub("N s", ln.rstrip()) for ln in lines if not TIMING.search(ln)]
    while kept and not kept[-1]:
        kept.pop()
    return kept


def matches(expected: list[str], actual: list[str]) -> bool:
    """Whether ``actual`` is ``expected`` with each ``...`` line standing for any lines."""
    parts = [r"(?:[^\n]*\n)*?" if ln.strip() == "..." else re.escape(ln) + r"\n" for ln in _clean(expected)]
    return re.fullmatch("".join(parts), "".join(ln + "\n" for ln in _clean(actual))) is not None


@contextlib.contextmanager
def _folder(tmp: Path):
    (tmp / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    old = Path.cwd()
    os.chdir(tmp)
    try:
        yield
    finally:
        os.chdir(old)


@pytest.fixture
def wide(monkeypatch):
    monkeypatch.setenv("COLUMNS", "100")      # --help output wraps at a fixed width


@pytest.mark.parametrize("block", _all("console"), ids=lambda b: b.id)
def test_console(block, tmp_path, wide):
    with _folder(tmp_path):
        for command, expected in session(block.text):
            actual = run(command).splitlines()
            assert matches(expected, actual), (
                f"{block.id}: `{command}` printed\n" + "\n".join(actual) + "\n--- the page shows\n" + "\n".join(expected))


def test_the_comparison_can_fail():
    """``...`` elides lines, times are ignored, and anything else must match line for line."""
    assert session("$ subdiv a \\\n    --b\nout 1\n...\nout 9\n$ subdiv c\n") == \
        [("subdiv a  --b", ["out 1", "...", "out 9"]), ("subdiv c", [])]
    assert matches(["a", "...", "z"], ["a", "b", "c", "z"]) and matches(["a", "...", "z"], ["a", "z"])
    assert matches(["done (1.5 s)", "x"], ["time: 3 s", "done (0.2 s)", "x  ", ""])
    assert not matches(["a", "...", "z"], ["a", "b"])
    assert not matches(["alpha = 2"], ["alpha = 3"])
    assert not matches(["a"], ["a", "b"])
    assert not matches(["a.b"], ["axb"])                      # text is literal, not a pattern


def test_console_blocks_exist():
    """The collector finds the examples (a renamed fence would silently turn the test off)."""
    assert len(_all("console")) >= 20
    assert all(session(b.text) for b in _all("console"))


# --------------------------------------------------------------------------------------------
# python, bash, toml
# --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("page", [p for p in PAGES if any(b.lang == "python" for b in blocks(p))],
                         ids=lambda p: str(p.relative_to(ROOT)))
def test_python(page, tmp_path):
    """The python blocks of a page run in order in one namespace, as the cells of a notebook."""
    namespace: dict = {"__name__": "__docs__"}
    with _folder(tmp_path):
        for block in (b for b in blocks(page) if b.lang == "python"):
            if ">>>" in block.text:
                test = doctest.DocTestParser().get_doctest(block.text, namespace, block.id, str(page), block.line)
                runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
                out = io.StringIO()
                runner.run(test, out=out.write, clear_globs=False)
                assert runner.failures == 0, out.getvalue()
                namespace = test.globs
            else:
                exec(compile(block.text, block.id, "exec"), namespace)


def _bash_commands() -> list[tuple[str, str]]:
    found = []
    for b in _all("bash"):
        text = re.sub(r"\\\n\s*", " ", b.text)
        for ln in text.splitlines():
            ln = ln.split("  #", 1)[0].strip()
            if ln.startswith("subdiv "):
                found.append((b.id, ln))
    return found


@pytest.mark.parametrize("where,command", _bash_commands(), ids=[c[:60] for _, c in _bash_commands()])
def test_bash_commands_parse(where, command):
    from analysis.cli.common import attach_dash_values
    from analysis.cli.main import build_parser

    parser = build_parser()
    argv = shlex.split(command)[1:]
    parser.parse_args(attach_dash_values(parser, argv))


def _paper_text(block: Block) -> str | None:
    """The paper file a toml block is (or completes), None for a fragment of another kind."""
    data = tomllib.loads(block.text)
    if "paper" in data:
        return block.text
    if set(data) == {"claims"}:
        earlier = [b for b in blocks(block.page) if b.lang == "toml" and b.line < block.line
                   and "paper" in tomllib.loads(b.text)]
        assert earlier, f"{block.id}: claims without a [paper] block above them on the page"
        return earlier[-1].text + "\n" + block.text
    return None


@pytest.mark.parametrize("block", _all("toml"), ids=lambda b: b.id)
def test_toml(block):
    mark = FILE_MARK.search(block.before.rstrip() + "\n")
    if mark:
        assert block.text == (ROOT / mark.group(1)).read_text(encoding="utf-8"), f"{block.id} is not {mark.group(1)}"
    text = _paper_text(block)
    if text is not None:
        from analysis.claims.paperfile import parse_paper
        from papers import catalogue

        paper = parse_paper(text, block.id, catalogue=catalogue)
        assert paper.claims


# --------------------------------------------------------------------------------------------
# what the pages must keep
# --------------------------------------------------------------------------------------------

def test_readme_keeps_the_test_command_and_stays_short():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert 'python -m pip install -e ".[test]" && python -m pytest' in text.splitlines()
    assert len(text.splitlines()) <= 250


def test_every_claim_kind_has_an_example():
    """docs/paper-files.md has a section with a loaded example claim for every kind the engine knows."""
    from analysis.claims.kinds import KIND_CLASSES

    page = ROOT / "docs" / "paper-files.md"
    text = page.read_text(encoding="utf-8")
    shown = {tomllib.loads(b.text)["claims"][0]["kind"] for b in blocks(page)
             if b.lang == "toml" and set(tomllib.loads(b.text)) == {"claims"}}
    for kind in KIND_CLASSES:
        assert f"### `{kind}`" in text and kind in shown, f"docs/paper-files.md: no example of the kind {kind!r}"


def test_every_command_is_in_the_guide():
    """Each command appears in docs/index.md's table and is run or shown somewhere in the guide."""
    from analysis.cli.main import EXAMPLES

    index = (ROOT / "docs" / "index.md").read_text(encoding="utf-8")
    commands = {ln.split()[1] for b in (*_all("console"), *_all("bash")) for ln in b.text.splitlines()
                if ln.startswith(("$ subdiv ", "subdiv ")) and len(ln.split()) > 2
                for ln in [ln.removeprefix("$ ")]}
    for command in EXAMPLES:
        assert f"`subdiv {command}`" in index and command in commands, f"the guide does not show `subdiv {command}`"


def test_no_issue_numbers_in_user_text():
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        assert not re.search(r"\bissues? #?\d", text, re.I), f"{page.name} mentions an issue number"


#: pages that other work adds (linked from docs/index.md before they exist)
ANNOUNCED = {"docs/jsr.md", "docs/surfaces.md"}


def test_relative_links_resolve():
    for page in PAGES:
        prose = re.sub(r"`[^`\n]*`", "", FENCE.sub("", page.read_text(encoding="utf-8")))   # not code
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", prose):
            if "://" in target or target.startswith("mailto:"):
                continue
            path = (page.parent / target).resolve()
            if str(path.relative_to(ROOT)) in ANNOUNCED and not path.exists():
                continue
            assert path.exists(), f"{page.name} links to a missing {target}"


# --------------------------------------------------------------------------------------------
# authoring aid: fill in the output of commands that show none
# --------------------------------------------------------------------------------------------

def _fill(page: Path, refresh: bool = False) -> None:
    text = page.read_text(encoding="utf-8")
    pieces, last = [], 0
    for m in FENCE.finditer(text):
        if m.group(1) != "console":
            continue
        body = m.group(2)
        new = []
        tmp = Path(__import__("tempfile").mkdtemp())
        with _folder(tmp):
            for command, expected in session(body):
                shown = [f"$ {command}"]
                keep = any(ln.strip() for ln in expected) and not (refresh and "..." not in
                                                                     [ln.strip() for ln in expected])
                if keep:
                    shown += expected
                else:
                    shown += run(command).splitlines()
                new.append("\n".join(shown).rstrip("\n"))
        pieces.append(text[last:m.start(2)] + "\n".join(new) + "\n")
        last = m.end(2)
    pieces.append(text[last:])
    page.write_text("".join(pieces), encoding="utf-8")


if __name__ == "__main__":      # python tests/test_docs_examples.py [--refresh] PAGE.md ...
    sys.path.insert(0, str(ROOT))
    os.environ.setdefault("COLUMNS", "100")
    names = [a for a in sys.argv[1:] if a != "--refresh"]
    for name in names:
        _fill(Path(name).resolve(), refresh="--refresh" in sys.argv)
