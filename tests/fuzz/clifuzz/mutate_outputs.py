"""Mutations of the run's outputs: outputs that collide with inputs or with each other (also
spelled differently: ./x, sub/../x, a symbolic link), and outputs that are folders, FIFOs,
symbolic links, existing files or odd names."""

from .config_files import render_config
from .mutate_documents import ensure_report, ensure_uncertainty
from .mutate_flags import mutate_unknown
from .values import VALID_SAMPLES_CONSTANT
from .vocabulary import CSV_SUMMARY_SUBS, FLAGS, KIND


def output_flags(sub):
    return [f for f in FLAGS[sub] if KIND.get(f) == "out"]


def ensure_config(c, sub, name=None):
    if c.value("config") and c.has_file(c.value("config")):
        return c.value("config")
    name = name or c.rng.choice(["cfg.toml", "cfg.json"])
    text = render_config("json" if name.endswith(".json") else "toml", [("periods", 2.0)] if sub in ("simulate", "converge") else [("width", 0.05)])
    c.add_file(name, "file", repr(text.encode()))
    c.inputs.add(name)
    c.set("config", name, anywhere=True)
    return name


def ensure_samples(c):
    if c.value("samples") and c.has_file(c.value("samples")):
        return c.value("samples")
    c.add_file("s.csv", "file", repr(VALID_SAMPLES_CONSTANT.encode()))
    c.inputs.add("s.csv")
    c.set("profile", "samples")
    c.set("samples", "s.csv", anywhere=True)
    return "s.csv"


def alias_of(c, target):
    """`target` (a path in the case folder) as written, or spelled another way (D24, D25)."""
    how = c.rng.choice(["same", "dot", "parent", "link"])
    c.tags.append(f"alias {how}")
    if how == "dot":
        return "./" + target
    if how == "parent":
        c.add_file("sub", "dir")
        return "sub/../" + target
    if how == "link":
        c.add_file("lnk", "symlink", target)
        return "lnk"
    return target


def an_input(c, sub):
    """An input file the command reads, created when the case has none; its path or None."""
    makers = []
    if "config" in FLAGS[sub]:
        makers.append(lambda: ensure_config(c, sub))
    if "samples" in FLAGS[sub]:
        makers.append(lambda: ensure_samples(c))
    if "uncertainty-file" in FLAGS[sub]:
        makers.append(lambda: ensure_uncertainty(c))
    if "design" in FLAGS[sub]:
        makers.append(lambda: ensure_report(c))
    return c.rng.choice(makers)() if makers else None


def two_outputs(sub):
    """Two output flags of one run, or None."""
    if sub in CSV_SUMMARY_SUBS:
        return ("out", "summary")
    return {"design": ("out", "profile-csv"), "montecarlo": ("out", "runs-csv")}.get(sub)


