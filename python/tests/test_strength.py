"""pressridge.strength on numpy arrays: equal to the command line (the Rust API) on the
sample distribution, for every layout, with clear errors."""

from __future__ import annotations

import re

import numpy as np
import pytest
import xarray as xr

import pressridge as pr
from conftest import MIN_TICKS, ticks_during


@pytest.fixture(scope="module")
def itd(sample):
    with xr.open_dataset(sample) as ds:
        return ds.load()


def cli_strength(cli, sample, tmp_path, *flags):
    out = tmp_path / "p.nc"
    cli("strength", "--input", sample, "--output", out, *flags)
    with xr.open_dataset(out) as ds:
        return ds["strength"].values


def write_cf_table(path, thickness, cf):
    import netCDF4

    with netCDF4.Dataset(path, "w") as f:
        f.createDimension("node", len(thickness))
        f.createVariable("thickness", "f8", ("node",))[:] = thickness
        f.createVariable("cf", "f8", ("node",))[:] = cf


CASES = [
    ({}, []),
    (
        dict(participation="thorndike", redistribution="uniform"),
        ["--participation", "thorndike", "--redistribution", "uniform"],
    ),
    (dict(law="hibler"), ["--strength", "hibler"]),
    (dict(cf="flato1991"), ["--cf-preset", "flato1991"]),
    (dict(cf=2.0), ["--cf", "2"]),
    (dict(mu_rdg=4.0, gstar=0.2), ["--param", "mu_rdg=4", "--param", "gstar=0.2"]),
]


@pytest.mark.parametrize("kwargs,flags", CASES, ids=lambda x: str(x))
def test_equals_command_line(cli, sample, itd, tmp_path, kwargs, flags):
    want = cli_strength(cli, sample, tmp_path, *flags)
    got = pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, **kwargs)
    assert got.shape == (60, 80)
    np.testing.assert_array_equal(got, want)  # the same routine: equal to the bit


def test_cf_table_file_equals_command_line(cli, sample, itd, tmp_path):
    table = tmp_path / "cf.nc"
    write_cf_table(table, [0.5, 1.5, 3.0], [12.0, 15.0, 20.0])
    want = cli_strength(cli, sample, tmp_path, "--cf-table", table)
    with pytest.warns(pr.CfClampedWarning, match="outside the C_f table") as rec:
        got = pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, cf=table)
    np.testing.assert_array_equal(got, want)
    # The warning says how many columns were clamped and in how many the clamp carries a
    # material share (>= 1 %) of the strength, as the command line's attributes do.
    assert pr.CF_CLAMPED_MATERIAL_SHARE == 0.01
    m = re.search(
        r"(\d+) of (\d+) columns .* carries >= 1% of the strength in (\d+) of them "
        r"\(at most ([0-9.]+)%\)",
        str(rec[0].message),
    )
    assert m, str(rec[0].message)
    clamped, ncol, material, share = int(m[1]), int(m[2]), int(m[3]), float(m[4])
    assert 0 < clamped <= ncol and material <= clamped and 0.0 <= share <= 100.0
    assert (material > 0) == (share >= 1.0)
    nodes = ([0.5, 1.5, 3.0], [12.0, 15.0, 20.0])
    with pytest.warns(pr.CfClampedWarning):
        by_nodes = pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, cf=nodes)
    np.testing.assert_array_equal(by_nodes, want)


def test_presets_and_default():
    assert pr.CF_PRESETS == {"hibler1980": 2.0, "flato1991": 15.0, "cice": 17.0}
    a, v = [0.5, 0.3], [0.4, 0.9]
    assert pr.strength(a, v) == pr.strength(a, v, cf=17.0) == pr.strength(a, v, cf="cice")
    assert pr.strength(a, v, cf=2.0) == pytest.approx(pr.strength(a, v) * 2 / 17, rel=1e-14)


