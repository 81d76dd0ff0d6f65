//! Interpolation in a ridging lookup table (made by [`super::tabulate`], read back by
//! `RidgeLookup::open` in [`crate::io::table_netcdf`]) for host models, the C ABI and Python.
//!
//! A table field lies on some of the axes `set` (an index), `thickness` (m, the lead-ice
//! sheet thickness) and `volume` (m³/m, the ridged volume V = U·h·t of eqs 13–16), in that
//! order. [`RidgeLookup::value`] interpolates it linearly along `thickness` and `volume`
//! (bilinearly on both) and takes the set by index.
//!
//! Policy outside the table (never silent extrapolation):
//! - a thickness or volume outside the axis range is **clamped** to the nearest end and the
//!   result is flagged ([`Lookup::clamped`]);
//! - a cell that no run reached holds NaN in the table (thin sheets reach smaller volumes in
//!   the same time), and any interpolation that gives such a cell a non-zero weight returns
//!   NaN: there is no data there, and the caller must decide what to do;
//! - a coordinate that is NaN or infinite, an unknown field or a set index out of range is an
//!   error ([`LookupError`]). Coordinates of axes the field does not lie on are ignored.
//!
//! ```
//! use pressridge::table::lookup::{Axes, Field, RidgeLookup};
//! // Work (J/m) on 2 thicknesses x 3 volumes, one set.
//! let work = Field::new(Axes::SET_THICKNESS_VOLUME, "J m-1", "work",
//!     ndarray::array![[[0.0, 1000.0, 3000.0], [0.0, 2000.0, 5000.0]]].into_dyn());
//! let t = RidgeLookup::new(vec!["mu=1".into()], vec![0.2, 0.4], vec![0.0, 5.0, 10.0],
//!     vec![("work_mean".into(), work)], Default::default()).unwrap();
//! let w = t.value("work_mean", 0, 0.3, 7.5).unwrap();
//! assert_eq!(w.value, 0.5 * (2000.0 + 3500.0)); // bilinear
//! assert!(!w.clamped);
//! let w = t.value("work_mean", 0, 0.5, 10.0).unwrap(); // thicker than the table
//! assert_eq!((w.value, w.clamped), (5000.0, true));
//! ```

use std::collections::BTreeMap;

use crate::itd::interp::{bracket, lerp};
use ndarray::ArrayD;

mod tables;

/// Which axes a field lies on, in the order `set`, `thickness`, `volume` (C order, volume
/// fastest).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Axes {
    /// The field has a `set` axis.
    pub set: bool,
    /// The field has a `thickness` axis.
    pub thickness: bool,
    /// The field has a `volume` axis.
    pub volume: bool,
}

impl Axes {
    /// `(set, thickness, volume)`: ensemble statistics and eq (15) forces.
    pub const SET_THICKNESS_VOLUME: Axes = Axes {
        set: true,
        thickness: true,
        volume: true,
    };
    /// `(set, thickness)`: fit coefficients per thickness, C_f per set.
    pub const SET_THICKNESS: Axes = Axes {
        set: true,
        thickness: true,
        volume: false,
    };
    /// `(set, volume)`: pooled fits and their bands, eq (16).
    pub const SET_VOLUME: Axes = Axes {
        set: true,
        thickness: false,
        volume: true,
    };
    /// `(set)`: pooled fit coefficients.
    pub const SET: Axes = Axes {
        set: true,
        thickness: false,
        volume: false,
    };
    /// `(thickness)`: the first set's C_f.
    pub const THICKNESS: Axes = Axes {
        set: false,
        thickness: true,
        volume: false,
    };

    /// Axis names in order, e.g. `["set", "thickness"]`.
    pub fn names(self) -> Vec<&'static str> {
        let mut v = Vec::with_capacity(3);
        if self.set {
            v.push("set");
        }
        if self.thickness {
            v.push("thickness");
        }
        if self.volume {
            v.push("volume");
        }
        v
    }
}

/// One tabulated field.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Its axes.
    pub axes: Axes,
    /// UDUNITS string, e.g. `J m-1`.
    pub units: String,
    /// Description.
    pub long_name: String,
    /// Values in `units`, one array axis per entry of `axes` in the order `set`,
    /// `thickness`, `volume` (the layout of [`crate::table::tabulate::RidgeTable`]'s grid
    /// fields), in standard (C) layout; NaN where no run reached.
    pub data: ArrayD<f64>,
}

impl Field {
    /// A field from its axes, units, description and values (an array over the axes, see
    /// [`Field::data`]; [`RidgeLookup::new`] checks its shape against the table's axes).
    pub fn new(axes: Axes, units: &str, long_name: &str, data: ArrayD<f64>) -> Self {
        Self {
            axes,
            units: units.into(),
            long_name: long_name.into(),
            data,
        }
    }
}

