"""The fixed corpus: cases 0 .. len(CORPUS)-1, one per item of the contract and per known defect
class, so that a short run (the sanitizer build) covers them all; random cases follow."""

import json

from .case import Case
from .config_files import deep_expr, huge_string_expr
from .mutate_documents import REPORT, deep_document_expr
from .values import LONG_GARBAGE, VALID_SAMPLES_CONSTANT


S_OK = repr(VALID_SAMPLES_CONSTANT.encode())
CFG_TOML = repr(b"periods = 2.0\n")
CFG_JSON = repr(b'{"periods": 2.0}\n')
MC_NO_UNCERTAIN = ["montecarlo", "--period-s", "0.05", "--stroke-m", "0.0005", "--a2", "5", "--a3", "4",
                   "--x-mu", "0.05", "--distance", "0.055", "--tolerance", "0.001", "--runs", "20"]


def _f(path, payload=None, kind="file"):
    return (path, kind, payload)


def _report(*changes):
    """A design report (mutate_documents.REPORT) with (section, key, value) changes."""
    report = json.loads(json.dumps(REPORT))
    for section, key, value in changes:
        report[section][key] = value
    return repr(json.dumps(report).encode())


U_TOML = repr(b'mu = "normal:0.3,3%"\n')
DESIGN = ["design", "--acceleration-grid", "4", "--period-grid", "2", "--stroke-grid", "1", "--entries", "3"]
MC = ["montecarlo", "--period-s", "0.05", "--stroke-m", "0.0005", "--a2", "5", "--a3", "4", "--x-mu", "0.05",
      "--distance", "0.055", "--tolerance", "0.001", "--uncertain", "mu=normal:0.3,3%", "--runs", "20"]


