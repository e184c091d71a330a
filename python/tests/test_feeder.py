"""The vibratory feeder from Python (docs/feeder.md): the closed-form onsets by hand, and the
contact core's run finding them (the second method), in SI units."""
import math

import numpy as np
import pytest

import selfalign as sa


def test_onsets_by_hand():
    # psi = theta = 0: both slips at K = mu_s, no lift-off; Gamma = 1 is the lift-off.
    o = sa.feeder_onsets(0.0, 0.0, 0.4)
    assert o.forward_slip == pytest.approx(0.4, rel=1e-15)
    assert o.backward_slip == pytest.approx(0.4, rel=1e-15)
    assert math.isinf(o.lift_off)
    assert sa.feeder_onsets(0.5, 0.1, 0.4).lift_off == pytest.approx(math.cos(0.1) / math.sin(0.5))
    drive = sa.FeederDrive(amplitude=1e-3, period=0.02, vibration_angle=0.5, incline=0.1, g=9.81)
    K = 1e-3 * (2 * math.pi / 0.02) ** 2 / 9.81
    assert sa.machine_number(drive) == pytest.approx(K, rel=1e-14)
    assert sa.throw_number(drive) == pytest.approx(K * math.sin(0.5) / math.cos(0.1), rel=1e-14)


@pytest.mark.parametrize("method", ["exact", "time-stepping"])
def test_a_run_in_si_units_slips_forward_just_above_the_onset(method):
    # A 50 Hz drive at psi = 20 deg on a level track, mu_s = 0.5, mu_k = 0.4, in SI (g = 9.81,
    # level g so that the friction bound is mu (g cos theta + z'')): nothing at 0.97 times the
    # forward onset, a forward slip at 1.03 times it, and a positive conveying velocity.
    psi, mu_s, g, period = math.radians(20), 0.5, 9.81, 0.02
    onset = sa.feeder_onsets(psi, 0.0, mu_s).forward_slip
    w = 2 * math.pi / period
    law = sa.FrictionLaw(mu_s, 0.4)
    below = sa.feeder_run(sa.FeederDrive(0.97 * onset * g / w**2, period, psi, 0.0, g), law,
                          level=g, steps_per_period=4000, periods=3, method=method)
    above = sa.feeder_run(sa.FeederDrive(1.5 * onset * g / w**2, period, psi, 0.0, g), law,
                          level=g, steps_per_period=4000, periods=10, method=method)
    assert below.first_event == sa.FeederEvent.none and below.stick_fraction == 1.0
    assert above.first_event == sa.FeederEvent.forward_slip
    assert above.velocity > 0 and not above.lifted_off
    hop = sa.FeederDrive(1.03 * sa.feeder_onsets(psi, 0.0, mu_s).lift_off * g / w**2, period, psi,
                         0.0, g)
    stopped = sa.feeder_run(hop, law, level=g, periods=3, flight=False, method=method)
    assert stopped.lifted_off and math.isnan(stopped.velocity)
    hopping = sa.feeder_run(hop, law, level=g, periods=3, method=method)
    assert hopping.lifted_off and hopping.first_event == sa.FeederEvent.forward_slip
    assert 0 < hopping.flight_fraction < 1 and hopping.velocity > 0
    # the classical lift-off phase asin(1 / Gamma): exactly, or to 1.5 steps (2000 per period)
    gamma = sa.throw_number(hop)
    assert hopping.lift_off_phase == pytest.approx(
        math.asin(1 / gamma), abs=1e-9 if method == "exact" else 2 * math.pi * 1.5 / 2000)


def test_bad_input_names_the_parameter():
    with pytest.raises(sa.InvalidParameter) as e:
        sa.FeederDrive(amplitude=1e-3, vibration_angle=math.pi / 2)
    assert e.value.name == "vibration_angle"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.feeder_onsets(0.1, 0.0, -1.0)
    assert e.value.name == "static_friction"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.feeder_run(sa.FeederDrive(1e-3), steps_per_period=1, method="time-stepping")
    assert e.value.name == "steps_per_period"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.feeder_run(sa.FeederDrive(1e-3), restitution=1.5)
    assert e.value.name == "restitution"
    with pytest.raises(sa.InvalidParameter) as e:
        sa.feeder_run(sa.FeederDrive(1e-3), method="integrator")
    assert e.value.name == "method"


