use super::*;

/// A profile whose every strip is ridged with solid thicknesses `ice` (m) and porosity `phi`.
fn profile(ice: &[f64], phi: f64) -> Profile {
    let n = ice.len();
    Profile {
        x0: 0.0,
        dx: 1.0,
        sail: vec![0.0; n],
        keel: vec![0.0; n],
        rubble_sail: vec![0.0; n],
        rubble_keel: vec![0.0; n],
        ridge_ice: ice.to_vec(),
        ridge_envelope: ice.iter().map(|x| x / (1.0 - phi)).collect(),
    }
}

/// n points at the mid-quantiles of a distribution with inverse CDF `q`.
fn quantiles(n: usize, q: impl Fn(f64) -> f64) -> Vec<f64> {
    (0..n).map(|i| q((i as f64 + 0.5) / n as f64)).collect()
}

/// Ridged ice drawn from Lipscomb's exponential (h = 0.3 m, μ_rdg = 3 m^½): the fit gives λ
/// and μ_rdg back, its KS distance is that of a 2000-point sample, the uniform's is not; the
/// porosity is the one the columns were built with.
#[test]
fn an_exponential_ridge_gives_its_mu_rdg_back() {
    let h: f64 = 0.3;
    let lambda = 3.0 * h.sqrt();
    let ice = quantiles(2000, |u| 2.0 * h - lambda * (1.0 - u).ln());
    let r = RidgedIce::of(&profile(&ice, 0.3), h).unwrap();
    let f = r.fit();
    assert_eq!(f.h_min, 0.6);
    assert!((f.lambda / lambda - 1.0).abs() < 2e-3, "{f:?}");
    assert!((f.mu_rdg / 3.0 - 1.0).abs() < 2e-3, "{f:?}");
    assert!(f.ks_exponential < 2e-3, "{f:?}");
    assert!(f.ks_uniform > 0.1, "{f:?}");
    assert!((r.porosity() - 0.3).abs() < 1e-12);
    assert_eq!(r.width(), 2000.0);
}

/// Ridged ice drawn from Hibler's uniform (h = 0.3 m, H* = 25 m): the fit gives H* back, and
/// the uniform fits better than the exponential.
#[test]
fn a_uniform_ridge_gives_its_h_star_back() {
    let h: f64 = 0.3;
    let h_max = 2.0 * (25.0 * h).sqrt();
    let ice = quantiles(1000, |u| 2.0 * h + u * (h_max - 2.0 * h));
    let f = RidgedIce::of(&profile(&ice, 0.0), h).unwrap().fit();
    assert!((f.h_star / 25.0 - 1.0).abs() < 1e-9, "{f:?}");
    assert!((f.h_max - h_max).abs() < 1e-9);
    assert!(f.ks_uniform < 1e-3 && f.ks_exponential > 0.1, "{f:?}");
}

/// Above 1 m the thinnest ridged ice is h + maxraft, as in Icepack; strips thinner than it
/// count against both shapes.
#[test]
fn thick_parents_start_at_h_plus_maxraft_and_thin_strips_count_against_the_fit() {
    let f = RidgedIce::of(&profile(&[4.0, 5.0, 6.0], 0.0), 2.0)
        .unwrap()
        .fit();
    assert_eq!(f.h_min, 3.0);
    assert_eq!(f.lambda, 2.0);
    // Half the strips below H_min: the distance is at least 1/2.
    let f = RidgedIce::of(&profile(&[0.1, 0.2, 1.0, 2.0], 0.0), 0.3)
        .unwrap()
        .fit();
    assert!(f.ks_exponential >= 0.5 && f.ks_uniform >= 0.5, "{f:?}");
    assert_eq!(f.below_min, 0.5);
}

/// The empirical distance of a sample from its own distribution is at most 1/n; from a
/// disjoint one it is 1.
#[test]
fn ks_distance_bounds() {
    let xs = quantiles(10, |u| u);
    assert!((ks_distance(&xs, |x| x.clamp(0.0, 1.0)) - 0.05).abs() < 1e-12);
    assert_eq!(ks_distance(&xs, |x| if x < 5.0 { 0.0 } else { 1.0 }), 1.0);
}

