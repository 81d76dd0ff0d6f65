"""xarray and dask face of pressridge: ice strength and the ridging step on an
:class:`xarray.Dataset` holding a thickness distribution.

The dataset has ``aicen`` (dimensionless) and ``vicen`` (m) with one category dimension,
found **by name**, anywhere among their dimensions: ``category_dim=`` if given, else the one
dimension named as in :data:`CATEGORY_DIMS` (CICE history ``nc``, as in
``aicen(time, nc, nj, ni)``; CICE restart and ``data/sample_itd.nc`` ``ncat``; SIS2
diagnostics ``ct``). No such dimension, or more than one, is an error listing the dimensions
seen. Every other dimension (``time``, ``nj``, ``ni``, an ensemble member...) is kept.
Optional: ``aice0``, ``hin_max`` (m, ncat + 1 values; else CICE history's ``NCAT``, the
upper bound of each category, from 0 m), ``divu`` and ``shear`` (1/s); for the complete
ridging step ``vsnon`` (m), the tracers under their CICE restart names (the layout told from
them) and ``Tf`` (degC). The functions go
through :func:`xarray.apply_ufunc` with ``dask="parallelized"``: on dask-backed data they
stay lazy and work chunk by chunk, chunked over the other dimensions only (the category
dimension is gathered into one chunk). Coordinates are kept; the outputs carry CF
``units``, ``long_name`` (``standard_name`` where CF has one) and the options used as
attributes.

Missing data: when ``aicen``, ``vicen`` or ``aice0`` has a ``_FillValue`` or
``missing_value`` (so that xarray decoded missing cells to NaN), columns with a NaN are
treated as masked (land) and give NaN, as ``pressridge strength`` does with fill values.
Otherwise a NaN is an error. ``mask=True``/``False`` forces either behaviour. CICE's
ocean mask ``tmask`` (1 ocean, 0 land), where the dataset has it, marks land too: cells
where it is 0 are missing in the outputs, as ``pressridge strength`` does (not with
``mask=False``).
"""

from __future__ import annotations

import itertools
from typing import Any, Hashable, List, Optional, Tuple, Union

import numpy as np
import xarray as xr

import pressridge as _pr

__all__ = ["strength", "ridge_step"]


#: Names of the category dimension looked for, when ``category_dim`` is not given: CICE
#: history files (``nc``), CICE restart and pressridge files (``ncat``), SIS2 diagnostics
#: (``ct``). The list is the command line's (``pressridge::io::itd_netcdf::CATEGORY_DIM_NAMES``,
#: read from the Rust core); assign a longer tuple here to look for more names, e.g.
#: ``pressridge.xr.CATEGORY_DIMS += ("zaxis_1",)``.
CATEGORY_DIMS = tuple(_pr._core.CATEGORY_DIMS)


def _find_category_dim(aicen: xr.DataArray, category_dim: Optional[Hashable]) -> Hashable:
    """The category dimension of ``aicen``: ``category_dim`` if given, else the one dimension
    named as in :data:`CATEGORY_DIMS`; none or several is an error listing the dimensions."""
    dims = ", ".join(f"{d}={n}" for d, n in aicen.sizes.items())
    if category_dim is not None:
        if category_dim not in aicen.dims:
            raise ValueError(f"aicen has no dimension {category_dim!r} (dims {aicen.dims})")
        return category_dim
    found = [d for d in aicen.dims if d in CATEGORY_DIMS]
    if len(found) == 1:
        return found[0]
    if not found:
        raise ValueError(
            f"aicen has dimensions ({dims}) and none is a category dimension "
            f"({', '.join(CATEGORY_DIMS)}); name it with category_dim="
        )
    raise ValueError(
        f"aicen has dimensions ({dims}) and more than one is named as a category dimension "
        f"({', '.join(map(str, found))}); name the right one with category_dim="
    )


def _category_vars(ds: xr.Dataset, category_dim: Optional[Hashable]):
    for name in ("aicen", "vicen"):
        if name not in ds:
            raise ValueError(f"the dataset has no variable `{name}`")
    aicen = ds["aicen"]
    if aicen.ndim == 0:
        raise ValueError("aicen is a scalar; it needs a category dimension")
    cat = _find_category_dim(aicen, category_dim)
    vicen = ds["vicen"]
    if set(vicen.dims) != set(aicen.dims):
        raise ValueError(f"vicen has dimensions {vicen.dims}, expected those of aicen {aicen.dims}")
    spatial = [d for d in aicen.dims if d != cat]
    aice0 = ds["aice0"] if "aice0" in ds else None
    if aice0 is not None and set(aice0.dims) != set(spatial):
        raise ValueError(
            f"aice0 has dimensions {aice0.dims}, expected the spatial dimensions {tuple(spatial)}"
        )
    # Category dimension whole, so chunks split the spatial dimensions only.
    if aicen.chunks is not None:
        aicen = aicen.chunk({cat: -1})
    if vicen.chunks is not None:
        vicen = vicen.chunk({cat: -1})
    return aicen, vicen, aice0, cat, spatial


def _has_fill(*vars: Optional[xr.DataArray]) -> bool:
    keys = ("_FillValue", "missing_value")
    return any(
        v is not None and any(k in v.encoding or k in v.attrs for k in keys) for v in vars
    )


def _mask_flag(mask: Union[str, bool], *vars: Optional[xr.DataArray]) -> bool:
    if mask == "auto":
        return _has_fill(*vars)
    if isinstance(mask, bool):
        return mask
    raise ValueError(f"mask must be 'auto', True or False, got {mask!r}")


