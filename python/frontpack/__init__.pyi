# Type stubs of the package frontpack (the compiled core and the Python layer, as one API).
# The contracts are in the docstrings (help(frontpack.fill)) and in include/frontpack/*.hpp.
import enum
import os
from typing import Any, Callable, Iterable, Literal, Mapping, Optional, Sequence, Tuple, TypedDict, Union

import numpy as np
import numpy.typing as npt

__version__: str
default_radius_spec: str

ArrayLike = npt.ArrayLike
Disks = npt.NDArray[np.float64]  # shape (N, 3): x, y, r
Bounds = Tuple[float, float, float, float]  # xmin, ymin, xmax, ymax
Site = Tuple[int, int, Optional[int]]  # part, ring (0 outer, k >= 1 the k-th hole), vertex
PathLike = Union[str, os.PathLike[str]]
# WKT text, a path, a Domain, a shapely geometry (__geo_interface__ or .wkt), a GeoJSON-like dict.
Shape = Union["Domain", str, os.PathLike[str], Mapping[str, Any], Any]

class Error(Exception): ...
class CancelledError(Error): ...
class OptionError(Error, ValueError): ...

class LimitError(Error):
    estimate: int

class NothingFitsError(Error): ...

class IoError(Error, OSError):
    path: str

class WktError(Error, ValueError):
    kind: Literal["syntax", "unsupported_geometry", "empty_geometry", "dimension", "bad_number"]
    detail: str
    source: str
    offset: int
    line: int
    column: int

class InvalidDomainError(Error, ValueError):
    kind: str
    site: Site
    other_site: Optional[Site]
    where: Optional[Tuple[float, float]]

class DiskFileError(Error, ValueError):
    kind: str
    detail: str
    source: str
    line: int
    column: int

class DomainFileError(Error, ValueError):
    kind: str
    detail: str
    source: str
    entity: str

class Location(enum.IntEnum):
    outside = 0
    boundary = 1
    inside = 2

