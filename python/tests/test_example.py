"""The worked example of docs/python.md runs (on the tiny campaign's table)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "strength_difference.py"


def test_worked_example_runs(cli_campaign, tmp_path):
    png = tmp_path / "difference.png"
    r = subprocess.run(
        [sys.executable, str(EXAMPLE), str(cli_campaign[1]), str(png)],
        capture_output=True, text=True, timeout=300,
    )
    assert r.returncode == 0, r.stderr
    assert png.stat().st_size > 10_000
    assert "difference" in r.stdout


CICE_EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "cice_history_strength.py"


def test_cice_history_example_runs_and_its_sample_is_reproducible(cli_campaign, tmp_path):
    import xarray as xr

    root = Path(__file__).resolve().parents[2]
    made = tmp_path / "sample.nc"
    r = subprocess.run([sys.executable, str(CICE_EXAMPLE), "--make-sample", str(made)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    with xr.open_dataset(made) as a, xr.open_dataset(root / "data" / "cice_history_sample.nc") as b:
        xr.testing.assert_identical(a, b)
        assert a.aicen.dims == ("time", "nc", "nj", "ni")
    png = tmp_path / "map.png"
    r = subprocess.run(
        [sys.executable, str(CICE_EXAMPLE), str(made), str(cli_campaign[1]), str(png)],
        capture_output=True, text=True, timeout=300,
    )
    assert r.returncode == 0, r.stderr
    assert png.stat().st_size > 10_000
    assert "360 missing (land) cells" in r.stdout and "difference" in r.stdout
