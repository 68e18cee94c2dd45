"""gearsim.run: the same arrays as the CLI's CSV files, bit for bit; out= writes the CLI's files."""
import json

import numpy

import gearsim
from conftest import read_csv_columns, scenario_path


def spur(**overrides):
    return gearsim.load_scenario(scenario_path("spur_pair.yaml"), {"output.per_step_log": False, **overrides})


def assert_same_columns(arrays, csv_file):
    expected = read_csv_columns(csv_file)
    assert list(arrays) == list(expected)
    for name, values in expected.items():
        assert arrays[name].dtype == numpy.float64
        assert numpy.array_equal(arrays[name], values), name


def test_arrays_equal_the_cli_csv_bit_for_bit(spur_cli_run):
    r = gearsim.run(spur(), duration=0.05)
    assert r.out is None
    assert_same_columns(r.state, spur_cli_run / "state.csv")
    assert_same_columns(r.contacts, spur_cli_run / "contacts.csv")
    assert "te_rad" in r.state and "pinion__wheel_force_N" in r.contacts


def test_summary_has_the_cli_summary_keys(spur_cli_run):
    r = gearsim.run(spur(), duration=0.05)
    cli = json.loads((spur_cli_run / "summary.json").read_text())
    assert list(r.summary) == list(cli)
    assert r.summary["status"] == "completed"
    assert r.summary["steps"] == cli["steps"] == 2500  # 0.05 s / 2e-5 s
    assert r.summary["bodies"] == cli["bodies"]


def test_out_writes_the_cli_files(tmp_path, spur_cli_run):
    r = gearsim.run(spur(), out=tmp_path, duration=0.05)
    assert r.out == str(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in spur_cli_run.iterdir())
    for name in ("state.csv", "contacts.csv", "scenario.json"):
        assert (tmp_path / name).read_bytes() == (spur_cli_run / name).read_bytes(), name
    assert json.loads((tmp_path / "summary.json").read_text())["status"] == "completed"