def test_the_regime_chart_is_the_closed_form_regimes_and_the_runs():
    # A 3 x 8 chart: the regime array is feeder_onsets' classification cell by cell (by hand
    # here), the runs stick exactly where the regime is stick and lift off where it hops.
    angles = [0.0, 0.3, 0.8]
    ks = [0.2, 0.4, 0.6, 0.9, 1.3, 2.0, 3.0, 4.5]
    chart = sa.feeder_regime_chart(angles, ks, incline=0.02, mu_static=0.5, mu_kinetic=0.4,
                                   steps_per_period=400)
    assert chart["regime"].shape == (3, 8) and not chart["failed"].any()
    for i, psi in enumerate(angles):
        o = sa.feeder_onsets(psi, 0.02, 0.5)
        for j, K in enumerate(ks):
            if K >= o.lift_off:
                expected = sa.FeederRegime.hopping
            elif K > o.forward_slip and K > o.backward_slip:
                expected = sa.FeederRegime.both
            elif K > o.forward_slip:
                expected = sa.FeederRegime.forward
            elif K > o.backward_slip:
                expected = sa.FeederRegime.backward
            else:
                expected = sa.FeederRegime.stick
            assert chart["regime"][i, j] == expected
            near = any(abs(K - k) < 0.05 * k for k in (o.forward_slip, o.backward_slip, o.lift_off))
            if not near:
                assert (chart["first_event"][i, j] == sa.FeederEvent.none) == (expected == sa.FeederRegime.stick)
                assert bool(chart["lifted_off"][i, j]) == (expected == sa.FeederRegime.hopping)


def test_the_regime_chart_figure(tmp_path):
    # The onset curves are feeder_onsets' values (by hand at psi = 0: K_f = K_b = mu_s, no
    # lift-off); the figure is written atomically as a PNG.
    from selfalign import feeder_figures

    curves = feeder_figures.onset_curves([0.0, 0.5], 0.0, 0.5)
    assert curves["forward_slip"][0] == pytest.approx(0.5) and math.isinf(curves["lift_off"][0])
    assert curves["lift_off"][1] == pytest.approx(1 / math.sin(0.5))
    chart = sa.feeder_regime_chart([0.0, 0.4, 0.8], [0.2, 0.6, 1.5, 4.0], mu_static=0.5,
                                   mu_kinetic=0.4, periods=3)
    png = tmp_path / "regimes.png"
    ax = feeder_figures.plot_regime_chart(chart, incline=0.0, mu_static=0.5, path=png)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert ax.get_xscale() == "log"
    assert [p.name for p in tmp_path.iterdir()] == ["regimes.png"]


def test_a_part_stops_past_a_friction_step_by_both_methods():
    # SI: 50 Hz, psi = 0.35, theta = 0.02, K = 1.5; mu 0.5 / 0.4 before 10 mm, 7 times that
    # after (the rough side's onsets hold a part at this K). The exact stop and the contact
    # core's at 20 000 steps per period agree to its order-1 error (measured 8e-7 m; at 2 000
    # steps the part reaches the step a period earlier and stops 0.35 um past it instead of
    # 58 um: the depth depends on the phase of arrival).
    g, period = 9.81, 0.02
    w = 2 * math.pi / period
    drive = sa.FeederDrive(1.5 * g / w**2, period, 0.35, 0.02, g)
    law = sa.FrictionLaw(0.5, 0.4)
    exact = sa.feeder_stop(drive, law, step_position=0.01, c_mu=7.0, level=g)
    stepped = sa.feeder_stop(drive, law, step_position=0.01, c_mu=7.0, level=g,
                             method="time-stepping", steps_per_period=20000)
    assert exact.stopped and stepped.stopped
    assert exact.end_position > 0.01 and not exact.lifted_off
    assert stepped.end_position == pytest.approx(exact.end_position, abs=5e-6)
    # the end of the last step that moved: measured 3.2e-5 s (1.6e-3 periods) before the exact
    # stop
    assert stepped.stop_time == pytest.approx(exact.stop_time, abs=2e-3 * period)
    assert stepped.periods == exact.periods
    never = sa.feeder_stop(sa.FeederDrive(1.3 / math.sin(0.35) * g / w**2, period, 0.35, 0.0, g),
                           law, step_position=0.01, c_mu=3.0, level=g, max_periods=20)
    assert not never.stopped and math.isnan(never.end_position) and never.periods == 20
    with pytest.raises(sa.InvalidParameter) as e:
        sa.feeder_stop(drive, law, step_position=0.01, c_mu=0.0)
    assert e.value.name == "c_mu"


def test_the_designed_drive_conveys_at_the_target_by_both_methods():
    # SI, 50 Hz, theta = 0.02, mu 0.5 / 0.4: 0.01 m/s without a flight. The design's amplitude
    # at its angle conveys at the target by the exact run and, to its order-1 error, by the
    # contact core (measured 1.4e-5 relative at 20 000 steps per period).
    d = sa.design_feeder_drive(0.01, period=0.02, incline=0.02, mu_static=0.5, mu_kinetic=0.4,
                               g=9.81)
    assert d["feasible"]
    best = d["best"]
    assert best["machine_number"] == pytest.approx(np.nanmin(d["candidates"]["machine_number"]))
    assert best["throw_number"] <= 1.0 and best["flight_angle"] == 0.0
    drive = sa.FeederDrive(best["amplitude"], 0.02, best["vibration_angle"], 0.02, 9.81)
    law = sa.FrictionLaw(0.5, 0.4)
    exact = sa.feeder_run(drive, law, level=9.81, periods=20)
    moreau = sa.feeder_run(drive, law, level=9.81, periods=20, method="time-stepping",
                           steps_per_period=20000)
    assert exact.velocity == pytest.approx(0.01, rel=1e-6)
    assert moreau.velocity == pytest.approx(0.01, rel=1e-3)
    assert not exact.lifted_off
    unreachable = sa.design_feeder_drive(5.0, period=0.02, g=9.81, vibration_angles=[0.3, 0.6])
    assert not unreachable["feasible"] and math.isnan(unreachable["best"]["amplitude"])
    assert all(r is not None for r in unreachable["candidates"]["reason"])
    with pytest.raises(sa.InvalidParameter) as e:
        sa.design_feeder_drive(0.0)
    assert e.value.name == "target_speed"


