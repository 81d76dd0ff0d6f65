#!/usr/bin/env python3
"""The trends of the energies with friction at one sheet thickness, read from campaign records:
the ordinary least-squares slope over μ = 0.4-1.0 of W, ΔPE and W/ΔPE at each μ_w, with its
95 % Student-t interval (n - 2 degrees of freedom), the method of `pressridge findings`
(crates/lab/src/findings.rs, `slope`) applied at any thickness. docs/validation.md quotes it.

    scripts/friction-slopes.py --thickness 0.2 CAMPAIGN_DIR...

Every run.json under the campaign directories whose sheet is THICKNESS m thick (and whose
scene is otherwise the campaign's) counts once per (scene point, seed), so the default pair
may come from the thickness set and the others from friction-thickness. Energies in kJ/m.
"""
import argparse
import json
import math
import os
import sys


def t_quantile(p, df):
    """The p-quantile of Student's t with df degrees of freedom (bisection on its CDF, the
    CDF by Simpson's rule on the density: standard library only, no SciPy on the CI image)."""

    def cdf(t):
        c = math.exp(math.lgamma((df + 1) / 2) - math.lgamma(df / 2)) / math.sqrt(df * math.pi)
        n = 2000
        h = t / n
        s = 0.0
        for i in range(n + 1):
            x = i * h
            w = 1 if i in (0, n) else (4 if i % 2 else 2)
            s += w * c * (1 + x * x / df) ** (-(df + 1) / 2)
        return 0.5 + s * h / 3

    lo, hi = 0.0, 50.0
    for _ in range(60):
        mid = (lo + hi) / 2
        if cdf(mid) < p:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def slope(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    b = sxy / sxx
    a = my - b * mx
    sse = sum((v - a - b * u) ** 2 for u, v in zip(x, y))
    h = t_quantile(0.975, n - 2) * math.sqrt(sse / (n - 2) / sxx)
    return b, b - h, b + h


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--thickness", type=float, required=True, help="sheet thickness (m)")
    ap.add_argument("campaigns", nargs="+", help="campaign directories (each with runs/)")
    a = ap.parse_args()
    seen = {}
    for camp in a.campaigns:
        root = os.path.join(camp, "runs")
        if not os.path.isdir(root):
            sys.exit(f"friction-slopes: {camp} has no runs/ directory")
        for d, _, files in sorted(os.walk(root)):
            if "run.json" not in files:
                continue
            with open(os.path.join(d, "run.json"), encoding="utf-8") as f:
                r = json.load(f)
            s = r["scene"]
            if abs(s["sheet"]["thickness"] - a.thickness) > 1e-9:
                continue
            mu, muw = s["contact"]["mu"], s["contact"]["mu_water"]
            w, pe = r["summary"]["work"], r["summary"]["potential_energy"]
            seen[(mu, muw, r["seed"])] = (w, pe)
    if not seen:
        sys.exit(f"friction-slopes: no run at sheet.thickness = {a.thickness} m")
    print(f"h = {a.thickness} m, OLS slope per unit μ over μ = 0.4-1.0, 95 % t interval")
    for muw in sorted({k[1] for k in seen}, reverse=True):
        runs = [(k[0], v) for k, v in sorted(seen.items()) if k[1] == muw]
        per_mu = {}
        for mu, _ in runs:
            per_mu[mu] = per_mu.get(mu, 0) + 1
        x = [mu for mu, _ in runs]
        counts = ", ".join(f"{m:g}: {c}" for m, c in sorted(per_mu.items()))
        print(f"μ_w = {muw:g} ({len(runs)} runs; per μ {counts})")
        for name, f, unit in [
            ("W", lambda v: v[0] / 1e3, "kJ/m"),
            ("ΔPE", lambda v: v[1] / 1e3, "kJ/m"),
            ("W/ΔPE", lambda v: v[0] / v[1], ""),
        ]:
            b, lo, hi = slope(x, [f(v) for _, v in runs])
            print(f"  {name}: {b:+.1f} [{lo:+.1f}, {hi:+.1f}] {unit}".rstrip())


if __name__ == "__main__":
    main()
