"""pressridge.xr on xarray Datasets, eager and dask-chunked."""

from __future__ import annotations

import dask.array as da
import numpy as np
import pytest
import xarray as xr

import pressridge as pr
import pressridge.xr as prx


@pytest.fixture()
def ds(sample):
    d = xr.load_dataset(sample)
    # Coordinates to keep: 1-D on each spatial dimension and a 2-D one.
    d = d.assign_coords(
        nj=("nj", np.arange(60) * 10.0e3, {"units": "m"}),
        ni=("ni", np.arange(80) * 10.0e3, {"units": "m"}),
    )
    lat = 70.0 + 0.1 * d.nj / 10.0e3 + 0.0 * d.ni
    return d.assign_coords(lat=lat.assign_attrs(units="degrees_north"))


def test_strength_equals_numpy_and_command_line(ds, cli, sample, tmp_path):
    p = prx.strength(ds)
    assert p.name == "strength" and p.dims == ("nj", "ni")
    assert p.attrs["units"] == "N m-1" and p.attrs["cf"] == "constant 17.0"
    np.testing.assert_array_equal(p.coords["ni"], ds.ni)
    assert p.coords["lat"].attrs["units"] == "degrees_north"
    np.testing.assert_array_equal(
        p.values, pr.strength(ds.aicen.values, ds.vicen.values, ds.aice0.values)
    )
    out = tmp_path / "p.nc"
    cli("strength", "--input", sample, "--output", out, "--cf-preset", "hibler1980")
    np.testing.assert_array_equal(
        prx.strength(ds, cf="hibler1980").values, xr.load_dataset(out).strength.values
    )


def test_chunked_strength_is_lazy_and_equal(ds):
    eager = prx.strength(ds, participation="thorndike", cf=15.0, mu_rdg=4.0)
    # Chunks over the spatial dimensions and (badly) over the categories too.
    lazy_ds = ds.chunk({"nj": 25, "ni": 30, "ncat": 2})
    lazy = prx.strength(lazy_ds, participation="thorndike", cf=15.0, mu_rdg=4.0)
    assert isinstance(lazy.data, da.Array)
    assert lazy.chunks == ((25, 25, 10), (30, 30, 20))
    np.testing.assert_array_equal(lazy.compute().values, eager.values)
    np.testing.assert_array_equal(lazy.coords["lat"].values, ds.lat.values)


def test_chunked_strength_on_a_distributed_cluster(ds):
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as c, Client(c):
        lazy = prx.strength(ds.chunk({"nj": 30, "ni": 40}))
        got = lazy.compute()
    np.testing.assert_array_equal(got.values, prx.strength(ds).values)


def test_category_dimension_elsewhere(ds):
    # (time, nj, ni, ncat) storage: the category dimension named, not first.
    t = ds[["aicen", "vicen", "aice0"]].expand_dims(time=2).transpose("time", "nj", "ni", "ncat")
    p = prx.strength(t, category_dim="ncat")
    assert p.dims == ("time", "nj", "ni")
    np.testing.assert_array_equal(p.isel(time=1).values, prx.strength(ds).values)


def test_ridge_step_equals_numpy_and_keeps_the_dataset(ds, cli, sample, tmp_path):
    r = prx.ridge_step(ds, dt=1800.0)
    n = pr.ridge_step(
        ds.aicen.values,
        ds.vicen.values,
        ds.aice0.values,
        dt=1800.0,
        convergence=np.maximum(-ds.divu.values, 0),
        shear=ds.shear.values,
    )
    for name in n._fields[:8]:  # the area-volume step's fields
        np.testing.assert_array_equal(r[name].values, getattr(n, name), err_msg=name)
    assert r.aicen.dims == ds.aicen.dims and r.aicen.attrs == ds.aicen.attrs
    assert r.closing.attrs["units"] == "s-1" and r.dvirdgdt.attrs["units"] == "m s-1"
    assert r.attrs["title"] == ds.attrs["title"] and r.attrs["dt"] == "1800.0 s"
    np.testing.assert_array_equal(r.divu, ds.divu)
    np.testing.assert_array_equal(r.coords["lat"], ds.lat)
    # The same as the command line.
    out = tmp_path / "r.nc"
    cli("ridge-step", "--input", sample, "--output", out, "--dt", 1800)
    want = xr.load_dataset(out)
    for name in ("aicen", "vicen", "aice0", "closing", "opening", "dardg1dt", "dardg2dt", "dvirdgdt"):
        np.testing.assert_array_equal(r[name].values, want[name].values, err_msg=name)


