//! Strength, participation, redistribution and category bounds against hand-derived cases
//! (following Icepack's `ridge_itd` and `icepack_ice_strength` step by step) and invariants.

use std::sync::Arc;

use approx::assert_relative_eq;
use ndarray::{Array1, Array2};
use pressridge::itd::details::participation;
use pressridge::itd::details::{category_fractions, ridge_geometry};
use pressridge::itd::{
    CategoryBounds, Cf, ColumnError, ItdError, ItdParams, StrengthOptions, Workspace,
    category_bounds,
    details::{CfPreset, CfProvider, CfTable, Participation, Redistribution, StrengthFormula},
    strength_batch, strength_column,
};

/// C_p = g ρ_i (ρ_w − ρ_i) / (2 ρ_w) = 0.5 · 9.80616 · 109 · 917 / 1026 = 477.6584359064328 N/m³.
const CP: f64 = 477.658_435_906_432_8;

fn opts(p: Participation, r: Redistribution, cf: f64) -> StrengthOptions {
    StrengthOptions {
        participation: p,
        redistribution: r,
        cf: Cf::Constant(cf),
        ..Default::default()
    }
}

fn p_of(aicen: &[f64], vicen: &[f64], aice0: f64, o: &StrengthOptions) -> f64 {
    let mut ws = Workspace::new(aicen.len());
    strength_column(aicen, vicen, Some(aice0), o, &mut ws)
        .unwrap()
        .strength
}

#[test]
fn cp_matches_cice() {
    assert_relative_eq!(ItdParams::default().cp(), CP, max_relative = 1e-15);
}

/// One category, full cover, Thorndike participation, Hibler (1980) uniform redistribution.
///
/// aice0 = 0 (≤ puny, so G(0) = 0), a₁ = 1, v₁ = 2 m → h = 2 m, G(1) = 1.
/// Thorndike: G(0) = 0 < G* and G(1) = 1 ≥ G*, so
///   a_P1 = (1/G*)(G* − 0)(2 − (1/G*)(G* + 0)) = 1 · (2 − 1) = 1, a_P0 = 0.
/// Uniform: h_min = min(2h, h + 1) = 3 m, h_max = 2√(25·2) = 14.142135623730951 m,
///   k = (3 + 14.1421356)/2 / 2 = 4.285533905932738,
///   aksum = 1 − 1/k = 0.7666568455763152,
///   ⟨h_r²⟩ = (h_max² + h_max h_min + h_min²)/3 = (200 + 42.4264069 + 9)/3 = 83.80880229039762,
///   ⟨h_r²⟩/k − h² = 19.5562103 − 4 = 15.556210294912322.
/// P = 17 · C_p · 15.556210294912322 / 0.7666568455763152 = 164766.59284602327 N/m.
#[test]
fn one_category_thorndike_uniform_by_hand() {
    let o = opts(Participation::Thorndike, Redistribution::Uniform, 17.0);
    let p = p_of(&[1.0], &[2.0], 0.0, &o);
    let expected = 17.0 * CP * 15.556_210_294_912_322 / 0.766_656_845_576_315_2;
    assert_relative_eq!(p, expected, max_relative = 1e-13);
    assert_relative_eq!(p, 164_766.592_846_023_27, max_relative = 1e-13);
}

/// Same column, exponential (Lipscomb 2007) redistribution:
///   h_min = 3 m, λ = 3√2 = 4.242640687119286 m, k = (3 + 4.2426407)/2 = 3.621320343559643,
///   aksum = 1 − 1/k = 0.7238576250846034,
///   ⟨h_r²⟩ = 9 + 2·3·4.2426407 + 2·18 = 70.45584412271572, ⟨h_r²⟩/k − 4 = 15.45584412271571.
/// P = 17 C_p 15.45584412271571 / 0.7238576250846034 = 173382.77480039193 N/m.
#[test]
fn one_category_thorndike_exponential_by_hand() {
    let o = opts(Participation::Thorndike, Redistribution::Exponential, 17.0);
    let p = p_of(&[1.0], &[2.0], 0.0, &o);
    assert_relative_eq!(
        p,
        17.0 * CP * 15.455_844_122_715_71 / 0.723_857_625_084_603_4,
        max_relative = 1e-13
    );
}

