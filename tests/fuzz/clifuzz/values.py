"""The values a case draws from: valid and cheap values per flag, edge values per kind, big
requests, the base command line of each subcommand and samples CSV variants."""


# Valid, cheap values per flag ("sub:flag" overrides "flag").
VALID = {
    "period": ["1", "0.5", "2", "1.05"], "stroke": ["0.084", "0.05", "0.1", "0.02"],
    "a2": ["2.3", "3", "1.8", "0.9", "2.45", "2.2"], "a3": ["1.3", "0.9", "1.1", "2.5", "1.5"],
    "durations": ["0.3,0.4,0.3", "0.5,0.5"], "accelerations": ["0,-3,4", "1,-1"],
    "fourier-cos": ["0.04", "0.04,0.01", "0"], "fourier-sin": ["0", "0.02", "0.01,0.005"],
    "units": ["dimensionless", "si"], "method": ["exact", "time-stepping"],
    "profile": ["three-phase", "quadratic-sequence", "fourier", "samples"],
    "interpolation": ["constant", "linear"], "friction": ["two-region", "uniform"],
    "x-mu": ["0.5", "0.2", "0", "-0.1"], "width": ["0.05", "0.02", "0.1"],
    "c-mu": ["2.5", "1.5", "4"], "mu": ["0.3", "0.5"], "g": ["9.81", "1"],
    "length-scale": ["0.001", "0.01"], "mass": ["1", "0.2"], "t0": ["0", "0.25", "-1"],
    "x0": ["0", "0.45", "-0.2"], "v0": ["0", "0.02", "-0.1"], "periods": ["1", "2", "0.5", "3"],
    "step": ["1e-3", "1e-4", "2e-3"], "theta": ["0.5", "0", "1"],
    "output-step": ["0", "0.05", "0.01"], "fd-step": ["1e-7", "1e-5"],
    "v1": ["0.5", "0", "2"], "v2": ["-0.5", "0", "0.1"], "samples-per-period": ["20", "1", "50"],
    "fractions": ["0.99,0.999", "0.5", "0,1"], "max-periods": ["200", "50", "1"],
    "entries": ["3", "1", "5"], "x1": ["0.5", "0.52", "0.6"], "from": ["0.5", "0.45"],
    "to": ["0.55", "0.6"], "n": ["5", "1", "3"], "threads": ["1", "2", "0"],
    "a2-range": ["1:3:3", "0.5:2:2", "2.3:2.3:1", "0.1:3:3", "3:1:2"],
    "a3-range": ["0.5:2:2", "1:3:3", "1.3:1.3:1", "0.1:3:2"],
    "family": ["three-phase", "scaled-shape"],
    "sweep period:range": ["0.5:2:3", "1:1:1", "0.2:1:2"],
    "sweep stroke:range": ["0.01:0.1:3", "0.084:0.084:1", "0.001:0.2:2"],
    "sweep positioning:a2-range": ["1.5:2.5:2", "2.3:2.3:1", "0.5:3:2"],
    "sweep positioning:a3-range": ["1:1.5:2", "1.3:1.3:1"],
    "sweep positioning:max-periods": ["100", "20", "1"],
    "optimize:family": ["three-phase", "piecewise-constant", "fourier", "all"],
    "optimize:period": ["0.072", "1", "0.5"], "optimize:stroke": ["0.021", "0.084", "0.01"],
    "optimize:velocity-max": ["3.2", "10", "1"], "optimize:acceleration-max": ["1275", "100"],
    "order": ["3", "1", "2"], "segments": ["3", "2", "4"], "starts": ["1", "2"],
    "max-evaluations": ["40", "10", "1"], "seed": ["1", "0", "42"],
    "design:width": ["0.01", "0.005"], "design:mu": ["0.3", "0.5"], "design:c-mu": ["2.5", "3"],
    "design:g": ["9.81"], "design:mass": ["1", "0.5"], "distance": ["0.1", "0.05"],
    "stroke-max": ["0.002", "0.001"], "frequency-min": ["5", "10"],
    "frequency-max": ["50", "20"], "design:velocity-max": ["0.2", "0.5"],
    "design:acceleration-max": ["10", "20"], "tolerance": ["0", "1e-4"],
    "jerk": ["50", "20"], "times": ["0,0.5", "0,0.3,0.6"], "field-interpolation": ["steps", "linear"],
    "footprint": ["uniform", "point"], "mu-static": ["0.36", "0.3"], "mu-backward": ["0.25", "0.3"],
    "stribeck-velocity": ["0.1", "0.3"], "stribeck-exponent": ["1", "2"], "viscous": ["0.1", "0"],
    "relative-tolerance": ["1e-6", "1e-8"], "absolute-tolerance": ["1e-8", "1e-10"],
    "design:jerk-max": ["3000", "1000"], "optimize:jerk-max": ["1e5", "3e4"], "montecarlo:jerk": ["3000"],
    "acceleration-grid": ["4", "3", "2"], "period-grid": ["2", "1"], "stroke-grid": ["1", "2"],
    "design:entries": ["3", "2"], "sample-rate": ["2000", "100"],
}


