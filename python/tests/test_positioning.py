"""Positioning accuracy (Sect. 7.1, eq. 39) and the Fig. 17 surfaces."""

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL, PERIOD, STROKE

W, C_MU = 0.05, 4.0  # c_mu > every a2 used: the objects stop


def test_positioning_accuracy_is_eq_39(case1_profile):
    n = 25
    acc = sa.positioning_accuracy(case1_profile, W, C_MU, sa.PositioningOptions(entries=n))
    assert acc.reaches and acc.all_stopped
    steady = sa.steady_state(case1_profile)
    assert acc.steady.v_bar == steady.v_bar
    # Entries x_0s ∈ [-v̄Δt, 0].
    assert acc.entries.shape == (n,) and acc.entries.dtype == np.float64
    assert np.all(acc.entries <= 0) and np.all(acc.entries >= -steady.v_bar * PERIOD - 1e-15)
    ends = acc.end_positions
    assert ends.shape == (n,) and len(acc.runs) == n
    np.testing.assert_array_equal(ends, [r.end_position for r in acc.runs])
    overshoot = ends - acc.x_mu
    assert acc.overshoot_min == pytest.approx(overshoot.min(), abs=CLOSED_FORM_TOL)
    assert acc.overshoot_max == pytest.approx(overshoot.max(), abs=CLOSED_FORM_TOL)
    dx_d = (overshoot.max() - overshoot.min()) / 2  # eq. (39)
    assert acc.dx_d == pytest.approx(dx_d, abs=CLOSED_FORM_TOL)
    assert acc.x_d == pytest.approx(acc.x_mu + overshoot.min() + dx_d, abs=CLOSED_FORM_TOL)
    friction = sa.two_region_friction(acc.x_mu, W, C_MU)
    assert acc.x_stick_min == pytest.approx(
        sa.stick_position_min(friction.two_region, case1_profile.peak_acceleration), rel=CLOSED_FORM_TOL)
    assert acc.accumulating_entries == sum(r.kind == sa.StopKind.accumulation for r in acc.runs)


def test_positioning_accuracy_on_a_field_where_it_stands(case1_profile):
    # The two-region table as a field of steps under the footprint (eq. 9 as a window average),
    # moved on by 0.4: the table's motion is the same everywhere, so the spread is the paper's
    # and the ends move with the field (second method: the two-region overload; 1e-9 covers the
    # rounding of the moved positions over the runs' arcs).
    options = sa.PositioningOptions(entries=9)
    paper = sa.positioning_accuracy(case1_profile, W, C_MU, options)
    field = sa.FieldFriction(sa.FrictionField.steps([paper.x_mu + 0.4], [1.0, C_MU]),
                             sa.UniformFootprint(W))
    moved = sa.positioning_accuracy(case1_profile, field, options)
    assert moved.x_mu == paper.x_mu + 0.4
    np.testing.assert_allclose(moved.entries, paper.entries + 0.4, rtol=0, atol=1e-9)
    np.testing.assert_allclose(moved.end_positions, paper.end_positions + 0.4, rtol=0, atol=1e-9)
    assert moved.dx_d == pytest.approx(paper.dx_d, abs=1e-9)
    with pytest.raises(sa.InvalidParameter) as error:
        sa.positioning_accuracy(case1_profile, sa.UniformFriction(), options)
    assert error.value.name == "friction"


