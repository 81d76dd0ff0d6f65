"""The complete ridging step's other inputs in Python: the freezing temperature per column
(numpy and the dataset's ``Tf``), the thermodynamic constants (``STEP_PARAMETERS``, the Rust
``RidgeStepParams::FIELDS``), general tracer layouts (``TracerLayout.from_fields``) and the
layout told from a dataset's variable names (``TracerLayout.detect``, the command line's)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import pressridge as pr
from test_ridge_step_full import _dataset, _random_columns


def _columns(layout, ncat=4, ncol=300, seed=21):
    rng = np.random.default_rng(seed)
    return _random_columns(rng, ncat, ncol, layout)


# ---------------------------------------------------------------------------------------
# Freezing temperature per column


def test_freezing_temperature_per_column_equals_column_calls():
    layout = pr.TracerLayout.cice(2, 1, age=True)
    hin, aicen, vicen, vsnon, t, aice0 = _columns(layout)
    ncol = aicen.shape[1]
    tf = np.linspace(-2.1, -1.5, ncol)
    common = dict(vsnon=vsnon, trcrn=t, layout=layout, dt=3600.0, convergence=2e-6,
                  shear=1e-6, hin_max=hin)
    r = pr.ridge_step(aicen, vicen, aice0, tf=tf, **common)
    zapped = r.categories["first_ice"] == 1
    assert zapped.any(), "some tiny categories are zapped"
    ts = layout.field("Tsfc")[0]
    # An emptied category takes its own column's Tf.
    np.testing.assert_array_equal(r.trcrn[:, ts][zapped], np.broadcast_to(tf, zapped.shape)[zapped])
    for c in range(0, ncol, 37):
        one = pr.ridge_step(aicen[:, c], vicen[:, c], aice0[c], tf=tf[c],
                            **{**common, "vsnon": vsnon[:, c], "trcrn": t[:, :, c]})
        np.testing.assert_array_equal(one.trcrn, r.trcrn[:, :, c])
        assert one.fhocn == r.fhocn[c]
    with pytest.raises(ValueError, match="tf has shape"):
        pr.ridge_step(aicen, vicen, aice0, tf=tf[:-1], **common)
    bad = tf.copy()
    bad[5] = np.nan
    with pytest.raises(ValueError, match=r"tf.*\(5,\)|\(5,\).*tf"):
        pr.ridge_step(aicen, vicen, aice0, tf=bad, **common)


def test_xarray_takes_tf_from_the_dataset():
    import xarray as xr
    import pressridge.xr as prx

    ds, layout = _dataset()
    tf = xr.DataArray(
        np.linspace(-2.0, -1.6, ds.sizes["nj"] * ds.sizes["ni"]).reshape(ds.sizes["nj"], ds.sizes["ni"]),
        dims=("nj", "ni"),
    )
    want = prx.ridge_step(ds, dt=1800.0, convergence=2e-6, tf=tf)
    got = prx.ridge_step(ds.assign(Tf=tf.assign_attrs(units="degC")), dt=1800.0, convergence=2e-6)
    np.testing.assert_array_equal(got.Tsfcn.values, want.Tsfcn.values)
    assert "Tf" in got.attrs["tf"]
    with pytest.raises(ValueError, match=r"`Tf`.*'K'"):
        prx.ridge_step(ds.assign(Tf=(tf + 273.15).assign_attrs(units="K")), dt=1800.0,
                       convergence=2e-6)
    with pytest.raises(ValueError, match=r"`Tf`.*no `units`"):
        prx.ridge_step(ds.assign(Tf=tf), dt=1800.0, convergence=2e-6)


# ---------------------------------------------------------------------------------------
# Thermodynamic constants


def test_step_constants_are_one_list_and_reach_the_step():
    assert set(pr.STEP_PARAMETERS) == {
        "rhos", "lfresh", "cp_ice", "fsnowrdg", "ice_ref_salinity", "itd_area_min",
        "itd_mass_min", "hs_min", "tmin",
    }
    assert pr.STEP_PARAMETERS["rhos"][0] == "kg m-3"
    assert pr.DEFAULT_STEP_PARAMETERS["rhos"] == 330.0
    assert pr.DEFAULT_STEP_PARAMETERS["lfresh"] == 2.835e6 - 2.501e6
    layout = pr.TracerLayout.cice(2, 1)
    hin, aicen, vicen, vsnon, t, aice0 = _columns(layout, seed=3)
    dt = 1800.0
    common = dict(vsnon=vsnon, trcrn=t, layout=layout, dt=dt, convergence=5e-6, hin_max=hin)
    d = pr.ridge_step(aicen, vicen, aice0, **common)
    f = pr.ridge_step(aicen, vicen, aice0, fsnowrdg=0.2, **common)
    # More snow reaches the ocean with fsnowrdg = 0.2 (0.8 of the snow on ridging ice).
    assert (f.snow_to_ocean >= d.snow_to_ocean).all()
    assert f.snow_to_ocean.sum() > d.snow_to_ocean.sum()
    r = pr.ridge_step(aicen, vicen, aice0, rhos=300.0, rhoi=900.0, fsnowrdg=0.2,
                      salt_flux="prognostic", **common)
    # The fresh water uses rhoi = 900 and rhos = 300.
    np.testing.assert_allclose(
        r.fresh, (900.0 * r.ice_to_ocean + 300.0 * r.snow_to_ocean) / dt, rtol=1e-12, atol=1e-25
    )
    # Prognostic salt flux: the zapped ice's own salinity, so salt is conserved.
    si, li = layout.field("sice")
    s0 = (vicen * t[:, si : si + li].mean(1)).sum(0)
    s1 = (r.vicen * r.trcrn[:, si : si + li].mean(1)).sum(0) + r.fsalt * dt / (900.0 * 1e-3)
    np.testing.assert_allclose(s1, s0, rtol=1e-10)
    with pytest.raises(ValueError, match="rhos"):
        pr.ridge_step(aicen, vicen, aice0, rhos=-1.0, **common)
    with pytest.raises(ValueError, match=r"fsnowrdg.*\[0, 1\]"):
        pr.ridge_step(aicen, vicen, aice0, fsnowrdg=2.0, **common)
    with pytest.raises(ValueError, match="rhoz.*constants of the complete step: rhos"):
        pr.ridge_step(aicen, vicen, aice0, rhoz=1.0, **common)
    with pytest.raises(ValueError, match="salt_flux"):
        pr.ridge_step(aicen, vicen, aice0, salt_flux="none", **common)
    with pytest.raises(ValueError, match="rhos.*belong"):
        pr.ridge_step(aicen, vicen, aice0, dt=dt, convergence=1e-6, rhos=300.0)


def test_xarray_writes_the_constants_used():
    import pressridge.xr as prx

    ds, _ = _dataset()
    r = prx.ridge_step(ds, dt=1800.0, convergence=2e-6, rhos=300.0, salt_flux="prognostic")
    assert r.attrs["rhos"] == "300 kg m-3"
    assert r.attrs["rhoi"] == "917 kg m-3"
    assert r.attrs["salt_flux"] == "prognostic"
    for name, (units, _) in pr.STEP_PARAMETERS.items():
        assert r.attrs[name].endswith(units)


# ---------------------------------------------------------------------------------------
# General layouts


def test_layout_from_fields():
    F = pr.TracerLayout.from_fields
    # Icepack's names need no more than their levels.
    l = F([{"name": "Tsfc"}, {"name": "qice", "levels": 3}, {"name": "qsno", "levels": 2},
           {"name": "sice", "levels": 3}, ("FY",), ("alvl",), ("vlvl",), ("apnd",), ("hpnd",),
           ("ipnd",)])
    assert l == pr.TracerLayout.cice(3, 2, first_year=True, level_ice=True, ponds=True)
    assert "TracerLayout.cice(nilyr=3, nslyr=2" in repr(l)
    assert pickle.loads(pickle.dumps(l)) == l
    # Any other tracer, on any base; no surface temperature.
    g = F([("qice", 2), ("qsno", 1), ("sice", 2),
           {"name": "bgc", "levels": 2, "base": "ice_volume"},
           ("dust", 1, "snow_volume", [], "other")])
    assert g.ntrcr == 8 and g.names[-3:] == ["bgc001", "bgc002", "dust"]
    assert g.flags == dict(age=False, first_year=False, level_ice=False, ponds=False,
                           snow=False, isotopes=0, aerosols=0, pond_topo=False,
                           pond_sealvl=False, fsd=0, brine=False)
    assert "from_fields" in repr(g) and pickle.loads(pickle.dumps(g)) == g
    assert hash(pickle.loads(pickle.dumps(g))) == hash(g)
    assert g.spec()[3] == dict(name="bgc", levels=2, base="ice_volume", strata=[], role="other")
    # It ridges: the other tracers move with their base and are conserved with it.
    rng = np.random.default_rng(8)
    ncat, ncol = 3, 50
    hin = pr.category_bounds(ncat)
    aicen = rng.uniform(0.2, 0.3, (ncat, ncol))
    vicen = aicen * (0.5 + hin[:-1, None])
    vsnon = 0.1 * aicen
    t = np.zeros((ncat, g.ntrcr, ncol))
    t[:, 0:2] = -3e8
    t[:, 2] = -1.1e8
    t[:, 3:5] = 4.0
    t[:, 5:7] = rng.uniform(0, 1, (ncat, 2, ncol))
    t[:, 7] = rng.uniform(0, 1, (ncat, ncol))
    r = pr.ridge_step(aicen, vicen, vsnon=vsnon, trcrn=t, layout=g, dt=3600.0,
                      convergence=3e-6, hin_max=hin, cleanup=False)
    assert (r.dardg1dt > 0).all()
    np.testing.assert_allclose((r.vicen * r.trcrn[:, 5]).sum(0), (vicen * t[:, 5]).sum(0), rtol=1e-12)
    # A snow tracer stays in [min, max] of its inputs (it moves with the snow).
    assert (r.trcrn[:, 7] >= t[:, 7].min() - 1e-12).all() and (r.trcrn[:, 7] <= 1.0 + 1e-12).all()
    # Errors name the field and what is wrong.
    with pytest.raises(ValueError, match=r"fields\[1\] \(`bgc`\).*base"):
        F([("qice",), ("bgc",), ("qsno",), ("sice",)])
    with pytest.raises(ValueError, match=r"fields\[1\] \(`bgc`\): unknown base `volume`"):
        F([("qice",), ("bgc", 1, "volume"), ("qsno",), ("sice",)])
    with pytest.raises(ValueError, match=r"fields\[0\] \(`qice`\): levels = 0"):
        F([("qice", 0), ("qsno",), ("sice",)])
    with pytest.raises(ValueError, match=r"fields\[2\] \(`sice`\): unknown role `salt`"):
        F([("qice",), ("qsno",), {"name": "sice", "role": "salt"}])
    with pytest.raises(ValueError, match=r"fields\[0\]: unknown key `lvls`"):
        F([{"name": "qice", "lvls": 2}])
    with pytest.raises(ValueError, match="qice and sice need the same number of levels"):
        F([("qice", 2), ("qsno",), ("sice", 3)])
    with pytest.raises(ValueError, match="no qsno field"):
        F([("qice",), ("sice",)])
    with pytest.raises(ValueError, match=r"apnd.*alvl|alvl.*apnd|ponds"):
        F([("qice",), ("qsno",), ("sice",), ("apnd",), ("hpnd",)])


# ---------------------------------------------------------------------------------------
# Layout detection


def test_layout_detection_from_names_and_datasets():
    import pressridge.xr as prx

    l = pr.TracerLayout.cice(3, 2, age=True, level_ice=True)
    assert pr.TracerLayout.detect(l.names + ["aicen", "vsnon"]) == l
    assert pr.TracerLayout.detect(["aicen", "vicen", "divu"]) is None
    with pytest.raises(ValueError, match="`vlvl`.*alvl, vlvl go together"):
        pr.TracerLayout.detect([n for n in l.names if n != "vlvl"])
    with pytest.raises(ValueError, match="`qice001`"):
        pr.TracerLayout.detect(["aicen", "vsnon"])
    ds, layout = _dataset()
    auto = prx.ridge_step(ds, dt=1800.0, convergence=2e-6)
    given = prx.ridge_step(ds, dt=1800.0, convergence=2e-6, layout=layout)
    for name in layout.names + ["fhocn", "aicen"]:
        np.testing.assert_array_equal(auto[name].values, given[name].values)
    assert auto.attrs["tracers"] == " ".join(layout.names)
    # Missing or ambiguous variables are named.
    with pytest.raises(ValueError, match="`hpnd`"):
        prx.ridge_step(ds.drop_vars("hpnd"), dt=1800.0, convergence=2e-6)
    with pytest.raises(ValueError, match="`qice001`"):
        prx.ridge_step(ds.drop_vars([n for n in layout.names]), dt=1800.0, convergence=2e-6)
    smaller = pr.TracerLayout.cice(3, 1, level_ice=True, ponds=True)
    with pytest.raises(ValueError, match="ambiguous.*iage"):
        prx.ridge_step(ds.assign(iage=ds.aicen * 0), dt=1800.0, convergence=2e-6, layout=smaller)
    # No snow, no tracers: the area-volume step, as the command line.
    bare = ds.drop_vars(layout.names + ["vsnon"])
    r = prx.ridge_step(bare, dt=1800.0, convergence=2e-6)
    assert "fhocn" not in r
    with pytest.raises(ValueError, match="rhos belong"):
        prx.ridge_step(bare, dt=1800.0, convergence=2e-6, rhos=300.0)


# ---------------------------------------------------------------------------------------
# The command line and xarray on the same file


def test_command_line_host_rates_tf_and_constants_equal_xarray(cli, tmp_path):
    """``pressridge ridge-step --rates host`` with ``Tf`` per cell and constants from
    ``--param``/``--param-file`` gives what ``xr.ridge_step`` gives on the same dataset, to
    the bit, and both write the constants used with their units."""
    import xarray as xr
    import pressridge.xr as prx

    ds, layout = _dataset(ntime=1)
    ds = ds.isel(time=0).drop_vars("time")
    nj, ni = ds.sizes["nj"], ds.sizes["ni"]
    closing = np.linspace(1e-7, 4e-6, nj * ni).reshape(nj, ni)
    ds["closing"] = (("nj", "ni"), closing, {"units": "s-1"})
    ds["opening"] = (("nj", "ni"), 0.1 * closing, {"units": "s-1"})
    ds["Tf"] = (("nj", "ni"), np.linspace(-2.0, -1.7, nj * ni).reshape(nj, ni), {"units": "degC"})
    ds = ds.rename({"nc_bounds": "nb"})
    # Numbers in order (category first) for the command line.
    ds = ds.transpose("nc", "nj", "ni", "nb")
    inp, out = tmp_path / "in.nc", tmp_path / "out.nc"
    ds.to_netcdf(inp)
    (tmp_path / "c.txt").write_text("fsnowrdg = 0.25\n")
    cli("ridge-step", "--input", inp, "--output", out, "--dt", "1800", "--rates", "host",
        "--param", "rhos=310", "--param-file", tmp_path / "c.txt", "--no-cleanup")
    want = prx.ridge_step(ds, dt=1800.0, closing=ds.closing, opening=ds.opening,
                          rhos=310.0, fsnowrdg=0.25, cleanup=False)
    got = xr.open_dataset(out)
    for name in layout.names + ["aicen", "vicen", "vsnon", "aice0", "fresh", "fhocn", "fsalt",
                                "dardg1dt", "opening", "krdgn"]:
        np.testing.assert_array_equal(got[name].values, want[name].transpose(*got[name].dims).values, err_msg=name)
    for name in ["rhoi", *pr.STEP_PARAMETERS, "salt_flux"]:
        assert got.attrs[name] == want.attrs[name], name
    assert got.attrs["rates"].startswith("host") and "Tf" in got.attrs["tf"]
    got.close()


# ---------------------------------------------------------------------------------------
# One parser of the step's constants: the command line and Python


def test_command_line_and_python_take_exactly_the_librarys_names(cli, sample, tmp_path):
    """``pressridge ridge-step --param`` and the keywords of ``ridge_step`` and
    ``xr.ridge_step`` go through the library's one parser of the step's constants (the Rust
    ``RidgeStepOptions`` set: ``PARAMETERS`` then ``STEP_PARAMETERS``): each accepts every
    name (all at their defaults: the default step, to the bit), and a misspelt name is
    refused by each, complete step or area-volume step, with the same message (the closest
    name and every valid name); Python calls it a keyword or parameter, its parameters being
    keywords."""
    import xarray as xr
    import pressridge.xr as prx

    names = [*pr.PARAMETERS, *pr.STEP_PARAMETERS]
    defaults = {**pr.DEFAULT_PARAMETERS, **pr.DEFAULT_STEP_PARAMETERS}
    assert list(defaults) == names, "one value per name, no name twice"
    ds, layout = _dataset(ntime=1)
    ds = ds.isel(time=0).drop_vars("time").rename({"nc_bounds": "nb"})
    ds = ds.transpose("nc", "nj", "ni", "nb")
    inp = tmp_path / "in.nc"
    ds.to_netcdf(inp)
    forcing = ["--dt", "1800", "--convergence", "2e-6", "--shear", "1e-6"]

    # Every name accepted, at its default: the default step.
    every = [a for n in names for a in ("--param", f"{n}={defaults[n]!r}")]
    cli("ridge-step", "--input", inp, "--output", tmp_path / "plain.nc", *forcing)
    cli("ridge-step", "--input", inp, "--output", tmp_path / "every.nc", *forcing, *every)
    with xr.open_dataset(tmp_path / "plain.nc") as p, xr.open_dataset(tmp_path / "every.nc") as g:
        for v in p.data_vars:
            np.testing.assert_array_equal(g[v].values, p[v].values, err_msg=v)
        assert g.attrs["parameter_overrides"] == ", ".join(f"{n}={defaults[n]!r}" for n in names)
    hin, aicen, vicen, vsnon, t, aice0 = _columns(layout, ncol=40, seed=5)
    common = dict(vsnon=vsnon, trcrn=t, layout=layout, dt=1800.0, convergence=2e-6,
                  shear=1e-6, hin_max=hin)
    d = pr.ridge_step(aicen, vicen, aice0, **common)
    e = pr.ridge_step(aicen, vicen, aice0, **common, **defaults)
    for f in ("aicen", "vicen", "vsnon", "trcrn", "fresh", "fhocn", "fsalt"):
        np.testing.assert_array_equal(getattr(e, f), getattr(d, f), err_msg=f)

    # A misspelt name: the same message from every face.
    bad = ("fsnowrgd", 0.3)
    said = []
    for extra in (forcing, ["--dt", "1800"]):
        src = inp if extra is forcing else sample
        r = cli("ridge-step", "--input", src, "--output", tmp_path / "bad.nc", *extra,
                "--param", f"{bad[0]}={bad[1]}", check=False)
        assert r.returncode != 0 and "unknown parameter " in r.stderr, r.stderr
        said.append(r.stderr.strip().split("unknown parameter ", 1)[1])
    with xr.open_dataset(sample) as s:
        a, v = s.aicen.values, s.vicen.values
    for call in (
        lambda: pr.ridge_step(aicen, vicen, aice0, **common, **dict([bad])),
        lambda: pr.ridge_step(a, v, dt=1800.0, convergence=0.0, **dict([bad])),
        lambda: prx.ridge_step(ds, dt=1800.0, convergence=2e-6, **dict([bad])),
    ):
        with pytest.raises(ValueError) as err:
            call()
        said.append(str(err.value).split("unknown keyword or parameter ", 1)[1])
    assert len(set(said)) == 1, said
    msg = said[0]
    assert msg.startswith("`fsnowrgd` (did you mean `fsnowrdg`?); ridging parameters: "), msg
    # The names listed are the library's, every one, in order.
    groups = [part.split(": ", 1) for part in msg.split("; ")[1:]]
    assert [g[0] for g in groups] == ["ridging parameters", "constants of the complete step"]
    assert [n for g in groups for n in g[1].split(", ")] == names


# ---------------------------------------------------------------------------------------
# Packed tracers (Icepack column driver's history `trcrn(time, ncat, ntrcr, ni)`)


def _packed(ds, layout):
    """``ds`` with its restart-name tracers packed into ``trcrn`` as icedrv writes it: the
    tracer dimension after the category dimension."""
    import xarray as xr

    t = xr.concat([ds[n] for n in layout.names], dim="ntrcr").transpose("time", "nc", "ntrcr", "nj", "ni")
    return ds.drop_vars(layout.names).assign(trcrn=t)


def test_icepack_layout_names_round_trip_and_are_refused_by_name():
    l = pr.TracerLayout.from_icepack("icedrv")
    assert l.ntrcr == 21 and l.icepack == "nilyr=7,nslyr=1,tr_lvl,tr_pond_lvl"
    assert l == pr.TracerLayout.cice(7, 1, level_ice=True, ponds=True)
    s = pr.TracerLayout.cice(2, 1, snow=True, isotopes=1, aerosols=2, pond_topo=True)
    assert pr.TracerLayout.from_icepack(s.icepack) == s
    sealvl = pr.TracerLayout.from_icepack("nilyr=2,nslyr=1,tr_pond_sealvl")
    assert sealvl.flags["pond_sealvl"] and not sealvl.flags["pond_topo"]
    assert sealvl.icepack.endswith("tr_pond_sealvl")
    assert pr.TracerLayout.from_fields([("Tsfc",), ("qice", 2), ("qsno", 1), ("sice", 2), ("bgc", 1, "area")]).icepack is None
    with pytest.raises(ValueError, match="`tr_aero`.*n_aero"):
        pr.TracerLayout.from_icepack("icedrv,tr_aero")
    with pytest.raises(ValueError, match="`nslyr`"):
        pr.TracerLayout.from_icepack("nilyr=7")


def test_xarray_packed_tracers_equal_the_named_ones(tmp_path):
    import pressridge.xr as prx

    ds, layout = _dataset()
    packed = _packed(ds, layout)
    spec = layout.icepack
    want = prx.ridge_step(ds, dt=1800.0, convergence=2e-6, shear=1e-6)
    for p in (packed, packed.chunk({"nj": 1})):
        got = prx.ridge_step(p, dt=1800.0, convergence=2e-6, shear=1e-6, tracer_layout=spec)
        assert got.trcrn.dims == packed.trcrn.dims
        assert got.trcrn.attrs["tracer_layout"] == spec
        for it, n in enumerate(layout.names):
            np.testing.assert_array_equal(got.trcrn.isel(ntrcr=it).values, want[n].values, err_msg=n)
            assert n not in got
        for n in ("aicen", "vicen", "vsnon", "fhocn", "fresh"):
            np.testing.assert_array_equal(got[n].values, want[n].values, err_msg=n)
    # The layout object does as well as its text.
    got = prx.ridge_step(packed, dt=1800.0, convergence=2e-6, tracer_layout=layout)
    assert got.trcrn.attrs["tracer_layout"] == spec
    with pytest.raises(ValueError, match="name its layout with tracer_layout"):
        prx.ridge_step(packed, dt=1800.0, convergence=2e-6)
    with pytest.raises(ValueError, match=r"holds 14 tracers.*has 21"):
        prx.ridge_step(packed, dt=1800.0, convergence=2e-6, tracer_layout="icedrv")
    with pytest.raises(ValueError, match="tracer_var needs tracer_layout"):
        prx.ridge_step(ds, dt=1800.0, convergence=2e-6, tracer_var="trcrn")
    with pytest.raises(ValueError, match="one tracer dimension"):
        prx.ridge_step(packed, dt=1800.0, convergence=2e-6, tracer_layout=spec, tracer_var="vsnon")


def test_command_line_packed_tracers_equal_xarray(cli, tmp_path):
    """``pressridge ridge-step --tracer-layout`` and ``xr.ridge_step(tracer_layout=)`` on
    the same packed file give the same bits."""
    import xarray as xr
    import pressridge.xr as prx

    ds, layout = _dataset()
    packed = _packed(ds, layout).rename({"nc_bounds": "nb"})
    inp, out = tmp_path / "in.nc", tmp_path / "out.nc"
    packed.to_netcdf(inp)
    cli("ridge-step", "--input", inp, "--output", out, "--dt", "1800", "--convergence", "2e-6",
        "--tracer-layout", layout.icepack)
    want = prx.ridge_step(packed, dt=1800.0, convergence=2e-6, tracer_layout=layout.icepack)
    got = xr.open_dataset(out)
    assert got.trcrn.dims == packed.trcrn.dims
    for n in ("trcrn", "aicen", "vsnon", "fhocn", "aice0"):
        np.testing.assert_array_equal(got[n].values, want[n].transpose(*got[n].dims).values, err_msg=n)
    got.close()


def test_command_line_and_xarray_carry_the_column_drivers_biogeochemistry(cli, tmp_path):
    """A packed history with the column driver's z-tracers (nitrate and a z-aerosol on the
    brine grid) and one aerosol: the command line and ``xr.ridge_step`` give the same bits,
    the per-species fluxes included, one field per row as ``faero_ocn001``, ``flux_bio001``."""
    import xarray as xr
    import pressridge.xr as prx

    spec = ("nilyr=3,nslyr=1,tr_lvl,tr_pond_lvl,tr_aero,n_aero=1,tr_brine,z_tracers,nblyr=2,"
            "tr_bgc_Nit,tr_zaero,n_zaero=1")
    layout = pr.TracerLayout.from_icepack(spec)
    assert layout.icepack == spec and layout.nbtrcr == 2
    # 13 physical, 4 aerosol, fbri; 2 bio tracers of 5 levels each; 2 zbgc_frac.
    assert layout.ntrcr == 18 + 10 + 2
    ds, _ = _dataset(layout=layout)
    packed = _packed(ds, layout).rename({"nc_bounds": "nb"})
    inp, out = tmp_path / "in.nc", tmp_path / "out.nc"
    packed.to_netcdf(inp)
    cli("ridge-step", "--input", inp, "--output", out, "--dt", "1800", "--convergence", "2e-6",
        "--tracer-layout", spec)
    want = prx.ridge_step(packed, dt=1800.0, convergence=2e-6, tracer_layout=spec)
    got = xr.open_dataset(out)
    species = ["faero_ocn001", "flux_bio001", "flux_bio002"]
    assert "fiso_ocn001" not in want and "flux_bio003" not in want
    for n in ("trcrn", "aicen", "vsnon", "fhocn", "aice0", *species):
        np.testing.assert_array_equal(got[n].values, want[n].transpose(*got[n].dims).values, err_msg=n)
    for n in species:
        assert got[n].attrs["units"] == want[n].attrs["units"], n
    got.close()
    assert (want.flux_bio002 > 0).any() and (want.flux_bio002 >= 0).all()
    # Without the bio switches the count says where they go.
    with pytest.raises(ValueError, match=r"holds 30 tracers.*has 18.*z_tracers"):
        prx.ridge_step(packed, dt=1800.0, convergence=2e-6,
                       tracer_layout="nilyr=3,nslyr=1,tr_lvl,tr_pond_lvl,tr_aero,n_aero=1,tr_brine")
