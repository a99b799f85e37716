"""Contact mechanics of coated elastic bodies.

Rigid indenters (flat punches, spheres, paraboloids, cones, any height map)
pressed into an elastic half-space or an elastic layer bonded to a rigid or
elastic base, with and without JKR-limit adhesion: a boundary-element solver,
exact axisymmetric solutions and scenes (whole loading cycles), from the
Rust crate ``layered-contact``.

Units are SI. Depth ``d > 0`` presses in, pressure ``p > 0`` compresses,
adhesive forces are negative. Field arrays are ``rows x columns`` with
``[i, j]`` at ``(x[i], y[j])``, the cell centres in metres from the
indenter's axis.

>>> import layered_contact as lc
>>> rubber = lc.Material(1e6, 0.5)
>>> solver = lc.ContactSolver(lc.Substrate.half_space(rubber), 64, 64, 2e-5)
>>> s = solver.solve_depth(lc.Indenter.paraboloid(0.01), 1e-5)
>>> round(s.force / lc.analytic.hertz_force(rubber, 0.01, 1e-5), 2)
1.0
"""

from __future__ import annotations

import os
from typing import Any, Callable, Mapping, Optional, Union

import numpy as np
import numpy.typing as npt

from . import analytic
from ._native import refine_heights, rough_surface_heights, subsurface_stress
from .rough import interface_curve
from .stress import plot_section
from ._native import (
    CohesivePullOff,
    CohesiveZoneWarning,
    ConvergenceError,
    ContactSolver,
    Curve,
    EdgeContactWarning,
    Indenter,
    InvalidInputError,
    LayeredContactError,
    Material,
    Solution,
    Substrate,
)
from ._native import check_scene as _check_scene
from ._native import edge_release as _edge_release
from ._native import peel_punch as _peel_punch
from ._native import run_scene as _run_scene
from ._native import scene_reference as _scene_reference
from ._native import scene_schema as _scene_schema

SceneLike = Union[Mapping[str, Any], str, "os.PathLike[str]"]

__all__ = [
    "CohesivePullOff",
    "CohesiveZoneWarning",
    "ConvergenceError",
    "ContactSolver",
    "Curve",
    "EdgeContactWarning",
    "Indenter",
    "InvalidInputError",
    "LayeredContactError",
    "Material",
    "Solution",
    "Substrate",
    "analytic",
    "check_scene",
    "curve_table",
    "curve_to_dict",
    "edge_release",
    "peel_punch",
    "plot_curve",
    "plot_field",
    "plot_section",
    "refine_heights",
    "rough_surface_heights",
    "run_scene",
    "scene_reference",
    "scene_schema",
    "subsurface_stress",
    "write_curve_csv",
    "interface_curve",
]


def _scene(scene: SceneLike) -> Any:
    if isinstance(scene, Mapping):
        return dict(scene)
    return os.fspath(scene)


def edge_release(
    solver: ContactSolver,
    indenter: Indenter,
    depth: float,
    contact: Any,
    window: float = 8.0,
) -> dict:
    """The local Griffith criterion: the energy release rate along the edge
    of ``contact`` (a boolean array of the solver's ``rows x columns``
    cells, held bonded to ``indenter`` at ``depth``, m), smoothed along the
    edge over ``window`` cells; the edge of one digital ellipse on a
    half-space (or disc on any body) under a planar face (a flat punch,
    tilted or not) or a quadratic one (a paraboloid) on an isolated grid is
    fitted instead in the five (nine) functions where the release rate lies
    exactly (Galin's pressure; on a disc the angular modes 0 to 2 (4)).

    Returns a dict of arrays over the edge cells: ``row``, ``column``,
    ``x``, ``y`` (m), ``normal_x``, ``normal_y`` (outward), ``release_rate``
    (J/m^2) and ``stress_intensity`` (Pa m^1/2, positive where the edge
    pulls), and the floats ``force`` (N) and ``depth`` (m); ``fit`` is
    ``"modes"`` (``fit_functions`` 5 or 9) where the rates were fitted over
    the whole edge, ``"window"`` (0) where smoothed by the window. The edge
    starts to detach where ``release_rate`` first reaches the work of
    adhesion."""
    import numpy as np

    mask = np.ascontiguousarray(np.asarray(contact, dtype=bool))
    return _edge_release(solver, indenter, depth, mask, window)


