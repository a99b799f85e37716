"""Type stubs of the compiled extension (see the Rust sources in python/rust/lib.rs)."""

from typing import Any, Callable, Dict, List, Literal, Optional, Sequence, Tuple, final

from typing_extensions import Self

import numpy as np
import numpy.typing as npt

__all__ = [
    "CohesivePullOff",
    "CohesiveZoneWarning",
    "ContactSolver",
    "ConvergenceError",
    "Curve",
    "EdgeContactWarning",
    "ForceCurve",
    "Indenter",
    "InvalidInputError",
    "LayeredContactError",
    "Material",
    "ModulusFamily",
    "Solution",
    "Substrate",
    "before_jump_off",
    "check_scene",
    "edge_release",
    "flat_punch_pull_off_force",
    "flat_punch_stiffness",
    "hertz_contact_radius",
    "hertz_force",
    "jkr_pull_off_force",
    "jkr_sinusoid_pull_off",
    "jkr_state",
    "paraboloid_pull_off_force",
    "paraboloid_series",
    "paraboloid_state",
    "peel_punch",
    "refine_heights",
    "rough_surface_heights",
    "run_scene",
    "scene_reference",
    "scene_schema",
    "subsurface_stress",
    "tip_pressure",
    "tip_pull_off",
]

class LayeredContactError(Exception): ...
class InvalidInputError(LayeredContactError): ...
class ConvergenceError(LayeredContactError): ...
class EdgeContactWarning(UserWarning): ...
class CohesiveZoneWarning(UserWarning): ...

@final
class Material:
    def __new__(cls, youngs_modulus: float, poisson_ratio: float) -> Self: ...
    @property
    def youngs_modulus(self) -> float: ...
    @property
    def poisson_ratio(self) -> float: ...
    @property
    def contact_modulus(self) -> float: ...

@final
class Substrate:
    @staticmethod
    def half_space(material: Material) -> Substrate: ...
    @staticmethod
    def layer_on_rigid_base(layer: Material, thickness: float) -> Substrate: ...
    @staticmethod
    def layer_resting_on_rigid_base(layer: Material, thickness: float) -> Substrate: ...
    @staticmethod
    def layer_resting_on_elastic_base(
        layer: Material, thickness: float, base: Material
    ) -> Substrate: ...
    @staticmethod
    def layer_on_elastic_base(layer: Material, thickness: float, base: Material) -> Substrate: ...
    @staticmethod
    def layer_resting_on(layer: Material, thickness: float, support: Substrate) -> Substrate: ...
    @staticmethod
    def stack(
        layers: Sequence[tuple[Material, float]], base: Material | None = None
    ) -> Substrate: ...
    @property
    def layer_count(self) -> int: ...
    @property
    def total_thickness(self) -> float | None: ...

@final
class Indenter:
    @staticmethod
    def flat_punch(radius: float) -> Indenter: ...
    @staticmethod
    def sphere(radius: float) -> Indenter: ...
    @staticmethod
    def paraboloid(radius: float) -> Indenter: ...
    @staticmethod
    def cone(half_angle: float, base_radius: float) -> Indenter: ...
    @staticmethod
    def wavy(
        rows: int, columns: int, spacing: float, waves: Tuple[int, int], amplitude: float
    ) -> Indenter: ...
    @staticmethod
    def height_map(heights: npt.NDArray[np.float64], spacing: float) -> Indenter: ...
    @staticmethod
    def rough_surface(
        hurst: float,
        long_cutoff: float,
        short_cutoff: float,
        seed: int,
        cells: int,
        spacing: float,
        rms_height: Optional[float] = None,
        rms_slope: Optional[float] = None,
    ) -> Indenter: ...
    def tilted(self, angle_y: float, angle_x: float) -> Indenter: ...
    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]: ...
    def height(
        self, x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.float64]: ...
    @property
    def bounding_radius(self) -> float: ...

@final
class Solution:
    depth: float
    force: float
    contact_area: float
    contact_radius: float
    contact_cells: int
    edge_contact: bool
    iterations: int
    coarse_iterations: int
    mean_gap: Optional[float]
    residual: float
    pressure: Optional[npt.NDArray[np.float64]]
    displacement: Optional[npt.NDArray[np.float64]]
    gap: Optional[npt.NDArray[np.float64]]
    x: npt.NDArray[np.float64]
    y: npt.NDArray[np.float64]

@final
class CohesivePullOff:
    force: float
    depth: float
    solves: int
    iterations: int
    cells_across: float
    zone_cells: float
    @property
    def zone_spans_contact(self) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]: ...
    @staticmethod
    def _rebuild(state: Tuple[float, float, int, int, float, float]) -> CohesivePullOff: ...

@final
class ContactSolver:
    def __new__(
        cls,
        substrate: Substrate,
        rows: int,
        columns: int,
        spacing: float,
        periodic: bool = False,
        tolerance: float = 1e-8,
        max_iterations: int = 10000,
        coarse_blocks: int | Literal["box"] | None = None,
    ) -> Self: ...
    def solve_depth(self, indenter: Indenter, depth: float, warm_start: bool = False) -> Solution: ...
    def solve_force(self, indenter: Indenter, force: float, warm_start: bool = False) -> Solution: ...
    def solve_depth_cohesive(
        self,
        indenter: Indenter,
        depth: float,
        advancing: float,
        receding: float | None = None,
        zone_cells: float | None = None,
        warm_start: bool = False,
        cells_across: float | None = None,
    ) -> Solution: ...
    def solve_force_cohesive(
        self,
        indenter: Indenter,
        force: float,
        advancing: float,
        receding: float | None = None,
        zone_cells: float | None = None,
        cells_across: float | None = None,
    ) -> Solution: ...
    def cohesive_pull_off(
        self,
        indenter: Indenter,
        depth: float,
        step: float,
        advancing: float,
        receding: float | None = None,
        zone_cells: float | None = None,
        cells_across: float | None = None,
    ) -> CohesivePullOff: ...
    @property
    def grid(self) -> Tuple[int, int, float]: ...
    @property
    def coarse_blocks(self) -> Optional[int]: ...
    @property
    def last_preconditioning(self) -> Optional[Dict[str, Any]]: ...