/// The histogram gives area fractions that add to one, the top edge in the last bin.
#[test]
fn histogram_of_area_fractions() {
    let r = RidgedIce::of(&profile(&[0.5, 1.5, 1.5, 3.0], 0.0), 0.3).unwrap();
    assert_eq!(r.histogram(&[0.0, 1.0, 2.0, 3.0]), vec![0.25, 0.5, 0.25]);
    assert_eq!(r.histogram(&[0.0, 1.0]), vec![0.25]);
}

/// Records without the columns, profiles without rubble and a bad thickness are errors.
#[test]
fn missing_columns_no_ridge_and_bad_thickness_are_errors() {
    let mut p = profile(&[1.0], 0.0);
    assert!(matches!(
        RidgedIce::of(&p, f64::NAN),
        Err(RidgedError::Thickness(_))
    ));
    assert!(matches!(
        RidgedIce::of(&p, 0.0),
        Err(RidgedError::Thickness(_))
    ));
    p.ridge_ice = vec![0.0];
    assert_eq!(RidgedIce::of(&p, 0.3), Err(RidgedError::NoRidge));
    p.ridge_ice.clear();
    assert_eq!(RidgedIce::of(&p, 0.3), Err(RidgedError::NoColumns));
}

/// The ensemble's statistics are over the runs' own fits; the pooled fit over all strips.
#[test]
fn an_ensemble_pools_strips_and_spreads_run_fits() {
    let a = RidgedIce::of(&profile(&[1.0, 2.0], 0.2), 0.25).unwrap();
    let b = RidgedIce::of(&profile(&[2.0, 3.0, 4.0], 0.4), 0.25).unwrap();
    let e = RidgedEnsemble::of(&[a, b]).unwrap();
    assert_eq!(e.pooled.ice.len(), 5);
    assert_eq!(e.fit.mean, 12.0 / 5.0);
    assert_eq!(e.mean_thickness.mean, (1.5 + 3.0) / 2.0);
    assert_eq!(e.lambda.mean, (1.0 + 2.5) / 2.0);
    assert_eq!(e.mu_rdg.mean, (2.0 + 5.0) / 2.0);
    assert!((e.porosity.mean - 0.3).abs() < 1e-12);
    assert_eq!(e.width.mean, 2.5);
    let c = e.columns();
    let get = |n: &str| c.iter().find(|x| x.0 == n).unwrap().1;
    assert_eq!((get("runs"), get("strips")), (2.0, 5.0));
    assert_eq!(get("mu_rdg"), e.mu_rdg.mean);
    assert_eq!(get("h_star_ci95"), e.h_star.half_width_95());
    assert_eq!(get("pooled_mu_rdg"), e.fit.mu_rdg);
    assert_eq!(c.len(), 2 + 6 * 3 + 5);
    assert!(RidgedEnsemble::of(&[]).is_none());
}

/// Ridged ice no thicker on average than H_min has no Lipscomb shape of its mean: the host's
/// μ_rdg is absent there (NaN in the table), present and the runs' mean elsewhere.
#[test]
fn ridged_ice_thinner_than_h_min_gives_no_host_mu_rdg() {
    // h = 4 m: H_min = h + 1 m = 5 m; strips of 4.5 and 5.3 m average 4.9 m.
    let thin = RidgedIce::of(&profile(&[4.5, 5.3], 0.1), 4.0).unwrap();
    let e = RidgedEnsemble::of(&[thin.clone(), thin]).unwrap();
    assert!(e.mu_rdg.mean < 0.0, "{:?}", e.mu_rdg);
    assert_eq!(e.host_mu_rdg(), None);
    let a = RidgedIce::of(&profile(&[1.0, 2.0], 0.2), 0.25).unwrap();
    let e = RidgedEnsemble::of(&[a.clone(), a]).unwrap();
    assert_eq!(e.host_mu_rdg(), Some(e.mu_rdg.mean));
}

/// The table's bins are in units of h; a strip beyond 20h lands in the last bin.
#[test]
fn table_histogram_is_in_units_of_h_and_catches_the_tail() {
    let r = RidgedIce::of(&profile(&[0.1, 0.25, 0.75, 9.0], 0.0), 0.2).unwrap();
    let f = r.table_histogram();
    assert_eq!(f.len(), 40);
    // H/h = 0.5, 1.25, 3.75, 45.
    assert_eq!((f[1], f[2], f[7], f[39]), (0.25, 0.25, 0.25, 0.25));
    assert!((f.iter().sum::<f64>() - 1.0).abs() < 1e-15);
}
