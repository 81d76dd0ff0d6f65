"""pressridge for Python: ice strength and the ridging step on numpy arrays, the
Hopkins (1994) pressure-ridge simulator, seeded campaigns and their lookup tables.

Everything here calls the Rust library ``pressridge`` (the compiled module
:mod:`pressridge._core`); no physics is done in Python. Units are SI throughout:
area fractions are dimensionless, ``vicen`` is ice volume per unit grid-cell area (m),
thicknesses are m, rates 1/s, strength N/m; the simulator's energies are J per metre of
ridge and its forces N/m.

Arrays of a thickness distribution have the category axis first and any spatial shape
after it, e.g. ``aicen[ncat, nj, ni]``. C- and Fortran-ordered float64 arrays reach the
library without a copy; other layouts and dtypes are converted first. Long calls release
the GIL. Bad input raises :class:`ValueError` (or :class:`OSError` for files) with the
library's message.

The xarray/dask face is :mod:`pressridge.xr`.
"""

from __future__ import annotations

import os as _os
import warnings as _warnings
from typing import Any, NamedTuple, Optional, Tuple, Union

import numpy as _np

from . import _core
from ._table import Table
from ._run import Run, State, load_run, load_state, plot_state
from ._options import Participation, Redistribution, StrengthLaw, StrengthOptions
from . import _options
from ._simulator import (
    RAFTING_REACH,
    CampaignResult,
    Simulation,
    campaign,
    redistribution,
    scene,
    simulate,
    tabulate,
)

__version__: str = _core.__version__

__all__ = [
    "CfClampedWarning",
    "RidgeStepResult",
    "TracerLayout",
    "STEP_CELL_OUTPUTS",
    "STEP_SPECIES_OUTPUTS",
    "STEP_CATEGORY_OUTPUTS",
    "Simulation",
    "CampaignResult",
    "Table",
    "strength",
    "StrengthOptions",
    "ridge_step",
    "category_bounds",
    "simulate",
    "scene",
    "campaign",
    "tabulate",
    "redistribution",
    "PARAMETERS",
    "DEFAULT_PARAMETERS",
    "STEP_PARAMETERS",
    "DEFAULT_STEP_PARAMETERS",
    "CF_PRESETS",
    "DEFAULT_FRICTION",
    "RAFTING_REACH",
    "CF_CLAMPED_MATERIAL_SHARE",
    "Run",
    "State",
    "load_run",
    "load_state",
    "plot_state",
]

#: Names of the ITD parameters accepted as keywords by :func:`strength` and
#: :func:`ridge_step` (the fields of the Rust ``ItdParams``).
PARAMETERS: Tuple[str, ...] = tuple(_core.param_names())
#: CICE/Icepack's default value of every parameter (SI units, see ``docs/strength.md``).
DEFAULT_PARAMETERS: dict = dict(_core.default_params())
#: The thermodynamic constants of the complete ridging step, accepted as keywords by
#: :func:`ridge_step` with the complete step (the Rust ``RidgeStepParams::FIELDS``, the
#: list the command line's ``--param`` reads too): ``{name: (units, description)}`` —
#: ``rhos`` (kg m-3), ``lfresh`` (J kg-1), ``cp_ice`` (J kg-1 K-1), ``fsnowrdg`` (1),
#: ``ice_ref_salinity`` (ppt), ``itd_area_min`` (1), ``itd_mass_min`` (kg m-2), ``hs_min``
#: (m), ``tmin`` (degC). The ice and sea-water densities are :data:`PARAMETERS` ``rhoi``,
#: ``rhow`` (kg m-3).
STEP_PARAMETERS: dict = {n: (u, d) for n, u, d, _ in _core.step_parameters()}
#: Icepack's default of every :data:`STEP_PARAMETERS` constant, in its units.
DEFAULT_STEP_PARAMETERS: dict = {n: v for n, _, _, v in _core.step_parameters()}
#: Named constant values of C_f (dimensionless): ``hibler1980`` = 2, ``flato1991`` = 15,
#: ``cice`` = 17.
CF_PRESETS: dict = dict(_core.cf_presets())

PathLike = Union[str, "_os.PathLike[str]"]
CfLike = Union[None, float, str, "_os.PathLike[str]", Table, Tuple[Any, Any]]


#: Share of a column's strength (dimensionless, 0.01) from C_f held at a table's end value at
#: or above which :class:`CfClampedWarning` counts the clamp as material: below it, even a
#: C_f wrong by a factor of two moves P by under 1 %.
CF_CLAMPED_MATERIAL_SHARE: float = float(_core.CF_CLAMPED_MATERIAL_SHARE)