def peel_punch(
    solver: ContactSolver,
    indenter: Indenter,
    work_of_adhesion: float,
    bonded: Optional[npt.NDArray[np.bool_]] = None,
) -> dict:
    """The pull-off of a flat punch, tilted or not, bonded over its whole face
    (the cells ``indenter`` reaches, ending at a rim inside the grid), or
    over ``bonded`` (a boolean ``rows x columns`` mask of face cells: a face
    bonded in part, such as a tilted face pressed in to where its contact
    reaches the rim on one side), by the local Griffith criterion along its
    peeling path: each contact's critical depth and force, where its first
    edge cell releases the work of adhesion, then the edge cells near it
    peeled, to the last few cells. A pull-off held by a remnant of less
    than a sixteenth of the start's cells or of 64 cells is refused as
    unresolved (``LayeredContactError``: refine the grid).

    Returns a dict of arrays over the path's contacts: ``depth`` (m) and
    ``force`` (N) at which each comes off, ``stiffness`` (N/m, its bonded
    ``dF/dd``), ``contact_cells``,
    ``contact_area`` (m^2), ``peels_x``, ``peels_y`` (m, where it peels
    next), ``fitted_by_modes`` (whether that contact's release rates were
    fitted over its whole edge, a disc's or an ellipse's, rather than
    smoothed by the window); and ``pull_off_force``, ``pull_off_depth`` (the most tensile
    force along the path: the pull-off under force control),
    ``jump_off_depth``, ``jump_off_force`` (under fixed grips),
    ``detaches_at_onset`` (a disc: True; a punch with corners comes off
    later) and ``iterations``."""
    return _peel_punch(solver, indenter, work_of_adhesion, bonded)


def run_scene(
    scene: SceneLike,
    progress: Optional[Callable[[dict], None]] = None,
    indenter: Optional[Indenter] = None,
    iteration: Optional[Callable[[dict], None]] = None,
) -> Curve:
    """Run a scene: a dict with the structure of a scene file, or the path
    of a TOML or JSON scene file (height-map paths relative to it).

    ``progress(step)`` is called after each step with a dict (``phase``,
    ``depth`` m, ``force`` N, ``contact_area`` m^2, ``contact_radius`` m,
    ``iterations``). ``iteration(info)`` is called with a dict
    (``iteration``, ``residual``, ``contact_cells``) for every iteration of
    the inner solves; with the energy-balance adhesion (the default) once
    per contact set of the family it builds before any step (the steps then
    come at once), so that progress shows during that build. An exception
    either raises (or Ctrl-C) stops reporting and is raised when the run
    returns. ``indenter`` replaces the scene's indenter by any
    :class:`Indenter`; the grid then spans its bounding radius with
    ``resolution.cells_across`` cells across its diameter.
    """
    return _run_scene(_scene(scene), progress, indenter, iteration)


def check_scene(scene: SceneLike) -> dict:
    """Validate a scene without solving it: the grid it is solved on and
    the memory it needs, as a dict (``rows``, ``columns``, ``spacing``,
    ``memory_bytes``)."""
    rows, columns, spacing, memory = _check_scene(_scene(scene))
    return {"rows": rows, "columns": columns, "spacing": spacing, "memory_bytes": memory}


def scene_reference(scene: SceneLike) -> dict:
    """The exact values of the scene's results where they exist (untilted
    flat punch, paraboloid, sphere or cone on an isolated grid): a dict from
    ``stiffness``, ``peak_force``, ``peak_contact_radius``,
    ``pull_off_force`` to values."""
    return _scene_reference(_scene(scene))


def scene_schema() -> dict:
    """The JSON Schema of a scene (draft 2020-12), as a dict: every key
    with its type, default and description (units included). Validate a
    scene dict with any JSON Schema tool, e.g.
    ``jsonschema.validate(scene, layered_contact.scene_schema())``."""
    import json

    return json.loads(_scene_schema())


CURVE_COLUMNS = (
    ("phase", ""),
    ("depth", "m"),
    ("force", "N"),
    ("contact_area", "m^2"),
    ("contact_radius", "m"),
    ("iterations", ""),
)


