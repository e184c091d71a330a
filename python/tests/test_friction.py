"""Friction maps m(x) = mu_bar(x)/mu_1, eqs. (7)-(9) and (42)."""

import pickle

import numpy as np
import pytest

import selfalign as sa

from conftest import CLOSED_FORM_TOL


def test_two_region_map_is_eq_7_to_9():
    x_mu, w, c_mu = 0.5, 0.05, 2.5
    f = sa.two_region_friction(x_mu, w, c_mu)
    x = np.linspace(0.3, 0.7, 401)
    z = np.minimum(np.maximum(x - x_mu, 0.0), w)  # eq. (8)
    expected = 1.0 + (c_mu - 1.0) / w * z  # eqs. (7), (9)
    np.testing.assert_allclose(f.bound(x), expected, rtol=CLOSED_FORM_TOL, atol=CLOSED_FORM_TOL)
    assert f.bound(0.0) == 1.0 and f.bound(1.0) == pytest.approx(c_mu)


def test_b1_b2_are_eq_42():
    t = sa.two_region_friction(0.5, 0.05, 2.5).two_region
    assert t == sa.TwoRegionTable(0.5, 0.05, 2.5)
    assert t.b1 == pytest.approx((2.5 - 1) / 0.05, rel=CLOSED_FORM_TOL)
    assert t.b2 == pytest.approx((2.5 - 1) * 0.5 / 0.05 - 1, rel=CLOSED_FORM_TOL)


def test_the_two_region_table_is_a_field_friction_that_keeps_its_parameters():
    # The paper's table is the field family's named member: the step field 1 -> c_mu at x_mu
    # under a uniform footprint of width w (eq. 7 gives eq. 9). The same field read as data has
    # the same level, but only the named one carries the table (eqs. 41, 59, 60 read it).
    two = sa.two_region_friction(0.5, 0.05, 2.5)
    data = sa.FieldFriction(sa.FrictionField.steps([0.5], [1.0, 2.5]), 0.05)
    assert isinstance(two, sa.FieldFriction)
    assert two.field == data.field and two.footprint == data.footprint
    assert data.two_region is None
    x = np.linspace(0.4, 0.6, 201)
    np.testing.assert_array_equal(two.bound(x), data.bound(x))
    assert sa.FieldFriction(sa.TwoRegionTable(0.5, 0.05, 2.5)) == two
    assert two != data  # the table is part of the value
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        again = pickle.loads(pickle.dumps(two, protocol=protocol))
        assert again == two and again.two_region == two.two_region
        assert pickle.loads(pickle.dumps(data, protocol=protocol)).two_region is None
    assert eval(repr(two), vars(sa)) == two
    with pytest.raises(sa.InvalidParameter, match="c_mu"):
        sa.two_region_friction(0.5, 0.05, 1.0)
    with pytest.raises(sa.InvalidParameter, match="x_mu"):
        sa.TwoRegionTable(1e51, 1e43, 2.5)  # beyond the field's positions (|x| <= 1e50)


def test_bound_keeps_the_shape_of_its_argument():
    f = sa.UniformFriction(1.5)
    x = np.zeros((2, 3, 4))
    assert f.bound(x).shape == (2, 3, 4)
    assert np.all(f.bound(x) == 1.5)
    assert f.bound(0.1) == 1.5


def test_pieces_cover_the_line_and_reproduce_the_map():
    f = sa.two_region_friction(0.5, 0.05, 2.5)
    p = f.pieces()
    assert p["begin"][0] == -np.inf and p["end"][-1] == np.inf
    np.testing.assert_array_equal(p["end"][:-1], p["begin"][1:])
    mid = 0.5 + 0.025
    k = np.searchsorted(p["begin"], mid, side="right") - 1
    assert p["bound_at_begin"][k] + p["slope"][k] * (mid - p["begin"][k]) == pytest.approx(
        f.bound(mid), rel=CLOSED_FORM_TOL)


def test_a_one_step_field_is_the_papers_table_by_value():
    table = sa.TwoRegionTable(0.3, 0.05, 2.5)
    assert sa.as_two_region_table(sa.two_region_friction(0.3, 0.05, 2.5)) == table
    read = sa.FieldFriction(sa.FrictionField.steps([0.3], [1.0, 2.5]), 0.05)
    assert sa.as_two_region_table(read) == table
    assert sa.as_two_region_table(sa.FieldFriction(sa.FrictionField.steps([0.3, 0.4], [1.0, 2.0, 3.0]), 0.05)) is None
    assert sa.as_two_region_table(sa.FieldFriction(sa.FrictionField.steps([0.3], [1.0, 2.5]), sa.PointFootprint())) is None
    assert sa.as_two_region_table(sa.UniformFriction()) is None
