"""gearsim.run and gearsim.analyze hold their folder as the CLI does: one writer at a time
(gearsim.FolderBusy, an OSError, naming the holder), a folder of the user's files refused and
left as it was, a previous run's outputs (its manifest's) removed."""
import fcntl

import pytest

import gearsim
from conftest import scenario_path


def spur():
    return gearsim.load_scenario(scenario_path("spur_pair.yaml"), {"output.per_step_log": False})


def test_a_folder_another_command_holds_is_refused_naming_it(tmp_path):
    with open(tmp_path / ".gearsim.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        lock.write("gearsim run (pid 1, since 2026-01-01T00:00:00Z)\n")
        lock.flush()
        with pytest.raises(gearsim.FolderBusy, match="in use by gearsim run \\(pid 1"):
            gearsim.run(spur(), out=tmp_path, duration=0.05)
        with pytest.raises(OSError):
            gearsim.analyze(tmp_path)
    assert not (tmp_path / "state.csv").exists()


def test_a_folder_of_the_users_files_is_refused_and_left_as_it_was(tmp_path):
    (tmp_path / "state.csv").write_text("mine\n")
    with pytest.raises(gearsim.InputError, match="holds files that gearsim did not write"):
        gearsim.run(spur(), out=tmp_path, duration=0.05)
    assert (tmp_path / "state.csv").read_text() == "mine\n"


def test_a_second_run_removes_the_first_runs_outputs_only(tmp_path):
    gearsim.run(spur(), out=tmp_path, duration=0.3)
    gearsim.analyze(tmp_path)
    assert (tmp_path / "analysis.json").exists()
    (tmp_path / "notes.txt").write_text("mine\n")
    gearsim.run(spur(), out=tmp_path, duration=0.05)
    assert not (tmp_path / "analysis.json").exists()
    assert (tmp_path / "notes.txt").read_text() == "mine\n"
    assert (tmp_path / "state.csv").exists()


def test_a_run_whose_writes_fail_raises_output_error(tmp_path):
    # The tests' failing writer (tests/support/fail_writes.cpp) preloaded into a fresh interpreter:
    # from the 5th write to a file on, every write fails with ENOSPC, as on a full disk.
    import os
    import subprocess
    import sys
    from conftest import BINARY
    script = ("import gearsim, sys\n"
              f"s = gearsim.load_scenario({str(scenario_path('spur_pair.yaml'))!r})\n"
              "try:\n"
              f"    gearsim.run(s, out={str(tmp_path / 'out')!r}, duration=0.3)\n"
              "except gearsim.OutputError as e:\n"
              "    print('OutputError:', e)\n")
    env = dict(os.environ, LD_PRELOAD=str(BINARY / "tests" / "libgearsim_fail_writes.so"), GEARSIM_FAIL_WRITES_FROM="5")
    r = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "OutputError:" in r.stdout and "No space left on device" in r.stdout, r.stdout + r.stderr
