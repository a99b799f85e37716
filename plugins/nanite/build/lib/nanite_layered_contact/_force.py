"""The force of a tip on a film, through layered_contact.fit's exact tables,
cached per tip and film (the tables do not depend on the modulus)."""

from collections import OrderedDict

import numpy as np

from layered_contact.fit import CurveModel, Sample

# Tables kept (each a few hundred exact states).
_CACHED = 32
_MODELS: "OrderedDict[tuple, CurveModel]" = OrderedDict()


def film_force(tip, delta, E, nu, h, contact_point, baseline, radius=None, half_angle=None):
    """Force (N) at tip positions ``delta`` (m, nanite's sign: indentation
    is ``contact_point - delta``) of a ``tip`` on a film of modulus ``E``
    (Pa), Poisson ratio ``nu`` and thickness ``h`` (m) bonded to glass."""
    indentation = contact_point - np.asarray(delta, dtype=float)
    deepest = float(np.max(indentation, initial=0.0))
    key = (tip, radius, half_angle, nu, h)
    model = _MODELS.get(key)
    if model is None or model.max_depth < deepest:
        # Room to move the contact point without rebuilding at every step.
        reach = 1.5 * max(deepest, 1e-3 * h)
        model = CurveModel(tip, radius, Sample(thickness=h, poisson_ratio=nu), reach,
                           half_angle=half_angle)
        _MODELS[key] = model
        while len(_MODELS) > _CACHED:
            _MODELS.popitem(last=False)
    _MODELS.move_to_end(key)
    return model.force(indentation, E) + baseline