/// Open water at or above G*: Thorndike gives a_P0 = (1/G*)·G*·(2 − 1) = 1 and nothing else
/// participates, so the net-to-gross ratio is 1 and P = 0 whatever the ice.
#[test]
fn open_water_at_or_above_gstar_gives_zero_strength() {
    for aice0 in [0.15, 0.2, 0.6] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            let o = opts(Participation::Thorndike, r, 17.0);
            let ai = 1.0 - aice0;
            let mut ws = Workspace::new(2);
            let s = strength_column(
                &[ai / 2.0, ai / 2.0],
                &[0.5 * ai, 3.0 * ai],
                Some(aice0),
                &o,
                &mut ws,
            )
            .unwrap();
            assert_eq!(s.strength, 0.0, "aice0 = {aice0}");
            assert_eq!(ws.apartic()[0], 1.0);
        }
    }
    // Just below G*, thin ice participates and P > 0.
    let o = opts(Participation::Thorndike, Redistribution::Uniform, 17.0);
    assert!(p_of(&[0.86], &[0.86], 0.14, &o) > 0.0);
}

/// Full cover, two categories, Thorndike.
/// a = (0.1, 0.9), v = (0.05, 2.7) m → h = (0.5, 3) m; G = (0, 0.1, 1).
///   a_P1 = (1/0.15)(0.1)(2 − 0.1/0.15) = 8/9,
///   a_P2 = (1/0.15)(0.15 − 0.1)(2 − (0.25/0.15)) = 1/9.
/// Exponential redistribution:
///   n=1: h_min = 1, λ = 3√0.5 = 2.121320343559643, k = 6.242640687119286,
///        ⟨h_r²⟩ = 1 + 2·2.1213203 + 2·4.5 = 14.242640687119287, term = 14.2426/6.2426 − 0.25
///        = 2.031508964068163;
///   n=2: h_min = 4, λ = 3√3 = 5.196152422706632, k = 3.0653841409022107,
///        ⟨h_r²⟩ = 16 + 8·5.1961524 + 54 = 111.56921938165306, term = 27.396488744414185.
///   Σ a_Pn·term = 8/9·2.031508964 + 1/9·27.396488744 = 4.849840050773276,
///   aksum = 8/9 (1 − 1/6.2426407) + 1/9 (1 − 1/3.0653841) = 0.8213630719912153.
/// P = 17 C_p 4.849840050773276 / 0.8213630719912153 = 47946.68833401088 N/m.
#[test]
fn full_cover_two_categories_thorndike_by_hand() {
    let mut ws = Workspace::new(2);
    let o = opts(Participation::Thorndike, Redistribution::Exponential, 17.0);
    let s = strength_column(&[0.1, 0.9], &[0.05, 2.7], Some(0.0), &o, &mut ws).unwrap();
    assert_relative_eq!(ws.apartic()[1], 8.0 / 9.0, max_relative = 1e-14);
    assert_relative_eq!(ws.apartic()[2], 1.0 / 9.0, max_relative = 1e-14);
    assert_relative_eq!(
        s.strength,
        17.0 * CP * 4.849_840_050_773_276 / 0.821_363_071_991_215_3,
        max_relative = 1e-13
    );
    // Uniform: ⟨h_r²⟩ = (7.0710678² + 7.0710678 + 1)/3 = 19.357022603955162 and
    // (17.3205081² + 4·17.3205081 + 16)/3 = 128.42734410091836, k = 8.0710678, 3.5534180;
    // Σ = 4.9253886166301175, aksum = 0.8585984522786653 → P = 46581.8545122236 N/m.
    let o = opts(Participation::Thorndike, Redistribution::Uniform, 17.0);
    let p = p_of(&[0.1, 0.9], &[0.05, 2.7], 0.0, &o);
    assert_relative_eq!(p, 46_581.854_512_223_6, max_relative = 1e-13);
}

