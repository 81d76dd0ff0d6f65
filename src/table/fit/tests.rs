use super::*;
use rand_xoshiro::Xoshiro256PlusPlus;
use rand_xoshiro::rand_core::{Rng, SeedableRng};

/// Uniform on (0, 1].
fn uniform(rng: &mut Xoshiro256PlusPlus) -> f64 {
    ((rng.next_u64() >> 11) + 1) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// Standard normal by Box–Muller.
fn normal(rng: &mut Xoshiro256PlusPlus) -> f64 {
    let (u1, u2) = (uniform(rng), uniform(rng));
    (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
}

fn rel(x: f64, y: f64) -> f64 {
    (x - y).abs() / y.abs()
}

/// Ridged volumes of one run sampled every 25 s: V = U·h·t, U = 0.05 m/s, h = 0.5 m.
fn sample_volumes(n: usize) -> Vec<f64> {
    (1..=n).map(|i| 0.05 * 0.5 * 25.0 * i as f64).collect()
}

#[test]
fn exact_recovery_on_noiseless_data() {
    // Realistic magnitudes (a ~ 1e3 J/m⁵, b ~ 1e4 J/m³) and wildly rescaled V.
    for (scale, a, b) in [
        (1.0, 1.8e3, 2.4e4),
        (1e-4, 7.0e9, -3.0e2),
        (1e4, 2.5e-5, 1.0e3),
        // Extreme units (terms of comparable size): the scaling must keep all finite.
        (1e100, 3e-100, 5.0),
        (1e-100, 3e100, 5.0),
    ] {
        let v: Vec<f64> = sample_volumes(40).iter().map(|x| x * scale).collect();
        let y: Vec<f64> = v.iter().map(|&x| x * (a * x + b)).collect();
        let fit = fit_through_origin(&v, &y).unwrap();
        assert!(rel(fit.a, a) < 1e-10, "a {} vs {a}", fit.a);
        assert!(rel(fit.b, b) < 1e-10, "b {} vs {b}", fit.b);
        assert_eq!((fit.n, fit.dof), (40, 38));
        assert!(fit.r_squared > 1.0 - 1e-12);
        let ymax = y.iter().fold(0.0_f64, |m, &e| m.max(e.abs()));
        assert!(fit.residual_variance.sqrt() < 1e-12 * ymax);
    }
    // Negative and positive V mixed (the basis is still independent).
    let v = [-2.0, -0.5, 1.0, 3.0];
    let y: Vec<f64> = v.iter().map(|&x| x * (0.3 * x - 4.0)).collect();
    let fit = fit_through_origin(&v, &y).unwrap();
    assert!(rel(fit.a, 0.3) < 1e-12 && rel(fit.b, -4.0) < 1e-12);
}

#[test]
fn matches_hand_computed_normal_equations_on_four_points() {
    // V = 1..4, y = (3, 9, 20, 33). By hand:
    //   ΣV⁴ = 354, ΣV³ = 100, ΣV² = 30, ΣV²y = 747, ΣVy = 213,
    //   det = 354·30 − 100² = 620,
    //   a = (30·747 − 100·213)/620 = 1110/620 = 111/62,
    //   b = (354·213 − 100·747)/620 = 702/620 = 351/310,
    //   residuals = (12, −66, 76, −27)/155, RSS = 71/155, s² = RSS/2 = 71/310,
    //   (XᵀX)⁻¹ = [[30, −100], [−100, 354]]/620,
    //   uncentred R² = 1 − (71/155)/Σy² = 1 − (71/155)/1579.
    let v = [1.0, 2.0, 3.0, 4.0];
    let y = [3.0, 9.0, 20.0, 33.0];
    let fit = fit_through_origin(&v, &y).unwrap();
    assert!(rel(fit.a, 111.0 / 62.0) < 1e-13);
    assert!(rel(fit.b, 351.0 / 310.0) < 1e-13);
    let s2 = 71.0 / 310.0;
    assert!(rel(fit.residual_variance, s2) < 1e-12);
    assert_eq!((fit.n, fit.dof), (4, 2));
    let inv = [
        [30.0 / 620.0, -100.0 / 620.0],
        [-100.0 / 620.0, 354.0 / 620.0],
    ];
    for (j, k) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        assert!(rel(fit.xtx_inv[j][k], inv[j][k]) < 1e-12);
        assert!(rel(fit.cov[j][k], s2 * inv[j][k]) < 1e-12);
    }
    assert!(rel(fit.r_squared, 1.0 - (71.0 / 155.0) / 1579.0) < 1e-14);
    let se = fit.standard_errors();
    assert!(rel(se[0], (s2 * 30.0 / 620.0).sqrt()) < 1e-12);
    // Bands at V = 2.5 by hand: g = (6.25, 2.5), gᵀ(XᵀX)⁻¹g = (30·39.0625 −
    // 2·100·15.625 + 354·6.25)/620 = 259.375/620; t_{0.975,2} = 4.302652729911275.
    let t = 4.302_652_729_911_275;
    let c = 2.5 * (2.5 * 111.0 / 62.0 + 351.0 / 310.0);
    let hm = t * (s2 * 259.375 / 620.0).sqrt();
    let hp = t * (s2 * (1.0 + 259.375 / 620.0)).sqrt();
    let (lo, hi) = fit.confidence_band(2.5, 0.95);
    assert!(rel(lo, c - hm) < 1e-10 && rel(hi, c + hm) < 1e-10);
    let (lo, hi) = fit.prediction_band(2.5, 0.95);
    assert!(rel(lo, c - hp) < 1e-10 && rel(hi, c + hp) < 1e-10);
}

#[test]
fn bad_input_is_rejected_with_the_right_error() {
    let ok = [1.0, 2.0, 3.0];
    assert_eq!(
        fit_through_origin(&ok, &[1.0, 2.0]),
        Err(FitError::LengthMismatch { left: 3, right: 2 })
    );
    assert_eq!(
        fit_through_origin(&[1.0, 2.0], &[1.0, 2.0]),
        Err(FitError::TooFewPoints { n: 2 })
    );
    assert_eq!(
        fit_through_origin(&[], &[]),
        Err(FitError::TooFewPoints { n: 0 })
    );
    assert_eq!(
        fit_through_origin(&[1.0, f64::NAN, 3.0], &ok),
        Err(FitError::NonFinite {
            which: "V",
            index: 1
        })
    );
    assert_eq!(
        fit_through_origin(&ok, &[1.0, 2.0, f64::INFINITY]),
        Err(FitError::NonFinite {
            which: "y",
            index: 2
        })
    );
    assert_eq!(
        fit_through_origin(&[2.0, 2.0, 2.0], &ok),
        Err(FitError::AllVEqual { value: 2.0 })
    );
    assert_eq!(
        fit_through_origin(&[0.0; 3], &ok),
        Err(FitError::AllVEqual { value: 0.0 })
    );
    // One distinct non-zero V: V² = 5·V on every sample.
    assert!(matches!(
        fit_through_origin(&[0.0, 5.0, 0.0, 5.0], &[0.0, 1.0, 0.0, 1.1]),
        Err(FitError::RankDeficient { .. })
    ));
    assert!(data_ratio(&[1.0], &[1.0, 2.0]).is_err());
}

/// Simulates `reps` data sets `y = V(aV + b) + σε` on `n` samples and counts how often
/// the 95 % intervals cover the truth: [a, b, mean curve at V₀, fresh observation].
fn coverage(n: usize, reps: u64, seed: u64) -> [f64; 4] {
    let (a, b, sigma) = (1.8e3, 2.4e4, 300.0);
    let v = sample_volumes(n);
    let v0 = v[n / 3];
    let vmax = v[n - 1];
    let mut hits = [0u32; 4];
    let mut y = vec![0.0; n];
    for r in 0..reps {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed + r);
        for (yi, &vi) in y.iter_mut().zip(&v) {
            *yi = vi * (a * vi + b) + sigma * normal(&mut rng);
        }
        let fit = fit_through_origin(&v, &y).unwrap();
        let [ia, ib] = fit.coefficient_intervals(0.95);
        hits[0] += u32::from(ia.0 <= a && a <= ia.1);
        hits[1] += u32::from(ib.0 <= b && b <= ib.1);
        let (lo, hi) = fit.confidence_band(v0, 0.95);
        let truth = v0 * (a * v0 + b);
        hits[2] += u32::from(lo <= truth && truth <= hi);
        let vn = vmax * uniform(&mut rng);
        let yn = vn * (a * vn + b) + sigma * normal(&mut rng);
        let (lo, hi) = fit.prediction_band(vn, 0.95);
        hits[3] += u32::from(lo <= yn && yn <= hi);
    }
    hits.map(|h| f64::from(h) / reps as f64)
}

