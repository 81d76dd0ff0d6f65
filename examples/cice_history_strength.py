"""p* of a CICE history file with C_f = 17 and with the simulator's C_f table, and a map of
the difference (docs/python.md, "A CICE history file").

    python examples/cice_history_strength.py [HISTORY.nc] [TABLE.nc] [OUT.png]
    python examples/cice_history_strength.py --make-sample data/cice_history_sample.nc

HISTORY.nc is a CICE history file with `aicen` and `vicen` (time, nc, nj, ni), e.g. from
`f_aicen = 'd'`, `f_vicen = 'd'` in ice_in; the category dimension is found by name (`nc`),
`time` is kept, land (`_FillValue`) stays missing, and the map is drawn on `TLON`/`TLAT`
when the file has them. The default is `data/cice_history_sample.nc`, a small synthetic file
in the same layout made from `data/sample_itd.nc` by `--make-sample` (not model output).
TABLE.nc defaults to `data/ridging_table.nc` (the simulator's table). OUT.png defaults to
`docs/figures/cice_history_strength.png`.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import xarray as xr

import pressridge as pr
import pressridge.xr as prx

ROOT = Path(__file__).resolve().parents[1]


def make_sample(out: Path) -> None:
    """A CICE-history-like file (two daily means, 30 x 40 cells, five categories, a coast)
    from the analytic `data/sample_itd.nc`: `aicen`, `vicen` (time, nc, nj, ni) float32 with
    `_FillValue` 1e30 on land, `aice`, `tmask`, `TLON`/`TLAT`, `NCAT`, `time` (noleap)."""
    s = xr.load_dataset(ROOT / "data" / "sample_itd.nc").isel(nj=slice(25, 55), ni=slice(0, 40))
    nj, ni = s.sizes["nj"], s.sizes["ni"]
    j, i = np.meshgrid(np.arange(nj), np.arange(ni), indexing="ij")
    land = i < 4 + (j // 6)  # a coast along the western edge
    cat = s[["aicen", "vicen"]].rename({"ncat": "nc"}).drop_vars(
        [c for c in s.coords], errors="ignore"
    )
    # Day 2: the same ice, 20 % thicker.
    d = xr.concat([cat, cat.assign(vicen=cat.vicen * 1.2)], dim="time")
    d = d.transpose("time", "nc", "nj", "ni").where(~land).astype(np.float32)
    attrs = {
        "aicen": {"units": "1", "long_name": "ice area, categories"},
        "vicen": {"units": "m", "long_name": "ice volume, categories"},
    }
    for k in ("aicen", "vicen"):
        d[k].attrs = attrs[k] | {"coordinates": "TLON TLAT time"}
        d[k].encoding = {"_FillValue": np.float32(1.0e30), "dtype": "float32"}
    d["aice"] = d.aicen.sum("nc", skipna=False).assign_attrs(
        units="1", long_name="ice area  (aggregate)", coordinates="TLON TLAT time"
    )
    d["aice"].encoding = {"_FillValue": np.float32(1.0e30), "dtype": "float32"}
    d["tmask"] = (("nj", "ni"), (~land).astype(np.float32), {
        "long_name": "ocean grid mask", "comment": "0 = land, 1 = ocean",
        "coordinates": "TLON TLAT"})
    lon = -150.0 + 0.5 * i + 0.1 * j
    lat = 72.0 + 0.25 * j - 0.02 * i
    d = d.assign_coords(
        time=("time", np.array([0.5, 1.5]), {"long_name": "model time"}),
        TLON=(("nj", "ni"), lon.astype(np.float32),
              {"long_name": "T grid center longitude", "units": "degrees_east"}),
        TLAT=(("nj", "ni"), lat.astype(np.float32),
              {"long_name": "T grid center latitude", "units": "degrees_north"}),
    )
    d["time"].attrs.update(units="days since 2005-01-01 00:00:00", calendar="noleap")
    d["NCAT"] = ("nc", s.hin_max.values[1:].astype(np.float32),
                 {"long_name": "category maximum thickness", "units": "m"})
    for k in ("time", "TLON", "TLAT", "NCAT", "tmask"):
        d[k].encoding["_FillValue"] = None
    d.attrs = {
        "title": "synthetic CICE-style history file (not model output)",
        "source": "pressridge examples/cice_history_strength.py --make-sample, from "
        "data/sample_itd.nc (analytic)",
        "Conventions": "CF-1.0",
        "history": "python examples/cice_history_strength.py --make-sample",
    }
    d.to_netcdf(out, format="NETCDF3_64BIT")
    print(f"wrote {out}")


def main(argv: list[str]) -> None:
    if argv[:1] == ["--make-sample"]:
        make_sample(Path(argv[1]) if len(argv) > 1 else ROOT / "data" / "cice_history_sample.nc")
        return
    history = Path(argv[0]) if len(argv) > 0 else ROOT / "data" / "cice_history_sample.nc"
    table_path = Path(argv[1]) if len(argv) > 1 else ROOT / "data" / "ridging_table.nc"
    out = Path(argv[2]) if len(argv) > 2 else ROOT / "docs" / "figures" / "cice_history_strength.png"

    # --8<-- [start:example]
    ds = xr.open_dataset(history, chunks={"time": 1})  # aicen(time, nc, nj, ni), lazy
    table = pr.Table.open(table_path)                   # the simulator's C_f(h)
    p17 = prx.strength(ds, cf=17.0)                     # (time, nj, ni), N m-1, CICE's C_f
    ptab = prx.strength(ds, cf=table)                   # C_f of the ridging ice, from the table
    diff = (ptab - p17).rename("strength_difference").compute()
    p17, ptab = p17.compute(), ptab.compute()
    # --8<-- [end:example]

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t0 = {"time": 0} if "time" in p17.dims else {}
    on_grid = "TLON" in p17.coords and "TLAT" in p17.coords
    x, y = (p17.TLON.values, p17.TLAT.values) if on_grid else (None, None)
    when = str(p17.time.values[0]) if "time" in p17.dims else ""

    def draw(ax, da, **kw):
        v = da.isel(t0).values
        return ax.pcolormesh(x, y, v, shading="auto", **kw) if on_grid else ax.pcolormesh(v, **kw)

    vmax = float(max(p17.max(), ptab.max())) / 1e3
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4), constrained_layout=True)
    for ax, da, title in (
        (axes[0], p17 / 1e3, "p*, C_f = 17 (CICE)"),
        (axes[1], ptab / 1e3, f"p*, C_f from {table_path.name}"),
    ):
        fig.colorbar(draw(ax, da, vmin=0, vmax=vmax, cmap="viridis"), ax=ax,
                     label="ice strength p* (kN m$^{-1}$)")
        ax.set_title(title)
    lim = float(np.nanmax(np.abs(diff.values))) / 1e3 or 1.0
    fig.colorbar(draw(axes[2], diff / 1e3, vmin=-lim, vmax=lim, cmap="RdBu_r"), ax=axes[2],
                 label="Δp* (kN m$^{-1}$)")
    axes[2].set_title("difference: table − C_f = 17")
    for ax in axes:
        ax.set_facecolor("0.85")  # land (missing) in grey
        ax.set_xlabel("longitude (°E)" if on_grid else "ni")
        ax.set_ylabel("latitude (°N)" if on_grid else "nj")
    fig.suptitle(f"{history.name} {when}: Rothrock (1975) strength, exponential participation "
                 "and redistribution; grey: land")
    fig.savefig(out, dpi=90)
    ice = np.isfinite(diff.values)
    print(f"{history.name}: dims {dict(p17.sizes)}, {int((~ice).sum())} missing (land) cells")
    print(f"max p* {float(p17.max()):.0f} N/m (C_f = 17), {float(ptab.max()):.0f} N/m (table); "
          f"difference {float(diff.min()):.0f} to {float(diff.max()):.0f} N/m")
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
