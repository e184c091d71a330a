"""Seeded fuzz test of the Python API (issue 9).

Every public function and class of `selfalign` is called with mutated arguments (NaN, inf,
negative, zero, huge, denormal, wrong types, huge thread counts and orders, out-of-range enum
values, attributes such as ExactState.segment set to nonsense). Each call must either

  * return a result with no NaN where a number is expected (NaN, inf and None only where the
    docstrings say so: see the checks below, each citing its docstring), or
  * raise selfalign.InvalidParameter, ValueError or TypeError with a one-line message that names
    the parameter and carries no C++ internals ("std::", "vector::", "bad_alloc",
    "Unable to cast", "json.exception", ...),

and never crash the interpreter or hang. Issue 20 added: objects of every class made by
cls.__new__ alone and used in every way (D33), pickles of every kind of object under protocols
0 .. 5 (D37), and, as fixed calls, every parameter of every function and constructor given an
object of a foreign type, whose refusal must name that parameter (D38). The calls run in a worker subprocess (python -X
faulthandler) so a segfault is seen as the worker's death; the parent restarts a worker after
the crashing call and goes on. A call is Python source, so every failure is printed with a
reproducer to paste into a shell.

  SELFALIGN_FUZZ_SEED       seed (default 20100601)
  SELFALIGN_FUZZ_API_CALLS  number of random calls after the fixed ones (default 1500)
"""

import json
import math
import os
import random
import re
import select
import signal
import subprocess
import sys
import tempfile
import time

SEED = int(os.environ.get("SELFALIGN_FUZZ_SEED", "20100601"))
CALLS = int(os.environ.get("SELFALIGN_FUZZ_API_CALLS", "1500"))
CALL_TIMEOUT = float(os.environ.get("SELFALIGN_FUZZ_API_TIMEOUT", "6"))
MEMORY_LIMIT = 4 << 30  # address space of the worker: a runaway allocation fails, not the machine
# InvalidParameter shows the name and the value up to 60 characters, the range up to 240 (src/error.cpp)
MAX_MESSAGE = 500

PRELUDE = ("import copy, math, pickle, numpy as np, selfalign as sa; nan, inf = math.nan, math.inf; "
           "Wrong = type('Wrong', (), {}); "
           "P = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3); "
           "Q = sa.PiecewisePolynomialProfile.from_accelerations([0.3, 0.4, 0.3], [0.0, -3.0, 4.0]); "
           "R = sa.FourierProfile(1.0, [0.04], [0.0]); "
           "F = sa.two_region_friction(0.5, 0.05, 2.5); U = sa.UniformFriction()")

INTERNALS = ["std::", "vector::", "bad_alloc", "bad_array_new_length", "basic_string", "_M_",
             "Unable to cast", "json.exception", "terminate called", "nlohmann", "tbb::",
             "PYBIND11", "Eigen", "__cxa"]
ALLOWED_TYPES = ("InvalidParameter", "ValueError", "TypeError")

# ---- argument pools (Python source) ----------------------------------------------------------

BAD_FLOAT = ["nan", "inf", "-inf", "0.0", "-0.0", "-1.0", "1e308", "-1e308", "5e-324", "1e-300",
             "2**2000", "'x'", "None", "[1.0]", "True", "np.float64('nan')", "1j", "''"]
BAD_INT = ["0", "-1", "3", "4", "100", "2**31", "2**63", "10**30", "-(2**31) - 1", "1.5", "'3'", "None", "nan",
           "np.int64(-5)", "2**64"]
BAD_ARRAY = ["[]", "[nan]", "[inf]", "[1e308, -1e308]", "np.zeros((2, 2))", "'abc'", "[[1.0, 2.0]]",
             "None", "[1.0, 'a']", "np.array([1.0, nan])", "[5e-324]", "[-1.0]", "[0.0, 0.0]",
             "np.array([1, 2], dtype=np.int8)", "np.array([], dtype=float)", "{1: 2}"]
BAD_CALLBACK = ["42", "lambda: None", "'x'"]
RAISING_CALLBACK = "lambda done, total: 1 / 0"   # the user's exception may propagate as is

# Parameter spec: (valid source values, bad source values, big source values).
# Big values ask for unbounded work or memory: they must be refused (or done) within the timeout.
FL = lambda *valid: (list(valid), BAD_FLOAT, [])           # noqa: E731
IN = lambda *valid, big=(): (list(valid), BAD_INT, list(big))  # noqa: E731
AR = lambda *valid, big=(): (list(valid), BAD_ARRAY, list(big))  # noqa: E731

PROFILES = (["P", "Q"], ["R", "None", "F", "sa.ThreePhaseParameters(1, 0.084, 2.3, 1.3)", "1"], [])
TPROFILES = (["P"], ["Q", "R", "None", "'P'"], [])
FRICTIONS = (["F", "U"], ["None", "P", "sa.two_region_friction(0.5, 5e-324, 2.5)",
                          "sa.two_region_friction(1e308, 0.05, 2.5)", "sa.UniformFriction(1e308)"], [])
TWO_REGION = (["F"], ["U", "None", "sa.two_region_friction(0.5, 5e-324, 2.5)",
                      "sa.two_region_friction(0.5, 0.05, 1e308)", "sa.two_region_friction(-1e308, 1e308, 3e16)"], [])
TABLE = (["F.two_region", "sa.TwoRegionTable(0.5, 0.05, 2.5)"],
         ["U", "F", "None", "sa.TwoRegionTable(0.5, 5e-324, 2.5)", "sa.TwoRegionTable(0.5, 0.05, 1e308)",
          "sa.TwoRegionTable(-1e308, 1e308, 3e16)", "sa.TwoRegionTable(1e51, 1e43, 2.5)"], [])
THREADS = IN("0", "1", "2", big=["10**9", "2**31 - 1"])
PROGRESS = (["None", "lambda done, total: None"], BAD_CALLBACK + [RAISING_CALLBACK], [])
METHOD = (["'exact'", "'time-stepping'", "sa.Method.exact"],
          ["'x'", "''", "None", "sa.Method(5)", "5", "sa.Method(-1)"], [])
INTERP = (["'constant'", "'linear'", "sa.Interpolation.linear"],
          ["'cubic'", "None", "sa.Interpolation(7)", "3", "''"], [])
SMALL_A2 = AR("[1.0, 2.3]", "np.array([0.5, 3.0])", big=["np.linspace(0.1, 3, 100000)"])
SMALL_A3 = AR("[1.3]", "[0.9, 2.0]", big=["np.linspace(0.1, 3, 100000)"])
# A million valid cells is a long computation, not misuse: the sweeps take up to 1e7 cells, so
# the "big" grid here is beyond that limit (refused at once), not inside it.
PERIODS_GRID = AR("[0.5, 1.0]", "[2.0]", big=["np.linspace(0.1, 3, 2 * 10**7)"])
BOOL = (["True", "False"], ["None", "'yes'", "2"], [])

