#!/usr/bin/env python3
"""Figures and summary of tables-cice.sh's runs (docs/host-cice.md, "What the tables do").

    .venv/bin/python fortran-bridge/cice/tables-figures.py RUNS_DIR [--out DIR] [--last N]

RUNS_DIR holds tables-CONFIG/history/iceh.*.nc (daily means) of each configuration run. Writes
into DIR (default docs/figures/cice):
  series.png       domain means against day: thickness, strength, ridged area and volume,
                   ice speed, one line per configuration
  maps.png         the last day's mean thickness, strength, ridged volume and ice speed of
                   stock CICE, and each configuration's difference from it
  itd.png          the last day's thickness distribution: the domain's ice area and volume
                   per category
and prints a Markdown table of the domain means over the last N days (default 10) with
their differences from stock CICE, and how far each quantity still drifts (the change of
its mean from the N days before). Needs numpy, netCDF4 and matplotlib (the test
environment's, scripts/setup.sh --python).
"""
import argparse
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402

ORDER = ["cice", "hibler", "cf", "mu_rdg", "tables"]
LABELS = {
    "cice": "CICE: C_f 17, μ_rdg 3",
    "hibler": "CICE: Hibler's strength",
    "cf": "C_f(h) of the table",
    "mu_rdg": "μ_rdg(h) of the table",
    "tables": "both from the table",
}
# Domain means: (history variable, label, unit, scale).
SERIES = [
    ("hi", "mean thickness", "m", 1.0),
    ("hi_max", "thickest cell", "m", 1.0),
    ("strength", "mean strength", "kN/m", 1e-3),
    ("ardg", "ridged area fraction", "1", 1.0),
    ("vrdg", "ridged volume", "m", 1.0),
    ("speed", "ice speed", "cm/s", 100.0),
]


def read_config(d):
    """Daily fields of one configuration: dict of name -> array (day, ...), over ice cells."""
    files = sorted(glob.glob(os.path.join(d, "history", "iceh.*.nc")))
    if not files:
        raise SystemExit(f"tables-figures: no history files in {d}/history")
    out = {k: [] for k in ["hi", "aice", "strength", "ardg", "vrdg", "speed", "aicen", "vicen"]}
    for f in files:
        with netCDF4.Dataset(f) as n:
            def var(name):
                a = np.ma.filled(n[name][0].astype(float), np.nan)
                return a

            for k in ["hi", "aice", "strength", "ardg", "vrdg", "aicen", "vicen"]:
                out[k].append(var(k))
            u, v = var("uvel"), var("vvel")
            out["speed"].append(np.hypot(u, v))
    out["hi_max"] = [np.full_like(h, np.nanmax(h)) for h in out["hi"]]
    return {k: np.array(v) for k, v in out.items()}, len(files)