# Values that ask for an unbounded amount of work or memory: they must be refused (or finish)
# within the short "big request" timeout. Only these cost flags get huge values.
BIG = {
    "periods": ["1e9", "1e12", "1e308", "inf", "1.7976931348623157e308"],
    "step": ["1e-12", "5e-324", "1e-300"],
    "output-step": ["1e-12", "5e-324", "1e-300"],
    "samples-per-period": ["1000000000", "4294967297", "2147483648"],
    "entries": ["1000000000", "4294967297"],
    "n": ["1000000000", "4294967297"],
    "threads": ["1000000000", "4294967295", "2147483647", "65536"],
    "order": ["1000000000", "2147483647"],
    "segments": ["1000000000", "2147483647"],
    "sample-rate": ["1e12", "1e300", "inf"],
    "a2-range": ["1:3:1000000000", "1:3:4294967297", "1:3:1e12"],
    "a3-range": ["1:3:1000000000"],
    "range": ["0.5:2:1000000000", "0.5:2:9223372036854775807"],
}
# Cost flags outside BIG: only small valid or invalid values (their huge values could be
# legitimately slow: millions of optimiser starts, stopping runs that never stop, ...).
NO_HUGE = {"max-periods", "starts", "max-evaluations", "acceleration-grid", "period-grid",
           "stroke-grid", "fd-step"}
COST = set(BIG) | NO_HUGE

LONG_GARBAGE = "9" * 3000
EDGE_NUMBERS = [
    "0", "-0", "-1", "-2.5", "1e-300", "5e-324", "4.9e-324", "2.2250738585072014e-308", "1e-9",
    "1e308", "-1e308", "1.7976931348623157e308", "3e16", "9007199254740993", "nan", "-nan",
    "1e60", "-1e60", "1e51",
    "NaN", "inf", "-inf", "Infinity", "1e999", "-1e999", "1e-999", "", " ", "abc", "1.5.2",
    "0x1p3", "0x10", "1e", "+2", "2 ", " 2", "1,2", "1_000", "--", "-", "true", "1/2", "\uff12",
    "\udcff\udcfe", LONG_GARBAGE, "-" + LONG_GARBAGE]
SMALL_INVALID = ["0", "-0", "-1", "-2", "nan", "-nan", "", " ", "abc", "1e999", "-inf", "0.5",
                 "1.5", "5e-324", "-1e308", "1e", "0x10", LONG_GARBAGE]
EDGE_TEXT = ["", " ", "SI", "Exact", "three_phase", "Three-Phase", "dimensionless ", "none", "-",
             "time_stepping", "nan", "\udcff", "\u00e9", "x" * 3000, "exact,exact", "1"]
EDGE_LIST = ["", ",", "1,,2", "1,", ",1", "nan", "inf,1", "1e999", "0,0,0", "-0.3,0.4,0.9",
             "1;2", "a,b", "5e-324,1", "1e308,-1e308", "0.5,0.5,0", "1 2", " 0.3, 0.7",
             ",".join(["0.001"] * 300), "0.3,0.4,0.3,", "0.3,nan,0.3", "1e-320,1", "-1,2",
             LONG_GARBAGE]
