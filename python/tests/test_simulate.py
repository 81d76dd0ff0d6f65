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


def test_ctrl_c_stops_a_run(sigint_handled):
    import _thread

    timer = threading.Timer(0.3, _thread.interrupt_main)
    t0 = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        pr.simulate()  # the 400 s default scene: minutes if not stopped
    timer.join()
    assert time.perf_counter() - t0 < 10.0


def test_progress_shows_and_is_silent_on_request(capsys):
    seen = []
    pr.simulate(sets=SETS, progress=lambda t, d: seen.append((t, d)))
    assert seen and all(d == 2.0 for _, d in seen)
    assert [t for t, _ in seen] == sorted(t for t, _ in seen)
    assert abs(seen[-1][0] - 2.0) < 1e-3, "the last report is at the end"
    capsys.readouterr()
    pr.simulate(sets=SETS, progress=False)
    assert capsys.readouterr().err == ""
    pr.simulate(sets=SETS)  # the default shows progress (stderr is not a terminal here)
    err = capsys.readouterr().err
    assert "simulate:" in err and "of 2 s simulated (100.0 %)" in err, err
    with pytest.raises(ValueError, match="progress must be"):
        pr.simulate(sets=SETS, progress="yes")


def test_a_run_directory_loads_and_plots(cli, tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.collections import PolyCollection

    out = tmp_path / "run"
    cli("simulate", *[x for s in SETS for x in ("--set", s)], "--out", out, "--no-figures")
    run = pr.load_run(out)
    want = json.loads((out / "summary.json").read_text())
    assert run.summary == want
    assert run.series["work"].attrs["units"] == "J/m"
    assert run.series["time"].size == 5 and run.units["ridging_force"] == "N/m"
    np.testing.assert_array_equal(run.series["work"].values[-1], want["work"])
    st = run.state
    assert len(st.polygons) == want["bodies"] == len(st.roles)
    assert abs(st.time - want["time"]) < 1e-12 and st.water_level == 0.0
    assert {"Sheet", "Floe"} <= set(st.roles)
    # Each outline is its block moved to its pose: the centroid of the vertices of a
    # rectangle is its centre.
    k = st.roles.index("Sheet")
    np.testing.assert_allclose(st.polygons[k].mean(axis=0), st.pos[k], atol=1e-9)
    ax = pr.plot_state(run)
    coll = [c for c in ax.collections if isinstance(c, PolyCollection)]
    assert len(coll) == 1 and len(coll[0].get_paths()) == want["bodies"]
    with pytest.raises(FileNotFoundError, match="not a run directory"):
        pr.load_run(tmp_path)


def test_threads_give_the_same_bits():
    """``threads=`` runs each step's force phases on several threads; the run is the same to
    the bit, and a count below one is refused by name."""
    one = pr.simulate(sets=SETS, progress=False)
    two = pr.simulate(sets=SETS, progress=False, threads=2)
    for s in (one.summary, two.summary):
        s.pop("wall_seconds")
    assert one.summary == two.summary
    for name in one.series:
        np.testing.assert_array_equal(one.series[name], two.series[name], err_msg=name)
    for bad in (0, -1, 1.5, True):
        with pytest.raises(ValueError, match="threads"):
            pr.simulate(sets=SETS, progress=False, threads=bad)
