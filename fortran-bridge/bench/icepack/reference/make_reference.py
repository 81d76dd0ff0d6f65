#!/usr/bin/env python3
"""Reference columns of icepack_step_ridge with snow, isotope and aerosol tracers.

Takes the cases of tests/data/icepack/ridge_step_cases.jsonl (the 23-tracer CICE layout),
adds to every category the snow tracers (smice, smliq, rhos, rsnw), N_ISO isotope species
in snow and ice and N_AERO aerosol species (snow and ice, surface layer and interior: four
tracers each) in Icepack's driver order (icedrv_init.F90), runs them through Icepack's
icepack_step_ridge with the driver ridge_reference (built by make-reference.sh) and writes
the same JSONL schema with the extended layout and the fluxes faero_ocn and fiso_ocn.

    make_reference.py DRIVER IN.jsonl OUT.jsonl [VARIANT]

VARIANT `aero` (default): the layout above. `topo`: topography ponds instead of level-ice
ponds (apnd on the area, hpnd and ipnd on apnd), the snow tracers with Icepack's refills
(snwredist = 'ITD', snwgrain), three floe-size categories, one isotope and one aerosol
species, and the brine fraction fbri. `bgc`: `topo` with two vertically resolved bio tracers
(z_tracers, nblyr = 2: three levels in the ice on fbri, two in the snow) after fbri, as
Icepack's driver lays them out (init_bgc_trcr); `skl`: `topo` with two skeletal bio tracers
(skl_bgc, one level each, on the ice area). Both book Icepack's flux_bio.
"""
import json
import re
import subprocess
import sys

N_ISO, N_AERO, NFSD, TOPO = 3, 2, 0, False
# Bio tracers: kind (0 none, 1 skl_bgc, 2 z_tracers), bio grid layers, number.
BGC, NBLYR, NBTRCR = 0, 1, 0


def set_variant(v):
    global N_ISO, N_AERO, NFSD, TOPO, BGC, NBLYR, NBTRCR
    if v in ("topo", "bgc", "skl"):
        N_ISO, N_AERO, NFSD, TOPO = 1, 1, 3, True
    else:
        assert v == "aero", v
    if v == "bgc":
        BGC, NBLYR, NBTRCR = 2, 2, 2
    elif v == "skl":
        BGC, NBLYR, NBTRCR = 1, 1, 2


def bio_levels():
    """Tracers per bio tracer: nblyr + 1 in the ice and 2 in the snow, or 1 (skeletal)."""
    return NBLYR + 3 if BGC == 2 else 1


def layout(params):
    """Fields (name, levels, depend, strata) in Icepack's driver order."""
    nilyr, nslyr = params["nilyr"], params["nslyr"]
    f = [(t["name"], t["levels"]) for t in params["tracer_layout"]]
    f += [("smice", nslyr), ("smliq", nslyr), ("rhos", nslyr), ("rsnw", nslyr)]
    if NFSD:
        f += [("fsd", NFSD)]
    f += [("isosno", N_ISO), ("isoice", N_ISO)]
    for k in range(1, N_AERO + 1):
        f += [(f"aerosnossl{k:03d}", 1), (f"aerosnoint{k:03d}", 1),
              (f"aeroicessl{k:03d}", 1), (f"aeroiceint{k:03d}", 1)]
    if TOPO:
        f += [("fbri", 1)]
    if NBTRCR:
        f += [("bgc", NBTRCR * bio_levels())]
    start, i = {}, 0
    for name, lev in f:
        start[name] = i
        i += lev
    assert f[2][0] == "qsno" and nilyr == f[1][1]
    return f, start, i


def depend(name, start):
    """Icepack's trcr_depend, trcr_base, n_trcr_strata, nt_strata (1-based) of a field."""
    snow = {"qsno", "smice", "smliq", "rhos", "rsnw", "isosno"}
    ice = {"qice", "sice", "iage", "vlvl", "isoice", "fbri"}
    if TOPO and name == "apnd":
        return 0, [1, 0, 0], []
    if TOPO and name in ("hpnd", "ipnd"):
        return 2 + start["apnd"] + 1, [1, 0, 0], [start["apnd"] + 1]
    if name in ("apnd",):
        return 2 + start["alvl"] + 1, [1, 0, 0], [start["alvl"] + 1]
    if name in ("hpnd", "ipnd"):
        return 2 + start["apnd"] + 1, [1, 0, 0], [start["alvl"] + 1, start["apnd"] + 1]
    if name in snow or name.startswith("aerosno"):
        return 2, [0, 0, 1], []
    if name in ice or name.startswith("aeroice"):
        return 1, [0, 1, 0], []
    return 0, [1, 0, 0], []