# (template, {parameter: spec}, validator). A template assigns `result`.
CATALOGUE = [
    ("result = sa.Scales({length_m}, {mu}, {gravity}).time",
     {"length_m": FL("1e-3"), "mu": FL("0.3"), "gravity": FL("9.81")}, "finite_if_finite_inputs"),
    ("result = sa.Scales(1e-3, 0.3).{conv}({value})",
     {"conv": (["length_to_si", "time_from_si", "velocity_to_si", "acceleration_from_si"], [], []),
      "value": (["1.0", "[1.0, 2.0]"], BAD_FLOAT + BAD_ARRAY, [])}, "finite_if_finite_inputs"),
    ("result = sa.UniformFriction({level}).bound({x})",
     {"level": FL("1.0"), "x": (["0.3", "[0.0, 1.0]"], BAD_FLOAT + BAD_ARRAY, [])}, "finite_if_finite_inputs"),
    ("f = sa.two_region_friction({x_mu}, {width}, {c_mu}); result = (f.bound({x}), f.pieces(), f.two_region.b1, f.two_region.b2)",
     {"x_mu": FL("0.5"), "width": FL("0.05"), "c_mu": FL("2.5"),
      "x": (["0.52", "np.linspace(0, 1, 5)"], BAD_FLOAT + BAD_ARRAY, [])}, "finite_if_finite_inputs"),
    ("result = sa.solve_three_phase(sa.ThreePhaseParameters({period}, {stroke}, {a2}, {a3}))",
     {"period": FL("1.0"), "stroke": FL("0.084"), "a2": FL("2.3", "1e5"), "a3": FL("1.3", "0.9")}, "solution"),
    ("result = sa.predict_case(sa.ThreePhaseParameters({period}, {stroke}, {a2}, {a3}))",
     {"period": FL("1.0"), "stroke": FL("0.084"), "a2": FL("2.3"), "a3": FL("1.3")}, "none"),
    ("p = sa.ThreePhaseParameters(1.0, 0.084, 2.3, 1.3); p.{attr} = {value}; p.validate(); "
     "result = sa.ThreePhaseProfile(p).sample(np.linspace(0, 1, 11))",
     {"attr": (["period", "stroke", "a2", "a3"], [], []), "value": FL("1.5")}, "finite_if_finite_inputs"),
    ("result = sa.ThreePhaseProfile({period}, {stroke}, {a2}, {a3}).sample({t})",
     {"period": FL("1.0"), "stroke": FL("0.084"), "a2": FL("2.3"), "a3": FL("1.3"),
      "t": (["0.25", "np.linspace(0, 2, 7)"], BAD_FLOAT + BAD_ARRAY, [])}, "finite_if_finite_inputs"),
    ("q = sa.PiecewisePolynomialProfile.from_accelerations({durations}, {accels}); "
     "result = (q.sample({t}), q.segment_at({phase}), q.phase({t}), q.segments())",
     {"durations": AR("[0.3, 0.4, 0.3]"), "accels": AR("[0.0, -3.0, 4.0]"),
      "t": FL("0.5"), "phase": FL("0.1")}, "finite_if_finite_inputs"),
    ("r = sa.FourierProfile({period}, {cos}, {sin}); result = (r.sample({t}), r.stroke, r.peak_acceleration)",
     {"period": FL("1.0"), "cos": AR("[0.04]", "[0.04, 0.01]", big=["np.full(10**6, 1e-9)"]),
      "sin": AR("[0.0]", "[]"), "t": FL("0.3")}, "finite_if_finite_inputs"),
    ("s = sa.AccelerationSamples({t}, {ydd}); result = sa.make_sampled_profile(s, {interp}).sample(0.3)",
     {"t": AR("[0.0, 0.5, 1.0]", "[0.0, 0.25, 0.5, 0.75, 1.0]"),
      "ydd": AR("[1.0, -1.0, 0.0]", "[0.0, 1.0, 0.0, -1.0, 0.0]"), "interp": INTERP}, "finite_if_finite_inputs"),
    ("s = sa.AccelerationSamples([0.0, 0.5, 1.0], [1.0, -1.0, 0.0]); s.{attr} = {value}; "
     "result = sa.make_sampled_profile(s).sample(0.3)",
     {"attr": (["t", "ydd"], [], []), "value": AR("[0.0, 0.5, 1.0]")}, "finite_if_finite_inputs"),
    ("result = sa.LinearAccelerationProfile(sa.AccelerationSamples({t}, {ydd})).sample(0.5)",
     {"t": AR("[0.0, 0.5, 1.0]"), "ydd": AR("[0.0, 1.0, 0.0]")}, "finite_if_finite_inputs"),
    ("result = sa.read_acceleration_samples({path})",
     {"path": (["'/dev/null'"], ["'/nonexistent.csv'", "'/'", "''", "None", "123", "'\\x00'",
                                  "b'/nonexistent'", "'x' * 5000"], [])}, "none"),
    ("result = sa.simulate({profile}, {friction}, sa.ObjectState({t0}, {x0}, {xd0}), "
     "sa.SimulationOptions(method={method}, duration={duration}, step={step}, theta={theta}, "
     "output_step={output_step}, record={record}))",
     {"profile": PROFILES, "friction": FRICTIONS, "t0": FL("0.0", "0.25"), "x0": FL("0.0", "0.45"),
      "xd0": FL("0.0", "-0.1"), "method": METHOD, "duration": (["2.0", "0.5"], BAD_FLOAT, ["1e12", "1e308"]),
      "step": (["1e-3"], BAD_FLOAT, ["1e-12"]), "theta": FL("0.5", "1.0"),
      "output_step": (["0.0", "0.05"], BAD_FLOAT, ["1e-12"]), "record": BOOL}, "simulation"),
    ("s = sa.make_exact_state({profile}, {friction}, sa.ObjectState({t0}, {x0}, {xd0})); s.{attr} = {value}; "
     "n = sa.advance_exact({profile}, {friction}, s, {t_end}); result = (n, s.object, s.segment, s.period_index)",
     {"profile": PROFILES, "friction": FRICTIONS, "t0": FL("0.0"), "x0": FL("0.0"), "xd0": FL("0.0"),
      "attr": (["segment", "period_index"], [], []),
      "value": IN("0", "1", "2"), "t_end": (["2.0"], BAD_FLOAT, [])}, "exact_state"),
    ("s = sa.make_exact_state(P, F); s.object = sa.ObjectState({t}, {x}, {xd}); "
     "n = sa.advance_exact(P, F, s, {t_end}); result = (n, s.object)",
     {"t": FL("0.0", "0.5"), "x": FL("0.0", "0.6"), "xd": FL("0.0", "0.1"),
      "t_end": (["2.0"], BAD_FLOAT, [])}, "exact_state"),
    ("result = sa.exact_arcs({profile}, {friction}, sa.ObjectState(), {duration})",
     {"profile": PROFILES, "friction": FRICTIONS, "duration": (["2.0"], BAD_FLOAT, ["1e12"])}, "finite_arrays"),
    ("result = sa.decide_at_rest({a}, {bound})", {"a": FL("0.5"), "bound": FL("1.0")}, "none"),
    ("o = sa.TimeSteppingOptions(step={step}, theta={theta}); s = sa.make_time_stepping_state({profile}); "
     "s.{attr} = {value}; sa.advance_time_stepping({profile}, {friction}, o, s, {steps}); result = s.object",
     {"step": (["1e-3"], BAD_FLOAT, ["5e-324"]), "theta": FL("0.5"), "profile": PROFILES,
      "friction": FRICTIONS, "attr": (["step_index", "t0", "table_velocity", "stick"], [], []),
      "value": (["0", "1.0"], BAD_FLOAT + BAD_INT, []),
      "steps": IN("10", "100", big=["10**12", "2**62"])}, "object_state"),
    ("result = sa.steady_state({profile}, sa.SteadyStateOptions(max_periods={max_periods}, "
     "velocity_tol={tol}, steps_per_period={spp}, theta={theta}, stepping_tol={stol}))",
     {"profile": (["P", "Q"], ["None", "F", "1"], []), "max_periods": IN("200", "20"),
      "tol": FL("1e-13"), "spp": IN("4000", "100"), "theta": FL("0.5"), "stol": FL("0.0")}, "steady"),
    ("result = sa.objective_f({v}, {c})",
     {"v": (["0.05", "np.array([0.0, 0.1])"], BAD_FLOAT + BAD_ARRAY, []), "c": FL("10000.0")},
     "finite_or_inf_if_finite_inputs"),
    ("result = sa.make_monodromy({matrix}).multipliers",
     {"matrix": (["[[1.0, 0.0], [0.0, 0.5]]", "np.eye(2)"],
                 BAD_ARRAY + ["[[nan, 0], [0, 1]]", "[[1e308, 1e308], [1e308, 1e308]]", "np.eye(3)"], [])},
     "finite_if_finite_inputs"),
    ("result = sa.floquet_multipliers({profile}, sa.FloquetOptions(fd_step={h}))",
     {"profile": PROFILES, "h": FL("1e-7", "1e-5")}, "floquet"),
    ("result = sa.slip_slip_multiplier({a2}, {a3})",
     {"a2": (["2.3", "[2.0, 3.0]"], BAD_FLOAT + BAD_ARRAY, []), "a3": (["1.3", "[1.5, 2.5]"], BAD_FLOAT + BAD_ARRAY, [])},
     "finite_if_finite_inputs"),
    ("result = sa.velocity_convergence({profile}, sa.ConvergenceOptions(v1={v1}, v2={v2}, t0={t0}, "
     "duration={duration}, samples_per_period={spp}))",
     {"profile": PROFILES, "v1": FL("0.5"), "v2": FL("-0.5"), "t0": FL("0.0"),
      "duration": (["2.0"], BAD_FLOAT, ["1e12"]), "spp": IN("50", "1", big=["10**9"])}, "convergence"),
    ("result = sa.{grid}({lo}, {hi}, {n})",
     {"grid": (["linear_grid", "log_grid"], [], []), "lo": FL("0.1"), "hi": FL("3.0"),
      "n": IN("5", "1", big=["10**9", "2**31 - 1"])}, "finite_if_finite_inputs"),
    ("result = sa.sweep_accelerations({period}, {stroke}, {a2}, {a3}, threads={threads}, progress={progress})",
     {"period": FL("1.0"), "stroke": FL("0.084"), "a2": SMALL_A2, "a3": SMALL_A3, "threads": THREADS,
      "progress": PROGRESS}, "sweep"),
    ("result = sa.sweep_period({family}, {stroke}, {periods}, threads={threads}, progress={progress})",
     {"family": (["sa.ThreePhaseFamily(2.3, 1.3)", "sa.ScaledShapeFamily.paper_like()",
                  "sa.ScaledFourierFamily([0.04], [0.0])"],
                 ["sa.ThreePhaseFamily(nan, 1.3)", "sa.ScaledFourierFamily([], [])", "None", "P",
                  "sa.ScaledShapeFamily(Q)"], []),
      "stroke": FL("0.084"), "periods": PERIODS_GRID, "threads": THREADS, "progress": PROGRESS}, "sweep"),
    ("result = sa.sweep_stroke({family}, {period}, {strokes}, threads={threads})",
     {"family": (["sa.ThreePhaseFamily(2.3, 1.3)", "sa.ScaledShapeFamily.paper_like()"],
                 ["sa.ThreePhaseFamily(2.3, -1.0)", "None"], []),
      "period": FL("1.0"), "strokes": AR("[0.05, 0.084]"), "threads": THREADS}, "sweep"),
    ("result = {family}.make({period}, {stroke})",
     {"family": (["sa.ThreePhaseFamily(2.3, 1.3)", "sa.ScaledShapeFamily.paper_like()",
                  "sa.ScaledFourierFamily([0.04], [0.0])"], ["sa.ThreePhaseFamily(0.0, 1.3)"], []),
      "period": FL("1.0"), "stroke": FL("0.084")}, "none"),
    ("result = (sa.sticks_permanently({friction}, {peak}, {x}), sa.stick_position_min({table}, {peak}))",
     {"friction": TWO_REGION, "table": TABLE, "peak": FL("2.3"), "x": (["0.6", "[0.5, 0.6]"], BAD_FLOAT + BAD_ARRAY, [])},
     "finite_or_inf_if_finite_inputs"),
    ("m = sa.StickPositionMap({profile}, {table}); result = (m({x}), m.fixed_point(), "
     "m.slope_at_fixed_point(), m.basin_lower_bound(), m.accumulates_for_every_entry(), "
     "m.proves_accumulation_from({x1}), m.slip_duration({x}))",
     {"profile": TPROFILES, "table": TABLE,
      "x": (["0.52", "np.linspace(0.5, 0.55, 4)"], BAD_FLOAT + BAD_ARRAY, []), "x1": FL("0.52")},
     "finite_if_finite_inputs"),
    ("result = sa.stopping_run({profile}, {friction}, sa.ObjectState({t0}, {x0}, {v0}), "
     "sa.StoppingOptions(max_periods={max_periods}, fractions={fractions}))",
     {"profile": PROFILES, "friction": TWO_REGION, "t0": FL("0.0"), "x0": FL("0.0", "0.45"),
      "v0": FL("0.0"), "max_periods": IN("200", "20"),
      "fractions": AR("[0.99, 0.999]", "[0.5]")}, "stopping"),
    ("result = sa.stopping_run({profile}, {friction}, sa.ObjectState(), "
     "sa.StoppingOptions(max_periods={max_periods}, method={method}, steps_per_period={spp}))",
     {"profile": PROFILES, "friction": TWO_REGION, "max_periods": IN("50", "5"),
      "method": (["None", "'time-stepping'", "'exact'"], ["'x'", "5", "sa.Method(-1)"], []),
      "spp": IN("200", "50", big=["10**9"])}, "stopping"),
    ("m = sa.PeriodStickPositionMap({profile}, {friction}); result = m({x})",
     {"profile": PROFILES, "friction": FRICTIONS,
      "x": (["0.52", "np.linspace(0.5, 0.55, 4)"], BAD_FLOAT + BAD_ARRAY, [])}, "none"),
    ("result = sa.positioning_accuracy({profile}, {width}, {c_mu}, sa.PositioningOptions(entries={entries}, "
     "stopping=sa.StoppingOptions(max_periods={max_periods}), stop_at_first_failure={first}))",
     {"profile": PROFILES, "width": FL("0.05"), "c_mu": FL("2.5"), "entries": IN("3", "1", big=["10**9"]),
      "max_periods": IN("200"), "first": BOOL}, "positioning"),
    ("result = sa.positioning_surfaces({period}, {stroke}, {width}, {c_mu}, {a2}, {a3}, "
     "options=sa.PositioningOptions(entries={entries}, stopping=sa.StoppingOptions(max_periods=100)), "
     "threads={threads}, progress={progress})",
     {"period": FL("1.0"), "stroke": FL("0.084"), "width": FL("0.05"), "c_mu": FL("2.5"),
      "a2": AR("[2.3]", "[1.5, 2.5]"), "a3": AR("[1.3]"), "entries": IN("3", big=["10**9"]),
      "threads": THREADS, "progress": PROGRESS}, "positioning_surfaces"),
    ("r = sa.DesignRequest(); r.acceleration_grid = 4; r.period_grid = 2; r.stroke_grid = 1; r.entries = 3; "
     "r.{attr} = {value}; result = sa.design_process(r, threads={threads}, progress={progress})",
     {"attr": (["width", "mu", "c_mu", "gravity", "distance", "stroke_max", "frequency_min", "frequency_max",
                "velocity_max", "acceleration_max", "tolerance", "mass", "mu_static",
                "mu_backward"], [], []),
      "value": FL("0.01", "0.3"), "threads": THREADS, "progress": PROGRESS}, "design"),
    ("r = sa.DesignRequest(); r.acceleration_grid = 4; r.period_grid = 2; r.stroke_grid = 1; r.entries = 3; "
     "r.{attr} = {value}; result = sa.design_process(r)",
     {"attr": (["acceleration_grid", "period_grid", "stroke_grid", "entries"], [], []),
      "value": IN("2", "3", big=["10**9"])}, "design"),
    ("result = sa.{optimizer}(sa.ActuatorLimits(period={period}, stroke={stroke}, max_velocity={vmax}, "
     "max_acceleration={amax}), sa.OptimizeOptions(order={order}, segments={segments}, starts={starts}, "
     "max_evaluations={evals}, seed={seed}, grid=8))",
     {"optimizer": (["optimize_three_phase", "optimize_piecewise_constant", "optimize_fourier"], [], []),
      "period": FL("0.072"), "stroke": FL("0.021"), "vmax": FL("3.2"), "amax": FL("1275.0"),
      # order 100 is the valid maximum and an optimisation at it takes ~10 s: long work, not
      # misuse, so it is left out of the "bad" pool here (101 and beyond are refused at once).
      "order": (["3", "1"], [v for v in BAD_INT if v != "100"] + ["101"], ["10**9", "2**31 - 1"]),
      "segments": IN("3", "2", big=["10**9"]),
      "starts": IN("1"), "evals": IN("30"), "seed": IN("1", "0")}, "optimization"),
    ("result = sa.rebuild_profile(sa.compare_families(sa.ActuatorLimits(stroke={stroke}), "
     "sa.OptimizeOptions(order=2, segments=2, starts=1, max_evaluations=20, grid=8))[{k}])",
     {"stroke": FL("0.021", "0.084"), "k": (["0", "1", "2"], [], [])}, "none"),
    ("result = {enum}({value})",
     {"enum": (["sa.Method", "sa.Interpolation", "sa.StopKind", "sa.StickSlipCase", "sa.describe",
                "sa.ArcKind", "sa.ArcEnd"], [], []),
      "value": (["0", "1"], ["5", "-1", "2**40", "'x'", "''", "None", "1.5", "'exact'", "'linear'"], [])},
     "none"),
    ("result = sa.simulate(P, F, options=sa.SimulationOptions(method=sa.Method({value}), duration=1.0))",
     {"value": (["0", "1"], ["2", "5", "-1", "255"], [])}, "simulation"),
    ("result = sa.make_sampled_profile(sa.AccelerationSamples([0.0, 0.5, 1.0], [1.0, -1.0, 0.0]), "
     "sa.Interpolation({value})).sample(0.3)",
     {"value": (["0", "1"], ["2", "7", "-1"], [])}, "finite_if_finite_inputs"),
    ("o = sa.SimulationOptions(); o.{attr} = {value}; result = sa.simulate(P, F, options=o)",
     {"attr": (["duration", "step", "theta", "output_step"], [], []), "value": FL("1.0")}, "simulation"),
    ("o = sa.SteadyStateOptions(); o.{attr} = {value}; result = sa.steady_state(Q, o)",
     {"attr": (["max_periods", "steps_per_period"], [], []), "value": IN("50")}, "steady"),
    ("o = sa.OptimizeOptions(starts=1, max_evaluations=20, grid=8); o.{attr} = {value}; "
     "result = sa.optimize_piecewise_constant(sa.ActuatorLimits(), o)",
     {"attr": (["order", "segments"], [], []), "value": IN("2", big=["10**9"])}, "optimization"),
    ("s = sa.steady_state(P); s.v_bar = {value}; result = s.v_bar",
     {"value": (["1.0"], [], [])}, "readonly"),
    # planar motion (issue 13)
    ("result = sa.polar_moment(sa.disc_patch({radius}, {rings}, {sectors}))",
     {"radius": FL("0.2"), "rings": IN("3", big=["10**5"]), "sectors": IN("6", big=["10**5"])},
     "finite_if_finite_inputs"),
    ("result = sa.polar_moment(sa.polygon_patch({xs}, {ys}, {subdivisions}))",
     {"xs": AR("[0.0, 1.0, 1.0, 0.0]", "[0.0, 2.0, 1.0]"), "ys": AR("[0.0, 0.0, 1.0, 1.0]", "[0.0, 0.0, 1.0]"),
      "subdivisions": IN("1", "3", big=["10**6"])}, "none"),
    ("result = sa.weighted_points_patch({xs}, {ys}, {loads})",
     {"xs": AR("[-0.1, 0.1]"), "ys": AR("[0.0, 0.0]"), "loads": AR("[0.5, 0.5]")}, "none"),
    ("result = sa.planar_level(sa.GridField(dx={dx}, dy=0.5, nx=2, ny=2, levels={levels}), {x}, 0.2)",
     {"dx": FL("0.5"), "levels": AR("[1.0, 2.0, 1.0, 2.0]"), "x": FL("0.3")}, "finite_if_finite_inputs"),
    ("result = sa.simulate_planar(P, R, field=sa.CircularPocketField(centre_x=0.3, radius={radius}, "
     "width={width}, c_mu={c_mu}), part=sa.RigidPart({inertia}, sa.rectangle_patch(0.2, 0.1, 2, 2)), "
     "step={step}, periods={periods})",
     {"radius": FL("0.2"), "width": FL("0.05"), "c_mu": FL("2.5"), "inertia": FL("0.01"),
      "step": FL("0.01"), "periods": IN("2", big=["10**9"])}, "none"),
    ("result = sa.planar_stop(P, field=sa.StripField(origin_x=0.4, half_width={half_width}), "
     "part=sa.RigidPart(0.01, sa.disc_patch(0.1, 2, 4)), step={step}, entries={entries}, "
     "max_periods={max_periods})",
     {"half_width": FL("0.3"), "step": FL("0.02"), "entries": AR("[[0.0, 0.0, 0.0]]"),
      "max_periods": IN("20", big=["10**9"])}, "none"),
]

