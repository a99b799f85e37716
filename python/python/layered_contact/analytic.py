"""Closed forms and exact axisymmetric solutions, vectorised over NumPy
arrays (scalars in, floats out).

Hertz (1882) and Johnson, Kendall & Roberts (1971) on a half-space; the
exact flat-punch stiffness and paraboloid pull-off on any substrate from the
axisymmetric integral equation of the Rust crate (``analytic::Axisymmetric``).
"""

from __future__ import annotations

from typing import Any, Tuple, Union

import numpy as np

from . import _native
from ._native import ForceCurve, InvalidInputError, Material, Substrate

ArrayLike = Union[float, "np.typing.ArrayLike"]

__all__ = [
    "DIMITRIADIS_BONDED",
    "ForceCurve",
    "bottom_effect_series",
    "flat_punch_pull_off_force",
    "flat_punch_stiffness",
    "hertz_contact_radius",
    "hertz_force",
    "jkr_pull_off_force",
    "jkr_sinusoid_pull_off",
    "jkr_state",
    "paraboloid_pull_off_force",
    "paraboloid_state",
    "tip_pressure",
    "tip_pull_off",
]


# The most values one call takes (as the native layer): a broadcast view of
# one value can claim billions, and copying it would exhaust memory.
_MAX_VALUES = 2**27


def _array(x: ArrayLike) -> np.ndarray:
    values = np.asarray(x, dtype=np.float64)
    if values.size > _MAX_VALUES:
        raise InvalidInputError(
            f"the array has shape {values.shape}: at most 2^27 values per call (split it)"
        )
    return np.ascontiguousarray(values)


def _out(result: np.ndarray, x: ArrayLike) -> Any:
    return float(result.reshape(-1)[0]) if np.ndim(x) == 0 else result.reshape(np.shape(x))


def hertz_force(material: Material, radius: float, depth: ArrayLike) -> Any:
    """Hertz: ``F = 4/3 E* sqrt(R) d^(3/2)`` (N) of a paraboloid of tip
    radius ``radius`` (m) at ``depth`` (m) on a half-space."""
    return _out(_native.hertz_force(material, radius, _array(depth)), depth)


def hertz_contact_radius(material: Material, radius: float, depth: ArrayLike) -> Any:
    """Hertz: ``a = sqrt(R d)`` (m)."""
    return _out(_native.hertz_contact_radius(material, radius, _array(depth)), depth)


def jkr_state(
    material: Material, radius: float, work_of_adhesion: float, contact_radius: ArrayLike
) -> Tuple[Any, Any]:
    """JKR: ``(force, depth)`` (N, m) at ``contact_radius`` (m) for a
    paraboloid on a half-space with work of adhesion ``work_of_adhesion``
    (J/m^2)."""
    force, depth = _native.jkr_state(material, radius, work_of_adhesion, _array(contact_radius))
    return _out(force, contact_radius), _out(depth, contact_radius)


def jkr_pull_off_force(material: Material, radius: float, work_of_adhesion: float) -> float:
    """JKR: pull-off force under load control, ``-3/2 pi R w`` (N)."""
    return _native.jkr_pull_off_force(material, radius, work_of_adhesion)


def flat_punch_stiffness(substrate: Substrate, radius: ArrayLike) -> Any:
    """Exact stiffness ``dF/dd`` (N/m) of a bonded flat punch of radius
    ``radius`` (m) on ``substrate`` (``2 E* a`` on a half-space)."""
    return _out(_native.flat_punch_stiffness(substrate, _array(radius)), radius)


def paraboloid_pull_off_force(
    substrate: Substrate, radius: float, work_of_adhesion: float
) -> float:
    """Exact load-controlled pull-off force (N) of a paraboloid of tip radius
    ``radius`` (m) on ``substrate`` (JKR's on a half-space)."""
    return _native.paraboloid_pull_off_force(substrate, radius, work_of_adhesion)


def paraboloid_state(
    substrate: Substrate, radius: float, work_of_adhesion: float, contact_radius: ArrayLike
) -> Tuple[Any, Any]:
    """Exact ``(force, depth)`` (N, m) of a paraboloid of tip radius
    ``radius`` (m) on ``substrate`` at ``contact_radius`` (m), with work of
    adhesion ``work_of_adhesion`` (J/m^2, 0 for none): Hertz and JKR on a
    half-space, their exact counterparts on a coated body."""
    force, depth = _native.paraboloid_state(substrate, radius, work_of_adhesion, _array(contact_radius))
    return _out(force, contact_radius), _out(depth, contact_radius)


