"""Checks of one run against the contract: exit code and signals, the folder before and after
(inputs unchanged, only designated outputs, no temporary), the error line, outputs' content."""

import json
import math
import os
import re
import signal

from .content import check_csv, check_json
from .contract import (DOCUMENT_ERRORS, DOCUMENTED_INTERNALS, GENERIC_NAMES, HELP_FLAGS,
                       INTERNALS, PARAM_NAMES, PREFIX, SANITIZER_MARKERS, WARNING_PREFIX)
from .folder import describe, read_head
from .vocabulary import CSV_SUMMARY_SUBS


def designated_outputs(case):
    """Paths the run may create or change on exit 0."""
    sub = case.sub_name()
    outs = set(case.config_outputs)
    argv = case.argv()
    for i, a in enumerate(argv):
        for flag in OUTPUT_FLAGS:
            if a == "--" + flag and i + 1 < len(argv):
                outs.add((argv[i + 1], flag))
            elif a.startswith("--" + flag + "="):
                outs.add((a.split("=", 1)[1], flag))
    if sub in CSV_SUMMARY_SUBS:
        for o, flag in list(outs):
            if o and flag == "out":
                outs.add((os.path.splitext(o)[0] + ".summary.json", "summary"))
    # "-" is standard output for --summary (docs/cli.md); for --out it is not documented, and a
    # file named "-" is accepted there.
    return {os.path.normpath(o) for o, flag in outs if o and not (o == "-" and flag == "summary")}


INPUT_FLAGS = ("config", "samples", "uncertainty-file", "design")
OUTPUT_FLAGS = ("out", "summary", "profile-csv", "runs-csv")


def read_inputs(case):
    """The candidate inputs the final command line reads: values of the input flags, and the
    samples file a given config names."""
    argv = case.argv()
    named = set()
    for i, a in enumerate(argv):
        for flag in INPUT_FLAGS:
            if a == "--" + flag and i + 1 < len(argv):
                named.add(argv[i + 1])
            elif a.startswith("--" + flag + "="):
                named.add(a.split("=", 1)[1])
    for cfg, samples in case.config_inputs.items():
        if cfg in named:
            named.add(samples)
    named = {os.path.normpath(p) for p in named if p}
    return {os.path.normpath(p) for p in case.inputs if p and os.path.normpath(p) in named}


def resolve_in(before, path):
    """Follows symbolic links recorded in the snapshot (inside the case folder)."""
    seen = 0
    while path in before and before[path][0] == "symlink" and seen < 8:
        path = os.path.normpath(os.path.join(os.path.dirname(path), before[path][1]))
        seen += 1
    return path


def aliased_outputs(case, before):
    """Two output flags of the command line naming one file (./x and x, sub/../x, a link): the
    run must refuse them (docs/cli.md, "Outputs and inputs"; D25)."""
    argv = case.argv()
    files = {}
    for i, a in enumerate(argv):
        for flag in OUTPUT_FLAGS:
            path = argv[i + 1] if a == "--" + flag and i + 1 < len(argv) else \
                a.split("=", 1)[1] if a.startswith("--" + flag + "=") else None
            if path and path != "-":
                files.setdefault(resolve_in(before, os.path.normpath(path)), set()).add(flag)
    return sorted(f"{p} ({', '.join(sorted(flags))})" for p, flags in files.items() if len(flags) > 1)


def names_parameter(msg):
    if re.search(r"--[A-Za-z]", msg):
        return True
    m = re.match(r"invalid (.+?) = ", msg)
    if m and any(w in PARAM_NAMES or w in ("config file", "config key")
                 for w in re.findall(r"[A-Za-z][A-Za-z0-9_\-]*", m.group(1)) + [m.group(1)]):
        return True
    words = set(re.findall(r"[A-Za-z][A-Za-z0-9_\-]*", msg))
    if any(w in PARAM_NAMES and len(w) >= 3 and w not in ("from", "out") for w in words):
        return True
    return any(g in msg for g in GENERIC_NAMES)