# ---- every class, every protocol, every binding (issue 20: D33, D37, D38) ----------------------


def _bound_class_names():
    """Every pybind11 class the extension exports (enums included), discovered from it."""
    import selfalign._selfalign as ext
    base = ext.Scales.__mro__[-2]  # pybind11's common base
    return sorted(n for n, v in vars(ext).items() if isinstance(v, type) and issubclass(v, base))


CLASS_NAMES = _bound_class_names()
# Instances to pickle: value types, enums, and classes that are not values (they must refuse).
PICKLED = ["P", "Q", "R", "F", "U", "sa.PeriodMap(P)", "sa.StickPositionMap(P, F)",
           "sa.Method.exact", "sa.StopKind.accumulation", "sa.Interpolation.linear",
           "sa.StickSlipCase.slip_slip", "sa.ObjectState(0.1, 0.2, 0.3)", "sa.Scales(1e-3, 0.3)",
           "sa.SimulationOptions()", "sa.SteadyStateOptions()", "sa.DesignRequest()",
           "sa.ProcessUncertainty(mu=0.3)", "sa.Normal(0.3, 0.01)", "sa.RigidPart()",
           "sa.StripField()", "sa.FrictionLaw(1.2, 1.0, 0.9)", "sa.steady_state(P)",
           "sa.ThreePhaseFamily(2.3, 1.3)", "sa.PlanarPose(0.1, 0.2, 0.3)",
           "sa.simulate(P, F, options=sa.SimulationOptions(duration=1.0))"]
