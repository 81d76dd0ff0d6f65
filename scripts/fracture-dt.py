#!/usr/bin/env python3
"""Joints broken against the time step (docs/speed-vs-error.md, "Fracture and the time step").

    scripts/fracture-dt.py [DIR]    (default: data/speed-vs-error/fracture-dt)

Reads the run records of the fracture-dt campaign (data/campaigns/speed-vs-error/fracture-dt.toml)
and prints, per time-step safety factor, the step, the joints broken by each seed, their mean with
a 95 % Student-t interval, and the mean's difference from the smallest step's with its 95 % Welch
interval. Standard library only.
"""
import glob
import json
import math
import os
import statistics as st
import sys

# Two-sided 95 % Student-t quantiles for 1-30 degrees of freedom (beyond: 1.96).
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179,
       2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
       2.060, 2.056, 2.052, 2.048, 2.045, 2.042]


def t95(dof):
    return T95[min(int(dof), 30) - 1] if dof < 30.5 else 1.96


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "data/speed-vs-error/fracture-dt"
    points = {}
    for path in glob.glob(os.path.join(root, "runs", "*", "seed-*", "run.json")):
        with open(path) as f:
            r = json.load(f)
        s = r["summary"]
        key = float(os.path.basename(os.path.dirname(os.path.dirname(path))).split("=")[-1])
        points.setdefault(key, []).append((r["seed"], s["blocks_broken"], s["dt"]))
    if not points:
        sys.exit(f"no run records under {root}")
    print("| Δt / stable limit | Δt (s) | runs | joints broken per seed | mean ± 95 % | vs smallest Δt |")
    print("|---|---|---|---|---|---|")
    base = None
    for key in sorted(points):
        runs = sorted(points[key])
        b = [x[1] for x in runs]
        n, m, sd = len(b), st.mean(b), st.stdev(b)
        half = t95(n - 1) * sd / math.sqrt(n)
        if base is None:
            base, diff = (n, m, sd), "—"
        else:
            va, vb = base[2] ** 2 / base[0], sd**2 / n
            dof = (va + vb) ** 2 / (va**2 / (base[0] - 1) + vb**2 / (n - 1))
            d, h = m - base[1], t95(dof) * math.sqrt(va + vb)
            diff = f"{100 * d / base[1]:+.0f} % [{100 * (d - h) / base[1]:+.0f}, {100 * (d + h) / base[1]:+.0f}]"
        print(f"| {key:g} | {runs[0][2]:.3e} | {n} | {', '.join(map(str, b))} | {m:.1f} ± {half:.1f} | {diff} |")


if __name__ == "__main__":
    main()
