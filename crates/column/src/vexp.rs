//! e^x of several arguments at once, with the bits of the platform's `exp`.
//!
//! The exponential participation (Lipscomb et al. 2007, `docs/strength.md`) takes one
//! e^{−G/a*} per category boundary of every column. Icepack calls the C library's `exp` for
//! each, and pressridge gives Icepack's bits, so it must give that `exp`'s bits too. glibc
//! (≥ 2.28) computes `exp` on x86-64 CPUs with FMA by the table-driven algorithm of ARM's
//! optimized-routines (Szabolcs Nagy; MIT OR Apache-2.0 WITH LLVM-exception): with N = 128,
//! x = k·ln2/N + r, |r| ≤ ln2/(2N), and e^x = 2^(k/N)·(1 + tail_k)·e^r, 2^(k/N) and its
//! rounding error tail_k from a table, e^r − 1 from a degree-5 polynomial, and fused
//! multiply-adds exactly where glibc's build fuses them (read from its object code). This
//! module evaluates the same operations for four arguments at a time (AVX2 and FMA), which
//! costs a fraction of a scalar call each. No crate offers a vector exp with glibc's bits
//! (SLEEF and the others round differently), hence our own, kept to this one use.
//!
//! It is used only where it gives the same bits as `f64::exp`: on first use, on an x86-64 CPU
//! with AVX2 and FMA, it is compared with `f64::exp` on 1024 arguments that reach every table
//! entry. On any difference (another C library, glibc's variant for CPUs without FMA) and on
//! other CPUs every argument goes to `f64::exp`. Arguments outside the algorithm's main range
//! (|x| ≥ 512, NaN, ±∞) always do; |x| < 2⁻⁵⁴ gives 1 + x, as glibc does.

// Elsewhere than x86-64 only the scalar path is compiled in.
#![cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]

use std::sync::atomic::{AtomicU8, Ordering};

/// log2 of the table size N.
const TABLE_BITS: u32 = 7;
/// Table size N.
const N: usize = 1 << TABLE_BITS;
/// N/ln 2.
const INV_LN2_N: f64 = f64::from_bits(0x4067_1547_652b_82fe);
/// −ln 2/N, leading part (trailing bits zero, so k·it is exact).
const NEG_LN2_HI_N: f64 = f64::from_bits(0xbf76_2e42_fefa_0000);
/// −ln 2/N, trailing part.
const NEG_LN2_LO_N: f64 = f64::from_bits(0xbd0c_f79a_bc9e_3b3a);
/// Polynomial e^r − 1 ≈ r + C2·r² + C3·r³ + C4·r⁴ + C5·r⁵ (the algorithm's minimax fit).
const C2: f64 = f64::from_bits(0x3fdf_ffff_ffff_fdbd);
const C3: f64 = f64::from_bits(0x3fc5_5555_5555_543c);
const C4: f64 = f64::from_bits(0x3fa5_5555_cf17_2b91);
const C5: f64 = f64::from_bits(0x3f81_1111_67a4_d017);
/// 1.5·2⁵²: adding it rounds N·x/ln 2 to an integer held in the low bits.
const SHIFT: f64 = f64::from_bits(0x4338_0000_0000_0000);

/// The exponent field of |x| below which e^x is 1 + x (|x| < 2⁻⁵⁴) and from which the main
/// path does not apply (|x| ≥ 512).
const TOP_TINY: u64 = 0x3c9;
const TOP_LARGE: u64 = 0x408;

const UNKNOWN: u8 = 0;
const SCALAR: u8 = 1;
const FUSED: u8 = 2;
static MODE: AtomicU8 = AtomicU8::new(UNKNOWN);

/// Replaces every element of `x` by e^x, bit for bit as `f64::exp` gives it.
#[inline]
pub(crate) fn exp_in_place(x: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if fused() {
        // SAFETY: `fused()` holds only on a CPU with AVX2 and FMA.
        unsafe { exp_fused(x) };
        return;
    }
    for v in x {
        *v = v.exp();
    }
}

