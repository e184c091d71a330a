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
    return sa.two_region_friction(0.07, W, C_MU)


def test_stick_position_min_is_eq_41(friction):
    for peak in (1.5, 3.0, 3.9):
        expected = friction.two_region.x_mu + W * (peak - 1) / (C_MU - 1)
        assert sa.stick_position_min(friction.two_region, peak) == pytest.approx(expected,
                                                                      rel=CLOSED_FORM_TOL)
    assert sa.stick_position_min(friction.two_region, 0.8) == friction.two_region.x_mu
    assert math.isinf(sa.stick_position_min(friction.two_region, C_MU + 0.1))


def test_sticks_permanently_is_eq_40(friction):
    x = np.linspace(0.0, 0.2, 81).reshape(9, 9)
    held = sa.sticks_permanently(friction, 3.0, x)
    assert held.dtype == np.bool_ and held.shape == x.shape
    np.testing.assert_array_equal(held, friction.bound(x) >= 3.0)
    assert sa.sticks_permanently(friction, 3.0, 1.0) is True


def eq59(x_n, friction):
    """eq. (59), written out from docs/accumulation.md."""
    t1, t2, _, _ = three_phase_times(PERIOD, STROKE, A2, A3)
    b1, b2 = friction.two_region.b1, friction.two_region.b2
    c1, c2, K = (b2 + A2) / b1, (b2 - A3) / b1, (A2 + A3) / b1
    theta = math.sqrt(b1) * (t2 - t1)
    d = x_n - c1
    return c2 + np.sqrt((K + d * np.cos(theta)) ** 2 + (d * np.sin(theta)) ** 2), c1, K, theta


def test_stick_position_map_is_eq_59(profile, friction):
    m = sa.StickPositionMap(profile, friction.two_region)
    x = np.linspace(friction.two_region.x_mu, friction.two_region.x_mu + W, 11)
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
    m = sa.StickPositionMap(profile, friction.two_region)
    x_min = sa.stick_position_min(friction.two_region, profile.peak_acceleration)
    assert m.fixed_point() == pytest.approx(x_min, rel=CLOSED_FORM_TOL)
    assert m(x_min) == pytest.approx(x_min, rel=CLOSED_FORM_TOL)
    assert m.accumulates_for_every_entry() == (m(friction.two_region.x_mu) < x_min)


def test_stopping_run_ends_where_simulate_stops(profile, friction):
    run = sa.stopping_run(profile, friction, sa.ObjectState(0.0, 0.0, 0.0))
    assert run.kind == sa.StopKind.permanent_stick
    assert run.x_stick_min == pytest.approx(sa.stick_position_min(friction.two_region, A2))
    assert run.end_position >= friction.two_region.x_mu
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
    friction = sa.two_region_friction(acc.x_mu, W, C_MU)
    m = sa.StickPositionMap(profile, friction.two_region)
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
                        sa.two_region_friction(0.07, W, C_MU), sa.ObjectState(),
                        sa.StoppingOptions(fractions=[1.5]))


def test_every_entry_condition_is_none_outside_its_derivation():
    """Issue 9 / F02: Sect. 7.3's condition needs x_stick,min to exist (peak <= c_mu, eq. 41)
    and to be the map's fixed point (a2 >= a3, eq. 60); elsewhere it is None, with a reason."""
    beyond_c_mu = sa.StickPositionMap(
        sa.ThreePhaseProfile(0.60597757985852, 0.012412335492963484, 8.508483283348117,
                             1.2561507198610682), sa.TwoRegionTable(0.008150211493444207, 0.06676181403696926, 4.739200637052614))
    a3_above_a2 = sa.StickPositionMap(sa.ThreePhaseProfile(PERIOD, STROKE, 1.3, 2.3), sa.TwoRegionTable(0.5, 0.05, 2.5))
    for m, phrase in ((beyond_c_mu, "> c_mu"), (a3_above_a2, "y3'' > y2''")):
        assert m.accumulates_for_every_entry() is None
        assert m.accumulation_condition_applies() is False
        assert phrase in m.accumulation_condition_reason()
    inside = sa.StickPositionMap(sa.ThreePhaseProfile(PERIOD, STROKE, 2.3, 1.3), sa.TwoRegionTable(0.5, 0.05, 2.5))
    assert inside.accumulation_condition_applies() is True
    assert inside.accumulation_condition_reason() == ""
    assert inside.accumulates_for_every_entry() is (inside(0.5) < inside.fixed_point())


