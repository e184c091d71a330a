"""Planar motion of a rigid part (issue 13): contact patches, planar fields, simulate_planar and
the planar analyses, checked against independent values (the 1-D time-stepping scheme, the
closed-form stop of a sliding disc), bad input, and the figures."""

import math
import os
import pickle

import numpy as np
import pytest

import selfalign as sa

PROFILE = sa.ThreePhaseProfile(1.0, 0.084, 3.0, 0.9)


# ---- (a) the 1-D scheme along one axis -----------------------------------------------------

def test_point_patch_along_x_is_the_1d_time_stepping_scheme():
    h, periods = 1e-3, 3
    start = sa.ObjectState(0.0, 0.1, 0.2)
    one_d = sa.simulate(PROFILE, sa.UniformFriction(), start,
                        sa.SimulationOptions(method="time-stepping", duration=periods * 1.0,
                                             step=h, theta=0.5)).trajectory
    r = sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                           step=h, periods=periods, pose=(0.1, 0.0, 0.0), twist=(0.2, 0.0, 0.0))
    assert len(r["t"]) == len(one_d.t) == periods * 1000 + 1
    np.testing.assert_allclose(r["t"], one_d.t, rtol=0, atol=1e-12)
    np.testing.assert_allclose(r["x"], one_d.x, rtol=0, atol=1e-10)
    np.testing.assert_allclose(r["ux"], one_d.xd, rtol=0, atol=1e-10)
    np.testing.assert_allclose(r["table_x"], one_d.y, rtol=0, atol=1e-10)
    assert np.all(r["y"] == 0) and np.all(r["uy"] == 0) and np.all(r["table_y"] == 0)
    assert np.all(r["angle"] == 0) and np.all(r["omega"] == 0) and np.all(r["table_angle"] == 0)
    np.testing.assert_array_equal(r["mode"][1:] == sa.PatchMode.stick, one_d.stick[1:])
    assert set(np.unique(r["mode"])) <= {0, 2} and np.all(r["pivot"] == -1)


def test_sampling_every_n_steps_keeps_t0_and_the_last_step():
    full = sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                              step=0.01, periods=2)
    sparse = sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                step=0.01, periods=2, every=30)
    idx = list(range(0, 201, 30)) + [200]
    for key in ("t", "x", "ux", "table_x", "mode"):
        np.testing.assert_array_equal(sparse[key], full[key][idx], err_msg=key)
    assert full["t"][0] == 0 and full["t"][-1] == pytest.approx(2.0)
    assert full["mode"].dtype == np.int8 and full["x"].dtype == np.float64


def test_a_held_part_keeps_its_pose_on_a_rotating_table():
    part = sa.RigidPart(0.005, sa.rectangle_patch(0.2, 0.1, 2, 2))
    r = sa.simulate_planar(PROFILE, PROFILE, PROFILE, field=sa.UniformPlanarField(10.0),
                           part=part, step=0.01, periods=2, pose=(0.3, -0.1, 0.4))
    assert np.all(r["x"] == 0.3) and np.all(r["y"] == -0.1) and np.all(r["angle"] == 0.4)
    assert np.all(r["mode"] == sa.PatchMode.stick)
    y, _, _ = PROFILE.sample(r["t"])
    np.testing.assert_allclose(r["table_x"], y, atol=1e-12)
    np.testing.assert_allclose(r["table_angle"], y, atol=1e-12)


# ---- (b) a uniform disc on a table at rest -------------------------------------------------

DISC = sa.RigidPart(0.02, sa.disc_patch(0.2, 12, 24))  # j = r^2/2 for r = 0.2


def _stop_index(values):
    """The first sample from which values stay exactly 0."""
    moving = np.flatnonzero(values != 0)
    return 0 if moving.size == 0 else int(moving[-1]) + 1


def test_sliding_and_spinning_disc_stops_both_at_once():
    h = 1e-3
    r = sa.simulate_planar(field=sa.UniformPlanarField(), part=DISC, step=h, duration=1.0,
                           twist=(0.3, 0.0, 2.0))
    translation = _stop_index(np.hypot(r["ux"], r["uy"]))
    spin = _stop_index(r["omega"])
    assert 0 < translation < len(r["t"]) - 1 and 0 < spin < len(r["t"]) - 1
    assert abs(translation - spin) <= 5
    # the spin takes part of the friction as torque: it slides longer than a pure slide (0.3)
    assert r["t"][translation] > 0.3
    assert np.all(r["mode"][max(translation, spin) + 1:] == sa.PatchMode.stick)


