"""``--help``: the top-level help names every kind of scheme the tool takes, and every command's help ends
with examples that are valid command lines (parsed here, not run)."""

from __future__ import annotations

import contextlib
import io
import shlex

import pytest

from analysis.cli.common import attach_dash_values
from analysis.cli.main import EXAMPLES, build_parser, main


def _help(argv: list[str]) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit):
        main(argv)
    return out.getvalue()


def test_top_level_help_names_every_kind_of_scheme():
    text = " ".join(_help(["--help"]).split())
    assert "binary and m-ary" in text and "level-dependent" in text and "non-uniform" in text
    assert "examples:" in text


def test_every_command_has_examples():
    parser = build_parser()
    commands = parser._subparsers._group_actions[0].choices
    assert set(commands) == set(EXAMPLES)
    for name in commands:
        assert "examples:\n  subdiv " + name in _help([name, "--help"])


@pytest.mark.parametrize("line", [ln for lines in EXAMPLES.values() for ln in lines])
def test_examples_parse(line):
    parser = build_parser()
    argv = shlex.split(line)[1:]
    args = parser.parse_args(attach_dash_values(parser, argv))
    assert args.command == argv[0]
