"""Two-parameter atlases of the Hölder exponent: certified alpha enclosures on a refined grid.

:func:`holder_atlas` takes a symbol with two free parameters (fix any others first with
``symbol.subs``), evaluates a certified enclosure of the Hölder exponent alpha
(:func:`analysis.regularity.holder.holder_exponent`) and certified C^j verdicts at exact rational grid
points, refines the cells where the C^j verdicts of the corners differ, and runs the point
evaluations in parallel — local processes, a Dask cluster, or serially. :func:`plot_atlas`
draws the result as a heat map with the C^j boundaries.

Every sample is exact: the parameter values are rationals, the symbol is substituted exactly, and
the enclosure ``[alpha_lower, alpha_upper]`` is rigorous (JSR bounds in exact/ball arithmetic).
Between samples nothing is proven: the atlas is a *map*, and the boundaries it shows are
located to the final grid spacing only (:func:`analysis.regularity.ranges.ck_parameter_set` locates a
one-parameter boundary exactly).

Examples
--------
A two-parameter family through the linear (s = t = 0), cubic (s = 1/4, t = 0) and quintic
(s = 1/4, t = 1/16) B-splines: ``a(z) = (1+z)^2/(2z) (1 + s (z - 2 + 1/z) + t (z^2 - 2 + z^-2))``.

>>> import sympy as sp
>>> from analysis.algebra.symbol import LaurentSymbol
>>> z, s, t = sp.symbols("z s t")
>>> a = LaurentSymbol.from_expr((1 + z)**2 / (2*z) * (1 + s*(z - 2 + 1/z) + t*(z**2 - 2 + z**-2)))
>>> r = holder_atlas(a, "s", (0, "1/4"), "t", (0, 0), n1=3, n2=1, j_levels=(1, 2),
...                  executor=None, progress=False)
>>> [(str(p["p1"]), p["alpha"], p["C^1"], p["C^2"], p["exceptional"]) for p in r.value]
[('0', 1, False, False, False), ('1/16', None, True, False, False), ('1/8', None, True, False, False), ('1/4', 3, True, True, True)]
>>> r.status, r.witness["counts"]["per_level"]      # s = 0 and 1/8 disagree on C^1: 1/16 added
('certified', [3, 1])
>>> r.witness["exceptional"][0]                     # s = 1/4: four factors (1+z) instead of two
{'condition': {'s': 1/4}, 'factors': 4}

Algorithm
---------
1. The grid: ``n1 x n2`` rational points ``lo + (hi - lo) i / (n - 1)``, on a lattice ``2^R``
   times finer (``R = refine_levels``) so that refined points stay exact and shared.
2. Each point: substitute, ``holder_exponent`` (budgeted), and for every ``j`` a C^j verdict
   read off the enclosure (``alpha_lower > j``: C^j; ``alpha_upper <= j``: not C^j); only when
   the enclosure straddles ``j`` is :func:`analysis.regularity.holder.smoothness` called (exact
   borderline analysis). ``j`` above the number of factors ``(1+z)`` minus one is "not C^j".
3. Refinement, level by level: a cell whose four corners disagree on some C^j verdict (an
   undecided verdict counts as a disagreement) is cut into four; the new corners are evaluated
   in one parallel batch; only the children of refined cells are candidates at the next level.
   Corners on an *exceptional set* (parameters where ``a`` has more factors ``(1+z)`` than
   generically, e.g. ``mu = omega`` for seed 004's (3.6)) are left out of the comparison: alpha
   jumps up there, but the set is known exactly from the factorization (``witness
   ["exceptional"]``) and has measure zero, so refining around it would be wasted work.
4. Parallelism: the tasks are plain tuples (the mask's sympy coefficients, the lowest exponent,
   the parameter names, the exact values), rebuilt in the worker, so any pickling executor can
   run them: :class:`concurrent.futures.ProcessPoolExecutor` (``executor="local"``), a Dask
   cluster (``executor="dask://host:port"``, via ``distributed.Client.map`` and
   ``distributed.as_completed``), or in process (``executor=None``). Results do not depend on
   the executor: the budget of each JSR computation counts work, not time. The tasks of one process
   run one at a time (python-flint's precision is global to a process, so threads of a Dask worker or a
   thread pool would change each other's enclosures).

References
----------
O. Rioul, *Simple regularity criteria for subdivision schemes*, SIAM J. Math. Anal. 23 (1992).
I. Daubechies, J. Lagarias, *Two-scale difference equations II*, SIAM J. Math. Anal. 23 (1992).
N. Guglielmi, V. Protasov, *Exact computation of joint spectral characteristics of linear
operators*, Found. Comput. Math. 13 (2013).
M. Rocklin, *Dask: parallel computation with blocked algorithms and task scheduling*, Proc.
SciPy 2015 (the ``distributed`` scheduler).
"""