def test_the_reproduce_runs_feeder_figure_checks_the_flight_equation(tmp_path):
    # Fig. F1 (beyond the paper): the exact solver's flight angles against the bouncing-ball
    # flight equation solved by bisection in NumPy (feeder_figures.flight_equation_angle, the
    # equation alone), over 44 throw numbers; measured 7.1e-15 rad. The equation's root at
    # Gamma = 2 matches the C++ test's long-double bisection (4.658851475711560 rad).
    from selfalign import feeder_figures, figures
    assert feeder_figures.flight_equation_angle(2.0) == pytest.approx(4.658851475711560, abs=1e-12)
    fig = figures.figF1(str(tmp_path))
    assert fig.number == "F1" and fig.raw["worst_flight_difference"] < 1e-12
    for path in fig.files + fig.data:
        assert (tmp_path / path.split("/")[-1]).stat().st_size > 0


def test_python_m_selfalign_regimes_writes_the_clis_csv_and_a_png(tmp_path, capsys):
    # `python -m selfalign regimes` takes the C++ command's flags and writes the same CSV, byte
    # for byte (the same cells, the same shortest number text), plus the PNG figure; bad input
    # is one line naming the flag, exit 2, no file.
    import os
    import pathlib
    import subprocess
    from selfalign import regimes
    flags = ["--mu-static", "0.5", "--mu-kinetic", "0.4", "--angles", "6", "--machine-numbers",
             "9", "--incline", "0.03"]
    assert regimes.main(flags + ["--csv", str(tmp_path / "py.csv"),
                                 "--png", str(tmp_path / "py.png")]) == 0
    assert (tmp_path / "py.png").stat().st_size > 0
    rows = (tmp_path / "py.csv").read_text().splitlines()
    assert len(rows) == 55 and rows[0].startswith("vibration_angle_rad,machine_number")
    root = pathlib.Path(__file__).resolve().parents[2]
    cli = pathlib.Path(os.environ.get("SELFALIGN_CLI", root / "build/release/apps/selfalign/selfalign"))
    if cli.exists():
        subprocess.run([str(cli), "regimes", *flags, "--csv", str(tmp_path / "cpp.csv"),
                        "--quiet"], check=True, capture_output=True)
        assert (tmp_path / "cpp.csv").read_bytes() == (tmp_path / "py.csv").read_bytes()
    capsys.readouterr()
    assert regimes.main(["--mu-static", "0.5", "--mu-kinetic", "0.9",
                         "--csv", str(tmp_path / "bad.csv")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "mu-kinetic" in err
    assert not (tmp_path / "bad.csv").exists()


def test_a_two_frequency_drive_has_the_onsets_of_its_shape():
    # r = 0.25, phi2 = pi/2: s = sin(phi) + cos(2 phi) peaks at 9/8 and dips to -2, by hand; the
    # lift-off onset is cos(theta) / (sin(psi) 9/8). The exact run and the contact core agree.
    drive = sa.FeederDrive(2.0 / (2 * math.pi) ** 2, 1.0, 0.4, 0.03, 1.0, harmonic_ratio=0.25,
                           harmonic_phase=math.pi / 2)
    shape = sa.feeder_shape(drive)
    assert shape.peak_up == pytest.approx(1.125, abs=1e-12)
    assert shape.peak_down == pytest.approx(2.0, abs=1e-12)
    onsets = sa.feeder_onsets(drive, 0.5)
    assert onsets.lift_off == pytest.approx(math.cos(0.03) / (math.sin(0.4) * 1.125), rel=1e-12)
    assert sa.throw_number(drive) == pytest.approx(2.0 * math.sin(0.4) * 1.125 / math.cos(0.03))
    law = sa.FrictionLaw(0.5, 0.4)
    exact = sa.feeder_run(drive, law, periods=6)
    stepped = sa.feeder_run(drive, law, periods=6, method="time-stepping", steps_per_period=50000)
    assert stepped.velocity == pytest.approx(exact.velocity, abs=5.0 / 50000)
    with pytest.raises(sa.InvalidParameter) as e:
        sa.FeederDrive(1e-3, harmonic_ratio=-1.0)
    assert e.value.name == "harmonic_ratio"
