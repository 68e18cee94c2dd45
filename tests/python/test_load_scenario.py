"""gearsim.load_scenario: the scenario file through input::load_scenario, errors as gearsim.InputError."""
import pytest
import yaml

import gearsim
from conftest import scenario_path


def test_input_error_is_a_value_error():
    assert issubclass(gearsim.InputError, ValueError)


def test_an_override_is_applied():
    s = gearsim.load_scenario(scenario_path("spur_pair.yaml"), {"solver.time_step_s": 1e-5, "duration_s": 0.25})
    assert s.time_step_s == 1e-5
    assert s.duration_s == 0.25
    assert s.overrides == ["solver.time_step_s=1e-05", "duration_s=0.25"]


def test_a_bad_override_raises_input_error_naming_the_key():
    with pytest.raises(gearsim.InputError, match="solver.time_step_s"):
        gearsim.load_scenario(scenario_path("spur_pair.yaml"), {"solver.time_step_s": -1.0})


def test_an_unknown_key_raises_input_error_naming_it():
    with pytest.raises(gearsim.InputError, match="solver.no_such_key"):
        gearsim.load_scenario(scenario_path("spur_pair.yaml"), ["solver.no_such_key=3"])


def test_a_missing_file_raises_input_error():
    with pytest.raises(gearsim.InputError):
        gearsim.load_scenario(scenario_path("no_such_scenario.yaml"))


def test_str_is_the_expanded_scenario_as_yaml():
    s = gearsim.load_scenario(scenario_path("paper_dynamics.yaml"))
    text = str(s)
    assert "\nname: " in text and "\n  time_step_s: " in text and not text.startswith("{")  # block YAML, not JSON
    record = yaml.safe_load(text)
    assert record == s.to_dict()  # every value, doubles to the last bit
    assert record["name"] == "paper_dynamics"


def test_set_reloads_with_one_more_override():
    s = gearsim.load_scenario(scenario_path("spur_pair.yaml"))
    assert s.set("output.sample_rate_hz", 5000) is s
    assert s.sample_rate_hz == 5000
    assert s.overrides == ["output.sample_rate_hz=5000"]


def test_a_refused_set_leaves_the_scenario_as_it_was():
    s = gearsim.load_scenario(scenario_path("spur_pair.yaml"))
    with pytest.raises(gearsim.InputError, match="duration_s"):
        s.set("duration_s", "not a number")
    assert s.overrides == []
    assert s.duration_s == 0.5