def test_diagonal_stick_positions_contract_by_cos_cosh():
    """Issue 9 / F03: on the diagonal a2 = a3 the object slides back after each stop of eq. (59)
    (m < a3 below x_stick,min); its stick positions contract by cos θ cosh(sqrt(b1)(t3 - t2))
    per period (docs/accumulation.md), and a stopping run reports accumulation."""
    a = 2.45
    profile = sa.ThreePhaseProfile(PERIOD, STROKE, a, a)
    friction = sa.two_region_friction(0.5, 0.05, 2.5)
    m = sa.StickPositionMap(profile, friction.two_region)
    t1, t2, _, _ = three_phase_times(PERIOD, STROKE, a, a)
    omega = math.sqrt(friction.two_region.b1)
    lam = math.cos(omega * (t2 - t1)) * math.cosh(omega * (PERIOD - t2))
    assert m.contraction_at_fixed_point() == pytest.approx(lam, rel=1e-9)
    # Iterates of the composed arcs approach x_stick,min from below at that rate.
    c1 = m.fixed_point()
    x = [0.5 + 0.1 * (c1 - 0.5)]
    for _ in range(12):
        x.append(float(m.next_stick_position(x[-1])))
    d = c1 - np.asarray(x)
    assert np.all(d > 0) and np.all(np.diff(d) < 0)
    # The ratio's deviation from the slope is O(c1 - x_n): below 1e-3 after 12 periods.
    assert d[-1] / d[-2] == pytest.approx(lam, abs=1e-3)
    run = sa.stopping_run(profile, friction, sa.ObjectState(0.0, 0.0, 0.0))
    assert run.kind == sa.StopKind.accumulation
    assert run.end_position == pytest.approx(sa.stick_position_min(friction.two_region, a),
                                             rel=CLOSED_FORM_TOL)


def test_a_run_that_never_stops_has_no_end_position():
    # Issue 9: the end position of a run that never stops was 0.0 in Python (null in the CLI).
    # On the uniform part of the table, x_mu far ahead: the object never arrives in 3 periods.
    profile = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    run = sa.stopping_run(profile, sa.two_region_friction(50.0, 0.05, 2.5), sa.ObjectState(),
                          sa.StoppingOptions(max_periods=3))
    assert run.kind == sa.StopKind.not_stopped
    assert np.isnan(run.end_position) and np.isnan(run.process_time)



def test_one_stopping_criterion_for_the_time_stepped_run_and_the_planar_stop():
    # Issue 21: stuck for a whole period decides both; on a smooth motion onto a level 2.7 below
    # its peak |y''| = 2.78 the continuous motion never stops, while Moreau's step of h = 1/20
    # holds the part (2.7 >= max |Δy'| / h): the 1-D run and the planar stop of a point on the
    # same level along x stop at the same step and place (tests/test_final_stick.cpp by hand).
    wave = sa.FourierProfile(1.0, [0.04, 0.0], [0.0, 0.01])
    level = sa.FrictionField.ramps([0.05, 0.0500001], [1.0, 2.7])
    friction = sa.FieldFriction(level, sa.PointFootprint())
    exact = sa.stopping_run(wave, friction, sa.ObjectState())
    assert exact.method == sa.Method.exact and exact.never_stops
    options = sa.StoppingOptions(method="time-stepping", steps_per_period=20, max_periods=500)
    assert options.to_dict()["steps_per_period"] == 20
    one = sa.stopping_run(wave, friction, sa.ObjectState(), options)
    assert one.method == sa.Method.time_stepping
    assert one.kind == sa.StopKind.permanent_stick
    problem = sa.PlanarProblem(wave, field=sa.AxisField(level),
                               part=sa.RigidPart(0.01, sa.point_patch()), step=1.0 / 20)
    run = sa.planar_stop(problem, entries=[sa.PlanarPose(0, 0, 0)], max_periods=500,
                         threads=1).runs[0]
    assert run.stopped
    assert run.end.x == pytest.approx(one.end_position, abs=1e-12)
    assert run.process_time == one.process_time
    with pytest.raises(sa.InvalidParameter, match="steps_per_period"):
        sa.stopping_run(wave, friction, sa.ObjectState(), sa.StoppingOptions(steps_per_period=0))


def test_the_period_maps_stick_positions_on_any_level():
    # Issue 21: accumulation on any level. On the paper's table the exact solver's map is eq.
    # (59) with the slide back (the closed form, a second method); on two ramps with a kink it
    # accumulates at the general eq. (41), where the stopping run ends (accumulation).
    profile = sa.ThreePhaseProfile(1.0, 0.084, 2.45, 2.45)
    paper = sa.two_region_friction(0.5, 0.05, 2.5)
    closed = sa.StickPositionMap(profile, paper.two_region)
    numeric = sa.PeriodStickPositionMap(profile, paper)
    x = np.linspace(0.5, 0.55, 21)
    a, b = closed.next_stick_position(x), numeric(x)
    ok = ~np.isnan(a)
    assert ok.sum() >= 15
    np.testing.assert_allclose(b[ok], a[ok], rtol=0, atol=1e-12)
    kink = sa.FieldFriction(sa.FrictionField.ramps([0.1, 0.125, 0.15], [1.0, 1.9, 2.5]),
                            sa.PointFootprint())
    three = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    m = sa.PeriodStickPositionMap(three, kink)
    xs = [0.1]
    for _ in range(40):
        xs.append(m(xs[-1]))
    run = sa.stopping_run(three, kink, sa.ObjectState())
    assert run.kind == sa.StopKind.accumulation
    assert xs[-1] == pytest.approx(run.x_stick_min, abs=1e-9)
    assert np.all(np.diff(xs) >= 0)
    assert m(run.x_stick_min) == run.x_stick_min  # held for good there (eq. 40)