/// An interpolated value and whether a coordinate was clamped to the table's range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lookup {
    /// The value, in the field's units (NaN where the table has no data).
    pub value: f64,
    /// True when the thickness or the volume lay outside the table and was clamped.
    pub clamped: bool,
}

/// Errors of table construction and lookup.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LookupError {
    /// No field of that name.
    #[error("the table has no field `{name}` (it has: {known})")]
    UnknownField {
        /// The name asked for.
        name: String,
        /// The fields the table has, comma-separated.
        known: String,
    },
    /// The set index is out of range.
    #[error("set index {set} is out of range: the table has {nsets} set(s)")]
    Set {
        /// The index asked for.
        set: usize,
        /// Number of sets.
        nsets: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("{axis} = {value} is not finite")]
    NotFinite {
        /// `thickness` or `volume`.
        axis: &'static str,
        /// The value.
        value: f64,
    },
    /// The table itself is inconsistent.
    #[error("invalid ridging table: {0}")]
    Invalid(String),
    /// No set of the table has the friction pair asked for.
    #[error(
        "the table has no set at friction mu = {mu}, mu_w = {mu_w} (it has: {known}); tabulate runs at that friction (pressridge campaign, then tabulate) or choose one of these"
    )]
    Friction {
        /// μ asked for (dimensionless).
        mu: f64,
        /// μ_w asked for (dimensionless).
        mu_w: f64,
        /// The pairs the table has.
        known: String,
    },
    /// The table has no friction coordinates (it was made before they were written).
    #[error(
        "the table has no friction coordinates mu, mu_w: it was made by an older pressridge; re-run `pressridge tabulate` on its campaign to choose C_f by friction"
    )]
    NoFriction,
}

/// A ridging lookup table: fields on (set, thickness, volume) with interpolation.
#[derive(Clone, Debug, PartialEq)]
pub struct RidgeLookup {
    sets: Vec<String>,
    thickness: Vec<f64>,
    volume: Vec<f64>,
    fields: BTreeMap<String, Field>,
    attributes: BTreeMap<String, String>,
}

fn check_axis(name: &str, xs: &[f64]) -> Result<(), LookupError> {
    if xs.is_empty() {
        return Err(LookupError::Invalid(format!("the {name} axis is empty")));
    }
    crate::itd::interp::check_axis(name, xs).map_err(LookupError::Invalid)
}

impl RidgeLookup {
    /// A table from its axes (set labels; thickness in m and volume in m³/m, finite and
    /// strictly increasing), its fields and its global attributes (provenance).
    pub fn new(
        sets: Vec<String>,
        thickness: Vec<f64>,
        volume: Vec<f64>,
        fields: Vec<(String, Field)>,
        attributes: BTreeMap<String, String>,
    ) -> Result<Self, LookupError> {
        if sets.is_empty() {
            return Err(LookupError::Invalid("the set axis is empty".into()));
        }
        check_axis("thickness", &thickness)?;
        check_axis("volume", &volume)?;
        let mut map = BTreeMap::new();
        for (name, f) in fields {
            let want: Vec<usize> = [
                (f.axes.set, sets.len()),
                (f.axes.thickness, thickness.len()),
                (f.axes.volume, volume.len()),
            ]
            .into_iter()
            .filter_map(|(on, n)| on.then_some(n))
            .collect();
            if f.data.shape() != want {
                return Err(LookupError::Invalid(format!(
                    "field `{name}` on ({}) has shape {:?}, expected {want:?}",
                    f.axes.names().join(", "),
                    f.data.shape()
                )));
            }
            // Standard layout, so that `value` may index the values as one C-order slice.
            let mut f = f;
            if !f.data.is_standard_layout() {
                f.data = f.data.as_standard_layout().into_owned();
            }
            map.insert(name, f);
        }
        Ok(Self {
            sets,
            thickness,
            volume,
            fields: map,
            attributes,
        })
    }

    /// Set labels (the campaign settings other than thickness, e.g. `contact.mu=1`).
    pub fn sets(&self) -> &[String] {
        &self.sets
    }

    /// Thickness axis (m).
    pub fn thickness(&self) -> &[f64] {
        &self.thickness
    }

    /// The friction pair (μ, μ_w) of each set (dimensionless), from the coordinate variables
    /// `mu` and `mu_w` (a friction grid or `mu(set)`, `mu_w(set)`); `None` for a table made
    /// before they were written.
    pub fn friction(&self) -> Option<Vec<(f64, f64)>> {
        let (mu, mu_w) = (self.fields.get("mu")?, self.fields.get("mu_w")?);
        if mu.axes != Axes::SET || mu_w.axes != Axes::SET {
            return None;
        }
        Some(
            mu.data
                .iter()
                .copied()
                .zip(mu_w.data.iter().copied())
                .collect(),
        )
    }

