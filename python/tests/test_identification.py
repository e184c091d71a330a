"""identify() (issue 25; docs/identification.md) from Python, and its second method: the same
multiple-shooting fit written here with scipy.optimize.least_squares over the library's
single-run simulate() (the scaling of Sect. 3.2 done by hand), which must agree with the C++
estimate to 1 % of its standard error."""

import math

import numpy as np
import pytest
import scipy.optimize

import selfalign as sa

# The finite-jerk run of tests/test_identification.cpp: 20 Hz, the paper's Sect. 7.2 profile in
# SI with mu = 0.3 (a2 = 2.3 mu g, a3 = 1.3 mu g), jerk limit 800 m/s^3, mu_static = 0.36.
L, G = 1e-3, 9.81
PERIOD, STROKE, A2, A3, JERK = 0.05, 6.2e-4, 6.77, 3.83, 800.0
MU, MU_STATIC = 0.3, 0.36
NOISE, OFFSET, RATE = 2e-6, 3e-3, 2000.0


def config(mu=MU, mu_static=MU_STATIC):
    return dict(units="si", profile="three-phase", period=PERIOD, stroke=STROKE, a2=A2, a3=A3,
                jerk=JERK, friction="uniform", mu=mu, mu_static=mu_static, g=G, length_scale=L)


def model(mu, mu_static):
    """The model in Sect. 3.2's units by hand: T = sqrt(L / (mu g)), accelerations / (mu g)."""
    T = math.sqrt(L / (mu * G))
    a = mu * G
    profile = sa.JerkLimitedThreePhaseProfile(PERIOD / T, STROKE / L, A2 / a, A3 / a, JERK / (a / T))
    return T, profile, sa.FrictionLaw(mu_static / mu, 1.0)


def synthesize(seed, periods=20):
    T, profile, law = model(MU, MU_STATIC)
    opts = sa.SimulationOptions(duration=periods * PERIOD / T, output_step=1 / RATE / T)
    run = sa.simulate(profile, sa.UniformFriction(1.0), sa.ObjectState(0, 0, 0), opts, law=law)
    t = np.asarray(run.trajectory.t)[:-1] * T
    x = np.asarray(run.trajectory.x)[:-1] * L
    rng = np.random.default_rng(seed)
    return {"t": t - OFFSET, "x": x + rng.normal(0, NOISE, x.size), "source": f"seed{seed}"}


def residuals(p, data, windows):
    """x_model - x_data, each window from its own state (x_k, v_k) at its first sample."""
    mu, mu_static, tau = p[:3]
    T, profile, law = model(mu, mu_static)
    friction = sa.UniformFriction(1.0)
    out = []
    for k, idx in enumerate(windows):
        t = data["t"][idx]
        xk, vk = p[3 + 2 * k], p[4 + 2 * k]
        dt = t[1] - t[0]
        start = sa.ObjectState((t[0] + tau) / T, xk / L, vk / (L / T))
        opts = sa.SimulationOptions(duration=(t[-1] - t[0]) / T, output_step=dt / T)
        run = sa.simulate(profile, friction, start, opts, law=law)
        x = np.asarray(run.trajectory.x)[: idx.size] * L
        out.append(x - data["x"][idx])
    return np.concatenate(out)


def test_scipy_least_squares_agrees_with_the_library_to_one_percent_of_its_standard_error():
    data = synthesize(5)
    start = config(mu=0.31, mu_static=0.34)
    r = sa.identify(data, start, ["mu", "mu_static", "time_offset"], starts=0, profile=[])
    assert r.converged
    # The windows are the library's partition of the samples (a layout, not a result).
    w = r.runs[0]["window"]
    windows = [np.flatnonzero(w == k) for k in range(w.max() + 1)]
    # scipy starts from the same parameters and from states read off the data (first sample,
    # a difference of the first two).
    p0 = [0.31, 0.34, 0.0]
    for idx in windows:
        t, x = data["t"][idx], data["x"][idx]
        p0 += [x[0], (x[4] - x[0]) / (t[4] - t[0])]
    lower = [0.31 * 0.7, 0.34 * 0.7, -PERIOD / 2] + [-np.inf] * (2 * len(windows))
    upper = [0.31 * 1.3, 0.34 * 1.3, PERIOD / 2] + [np.inf] * (2 * len(windows))
    fit = scipy.optimize.least_squares(residuals, p0, args=(data, windows), bounds=(lower, upper),
                                       x_scale="jac", diff_step=1e-7, xtol=1e-15, ftol=1e-15,
                                       gtol=1e-15, max_nfev=400)
    n, m = fit.fun.size, fit.x.size
    sigma2 = fit.fun @ fit.fun / (n - m)
    cov = np.linalg.pinv(fit.jac.T @ fit.jac) * sigma2
    se_scipy = np.sqrt(np.diag(cov)[:2])
    est = r.estimates
    se = r.standard_errors
    print("library", est, se, "scipy", fit.x[:2], se_scipy, "offset", fit.x[2],
          r.runs[0]["time_offset"])
    np.testing.assert_array_less(np.abs(fit.x[:2] - est), 0.01 * se)
    assert abs(fit.x[2] - r.runs[0]["time_offset"]) < 0.01 * r.runs[0]["time_offset_standard_error"]
    # The standard errors from scipy's own Jacobian agree to 10 %.
    np.testing.assert_allclose(se_scipy, se, rtol=0.1)
    # Both recover the truth.
    assert abs(est[0] - MU) < 4 * se[0] and abs(est[1] - MU_STATIC) < 4 * se[1]


