"""Hostile input through every option of the command line: injection attempts, huge numbers, deep
nesting, malformed text. Each must end in exit code 2, one line ``subdiv: error: ...`` on stderr
and, with ``--json``, one JSON document ``{"error": {...}}`` on stdout — and no side effect: the
marker file an injection would create never appears.

The commands run in-process (``analysis.cli.main.main``) for speed; the resource test runs the
huge inputs in one subprocess and checks its peak memory.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from analysis.cli.main import main

#: Where an injection would leave its mark (one folder for the whole corpus).
MARK_DIR = Path(tempfile.mkdtemp(prefix="subdiv-hostile-"))
MARK = MARK_DIR / "ran"

#: Code that would run if any text reached eval (each creates MARK if it runs).
INJECTIONS = [
    f"__import__('os').system('touch {MARK}')",
    f"__import__('pathlib').Path('{MARK}').touch()",
    f"open('{MARK}', 'w')",
    f"exec(\"open('{MARK}', 'w')\")",
    f"eval(\"__import__('os').system('touch {MARK}')\")",
    f"getattr(__builtins__, 'open')('{MARK}', 'w')",
    f"[open('{MARK}', 'w') for x in (1,)]",
    f"(lambda: open('{MARK}', 'w'))()",
    f"1 if open('{MARK}', 'w') else 0",
    f"z.__class__.__init__.__globals__['os'].system('touch {MARK}')",
    "().__class__.__base__.__subclasses__()",
    f"eval(chr(111)+chr(112)+chr(101)+chr(110)+'(\"{MARK}\",\"w\")')",
    "compile('1', 'x', 'eval')",
    "__builtins__",
    "globals()",
    f"Symbol('x').__class__.__mro__",
    f"1; __import__('os').system('touch {MARK}')",
    f"f'{{open(\"{MARK}\", \"w\")}}'",
    "sympify('1')",
    f"lambdify(z, '__import__(\"os\").system(\"touch {MARK}\")')(1)",
]

#: Sizes no input may ask for, and text that is no formula.
HUGE = ["10**10**10", "9" * 5000, "z**(10**9)", "1/10**100000", "2**2**2**2**2**2", "(" * 400 + "1" + ")" * 400,
        "+".join(["z"] * 50000), "((1+z)**100)**100", "1e999999", "-".join(["1"] * 200000), "x" * 300,
        "sin(" * 150 + "1" + ")" * 150, "1" * 100001]
MALFORMED = ["1//2", "abc,,1", "[1,2]", "1 2", "w=1", "'1'", "2z", "1/0", "oo", "nan", "True", "None", "...", "@",
             "\x00", "1 < 2", "z if z else 1", "{1}", "x[0]", "-"]


def _run(capsys, argv: list[str]) -> tuple[int, str, str, float]:
    t0 = time.perf_counter()
    code = main(argv)
    dt = time.perf_counter() - t0
    out, err = capsys.readouterr()
    return code, out, err, dt


def _assert_clean_error(argv, code, out, err, dt) -> None:
    assert not MARK.exists(), f"{argv}: an injection ran"
    assert code == 2, (argv, code, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("subdiv: error: "), (argv, err)
    doc = json.loads(out)                              # one JSON document, nothing else on stdout
    assert set(doc) == {"error"} and doc["error"]["message"] and doc["error"]["kind"], (argv, doc)
    assert dt < 5.0, f"{argv}: {dt:.1f} s"


#: (command line with {} where the hostile text goes); every text option of every command.
TARGETS = [
    ["symbol", "--mask", "{}"],
    ["symbol", "--mask", "1/2,{},1/2"],
    ["symbol", "--symbol", "{}"],
    ["symbol", "--even", "{}", "--odd", "1"],
    ["symbol", "--mask", "1,1", "--param", "w={}"],
    ["symbol", "--mask", "c,c", "--where", "c={}"],
    ["symbol", "--mask", "1,1", "--start", "{}"],
    ["factor", "--symbol", "{}"],
    ["norm", "--scheme", "dfh-chaikin-perturbation", "--m", "3", "--L", "2", "--solve", "omega", "--within", "{},1"],
    ["norm", "--mask", "1/2,1,1/2", "--m", "1", "--L", "{}"],
    ["refine", "--scheme", "chaikin", "--points", "0,0;{},1", "--steps", "1"],
    ["refine", "--scheme", "chaikin", "--points", "0,0;1,1", "--steps", "{}"],
    ["matrices", "--mask", "{}"],
    ["holder", "--mask", "{}"],
    ["holder", "--mask", "-1/16,0,9/16,1,9/16,0,{}", "--start", "-3"],
    ["holder", "--scheme", "four-point", "--param", "w={}"],
    ["holder", "--mask", "1/4,3/4,3/4,1/4", "--arity", "{}"],
    ["holder", "--mask", "1/4,3/4,3/4,1/4", "--C", "{}"],
    ["holder", "--mask", "1/4,3/4,3/4,1/4", "--budget", "{}"],
    ["holder", "--scheme", "exp-bspline-3-trig", "--box", "theta={},1"],
    ["range", "--scheme", "four-point", "--C", "1", "--within", "{},1/8"],
    ["range", "--scheme", "four-point", "--C", "1", "--within", "0,1/8", "--grid", "{}"],
    ["atlas", "--symbol", "(1+z)**2/(2*z)*(1 + s*(z-2+1/z) + t*(z**2-2+z**-2))", "--x", "s={}:1/8:3",
     "--y", "t=-1/8:0:2", "--no-progress"],
    ["series", "--scheme", "exp-bspline-3-trig", "--param", "theta={}", "--m", "1"],
    ["bound", "--lhs", "{}", "--rhs", "1"],
    ["bound", "--lhs", "1/2**n", "--rhs", "{}"],
    ["reproduce", "--scheme", "exp-bspline-3-trig", "--param", "theta=1", "--lambdas", "{}"],
    ["derive", "--support", "{}", "--sum-rules", "2"],
    ["vertex", "--lattice", "triangle", "--centre", "{}", "--valence", "4", "--ring", "1"],
    ["vertex", "--scheme", "loop", "--valence", "{}", "--ring", "1"],
    ["surface", "--scheme", "butterfly", "--C", "1", "--within", "{},1/8"],
    ["surface", "--scheme", "butterfly", "--C", "{}", "--within", "0,1/8"],
    ["surface", "--scheme", "butterfly", "--C", "1", "--within", "0,1/8", "--grid-cells", "{}"],
]


def _mask_file_cases():
    """Hostile values in every field of a bivariate mask file (TOML and JSON)."""
    out = []
    for i, v in enumerate(INJECTIONS + HUGE[:6] + MALFORMED[:6]):
        out.append(pytest.param("m.json", json.dumps({"symbol": v}), id=f"json-symbol-{i}"))
        out.append(pytest.param("m.json", json.dumps({"mask": [[0, 0, v], [1, 0, "1"]]}), id=f"json-entry-{i}"))
        out.append(pytest.param("m.toml", f"mask = {json.dumps('0,0:1; 1,0:' + v)}\n", id=f"toml-list-{i}"))
    for i, text in enumerate(['dilation = [[1, 1], [1, "x"]]\nsymbol = "1+z1"', 'symbol = "1+z1"\nmask = "0,0:1"',
                              'symbol = "1+z1"\nrun = "x"', 'mask = [[0, 0]]', 'mask = [[true, 0, "1"]]',
                              'mask = [[0, 0, 1.5]]', 'mask = []', 'symbol = 3', '[[[', 'dilation = "hexagonal"\nsymbol = "1"',
                              "mask = [" + ", ".join(f"[{k}, 0, 1]" for k in range(1200)) + "]",
                              'mask = [[100, 0, "1"]]']):
        out.append(pytest.param("m.toml", text, id=f"toml-shape-{i}"))
    out.append(pytest.param("m.toml", "x = 1\n" * 60_000, id="too-big"))
    return out


@pytest.mark.parametrize("name,text", _mask_file_cases())
def test_hostile_mask_files(capsys, tmp_path, name, text):
    f = tmp_path / name
    f.write_text(text, encoding="utf-8")
    argv = ["surface", "--file", str(f), "--json"]
    _assert_clean_error(argv, *_run(capsys, argv))


def _cases():
    """Each target with a share of each corpus (every target gets injections; sizes and malformed
    text rotate through the targets so that every value is used and the suite stays fast)."""
    out = []
    for i, t in enumerate(TARGETS):
        vals = INJECTIONS[i % 4::4] + [HUGE[i % len(HUGE)], MALFORMED[i % len(MALFORMED)],
                                       MALFORMED[(i + 7) % len(MALFORMED)]]
        for j, v in enumerate(vals):
            out.append(pytest.param([x.replace("{}", v) for x in t] + ["--json"], id=f"{t[0]}-{i}-{j}"))
    return out


@pytest.mark.parametrize("argv", _cases())
def test_hostile_option_values(capsys, argv):
    _assert_clean_error(argv, *_run(capsys, argv))


@pytest.mark.parametrize("value", INJECTIONS + HUGE + MALFORMED, ids=lambda v: repr(v[:24]))
def test_every_value_through_the_mask(capsys, value):
    argv = ["holder", "--mask", f"1/4,{value},1/4", "--json"]
    _assert_clean_error(argv, *_run(capsys, argv))


def test_the_corpus_is_large_enough():
    assert len(_cases()) + len(INJECTIONS + HUGE + MALFORMED) >= 200


def test_huge_inputs_stay_small_in_a_fresh_process(tmp_path):
    """The huge inputs in one fresh interpreter: every one a clean error, peak memory under 1 GB."""
    script = tmp_path / "run.py"
    script.write_text(
        "import json, resource, sys\n"
        "from analysis.cli.main import main\n"
        f"values = {HUGE!r}\n"
        "codes = [main(['symbol', '--symbol', v]) for v in values]\n"
        "codes += [main(['holder', '--mask', '1/2,' + v + ',1/2']) for v in values]\n"
        "peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024\n"
        "print(json.dumps({'codes': codes, 'peak': peak}), file=sys.__stdout__)\n")
    t0 = time.perf_counter()
    p = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=120,
                       cwd=Path(__file__).resolve().parents[1])
    dt = time.perf_counter() - t0
    res = json.loads(p.stdout.strip().splitlines()[-1])
    assert res["codes"] == [2] * (2 * len(HUGE)), p.stderr
    assert res["peak"] < 1 << 30, res["peak"]
    assert dt < 60, dt
    assert "internal error" not in p.stderr and "MemoryError" not in p.stderr


def test_mistyped_command_and_option(capsys):
    code, out, err, _ = _run(capsys, ["holdr", "--mask", "1,1", "--json"])
    assert code == 2 and "did you mean `subdiv holder`" in err and json.loads(out)["error"]["kind"] == "usage"
    code, out, err, _ = _run(capsys, ["holder", "--maks", "1,1", "--json"])
    assert code == 2 and "did you mean --mask" in err


def test_unknown_name_in_a_mask_is_an_error_naming_it(capsys):
    code, out, err, _ = _run(capsys, ["holder", "--mask", "-1/l6,0,9/16,1,9/16,0,-1/16", "--start", "-3"])
    assert code == 2 and "'l6'" in err and "--param l6=" in err


def test_table_paths_that_leave_their_place_are_refused(capsys, tmp_path):
    """``--table``: a report's table is a name inside its output folder (``..``, an absolute path or a
    symbolic link leading out are refused); another command's table is the named file, never a
    symbolic link (which would write through to its target). Refused before any computation."""
    paper = tmp_path / "p.toml"
    paper.write_text('[paper]\nid = "991"\ntitle = "t"\ncitation = "c"\n[schemes.chaikin]\n'
                     'mask = ["1/4", "3/4", "3/4", "1/4"]\nstart = -2\n[[claims]]\nid = "a"\nstatement = "s"\n'
                     'kind = "interpolatory"\nscheme = "chaikin"\n')
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    out.mkdir()
    elsewhere.mkdir()
    (out / "link").symlink_to(elsewhere, target_is_directory=True)
    target = tmp_path / "precious.txt"
    target.write_text("keep")
    (tmp_path / "t.csv").symlink_to(target)
    cases = [["report", str(paper), "--output", str(out), "--table", name]
             for name in ("../escape.tex", str(tmp_path / "abs.csv"), "link/x.csv", "../../x.csv")]
    cases += [["holder", "--scheme", "chaikin", "--table", str(tmp_path / "t.csv")],
              ["check", str(paper), "--table", str(tmp_path / "t.csv")],
              ["holder", "--scheme", "chaikin", "--table", str(tmp_path / "x.exe")]]
    for argv in cases:
        code, stdout, err, dt = _run(capsys, [*argv, "--json"])
        _assert_clean_error(argv, code, stdout, err, dt)
        assert "refusing to write --table" in err or "end the name in .csv" in err, err
    assert sorted(os.listdir(tmp_path)) == ["elsewhere", "out", "p.toml", "precious.txt", "t.csv"]
    assert os.listdir(elsewhere) == [] and os.listdir(out) == ["link"] and target.read_text() == "keep"


def test_marker_never_created():
    assert not MARK.exists()
    assert os.listdir(MARK_DIR) == []


# ------------------------------------------------------------------------------------------------
# paper files: every string field of every claim kind's example, replaced by hostile text
# ------------------------------------------------------------------------------------------------

_PAPER_BASE = '''[paper]
id = "990"
title = "hostile"
citation = "none"

[schemes.four-point]
mask = ["-w", 0, "1/2+w", 1, "1/2+w", 0, "-w"]
start = -3
parameters = { w = "(0, 1/4)" }

[schemes.exp-chaikin]
level_symbol = "(1+z)*(1+2*v*z+z**2)/(2*(1+v)*z**2)"
where = { v = "cosh(t/2**(n+1))" }
parameters = { t = "(0, oo)" }
'''

#: Fields that are free text (printed, never read as a formula or a name).
_FREE_TEXT = {"label", "source", "settle", "evaluator"}
_LEVEL_KINDS = {"weighted series", "asymptotic equivalence", "exponential reproduction"}


def _toml(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, list):
        return "[" + ", ".join(_toml(x) for x in v) + "]"
    return "{ " + ", ".join(f"{json.dumps(k)} = {_toml(x)}" for k, x in v.items()) + " }"


def _string_paths(v, pre=()):
    if isinstance(v, str):
        yield pre
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from _string_paths(x, pre + (i,))
    elif isinstance(v, dict):
        for k, x in v.items():
            yield from _string_paths(x, pre + (k,))


def _paper_cases():
    import copy
    import tomllib

    from analysis.claims.kinds import KIND_CLASSES

    out = []
    values = [INJECTIONS[0], INJECTIONS[3], HUGE[0], HUGE[2], MALFORMED[0]]
    n = 0
    for name, cls in sorted(KIND_CLASSES.items()):
        example = tomllib.loads(cls.example)
        for path in _string_paths(example):
            if path[-1] in _FREE_TEXT or (len(path) > 1 and path[-2] in _FREE_TEXT):
                continue
            fields = copy.deepcopy(example)
            target = fields
            for k in path[:-1]:
                target = target[k]
            target[path[-1]] = values[n % len(values)]
            n += 1
            scheme = fields.pop("scheme", None) if cls.uses_scheme else None
            scheme = scheme or ("exp-chaikin" if name in _LEVEL_KINDS else "four-point")
            body = "\n".join(f"{k} = {_toml(v)}" for k, v in fields.items())
            text = (_PAPER_BASE + f'\n[[claims]]\nid = "c1"\nstatement = "s"\nkind = "{name}"\n'
                    + (f'scheme = "{scheme}"\n' if cls.uses_scheme else "") + body + "\n")
            out.append(pytest.param(text, id=f"{name}-{'.'.join(map(str, path))}"))
    # kind "vertex": the fields of its user rules and the butterfly's tension (not in its example)
    base = {"lattice": "triangle", "centre": "3/(8*n)", "edge": "3/8; 1/n", "valence": "4",
            "property": "eigen-conditions"}
    for key in ("lattice", "centre", "edge", "tension"):
        for value in values:
            fields = dict(base, **{key: value})
            if key == "tension":
                fields = {"surface": "butterfly", "valence": "4", "property": "C1", "tension": value}
            body = "\n".join(f"{k} = {_toml(v)}" for k, v in fields.items())
            text = _PAPER_BASE + f'\n[[claims]]\nid = "c1"\nstatement = "s"\nkind = "vertex"\n{body}\n'
            out.append(pytest.param(text, id=f"vertex-{key}-{value[:12]}"))
    for field, value in [("mask", f'["{INJECTIONS[0]}", 1]'), ("mask", '["10**10**10", 1]'),
                         ("symbol", json.dumps(INJECTIONS[2])), ("symbol", '"z**(10**9)"'),
                         ("parameters", '{ w = "(0, __import__(\'os\'))" }')]:
        text = (f'[paper]\nid = "991"\ntitle = "t"\ncitation = "c"\n[schemes.s]\n{field} = {value}\nstart = 0\n'
                '[[claims]]\nid = "c1"\nstatement = "s"\nkind = "sum rules"\nfactors = 1\n')
        if field == "parameters":
            text = text.replace("start = 0", 'mask = ["w", "1-w"]\nstart = 0')
        out.append(pytest.param(text, id=f"scheme-{field}-{value[:12]}"))
    for i, value in enumerate([f'{{ symbol = {json.dumps(INJECTIONS[1])} }}', '{ symbol = "z1**(10**9)" }',
                               f'{{ mask = [[0, 0, {json.dumps(INJECTIONS[3])}]] }}', '{ mask = "0,0: 10**10**10" }',
                               '{ symbol = "1+z1", dilation = [[1, 1], [1, 1]] }', '{ symbol = "1+z1", dilation = "x" }',
                               '{ symbol = "1+w*z1" }\nparameters = { w = "(0, __import__(\'os\'))" }']):
        text = (f'[paper]\nid = "991"\ntitle = "t"\ncitation = "c"\n[schemes.s]\nbivariate = {value}\n'
                '[[claims]]\nid = "c1"\nstatement = "s"\nkind = "sum rules"\nfactors = 1\n')
        out.append(pytest.param(text, id=f"scheme-bivariate-{i}"))
    return out


@pytest.mark.parametrize("text", _paper_cases())
def test_hostile_paper_file_fields(capsys, tmp_path, text):
    f = tmp_path / "p.toml"
    f.write_text(text, encoding="utf-8")
    argv = ["report", str(f), "--output", str(tmp_path / "out"), "--json"]
    _assert_clean_error(argv, *_run(capsys, argv))
    assert not (tmp_path / "out" / "990.md").exists()


def test_no_text_reaches_sympy_in_the_source():
    """The reader is the only place that turns text into expressions: no module of the engine,
    the catalogue or the papers calls ``sympify``/``parse_expr``/``eval``/``exec`` (the results
    contract converts its own values with ``sympify(..., strict=True)``, which refuses text)."""
    import re

    root = Path(__file__).resolve().parents[1]
    bad = []
    for pkg in ("analysis", "schemes", "papers"):
        for f in (root / pkg).rglob("*.py"):
            if f.name == "reader.py" and f.parent.name == "algebra":
                continue
            for i, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
                code = line.split("#")[0]
                if re.search(r"(?<![.\w])(parse_expr|eval|exec)\(|sympify\(|\bS\(\s*['\"]", code) and \
                        not (f.name == "jsonable.py" and "strict=True" in code):
                    bad.append(f"{f.relative_to(root)}:{i}: {line.strip()}")
    assert not bad, "\n".join(bad)
