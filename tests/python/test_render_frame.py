"""gearsim.render_frame: one OSMesa frame of a run folder, as `gearsim render` draws it."""
import numpy
import pytest

import gearsim
from conftest import run_cli

T_S = 0.02        # a time inside the 0.05 s run, s
SIZE = (160, 240)  # height, width: small, for speed
BACKGROUND = (28, 31, 38)  # render::RenderSettings' default background


@pytest.fixture(scope="module")
def cli_frame(spur_cli_run):
    """The first PNG frame `gearsim render --from T_S` writes, decoded to uint8 RGB."""
    image = pytest.importorskip("matplotlib.image")
    run_cli("render", spur_cli_run, "--from", T_S, "--to", T_S + 0.001, "--png-every", 1,
            "--width", SIZE[1], "--height", SIZE[0])
    png = image.imread(spur_cli_run / "frames" / "overview_00000.png")  # float32 in [0, 1]
    return numpy.rint(png[:, :, :3] * 255).astype(numpy.uint8)


def test_frame_equals_the_cli_png_pixel_for_pixel(spur_cli_run, cli_frame):
    frame = gearsim.render_frame(spur_cli_run, T_S, width_px=SIZE[1], height_px=SIZE[0])
    assert frame.shape == (*SIZE, 3) and frame.dtype == numpy.uint8
    assert numpy.array_equal(frame, cli_frame)


def test_the_gears_cover_a_plausible_share_of_the_frame(spur_cli_run):
    # The overview frames the whole pair: gears on a good part of the frame, background around.
    frame = gearsim.render_frame(spur_cli_run, T_S, width_px=SIZE[1], height_px=SIZE[0])
    share = numpy.any(frame != numpy.array(BACKGROUND, dtype=numpy.uint8), axis=2).mean()
    assert 0.2 < share < 0.9


def test_the_gears_turn_between_frames(spur_cli_run):
    a = gearsim.render_frame(spur_cli_run, 0.01, width_px=SIZE[1], height_px=SIZE[0])
    b = gearsim.render_frame(spur_cli_run, 0.045, width_px=SIZE[1], height_px=SIZE[0])
    assert not numpy.array_equal(a, b)


def test_a_time_outside_the_logged_span_raises_input_error(spur_cli_run):
    with pytest.raises(gearsim.InputError, match=r"t_s: .* outside the logged .*state\.csv"):
        gearsim.render_frame(spur_cli_run, 1.0)


def test_an_unknown_camera_raises_input_error(spur_cli_run):
    with pytest.raises(gearsim.InputError, match="camera"):
        gearsim.render_frame(spur_cli_run, T_S, camera="drone")


def test_a_folder_without_a_run_raises_input_error(tmp_path):
    with pytest.raises(gearsim.InputError, match=str(tmp_path)):
        gearsim.render_frame(tmp_path, T_S)