    /// The set at friction μ = `mu`, μ_w = `mu_w` (dimensionless; equal to 1e-9).
    pub fn friction_set(&self, mu: f64, mu_w: f64) -> Result<usize, LookupError> {
        let pairs = self.friction().ok_or(LookupError::NoFriction)?;
        pairs
            .iter()
            .position(|&(a, b)| (a - mu).abs() <= 1e-9 && (b - mu_w).abs() <= 1e-9)
            .ok_or_else(|| LookupError::Friction {
                mu,
                mu_w,
                known: pairs
                    .iter()
                    .map(|(a, b)| format!("({a}, {b})"))
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }

    /// Volume axis (m³/m).
    pub fn volume(&self) -> &[f64] {
        &self.volume
    }

    /// Names of the fields, sorted.
    pub fn variables(&self) -> impl Iterator<Item = &str> {
        self.fields.keys().map(String::as_str)
    }

    /// A field by name.
    pub fn field(&self, name: &str) -> Option<&Field> {
        self.fields.get(name)
    }

    /// A global attribute (provenance: `pressridge_version`, `campaign_spec`, `seeds`,
    /// `history`, ...).
    pub fn attribute(&self, name: &str) -> Option<&str> {
        self.attributes.get(name).map(String::as_str)
    }

    /// Field `name` of set `set` at sheet thickness `thickness` (m) and ridged volume
    /// `volume` (m³/m), interpolated linearly along each axis the field has; see the module
    /// documentation for clamping and missing data.
    pub fn value(
        &self,
        name: &str,
        set: usize,
        thickness: f64,
        volume: f64,
    ) -> Result<Lookup, LookupError> {
        let f = self
            .fields
            .get(name)
            .ok_or_else(|| LookupError::UnknownField {
                name: name.into(),
                known: self.variables().collect::<Vec<_>>().join(", "),
            })?;
        let a = f.axes;
        if a.set && set >= self.sets.len() {
            return Err(LookupError::Set {
                set,
                nsets: self.sets.len(),
            });
        }
        let (nh, nv) = (self.thickness.len(), self.volume.len());
        let (ih, wh, ch) = if a.thickness {
            if !thickness.is_finite() {
                return Err(LookupError::NotFinite {
                    axis: "thickness",
                    value: thickness,
                });
            }
            bracket(&self.thickness, thickness)
        } else {
            (0, 0.0, false)
        };
        let (iv, wv, cv) = if a.volume {
            if !volume.is_finite() {
                return Err(LookupError::NotFinite {
                    axis: "volume",
                    value: volume,
                });
            }
            bracket(&self.volume, volume)
        } else {
            (0, 0.0, false)
        };
        let sh = if a.volume { nv } else { 1 };
        let ss = if a.thickness { nh * sh } else { sh };
        let base = if a.set { set * ss } else { 0 };
        let d = f
            .data
            .as_slice()
            .expect("standard layout, by RidgeLookup::new");
        let row = |i: usize| {
            let o = base + i * sh;
            lerp(d[o + iv], || d[o + iv + 1], wv)
        };
        let value = lerp(row(ih), || row(ih + 1), wh);
        Ok(Lookup {
            value,
            clamped: ch || cv,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use ndarray::{Array, IxDyn};

    fn table() -> RidgeLookup {
        // Two sets, three thicknesses, four volumes; work = 1000·set + 100·ih + iv, with the
        // thinnest row missing beyond the second volume.
        let mut work = Vec::new();
        for s in 0..2 {
            for ih in 0..3 {
                for iv in 0..4 {
                    work.push(if ih == 0 && iv > 1 {
                        f64::NAN
                    } else {
                        (1000 * s + 100 * ih + iv) as f64
                    });
                }
            }
        }
        let cf = vec![10.0, 12.0, 16.0, 20.0, f64::NAN, 24.0];
        RidgeLookup::new(
            vec!["a".into(), "b".into()],
            vec![0.2, 0.3, 0.5],
            vec![0.0, 1.0, 2.0, 4.0],
            vec![
                (
                    "work_mean".into(),
                    Field::new(
                        Axes::SET_THICKNESS_VOLUME,
                        "J m-1",
                        "w",
                        Array::from_shape_vec((2, 3, 4), work).unwrap().into_dyn(),
                    ),
                ),
                (
                    "cf_by_set".into(),
                    Field::new(
                        Axes::SET_THICKNESS,
                        "1",
                        "cf",
                        Array::from_shape_vec((2, 3), cf).unwrap().into_dyn(),
                    ),
                ),
                (
                    "pooled_work_a".into(),
                    Field::new(
                        Axes::SET,
                        "J m-5",
                        "a",
                        ndarray::array![3.0, 4.0].into_dyn(),
                    ),
                ),
            ],
            BTreeMap::new(),
        )
        .unwrap()
    }

    #[test]
    fn nodes_are_exact_and_interior_is_bilinear() {
        let t = table();
        for s in 0..2 {
            for (ih, &h) in [0.3, 0.5].iter().enumerate() {
                for (iv, &v) in [0.0, 1.0, 2.0, 4.0].iter().enumerate() {
                    let l = t.value("work_mean", s, h, v).unwrap();
                    assert_eq!(l.value, (1000 * s + 100 * (ih + 1) + iv) as f64);
                    assert!(!l.clamped);
                }
            }
        }
        // h = 0.4 is halfway between 0.3 and 0.5, V = 3 halfway between 2 and 4.
        let l = t.value("work_mean", 1, 0.4, 3.0).unwrap();
        assert!((l.value - (1000.0 + 150.0 + 2.5)).abs() < 1e-12);
    }

    #[test]
    fn clamps_and_flags_outside_and_never_extrapolates() {
        let t = table();
        let l = t.value("work_mean", 0, 0.9, 9.0).unwrap();
        assert_eq!((l.value, l.clamped), (203.0, true));
        let l = t.value("work_mean", 0, 0.3, -1.0).unwrap();
        assert_eq!((l.value, l.clamped), (100.0, true));
        let l = t.cf(0, 0.1).unwrap();
        assert_eq!((l.value, l.clamped), (10.0, true));
    }

    #[test]
    fn missing_cells_give_nan_only_where_they_carry_weight() {
        let t = table();
        // The thinnest row reached V = 1 only.
        assert!(t.value("work_mean", 0, 0.25, 1.5).unwrap().value.is_nan());
        assert!(t.value("work_mean", 0, 0.2, 3.0).unwrap().value.is_nan());
        // At h = 0.3 exactly the thin row has no weight.
        assert_eq!(t.value("work_mean", 0, 0.3, 3.0).unwrap().value, 102.5);
        // At V = 1 exactly, the missing V = 2 column has no weight.
        assert_eq!(t.value("work_mean", 0, 0.25, 1.0).unwrap().value, 51.0);
    }

    #[test]
    fn fields_on_fewer_axes_ignore_the_other_coordinates() {
        let t = table();
        assert_eq!(
            t.value("pooled_work_a", 1, f64::NAN, f64::NAN)
                .unwrap()
                .value,
            4.0
        );
        assert_eq!(t.cf(0, 0.4).unwrap().value, 14.0);
    }

    #[test]
    fn bad_requests_are_errors() {
        let t = table();
        assert!(matches!(
            t.value("nope", 0, 0.3, 1.0),
            Err(LookupError::UnknownField { .. })
        ));
        assert!(matches!(
            t.value("work_mean", 2, 0.3, 1.0),
            Err(LookupError::Set { set: 2, nsets: 2 })
        ));
        assert!(matches!(
            t.value("work_mean", 0, f64::NAN, 1.0),
            Err(LookupError::NotFinite {
                axis: "thickness",
                ..
            })
        ));
        assert!(matches!(
            t.value("work_mean", 0, 0.3, f64::INFINITY),
            Err(LookupError::NotFinite { axis: "volume", .. })
        ));
        let e = t.value("nope", 0, 0.3, 1.0).unwrap_err().to_string();
        assert!(e.contains("work_mean"), "{e}");
    }

    #[test]
    fn cf_table_skips_missing_thicknesses() {
        let t = table();
        let c = t.cf_table(1).unwrap();
        assert_eq!(c.thickness(), &[0.2, 0.5]);
        assert_eq!(c.values(), &[20.0, 24.0]);
    }

    #[test]
    fn inconsistent_tables_are_refused() {
        let bad = |h: Vec<f64>, shape: &[usize]| {
            RidgeLookup::new(
                vec!["a".into()],
                h,
                vec![0.0, 1.0],
                vec![(
                    "w".into(),
                    Field::new(
                        Axes::SET_THICKNESS_VOLUME,
                        "J m-1",
                        "w",
                        ArrayD::zeros(IxDyn(shape)),
                    ),
                )],
                BTreeMap::new(),
            )
        };
        assert!(bad(vec![0.2, 0.3], &[1, 2, 2]).is_ok());
        assert!(bad(vec![0.3, 0.2], &[1, 2, 2]).is_err());
        assert!(bad(vec![0.2, f64::NAN], &[1, 2, 2]).is_err());
        assert!(bad(vec![0.2, 0.3], &[1, 2, 3]).is_err());
        assert!(bad(vec![0.2, 0.3], &[1, 4]).is_err());
        assert!(bad(vec![], &[1, 0, 2]).is_err());
    }
}