from __future__ import annotations

import functools
import os
import threading
import time
from typing import Any, Iterable, Mapping, Sequence

import sympy as sp

from ..result import CERTIFIED, INCONCLUSIVE, AnalysisError, Result
from ..algebra.symbol import LaurentSymbol
from ..algebra.reader import as_expr
from .atlas_axes import MAX_GRID_POINTS, _check_points, _parse_range

__all__ = ["holder_atlas", "plot_atlas", "evaluate_point", "DEFAULT_J_LEVELS"]

#: The C^j verdicts computed when ``j_levels`` is not given.
DEFAULT_J_LEVELS = (1, 2, 3)

#: Refuse atlases with more refinement levels than this (each level can quadruple the points).
MAX_REFINE_LEVELS = 8

#: Local worker processes at most (``--workers``).
MAX_WORKERS = 64


# --------------------------------------------------------------------------------------------
# one point (runs in the workers)
# --------------------------------------------------------------------------------------------

@functools.lru_cache(maxsize=16)
def _rebuild(mask: tuple[sp.Expr, ...], start: int, names: tuple[str, ...]) -> LaurentSymbol:
    params = tuple(sp.Symbol(n) for n in names)
    return LaurentSymbol.from_mask(list(mask), start=start, params=params)


def _payload(symbol: LaurentSymbol) -> tuple[tuple[sp.Expr, ...], int, tuple[str, ...]]:
    """The picklable description of ``symbol``: its mask (sympy objects pickle), start, parameter names."""
    return tuple(symbol.mask), symbol.start, tuple(p.name for p in symbol.params)


def _verdicts(a: LaurentSymbol, h: Result | None, k: int | None, j_levels: Sequence[int],
              budget: float, m: int = 2) -> dict[str, Any]:
    from .holder import smoothness

    out: dict[str, Any] = {}
    for j in j_levels:
        key = f"C^{j}"
        if h is None or k is None:
            out[key] = None
        elif j > k:
            out[key] = False          # alpha <= k + 1 and C^j needs (1+z)^(j+1) | a (smoothness())
        elif h.lower is not None and h.lower > j:
            out[key] = True
        elif h.upper is not None and h.upper <= j:
            out[key] = False
        else:
            out[key] = smoothness(a, j, budget=budget, arity=m).value
    return out


