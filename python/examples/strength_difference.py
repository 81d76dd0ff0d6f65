"""Worked example of docs/python.md: p* of the sample thickness distribution with C_f = 17
and with the simulator's C_f table, and their difference, as a PNG.

    python python/examples/strength_difference.py [TABLE.nc] [OUT.png]

TABLE.nc defaults to data/ridging_table.nc when it exists; otherwise the script runs the
tiny campaign of the test suite (2 thicknesses x 2 seeds x 5 s) and tabulates it, which is
enough to show the mechanics but not a table to use for science.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

import pressridge as pr
import pressridge.xr as prx

ROOT = Path(__file__).resolve().parents[2]

TINY_SPEC = """\
name = "tiny"
seeds = 2
sample_interval = 1.0
set = ["duration=5.0", "sheet.length=8.0"]

[[axis]]
keys = ["sheet.thickness", "sheet.block_width"]
values = [[0.25, 0.25], [0.35, 0.25]]
"""


def tiny_table(workdir: Path) -> Path:
    spec = workdir / "tiny.toml"
    spec.write_text(TINY_SPEC)
    pr.campaign(spec, workdir / "campaign")  # all cores of this machine
    pr.tabulate(workdir / "campaign", workdir / "table.nc", points=11)
    return workdir / "table.nc"


def main() -> None:
    default = ROOT / "data" / "ridging_table.nc"
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else ROOT / "docs" / "figures" / "python_strength_difference.png"
    with tempfile.TemporaryDirectory() as tmp:
        if len(sys.argv) > 1:
            table_path = Path(sys.argv[1])
        elif default.is_file():
            table_path = default
        else:
            table_path = tiny_table(Path(tmp))
        table = pr.Table.open(table_path)
        print(table)
        for h, cf in zip(*table.cf_nodes()):
            print(f"  C_f({h:.2f} m) = {cf:.2f}")

        # --8<-- [start:example]
        ds = xr.open_dataset(ROOT / "data" / "sample_itd.nc", chunks={"nj": 30, "ni": 40})
        p17 = prx.strength(ds, cf=17.0).compute()    # CICE's default C_f
        ptab = prx.strength(ds, cf=table).compute()  # C_f(h) of the ridging ice, from the table
        diff = (ptab - p17).rename("strength_difference")
        # --8<-- [end:example]

    vmax = float(max(p17.max(), ptab.max())) / 1e3
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), constrained_layout=True)
    for ax, da, title in (
        (axes[0], p17 / 1e3, "p*, C_f = 17 (CICE)"),
        (axes[1], ptab / 1e3, f"p*, C_f from {table_path.name}"),
    ):
        im = ax.pcolormesh(da.values, vmin=0, vmax=vmax, cmap="viridis")
        ax.set_title(title)
        fig.colorbar(im, ax=ax, label="ice strength p* (kN/m)")
    lim = float(np.nanmax(np.abs(diff.values))) / 1e3
    im = axes[2].pcolormesh(diff.values / 1e3, vmin=-lim, vmax=lim, cmap="RdBu_r")
    axes[2].set_title("difference: table − C_f = 17")
    fig.colorbar(im, ax=axes[2], label="Δp* (kN/m)")
    for ax in axes:
        ax.set_xlabel("ni")
        ax.set_ylabel("nj")
        ax.set_aspect("equal")
    fig.suptitle("data/sample_itd.nc: Rothrock (1975) strength, exponential participation and redistribution")
    fig.savefig(out, dpi=90)
    print(f"max p* {float(p17.max()):.0f} N/m (C_f = 17), {float(ptab.max()):.0f} N/m (table); "
          f"difference {float(diff.min()):.0f} to {float(diff.max()):.0f} N/m")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
