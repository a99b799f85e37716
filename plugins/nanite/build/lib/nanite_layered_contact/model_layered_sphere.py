import lmfit

from ._force import film_force


def get_parameter_defaults():
    """Return the default model parameters"""
    # The order of the parameters must match the order
    # of ´parameter_names´ and ´parameter_keys´.
    params = lmfit.Parameters()
    params.add("E", value=3e3, min=0)
    params.add("R", value=10e-6, min=0, vary=False)
    params.add("nu", value=.5, min=0, max=0.5, vary=False)
    params.add("h", value=5e-6, min=0, vary=False)
    params.add("contact_point", value=0)
    params.add("baseline", value=0)
    return params


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
parameter_keys = ["E", "R", "nu", "h", "contact_point", "baseline"]
parameter_names = ["Young's Modulus", "Sphere Radius", "Poisson's Ratio",
                   "Film Thickness", "Contact Point", "Force Baseline"]
parameter_units = ["Pa", "m", "", "m", "m", "N"]
valid_axes_x = ["tip position"]
valid_axes_y = ["force"]
