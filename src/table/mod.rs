//! Tabulation of ridging ensembles for large-scale ice models.
//!
//! - [`fit`] — least-squares fits of work and potential energy against ridged volume
//!   (Hopkins 1994, eqs 13–16), with confidence and prediction bands;
//! - [`tabulate`] — campaign records to a lookup table (ensemble statistics on a volume
//!   grid, fits per thickness and pooled, C_f per thickness).

pub mod fit;
pub mod tabulate;