CATALOGUE += [
    # The parameter view (docs/parameters.md): configs as dicts of config keys, values by name.
    ("result = sa.model_parameters({{'units': {units}, 'mu': {mu}, 'friction': {friction}, "
     "'a2': {a2}}})",
     {"units": (["'si'", "'dimensionless'"], ["'imperial'", "None", "1"], []), "mu": FL("0.3"),
      "friction": (["'two-region'", "'uniform'"], ["'field'", "'x'", "None"], []),
      "a2": FL("2.3")}, "parameters"),
    ("result = sa.with_parameters({{'profile': 'quadratic-sequence', 'durations': [0.5, 0.5], "
     "'accelerations': [1.0, -1.0]}}, {{{name}: {value}}})",
     {"name": (["'accelerations[1]'", "'time_scale'", "'amplitude_scale'", "'mu_static'"],
               ["'accelerations[2]'", "'accelerations'", "'step'", "'c_mu'", "None", "1", "''"],
               []),
      "value": FL("0.4", "2.0")}, "none"),
    # D33: an object made by cls.__new__ alone, used in every way: a TypeError each time it is read
    ("o = sa.{cls}.__new__(sa.{cls}); result = {use}",
     {"cls": (CLASS_NAMES, [], []),
      "use": (["repr(o)", "o == o", "pickle.dumps(o, protocol=0)", "pickle.dumps(o, protocol=1)",
               "pickle.dumps(o)", "copy.deepcopy(o)",
               # to_dict where the class has one (the abstract bases have none: AttributeError)
               "o.to_dict() if hasattr(type(o), 'to_dict') else repr(o)",
               "[getattr(o, a) for a in dir(o) if not a.startswith('_')]", "sa.simulate(o, F)",
               "sa.steady_state(o)", "sa.PeriodMap(o)", "sa.stopping_run(P, o)",
               "sa.ProcessUncertainty(mu=o)", "sa.design_process(o)", "sa.monte_carlo(o, o, o)",
               "sa.merge_monte_carlo([o])", "sa.planar_stop(o, field=o, part=o, step=0.01, "
               "entries=[[0.0, 0.0, 0.0]], max_periods=2)"], [], [])},
     "none"),
    # D37: pickled under protocols 0 .. 5: a value type round-trips, any other class refuses
    ("x = {obj}; result = (x, pickle.loads(pickle.dumps(x, protocol={protocol})))",
     {"obj": (PICKLED, [], []), "protocol": (["0", "1", "2", "3", "4", "5"], [], [])},
     "round_trip"),
]