def evaluate_point(symbol: LaurentSymbol, values: Mapping[str, Any], j_levels: Sequence[int] = DEFAULT_J_LEVELS,
                   budget: int = 2_000, *, arity: int = 2) -> dict[str, Any]:
    """Certified alpha enclosure and C^j verdicts of ``symbol.subs(values)`` (one atlas sample), arity ``m``:
    ``alpha = k - log_m JSR(T_0, ..., T_{m-1})``; ``j > k`` is not C^j (too few factors ``q_m``).

    Returns a dict with ``alpha_lower``, ``alpha_upper`` (rationals), ``alpha`` (exact when
    known), ``alpha_exact`` (a closed form such as ``"3 - log2(rho(T_01))/2"`` when the JSR is
    proven attained), ``k`` (factors ``(1+z)`` minus one), ``status``, one ``"C^j"`` entry per
    ``j`` (True / False / None = undecided), ``timing`` (``{"seconds": ...}``, wall clock, reported
    only), and ``note`` when the point could not be analysed (e.g. the sum rules fail there).
    ``budget``: work units of each JSR computation (:func:`analysis.jsr.jsr_bounds`).

    ``status`` is *certified* when the enclosure is certified and every verdict is decided.

    >>> from analysis.algebra.symbol import LaurentSymbol
    >>> w = sp.Symbol("w")
    >>> p = evaluate_point(LaurentSymbol.from_mask(["1/8", "1/2", "3/4", "1/2", "1/8"], start=-2), {}, (2, 3))
    >>> p["alpha"], p["C^2"], p["C^3"], p["status"]
    (3, True, False, 'certified')
    >>> s = evaluate_point(LaurentSymbol.from_expr("(1+z+z**2)**4/(27*z**4)"), {}, (2, 3), arity=3)
    >>> s["alpha"], s["C^2"], s["C^3"], s["status"]           # ternary cubic B-spline: alpha = 3
    (3, True, False, 'certified')
    """
    from ..algebra.factorization import check_arity
    from .convergence import difference_mask
    from .holder import holder_exponent

    m = check_arity(arity)
    t0 = time.perf_counter()
    a = symbol.subs(dict(values)) if values else symbol
    sample: dict[str, Any] = {"alpha_lower": None, "alpha_upper": None, "alpha": None, "alpha_exact": None,
                              "k": None, "status": INCONCLUSIVE}
    h = k = None
    try:
        k, _ = difference_mask(a, arity=m)
        h = holder_exponent(a, budget=budget, arity=m)
    except AnalysisError as exc:
        sample["note"] = str(exc)
    if h is not None:
        sample.update(alpha_lower=h.lower, alpha_upper=h.upper, alpha=h.value, k=k)
        ex = h.witness.get("alpha_exact")
        sample["alpha_exact"] = None if ex is None else (ex if isinstance(ex, str) else sp.sstr(ex))
    try:
        sample.update(_verdicts(a, h, k, j_levels, budget, m))
    except AnalysisError as exc:  # pragma: no cover - verdicts only fail where alpha failed
        sample["note"] = str(exc)
        sample.update({f"C^{j}": None for j in j_levels})
    decided = all(sample[f"C^{j}"] is not None for j in j_levels)
    sample["status"] = CERTIFIED if h is not None and h.status == CERTIFIED and decided else INCONCLUSIVE
    sample["timing"] = {"seconds": round(time.perf_counter() - t0, 4)}
    return sample


#: python-flint's working precision (``flint.ctx.prec``) is global to the process: two points evaluated at
#: once by threads of one process (a thread pool, a Dask worker with several threads) would change each
#: other's precision and hence their enclosures, so the tasks of one process run one at a time
_ONE_TASK_AT_A_TIME = threading.Lock()


def _evaluate_task(task: tuple) -> dict[str, Any]:
    """The picklable unit of work: ``(mask, start, names, ((name, "p/q"), ...), j_levels, budget, key[, arity])``."""
    mask, start, names, values, j_levels, budget, key, *m = task
    symbol, vals = _rebuild(mask, start, names), {n: sp.Rational(v) for n, v in values}
    with _ONE_TASK_AT_A_TIME:
        sample = evaluate_point(symbol, vals, j_levels, budget, arity=m[0] if m else 2)
    sample["key"] = key
    return sample


# --------------------------------------------------------------------------------------------
# executors
# --------------------------------------------------------------------------------------------

def _dask_address(executor: str) -> str:
    rest = executor[len("dask://"):].strip()
    if not rest:
        raise AnalysisError("executor 'dask://' needs a scheduler address, e.g. dask://127.0.0.1:8786")
    return rest if "://" in rest else f"tcp://{rest}"


def _check_executor(executor, workers) -> str:
    if workers is not None and (not isinstance(workers, int) or isinstance(workers, bool) or workers < 1):
        raise AnalysisError(f"workers must be a positive integer, not {workers!r}")
    if workers is not None and workers > MAX_WORKERS:
        raise AnalysisError(f"{workers} workers exceed the limit {MAX_WORKERS}: use fewer (default: all cores)")
    if executor is None or executor in ("serial", "none"):
        return "serial"
    if executor == "local":
        return "local"
    if isinstance(executor, str) and executor.startswith("dask://"):
        _dask_address(executor)
        return "dask"
    if hasattr(executor, "submit"):
        return "object"
    raise AnalysisError(f"unknown executor {executor!r}: use 'local', 'serial', or 'dask://HOST:PORT'")


