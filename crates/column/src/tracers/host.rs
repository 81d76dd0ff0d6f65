//! A host's own tracer tables (Icepack's `trcr_depend`, `trcr_base`, `n_trcr_strata`,
//! `nt_strata`) laid over a layout ([`TracerLayout::with_host_tables`]).

use super::{TracerBase, TracerLayout};
use crate::ItdError;

impl TracerLayout {
    /// The layout with `n` more single-level tracers at its end that the flags do not name
    /// (role [`super::TracerRole::Other`], carried on the area, no strata, one field
    /// `unnamed` with `n` levels), for a host whose tracer array is longer than its flags'
    /// layout: CICE adds one slot after every tracer its flags count (`ice_init_column.F90`,
    /// `count_tracers`: `ntrcr = ntrcr + 1`), where the indices of the tracers that are off
    /// point, and Icepack ridges it as any area tracer. The layout's other settings are kept;
    /// a host's tables given after this ([`TracerLayout::with_host_tables`]) may carry them
    /// otherwise. `n = 0` gives the layout back.
    pub fn with_unnamed_tracers(mut self, n: usize) -> Self {
        if n == 0 {
            return self;
        }
        self.starts.push(self.ntrcr);
        self.fields.push(super::TracerField {
            name: "unnamed".to_string(),
            role: super::TracerRole::Other,
            levels: n,
            base: TracerBase::Area,
            strata: Vec::new(),
            empty: 0.0,
        });
        self.ntrcr += n;
        self.base.extend(std::iter::repeat_n(TracerBase::Area, n));
        self.base_idx.extend(std::iter::repeat_n(0, n));
        self.nstrata.extend(std::iter::repeat_n(0, n));
        self.strata.extend(std::iter::repeat_n([0, 0], n));
        self.empty.extend(std::iter::repeat_n(0.0, n));
        if let Some(d) = &mut self.host_depend {
            d.extend(std::iter::repeat_n(0, n));
        }
        self.derive_lists();
        self
    }

    /// The layout with each tracer carried as a host's tables say (Icepack's `trcr_depend`,
    /// `trcr_base(ntrcr, 3)` in Fortran order, `n_trcr_strata`, `nt_strata(ntrcr, 2)` in
    /// Fortran order, 1-based tracer numbers), as Icepack moves every tracer through them:
    /// the base and strata of each tracer are the host's, the roles (which tracer is an
    /// enthalpy, a pond, an aerosol...) stay the layout's. For a host whose tables differ from
    /// those the layout derives (e.g. Icepack's column driver gives only the first isotope
    /// species its dependency; the others are area tracers there). Each `trcr_base` row must
    /// hold one 1 and two 0; a stratum must be an earlier single tracer. `trcr_depend` is
    /// kept as given, as Icepack keeps it: it decides only which branch of
    /// `icepack_compute_tracers` a tracer takes (0: the area, where it exceeds `puny`), so it
    /// may disagree with the base and strata. Icepack's column driver sets its bio tracers'
    /// `trcr_depend` to `2 + nt_fbri` and then resets their bases to the area and their strata
    /// to none (`icedrv_init.F90`, `init_state`), and ridges them so. It must be 0, 1, 2 or
    /// `2 + nt` with `nt` a tracer (1-based).
    pub fn with_host_tables(
        mut self,
        trcr_depend: &[i32],
        trcr_base: &[f64],
        n_trcr_strata: &[i32],
        nt_strata: &[i32],
    ) -> Result<Self, ItdError> {
        let nt = self.ntrcr;
        let bad = |msg: String| ItdError::Layout(format!("host tracer tables: {msg}"));
        if trcr_depend.len() != nt
            || trcr_base.len() != 3 * nt
            || n_trcr_strata.len() != nt
            || nt_strata.len() != 2 * nt
        {
            return Err(bad(format!(
                "need trcr_depend({nt}), trcr_base({nt}, 3), n_trcr_strata({nt}), \
                 nt_strata({nt}, 2)"
            )));
        }
        for it in 0..nt {
            let row = [trcr_base[it], trcr_base[nt + it], trcr_base[2 * nt + it]];
            let k = match row {
                [1.0, 0.0, 0.0] => 0u8,
                [0.0, 1.0, 0.0] => 1,
                [0.0, 0.0, 1.0] => 2,
                _ => {
                    return Err(bad(format!(
                        "tracer {}: trcr_base {row:?} is not one of area, ice volume, snow volume",
                        it + 1
                    )));
                }
            };
            let n = n_trcr_strata[it];
            if !(0..=2).contains(&n) {
                return Err(bad(format!("tracer {}: n_trcr_strata = {n}", it + 1)));
            }
            let mut st = [0usize; 2];
            for j in 0..n as usize {
                let s1 = nt_strata[j * nt + it];
                if !(1..=it as i32).contains(&s1) {
                    return Err(bad(format!(
                        "tracer {}: stratum {s1} must be an earlier tracer (1-based)",
                        it + 1
                    )));
                }
                st[j] = s1 as usize - 1;
            }
            let d = trcr_depend[it];
            if !(0..=2 + nt as i32).contains(&d) {
                return Err(bad(format!(
                    "tracer {}: trcr_depend = {d}: must be 0 (area), 1 (ice volume), 2 (snow \
                     volume) or 2 + a tracer (1 to {nt})",
                    it + 1
                )));
            }
            self.base_idx[it] = k;
            self.base[it] = TracerBase::ALL[k as usize];
            self.nstrata[it] = n as u8;
            self.strata[it] = st;
            if k == 0 {
                self.empty[it] = 0.0;
            }
        }
        // Kept only where it says more than the bases and strata do, so that a host giving
        // the layout's own tables gets the layout back.
        self.host_depend = None;
        self.host_depend = (self.trcr_depend() != trcr_depend).then(|| trcr_depend.to_vec());
        self.derive_lists();
        Ok(self)
    }
}
