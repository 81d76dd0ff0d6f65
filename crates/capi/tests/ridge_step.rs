//! The complete ridging step through the C ABI (`pressridge_ridger_*`,
//! `pressridge_ridge_cell`, `pressridge_ridge_cells`): the same bits as the Rust API, the
//! tracer layout as Icepack's arrays, clear errors with the cell unchanged.

// Per-category and per-tracer tables are indexed by number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use std::ptr::{null, null_mut};

use pressridge::itd::{
    ColumnMut, RidgeStepOptions, StepForcing, StepWorkspace,
    details::{CiceTracerFlags, Closing, OceanFluxes, TracerLayout},
    ridge_step_column,
};
use pressridge_capi::ridge_step::*;
use pressridge_capi::*;

const NCAT: usize = 5;

/// The 23 CICE tracers of the reference data: age, first-year ice, level ice, level ponds.
fn cice_tracers() -> PressridgeTracers {
    PressridgeTracers {
        flags: 15,
        ..Default::default()
    }
}

fn ridger(cleanup: i32) -> *mut PressridgeRidger {
    let mut r = null_mut();
    let rc =
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_ridger_new(NCAT as i64, 7, 1, &cice_tracers(), null(), null(), cleanup, 1, &mut r)
        };
    assert_eq!(rc, PRESSRIDGE_OK);
    r
}

/// A winter column with snow, ponds and every tracer, 5 categories.
fn column(layout: &TracerLayout, c: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>, f64) {
    let nt = layout.ntrcr();
    let w = [0.04, 0.16, 0.35, 0.25, 0.17];
    let h = [0.35, 1.0, 1.85, 2.9, 4.6];
    let f = 1.0 + 0.01 * c as f64;
    let a: Vec<f64> = w
        .iter()
        .map(|x| x * 0.97 / 0.97 * f.min(1.02) / 1.02)
        .collect();
    let v: Vec<f64> = a.iter().zip(h).map(|(a, h)| a * h * f).collect();
    let s: Vec<f64> = v.iter().map(|v| 0.1 * v).collect();
    let mut t = vec![0.0; NCAT * nt];
    for n in 0..NCAT {
        let tr = &mut t[n * nt..(n + 1) * nt];
        tr[0] = -20.0;
        for k in 0..7 {
            tr[1 + k] = -3.0e8 - 1e6 * k as f64;
            tr[9 + k] = 4.0 + 0.1 * k as f64;
        }
        tr[8] = -1.2e8;
        tr[16] = 1e7;
        tr[17] = 0.3;
        tr[18] = 0.8;
        tr[19] = 0.75;
        tr[20] = 0.2;
        tr[21] = 0.1;
        tr[22] = 0.01;
    }
    let a0 = 1.0 - a.iter().sum::<f64>();
    (a, v, s, t, a0)
}

