"""Every numeric keyword is checked against the bound of the CLI option it stands for
(input/input_limits.hpp) before anything runs: gearsim.InputError (a ValueError) naming the
keyword, with the message the CLI gives for its option."""
import math
import subprocess

import pytest

import gearsim
from conftest import BINARY, SOURCE, scenario_path

MESH = SOURCE / "assets" / "gears" / "spur_pair" / "pinion.stl"
SWEEP = SOURCE / "assets" / "sweeps" / "spur_speed_sweep.yaml"


def cli_refusal(*args):
    """What the CLI prints when it refuses an option (exit 2, the bad-input code)."""
    r = subprocess.run([str(BINARY / "bin" / "gearsim"), *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 2, r.stdout + r.stderr
    return r.stdout + r.stderr


def refusal(call, keyword):
    """The message of the InputError `call` raises, less its leading "keyword: "."""
    with pytest.raises(gearsim.InputError) as e:
        call()
    assert isinstance(e.value, ValueError)
    message = str(e.value)
    assert message.startswith(keyword + ": "), message
    return message[len(keyword) + 2:]


@pytest.mark.parametrize("duration", [1e9, math.inf, math.nan, 0.0, -1.0])
def test_run_refuses_a_duration_beyond_the_clis_bound(duration, tmp_path):
    # Unchecked, 1e9 s runs unbounded and infinity returns "completed" after 0 s.
    scenario = gearsim.load_scenario(scenario_path("spur_pair.yaml"))
    message = refusal(lambda: gearsim.run(scenario, out=tmp_path / "py", duration=duration), "duration")
    assert message.startswith("expected a duration in (0, 10000] s, got ")
    assert message in cli_refusal("run", scenario_path("spur_pair.yaml"), "--out", tmp_path / "cli", f"--duration={duration!r}")
    assert not (tmp_path / "py" / "summary.json").exists()


@pytest.mark.parametrize("keyword, value, option", [("harmonics", -1, "--harmonics"), ("harmonics", 51, "--harmonics"),
                                                    ("phases", 2, "--phases"), ("max_speed_rad_s", math.inf, "--max-speed"),
                                                    ("max_speed_rad_s", math.nan, "--max-speed"), ("max_speed_rad_s", 0.0, "--max-speed")])
def test_modes_refuses_what_the_cli_refuses(keyword, value, option):
    scenario = gearsim.load_scenario(scenario_path("lin_parker_1999.yaml"))
    message = refusal(lambda: gearsim.modes(scenario, **{keyword: value}), keyword)
    assert message.startswith("expected a ")
    assert message in cli_refusal("modes", scenario_path("lin_parker_1999.yaml"), f"{option}={value!r}")


@pytest.mark.parametrize("keyword, value, option", [("density_kg_m3", math.nan, "--density"), ("density_kg_m3", 1e300, "--density"),
                                                    ("tooth0_deg", math.inf, "--tooth0-deg"), ("teeth", 2, "--teeth"),
                                                    ("teeth", 5000, "--teeth"), ("prism_tolerance_um", 0.0, "--prism-tolerance"),
                                                    ("hausdorff_spacing_mm", 1e-300, "--hausdorff-spacing")])
def test_inspect_refuses_what_the_cli_refuses(keyword, value, option):
    message = refusal(lambda: gearsim.inspect(MESH, **{keyword: value}), keyword)
    assert message.startswith("expected a")
    assert message in cli_refusal("inspect", MESH, f"{option}={value!r}")


def test_analyze_refuses_a_window_start_beyond_the_clis_bound(tmp_path):
    message = refusal(lambda: gearsim.analyze(tmp_path, from_s=math.nan), "from_s")
    assert message == "expected a time in [0, 10000] s, got nan"
    assert message in cli_refusal("analyze", tmp_path, "--from=nan")


def test_render_frame_refuses_a_time_or_size_beyond_the_bounds(tmp_path):
    assert refusal(lambda: gearsim.render_frame(tmp_path, math.inf), "t_s") == "expected a time in [0, 10000] s, got inf"
    assert refusal(lambda: gearsim.render_frame(tmp_path, 0.01, width_px=8), "width_px") == \
        "expected a frame size in [16, 4096] px, got 8"


def test_sweep_refuses_a_job_count_beyond_the_clis_bound(tmp_path):
    message = refusal(lambda: gearsim.sweep(SWEEP, tmp_path / "py", jobs=0), "jobs")
    assert message == "expected a number of jobs in [1, 1024], got 0"
    assert message in cli_refusal("sweep", SWEEP, "--out", tmp_path / "cli", "--jobs=0")


def test_tolerance_refuses_a_module_that_is_no_number():
    with pytest.raises(gearsim.InputError, match="module_mm = nan is out of range"):
        gearsim.tolerance(math.nan, 20, 40.0, 6, standard="din")
