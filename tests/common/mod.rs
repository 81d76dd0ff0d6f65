//! Helpers of the integration tests: the command-line binary (for the tests of crates/cli,
//! which include this module by path, as those of crates/capi do), scratch directories and
//! small NetCDF inputs written value by value; the library's step of one column ([`column`]),
//! Icepack's reference cases ([`icepack`]) and a small gridded distribution ([`grid`]).
#![allow(dead_code)]

pub mod column;
pub mod grid;
pub mod icepack;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `pressridge` binary, run from the repository's root (relative paths such as
/// `data/sample_itd.nc` name the repository's files). HDF5 file locking is off for
/// everything cargo runs: see `.cargo/config.toml`. Only the tests of the crate that builds
/// the binary, crates/cli, have it.
pub fn bin() -> Command {
    match option_env!("CARGO_BIN_EXE_pressridge") {
        Some(path) => {
            let mut c = Command::new(path);
            c.current_dir(repo());
            c
        }
        None => panic!("the `pressridge` binary is crates/cli's: call bin() from its tests"),
    }
}

/// The repository's root (the folder of `Cargo.lock`): these helpers serve the tests of the
/// root package and of the crates under `crates/`.
pub fn repo() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .find(|d| d.join("Cargo.lock").is_file())
        .expect("Cargo.lock above the package")
}

/// A fresh, empty scratch directory for test `name`, removed when the test passes and kept
/// (for a look at what the test left) when it panics.
pub fn scratch(name: &str) -> Scratch {
    let d = std::env::temp_dir().join(format!("pressridge-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    Scratch(d)
}

/// A scratch directory that removes itself on drop unless the thread is panicking.
pub struct Scratch(PathBuf);

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<std::ffi::OsStr> for Scratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.as_os_str()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

/// Asserts that a command failed with exit code 1 (not a signal, not a panic) and a one-line
/// error containing every needle.
pub fn fails_with(out: &Output, needles: &[&str]) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(1),
        "expected a clean failure, got {:?}: {err}",
        out.status
    );
    assert!(!err.contains("panicked"), "panic: {err}");
    let lines: Vec<&str> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "not one line: {err}");
    for n in needles {
        assert!(err.contains(n), "message lacks `{n}`: {err}");
    }
}