/// CICE default options (exponential participation, exponential redistribution, C_f = 17)
/// on a five-category column, following Icepack's `ridge_itd` and `icepack_ice_strength`:
/// aice0 = 0.02, aicen = (0.08, 0.25, 0.35, 0.2, 0.1), vicen = (0.024, 0.25, 0.63, 0.6, 0.45) m,
/// h = (0.3, 1, 1.8, 3, 4.5) m.
///   G = (0.02, 0.10, 0.35, 0.70, 0.90, 1.0) (total area 1, so no rescaling),
///   a_Pn = (e^{−G(n−1)/0.05} − e^{−G(n)/0.05}) / (1 − e^{−20})
///        = (0.32967995, 0.53498476, 0.13442340, 9.1105e-4, 8.163e-7, 1.317e-8),
///   h_min = (0.6, 2, 2.8, 4, 5.5), λ = 3√h = (1.64316767, 3, 4.02492236, 5.19615242, 6.36396103),
///   k = (7.47722558, 5, 3.79162353, 3.06538414, 2.63643578),
///   aksum = a_P0 + Σ a_Pn (1 − 1/k_n) = 0.9013262031159035,
///   ⟨h_r²⟩/k − h² = (0.94404680, 5.8, 13.31743632, 27.39648874, 48.49947321),
///   Σ a_Pn·(⟨h_r²⟩/k − h²) = 1.2968622440170634.
/// P = 17 C_p 1.2968622440170634 / 0.9013262031159035 = 11683.641518099608 N/m.
#[test]
fn cice_default_five_categories_by_hand() {
    let a = [0.08, 0.25, 0.35, 0.2, 0.1];
    let v = [0.024, 0.25, 0.63, 0.6, 0.45];
    let mut ws = Workspace::new(5);
    let s = strength_column(&a, &v, Some(0.02), &StrengthOptions::default(), &mut ws).unwrap();
    assert_relative_eq!(
        ws.apartic()[0],
        0.329_679_954_643_881_9,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        ws.apartic()[1],
        0.534_984_763_901_712_5,
        max_relative = 1e-12
    );
    assert_relative_eq!(ws.krdg()[2], 3.791_623_533_055_345, max_relative = 1e-13);
    assert_relative_eq!(s.strength, 11_683.641_518_099_608, max_relative = 1e-12);
    // Thorndike + uniform on the same column: a_P = (0.24888889, 0.64, 0.11111111, 0, 0, 0),
    // aksum = 0.9182947533836463, Σ = 1.3053882686326732 → P = 11543.140345644804 N/m.
    let o = opts(Participation::Thorndike, Redistribution::Uniform, 17.0);
    assert_relative_eq!(
        p_of(&a, &v, 0.02, &o),
        11_543.140_345_644_804,
        max_relative = 1e-12
    );
}

#[test]
fn hibler_1979_by_hand() {
    // P = 2.75e4 · 1.5 · exp(−20 · (1 − 0.9)) = 41250 · e^{−2} = 5582.588... N/m.
    let o = StrengthOptions {
        formula: StrengthFormula::Hibler1979,
        ..Default::default()
    };
    let p = p_of(&[0.4, 0.5], &[0.5, 1.0], 0.1, &o);
    assert_relative_eq!(p, 41_250.0 * (-2.0f64).exp(), max_relative = 1e-14);
}

#[test]
fn cf_presets_scale_rothrock_strength() {
    let a = [0.08, 0.25, 0.35, 0.2, 0.1];
    let v = [0.024, 0.25, 0.63, 0.6, 0.45];
    let base = p_of(
        &a,
        &v,
        0.02,
        &opts(Participation::Exponential, Redistribution::Exponential, 1.0),
    );
    for (preset, c) in [
        (CfPreset::Hibler1980, 2.0),
        (CfPreset::Flato1991, 15.0),
        (CfPreset::Cice, 17.0),
    ] {
        let o = StrengthOptions {
            cf: preset.into(),
            ..Default::default()
        };
        assert_relative_eq!(p_of(&a, &v, 0.02, &o), c * base, max_relative = 1e-13);
    }
}

#[test]
fn participation_sums_to_one_and_uses_normalised_cumulative_area() {
    let p = ItdParams::default();
    let a = [0.1, 0.3, 0.2];
    for kind in [Participation::Thorndike, Participation::Exponential] {
        let mut g = [0.0; 5];
        let mut ap = [0.0; 4];
        participation(kind, &p, 0.4, &a, &mut g, &mut ap);
        assert_relative_eq!(ap.iter().sum::<f64>(), 1.0, max_relative = 1e-14);
        // Doubling every area (total 2) leaves the normalised participation unchanged.
        let mut g2 = [0.0; 5];
        let mut ap2 = [0.0; 4];
        participation(kind, &p, 0.8, &[0.2, 0.6, 0.4], &mut g2, &mut ap2);
        for (x, y) in ap.iter().zip(&ap2) {
            assert_relative_eq!(x, y, max_relative = 1e-13);
        }
    }
}

#[test]
fn redistribution_fractions_sum_to_one() {
    let p = ItdParams::default();
    let h = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
    for kind in [Redistribution::Uniform, Redistribution::Exponential] {
        for hi in [0.05, 0.3, 1.0, 2.5, 6.0] {
            let g = ridge_geometry(&kind, &p, 0.5, 0.5 * hi);
            let (mut fa, mut fv) = (0.0, 0.0);
            for nr in 0..5 {
                let last = nr == 4;
                let hi_b = if last { p.big } else { h[nr + 1] };
                let (a, v) = category_fractions(&kind, &p, &g, h[nr], hi_b, last);
                assert!(a >= 0.0 && v >= 0.0);
                fa += a;
                fv += v;
            }
            assert_relative_eq!(fa, 1.0, max_relative = 1e-12);
            assert_relative_eq!(fv, 1.0, max_relative = 1e-12);
        }
    }
}