#[test]
fn noisy_data_true_coefficients_lie_in_their_intervals() {
    let (a, b) = (1.8e3, 2.4e4);
    let v = sample_volumes(60);
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
    let y: Vec<f64> = v
        .iter()
        .map(|&x| x * (a * x + b) + 300.0 * normal(&mut rng))
        .collect();
    let fit = fit_through_origin(&v, &y).unwrap();
    let [ia, ib] = fit.coefficient_intervals(0.95);
    assert!(ia.0 <= a && a <= ia.1, "{ia:?}");
    assert!(ib.0 <= b && b <= ib.1, "{ib:?}");
    // The estimate is informative: intervals are narrow relative to the values.
    assert!(ia.1 - ia.0 < 0.1 * a && ib.1 - ib.0 < 0.5 * b);
    // The residual variance estimates σ² = 9e4 within sampling error (χ²₅₈).
    assert!((fit.residual_variance / 9e4 - 1.0).abs() < 0.4);
}

#[test]
fn intervals_have_nominal_coverage_with_few_points() {
    // n = 6 (4 dof), 400 replicates: a normal quantile in place of t gives ~0.88, a
    // confidence band used for prediction far less.
    let c = coverage(6, 400, 1000);
    for (name, x) in ["a", "b", "mean curve", "new observation"].iter().zip(c) {
        assert!((0.92..=0.98).contains(&x), "{name}: coverage {x}");
    }
    // Sharper: n = 4 (2 dof), 4000 replicates (binomial sd 0.0034), window ±3 sd.
    // Here the normal quantile gives ~0.81 and s² = RSS/n gives ~0.91.
    let c = coverage(4, 4000, 20_000);
    for (name, x) in ["a", "b", "mean curve", "new observation"].iter().zip(c) {
        assert!((0.94..=0.96).contains(&x), "n = 4, {name}: coverage {x}");
    }
}

