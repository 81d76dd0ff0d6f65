//! Biogeochemical tracers through the C ABI: Icepack's reference cases with vertically
//! resolved (`z_tracers`) and skeletal (`skl_bgc`) bio tracers, set up with
//! `PressridgeTracers::bgc_*` and Icepack's tracer tables, stepped by
//! `pressridge_ridge_cell` and `pressridge_ridge_cells`: the same bits as the Rust step
//! (which `tests/itd_icepack_reference.rs` holds to Icepack's), `flux_bio` equal to
//! Icepack's, and bad set-ups refused by name.

#[path = "../../../tests/common/mod.rs"]
mod common;

use std::ptr::{null, null_mut};

use common::column::{Column, step};
use common::icepack::{self, num, nums};
use pressridge::itd::{
    StepForcing,
    details::{Closing, TracerLayout},
};
use pressridge_capi::itd::PressridgeOptions;
use pressridge_capi::ridge_step::*;
use pressridge_capi::*;
use serde_json::Value;

/// The C set-up of a reference file's parameters (Icepack's flags, bio tracers and tables)
/// and a case's options; the other fields hold the arrays its pointers point into.
struct Setup {
    tracers: PressridgeTracers,
    _ints: [Vec<i32>; 4],
    _base: Vec<f64>,
}

fn setup(params: &Value) -> Setup {
    let f = &params["tracer_flags"];
    let flag = |k: &str| f[k].as_bool().unwrap_or(false);
    let count = |on: &str, n: &str| {
        if flag(on) {
            f[n].as_i64().unwrap() as i32
        } else {
            0
        }
    };
    let mut flags = 0;
    for (k, bit) in [
        ("tr_iage", PRESSRIDGE_TRACER_AGE),
        ("tr_FY", PRESSRIDGE_TRACER_FIRST_YEAR),
        ("tr_lvl", PRESSRIDGE_TRACER_LEVEL_ICE),
        ("tr_pond_lvl", PRESSRIDGE_TRACER_PONDS),
        ("tr_snow", PRESSRIDGE_TRACER_SNOW),
        ("tr_pond_topo", PRESSRIDGE_TRACER_POND_TOPO),
        ("tr_pond_sealvl", PRESSRIDGE_TRACER_POND_SEALVL),
        ("tr_brine", PRESSRIDGE_TRACER_BRINE),
    ] {
        if flag(k) {
            flags |= bit;
        }
    }
    let t = &params["host_tables"];
    let ints = |v: &Value| -> Vec<i32> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_i64().unwrap() as i32)
            .collect()
    };
    // trcr_base(ntrcr, 3) and nt_strata(ntrcr, 2) in Fortran order.
    let column = |k: &str, j: usize| -> Vec<Value> {
        t[k].as_array()
            .unwrap()
            .iter()
            .map(|r| r[j].clone())
            .collect()
    };
    let dep = ints(&t["trcr_depend"]);
    let base: Vec<f64> = (0..3)
        .flat_map(|j| column("trcr_base", j))
        .map(|x| num(&x))
        .collect();
    let nst = ints(&t["n_trcr_strata"]);
    let st: Vec<i32> = (0..2)
        .flat_map(|j| column("nt_strata", j))
        .map(|x| x.as_i64().unwrap() as i32)
        .collect();
    let bgc = &params["bgc"];
    let bio = ints(&bgc["bio_index"]);
    let (kind, nblyr, sk_l) = match bgc["kind"].as_str().unwrap() {
        "z_tracers" => (
            PRESSRIDGE_BGC_VERTICAL,
            bgc["nblyr"].as_i64().unwrap() as i32,
            0.0,
        ),
        "skl_bgc" => (PRESSRIDGE_BGC_SKELETAL, 0, num(&bgc["sk_l"])),
        k => panic!("bgc kind {k}"),
    };
    let ntrcr = params["ntrcr"].as_i64().unwrap();
    // The tracers before the bio ones: the layout of the flags alone.
    let cice = icepack::layout(&Value::Object(
        params
            .as_object()
            .unwrap()
            .iter()
            .filter(|(k, _)| *k != "bgc" && *k != "host_tables")
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect(),
    ))
    .ntrcr();
    let tracers = PressridgeTracers {
        flags,
        n_iso: count("tr_iso", "n_iso"),
        n_aero: count("tr_aero", "n_aero"),
        nfsd: count("tr_fsd", "nfsd"),
        rhos_empty: f["rhos_empty"].as_f64().unwrap_or(0.0),
        smice_empty: f["smice_empty"].as_f64().unwrap_or(0.0),
        rsnw_empty: f["rsnw_empty"].as_f64().unwrap_or(0.0),
        host_trcr_depend: dep.as_ptr(),
        host_trcr_base: base.as_ptr(),
        host_n_trcr_strata: nst.as_ptr(),
        host_nt_strata: st.as_ptr(),
        host_ntrcr: ntrcr,
        bgc_kind: kind,
        bgc_ntrcr: (ntrcr as usize - cice) as i32,
        nblyr,
        sk_l,
        nbtrcr: bio.len() as i32,
        bio_index: bio.as_ptr(),
    };
    Setup {
        tracers,
        _ints: [dep, nst, st, bio],
        _base: base,
    }
}

