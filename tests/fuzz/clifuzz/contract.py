"""Documented allowances: what docs/cli.md and docs/config.md let a run do, each with its source.

Non-finite CSV cells and JSON nulls that are documented, what an error line may name and must
not show, and the limits of an error line and of a run's time."""

from .vocabulary import CONFIG_KEYS, FLAGS


# CSV columns that may hold nan / inf, and when: subcommand -> {column: rule}.
ALLOWED_NONFINITE_CSV = {
    # docs/cli.md, "sweep accelerations": "Non-physical cells (case 0) have nan in v_bar, f,
    # x_dot_0s and converged 0; v̄ = 0 gives f = inf".
    "sweep accelerations": {"v_bar": "nan-if-case0", "x_dot_0s": "nan-if-case0",
                            "f": "nan-if-case0-inf-if-vbar0"},
    # docs/cli.md, "sweep period, sweep stroke": "physical 0 (...) then case 0 and nan in v_bar
    # and f"; f = 1/(10000 v̄²) (eq. 11) is inf for v̄ = 0 (cli.md "steady": f "null when infinite
    # (v̄ = 0)"; README "sweep": "Non-finite values are inf / nan in CSV").
    "sweep period": {"v_bar": "nan-if-nonphysical", "f": "nan-if-nonphysical-inf-if-vbar0"},
    "sweep stroke": {"v_bar": "nan-if-nonphysical", "f": "nan-if-nonphysical-inf-if-vbar0"},
    # docs/cli.md, "sweep positioning": "f [-] (nan for case 0)", "Δx_d ([-] / m; nan where the
    # object does not arrive or an entry does not stop)"; f = inf for v̄ = 0 as above (the CSV has
    # no v_bar column: inf is accepted in f).
    "sweep positioning": {"f": "nan-if-case0-or-inf", "dx_d": "any"},
    # docs/cli.md, "accuracy": "end position and end - x_mu ([-] / m; nan when the entry did not
    # stop)".
    "accuracy": {"end_position": "nan-if-not-stopped", "overshoot": "nan-if-not-stopped"},
}
# Sweep rows with status "failed" (docs/cli.md, "sweep accelerations": "status ok, or failed for a
# cell that could not be computed (never expected; its numbers are nan and the summary's failures
# says why)") may hold nan in every column but the grid's own; they are counted as notes.
GRID_COLUMNS = {"a2", "a3", "period", "stroke"}
TEXT_CSV_COLUMNS = {"stop", "status"}  # accuracy: the stop kind; sweeps: ok / failed
# f = 1/(10000 v̄²) overflows a double for |v̄| < 1/sqrt(1e4 · DBL_MAX) = 7.5e-157.
F_OVERFLOW_VBAR = 7.4e-157


