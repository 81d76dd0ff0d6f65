//! `TracerLayout`: the Python class over the library's tracer layout.
//!
//! Owns `PyTracerLayout` (constructors `cice`, `from_fields`, `detect`; the fields, names,
//! units and Icepack's `trcr_depend`; pickling) and the reading of a field from Python.

use std::sync::Arc;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use pressridge::itd::details::{
    BgcKind, BgcTracers, CiceLayoutSpec, CiceTracerFlags, TracerBase, TracerField, TracerLayout,
    TracerRole,
};

use crate::errors::{BindError, value_err};

/// A tracer layout: which tracers each thickness category carries, in what order and on
/// what base (the Rust ``pressridge::itd::details::TracerLayout``, not a copy of it).
///
/// Make one with ``TracerLayout.cice(nilyr, nslyr, *, age=False, first_year=False,
/// level_ice=False, ponds=False, snow=False, isotopes=0, aerosols=0, pond_topo=False,
/// pond_sealvl=False, fsd=0, brine=False)``: CICE/Icepack's order ``Tsfc``, ``qice(nilyr)``,
/// ``qsno(nslyr)``, ``sice(nilyr)``, then ``iage``, ``FY``, ``alvl``, ``vlvl``, ``apnd``,
/// ``hpnd``, ``ipnd`` as the flags (Icepack's ``tr_iage``, ``tr_FY``, ``tr_lvl``,
/// ``tr_pond_lvl``) select, then with ``snow=True`` ``smice``, ``smliq``, ``rhos``, ``rsnw``
/// (``nslyr`` each), with ``isotopes=n`` ``isosno(n)``, ``isoice(n)`` and with
/// ``aerosols=n`` four tracers per species (``aerosnossl001``, ``aerosnoint001``,
/// ``aeroicessl001``, ``aeroiceint001``, ...); ``pond_topo`` or ``pond_sealvl`` give ponds on
/// the ice area instead (one pond scheme at a time), ``fsd=n`` the floe-size tracers
/// ``fsd(n)`` after the snow tracers and ``brine`` the brine fraction ``fbri`` last;
/// ``ponds`` needs ``level_ice``. ``with_empty_value(name, value)`` sets Icepack's snow
/// refills. Or with
/// ``TracerLayout.from_fields(fields)`` for any layout the Rust ``TracerLayout::new``
/// accepts, or ``TracerLayout.detect(names)`` from CICE restart variable names. Units:
/// ``Tsfc`` degC, enthalpies J m-3 (negative), salinity ppt, age s, fractions 1, pond depth
/// and lid m.
///
/// Attributes and methods: ``ntrcr``, ``nilyr``, ``nslyr``, ``flags``, ``icepack`` (the
/// layout in Icepack's names, as ``from_icepack`` takes it), ``fields()`` (name,
/// first index, levels, base, strata, units, long name), ``spec()`` (the fields as
/// ``from_fields`` takes them), ``field(name)`` (first index, levels), ``names`` (per tracer,
/// the CICE restart variable name: ``Tsfcn``, ``qice001``...), ``units``, ``long_names``,
/// ``trcr_depend()`` (Icepack's).
#[pyclass(frozen, name = "TracerLayout", module = "pressridge._core")]
pub(crate) struct PyTracerLayout {
    pub(crate) inner: Arc<TracerLayout>,
}

