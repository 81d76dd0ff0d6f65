//! # pressridge-lab
//!
//! The research lab of pressridge, apart from the products: what the project's own studies
//! read and print, and nothing a host model or a table user links.
//!
//! - [`findings`] — each finding Hopkins (1994) states in words, tested on ensembles of
//!   committed run records, with its 95 % interval and a verdict (`pressridge findings`,
//!   `docs/findings.md`);
//! - [`choices`] — the register of open modelling choices: each probe campaign's shift from
//!   its baseline, with Welch's 95 % interval (`pressridge findings --choices`,
//!   `docs/choices.md`);
//! - [`equivalence`] — the step's equivalence test, shared by the programs that judge a
//!   numerical change on ensembles;
//! - the investigation programs behind `docs/` (`crates/lab/research/`, examples of this
//!   crate: `cargo run --release --example NAME`);
//! - the committed run records all of these read (`crates/lab/records/`, records-only
//!   campaign archives: the provenance of the shipped table and of the docs' numbers).
//!
//! Everything here reads the products' data types (`pressridge::record::RunRecord`,
//! `pressridge::scene::Scene`, `pressridge::table`); no product crate depends on this one.
//!
//! ## Example: the findings on a set of records
//!
//! ```
//! use pressridge::scene::Scene;
//! use pressridge_lab::findings::{findings, markdown};
//!
//! // No records: the table names the runs it lacks instead of judging on too few.
//! let missing = findings(&[], 2, &Scene::default()).unwrap_err();
//! assert!(!missing.to_string().is_empty());
//! # let _ = markdown;
//! ```

#![warn(missing_docs)]

pub mod choices;
pub mod equivalence;
pub mod findings;