def internals_in(msg):
    for marker in INTERNALS:
        if marker in msg:
            if any(rx.match(msg) and marker in doc for rx, doc in DOCUMENTED_INTERNALS) \
                    and marker in ("json.exception",):
                continue
            return marker
    return None


def check(case, o, max_line):
    f = []
    rc, stderr_b, stdout_b = o["rc"], o["stderr"], o["stdout"]
    stderr = stderr_b.decode("utf-8", "replace")
    sub = case.sub_name()
    if o["timed_out"]:
        f.append(("big-request-slow" if case.big else "timeout",
                  f"no exit within {o['timeout']:.0f} s"))
    elif any(m in stderr for m in SANITIZER_MARKERS):
        line = next((ln for ln in stderr.splitlines() if any(m in ln for m in SANITIZER_MARKERS)), "")
        f.append(("sanitizer", line.strip()[:200]))
    elif rc < 0 or rc >= 128:
        sig = -rc if rc < 0 else rc - 128
        try:
            name = signal.Signals(sig).name
        except ValueError:
            name = str(sig)
        f.append(("signal", f"{name} (rc {rc}); stderr: {stderr.strip()[:120]!r}"))
    elif rc not in (0, 2):
        f.append(("exit-code", f"rc {rc}; stderr: {stderr.strip()[:160]!r}"))

    before, after = o["before"], o["after"]
    changed = sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p))
    inputs = read_inputs(case)
    inputs |= {resolve_in(before, p) for p in inputs}
    for p in changed:
        if p in inputs or any(p.startswith(i + os.sep) for i in inputs):
            f.append(("input-changed", f"{p}: {describe(before.get(p))} -> {describe(after.get(p))}"))
    outs = designated_outputs(case)
    outs |= {resolve_in(before, p) for p in outs}
    tmp = [p for p in after if p not in before and p not in outs
           and re.search(r"\.tmp", os.path.basename(p))]
    if tmp:
        f.append(("temp-left", ", ".join(tmp[:3])))

    if o["timed_out"] or rc not in (0, 2):
        return f
    f += check_expected(case, rc, stderr)
    if rc == 2:
        lines = stderr.split("\n")
        if not (stderr.endswith("\n") and len(lines) == 2):
            f.append(("error-lines", f"{stderr.count(chr(10))} newline(s): {stderr[:160]!r}"))
        first = lines[0]
        if not first.startswith(PREFIX):
            f.append(("error-prefix", repr(first[:160])))
        else:
            msg = first[len(PREFIX):]
            if len(msg) > max_line:
                f.append(("error-too-long", f"message of {len(msg)} characters: {first[:120]!r}..."))
            marker = internals_in(msg)
            if marker:
                f.append(("error-internals", f"{marker!r} in {first[:200]!r}"))
            if any(w in msg for w in DOCUMENT_ERRORS) and not (
                    "line " in msg and any(fs.path in msg for fs in case.files)):
                f.append(("error-no-place", f"a document error without its file and line: {first[:200]!r}"))
            if not names_parameter(msg):
                f.append(("error-no-parameter", repr(first[:200])))
        if stdout_b.strip():
            f.append(("error-with-stdout", repr(stdout_b[:80])))
        wrote = [p for p in changed if not (p in inputs)]
        if wrote:
            f.append(("error-wrote-files",
                      "; ".join(f"{p}: {describe(before.get(p))} -> {describe(after.get(p))}"
                                for p in wrote[:3])))
        return f

    # exit 0
    if HELP_FLAGS & set(case.argv()):
        if changed:
            f.append(("unexpected-file", f"help/version wrote {', '.join(changed[:3])}"))
        return f
    noise = [ln for ln in stderr.strip().splitlines() if not ln.startswith(WARNING_PREFIX)]
    if noise:
        f.append(("stderr-on-success", repr(noise[0][:160])))
    if case.must_refuse and case.value(case.must_refuse[0]) == case.must_refuse[1]:
        f.append(("invalid-accepted", f"exit 0 for an input that must be refused ({'; '.join(case.tags)})"))
    for alias in aliased_outputs(case, before):
        f.append(("outputs-aliased", f"exit 0 with two outputs naming {alias}"))
    for p in changed:
        if p in inputs or p.endswith(".tmp") or p in tmp:
            continue
        b, a = before.get(p), after.get(p)
        if b and b[0] != "file" and b != a and not (b[0] == "dir" and a and a[0] == "dir"):
            f.append(("special-replaced", f"{p}: {describe(b)} -> {describe(a)}"))
        elif b and a and b[0] == "file" and a[0] == "file" and b[2] != a[2]:
            f.append(("output-mode-changed", f"{p}: mode {b[2]:o} -> {a[2]:o}"))
        elif p not in outs and not p.endswith(".summary.json"):
            f.append(("unexpected-file", f"{p}: {describe(b)} -> {describe(a)}"))
    for p in sorted(outs):
        if after.get(p, ("",))[0] == "file" and before.get(p) != after.get(p):
            data = read_head(os.path.join(o["cwd"], p), 32 << 20)
            f += check_content(sub, p, data, case)
    out_flag = case.value("out")
    if out_flag and "=" not in (case.units[case.find("out")][0]) and not out_flag.startswith("-") \
            and os.path.normpath(out_flag) not in before and "/" not in out_flag \
            and case.argv().count("--out") == 1 and after.get(os.path.normpath(out_flag), ("",))[0] != "file":
        f.append(("output-missing", f"--out {out_flag!r} given, exit 0, no such file"))
    text = stdout_b.decode("utf-8", "replace")
    if text.lstrip().startswith("{"):
        f += check_content(sub, "<stdout>", stdout_b, case)
    elif sub.startswith("sweep") and text.strip() and "--help" not in case.argv() \
            and "-h" not in case.argv():
        f += check_content(sub, "<stdout>", stdout_b, case)
    if sub == "simulate":
        f += check_simulate(case, o)
    return f