EDGE_RANGE = ["", "1:3", "1:3:0", "1:3:-1", "3:1:2", "0:3:3", "-1:3:3", "1:3:1.5", "1:3:nan",
              "nan:3:3", "1:inf:3", "1:1e999:3", "1e308:1.7976931348623157e308:3",
              "5e-324:1:3", "1:1:1", "1:3:3:3", "a:b:c", "1::3", "::", "1:3:1e0",
              "1.7e308:1:3", "1:3:" + LONG_GARBAGE]
EDGE_INT = ["0", "-1", "-0", "1.5", "1e3", "nan", "", "abc", "99999999999999999999", "-2147483649",
            "0x10", " 3", LONG_GARBAGE]

# Curated big requests: (subcommand, units) that must end within the short timeout.
BIG_REQUESTS = {
    "simulate": [["--periods", "1e9", "--out", "p.csv"], ["--output-step", "1e-12", "--out", "p.csv"],
                 ["--periods", "1e308"], ["--periods", "1e12", "--output-step", "1e300"],
                 ["--method", "time-stepping", "--step", "1e-12", "--periods", "1", "--out", "t.csv"],
                 ["--method", "time-stepping", "--step", "5e-324", "--output-step", "1"]],
    "converge": [["--samples-per-period", "1000000000", "--out", "c.csv"],
                 ["--periods", "1e12", "--out", "c.csv"]],
    "stop": [["--output-step", "1e-12", "--out", "s.csv"]],
    "accuracy": [["--entries", "1000000000"], ["--entries", "1000000000", "--out", "e.csv"]],
    "accumulation": [["--n", "1000000000", "--out", "m.csv"],
                     ["--n", "4294967297", "--out", "m.csv"]],
    "sweep accelerations": [["--a2-range", "1:3:1000000000", "--a3-range", "1:3:2"],
                            ["--a2-range", "1:3:100000", "--a3-range", "1:3:100000"],
                            ["--threads", "1000000000"], ["--threads", "4294967295"]],
    "sweep period": [["--range", "0.5:2:1000000000"], ["--threads", "2147483647"]],
    "sweep stroke": [["--range", "0.01:0.1:1000000000"]],
    "sweep positioning": [["--entries", "1000000000"], ["--a2-range", "1:2:1000000000"],
                          ["--threads", "1000000000"]],
    "optimize": [["--order", "1000000000"], ["--segments", "1000000000"]],
    "design": [["--sample-rate", "1e12", "--profile-csv", "p.csv"],
               ["--entries", "1000000000"], ["--acceleration-grid", "1000000000"],
               ["--uncertain", "mu=normal:0.3,3%", "--monte-carlo", "100000000"]],
    "montecarlo": [["--runs", "100000000"], ["--worst-case", "--interior-points", "1000000"]],
}

# Base command lines: valid and cheap (a few ms in release).
BASE = {
    "simulate": [["--periods", "2"]],
    "steady": [],
    "floquet": [],
    "converge": [["--periods", "2"], ["--samples-per-period", "20"]],
    "stop": [["--max-periods", "200"]],
    "accuracy": [["--entries", "3"], ["--max-periods", "200"]],
    "accumulation": [["--n", "5"]],
    "sweep accelerations": [["--a2-range", "1:3:3"], ["--a3-range", "0.5:2:2"], ["--quiet"],
                            ["--threads", "2"]],
    "sweep period": [["--range", "0.5:2:3"], ["--quiet"], ["--threads", "1"]],
    "sweep stroke": [["--range", "0.01:0.1:3"], ["--quiet"]],
    "sweep positioning": [["--a2-range", "1.5:2.5:2"], ["--a3-range", "1:1.5:2"],
                          ["--entries", "3"], ["--max-periods", "100"], ["--quiet"],
                          ["--threads", "2"]],
    "optimize": [["--family", "three-phase"], ["--starts", "1"], ["--max-evaluations", "40"],
                 ["--order", "3"], ["--segments", "3"], ["--quiet"]],
    "design": [["--acceleration-grid", "4"], ["--period-grid", "2"], ["--stroke-grid", "1"],
               ["--entries", "3"]],
    "montecarlo": [["--period-s", "0.05"], ["--stroke-m", "0.0005"], ["--a2", "5"], ["--a3", "4"],
                   ["--x-mu", "0.05"], ["--distance", "0.055"], ["--tolerance", "0.001"],
                   ["--uncertain", "mu=normal:0.3,3%"], ["--runs", "50"]],
    "parameters": [["--set", "c_mu=3"], ["--set", "time_scale=1.1"], ["--json"]],
}

