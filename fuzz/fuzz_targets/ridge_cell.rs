//! The complete ridging step of the C ABI (`pressridge_ridger_new`, `pressridge_ridge_cell`)
//! on arbitrary set-ups (1–8 categories, 1–4 ice and 1–3 snow layers, any tracer flags and
//! species counts, participation and redistribution codes, clean-up and rebinning, a few
//! ridging parameters), arbitrary cells (any bits in the state, the bounds, the forcing) and
//! either closing convention: a refused set-up or cell is a status code, never a crash; a
//! refused cell is left as it was, bit for bit; an accepted one is finite with no negative
//! area, volume or snow.
#![no_main]

#[path = "bytes.rs"]
mod bytes;

use bytes::Bytes;
use libfuzzer_sys::fuzz_target;
use pressridge_capi::PRESSRIDGE_OK;
use pressridge_capi::itd::PressridgeOptions;
use pressridge_capi::ridge_step::{
    PressridgeCategoryDiagnostics, PressridgeOceanFluxes, PressridgeRidger,
    PressridgeStepDiagnostics, PressridgeTracers, pressridge_ridge_cell, pressridge_ridger_free,
    pressridge_ridger_new, pressridge_ridger_tracers,
};

/// Values a sea-ice state holds, for [`Bytes::f64_from`].
const NICE: [f64; 16] = [
    0.0, 1e-12, 1e-6, 0.01, 0.1, 0.25, 0.5, 0.9, 1.0, 2.5, 10.0, -1.8, -2.0e8, 3600.0, 1e-7, 4.0,
];

fuzz_target!(|input: &[u8]| {
    let mut d = Bytes(input);
    let ncat = 1 + usize::from(d.byte() % 8);
    let layers = d.byte();
    let (nilyr, nslyr) = (1 + i64::from(layers % 4), 1 + i64::from((layers >> 2) % 3));
    let t = PressridgeTracers {
        flags: i32::from(d.byte()),
        n_iso: i32::from(d.byte() % 5),
        n_aero: i32::from(d.byte() % 8),
        nfsd: i32::from(d.byte() % 4),
        ..PressridgeTracers::default()
    };
    let codes = d.byte();
    let mut o = PressridgeOptions::default();
    o.participation = i32::from(codes & 3);
    o.redistribution = i32::from((codes >> 2) & 3);
    if codes & 16 != 0 {
        o.params.mu_rdg = d.f64_from(&NICE);
        o.params.cs = d.f64_from(&NICE);
    }
    let (cleanup, rebin, host_rates) = (codes & 32 != 0, codes & 64 != 0, codes & 128 != 0);
    let mut ridger: *mut PressridgeRidger = std::ptr::null_mut();
    // SAFETY: `t` and `o` are live locals with null host tables; `ridger` is a live local.
    let rc = unsafe {
        pressridge_ridger_new(
            ncat as i64,
            nilyr,
            nslyr,
            &t,
            &o,
            std::ptr::null(),
            i32::from(cleanup),
            i32::from(rebin),
            &mut ridger,
        )
    };
    if rc != PRESSRIDGE_OK {
        assert!(ridger.is_null() || rc == PRESSRIDGE_OK);
        return;
    }
    let mut nt = 0i64;
    use std::ptr::null_mut;
    // SAFETY: a live handle and a live local; no tables asked for.
    let rc = unsafe {
        pressridge_ridger_tracers(
            ridger,
            &mut nt,
            0,
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    let nt = usize::try_from(nt).expect("a tracer count");
    let (dt, ndtd) = (d.f64_from(&NICE), i32::from(d.byte() % 4));
    let (conv, shear, tf) = (d.f64_from(&NICE), d.f64_from(&NICE), d.f64_from(&NICE));
    let closing = d.f64_from(&NICE);
    let mut opening = d.f64_from(&NICE);
    let mut hin_max: Vec<f64> = (0..=ncat).map(|_| d.f64_from(&NICE)).collect();
    let mut a: Vec<f64> = (0..ncat).map(|_| d.f64_from(&NICE)).collect();
    let mut v: Vec<f64> = (0..ncat).map(|_| d.f64_from(&NICE)).collect();
    let mut s: Vec<f64> = (0..ncat).map(|_| d.f64_from(&NICE)).collect();
    let mut tr: Vec<f64> = (0..nt * ncat).map(|_| d.f64_from(&NICE)).collect();
    let (mut aice0, mut aice) = (d.f64_from(&NICE), d.f64_from(&NICE));
    let before = ((), a.clone(), v.clone(), s.clone(), tr.clone(), aice0, aice);
    let mut fluxes = PressridgeOceanFluxes::default();
    let mut diag = PressridgeStepDiagnostics::default();
    let mut cats = vec![0.0; 9 * ncat];
    let mut first_ice = vec![0i32; ncat];
    let base = cats.as_mut_ptr();
    // SAFETY: k < 9, so k·ncat lies inside `cats`, which outlives the call below.
    let p = |k: usize| unsafe { base.add(k * ncat) };
    let categories = PressridgeCategoryDiagnostics {
        dardg1ndt: p(0),
        dardg2ndt: p(1),
        dvirdgndt: p(2),
        aparticn: p(3),
        krdgn: p(4),
        araftn: p(5),
        vraftn: p(6),
        aredistn: p(7),
        vredistn: p(8),
        first_ice: first_ice.as_mut_ptr(),
    };
    // SAFETY: every array holds what the call reads and writes for `ncat` categories and
    // `nt` tracers (`cats` 9·ncat values, one block of `ncat` per pointer); the others are
    // live locals; `closing` is null or a live local.
    let rc = unsafe {
        pressridge_ridge_cell(
            ridger,
            dt,
            ndtd,
            hin_max.as_mut_ptr(),
            conv,
            shear,
            if host_rates {
                &closing
            } else {
                std::ptr::null()
            },
            &mut opening,
            a.as_mut_ptr(),
            tr.as_mut_ptr(),
            v.as_mut_ptr(),
            s.as_mut_ptr(),
            &mut aice0,
            &mut aice,
            tf,
            &mut fluxes,
            &mut diag,
            &categories,
        )
    };
    if rc == PRESSRIDGE_OK {
        for (name, x) in [("aicen", &a), ("vicen", &v), ("vsnon", &s)] {
            assert!(
                x.iter().all(|y| y.is_finite() && *y >= 0.0),
                "{name} {x:?} from an accepted cell"
            );
        }
        assert!(tr.iter().all(|y| y.is_finite()), "a tracer not finite");
        assert!(aice0.is_finite() && aice.is_finite());
    } else {
        let bits = |x: &[f64]| x.iter().map(|y| y.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&before.1), bits(&a), "aicen changed by a refused cell");
        assert_eq!(bits(&before.2), bits(&v), "vicen changed by a refused cell");
        assert_eq!(bits(&before.3), bits(&s), "vsnon changed by a refused cell");
        assert_eq!(
            bits(&before.4),
            bits(&tr),
            "trcrn changed by a refused cell"
        );
        assert_eq!(before.5.to_bits(), aice0.to_bits());
        assert_eq!(before.6.to_bits(), aice.to_bits());
        assert_eq!(
            fluxes,
            PressridgeOceanFluxes::default(),
            "fluxes of a refused cell"
        );
    }
    // SAFETY: the handle from pressridge_ridger_new, freed once.
    assert_eq!(unsafe { pressridge_ridger_free(ridger) }, PRESSRIDGE_OK);
});
