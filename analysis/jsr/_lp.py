"""The membership linear programs of the invariant polytope, solved by HiGHS directly.

A membership test of the float polytope (:mod:`analysis.jsr._polytope`) asks for the Minkowski
norm of ``x`` in the absolutely convex hull of the columns of ``V``:

    min sum(l+ + l-)  subject to  V (l+ - l-) = x,  l+, l- >= 0.

Two solvers, both HiGHS (Huangfu–Hall dual simplex) and both without a modelling layer:

* :class:`WarmLP` is the LP over *all* vertices, one persistent ``highspy`` model: a new vertex is
  appended as a column pair, a query changes the row bounds to ``x`` only, and the dual simplex
  restarts from the previous optimal basis (Mejstrik 2020 warm-starts the same way).
* :func:`small_lp` is the LP over a few columns (the vertices best aligned with ``x``), a fresh
  model each time. It builds the very model that ``scipy.optimize.linprog(method="highs")``
  builds and passes it, with the same options, to the same HiGHS library (the copy bundled with
  SciPy), skipping linprog's input validation and option checking, which cost three times the
  solve on these 16 x 100 problems; one HiGHS object per thread takes every model (``passModel``
  clears the previous basis and solution, so nothing carries over; a test checks it). Same model, same options, same library: the same solution,
  bit for bit, as ``linprog`` (a test compares them), so polytopes, certificates and the work
  counted do not change. Without the bundled module (another SciPy layout) it calls ``linprog``.

Only the float phase uses these LPs; the certificate re-checks every membership exactly.

Examples
--------
>>> import numpy as np
>>> V = np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 1.0]])
>>> value, lam, _dual = small_lp(V, np.array([0.5, 0.5]))
>>> value, np.abs(lam).tolist()
(0.5, [0.0, 0.0, 0.5])
>>> w = WarmLP.create(2)
>>> w.sync([V[:, 0], V[:, 1]])
>>> w.solve(np.array([0.5, 0.5]))[0]
1.0

References
----------
Q. Huangfu, J. A. J. Hall, *Parallelizing the dual revised simplex method*, Math. Program.
Comput. 10 (2018) 119-142.
T. Mejstrik, *Algorithm 1011: Improved invariant polytope algorithm and applications*, ACM Trans.
Math. Softw. 46(3) (2020) 29.
"""

from __future__ import annotations

import threading
import warnings

import numpy as np

__all__ = ["WarmLP", "small_lp"]

#: HiGHS prints its banner ("Running HiGHS ...", "Includes third-party software ...") to the C
#: stdout when the first ``Highs`` object of a process is constructed — before any option such
#: as ``output_flag`` can be set; later constructions are silent.
_HIGHS_BANNER_DONE = False
_HIGHS_LOCK = threading.Lock()


def _quiet_highs(highspy):
    """A new ``highspy.Highs()``; the first one of the process is built with file descriptor 1
    pointed at ``os.devnull`` so the banner reaches no one's stdout (``--json`` output stays JSON)."""
    global _HIGHS_BANNER_DONE
    with _HIGHS_LOCK:
        if _HIGHS_BANNER_DONE:
            return highspy.Highs()
        import os
        import sys

        try:
            sys.stdout.flush()
        except (OSError, ValueError, AttributeError):
            pass
        try:
            saved = os.dup(1)
        except OSError:                       # no fd 1 at all: nothing to protect
            saved = None
        if saved is None:
            h = highspy.Highs()
        else:
            devnull = os.open(os.devnull, os.O_WRONLY)
            try:
                os.dup2(devnull, 1)
                h = highspy.Highs()
                try:                          # HiGHS flushes its log lines; make sure of it
                    import ctypes

                    ctypes.CDLL(None).fflush(None)
                except (OSError, AttributeError, TypeError):  # pragma: no cover
                    pass
            finally:
                os.dup2(saved, 1)
                os.close(saved)
                os.close(devnull)
        _HIGHS_BANNER_DONE = True
        return h


class WarmLP:
    """The membership LP over all vertices as one persistent HiGHS model (``highspy``): new
    vertices are appended as column pairs, a query only changes the row bounds to ``x``, and the
    dual simplex restarts from the previous optimal basis. Solving from scratch each time is
    5-10x slower on polytopes of 1000+ vertices."""

    def __init__(self, h, n: int):
        self.h, self.n, self.m = h, n, 0

    @classmethod
    def create(cls, n: int) -> "WarmLP | None":
        try:
            import highspy
        except ImportError:          # pragma: no cover - highspy is a dependency
            return None
        h = _quiet_highs(highspy)
        for key, val in (("output_flag", False), ("presolve", "off"), ("solver", "simplex"),
                         ("simplex_strategy", 1), ("threads", 1), ("primal_feasibility_tolerance", 1e-10),
                         ("dual_feasibility_tolerance", 1e-10)):
            h.setOptionValue(key, val)
        empty_i, empty_v = np.array([], dtype=np.int32), np.array([], dtype=np.float64)
        for _ in range(n):
            h.addRow(0.0, 0.0, 0, empty_i, empty_v)
        return cls(h, n)

    def sync(self, V: list[np.ndarray]) -> None:
        """Append the vertices ``V[m:]`` not in the model yet (each as the pair ``+v, -v``)."""
        import highspy

        for v in V[self.m:]:
            idx = np.nonzero(v)[0].astype(np.int32)
            vals = np.asarray(v[idx], dtype=np.float64)
            self.h.addCol(1.0, 0.0, highspy.kHighsInf, len(idx), idx, vals)
            self.h.addCol(1.0, 0.0, highspy.kHighsInf, len(idx), idx, -vals)
        self.m = len(V)

    def solve(self, x: np.ndarray):
        """``(value, lambda, row duals)`` or ``None`` (infeasible: ``x`` not in the span)."""
        import highspy

        h = self.h
        for i in range(self.n):
            h.changeRowBounds(i, float(x[i]), float(x[i]))
        h.run()
        if h.getModelStatus() != highspy.HighsModelStatus.kOptimal:
            return None
        sol = h.getSolution()
        col = np.asarray(sol.col_value, dtype=float)
        if len(col) != 2 * self.m:
            return None
        lam = col[0::2] - col[1::2]
        y = np.asarray(sol.row_dual, dtype=float) if sol.dual_valid else None
        return float(np.sum(np.abs(lam))), lam, y


