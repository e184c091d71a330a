"""The sweeps' .npy output (issue 22): `selfalign sweep ... --out FILE.npy` writes the CSV's
columns as a NumPy structured array; numpy.load (the second reader, independent of selfalign)
gives the CSV's values: numbers bit for bit (the CSV prints 17 significant digits), flags and
counts as integers, the status as bytes."""

import csv
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = pathlib.Path(os.environ.get("SELFALIGN_CLI", ROOT / "build/release/apps/selfalign/selfalign"))


def run(*args, cwd):
    if not CLI.exists():
        pytest.skip(f"the CLI is not built at {CLI} (scripts/test.sh builds it first)")
    subprocess.run([str(CLI), *args, "--quiet"], cwd=cwd, check=True)


@pytest.mark.parametrize("sweep", [
    ["sweep", "accelerations", "--a2-range", "0.5:3:7", "--a3-range", "0.5:3:6"],
    ["sweep", "period", "--range", "0.5:2:5"],
    ["sweep", "positioning", "--a2-range", "1.5:3:3", "--a3-range", "0.8:2:3", "--entries", "3"],
])
def test_a_sweep_as_npy_is_its_csv(tmp_path, sweep):
    run(*sweep, "--out", "cells.csv", cwd=tmp_path)
    run(*sweep, "--out", "cells.npy", cwd=tmp_path)
    rows = list(csv.DictReader(open(tmp_path / "cells.csv")))
    cells = np.load(tmp_path / "cells.npy")
    assert cells.shape == (len(rows),)
    assert list(cells.dtype.names) == list(rows[0].keys())
    for name in cells.dtype.names:
        kind = cells.dtype[name].kind
        for i, row in enumerate(rows):
            if kind == "S":
                assert cells[name][i].decode() == row[name]
            elif kind == "i":
                assert cells[name][i] == int(row[name])
            else:
                value = float(row[name])
                assert (math.isnan(value) and math.isnan(cells[name][i])) or cells[name][i] == value
    assert '"format": "npy"' in (tmp_path / "cells.summary.json").read_text()