class _Runner:
    """Runs batches of tasks on one executor, kept open across refinement levels."""

    def __init__(self, executor, workers: int | None, progress: bool):
        self.kind = _check_executor(executor, workers)
        self.executor = executor
        self.workers = workers
        self.progress = progress
        self._pool = None
        self._client = None
        self.description = "serial (in process)"

    def __enter__(self) -> "_Runner":
        if self.kind == "local":
            from concurrent.futures import ProcessPoolExecutor

            n = min(self.workers or os.cpu_count() or 1, MAX_WORKERS)
            self._pool = ProcessPoolExecutor(max_workers=n)
            self.description = f"local processes ({n})"
        elif self.kind == "dask":
            try:
                from distributed import Client
            except ImportError:  # pragma: no cover - a declared dependency
                raise AnalysisError("executor dask:// needs the 'distributed' package") from None
            addr = _dask_address(self.executor)
            try:
                self._client = Client(addr, timeout="10s", set_as_default=False)
            except (OSError, TimeoutError) as exc:
                raise AnalysisError(f"cannot connect to the Dask scheduler at {addr}: "
                                    f"{str(exc).splitlines()[0] if str(exc) else type(exc).__name__}") from None
            nw = len(self._client.scheduler_info().get("workers", {}))
            self.description = f"dask cluster at {addr} ({nw} workers)"
        elif self.kind == "object":
            self.description = f"{type(self.executor).__name__} (caller's executor)"
        return self

    def __exit__(self, *exc) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
        if self._client is not None:
            self._client.close()

    def run(self, tasks: list[tuple], desc: str) -> list[dict]:
        from .. import progress as announce

        step = announce.step if self.progress else (lambda n=1: None)
        if self.progress:
            announce.stage(f"{desc}: points", len(tasks))
        results: list[dict | None] = [None] * len(tasks)
        if self.kind == "serial" or not tasks:
            for i, t in enumerate(tasks):
                results[i] = _evaluate_task(t)
                step()
        elif self.kind in ("local", "object"):
            from concurrent.futures import as_completed

            pool = self._pool if self.kind == "local" else self.executor
            futures = {pool.submit(_evaluate_task, t): i for i, t in enumerate(tasks)}
            for fut in as_completed(futures):
                results[futures[fut]] = fut.result()
                step()
        else:
            from distributed import as_completed

            futures = self._client.map(_evaluate_task, tasks, pure=False)
            index = {f.key: i for i, f in enumerate(futures)}
            for fut in as_completed(futures, loop=self._client.loop):
                results[index[fut.key]] = fut.result()
                step()
        return results  # type: ignore[return-value]


# --------------------------------------------------------------------------------------------
# exceptional parameter sets (more factors (1+z): alpha may jump up there)
# --------------------------------------------------------------------------------------------

def _exceptional(symbol: LaurentSymbol, m: int = 2) -> list[dict]:
    from ..algebra.factorization import smoothing_factor

    try:
        f = smoothing_factor(symbol, arity=m)
    except AnalysisError:  # pragma: no cover - defensive
        return []
    out: list[dict] = []

    def walk(cases, acc):
        for c in cases:
            cond = dict(acc)
            cond.update({k: as_expr(v).subs(acc) for k, v in c["condition"].items()})
            cond = {k: sp.simplify(v.subs(cond)) for k, v in cond.items()}
            out.append({"condition": {str(k): v for k, v in cond.items()}, "factors": c.get("k")})
            walk(c.get("exceptional", []), cond)

    walk(f.witness.get("exceptional", []), {})
    return out


# --------------------------------------------------------------------------------------------
# the atlas
# --------------------------------------------------------------------------------------------

