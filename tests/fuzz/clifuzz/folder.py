"""The case folder: files created before the run, snapshots of it (lstat only: a FIFO is never
opened), a reader kept on each FIFO during the run, and reading its files back."""

import hashlib
import os
import stat
import threading
import time

from .case import payload_bytes


def create_files(case, root):
    for f in case.files:
        p = os.path.join(root, f.path)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        if f.kind in ("file", "file600"):
            with open(p, "wb") as fh:
                fh.write(payload_bytes(f))
            if f.kind == "file600":
                os.chmod(p, 0o600)
        elif f.kind == "dir":
            os.makedirs(p, exist_ok=True)
        elif f.kind == "fifo":
            os.mkfifo(p)
        elif f.kind == "symlink":
            os.symlink(f.payload, p)


def snapshot(root):
    """path -> (type, detail, mode): lstat only, never opens a FIFO; files hashed."""
    out = {}
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False):
        for name in dirnames + filenames:
            p = os.path.join(dirpath, name)
            rel = os.path.relpath(p, root)
            st = os.lstat(p)
            mode = stat.S_IMODE(st.st_mode)
            if stat.S_ISLNK(st.st_mode):
                out[rel] = ("symlink", os.readlink(p), mode)
            elif stat.S_ISDIR(st.st_mode):
                out[rel] = ("dir", "", mode)
            elif stat.S_ISFIFO(st.st_mode):
                out[rel] = ("fifo", "", mode)
            elif stat.S_ISREG(st.st_mode):
                h = hashlib.sha256()
                with open(p, "rb") as fh:
                    for block in iter(lambda: fh.read(1 << 20), b""):
                        h.update(block)
                out[rel] = ("file", h.hexdigest() + f":{st.st_size}", mode)
            else:
                out[rel] = ("other", "", mode)
    return out


def describe(entry):
    if entry is None:
        return "absent"
    kind, detail, mode = entry
    if kind == "file":
        return f"file({detail.split(':')[1]} B)"
    if kind == "symlink":
        return f"symlink->{detail}"
    return kind


class FifoDrain:
    """Keeps a reader on each FIFO during the run, so a program that writes into it is not
    blocked (writing into a FIFO is acceptable; replacing it is not)."""

    def __init__(self, paths):
        self.fds = [os.open(p, os.O_RDONLY | os.O_NONBLOCK) for p in paths]
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.run, daemon=True)
        if self.fds:
            self.thread.start()

    def run(self):
        while not self.stop.is_set():
            for fd in self.fds:
                try:
                    while os.read(fd, 1 << 16):
                        pass
                except (BlockingIOError, OSError):
                    pass
            time.sleep(0.005)

    def close(self):
        self.stop.set()
        if self.fds:
            self.thread.join()
        for fd in self.fds:
            os.close(fd)


def read_head(path, limit):
    """The first `limit` bytes, cut back to the last whole line when the file is longer."""
    with open(path, "rb") as fh:
        data = fh.read(limit + 1)
    if len(data) > limit:
        data = data[:limit]
        data = data[: data.rfind(b"\n") + 1]
    return data
