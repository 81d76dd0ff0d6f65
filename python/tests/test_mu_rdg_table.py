"""``redistribution="table"`` with ``mu_rdg_table=`` (issue 34): Lipscomb's exponential with
mu_rdg per category thickness from the simulator's ridges, in numpy, xarray and the command
line. A table of one value is that mu_rdg to the bit; a ridging table file is read at its
friction pair; the command line and xarray agree bit for bit."""

import numpy as np
import pytest

import pressridge as pr

from test_ridge_step_full import _dataset


def _table_file(path, h, curves):
    """A ridging table as ``pressridge tabulate`` lays out its friction grid, holding only
    ``mu_rdg(thickness, mu, mu_w)``: ``curves`` at (0.4, 0.6) and (1.0, 0.6)."""
    import xarray as xr

    data = np.stack(curves, axis=1)[:, :, None]  # (thickness, mu, mu_w)
    xr.Dataset(
        {"mu_rdg": (("thickness", "mu", "mu_w"), data, {"units": "m^0.5"})},
        coords={"thickness": h, "volume": [0.0], "mu": [0.4, 1.0], "mu_w": [0.6]},
    ).to_netcdf(path)
    return path


FLAT = ([1e-3, 1e3], [2.5, 2.5])


def _columns():
    rng = np.random.default_rng(3)
    ncat, ncol = 5, 60
    a = rng.dirichlet(np.ones(ncat + 1), size=ncol).T
    a0, a = a[0], a[1:]
    h = np.array([0.4, 1.0, 1.9, 3.3, 6.0])[:, None] * rng.uniform(0.8, 1.2, (ncat, ncol))
    return a, a * h, a0


def test_a_table_of_one_value_is_that_mu_rdg_in_every_routine():
    a, v, a0 = _columns()
    t = dict(redistribution="table", mu_rdg_table=FLAT)
    np.testing.assert_array_equal(pr.strength(a, v, a0, **t), pr.strength(a, v, a0, mu_rdg=2.5))
    kw = dict(dt=3600.0, convergence=3e-6, shear=1e-6)
    x = pr.ridge_step(a, v, a0, **kw, **t)
    y = pr.ridge_step(a, v, a0, **kw, mu_rdg=2.5)
    for f in ("aicen", "vicen", "aice0", "dardg2dt"):
        np.testing.assert_array_equal(getattr(x, f), getattr(y, f), err_msg=f)
    ds, layout = _dataset()
    d = ds.isel(time=0)
    trc = np.stack([d[n].values for n in layout.names], axis=1)
    full = dict(vsnon=d.vsnon.values, trcrn=trc, layout=layout, hin_max=d.hin_max.values, **kw)
    args = (d.aicen.values, d.vicen.values, d.aice0.values)
    x = pr.ridge_step(*args, **full, **t)
    y = pr.ridge_step(*args, **full, mu_rdg=2.5)
    for f in ("aicen", "vicen", "vsnon", "trcrn", "fhocn", "fresh"):
        np.testing.assert_array_equal(getattr(x, f), getattr(y, f), err_msg=f)


def test_a_varying_table_sets_each_categorys_scale():
    a, v, a0 = _columns()
    nodes = ([0.5, 3.0], [1.0, 4.0])
    p = pr.strength(a, v, a0, redistribution="table", mu_rdg_table=nodes)
    lo, hi = pr.strength(a, v, a0, mu_rdg=1.0), pr.strength(a, v, a0, mu_rdg=4.0)
    assert np.all(lo <= p) and np.all(p <= hi) and np.any(lo < p) and np.any(p < hi)


