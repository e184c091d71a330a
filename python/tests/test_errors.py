"""Misuse raises selfalign.InvalidParameter (a ValueError) carrying name, value and range."""

import math

import numpy as np
import pytest

import selfalign as sa


def test_invalid_parameter_is_a_value_error():
    assert issubclass(sa.InvalidParameter, ValueError)


def test_negative_width_names_the_width():
    with pytest.raises(sa.InvalidParameter) as info:
        sa.two_region_friction(x_mu=0.5, width=-1.0, c_mu=2.5)
    e = info.value
    assert (e.name, e.value, e.allowed) == ("width", "-1", "must be > 0")
    assert str(e) == "invalid width = -1: must be > 0"


@pytest.mark.parametrize("width", [0.0, -0.05])
def test_width_must_be_positive(width):
    with pytest.raises(sa.InvalidParameter) as info:
        sa.two_region_friction(0.5, width, 2.5)
    assert info.value.name == "width"


@pytest.mark.parametrize("c_mu", [1.0, 0.5])
def test_friction_ratio_must_exceed_one(c_mu):
    with pytest.raises(sa.InvalidParameter) as info:
        sa.two_region_friction(0.5, 0.05, c_mu)
    assert info.value.name == "c_mu"
    assert "1" in info.value.allowed


@pytest.mark.parametrize("field", ["period", "stroke", "a2", "a3"])
def test_nan_three_phase_parameter_is_named(field):
    values = dict(period=1.0, stroke=0.084, a2=3.0, a3=0.9)
    values[field] = math.nan
    with pytest.raises(sa.InvalidParameter) as info:
        sa.ThreePhaseProfile(**values)
    assert info.value.name == field
    assert info.value.value.lower() == "nan"


def test_case_zero_profile_is_an_error_but_its_solution_is_a_value():
    p = sa.ThreePhaseParameters(period=1.0, stroke=0.084, a2=1.0, a3=1.0)  # 1 + 1 > 1/(8 Δy)
    assert sa.solve_three_phase(p).physical is False
    assert sa.predict_case(p) == sa.StickSlipCase.non_physical
    with pytest.raises(sa.InvalidParameter) as info:
        sa.ThreePhaseProfile(p)
    assert info.value.name == "a2, a3"


def test_bad_method_string_is_an_invalid_parameter():
    with pytest.raises(sa.InvalidParameter) as info:
        sa.Method("runge-kutta")
    assert info.value.name == "method"


def test_exact_request_on_a_sloped_friction_map_is_exact_for_a_fourier_profile():
    # Since issue 11 Fourier profiles are exact on piecewise-constant levels and across the
    # transition region's slope too (harmonic-by-harmonic closed form), no longer refused.
    profile = sa.FourierProfile(1.0, [0.0], [0.05])
    r = sa.simulate(profile, sa.two_region_friction(0.5, 0.05, 2.5),
                    options=sa.SimulationOptions(method="exact", duration=2.0))
    assert r.method == sa.Method.exact
    assert r.integrator.steps == 0


def test_grids_must_be_one_dimensional():
    with pytest.raises(sa.InvalidParameter) as info:
        sa.sweep_accelerations(1.0, 0.084, np.ones((2, 2)), [1.0])
    assert info.value.name == "a2"


def test_negative_thread_count_is_rejected():
    with pytest.raises(sa.InvalidParameter) as info:
        sa.sweep_accelerations(1.0, 0.084, [3.0], [0.9], threads=-1)
    assert info.value.name == "threads"


def test_progress_must_be_callable():
    with pytest.raises(TypeError):
        sa.sweep_accelerations(1.0, 0.084, [3.0], [0.9], progress=42)


def test_enums_refuse_values_that_are_not_members():
    # Issue 9: Method(7) was accepted (shown as Method.???).
    for enum, count in ((sa.Method, 3), (sa.Interpolation, 2), (sa.StopKind, 3)):
        assert enum(count - 1) is not None
        with pytest.raises(sa.InvalidParameter):
            enum(count)
        with pytest.raises(sa.InvalidParameter):
            enum(-1)


def test_nan_and_huge_ints_are_refused_naming_the_argument():
    # Issue 9: NaN inputs returned NaN silently; 2**2000 raised "Unable to cast ...".
    profile = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    for call, name in ((lambda: sa.objective_f(float("nan")), "v_bar"),
                       (lambda: sa.objective_f(2**2000), "v_bar"),
                       (lambda: profile.sample(2**2000), "t"),
                       (lambda: profile.velocity(np.array([0.1, np.nan])), "t"),
                       (lambda: sa.UniformFriction().bound(np.inf), "x")):
        with pytest.raises(sa.InvalidParameter) as info:
            call()
        assert info.value.name == name
        assert "std::" not in str(info.value) and "cast" not in str(info.value)


