"""Hausdorff Lens: the exact Hausdorff distance between triangle meshes (Straub 2007).

Type stub of the compiled module `hlens` (python/*.cpp); see the docstrings there and README.md.
"""
from os import PathLike
from typing import Any, Callable, Iterator, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, PathLike]

def load(path: _Path, weld: bool = True) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """Read .obj .ply .stl .off .gltf .glb into V (n, 3) float64 and F (m, 3) int64.

    Raises ValueError with hlens-cli's message ("<path>: ...") for a bad file."""

class OneSided:
    """One direction of a comparison: h(A,B) (Result.a_to_b) or h(B,A) (Result.b_to_a)."""
    distance: float
    relative: Optional[float]  # distance / diagonal of both meshes' bounding box
    lower: float               # certified: lower <= h <= upper
    upper: float
    target: int                # witness triangle of the measured mesh
    from_point: list[float]    # witness point, and its nearest point on the other mesh
    to_point: list[float]
    exact_targets: int
    exact_solves: int
    seconds: float
    target_max: npt.NDArray[np.float64]  # per triangle: its largest distance (upper bound where not exact)
    target_exact: npt.NDArray[np.bool_]
    # stats=True only (None otherwise): the fields of `hlens-cli distance --stats` for this direction
    area: Optional[float]
    mean: Optional[float]
    rms: Optional[float]
    percentiles: Optional[dict[str, float]]      # {'50', '90', '95', '99'}
    histogram: Optional[dict[str, list[float]]]  # histogram=N: {'edges': N+1, 'area': N}
    area_above: Optional[float]                  # with a tolerance: the area where d > tolerance
    fraction_above: Optional[float]
    stats_error: Optional[dict[str, float]]
    stats_seconds: Optional[dict[str, Any]]
    sliver_triangles: Optional[int]              # None if there are none
    sliver_area: Optional[float]
    target_mean: Optional[npt.NDArray[np.float64]]  # per triangle: mean distance (0 for a sliver)
    target_rms: Optional[npt.NDArray[np.float64]]   # per triangle: RMS distance
    def to_dict(self) -> dict[str, Any]: ...

class Result:
    """The content of `hlens-cli distance --json` as attributes; to_dict() gives the same dict."""
    a_to_b: OneSided
    b_to_a: Optional[OneSided]  # None when one_sided
    hausdorff: Optional[float]
    relative: Optional[float]
    diagonal: float             # of the union of both meshes' bounding boxes
    a: dict[str, Any]           # {'path', 'vertices', 'triangles'}
    b: dict[str, Any]
    seconds: float
    mode: str
    threads: int
    units: Optional[str]
    tolerance: Optional[float]
    exceeds: Optional[bool]     # with a tolerance
    index: Optional[int]        # batch only
    path: str                   # B's path ('' for arrays)
    ok: bool                    # True
    def to_dict(self) -> dict[str, Any]: ...

class BatchFailure:
    """A file of batch() that could not be read or compared."""
    index: int
    path: str
    error: str
    ok: bool                    # False
    def to_dict(self) -> dict[str, Any]: ...

class BatchIterator(Iterator[Union[Result, BatchFailure]]):
    def __iter__(self) -> "BatchIterator": ...
    def __next__(self) -> Union[Result, BatchFailure]: ...

def distance(VA: npt.ArrayLike, FA: npt.ArrayLike, VB: npt.ArrayLike, FB: npt.ArrayLike, *,
             one_sided: bool = False, mode: str = "fast", threads: int = 0, stats: bool = False,
             tolerance: Optional[float] = None, histogram: int = 0,
             progress: Optional[Callable[[float], Any]] = None, units: Optional[str] = None) -> Result:
    """Exact h(A,B), h(B,A) and the Hausdorff distance, as `hlens-cli distance --json`.

    Vertices: any real or integer dtype; triangles: any integer dtype; C or Fortran order, or
    lists. Bad input raises ValueError. stats=True adds each direction's surface statistics
    (`hlens-cli distance --stats`; slow: every triangle's full construction) and the per-triangle
    arrays target_mean and target_rms; histogram=N (with stats) N bins from 0 to the distance."""

def batch(reference: _Path, paths: Sequence[_Path], *, one_sided: bool = False, mode: str = "fast",
          threads: int = 0, jobs: int = 1, stats: bool = False, tolerance: Optional[float] = None,
          histogram: int = 0, weld: bool = True, units: Optional[str] = None) -> BatchIterator:
    """Compare the reference file with each file, yielding each pair as it finishes.

    stats, histogram, tolerance: as for distance() (`hlens-cli batch --stats --histogram N`)."""

def trace(VA: npt.ArrayLike, FA: npt.ArrayLike, VB: npt.ArrayLike, FB: npt.ArrayLike,
          target: int) -> list[dict[str, Any]]:
    """Every event of triangle `target` of A against B, then a final summary (hlens-cli trace --json)."""

class TargetSolver:
    """One target triangle of A against B, step by step."""
    def __init__(self, VA: npt.ArrayLike, FA: npt.ArrayLike, VB: npt.ArrayLike, FB: npt.ArrayLike,
                 target: int) -> None: ...
    def step(self) -> bool: ...
    def step_event(self) -> Optional[dict[str, Any]]: ...
    def run(self) -> None: ...
    events: list[dict[str, Any]]
    finished: bool
    max_sq: float
    max_point: list[float]
    max_point_2d: list[float]
    search_radius: float
    insertions: int
    corners: npt.NDArray[np.float64]  # (3, 2), the target in its frame
    def domains(self, per_arc: int = 16) -> list[dict[str, Any]]:
        """Domains: face, label, covered, area, poly {a..f, type}, loops [(k, 2) arrays], arcs."""
