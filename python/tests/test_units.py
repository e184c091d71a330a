"""Scales: the SI <-> dimensionless conversion of Sect. 3.2, eq. (4)."""

import math

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL


def test_scales_follow_eq_4():
    s = sa.Scales(length_m=1e-3, mu=0.3, gravity=9.81)
    T = math.sqrt(1e-3 / (0.3 * 9.81))  # T = sqrt(L / (mu g))
    assert s.time == pytest.approx(T, rel=CLOSED_FORM_TOL)
    assert s.velocity == pytest.approx(1e-3 / T, rel=CLOSED_FORM_TOL)
    assert s.acceleration == pytest.approx(0.3 * 9.81, rel=CLOSED_FORM_TOL)
    assert s.time_to_si(2.0) == pytest.approx(2.0 * T, rel=CLOSED_FORM_TOL)


def test_conversions_are_vectorised_and_invert_each_other():
    s = sa.Scales(0.02, 0.25)
    x = np.linspace(-1.0, 1.0, 12).reshape(3, 4)
    for to_si, from_si in [
        (s.length_to_si, s.length_from_si),
        (s.time_to_si, s.time_from_si),
        (s.velocity_to_si, s.velocity_from_si),
        (s.acceleration_to_si, s.acceleration_from_si),
    ]:
        y = to_si(x)
        assert y.shape == x.shape and y.dtype == np.float64
        np.testing.assert_allclose(from_si(y), x, rtol=CLOSED_FORM_TOL, atol=1e-15)
    assert isinstance(s.length_to_si(1.0), float)


def test_default_gravity_is_9_81():
    assert sa.Scales(1.0, 1.0).gravity == 9.81


@pytest.mark.parametrize("kwargs, name", [
    (dict(length_m=0.0, mu=0.3), "length_scale"),  # the library's (and the CLI's) name
    (dict(length_m=1e-3, mu=-0.3), "mu"),
])
def test_non_positive_scales_are_rejected(kwargs, name):
    with pytest.raises(sa.InvalidParameter) as info:
        sa.Scales(**kwargs)
    assert info.value.name == name


def test_jerk_follows_eq_4():
    # jerk scales with L/T^3 = mu g / T (Dimension::jerk of the CLI and config files)
    s = sa.Scales(length_m=2e-3, mu=0.25, gravity=9.81)
    T = math.sqrt(2e-3 / (0.25 * 9.81))
    assert s.jerk == pytest.approx(0.25 * 9.81 / T, rel=CLOSED_FORM_TOL)
    assert s.jerk_to_si(3.0) == pytest.approx(3.0 * 0.25 * 9.81 / T, rel=CLOSED_FORM_TOL)
    assert s.jerk_from_si(s.jerk_to_si(3.0)) == pytest.approx(3.0, rel=CLOSED_FORM_TOL)
    np.testing.assert_allclose(s.jerk_to_si(np.array([1.0, 2.0])),
                               [s.jerk, 2 * s.jerk], rtol=CLOSED_FORM_TOL)


def test_absent_and_unbounded_values_pass_through_every_conversion():
    # NaN means absent (a run that never stops), +-inf unbounded (no jerk limit, a process time
    # that accumulates): a conversion keeps them, elementwise too.
    s = sa.Scales(1e-3, 0.3)
    names = [f"{q}_{d}" for q in ("length", "time", "velocity", "acceleration", "jerk")
             for d in ("to_si", "from_si")]
    for name in names:
        convert = getattr(s, name)
        assert math.isnan(convert(math.nan)), name
        assert convert(math.inf) == math.inf and convert(-math.inf) == -math.inf, name
        out = convert(np.array([math.nan, math.inf, -math.inf, 1.0]))
        assert math.isnan(out[0]) and out[1] == math.inf and out[2] == -math.inf, name
        assert math.isfinite(out[3]), name