def test_positioning_surfaces_shapes_and_cells():
    a2, a3 = np.array([2.5, 3.0, 4.0]), np.array([0.9, 1.2])
    options = sa.PositioningOptions(entries=8, stopping=sa.StoppingOptions(max_periods=300))
    r = sa.positioning_surfaces(PERIOD, STROKE, W, C_MU, a2, a3, options=options, threads=1)
    shape = (3, 2)
    for key, dtype in [("case", np.int32), ("f", np.float64), ("accumulates", np.bool_),
                       ("dx_d", np.float64), ("accumulating_entries", np.int32),
                       ("max_periods_p99", np.int32), ("max_periods_p999", np.int32)]:
        assert r[key].shape == shape and r[key].dtype == dtype, key
    for i, x in enumerate(a2):
        for j, y in enumerate(a3):
            if not sa.solve_three_phase(sa.ThreePhaseParameters(PERIOD, STROKE, x, y)).physical:
                assert r["case"][i, j] == sa.StickSlipCase.non_physical
                assert np.isnan(r["f"][i, j]) and np.isnan(r["dx_d"][i, j])
                continue
            profile = sa.ThreePhaseProfile(PERIOD, STROKE, x, y)
            acc = sa.positioning_accuracy(profile, W, C_MU, options)
            assert r["case"][i, j] == acc.steady.motion_case
            assert r["f"][i, j] == acc.steady.f
            assert r["accumulates"][i, j] == acc.accumulates
            assert r["accumulating_entries"][i, j] == acc.accumulating_entries
            if acc.all_stopped:
                assert r["dx_d"][i, j] == pytest.approx(acc.dx_d, rel=CLOSED_FORM_TOL)


def test_positioning_surfaces_on_a_field_where_it_stands():
    # The two-region table written as a field of one step, anywhere: the Fig. 17 cells are the
    # placed table's to rounding (translation invariance; second method: the width, c_mu form),
    # also split over an executor (thread pool: the chunks and their merge).
    import concurrent.futures
    a2, a3 = np.array([1.8, 2.3]), np.array([1.1, 1.3])
    options = sa.PositioningOptions(entries=6)
    paper = sa.positioning_surfaces(PERIOD, STROKE, W, C_MU, a2, a3, options=options, threads=1)
    field = sa.FieldFriction(sa.FrictionField.steps([0.7], [1.0, C_MU]), sa.UniformFootprint(W))
    local = sa.positioning_surfaces(PERIOD, STROKE, field, a2, a3, options=options, threads=1)
    np.testing.assert_allclose(local["dx_d"], paper["dx_d"], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(local["case"], paper["case"])
    with concurrent.futures.ThreadPoolExecutor(2) as ex:
        split = sa.positioning_surfaces(PERIOD, STROKE, field, a2, a3, options=options,
                                        executor=ex, chunk_size=1)
        by_name = sa.positioning_surfaces(PERIOD, STROKE, friction=field, a2=a2, a3=a3,
                                          options=options, executor=ex, chunk_size=1)
    for r in (split, by_name):
        np.testing.assert_array_equal(r["dx_d"], local["dx_d"])
    with pytest.raises(sa.InvalidParameter) as error:
        sa.positioning_surfaces(PERIOD, STROKE, sa.UniformFriction(), a2, a3)
    assert error.value.name == "friction"


def test_positioning_surfaces_do_not_depend_on_threads():
    a2, a3 = sa.linear_grid(2.5, 5.0, 4), sa.linear_grid(0.8, 1.6, 3)
    options = sa.PositioningOptions(entries=6, stopping=sa.StoppingOptions(max_periods=200))
    calls = []
    one = sa.positioning_surfaces(PERIOD, STROKE, W, C_MU, a2, a3, options=options, threads=1)
    two = sa.positioning_surfaces(PERIOD, STROKE, W, C_MU, a2, a3, options=options, threads=2,
                                  progress=lambda d, t: calls.append((d, t)))
    for key in one:
        np.testing.assert_array_equal(one[key], two[key])
    assert calls[-1] == (12, 12)


def test_diagonal_cell_accumulates():
    """Issue 9 / F03: the diagonal a2 = a3 accumulates (stick positions contract to
    x_stick,min, docs/accumulation.md), so it counts in the periods-to-p surfaces."""
    options = sa.PositioningOptions(entries=6, stopping=sa.StoppingOptions(max_periods=300))
    r = sa.positioning_surfaces(PERIOD, STROKE, 0.05, 2.5, [2.45], [2.45], options=options,
                                threads=1)
    assert r["accumulates"][0, 0]
    assert r["accumulating_entries"][0, 0] == 6
    assert r["dx_d"][0, 0] == 0.0
    assert 1 <= r["max_periods_p99"][0, 0] <= r["max_periods_p999"][0, 0]
    assert r["failure"][0, 0] == ""  # computed (a failed cell would say why)
