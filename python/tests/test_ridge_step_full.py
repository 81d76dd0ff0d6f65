"""The complete ridging step in Python (snow, tracers, ocean fluxes): bit for bit the C ABI's
``pressridge_ridge_cell`` (the Rust ``ridge_step_column``) on every Icepack reference case of
``tests/data/icepack/ridge_step_cases.jsonl``, within the reference test's tolerance of Icepack
on the typical and hard ones, conserving on random columns, and the old area-volume call
unchanged."""

from __future__ import annotations

import ctypes
import json
import math
import os
import re
from pathlib import Path

import numpy as np
import pytest

import pressridge as pr

ROOT = Path(__file__).resolve().parents[2]
CASES = ROOT / "tests" / "data" / "icepack" / "ridge_step_cases.jsonl"
HEADER = ROOT / "include" / "pressridge.h"
# The C library the tests compare against: PRESSRIDGE_LIB (scripts/test-python.sh sets it
# to the build it made), else the release build.
LIB = Path(os.environ.get("PRESSRIDGE_LIB", ROOT / "target" / "release" / "libpressridge.so"))


def _num(x):
    return float(x)  # "nan", "inf" strings and numbers alike


def _read_cases():
    lines = [json.loads(l) for l in CASES.read_text().splitlines() if l.strip()]
    params, cases = lines[0], lines[1:]
    assert params["kind"] == "params"
    f = params["tracer_flags"]
    layout = pr.TracerLayout.cice(
        params["nilyr"],
        params["nslyr"],
        age=f["tr_iage"],
        first_year=f["tr_FY"],
        level_ice=f["tr_lvl"],
        ponds=f["tr_pond_lvl"],
    )
    assert layout.ntrcr == params["ntrcr"]
    for fl in params["tracer_layout"]:
        assert layout.field(fl["name"]) == (fl["index0"], fl["levels"])
    return params, layout, cases


PARAMS, LAYOUT, ALL_CASES = _read_cases()


def _tracers(d, ncat):
    """Tracers of a case as (ncat, ntrcr)."""
    t = np.full((ncat, LAYOUT.ntrcr), np.nan)
    for name, per_cat in d.items():
        start, levels = LAYOUT.field(name)
        for n, lv in enumerate(per_cat):
            t[n, start : start + levels] = [_num(x) for x in lv]
    assert not np.isnan(t).any()
    return t


class Case:
    def __init__(self, c):
        i = c["inputs"]
        self.name, self.group, self.out = c["case"], c["group"], c["outputs"]
        self.ncat = i["ncat"]
        self.hin_max = np.array([_num(x) for x in i["hin_max"]])
        self.aicen = np.array([_num(x) for x in i["aicen"]])
        self.vicen = np.array([_num(x) for x in i["vicen"]])
        self.vsnon = np.array([_num(x) for x in i["vsnon"]])
        self.trcrn = _tracers(i["trcrn"], self.ncat)
        self.aice0, self.aice = _num(i["aice0"]), _num(i["aice"])
        self.rates = i["closing_in"] is not None
        self.c1 = _num(i["closing_in"] if self.rates else i["rdg_conv"])
        self.c2 = _num(i["opening_in"] if self.rates else i["rdg_shear"])
        self.dt, self.ndtd, self.tf = _num(i["dt"]), i["ndtd"], _num(i["Tf"])
        self.partic, self.redist, self.mu_rdg = i["krdg_partic"], i["krdg_redist"], _num(i["mu_rdg"])
        self.cleanup, self.rebin = i["docleanup"], i["dorebin"]

    def kwargs(self):
        k = dict(
            participation="exponential" if self.partic == 1 else "thorndike",
            redistribution="exponential" if self.redist == 1 else "uniform",
            mu_rdg=self.mu_rdg,
            dt=self.dt,
            ndtd=self.ndtd,
            tf=self.tf,
            cleanup=self.cleanup,
            rebin=self.rebin,
            hin_max=self.hin_max,
            layout=LAYOUT,
        )
        if self.rates:
            k.update(closing=self.c1, opening=self.c2)
        else:
            k.update(convergence=self.c1, shear=self.c2)
        return k

    def python(self, reps=(1,), order="C"):
        """pr.ridge_step on the case repeated over a spatial shape `reps`."""
        def rep(x):
            x = np.asarray(x, dtype=float)
            y = np.broadcast_to(x.reshape(x.shape + (1,) * len(reps)), x.shape + tuple(reps))
            return np.array(y, order=order)
        t = rep(self.trcrn)
        return pr.ridge_step(
            rep(self.aicen),
            rep(self.vicen),
            rep(self.aice0),
            vsnon=rep(self.vsnon),
            trcrn=t,
            aice=rep(self.aice),
            **self.kwargs(),
        )