class CfClampedWarning(UserWarning):
    """Some columns had ridging-ice thicknesses outside the C_f table: C_f was clamped to
    the table's end values there."""


def _aligned(a: _np.ndarray) -> _np.ndarray:
    """``a``, or an aligned copy when its data are not aligned for its dtype (numpy allows
    such views, e.g. arrays dask.distributed unpickles from a byte buffer; the extension
    refuses them)."""
    return a if a.flags.aligned else _np.require(a, requirements="A")


def _f64(x: Any, name: str) -> _np.ndarray:
    try:
        a = _np.asarray(x, dtype=_np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name} must be an array of numbers: {e}") from None
    return _aligned(a)


def _bool(x: Any, name: str) -> _np.ndarray:
    a = _np.asarray(x)
    if a.dtype != _np.bool_:
        raise ValueError(f"{name} must be a boolean array, got dtype {a.dtype}")
    return _aligned(a)


def _params(params: dict, step: bool = False) -> list:
    """(name, value) pairs of ITD parameters (:data:`PARAMETERS`), or with ``step`` of the
    complete ridging step's constants (:data:`PARAMETERS` and :data:`STEP_PARAMETERS`). An
    unknown name raises the library's message (the closest valid name and all), as the
    command line's ``--param`` does."""
    out = []
    for k, v in params.items():
        _core.check_param_name(k, step)
        if isinstance(v, (bool, _np.bool_)):
            raise ValueError(f"parameter `{k}` must be a number, got {v!r}")
        try:
            out.append((k, float(v)))
        except (TypeError, ValueError):
            raise ValueError(f"parameter `{k}` must be a number, got {v!r}") from None
    return out


#: The friction pair (mu, mu_w) whose C_f a ridging table gives by default: Hopkins
#: (1994)'s thickness set, 1.0 between blocks above and 0.6 below the water line.
DEFAULT_FRICTION: Tuple[float, float] = tuple(_core.DEFAULT_FRICTION)  # type: ignore[assignment]


def _friction_arg(friction: Any) -> Optional[Tuple[float, float]]:
    if friction is None:
        return None
    try:
        mu, mu_w = (float(x) for x in friction)
    except (TypeError, ValueError):
        raise ValueError(
            f"friction must be a pair (mu, mu_w) of numbers, e.g. (1.0, 0.6); got {friction!r}"
        ) from None
    if not (_np.isfinite(mu) and _np.isfinite(mu_w) and mu >= 0 and mu_w >= 0):
        raise ValueError(f"friction = {friction!r}: mu and mu_w must be finite and non-negative")
    return mu, mu_w


def _cf_table_nodes(cf: CfLike, friction: Any) -> Tuple[Optional[tuple], Optional[Tuple[float, float]]]:
    """For a table or a table file, the (thickness, cf) nodes at ``friction`` and the
    friction they are for (None when the source does not say); else (None, None)."""
    f = _friction_arg(friction)
    if isinstance(cf, Table):
        pairs = cf.friction
        if pairs is None:
            if f is not None:
                raise ValueError(
                    f"{cf.path}: the table has no friction coordinates mu, mu_w (made "
                    "by an older pressridge); re-tabulate its campaign to choose C_f by friction"
                )
            return cf.cf_nodes(0), None
        want = f or DEFAULT_FRICTION
        s = cf.friction_set(*want)
        return cf.cf_nodes(s), tuple(pairs[s])
    if isinstance(cf, (str, _os.PathLike)) and not (isinstance(cf, str) and cf in CF_PRESETS):
        p = _os.fspath(cf)
        if _os.path.exists(p):
            h, c, label = _core.read_cf_table_at_friction(p, f)
            return (h, c), (None if label is None else tuple(label))
    if f is not None:
        raise ValueError(
            "friction chooses the C_f of a table: give cf= a pressridge.Table or a table file"
        )
    return None, None


def _constant_cf(cf: CfLike) -> bool:
    """Whether ``cf`` is a constant (none, a number or a preset name) rather than a table."""
    return cf is None or isinstance(cf, (int, float)) or (isinstance(cf, str) and cf in CF_PRESETS)


