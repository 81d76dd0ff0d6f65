"""Ridging lookup tables: the NetCDF tables that ``pressridge tabulate`` (or
:func:`pressridge.tabulate`) writes, read back by the Rust ``RidgeLookup``."""

from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from . import _core


def _flat(x: np.ndarray) -> np.ndarray:
    """A contiguous, aligned 1-D float64 copy or view of ``x`` for the extension."""
    return np.require(np.ravel(x), dtype=np.float64, requirements=["C", "A"])


class Table:
    """A ridging lookup table.

    Fields lie on some of the axes ``set`` (a campaign setting other than thickness, e.g.
    ``contact.mu=1``), ``thickness`` (m, the lead-ice sheet thickness) and ``volume``
    (m³ per metre of ridge, the ridged volume V = U·h·t). :meth:`value` interpolates a
    field linearly along thickness and volume (bilinearly on both); outside the axes it
    clamps to the nearest end and flags the result; where no run reached a cell the table
    holds NaN and so does any interpolation that touches it.

    Open one with :meth:`Table.open`; :meth:`to_xarray` gives the whole file as an
    :class:`xarray.Dataset`.
    """

    __slots__ = ("_core", "_path")

    def __init__(self, core: Any, path: str) -> None:
        self._core = core
        self._path = path

    @classmethod
    def open(cls, path: Union[str, "os.PathLike[str]"]) -> "Table":
        """Reads a table file; :class:`FileNotFoundError`/:class:`OSError` if it cannot be
        read, :class:`ValueError` if it is not a ridging table."""
        p = os.fspath(path)
        return cls(_core.RidgeLookup.open(p), os.path.abspath(p))

    def __reduce__(self) -> Tuple[Any, Tuple[str]]:
        return (Table.open, (self._path,))

    def __repr__(self) -> str:
        return (
            f"<pressridge.Table {self._path!r}: {len(self.sets)} set(s), "
            f"{self.thickness.size} thicknesses {self.thickness.min()}–{self.thickness.max()} m, "
            f"{self.volume.size} volumes up to {self.volume.max():.4g} m³/m>"
        )

    @property
    def path(self) -> str:
        """The file the table was read from."""
        return self._path

    @property
    def sets(self) -> List[str]:
        """Set labels, in the order of the ``set`` axis."""
        return list(self._core.sets())

    @property
    def thickness(self) -> np.ndarray:
        """Thickness axis (m)."""
        return self._core.thickness()

    @property
    def volume(self) -> np.ndarray:
        """Ridged-volume axis (m³/m)."""
        return self._core.volume()

    @property
    def variables(self) -> List[str]:
        """Names of the fields (``work_mean``, ``potential_energy_mean``, ``force_fit``,
        ``cf_by_set``, ...), sorted."""
        return list(self._core.variables())

    def attribute(self, name: str) -> Any:
        """A global attribute (provenance: ``pressridge_version``, ``campaign_spec``,
        ``scene``, ``seeds``, ``history``, ...), or None."""
        return self._core.attribute(name)

    def field(self, name: str) -> Dict[str, Any]:
        """A field as stored: ``dims`` (its axes), ``units``, ``long_name`` and ``data``
        (a numpy array over ``dims``)."""
        dims, units, long_name, data = self._core.field(name)
        return {"dims": tuple(dims), "units": units, "long_name": long_name, "data": data}

    def _set_index(self, set: Union[int, str]) -> int:
        if isinstance(set, str):
            try:
                return self.sets.index(set)
            except ValueError:
                raise ValueError(f"no set {set!r} in the table (sets: {self.sets})") from None
        i = int(set)
        if i < 0:
            raise ValueError(f"set index {set} is negative")
        return i

    def value(
        self,
        name: str,
        thickness: Any,
        volume: Any = 0.0,
        *,
        set: Union[int, str] = 0,
        return_clamped: bool = False,
    ) -> Any:
        """Field ``name`` interpolated at sheet thickness ``thickness`` (m) and ridged volume
        ``volume`` (m³/m), both broadcast against each other; coordinates of axes the field
        does not have are ignored. ``set`` is an index or a label.

        Returns an array of the broadcast shape (a float for scalars), in the field's units;
        with ``return_clamped=True`` also a boolean array that is True where a coordinate
        lay outside the table and was clamped. Raises :class:`ValueError` for an unknown
        field, a set out of range or a coordinate that is NaN or infinite.
        """
        h, v = np.broadcast_arrays(
            np.asarray(thickness, dtype=np.float64), np.asarray(volume, dtype=np.float64)
        )
        vals, clamped = self._core.value(
            name, self._set_index(set), _flat(h), _flat(v)
        )
        vals = vals.reshape(h.shape)
        clamped = clamped.reshape(h.shape)
        if h.ndim == 0:
            vals, clamped = vals[()], clamped[()]
        return (vals, clamped) if return_clamped else vals

    def cf(self, thickness: Any, *, set: Union[int, str] = 0, return_clamped: bool = False) -> Any:
        """C_f (dimensionless; the ensemble mean of the final work over potential energy)
        at ridging-ice thickness ``thickness`` (m), interpolated and clamped like
        :meth:`value`."""
        h = np.asarray(thickness, dtype=np.float64)
        vals, clamped = self._core.cf(self._set_index(set), _flat(h))
        vals = vals.reshape(h.shape)
        clamped = clamped.reshape(h.shape)
        if h.ndim == 0:
            vals, clamped = vals[()], clamped[()]
        return (vals, clamped) if return_clamped else vals

    @property
    def friction(self) -> Optional[List[Tuple[float, float]]]:
        """The friction pair (mu, mu_w) of each set (dimensionless, between blocks above
        and below the water line), from the table's ``mu`` and ``mu_w`` coordinates; None for a
        table made before they were written."""
        f = self._core.friction()
        return None if f is None else [(float(a), float(b)) for a, b in f]

    def friction_set(self, mu: float, mu_w: float) -> int:
        """The index of the set at friction (mu, mu_w); :class:`ValueError` listing the
        pairs the table has when it has not that one."""
        return int(self._core.friction_set(float(mu), float(mu_w)))

    def cf_nodes(self, set: Union[int, str] = 0) -> Tuple[np.ndarray, np.ndarray]:
        """The (thickness in m, C_f) nodes of a set where C_f is not NaN (a NaN marks a
        thickness no run reached): what ``pressridge.strength(..., cf=table)`` interpolates
        (the first set)."""
        return self._core.cf_nodes(self._set_index(set))

    def to_xarray(self) -> Any:
        """The whole table file as an :class:`xarray.Dataset` (loaded into memory; the file
        is closed again). A table whose sets differ only in friction is a friction grid:
        dimensions ``thickness``, ``mu``, ``mu_w``, ``volume`` (select with
        ``ds.cf_by_set.sel(mu=1.0, mu_w=0.6)``); any other keeps a ``set`` dimension
        (docs/tables.md)."""
        import xarray as xr

        return xr.load_dataset(self._path)
