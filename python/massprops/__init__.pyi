"""Type stubs of the massprops package (the compiled _massprops module and the Python wrappers)."""

import enum
import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
DEFAULT_VALIDITY_TOLERANCE: float

ArrayLike = npt.ArrayLike
Vector3 = npt.NDArray[np.float64]
Matrix3 = npt.NDArray[np.float64]
PathOrText = Union[str, bytes, os.PathLike[str]]
SolverArg = Union[PrincipalSolver, str]

# ------------- core: rotational, unit and spatial inertia, principal moments (core_bindings.cc)

class PrincipalSolver(enum.Enum):
    ACCURATE: int
    FAST: int

class RotationalInertia:
    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, Ixx: float, Iyy: float, Izz: float, Ixy: float = 0.0, Ixz: float = 0.0,
                 Iyz: float = 0.0, *, skip_validity_check: bool = False) -> None: ...
    @overload
    def __init__(self, mass: float, p_PQ_E: ArrayLike) -> None: ...
    @staticmethod
    def make_from_moments_and_products_of_inertia(
        Ixx: float, Iyy: float, Izz: float, Ixy: float, Ixz: float, Iyz: float,
        skip_validity_check: bool = False) -> RotationalInertia: ...
    @staticmethod
    def from_matrix(I: ArrayLike, skip_validity_check: bool = False) -> RotationalInertia: ...
    @staticmethod
    def triaxially_symmetric(I_triaxial: float) -> RotationalInertia: ...
    def get_moments(self) -> Vector3: ...
    def get_products(self) -> Vector3: ...
    def trace(self) -> float: ...
    def calc_maximum_possible_moment_of_inertia(self) -> float: ...
    def __getitem__(self, index: Tuple[int, int]) -> float: ...
    def copy_to_full_matrix3(self) -> Matrix3: ...
    def __array__(self, dtype: Any = None, copy: Any = None) -> Matrix3: ...
    def is_nearly_equal_to(self, other: RotationalInertia, precision: float) -> bool: ...
    def __eq__(self, other: object) -> bool: ...
    def __ne__(self, other: object) -> bool: ...
    def __add__(self, other: RotationalInertia) -> RotationalInertia: ...
    def __sub__(self, other: RotationalInertia) -> RotationalInertia: ...
    @overload
    def __mul__(self, s: float) -> RotationalInertia: ...
    @overload
    def __mul__(self, w_E: ArrayLike) -> Vector3: ...
    def __rmul__(self, s: float) -> RotationalInertia: ...
    def __truediv__(self, s: float) -> RotationalInertia: ...
    def multiply_by_scalar_skip_validity_check(self, s: float) -> RotationalInertia: ...
    def set_to_nan(self) -> None: ...
    def set_zero(self) -> None: ...
    def is_nan(self) -> bool: ...
    def is_inf(self) -> bool: ...
    def is_finite(self) -> bool: ...
    def is_zero(self) -> bool: ...
    def calc_principal_moments_of_inertia(self, solver: SolverArg = "accurate") -> Vector3: ...
    def calc_principal_moments_and_axes_of_inertia(
        self, solver: SolverArg = "accurate") -> Tuple[Vector3, Matrix3]: ...
    def could_be_physically_valid(self, relative_tolerance: float = ...) -> bool: ...
    def criticize_not_physically_valid(self, relative_tolerance: float = ...) -> str: ...
    def re_express(self, R_AE: ArrayLike) -> RotationalInertia: ...
    def shift_from_center_of_mass(self, mass: float, p_BcmQ_E: ArrayLike) -> RotationalInertia: ...
    def shift_to_center_of_mass(self, mass: float, p_QBcm_E: ArrayLike) -> RotationalInertia: ...
    def shift_to_then_away_from_center_of_mass(
        self, mass: float, p_PBcm_E: ArrayLike, p_QBcm_E: ArrayLike) -> RotationalInertia: ...