/// Strength rises with the fraction of thick ice (h = 3 m vs 0.5 m), 5% open water.
#[test]
fn strength_rises_with_thick_ice_fraction() {
    for p in [Participation::Thorndike, Participation::Exponential] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            let o = opts(p, r, 17.0);
            let mut last = -1.0;
            for i in 0..=19 {
                let thick = 0.95 * i as f64 / 19.0;
                let thin = f64::max(0.95 - thick, 0.0);
                let s = p_of(&[thin, thick], &[0.5 * thin, 3.0 * thick], 0.05, &o);
                assert!(
                    s >= last,
                    "{p:?}/{r:?}: P fell from {last} to {s} at thick fraction {thick}"
                );
                last = s;
            }
            assert!(last > 0.0);
        }
    }
}

#[test]
fn no_nan_for_valid_columns() {
    let cases: &[(&[f64], &[f64], f64)] = &[
        (&[0.0, 0.0, 0.0], &[0.0, 0.0, 0.0], 1.0), // open water only
        (&[0.0, 0.0, 0.0], &[0.0, 0.0, 0.0], 0.0), // empty: defined as 0 (CICE: 0/0)
        (&[1.0, 0.0, 0.0], &[0.0, 0.0, 0.0], 0.0), // ice of zero thickness
        (&[1e-12, 0.0, 0.0], &[1e-12, 0.0, 0.0], 1.0), // area below puny
        (&[0.0, 0.0, 1.0], &[0.0, 0.0, 50.0], 0.0), // very thick ice
        (&[0.3, 0.3, 0.4], &[1e-9, 0.3, 0.8], 0.0),
    ];
    for p in [Participation::Thorndike, Participation::Exponential] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            for f in [StrengthFormula::Rothrock, StrengthFormula::Hibler1979] {
                let o = StrengthOptions {
                    participation: p,
                    redistribution: r,
                    formula: f,
                    ..Default::default()
                };
                for (a, v, a0) in cases {
                    let s = p_of(a, v, *a0, &o);
                    assert!(
                        s.is_finite() && s >= 0.0,
                        "{p:?}/{r:?}/{f:?} {a:?} {v:?}: {s}"
                    );
                }
            }
        }
    }
    assert_eq!(
        p_of(&[0.0; 3], &[0.0; 3], 0.0, &StrengthOptions::default()),
        0.0
    );
}

#[test]
fn bad_input_names_variable_and_column() {
    let o = StrengthOptions::default();
    let aicen = Array2::from_shape_vec((2, 3), vec![0.5, 0.5, 0.5, 0.5, f64::NAN, 0.5]).unwrap();
    let vicen = Array2::from_elem((2, 3), 0.5);
    let mut out = Array1::zeros(3);
    let e = strength_batch(aicen.view(), vicen.view(), None, &o, out.view_mut()).unwrap_err();
    assert!(matches!(
        e,
        ItdError::Column {
            column: 1,
            source: ColumnError::NotFinite {
                var: "aicen",
                category: Some(1),
                ..
            }
        }
    ));
    assert!(e.to_string().contains("column 1") && e.to_string().contains("aicen[category 1]"));

    let aicen = Array2::from_elem((2, 3), 0.4);
    let mut vicen = Array2::from_elem((2, 3), 0.5);
    vicen[[0, 2]] = -0.1;
    let e = strength_batch(aicen.view(), vicen.view(), None, &o, out.view_mut()).unwrap_err();
    assert!(matches!(
        e,
        ItdError::Column {
            column: 2,
            source: ColumnError::Negative {
                var: "vicen",
                category: Some(0),
                ..
            }
        }
    ));

    // Area sum that no ridging step could leave: aice0 + Σ aicen = 1.3.
    let vicen = Array2::from_elem((2, 3), 0.5);
    let aice0 = Array1::from_elem(3, 0.5);
    let e = strength_batch(
        aicen.view(),
        vicen.view(),
        Some(aice0.view()),
        &o,
        out.view_mut(),
    )
    .unwrap_err();
    assert!(matches!(
        e,
        ItdError::Column {
            column: 0,
            source: ColumnError::AreaSum { .. }
        }
    ));
    // Without aice0, Σ aicen above 1.
    let big = Array2::from_elem((2, 3), 0.6);
    let e = strength_batch(big.view(), vicen.view(), None, &o, out.view_mut()).unwrap_err();
    assert!(matches!(
        e,
        ItdError::Column {
            column: 0,
            source: ColumnError::IceAreaAboveOne { .. }
        }
    ));
    // Shape mismatch.
    let v2 = Array2::from_elem((3, 3), 0.5);
    let e = strength_batch(aicen.view(), v2.view(), None, &o, out.view_mut()).unwrap_err();
    assert!(matches!(e, ItdError::Shape { var: "vicen", .. }));
    // Bad C_f.
    // Bad C_f: not finite, below the work's own potential-energy gain, or so large that
    // C_f·C_p·Σ overflows (the fuzzer's find: C_f = 2e307 gave a NaN strength).
    for c in [f64::NAN, 0.0, 0.5, 1001.0, 2e307] {
        let bad = StrengthOptions {
            cf: Cf::Constant(c),
            ..Default::default()
        };
        assert!(matches!(
            strength_batch(aicen.view(), vicen.view(), None, &bad, out.view_mut()),
            Err(ItdError::Parameter { name: "cf", .. })
        ));
    }
}