def test_pure_slide_of_a_disc_stops_at_v0_over_k():
    h = 1e-3
    r = sa.simulate_planar(field=sa.UniformPlanarField(), part=DISC, step=h, duration=0.5,
                           twist=(0.3, 0.0, 0.0))
    stop = _stop_index(r["ux"])
    assert abs(r["t"][stop] - 0.3) <= 2 * h  # decelerates at k m = 1
    assert np.abs(r["omega"]).max() < 1e-12 and np.abs(r["uy"]).max() < 1e-12  # round-off
    assert r["x"][-1] == pytest.approx(0.3 ** 2 / 2, abs=2 * h * 0.3)  # v0^2 / (2 k)


# ---- patches and fields --------------------------------------------------------------------

def test_patches_carry_unit_load_centred_on_the_origin():
    for patch in (sa.point_patch(), sa.disc_patch(0.2, 12, 24), sa.rectangle_patch(0.4, 0.2, 4, 2),
                  sa.polygon_patch([0, 1, 1, 0], [0, 0, 1, 1], 3),
                  sa.weighted_points_patch([-0.1, 0.1], [0.0, 0.0], [0.5, 0.5])):
        loads = np.array([p.load for p in patch])
        xs = np.array([p.x for p in patch])
        ys = np.array([p.y for p in patch])
        assert loads.sum() == pytest.approx(1, abs=1e-12)
        assert abs(loads @ xs) < 1e-12 and abs(loads @ ys) < 1e-12
    # r^2/2, less O(1/rings^2) and the sectors' (sin(a/2)/(a/2))^2, a = 2 pi/sectors
    assert sa.polar_moment(sa.disc_patch(0.2, 40, 200)) == pytest.approx(0.02, rel=1e-3)
    # a unit square: polar moment (1 + 1)/12 in the limit
    assert sa.polar_moment(sa.rectangle_patch(1, 1, 40, 40)) == pytest.approx(1 / 6, rel=1e-3)
    assert sa.patch_radius(sa.weighted_points_patch([-0.1, 0.1], [0, 0], [0.5, 0.5])) == \
        pytest.approx(0.1)
    assert sa.RigidPart().patch == sa.point_patch() == [sa.ContactPoint(0, 0, 1)]


def test_planar_level_is_vectorised_and_matches_the_fields():
    step = sa.HalfPlaneStepField(origin_x=1.0, width=0.5, c_mu=3.0)
    assert sa.planar_level(step, 0.9, 7.0) == 1.0
    assert sa.planar_level(step, 1.25, -3.0) == pytest.approx(2.0)
    assert sa.planar_level(step, 2.0, 0.0) == 3.0
    x = np.linspace(0, 2, 5)
    y = np.array([[0.0], [1.0]])
    out = sa.planar_level(step, x, y)
    assert out.shape == (2, 5)
    np.testing.assert_allclose(out[0], [1.0, 1.0, 1.0, 3.0, 3.0])
    disc = sa.CircularPocketField(radius=1.0, width=0.2, c_mu=2.0)
    assert sa.planar_level(disc, 0.0, 0.0) == 2.0 and sa.planar_level(disc, 0.9, 0.0) == \
        pytest.approx(1.5)
    grid = sa.GridField(dx=1.0, dy=1.0, nx=2, ny=2, levels=[1.0, 2.0, 3.0, 4.0])
    assert sa.planar_level(grid, 0.5, 0.5) == pytest.approx(2.5)
    rot = sa.rotated_field(step, math.pi / 2)
    assert type(rot) is sa.HalfPlaneStepField
    assert sa.planar_level(rot, 0.0, 2.0) == 3.0
    # The 1-D field along an axis: steps 1 -> 3 at 0.3 along +y from (0, 0.1), any x.
    axis = sa.AxisField(sa.FrictionField.steps([0.3], [1.0, 3.0]), origin_y=0.1,
                        angle=math.pi / 2)
    np.testing.assert_array_equal(sa.planar_level(axis, [5.0, -2.0], [0.35, 0.45]), [1.0, 3.0])
    assert type(sa.rotated_field(axis, 0.2)) is sa.AxisField


