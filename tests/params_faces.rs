//! The thickness-distribution parameters are listed once, in Rust (`ItdParams::FIELDS`);
//! the faces that cannot be generated from that list are checked against it here, as text:
//! the C struct `PressridgeParams` of `include/pressridge.h` and the Fortran type
//! `pressridge_params` of `fortran-bridge/src/pressridge_cabi.f90` (same fields, same order,
//! same types, the Fortran initial values equal to `ItdParams::default()`), and the Fortran
//! overrides by Icepack name in `pressridge_init_parameters`
//! (`fortran-bridge/src/pressridge_base.f90`). The Python face
//! (`PARAMETERS`, `DEFAULT_PARAMETERS`) is built from `ItdParams::FIELDS` by the extension.

use pressridge::itd::ItdParams;

/// The one documented difference: the C layout (and the Fortran type, which binds it)
/// keeps the doubles first and puts the one integer, `nitermax` (`int64_t`), last.
const MOVED_TO_END: &[&str] = &["nitermax"];

/// The Fortran source that declares the type `pressridge_params` (the C ABI's types).
const FORTRAN_TYPES: &str = "fortran-bridge/src/pressridge_cabi.f90";

/// The Fortran source of `pressridge_init_parameters` (the overrides by Icepack name).
const FORTRAN_OVERRIDES: &str = "fortran-bridge/src/pressridge_base.f90";

/// The Rust names in the order of the C and Fortran faces, with the C type of each.
fn expected() -> Vec<(&'static str, &'static str)> {
    let ty = |n: &str| {
        if n == "nitermax" { "int64_t" } else { "double" }
    };
    for m in MOVED_TO_END {
        assert!(
            ItdParams::NAMES.contains(m),
            "{m} is not an ItdParams field"
        );
    }
    ItdParams::NAMES
        .iter()
        .copied()
        .filter(|n| !MOVED_TO_END.contains(n))
        .chain(MOVED_TO_END.iter().copied())
        .map(|n| (n, ty(n)))
        .collect()
}

fn read(rel: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The text between the line starting with `start` and the next line starting with `end`.
fn block<'a>(text: &'a str, start: &str, end: &str, file: &str) -> Vec<&'a str> {
    let mut lines = text.lines().map(str::trim);
    lines
        .by_ref()
        .find(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("{file}: no line starting with `{start}`"));
    let body: Vec<&str> = lines.by_ref().take_while(|l| !l.starts_with(end)).collect();
    body
}

/// (name, C type) of the fields of the C struct, in order.
fn c_fields() -> Vec<(String, String)> {
    let file = "include/pressridge.h";
    let text = read(file);
    block(
        &text,
        "typedef struct PressridgeParams {",
        "} PressridgeParams;",
        file,
    )
    .into_iter()
    .map(|l| l.split("//").next().unwrap().trim())
    .filter(|l| !l.is_empty())
    .map(|l| {
        let decl = l
            .strip_suffix(';')
            .unwrap_or_else(|| panic!("{file}: cannot read the field `{l}`"));
        let (ty, name) = decl
            .rsplit_once(' ')
            .unwrap_or_else(|| panic!("{file}: cannot read the field `{l}`"));
        (name.trim().to_string(), ty.trim().to_string())
    })
    .collect()
}

/// (name, C type, initial value) of the components of the Fortran type, in order.
fn fortran_fields() -> Vec<(String, String, f64)> {
    let file = FORTRAN_TYPES;
    let text = read(file);
    block(
        &text,
        "type, bind(C), public :: pressridge_params",
        "end type pressridge_params",
        file,
    )
    .into_iter()
    .map(|l| l.split('!').next().unwrap().trim())
    .filter(|l| !l.is_empty())
    .map(|l| {
        let (ty, rest) = l
            .split_once("::")
            .unwrap_or_else(|| panic!("{file}: cannot read the component `{l}`"));
        let (name, init) = rest
            .split_once('=')
            .unwrap_or_else(|| panic!("{file}: `{l}` has no initial value"));
        let cty = match ty.trim() {
            "real(c_double)" => "double",
            "integer(c_int64_t)" => "int64_t",
            other => panic!("{file}: type `{other}` of `{l}` not handled"),
        };
        let init = init.trim();
        let number = init.split("_c_").next().unwrap();
        let value: f64 = number
            .parse()
            .unwrap_or_else(|_| panic!("{file}: cannot read the initial value `{init}` of `{l}`"));
        (name.trim().to_lowercase(), cty.to_string(), value)
    })
    .collect()
}

