"""gearsim.run: the same arrays as the CLI's CSV files, bit for bit; out= writes the CLI's files."""
import json
import threading
import time

import numpy

import gearsim
from conftest import read_csv_columns, run_cli, scenario_path


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


def test_paper_arrays_with_sensors_equal_the_cli_csv(tmp_path):
    overrides = ["output.per_step_log=false", "solver.time_step_s=2e-5"]
    run_cli("run", scenario_path("paper_dynamics_healthy.yaml"), "--out", tmp_path, "--duration", "0.06",
            *[f"--set={o}" for o in overrides], "--no-analyze")
    r = gearsim.run(gearsim.load_scenario(scenario_path("paper_dynamics_healthy.yaml"), overrides), duration=0.06)
    assert_same_columns(r.state, tmp_path / "state.csv")
    assert_same_columns(r.contacts, tmp_path / "contacts.csv")
    assert_same_columns(r.sensors, tmp_path / "sensors.csv")
    assert {"sun_angle_rad", "te_rad"} <= set(r.state) and "sun__planet_0_force_N" in r.contacts


def test_the_gil_is_released_while_the_world_steps():
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=count)
    thread.start()
    start = time.perf_counter()
    try:
        gearsim.run(spur(), duration=0.5)  # ~0.7 s of stepping
    finally:
        stop.set()
        thread.join()
    during = [t for t in ticks if t > start + 0.1]
    assert len(during) > 50  # a thread that could not run would not tick while the run steps


def test_steps_hold_every_contact_of_every_step_as_the_point_samples_say():
    # contacts.csv's point sample of a pair at an output step is the sum of that step's tooth-pair
    # forces, which steps.h5 holds as impulses: the two logs agree to rounding.
    r = gearsim.run(spur(**{"output.per_step_log": True}), duration=0.05)
    s = r.steps
    assert s["pairs"] == ["pinion__wheel"]
    dt = s["time_step_s"]
    assert dt == r.summary["time_step_s"]
    assert s["step"].dtype == numpy.int64 and s["normal_impulse_N_s"].dtype == numpy.float64
    assert numpy.all(numpy.diff(s["step"]) >= 0) and s["step"].max() == r.summary["steps"]
    assert set(numpy.unique(s["flank_a"])) <= {0, 1}
    steps_of_rows = numpy.rint(r.contacts["time_s"] / dt).astype(numpy.int64)
    per_step = numpy.bincount(s["step"], weights=s["normal_impulse_N_s"], minlength=r.summary["steps"] + 1) / dt
    expected = r.contacts["pinion__wheel_force_point_N"]
    assert numpy.allclose(per_step[steps_of_rows], expected, rtol=1e-12, atol=1e-9)
    assert expected.max() > 100  # a loaded mesh (10 N·m on the wheel), not zeros
    assert gearsim.run(spur(), duration=0.01).steps == {}  # no per-step log: no entry