def test_a_point_part_on_an_axis_field_is_the_1d_scheme_on_that_field():
    # The 1-D field is the planar family's one-axis case: the second method is the 1-D Moreau
    # scheme on the same field under a point footprint (tolerance as the uniform case above).
    field = sa.FrictionField.ramps([0.05, 0.08, 0.1, 0.16], [1.0, 1.4, 1.2, 4.0])
    h, periods = 1e-3, 6
    one_d = sa.simulate(PROFILE, sa.FieldFriction(field, sa.PointFootprint()), sa.ObjectState(),
                        sa.SimulationOptions(method="time-stepping", duration=periods * 1.0,
                                             step=h, theta=0.5)).trajectory
    r = sa.simulate_planar(PROFILE, field=sa.AxisField(field), part=sa.RigidPart(), step=h,
                           periods=periods)
    assert one_d.x[-1] > 0.1  # it walks onto the rising friction
    np.testing.assert_allclose(r["x"], one_d.x, rtol=0, atol=1e-10)
    np.testing.assert_allclose(r["ux"], one_d.xd, rtol=0, atol=1e-10)


# ---- (c) bad input -------------------------------------------------------------------------

@pytest.mark.parametrize("make, name", [
    (lambda: sa.RigidPart(0.0), "inertia"),
    (lambda: sa.RigidPart(-1.0, sa.point_patch()), "inertia"),
    (lambda: sa.polygon_patch([0.0, 1.0], [0.0, 0.0]), "polygon"),
    (lambda: sa.polygon_patch([0.0, 1.0, 1.0, 0.0], [0.0, 1.0, 0.0, 1.0]), "polygon"),
    (lambda: sa.weighted_points_patch([-0.1, 0.1], [0.0, 0.0], [0.5, 0.4]), "load_fractions"),
    (lambda: sa.GridField(levels=[1.0, math.nan, 1.0, 1.0]), "levels"),
    (lambda: sa.AxisField(sa.FrictionField.steps([0.0], [1.0, 0.0])), "levels"),
    (lambda: sa.AxisField(sa.FrictionField.steps([0.0], [1.0, 2.0]), angle=math.inf), "angle"),
    (lambda: sa.HalfPlaneStepField(width=-1.0), "width"),
    (lambda: sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                step=0.01, periods=1, every=0), "every"),
    (lambda: sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                step=0.3, periods=1), "step"),
    (lambda: sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                step=0.01, periods=1, law=sa.FrictionLaw(1.2, 1.0, 0.9)), "law"),
    (lambda: sa.simulate_planar(field=sa.UniformPlanarField(), part=sa.RigidPart(), step=0.01,
                                periods=1), "periods"),
    (lambda: sa.planar_steady(field=sa.UniformPlanarField(), part=sa.RigidPart(), step=0.01),
     "motion"),
    (lambda: sa.simulate_planar(field=sa.UniformPlanarField(), part=sa.RigidPart(), step=0.01,
                                duration=0.015), "duration"),
    (lambda: sa.planar_level(sa.UniformPlanarField(), [0.0, math.inf], 0.0), "x"),
    (lambda: sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                step=0.01, periods=1, duration=1.0), "periods"),
    (lambda: sa.simulate_planar(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                step=0.01, periods=1, x_direction=(1.0, 1.0)), "x_direction"),
    (lambda: sa.planar_stop(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                            step=0.01, entries=[[0.0, 0.0]], max_periods=1), "entries"),
])
def test_bad_input_raises_naming_the_parameter(make, name):
    with pytest.raises(sa.InvalidParameter) as error:
        make()
    assert error.value.name == name
    assert name in str(error.value)


# ---- analyses -----------------------------------------------------------------------------

def test_steady_drift_of_a_point_is_the_1d_steady_velocity():
    r = sa.planar_steady(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                         step=1e-3, transient=3, window=2)
    v_bar = sa.steady_state(PROFILE).v_bar
    assert r.drift_x == pytest.approx(v_bar, abs=5e-3)
    assert r.drift_y == 0 and r.rotation_rate == 0 and r.change < 1e-9
    assert r.census.total() == 2000 and r.census.pivot == 0


