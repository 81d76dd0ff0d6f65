"""pressridge.ridge_step on numpy arrays: equal to `pressridge ridge-step`, conserving, not
touching its inputs."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import pressridge as pr

DT = 3600.0


@pytest.fixture(scope="module")
def itd(sample):
    with xr.open_dataset(sample) as ds:
        return ds.load()


def test_equals_command_line(cli, sample, itd, tmp_path):
    out = tmp_path / "r.nc"
    cli("ridge-step", "--input", sample, "--output", out, "--dt", DT, "--param", "cs=0.5")
    want = xr.load_dataset(out)
    a, v, a0 = (itd[k].values.copy() for k in ("aicen", "vicen", "aice0"))
    conv = np.maximum(-itd.divu.values, 0.0)
    r = pr.ridge_step(
        a, v, a0, dt=DT, convergence=conv, shear=itd.shear.values, hin_max=itd.hin_max.values, cs=0.5
    )
    for name in ("aicen", "vicen", "aice0", "closing", "opening", "dardg1dt", "dardg2dt", "dvirdgdt"):
        np.testing.assert_array_equal(getattr(r, name), want[name].values, err_msg=name)
    # Inputs untouched; volume conserved, area 1.
    np.testing.assert_array_equal(a, itd.aicen.values)
    np.testing.assert_allclose(r.vicen.sum(0), v.sum(0), rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(r.aice0 + r.aicen.sum(0), 1.0, atol=1e-10)
    assert (r.dardg1dt >= 0).all() and r.dardg1dt.max() > 0


def test_defaults_and_layouts(itd):
    a, v = itd.aicen.values, itd.vicen.values
    # aice0 = 1 - sum(aicen) and CICE's default bounds (the sample's own) when not given.
    r = pr.ridge_step(a, v, dt=DT, convergence=1e-6)
    r2 = pr.ridge_step(a, v, np.maximum(1.0 - a.sum(0), 0.0), dt=DT, convergence=np.full((60, 80), 1e-6), shear=0.0, hin_max=pr.category_bounds(5))
    for x, y in zip(r, r2):
        np.testing.assert_array_equal(x, y)
    np.testing.assert_array_equal(pr.category_bounds(5), itd.hin_max.values)
    rf = pr.ridge_step(np.asfortranarray(a), np.asfortranarray(v), dt=DT, convergence=1e-6)
    assert rf.aicen.flags.f_contiguous and r.aicen.flags.c_contiguous
    for x, y in zip(r, rf):
        np.testing.assert_array_equal(x, y)
    one = pr.ridge_step(a[:, 3, 4], v[:, 3, 4], dt=DT, convergence=1e-6)
    assert one.aicen.shape == (5,) and isinstance(one.closing, float)
    np.testing.assert_array_equal(one.aicen, r.aicen[:, 3, 4])


def test_errors(itd):
    a, v = itd.aicen.values, itd.vicen.values
    with pytest.raises(ValueError, match="dt is negative"):
        pr.ridge_step(a, v, dt=-1.0, convergence=0.0)
    with pytest.raises(ValueError, match=r"convergence is negative"):
        pr.ridge_step(a, v, dt=DT, convergence=-1e-6)
    with pytest.raises(ValueError, match="does not broadcast"):
        pr.ridge_step(a, v, dt=DT, convergence=np.zeros(7))
    with pytest.raises(ValueError, match="hin_max"):
        pr.ridge_step(a, v, dt=DT, convergence=0.0, hin_max=[0, 1, 2])
    with pytest.raises(ValueError, match="unknown keyword or parameter `Cs`"):
        pr.ridge_step(a, v, dt=DT, convergence=0.0, Cs=0.5)
    big = a.copy()
    big[:, 2, 2] = 0.9
    with pytest.raises(ValueError, match=r"\(2, 2\): total area .* exceeds the maximum"):
        pr.ridge_step(big, v, 1.0 - a.sum(0), dt=DT, convergence=0.0)
    with pytest.raises(ValueError, match="convergence is needed"):
        pr.ridge_step(a, v, dt=DT)  # convergence (or the host's closing) is required
