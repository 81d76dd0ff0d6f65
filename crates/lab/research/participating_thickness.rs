//! Which ice thicknesses the C_f lookup of the strength routine is asked for (issue 14,
//! item 4): the thickness axis a ridging table needs.
//!
//! `cargo run --release --example participating_thickness [-- ITD.nc [CASES.jsonl]]`
//! (defaults `data/sample_itd.nc` and `tests/data/icepack/ridge_step_cases.jsonl`).
//!
//! The Rothrock strength with a C_f table looks C_f up at h_n = vicen/aicen of every
//! category with aicen > puny and a participation a_Pn > 0 (`itd::strength_column`). This
//! example asks the strength routine itself: a [`CfProvider`] records every thickness it is
//! queried at, and a second pass per category (C_f = 1 for that category, 0 for the others)
//! gives each category's share of the strength sum. Per column it then reports the thinnest
//! and thickest ice looked up (a) at any a_Pn > 0 (what `cf_clamped_columns` counts), (b) at
//! a_Pn ≥ 1e-3 and ≥ 1e-2 of the closing, and (c) for categories carrying ≥ 1 % of the
//! strength, and counts the columns with some such ice outside [0.10, H] for H = 1, 2, 3,
//! 5 m and beyond. The sample file is run with CICE's defaults (exponential participation
//! and redistribution); each `typical` Icepack case with its own `krdg_partic`,
//! `krdg_redist` and `mu_rdg`.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use pressridge::io::itd_netcdf::read_itd;
use pressridge::itd::{
    Cf, StrengthOptions, Workspace,
    details::{CfLookup, CfProvider, Participation, Redistribution},
    strength_column,
};

/// Records the thicknesses it is asked for; returns 1 for the `only`-th query (or for
/// every query when `only` is `None`) and 0 otherwise.
#[derive(Debug, Default)]
struct Recorder {
    state: Mutex<(Vec<f64>, Option<usize>)>,
}

impl CfProvider for Recorder {
    fn lookup(&self, h: f64) -> CfLookup {
        let mut s = self.state.lock().expect("not poisoned");
        let k = s.0.len();
        s.0.push(h);
        let value = match s.1 {
            Some(only) if only != k => 0.0,
            _ => 1.0,
        };
        CfLookup {
            value,
            clamped: false,
        }
    }
}

/// One looked-up category of a column: thickness (m), a_Pn, share of the strength sum.
#[derive(Clone, Copy, Debug)]
struct Looked {
    h: f64,
    ap: f64,
    share: f64,
}

/// The categories the strength routine looks C_f up at in one column.
fn looked_up(aicen: &[f64], vicen: &[f64], aice0: f64, opts_base: &StrengthOptions) -> Vec<Looked> {
    let ncat = aicen.len();
    let rec = Arc::new(Recorder::default());
    let mut opts = opts_base.clone();
    opts.cf = Cf::Custom(rec.clone());
    let mut ws = Workspace::new(ncat);
    let total = strength_column(aicen, vicen, Some(aice0), &opts, &mut ws)
        .expect("valid column")
        .strength;
    let hs = std::mem::take(&mut rec.state.lock().expect("not poisoned").0);
    // The same guard as the strength routine: aicen > puny and a_Pn > 0, in category order.
    let ap: Vec<f64> = (0..ncat)
        .filter(|&n| aicen[n] > opts.params.puny && ws.apartic()[n + 1] > 0.0)
        .map(|n| ws.apartic()[n + 1])
        .collect();
    assert_eq!(ap.len(), hs.len(), "one lookup per participating category");
    (0..hs.len())
        .map(|k| {
            rec.state.lock().expect("not poisoned").1 = Some(k);
            let part = strength_column(aicen, vicen, Some(aice0), &opts, &mut ws)
                .expect("valid column")
                .strength;
            rec.state.lock().expect("not poisoned").0.clear();
            Looked {
                h: hs[k],
                ap: ap[k],
                share: if total > 0.0 { part / total } else { 0.0 },
            }
        })
        .collect()
}

const UPPER: [f64; 7] = [1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0];

/// Counts, for one selection rule, the columns with selected ice outside [0.10, H].
struct Tally {
    name: &'static str,
    columns: usize,
    below: usize,
    above: [usize; UPPER.len()],
    hmin: f64,
    hmax: f64,
}

impl Tally {
    fn new(name: &'static str) -> Self {
        Tally {
            name,
            columns: 0,
            below: 0,
            above: [0; UPPER.len()],
            hmin: f64::INFINITY,
            hmax: 0.0,
        }
    }
    fn add(&mut self, hs: &[f64]) {
        if hs.is_empty() {
            return;
        }
        self.columns += 1;
        let lo = hs.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = hs.iter().copied().fold(0.0, f64::max);
        self.hmin = self.hmin.min(lo);
        self.hmax = self.hmax.max(hi);
        if lo < 0.10 {
            self.below += 1;
        }
        for (c, &u) in self.above.iter_mut().zip(&UPPER) {
            if hi > u {
                *c += 1;
            }
        }
    }
    fn print(&self) {
        let above: Vec<String> = UPPER
            .iter()
            .zip(&self.above)
            .map(|(u, c)| format!("> {u} m: {c}"))
            .collect();
        println!(
            "  {:<28} {:>5} columns, h {:.3}–{:.3} m; < 0.10 m: {}; {}",
            self.name,
            self.columns,
            self.hmin,
            self.hmax,
            self.below,
            above.join(", ")
        );
    }
}