#: linprog's acceptance test of a HiGHS solution (``scipy.optimize._linprog_util._check_result``):
#: bounds and equality residuals within ``10 sqrt(1e-9)``
_LINPROG_CHECK_TOL = float(np.sqrt(1e-9) * 10)


def _bundled_core():
    """SciPy's bundled HiGHS bindings and the options ``linprog(method="highs")`` passes, or
    ``None`` when this SciPy does not have them where expected."""
    global _CORE
    if _CORE is None:
        try:
            from scipy.optimize._highspy import _core as core

            opts = core.HighsOptions()
            opts.presolve = "on"
            opts.highs_debug_level = core.HighsDebugLevel.kHighsDebugLevelNone
            opts.log_to_console = False
            opts.output_flag = False
            opts.simplex_strategy = 1                 # dual simplex, as linprog sets it
            _CORE = (core, opts)
        except (ImportError, AttributeError):  # pragma: no cover - other SciPy layouts
            _CORE = False
    return _CORE or None


_CORE = None
#: one HiGHS object per thread for :func:`small_lp`, reused: ``passModel`` replaces the model and clears the
#: solver state (basis, solution, factorization), so a solve gives what a fresh object gives, bit for bit (a
#: test compares them); constructing the object cost a third of the solve on these small problems
_SMALL = threading.local()


def _small_highs(core):
    h = getattr(_SMALL, "highs", None)
    if h is None:
        h = _SMALL.highs = core._Highs()
    return h


def small_lp(Vm: np.ndarray, x: np.ndarray):
    """``min ||lambda||_1`` subject to ``Vm lambda = x``: ``(value, lambda, row duals)``, or
    ``None`` when HiGHS reports no optimum (``x`` outside the span) or linprog would reject the
    solution. Identical to ``linprog(ones(2m), A_eq=[Vm, -Vm], b_eq=x, bounds=(0, None),
    method="highs")`` (value ``fun``, ``lambda = x[:m] - x[m:]``, duals ``eqlin.marginals``)."""
    core = _bundled_core()
    if core is None:  # pragma: no cover - other SciPy layouts
        return _linprog_lp(Vm, x)
    h_, opts = core
    n, m = Vm.shape
    At = np.concatenate([Vm.T, -Vm.T])            # the columns of [Vm, -Vm], as rows
    nz = At != 0                                  # compressed sparse columns, as scipy builds them
    _, rows = np.nonzero(nz)
    start = np.zeros(2 * m + 1, dtype=np.int32)
    np.cumsum(nz.sum(axis=1), out=start[1:])
    xb = np.array(x, dtype=float)
    lp = h_.HighsLp()
    lp.num_col_ = 2 * m
    lp.num_row_ = n
    lp.a_matrix_.num_col_ = 2 * m
    lp.a_matrix_.num_row_ = n
    lp.a_matrix_.format_ = h_.MatrixFormat.kColwise
    lp.col_cost_ = np.ones(2 * m)
    lp.col_lower_ = np.zeros(2 * m)
    lp.col_upper_ = np.full(2 * m, h_.kHighsInf)
    lp.row_lower_ = xb
    lp.row_upper_ = xb
    lp.a_matrix_.start_ = start
    lp.a_matrix_.index_ = rows.astype(np.int32)
    lp.a_matrix_.value_ = At[nz]
    h = _small_highs(h_)
    h.passOptions(opts)
    h.passModel(lp)
    h.run()
    if h.getModelStatus() != h_.HighsModelStatus.kOptimal:
        return None
    sol = h.getSolution()
    col = np.array(sol.col_value)
    con = xb - np.array(sol.row_value)
    fun = h.getInfo().objective_function_value
    if np.isnan(col).any() or np.isnan(fun) or np.isnan(con).any() \
            or (col < -_LINPROG_CHECK_TOL).any() or (np.abs(con) > _LINPROG_CHECK_TOL).any():
        return None
    return float(fun), col[:m] - col[m:], np.array(sol.row_dual)


def _linprog_lp(Vm: np.ndarray, x: np.ndarray):
    """:func:`small_lp` through ``scipy.optimize.linprog`` (the reference it must equal)."""
    from scipy.optimize import linprog

    m = Vm.shape[1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = linprog(np.ones(2 * m), A_eq=np.hstack([Vm, -Vm]), b_eq=x, bounds=(0, None),
                      method="highs")
    if res.status != 0 or res.x is None:
        return None
    return float(res.fun), res.x[:m] - res.x[m:], np.asarray(res.eqlin.marginals, dtype=float)