CASES = [Case(c) for c in ALL_CASES]


# ---------------------------------------------------------------------------------------
# The C ABI, through ctypes, with its structs read from the generated header


def _structs():
    """ctypes classes of the header's structs (fields of double, int32_t, int64_t, their
    fixed-size arrays and pointers), so that no layout is written twice."""
    text = HEADER.read_text()
    types = {"double": ctypes.c_double, "int32_t": ctypes.c_int32, "int64_t": ctypes.c_int64}
    out = {}
    for name, body in re.findall(r"typedef struct (\w+) \{(.*?)\} \1;", text, re.S):
        fields = []
        for line in body.splitlines():
            line = line.split("//")[0].strip()
            if not line:
                continue
            m = re.match(r"(?:const\s+)?(?:struct\s+)?(\w+)\s*(\*?)\s*(\w+)(?:\[(\d+)\])?;$",
                         line)
            assert m, f"cannot read the field `{line}` of {name} in {HEADER}"
            ty, ptr, fname, count = m.group(1), m.group(2), m.group(3), m.group(4)
            if ptr:
                fields.append((fname, ctypes.c_void_p))
            elif ty in types and count:
                fields.append((fname, types[ty] * int(count)))
            elif ty in types:
                fields.append((fname, types[ty]))
            elif ty in out:
                fields.append((fname, out[ty]))
            else:
                raise AssertionError(f"field type {ty} of {name} not handled")
        out[name] = type(name, (ctypes.Structure,), {"_fields_": fields})
    return out


@pytest.fixture(scope="module")
def clib():
    if not LIB.is_file():
        pytest.fail(f"{LIB} is not built: run scripts/test-python.sh (cargo build --release --lib), or set PRESSRIDGE_LIB")
    lib = ctypes.CDLL(str(LIB))
    return lib, _structs()


def _c_step(clib, case: Case):
    lib, S = clib
    dp = ctypes.POINTER(ctypes.c_double)
    opts = S["PressridgeOptions"]()
    assert lib.pressridge_options_default(ctypes.byref(opts)) == 0
    opts.participation = case.partic
    opts.redistribution = case.redist
    opts.params.mu_rdg = case.mu_rdg
    r = ctypes.c_void_p()
    flags = 1 | 2 | 4 | 8
    rc = lib.pressridge_ridger_new(
        ctypes.c_int64(case.ncat),
        ctypes.c_int64(LAYOUT.nilyr),
        ctypes.c_int64(LAYOUT.nslyr),
        ctypes.byref(S["PressridgeTracers"](flags=flags)),
        ctypes.byref(opts),
        None,
        ctypes.c_int32(int(case.cleanup)),
        ctypes.c_int32(int(case.rebin)),
        ctypes.byref(r),
    )
    assert rc == 0
    hin = np.array(case.hin_max)
    a, v, s = np.array(case.aicen), np.array(case.vicen), np.array(case.vsnon)
    t = np.array(case.trcrn, order="C")  # a copy, (ncat, ntrcr): Icepack's trcrn(ntrcr, ncat)
    a0 = ctypes.c_double(case.aice0)
    ai = ctypes.c_double(case.aice)
    closing = ctypes.c_double(case.c1)
    opening = ctypes.c_double(case.c2 if case.rates else 0.0)
    fl = S["PressridgeOceanFluxes"]()
    dg = S["PressridgeStepDiagnostics"]()
    names = [n for n, _ in S["PressridgeCategoryDiagnostics"]._fields_]
    cat_arrays = {n: np.zeros(case.ncat) for n in names if n != "first_ice"}
    first = np.zeros(case.ncat, dtype=np.int32)
    cd = S["PressridgeCategoryDiagnostics"](
        **{n: x.ctypes.data for n, x in cat_arrays.items()}, first_ice=first.ctypes.data
    )
    lib.pressridge_ridge_cell.argtypes = [
        ctypes.c_void_p, ctypes.c_double, ctypes.c_int32, dp, ctypes.c_double,
        ctypes.c_double, dp, dp, dp, dp, dp, dp, dp, dp, ctypes.c_double,
        ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p,
    ]
    p = lambda x: x.ctypes.data_as(dp)  # noqa: E731
    rc = lib.pressridge_ridge_cell(
        r, case.dt, case.ndtd, p(hin),
        0.0 if case.rates else case.c1, 0.0 if case.rates else case.c2,
        ctypes.pointer(closing) if case.rates else None, ctypes.pointer(opening),
        p(a), p(t), p(v), p(s), ctypes.pointer(a0), ctypes.pointer(ai), case.tf,
        ctypes.addressof(fl), ctypes.addressof(dg), ctypes.addressof(cd),
    )
    lib.pressridge_ridger_free(r)
    if rc != 0:
        return None
    cat_arrays["first_ice"] = first.astype(float)
    return dict(
        aicen=a, vicen=v, vsnon=s, trcrn=t, aice0=a0.value, aice=ai.value, hin_max=hin,
        fresh=fl.fresh, fsalt=fl.fsalt, fhocn=fl.fhocn, fpond=fl.fpond,
        dpnd_ridge=fl.dpnd_ridge, closing=dg.closing, opening=dg.opening,
        dardg1dt=dg.dardg1dt, dardg2dt=dg.dardg2dt, dvirdgdt=dg.dvirdgdt,
        ice_to_ocean=dg.ice_to_ocean, snow_to_ocean=dg.snow_to_ocean, niter=float(dg.niter),
        categories=cat_arrays,
    )


