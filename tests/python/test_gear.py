"""gearsim.gear: a gear-set spec's gears as `gearsim gears --json` gives them, with outline and flank tables."""
import json

import numpy
import pytest

import gearsim
from conftest import SOURCE, run_cli

SPEC = SOURCE / "assets" / "specs" / "spur_pair_gearset.yaml"


@pytest.fixture(scope="module")
def cli():
    return json.loads(run_cli("gears", SPEC, "--json").stdout)


@pytest.fixture(scope="module")
def gears():
    return gearsim.gear(SPEC)


def shoelace_area(x, y):
    """Signed area of a closed polygon (last point not repeated), m²."""
    return 0.5 * numpy.sum(x * numpy.roll(y, -1) - numpy.roll(x, -1) * y)


def test_every_gear_of_the_spec_in_file_order(gears, cli):
    assert list(gears) == list(cli["gears"]) == ["pinion", "wheel"]


def test_the_gear_table_equals_the_cli_json(gears, cli):
    for name, entry in cli["gears"].items():
        for key, value in entry.items():
            assert gears[name][key] == value, (name, key)


def test_radii_are_half_the_cli_diameters(gears, cli):
    for name, entry in cli["gears"].items():
        for what in ("reference", "base", "tip", "root", "form"):
            assert 2 * gears[name][f"{what}_radius_m"] == entry[f"{what}_diameter_m"]


def test_the_mesh_with_its_mate_is_the_cli_train_mesh(gears, cli):
    mesh = cli["train"]["mesh"]
    assert gears["pinion"]["meshes"] == {"wheel": mesh}
    assert gears["wheel"]["meshes"] == {"pinion": mesh}
    assert gears["pinion"]["meshes"]["wheel"]["contact_ratio"] > 1


def test_outline_area_times_face_width_is_the_cli_mesh_volume(gears, cli):
    # The mesh is the outline extruded over the face width: its volume is the outline's area
    # (toothed loop minus the bore) times the face width, to rounding (1e-12 relative).
    for name, entry in cli["gears"].items():
        g = gears[name]
        area = abs(shoelace_area(g["outline_x_m"], g["outline_y_m"]))
        area -= sum(abs(shoelace_area(x, y)) for x, y in g["other_loops_m"])
        assert area * entry["face_width_m"] == pytest.approx(entry["mesh"]["volume_m3"], rel=1e-12)


def test_outline_spans_root_to_tip_circle(gears):
    # Tessellated points lie on the exact curves: the outline touches the tip and root circles
    # (to 1 nm of rounding) and leaves neither.
    for g in gears.values():
        r = numpy.hypot(g["outline_x_m"], g["outline_y_m"])
        assert r.max() == pytest.approx(g["tip_radius_m"], abs=1e-9)
        assert r.min() == pytest.approx(g["root_radius_m"], abs=1e-9)


def test_flank_table_gives_the_tooth_thickness_at_the_reference_circle(gears):
    # Arc thickness s = r·(θ_ccw − θ_cw) on the reference circle; the table follows the outline
    # to its chordal deviation (0.5 µm) and is interpolated between 4096 radii: 1 µm.
    for g in gears.values():
        r = g["reference_radius_m"]
        ccw = numpy.array([numpy.interp(r, g["flank_radius_m"], row) for row in g["flank_ccw_rad"]])
        cw = numpy.array([numpy.interp(r, g["flank_radius_m"], row) for row in g["flank_cw_rad"]])
        assert g["flank_ccw_rad"].shape == (g["teeth"], len(g["flank_radius_m"]))
        assert numpy.abs(r * (ccw - cw) - g["tooth_thickness_m"]).max() < 1e-6


def test_error_free_flanks_are_mirror_images(gears):
    # No errors in this spec: every tooth symmetric about its centre line, to 1 µm at the tip.
    for g in gears.values():
        tip = g["tip_radius_m"]
        assert numpy.nanmax(numpy.abs(g["flank_ccw_rad"] + g["flank_cw_rad"])) * tip < 1e-6


def test_one_gear_by_name(gears):
    wheel = gearsim.gear(SPEC, "wheel")
    assert wheel["teeth"] == 31
    assert numpy.array_equal(wheel["outline_x_m"], gears["wheel"]["outline_x_m"])


def test_an_unknown_name_raises_input_error_naming_the_gears():
    with pytest.raises(gearsim.InputError, match="no gear 'moon'.*pinion, wheel"):
        gearsim.gear(SPEC, "moon")


def test_a_bad_spec_raises_input_error_naming_file_and_key(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(SPEC.read_text().replace("teeth: 20", "teeth: 2"))
    with pytest.raises(gearsim.InputError, match=r"bad\.yaml:\d+:\d+: gears\.pinion\.teeth"):
        gearsim.gear(bad)
