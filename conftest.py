"""Test-suite setup shared by every worker.

Compiled bytecode is kept even where the environment sets ``PYTHONDONTWRITEBYTECODE``: the suite
imports every module in each pytest-xdist worker and in hundreds of ``subdiv`` subprocesses, and
without ``__pycache__`` each of them compiles the sources again (about 12 s of CPU per worker for
the collection alone). The files go to ``__pycache__`` folders, which git ignores.
"""

import os
import sys

sys.dont_write_bytecode = False
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
