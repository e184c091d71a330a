"""Friction maps m(x) = mu_bar(x)/mu_1, eqs. (7)-(9) and (42)."""

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL


def test_two_region_map_is_eq_7_to_9():
    x_mu, w, c_mu = 0.5, 0.05, 2.5
    f = sa.TwoRegionFriction(x_mu, w, c_mu)
    x = np.linspace(0.3, 0.7, 401)
    z = np.minimum(np.maximum(x - x_mu, 0.0), w)  # eq. (8)
    expected = 1.0 + (c_mu - 1.0) / w * z  # eqs. (7), (9)
    np.testing.assert_allclose(f.bound(x), expected, rtol=CLOSED_FORM_TOL, atol=CLOSED_FORM_TOL)
    assert f.bound(0.0) == 1.0 and f.bound(1.0) == pytest.approx(c_mu)


def test_b1_b2_are_eq_42():
    f = sa.TwoRegionFriction(0.5, 0.05, 2.5)
    assert f.b1 == pytest.approx((2.5 - 1) / 0.05, rel=CLOSED_FORM_TOL)
    assert f.b2 == pytest.approx((2.5 - 1) * 0.5 / 0.05 - 1, rel=CLOSED_FORM_TOL)


def test_bound_keeps_the_shape_of_its_argument():
    f = sa.UniformFriction(1.5)
    x = np.zeros((2, 3, 4))
    assert f.bound(x).shape == (2, 3, 4)
    assert np.all(f.bound(x) == 1.5)
    assert f.bound(0.1) == 1.5


def test_pieces_cover_the_line_and_reproduce_the_map():
    f = sa.TwoRegionFriction(0.5, 0.05, 2.5)
    p = f.pieces()
    assert p["begin"][0] == -np.inf and p["end"][-1] == np.inf
    np.testing.assert_array_equal(p["end"][:-1], p["begin"][1:])
    mid = 0.5 + 0.025
    k = np.searchsorted(p["begin"], mid, side="right") - 1
    assert p["bound_at_begin"][k] + p["slope"][k] * (mid - p["begin"][k]) == pytest.approx(
        f.bound(mid), rel=CLOSED_FORM_TOL)
