"""dualmech: every mechanics problem written twice -- Newton--Euler and Lagrange -- and proved equal.

The public API, in one list:
"""
from .kinematics import (Frame, Point, RelativeMotion, Vector, coordinate, rot_axis, rot_x,
                         rot_y, rot_z, skew, t)
from .bodies import (MassProperties, Particle, RigidBody, composite, cuboid, parallel_axis,
                     point_mass, solid_cylinder, solid_sphere, thin_disk, thin_rod)
from .equations import EquationSet, ModelError
from .direct import NewtonEuler
from .lagrange import Lagrangian

__all__ = [
    "Frame", "Point", "RelativeMotion", "Vector", "coordinate", "rot_axis", "rot_x", "rot_y",
    "rot_z", "skew", "t",
    "MassProperties", "Particle", "RigidBody", "composite", "cuboid", "parallel_axis",
    "point_mass", "solid_cylinder", "solid_sphere", "thin_disk", "thin_rod",
    "EquationSet", "ModelError", "NewtonEuler", "Lagrangian",
]
__version__ = "0.1.0"