def _same_bits(what, ours, theirs):
    ours = np.asarray(ours, dtype=float)
    theirs = np.asarray(theirs, dtype=float)
    assert ours.shape == theirs.shape, what
    assert np.array_equal(ours.view(np.uint64), theirs.view(np.uint64)), (
        f"{what}: {ours} vs {theirs}"
    )


def _squeeze(r, reps):
    """The first column of a result over spatial shape `reps`."""
    idx = (0,) * len(reps)
    out = {}
    for k in ("aicen", "vicen", "vsnon"):
        out[k] = getattr(r, k)[(slice(None),) + idx]
    out["trcrn"] = r.trcrn[(slice(None), slice(None)) + idx]
    for k in ("aice0", "aice", "fresh", "fsalt", "fhocn", "fpond", "dpnd_ridge", "closing",
              "opening", "dardg1dt", "dardg2dt", "dvirdgdt", "ice_to_ocean",
              "snow_to_ocean", "niter"):
        out[k] = np.asarray(getattr(r, k))[idx]
    out["hin_max"] = r.hin_max
    out["categories"] = {k: v[(slice(None),) + idx] for k, v in r.categories.items()}
    return out


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_icepack_reference_python_equals_c_bit_for_bit(clib, case):
    want = _c_step(clib, case)
    if want is None:
        # The library refuses this column (an Icepack abort or negative answer): so must
        # Python, with a ValueError that says why.
        with pytest.raises(ValueError, match="."):
            case.python()
        return
    for reps, order in (((1,), "C"), ((2, 3), "C"), ((2, 3), "F")):
        got = _squeeze(case.python(reps, order), reps)
        for k, w in want.items():
            if k == "categories":
                for n, x in w.items():
                    _same_bits(f"{case.name}: {n}", got[k][n], x)
            else:
                _same_bits(f"{case.name}: {k}", got[k], w)


def _close(ours, theirs):
    ours, theirs = float(ours), float(theirs)
    if ours == theirs:
        return True
    d = abs(ours - theirs)
    return d <= 1e-14 or d <= 1e-12 * max(abs(ours), abs(theirs))


@pytest.mark.parametrize(
    "case", [c for c in CASES if c.group in ("typical", "hard")], ids=lambda c: c.name
)
def test_icepack_reference_python_equals_icepack(case):
    o = case.out
    if o["aborted"]:
        with pytest.raises(ValueError):
            case.python()
        return
    r = _squeeze(case.python(), (1,))
    for k in ("aicen", "vicen", "vsnon"):
        want = [_num(x) for x in o[k]]
        assert all(_close(a, b) for a, b in zip(r[k], want)), (k, r[k], want)
    for k in ("fresh", "fsalt", "fhocn", "fpond", "dpnd_ridge", "opening", "dardg1dt",
              "dardg2dt", "dvirdgdt", "aice"):
        assert _close(r[k], _num(o[k])), (k, r[k], o[k])
    assert all(_close(a, _num(b)) for a, b in zip(r["hin_max"], o["hin_max"]))
    for k in ("dardg1ndt", "krdgn", "aparticn", "vredistn"):
        assert all(_close(a, _num(b)) for a, b in zip(r["categories"][k], o[k])), k
    # Tracers where their base exceeds puny (Tsfc, qice, qsno, sice: no strata).
    want = _tracers(o["trcrn"], case.ncat)
    puny = PARAMS["puny"]
    ea = [_num(x) for x in o["aicen"]]
    ev = [_num(x) for x in o["vicen"]]
    es = [_num(x) for x in o["vsnon"]]
    for name, base in (("Tsfc", ea), ("qice", ev), ("sice", ev), ("qsno", es)):
        start, levels = LAYOUT.field(name)
        for n in range(case.ncat):
            if base[n] > puny:
                for k in range(start, start + levels):
                    assert _close(r["trcrn"][n, k], want[n, k]), (name, n, k)