#[test]
fn batch_accepts_fortran_and_c_layouts() {
    // Fortran aicen(ncat, ncol): category fastest → shape (ncat, ncol) with strides (1, ncat).
    let ncat = 5;
    let ncol = 4;
    let col_a = [0.08, 0.25, 0.35, 0.2, 0.1];
    let col_v = [0.024, 0.25, 0.63, 0.6, 0.45];
    let fa: Vec<f64> = (0..ncol).flat_map(|_| col_a).collect();
    let fv: Vec<f64> = (0..ncol).flat_map(|_| col_v).collect();
    use ndarray::ShapeBuilder;
    let a_f = ndarray::ArrayView2::from_shape((ncat, ncol).f(), &fa).unwrap();
    let v_f = ndarray::ArrayView2::from_shape((ncat, ncol).f(), &fv).unwrap();
    let a_c = a_f.to_owned().as_standard_layout().to_owned();
    let v_c = v_f.to_owned().as_standard_layout().to_owned();
    let a0 = Array1::from_elem(ncol, 0.02);
    let mut out_f = Array1::zeros(ncol);
    let mut out_c = Array1::zeros(ncol);
    let o = StrengthOptions::default();
    strength_batch(a_f, v_f, Some(a0.view()), &o, out_f.view_mut()).unwrap();
    strength_batch(
        a_c.view(),
        v_c.view(),
        Some(a0.view()),
        &o,
        out_c.view_mut(),
    )
    .unwrap();
    for c in 0..ncol {
        assert_relative_eq!(out_f[c], 11_683.641_518_099_608, max_relative = 1e-12);
        assert_eq!(out_f[c], out_c[c]);
    }
}