def _mu_rdg_nodes(table: Any, friction: Any = None) -> Optional[Tuple[list, list]]:
    """Normalises ``mu_rdg_table`` to (thickness m, mu_rdg m^0.5) nodes for the core: a
    ridging table file's ``mu_rdg`` at ``friction``, or node arrays as given."""
    if table is None:
        return None
    if isinstance(table, (str, _os.PathLike)):
        return _core.mu_rdg_table_nodes(_os.fspath(table), friction)
    try:
        h, m = table
        return [float(x) for x in _np.ravel(h)], [float(x) for x in _np.ravel(m)]
    except (TypeError, ValueError):
        raise ValueError(
            "mu_rdg_table must be the path of a ridging table or (thickness_m, mu_rdg) node "
            f"arrays, got {type(table).__name__}"
        ) from None


def _cf_args(cf: CfLike, friction: Any = None) -> Tuple[Optional[float], Optional[tuple], Optional[str]]:
    """Normalises ``cf`` to (constant, (thickness, cf) nodes, file) for the core; tables
    and table files give the nodes at ``friction`` (default :data:`DEFAULT_FRICTION`)."""
    nodes, _ = _cf_table_nodes(cf, friction)
    if nodes is not None:
        return None, (list(nodes[0]), list(nodes[1])), None
    if cf is None:
        return None, None, None
    if isinstance(cf, (bool, _np.bool_)):
        raise ValueError("cf must be a number, a preset name, a table or a file, not a bool")
    if isinstance(cf, (int, float, _np.integer, _np.floating)):
        return float(cf), None, None
    if isinstance(cf, str) and cf in CF_PRESETS:
        return CF_PRESETS[cf], None, None
    if isinstance(cf, (str, _os.PathLike)):
        p = _os.fspath(cf)
        if isinstance(cf, str) and not _os.path.exists(p):
            raise ValueError(
                f"cf = {cf!r} is neither a C_f preset ({', '.join(CF_PRESETS)}) nor an "
                "existing C_f table file"
            )
        return None, None, p
    if isinstance(cf, tuple) and len(cf) == 2:
        h = _f64(cf[0], "cf thickness nodes").ravel().tolist()
        c = _f64(cf[1], "cf values").ravel().tolist()
        return None, (h, c), None
    raise ValueError(
        "cf must be a number, a preset name "
        f"({', '.join(CF_PRESETS)}), a (thickness, cf) pair of arrays, a pressridge.Table "
        f"or the path of a C_f table file; got {type(cf).__name__}"
    )


def _resolve_cf(cf: CfLike, friction: Any = None) -> CfLike:
    """``cf`` with tables and files read into (thickness, cf) nodes at ``friction``, so
    that it pickles cheaply."""
    value, nodes, path = _cf_args(cf, friction)
    if path is not None:
        h, c = _core.read_cf_table(path)
        return (h, c)
    if nodes is not None:
        return (_np.asarray(nodes[0]), _np.asarray(nodes[1]))
    return value


def _scalar_if_0d(a: _np.ndarray) -> Any:
    return a[()] if a.ndim == 0 else a