def test_snow_isotope_and_aerosol_tracers_equal_icepack_bit_for_bit():
    """The 41-tracer reference (tests/data/icepack/ridge_step_tracers.jsonl): the fluxes
    faero_ocn and fiso_ocn, and the added tracers where their base exceeds puny."""
    lines = [json.loads(l) for l in (ROOT / "tests/data/icepack/ridge_step_tracers.jsonl").open()]
    params, cases = lines[0], lines[1:]
    f = params["tracer_flags"]
    layout = pr.TracerLayout.cice(params["nilyr"], params["nslyr"], age=True, first_year=True,
                                  level_ice=True, ponds=True, snow=f["tr_snow"],
                                  isotopes=f["n_iso"], aerosols=f["n_aero"])
    assert layout.ntrcr == params["ntrcr"] == 41
    checked = 0
    for c in cases:
        o = c["outputs"]
        if c["group"] == "stress" or o["aborted"]:
            continue
        i23 = dict(c["inputs"], trcrn={f["name"]: c["inputs"]["trcrn"][f["name"]]
                                       for f in LAYOUT.spec()})
        case = Case(dict(c, inputs=i23))
        case.trcrn = np.zeros((case.ncat, layout.ntrcr))
        for name, per_cat in c["inputs"]["trcrn"].items():
            start, levels = layout.field(name)
            case.trcrn[:, start : start + levels] = per_cat
        k = case.kwargs()
        k["layout"] = layout
        r = pr.ridge_step(case.aicen, case.vicen, case.aice0, vsnon=case.vsnon,
                          trcrn=case.trcrn, aice=case.aice, **k)
        assert r.faero_ocn.shape == (2,) and r.fiso_ocn.shape == (3,)
        assert list(r.faero_ocn) == [_num(x) for x in o["faero_ocn"]], c["case"]
        assert list(r.fiso_ocn) == [_num(x) for x in o["fiso_ocn"]], c["case"]
        for name, per_cat in o["trcrn"].items():
            if not name.startswith(("aero", "iso", "sm", "rhos", "rsnw")):
                continue
            start, levels = layout.field(name)
            base = o["vicen"] if name.startswith(("aeroice", "isoice")) else o["vsnon"]
            for n in range(case.ncat):
                if _num(base[n]) > params["puny"]:
                    got = r.trcrn[n, start : start + levels]
                    assert list(got) == [_num(x) for x in per_cat[n]], (c["case"], name, n)
                    checked += levels
    assert checked > 100
    assert set(pr.STEP_SPECIES_OUTPUTS) == {"faero_ocn", "fiso_ocn", "flux_bio"}


# ---------------------------------------------------------------------------------------
# Conservation on random columns


def _random_columns(rng, ncat, ncol, layout):
    hin = pr.category_bounds(ncat)
    a = rng.dirichlet(np.ones(ncat + 1), size=ncol).T  # (ncat + 1, ncol), sums to 1
    aice0, aicen = a[0] * rng.uniform(0.0, 1.0, ncol), a[1:]
    tiny = rng.uniform(size=aicen.shape) < 0.1
    aicen = np.where(tiny, 10.0 ** rng.uniform(-13, -9, aicen.shape), aicen)
    mid = 0.5 * (hin[:-1] + np.minimum(hin[1:], hin[:-1] + 3.0))
    h = mid[:, None] * rng.uniform(0.6, 1.4, aicen.shape)
    vicen = aicen * h
    vsnon = aicen * rng.uniform(0.0, 0.4, aicen.shape)
    nt = layout.ntrcr
    t = np.zeros((ncat, nt, ncol))
    for it, (units, name) in enumerate(zip(layout.units, layout.names)):
        if name == "Tsfcn":
            t[:, it] = rng.uniform(-30, -1.8, (ncat, ncol))
        elif name.startswith("qice"):
            t[:, it] = rng.uniform(-3.3e8, -2.5e8, (ncat, ncol))
        elif name.startswith("qsno"):
            t[:, it] = rng.uniform(-1.3e8, -1.1e8, (ncat, ncol))
        elif name.startswith("sice"):
            t[:, it] = rng.uniform(1, 8, (ncat, ncol))
        elif name == "iage":
            t[:, it] = rng.uniform(0, 3e7, (ncat, ncol))
        elif name == "hpnd" or name == "ipnd":
            t[:, it] = rng.uniform(0, 0.3, (ncat, ncol))
        else:
            t[:, it] = rng.uniform(0, 1, (ncat, ncol))
    return hin, aicen, vicen, vsnon, t, aice0