def _apply_tmask(ds: xr.Dataset, aicen: xr.DataArray, use_mask: bool, mask: Union[str, bool]):
    """CICE's ocean mask ``tmask`` (1 ocean, 0 land; over ``nj, ni``, without ``time``):
    land cells (0 or missing) become missing in ``aicen`` and so in the outputs, as a
    ``_FillValue`` does, unless ``mask=False``."""
    if mask is False or "tmask" not in ds:
        return aicen, use_mask
    tmask = ds["tmask"]
    extra = set(tmask.dims) - set(aicen.dims)
    if extra:
        raise ValueError(
            f"tmask has dimensions {tuple(tmask.dims)}, not all among those of aicen "
            f"{tuple(aicen.dims)}"
        )
    ocean = (tmask != 0) & tmask.notnull()
    return aicen.where(ocean).transpose(*aicen.dims), True


def _valid(a: np.ndarray, v: np.ndarray, a0: Optional[np.ndarray]) -> np.ndarray:
    """Columns without a missing (NaN) value; a, v have the category axis first."""
    bad = np.isnan(a).any(axis=0) | np.isnan(v).any(axis=0)
    if a0 is not None:
        bad |= np.isnan(a0)
    return ~bad


def _strength_block(a, v, *rest, has_aice0, mask, options, clamp_note):
    # apply_ufunc moved the category axis last; put it first again (a view, no copy).
    a = np.moveaxis(a, -1, 0)
    v = np.moveaxis(v, -1, 0)
    a0 = rest[0] if has_aice0 else None
    valid = _valid(a, v, a0) if mask else None
    return np.asarray(
        _pr.strength(a, v, a0, valid=valid, _clamp_note=clamp_note, **options)
    )


_calls = itertools.count(1)


def strength(
    ds: xr.Dataset,
    *,
    options: Optional[_pr.StrengthOptions] = None,
    participation: Optional[_pr.Participation] = None,
    redistribution: Optional[_pr.Redistribution] = None,
    law: Optional[_pr.StrengthLaw] = None,
    cf: Any = None,
    friction: Optional[Tuple[float, float]] = None,
    category_dim: Optional[Hashable] = None,
    mask: Union[str, bool] = "auto",
    mu_rdg_table: Any = None,
    **params: float,
) -> xr.DataArray:
    """Ice strength P (N/m) of the thickness distribution in ``ds``.

    Options and parameters as :func:`pressridge.strength` (``cf`` may be a number, a preset
    name, a :class:`pressridge.Table`, a C_f table file or (thickness, cf) nodes; with a
    table, ``friction`` = (mu, mu_w) chooses its set, default (1.0, 0.6), and the output's
    ``cf_friction`` attribute records the pair; ``redistribution="table"`` with
    ``mu_rdg_table``, a ridging table file or nodes, read once here, its nodes recorded in
    the ``mu_rdg_table`` attribute). ``options`` is a
    :class:`pressridge.StrengthOptions`; keywords given explicitly override its fields and
    parameter keywords are laid over its ``params``, as in :func:`pressridge.strength`.
    ``category_dim`` names the category dimension (default: the one dimension of ``aicen``
    named as in :data:`CATEGORY_DIMS`; a dataset with none or several is refused with the
    dimensions listed); every other dimension (``time``, ``nj``, ``ni``, ensemble...) is a
    column dimension and is kept, in the order of ``aicen``.

    Returns a :class:`xarray.DataArray` named ``strength`` (N m-1) on the other dimensions of
    ``aicen``, with their coordinates; lazy (dask) when the input is. Errors in the data
    raise :class:`ValueError` when computed.
    """
    aicen, vicen, aice0, cat, spatial = _category_vars(ds, category_dim)
    use_mask = _mask_flag(mask, ds["aicen"], ds["vicen"], aice0)
    aicen, use_mask = _apply_tmask(ds, aicen, use_mask, mask)
    participation, redistribution, law, cf, friction, params = _pr._options.merge(
        options, participation, redistribution, law, cf, friction, params
    )
    # Read a C_f file once here, so that the tasks carry only small arrays.
    block_options = dict(
        participation=participation,
        redistribution=redistribution,
        law=law,
        cf=None,
        **params,
    )
    # A mu_rdg table file is read once, at the friction asked for: its nodes go to the tasks.
    mu_nodes = _pr._mu_rdg_nodes(mu_rdg_table, friction)
    block_options["mu_rdg_table"] = mu_nodes
    if mu_nodes is not None and _pr._constant_cf(cf):
        friction = None  # it chose the mu_rdg table's set; the C_f is a constant
    # A table (or its file) is read once: its nodes at the friction asked for, and the pair.
    nodes, cf_friction = _pr._cf_table_nodes(cf, friction)
    block_options["cf"] = (
        _pr._resolve_cf(cf) if nodes is None else (np.asarray(nodes[0]), np.asarray(nodes[1]))
    )
    _pr._params(params)  # unknown names fail now, not at compute time
    args: List[xr.DataArray] = [aicen, vicen]
    if aice0 is not None:
        args.append(aice0)
    out = xr.apply_ufunc(
        _strength_block,
        *args,
        input_core_dims=[[cat], [cat]] + [[]] * (len(args) - 2),
        output_core_dims=[[]],
        dask="parallelized",
        output_dtypes=[np.float64],
        kwargs=dict(
            has_aice0=aice0 is not None,
            mask=use_mask,
            options=block_options,
            # Lazy data: every chunk warns with the same text (this call's number), which
            # the warnings filter shows once; eager data is one block: the exact count.
            clamp_note=(
                None
                if aicen.chunks is None
                else f"pressridge.xr.strength call {next(_calls)}, over dask chunks"
            ),
        ),
        keep_attrs=True,  # keeps the coordinates' attributes; data attributes set below
    )
    out = out.transpose(*spatial)
    out.name = "strength"
    cf_desc = block_options["cf"]
    units, long_name, standard_name = _pr._core.STRENGTH_META
    out.attrs = {
        "units": units,
        "long_name": long_name,
        "standard_name": standard_name,
        "participation": participation,
        "redistribution": redistribution,
        **_mu_rdg_attrs(mu_nodes),
        "strength_formula": law,
        "cf": _describe_cf(cf, cf_desc),
        "cf_friction": (
            "not applicable: constant C_f"
            if not isinstance(cf_desc, tuple)
            else "unknown: the C_f source does not say"
            if cf_friction is None
            else f"mu = {cf_friction[0]:g}, mu_w = {cf_friction[1]:g}"
        ),
        "parameter_overrides": ", ".join(f"{k}={v}" for k, v in params.items()) or "none",
        "source": f"pressridge {_pr.__version__} (Python)",
    }
    return out


