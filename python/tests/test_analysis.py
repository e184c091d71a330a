"""Motion cases (Table 1, Fig. 8), steady state (eqs. 10, 11, 15-24), Floquet multipliers
(eqs. 25-33) and velocity convergence (eqs. 35, 36)."""

import itertools
import math

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL, PERIOD, STROKE, case1_mean_velocity, fig8_case

# A slip-slip (case 4) profile: short period, high accelerations (fig8_case checks it).
SLIP_SLIP = dict(period=0.3, stroke=STROKE, a2=20.0, a3=30.0)
# Central differences of the exact period map, which is affine near a slip-slip response:
# no truncation error, rounding ~1e-16/1e-6; 1e-8 leaves headroom.
PERIOD_MAP_FD_TOL = 1e-8


@pytest.mark.parametrize("a2, a3", list(itertools.product(
    [0.5, 0.95, 1.2, 2.0, 3.0, 6.0, 15.0, 40.0], [0.5, 0.9, 1.1, 2.5, 8.0, 30.0])))
@pytest.mark.parametrize("period", [0.3, 1.0])
def test_predict_case_follows_the_fig8_rules(period, a2, a3):
    p = sa.ThreePhaseParameters(period, STROKE, a2, a3)
    assert sa.predict_case(p) == fig8_case(period, STROKE, a2, a3)


def test_describe_gives_table_1():
    assert sa.describe(sa.StickSlipCase.slip_slip) == sa.describe(4)
    assert "x' >= 0" in sa.describe(sa.StickSlipCase.stick_slip_forward)
    assert len({sa.describe(c) for c in sa.StickSlipCase}) == 6


@pytest.mark.parametrize("a2, a3", [(3.0, 0.9), (2.5, 0.95), (6.0, 1.0)])
def test_case1_mean_velocity_is_the_closed_form(a2, a3):
    profile = sa.ThreePhaseProfile(period=PERIOD, stroke=STROKE, a2=a2, a3=a3)
    s = sa.steady_state(profile)
    assert s.converged and s.method == sa.Method.exact
    assert s.motion_case == sa.StickSlipCase.stick_slip_forward
    assert s.x_dot_0s == 0.0  # stuck at t0 (Sect. 5.1)
    v_bar = case1_mean_velocity(PERIOD, STROKE, a2, a3)
    assert s.v_bar == pytest.approx(v_bar, rel=CLOSED_FORM_TOL)  # eq. (10)
    assert s.f == pytest.approx(1.0 / (1e4 * v_bar**2), rel=CLOSED_FORM_TOL)  # eq. (11)
    assert s.displacement == pytest.approx(v_bar * PERIOD, rel=CLOSED_FORM_TOL)


def test_pure_stick_has_zero_velocity_and_infinite_objective():
    s = sa.steady_state(sa.ThreePhaseProfile(period=2.0, stroke=STROKE, a2=0.9, a3=0.9))
    assert s.motion_case == sa.StickSlipCase.pure_stick
    assert s.v_bar == 0.0 and math.isinf(s.f) and s.f > 0


def test_objective_is_eq_11_elementwise():
    v = np.array([[0.0, 0.01], [0.1, -0.2]])
    f = sa.objective_f(v)
    assert f.shape == v.shape
    with np.errstate(divide="ignore"):
        np.testing.assert_allclose(f, 1.0 / (sa.OBJECTIVE_SCALE * v**2), rtol=CLOSED_FORM_TOL)
    assert sa.OBJECTIVE_SCALE == 1e4
    assert sa.objective_f(0.5, c=2.0) == pytest.approx(2.0)


def test_fourier_steady_state_is_exact_and_a_pure_harmonic_walks_nowhere():
    # Since issue 11 a Fourier profile on the uniform table takes the exact smooth-profile
    # solver. A single harmonic is odd under t -> t + Δt/2 (y'' changes sign), so its unique
    # steady state has v̄ = 0 (docs/single-harmonic-steady-state.md): peak y'' = 0.05 (2π)^2
    # = 1.97 > 1, so it does slip, both ways alike.
    s = sa.steady_state(sa.FourierProfile(1.0, [0.0], [0.05]),
                        sa.SteadyStateOptions(steps_per_period=2000))
    assert s.method == sa.Method.exact
    assert s.converged
    assert abs(s.v_bar) < 1e-13


def test_slip_slip_multiplier_formula_eq_33():
    a2 = np.array([2.0, 3.0, 20.0])
    a3 = np.array([[1.5], [30.0]])
    expected = (a2 - 1) * (a3 - 1) / ((a2 + 1) * (a3 + 1))
    got = sa.slip_slip_multiplier(a2, a3)
    assert got.shape == (2, 3)
    np.testing.assert_allclose(got, expected, rtol=CLOSED_FORM_TOL)
    assert sa.slip_slip_multiplier(20.0, 30.0) == pytest.approx(19 * 29 / (21 * 31))