def test_conserves_on_random_columns():
    rng = np.random.default_rng(15)
    layout = pr.TracerLayout.cice(4, 2, age=True, first_year=True, level_ice=True, ponds=True)
    ncat, ncol = 5, 4000
    hin, aicen, vicen, vsnon, t, aice0 = _random_columns(rng, ncat, ncol, layout)
    conv = 10.0 ** rng.uniform(-9, -3, ncol)
    shear = 10.0 ** rng.uniform(-9, -4, ncol)
    dt = 3600.0
    r = pr.ridge_step(
        aicen, vicen, aice0, vsnon=vsnon, trcrn=t, layout=layout, dt=dt,
        convergence=conv, shear=shear, hin_max=hin,
    )
    for x in (r.aicen, r.vicen, r.vsnon):
        assert np.isfinite(x).all() and (x >= 0).all()
    assert np.isfinite(r.trcrn).all()
    # Area: the cell is full after ridging.
    np.testing.assert_allclose(r.aice0 + r.aicen.sum(0), 1.0, rtol=0, atol=1e-12)
    p = pr.DEFAULT_PARAMETERS
    rhoi, rhos = p["rhoi"], 330.0
    rel = lambda a, b: np.abs(a - b) / np.maximum(np.abs(b), 1e-300)  # noqa: E731
    # Ice volume: kept or put into the ocean.
    assert (rel(r.vicen.sum(0) + r.ice_to_ocean, vicen.sum(0)) < 1e-12).all()
    # Snow volume, and its water in the fresh-water flux.
    assert (rel(r.vsnon.sum(0) + r.snow_to_ocean, vsnon.sum(0)) < 1e-12).all()
    water_out = (rhoi * r.ice_to_ocean + rhos * r.snow_to_ocean) / dt
    np.testing.assert_allclose(r.fresh, water_out, rtol=1e-12, atol=1e-25)
    # Enthalpy: ice and snow enthalpy kept or given to the ocean (fhocn * dt).
    def enthalpy(vi, vs, tr):
        qs, ls = layout.field("qice")
        ss, lss = layout.field("qsno")
        return (vi * tr[:, qs : qs + ls].mean(1)).sum(0) + (vs * tr[:, ss : ss + lss].mean(1)).sum(0)
    e0 = enthalpy(vicen, vsnon, t)
    e1 = enthalpy(r.vicen, r.vsnon, r.trcrn) + r.fhocn * dt
    assert (rel(e1, e0) < 1e-12).all()
    # Salt: the amount kept; the clean-up's flux uses Icepack's constant reference salinity.
    si, li = layout.field("sice")
    assert (r.fsalt >= 0).all()
    s1 = (r.vicen * r.trcrn[:, si : si + li].mean(1)).sum(0)
    s0 = (vicen * t[:, si : si + li].mean(1)).sum(0)
    zapless = r.ice_to_ocean == 0
    assert (rel(s1[zapless], s0[zapless]) < 1e-12).all()


# ---------------------------------------------------------------------------------------
# Conventions, compatibility, errors


def test_area_volume_call_is_unchanged_and_complete_step_without_tracers_conserves():
    rng = np.random.default_rng(3)
    aicen = rng.uniform(0.05, 0.2, (5, 30))
    vicen = aicen * pr.category_bounds(5)[1:, None].clip(max=6) * 0.8
    old = pr.ridge_step(aicen, vicen, dt=3600.0, convergence=1e-6, shear=5e-7)
    # The area-volume call: the eight fields of earlier versions, the rest None.
    assert old[8:] == (None,) * (len(old) - 8)
    # The complete step with the host's rates and no snow or tracers.
    new = pr.ridge_step(aicen, vicen, dt=3600.0, closing=2e-6, opening=0.0)
    assert new.trcrn is None and (new.vsnon == 0).all()
    np.testing.assert_allclose(new.vicen.sum(0) + new.ice_to_ocean, vicen.sum(0), rtol=1e-12)
    assert (new.aicen >= 0).all() and (new.dardg1dt > 0).all()


def test_both_conventions_and_optional_cleanup():
    rng = np.random.default_rng(4)
    layout = pr.TracerLayout.cice(2, 1)
    hin, aicen, vicen, vsnon, t, aice0 = _random_columns(rng, 3, 20, layout)
    common = dict(vsnon=vsnon, trcrn=t, layout=layout, dt=1800.0, hin_max=hin)
    a = pr.ridge_step(aicen, vicen, aice0, convergence=1e-6, shear=1e-6, **common)
    # The host's rates: closing/opening as CICE derived them (its closing; the opening that
    # keeps the cell full) give a valid step too, and without the clean-up nothing is zapped.
    b = pr.ridge_step(aicen, vicen, aice0, closing=a.closing, opening=0.0, cleanup=False, **common)
    assert (b.ice_to_ocean == 0).all()
    assert (b.categories["first_ice"] == 0).all()
    assert b.hin_max[-1] == hin[-1] and a.hin_max[-1] == pr.DEFAULT_PARAMETERS["big"]
    np.testing.assert_allclose(b.vicen.sum(0), vicen.sum(0), rtol=1e-12)


