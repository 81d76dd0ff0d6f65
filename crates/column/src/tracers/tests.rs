//! Unit tests of the tracer layout.

use super::*;

#[test]
fn cice_layout_matches_icepack_indices() {
    let l = TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap();
    assert_eq!(l.ntrcr(), 23);
    assert_eq!(l.field("qsno"), Some((8, 1)));
    assert_eq!(l.field("sice"), Some((9, 7)));
    assert_eq!(l.field("ipnd"), Some((22, 1)));
    let d = l.trcr_depend();
    assert_eq!(d[0], 0);
    assert_eq!(d[1], 1);
    assert_eq!(d[8], 2);
    // apnd on alvl (1-based 19), hpnd/ipnd on apnd (1-based 21).
    assert_eq!(d[20], 2 + 19);
    assert_eq!(d[21], 2 + 21);
    assert_eq!(l.strata_one_based()[21], [19, 21]);
}

#[test]
fn cice_restart_names_follow_the_layout() {
    let l = TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap();
    let n = l.cice_restart_names();
    assert_eq!(n.len(), 23);
    assert_eq!(n[0], "Tsfcn");
    assert_eq!(n[1], "qice001");
    assert_eq!(n[7], "qice007");
    assert_eq!(n[8], "qsno001");
    assert_eq!(n[9], "sice001");
    assert_eq!(n[16], "iage");
    assert_eq!(n[22], "ipnd");
    assert_eq!(
        l.field_of(8).map(|(f, k)| (f.name.as_str(), k)),
        Some(("qsno", 0))
    );
    assert_eq!(
        l.field_of(12).map(|(f, k)| (f.name.as_str(), k)),
        Some(("sice", 3))
    );
    assert!(l.field_of(23).is_none());
}

/// Detection from variable names: the layout that names them, nothing without snow or
/// tracers, and a missing member named.
#[test]
fn detect_cice_from_names() {
    let want = TracerLayout::cice(
        3,
        2,
        CiceTracerFlags {
            first_year: true,
            level_ice: true,
            ..Default::default()
        },
    )
    .unwrap();
    let mut names = want.cice_restart_names();
    names.push("vsnon".into());
    let has = |n: &str| names.iter().any(|m| m == n);
    let (got, flags) = TracerLayout::detect_cice(&has).unwrap().unwrap();
    assert_eq!(got, want);
    assert!(flags.first_year && flags.level_ice && !flags.age && !flags.ponds);
    assert_eq!(TracerLayout::detect_cice(&|n| n == "aicen").unwrap(), None);
    let without_vlvl = |n: &str| n != "vlvl" && has(n);
    let e = TracerLayout::detect_cice(&without_vlvl).unwrap_err();
    assert_eq!(e.var, "vlvl");
    assert!(e.why.contains("alvl"), "{e}");
    let without_sice2 = |n: &str| n != "sice002" && has(n);
    assert_eq!(
        TracerLayout::detect_cice(&without_sice2).unwrap_err().var,
        "sice002"
    );
    for r in TracerRole::ALL {
        assert_eq!(TracerRole::from_name(r.name()), Some(r));
    }
    for b in TracerBase::ALL {
        assert_eq!(TracerBase::from_name(b.name()), Some(b));
    }
}

#[test]
fn ponds_without_level_ice_rejected() {
    let f = CiceTracerFlags {
        ponds: true,
        ..Default::default()
    };
    assert!(TracerLayout::cice(2, 1, f).is_err());
}

#[test]
fn aerosols_and_isotopes_are_paired_by_species() {
    use TracerBase::*;
    use TracerRole::*;
    let flags = CiceTracerFlags {
        snow: true,
        isotopes: 2,
        aerosols: 2,
        ..CiceTracerFlags::ALL
    };
    let l = TracerLayout::cice(7, 1, flags).unwrap();
    // 23 + 4 snow + 2·2 isotopes + 4·2 aerosols, Icepack's driver order.
    assert_eq!(l.ntrcr(), 39);
    assert_eq!(l.iso, Some((27, 29, 2)));
    assert_eq!(l.aero, vec![[31, 32, 33, 34], [35, 36, 37, 38]]);
    let d = l.trcr_depend();
    assert_eq!((d[23], d[27], d[29], d[31], d[33]), (2, 2, 1, 2, 1));
    assert!(
        TracerLayout::cice(
            7,
            1,
            CiceTracerFlags {
                aerosols: 7,
                ..flags
            }
        )
        .is_err()
    );
    assert!(
        TracerLayout::cice(
            7,
            1,
            CiceTracerFlags {
                isotopes: 4,
                ..flags
            }
        )
        .is_err()
    );
    // Rules of TracerLayout::new: whole species, the right base, both isotope fields.
    let core = || {
        vec![
            TracerField::new("qice", IceEnthalpy, 2, IceVolume, &[]),
            TracerField::new("qsno", SnowEnthalpy, 1, SnowVolume, &[]),
            TracerField::new("sice", IceSalinity, 2, IceVolume, &[]),
        ]
    };
    let with = |extra: Vec<TracerField>| TracerLayout::new([core(), extra].concat());
    let a = |name: &str, role, base| TracerField::new(name, role, 1, base, &[]);
    let species = vec![
        a("s1", AerosolSnow, SnowVolume),
        a("s2", AerosolSnow, SnowVolume),
        a("i1", AerosolIce, IceVolume),
        a("i2", AerosolIce, IceVolume),
    ];
    assert_eq!(with(species.clone()).unwrap().aero, vec![[5, 6, 7, 8]]);
    assert!(with(species[..3].to_vec()).is_err(), "half a species");
    let mut wrong = species.clone();
    wrong[2] = a("i1", AerosolIce, SnowVolume);
    assert!(with(wrong).is_err(), "ice aerosol on snow");
    let iso = |n| TracerField::new("isosno", IsotopeSnow, n, SnowVolume, &[]);
    assert!(with(vec![iso(2)]).is_err(), "isosno without isoice");
    let isoice = TracerField::new("isoice", IsotopeIce, 3, IceVolume, &[]);
    assert!(
        with(vec![iso(2), isoice.clone()]).is_err(),
        "species differ"
    );
    assert_eq!(with(vec![iso(3), isoice]).unwrap().iso, Some((5, 8, 3)));
}