#[test]
fn cf_table_interpolates_clamps_and_flags() {
    let t = CfTable::new(vec![0.5, 1.5, 3.5], vec![10.0, 20.0, 30.0]).unwrap();
    assert_eq!(t.lookup(1.0).value, 15.0);
    assert_eq!(t.lookup(2.5).value, 25.0);
    assert!(!t.lookup(2.5).clamped);
    assert_eq!(t.lookup(0.1).value, 10.0);
    assert!(t.lookup(0.1).clamped);
    assert_eq!(t.lookup(9.0).value, 30.0);
    assert!(t.lookup(9.0).clamped);
    assert!(CfTable::new(vec![1.0, 1.0], vec![2.0, 3.0]).is_err());
    assert!(CfTable::new(vec![1.0], vec![-2.0]).is_err());
    // Finite but unphysical nodes are refused by name (the fuzzer's finds: a spacing of
    // 3e308 m made the interpolation weight NaN, C_f near 1e-323 rounded to 0 between
    // nodes): C_f within [1, 1000] (limits::CF), thickness within [0, 1000] m.
    for (h, c, what) in [
        (vec![0.5, 1.0], vec![10.0, 2e307], "cf[1] = "),
        (vec![0.5, 1.0], vec![10.0, 0.5], "cf[1] = "),
        (vec![0.5, 1.0], vec![1e-323, 10.0], "cf[0] = "),
        (vec![-1.5e308, 1.5e308], vec![10.0, 12.0], "thickness[0] = "),
        (vec![0.5, 2e3], vec![10.0, 12.0], "thickness[1] = "),
    ] {
        let e = CfTable::new(h, c).unwrap_err().to_string();
        assert!(e.contains(what) && e.contains("out of range"), "{e}");
    }
    assert!(CfTable::new(vec![0.0, 1000.0], vec![1.0, 1000.0]).is_ok());

    // A flat table equals the constant, and a table is evaluated at each category's h.
    let a = [0.08, 0.25, 0.35, 0.2, 0.1];
    let v = [0.024, 0.25, 0.63, 0.6, 0.45];
    let flat = StrengthOptions {
        cf: Cf::Table(Arc::new(
            CfTable::new(vec![0.0, 10.0], vec![17.0, 17.0]).unwrap(),
        )),
        ..Default::default()
    };
    assert_relative_eq!(
        p_of(&a, &v, 0.02, &flat),
        11_683.641_518_099_608,
        max_relative = 1e-12
    );
    // C_f = 10 below 1.4 m, 30 above: only categories 1–2 (h = 0.3, 1 m) get 10.
    let step = CfTable::new(vec![1.39, 1.41], vec![10.0, 30.0]).unwrap();
    let o = StrengthOptions {
        cf: Cf::Table(Arc::new(step)),
        ..Default::default()
    };
    let mut ws = Workspace::new(5);
    let s = strength_column(&a, &v, Some(0.02), &o, &mut ws).unwrap();
    assert!(s.cf_clamped);
    // Terms a_Pn (⟨h_r²⟩/k − h²) from the five-category derivation above.
    let ap = [
        0.534_984_763_901_712_5,
        0.134_423_401_548_125_32,
        9.110_504_387_132_267e-4,
        8.162_987_410_413_71e-7,
        1.316_882_614_941_699e-8,
    ];
    let term = [
        0.944_046_803_779_245,
        5.8,
        13.317_436_324_014_265,
        27.396_488_744_414_178,
        48.499_473_207_931_715,
    ];
    let cf = [10.0, 10.0, 30.0, 30.0, 30.0];
    let sum: f64 = (0..5).map(|n| cf[n] * ap[n] * term[n]).sum();
    assert_relative_eq!(
        s.strength,
        CP * sum / 0.901_326_203_115_903_5,
        max_relative = 1e-11
    );
    // Every category lies outside that table: all of P comes from clamped C_f.
    assert_relative_eq!(s.cf_clamped_share, 1.0, max_relative = 1e-15);

    // A table over 0.1–2.0 m (C_f 10 → 30) holds categories 0–2 (h = 0.3, 1.0, 1.8 m) and
    // clamps 3–4 (h = 3.0, 4.5 m) at 30: their share of P is their part of the sum.
    let o = StrengthOptions {
        cf: Cf::Table(Arc::new(
            CfTable::new(vec![0.1, 2.0], vec![10.0, 30.0]).unwrap(),
        )),
        ..Default::default()
    };
    let s = strength_column(&a, &v, Some(0.02), &o, &mut ws).unwrap();
    let h = [0.3, 1.0, 1.8, 3.0, 4.5];
    let cf: Vec<f64> = h
        .iter()
        .map(|&h| (10.0 + 20.0 * (h - 0.1) / 1.9_f64).min(30.0))
        .collect();
    let part = |n: usize| cf[n] * ap[n] * term[n];
    let sum: f64 = (0..5).map(part).sum();
    assert!(s.cf_clamped);
    assert_relative_eq!(
        s.cf_clamped_share,
        (part(3) + part(4)) / sum,
        max_relative = 1e-10
    );
    assert!(s.cf_clamped_share > 0.0 && s.cf_clamped_share < 1e-3);
    // Nothing clamped, nothing shared; and a batch counts a material clamp only at ≥ 1 %.
    let s = strength_column(&a, &v, Some(0.02), &flat, &mut ws).unwrap();
    assert!(!s.cf_clamped && s.cf_clamped_share == 0.0);
    assert_eq!(pressridge::itd::details::CF_CLAMPED_MATERIAL_SHARE, 0.01);
}