def test_layout_object():
    l = pr.TracerLayout.cice(7, 1, age=True, first_year=True, level_ice=True, ponds=True)
    assert l.ntrcr == 23 and l.nilyr == 7 and l.nslyr == 1
    assert l.names[:3] == ["Tsfcn", "qice001", "qice002"] and l.names[-1] == "ipnd"
    assert l.field("hpnd") == (21, 1)
    assert l.units[0] == "degC" and l.units[1] == "J m-3"
    assert l.flags == dict(age=True, first_year=True, level_ice=True, ponds=True, snow=False,
                           isotopes=0, aerosols=0, pond_topo=False, pond_sealvl=False, fsd=0,
                           brine=False)
    import pickle

    assert pickle.loads(pickle.dumps(l)) == l
    assert l != pr.TracerLayout.cice(7, 1)
    with pytest.raises(ValueError, match="level_ice"):
        pr.TracerLayout.cice(2, 1, ponds=True)
    with pytest.raises(ValueError, match="nilyr"):
        pr.TracerLayout.cice(0, 1)
    # Snow, isotope and aerosol tracers in Icepack's driver order (41 with the 23 above).
    x = pr.TracerLayout.cice(7, 1, age=True, first_year=True, level_ice=True, ponds=True,
                             snow=True, isotopes=3, aerosols=2)
    assert x.ntrcr == 41 and x.field("smice") == (23, 1) and x.field("isoice") == (30, 3)
    assert x.names[27:30] == ["isosno001", "isosno002", "isosno003"]
    assert x.names[-4:] == ["aerosnossl002", "aerosnoint002", "aeroicessl002", "aeroiceint002"]
    assert x.flags["aerosols"] == 2 and x.flags["isotopes"] == 3 and x.flags["snow"]
    assert "snow=True, isotopes=3, aerosols=2" in repr(x)
    assert x.units[-1] == "kg m-3"
    with pytest.raises(ValueError, match="aerosols = 7"):
        pr.TracerLayout.cice(7, 1, aerosols=7)
    # Topography ponds, floe size, brine and the snow refills (37 tracers, Icepack's order).
    t = pr.TracerLayout.cice(7, 1, age=True, first_year=True, level_ice=True, pond_topo=True,
                             snow=True, fsd=3, isotopes=1, aerosols=1, brine=True)
    assert t.ntrcr == 37 and t.names[-1] == "fbri" and t.field("fsd") == (27, 3)
    assert t.flags["pond_topo"] and t.flags["brine"] and t.flags["fsd"] == 3
    assert "pond_topo=True, fsd=3, brine=True" in repr(t)
    r = t.with_empty_value("rhos", 100.0)
    assert r != t and r.ntrcr == 37
    with pytest.raises(ValueError, match="empty value"):
        t.with_empty_value("fsd", 1.0)
    with pytest.raises(ValueError, match="one pond scheme"):
        pr.TracerLayout.cice(7, 1, level_ice=True, ponds=True, pond_topo=True)
    with pytest.raises(ValueError, match="no tracer field `x`"):
        l.field("x")
    assert set(pr.STEP_CELL_OUTPUTS) <= set(pr.RidgeStepResult._fields)
    assert pr.STEP_CELL_OUTPUTS["fhocn"][0] == "W m-2"


