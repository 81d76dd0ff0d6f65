//! A host's tracer array longer than its flags' layout (CICE's slot after its tracers,
//! `TracerLayout::with_unnamed_tracers`): the unnamed tracer is an area tracer, so ridging
//! keeps a uniform value uniform (Σ a·c moved with the area gives c back wherever there is
//! ice), and the named tracers, the state and the fluxes are those of the step without it, to
//! the bit. Through the C ABI a host may give up to 8 more than the layout, not fewer.

mod common;

use common::column::{Column, step};
use pressridge::itd::{
    CategoryBounds, RidgeStepOptions, StepForcing, category_bounds,
    details::{CiceTracerFlags, Closing, TracerLayout},
};

#[test]
fn an_unnamed_area_tracer_is_ridged_with_the_area_and_changes_nothing_else() {
    let flags = CiceTracerFlags {
        age: true,
        first_year: true,
        level_ice: true,
        ponds: true,
        ..Default::default()
    };
    let named = TracerLayout::cice(7, 1, flags).unwrap();
    let wide = named.clone().with_unnamed_tracers(1);
    let (nt, nw) = (named.ntrcr(), wide.ntrcr());
    assert_eq!(nw, nt + 1);
    assert_eq!(wide.trcr_depend()[nt], 0, "an area tracer");
    assert_eq!(wide.base_codes()[nt], 0);
    assert_eq!(&wide.trcr_depend()[..nt], &named.trcr_depend()[..]);
    let hin = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
    let aicen = vec![0.3, 0.25, 0.2, 0.1, 0.05];
    let h = [0.4, 1.0, 2.0, 3.0, 5.0];
    let vicen: Vec<f64> = aicen.iter().zip(h).map(|(a, h)| a * h).collect();
    let vsnon: Vec<f64> = vicen.iter().map(|v| 0.1 * v).collect();
    // Plausible named tracers: Tsfc, enthalpies, salinity, age, FY, level ice, ponds.
    let per_cat: Vec<f64> = (0..nt)
        .map(|it| match it {
            0 => -5.0,
            1..=7 => -3.0e8,
            8 => -1.2e8,
            9..=15 => 4.0,
            16 => 3.0e7,
            17 => 0.5,
            18 | 19 => 0.8,
            _ => 0.1,
        })
        .collect();
    let c = 0.37;
    let t_named: Vec<f64> = (0..5).flat_map(|_| per_cat.iter().copied()).collect();
    let t_wide: Vec<f64> = (0..5)
        .flat_map(|_| per_cat.iter().copied().chain([c]))
        .collect();
    let forcing = StepForcing {
        closing: Closing::Deformation {
            convergence: 5e-6,
            shear: 2e-6,
        },
        dt: 3600.0,
        ndtd: 1,
        tf: -1.8,
    };
    let opts = RidgeStepOptions::default();
    let a = step(
        &Column::new(aicen.clone(), vicen.clone(), vsnon.clone(), t_named, 0.1),
        &hin,
        forcing,
        &opts,
        &named,
    );
    let b = step(
        &Column::new(aicen, vicen, vsnon, t_wide, 0.1),
        &hin,
        forcing,
        &opts,
        &wide,
    );
    a.result.unwrap();
    b.result.unwrap();
    let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&a.col.aicen), bits(&b.col.aicen));
    assert_eq!(bits(&a.col.vicen), bits(&b.col.vicen));
    assert_eq!(bits(&a.col.vsnon), bits(&b.col.vsnon));
    assert_eq!(a.col.aice0.to_bits(), b.col.aice0.to_bits());
    assert_eq!(a.fluxes, b.fluxes);
    for n in 0..5 {
        assert_eq!(
            bits(&a.col.trcrn[n * nt..(n + 1) * nt]),
            bits(&b.col.trcrn[n * nw..n * nw + nt]),
            "named tracers of category {n}"
        );
        let u = b.col.trcrn[n * nw + nt];
        if b.col.aicen[n] > 1e-11 {
            assert!((u - c).abs() <= 1e-14, "category {n}: {u} against {c}");
        }
    }
    // Ridging moved area out of the thinnest category (the test means something).
    assert!(
        a.col.aicen[0] < 0.3 - 1e-3,
        "little ridging: {}",
        a.col.aicen[0]
    );
}