def curve_table(curve: Curve) -> dict:
    """The steps of a curve as columns of equal length (``phase``,
    ``depth`` m, ``force`` N, ``contact_area`` m^2, ``contact_radius`` m,
    ``iterations``): ``pandas.DataFrame(curve_table(curve))`` is a table of
    it."""
    return {name: getattr(curve, name) for name, _ in CURVE_COLUMNS}


def write_curve_csv(curve: Curve, path: "os.PathLike[str] | str") -> None:
    """Writes the steps of a curve as CSV, one row per step, with the units
    in the header (``depth_m``, ``force_N``, ...) as the tool's curve.csv,
    every number in the shortest digits that read back exactly."""
    import csv

    table = curve_table(curve)
    header = [f"{name}_{unit.replace('^', '')}" if unit else name for name, unit in CURVE_COLUMNS]
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        for row in zip(*(table[name] for name, _ in CURVE_COLUMNS)):
            writer.writerow([v if isinstance(v, (str, int)) else repr(float(v)) for v in row])


def plot_curve(curve: Curve, ax: Any = None, unit: float = 1e-6) -> Any:
    """Force against depth, the loading and unloading phases in their own
    colours and the pull-off marked (matplotlib, an optional dependency).
    Depths are plotted in ``unit`` metres (micrometres by default), forces
    in newtons. Returns the axes."""
    import matplotlib.pyplot as plt

    import numpy as np

    if ax is None:
        _, ax = plt.subplots()
    phase = np.asarray(curve.phase)
    depth = np.asarray(curve.depth) / unit
    force = np.asarray(curve.force)
    for name in ("loading", "unloading"):
        chosen = phase == name
        if chosen.any():
            ax.plot(depth[chosen], force[chosen], ".-", label=name)
    if curve.pull_off is not None:
        ax.plot(curve.pull_off["depth"] / unit, curve.pull_off["force"], "kx", ms=9,
                label=f"pull-off {curve.pull_off['force']:.4g} N")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel(f"depth [{unit:g} m]")
    ax.set_ylabel("force [N]")
    ax.set_title(repr(curve), fontsize=9)
    ax.legend()
    return ax


FIELD_UNITS = {"pressure": "Pa", "displacement": "m", "gap": "m"}


def plot_field(solution: Solution, field: str = "pressure", ax: Any = None) -> Any:
    """Draws one field of a :class:`Solution` (``pressure`` Pa,
    ``displacement`` or ``gap`` m; a curve's is ``curve.peak``) on the cell
    centres, ``x`` (the rows) upwards and ``y`` (the columns) across, in
    millimetres, with a colour bar in the field's unit (matplotlib, an
    optional dependency). Returns the axes."""
    import matplotlib.pyplot as plt

    import numpy as np

    if field not in FIELD_UNITS:
        raise ValueError(f"field {field!r}: expected one of {sorted(FIELD_UNITS)}")
    values = getattr(solution, field)
    if values is None:
        raise ValueError(f"the solution carries no {field}: ask for it in outputs.fields")
    values = np.asarray(values)
    if ax is None:
        _, ax = plt.subplots()
    x, y = np.asarray(solution.x) * 1e3, np.asarray(solution.y) * 1e3
    # Cells where the indenter cannot reach have an infinite gap.
    mesh = ax.pcolormesh(y, x, np.ma.masked_invalid(values), shading="nearest")
    ax.set_aspect("equal")
    ax.set_xlabel("y [mm]")
    ax.set_ylabel("x [mm]")
    ax.set_title(f"{field} at depth {solution.depth:.4g} m, force {solution.force:.4g} N", fontsize=9)
    ax.figure.colorbar(mesh, ax=ax, label=f"{field} [{FIELD_UNITS[field]}]")
    return ax


def curve_to_dict(curve: Curve) -> dict:
    """A curve as plain Python and NumPy values (for sweeps that want no
    ``layered_contact`` objects; a ``Curve`` itself pickles too)."""
    return {
        "phase": list(curve.phase),
        "depth": curve.depth,
        "force": curve.force,
        "contact_area": curve.contact_area,
        "contact_radius": curve.contact_radius,
        "iterations": list(curve.iterations),
        "stiffness": curve.stiffness,
        "pull_off": curve.pull_off,
        "grid": curve.grid,
    }
