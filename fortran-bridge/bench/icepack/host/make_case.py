#!/usr/bin/env python3
"""One case of Icepack's column driver (icedrv) as Icepack's scripts set it up.

    make_case.py ICEPACK_DIR CASE DATA_DIR namelist   -> the namelist icepack_in
    make_case.py ICEPACK_DIR CASE DATA_DIR cppdefs    -> the preprocessor definitions
    make_case.py ICEPACK_DIR CASE DATA_DIR layout STDOUT -> the tracer layout in Icepack's
        names (`pressridge ridge-step --tracer-layout`), read from what the driver printed of
        its tracers (icepack_write_tracer_flags, _sizes and the bgc parameters) in STDOUT

CASE is `default` or options joined by commas (`alt01`, `thermo1,dyn`, ...), each applied
over `run1year` as base_suite.ts runs them: the options' set_env.* files change the sizes
(the -D definitions icepack.build makes from icepack.settings), their set_nml.* files the
namelist (keys replaced where configuration/scripts/icepack_in has them). The run reads its
deformation from DATA_DIR/SHEBA/open_clos_lindsay.dat, writes its diagnostics daily and its
NetCDF history (`history_format = 'nc'`).
"""
import re
import sys
from pathlib import Path

src, case, data, what = Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
scripts = src / "configuration" / "scripts"
options = ["run1year"] + ([] if case == "default" else case.split(","))

if what == "cppdefs":
    env = {}
    for line in (scripts / "icepack.settings").read_text().splitlines():
        m = re.match(r"\s*setenv\s+(\w+)\s+(\S+)", line)
        if m:
            env[m.group(1)] = m.group(2)
    for o in options:
        f = scripts / "options" / f"set_env.{o}"
        if f.exists():
            for line in f.read_text().splitlines():
                m = re.match(r"\s*setenv\s+(\w+)\s+(\S+)", line)
                if m:
                    env[m.group(1)] = m.group(2)
    keys = ["NICELYR", "NSNWLYR", "NICECAT", "NFSDCAT", "TRAGE", "TRFY", "TRLVL", "TRPND",
            "TRSNOW", "TRBRI", "NTRISO", "NTRAERO", "NBGCLYR", "TRALG", "TRBGCZ", "TRDOC",
            "TRDIC", "TRDON", "TRFED", "TRFEP", "TRZAERO", "TRBGCS"]
    defs = [f"-DNXGLOB={env['ICE_NXGLOB']}"] + [f"-D{k}={env[k]}" for k in keys]
    print(" ".join(defs + ["-DNO_SNICARHC"]))
    sys.exit(0)

if what == "layout":
    # The driver's own report of its tracers, after its reconciliation of namelist and sizes:
    # lines `   name = value` of Icepack's write routines.
    said = {}
    for line in Path(sys.argv[5]).read_text().splitlines():
        m = re.match(r"^   (\w+)\s*=\s*(\S+)\s*$", line)
        if m:
            said.setdefault(m.group(1).lower(), m.group(2))
    counts = ["nilyr", "nslyr", "nfsd", "n_iso", "n_aero", "nblyr", "n_algae", "n_doc", "n_dic",
              "n_don", "n_fed", "n_fep", "n_zaero"]
    switches = ["tr_iage", "tr_fy", "tr_lvl", "tr_pond_lvl", "tr_pond_topo", "tr_pond_sealvl",
                "tr_snow", "tr_fsd", "tr_iso", "tr_aero", "tr_brine", "z_tracers", "skl_bgc",
                "tr_bgc_n", "tr_bgc_nit", "tr_bgc_c", "tr_bgc_chl", "tr_bgc_am", "tr_bgc_sil",
                "tr_bgc_dms", "tr_bgc_pon", "tr_bgc_don", "tr_bgc_fe", "tr_bgc_hum", "tr_zaero"]
    items = [f"{k}={said[k]}" for k in counts if k in said]
    items += [k for k in switches if said.get(k) == "T"]
    print(",".join(items))
    sys.exit(0)

assert what == "namelist", what
text = (scripts / "icepack_in").read_text()
sets = {}
for o in options:
    f = scripts / "options" / f"set_nml.{o}"
    if not f.exists():
        sys.exit(f"make_case.py: no option set_nml.{o} in {scripts / 'options'}")
    for line in f.read_text().splitlines():
        m = re.match(r"\s*(\w+)\s*=\s*(.+?)\s*$", line)
        if m:
            sets[m.group(1)] = m.group(2)
sets["data_dir"] = f"'{data}/'"
sets["history_format"] = "'nc'"
sets["diagfreq"] = sets.get("diagfreq", "24")
out = []
for line in text.splitlines():
    m = re.match(r"(\s*)(\w+)(\s*=\s*)(.+?)\s*$", line)
    if m and m.group(2) in sets:
        line = f"{m.group(1)}{m.group(2)}{m.group(3)}{sets[m.group(2)]}"
    out.append(line)
print("\n".join(out))