def holder_atlas(symbol: LaurentSymbol, p1: str, range1, p2: str, range2, *, n1: int = 9, n2: int = 9,
                 j_levels: Iterable[int] = DEFAULT_J_LEVELS, refine_levels: int = 1,
                 executor="local", workers: int | None = None, budget: int = 2_000,
                 progress: bool = True, arity: int = 2) -> Result:
    """Certified Hölder-exponent enclosures and C^j verdicts on an adaptively refined 2-D grid.

    Parameters
    ----------
    symbol
        A :class:`LaurentSymbol` whose free parameters are exactly ``p1`` and ``p2`` (substitute
        the others first: ``symbol.subs({"omega": 0})``).
    p1, p2
        Parameter names (x and y axis).
    range1, range2
        ``(low, high)`` exact rationals (``"-1/5"``, ``"0.2"`` = 1/5, ints) or ``"LO:HI"``.
    n1, n2
        Grid points per axis, ends included (``n = 1`` needs ``low == high``).
    j_levels
        The ``j`` of the C^j verdicts; refinement follows their boundaries.
    refine_levels
        How many times a cell with disagreeing corner verdicts may be cut in four (0: plain grid).
    executor
        ``"local"`` (a process pool), ``"dask://HOST:PORT"`` (a running Dask scheduler; the workers
        must be able to import ``analysis``), ``None``/``"serial"`` (in process), or any object with
        a ``concurrent.futures``-style ``submit``.
    workers
        Local processes (default: all cores); ignored for Dask.
    budget
        Work budget of each JSR computation, in the work units of :func:`analysis.jsr.jsr_bounds`
        (counted, never timed: about a millisecond each on the reference machine, so the atlas
        does not depend on the machine, its load or the executor); a point that runs out is
        *inconclusive* but keeps a rigorous (wider) enclosure.
    progress
        Announce the points done to :mod:`analysis.progress` (``subdiv atlas`` shows them on a terminal);
        False: silent even when someone listens.
    arity
        ``m`` of an m-ary family (factors ``1+...+z^{m-1}``, ``alpha = k - log_m JSR``); default 2.

    Returns
    -------
    Result
        ``value``: the samples, sorted by ``(p1, p2)``, each a dict with ``p1``, ``p2`` (exact),
        ``alpha_lower``, ``alpha_upper``, ``alpha`` (exact when known), ``alpha_exact``, ``k``,
        ``status``, ``"C^j"`` verdicts (True/False/None), ``level`` (0 = initial grid), ``index``
        (lattice coordinates) and ``exceptional`` (more factors ``(1+z)`` than generic).
        ``status``: *certified* when every sample is.
        ``witness``: ``grid`` (names, ranges, sizes, ``refine_levels``, ``j_levels``, lattice step),
        ``counts`` (samples, certified, inconclusive, per level, refined cells per level, C^j
        tallies), ``exceptional`` (parameter sets with more factors ``(1+z)``, where alpha can jump
        up), ``executor``. ``provenance["timing"]``: ``seconds`` (wall), ``task_seconds`` (sum over
        samples) and ``samples`` (each sample's seconds, in the order of ``value``).

    Examples
    --------
    See the module docstring; :func:`plot_atlas` draws the result.
    """
    t_start = time.perf_counter()
    if not isinstance(symbol, LaurentSymbol):
        raise AnalysisError("holder_atlas needs a LaurentSymbol")
    p1, p2 = str(p1), str(p2)
    if p1 == p2:
        raise AnalysisError(f"the two axes must be different parameters (both are {p1!r})")
    names = {p.name for p in symbol.params}
    for p in (p1, p2):
        if p not in names:
            known = ", ".join(sorted(names)) or "none"
            raise AnalysisError(f"unknown parameter {p!r} (this symbol's parameters: {known})")
    others = sorted(names - {p1, p2})
    if others:
        raise AnalysisError(f"free parameter(s) {', '.join(others)} not on an axis: fix them first "
                            f"(symbol.subs, or --param {others[0]}=VALUE)")
    lo1, hi1 = _parse_range(range1, p1)
    lo2, hi2 = _parse_range(range2, p2)
    for n, p, lo, hi in ((n1, p1, lo1, hi1), (n2, p2, lo2, hi2)):
        if not isinstance(n, int) or isinstance(n, bool) or n < 1:
            raise AnalysisError(f"the number of points of {p} must be a positive integer, not {n!r}")
        if n == 1 and lo != hi:
            raise AnalysisError(f"one point for {p} needs low == high; use at least 2 points")
        if n > 1 and lo == hi:
            raise AnalysisError(f"the range of {p} is a single value: use 1 point or low < high")
        _check_points(p, n)
    if n1 * n2 > MAX_GRID_POINTS:
        raise AnalysisError(f"a grid of {n1} x {n2} = {n1 * n2} points exceeds the limit {MAX_GRID_POINTS}: "
                            "use fewer points per axis, and --refine to add points where the verdicts change")
    if not isinstance(refine_levels, int) or isinstance(refine_levels, bool) \
            or not 0 <= refine_levels <= MAX_REFINE_LEVELS:
        raise AnalysisError(f"refine_levels must be an integer between 0 and {MAX_REFINE_LEVELS}")
    try:
        js = tuple(sorted({int(j) for j in j_levels}))
    except (TypeError, ValueError):
        raise AnalysisError("j_levels must be a list of integers") from None
    if not js or js[0] < 0:
        raise AnalysisError("j_levels must be a non-empty list of integers >= 0")
    try:
        budget = int(float(budget))
    except (TypeError, ValueError, OverflowError):
        raise AnalysisError(f"budget must be a number of work units, not {budget!r}") from None
    if not budget > 0:
        raise AnalysisError("budget must be a positive number of work units")
    _check_executor(executor, workers)

    R = refine_levels
    scale = 2 ** R
    N1, N2 = (n1 - 1) * scale, (n2 - 1) * scale   # lattice index ranges 0..N

    def coord(i: int, N: int, lo, hi):
        return lo if N == 0 else lo + (hi - lo) * sp.Rational(i, N)

    mask, start, pnames = _payload(symbol)
    samples: dict[tuple[int, int], dict] = {}
    # an axis with one point is a fixed value: 'generic' refers to the sampled set
    fixed = {p: lo for p, n, lo in ((p1, n1, lo1), (p2, n2, lo2)) if n == 1}
    region = symbol.subs(fixed) if fixed else symbol
    from ..algebra.factorization import check_arity
    generic_k = _generic_k(region, check_arity(arity))

    def tasks_for(keys):
        out = []
        for (i, j) in keys:
            vals = ((p1, str(coord(i, N1, lo1, hi1))), (p2, str(coord(j, N2, lo2, hi2))))
            out.append((mask, start, pnames, vals, js, budget, (i, j)) + ((arity,) if arity != 2 else ()))
        return out

    per_level, refined_cells = [], []
    with _Runner(executor, workers, progress) as runner:
        keys0 = [(i * scale, j * scale) for i in range(n1) for j in range(n2)]
        for s in runner.run(tasks_for(keys0), "atlas grid"):
            s["level"] = 0
            samples[tuple(s["key"])] = s
        per_level.append(len(keys0))
        cells = [(i * scale, j * scale, scale) for i in range(max(n1 - 1, 1)) for j in range(max(n2 - 1, 1))]
        for level in range(1, R + 1):
            split = [c for c in cells if _disagree(c, samples, js, N1, N2, generic_k)]
            refined_cells.append(len(split))
            half = scale >> level
            children, new_keys = [], []
            seen = set(samples)
            for (i, j, size) in split:
                for di in (0, half):
                    for dj in (0, half):
                        children.append((i + di, j + dj, half))
                for di in (0, half, size):
                    for dj in (0, half, size):
                        key = (min(i + di, N1), min(j + dj, N2))
                        if key not in seen:
                            seen.add(key)
                            new_keys.append(key)
            new_keys.sort()
            for s in runner.run(tasks_for(new_keys), f"atlas refine {level}/{R}"):
                s["level"] = level
                samples[tuple(s["key"])] = s
            per_level.append(len(new_keys))
            cells = children
            if not children:
                refined_cells.extend([0] * (R - level))
                per_level.extend([0] * (R - level))
                break
        description = runner.description

    rows, sample_seconds = [], []
    for (i, j), s in sorted(samples.items()):
        s = dict(s)
        s.pop("key", None)
        sample_seconds.append((s.pop("timing", None) or {}).get("seconds"))
        row = {"p1": coord(i, N1, lo1, hi1), "p2": coord(j, N2, lo2, hi2), "index": (i, j)}
        row.update(s)
        row["exceptional"] = _is_exceptional(row, generic_k)
        rows.append(row)
    certified = sum(1 for r in rows if r["status"] == CERTIFIED)
    tallies = {f"C^{j}": {"yes": sum(1 for r in rows if r[f"C^{j}"] is True),
                          "no": sum(1 for r in rows if r[f"C^{j}"] is False),
                          "undecided": sum(1 for r in rows if r[f"C^{j}"] is None)} for j in js}
    wall = time.perf_counter() - t_start
    witness = {
        "grid": {"p1": {"name": p1, "range": (lo1, hi1), "n": n1},
                 "p2": {"name": p2, "range": (lo2, hi2), "n": n2},
                 "refine_levels": R, "j_levels": js,
                 "lattice_step": (sp.Rational(0) if N1 == 0 else (hi1 - lo1) / N1,
                                  sp.Rational(0) if N2 == 0 else (hi2 - lo2) / N2)},
        "counts": {"samples": len(rows), "certified": certified, "inconclusive": len(rows) - certified,
                   "per_level": per_level, "refined_cells": refined_cells, "verdicts": tallies},
        "exceptional": _exceptional(region, arity),
        "generic_k": generic_k,
        "exceptional_samples": sum(1 for r in rows if r["exceptional"]),
        "executor": description, **({"arity": arity} if arity != 2 else {}),
    }
    return Result(value=rows, status=CERTIFIED if certified == len(rows) else INCONCLUSIVE, witness=witness,
                  provenance={"method": "certified Hölder enclosures (alpha = k - log2 JSR) at exact rational "
                                        "points; cells with disagreeing C^j corner verdicts refined",
                              "budget": budget, "symbol": symbol,
                              "caveat": "between samples the map is interpolated, not proven",
                              "timing": {"seconds": round(wall, 3),
                                         "task_seconds": round(sum(x or 0 for x in sample_seconds), 3),
                                         "samples": sample_seconds}})


