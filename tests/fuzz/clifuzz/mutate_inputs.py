"""Mutations of the run's input files: JSON / TOML config files and samples CSVs."""

from .config_files import (MANY_ROWS_EXPR, Raw, deep_expr, huge_string_expr, render_config,
                           typed)
from .mutate_flags import mutate_number, pool, time_stepping_for_simulate
from .values import SAMPLES_VARIANTS, VALID_SAMPLES_CONSTANT
from .vocabulary import CONFIG_KEYS, FLAGS, KIND


def mutate_config(c, sub):
    rng = c.rng
    fmt = rng.choice(["json", "toml"])
    name = rng.choice([f"cfg.{fmt}"] * 6 + [f"run.{fmt}", f"c.{fmt.upper()}", "cfg", "cfg.txt",
                                               f"cfg.{fmt}.bak", f"my cfg.{fmt}", f".{fmt}"])
    variant = rng.choice(["valid"] * 4 + ["wrong-type"] * 3 + ["unknown-key"] * 2 + [
        "deep", "deep", "huge-number", "huge-number", "nonfinite", "syntax", "syntax", "huge-string",
        "dir", "missing", "empty-path", "outputs-in-config", "outputs-in-config", "samples-key",
        "duplicate-key", "null"])
    c.tags.append(f"config {name} ({variant})")
    if variant == "dir":
        c.add_file(name, "dir")
        c.inputs.add(name)
        c.set("config", name, anywhere=True)
        return
    if variant == "missing":
        c.set("config", rng.choice(["nothere.json", "nothere.toml", "nodir/cfg.toml"]), anywhere=True)
        return
    if variant == "empty-path":
        c.set("config", "", anywhere=True)
        return
    items = []
    # move some flags into the file
    for u in list(c.units):
        if len(u) == 2 and u[0].startswith("--") and u[0][2:].replace("-", "_") in CONFIG_KEYS \
                and u[0][2:] != "config" and rng.random() < 0.6:
            c.units.remove(u)
            items.append((u[0][2:].replace("-", "_"), typed(u[0][2:], u[1])))
            if u[0][2:] in ("out", "summary"):
                c.config_outputs.add((u[1], u[0][2:]))
    for _ in range(rng.randint(0, 3)):
        key = rng.choice(CONFIG_KEYS[:-2])
        flag = key.replace("_", "-")
        if KIND.get(flag) in ("num", "list", "text"):
            items.append((key, typed(flag, rng.choice(pool(sub, flag)))))
    expr = None
    if variant == "wrong-type":
        key = rng.choice(CONFIG_KEYS[:-2])
        flag = key.replace("_", "-")
        if KIND.get(flag) == "num":
            bad = rng.choice(["wide", True, [1], {"a": 1}, "1", "", Raw("[]")])
        elif KIND.get(flag) == "list":
            bad = rng.choice(["0.3,0.4", 1, [[1]], ["a"], [True], {"a": 1}, [Raw("1e999")]])
        else:
            bad = rng.choice([3, [], ["si"], True, {"x": "y"}, 1.5])
        items.append((key, bad))
    elif variant == "unknown-key":
        items.append((rng.choice(["widht", "WIDTH", "", " width", "out ", "config", "json",
                                  "entries", "threads", "x" * 3000, "c-mu", "a2.x"]), 1.0))
        if fmt == "toml" and rng.random() < 0.5:
            items.append((Raw("[sec]\nwidth"), 1.0))  # a table header
    elif variant == "deep":
        depth = rng.choice([64, 1000, 100000, 100000])
        expr = deep_expr(fmt, depth)
        c.tags.append(f"depth {depth}")
    elif variant == "huge-number":
        key = rng.choice(["width", "periods", "a2", "c_mu", "x0", "t0", "stroke", "mu"])
        lit = rng.choice(["1e999", "-1e999", "1e308", "5e-324", "1e-400",
                          "123456789012345678901234567890", "-9223372036854775809",
                          "9223372036854775807", "1.7976931348623157e309"])
        items.append((key, Raw(lit)))
        if key == "periods" and lit in ("1e308", "123456789012345678901234567890", "9223372036854775807"):
            c.big = True
    elif variant == "nonfinite":
        key = rng.choice(["width", "a2", "period", "x0", "theta", "mu"])
        items.append((key, Raw(rng.choice(["nan", "inf", "-inf", "+nan", "NaN", "Infinity"]))))
    elif variant == "syntax":
        body = render_config(fmt, items)
        choice = rng.choice(["truncated", "garbage", "empty", "bom", "nul", "array", "number",
                             "string", "comment", "trailing-comma", "crlf", "latin1", "only-ws"])
        c.tags.append(choice)
        text = {"truncated": body[: max(1, len(body) // 2)], "garbage": "@@@ not a config !!!\n",
                "empty": "", "bom": "\ufeff" + body, "nul": body + "\x00",
                "array": "[1, 2]\n" if fmt == "json" else "[[x]]\n", "number": "1\n",
                "string": '"units"\n', "comment": "// c\n" + body if fmt == "json" else "# c\n" + body,
                "trailing-comma": body.rstrip().rstrip("}") + ",}\n" if fmt == "json" else body + "=\n",
                "crlf": body.replace("\n", "\r\n"), "latin1": None, "only-ws": "  \n\t\n"}[choice]
        expr = repr(text.encode("utf-8", "surrogateescape")) if text is not None else \
            repr(b'{"units": "\xe9"}' if fmt == "json" else b'units = "\xe9"\n')
    elif variant == "huge-string":
        expr = huge_string_expr(fmt)
    elif variant == "outputs-in-config":
        target = rng.choice([name, "o.csv", "o.csv", "s.csv", "d", "o.summary.json", ""])
        key = rng.choice(["out", "summary"])
        items.append((key, target))
        if rng.random() < 0.4:
            items.append(("summary" if key == "out" else "out", rng.choice([name, "o2.csv", "-"])))
        if target == "s.csv" and not c.has_file("s.csv"):
            c.add_file("s.csv", "file", repr(VALID_SAMPLES_CONSTANT.encode()))
            c.inputs.add("s.csv")
        if target == "d":
            c.add_file("d", "dir")
        for k, v in items:
            if k in ("out", "summary") and isinstance(v, str):
                c.config_outputs.add((v, k))
    elif variant == "samples-key":
        sname = rng.choice(["s.csv", "s.csv", name, "d", "nothere.csv"])
        items += [("profile", "samples"), ("samples", sname)]
        c.config_inputs[name] = sname
        if sname == "s.csv":
            text = rng.choice(SAMPLES_VARIANTS)[1] or VALID_SAMPLES_CONSTANT
            c.add_file("s.csv", "file", repr(text.encode("utf-8", "surrogateescape")))
            c.inputs.add("s.csv")
        elif sname == "d":
            c.add_file("d", "dir")
    elif variant == "duplicate-key":
        items += [("width", 0.05), ("width", 0.06)]
    elif variant == "null":
        items.append((rng.choice(["width", "units", "durations"]), None))
    if expr is None:
        expr = repr(render_config(fmt, items).encode("utf-8", "surrogateescape"))
    c.add_file(name, "file", expr)
    c.inputs.add(name)
    c.set("config", name, anywhere=True)


def mutate_samples(c, sub):
    rng = c.rng
    if "samples" not in FLAGS[sub]:
        return mutate_number(c, sub)
    label, text = rng.choice(SAMPLES_VARIANTS)
    name = rng.choice(["s.csv"] * 5 + ["samples.txt", "s", "my s.csv"])
    c.tags.append(f"samples {name} ({label})")
    if label == "valid-many-rows":
        expr = MANY_ROWS_EXPR
    else:
        expr = repr(text.encode("utf-8", "surrogateescape"))
    r = rng.random()
    if r < 0.05:
        c.add_file(name, "dir")
    elif r < 0.08:
        name = "nothere.csv"
    elif r < 0.1:
        name = ""
    else:
        c.add_file(name, "file", expr)
    c.inputs.add(name)
    c.set("profile", "samples")
    c.set("samples", name, anywhere=True)
    if rng.random() < 0.3:
        c.set("interpolation", "linear")
        time_stepping_for_simulate(c, sub)
