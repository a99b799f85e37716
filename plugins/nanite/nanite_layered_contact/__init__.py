"""nanite fit models of films on a rigid support, exact (layered-contact).

Call :func:`register` once; the models then appear in
``nanite.model.models_available`` under ``layered_para``,
``layered_sphere`` and ``layered_cone``.
"""

from . import model_layered_cone, model_layered_paraboloid, model_layered_sphere

MODELS = (model_layered_paraboloid, model_layered_sphere, model_layered_cone)

__all__ = ["MODELS", "register"]


def register():
    """Register the models with nanite; returns their ``NaniteFitModel``s."""
    import nanite.model

    return [nanite.model.register_model(module) for module in MODELS]
