//! Reading Icepack 1.5.3's reference cases of the complete step
//! (`tests/data/icepack/ridge_step_cases.jsonl`, described in the README next to it).

use pressridge::itd::{
    RidgeStepOptions,
    details::{BgcKind, BgcTracers, CiceTracerFlags, Participation, Redistribution, TracerLayout},
};
use serde_json::Value;

/// The reference file (the 23-tracer CICE layout), relative to the repository's root.
pub const FILE: &str = "tests/data/icepack/ridge_step_cases.jsonl";

/// The same cases with snow, isotope and aerosol tracers (41 tracers).
pub const TRACERS_FILE: &str = "tests/data/icepack/ridge_step_tracers.jsonl";

/// Topography ponds, the snow tracers with Icepack's refills, floe size and brine (37 tracers).
pub const TOPO_FILE: &str = "tests/data/icepack/ridge_step_tracers_topo.jsonl";

/// The topography-pond layout with two vertically resolved bio tracers (`z_tracers`,
/// `nblyr = 2`; 47 tracers) and Icepack's tracer tables.
pub const BGC_FILE: &str = "tests/data/icepack/ridge_step_tracers_bgc.jsonl";

/// The topography-pond layout with two skeletal bio tracers (`skl_bgc`; 39 tracers) and
/// Icepack's tracer tables.
pub const SKL_FILE: &str = "tests/data/icepack/ridge_step_tracers_skl.jsonl";

/// The first reference file's first line (the parameters) and its cases.
#[allow(dead_code)]
pub fn read() -> (Value, Vec<Value>) {
    read_file(FILE)
}

/// A reference file's first line (the parameters) and its cases, one JSON value a line;
/// `file` is relative to the repository's root.
pub fn read_file(file: &str) -> (Value, Vec<Value>) {
    let text = std::fs::read_to_string(super::repo().join(file)).expect("reference file");
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    let params: Value = serde_json::from_str(lines.next().unwrap()).unwrap();
    let cases = lines.map(|l| serde_json::from_str(l).unwrap()).collect();
    (params, cases)
}

/// A number (`"nan"`, `"inf"` and `"-inf"` stand for themselves).
pub fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().unwrap(),
        Value::String(s) => match s.as_str() {
            "nan" => f64::NAN,
            "inf" => f64::INFINITY,
            "-inf" => f64::NEG_INFINITY,
            _ => panic!("bad number {s}"),
        },
        _ => panic!("not a number: {v}"),
    }
}

pub fn nums(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(num).collect()
}

