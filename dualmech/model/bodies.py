"""Particles, rigid bodies, standard inertias, the parallel-axis theorem and composites.

Inertia tensors are 3x3 matrices of components in a body's own frame, about its mass centre
unless a function says otherwise.

Example
-------
The rod + disk pendulum of MIT 2.003J quiz 2: a thin rod (mass m, length 4r) hanging from A
along ``-j``, a thin disk (mass 2m, radius r, face in the plane of motion) centred 5r below A.

>>> import sympy as sp
>>> from dualmech.model.bodies import thin_rod, thin_disk, composite
>>> m, r = sp.symbols("m r", positive=True)
>>> total = composite([(m, thin_rod(m, 4*r, axis="y"), sp.Matrix([0, -2*r, 0])),
...                    (2*m, thin_disk(2*m, r, normal="z"), sp.Matrix([0, -5*r, 0]))])
>>> total.mass, total.center.T
(3*m, Matrix([[0, -4*r, 0]]))
>>> (total.inertia_about(sp.zeros(3, 1)) / (m*r**2)).applyfunc(sp.simplify)
Matrix([
[335/6,   0,     0],
[    0, 1/2,     0],
[    0,   0, 169/3]])
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable

import sympy as sp

from dualmech.model._algebra import merge_names, names_of, to_se
from dualmech.model._expr import as_expr, as_matrix, refuse_text, refuse_text_in
from dualmech.model.kinematics import Frame, Point, Vector

__all__ = [
    "Particle", "RigidBody", "MassProperties", "parallel_axis", "composite",
    "point_mass", "thin_rod", "thin_disk", "solid_cylinder", "solid_sphere", "cuboid",
]

_AXES = {"x": 0, "y": 1, "z": 2}


def _axis(name: str) -> int:
    try:
        return _AXES[name]
    except KeyError:
        raise ValueError(f"`axis` must be one of 'x', 'y', 'z', got {name!r}.") from None


def _diag_about(axis: int, along, across) -> sp.Matrix:
    d = [across] * 3
    d[axis] = along
    return sp.diag(*d)


@refuse_text
def point_mass(m) -> sp.Matrix:
    """Inertia of a point mass about itself: zero."""
    return sp.zeros(3, 3)


@refuse_text
def thin_rod(m, length, axis: str = "z") -> sp.Matrix:
    """Thin rod of mass ``m`` along ``axis``, about its centre: ``m L^2/12`` across, 0 along."""
    return _diag_about(_axis(axis), 0, m * length**2 / 12)


@refuse_text
def thin_disk(m, radius, normal: str = "z") -> sp.Matrix:
    """Thin disk with its face normal along ``normal``: ``m r^2/2`` about the normal, ``m r^2/4`` across."""
    return _diag_about(_axis(normal), m * radius**2 / 2, m * radius**2 / 4)


@refuse_text
def solid_cylinder(m, radius, length, axis: str = "z") -> sp.Matrix:
    """Solid cylinder: ``m r^2/2`` about its axis, ``m(3r^2 + L^2)/12`` across."""
    return _diag_about(_axis(axis), m * radius**2 / 2, m * (3 * radius**2 + length**2) / 12)


@refuse_text
def solid_sphere(m, radius) -> sp.Matrix:
    """Solid sphere: ``2 m r^2 / 5`` about every axis."""
    return sp.eye(3) * sp.Rational(2, 5) * m * radius**2


@refuse_text
def cuboid(m, a, b, c) -> sp.Matrix:
    """Solid box with edges ``a, b, c`` along x, y, z."""
    return sp.diag(m * (b**2 + c**2), m * (a**2 + c**2), m * (a**2 + b**2)) / 12


@refuse_text
def parallel_axis(inertia_c: sp.Matrix, mass, d: sp.Matrix) -> sp.Matrix:
    """Inertia about a point B from the inertia about the mass centre C; ``d`` is ``C - B``.

    ``I_B = I_C + m (|d|^2 1 - d d^T)``, all components in one frame.
    """
    d = sp.Matrix(d)
    return sp.Matrix(inertia_c) + mass * ((d.T * d)[0, 0] * sp.eye(3) - d * d.T)


@refuse_text_in
@dataclass(frozen=True)
class MassProperties:
    """Mass, mass centre and inertia about the mass centre of a (composite) body.

    Made by :func:`composite`; components are in the one frame the parts were given in.

    Examples
    --------
    Two point masses ``m`` at ``x = 0`` and ``x = L``:

    >>> import sympy as sp
    >>> from dualmech import composite, point_mass
    >>> m, L = sp.symbols("m L", positive=True)
    >>> body = composite([(m, point_mass(m), [0, 0, 0]), (m, point_mass(m), [L, 0, 0])])
    >>> body.mass, body.center.T, body.inertia[2, 2]
    (2*m, Matrix([[L/2, 0, 0]]), L**2*m/2)
    """

    mass: sp.Expr
    center: sp.Matrix = field(compare=False)
    inertia: sp.Matrix = field(compare=False)

    def inertia_about(self, point: sp.Matrix) -> sp.Matrix:
        """Inertia about ``point`` (components in the same frame as ``center``)."""
        return parallel_axis(self.inertia, self.mass, self.center - sp.Matrix(point))


@refuse_text
def composite(parts: Iterable[tuple]) -> MassProperties:
    """Combine parts ``(mass, inertia about own centre, centre position)`` into one body.

    All positions and inertias are components in one common frame.
    """
    parts = [(as_expr(m), sp.Matrix(I), sp.Matrix(c)) for m, I, c in parts]
    if not parts:
        raise ValueError("`parts` must hold at least one (mass, inertia, centre) triple.")
    mass = sp.Add(*[m for m, _, _ in parts])
    center = sum((m * c for m, _, c in parts), sp.zeros(3, 1)) / mass
    center = center.applyfunc(sp.simplify)
    inertia = sum((parallel_axis(I, m, c - center) for m, I, c in parts), sp.zeros(3, 3))
    return MassProperties(mass, center, inertia.applyfunc(sp.simplify))


@refuse_text_in
@dataclass(frozen=True, eq=False)
class Particle:
    """A point mass ``mass`` at ``point``: no inertia, no rotation (model no more than needed).

    Examples
    --------
    >>> import sympy as sp
    >>> from dualmech import Frame, Particle, Point, coordinate, rate
    >>> x = coordinate("x"); m = sp.Symbol("m", positive=True)
    >>> O = Frame.ground()
    >>> block = Particle("block", m, Point.origin(O).locate("block", x * O.x))
    >>> block.kinetic_energy(O) == m * rate(x)**2 / 2
    True
    """

    name: str
    mass: sp.Expr
    point: Point

    @property
    def masscenter(self) -> Point:
        return self.point

    def linear_momentum(self, frame: Frame) -> Vector:
        return self.mass * self.point.vel(frame)

    def angular_momentum(self, about: Point, frame: Frame) -> Vector:
        """``h_B = r_BC x m v_C`` (absolute velocity)."""
        return self.point.pos_from(about).cross(self.linear_momentum(frame))

    def kinetic_energy(self, frame: Frame) -> sp.Expr:
        v = self.point.vel(frame)
        return self.mass * v.dot(v) / 2


@refuse_text_in
@dataclass(frozen=True, eq=False)
class RigidBody:
    """A rigid body fixed in ``frame``: mass centre ``masscenter``, ``inertia`` about it.

    ``inertia`` is the 3x3 inertia matrix about the mass centre in ``frame``'s axes
    (:func:`thin_rod`, :func:`thin_disk`, :func:`solid_cylinder`, :func:`solid_sphere`,
    :func:`cuboid`, :func:`composite` give the standard ones).

    Examples
    --------
    A uniform rod of length ``L`` hinged at one end: ``T = m L^2 theta'^2 / 6``.

    >>> import sympy as sp
    >>> from dualmech import Frame, Point, RigidBody, coordinate, rate, rot_z, thin_rod
    >>> theta = coordinate("theta"); m, L = sp.symbols("m L", positive=True)
    >>> O = Frame.ground(); rod = O.child("rod", rot_z(theta))
    >>> G = Point.origin(O).locate("G", L / 2 * rod.x)
    >>> body = RigidBody("rod", m, G, rod, thin_rod(m, L, axis="x"))
    >>> sp.simplify(body.kinetic_energy(O) - m * L**2 * rate(theta)**2 / 6)
    0
    """

    name: str
    mass: sp.Expr
    masscenter: Point
    frame: Frame
    inertia: sp.Matrix = field(compare=False)

    def __post_init__(self):
        I = as_matrix(self.inertia)
        if I.shape != (3, 3):
            raise ValueError(f"the inertia of body `{self.name}` must be 3x3, got {I.shape}.")
        if (I - I.T).applyfunc(sp.expand) != sp.zeros(3, 3):
            raise ValueError(f"the inertia of body `{self.name}` must be symmetric.")
        object.__setattr__(self, "inertia", I)

    def linear_momentum(self, frame: Frame) -> Vector:
        return self.mass * self.masscenter.vel(frame)

    def angular_velocity(self, frame: Frame) -> Vector:
        return self.frame.ang_vel_in(frame)

    def inertia_about(self, point: Point) -> sp.Matrix:
        """Inertia about ``point`` in body-frame components (parallel-axis theorem)."""
        d = self.masscenter.pos_from(point).express(self.frame).components
        return parallel_axis(self.inertia, self.mass, d)

    def angular_momentum(self, about: Point, frame: Frame) -> Vector:
        """``H_B = I_C w + r_BC x m v_C`` (absolute velocities), about any point ``B``.

        For a point ``B`` fixed in the body this equals the MIT 2.003 form
        ``I_B w + m r_BC x v_B``; for a point that is not (a pivot of another body, a point of
        a system), only the centre form is the angular momentum.
        """
        w = self.angular_velocity(frame).express(self.frame)
        spin = _times(self.inertia, w)
        return spin + self.masscenter.pos_from(about).cross(self.linear_momentum(frame))

    def kinetic_energy(self, frame: Frame) -> sp.Expr:
        v = self.masscenter.vel(frame)
        w = self.angular_velocity(frame).express(self.frame).components
        return self.mass * v.dot(v) / 2 + (w.T * self.inertia * w)[0, 0] / 2


def _times(inertia: sp.Matrix, w: Vector) -> Vector:
    """``I w`` in ``w``'s frame, on symengine (``I`` given in that frame's axes)."""
    names, I = w.se_names, []
    for x in inertia:
        I.append(to_se(x))
        names = merge_names(names, names_of(x))
    c = w.se_components
    return Vector.from_se(w.frame, (I[3 * i] * c[0] + I[3 * i + 1] * c[1] + I[3 * i + 2] * c[2]
                                    for i in range(3)), names)

