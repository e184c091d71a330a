"""Mutations of the command line's flags: numbers, text, lists, ranges, repeated, unknown and
`--flag=` forms, dropped units, help, big requests."""

from .values import (BIG, BIG_REQUESTS, COST, EDGE_INT, EDGE_LIST, EDGE_NUMBERS, EDGE_RANGE,
                     EDGE_TEXT, SMALL_INVALID, VALID, VALID_SAMPLES_CONSTANT)
from .vocabulary import FLAGS, KIND, SUBCOMMANDS


def pool(sub, flag):
    return VALID.get(f"{sub}:{flag}") or VALID.get(flag) or ["1"]


def flag_of_kind(c, sub, kind):
    """A flag of `sub` whose value is of `kind` (vocabulary.KIND), drawn from c.rng; None where
    `sub` has none."""
    flags = [f for f in FLAGS[sub] if KIND.get(f) == kind]
    return c.rng.choice(flags) if flags else None


def tiny_positive(text):
    """Whether `text` reads as a number in (0, 1e-4): a step that makes a run a big request."""
    try:
        return 0 < float(text) < 1e-4
    except ValueError:
        return False


def time_stepping_for_simulate(c, sub):
    """simulate of a profile the exact method does not take (docs/config.md, "method": exact
    "needs a piecewise-constant y''"; "time-stepping": "any profile"): time-stepping, cheap."""
    if sub == "simulate":
        c.set("method", "time-stepping")
        c.set("step", "1e-3")
        c.set("output-step", "0.05")


def rand_float_text(rng):
    e = rng.uniform(-320, 308)
    v = rng.choice([1, -1]) * 10 ** e if e < 308 else 1e308
    return repr(v)


def mutate_number(c, sub):
    rng = c.rng
    flags = [f for f in FLAGS[sub] if KIND.get(f) in ("num", "int")]
    flag = rng.choice(flags)
    r = rng.random()
    if r < 0.3:
        v = rng.choice(pool(sub, flag))
    elif flag in BIG and r < 0.42:
        v = rng.choice(BIG[flag])
        c.big = True
    elif flag in COST:
        v = rng.choice(SMALL_INVALID + (EDGE_INT if KIND[flag] == "int" else []))
    elif r < 0.85:
        v = rng.choice(EDGE_NUMBERS + (EDGE_INT if KIND[flag] == "int" else []))
    else:
        v = rand_float_text(rng) if KIND[flag] == "num" else str(rng.choice([-1, 1]) * rng.getrandbits(rng.choice([8, 31, 32, 63, 64, 70])))
    time_step = flag == "step" and c.value("method") == "time-stepping" \
        and v not in pool(sub, flag)
    if (time_step or flag == "output-step") and tiny_positive(v):
        c.big = True
    c.set(flag, v, anywhere=True)
    c.tags.append(f"--{flag} {short(v)}")


def mutate_text(c, sub):
    rng = c.rng
    flag = flag_of_kind(c, sub, "text")
    if flag is None:
        return mutate_number(c, sub)
    v = rng.choice(pool(sub, flag)) if rng.random() < 0.4 else rng.choice(EDGE_TEXT)
    c.set(flag, v, anywhere=True)
    c.tags.append(f"--{flag} {short(v)}")
    if flag == "profile" and v == "samples" and c.value("samples") is None:
        c.add_file("s.csv", "file", repr(VALID_SAMPLES_CONSTANT.encode()))
        c.inputs.add("s.csv")
        c.set("samples", "s.csv")
    if flag == "profile" and v == "quadratic-sequence" and c.value("durations") is None:
        c.set("durations", "0.3,0.4,0.3")
        c.set("accelerations", "0,-3,4")
    if flag == "profile" and v == "fourier" and c.value("fourier-cos") is None:
        c.set("fourier-cos", "0.04")


def mutate_list(c, sub):
    rng = c.rng
    flag = flag_of_kind(c, sub, "list")
    if flag is None:
        return mutate_number(c, sub)
    v = rng.choice(pool(sub, flag)) if rng.random() < 0.3 else rng.choice(EDGE_LIST)
    c.set(flag, v, anywhere=True)
    if flag in ("durations", "accelerations") and rng.random() < 0.7:
        c.set("profile", "quadratic-sequence")
        other = "accelerations" if flag == "durations" else "durations"
        if c.value(other) is None:
            c.set(other, rng.choice(pool(sub, other) + EDGE_LIST[:6]))
    if flag.startswith("fourier") and rng.random() < 0.7:
        c.set("profile", "fourier")
    c.tags.append(f"--{flag} {short(v)}")