/// One field of `from_fields`: a dict (`name`, `levels`, `base`, `strata`, `role`) or a
/// sequence in that order; missing items default to Icepack's for the role, the role to the
/// one whose Icepack name is `name` (else `other`).
fn field_from_py(i: usize, item: &Bound<'_, PyAny>) -> Result<TracerField, BindError> {
    const KEYS: [&str; 5] = ["name", "levels", "base", "strata", "role"];
    let mut got: [Option<Bound<'_, PyAny>>; 5] = Default::default();
    let at = |what: &str| format!("fields[{i}]{what}");
    if let Ok(d) = item.cast::<PyDict>() {
        for (k, v) in d.iter() {
            let k: String = k
                .extract()
                .map_err(|_| value_err(at(": keys must be strings")))?;
            let Some(pos) = KEYS.iter().position(|x| *x == k) else {
                return Err(value_err(format!(
                    "{}: unknown key `{k}`; the keys are {}",
                    at(""),
                    KEYS.join(", ")
                )));
            };
            got[pos] = Some(v);
        }
    } else if let Ok(seq) = item.extract::<Vec<Bound<'_, PyAny>>>()
        && !item.is_instance_of::<pyo3::types::PyString>()
    {
        if seq.is_empty() || seq.len() > 5 {
            return Err(value_err(at(&format!(
                ": a sequence of 1 to 5 items ({}), got {}",
                KEYS.join(", "),
                seq.len()
            ))));
        }
        for (k, v) in seq.into_iter().enumerate() {
            got[k] = Some(v);
        }
    } else {
        return Err(value_err(at(&format!(
            ": a dict with keys {} or a sequence in that order, got {}",
            KEYS.join(", "),
            item.get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_default()
        ))));
    }
    let name: String = match &got[0] {
        Some(v) => v
            .extract()
            .map_err(|_| value_err(at(": `name` must be a string")))?,
        None => return Err(value_err(at(": `name` is missing"))),
    };
    let at = |what: &str| format!("fields[{i}] (`{name}`): {what}");
    let role = match &got[4] {
        Some(v) if !v.is_none() => {
            let r: String = v
                .extract()
                .map_err(|_| value_err(at("`role` must be a string")))?;
            TracerRole::from_name(&r).ok_or_else(|| {
                let all: Vec<&str> = TracerRole::ALL.iter().map(|r| r.name()).collect();
                value_err(at(&format!(
                    "unknown role `{r}`; one of {}",
                    all.join(", ")
                )))
            })?
        }
        _ => TracerRole::ALL
            .into_iter()
            .find(|r| r.icepack().is_some_and(|(n, _, _)| n == name))
            .unwrap_or(TracerRole::Other),
    };
    let levels: usize = match &got[1] {
        Some(v) if !v.is_none() => {
            let n: i64 = v
                .extract()
                .map_err(|_| value_err(at("`levels` must be an integer")))?;
            if !(1..=1 << 20).contains(&n) {
                return Err(value_err(at(&format!("levels = {n}: must be at least 1"))));
            }
            n as usize
        }
        _ => 1,
    };
    let base = match &got[2] {
        Some(v) if !v.is_none() => {
            let b: String = v
                .extract()
                .map_err(|_| value_err(at("`base` must be a string")))?;
            TracerBase::from_name(&b).ok_or_else(|| {
                let all: Vec<&str> = TracerBase::ALL.iter().map(|b| b.name()).collect();
                value_err(at(&format!(
                    "unknown base `{b}`; one of {}",
                    all.join(", ")
                )))
            })?
        }
        _ => match role.icepack() {
            Some((_, b, _)) => b,
            None => {
                return Err(value_err(at(
                    "`base` is needed (area, ice_volume or snow_volume) for a tracer of role other",
                )));
            }
        },
    };
    let strata: Vec<String> = match &got[3] {
        Some(v) if !v.is_none() => {
            if v.is_instance_of::<pyo3::types::PyString>() {
                return Err(value_err(at(
                    "`strata` must be a list of field names, not a string",
                )));
            }
            v.extract()
                .map_err(|_| value_err(at("`strata` must be a list of field names")))?
        }
        _ => role
            .icepack()
            .map(|(_, _, s)| s.iter().map(|x| x.to_string()).collect())
            .unwrap_or_default(),
    };
    Ok(TracerField {
        name,
        role,
        levels,
        base,
        strata,
        // Icepack's: 1 for the brine fraction, else 0 (TracerLayout::with_empty_value).
        empty: if role == TracerRole::BrineFraction {
            1.0
        } else {
            0.0
        },
    })
}

impl PyTracerLayout {
    /// `f` of the role of every tracer, in tracer order.
    fn per_tracer(&self, f: impl Fn(&TracerRole) -> &'static str) -> Vec<&'static str> {
        (0..self.inner.ntrcr())
            .map(|it| f(&self.inner.field_of(it).expect("index in range").0.role))
            .collect()
    }
}

#[pymethods]
impl PyTracerLayout {
    /// The CICE/Icepack layout (`TracerLayout::cice`) for `nilyr` ice and `nslyr` snow layers
    /// (both >= 1) with the optional tracers of `CiceTracerFlags` by keyword.
    #[staticmethod]
    #[pyo3(signature = (nilyr, nslyr, *, age = false, first_year = false, level_ice = false, ponds = false, snow = false, isotopes = 0, aerosols = 0, pond_topo = false, pond_sealvl = false, fsd = 0, brine = false))]
    #[allow(clippy::too_many_arguments)]
    fn cice(
        nilyr: i64,
        nslyr: i64,
        age: bool,
        first_year: bool,
        level_ice: bool,
        ponds: bool,
        snow: bool,
        isotopes: i64,
        aerosols: i64,
        pond_topo: bool,
        pond_sealvl: bool,
        fsd: i64,
        brine: bool,
    ) -> PyResult<Self> {
        for (name, v) in [("nilyr", nilyr), ("nslyr", nslyr)] {
            if !(1..=1 << 20).contains(&v) {
                return Err(value_err(format!("{name} = {v}: must be at least 1")).into());
            }
        }
        for (name, v, max) in [
            ("isotopes", isotopes, 3),
            ("aerosols", aerosols, 6),
            ("fsd", fsd, 1 << 20),
        ] {
            if !(0..=max).contains(&v) {
                return Err(value_err(format!("{name} = {v}: must be 0 to {max}")).into());
            }
        }
        let flags = CiceTracerFlags {
            age,
            first_year,
            level_ice,
            ponds,
            snow,
            isotopes: isotopes as usize,
            aerosols: aerosols as usize,
            pond_topo,
            pond_sealvl,
            fsd: fsd as usize,
            brine,
        };
        let l = TracerLayout::cice(nilyr as usize, nslyr as usize, flags).map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// The CICE/Icepack layout named in Icepack's words, as the command line's
    /// `--tracer-layout` takes it (`CiceLayoutSpec`): `nilyr=N,nslyr=N` and the switches
    /// that are on (`tr_iage`, `tr_FY`, `tr_lvl`, `tr_pond_lvl`, `tr_pond_topo`,
    /// `tr_pond_sealvl`, `tr_snow`, `tr_fsd,nfsd=N`, `tr_iso,n_iso=N`, `tr_aero,n_aero=N`,
    /// `tr_brine`), or the preset `icedrv`; in Icepack's packing order. A ValueError names the
    /// item refused.
    #[staticmethod]
    fn from_icepack(text: &str) -> PyResult<Self> {
        let spec: CiceLayoutSpec = text.parse().map_err(value_err)?;
        let l = spec.layout().map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// The layout in Icepack's words (`from_icepack`'s text, canonical), or None when it is
    /// not exactly a CICE layout.
    #[getter]
    fn icepack(&self) -> Option<String> {
        self.inner.cice_spec().map(|s| s.to_string())
    }

    /// This layout with `extra` biogeochemical tracers after every other (Rust
    /// `TracerLayout::with_bgc`): `kind` `"z_tracers"` (Icepack's vertically resolved bio
    /// tracers: `nblyr + 1` levels on the brine grid, which needs the brine fraction, and two
    /// in the snow) or `"skl_bgc"` (the skeletal layer, `sk_l` m thick, default 0.03);
    /// `bio_index`: per bio tracer its first tracer, 0-based. The step books their flux to
    /// the ocean in `flux_bio`. Give the host's tables with `with_host_tables` after this.
    #[pyo3(signature = (extra, kind, bio_index, *, nblyr = 1, sk_l = 0.03))]
    fn with_bgc(
        &self,
        extra: usize,
        kind: &str,
        bio_index: Vec<usize>,
        nblyr: usize,
        sk_l: f64,
    ) -> PyResult<Self> {
        let kind = match kind {
            "z_tracers" => BgcKind::Vertical { nblyr },
            "skl_bgc" => BgcKind::Skeletal { sk_l },
            k => {
                return Err(
                    value_err(format!("kind = {k:?}: \"z_tracers\" or \"skl_bgc\"")).into(),
                );
            }
        };
        let l = (*self.inner)
            .clone()
            .with_bgc(extra, BgcTracers { kind, bio_index })
            .map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// This layout with each tracer carried as a host's tables say (Rust
    /// `TracerLayout::with_host_tables`; Icepack's `trcr_depend`, `trcr_base` (ntrcr, 3),
    /// `n_trcr_strata`, `nt_strata` (ntrcr, 2), 1-based tracer numbers as Icepack has them).
    fn with_host_tables(
        &self,
        trcr_depend: Vec<i32>,
        trcr_base: Vec<[f64; 3]>,
        n_trcr_strata: Vec<i32>,
        nt_strata: Vec<[i32; 2]>,
    ) -> PyResult<Self> {
        // Fortran order, as Icepack's arrays are.
        let base: Vec<f64> = (0..3)
            .flat_map(|j| trcr_base.iter().map(move |r| r[j]))
            .collect();
        let strata: Vec<i32> = (0..2)
            .flat_map(|j| nt_strata.iter().map(move |r| r[j]))
            .collect();
        let l = (*self.inner)
            .clone()
            .with_host_tables(&trcr_depend, &base, &n_trcr_strata, &strata)
            .map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// Number of bio tracers (Icepack `nbtrcr`; 0 without them).
    #[getter]
    fn nbtrcr(&self) -> usize {
        self.inner.n_bio()
    }

    /// This layout with `value` as the field `name`'s value where its base volume is zero
    /// and in emptied categories (units of the tracer; Rust `TracerLayout::with_empty_value`):
    /// Icepack's refills of the snow tracers, ``rhos`` = ``rhosnew`` with ``snwredist =
    /// 'ITD'``, ``smice`` = ``rhos`` and ``rsnw`` = ``rsnw_fall`` with ``snwgrain``. Only for
    /// ice- and snow-volume tracers.
    fn with_empty_value(&self, name: &str, value: f64) -> PyResult<Self> {
        let l = (*self.inner)
            .clone()
            .with_empty_value(name, value)
            .map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// Any layout (`TracerLayout::new`): `fields` in storage order, each a dict with keys
    /// `name` (str), `levels` (int >= 1, default 1), `base` (`area`, `ice_volume`,
    /// `snow_volume`), `strata` (names of earlier single-level fields it is also carried on),
    /// `role` (`surface_temperature`, `ice_enthalpy`, `snow_enthalpy`, `ice_salinity`, `age`,
    /// `first_year`, `level_area`, `level_volume`, `pond_area`, `pond_depth`, `pond_lid`,
    /// `aerosol_snow`, `aerosol_ice`, `isotope_snow`, `isotope_ice`, `other`), or a sequence
    /// in that order. The role defaults to the one whose Icepack name is `name` (`Tsfc`,
    /// `qice`, `qsno`, `sice`, `iage`, `FY`, `alvl`, `vlvl`, `apnd`, `hpnd`, `ipnd`,
    /// `isosno`, `isoice`), else `other`; base and strata default to Icepack's for the role.
    /// Errors name the field and what is wrong.
    #[staticmethod]
    fn from_fields(fields: Vec<Bound<'_, PyAny>>) -> PyResult<Self> {
        let f: Vec<TracerField> = fields
            .iter()
            .enumerate()
            .map(|(i, x)| field_from_py(i, x))
            .collect::<Result<_, _>>()?;
        let l = TracerLayout::new(f).map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// The CICE layout of a dataset or file holding these variable names (CICE restart names:
    /// `vsnon`, `Tsfcn`, `qice001`.., `qsno001`.., `sice001`.., `iage`, `FY`, `alvl`, `vlvl`,
    /// `apnd`, `hpnd`, `ipnd`), as the command line tells it (`TracerLayout::detect_cice`):
    /// None when there is no snow and no tracer; a missing member of a group is a ValueError
    /// naming the variable.
    #[staticmethod]
    fn detect(names: Vec<String>) -> PyResult<Option<Self>> {
        let has = |n: &str| names.iter().any(|m| m == n);
        match TracerLayout::detect_cice(&has) {
            Ok(Some((l, _))) => Ok(Some(Self { inner: Arc::new(l) })),
            Ok(None) => Ok(None),
            Err(e) => Err(value_err(format!("tracer variable `{}` {e}", e.var)).into()),
        }
    }

    /// Tracers per category (Icepack `ntrcr`).
    #[getter]
    fn ntrcr(&self) -> usize {
        self.inner.ntrcr()
    }

    /// Ice layers.
    #[getter]
    fn nilyr(&self) -> usize {
        self.inner.nilyr()
    }

    /// Snow layers.
    #[getter]
    fn nslyr(&self) -> usize {
        self.inner.nslyr()
    }

    /// The optional CICE tracers carried, as a dict of `CiceTracerFlags` field names.
    #[getter]
    fn flags<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let f = self.inner.cice_flags();
        for (k, v) in [
            ("age", f.age),
            ("first_year", f.first_year),
            ("level_ice", f.level_ice),
            ("ponds", f.ponds),
            ("snow", f.snow),
            ("pond_topo", f.pond_topo),
            ("pond_sealvl", f.pond_sealvl),
            ("brine", f.brine),
        ] {
            d.set_item(k, v)?;
        }
        d.set_item("isotopes", f.isotopes)?;
        d.set_item("aerosols", f.aerosols)?;
        d.set_item("fsd", f.fsd)?;
        Ok(d)
    }

    /// Fields in storage order: (name, first index, levels, base, strata, units, long_name).
    #[allow(clippy::type_complexity)]
    fn fields(
        &self,
    ) -> Vec<(
        String,
        usize,
        usize,
        &'static str,
        Vec<String>,
        &'static str,
        &'static str,
    )> {
        self.inner
            .fields()
            .iter()
            .map(|f| {
                let (start, _) = self.inner.field(&f.name).expect("own field");
                (
                    f.name.clone(),
                    start,
                    f.levels,
                    f.base.name(),
                    f.strata.clone(),
                    f.role.units(),
                    f.role.long_name(),
                )
            })
            .collect()
    }

    /// The fields as `from_fields` takes them: a list of dicts `name`, `levels`, `base`,
    /// `strata`, `role`.
    fn spec<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        self.inner
            .fields()
            .iter()
            .map(|f| {
                let d = PyDict::new(py);
                d.set_item("name", &f.name)?;
                d.set_item("levels", f.levels)?;
                d.set_item("base", f.base.name())?;
                d.set_item("strata", f.strata.clone())?;
                d.set_item("role", f.role.name())?;
                Ok(d)
            })
            .collect()
    }

    /// (first index, levels) of the field `name`.
    fn field(&self, name: &str) -> PyResult<(usize, usize)> {
        self.inner.field(name).ok_or_else(|| {
            let known: Vec<&str> = self
                .inner
                .fields()
                .iter()
                .map(|f| f.name.as_str())
                .collect();
            value_err(format!(
                "no tracer field `{name}` in this layout (it has: {})",
                known.join(", ")
            ))
            .into()
        })
    }

    /// Per tracer, the variable name of a CICE restart file (`Tsfcn`, `qice001`, ...).
    #[getter]
    fn names(&self) -> Vec<String> {
        self.inner.cice_restart_names()
    }

    /// Per tracer, its CF units.
    #[getter]
    fn units(&self) -> Vec<&'static str> {
        self.per_tracer(|r| r.units())
    }

    /// Per tracer, its long name.
    #[getter]
    fn long_names(&self) -> Vec<&'static str> {
        self.per_tracer(|r| r.long_name())
    }

    /// Icepack's `trcr_depend` per tracer (0 area, 1 ice volume, 2 snow volume, 2 + nt).
    fn trcr_depend(&self) -> Vec<i32> {
        self.inner.trcr_depend()
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyTracerLayout>()
            .is_ok_and(|o| *o.get().inner == *self.inner)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        for f in self.inner.fields() {
            f.name.hash(&mut h);
            f.levels.hash(&mut h);
            f.base.name().hash(&mut h);
            f.role.name().hash(&mut h);
            f.strata.hash(&mut h);
        }
        h.finish()
    }

    fn __repr__(&self) -> String {
        let l = &*self.inner;
        if let Some(spec) = l.cice_spec().filter(|s| s.bgc.is_some()) {
            // The column driver's biogeochemistry has no constructor keywords: its text.
            return format!(
                "TracerLayout.from_icepack({:?}) with {} tracers",
                spec.to_string(),
                l.ntrcr()
            );
        }
        if let Some(spec) = l.cice_spec() {
            let f = spec.flags;
            // The newer keywords only where set, so the common layouts read as before.
            let mut more = String::new();
            if f.snow {
                more += ", snow=True";
            }
            if f.isotopes > 0 {
                more += &format!(", isotopes={}", f.isotopes);
            }
            if f.aerosols > 0 {
                more += &format!(", aerosols={}", f.aerosols);
            }
            if f.pond_topo {
                more += ", pond_topo=True";
            }
            if f.pond_sealvl {
                more += ", pond_sealvl=True";
            }
            if f.fsd > 0 {
                more += &format!(", fsd={}", f.fsd);
            }
            if f.brine {
                more += ", brine=True";
            }
            return format!(
                "TracerLayout.cice(nilyr={}, nslyr={}, age={}, first_year={}, level_ice={}, ponds={}{more}) with {} tracers",
                l.nilyr(),
                l.nslyr(),
                py_bool(f.age),
                py_bool(f.first_year),
                py_bool(f.level_ice),
                py_bool(f.ponds),
                l.ntrcr()
            );
        }
        let parts: Vec<String> = l
            .fields()
            .iter()
            .map(|f| {
                let strata = if f.strata.is_empty() {
                    String::new()
                } else {
                    format!(" on {}", f.strata.join("*"))
                };
                format!(
                    "{}[{}] {} {}{strata}",
                    f.name,
                    f.levels,
                    f.role.name(),
                    f.base.name()
                )
            })
            .collect();
        format!(
            "TracerLayout.from_fields({}) with {} tracers",
            parts.join(", "),
            l.ntrcr()
        )
    }

    /// Pickling (dask workers): rebuilt from its fields.
    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, (Vec<Bound<'py, PyDict>>,))> {
        let make = slf.getattr("from_fields")?;
        Ok((make, (slf.get().spec(slf.py())?,)))
    }
}

fn py_bool(b: bool) -> &'static str {
    if b { "True" } else { "False" }
}