def _describe_cf(cf: Any, resolved: Any) -> str:
    if resolved is None:
        return f"constant {_pr.CF_PRESETS['cice']}"
    if isinstance(resolved, float):
        return f"constant {resolved}"
    h = np.asarray(resolved[0])
    where = f" from {getattr(cf, 'path', cf)}" if not isinstance(cf, tuple) else ""
    return f"table of {h.size} nodes, thickness {h.min()} to {h.max()} m{where}"


_RATES = [
    ("closing", "s-1", "net closing rate"),
    ("opening", "s-1", "opening rate"),
    ("dardg1dt", "s-1", "rate of area loss by ridging ice"),
    ("dardg2dt", "s-1", "rate of area gain by new ridges"),
    ("dvirdgdt", "m s-1", "rate of ice volume ridged"),
]


def _ridge_block(a, v, *rest, names, scalars, mask, options):
    a = np.moveaxis(a, -1, 0)
    v = np.moveaxis(v, -1, 0)
    fields = dict(zip(names, rest))
    fields.update(scalars)
    a0 = fields.get("aice0")
    valid = _valid(a, v, a0) if mask else None
    r = _pr.ridge_step(
        a,
        v,
        a0,
        convergence=fields["convergence"],
        shear=fields["shear"],
        valid=valid,
        **options,
    )
    return (
        np.moveaxis(r.aicen, 0, -1),
        np.moveaxis(r.vicen, 0, -1),
        *[np.broadcast_to(np.asarray(x), a.shape[1:]) for x in r[2:8]],
    )



def _bounds_from(ds: xr.Dataset) -> Optional[np.ndarray]:
    """Category bounds (m) from ``hin_max`` or CICE history's ``NCAT`` (upper bounds, from
    0 m), as the command line; both present must agree (to NCAT's single precision)."""
    h = np.asarray(ds["hin_max"].values, dtype=np.float64) if "hin_max" in ds else None
    n = None
    if "NCAT" in ds:
        n = np.concatenate([[0.0], np.asarray(ds["NCAT"].values, dtype=np.float64).ravel()])
    if h is not None and n is not None:
        if h.shape != n.shape or not np.all(np.abs(h - n) <= 1e-6 * np.maximum(np.abs(h), 1.0)):
            raise ValueError(
                f"the category bounds disagree: hin_max is {h.tolist()} m, NCAT (upper "
                f"bounds, from 0 m) gives {n.tolist()} m"
            )
    return h if h is not None else n


def _mu_rdg_attrs(nodes) -> dict:
    """The ``mu_rdg_table`` attribute (its nodes) of a table redistribution, as the command
    line writes it; none otherwise."""
    if nodes is None:
        return {}
    pairs = ", ".join(f"{h:g}: {m:g}" for h, m in zip(*nodes))
    return {"mu_rdg_table": f"thickness (m): mu_rdg (m^0.5), linear, held at the ends: {pairs}"}


def _step_options(ds: xr.Dataset, dt, hin_max, participation, redistribution, /, mu_rdg=None,
                  **rest) -> dict:
    """The keywords of a ridging step: ``dt`` (s), the category bounds ``hin_max`` (m; from
    ``ds`` when None, see ``_bounds_from``), the two schemes (``mu_rdg``: the nodes of a
    table redistribution) and ``rest``."""
    if hin_max is None:
        hin_max = _bounds_from(ds)
    if mu_rdg is not None:
        rest["mu_rdg_table"] = mu_rdg
    return dict(
        dt=dt,
        hin_max=None if hin_max is None else np.asarray(hin_max, dtype=np.float64),
        participation=participation,
        redistribution=redistribution,
        **rest,
    )


_PER_SECOND = {"s-1", "1/s", "s^-1", "/s", "s**-1"}
_PERCENT_PER_DAY = {"%/day", "%/d", "%day-1", "percent/day"}


def _units(da: xr.DataArray) -> Optional[str]:
    u = da.attrs.get("units")
    return None if u is None else "".join(str(u).split())


