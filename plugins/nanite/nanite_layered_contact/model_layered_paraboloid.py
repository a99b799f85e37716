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


def layered_paraboloid(delta, E, R, nu, h, contact_point=0, baseline=0):
    r"""Paraboloid on a film bonded to a rigid support, exact

    The force of a paraboloid of tip radius :math:`R` indenting a film of
    thickness :math:`h` bonded to glass, from the exact solution of the
    axisymmetric contact problem of the layered body (a Fredholm equation
    of the second kind, solved to 1e-10 by layered-contact), not a
    truncated bottom-effect series. For :math:`\delta \ll h` it is Hertz's

    .. math::

        F = \frac{4}{3} \frac{E}{1-\nu^2} \sqrt{R} \delta^{3/2}
            \left(1 + c\chi + \frac{7}{6}c^2\chi^2 + \dots\right),
        \quad \chi = \frac{\sqrt{R\delta}}{h},

    with :math:`c = 2 a_0/\pi` (1.1270 at :math:`\nu = 0.5`); at any depth
    it is exact.

    Parameters
    ----------
    delta: 1d ndarray
        Indentation [m]
    E: float
        Young's modulus of the film [N/m²]
    R: float
        Tip radius [m]
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
    return film_force("paraboloid", delta, E, nu, h, contact_point, baseline, radius=R)


model_doc = layered_paraboloid.__doc__
model_func = layered_paraboloid
model_key = "layered_para"
model_name = "paraboloid on a film on glass (exact, layered-contact)"
parameter_keys = ["E", "R", "nu", "h", "contact_point", "baseline"]
parameter_names = ["Young's Modulus", "Tip Radius", "Poisson's Ratio",
                   "Film Thickness", "Contact Point", "Force Baseline"]
parameter_units = ["Pa", "m", "", "m", "m", "N"]
valid_axes_x = ["tip position"]
valid_axes_y = ["force"]