# D38: every parameter of every function and constructor given an object of a foreign type
# (Wrong()), the other required parameters valid: the call must raise TypeError (or
# InvalidParameter) naming that parameter, or pybind11's list of the accepted signatures.
VALID_BY_TYPE = {
    "float": "1.0", "int": "2", "bool": "True", "str": "'x'",
    "Callable[[int, int], None]": "None", "StickSlipCase": "sa.StickSlipCase.slip_slip",
    "List[selfalign._selfalign.MonteCarloResult]": "[sa.monte_carlo(sa.DesignRequest(tolerance=1e-3), "
        "sa.Process(period=0.05, stroke=0.002, a2=20.0, a3=10.0, x_mu=0.01), "
        "sa.ProcessUncertainty(mu='normal:0.3,1%'), runs=2, max_periods=20)]",
    "List[selfalign._selfalign.ContactPoint]": "[sa.ContactPoint(0.0, 0.0, 1.0)]",
    "Union[selfalign._selfalign.UniformPlanarField, selfalign._selfalign.HalfPlaneStepField, "
    "selfalign._selfalign.StripField, selfalign._selfalign.RectangularPocketField, "
    "selfalign._selfalign.CircularPocketField, selfalign._selfalign.GridField, "
    "selfalign._selfalign.AxisField]":
        "sa.UniformPlanarField()",
}
VALID_BY_CLASS = {  # classes without a default constructor, or an example that is cheap
    "TableProfile": "P", "ThreePhaseProfile": "P", "FourierProfile": "R",
    "PiecewisePolynomialProfile": "Q", "FrictionMap": "F", "TwoRegionTable": "F.two_region",
    "AccelerationSamples": "sa.AccelerationSamples([0.0, 0.5, 1.0], [1.0, -1.0, 0.0])",
    "ExactState": "sa.make_exact_state(P, F)", "TimeSteppingState": "sa.make_time_stepping_state(P)",
    "PeriodMap": "sa.PeriodMap(P)", "ProfileFamily": "sa.ThreePhaseFamily(2.3, 1.3)",
    "ThreePhaseParameters": "P.parameters", "ThreePhaseFamily": "sa.ThreePhaseFamily(2.3, 1.3)",
    "Interpolation": "sa.Interpolation.linear", "Method": "sa.Method.exact",
    "StopKind": "sa.StopKind.accumulation", "FrictionField": "sa.FrictionField([0.5], [1.0], [2.0])",
    "DesignRequest": "sa.DesignRequest(acceleration_grid=4, period_grid=2, stroke_grid=1, entries=3)",
    "DesignResult": "sa.design_process(sa.DesignRequest(acceleration_grid=4, period_grid=2, "
                    "stroke_grid=1, entries=3))",
    "Process": "sa.Process(period=0.05, stroke=0.002, a2=20.0, a3=10.0, x_mu=0.01)",
    "JerkLimitedThreePhaseParameters": "sa.JerkLimitedThreePhaseParameters(1.0, 0.084, 3.0, 0.9, 50.0)",
    "OptimizationResult": "sa.optimize_three_phase(sa.ActuatorLimits(), "
                          "sa.OptimizeOptions(grid=6, polish=1, starts=1))",
}
VALID_OBJECT_BY_NAME = {  # parameters typed `object`, by name
    "x": "0.5", "value": "1.0", "t": "[0.0, 0.5, 1.0]", "a2": "[2.3]", "a3": "[1.3]", "periods": "[1.0]",
    "strokes": "[0.084]", "matrix": "np.eye(2)", "xs": "[0.0, 1.0, 1.0, 0.0]",
    "ys": "[0.0, 0.0, 1.0, 1.0]", "loads": "[0.5, 0.5]", "entries": "[[0.0, 0.0, 0.0]]",
    "v": "0.1", "a": "0.5", "bound": "1.0", "values": "[1.0, 2.0]", "durations": "[0.5, 0.5]",
    "accelerations": "[1.0, -1.0]", "accels": "[1.0, -1.0]", "ydd": "[1.0, -1.0, 0.0]",
    "cos": "[0.04]", "sin": "[0.0]", "path": "'/dev/null'", "cos_coeffs": "[0.04]",
    "sin_coeffs": "[0.0]", "footprint": "sa.PointFootprint()", "left": "[1.0]",
    "position": "[0.5]", "right": "[2.0]", "v_bar": "0.1", "y": "0.2",
    "queue": "[sa.RowPart()]", "parts": "[sa.RowPart()]",
}


