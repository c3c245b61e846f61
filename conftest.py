"""Test-suite setup shared by every worker.

Compiled bytecode is kept even where the environment sets ``PYTHONDONTWRITEBYTECODE``: the suite
imports every module in each pytest-xdist worker and in hundreds of ``subdiv`` subprocesses, and
without ``__pycache__`` each of them compiles the sources again (about 12 s of CPU per worker for
the collection alone). The files go to ``__pycache__`` folders, which git ignores.

BLAS runs one thread per process (below): the suite already runs one process per core.

Garbage collection: the collection builds a large heap that lives for the whole session (sympy,
scipy, matplotlib, every module of the package, the bundled papers and the catalogue: about 250 000
tracked objects), and every full collection traverses it again: about 0.9 s of CPU during the
collection and 1.3 s at the end of the session (pytest collects five times there), in each xdist
worker, and more during the tests. So the collector is paused while the tests are collected, and
what survives the collection is then moved to the permanent generation (``gc.freeze()``, after one
full collection, so no garbage is frozen): later collections, during the tests and at the end,
traverse only the objects created after it. Reference counting frees objects as before, and cycles
created by the tests are collected as before; only memory, never a result, depends on it.
"""

import gc
import os
import sys

import pytest

sys.dont_write_bytecode = False
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
# One BLAS thread per test process (set before numpy is imported; inherited by the xdist workers and the
# `subdiv` subprocesses). The engine's float products are small to mid-sized (a 6139 x 11 by 11 x 11 Bernstein
# screen is the largest common one); from that size on OpenBLAS starts a second thread, which on this 2-core
# machine, with the other worker busy, spins: 7.6 ms of CPU per such product instead of 0.6 ms single-threaded.
# A threaded product can differ from the one-thread product in the last bit of a few entries (rows at the
# threads' boundary); the engine's float products only screen (margins of 1e-9 and more) before exact or Arb
# decisions, and one thread computes what a one-core machine computes. Golden files: unchanged.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


@pytest.hookimpl(hookwrapper=True)
def pytest_collection(session):
    """Collect with the garbage collector paused, then freeze what survives (see the module docstring)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()
        gc.collect()
        gc.freeze()
