"""Real model files (issue 17): the category dimension found by name, every other dimension
kept, land missing, CF outputs of the command line readable by xarray with decoded
coordinates."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import pressridge as pr
import pressridge.xr as prx


def cice_history(sample, ntime: int = 2) -> xr.Dataset:
    """A CICE-history-like dataset from the sample: ``aicen(time, nc, nj, ni)`` in single
    precision, ``time`` in days (noleap), ``TLON``/``TLAT``, ``NCAT`` upper bounds and land
    (NaN, written with a _FillValue) in the first row's first 4 cells."""
    s = xr.load_dataset(sample).isel(nj=slice(30, 42), ni=slice(0, 16))  # thick, compact ice
    cat = s[["aicen", "vicen"]].rename({"ncat": "nc"})
    times = [cat.assign(vicen=cat.vicen * (1.0 + 0.25 * it)) for it in range(ntime)]
    d = xr.concat(times, dim="time").transpose("time", "nc", "nj", "ni").astype(np.float32)
    for k in ("aicen", "vicen"):
        d[k][:, :, 0, :4] = np.nan
        d[k].encoding["_FillValue"] = np.float32(1.0e30)
        d[k].attrs["units"] = "1" if k == "aicen" else "m"
    lon = (10.0 + 0.5 * d.ni + 0.0 * d.nj).astype(np.float32)
    lat = (70.0 + 0.2 * d.nj + 0.0 * d.ni).astype(np.float32)
    d = d.assign_coords(
        time=("time", np.arange(ntime) * 31.0),
        TLON=lon.assign_attrs(units="degrees_east", long_name="T grid center longitude"),
        TLAT=lat.assign_attrs(units="degrees_north", long_name="T grid center latitude"),
    )
    d["time"].attrs.update(units="days since 2000-01-01 00:00:00", calendar="noleap")
    d["NCAT"] = ("nc", s.hin_max.values[1:].astype(np.float32), {"units": "m"})
    d.attrs["history"] = "synthetic CICE history"
    return d


def test_time_first_equals_the_per_time_computation(sample):
    d = cice_history(sample)
    p = prx.strength(d)
    assert p.dims == ("time", "nj", "ni")
    assert p.attrs["units"] == "N m-1"
    assert p.attrs["standard_name"] == "compressive_strength_of_sea_ice"
    for it in range(2):
        one = d.isel(time=it)
        np.testing.assert_array_equal(p.isel(time=it).values, prx.strength(one).values)
        a = one.aicen.values.astype(np.float64)
        v = one.vicen.values.astype(np.float64)
        ok = ~np.isnan(a).any(axis=0)
        want = pr.strength(np.nan_to_num(a), np.nan_to_num(v), valid=ok)
        np.testing.assert_array_equal(p.isel(time=it).values, want)
    # Land missing, ice in kN/m (the category axis mistaken for time gave ~10 N/m).
    assert np.isnan(p.values[:, 0, :4]).all()
    assert np.nanmedian(p.values) > 1.0e3
    # dask, chunked over time and space: the same.
    lazy = prx.strength(d.chunk({"time": 1, "nj": 5}))
    np.testing.assert_array_equal(lazy.compute().values, p.values)


def test_category_dimension_by_name_is_configurable_or_refused(sample, monkeypatch):
    d = cice_history(sample)
    p = prx.strength(d)
    # SIS2's diagnostic name.
    np.testing.assert_array_equal(prx.strength(d.rename({"nc": "ct"})).values, p.values)
    other = d.rename({"nc": "k"})
    with pytest.raises(ValueError, match=r"\(time=2, k=5, nj=12, ni=16\).*category_dim="):
        prx.strength(other)
    np.testing.assert_array_equal(prx.strength(other, category_dim="k").values, p.values)
    monkeypatch.setattr(prx, "CATEGORY_DIMS", prx.CATEGORY_DIMS + ("k",))
    np.testing.assert_array_equal(prx.strength(other).values, p.values)
    # Two names: ambiguous.
    two = d.rename({"time": "ncat"})
    with pytest.raises(ValueError, match=r"\(ncat=2, nc=5, nj=12, ni=16\).*more than one"):
        prx.strength(two)
    assert prx.CATEGORY_DIMS[:3] == ("nc", "ncat", "ct")  # the command line's list first


def test_ridge_step_takes_the_bounds_from_ncat(sample):
    d = cice_history(sample, ntime=1)
    s = xr.load_dataset(sample)
    got = prx.ridge_step(d, dt=1800.0, convergence=2e-6, shear=1e-6)
    want = prx.ridge_step(d, dt=1800.0, convergence=2e-6, shear=1e-6,
                          hin_max=s.hin_max.values.astype(np.float32).astype(np.float64))
    np.testing.assert_array_equal(got.aicen.values, want.aicen.values)
    assert np.isnan(got.aicen.values[:, :, 0, :4]).all()
    bad = d.assign(hin_max=("b", s.hin_max.values * 1.1))
    with pytest.raises(ValueError, match="NCAT"):
        prx.ridge_step(bad, dt=1800.0, convergence=2e-6)


