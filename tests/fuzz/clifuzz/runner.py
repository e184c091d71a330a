"""Running cases: each in a fresh temporary folder, under a timeout (short for big requests) and
resource limits, a binary being relinked retried; many cases on parallel threads."""

import os
import resource
import shlex
import shutil
import signal
import subprocess
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

from .checks import check
from .folder import FifoDrain, create_files, read_head, snapshot
from .generate import generate


class Runner:
    def __init__(self, args):
        self.binary = os.path.abspath(args.binary)
        self.asan = args.asan
        self.timeout = args.timeout * args.timeout_scale
        self.big_timeout = args.big_timeout * args.timeout_scale
        self.mem_mb = args.mem_mb
        self.max_line = args.max_line
        self.workroot = args.workroot
        self.keep = args.keep
        self.env = dict(os.environ)
        # bad_alloc stays an exception (as in release); a runaway allocation is stopped at 2 GB
        self.env.setdefault("ASAN_OPTIONS", "allocator_may_return_null=1:hard_rss_limit_mb=2048:"
                                            "detect_leaks=1:abort_on_error=0")
        self.env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
        self.env["LC_ALL"] = "C"

    def preexec(self):
        # runs in the child between fork and exec: plain system calls only
        if not self.asan and self.mem_mb > 0:
            lim = self.mem_mb * 1024 * 1024
            resource.setrlimit(resource.RLIMIT_AS, (lim, lim))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    def spawn(self, argv, cwd, so, se):
        # The binary may be relinked while we run (ETXTBSY, EACCES, ENOENT for a moment): retry.
        for attempt in range(120):
            try:
                return subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL, stdout=so,
                                        stderr=se, env=self.env, start_new_session=True,
                                        preexec_fn=self.preexec)
            except OSError:
                if attempt == 119:
                    raise
                time.sleep(0.5)

    def run(self, case):
        """Runs one case; returns (outcome dict, failures list)."""
        root = tempfile.mkdtemp(prefix=f"case{case.index}-", dir=self.workroot)
        cwd = os.path.join(root, "w")
        os.mkdir(cwd)
        try:
            create_files(case, cwd)
            before = snapshot(cwd)
            fifos = [os.path.join(cwd, p) for p, e in before.items() if e[0] == "fifo"]
            drain = FifoDrain(fifos)
            argv = [self.binary] + [os.fsencode(a) for a in case.argv()]
            timeout = self.big_timeout if case.big else self.timeout
            out_path, err_path = os.path.join(root, "stdout"), os.path.join(root, "stderr")
            t0 = time.monotonic()
            with open(out_path, "wb") as so, open(err_path, "wb") as se:
                p = self.spawn(argv, cwd, so, se)
                t0 = time.monotonic()
                timed_out = False
                try:
                    rc = p.wait(timeout=timeout)
                except subprocess.TimeoutExpired:
                    timed_out = True
                    os.killpg(p.pid, signal.SIGKILL)
                    rc = p.wait()
            elapsed = time.monotonic() - t0
            drain.close()
            after = snapshot(cwd)
            stdout = read_head(out_path, 8 << 20)
            stderr = read_head(err_path, 1 << 20)
            outcome = dict(rc=rc, timed_out=timed_out, elapsed=elapsed, timeout=timeout,
                           stdout=stdout, stderr=stderr, before=before, after=after, cwd=cwd)
            failures = check(case, outcome, self.max_line)
            return outcome, failures
        finally:
            if not self.keep:
                shutil.rmtree(root, ignore_errors=True)


def run_cases(runner, indices, seed, jobs, budget, verbose):
    """Runs cases `indices` of `seed` on `jobs` threads, in order; starts no case after `budget`
    seconds (0: none). Returns ({index: (case, outcome, failures)}, skipped indices, seconds)."""
    start = time.monotonic()
    results = {}
    skipped = []

    def job(i):
        if budget and time.monotonic() - start > budget:
            skipped.append(i)
            return i, None, None, None
        c = generate(i, seed)
        outcome, fails = runner.run(c)
        return i, c, outcome, fails

    with ThreadPoolExecutor(max_workers=max(1, jobs)) as executor:
        for i, c, outcome, fails in executor.map(job, indices):
            if c is None:
                continue
            results[i] = (c, outcome, fails)
            if verbose:
                print(f"[{i}] rc={outcome['rc']} {outcome['elapsed']:.2f}s "
                      f"{'; '.join(c.tags)}\n    {' '.join(shlex.quote(a) for a in c.argv())}")
                if outcome["stderr"]:
                    print("    stderr: " + outcome["stderr"][:300].decode("utf-8", "replace").rstrip())
                for k, d in fails:
                    print(f"    FAIL {k}: {d}")
    elapsed = time.monotonic() - start
    return results, skipped, elapsed
