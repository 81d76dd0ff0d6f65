//! The batched strength of the C ABI (`pressridge_strength`) on arbitrary grid layouts
//! (`PressridgeGrid`: sizes, strides and lengths that may not fit their arrays, arrays of
//! exactly the stated length), null pointers where the call allows them and where it does
//! not, an output that may overlap an input, masks and option codes: a status, never a
//! crash or an access outside the arrays (AddressSanitizer); an accepted grid gives each
//! computed column the bits `pressridge_strength_cell` gives it, and each masked column the
//! fill value.
#![no_main]

use libfuzzer_sys::fuzz_target;
use pressridge_capi::itd::{PressridgeOptions, pressridge_strength, pressridge_strength_cell};
use pressridge_capi::{PRESSRIDGE_OK, PressridgeGrid};

#[path = "bytes.rs"]
mod bytes;
use bytes::Bytes;

/// Values of ice area fractions and thicknesses, for [`Bytes::f64_from`].
const NICE: [f64; 8] = [0.0, 1e-12, 0.01, 0.1, 0.25, 0.5, 1.0, 2.5];

/// A grid number: small, or (rarely) anything.
fn size(d: &mut Bytes<'_>) -> i64 {
    match d.byte() {
        250 => i64::MAX,
        251 => -1,
        252 => i64::MIN,
        b => i64::from(b % 24),
    }
}

fuzz_target!(|input: &[u8]| {
    let mut d = Bytes(input);
    let g = PressridgeGrid {
        ncat: size(&mut d),
        ncol: size(&mut d),
        cat_stride: size(&mut d),
        col_stride: size(&mut d),
        len: size(&mut d).saturating_mul(8),
        col_stride_1d: size(&mut d),
        len_1d: size(&mut d),
    };
    let ptrs = d.byte();
    let codes = d.byte();
    let mut o = PressridgeOptions::default();
    o.participation = i32::from(codes & 3);
    o.redistribution = i32::from((codes >> 2) & 3);
    o.strength_law = i32::from((codes >> 4) & 3);
    o.fill = -1.0;
    // Arrays of exactly the lengths the grid states: a length too large to allocate here is
    // a promise this harness cannot keep, so it is not made; a negative one is passed on
    // (with empty arrays), for the call to refuse.
    if g.len > 4096 || g.len_1d > 4096 {
        return;
    }
    let cap = |n: i64| usize::try_from(n).unwrap_or(0);
    let (n2, n1) = (cap(g.len), cap(g.len_1d));
    let mut a: Vec<f64> = (0..n2)
        .map(|_| d.f64_from(&NICE).abs().min(1.0) * 0.2)
        .collect();
    let v: Vec<f64> = a
        .iter()
        .map(|x| x * (0.1 + f64::from(d.byte()) / 32.0))
        .collect();
    let a0: Vec<f64> = (0..n1).map(|_| d.f64_from(&NICE)).collect();
    let valid: Vec<i32> = (0..n1).map(|_| i32::from(d.byte() % 3 != 0)).collect();
    let mut s = vec![f64::NAN; n1];
    let mut clamped = -1i64;
    let null = std::ptr::null::<f64>();
    // The output may be the aicen array itself (an overlap the call must refuse), where
    // that array is long enough to be an output of `len_1d` values.
    let overlap = ptrs & 64 != 0 && n1 > 0 && n2 >= n1;
    let a_ptr = a.as_mut_ptr();
    let out = if overlap { a_ptr } else { s.as_mut_ptr() };
    // SAFETY: every non-null pointer is valid for the length the grid states (`len`, `len_1d`),
    // which is all the call may touch; the grid, options and counters are live locals.
    let rc = unsafe {
        pressridge_strength(
            if ptrs & 1 != 0 { std::ptr::null() } else { &g },
            if ptrs & 2 != 0 {
                null
            } else {
                a_ptr.cast_const()
            },
            v.as_ptr(),
            if ptrs & 4 != 0 { a0.as_ptr() } else { null },
            if ptrs & 8 != 0 {
                valid.as_ptr()
            } else {
                std::ptr::null()
            },
            if ptrs & 16 != 0 { std::ptr::null() } else { &o },
            out,
            if ptrs & 32 != 0 {
                &mut clamped
            } else {
                std::ptr::null_mut()
            },
        )
    };
    if overlap {
        assert!(rc != PRESSRIDGE_OK, "an output over aicen accepted");
    }
    if rc != PRESSRIDGE_OK {
        return;
    }
    // Accepted: the grid is sound, so its columns can be read back.
    let (ncat, ncol) = (g.ncat as usize, g.ncol as usize);
    let opts = if ptrs & 16 != 0 {
        PressridgeOptions::default()
    } else {
        o
    };
    for c in 0..ncol {
        let at = c * g.col_stride_1d as usize;
        if ptrs & 8 != 0 && valid[at] == 0 {
            assert_eq!(s[at].to_bits(), opts.fill.to_bits(), "masked column {c}");
            continue;
        }
        let ac: Vec<f64> = (0..ncat)
            .map(|n| a[c * g.col_stride as usize + n * g.cat_stride as usize])
            .collect();
        let vc: Vec<f64> = (0..ncat)
            .map(|n| v[c * g.col_stride as usize + n * g.cat_stride as usize])
            .collect();
        let a0c = if ptrs & 4 != 0 {
            a0[at]
        } else {
            f64::max(1.0 - ac.iter().sum::<f64>(), 0.0)
        };
        let mut p = f64::NAN;
        // SAFETY: `ac`, `vc` hold `ncat` values; `opts` and `p` are live locals.
        let rc = unsafe {
            pressridge_strength_cell(ncat as i64, ac.as_ptr(), vc.as_ptr(), a0c, &opts, &mut p)
        };
        assert_eq!(
            rc, PRESSRIDGE_OK,
            "column {c} accepted in the grid, refused alone"
        );
        assert_eq!(
            p.to_bits(),
            s[at].to_bits(),
            "column {c}: grid {} cell {p}",
            s[at]
        );
    }
});