def domain_mean(a):
    """Mean over the grid of each day (NaN cells left out)."""
    return np.nanmean(a.reshape(a.shape[0], -1), axis=1)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs")
    p.add_argument("--out", default="docs/figures/cice")
    p.add_argument("--last", type=int, default=10)
    a = p.parse_args()
    configs = [c for c in ORDER if os.path.isdir(os.path.join(a.runs, f"tables-{c}"))]
    if "cice" not in configs:
        raise SystemExit(f"tables-figures: {a.runs}/tables-cice (stock CICE) is needed")
    data, days = {}, {}
    for c in configs:
        data[c], days[c] = read_config(os.path.join(a.runs, f"tables-{c}"))
    n = min(days.values())
    os.makedirs(a.out, exist_ok=True)

    # Time series.
    fig, axes = plt.subplots(len(SERIES), 1, figsize=(7.5, 2.1 * len(SERIES)), sharex=True)
    day = np.arange(1, n + 1)
    for ax, (k, label, unit, s) in zip(axes, SERIES):
        for c in configs:
            ax.plot(day, s * domain_mean(data[c][k][:n]), label=LABELS[c])
        ax.set_ylabel(f"{label} ({unit})")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8, ncol=2)
    axes[-1].set_xlabel("day")
    fig.suptitle("CICE gbox128: domain means of the daily history")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "series.png"), dpi=120)
    plt.close(fig)

    # Maps of the last day: stock CICE's fields, and each configuration's difference from it.
    others = [c for c in configs if c != "cice"]
    rows = [SERIES[0], SERIES[2], SERIES[4], SERIES[5]]
    ncol = 1 + len(others)
    fig, axes = plt.subplots(len(rows), ncol, figsize=(2.9 * ncol + 1.2, 2.7 * len(rows)), squeeze=False)
    for r, (k, label, unit, s) in enumerate(rows):
        ax = axes[r, 0]
        im = ax.imshow(s * data["cice"][k][n - 1], origin="lower", cmap="viridis")
        ax.set_title(f"{LABELS['cice']}\n{label} ({unit})", fontsize=8)
        fig.colorbar(im, ax=ax, shrink=0.8)
        diffs = [s * (data[c][k][n - 1] - data["cice"][k][n - 1]) for c in others]
        dmax = max((np.nanmax(np.abs(d)) for d in diffs), default=1.0) or 1.0
        for j, (c, d) in enumerate(zip(others, diffs)):
            ax = axes[r, 1 + j]
            im = ax.imshow(d, origin="lower", vmin=-dmax, vmax=dmax, cmap="RdBu_r")
            ax.set_title(f"{LABELS[c]} − CICE\n{label} ({unit})", fontsize=8)
        if others:
            fig.colorbar(im, ax=axes[r, 1:].tolist(), shrink=0.8)
    for ax in axes.flat:
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle(f"CICE gbox128, day {n}: stock CICE and the differences from it")
    fig.savefig(os.path.join(a.out, "maps.png"), dpi=80)
    plt.close(fig)

    # Thickness distribution of the last day: area and volume per category over the domain.
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
    ncat = data["cice"]["aicen"].shape[1]
    w = 0.8 / len(configs)
    for j, c in enumerate(configs):
        ar = np.nanmean(data[c]["aicen"][n - 1].reshape(ncat, -1), axis=1)
        vo = np.nanmean(data[c]["vicen"][n - 1].reshape(ncat, -1), axis=1)
        x = np.arange(1, ncat + 1) + (j - (len(configs) - 1) / 2) * w
        axes[0].bar(x, ar, w, label=LABELS[c])
        axes[1].bar(x, vo, w, label=LABELS[c])
    axes[0].set_ylabel("domain-mean area fraction (1)")
    axes[1].set_ylabel("domain-mean volume (m)")
    for ax in axes:
        ax.set_xlabel("thickness category")
        ax.grid(alpha=0.3, axis="y")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"CICE gbox128, day {n}: the thickness distribution")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "itd.png"), dpi=120)
    plt.close(fig)

    # The summary: means over the last N days, differences from CICE then and over the N days
    # before (whether a difference has settled), and CICE's own drift.
    last = max(1, min(a.last, n // 2))
    print(f"Domain means over days {n - last + 1}-{n} of {n}; in brackets the difference from "
          f"stock CICE, then over days {n - 2 * last + 1}-{n - last} (stock CICE: the change "
          f"of its mean between the two):\n")
    head = "| configuration | " + " | ".join(f"{lbl} ({u})" for _, lbl, u, _ in SERIES) + " |"
    print(head)
    print("|---" * (len(SERIES) + 1) + "|")

    def windows(c, k, s):
        m = s * domain_mean(data[c][k][:n])
        return m[n - last:].mean(), m[n - 2 * last:n - last].mean()

    for c in configs:
        cells = []
        for k, _, _, s in SERIES:
            now, before = windows(c, k, s)
            if c == "cice":
                cells.append(f"{now:.3g} (drift {100 * (now / before - 1):+.1f} %)")
            else:
                rn, rb = windows("cice", k, s)
                cells.append(f"{now:.3g} ({100 * (now / rn - 1):+.1f} %; {100 * (before / rb - 1):+.1f} %)")
        print(f"| {LABELS[c]} | " + " | ".join(cells) + " |")
    print(f"\nfigures: {a.out}/series.png, maps.png, itd.png", file=sys.stderr)


if __name__ == "__main__":
    main()
