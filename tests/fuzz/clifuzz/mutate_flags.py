"""Mutations of the command line's flags: numbers, text, lists, ranges, repeated, unknown and
`--flag=` forms, dropped units, help, big requests."""

from .values import (BIG, BIG_REQUESTS, COST, EDGE_INT, EDGE_LIST, EDGE_NUMBERS, EDGE_RANGE,
                     EDGE_TEXT, LAWS, NAN_HUGE, SMALL_INVALID, VALID, VALID_SAMPLES_CONSTANT)
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


# ---- single mutations with an expected outcome (Case.expect, checked in checks.py) ----
# Subcommands where a valid law on the valid base command must run (exit 0): every analysis
# takes the law (README). Not design (an infeasible request is an error, docs/cli.md) nor
# accumulation (D28: it takes the law or refuses its flags; docs/cli.md says which).
LAW_MUST_RUN = {"simulate", "steady", "floquet", "converge", "stop", "accuracy",
                "sweep accelerations", "sweep period", "sweep stroke", "sweep positioning",
                "optimize", "montecarlo"}


def nan_huge(c, sub):
    """NaN or a number beyond ±1e50 on one number flag of `sub`, whether the run uses it or
    not: exit 2 naming that flag (docs/cli.md "Errors"; D29, D35)."""
    flag = c.rng.choice([f for f in FLAGS[sub] if KIND.get(f) == "num"])
    v = c.rng.choice(NAN_HUGE)
    c.set(flag, v, anywhere=True)
    c.expect = ("refused", flag)
    c.tags.append(f"--{flag} {v} (must be refused)")


def law(c, sub):
    """A valid friction law on a subcommand that lists the law flags: it runs (D22, D27)."""
    laws = [u for u in LAWS if all(u[i][2:] in FLAGS[sub] for i in range(0, len(u), 2))]
    if not laws:
        return nan_huge(c, sub)
    units = c.rng.choice(laws)
    for i in range(0, len(units), 2):
        c.set(units[i][2:], units[i + 1])
    if sub in LAW_MUST_RUN:
        c.expect = ("runs",)
    c.tags.append("law " + " ".join(units))


def typo_of(rng, word):
    """`word` with one typo a user makes: two letters swapped, one dropped, '-' as '_'."""
    kinds = ["swap", "drop"] + (["underscore"] * 2 if "-" in word else [])
    kind = rng.choice(kinds)
    if kind == "underscore":
        return word.replace("-", "_")
    i = rng.randrange(1, len(word) - 1)
    if kind == "swap" and word[i] != word[i + 1]:
        return word[:i] + word[i + 1] + word[i] + word[i + 2:]
    return word[:i] + word[i + 1:]


def typo(c, sub):
    """A mistyped subcommand or flag: exit 2 with "did you mean ...?" (docs/cli.md)."""
    rng = c.rng
    names = [f for f in FLAGS[sub] if len(f) >= 5]
    if rng.random() < 0.4 or not names:
        i = len(c.sub) - 1  # the subcommand, or the sweep kind
        wrong = typo_of(rng, c.sub[i])
        if wrong in FLAGS or wrong in [s.split()[-1] for s in FLAGS]:
            return nan_huge(c, sub)
        c.sub[i] = wrong
    else:
        flag = rng.choice(names)
        wrong = typo_of(rng, flag)
        if wrong in FLAGS[sub]:
            return nan_huge(c, sub)
        unit = ["--" + wrong] if KIND.get(flag) == "bool" else ["--" + wrong, rng.choice(pool(sub, flag))]
        c.units.insert(rng.randint(0, len(c.units)), unit)
    c.expect = ("hint",)
    c.tags.append("typo " + " ".join(c.sub) + (f" --{wrong}" if c.sub[-1] != wrong else ""))


EXPECTING = [(nan_huge, 6), (law, 4), (typo, 2)]


def short(s, n=40):
    s = repr(s)[1:-1] if not isinstance(s, str) else s.encode("unicode_escape").decode()
    return s if len(s) <= n else s[: n - 12] + f"...({len(s)} ch)"
