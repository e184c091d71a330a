"""simulate(), its NumPy trajectory, the exact solver's arcs and time stepping."""

import gc

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL, PERIOD, case1_mean_velocity, three_phase_times

A2, A3 = 3.0, 0.9  # the case1_profile fixture
# Moreau's method with h = 1e-4 is first order in h at the stick/slip events: the position
# after one period differs from the exact one by O(h) = 1e-4 times O(1) velocities.
TIME_STEPPING_TOL = 5e-4


def test_case1_run_from_rest_follows_eqs_12_to_24(case1_profile):
    r = sa.simulate(case1_profile, sa.UniformFriction(), sa.ObjectState(0, 0, 0),
                    sa.SimulationOptions(duration=PERIOD, output_step=1e-3))
    t1, t2, _, _ = three_phase_times(PERIOD, 0.084, A2, A3)
    tr = r.trajectory
    stuck_start = tr.t < t1  # eqs. (12)-(14)
    assert np.all(tr.x[stuck_start] == 0) and np.all(tr.xd[stuck_start] == 0)
    slip = (tr.t > t1) & (tr.t < t2)  # eqs. (16), (17)
    np.testing.assert_allclose(tr.xd[slip], (A2 - 1) * (tr.t[slip] - t1), atol=CLOSED_FORM_TOL)
    np.testing.assert_allclose(tr.x[slip], (A2 - 1) * (tr.t[slip] - t1) ** 2 / 2,
                               atol=CLOSED_FORM_TOL)
    v2 = (A2 - 1) * (t2 - t1)
    t_stop = t2 + v2 / (1 + A3)  # eq. (21)
    decel = (tr.t > t2) & (tr.t < t_stop)  # eq. (19)
    np.testing.assert_allclose(tr.xd[decel], v2 - (1 + A3) * (tr.t[decel] - t2),
                               atol=CLOSED_FORM_TOL)
    stuck_end = tr.t > t_stop  # eqs. (22)-(24)
    assert np.all(tr.xd[stuck_end] == 0) and np.all(tr.stick[stuck_end])
    assert r.final_state.x == pytest.approx(case1_mean_velocity(PERIOD, 0.084, A2, A3) * PERIOD,
                                            rel=CLOSED_FORM_TOL)
    assert r.mean_velocity_last_period == pytest.approx(r.final_state.x / PERIOD,
                                                        rel=CLOSED_FORM_TOL)


def test_trajectory_columns_are_typed_equal_length_read_only_views(case1_profile):
    r = sa.simulate(case1_profile, sa.UniformFriction(),
                    options=sa.SimulationOptions(duration=3.0))
    tr = r.trajectory
    n = len(tr)
    assert n == 3 * 200 + 1  # default output step Δt/200 (exact solver), plus the end time
    for name in ("t", "x", "xd", "y", "yd", "ydd"):
        a = getattr(tr, name)
        assert a.dtype == np.float64 and a.shape == (n,)
        assert not a.flags.writeable
    assert tr.stick.dtype == np.bool_ and tr.stick.shape == (n,)
    np.testing.assert_allclose(np.diff(tr.t), PERIOD / 200, rtol=1e-9)
    assert r.stick_fraction == pytest.approx(tr.stick.mean())
    assert set(tr.as_dict()) == {"t", "x", "xd", "y", "yd", "ydd", "stick"}
    with pytest.raises(ValueError):
        tr.x[0] = 1.0


def test_table_columns_are_the_profile(case1_profile):
    tr = sa.simulate(case1_profile, sa.UniformFriction(),
                     options=sa.SimulationOptions(duration=2.0)).trajectory
    y, yd, _ = case1_profile.sample(tr.t)
    np.testing.assert_allclose(tr.y, y, atol=1e-12)
    np.testing.assert_allclose(tr.yd, yd, atol=1e-12)


def test_views_outlive_the_result(case1_profile):
    r = sa.simulate(case1_profile, sa.UniformFriction(),
                    options=sa.SimulationOptions(duration=2.0))
    x = r.trajectory.x
    expected = np.array(x)
    del r
    gc.collect()
    np.testing.assert_array_equal(x, expected)


def test_summary_only_run_records_nothing(case1_profile):
    r = sa.simulate(case1_profile, sa.UniformFriction(),
                    options=sa.SimulationOptions(duration=2.0, record=False))
    assert len(r.trajectory) == 0 and r.trajectory.x.shape == (0,)
    assert r.final_state.t == pytest.approx(2.0)