def check_expected(case, rc, stderr):
    """The outcome a single mutation with an expectation must have (Case.expect)."""
    if case.expect is None or HELP_FLAGS & set(case.argv()):
        return []
    first = stderr.split("\n")[0]
    kind = case.expect[0]
    if kind == "refused":
        flag = case.expect[1]
        if rc == 0:
            return [("invalid-accepted", f"--{flag} {case.value(flag)!r} ran (exit 0)")]
        if flag not in first and flag.replace("-", "_") not in first:
            return [("error-wrong-parameter", f"--{flag} {case.value(flag)!r}: {first[:200]!r}")]
    elif kind == "runs" and rc == 2:
        return [("valid-refused", repr(first[:200]))]
    elif kind == "hint":
        if rc == 0:
            return [("typo-accepted", " ".join(case.argv())[:160])]
        if "did you mean" not in first:
            return [("no-suggestion", repr(first[:200]))]
    return []


def check_content(sub, where, data, case):
    text = data.decode("utf-8", "replace")
    if text.lstrip().startswith("{"):
        return check_json(sub, where, text)
    return check_csv(sub, where, text)


def check_simulate(case, o):
    """docs/config.md, "Output CSV": one row per sample at t0 + j·output_step and at the end
    time; the summary's final.t is the end time t0 + periods·Δt."""
    f = []
    summary = None
    for p in designated_outputs(case):
        if p.endswith(".json") and o["after"].get(p, ("",))[0] == "file":
            try:
                with open(os.path.join(o["cwd"], p)) as fh:
                    summary = json.load(fh)
            except (ValueError, OSError):
                return f
    if summary is None and o["stdout"].lstrip().startswith(b"{"):
        try:
            summary = json.loads(o["stdout"])
        except ValueError:
            return f
    if not isinstance(summary, dict):
        return f
    try:
        t_begin, t_end = summary["initial"]["t"], summary["final"]["t"]
        expected = t_begin + summary["periods"] * summary["profile"]["period"]
    except (KeyError, TypeError):
        return f
    if all(isinstance(v, (int, float)) for v in (t_begin, t_end, expected)) and \
            math.isfinite(expected) and abs(t_end - expected) > 1e-9 * max(1.0, abs(expected)):
        f.append(("simulate-end-time", f"final.t = {t_end!r}, expected t0 + periods·Δt = {expected!r}"))
    return f
