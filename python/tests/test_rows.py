"""Queues of 1-D parts from Python (analysis/row.hpp, docs/rows.md): a touching queue of
identical parts conveys as one part (against a lone part, by row_run and by the 1-D exact
solver of simulate), a queue stops packed at a friction step by both methods, bad input names
the offending parameter, and the figure is written."""

import math
import pickle

import numpy as np
import pytest

import selfalign as sa

PROFILE = sa.ThreePhaseProfile(period=1.0, stroke=0.084, a2=3.0, a3=0.9)  # Sect. 7.2
LAW = sa.FrictionLaw(1.2, 1.0)


def identical_queue(n, length, pitch, law=LAW):
    return sa.RowQueue([sa.RowPart(length=length, law=law, x=i * pitch) for i in range(n)])


def stopping_queue():
    """tests/test_rows.cpp, RowAnalysis.AQueueStopsAtTheStepAndTheMethodsAgree: three parts
    of length 0.25 with gaps, the rear one (static 1.1, kinetic 0.8) conveying faster."""
    laws = [sa.FrictionLaw(1.1, 0.8), LAW, LAW]
    return sa.RowQueue([sa.RowPart(0.25, 1.0, law, 0.375 * i) for i, law in enumerate(laws)])


STEP = sa.FrictionField.steps([1.5], [1.0, 4.0])