def period_map(profile, v):
    """P(v) = x'(t0 + Δt) from x'(t0) = v on the uniform table, by simulate()."""
    run = sa.simulate(profile, sa.UniformFriction(), sa.ObjectState(0.0, 0.0, v),
                      sa.SimulationOptions(duration=profile.period, record=False))
    return run.final_state.xd


def test_slip_slip_floquet_multipliers():
    assert fig8_case(**SLIP_SLIP) == 4
    profile = sa.ThreePhaseProfile(**SLIP_SLIP)
    fl = sa.floquet_multipliers(profile)
    assert fl.steady.motion_case == sa.StickSlipCase.slip_slip
    lam2 = (SLIP_SLIP["a2"] - 1) * (SLIP_SLIP["a3"] - 1) / (
        (SLIP_SLIP["a2"] + 1) * (SLIP_SLIP["a3"] + 1))
    for mono in (fl.analytic, fl.saltation, fl.finite_difference):
        assert mono.available
        assert mono.matrix.shape == (2, 2) and mono.matrix.dtype == np.float64
        assert mono.multipliers.shape == (2,) and mono.multipliers.dtype == np.complex128
        np.testing.assert_allclose(mono.multipliers, [1.0, lam2], atol=1e-6)
    # Analytic Φ = [[1, m12], [0, λ2]] (eq. 33).
    assert fl.analytic.matrix[1, 0] == 0.0 and fl.analytic.matrix[0, 0] == 1.0
    assert fl.analytic.matrix[1, 1] == pytest.approx(lam2, rel=CLOSED_FORM_TOL)
    # A second method: the slope of the period map, by central differences of simulate().
    v, dv = fl.steady.x_dot_0s, 1e-6
    slope = (period_map(profile, v + dv) - period_map(profile, v - dv)) / (2 * dv)
    assert slope == pytest.approx(lam2, abs=PERIOD_MAP_FD_TOL)
    assert fl.spread < 1e-6


def test_sticking_response_has_multipliers_one_and_zero(case1_profile):
    fl = sa.floquet_multipliers(case1_profile)
    np.testing.assert_array_equal(fl.analytic.matrix, [[1.0, 0.0], [0.0, 0.0]])  # eq. (30)
    np.testing.assert_allclose(fl.saltation.multipliers, [1.0, 0.0], atol=1e-9)


def test_floquet_without_three_phase_parameters_has_no_analytic_matrix():
    profile = sa.ScaledShapeFamily.paper_like().make(1.0, STROKE)
    fl = sa.floquet_multipliers(profile)
    assert not fl.analytic.available and fl.saltation.available


def test_make_monodromy_matches_numpy():
    m = np.array([[0.5, 2.0], [-1.0, 0.3]])
    mono = sa.make_monodromy(m)
    np.testing.assert_array_equal(mono.matrix, m)
    expected = sorted(np.linalg.eigvals(m), key=abs, reverse=True)
    np.testing.assert_allclose(sorted(mono.multipliers, key=abs, reverse=True), expected,
                               rtol=1e-12)
    with pytest.raises(sa.InvalidParameter):
        sa.make_monodromy(np.eye(3))


@pytest.mark.parametrize("params", [dict(period=PERIOD, stroke=STROKE, a2=3.0, a3=0.9),
                                    SLIP_SLIP])
def test_velocity_convergence_lyapunov_function(params):
    profile = sa.ThreePhaseProfile(**params)
    c = sa.velocity_convergence(profile, sa.ConvergenceOptions(v1=0.5, v2=-0.5, duration=5.0))
    n = len(c.t)
    for a in (c.t, c.v1, c.v2, c.lyapunov):
        assert a.shape == (n,) and a.dtype == np.float64
    np.testing.assert_allclose(c.lyapunov, 0.5 * (c.v1 - c.v2) ** 2, rtol=1e-12, atol=1e-15)
    # eq. (36): V never increases.
    assert np.all(np.diff(c.lyapunov) <= 1e-12)
    # The intervals tile [t0, t0 + duration], alternating '=' and '≠'.
    iv = c.interval_arrays
    assert iv["t_begin"][0] == 0.0 and iv["t_end"][-1] == 5.0
    np.testing.assert_array_equal(iv["t_begin"][1:], iv["t_end"][:-1])
    assert np.all(iv["same"][1:] != iv["same"][:-1])
    assert [i.same for i in c.intervals] == list(iv["same"])
    # V is constant on '=' intervals (both slip the same way).
    for b, e, same in zip(iv["t_begin"], iv["t_end"], iv["same"]):
        inside = (c.t >= b) & (c.t <= e)
        if same and inside.sum() > 1:
            assert np.ptp(c.lyapunov[inside]) <= 1e-12 * max(1.0, c.lyapunov[inside].max())


def test_sticking_responses_coincide_after_a_common_stick(case1_profile):
    c = sa.velocity_convergence(case1_profile)
    assert c.t_coincide is not None
    after = c.t >= c.t_coincide
    np.testing.assert_array_equal(c.v1[after], c.v2[after])
    slip_slip = sa.velocity_convergence(sa.ThreePhaseProfile(**SLIP_SLIP))
    assert slip_slip.t_coincide is None  # case 4 converges only as t -> infinity