def test_layouts_pass_without_copy_and_agree(itd):
    a, v, a0 = itd.aicen.values, itd.vicen.values, itd.aice0.values
    assert a.flags.c_contiguous
    want = pr.strength(a, v, a0)
    assert pr._core._layout(a) == ("view", "C")
    af, vf, a0f = (np.asfortranarray(x) for x in (a, v, a0))
    assert pr._core._layout(af) == ("view", "F")
    got = pr.strength(af, vf, a0f)
    assert got.flags.f_contiguous  # the output follows the input's order
    np.testing.assert_array_equal(got, want)
    # (nj, ni, ncat) storage seen as (ncat, nj, ni): category axis strided, still a view.
    at = np.ascontiguousarray(np.moveaxis(a, 0, -1))
    vt = np.ascontiguousarray(np.moveaxis(v, 0, -1))
    assert pr._core._layout(np.moveaxis(at, -1, 0)) == ("view", "C")
    np.testing.assert_array_equal(pr.strength(np.moveaxis(at, -1, 0), np.moveaxis(vt, -1, 0), a0), want)
    # A strided slice cannot be flattened without a copy; the numbers do not change.
    assert pr._core._layout(a[:, ::2, :])[0] == "copy"
    np.testing.assert_array_equal(pr.strength(a[:, ::2], v[:, ::2], a0[::2]), want[::2])
    # Other dtypes are converted.
    np.testing.assert_array_equal(
        pr.strength(a.astype(">f8"), v.astype(">f8"), a0.astype(">f8")), want
    )


def test_any_trailing_shape(itd):
    a, v, a0 = itd.aicen.values, itd.vicen.values, itd.aice0.values
    want = pr.strength(a, v, a0)
    flat = pr.strength(a.reshape(5, -1), v.reshape(5, -1), a0.reshape(-1))
    np.testing.assert_array_equal(flat, want.reshape(-1))
    cube = pr.strength(a.reshape(5, 6, 10, 80), v.reshape(5, 6, 10, 80), a0.reshape(6, 10, 80))
    np.testing.assert_array_equal(cube, want.reshape(6, 10, 80))
    one = pr.strength(a[:, 7, 9], v[:, 7, 9], a0[7, 9])
    assert isinstance(one, float) and one == want[7, 9]


def test_valid_mask_skips_columns(itd):
    a, v, a0 = itd.aicen.values.copy(), itd.vicen.values.copy(), itd.aice0.values
    a[:, 0, 0] = np.nan
    ok = np.ones((60, 80), bool)
    ok[0, 0] = False
    got = pr.strength(a, v, a0, valid=ok)
    assert np.isnan(got[0, 0])
    want = pr.strength(itd.aicen.values, v, a0)
    np.testing.assert_array_equal(got[ok], want[ok])


@pytest.mark.parametrize(
    "change,message",
    [
        (lambda a, v, a0: a.__setitem__((2, 3, 4), np.nan), r"at spatial index \(3, 4\): aicen\[category 2\] is not finite"),
        (lambda a, v, a0: a.__setitem__((1, 0, 5), -0.2), r"at spatial index \(0, 5\): aicen\[category 1\] is negative"),
        (lambda a, v, a0: v.__setitem__((0, 10, 11), -1.0), r"\(10, 11\): vicen\[category 0\] is negative"),
        (lambda a, v, a0: a0.__setitem__((5, 5), 0.9), r"\(5, 5\): total area .* differs from 1"),
    ],
)
def test_bad_values_are_named(itd, change, message):
    a, v, a0 = (x.copy() for x in (itd.aicen.values, itd.vicen.values, itd.aice0.values))
    change(a, v, a0)
    with pytest.raises(ValueError, match=message):
        pr.strength(a, v, a0)