def test_drift_field_arrays_match_its_samples_and_stop_in_a_rough_region():
    field = sa.HalfPlaneStepField(origin_x=0.3, width=0.05, c_mu=4.0)
    xs, ys = [0.0, 0.5], [0.0, 0.1, 0.2]
    d = sa.planar_drift_field(PROFILE, field=field, part=sa.RigidPart(), step=0.005, xs=xs,
                              ys=ys, angles=[0.0, 1.0], periods=2, threads=1)
    assert d["drift_x"].shape == (3, 2, 2) and len(d["samples"]) == 12
    for i, s in enumerate(d["samples"]):
        iy, ix, ia = np.unravel_index(i, (3, 2, 2))
        assert (s.x, s.y, s.angle) == (xs[ix], ys[iy], [0.0, 1.0][ia])
        assert s.drift_x == d["drift_x"][iy, ix, ia] and s.census.stick == d["stick"][iy, ix, ia]
    assert np.all(d["drift_x"][:, 0, :] > 0)  # smooth region: walks along +x
    assert np.all(d["drift_x"][:, 1, :] == 0)  # deep in the rough region: held
    assert d["failed"].shape == (3, 2, 2) and not d["failed"].any()
    assert all(s.failure == "" for s in d["samples"])
    summary = sa.planar_stop(PROFILE, field=field, part=sa.RigidPart(), step=0.005,
                             entries=np.array([[0.0, 0.0, 0.0], [0.1, 0.2, 0.5]]),
                             max_periods=60, threads=1)
    assert summary.stopped == 2 and all(run.stopped for run in summary.runs)
    assert summary.failed == 0 and all(run.failure == "" for run in summary.runs)
    assert 0.3 <= summary.min_x <= summary.max_x < 0.3 + field.width
    assert summary.min_y == 0.0 and summary.max_y == 0.2 and summary.angle_range == 0.5
    assert summary.max_process_time == max(run.process_time for run in summary.runs)


def test_value_types_pickle_and_compare():
    values = [sa.ContactPoint(0.1, -0.2, 0.5), sa.PlanarPose(1, 2, 3), sa.PlanarTwist(0.1, 0, 2),
              sa.GridField(nx=3, levels=[1, 2, 3, 4, 5, 6]), DISC,
              sa.StripField(angle=0.3, half_width=0.4)]
    for v in values:
        w = pickle.loads(pickle.dumps(v))
        assert type(w) is type(v) and w == v and repr(w) == repr(v)
        assert eval(repr(v), vars(sa)) == v


# ---- (d) figures ---------------------------------------------------------------------------

def test_figures_write_png_and_gif(tmp_path):
    import matplotlib.pyplot as plt

    from selfalign import planar_figures

    field = sa.CircularPocketField(centre_x=0.15, radius=0.1, width=0.05, c_mu=3.0)
    part = sa.RigidPart(0.005, sa.rectangle_patch(0.2, 0.1, 3, 2))
    r = sa.simulate_planar(PROFILE, None, PROFILE, field=field, part=part, step=0.01, periods=2,
                           every=10, twist=(0.1, 0.05, 1.0))
    png = tmp_path / "path.png"
    ax = planar_figures.plot_planar_path(r, field, part, path=png)
    plt.close(ax.figure)
    assert png.stat().st_size > 0 and png.read_bytes()[:4] == b"\x89PNG"

    d = sa.planar_drift_field(PROFILE, field=field, part=sa.RigidPart(), step=0.02,
                              xs=np.linspace(-0.2, 0.3, 4), ys=np.linspace(-0.1, 0.1, 3),
                              periods=1, threads=1)
    drift_png = tmp_path / "drift.png"
    ax = planar_figures.plot_drift_field(d, path=drift_png)
    plt.close(ax.figure)
    assert drift_png.stat().st_size > 0

    gif = tmp_path / "part.gif"
    assert planar_figures.animate_planar(r, field, part, gif, fps=10, max_frames=6) == str(gif)
    data = gif.read_bytes()
    assert len(data) > 0 and data[:4] == b"GIF8"
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".tmp-")] == []
    umask = os.umask(0)
    os.umask(umask)
    for written in (png, drift_png, gif):  # a new file's permissions, not mkstemp's 0600
        assert written.stat().st_mode & 0o777 == 0o666 & ~umask, written


