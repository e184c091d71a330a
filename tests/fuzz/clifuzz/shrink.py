"""Shrinking a failing case to a minimal command line that fails the same way."""

import time

from .case import clone


def shrink(case, kind, runner, budget, seconds=10.0):
    """Greedy: drop argument units, then files, while the failure kind persists (at most `budget`
    runs and about `seconds`)."""
    best = case
    runs = 0
    progress = True
    if kind in ("timeout", "big-request-slow"):
        return case   # each try would cost a timeout
    end = time.monotonic() + seconds
    while progress and runs < budget and time.monotonic() < end:
        progress = False
        for i in range(len(best.units) - 1, -1, -1):
            if runs >= budget:
                break
            cand = clone(best)
            del cand.units[i]
            runs += 1
            _, fails = runner.run(cand)
            if any(k == kind for k, _ in fails):
                best, progress = cand, True
        for i in range(len(best.files) - 1, -1, -1):
            if runs >= budget:
                break
            cand = clone(best)
            removed = cand.files.pop(i)
            cand.inputs.discard(removed.path)
            if any(f.path.startswith(removed.path + "/") for f in cand.files):
                continue
            runs += 1
            _, fails = runner.run(cand)
            if any(k == kind for k, _ in fails):
                best, progress = cand, True
    return best