def rows(name, lev, start):
    """Icepack's table rows (trcr_depend, trcr_base, strata) of each level of a field: the
    bio tracers as Icepack's driver sets them (init_bgc_trcr), the rest by depend()."""
    if name != "bgc":
        return [depend(name, start)] * lev
    out = []
    for _ in range(NBTRCR):
        if BGC == 2:
            fb = start["fbri"] + 1
            out += [(2 + fb, [0, 1, 0], [fb])] * (NBLYR + 1)
            out += [(2, [0, 0, 1], [])] * 2
        else:
            out += [(0, [1, 0, 0], [])]
    return out


def extra(name, k, n, area):
    """A deterministic value of an added tracer (level k, category n); zero without ice.
    Snow tracers in kg m-3 and m, isotopes and aerosols in kg m-3 of their base."""
    if area <= 0.0:
        return 0.0
    x = (n + 1) * (k + 1)
    if name.startswith("aero"):
        scale = {"aerosnossl": 3.0, "aerosnoint": 1.0, "aeroicessl": 0.5, "aeroiceint": 0.2}
        return 1.0e-6 * (1 + int(name[-3:])) * (n + 1) * scale[name[:10]]
    if name == "fsd":
        return [0.5, 0.3, 0.2][k]
    if name == "bgc":
        return 1.0 + 0.1 * k + 0.5 * n
    return {"smice": 250.0 + 5.0 * x, "smliq": 2.0 + 0.5 * x, "rhos": 300.0 + 3.0 * x,
            "rsnw": 1.0e-4 * (1 + 0.1 * x), "isosno": 1.0e-3 * (1 + 0.3 * x),
            "isoice": 2.0e-3 * (1 + 0.2 * x), "fbri": 0.8 + 0.02 * n}[name]


def fnum(x):
    return repr(float(x))