def mutate_range(c, sub):
    rng = c.rng
    flag = flag_of_kind(c, sub, "range")
    if flag is None:
        return mutate_number(c, sub)
    r = rng.random()
    if r < 0.3:
        v = rng.choice(pool(sub, flag))
    elif r < 0.4:
        v = rng.choice(BIG.get(flag, ["1:3:1000000000"]))
        c.big = True
    else:
        v = rng.choice(EDGE_RANGE)
    c.set(flag, v, anywhere=True)
    if rng.random() < 0.3:
        c.set("log")
    c.tags.append(f"--{flag} {short(v)}")


def mutate_repeat(c, sub):
    rng = c.rng
    valued = [u for u in c.units if len(u) == 2 and u[0].startswith("--")]
    if not valued:
        return mutate_unknown(c, sub)
    u = rng.choice(valued)
    flag = u[0][2:]
    v = rng.choice(pool(sub, flag)) if KIND.get(flag) not in ("out", "file") else u[1]
    c.units.insert(rng.randint(0, len(c.units)), ["--" + flag, v])
    c.tags.append(f"repeated --{flag}")


UNKNOWN_UNITS = [["--bogus"], ["--bogus", "1"], ["-x"], ["--a4", "1"], ["---out", "x.csv"],
                 ["--OUT", "x.csv"], ["--Periods", "2"], ["--", "x"], ["extra"], [""], ["-"],
                 ["--json=1"], ["--quiet=false"], ["--c_mu", "2"], ["-periods", "2"],
                 ["--" + "y" * 3000], ["\udcff"], ["--width", "0.05", "0.06"]]


def mutate_unknown(c, sub):
    rng = c.rng
    r = rng.random()
    if r < 0.25:  # a flag of another subcommand
        other = rng.choice(SUBCOMMANDS)
        flag = rng.choice([f for f in FLAGS[other] if f not in FLAGS[sub]] or ["bogus"])
        unit = ["--" + flag] if KIND.get(flag) == "bool" else ["--" + flag, rng.choice(pool(other, flag))]
        if KIND.get(flag) in ("out", "file"):
            unit = ["--" + flag, "z.csv"]
    elif r < 0.35:  # a flag of this subcommand without its value, last
        flag = rng.choice([f for f in FLAGS[sub] if KIND.get(f) != "bool"])
        c.units.append(["--" + flag])
        c.tags.append(f"--{flag} without value")
        return
    else:
        unit = rng.choice(UNKNOWN_UNITS)
    c.units.insert(rng.randint(0, len(c.units)), list(unit))
    c.tags.append("unknown " + short(" ".join(unit)))


def mutate_equals(c, sub):
    rng = c.rng
    r = rng.random()
    valued = [i for i, u in enumerate(c.units) if len(u) == 2 and u[0].startswith("--")]
    if r < 0.5 and valued:
        i = rng.choice(valued)
        c.units[i] = [c.units[i][0] + "=" + c.units[i][1]]
        c.tags.append(f"{c.units[i][0][:40]} form")
        return
    outs = [f for f in FLAGS[sub] if KIND.get(f) in ("out", "file")]
    flag = rng.choice(outs) if outs else "out"
    unit = rng.choice([["--%s=" % flag], ["--%s=" % flag, "--json"], ["--%s=" % flag, "--quiet"],
                       ["--%s=a.csv=b" % flag], ["--%s==x.csv" % flag], ["--%s" % flag, ""]])
    c.units.insert(rng.randint(0, len(c.units)), unit)
    c.tags.append(" ".join(unit) or "''")


def mutate_drop(c, sub):
    if c.units:
        u = c.units.pop(c.rng.randrange(len(c.units)))
        c.tags.append("dropped " + short(" ".join(u)))


def mutate_help(c, sub):
    c.units.insert(c.rng.randint(0, len(c.units)), [c.rng.choice(["--help", "-h", "--version"])])
    c.tags.append("help")


def mutate_big(c, sub):
    units = c.rng.choice(BIG_REQUESTS.get(sub, [["--bogus-big"]]))
    for i in range(0, len(units), 2):
        c.set(units[i][2:], units[i + 1] if i + 1 < len(units) else None)
    c.big = True
    c.tags.append("big " + " ".join(units))


def short(s, n=40):
    s = repr(s)[1:-1] if not isinstance(s, str) else s.encode("unicode_escape").decode()
    return s if len(s) <= n else s[: n - 12] + f"...({len(s)} ch)"