#[test]
fn category_bounds_match_cice() {
    let b = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
    for (x, y) in b.iter().zip([0.0, 0.6, 1.4, 2.4, 3.6, 5.0]) {
        assert_relative_eq!(*x, y, max_relative = 1e-14);
    }
    // kcatbound = 0 (Lipscomb 2001), ncat = 5: 0.6445, 1.3914, 2.4702, 4.5673, 9.3338 m
    // (c₁ = 0.6, c₂ = 9, H(n) − H(n−1) = 0.6 + 9(1 + tanh(3((n−1)/5 − 1)))).
    let o = category_bounds(&CategoryBounds::Original, 5).unwrap();
    for (x, y) in o[1..].iter().zip([
        0.644_507_216_819_425_8,
        1.391_433_497_576_303_6,
        2.470_179_381_959_888_5,
        4.567_287_918_850_491,
        9.333_841_815_868_174,
    ]) {
        assert_relative_eq!(*x, y, max_relative = 1e-13);
    }
    assert_eq!(
        category_bounds(&CategoryBounds::Wmo, 7).unwrap(),
        vec![0.0, 0.10, 0.15, 0.30, 0.70, 1.20, 2.00, 999.0]
    );
    assert!(category_bounds(&CategoryBounds::Wmo, 4).is_err());
    // kcatbound = 3, ncat = 5: b₃ = max(20, 60) = 60, H(n) = 0.1(n + 60 n(n+1)/40).
    let a = category_bounds(&CategoryBounds::Asymptotic, 5).unwrap();
    assert_relative_eq!(a[1], 0.1 * (1.0 + 3.0), max_relative = 1e-14);
    assert_relative_eq!(a[5], 0.1 * (5.0 + 45.0), max_relative = 1e-14);
    assert_eq!(
        category_bounds(&CategoryBounds::SingleCategory, 1).unwrap(),
        vec![0.0, 100.0]
    );
    assert!(category_bounds(&CategoryBounds::User(vec![0.0, 1.0, 1.0]), 2).is_err());
    assert!(category_bounds(&CategoryBounds::User(vec![0.0, 1.0, 3.0]), 2).is_ok());
}

/// An empty middle category with CICE's default options (Icepack's `ridge_itd`: an empty
/// category adds nothing to G, so its a_Pn is 0):
/// aice0 = 0.05, aicen = (0.3, 0, 0.65), vicen = (0.3, 0, 1.95) m → h = (1, –, 3) m;
/// G = (0.05, 0.35, 0.35, 1.0); a_P = (1 − e^{−1})/(1 − e^{−20}) = 0.6321205601314552,
/// (e^{−1} − e^{−7})/(1 − e^{−20}) = 0.3669675599622644, 0, e^{−7} − e^{−20} = 9.1188e-4;
/// k = (5, –, 3.0653841409022107); aksum = 0.9263090114550613;
/// Σ a_Pn (⟨h_r²⟩/k − h²) = 0.36696756·5.8 + 9.1188e-4·27.39648874 = 2.153394155369802.
/// P = 17 C_p 2.153394155369802 / 0.9263090114550613 = 18877.045148228273 N/m.
#[test]
fn empty_middle_category_by_hand() {
    let mut ws = Workspace::new(3);
    let s = strength_column(
        &[0.3, 0.0, 0.65],
        &[0.3, 0.0, 1.95],
        Some(0.05),
        &StrengthOptions::default(),
        &mut ws,
    )
    .unwrap();
    assert_eq!(ws.apartic()[2], 0.0);
    assert_relative_eq!(
        ws.apartic()[3],
        9.118_799_062_804_184e-4,
        max_relative = 1e-12
    );
    assert_relative_eq!(s.strength, 18_877.045_148_228_273, max_relative = 1e-12);
}

#[test]
fn masked_columns_get_the_fill_value_and_are_not_validated() {
    let mut aicen = Array2::from_elem((2, 3), 0.5);
    aicen[[0, 1]] = 1.0e30; // land / missing
    let vicen = Array2::from_elem((2, 3), 0.5);
    let valid = Array1::from(vec![true, false, true]);
    let mut out = Array1::zeros(3);
    let s = pressridge::itd::details::strength_batch_masked(
        aicen.view(),
        vicen.view(),
        None,
        Some(valid.view()),
        -1.0,
        &StrengthOptions::default(),
        out.view_mut(),
    )
    .unwrap();
    assert_eq!(s.columns, 2);
    assert_eq!(out[1], -1.0);
    assert!(out[0] > 0.0 && out[0] == out[2]);
}

#[test]
fn parameters_are_overridable_by_name() {
    let a = [0.08, 0.25, 0.35, 0.2, 0.1];
    let v = [0.024, 0.25, 0.63, 0.6, 0.45];
    let base = p_of(&a, &v, 0.02, &StrengthOptions::default());
    let mut params = ItdParams::default();
    params.set("mu_rdg", 4.0).unwrap();
    assert_eq!(params.mu_rdg, 4.0);
    // Wider ridges (μ = 4 m^½, ~ H* = 50 m in Lipscomb et al. 2007) make stronger ice.
    let o = StrengthOptions {
        params,
        ..Default::default()
    };
    assert!(p_of(&a, &v, 0.02, &o) > base);
    // Doubling g doubles C_p and hence P.
    let mut params = ItdParams::default();
    params.set("gravit", 2.0 * 9.80616).unwrap();
    let o = StrengthOptions {
        params,
        ..Default::default()
    };
    assert_relative_eq!(p_of(&a, &v, 0.02, &o), 2.0 * base, max_relative = 1e-14);
    let mut params = ItdParams::default();
    assert!(params.set("no_such", 1.0).is_err());
    assert!(params.set("hstar", -1.0).is_err());
    assert!(params.set("nitermax", 2.5).is_err());
    assert!(params.set("rhoi", 2000.0).is_err());
    assert_eq!(
        params,
        ItdParams::default(),
        "a rejected value changes nothing"
    );
    assert!(params.set("cs", 0.0).is_ok());
}

