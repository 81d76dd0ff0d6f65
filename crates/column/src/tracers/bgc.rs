//! Biogeochemical tracers (Icepack's `skl_bgc` or `z_tracers` with `nbtrcr` bio tracers):
//! appended to a layout after every other tracer, carried as a host's tracer tables say
//! ([`TracerLayout::with_host_tables`]), and booked in the biogeochemical flux to the ocean,
//! `flux_bio` (mmol or kg m⁻² s⁻¹, the tracer's unit times m s⁻¹), where ridging puts snow into
//! the ocean and where the clean-up zaps ice and snow (`icepack_mechred.F90` `ridge_shift`,
//! `icepack_itd.F90` `zap_small_areas`, `zap_snow`, `zap_small_bgc`).

use super::{TracerBase, TracerField, TracerLayout, TracerRole};
use crate::ItdError;

/// Most bio tracers a layout may carry (Icepack's `icepack_max_nbtrcr`: algal nitrogen and
/// chlorophyll for 3 algae, DIC, 3 DOC, DON, nitrate, ammonium, silicate, PON, humics, 3 DMS
/// species, 2 × 2 iron, 6 aerosols).
pub const MAX_NBTRCR: usize = 29;

/// How the bio tracers are resolved in the vertical.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BgcKind {
    /// Icepack's `skl_bgc`: one value per bio tracer, in the skeletal layer at the ice bottom,
    /// `sk_l` thick (m; Icepack's default 0.03 m), carried on ice area.
    Skeletal {
        /// Skeletal layer thickness (m, > 0).
        sk_l: f64,
    },
    /// Icepack's `z_tracers`: per bio tracer `nblyr + 1` values on the brine grid of the ice
    /// (carried on the brine fraction `fbri`, which the layout must have) and two in the snow
    /// (surface layer and interior, carried on snow volume).
    Vertical {
        /// Bio grid layers in the ice (Icepack's `nblyr`, ≥ 1).
        nblyr: usize,
    },
}

/// The bio tracers of a layout: their kind and, per bio tracer, its first tracer (0-based,
/// Icepack's `bio_index` less one).
#[derive(Debug, Clone, PartialEq)]
pub struct BgcTracers {
    /// Skeletal or vertically resolved.
    pub kind: BgcKind,
    /// Per bio tracer (at most [`MAX_NBTRCR`]), its first tracer, 0-based, among the tracers
    /// appended by [`TracerLayout::with_bgc`].
    pub bio_index: Vec<usize>,
}

impl BgcTracers {
    /// Tracers per bio tracer: 1 (skeletal) or `nblyr + 3` (vertical).
    pub fn levels(&self) -> usize {
        match self.kind {
            BgcKind::Skeletal { .. } => 1,
            BgcKind::Vertical { nblyr } => nblyr + 3,
        }
    }

    /// Per bio tracer, its content in the snow of one category (`trc`, the category's
    /// tracers): `ssl` times its snow surface-layer value plus `int` times its interior value
    /// (Icepack's `dzssl`/`dzint` or `dvssl`/`dvint`). None for skeletal tracers, which have
    /// no snow levels.
    pub(crate) fn snow_content<'a>(
        &'a self,
        trc: &'a [f64],
        ssl: f64,
        int: f64,
    ) -> impl Iterator<Item = f64> + 'a {
        let (nblyr, count) = match self.kind {
            BgcKind::Vertical { nblyr } => (nblyr, self.bio_index.len()),
            BgcKind::Skeletal { .. } => (0, 0),
        };
        self.bio_index[..count]
            .iter()
            .map(move |&bi| trc[bi + nblyr + 1] * ssl + trc[bi + nblyr + 2] * int)
    }
}

impl TracerLayout {
    /// The layout with `extra` more tracers after every other, the biogeochemical tracers of a
    /// host (Icepack's tracers from `ntrcr_o + 1` on: the bio tracers and what goes with them,
    /// e.g. `zbgc_frac`), of which `bgc.bio_index` names the bio tracers whose fluxes to the
    /// ocean the step books in `OceanFluxes::flux_bio`. The extra tracers are carried on ice
    /// volume until a host's tables say otherwise: give Icepack's tables with
    /// [`TracerLayout::with_host_tables`] after this call (which it must precede, as it must
    /// precede [`TracerLayout::with_empty_value`]). Vertical bio tracers need the brine
    /// fraction `fbri`.
    pub fn with_bgc(self, extra: usize, bgc: BgcTracers) -> Result<Self, ItdError> {
        let bad = |m: String| Err(ItdError::Layout(format!("biogeochemical tracers: {m}")));
        let nbtrcr = bgc.bio_index.len();
        if nbtrcr == 0 || nbtrcr > MAX_NBTRCR {
            return bad(format!("{nbtrcr} bio tracers: give 1 to {MAX_NBTRCR}"));
        }
        if self.bgc.is_some() {
            return bad("the layout has them already".into());
        }
        match bgc.kind {
            BgcKind::Skeletal { sk_l } if !(sk_l > 0.0 && sk_l.is_finite()) => {
                return bad(format!(
                    "skeletal layer thickness sk_l = {sk_l} m: must be > 0"
                ));
            }
            BgcKind::Vertical { nblyr: 0 } => {
                return bad("nblyr = 0: the vertical bio grid needs at least one layer".into());
            }
            BgcKind::Vertical { .. } if self.nt_fbri.is_none() => {
                return bad(
                    "vertically resolved bio tracers (z_tracers) need the brine fraction fbri"
                        .into(),
                );
            }
            _ => {}
        }
        let levels = bgc.levels();
        let start = self.ntrcr;
        for (it, &b) in bgc.bio_index.iter().enumerate() {
            if b < start || b + levels > start + extra {
                return bad(format!(
                    "bio tracer {} starts at tracer {b} and spans {levels}, outside the \
                     {extra} appended tracers {start}..{}",
                    it + 1,
                    start + extra
                ));
            }
        }
        let zap_pond_water = self.zap_pond_water;
        let mut fields = self.fields;
        fields.push(TracerField::new(
            "bgc",
            TracerRole::Other,
            extra,
            TracerBase::IceVolume,
            &[],
        ));
        let mut l = Self::new(fields)?;
        l.zap_pond_water = zap_pond_water;
        l.bgc = Some(bgc);
        Ok(l)
    }

    /// The bio tracers whose fluxes the step books, if any.
    pub fn bgc(&self) -> Option<&BgcTracers> {
        self.bgc.as_ref()
    }

    /// Number of bio tracers (Icepack's `nbtrcr`; 0 without them): the length of
    /// `OceanFluxes::flux_bio` the step fills.
    pub fn n_bio(&self) -> usize {
        self.bgc.as_ref().map_or(0, |b| b.bio_index.len())
    }
}