def test_command_line_outputs_open_with_decoded_coordinates(sample, cli, tmp_path):
    d = cice_history(sample)
    src = tmp_path / "iceh.nc"
    d.to_netcdf(src)
    out = tmp_path / "p.nc"
    cli("strength", "--input", src, "--output", out)
    with xr.open_dataset(out) as o, xr.open_dataset(src) as i:
        p = o.strength
        assert p.dims == ("time", "nj", "ni")
        assert {"TLON", "TLAT", "time"} <= set(p.coords)
        assert o.time.dtype == i.time.dtype and o.time.encoding["calendar"] == "noleap"
        np.testing.assert_array_equal(o.time.values, i.time.values)
        np.testing.assert_array_equal(o.TLAT.values, i.TLAT.values)
        assert o.TLAT.attrs["units"] == "degrees_north"
        assert p.attrs["units"] == "N m-1"
        assert p.attrs["standard_name"] == "compressive_strength_of_sea_ice"
        assert o.attrs["Conventions"] == "CF-1.8"
        assert o.attrs["history"].startswith("synthetic CICE history\n")
        assert "strength --input" in o.attrs["history"]
        for k in ("participation", "redistribution", "cf", "strength_formula"):
            assert k in o.attrs
        # Land stays missing (NaN once decoded); the rest equals pressridge.xr.
        assert np.isnan(p.values[:, 0, :4]).all()
        np.testing.assert_array_equal(p.values, prx.strength(i).values)
    r = tmp_path / "r.nc"
    cli("ridge-step", "--input", src, "--output", r, "--dt", 1800, "--convergence", 2e-6)
    with xr.open_dataset(r) as o:
        assert o.aicen.dims == ("time", "nc", "nj", "ni")
        assert {"TLON", "TLAT", "time"} <= set(o.aicen.coords)
        assert np.isnan(o.aicen.values[:, :, 0, :4]).all() and np.isnan(o.closing.values[:, 0, :4]).all()
        assert o.attrs["category_bounds"].startswith("NCAT")
        for name, v in o.data_vars.items():
            assert "units" in v.attrs and "long_name" in v.attrs, name


def test_cf_clamp_warning_once_per_call_not_per_chunk(sample):
    import warnings

    d = cice_history(sample)
    nodes = (np.array([0.2, 0.3]), np.array([15.0, 16.0]))  # thicker ridging ice: clamped
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("default")
        lazy = prx.strength(d.chunk({"time": 1, "nj": 4}), cf=nodes)  # 6 chunks
        assert lazy.data.npartitions == 6
        lazy.compute(scheduler="threads")
        prx.strength(d.chunk({"time": 1, "nj": 4}), cf=nodes).compute(scheduler="sync")
        prx.strength(d, cf=nodes)  # eager: one block, the exact count
    got = [x for x in w if issubclass(x.category, pr.CfClampedWarning)]
    assert len(got) == 3, [str(x.message) for x in got]
    assert "over dask chunks" in str(got[0].message)
    assert "columns had ridging-ice thicknesses" in str(got[2].message)


def test_tmask_zero_is_land(sample):
    """CICE's ocean mask ``tmask`` (1 ocean, 0 land; over nj, ni without time) makes cells
    missing like a _FillValue, at every time, even where aicen holds numbers there."""
    d = cice_history(sample)
    p_all = prx.strength(d, cf=17.0).values
    tmask = xr.ones_like(d.TLON).transpose("nj", "ni").astype(np.float32).reset_coords(drop=True)
    tmask[1, :3] = 0.0  # ocean values in aicen, land by the mask
    d["tmask"] = tmask
    p = prx.strength(d, cf=17.0)
    assert p.dims == ("time", "nj", "ni")
    land = np.broadcast_to((tmask.values == 0)[None], p.shape)
    assert np.isnan(p.values[land]).all()
    ok = ~land & ~np.isnan(p_all)
    np.testing.assert_array_equal(p.values[ok], p_all[ok])
    assert np.isnan(prx.strength(d.chunk({"nj": 4}), cf=17.0).values[land]).all()
    r = prx.ridge_step(d, dt=1800.0, convergence=2e-6, shear=1e-6)
    assert np.isnan(r.aicen.values[:, :, 1, :3]).all()
    # The shipped CICE history sample: missing exactly where its tmask is 0.
    s = xr.open_dataset(sample.parent / "cice_history_sample.nc")
    ps = prx.strength(s, cf=17.0)
    np.testing.assert_array_equal(
        np.isnan(ps.values), np.broadcast_to((s.tmask.values == 0)[None], ps.shape)
    )