def _is_percent_per_day(da: xr.DataArray) -> bool:
    return _units(da) in _PERCENT_PER_DAY


def _rate_per_second(da: xr.DataArray) -> xr.DataArray:
    """A strain rate in 1/s: CICE history %/day converted; s-1 as given; any other unit, or
    none, refused by name (as the command line does), so that %/day is never taken for 1/s."""
    u = _units(da)
    if u is None:
        raise ValueError(
            f"variable `{da.name}` has no `units` attribute; a strain rate must say its unit: "
            "'s-1' (1/s) or CICE history's '%/day'"
        )
    if u in _PER_SECOND:
        return da
    if u in _PERCENT_PER_DAY:
        return da / 100.0 / 86400.0
    raise ValueError(
        f"variable `{da.name}` has units {da.attrs.get('units')!r}; expected '%/day' "
        "(CICE history) or 's-1'"
    )

_DEGC = {"degc", "deg_c", "degrees_c", "degree_c", "degree_celsius", "degrees_celsius",
         "celsius", "c"}


def _temperature_degc(da: xr.DataArray) -> xr.DataArray:
    """A freezing temperature in degC: other units (K) or none refused by name, as the
    command line does."""
    u = _units(da)
    if u is None:
        raise ValueError(
            f"variable `{da.name}` has no `units` attribute; the freezing temperature must be "
            "in 'degC' (say so with units='degC')"
        )
    if u.lower() not in _DEGC:
        raise ValueError(
            f"variable `{da.name}` has units {da.attrs.get('units')!r}; expected 'degC'"
        )
    return da


def _constants_used(params: dict) -> dict:
    """Global attributes: the thermodynamic constants of the complete step used, with their
    units (as the command line writes them)."""
    def fmt(v: float) -> str:
        # Shortest round-trip digits, no exponent: Rust's `{}` of an f64, as the CLI writes.
        return np.format_float_positional(v, trim="-")

    rhoi = float(params.get("rhoi", _pr.DEFAULT_PARAMETERS["rhoi"]))
    out = {"rhoi": f"{fmt(rhoi)} kg m-3"}
    for name, (units, _) in _pr.STEP_PARAMETERS.items():
        v = float(params.get(name, _pr.DEFAULT_STEP_PARAMETERS[name]))
        out[name] = f"{fmt(v)} {units}"
    return out