def strength(
    aicen: Any,
    vicen: Any,
    aice0: Any = None,
    *,
    options: Optional[StrengthOptions] = None,
    participation: Optional[Participation] = None,
    redistribution: Optional[Redistribution] = None,
    law: Optional[StrengthLaw] = None,
    cf: CfLike = None,
    friction: Optional[Tuple[float, float]] = None,
    valid: Any = None,
    mu_rdg_table: Any = None,
    _clamp_note: Optional[str] = None,
    **params: float,
) -> Any:
    """Ice strength P (N/m) of thickness distributions, as CICE/Icepack
    ``icepack_ice_strength``.

    Parameters
    ----------
    aicen : array_like, shape (ncat, ...)
        Ice area fraction of each category (dimensionless). **Axis 0 is the category
        axis**, whatever the data: the other axes are columns (any spatial shape). A CICE
        history array ``aicen(time, nc, nj, ni)`` must first be moved
        (``np.moveaxis(a, 1, 0)``), or given as a dataset to :func:`pressridge.xr.strength`,
        which finds the category dimension by name.
    vicen : array_like, same shape as ``aicen``
        Ice volume per unit grid-cell area of each category (m).
    aice0 : array_like, shape ``aicen.shape[1:]``, optional
        Open-water fraction (dimensionless). Default: 1 - sum(aicen) (then sum(aicen) may
        not exceed 1). When given, aice0 + sum(aicen) must be 1 within
        ``area_tolerance`` (1e-6). A column with aice0 and every aicen exactly 0 (land)
        has strength 0.
    options : StrengthOptions, optional
        The options below as one typed value (:class:`StrengthOptions`; default: CICE's,
        as ``StrengthOptions()``). A keyword option given explicitly (not None) overrides
        the same field of ``options``; parameter keywords are laid over ``options.params``.
    participation : {"exponential", "thorndike"}
        Participation function: Lipscomb et al. (2007) (CICE ``krdg_partic = 1``, default)
        or Thorndike et al. (1975) (0).
    redistribution : {"exponential", "uniform", "table"}
        Ridged-ice redistribution: Lipscomb et al. (2007) (``krdg_redist = 1``, default),
        Hibler (1980) (0), or Lipscomb's exponential with mu_rdg per category thickness
        from ``mu_rdg_table`` (the simulator's ridges; clamped at the table's ends).
    law : {"rothrock", "hibler"}
        Rothrock (1975) energetics with C_f (``kstrength = 1``, default) or Hibler (1979)
        P = P* h exp(-C* (1 - A)) (0).
    cf : float, str, Table, path or (thickness, cf) pair, optional
        Frictional factor C_f (dimensionless; Rothrock only): a number; a preset
        ``"cice"`` (17, the default), ``"flato1991"`` (15), ``"hibler1980"`` (2); a
        :class:`Table` (its first set's C_f against the ridging ice's thickness); the path
        of a C_f table file (``thickness`` in m and ``cf``, as ``--cf-table``); or node
        arrays ``(thickness_m, cf)``. Tables are interpolated linearly in the thickness of
        the ridging category and clamped outside their range (with a
        :class:`CfClampedWarning`).
    friction : (float, float), optional
        With a :class:`Table` or a table file made by ``pressridge tabulate``: the friction
        pair (mu, mu_w) (dimensionless, between blocks above and below the water line) of
        the simulations whose C_f to use; default :data:`DEFAULT_FRICTION` (1.0, 0.6). A
        pair the table does not hold raises :class:`ValueError` listing the pairs it has.
        An error with a constant C_f. :func:`pressridge.xr.strength` records the pair in
        the ``cf_friction`` attribute.
    valid : array_like of bool, shape ``aicen.shape[1:]``, optional
        Columns to compute; the others (land, missing data) are not checked and get NaN.
    mu_rdg_table : path or (thickness, mu_rdg) pair, optional
        With ``redistribution="table"``: a ridging table of ``pressridge tabulate`` whose
        ``mu_rdg`` (m^0.5) at ``friction`` (default :data:`DEFAULT_FRICTION`) to use, or
        node arrays ``(thickness_m, mu_rdg)``; as the command line's ``--mu-rdg-table``.
    **params : float
        Overrides of the ITD parameters by name (see :data:`PARAMETERS`,
        e.g. ``mu_rdg=4.0``, ``pstar=2.75e4``); defaults are CICE's.

    Returns
    -------
    numpy.ndarray of shape ``aicen.shape[1:]`` (a float for 1-D input)
        Strength P (N/m), in the memory order of ``aicen`` (C or Fortran).

    Raises
    ------
    ValueError
        NaN, infinite or negative values (naming the spatial index and category), areas
        that do not sum to 1, mismatched shapes, unknown options or parameters.
    OSError
        An unreadable C_f table file (FileNotFoundError if it does not exist).
    """
    a = _f64(aicen, "aicen")
    v = _f64(vicen, "vicen")
    a0 = None if aice0 is None else _f64(aice0, "aice0")
    ok = None if valid is None else _bool(valid, "valid")
    participation, redistribution, law, cf, friction, params = _options.merge(
        options, participation, redistribution, law, cf, friction, params
    )
    mu_nodes = _mu_rdg_nodes(mu_rdg_table, friction)
    # With a mu_rdg table, `friction` chooses its set, and the C_f table's only if C_f is one.
    value, nodes, path = _cf_args(
        cf, None if mu_nodes is not None and _constant_cf(cf) else friction
    )
    out, clamped, material, share_max = _core.strength(
        a,
        v,
        a0,
        ok,
        dict(
            participation=participation,
            redistribution=redistribution,
            law=law,
            cf_value=value,
            cf_nodes=nodes,
            cf_file=path,
            mu_rdg_nodes=mu_nodes,
            params=_params(params),
        ),
    )
    if clamped:
        ncol = int(_np.prod(a.shape[1:], dtype=_np.int64))
        # _clamp_note (pressridge.xr, per dask chunk): one text for every chunk of a call, so
        # that the warnings filter shows it once per call rather than once per chunk.
        text = (
            f"{clamped} of {ncol} columns had ridging-ice thicknesses outside the C_f "
            "table; C_f was clamped to the table's end values there; the clamped ice "
            f"carries >= {CF_CLAMPED_MATERIAL_SHARE:.0%} of the strength in {material} of them "
            f"(at most {share_max:.1%})"
            if _clamp_note is None
            else "some columns had ridging-ice thicknesses outside the C_f table; C_f was "
            f"clamped to the table's end values there ({_clamp_note})"
        )
        _warnings.warn(text, CfClampedWarning, stacklevel=2)
    return _scalar_if_0d(out)