/// The batched driver evaluates Rothrock/constant-C_f columns in blocks (SIMD across
/// columns); every value must be bit-identical to the per-column routine, for every option
/// pair, with and without `aice0`, including empty categories, tiny areas, zero volumes,
/// open water only and odd column counts.
#[test]
fn batch_block_path_is_bit_identical_to_the_column_routine() {
    let mut state: u64 = 12345;
    let mut rnd = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let ncat = 5;
    let ncol = 4003;
    let mut a = Array2::zeros((ncat, ncol));
    let mut v = Array2::zeros((ncat, ncol));
    let mut a0 = Array1::zeros(ncol);
    for c in 0..ncol {
        let kind = c % 7;
        let mut w: Vec<f64> = (0..=ncat).map(|_| rnd()).collect();
        if kind == 1 {
            w[2] = 0.0; // empty category
        }
        if kind == 2 {
            w[0] = 1e-13; // open water below puny
        }
        if kind == 3 {
            w[1..].iter_mut().for_each(|x| *x = 0.0); // open water only
        }
        let s: f64 = w.iter().sum();
        for n in 0..ncat {
            a[[n, c]] = w[n + 1] / s;
            let h = if kind == 4 && n == 0 {
                0.0
            } else {
                0.2 + 5.0 * rnd()
            };
            v[[n, c]] = a[[n, c]] * h;
        }
        a0[c] = w[0] / s;
    }
    for p in [Participation::Thorndike, Participation::Exponential] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            let o = opts(p, r, 17.0);
            for with_a0 in [true, false] {
                let mut out = Array1::zeros(ncol);
                let a0v = with_a0.then(|| a0.view());
                strength_batch(a.view(), v.view(), a0v, &o, out.view_mut()).unwrap();
                let mut ws = Workspace::new(ncat);
                for c in 0..ncol {
                    let ac: Vec<f64> = a.column(c).to_vec();
                    let vc: Vec<f64> = v.column(c).to_vec();
                    let s = strength_column(&ac, &vc, with_a0.then(|| a0[c]), &o, &mut ws)
                        .unwrap()
                        .strength;
                    assert_eq!(
                        out[c].to_bits(),
                        s.to_bits(),
                        "{p:?}/{r:?} column {c}: {} vs {s}",
                        out[c]
                    );
                }
            }
        }
    }
    // A bad column inside a block is still reported by its own index.
    let mut bad = a.clone();
    bad[[3, 2001]] = -0.5;
    let mut out = Array1::zeros(ncol);
    let e = strength_batch(
        bad.view(),
        v.view(),
        Some(a0.view()),
        &StrengthOptions::default(),
        out.view_mut(),
    )
    .unwrap_err();
    assert!(matches!(
        e,
        ItdError::Column {
            column: 2001,
            source: ColumnError::Negative {
                var: "aicen",
                category: Some(3),
                ..
            }
        }
    ));
}

/// A custom C_f provider is checked at each lookup (tables are checked when built): a value
/// outside [1, 1000] is an error naming the category and thickness, never a NaN strength.
#[test]
fn custom_cf_provider_out_of_range_is_refused() {
    #[derive(Debug)]
    struct Wild;
    impl CfProvider for Wild {
        fn lookup(&self, h: f64) -> pressridge::itd::details::CfLookup {
            pressridge::itd::details::CfLookup {
                value: if h > 1.0 { f64::NAN } else { 12.0 },
                clamped: false,
            }
        }
    }
    let a = [0.08, 0.25, 0.35, 0.2, 0.1];
    let v = [0.024, 0.25, 0.63, 0.6, 0.45];
    let o = StrengthOptions {
        cf: Cf::Custom(Arc::new(Wild)),
        ..Default::default()
    };
    let mut ws = Workspace::new(5);
    let e = strength_column(&a, &v, Some(0.02), &o, &mut ws).unwrap_err();
    assert!(
        matches!(e, ColumnError::CfOutOfRange { category: 2, value, .. } if value.is_nan()),
        "{e:?}"
    );
    assert!(e.to_string().contains("[1, 1000]"), "{e}");
}
