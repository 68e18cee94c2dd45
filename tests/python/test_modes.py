"""gearsim.modes: the modal analysis as `gearsim modes --json` gives it."""
import json

import pytest

import gearsim
from conftest import run_cli, scenario_path


@pytest.fixture(scope="module")
def lin_parker():
    return gearsim.load_scenario(scenario_path("lin_parker_1999.yaml"))


def test_lin_parker_has_18_natural_frequencies_the_first_rigid(lin_parker):
    m = gearsim.modes(lin_parker)
    f = m["natural_frequencies_hz"]
    assert len(f) == 18  # 3 planar coordinates × (sun, ring, carrier, 3 planets)
    assert f[0] == 0  # the free rotation of the train
    assert all(a <= b for a, b in zip(f, f[1:]))


def test_modes_equal_the_cli_json(lin_parker):
    cli = json.loads(run_cli("modes", scenario_path("lin_parker_1999.yaml"), "--json").stdout)
    assert gearsim.modes(lin_parker) == cli


def test_a_bad_drive_raises_input_error(lin_parker):
    with pytest.raises(gearsim.InputError, match="drive"):
        gearsim.modes(lin_parker, drive="sun=up")