class Domain:
    @staticmethod
    def from_wkt(wkt: str) -> Domain: ...
    @staticmethod
    def from_file(
        path: PathLike,
        format: str = "auto",
        max_deviation: float = 0.0,
        relative_deviation: float = 1e-3,
        join_tolerance: float = 1e-9,
    ) -> Domain: ...
    @staticmethod
    def from_rings(outer: ArrayLike, holes: Optional[Iterable[ArrayLike]] = None) -> Domain: ...
    @staticmethod
    def from_polygons(polygons: Iterable[Tuple[ArrayLike, Iterable[ArrayLike]]]) -> Domain: ...
    @staticmethod
    def from_shape(shape: Shape) -> Domain: ...
    @staticmethod
    def periodic(bounds: Sequence[float], axes: Literal["x", "xy"] = "xy") -> Domain: ...
    @property
    def periodicity(self) -> Literal["none", "x", "xy"]: ...
    @property
    def area(self) -> float: ...
    @property
    def perimeter(self) -> float: ...
    @property
    def bbox(self) -> Bounds: ...
    @property
    def num_polygons(self) -> int: ...
    @property
    def num_holes(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def max_abs_coordinate(self) -> float: ...
    @property
    def wkt(self) -> str: ...
    @property
    def __geo_interface__(self) -> dict[str, Any]: ...
    def polygons(self) -> list[Tuple[npt.NDArray[np.float64], list[npt.NDArray[np.float64]]]]: ...
    def locate(self, points: ArrayLike) -> Union[Location, npt.NDArray[np.uint8]]: ...
    def contains(self, disks: ArrayLike) -> Union[bool, npt.NDArray[np.bool_]]: ...
    def to_wkt(self) -> str: ...

def as_domain(shape: Shape) -> Domain: ...
def read_domain_file(
    path: PathLike,
    format: str = "auto",
    max_deviation: float = 0.0,
    relative_deviation: float = 1e-3,
    join_tolerance: float = 1e-9,
) -> dict[str, Any]: ...
def has_dxf_reader() -> bool: ...
def has_gis_reader() -> bool: ...

class Radii:
    def __init__(self, spec: str) -> None: ...
    @staticmethod
    def uniform(rmin: float, rmax: float) -> Radii: ...
    @staticmethod
    def constant(r: float) -> Radii: ...
    @staticmethod
    def normal(mean: float, sd: float, lo: float, hi: float) -> Radii: ...
    @staticmethod
    def lognormal(median: float, gsd: float, lo: float, hi: float) -> Radii: ...
    @staticmethod
    def discrete(
        classes: Iterable[Tuple[float, float]],
        basis: Literal["number", "area"] = "number",
        kind: Literal["radius", "diameter"] = "radius",
    ) -> Radii: ...
    @staticmethod
    def grading_curve(
        points: Iterable[Tuple[float, float]],
        basis: Literal["number", "area"] = "area",
        kind: Literal["radius", "diameter"] = "diameter",
    ) -> Radii: ...
    @property
    def min(self) -> float: ...
    @property
    def max(self) -> float: ...
    def describe(self) -> str: ...
    def quantile(self, u: float) -> float: ...
    def cdf(self, r: float) -> float: ...
    def sample(self, n: int, seed: int = 0) -> npt.NDArray[np.float64]: ...

class Progress:
    disks: int
    fraction: float
    area: float
    phase: Literal["generate", "certify", "jam"]

class StopSource:
    def __init__(self) -> None: ...
    def request_stop(self) -> bool: ...
    @property
    def stop_requested(self) -> bool: ...

class Certificate:
    generated: int
    culled: int
    dropped: int
    candidate_pairs: int
    exact: bool

class FillStats:
    attempts: int
    cuts: int
    blocked_segments: int
    exact_checks: int
    void_fills: int
    skipped_radii: int
    cavities: int
    jam_rounds: int
    jam_inserted: int
    jam_steps: int
    seconds_front: float
    seconds_jam: float
    seconds_cull: float
    seconds_overlap: float

# The dicts of the result structs (include/frontpack/{fill,stats}.hpp): one key per field, in the
# order of the field lists (python/tests/test_result_fields.py checks them against the module).
class TargetReport(TypedDict):
    fraction_requested: float
    fraction_achieved: float
    fraction_dense: float
    scale: float
    removed: int
    fills: int
    count_requested: int
    count_achieved: int
    height: Optional[float]
    area_filled: float
    outside_original: int

class Packing:
    disks: Disks
    certificate: Certificate
    stats: FillStats
    truncated: bool
    cancelled: bool
    target: Optional[TargetReport]
    def __len__(self) -> int: ...

def fill(
    domain: Shape,
    radius: Union[Radii, str, float] = "uniform:0.01,0.05",
    *,
    method: Literal["boundary", "closed", "open"] = "boundary",
    seed: int = 0,
    window: int = 5,
    start: Optional[Tuple[float, float]] = None,
    clearance: float = 0.0,
    fill_voids: bool = True,
    max_disks: int = 50_000_000,
    memory_limit: int = 0,
    fraction: Optional[float] = None,
    count: int = 0,
    height: Optional[float] = None,
    jam: bool = False,
    progress: Union[None, bool, Callable[[Progress], Optional[bool]]] = None,
    stop: Optional[StopSource] = None,
) -> Packing: ...

class CertifyReport:
    certificate: Certificate
    outside: npt.NDArray[np.int64]
    overlapping: npt.NDArray[np.int64]  # shape (K, 2)
    deepest_overlap: Optional[Tuple[int, int]]
    deepest_overlap_depth: float
    farthest_outside: Optional[int]
    farthest_outside_by: float
    @property
    def valid(self) -> bool: ...
    def __bool__(self) -> bool: ...

def certify(domain: Shape, disks: ArrayLike) -> CertifyReport: ...

class SizeClassRow(TypedDict):
    radius: float
    requested_number: float
    requested_area: float
    achieved_number: float
    achieved_area: float
    requested_number_passing: float
    requested_area_passing: float
    achieved_number_passing: float
    achieved_area_passing: float

class HistogramBin(TypedDict):
    lo: float
    hi: float
    count: int
    achieved_number: float
    achieved_area: float
    requested_number: float
    requested_area: float

class SizeStats(TypedDict):
    count: int
    rmin: float
    rmax: float
    mean: float
    sd: float
    median_number: float
    median_area: float
    compared: bool
    requested: str
    ks_number: float
    ks_area: float
    ks_number_at: float
    ks_area_at: float
    classes: list[SizeClassRow]
    histogram: list[HistogramBin]

class EmptyCircle(TypedDict):
    computed: bool
    radius: float
    radius_upper: float
    centre: Tuple[float, float]
    tolerance: float

# "from" is a keyword: the functional form.
CoverageBin = TypedDict("CoverageBin", {"from": float, "to": float, "fraction": float, "error": float, "samples": int})

class CellCoverage(TypedDict):
    cell_side: float
    cells: int
    p1: float
    p5: float
    p50: float
    sd: float
    origin: Tuple[float, float]
    nx: int
    ny: int
    map: npt.NDArray[np.float64]  # shape (ny, nx)

class PackingStats(TypedDict):
    disks: int
    domain_area: float
    disk_area: float
    packing_fraction: float
    void_ratio: float
    walls: bool
    band_width: float
    interior_fraction: float
    band_fraction: float
    interior_error: float
    band_error: float
    interior_area: float
    band_area: float
    interior_samples: int
    band_samples: int
    contact_gap: float
    contacts: int
    overlaps: int
    max_overlap: float
    wall_contacts: int
    mean_coordination: float
    coordination_histogram: list[int]
    rattlers: int
    mean_coordination_without_rattlers: float
    interior_disks: int
    interior_coordination: float
    band_disks: int
    band_median_area: float
    inside_median_area: float
    segregation_ks_area: float
    largest_empty_circle: EmptyCircle
    holes: dict[float, int]  # HoleCount: {radius: count}
    coverage_unit: float
    coverage_profile: list[CoverageBin]
    cell_coverage: CellCoverage
    sizes: SizeStats

def measure(
    domain: Shape,
    disks: ArrayLike,
    *,
    requested: Optional[Radii] = None,
    contact_gap: float = 0.0,
    band_width: float = 0.0,
    samples: int = 1_000_000,
    histogram_bins: int = 20,
    contacts: bool = True,
    empty_circle: bool = True,
    holes: bool = True,
    hole_radii: Sequence[float] = (),
    coverage_profile: bool = True,
    cell_coverage: bool = True,
    cell_side: float = 0.0,
    max_disks: int = 50_000_000,
    memory_limit: int = 0,
) -> PackingStats: ...

WriteFormat = Literal["csv", "yade", "lammps", "vtp", "svg"]

def write(
    path: PathLike,
    domain: Shape,
    disks: ArrayLike,
    format: Optional[WriteFormat] = None,
    *,
    types: Optional[ArrayLike] = None,
    width: float = 800.0,
    colour_by_size: bool = True,
    density: float = 1.0,
    atom_type: int = 1,
    type_densities: Sequence[float] = (),
    atom_types: int = 0,
) -> None: ...
def dumps(
    domain: Shape,
    disks: ArrayLike,
    format: WriteFormat,
    *,
    types: Optional[ArrayLike] = None,
    width: float = 800.0,
    colour_by_size: bool = True,
    density: float = 1.0,
    atom_type: int = 1,
    type_densities: Sequence[float] = (),
    atom_types: int = 0,
) -> str: ...
def render(path: PathLike, domain: Shape, disks: ArrayLike, width: float = 800.0, colour_by_size: bool = True) -> None: ...
def read_disks(
    path: PathLike,
    format: Optional[Literal["csv", "yade", "lammps", "lammps-dump", "vtp"]] = None,
    *,
    timestep: Optional[int] = None,
    radius_array: str = "",
) -> Disks: ...
def assign_types(rule: Union[str, Sequence[float]], disks: ArrayLike) -> npt.NDArray[np.uint32]: ...
def wall_disks(domain: Shape, wall_radius: float, rmin: float) -> Disks: ...
def make_deck(
    domain: Shape,
    disks: ArrayLike,
    simulator: Literal["lammps", "liggghts", "yade"] = "lammps",
    *,
    types: Optional[ArrayLike] = None,
    densities: Sequence[float] = (2500.0,),
    thickness: float = 0.0,
    gravity: float = 9.81,
    wall_radius: float = 0.0,
    steps: int = 5000,
) -> dict[str, str]: ...