def test_errors_name_the_parameter_and_column():
    layout = pr.TracerLayout.cice(1, 1)
    a = np.full((2, 3), 0.4)
    v = a * 1.0
    t = np.zeros((2, layout.ntrcr, 3))
    t[:, layout.field("qice")[0]] = -3e8
    t[:, layout.field("qsno")[0]] = -1.1e8
    ok = dict(trcrn=t, layout=layout, dt=3600.0, convergence=1e-6)
    pr.ridge_step(a, v, vsnon=0.01 * a, **ok)
    with pytest.raises(ValueError, match="vsnon needs trcrn"):
        pr.ridge_step(a, v, vsnon=0.0, dt=3600.0, convergence=1e-6)
    with pytest.raises(ValueError, match="trcrn needs layout"):
        pr.ridge_step(a, v, trcrn=t, dt=3600.0, convergence=1e-6)
    with pytest.raises(ValueError, match="trcrn has shape"):
        pr.ridge_step(a, v, **{**ok, "trcrn": t[:, :2]})
    with pytest.raises(ValueError, match="closing needs opening"):
        pr.ridge_step(a, v, trcrn=t, layout=layout, dt=3600.0, closing=1e-6)
    with pytest.raises(ValueError, match="not both"):
        pr.ridge_step(a, v, **ok, closing=1e-6, opening=0.0)
    with pytest.raises(ValueError, match="ndtd"):
        pr.ridge_step(a, v, **ok, ndtd=0)
    with pytest.raises(ValueError, match="belong"):
        pr.ridge_step(a, v, dt=3600.0, convergence=1e-6, ndtd=2)
    bad = v.copy()
    bad[1, 2] = -1.0
    with pytest.raises(ValueError, match=r"spatial index \(2,\).*vicen"):
        pr.ridge_step(a, bad, **ok)
    tb = t.copy()
    tb[0, 0, 1] = np.nan
    with pytest.raises(ValueError, match=r"spatial index \(1,\)"):
        pr.ridge_step(a, v, **{**ok, "trcrn": tb})
    # A masked column is left alone, its outputs missing.
    valid = np.array([True, False, True])
    r = pr.ridge_step(a, bad, **ok, valid=np.array([True, True, False]))
    assert math.isnan(r.fresh[2]) and r.vicen[1, 2] == -1.0
    r = pr.ridge_step(a, v, **ok, valid=valid)
    assert math.isnan(r.aice0[1]) and not math.isnan(r.aice0[0])


def test_releases_the_gil():
    from conftest import MIN_TICKS, ticks_during

    rng = np.random.default_rng(5)
    layout = pr.TracerLayout.cice(7, 1, age=True, first_year=True, level_ice=True, ponds=True)
    hin, aicen, vicen, vsnon, t, aice0 = _random_columns(rng, 5, 60000, layout)
    _, ticks = ticks_during(
        lambda: pr.ridge_step(aicen, vicen, aice0, vsnon=vsnon, trcrn=t, layout=layout,
                              dt=3600.0, convergence=1e-6, hin_max=hin)
    )
    assert ticks >= MIN_TICKS


# ---------------------------------------------------------------------------------------
# xarray


def _dataset(ntime=2, ncat=4, nj=3, ni=5, seed=7, layout=None):
    import xarray as xr

    rng = np.random.default_rng(seed)
    if layout is None:
        layout = pr.TracerLayout.cice(3, 1, age=True, level_ice=True, ponds=True)
    ncol = ntime * nj * ni
    hin, aicen, vicen, vsnon, t, aice0 = _random_columns(rng, ncat, ncol, layout)
    shape = (ncat, ntime, nj, ni)
    # (time, nc, nj, ni): time first, as in CICE history files.
    to_ds = lambda x: np.moveaxis(x.reshape(shape), 1, 0)  # noqa: E731
    dims = ("time", "nc", "nj", "ni")
    ds = xr.Dataset(
        {
            "aicen": (dims, to_ds(aicen)),
            "vicen": (dims, to_ds(vicen)),
            "vsnon": (dims, to_ds(vsnon)),
            "aice0": (("time", "nj", "ni"), aice0.reshape(ntime, nj, ni)),
            "hin_max": (("nc_bounds",), hin),
        },
        coords={"time": [0.0, 3600.0][:ntime]},
    )
    for it, name in enumerate(layout.names):
        ds[name] = (dims, to_ds(t[:, it]))
    return ds, layout


