from ._force import film_force
# The sphere takes the paraboloid's parameters (a radius, the film).
from .model_layered_paraboloid import get_parameter_defaults  # noqa: F401
from .model_layered_paraboloid import parameter_keys, parameter_units  # noqa: F401


def layered_sphere(delta, E, R, nu, h, contact_point=0, baseline=0):
    r"""Sphere on a film bonded to a rigid support, exact

    The force of a sphere of radius :math:`R` (its cap, not its
    paraboloid: colloidal probes indenting to depths comparable to their
    radius) indenting a film of thickness :math:`h` bonded to glass, from the exact solution of the
    axisymmetric contact problem of the layered body (layered-contact);
    on a half-space it is Sneddon's sphere. The contact radius must stay
    below 0.95 :math:`R`.

    Parameters
    ----------
    delta: 1d ndarray
        Indentation [m]
    E: float
        Young's modulus of the film [N/m²]
    R: float
        Sphere radius [m]
    nu: float
        Poisson's ratio of the film
    h: float
        Film thickness [m]
    contact_point: float
        Indentation offset [m]
    baseline: float
        Force offset [N]

    Returns
    -------
    F: float
        Force [N]

    References
    ----------
    layered-contact ``analytic::Axisymmetric``; the series and where
    Dimitriadis et al. (2002) leave it: its ``doc::bottom_effect``.
    """
    return film_force("sphere", delta, E, nu, h, contact_point, baseline, radius=R)


model_doc = layered_sphere.__doc__
model_func = layered_sphere
model_key = "layered_sphere"
model_name = "sphere on a film on glass (exact, layered-contact)"
parameter_names = ["Young's Modulus", "Sphere Radius", "Poisson's Ratio",
                   "Film Thickness", "Contact Point", "Force Baseline"]
valid_axes_x = ["tip position"]
valid_axes_y = ["force"]