/// The CICE tracer layout of the parameters' `nilyr`, `nslyr` and `tracer_flags`.
pub fn layout(params: &Value) -> TracerLayout {
    let flags = &params["tracer_flags"];
    let flag = |k: &str| flags[k].as_bool().unwrap_or(false);
    let count = |on: &str, n: &str| {
        if flag(on) {
            flags[n].as_u64().unwrap_or(0) as usize
        } else {
            0
        }
    };
    let mut layout = TracerLayout::cice(
        params["nilyr"].as_u64().unwrap() as usize,
        params["nslyr"].as_u64().unwrap() as usize,
        CiceTracerFlags {
            age: flag("tr_iage"),
            first_year: flag("tr_FY"),
            level_ice: flag("tr_lvl"),
            ponds: flag("tr_pond_lvl"),
            snow: flag("tr_snow"),
            isotopes: count("tr_iso", "n_iso"),
            aerosols: count("tr_aero", "n_aero"),
            pond_topo: flag("tr_pond_topo"),
            pond_sealvl: flag("tr_pond_sealvl"),
            fsd: count("tr_fsd", "nfsd"),
            brine: flag("tr_brine"),
        },
    )
    .unwrap();
    // Bio tracers after every other: their kind, and the tracers' carriage as Icepack was
    // given it.
    let bgc = &params["bgc"];
    if !bgc.is_null() {
        let cice = layout.ntrcr();
        let extra = params["ntrcr"].as_u64().unwrap() as usize - cice;
        let kind = match bgc["kind"].as_str().unwrap() {
            "z_tracers" => BgcKind::Vertical {
                nblyr: bgc["nblyr"].as_u64().unwrap() as usize,
            },
            "skl_bgc" => BgcKind::Skeletal {
                sk_l: num(&bgc["sk_l"]),
            },
            k => panic!("bgc kind {k}"),
        };
        let bio_index = bgc["bio_index"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b.as_u64().unwrap() as usize - 1)
            .collect();
        layout = layout
            .with_bgc(extra, BgcTracers { kind, bio_index })
            .unwrap();
    }
    // Icepack's refills of the snow tracers (snwredist = 'ITD', snwgrain).
    for (name, key) in [
        ("rhos", "rhos_empty"),
        ("smice", "smice_empty"),
        ("rsnw", "rsnw_empty"),
    ] {
        if let Some(v) = flags[key].as_f64() {
            layout = layout.with_empty_value(name, v).unwrap();
        }
    }
    let t = &params["host_tables"];
    if !t.is_null() {
        let ints = |k: &str| -> Vec<i32> {
            t[k].as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_i64().unwrap() as i32)
                .collect()
        };
        // trcr_base(ntrcr, 3) and nt_strata(ntrcr, 2) in Fortran order.
        let fortran = |k: &str, cols: usize| -> Vec<Value> {
            let rows = t[k].as_array().unwrap();
            (0..cols)
                .flat_map(|j| rows.iter().map(move |r| r[j].clone()))
                .collect()
        };
        let base: Vec<f64> = fortran("trcr_base", 3).iter().map(num).collect();
        let strata: Vec<i32> = fortran("nt_strata", 2)
            .iter()
            .map(|x| x.as_i64().unwrap() as i32)
            .collect();
        layout = layout
            .with_host_tables(&ints("trcr_depend"), &base, &ints("n_trcr_strata"), &strata)
            .unwrap();
    }
    layout
}

/// Tracers of a case as `trcrn[n * ntrcr + it]`.
pub fn tracers(v: &Value, layout: &TracerLayout, ncat: usize) -> Vec<f64> {
    let nt = layout.ntrcr();
    let mut t = vec![f64::NAN; ncat * nt];
    let obj = v.as_object().unwrap();
    assert_eq!(obj.len(), layout.fields().len(), "tracer fields");
    for (name, per_cat) in obj {
        let (start, levels) = layout
            .field(name)
            .unwrap_or_else(|| panic!("tracer {name} not in the layout"));
        let per_cat = per_cat.as_array().unwrap();
        assert_eq!(per_cat.len(), ncat);
        for (n, lv) in per_cat.iter().enumerate() {
            let lv = nums(lv);
            assert_eq!(lv.len(), levels, "{name} levels");
            t[n * nt + start..n * nt + start + levels].copy_from_slice(&lv);
        }
    }
    assert!(t.iter().all(|x| !x.is_nan()), "every tracer given");
    t
}

/// The options of a case's inputs: participation, redistribution, `mu_rdg`, clean-up and
/// rebinning; the rest the library's defaults.
#[allow(clippy::field_reassign_with_default)]
pub fn options(i: &Value) -> RidgeStepOptions {
    let mut opts = RidgeStepOptions::default();
    opts.participation = match i["krdg_partic"].as_i64().unwrap() {
        0 => Participation::Thorndike,
        1 => Participation::Exponential,
        k => panic!("krdg_partic {k}"),
    };
    opts.redistribution = match i["krdg_redist"].as_i64().unwrap() {
        0 => Redistribution::Uniform,
        1 => Redistribution::Exponential,
        k => panic!("krdg_redist {k}"),
    };
    opts.params.mu_rdg = num(&i["mu_rdg"]);
    opts.cleanup = i["docleanup"].as_bool().unwrap();
    opts.rebin = i["dorebin"].as_bool().unwrap();
    opts
}
