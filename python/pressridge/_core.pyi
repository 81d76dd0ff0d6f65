"""Type stubs of the compiled module ``pressridge._core`` (python/src/: one Rust module
per face, listed in lib.rs).

These functions take already-normalised arguments; the documented API is in
``pressridge/__init__.py``, ``pressridge/_table.py`` and ``pressridge/xr.py``.
"""

from os import PathLike
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, TypedDict, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, PathLike[str]]
_F64 = npt.NDArray[np.float64]
_Bool = npt.NDArray[np.bool_]

__version__: str
CATEGORY_DIMS: List[str]
STRENGTH_META: Tuple[str, str, str]

class _StrengthArgs(TypedDict):
    """The options of ``strength`` (the normalised ``pressridge.StrengthOptions``)."""

    participation: str
    redistribution: str
    law: str
    cf_value: Optional[float]
    cf_nodes: Optional[Tuple[Sequence[float], Sequence[float]]]
    cf_file: Optional[_Path]
    params: Sequence[Tuple[str, float]]

def strength(
    aicen: _F64,
    vicen: _F64,
    aice0: Optional[_F64],
    valid: Optional[_Bool],
    options: _StrengthArgs,
) -> Tuple[_F64, int, int, float]:
    """Strength P (N/m) of shape ``aicen.shape[1:]``, the number of columns where a C_f
    table was clamped, of these the columns where the clamped ice carries at least 1 % of
    P, and the largest share of a column's P from clamped C_f (0-1)."""

def _layout(aicen: _F64) -> Tuple[str, str]:
    """("view" | "copy", "C" | "F"): how ``aicen`` reaches the batch routines."""

def ridge_step(
    aicen: _F64,
    vicen: _F64,
    aice0: Optional[_F64],
    hin_max: Optional[Sequence[float]],
    convergence: _F64,
    shear: _F64,
    dt: float,
    valid: Optional[_Bool],
    participation_name: str,
    redistribution_name: str,
    params: Sequence[Tuple[str, float]],
) -> Tuple[_F64, _F64, _F64, List[_F64]]:
    """(aicen, vicen, aice0, [closing, opening, dardg1dt, dardg2dt, dvirdgdt])."""

class TracerLayout:
    @staticmethod
    def cice(
        nilyr: int,
        nslyr: int,
        *,
        age: bool = False,
        first_year: bool = False,
        level_ice: bool = False,
        ponds: bool = False,
    ) -> "TracerLayout": ...
    @staticmethod
    def from_fields(fields: Sequence[Union[dict, Sequence[Any]]]) -> "TracerLayout":
        """Any layout: each field a dict with keys name, levels (>= 1, default 1), base
        ("area", "ice_volume", "snow_volume"), strata (earlier field names), role
        ("surface_temperature", "ice_enthalpy", "snow_enthalpy", "ice_salinity", "age",
        "first_year", "level_area", "level_volume", "pond_area", "pond_depth", "pond_lid",
        "other"), or a sequence in that order; defaults are Icepack's for the role, the role
        Icepack's for the name (Tsfc, qice, ...), else "other". ValueError names the field."""
    @staticmethod
    def from_icepack(text: str) -> "TracerLayout":
        """The CICE layout in Icepack's names, as --tracer-layout takes it: "nilyr=7,nslyr=1,
        tr_lvl,tr_pond_lvl" (switches tr_iage, tr_FY, tr_lvl, tr_pond_lvl, tr_pond_topo,
        tr_pond_sealvl, tr_snow, tr_fsd+nfsd, tr_iso+n_iso, tr_aero+n_aero, tr_brine) or the
        preset "icedrv"; ValueError names the item refused."""
    @property
    def icepack(self) -> Optional[str]:
        """The layout in Icepack's names (from_icepack's text), None if not a CICE layout."""
    def with_bgc(self, extra: int, kind: str, bio_index: Sequence[int], *, nblyr: int = 1,
                 sk_l: float = 0.03) -> "TracerLayout":
        """extra biogeochemical tracers after every other: kind "z_tracers" (nblyr + 1 levels
        on the brine grid and 2 in the snow) or "skl_bgc"; bio_index 0-based; the step books
        flux_bio."""
    def with_host_tables(self, trcr_depend: Sequence[int], trcr_base: Sequence[Sequence[float]],
                         n_trcr_strata: Sequence[int],
                         nt_strata: Sequence[Sequence[int]]) -> "TracerLayout":
        """Each tracer carried as Icepack's tables say (1-based tracer numbers)."""
    @property
    def nbtrcr(self) -> int: ...
    @staticmethod
    def detect(names: Sequence[str]) -> Optional["TracerLayout"]:
        """The CICE layout of these variable names (CICE restart names), as the command
        line tells it; None without snow or tracers; ValueError names a missing variable."""
    def spec(self) -> List[dict]:
        """The fields as from_fields takes them (dicts name, levels, base, strata, role)."""
    @property
    def ntrcr(self) -> int: ...
    @property
    def nilyr(self) -> int: ...
    @property
    def nslyr(self) -> int: ...
    @property
    def flags(self) -> dict[str, bool]: ...
    @property
    def names(self) -> List[str]: ...
    @property
    def units(self) -> List[str]: ...
    @property
    def long_names(self) -> List[str]: ...
    def fields(self) -> List[Tuple[str, int, int, str, List[str], str, str]]:
        """[(name, first index, levels, base, strata, units, long_name)]."""
    def field(self, name: str) -> Tuple[int, int]: ...
    def trcr_depend(self) -> List[int]: ...

