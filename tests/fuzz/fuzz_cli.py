#!/usr/bin/env python3
"""Seeded fuzz test of the `selfalign` command line against its documented contract (issue 9).

Every case runs the binary once, in a fresh temporary folder, with a mutated command line and
mutated input files (JSON / TOML configs, samples CSVs, outputs colliding with inputs, outputs that
are folders, FIFOs or symbolic links), and checks the contract of docs/cli.md and docs/config.md:

  * no signal, no sanitizer report, no hang (per-case timeout), exit code 0 or 2 only;
  * exit 2: stderr is exactly one line `selfalign: error: <message>`, short, naming a parameter,
    free of library internals; nothing on stdout; the folder is exactly as before (no output
    file, no temporary, no input changed);
  * exit 0: no input changed, no file other than the run's outputs created, no temporary left,
    special files (FIFO, symbolic link, folder) at an output path not replaced, stderr silent,
    JSON parses with no NaN / Infinity and null only where documented, CSV numbers finite except
    in the columns documented to hold `nan` / `inf` (ALLOWED_NONFINITE_CSV, each with its source);
  * "big requests" (1e9 periods with --out, 1e9 grid cells, 1e9 threads, ...) end quickly.

Deterministic for a seed: cases 0 .. len(CORPUS)-1 are a fixed corpus (one per contract item and
per known defect class of ../shared/repro/), every later case i is generated from
random.Random(f"{seed}:{i}") alone.

  SELFALIGN_FUZZ_SEED   seed (default 20100601)          --seed overrides
  SELFALIGN_FUZZ_CASES  number of cases (default 2000; --asan: a tenth, 200)   --cases overrides

  fuzz_cli.py --binary build/release/apps/selfalign/selfalign
  fuzz_cli.py --binary build/asan/apps/selfalign/selfalign --asan     # fewer cases, longer timeouts
  fuzz_cli.py --binary B --seed 7 --only 123 --verbose                 # one case, its outcome
  fuzz_cli.py --binary B --list --cases 20                            # print cases, run nothing

On failure it prints, per failing case, a shell reproducer (for the first case of each failure kind
shrunk to a minimal command line), then counts per exit code and per failure kind; exit status 1.

The code lives in the package clifuzz/ beside this file (one concept per module, see
tests/fuzz/README.md); this file is the command line only.
"""

import argparse
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from clifuzz.contract import BIG_REQUEST_TIMEOUT_S, CASE_TIMEOUT_S, MAX_ERROR_LINE  # noqa: E402
from clifuzz.generate import generate  # noqa: E402
from clifuzz.report import print_failures, print_summary, tally  # noqa: E402
from clifuzz.reproducer import reproducer  # noqa: E402
from clifuzz.runner import Runner, run_cases  # noqa: E402
from clifuzz.vocabulary import drift_from_help  # noqa: E402

DEFAULT_SEED = 20100601
DEFAULT_CASES = 2000
DEFAULT_ASAN_CASES = 200


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", required=True, help="the selfalign executable")
    ap.add_argument("--asan", action="store_true",
                    help="sanitizer build: fewer cases (SELFALIGN_FUZZ_CASES / 10 by default), "
                         "timeouts x5, no address-space limit (ASAN_OPTIONS hard_rss_limit_mb)")
    ap.add_argument("--seed", type=int, default=None)
    ap.add_argument("--cases", type=int, default=None)
    ap.add_argument("--first", type=int, default=0, help="index of the first case")
    ap.add_argument("--only", type=int, action="append", help="run only these case indices")
    ap.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--timeout", type=float, default=CASE_TIMEOUT_S,
                    help="per-case timeout [s] (release)")
    ap.add_argument("--big-timeout", type=float, default=BIG_REQUEST_TIMEOUT_S,
                    help="timeout of big requests [s] (release): they must be refused quickly")
    ap.add_argument("--timeout-scale", type=float, default=None, help="default 1; --asan: 5")
    ap.add_argument("--mem-mb", type=int, default=4096, help="address-space limit per run (release)")
    ap.add_argument("--max-line", type=int, default=MAX_ERROR_LINE,
                    help="longest error message accepted, after 'selfalign: error: '")
    ap.add_argument("--budget", type=float, default=0,
                    help="stop starting cases after this many seconds (0: none); counts as a failure")
    ap.add_argument("--shrink", type=int, default=None,
                    help="runs spent shrinking the first case of each failure kind (default 40; --asan: 0)")
    ap.add_argument("--shrink-seconds", type=float, default=30.0, help="time spent shrinking, in all")
    ap.add_argument("--max-print", type=int, default=60, help="failing cases printed in full")
    ap.add_argument("--keep", action="store_true", help="keep the case folders")
    ap.add_argument("--list", action="store_true", help="print the cases, run nothing")
    ap.add_argument("--verbose", action="store_true")
    args = ap.parse_args()

    seed = args.seed if args.seed is not None else int(os.environ.get("SELFALIGN_FUZZ_SEED", DEFAULT_SEED))
    env_cases = os.environ.get("SELFALIGN_FUZZ_CASES")
    if args.cases is not None:
        ncases = args.cases
    elif env_cases:
        ncases = int(env_cases) // (10 if args.asan else 1)
    else:
        ncases = DEFAULT_ASAN_CASES if args.asan else DEFAULT_CASES
    if args.timeout_scale is None:
        args.timeout_scale = 5.0 if args.asan else 1.0
    shrink_budget = args.shrink if args.shrink is not None else (0 if args.asan else 40)
    indices = args.only or list(range(args.first, args.first + ncases))

    if args.list:
        for i in indices:
            c = generate(i, seed)
            print(f"[{i}] {'BIG ' if c.big else ''}{'; '.join(c.tags)}\n    {reproducer(c, 'selfalign')}")
        return 0
    if not os.access(args.binary, os.X_OK):
        print(f"fuzz_cli: no executable at {args.binary}", file=sys.stderr)
        return 2

    drift = drift_from_help(args.binary)
    if drift:
        print("fuzz_cli: the vocabulary differs from --help:\n  " + "\n  ".join(drift), file=sys.stderr)
        return 1
    args.workroot = tempfile.mkdtemp(prefix="selfalign-fuzz-")
    runner = Runner(args)
    results, skipped, elapsed = run_cases(runner, indices, seed, args.jobs, args.budget,
                                          args.verbose)
    counts, by_kind, failing = tally(results)

    binary = os.path.abspath(args.binary)
    if failing:
        print_failures(results, failing, by_kind, seed, binary, args.max_print, runner,
                       shrink_budget, args.shrink_seconds)
    if not args.keep:
        shutil.rmtree(args.workroot, ignore_errors=True)
    else:
        print(f"case folders kept under {args.workroot}")

    print_summary(seed, results, elapsed, args.jobs, args.asan, counts, failing, by_kind, skipped,
                  args.budget)
    return 1 if failing or skipped else 0


if __name__ == "__main__":
    sys.exit(main())
