"""The simulator, its campaigns and their tables from Python: :func:`scene`,
:func:`simulate`, :func:`campaign` (local threads or a dask client) and :func:`tabulate`,
with their results :class:`Simulation` and :class:`CampaignResult`, re-exported by
:mod:`pressridge`.

Owns the scene overrides by keyword (written as the command line's ``--set``), the progress
reports of long calls and the dispatch of a campaign's runs to dask workers; the scenes,
runs, campaigns and tables themselves are the library's (:mod:`pressridge._core`).
"""

from __future__ import annotations

import datetime as _dt
import json as _json
import os as _os
import warnings as _warnings
from typing import Any, NamedTuple, Optional, Sequence, Union

import numpy as _np

from . import _core
from . import _progress
from ._table import Table

PathLike = Union[str, "_os.PathLike[str]"]

#: A run counts as rafted when its intact lead sheet passed the floe's nose by more than
#: this (m): the default ``rafting_reach`` of :func:`tabulate` (``--rafting-reach``).
RAFTING_REACH: float = float(_core.RAFTING_REACH)


# ---------------------------------------------------------------------------------------
# The simulator


def _toml_value(v: Any) -> str:
    if isinstance(v, (bool, _np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, _np.integer)):
        return str(int(v))
    if isinstance(v, (float, _np.floating)):
        f = float(v)
        if _np.isnan(f):
            return "nan"
        if _np.isinf(f):
            return "inf" if f > 0 else "-inf"
        return repr(f)
    if isinstance(v, str):
        return _json.dumps(v)
    if isinstance(v, (list, tuple, _np.ndarray)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise ValueError(f"cannot use {v!r} ({type(v).__name__}) as a scene value")


def _overrides(overrides: dict, sets: Optional[Sequence[str]]) -> list:
    out = list(sets or [])
    for k, v in overrides.items():
        out.append(f"{k.replace('__', '.')}={_toml_value(v)}")
    return out


class Simulation(NamedTuple):
    """The outcome of :func:`simulate`."""

    #: Headline numbers of the run (as ``summary.json`` of ``pressridge simulate``):
    #: energies in J/m, times in s, volume in m³/m.
    summary: dict
    #: Time series sampled every ``numerics.sample_interval``: ``time`` (s), the energy
    #: budget (J/m) and the forces ``ridging_force``, ``mean_force`` (N/m), as in
    #: ``series.csv``.
    series: dict
    #: Unit of every series column.
    units: dict
    #: The resolved scene as TOML text.
    scene: str


def scene(scene: Optional[PathLike] = None, *, sets: Optional[Sequence[str]] = None, **overrides: Any) -> str:
    """The resolved scene as TOML text (as ``pressridge simulate --print-scene``), with the
    same arguments as :func:`simulate`."""
    path = None if scene is None else _os.fspath(scene)
    return _core.scene_toml(path, _overrides(overrides, sets))


def simulate(
    scene: Optional[PathLike] = None,
    *,
    sets: Optional[Sequence[str]] = None,
    progress: Any = True,
    threads: int = 1,
    **overrides: Any,
) -> Simulation:
    """Runs the discrete-element ridge simulator on a scene.

    Parameters
    ----------
    scene : path, optional
        A scene file (TOML, e.g. ``data/scenes/figure5.toml``); the built-in default (the
        paper's Figure 5 experiment, 400 s) when omitted.
    sets : list of str, optional
        Overrides as on the command line, ``"contact.mu=0.4"``.
    progress : bool or callable, default True
        True shows the simulated time against the scene's duration with an ETA (a tqdm bar
        when tqdm is installed — a widget in notebooks —, else a line on stderr, every few
        seconds when stderr is not a terminal); False is silent; a callable is called with
        ``(time_s, duration_s)`` instead, at most five times a second.
    threads : int, default 1
        Threads each time step's force phases run on; the results are the same to the bit
        on any number.
    **overrides
        Overrides by keyword; a dotted key is written with ``__`` (``contact__mu=0.4``) or
        passed as ``**{"contact.mu": 0.4}``. Values are numbers, booleans, strings or
        lists, in the scene's units (SI: m, s, Pa, kg/m³).

    Returns
    -------
    Simulation
        ``summary`` (dict), ``series`` (dict of 1-D numpy arrays), ``units``, ``scene``.

    The run releases the GIL; Ctrl-C stops it at the next sample with
    :class:`KeyboardInterrupt`. Unknown keys and bad values raise :class:`ValueError`.
    """
    path = None if scene is None else _os.fspath(scene)
    if isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise ValueError(f"threads: expected a whole number of at least 1, got {threads!r}")
    show, bar = _progress.callback(progress, "simulate", "s simulated")
    try:
        summary, toml, series = _core.simulate(
            path, _overrides(overrides, sets), show, threads
        )
    finally:
        if bar is not None:
            bar.close()
    return Simulation(
        summary=_json.loads(summary),
        series=dict(series),
        units=dict(_core.series_units()),
        scene=toml,
    )


# ---------------------------------------------------------------------------------------
# Campaigns and tables


class CampaignResult(NamedTuple):
    """Counts of a :func:`campaign` call."""

    #: Runs found finished in the result directory and skipped.
    skipped: int
    #: Runs made by this call.
    done: int
    #: Runs in the campaign.
    total: int


def _run_planned_on_worker(run_json: str, spec_json: str, out: str) -> str:
    """Runs one planned run on a dask worker and writes it into ``out``."""
    from pressridge import _core as core

    return core.campaign_run_planned(spec_json, run_json, out)


def campaign(
    spec: PathLike,
    out: PathLike,
    client: Any = None,
    *,
    threads: Optional[int] = None,
    progress: Any = True,
    resume_from: Union[None, PathLike, Sequence[PathLike]] = None,
) -> CampaignResult:
    """Runs a seeded campaign (a spec TOML, as ``pressridge campaign``) into the result
    directory ``out``, skipping runs already there.

    ``resume_from``: one or more earlier result directories or records-only archives of
    the same campaign (e.g. ``crates/lab/records/paper/<set>``) whose finished runs are taken into
    ``out`` (their records, without final states) instead of being run again, as the
    command line's ``--resume-from``.

    With ``client=None`` the runs go to ``threads`` threads of this process (all cores by
    default). With a :class:`dask.distributed.Client` every run still to do becomes one
    task on the cluster; the workers must see ``out`` (a shared file system). Either way
    the directory is the command line's: ``campaign.json``, ``plan.json`` and
    ``runs/<id>/run.json`` with ``state.json``, each written atomically, so a campaign
    interrupted anywhere resumes by calling this again. Runs are deterministic: the
    records equal the command line's bit for bit (but for the wall-clock time).

    ``progress``: True (the default) shows the runs done against the runs to do (a tqdm
    bar when tqdm is installed, else lines on stderr as :func:`simulate`); False is silent;
    a callable is called with a dict (``skipped``, ``done``, ``total``, and without a
    client ``simulated`` seconds) as runs finish.

    Raises :class:`ValueError` for a bad spec or a directory holding another campaign,
    :class:`OSError` for files.
    """
    spec_p = _os.path.abspath(_os.fspath(spec))
    out_p = _os.path.abspath(_os.fspath(out))
    if resume_from is not None:
        dirs = [resume_from] if isinstance(resume_from, (str, bytes, _os.PathLike)) else resume_from
        for d in dirs:
            _core.campaign_adopt(spec_p, out_p, _os.path.abspath(_os.fspath(d)))
    bar = None
    if progress is True:
        show, bar = _progress.callback(True, "campaign", "runs")

        def progress(d: dict) -> None:
            show(d["skipped"] + d["done"], d["total"])

    try:
        return _campaign(spec_p, out_p, client, threads, progress or None)
    finally:
        if bar is not None:
            bar.close()


def _campaign(spec_p: str, out_p: str, client: Any, threads: Optional[int], progress: Any) -> CampaignResult:
    if client is None:
        n = threads if threads is not None else (_os.cpu_count() or 1)
        if int(n) < 1:
            raise ValueError(f"threads must be at least 1, got {threads}")
        skipped, done = _core.campaign_local(spec_p, out_p, int(n), progress)
        return CampaignResult(skipped, done, skipped + done)
    spec_json, todo, skipped, total = _core.campaign_prepare(spec_p, out_p)
    if not todo:
        return CampaignResult(skipped, 0, total)
    from distributed import as_completed

    futures = [
        client.submit(
            _run_planned_on_worker,
            run_json,
            spec_json,
            out_p,
            key=f"pressridge-run-{_json.loads(run_json)['id']}-{_os.urandom(4).hex()}",
            pure=False,
        )
        for run_json in todo
    ]
    done = 0
    try:
        for fut in as_completed(futures):
            fut.result()  # re-raises the worker's error (ValueError/OSError) here
            done += 1
            if progress is not None:
                progress({"skipped": skipped, "done": done, "total": total})
    finally:
        for f in futures:
            if not f.done():
                f.cancel()
    return CampaignResult(skipped, done, total)


def tabulate(
    campaign_dir: Union[PathLike, Sequence[PathLike]],
    out: PathLike,
    *,
    points: int = 41,
    allow_partial: bool = False,
    rafting_reach: float = RAFTING_REACH,
    exclude_rafted: bool = False,
    scaled_with_thickness: Sequence[str] = (),
) -> Table:
    """Tabulates campaign directories into a NetCDF lookup table, as ``pressridge
    tabulate`` (the same library pipeline, ``campaign::tabulation::tabulate_campaigns``):
    ensemble statistics of work (J/m), potential energy (J/m), their ratio and the ridging
    force (N/m) on a grid of ``points`` ridged volumes (m³/m), fits (eqs 13-16) and C_f per
    thickness. Returns the table, opened.

    ``campaign_dir`` is one result directory or a list of them (``--campaign`` repeated):
    runs are grouped into sets by their scenes, and a run two campaigns share is counted
    once.

    An incomplete campaign (missing runs, or records that do not match their digests)
    raises ``ValueError`` naming the runs, unless ``allow_partial`` (``--allow-partial``):
    then the complete runs are tabulated and the table's attributes ``runs_planned``,
    ``runs_tabulated`` and ``partial`` say what was left out (docs/failure.md).

    ``scaled_with_thickness`` (``--scaled-with-thickness``) names scene keys that vary with
    the sheet thickness within a set, e.g. ``["floe.thickness", "floe.length"]`` for a
    campaign that scales the floe with the sheet: runs that differ only in these make one
    set, and the table records their values per thickness (attributes ``scaled_keys``,
    ``scaled_values``).

    A run counts as rafted when its intact lead sheet passed the floe's nose by more than
    ``rafting_reach`` (m, ``--rafting-reach``; default :data:`RAFTING_REACH`, 2 m) in a
    scene of the paper's size, scaled with a scene scaled with the sheet (docs/tables.md).
    ``exclude_rafted`` (``--exclude-rafted``) leaves rafted runs out of the table (listed in
    its ``excluded_runs`` attribute). Runs left out, partial campaigns and missing fits are
    reported as ``UserWarning``, as the command line prints them."""
    if int(points) < 2:
        raise ValueError(f"points must be at least 2, got {points}")
    if isinstance(campaign_dir, (str, bytes, _os.PathLike)):
        dirs = [_os.fspath(campaign_dir)]
    else:
        dirs = [_os.fspath(d) for d in campaign_dir]
    if not dirs:
        raise ValueError("tabulate needs at least one campaign directory")
    outp = _os.fspath(out)
    shown = dirs[0] if len(dirs) == 1 else dirs
    extra = "".join(
        [
            ", allow_partial=True" if allow_partial else "",
            f", rafting_reach={float(rafting_reach)!r}" if float(rafting_reach) != RAFTING_REACH else "",
            ", exclude_rafted=True" if exclude_rafted else "",
            f", scaled_with_thickness={list(scaled_with_thickness)!r}" if scaled_with_thickness else "",
        ]
    )
    command = f"pressridge.tabulate({shown!r}, {outp!r}, points={int(points)}{extra}) (Python)"
    date = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d")
    _, warnings = _core.tabulate(
        dirs,
        outp,
        int(points),
        command,
        date,
        bool(allow_partial),
        float(rafting_reach),
        bool(exclude_rafted),
        [str(k) for k in scaled_with_thickness],
    )
    for w in warnings:
        _warnings.warn(w, UserWarning, stacklevel=2)
    return Table.open(outp)


def redistribution(campaign_dir: Union[PathLike, Sequence[PathLike]]) -> "list[dict[str, float]]":
    """The thickness distribution of the simulated ridged ice, as ``pressridge
    redistribution`` (``table::redistribution``): one dict per lead-ice thickness and friction
    pair of the campaigns' runs, with ``thickness`` (m), ``mu``, ``mu_w``, ``runs``,
    ``strips``; for ``width`` (ridged width, m), ``mean_thickness`` (mean solid thickness, m),
    ``porosity``, ``lambda`` (m), ``mu_rdg`` (Lipscomb's parameter, m^0.5) and ``h_star``
    (Hibler's H*, m) the mean over the runs' own fits, ``_std`` (seed spread) and ``_ci95``
    (half-width of the 95 % Student-t interval); ``pooled_mu_rdg``, ``pooled_h_star`` and the
    Kolmogorov-Smirnov distances ``ks_exponential``, ``ks_uniform`` of the shapes fitted to
    all strips together, and ``below_h_min``, the area share of strips thinner than H_min.
    Runs whose records predate the ridge columns are left out with a ``UserWarning``; none
    with them raises ``ValueError``."""
    if isinstance(campaign_dir, (str, bytes, _os.PathLike)):
        dirs = [_os.fspath(campaign_dir)]
    else:
        dirs = [_os.fspath(d) for d in campaign_dir]
    rows, without = _core.redistribution(dirs)
    if without:
        _warnings.warn(
            f"{without} runs have no ridge columns (recorded before they were kept) and are left out",
            UserWarning,
            stacklevel=2,
        )
    if not rows:
        raise ValueError(f"no run with ridge columns in {dirs!r}: run the campaign again")
    return rows
