"""Table profiles: the three-phase closed form and constraints (Sect. 4.4.3, Appendix),
piecewise-constant sequences, Fourier series (Sect. 4.4.2), sampled CSV profiles, and the
vectorised sample()."""

import math

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL, PERIOD, STROKE, three_phase_times

# Numerical integration over a grid that contains every acceleration switch: the left
# Riemann sum of a right-continuous piecewise-constant y'' and the trapezoidal rule on the
# piecewise-linear y' are exact, so only rounding over 2e5 summands remains (~1e-13);
# 1e-9 leaves a wide margin.
INTEGRATION_TOL = 1e-9


def fine_grid(profile, n=200_001):
    t = np.linspace(0.0, profile.period, n)
    switches = []
    pwc = profile.piecewise_constant()
    if pwc is not None:
        switches = list(pwc.segments()["begin"])
    return np.unique(np.concatenate([t, switches]))


def cumulative_trapezoid(f, t):
    return np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))])


def cumulative_left_sum(f, t):
    return np.concatenate([[0.0], np.cumsum(f[:-1] * np.diff(t))])


@pytest.mark.parametrize("a2, a3", [(3.0, 0.9), (1.8, 1.1), (12.0, 4.0), (2.5, 1.0)])
def test_three_phase_solution_is_the_closed_form(a2, a3):
    r = sa.solve_three_phase(sa.ThreePhaseParameters(PERIOD, STROKE, a2, a3))
    t1, t2, yd_ini, y_ini = three_phase_times(PERIOD, STROKE, a2, a3)
    assert r.physical
    assert r.t1 == pytest.approx(t1, rel=CLOSED_FORM_TOL)
    assert r.t2 == pytest.approx(t2, rel=CLOSED_FORM_TOL)
    assert r.t3 == PERIOD
    assert r.yd_ini == pytest.approx(yd_ini, rel=CLOSED_FORM_TOL)
    assert r.y_ini == pytest.approx(y_ini, rel=CLOSED_FORM_TOL)
    assert r.inverse_accel_sum == pytest.approx(1 / a2 + 1 / a3, rel=CLOSED_FORM_TOL)
    assert r.inverse_accel_limit == pytest.approx(PERIOD**2 / (8 * STROKE), rel=CLOSED_FORM_TOL)


def test_case_zero_is_exactly_beyond_the_limit():
    limit = PERIOD**2 / (8 * STROKE)  # 1/a2 + 1/a3 <= Δt^2/(8 Δy)
    a = 2.0 / limit  # 1/a + 1/a = limit: just physical
    assert sa.solve_three_phase(sa.ThreePhaseParameters(PERIOD, STROKE, a * 1.001, a * 1.001)).physical
    assert not sa.solve_three_phase(sa.ThreePhaseParameters(PERIOD, STROKE, a * 0.999, a * 0.999)).physical


@pytest.mark.parametrize("a2, a3", [(3.0, 0.9), (1.8, 1.1), (12.0, 4.0)])
def test_three_phase_profile_satisfies_the_appendix_constraints(a2, a3):
    profile = sa.ThreePhaseProfile(period=PERIOD, stroke=STROKE, a2=a2, a3=a3)
    t = fine_grid(profile)
    y, yd, ydd = profile.sample(t)
    # Constraint 7 and the two free accelerations: y'' = 0, -a2, +a3 on the three intervals.
    sol = profile.solution
    assert set(np.unique(ydd[:-1])) == {0.0, -a2, a3}
    assert np.all(ydd[t < sol.t1] == 0.0)
    # y' and y are the integrals of y'' and y' (consistency of sample()).
    np.testing.assert_allclose(yd, yd[0] + cumulative_left_sum(ydd, t), atol=INTEGRATION_TOL)
    np.testing.assert_allclose(y, y[0] + cumulative_trapezoid(yd, t), atol=INTEGRATION_TOL)
    # Constraints 5, 6: periodic y and y' (the integrals over a period vanish).
    assert y[-1] == pytest.approx(y[0], abs=INTEGRATION_TOL)
    assert yd[-1] == pytest.approx(yd[0], abs=INTEGRATION_TOL)
    assert np.trapz(yd, t) == pytest.approx(0.0, abs=INTEGRATION_TOL)
    # Constraints 1, 4: min y = 0 and stroke Δy.
    assert y.min() == pytest.approx(0.0, abs=INTEGRATION_TOL)
    assert y.max() - y.min() == pytest.approx(STROKE, abs=INTEGRATION_TOL)
    assert profile.stroke == pytest.approx(STROKE, rel=CLOSED_FORM_TOL)
    assert profile.peak_acceleration == max(a2, a3)


