"""The command line, as `selfalign SUBCOMMAND --help` lists it: subcommands, their flags, the
kind of value each flag takes, and the config file's keys."""

import re
import subprocess


CONFIG_KEYS = [  # docs/config.md, "Keys"
    "units", "method", "profile", "period", "stroke", "a2", "a3", "jerk", "durations",
    "accelerations", "times", "fourier_cos", "fourier_sin", "samples", "interpolation", "friction",
    "field_file", "field_positions", "field_levels", "field_interpolation", "footprint", "x_mu", "width", "c_mu", "mu_static",
    "mu_backward", "stribeck_velocity", "stribeck_exponent", "viscous", "mu", "g", "length_scale",
    "mass", "t0", "x0", "v0", "periods", "step", "theta", "output_step", "relative_tolerance",
    "absolute_tolerance", "out", "summary"]

# The friction law's flags (docs/config.md, "Friction law"): every subcommand that describes a
# table motion takes them.
LAW = ["mu-static", "mu-backward", "stribeck-velocity", "stribeck-exponent", "viscous",
       "relative-tolerance", "absolute-tolerance"]
_PROFILE = ["config", "units", "profile", "period", "stroke", "a2", "a3", "jerk", "durations",
            "accelerations", "times", "fourier-cos", "fourier-sin", "samples", "interpolation"]
_FIELD = ["field-file", "field-positions", "field-levels", "field-interpolation", "footprint"]
_SCALES = ["mu", "g", "length-scale", "mass"]
_MODEL = (_PROFILE + ["method", "friction"] + _FIELD + ["x-mu", "width", "c-mu"] + LAW + _SCALES
          + ["t0", "x0", "v0", "periods", "step", "theta", "output-step"])
# A steady state on the uniform table reads no friction map, initial state or time-stepping keys
# (its flags are the profile, the law with the integrator's tolerances, the scales).
_UNIFORM = _PROFILE + LAW + _SCALES
# The sweeps always run three-phase profiles: no profile choice, and no flag for the swept values.
_THREE_PHASE = ["config", "units", "period", "stroke", "a2", "a3", "jerk"] + LAW + _SCALES
_SECT7 = _PROFILE + _FIELD + ["width", "c-mu"] + LAW + _SCALES
_SWEEP = ["out", "summary", "threads", "quiet", "log"]
_REQUEST = ["mass", "width", "mu", "c-mu", "g", "distance", "stroke-max", "frequency-min",
            "frequency-max", "velocity-max", "acceleration-max", "jerk-max", "mu-static",
            "mu-backward", "tolerance", "uncertain", "uncertainty-file"]

FLAGS = {  # as `selfalign SUBCOMMAND --help` lists them (fuzz_cli.py checks it at start)
    "simulate": _MODEL + ["out", "summary"],
    "steady": _UNIFORM + ["out", "json"],
    "floquet": _UNIFORM + ["fd-step", "out", "json"],
    "converge": _UNIFORM + ["t0", "periods", "v1", "v2", "out", "summary", "samples-per-period"],
    "stop": _SECT7 + ["x-mu", "t0", "x0", "v0", "output-step", "fractions", "max-periods", "out",
                      "summary", "json"],
    "accuracy": _SECT7 + ["out", "summary", "json", "entries", "max-periods"],
    # accumulation: eq. (59) is the paper's law's, so no law flags (issue 20, D28)
    "accumulation": [f for f in _SECT7 if f not in LAW] + ["x-mu", "out", "summary", "json", "x1",
                                                          "from", "to", "n"],
    "sweep accelerations": [f for f in _THREE_PHASE if f not in ("a2", "a3")] + _SWEEP
    + ["a2-range", "a3-range", "search"],
    "sweep period": [f for f in _THREE_PHASE if f != "period"] + _SWEEP + ["range", "family"],
    "sweep stroke": [f for f in _THREE_PHASE if f != "stroke"] + _SWEEP + ["range", "family"],
    "sweep positioning": [f for f in _THREE_PHASE if f not in ("a2", "a3")] + _SWEEP
    + ["friction"] + _FIELD + ["width", "c-mu", "a2-range", "a3-range", "entries", "max-periods"],
    "optimize": ["family", "period", "stroke", "velocity-max", "acceleration-max", "jerk-max", "mu",
                 "mu-static", "mu-backward", "order", "segments", "starts", "max-evaluations",
                 "seed", "threads", "json", "quiet", "out"],
    "design": _REQUEST + ["acceleration-grid", "period-grid", "stroke-grid", "entries", "json",
                          "out", "profile-csv", "sample-rate", "robust", "probability-target",
                          "time-quantile", "screening-runs", "verification-runs", "finalists",
                          "seed", "threads", "monte-carlo", "fragility-level", "quiet",
                          "moving-mass"],
    "montecarlo": _REQUEST + ["design", "period-s", "stroke-m", "a2", "a3", "jerk", "x-mu", "runs",
                              "seed", "first-run", "max-periods", "threads", "time-quantile",
                              "bins", "worst-case", "sigmas", "interior-points", "json", "quiet",
                              "out", "runs-csv"],
    # the model's parameter view: its model keys (no solver or output key), --set, --json
    "parameters": _PROFILE + ["friction"] + _FIELD + ["x-mu", "width", "c-mu"]
    + LAW[:5] + ["mu", "g", "length-scale", "t0", "x0", "v0", "out", "json", "set"],
}
SUBCOMMANDS = list(FLAGS)
CONFIG_SUBS = [s for s in SUBCOMMANDS if "config" in FLAGS[s]]
# Subcommands whose --out is a CSV with a summary JSON beside it (`<out stem>.summary.json`).
CSV_SUMMARY_SUBS = ["simulate", "converge", "stop", "accuracy", "accumulation",
                    "sweep accelerations", "sweep period", "sweep stroke", "sweep positioning"]

