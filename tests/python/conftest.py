"""Shared fixtures of the gearsim Python module's tests (run by ctest, label python).

GEARSIM_SOURCE_DIR and GEARSIM_BINARY_DIR come from ctest (tests/python/CMakeLists.txt); the
module is imported from GEARSIM_BINARY_DIR/python (PYTHONPATH)."""
import csv
import os
import pathlib
import subprocess

import numpy
import pytest

SOURCE = pathlib.Path(os.environ.get("GEARSIM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = pathlib.Path(os.environ.get("GEARSIM_BINARY_DIR", SOURCE / "build"))
SCENARIOS = SOURCE / "assets" / "scenarios"


def scenario_path(name):
    return SCENARIOS / name


def read_csv_columns(path):
    """A CSV log as {column: float64 array}, every value parsed by float() (correctly rounded)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], rows[1:]
    return {name: numpy.array([float(r[c]) for r in data], dtype=numpy.float64) for c, name in enumerate(header)}


def run_cli(*args):
    """Runs build/bin/gearsim with args; returns the completed process (check=True)."""
    return subprocess.run([str(BINARY / "bin" / "gearsim"), *map(str, args)], check=True,
                          capture_output=True, text=True)


@pytest.fixture(scope="session")
def spur_cli_run(tmp_path_factory):
    """The CLI's run of spur_pair.yaml for 0.05 s with one override, not analysed."""
    out = tmp_path_factory.mktemp("spur_cli")
    run_cli("run", scenario_path("spur_pair.yaml"), "--out", out, "--duration", "0.05",
            "--set", "output.per_step_log=false", "--no-analyze")
    return out


@pytest.fixture(scope="session")
def spur_analysable_run(tmp_path_factory):
    """A run of spur_pair.yaml long enough to analyse (0.3 s, with its per-step log), by gearsim.run."""
    import gearsim
    out = tmp_path_factory.mktemp("spur_py")
    gearsim.run(gearsim.load_scenario(scenario_path("spur_pair.yaml")), out=out, duration=0.3)
    return out
