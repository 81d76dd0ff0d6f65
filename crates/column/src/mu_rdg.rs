//! Lipscomb's e-folding parameter μ_rdg as a function of the ridging ice's thickness, from a
//! ridging table of simulated ridges (issue 34): the exponential redistribution of Lipscomb
//! et al. (2007), λ = μ_rdg(h)·√h, with μ_rdg read per category thickness h instead of one
//! constant (`ItdParams::mu_rdg`). Piecewise linear between the table's nodes and held at
//! the end value outside them, with the lookup flagged as clamped, as C_f is
//! ([`crate::details::CfTable`]).
//!
//! The nodes are held inline (at most [`MU_RDG_MAX_NODES`]) so that the options that carry
//! the table stay `Copy`, as a host's per-cell calls need them.

use super::ItdError;
use crate::limits;

/// Most nodes a [`MuRdgTable`] holds: a ridging table has one per tabulated lead-ice
/// thickness (19 in the shipped one).
pub const MU_RDG_MAX_NODES: usize = 32;

/// μ_rdg (m^½) at node thicknesses (m); see the module documentation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MuRdgTable {
    len: usize,
    thickness: [f64; MU_RDG_MAX_NODES],
    mu_rdg: [f64; MU_RDG_MAX_NODES],
}

/// One lookup of a [`MuRdgTable`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MuRdgLookup {
    /// μ_rdg (m^½).
    pub value: f64,
    /// The thickness lay outside the table's nodes and the end value was used.
    pub clamped: bool,
}

impl MuRdgTable {
    /// A table from node thicknesses (m; strictly increasing, in
    /// [`limits::CATEGORY_THICKNESS`]) and μ_rdg values (m^½, in [`limits::MU_RDG`]): 1 to
    /// [`MU_RDG_MAX_NODES`] nodes.
    pub fn new(thickness: &[f64], mu_rdg: &[f64]) -> Result<Self, ItdError> {
        if thickness.len() > MU_RDG_MAX_NODES {
            return Err(ItdError::MuRdgTable(format!(
                "{} nodes: give 1 to {MU_RDG_MAX_NODES}",
                thickness.len()
            )));
        }
        super::nodes::check(thickness, "mu_rdg", mu_rdg, limits::MU_RDG)
            .map_err(ItdError::MuRdgTable)?;
        let mut t = MuRdgTable {
            len: thickness.len(),
            thickness: [0.0; MU_RDG_MAX_NODES],
            mu_rdg: [0.0; MU_RDG_MAX_NODES],
        };
        t.thickness[..t.len].copy_from_slice(thickness);
        t.mu_rdg[..t.len].copy_from_slice(mu_rdg);
        Ok(t)
    }

    /// As [`MuRdgTable::new`], leaving out the nodes whose μ_rdg is NaN (a thickness no run
    /// of the table reached, or whose runs kept no ridge columns); at least one must remain.
    pub fn from_nodes(thickness: &[f64], mu_rdg: &[f64]) -> Result<Self, ItdError> {
        let (h, m) =
            super::nodes::known(thickness, "mu_rdg", mu_rdg).map_err(ItdError::MuRdgTable)?;
        Self::new(&h, &m)
    }

    /// Node thicknesses (m).
    pub fn thickness(&self) -> &[f64] {
        &self.thickness[..self.len]
    }

    /// Node values of μ_rdg (m^½).
    pub fn values(&self) -> &[f64] {
        &self.mu_rdg[..self.len]
    }

    /// μ_rdg at thickness `h` (m); a NaN `h` gives the first node's value, flagged clamped.
    #[inline]
    pub fn lookup(&self, h: f64) -> MuRdgLookup {
        let (value, clamped) = super::nodes::lookup(self.thickness(), self.values(), h);
        MuRdgLookup { value, clamped }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookups_interpolate_between_nodes_and_hold_the_ends() {
        let t = MuRdgTable::new(&[0.2, 0.4, 1.0], &[2.0, 3.0, 1.0]).unwrap();
        assert_eq!(t.thickness(), [0.2, 0.4, 1.0]);
        let at = |h: f64| t.lookup(h);
        assert_eq!(at(0.3).value, 2.5);
        assert!(!at(0.3).clamped);
        assert_eq!(at(0.7).value, 2.0);
        assert_eq!((at(0.2).value, at(0.2).clamped), (2.0, false));
        assert_eq!((at(1.0).value, at(1.0).clamped), (1.0, false));
        assert_eq!((at(0.05).value, at(0.05).clamped), (2.0, true));
        assert_eq!((at(5.0).value, at(5.0).clamped), (1.0, true));
    }

    #[test]
    fn bad_tables_are_refused_by_name() {
        let why = |h: &[f64], m: &[f64]| MuRdgTable::new(h, m).unwrap_err().to_string();
        assert!(why(&[], &[]).contains("no nodes"));
        assert!(why(&[0.2], &[1.0, 2.0]).contains("mu_rdg has 2"));
        assert!(why(&[0.4, 0.2], &[1.0, 2.0]).contains("not strictly increasing"));
        assert!(why(&[0.2], &[0.0]).contains("mu_rdg[0]"));
        assert!(why(&[0.2], &[f64::NAN]).contains("mu_rdg[0]"));
        assert!(why(&[-1.0], &[1.0]).contains("thickness[0]"));
        let many: Vec<f64> = (1..=33).map(f64::from).collect();
        assert!(why(&many, &many).contains("33 nodes"));
        let t = MuRdgTable::from_nodes(&[0.2, 0.3, 0.4], &[1.0, f64::NAN, 2.0]).unwrap();
        assert_eq!(t.values(), [1.0, 2.0]);
        assert!(MuRdgTable::from_nodes(&[0.2], &[f64::NAN]).is_err());
    }
}