TracerLayout = _core.TracerLayout
# Its documentation is the Rust doc comment of `PyTracerLayout` (python/src/tracers.rs).


#: Names, units and meanings of the per-cell outputs of the complete step (from the Rust
#: ``itd::CELL_OUTPUTS``), of its per-category outputs (``itd::CATEGORY_OUTPUTS``) and of its
#: per-species outputs (``itd::SPECIES_OUTPUTS``: aerosol and isotope fluxes):
#: ``{name: (units, long_name)}``.
STEP_CELL_OUTPUTS: dict
STEP_CATEGORY_OUTPUTS: dict
STEP_SPECIES_OUTPUTS: dict
_cell, _cat, _species = _core.step_outputs()
STEP_CELL_OUTPUTS = {n: (u, ln) for n, u, ln in _cell}
STEP_CATEGORY_OUTPUTS = {n: (u, ln) for n, u, ln in _cat}
STEP_SPECIES_OUTPUTS = {n: (u, ln) for n, u, ln in _species}
del _cell, _cat, _species


class RidgeStepResult(NamedTuple):
    """The outcome of :func:`ridge_step`: the updated state, the rates and, for the complete
    step, snow, tracers, ocean fluxes and diagnostics (``None`` for the area-volume step)."""

    #: Area fraction of each category after the step (dimensionless), shape (ncat, ...).
    aicen: Any
    #: Ice volume per unit area of each category after the step (m).
    vicen: Any
    #: Open-water fraction after the step (dimensionless).
    aice0: Any
    #: Net closing rate requested at the start of the step (1/s).
    closing: Any
    #: Opening rate (1/s; the complete step: of the last ridging pass, Icepack ``opening``).
    opening: Any
    #: Rate of fractional area loss by ridging ice (1/s, CICE ``dardg1dt``).
    dardg1dt: Any
    #: Rate of fractional area gain by new ridges (1/s, CICE ``dardg2dt``).
    dardg2dt: Any
    #: Rate of ice volume ridged (m/s, CICE ``dvirdgdt``).
    dvirdgdt: Any
    #: Snow volume per unit area of each category after the step (m).
    vsnon: Any = None
    #: Tracers after the step, shape (ncat, ntrcr, ...) (``None`` when none were given).
    trcrn: Any = None
    #: Total ice area (dimensionless), recomputed by the clean-up (Icepack ``aice``).
    aice: Any = None
    #: Category bounds after the call (m): the top one is ``big`` (1e8 m) when closing came
    #: from the deformation, as Icepack writes it.
    hin_max: Any = None
    #: Fresh water into the ocean (kg m-2 s-1, averaged over ``ndtd*dt``).
    fresh: Any = None
    #: Salt into the ocean (kg m-2 s-1, averaged over ``ndtd*dt``).
    fsalt: Any = None
    #: Heat flux into the ocean (W m-2, averaged over ``ndtd*dt``; negative: the ocean melts
    #: the snow and ice put into it).
    fhocn: Any = None
    #: Pond water lost by ridging, with sign (m over the cell, per step): ``-dpnd_ridge``.
    fpond: Any = None
    #: Pond water drained by ridging (m over the cell, per step).
    dpnd_ridge: Any = None
    #: Ice volume per unit area put into the ocean by the clean-up (m, per step).
    ice_to_ocean: Any = None
    #: Snow volume per unit area put into the ocean by ridging and clean-up (m, per step).
    snow_to_ocean: Any = None
    #: Ridging passes done (a float array: NaN in masked columns).
    niter: Any = None
    #: Aerosol flux to the ocean per species (kg m-2 s-1, over ``ndtd*dt``; Icepack
    #: ``faero_ocn``), shape (n_aero, ...): the layout's aerosol species (none: shape (0, ...)).
    faero_ocn: Any = None
    #: Water-isotope flux to the ocean per species (kg m-2 s-1; ``fiso_ocn``), (n_iso, ...).
    fiso_ocn: Any = None
    #: Biogeochemical flux to the ocean per bio tracer (the tracer's unit times m s-1, e.g.
    #: mmol m-2 s-1; Icepack ``flux_bio``), (nbtrcr, ...): none without bio tracers
    #: (:meth:`TracerLayout.with_bgc`).
    flux_bio: Any = None
    #: Per-category diagnostics, shape (ncat, ...) each, Icepack's names and units
    #: (:data:`STEP_CATEGORY_OUTPUTS`): ``dardg1ndt``, ``dardg2ndt``, ``dvirdgndt``,
    #: ``aparticn``, ``krdgn``, ``araftn``, ``vraftn``, ``aredistn``, ``vredistn``,
    #: ``first_ice`` (1 where the clean-up emptied the category).
    categories: Optional[dict] = None


