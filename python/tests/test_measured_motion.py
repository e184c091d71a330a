"""read_measured_motion (issue 25, item 1): hand-written files, SI values worked out by hand."""

import math

import numpy as np
import pytest

import selfalign as sa


def test_a_tracker_export_in_millimetres(tmp_path):
    path = tmp_path / "run1.csv"
    path.write_text("mass A\n"
                    "t [ms]\tx [mm]\tangle [deg]\n"
                    "0\t1.5\t90\n"
                    "2.5\t\t0\n"
                    "4\t2.0\t-45\n")
    r = sa.read_measured_motion(path)
    np.testing.assert_array_equal(r["t"], [0.0, 4e-3])
    np.testing.assert_array_equal(r["x"], [1.5e-3, 2.0e-3])
    assert r["angle"][0] == pytest.approx(math.pi / 2, rel=1e-15)
    assert r["angle"][1] == pytest.approx(-math.pi / 4, rel=1e-15)
    assert r["y"] is None and r["table_acceleration"] is None
    assert r["skipped"] == 1
    assert r["title"] == "mass A"
    assert r["line"].dtype == np.int64 and list(r["line"]) == [3, 5]


def test_time_going_back_names_the_line_and_writes_nothing(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("t,x\n0,0\n0.2,1\n0.1,2\n")
    before = sorted(p.name for p in tmp_path.iterdir())
    with pytest.raises(sa.InvalidParameter, match=r"bad\.csv:4 time"):
        sa.read_measured_motion(str(path))
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_no_time_column_and_a_wrong_type(tmp_path):
    path = tmp_path / "none.csv"
    path.write_text("a,x\n1,2\n")
    with pytest.raises(sa.InvalidParameter, match="time column"):
        sa.read_measured_motion(path)
    with pytest.raises(TypeError, match="path"):
        sa.read_measured_motion(3)


def test_a_side_file_gives_the_units(tmp_path):
    path = tmp_path / "run2.txt"
    path.write_text("t x\n0 2\n40 3\n")
    (tmp_path / "run2.txt.units").write_text("t = ms\nx = mm\n")
    r = sa.read_measured_motion(path)
    np.testing.assert_array_equal(r["t"], [0.0, 0.04])
    np.testing.assert_array_equal(r["x"], [2e-3, 3e-3])
