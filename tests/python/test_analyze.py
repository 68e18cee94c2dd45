"""gearsim.analyze: the analysis.json dict of a run folder, as `gearsim analyze` writes it."""
import json
import shutil

import numpy
import pytest

import gearsim
from conftest import read_csv_columns, run_cli


def test_analyze_returns_the_analysis_json(tmp_path, spur_analysable_run):
    folder = tmp_path / "run"
    shutil.copytree(spur_analysable_run, folder)
    analysis = gearsim.analyze(folder)
    spectrum = analysis.pop("spectrum")
    assert analysis == json.loads((folder / "analysis.json").read_text())
    assert "pinion__wheel" in json.dumps(analysis)
    # The spectra as arrays: spectrum.csv by column, bit for bit.
    expected = read_csv_columns(folder / "spectrum.csv")
    assert list(spectrum) == list(expected) == ["frequency_hz", "pinion__wheel_amplitude_N"]
    for name, values in expected.items():
        assert numpy.array_equal(spectrum[name], values), name
    # Its largest line is a mesh harmonic: the pair's mesh frequency or a multiple of it.
    f_mesh = analysis["pairs"]["pinion__wheel"]["mesh_harmonics"][0]["expected_hz"]
    peak = spectrum["frequency_hz"][numpy.argmax(spectrum["pinion__wheel_amplitude_N"][1:]) + 1]
    assert abs(peak / f_mesh - round(peak / f_mesh)) < 0.02 and round(peak / f_mesh) >= 1


def test_analyze_equals_the_cli_analysis(tmp_path, spur_analysable_run):
    folder = tmp_path / "run"
    shutil.copytree(spur_analysable_run, folder)
    analysis = gearsim.analyze(folder)
    analysis.pop("spectrum")
    run_cli("analyze", folder)
    assert analysis == json.loads((folder / "analysis.json").read_text())


def test_analyze_of_a_folder_that_is_no_run_raises_input_error(tmp_path):
    with pytest.raises(gearsim.InputError, match="summary.json"):
        gearsim.analyze(tmp_path)