def test_files_are_read_at_their_friction_and_bad_uses_refused(tmp_path):
    f = _table_file(tmp_path / "t.nc", [0.2, 1.0, 5.0], [[1.0, 1.5, 2.0], [2.5, 2.5, 2.5]])
    a, v, a0 = _columns()
    t = pr.strength(a, v, a0, redistribution="table", mu_rdg_table=f)
    np.testing.assert_array_equal(t, pr.strength(a, v, a0, mu_rdg=2.5))
    low = pr.strength(a, v, a0, redistribution="table", mu_rdg_table=str(f), friction=(0.4, 0.6))
    assert np.all(low < t)
    with pytest.raises(ValueError, match="needs mu_rdg_table"):
        pr.strength(a, v, a0, redistribution="table")
    with pytest.raises(ValueError, match="only"):
        pr.strength(a, v, a0, mu_rdg_table=FLAT)
    with pytest.raises(ValueError, match=r"mu_rdg\[0\]"):
        pr.strength(a, v, a0, redistribution="table", mu_rdg_table=([0.2], [-1.0]))
    with pytest.raises(ValueError, match="0.7"):
        pr.strength(a, v, a0, redistribution="table", mu_rdg_table=f, friction=(0.7, 0.6))
    import xarray as xr

    old = tmp_path / "no-mu-rdg.nc"
    xr.Dataset(
        {"cf": (("thickness", "mu", "mu_w"), np.full((2, 2, 1), 17.0), {"units": "1"})},
        coords={"thickness": [0.2, 0.3], "volume": [0.0], "mu": [0.4, 1.0], "mu_w": [0.6]},
    ).to_netcdf(old)
    with pytest.raises(ValueError, match="ridge columns"):
        pr.strength(a, v, a0, redistribution="table", mu_rdg_table=old)


def test_the_shipped_table_holds_the_simulated_mu_rdg():
    a, v, a0 = _columns()
    f = pr_data("ridging_table.nc")
    import xarray as xr

    with xr.open_dataset(f) as ds:
        nodes = ds.mu_rdg.sel(mu=1.0, mu_w=0.6).dropna("thickness")
        lo, hi = float(nodes.min()), float(nodes.max())
        # Positive (a mean no thicker than H_min has no exponential: NaN, dropped) and below 4.
        assert nodes.sizes["thickness"] >= 10 and 0.0 < lo <= hi <= 4.0
    t = pr.strength(a, v, a0, redistribution="table", mu_rdg_table=f, friction=(1.0, 0.6))
    # p* rises with mu_rdg in every category, so it lies between the table's extremes.
    assert np.all(t >= pr.strength(a, v, a0, mu_rdg=lo))
    assert np.all(t <= pr.strength(a, v, a0, mu_rdg=hi))


def pr_data(name):
    from pathlib import Path

    return Path(__file__).resolve().parents[2] / "data" / name


def test_command_line_and_xarray_agree(cli, sample, tmp_path):
    import xarray as xr
    import pressridge.xr as prx

    f = _table_file(tmp_path / "t.nc", [0.2, 1.0, 5.0], [[1.0, 1.5, 2.0], [2.0, 3.0, 1.5]])
    out = tmp_path / "p.nc"
    cli("strength", "--input", sample, "--output", out, "--redistribution", "table",
        "--mu-rdg-table", f)
    with xr.open_dataset(sample) as ds:
        want = prx.strength(ds, redistribution="table", mu_rdg_table=f)
        with xr.open_dataset(out) as got:
            np.testing.assert_array_equal(got.strength.values, want.values)
            assert got.attrs["mu_rdg_table"] == want.attrs["mu_rdg_table"]
        # C_f given as node arrays beside the mu_rdg table (a table of C_f = 17 sums in
        # another order than the constant, so to round-off).
        nodes = (np.array([0.1, 10.0]), np.array([17.0, 17.0]))
        both = prx.strength(ds, cf=nodes, redistribution="table", mu_rdg_table=f)
        np.testing.assert_allclose(both.values, want.values, rtol=1e-13)
        step = tmp_path / "s.nc"
        cli("ridge-step", "--input", sample, "--output", step, "--dt", "3600",
            "--convergence", "2e-6", "--shear", "0", "--redistribution", "table",
            "--mu-rdg-table", f, "--friction", "0.4,0.6")
        r = prx.ridge_step(ds, dt=3600.0, convergence=2e-6, shear=0.0, redistribution="table",
                           mu_rdg_table=f, friction=(0.4, 0.6))
        with xr.open_dataset(step) as got:
            for n in ("aicen", "vicen"):
                np.testing.assert_array_equal(got[n].values, r[n].transpose(*got[n].dims).values)
            assert got.attrs["mu_rdg_table"] == r.attrs["mu_rdg_table"]
