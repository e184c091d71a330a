"""The general core through Python: jerk-limited profiles, friction fields with footprints,
the period map, Coulomb laws with static > kinetic, and their use in the analyses.

Expected values are independent of the code under test: sampled integrals (NumPy), hand
formulas of the docs (docs/jerk-limited-three-phase.md, docs/static-kinetic-two-level.md),
the paper's two-region map (an independent implementation), and finite differences against
saltation.
"""

import gc
import math

import numpy as np
import pytest

import selfalign as sa

trapezoid = getattr(np, "trapezoid", None) or np.trapz  # NumPy < 2 has only trapz

BASE = dict(period=2.0, stroke=0.1, a2=2.5, a3=1.5)  # the C++ tests' jerk-limited setting
TWO_LEVEL = ([1.0, 1.0, 1.5], [-1.5, -3.0, 3.0])  # docs/static-kinetic-two-level.md, S3-S7


def jerk_limited(jerk, **overrides):
    return sa.JerkLimitedThreePhaseProfile(**{**BASE, **overrides, "jerk": jerk})


# ---- jerk-limited three-phase profile --------------------------------------------------------


@pytest.mark.parametrize("jerk", [20.0, 300.0])
def test_jerk_limited_profile_has_the_requested_stroke_and_a_periodic_velocity(jerk):
    profile = jerk_limited(jerk)
    t = np.linspace(0.0, BASE["period"], 200_001)
    y, yd, ydd = profile.sample(t)
    # max y - min y over dense samples; min y = 0 (Sect. 4.4.3, constraint 1).
    assert y.max() - y.min() == pytest.approx(BASE["stroke"], abs=1e-9)
    assert y.min() == pytest.approx(0.0, abs=1e-9)
    # y periodic: the velocity integrates to zero over a period; y' periodic: so does y''.
    assert trapezoid(yd, t) == pytest.approx(0.0, abs=1e-10)
    # (The trapezoid rule is off by up to j h^2/8 at each of the six kinks of y''.)
    h = t[1] - t[0]
    assert trapezoid(ydd, t) == pytest.approx(0.0, abs=6 * jerk * h * h / 8)
    # y' is the integral of y'' (cumulative trapezoid of the samples).
    cumulative = np.concatenate([[0.0], np.cumsum(0.5 * (ydd[1:] + ydd[:-1]) * np.diff(t))])
    np.testing.assert_allclose(yd - yd[0], cumulative, atol=1e-8)
    # |y'''| <= j on the samples, and the plateaus are -a2 and +a3.
    assert np.abs(np.diff(ydd) / np.diff(t)).max() <= jerk * (1 + 1e-6)
    assert ydd.min() == pytest.approx(-BASE["a2"], abs=1e-12)
    assert ydd.max() == pytest.approx(BASE["a3"], abs=1e-12)


def test_jerk_limited_durations_follow_the_hand_formulas():
    j = 50.0
    r = jerk_limited(j).solution
    a2, a3 = BASE["a2"], BASE["a3"]
    assert r.physical and r.reason == sa.JerkLimitedCase0.none
    d = r.durations()
    assert d.shape == (6,) and d.sum() == pytest.approx(BASE["period"], rel=1e-14)
    # Ramps of duration |Δy''|/j; plateaus T2h = D/a2 - a2/j, T3h = D/a3 - a3/j.
    np.testing.assert_allclose(d[[1, 3, 5]], [a2 / j, (a2 + a3) / j, a3 / j], rtol=1e-15)
    D = r.velocity_swing
    assert r.hold2 == pytest.approx(D / a2 - a2 / j, rel=1e-12)
    assert r.hold3 == pytest.approx(D / a3 - a3 / j, rel=1e-12)
    assert r.hold0 == pytest.approx(
        BASE["period"] - (1 / a2 + 1 / a3) * D - (a2 + a3) / j, rel=1e-12
    )


