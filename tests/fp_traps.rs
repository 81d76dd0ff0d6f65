//! A host that traps floating-point exceptions (gfortran's `-ffpe-trap=invalid,zero,overflow`,
//! as CICE's debug build links every program) gets none from the strength and the ridging step
//! on ordinary columns with empty categories: with the traps on, a 0/0 of an unused lane kills
//! the process (SIGFPE), so this test binary runs alone and a crash fails it. glibc on x86_64
//! only (`feenableexcept`).
#![cfg(all(target_os = "linux", target_env = "gnu", target_arch = "x86_64"))]

use pressridge::itd::{
    Cf, StrengthOptions, Workspace,
    details::{StrengthConsts, strength_column_constant_cf},
    strength_column,
};

unsafe extern "C" {
    fn feenableexcept(excepts: i32) -> i32;
    fn fedisableexcept(excepts: i32) -> i32;
}
/// FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW on x86_64 (glibc's fenv.h).
const TRAPS: i32 = 0x01 | 0x04 | 0x08;

#[test]
fn the_strength_raises_no_trapped_exception_on_empty_categories() {
    let columns: [([f64; 5], [f64; 5]); 3] = [
        ([0.3, 0.0, 0.2, 0.0, 0.1], [0.15, 0.0, 0.4, 0.0, 0.5]),
        ([0.0; 5], [0.0; 5]),
        ([0.5, 0.3, 0.1, 0.05, 0.0], [0.2, 0.4, 0.2, 0.16, 0.0]),
    ];
    for exponential in [false, true] {
        let mut opts = StrengthOptions {
            cf: Cf::Constant(17.0),
            ..Default::default()
        };
        if !exponential {
            opts.redistribution = pressridge::itd::details::Redistribution::Uniform;
        }
        let k = StrengthConsts::new(&opts).expect("Rothrock with a constant C_f");
        let mut ws = Workspace::new(5);
        let mut got = Vec::new();
        // SAFETY: glibc's feenableexcept/fedisableexcept change this thread's FP control word
        // only; the traps are switched off again before the asserts.
        unsafe { feenableexcept(TRAPS) };
        for (a, v) in &columns {
            let fast = strength_column_constant_cf(a, v, None, &opts, &k).unwrap();
            let full = strength_column(a, v, None, &opts, &mut ws).unwrap();
            got.push((fast.strength, full.strength));
        }
        // SAFETY: as above.
        unsafe { fedisableexcept(TRAPS) };
        for (fast, full) in got {
            assert!(fast.is_finite() && fast >= 0.0);
            assert_eq!(
                fast.to_bits(),
                full.to_bits(),
                "the fast path is the full one"
            );
        }
    }
}
