"""gearsim.tolerance: what `gearsim tolerance --json` prints."""
import json

import pytest

import gearsim
from conftest import run_cli


@pytest.mark.parametrize("standard", ["both", "din", "iso"])
def test_tolerances_equal_the_cli_json(standard):
    cli = json.loads(run_cli("tolerance", "--module", 2, "--teeth", 20, "--diameter", 40, "--quality", 6,
                             "--standard", standard, "--json").stdout)
    assert gearsim.tolerance(2, 20, 40, 6, standard=standard) == cli


def test_with_a_contact_ratio_equal_the_cli_json():
    cli = json.loads(run_cli("tolerance", "--module", 3, "--teeth", 31, "--diameter", 93, "--quality", 8,
                             "--standard", "iso", "--contact-ratio", 1.6, "--json").stdout)
    t = gearsim.tolerance(module_mm=3, teeth=31, reference_diameter_mm=93, quality=8, standard="iso", contact_ratio=1.6)
    assert t == cli
    assert t["iso1328_formulas"]["single_flank_error_um"] is not None  # Annex A needs ε_γ


def test_an_out_of_range_quality_raises_input_error_naming_it():
    with pytest.raises(gearsim.InputError, match="quality"):
        gearsim.tolerance(2, 20, 40, 13)


def test_an_unknown_standard_raises_input_error():
    with pytest.raises(gearsim.InputError, match="standard"):
        gearsim.tolerance(2, 20, 40, 6, standard="agma")