def test_xarray_complete_step_with_time_before_categories():
    import pressridge.xr as prx

    ds, layout = _dataset()
    r = prx.ridge_step(ds, dt=1800.0, convergence=2e-6, shear=1e-6, layout=layout)
    assert r.aicen.dims == ("time", "nc", "nj", "ni")
    assert r.fhocn.dims == ("time", "nj", "ni") and r.fhocn.attrs["units"] == "W m-2"
    assert r.krdgn.dims == ("time", "nc", "nj", "ni")
    assert r.qice001.attrs["units"] == "J m-3"
    for k in range(ds.sizes["time"]):
        d = ds.isel(time=k)
        t = np.stack([d[n].values for n in layout.names], axis=1)
        n = pr.ridge_step(
            d.aicen.values, d.vicen.values, d.aice0.values, vsnon=d.vsnon.values, trcrn=t,
            layout=layout, dt=1800.0, convergence=2e-6, shear=1e-6, hin_max=d.hin_max.values,
        )
        rk = r.isel(time=k)
        np.testing.assert_array_equal(rk.aicen.values, n.aicen)
        np.testing.assert_array_equal(rk.vsnon.values, n.vsnon)
        np.testing.assert_array_equal(rk.qsno001.values, n.trcrn[:, layout.field("qsno")[0]])
        np.testing.assert_array_equal(rk.fresh.values, n.fresh)
        np.testing.assert_array_equal(rk.dardg1ndt.values, n.categories["dardg1ndt"])
    # dask: lazy, chunk by chunk, the same numbers.
    lazy = prx.ridge_step(ds.chunk({"time": 1, "nj": 2}), dt=1800.0, convergence=2e-6,
                          shear=1e-6, layout=layout)
    assert lazy.fhocn.chunks is not None
    np.testing.assert_array_equal(lazy.fhocn.values, r.fhocn.values)
    np.testing.assert_array_equal(lazy.ipnd.values, r.ipnd.values)
    # The host's rates (SIS2), no clean-up.
    s = prx.ridge_step(ds, dt=1800.0, closing=1e-6, opening=0.0, cleanup=False, layout=layout)
    assert float(s.hin_max[-1]) == float(ds.hin_max[-1])
    # Without a category dimension named nc/ncat and time first: refused, not guessed.
    bad = ds.rename({"nc": "cat"})
    with pytest.raises(ValueError, match="category_dim"):
        prx.ridge_step(bad, dt=1800.0, convergence=1e-6, layout=layout)
    ok = prx.ridge_step(bad, dt=1800.0, convergence=2e-6, shear=1e-6, layout=layout,
                        category_dim="cat")
    np.testing.assert_array_equal(ok.fresh.values, r.fresh.values)
    # Without layout=, the layout is told from the dataset's variables.
    auto = prx.ridge_step(ds, dt=1800.0, convergence=2e-6, shear=1e-6)
    np.testing.assert_array_equal(auto.fresh.values, r.fresh.values)
    np.testing.assert_array_equal(auto.ipnd.values, r.ipnd.values)
    with pytest.raises(ValueError, match="qice002"):
        prx.ridge_step(ds.drop_vars("qice002"), dt=1800.0, convergence=1e-6, layout=layout)


def test_bio_tracers_and_flux_bio_equal_icepack_bit_for_bit():
    """The vertically resolved bio tracers (tests/data/icepack/ridge_step_tracers_bgc.jsonl):
    a layout made with TracerLayout.with_bgc and Icepack's own tables (with_host_tables)
    gives Icepack's flux_bio and bio tracers bit for bit."""
    lines = [json.loads(l) for l in (ROOT / "tests/data/icepack/ridge_step_tracers_bgc.jsonl").open()]
    params, cases = lines[0], lines[1:]
    f, b, t = params["tracer_flags"], params["bgc"], params["host_tables"]
    layout = pr.TracerLayout.cice(params["nilyr"], params["nslyr"], age=True, first_year=True,
                                  level_ice=True, snow=True, isotopes=f["n_iso"],
                                  aerosols=f["n_aero"], pond_topo=True, fsd=f["nfsd"],
                                  brine=True)
    extra = params["ntrcr"] - layout.ntrcr
    layout = layout.with_bgc(extra, "z_tracers", [i - 1 for i in b["bio_index"]],
                             nblyr=b["nblyr"])
    for name, key in (("rhos", "rhos_empty"), ("smice", "smice_empty"), ("rsnw", "rsnw_empty")):
        layout = layout.with_empty_value(name, f[key])
    layout = layout.with_host_tables(t["trcr_depend"], t["trcr_base"], t["n_trcr_strata"],
                                     t["nt_strata"])
    assert layout.ntrcr == 47 and layout.nbtrcr == 2
    start, levels = layout.field("bgc")
    nonzero = 0
    for c in cases:
        o = c["outputs"]
        if c["group"] == "stress" or o["aborted"]:
            continue
        i = c["inputs"]
        # Case reads the 23-tracer fields; the whole layout's tracers are set below.
        i23 = dict(i, trcrn={f["name"]: i["trcrn"][f["name"]] for f in LAYOUT.spec()})
        case = Case(dict(c, inputs=i23))
        trcrn = np.zeros((case.ncat, layout.ntrcr))
        for name, per_cat in i["trcrn"].items():
            s, n = layout.field(name)
            trcrn[:, s : s + n] = per_cat
        k = case.kwargs()
        k["layout"] = layout
        r = pr.ridge_step(case.aicen, case.vicen, case.aice0, vsnon=case.vsnon, trcrn=trcrn,
                          aice=case.aice, **k)
        assert r.flux_bio.shape == (2,)
        assert list(r.flux_bio) == [_num(x) for x in o["flux_bio"]], c["case"]
        nonzero += any(x != 0 for x in r.flux_bio)
        assert r.trcrn[:, start : start + levels].tolist() == [
            [_num(x) for x in per_cat] for per_cat in o["trcrn"]["bgc"]], c["case"]
    assert nonzero >= 5