def ridge_step(
    aicen: Any,
    vicen: Any,
    aice0: Any = None,
    *,
    dt: float,
    convergence: Any = None,
    shear: Any = 0.0,
    hin_max: Any = None,
    participation: str = "exponential",
    redistribution: str = "exponential",
    valid: Any = None,
    vsnon: Any = None,
    trcrn: Any = None,
    layout: Optional[TracerLayout] = None,
    aice: Any = None,
    closing: Any = None,
    opening: Any = None,
    tf: Any = None,
    ndtd: Optional[int] = None,
    cleanup: Optional[bool] = None,
    rebin: Optional[bool] = None,
    salt_flux: Optional[str] = None,
    mu_rdg_table: Any = None,
    friction: Optional[Tuple[float, float]] = None,
    **params: float,
) -> RidgeStepResult:
    """One ridging step; the inputs are not modified.

    Two routines, chosen by the arguments:

    * **the complete step** (Icepack ``icepack_step_ridge``, Rust
      ``itd::ridge_step_column``, the C ``pressridge_ridge_cell``, bit for bit) when
      ``trcrn``, ``vsnon`` or ``closing`` is given: ice area, ice volume, snow volume and
      every tracer move together, the clean-up zaps tiny categories into the ocean fluxes;
    * **the area-volume step** (Icepack ``ridge_ice`` on ``aicen``, ``vicen`` only, Rust
      ``itd::ridge_batch``; the call of earlier versions, numbers unchanged)
      otherwise.

    Parameters
    ----------
    aicen, vicen : array_like, shape (ncat, ...)
        Area fractions (dimensionless) and ice volumes per unit area (m) per category.
    aice0 : array_like, shape ``aicen.shape[1:]``, optional
        Open-water fraction; default max(1 - sum(aicen), 0). The total area may exceed 1
        (what advection leaves) or fall below it.
    dt : float
        Dynamics time step (s, > 0).
    convergence : float or array_like
        Icepack ``rdg_conv`` = -min(div u, 0) (1/s, >= 0), a scalar or of the spatial
        shape. Needed unless ``closing`` is given.
    shear : float or array_like
        Icepack ``rdg_shear`` = (Delta - |div u|)/2 (1/s, >= 0); a fraction ``cs`` of it
        ridges. Default 0.
    hin_max : array_like of ncat + 1 floats, optional
        Category bounds (m); default CICE's ``kcatbound = 1`` bounds
        (:func:`category_bounds`).
    participation, redistribution : str
        As in :func:`strength`; ``redistribution="table"`` with ``mu_rdg_table`` (a
        ridging table file, its ``mu_rdg`` at ``friction``, default
        :data:`DEFAULT_FRICTION`, or ``(thickness_m, mu_rdg)`` nodes).
    valid : array_like of bool, optional
        Columns to step; the others are left unchanged and their aice0, rates, fluxes and
        diagnostics are NaN.
    vsnon : float or array_like, shape (ncat, ...), optional
        Snow volume per unit area per category (m); complete step. Default 0 (no snow).
        Snow needs its enthalpy: give ``trcrn`` with it.
    trcrn : array_like, shape (ncat, layout.ntrcr, ...), optional
        Tracers (complete step), in the order and units of ``layout``; per column the
        memory order of Icepack's ``trcrn(ntrcr, ncat)``. Without it the column carries no
        tracers (the clean-up's heat flux then has no enthalpy to carry).
    layout : TracerLayout
        The layout of ``trcrn`` (required with it), e.g.
        ``TracerLayout.cice(7, 1, age=True, first_year=True, level_ice=True, ponds=True)``.
    aice : float or array_like, optional
        Total ice area (Icepack ``aice``, only overwritten by the clean-up); default
        sum(aicen).
    closing, opening : float or array_like, optional
        The host's net closing and opening rates (1/s, >= 0; SIS2's convention): the
        complete step uses them as given (with ``hin_max`` as given) instead of deriving them
        from ``convergence`` and ``shear`` (CICE's convention). Give both.
    tf : float or array_like, optional
        Freezing temperature (degC) for the surface temperature of emptied categories: a
        number for every column or an array of the spatial shape (one per column, e.g.
        from the sea-surface salinity); default -1.8.
    ndtd : int, optional
        Dynamics subcycles per thermodynamic step (>= 1, default 1); the ocean fluxes are
        averaged over ``ndtd*dt``.
    cleanup, rebin : bool, optional
        Icepack's ``docleanup`` and ``dorebin`` (default True): run the clean-up (zap tiny
        categories into the ocean fluxes, rebin) after ridging.
    salt_flux : str, optional
        Complete step: salt flux of the ice the clean-up zaps, Icepack's
        ``saltflux_option``: ``"constant"`` (default; ``ice_ref_salinity``) or
        ``"prognostic"`` (its own salinity).
    **params : float
        ITD parameter overrides (:data:`PARAMETERS`, e.g. ``cs=0.5``, ``rhoi=917.0`` in
        kg m-3) and, for the complete step, its thermodynamic constants
        (:data:`STEP_PARAMETERS`, e.g. ``rhos=330.0`` kg m-3, ``lfresh=3.34e5`` J kg-1,
        ``fsnowrdg=0.5``), each in the units listed there.

    Returns
    -------
    RidgeStepResult
        New arrays in the memory order of the input (C or Fortran). The area-volume step
        fills ``aicen``, ``vicen``, ``aice0`` and the rates ``closing``, ``opening``,
        ``dardg1dt``, ``dardg2dt`` (1/s), ``dvirdgdt`` (m/s); the complete step also
        ``vsnon``, ``trcrn`` (if given), ``aice``, ``hin_max``, the fluxes ``fresh``,
        ``fsalt`` (kg m-2 s-1), ``fhocn`` (W m-2), ``fpond``, ``dpnd_ridge`` (m),
        ``ice_to_ocean``, ``snow_to_ocean`` (m), ``niter``, the aerosol and isotope fluxes
        ``faero_ocn``, ``fiso_ocn`` (kg m-2 s-1, one row per species of the layout) and
        ``categories``. Area, ice and snow volume, enthalpy, salt, aerosols and isotopes are
        conserved with the fluxes to round-off.

    Raises
    ------
    ValueError
        Bad shapes, NaN, infinite or negative values, a column where Icepack would abort or
        return a negative amount (naming the spatial index and what is wrong), unknown
        options or parameters.
    """
    a = _f64(aicen, "aicen")
    v = _f64(vicen, "vicen")
    if a.ndim == 0:
        raise ValueError("aicen has shape (); it needs the category axis first")
    spatial = a.shape[1:]
    a0 = None if aice0 is None else _f64(aice0, "aice0")
    ok = None if valid is None else _bool(valid, "valid")

    def field(x: Any, name: str, shape: tuple = spatial) -> _np.ndarray:
        f = _f64(x, name)
        try:
            return _np.broadcast_to(f, shape)
        except ValueError:
            what = "spatial shape" if shape == spatial else "shape"
            raise ValueError(
                f"{name} has shape {f.shape}, which does not broadcast to the {what} of "
                f"aicen {shape}"
            ) from None

    try:
        dt_f = float(dt)
    except (TypeError, ValueError):
        raise ValueError(f"dt must be a number of seconds, got {dt!r}") from None
    h = None if hin_max is None else _f64(hin_max, "hin_max").ravel().tolist()
    complete = vsnon is not None or trcrn is not None or closing is not None
    if not complete:
        extra = [
            k
            for k, x in (
                ("layout", layout),
                ("aice", aice),
                ("opening", opening),
                ("tf", tf),
                ("ndtd", ndtd),
                ("cleanup", cleanup),
                ("rebin", rebin),
                ("salt_flux", salt_flux),
            )
            if x is not None
        ] + [k for k in params if k in STEP_PARAMETERS]
        if extra:
            raise ValueError(
                f"{', '.join(extra)} belong(s) to the complete step: give trcrn (with layout), "
                "vsnon or closing as well"
            )
        if convergence is None:
            raise ValueError(
                "convergence is needed (1/s), or closing and opening (the host's rates)"
            )
        conv = field(convergence, "convergence")
        shr = field(shear, "shear")
        a_new, v_new, a0_new, rates = _core.ridge_step(
            a,
            v,
            a0,
            h,
            conv,
            shr,
            dt_f,
            ok,
            participation,
            redistribution,
            _params(params, step=True),
            _mu_rdg_nodes(mu_rdg_table, friction),
        )
        return RidgeStepResult(
            a_new, v_new, _scalar_if_0d(a0_new), *[_scalar_if_0d(r) for r in rates]
        )

    if vsnon is not None and trcrn is None:
        raise ValueError(
            "vsnon needs trcrn (with layout): the snow's enthalpy is a tracer, and snow "
            "without it would be zapped by the clean-up"
        )
    if trcrn is not None and layout is None:
        raise ValueError("trcrn needs layout= (a pressridge.TracerLayout)")
    if layout is not None and not isinstance(layout, TracerLayout):
        raise ValueError(f"layout must be a pressridge.TracerLayout, got {type(layout).__name__}")
    rates_given = closing is not None
    if rates_given:
        if opening is None:
            raise ValueError("closing needs opening (1/s): the host gives both rates")
        if convergence is not None:
            raise ValueError("give convergence/shear (CICE) or closing/opening (SIS2), not both")
        c1 = field(closing, "closing")
        c2 = field(opening, "opening")
    else:
        if opening is not None:
            raise ValueError("opening is given without closing: give both (the host's rates)")
        if convergence is None:
            raise ValueError(
                "convergence is needed (1/s), or closing and opening (the host's rates)"
            )
        c1 = field(convergence, "convergence")
        c2 = field(shear, "shear")
    s = _np.zeros(a.shape) if vsnon is None else field(vsnon, "vsnon", a.shape)
    t = None if trcrn is None else _f64(trcrn, "trcrn")
    ai = None if aice is None else field(aice, "aice")
    tf_a = field(-1.8 if tf is None else tf, "tf")
    n = 1 if ndtd is None else ndtd
    if isinstance(n, (bool, _np.bool_)) or not isinstance(n, (int, _np.integer)):
        raise ValueError(f"ndtd must be an integer >= 1, got {ndtd!r}")
    (a_new, v_new, s_new), t_new, (a0_new, ai_new), h_used, cell, cats, species = (
        _core.ridge_step_full(
            a,
            v,
            s,
            t,
            layout,
            a0,
            ai,
            h,
            c1,
            c2,
            rates_given,
            tf_a,
            dt_f,
            int(n),
            ok,
            participation,
            redistribution,
            _params(params, step=True),
            True if cleanup is None else bool(cleanup),
            True if rebin is None else bool(rebin),
            "constant" if salt_flux is None else str(salt_flux),
            _mu_rdg_nodes(mu_rdg_table, friction),
        )
    )
    c = {k: _scalar_if_0d(x) for k, x in cell}
    sp = dict(species)
    return RidgeStepResult(
        aicen=a_new,
        vicen=v_new,
        aice0=_scalar_if_0d(a0_new),
        closing=c["closing"],
        opening=c["opening"],
        dardg1dt=c["dardg1dt"],
        dardg2dt=c["dardg2dt"],
        dvirdgdt=c["dvirdgdt"],
        vsnon=s_new,
        trcrn=t_new,
        aice=_scalar_if_0d(ai_new),
        hin_max=h_used,
        fresh=c["fresh"],
        fsalt=c["fsalt"],
        fhocn=c["fhocn"],
        fpond=c["fpond"],
        dpnd_ridge=c["dpnd_ridge"],
        ice_to_ocean=c["ice_to_ocean"],
        snow_to_ocean=c["snow_to_ocean"],
        niter=c["niter"],
        faero_ocn=sp["faero_ocn"],
        fiso_ocn=sp["fiso_ocn"],
        flux_bio=sp["flux_bio"],
        categories=dict(cats),
    )


def category_bounds(ncat: int, scheme: str = "round_numbers") -> _np.ndarray:
    """The ``ncat + 1`` category bounds hin_max (m) of CICE's ``kcatbound`` options:
    ``"round_numbers"`` (1, default: 0, 0.6, 1.4, 2.4, 3.6, 5 m for 5 categories),
    ``"original"`` (0), ``"wmo"`` (2), ``"asymptotic"`` (3), ``"single"`` (-1)."""
    return _core.category_bounds(int(ncat), scheme)
