"""Shared fixtures: the command-line binary the Python results are compared with, the sample
distribution, and one tiny campaign made by the command line (tabulated) for the campaign
and table tests."""

from __future__ import annotations

import os
import subprocess
import threading
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "data" / "sample_itd.nc"

# 2 thicknesses x 2 seeds x 5 s of a short sheet: 4 runs of a few seconds each.
TINY_SPEC = """\
name = "tiny"
seeds = 2
sample_interval = 1.0
set = ["duration=5.0", "sheet.length=8.0", "floe.nose_slope=1.0"]

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


# A call that holds the GIL throughout lets this thread tick at most once at each of its two
# boundaries (a thread switch just before or just after it); a call that releases the GIL
# for a fraction of a second lets it tick hundreds of times.
MIN_TICKS = 5


def ticks_during(call):
    """Runs `call()` in a worker thread while this thread counts ticks; returns (the call's
    result, the ticks counted between the call's start and its end, as the worker saw them).
    A call that held the GIL throughout would see none: this thread cannot run Python then.
    Nothing here depends on how long anything takes."""
    state = {"ticks": 0}
    done = threading.Event()

    def work():
        before = state["ticks"]
        state["result"] = call()
        state["during"] = state["ticks"] - before
        done.set()

    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        state["ticks"] += 1
        done.wait(0.001)
    t.join()
    return state["result"], state["during"]


@pytest.fixture()
def sigint_handled():
    """Python's own SIGINT handler for the test: a process started in the background by a
    non-interactive shell inherits SIGINT ignored, and `_thread.interrupt_main` then does
    nothing, so the Ctrl-C tests would test the launcher instead of the extension."""
    import signal

    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, old)
