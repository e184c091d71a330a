"""The parameter view from Python (model_parameters, with_parameters): the C++ view's names and
rules, configs as dicts of config keys. Expected values follow from y(t) -> a y(t / p) and the
config's own values, not from the view."""

import math

import pytest

import selfalign as sa


def by_name(config):
    return {p.name: p for p in sa.model_parameters(config)}


def test_the_view_lists_the_models_parameters_in_its_units():
    si = by_name({"units": "si", "mu": 0.2, "a2": 3.0, "a3": 2.0, "period": 0.05,
                  "stroke": 2e-4})
    assert si["a2"].value == 3.0 and si["a2"].unit == "[m/s^2]"
    assert si["mu_static"].value == 0.2          # unset: equal to mu
    assert math.isnan(si["stribeck_velocity"].value)  # absent, not 0
    assert "g" in si and si["amplitude_scale"].value == 1.0
    uniform = by_name({"friction": "uniform", "profile": "fourier", "fourier_cos": [0.1, 0.02]})
    assert "c_mu" not in uniform and "g" not in uniform
    assert "fourier_cos[1]" in uniform and "fourier_sin[0]" not in uniform


def test_with_parameters_rescales_the_motion_and_sets_elements():
    c = sa.with_parameters({"profile": "fourier", "fourier_cos": [0.1, 0.02], "period": 1.5},
                           {"fourier_cos[1]": 0.03, "amplitude_scale": 2.0, "time_scale": 0.5})
    assert c["fourier_cos"] == pytest.approx([0.2, 0.06], rel=1e-15)
    assert c["period"] == 0.75
    three = sa.with_parameters({}, {"time_scale": 2.0, "mu_static": 0.4})
    assert three["a2"] == 2.3 / 4 and three["stroke"] == 0.084 and three["mu_static"] == 0.4


@pytest.mark.parametrize("values, name", [
    ({"c_mu": 3.0}, "c_mu"),            # uniform table: no c_mu
    ({"step": 1e-3}, "step"),           # a solver setting
    ({"mu_statc": 0.4}, "mu_statc"),    # a typo
    ({"time_scale": 0.0}, "time_scale"),
    ({"x0": float("nan")}, "x0"),
])
def test_what_is_not_a_parameter_is_refused_by_name(values, name):
    with pytest.raises(sa.InvalidParameter) as e:
        sa.with_parameters({"friction": "uniform"}, values)
    assert e.value.name == name


def test_a_fields_samples_in_the_config_are_parameters():
    config = {"field_positions": [0.0, 0.5], "field_levels": [1.0, 2.5], "footprint": "point"}
    names = by_name(config)
    assert names["field_levels[1]"].value == 2.5 and "c_mu" not in names
    changed = sa.with_parameters(config, {"field_levels[1]": 3.0})
    assert changed["friction"] == "field" and changed["field_levels"] == [1.0, 3.0]


def test_the_planar_view_gives_the_files_numbers(tmp_path):
    # Second method: the example file read with the standard library's TOML reader. Every
    # parameter the file gives is listed with the file's value; a setting is not listed.
    import pathlib
    import tomllib
    example = pathlib.Path(__file__).resolve().parents[2] / "examples" / "planar.toml"
    doc = tomllib.loads(example.read_text())
    view = {p.name: p for p in sa.planar_model_parameters(example)}
    given = 0
    for name, p in view.items():
        section, _, key = name.rpartition(".")
        node = doc
        for part in section.split("."):
            node = node.get(part, {})
        key, _, index = key.partition("[")
        if key in node:
            value = node[key][int(index[:-1])] if index else node[key]
            assert p.value == value, name
            given += 1
    assert given >= 20
    assert "run.step" not in view and "scales.length" not in view and "part.mass" not in view
    assert view["field.centre[0]"].unit == "[m]" and view["run.pose[2]"].unit == "[rad]"
    # a change by name is applied first, checked as the file's values are
    changed = {p.name: p.value for p in sa.planar_model_parameters(
        str(example), ["field.centre[0]=0.02", "table.x.a2=5"])}
    assert changed["field.centre[0]"] == 0.02 and changed["table.x.a2"] == 5.0
    with pytest.raises(sa.InvalidParameter, match="field.c_mu"):
        sa.planar_model_parameters(example, ["field.c_mu=0.5"])
    with pytest.raises(TypeError):
        sa.planar_model_parameters(3)