def _generic_k(symbol: LaurentSymbol, m: int = 2) -> int | None:
    """``N - 1`` for the generic number ``N`` of factors ``q_m`` (``(1+z)`` for ``m = 2``) of the family."""
    from ..algebra.factorization import smoothing_factor

    try:
        return int(smoothing_factor(symbol, exceptional=False, arity=m).value) - 1
    except (AnalysisError, TypeError, ValueError):  # pragma: no cover - defensive
        return None


def _is_exceptional(sample: Mapping, generic_k: int | None) -> bool:
    """Does the sample lie on an exceptional set (more factors ``(1+z)`` than generic)?"""
    return generic_k is not None and sample.get("k") is not None and sample["k"] > generic_k


def _disagree(cell, samples, js, N1, N2, generic_k=None) -> bool:
    """Do the generic corners of ``cell`` disagree on a C^j verdict?

    Corners on an exceptional set (more factors ``(1+z)``, known exactly from the factorization)
    are left out: a jump of alpha there is explained, and refining around it would only resolve
    a set of measure zero that the factorization already gives exactly.
    """
    i, j, size = cell
    corners = {(min(i + di, N1), min(j + dj, N2)) for di in (0, size) for dj in (0, size)}
    pts = [samples[c] for c in corners if c in samples and not _is_exceptional(samples[c], generic_k)]
    return any(len({p[f"C^{k}"] for p in pts}) > 1 for k in js)