def _split_top_level(text):
    """text split at the commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _signatures(obj):
    """[(name, type, has_default, keyword_only)] per overload, from pybind11's docstring."""
    doc = (obj.__init__ if isinstance(obj, type) else obj).__doc__ or ""
    out = []
    for line in doc.splitlines():
        m = re.match(r"^(?:\d+\. )?(\w+)\((.*)\) -> ", line)
        if not m:
            continue
        params, keyword_only = [], False
        for part in _split_top_level(m.group(2)):
            if part == "*":
                keyword_only = True
                continue
            pm = re.match(r"^(\w+): (.*?)(?: = (.*))?$", part)
            if not pm or pm.group(1) == "self":
                continue
            params.append((pm.group(1), pm.group(2), pm.group(3) is not None, keyword_only))
        out.append(params)
    return out


def _valid(name, type_):
    if type_ == "object":
        return VALID_OBJECT_BY_NAME.get(name)
    if type_ in VALID_BY_TYPE:
        return VALID_BY_TYPE[type_]
    m = re.match(r"^selfalign\._selfalign\.(\w+)$", type_)
    if not m:
        return None
    cls = m.group(1)
    return VALID_BY_CLASS.get(cls, f"sa.{cls}()")


_WRONG_TYPE_CALLS = None


def wrong_type_calls():
    """(code, validator) for each parameter of each function and constructor that can be
    called with every other required parameter valid."""
    global _WRONG_TYPE_CALLS
    if _WRONG_TYPE_CALLS is None:
        import selfalign._selfalign as ext
        calls = []
        for callee, obj in sorted(vars(ext).items()):
            if callee.startswith("_") or not callable(obj) or (
                    isinstance(obj, type) and (issubclass(obj, BaseException) or callee not in CLASS_NAMES)):
                continue
            for params in _signatures(obj):
                for k, (name, _, _, _) in enumerate(params):
                    positional, keywords, ok = [], [], True
                    for j, (other, other_type, has_default, keyword_only) in enumerate(params):
                        unnamed = re.match(r"^arg\d+$", other) is not None
                        if j == k:
                            value = "Wrong()"
                        elif has_default:
                            if unnamed and j < k:
                                ok = False  # an unnamed parameter after it needs its place
                            continue
                        else:
                            value = _valid(other, other_type)
                            ok = ok and value is not None
                        # by keyword once the parameter under test went by keyword (the
                        # positions after it would shift)
                        if keyword_only or (not unnamed and (j == k or (j > k and keywords))):
                            keywords.append(f"{other}={value}")
                        elif keywords:
                            ok = False
                        else:
                            positional.append(value)
                    if ok:
                        calls.append((f"result = sa.{callee}({', '.join(positional + keywords)})",
                                      f"wrong_type:{name}"))
        _WRONG_TYPE_CALLS = sorted(set(calls))
    return _WRONG_TYPE_CALLS


# Calls 0 .. len(CORPUS)-1: fixed, one per known defect class of the module (see
# ../shared/repro/D02, D03, D11, D13) and per contract item; random calls follow.
CORPUS = [
    ("result = sa.sweep_accelerations(1.0, 0.084, [2.0], [1.5], threads=10**9)", "sweep"),
    ("s = sa.make_exact_state(P, F); s.segment = 3; result = (sa.advance_exact(P, F, s, 2.0), s.object)",
     "exact_state"),
    ("s = sa.make_exact_state(P, F); s.segment = -1; result = (sa.advance_exact(P, F, s, 2.0), s.object)",
     "exact_state"),
    ("s = sa.make_exact_state(Q, F); s.period_index = 2**62; result = (sa.advance_exact(Q, F, s, 2.0), s.object)",
     "exact_state"),
    ("result = sa.simulate(P, F, options=sa.SimulationOptions(duration=1e308))", "simulation"),
    ("result = sa.optimize_fourier(sa.ActuatorLimits(), sa.OptimizeOptions(order=10**9, starts=1))", "optimization"),
    ("result = sa.objective_f(2**2000)", "finite_or_inf_if_finite_inputs"),
    ("result = sa.linear_grid(1e308, 1.0, 3)", "finite_if_finite_inputs"),
    ("result = sa.FourierProfile(1e-320, [0.04], [0.0]).stroke", "finite_if_finite_inputs"),
    ("result = sa.linear_grid(0.0, 1.0, 10**9)", "finite_if_finite_inputs"),
    ("result = sa.simulate(P, F, options=sa.SimulationOptions(method=sa.Method(5), duration=1.0))", "simulation"),
    ("result = sa.make_sampled_profile(sa.AccelerationSamples([0.0, 0.5, 1.0], [1.0, -1.0, 0.0]), "
     "sa.Interpolation(7)).sample(0.3)", "finite_if_finite_inputs"),
    ("result = sa.two_region_friction(0.5, -1.0, 2.5)", "none"),
    ("result = sa.two_region_friction('a', 1, 2)", "none"),
    ("result = sa.sweep_accelerations(1.0, 0.084, [2.0, 3.0], [1.5], progress=lambda done, total: 1 / 0)", "sweep"),
    ("result = sa.velocity_convergence(P, sa.ConvergenceOptions(v2=-1e308, duration=2.0))", "convergence"),
    ("result = sa.floquet_multipliers(P, sa.FloquetOptions(fd_step=1e308))", "floquet"),
    ("result = sa.read_acceleration_samples('x' * 5000)", "none"),
    ("result = sa.slip_slip_multiplier(-1.0, 1.0)", "finite_if_finite_inputs"),
    ("result = sa.positioning_accuracy(P, 0.05, 3e16, sa.PositioningOptions(entries=1))", "positioning"),
]

# ---- the worker: runs calls, one JSON line per START and per outcome --------------------------


def corpus():
    """The fixed calls: CORPUS, then every binding with a wrong-typed argument (D38)."""
    return CORPUS + wrong_type_calls()


def total_calls():
    """The fixed calls and CALLS random ones."""
    return len(corpus()) + CALLS


def make_call(index, seed):
    """Deterministic: (code, parameters, validator, big)."""
    if index < len(corpus()):
        code, validator = corpus()[index]
        return code, [], validator, False
    # the random calls keep their numbers from before the fixed wrong-type calls were added
    rng = random.Random(f"api:{seed}:{index - len(wrong_type_calls())}")
    template, params, validator = CATALOGUE[rng.randrange(len(CATALOGUE))]
    values, big = {}, False
    names = list(params)
    n_bad = rng.choice([0, 1, 1, 1, 2])
    bad = set(rng.sample(names, min(n_bad, len(names))))
    for name in names:
        valid, bad_pool, big_pool = params[name]
        if name in bad and (bad_pool or big_pool):
            if big_pool and rng.random() < 0.25:
                values[name] = rng.choice(big_pool)
                big = True
            else:
                values[name] = rng.choice(bad_pool or valid)
        else:
            values[name] = rng.choice(valid)
    return template.format(**values), names, validator, big


def has_nonfinite_input(code):
    return bool(re.search(r"\bnan\b|\binf\b|1e308|2\*\*2000|'nan'|1e-300|5e-324", code))


def nan_in(x):
    import numpy as np
    if x is None or isinstance(x, (bool, str)):
        return False
    if isinstance(x, float):
        return math.isnan(x)
    if isinstance(x, (int,)):
        return False
    if isinstance(x, complex):
        return math.isnan(x.real) or math.isnan(x.imag)
    if isinstance(x, np.ndarray):
        return x.dtype.kind in "fc" and bool(np.isnan(x).any())
    if isinstance(x, np.generic):
        return bool(np.isnan(x)) if x.dtype.kind in "fc" else False
    if isinstance(x, (list, tuple)):
        return any(nan_in(v) for v in x)
    if isinstance(x, dict):
        return any(nan_in(v) for v in x.values())
    return False


