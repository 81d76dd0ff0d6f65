"""pressridge.campaign and pressridge.tabulate: the same result directory and table as the
command line, through a dask LocalCluster with two worker processes and through threads."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
import xarray as xr

import pressridge as pr


def records(out):
    """{run id: (run.json without the wall-clock time, state.json bytes)}."""
    ids = json.loads((out / "plan.json").read_text())
    recs = {}
    for i in ids:
        rec = json.loads((out / "runs" / i / "run.json").read_text())
        rec["summary"].pop("wall_seconds")
        recs[i] = (rec, (out / "runs" / i / "state.json").read_bytes())
    return recs


def assert_same_directory(a, b):
    assert (a / "campaign.json").read_bytes() == (b / "campaign.json").read_bytes()
    assert (a / "plan.json").read_bytes() == (b / "plan.json").read_bytes()
    ra, rb = records(a), records(b)
    assert list(ra) == list(rb) and len(ra) == 4
    for i in ra:
        assert ra[i][0] == rb[i][0], i  # every number equal, to the bit (JSON round-trips)
        assert ra[i][1] == rb[i][1], i


def assert_same_table(a, b):
    ta, tb = xr.load_dataset(a), xr.load_dataset(b)
    xr.testing.assert_identical(ta.drop_attrs(), tb.drop_attrs())
    for k in set(ta.attrs) | set(tb.attrs):
        if k != "history":  # date and command
            assert ta.attrs[k] == tb.attrs[k], k
    assert "pressridge.tabulate" in tb.attrs["history"] or "pressridge.tabulate" in ta.attrs["history"]


@pytest.fixture(scope="module")
def cluster():
    from distributed import Client, LocalCluster

    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as c, Client(c) as client:
        yield client


def test_local_cluster_equals_command_line(cluster, cli_campaign, tiny_spec, tmp_path):
    cli_out, cli_table = cli_campaign
    out = tmp_path / "dask"
    from distributed import get_task_stream

    seen = []
    with get_task_stream(cluster) as ts:
        r = pr.campaign(tiny_spec, out, client=cluster, progress=seen.append)
    assert r == pr.CampaignResult(skipped=0, done=4, total=4)
    assert [p["done"] for p in seen] == [1, 2, 3, 4]
    assert len({t["worker"] for t in ts.data}) == 2  # both worker processes ran runs
    assert_same_directory(cli_out, out)
    table = pr.tabulate(out, tmp_path / "table.nc", points=11)
    assert isinstance(table, pr.Table)
    assert_same_table(cli_table, tmp_path / "table.nc")

    # Resumable: nothing to do, then only the missing run is redone.
    assert pr.campaign(tiny_spec, out, client=cluster) == pr.CampaignResult(4, 0, 4)
    victim = json.loads((out / "plan.json").read_text())[2]
    shutil.rmtree(out / "runs" / victim)
    assert pr.campaign(tiny_spec, out, client=cluster) == pr.CampaignResult(3, 1, 4)
    assert_same_directory(cli_out, out)
    # The command line resumes a directory made through dask.
    from conftest import _binary
    import subprocess

    res = subprocess.run(
        [str(_binary()), "campaign", "--spec", str(tiny_spec), "--out", str(out)],
        capture_output=True, text=True, check=True,
    )
    assert "4 already done, 0 run now" in res.stdout


def test_threads_equal_command_line(cli_campaign, tiny_spec, tmp_path):
    cli_out, _ = cli_campaign
    out = tmp_path / "threads"
    seen = []
    r = pr.campaign(tiny_spec, out, threads=2, progress=seen.append)
    assert r == pr.CampaignResult(0, 4, 4)
    assert_same_directory(cli_out, out)
    assert pr.campaign(tiny_spec, out, threads=1) == pr.CampaignResult(4, 0, 4)


def test_errors(cluster, tiny_spec, tmp_path):
    with pytest.raises(FileNotFoundError, match="nope.toml"):
        pr.campaign(tmp_path / "nope.toml", tmp_path / "o")
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "x"\nseedz = 2\n')
    with pytest.raises(ValueError, match="seedz"):
        pr.campaign(bad, tmp_path / "o", client=cluster)
    unknown = tmp_path / "unknown.toml"
    unknown.write_text('name = "x"\nset = ["sheet.thicknes=0.3"]\n')
    with pytest.raises(ValueError, match="thicknes"):
        pr.campaign(unknown, tmp_path / "o")
    # A directory holding another grid is refused, with either runner.
    other = tmp_path / "other.toml"
    other.write_text(tiny_spec.read_text().replace("0.35", "0.40"))
    out = tmp_path / "o2"
    (out).mkdir()
    shutil.copy(tiny_spec.parent / "tiny.toml", tmp_path / "tiny.toml")
    pr.campaign(tmp_path / "tiny.toml", out, threads=2)
    for client in (None, cluster):
        with pytest.raises(ValueError, match="another grid"):
            pr.campaign(other, out, client=client)
    with pytest.raises(ValueError, match="threads must be at least 1"):
        pr.campaign(tiny_spec, out, threads=0)
    with pytest.raises(FileNotFoundError):
        pr.tabulate(tmp_path / "no-campaign", tmp_path / "t.nc")
    with pytest.raises(ValueError, match="points"):
        pr.tabulate(out, tmp_path / "t.nc", points=1)


def test_ctrl_c_stops_a_threaded_campaign_after_the_runs_in_flight(tiny_spec, tmp_path, sigint_handled):
    import _thread
    import threading

    out = tmp_path / "interrupted"
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        pr.campaign(tiny_spec, out, threads=1)
    timer.join()
    finished = list(out.glob("runs/*/*/run.json"))
    assert 1 <= len(finished) < 4  # the run in flight was finished and written
    r = pr.campaign(tiny_spec, out, threads=2)
    assert r.skipped == len(finished) and r.skipped + r.done == 4


def test_tabulate_refuses_an_incomplete_campaign_unless_partial_is_allowed(cli_campaign, tmp_path):
    src, _ = cli_campaign
    out = tmp_path / "copy"
    shutil.copytree(src, out)
    ids = json.loads((out / "plan.json").read_text())
    (out / "runs" / ids[1] / "state.json").unlink()
    with pytest.raises(ValueError, match="state.json is missing") as e:
        pr.tabulate(out, tmp_path / "t.nc", points=5)
    assert ids[1] in str(e.value)
    assert not (tmp_path / "t.nc").exists()
    pr.tabulate(out, tmp_path / "t.nc", points=5, allow_partial=True)
    attrs = xr.load_dataset(tmp_path / "t.nc").attrs
    assert (attrs["runs_planned"], attrs["runs_tabulated"]) == (4, 3)
    assert attrs["partial"].startswith("yes") and ids[1] in attrs["partial"]


def test_tabulate_takes_several_campaigns_and_the_rafting_options_of_the_command_line(
    cli, cli_campaign, tmp_path
):
    """A list of campaigns, ``rafting_reach`` and ``exclude_rafted`` are ``--campaign``
    repeated, ``--rafting-reach`` and ``--exclude-rafted``: the same table, attributes
    included (both faces run the library's ``tabulate_campaigns``)."""
    src, _ = cli_campaign
    other = tmp_path / "other"
    shutil.copytree(src, other)  # the same runs again: each is counted once
    # A reach between the two largest overruns: the run that slid farthest is rafted.
    over = sorted(
        ((rec["summary"]["sheet_overrun_max"], i) for i, (rec, _) in records(src).items()),
        reverse=True,
    )
    reach = 0.5 * (over[0][0] + over[1][0])
    cli_nc, py_nc = tmp_path / "cli.nc", tmp_path / "py.nc"
    cli(
        "tabulate", "--campaign", src, "--campaign", other, "--out", cli_nc, "--points", "11",
        "--rafting-reach", repr(reach), "--exclude-rafted",
    )
    with pytest.warns(UserWarning, match="rafted") as seen:
        table = pr.tabulate(
            [src, other], py_nc, points=11, rafting_reach=reach, exclude_rafted=True
        )
    assert isinstance(table, pr.Table)
    assert any(over[0][1] in str(w.message) for w in seen)
    assert_same_table(cli_nc, py_nc)
    attrs = xr.load_dataset(py_nc).attrs
    assert (attrs["runs_planned"], attrs["runs_tabulated"]) == (8, 3)
    assert over[0][1] in attrs["excluded_runs"]
    assert "pressridge.tabulate" in attrs["history"] and "exclude_rafted=True" in attrs["history"]

    # Defaults are the command line's: one path or a list of one, nothing left out.
    pr.tabulate([src], tmp_path / "one.nc", points=11)
    _, cli_table = cli_campaign
    assert_same_table(cli_table, tmp_path / "one.nc")
    with pytest.raises(ValueError, match="rafting reach"):
        pr.tabulate(src, tmp_path / "bad.nc", points=11, rafting_reach=-1.0)
    with pytest.raises(ValueError, match="at least one campaign"):
        pr.tabulate([], tmp_path / "none.nc")


def test_resume_from_an_archive_runs_only_what_it_lacks(cli_campaign, tiny_spec, tmp_path):
    # A records-only archive of the command line's campaign with one run missing: the
    # Python campaign takes the others and makes only that one, as --resume-from does.
    src, _ = cli_campaign
    arch = tmp_path / "archive"
    for f in ("campaign.json", "plan.json"):
        (arch / f).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(src / f, arch / f)
    ids = json.loads((src / "plan.json").read_text())
    for i in ids[1:]:
        (arch / "runs" / i).mkdir(parents=True)
        shutil.copy(src / "runs" / i / "run.json", arch / "runs" / i / "run.json")
    (arch / "RECORDS-ONLY").write_text("records only\n")
    out = tmp_path / "out"
    r = pr.campaign(tiny_spec, out, threads=1, progress=False, resume_from=arch)
    assert (r.skipped, r.done) == (len(ids) - 1, 1)
    assert (out / "runs" / ids[0] / "state.json").is_file()
    assert not (out / "runs" / ids[1] / "state.json").exists()
    for i in ids:
        a = json.loads((src / "runs" / i / "run.json").read_text())
        b = json.loads((out / "runs" / i / "run.json").read_text())
        for d in (a, b):
            d["summary"]["wall_seconds"] = 0
            d["digest"] = None
        assert a == b, i


def test_tabulate_takes_the_keys_scaled_with_the_thickness_of_the_command_line(
    cli, cli_campaign, tmp_path
):
    """``scaled_with_thickness`` is ``--scaled-with-thickness``: the same table, with the
    keys and their values per thickness in its attributes; a key no scene has is a
    ``ValueError`` naming it."""
    src, _ = cli_campaign
    cli_nc, py_nc = tmp_path / "cli.nc", tmp_path / "py.nc"
    keys = ["floe.thickness", "sheet.length"]
    cli(
        "tabulate", "--campaign", src, "--out", cli_nc, "--points", "11",
        "--scaled-with-thickness", ",".join(keys),
    )
    pr.tabulate(src, py_nc, points=11, scaled_with_thickness=keys)
    assert_same_table(cli_nc, py_nc)
    attrs = xr.load_dataset(py_nc).attrs
    assert attrs["scaled_keys"] == "floe.thickness sheet.length"
    assert "floe.thickness=2.0" in attrs["scaled_values"]
    assert "scaled_with_thickness=['floe.thickness', 'sheet.length']" in attrs["history"]
    with pytest.raises(ValueError, match="floe.thicknes"):
        pr.tabulate(src, tmp_path / "bad.nc", points=11, scaled_with_thickness=["floe.thicknes"])


def test_redistribution_agrees_with_the_command_line_and_names_what_it_lacks(cli, cli_campaign, tmp_path):
    """The simulated ridged ice per thickness, as ``pressridge redistribution`` prints it: one
    row per thickness of the tiny campaign, with μ_rdg and H* from the same fits; a directory
    that is no campaign is an error naming it."""
    out, _ = cli_campaign
    rows = pr.redistribution(out)
    assert [r["thickness"] for r in rows] == [0.25, 0.35]
    md = tmp_path / "ridged.md"
    cli("redistribution", "--records", out, "--out", md)
    text = md.read_text()
    for r in rows:
        assert r["runs"] == 2 and r["strips"] >= 2
        assert 0.0 <= r["porosity"] < 1.0 and r["ks_exponential"] <= 1.0
        assert r["mu_rdg"] == pytest.approx((r["mean_thickness"] - 2 * r["thickness"]) / r["thickness"] ** 0.5)
        assert f"| {r['thickness']} | 1 | 0.6 | 2 |" in text
    with pytest.raises((ValueError, OSError), match="nowhere"):
        pr.redistribution(tmp_path / "nowhere")
