"""pressridge.Table: the lookup table `pressridge tabulate` writes, read back by the Rust
RidgeLookup and interpolated; strength with the simulator's C_f."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
import xarray as xr

import pressridge as pr
import pressridge.xr as prx


@pytest.fixture(scope="module")
def table(cli_campaign):
    return pr.Table.open(cli_campaign[1])


def test_axes_and_fields(table, cli_campaign):
    ds = xr.load_dataset(cli_campaign[1])
    assert table.sets == [""] or len(table.sets) == 1
    np.testing.assert_array_equal(table.thickness, [0.25, 0.35])
    np.testing.assert_array_equal(table.volume, ds.volume.values)
    assert {"work_mean", "cf", "cf_by_set", "force_fit"} <= set(table.variables)
    f = table.field("work_mean")
    assert f["dims"] == ("set", "thickness", "volume") and f["units"] == "J m-1"
    # The file holds the one set as the (mu, mu_w) cell of a friction grid.
    on_grid = ds.work_mean.transpose("mu", "mu_w", "thickness", "volume").values
    np.testing.assert_array_equal(f["data"], on_grid.reshape(f["data"].shape))
    assert "tiny" in table.attribute("campaign_spec")
    assert table.attribute("no such attribute") is None
    xr.testing.assert_identical(table.to_xarray(), ds)
    assert "2 thicknesses" in repr(table)


def test_table_opens_in_xarray_with_its_dimensions_and_units(cli_campaign):
    """Issue 5: the tiny campaign's table (2 thicknesses, one set, 11 volumes) is a CF file
    that xarray opens, with units on every variable."""
    with xr.open_dataset(cli_campaign[1]) as ds:
        assert dict(ds.sizes) == {
            "thickness": 2,
            "mu": 1,
            "mu_w": 1,
            "volume": 11,
            "ridged_bin": 40,
            "bounds2": 2,
        }
        # The binned ridged-ice distribution (issue 34): a fraction per bin of H/h, each
        # thickness's adding to one.
        assert ds.ridged_fraction.dims == ("thickness", "mu", "mu_w", "ridged_bin")
        np.testing.assert_allclose(ds.ridged_fraction.sum("ridged_bin").values, 1.0, rtol=1e-12)
        assert ds.ridged_bin.attrs["bounds"] == "ridged_bin_bounds"
        assert ds.attrs["Conventions"] == "CF-1.8"
        assert ds.work_mean.dims == ("thickness", "mu", "mu_w", "volume")
        assert ds.work_fit.dims == ("mu", "mu_w", "volume")
        assert ds.cf_by_set.dims == ("thickness", "mu", "mu_w")
        # Friction is chosen by value, as a modeller would with xarray.
        at = ds.cf_by_set.sel(mu=1.0, mu_w=0.6)
        np.testing.assert_array_equal(at.values, ds.cf.values)
        assert ds.cf.dims == ("thickness",)
        for name, var in ds.variables.items():
            assert var.attrs.get("units"), f"{name} has no units"
            assert var.attrs.get("long_name"), f"{name} has no long_name"
        want = {
            "thickness": "m",
            "volume": "m3 m-1",
            "work_mean": "J m-1",
            "potential_energy_mean": "J m-1",
            "ratio_mean": "1",
            "force_mean": "N m-1",
            "force_fit": "N m-1",
            "work_a": "J m-5",  # W = V(aV + b), W in J/m, V in m3/m
            "work_b": "J m-3",
            "cf": "1",
        }
        assert {k: ds[k].attrs["units"] for k in want} == want
        assert ds.volume.values[0] == 0.0 and np.all(np.diff(ds.volume.values) > 0)


def test_interpolation(table, cli_campaign):
    ds = xr.load_dataset(cli_campaign[1])
    w = ds.work_mean.sel(mu=1.0, mu_w=0.6).values  # (thickness, volume) of the one set
    h, v = np.meshgrid(table.thickness, table.volume, indexing="ij")
    vals, clamped = table.value("work_mean", h, v, return_clamped=True)
    np.testing.assert_array_equal(vals, w)  # nodes give the stored values (NaN included)
    assert not clamped.any()
    # Half way in thickness at the first volumes (where both thicknesses have data).
    mid = table.value("work_mean", 0.30, table.volume[:3])
    np.testing.assert_allclose(mid, 0.5 * (w[0, :3] + w[1, :3]), rtol=1e-14)
    # Outside the axes: clamped and flagged.
    val, c = table.value("work_mean", 1.0, table.volume[1], return_clamped=True)
    assert c and val == w[1, 1]
    np.testing.assert_array_equal(table.cf(table.thickness), ds.cf.values)
    cf, c = table.cf(0.1, return_clamped=True)
    assert c and cf == ds.cf.values[0]
    h_nodes, cf_nodes = table.cf_nodes()
    np.testing.assert_array_equal(cf_nodes, ds.cf.values)


@pytest.mark.filterwarnings("ignore::pressridge.CfClampedWarning")  # from dask's threads
def test_strength_with_the_table_equals_command_line(table, cli_campaign, cli, sample, tmp_path):
    out = tmp_path / "p.nc"
    cli("strength", "--input", sample, "--output", out, "--cf-table", cli_campaign[1])
    want = xr.load_dataset(out).strength.values
    itd = xr.load_dataset(sample)
    with pytest.warns(pr.CfClampedWarning):
        got = pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, cf=table)
    np.testing.assert_array_equal(got, want)
    with pytest.warns(pr.CfClampedWarning):
        by_path = pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, cf=table.path)
    np.testing.assert_array_equal(by_path, want)
    lazy = prx.strength(itd.chunk({"nj": 30}), cf=table)
    assert "table of 2 nodes" in lazy.attrs["cf"]
    np.testing.assert_array_equal(lazy.values, want)


def test_pickles(table):
    back = pickle.loads(pickle.dumps(table))
    assert back.path == table.path
    np.testing.assert_array_equal(back.volume, table.volume)


def test_errors(table, sample, tmp_path):
    with pytest.raises(FileNotFoundError, match="missing.nc"):
        pr.Table.open(tmp_path / "missing.nc")
    with pytest.raises(ValueError, match="missing variable `thickness`"):
        pr.Table.open(sample)
    not_nc = tmp_path / "text.nc"
    not_nc.write_text("not a NetCDF file")
    with pytest.raises(OSError):
        pr.Table.open(not_nc)
    with pytest.raises(ValueError, match="no field `work`"):
        table.value("work", 0.3, 1.0)
    with pytest.raises(ValueError, match="set index 3 is out of range"):
        table.value("work_mean", 0.3, 1.0, set=3)
    with pytest.raises(ValueError, match="no set 'mu=1'"):
        table.cf(0.3, set="mu=1")
    with pytest.raises(ValueError, match="thickness = NaN is not finite"):
        table.value("work_mean", np.nan, 1.0)


def test_friction_chooses_the_set(table, cli_campaign, cli, sample, tmp_path):
    """The table's sets carry their friction pair; strength takes C_f at the pair asked for
    (default 1.0, 0.6), equal to the command line's --friction, and refuses a pair the table
    does not hold, naming the pairs it has."""
    assert table.friction == [(1.0, 0.6)]
    assert table.friction_set(1.0, 0.6) == 0
    assert pr.DEFAULT_FRICTION == (1.0, 0.6)
    out = tmp_path / "p.nc"
    cli("strength", "--input", sample, "--output", out, "--cf-table", cli_campaign[1],
        "--friction", "1.0,0.6")
    want = xr.load_dataset(out).strength.values
    itd = xr.load_dataset(sample)
    for cf in (table, table.path):
        with pytest.warns(pr.CfClampedWarning):
            got = pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, cf=cf,
                              friction=(1.0, 0.6))
        np.testing.assert_array_equal(got, want)
        with pytest.raises(ValueError, match=r"mu = 0.4, mu_w = 0.3.*\(1, 0.6\)"):
            pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, cf=cf,
                        friction=(0.4, 0.3))
    with pytest.raises(ValueError, match="friction chooses the C_f of a table"):
        pr.strength(itd.aicen.values, itd.vicen.values, cf=17.0, friction=(1.0, 0.6))
    with pytest.raises(ValueError, match="friction must be a pair"):
        pr.strength(itd.aicen.values, itd.vicen.values, cf=table, friction=1.0)
    lazy = prx.strength(itd.chunk({"nj": 30}), cf=table)
    assert lazy.attrs["cf_friction"] == "mu = 1, mu_w = 0.6"
    assert prx.strength(itd, cf=17).attrs["cf_friction"].startswith("not applicable")