/// A ridger of `tracers` with a case's options, or the status of the refusal.
fn ridger(tracers: &PressridgeTracers, i: &Value) -> Result<*mut PressridgeRidger, i32> {
    let mut o = PressridgeOptions {
        participation: i["krdg_partic"].as_i64().unwrap() as i32,
        redistribution: i["krdg_redist"].as_i64().unwrap() as i32,
        ..Default::default()
    };
    o.params.mu_rdg = num(&i["mu_rdg"]);
    let flag = |k: &str| i32::from(i[k].as_bool().unwrap_or(true));
    let mut r = null_mut();
    // SAFETY: `tracers`' pointers hold the lengths it states (Setup keeps them); the other
    // pointers are live locals or null where allowed.
    let rc = unsafe {
        pressridge_ridger_new(
            i["ncat"].as_i64().unwrap(),
            i["nilyr"].as_i64().unwrap(),
            i["nslyr"].as_i64().unwrap(),
            tracers,
            &o,
            null(),
            flag("docleanup"),
            flag("dorebin"),
            &mut r,
        )
    };
    if rc == PRESSRIDGE_OK { Ok(r) } else { Err(rc) }
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|v| v.to_bits()).collect()
}

/// Every case of `file` through the C ABI, one cell a call and all cells in one call, against
/// the Rust step and Icepack's `flux_bio`; the number of cases stepped.
fn every_case(file: &str) -> usize {
    let (params, cases) = icepack::read_file(file);
    let s = setup(&params);
    let layout: TracerLayout = icepack::layout(&params);
    let nt = layout.ntrcr();
    let nb = s.tracers.nbtrcr as usize;
    let mut stepped = 0;
    for c in &cases {
        let (i, out) = (&c["inputs"], &c["outputs"]);
        let name = c["case"].as_str().unwrap();
        let ncat = i["ncat"].as_u64().unwrap() as usize;
        let r = ridger(&s.tracers, i).unwrap_or_else(|rc| panic!("{name}: ridger_new {rc}"));
        let closing = if i["closing_in"].is_null() {
            None
        } else {
            Some((num(&i["closing_in"]), num(&i["opening_in"])))
        };
        let (conv, shear) = (num(&i["rdg_conv"]), num(&i["rdg_shear"]));
        let forcing = StepForcing {
            closing: match closing {
                Some((closing, opening)) => Closing::Rates { closing, opening },
                None => Closing::Deformation {
                    convergence: conv,
                    shear,
                },
            },
            dt: num(&i["dt"]),
            ndtd: i["ndtd"].as_u64().unwrap() as u32,
            tf: num(&i["Tf"]),
        };
        let trcrn = icepack::tracers(&i["trcrn"], &layout, ncat);
        let mut col = Column::new(
            nums(&i["aicen"]),
            nums(&i["vicen"]),
            nums(&i["vsnon"]),
            trcrn.clone(),
            num(&i["aice0"]),
        );
        col.aice = num(&i["aice"]);
        let hin = nums(&i["hin_max"]);
        let want = step(&col, &hin, forcing, &icepack::options(i), &layout);

        // A fresh copy of the case's column: aicen, vicen, vsnon, trcrn, aice0, aice.
        let fresh = || {
            (
                nums(&i["aicen"]),
                nums(&i["vicen"]),
                nums(&i["vsnon"]),
                trcrn.clone(),
                num(&i["aice0"]),
                num(&i["aice"]),
            )
        };
        // One cell.
        let (mut a, mut v, mut sn, mut t, mut a0, mut ai) = fresh();
        let mut h = hin.clone();
        let mut opening = closing.map_or(0.0, |c| c.1);
        let cl = closing.map(|c| c.0);
        let mut fl = PressridgeOceanFluxes::default();
        // SAFETY: every pointer is a live local or buffer of the ridger's sizes.
        let rc = unsafe {
            pressridge_ridge_cell(
                r,
                forcing.dt,
                forcing.ndtd as i32,
                h.as_mut_ptr(),
                conv,
                shear,
                cl.as_ref().map_or(null(), |c| c as *const f64),
                &mut opening,
                a.as_mut_ptr(),
                t.as_mut_ptr(),
                v.as_mut_ptr(),
                sn.as_mut_ptr(),
                &mut a0,
                &mut ai,
                forcing.tf,
                &mut fl,
                null_mut(),
                null(),
            )
        };
        match &want.result {
            Err(e) => {
                assert_ne!(rc, PRESSRIDGE_OK, "{name}: Rust refused ({e}), C accepted");
                // SAFETY: a handle from its *_new, freed once.
                unsafe { pressridge_ridger_free(r) };
                continue;
            }
            Ok(_) => assert_eq!(rc, PRESSRIDGE_OK, "{name}"),
        }
        let w = &want.col;
        assert_eq!(bits(&a), bits(&w.aicen), "{name}: aicen");
        assert_eq!(bits(&v), bits(&w.vicen), "{name}: vicen");
        assert_eq!(bits(&sn), bits(&w.vsnon), "{name}: vsnon");
        assert_eq!(bits(&t), bits(&w.trcrn), "{name}: trcrn");
        assert_eq!(a0.to_bits(), w.aice0.to_bits(), "{name}: aice0");
        let wf = &want.fluxes;
        assert_eq!(
            bits(&[fl.fresh, fl.fsalt, fl.fhocn, fl.fpond]),
            bits(&[wf.fresh, wf.fsalt, wf.fhocn, wf.fpond]),
            "{name}: fluxes"
        );
        assert_eq!(bits(&fl.flux_bio), bits(&wf.flux_bio), "{name}: flux_bio");
        // Icepack's own flux_bio, bit for bit (Icepack aborted nowhere the step succeeded).
        if !out["aborted"].as_bool().unwrap_or(false) {
            let theirs = nums(&out["flux_bio"]);
            assert_eq!(
                bits(&fl.flux_bio[..nb]),
                bits(&theirs[..nb]),
                "{name}: Icepack"
            );
        }

        // The same cell through the batched call, its flux_bio (nbtrcr, 1) added to.
        let (mut a, mut v, mut sn, mut t, mut a0, mut ai) = fresh();
        let mut fbio = vec![0.5; nb];
        let mut op = [closing.map_or(0.0, |c| c.1)];
        let cells = PressridgeCellArrays {
            rdg_conv: &conv,
            rdg_shear: &shear,
            closing: cl.as_ref().map_or(null(), |c| c as *const f64),
            opening: op.as_mut_ptr(),
            tf: &forcing.tf,
            valid: null(),
            fresh: null_mut(),
            fsalt: null_mut(),
            fhocn: null_mut(),
            fpond: null_mut(),
            dardg1dt: null_mut(),
            dardg2dt: null_mut(),
            dvirdgdt: null_mut(),
            faero_ocn: null_mut(),
            fiso_ocn: null_mut(),
            flux_bio: fbio.as_mut_ptr(),
        };
        // The batched call keeps hin_max; the CICE convention's top bound is params.big.
        let hb = hin.clone();
        // SAFETY: as above; one column.
        let rc = unsafe {
            pressridge_ridge_cells(
                r,
                1,
                forcing.dt,
                forcing.ndtd as i32,
                hb.as_ptr(),
                a.as_mut_ptr(),
                t.as_mut_ptr(),
                v.as_mut_ptr(),
                sn.as_mut_ptr(),
                &mut a0,
                &mut ai,
                &cells,
            )
        };
        assert_eq!(rc, PRESSRIDGE_OK, "{name}: batched");
        assert_eq!(bits(&t), bits(&w.trcrn), "{name}: batched trcrn");
        let added: Vec<f64> = wf.flux_bio[..nb].iter().map(|x| 0.5 + x).collect();
        assert_eq!(bits(&fbio), bits(&added), "{name}: batched flux_bio");
        // SAFETY: a handle from its *_new, freed once.
        unsafe { pressridge_ridger_free(r) };
        assert!(nt > 0);
        stepped += 1;
    }
    stepped
}

