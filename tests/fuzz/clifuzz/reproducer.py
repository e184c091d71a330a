"""A failing case as a shell reproducer: create its files, then run the binary."""

import json
import os
import shlex

from .case import payload_bytes


def ansi_c(b):
    """bash $'...' quoting of bytes."""
    out = []
    for c in b:
        ch = chr(c)
        if 32 <= c < 127 and ch not in "'\\":
            out.append(ch)
        else:
            out.append(f"\\x{c:02x}")
    return "$'" + "".join(out) + "'"


def sh_quote(s):
    b = os.fsencode(s)
    if all(32 <= c < 127 for c in b):
        return shlex.quote(s)
    return ansi_c(b)


def reproducer(case, binary):
    steps = ['cd "$(mktemp -d)"']
    for fs in case.files:
        d = os.path.dirname(fs.path)
        if d and not any(f.path == d for f in case.files):
            steps.append(f"mkdir -p {sh_quote(d)}")
        if fs.kind in ("file", "file600"):
            data = payload_bytes(fs)
            if len(data) <= 300:
                q = shlex.quote(data.decode()) if all(32 <= c < 127 for c in data) else ansi_c(data)
                steps.append(f"printf %s {q} > {sh_quote(fs.path)}")
            else:
                code = f"open({json.dumps(fs.path)}, \"wb\").write({fs.payload})"
                steps.append(f"python3 -c '{code}'" if "'" not in code else
                             f"python3 -c {shlex.quote(code)}")
            if fs.kind == "file600":
                steps.append(f"chmod 600 {sh_quote(fs.path)}")
        elif fs.kind == "dir":
            steps.append(f"mkdir -p {sh_quote(fs.path)}")
        elif fs.kind == "fifo":
            steps.append(f"mkfifo {sh_quote(fs.path)}")
        elif fs.kind == "symlink":
            steps.append(f"ln -s {sh_quote(fs.payload)} {sh_quote(fs.path)}")
    steps.append(" ".join([sh_quote(binary)] + [sh_quote(a) for a in case.argv()]))
    return " && ".join(steps)