class UnitInertia(RotationalInertia):
    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, Ixx: float, Iyy: float, Izz: float, Ixy: float = 0.0, Ixz: float = 0.0,
                 Iyz: float = 0.0, *, skip_validity_check: bool = False) -> None: ...
    @overload
    def __init__(self, I: RotationalInertia) -> None: ...
    def set_from_rotational_inertia(self, I: RotationalInertia, mass: float) -> UnitInertia: ...
    def re_express(self, R_AE: ArrayLike) -> UnitInertia: ...
    def shift_from_center_of_mass(self, p_BcmQ_E: ArrayLike) -> UnitInertia: ...  # type: ignore[override]
    def shift_to_center_of_mass(self, p_QBcm_E: ArrayLike) -> UnitInertia: ...  # type: ignore[override]
    def shift_to_then_away_from_center_of_mass(  # type: ignore[override]
        self, p_PBcm_E: ArrayLike, p_QBcm_E: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def point_mass(p_FQ: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def triaxially_symmetric(I_triaxial: float) -> UnitInertia: ...
    @staticmethod
    def solid_ellipsoid(a: float, b: float, c: float) -> UnitInertia: ...
    @staticmethod
    def solid_sphere(r: float) -> UnitInertia: ...
    @staticmethod
    def hollow_sphere(r: float) -> UnitInertia: ...
    @staticmethod
    def solid_box(Lx: float, Ly: float, Lz: float) -> UnitInertia: ...
    @staticmethod
    def solid_cube(L: float) -> UnitInertia: ...
    @staticmethod
    def solid_cylinder(r: float, L: float, unit_vector: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def solid_cylinder_about_end(r: float, L: float, unit_vector: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def solid_capsule(r: float, L: float, unit_vector: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def thin_rod(L: float, unit_vector: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def thin_disk(r: float, unit_normal: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def axially_symmetric(J: float, K: float, unit_vector: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def straight_line(K: float, unit_vector: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def solid_tetrahedron_about_vertex(p1: ArrayLike, p2: ArrayLike,
                                       p3: ArrayLike) -> UnitInertia: ...
    @staticmethod
    def solid_tetrahedron_about_point(p0: ArrayLike, p1: ArrayLike, p2: ArrayLike,
                                      p3: ArrayLike) -> UnitInertia: ...

class SpatialInertia:
    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, mass: float, p_PScm_E: ArrayLike, G_SP_E: UnitInertia,
                 skip_validity_check: bool = False) -> None: ...
    @staticmethod
    def make_from_central_inertia(mass: float, p_PScm_E: ArrayLike,
                                  I_SScm_E: RotationalInertia) -> SpatialInertia: ...
    @staticmethod
    def point_mass(mass: float, p_PQ_E: ArrayLike) -> SpatialInertia: ...
    @staticmethod
    def make_unitary() -> SpatialInertia: ...
    @staticmethod
    def zero() -> SpatialInertia: ...
    @staticmethod
    def nan() -> SpatialInertia: ...
    def get_mass(self) -> float: ...
    def get_com(self) -> Vector3: ...
    def calc_com_moment(self) -> Vector3: ...
    def get_unit_inertia(self) -> UnitInertia: ...
    def calc_rotational_inertia(self) -> RotationalInertia: ...
    def is_nan(self) -> bool: ...
    def set_nan(self) -> None: ...
    def is_physically_valid(self, relative_tolerance: float = ...) -> bool: ...
    def criticize_not_physically_valid(self, relative_tolerance: float = ...) -> str: ...
    def calc_pseudo_inertia(self) -> npt.NDArray[np.float64]: ...
    def copy_to_full_matrix6(self) -> npt.NDArray[np.float64]: ...
    def shift(self, p_PQ_E: ArrayLike) -> SpatialInertia: ...
    def re_express(self, R_AE: ArrayLike) -> SpatialInertia: ...
    def __add__(self, other: SpatialInertia) -> SpatialInertia: ...
    def __eq__(self, other: object) -> bool: ...
    def __ne__(self, other: object) -> bool: ...

def principal_moments(I: ArrayLike, solver: SolverArg = "accurate") -> npt.NDArray[np.float64]: ...
def is_physically_valid(I: ArrayLike, tolerance: float = 1e-6) -> npt.NDArray[np.bool_]: ...

# -------------------------------- reading: models from URDF and SDF files (reading_bindings.cc)

class ReadError(Exception):
    file: str
    line: int
    column: int
    element: str
    message: str
    errors: List[str]

class SourceLocation:
    file: str
    line: int
    column: int

class Pose:
    p_AB: Vector3
    R_AB: Matrix3
    def inverse(self) -> Pose: ...
    def is_identity(self) -> bool: ...
    def __mul__(self, X_BC: Pose) -> Pose: ...

class Inertial:
    mass: float
    X_BBi: Pose
    ixx: float
    iyy: float
    izz: float
    ixy: float
    ixz: float
    iyz: float
    inertia: Matrix3
    location: SourceLocation
    mass_location: SourceLocation
    inertia_location: SourceLocation
    pose_location: SourceLocation

class Geometry:
    type: str
    size: Vector3
    radius: float
    length: float
    radii: Vector3
    uri: str
    scale: Vector3
    submesh: str
    center_submesh: bool
    X_BG: Pose
    is_collision: bool
    location: SourceLocation

class Link:
    name: str
    inertial: Optional[Inertial]
    mass: Optional[float]
    com: Optional[Vector3]
    inertia: Optional[Matrix3]
    geometries: List[Geometry]
    ignored_rules: List[str]
    inertial_unreadable: bool
    location: SourceLocation
    line: int
    def rotational_inertia(self) -> Optional[RotationalInertia]: ...
    def spatial_inertia(self) -> Optional[SpatialInertia]: ...

class Joint:
    name: str
    type: str
    parent: str
    child: str
    X_PC: Pose
    axis: Vector3
    location: SourceLocation

class CompositeInertia:
    frame: str
    mass: float
    com: Vector3
    inertia_about_com: Matrix3
    unreachable_links: List[str]
    def calc_inertia_about_origin(self) -> Matrix3: ...
    def rotational_inertia(self) -> RotationalInertia: ...

class WeldedGroup:
    root_link: str
    links: List[str]
    link_indices: List[int]
    X_RL: List[Pose]
    parent_joint: Optional[str]
    is_moving: bool
    composite: CompositeInertia

class Model:
    name: str
    format: str
    file: str
    links: List[Link]
    joints: List[Joint]
    root_link: str
    location: SourceLocation
    is_static: bool
    def find_link(self, name: str) -> int: ...
    def link(self, name: str) -> Link: ...
    def welded_groups(self) -> List[WeldedGroup]: ...
    def composite(self) -> CompositeInertia: ...

def read(path_or_text: PathOrText, *, model_paths: Sequence[str] = ...) -> Model: ...
def read_all(path_or_text: PathOrText, *, model_paths: Sequence[str] = ...) -> List[Model]: ...

# ------------------ checking: findings and rules (checking_bindings.cc; check() in __init__.py)

class Finding:
    rule: str
    severity: str
    model: str
    link: str
    file: str
    line: int
    column: int
    message: str
    headline: str
    evidence: Dict[str, float]
    help: str
    values: Dict[str, float]
    group: List[str]
    repair: Optional[Repair]
    source: Optional[Dict[str, Any]]
    def to_dict(self) -> Dict[str, Any]: ...

class CheckOptions:
    tolerance: Optional[float]
    disable: Sequence[str]
    severity: Mapping[str, str]
    config: Optional[Union[str, os.PathLike[str]]]
    model_paths: Sequence[str]
    geometry: bool
    geometry_factor: float
    package_paths: Sequence[str]
    def __init__(self, tolerance: Optional[float] = None, disable: Sequence[str] = (),
                 severity: Mapping[str, str] = ..., config: Optional[Union[str, os.PathLike[str]]] = "auto",
                 model_paths: Sequence[str] = (), geometry: bool = False,
                 geometry_factor: float = 2.0, package_paths: Sequence[str] = ()) -> None: ...

def check(path_or_text: PathOrText, options: Optional[CheckOptions] = None, *,
          source_root: Union[None, str, os.PathLike[str], Sequence[str]] = ...,
          xacro_args: Optional[Mapping[str, str]] = ...,
          tolerance: Optional[float] = ..., disable: Sequence[str] = ...,
          severity: Mapping[str, str] = ..., config: Optional[Union[str, os.PathLike[str]]] = ...,
          model_paths: Sequence[str] = ..., geometry: bool = ..., geometry_factor: float = ...,
          package_paths: Sequence[str] = ...) -> List[Finding]: ...
def rules() -> List[Dict[str, Any]]: ...

# -------- reporting: the report as Python data (reporting_bindings.cc; report() in __init__.py)

def report(path_or_text: PathOrText, *, joints: Optional[Mapping[str, float]] = None,
           frame: str = "", only: Sequence[str] = (), subtree: str = "", geometry: bool = False,
           package_paths: Sequence[str] = (), model_paths: Sequence[str] = ()) -> Dict[str, Any]: ...
def diff(a: Union[str, os.PathLike[str]], b: Union[str, os.PathLike[str]], *,
         tolerance: float = 1e-6, target: Optional[str] = None,
         model_paths: Sequence[str] = ()) -> Dict[str, Any]: ...

# ---------- identification: the report as Python data (identify_bindings.cc; in __init__.py)

def identify(robot: Union[str, os.PathLike[str]], data: Union[str, os.PathLike[str]], *,
             validate: float = 0.3) -> Dict[str, Any]: ...

# ------------------- fixing: repairs and fixed files (fixing_bindings.cc; fix() in __init__.py)

class FieldChange:
    element: str
    attribute: str
    line: int
    first_token: int
    old_values: List[float]
    new_values: List[float]

class Repair:
    rule: str
    link: str
    method: str
    before: Optional[Inertial]
    after: Inertial
    inserts_inertial: bool
    inserts_origin: bool
    changes: List[FieldChange]
    link_line: int
    why: str
    relative_change: float
    resolves: List[str]

class PatchError:
    link: str
    line: int
    message: str

class FixResult:
    path: str
    original: str
    text: str
    changed: bool
    reads_back: bool
    changes: List[Repair]
    patch_errors: List[PatchError]
    remaining_errors: List[Finding]
    warnings: List[str]
    written: Optional[str]
    def diff(self, context: int = 3) -> str: ...

def fix(path_or_text: PathOrText, apply: Iterable[str] = (), dry_run: bool = True, *,
        output: Optional[Union[str, os.PathLike[str]]] = None, backup: Optional[str] = None,
        repair: str = "project", fix_units: bool = False,
        density: Union[float, Mapping[str, float]] = 1000.0,
        from_geometry: Union[bool, str, Sequence[str]] = False, tolerance: float = 1e-6,
        geometry: bool = False, package_paths: Sequence[str] = (),
        model_paths: Sequence[str] = (), total_mass: Optional[float] = None,
        mass: Mapping[str, float] = {}, material: Mapping[str, str] = {}) -> FixResult: ...
def repair_inertia(I: ArrayLike, method: str = "project", tolerance: float = 1e-6) -> Matrix3: ...
