"""massprops: validate and repair the mass properties of robot models.

The core classes (RotationalInertia, UnitInertia, SpatialInertia) with numpy arrays in and out,
vectorised batch helpers (principal_moments, is_physically_valid), and the file side of the
`massprops` command-line tool: read, check, report and fix URDF and SDF files.

>>> import massprops
>>> findings = massprops.check("robot.urdf")
>>> [f.link for f in findings if f.rule == "inertia-not-physical"]
>>> result = massprops.fix("robot.urdf")          # dry run: nothing is written
>>> print(result.diff())

See docs/python.md for the whole API.
"""

from __future__ import annotations

import dataclasses
import os
import tempfile
from typing import Dict, Iterable, Mapping, Optional, Sequence, Union

from ._massprops import (  # noqa: F401  (re-exported)
    DEFAULT_VALIDITY_TOLERANCE,
    CompositeInertia,
    FieldChange,
    Finding,
    FixResult,
    Geometry,
    Inertial,
    Joint,
    Link,
    Model,
    PatchError,
    Pose,
    PrincipalSolver,
    ReadError,
    Repair,
    RotationalInertia,
    SourceLocation,
    SpatialInertia,
    UnitInertia,
    WeldedGroup,
    __version__,
    is_physically_valid,
    principal_moments,
    read,
    read_all,
    repair_inertia,
    rules,
)
from . import _massprops

__all__ = [
    "CheckOptions", "CompositeInertia", "DEFAULT_VALIDITY_TOLERANCE", "FieldChange", "Finding",
    "FixResult", "Geometry", "Inertial", "Joint", "Link", "Model", "PatchError", "Pose",
    "PrincipalSolver", "ReadError", "Repair", "RotationalInertia", "SourceLocation",
    "SpatialInertia", "UnitInertia", "WeldedGroup", "check", "diff", "fix", "identify",
    "is_physically_valid",
    "principal_moments", "read", "read_all", "repair_inertia", "report", "rules",
]

PathOrText = Union[str, bytes, "os.PathLike[str]"]


@dataclasses.dataclass
class CheckOptions:
    """Options of check(), the same as `massprops check`'s.

    tolerance: validity tolerance relative to the trace (None: the configuration file's, else
        1e-6), 0 <= tolerance < 1.
    disable: rule ids to turn off.
    severity: {rule id: 'off' | 'note' | 'warning' | 'error'}.
    config: 'auto' (the nearest .massprops.toml upward from the file's folder, else from the
        working directory, as the tool does), None (no configuration file), or a path.
    model_paths: folders searched for SDF model:// URIs (before the configuration's).
    geometry: read link geometry, meshes too (`check --geometry`).
    geometry_factor: inertia-disagrees-with-geometry threshold (> 1).
    package_paths: folders searched first for package:// mesh URIs (then the description's
        repository, an ancestor folder of that name, ROS_PACKAGE_PATH; docs/meshes.md).
    """

    tolerance: Optional[float] = None
    disable: Sequence[str] = ()
    severity: Mapping[str, str] = dataclasses.field(default_factory=dict)
    config: Optional[Union[str, "os.PathLike[str]"]] = "auto"
    model_paths: Sequence[str] = ()
    geometry: bool = False
    geometry_factor: float = 2.0
    package_paths: Sequence[str] = ()


def _strings(value: Iterable[str], name: str) -> list:
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be a list of strings, not a single string")
    items = list(value)
    for item in items:
        if not isinstance(item, str):
            raise TypeError(f"{name} must hold strings, got {type(item).__name__}")
    return items


def check(path_or_text: PathOrText, options: Optional[CheckOptions] = None, *,
          source_root: Union[None, str, "os.PathLike[str]", Sequence[str]] = None,
          xacro_args: Optional[Mapping[str, str]] = None, **kwargs) -> list:
    """Checks a URDF or SDF model and returns its findings (list of Finding).

    The findings are those `massprops check --format json FILE` reports, in the same order:
    read warnings, the reader's findings, then each model's checks. options: a CheckOptions;
    keyword arguments (tolerance=, disable=, severity=, config=, model_paths=, geometry=,
    geometry_factor=, package_paths=) override its fields. Raises massprops.ReadError when the
    file cannot be read, ValueError for an unknown rule or a bad value, TypeError for a wrong
    type.

    source_root: for an expanded xacro package, the folder(s) of its sources (as `massprops check
    --expanded FILE --source-root DIR`): each finding's `source` then says where its numbers were
    written ({file, line, how, ...}, docs/xacro.md); xacro_args: the arguments of the expansion.

    >>> for f in massprops.check("robot.urdf", disable=["units-suspect"]):
    ...     print(f.severity, f.link, f.line, f.message)
    >>> f = massprops.check("robot.urdf", source_root="robot_description")[0]
    >>> f.source["file"], f.source["line"], f.source["how"]
    """
    if options is None:
        options = CheckOptions()
    elif not isinstance(options, CheckOptions):
        raise TypeError(f"options must be a massprops.CheckOptions, got {type(options).__name__}")
    try:
        options = dataclasses.replace(options, **kwargs)
    except TypeError as error:
        raise TypeError(f"check: {error}") from None
    severity = dict(options.severity)
    return _massprops._check(
        path_or_text,
        None if options.tolerance is None else float(options.tolerance),
        _strings(options.disable, "disable"),
        severity,
        options.config,
        _strings(options.model_paths, "model_paths"),
        bool(options.geometry),
        float(options.geometry_factor),
        _strings(options.package_paths, "package_paths"),
        _source_roots(source_root),
        {str(k): str(v) for k, v in (xacro_args or {}).items()},
    )