def test_a_touching_queue_of_identical_parts_conveys_as_one_part():
    # docs/rows.md section 4: identical touching parts never separate; the queue moves as a
    # lone part, whose mean velocity over period 10 the 1-D exact solver (simulate) gives too.
    run = sa.row_run(PROFILE, identical_queue(4, 0.25, 0.25), 10, samples_per_period=4)
    lone = sa.row_run(PROFILE, [sa.RowPart(length=0.25, law=LAW)], 10)
    one_d = sa.simulate(PROFILE, sa.UniformFriction(), sa.ObjectState(0.0, 0.0, 0.0),
                        sa.SimulationOptions(method="exact", duration=10.0), law=LAW)
    v_bar = one_d.mean_velocity_last_period
    assert v_bar > 0.01
    assert lone.queue_velocity == pytest.approx(v_bar, abs=1e-12)
    assert run.queue_velocity == pytest.approx(lone.queue_velocity, abs=1e-12)
    assert run.queue_velocity == pytest.approx(v_bar, abs=1e-12)
    np.testing.assert_allclose(run.mean_velocity, v_bar, rtol=0, atol=1e-12)
    assert run.clusters.dtype == np.int32 and run.clusters.tolist() == [4]
    assert run.pitch == 0.25
    assert run.throughput_per_period == pytest.approx(run.queue_velocity / 0.25, rel=1e-14)
    assert run.collisions == 0 and run.separations == 0
    # the trajectories: 10 periods x 4 samples after t = 0, every part at a constant offset
    assert run.times.shape == (41,) and run.positions.shape == (41, 4)
    np.testing.assert_allclose(run.times, np.arange(41) / 4, rtol=0, atol=1e-15)
    np.testing.assert_allclose(np.diff(run.positions, axis=1), 0.25, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(run.positions[-1], run.x)
    for name in ("x", "v", "mean_velocity", "times", "positions"):
        a = getattr(run, name)
        assert a.dtype == np.float64 and not a.flags.writeable, name
    # a lone part has no pitch: NaN, not 0
    assert math.isnan(lone.pitch) and math.isnan(lone.throughput_per_period)
    assert lone.clusters.tolist() == [1]


def test_the_time_stepping_queue_conveys_at_the_same_velocity():
    run = sa.row_run(PROFILE, identical_queue(4, 0.25, 0.25), 10, method="time-stepping",
                     steps_per_period=20000, samples_per_period=1)
    exact = sa.row_run(PROFILE, identical_queue(4, 0.25, 0.25), 10)
    assert run.queue_velocity == pytest.approx(exact.queue_velocity, abs=2e-4)  # O(h)
    assert run.clusters.tolist() == [4]


def test_a_queue_stops_packed_at_the_step_and_the_methods_agree():
    # Only the front part on the rough side cannot hold the cluster (pooled static bound
    # (1.1 + 1.2 + 4.8)/3 < 3, the table's push); two can ((1.1 + 4.8 + 4.8)/3 > 3): the queue
    # stops packed with the middle part's leading edge just past the step.
    exact = sa.row_stop(PROFILE, stopping_queue(), STEP, 400, samples_per_period=2)
    moreau = sa.row_stop(PROFILE, stopping_queue(), STEP, 400, method="time-stepping",
                         steps_per_period=20000, samples_per_period=2)
    assert exact.stopped and moreau.stopped
    assert exact.accumulated
    assert exact.collisions > 0
    assert exact.x[1] > 1.5 > exact.x[0]
    np.testing.assert_allclose(exact.x, moreau.x, rtol=0, atol=2e-3)
    np.testing.assert_allclose(exact.gaps, moreau.gaps, rtol=0, atol=2e-3)
    # packed: each leading edge one length (0.25) ahead of the one behind
    np.testing.assert_allclose(np.diff(exact.x), 0.25, rtol=0, atol=1e-9)
    assert exact.gaps.shape == (2,) and np.all(np.abs(exact.gaps) <= 1e-9)
    # the C++ exact solver's values (tests/test_rows.cpp prints them)
    np.testing.assert_allclose(exact.x, [1.26134, 1.51134, 1.76134], rtol=0, atol=1e-4)
    # errors: the front part against the step, the others against the packed targets
    np.testing.assert_allclose(exact.error, exact.x - np.array([1.0, 1.25, 1.5]), rtol=0,
                               atol=1e-15)
    assert 0 < exact.stop_time <= exact.periods
    assert np.all(exact.process_time > 0) and np.nanmax(exact.process_time) == exact.stop_time
    assert exact.positions.shape == (2 * exact.periods + 1, 3)
    np.testing.assert_array_equal(exact.positions[-1], exact.x)


def test_a_queue_that_does_not_stop_is_a_result_with_nan():
    stop = sa.row_stop(PROFILE, [sa.RowPart(0.25, law=LAW)], STEP, 2)
    assert not stop.stopped and stop.periods == 2
    assert math.isnan(stop.stop_time)
    assert stop.gaps.shape == (0,) and stop.x.shape == (1,)
    assert not np.isnan(stop.process_time).any()  # it moved
    # a part that never moves (held: static 100 > the table's 3): NaN process time
    held = sa.row_stop(PROFILE, [sa.RowPart(0.25, law=sa.FrictionLaw(100.0, 100.0))], STEP, 5)
    assert held.stopped and np.isnan(held.process_time).all()


def test_bad_input_names_the_parameter():
    overlapping = sa.RowQueue([sa.RowPart(0.25, x=0.0), sa.RowPart(0.25, x=0.2)])
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, overlapping, 2)
    assert e.value.name == "parts[1].x" and "overlaps parts[0]" in str(e.value)
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_stop(PROFILE, overlapping, STEP, 2)
    assert e.value.name == "parts[1].x"
    bouncy = sa.RowQueue(identical_queue(2, 0.25, 0.5).parts, restitution=1.5)
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, bouncy, 2)
    assert e.value.name == "restitution"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart(length=0.0)], 2)
    assert e.value.name == "parts[0].length"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart(law=LAW.with_viscous(0.1))], 2)
    assert e.value.name == "parts[0].law"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [], 2)
    assert e.value.name == "parts"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart()], 2, method="integrator")
    assert e.value.name == "method"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart()], 0)
    assert e.value.name == "periods"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_stop(PROFILE, [sa.RowPart()], STEP, 0)
    assert e.value.name == "max_periods"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart()], 2, samples_per_period=0)
    assert e.value.name == "samples_per_period"
    # the binding's bounds on what a run returns and costs
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart()], 10**6, samples_per_period=100)
    assert e.value.name == "periods"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_run(PROFILE, [sa.RowPart()], 10**5, method="time-stepping",
                   steps_per_period=10**5, samples_per_period=1)
    assert e.value.name == "steps_per_period"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_stop(PROFILE, [sa.RowPart()], STEP, 10**7)
    assert e.value.name == "max_periods"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.row_stop(PROFILE, [sa.RowPart()], STEP, 10**6, method="time-stepping",
                    samples_per_period=1)
    assert e.value.name == "steps_per_period"
    # wrong types name the argument
    with pytest.raises(TypeError, match=r"queue\[1\]"):
        sa.row_run(PROFILE, [sa.RowPart(), 1.0], 2)
    with pytest.raises(TypeError, match="queue"):
        sa.row_run(PROFILE, 3, 2)
    with pytest.raises(TypeError, match=r"parts\[0\]"):
        sa.RowQueue(["x"])
    with pytest.raises(TypeError, match="parts"):
        sa.RowQueue("ab")


def test_parts_and_queues_are_values():
    part = sa.RowPart(0.25, 2.0, sa.FrictionLaw(1.2, 1.0, 0.9), 0.5, 0.1)
    assert (part.length, part.mass, part.x, part.v) == (0.25, 2.0, 0.5, 0.1)
    assert part.law == sa.FrictionLaw(1.2, 1.0, 0.9)
    queue = sa.RowQueue((sa.RowPart(), part), restitution=0.4)
    assert len(queue) == 2 and queue.parts[1] == part and queue.restitution == 0.4
    for x in (part, queue):
        assert eval(repr(x), vars(sa)) == x
        assert pickle.loads(pickle.dumps(x)) == x
    with pytest.raises(AttributeError):
        part.x = 1.0
    # a list of parts is the queue with restitution 0
    parts = identical_queue(3, 0.25, 0.3).parts
    a = sa.row_run(PROFILE, parts, 3)
    b = sa.row_run(PROFILE, sa.RowQueue(parts, 0.0), 3)
    assert a == b and a.to_dict().keys() == set(type(a)._record_fields)