def ridge_step(
    ds: xr.Dataset,
    *,
    dt: float,
    convergence: Any = None,
    shear: Any = None,
    hin_max: Any = None,
    participation: str = "exponential",
    redistribution: str = "exponential",
    category_dim: Optional[Hashable] = None,
    mask: Union[str, bool] = "auto",
    layout: Optional["_pr.TracerLayout"] = None,
    closing: Any = None,
    opening: Any = None,
    tf: Any = None,
    ndtd: Optional[int] = None,
    cleanup: Optional[bool] = None,
    rebin: Optional[bool] = None,
    salt_flux: Optional[str] = None,
    tracer_layout: Any = None,
    tracer_var: Optional[str] = None,
    mu_rdg_table: Any = None,
    friction: Optional[Tuple[float, float]] = None,
    **params: float,
) -> xr.Dataset:
    """One ridging step (``dt`` in s) of the thickness distribution in ``ds``.

    **The complete step** (snow, tracers, ocean fluxes; as :func:`pressridge.ridge_step`)
    runs when the dataset holds snow or tracers: ``vsnon`` (m; absent: no snow) and one
    variable per tracer under its CICE restart name (``Tsfcn``, ``qice001``..,
    ``qsno001``.., ``sice001``.., ``iage``, ``FY``, ``alvl``, ``vlvl``, ``apnd``, ``hpnd``,
    ``ipnd``), each with the dimensions of ``aicen``. The tracer layout is told from these
    names as the command line tells it (:meth:`pressridge.TracerLayout.detect`: the layers
    counted, each optional group used when complete; a missing member of a group, or
    ``vsnon`` without the enthalpies, is a ``ValueError`` naming the variable), or given
    as ``layout`` (a :class:`pressridge.TracerLayout` whose ``names`` the dataset holds; a
    dataset with CICE tracer variables the layout does not carry is refused as
    ambiguous). ``closing`` and ``opening`` (1/s, numbers or DataArrays) give the host's
    rates (SIS2) instead of the deformation (CICE). ``tf`` (degC; a number or a DataArray
    on the spatial dimensions) defaults to the dataset's ``Tf`` (its ``units`` must be
    degC), else -1.8. ``ndtd``, ``cleanup``, ``rebin``, ``salt_flux`` and the constants of
    :data:`pressridge.STEP_PARAMETERS` (keywords, SI units) as in
    :func:`pressridge.ridge_step`. The result then also has ``vsnon``, the tracers,
    ``aice``, the fluxes and diagnostics of :data:`pressridge.STEP_CELL_OUTPUTS` and
    :data:`pressridge.STEP_CATEGORY_OUTPUTS` (with their units), one field per species row
    of :data:`pressridge.STEP_SPECIES_OUTPUTS` (``faero_ocn001``, ..., ``fiso_ocn001``, ...,
    ``flux_bio001``, ..., as the command line names them), ``hin_max`` as Icepack
    leaves it, and the thermodynamic constants used as attributes (``rhoi``, ``rhos``, ...
    with their units).

    The category dimension is ``category_dim`` if given, else the one dimension of
    ``aicen`` named as in :data:`CATEGORY_DIMS` (``nc``, ``ncat``, ``ct``; none or several
    is refused with the dimensions listed); every other dimension (``time``, ``nj``,
    ``ni``...) is kept.

    ``convergence`` (1/s): a number or a DataArray on the spatial dimensions; default
    max(-divu, 0) from the dataset's ``divu``. ``shear`` (1/s): likewise; default the
    dataset's ``shear``, else 0. The dataset's ``divu`` and ``shear`` are read by their
    ``units``: ``s-1`` (or none) as given (``shear`` being the ridging shear term); ``%/day``
    (CICE history) converted, ``shear`` then being CICE's shear strain rate from which the
    term is formed as Icepack does; other units raise ``ValueError``. ``hin_max`` (m):
    default the dataset's ``hin_max``, else its ``NCAT`` (CICE history: upper bounds, from
    0 m; both present must agree), else CICE's ``kcatbound = 1`` bounds. ``aice0`` defaults to max(1 - sum(aicen), 0). Other options as
    :func:`pressridge.ridge_step`.

    **Packed tracers** (Icepack column driver's history, ``trcrn(time, ncat, ntrcr, ni)``):
    ``tracer_layout`` names their layout in Icepack's words, as the command line's
    ``--tracer-layout`` (a string for :meth:`pressridge.TracerLayout.from_icepack`, e.g.
    ``"icedrv"`` or ``"nilyr=7,nslyr=1,tr_iage,tr_FY,tr_lvl,tr_pond_lvl"``, or a CICE
    :class:`pressridge.TracerLayout`); ``tracer_var`` (default ``trcrn``) must have the
    dimensions of ``aicen`` and one more, as long as the layout's tracer count. The result
    holds the array again in the same dimensions, with the layout in its ``tracer_layout``
    attribute. A dataset with ``trcrn`` and no tracer under restart names needs
    ``tracer_layout``.

    Returns a copy of ``ds`` (coordinates, attributes and other variables kept) with
    ``aicen``, ``vicen``, ``aice0`` after the step and the rates ``closing``, ``opening``,
    ``dardg1dt``, ``dardg2dt`` (1/s) and ``dvirdgdt`` (m/s); lazy when the input is dask.
    """
    if tracer_layout is not None:
        unpacked, layout, repack = _unpack_tracers(ds, tracer_layout, tracer_var or "trcrn")
        return repack(ridge_step(
            unpacked, dt=dt, convergence=convergence, shear=shear, hin_max=hin_max,
            participation=participation, redistribution=redistribution,
            category_dim=category_dim, mask=mask, layout=layout, closing=closing,
            opening=opening, tf=tf, ndtd=ndtd, cleanup=cleanup, rebin=rebin,
            salt_flux=salt_flux, **params,
        ))
    if tracer_var is not None:
        raise ValueError("tracer_var needs tracer_layout, the layout of the packed tracers")
    if "trcrn" in ds and "Tsfcn" not in ds:
        raise ValueError(
            "the dataset holds the packed tracer array `trcrn`: name its layout with "
            "tracer_layout= in Icepack's names, e.g. tracer_layout='icedrv' for the column "
            "driver's defaults or 'nilyr=7,nslyr=1,tr_iage,tr_FY,tr_lvl,tr_pond_lvl'"
        )
    detected = _pr.TracerLayout.detect([str(n) for n in ds.data_vars])
    if layout is None:
        layout = detected
    elif detected is not None:
        if not isinstance(layout, _pr.TracerLayout):
            raise ValueError(
                f"layout must be a pressridge.TracerLayout, got {type(layout).__name__}"
            )
        extra_vars = [n for n in detected.names if n not in layout.names]
        if extra_vars:
            raise ValueError(
                f"ambiguous tracers: the dataset has {', '.join(extra_vars)}, which the "
                f"layout {layout!r} does not carry (they would not move with the ice); "
                f"pass layout=None to use the layout of the dataset ({detected!r}) or drop "
                "those variables"
            )
    if layout is None:
        extra = [
            k
            for k, x in (("closing", closing), ("opening", opening), ("tf", tf), ("ndtd", ndtd),
                         ("cleanup", cleanup), ("rebin", rebin), ("salt_flux", salt_flux))
            if x is not None
        ] + [k for k in params if k in _pr.STEP_PARAMETERS]
        if extra:
            raise ValueError(
                f"{', '.join(extra)} belong(s) to the complete step, but the dataset has no "
                "snow or tracer variables (vsnon, Tsfcn, qice001.., sice001.., qsno001..); "
                "pass layout= for tracers under other names"
            )
    aicen, vicen, aice0, cat, spatial = _category_vars(ds, category_dim)
    use_mask = _mask_flag(mask, ds["aicen"], ds["vicen"], aice0)
    aicen, use_mask = _apply_tmask(ds, aicen, use_mask, mask)
    _pr._params(params, step=True)
    # A mu_rdg table file is read once here; its nodes go to the tasks.
    mu_nodes = _pr._mu_rdg_nodes(mu_rdg_table, friction)
    if layout is not None and tf is None and "Tf" in ds:
        tf = _temperature_degc(ds["Tf"])
    conv_desc = "max(-divu, 0) from input"
    if layout is not None and closing is not None:
        if convergence is not None or shear is not None:
            raise ValueError("give convergence/shear (CICE) or closing/opening (SIS2), not both")
        if opening is None:
            raise ValueError("closing needs opening (1/s): the host gives both rates")
        return _complete(
            ds, aicen, vicen, aice0, cat, spatial, use_mask, layout, dt, hin_max,
            dict(closing=closing, opening=opening), "host closing/opening",
            participation, redistribution, tf, ndtd, cleanup, rebin, salt_flux, params,
            mu_nodes,
        )

    def _divu() -> Optional[xr.DataArray]:
        return _rate_per_second(ds["divu"]) if "divu" in ds else None

    if convergence is None:
        divu = _divu()
        if divu is None:
            raise ValueError("no convergence: pass convergence= or put `divu` in the dataset")
        convergence = (-divu).clip(min=0.0)
    elif not isinstance(convergence, xr.DataArray):
        conv_desc = f"{float(convergence)} s-1"
    shear_desc = "from input (or 0)"
    if shear is None:
        if "shear" not in ds:
            shear = 0.0
        elif _is_percent_per_day(ds["shear"]):
            # CICE history: the shear strain rate; Icepack's ridging term needs divu.
            divu = _divu()
            if divu is None:
                raise ValueError(
                    "`shear` in %/day is CICE's shear strain rate: `divu` is needed to form "
                    "the ridging shear term"
                )
            rate = _rate_per_second(ds["shear"])
            delta = np.sqrt(divu**2 + 0.25 * rate**2)
            shear = 0.5 * (delta - abs(divu))
        else:
            shear = _rate_per_second(ds["shear"])
    elif not isinstance(shear, xr.DataArray):
        shear_desc = f"{float(shear)} s-1"
    if layout is not None:
        if opening is not None:
            raise ValueError("opening is given without closing: give both (the host's rates)")
        return _complete(
            ds, aicen, vicen, aice0, cat, spatial, use_mask, layout, dt, hin_max,
            dict(convergence=convergence, shear=shear), f"convergence: {conv_desc}; shear: {shear_desc}",
            participation, redistribution, tf, ndtd, cleanup, rebin, salt_flux, params,
            mu_nodes,
        )
    options = _step_options(ds, dt, hin_max, participation, redistribution, mu_nodes, **params)
    names: List[str] = []
    arrays: List[xr.DataArray] = []
    scalars = {}
    for name, x in (("aice0", aice0), ("convergence", convergence), ("shear", shear)):
        if x is None:
            continue
        if isinstance(x, xr.DataArray):
            names.append(name)
            arrays.append(x)
        else:
            scalars[name] = float(x)
    results = xr.apply_ufunc(
        _ridge_block,
        aicen,
        vicen,
        *arrays,
        input_core_dims=[[cat], [cat]] + [[]] * len(arrays),
        output_core_dims=[[cat], [cat]] + [[]] * 6,
        dask="parallelized",
        output_dtypes=[np.float64] * 8,
        kwargs=dict(names=tuple(names), scalars=scalars, mask=use_mask, options=options),
        keep_attrs=True,  # keeps the coordinates' attributes; data attributes set below
    )
    out = ds.copy()
    dims_cat = list(ds["aicen"].dims)
    def with_attrs(r: xr.DataArray, dims: List[Hashable], attrs: dict) -> xr.DataArray:
        r = r.transpose(*dims)
        r.attrs = dict(attrs)
        return r

    for name in ("aicen", "vicen"):
        out[name] = with_attrs(results[0 if name == "aicen" else 1], dims_cat, ds[name].attrs)
    a0_attrs = (
        ds["aice0"].attrs
        if "aice0" in ds
        else {"units": "1", "long_name": "open water fraction"}
    )
    out["aice0"] = with_attrs(results[2], spatial, a0_attrs)
    for (name, units, long_name), r in zip(_RATES, results[3:]):
        out[name] = with_attrs(r, spatial, {"units": units, "long_name": long_name})
    if "hin_max" not in out:
        h = (
            _pr.category_bounds(ds.sizes[cat])
            if options["hin_max"] is None
            else options["hin_max"]
        )
        out["hin_max"] = xr.DataArray(
            h, dims=[f"{cat}_bounds"], attrs={"units": "m", "long_name": "thickness category bounds"}
        )
    out.attrs.update(
        {
            "participation": participation,
            "redistribution": redistribution,
            **_mu_rdg_attrs(mu_nodes),
            "dt": f"{float(dt)} s",
            "convergence": conv_desc,
            "shear": shear_desc,
            "parameter_overrides": ", ".join(f"{k}={v}" for k, v in params.items()) or "none",
            "history": (ds.attrs.get("history", "") + "\n" if ds.attrs.get("history") else "")
            + f"pressridge.xr.ridge_step (pressridge {_pr.__version__})",
        }
    )
    return out


