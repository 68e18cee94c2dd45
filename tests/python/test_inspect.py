"""gearsim.inspect: what `gearsim inspect MESH --json` reports for a CAD mesh."""
import json

import pytest

import gearsim
from conftest import SOURCE, run_cli

MESH = SOURCE / "assets" / "gears" / "spur_pair" / "pinion.stl"


def without_timing(report):
    return {k: v for k, v in report.items() if k != "decompose_seconds"}


@pytest.mark.parametrize("args, kwargs", [([], {}), (["--teeth", "20", "--unit", "mm"], {"teeth": 20, "unit": "mm"})])
def test_the_report_equals_the_cli_json(args, kwargs):
    cli = json.loads(run_cli("inspect", MESH, *args, "--json").stdout)
    py = gearsim.inspect(MESH, **kwargs)
    assert without_timing(py) == without_timing(cli)


def test_the_volume_is_the_gear_tables_and_the_gear_is_recognised():
    # The STL holds float32 mm coordinates of the generated pinion: its volume is the generated
    # mesh's to float32 rounding (~1e-7 relative per coordinate, 1e-6 for the volume).
    report = gearsim.inspect(MESH)
    generated = gearsim.gear(SOURCE / "assets" / "specs" / "spur_pair_gearset.yaml", "pinion")
    assert report["volume_mm3"] * 1e-9 == pytest.approx(generated["mesh"]["volume_m3"], rel=1e-6)
    assert report["gear"]["teeth"] == generated["teeth"]
    assert report["gear"]["module_mm"] == pytest.approx(generated["module_m"] * 1e3, rel=1e-6)


def test_a_missing_file_raises_input_error_naming_it(tmp_path):
    with pytest.raises(gearsim.InputError, match="nothing.stl"):
        gearsim.inspect(tmp_path / "nothing.stl")


def test_a_damaged_file_raises_input_error_naming_it(tmp_path):
    bad = tmp_path / "damaged.stl"
    bad.write_bytes(b"solid x\nfacet normal 0 0 1\nthis is not STL\n")
    with pytest.raises(gearsim.InputError, match="damaged.stl"):
        gearsim.inspect(bad)


def test_an_open_mesh_raises_input_error_naming_file_and_edge(tmp_path):
    one = tmp_path / "one_triangle.stl"
    one.write_text("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                   "endloop\nendfacet\nendsolid t\n")
    with pytest.raises(gearsim.InputError, match="one_triangle.stl.*edge"):
        gearsim.inspect(one)


def test_an_unknown_unit_raises_input_error_naming_it():
    with pytest.raises(gearsim.InputError, match="unit.*furlong"):
        gearsim.inspect(MESH, unit="furlong")