def test_the_queue_figure(tmp_path):
    from selfalign import row_figures

    png = tmp_path / "queue.png"
    stop = row_figures.figure_queue_stop(png)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert [p.name for p in tmp_path.iterdir()] == ["queue.png"]
    assert stop.stopped and stop.x[1] > row_figures.QUEUE_STOP_STEP > stop.x[0]
    run = sa.row_run(PROFILE, identical_queue(2, 0.25, 0.5), 3)
    fig = row_figures.queue_trajectories(run, lengths=0.25)
    ax = fig.axes[0]
    assert len(ax.lines) == 2 and len(ax.collections) == 2  # the edges and the bands
    np.testing.assert_array_equal(ax.lines[1].get_ydata(), run.positions[:, 1])
    import matplotlib.pyplot as plt

    plt.close(fig)


# --- Monte Carlo of a queue (robust/row_monte_carlo.hpp, docs/rows.md section 11) ----------


def test_row_monte_carlo_without_uncertainty_is_row_stop_in_every_run():
    # every input known: each run is the nominal queue, so row_stop's end positions and errors
    # (sampled once a period, as the study samples) in every run, bit for bit
    ref = sa.row_stop(PROFILE, stopping_queue(), STEP, 400, samples_per_period=1)
    r = sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0, sa.ProcessUncertainty(),
                           runs=3, max_periods=400, tolerance=0.3)
    assert r.end_position.shape == (3, 3)
    assert r.stopped.dtype == np.bool_ and r.stopped.all()
    for run in range(3):
        np.testing.assert_array_equal(r.end_position[run], ref.x)
        np.testing.assert_array_equal(r.error[run], ref.error)
    np.testing.assert_array_equal(r.p_within, [1.0, 1.0, 1.0])
    assert r.p_all_within == 1.0


def test_row_monte_carlo_draws_follow_draw_inputs_and_the_threads_do_not_matter():
    # part 0 of run r draws what the single-part study draws (draw_inputs); mu is the factor on
    # the nominal 0.3; the per-run inputs are part 0's for every part
    u = sa.ProcessUncertainty(mu="normal:0.3,5%", c_mu="uniform:3.5,4.5",
                              x_mu_offset="uniform:-0.02,0.02")
    one = sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0, u, runs=8, seed=3,
                             max_periods=400, threads=1)
    two = sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0, u, runs=8, seed=3,
                             max_periods=400, threads=2)
    assert one == two
    single = sa.draw_inputs(sa.DesignRequest(mu=0.3, c_mu=4.0), u, seed=3, runs=8)
    np.testing.assert_array_equal(one.inputs["mu"][:, 0], single["mu"] / 0.3)
    for name in ("c_mu", "x_mu_offset"):
        for part in range(3):
            np.testing.assert_array_equal(one.inputs[name][:, part], single[name])
    assert np.isnan(one.inputs["width"]).all()
    assert not np.array_equal(one.inputs["mu"][:, 1], one.inputs["mu"][:, 0])  # own stream
    # the summary from the columns
    stopped = one.queue_stopped
    np.testing.assert_allclose(one.end_mean, one.end_position[stopped].mean(axis=0), rtol=1e-14)
    np.testing.assert_allclose(one.error_sd, one.error[stopped].std(axis=0, ddof=1), rtol=1e-12)
    assert pickle.loads(pickle.dumps(one)) == one


def test_row_monte_carlo_absent_values_are_nan_and_bad_input_is_named():
    u = sa.ProcessUncertainty(c_mu="uniform:3.5,4.5")
    r = sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0, u, runs=2, max_periods=2)
    assert not r.queue_stopped.any()
    assert np.isnan(r.end_position).all() and np.isnan(r.error).all()
    assert np.isnan(r.end_mean).all() and (r.within == 0).all()
    # no run stopped: no quantile (empirical_quantile's NaN, as MonteCarloResult's)
    assert math.isnan(r.process_time_quantile(0, 0.5))
    with pytest.raises(sa.InvalidParameter, match="width.uncertain"):
        sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0,
                           sa.ProcessUncertainty(width="uniform:0.9,1.1"), runs=2)
    with pytest.raises(sa.InvalidParameter, match="runs"):
        sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0, u, runs=0)
    with pytest.raises(sa.InvalidParameter, match="tolerance"):
        sa.row_monte_carlo(PROFILE, stopping_queue(), 1.5, 4.0, u, runs=2, tolerance=0.0)