#[test]
fn snow_isotope_and_aerosol_tracers_are_detected_from_names() {
    let flags = CiceTracerFlags {
        snow: true,
        isotopes: 2,
        aerosols: 3,
        ..CiceTracerFlags::ALL
    };
    let l = TracerLayout::cice(4, 2, flags).unwrap();
    let names = l.cice_restart_names();
    assert!(names.contains(&"smice002".to_string()) && names.contains(&"rsnw001".to_string()));
    assert!(names.contains(&"isoice002".to_string()));
    assert!(names.contains(&"aeroiceint003".to_string()));
    let mut all = names.clone();
    all.push("vsnon".into());
    let has = |n: &str| all.iter().any(|m| m == n);
    let (got, f) = TracerLayout::detect_cice(&has).unwrap().unwrap();
    assert_eq!((got, f), (l, flags));
    // A species without one of its four tracers is named.
    let short: Vec<String> = all
        .iter()
        .filter(|n| *n != "aeroicessl002")
        .cloned()
        .collect();
    let has = |n: &str| short.iter().any(|m| m == n);
    assert_eq!(
        TracerLayout::detect_cice(&has).unwrap_err().var,
        "aeroicessl002"
    );
}

#[test]
fn host_tables_carry_each_tracer_as_the_host_says() {
    let flags = CiceTracerFlags {
        isotopes: 3,
        ..CiceTracerFlags::ALL
    };
    let l = TracerLayout::cice(7, 1, flags).unwrap();
    let nt = l.ntrcr();
    let dep = l.trcr_depend();
    let base: Vec<f64> = (0..3)
        .flat_map(|k| l.base_codes().into_iter().map(move |b| f64::from(b == k)))
        .collect();
    let nst: Vec<i32> = l.nstrata.iter().map(|&n| i32::from(n)).collect();
    let st1 = l.strata_one_based();
    let st: Vec<i32> = (0..2).flat_map(|j| st1.iter().map(move |s| s[j])).collect();
    // The layout's own tables give the layout back.
    let same = l.clone().with_host_tables(&dep, &base, &nst, &st).unwrap();
    assert_eq!(same, l);
    // Icepack's column driver: only the first isotope species gets its dependency, the
    // others are area tracers (trcr_depend 0, trcr_base area).
    let (isno, _) = l.field("isosno").unwrap();
    let (mut dep2, mut base2) = (dep.clone(), base.clone());
    for it in [isno + 1, isno + 2] {
        dep2[it] = 0;
        base2[it] = 1.0;
        base2[nt + it] = 0.0;
        base2[2 * nt + it] = 0.0;
    }
    let host = l
        .clone()
        .with_host_tables(&dep2, &base2, &nst, &st)
        .unwrap();
    assert_eq!(host.trcr_depend(), dep2);
    assert!(host.area_direct[isno + 1] && !host.area_direct[isno]);
    assert_eq!(host.iso, l.iso, "the roles stay the layout's");
    // An empty value set afterwards keeps the host's tables, and is not given to the tracers
    // they put on the area.
    let e = host.clone().with_empty_value("isosno", 1.0).unwrap();
    assert_eq!(e.trcr_depend(), dep2);
    assert_eq!(e.refilled, vec![isno]);
    // A trcr_depend that disagrees with its base and strata is kept as Icepack keeps it
    // (the column driver's bio tracers: 2 + nt_fbri on a base reset to the area): the
    // tracer is carried on its base and leaves the area branch of the tracer update.
    dep2[isno + 1] = 2 + isno as i32 + 1;
    let odd = l
        .clone()
        .with_host_tables(&dep2, &base2, &nst, &st)
        .unwrap();
    assert_eq!(odd.trcr_depend(), dep2);
    assert!(!odd.area_direct[isno + 1] && odd.base_idx[isno + 1] == 0);
    // One that names no base and no tracer is refused, naming the tracer (1-based).
    for bad in [-1, 3 + nt as i32] {
        dep2[isno + 1] = bad;
        let e = l
            .clone()
            .with_host_tables(&dep2, &base2, &nst, &st)
            .unwrap_err();
        assert!(
            e.to_string().contains(&format!("tracer {}", isno + 2)),
            "{e}"
        );
    }
    assert!(l.with_host_tables(&dep[1..], &base, &nst, &st).is_err());
}