def step_outputs() -> Tuple[List[Tuple[str, str, str]], List[Tuple[str, str, str]]]:
    """([(cell output, units, long_name)], [(category output, units, long_name)])."""

def step_parameters() -> List[Tuple[str, str, str, float]]:
    """The complete step's thermodynamic constants: [(name, SI units, description,
    Icepack default)]."""

def ridge_step_full(
    aicen: _F64,
    vicen: _F64,
    vsnon: _F64,
    trcrn: Optional[_F64],
    layout: Optional[TracerLayout],
    aice0: Optional[_F64],
    aice: Optional[_F64],
    hin_max: Optional[Sequence[float]],
    c1: _F64,
    c2: _F64,
    rates: bool,
    tf: _F64,
    dt: float,
    ndtd: int,
    valid: Optional[_Bool],
    participation_name: str,
    redistribution_name: str,
    params: Sequence[Tuple[str, float]],
    cleanup: bool,
    rebin: bool,
    salt_flux: str,
) -> Tuple[
    Tuple[_F64, _F64, _F64],
    Optional[_F64],
    Tuple[_F64, _F64],
    _F64,
    List[Tuple[str, _F64]],
    List[Tuple[str, _F64]],
]:
    """((aicen, vicen, vsnon), trcrn, (aice0, aice), hin_max used, [(cell output, array)],
    [(category output, array)])."""

def category_bounds(ncat: int, scheme: str = "round_numbers") -> _F64: ...
def param_names() -> List[str]: ...
def check_param_name(name: str, ridge_step: bool = False, keyword: bool = True) -> None:
    """Raises the library's ValueError (closest valid name, every valid name) unless
    ``name`` is an ITD parameter, or with ``ridge_step`` a constant of the complete step."""
def cf_presets() -> List[Tuple[str, float]]: ...
def read_cf_table(path: _Path) -> Tuple[_F64, _F64]: ...
def read_cf_table_at_friction(
    path: _Path, friction: Optional[Tuple[float, float]] = None
) -> Tuple[_F64, _F64, Optional[Tuple[float, float]]]: ...

DEFAULT_FRICTION: Tuple[float, float]
RAFTING_REACH: float
CF_CLAMPED_MATERIAL_SHARE: float
def default_params() -> dict[str, float]: ...
def param_meta() -> List[Tuple[str, str, str, float]]:
    """Every ITD parameter: (name, units, description, CICE default)."""
def scene_toml(scene: Optional[_Path], sets: Sequence[str]) -> str: ...
def simulate(
    scene: Optional[_Path],
    sets: Sequence[str],
    progress: Optional[Callable[[float, float], None]] = None,
) -> Tuple[str, str, List[Tuple[str, _F64]]]:
    """(summary JSON, resolved scene TOML, [(series column, values)])."""

def series_units() -> List[Tuple[str, str]]: ...
def campaign_local(
    spec: _Path, out: _Path, threads: int, progress: Optional[Callable[[dict], object]]
) -> Tuple[int, int]:
    """(skipped, done)."""

def campaign_prepare(spec: _Path, out: _Path) -> Tuple[str, List[str], int, int]:
    """(spec JSON, [planned run JSON still to do], skipped, total)."""

def campaign_run_planned(spec_json: str, run_json: str, out: _Path) -> str:
    """Runs one planned run, writes it; returns its id."""

def tabulate(
    campaign_dirs: List[_Path],
    out: _Path,
    points: int,
    command: str,
    date: str,
    allow_partial: bool = False,
    rafting_reach: float = 2.0,
    exclude_rafted: bool = False,
    scaled_keys: List[str] = ...,
) -> Tuple[List[Tuple[str, float, float]], List[str]]:
    """([(set, thickness (m), C_f)], [warning]) (``campaign::tabulation::tabulate_campaigns``)."""

def redistribution(campaign_dirs: List[_Path]) -> Tuple[List[Dict[str, float]], int]:
    """([row per (thickness, mu, mu_w)], runs without ridge columns) (``table::redistribution``)."""

class RidgeLookup:
    @staticmethod
    def open(path: _Path) -> "RidgeLookup": ...
    def sets(self) -> List[str]: ...
    def friction(self) -> Optional[List[Tuple[float, float]]]: ...
    def friction_set(self, mu: float, mu_w: float) -> int: ...
    def thickness(self) -> _F64: ...
    def volume(self) -> _F64: ...
    def variables(self) -> List[str]: ...
    def attribute(self, name: str) -> Optional[str]: ...
    def field(self, name: str) -> Tuple[List[str], str, str, _F64]: ...
    def value(
        self, name: str, set: int, thickness: _F64, volume: _F64
    ) -> Tuple[_F64, _Bool]: ...
    def cf(self, set: int, thickness: _F64) -> Tuple[_F64, _Bool]: ...
    def cf_nodes(self, set: int) -> Tuple[_F64, _F64]: ...