@final
class Curve:
    phase: list[str]
    depth: npt.NDArray[np.float64]
    force: npt.NDArray[np.float64]
    contact_area: npt.NDArray[np.float64]
    contact_radius: npt.NDArray[np.float64]
    iterations: list[int]
    stiffness: Optional[float]
    pull_off: Optional[dict]
    grid: Tuple[int, int, float]
    peak: Optional[Solution]
    caveats: list[str]
    adhesion_method: Optional[str]
    stresses: Optional[dict]
    zone_scales: Optional[dict]
    def __len__(self) -> int: ...

def run_scene(
    scene: Any,
    progress: Optional[Callable[[dict], None]] = None,
    indenter: Optional[Indenter] = None,
    iteration: Optional[Callable[[dict], None]] = None,
) -> Curve: ...
def refine_heights(
    heights: npt.NDArray[np.float64], factor: int
) -> npt.NDArray[np.float64]: ...
def rough_surface_heights(
    hurst: float,
    long_cutoff: float,
    short_cutoff: float,
    seed: int,
    cells: int,
    spacing: float,
    rms_height: Optional[float] = None,
    rms_slope: Optional[float] = None,
) -> npt.NDArray[np.float64]: ...
def subsurface_stress(
    substrate: Substrate,
    pressure: npt.NDArray[np.float64],
    spacing: float,
    depths: List[float],
    periodic: bool = False,
    padding: Optional[int] = None,
    side: str = "below",
    interfaces: bool = False,
) -> dict: ...
def check_scene(scene: Any) -> Tuple[int, int, float, int]: ...
def scene_reference(scene: Any) -> dict: ...
def scene_schema() -> str: ...
def hertz_force(material: Material, radius: float, depth: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]: ...
def hertz_contact_radius(
    material: Material, radius: float, depth: npt.NDArray[np.float64]
) -> npt.NDArray[np.float64]: ...
def jkr_state(
    material: Material, radius: float, work_of_adhesion: float, contact_radius: npt.NDArray[np.float64]
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def jkr_pull_off_force(material: Material, radius: float, work_of_adhesion: float) -> float: ...
def jkr_sinusoid_pull_off(
    material: Material, wavelength: float, amplitude: float, work_of_adhesion: float
) -> Tuple[float, float]: ...
def edge_release(
    solver: ContactSolver,
    indenter: Indenter,
    depth: float,
    contact: npt.NDArray[np.bool_],
    window: float = ...,
) -> dict: ...
def peel_punch(
    solver: ContactSolver,
    indenter: Indenter,
    work_of_adhesion: float,
    bonded: Optional[npt.NDArray[np.bool_]] = None,
) -> dict: ...
def flat_punch_stiffness(substrate: Substrate, radius: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]: ...
def paraboloid_pull_off_force(substrate: Substrate, radius: float, work_of_adhesion: float) -> float: ...
def paraboloid_state(
    substrate: Substrate, radius: float, work_of_adhesion: float, contact_radius: npt.NDArray[np.float64]
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def flat_punch_pull_off_force(substrate: Substrate, radius: float, work_of_adhesion: float) -> float: ...
def paraboloid_series(poisson_ratio: float) -> List[float]: ...
def before_jump_off(
    position: npt.NDArray[np.float64], force: npt.NDArray[np.float64]
) -> npt.NDArray[np.bool_]: ...

@final
class ModulusFamily:
    def __new__(
        cls,
        substrate: Substrate,
        kind: str,
        radius: float,
        max_depth: float,
        youngs_range: Tuple[float, float],
        nodes: int = 12,
        half_angle: float = ...,
    ) -> Self: ...
    def forces(
        self, depth: npt.NDArray[np.float64], youngs_modulus: float, work_of_adhesion: float = 0.0
    ) -> npt.NDArray[np.float64]: ...
    def reach(self, youngs_modulus: float, work_of_adhesion: float = 0.0) -> float: ...
    @property
    def youngs_range(self) -> Tuple[float, float]: ...

@final
class ForceCurve:
    def __new__(
        cls, substrate: Substrate, kind: str, radius: float, max_depth: float, half_angle: float = ...
    ) -> Self: ...
    def reach(self, modulus_ratio: float = 1.0, work_of_adhesion: float = 0.0) -> float: ...
    def forces(
        self, depth: npt.NDArray[np.float64], modulus_ratio: float = 1.0, work_of_adhesion: float = 0.0
    ) -> npt.NDArray[np.float64]: ...
    @property
    def contact_modulus(self) -> float: ...
    @property
    def max_depth(self) -> float: ...

def tip_pressure(
    substrate: Substrate,
    kind: str,
    radius: float,
    work_of_adhesion: float,
    contact_radius: float,
    r: npt.NDArray[np.float64],
    half_angle: float = ...,
) -> Tuple[npt.NDArray[np.float64], float]: ...
def tip_pull_off(
    substrate: Substrate,
    kind: str,
    radius: float,
    work_of_adhesion: float,
    half_angle: float = ...,
    spring: Optional[float] = None,
) -> Dict[str, Dict[str, float]]: ...
