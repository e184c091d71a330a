"""The report of a run: counts per exit code and per failure kind, failing cases as shell
reproducers, the first case of each failure kind shrunk."""

import sys
import time

from .content import NOTES
from .reproducer import reproducer
from .shrink import shrink


def tally(results):
    """Counts per exit code ("exit 0", "exit 2", "other"), failing cases per failure kind, and
    the failing case indices, in index order."""
    counts = {"exit 0": 0, "exit 2": 0, "other": 0}
    by_kind = {}
    failing = []
    for i in sorted(results):
        c, o, fails = results[i]
        key = "exit 0" if o["rc"] == 0 and not o["timed_out"] else \
            "exit 2" if o["rc"] == 2 and not o["timed_out"] else "other"
        counts[key] += 1
        if fails:
            failing.append(i)
            for k in sorted({k for k, _ in fails}):
                by_kind.setdefault(k, []).append(i)
    return counts, by_kind, failing


def print_failures(results, failing, by_kind, seed, binary, max_print, runner, shrink_budget,
                   shrink_seconds):
    """Each failing case (the first `max_print`) with a reproducer, then the first case of each
    failure kind shrunk (at most `shrink_budget` runs each, `shrink_seconds` in all)."""
    print(f"FAILURES (seed {seed}); rerun one case: SELFALIGN_FUZZ_SEED={seed} "
          f"{sys.argv[0]} --binary {binary} --only N --verbose\n")
    for i in failing[: max_print]:
        c, o, fails = results[i]
        print(f"case {i} [{', '.join(sorted({k for k, _ in fails}))}]  ({'; '.join(c.tags)})")
        for k, d in fails:
            print(f"  {k}: {d}")
        print(f"  reproduce: {reproducer(c, binary)}")
    if len(failing) > max_print:
        print(f"... and {len(failing) - max_print} more failing cases")
    if shrink_budget > 0:
        print("\nMINIMAL REPRODUCERS (first case of each failure kind, shrunk):")
        shrink_end = time.monotonic() + shrink_seconds
        for k in sorted(by_kind):
            c = results[by_kind[k][0]][0]
            small = shrink(c, k, runner, shrink_budget, max(0.0, shrink_end - time.monotonic()))
            print(f"  {k} (case {c.index}, {len(by_kind[k])} cases): {reproducer(small, binary)}")


def print_summary(seed, results, elapsed, jobs, asan, counts, failing, by_kind, skipped, budget):
    """The last lines: counts per exit code, failing cases per failure kind, notes, budget."""
    print(f"\nselfalign CLI fuzz: seed {seed}, {len(results)} cases in {elapsed:.1f} s "
          f"({jobs} jobs{', asan' if asan else ''}): exit 0: {counts['exit 0']}, "
          f"exit 2: {counts['exit 2']}, other: {counts['other']}; failing cases: {len(failing)}")
    for k in sorted(by_kind, key=lambda k: -len(by_kind[k])):
        print(f"  {k}: {len(by_kind[k])}")
    if NOTES:
        print(f"  note: {len(NOTES)} sweep cells with status failed (documented; e.g. {NOTES[0]})")
    if skipped:
        print(f"  budget-exhausted: {len(skipped)} cases not run after {budget:.0f} s")