def nonfinite_in(x):
    import numpy as np
    if isinstance(x, float):
        return not math.isfinite(x)
    if isinstance(x, np.ndarray):
        return x.dtype.kind in "fc" and not bool(np.isfinite(x).all())
    if isinstance(x, (list, tuple)):
        return any(nonfinite_in(v) for v in x)
    if isinstance(x, dict):
        return any(nonfinite_in(v) for v in x.values())
    return False


def validate(result, validator, code):
    """Returns a failure description or None. Each allowance cites the docstring it rests on."""
    import numpy as np
    import selfalign as sa
    clean = not has_nonfinite_input(code)
    if validator in ("none", "readonly"):
        return None
    if validator.startswith("wrong_type:"):
        return f"accepted Wrong() for {validator.split(':')[1]}"
    if validator == "parameters":
        # model_parameters: "NaN when absent (no Stribeck decay)"
        bad = [p.name for p in result if p.name != "stribeck_velocity" and not math.isfinite(p.value)]
        return f"non-finite parameters {bad}" if clean and bad else None
    if validator == "round_trip":
        before, after = result
        return None if type(after) is type(before) and after == before else f"unpickled as {after!r}"
    if validator.startswith("finite") and clean and "None" in code and nan_in(result):
        return "None argument taken as NaN"
    if validator == "finite_if_finite_inputs":
        if clean and nan_in(result):
            return "NaN result from non-NaN inputs"
        return None
    if validator == "finite_or_inf_if_finite_inputs":
        # objective_f: "+inf where v̄ = 0"; stick_position_min: "+inf when it exceeds c_mu"
        if clean and nan_in(result):
            return "NaN result from non-NaN inputs"
        return None
    if validator == "solution":
        if result.physical and nan_in([result.t1, result.t2, result.t3, result.y_ini, result.yd_ini]):
            return "physical ThreePhaseSolution with NaN"
        return None
    if validator == "simulation":
        tr = result.trajectory
        bad = [k for k in ("t", "x", "xd", "y", "yd", "ydd") if nan_in(getattr(tr, k))]
        fs = result.final_state
        if nan_in([fs.t, fs.x, fs.xd]):
            bad.append("final_state")
        # mean_velocity_last_period: "NaN if the run is shorter than a period" (docstring)
        if nan_in(result.stick_fraction) and len(tr) > 0:
            bad.append("stick_fraction")
        return f"NaN in {bad}" if bad else None
    if validator == "exact_state":
        n, obj = result[0], result[1]
        return "NaN object state" if clean and nan_in([obj.t, obj.x, obj.xd]) else None
    if validator == "object_state":
        return "NaN object state" if clean and nan_in([result.t, result.x, result.xd]) else None
    if validator == "finite_arrays":
        return "NaN in arrays" if nan_in(result) else None
    if validator == "steady":
        # SteadyState.f: "+inf when v̄ = 0" (docstring): inf allowed there only
        vals = [result.v_bar, result.x_dot_0s, result.phase, result.displacement, result.f]
        if nan_in(vals):
            return f"NaN in steady state {vals}"
        if math.isinf(result.f) and result.v_bar != 0:
            return f"f = inf with v_bar = {result.v_bar}"
        return None
    if validator == "floquet":
        bad = [m for m in ("analytic", "saltation", "finite_difference")
               if getattr(result, m).available and (nan_in(getattr(result, m).matrix)
                                                    or nan_in(getattr(result, m).multipliers))]
        if nan_in(result.spread):
            bad.append("spread")
        return f"NaN in {bad}" if bad else None
    if validator == "convergence":
        # t_coincide: "None if not reached" (docstring); the arrays are numbers
        bad = [k for k in ("t", "v1", "v2", "lyapunov") if nonfinite_in(getattr(result, k))]
        return f"non-finite in {bad}" if bad else None
    if validator == "sweep":
        # sweep_accelerations / sweep_period docstrings: v_bar, f, x_dot_0s NaN for case 0 / where the
        # family has no member / where the cell could not be computed (failure != '').
        case = result.get("observed")
        failure = result.get("failure")
        physical = result.get("physical")
        for k in ("v_bar", "f", "x_dot_0s"):
            if k not in result:
                continue
            arr = np.asarray(result[k], dtype=float)
            allowed = np.zeros(arr.shape, dtype=bool)
            for extra in (None if case is None else np.asarray(case) == 0,
                          None if physical is None else ~np.asarray(physical, dtype=bool),
                          None if failure is None else np.asarray(failure) != ""):
                if extra is not None and extra.shape == arr.shape:
                    allowed |= extra
            if bool((np.isnan(arr) & ~allowed).any()):
                return f"NaN in '{k}' of a physical, computed cell"
        return None
    if validator == "stopping":
        # entry_time "NaN if never", time_to_fraction "NaN if not reached", process_time "+inf for
        # accumulation" (docstrings); end_position is a number unless the run did not stop.
        if nan_in(result.stick_positions):
            return "NaN stick position"
        if result.kind != sa.StopKind.not_stopped and nan_in(result.end_position):
            return f"NaN end_position for {result.kind}"
        if result.kind == sa.StopKind.permanent_stick and nan_in(result.process_time):
            return "NaN process_time for permanent stick"
        return None
    if validator == "positioning":
        if not result.reaches:
            return None   # "False when v̄ <= 0: the object never walks into the region"
        s = result.steady
        if nan_in([s.v_bar, s.x_dot_0s, result.x_mu]):
            return "NaN in steady state / x_mu"
        if result.all_stopped and nan_in([result.dx_d, result.x_d, result.overshoot_min, result.overshoot_max]):
            return "every entry stopped but dx_d / x_d / overshoot is NaN"
        stopped = [r.kind != sa.StopKind.not_stopped for r in result.runs]
        ends = np.asarray(result.end_positions, dtype=float)
        if len(stopped) == len(ends) and bool((np.isnan(ends) & np.asarray(stopped, dtype=bool)).any()):
            return "NaN end position for an entry that stopped"
        return None
    if validator == "positioning_surfaces":
        # docstring: 'dx_d' NaN where the object does not come to rest; f: NaN for case 0 (as the CLI)
        f = np.asarray(result["f"], dtype=float)
        if bool((np.isnan(f) & (np.asarray(result["case"]) != 0)).any()):
            return "NaN f in a physical cell"
        return None
    if validator == "design":
        if not result.feasible:
            return None   # "message: why not, naming the binding limit": no design, no numbers
        vals = [result.period, result.stroke, result.a2, result.a3, result.v_bar, result.x_mu,
                result.end_position, result.error_band]
        return f"feasible design with NaN {vals}" if nan_in(vals) else None
    if validator == "optimization":
        if result.feasible and nan_in([result.f, result.v_bar, result.parameters]):
            return "feasible optimum with NaN"
        return None
    return None


_API_NAMES = None


def api_parameter_names():
    """Every parameter name in the module's signatures (docstrings' first lines)."""
    global _API_NAMES
    if _API_NAMES is None:
        import selfalign as sa
        names = set()
        for obj in vars(sa).values():
            members = [a for a in dir(obj) if not a.startswith("__") or a == "__init__"] \
                if isinstance(obj, type) else []
            for o in [obj] + [getattr(obj, a, None) for a in members]:
                doc = getattr(o, "__doc__", None) or ""
                names |= set(re.findall(r"[(,]\s*\*?\s*([a-z_][a-z0-9_]*)\s*:", doc))
        names = {n for n in names if len(n) > 1} - {"self", "arg0", "arg1", "value", "str", "result"}
        _API_NAMES = names
    return _API_NAMES