VALID_SAMPLES_CONSTANT = "t,ydd\n0,1\n0.5,-1\n1,0\n"
VALID_SAMPLES_BOTH = "0,0\n0.25,1\n0.5,0\n0.75,-1\n1,0\n"  # zero net velocity for both interpolations
SAMPLES_VARIANTS = [
    ("valid", VALID_SAMPLES_CONSTANT), ("valid-no-header", VALID_SAMPLES_BOTH),
    ("valid-comments-crlf", "# period 1\r\nt,ydd\r\n\r\n0,1\r\n0.5,-1\r\n1,0\r\n"),
    ("valid-spaces", "t , ydd\n 0 , 1 \n0.5,-1\n1,0\n"),
    ("valid-many-rows", None),  # generated
    ("empty", ""), ("header-only", "t,ydd\n"), ("one-row", "0,1\n"), ("one-row-header", "t,ydd\n0,0\n"),
    ("t0-not-zero", "0.1,1\n0.5,-1\n1,0\n"), ("repeated-t", "0,1\n0.5,-1\n0.5,0\n1,0\n"),
    ("decreasing-t", "0,1\n0.7,-1\n0.4,0\n1,0\n"), ("nan-ydd", "0,nan\n0.5,-1\n1,0\n"),
    ("inf-t", "0,1\n0.5,-1\ninf,0\n"), ("first-row-1e400", "0,1e400\n0,1\n0.5,-1\n1,0\n"),
    ("huge-ydd", "0,1e308\n0.5,-1e308\n1,0\n"), ("huge-t", "0,1\n5e299,-1\n1e300,0\n"),
    ("tiny-t", "0,1\n5e-324,-1\n1e-323,0\n"), ("tiny-ydd", "0,1e-300\n0.5,-1e-300\n1,0\n"),
    ("net-velocity", "0,1\n0.5,1\n1,1\n"), ("semicolons", "0;1\n0.5;-1\n1;0\n"),
    ("three-columns", "0,1,2\n0.5,-1,3\n1,0,1\n"), ("one-column", "0\n0.5\n1\n"),
    ("text", "a,b\nc,d\ne,f\n"), ("trailing-garbage", "0,1\n0.5,-1\n1,0\ngarbage\n"),
    ("binary", "\x00\x01\x02,\xff\n"), ("long-line", "0," + "1" * 5000 + "\n0.5,-1\n1,0\n"),
    ("hex", "0x0,1\n0.5,-1\n1,0\n"), ("negative-t", "-1,1\n0,-1\n1,0\n"),
    ("two-headers", "t,ydd\nt,ydd\n0,1\n0.5,-1\n1,0\n"), ("bom", "\ufefft,ydd\n0,1\n0.5,-1\n1,0\n"),
]

# NaN or beyond ±1e50: refused on every number flag, used by the run or not (docs/cli.md
# "Errors"; found D29, D35).
NAN_HUGE = ["nan", "NaN", "-nan", "inf", "-inf", "1e60", "-1e60", "1e51", "-1e51"]

# Valid friction laws (docs/config.md "Friction law": absolute coefficients with --mu): every
# subcommand that lists the law flags takes them (README: "Every analysis takes them"; found D22,
# D27, D28). Cheap: Coulomb laws run the exact solver, Stribeck and viscous ones the slip
# integrator at a loose tolerance.
LAWS = [["--mu", "0.3", "--mu-static", "0.36"],
        ["--mu", "0.3", "--mu-backward", "0.25"],
        ["--mu", "0.3", "--mu-static", "0.39", "--mu-backward", "0.27"],
        ["--mu", "0.3", "--mu-static", "0.36", "--stribeck-velocity", "0.1",
         "--relative-tolerance", "1e-6"],
        ["--viscous", "0.1", "--relative-tolerance", "1e-6"]]
