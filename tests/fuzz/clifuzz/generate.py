"""Case i of a seed: the corpus for the first indices, then a random case built from
random.Random(f"{seed}:{i}") alone: a base command line, a profile, outputs, and weighted
mutations."""

from .case import Case
from .corpus import CORPUS, corpus_case
from .mutate_flags import (EXPECTING, mutate_big, mutate_drop, mutate_equals, mutate_help,
                           mutate_list, mutate_number, mutate_range, mutate_repeat, mutate_text,
                           mutate_unknown, pool, time_stepping_for_simulate)
from .mutate_documents import mutate_design_report, mutate_uncertainty_file
from .mutate_inputs import mutate_config, mutate_samples
from .mutate_outputs import ensure_samples, mutate_collision, output_flags
from .values import BASE
from .vocabulary import CONFIG_SUBS, CSV_SUMMARY_SUBS, FLAGS, SUBCOMMANDS


def choose_outputs(c, sub):
    rng = c.rng
    outs = output_flags(sub)
    r = rng.random()
    if sub in CSV_SUMMARY_SUBS:
        if r < 0.3:
            c.set("out", "o.csv")
        elif r < 0.4:
            c.set("out", "o.csv")
            c.set("summary", rng.choice(["s.json", "-", "o2.json"]))
        elif r < 0.5 and "json" in FLAGS[sub]:
            c.set("json")
        elif r < 0.55 and "json" in FLAGS[sub]:
            c.set("out", "o.csv")
            c.set("json")
        elif r < 0.6:
            c.set("summary", rng.choice(["-", "s.json"]))
    else:
        if r < 0.35:
            c.set("json")
        elif r < 0.55:
            c.set("out", "r.json")
        elif r < 0.6:
            c.set("out", "r.json")
            c.set("json")
        if "profile-csv" in outs and rng.random() < 0.3:
            c.set("profile-csv", "p.csv")
            c.set("sample-rate", rng.choice(pool(sub, "sample-rate")))


def choose_profile(c, sub):
    rng = c.rng
    r = rng.random()
    if r < 0.08:
        c.set("profile", "quadratic-sequence")
        c.set("durations", "0.3,0.4,0.3")
        c.set("accelerations", "0,-3,4")
        c.tags.append("quadratic-sequence")
    elif r < 0.14:
        c.set("profile", "fourier")
        c.set("fourier-cos", rng.choice(["0.04", "0.04,0.01"]))
        c.tags.append("fourier")
        time_stepping_for_simulate(c, sub)
    elif r < 0.2:
        ensure_samples(c)
        c.tags.append("samples")
    elif r < 0.27:
        c.set("units", "si")
        c.tags.append("si")
    elif r < 0.32 and sub == "simulate":
        c.set("method", "time-stepping")
        c.set("step", rng.choice(["1e-3", "1e-4"]))
        c.tags.append("time-stepping")


MUTATIONS = [(mutate_number, 30), (mutate_text, 6), (mutate_list, 6), (mutate_range, 5),
             (mutate_repeat, 4), (mutate_unknown, 5), (mutate_equals, 5), (mutate_drop, 3),
             (mutate_help, 1), (mutate_big, 3), (mutate_config, 14), (mutate_samples, 8),
             (mutate_collision, 14), (mutate_uncertainty_file, 4), (mutate_design_report, 4)]


def generate(index, seed):
    if index < len(CORPUS):
        return corpus_case(index, seed)
    c = Case(index, seed)
    rng = c.rng
    if rng.random() < 0.015:  # the top level
        c.sub = rng.choice([[], ["--help"], ["--version"], ["simulat"], ["sweep"], ["sweep", "x"],
                            ["sweep", "--help"], ["SIMULATE"], [""], ["-"], ["help"],
                            ["--version", "steady"], ["steady", "steady"], ["--bogus"],
                            ["sweep", "accelerations", "period"]])
        c.tags.append("top level")
        return c
    sub = rng.choice(SUBCOMMANDS)
    c.sub = sub.split()
    c.units = [list(u) for u in BASE[sub]]
    if rng.random() < 0.12:  # one mutation with an expected outcome, on the valid base
        fn = rng.choices([f for f, _ in EXPECTING], [w for _, w in EXPECTING])[0]
        fn(c, sub)
        return c
    if sub in CONFIG_SUBS:
        choose_profile(c, sub)
    choose_outputs(c, sub)
    fns = [f for f, _ in MUTATIONS]
    weights = [w for _, w in MUTATIONS]
    for _ in range(rng.choice([0, 1, 1, 1, 2, 2, 2, 3, 4])):
        fn = rng.choices(fns, weights)[0]
        if fn in (mutate_config,) and sub not in CONFIG_SUBS:
            fn = mutate_number
        fn(c, sub)
    if not c.tags:
        c.tags.append("valid")
    return c