def test_chunked_ridge_step_equals_eager(ds):
    eager = prx.ridge_step(ds, dt=600.0, convergence=2e-6, shear=1e-6)
    lazy = prx.ridge_step(ds.chunk({"nj": 20, "ni": 20}), dt=600.0, convergence=2e-6, shear=1e-6)
    assert isinstance(lazy.aicen.data, da.Array) and isinstance(lazy.closing.data, da.Array)
    assert lazy.aicen.chunks[0] == (5,)
    computed = lazy.compute()
    for name in ("aicen", "vicen", "aice0", "closing", "opening", "dardg1dt", "dardg2dt", "dvirdgdt"):
        np.testing.assert_array_equal(computed[name].values, eager[name].values, err_msg=name)


def test_missing_values_are_masked_only_when_declared(ds):
    d = ds.copy(deep=True)
    d["aicen"][:, 0, :3] = np.nan
    d["vicen"][:, 0, :3] = np.nan
    with pytest.raises(ValueError, match=r"at spatial index \(0, 0\): aicen\[category 0\] is not finite"):
        prx.strength(d).values
    # Declared missing data (as xarray decodes a variable with a _FillValue): masked.
    d["aicen"].encoding["_FillValue"] = 1.0e20
    p = prx.strength(d)
    assert np.isnan(p.values[0, :3]).all()
    np.testing.assert_array_equal(p.values[1:], prx.strength(ds).values[1:])
    r = prx.ridge_step(d, dt=600.0)
    assert np.isnan(r.closing.values[0, :3]).all() and np.isnan(r.aicen.values[:, 0, :3]).all()
    with pytest.raises(ValueError, match="not finite"):
        prx.strength(d, mask=False).values


def test_missing_fill_masks_round_trip_through_netcdf(ds, tmp_path):
    d = ds[["aicen", "vicen", "aice0"]].copy(deep=True)
    for k in ("aicen", "vicen"):
        d[k][:, 5, 5] = np.nan
    d["aice0"][5, 5] = np.nan
    f = tmp_path / "land.nc"
    d.to_netcdf(f)  # xarray writes NaN with a _FillValue
    with xr.open_dataset(f, chunks={"nj": 30}) as back:
        p = prx.strength(back).compute()
    assert np.isnan(p.values[5, 5]) and np.isfinite(np.delete(p.values.ravel(), 5 * 80 + 5)).all()


def test_bad_datasets(ds):
    with pytest.raises(ValueError, match="no variable `vicen`"):
        prx.strength(ds.drop_vars("vicen"))
    with pytest.raises(ValueError, match="no convergence"):
        prx.ridge_step(ds.drop_vars("divu"), dt=60.0)
    with pytest.raises(ValueError, match="unknown keyword or parameter `bogus`"):
        prx.strength(ds.chunk({"nj": 30}), bogus=1.0)
    with pytest.raises(ValueError, match="has no dimension 'cat'"):
        prx.strength(ds, category_dim="cat")
    with pytest.raises(ValueError, match="aice0 has dimensions"):
        prx.strength(ds.assign(aice0=ds.aicen.isel(nj=0)))


def test_cice_history_rates_in_percent_per_day_are_converted_or_refused(ds):
    """CICE history `divu`, `shear` in %/day: converted to 1/s (the shear strain rate turned
    into Icepack's ridging shear term); an unknown unit, or none, is refused by name."""
    divu_s = ds["divu"]
    rate = xr.full_like(divu_s, 2.0e-6)
    delta = np.sqrt(divu_s**2 + 0.25 * rate**2)
    term = 0.5 * (delta - abs(divu_s))
    want = prx.ridge_step(ds.assign(shear=term.assign_attrs(units="s-1")), dt=3600.0)
    pct = ds.assign(
        divu=(divu_s * 100.0 * 86400.0).assign_attrs(units="%/day"),
        shear=(rate * 100.0 * 86400.0).assign_attrs(units="%/day"),
    )
    got = prx.ridge_step(pct, dt=3600.0)
    np.testing.assert_allclose(got.aicen.values, want.aicen.values, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(got.closing.values, want.closing.values, rtol=1e-9, atol=1e-20)
    with pytest.raises(ValueError, match="m/s"):
        prx.ridge_step(ds.assign(divu=divu_s.assign_attrs(units="m/s")), dt=3600.0)
    # No units at all: refused by name, as the command line does, never taken for 1/s.
    bare = divu_s.copy()
    bare.attrs.pop("units")
    with pytest.raises(ValueError, match="`divu` has no `units`"):
        prx.ridge_step(ds.assign(divu=bare), dt=3600.0)