/// Whether [`exp_in_place`] uses the four-lane evaluation on this machine.
pub(crate) fn fused() -> bool {
    match MODE.load(Ordering::Relaxed) {
        FUSED => true,
        SCALAR => false,
        _ => {
            let ok = fused_agrees();
            MODE.store(if ok { FUSED } else { SCALAR }, Ordering::Relaxed);
            ok
        }
    }
}

/// The CPU has AVX2 and FMA and the four-lane evaluation gives `f64::exp`'s bits on 1024
/// arguments in [−40, 5] that reach every table entry, and on a few at the edges of its
/// range.
fn fused_agrees() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        if !(std::arch::is_x86_feature_detected!("avx2")
            && std::arch::is_x86_feature_detected!("fma"))
        {
            return false;
        }
        let golden = 0.618_033_988_749_894_9_f64;
        let mut x: Vec<f64> = (0..1024)
            .map(|i| -40.0 + 45.0 * (i as f64 * golden).fract())
            .collect();
        x.extend([
            0.0, -0.0, 1e-17, -1e-17, 5.6e-17, 511.9, -511.9, 600.0, -800.0,
        ]);
        let mut y = x.clone();
        // SAFETY: AVX2 and FMA checked above.
        unsafe { exp_fused(&mut y) };
        x.iter()
            .zip(&y)
            .all(|(a, b)| a.exp().to_bits() == b.to_bits())
    }
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// Four lanes at a time; a lane outside the main range is finished by [`lane_outside`].
/// Called through [`exp_in_place`]; the batch kernel's AVX2+FMA build
/// (`lanes::dispatch_avx2_fma`) is the one caller that may inline it.
///
/// # Safety
/// The CPU must have AVX2 and FMA (callers check with `is_x86_feature_detected!`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
unsafe fn exp_fused(x: &mut [f64]) {
    let mut chunks = x.chunks_exact_mut(4);
    for c in &mut chunks {
        let y = exp4([c[0], c[1], c[2], c[3]]);
        c.copy_from_slice(&y);
    }
    let rest = chunks.into_remainder();
    if !rest.is_empty() {
        let mut lanes = [-1.0; 4];
        lanes[..rest.len()].copy_from_slice(rest);
        let y = exp4(lanes);
        let n = rest.len();
        rest.copy_from_slice(&y[..n]);
    }
}

/// e^x of four arguments: the main path in every lane (branch-free), then the lanes outside
/// its range again. Compiled only inside [`exp_fused`] (with FMA).
#[inline(always)]
fn exp4(x: [f64; 4]) -> [f64; 4] {
    let mut y = [0.0; 4];
    let mut outside = false;
    for l in 0..4 {
        let top = (x[l].to_bits() >> 52) & 0x7ff;
        outside |= !(TOP_TINY..TOP_LARGE).contains(&top);
        y[l] = main_path(x[l]);
    }
    if outside {
        for l in 0..4 {
            let top = (x[l].to_bits() >> 52) & 0x7ff;
            if !(TOP_TINY..TOP_LARGE).contains(&top) {
                y[l] = lane_outside(x[l], top);
            }
        }
    }
    y
}

/// glibc's main path for 2⁻⁵⁴ ≤ |x| < 512, with its fused multiply-adds (`mul_add` is a
/// single rounding on every target, so the bits do not depend on the vectorisation).
#[inline(always)]
fn main_path(x: f64) -> f64 {
    let kd = x.mul_add(INV_LN2_N, SHIFT);
    let ki = kd.to_bits();
    let kd = kd - SHIFT;
    let r = kd.mul_add(NEG_LN2_HI_N, x);
    let r = kd.mul_add(NEG_LN2_LO_N, r);
    let idx = 2 * (ki as usize % N);
    let top = ki << (52 - TABLE_BITS);
    let tail = f64::from_bits(TABLE[idx]);
    let scale = f64::from_bits(TABLE[idx + 1].wrapping_add(top));
    let r2 = r * r;
    let tmp = (r2 * r2).mul_add(r.mul_add(C5, C4), r.mul_add(C3, C2).mul_add(r2, r + tail));
    scale.mul_add(tmp, scale)
}

/// e^x outside the main path: 1 + x below 2⁻⁵⁴ (glibc's answer), the C library beyond.
#[cold]
fn lane_outside(x: f64, top: u64) -> f64 {
    if top < TOP_TINY { 1.0 + x } else { x.exp() }
}