def _unpack_tracers(ds: xr.Dataset, tracer_layout: Any, var: str):
    """The dataset with the packed tracers ``ds[var]`` split into one variable per tracer
    (CICE restart names), the layout, and the function that packs a result back into
    ``var`` with the input's dimensions."""
    if isinstance(tracer_layout, _pr.TracerLayout):
        layout = tracer_layout
        spec = layout.icepack
        if spec is None:
            raise ValueError(
                f"tracer_layout {layout!r} is not a CICE layout: packed tracers are read in "
                "Icepack's packing order"
            )
    elif isinstance(tracer_layout, str):
        layout = _pr.TracerLayout.from_icepack(tracer_layout)
        spec = layout.icepack
    else:
        raise ValueError(
            "tracer_layout must be a string in Icepack's names (e.g. 'icedrv') or a "
            f"pressridge.TracerLayout, got {type(tracer_layout).__name__}"
        )
    if var not in ds:
        raise ValueError(f"tracer_layout is given but the dataset has no packed tracer variable `{var}`")
    packed = ds[var]
    base = list(ds["aicen"].dims)
    extra = [d for d in packed.dims if d not in base]
    if len(extra) != 1 or [d for d in packed.dims if d != (extra or [None])[0]] != base:
        raise ValueError(
            f"`{var}` has dimensions {packed.dims}, expected those of aicen {tuple(base)} with "
            "one tracer dimension inserted"
        )
    tdim = extra[0]
    names = list(layout.names)
    if packed.sizes[tdim] != len(names):
        more = (" (Icepack packs biogeochemical tracers last: name them too, e.g. "
                "`tr_brine,z_tracers,nblyr=7,tr_zaero,n_zaero=3`)"
                if packed.sizes[tdim] > len(names) else "")
        raise ValueError(
            f"`{var}`: its tracer dimension `{tdim}` holds {packed.sizes[tdim]} tracers, but the "
            f"layout `{spec}` has {len(names)} ({' '.join(names)}): give the switches that are on "
            f"in the host's tracer_nml{more}"
        )
    clash = [n for n in names if n in ds]
    if clash:
        raise ValueError(
            f"ambiguous tracers: the dataset has both the packed `{var}` and {', '.join(clash)}"
        )
    unpacked = ds.drop_vars(var)
    for i, n in enumerate(names):
        unpacked[n] = packed.isel({tdim: i}, drop=True)

    def repack(out: xr.Dataset) -> xr.Dataset:
        stacked = xr.concat([out[n] for n in names], dim=tdim).transpose(*packed.dims)
        stacked.attrs = dict(packed.attrs)
        stacked.attrs.update({
            "tracer_layout": spec,
            "tracers": " ".join(names),
            "tracer_units": ", ".join(layout.units),
        })
        out = out.drop_vars(names)
        out[var] = stacked
        if tdim in ds.coords:
            out = out.assign_coords({tdim: ds[tdim]})
        out.attrs["tracer_layout"] = f"{spec} (packed in `{var}`)"
        return out

    return unpacked, layout, repack


