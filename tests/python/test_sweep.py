"""gearsim.sweep: a sweep run as `gearsim sweep` runs it, its table as arrays."""
import csv
import json
import os
import signal
import threading
import time

import numpy
import pytest

import gearsim
from conftest import BINARY, run_cli, scenario_path

PARAMETER = "loads[0].constant_torque_N_m"


def write_sweep(folder, duration_s=0.05, collect="summary: [created_energy_J, max_penetration_um, steps]", grid=None):
    """A two-case sweep of spur_pair.yaml (two wheel loads), short runs, without the step log."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "sweep.yaml"
    path.write_text(f"name: tiny\nscenario: {scenario_path('spur_pair.yaml')}\n"
                    f"set: [\"duration_s={duration_s}\", \"output.per_step_log=false\"]\n"
                    f"grid:\n  {grid or PARAMETER + ': [5, 10]'}\ncollect:\n  {collect}\n")
    return path


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    """The same sweep by the CLI and by gearsim.sweep (while another Python thread counts)."""
    root = tmp_path_factory.mktemp("sweep")
    sweep_file = write_sweep(root)
    run_cli("sweep", sweep_file, "--out", root / "cli", "--jobs", 2)
    ticks = []
    stop = threading.Event()
    counter = threading.Thread(target=lambda: [ticks.append(1) or time.sleep(0.01) for _ in iter(stop.is_set, True)])
    counter.start()
    table = gearsim.sweep(sweep_file, root / "py", jobs=2)
    stop.set()
    counter.join()
    return root, sweep_file, table, len(ticks)


def test_the_table_equals_the_cli_sweep_csv(swept):
    root, _, table, _ = swept
    header, rows = read_table(root / "cli" / "sweep.csv")
    assert list(table) == header
    assert table["index"].dtype == numpy.int64 and table["index"].tolist() == [int(r[0]) for r in rows]
    assert table["status"] == [r[header.index("status")] for r in rows] == ["completed", "completed"]
    for c, name in enumerate(header):
        if name not in ("index", "status"):
            assert table[name].tolist() == [float(r[c]) for r in rows], name


def test_the_files_equal_the_cli_sweep_csv(swept):
    root, _, _, _ = swept
    assert (root / "py" / "sweep.csv").read_bytes() == (root / "cli" / "sweep.csv").read_bytes()


def test_the_load_changes_the_result(swept):
    # Twice the wheel load: deeper contact.
    _, _, table, _ = swept
    assert table[PARAMETER].tolist() == [5.0, 10.0]
    assert table["summary.max_penetration_um"][1] > table["summary.max_penetration_um"][0]


def test_another_python_thread_runs_while_the_sweep_runs(swept):
    # The sweep takes about a second (two runs, each ~0.3 s of setup and stepping); a thread
    # ticking every 10 ms with the GIL free ticks dozens of times, with it held hardly once.
    assert swept[3] > 10


def test_sweeping_again_resumes_without_running_a_case(swept):
    root, sweep_file, table, _ = swept
    records = sorted((root / "py" / "cases").glob("*/case.json"))
    before = [p.stat().st_mtime_ns for p in records]
    again = gearsim.sweep(sweep_file, root / "py", jobs=2)
    assert [p.stat().st_mtime_ns for p in records] == before
    assert again["status"] == table["status"] and again["summary.steps"].tolist() == table["summary.steps"].tolist()


def test_cases_that_do_not_complete_raise_with_the_table(tmp_path):
    # mean_force_N needs a steady window after the ramps; 0.05 s runs have none: both cases fail
    # (the CLI exits with 5).
    sweep_file = write_sweep(tmp_path, collect="metrics: [mean_force_N]")
    with pytest.raises(gearsim.SweepCasesFailed, match="2 of 2 cases did not complete") as failed:
        gearsim.sweep(sweep_file, tmp_path / "out", jobs=2)
    assert failed.value.table["status"] == ["failed", "failed"]
    # check=False: the same table returned (failed cases are final: nothing runs again).
    assert gearsim.sweep(sweep_file, tmp_path / "out", check=False)["status"] == ["failed", "failed"]


def test_a_bad_sweep_file_raises_input_error_naming_the_key(tmp_path):
    sweep_file = write_sweep(tmp_path, grid="motors[0].no_such_key_rad_s: [1, 2]")
    with pytest.raises(gearsim.InputError, match="no_such_key_rad_s"):
        gearsim.sweep(sweep_file, tmp_path / "out")
    assert not (tmp_path / "out" / "cases").exists()  # refused before anything ran


def test_a_missing_executable_raises_input_error(tmp_path):
    with pytest.raises(gearsim.InputError, match="executable"):
        gearsim.sweep(write_sweep(tmp_path), tmp_path / "out", executable=tmp_path / "no_gearsim")


def test_ctrl_c_interrupts_the_sweep_leaving_it_resumable(tmp_path):
    # Two 100 s cases; SIGINT to this process once both log. The running cases get SIGINT, are
    # recorded interrupted (not final: a resume runs them again) and the table is written.
    sweep_file = write_sweep(tmp_path, duration_s=100)
    logs = [tmp_path / "out" / "cases" / f"0000{i}" / "state.csv" for i in (0, 1)]

    def interrupt_once_stepping():
        deadline = time.monotonic() + 20
        while not all(p.exists() for p in logs) and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.2)
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt_once_stepping).start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        gearsim.sweep(sweep_file, tmp_path / "out", jobs=2, executable=BINARY / "bin" / "gearsim")
    assert time.monotonic() - started < 40
    header, rows = read_table(tmp_path / "out" / "sweep.csv")
    assert [r[header.index("status")] for r in rows] == ["interrupted", "interrupted"]
    for record in sorted((tmp_path / "out" / "cases").glob("*/case.json")):
        assert json.loads(record.read_text())["status"] == "interrupted"
    summary = json.loads((tmp_path / "out" / "cases" / "00000" / "summary.json").read_text())
    assert summary["status"] == "interrupted" and summary["sim_seconds"] < 100
