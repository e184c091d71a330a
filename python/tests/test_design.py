"""design_process from Python: a feasible design meets the limits and its replay settles in
the band at the predicted time (within one table period); infeasible requests explain why."""

import pickle
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import selfalign as sa


def small(**kw):
    return sa.DesignRequest(acceleration_grid=10, period_grid=2, stroke_grid=1, entries=10, **kw)


def test_design_meets_limits_and_replays():
    req = small()
    d = sa.design_process(req, threads=1)
    assert d.feasible, d.message
    assert d.velocity_peak <= req.velocity_max * (1 + 1e-12)
    assert max(d.a2, d.a3) <= req.acceleration_max * (1 + 1e-12)
    assert abs(d.end_position - req.distance) <= d.error_band + 1e-12
    scales = sa.Scales(req.width, req.mu, req.gravity)
    profile = sa.ThreePhaseProfile(d.dimensionless)
    friction = sa.two_region_friction(d.x_mu_dimensionless, 1.0, req.c_mu)
    t_p = scales.time_from_si(d.process_time)
    run = sa.simulate(profile, friction, sa.ObjectState(),
                      sa.SimulationOptions(duration=t_p + 10 * profile.period,
                                           output_step=profile.period / 200))
    tr = run.trajectory
    inside = np.abs(tr.x - scales.length_from_si(d.end_position)) <= scales.length_from_si(d.error_band)
    outside = np.nonzero(~inside)[0]
    settle = tr.t[outside[-1] + 1] if len(outside) else tr.t[0]
    assert abs(settle - t_p) <= profile.period


def test_infeasible_design_names_the_limit():
    d = sa.design_process(small(acceleration_max=2.0))
    assert not d.feasible
    assert "acceleration_max" in d.message


def test_design_misuse_raises():
    with pytest.raises(sa.InvalidParameter) as e:
        sa.design_process(small(width=-1.0))
    assert e.value.name == "width"


def test_absent_coefficients_are_none_and_nan_is_refused():
    """issue 20, D29: a coefficient not given is None (static = kinetic), never NaN; NaN is
    refused naming it, like any other bad number."""
    req = small()
    assert req.mu_static is None and req.mu_backward is None
    assert req.to_dict()["mu_static"] is None
    again = pickle.loads(pickle.dumps(small(mu_static=0.36)))
    assert again.mu_static == 0.36 and again.mu_backward is None
    for field in ("mu_static", "mu_backward"):
        with pytest.raises(sa.InvalidParameter) as e:
            sa.design_process(small(**{field: float("nan")}))
        assert e.value.name == field
    req.mu_static = 0.36
    req.mu_static = None
    assert req.mu_static is None


def test_the_largest_grid_is_refused_within_a_memory_limit():
    """D36: the flags' largest grid (200^2 x 100 x 20 x 1000 = 8e10 steady entries) ended in
    MemoryError (std::bad_alloc) under 4 GiB; it is refused up front, naming the grid."""
    code = textwrap.dedent("""
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))
        import selfalign as sa
        try:
            sa.design_process(sa.DesignRequest(acceleration_grid=200, period_grid=100,
                                               stroke_grid=20, entries=1000), threads=1)
        except sa.InvalidParameter as e:
            print("refused", e.name)
        """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == "refused grid", out.stderr


def test_a_design_says_which_limits_it_sits_on():
    d = sa.design_process(small(), threads=1)
    assert d.feasible
    assert isinstance(d.limits, list) and all(isinstance(x, str) for x in d.limits)
    assert d.to_dict()["limits"] == d.limits