#[test]
fn intervals_have_nominal_coverage_with_many_points() {
    let c = coverage(40, 400, 5000);
    for (name, x) in ["a", "b", "mean curve", "new observation"].iter().zip(c) {
        assert!((0.92..=0.98).contains(&x), "{name}: coverage {x}");
    }
}

#[test]
fn prediction_band_is_wider_than_confidence_band() {
    let v = [1.0, 2.0, 3.0, 4.0];
    let fit = fit_through_origin(&v, &[3.0, 9.0, 20.0, 33.0]).unwrap();
    let band = Band::linspace(&fit, 0.0, 5.0, 11, 0.95);
    assert_eq!(band.v.len(), 11);
    assert_eq!((band.v[0], band.v[10]), (0.0, 5.0));
    assert!((band.v[3] - 1.5).abs() < 1e-15);
    for i in 0..11 {
        let x = band.v[i];
        assert_eq!(band.fit[i], fit.eval(x));
        assert!(band.pred_lo[i] < band.conf_lo[i] || x == 0.0);
        assert!(band.conf_lo[i] <= band.fit[i] && band.fit[i] <= band.conf_hi[i]);
        assert!(band.conf_hi[i] < band.pred_hi[i]);
        assert_eq!(
            (band.conf_lo[i], band.conf_hi[i]),
            fit.confidence_band(x, 0.95)
        );
        assert_eq!(
            (band.pred_lo[i], band.pred_hi[i]),
            fit.prediction_band(x, 0.95)
        );
    }
    // The curve passes through the origin exactly: no mean uncertainty there.
    assert_eq!((band.conf_lo[0], band.conf_hi[0]), (0.0, 0.0));
}

