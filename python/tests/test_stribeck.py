"""Velocity-dependent friction (Stribeck, viscous) from Python: the law's API, the slip
integrator behind simulate / steady_state / floquet / sweeps, and its provenance.

Expected values are independent: the exact solvers' Coulomb solution (static = kinetic makes
the Stribeck term vanish), position invariance and the stick ({1, 0} Floquet multipliers), and
Moreau time-stepping as a second method."""
import math

import numpy as np
import pytest

import selfalign as sa

PROFILE = sa.ThreePhaseProfile(sa.ThreePhaseParameters(1.05, 0.084, 2.2, 0.9))
LAW = sa.FrictionLaw(1.3, 1.0).with_stribeck(0.01, 2.0).with_viscous(0.1)


def test_law_keeps_its_terms_and_names_bad_ones():
    assert LAW.velocity_dependent and LAW.stribeck_velocity == 0.01 and LAW.viscous == 0.1
    assert "stribeck_velocity=0.01" in repr(LAW)
    # mu(0) = static, mu(inf) = kinetic (S2 of docs/slip-integrator.md)
    assert LAW.kinetic(1, 0.0) == pytest.approx(1.3, abs=1e-15)
    assert LAW.kinetic(1, 1.0) == pytest.approx(1.0, abs=1e-15)
    assert not hasattr(sa, "CoulombFriction")  # no Python-only alias (issue 21 item 7)
    for call, name in ((lambda: LAW.with_stribeck(0.0), "stribeck_velocity"),
                       (lambda: LAW.with_stribeck(0.1, -2.0), "stribeck_exponent"),
                       (lambda: LAW.with_viscous(-1.0), "viscous"),
                       (lambda: sa.IntegratorOptions(relative_tolerance=1.0), "relative_tolerance"),
                       (lambda: sa.IntegratorOptions(absolute_tolerance=0.0), "absolute_tolerance")):
        with pytest.raises(sa.InvalidParameter) as info:
            call()
        assert info.value.name == name


def test_static_equal_kinetic_reproduces_the_exact_coulomb_steady_state():
    exact = sa.steady_state(PROFILE, sa.FrictionLaw(1.0, 1.0))
    integrated = sa.steady_state(PROFILE, sa.FrictionLaw(1.0, 1.0).with_stribeck(1.0))
    assert exact.method == sa.Method.exact and integrated.method == sa.Method.integrator
    assert integrated.v_bar == pytest.approx(exact.v_bar, abs=1e-12)  # parabolic arcs: exact
    assert integrated.integrator.steps > 0


def test_simulate_reports_the_integrator_and_never_creeps():
    r = sa.simulate(PROFILE, sa.UniformFriction(), sa.ObjectState(0, 0, 0),
                    sa.SimulationOptions(duration=10 * PROFILE.period), law=LAW)
    assert r.method == sa.Method.integrator
    assert r.integrator.steps > 0 and r.integrator.events > 0
    stick = np.asarray(r.trajectory.stick, dtype=bool)
    assert stick.sum() > 100
    assert np.all(np.asarray(r.trajectory.xd)[stick] == 0.0)


def test_moreau_agrees_with_the_integrator():
    # second method: time-stepping at h = Δt/1e5, O(h) (docs/slip-integrator.md: 8e-6 RMS)
    ref = sa.steady_state(PROFILE, LAW)
    run = sa.simulate(PROFILE, sa.UniformFriction(), sa.ObjectState(0, 0, ref.x_dot_0s),
                      sa.SimulationOptions(method="time-stepping", duration=PROFILE.period,
                                           step=PROFILE.period / 100000, record=False), law=LAW)
    assert run.method == sa.Method.time_stepping
    assert run.final_state.x / PROFILE.period == pytest.approx(ref.v_bar, abs=1e-4)


def test_floquet_and_sweeps_run_through_the_integrator():
    a = sa.floquet_multipliers(PROFILE, LAW, sa.FloquetOptions(fd_step=1e-5))
    assert not a.saltation.available and math.isnan(a.spread)
    mods = sorted(abs(z) for z in a.finite_difference.multipliers)
    assert mods[0] == pytest.approx(0.0, abs=1e-4) and mods[1] == pytest.approx(1.0, abs=1e-4)
    grid = sa.sweep_accelerations(1.05, 0.084, [2.2, 3.0], [0.9], law=LAW, threads=1)
    v = np.asarray(grid["v_bar"])
    assert v.shape == (2, 1)
    assert v[0, 0] == pytest.approx(sa.steady_state(PROFILE, LAW).v_bar, abs=1e-12)


def test_stopping_through_the_integrator_matches_the_exact_run():
    # static = kinetic: the integrator's events (entry, targets, stops) against the exact
    # solver's closed-form arcs
    p = sa.ThreePhaseProfile(sa.ThreePhaseParameters(1.0, 0.084, 1.8, 1.1))
    f = sa.two_region_friction(0.1, 0.05, 2.5)
    o = sa.StoppingOptions(fractions=[0.5, 0.9],
                           integrator=sa.IntegratorOptions(relative_tolerance=1e-12,
                                                           absolute_tolerance=1e-14))
    exact = sa.stopping_run(p, f, sa.ObjectState(0, 0, 0), o, law=sa.FrictionLaw(1.0, 1.0))
    integ = sa.stopping_run(p, f, sa.ObjectState(0, 0, 0), o,
                            law=sa.FrictionLaw(1.0, 1.0).with_stribeck(1.0))
    assert integ.kind == exact.kind == sa.StopKind.permanent_stick
    for key in ("end_position", "process_time", "entry_time"):
        assert getattr(integ, key) == pytest.approx(getattr(exact, key), abs=1e-9)
    np.testing.assert_allclose(integ.time_to_fraction, exact.time_to_fraction, atol=1e-9)


def test_work_budget_ends_a_stiff_slip_naming_the_viscous_rate():
    """issue 20, D26: a stiff slip (viscous c x period far above the explicit steps allowed)
    ran for hours; the integrator's budget ends it with an error naming the cause."""
    options = sa.SteadyStateOptions(
        integrator=sa.IntegratorOptions(max_steps_per_period=1e3))
    with pytest.raises(sa.InvalidParameter) as info:
        sa.steady_state(PROFILE, sa.FrictionLaw(1.0, 1.0).with_viscous(1e9), options)
    assert info.value.name == "viscous"
    with pytest.raises(sa.InvalidParameter) as info:
        sa.IntegratorOptions(max_steps_per_period=0.5)
    assert info.value.name == "max_steps_per_period"
