"""The shipped ridging table (``data/ridging_table.nc``) as a new user reads it: at every
setting (thickness and friction pair) the final ridged volume, 100·h for the 400-s runs at
0.25 m/s, holds every run of that setting, and ``Table.value`` there is a number. Until
2026-12-01 the volume axis ran to 600.0001 m³/m, so its points missed the runs' final
volumes by about 1e-5 m³/m and held 0–3 of their 7–12 runs."""

import os

import numpy as np
import pytest

import pressridge as pr

TABLE = os.path.join(os.path.dirname(__file__), "..", "..", "data", "ridging_table.nc")


@pytest.fixture(scope="module")
def shipped():
    return pr.Table.open(TABLE)


def test_the_volume_axis_is_round(shipped):
    v = shipped.volume
    assert np.array_equal(v, 2.5 * np.arange(v.size))


def test_every_setting_holds_all_its_runs_at_its_final_volume(shipped):
    ds = shipped.to_xarray()
    runs, cf_runs = ds["runs"], ds["cf_runs"]
    settings = 0
    for h in ds.thickness.values:
        for mu in ds.mu.values:
            for mu_w in ds.mu_w.values:
                n = int(cf_runs.sel(thickness=h, mu=mu, mu_w=mu_w))
                if n == 0:
                    continue
                final = 100.0 * h
                at_end = int(runs.sel(thickness=h, mu=mu, mu_w=mu_w, volume=final))
                assert at_end == n, (h, mu, mu_w, at_end, n)
                settings += 1
    assert settings == 40


def test_value_at_the_final_volume_is_a_number(shipped):
    w = shipped.value("work_mean", thickness=0.2, volume=20.0)
    assert np.isfinite(w) and w > 0.0