def main():
    driver, src, dst = sys.argv[1:4]
    set_variant(sys.argv[4] if len(sys.argv) > 4 else "aero")
    lines = [json.loads(l) for l in open(src) if l.strip()]
    params, cases = lines[0], lines[1:]
    fields, start, ntrcr = layout(params)
    nt = {k: 0 for k in ["Tsfc", "qice", "qsno", "sice", "iage", "FY", "alvl", "vlvl", "apnd",
                         "hpnd", "ipnd", "smice", "smliq", "rhos", "rsnw", "isosno", "isoice"]}
    for k in nt:
        nt[k] = start[k] + 1
    out = [f"{params['nilyr']} {params['nslyr']} {ntrcr} {N_AERO} {N_ISO} {NFSD}",
           " ".join(str(v) for v in nt.values()) + f" {start['aerosnossl001'] + 1}"
           + f" {start['fsd'] + 1 if NFSD else 0} {start['fbri'] + 1 if TOPO else 0}",
           ("1 1 1 0 1 1 1 1 1 1 1" if TOPO else "1 1 1 1 1 1 1 0 0 0 0"),
           f"{NBLYR} {NBTRCR} {BGC}"]
    bio_index = [start["bgc"] + 1 + j * bio_levels() for j in range(NBTRCR)]
    if NBTRCR:
        out.append(" ".join(str(b) for b in bio_index))
    tables = {"trcr_depend": [], "trcr_base": [], "n_trcr_strata": [], "nt_strata": []}
    for name, lev in fields:
        for d, base, strata in rows(name, lev, start):
            s = (strata + [0, 0])[:2]
            out.append(f"{d} {base[0]} {base[1]} {base[2]} {len(strata)} {s[0]} {s[1]}")
            tables["trcr_depend"].append(d)
            tables["trcr_base"].append(base)
            tables["n_trcr_strata"].append(len(strata))
            tables["nt_strata"].append(s)
    out.append(str(len(cases)))
    for c in cases:
        i = c["inputs"]
        ncat = i["ncat"]
        hasc = i["closing_in"] is not None
        out.append(f"{ncat} {i['ndtd']} {i['krdg_partic']} {i['krdg_redist']} {int(hasc)} "
                   f"{int(i['docleanup'])} {int(i['dorebin'])}")
        out.append(" ".join(fnum(x) for x in [
            i["dt"], i["rdg_conv"], i["rdg_shear"], i["mu_rdg"], i["Tf"], i["aice0"],
            i["aice"], i["closing_in"] or 0.0, i["opening_in"] or 0.0]))
        for k in ("hin_max", "aicen", "vicen", "vsnon"):
            out.append(" ".join(fnum(x) for x in i[k]))
        tr = []
        for n in range(ncat):
            for name, lev in fields:
                for k in range(lev):
                    if name in i["trcrn"]:
                        tr.append(i["trcrn"][name][n][k])
                    else:
                        tr.append(extra(name, k, n, i["aicen"][n]))
        out.append(" ".join(fnum(x) for x in tr))
        out.append(" ".join(str(int(b)) for b in i["first_ice"]))
        # Keep the added tracers in the case's inputs, by field as the schema has them.
        i["trcrn"] = {name: [[tr[n * ntrcr + start[name] + k] for k in range(lev)]
                             for n in range(ncat)] for name, lev in fields}
    res = subprocess.run([driver], input="\n".join(out) + "\n", capture_output=True,
                         text=True, check=True)
    warnings = {}
    cur = None
    for l in open("warnings.txt"):
        if l.startswith("case "):
            cur = int(l.split()[1])
            warnings[cur] = []
        elif l.strip():
            # As the 23-tracer file: one leading blank less, file names without directories.
            l = re.sub(r"\S*/(\w+\.F90)", r"\1", l.rstrip())
            warnings[cur].append(l[1:] if l.startswith(" ") else l)
    parsed, cur = {}, None
    for l in res.stdout.splitlines():
        w = l.split()
        if not w:
            continue
        if w[0] == "refill":
            refill = [float(x.replace("E", "e")) for x in w[1:]]
            continue
        if w[0] == "case":
            cur = int(w[1])
            parsed[cur] = {}
        elif w[0] == "aborted":
            parsed[cur]["aborted"] = w[1] == "T"
        elif w[0] == "first_ice":
            parsed[cur]["first_ice"] = [x == "1" for x in w[1:]]
        else:
            parsed[cur][w[0]] = [float(x.replace("E", "e")) for x in w[1:]]

    def num(x):
        return x if x == x and abs(x) != float("inf") else (
            "nan" if x != x else ("inf" if x > 0 else "-inf"))

    params = dict(params)
    params["ntrcr"] = ntrcr
    params["tracer_layout"] = [{"name": n, "index0": start[n], "levels": l} for n, l in fields]
    dep = {}
    for n, _ in fields:
        d, _, s = depend(n, start)
        dep[n] = d if d < 3 else ("2+nt_alvl" if n == "apnd" else "2+nt_apnd")
    params["tracer_depend"] = dep
    flags = dict(params["tracer_flags"])
    flags.update(tr_snow=True, tr_iso=True, tr_aero=True, n_aero=N_AERO, n_iso=N_ISO)
    if TOPO:
        # Icepack's refills where there is no snow (snwredist = 'ITD', snwgrain), and the
        # other groups of this variant.
        flags.update(tr_pond_lvl=False, tr_pond_topo=True, tr_brine=True, tr_fsd=True,
                     nfsd=NFSD, snwredist="ITD", snwgrain=True, rhos_empty=refill[0],
                     smice_empty=refill[1], rsnw_empty=refill[2])
    if NBTRCR:
        # The bio tracers and the tables Icepack was given for every tracer (1-based).
        params["bgc"] = {"kind": "z_tracers" if BGC == 2 else "skl_bgc", "nblyr": NBLYR,
                         "bio_index": bio_index, "sk_l": 0.03}
        params["host_tables"] = tables
    params["tracer_flags"] = flags
    params["generator"] = ("fortran-bridge/bench/icepack/reference/make-reference.sh from "
                           "tests/data/icepack/ridge_step_cases.jsonl")
    with open(dst, "w") as f:
        f.write(json.dumps(params) + "\n")
        for k, c in enumerate(cases, start=1):
            p = parsed[k]
            ncat = c["inputs"]["ncat"]
            o = {"aborted": p["aborted"], "warnings": "\n".join(warnings.get(k, []))}
            for key in ("hin_max", "aicen", "vicen", "vsnon", "dardg1ndt", "dardg2ndt",
                        "dvirdgndt", "aparticn", "krdgn", "aredistn", "vredistn", "araftn",
                        "vraftn", "faero_ocn", "fiso_ocn", "flux_bio"):
                o[key] = [num(x) for x in p[key]]
            for key in ("aice0", "aice", "opening", "dardg1dt", "dardg2dt", "dvirdgdt", "fresh",
                        "fsalt", "fhocn", "fpond", "dpnd_ridge", "strength"):
                o[key] = num(p[key][0])
            o["closing"] = num(p["closing"][0]) if c["inputs"]["closing_in"] is not None else None
            t = p["trcrn"]
            o["trcrn"] = {name: [[num(t[n * ntrcr + start[name] + k]) for k in range(lev)]
                                 for n in range(ncat)] for name, lev in fields}
            o["first_ice"] = p["first_ice"]
            c = dict(c)
            c["outputs"] = o
            f.write(json.dumps(c) + "\n")
    print(f"{len(cases)} cases, {ntrcr} tracers, into {dst}")


if __name__ == "__main__":
    main()
