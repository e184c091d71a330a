"""Parameter studies: sweep_accelerations (Figs. 10, 11), families and sweep_period /
sweep_stroke (Figs. 4, 5), grids, thread-count invariance, progress and the GIL."""

import threading
import time

import numpy as np
import pytest

import selfalign as sa

from conftest import PERIOD, STROKE, fig8_case

A2 = np.array([0.8, 1.5, 3.0, 6.0, 20.0])
A3 = np.array([0.5, 0.9, 2.0, 8.0])


def assert_same_arrays(a, b):
    assert a.keys() == b.keys()
    for k in a:
        assert a[k].dtype == b[k].dtype
        np.testing.assert_array_equal(a[k], b[k])  # NaN == NaN here


def test_sweep_accelerations_shapes_and_types():
    r = sa.sweep_accelerations(PERIOD, STROKE, A2, A3)
    shape = (len(A2), len(A3))
    for key, dtype in [("predicted", np.int32), ("observed", np.int32), ("v_bar", np.float64),
                       ("f", np.float64), ("x_dot_0s", np.float64), ("converged", np.bool_)]:
        assert r[key].shape == shape and r[key].dtype == dtype, key
    np.testing.assert_array_equal(r["a2"], A2)
    np.testing.assert_array_equal(r["a3"], A3)


def test_sweep_cells_are_the_single_computations():
    r = sa.sweep_accelerations(PERIOD, STROKE, A2, A3, closed_form=False)  # the search
    for i, a2 in enumerate(A2):
        for j, a3 in enumerate(A3):
            expected_case = fig8_case(PERIOD, STROKE, a2, a3)
            assert r["predicted"][i, j] == expected_case
            if expected_case == 0:
                assert r["observed"][i, j] == 0
                assert np.isnan(r["v_bar"][i, j]) and np.isnan(r["f"][i, j])
                assert not r["converged"][i, j]
                continue
            s = sa.steady_state(sa.ThreePhaseProfile(PERIOD, STROKE, a2, a3))
            assert r["observed"][i, j] == s.motion_case
            assert r["v_bar"][i, j] == s.v_bar and r["f"][i, j] == s.f
            assert r["x_dot_0s"][i, j] == s.x_dot_0s
            assert r["converged"][i, j] == s.converged


def test_sweep_is_identical_for_any_thread_count():
    a2 = sa.linear_grid(0.5, 12.0, 23)
    a3 = sa.log_grid(0.3, 30.0, 17)
    one = sa.sweep_accelerations(PERIOD, STROKE, a2, a3, threads=1)
    two = sa.sweep_accelerations(PERIOD, STROKE, a2, a3, threads=2)
    every = sa.sweep_accelerations(PERIOD, STROKE, a2, a3)
    assert_same_arrays(one, two)
    assert_same_arrays(one, every)


def test_progress_reports_every_cell_in_order():
    calls = []
    sa.sweep_accelerations(PERIOD, STROKE, A2, A3, threads=2,
                           progress=lambda done, total: calls.append((done, total)))
    total = len(A2) * len(A3)
    assert calls and all(t == total for _, t in calls)
    done = [d for d, _ in calls]
    assert done == sorted(done) and done[-1] == total


class Stop(Exception):
    pass


def test_an_exception_in_progress_stops_the_sweep():
    def progress(done, total):
        raise Stop(done)

    with pytest.raises(Stop):
        sa.sweep_accelerations(PERIOD, STROKE, sa.linear_grid(1, 10, 40), A3, threads=2,
                               progress=progress)


def test_sweep_releases_the_gil():
    # A sweep long enough (>= 0.2 s) that holding the GIL would visibly freeze this thread: an
    # acceleration grid made finer until it takes that long. (It used time-stepping steady
    # states of a Fourier family; those are exact and fast since issue 11.)
    def sweep(n):
        grid = sa.linear_grid(0.5, 3.0, n)
        sa.sweep_accelerations(1.0, 0.084, grid, grid, threads=1)

    steps, duration = 20, 0.0
    while duration < 0.2 and steps < 5_000:
        steps *= 2
        start = time.perf_counter()
        sweep(steps)
        duration = time.perf_counter() - start

    worker = threading.Thread(target=sweep, args=(steps,))
    largest_gap, last = 0.0, time.perf_counter()
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        largest_gap, last = max(largest_gap, now - last), now
    worker.join()
    # Holding the GIL, this loop would stall for the whole sweep; released, for at most a few
    # GIL switch intervals (5 ms each).
    assert largest_gap < 0.5 * duration, (largest_gap, duration)


def test_grids_match_numpy():
    np.testing.assert_allclose(sa.linear_grid(0.5, 4.0, 8), np.linspace(0.5, 4.0, 8), rtol=1e-15)
    np.testing.assert_allclose(sa.log_grid(0.1, 100.0, 7), np.geomspace(0.1, 100.0, 7),
                               rtol=1e-13)
    g = sa.log_grid(0.1, 100.0, 7)
    assert g[0] == 0.1 and g[-1] == 100.0 and g.dtype == np.float64
    np.testing.assert_array_equal(sa.linear_grid(2.0, 5.0, 1), [2.0])
    with pytest.raises(sa.InvalidParameter):
        sa.log_grid(-1.0, 1.0, 3)