/// 2^(k/N) for k = 0..N as the algorithm stores it: word 2k is its relative rounding error
/// tail_k, word 2k + 1 its nearest double less k·2⁴⁵ (so that adding k·2⁴⁵ of the
/// argument's integer part puts the exponent in). Computed from that definition with
/// 80-digit decimal arithmetic by `scripts/exp-table.py`, not copied.
#[rustfmt::skip]
const TABLE: [u64; 2 * N] = [
    0x0000000000000000, 0x3ff0000000000000, 0x3c9b3b4f1a88bf6e, 0x3feff63da9fb3335,
    0xbc7160139cd8dc5d, 0x3fefec9a3e778061, 0xbc905e7a108766d1, 0x3fefe315e86e7f85,
    0x3c8cd2523567f613, 0x3fefd9b0d3158574, 0xbc8bce8023f98efa, 0x3fefd06b29ddf6de,
    0x3c60f74e61e6c861, 0x3fefc74518759bc8, 0x3c90a3e45b33d399, 0x3fefbe3ecac6f383,
    0x3c979aa65d837b6d, 0x3fefb5586cf9890f, 0x3c8eb51a92fdeffc, 0x3fefac922b7247f7,
    0x3c3ebe3d702f9cd1, 0x3fefa3ec32d3d1a2, 0xbc6a033489906e0b, 0x3fef9b66affed31b,
    0xbc9556522a2fbd0e, 0x3fef9301d0125b51, 0xbc5080ef8c4eea55, 0x3fef8abdc06c31cc,
    0xbc91c923b9d5f416, 0x3fef829aaea92de0, 0x3c80d3e3e95c55af, 0x3fef7a98c8a58e51,
    0xbc801b15eaa59348, 0x3fef72b83c7d517b, 0xbc8f1ff055de323d, 0x3fef6af9388c8dea,
    0x3c8b898c3f1353bf, 0x3fef635beb6fcb75, 0xbc96d99c7611eb26, 0x3fef5be084045cd4,
    0x3c9aecf73e3a2f60, 0x3fef54873168b9aa, 0xbc8fe782cb86389d, 0x3fef4d5022fcd91d,
    0x3c8a6f4144a6c38d, 0x3fef463b88628cd6, 0x3c807a05b0e4047d, 0x3fef3f49917ddc96,
    0x3c968efde3a8a894, 0x3fef387a6e756238, 0x3c875e18f274487d, 0x3fef31ce4fb2a63f,
    0x3c80472b981fe7f2, 0x3fef2b4565e27cdd, 0xbc96b87b3f71085e, 0x3fef24dfe1f56381,
    0x3c82f7e16d09ab31, 0x3fef1e9df51fdee1, 0xbc3d219b1a6fbffa, 0x3fef187fd0dad990,
    0x3c8b3782720c0ab4, 0x3fef1285a6e4030b, 0x3c6e149289cecb8f, 0x3fef0cafa93e2f56,
    0x3c834d754db0abb6, 0x3fef06fe0a31b715, 0x3c864201e2ac744c, 0x3fef0170fc4cd831,
    0x3c8fdd395dd3f84a, 0x3feefc08b26416ff, 0xbc86a3803b8e5b04, 0x3feef6c55f929ff1,
    0xbc924aedcc4b5068, 0x3feef1a7373aa9cb, 0xbc9907f81b512d8e, 0x3feeecae6d05d866,
    0xbc71d1e83e9436d2, 0x3feee7db34e59ff7, 0xbc991919b3ce1b15, 0x3feee32dc313a8e5,
    0x3c859f48a72a4c6d, 0x3feedea64c123422, 0xbc9312607a28698a, 0x3feeda4504ac801c,
    0xbc58a78f4817895b, 0x3feed60a21f72e2a, 0xbc7c2c9b67499a1b, 0x3feed1f5d950a897,
    0x3c4363ed60c2ac11, 0x3feece086061892d, 0x3c9666093b0664ef, 0x3feeca41ed1d0057,
    0x3c6ecce1daa10379, 0x3feec6a2b5c13cd0, 0x3c93ff8e3f0f1230, 0x3feec32af0d7d3de,
    0x3c7690cebb7aafb0, 0x3feebfdad5362a27, 0x3c931dbdeb54e077, 0x3feebcb299fddd0d,
    0xbc8f94340071a38e, 0x3feeb9b2769d2ca7, 0xbc87deccdc93a349, 0x3feeb6daa2cf6642,
    0xbc78dec6bd0f385f, 0x3feeb42b569d4f82, 0xbc861246ec7b5cf6, 0x3feeb1a4ca5d920f,
    0x3c93350518fdd78e, 0x3feeaf4736b527da, 0x3c7b98b72f8a9b05, 0x3feead12d497c7fd,
    0x3c9063e1e21c5409, 0x3feeab07dd485429, 0x3c34c7855019c6ea, 0x3feea9268a5946b7,
    0x3c9432e62b64c035, 0x3feea76f15ad2148, 0xbc8ce44a6199769f, 0x3feea5e1b976dc09,
    0xbc8c33c53bef4da8, 0x3feea47eb03a5585, 0xbc845378892be9ae, 0x3feea34634ccc320,
    0xbc93cedd78565858, 0x3feea23882552225, 0x3c5710aa807e1964, 0x3feea155d44ca973,
    0xbc93b3efbf5e2228, 0x3feea09e667f3bcd, 0xbc6a12ad8734b982, 0x3feea012750bdabf,
    0xbc6367efb86da9ee, 0x3fee9fb23c651a2f, 0xbc80dc3d54e08851, 0x3fee9f7df9519484,
    0xbc781f647e5a3ecf, 0x3fee9f75e8ec5f74, 0xbc86ee4ac08b7db0, 0x3fee9f9a48a58174,
    0xbc8619321e55e68a, 0x3fee9feb564267c9, 0x3c909ccb5e09d4d3, 0x3feea0694fde5d3f,
    0xbc7b32dcb94da51d, 0x3feea11473eb0187, 0x3c94ecfd5467c06b, 0x3feea1ed0130c132,
    0x3c65ebe1abd66c55, 0x3feea2f336cf4e62, 0xbc88a1c52fb3cf42, 0x3feea427543e1a12,
    0xbc9369b6f13b3734, 0x3feea589994cce13, 0xbc805e843a19ff1e, 0x3feea71a4623c7ad,
    0xbc94d450d872576e, 0x3feea8d99b4492ed, 0x3c90ad675b0e8a00, 0x3feeaac7d98a6699,
    0x3c8db72fc1f0eab4, 0x3feeace5422aa0db, 0xbc65b6609cc5e7ff, 0x3feeaf3216b5448c,
    0x3c7bf68359f35f44, 0x3feeb1ae99157736, 0xbc93091fa71e3d83, 0x3feeb45b0b91ffc6,
    0xbc5da9b88b6c1e29, 0x3feeb737b0cdc5e5, 0xbc6c23f97c90b959, 0x3feeba44cbc8520f,
    0xbc92434322f4f9aa, 0x3feebd829fde4e50, 0xbc85ca6cd7668e4b, 0x3feec0f170ca07ba,
    0x3c71affc2b91ce27, 0x3feec49182a3f090, 0x3c6dd235e10a73bb, 0x3feec86319e32323,
    0xbc87c50422622263, 0x3feecc667b5de565, 0x3c8b1c86e3e231d5, 0x3feed09bec4a2d33,
    0xbc91bbd1d3bcbb15, 0x3feed503b23e255d, 0x3c90cc319cee31d2, 0x3feed99e1330b358,
    0x3c8469846e735ab3, 0x3feede6b5579fdbf, 0xbc82dfcd978e9db4, 0x3feee36bbfd3f37a,
    0x3c8c1a7792cb3387, 0x3feee89f995ad3ad, 0xbc907b8f4ad1d9fa, 0x3feeee07298db666,
    0xbc55c3d956dcaeba, 0x3feef3a2b84f15fb, 0xbc90a40e3da6f640, 0x3feef9728de5593a,
    0xbc68d6f438ad9334, 0x3feeff76f2fb5e47, 0xbc91eee26b588a35, 0x3fef05b030a1064a,
    0x3c74ffd70a5fddcd, 0x3fef0c1e904bc1d2, 0xbc91bdfbfa9298ac, 0x3fef12c25bd71e09,
    0x3c736eae30af0cb3, 0x3fef199bdd85529c, 0x3c8ee3325c9ffd94, 0x3fef20ab5fffd07a,
    0x3c84e08fd10959ac, 0x3fef27f12e57d14b, 0x3c63cdaf384e1a67, 0x3fef2f6d9406e7b5,
    0x3c676b2c6c921968, 0x3fef3720dcef9069, 0xbc808a1883ccb5d2, 0x3fef3f0b555dc3fa,
    0xbc8fad5d3ffffa6f, 0x3fef472d4a07897c, 0xbc900dae3875a949, 0x3fef4f87080d89f2,
    0x3c74a385a63d07a7, 0x3fef5818dcfba487, 0xbc82919e2040220f, 0x3fef60e316c98398,
    0x3c8e5a50d5c192ac, 0x3fef69e603db3285, 0x3c843a59ac016b4b, 0x3fef7321f301b460,
    0xbc82d52107b43e1f, 0x3fef7c97337b9b5f, 0xbc892ab93b470dc9, 0x3fef864614f5a129,
    0x3c74b604603a88d3, 0x3fef902ee78b3ff6, 0x3c83c5ec519d7271, 0x3fef9a51fbc74c83,
    0xbc8ff7128fd391f0, 0x3fefa4afa2a490da, 0xbc8dae98e223747d, 0x3fefaf482d8e67f1,
    0x3c8ec3bc41aa2008, 0x3fefba1bee615a27, 0x3c842b94c3a9eb32, 0x3fefc52b376bba97,
    0x3c8a64a931d185ee, 0x3fefd0765b6e4540, 0xbc8e37bae43be3ed, 0x3fefdbfdad9cbe14,
    0x3c77893b4d91cd9d, 0x3fefe7c1819e90d8, 0x3c5305c14160cc89, 0x3feff3c22b8f71f1,
];

