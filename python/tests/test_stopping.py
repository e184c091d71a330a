"""Stopping in the friction transition region (Sect. 7.2, 7.3): eqs. (40), (41), the
stick-position map (59)-(60) and stopping runs."""

import math

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL, PERIOD, STROKE, three_phase_times

W, C_MU = 0.05, 4.0
A2, A3 = 3.0, 1.2  # a2 >= a3: a2 is the peak acceleration, the map's fixed point is eq. (41)


@pytest.fixture
def profile():
    return sa.ThreePhaseProfile(period=PERIOD, stroke=STROKE, a2=A2, a3=A3)


@pytest.fixture
def friction():
    return sa.TwoRegionFriction(0.07, W, C_MU)


def test_stick_position_min_is_eq_41(friction):
    for peak in (1.5, 3.0, 3.9):
        expected = friction.x_mu + W * (peak - 1) / (C_MU - 1)
        assert sa.stick_position_min(friction, peak) == pytest.approx(expected,
                                                                      rel=CLOSED_FORM_TOL)
    assert sa.stick_position_min(friction, 0.8) == friction.x_mu
    assert math.isinf(sa.stick_position_min(friction, C_MU + 0.1))


def test_sticks_permanently_is_eq_40(friction):
    x = np.linspace(0.0, 0.2, 81).reshape(9, 9)
    held = sa.sticks_permanently(friction, 3.0, x)
    assert held.dtype == np.bool_ and held.shape == x.shape
    np.testing.assert_array_equal(held, friction.bound(x) >= 3.0)
    assert sa.sticks_permanently(friction, 3.0, 1.0) is True


def eq59(x_n, friction):
    """eq. (59), written out from docs/accumulation.md."""
    t1, t2, _, _ = three_phase_times(PERIOD, STROKE, A2, A3)
    b1, b2 = friction.b1, friction.b2
    c1, c2, K = (b2 + A2) / b1, (b2 - A3) / b1, (A2 + A3) / b1
    theta = math.sqrt(b1) * (t2 - t1)
    d = x_n - c1
    return c2 + np.sqrt((K + d * np.cos(theta)) ** 2 + (d * np.sin(theta)) ** 2), c1, K, theta


def test_stick_position_map_is_eq_59(profile, friction):
    m = sa.StickPositionMap(profile, friction)
    x = np.linspace(friction.x_mu, friction.x_mu + W, 11)
    expected, c1, K, theta = eq59(x, friction)
    np.testing.assert_allclose(m(x), expected, rtol=CLOSED_FORM_TOL)
    assert m(float(x[3])) == pytest.approx(expected[3], rel=CLOSED_FORM_TOL)
    assert m.fixed_point() == pytest.approx(c1, rel=CLOSED_FORM_TOL)  # eq. (60)
    assert m.slope_at_fixed_point() == pytest.approx(math.cos(theta), rel=CLOSED_FORM_TOL)
    assert m.basin_lower_bound() == pytest.approx(c1 - 2 * K * math.cos(theta),
                                                  rel=CLOSED_FORM_TOL)
    # The slope, by central differences of the map: O(h^2) error with h = 1e-6.
    h = 1e-6
    fd = (m(c1 + h) - m(c1 - h)) / (2 * h)
    assert fd == pytest.approx(math.cos(theta), abs=1e-6)


def test_fixed_point_of_the_map_equals_stick_position_min(profile, friction):
    m = sa.StickPositionMap(profile, friction)
    x_min = sa.stick_position_min(friction, profile.peak_acceleration)
    assert m.fixed_point() == pytest.approx(x_min, rel=CLOSED_FORM_TOL)
    assert m(x_min) == pytest.approx(x_min, rel=CLOSED_FORM_TOL)
    assert m.accumulates_for_every_entry() == (m(friction.x_mu) < x_min)


def test_stopping_run_ends_where_simulate_stops(profile, friction):
    run = sa.stopping_run(profile, friction, sa.ObjectState(0.0, 0.0, 0.0))
    assert run.kind == sa.StopKind.permanent_stick
    assert run.x_stick_min == pytest.approx(sa.stick_position_min(friction, A2))
    assert run.end_position >= friction.x_mu
    assert sa.sticks_permanently(friction, A2, run.end_position)
    assert run.entry_time <= run.process_time < math.inf
    later = sa.simulate(profile, friction, options=sa.SimulationOptions(
        duration=run.process_time + 5 * PERIOD, record=False))
    assert later.final_state.x == pytest.approx(run.end_position, abs=1e-12)
    assert later.final_state.xd == 0.0
    pos = run.stick_positions
    assert pos.dtype == np.float64 and np.all(np.diff(pos) > 0) and pos[-1] == run.end_position
    assert run.time_to_fraction.shape == (2,) and run.periods_to_fraction.shape == (2,)
    assert run.periods_to_fraction.dtype == np.int32


def test_accumulating_runs_follow_the_map_to_x_stick_min(profile):
    acc = sa.positioning_accuracy(profile, W, C_MU, sa.PositioningOptions(entries=10))
    friction = sa.TwoRegionFriction(acc.x_mu, W, C_MU)
    m = sa.StickPositionMap(profile, friction)
    accumulating = [r for r in acc.runs if r.kind == sa.StopKind.accumulation]
    assert accumulating
    for r in accumulating:
        assert r.end_position == pytest.approx(m.fixed_point(), rel=CLOSED_FORM_TOL)
        assert math.isinf(r.process_time)
        pos = r.stick_positions
        assert m.proves_accumulation_from(pos[0])
        # The simulated stick positions are the iterates of eq. (59).
        np.testing.assert_allclose(m(pos[:-1]), pos[1:], atol=1e-12)


def test_stopping_options_defaults():
    o = sa.StoppingOptions()
    assert o.max_periods == 10_000
    np.testing.assert_array_equal(o.fractions, [0.99, 0.999])
    o.fractions = [0.5]
    np.testing.assert_array_equal(o.fractions, [0.5])
    with pytest.raises(sa.InvalidParameter):
        sa.stopping_run(sa.ThreePhaseProfile(PERIOD, STROKE, A2, A3),
                        sa.TwoRegionFriction(0.07, W, C_MU), sa.ObjectState(),
                        sa.StoppingOptions(fractions=[1.5]))