/// Asserts success and returns stdout.
pub fn succeeds(out: &Output) -> String {
    assert!(
        out.status.success(),
        "{:?}: {}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Values of a test variable.
#[derive(Clone, Debug)]
pub enum Data {
    F64(Vec<f64>),
    I32(Vec<i32>),
    /// A string (text) variable, left at its fill value.
    Text,
}

/// A variable of a test file: name, dimensions (name, length), values, `units` attribute.
#[derive(Clone, Debug)]
pub struct Var {
    pub name: String,
    pub dims: Vec<(String, usize)>,
    pub data: Data,
    pub units: Option<String>,
}

impl Var {
    pub fn f64(name: &str, dims: &[(&str, usize)], v: Vec<f64>) -> Var {
        Var {
            name: name.into(),
            dims: dims.iter().map(|(n, l)| (n.to_string(), *l)).collect(),
            data: Data::F64(v),
            units: None,
        }
    }

    /// The same variable with a `units` attribute.
    pub fn with_units(mut self, units: &str) -> Var {
        self.units = Some(units.into());
        self
    }
}

/// Writes `vars` into a new NetCDF file (classic 64-bit-offset format). Dimensions are made as
/// the variables name them; the first length given for a name wins.
pub fn write_nc(path: &Path, vars: &[Var]) {
    // One writer at a time in this process: the tests of a binary run on several threads,
    // and HDF5 (under the NetCDF-4 files) is not reliably thread-safe.
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _guard = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let _ = std::fs::remove_file(path);
    // Text needs the NetCDF-4 format (string variables); the rest is written as the
    // library writes.
    // So does an empty (unlimited) dimension that is not the first of its variables.
    let nc4 = vars
        .iter()
        .any(|v| matches!(v.data, Data::Text) || v.dims.iter().any(|d| d.1 == 0));
    let mut f = if nc4 {
        netcdf::create(path).unwrap()
    } else {
        netcdf::create_with(path, netcdf::Options::_64BIT_OFFSET).unwrap()
    };
    let mut made: Vec<String> = Vec::new();
    for v in vars {
        for (n, l) in &v.dims {
            if !made.contains(n) {
                f.add_dimension(n, *l).unwrap();
                made.push(n.clone());
            }
        }
    }
    for v in vars {
        let dims: Vec<&str> = v.dims.iter().map(|d| d.0.as_str()).collect();
        match &v.data {
            Data::F64(_) => {
                f.add_variable::<f64>(&v.name, &dims).unwrap();
            }
            Data::I32(_) => {
                f.add_variable::<i32>(&v.name, &dims).unwrap();
            }
            Data::Text => {
                f.add_string_variable(&v.name, &dims).unwrap();
            }
        }
        if let Some(u) = &v.units {
            f.variable_mut(&v.name)
                .unwrap()
                .put_attribute("units", u.as_str())
                .unwrap();
        }
    }
    f.enddef().unwrap();
    for v in vars {
        let mut var = f.variable_mut(&v.name).unwrap();
        let n: usize = v.dims.iter().map(|d| d.1).product();
        match &v.data {
            Data::F64(x) if n > 0 && x.len() == n => var.put_values(x, ..).unwrap(),
            Data::I32(x) if n > 0 && x.len() == n => var.put_values(x, ..).unwrap(),
            _ => {}
        }
    }
    f.close().unwrap();
}

/// Writes `vars` (name, dimension names, values) into a new classic-format NetCDF file with
/// the dimensions `dims` (name, length): [`write_nc`] for `f64` variables.
pub fn write_f64(path: &Path, dims: &[(&str, usize)], vars: &[(&str, &[&str], Vec<f64>)]) {
    let len = |d: &str| {
        dims.iter()
            .find(|x| x.0 == d)
            .unwrap_or_else(|| panic!("no dimension {d}"))
            .1
    };
    let vars: Vec<Var> = vars
        .iter()
        .map(|(name, ds, v)| {
            let ds: Vec<(&str, usize)> = ds.iter().map(|&d| (d, len(d))).collect();
            Var::f64(name, &ds, v.clone())
        })
        .collect();
    write_nc(path, &vars);
}

/// The `_FillValue` of variable `name` of a NetCDF file, if it has one as a number.
pub fn fill_value(path: &Path, name: &str) -> Option<f64> {
    let f = netcdf::open(path).unwrap();
    let v = f
        .variable(name)
        .unwrap_or_else(|| panic!("output has no `{name}`"));
    v.attributes()
        .find(|a| a.name() == "_FillValue")
        .and_then(|a| a.value().ok())
        .and_then(|x| f64::try_from(x).ok())
}

/// The values of variable `name` of a NetCDF file, as `f64`, in C order.
pub fn read_values(path: &Path, name: &str) -> Vec<f64> {
    let f = netcdf::open(path).unwrap();
    let v = f
        .variable(name)
        .unwrap_or_else(|| panic!("output has no `{name}`"));
    v.get_values::<f64, _>(..).unwrap()
}

/// The text global attribute `name` of a NetCDF file.
pub fn global(path: &Path, name: &str) -> String {
    let f = netcdf::open(path).unwrap();
    f.attribute(name)
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok())
        .unwrap_or_else(|| panic!("no global attribute {name}"))
}

/// A valid 2-category distribution on a 2 × 3 grid with bounds, divergence and shear.
pub fn good_itd() -> Vec<Var> {
    let cat = [("nc", 2), ("y", 2), ("x", 3)];
    let sp = [("y", 2), ("x", 3)];
    let mut aicen = vec![0.4; 6];
    aicen.extend(vec![0.4; 6]);
    let mut vicen = vec![0.2; 6];
    vicen.extend(vec![0.8; 6]);
    vec![
        Var::f64("aicen", &cat, aicen),
        Var::f64("vicen", &cat, vicen),
        Var::f64("aice0", &sp, vec![0.2; 6]),
        Var::f64("hin_max", &[("nb", 3)], vec![0.0, 1.0, 3.0]),
        Var::f64("divu", &sp, vec![-1e-6; 6]).with_units("s-1"),
        Var::f64("shear", &sp, vec![0.0; 6]).with_units("s-1"),
    ]
}

/// A tiny campaign spec: two thicknesses × two seeds of a 3-s run of an 8-m sheet, sampled
/// every second (the campaign tests of the library and of the command line).
pub const TINY_CAMPAIGN: &str = r#"
name = "tiny"
seeds = 2
sample_interval = 1.0
set = ["duration=3.0", "sheet.length=8.0", "floe.nose_slope=1.0"]

[[axis]]
keys = ["sheet.thickness", "sheet.block_width"]
values = [[0.25, 0.25], [0.35, 0.25]]
"#;

/// Runs `pressridge simulate` with `args` into a fresh scratch directory for test `name`,
/// asserts success and returns the directory.
pub fn simulate(name: &str, args: &[&str]) -> Scratch {
    let dir = scratch(name);
    let mut cmd = bin();
    cmd.arg("simulate").args(args).arg("--out").arg(&dir);
    succeeds(&cmd.output().unwrap());
    dir
}

/// The names of the files in `dir` (sorted).
pub fn names_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .map(|it| {
            it.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

// A small deterministic pseudo-random generator (SplitMix64) for fuzzing and kill delays:
// the simulator's tests' one, included by path.
#[path = "../../crates/sim/tests/support/rng.rs"]
mod rng;
#[allow(unused_imports)] // not every test binary that includes this module draws noise
pub use rng::Rng;

/// A ridging table as `pressridge tabulate` lays out its friction grid, holding only
/// `mu_rdg(thickness, mu, mu_w)` (m^0.5): two friction pairs, (μ, μ_w) = (0.4, 0.6) with
/// `mu_rdg[0]` and (1.0, 0.6) with `mu_rdg[1]`, at the thicknesses `h` (m).
#[allow(dead_code)]
pub fn write_mu_rdg_table(path: &Path, h: &[f64], mu_rdg: [&[f64]; 2]) {
    write_friction_grid(path, h, "mu_rdg", "m^0.5", mu_rdg);
}

/// A ridging table as [`write_mu_rdg_table`] lays it out, holding C_f (`cf_by_set`'s values
/// as `cf`) and no `mu_rdg`: a table made from records without ridge columns.
#[allow(dead_code)]
pub fn write_table_without_mu_rdg(path: &Path, h: &[f64]) {
    let cf = vec![17.0; h.len()];
    write_friction_grid(path, h, "cf", "1", [&cf, &cf]);
}

fn write_friction_grid(path: &Path, h: &[f64], name: &str, units: &str, v: [&[f64]; 2]) {
    let nh = h.len();
    let grid: Vec<f64> = (0..nh).flat_map(|k| [v[0][k], v[1][k]]).collect();
    write_nc(
        path,
        &[
            Var::f64("thickness", &[("thickness", nh)], h.to_vec()),
            Var::f64("volume", &[("volume", 1)], vec![0.0]),
            Var::f64("mu", &[("mu", 2)], vec![0.4, 1.0]),
            Var::f64("mu_w", &[("mu_w", 1)], vec![0.6]),
            Var::f64(name, &[("thickness", nh), ("mu", 2), ("mu_w", 1)], grid).with_units(units),
        ],
    );
}
