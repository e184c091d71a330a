"""Mutations of the robust commands' documents (issue 20): the --uncertainty-file of design and
montecarlo and montecarlo's --design report, valid, nested deeply (D23), malformed (D31) or
with values of the wrong type (D30)."""

import json

from .mutate_flags import mutate_number

# A `selfalign design --json` report, reduced to what montecarlo reads (docs/cli.md), for the
# process of the montecarlo base command line (values.py).
REPORT = {
    "units": "si", "feasible": True,
    "profile": {"kind": "three-phase", "jerk_m_per_s3": None, "period_s": 0.05,
                "stroke_m": 0.0005, "a2_m_per_s2": 5, "a3_m_per_s2": 4},
    "x_mu_m": 0.05,
    "request": {"mass_kg": 1, "width_m": 0.01, "mu": 0.3, "c_mu": 2.5, "g_m_per_s2": 9.81,
                "mu_static": None, "mu_backward": None, "distance_m": 0.055,
                "tolerance_m": 0.001},
}
PROCESS_FLAGS = ["period-s", "stroke-m", "a2", "a3", "jerk", "x-mu", "distance", "tolerance"]
REPORT_KEYS = [("profile", "jerk_m_per_s3"), ("profile", "period_s"), ("profile", "stroke_m"),
               ("profile", "a2_m_per_s2"), ("profile", "a3_m_per_s2"), (None, "x_mu_m")] + \
              [("request", k) for k in REPORT["request"]]
WRONG_TYPED = [[1], "500", True, None, {"a": 1}, "0.05", [], False]
VALID_UNCERTAINTY = {"json": b'{"mu": "normal:0.3,3%", "c_mu": "uniform:2.4,2.6"}\n',
                     "toml": b'mu = "normal:0.3,3%"\nc_mu = "uniform:2.4,2.6"\n'}


def deep_document_expr(fmt, depth, shape):
    """Bytes of a document nested `depth` deep: JSON arrays or objects; TOML arrays, inline
    tables, a dotted key or a table header (Python expressions, no single quotes)."""
    if fmt == "json":
        if shape == "object":
            return f'b"{{" + b"\\"a\\": {{" * {depth} + b"}}" * {depth} + b"}}"'
        return f'b"{{\\"mu\\": " + b"[" * {depth} + b"]" * {depth} + b"}}"'
    if shape == "dotted":
        return f'b"mu" + b".a" * {depth} + b" = 1\\n"'
    if shape == "header":
        return f'b"[a" + b".a" * {depth} + b"]\\nx = 1\\n"'
    if shape == "inline":
        return f'b"mu = " + b"{{a = " * {depth} + b"1" + b"}}" * {depth} + b"\\n"'
    return f'b"mu = " + b"[" * {depth} + b"]" * {depth} + b"\\n"'


def malformed_expr(fmt, rng):
    if fmt == "json":
        return repr(rng.choice([b"\xff\xfe{", b'{"mu": 0x10}', b'{"mu": 1e999}', b'{"mu": ',
                                b"", b"[1, 2]", b'{"mu": "normal:0.3,3%",}']))
    return repr(rng.choice([b"mu = = 1\n", b'mu = "\xff"\n', b"[[\n", b"mu = 1e999\n",
                            b'mu = """\n', b"mu = [1,\n"]))


def ensure_uncertainty(c, name=None):
    """An uncertainty file the case reads (--uncertainty-file), valid; its path."""
    if c.value("uncertainty-file") and c.has_file(c.value("uncertainty-file")):
        return c.value("uncertainty-file")
    name = name or c.rng.choice(["u.toml", "u.json"])
    c.add_file(name, "file", repr(VALID_UNCERTAINTY[name.rsplit(".", 1)[1]]))
    c.inputs.add(name)
    c.set("uncertainty-file", name, anywhere=True)
    return name


def ensure_report(c, report=None, name="d.json"):
    """A design report montecarlo reads (--design); its path."""
    if report is None and c.value("design") and c.has_file(c.value("design")):
        return c.value("design")
    text = json.dumps(REPORT if report is None else report).encode()
    c.add_file(name, "file", repr(text))
    c.inputs.add(name)
    c.set("design", name, anywhere=True)
    return name


