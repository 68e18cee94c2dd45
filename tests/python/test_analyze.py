"""gearsim.analyze: the analysis.json dict of a run folder, as `gearsim analyze` writes it."""
import json
import shutil

import pytest

import gearsim
from conftest import run_cli


def test_analyze_returns_the_analysis_json(tmp_path, spur_analysable_run):
    folder = tmp_path / "run"
    shutil.copytree(spur_analysable_run, folder)
    analysis = gearsim.analyze(folder)
    assert analysis == json.loads((folder / "analysis.json").read_text())
    assert "pinion__wheel" in json.dumps(analysis)


def test_analyze_equals_the_cli_analysis(tmp_path, spur_analysable_run):
    folder = tmp_path / "run"
    shutil.copytree(spur_analysable_run, folder)
    analysis = gearsim.analyze(folder)
    run_cli("analyze", folder)
    assert analysis == json.loads((folder / "analysis.json").read_text())


def test_analyze_of_a_folder_that_is_no_run_raises_input_error(tmp_path):
    with pytest.raises(gearsim.InputError, match="summary.json"):
        gearsim.analyze(tmp_path)