def test_planar_steady_state_of_a_point_on_an_x_motion_is_the_1d_steady_state():
    """The fixed point of the planar period map (issue 21) with the exact point solver against
    the 1-D exact steady state, a second method (eq. 10): agree to 1e-10; drift NaN when the
    search is cut short, never 0."""
    law = sa.FrictionLaw(1.2, 1.0)
    s = sa.planar_steady_state(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                               law=law, step=1e-3)
    assert s.converged and not s.level_changed and s.method == sa.Method.exact
    one_d = sa.steady_state(PROFILE, law)
    assert abs(s.drift_x - one_d.v_bar) <= 1e-10
    assert abs(s.twist_0s.ux - one_d.x_dot_0s) <= 1e-10
    assert s.drift_y == 0.0
    cut = sa.planar_steady_state(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                                 law=law, step=1e-3, max_periods=1)
    assert not cut.converged and math.isnan(cut.drift_x)
    with pytest.raises(sa.InvalidParameter, match="max_periods"):
        sa.planar_steady_state(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(),
                               step=1e-3, max_periods=0)


# ---- the model object (issue 21: a PlanarProblem instead of ten loose arguments) ------------

def test_a_planar_problem_is_the_keyword_form_bit_for_bit():
    cross = sa.ThreePhaseProfile(0.5, 0.02, 2.5, 1.5)
    field = sa.HalfPlaneStepField(origin_x=0.3, width=0.05, c_mu=4.0)
    part = sa.RigidPart(0.01, sa.rectangle_patch(0.04, 0.02, 2, 2))
    law = sa.FrictionLaw(1.2, 1.0)
    loose = dict(field=field, part=part, law=law, step=0.005, theta=0.5)
    problem = sa.PlanarProblem(PROFILE, cross, **loose)
    assert problem.x_profile is PROFILE and problem.y_profile is cross and problem.rotation is None
    assert problem.field == field and problem.part == part and problem.law == law
    assert (problem.step, problem.theta) == (0.005, 0.5)
    assert problem.x_direction == (1.0, 0.0) and problem.y_direction == (0.0, 1.0)
    assert repr(problem).startswith("PlanarProblem(x_profile=")
    a = sa.simulate_planar(problem, periods=2, pose=(0.1, 0.0, 0.3))
    b = sa.simulate_planar(PROFILE, cross, periods=2, pose=(0.1, 0.0, 0.3), **loose)
    assert all(np.array_equal(a[k], b[k]) for k in b)
    s1 = sa.planar_steady_state(problem, max_periods=50)
    s2 = sa.planar_steady_state(PROFILE, cross, max_periods=50, **loose)
    assert s1.to_dict() == s2.to_dict() or (math.isnan(s1.drift_x) and math.isnan(s2.drift_x))
    f1 = sa.planar_drift_field(problem, xs=[0.0, 0.5], ys=[0.0], periods=1, threads=1)
    f2 = sa.planar_drift_field(PROFILE, cross, xs=[0.0, 0.5], ys=[0.0], periods=1, threads=2,
                               **loose)
    assert np.array_equal(f1["drift_x"], f2["drift_x"])
    r1 = sa.planar_stop(problem, entries=[[0.0, 0.0, 0.0]], max_periods=30, threads=1)
    r2 = sa.planar_stop(PROFILE, cross, entries=[[0.0, 0.0, 0.0]], max_periods=30, **loose)
    assert r1.runs[0].to_dict() == r2.runs[0].to_dict()
    w1 = sa.planar_steady(problem, transient=1, window=1)
    w2 = sa.planar_steady(PROFILE, cross, transient=1, window=1, **loose)
    assert w1.to_dict() == w2.to_dict()


def test_a_planar_problem_is_checked_when_made():
    with pytest.raises(sa.InvalidParameter) as error:
        sa.PlanarProblem(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(), step=-1.0)
    assert error.value.name == "step"
    with pytest.raises(sa.InvalidParameter) as error:
        sa.PlanarProblem(PROFILE, field=sa.UniformPlanarField(), part=sa.RigidPart(), step=0.01,
                         x_direction=(1.0, 1.0))
    assert error.value.name == "x_direction"