def test_sample_extends_periodically_and_keeps_shapes(case1_profile):
    t = np.linspace(-2.0, 3.0, 60).reshape(3, 4, 5)
    y, yd, ydd = case1_profile.sample(t)
    for a in (y, yd, ydd):
        assert a.shape == t.shape and a.dtype == np.float64
    y2, yd2, ydd2 = case1_profile.sample(t + 3 * PERIOD)
    np.testing.assert_allclose(y2, y, atol=1e-12)
    np.testing.assert_allclose(yd2, yd, atol=1e-12)
    s = case1_profile.state(0.4)
    assert case1_profile.sample(0.4) == (s.y, s.yd, s.ydd)
    np.testing.assert_array_equal(case1_profile.velocity(t), yd)


def test_piecewise_constant_segments_reproduce_the_accelerations():
    durations, accels = [0.2, 0.3, 0.5], [1.0, -2.0, 0.8]  # 0.2 - 0.6 + 0.4 = 0
    p = sa.PiecewisePolynomialProfile.from_accelerations(durations, accels)
    seg = p.segments()
    np.testing.assert_allclose(seg["begin"], [0.0, 0.2, 0.5], atol=CLOSED_FORM_TOL)
    np.testing.assert_array_equal(seg["accel"], accels)
    assert p.period == pytest.approx(1.0)
    assert p.kind == "quadratic-sequence"
    assert p.piecewise_constant() is p
    assert p.segment_at(0.25) == 1
    assert p.phase(2.7) == pytest.approx(0.7)
    # Zero-mean velocity: y periodic.
    t = fine_grid(p)
    _, yd, _ = p.sample(t)
    assert np.trapz(yd, t) == pytest.approx(0.0, abs=INTEGRATION_TOL)


def test_piecewise_constant_velocity_must_return():
    with pytest.raises(sa.InvalidParameter):
        sa.PiecewisePolynomialProfile.from_accelerations([0.5, 0.5], [1.0, -0.5])


def test_fourier_profile_is_the_series_shifted_to_min_zero():
    A, B = [0.02, 0.0, 0.004], [0.03, 0.01]
    p = sa.FourierProfile(2.0, A, B)
    w = 2 * math.pi / 2.0
    t = np.linspace(0.0, 2.0, 20_001)
    series = sum(a * np.cos((k + 1) * w * t) for k, a in enumerate(A)) + sum(
        b * np.sin((k + 1) * w * t) for k, b in enumerate(B))
    y, yd, ydd = p.sample(t)
    np.testing.assert_allclose(y - p.offset, series, atol=1e-14)
    # min over the fine grid is within O(h^2 |y''|) of the exact minimum 0.
    assert y.min() == pytest.approx(0.0, abs=1e-7)
    assert p.order == 3
    np.testing.assert_array_equal(p.cos_coeffs, A)
    np.testing.assert_array_equal(p.sin_coeffs, B + [0.0])
    assert p.piecewise_constant() is None
    dseries = sum(-(k + 1) * w * a * np.sin((k + 1) * w * t) for k, a in enumerate(A)) + sum(
        (k + 1) * w * b * np.cos((k + 1) * w * t) for k, b in enumerate(B))
    np.testing.assert_allclose(yd, dseries, atol=1e-13)


def test_sampled_profiles_from_csv(tmp_path):
    csv = tmp_path / "accel.csv"
    # Zero net velocity change both ways: sum ydd_i Δt_i = 0 (constant) and the trapezoid
    # 0.25 (1 + 0 - 1 + 0) = 0 (linear).
    csv.write_text("t,ydd\n# one period\n0,1\n0.25,1\n0.5,-1\n0.75,-1\n1,1\n")
    samples = sa.read_acceleration_samples(csv)
    np.testing.assert_array_equal(samples.t, [0, 0.25, 0.5, 0.75, 1])
    np.testing.assert_array_equal(samples.ydd, [1, 1, -1, -1, 1])
    assert len(samples) == 5

    constant = sa.make_sampled_profile(samples)  # default: piecewise constant
    assert isinstance(constant, sa.PiecewisePolynomialProfile)
    assert constant.kind == "samples-constant"
    np.testing.assert_array_equal(constant.segments()["accel"], [1, 1, -1, -1])

    linear = sa.make_sampled_profile(samples, "linear")
    assert isinstance(linear, sa.LinearAccelerationProfile)
    assert linear.piecewise_constant() is None
    _, _, ydd = linear.sample(np.array([0.0, 0.125, 0.375, 0.5, 0.875]))
    np.testing.assert_allclose(ydd, [1.0, 1.0, 0.0, -1.0, 0.0], atol=CLOSED_FORM_TOL)


def test_malformed_csv_names_the_file(tmp_path):
    csv = tmp_path / "bad.csv"
    csv.write_text("0,1\n0.5,oops\n")
    with pytest.raises(sa.InvalidParameter) as info:
        sa.read_acceleration_samples(str(csv))
    assert "bad.csv" in str(info.value)
