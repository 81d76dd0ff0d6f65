"""Shared fixtures: the command-line binary the Python results are compared with, the sample
distribution, and one tiny campaign made by the command line (tabulated) for the campaign
and table tests."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "data" / "sample_itd.nc"

# 2 thicknesses x 2 seeds x 5 s of a short sheet: 4 runs of a few seconds each.
TINY_SPEC = """\
name = "tiny"
seeds = 2
sample_interval = 1.0
set = ["duration=5.0", "sheet.length=8.0"]

[[axis]]
keys = ["sheet.thickness", "sheet.block_width"]
values = [[0.25, 0.25], [0.35, 0.25]]
"""


def _binary() -> Path:
    env = os.environ.get("PRESSRIDGE_BIN")
    p = Path(env) if env else ROOT / "target" / "release" / "pressridge"
    if not p.is_file():
        raise RuntimeError(
            f"the pressridge command line is not built at {p}: run scripts/test-python.sh, "
            "or set PRESSRIDGE_BIN"
        )
    return p


@pytest.fixture(scope="session")
def cli():
    """Runs the pressridge command line; fails the test with its stderr on error."""
    exe = _binary()

    def run(*args: object, check: bool = True) -> subprocess.CompletedProcess:
        r = subprocess.run(
            [str(exe), *map(str, args)], capture_output=True, text=True, timeout=600
        )
        if check and r.returncode != 0:
            pytest.fail(f"pressridge {' '.join(map(str, args))} failed:\n{r.stderr}")
        return r

    return run


@pytest.fixture(scope="session")
def sample() -> Path:
    return SAMPLE


@pytest.fixture(scope="session")
def tiny_spec(tmp_path_factory) -> Path:
    d = tmp_path_factory.mktemp("spec")
    p = d / "tiny.toml"
    p.write_text(TINY_SPEC)
    return p


@pytest.fixture(scope="session")
def cli_campaign(cli, tiny_spec, tmp_path_factory):
    """The tiny campaign run and tabulated by the command line: (result dir, table file)."""
    d = tmp_path_factory.mktemp("cli-campaign")
    out = d / "out"
    cli("campaign", "--spec", tiny_spec, "--out", out, "--threads", "2")
    table = d / "table.nc"
    cli("tabulate", "--campaign", out, "--out", table, "--points", "11")
    return out, table