# JSON keys that may be null, per subcommand (docs/cli.md, docs/config.md). A key path is the
# chain of object keys joined by '.', list indices dropped. Conditions are checked separately.
NULLABLE = {
    # docs/config.md "Summary JSON": mean_velocity_last_period "null when the run is shorter than
    # a period"; stick_fraction "null when no trajectory is written" (checked in check_json);
    # scales "null in dimensionless runs"; trajectory_file "or null"; friction "c_mu (null for
    # uniform)" (x_mu and width likewise have no meaning for uniform).
    # "integrator" and the law's speed terms: null unless the law has them (docs/config.md).
    "simulate": {"mean_velocity_last_period", "stick_fraction", "scales", "trajectory_file",
                 "friction.x_mu", "friction.width", "friction.c_mu", "integrator",
                 "law.stribeck_velocity", "law.stribeck_exponent", "law.viscous"},
    # docs/cli.md "steady" key table and the case-0 paragraph.
    "steady": {"case_a_priori", "v_bar", "f", "x_dot_0s", "x_dot_0s_error", "phase", "displacement", "converged",
               "periods", "method", "a2", "a3", "t1", "t2", "t3", "y_ini", "y_dot_ini", "jerk",
               "pattern", "integrator", "law.stribeck_velocity", "law.stribeck_exponent",
               "law.viscous"},
    # docs/cli.md "floquet": matrix, multipliers "null where available is false";
    # slip_slip_lambda2_formula "null otherwise".
    "floquet": {"analytic.matrix", "analytic.multipliers", "saltation.matrix",
                "saltation.multipliers", "finite_difference.matrix",
                "finite_difference.multipliers", "slip_slip_lambda2_formula", "spread",
                "integrator", "law.stribeck_velocity", "law.stribeck_exponent", "law.viscous"},
    # docs/cli.md "converge": t_coincide "null if not reached", csv_file "or null".
    "converge": {"t_coincide", "csv_file"},
    # docs/cli.md "stop" key table; "Every report has ... csv_file (the CSV path or null)".
    "stop": {"law.stribeck_velocity", "law.stribeck_exponent", "law.viscous",
             "end_position", "process_time", "entry_time", "x_stick_min", "fractions.position",
             "fractions.time", "fractions.periods_from_entry", "csv_file"},
    # docs/cli.md "accuracy": reaches false -> "nothing below is computed: null"; x_stick_min
    # "null when max|y''| > c_mu"; dx_d, x_d "null unless every entry stopped"; overshoot_* are
    # "over the entries that stopped" (none: null).
    "accuracy": {"case", "case_name", "v_bar", "x_dot_0s", "f", "x_mu", "x_stick_min",
                 "overshoot_min", "overshoot_max", "dx_d", "x_d", "csv_file"},
    # docs/cli.md "accumulation": x_stick_min "null when max|y''| > c_mu" (and so the difference
    # with it, and contraction_at_fixed_point "null where x_stick,min does not exist");
    # iterates.fractions "(null: not within them)"; accumulates_for_every_entry "null where the
    # condition's derivation does not hold", accumulation_condition_reason null when it applies
    # (the pairing is checked in check_json).
    "accumulation": {"x_stick_min", "fixed_point_minus_x_stick_min", "iterates.fractions.position",
                     "iterates.fractions.iterations", "csv_file", "accumulation_condition_reason",
                     "accumulates_for_every_entry", "contraction_at_fixed_point"},
    # docs/cli.md "sweep period, sweep stroke": a2, a3 "(three-phase family; else null)";
    # summaries: csv_file.
    # and the law's speed terms (docs/config.md: null when the law has none).
    "sweep accelerations": {"csv_file", "law.stribeck_velocity", "law.stribeck_exponent",
                            "law.viscous"},
    "sweep period": {"csv_file", "a2", "a3", "law.stribeck_velocity", "law.stribeck_exponent",
                     "law.viscous"},
    "sweep stroke": {"csv_file", "a2", "a3", "law.stribeck_velocity", "law.stribeck_exponent",
                     "law.viscous"},
    "sweep positioning": {"csv_file", "law.stribeck_velocity", "law.stribeck_exponent",
                          "law.viscous"},
    "optimize": {"law.stribeck_velocity", "law.stribeck_exponent", "law.viscous", "results.f", "results.v_bar", "results.max_jerk", "limits.max_jerk"},  # f, v_bar: infeasible results only (check_json); max_jerk: infinite (no limit, jumps)
    # docs/cli.md "design": jerk null without a limit; law as for steady (no speed terms); fragility's end positions and shifts
    # null where a run with mu or c_mu off does not stop; T_p quantiles null (infinite) when
    # more runs than 1 - q never stop; end-position quantiles null when none stopped.
    "design": {"profile.jerk_m_per_s3", "fragility.end_m_with_c_mu_low_high",
               "fragility.end_m_with_mu_low_high", "fragility.end_shift_c_mu_m",
               "fragility.end_shift_mu_m", "fragility.end_nominal_m",
               "robust.time_quantile_value_s", "request.mu_static", "request.mu_backward",
               "law.stribeck_velocity", "law.stribeck_exponent", "law.viscous"}
              | {f"{block}.process_time_quantiles_s.{q}" for block in ("monte_carlo", "robust.verification") for q in ("0.5", "0.9", "0.99")}
              | {f"{block}.end_position_quantiles_m.{q}" for block in ("monte_carlo", "robust.verification") for q in ("0.005", "0.05", "0.5", "0.95", "0.995")}
              | {"monte_carlo.process_time_at_quantile_s", "robust.verification.process_time_at_quantile_s"},
    # docs/cli.md "montecarlo": the same quantiles; the worst case's error, end and T_p null
    # when a run in the box does not stop; jerk null without a limit.
    # docs/cli.md "parameters": a value is null when absent (no Stribeck decay).
    "parameters": {"parameters.value"},
    "montecarlo": {"process.jerk_m_per_s3", "worst_case.worst_error_m",
                   "worst_case.worst_end_position_m", "worst_case.slowest_process_time_s"}
                  | {f"monte_carlo.process_time_quantiles_s.{q}" for q in ("0.5", "0.9", "0.99")}
                  | {f"monte_carlo.end_position_quantiles_m.{q}" for q in ("0.005", "0.05", "0.5", "0.95", "0.995")}
                  | {"monte_carlo.process_time_at_quantile_s"},
}

# Markers of library internals that must not reach a user's error line.
INTERNALS = ["std::", "vector::", "CLI::", "toml::", "nlohmann::", "tbb::", "bad_alloc", "bad_array_new_length", "basic_string", "_M_",
             "Unable to cast", "terminate called", "what()", "stoi", "stod", "nlohmann", "tbb",
             "TBB", "Eigen", "__cxa", "Assertion", "vector", "out_of_range", "invalid_argument",
             "length_error", "nlopt", "NLopt", "json.exception", "TOML_"]
# Errors about a JSON / TOML document: they name the file, the line and the column
# (docs/cli.md, "Errors"; D31: "number overflow" named neither).
DOCUMENT_ERRORS = ["parse error", "syntax error", "number overflow", "not valid JSON",
                   "not valid TOML", "nests too deeply"]
DOCUMENTED_INTERNALS = []  # docs/config.md no longer shows a parser id in any message

SANITIZER_MARKERS = ["ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:",
                     "UndefinedBehaviorSanitizer", "AddressSanitizer:", "ThreadSanitizer"]

ALL_FLAGS = sorted({f for fl in FLAGS.values() for f in fl} | {"help", "version"})
# docs/parameters.md: the parameter view's own names (the factors on the table's motion).
PARAM_NAMES = (set(ALL_FLAGS) | {f.replace("-", "_") for f in ALL_FLAGS} | set(CONFIG_KEYS)
               | {"amplitude_scale", "time_scale"})
GENERIC_NAMES = ["fraction p", "config file", "config key", "output file", "output", "samples", "summary",
                 "subcommand", "argument", "design infeasible", "profile", "file", "input"]
PREFIX = "selfalign: error: "
# docs/cli.md "Errors": a run that goes ahead with something to know adds warning lines on
# stderr (exit 0 only; an error is one line and no warning).
WARNING_PREFIX = "selfalign: warning: "
HELP_FLAGS = {"--help", "-h", "--version"}


# Limits.
# apps/selfalign/main.cpp cuts a message at kMaxErrorLine = 300 characters and appends "...".
MAX_ERROR_LINE = 303
# Time limits of one run: the fuzzer's own choice (stated in tests/fuzz/README.md), release build;
# --asan multiplies both by 5 (--timeout-scale). Big requests must be refused quickly.
CASE_TIMEOUT_S = 20.0
BIG_REQUEST_TIMEOUT_S = 5.0