def test_bad_arguments(itd):
    a, v, a0 = itd.aicen.values, itd.vicen.values, itd.aice0.values
    with pytest.raises(ValueError, match=r"vicen has shape \(5, 60, 79\), expected the shape of aicen \(5, 60, 80\)"):
        pr.strength(a, v[..., :-1])
    with pytest.raises(ValueError, match=r"aice0 has shape \(80, 60\), expected the spatial shape"):
        pr.strength(a, v, a0.T)
    with pytest.raises(ValueError, match="category axis first"):
        pr.strength(np.float64(0.3), np.float64(0.3))
    with pytest.raises(ValueError, match="unknown participation `linear`"):
        pr.strength(a, v, participation="linear")
    with pytest.raises(ValueError, match="unknown redistribution"):
        pr.strength(a, v, redistribution="gamma")
    with pytest.raises(ValueError, match="unknown strength law"):
        pr.strength(a, v, law="coulomb")
    with pytest.raises(ValueError, match="unknown keyword or parameter `mu`"):
        pr.strength(a, v, mu=3.0)
    with pytest.raises(ValueError, match="invalid parameter mu_rdg = -1: must be positive"):
        pr.strength(a, v, mu_rdg=-1)
    with pytest.raises(ValueError, match=r"invalid parameter cf = 0: must lie in \[1, 1000\]"):
        pr.strength(a, v, cf=0.0)
    with pytest.raises(ValueError, match=r"invalid parameter cf = 2000+: must lie in \[1, 1000\]"):
        pr.strength(a, v, cf=2e307)
    with pytest.raises(ValueError, match=r"cf\[1\] = 0.5 is out of range"):
        pr.strength(a, v, cf=([0.5, 1.0], [10.0, 0.5]))
    with pytest.raises(ValueError, match="neither a C_f preset"):
        pr.strength(a, v, cf="cice2")
    with pytest.raises(ValueError, match="strictly increasing"):
        pr.strength(a, v, cf=([1.0, 0.5], [10.0, 12.0]))
    with pytest.raises(ValueError, match="must be an array of numbers"):
        pr.strength(a, "thick")


def test_missing_cf_file(itd, tmp_path):
    from pathlib import Path

    with pytest.raises(FileNotFoundError, match="nope.nc"):
        pr.strength(itd.aicen.values, itd.vicen.values, cf=Path(tmp_path / "nope.nc"))


def test_releases_the_gil():
    """Python threads keep running while the library computes."""
    rng = np.random.default_rng(1)
    a = rng.uniform(0, 0.2, (5, 400_000))
    v = a * rng.uniform(0.2, 4.0, a.shape)

    def work():
        for _ in range(5):
            pr.strength(a, v, law="rothrock", participation="thorndike", cf=([0.1, 5.0], [10.0, 20.0]))
        return True

    done, during = ticks_during(work)
    assert done
    # With the GIL held for the whole call this thread could not tick during it.
    assert during >= MIN_TICKS, during


@pytest.mark.parametrize("detach", [False, True])
def test_a_rust_panic_becomes_runtime_error(detach):
    with pytest.raises(RuntimeError, match="internal error .*deliberate test panic"):
        pr._core._panic_for_test(detach)


def _unaligned(a):
    """A copy of ``a`` whose data start one byte past an 8-byte boundary (numpy's
    ``flags.aligned`` False), as dask.distributed can unpickle arrays from a byte buffer."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    buf = np.zeros(a.nbytes + 8, dtype=np.uint8)
    start = 1 if buf.ctypes.data % 8 == 0 else 8 - buf.ctypes.data % 8 + 1
    u = buf[start : start + a.nbytes].view(np.float64).reshape(a.shape)
    u[...] = a
    assert not u.flags.aligned
    return u


def test_unaligned_arrays_are_copied_or_refused(itd):
    # The public call copies unaligned input and gives the same bits; the extension itself
    # refuses it with a ValueError naming the argument (a panic must not reach Python).
    a, v, a0 = itd.aicen.values, itd.vicen.values, itd.aice0.values
    want = pr.strength(a, v, a0)
    got = pr.strength(_unaligned(a), _unaligned(v), _unaligned(a0))
    np.testing.assert_array_equal(got, want)
    with pytest.raises(ValueError, match="aicen: the array's data are not aligned"):
        pr._core._layout(_unaligned(a))
