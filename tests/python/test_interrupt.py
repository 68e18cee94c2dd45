"""Ctrl-C during gearsim.run: the run stops between two steps, its logs are complete and
summary.json says interrupted, and KeyboardInterrupt is raised once the run has stopped."""
import json
import os
import signal
import threading

import pytest

import gearsim
from conftest import scenario_path


def test_sigint_stops_the_run_and_raises_keyboard_interrupt(tmp_path):
    s = gearsim.load_scenario(scenario_path("spur_pair.yaml"), {"output.per_step_log": False})
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            gearsim.run(s, out=tmp_path, duration=100.0)  # ~5 min if not stopped
    finally:
        timer.cancel()
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["status"] == "interrupted"
    assert summary["signal"] == "SIGINT"
    assert 0 < summary["sim_seconds"] < 100.0
    rows = (tmp_path / "state.csv").read_text().splitlines()[1:]
    assert float(rows[-1].split(",")[0]) == pytest.approx(summary["sim_seconds"], abs=1e-9)
