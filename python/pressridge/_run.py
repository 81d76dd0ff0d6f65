"""A run directory of ``pressridge simulate`` (or one run of a campaign) in Python: the
summary, the time series and the states, and a state drawn with matplotlib.

>>> run = pressridge.load_run("runs/default")          # doctest: +SKIP
>>> run.series["work"].plot()                            # xarray, with units  # doctest: +SKIP
>>> pressridge.plot_state(run.state)                     # matplotlib axes  # doctest: +SKIP
"""

import csv
import json
import os
from typing import Any, Dict, List, NamedTuple, Optional, Union

import numpy as np

PathLike = Union[str, "os.PathLike[str]"]

#: Fill colours of the bodies by role (sheet, rubble, floe, anything else).
ROLE_COLOURS = {"Sheet": "#7fb3d5", "Rubble": "#d6eaf8", "Floe": "#5d6d7e"}


class State(NamedTuple):
    """A saved state (``state.json`` or a snapshot ``snapshots/tNNNNN.json``)."""

    #: Simulated time (s).
    time: float
    #: Each body's outline in world coordinates (m), an array of shape (k, 2).
    polygons: List[np.ndarray]
    #: Each body's role: ``"Sheet"``, ``"Rubble"``, ``"Floe"`` or ``"Free"``.
    roles: List[str]
    #: Centroids (m), shape (n, 2).
    pos: np.ndarray
    #: Velocities (m/s), shape (n, 2).
    vel: np.ndarray
    #: Still-water level (m), or None without water.
    water_level: Optional[float]


class Run(NamedTuple):
    """What :func:`load_run` reads from a run directory."""

    #: The directory.
    path: str
    #: ``summary.json`` (a campaign run's ``run.json`` summary), energies in J/m.
    summary: Dict[str, Any]
    #: ``series.csv`` as an :class:`xarray.Dataset` on ``time`` (s) with each column's
    #: units in its attributes when xarray is installed, else a dict of numpy arrays
    #: (``units`` in :attr:`units`). None when the directory has no series.
    series: Any
    #: Units of the series columns by name.
    units: Dict[str, str]
    #: The final state (``state.json``), or None.
    state: Optional[State]
    #: Snapshot files in time order (``snapshots/t*.json``), to read with :func:`load_state`.
    snapshots: List[str]


def _xy(v: Any) -> List[float]:
    return [v["x"], v["y"]] if isinstance(v, dict) else list(v)


def load_state(path: PathLike) -> State:
    """Reads a state file: every body's outline placed at its pose (m)."""
    with open(os.fspath(path)) as f:
        s = json.load(f)
    polys, roles, pos, vel = [], [], [], []
    for b in s["bodies"]:
        v = np.asarray(b["shape"]["vertices"], dtype=np.float64)
        c, sn = np.cos(b["theta"]), np.sin(b["theta"])
        p = np.asarray(_xy(b["pos"]))
        polys.append(v @ np.array([[c, sn], [-sn, c]]) + p)
        roles.append(str(b.get("role", "Free")))
        pos.append(p)
        vel.append(_xy(b["vel"]))
    water = (s.get("params") or {}).get("water")
    return State(
        time=float(s["time"]),
        polygons=polys,
        roles=roles,
        pos=np.asarray(pos, dtype=np.float64).reshape(-1, 2),
        vel=np.asarray(vel, dtype=np.float64).reshape(-1, 2),
        water_level=None if not water else float(water.get("level", 0.0)),
    )


def _read_series(path: str) -> "tuple[Any, Dict[str, str]]":
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names, units = [], {}
    for h in rows[0]:
        name, _, unit = h.partition(" [")
        names.append(name)
        units[name] = unit.rstrip("]")
    data = np.asarray(rows[1:], dtype=np.float64).reshape(-1, len(names))
    cols = {n: data[:, k] for k, n in enumerate(names)}
    try:
        import xarray as xr
    except ImportError:
        return cols, units
    t = cols.pop("time")
    ds = xr.Dataset(
        {n: ("time", c, {"units": units[n]}) for n, c in cols.items()},
        coords={"time": ("time", t, {"units": units["time"]})},
    )
    return ds, units


def load_run(path: PathLike) -> Run:
    """Reads a run directory: ``summary.json`` (or a campaign run's ``run.json``),
    ``series.csv``, ``state.json`` and the snapshot list. Raises :class:`FileNotFoundError`
    naming the directory when it holds neither a summary nor a run record."""
    d = os.fspath(path)
    summary_p, record_p = os.path.join(d, "summary.json"), os.path.join(d, "run.json")
    if os.path.exists(summary_p):
        with open(summary_p) as f:
            summary = json.load(f)
    elif os.path.exists(record_p):
        with open(record_p) as f:
            summary = json.load(f)["summary"]
    else:
        raise FileNotFoundError(
            f"{d}: not a run directory (no summary.json of `pressridge simulate`, no run.json "
            "of a campaign run)"
        )
    series_p = os.path.join(d, "series.csv")
    series, units = _read_series(series_p) if os.path.exists(series_p) else (None, {})
    state_p = os.path.join(d, "state.json")
    snap_d = os.path.join(d, "snapshots")
    snaps = (
        sorted(
            os.path.join(snap_d, f)
            for f in os.listdir(snap_d)
            if f.startswith("t") and f.endswith(".json")
        )
        if os.path.isdir(snap_d)
        else []
    )
    return Run(
        path=d,
        summary=summary,
        series=series,
        units=units,
        state=load_state(state_p) if os.path.exists(state_p) else None,
        snapshots=snaps,
    )


def plot_state(state: Union[State, Run, PathLike], ax: Any = None, *, water: bool = True) -> Any:
    """Draws a state (a :class:`State`, a :class:`Run`'s final state, or a state file) with
    matplotlib: every block filled by its role, the water line, equal axes in metres.
    Returns the axes (a new figure's when ``ax`` is None)."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    if isinstance(state, Run):
        if state.state is None:
            raise ValueError(f"{state.path}: the run has no state.json")
        state = state.state
    elif not isinstance(state, State):
        state = load_state(state)
    if ax is None:
        _, ax = plt.subplots(figsize=(10, 4))
    colours = [ROLE_COLOURS.get(r, "#f5cba7") for r in state.roles]
    ax.add_collection(
        PolyCollection(state.polygons, facecolors=colours, edgecolors="#1b2631", linewidths=0.3)
    )
    if state.polygons:
        allp = np.concatenate(state.polygons)
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        pad = 0.05 * max(hi[0] - lo[0], hi[1] - lo[1], 1.0)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    if water and state.water_level is not None:
        ax.axhline(state.water_level, color="#2e86c1", linewidth=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"t = {state.time:.1f} s")
    return ax