def mutate_collision(c, sub):
    rng = c.rng
    outs = output_flags(sub)
    if not outs:
        return mutate_unknown(c, sub)
    has_summary = "summary" in outs
    choices = ["out=config", "out=samples", "out=dir", "out=dir/", "out=.", "out=nodir",
               "out=fifo", "out=symlink", "out=dangling", "out=symlink-dir", "out=symlink-config",
               "out=existing", "out=existing-600", "out=empty", "out=trailing-slash",
               "out=odd-name", "out=tmp-name", "out=no-extension", "out=dash"]
    if has_summary:
        choices += ["summary=config", "summary=samples", "summary=out", "derived=config",
                    "derived=dir", "derived=fifo", "summary=dir", "summary=fifo",
                    "derived=symlink-config"]
    if "profile-csv" in outs:
        choices += ["csv=out", "csv=dir", "csv=fifo"]
    choices += ["input-alias"] * 3 + (["outputs-alias"] * 3 if two_outputs(sub) else [])
    kind = rng.choice(choices)
    c.tags.append(kind)
    if kind == "input-alias":  # any output over any input, however spelled (D24)
        target = an_input(c, sub)
        if target is None:
            return mutate_unknown(c, sub)
        c.set(rng.choice(outs), alias_of(c, target))
    elif kind == "outputs-alias":  # two outputs naming one file (D25)
        first, second = two_outputs(sub)
        name = rng.choice(["o.csv", "same.out"])
        c.set(first, name)
        c.set(second, alias_of(c, name))
    elif kind == "out=config":
        c.set("out", ensure_config(c, sub))
    elif kind == "out=samples":
        if "samples" in FLAGS[sub]:
            c.set("out", ensure_samples(c))
        else:
            c.set("out", ensure_config(c, sub) if "config" in FLAGS[sub] else "o.csv")
    elif kind in ("out=dir", "out=dir/"):
        c.add_file("d", "dir")
        c.set("out", "d" if kind == "out=dir" else "d/")
    elif kind == "out=.":
        c.set("out", ".")
    elif kind == "out=nodir":
        c.set("out", "nodir/o.csv")
    elif kind == "out=fifo":
        c.add_file("fifo.csv", "fifo")
        c.set("out", "fifo.csv")
    elif kind == "out=symlink":
        c.add_file("victim", "dir")
        c.add_file("victim/t.txt", "file", repr(b"ORIGINAL\n"))
        c.add_file("link.csv", "symlink", "victim/t.txt")
        c.set("out", "link.csv")
    elif kind == "out=dangling":
        c.add_file("dangling.csv", "symlink", "missing/target.csv")
        c.set("out", "dangling.csv")
    elif kind == "out=symlink-dir":
        c.add_file("d", "dir")
        c.add_file("dlink", "symlink", "d")
        c.set("out", "dlink")
    elif kind == "out=symlink-config":
        target = ensure_config(c, sub) if "config" in FLAGS[sub] else None
        if target is None:   # no input to point at: a plain file (writing through is accepted)
            c.add_file("victim.json", "file", repr(b'{"keep": 1}\n'))
            target = "victim.json"
        c.add_file("clink.csv", "symlink", target)
        c.set("out", "clink.csv")
    elif kind in ("out=existing", "out=existing-600"):
        c.add_file("old.csv", "file", repr(b"old contents\n"))
        if kind == "out=existing-600":
            c.files[-1].kind = "file600"
        c.set("out", "old.csv")
    elif kind == "out=empty":
        c.set("out", "")
    elif kind == "out=trailing-slash":
        c.set("out", "o.csv/")
    elif kind == "out=odd-name":
        c.set("out", rng.choice(["a b.csv", "\u00fc.csv", "-x.csv", "o.csv\n", ".csv", "o.",
                                 "..csv", "o.summary.json", "cfg.toml.csv"]))
    elif kind == "out=tmp-name":
        c.set("out", "o.csv.tmp-1")
    elif kind == "out=no-extension":
        c.set("out", "o")
    elif kind == "out=dash":
        c.set("out", "-")
    elif kind == "summary=config":
        c.set("out", "o.csv")
        c.set("summary", ensure_config(c, sub))
    elif kind == "summary=samples":
        c.set("out", "o.csv")
        c.set("summary", ensure_samples(c) if "samples" in FLAGS[sub] else "o.csv")
    elif kind == "summary=out":
        c.set("out", "o.csv")
        c.set("summary", rng.choice(["o.csv", "./o.csv"]))
    elif kind == "derived=config":
        name = "run.summary.json"
        c.add_file(name, "file", repr(render_config("json", [("width", 0.05)]).encode()))
        c.inputs.add(name)
        c.set("config", name, anywhere=True)
        c.set("out", "run.csv")
        c.drop("summary")
    elif kind == "derived=dir":
        c.add_file("run.summary.json", "dir")
        c.set("out", "run.csv")
        c.drop("summary")
    elif kind == "derived=fifo":
        c.add_file("run.summary.json", "fifo")
        c.set("out", "run.csv")
        c.drop("summary")
    elif kind == "derived=symlink-config":
        target = ensure_config(c, sub)
        c.add_file("run.summary.json", "symlink", target)
        c.set("out", "run.csv")
        c.drop("summary")
    elif kind == "summary=dir":
        c.add_file("d", "dir")
        c.set("out", "o.csv")
        c.set("summary", "d")
    elif kind == "summary=fifo":
        c.add_file("fifo.json", "fifo")
        c.set("out", "o.csv")
        c.set("summary", "fifo.json")
    elif kind == "csv=out":
        c.set("out", "r.json")
        c.set("profile-csv", "r.json")
    elif kind == "csv=dir":
        c.add_file("d", "dir")
        c.set("profile-csv", "d")
    elif kind == "csv=fifo":
        c.add_file("fifo.csv", "fifo")
        c.set("profile-csv", "fifo.csv")
