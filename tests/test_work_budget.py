"""Work budgets decide, the wall clock only reports (DESIGN.md, "Determinism"): the budget helper
(:mod:`analysis.jsr._work`): shares sum to the whole, exhaustion is a count."""

from __future__ import annotations

import pytest

from analysis.jsr._work import Work


@pytest.mark.parametrize("total, weights", [(1000, [1, 1, 2]), (7, [1, 1, 1]), (10_001, [9, 16, 1, 4]),
                                            (3, [5, 0, 5]), (0, [1, 2]), (5, [0, 0])])
def test_split_shares_sum_to_the_whole(total, weights):
    w = Work(total)
    w.charge(total // 3)
    parts = w.split(weights)
    assert sum(p.total for p in parts) == w.left
    assert all(p.total >= 0 for p in parts)
    if sum(weights) > 0:              # in proportion, to one unit
        for p, wt in zip(parts, weights):
            assert abs(p.total - w.left * wt / sum(weights)) < 1


def test_shares_charge_their_parent_and_exhaust_by_count():
    w = Work(100)
    s = w.share(0.25)
    assert (s.total, s.exhausted, w.left) == (25, False, 100)
    for _ in range(24):
        s.charge()
    assert not s.exhausted and w.spent == 24
    s.charge()
    assert s.exhausted and w.left == 75 and not w.exhausted
    grand = s.sub(10)                 # nothing left in s: an empty child, exhausted at once
    assert grand.total == 0 and grand.exhausted
    t = w.sub(10 ** 9)                # never more than what is left
    assert t.total == 75
    t.charge(80)                      # the last step may overrun
    assert t.exhausted and w.exhausted and w.left == 0


def test_exhaustion_is_deterministic():
    def run():
        w, trace = Work(1000), []
        phases = [w.share(f) for f in (0.25, 0.5)]
        for i, p in enumerate(phases):
            while not p.exhausted:
                p.charge(7 + i)
                trace.append((i, p.spent, w.left))
        return trace
    assert run() == run()


@pytest.mark.parametrize("bad", [-1, float("inf"), float("nan"), "10"])
def test_bad_budgets_are_refused(bad):
    with pytest.raises(ValueError):
        Work(bad)