def test_jerk_below_the_ramp_bound_is_case_zero_with_its_reason():
    # j_p = (s max(a2, a3)^2 + a2 + a3)/Δt = 16/3 here: below it the ramps outlast the period.
    s = 1 / BASE["a2"] + 1 / BASE["a3"]
    j_p = (s * max(BASE["a2"], BASE["a3"]) ** 2 + BASE["a2"] + BASE["a3"]) / BASE["period"]
    assert j_p == pytest.approx(16 / 3)
    r = sa.solve_jerk_limited_three_phase(sa.JerkLimitedThreePhaseParameters(**BASE, jerk=5.0))
    assert not r.physical
    assert r.reason == sa.JerkLimitedCase0.ramps_exceed_period
    assert r.min_jerk >= j_p
    with pytest.raises(sa.InvalidParameter) as info:
        jerk_limited(5.0)
    assert info.value.name == "jerk"
    # No jerk helps when the jump profile is case 0 (1/a2 + 1/a3 > Δt^2/(8Δy)).
    r = sa.solve_jerk_limited_three_phase(
        sa.JerkLimitedThreePhaseParameters(period=1.0, stroke=0.084, a2=1.0, a3=1.0, jerk=5.0)
    )
    assert r.reason == sa.JerkLimitedCase0.accelerations_too_low and math.isinf(r.min_jerk)


def test_infinite_jerk_is_the_three_phase_profile():
    jump = sa.ThreePhaseProfile(**BASE)
    limited = jerk_limited(math.inf)
    t = np.linspace(0.0, 2 * BASE["period"], 1001)
    for a, b in zip(limited.sample(t), jump.sample(t)):
        np.testing.assert_array_equal(a, b)
    params = eval(repr(limited.parameters), vars(sa))  # the repr evaluates back (inf included)
    assert math.isinf(params.jerk) and params.a2 == BASE["a2"]


def test_steady_velocity_tends_to_the_jump_profiles_like_one_over_jerk():
    v_inf = sa.steady_state(sa.ThreePhaseProfile(**BASE)).v_bar
    errors = [abs(sa.steady_state(jerk_limited(j)).v_bar - v_inf) for j in (1e2, 1e3, 1e4)]
    for coarse, fine in zip(errors, errors[1:]):
        assert 8.0 <= coarse / fine <= 12.0, errors


# ---- friction field and footprint ------------------------------------------------------------


def test_step_field_under_a_uniform_footprint_is_the_two_region_table():
    field = sa.FrictionField.steps([0.5], [1.0, 2.5])
    two = sa.two_region_friction(0.5, 0.05, 2.5)
    x = np.linspace(0.3, 0.7, 40_001)
    for footprint in (0.05, sa.UniformFootprint(0.05)):
        friction = sa.FieldFriction(field, footprint)
        np.testing.assert_allclose(friction.bound(x), two.bound(x), rtol=1e-14, atol=1e-14)
        assert friction.footprint == sa.UniformFootprint(0.05)
        for key, values in two.pieces().items():
            np.testing.assert_allclose(friction.pieces()[key], values, rtol=1e-14)


def test_field_values_nodes_and_integral_by_hand():
    field = sa.FrictionField.steps([0.5], [1.0, 2.5])
    assert field(0.49) == 1.0 and field(0.5) == 2.5  # right-continuous
    assert field(np.array([[0.0, 1.0]])).tolist() == [[1.0, 2.5]]
    assert field.integral(0.0, 1.0) == pytest.approx(0.5 * 1.0 + 0.5 * 2.5)
    assert field.piecewise_constant and (field.min_level, field.max_level) == (1.0, 2.5)
    nodes = field.nodes()
    assert nodes["position"].tolist() == [0.5]
    assert (nodes["left"].tolist(), nodes["right"].tolist()) == ([1.0], [2.5])
    ramp = sa.FrictionField.ramps([0.0, 1.0], [1.0, 3.0])
    assert ramp(0.25) == pytest.approx(1.5) and not ramp.piecewise_constant
    assert ramp.integral(0.0, 1.0) == pytest.approx(2.0)
    assert ramp == sa.FrictionField([0.0, 1.0], [1.0, 3.0], [1.0, 3.0])
    # A point footprint reads the field itself.
    point = sa.FieldFriction(ramp, sa.PointFootprint())
    x = np.linspace(-1.0, 2.0, 301)
    np.testing.assert_array_equal(point.bound(x), ramp(x))
    # A uniform footprint on ramps is piecewise quadratic: no affine pieces.
    assert sa.FieldFriction(ramp, 0.1).pieces() is None