# --------------------------------------------------------------------------------------------
# the figure
# --------------------------------------------------------------------------------------------

def _mid(row) -> float:
    lo, hi = row.get("alpha_lower"), row.get("alpha_upper")
    vals = [float(v) for v in (lo, hi) if v is not None]
    return sum(vals) / len(vals) if vals else float("nan")


def plot_atlas(result: Result, path, *, title: str | None = None, cmap: str = "viridis") -> str:
    """Write a heat map of an atlas (PNG/PDF/SVG by the file extension); returns the path.

    Colour: the midpoint of each certified alpha enclosure, interpolated on a Delaunay
    triangulation of the generic samples. Samples on an exceptional set (more factors (1+z),
    where alpha jumps up) are drawn as squares in their own colour on the same scale, never
    interpolated, and the exceptional sets themselves as dashed magenta lines / stars. Lines: the
    C^j boundaries, drawn as the 1/2-level contour of the certified C^j verdict of the generic
    samples (1 = C^j, 0 = not, undecided = 1/2), i.e. midway between samples with different
    verdicts. Black dots: samples; red crosses: inconclusive samples.

    Uses matplotlib's Agg canvas only (no display, no pyplot state).
    """
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.tri import Triangulation

    rows = list(result.value or [])
    grid = result.witness.get("grid", {})
    if not rows or "p1" not in grid:
        raise AnalysisError("plot_atlas needs the Result of holder_atlas")
    n1, n2 = grid["p1"]["name"], grid["p2"]["name"]
    js, m = list(grid.get("j_levels", ())), result.witness.get("arity", 2)
    q = "(1+z)" if m == 2 else f"(1+...+z^{m - 1})"
    x = np.array([float(r["p1"]) for r in rows])
    y = np.array([float(r["p2"]) for r in rows])
    al = np.array([_mid(r) for r in rows])
    exc = np.array([bool(r.get("exceptional")) for r in rows])
    gen = ~exc
    finite = al[np.isfinite(al)]
    vmin, vmax = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    if vmin == vmax:
        vmin, vmax = vmin - 0.5, vmax + 0.5

    fig = Figure(figsize=(7.5, 5.8))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    handles = []
    xg, yg, ag = x[gen], y[gen], al[gen]
    two_d = len(set(xg)) > 1 and len(set(yg)) > 1 and len(set(zip(xg, yg))) >= 3
    mappable = None
    if two_d:
        try:
            tri = Triangulation(xg, yg)
        except (ValueError, RuntimeError):  # collinear generic samples
            two_d = False
    if two_d:
        bad = ~np.isfinite(ag)
        if bad.any():
            tri.set_mask(bad[tri.triangles].any(axis=1))
        vals = np.where(np.isfinite(ag), ag, vmin)
        mappable = ax.tripcolor(tri, vals, shading="gouraud", cmap=cmap, vmin=vmin, vmax=vmax)
        styles = ["-", "--", "-.", ":"]
        colours = ["white", "orange", "red", "cyan", "black", "magenta"]
        gen_rows = [r for r, g in zip(rows, gen) if g]
        for n, j in enumerate(js):
            ind = np.array([0.5 if r[f"C^{j}"] is None else float(bool(r[f"C^{j}"])) for r in gen_rows])
            if ind.min() < ind.max():
                col, ls = colours[n % len(colours)], styles[n % len(styles)]
                ax.tricontour(tri, ind, levels=[0.5], colors=col, linestyles=ls, linewidths=1.6)
                handles.append(Line2D([], [], color=col, ls=ls, label=f"C^{j} boundary"))
    else:
        mappable = ax.scatter(xg, yg, c=ag, cmap=cmap, vmin=vmin, vmax=vmax, s=60)
    if exc.any():
        sc = ax.scatter(x[exc], y[exc], c=al[exc], cmap=cmap, vmin=vmin, vmax=vmax, s=38, marker="s",
                        edgecolors="magenta", linewidths=1.2, zorder=3)
        mappable = mappable if mappable is not None else sc
        handles.append(Line2D([], [], color="magenta", marker="s", mfc="none", ls="",
                              label=f"sample with more factors {q}"))
    fig.colorbar(mappable, ax=ax, label="Hölder exponent α (midpoint of the certified enclosure)")
    ax.plot(x, y, "k.", ms=2.5)
    handles.append(Line2D([], [], color="k", marker=".", ls="", label="sample"))
    inc = [r["status"] != CERTIFIED for r in rows]
    if any(inc):
        ax.plot(x[np.array(inc)], y[np.array(inc)], "rx", ms=7, mew=1.5)
        handles.append(Line2D([], [], color="r", marker="x", ls="", label="inconclusive"))
    # exceptional curves x = e(y) or y = e(x), and points
    (xlo, xhi), (ylo, yhi) = [tuple(float(v) for v in grid[k]["range"]) for k in ("p1", "p2")]
    drew = False
    for ex in result.witness.get("exceptional", []):
        cond = {k: as_expr(v) for k, v in ex["condition"].items()}
        sym = {n1: sp.Symbol(n1), n2: sp.Symbol(n2)}
        if len(cond) == 1:
            (name, expr), = cond.items()
            other = n2 if name == n1 else n1
            if name not in sym or expr.free_symbols - {sym[other]}:
                continue
            f = sp.lambdify(sym[other], expr, "numpy")
            if name == n1:
                ys = np.linspace(ylo, yhi, 50)
                xs = np.broadcast_to(np.asarray(f(ys), dtype=float), ys.shape)
            else:
                xs = np.linspace(xlo, xhi, 50)
                ys = np.broadcast_to(np.asarray(f(xs), dtype=float), xs.shape)
            ax.plot(xs, ys, color="magenta", ls=(0, (4, 3)), lw=1.0)
            drew = True
        elif len(cond) == 2 and set(cond) == {n1, n2} and all(not v.free_symbols for v in cond.values()):
            ax.plot([float(cond[n1])], [float(cond[n2])], marker="*", color="magenta", ms=11, ls="")
            drew = True
    if drew:
        handles.append(Line2D([], [], color="magenta", ls=(0, (4, 3)), marker="*",
                              label=f"more factors {q}"))
    ax.set_xlim(xlo - 1e-9, xhi + 1e-9) if xlo == xhi else ax.set_xlim(xlo, xhi)
    if ylo != yhi:
        ax.set_ylim(ylo, yhi)
    ax.set_xlabel(n1)
    ax.set_ylabel(n2)
    c = result.witness.get("counts", {})
    ax.set_title(title or f"Hölder exponent α({n1}, {n2}): {c.get('samples', len(rows))} samples, "
                          f"{c.get('inconclusive', 0)} inconclusive", fontsize=10)
    ax.legend(handles=handles, loc="upper left", fontsize=7, framealpha=0.8)
    path = os.fspath(path)
    fig.savefig(path, dpi=140, bbox_inches="tight")
    return path