def flat_punch_pull_off_force(substrate: Substrate, radius: float, work_of_adhesion: float) -> float:
    """Exact pull-off force (N) of a bonded flat punch of radius ``radius``
    (m) on ``substrate`` (Kendall's ``-sqrt(8 pi a^3 E* w)`` on a
    half-space)."""
    return _native.flat_punch_pull_off_force(substrate, radius, work_of_adhesion)


def jkr_sinusoid_pull_off(
    material: Material, wavelength: float, amplitude: float, work_of_adhesion: float
) -> Tuple[float, float]:
    """Johnson (1995): the pull-off mean pressure (Pa, negative) and contact
    half-width (m) of an adhesive wavy surface ``z = g (1 - cos(2 pi x /
    lambda))`` on a half-space, plane strain, JKR limit."""
    return _native.jkr_sinusoid_pull_off(material, wavelength, amplitude, work_of_adhesion)


def tip_pull_off(
    substrate: Substrate,
    tip: str,
    work_of_adhesion: float,
    *,
    radius: float = float("nan"),
    half_angle: float = float("nan"),
    spring: "float | None" = None,
) -> dict:
    """Exact pull-offs of an axisymmetric ``tip`` (``"paraboloid"``,
    ``"sphere"``, ``"cone"``, ``"rounded_cone"``; ``radius`` m, the apex's
    for the rounded cone, and ``half_angle`` rad for cones) with work of
    adhesion ``work_of_adhesion`` (J/m^2) on ``substrate``: a dict of
    ``{"force", "depth", "contact_radius"}`` (N, m, m) under
    ``load_control`` and ``displacement_control`` and, on a cantilever of
    stiffness ``spring`` (N/m), where it jumps off (``spring_pull_off``,
    the least position of the cantilever's base ``d + F/k``, where
    ``dF/dd = -k``) and where it lands when brought to touch
    (``spring_jump_in``, the first contact radius where ``F + k d = 0``)."""
    return _native.tip_pull_off(
        substrate, tip, radius, work_of_adhesion, half_angle=half_angle, spring=spring
    )


def tip_pressure(
    substrate: Substrate,
    tip: str,
    contact_radius: float,
    r: ArrayLike,
    *,
    radius: float = float("nan"),
    half_angle: float = float("nan"),
    work_of_adhesion: float = 0.0,
) -> Tuple[Any, float]:
    """Exact pressure (Pa, compressive positive) at radii ``r`` (m) under an
    axisymmetric ``tip`` (as :func:`tip_pull_off`) on ``substrate`` at its
    equilibrium of contact radius ``contact_radius`` (m), with work of
    adhesion ``work_of_adhesion`` (J/m^2, 0 for none), and the least
    pressure over that disc divided by its mean. A negative least pressure
    without adhesion means the disc pulls on the tip inside: a stiff layer
    on a far softer base lifts off the tip's middle, the contact is a ring,
    and the disc's solution is not the contact's (scenes then have no exact
    values)."""
    pressure, least = _native.tip_pressure(
        substrate,
        tip,
        radius,
        work_of_adhesion,
        contact_radius,
        _array(r),
        half_angle=half_angle,
    )
    return _out(pressure, r), least


#: Dimitriadis et al. (2002), bonded layer, nu = 0.5: the coefficients of
#: ``chi`` to ``chi^4`` in ``F / F_Hertz`` that AFM software fits (see
#: :func:`bottom_effect_series` for the exact ones).
DIMITRIADIS_BONDED = (1.133, 1.283, 0.769, 0.0975)


def bottom_effect_series(poisson_ratio: float) -> Tuple[float, float, float, float]:
    """The exact small-indentation series of a paraboloid on a layer of
    Poisson ratio ``poisson_ratio`` bonded to a rigid base: the coefficients
    of ``chi``, ``chi^2``, ``chi^3``, ``chi^4`` in ``F / F_Hertz`` with
    ``chi = sqrt(R d)/h`` (1.1270, 1.4817, 1.4700, 1.0047 at 0.5; the
    crate's ``doc::bottom_effect`` compares them with Dimitriadis')."""
    return tuple(_native.paraboloid_series(poisson_ratio))
