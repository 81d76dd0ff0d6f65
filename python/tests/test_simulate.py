"""pressridge.simulate: the same run as `pressridge simulate`, bit for bit."""

from __future__ import annotations

import json
import threading
import time

import numpy as np
import pytest

import pressridge as pr
from conftest import MIN_TICKS, ticks_during

SETS = ["duration=2.0", "sheet.length=8.0", "numerics.sample_interval=0.5"]


def test_equals_command_line(cli, tmp_path):
    out = tmp_path / "run"
    cli("simulate", *[x for s in SETS for x in ("--set", s)], "--out", out, "--no-figures")
    want = json.loads((out / "summary.json").read_text())
    sim = pr.simulate(sets=SETS[:1], **{"sheet.length": 8.0}, numerics__sample_interval=0.5)
    for s in (want, sim.summary):
        s.pop("wall_seconds")
    assert sim.summary == want
    assert abs(sim.summary["time"] - 2.0) <= sim.summary["dt"] and sim.summary["work"] > 0
    lines = (out / "series.csv").read_text().splitlines()
    header = [h.split(" [")[0] for h in lines[0].split(",")]
    assert header == list(sim.series)
    rows = np.array([[float(x) for x in ln.split(",")] for ln in lines[1:]])
    for k, name in enumerate(header):
        np.testing.assert_array_equal(sim.series[name], rows[:, k], err_msg=name)
    assert sim.units["work"] == "J/m" and sim.units["ridging_force"] == "N/m"
    assert len(sim.series["time"]) == 5
    assert 'duration = 2.0' in sim.scene and sim.scene == pr.scene(sets=SETS)


def test_scene_files_and_errors(tmp_path, sample):
    from pathlib import Path

    pile = Path(__file__).resolve().parents[2] / "data" / "scenes" / "rubble-pile.toml"
    assert "pile" in pr.scene(pile)
    with pytest.raises(ValueError, match="contact.mew"):
        pr.simulate(duration=0.1, **{"contact.mew": 0.4})
    with pytest.raises(ValueError, match="duration"):
        pr.simulate(duration=-1.0)
    with pytest.raises(FileNotFoundError, match="nope.toml"):
        pr.simulate(tmp_path / "nope.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("durationn = 3\n")
    with pytest.raises(ValueError, match="durationn"):
        pr.simulate(bad)


def test_releases_the_gil():
    sim, during = ticks_during(lambda: pr.simulate(duration=4.0, **{"sheet.length": 8.0}))
    assert sim.summary["steps"] > 0
    # With the GIL held for the whole run this thread could not tick during it.
    assert during >= MIN_TICKS, during


def test_ctrl_c_stops_a_run():
    import _thread

    timer = threading.Timer(0.3, _thread.interrupt_main)
    t0 = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        pr.simulate()  # the 400 s default scene: minutes if not stopped
    timer.join()
    assert time.perf_counter() - t0 < 10.0