#[test]
fn vertical_bio_tracers_through_the_c_abi() {
    assert!(every_case(icepack::BGC_FILE) > 0);
}

#[test]
fn skeletal_bio_tracers_through_the_c_abi() {
    assert!(every_case(icepack::SKL_FILE) > 0);
}

#[test]
fn bad_bio_set_ups_are_refused_by_name() {
    let (params, cases) = icepack::read_file(icepack::BGC_FILE);
    let s = setup(&params);
    let i = &cases[0]["inputs"];
    let message = || {
        let mut buf = vec![0u8; 512];
        // SAFETY: a live buffer of the length passed.
        unsafe { pressridge_last_error(buf.as_mut_ptr().cast(), 512, null_mut()) };
        String::from_utf8_lossy(&buf)
            .trim_end_matches('\0')
            .to_string()
    };
    let bio = [0i32, 44];
    for (t, code, says) in [
        (
            PressridgeTracers {
                bgc_kind: 3,
                ..s.tracers
            },
            PRESSRIDGE_ERR_BAD_VALUE,
            "tracers.bgc_kind = 3",
        ),
        (
            PressridgeTracers {
                nbtrcr: 30,
                ..s.tracers
            },
            PRESSRIDGE_ERR_BAD_VALUE,
            "tracers.nbtrcr = 30",
        ),
        (
            PressridgeTracers {
                bio_index: null(),
                ..s.tracers
            },
            PRESSRIDGE_ERR_NULL_POINTER,
            "tracers.bio_index",
        ),
        (
            PressridgeTracers {
                bio_index: bio.as_ptr(),
                ..s.tracers
            },
            PRESSRIDGE_ERR_BAD_VALUE,
            "tracers.bio_index[0] = 0",
        ),
        (
            PressridgeTracers {
                flags: s.tracers.flags & !PRESSRIDGE_TRACER_BRINE,
                ..s.tracers
            },
            PRESSRIDGE_ERR_BAD_VALUE,
            "need the brine fraction fbri",
        ),
        (
            PressridgeTracers {
                bgc_kind: PRESSRIDGE_BGC_SKELETAL,
                sk_l: 0.0,
                ..s.tracers
            },
            PRESSRIDGE_ERR_BAD_VALUE,
            "sk_l = 0 m",
        ),
    ] {
        assert_eq!(ridger(&t, i).err(), Some(code), "{says}");
        let m = message();
        assert!(m.contains(says), "{says}: {m}");
    }
}