def _source_roots(value) -> list:
    if value is None:
        return []
    if isinstance(value, (str, os.PathLike)):
        return [os.fspath(value)]
    return [os.fspath(v) for v in value]


def report(path_or_text: PathOrText, *, joints: Optional[Mapping[str, float]] = None,
           frame: str = "", only: Sequence[str] = (), subtree: str = "",
           geometry: bool = False, package_paths: Sequence[str] = (),
           model_paths: Sequence[str] = ()) -> dict:
    """The mass report (`massprops report --format json`) as Python data.

    Returns {"models": [...], "errors": []}: per model its links, welded groups and total, each
    with mass, com, inertia_about_com, principal_moments, principal_axes, equivalent_box and
    digits_lost (schema: docs/report.md). joints: {joint: value} (radians or metres; others at
    0); frame: a link whose frame expresses everything; only: these links and their groups;
    subtree: a link and its descendants. Raises ReadError (unreadable file), ValueError (a
    joint or link the model does not have).

    >>> total = massprops.report("robot.urdf")["models"][0]["total"]
    >>> total["mass"], total["com"]
    """
    return _massprops._report(
        path_or_text, dict(joints or {}), frame, _strings(only, "only"), subtree,
        bool(geometry), _strings(package_paths, "package_paths"),
        _strings(model_paths, "model_paths"))


def diff(a: Union[str, "os.PathLike[str]"], b: Union[str, "os.PathLike[str]"], *,
         tolerance: float = 1e-6, target: Optional[str] = None,
         model_paths: Sequence[str] = ()) -> dict:
    """Compares the mass properties of two descriptions of one robot: `massprops diff A B
    --format json` as Python data (equal to json.loads of its output, schema in docs/cli.md).

    Returns {"a", "b", "tolerance", "differs", "entries": [{"kind" ("link", "group" or "total"),
    "name", "a", "b", "differs", ...}]}. Each file's first model is compared. target: as
    `--target` (None: the .massprops.toml found for the file, else generic). Raises ReadError
    (a file that cannot be read or holds no model), ValueError (a negative tolerance, an
    unknown target).

    >>> result = massprops.diff("robot.urdf", "robot.xml")
    >>> [e["name"] for e in result["entries"] if e["differs"]]
    """
    return _massprops._diff(os.fspath(a), os.fspath(b), float(tolerance), target,
                            _strings(model_paths, "model_paths"))


def identify(robot: Union[str, "os.PathLike[str]"], data: Union[str, "os.PathLike[str]"], *,
             validate: float = 0.3) -> dict:
    """The mass properties a recorded trajectory proves, physically consistent: `massprops
    identify ROBOT DATA --validate V --format json` as Python data (equal to json.loads of its
    output; fields in docs/identify.md).

    robot: a URDF, SDF or MJCF file with a fixed base. data: the recording, a CSV file (`time`
    and per joint `J.q`, `J.tau`, optionally `J.dq`, `J.ddq`; or PlotJuggler's export of
    /joint_states), or a ROS 2 bag (a rosbag2 folder or .db3 file). validate: the last fraction
    of the samples held out to judge the fit, 0 to 0.9.

    Returns {"identifiability": {"rank", "parameters", "condition_number", "unexcited_links",
    "base_parameters"}, "training_samples", "validation_samples", "joints": [{"joint",
    "rms_file", "rms_least_squares", "rms_identified"}], "links": [{"link", "file",
    "identified", "least_squares_consistent", "identified_consistent", "geometry_bound",
    "ellipsoid_ratio", "least_squares_within_geometry"}], "inconsistent_least_squares_links",
    "geometry_bound_links", "least_squares_outside_geometry_links", "solver"}. Where a link's
    geometry is known, its estimate lies inside the ellipsoid bounding it (docs/identify.md).
    Raises ReadError (a file that cannot be read: the model, a missing column, NaN, time going
    back, a bag without JointState), ValueError (not a fixed-base tree, joints missing on either
    side, validate out of range, too few samples).

    >>> r = massprops.identify("arm.urdf", "log.csv")
    >>> [(j["joint"], j["rms_file"], j["rms_identified"]) for j in r["joints"]]
    """
    return _massprops._identify(os.fspath(robot), os.fspath(data), float(validate))