#[test]
fn cell_call_is_bitwise_the_rust_step_and_reports_icepack_tracer_tables() {
    let r = ridger(1);
    let layout = TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap();
    let nt = layout.ntrcr();
    // Icepack's tracer arrays.
    let mut ntrcr = 0i64;
    let mut dep = vec![0i32; nt];
    let mut base = vec![0.0; nt * 3];
    let mut nstr = vec![0i32; nt];
    let mut str = vec![0i32; nt * 2];
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridger_tracers(
            r,
            &mut ntrcr,
            nt as i64,
            dep.as_mut_ptr(),
            base.as_mut_ptr(),
            nstr.as_mut_ptr(),
            str.as_mut_ptr(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    assert_eq!(ntrcr, 23);
    assert_eq!(dep[21], 2 + 21); // hpnd on apnd (1-based 21)
    assert_eq!((nstr[21], str[21], str[21 + nt]), (2, 19, 21));
    assert_eq!((base[1], base[1 + nt], base[8 + 2 * nt]), (0.0, 1.0, 1.0));
    let (mut start, mut levels) = (0i64, 0i64);
    let rc =
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridger_tracer_field(r, b"sice".as_ptr(), 4, &mut start, &mut levels) };
    assert_eq!((rc, start, levels), (PRESSRIDGE_OK, 9, 7));

    let hin0 = [0.0, 0.6, 1.4, 2.4, 3.6, 999.9];
    let (a, v, s, t, a0) = column(&layout, 0);
    // Rust.
    let (mut ra, mut rv, mut rs, mut rt, mut ra0, mut raice) =
        (a.clone(), v.clone(), s.clone(), t.clone(), a0, 0.0);
    let mut rf = OceanFluxes::default();
    let mut ws = StepWorkspace::new(NCAT, nt);
    let forcing = StepForcing {
        closing: Closing::Deformation {
            convergence: 3e-6,
            shear: 2e-6,
        },
        dt: 3600.0,
        ndtd: 1,
        tf: -1.836,
    };
    let d = ridge_step_column(
        &mut ColumnMut {
            aicen: &mut ra,
            vicen: &mut rv,
            vsnon: &mut rs,
            trcrn: &mut rt,
            aice0: &mut ra0,
            aice: &mut raice,
        },
        &hin0,
        forcing,
        &RidgeStepOptions::default(),
        &layout,
        &mut rf,
        &mut ws,
    )
    .unwrap();
    // C.
    let (mut ca, mut cv, mut cs, mut ct, mut ca0, mut caice) =
        (a.clone(), v.clone(), s.clone(), t.clone(), a0, 0.0);
    let mut hin = hin0;
    let mut fl = PressridgeOceanFluxes::default();
    let mut cd = PressridgeStepDiagnostics::default();
    let mut opening = 0.0;
    let mut krdgn = [0.0; NCAT];
    let mut first_ice = [0i32; NCAT];
    let cats = PressridgeCategoryDiagnostics {
        dardg1ndt: null_mut(),
        dardg2ndt: null_mut(),
        dvirdgndt: null_mut(),
        aparticn: null_mut(),
        krdgn: krdgn.as_mut_ptr(),
        araftn: null_mut(),
        vraftn: null_mut(),
        aredistn: null_mut(),
        vredistn: null_mut(),
        first_ice: first_ice.as_mut_ptr(),
    };
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridge_cell(
            r,
            3600.0,
            1,
            hin.as_mut_ptr(),
            3e-6,
            2e-6,
            null(),
            &mut opening,
            ca.as_mut_ptr(),
            ct.as_mut_ptr(),
            cv.as_mut_ptr(),
            cs.as_mut_ptr(),
            &mut ca0,
            &mut caice,
            -1.836,
            &mut fl,
            &mut cd,
            &cats,
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    assert_eq!((ca, cv, cs, ct), (ra, rv, rs, rt));
    assert_eq!(
        (ca0.to_bits(), caice.to_bits()),
        (ra0.to_bits(), raice.to_bits())
    );
    assert_eq!(
        hin[NCAT], 1e8,
        "CICE convention: top bound set to big, as Icepack"
    );
    assert_eq!(opening.to_bits(), d.opening.to_bits());
    assert_eq!(cd.dardg1dt.to_bits(), d.dardg1dt.to_bits());
    assert_eq!(
        (fl.fresh, fl.fhocn, fl.fpond),
        (rf.fresh, rf.fhocn, rf.fpond)
    );
    assert_eq!(krdgn.to_vec(), ws.krdgn);
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    unsafe { pressridge_ridger_free(r) };
}

#[test]
fn batched_cells_equal_cell_calls_and_errors_name_the_cell() {
    let r = ridger(1);
    let layout = TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap();
    let nt = layout.ntrcr();
    let ncol = 6;
    let (mut a, mut v, mut s, mut t, mut a0) = (vec![], vec![], vec![], vec![], vec![]);
    for c in 0..ncol {
        let (ca, cv, cs, ct, c0) = column(&layout, c);
        a.extend(ca);
        v.extend(cv);
        s.extend(cs);
        t.extend(ct);
        a0.push(c0);
    }
    let conv: Vec<f64> = (0..ncol).map(|c| 1e-6 * (c + 1) as f64).collect();
    let shear = vec![2e-6; ncol];
    let hin = [0.0, 0.6, 1.4, 2.4, 3.6, 999.9];
    let (mut ba, mut bv, mut bs, mut bt, mut ba0) =
        (a.clone(), v.clone(), s.clone(), t.clone(), a0.clone());
    let mut baice = vec![0.0; ncol];
    let mut fresh = vec![0.0; ncol];
    let mut opening = vec![0.0; ncol];
    let cells = PressridgeCellArrays {
        rdg_conv: conv.as_ptr(),
        rdg_shear: shear.as_ptr(),
        closing: null(),
        opening: opening.as_mut_ptr(),
        tf: null(),
        valid: null(),
        fresh: fresh.as_mut_ptr(),
        fsalt: null_mut(),
        fhocn: null_mut(),
        fpond: null_mut(),
        dardg1dt: null_mut(),
        dardg2dt: null_mut(),
        dvirdgdt: null_mut(),
        faero_ocn: null_mut(),
        fiso_ocn: null_mut(),
        flux_bio: null_mut(),
    };
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridge_cells(
            r,
            ncol as i64,
            1800.0,
            2,
            hin.as_ptr(),
            ba.as_mut_ptr(),
            bt.as_mut_ptr(),
            bv.as_mut_ptr(),
            bs.as_mut_ptr(),
            ba0.as_mut_ptr(),
            baice.as_mut_ptr(),
            &cells,
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    for c in 0..ncol {
        let mut h = hin;
        let mut fl = PressridgeOceanFluxes::default();
        let (mut ca0, mut caice, mut op) = (a0[c], 0.0, 0.0);
        let (sa, sv, sst) = (c * NCAT, c * NCAT, c * NCAT * nt);
        let mut ca = a[sa..sa + NCAT].to_vec();
        let mut cv = v[sv..sv + NCAT].to_vec();
        let mut cs = s[sv..sv + NCAT].to_vec();
        let mut ct = t[sst..sst + NCAT * nt].to_vec();
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe {
            pressridge_ridge_cell(
                r,
                1800.0,
                2,
                h.as_mut_ptr(),
                conv[c],
                shear[c],
                null(),
                &mut op,
                ca.as_mut_ptr(),
                ct.as_mut_ptr(),
                cv.as_mut_ptr(),
                cs.as_mut_ptr(),
                &mut ca0,
                &mut caice,
                -1.8,
                &mut fl,
                null_mut(),
                null(),
            )
        };
        assert_eq!(rc, PRESSRIDGE_OK);
        assert_eq!(ca, ba[sa..sa + NCAT]);
        assert_eq!(ct, bt[sst..sst + NCAT * nt]);
        assert_eq!(ca0.to_bits(), ba0[c].to_bits());
        assert_eq!(fl.fresh.to_bits(), fresh[c].to_bits());
        assert_eq!(op.to_bits(), opening[c].to_bits());
    }
    // A negative volume in cell 3: error naming the variable, category and cell; cell 3
    // and later unchanged.
    let (mut ea, mut ev, mut es, mut et, mut ea0) =
        (a.clone(), v.clone(), s.clone(), t.clone(), a0.clone());
    ev[3 * NCAT + 2] = -1e-3;
    let before = ev.clone();
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridge_cells(
            r,
            ncol as i64,
            1800.0,
            1,
            hin.as_ptr(),
            ea.as_mut_ptr(),
            et.as_mut_ptr(),
            ev.as_mut_ptr(),
            es.as_mut_ptr(),
            ea0.as_mut_ptr(),
            baice.as_mut_ptr(),
            &cells,
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    let mut need = 0i64;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    unsafe { pressridge_last_error(null_mut(), 0, &mut need) };
    let mut buf = vec![0u8; need as usize];
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    unsafe { pressridge_last_error(buf.as_mut_ptr().cast(), need, null_mut()) };
    let msg = String::from_utf8_lossy(&buf).to_string();
    assert!(msg.contains("vicen") && msg.contains("column 3"), "{msg}");
    assert_eq!(ev[3 * NCAT..], before[3 * NCAT..]);
    assert_eq!(ea[3 * NCAT..], a[3 * NCAT..]);
    // Bad set-up: ponds without level ice.
    let mut bad = null_mut();
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridger_new(
            5,
            7,
            1,
            &PressridgeTracers {
                flags: PRESSRIDGE_TRACER_PONDS,
                ..Default::default()
            },
            null(),
            null(),
            1,
            1,
            &mut bad,
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    unsafe { pressridge_ridger_free(r) };
}

/// Snow, isotope and aerosol tracers through the C ABI: the ridger made with
/// `PRESSRIDGE_TRACER_SNOW`, `n_iso` and `n_aero`; `pressridge_ridge_cell` adds the same
/// `faero_ocn` and `fiso_ocn` as the Rust step, and `pressridge_ridge_cells` the same per
/// column (`faero_ocn(n_aero, ncol)`); species counts out of range are refused by name.
#[test]
fn aerosol_and_isotope_fluxes_through_the_c_abi() {
    let flags = CiceTracerFlags {
        snow: true,
        isotopes: 2,
        aerosols: 3,
        ..CiceTracerFlags::ALL
    };
    let layout = TracerLayout::cice(7, 1, flags).unwrap();
    let nt = layout.ntrcr();
    let mut r = null_mut();
    let tracers = PressridgeTracers {
        flags: 31,
        n_iso: 2,
        n_aero: 3,
        ..Default::default()
    };
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
    // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe { pressridge_ridger_new(5, 7, 1, &tracers, null(), null(), 1, 1, &mut r) };
    assert_eq!(rc, PRESSRIDGE_OK);
    // The 23 CICE tracers of `column`, then the added ones: positive amounts.
    let small = TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap();
    let ncol = 3;
    let (mut a, mut v, mut s, mut t, mut a0) = (vec![], vec![], vec![], vec![], vec![]);
    for c in 0..ncol {
        let (ca, cv, cs, ct, ca0) = column(&small, c);
        for n in 0..NCAT {
            t.extend_from_slice(&ct[n * 23..(n + 1) * 23]);
            t.extend((23..nt).map(|it| 1e-3 * (1 + it % 7 + n) as f64));
        }
        a.extend(ca);
        v.extend(cv);
        s.extend(cs);
        a0.push(ca0);
    }
    let hin = [0.0, 0.6, 1.4, 2.4, 3.6, 999.9];
    let forcing = StepForcing {
        closing: Closing::Deformation {
            convergence: 3e-6,
            shear: 2e-6,
        },
        dt: 3600.0,
        ndtd: 1,
        tf: -1.8,
    };
    // Rust, per column.
    let mut want = Vec::new();
    for c in 0..ncol {
        let (mut ra, mut rv, mut rs) = (
            a[c * NCAT..(c + 1) * NCAT].to_vec(),
            v[c * NCAT..(c + 1) * NCAT].to_vec(),
            s[c * NCAT..(c + 1) * NCAT].to_vec(),
        );
        let mut rt = t[c * NCAT * nt..(c + 1) * NCAT * nt].to_vec();
        let (mut ra0, mut raice) = (a0[c], 0.0);
        let mut rf = OceanFluxes::default();
        let mut ws = StepWorkspace::new(NCAT, nt);
        let mut col = ColumnMut {
            aicen: &mut ra,
            vicen: &mut rv,
            vsnon: &mut rs,
            trcrn: &mut rt,
            aice0: &mut ra0,
            aice: &mut raice,
        };
        let opts = RidgeStepOptions::default();
        ridge_step_column(&mut col, &hin, forcing, &opts, &layout, &mut rf, &mut ws).unwrap();
        assert!(rf.faero_ocn[2] > 0.0 && rf.fiso_ocn[1] > 0.0);
        want.push((rf, rt));
    }
    // C, one cell.
    let (mut ca, mut cv, mut cs) = (a[..NCAT].to_vec(), v[..NCAT].to_vec(), s[..NCAT].to_vec());
    let mut ct = t[..NCAT * nt].to_vec();
    let (mut ca0, mut caice, mut opening) = (a0[0], 0.0, 0.0);
    let mut h = hin;
    let mut fl = PressridgeOceanFluxes {
        faero_ocn: [0.0, 0.0, 0.0, 7.0, 7.0, 7.0],
        ..Default::default()
    };
    // SAFETY: as above.
    let rc = unsafe {
        pressridge_ridge_cell(
            r,
            3600.0,
            1,
            h.as_mut_ptr(),
            3e-6,
            2e-6,
            null(),
            &mut opening,
            ca.as_mut_ptr(),
            ct.as_mut_ptr(),
            cv.as_mut_ptr(),
            cs.as_mut_ptr(),
            &mut ca0,
            &mut caice,
            -1.8,
            &mut fl,
            null_mut(),
            null(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    assert_eq!(fl.faero_ocn[..3], want[0].0.faero_ocn[..3]);
    assert_eq!(
        fl.faero_ocn[3..],
        [7.0; 3],
        "beyond n_aero: left as they were"
    );
    assert_eq!(fl.fiso_ocn[..2], want[0].0.fiso_ocn[..2]);
    assert_eq!(ct, want[0].1);
    // C, three cells: species fastest.
    let mut faero = vec![0.0; 3 * ncol];
    let mut fiso = vec![0.0; 2 * ncol];
    let conv = vec![3e-6; ncol];
    let shear = vec![2e-6; ncol];
    let tf = vec![-1.8; ncol];
    let mut aice = vec![0.0; ncol];
    let cells = PressridgeCellArrays {
        rdg_conv: conv.as_ptr(),
        rdg_shear: shear.as_ptr(),
        closing: null(),
        opening: null_mut(),
        tf: tf.as_ptr(),
        valid: null(),
        fresh: null_mut(),
        fsalt: null_mut(),
        fhocn: null_mut(),
        fpond: null_mut(),
        dardg1dt: null_mut(),
        dardg2dt: null_mut(),
        dvirdgdt: null_mut(),
        faero_ocn: faero.as_mut_ptr(),
        fiso_ocn: fiso.as_mut_ptr(),
        flux_bio: null_mut(),
    };
    // SAFETY: as above.
    let rc = unsafe {
        pressridge_ridge_cells(
            r,
            ncol as i64,
            3600.0,
            1,
            hin.as_ptr(),
            a.as_mut_ptr(),
            t.as_mut_ptr(),
            v.as_mut_ptr(),
            s.as_mut_ptr(),
            a0.as_mut_ptr(),
            aice.as_mut_ptr(),
            &cells,
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    for (c, (f, rt)) in want.iter().enumerate() {
        assert_eq!(faero[3 * c..3 * c + 3], f.faero_ocn[..3], "column {c}");
        assert_eq!(fiso[2 * c..2 * c + 2], f.fiso_ocn[..2], "column {c}");
        assert_eq!(t[c * NCAT * nt..(c + 1) * NCAT * nt], rt[..]);
    }
    // SAFETY: a handle from its *_new (or null), freed once and not used after.
    unsafe { pressridge_ridger_free(r) };
    let mut bad = null_mut();
    let too_many = PressridgeTracers {
        n_aero: 7,
        ..tracers
    };
    // SAFETY: as above.
    let rc = unsafe { pressridge_ridger_new(5, 7, 1, &too_many, null(), null(), 1, 1, &mut bad) };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    let mut buf = vec![0u8; 256];
    // SAFETY: as above.
    unsafe { pressridge_last_error(buf.as_mut_ptr().cast(), 256, null_mut()) };
    let msg = String::from_utf8_lossy(&buf).to_string();
    assert!(msg.contains("tracers.n_aero = 7"), "{msg}");
    // The other groups: topography ponds, floe size, brine and the snow refills make the
    // layout of Icepack's driver (45 tracers here).
    let all = PressridgeTracers {
        flags: 1 | 2 | 4 | 16 | PRESSRIDGE_TRACER_POND_TOPO | PRESSRIDGE_TRACER_BRINE,
        nfsd: 3,
        rhos_empty: 100.0,
        smice_empty: 330.0,
        rsnw_empty: 54.5,
        ..tracers
    };
    let mut r = null_mut();
    // SAFETY: as above.
    let rc = unsafe { pressridge_ridger_new(5, 7, 1, &all, null(), null(), 1, 1, &mut r) };
    assert_eq!(rc, PRESSRIDGE_OK);
    let mut ntrcr = 0i64;
    // SAFETY: as above.
    let rc = unsafe {
        pressridge_ridger_tracers(
            r,
            &mut ntrcr,
            0,
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
        )
    };
    assert_eq!((rc, ntrcr), (PRESSRIDGE_OK, 23 + 4 + 3 + 4 + 12 + 1));
    // SAFETY: a handle from its *_new (or null), freed once and not used after.
    unsafe { pressridge_ridger_free(r) };
    let two_schemes = PressridgeTracers {
        flags: 15 | PRESSRIDGE_TRACER_POND_TOPO,
        ..Default::default()
    };
    // SAFETY: as above.
    let rc =
        unsafe { pressridge_ridger_new(5, 7, 1, &two_schemes, null(), null(), 1, 1, &mut bad) };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
}

/// A host's own tracer tables through the C ABI (`PressridgeTracers.host_*`): the ridger
/// reports them back as its tables; all four or none; a table that contradicts itself is
/// refused naming the tracer.
#[test]
fn host_tracer_tables_through_the_c_abi() {
    let base = PressridgeTracers {
        flags: 15,
        n_iso: 3,
        ..Default::default()
    };
    let new = |t: &PressridgeTracers| {
        let mut r = null_mut();
        // SAFETY: every non-null pointer is a live local or buffer of at least the length
        // passed; the entry point checks nulls, sizes and handles itself.
        let rc = unsafe { pressridge_ridger_new(5, 7, 1, t, null(), null(), 1, 1, &mut r) };
        (rc, r)
    };
    let tables = |r: *mut PressridgeRidger, nt: usize| {
        let (mut dep, mut b, mut nst, mut st) = (
            vec![0i32; nt],
            vec![0.0; 3 * nt],
            vec![0i32; nt],
            vec![0i32; 2 * nt],
        );
        let mut n = 0i64;
        // SAFETY: as above.
        let rc = unsafe {
            pressridge_ridger_tracers(
                r,
                &mut n,
                nt as i64,
                dep.as_mut_ptr(),
                b.as_mut_ptr(),
                nst.as_mut_ptr(),
                st.as_mut_ptr(),
            )
        };
        assert_eq!((rc, n), (PRESSRIDGE_OK, nt as i64));
        (dep, b, nst, st)
    };
    let (rc, r) = new(&base);
    assert_eq!(rc, PRESSRIDGE_OK);
    let nt = 23 + 6;
    let (mut dep, mut b, nst, st) = tables(r, nt);
    // SAFETY: a handle from its *_new, freed once and not used after.
    unsafe { pressridge_ridger_free(r) };
    // Icepack's column driver: isotope species 2 and 3 (tracers 25, 26) on the area.
    for it in [24, 25] {
        dep[it] = 0;
        b[it] = 1.0;
        b[2 * nt + it] = 0.0;
    }
    let host = PressridgeTracers {
        host_trcr_depend: dep.as_ptr(),
        host_trcr_base: b.as_ptr(),
        host_n_trcr_strata: nst.as_ptr(),
        host_nt_strata: st.as_ptr(),
        host_ntrcr: nt as i64,
        ..base
    };
    let (rc, r) = new(&host);
    assert_eq!(rc, PRESSRIDGE_OK);
    assert_eq!(tables(r, nt).0, dep, "the host's trcr_depend");
    // SAFETY: as above.
    unsafe { pressridge_ridger_free(r) };
    let partial = PressridgeTracers {
        host_trcr_base: null(),
        ..host
    };
    assert_eq!(new(&partial).0, PRESSRIDGE_ERR_BAD_VALUE);
    let short = PressridgeTracers {
        host_ntrcr: nt as i64 - 1,
        ..host
    };
    assert_eq!(new(&short).0, PRESSRIDGE_ERR_BAD_SIZE);
    // CICE's array: one slot more than its flags count, an area tracer there (its tables say
    // so); nine more are refused.
    let (mut dep1, mut b1, mut nst1, mut st1) = (dep.clone(), Vec::new(), nst.clone(), Vec::new());
    dep1.push(0);
    nst1.push(0);
    for k in 0..3 {
        b1.extend_from_slice(&b[k * nt..(k + 1) * nt]);
        b1.push(if k == 0 { 1.0 } else { 0.0 });
    }
    for k in 0..2 {
        st1.extend_from_slice(&st[k * nt..(k + 1) * nt]);
        st1.push(0);
    }
    let cice = PressridgeTracers {
        host_trcr_depend: dep1.as_ptr(),
        host_trcr_base: b1.as_ptr(),
        host_n_trcr_strata: nst1.as_ptr(),
        host_nt_strata: st1.as_ptr(),
        host_ntrcr: nt as i64 + 1,
        ..host
    };
    let (rc, r) = new(&cice);
    assert_eq!(rc, PRESSRIDGE_OK);
    assert_eq!(
        tables(r, nt + 1).0,
        dep1,
        "the layout and one unnamed area tracer"
    );
    // SAFETY: as above.
    unsafe { pressridge_ridger_free(r) };
    let long = PressridgeTracers {
        host_ntrcr: nt as i64 + 9,
        ..host
    };
    assert_eq!(new(&long).0, PRESSRIDGE_ERR_BAD_SIZE);
    // A trcr_depend of no base and no tracer is refused, naming the tracer; one that only
    // disagrees with its base is kept, as Icepack keeps it (the with_host_tables doc).
    dep[24] = -1;
    let (rc, _) = new(&host);
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    let mut buf = vec![0u8; 256];
    // SAFETY: as above.
    unsafe { pressridge_last_error(buf.as_mut_ptr().cast(), 256, null_mut()) };
    let msg = String::from_utf8_lossy(&buf).to_string();
    assert!(msg.contains("tracer 25"), "{msg}");
}
