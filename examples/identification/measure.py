#!/usr/bin/python3
"""Turns a `selfalign simulate` trajectory (t, x in SI) into what a video tracker exports, for
docs/identification.md's example: a title line, time in ms and position in mm, position noise
(sd 5 um), the tracker's clock 3 ms behind the drive's, every 50th frame dropped and one frame
with a missing position.

    /usr/bin/python3 examples/identification/measure.py truth.csv run1.csv
"""
import sys

import numpy as np

NOISE_M, OFFSET_S, SEED = 5e-6, 3e-3, 2026


def main(source, target):
    d = np.genfromtxt(source, delimiter=",", names=True)
    rng = np.random.default_rng(SEED)
    t = (d["t"] - OFFSET_S) * 1e3
    x = (d["x"] + rng.normal(0, NOISE_M, d["x"].size)) * 1e3
    keep = np.arange(t.size) % 50 != 49
    with open(target, "w") as f:
        f.write("mass A\nt [ms]\tx [mm]\tframe\n")
        for i in np.flatnonzero(keep):
            xs = "" if i == 700 else f"{x[i]:.6f}"
            f.write(f"{t[i]:.4f}\t{xs}\t{i}\n")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