KIND = {}  # flag -> num | int | list | text | file | out | range | bool
for _f in ["period", "stroke", "a2", "a3", "x-mu", "width", "c-mu", "mu", "g", "length-scale",
           "mass", "t0", "x0", "v0", "periods", "step", "theta", "output-step", "fd-step", "v1",
           "v2", "x1", "from", "to", "velocity-max", "acceleration-max", "distance", "stroke-max",
           "frequency-min", "frequency-max", "tolerance", "sample-rate", "jerk-max", "mu-static",
           "mu-backward", "probability-target", "time-quantile", "fragility-level",
           "moving-mass", "period-s", "stroke-m", "jerk", "sigmas", "stribeck-velocity",
           "stribeck-exponent", "viscous", "relative-tolerance", "absolute-tolerance"]:
    KIND[_f] = "num"
for _f in ["samples-per-period", "max-periods", "entries", "n", "threads", "order", "segments",
           "starts", "max-evaluations", "seed", "acceleration-grid", "period-grid", "stroke-grid",
           "screening-runs", "verification-runs", "finalists", "monte-carlo", "runs", "first-run",
           "bins", "interior-points"]:
    KIND[_f] = "int"
for _f in ["durations", "accelerations", "times", "fourier-cos", "fourier-sin", "fractions",
           "field-positions", "field-levels"]:
    KIND[_f] = "list"
for _f in ["units", "method", "profile", "interpolation", "friction", "family", "uncertain",
           "field-interpolation", "footprint", "set"]:
    KIND[_f] = "text"
for _f in ["config", "samples", "uncertainty-file", "design", "field-file"]:
    KIND[_f] = "file"
for _f in ["out", "summary", "profile-csv", "runs-csv"]:
    KIND[_f] = "out"
for _f in ["a2-range", "a3-range", "range"]:
    KIND[_f] = "range"
for _f in ["json", "quiet", "log", "robust", "worst-case", "search"]:
    KIND[_f] = "bool"


def drift_from_help(binary):
    """Flags `selfalign SUBCOMMAND --help` lists that FLAGS lacks, and the reverse: a flag the
    fuzzer does not know is a flag it never mutates (fuzz_cli.py refuses to run then)."""
    problems = []
    for sub in SUBCOMMANDS:
        out = subprocess.run([binary] + sub.split() + ["--help"], capture_output=True,
                             text=True, timeout=30).stdout
        listed = set(re.findall(r"^\s+--([a-z0-9-]+)", out, re.M)) - {"help"}
        for f in sorted(listed - set(FLAGS[sub])):
            problems.append(f"{sub}: --{f} is in --help but not in clifuzz/vocabulary.py")
        for f in sorted(set(FLAGS[sub]) - listed):
            problems.append(f"{sub}: --{f} is in clifuzz/vocabulary.py but not in --help")
    return problems