def _complete_block(a, v, s, *rest, nt, names, scalars, mask, layout, options):
    """One chunk of the complete step; apply_ufunc put the category axis last."""
    a, v, s = (np.moveaxis(x, -1, 0) for x in (a, v, s))
    t = np.stack([np.moveaxis(x, -1, 0) for x in rest[:nt]], axis=1)  # (ncat, nt, ...)
    fields = dict(zip(names, rest[nt:]))
    fields.update(scalars)
    a0 = fields.pop("aice0", None)
    valid = None
    if mask:
        bad = np.isnan(a).any(0) | np.isnan(v).any(0) | np.isnan(s).any(0)
        bad |= np.isnan(t).any(axis=(0, 1))
        if a0 is not None:
            bad |= np.isnan(a0)
        valid = ~bad
    r = _pr.ridge_step(a, v, a0, vsnon=s, trcrn=t, layout=layout, valid=valid, **fields, **options)
    sp = a.shape[1:]
    last = lambda x: np.moveaxis(np.asarray(x), 0, -1)  # noqa: E731
    cell = [np.broadcast_to(np.asarray(getattr(r, k)), sp) for k in _pr.STEP_CELL_OUTPUTS]
    return (
        last(r.aicen),
        last(r.vicen),
        last(r.vsnon),
        *[last(r.trcrn[:, it]) for it in range(nt)],
        np.broadcast_to(np.asarray(r.aice0), sp),
        np.broadcast_to(np.asarray(r.aice), sp),
        *cell,
        *[last(r.categories[k]) for k in _pr.STEP_CATEGORY_OUTPUTS],
        # One spatial field per species row (faero_ocn, fiso_ocn, flux_bio), as the command
        # line writes them (`faero_ocn001`, ...).
        *[np.broadcast_to(np.asarray(row), sp) for k in _pr.STEP_SPECIES_OUTPUTS
          for row in np.asarray(getattr(r, k))],
    )


def _species_counts(layout) -> List[int]:
    """Rows of each of ``STEP_SPECIES_OUTPUTS`` for a layout (Rust ``species_counts``)."""
    f = layout.flags
    return [f["aerosols"], f["isotopes"], layout.nbtrcr]


