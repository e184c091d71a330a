"""The figure of an identification (docs/identification.md, "Out"): the fit over the data and
the residuals, per run, from ``selfalign identify --fit-csv`` or an :class:`Identification`.

    python -m selfalign identification-figure fit.csv fit.png

Top: measured positions (dots) and the fitted model's (line), each shooting window's fit in
turn, stick samples marked. Bottom: residuals with +-2 sigma. Bad input: one line
``python -m selfalign identification-figure: error: ...``, exit 2, no file written; the PNG is
written atomically.
"""
from __future__ import annotations

import os
import sys
import tempfile

import numpy as np


def _runs_from_csv(path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    if d.dtype.names is None or not {"run", "t", "x_measured", "x_fitted", "residual",
                                     "window", "stick"} <= set(d.dtype.names):
        raise ValueError(f"{path}: not a fit CSV of selfalign identify --fit-csv "
                         "(run,t,x_measured,x_fitted,residual,window,stick)")
    d = np.atleast_1d(d)
    runs = []
    for r in np.unique(d["run"]).astype(int):
        s = d[d["run"] == r]
        runs.append({"source": f"run {r}", "t": s["t"], "x_measured": s["x_measured"],
                     "x_fitted": s["x_fitted"], "residual": s["residual"],
                     "window": s["window"].astype(int), "stick": s["stick"].astype(bool)})
    return runs


def plot_identification(runs, path, title="identify: fit over the data"):
    """Writes the figure of ``runs`` (a fit CSV's path, an Identification, or its ``runs``
    list) to ``path`` (PNG, atomically). Positions in mm, time in s (the data's units when the
    config was dimensionless)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if isinstance(runs, (str, os.PathLike)):
        runs = _runs_from_csv(runs)
    elif hasattr(runs, "runs"):
        runs = runs.runs
    fig, axes = plt.subplots(2, len(runs), figsize=(7 * len(runs), 6), sharex="col",
                             squeeze=False, gridspec_kw={"height_ratios": [2, 1]})
    for k, run in enumerate(runs):
        top, bottom = axes[0][k], axes[1][k]
        t, w = run["t"], run["window"]
        top.plot(t, run["x_measured"] * 1e3, ".", ms=2, color="0.55", label="measured")
        for j in np.unique(w):
            m = w == j
            top.plot(t[m], run["x_fitted"][m] * 1e3, "-", lw=1.2, color="C0",
                     label="fitted (each window)" if j == w.min() else None)
        st = run["stick"]
        top.plot(t[st], run["x_fitted"][st] * 1e3, "|", ms=4, color="C3", label="stick (fit)")
        top.set_ylabel("x [mm]")
        top.set_title(str(run.get("source", f"run {k}")))
        top.legend(loc="upper left", fontsize=8)
        res = run["residual"] * 1e6
        sigma = float(np.sqrt(np.nanmean(res ** 2)))
        bottom.plot(t, res, ".", ms=2, color="C0")
        for s in (-2 * sigma, 2 * sigma):
            bottom.axhline(s, color="C3", lw=0.8, ls="--")
        bottom.set_ylabel("residual [um]")
        bottom.set_xlabel("t [s]")
        bottom.set_title(f"rms {sigma:.3g} um; dashed: +-2 rms", fontsize=9)
    fig.suptitle(title)
    fig.tight_layout()
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".identification-", suffix=".png", dir=folder)
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=120)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if os.path.exists(tmp):
            os.remove(tmp)


def main(argv):
    prog = "python -m selfalign identification-figure"
    if len(argv) != 2 or argv[0].startswith("-"):
        print(f"usage: {prog} FIT_CSV PNG", file=sys.stderr)
        return 2
    source, target = argv
    try:
        if not os.path.isfile(source):
            raise ValueError(f"{source}: no such file")
        if os.path.abspath(source) == os.path.abspath(target):
            raise ValueError(f"png = {target}: must not be the input")
        if not target.endswith(".png"):
            raise ValueError(f"png = {target}: must end in .png")
        plot_identification(source, target)
    except (ValueError, OSError) as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        return 2
    return 0