def message_problem(exc, names, code):
    kind = type(exc).__name__
    msg = str(exc)
    callback_raise = RAISING_CALLBACK in code
    if kind == "ZeroDivisionError" and callback_raise:
        return None   # the user's own callback raised: propagating it is right
    if kind == "AttributeError" and re.search(r"\b[a-z]\.[a-z_]+ = ", code) and \
            re.search(r"has no setter|can't set attribute|read-only|not writable", msg):
        return None   # assigning a read-only property: Python's own answer
    if kind not in ALLOWED_TYPES:
        return f"exception type {kind}"
    for marker in INTERNALS:
        if marker in msg:
            return f"internals {marker!r} in message"
    pybind_signature = kind == "TypeError" and "incompatible" in msg and "arguments" in msg
    if "\n" in msg.strip() and not pybind_signature:
        return "multi-line message"
    if len(msg) > MAX_MESSAGE and not pybind_signature:
        return f"message of {len(msg)} characters"
    if kind == "InvalidParameter":
        if not exc.name or not msg.startswith(f"invalid {exc.name} = "):
            return f"InvalidParameter without its name (name={exc.name!r})"
        return None
    if pybind_signature:
        return None   # pybind11 lists the signature: every parameter by name and type
    words = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", msg))
    known = set(names) | set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", code)) | api_parameter_names()
    if not (words & known) and not callback_raise:
        return "message names no parameter"
    return None


def wrong_type_problem(exc, parameter):
    """None if the refusal of a wrong-typed `parameter` names it (or pybind11 lists the
    accepted signatures, naming every parameter and its type)."""
    msg = str(exc)
    if type(exc).__name__ == "TypeError" and "incompatible" in msg and "arguments" in msg:
        return None
    if re.search(rf"\b{parameter}\b", msg):
        return None
    return f"the refusal does not name {parameter}"


def worker(seed, start, stop):
    import faulthandler
    import resource
    faulthandler.enable()
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    env = {}
    exec(PRELUDE, env)
    out = sys.stdout
    for i in range(start, stop):
        code, names, validator, big = make_call(i, seed)
        out.write(json.dumps({"i": i, "start": True}) + "\n")
        out.flush()
        ns = dict(env)
        problem = None
        t0 = time.monotonic()
        try:
            exec(code, ns)
            try:
                problem = validate(ns.get("result"), validator, code)
            except Exception as e:   # a result that cannot even be inspected
                problem = f"inspecting the result raised {type(e).__name__}: {str(e)[:120]}"
            outcome = "result"
        except BaseException as e:   # noqa: B036 (we classify every exception)
            if isinstance(e, KeyboardInterrupt):
                raise
            problem = message_problem(e, names, code)
            if problem is None and validator.startswith("wrong_type:"):
                problem = wrong_type_problem(e, validator.split(":")[1])
            outcome = f"{type(e).__name__}: {str(e)[:200]}"
        out.write(json.dumps({"i": i, "outcome": outcome, "problem": problem,
                              "seconds": round(time.monotonic() - t0, 3)}) + "\n")
        out.flush()


# ---- the parent ------------------------------------------------------------------------------


def run_calls(seed, count, timeout=CALL_TIMEOUT):
    """Runs calls 0..count-1 in worker processes; returns {index: (outcome, problem)}."""
    results = {}
    start = 0
    here = os.path.abspath(__file__)
    while start < count:
        # stderr to a file: a chatty worker must not block on a full pipe
        err_file = tempfile.TemporaryFile()
        proc = subprocess.Popen([sys.executable, "-X", "faulthandler", here, "--worker", str(seed),
                                 str(start), str(count)], stdout=subprocess.PIPE,
                                stderr=err_file, start_new_session=True)
        current, buf, heard = None, b"", False
        deadline = time.monotonic() + 60 + timeout   # import and the first call
        while True:
            ready, _, _ = select.select([proc.stdout], [], [], max(0.0, deadline - time.monotonic()))
            if not ready:   # the current call hangs
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
                if current is not None:
                    results[current] = ("hang", f"no return within {timeout:.0f} s")
                break
            chunk = os.read(proc.stdout.fileno(), 1 << 16)
            if not chunk:   # the worker ended
                proc.wait()
                break
            buf += chunk
            while b"\n" in buf:
                line, buf = buf.split(b"\n", 1)
                msg = json.loads(line)
                heard = True
                if msg.get("start"):
                    current = msg["i"]
                    deadline = time.monotonic() + timeout
                else:
                    results[msg["i"]] = (msg["outcome"], msg["problem"])
                    current = None
        err_file.seek(0, os.SEEK_END)
        err_file.seek(max(0, err_file.tell() - 65536))
        err = err_file.read().decode("utf-8", "replace")   # the tail: faulthandler's report
        err_file.close()
        proc.stdout.close()
        if not heard:
            raise RuntimeError(f"the fuzz worker ran no call (exit {proc.returncode}): {err[-800:]}")
        if current is not None and current not in results:
            rc = proc.returncode
            how = f"signal {signal.Signals(-rc).name}" if rc is not None and rc < 0 else f"exit {rc}"
            fault = next((ln for ln in err.splitlines() if "Fatal Python error" in ln), err.strip()[-200:])
            results[current] = ("crash", f"worker died ({how}): {fault}")
        nxt = max(results) + 1 if results else start + 1
        if current is not None:
            nxt = current + 1
        start = max(nxt, start + 1)
    return results


def reproducer(code):
    return f"{sys.executable} -X faulthandler -c {json.dumps(PRELUDE + '; ' + code)}"


def report(seed, results):
    failures = []
    for i in sorted(results):
        outcome, problem = results[i]
        if outcome in ("crash", "hang") or problem:
            code, _, _, big = make_call(i, seed)
            if outcome in ("crash", "hang"):
                failures.append((i, outcome, code, problem))
            else:
                failures.append((i, problem, code, outcome))
    return failures


def test_python_api_fuzz():
    t0 = time.monotonic()
    results = run_calls(SEED, total_calls())
    failures = report(SEED, results)
    kinds = {}
    for i, what, code, outcome in failures:
        kind = what.split(":")[0] if what in ("crash", "hang") else re.sub(r"[\d.e+-]{4,}", "N", what)[:60]
        kinds.setdefault(kind, []).append(i)
    lines = [f"Python API fuzz: seed {SEED}, {len(results)} calls in {time.monotonic() - t0:.1f} s, "
             f"{len(failures)} failing (SELFALIGN_FUZZ_SEED={SEED})"]
    for kind, idx in sorted(kinds.items(), key=lambda kv: -len(kv[1])):
        lines.append(f"  {len(idx):4d}  {kind}")
    for i, what, code, outcome in failures[:150]:
        lines.append(f"call {i}: {what}\n    outcome: {outcome[:240]}\n    reproduce: {reproducer(code)}")
    assert len(results) == total_calls(), f"{total_calls() - len(results)} calls never ran"
    assert not failures, "\n".join(lines)


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "--worker":
        worker(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]))
    else:
        n = int(sys.argv[1]) if len(sys.argv) > 1 else total_calls()
        res = run_calls(SEED, n)
        fails = report(SEED, res)
        for i, what, code, outcome in fails:
            print(f"call {i}: {what}\n    outcome: {outcome[:240]}\n    reproduce: {reproducer(code)}")
        print(f"{len(res)} calls, {len(fails)} failing")
