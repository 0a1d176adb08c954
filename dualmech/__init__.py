"""dualmech: every mechanics problem written twice -- Newton--Euler and Lagrange -- and proved equal.

The public API, in one list (``__all__``).  Names are imported when first used, so the
``dualmech`` command starts without loading sympy for work that does not need it
(``dualmech list`` reads declarations only).
"""
from importlib import import_module

_HOME = {
    "model.kinematics": ("Frame", "Point", "RelativeMotion", "Vector", "coordinate", "rot_axis",
                   "rot_x", "rot_y", "rot_z", "skew", "t"),
    "model.bodies": ("MassProperties", "Particle", "RigidBody", "composite", "cuboid",
               "parallel_axis", "point_mass", "solid_cylinder", "solid_sphere", "thin_disk",
               "thin_rod"),
    "model.equations": ("EquationSet", "ModelError"),
    "model.direct": ("NewtonEuler",),
    "model.lagrange": ("Lagrangian",),
}
_WHERE = {name: module for module, names in _HOME.items() for name in names}

__all__ = [name for names in _HOME.values() for name in names]
__version__ = "0.2.0"


def __getattr__(name):
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module 'dualmech' has no attribute {name!r}")
    value = getattr(import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(list(globals()) + __all__)
