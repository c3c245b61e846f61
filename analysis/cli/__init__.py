"""The ``subdiv`` command: parsing, one module per command group, output (text or one JSON document).

Only this layer parses command lines and prints. :mod:`.main` builds the parser and runs a
command; the command groups register themselves (:data:`~analysis.cli.main.COMMAND_MODULES`).
Layering: the top layer; it may import everything, and nothing in :mod:`analysis` imports it.
"""

from .main import build_parser, main

__all__ = ["build_parser", "main"]