#[test]
fn c_struct_has_the_rust_fields_in_order() {
    let c = c_fields();
    let want = expected();
    assert_eq!(
        c.iter()
            .map(|(n, t)| (n.as_str(), t.as_str()))
            .collect::<Vec<_>>(),
        want,
        "PressridgeParams in include/pressridge.h (crates/capi/src/itd.rs) against ItdParams::FIELDS \
         (with {MOVED_TO_END:?} last)"
    );
}

#[test]
fn fortran_type_has_the_rust_fields_in_order_with_the_rust_defaults() {
    let f = fortran_fields();
    let want = expected();
    assert_eq!(
        f.iter()
            .map(|(n, t, _)| (n.as_str(), t.as_str()))
            .collect::<Vec<_>>(),
        want,
        "pressridge_params in {FORTRAN_TYPES} against ItdParams::FIELDS \
         (with {MOVED_TO_END:?} last, as the C struct it binds)"
    );
    let d = ItdParams::default();
    for (name, _, value) in &f {
        assert_eq!(
            Some(*value),
            d.get(name),
            "initial value of pressridge_params%{name} in {FORTRAN_TYPES}"
        );
    }
}

/// `pressridge_init_parameters` takes Icepack's names (`Gstar`, `Pstar`, ...), which are
/// the Rust names up to case (Fortran ignores case): each `if (present(X)) ...%params%y = X`
/// sets the field y = lower-case X, and y is a Rust name.
#[test]
fn fortran_overrides_by_icepack_name_set_the_field_of_that_name() {
    let file = FORTRAN_OVERRIDES;
    let text = read(file);
    let mut seen = 0;
    for line in text.lines().map(str::trim) {
        let Some((lhs, rhs)) = line.split_once("%params%") else {
            continue;
        };
        let (field, value) = rhs
            .split_once('=')
            .map(|(a, b)| (a.trim(), b.trim()))
            .unwrap_or((rhs.trim(), ""));
        let field = field.to_lowercase();
        assert!(
            ItdParams::NAMES.contains(&field.as_str()),
            "{file}: `{line}` names a parameter `{field}` that ItdParams::FIELDS does not list"
        );
        if let Some(arg) = lhs
            .strip_prefix("if (present(")
            .and_then(|r| r.split_once(')'))
            .map(|(a, _)| a)
        {
            assert_eq!(arg.to_lowercase(), field, "{file}: `{line}`");
            assert_eq!(value, arg, "{file}: `{line}`");
            seen += 1;
        }
    }
    assert!(seen >= 10, "{file}: only {seen} overrides found");
}

/// The Python extension's `param_names` and `default_params` are built from
/// `ItdParams::NAMES` and `ItdParams::FIELDS` and list no parameter by hand (in any of its
/// source files).
#[test]
fn python_extension_takes_the_parameters_from_the_rust_list() {
    let file = "python/src/*.rs";
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("python/src");
    let mut names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    names.sort();
    assert!(names.len() > 1, "{file}: {names:?}");
    let text: String = names
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    assert!(
        text.contains("ItdParams::NAMES.to_vec()"),
        "{file}: param_names"
    );
    assert!(
        text.contains("for f in ItdParams::FIELDS"),
        "{file}: default_params"
    );
    for f in ItdParams::FIELDS {
        assert!(
            !text.contains(&format!("\"{}\"", f.name)),
            "{file} spells the parameter \"{}\" out: take it from ItdParams::FIELDS",
            f.name
        );
    }
}