def test_exact_state_is_read_only_and_checked():
    # Issue 9, D03: setting ExactState.segment from Python crashed the solver.
    profile = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    friction = sa.two_region_friction(0.5, 0.05, 2.5)
    state = sa.make_exact_state(profile, friction)
    for attribute in ("segment", "period_index", "object"):
        with pytest.raises(AttributeError):
            setattr(state, attribute, 3)
    with pytest.raises(sa.InvalidParameter):
        sa.advance_exact(profile, friction, state, 1e300)  # beyond 1e8 periods


def test_oversized_requests_are_refused_before_allocating():
    # Issue 9, D11: bad_alloc / vector::reserve messages, or minutes of work.
    profile = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    friction = sa.two_region_friction(0.5, 0.05, 2.5)
    cases = ((lambda: sa.simulate(profile, friction,
                                  options=sa.SimulationOptions(duration=1e308)), "duration"),
             (lambda: sa.simulate(profile, friction,
                                  options=sa.SimulationOptions(output_step=1e-12)), "output_step"),
             (lambda: sa.optimize_fourier(sa.ActuatorLimits(),
                                          sa.OptimizeOptions(order=10**9, starts=1)), "order"),
             (lambda: sa.linear_grid(0.0, 1.0, 10**9), "grid size"))
    for call, name in cases:
        with pytest.raises(sa.InvalidParameter) as info:
            call()
        assert info.value.name == name, str(info.value)


class _Foreign:
    """An object of a type no parameter takes."""


def test_a_wrong_type_names_the_parameter_and_the_expected_type():
    # Issue 20, D38: these raised RuntimeError("Unable to cast Python instance to C++ type").
    # (Every parameter of every binding: the fixed calls of test_fuzz_api.py.)
    request = sa.DesignRequest(acceleration_grid=4, period_grid=2, stroke_grid=1, entries=3,
                               tolerance=0.001)
    design = sa.design_process(request, threads=1)
    cases = [
        (lambda: sa.actuator_samples(request, design, 2000.0, moving_mass="1.0"),
         "moving_mass: expected a float [kg] or None, got str"),
        (lambda: sa.ProcessUncertainty(mu=_Foreign()), "mu: expected a Normal, Uniform"),
        (lambda: sa.ProcessUncertainty(c_mu=[1, 2]), "c_mu: expected"),
        (lambda: sa.planar_level(sa.UniformPlanarField(), 0.5, _Foreign()),
         "y: expected a float or an array-like of floats, got _Foreign"),
        (lambda: sa.read_acceleration_samples(_Foreign()),
         "path: expected a str or os.PathLike, got _Foreign"),
        (lambda: sa.ObjectState.__new__(sa.ObjectState).__setstate__((0.0, "x", 0.0)),
         "pickle state: field 'x' has the wrong type (str)"),
        (lambda: sa.Normal.__new__(sa.Normal).__setstate__((0.3, "a", 0.0, 1.0)),
         "pickle state: field 'sd' has the wrong type (str)"),
    ]
    for call, message in cases:
        with pytest.raises(TypeError) as info:
            call()
        assert message in str(info.value)
        assert "Unable to cast" not in str(info.value)


def test_a_number_for_an_uncertain_input_is_known_exactly():
    # Issue 20, D38: ProcessUncertainty(mu=0.25) means mu is 0.25 (a normal of zero spread).
    u = sa.ProcessUncertainty(mu=0.25, c_mu=3)
    assert u.mu == sa.Normal(0.25, 0.0) and u.c_mu == sa.Normal(3.0, 0.0)
    assert sa.ProcessUncertainty(mu=None).mu == sa.Known()
    request = sa.DesignRequest(tolerance=0.001)
    drawn = sa.draw_inputs(request, u, runs=5)
    assert (drawn["mu"] == 0.25).all() and (drawn["c_mu"] == 3.0).all()
    with pytest.raises(TypeError, match="static_ratio"):
        sa.ProcessUncertainty(static_ratio=True)  # a bool is not a number here
    with pytest.raises(sa.InvalidParameter) as info:
        sa.ProcessUncertainty(mu=-0.3)  # the domain check of any distribution
    assert info.value.name.startswith("mu")