def mutate_uncertainty_file(c, sub):
    if sub not in ("design", "montecarlo"):
        return mutate_number(c, sub)
    rng = c.rng
    fmt = rng.choice(["json", "toml"])
    name = f"u.{fmt}"
    variant = rng.choice(["valid", "valid", "deep", "deep", "deep", "malformed", "malformed",
                          "wrong-type", "unknown-key", "dir", "missing"])
    c.tags.append(f"uncertainty-file {name} ({variant})")
    if variant == "valid":
        ensure_uncertainty(c, name)
        if sub == "design" and rng.random() < 0.5:
            c.set("monte-carlo", "20")
            c.set("tolerance", "0.001")
        return
    if variant == "dir":
        c.add_file(name, "dir")
    elif variant == "missing":
        name = "nothere." + fmt
    else:
        if variant == "deep":
            shape = rng.choice(["array", "object"] if fmt == "json" else
                               ["array", "dotted", "header", "inline"])
            depth = rng.choice([3, 64, 300, 100000])
            expr = deep_document_expr(fmt, depth, shape)
            c.tags.append(f"{shape} depth {depth}")
        elif variant == "malformed":
            expr = malformed_expr(fmt, rng)
        elif variant == "wrong-type":
            value = rng.choice([1, [1], True, {"a": "b"}, None] if fmt == "json" else
                               ["1", "[1]", "true", "{a = 1}", "1979-05-27"])
            expr = repr((json.dumps({"mu": value}) if fmt == "json" else f"mu = {value}\n").encode())
        else:
            expr = repr(b'{"nu": "normal:0.3,3%"}' if fmt == "json" else b'nu = "normal:0.3,3%"\n')
        c.add_file(name, "file", expr)
    c.inputs.add(name)
    c.set("uncertainty-file", name, anywhere=True)


def mutate_design_report(c, sub):
    if sub != "montecarlo":
        return mutate_number(c, sub)
    rng = c.rng
    variant = rng.choice(["valid", "valid", "wrong-type", "wrong-type", "wrong-type", "missing-key",
                          "deep", "deep", "malformed", "not-a-report", "toml", "dir"])
    c.tags.append(f"design report ({variant})")
    for flag in PROCESS_FLAGS:  # the report is the process, as a user runs it (flags would win)
        c.drop(flag)
    report = json.loads(json.dumps(REPORT))
    if variant == "valid":
        if rng.random() < 0.5:
            report["profile"]["jerk_m_per_s3"] = rng.choice([2000.0, 1e4])
        ensure_report(c, report)
        return
    if variant in ("wrong-type", "missing-key"):
        section, key = rng.choice(REPORT_KEYS)
        node = report[section] if section else report
        if variant == "missing-key":
            del node[key]
        else:
            node[key] = rng.choice(WRONG_TYPED)
        c.tags.append(f"{section + '.' if section else ''}{key}")
        c.must_refuse = ("design", ensure_report(c, report))  # every key read is typed (D30)
        return
    name = "d.json"
    if variant == "dir":
        c.add_file(name, "dir")
    elif variant == "toml":
        name = "d.toml"  # a report in TOML: read as the same keys
        c.add_file(name, "file", repr(
            b'x_mu_m = 0.05\n[profile]\nperiod_s = 0.05\nstroke_m = 0.0005\na2_m_per_s2 = 5\n'
            b'a3_m_per_s2 = 4\njerk_m_per_s3 = "none"\n'))
    else:
        depth = rng.choice([7, 8, 100000])  # the report's limit is 8 levels, the top counting 1
        expr = {"deep": lambda: f'b"{{\\"profile\\": " + b"[" * {depth} + b"]" * {depth} + b"}}"',
                "malformed": lambda: repr(rng.choice([
                    json.dumps(REPORT).replace('"period_s": 0.05', '"period_s": 1e999').encode(),
                    json.dumps(REPORT).encode()[:40], b"\xff\xfe{"])),
                "not-a-report": lambda: repr(rng.choice([b"[1, 2]", b'{"profile": 1}', b"{}"]))}[variant]()
        c.add_file(name, "file", expr)
    c.inputs.add(name)
    c.set("design", name, anywhere=True)
    c.must_refuse = ("design", name)  # none of these is a report montecarlo can evaluate