def test_three_phase_family_and_sweep_period():
    family = sa.ThreePhaseFamily(3.0, 0.9)
    assert family.name == "three-phase"
    periods = np.array([0.5, 0.8, 1.0, 1.5, 2.0])
    r = sa.sweep_period(family, STROKE, periods, threads=2)
    for key, dtype in [("period", np.float64), ("stroke", np.float64), ("physical", np.bool_),
                       ("observed", np.int32), ("v_bar", np.float64), ("f", np.float64)]:
        assert r[key].shape == periods.shape and r[key].dtype == dtype
    np.testing.assert_array_equal(r["period"], periods)
    assert np.all(r["stroke"] == STROKE)
    for k, period in enumerate(periods):
        physical = sa.solve_three_phase(sa.ThreePhaseParameters(period, STROKE, 3.0, 0.9)).physical
        assert r["physical"][k] == physical
        member = family.make(period, STROKE)
        if not physical:
            assert member is None and np.isnan(r["v_bar"][k])
            continue
        s = sa.steady_state(member)
        assert r["v_bar"][k] == s.v_bar and r["observed"][k] == s.motion_case


def test_scaled_shape_family_members_have_the_requested_period_and_stroke():
    family = sa.ScaledShapeFamily.paper_like()
    for period, stroke in [(1.0, 0.084), (0.5, 0.2), (3.0, 0.01)]:
        member = family.make(period, stroke)
        assert isinstance(member, sa.PiecewisePolynomialProfile)
        assert member.period == pytest.approx(period, rel=1e-12)
        assert member.stroke == pytest.approx(stroke, rel=1e-12)
        # Durations scale with Δt: fractions (0.35, 0.35, 0.30) of the period.
        np.testing.assert_allclose(member.segments()["begin"], [0, 0.35 * period, 0.7 * period],
                                   rtol=1e-12, atol=1e-15)
    strokes = np.array([0.02, 0.05, 0.1])
    r = sa.sweep_stroke(family, 1.0, strokes)
    np.testing.assert_array_equal(r["stroke"], strokes)
    assert np.all(r["physical"])
    assert r["v_bar"][0] == sa.steady_state(family.make(1.0, 0.02)).v_bar


def test_scaled_fourier_family_scales_the_stroke():
    family = sa.ScaledFourierFamily([0.0, 0.3], [1.0])
    member = family.make(2.0, 0.05)
    assert isinstance(member, sa.FourierProfile)
    assert member.stroke == pytest.approx(0.05, rel=1e-9)
    assert member.period == 2.0
    # Same harmonic content: coefficient ratios are kept.
    assert member.cos_coeffs[1] / member.sin_coeffs[0] == pytest.approx(0.3)


def test_more_threads_than_cores_are_capped_not_a_crash():
    # Issue 9, D02: threads=10**9 crashed oneTBB (segfault); it is capped at the cores.
    one = sa.sweep_accelerations(PERIOD, STROKE, A2, A3, threads=1)
    many = sa.sweep_accelerations(PERIOD, STROKE, A2, A3, threads=10**9)
    assert_same_arrays(one, many)
    with pytest.raises(sa.InvalidParameter, match="threads"):
        sa.sweep_accelerations(PERIOD, STROKE, A2, A3, threads=-1)


def test_every_cell_reports_its_failure_status():
    # Issue 9, F01: a cell that cannot be computed gets its own status; here all can.
    r = sa.sweep_accelerations(PERIOD, STROKE, A2, A3)
    assert r["failure"].shape == (len(A2), len(A3))
    assert all(m == "" for m in r["failure"].ravel())
    p = sa.sweep_period(sa.ThreePhaseFamily(2.3, 1.3), STROKE, [0.5, 1.0])
    assert list(p["failure"]) == ["", ""]


def test_closed_form_cells_agree_with_the_search_and_the_single_closed_form():
    """The default cells are the closed-form steady state (docs/three-phase-steady-state.md):
    the same as three_phase_steady_state bit for bit, and within 1e-10 (relative to 1 + |v|,
    the tolerance of tests/test_three_phase_steady_state.cpp) of the fixed-point search."""
    for law in (sa.FrictionLaw(), sa.FrictionLaw(1.2, 1.0, 0.7)):
        closed = sa.sweep_accelerations(PERIOD, STROKE, A2, A3, law=law)
        search = sa.sweep_accelerations(PERIOD, STROKE, A2, A3, law=law, closed_form=False)
        np.testing.assert_array_equal(closed["predicted"], search["predicted"])
        np.testing.assert_array_equal(closed["observed"], search["observed"])
        np.testing.assert_array_equal(closed["converged"], search["converged"])
        for key in ("v_bar", "x_dot_0s"):
            np.testing.assert_allclose(closed[key], search[key], rtol=0,
                                       atol=1e-10 * (1 + np.nanmax(np.abs(search[key]))))
        for i, a2 in enumerate(A2):
            for j, a3 in enumerate(A3):
                s = sa.three_phase_steady_state(sa.ThreePhaseParameters(PERIOD, STROKE, a2, a3),
                                                law)
                assert int(s.motion_case) == closed["observed"][i, j]
                np.testing.assert_array_equal([s.v_bar, s.f, s.x_dot_0s],
                                              [closed["v_bar"][i, j], closed["f"][i, j],
                                               closed["x_dot_0s"][i, j]])


def test_three_phase_steady_state_refuses_a_velocity_dependent_law():
    law = sa.FrictionLaw(1.2, 1.0).with_stribeck(0.1)
    with pytest.raises(sa.InvalidParameter, match="law"):
        sa.three_phase_steady_state(sa.ThreePhaseParameters(1.0, 0.084, 2.0, 2.0), law)
    s = sa.three_phase_steady_state(sa.ThreePhaseParameters(1.0, 0.084, 0.2, 0.2))
    assert s.motion_case == sa.StickSlipCase.non_physical and np.isnan(s.v_bar)