/// A selection rule: its name and which looked-up categories it keeps.
type Rule = (&'static str, fn(&Looked) -> bool);

/// The four selection rules over a set of columns.
fn tally(columns: &[Vec<Looked>]) -> Vec<Tally> {
    let rules: [Rule; 4] = [
        ("a_Pn > 0 (as cf_clamped)", |l| l.ap > 0.0),
        ("a_Pn >= 1e-3", |l| l.ap >= 1e-3),
        ("a_Pn >= 1e-2", |l| l.ap >= 1e-2),
        ("share of strength >= 1 %", |l| l.share >= 0.01),
    ];
    rules
        .iter()
        .map(|(name, keep)| {
            let mut t = Tally::new(name);
            for c in columns {
                let hs: Vec<f64> = c.iter().filter(|l| keep(l)).map(|l| l.h).collect();
                t.add(&hs);
            }
            t
        })
        .collect()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let itd = PathBuf::from(args.first().map_or("data/sample_itd.nc", String::as_str));
    let cases = PathBuf::from(
        args.get(1)
            .map_or("tests/data/icepack/ridge_step_cases.jsonl", String::as_str),
    );

    // The sample file, CICE's defaults.
    let g = read_itd(&itd)?;
    let opts = StrengthOptions::default();
    let mut columns = Vec::new();
    let mut share_above = [0.0_f64; UPPER.len()];
    for c in 0..g.ncol() {
        if g.valid.as_ref().is_some_and(|v| !v[c]) {
            continue;
        }
        let aicen: Vec<f64> = g.aicen.column(c).to_vec();
        let vicen: Vec<f64> = g.vicen.column(c).to_vec();
        let aice0 = g
            .aice0
            .as_ref()
            .map_or_else(|| 1.0 - aicen.iter().sum::<f64>(), |a| a[c]);
        let l = looked_up(&aicen, &vicen, aice0, &opts);
        for (s, &u) in share_above.iter_mut().zip(&UPPER) {
            *s = s.max(l.iter().filter(|x| x.h > u).map(|x| x.share).sum());
        }
        columns.push(l);
    }
    println!(
        "{} ({} columns, {} with ice looked up; exponential participation and redistribution):",
        itd.display(),
        g.ncol(),
        columns.iter().filter(|c| !c.is_empty()).count()
    );
    for t in tally(&columns) {
        t.print();
    }
    let largest: Vec<String> = UPPER
        .iter()
        .zip(&share_above)
        .map(|(u, s)| format!("> {u} m: {:.1} %", 100.0 * s))
        .collect();
    println!(
        "  largest share of one column's strength from ice thicker than H: {}",
        largest.join(", ")
    );

    // The typical Icepack cases, each with its own options.
    println!("{} (group \"typical\"):", cases.display());
    let text = std::fs::read_to_string(&cases)?;
    for line in text.lines() {
        let v: serde_json::Value = serde_json::from_str(line)?;
        if v["kind"] != "case" || v["group"] != "typical" {
            continue;
        }
        let i = &v["inputs"];
        let f = |k: &str| -> Vec<f64> {
            i[k].as_array()
                .expect("array")
                .iter()
                .map(|x| x.as_f64().expect("number"))
                .collect()
        };
        let (aicen, vicen) = (f("aicen"), f("vicen"));
        let aice0 = i["aice0"].as_f64().expect("aice0");
        let mut o = StrengthOptions {
            participation: match i["krdg_partic"].as_i64() {
                Some(0) => Participation::Thorndike,
                _ => Participation::Exponential,
            },
            redistribution: match i["krdg_redist"].as_i64() {
                Some(0) => Redistribution::Uniform,
                _ => Redistribution::Exponential,
            },
            ..StrengthOptions::default()
        };
        if let Some(mu) = i["mu_rdg"].as_f64() {
            o.params.mu_rdg = mu;
        }
        let l = looked_up(&aicen, &vicen, aice0, &o);
        let cats: Vec<String> = l
            .iter()
            .map(|x| format!("{:.2} m (a_P {:.2e}, {:.1} %)", x.h, x.ap, 100.0 * x.share))
            .collect();
        println!(
            "  {} [{}, {}]: {}",
            v["case"].as_str().unwrap_or("?"),
            o.participation.name(),
            o.redistribution.name(),
            cats.join("; ")
        );
    }
    Ok(())
}