def _complete(ds, aicen, vicen, aice0, cat, spatial, use_mask, layout, dt, hin_max, forcing,
              forcing_desc, participation, redistribution, tf, ndtd, cleanup, rebin, salt_flux,
              params, mu_nodes=None):
    """The complete step over the dataset (see :func:`ridge_step`)."""
    if not isinstance(layout, _pr.TracerLayout):
        raise ValueError(f"layout must be a pressridge.TracerLayout, got {type(layout).__name__}")
    names = list(layout.names)
    missing = [n for n in names if n not in ds]
    if missing:
        raise ValueError(
            f"the dataset lacks the tracer variable(s) {', '.join(missing)} of the layout "
            f"{layout!r} (CICE restart names)"
        )

    def cat_var(name: str) -> xr.DataArray:
        x = ds[name]
        if set(x.dims) != set(ds["aicen"].dims):
            raise ValueError(
                f"{name} has dimensions {x.dims}, expected those of aicen {ds['aicen'].dims}"
            )
        return x.chunk({cat: -1}) if x.chunks is not None else x

    vsnon = cat_var("vsnon") if "vsnon" in ds else xr.zeros_like(ds["aicen"])
    tracers = [cat_var(n) for n in names]
    options = _step_options(
        ds, dt, hin_max, participation, redistribution, mu_nodes,
        tf=tf if not isinstance(tf, xr.DataArray) else None,
        ndtd=ndtd,
        cleanup=cleanup,
        rebin=rebin,
        salt_flux=salt_flux,
        **params,
    )
    spatial_in = dict(forcing)
    spatial_in["aice0"] = aice0
    if isinstance(tf, xr.DataArray):
        spatial_in["tf"] = tf
        options.pop("tf")
    if "aice" in ds:
        spatial_in["aice"] = ds["aice"]
    keys: List[str] = []
    arrays: List[xr.DataArray] = []
    scalars = {}
    for name, x in spatial_in.items():
        if x is None:
            continue
        if isinstance(x, xr.DataArray):
            keys.append(name)
            arrays.append(x)
        else:
            scalars[name] = float(x)
    nt = len(names)
    ncell = len(_pr.STEP_CELL_OUTPUTS)
    ncatout = len(_pr.STEP_CATEGORY_OUTPUTS)
    nspecies = _species_counts(layout)
    out_core = [[cat]] * (3 + nt) + [[]] * (2 + ncell) + [[cat]] * ncatout + [[]] * sum(nspecies)
    results = xr.apply_ufunc(
        _complete_block,
        aicen,
        vicen,
        vsnon,
        *tracers,
        *arrays,
        input_core_dims=[[cat]] * (3 + nt) + [[]] * len(arrays),
        output_core_dims=out_core,
        dask="parallelized",
        output_dtypes=[np.float64] * len(out_core),
        kwargs=dict(
            nt=nt, names=tuple(keys), scalars=scalars, mask=use_mask, layout=layout,
            options=options,
        ),
        keep_attrs=True,
    )
    out = ds.copy()
    dims_cat = list(ds["aicen"].dims)

    def put(name, r, dims, attrs):
        r = r.transpose(*dims)
        r.attrs = dict(attrs)
        out[name] = r

    put("aicen", results[0], dims_cat, ds["aicen"].attrs)
    put("vicen", results[1], dims_cat, ds["vicen"].attrs)
    put(
        "vsnon",
        results[2],
        dims_cat,
        ds["vsnon"].attrs
        if "vsnon" in ds
        else {"units": "m", "long_name": "snow volume per unit grid-cell area in each thickness category"},
    )
    for it, (name, units, long_name) in enumerate(zip(names, layout.units, layout.long_names)):
        put(name, results[3 + it], dims_cat, ds[name].attrs or {"units": units, "long_name": long_name})
    k = 3 + nt
    put("aice0", results[k], spatial, ds["aice0"].attrs if "aice0" in ds else {"units": "1", "long_name": "open water fraction"})
    put("aice", results[k + 1], spatial, {"units": "1", "long_name": "total ice area fraction (recomputed by the clean-up)"})
    for j, (name, (units, long_name)) in enumerate(_pr.STEP_CELL_OUTPUTS.items()):
        put(name, results[k + 2 + j], spatial, {"units": units, "long_name": long_name})
    for j, (name, (units, long_name)) in enumerate(_pr.STEP_CATEGORY_OUTPUTS.items()):
        put(name, results[k + 2 + ncell + j], dims_cat, {"units": units, "long_name": long_name})
    j = k + 2 + ncell + ncatout
    for (name, (units, long_name)), count in zip(_pr.STEP_SPECIES_OUTPUTS.items(), nspecies):
        for row in range(count):
            put(f"{name}{row + 1:03d}", results[j], spatial, {"units": units, "long_name": long_name})
            j += 1
    h = (
        _pr.category_bounds(ds.sizes[cat])
        if options["hin_max"] is None
        else np.array(options["hin_max"])
    )
    if "closing" not in forcing:
        h = np.array(h, dtype=float)
        h[-1] = _pr.DEFAULT_PARAMETERS["big"] if "big" not in params else float(params["big"])
    hdims = ds["hin_max"].dims if "hin_max" in ds else [f"{cat}_bounds"]
    out["hin_max"] = xr.DataArray(h, dims=hdims, attrs={"units": "m", "long_name": "thickness category bounds after the step (Icepack hin_max)"})
    out.attrs.update(
        {
            "ridging_step": "complete (Icepack icepack_step_ridge: snow, tracers, ocean fluxes)",
            "participation": participation,
            "redistribution": redistribution,
            **_mu_rdg_attrs(mu_nodes),
            "dt": f"{float(dt)} s",
            "forcing": forcing_desc,
            "tracers": " ".join(names),
            "tf": "dataset variable `Tf` (degC)"
            if isinstance(tf, xr.DataArray) and tf.name == "Tf"
            else ("per-cell DataArray (degC)" if isinstance(tf, xr.DataArray)
                  else f"{-1.8 if tf is None else float(tf)} degC"),
            "salt_flux": salt_flux or "constant",
            **_constants_used(params),
            "parameter_overrides": ", ".join(f"{k}={v}" for k, v in params.items()) or "none",
            "history": (ds.attrs.get("history", "") + "\n" if ds.attrs.get("history") else "")
            + f"pressridge.xr.ridge_step (pressridge {_pr.__version__})",
        }
    )
    return out