CORPUS = [
    # (tag, argv, files, inputs, big[, expect[, must_refuse]]): as Case.expect, Case.must_refuse
    ("no subcommand", [], [], [], False),
    ("--help", ["--help"], [], [], False),
    ("--version", ["--version"], [], [], False),
    ("unknown subcommand", ["simulat"], [], [], False),
    ("sweep without kind", ["sweep"], [], [], False),
    ("simulate default + out", ["simulate", "--periods", "2", "--out", "run.csv"], [], [], False),
    ("steady json", ["steady", "--json"], [], [], False),
    ("steady case 0", ["steady", "--a2", "0.5", "--a3", "0.5", "--json"], [], [], False),
    ("floquet json", ["floquet", "--a2", "1.2", "--a3", "2.5", "--json"], [], [], False),
    ("converge out", ["converge", "--periods", "2", "--out", "c.csv"], [], [], False),
    ("stop out", ["stop", "--out", "s.csv"], [], [], False),
    ("accuracy out", ["accuracy", "--entries", "5", "--out", "e.csv"], [], [], False),
    ("accumulation out", ["accumulation", "--n", "5", "--out", "m.csv"], [], [], False),
    ("sweep accelerations", ["sweep", "accelerations", "--a2-range", "0.5:3:4", "--a3-range",
                             "0.5:3:4", "--quiet", "--out", "a.csv"], [], [], False),
    ("sweep period", ["sweep", "period", "--range", "0.2:2:4", "--quiet", "--out", "p.csv"], [], [], False),
    ("sweep stroke scaled", ["sweep", "stroke", "--range", "0.01:0.1:3", "--family", "scaled-shape",
                             "--quiet"], [], [], False),
    ("sweep positioning", ["sweep", "positioning", "--a2-range", "1.5:2.5:2", "--a3-range", "1:1.5:2",
                           "--entries", "3", "--quiet", "--out", "q.csv"], [], [], False),
    ("optimize all", ["optimize", "--family", "all", "--starts", "1", "--max-evaluations", "40",
                      "--order", "3", "--quiet", "--json"], [], [], False),
    ("optimize infeasible", ["optimize", "--family", "three-phase", "--stroke", "0.084", "--starts",
                             "1", "--max-evaluations", "40", "--quiet", "--out", "o.json"], [], [], False),
    ("design profile csv", ["design", "--acceleration-grid", "4", "--period-grid", "2", "--stroke-grid",
                            "1", "--entries", "3", "--profile-csv", "p.csv", "--out", "d.json"], [], [], False),
    ("design infeasible", ["design", "--acceleration-grid", "4", "--period-grid", "2",
                           "--velocity-max", "1e-9"], [], [], False),
    ("design robust", ["design", "--acceleration-grid", "4", "--period-grid", "2", "--stroke-grid", "1",
                       "--entries", "3", "--tolerance", "0.002", "--uncertain", "mu=normal:0.3,3%",
                       "--robust", "--screening-runs", "20", "--verification-runs", "200",
                       "--finalists", "2", "--json"], [], [], False),
    ("design monte carlo", ["design", "--acceleration-grid", "4", "--period-grid", "2", "--stroke-grid",
                            "1", "--entries", "3", "--tolerance", "0.001", "--uncertainty-file", "u.toml",
                            "--monte-carlo", "100", "--out", "d.json"],
     [_f("u.toml", repr(b'mu = "normal:0.3,3%"\nc_mu = "uniform:2.4,2.6"\n'))], ["u.toml"], False),
    ("montecarlo worst case", ["montecarlo", "--period-s", "0.05", "--stroke-m", "0.0005", "--a2", "5",
                               "--a3", "4", "--x-mu", "0.05", "--distance", "0.055", "--tolerance",
                               "0.001", "--uncertain", "mu=normal:0.3,3%", "--runs", "200",
                               "--worst-case", "--interior-points", "8", "--out", "m.json",
                               "--runs-csv", "runs.csv"], [], [], False),
    ("uncertain sd < 0", ["montecarlo", "--period-s", "0.05", "--stroke-m", "0.0005", "--a2", "5",
                          "--a3", "4", "--x-mu", "0.05", "--uncertain", "mu=normal:0.3,-0.01",
                          "--out", "m.json"], [], [], False),
    # numbers
    ("width nan", ["simulate", "--width", "nan"], [], [], False),
    ("width denormal (D09)", ["simulate", "--width", "1e-320"], [], [], False),
    ("periods 1e999", ["simulate", "--periods", "1e999"], [], [], False),
    ("periods empty", ["simulate", "--periods", ""], [], [], False),
    ("valid a2 = 1e5 (D08)", ["steady", "--a2", "1e5", "--json"], [], [], False),
    ("stroke 1e-10 (D08)", ["steady", "--stroke", "1e-10", "--json"], [], [], False),
    ("v2 huge", ["converge", "--periods", "2", "--v2", "7.4e283", "--out", "c.csv"], [], [], False),
    ("acceleration-max 0", ["optimize", "--acceleration-max", "0", "--quiet"], [], [], False),
    ("fd-step 1e308", ["floquet", "--fd-step", "1e308", "--json"], [], [], False),
    ("v0 1e308", ["simulate", "--periods", "2", "--v0", "1e308"], [], [], False),
    ("a3 1e308 map", ["accumulation", "--a3", "1e308", "--n", "3", "--json"], [], [], False),
    ("map grid to 1.6e299", ["accumulation", "--n", "3", "--to", "1.6e299", "--out", "m.csv"], [], [], False),
    ("x0 1e308", ["simulate", "--periods", "1", "--x0", "1e308", "--out", "r.csv"], [], [], False),
    ("t0 1e308", ["simulate", "--periods", "1", "--t0", "1e308", "--out", "r.csv"], [], [], True),
    ("threads 1e9 (D02)", ["sweep", "accelerations", "--a2-range", "1:3:3", "--a3-range", "1:3:3",
                           "--quiet", "--threads", "1000000000"], [], [], True),
    ("threads 3 (D15)", ["sweep", "accelerations", "--a2-range", "1:3:3", "--a3-range", "1:3:3",
                         "--quiet", "--threads", "3", "--out", "s.csv"], [], [], False),
    ("threads -1", ["sweep", "period", "--range", "1:2:2", "--threads", "-1"], [], [], False),
    ("huge value echoed", ["simulate", "--width", LONG_GARBAGE], [], [], False),
    ("unknown flag", ["steady", "--bogus", "1"], [], [], False),
    ("repeated flag", ["steady", "--a2", "2", "--a2", "3"], [], [], False),
    ("--out= swallows a flag (D18)", ["steady", "--out=", "--json"], [], [], False),
    ("--summary= swallows a flag", ["converge", "--periods", "2", "--summary=", "--quiet"], [], [], False),
    # issue 20: NaN is never "not given", unused keys are checked, messages name the user's
    # flag, typos get a suggestion, a valid law runs everywhere (expectations: Case.expect)
    ("design --mu-static nan (D29)", ["design", "--acceleration-grid", "4", "--period-grid", "2",
                                      "--stroke-grid", "1", "--entries", "3", "--mu-static", "nan"],
     [], [], False, ("refused", "mu-static")),
    ("montecarlo --x-mu nan (D29)", MC_NO_UNCERTAIN + ["--uncertain", "mu=normal:0.3,3%", "--x-mu", "nan"], [], [],
     False, ("refused", "x-mu")),
    ("unused --width nan (D35)", ["steady", "--width", "nan"], [], [], False, ("refused", "width")),
    ("unused --x0 1e60 (D35)", ["steady", "--x0", "1e60"], [], [], False, ("refused", "x0")),
    ("unused --stroke-max nan", MC_NO_UNCERTAIN + ["--uncertain", "mu=normal:0.3,3%", "--stroke-max", "nan"], [],
     [], False, ("refused", "stroke-max")),
    ("--mu-backward 1e-300 (D32)", ["steady", "--mu-backward", "1e-300"], [], [], False,
     ("refused", "mu-backward")),
    ("--times gap 5e-324 (D32)", ["simulate", "--profile", "piecewise-linear", "--times", "0,5e-324",
                                  "--accelerations", "1,-1", "--period", "1"], [], [], False,
     ("refused", "times")),
    ("--field-interpolation cubic (D32)", ["simulate", "--friction", "field", "--field-file", "f.csv",
                                           "--field-interpolation", "cubic"],
     [_f("f.csv", repr(b"0,1\n1,2\n"))], ["f.csv"], False, ("refused", "field-interpolation")),
    ("subcommand typo", ["desing"], [], [], False, ("hint",)),
    ("flag typo --c_mu", ["simulate", "--c_mu", "2"], [], [], False, ("hint",)),
    ("montecarlo nothing uncertain", MC_NO_UNCERTAIN, [], [], False, ("refused", "uncertain")),
    ("--mu-static without --mu (F07)", ["steady", "--mu-static", "0.36", "--json"], [], [], False,
     ("runs",)),
    ("law on converge (D22)", ["converge", "--periods", "2", "--mu", "0.3", "--mu-static", "0.36",
                               "--stribeck-velocity", "0.1", "--relative-tolerance", "1e-6"], [], [],
     False, ("runs",)),
    ("law on accuracy (D27)", ["accuracy", "--entries", "3", "--mu", "0.3", "--mu-static", "0.36",
                               "--stribeck-velocity", "0.1", "--relative-tolerance", "1e-6"], [], [],
     False, ("runs",)),
    # config files
    ("deep JSON (D01)", ["simulate", "--config", "deep.json"], [_f("deep.json", deep_expr("json", 100000))], ["deep.json"], False),
    ("deep TOML", ["steady", "--config", "deep.toml"], [_f("deep.toml", deep_expr("toml", 100000))], ["deep.toml"], False),
    ("JSON 1e999 (D10)", ["simulate", "--config", "run.json"], [_f("run.json", repr(b'{"width": 1e999}'))], ["run.json"], False),
    ("TOML 1e999", ["simulate", "--config", "run.toml"], [_f("run.toml", repr(b"width = 1e999\n"))], ["run.toml"], False),
    ("TOML nan", ["steady", "--config", "run.toml"], [_f("run.toml", repr(b"a2 = nan\n"))], ["run.toml"], False),
    ("config is a folder (D06)", ["steady", "--config", "run.toml", "--json"], [_f("run.toml", kind="dir")], ["run.toml"], False),
    ("config empty path (D06)", ["steady", "--config", "", "--json"], [], [], False),
    ("config huge string (D16)", ["steady", "--config", "big.json"], [_f("big.json", huge_string_expr("json"))], ["big.json"], False),
    ("config wrong type", ["simulate", "--config", "run.json"], [_f("run.json", repr(b'{"width": "wide"}'))], ["run.json"], False),
    ("config unknown key", ["simulate", "--config", "run.toml"], [_f("run.toml", repr(b"widht = 1\n"))], ["run.toml"], False),
    ("config top-level array", ["simulate", "--config", "run.json"], [_f("run.json", repr(b"[1, 2]"))], ["run.json"], False),
    ("config empty", ["simulate", "--config", "run.json"], [_f("run.json", repr(b""))], ["run.json"], False),
    ("config TOML table", ["simulate", "--config", "run.toml"], [_f("run.toml", repr(b"[sec]\nwidth = 1\n"))], ["run.toml"], False),
    ("config names its own out", ["steady", "--config", "run.json"], [_f("run.json", repr(b'{"out": "run.json"}'))], ["run.json"], False),
    # samples
    ("samples first row dropped (D17)", ["steady", "--profile", "samples", "--samples", "s.csv", "--json"],
     [_f("s.csv", repr(b"0,1e400\n0,1\n0.5,-1\n1,0\n"))], ["s.csv"], False),
    ("samples net velocity (D07)", ["simulate", "--profile", "samples", "--samples", "s.csv"],
     [_f("s.csv", repr(b"t,ydd\n0,1\n0.5,1\n1,1\n"))], ["s.csv"], False),
    ("samples one row", ["steady", "--profile", "samples", "--samples", "s.csv"], [_f("s.csv", repr(b"0,0\n"))], ["s.csv"], False),
    ("samples header only", ["steady", "--profile", "samples", "--samples", "s.csv"], [_f("s.csv", repr(b"t,ydd\n"))], ["s.csv"], False),
    ("samples huge times (D13)", ["simulate", "--profile", "samples", "--samples", "s.csv", "--periods", "1", "--out", "run.csv"],
     [_f("s.csv", repr(b"0,1\n5e299,-1\n1e300,0\n"))], ["s.csv"], False),
    ("samples huge ydd", ["stop", "--profile", "samples", "--samples", "s.csv", "--out", "o.csv"],
     [_f("s.csv", repr(b"0,1e308\n0.5,-1e308\n1,0\n"))], ["s.csv"], False),
    ("samples is a folder", ["steady", "--profile", "samples", "--samples", "s.csv"], [_f("s.csv", kind="dir")], ["s.csv"], False),
    # outputs colliding with inputs, special files
    ("out = config (D05)", ["simulate", "--config", "cfg.toml", "--out", "cfg.toml"], [_f("cfg.toml", CFG_TOML)], ["cfg.toml"], False),
    ("derived summary = config (D05)", ["simulate", "--config", "run.summary.json", "--out", "run.csv"],
     [_f("run.summary.json", CFG_JSON)], ["run.summary.json"], False),
    ("out = samples (D05)", ["simulate", "--profile", "samples", "--samples", "s.csv", "--periods", "1", "--out", "s.csv"],
     [_f("s.csv", S_OK)], ["s.csv"], False),
    ("summary = samples", ["converge", "--profile", "samples", "--samples", "s.csv", "--periods", "1", "--out", "c.csv",
                           "--summary", "s.csv"], [_f("s.csv", S_OK)], ["s.csv"], False),
    ("summary = out", ["simulate", "--periods", "1", "--out", "o.csv", "--summary", "o.csv"], [], [], False),
    ("summary path is a folder (D04)", ["simulate", "--periods", "2", "--out", "run.csv"], [_f("run.summary.json", kind="dir")], [], False),
    ("out is a folder", ["steady", "--out", "d"], [_f("d", kind="dir")], [], False),
    ("out in a missing folder", ["accuracy", "--entries", "2", "--out", "nodir/e.csv"], [], [], False),
    ("out symlink (D21)", ["simulate", "--periods", "1", "--out", "link.csv"],
     [_f("victim", kind="dir"), _f("victim/t.txt", repr(b"ORIGINAL\n")), _f("link.csv", "victim/t.txt", "symlink")], [], False),
    ("out FIFO (D21)", ["simulate", "--periods", "1", "--out", "fifo.csv"], [_f("fifo.csv", kind="fifo")], [], False),
    ("out mode 600 (D21)", ["simulate", "--periods", "1", "--out", "mode600.csv"], [_f("mode600.csv", repr(b"x\n"), "file600")], [], False),
    ("out symlink to config", ["simulate", "--config", "cfg.toml", "--out", "clink.csv"],
     [_f("cfg.toml", CFG_TOML), _f("clink.csv", "cfg.toml", "symlink")], ["cfg.toml"], False),
    ("profile-csv = out", ["design", "--acceleration-grid", "4", "--period-grid", "2", "--stroke-grid", "1",
                           "--entries", "3", "--out", "r.json", "--profile-csv", "r.json"], [], [], False),
    # the robust commands' documents and outputs (issue 20)
    ("deep uncertainty JSON (D23)", MC + ["--uncertainty-file", "u.json"],
     [_f("u.json", deep_document_expr("json", 100000, "array"))], ["u.json"], False),
    ("deep uncertainty dotted TOML (D23)", DESIGN + ["--uncertainty-file", "u.toml"],
     [_f("u.toml", deep_document_expr("toml", 100000, "dotted"))], ["u.toml"], False),
    ("deep design report (D23)", ["montecarlo", "--design", "d.json", "--runs", "20"],
     [_f("d.json", 'b"{\\"profile\\": " + b"[" * 100000 + b"]" * 100000 + b"}"')], ["d.json"], False),
    ("report jerk [1] (D30)", ["montecarlo", "--design", "d.json", "--uncertain", "mu=normal:0.3,3%", "--runs", "20"],
     [_f("d.json", _report(("profile", "jerk_m_per_s3", [1])))], ["d.json"], False, None, ("design", "d.json")),
    ("report distance true (D30)", ["montecarlo", "--design", "d.json", "--uncertain", "mu=normal:0.3,3%", "--runs", "20"],
     [_f("d.json", _report(("request", "distance_m", True)))], ["d.json"], False, None, ("design", "d.json")),
    ("report 1e999 (D31)", ["montecarlo", "--design", "d.json", "--uncertain", "mu=normal:0.3,3%"],
     [_f("d.json", repr(b'{"profile": {"period_s": 1e999}}'))], ["d.json"], False),
    ("uncertainty invalid byte (D31)", MC + ["--uncertainty-file", "u.json"], [_f("u.json", repr(b"\xff\xfe{"))], ["u.json"], False),
    ("out = design report (D24)", ["montecarlo", "--design", "d.json", "--uncertain", "mu=normal:0.3,3%", "--runs", "20",
                                   "--out", "d.json"], [_f("d.json", _report())], ["d.json"], False),
    ("runs-csv = uncertainty file (D24)", MC + ["--uncertainty-file", "u.toml", "--runs-csv", "./u.toml"],
     [_f("u.toml", U_TOML)], ["u.toml"], False),
    ("profile-csv -> link to uncertainty (D24)", DESIGN + ["--uncertainty-file", "u.toml", "--monte-carlo", "20",
                                                          "--tolerance", "0.001", "--profile-csv", "lnk"],
     [_f("u.toml", U_TOML), _f("lnk", "u.toml", "symlink")], ["u.toml"], False),
    ("out = sub/../uncertainty (D24)", DESIGN + ["--uncertainty-file", "u.toml", "--out", "sub/../u.toml"],
     [_f("u.toml", U_TOML), _f("sub", kind="dir")], ["u.toml"], False),
    ("design ./x and x (D25)", DESIGN + ["--out", "./same.out", "--profile-csv", "same.out"], [], [], False),
    ("montecarlo x and sub/../x (D25)", MC + ["--out", "same.out", "--runs-csv", "sub/../same.out"],
     [_f("sub", kind="dir")], [], False),
    ("simulate ./x and x", ["simulate", "--periods", "1", "--out", "./o.csv", "--summary", "o.csv"], [], [], False),
    # big requests: refused (or done) quickly
    ("periods 1e9 --out (D11)", ["simulate", "--periods", "1e9", "--out", "p.csv"], [], [], True),
    ("output-step 1e-12 (D11)", ["simulate", "--output-step", "1e-12"], [], [], True),
    ("periods 1e308 (D11)", ["simulate", "--periods", "1e308"], [], [], True),
    ("step > duration (D14)", ["simulate", "--method", "time-stepping", "--step", "10", "--periods", "1", "--out", "ts.csv"], [], [], False),
    ("step 5e-324", ["simulate", "--method", "time-stepping", "--step", "5e-324", "--output-step", "1", "--periods", "2"], [], [], True),
    ("c_mu 3e16 (D12)", ["accuracy", "--c-mu", "3e16", "--a2", "2.5", "--a3", "1", "--entries", "1", "--json"], [], [], True),
    ("1e9 cells", ["sweep", "accelerations", "--a2-range", "1:3:1000000000", "--a3-range", "1:3:2", "--quiet"], [], [], True),
    ("converge 1e12 periods", ["converge", "--periods", "1e12", "--out", "c.csv"], [], [], True),
    ("converge 1e9 samples", ["converge", "--samples-per-period", "1000000000", "--out", "c.csv"], [], [], True),
    ("accumulation 1e9 points", ["accumulation", "--n", "1000000000", "--out", "m.csv"], [], [], True),
    ("accuracy 1e9 entries", ["accuracy", "--entries", "1000000000"], [], [], True),
    ("optimize order 1e9", ["optimize", "--order", "1000000000", "--quiet"], [], [], True),
    ("design sample rate 1e12", ["design", "--acceleration-grid", "4", "--period-grid", "2", "--stroke-grid", "1",
                                 "--entries", "3", "--sample-rate", "1e12", "--profile-csv", "p.csv"], [], [], True),
    ("design 1e9 grid", ["design", "--acceleration-grid", "1000000000"], [], [], True),
]


def corpus_case(index, seed):
    tag, argv, files, inputs, big = CORPUS[index][:5]
    extra = CORPUS[index][5:]
    c = Case(index, seed)
    n = 2 if argv[:1] == ["sweep"] and len(argv) > 1 and not argv[1].startswith("-") else min(1, len(argv))
    if argv[:1] and argv[0].startswith("-"):
        n = 0
    c.sub = argv[:n]
    rest = argv[n:]
    i = 0
    while i < len(rest):
        if rest[i].startswith("--") and "=" not in rest[i] and i + 1 < len(rest) \
                and not rest[i + 1].startswith("--"):
            c.units.append(rest[i:i + 2])
            i += 2
        else:
            c.units.append([rest[i]])
            i += 1
    for path, kind, payload in files:
        c.add_file(path, kind, payload)
    c.inputs = set(inputs)
    c.big = big
    c.expect = extra[0] if extra else None
    c.must_refuse = extra[1] if len(extra) > 1 else None
    c.tags = ["corpus: " + tag]
    return c
