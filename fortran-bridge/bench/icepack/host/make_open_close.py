#!/usr/bin/env python3
"""A year of hourly deformation for icedrv in the format of the SHEBA open/close file it
reads (`ocn_data_type = 'SHEBA'`, `ice_open_clos` in icedrv_forcing.F90): per line the time
(hours), the opening rate and the closing rate as divergence (1/s; negative: closing; the
driver takes closing = -value). Opening 2e-7 1/s and closing 2e-7 1/s plus 0.3 per year of
net closing, each varying over the day and the season so that the column ridges and opens
every day. The driver's `uniform_ice` inflow replaces what ridging closes, so the net must
stay a fraction per year: a net of 8.7 per year made a column 17 km thick.

    make_open_close.py OUT [HOURS]   (HOURS: 8760)
"""
import math
import sys

out = sys.argv[1]
hours = int(sys.argv[2]) if len(sys.argv) > 2 else 8760
year = 365.0 * 86400.0
net = 0.3 / year  # 1/s
with open(out, "w") as f:
    for h in range(hours):
        day = 2.0 * math.pi * h / 24.0
        season = 2.0 * math.pi * h / 8760.0
        opening = 2.0e-7 * (1.0 + 0.5 * math.sin(day)) * (1.0 + 0.3 * math.cos(season))
        closing = (2.0e-7 * (1.0 + 0.5 * math.sin(day)) * (1.0 + 0.3 * math.cos(season))
                   + net)
        f.write(f"{h:8.1f} {opening:16.8e} {-closing:16.8e}\n")