def _write_atomically(path: str, text: str, mode: Optional[int]) -> None:
    """Writes text to path through a temporary file in the same folder, flushed and renamed
    over path only when complete; on failure path is untouched."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".",
                               suffix=".massprops-tmp")
    try:
        with os.fdopen(fd, "wb") as out:
            out.write(text.encode("utf-8", "surrogateescape"))
            out.flush()
            os.fsync(out.fileno())
        if mode is not None:
            os.chmod(tmp, mode)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def fix(path_or_text: PathOrText, apply: Iterable[str] = (), dry_run: bool = True, *,
        output: Optional[Union[str, "os.PathLike[str]"]] = None, backup: Optional[str] = None,
        repair: str = "project", fix_units: bool = False,
        density: Union[float, Mapping[str, float]] = 1000.0,
        from_geometry: Union[bool, str, Sequence[str]] = False, tolerance: float = 1e-6,
        geometry: bool = False, package_paths: Sequence[str] = (),
        model_paths: Sequence[str] = (), total_mass: Optional[float] = None,
        mass: Mapping[str, float] = {}, material: Mapping[str, str] = {}) -> FixResult:
    """Repairs the mass properties that have a known remedy; returns a FixResult.

    Physics decides by default: every error finding with a remedy is repaired
    (inertia-not-physical, mass-not-positive, ...). A heuristic repair (a warning such as
    units-suspect, products-sign-suspect, inertia-about-origin-suspect) runs only when its rule
    id is named in `apply`. from_geometry: True (every link with usable geometry) or link names:
    replace their inertials by their geometry's (`fix --from-geometry`).

    The mass repairs of `massprops fix` (docs/fix.md), each only when given: total_mass (kg,
    `--total-mass`: every link's mass and inertia times one factor), mass ({link: kg},
    `--mass LINK=KG`), density as {link: kg/m³} (`--density LINK=RHO`; a number keeps its old
    meaning: the density of masses computed from geometry) and material ({link: name},
    `--material LINK=NAME`: aluminium-6061, steel, pla, abs, petg, nylon, carbon-fibre).

    >>> massprops.fix("arm.urdf", total_mass=10.5, mass={"tool": 6.0})

    Nothing is written unless dry_run=False: then the repaired text goes to `output` when given,
    else over the input file (through a temporary file renamed when complete, keeping the
    file's mode; with `backup`, the original is kept as FILE+backup). A file that needs no
    change is never rewritten. result.written names the file written (None otherwise).

    >>> result = massprops.fix("robot.urdf", apply=["units-suspect"])
    >>> for change in result.changes: print(change)
    >>> massprops.fix("robot.urdf", dry_run=False)     # writes robot.urdf
    """
    if isinstance(apply, str):
        apply = [a for a in apply.split(",") if a]
    link_densities: Dict[str, float] = {}
    if isinstance(density, Mapping):
        link_densities = {str(k): float(v) for k, v in density.items()}
        density = 1000.0
    result = _massprops._fix(
        path_or_text, _strings(apply, "apply"), repair, bool(fix_units), float(density),
        from_geometry, float(tolerance), bool(geometry), _strings(package_paths, "package_paths"),
        _strings(model_paths, "model_paths"),
        None if total_mass is None else float(total_mass),
        {str(k): float(v) for k, v in mass.items()}, link_densities,
        {str(k): str(v) for k, v in material.items()})
    if dry_run:
        if output is not None or backup is not None:
            raise ValueError("fix: output and backup need dry_run=False")
        return result
    if not result.reads_back:
        raise RuntimeError(f"fix: the repaired text of {result.path} does not read back; "
                           "nothing written")
    if output is not None:
        target = os.fspath(output)
        if backup is not None:
            raise ValueError("fix: backup is for writing over the input (no output)")
    else:
        if result.path == "<string>":
            raise ValueError("fix: model text has no file to write back to; give output=")
        target = os.path.realpath(result.path)
    if output is not None and not result.changed and os.path.exists(target) and \
            result.path != "<string>" and os.path.samefile(target, result.path):
        return result  # the input itself, unchanged: never rewritten
    if output is None and not result.changed:
        return result
    mode = None
    if output is None:
        mode = os.stat(target).st_mode & 0o7777
        if backup:
            _write_atomically(target + backup, result.original, mode)
    _write_atomically(target, result.text, mode)
    result.written = target
    return result