def test_field_from_csv_matches_the_factory(tmp_path):
    csv = tmp_path / "field.csv"
    csv.write_text("position,level\n# comment\n0.0,1.0\n0.5,2.5\n")
    assert sa.FrictionField.from_csv(csv, "steps") == sa.FrictionField.steps([0.5], [1.0, 2.5])
    linear = sa.FrictionField.from_csv(str(csv), "linear")
    assert linear == sa.FrictionField.ramps([0.0, 0.5], [1.0, 2.5])
    csv.write_text("position,level\n0.0,1.0\n0.5,-0.2\n")
    with pytest.raises(sa.InvalidParameter, match="field.csv:3"):
        sa.FrictionField.from_csv(csv)


def test_stopping_on_a_field_is_the_stop_on_the_two_region_table():
    profile = sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=3.0, a3=0.9)
    law = sa.FrictionLaw(1.2, 1.0)
    start = sa.ObjectState(0.0, 0.3, 0.0)
    field = sa.FieldFriction(sa.FrictionField.steps([0.5], [1.0, 2.5]), 0.05)
    on_field = sa.stopping_run(profile, field, start, law=law)
    on_two = sa.stopping_run(profile, sa.two_region_friction(0.5, 0.05, 2.5), start, law=law)
    assert on_field.kind == sa.StopKind.permanent_stick
    assert on_field.end_position == on_two.end_position
    # eq. (40) with the static coefficient: static m(x) >= max|y''| = 3 from
    # x = 0.5 + 0.05 (3/1.2 - 1)/(2.5 - 1) = 0.55 on.
    assert on_field.end_position >= 0.55 - 1e-15


# ---- period map ------------------------------------------------------------------------------


def test_period_map_monodromy_by_saltation_matches_finite_differences():
    law = sa.FrictionLaw(1.3, 1.0)
    profile = jerk_limited(30.0)
    steady = sa.steady_state(profile, law)
    assert steady.converged
    period_map = sa.PeriodMap(profile, law)
    assert period_map.method == sa.Method.exact and period_map.period == BASE["period"]
    end = period_map(0.0, steady.x_dot_0s)
    assert end.t == BASE["period"]
    assert end.xd == pytest.approx(steady.x_dot_0s, abs=1e-12)  # the steady state is fixed
    saltation = period_map.saltation_monodromy(0.0, steady.x_dot_0s)
    differences = period_map.finite_difference_monodromy(0.0, steady.x_dot_0s, h=1e-7)
    assert saltation.shape == differences.shape == (2, 2)
    np.testing.assert_allclose(saltation, differences, atol=1e-6)
    # Uniform table: a shift in x shifts the image (first column [1, 0]).
    np.testing.assert_allclose(saltation[:, 0], [1.0, 0.0], atol=1e-12)


def test_period_map_arcs_are_the_exact_solvers_arcs():
    profile = jerk_limited(300.0)
    period_map = sa.PeriodMap(profile, sa.UniformFriction())
    arcs = period_map.arcs(0.0, 0.05)
    reference = sa.exact_arcs(profile, sa.UniformFriction(), sa.ObjectState(0.0, 0.0, 0.05),
                              duration=BASE["period"])
    assert arcs.keys() == reference.keys()
    for key in arcs:
        np.testing.assert_array_equal(arcs[key], reference[key])
    np.testing.assert_array_equal(arcs["t0"][1:], arcs["t1"][:-1])  # a chain over the period
    assert arcs["t1"][-1] == BASE["period"]


def test_period_map_keeps_its_profile_and_friction_alive():
    period_map = sa.PeriodMap(
        sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=3.0, a3=0.9),
        sa.FieldFriction(sa.FrictionField.steps([0.5], [1.0, 2.5]), 0.05),
        sa.FrictionLaw(1.2, 1.0),
    )
    gc.collect()
    before = period_map(0.3, 0.0)
    assert isinstance(period_map.friction, sa.FieldFriction)
    assert period_map.profile.kind == "three-phase"
    assert period_map(0.3, 0.0).x == before.x


def test_period_map_integrates_what_the_exact_solvers_cannot_take():
    # A Fourier profile is exact on the transition region's slope too (issue 11); a Stribeck
    # law is not: there the map takes the slip integrator (no arcs, no step).
    period_map = sa.PeriodMap(sa.FourierProfile(1.0, [0.05], [0.0]),
                              sa.two_region_friction(0.5, 0.05, 2.5), steps_per_period=200)
    assert period_map.method == sa.Method.exact
    assert len(period_map.arcs(0.49, 0.05)) > 0
    stribeck = sa.PeriodMap(sa.FourierProfile(1.0, [0.05], [0.0]),
                            sa.two_region_friction(0.5, 0.05, 2.5),
                            sa.FrictionLaw(1.2, 1.0).with_stribeck(0.01), steps_per_period=200)
    assert stribeck.method == sa.Method.integrator
    assert stribeck.step == 0.0
    assert stribeck.finite_difference_monodromy(0.0, 0.0, 1e-6).shape == (2, 2)
    with pytest.raises(sa.InvalidParameter):
        stribeck.arcs(0.0, 0.0)


