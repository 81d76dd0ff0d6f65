#!/usr/bin/env python3
"""What a campaign cost, from its run records: per campaign directory the runs, those not
already counted in an earlier directory (the same scene and seed, e.g. the friction set's
Figure 5 pair taken from the thickness set), the sum of the runs' own wall times
(`summary.wall_seconds`) and of their time steps (`summary.steps`). The summed wall time is an
upper bound on the CPU time (each run is single-threaded), reached where nothing else shared
the cores; the steps do not depend on the machine.

    scripts/campaign-cost.py CAMPAIGN_DIR...
"""
import json
import os
import sys


def main():
    dirs = sys.argv[1:]
    if not dirs or any(d.startswith("-") for d in dirs):
        sys.exit(__doc__.strip())
    seen = set()
    total = [0, 0.0, 0]
    print("| campaign | runs | counted here | summed run wall (h) | steps (millions) |")
    print("|---|---|---|---|---|")
    for d in dirs:
        root = os.path.join(d, "runs")
        if not os.path.isdir(root):
            sys.exit(f"campaign-cost: {d} has no runs/ directory")
        runs = new = steps = 0
        wall = 0.0
        for dirpath, _, files in sorted(os.walk(root)):
            if "run.json" not in files:
                continue
            with open(os.path.join(dirpath, "run.json"), encoding="utf-8") as f:
                r = json.load(f)
            runs += 1
            key = (json.dumps(r["scene"], sort_keys=True), r["seed"])
            if key in seen:
                continue
            seen.add(key)
            new += 1
            wall += r["summary"]["wall_seconds"]
            steps += r["summary"]["steps"]
        total[0] += new
        total[1] += wall
        total[2] += steps
        print(f"| {d} | {runs} | {new} | {wall / 3600:.2f} | {steps / 1e6:.0f} |")
    print(f"| all | | {total[0]} | {total[1] / 3600:.2f} | {total[2] / 1e6:.0f} |")


if __name__ == "__main__":
    main()