def test_the_exact_point_solver_from_python():
    # Issue 22: simulate_planar(method="exact") runs the exact event-driven point solver at the
    # samples' times. Second method: Moreau converges to it at first order (the error at h/4 is
    # about a quarter of the error at h); a patch part is refused by name.
    along = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    across = sa.ThreePhaseProfile(1.0, 0.084, 3.0, 0.9)
    errors = []
    for step in (1 / 400, 1 / 1600):
        problem = sa.PlanarProblem(along, across, field=sa.UniformPlanarField(1.0),
                                   part=sa.RigidPart(0.01, sa.point_patch()),
                                   law=sa.FrictionLaw(1.3, 1.0), step=step)
        every = round(0.25 / step)
        exact = sa.simulate_planar(problem, periods=2, twist=(0.1, -0.05, 0), every=every,
                                   method="exact")
        moreau = sa.simulate_planar(problem, periods=2, twist=(0.1, -0.05, 0), every=every)
        np.testing.assert_array_equal(exact["t"], moreau["t"])
        errors.append(max(np.abs(exact["x"] - moreau["x"]).max(),
                          np.abs(exact["y"] - moreau["y"]).max()))
        assert set(exact["mode"]) <= {0, 2} and np.all(exact["pivot"] == -1)
    assert 2 < errors[0] / errors[1] < 8
    patch = sa.PlanarProblem(along, field=sa.UniformPlanarField(1.0),
                             part=sa.RigidPart(0.01, sa.rectangle_patch(0.04, 0.02, 2, 2)), step=0.01)
    with pytest.raises(sa.InvalidParameter, match="method"):
        sa.simulate_planar(patch, periods=1, method="exact")


def test_the_patch_integrator_from_python():
    # Issue 22 item 4: simulate_planar(method="integrator") runs the patch integrator at the
    # samples' times. Second methods: for a point part the exact point solver (closed-form arcs,
    # to 1e-12 at tolerance 1e-12); for a 16-point bar swinging about its rough end, Moreau
    # converges to it at first order. A rotating table is refused by name.
    along = sa.ThreePhaseProfile(1.0, 0.084, 2.3, 1.3)
    across = sa.ThreePhaseProfile(1.0, 0.084, 3.0, 0.9)
    tight = sa.IntegratorOptions(relative_tolerance=1e-12, absolute_tolerance=1e-14)
    point = sa.PlanarProblem(along, across, field=sa.UniformPlanarField(1.0),
                             part=sa.RigidPart(0.01, sa.point_patch()),
                             law=sa.FrictionLaw(1.3, 1.0), step=1 / 400)
    exact = sa.simulate_planar(point, periods=2, twist=(0.1, -0.05, 0), every=100, method="exact")
    run = sa.simulate_planar(point, periods=2, twist=(0.1, -0.05, 0), every=100,
                             method="integrator", integrator=tight)
    np.testing.assert_array_equal(run["t"], exact["t"])
    for key in ("x", "y", "ux", "uy"):
        np.testing.assert_allclose(run[key], exact[key], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(run["mode"], exact["mode"])
    assert run["integration"].steps > 0 and "integration" not in exact

    bar = sa.RigidPart(0.4 * 0.4 / 12, sa.rectangle_patch(0.4, 0.03, 8, 2))
    rough_end = sa.HalfPlaneStepField(origin_x=0.05, origin_y=0.0, angle=0.0, width=0.02, c_mu=2.5)
    errors = []
    for step in (1e-3, 1e-4):
        problem = sa.PlanarProblem(None, across, field=rough_end, part=bar,
                                   law=sa.FrictionLaw(1.3, 1.0), step=step)
        every = round(0.25 / step)
        ref = sa.simulate_planar(problem, periods=2, every=every, method="integrator",
                                 integrator=tight)
        moreau = sa.simulate_planar(problem, periods=2, every=every)
        errors.append(max(np.abs(ref[k] - moreau[k]).max() for k in ("x", "y", "angle")))
    assert ref["integration"].pivots > 0
    assert 4 < errors[0] / errors[1] < 25
    turning = sa.PlanarProblem(along, rotation=across, field=sa.UniformPlanarField(1.0),
                               part=bar, step=0.01)
    with pytest.raises(sa.InvalidParameter, match="method"):
        sa.simulate_planar(turning, periods=1, method="integrator")