# ---- static > kinetic: the hand-derived two-level steady states ------------------------------


@pytest.mark.parametrize(
    "static, v_bar",
    [(1.6, -3.0 / 35.0), (2.5, -3.0 / 35.0), (1.2, -1.0 / 168.0)],  # sets S5, S6, S4
)
def test_two_level_steady_state_matches_the_hand_derivation(static, v_bar):
    profile = sa.PiecewisePolynomialProfile.from_accelerations(*TWO_LEVEL)
    steady = sa.steady_state(profile, sa.FrictionLaw(static, 1.0))
    assert steady.converged
    assert steady.v_bar == pytest.approx(v_bar, abs=1e-12)


# ---- sweeps take the law and the jerk --------------------------------------------------------


def test_sweeps_take_the_law_and_the_jerk():
    law = sa.FrictionLaw(1.3, 1.0)
    a2, a3 = [2.5, 4.0], [1.5, 2.2]
    grid = sa.sweep_accelerations(BASE["period"], BASE["stroke"], a2, a3, law=law, jerk=300.0,
                                  threads=1)
    for i, x in enumerate(a2):
        for j, y in enumerate(a3):
            profile = sa.JerkLimitedThreePhaseProfile(BASE["period"], BASE["stroke"], x, y, 300.0)
            assert grid["v_bar"][i, j] == sa.steady_state(profile, law).v_bar
    family = sa.JerkLimitedThreePhaseFamily(2.5, 1.5, 30.0)
    points = sa.sweep_period(family, BASE["stroke"], [0.5, 2.0], law=law, threads=1)
    # Δt = 0.5: 1/a2 + 1/a3 = 16/15 > Δt^2/(8 Δy) = 5/16, case 0 for any jerk.
    assert points["physical"].tolist() == [False, True]
    assert points["v_bar"][1] == sa.steady_state(jerk_limited(30.0), law).v_bar
    assert family.make(0.5, BASE["stroke"]) is None
    assert isinstance(family.make(2.0, BASE["stroke"]), sa.JerkLimitedThreePhaseProfile)


# ---- misuse ----------------------------------------------------------------------------------


def test_kinetic_above_static_names_both_coefficients():
    with pytest.raises(sa.InvalidParameter) as info:
        sa.FrictionLaw(1.0, 1.2)
    assert "static" in info.value.name and "kinetic" in info.value.name


@pytest.mark.parametrize("jerk", [-1.0, 0.0, math.nan])
def test_bad_jerk_is_named(jerk):
    with pytest.raises(sa.InvalidParameter) as info:
        jerk_limited(jerk)
    assert info.value.name == "jerk"
    with pytest.raises(sa.InvalidParameter) as info:
        sa.sweep_accelerations(1.0, 0.084, [3.0], [0.9], jerk=jerk)
    assert info.value.name == "jerk"


def test_unsorted_field_positions_are_named():
    with pytest.raises(sa.InvalidParameter) as info:
        sa.FrictionField.steps([0.5, 0.2], [1.0, 2.0, 3.0])
    assert info.value.name == "friction field positions[1]"
    with pytest.raises(sa.InvalidParameter) as info:
        sa.FrictionField.steps([0.5], [1.0])  # one level too few
    assert info.value.name == "friction field levels"


def test_bad_footprints_and_period_map_arguments():
    field = sa.FrictionField.steps([0.5], [1.0, 2.5])
    with pytest.raises(sa.InvalidParameter) as info:
        sa.FieldFriction(field, -1.0)
    assert info.value.name == "footprint width"
    with pytest.raises(TypeError):
        sa.FieldFriction(field, "wide")
    period_map = sa.PeriodMap(sa.ThreePhaseProfile(**BASE))
    with pytest.raises(sa.InvalidParameter) as info:
        period_map(math.nan, 0.0)
    assert info.value.name == "x0"
    with pytest.raises(sa.InvalidParameter) as info:
        period_map.finite_difference_monodromy(0.0, 0.0, h=0.0)
    assert info.value.name == "h"