def test_result_arrays_report_and_uncertainty_text():
    data = synthesize(6)
    r = sa.identify([data], [config(mu=0.31, mu_static=0.34)], ["mu", "mu_static", "time_offset"],
                    starts=0, profile=["mu"], profile_points=5)
    assert r.names == ["mu", "mu_static"]
    assert r.estimates.shape == (2,) and r.covariance.shape == (2, 2)
    assert r.intervals.shape == (2, 2) and np.all(r.intervals[:, 0] < r.intervals[:, 1])
    np.testing.assert_allclose(np.diag(r.correlation), 1.0)
    assert r.identifiable.dtype == np.bool_ and r.identifiable.all()
    run = r.runs[0]
    assert run["t"].size == run["x_fitted"].size == run["residual"].size == data["t"].size
    np.testing.assert_allclose(run["residual"], run["x_fitted"] - run["x_measured"], atol=1e-15)
    assert abs(run["residual"].std() - NOISE) < 0.2 * NOISE
    assert len(r.profiles) == 1 and r.profiles[0]["values"].size == 5
    lo, hi = r.profile_intervals[0]
    assert lo < r.estimates[0] < hi
    rep = r.report()
    assert rep["parameters"][0]["name"] == "mu"
    assert rep["residuals"]["samples"] == data["t"].size
    text = r.uncertainty_text(0.31)
    assert text.count('"normal:') == 2 and "static_ratio" in text


def test_mu_static_of_a_part_that_never_sticks_is_none_of_a_number():
    fast = dict(config(), stroke=STROKE * 10, a2=A2 * 10, a3=A3 * 10, jerk=JERK * 10)
    T, profile, law = model(MU, MU_STATIC)
    profile = sa.JerkLimitedThreePhaseProfile(PERIOD / T, 10 * STROKE / L,
                                              10 * A2 / (MU * G), 10 * A3 / (MU * G),
                                              10 * JERK / (MU * G / T))
    opts = sa.SimulationOptions(duration=20 * PERIOD / T, output_step=1 / RATE / T)
    run = sa.simulate(profile, sa.UniformFriction(1.0), sa.ObjectState(0, 0, 0), opts, law=law)
    t = np.asarray(run.trajectory.t)[:-1] * T
    x = np.asarray(run.trajectory.x)[:-1] * L
    keep = t >= 2 * PERIOD  # the start from rest dropped
    rng = np.random.default_rng(1)
    data = {"t": t[keep], "x": x[keep] + rng.normal(0, NOISE, keep.sum())}
    r = sa.identify(data, dict(fast, mu_static=0.34), ["mu", "mu_static"], starts=0, profile=[])
    assert not r.identifiable[1] and math.isnan(r.estimates[1]) and "never sticks" in r.reasons[1]
    assert r.report()["parameters"][1]["estimate"] is None
    assert any("mu_static" in w for w in r.warnings)


def test_bad_input_names_the_parameter(tmp_path):
    data = synthesize(1, periods=2)
    with pytest.raises(sa.InvalidParameter, match="friction_coefficient"):
        sa.identify(data, config(), ["friction_coefficient"], starts=0)
    with pytest.raises(sa.InvalidParameter, match="samples"):
        sa.identify({"t": data["t"][:2], "x": data["x"][:2]}, config(), ["mu"], starts=0)
    bad = {"t": data["t"][::-1].copy(), "x": data["x"]}
    with pytest.raises(sa.InvalidParameter, match="time strictly increasing"):
        sa.identify(bad, config(), ["mu"], starts=0)
    before = sorted(p.name for p in tmp_path.iterdir())
    (tmp_path / "run.csv").write_text("frame,x\n1,0.0\n2,0.1\n")
    with pytest.raises(sa.InvalidParameter, match="run.csv"):
        sa.identify(str(tmp_path / "run.csv"), config(), ["mu"], starts=0)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(before + ["run.csv"])


def test_identification_figure_from_the_fit_csv(tmp_path):
    import subprocess
    import sys
    data = synthesize(2, periods=6)
    r = sa.identify(data, config(mu=0.31, mu_static=0.34), ["mu", "mu_static", "time_offset"],
                    starts=0, profile=[])
    run = r.runs[0]
    csv = tmp_path / "fit.csv"
    with open(csv, "w") as f:
        f.write("run,t,x_measured,x_fitted,residual,window,stick\n")
        for i in range(run["t"].size):
            f.write(f"0,{run['t'][i]!r},{run['x_measured'][i]!r},{run['x_fitted'][i]!r},"
                    f"{run['residual'][i]!r},{run['window'][i]},{int(run['stick'][i])}\n")
    png = tmp_path / "fit.png"
    cmd = [sys.executable, "-m", "selfalign", "identification-figure"]
    done = subprocess.run(cmd + [str(csv), str(png)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # Bad input: one line, exit 2, nothing written.
    bad = subprocess.run(cmd + [str(tmp_path / "none.csv"), str(tmp_path / "x.png")],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and len(bad.stderr.splitlines()) == 1 and "none.csv" in bad.stderr
    assert not (tmp_path / "x.png").exists()