#[cfg(test)]
mod tests {
    use super::*;

    /// A fixed 64-bit generator (SplitMix64), uniform in [0, 1).
    fn uniform(state: &mut u64) -> f64 {
        *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    #[test]
    fn vexp_is_the_platform_exp_bit_for_bit() {
        // On x86-64 Linux with glibc (≥ 2.28) and a CPU with FMA the four-lane path must be
        // the one in use; elsewhere the check below compares f64::exp with itself.
        #[cfg(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu"))]
        if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
        {
            assert!(
                fused(),
                "the four-lane exp disagrees with glibc's exp on this machine"
            );
        }
        let mut s = 7u64;
        let mut x: Vec<f64> = Vec::new();
        // The participation's range, densely; the whole finite range; the edges.
        x.extend((0..1_000_000).map(|_| -25.0 * uniform(&mut s)));
        x.extend((0..200_000).map(|_| -745.2 + 1455.0 * uniform(&mut s)));
        x.extend((0..20_000).map(|_| (uniform(&mut s) - 0.5) * 1e-15));
        x.extend([
            0.0,
            -0.0,
            5.55e-17,
            -5.55e-17,
            1e-300,
            -1e-300,
            511.999,
            -511.999,
            512.0,
            -512.0,
            709.78,
            709.79,
            -708.4,
            -745.13,
            -746.0,
            1000.0,
            -1000.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
        ]);
        // Every chunk length, so the remainder lanes are checked too.
        for len in [x.len(), 1, 2, 3, 5, 6, 7] {
            let mut y = x[..len].to_vec();
            exp_in_place(&mut y);
            for (a, b) in x[..len].iter().zip(&y) {
                assert_eq!(
                    a.exp().to_bits(),
                    b.to_bits(),
                    "exp({a:e}): {b:e} against {:e}",
                    a.exp()
                );
            }
        }
        let mut nan = [f64::NAN, -1.0, f64::NAN, 1.0, f64::NAN];
        exp_in_place(&mut nan);
        assert!(nan[0].is_nan() && nan[2].is_nan() && nan[4].is_nan());
        assert_eq!(nan[1], (-1.0f64).exp());
    }
}
