"""Arguments of the level-dependent commands (``series``, ``holder``, ``reproduce``; every arity, every level map).

One reading of ``--box NAME=LOW,HIGH`` (repeatable), of ``--param`` together with ``--box``, and of ``--C K``
for :mod:`analysis.cli.levels` (every arity: ``--arity M``) and :mod:`analysis.cli.levels_rational` (the level through n itself).

Examples
--------
>>> import argparse
>>> param_box_values(argparse.Namespace(param=["omega=1/100"], box=["alpha=0,pi/3"]))
{'omega': 1/100, 'alpha': (0, pi/3)}
>>> k_max_arg(argparse.Namespace(C="x"))
Traceback (most recent call last):
...
analysis.result.AnalysisError: --C must be an integer, not 'x'
"""

from __future__ import annotations

from .common import read_number
from ..result import AnalysisError
from .common import _parse_params


def parse_boxes(items, example: str = "alpha=1/10,pi/3") -> dict:
    """``--box NAME=LOW,HIGH`` (repeatable) as ``{name: (low, high)}`` with numeric exact ends (``example``:
    the one the error message shows).

    >>> parse_boxes(["alpha=1/10,pi/3"])
    {'alpha': (1/10, pi/3)}
    >>> parse_boxes(["alpha=1"])
    Traceback (most recent call last):
    ...
    analysis.result.AnalysisError: malformed --box 'alpha=1': use NAME=LOW,HIGH, e.g. alpha=1/10,pi/3
    """
    out = {}
    for item in items or []:
        if "=" not in item or "," not in item:
            raise AnalysisError(f"malformed --box {item!r}: use NAME=LOW,HIGH, e.g. {example}")
        name, rng = (x.strip() for x in item.split("=", 1))
        lo, hi = (read_number(x.strip(), f"--box {name}") for x in rng.split(",", 1))
        if name in out:
            raise AnalysisError(f"--box {name} is given twice: give it once")
        out[name] = (lo, hi)
    return out


def param_box_values(args, example: str = "alpha=1/10,pi/3") -> dict:
    """``--param NAME=VALUE`` and ``--box NAME=LOW,HIGH`` together (a name given by both is an error)."""
    v = _parse_params(getattr(args, "param", None))
    box = parse_boxes(getattr(args, "box", None), example)
    both = sorted(set(v) & set(box))
    if both:
        raise AnalysisError(f"{both[0]} is given both by --param and by --box: give one of them")
    v.update(box)
    return v


def k_max_arg(args) -> int | None:
    """``--C K`` of ``subdiv holder`` on a level-dependent scheme: the largest k to decide (None: all)."""
    if args.C is None:
        return None
    try:
        k_max = int(args.C)
    except ValueError:
        raise AnalysisError(f"--C must be an integer, not {args.C!r}") from None
    if k_max < 0:
        raise AnalysisError("--C must be >= 0")
    return k_max


def stationary_options_refused(args) -> None:
    """``--approx``/``--sobolev`` are stationary-only: a one-line error on a level-dependent scheme."""
    if getattr(args, "approx", False) or getattr(args, "sobolev", False):
        raise AnalysisError("--approx and --sobolev are for stationary schemes; this scheme depends on the level n")