#[test]
fn force_is_thickness_times_work_derivative() {
    let (a, b, h) = (1.8e3, 2.4e4, 0.5);
    let v = sample_volumes(20);
    let y: Vec<f64> = v.iter().map(|&x| x * (a * x + b)).collect();
    let fit = fit_through_origin(&v, &y).unwrap();
    for x in [0.0, 1.0, 7.5] {
        // Eq (15), and the central difference h·ΔW/ΔV (exact for a quadratic).
        assert!(rel(force(&fit, h, x), h * (2.0 * a * x + b)) < 1e-10);
        let d = 1e-2;
        let fd = h * (fit.eval(x + d) - fit.eval(x - d)) / (2.0 * d);
        assert!(rel(force(&fit, h, x), fd) < 1e-8);
    }
    // Noiseless data: no uncertainty.
    assert!(force_std_error(&fit, h, 3.0) < 1e-6 * force(&fit, h, 3.0));
    // Hand example: se(F) at V = 2.5, h = 0.3 = 0.3·sqrt(s²·gᵀ(XᵀX)⁻¹g), g = (5, 1).
    let fit = fit_through_origin(&[1.0, 2.0, 3.0, 4.0], &[3.0, 9.0, 20.0, 33.0]).unwrap();
    let q: f64 = (30.0 * 25.0 - 2.0 * 100.0 * 5.0 + 354.0) / 620.0;
    assert!(
        rel(
            force_std_error(&fit, 0.3, 2.5),
            0.3 * (71.0 / 310.0 * q).sqrt()
        ) < 1e-12
    );
}

#[test]
fn ratios_of_fits_and_data() {
    let v = sample_volumes(30);
    let (aw, bw, ap, bp) = (1.8e3, 2.4e4, 400.0, 1.0e3);
    let w: Vec<f64> = v.iter().map(|&x| x * (aw * x + bw)).collect();
    let pe: Vec<f64> = v.iter().map(|&x| x * (ap * x + bp)).collect();
    let fw = fit_through_origin(&v, &w).unwrap();
    let fp = fit_through_origin(&v, &pe).unwrap();
    for x in [0.0, 2.0, 9.0] {
        let r16 = (2.0 * aw * x + bw) / (2.0 * ap * x + bp);
        assert!(rel(ratio(&fw, &fp, x), r16) < 1e-10);
        assert!(rel(fitted_ratio(&fw, &fp, x), (aw * x + bw) / (ap * x + bp)) < 1e-10);
    }
    assert!(rel(fitted_ratio(&fw, &fp, 0.0), bw / bp) < 1e-10);
    let dr = data_ratio(&w, &pe).unwrap();
    for (i, &x) in v.iter().enumerate() {
        assert!(rel(dr[i], fitted_ratio(&fw, &fp, x)) < 1e-10);
    }
}

#[test]
fn ratio_std_error_matches_monte_carlo_spread() {
    // W and PE share part of their noise (PE is part of the work), so the
    // cross-covariance matters; the delta-method standard error must reproduce the
    // scatter of the eq (16) ratio over replicates, and ignoring the correlation must not.
    let v = sample_volumes(40);
    let (aw, bw, ap, bp) = (1.8e3, 2.4e4, 400.0, 1.0e3);
    let x0 = 5.0;
    let reps = 2000;
    let (mut sum, mut sum2, mut se_corr, mut se_ind) = (0.0, 0.0, 0.0, 0.0);
    let (mut w, mut pe) = (vec![0.0; 40], vec![0.0; 40]);
    for r in 0..reps {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(90_000 + r);
        for i in 0..40 {
            let common = normal(&mut rng);
            let x = v[i];
            pe[i] = x * (ap * x + bp) + 60.0 * common;
            w[i] = x * (aw * x + bw) + 240.0 * common + 60.0 * normal(&mut rng);
        }
        let fw = fit_through_origin(&v, &w).unwrap();
        let fp = fit_through_origin(&v, &pe).unwrap();
        let c = cross_covariance(&v, &w, &pe, &fw, &fp).unwrap();
        let rr = ratio(&fw, &fp, x0);
        sum += rr;
        sum2 += rr * rr;
        se_corr += ratio_std_error(&fw, &fp, Some(&c), x0);
        se_ind += ratio_std_error(&fw, &fp, None, x0);
    }
    let n = reps as f64;
    let sd = (sum2 / n - (sum / n).powi(2)).sqrt();
    let (se_corr, se_ind) = (se_corr / n, se_ind / n);
    assert!(
        (se_corr / sd - 1.0).abs() < 0.1,
        "delta {se_corr} vs MC {sd}"
    );
    assert!(
        (se_ind / sd - 1.0).abs() > 0.3,
        "independent {se_ind} vs MC {sd}"
    );
}
