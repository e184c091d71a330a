#!/usr/bin/python3
"""Seeded fuzz of `selfalign planar` configs (standard library only): each case mutates one or
two keys of a small valid TOML config (numbers to 0, negatives, NaN, inf, huge, tiny, wrong
types, wrong array lengths; unknown keys; removed keys; other shapes and field types) and runs
one of simulate/steady/field/stop/parameters with --csv and --out; some cases set keys with --set
SECTION.KEY=VALUE instead of (or over) the file (good, bad and unknown keys, malformed
assignments: the same key table and checks as the file's values). About 40% of the cases are
valid-leaning instead: whole valid sections swapped in (every field type, part shape) and valid
--set flags; these must run, and a refusal fails the case. A few cases instead name the config as
an output, or one file by both outputs (./o.csv and o.csv, a parent path, a link: issue 20, D24,
D25), or nest the config 1e5 deep (D23): these must be refused. A case fails on a signal, an
exit code other than 0 or 2, an exit 2 whose stderr is not one "selfalign: error: " line or that
leaves a file behind, an exit 0 with anything on stderr or for a case that must be refused, or a
changed config. Runs slower than --timeout seconds are counted (long valid runs exist) but not
failures.

    /usr/bin/python3 tests/fuzz/fuzz_planar.py --binary build/release/apps/selfalign/selfalign \\
        --seed 1 --cases 200
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile

BASE = {
    "units": '"dimensionless"',
    "table.x": {"profile": '"three-phase"', "period": "1.0", "stroke": "0.084", "a2": "3.0", "a3": "0.9"},
    "table.y": {"profile": '"fourier"', "period": "0.5", "cos": "[0.01]", "sin": "[0.0]"},
    "table.rotation": {"profile": '"fourier"', "period": "1.0", "cos": "[0.02]", "sin": "[0.0]"},
    "part": {"inertia": "0.01", "shape": '"rectangle"', "length": "0.2", "width": "0.1", "nx": "2", "ny": "2"},
    "friction": {"mu_static": "0.24"},
    "field": {"type": '"circle"', "centre": "[0.3, 0.0]", "radius": "0.2", "width": "0.05", "c_mu": "2.5"},
    "run": {"step": "0.02", "periods": "3", "every": "5", "transient": "2", "steady_periods": "3",
            "pose": "[0.0, 0.0, 0.0]", "twist": "[0.1, 0.0, 0.5]"},
    "field_map": {"x": "[0.0, 0.2]", "y": "[0.0]", "angles": "[0.0]", "periods": "1"},
    "stop": {"entries": "[[0.0, 0.0, 0.0]]", "max_periods": "20"},
}
VALUES = ["0", "-1", "nan", "inf", "-inf", "1e300", "-1e300", "1e-300", "2", "0.5", "100000000",
          '"abc"', "[]", "[1.0]", "[1.0, 2.0, 3.0, 4.0]", "[nan, 1.0, 1.0]", "true", "3.5"]
ALTERNATIVES = {
    ("part", "shape"): ['"point"', '"disc"', '"polygon"', '"points"', '"blob"'],
    ("field", "type"): ['"uniform"', '"half-plane"', '"strip"', '"rectangle"', '"grid"', '"axis"', '"x"'],
    ("table.x", "profile"): ['"fourier"', '"sampled"'],
}
EXTRA = {  # keys that other shapes and types need, with good and bad values
    "part": {"radius": ["0.1", "-0.1"], "rings": ["2", "0"], "sectors": ["4", "100000"],
             "xs": ["[0.0, 0.1, 0.0]", "[0.0, 0.1, 0.1, 0.0]", "[-0.1, 0.1]"],
             "ys": ["[0.0, 0.0, 0.1]", "[0.0, 0.1, 0.0, 0.1]", "[0.0, 0.0]"],
             "loads": ["[0.5, 0.5]", "[0.6, 0.6]", "[1.5, -0.5]"], "subdivisions": ["2", "0"]},
    "field": {"levels": ["[1.0, 2.0, 1.0, 2.0]", "[1.0, nan, 1.0, 1.0]"], "dx": ["0.1"], "dy": ["0.1"],
              "nx": ["2", "1"], "ny": ["2"], "half_width": ["0.1", "0"], "half_length": ["0.2"],
              "origin": ["[0.1, 0.0]"], "angle": ["0.3", "nan"], "level": ["2.0", "-1"], "colour": ['"red"'],
              "positions": ["[0.0, 0.1, 0.2, 0.3]", "[0.3, 0.1]", "[0.1]"],
              "interpolation": ['"linear"', '"steps"', '"cubic"'],
              "file": ['"missing_field.csv"']},
}
# Whole sections that are valid (each field type and part shape with the keys it needs): a
# "valid-leaning" case swaps in one or two of them and sets valid keys, so that runs go ahead
# and the solvers, not only the reader, see varied input.
VALID_SECTIONS = {
    "field": [
        {"type": '"uniform"', "level": "2.0"},
        {"type": '"half-plane"', "origin": "[0.2, 0.0]", "angle": "0.3", "width": "0.05", "c_mu": "3.0"},
        {"type": '"strip"', "origin": "[0.2, 0.0]", "angle": "0.1", "half_width": "0.1", "width": "0.05", "c_mu": "2.0"},
        {"type": '"rectangle"', "centre": "[0.3, 0.0]", "half_length": "0.1", "half_width": "0.2", "width": "0.05", "c_mu": "2.5"},
        {"type": '"grid"', "origin": "[-0.5, -0.5]", "dx": "0.5", "dy": "0.5", "nx": "3", "ny": "3",
         "levels": "[1.0, 1.2, 1.5, 1.0, 1.3, 2.0, 1.1, 1.4, 3.0]"},
        {"type": '"axis"', "positions": "[0.0, 0.1, 0.25]", "levels": "[1.0, 1.5, 3.0]", "angle": "0.2"},
        {"type": '"axis"', "positions": "[0.0, 0.15]", "levels": "[1.0, 2.5]", "interpolation": '"linear"'},
    ],
    "part": [
        {"inertia": "0.02"},
        {"inertia": "0.01", "shape": '"disc"', "radius": "0.1", "rings": "2", "sectors": "5"},
        {"inertia": "0.01", "shape": '"polygon"', "xs": "[-0.1, 0.1, 0.0]", "ys": "[-0.05, -0.05, 0.1]"},
        {"inertia": "0.01", "shape": '"points"', "xs": "[-0.1, 0.1]", "ys": "[0.0, 0.0]", "loads": "[0.5, 0.5]"},
    ],
    "table.y": [{"profile": '"three-phase"', "period": "0.5", "stroke": "0.02", "a2": "2.0", "a3": "1.0"}],
    "friction": [{"mu_static": "0.3"}, {}],
}
VALID_SETS = ["run.periods=2", "run.theta=1", "run.step=0.025", "field.c_mu=3", "table.x.a2=4",
              "run.pose=0.05,0.02,0.3", "run.twist=0,0,0", "stop.max_periods=5"]
SET_VALUES = ["0", "-1", "nan", "inf", "1e300", "2", "0.5", "abc", "", "0.1,0.2", "[1, 2, 3]",
              "0,0,0", "[[0, 0, 0]]", "[[0, 0]]", "[[0, 0, nan]]", "3.5", "point", "fourier"]


def set_flags(rng):
    """Zero to three --set assignments: known keys (from BASE and EXTRA), unknown ones, or
    malformed text."""
    flags = []
    for _ in range(rng.choice([0, 0, 1, 1, 2, 3])):
        kind = rng.random()
        if kind < 0.1:
            flags += ["--set", rng.choice(["run.step", "=1", "run..step=1", "table.x=1", "stop=3"])]
            continue
        section = rng.choice([k for k, v in BASE.items() if isinstance(v, dict)] + ["run", "bogus"])
        keys = list(BASE.get(section, {})) + list(EXTRA.get(section, {})) + ["colour"]
        element = rng.choice(["", "", "", "[0]", "[2]", "[9]", "[x]", "[-1]", "["])
        flags += ["--set", f"{section}.{rng.choice(keys)}{element}={rng.choice(SET_VALUES)}"]
    return flags


def render(cfg):
    out = []
    for key, val in cfg.items():
        if not isinstance(val, dict):
            out.append(f"{key} = {val}")
    for key, val in cfg.items():
        if isinstance(val, dict):
            out.append(f"[{key}]")
            out.extend(f"{k} = {v}" for k, v in val.items())
    return "\n".join(out) + "\n"


def mutate(rng):
    cfg = {k: (dict(v) if isinstance(v, dict) else v) for k, v in BASE.items()}
    for _ in range(rng.choice([1, 1, 2, 3])):
        section = rng.choice([k for k, v in cfg.items() if isinstance(v, dict)] + ["__drop_section"])
        if section == "__drop_section":
            cfg.pop(rng.choice(["table.y", "table.rotation", "field", "friction", "stop"]), None)
            continue
        table = cfg[section]
        op = rng.random()
        if op < 0.15 and table:
            table.pop(rng.choice(list(table)))
        elif op < 0.3 and section in EXTRA:
            k = rng.choice(list(EXTRA[section]))
            table[k] = rng.choice(EXTRA[section][k])
        elif op < 0.4:
            table[rng.choice(["bogus", "Step", "inertia_kg"])] = "1.0"
        elif table:
            k = rng.choice(list(table))
            alts = ALTERNATIVES.get((section, k))
            table[k] = rng.choice(alts) if alts and rng.random() < 0.6 else rng.choice(VALUES)
    return cfg


def valid_leaning(rng):
    """One or two valid sections swapped in, and zero to two valid --set flags."""
    cfg = {k: (dict(v) if isinstance(v, dict) else v) for k, v in BASE.items()}
    for section in rng.sample(list(VALID_SECTIONS), rng.choice([1, 2])):
        cfg[section] = dict(rng.choice(VALID_SECTIONS[section]))
    flags = []
    for value in rng.sample(VALID_SETS, rng.choice([0, 1, 2])):
        flags += ["--set", value]
    return cfg, flags


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=200)
    ap.add_argument("--timeout", type=float, default=20)
    a = ap.parse_args()
    a.binary = os.path.abspath(a.binary)
    rng = random.Random(a.seed)
    failures, slow, ok, refused = [], 0, 0, 0
    for case in range(a.cases):
        valid = rng.random() < 0.4
        cfg, valid_flags = valid_leaning(rng) if valid else (mutate(rng), [])
        command = rng.choice(["simulate", "steady", "field", "stop", "parameters"])
        special = rng.choice(["aliased outputs", "output over config", "deep config"]) \
            if rng.random() < 0.08 else None
        with tempfile.TemporaryDirectory() as root:
            path = os.path.join(root, "p.toml")
            text = render(cfg)
            outputs = ["--csv", "o.csv", "--out", "r.json"]
            if special == "aliased outputs":
                outputs = rng.choice([["--csv", "./o.csv", "--out", "o.csv"],
                                      ["--csv", "o.csv", "--out", "../work/o.csv"]])
            elif special == "output over config":
                os.symlink("p.toml", os.path.join(root, "lnk"))
                outputs = ["--csv", rng.choice(["../p.toml", "../work/../p.toml", "../lnk"]),
                           "--out", "r.json"]
            elif special == "deep config":
                deep = 100000
                if rng.random() < 0.5:
                    path, text = os.path.join(root, "p.json"), "{\"table\": " + "[" * deep + "]" * deep + "}"
                else:
                    text = "table" + ".x" * deep + " = 1\n"
            with open(path, "w") as f:
                f.write(text)
            work = os.path.join(root, "work")
            os.mkdir(work)
            flags = valid_flags if valid else set_flags(rng)
            args = [a.binary, "planar", command, "--config", path] + outputs + flags
            try:
                r = subprocess.run(args, cwd=work, capture_output=True, text=True, timeout=a.timeout)
            except subprocess.TimeoutExpired:
                slow += 1
                continue
            left = os.listdir(work)
            why = None
            if r.returncode not in (0, 2):
                why = f"exit {r.returncode}"
            elif r.returncode == 2:
                refused += 1
                lines = r.stderr.splitlines()
                if len(lines) != 1 or not lines[0].startswith("selfalign: error: "):
                    why = "stderr not one error line: " + r.stderr[:300]
                elif left:
                    why = f"left {left}"
                elif valid and not special:
                    why = "a valid config was refused: " + lines[0][:300]
            else:
                ok += 1
                # docs/cli.md "Warnings": a run that goes ahead may add warning lines (planar
                # steady: the level under the part changed inside its windows), nothing else.
                noise = [ln for ln in r.stderr.splitlines() if not ln.startswith("selfalign: warning: ")]
                if noise:
                    why = "stderr on success: " + "\n".join(noise)[:300]
                elif special:
                    why = f"{special}: exit 0, must be refused ({' '.join(outputs)})"
            with open(path) as f:
                if f.read() != text:
                    why = f"the config was changed ({' '.join(outputs)})"
            if why:
                failures.append((case, command, why, text[:2000]))
    print(f"planar fuzz seed {a.seed}: {a.cases} cases, {ok} ran, {refused} refused, {slow} slow, "
          f"{len(failures)} failed")
    for case, command, why, text in failures[:10]:
        print(f"--- case {case} ({command}): {why}\n{text}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
