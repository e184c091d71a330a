"""``python -m selfalign regimes``: the vibratory feeder's regime chart (docs/feeder.md) as CSV
rows and a PNG figure, with the flags of the C++ ``selfalign regimes``.

    python -m selfalign regimes --mu-static 0.5 --mu-kinetic 0.4 --csv chart.csv \\
        --png chart.png

The cells are :func:`selfalign.feeder_regime_chart`'s (exact runs by default); the figure is
:func:`selfalign.feeder_figures.plot_regime_chart` (regimes, onset curves, speed contours).
Bad input: one line ``python -m selfalign regimes: error: ...`` naming the flag, exit 2, no
file written; both files are written atomically, the CSV and the PNG only when both can be.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
from typing import Optional

import numpy as np

from . import _selfalign as sa

_COLUMNS = ("vibration_angle_rad,machine_number,throw_number,regime,first_event,lifted_off,"
            "dimensionless_speed,stick_fraction,flight_fraction,status")


class _Bad(Exception):
    """One line naming the flag."""


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m selfalign regimes",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--angle-min", type=float, default=0.0, help="least vibration angle [rad]")
    p.add_argument("--angle-max", type=float, default=1.2, help="largest vibration angle [rad]")
    p.add_argument("--angles", type=int, default=25, help="vibration angles, in [1, 2000]")
    p.add_argument("--k-min", type=float, default=0.1, help="least machine number, > 0")
    p.add_argument("--k-max", type=float, default=10.0, help="largest machine number")
    p.add_argument("--machine-numbers", type=int, default=25,
                   help="machine numbers (geometric), in [1, 2000]")
    p.add_argument("--incline", type=float, default=0.0, help="track incline [rad]")
    p.add_argument("--mu-static", type=float, required=True, help="static friction, > 0")
    p.add_argument("--mu-kinetic", type=float, required=True,
                   help="kinetic friction, in (0, mu-static]")
    p.add_argument("--periods", type=int, default=10, help="periods from rest per cell")
    p.add_argument("--method", default="exact", help="exact (default) or time-stepping")
    p.add_argument("--steps-per-period", type=int, default=200,
                   help="Moreau steps per period (time-stepping)")
    p.add_argument("--restitution", type=float, default=0.0, help="Newton's e, in [0, 1]")
    p.add_argument("--threads", type=int, default=0, help="worker threads (0: all cores)")
    p.add_argument("--csv", help="write the cells to FILE")
    p.add_argument("--png", help="write the figure to FILE")
    return p


def _axis(lo: float, hi: float, n: int, geometric: bool) -> np.ndarray:
    """n points from lo to hi as the C++ command computes them (C's pow: the same doubles)."""
    f = [0.0 if n == 1 else i / (n - 1) for i in range(n)]
    return np.array([lo * math.pow(hi / lo, x) if geometric else lo + (hi - lo) * x for x in f])


def _csv_text(chart: dict) -> str:
    def num(v: float) -> str:  # the C++ command's shortest round-trip text (std::to_chars)
        v = float(v)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        text = repr(v)
        return text[:-2] if text.endswith(".0") else text

    rows = [_COLUMNS]
    shape = chart["regime"].shape
    for i in range(shape[0]):
        for j in range(shape[1]):
            rows.append(",".join([
                num(chart["vibration_angle"][i, j]), num(chart["machine_number"][i, j]),
                num(chart["throw_number"][i, j]), sa.FeederRegime(int(chart["regime"][i, j])).name,
                sa.FeederEvent(int(chart["first_event"][i, j])).name.replace("_", " "),
                "true" if chart["lifted_off"][i, j] else "false",
                num(chart["dimensionless_speed"][i, j]), num(chart["stick_fraction"][i, j]),
                num(chart["flight_fraction"][i, j]),
                "failed" if chart["failed"][i, j] else "ok"]))
    return "\n".join(rows) + "\n"


def run(argv: Optional[list[str]] = None) -> int:
    args = _parser().parse_args(argv)
    for name, n in (("angles", args.angles), ("machine-numbers", args.machine_numbers)):
        if not 1 <= n <= 2000:
            raise _Bad(f"invalid {name} = {n}: must be in [1, 2000]")
    if not (args.k_min > 0 and args.k_max > 0):
        raise _Bad(f"invalid k-min/k-max = {args.k_min}/{args.k_max}: must be > 0")
    for name in ("csv", "png"):
        path = getattr(args, name)
        if path is not None and not os.path.isdir(os.path.dirname(os.path.abspath(path))):
            raise _Bad(f"invalid {name} = {path}: its folder does not exist")
    angles = _axis(args.angle_min, args.angle_max, args.angles, False)
    ks = _axis(args.k_min, args.k_max, args.machine_numbers, True)
    try:
        chart = sa.feeder_regime_chart(
            angles, ks, incline=args.incline, mu_static=args.mu_static,
            mu_kinetic=args.mu_kinetic, periods=args.periods, method=args.method,
            steps_per_period=args.steps_per_period, restitution=args.restitution,
            threads=args.threads)
    except sa.InvalidParameter as e:  # named as the flag: mu_static -> mu-static
        raise _Bad(str(e).replace(e.name, e.name.replace("_", "-"), 1)) from None
    from . import feeder_figures
    from .planar_figures import _write_atomically
    if args.csv is not None:
        text = _csv_text(chart)

        def write_csv(tmp: str) -> None:
            with open(tmp, "w", encoding="utf-8") as out:
                out.write(text)
        _write_atomically(args.csv, ".csv", write_csv)
    if args.png is not None:
        feeder_figures.plot_regime_chart(chart, incline=args.incline, mu_static=args.mu_static,
                                         path=args.png)
    counts = {r.name: int(np.sum(chart["regime"] == int(r))) for r in sa.FeederRegime}
    print(f"{chart['regime'].size} cells: " + ", ".join(f"{k} {v}" for k, v in counts.items())
          + f"; failed {int(np.sum(chart['failed']))}")
    return 0


def main(argv: Optional[list[str]] = None) -> int:
    try:
        return run(argv)
    except _Bad as e:
        print(f"python -m selfalign regimes: error: {e}", file=sys.stderr)
        return 2