def test_exact_and_time_stepping_agree(case1_profile):
    friction = sa.two_region_friction(0.3, 0.05, 2.5)
    exact = sa.simulate(case1_profile, friction, options=sa.SimulationOptions(duration=6.0))
    stepped = sa.simulate(case1_profile, friction,
                          options=sa.SimulationOptions(method="time-stepping", duration=6.0,
                                                       record=False))
    assert stepped.final_state.x == pytest.approx(exact.final_state.x, abs=TIME_STEPPING_TOL)
    assert stepped.work == 60_000


def test_time_stepping_state_matches_simulate(case1_profile):
    friction = sa.UniformFriction()
    options = sa.TimeSteppingOptions(step=1e-3)
    state = sa.make_time_stepping_state(case1_profile, sa.ObjectState(0.0, 0.0, 0.2))
    sa.advance_time_stepping(case1_profile, friction, options, state, 2000)
    assert state.step_index == 2000
    run = sa.simulate(case1_profile, friction, sa.ObjectState(0.0, 0.0, 0.2),
                      sa.SimulationOptions(method=sa.Method.time_stepping, step=1e-3,
                                           duration=2.0, record=False))
    assert state.object.x == pytest.approx(run.final_state.x, abs=1e-14)
    assert state.object.xd == pytest.approx(run.final_state.xd, abs=1e-14)
    with pytest.raises(sa.InvalidParameter):
        sa.advance_time_stepping(case1_profile, friction, sa.TimeSteppingOptions(step=-1.0),
                                 state, 1)


def test_exact_state_matches_simulate(case1_profile):
    friction = sa.two_region_friction(0.2, 0.05, 2.5)
    state = sa.make_exact_state(case1_profile, friction, sa.ObjectState(0.0, 0.0, 0.0))
    arcs = sa.advance_exact(case1_profile, friction, state, 5.0)
    assert arcs > 0 and state.object.t == 5.0
    run = sa.simulate(case1_profile, friction, options=sa.SimulationOptions(duration=5.0))
    assert state.object.x == run.final_state.x


def test_exact_arcs_are_contiguous_closed_forms(case1_profile):
    friction = sa.two_region_friction(0.15, 0.05, 2.5)
    arcs = sa.exact_arcs(case1_profile, friction, sa.ObjectState(0, 0, 0), duration=7.9)
    n = len(arcs["t0"])
    assert n > 10
    for key, dtype in [("t0", np.float64), ("kind", np.int8), ("direction", np.int8),
                       ("end", np.int8), ("segment", np.int64), ("piece", np.int64)]:
        assert arcs[key].dtype == dtype and arcs[key].shape == (n,)
    # Contiguous in time and state, covering [0, 7.9] (7.9: not a switch time).
    assert arcs["t0"][0] == 0.0 and arcs["t1"][-1] == 7.9
    np.testing.assert_array_equal(arcs["t0"][1:], arcs["t1"][:-1])
    np.testing.assert_allclose(arcs["x0"][1:], arcs["x1"][:-1], atol=1e-15)
    assert sa.ArcEnd(arcs["end"][-1]) is sa.ArcEnd.horizon
    kinds = arcs["kind"]
    # Stick arcs do not move; parabolic arcs obey x'' = -sigma m - A (eq. 6 with m constant).
    stick = kinds == sa.ArcKind.stick
    np.testing.assert_array_equal(arcs["x1"][stick], arcs["x0"][stick])
    assert np.all(arcs["direction"][stick] == 0)
    par = kinds == sa.ArcKind.parabolic
    np.testing.assert_allclose(arcs["alpha"][par],
                               -arcs["direction"][par] * arcs["bound0"][par]
                               - arcs["table_accel"][par], atol=CLOSED_FORM_TOL)
    # The object enters the transition region, where arcs are harmonic (eqs. 42-47).
    assert np.any(kinds == sa.ArcKind.harmonic)
    harmonic = kinds == sa.ArcKind.harmonic
    np.testing.assert_allclose(arcs["omega"][harmonic], np.sqrt(friction.two_region.b1), rtol=1e-12)


def test_set_valued_friction_law_eq_2():
    # eq. (2) at rest: held iff |y''| <= bound, else a slip against the push, -sign(y'')
    assert sa.decide_at_rest(0.5, 1.0) == 0 and sa.decide_at_rest(-1.0, 1.0) == 0
    assert sa.decide_at_rest(1.5, 1.0) == -1 and sa.decide_at_rest(-1.5, 1.0) == 1
    assert sa.decide_at_rest(0.5, 1.0, breaking=1) == 1
    assert sa.decide_at_rest(1.5, 1.0, stalled=True) == 0
