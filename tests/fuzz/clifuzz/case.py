"""One fuzz case: its command line as argument units, the files prepared before the run, and
what the checks need to know (inputs, outputs named in a config, big request)."""

import random


class FileSpec:
    """A file system entry prepared before the run: file (Python expression of its bytes),
    dir, fifo or symlink (target)."""

    def __init__(self, path, kind, payload=None):
        self.path, self.kind, self.payload = path, kind, payload


class Case:
    def __init__(self, index, seed):
        self.index, self.seed = index, seed
        self.rng = random.Random(f"{seed}:{index}")
        self.sub = []          # subcommand tokens
        self.units = []        # argument units: lists of tokens
        self.files = []        # FileSpec, in creation order
        self.tags = []         # what was mutated, for the report
        self.big = False       # a big request: short timeout
        self.inputs = set()    # candidate inputs: those the final command line reads never change
        self.config_inputs = {}  # config path -> samples path named inside it
        self.config_outputs = set()  # (path, key): out / summary named inside a config file
        # What the contract says this case must do beyond the general checks (checks.py):
        # ("refused", flag): exit 2 naming the flag; ("runs",): exit 0; ("hint",): exit 2 with
        # a "did you mean" suggestion. None: only the general contract.
        self.expect = None
        self.must_refuse = None  # (flag, path): an input the run must refuse while the command
        #                          line still gives it (e.g. a wrong-typed design report)

    def argv(self):
        return self.sub + [t for u in self.units for t in u]

    def sub_name(self):
        return " ".join(self.sub[:2]) if self.sub[:1] == ["sweep"] else " ".join(self.sub[:1])

    def add_file(self, path, kind, payload=None):
        self.files = [f for f in self.files if f.path != path]
        self.files.append(FileSpec(path, kind, payload))

    def has_file(self, path):
        return any(f.path == path for f in self.files)

    # -- units --
    def find(self, flag):
        for i, u in enumerate(self.units):
            if u and (u[0] == "--" + flag or u[0].startswith("--" + flag + "=")):
                return i
        return -1

    def value(self, flag):
        i = self.find(flag)
        if i < 0:
            return None
        u = self.units[i]
        if "=" in u[0]:
            return u[0].split("=", 1)[1]
        return u[1] if len(u) > 1 else None

    def set(self, flag, value=None, anywhere=False):
        unit = ["--" + flag] if value is None else ["--" + flag, value]
        i = self.find(flag)
        if i >= 0:
            self.units[i] = unit
        elif anywhere:
            self.units.insert(self.rng.randint(0, len(self.units)), unit)
        else:
            self.units.append(unit)

    def drop(self, flag):
        i = self.find(flag)
        if i >= 0:
            del self.units[i]


def payload_bytes(fs):
    return eval(fs.payload, {"__builtins__": {"range": range}})  # noqa: S307 (our own recipes)


def clone(case):
    c = Case(case.index, case.seed)
    c.sub, c.units = list(case.sub), [list(u) for u in case.units]
    c.files = list(case.files)
    c.tags, c.big, c.must_refuse = list(case.tags), case.big, case.must_refuse
    c.inputs, c.config_outputs = set(case.inputs), set(case.config_outputs)
    c.config_inputs = dict(case.config_inputs)
    c.expect = case.expect
    return c
