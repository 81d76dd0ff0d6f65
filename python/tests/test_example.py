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
