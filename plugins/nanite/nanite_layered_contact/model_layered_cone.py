import lmfit
import numpy as np

from ._force import film_force


def get_parameter_defaults():
    """Return the default model parameters"""
    # The order of the parameters must match the order
    # of ´parameter_names´ and ´parameter_keys´.
    params = lmfit.Parameters()
    params.add("E", value=3e3, min=0)
    params.add("alpha", value=25, min=0, max=90, vary=False)
    params.add("nu", value=.5, min=0, max=0.5, vary=False)
    params.add("h", value=5e-6, min=0, vary=False)
    params.add("contact_point", value=0)
    params.add("baseline", value=0)
    return params


def layered_cone(delta, E, alpha, nu, h, contact_point=0, baseline=0):
    r"""Cone on a film bonded to a rigid support, exact

    The force of a cone of half-angle :math:`\alpha` indenting a film of
    thickness :math:`h` bonded to glass, from the exact solution of the
    axisymmetric contact problem of the layered body (layered-contact); on
    a half-space it is Sneddon's

    .. math::

        F = \frac{2}{\pi} \frac{E}{1-\nu^2} \tan\alpha \, \delta^2.

    Parameters
    ----------
    delta: 1d ndarray
        Indentation [m]
    E: float
        Young's modulus of the film [N/m²]
    alpha: float
        Half cone angle [degrees]
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
    Sneddon (1965); layered-contact ``analytic::Tip::Cone``.
    """
    return film_force("cone", delta, E, nu, h, contact_point, baseline,
                      half_angle=np.radians(alpha))


model_doc = layered_cone.__doc__
model_func = layered_cone
model_key = "layered_cone"
model_name = "cone on a film on glass (exact, layered-contact)"
parameter_keys = ["E", "alpha", "nu", "h", "contact_point", "baseline"]
parameter_names = ["Young's Modulus", "Half Cone Angle", "Poisson's Ratio",
                   "Film Thickness", "Contact Point", "Force Baseline"]
parameter_units = ["Pa", "°", "", "m", "m", "N"]
valid_axes_x = ["tip position"]
valid_axes_y = ["force"]
